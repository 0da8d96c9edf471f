// The rolling-sphere envelope of a wall profile and its tilt statistics
// (rollingSphereEnvelope.hpp), and the profile file reader (profileFile.hpp).
// Oracles, none of which calls the code under test for its expectation:
//  - sinusoid z = A sin(2 pi x/L), sphere radius r below the valley radius
//    of curvature L^2/(4 pi^2 A): the centre curve is the parallel curve and
//    the tilt distribution is that of atan(z') with x uniform (derived below),
//    whose moments are integrated here by Boost's adaptive Gauss-Kronrod;
//    the centre heights against the parallel curve solved by Newton here;
//  - flat profile: tilt exactly 0, centre exactly z + r;
//  - large sphere on a periodic profile: it rests on the highest point only,
//    tilt -asin(u/r), u the distance to it: E[theta^2] by its antiderivative;
//    any sphere on a trimmed profile: |theta| <= acos(1 - (zmax - zmin)/r);
//  - a brute-force envelope written here (every x against every x');
//  - the synthetic Gaussian profile: Rq exactly, rms slope 2 pi Rq/RSm and
//    zero up-crossings (Rice) counted here, Ra/Rq = sqrt(2/pi); Rz over 5 RSm
//    and Delta(2 RSm) against an independent random-phase cosine sum made here;
//  - bad input: every case named in the message.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "profileFile.hpp"
#include "rollingSphereEnvelope.hpp"
#include "limitsAndUnits.hpp"
#include "testSupport.hh"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <vector>

using namespace roughWall;

namespace
{

constexpr double piTyped = 3.14159265358979323846;

//- A sinusoid's samples, periodic: n points per wavelength L
SampledProfile sinusoid(double A, double L, int n)
{
    SampledProfile p;
    p.ends = ProfileEnds::periodic;
    p.period = L;
    for (int i = 0; i < n; ++i)
    {
        const double x = L*i/n;
        p.x.push_back(x);
        p.z.push_back(A*std::sin(2*piTyped*x/L));
    }
    return p;
}

//- A rough random profile: random walk plus noise, non-uniform spacing
SampledProfile randomProfile(int n, double h, unsigned seed, bool uniformSpacing)
{
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> u(0, 1);
    SampledProfile p;
    double x = 0, walk = 0;
    for (int i = 0; i < n; ++i)
    {
        walk += (u(g) - 0.5)*h;
        p.x.push_back(x);
        p.z.push_back(walk + 0.5*h*(u(g) - 0.5));
        x += uniformSpacing ? h : h*(0.5 + u(g));
    }
    return p;
}

std::string messageOf(const std::function<void()>& f)
{
    try
    {
        f();
    }
    catch (const std::exception& e)
    {
        return e.what();
    }
    return "(no exception)";
}

} // namespace


// Sinusoid below its valley radius of curvature rho = L^2/(4 pi^2 A).
// Derivation of the oracle: the sphere touches at the foot x_f, where the
// tilt is theta(x_f) = atan(z'(x_f)) (envelope theorem: the maximum of
// z(x') + sqrt(r^2 - (x - x')^2) over x' is where z'(x') = c'(x)); its centre
// is X = x_f - r sin(theta), so dX = (1 - r kappa) dx_f with the curvature
// kappa = z''/(1 + z'^2)^(3/2) = cos(theta) dtheta/dx_f; X is monotone while
// r kappa < 1 (r < rho). Over a period, for any g:
//   int g(theta) dX = int g(theta) dx_f - r int g(theta) cos(theta) dtheta,
// and the last integral is of an exact differential over a closed loop: 0.
// So with X uniform the tilt has the law of atan(z'(x)) with x uniform, for
// every r < rho: E[theta^k] = (1/2pi) int_0^2pi atan(a cos phi)^k dphi,
// a = 2 pi A/L. The sphere rests on the polyline through the samples: its
// chords have the slope of the curve at an inner point, and the vertex arcs
// cover a fraction r kappa of x; the error is O(h^2): tolerance
// (a k h)^2 = slope change over a spacing, squared (4e-7 here).
TEST(roughnessProfile, SinusoidBelowCrestRadiusGivesSlopeAngleLaw)
{
    const double L = 100e-6, a = 0.5, A = a*L/(2*piTyped);
    const double rho = L*L/(4*piTyped*piTyped*A);   // = L/pi
    const int n = 4000;
    const SampledProfile p = sinusoid(A, L, n);

    const auto moment = [a](int k)
    {
        return roughWallTest::integrate
        (
            [a, k](double phi) { return std::pow(std::atan(a*std::cos(phi)), k); },
            0, 2*piTyped
        )/(2*piTyped);
    };
    const double m2 = moment(2), m4 = moment(4);
    const double kurtosis = m4/(m2*m2) - 3;
    // The typed check of the quadrature: atan(y)^2 = y^2 - 2 y^4/3 +
    // 23 y^6/45 - ..., E[cos^2, cos^4, cos^6] = 1/2, 3/8, 5/16, so
    // E[theta^2] = a^2/2 - a^4/4 + 23 a^6/144 - ... (next term < 1e-3 at 0.5)
    EXPECT_NEAR(m2, 0.125 - 0.015625 + 23.0/144*std::pow(0.5, 6), 1e-3);

    for (const double r : {0.05*rho, 0.4*rho, 0.9*rho})
    {
        const double h = L/n;
        // Measured: 1.1 (a k h)^2 at r = 0.9 rho
        const double tol = 2*std::pow(a*2*piTyped/L*h, 2);
        const TiltStatistics s = tiltStatistics(p, 2*r);
        EXPECT_NEAR(s.rms*s.rms, m2, tol) << "r/rho = " << r/rho;
        EXPECT_NEAR(s.mean, 0, tol) << "r/rho = " << r/rho;
        EXPECT_NEAR(s.skewness, 0, 1e-5) << "r/rho = " << r/rho;
        EXPECT_NEAR(s.excessKurtosis, kurtosis, 10*tol) << "r/rho = " << r/rho;
        EXPECT_NEAR(s.length, L, 1e-12*L);

        // The centre on the parallel curve: for each X solve
        // X = x_f - r sin(theta(x_f)) by Newton, c = z(x_f) + r cos(theta).
        // Resting on the polyline instead of the curve lowers it by at most
        // the chords' sag h^2 max|z''|/8 = h^2/(8 rho).
        const RollingSphereEnvelope e = rollingSphereEnvelope(p, r);
        double worst = 0;
        const double k = 2*piTyped/L;
        for (std::size_t i = 0; i < e.x.size(); i += 7)
        {
            double xf = e.x[i];
            for (int it = 0; it < 50; ++it)
            {
                const double s1 = a*std::cos(k*xf), s2 = -a*k*std::sin(k*xf);
                const double q = std::sqrt(1 + s1*s1);
                const double F = xf - r*s1/q - e.x[i];
                const double dF = 1 - r*s2/(q*q*q);
                xf -= F/dF;
            }
            const double s1 = a*std::cos(k*xf);
            const double c = A*std::sin(k*xf) + r/std::sqrt(1 + s1*s1);
            worst = std::max(worst, std::abs(e.centre[i] - c));
        }
        EXPECT_LT(worst, h*h/(8*rho) + 1e-15) << "r/rho = " << r/rho;
    }
}


// Flat profile (trimmed ends): every tilt exactly 0, centre exactly z + r
TEST(roughnessProfile, FlatProfileHasNoTilt)
{
    SampledProfile p;
    for (int i = 0; i < 500; ++i)
    {
        p.x.push_back(1e-6*i);
        p.z.push_back(3e-6);
    }
    for (const double d : {5e-6, 40e-6, 300e-6})
    {
        const TiltStatistics s = tiltStatistics(p, d);
        EXPECT_EQ(s.rms, 0) << "d = " << d;
        EXPECT_EQ(s.mean, 0) << "d = " << d;
        EXPECT_TRUE(std::isnan(s.skewness));
        EXPECT_NEAR(s.length, 499e-6 - d, 1e-15);
        const RollingSphereEnvelope e = rollingSphereEnvelope(p, 0.5*d);
        for (std::size_t i = 0; i < e.x.size(); ++i)
        {
            ASSERT_EQ(e.tilt[i], 0);
            ASSERT_EQ(e.centre[i], 3e-6 + 0.5*d);
        }
    }
}


// A sphere much larger than a periodic profile's period rests on the
// highest point (and its images) alone: tilt -asin(u/r), u = X - x_max
// wrapped into [-L/2, L/2). Oracle: the mean of asin(u/r)^2 over u uniform,
// [u asin^2 + 2 sqrt(r^2 - u^2) asin - 2 u]/L between -L/2 and L/2; the
// profile is sampled at N uniform points: rectangle rule, relative error
// below 1e-4 for N = 400.
TEST(roughnessProfile, LargeSphereRestsOnTheHighestPeak)
{
    SampledProfile p = randomProfile(400, 1e-6, 3, true);
    p.ends = ProfileEnds::periodic;
    const double L = 400e-6;
    p.period = L;
    // A spike 10 um above the rest: a sphere of r > L^2/(8*10 um) = 2 mm
    // over it cannot reach any other point
    const std::size_t top = std::max_element(p.z.begin(), p.z.end()) - p.z.begin();
    p.z[top] += 10e-6;
    for (const double r : {50*L, 500*L})
    {
        const auto F = [r](double u)
        {
            const double s = std::asin(u/r);
            return u*s*s + 2*std::sqrt(r*r - u*u)*s - 2*u;
        };
        const double m2 = (F(0.5*L) - F(-0.5*L))/L;
        const TiltStatistics s = tiltStatistics(p, 2*r);
        EXPECT_NEAR(s.rms*s.rms/m2, 1, 1e-4) << "r/L = " << r/L;
        // The abscissae x_top + i h, i = -199 .. 200 (or -200 .. 199 as the
        // wrap falls): mean tilt -h/(2 r) (or +)
        EXPECT_NEAR(std::abs(s.mean), 1e-6/(2*r), 1e-3*std::sqrt(m2));
        // By hand: asin(u/r) ~ u/r, E = L^2/(12 r^2)
        EXPECT_NEAR(m2, L*L/(12*r*r), 1e-3*m2);
        const RollingSphereEnvelope e = rollingSphereEnvelope(p, r);
        for (std::size_t i = 0; i < e.x.size(); ++i)
        {
            const double wrapped = std::remainder(e.footX[i] - p.x[top], L);
            ASSERT_NEAR(wrapped, 0, 1e-9*L) << "the contact is not the highest point";
        }
    }
}


// Any sphere on a trimmed profile: the sample under the centre is below the
// sphere, so r (1 - cos theta) <= zmax - zmin; Delta falls with r
TEST(roughnessProfile, LargeSphereTiltBoundedByProfileHeight)
{
    const SampledProfile p = randomProfile(4000, 1e-6, 5, true);
    const double Rt =
        *std::max_element(p.z.begin(), p.z.end()) - *std::min_element(p.z.begin(), p.z.end());
    double previous = 10;
    for (const double d : {100e-6, 400e-6, 1000e-6, 3000e-6})
    {
        const double r = 0.5*d;
        const RollingSphereEnvelope e = rollingSphereEnvelope(p, r);
        const double bound = std::acos(1 - Rt/r);
        double worst = 0;
        for (std::size_t i = 0; i < e.x.size(); ++i)
        {
            if (e.x[i] >= p.x.front() + r && e.x[i] <= p.x.back() - r)
            {
                worst = std::max(worst, std::abs(e.tilt[i]));
            }
        }
        EXPECT_LE(worst, bound) << "d = " << d;
        const TiltStatistics s = tiltStatistics(p, d);
        EXPECT_LT(s.rms, previous) << "d = " << d;
        previous = s.rms;
    }

}


// The stack envelope against every x against every x' of the polyline
// (every vertex and every segment), on random profiles with non-uniform
// spacing, trimmed and periodic, radii from a third of the spacing to the
// whole profile
TEST(roughnessProfile, EnvelopeEqualsBruteForce)
{
    for (const bool periodic : {false, true})
    {
        SampledProfile p = randomProfile(1500, 1e-6, periodic ? 11 : 7, false);
        if (periodic)
        {
            p.ends = ProfileEnds::periodic;
            p.period = p.x.back() - p.x.front() + 1e-6;
        }
        const double h = largestSpacing(p);
        for (const double r : {0.3*h, 0.51*h, 3*h, 10*h, 40*h, 400*h, 3000*h})
        {
            const RollingSphereEnvelope e = rollingSphereEnvelope(p, r);
            ASSERT_EQ(e.x.size(), p.x.size());
            const long copies = periodic ? static_cast<long>(std::ceil(r/p.period)) + 1 : 0;
            // The polyline's vertices, images included
            std::vector<double> vx, vz;
            for (long c = -copies; c <= copies; ++c)
            {
                for (std::size_t j = 0; j < p.x.size(); ++j)
                {
                    vx.push_back(p.x[j] + c*p.period);
                    vz.push_back(p.z[j]);
                }
            }
            long tiltsCompared = 0, tiltsDiffering = 0;
            double ell = 0, steepest = 0;
            for (std::size_t j = 0; j + 1 < p.x.size(); ++j)
            {
                const double dx = p.x[j + 1] - p.x[j], dz = p.z[j + 1] - p.z[j];
                ell = std::max(ell, std::hypot(dx, dz));
                steepest = std::max(steepest, std::abs(std::atan2(dz, dx)));
            }
            const double room = r*std::cos(steepest) - ell*std::sin(steepest);
            const double delta = room > 0 ? ell*ell/(2*room) : 0;
            for (std::size_t i = 0; i < p.x.size(); ++i)
            {
                double best = -1e300, second = -1e300, bestTilt = 0;
                const auto offer = [&](double v, double t)
                {
                    if (v > best) { second = best; best = v; bestTilt = t; }
                    else if (v > second) { second = v; }
                };
                for (std::size_t j = 0; j < vx.size(); ++j)
                {
                    const double u = p.x[i] - vx[j];
                    if (std::abs(u) <= r)
                    {
                        offer(vz[j] + std::sqrt(r*r - u*u), -std::asin(u/r));
                    }
                    if (j + 1 < vx.size())
                    {
                        // The segment's interior: the centre at distance r
                        // along its normal from the foot (x_f, z_f)
                        const double dx = vx[j + 1] - vx[j], dz = vz[j + 1] - vz[j];
                        const double len = std::hypot(dx, dz);
                        const double xf = p.x[i] + r*dz/len;   // foot below-left/right
                        if (xf > vx[j] && xf < vx[j + 1])
                        {
                            const double zf = vz[j] + (xf - vx[j])*dz/dx;
                            offer(zf + r*dx/len, std::atan2(dz, dx));
                        }
                    }
                }
                // Never above the brute force, below it by less than the
                // near-double-contact drop delta of the header
                ASSERT_LE(e.centre[i], best + 1e-12*(r + 1e-5));
                ASSERT_LE(best - e.centre[i], delta + 1e-12*(r + 1e-5))
                    << "periodic " << periodic << " r/h = " << r/h << " i = " << i;
                if (best - second > 1e-9*(r + 1e-5))
                {
                    ++tiltsCompared;
                    tiltsDiffering += std::abs(e.tilt[i] - bestTilt) > 1e-12;
                }
            }
            EXPECT_GT(tiltsCompared, static_cast<long>(p.x.size()/2));
            // Near double contacts only (header): measured 0 on these
            // profiles; at most 1 in 1000 allowed
            EXPECT_LE(tiltsDiffering, tiltsCompared/1000)
                << "periodic " << periodic << " r/h = " << r/h;
        }
    }
}


// The statistics weigh each abscissa by its cell: on non-uniform spacing,
// the brute-force tilts integrated here by cells give the same moments
TEST(roughnessProfile, StatisticsWeighByCell)
{
    const SampledProfile p = randomProfile(3000, 1e-6, 13, false);
    const double d = 60e-6, r = 0.5*d;
    const RollingSphereEnvelope e = rollingSphereEnvelope(p, r);
    const double lo = p.x.front() + r, hi = p.x.back() - r;
    double W = 0, S2 = 0, S1 = 0;
    for (std::size_t i = 0; i < p.x.size(); ++i)
    {
        const double left = i > 0 ? 0.5*(p.x[i - 1] + p.x[i]) : p.x[0];
        const double right = i + 1 < p.x.size() ? 0.5*(p.x[i] + p.x[i + 1]) : p.x[i];
        const double w = std::max(0.0, std::min(hi, right) - std::max(lo, left));
        W += w;
        S1 += w*e.tilt[i];
        S2 += w*e.tilt[i]*e.tilt[i];
    }
    const TiltStatistics s = tiltStatistics(p, d);
    EXPECT_NEAR(W, hi - lo, 1e-15);
    EXPECT_NEAR(s.rms, std::sqrt(S2/W), 1e-12);
    EXPECT_NEAR(s.mean, S1/W, 1e-12);
    // The unweighted mean differs on this spacing: the weights matter
    double plain = 0;
    long count = 0;
    for (std::size_t i = 0; i < p.x.size(); ++i)
    {
        if (p.x[i] >= lo && p.x[i] <= hi) { plain += e.tilt[i]*e.tilt[i]; ++count; }
    }
    EXPECT_GT(std::abs(std::sqrt(plain/count) - s.rms), 1e-5);
}


// The synthetic Gaussian profile: Rq exactly; the rms slope (differences of
// the samples) 2 pi Rq/RSm and the zero up-crossings one per RSm (Rice),
// both counted here; Ra/Rq = sqrt(2/pi). Statistical tolerances: on seeds
// 1..8 of the default 5000 RSm the relative spread (sd) was measured as
// 0.63 % (rms slope), 0.60 % (length per up-crossing), 0.17 % (Ra/Rq):
// 2 %, 2 % and 0.5 % are 3 sd (fixed seeds: deterministic).
TEST(roughnessProfile, SyntheticProfileHasRiceWidthAndSlope)
{
    for (const std::uint64_t seed : {1u, 2u, 3u})
    {
        SyntheticProfileSettings set;
        set.Rq = 2e-6;
        set.RSm = 60e-6;
        set.seed = seed;
        const SampledProfile p = syntheticGaussianProfile(set);
        const std::size_t n = p.z.size();
        const double h = p.x[1] - p.x[0];
        EXPECT_NEAR(p.period, n*h, 1e-9*p.period);
        EXPECT_GE(p.period, 5000*60e-6);
        double q = 0, s2 = 0, absSum = 0, mean = 0;
        long up = 0;
        for (std::size_t i = 0; i < n; ++i)
        {
            const std::size_t j = (i + 1) % n;
            mean += p.z[i];
            q += p.z[i]*p.z[i];
            absSum += std::abs(p.z[i]);
            const double slope = (p.z[j] - p.z[i])/h;
            s2 += slope*slope;
            up += p.z[i] < 0 && p.z[j] >= 0;
        }
        EXPECT_NEAR(mean/n, 0, 1e-12*2e-6);
        EXPECT_NEAR(std::sqrt(q/n), 2e-6, 1e-12*2e-6);
        EXPECT_NEAR(std::sqrt(s2/n)/(2*piTyped*2e-6/60e-6), 1, 0.02) << "seed " << seed;
        EXPECT_NEAR(p.period/up/60e-6, 1, 0.02) << "seed " << seed;
        EXPECT_NEAR(absSum/n/2e-6/std::sqrt(2/piTyped), 1, 0.005) << "seed " << seed;
        EXPECT_NEAR(limits::rqPerRaGaussian, std::sqrt(piTyped/2), 1e-15);
    }
}


// An independent Gaussian profile: a random-phase sum of M cosines whose
// wavenumbers are drawn from the spectral density of R(tau) = Rq^2
// exp(-tau^2/(2 l^2)) (normal, sd 1/l), l = RSm/(2 pi). Its mean
// peak-to-valley height over windows of 5 RSm is rzPerRqGaussian Rq, and
// its Delta(2 RSm), Delta(RSm/2) equal those of the library's synthetic
// profile. Tolerances 3 %: the seed spread of Delta at 5000 RSm is 0.4-0.6 %
// (docs/figures/roughnessProfile-seeds.csv), so about 1.3 % at the 1000 RSm
// used here, and that of Rz (1596 windows of 5 RSm) was 0.3 % (4 seeds).
TEST(roughnessProfile, SyntheticProfileAgreesWithCosineSum)
{
    const double Rq = 1e-6, RSm = 50e-6, l = RSm/(2*piTyped);
    const int M = 400;
    const double length = 1000*RSm, h = l/16;
    const std::size_t n = static_cast<std::size_t>(length/h);
    std::mt19937_64 g(99);
    std::normal_distribution<double> k(0, 1/l);
    std::uniform_real_distribution<double> phase(0, 2*piTyped);
    std::vector<double> kw(M), ph(M);
    for (int m = 0; m < M; ++m) { kw[m] = k(g); ph[m] = phase(g); }
    SampledProfile c;
    for (std::size_t i = 0; i < n; ++i)
    {
        const double x = i*h;
        double z = 0;
        for (int m = 0; m < M; ++m) z += std::cos(kw[m]*x + ph[m]);
        c.x.push_back(x);
        c.z.push_back(Rq*std::sqrt(2.0/M)*z);
    }
    const std::size_t w = static_cast<std::size_t>(std::llround(5*RSm/h));
    double range = 0;
    long windows = 0;
    for (std::size_t a = 0; a + w <= n; a += w, ++windows)
    {
        const auto mm = std::minmax_element(c.z.begin() + a, c.z.begin() + a + w);
        range += *mm.second - *mm.first;
    }
    EXPECT_NEAR(range/windows/Rq/limits::rzPerRqGaussian, 1, 0.03);

    SyntheticProfileSettings set;
    set.Rq = Rq;
    set.RSm = RSm;
    set.lengthPerRSm = 1000;
    const SampledProfile p = syntheticGaussianProfile(set);
    for (const double d : {0.5*RSm, 2*RSm})
    {
        const double mine = tiltStatistics(p, d).rms;
        const double theirs = tiltStatistics(c, d).rms;
        EXPECT_NEAR(mine/theirs, 1, 0.03) << "d/RSm = " << d/RSm;
    }
}


TEST(roughnessProfile, BadInputIsNamed)
{
    SampledProfile p = randomProfile(50, 1e-6, 1, true);
    SampledProfile q = p;
    q.z.pop_back();
    EXPECT_NE(messageOf([&] { checkProfile(q); }).find("differ in length"), std::string::npos);
    q = p;
    q.x[20] = q.x[19];
    EXPECT_NE(messageOf([&] { checkProfile(q); }).find("strictly increasing at point 20"),
              std::string::npos);
    q = p;
    q.z[7] = std::nan("");
    EXPECT_NE(messageOf([&] { checkProfile(q); }).find("point 7 is not finite"),
              std::string::npos);
    q = p;
    q.ends = ProfileEnds::periodic;
    q.period = 10e-6;
    EXPECT_NE(messageOf([&] { checkProfile(q); }).find("period"), std::string::npos);
    EXPECT_NE(messageOf([&] { tiltStatistics(p, 0); }).find("diameter must be > 0"),
              std::string::npos);
    EXPECT_NE(messageOf([&] { tiltStatistics(p, 60e-6); }).find("not longer than the diameter"),
              std::string::npos);
    EXPECT_NE(messageOf([&] { rollingSphereEnvelope(p, -1e-6); }).find("radius must be > 0"),
              std::string::npos);
    SyntheticProfileSettings set;
    set.RSm = 1e-5;
    EXPECT_NE(messageOf([&] { syntheticGaussianProfile(set); }).find("Rq and RSm"),
              std::string::npos);
}


// The reader: accepted formats give the same points; each bad file is a
// ProfileFileError naming the file and the line
TEST(roughnessProfile, ProfileFileFormatsAndErrors)
{
    const auto read = [](const std::string& text)
    {
        std::istringstream in(text);
        return readProfile(in, "trace.txt", 3);
    };
    // Metres, blanks
    const SampledProfile a = read("0 1e-6\n1e-6 2e-6\n2e-6 -1e-6\n");
    // Header, comments, units, commas, semicolons, CRLF, blank lines
    const SampledProfile b = read
    (
        "Profile export, instrument X\r\nx [mm]; z [um]\r\n# units mm um\r\n"
        "% a comment\r\n\r\n0,1\r\n0.001; 2\r\n// another\r\n0.002\t-1\r\n"
    );
    ASSERT_EQ(a.x.size(), 3u);
    ASSERT_EQ(b.x.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i)
    {
        EXPECT_NEAR(b.x[i], a.x[i], 1e-18);
        EXPECT_NEAR(b.z[i], a.z[i], 1e-18);
    }
    EXPECT_TRUE(a.ends == ProfileEnds::trimmed);

    const auto error = [&](const std::string& text)
    {
        return messageOf([&] { read(text); });
    };
    EXPECT_EQ(error("0 1\n1 2\n1 3\n").rfind("trace.txt:3: x = 1 m is not above", 0), 0u)
        << error("0 1\n1 2\n1 3\n");
    EXPECT_EQ(error("0 1\n1 nan\n2 3\n").rfind("trace.txt:2: not a finite number", 0), 0u);
    EXPECT_EQ(error("0 1\n1 inf\n2 3\n").rfind("trace.txt:2: not a finite number", 0), 0u);
    EXPECT_EQ(error("0 1\n1 2 3\n2 3\n").rfind("trace.txt:2: expected two numbers", 0), 0u);
    EXPECT_EQ(error("0 1\nfoo bar\n2 3\n").rfind("trace.txt:2: expected two numbers", 0), 0u);
    EXPECT_EQ(error("0 1\n1\n2 3\n").rfind("trace.txt:2: expected two numbers", 0), 0u);
    EXPECT_EQ(error("# units km m\n0 1\n").rfind("trace.txt:1: units line", 0), 0u);
    EXPECT_EQ(error("0 1\n# units mm mm\n1 2\n").rfind("trace.txt:2: units must be", 0), 0u);
    EXPECT_EQ(error("# only\n0 1\n1 2\n").rfind("trace.txt: 2 points in 3 lines, at least 3", 0),
              0u) << error("# only\n0 1\n1 2\n");
    const std::string missing = messageOf([] { readProfileFile("/nonexistent/trace.txt"); });
    EXPECT_EQ(missing.rfind("/nonexistent/trace.txt: cannot open", 0), 0u) << missing;
    // The default minimum
    EXPECT_NE(messageOf([] { std::istringstream in("0 1\n1 2\n"); readProfile(in, "f"); })
                  .find("at least 10 needed"), std::string::npos);
}


// Levelling removes a least-squares line (trimmed) or the mean (periodic);
// a sinusoid of wavelength L has RSm = L and Rq = A/sqrt 2 (by hand)
TEST(roughnessProfile, LevellingAndProfileParameters)
{
    SampledProfile p = sinusoid(2e-6, 100e-6, 1000);
    p.ends = ProfileEnds::trimmed;
    SampledProfile tilted = p;
    for (std::size_t i = 0; i < p.x.size(); ++i)
    {
        tilted.z[i] += 5e-6 + 0.01*p.x[i];
    }
    const SampledProfile level = levelledProfile(tilted);
    // Least squares of sin over 0 .. L(1 - 1/n) leaves a small line of its
    // own: compare with the sinusoid levelled alone
    const SampledProfile reference = levelledProfile(p);
    for (std::size_t i = 0; i < p.x.size(); ++i)
    {
        ASSERT_NEAR(level.z[i], reference.z[i], 1e-15);
    }
    SampledProfile periodic = sinusoid(2e-6, 100e-6, 1000);
    for (double& z : periodic.z) z += 3e-6;
    const ProfileParameters q = profileParameters(levelledProfile(periodic));
    EXPECT_NEAR(q.Rq, 2e-6/std::sqrt(2.0), 1e-15);
    EXPECT_EQ(q.upCrossings, 1u);
    EXPECT_NEAR(q.RSm, 100e-6, 1e-18);
}


// RSm as ISO 4287 defines it: the mean spacing of successive zero
// up-crossings within the trace (issue 45: the length divided by the number
// of crossings gave 95.2 um for 20 periods of 100 um). Oracle: a trimmed
// trace z = A sin(2 pi x/L + phi), 20 periods of L = 100 um sampled at 0.1
// um, phi = 1 rad so that the trace starts and ends between crossings: its
// up-crossings are at x = (m - phi/(2 pi)) L, so their spacings are L
// exactly; linear interpolation between samples errs by O((2 pi h/L)^3)
// and the same at every crossing (L/h is an integer): RSm = L to 1e-6.
TEST(roughnessProfile, RSmOfATrimmedSinusoidIsItsWavelength)
{
    const double A = 2e-6, L = 100e-6, h = 0.1e-6, phi = 1;
    SampledProfile p;
    p.ends = ProfileEnds::trimmed;
    for (int i = 0; i < 20000; ++i)
    {
        p.x.push_back(i*h);
        p.z.push_back(A*std::sin(2*piTyped*i*h/L + phi));
    }
    // Crossings counted here: up-crossings at (m - phi/(2 pi)) L, m = 1..19
    // lie inside [0, 1999.9 um]; m = 20 (at 1984.1 um) too: 20 crossings
    std::size_t count = 0;
    for (int m = 0; m <= 21; ++m)
    {
        const double x = (m - phi/(2*piTyped))*L;
        count += x > p.x.front() && x < p.x.back();
    }
    const ProfileParameters q = profileParameters(p);
    EXPECT_EQ(q.upCrossings, count);
    EXPECT_NEAR(q.RSm/L, 1, 1e-6) << "RSm = " << q.RSm;
    EXPECT_NEAR(q.length, 19999*h, 1e-18);
}


// A trace whose elements differ in width, starting and ending between
// crossings, the last point below zero and the first above it (so that a
// crossing wrapping past the end would count). Oracle: z = A sin(2 pi
// u(x)), u(x) = x/L + b sin(2 pi x/(3.7 L)) (monotone: b 2 pi/3.7 < 1), so
// the up-crossings are where u is an integer: solved here by bisection on
// u, RSm = (last - first)/(count - 1); the samples, 2000 per L, interpolate
// the crossings to O(h^2 |z''/z'|), below 1e-6 of L.
TEST(roughnessProfile, RSmIsTheMeanSpacingOfUpCrossingsWithinTheTrace)
{
    const double A = 1e-6, L = 50e-6, b = 0.3, x0 = 0.1*L, x1 = 12.6*L;
    const auto u = [&](double x) { return x/L + b*std::sin(2*piTyped*x/(3.7*L)); };
    const auto z = [&](double x) { return A*std::sin(2*piTyped*u(x)); };
    SampledProfile p;
    p.ends = ProfileEnds::trimmed;
    const int n = 25001;
    for (int i = 0; i < n; ++i)
    {
        const double x = x0 + (x1 - x0)*i/(n - 1);
        p.x.push_back(x);
        p.z.push_back(z(x));
    }
    ASSERT_GT(p.z.front(), 0);
    ASSERT_LT(p.z.back(), 0) << "the wrapping pair (last, first) is an up-crossing";

    // The up-crossings: u(x) = m for the integers m in (u(x0), u(x1))
    std::vector<double> crossings;
    for (long m = long(std::ceil(u(x0))); m < u(x1); ++m)
    {
        double lo = x0, hi = x1;
        for (int k = 0; k < 200; ++k)
        {
            const double mid = 0.5*(lo + hi);
            (u(mid) < m ? lo : hi) = mid;
        }
        crossings.push_back(0.5*(lo + hi));
    }
    ASSERT_GE(crossings.size(), 3u);
    const double spacing =
        (crossings.back() - crossings.front())/(crossings.size() - 1);
    // The spacings differ: the mean is no length per crossing
    ASSERT_GT(std::fabs(spacing - (x1 - x0)/crossings.size()), 0.01*spacing);

    const ProfileParameters q = profileParameters(p);
    EXPECT_EQ(q.upCrossings, crossings.size());
    EXPECT_NEAR(q.RSm/spacing, 1, 1e-6)
        << "RSm = " << q.RSm << ", mean spacing " << spacing;

    // Periodic (the synthetic profile): the crossings' spacings round the
    // period, typed here for the sinusoid of 1000 points per period
    SampledProfile s = sinusoid(2e-6, 100e-6, 1000);
    for (double& zi : s.z) zi -= 0.5e-6;   // crossings off the samples
    const ProfileParameters qs = profileParameters(s);
    EXPECT_EQ(qs.upCrossings, 1u);
    EXPECT_NEAR(qs.RSm, 100e-6, 1e-18);

    // One crossing in a trimmed trace: no spacing, no RSm
    SampledProfile one;
    for (int i = 0; i < 20; ++i)
    {
        one.x.push_back(i*1e-6);
        one.z.push_back((i - 9.5)*1e-7);
    }
    const ProfileParameters q1 = profileParameters(one);
    EXPECT_EQ(q1.upCrossings, 1u);
    EXPECT_EQ(q1.RSm, 0);
}


// The reader's other forms of the units line and the comments (the header
// of profileFile.hpp): '//' and '%' comment lines carry a units line as '#'
// does, 'units:' as 'units', 'micron' and 'µm' (UTF-8) as um. Oracle: the
// points typed here in metres; a units line ignored would leave them in mm
// and um read as metres, 1e3 and 1e6 times too large. Numbers a double
// cannot hold (1e400, 1e-400) are refused naming the line, also as the
// first field of the first line (where a text field would be a header).
TEST(roughnessProfile, ProfileFileUnitFormsAndOutOfRangeNumbers)
{
    const auto read = [](const std::string& text)
    {
        std::istringstream in(text);
        return readProfile(in, "trace.txt", 3);
    };
    const auto error = [&](const std::string& text)
    {
        return messageOf([&] { read(text); });
    };
    const std::vector<double> x{0, 1e-3, 2e-3}, z{1e-6, 2e-6, -1e-6};
    for (const std::string units :
         {
             "// units mm um\n", "//units mm um\n", "  // units mm um\n",
             "% units mm um\n", "# units: mm um\n", "# units mm micron\n",
             "# units mm \xC2\xB5m\n", "// units: mm \xC2\xB5m\n"
         })
    {
        const SampledProfile p = read(units + "0 1\n1 2\n2 -1\n");
        ASSERT_EQ(p.x.size(), 3u) << units;
        for (std::size_t i = 0; i < 3; ++i)
        {
            EXPECT_NEAR(p.x[i], x[i], 1e-18) << units;
            EXPECT_NEAR(p.z[i], z[i], 1e-21) << units;
        }
    }
    // x in micron, z in nm
    const SampledProfile m = read("% units micron nm\n0 1\n1 2\n2 -1\n");
    EXPECT_NEAR(m.x[2], 2e-6, 1e-21);
    EXPECT_NEAR(m.z[1], 2e-9, 1e-24);
    // A comment line that is no units line changes nothing
    const SampledProfile c = read("// mm um\n% um um\n0 1\n1 2\n2 -1\n");
    EXPECT_EQ(c.x[2], 2.0);
    EXPECT_EQ(c.z[0], 1.0);

    for (const auto& [text, line] : std::vector<std::pair<std::string, int>>
         {
             {"0 1\n1 1e400\n2 3\n", 2}, {"0 1\n1 1e-400\n2 3\n", 2},
             {"0 1\n1e400 2\n2 3\n", 2}, {"0 1\n1 -1e400\n2 3\n", 2},
             {"1e-400 1\n1 2\n2 3\n", 1}, {"x z\n1e400 1\n1 2\n2 3\n", 2}
         })
    {
        const std::string e = error(text);
        EXPECT_EQ(e.rfind("trace.txt:" + std::to_string(line)
                        + ": a number out of the range of a double", 0), 0u) << e;
    }
}
