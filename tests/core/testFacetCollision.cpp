// The 3-D hard-sphere facet collision: reduction to the corrected closed forms
// (2.6)/(2.7) for in-plane spin, and its invariants on a million random inputs.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "restitutionCoefficients.hpp"
#include "testSupport.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace roughWall;
using namespace roughWallTest;

namespace
{

struct RandomInputs
{
    std::mt19937_64 engine;
    std::uniform_real_distribution<double> unit{0.0, 1.0};

    explicit RandomInputs(unsigned seed) : engine(seed) {}

    double uniform(double a, double b) { return a + (b - a)*unit(engine); }

    Vec3 direction()
    {
        std::normal_distribution<double> normal;
        Vec3 x(normal(engine), normal(engine), normal(engine));
        return x.normalized();
    }

    FacetMaterial material()
    {
        FacetMaterial m;
        m.e = uniform(0, 1);
        m.mu0 = uniform(0, 1);
        m.muD = uniform(0, m.mu0);
        return m;
    }
};

//- Kinetic energy per unit mass, I = m d^2/10 = (2/5) m r^2
double energy(const Vec3& v, const Vec3& w, double r)
{
    return 0.5*v.squaredNorm() + 0.2*r*r*w.squaredNorm();
}

} // namespace

TEST(FacetCollision, ReducesToCorrectedClosedFormsForInPlaneSpin)
{
    RandomInputs in(2024);
    int compared = 0, noSlip = 0;
    for (int i = 0; i < 100000; ++i)
    {
        const double alpha = in.uniform(0.01, 1.55);
        const double gamma = in.uniform(-alpha + 1e-3, 1.5);
        const double AOmega = in.uniform(-3, 3);
        const FacetMaterial m = in.material();
        const double r = in.uniform(1e-5, 1e-2);
        const double V = in.uniform(0.1, 30);

        const Vec3 N(0, 1, 0), t(1, 0, 0), z(0, 0, 1);
        const Vec3 v1 = V*Vec3(std::cos(alpha), -std::sin(alpha), 0);
        const Vec3 w1 = (AOmega*V*std::cos(alpha)/r)*z;
        const Vec3 n(-std::sin(gamma), std::cos(gamma), 0);

        const auto closed = closedFormRestitution(gamma, alpha, AOmega, m);
        // Skip inputs at the regime boundary, where round-off picks the branch
        const double slip = std::cos(gamma) - std::tan(alpha)*std::sin(gamma) + AOmega;
        const double limit = 3.5*m.mu0*(1 + m.e)*(std::tan(alpha)*std::cos(gamma) + std::sin(gamma));
        if (std::abs(std::abs(slip) - limit) < 1e-9*(1 + limit)) continue;

        Vec3 v = v1, w = w1;
        const Regime regime = collideWithFacet<true>(v, w, n, r, m);
        const auto k = restitutionCoefficients(v1, v, w, N, t, r);

        ASSERT_EQ(regime, closed.regime);
        const double scale = 1 + std::abs(closed.k.kn) + std::abs(closed.k.kt) + std::abs(closed.k.kOmega);
        EXPECT_NEAR(k.kn, closed.k.kn, 1e-12*scale);
        EXPECT_NEAR(k.kt, closed.k.kt, 1e-12*scale);
        EXPECT_NEAR(k.kOmega, closed.k.kOmega, 1e-12*scale);
        ++compared;
        noSlip += regime == Regime::noSlip;
    }
    // Both regimes were exercised
    EXPECT_GT(compared, 99000);
    EXPECT_GT(noSlip, 10000);
    EXPECT_GT(compared - noSlip, 10000);
}

TEST(FacetCollision, InvariantsOnAMillionRandomInputs)
{
    RandomInputs in(7);
    for (int i = 0; i < 1000000; ++i)
    {
        const Vec3 n = in.direction();
        Vec3 v = in.uniform(1e-3, 50)*in.direction();
        if (v.dot(n) > 0) v = -v;
        if (v.dot(n) == 0) continue;
        const double r = std::pow(10.0, in.uniform(-7, -2));
        const Vec3 w = in.uniform(0, 10)*in.uniform(0, 1)*v.norm()/r*in.direction();
        const FacetMaterial m = in.material();

        Vec3 v2 = v, w2 = w;
        const Regime regime = collideWithFacet<true>(v2, w2, n, r, m);

        ASSERT_TRUE(v2.allFinite() && w2.allFinite());
        const double E1 = energy(v, w, r), E2 = energy(v2, w2, r);
        ASSERT_LE(E2, E1*(1 + 1e-12));
        // Normal restitution on the facet
        ASSERT_NEAR(v2.dot(n), -m.e*v.dot(n), 1e-12*v.norm());
        // Angular momentum about the contact point is conserved:
        // (2/5) r^2 w + r n x v per unit mass
        const Vec3 L1 = 0.4*r*r*w + r*n.cross(v), L2 = 0.4*r*r*w2 + r*n.cross(v2);
        ASSERT_LE((L2 - L1).norm(), 1e-11*(L1.norm() + r*v.norm()));
        // Coulomb: |J_t| <= mu |J_n|
        const Vec3 J = v2 - v;
        const double Jn = J.dot(n);
        const double Jt = (J - Jn*n).norm();
        const double mu = regime == Regime::noSlip ? m.mu0 : m.muD;
        ASSERT_LE(Jt, mu*Jn + 1e-12*v.norm());
        if (regime == Regime::noSlip)
        {
            // Ends in exact rolling: no slip at the contact point
            const Vec3 c = v2 - r*w2.cross(n);
            ASSERT_LE((c - c.dot(n)*n).norm(), 1e-11*(v.norm() + r*w.norm()));
        }
    }
}

TEST(FacetCollision, ZeroSlipAndNoSpinAreSafe)
{
    const Vec3 n(0, 1, 0);
    // Pure normal impact: slip exactly zero
    Vec3 v(0, -2, 0), w = Vec3::Zero();
    EXPECT_EQ(collideWithFacet<true>(v, w, n, 1e-3, {0.8, 0.0, 0.0}), Regime::noSlip);
    EXPECT_EQ(v, Vec3(0, 1.6, 0));
    EXPECT_EQ(w, Vec3::Zero());
    // Rolling particle: contact velocity tangential part exactly zero
    const double r = 0.5;
    v = Vec3(1, -1, 0);
    w = Vec3(0, 0, -2);   // v_t + r w x (-n) = 1 - r*2 = 0
    collideWithFacet<true>(v, w, n, r, {0.5, 0.4, 0.4});
    EXPECT_TRUE(v.allFinite() && w.allFinite());
    EXPECT_DOUBLE_EQ(v.x(), 1);
    // Without spin: the spin vector is neither read nor written
    Vec3 untouched(std::nan(""), 1, 2);
    v = Vec3(3, -1, 0);
    collideWithFacet<false>(v, untouched, n, 1e-3, {0.8, 1.0, 1.0});
    EXPECT_TRUE(v.allFinite());
    EXPECT_TRUE(std::isnan(untouched.x()));
    // No-slip on a smooth wall without spin: k_t = 5/7, k_n = e
    EXPECT_DOUBLE_EQ(v.x(), 3.0*5/7);
    EXPECT_DOUBLE_EQ(v.y(), 0.8);
}

TEST(FacetCollision, SlidingNeverReversesTheSlip)
{
    // muD > mu0 (rejected by the adapters) would reverse the slip: the core caps it
    const Vec3 n(0, 1, 0);
    Vec3 v(1, -1, 0), w = Vec3::Zero();
    const double r = 1e-3;
    const double E1 = energy(v, w, r);
    EXPECT_EQ(collideWithFacet<true>(v, w, n, r, {1.0, 0.01, 5.0}), Regime::sliding);
    const Vec3 c = v - r*w.cross(n);
    EXPECT_GE(c.x(), -1e-15);
    EXPECT_LE(energy(v, w, r), E1);
}
