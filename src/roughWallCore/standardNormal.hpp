// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Standard normal variates by the ziggurat method (Marsaglia and Tsang 2000,
// in the form of Doornik 2005, "An improved ziggurat method to generate
// normal random samples"): 128 layers of equal area under exp(-x^2/2); in
// 98.8 % of the draws one uniform number and one multiplication, no
// logarithm, square root or sine. The wedges and the tail beyond r are
// sampled exactly by rejection, so the variates are exactly N(0, 1) for
// exact uniform numbers.
//
// The layer and the abscissa come from one uniform number u in [0, 1):
// 128 u = i + f with i the layer and f in [0, 1) (exact for u on a binary
// grid, which leaves f 46 of the 53 bits). Doornik's objection to
// Marsaglia and Tsang's original, which took both from the same 32 bits,
// does not apply: here they are disjoint bits of the number.
//
// The tables are built once, at static initialisation, with r solved so that
// the top layer closes exactly (the published r = 3.442619855899 leaves it
// 1.2e-9 too large).
#pragma once

#include "vectorAndPi.hpp"

#include <array>
#include <cmath>

namespace roughWall
{
namespace detail
{

//- Attempts of a rejection loop before its fallback. Every loop of the core
//  accepts with probability >= 0.6 per attempt, so a fallback is taken with
//  probability < 1e-39: it only bounds the work on a broken random stream.
constexpr int maxRejectionAttempts = 100;

//- The ziggurat's layer edges x_i and the ratios x_{i+1}/x_i
struct NormalZiggurat
{
    static constexpr int layers = 128;

    double r = 0;                          //!< start of the tail
    std::array<double, layers + 1> x{};    //!< x_0 = V/f(r) > x_1 = r > ... > x_128 = 0
    std::array<double, layers> ratio{};    //!< x_{i+1}/x_i

    static double f(double x) { return std::exp(-0.5*x*x); }

    //- Area of each layer for a tail starting at r
    static double layerArea(double r)
    {
        return r*f(r) + std::sqrt(0.5*pi)*std::erfc(r/std::sqrt(2.0));
    }

    //- Build the layers down from r; returns the excess of the top layer's
    //  area over V: zero for the right r, negative below it, positive above
    double build(double rTail)
    {
        r = rTail;
        const double V = layerArea(r);
        x[0] = V/f(r);
        x[1] = r;
        for (int i = 2; i < layers; ++i)
        {
            const double fi = f(x[i - 1]) + V/x[i - 1];
            if (!(fi < 1))
            {
                return -1;   // the layers reached the peak too early: r too small
            }
            x[i] = std::sqrt(-2*std::log(fi));
        }
        x[layers] = 0;
        for (int i = 0; i < layers; ++i)
        {
            ratio[i] = x[i + 1]/x[i];
        }
        return x[layers - 1]*(1 - f(x[layers - 1])) - V;
    }

    NormalZiggurat()
    {
        double lo = 3.4, hi = 3.5;   // excess < 0 at lo, > 0 at hi
        for (int i = 0; i < 200; ++i)
        {
            const double mid = 0.5*(lo + hi);
            if (mid == lo || mid == hi)
            {
                break;
            }
            (build(mid) < 0 ? lo : hi) = mid;
        }
        const double excessLo = build(lo);
        if (std::abs(excessLo) > std::abs(build(hi)))
        {
            build(hi);
        }
    }
};

inline const NormalZiggurat normalZiggurat;

//- Tail of the normal beyond r (Marsaglia 1964), as a magnitude > r
template<class Uniform01>
double normalTail(double r, Uniform01& uniform01)
{
    for (int attempt = 0; attempt < maxRejectionAttempts; ++attempt)
    {
        // log(1 - u) for u in [0, 1): finite, unlike log(u)
        const double x = std::log1p(-uniform01())/r;
        const double y = std::log1p(-uniform01());
        if (-2*y >= x*x)   // accepted with probability > 0.9
        {
            return r - x;
        }
    }
    return r;
}

//- One pass of the ziggurat from a uniform number: true and the variate in
//  x if u01 falls inside its layer's rectangle (below the curve)
inline bool zigguratRectangle(double u01, int& i, double& u, double& x)
{
    const NormalZiggurat& z = normalZiggurat;
    const double scaled = z.layers*u01;
    const int layer = static_cast<int>(scaled);
    i = layer & (z.layers - 1);   // 128 only if u01 rounded to 1
    u = 2*(scaled - layer) - 1;   // [-1, 1)
    x = u*z.x[i];
    return std::abs(u) < z.ratio[i];
}

//- The rest of standardNormal after a first pass (layer i, abscissa u)
//  missed its rectangle (1.2 % of the calls): the wedge or the tail of that
//  pass, then further passes. Out of line, so that the 98.8 % stay short.
template<class Uniform01>
#if defined(__GNUC__)
[[gnu::noinline]]
#endif
double standardNormalRest(int i, double u, Uniform01& uniform01)
{
    const NormalZiggurat& z = normalZiggurat;
    for (int attempt = 0; attempt < maxRejectionAttempts; ++attempt)
    {
        if (attempt > 0)
        {
            double x;
            if (zigguratRectangle(uniform01(), i, u, x))
            {
                return x;
            }
        }
        if (i == 0)
        {
            const double tail = normalTail(z.r, uniform01);
            return u < 0 ? -tail : tail;
        }
        // The wedge between x_{i+1} and x_i: accept under the curve
        const double x = u*z.x[i];
        const double f0 = std::exp(-0.5*(z.x[i]*z.x[i] - x*x));           // f(x_i)/f(x)
        const double f1 = std::exp(-0.5*(z.x[i + 1]*z.x[i + 1] - x*x));   // f(x_{i+1})/f(x)
        if (f1 + uniform01()*(f0 - f1) < 1)
        {
            return x;
        }
    }
    return 0;
}

} // namespace detail

//- A standard normal variate (ziggurat). Takes one uniform number in 98.8 %
//  of the calls, about 1.03 on average (each pass accepts with probability
//  >= 0.98; after maxRejectionAttempts passes, only on a broken stream, 0).
//  The first pass's rectangle is inline, the rest out of line.
template<class Uniform01>
inline double standardNormal(Uniform01& uniform01)
{
    int i;
    double u, x;
    if (detail::zigguratRectangle(uniform01(), i, u, x))
    {
        return x;
    }
    return detail::standardNormalRest(i, u, uniform01);
}

//- The most uniform numbers standardNormal can take, on any stream
constexpr long maxStandardNormalDraws =
    detail::maxRejectionAttempts*(1 + 2L*detail::maxRejectionAttempts);

} // namespace roughWall
