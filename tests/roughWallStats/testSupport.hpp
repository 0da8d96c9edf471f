// Shared helpers of the roughWallStats tests.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "model.hpp"

#include <cmath>

namespace roughWallStatsTest
{

constexpr double deg = 3.14159265358979323846/180;

//- A model in the tool's units: angles in degrees
inline roughWallStats::Model model
(
    double DeltaDeg,
    double AOmega = 0,
    double e = 0.8,
    double mu0 = 0.4,
    double muD = 0.4
)
{
    roughWallStats::Model m;
    m.Delta = DeltaDeg*deg;
    m.AOmega = AOmega;
    m.material = {e, mu0, muD};
    return m;
}

inline double relativeError(double value, double reference)
{
    return std::abs(value - reference)/std::abs(reference);
}

} // namespace roughWallStatsTest
