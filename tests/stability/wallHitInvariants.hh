// Invariants of one rough-wall hit, shared by the stability sweeps (GoogleTest,
// g++) and the libFuzzer target (clang++): every output finite, the particle
// leaves the mean wall, kinetic energy (translational + rotational) not
// increased beyond round-off, the facet-collision bound respected, a 2-D hit
// kept in its plane, a particle moving away left bit-for-bit unchanged, and
// the result reproducible from the random stream.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "roughWallCollision.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>

namespace roughWallStability
{

using roughWall::RoughWallParameters;
using roughWall::RoughWallReport;
using roughWall::Vec3;

//- One call of collideWithRoughWall: everything it reads
struct WallHitInput
{
    Vec3 velocity = Vec3::Zero();
    Vec3 spin = Vec3::Zero();
    Vec3 wallNormal = Vec3::UnitY();
    Vec3 emptyDirection = Vec3::Zero();   //!< zero in 3-D
    double radius = 1e-4;
    RoughWallParameters parameters;
    bool withSpin = true;
    unsigned long seed = 0;   //!< of the random stream, for the record only
};

//- Everything it returns, and how many uniform numbers it drew
struct WallHitResult
{
    Vec3 velocity = Vec3::Zero();
    Vec3 spin = Vec3::Zero();
    RoughWallReport report;
    long draws = 0;
};

//- Relative energy tolerance, about 450 ulps: a hit does some 30 rounded
//  operations per facet collision and rarely more than 10 collisions (the
//  sweeps measure at most 14 ulps). A facet normal that is not unit to
//  1e-13 (a tangent not orthogonal to the wall) is caught.
constexpr double energyTolerance = 1e-13;

//- Uniform numbers one facet draw may take from a random stream before the
//  draw-count check calls it a stall (expected about 4; the sampler's
//  rejection loops accept with probability >= 0.6, so 100 is never reached
//  by chance)
constexpr long drawsPerFacetLimit = 100;

//- The most uniform numbers one facet draw can take from any stream, even a
//  stuck one: every rejection loop at its attempt limit (tangent 1, tilt
//  attempts x (facet-angle attempts x (a normal variate + 1) + the inversion
//  fallback 1), lateral tilt attempts x a normal variate). More means a loop
//  without its bound.
constexpr long drawsPerFacetHardLimit = 1
    + roughWall::detail::maxRejectionAttempts
     *(roughWall::detail::maxRejectionAttempts*(roughWall::maxStandardNormalDraws + 1) + 1)
    + roughWall::detail::maxRejectionAttempts*roughWall::maxStandardNormalDraws;

//- Run the operator on a copy of the input with a uniform source
template<class Uniform01>
WallHitResult hitWall(const WallHitInput& in, Uniform01& source)
{
    WallHitResult out;
    out.velocity = in.velocity;
    out.spin = in.spin;
    long draws = 0;
    auto counting = [&source, &draws]() { ++draws; return source(); };
    out.report = in.withSpin
        ? roughWall::collideWithRoughWall<true>
          (
              out.velocity, out.spin, in.wallNormal, in.radius, in.parameters,
              counting, in.emptyDirection
          )
        : roughWall::collideWithRoughWall<false>
          (
              out.velocity, out.spin, in.wallNormal, in.radius, in.parameters,
              counting, in.emptyDirection
          );
    out.draws = draws;
    return out;
}

//- Bitwise equality (NaN == NaN, -0 != +0): "reproducible" and "unchanged"
inline bool sameBits(const Vec3& a, const Vec3& b)
{
    return std::memcmp(a.data(), b.data(), 3*sizeof(double)) == 0;
}

inline bool sameResult(const WallHitResult& a, const WallHitResult& b)
{
    const auto& ra = a.report;
    const auto& rb = b.report;
    return sameBits(a.velocity, b.velocity) && sameBits(a.spin, b.spin)
        && ra.facetCollisions == rb.facetCollisions && ra.noSlip == rb.noSlip
        && ra.sliding == rb.sliding && ra.fallback == rb.fallback
        && std::memcmp(&ra.firstGamma, &rb.firstGamma, sizeof(double)) == 0
        && a.draws == b.draws;
}

//- Kinetic energy per unit mass in units of scale^2 (no under/overflow for
//  any speed): v^2/2 + I w^2/(2m) with I = (2/5) m r^2
inline double scaledEnergy(const Vec3& v, const Vec3& w, double r, bool withSpin, double scale)
{
    double E = 0.5*(v/scale).squaredNorm();
    if (withSpin)
    {
        E += 0.2*((r*w)/scale).squaredNorm();
    }
    return E;
}

//- Energy after over energy before minus 1 (<= 0 when energy is not gained)
inline double energyGain(const WallHitInput& in, const WallHitResult& out)
{
    double scale = in.velocity.cwiseAbs().maxCoeff();
    if (in.withSpin)
    {
        scale = std::max(scale, (in.radius*in.spin).cwiseAbs().maxCoeff());
    }
    if (!(scale > 0))
    {
        return 0;
    }
    const double E0 = scaledEnergy(in.velocity, in.spin, in.radius, in.withSpin, scale);
    const double E1 = scaledEnergy(out.velocity, out.spin, in.radius, in.withSpin, scale);
    return E1/E0 - 1;
}

//- Allowed energy gain: relative round-off, plus the absolute round-off of
//  subnormal numbers (a few units of denorm_min in a velocity component, or
//  in a spin component, which is r denorm_min in r*Omega), relative to the
//  scale. Only inputs far outside the physical range (|v| < 1e-290 m/s, or
//  r > 1e15 |v| m with a subnormal spin) come near it.
inline double allowedEnergyGain(const WallHitInput& in)
{
    double scale = in.velocity.cwiseAbs().maxCoeff();
    double subnormalStep = 1;   // velocity units per denorm_min
    if (in.withSpin)
    {
        scale = std::max(scale, (in.radius*in.spin).cwiseAbs().maxCoeff());
        subnormalStep = std::max(1.0, in.radius);
    }
    const double tiny = 1e3*subnormalStep*std::numeric_limits<double>::denorm_min();
    return energyTolerance + (scale > 0 ? tiny/scale : 0);
}

//- Index of the coordinate axis e is, or -1
inline int coordinateAxis(const Vec3& e)
{
    for (int i = 0; i < 3; ++i)
    {
        if (e == Vec3::Unit(i)) return i;
    }
    return -1;
}

//- Hex-float dump of an input: paste it back to reproduce a failure exactly
inline std::string describe(const WallHitInput& in)
{
    std::ostringstream os;
    char buf[64];
    const auto hex = [&](double x) { std::snprintf(buf, sizeof buf, "%a", x); return std::string(buf); };
    const auto vec = [&](const Vec3& v) { return "(" + hex(v.x()) + ", " + hex(v.y()) + ", " + hex(v.z()) + ")"; };
    const auto& p = in.parameters;
    os << "withSpin=" << in.withSpin << " velocity=" << vec(in.velocity)
       << " spin=" << vec(in.spin) << " wallNormal=" << vec(in.wallNormal)
       << " emptyDirection=" << vec(in.emptyDirection) << " radius=" << hex(in.radius)
       << " e=" << hex(p.material.e) << " mu0=" << hex(p.material.mu0)
       << " muD=" << hex(p.material.muD) << " Delta=" << hex(p.roughnessAngle)
       << " lateralTilt=" << p.lateralTilt << " maxFacetCollisions=" << p.maxFacetCollisions
       << " seed=" << in.seed;
    return os.str();
}

//- The invariants of one hit; "" if all hold, else what failed
//  drawLimit: uniform numbers allowed per facet draw (drawsPerFacetLimit for
//  a random stream, drawsPerFacetHardLimit for an adversarial one)
inline std::string violation
(
    const WallHitInput& in,
    const WallHitResult& out,
    long drawLimit = drawsPerFacetLimit
)
{
    const auto& r = out.report;
    const Vec3& N = in.wallNormal;
    const int maxCollisions = std::max(0, in.parameters.maxFacetCollisions);

    if (!out.velocity.allFinite())
    {
        return "velocity not finite";
    }
    if (in.withSpin ? !out.spin.allFinite() : !sameBits(out.spin, in.spin))
    {
        return in.withSpin ? "spin not finite" : "spin touched without spin";
    }
    if (!(in.velocity.dot(N) < 0))
    {
        // Not moving into the wall: returned unchanged
        if (!sameBits(out.velocity, in.velocity) || !sameBits(out.spin, in.spin)
         || r.facetCollisions != 0 || r.fallback || r.noSlip || r.sliding || out.draws)
        {
            return "a particle not moving into the wall was changed";
        }
        return "";
    }
    if (!(out.velocity.dot(N) >= 0))
    {
        std::ostringstream os;
        os << "does not leave the wall: v.N = " << out.velocity.dot(N)
           << " (|v| = " << out.velocity.norm() << ")";
        return os.str();
    }
    const double gain = energyGain(in, out);
    if (!(gain <= allowedEnergyGain(in)))
    {
        std::ostringstream os;
        os << "kinetic energy increased by a factor 1 + " << gain;
        return os.str();
    }
    if (r.facetCollisions < 0 || r.facetCollisions > maxCollisions)
    {
        return "facet collisions " + std::to_string(r.facetCollisions)
             + " outside [0, " + std::to_string(maxCollisions) + "]";
    }
    if (r.facetCollisions == 0 && !r.fallback)
    {
        return "moving into the wall but neither a facet collision nor the fallback";
    }
    if (r.noSlip < 0 || r.sliding < 0 || r.noSlip + r.sliding != r.facetCollisions)
    {
        return "regime counts do not add up to the facet collisions";
    }
    if (r.facetCollisions > 0 && !(std::abs(r.firstGamma) < 0.5*roughWall::pi))
    {
        return "first facet tilt outside (-90, 90) deg";
    }
    if (out.draws > drawLimit*(maxCollisions + 1))
    {
        return "stall: " + std::to_string(out.draws) + " uniform draws";
    }
    const int axis = coordinateAxis(in.emptyDirection);
    if (axis >= 0 && in.velocity[axis] == 0 && N[axis] == 0)
    {
        // 2-D: in-plane velocity and spin about the empty direction stay so
        bool spinInPlane = true;
        for (int i = 0; i < 3; ++i)
        {
            spinInPlane = spinInPlane && (i == axis || in.spin[i] == 0);
        }
        if (out.velocity[axis] != 0)
        {
            return "2-D: velocity left the plane";
        }
        if (in.withSpin && spinInPlane)
        {
            for (int i = 0; i < 3; ++i)
            {
                if (i != axis && out.spin[i] != 0)
                {
                    return "2-D: spin left the empty direction";
                }
            }
        }
    }
    return "";
}

} // namespace roughWallStability
