// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// The parameters of a statistics run and the incidence they are taken at.
// Velocities are in units of the incident speed V and the particle radius is
// 1: with the spin given as A_Omega = r Omega'_z / V'_x the coefficients (2.5)
// depend on nothing else.
#pragma once

#include "facetCollision.hpp"
#include "restitutionCoefficients.hpp"
#include "gaussianMass.hpp"

#include <cmath>

namespace roughWallStats
{

using roughWall::FacetMaterial;
using roughWall::Regime;
using roughWall::Vec3;

//- The rough wall and the incident spin
struct Model
{
    FacetMaterial material{0.8, 0.4, 0.4};   //!< e, mu0, muD
    double Delta = 8*roughWall::pi/180;      //!< sd of the facet tilt [rad]
    double AOmega = 0;                       //!< r Omega'_z / V'_x, Omega_z along t x N
};

//- Incidence angle alpha in (0, 90] deg. At exactly 90 deg cos(alpha) is 0
//  (not 6e-17): V'_x = 0 there and k_t, k_Omega are undefined.
struct Incidence
{
    double degrees = 0;
    double alpha = 0;      //!< [rad]
    double cosAlpha = 1;   //!< V'_x / V
    double sinAlpha = 0;   //!< -V'_y / V

    static Incidence fromDegrees(double deg)
    {
        Incidence i;
        i.degrees = deg;
        i.alpha = deg*roughWall::pi/180;
        i.cosAlpha = deg == 90 ? 0.0 : std::cos(i.alpha);
        i.sinAlpha = deg == 90 ? 1.0 : std::sin(i.alpha);
        return i;
    }

    //- k_t and k_Omega are defined (V'_x > 0)
    bool tangentialDefined() const { return cosAlpha > 0; }

    //- Incident velocity in the wall frame x = t, y = N (into the fluid)
    Vec3 velocity() const { return Vec3(cosAlpha, -sinAlpha, 0); }

    //- Incident angular velocity (radius 1) for a given A_Omega
    Vec3 spin(double AOmega) const { return Vec3(0, 0, AOmega*cosAlpha); }
};

//- What the coefficients are made of: the outgoing velocity components and
//  spin (over the incident speed V, radius 1). Statistics are taken of these
//  and divided by sin(alpha) or cos(alpha) at the end, so that k_n ~ 1/alpha
//  never overflows a square.
struct Rebound
{
    double vx = 0;   //!< V''_x / V
    double vy = 0;   //!< V''_y / V
    double rw = 0;   //!< r Omega''_z / V

    static Rebound of(const Vec3& v, const Vec3& w)
    {
        return {v.x(), v.y(), w.z()};
    }
};

//- The restitution coefficients (2.5) of one outcome: the core's definition
using Coefficients = roughWall::RestitutionCoefficients;

//- The coefficients of an outcome at an incidence; kt, kOmega are 0 (not
//  used) when the incidence has V'_x = 0
inline Coefficients coefficientsOf(const Rebound& r, const Incidence& in)
{
    return roughWall::restitutionCoefficients
    (
        in.cosAlpha, -in.sinAlpha, r.vx, r.vy, r.rw
    );
}

//- Which coefficient a pdf is taken of
enum class Coefficient { kn, kt, kOmega };

inline const char* name(Coefficient c)
{
    return c == Coefficient::kn ? "kn" : c == Coefficient::kt ? "kt" : "kOmega";
}

inline double select(const Coefficients& k, Coefficient c)
{
    return c == Coefficient::kn ? k.kn : c == Coefficient::kt ? k.kt : k.kOmega;
}

} // namespace roughWallStats
