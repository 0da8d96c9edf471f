// The oracle's quadrature over the facet tilt, shared by the roughWallStats
// tests (testQuadrature.cc, testImpactDependent.cc): the literal density
// (1.3) of the facet tilt gamma at incidence alpha, up to its constant
// factor (normalised numerically), and integrals over gamma split at the
// kinks of a facet rebound (regime changes, sign of k_n) found by a dense
// scan and bisection, each piece by Boost's adaptive Gauss-Kronrod.
// Nothing of the tool or the core: the rebound is the caller's (testSupport.hh's
// facetRebound).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "testSupport.hh"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace roughWallStatsTest
{

class FacetTiltQuadrature
{
public:

    //- alpha, Delta [rad]; rebound(gamma): the facet rebound at tilt gamma;
    //  maxDepth, tolerance: of each Gauss-Kronrod piece
    FacetTiltQuadrature
    (
        double alpha,
        double Delta,
        std::function<FacetRebound(double)> rebound,
        unsigned maxDepth,
        double tolerance
    )
    :
        alpha_(alpha),
        Delta_(Delta),
        maxDepth_(maxDepth),
        tolerance_(tolerance)
    {
        // Kinks by dense sampling and bisection: regime changes and sign
        // of k_n
        const double lo = std::max(-alpha, -40*Delta);
        const double hi = std::min(0.5*roughWall::pi, 40*Delta);
        const auto state = [&](double g)
        {
            const auto r = rebound(g);
            return 2*r.noSlip + (r.kn < 0);
        };
        breaks_.push_back(lo);
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
                breaks_.push_back(0.5*(a + b));
            }
        }
        breaks_.push_back(hi);
    }

    //- (1.3) up to its constant factor, with exp(-g^2/2D^2) -
    //  exp(-(g+2a)^2/2D^2) = exp(-g^2/2D^2) (1 - exp(-2a(g+a)/D^2)) so that
    //  alpha << Delta keeps its digits
    double density(double g) const
    {
        if (g <= -alpha_) return 0.0;
        return std::exp(-g*g/(2*Delta_*Delta_))
            *-std::expm1(-2*alpha_*(g + alpha_)/(Delta_*Delta_));
    }

    //- The integral of density(g) f(g) over gamma
    double integral(const std::function<double(double)>& f) const
    {
        double sum = 0;
        for (std::size_t i = 0; i + 1 < breaks_.size(); ++i)
        {
            sum += boost::math::quadrature::gauss_kronrod<double, 61>::integrate
            (
                [&](double g) { return density(g)*f(g); },
                breaks_[i], breaks_[i + 1], maxDepth_, tolerance_
            );
        }
        return sum;
    }

    //- The mean of f(gamma) under the density
    double mean(const std::function<double(double)>& f) const
    {
        if (norm_ == 0) norm_ = integral([](double) { return 1.0; });
        return integral(f)/norm_;
    }

private:

    double alpha_, Delta_;
    unsigned maxDepth_;
    double tolerance_;
    std::vector<double> breaks_;
    mutable double norm_ = 0;
};

} // namespace roughWallStatsTest
