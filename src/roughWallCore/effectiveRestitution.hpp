// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Effective restitution coefficients of a wall hit, eq. (2.5), in the wall
// frame of the incident velocity: x = t (tangential incident direction),
// y = N (mean-wall normal into the fluid), z = t x N.
//   k_n = -V''_y / V'_y   signed: negative when the particle still moves
//                         toward the wall; |k_n| is the paper's (2.5)
//   k_t = V''_x / V'_x
//   k_Omega = r Omega''_z / V'_x
// and the closed forms (2.6)/(2.7) as corrected in the model notes, the
// independent oracle of the vector collision for in-plane spin; and
// collideAndMeasure, the hit with what the statistics count of it.
#pragma once

#include "facetCollision.hpp"
#include "roughWallCollision.hpp"

#include <cmath>

namespace roughWall
{

struct RestitutionCoefficients
{
    double kn = 0;       //!< signed -V''_y/V'_y
    double kt = 0;       //!< V''_x/V'_x
    double kOmega = 0;   //!< r Omega''_z / V'_x

    double absKn() const { return std::abs(kn); }
};

//- Coefficients (2.5) from the components, along t and N, of the incident
//  velocity (vx1 = V'_x, vy1 = V'_y < 0) and of the rebound (vx2 = V''_x,
//  vy2 = V''_y, rw2 = r Omega''_z): the one definition of k_n, k_t and
//  k_Omega. k_t and k_Omega are left 0 where V'_x = 0 (normal incidence:
//  the plane of incidence, and so t, is undefined)
inline RestitutionCoefficients restitutionCoefficients
(
    double vx1,
    double vy1,
    double vx2,
    double vy2,
    double rw2
)
{
    RestitutionCoefficients k;
    k.kn = -vy2/vy1;
    if (vx1 != 0)
    {
        k.kt = vx2/vx1;
        k.kOmega = rw2/vx1;
    }
    return k;
}

//- Coefficients (2.5) of one hit from incident (v1) and outgoing (v2, w2)
//  velocities and spins; t is the unit tangent of the plane of incidence
inline RestitutionCoefficients restitutionCoefficients
(
    const Vec3& v1,
    const Vec3& v2,
    const Vec3& w2,
    const Vec3& wallNormal,
    const Vec3& t,
    double radius
)
{
    return restitutionCoefficients
    (
        v1.dot(t),
        v1.dot(wallNormal),
        v2.dot(t),
        v2.dot(wallNormal),
        radius*w2.dot(t.cross(wallNormal))
    );
}

//- A tangential part of the incident velocity at most this fraction of its
//  magnitude counts as normal incidence: its direction is round-off
constexpr double normalIncidenceTangentialFraction = 1e-15;

//- k_n and k_t of a wall hit without spin, whether k_t is defined, and the
//  velocities they are ratios of (the statistics' impulse-weighted sums)
struct WallHitCoefficients
{
    RestitutionCoefficients k;   //!< kOmega is 0
    bool hasKt = false;          //!< false at normal incidence (k.kt 0)
    double vnIn = 0;             //!< |V'.N|, the incident normal speed
    double vnOut = 0;            //!< V''.N, signed
    double vtIn = 0;             //!< |V'_t| (0 without k_t)
    double vtOut = 0;            //!< V''.t, t = V'_t/|V'_t| (0 without k_t)
};

//- k_n and k_t (2.5) of a wall hit from the incident (v1) and rebound (v2)
//  velocities relative to the wall, k_t along the incident tangential
//  velocity (t = its direction). Inlined into collideAndMeasure: called
//  once per hit, out of line it costs a call and the vectors' stores
[[gnu::always_inline]] inline WallHitCoefficients wallHitCoefficients
(
    const Vec3& v1,
    const Vec3& v2,
    const Vec3& wallNormal
)
{
    constexpr double f = normalIncidenceTangentialFraction;
    const double vy1 = v1.dot(wallNormal);
    const Vec3 vt1 = v1 - vy1*wallNormal;
    const double vt1Sqr = vt1.squaredNorm();

    WallHitCoefficients hit;
    hit.hasKt = vt1Sqr > f*f*v1.squaredNorm();
    const double vx1 = hit.hasKt ? std::sqrt(vt1Sqr) : 0;
    const Vec3 t = hit.hasKt ? Vec3(vt1/vx1) : Vec3::Zero();
    hit.vnIn = std::abs(vy1);
    hit.vnOut = v2.dot(wallNormal);
    hit.vtIn = vx1;
    hit.vtOut = v2.dot(t);
    hit.k = restitutionCoefficients(vx1, vy1, hit.vtOut, hit.vnOut, 0);
    return hit;
}

//- One wall hit as the statistics count it: the core's report of the facet
//  collisions, k_n and k_t with the velocities of their ratios, and the
//  losses of |v|^2 and |omega|^2 (the kinetic energies per unit mass and per
//  unit moment of inertia, times two)
struct WallHit : RoughWallReport
{
    bool intoWall = false;         //!< false: not moving into the wall
    WallHitCoefficients coefficients;
    double speedSqrLoss = 0;       //!< |v'|^2 - |v''|^2
    double spinSqrLoss = 0;        //!< |omega'|^2 - |omega''|^2 (withSpin)
};

//- collideWithRoughWall (same arguments) for a particle moving into the wall
//  (velocity.dot(wallNormal) < 0), and what the statistics need of the hit:
//  one call per hit. A particle not moving into the wall is left unchanged
//  (intoWall false, nothing else set)
template<bool withSpin, class Uniform01, class Coefficients>
[[gnu::always_inline]] inline WallHit collideAndMeasure
(
    Vec3& velocity,
    Vec3& spin,
    const Vec3& wallNormal,
    double radius,
    const RoughWallParametersOf<Coefficients>& p,
    Uniform01& uniform01,
    const Vec3& emptyDirection
)
{
    if (!(velocity.dot(wallNormal) < 0))
    {
        return WallHit{};
    }
    const Vec3 v0(velocity);
    const double spin0Sqr = withSpin ? spin.squaredNorm() : 0;

    // Built in place, in this order (a braced list is evaluated left to
    // right): the collisions, then what they did
    return WallHit
    {
        collideWithRoughWall<withSpin>
        (
            velocity, spin, wallNormal, radius, p, uniform01, emptyDirection
        ),
        true,
        wallHitCoefficients(v0, velocity, wallNormal),
        v0.squaredNorm() - velocity.squaredNorm(),
        withSpin ? spin0Sqr - spin.squaredNorm() : 0
    };
}

//- Closed forms (2.6) (rolling/no-slip) and (2.7) (sliding) as corrected,
//  for one facet collision at tilt gamma, incidence alpha (z = tan alpha) and
//  spin parameter A_Omega = r Omega'_z / V'_x. Valid for 0 < alpha < pi/2.
struct ClosedFormRestitution
{
    RestitutionCoefficients k;
    Regime regime;
};

inline ClosedFormRestitution closedFormRestitution
(
    double gamma,
    double alpha,
    double AOmega,
    const FacetMaterial& m
)
{
    const double z = std::tan(alpha);
    const double c = std::cos(gamma);
    const double s = std::sin(gamma);
    const double e = m.e;
    const double slip = c - z*s + AOmega;      // facet slip / V'_x
    const double approach = z*c + s;           // facet approach speed / V'_x

    ClosedFormRestitution r;
    if (std::abs(slip) <= 3.5*m.mu0*(1 + e)*std::abs(approach))
    {
        r.regime = Regime::noSlip;
        r.k.kt = (5.0/7.0*(c - z*s) - 2.0/7.0*AOmega)*c - e*approach*s;
        r.k.kn = e*(c + s/z)*c + (5.0/7.0*(c/z - s) - 2.0/7.0*AOmega/z)*s;
        r.k.kOmega = -5.0/7.0*(c - z*s) + 2.0/7.0*AOmega;
    }
    else
    {
        r.regime = Regime::sliding;
        const double eps0 = slip > 0 ? 1 : -1;
        const double f = m.muD*(1 + e)*eps0;
        r.k.kt = ((c - z*s) - f*(s + z*c))*c - e*approach*s;
        r.k.kn = e*(s/z + c)*c + ((c/z - s) - f*(s/z + c))*s;
        r.k.kOmega = AOmega - 2.5*f*(s + z*c);
    }
    return r;
}

} // namespace roughWall
