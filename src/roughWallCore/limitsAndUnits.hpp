// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Every default and limit of the model's settings, and the degree-radian
// conversions they are given in, defined once: used by the
// OpenFOAM adapter's input checks, by roughWallStats's command line and by
// the documentation.
#pragma once

#include "vectorAndPi.hpp"

namespace roughWall
{
namespace limits
{

//- Largest roughness angle Delta [deg]: beyond it facets tilted past the
//  vertical (overhangs) become frequent (13 % of grazing hits at 45 deg)
constexpr double maxRoughnessAngleDeg = 45;

//- Bound on facet collisions per wall hit: default and allowed range
constexpr int defaultMaxFacetCollisions = 10;
constexpr int minMaxFacetCollisions = 1;
constexpr int maxMaxFacetCollisions = 1000;

//- Profile roughness (roughness { Ra ...; Rq ...; Rz ...; RSm ...; }, SI
//  units): the rms height Rq of a wall given by Ra or Rz alone is that of a
//  Gaussian profile, the profile the default envelope builds
//  (rollingSphereEnvelope.hpp), so that the flank-slope check below, the
//  synthetic profile and the closed-form estimate use one Rq
//  (ProfileRoughness::rmsHeight, profileRoughness.hpp):
//  - Rq = sqrt(pi/2) Ra, exact for Gaussian heights (E|z| = sqrt(2/pi) Rq);
//  - Rq = Rz/4.11 for Rz measured as the mean peak-to-valley height over
//    sampling lengths of 5 RSm: an assumption (2 RSm gives 3.21, 10 RSm
//    4.73; the ratio grows like 2 sqrt(2 ln n) with the number n of
//    elements per sampling length). Measured on 4 synthetic profiles of
//    2000 RSm (1596 windows): 4.112; checked in
//    tests/core/testRollingSphereEnvelope.cc against a random-phase cosine
//    sum
constexpr double rqPerRaGaussian = 1.2533141373155003;   // sqrt(pi/2)
constexpr double rzPerRqGaussian = 4.11;

//- Largest rms profile slope 2 pi Rq/RSm: its roughness angle atan(1) is
//  maxRoughnessAngleDeg, and the small-slope picture of a profile of
//  gentle flanks (a facet per flank) no longer holds beyond it
constexpr double maxProfileSlope = 1;

//- Degrees to radians, for the settings given in degrees
constexpr double degToRad(const double deg)
{
    return deg*(pi/180.0);
}

//- Radians to degrees, for the statistics reported in degrees
constexpr double radToDeg(const double rad)
{
    return rad*(180.0/pi);
}

} // End namespace limits
} // End namespace roughWall
