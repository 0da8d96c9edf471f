// Edge inputs of the rough-wall operator and of the distribution it samples:
// adversarial random sources (constant, extreme and periodic streams that
// drive every rejection loop to its fallback), speeds and sizes far outside
// the physical range (underflow and overflow of intermediate results), inputs
// the adapters reject but the core documents as safe (muD > mu0, a bound of
// 0, an unused NaN spin), and the distribution functions and samplers at the
// extremes of alpha and Delta.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "effectiveRestitution.hpp"
#include "sweepSummary.hh"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace roughWall;
using namespace roughWallStability;

namespace
{

constexpr double deg = pi/180;
constexpr double oneMinusUlp = 1 - 0x1p-53;   // largest double below 1

const std::vector<double> alphas{0, 1e-300, 1e-12, 1e-6, 1*deg, 45*deg, 0.5*pi - 1e-12, 0.5*pi};
const std::vector<double> Deltas{0, 1e-12, 1*deg, 8*deg, 30*deg, 45*deg};

//- A random source of a given kind; a copy restarts the same stream
struct Source
{
    enum Kind { constant0, constantHalf, constantTop, constantTiny, alternate, sawtooth, sticky, count };
    Kind kind;
    long n = 0;
    std::mt19937_64 engine{7};

    explicit Source(int k) : kind(static_cast<Kind>(k)) {}

    double operator()()
    {
        const long i = n++;
        switch (kind)
        {
            case constant0: return 0;
            case constantHalf: return 0.5;
            case constantTop: return oneMinusUlp;
            case constantTiny: return 0x1p-53;
            case alternate: return i % 2 ? oneMinusUlp : 0;
            case sawtooth: return (i % 17)/17.0;
            case sticky:
                // random at first, then stuck at the top value
                return i < 5 ? std::uniform_real_distribution<double>()(engine) : oneMinusUlp;
            default: return 0;
        }
    }
};

const std::vector<std::string> sourceNames
{
    "always 0", "always 0.5", "always 1 - 2^-53", "always 2^-53",
    "0, 1 - 2^-53, ...", "sawtooth k/17", "random, then stuck at 1 - 2^-53",
};

const std::vector<std::string> alphaNames
{
    "0", "1e-300", "1e-12", "1e-6", "1 deg", "45 deg", "90 deg - 1e-12", "90 deg",
};
const std::vector<std::string> DeltaNames{"0", "1e-12", "1 deg", "8 deg", "30 deg", "45 deg"};

std::string number(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", x);
    return buf;
}

template<class T, class F>
std::vector<std::string> names(const std::vector<T>& x, F f)
{
    std::vector<std::string> n;
    for (const auto& v : x) n.push_back(f(v));
    return n;
}

//- A wall frame not aligned with the axes
struct Frame { Vec3 N, t, z; };

Frame obliqueFrame()
{
    Frame f;
    f.N = Vec3(0.3, -0.8, 0.52).normalized();
    f.t = f.N.unitOrthogonal();
    f.z = f.t.cross(f.N);
    return f;
}

double seconds(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

TEST(EdgeInputs, AdversarialRandomSourcesKeepTheInvariants)
{
    // Constant and periodic streams drive the rejection loops of the tilt and
    // truncated-normal samplers to their exact fallbacks (e.g. a stream stuck
    // at 1 - 2^-53 gives tilts beyond 90 deg at Delta = 45 deg, rejected 100
    // times), and normal incidence to its tangent draw.
    const auto start = std::chrono::steady_clock::now();
    SweepSummary summary;
    summary.addFactor("random source", sourceNames);
    summary.addFactor("alpha", alphaNames);
    summary.addFactor("Delta", DeltaNames);
    summary.addFactor("geometry", {"3-D", "3-D oblique, lateral tilt", "2-D"});

    const Frame oblique = obliqueFrame();
    for (int k = 0; k < Source::count; ++k)
    for (std::size_t a = 0; a < alphas.size(); ++a)
    for (std::size_t d = 0; d < Deltas.size(); ++d)
    for (int geometry = 0; geometry < 3; ++geometry)
    for (double e : {0.0, 0.8, 1.0})
    for (double mu : {0.0, 0.4, 10.0})
    for (double A : {0.0, 1.0, -1e6})
    for (int bound : {1, 10})
    {
        const Frame f = geometry == 1 ? oblique : Frame{Vec3::UnitY(), Vec3::UnitX(), Vec3::UnitZ()};
        WallHitInput in;
        in.wallNormal = f.N;
        in.emptyDirection = geometry == 2 ? Vec3(Vec3::UnitZ()) : Vec3(Vec3::Zero());
        in.radius = 5e-5;
        in.parameters.material = {e, mu, mu};
        in.parameters.roughnessAngle = Deltas[d];
        in.parameters.lateralTilt = geometry == 1;
        in.parameters.maxFacetCollisions = bound;
        in.velocity = 3*(std::cos(alphas[a])*f.t - std::sin(alphas[a])*f.N);
        in.spin = (A*3/in.radius)*f.z;
        in.seed = k;   // the source kind
        summary.check(in, [k]() { return Source(k); }, {k, int(a), int(d), geometry},
                      drawsPerFacetHardLimit);
    }
    summary.write(summaryPath("adversarialSources"), "Adversarial random sources (testEdgeInputs.cc)", seconds(start));
    summary.expectNoFailures();
    EXPECT_GT(summary.total().fallbacks, 100);
}

TEST(EdgeInputs, SpeedsAndSizesFarOutsideThePhysicalRange)
{
    // Not physical, but nothing in the interface excludes them: underflow of
    // |v|^2 (|v| < 1e-154), subnormal velocities, |v|^2 near overflow, and
    // radius/spin combinations with r*Omega from 1e-300 to 1e150.
    const auto start = std::chrono::steady_clock::now();
    const std::vector<double> speeds{0, std::numeric_limits<double>::denorm_min(), 1e-315,
        1e-310, 1e-300, 1e-200, 1e-160, 1e-154, 1e-100, 1e100, 1e150};
    const std::vector<double> radii{1e-300, 1e-20, 1e-4, 1e20};
    SweepSummary summary;
    summary.addFactor("speed [m/s]", names(speeds, number));
    summary.addFactor("radius [m]", names(radii, number));
    summary.addFactor("geometry", {"3-D", "3-D oblique, lateral tilt", "2-D"});

    const Frame oblique = obliqueFrame();
    unsigned seed = 0;
    for (std::size_t v = 0; v < speeds.size(); ++v)
    for (std::size_t ir = 0; ir < radii.size(); ++ir)
    for (int geometry = 0; geometry < 3; ++geometry)
    for (double alpha : alphas)
    for (double Delta : {0.0, 8*deg, 45*deg})
    for (double e : {0.0, 0.5, 1.0})
    for (double mu : {0.0, 0.4})
    for (double A : {0.0, 1.0, 1e6})
    for (bool withSpin : {true, false})
    {
        const Frame f = geometry == 1 ? oblique : Frame{Vec3::UnitY(), Vec3::UnitX(), Vec3::UnitZ()};
        WallHitInput in;
        in.wallNormal = f.N;
        in.emptyDirection = geometry == 2 ? Vec3(Vec3::UnitZ()) : Vec3(Vec3::Zero());
        in.radius = radii[ir];
        in.withSpin = withSpin;
        in.parameters.material = {e, mu, mu};
        in.parameters.roughnessAngle = Delta;
        in.parameters.lateralTilt = geometry == 1;
        in.velocity = speeds[v]*(std::cos(alpha)*f.t - std::sin(alpha)*f.N);
        in.spin = (A*speeds[v]/in.radius)*f.z;
        // The spin a hit gives is of order |v|/r: it must be representable
        if (!in.spin.allFinite() || speeds[v]/radii[ir] > 1e300) continue;
        in.seed = ++seed;
        summary.check(in, [seed]() { return StdUniform01<std::mt19937_64>(seed); },
                      {int(v), int(ir), geometry});
    }
    summary.write(summaryPath("extremeMagnitudes"), "Speeds and sizes outside the physical range (testEdgeInputs.cc)", seconds(start));
    summary.expectNoFailures();
}

TEST(EdgeInputs, InputsTheAdaptersRejectButTheCoreDocumentsAsSafe)
{
    // muD > mu0 (the sliding impulse is capped), a bound of 0 (immediate
    // mean-wall rebound) or 1000 (the dictionary's maximum), friction 1e300,
    // an unused NaN spin without the spin model, a wall normal of length
    // 1 +- a few ulps (as n/mag(n) gives), velocity exactly zero or -0.
    const auto start = std::chrono::steady_clock::now();
    SweepSummary summary;
    summary.addFactor("(mu0, muD)", {"(0, 10)", "(0.4, 10)", "(1e300, 1e300)", "(0.4, 0.4)"});
    summary.addFactor("maxFacetCollisions", {"0", "1", "1000"});
    summary.addFactor("wall normal", {"unit", "length 1 + 4 ulp", "length 1 - 4 ulp"});

    const std::vector<std::pair<double, double>> frictions{{0, 10}, {0.4, 10}, {1e300, 1e300}, {0.4, 0.4}};
    const std::vector<int> bounds{0, 1, 1000};
    const Vec3 base = Vec3(0.3, -0.8, 0.52).normalized();
    const std::vector<Vec3> normals{base, base*(1 + 4*0x1p-53), base*(1 - 4*0x1p-53)};
    unsigned seed = 0;
    for (std::size_t m = 0; m < frictions.size(); ++m)
    for (std::size_t b = 0; b < bounds.size(); ++b)
    for (std::size_t n = 0; n < normals.size(); ++n)
    for (double alpha : alphas)
    for (double Delta : Deltas)
    for (double e : {0.0, 0.5, 1.0})
    for (double A : {0.0, 1.0, -1e3})
    for (bool withSpin : {true, false})
    {
        const Vec3 N = normals[n];
        const Vec3 t = N.unitOrthogonal();
        WallHitInput in;
        in.wallNormal = N;
        in.radius = 1e-4;
        in.withSpin = withSpin;
        in.parameters.material = {e, frictions[m].first, frictions[m].second};
        in.parameters.roughnessAngle = Delta;
        in.parameters.lateralTilt = true;
        in.parameters.maxFacetCollisions = bounds[b];
        in.velocity = 2*(std::cos(alpha)*t - std::sin(alpha)*N);
        in.spin = withSpin ? Vec3((A*2/in.radius)*t.cross(N))
                           : Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
        in.seed = ++seed;
        summary.check(in, [seed]() { return StdUniform01<std::mt19937_64>(seed); },
                      {int(m), int(b), int(n)});
    }
    summary.write(summaryPath("toleratedInputs"), "Inputs the adapters reject but the core tolerates (testEdgeInputs.cc)", seconds(start));
    summary.expectNoFailures();

    // Zero and negative-zero velocity: not moving into the wall, unchanged
    for (const Vec3& v : {Vec3(0, 0, 0), Vec3(-0.0, -0.0, -0.0), Vec3(1, -0.0, 0)})
    {
        WallHitInput in;
        in.velocity = v;
        in.spin = Vec3(1, 2, 3);
        in.parameters.roughnessAngle = 8*deg;
        StdUniform01<std::mt19937_64> uniform(1);
        const WallHitResult out = hitWall(in, uniform);
        EXPECT_EQ(violation(in, out), "");
        EXPECT_TRUE(sameBits(out.velocity, v));
        EXPECT_EQ(out.report.facetCollisions, 0);
    }
}

TEST(EdgeInputs, DistributionAndSamplersAtTheExtremes)
{
    // pdf >= 0, cdf and sf in [0, 1] and summing to 1, moments finite with
    // <gamma^2> >= <gamma>^2, samples finite with gamma >= -alpha, for the
    // extreme alpha and Delta and facet tilts from the shadow edge to 90 deg
    const std::vector<double> ratios{-1, -1e-12, 0, 1e-300, 1e-12, 1e-3, 0.5, 1, 3, 30, 1e3};
    long checks = 0;
    for (double Delta : Deltas)
    {
        const CollisionAngleDistribution P(Delta);
        for (double alpha : alphas)
        {
            SCOPED_TRACE(testing::Message() << "Delta=" << Delta << " alpha=" << alpha);
            const double m1 = P.mean(alpha), m2 = P.meanSquare(alpha);
            ASSERT_TRUE(std::isfinite(m1) && std::isfinite(m2));
            ASSERT_GE(m2*(1 + 1e-12), m1*m1);
            ASSERT_TRUE(std::isfinite(P.standardDeviation(alpha)));
            for (double ratio : ratios)
            {
                // gamma = alpha*ratio and Delta*ratio around the shadow edge and the mode
                for (double gamma : {ratio*alpha, ratio*Delta - alpha, ratio*Delta, 0.5*pi})
                {
                    const double pdf = P.pdf(gamma, alpha);
                    const double cdf = P.cdf(gamma, alpha), sf = P.sf(gamma, alpha);
                    ASSERT_FALSE(std::isnan(pdf)) << "gamma=" << gamma;
                    ASSERT_GE(pdf, 0) << "gamma=" << gamma;
                    ASSERT_TRUE(cdf >= 0 && cdf <= 1) << "cdf=" << cdf << " gamma=" << gamma;
                    ASSERT_TRUE(sf >= 0 && sf <= 1) << "sf=" << sf << " gamma=" << gamma;
                    ASSERT_NEAR(cdf + sf, 1, 1e-14) << "gamma=" << gamma;
                    ++checks;
                }
            }
            for (unsigned seed = 0; seed < 2000; ++seed)
            {
                StdUniform01<std::mt19937_64> uniform(seed);
                const double g1 = sampleFacetAngle(alpha, Delta, uniform);
                const double g2 = sampleFacetAngleByInversion(alpha, Delta, uniform);
                ASSERT_TRUE(std::isfinite(g1) && std::isfinite(g2));
                ASSERT_GE(g1, -alpha);
                ASSERT_GE(g2, -alpha);
                ++checks;
            }
            // The extreme uniform numbers, through the monotone sampler
            for (double U : {0.0, 0x1p-53, 0.5, oneMinusUlp})
            {
                auto constant = [U]() { return U; };
                const double g = sampleFacetAngleByInversion(alpha, Delta, constant);
                ASSERT_TRUE(std::isfinite(g)) << "U=" << U;
                ASSERT_GE(g, -alpha) << "U=" << U;
                ++checks;
            }
        }
    }
    std::printf("[stability] distribution extremes: %ld checks\n", checks);
}

TEST(EdgeInputs, FuzzFindingsStayFixed)
{
    // Inputs the libFuzzer target found (tests/fuzz/regressions/ holds the
    // raw inputs), as direct checks. Delta = 1e-300 or subnormal makes
    // alpha/Delta overflow to inf; gamma/Delta may overflow too.
    const double subnormalDelta = 0x0.006ffffffff31p-1022;   // 4.8e-311
    for (double Delta : {1e-300, 0x1.89617b1cf8586p-579, subnormalDelta, 0x0.0000200d5ffffp-1022})
    {
        const CollisionAngleDistribution P(Delta);
        for (double alpha : {0.0, 1e-300, 0.7730, 1.5666, 0.5*pi})
        {
            SCOPED_TRACE(testing::Message() << "Delta=" << Delta << " alpha=" << alpha);
            // <gamma^2> was inf*0 = NaN for alpha/Delta > 1e154
            EXPECT_TRUE(std::isfinite(P.meanSquare(alpha)));
            EXPECT_TRUE(std::isfinite(P.standardDeviation(alpha)));
            for (double gamma : {-1e86, -8.9e-3, -1e-300, 0.0, 1e-300, 1e-3, 1.0, 1e86, 1e300})
            {
                // pdf was inf*0 = NaN (Rayleigh branch, gamma/Delta = inf);
                // sf and cdf were NaN from -inf + inf in the normalisation
                const double pdf = P.pdf(gamma, alpha), cdf = P.cdf(gamma, alpha), sf = P.sf(gamma, alpha);
                EXPECT_GE(pdf, 0) << "gamma=" << gamma;
                EXPECT_TRUE(cdf >= 0 && cdf <= 1) << "gamma=" << gamma << " cdf=" << cdf;
                EXPECT_TRUE(sf >= 0 && sf <= 1) << "gamma=" << gamma << " sf=" << sf;
                EXPECT_NEAR(cdf + sf, 1, 1e-14) << "gamma=" << gamma;
            }
            // The inversion sampler's bracketing loop never ended (sf was
            // clamped to 1 from NaN): it must terminate inside the support
            for (double U : {0.25, 0.75, 0x1.fe3cb3e952875p-834})
            {
                auto constant = [U]() { return U; };
                const double g = sampleFacetAngleByInversion(alpha, Delta, constant);
                EXPECT_FALSE(std::isnan(g)) << "U=" << U;
            }
        }
    }
    // The exact sampler gave gamma = -2 alpha when s*s underflowed and the
    // exponential draw was 0 (stream 1 - 2^-53, 0, 0 at alpha/Delta = 1e-188)
    for (double alpha : {0x1.4e4e4e4dfe4e4p-625, 1e-300, 1e-170})
    {
        const double Delta = 0x1.678bc853c926bp-1;
        const std::vector<double> values{oneMinusUlp, 0, 0};
        std::size_t i = 0;
        auto stream = [&]() { return values[i++ % values.size()]; };
        const double g = sampleFacetAngle(alpha, Delta, stream);
        EXPECT_GE(g, -alpha) << "alpha=" << alpha;
    }
}
