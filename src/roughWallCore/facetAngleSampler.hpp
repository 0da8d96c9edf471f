// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Samplers of the collision angle distribution P(gamma, alpha), eq. (1.3).
//
// The random source is any callable `uniform01()` returning a double uniform
// in [0, 1) (a std:: engine through StdUniform01 below, OpenFOAM's
// Random::sample01<scalar>() through a lambda).
//
// Exact sampler (bounded cost for every alpha, no special function in most
// draws). With x = beta/Delta = (alpha + gamma)/Delta and h = alpha/Delta the
// density of x > 0 is proportional to
//     exp(-(x-h)^2/2) - exp(-(x+h)^2/2) = integral_{|x-h|}^{x+h} u exp(-u^2/2) du.
// Two exact methods, chosen by h (derivations in docs/theory.md, section 3):
//  - h >= 1: plain rejection. x = h + Z with Z ~ N(0, 1), kept if x > 0 and
//    with probability 1 - exp(-2 x h); then gamma = Delta Z. Acceptance
//    erf(h/sqrt 2) >= 0.68, above 0.997 for h >= 3; the exponential is
//    evaluated only when a bound on it cannot decide (< 1 % of the draws
//    for h >= 3).
//  - h < 1: the mixture. s ~ N(0, 1) truncated to (0, h) by a uniform
//    proposal s = h U1 kept if 2 E >= s^2, E = -ln(1 - U2) ~ Exp(1)
//    (acceptance >= 0.61); given acceptance E - s^2/2 is again Exp(1) and
//    independent of s (no memory), so R = sqrt(2 E) is the Rayleigh tail
//    beyond s without another draw, and gamma = Delta (R - 2 s).
// Normal variates by the ziggurat (standardNormal.hpp), logarithms by
// fastMath.hpp.
#pragma once

#include "CollisionAngleDistribution.hpp"
#include "fastMath.hpp"
#include "standardNormal.hpp"

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

//- -2 ln(1 - U) for U in [0, 1): twice a unit exponential, never infinite
template<class Uniform01>
double twoExponential(Uniform01& uniform01)
{
    return -2*fastMath::log1pMinus(uniform01());
}

//- Accept with probability 1 - exp(-y), y > 0, given U uniform in [0, 1):
//  U < 1 - exp(-y). exp(-y) <= 1/(1 + y + y^2/2) accepts and
//  exp(-y) >= 1 - y rejects without the exponential.
inline bool acceptOneMinusExp(double y, double U)
{
    const double keep = 1 - U;
    if (keep*(1 + y*(1 + 0.5*y)) > 1)
    {
        return true;
    }
    if (1 - y >= keep)
    {
        return false;
    }
    return std::exp(-y) < keep;
}

} // namespace detail

//- Sample of gamma ~ P(gamma, alpha) by inversion of the CDF (below); the
//  exact fallback of sampleFacetAngle's rejection loops
template<class Uniform01>
double sampleFacetAngleByInversion(double alpha, double Delta, Uniform01& uniform01);

namespace detail
{

//- gamma ~ P(gamma, alpha) by plain rejection (h = alpha/Delta >= 1), from
//  attempt firstAttempt on; the inversion fallback after the last
template<class Uniform01>
#if defined(__GNUC__)
[[gnu::noinline]]
#endif
double sampleFacetAnglePlain
(
    double h,
    double alpha,
    double Delta,
    Uniform01& uniform01,
    int firstAttempt
)
{
    for (int i = firstAttempt; i < maxRejectionAttempts; ++i)
    {
        const double Z = standardNormal(uniform01);
        const double x = h + Z;
        const double gamma = Delta*Z;
        // (gamma > -alpha is x > 0 but for the rounding of tiny Delta)
        if (x > 0 && gamma > -alpha && acceptOneMinusExp(2*x*h, uniform01()))
        {
            return gamma;
        }
    }
    return sampleFacetAngleByInversion(alpha, Delta, uniform01);
}

//- gamma ~ P(gamma, alpha) by the mixture (h = alpha/Delta < 1); the
//  inversion fallback after the last attempt
template<class Uniform01>
#if defined(__GNUC__)
[[gnu::noinline]]
#endif
double sampleFacetAngleMixture
(
    double h,
    double alpha,
    double Delta,
    Uniform01& uniform01
)
{
    for (int i = 0; i < maxRejectionAttempts; ++i)
    {
        const double s = h*uniform01();
        const double twoE = twoExponential(uniform01);
        if (twoE >= s*s)
        {
            // R >= s, also where s*s underflows (alpha < 1e-154 Delta):
            // else gamma = -2 Delta s could pass -alpha
            const double R = std::max(s, std::sqrt(twoE));
            return Delta*(R - 2*s);
        }
    }
    return sampleFacetAngleByInversion(alpha, Delta, uniform01);
}

//- sampleFacetAngle given h = alpha/Delta (Delta > 0), computed by the
//  caller (the operator multiplies by 1/Delta, known before alpha). The
//  first attempt of plain rejection, accepted without the exponential in
//  most draws, is inline; the rest of plain rejection and the mixture are
//  out of line (the same draws in the same order either way)
template<class Uniform01>
inline double sampleFacetAngleGivenH
(
    double h,
    double alpha,
    double Delta,
    Uniform01& uniform01
)
{
    if (!(h >= 1))
    {
        return sampleFacetAngleMixture(h, alpha, Delta, uniform01);
    }
    const double Z = standardNormal(uniform01);
    const double x = h + Z;
    const double gamma = Delta*Z;
    if (x > 0 && gamma > -alpha && acceptOneMinusExp(2*x*h, uniform01()))
    {
        return gamma;
    }
    return sampleFacetAnglePlain(h, alpha, Delta, uniform01, 1);
}

} // namespace detail

//- Exact sample of gamma ~ P(gamma, alpha) [rad]. Delta = 0 gives 0.
template<class Uniform01>
double sampleFacetAngle(double alpha, double Delta, Uniform01& uniform01)
{
    if (!(Delta > 0))
    {
        return 0;
    }
    return detail::sampleFacetAngleGivenH(alpha/Delta, alpha, Delta, uniform01);
}

//- Sample of gamma ~ P(gamma, alpha) by inversion of the CDF: a monotone map
//  from one uniform number. Safeguarded Newton on g = gamma/Delta (not on
//  beta, whose digits are lost to alpha when alpha >> Delta), solving
//  sf = 1 - U in the upper half and cdf = U in the lower half so that the
//  residual keeps its relative accuracy. 10-100x slower than
//  sampleFacetAngle; the test oracle.
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
