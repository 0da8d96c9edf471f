// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Statistics of one facet collision by deterministic quadrature over the
// facet tilt gamma:  E[f(k)] = int f(k(gamma)) P(gamma, alpha) dgamma / Z,
// over -alpha < gamma < pi/2 (facets beyond the vertical are overhangs, as in
// the operator and the sampler) with Z = cdf(pi/2, alpha). The integration is
// split at every kink of the integrands: the no-slip/sliding boundaries
// (closed form) and the zeros of k_n (|k_n| and the wall-ward indicator).
// Standard deviations are integrated about the mean (no cancellation
// between moments). Their relative accuracy is bounded below by the
// round-off of k itself, about 2 eps E|k| / sd: when sd << |mean| (tiny Delta,
// huge spin) the tolerance is relaxed to that floor.
#pragma once

#include "facetResponse.hh"
#include "statistics.hh"

#include <vector>

namespace roughWallStats
{

struct QuadratureSettings
{
    double tolerance = 1e-11;   //!< error estimate / integral of |f|, per quantity
    int maxIntervals = 4000;
};

//- The tilts that carry probability in double precision: beyond 40 Delta the
//  density is below exp(-800), i.e. 0
struct TiltRange
{
    double lo, hi;
};

TiltRange tiltRange(const Model& model, const Incidence& incidence);

//- Probability that an unrestricted draw is a facet below the vertical,
//  cdf(pi/2, alpha): the normalisation of the truncated distribution
double admissibleMass(const Model& model, const Incidence& incidence);

//- Breakpoints of the smooth pieces on the tilt range: ends, regime
//  boundaries and zeros of k_n, ascending
std::vector<double> smoothPieces(const FacetResponse& response, const TiltRange& range);

Statistics quadratureStatistics
(
    const Model& model,
    const Incidence& incidence,
    const QuadratureSettings& settings = QuadratureSettings()
);

} // namespace roughWallStats
