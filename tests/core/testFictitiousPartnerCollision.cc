// Sommerfeld's fictitious-partner model of inter-particle collisions
// (fictitiousPartnerCollision.hpp), against oracles written here:
// - the pair collision: the closed form of smooth spheres, and on random
//   inputs the invariants of two hard spheres (the partner's change follows
//   from the impulse): pair energy never grows and is kept for e = 1,
//   mu = 0; the real particle's angular momentum about the contact point is
//   kept; |J_t| <= mu |J_n|; a no-slip collision ends without slip;
// - the contact normal: cos^2 of its angle to the relative velocity uniform
//   on [0, 1] (an impact point uniform over the projected disc);
// - dilute kinetic theory of a Maxwellian gas of equal smooth spheres:
//   collision frequency f = 4 n d^2 sqrt(pi T) (T per component), the
//   frequency with correlation R as sqrt(1 - R) f (the relative velocity's
//   variance is 2 (1 - R) T per component), Haff's cooling
//   T = T0/(1 + t/t0)^2 with t0 = 6/((1 - e^2) f0), energy kept in
//   expectation for e = 1, and the anisotropy relaxing at (4/5) f (Grad's
//   13-moment production of hard spheres, p/mu = (16/5) n d^2 sqrt(pi T)).
// SPDX-License-Identifier: GPL-3.0-or-later

#include "fictitiousPartnerCollision.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace roughWall;

namespace
{

constexpr double pi_ = 3.14159265358979323846;

struct Rng
{
    std::mt19937_64 engine;
    std::uniform_real_distribution<double> unit{0.0, 1.0};
    std::normal_distribution<double> normal;

    explicit Rng(unsigned seed) : engine(seed) {}
    double operator()() { return unit(engine); }
    double gauss() { return normal(engine); }
    Vec3 gauss3(const Vec3& s) { return Vec3(s.x()*gauss(), s.y()*gauss(), s.z()*gauss()); }
    Vec3 direction() { return Vec3(gauss(), gauss(), gauss()).normalized(); }
};

// Pair collision --------------------------------------------------------------

TEST(FictitiousPartnerPair, smoothSpheresClosedForm)
{
    // u1' = u1 - (1 + e) m2/(m1 + m2) (g.n) n for smooth spheres
    Rng rng(1);
    for (int i = 0; i < 1000; ++i)
    {
        const Vec3 u2 = rng.gauss3(Vec3(1, 2, 3));
        Vec3 n = rng.direction();
        Vec3 u1 = u2 + rng.gauss3(Vec3(1, 1, 1));
        if ((u1 - u2).dot(n) > 0) n = -n;
        const double e = rng(), ratio = rng();
        const Vec3 expected = u1 - (1 + e)*ratio*(u1 - u2).dot(n)*n;
        Vec3 w = Vec3::Zero();
        collideWithPartner<false>(u1, w, 1e-4, u2, Vec3::Zero(), 2e-4, ratio, n, {e, 0.0});
        EXPECT_LT((u1 - expected).norm(), 1e-12*(1 + expected.norm()));
    }
}

TEST(FictitiousPartnerPair, invariantsOfTwoHardSpheres)
{
    Rng rng(2);
    int noSlipCases = 0;
    for (int i = 0; i < 200000; ++i)
    {
        const double r1 = 1e-4*(0.2 + rng()), r2 = 1e-4*(0.2 + rng());
        const double m1 = r1*r1*r1, m2 = r2*r2*r2;       // one density
        const double I1 = 0.4*m1*r1*r1, I2 = 0.4*m2*r2*r2;
        const PairMaterial mat{rng(), rng()};
        Vec3 n = rng.direction();
        const Vec3 u1 = rng.gauss3(Vec3(1, 1, 1)), u2 = rng.gauss3(Vec3(1, 1, 1));
        if ((u1 - u2).dot(n) > 0) n = -n;
        const Vec3 w1 = rng.gauss3(Vec3(1, 1, 1))/r1, w2 = rng.gauss3(Vec3(1, 1, 1))/r2;

        Vec3 u1p = u1, w1p = w1;
        collideWithPartner<true>(u1p, w1p, r1, u2, w2, r2, m2/(m1 + m2), n, mat);

        // The impulse on 1, and the partner's change it implies
        const Vec3 J = m1*(u1p - u1);
        const Vec3 u2p = u2 - J/m2;
        // (impulse -J at the partner's contact point, +r2 n from its centre)
        const Vec3 w2q = w2 + (r2*n).cross(-J)/I2;

        const double Jn = J.dot(n);
        const Vec3 Jt = J - Jn*n;
        EXPECT_GE(Jn, -1e-15);
        EXPECT_LE(Jt.norm(), mat.mu*Jn*(1 + 1e-12) + 1e-18);

        auto energy = [&](const Vec3& a, const Vec3& wa, const Vec3& b, const Vec3& wb)
        {
            return 0.5*m1*a.squaredNorm() + 0.5*I1*wa.squaredNorm()
                 + 0.5*m2*b.squaredNorm() + 0.5*I2*wb.squaredNorm();
        };
        const double E0 = energy(u1, w1, u2, w2), E1 = energy(u1p, w1p, u2p, w2q);
        EXPECT_LE(E1, E0*(1 + 1e-12));

        // Angular momentum of 1 about the contact point (at -r1 n from it)
        const Vec3 L0 = m1*(r1*n).cross(u1) + I1*w1;
        const Vec3 L1 = m1*(r1*n).cross(u1p) + I1*w1p;
        EXPECT_LT((L1 - L0).norm(), 1e-10*(L0.norm() + m1*r1*u1.norm()));

        // No-slip: the contact's slip vanishes after the collision
        const Vec3 c0 = (u1 - u2) - (r1*w1 + r2*w2).cross(n);
        const Vec3 slip0 = c0 - c0.dot(n)*n;
        if (slip0.norm() <= 3.5*mat.mu*(1 + mat.e)*std::abs(c0.dot(n)))
        {
            ++noSlipCases;
            const Vec3 c1 = (u1p - u2p) - (r1*w1p + r2*w2q).cross(n);
            const Vec3 slip1 = c1 - c1.dot(n)*n;
            EXPECT_LT(slip1.norm(), 1e-10*(1 + slip0.norm()));
        }
    }
    EXPECT_GT(noSlipCases, 1000);
}

TEST(FictitiousPartnerPair, elasticSmoothKeepsPairEnergy)
{
    Rng rng(3);
    for (int i = 0; i < 10000; ++i)
    {
        const double m1 = 0.5 + rng(), m2 = 0.5 + rng();
        Vec3 n = rng.direction();
        const Vec3 u1 = rng.gauss3(Vec3(1, 1, 1)), u2 = rng.gauss3(Vec3(1, 1, 1));
        if ((u1 - u2).dot(n) > 0) n = -n;
        Vec3 u1p = u1, w = Vec3::Zero();
        collideWithPartner<false>(u1p, w, 1, u2, Vec3::Zero(), 1, m2/(m1 + m2), n, {1.0, 0.0});
        const Vec3 u2p = u2 - m1/m2*(u1p - u1);
        const double E0 = m1*u1.squaredNorm() + m2*u2.squaredNorm();
        const double E1 = m1*u1p.squaredNorm() + m2*u2p.squaredNorm();
        EXPECT_NEAR(E1, E0, 1e-12*E0);
    }
}

TEST(FictitiousPartnerPair, contactNormalUniformOverTheDisc)
{
    // cos^2(theta) of the normal against -g is the fraction 1 - (b/R)^2 of
    // the disc: uniform on [0, 1]. Kolmogorov-Smirnov at 1 % (1.63/sqrt(N)).
    Rng rng(4);
    const int N = 20000;
    std::vector<double> c2;
    const Vec3 g = Vec3(0.3, -2, 0.7);
    double sumAzimuthCos = 0;
    for (int i = 0; i < N; ++i)
    {
        const Vec3 n = partnerContactNormal(g, rng);
        ASSERT_NEAR(n.norm(), 1, 1e-12);
        ASSERT_LT(n.dot(g), 0);
        const double c = -n.dot(g.normalized());
        c2.push_back(c*c);
        const Vec3 across = (-n - c*g.normalized());
        if (across.norm() > 1e-9) sumAzimuthCos += across.normalized().dot(Vec3::UnitX().cross(g).normalized());
    }
    std::sort(c2.begin(), c2.end());
    double D = 0;
    for (int i = 0; i < N; ++i)
    {
        D = std::max({D, std::abs(c2[i] - double(i)/N), std::abs(c2[i] - double(i + 1)/N)});
    }
    EXPECT_LT(D, 1.63/std::sqrt(N));
    // The azimuth: mean cosine against a fixed direction 0 within 4 s.e.
    EXPECT_LT(std::abs(sumAzimuthCos/N), 4*std::sqrt(0.5/N));
}

TEST(FictitiousPartnerPair, correlationFormula)
{
    EXPECT_DOUBLE_EQ(partnerCorrelation(0), 1);
    EXPECT_NEAR(partnerCorrelation(1), std::exp(-0.55), 1e-15);
    EXPECT_NEAR(partnerCorrelation(10), std::exp(-0.55*std::pow(10, 0.4)), 1e-15);
}

// A homogeneous gas in one cell -----------------------------------------------

//- N parcels of diameter d, one real particle each, in one cell of volume V
struct Gas
{
    std::vector<Vec3> u;
    double d = 1e-3;
    double V = 1;

    ParticleCellStatistics statistics() const
    {
        ParticleCellStatistics s({}, 2);
        s.clear(1);
        for (const Vec3& ui : u) s.add(0, d, 1, ui, Vec3::Zero());
        s.finish([this](int) { return V; });
        return s;
    }

    Vec3 temperature() const
    {
        Vec3 mean = Vec3::Zero(), sq = Vec3::Zero();
        for (const Vec3& ui : u) { mean += ui; sq += ui.cwiseProduct(ui); }
        mean /= u.size();
        return sq/u.size() - mean.cwiseProduct(mean);
    }
};

Gas maxwellian(int N, const Vec3& T, Rng& rng)
{
    Gas gas;
    const Vec3 s = T.cwiseSqrt();
    for (int i = 0; i < N; ++i) gas.u.push_back(rng.gauss3(s));
    return gas;
}

//- Collisions per particle and second over `steps` steps of dt, the gas
//  frozen (statistics fixed, velocities restored after each draw)
double frequency(const Gas& gas, double dt, double R, int steps, Rng& rng, double& stdError)
{
    const auto s = gas.statistics();
    FictitiousPartnerSettings settings;
    settings.material = {1, 0};
    double sum = 0, sum2 = 0;
    long n = 0;
    for (int step = 0; step < steps; ++step)
    {
        for (const Vec3& ui : gas.u)
        {
            Vec3 u = ui, w = Vec3::Zero();
            const auto out = collideWithFictitiousPartners<false>
                (u, w, gas.d, 1, 0, dt, R, s, settings, rng);
            sum += out.collisions;
            sum2 += double(out.collisions)*out.collisions;
            ++n;
        }
    }
    const double mean = sum/n;
    stdError = std::sqrt((sum2/n - mean*mean)/n)/dt;
    return mean/dt;
}

TEST(FictitiousPartnerGas, collisionFrequencyOfKineticTheory)
{
    Rng rng(5);
    const double T = 4;
    Gas gas = maxwellian(20000, Vec3(T, T, T), rng);
    gas.V = 20000/1e6;   // n = 1e6 per m^3
    const double T_ = gas.temperature().mean();
    const double f = 4*1e6*gas.d*gas.d*std::sqrt(pi_*T_);
    const double dt = 0.02/f;   // P ~ 0.02
    double se;
    const double measured = frequency(gas, dt, 0, 20, rng, se);
    EXPECT_LT(std::abs(measured - f), 3*se) << measured << " vs " << f << " se " << se;
    EXPECT_LT(se/f, 0.02);
}

TEST(FictitiousPartnerGas, splitStepKeepsTheFrequency)
{
    // dt with P ~ 0.5 > maxProbability 0.1: split into sub-steps; the
    // frequency is that of kinetic theory all the same
    Rng rng(6);
    Gas gas = maxwellian(20000, Vec3(1, 1, 1), rng);
    gas.V = 0.02;
    const double f = 4*1e6*gas.d*gas.d*std::sqrt(pi_*gas.temperature().mean());
    const double dt = 0.5/f;
    double se;
    const double measured = frequency(gas, dt, 0, 3, rng, se);
    EXPECT_LT(std::abs(measured - f), 3*se) << measured << " vs " << f;
    Vec3 u = gas.u[0], w = Vec3::Zero();
    const auto s = gas.statistics();
    const auto out = collideWithFictitiousPartners<false>
        (u, w, gas.d, 1, 0, 40*dt, 0, s, FictitiousPartnerSettings(), rng);
    EXPECT_EQ(out.subSteps, int(std::ceil(out.largestProbability/0.1)));
    EXPECT_GT(out.subSteps, 1);
}

TEST(FictitiousPartnerGas, correlationLowersTheFrequencyAsSqrtOneMinusR)
{
    Rng rng(7);
    Gas gas = maxwellian(20000, Vec3(1, 1, 1), rng);
    gas.V = 0.02;
    const double f0 = 4*1e6*gas.d*gas.d*std::sqrt(pi_*gas.temperature().mean());
    const double dt = 0.05/f0;
    for (double StK : {0.01, 0.3, 3.0})
    {
        const double R = partnerCorrelation(StK);
        double se;
        const double measured = frequency(gas, dt, R, 10, rng, se);
        const double expected = f0*std::sqrt(1 - R);
        EXPECT_LT(std::abs(measured - expected), 3*se)
            << "St_K " << StK << ": " << measured << " vs " << expected;
    }
}

//- Evolve the gas: statistics gathered from the whole gas, then every
//  particle collides (only the real particle changes), step after step
void evolve(Gas& gas, double dt, int steps, const PairMaterial& material, Rng& rng)
{
    FictitiousPartnerSettings settings;
    settings.material = material;
    for (int step = 0; step < steps; ++step)
    {
        const auto s = gas.statistics();
        for (Vec3& u : gas.u)
        {
            Vec3 w = Vec3::Zero();
            collideWithFictitiousPartners<false>(u, w, gas.d, 1, 0, dt, 0, s, settings, rng);
        }
    }
}

TEST(FictitiousPartnerGas, haffCooling)
{
    Rng rng(8);
    const double e = 0.8;
    Gas gas = maxwellian(20000, Vec3(1, 1, 1), rng);
    gas.V = 0.02;
    const double T0 = gas.temperature().mean();
    const double f0 = 4*1e6*gas.d*gas.d*std::sqrt(pi_*T0);
    const double t0 = 6/((1 - e*e)*f0);
    const double dt = 0.02/f0;
    double t = 0;
    for (int block = 0; block < 5; ++block)
    {
        const int steps = 100;
        evolve(gas, dt, steps, {e, 0}, rng);
        t += steps*dt;
        const double T = gas.temperature().mean();
        const double expected = T0/std::pow(1 + t/t0, 2);
        // The energy is a random walk of the collisions' changes: over six
        // seeds T/T0 of this gas scatters by 1.1 % (sd); 3.5 % is ~3 sd
        EXPECT_NEAR(T/expected, 1, 0.035) << "t/t0 = " << t/t0;
    }
    EXPECT_LT(gas.temperature().mean(), 0.6*T0);   // it did cool
}

TEST(FictitiousPartnerGas, elasticSmoothKeepsEnergyInExpectation)
{
    Rng rng(9);
    Gas gas = maxwellian(20000, Vec3(1, 1, 1), rng);
    gas.V = 0.02;
    const double T0 = gas.temperature().mean();
    const double f0 = 4*1e6*gas.d*gas.d*std::sqrt(pi_*T0);
    evolve(gas, 0.05/f0, 100, {1, 0}, rng);    // 5 collisions per particle
    // (a mean P of 0.05 per step: some steps are split; sd 1.1 %, above)
    EXPECT_NEAR(gas.temperature().mean()/T0, 1, 0.035);
}

TEST(FictitiousPartnerGas, anisotropyRelaxesAtTheKineticTheoryRate)
{
    // T_xx - T decays as exp(-(4/5) f t) for elastic smooth spheres
    Rng rng(10);
    const double a = 0.3;
    Gas gas = maxwellian(40000, Vec3(1 + 2*a, 1 - a, 1 - a), rng);
    gas.V = 0.04;
    const Vec3 T0 = gas.temperature();
    const double T = T0.mean();
    const double f = 4*1e6*gas.d*gas.d*std::sqrt(pi_*T);
    const double dt = 0.02/f;
    const int steps = 50;     // one collision per particle
    evolve(gas, dt, steps, {1, 0}, rng);
    const Vec3 T1 = gas.temperature();
    const double ratio = (T1.x() - T1.mean())/(T0.x() - T0.mean());
    const double expected = std::exp(-0.8*f*steps*dt);
    EXPECT_NEAR(ratio, expected, 0.05) << ratio << " vs " << expected;
}

// Statistics ---------------------------------------------------------------

TEST(FictitiousPartnerStatistics, cellsClassesAndPooling)
{
    // Two cells, two classes (bound 1.5 mm); cell 0 holds three parcels of
    // class 0 (its own statistics with minCellParcels = 3) and one of
    // class 1 (pooled)
    ParticleCellStatistics s({1.5e-3}, 3);
    s.clear(3);
    s.add(0, 1e-3, 2, Vec3(1, 0, 0), Vec3::Zero());
    s.add(1, 1e-3, 1, Vec3(5, 0, 0), Vec3::Zero());
    s.add(0, 1e-3, 1, Vec3(4, 0, 0), Vec3::Zero());
    s.add(0, 2e-3, 1, Vec3(0, 7, 0), Vec3::Zero());
    s.add(0, 1e-3, 1, Vec3(-1, 2, 0), Vec3::Zero());
    s.add(1, 2e-3, 3, Vec3(0, 1, 0), Vec3::Zero());
    s.finish([](int cell) { return cell == 0 ? 2.0 : 4.0; });

    EXPECT_DOUBLE_EQ(s.numberDensity(0), 5.0/2);
    EXPECT_DOUBLE_EQ(s.numberDensity(1), 4.0/4);
    EXPECT_DOUBLE_EQ(s.numberDensity(2), 0);
    // Without a parcel of weight 2 of cell 0: 3 real particles in 2 m^3
    EXPECT_DOUBLE_EQ(s.othersNumberDensity(0, 2), 3.0/2);

    // Cell 0, class 0: weights 2, 1, 1 at x = 1, 4, -1; y = 0, 0, 2
    const auto& c00 = s.classState(0, 0);
    EXPECT_FALSE(c00.pooled);
    EXPECT_DOUBLE_EQ(c00.mean.x(), (2*1 + 4 - 1)/4.0);
    const double mx = 1.25, varX = (2*1 + 16 + 1)/4.0 - mx*mx;
    EXPECT_NEAR(c00.rms.x(), std::sqrt(varX), 1e-14);
    EXPECT_NEAR(c00.rms.y(), std::sqrt(4/4.0 - 0.25), 1e-14);

    // Cell 0, class 1: one parcel: the cloud's class 1 (weights 1 and 3)
    const auto& c01 = s.classState(0, 1);
    EXPECT_TRUE(c01.pooled);
    EXPECT_DOUBLE_EQ(c01.mean.y(), (7 + 3)/4.0);

    // Partner diameters drawn with the real particles' weights: 1 mm with
    // probability 4/5 in cell 0
    Rng rng(11);
    int small = 0;
    const int N = 100000;
    for (int i = 0; i < N; ++i) small += s.drawPartnerDiameter(0, rng) < 1.5e-3;
    EXPECT_NEAR(double(small)/N, 0.8, 4*std::sqrt(0.16/N));
    for (int i = 0; i < 1000; ++i)
    {
        const double d = s.drawPartnerDiameter(1, rng);
        EXPECT_TRUE(d == 1e-3 || d == 2e-3);
    }
}

TEST(FictitiousPartnerGas, partnerMassRatioOfTwoSizes)
{
    // A particle (d, u = (1 0 0)) among partners of 2d at rest (rms 0):
    // after a smooth elastic collision, averaged over the impact disc
    // (<cos^2> = 1/2), E[u'] = (1 - (1 + e) m2/(m1 + m2)/2) u, m2/(m1 + m2)
    // = 8/9 for one density: u/9
    const double d = 1e-3;
    ParticleCellStatistics s({1.5e-3}, 1);
    s.clear(1);
    s.add(0, d, 1e-9, Vec3(1, 0, 0), Vec3::Zero());
    for (int i = 0; i < 10; ++i) s.add(0, 2*d, 1, Vec3::Zero(), Vec3::Zero());
    s.finish([](int) { return 1.0; });
    FictitiousPartnerSettings settings;
    settings.material = {1, 0};
    Rng rng(12);
    double sum = 0, sum2 = 0;
    int n = 0;
    const double dt = 0.5/collisionProbability(d, 2*d, 1, 10, 1);
    for (int i = 0; i < 200000; ++i)
    {
        Vec3 u(1, 0, 0), w = Vec3::Zero();
        const auto out = collideWithFictitiousPartners<false>
            (u, w, d, 1e-9, 0, dt, 0, s, settings, rng);
        if (out.collisions == 1)
        {
            sum += u.x();
            sum2 += u.x()*u.x();
            ++n;
        }
    }
    const double mean = sum/n, se = std::sqrt((sum2/n - mean*mean)/n);
    EXPECT_GT(n, 50000);
    EXPECT_LT(std::abs(mean - 1.0/9), 4*se) << mean << " +- " << se;
}

TEST(FictitiousPartnerGas, ownParcelLeftOutOfTheNumberDensity)
{
    // Oracle: parcels of weight w scattered uniformly at random over M
    // equal cells of volume V; the real density is N w/(M V). A particle
    // meets the other parcels of its cell only: their expected number, seen
    // from a parcel, is (N - 1)/M. With N = 3M parcels (3 per cell) the
    // mean collision probability per step, averaged over the parcels, is
    // that of the density (N - 1) w/(M V), where counting the parcel's own
    // weight would give (N - 1 + M) w/(M V), a third more.
    const int M = 200, N = 3*M;
    const double d = 1e-4, V = 1e-9, w = 2, dt = 1e-4;
    Rng rng(13);
    double sumP = 0;
    long parcels = 0;
    for (int round = 0; round < 50; ++round)
    {
        ParticleCellStatistics s({}, 1000);
        s.clear(M);
        std::vector<int> cell(N);
        for (int i = 0; i < N; ++i)
        {
            cell[i] = std::min(int(rng()*M), M - 1);
            s.add(cell[i], d, w, Vec3::Zero(), Vec3::Zero());
        }
        s.finish([V](int) { return V; });
        FictitiousPartnerSettings settings;
        settings.maxProbability = 1e9;   // no split: P is the step's
        for (int i = 0; i < N; ++i)
        {
            // A particle at 1 m/s through partners at rest (rms 0): its P
            // for a typical partner is that of |g| = 1 m/s
            Vec3 u(1, 0, 0), spin = Vec3::Zero();
            const auto out = collideWithFictitiousPartners<false>
                (u, spin, d, w, cell[i], dt, 0, s, settings, rng);
            sumP += out.largestProbability;
            ++parcels;
        }
    }
    const double expected =
        collisionProbability(d, d, 1, (N - 1)*w/(M*V), dt);
    EXPECT_NEAR(sumP/parcels, expected, 0.02*expected)
        << sumP/parcels << " vs " << expected;
}

} // namespace
