// roughWallInteraction benchmarks: samplers of P(gamma, alpha) to compare
// with the core's exact sampler.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// In g = gamma/Delta and h = alpha/Delta the shadowed density (1.3) is
//     p(g) = [phi(g) - phi(g + 2h)] / erf(h/sqrt2),   g > -h,
// with phi the standard normal density. Against the proposal q = phi,
//     p/q = -expm1(-2h(g + h)) / erf(h/sqrt2) <= 1/erf(h/sqrt2) = M,
// so plain rejection (propose g ~ N(0,1), accept with probability
// -expm1(-2h(g + h)) if g > -h) is exact, and needs on average
// M = 1/erf(h/sqrt2) proposals: ~1.25/h as h -> 0, never ending at h = 0.
//
// The "no-shadow" sampler is what a model without the shadow weighting
// does: draw g ~ N(0,1) again until g > -h. It is NOT (1.3): it is here to
// show, in the work-precision figure, what a biased sampler looks like.
#pragma once

#include "facetAngleSampler.hpp"

#include <cmath>
#include <limits>

namespace roughWallBench
{

//- Mean number of proposals of the plain rejection sampler, 1/erf(h/sqrt2)
inline double rejectionProposalsPerSample(double h)
{
    return h > 0 ? 1/std::erf(h/roughWall::sqrt2)
                 : std::numeric_limits<double>::infinity();
}

//- Standard normal pair by Box-Muller (the core's own construction)
template<class Uniform01>
void standardNormalPair(Uniform01& uniform01, double& z1, double& z2)
{
    const double r = std::sqrt(roughWall::detail::twoExponential(uniform01));
    const double theta = 2*roughWall::pi*uniform01();
    z1 = r*std::cos(theta);
    z2 = r*std::sin(theta);
}

//- Exact sample of gamma ~ (1.3) by rejection from N(0, Delta). Never
//  returns for alpha = 0 (acceptance probability 0): callers must not call
//  it there (rejectionProposalsPerSample is infinite).
template<class Uniform01>
double sampleFacetAngleByRejection
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
    const double h = alpha/Delta;
    const auto accept = [h, &uniform01](double g)
    {
        return g > -h && uniform01() < -std::expm1(-2*h*(g + h));
    };
    for (;;)
    {
        double z1, z2;
        standardNormalPair(uniform01, z1, z2);
        if (accept(z1))
        {
            return Delta*z1;
        }
        if (accept(z2))
        {
            return Delta*z2;
        }
    }
}

//- NOT (1.3): N(0, Delta) redrawn until gamma > -alpha (no shadow weighting)
template<class Uniform01>
double sampleFacetAngleWithoutShadow
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
    const double h = alpha/Delta;
    for (;;)
    {
        double z1, z2;
        standardNormalPair(uniform01, z1, z2);
        if (z1 > -h)
        {
            return Delta*z1;
        }
        if (z2 > -h)
        {
            return Delta*z2;
        }
    }
}

} // namespace roughWallBench
