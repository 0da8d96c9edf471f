// The rough-wall operator at exactly normal incidence, and the k_n, k_t of a
// wall hit that the OpenFOAM statistics report (wallHitCoefficients).
//
// Oracles, none of which calls the code under test:
//  - normal incidence: at alpha = 90 deg the first facet tilt follows
//    P(gamma, pi/2) of eq. (1.3), [phi(gamma) - phi(gamma + pi)] / erf(...),
//    gamma in (-pi/2, pi/2) (the core redraws overhangs), which is
//    symmetric up to the phi(gamma + pi) term (its mean is 5e-6 rad here). The facet collision of a sphere without spin arriving along -N
//    is written here from the model notes, section 4, in the plane of N and
//    the tilt direction; the moments over P(gamma, pi/2) are integrated by
//    Boost's Gauss-Kronrod quadrature of the literal (1.3), split at the
//    no-slip/sliding boundary and at the tilt beyond which the particle
//    still moves into the wall (found here by bisection). 10^6 wall hits,
//    fixed seed, tolerance 5 standard errors of the sample.
//  - wallHitCoefficients: k_n = -V''.N/V'.N, k_t = V''.t/|V'_t| with t the
//    direction of the incident tangential velocity (model notes (2.5),
//    docs/theory.md), values derived by hand for vectors chosen with
//    integer components.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "roughWallCollision.hpp"
#include "effectiveRestitution.hpp"
#include "testSupport.hh"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace roughWall;
using namespace roughWallTest;

namespace
{

constexpr double piTyped = 3.14159265358979323846;

//- The material of these tests: e 0.8, mu0 = muD = 0.1 (a low friction, so
//  that both regimes and re-collisions occur at Delta = 20 deg)
constexpr double eT = 0.8, muT = 0.1, DeltaDeg = 20;

//- One facet collision at normal incidence, in the plane (x = t, y = N):
//  v = (0, -1), facet normal n = (-sin g, cos g), no spin before
struct FacetOutcome
{
    bool noSlip;
    bool leaves;       //!< v''.N >= 0: the wall hit ends after this facet
    double kn;         //!< v''.N / |v'|
    double vt;         //!< |v''.t| / |v'|
    double rw;         //!< r |w''| / |v'|
};

FacetOutcome facetAtNormalIncidence(double g)
{
    const double nx = -std::sin(g), ny = std::cos(g);
    const double vx = 0, vy = -1;
    const double vn = vx*nx + vy*ny;                 // -cos g < 0
    const double jn = -(1 + eT)*vn;
    const double ux = vx - vn*nx, uy = vy - vn*ny;   // slip (no spin)
    const double slip = std::hypot(ux, uy);
    const bool noSlip = slip <= 3.5*muT*jn;
    const double scale = noSlip ? 2.0/7.0 : muT*jn/slip;
    const double jtx = -scale*ux, jty = -scale*uy;
    const double v2x = vx + jn*nx + jtx, v2y = vy + jn*ny + jty;
    // w'' = -(5/(2 r)) n x jt: r |w''| = 2.5 |n x jt|
    const double rw = 2.5*std::abs(nx*jty - ny*jtx);
    return {noSlip, v2y >= 0, v2y, std::abs(v2x), rw};
}

//- The literal (1.3) at alpha = pi/2 (unnormalised: the erf cancels)
double tiltDensity(double g)
{
    const double D = DeltaDeg*deg;
    const auto phi = [D](double x) { return std::exp(-0.5*x*x/(D*D)); };
    return phi(g) - phi(g + piTyped);
}

//- The tilt in (0, pi/2) where pred changes, by bisection
template<class Pred>
double boundary(const Pred& pred, double lo, double hi)
{
    for (int i = 0; i < 200; ++i)
    {
        const double mid = 0.5*(lo + hi);
        (pred(mid) == pred(lo) ? lo : hi) = mid;
    }
    return 0.5*(lo + hi);
}

//- Expectations over P(gamma, pi/2) truncated to (-pi/2, pi/2)
struct NormalIncidenceOracle
{
    double pLeaves, meanGamma, meanAbsGamma, meanGammaSqr;
    double knGivenLeaves, vtGivenLeaves, rwGivenLeaves, noSlipGivenLeaves;
};

NormalIncidenceOracle normalIncidenceOracle()
{
    const double half = 0.5*piTyped;
    const double gNoSlip =
        boundary([](double g) { return facetAtNormalIncidence(g).noSlip; }, 0, half);
    const double gLeave =
        boundary([](double g) { return facetAtNormalIncidence(g).leaves; }, 0, half);
    EXPECT_LT(gNoSlip, gLeave) << "sliding occurs before the particle stays";

    // Integral of f times the density over (-pi/2, pi/2), split at the kinks
    const auto moment = [&](auto f, bool leavingOnly)
    {
        const double cuts[] = {-half, -gLeave, -gNoSlip, 0, gNoSlip, gLeave, half};
        double sum = 0;
        for (int i = 0; i + 1 < 7; ++i)
        {
            if (leavingOnly && (cuts[i] < -gLeave || cuts[i + 1] > gLeave))
            {
                continue;
            }
            sum += integrate
            (
                [&](double g) { return f(g)*tiltDensity(g); },
                cuts[i], cuts[i + 1]
            );
        }
        return sum;
    };
    const double Z = moment([](double) { return 1.0; }, false);
    const double ZLeaves = moment([](double) { return 1.0; }, true);

    NormalIncidenceOracle o;
    o.pLeaves = ZLeaves/Z;
    o.meanGamma = moment([](double g) { return g; }, false)/Z;
    o.meanAbsGamma = moment([](double g) { return std::abs(g); }, false)/Z;
    o.meanGammaSqr = moment([](double g) { return g*g; }, false)/Z;
    o.knGivenLeaves =
        moment([](double g) { return facetAtNormalIncidence(g).kn; }, true)/ZLeaves;
    o.vtGivenLeaves =
        moment([](double g) { return facetAtNormalIncidence(g).vt; }, true)/ZLeaves;
    o.rwGivenLeaves =
        moment([](double g) { return facetAtNormalIncidence(g).rw; }, true)/ZLeaves;
    o.noSlipGivenLeaves = moment
    (
        [](double g) { return facetAtNormalIncidence(g).noSlip ? 1.0 : 0.0; },
        true
    )/ZLeaves;
    return o;
}

//- Sample mean and its standard error
struct Mean
{
    double n = 0, s = 0, s2 = 0;
    void add(double x) { n += 1; s += x; s2 += x*x; }
    double mean() const { return s/n; }
    double se() const { return std::sqrt(std::max(s2/n - mean()*mean(), 0.0)/n); }
};

void expectWithin(const Mean& m, double reference, const char* what)
{
    // 5 standard errors (fixed seed: the test is deterministic), at least
    // 1e-12 for a quantity that is constant in the sample
    EXPECT_LE(std::abs(m.mean() - reference), 5*m.se() + 1e-12)
        << what << ": sample " << m.mean() << " +- " << m.se()
        << ", oracle " << reference;
}

//- 10^6 wall hits at exactly normal incidence on the wall of normal N,
//  compared with the oracle. emptyDirection: 2-D when non-zero.
void checkNormalIncidence
(
    const Vec3& N,
    bool lateralTilt,
    const Vec3& emptyDirection
)
{
    static const NormalIncidenceOracle o = normalIncidenceOracle();

    RoughWallParameters p;
    p.material = {eT, muT, muT};
    p.roughnessAngle = DeltaDeg*deg;
    p.lateralTilt = lateralTilt;

    StdUniform01<std::mt19937_64> uniform(2026);
    const double r = 50e-6, V = 3;
    Mean leaves, gamma, absGamma, gammaSqr, kn, vt, rw, noSlip, tx, ty;
    // Two wall directions orthogonal to N, for the direction of the rebound
    const Vec3 a = N.unitOrthogonal(), b = N.cross(a);
    double maxOutOfPlane = 0;
    for (int i = 0; i < 1000000; ++i)
    {
        Vec3 v = -V*N;
        Vec3 w = Vec3::Zero();
        const RoughWallReport report =
            collideWithRoughWall<true>(v, w, N, r, p, uniform, emptyDirection);
        ASSERT_GE(report.facetCollisions, 1);
        ASSERT_GE(v.dot(N), 0);

        gamma.add(report.firstGamma);
        absGamma.add(std::abs(report.firstGamma));
        gammaSqr.add(report.firstGamma*report.firstGamma);
        const bool one = report.facetCollisions == 1 && !report.fallback;
        leaves.add(one);
        if (one)
        {
            const Vec3 vT = v - v.dot(N)*N;
            kn.add(v.dot(N)/V);
            vt.add(vT.norm()/V);
            rw.add(r*w.norm()/V);
            noSlip.add(report.noSlip);
            tx.add(v.dot(a)/V);
            ty.add(v.dot(b)/V);
        }
        if (emptyDirection.squaredNorm() > 0)
        {
            // No velocity along the plane normal, spin only about it
            maxOutOfPlane = std::max
            (
                {maxOutOfPlane, std::abs(v.dot(emptyDirection)),
                 r*(w - w.dot(emptyDirection)*emptyDirection).norm()}
            );
        }
    }

    expectWithin(leaves, o.pLeaves, "P(one facet collision)");
    expectWithin(gamma, o.meanGamma, "mean first gamma");
    expectWithin(absGamma, o.meanAbsGamma, "mean |first gamma|");
    expectWithin(gammaSqr, o.meanGammaSqr, "mean first gamma^2");
    expectWithin(kn, o.knGivenLeaves, "mean k_n, one facet");
    expectWithin(vt, o.vtGivenLeaves, "mean |v''_t|/V, one facet");
    expectWithin(rw, o.rwGivenLeaves, "mean r|w''|/V, one facet");
    expectWithin(noSlip, o.noSlipGivenLeaves, "P(no-slip), one facet");
    // The tilt direction is uniform in the wall plane (3-D) or either way
    // along it (2-D): the mean tangential rebound is zero
    expectWithin(tx, 0, "mean v''.a/V");
    expectWithin(ty, 0, "mean v''.b/V");
    EXPECT_EQ(maxOutOfPlane, 0) << "2-D: nothing out of the plane";
}

} // namespace


// The oracle's own numbers, so that a reader can see what is compared: a
// symmetric tilt (mean 0), |gamma| of a half-normal (sqrt(2/pi) Delta), all
// three kinds of hit present
TEST(NormalIncidence, OracleIsSymmetricAndCoversBothRegimes)
{
    const NormalIncidenceOracle o = normalIncidenceOracle();
    const double D = DeltaDeg*deg;
    EXPECT_NEAR(o.meanGamma, 0, 1e-4*D)
        << "symmetric up to phi(gamma + pi), 4.5 sd away at gamma = -90 deg";
    EXPECT_NEAR(o.meanAbsGamma, std::sqrt(2/piTyped)*D, 1e-3*D)
        << "half-normal up to the truncation at 90 deg (4.5 sd)";
    EXPECT_NEAR(o.meanGammaSqr, D*D, 1e-3*D*D);
    EXPECT_GT(o.pLeaves, 0.95);
    EXPECT_LT(o.pLeaves, 0.995) << "re-collisions occur";
    EXPECT_GT(o.noSlipGivenLeaves, 0.85);
    EXPECT_LT(o.noSlipGivenLeaves, 0.97) << "sliding occurs";
}

// 3-D, wall y = 0
TEST(NormalIncidence, OperatorStatisticsMatchTheOracle3D)
{
    checkNormalIncidence(Vec3(0, 1, 0), false, Vec3::Zero());
}

// 3-D, a wall not aligned with the axes, lateral tilt on: the lateral tilt
// rotates the facet normal about the incidence direction -N, i.e. turns the
// (already uniform) tilt direction: the statistics do not change
TEST(NormalIncidence, OperatorStatisticsMatchTheOracleObliqueWallLateralTilt)
{
    checkNormalIncidence(Vec3(1, 2, 3).normalized(), true, Vec3::Zero());
}

// 2-D (plane normal z): the tilt either way along x; nothing out of plane
TEST(NormalIncidence, OperatorStatisticsMatchTheOracle2D)
{
    checkNormalIncidence(Vec3(0, 1, 0), true, Vec3(0, 0, 1));
}


// wallHitCoefficients: k_n = -V''.N/V'.N; k_t = V''.t/|V'_t|, t = V'_t/|V'_t|
// (the projection of the rebound on the incident tangential direction, not
// the ratio of tangential speeds); at normal incidence no k_t. Hand-derived.
TEST(WallHitCoefficients, HandDerivedValues)
{
    struct Case
    {
        Vec3 N, v1, v2;
        bool hasKt;
        double kn, kt;
        double vnIn, vnOut, vtIn, vtOut;   // |V'.N|, V''.N, |V'_t|, V''.t
        const char* what;
    };
    const Vec3 y(0, 1, 0), z(0, 0, 1);
    // An oblique wall: N = (1, 2, 2)/3, tangents t = (2, -2, 1)/3 and
    // N x t = (2, 1, -2)/3 (orthonormal: checked below)
    const Vec3 No = Vec3(1, 2, 2)/3, to = Vec3(2, -2, 1)/3, lo = Vec3(2, 1, -2)/3;
    ASSERT_NEAR(No.dot(to), 0, 1e-16);
    ASSERT_NEAR(No.cross(to).dot(lo), 1, 1e-15);
    const Case cases[] =
    {
        // v1 = (3, -4, 0): |V'_t| = 3, V'.N = -4; V'' = (1.5, 2, 0.5):
        // k_n = 2/4, k_t = 1.5/3 (the out-of-plane 0.5 does not count)
        {y, {3, -4, 0}, {1.5, 2, 0.5}, true, 0.5, 0.5, 4, 2, 3, 1.5,
         "x-y plane"},
        // N = z, V' = (3, 4, -5): t = (0.6, 0.8, 0), |V'_t| = 5;
        // V'' = (4, 3, 1): V''.t = 4.8, k_t = 0.96, k_n = 1/5
        {z, {3, 4, -5}, {4, 3, 1}, true, 0.2, 0.96, 5, 1, 5, 4.8,
         "tangent (0.6, 0.8)"},
        // backward rebound: k_t = -1/2
        {y, {2, -1, 0}, {-1, 0.5, 0}, true, 0.5, -0.5, 1, 0.5, 2, -1,
         "backward"},
        // all of the rebound's tangential velocity sideways: k_t = 0
        // (|V''_t|/|V'_t| would be 3)
        {y, {1, -1, 0}, {0, 1, 3}, true, 1, 0, 1, 1, 1, 0,
         "sideways rebound"},
        // oblique wall: V' = -3 N + 2 t, V'' = 1.5 N - t + 0.7 (N x t)
        {No, -3*No + 2*to, 1.5*No - to + 0.7*lo, true, 0.5, -0.5,
         3, 1.5, 2, -1, "oblique wall"},
        // a rebound still moving into the wall: k_n signed, negative
        {y, {1, -2, 0}, {0.5, -0.4, 0}, true, -0.2, 0.5, 2, -0.4, 1, 0.5,
         "still wallward"},
        // normal incidence: no tangent, no k_t (left 0)
        {y, {0, -2, 0}, {0.3, 1.6, 0.4}, false, 0.8, 0, 2, 1.6, 0, 0,
         "normal incidence"},
        // a tangential part of 1e-16 of |V'| is round-off: normal incidence
        {y, {1e-16, -1, 0}, {0.1, 0.5, 0}, false, 0.5, 0, 1, 0.5, 0, 0,
         "1e-16 tangential"},
        // 1e-14 of |V'| is a direction: k_t = 2e-15/1e-14
        {y, {1e-14, -1, 0}, {2e-15, 0.5, 0}, true, 0.5, 0.2,
         1, 0.5, 1e-14, 2e-15, "1e-14 tangential"},
    };
    for (const Case& c : cases)
    {
        const WallHitCoefficients k = wallHitCoefficients(c.v1, c.v2, c.N);
        EXPECT_EQ(k.hasKt, c.hasKt) << c.what;
        EXPECT_NEAR(k.k.kn, c.kn, 1e-14) << c.what;
        EXPECT_NEAR(k.k.kt, c.kt, 1e-14) << c.what;
        EXPECT_EQ(k.k.kOmega, 0) << c.what;
        // The statistics' impulse-weighted sums add these
        EXPECT_NEAR(k.vnIn, c.vnIn, 1e-14) << c.what;
        EXPECT_NEAR(k.vnOut, c.vnOut, 1e-14) << c.what;
        EXPECT_NEAR(k.vtIn, c.vtIn, 1e-14*c.vtIn + 1e-30) << c.what;
        EXPECT_NEAR(k.vtOut, c.vtOut, 1e-14*std::abs(c.vtOut) + 1e-30)
            << c.what;
    }
}


// collideAndMeasure: the hit and what the statistics count of it, one call.
// Oracle: a smooth wall (Delta = 0), where the hit is one sliding collision
// with the mean wall, written here from the model notes, section 4: with
// N = y, V' = (3, -4, 0), e = 0.8, mu0 = muD = 0.1 the slip 3 exceeds
// 3.5 mu0 (1 + e) |V'.N| = 2.52, so V''.N = 0.8*4 = 3.2, V''.t = 3 - muD
// (1 + e) 4 = 2.28, and the spin gains |Delta omega| = 2.5 muD (1 + e) 4 / r
// = 3.6 rad/s for r = 0.5 (I = 0.4 m r^2); hence k_n = 0.8, k_t = 0.76,
// |V'|^2 - |V''|^2 = 25 - 2.28^2 - 3.2^2 = 9.5616 and |omega'|^2 -
// |omega''|^2 = -12.96. A particle leaving the wall is left alone.
TEST(CollideAndMeasure, SmoothWallHandDerived)
{
    RoughWallParameters p;
    p.material = FacetMaterial{0.8, 0.1, 0.1};
    p.roughnessAngle = 0;
    const Vec3 N(0, 1, 0);
    std::mt19937_64 gen(1);
    std::uniform_real_distribution<double> u(0, 1);
    auto uniform01 = [&]() { return u(gen); };

    Vec3 v(3, -4, 0), w(Vec3::Zero());
    const WallHit hit = collideAndMeasure<true>
    (
        v, w, N, 0.5, p, uniform01, Vec3::Zero()
    );
    EXPECT_TRUE(hit.intoWall);
    EXPECT_EQ(hit.facetCollisions, 1);
    EXPECT_EQ(hit.sliding, 1);
    EXPECT_NEAR(v.x(), 2.28, 1e-14);
    EXPECT_NEAR(v.y(), 3.2, 1e-14);
    EXPECT_TRUE(hit.coefficients.hasKt);
    EXPECT_NEAR(hit.coefficients.k.kn, 0.8, 1e-14);
    EXPECT_NEAR(hit.coefficients.k.kt, 0.76, 1e-14);
    EXPECT_NEAR(hit.coefficients.vnIn, 4, 1e-14);
    EXPECT_NEAR(hit.coefficients.vnOut, 3.2, 1e-14);
    EXPECT_NEAR(hit.coefficients.vtIn, 3, 1e-14);
    EXPECT_NEAR(hit.coefficients.vtOut, 2.28, 1e-14);
    EXPECT_NEAR(hit.speedSqrLoss, 9.5616, 1e-12);
    EXPECT_NEAR(hit.spinSqrLoss, -12.96, 1e-12);

    // Without spin: the same velocity, no spin loss
    Vec3 v2(3, -4, 0), w2(Vec3::Zero());
    const WallHit noSpin = collideAndMeasure<false>
    (
        v2, w2, N, 0.5, p, uniform01, Vec3::Zero()
    );
    EXPECT_NEAR(v2.x(), 2.28, 1e-14);
    EXPECT_EQ(noSpin.spinSqrLoss, 0);
    EXPECT_NEAR(noSpin.speedSqrLoss, 9.5616, 1e-12);

    // Leaving the wall (or grazing it): unchanged, not a hit
    for (const Vec3& away : {Vec3(1, 1, 0), Vec3(1, 0, 0)})
    {
        Vec3 v3(away), w3(0, 0, 2);
        const WallHit none = collideAndMeasure<true>
        (
            v3, w3, N, 0.5, p, uniform01, Vec3::Zero()
        );
        EXPECT_FALSE(none.intoWall);
        EXPECT_EQ(none.facetCollisions, 0);
        EXPECT_EQ(v3, away);
        EXPECT_EQ(w3, Vec3(0, 0, 2));
    }
}
