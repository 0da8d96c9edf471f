// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// The parameters of a statistics run and the incidence they are taken at.
// Velocities are in units of the incident speed V and the particle radius is
// 1: with the spin given as A_Omega = r Omega'_z / V'_x the coefficients (2.5)
// depend on nothing else.
#pragma once

#include "facetCollision.hpp"
#include "impactCoefficients.hpp"
#include "effectiveRestitution.hpp"
#include "gaussianMass.hpp"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace roughWallStats
{

using roughWall::FacetMaterial;
using roughWall::Regime;
using roughWall::Vec3;

//- e, mu0, muD as functions of the facet impact (--e-table, --mu0-polynomial,
//  ...): a function that is empty takes its constant from Model::material
struct ImpactDependence
{
    std::function<double(double)> e, mu0, muD;
    roughWall::ImpactArgument eArgument = roughWall::ImpactArgument::angle;
    double speed = 1;                  //!< incident speed V [m/s], for e(normal speed)
    std::vector<double> angleKinks;    //!< table nodes of mu0, muD, e(angle) [deg]

    bool any() const { return e || mu0 || muD; }
};

//- The rough wall and the incident spin
struct Model
{
    FacetMaterial material{0.8, 0.4, 0.4};   //!< e, mu0, muD (the constants)
    double Delta = 8*roughWall::pi/180;      //!< sd of the facet tilt [rad]
    double AOmega = 0;                       //!< r Omega'_z / V'_x, Omega_z along t x N
    ImpactDependence impact;                 //!< functions of the impact, if any
};

//- The core's coefficient policy of a Model with functions of the impact:
//  the velocities here are in units of V, so the normal speed is scaled by
//  V before e sees it. Bounds are checked at every call (throws
//  roughWall::CoefficientOutOfRange).
struct ModelCoefficients
{
    const Model* model;

    FacetMaterial operator()(const roughWall::FacetImpact& unitImpact) const
    {
        const ImpactDependence& f = model->impact;
        roughWall::FacetImpact impact = unitImpact;
        impact.normalSpeed *= f.speed;
        const double eArgument = roughWall::argumentOf(impact, f.eArgument);
        const FacetMaterial m
        {
            f.e ? f.e(eArgument) : model->material.e,
            f.mu0 ? f.mu0(impact.angleDeg) : model->material.mu0,
            f.muD ? f.muD(impact.angleDeg) : model->material.muD
        };
        roughWall::checkBounds(m, impact, f.eArgument);
        return m;
    }
};

//- The coefficients of a facet impact at b = alpha + gamma [rad]: the
//  angle between the velocity and the facet plane is min(b, pi - b) (beyond
//  pi/2 the facet is met from its other side), the normal speed sin(b) V
//  (the model's constants without functions)
inline FacetMaterial materialAt(const Model& model, double b)
{
    if (!model.impact.any())
    {
        return model.material;
    }
    roughWall::FacetImpact impact;
    impact.angleDeg = std::min(b, roughWall::pi - b)*(180/roughWall::pi);
    impact.normalSpeed = std::sin(b);
    return ModelCoefficients{&model}(impact);
}

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
