// Exactness of the samplers of P(gamma, alpha): Kolmogorov-Smirnov tests
// against the stable CDF with fixed seeds, the mean against (1.4), and a check
// that the KS test has the power to reject a wrong sampler.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "facetAngleSampler.hpp"
#include "standardNormal.hpp"
#include "testSupport.hh"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace roughWall;
using namespace roughWallTest;

namespace
{

using Uniform = StdUniform01<std::mt19937_64>;

//- Critical KS distance at significance 0.001 (asymptotic: 1.9495/sqrt(n))
double ksCritical(std::size_t n)
{
    return 1.9495/std::sqrt(static_cast<double>(n));
}

template<class Cdf>
double ksDistance(std::vector<double> x, const Cdf& cdf)
{
    std::sort(x.begin(), x.end());
    const double n = static_cast<double>(x.size());
    double d = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        const double F = cdf(x[i]);
        d = std::max({d, std::abs(F - i/n), std::abs((i + 1)/n - F)});
    }
    return d;
}

// both methods of the exact sampler and their boundary at h = 1
const std::vector<double> ratios{0, 1e-12, 1e-3, 0.1, 0.999, 1, 1.001, 3, 30, 1e5};

template<class Sampler>
void checkSampler(const Sampler& sampler, std::size_t n, unsigned seedBase)
{
    for (double Delta : {8*deg, 45*deg})
    {
        const CollisionAngleDistribution P(Delta);
        for (double ratio : ratios)
        {
            SCOPED_TRACE(testing::Message() << "Delta=" << Delta/deg << " alpha/Delta=" << ratio);
            const double alpha = ratio*Delta;
            Uniform uniform(seedBase + static_cast<unsigned>(1000*ratio));
            std::vector<double> gamma(n);
            double sum = 0;
            for (auto& g : gamma)
            {
                g = sampler(alpha, Delta, uniform);
                ASSERT_GT(g, -alpha);
                sum += g;
            }
            const double d = ksDistance(gamma, [&](double g) { return P.cdf(g, alpha); });
            EXPECT_LT(d, ksCritical(n));
            // mean within 4 standard errors of (1.4)
            const double se = P.standardDeviation(alpha)/std::sqrt(static_cast<double>(n));
            EXPECT_NEAR(sum/n, P.mean(alpha), 4*se);
        }
    }
}

} // namespace

TEST(FacetAngleSampler, ExactSamplerPassesKolmogorovSmirnov)
{
    checkSampler
    (
        [](double a, double D, Uniform& u) { return sampleFacetAngle(a, D, u); },
        200000, 11
    );
}

TEST(FacetAngleSampler, InverseCdfSamplerPassesKolmogorovSmirnov)
{
    checkSampler
    (
        [](double a, double D, Uniform& u) { return sampleFacetAngleByInversion(a, D, u); },
        50000, 23
    );
}

TEST(FacetAngleSampler, InverseCdfSamplerInvertsTheCdf)
{
    // A monotone map: cdf(sample(U)) == U to round-off
    const double Delta = 8*deg;
    const CollisionAngleDistribution P(Delta);
    for (double ratio : ratios)
    {
        const double alpha = ratio*Delta;
        for (double U : {1e-9, 0.01, 0.3, 0.5, 0.7, 0.99, 1 - 1e-9})
        {
            auto constant = [U]() { return U; };
            const double g = sampleFacetAngleByInversion(alpha, Delta, constant);
            const double F = U > 0.5 ? 1 - P.sf(g, alpha) : P.cdf(g, alpha);
            EXPECT_NEAR(F, U, 1e-12*std::max(std::min(U, 1 - U), 1e-3))
                << "alpha/Delta=" << ratio << " U=" << U;
        }
    }
}

TEST(FacetAngleSampler, KolmogorovSmirnovRejectsASamplerWithoutShadowCorrection)
{
    // N(0, Delta) conditioned on gamma > -alpha (no shadow correction): at
    // alpha = Delta it must be rejected, or the tests above prove nothing.
    const double Delta = 8*deg, alpha = Delta;
    const CollisionAngleDistribution P(Delta);
    Uniform uniform(5);
    std::normal_distribution<double> normal(0, Delta);
    std::mt19937_64 engine(5);
    std::vector<double> gamma;
    while (gamma.size() < 200000)
    {
        const double g = normal(engine);
        if (g > -alpha) gamma.push_back(g);
    }
    EXPECT_GT(ksDistance(gamma, [&](double g) { return P.cdf(g, alpha); }), 5*ksCritical(gamma.size()));
}

TEST(StandardNormal, ZigguratTablesCloseTheTopLayer)
{
    // Every layer has the area V of the base strip with its tail; r is
    // solved so that the top layer (up to the peak f(0) = 1) has it too
    const auto& z = detail::normalZiggurat;
    const double V = detail::NormalZiggurat::layerArea(z.r);
    EXPECT_NEAR(z.r, 3.442619855899, 1e-9);   // Marsaglia and Tsang's value
    for (int i = 1; i < z.layers - 1; ++i)
    {
        const double area = z.x[i]*(detail::NormalZiggurat::f(z.x[i + 1]) - detail::NormalZiggurat::f(z.x[i]));
        ASSERT_NEAR(area, V, 1e-12*V) << "layer " << i;
    }
    const double top = z.x[z.layers - 1]*(1 - detail::NormalZiggurat::f(z.x[z.layers - 1]));
    EXPECT_NEAR(top, V, 1e-12*V);
    EXPECT_EQ(z.x[z.layers], 0);
}

TEST(StandardNormal, PassesKolmogorovSmirnovAndMatchesTheTail)
{
    Uniform uniform(2027);
    const std::size_t n = 1000000;
    std::vector<double> z(n);
    double sum = 0, sum2 = 0, sum4 = 0;
    std::size_t tail = 0;
    const double r = detail::normalZiggurat.r;
    for (auto& x : z)
    {
        x = standardNormal(uniform);
        ASSERT_TRUE(std::isfinite(x));
        sum += x;
        sum2 += x*x;
        sum4 += x*x*x*x;
        tail += std::abs(x) > r;
    }
    const auto Phi = [](double x) { return 0.5*std::erfc(-x/std::sqrt(2.0)); };
    EXPECT_LT(ksDistance(z, Phi), ksCritical(n));
    // Moments within 4 standard errors (sd of x^2: sqrt 2, of x^4: sqrt 96)
    EXPECT_NEAR(sum/n, 0, 4/std::sqrt(double(n)));
    EXPECT_NEAR(sum2/n, 1, 4*std::sqrt(2.0/n));
    EXPECT_NEAR(sum4/n, 3, 4*std::sqrt(96.0/n));
    // The tail beyond r (5.8e-4: KS cannot see it) within 4 standard errors
    const double pTail = std::erfc(r/std::sqrt(2.0));
    EXPECT_NEAR(double(tail)/n, pTail, 4*std::sqrt(pTail/n));
}

TEST(StandardNormal, TailSamplerIsExact)
{
    // Beyond r the density is proportional to exp(-x^2/2): KS against the
    // conditional CDF 1 - erfc(x/sqrt2)/erfc(r/sqrt2)
    Uniform uniform(31);
    const double r = detail::normalZiggurat.r;
    std::vector<double> x(100000);
    for (auto& t : x)
    {
        t = detail::normalTail(r, uniform);
        ASSERT_GE(t, r);
    }
    const double tailMass = std::erfc(r/std::sqrt(2.0));
    EXPECT_LT(ksDistance(x, [&](double t) { return 1 - std::erfc(t/std::sqrt(2.0))/tailMass; }),
              ksCritical(x.size()));
}

TEST(FacetAngleSampler, AcceptanceBoundsDecideAsTheExponential)
{
    // The bounds that skip exp(-y) must never decide otherwise than
    // U < 1 - exp(-y) (grid away from the boundary itself)
    for (double y = 1e-6; y < 1e3; y *= 1.07)
    {
        for (double U = 0.0005; U < 1; U += 0.001)
        {
            const double keep = 1 - U;
            if (std::abs(std::exp(-y) - keep) < 1e-12) continue;
            ASSERT_EQ(detail::acceptOneMinusExp(y, U), std::exp(-y) < keep) << "y=" << y << " U=" << U;
        }
    }
}

TEST(FacetAngleSampler, ReproducibleFromTheSeed)
{
    Uniform a(42), b(42);
    for (int i = 0; i < 1000; ++i)
    {
        ASSERT_EQ(sampleFacetAngle(0.1, 0.14, a), sampleFacetAngle(0.1, 0.14, b));
    }
}

TEST(FacetAngleSampler, SmoothWallGivesZeroTilt)
{
    Uniform u(1);
    EXPECT_EQ(sampleFacetAngle(0.3, 0.0, u), 0);
    EXPECT_EQ(sampleFacetAngleByInversion(0.3, 0.0, u), 0);
}
