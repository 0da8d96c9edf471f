// Monte Carlo statistics (the exact sampler) against the quadrature, the
// full operator (--recollide), the lateral tilt, reproducibility by seed.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "monteCarloStatistics.hh"
#include "quadratureStatistics.hh"
#include "testSupport.hh"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace roughWallStats;
using namespace roughWallStatsTest;

namespace
{

//- |quadrature - Monte Carlo| in standard errors (0 if both are exact)
double zScore(double quadrature, double monteCarlo, double se)
{
    const double d = std::abs(quadrature - monteCarlo);
    return d == 0 ? 0 : d/se;
}

//- Standard error of a sample proportion, from the exact probability p (the
//  sample's own is 0 when no sample falls in a class of probability ~1e-9);
//  at least 1/n: below that one count is the resolution
double binomialSe(double p, long long n)
{
    p = std::min(1.0, std::max(0.0, p));
    return std::max(std::sqrt(p*(1 - p)/n), 1.0/n);
}

struct Case
{
    double DeltaDeg, alphaDeg, AOmega;
};

} // namespace

// 1e6 samples per case; every mean, standard deviation and probability within
// 4 standard errors (the cases are fixed by the seed: the test is
// deterministic; 4 sigma has a two-sided chance of 6e-5 per quantity)
TEST(MonteCarlo, AgreesWithQuadratureWithinFourStandardErrors)
{
    const std::vector<Case> cases
    {
        {8, 0.05, 0},     // alpha near 0
        {8, 1, 0},
        {8, 11.6, 0},
        {5, 30, 0.5},
        {8, 60, -0.5},
        {20, 3, 1.0},
        {45, 20, 0},      // 6.1 % overhangs removed (6.064 %, testQuadrature)
        {8, 89.5, 0},     // alpha near 90
        {5, 90, 0},       // normal incidence: k_n only
    };
    MonteCarloSettings settings;
    settings.samples = 1000000;
    settings.seed = 2026;
    double worst = 0;
    for (const Case& c : cases)
    {
        SCOPED_TRACE("Delta " + std::to_string(c.DeltaDeg) + " alpha " + std::to_string(c.alphaDeg)
                     + " A " + std::to_string(c.AOmega));
        const Model m = model(c.DeltaDeg, c.AOmega);
        const Incidence in = Incidence::fromDegrees(c.alphaDeg);
        const Statistics q = quadratureStatistics(m, in);
        const Statistics s = monteCarloStatistics(m, in, settings);
        std::vector<double> z
        {
            zScore(q.meanKn, s.meanKn, s.seMeanKn),
            zScore(q.sdKn, s.sdKn, s.seSdKn),
            zScore(q.meanAbsKn, s.meanAbsKn, s.seMeanAbsKn),
            zScore(q.pNoSlip, s.pNoSlip, binomialSe(q.pNoSlip, s.samples)),
            zScore(q.pWallward, s.pWallward, binomialSe(q.pWallward, s.samples)),
        };
        if (in.tangentialDefined())
        {
            z.insert(z.end(),
            {
                zScore(q.meanKt, s.meanKt, s.seMeanKt),
                zScore(q.sdKt, s.sdKt, s.seSdKt),
                zScore(q.meanKOmega, s.meanKOmega, s.seMeanKOmega),
                zScore(q.sdKOmega, s.sdKOmega, s.seSdKOmega),
            });
        }
        for (std::size_t i = 0; i < z.size(); ++i)
        {
            EXPECT_LT(z[i], 4) << "quantity " << i;
            worst = std::max(worst, z[i]);
        }
        std::printf("Delta %4g alpha %5g A %4g: mean kn %.6f (Q) %.6f +- %.6f (MC), "
                    "mean kt %.6f %.6f +- %.6f, largest |z| %.2f\n",
                    c.DeltaDeg, c.alphaDeg, c.AOmega, q.meanKn, s.meanKn, s.seMeanKn,
                    q.meanKt, s.meanKt, s.seMeanKt, *std::max_element(z.begin(), z.end()));
    }
    std::printf("largest |quadrature - Monte Carlo| / standard error: %.2f\n", worst);
}

TEST(MonteCarlo, ReproducibleBySeedAndIndependentOfOtherAngles)
{
    const Model m = model(8, 0.3);
    MonteCarloSettings settings;
    settings.samples = 20000;
    settings.seed = 7;
    const Incidence in = Incidence::fromDegrees(12.5);
    const Statistics a = monteCarloStatistics(m, in, settings);
    const Statistics b = monteCarloStatistics(m, in, settings);
    EXPECT_EQ(a.meanKn, b.meanKn);
    EXPECT_EQ(a.sdKt, b.sdKt);
    EXPECT_EQ(a.pNoSlip, b.pNoSlip);
    settings.seed = 8;
    const Statistics c = monteCarloStatistics(m, in, settings);
    EXPECT_NE(a.meanKn, c.meanKn);
    // The stream is a fixed function of (seed, alpha): the first uniforms
    Uniform01 u(7, 12.5), v(7, 12.5), w(7, 12.6);
    const double u0 = u(), v0 = v(), w0 = w();
    EXPECT_EQ(u0, v0);
    EXPECT_NE(u0, w0);
    EXPECT_GE(u0, 0);
    EXPECT_LT(u0, 1);
}

// The full operator: the particle always leaves (k_n >= 0, p_wallward = 0);
// the second facet collision happens exactly as often as the first one
// leaves the particle moving toward the wall (the first collision draws the
// same tilts as the one-collision model from the same stream)
TEST(MonteCarlo, RecollideLeavesTheWallAndCountsTheExtraCollisions)
{
    MonteCarloSettings single, full;
    single.samples = full.samples = 400000;
    single.seed = full.seed = 11;
    full.recollide = true;
    for (const Case& c : std::vector<Case>{{8, 2, 0}, {8, 12, 0}, {5, 20, 0.5}, {20, 40, 0}})
    {
        SCOPED_TRACE("alpha " + std::to_string(c.alphaDeg));
        const Model m = model(c.DeltaDeg, c.AOmega);
        const Incidence in = Incidence::fromDegrees(c.alphaDeg);
        const Statistics q = quadratureStatistics(m, in);
        const Statistics r = monteCarloStatistics(m, in, full);
        const Statistics s = monteCarloStatistics(m, in, single);
        EXPECT_EQ(r.pWallward, 0);
        EXPECT_GE(r.meanKn, 0);
        // P(N >= 2) = p_wallward; E[N] - 1 = P(N >= 2) + P(N >= 3) + ...
        const double extra = r.meanFacetCollisions - 1;
        EXPECT_GT(extra, q.pWallward - 4*s.sePWallward);
        EXPECT_LT(extra, 1.1*q.pWallward + 4*r.seMeanFacetCollisions);
        EXPECT_LT(r.pFallback, 1e-4);
        // Re-collision raises k_n: the wall-ward part of k_n is turned around
        EXPECT_GT(r.meanKn, s.meanKn);
        std::printf("alpha %g: p_wallward %.5f, mean facet collisions %.5f, mean kn %.5f -> %.5f\n",
                    c.alphaDeg, q.pWallward, r.meanFacetCollisions, s.meanKn, r.meanKn);
    }
}

// Isotropic 3-D roughness: the facet also turns sideways about the incidence
// direction; it lowers mean k_n at Delta = 8, alpha = 45 from 0.771 (in-plane,
// quadrature) to about 0.765 (model notes, section 4)
TEST(MonteCarlo, LateralTiltShiftsMeanKnAsDocumented)
{
    MonteCarloSettings settings;
    settings.samples = 400000;
    settings.seed = 3;
    settings.lateral = true;
    settings.recollide = true;
    const Model m = model(8);
    const Incidence in = Incidence::fromDegrees(45);
    const Statistics q = quadratureStatistics(m, in);
    const Statistics s = monteCarloStatistics(m, in, settings);
    std::printf("alpha 45: mean kn in-plane %.5f, with lateral tilt %.5f +- %.5f\n",
                q.meanKn, s.meanKn, s.seMeanKn);
    EXPECT_NEAR(q.meanKn, 0.771, 0.001);
    EXPECT_NEAR(s.meanKn, 0.765, 0.002);
    EXPECT_GT(q.meanKn - s.meanKn, 4*s.seMeanKn);
}
