// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Numerical building blocks: bracketed root finding on a scan, and a globally
// adaptive Gauss-Kronrod (10/21-point) quadrature of a vector of integrands
// that share their nodes. The Kronrod nodes and weights are Boost.Math's.
#pragma once

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace roughWallStats
{

//- Root of f in [a, b] where f(a) and f(b) differ in sign, to full precision
template<class F>
double bracketedRoot(const F& f, double a, double b, double fa, double fb)
{
    if (fa == 0) return a;
    if (fb == 0) return b;
    std::uintmax_t iterations = 200;
    const auto bracket = boost::math::tools::toms748_solve
    (
        f, a, b, fa, fb, boost::math::tools::eps_tolerance<double>(), iterations
    );
    return 0.5*(bracket.first + bracket.second);
}

//- The sign changes of f on (a, b), located on n equal sub-intervals and
//  refined to full precision; ascending. Two roots closer than (b - a)/n
//  can be missed: f then barely changes sign between them (a near-tangency),
//  which leaves a sliver of negligible probability.
template<class F>
std::vector<double> rootsByScan(const F& f, double a, double b, int n = 256)
{
    std::vector<double> roots;
    if (!(b > a))
    {
        return roots;
    }
    double x0 = a, f0 = f(a);
    for (int i = 1; i <= n; ++i)
    {
        const double x1 = i == n ? b : a + (b - a)*i/n;
        const double f1 = f(x1);
        if ((f0 < 0 && f1 > 0) || (f0 > 0 && f1 < 0))
        {
            const double r = bracketedRoot(f, x0, x1, f0, f1);
            if (r > a && r < b)
            {
                roots.push_back(r);
            }
        }
        else if (f1 == 0 && i < n)
        {
            roots.push_back(x1);
        }
        x0 = x1;
        f0 = f1;
    }
    return roots;
}

template<std::size_t C>
using Vector = std::array<double, C>;

template<std::size_t C>
struct QuadratureResult
{
    Vector<C> integral{};
    Vector<C> error{};   //!< estimated absolute error, |Kronrod - Gauss| summed
    Vector<C> l1{};      //!< integral of |f|: the scale of the tolerance
    int intervals = 0;
    bool converged = true;
};

//- Integral over [breakpoints.front(), breakpoints.back()] of a vector-valued
//  f(x) -> Vector<C>, smooth between consecutive breakpoints. The interval with
//  the largest error relative to its tolerance is bisected until, for every
//  component c, the summed error estimate |K21 - G10| is at most
//  max(tolerance * integral of |f_c|, absoluteTolerance[c]). |K21 - G10| is
//  the error of the 10-point Gauss rule: a pessimistic bound of the Kronrod
//  value's error that is kept. absoluteTolerance is the round-off floor of
//  integrands computed with cancellation.
template<std::size_t C, class F>
QuadratureResult<C> integrateAdaptive
(
    const F& f,
    const std::vector<double>& breakpoints,
    double tolerance,
    int maxIntervals = 4000,
    const Vector<C>& absoluteTolerance = Vector<C>{}
)
{
    using GK = boost::math::quadrature::gauss_kronrod<double, 21>;
    using G = boost::math::quadrature::gauss<double, 10>;
    const auto& x = GK::abscissa();
    const auto& wk = GK::weights();
    const auto& wg = G::weights();

    struct Interval
    {
        double a, b;
        Vector<C> integral, error, l1;
        bool splittable;
    };

    const auto rule = [&](double a, double b)
    {
        const double mid = 0.5*(a + b), half = 0.5*(b - a);
        Interval I{a, b, {}, {}, {}, true};
        Vector<C> kronrod{}, gauss{}, l1{};
        const Vector<C> f0 = f(mid);
        for (std::size_t c = 0; c < C; ++c)
        {
            kronrod[c] = wk[0]*f0[c];
            l1[c] = wk[0]*std::abs(f0[c]);
        }
        for (std::size_t i = 1; i < x.size(); ++i)
        {
            const Vector<C> fp = f(mid + half*x[i]);
            const Vector<C> fm = f(mid - half*x[i]);
            for (std::size_t c = 0; c < C; ++c)
            {
                kronrod[c] += wk[i]*(fp[c] + fm[c]);
                l1[c] += wk[i]*(std::abs(fp[c]) + std::abs(fm[c]));
                if (i & 1)
                {
                    gauss[c] += wg[i/2]*(fp[c] + fm[c]);
                }
            }
        }
        for (std::size_t c = 0; c < C; ++c)
        {
            I.integral[c] = half*kronrod[c];
            I.error[c] = half*std::abs(kronrod[c] - gauss[c]);
            I.l1[c] = half*l1[c];
        }
        // Bisection stops where the midpoint is no longer distinct
        I.splittable = mid > a && mid < b && half > 4*std::numeric_limits<double>::epsilon()*std::abs(mid);
        return I;
    };

    std::vector<Interval> intervals;
    for (std::size_t i = 0; i + 1 < breakpoints.size(); ++i)
    {
        if (breakpoints[i + 1] > breakpoints[i])
        {
            intervals.push_back(rule(breakpoints[i], breakpoints[i + 1]));
        }
    }

    QuadratureResult<C> result;
    for (;;)
    {
        Vector<C> error{}, l1{};
        for (const Interval& I : intervals)
        {
            for (std::size_t c = 0; c < C; ++c)
            {
                error[c] += I.error[c];
                l1[c] += I.l1[c];
            }
        }
        Vector<C> allowed{};
        bool done = true;
        for (std::size_t c = 0; c < C; ++c)
        {
            allowed[c] = std::max(tolerance*l1[c], absoluteTolerance[c]);
            done = done && error[c] <= allowed[c];
        }
        if (done || static_cast<int>(intervals.size()) >= maxIntervals)
        {
            result.converged = done;
            break;
        }
        // The worst interval, measured against each component's tolerance
        std::size_t worst = intervals.size();
        double worstScore = 0;
        for (std::size_t i = 0; i < intervals.size(); ++i)
        {
            if (!intervals[i].splittable) continue;
            for (std::size_t c = 0; c < C; ++c)
            {
                if (allowed[c] > 0)
                {
                    const double score = intervals[i].error[c]/allowed[c];
                    if (score > worstScore)
                    {
                        worstScore = score;
                        worst = i;
                    }
                }
            }
        }
        if (worst == intervals.size())
        {
            result.converged = false;   // only unsplittable intervals left
            break;
        }
        const Interval I = intervals[worst];
        const double mid = 0.5*(I.a + I.b);
        intervals[worst] = rule(I.a, mid);
        intervals.push_back(rule(mid, I.b));
    }

    for (const Interval& I : intervals)
    {
        for (std::size_t c = 0; c < C; ++c)
        {
            result.integral[c] += I.integral[c];
            result.error[c] += I.error[c];
            result.l1[c] += I.l1[c];
        }
    }
    result.intervals = static_cast<int>(intervals.size());
    return result;
}

} // namespace roughWallStats
