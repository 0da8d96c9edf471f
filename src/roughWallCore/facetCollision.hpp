// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Hard-sphere collision of a spinning sphere with a flat facet, as vectors
// (model notes section 4; Derevich's (2.1)-(2.4) as corrected). Impulses are
// per unit mass, so the particle mass never enters.
//
//   v_n = v.n < 0                   approach speed on the facet
//   c   = v - r (w x n)             velocity of the contact point
//   u_t = c - (c.n) n               slip velocity
//   j_n = -(1 + e) v_n              normal impulse
//   rolling/no-slip if |u_t| <= (7/2) mu0 (1 + e) |v_n|:  j_t = -(2/7) u_t
//   sliding otherwise:              j_t = -muD j_n u_t/|u_t|
//   v'' = v + j_n n + j_t,  w'' = w - (5/(2 r)) (n x j_t)
//
// "Rolling/no-slip" and "sliding" name the regimes; OpenFOAM's "stick" means
// deposition and has nothing to do with them.
//
// e, mu0, muD come from a coefficient policy: FacetMaterial (constants, the
// paper's model) or a function of the facet impact (impactCoefficients.hpp).
#pragma once

#include "fastMath.hpp"
#include "vectorAndPi.hpp"
#include "limitsAndUnits.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace roughWall
{

//- Facet material: normal restitution and friction coefficients
struct FacetMaterial
{
    double e = 1;     //!< normal restitution of a facet collision, [0, 1]
    double mu0 = 0;   //!< static friction: the no-slip criterion
    double muD = 0;   //!< dynamic (sliding) friction, <= mu0
};

enum class Regime { noSlip, sliding };

//- What a coefficient function of the impact sees
struct FacetImpact
{
    double angleDeg = 90;     //!< beta [deg], (0, 90]
    double normalSpeed = 0;   //!< -v.n, > 0
};

//- The impact of velocity v on the facet of unit outward normal n (v.n < 0):
//  beta = atan2(-v.n, |v - (v.n) n|), the angle between v and the facet plane
//  (alpha + gamma in 2-D), which the no-slip/sliding decision of a sphere
//  without spin sees (|slip| = |v.n|/tan(beta)), and the normal speed -v.n.
//  Both arguments of the arc tangent are >= 0: the core's libm-free atan2
//  (fastMath.hpp) applies
inline FacetImpact facetImpact(const Vec3& v, const Vec3& n)
{
    const double normalSpeed = -v.dot(n);
    const double tangentialSpeed = (v + normalSpeed*n).norm();
    return
    {
        limits::radToDeg(fastMath::atan2FirstQuadrant(normalSpeed, tangentialSpeed)),
        normalSpeed
    };
}

//- Collide a sphere (velocity v, angular velocity w, radius r) with a facet
//  of unit outward normal n; v.n < 0 is the caller's precondition. Without
//  spin (withSpin = false) the sphere arrives without spin, w is neither read
//  nor written, and no spin work is done.
//  The sliding impulse is capped at the no-slip impulse so that the slip never
//  reverses (only possible for muD > mu0, which the adapters reject): energy
//  can then never grow, whatever the input.
template<bool withSpin>
Regime collideWithFacet
(
    Vec3& v,
    Vec3& w,
    const Vec3& n,
    double radius,
    const FacetMaterial& material
)
{
    const double vn = v.dot(n);
    const double jn = -(1 + material.e)*vn;

    Vec3 contactVelocity = v;
    if constexpr (withSpin)
    {
        contactVelocity -= radius*w.cross(n);
    }
    const Vec3 slip = contactVelocity - contactVelocity.dot(n)*n;
    const double slip2 = slip.squaredNorm();
    const double noSlipLimit = 3.5*material.mu0*jn;   // >= 0

    Vec3 jt;
    Regime regime;
    // |slip| <= limit, without the square root the rolling case does not need
    if (slip2 <= noSlipLimit*noSlipLimit)
    {
        jt = -(2.0/7.0)*slip;
        regime = Regime::noSlip;
    }
    else
    {
        const double slipSpeed = std::sqrt(slip2);
        const double magnitude = std::min(material.muD*jn, (2.0/7.0)*slipSpeed);
        jt = -(magnitude/slipSpeed)*slip;
        regime = Regime::sliding;
    }

    v += jn*n + jt;
    if constexpr (withSpin)
    {
        w -= (2.5/radius)*n.cross(jt);
    }
    return regime;
}

//- The same with coefficients that depend on the impact: Coefficients is a
//  policy with FacetMaterial operator()(const FacetImpact&) const, asked
//  once per facet collision for the impact of v on this facet. Constant
//  coefficients (FacetMaterial) take the overload above, unchanged.
template<bool withSpin, class Coefficients>
std::enable_if_t<!std::is_same_v<Coefficients, FacetMaterial>, Regime>
collideWithFacet
(
    Vec3& v,
    Vec3& w,
    const Vec3& n,
    double radius,
    const Coefficients& coefficients
)
{
    const FacetMaterial material = coefficients(facetImpact(v, n));
    return collideWithFacet<withSpin>(v, w, n, radius, material);
}

} // namespace roughWall
