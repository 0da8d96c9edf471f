// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Samplers of the collision angle distribution P(gamma, alpha), eq. (1.3).
//
// The random source is any callable `uniform01()` returning a double uniform
// in [0, 1) (a std:: engine through StdUniform01 below, OpenFOAM's
// Random::sample01<scalar>() through a lambda).
//
// Exact sampler (no special functions, bounded cost for every alpha). With
// x = beta/Delta and h = alpha/Delta the density of x is proportional to
//     exp(-(x-h)^2/2) - exp(-(x+h)^2/2) = integral_{|x-h|}^{x+h} u exp(-u^2/2) du,
// a mixture: draw s from N(0,1) truncated to (0, h), then R = sqrt(s^2 - 2 ln U)
// (the Rayleigh tail beyond s) and gamma = Delta (R - 2 s). Derivation in
// docs/theory.md. The truncated normal is drawn by rejection with acceptance
// at least 0.61 (uniform proposal for h < 1, half-normal proposal above).
#pragma once

#include "CollisionAngleDistribution.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace roughWall
{

//- Adapter: a std:: random engine as a uniform01() callable
template<class Engine>
class StdUniform01
{
    Engine engine_;
    std::uniform_real_distribution<double> uniform_{0.0, 1.0};

public:

    explicit StdUniform01(typename Engine::result_type seed) : engine_(seed) {}

    double operator()() { return uniform_(engine_); }
};

namespace detail
{

//- Attempts of a rejection loop before its exact fallback; each attempt is
//  accepted with probability >= 0.6, so the fallback has probability < 1e-39.
constexpr int maxRejectionAttempts = 100;

//- -2 ln(1 - U) for U in [0, 1): twice a unit exponential, never infinite
template<class Uniform01>
double twoExponential(Uniform01& uniform01)
{
    return -2*std::log1p(-uniform01());
}

//- Exact fallback for truncatedStandardNormal: inverse CDF by bisection
template<class Uniform01>
double truncatedStandardNormalByInversion(double h, Uniform01& uniform01)
{
    const double target = uniform01()*gaussianMass(0, h);
    double lo = 0, hi = h;
    for (int i = 0; i < 200 && hi - lo > 1e-16*hi; ++i)
    {
        const double mid = 0.5*(lo + hi);
        (gaussianMass(0, mid) < target ? lo : hi) = mid;
    }
    return 0.5*(lo + hi);
}

} // namespace detail

//- Standard normal variate truncated to (0, h); 0 for h <= 0
template<class Uniform01>
double truncatedStandardNormal(double h, Uniform01& uniform01)
{
    if (!(h > 0))
    {
        return 0;
    }
    if (h < 1)
    {
        // Uniform proposal on (0, h), accepted with exp(-s^2/2) >= 0.61
        for (int i = 0; i < detail::maxRejectionAttempts; ++i)
        {
            const double s = h*uniform01();
            if (detail::twoExponential(uniform01) >= s*s)
            {
                return s;
            }
        }
    }
    else
    {
        // Half-normal proposals, two per Box-Muller pair, accepted with
        // probability erf(h/sqrt2) >= 0.68
        for (int i = 0; i < detail::maxRejectionAttempts; i += 2)
        {
            const double r = std::sqrt(detail::twoExponential(uniform01));
            const double theta = 2*pi*uniform01();
            const double s1 = r*std::abs(std::cos(theta));
            if (s1 < h)
            {
                return s1;
            }
            const double s2 = r*std::abs(std::sin(theta));
            if (s2 < h)
            {
                return s2;
            }
        }
    }
    return detail::truncatedStandardNormalByInversion(h, uniform01);
}

//- Exact sample of gamma ~ P(gamma, alpha) [rad]. Delta = 0 gives 0.
template<class Uniform01>
double sampleFacetAngle(double alpha, double Delta, Uniform01& uniform01)
{
    if (!(Delta > 0))
    {
        return 0;
    }
    const double s = truncatedStandardNormal(alpha/Delta, uniform01);
    // R >= s; the max keeps it so where s*s underflows (alpha < 1e-154 Delta)
    // and the exponential is 0: else gamma = -2 Delta s could pass -alpha
    const double R = std::max(s, std::sqrt(s*s + detail::twoExponential(uniform01)));
    return Delta*(R - 2*s);
}

//- Sample of gamma ~ P(gamma, alpha) by inversion of the CDF: a monotone map
//  from one uniform number. Safeguarded Newton on g = gamma/Delta (not on
//  beta, whose digits are lost to alpha when alpha >> Delta), solving
//  sf = 1 - U in the upper half and cdf = U in the lower half so that the
//  residual keeps its relative accuracy. 5-20x slower than sampleFacetAngle;
//  the test oracle.
template<class Uniform01>
double sampleFacetAngleByInversion
(
    double alpha,
    double Delta,
    Uniform01& uniform01
)
{
    if (!(Delta > 0))
    {
        return 0;
    }
    const CollisionAngleDistribution P(Delta);
    const double U = uniform01();
    const bool upper = U > 0.5;
    const double target = upper ? 1 - U : U;
    const auto residual = [&](double g)
    {
        const double gamma = Delta*g;
        return upper ? target - P.sf(gamma, alpha) : P.cdf(gamma, alpha) - target;
    };
    // Bracket: the residual increases with g and is <= 0 at g = -h
    const double h = alpha/Delta;
    double lo = -h, hi = 1;
    if (h > 40 && residual(-40) <= 0)
    {
        lo = -40;
    }
    // (bounded: hi reaches the largest double in 1024 doublings)
    for (int i = 0; i < 1100 && residual(hi) < 0; ++i)
    {
        lo = hi;
        hi *= 2;
    }
    double g = 0.5*(lo + hi);
    for (int i = 0; i < 200; ++i)
    {
        const double r = residual(g);
        if (r == 0)
        {
            break;
        }
        (r < 0 ? lo : hi) = g;
        const double slope = Delta*P.pdf(Delta*g, alpha);
        double next = g - r/slope;
        if (!(next > lo && next < hi))
        {
            next = 0.5*(lo + hi);
        }
        const bool converged = std::abs(next - g) <= 1e-15*(std::abs(g) + 1e-300);
        g = next;
        if (converged || hi - lo <= 1e-16*(std::abs(hi) + std::abs(lo)))
        {
            break;
        }
    }
    return Delta*g;
}

} // namespace roughWall
