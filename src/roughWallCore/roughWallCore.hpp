// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// The whole core in one include, as Eigen has one header per module:
//   vectorAndPi.hpp              Vec3 and pi
//   limitsAndUnits.hpp           every default and limit of the settings,
//                                degrees to radians and back
//   roughWallCollision.hpp       collideWithRoughWall: one wall hit, the entry point
//   effectiveRestitution.hpp     k_n and k_t of a hit (statistics)
//   profileRoughness.hpp         Delta(d) from Ra, Rq, Rz, RSm (closed-form estimate)
//   rollingSphereEnvelope.hpp    Delta(d) and the tilt's shape from a wall profile
//   profileFile.hpp              reading a measured profile trace
//   envelopeAngleTable.hpp       Delta(d) of a profile tabulated for look-ups per hit
//   roughnessAngle.hpp           Delta(d) in the four forms a patch gives it
//   spinLiftAndTorque.hpp        rotational lift and fluid torque of a sphere
//   fictitiousPartnerCollision.hpp  inter-particle collisions (Sommerfeld's model)
// (and, below collideWithRoughWall: facetAngleSampler, facetCollision,
// CollisionAngleDistribution, gaussianMass, standardNormal, fastMath)
#pragma once

#include "vectorAndPi.hpp"
#include "limitsAndUnits.hpp"
#include "roughWallCollision.hpp"
#include "effectiveRestitution.hpp"
#include "profileRoughness.hpp"
#include "rollingSphereEnvelope.hpp"
#include "profileFile.hpp"
#include "envelopeAngleTable.hpp"
#include "roughnessAngle.hpp"
#include "spinLiftAndTorque.hpp"
#include "fictitiousPartnerCollision.hpp"
