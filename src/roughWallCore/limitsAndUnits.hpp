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
//  units): the rms height Rq that a sinusoidal profile of the same Ra or Rz
//  has (Ra = 2A/pi, Rq = A/sqrt(2), Rz = 2A for amplitude A), used when Rq
//  is not given (profileRoughness.hpp)
constexpr double rqPerRaSinusoid = 1.1107207345395915;   // pi/(2 sqrt 2)
constexpr double rqPerRzSinusoid = 0.35355339059327373;  // 1/(2 sqrt 2)

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
