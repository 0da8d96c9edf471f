// Tests of P(gamma, alpha), eq. (1.3): normalisation, moments (1.4), corrected
// (1.6), CDF and survival function, against independent quadrature and the
// exact limits.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "CollisionAngleDistribution.hpp"
#include "testSupport.hh"

#include <gtest/gtest.h>

#include <vector>

using namespace roughWall;
using namespace roughWallTest;

namespace
{

const std::vector<double> Deltas{1e-12, 0.1*deg, 1*deg, 5*deg, 8*deg, 30*deg, 45*deg};
const std::vector<double> ratios{1e-12, 1e-6, 1e-3, 0.1, 0.5, 1, 2, 3, 5, 10, 30};

//- Integral of g(gamma) P(gamma, alpha) by Gauss-Kronrod, split at the mode
//  region so that narrow peaks are resolved
template<class G>
double expectation(const CollisionAngleDistribution& P, double alpha, const G& g)
{
    const double Delta = P.Delta();
    const auto f = [&](double gamma) { return g(gamma)*P.pdf(gamma, alpha); };
    // beyond 12 Delta from the mode region the mass is below 1e-31
    const double lo = std::max(-alpha, -12*Delta);
    const double hi = 12*Delta;
    double sum = 0;
    const int pieces = 12;
    for (int i = 0; i < pieces; ++i)
    {
        sum += integrate(f, lo + (hi - lo)*i/pieces, lo + (hi - lo)*(i + 1)/pieces);
    }
    return sum;
}

} // namespace

TEST(CollisionAngleDistribution, NormalisedAndMomentsMatchQuadrature)
{
    for (double Delta : Deltas)
    {
        const CollisionAngleDistribution P(Delta);
        for (double ratio : ratios)
        {
            const double alpha = ratio*Delta;
            if (alpha > 0.5*pi) continue;
            SCOPED_TRACE(testing::Message() << "Delta=" << Delta << " alpha/Delta=" << ratio);
            const double norm = expectation(P, alpha, [](double) { return 1.0; });
            EXPECT_LT(std::abs(norm - 1), 1e-10);
            const double m1 = expectation(P, alpha, [](double g) { return g; });
            const double m2 = expectation(P, alpha, [](double g) { return g*g; });
            // (1.4) is well conditioned except where <gamma> ~ 0 (alpha >> Delta):
            // there compare with the scale Delta
            EXPECT_LT(std::abs(P.mean(alpha) - m1), 1e-10*std::max(std::abs(m1), 1e-3*Delta));
            EXPECT_LT(relativeError(P.meanSquare(alpha), m2), 1e-10);
        }
    }
}

TEST(CollisionAngleDistribution, LimitsOfTheMoments)
{
    const double Delta = 8*deg;
    const CollisionAngleDistribution P(Delta);
    // alpha << Delta: Rayleigh moments, printed in the paper after (1.6)
    // (the corrections are O(alpha/Delta): 1e-12 relative at alpha = 1e-12 Delta)
    for (double alpha : {0.0, 1e-300, 1e-12*Delta})
    {
        EXPECT_NEAR(P.mean(alpha), std::sqrt(pi/2)*Delta, 1e-11*Delta);
        EXPECT_NEAR(P.meanSquare(alpha), 2*Delta*Delta, 1e-11*Delta*Delta);
        EXPECT_NEAR(P.standardDeviation(alpha), Delta*std::sqrt(2 - pi/2), 1e-10*Delta);
    }
    // alpha >> Delta: the plain normal N(0, Delta)
    EXPECT_NEAR(P.mean(30*Delta), 0, 1e-12*Delta);
    EXPECT_NEAR(P.standardDeviation(30*Delta), Delta, 1e-12*Delta);
}

TEST(CollisionAngleDistribution, PrintedEquation16IsWrong)
{
    // The printed <gamma^2> = Delta^2/erf(A) {1 + ...} diverges like 1/A;
    // the corrected form is finite and matches quadrature (test above).
    const double Delta = 8*deg;
    const CollisionAngleDistribution P(Delta);
    const double alpha = 1e-3*Delta;
    const double A = alpha/(std::sqrt(2.0)*Delta);
    const double printed = Delta*Delta/std::erf(A)
        *(1 + 2/std::sqrt(pi)*A*std::exp(-A*A) - 4*A*A*std::erfc(A));
    EXPECT_GT(printed, 100*P.meanSquare(alpha));
}

TEST(CollisionAngleDistribution, PdfLimits)
{
    const double Delta = 5*deg;
    const CollisionAngleDistribution P(Delta);
    for (double gamma : {-0.5*Delta, 0.1*Delta, Delta, 3*Delta})
    {
        // alpha >> Delta: N(0, Delta)
        const double normal = std::exp(-0.5*gamma*gamma/(Delta*Delta))/(std::sqrt(2*pi)*Delta);
        EXPECT_LT(relativeError(P.pdf(gamma, 1e5*Delta), normal), 1e-13);
        if (gamma > 0)
        {
            // alpha << Delta: Rayleigh in gamma
            const double rayleigh = gamma/(Delta*Delta)*std::exp(-0.5*gamma*gamma/(Delta*Delta));
            EXPECT_LT(relativeError(P.pdf(gamma, 0), rayleigh), 1e-14);
            EXPECT_LT(relativeError(P.pdf(gamma, 1e-9*Delta), rayleigh), 1e-8);
            EXPECT_LT(relativeError(P.pdf(gamma, 1e-300), rayleigh), 1e-14);
        }
    }
    // Shadow: no facet with gamma <= -alpha is hit
    EXPECT_EQ(P.pdf(-0.2, 0.2), 0);
    EXPECT_EQ(P.pdf(-0.3, 0.2), 0);
    EXPECT_EQ(P.cdf(-0.2, 0.2), 0);
    EXPECT_EQ(P.sf(-0.2, 0.2), 1);
}

TEST(CollisionAngleDistribution, CdfAndSurvivalMatchQuadratureInBothTails)
{
    for (double Delta : {1*deg, 8*deg, 45*deg})
    {
        const CollisionAngleDistribution P(Delta);
        for (double ratio : {0.0, 1e-12, 1e-3, 0.1, 1.0, 3.0, 30.0, 1e5})
        {
            const double alpha = ratio*Delta;
            const auto pdf = [&](double g) { return P.pdf(g, alpha); };
            // Points from the lower tail (beta -> 0) to the upper tail
            for (double b : {1e-6, 1e-3, 0.1, 0.5, 1.0, 2.0, 4.0, 8.0})
            {
                SCOPED_TRACE(testing::Message() << "Delta=" << Delta/deg
                    << " alpha/Delta=" << ratio << " beta/Delta=" << b);
                const double gammaLow = b*Delta - alpha;           // lower side
                const double gammaHigh = alpha + b*Delta;          // beyond the mode
                const double cdfRef = integrate(pdf, -alpha, gammaLow);
                if (cdfRef > 1e-300)
                {
                    EXPECT_LT(relativeError(P.cdf(gammaLow, alpha), cdfRef), 1e-10);
                }
                const double sfRef = integrate(pdf, gammaHigh, gammaHigh + 40*Delta);
                if (sfRef > 1e-300)
                {
                    EXPECT_LT(relativeError(P.sf(gammaHigh, alpha), sfRef), 1e-10);
                }
                EXPECT_NEAR(P.cdf(gammaLow, alpha) + P.sf(gammaLow, alpha), 1, 1e-14);
            }
        }
    }
}

TEST(CollisionAngleDistribution, SmoothWallIsAStep)
{
    const CollisionAngleDistribution P(0);
    EXPECT_EQ(P.cdf(-1e-9, 0.3), 0);
    EXPECT_EQ(P.cdf(0, 0.3), 1);
    EXPECT_EQ(P.mean(0.3), 0);
    EXPECT_EQ(P.meanSquare(0.3), 0);
}
