// The pdf of a restitution coefficient by the change of variables (2.8) as
// corrected: the analytic facet response behind it, its normalisation, its
// consistency with the exact bin probabilities, and the Monte Carlo histogram.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "coefficientDistribution.hh"
#include "monteCarloStatistics.hh"
#include "effectiveRestitution.hpp"
#include "testSupport.hh"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <vector>

using namespace roughWallStats;
using namespace roughWallStatsTest;

namespace
{

struct Case
{
    double DeltaDeg, alphaDeg, AOmega, e, mu0, muD;
    Coefficient which;
};

const std::vector<Case>& cases()
{
    static const std::vector<Case> list
    {
        {8, 5, 0, 0.8, 0.4, 0.4, Coefficient::kn},      // the paper's figure 3 (a)
        {8, 5, 0, 0.8, 0.4, 0.4, Coefficient::kt},      // figure 3 (b)
        {8, 12, 0, 0.8, 0.4, 0.4, Coefficient::kOmega},
        {8, 30, 0, 0.8, 0.4, 0.2, Coefficient::kt},     // muD < mu0: k_t jumps
        {5, 45, 0.8, 0.8, 0.4, 0.4, Coefficient::kn},   // spin
        {20, 1, 0, 0.8, 0.4, 0.4, Coefficient::kn},     // alpha << Delta
        {8, 90, 0, 0.8, 0.4, 0.4, Coefficient::kn},     // normal incidence
    };
    return list;
}

std::string describe(const Case& c)
{
    return std::string(name(c.which)) + " Delta " + std::to_string(c.DeltaDeg) + " alpha "
        + std::to_string(c.alphaDeg) + " A " + std::to_string(c.AOmega) + " muD "
        + std::to_string(c.muD);
}

} // namespace

// The analytic response (used for roots and Jacobians) equals the tool's
// vector collision and the oracle facetRebound (testSupport.hh: the model
// notes' vector form written in the tests); its derivative equals a
// finite difference of its value; the regime boundaries are where the
// regime changes
TEST(FacetResponse, AnalyticFormIsTheVectorCollisionWithItsDerivative)
{
    std::mt19937_64 engine(5);
    std::uniform_real_distribution<double> unit;
    int checked = 0;
    for (int i = 0; i < 20000; ++i)
    {
        Model m = model(45*unit(engine), 4*unit(engine) - 2, unit(engine), unit(engine));
        m.material.muD = m.material.mu0*unit(engine);
        const Incidence in = Incidence::fromDegrees(0.01 + 89.9*unit(engine));
        const FacetResponse response(m, in);
        const double gamma = -in.alpha + 1e-6 + (0.5*roughWall::pi + in.alpha - 1e-6)*unit(engine);

        Regime regime;
        const Coefficients v = response.collide(gamma, &regime);
        ASSERT_EQ(regime, response.regime(gamma));
        const FacetResponse::Value a = response.analytic(gamma, regime);
        const FacetRebound c = facetRebound(gamma, in.alpha, m.AOmega, m.material);
        ASSERT_EQ(c.noSlip, regime == Regime::noSlip);
        const double scale = 1 + std::abs(v.kn) + std::abs(v.kt) + std::abs(v.kOmega);
        ASSERT_NEAR(a.k.kn, v.kn, 1e-12*scale);
        ASSERT_NEAR(a.k.kt, v.kt, 1e-12*scale);
        ASSERT_NEAR(a.k.kOmega, v.kOmega, 1e-12*scale);
        ASSERT_NEAR(c.kn, v.kn, 1e-12*scale);
        ASSERT_NEAR(c.kt, v.kt, 1e-12*scale);
        ASSERT_NEAR(c.kOmega, v.kOmega, 1e-12*scale);

        const double h = 1e-6;
        const auto plus = response.analytic(gamma + h, regime);
        const auto minus = response.analytic(gamma - h, regime);
        const double dscale = scale + std::abs(a.dk.kn) + std::abs(a.dk.kt) + std::abs(a.dk.kOmega);
        ASSERT_NEAR(a.dk.kn, (plus.k.kn - minus.k.kn)/(2*h), 1e-6*dscale);
        ASSERT_NEAR(a.dk.kt, (plus.k.kt - minus.k.kt)/(2*h), 1e-6*dscale);
        ASSERT_NEAR(a.dk.kOmega, (plus.k.kOmega - minus.k.kOmega)/(2*h), 1e-6*dscale);

        for (const double g : response.regimeBoundaries(-in.alpha, 0.5*roughWall::pi))
        {
            const double d = 1e-9;
            ASSERT_NE(response.regime(g - d), response.regime(g + d)) << g;
            ++checked;
        }
    }
    EXPECT_GT(checked, 1000);
}

// The density integrates to 1 (less any atom). Between consecutive critical
// values it is smooth but may have inverse-square-root singularities at
// either end (extrema of k(gamma)): k = k_i + (k_i+1 - k_i) sin^2(theta/2)
// removes them, and Gauss-Kronrod does the rest.
TEST(CoefficientDistribution, DensityIntegratesToOne)
{
    for (const Case& c : cases())
    {
        SCOPED_TRACE(describe(c));
        const Model m = model(c.DeltaDeg, c.AOmega, c.e, c.mu0, c.muD);
        const CoefficientDistribution d(m, Incidence::fromDegrees(c.alphaDeg), c.which);
        const std::vector<double> k = d.criticalValues();
        double total = 0;
        for (std::size_t i = 0; i + 1 < k.size(); ++i)
        {
            const double a = k[i], width = k[i + 1] - k[i];
            const auto f = [&](double theta)
            {
                const double s = std::sin(0.5*theta);
                return d.density(a + width*s*s)*0.5*width*std::sin(theta);
            };
            total += boost::math::quadrature::gauss_kronrod<double, 61>::integrate
            (
                f, 0, roughWall::pi, 12, 1e-12
            );
        }
        double atoms = 0;
        for (const auto& atom : d.atoms()) atoms += atom.probability;
        std::printf("%s: integral of the density %.12f\n", describe(c).c_str(), total);
        EXPECT_NEAR(total + atoms, 1, 1e-8);
    }
}

// The exact bin probabilities sum to 1 over the whole range, and the density
// is their derivative: (P(k + h) - P(k - h))/2h -> pdf(k)
TEST(CoefficientDistribution, DensityIsTheDerivativeOfTheExactProbability)
{
    for (const Case& c : cases())
    {
        SCOPED_TRACE(describe(c));
        const Model m = model(c.DeltaDeg, c.AOmega, c.e, c.mu0, c.muD);
        const CoefficientDistribution d(m, Incidence::fromDegrees(c.alphaDeg), c.which);
        const std::vector<double> k = d.criticalValues();
        EXPECT_NEAR(d.probability(k.front() - 1, k.back() + 1), 1, 1e-13);

        const auto [lo, hi] = d.essentialRange(1e-4);
        EXPECT_GT(d.probability(lo, hi + 1e-12*std::abs(hi)), 1 - 2e-4 - 1e-12);
        int compared = 0;
        for (int i = 1; i < 40; ++i)
        {
            const double x = lo + (hi - lo)*i/40;
            const double h = 1e-6*(hi - lo);
            bool nearCritical = false;
            for (const double kc : k) nearCritical = nearCritical || std::abs(x - kc) < 1e-3*(hi - lo);
            if (nearCritical) continue;
            const double finite = d.probability(x - h, x + h)/(2*h);
            EXPECT_NEAR(d.density(x), finite, 1e-5*finite + 1e-9) << x;
            ++compared;
        }
        EXPECT_GT(compared, 30);
    }
}

// The histogram of 1e6 exact samples against the exact bin probabilities:
// chi-square over 40 bins below dof + 5 sqrt(2 dof); and the density at the
// bin centre against the histogram within 5 standard errors where it is
// smooth across the bin
TEST(CoefficientDistribution, MatchesTheMonteCarloHistogram)
{
    MonteCarloSettings settings;
    settings.samples = 1000000;
    settings.seed = 17;
    for (const Case& c : cases())
    {
        SCOPED_TRACE(describe(c));
        const Model m = model(c.DeltaDeg, c.AOmega, c.e, c.mu0, c.muD);
        const Incidence in = Incidence::fromDegrees(c.alphaDeg);
        const CoefficientDistribution d(m, in, c.which);
        const auto [lo, hi] = d.essentialRange(1e-4);
        const int bins = 40;
        std::vector<double> edges(bins + 1);
        for (int i = 0; i <= bins; ++i) edges[i] = i == bins ? hi : lo + (hi - lo)*i/bins;
        const Histogram h = sampleHistogram(m, in, c.which, edges, settings);

        const double n = static_cast<double>(h.samples);
        double chi2 = 0;
        int dof = 0, smoothBins = 0;
        for (int i = 0; i < bins; ++i)
        {
            const double p = d.probability(edges[i], edges[i + 1]);
            const double expected = n*p;
            if (expected < 5) continue;
            chi2 += std::pow(h.counts[i] - expected, 2)/expected;
            ++dof;

            // bin-centre density: compare where the bin holds no critical value
            bool smooth = true;
            for (const double kc : d.criticalValues()) smooth = smooth && !(kc >= edges[i] && kc <= edges[i + 1]);
            if (!smooth) continue;
            const double width = edges[i + 1] - edges[i];
            const double centre = d.density(0.5*(edges[i] + edges[i + 1]));
            const double histogram = h.counts[i]/(n*width);
            const double se = std::sqrt(static_cast<double>(h.counts[i]))/(n*width);
            // the centre value differs from the bin mean by O(width^2 pdf'')
            EXPECT_NEAR(centre, histogram, 5*se + 0.01*centre) << "bin " << i;
            ++smoothBins;
        }
        --dof;   // the total is fixed
        std::printf("%s: chi2 %.1f for %d degrees of freedom\n", describe(c).c_str(), chi2, dof);
        EXPECT_LT(chi2, dof + 5*std::sqrt(2.0*dof));
        EXPECT_GT(smoothBins, 10);
        // outside the range: at most the 2e-4 the range leaves out (4 se)
        EXPECT_LT(h.below + h.above, 2e-4*n + 4*std::sqrt(2e-4*n));
    }
}

// Sliding without friction keeps the spin: k_Omega = A_Omega is an atom
TEST(CoefficientDistribution, FrictionlessSlidingGivesAnAtomOfKOmega)
{
    const Model m = model(8, 0.5, 0.8, 0, 0);
    const CoefficientDistribution d(m, Incidence::fromDegrees(20), Coefficient::kOmega);
    ASSERT_EQ(d.atoms().size(), 1u);
    EXPECT_DOUBLE_EQ(d.atoms()[0].k, 0.5);
    EXPECT_NEAR(d.atoms()[0].probability, 1, 1e-13);
    EXPECT_NEAR(d.probability(0.49, 0.51), 1, 1e-13);
}
