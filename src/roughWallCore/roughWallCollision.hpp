// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// The rough-wall collision operator: one wall hit of a particle on a randomly
// rough wall, as applied by the OpenFOAM model and by roughWallStats --recollide.
//
//  1. From the incident velocity v and the mean-wall normal N (into the fluid)
//     build the plane of incidence: tangent t = tangential part of v / its
//     length, incidence angle alpha = atan2(-v.N, |v_t|) in [0, pi/2].
//     At normal incidence (no tangential velocity) the tilt direction is drawn
//     uniformly in the wall plane (in 2-D: either way along the plane).
//  2. Draw gamma ~ P(gamma, alpha) (shadow-corrected, eq. (1.3)), limited to
//     gamma < pi/2: a facet tilted beyond the vertical is an overhang that a
//     particle coming from above cannot hit, so such draws are redrawn (the
//     distribution is truncated there and renormalised; the mass removed is
//     below 1e-28 for Delta <= 8 deg, 2 % at Delta = 45 deg and grazing incidence).
//  3. Facet normal n = cos(gamma) N - sin(gamma) t. With lateralTilt (isotropic
//     3-D roughness, never in 2-D) n is further rotated by delta ~ N(0, Delta),
//     |delta| < pi/2, about the incidence direction v/|v|: this keeps the
//     approach speed v.n, so the shadow condition and P(gamma, alpha) stay exact.
//  4. Collide with the facet (facetCollision.hpp).
//  5. While the particle still moves toward the mean wall (v.N < 0), collide
//     again with a new gamma drawn for the new incidence, at most
//     maxFacetCollisions facet collisions in all. If the bound is reached the
//     fallback is a collision with the mean wall itself (gamma = 0), which
//     returns v.N = -e v.N >= 0: the particle always leaves the wall.
// Kinetic energy (translational + rotational) never increases for e <= 1.
#pragma once

#include "facetAngleSampler.hpp"
#include "facetCollision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roughWall
{

//- Parameters of a rough wall
struct RoughWallParameters
{
    FacetMaterial material;
    double roughnessAngle = 0;     //!< Delta [rad], in [0, pi/4]
    bool lateralTilt = false;      //!< isotropic 3-D roughness (never in 2-D)
    int maxFacetCollisions = 10;   //!< bound on facet collisions per wall hit
};

//- What one wall hit did, for statistics
struct RoughWallReport
{
    int facetCollisions = 0;   //!< 0: the particle was not moving into the wall
    int noSlip = 0;            //!< facet collisions ending in rolling/no-slip
    int sliding = 0;           //!< facet collisions ending in sliding
    double firstGamma = 0;     //!< tilt of the first facet [rad]
    bool fallback = false;     //!< the bound was reached: mean-wall rebound
};

namespace detail
{

//- Largest facet tilt: beyond the vertical a facet is an overhang
constexpr double maxFacetTilt = 0.5*pi;

//- Draw gamma ~ P(gamma, alpha) restricted to gamma < pi/2 (each draw is
//  accepted with probability >= 0.86 for Delta <= 45 deg)
template<class Uniform01>
double sampleFacetTilt(double alpha, double Delta, Uniform01& uniform01)
{
    for (int i = 0; i < maxRejectionAttempts; ++i)
    {
        const double gamma = sampleFacetAngle(alpha, Delta, uniform01);
        if (gamma < maxFacetTilt)
        {
            return gamma;
        }
    }
    return 0;   // probability < 1e-80: a facet parallel to the mean wall
}

//- N(0, Delta) lateral tilt with |delta| < pi/2
template<class Uniform01>
double sampleLateralTilt(double Delta, Uniform01& uniform01)
{
    for (int i = 0; i < maxRejectionAttempts; ++i)
    {
        const double r = std::sqrt(twoExponential(uniform01));
        const double delta = Delta*r*std::cos(2*pi*uniform01());
        if (std::abs(delta) < maxFacetTilt)
        {
            return delta;
        }
    }
    return 0;
}

//- Unit tangent of the plane of incidence: along the tangential velocity, or
//  random in the admissible wall directions at exactly normal incidence
template<class Uniform01>
Vec3 incidenceTangent
(
    const Vec3& tangential,
    const Vec3& wallNormal,
    const Vec3& emptyDirection,
    bool twoD,
    Uniform01& uniform01
)
{
    const double length = tangential.norm();
    if (length > 0)
    {
        // The tangential part is orthogonal to N only to the round-off of
        // the velocity; near normal incidence that round-off is all there
        // is, and a tangent not orthogonal to N makes the facet normal
        // non-unit (energy not conserved). Orthogonalise the unit vector
        // again; if little is left, the incidence is normal to round-off.
        Vec3 t = tangential/length;
        t -= t.dot(wallNormal)*wallNormal;
        const double tLength = t.norm();
        if (tLength > 0.5)
        {
            return t/tLength;
        }
    }
    if (twoD)
    {
        const Vec3 inPlane = emptyDirection.cross(wallNormal).normalized();
        return uniform01() < 0.5 ? inPlane : Vec3(-inPlane);
    }
    const Vec3 a = wallNormal.unitOrthogonal();
    const Vec3 b = wallNormal.cross(a);
    const double phi = 2*pi*uniform01();
    return std::cos(phi)*a + std::sin(phi)*b;
}

//- After a collision with the mean-wall plane v.N = -e v.N >= 0 up to
//  round-off. Where the round-off wins (e = 0, or grazing incidence on a wall
//  not aligned with the axes: v.N is then below the rounding error of the
//  tangential components) project the normal part out, and if rounding leaves
//  v.N < 0 again, lift it by a few ulps of |v| (a relative energy change of
//  order 1e-28): the particle must not stay in the wall.
inline void leaveMeanWall(Vec3& velocity, const Vec3& wallNormal)
{
    const double margin = std::max
    (
        16*std::numeric_limits<double>::epsilon()
       *velocity.lpNorm<Eigen::Infinity>(),    // no underflow of |v|^2
        16*std::numeric_limits<double>::denorm_min()
    );
    for (int i = 0; i < 4 && velocity.dot(wallNormal) < 0; ++i)
    {
        velocity -= (velocity.dot(wallNormal) - i*margin)*wallNormal;
    }
}

} // namespace detail

//- One hit of a particle on the rough wall. velocity is relative to the wall,
//  wallNormal the unit mean-wall normal pointing into the fluid, spin the
//  angular velocity (untouched when withSpin is false), emptyDirection the unit
//  normal of a 2-D case's plane (zero in 3-D). A particle not moving into the
//  wall (velocity.dot(wallNormal) >= 0) is returned unchanged.
template<bool withSpin, class Uniform01>
RoughWallReport collideWithRoughWall
(
    Vec3& velocity,
    Vec3& spin,
    const Vec3& wallNormal,
    double radius,
    const RoughWallParameters& p,
    Uniform01& uniform01,
    const Vec3& emptyDirection = Vec3::Zero()
)
{
    RoughWallReport report;
    const bool twoD = emptyDirection.squaredNorm() > 0;
    const double Delta = p.roughnessAngle;
    const bool lateral = p.lateralTilt && !twoD && Delta > 0;

    for (int draw = 0; velocity.dot(wallNormal) < 0; ++draw)
    {
        if (draw >= p.maxFacetCollisions)
        {
            collideWithFacet<withSpin>(velocity, spin, wallNormal, radius, p.material);
            detail::leaveMeanWall(velocity, wallNormal);
            report.fallback = true;
            break;
        }

        // Plane of incidence, from the direction of v, scaled by its largest
        // component first: |v|^2 underflows for |v| < 1e-154 (a NaN
        // direction made the lateral tilt return NaN velocities)
        const Vec3 direction = (velocity/velocity.cwiseAbs().maxCoeff()).normalized();
        const double normalPart = direction.dot(wallNormal);
        Vec3 tangential = direction - normalPart*wallNormal;
        if (twoD)
        {
            tangential -= tangential.dot(emptyDirection)*emptyDirection;
        }
        const Vec3 t = detail::incidenceTangent
        (
            tangential, wallNormal, emptyDirection, twoD, uniform01
        );
        const double alpha = std::atan2(-normalPart, tangential.norm());

        const double gamma = detail::sampleFacetTilt(alpha, Delta, uniform01);
        Vec3 n = std::cos(gamma)*wallNormal - std::sin(gamma)*t;
        if (lateral)
        {
            const double delta = detail::sampleLateralTilt(Delta, uniform01);
            n = Eigen::AngleAxisd(delta, direction)*n;
        }
        if (velocity.dot(n) >= 0)
        {
            // Only at round-off level (alpha + gamma ~ 0): the particle grazes
            // the facet without touching it; draw another facet.
            continue;
        }
        if (report.facetCollisions == 0)
        {
            report.firstGamma = gamma;
        }
        ++report.facetCollisions;
        const Regime regime =
            collideWithFacet<withSpin>(velocity, spin, n, radius, p.material);
        ++(regime == Regime::noSlip ? report.noSlip : report.sliding);
        if (n == wallNormal)
        {
            // A facet parallel to the mean wall (Delta = 0) leaves v.N =
            // -e v.N >= 0: a negative value is round-off, not a reason to
            // collide again (with e = 0 it would run to the bound every time)
            detail::leaveMeanWall(velocity, wallNormal);
            break;
        }
    }
    return report;
}

} // namespace roughWall
