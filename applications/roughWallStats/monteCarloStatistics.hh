// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Statistics by Monte Carlo with the core's exact sampler of the facet tilt
// (truncated below the vertical, as in the operator):
//  - default: one facet collision per wall hit, the paper's model;
//  - recollide: the full operator collideWithRoughWall (new facets until the
//    particle leaves, at most maxFacetCollisions, then a mean-wall rebound),
//    which is what the OpenFOAM model applies;
//  - lateral: isotropic 3-D roughness (the operator's extra N(0, Delta) tilt
//    of the facet about the incidence direction), with or without recollide.
// Each incidence angle has its own random stream, seeded from (seed, alpha):
// a row does not depend on the other angles asked for, nor on threads.
#pragma once

#include "model.hh"
#include "statistics.hh"
#include "limitsAndUnits.hpp"

#include <cstdint>
#include <random>

namespace roughWallStats
{

struct MonteCarloSettings
{
    long long samples = 1000000;
    std::uint64_t seed = 1;
    bool recollide = false;
    bool lateral = false;
    int maxFacetCollisions = roughWall::limits::defaultMaxFacetCollisions;
};

//- Uniform numbers in [0, 1) from a 64-bit Mersenne twister, with 53 random
//  bits: the same sequence on every platform (std:: distributions are not)
class Uniform01
{
    std::mt19937_64 engine_;

public:

    Uniform01(std::uint64_t seed, double alphaDeg);

    double operator()() { return (engine_() >> 11)*0x1.0p-53; }
};

//- What one wall hit did, as the statistics see it
struct Outcome
{
    Rebound rebound;          //!< velocity and spin leaving the wall model
    bool firstWallward = false;   //!< V''_y < 0 after the first facet collision
    int facetCollisions = 1;
    int noSlip = 0;           //!< facet collisions in the rolling/no-slip regime
    bool fallback = false;
};

//- Draws wall hits at one incidence
class WallHitSampler
{
public:

    WallHitSampler(const Model& model, const Incidence& incidence, const MonteCarloSettings& settings);

    Outcome operator()(Uniform01& uniform01) const;

private:

    Model model_;
    Incidence in_;
    MonteCarloSettings settings_;
};

Statistics monteCarloStatistics
(
    const Model& model,
    const Incidence& incidence,
    const MonteCarloSettings& settings
);

} // namespace roughWallStats
