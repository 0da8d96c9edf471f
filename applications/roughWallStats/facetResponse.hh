// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// One facet collision as a function of the facet tilt gamma, at a fixed
// incidence alpha and spin A_Omega: the coefficients (2.5), which regime
// (rolling/no-slip or sliding) applies, and where that changes.
//
// Two independent evaluations:
//  - collide(gamma): the core's vector collision (facetCollision.hpp), the
//    same arithmetic as the sampler and the OpenFOAM operator; the integrand
//    of the quadrature.
//  - analytic(gamma, regime): the facet-frame closed form with its derivative
//    in gamma, for root finding (kinks, k = k* in the pdf) and the Jacobian of
//    the change of variables (2.8). With beta = alpha + gamma (impact angle on
//    the facet), a = A_Omega cos(alpha) = r Omega'_z/V, all speeds over V:
//        tangential after  u = (5/7) cos b - (2/7) a            (no-slip)
//                          u = cos b - f sin b,  f = muD (1+e) sign(cos b + a)
//        normal after      nu = e sin b
//        r Omega''_z       rho = (2/7) a - (5/7) cos b          (no-slip)
//                          rho = a - (5/2) f sin b              (sliding)
//        V''_x = u cos g - nu sin g,   V''_y = u sin g + nu cos g
//    No-slip holds where |cos b + a| <= K sin b, K = (7/2) mu0 (1+e).
#pragma once

#include "model.hh"

#include <algorithm>
#include <cmath>
#include <vector>

namespace roughWallStats
{

class FacetResponse
{
public:

    //- Coefficients and their derivatives in gamma
    struct Value
    {
        Coefficients k;
        Coefficients dk;
        double vy = 0;    //!< V''_y / V: the sign of k_n
        double dvy = 0;
    };

    FacetResponse(const Model& model, const Incidence& incidence)
    :
        model_(model),
        in_(incidence),
        a_(model.AOmega*incidence.cosAlpha),
        K_(3.5*model.material.mu0*(1 + model.material.e))
    {}

    const Incidence& incidence() const { return in_; }
    const Model& model() const { return model_; }

    //- The core's vector collision with the facet of tilt gamma
    Rebound rebound(double gamma, Regime* regime = nullptr) const
    {
        Vec3 v = in_.velocity();
        Vec3 w = in_.spin(model_.AOmega);
        const Vec3 n(-std::sin(gamma), std::cos(gamma), 0);
        const Regime r = model_.impact.any()
            ? roughWall::collideWithFacet<true>(v, w, n, 1.0, ModelCoefficients{&model_})
            : roughWall::collideWithFacet<true>(v, w, n, 1.0, model_.material);
        if (regime)
        {
            *regime = r;
        }
        return Rebound::of(v, w);
    }

    //- The coefficients of the vector collision with the facet of tilt gamma
    Coefficients collide(double gamma, Regime* regime = nullptr) const
    {
        return coefficientsOf(rebound(gamma, regime), in_);
    }

    //- The regime of the facet collision at tilt gamma (closed-form criterion)
    Regime regime(double gamma) const
    {
        const double b = in_.alpha + gamma;
        return std::abs(std::cos(b) + a_) <= K(b)*std::sin(b)
            ? Regime::noSlip : Regime::sliding;
    }

    //- Closed form in the given regime (continued beyond its range, so that
    //  a piece's end values can be taken with the piece's own regime)
    //  With functions of the impact the coefficients are taken at b but their
    //  derivatives are left out (dk is then not the derivative: the pdf,
    //  which needs it, refuses such models)
    Value analytic(double gamma, Regime regime) const
    {
        const double b = in_.alpha + gamma;
        const FacetMaterial material = materialAt(model_, b);
        const double e = material.e;
        const double cb = std::cos(b), sb = std::sin(b);
        const double cg = std::cos(gamma), sg = std::sin(gamma);

        double u, du, rho, drho;
        if (regime == Regime::noSlip)
        {
            u = 5.0/7.0*cb - 2.0/7.0*a_;
            du = -5.0/7.0*sb;
            rho = 2.0/7.0*a_ - 5.0/7.0*cb;
            drho = 5.0/7.0*sb;
        }
        else
        {
            const double f =
                material.muD*(1 + e)*(cb + a_ >= 0 ? 1 : -1);
            u = cb - f*sb;
            du = -sb - f*cb;
            rho = a_ - 2.5*f*sb;
            drho = -2.5*f*cb;
        }
        const double nu = e*sb, dnu = e*cb;

        const double vx = u*cg - nu*sg;
        const double dvx = du*cg - u*sg - dnu*sg - nu*cg;
        const double vy = u*sg + nu*cg;
        const double dvy = du*sg + u*cg + dnu*cg - nu*sg;

        Value value;
        value.vy = vy;
        value.dvy = dvy;
        value.k = coefficientsOf(Rebound{vx, vy, rho}, in_);
        value.dk = coefficientsOf(Rebound{dvx, dvy, drho}, in_);
        return value;
    }

    //- The tilts in (gLo, gHi) where the regime changes, ascending: the
    //  solutions of cos b + a = +-K sin b, i.e. sqrt(1+K^2) cos(b -+ atan K) = -a
    //  With functions of the impact: by scanning the regime on 4096 intervals
    //  and bisection
    std::vector<double> regimeBoundaries(double gLo, double gHi) const
    {
        std::vector<double> gammas;
        if (model_.impact.any())
        {
            const int n = 4096;
            double g0 = gLo;
            Regime r0 = regime(g0);
            for (int i = 1; i <= n; ++i)
            {
                const double g1 = i == n ? gHi : gLo + (gHi - gLo)*i/n;
                const Regime r1 = regime(g1);
                if (r1 != r0)
                {
                    double lo = g0, hi = g1;
                    for (int k = 0; k < 60 && hi > lo; ++k)
                    {
                        const double mid = 0.5*(lo + hi);
                        (regime(mid) == r0 ? lo : hi) = mid;
                    }
                    gammas.push_back(0.5*(lo + hi));
                }
                g0 = g1;
                r0 = r1;
            }
            return gammas;
        }
        const double R = std::sqrt(1 + K_*K_);
        if (std::abs(a_) > R)
        {
            return gammas;   // |slip| > K sin b everywhere: always sliding
        }
        const double phase = std::atan(K_);
        const double c = std::acos(-a_/R);
        const double twoPi = 2*roughWall::pi;
        for (const double shift : {-phase, phase})
        {
            for (const double sign : {-1.0, 1.0})
            {
                for (int k = -1; k <= 1; ++k)
                {
                    const double g = shift + sign*c + k*twoPi - in_.alpha;
                    if (g > gLo && g < gHi)
                    {
                        gammas.push_back(g);
                    }
                }
            }
        }
        std::sort(gammas.begin(), gammas.end());
        gammas.erase(std::unique(gammas.begin(), gammas.end()), gammas.end());
        return gammas;
    }

private:

    //- (7/2) mu0 (1 + e) at the facet impact of b [rad]
    double K(double b) const
    {
        if (!model_.impact.any())
        {
            return K_;
        }
        const FacetMaterial m = materialAt(model_, b);
        return 3.5*m.mu0*(1 + m.e);
    }

    Model model_;
    Incidence in_;
    double a_;   //!< r Omega'_z / V
    double K_;   //!< (7/2) mu0 (1 + e) of the constants
};

} // namespace roughWallStats
