// roughWallStats with e, mu0, muD as functions of the facet impact angle
// (issue 31): the quadrature statistics, with incident spin, against an
// oracle written here: the vector collision of the model notes (facetRebound
// in testSupport.hh) with the coefficients of b = alpha + gamma in closed
// form, weighted by the literal density (1.3), Boost's adaptive
// Gauss-Kronrod split at the kinks found by a dense scan and bisection.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "quadratureStatistics.hh"
#include "testSupport.hh"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

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
    const double alpha = alphaDeg*deg, Delta = DeltaDeg*deg;
    const auto density = [&](double g)
    {
        if (g <= -alpha) return 0.0;
        return std::exp(-g*g/(2*Delta*Delta))*-std::expm1(-2*alpha*(g + alpha)/(Delta*Delta));
    };
    const auto closed = [&](double g)
    {
        return facetRebound(g, alpha, AOmega, materialAt(alpha + g));
    };
    const double lo = std::max(-alpha, -40*Delta), hi = std::min(0.5*roughWall::pi, 40*Delta);
    const auto state = [&](double g)
    {
        const auto r = closed(g);
        return 2*r.noSlip + (r.kn < 0);
    };
    std::vector<double> breaks{lo};
    const int n = 20000;
    for (int i = 0; i < n; ++i)
    {
        double a = lo + (hi - lo)*i/n, b = lo + (hi - lo)*(i + 1)/n;
        if (state(a) != state(b))
        {
            const int sa = state(a);
            for (int j = 0; j < 100; ++j)
            {
                const double mid = 0.5*(a + b);
                (state(mid) == sa ? a : b) = mid;
            }
            breaks.push_back(0.5*(a + b));
        }
    }
    breaks.push_back(hi);
    const auto integrate = [&](const std::function<double(double)>& f)
    {
        double sum = 0;
        for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
        {
            sum += boost::math::quadrature::gauss_kronrod<double, 61>::integrate
            (
                f, breaks[i], breaks[i + 1], 15, 1e-13
            );
        }
        return sum;
    };
    const double Z = integrate(density);
    Means m;
    m.kn = integrate([&](double g) { return density(g)*closed(g).kn; })/Z;
    m.kt = integrate([&](double g) { return density(g)*closed(g).kt; })/Z;
    m.kOmega = integrate([&](double g) { return density(g)*closed(g).kOmega; })/Z;
    m.pNoSlip = integrate([&](double g) { return closed(g).noSlip ? density(g) : 0.0; })/Z;
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
