// roughWallStats with e, mu0, muD as functions of the facet impact angle
// (issue 31): the quadrature statistics, with incident spin, against an
// oracle written here: the vector collision of the model notes (facetRebound
// in testSupport.hh) with the coefficients of b = alpha + gamma in closed
// form, weighted by the literal density (1.3), Boost's adaptive
// Gauss-Kronrod split at the kinks found by a dense scan and bisection
// (oracleQuadrature.hh).
// SPDX-License-Identifier: GPL-3.0-or-later

#include "oracleQuadrature.hh"
#include "quadratureStatistics.hh"
#include "testSupport.hh"

#include <gtest/gtest.h>

#include <cmath>

using namespace roughWallStats;
using namespace roughWallStatsTest;

namespace
{

// Of the facet impact angle b [deg]
double eOf(double b) { return 0.9 - 0.004*b; }
double mu0Of(double b) { return 0.12 + 0.3*std::exp(-b/12); }
double muDOf(double b) { return 0.75*mu0Of(b); }

//- The coefficients at b = alpha + gamma [rad]: of the angle between the
//  velocity and the facet plane, min(b, 180 deg - b) (beyond b = 90 deg the
//  particle meets the facet from its other side)
roughWall::FacetMaterial materialAt(double bRad)
{
    const double b = std::min(bRad, roughWall::pi - bRad)/deg;
    return {eOf(b), mu0Of(b), muDOf(b)};
}

struct Means { double kn, kt, kOmega, pNoSlip; };

Means oracle(double DeltaDeg, double AOmega, double alphaDeg)
{
    const double alpha = alphaDeg*deg;
    const auto closed = [&](double g)
    {
        return facetRebound(g, alpha, AOmega, materialAt(alpha + g));
    };
    const FacetTiltQuadrature q(alpha, DeltaDeg*deg, closed, 15, 1e-13);
    Means m;
    m.kn = q.mean([&](double g) { return closed(g).kn; });
    m.kt = q.mean([&](double g) { return closed(g).kt; });
    m.kOmega = q.mean([&](double g) { return closed(g).kOmega; });
    m.pNoSlip = q.mean([&](double g) { return closed(g).noSlip ? 1.0 : 0.0; });
    return m;
}

} // namespace

// Mean k_n, k_t, k_Omega and the no-slip probability, Delta = 8 and 20 deg,
// A_Omega = 0 and 0.5, alpha = 10 and 40 deg: 2e-8 (both quadratures reach
// about 1e-11). The friction falls steeply with b: some cases nearly always
// slide, others roll in more than 20 % of the hits.
TEST(impactDependent, quadratureMatchesTheOracleWithSpin)
{
    Model model;
    model.impact.e = eOf;
    model.impact.mu0 = mu0Of;
    model.impact.muD = muDOf;
    double minNoSlip = 1, maxNoSlip = 0;
    for (const double DeltaDeg : {8.0, 20.0})
    {
        for (const double AOmega : {0.0, 0.5})
        {
            model.Delta = DeltaDeg*deg;
            model.AOmega = AOmega;
            for (const double alphaDeg : {10.0, 40.0})
            {
                const Statistics s = quadratureStatistics
                (
                    model, Incidence::fromDegrees(alphaDeg), QuadratureSettings()
                );
                const Means o = oracle(DeltaDeg, AOmega, alphaDeg);
                const std::string tag = "Delta " + std::to_string(DeltaDeg)
                    + " A " + std::to_string(AOmega) + " alpha " + std::to_string(alphaDeg);
                EXPECT_NEAR(s.meanKn, o.kn, 2e-8) << tag;
                EXPECT_NEAR(s.meanKt, o.kt, 2e-8) << tag;
                EXPECT_NEAR(s.meanKOmega, o.kOmega, 2e-8) << tag;
                EXPECT_NEAR(s.pNoSlip, o.pNoSlip, 2e-8) << tag;
                minNoSlip = std::min(minNoSlip, o.pNoSlip);
                maxNoSlip = std::max(maxNoSlip, o.pNoSlip);
            }
        }
    }
    EXPECT_LT(minNoSlip, 0.1);
    EXPECT_GT(maxNoSlip, 0.2);
}

// Coefficients out of bounds inside the integration range: the quadrature
// throws CoefficientOutOfRange (it never clamps)
TEST(impactDependent, quadratureRefusesCoefficientsOutOfBounds)
{
    Model model;
    model.impact.e = [](double b) { return b < 50 ? 0.8 : 1.3; };
    EXPECT_THROW
    (
        quadratureStatistics(model, Incidence::fromDegrees(45), QuadratureSettings()),
        roughWall::CoefficientOutOfRange
    );
}
