// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Probability mass of the standard normal distribution on an interval,
// accurate to a few ulps in relative terms for every interval: short
// intervals by Gauss-Legendre quadrature (no cancellation), tails by erfc.
#pragma once

#include "vectorAndPi.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace roughWall
{

constexpr double sqrt2 = 1.41421356237309504880;
constexpr double invSqrt2Pi = 0.39894228040143267794;

//- Standard normal density
inline double standardNormalPdf(double u)
{
    return invSqrt2Pi*std::exp(-0.5*u*u);
}

namespace detail
{
//- 20-point Gauss-Legendre nodes and weights on [-1, 1] (positive half)
constexpr std::array<std::array<double, 2>, 10> gaussLegendre20{{
    {7.65265211334973383e-02, 1.52753387130725782e-01},
    {2.27785851141645096e-01, 1.49172986472603658e-01},
    {3.73706088715419549e-01, 1.42096109318381875e-01},
    {5.10867001950827126e-01, 1.31688638449176526e-01},
    {6.36053680726515025e-01, 1.18194531961518245e-01},
    {7.46331906460150796e-01, 1.01930119817240261e-01},
    {8.39116971822218782e-01, 8.32767415767046715e-02},
    {9.12234428251325835e-01, 6.26720483341094425e-02},
    {9.63971927277913809e-01, 4.06014298003862170e-02},
    {9.93128599185094885e-01, 1.76140071391532732e-02}
}};
} // namespace detail

//- Integral of a smooth function over [a, c] by 20-point Gauss-Legendre
template<class Function>
double gaussLegendre20(const Function& f, double a, double c)
{
    const double mid = 0.5*(a + c);
    const double half = 0.5*(c - a);
    double sum = 0;
    for (const auto& nw : detail::gaussLegendre20)
    {
        sum += nw[1]*(f(mid - half*nw[0]) + f(mid + half*nw[0]));
    }
    return half*sum;
}

//- Mass of the standard normal distribution on [a, a + width] (0 if
//  width <= 0). The width is passed on its own so that narrow intervals keep
//  their relative accuracy (a and a + width may agree in most digits).
//  Intervals on which the density varies by less than a factor e are
//  integrated by quadrature (exact to round-off, no cancellation); the rest
//  by differences of erfc taken on the side where they do not cancel.
namespace detail
{
//- Mass on [a, c] of the given width: the quadrature uses a and the width,
//  the erfc differences a and c, so neither loses digits to the other
inline double gaussianMassOn(double a, double c, double width)
{
    if (!(width > 0))
    {
        return 0;
    }
    const double farthest = std::max(std::abs(a), std::abs(c));
    if (width < 2 && width*farthest < 1)
    {
        const double half = 0.5*width;
        const double mid = a + half;
        double sum = 0;
        for (const auto& nw : detail::gaussLegendre20)
        {
            sum += nw[1]*(standardNormalPdf(mid - half*nw[0]) + standardNormalPdf(mid + half*nw[0]));
        }
        return half*sum;
    }
    if (a >= 0)
    {
        return 0.5*(std::erfc(a/sqrt2) - std::erfc(c/sqrt2));
    }
    if (c <= 0)
    {
        return 0.5*(std::erfc(-c/sqrt2) - std::erfc(-a/sqrt2));
    }
    // a < 0 < c and width >= 1: the mass is at least 0.38, no cancellation
    return 1 - 0.5*(std::erfc(-a/sqrt2) + std::erfc(c/sqrt2));
}
} // namespace detail

inline double gaussianMassFrom(double a, double width)
{
    // an infinite width reaches +inf even from a = -inf (-inf + inf is NaN)
    return detail::gaussianMassOn(a, std::isinf(width) ? width : a + width, width);
}

//- Mass of the standard normal distribution on [a, c] (0 if c <= a)
inline double gaussianMass(double a, double c)
{
    return detail::gaussianMassOn(a, c, c - a);
}

} // namespace roughWall
