// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// A spinning particle between wall hits (docs/spin.md): the rotational
// (Magnus) lift and the fluid torque, with the slip quantities
//   U_rel     = U_f - U_p                    slip velocity
//   Omega_rel = 0.5 curl(U_f) - omega_p      slip spin
//   Re_p = |U_rel| d/nu,  Re_R = |Omega_rel| d^2/nu.
//
// Rotational lift     F = (pi/8) rho_f d^3 (Re_p/Re_R) C_LR (Omega_rel x U_rel)
//   RubinowKeller     C_LR = Re_R/Re_p (Rubinow & Keller 1961, Re_p << 1)
//   OesterleBuiDinh   C_LR = 0.45 + (Re_R/Re_p - 0.45) exp(-0.05684 Re_R^0.4 Re_p^0.3)
//                     (Oesterle & Bui Dinh 1998, fitted for Re_p < 140; used
//                     unchanged above, where it tends smoothly to the
//                     constant 0.45: nothing diverges or switches)
//   Loth              C_LR = Omega* (1 - {0.675 + 0.15 (1 + tanh[0.28 (Omega* - 2)])}
//                                    tanh[0.18 Re_p^0.5]),  Omega* = Re_R/Re_p = 2 Gamma
//                     (Loth 2008, AIAA J. 46, 801-809, as reproduced in
//                     docs/spin.md: Re_p < 2000, Omega* < 20; linear in the
//                     spin, Rubinow-Keller's Omega* for Re_p -> 0)
// Fluid torque        T = (rho_f/2) (d/2)^5 C_R |Omega_rel| Omega_rel
//   Stokes            C_R = 64 pi/Re_R (all Re_R)
//   DennisSinghIngham C_R = 64 pi/Re_R                       Re_R <= 32
//                     C_R = 12.9/sqrt(Re_R) + 128.4/Re_R     Re_R > 32
//                     (Dennis, Singh & Ingham 1980, computed up to 1000; used
//                     unchanged above, where the 12.9/sqrt(Re_R) boundary-layer
//                     term dominates)
//
// The spin update (slipSpinDecay) is the exact solution of
//   I d(omega_p)/dt = T(Omega_rel),  I = (pi/60) rho_p d^5,
// with the fluid vorticity frozen over the step: Omega_rel keeps its
// direction and its magnitude W obeys dW/dt = -lambda(W) W,
//   lambda = 15 rho_f/(16 pi rho_p) W C_R(W d^2/nu)
//          = 1/tau_omega = 60 mu/(rho_p d^2)                   (Stokes)
//          = (15 rho_f/(16 pi rho_p)) (12.9 sqrt(nu W)/d + 128.4 nu/d^2)
// which is solved in closed form in each regime (exponential; a Bernoulli
// equation for sqrt(W)) and joined where W crosses Re_R = 32.  The factor
// W(t + dt)/W(t) lies in [0, 1] for every time step: the slip spin never
// overshoots or reverses, and the rotational energy relative to the fluid,
// I W^2/2, never grows.
//
// Every function is safe for d, |U_rel|, |Omega_rel| zero, subnormal or
// huge (finite): no 0*inf, no 0/0, no NaN (tests/core/testParticleSpin.cc).
#pragma once

#include "vectorAndPi.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace roughWall
{

namespace spin
{

//- Rotational-lift coefficient C_LR (a named choice, see above)
enum class LiftCoefficient
{
    RubinowKeller,
    OesterleBuiDinh,
    Loth
};

//- Rotational-drag (torque) coefficient C_R
enum class TorqueCoefficient
{
    Stokes,
    DennisSinghIngham
};

//- Largest particle Reynolds number of Oesterle & Bui Dinh's fit
constexpr double oesterleBuiDinhMaxRe = 140;

//- The rest of their measured range: 10 < Re_p, 1 < Gamma < 6, with
//  Gamma = |Omega| d/(2 |U|) = Omega*/2
constexpr double oesterleBuiDinhMinRe = 10;
constexpr double oesterleBuiDinhMinGamma = 1;
constexpr double oesterleBuiDinhMaxGamma = 6;

//- Rubinow & Keller's theory is for Re_p << 1: counted as in range below 1
constexpr double rubinowKellerMaxRe = 1;

//- Range of Loth's correlation: Re_p < 2000, Omega* = Re_R/Re_p < 20
constexpr double lothMaxRe = 2000;
constexpr double lothMaxSpinRatio = 20;

//- Largest Re_R of Dennis, Singh & Ingham's Stokes branch, and of their
//  computations
constexpr double dennisStokesMaxReR = 32;
constexpr double dennisMaxReR = 1000;


// * * * * * * * * * * * * * * * Safe arithmetic  * * * * * * * * * * * * * //

//- a*b for a, b >= 0 (finite or +inf): 0 if either is 0 (never 0*inf)
inline double product(const double a, const double b)
{
    return (a == 0 || b == 0) ? 0 : a*b;
}

//- |v| without overflow or underflow of |v|^2
inline double magnitude(const Vec3& v)
{
    const double s = v.squaredNorm();
    if (s >= std::numeric_limits<double>::min() && s <= std::numeric_limits<double>::max())
    {
        return std::sqrt(s);
    }
    return v.stableNorm();
}

//- m v for m >= 0 and |v_i| <= 1: components that are zero stay zero (never 0*inf)
inline Vec3 scaled(const Vec3& v, const double m)
{
    const auto component = [m](const double x)
    {
        return x < 0 ? -product(-x, m) : product(x, m);
    };
    return Vec3(component(v.x()), component(v.y()), component(v.z()));
}

//- The unit vector along v, zero if |v| is zero (or not finite)
inline Vec3 direction(const Vec3& v, const double magV)
{
    if (magV > 0 && magV <= std::numeric_limits<double>::max())
    {
        return v/magV;
    }
    return Vec3::Zero();
}

//- expm1(x)/x for x >= 0 (1 at x = 0, +inf at x = +inf)
inline double expm1OverX(const double x)
{
    if (x < 1e-8)
    {
        return 1 + 0.5*x;
    }
    if (x > std::numeric_limits<double>::max())
    {
        return x;
    }
    return std::expm1(x)/x;
}

//- log1p(q)/q for q >= 0 (1 at q = 0)
inline double log1pOverX(const double q)
{
    if (q < 1e-8)
    {
        return 1 - 0.5*q;
    }
    if (q > std::numeric_limits<double>::max())
    {
        return 0;
    }
    return std::log1p(q)/q;
}


// * * * * * * * * * * * * * * Reynolds numbers  * * * * * * * * * * * * * * //

//- Re_p = |U_rel| d/nu
inline double particleReynolds(const double slipSpeed, const double d, const double nu)
{
    return product(slipSpeed, d)/nu;
}

//- Re_R = |Omega_rel| d^2/nu
inline double rotationalReynolds(const double slipSpin, const double d, const double nu)
{
    return product(slipSpin, product(d, d))/nu;
}


// * * * * * * * * * * * * * * * Rotational lift * * * * * * * * * * * * * * //

//- C_LR of Rubinow & Keller (1961): Re_R/Re_p (Re_p, Re_R > 0)
inline double liftCoefficientRubinowKeller(const double Rep, const double ReR)
{
    return ReR/Rep;
}

//- C_LR of Oesterle & Bui Dinh (1998) (Re_p, Re_R > 0)
inline double liftCoefficientOesterleBuiDinh(const double Rep, const double ReR)
{
    return 0.45 + (ReR/Rep - 0.45)*std::exp(-0.05684*std::pow(ReR, 0.4)*std::pow(Rep, 0.3));
}

//- Loth's factor on the Rubinow-Keller force, (Re_p/Re_R) C_LR, of the
//  spin ratio Omega* = Re_R/Re_p (>= 0, +inf allowed) and Re_p >= 0:
//    1 - {0.675 + 0.15 (1 + tanh[0.28 (Omega* - 2)])} tanh[0.18 Re_p^0.5]
//  in [0.025, 1]: 1 at Re_p = 0 (Rubinow-Keller), never negative
inline double lothFactor(const double spinRatio, const double Rep)
{
    return
        1
      - (0.675 + 0.15*(1 + std::tanh(0.28*(spinRatio - 2))))
       *std::tanh(0.18*std::sqrt(Rep));
}

//- C_LR of Loth (2008) (Re_p, Re_R > 0)
inline double liftCoefficientLoth(const double Rep, const double ReR)
{
    const double spinRatio = ReR/Rep;
    return spinRatio*lothFactor(spinRatio, Rep);
}

//- Is a lift evaluation at Re_p and spin ratio Omega* = Re_R/Re_p
//  (= |Omega| d/|U| = 2 Gamma) inside the range the correlation was
//  derived or measured for?
inline bool liftInRange(const LiftCoefficient c, const double Rep, const double spinRatio)
{
    switch (c)
    {
        case LiftCoefficient::RubinowKeller:
            return Rep < rubinowKellerMaxRe;
        case LiftCoefficient::Loth:
            return Rep < lothMaxRe && spinRatio < lothMaxSpinRatio;
        default:
            return
                Rep > oesterleBuiDinhMinRe && Rep < oesterleBuiDinhMaxRe
             && spinRatio > 2*oesterleBuiDinhMinGamma
             && spinRatio < 2*oesterleBuiDinhMaxGamma;
    }
}

//- That range as text, for the log
inline const char* liftRange(const LiftCoefficient c)
{
    switch (c)
    {
        case LiftCoefficient::RubinowKeller:
            return "Re_p < 1 (derived for Re_p << 1)";
        case LiftCoefficient::Loth:
            return "Re_p < 2000, Omega* = Re_R/Re_p < 20";
        default:
            return "10 < Re_p < 140, 1 < Gamma = Re_R/(2 Re_p) < 6";
    }
}

//- C_LR of a named choice (Re_p, Re_R > 0)
inline double liftCoefficient(const LiftCoefficient c, const double Rep, const double ReR)
{
    switch (c)
    {
        case LiftCoefficient::RubinowKeller:
            return liftCoefficientRubinowKeller(Rep, ReR);
        case LiftCoefficient::Loth:
            return liftCoefficientLoth(Rep, ReR);
        default:
            return liftCoefficientOesterleBuiDinh(Rep, ReR);
    }
}

//- The rotational lift on a sphere of diameter d [m] with slip velocity
//  slipU = U_f - U_p [m/s] and slip spin slipOmega = 0.5 curl(U_f) - omega_p
//  [1/s] in a fluid of density rho [kg/m^3] and kinematic viscosity nu
//  [m^2/s]:  F = (pi/8) rho d^3 (Re_p/Re_R) C_LR (slipOmega x slipU)  [N].
//
//  Written without Re_p/Re_R (which is 0/0 at rest): with
//  E = exp(-0.05684 Re_R^0.4 Re_p^0.3) and Re_p/Re_R = |U|/(|Omega| d),
//    RubinowKeller    (Re_p/Re_R) C_LR = 1
//    OesterleBuiDinh  (Re_p/Re_R) C_LR = E + 0.45 (|U|/(|Omega| d)) (1 - E)
//    Loth             (Re_p/Re_R) C_LR = lothFactor(|Omega| d/|U|, Re_p)
//  so  |F| = (pi/8) rho [d^3 |Omega||U| E + 0.45 d^2 |U|^2 (1 - E)] sin(angle).
inline Vec3 rotationalLift
(
    const Vec3& slipU,
    const Vec3& slipOmega,
    const double d,
    const double rho,
    const double nu,
    const LiftCoefficient c
)
{
    const double U = magnitude(slipU);
    const double W = magnitude(slipOmega);

    // Written so that NaN input gives no force either
    if (!(U > 0) || !(W > 0) || !(d > 0))
    {
        return Vec3::Zero();
    }

    // |sin(angle)| <= 1 along Omega x U
    const Vec3 axis = direction(slipOmega, W).cross(direction(slipU, U));

    const double d2 = product(d, d);
    const double spinTerm = product(product(d2, d), product(W, U));   // d^3 W U

    double m = spinTerm;
    if (c == LiftCoefficient::OesterleBuiDinh)
    {
        const double Rep = particleReynolds(U, d, nu);
        const double ReR = rotationalReynolds(W, d, nu);

        // Re_R^0.4 Re_p^0.3 = (Re_R^4 Re_p^3)^0.1: one pow where the
        // product is a normal number, two elsewhere
        const double q = (ReR*ReR)*(ReR*ReR)*(Rep*Rep*Rep);
        const double x = 0.05684*
        (
            q >= std::numeric_limits<double>::min() && q <= std::numeric_limits<double>::max()
          ? std::pow(q, 0.1)
          : product(std::pow(ReR, 0.4), std::pow(Rep, 0.3))
        );

        // E and 1 - E, each to full relative accuracy, from one exponential
        double E, oneMinusE;
        if (x < 0.7)
        {
            const double m1 = std::expm1(-x);
            E = 1 + m1;
            oneMinusE = -m1;
        }
        else
        {
            E = std::exp(-x);
            oneMinusE = 1 - E;
        }

        m = product(spinTerm, E) + 0.45*product(product(d2, product(U, U)), oneMinusE);
    }
    else if (c == LiftCoefficient::Loth)
    {
        // Omega* = |Omega| d/|U| (+inf for a subnormal |U|: tanh -> 1)
        const double spinRatio = product(W, d)/U;
        m = product(spinTerm, lothFactor(spinRatio, particleReynolds(U, d, nu)));
    }

    return scaled(axis, product(pi/8*rho, m));
}


// * * * * * * * * * * * * * * * * Fluid torque  * * * * * * * * * * * * * * //

//- C_R of the Stokes flow: 64 pi/Re_R (Re_R > 0)
inline double torqueCoefficientStokes(const double ReR)
{
    return 64*pi/ReR;
}

//- C_R of Dennis, Singh & Ingham (1980) (Re_R > 0)
inline double torqueCoefficientDennisSinghIngham(const double ReR)
{
    if (ReR <= dennisStokesMaxReR)
    {
        return 64*pi/ReR;
    }
    return 12.9/std::sqrt(ReR) + 128.4/ReR;
}

//- Is a torque evaluation at Re_R inside the range of its coefficient?
//  Stokes: Re_R <= 32, where Dennis, Singh & Ingham's computations follow
//  it; DennisSinghIngham: Re_R <= 1000, their computations
inline bool torqueInRange(const TorqueCoefficient c, const double ReR)
{
    return ReR <= (c == TorqueCoefficient::Stokes ? dennisStokesMaxReR : dennisMaxReR);
}

//- That range as text, for the log
inline const char* torqueRange(const TorqueCoefficient c)
{
    return c == TorqueCoefficient::Stokes
        ? "Re_R <= 32, where Dennis, Singh & Ingham follow Stokes"
        : "Re_R <= 1000, Dennis, Singh & Ingham's computations";
}

//- C_R of a named choice (Re_R > 0)
inline double torqueCoefficient(const TorqueCoefficient c, const double ReR)
{
    return c == TorqueCoefficient::Stokes
        ? torqueCoefficientStokes(ReR)
        : torqueCoefficientDennisSinghIngham(ReR);
}

//- The fluid torque on a sphere of diameter d with slip spin slipOmega:
//  T = (rho/2) (d/2)^5 C_R |slipOmega| slipOmega  [N m].
//  Written with |Omega| C_R (finite at rest):
//    Re_R <= 32 or Stokes: T = pi rho nu d^3 Omega    (= 8 pi mu r^3 Omega)
//    Re_R > 32:            T = (rho/64) (12.9 d^4 sqrt(nu |Omega|) + 128.4 nu d^3) Omega
inline Vec3 fluidTorque
(
    const Vec3& slipOmega,
    const double d,
    const double rho,
    const double nu,
    const TorqueCoefficient c
)
{
    const double W = magnitude(slipOmega);
    if (!(W > 0) || !(d > 0))
    {
        return Vec3::Zero();
    }

    const double d3 = product(product(d, d), d);
    const double ReR = rotationalReynolds(W, d, nu);

    double m;   // |T|
    if (c == TorqueCoefficient::Stokes || ReR <= dennisStokesMaxReR)
    {
        m = product(pi*rho*nu, product(d3, W));
    }
    else
    {
        m = rho/64
           *(
                product(12.9*std::sqrt(nu), product(product(d3, d), std::pow(W, 1.5)))
              + product(128.4*nu, product(d3, W))
            );
    }

    return scaled(direction(slipOmega, W), m);
}

//- Stokes spin relaxation time of a sphere: tau_omega = rho_p d^2/(60 mu) [s]
inline double spinRelaxationTime(const double rhoP, const double d, const double mu)
{
    return product(rhoP, product(d, d))/(60*mu);
}


// * * * * * * * * * * * * * * * * Spin update  * * * * * * * * * * * * * * //

//- The factor W(t + dt)/W(t) in [0, 1] by which the fluid torque alone
//  shrinks the slip spin of magnitude W over dt [s] (fluid vorticity frozen):
//  the exact solution of dW/dt = -lambda(W) W (see the top of this file).
//  rhoP: particle density; rho, nu: fluid density and kinematic viscosity.
inline double slipSpinDecay
(
    const double W,
    const double dt,
    const double d,
    const double rhoP,
    const double rho,
    const double nu,
    const TorqueCoefficient c
)
{
    if (!(dt > 0) || !(W > 0) || !(W <= std::numeric_limits<double>::max()))
    {
        return 1;
    }

    const double d2 = product(d, d);

    // Stokes rate 1/tau = 60 rho nu/(rho_p d^2) (inf for d = 0: locks at once)
    const double stokesRate = 60*rho*nu/product(rhoP, d2);
    const double ReR = rotationalReynolds(W, d, nu);

    if (c == TorqueCoefficient::Stokes || !(ReR > dennisStokesMaxReR))
    {
        return std::exp(-product(dt, stokesRate));
    }

    // Re_R > 32: dW/dt = -(A sqrt(W) + B) W; with w = 1/sqrt(W),
    // dw/dt = (B/2) w + A/2, so  w(t) = w0 e^{x} + (A t/2) expm1(x)/x,
    // x = B t/2
    const double c0 = 15*rho/(16*pi*rhoP);
    const double A = c0*12.9*std::sqrt(nu)/d;
    const double B = c0*128.4*nu/d2;

    if (!(A <= std::numeric_limits<double>::max()) || !(B <= std::numeric_limits<double>::max()))
    {
        // d so small that nu/d^2 overflows: relaxes at once
        return 0;
    }

    const double w0 = 1/std::sqrt(W);
    const double x = product(B, dt)/2;
    const double w = product(w0, std::exp(x)) + product(product(A, dt)/2, expm1OverX(x));

    // Threshold Re_R = 32: w32 = 1/sqrt(32 nu/d^2)
    const double w32 = d/std::sqrt(dennisStokesMaxReR*nu);

    if (w <= w32)
    {
        // Still at Re_R >= 32 at the end of the step; w >= w0
        const double r = w0/w;
        return r*r;
    }

    // Crosses Re_R = 32 at t*: (w0 + A/B) e^{B t*/2} = w32 + A/B
    const double gap = w32 > w0 ? w32 - w0 : 0;
    const double q = product(gap, B)/(A + product(B, w0));
    double tStar = 2*gap/(A + product(B, w0))*log1pOverX(q);
    tStar = tStar < dt ? tStar : dt;

    const double r = w0 < w32 ? w0/w32 : 1;
    return r*r*std::exp(-product(dt - tStar, stokesRate));
}

//- The slip spin after dt under the fluid torque (fluid vorticity frozen)
inline Vec3 relaxSlipSpin
(
    const Vec3& slipOmega,
    const double dt,
    const double d,
    const double rhoP,
    const double rho,
    const double nu,
    const TorqueCoefficient c
)
{
    return slipOmega*slipSpinDecay(magnitude(slipOmega), dt, d, rhoP, rho, nu, c);
}

} // End namespace spin
} // End namespace roughWall
