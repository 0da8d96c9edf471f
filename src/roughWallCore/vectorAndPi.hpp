// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// What every header of the core shares, defined once: the vector type and pi.
// Include roughWallCore.hpp for the whole core.
#pragma once

#include <Eigen/Core>

namespace roughWall
{

//- The core's vector: velocities, spins, normals
using Vec3 = Eigen::Vector3d;

//- pi, to double precision
constexpr double pi = 3.14159265358979323846;

} // namespace roughWall
