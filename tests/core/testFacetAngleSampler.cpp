// Exactness of the samplers of P(gamma, alpha): Kolmogorov-Smirnov tests
// against the stable CDF with fixed seeds, the mean against (1.4), and a check
// that the KS test has the power to reject a wrong sampler.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "facetAngleSampler.hpp"
#include "testSupport.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

const std::vector<double> ratios{0, 1e-12, 1e-3, 0.1, 1, 3, 30, 1e5};

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

TEST(FacetAngleSampler, TruncatedNormalIsExact)
{
    for (double h : {1e-3, 0.5, 0.999, 1.0, 1.001, 3.0, 10.0})
    {
        Uniform uniform(77);
        std::vector<double> s(100000);
        for (auto& x : s)
        {
            x = truncatedStandardNormal(h, uniform);
            ASSERT_GT(x, 0);
            ASSERT_LT(x, h);
        }
        const double mass = gaussianMass(0, h);
        EXPECT_LT(ksDistance(s, [&](double x) { return gaussianMass(0, x)/mass; }), ksCritical(s.size()))
            << "h=" << h;
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
