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
//     below 1e-28 for Delta <= 8 deg, 13.5 % (e^-2) at Delta = 45 deg and
//     grazing incidence).
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
#include "fastMath.hpp"
#include "limitsAndUnits.hpp"
#include "standardNormal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roughWall
{

//- Parameters of a rough wall. Coefficients: the coefficient policy of the
//  facet collisions (facetCollision.hpp): FacetMaterial for constants, or
//  e, mu0, muD as functions of the facet impact (impactCoefficients.hpp)
template<class Coefficients>
struct RoughWallParametersOf
{
    Coefficients material;
    double roughnessAngle = 0;     //!< Delta [rad], in [0, pi/4]
    bool lateralTilt = false;      //!< isotropic 3-D roughness (never in 2-D)
    int maxFacetCollisions = limits::defaultMaxFacetCollisions;  //!< bound per wall hit
};

//- Constant e, mu0, muD: the paper's model
using RoughWallParameters = RoughWallParametersOf<FacetMaterial>;

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

//- Smallest roughness angle whose reciprocal is used (1/Delta <= 1e300):
//  below it h = alpha/Delta is divided out
constexpr double minReciprocalDelta = 1e-300;

//- Draw gamma ~ P(gamma, alpha) restricted to gamma < pi/2 (each draw is
//  accepted with probability >= 0.86 for Delta <= 45 deg). Delta > 0;
//  invDelta = 1/Delta if Delta >= minReciprocalDelta, else 0: h = alpha/Delta
//  as a product, which, unlike the division, does not hold up the sampler
//  once alpha is known
template<class Uniform01>
double sampleFacetTilt
(
    double alpha,
    double Delta,
    double invDelta,
    Uniform01& uniform01
)
{
    const double h = invDelta > 0 ? alpha*invDelta : alpha/Delta;
    for (int i = 0; i < maxRejectionAttempts; ++i)
    {
        const double gamma =
            sampleFacetAngleGivenH(h, alpha, Delta, uniform01);
        if (gamma < maxFacetTilt)
        {
            return gamma;
        }
    }
    return 0;   // probability < 1e-80: a facet parallel to the mean wall
}

//- The same for any Delta >= 0 (Delta = 0 gives 0), h by division
template<class Uniform01>
double sampleFacetTilt(double alpha, double Delta, Uniform01& uniform01)
{
    return Delta > 0 ? sampleFacetTilt(alpha, Delta, 0.0, uniform01) : 0;
}

//- N(0, Delta) lateral tilt with |delta| < pi/2
template<class Uniform01>
double sampleLateralTilt(double Delta, Uniform01& uniform01)
{
    for (int i = 0; i < maxRejectionAttempts; ++i)
    {
        const double delta = Delta*standardNormal(uniform01);
        if (std::abs(delta) < maxFacetTilt)
        {
            return delta;
        }
    }
    return 0;
}

//- Smallest squared length normalised by its square root: far above the
//  subnormal range (2.2e-308), where squares lose precision
constexpr double minNormalizableSquare = 1e-280;

//- The plane of incidence of a velocity on the mean wall
struct IncidenceFrame
{
    Vec3 tangent;    //!< unit, in the wall plane, along the tangential velocity
    double alpha;    //!< incidence angle to the mean wall, [0, pi/2]
};

//- The unit tangent at exactly normal incidence: drawn uniformly among the
//  admissible wall directions (in 2-D: either way along the plane)
template<class Uniform01>
Vec3 randomWallTangent
(
    const Vec3& wallNormal,
    const Vec3& emptyDirection,
    bool twoD,
    Uniform01& uniform01
)
{
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

//- Plane of incidence of a velocity moving into the wall. direction is the
//  velocity or any positive multiple of it.
template<class Uniform01>
IncidenceFrame incidenceFrame
(
    const Vec3& direction,
    const Vec3& wallNormal,
    const Vec3& emptyDirection,
    bool twoD,
    Uniform01& uniform01
)
{
    const double approach = std::max(-direction.dot(wallNormal), 0.0);
    Vec3 tangential = direction + approach*wallNormal;
    if (twoD)
    {
        tangential -= tangential.dot(emptyDirection)*emptyDirection;
    }
    // The tangential part is orthogonal to N only to the round-off of the
    // velocity; near normal incidence that round-off is all there is, and a
    // tangent not orthogonal to N makes the facet normal non-unit (energy not
    // conserved). Project once more ("twice is enough"); if this removes
    // much, the incidence is normal to round-off.
    const double firstLength2 = tangential.squaredNorm();
    tangential -= tangential.dot(wallNormal)*wallNormal;
    const double length2 = tangential.squaredNorm();
    if (length2 > 0.25*firstLength2 && length2 > 0)
    {
        // The angle from the first projection's length: the second one
        // changes it by (t.N)^2, O(ulp^2) of |v|^2, which moves alpha by
        // O(ulp) at most; so alpha, which the sampler waits for, does not
        // wait for the second projection
        const double alpha =
            fastMath::atan2FirstQuadrant(approach, std::sqrt(firstLength2));
        if (length2 < minNormalizableSquare)
        {
            // A tangential part below 1e-140 of a direction of order one:
            // its squared length is subnormal and has lost bits, and so
            // would the unit tangent (|t|^2 - 1 = 8e-8 was seen, and the
            // facet normal and the energy with it). Scale it up first
            tangential /= tangential.cwiseAbs().maxCoeff();
            return {tangential.normalized(), alpha};
        }
        return {tangential*(1/std::sqrt(length2)), alpha};
    }
    return
    {
        randomWallTangent(wallNormal, emptyDirection, twoD, uniform01),
        0.5*pi
    };
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
template<bool withSpin, class Uniform01, class Coefficients>
RoughWallReport collideWithRoughWall
(
    Vec3& velocity,
    Vec3& spin,
    const Vec3& wallNormal,
    double radius,
    const RoughWallParametersOf<Coefficients>& p,
    Uniform01& uniform01,
    const Vec3& emptyDirection = Vec3::Zero()
)
{
    RoughWallReport report;
    const bool twoD = emptyDirection.squaredNorm() > 0;
    const double Delta = p.roughnessAngle;
    const bool lateral = p.lateralTilt && !twoD && Delta > 0;

    if (!(Delta > 0))
    {
        // A smooth wall: every facet is the mean wall, no plane of incidence
        // or draw is needed
        if (velocity.dot(wallNormal) < 0)
        {
            const Regime regime = collideWithFacet<withSpin>
            (
                velocity, spin, wallNormal, radius, p.material
            );
            detail::leaveMeanWall(velocity, wallNormal);
            if (p.maxFacetCollisions > 0)
            {
                report.facetCollisions = 1;
                ++(regime == Regime::noSlip ? report.noSlip : report.sliding);
            }
            else
            {
                report.fallback = true;   // as the loop below reports it
            }
        }
        return report;
    }

    const double invDelta = Delta >= detail::minReciprocalDelta ? 1/Delta : 0;

    for (int draw = 0; velocity.dot(wallNormal) < 0; ++draw)
    {
        if (draw >= p.maxFacetCollisions)
        {
            collideWithFacet<withSpin>(velocity, spin, wallNormal, radius, p.material);
            detail::leaveMeanWall(velocity, wallNormal);
            report.fallback = true;
            break;
        }

        // The plane of incidence from the direction of v; |v|^2 underflows
        // for |v| < 1e-154 (a NaN direction made the lateral tilt return NaN
        // velocities) and overflows above 1e154: scale such v first
        Vec3 direction = velocity;
        const double speed2 = direction.squaredNorm();
        if
        (
            !(speed2 > detail::minNormalizableSquare
           && speed2 < 1/detail::minNormalizableSquare)
        )
        {
            direction /= direction.cwiseAbs().maxCoeff();
        }
        const detail::IncidenceFrame frame = detail::incidenceFrame
        (
            direction, wallNormal, emptyDirection, twoD, uniform01
        );

        const double gamma =
            detail::sampleFacetTilt(frame.alpha, Delta, invDelta, uniform01);
        double sinGamma, cosGamma;
        fastMath::sinCosHalfPiSqrt(gamma, sinGamma, cosGamma);
        Vec3 n = cosGamma*wallNormal - sinGamma*frame.tangent;
        if (lateral)
        {
            // Rotate n about the incidence direction u: v.n is kept
            const double delta = detail::sampleLateralTilt(Delta, uniform01);
            double sinDelta, cosDelta;
            fastMath::sinCosHalfPi(delta, sinDelta, cosDelta);
            const Vec3 u = direction*(1/direction.norm());
            n = cosDelta*n + sinDelta*u.cross(n) + ((1 - cosDelta)*u.dot(n))*u;
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
            // A facet parallel to the mean wall (gamma = 0) leaves v.N =
            // -e v.N >= 0: a negative value is round-off, not a reason to
            // collide again (with e = 0 it would run to the bound every time)
            detail::leaveMeanWall(velocity, wallNormal);
            break;
        }
    }
    return report;
}

} // namespace roughWall
