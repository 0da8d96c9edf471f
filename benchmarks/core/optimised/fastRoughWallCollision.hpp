// roughWallInteraction benchmarks: an optimised copy of the core's
// collideWithRoughWall (src/roughWallCore/roughWallCollision.hpp and
// facetAngleSampler.hpp, as of commit f9ea2c9), the same algorithm drawing
// the same uniform numbers in the same order, with
//   - libm's atan2, sincos, log1p replaced by fastMath.hpp (<= 2.4 ulp),
//   - a squeeze in the truncated-normal rejection for h < 1: -2 log(1-u) >= 2u,
//     so 2u >= s^2 accepts without the logarithm (same decisions),
//   - one division (a reciprocal) for each of the four normalisations of the
//     incidence frame instead of three, the tangent's length computed once,
//   - the lateral tilt by Rodrigues' formula instead of Eigen's AngleAxis.
// For the same random stream its results agree with the core's to round-off
// (compareOptimised measures it); it is a candidate for the core.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "fastMath.hpp"

#include "roughWallCollision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roughWallOptimised
{

using roughWall::Vec3;
using roughWall::RoughWallParameters;
using roughWall::RoughWallReport;
using roughWall::Regime;
namespace fastMath = roughWall::fastMath;

//- -2 ln(1 - U): twice a unit exponential, never infinite
template<class Uniform01>
double twoExponential(Uniform01& uniform01)
{
    return -2*fastMath::log1pMinus(uniform01());
}

//- As roughWall::truncatedStandardNormal
template<class Uniform01>
double truncatedStandardNormal(double h, Uniform01& uniform01)
{
    if (!(h > 0))
    {
        return 0;
    }
    if (h < 1)
    {
        for (int i = 0; i < roughWall::detail::maxRejectionAttempts; ++i)
        {
            const double s = h*uniform01();
            const double u = uniform01();
            // -2 ln(1-u) >= 2u: the logarithm only decides when 2u < s^2
            if (2*u >= s*s || -2*fastMath::log1pMinus(u) >= s*s)
            {
                return s;
            }
        }
    }
    else
    {
        for (int i = 0; i < roughWall::detail::maxRejectionAttempts; i += 2)
        {
            const double r = std::sqrt(twoExponential(uniform01));
            double absCos, absSin;
            fastMath::absCosSinTwoPi(uniform01(), absCos, absSin);
            const double s1 = r*absCos;
            if (s1 < h)
            {
                return s1;
            }
            const double s2 = r*absSin;
            if (s2 < h)
            {
                return s2;
            }
        }
    }
    return roughWall::detail::truncatedStandardNormalByInversion(h, uniform01);
}

//- As roughWall::sampleFacetAngle
template<class Uniform01>
double sampleFacetAngle(double alpha, double Delta, Uniform01& uniform01)
{
    if (!(Delta > 0))
    {
        return 0;
    }
    const double s = truncatedStandardNormal(alpha/Delta, uniform01);
    // as the core: R >= s also where s*s underflows
    const double R = std::max(s, std::sqrt(s*s + twoExponential(uniform01)));
    return Delta*(R - 2*s);
}

namespace detail
{

template<class Uniform01>
double sampleFacetTilt(double alpha, double Delta, Uniform01& uniform01)
{
    for (int i = 0; i < roughWall::detail::maxRejectionAttempts; ++i)
    {
        const double gamma = sampleFacetAngle(alpha, Delta, uniform01);
        if (gamma < roughWall::detail::maxFacetTilt)
        {
            return gamma;
        }
    }
    return 0;
}

//- cos(2 pi u), u in [0, 1)
inline double cosTwoPi(double u)
{
    const double t = 4*u;
    const int q = static_cast<int>(t + 0.5);
    const double x = (t - q)*1.57079632679489655800;
    switch (q & 3)
    {
        case 0: return fastMath::detail::kernelCos(x);
        case 1: return -fastMath::detail::kernelSin(x);
        case 2: return -fastMath::detail::kernelCos(x);
        default: return fastMath::detail::kernelSin(x);
    }
}

template<class Uniform01>
double sampleLateralTilt(double Delta, Uniform01& uniform01)
{
    for (int i = 0; i < roughWall::detail::maxRejectionAttempts; ++i)
    {
        const double r = std::sqrt(twoExponential(uniform01));
        const double delta = Delta*r*cosTwoPi(uniform01());
        if (std::abs(delta) < roughWall::detail::maxFacetTilt)
        {
            return delta;
        }
    }
    return 0;
}

} // namespace detail

//- As roughWall::collideWithRoughWall
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
            // As the core (not on the fast path)
            roughWall::collideWithFacet<withSpin>
            (
                velocity, spin, wallNormal, radius, p.material
            );
            roughWall::detail::leaveMeanWall(velocity, wallNormal);
            report.fallback = true;
            break;
        }

        // Plane of incidence as in the core, with reciprocals: one division
        // for each normalisation instead of three
        const Vec3 scaled = velocity*(1/velocity.cwiseAbs().maxCoeff());
        const Vec3 direction = scaled*(1/scaled.norm());
        const double normalPart = direction.dot(wallNormal);
        Vec3 tangential = direction - normalPart*wallNormal;
        if (twoD)
        {
            tangential -= tangential.dot(emptyDirection)*emptyDirection;
        }
        const double length = tangential.norm();
        Vec3 t = tangential*(1/length);
        t -= t.dot(wallNormal)*wallNormal;
        const double tLength = t.norm();
        if (length > 0 && tLength > 0.5)
        {
            t *= 1/tLength;
        }
        else
        {
            // normal incidence to round-off: the core's random tangent
            t = roughWall::detail::incidenceTangent
            (
                tangential, wallNormal, emptyDirection, twoD, uniform01
            );
        }
        const double alpha = fastMath::atan2FirstQuadrant(-normalPart, length);

        const double gamma = detail::sampleFacetTilt(alpha, Delta, uniform01);
        double sinGamma, cosGamma;
        fastMath::sinCosHalfPi(gamma, sinGamma, cosGamma);
        Vec3 n = cosGamma*wallNormal - sinGamma*t;
        if (lateral)
        {
            // Rotation by delta about the unit incidence direction k
            const double delta = detail::sampleLateralTilt(Delta, uniform01);
            double s, c;
            fastMath::sinCosHalfPi(delta, s, c);
            const Vec3& k = direction;
            n = c*n + s*k.cross(n) + ((1 - c)*k.dot(n))*k;
        }
        if (velocity.dot(n) >= 0)
        {
            continue;
        }
        if (report.facetCollisions == 0)
        {
            report.firstGamma = gamma;
        }
        ++report.facetCollisions;
        const Regime regime = roughWall::collideWithFacet<withSpin>
        (
            velocity, spin, n, radius, p.material
        );
        ++(regime == Regime::noSlip ? report.noSlip : report.sliding);
        if (n == wallNormal)
        {
            // as the core: a facet parallel to the mean wall ends the hit
            roughWall::detail::leaveMeanWall(velocity, wallNormal);
            break;
        }
    }
    return report;
}

} // namespace roughWallOptimised
