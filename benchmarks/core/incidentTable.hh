// roughWallInteraction benchmarks: tables of incident wall hits.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// A benchmark loop cycles through a table of incident velocities and spins
// (so that neither the compiler nor the branch predictor sees one fixed hit):
// speed 10 m/s at incidence alpha on the mean wall z = 0 (normal +z into the
// fluid), tangential direction uniform in the wall plane (3-D) or along +x
// (2-D, empty direction y), spin of magnitude 0.5 V/r about a random axis
// (3-D) or about y (2-D). alpha < 0 draws alpha ~ U(0, 90 deg) per entry.
#pragma once

#include "roughWallCollision.hpp"

#include <cmath>
#include <random>
#include <vector>

namespace roughWallBench
{

using roughWall::Vec3;

struct IncidentTable
{
    static constexpr std::size_t size = 1024;   //!< a power of two
    static constexpr std::size_t mask = size - 1;
    static constexpr double speed = 10;         //!< [m/s]
    static constexpr double radius = 100e-6;    //!< [m]

    Vec3 wallNormal{0, 0, 1};
    Vec3 emptyDirection{0, 0, 0};
    std::vector<Vec3> velocity;
    std::vector<Vec3> spin;

    IncidentTable(double alphaDeg, bool twoD, unsigned seed = 12345)
    {
        std::mt19937_64 engine(seed);
        std::uniform_real_distribution<double> uniform(0, 1);
        const double deg = roughWall::pi/180;
        if (twoD)
        {
            emptyDirection = Vec3(0, 1, 0);
        }
        velocity.reserve(size);
        spin.reserve(size);
        for (std::size_t i = 0; i < size; ++i)
        {
            const double alpha =
                alphaDeg < 0 ? 90*deg*(1 - uniform(engine)) : alphaDeg*deg;
            const double azimuth = twoD ? 0 : 2*roughWall::pi*uniform(engine);
            const Vec3 t(std::cos(azimuth), std::sin(azimuth), 0);
            velocity.push_back(speed*(std::cos(alpha)*t - std::sin(alpha)*wallNormal));

            Vec3 axis = emptyDirection;
            if (!twoD)
            {
                const double c = 2*uniform(engine) - 1;
                const double phi = 2*roughWall::pi*uniform(engine);
                const double s = std::sqrt(1 - c*c);
                axis = Vec3(s*std::cos(phi), s*std::sin(phi), c);
            }
            spin.push_back((0.5*speed/radius)*axis);
        }
    }
};

//- Glass beads on steel (Sommerfeld's data, the paper's comparison)
inline roughWall::FacetMaterial glassOnSteel()
{
    return roughWall::FacetMaterial{0.8, 0.4, 0.4};
}

} // namespace roughWallBench
