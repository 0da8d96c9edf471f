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
// independent oracle of the vector collision for in-plane spin.
#pragma once

#include "facetCollision.hpp"

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

//- Coefficients (2.5) of one hit from incident (v1, w1) and outgoing (v2, w2)
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
    const double vx = v1.dot(t);
    const double vy = v1.dot(wallNormal);
    RestitutionCoefficients k;
    k.kn = -v2.dot(wallNormal)/vy;
    k.kt = v2.dot(t)/vx;
    k.kOmega = radius*w2.dot(t.cross(wallNormal))/vx;
    return k;
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
