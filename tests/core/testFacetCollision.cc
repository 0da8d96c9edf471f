// The 3-D hard-sphere facet collision: reduction to the corrected closed forms
// (2.6)/(2.7) for in-plane spin (typed in this file from the paper and the
// model notes), and its invariants on a million random inputs (energy, the
// impulse cone |J_t| <= mu |J_n|, exact rolling after a stick).
// SPDX-License-Identifier: GPL-3.0-or-later

#include "effectiveRestitution.hpp"
#include "testSupport.hh"

#include <gtest/gtest.h>

#include <cmath>
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

//- Derevich's closed forms (2.6) (no-slip) and (2.7) (sliding) with the
//  corrections of the model notes, section 3 ((2.3): "eps/7" read as 1 and
//  V'_y(g) > 0 toward the facet; (2.6): k_Omega = -(5/7)(cos g - z sin g)
//  + (2/7) A_Omega and the spin term of k_n is -(2/7) A_Omega/z), typed here
//  from the paper: z = tan alpha, A_Omega = r Omega'_z/V'_x, eps0 the sign of
//  the facet slip, no-slip if |slip| <= (7/2) mu0 (1 + e) (z cos g + sin g).
struct PaperRestitution
{
    double kn, kt, kOmega;
    bool noSlip;
};

PaperRestitution paperClosedForm(double g, double alpha, double A, const FacetMaterial& m)
{
    const double z = std::tan(alpha), c = std::cos(g), s = std::sin(g), e = m.e;
    const double slip = c - z*s + A;
    PaperRestitution k;
    k.noSlip = std::abs(slip) <= 3.5*m.mu0*(1 + e)*(z*c + s);
    if (k.noSlip)
    {
        k.kt = (5.0/7.0*(c - z*s) - 2.0/7.0*A)*c - e*(z*c + s)*s;
        k.kn = e*(c + s/z)*c + (5.0/7.0*(c/z - s) - 2.0/7.0*A/z)*s;
        k.kOmega = -5.0/7.0*(c - z*s) + 2.0/7.0*A;
    }
    else
    {
        const double f = m.muD*(1 + e)*(slip > 0 ? 1 : -1);
        k.kt = ((c - z*s) - f*(s + z*c))*c - e*(z*c + s)*s;
        k.kn = e*(s/z + c)*c + ((c/z - s) - f*(s/z + c))*s;
        k.kOmega = A - 2.5*f*(s + z*c);
    }
    return k;
}

} // namespace

// Oracle: the paper's closed forms as corrected, typed above (paperClosedForm);
// the core's vector collision and its closedFormRestitution (which
// roughWallStats integrates) must both reproduce them.
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

        const PaperRestitution paper = paperClosedForm(gamma, alpha, AOmega, m);
        const auto core = closedFormRestitution(gamma, alpha, AOmega, m);
        // Skip inputs at the regime boundary, where round-off picks the branch
        const double slip = std::cos(gamma) - std::tan(alpha)*std::sin(gamma) + AOmega;
        const double limit = 3.5*m.mu0*(1 + m.e)*(std::tan(alpha)*std::cos(gamma) + std::sin(gamma));
        if (std::abs(std::abs(slip) - limit) < 1e-9*(1 + limit)) continue;

        Vec3 v = v1, w = w1;
        const Regime regime = collideWithFacet<true>(v, w, n, r, m);
        const auto k = restitutionCoefficients(v1, v, w, N, t, r);

        ASSERT_EQ(regime == Regime::noSlip, paper.noSlip);
        ASSERT_EQ(core.regime == Regime::noSlip, paper.noSlip);
        const double scale = 1 + std::abs(paper.kn) + std::abs(paper.kt) + std::abs(paper.kOmega);
        EXPECT_NEAR(k.kn, paper.kn, 1e-12*scale);
        EXPECT_NEAR(k.kt, paper.kt, 1e-12*scale);
        EXPECT_NEAR(k.kOmega, paper.kOmega, 1e-12*scale);
        EXPECT_NEAR(core.k.kn, paper.kn, 1e-12*scale);
        EXPECT_NEAR(core.k.kt, paper.kt, 1e-12*scale);
        EXPECT_NEAR(core.k.kOmega, paper.kOmega, 1e-12*scale);
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
