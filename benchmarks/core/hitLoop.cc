// roughWallInteraction benchmarks: a plain loop of wall hits, to count
// instructions per hit under callgrind (timing-noise free):
//   valgrind --tool=callgrind --callgrind-out-file=/dev/null (one line)
//       hitLoop rough 1 0 3 mix 8 200000
// benchmarks/scripts/instructionCount.py runs it at two hit counts and
// divides the difference of the collected instruction counts.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Usage: hitLoop model spin lateral dim alpha Delta hits [rng]
//   model    rough | smooth | standard | none (the loop and table alone)
//   spin     0 | 1        lateral 0 | 1        dim 2 | 3
//   alpha    incidence [deg], or "mix" for U(0, 90 deg)
//   Delta    roughness angle [deg]
//   rng      foam (default: v1912's Random) | foam13 (OpenFOAM-13's
//            randomGenerator)
// Prints a checksum of the outgoing velocities.

#include "benchRandom.hh"
#include "incidentTable.hh"

#include "roughWallCollision.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace roughWallBench;
using roughWall::Vec3;

namespace
{

enum class Model { rough, smooth, standard, none };

template<bool withSpin, Model model, class Uniform = FoamUniform01>
double loop
(
    const IncidentTable& table,
    const roughWall::RoughWallParameters& p,
    long hits
)
{
    Uniform uniform01(1);
    const Vec3 nw = -table.wallNormal;
    double checksum = 0;
    for (long n = 0; n < hits; ++n)
    {
        const std::size_t i = n & IncidentTable::mask;
        Vec3 v = table.velocity[i];
        Vec3 w = table.spin[i];
        if constexpr (model == Model::rough)
        {
            roughWall::collideWithRoughWall<withSpin>
            (
                v, w, table.wallNormal, IncidentTable::radius, p, uniform01,
                table.emptyDirection
            );
        }
        else if constexpr (model == Model::smooth)
        {
            roughWall::collideWithFacet<withSpin>
            (
                v, w, table.wallNormal, IncidentTable::radius, p.material
            );
        }
        else if constexpr (model == Model::standard)
        {
            // StandardWallInteraction's rebound (e, mu read at run time)
            const double Un = v.dot(nw);
            const Vec3 Ut = v - Un*nw;
            if (Un > 0)
            {
                v -= (1.0 + p.material.e)*Un*nw;
            }
            v -= p.material.muD*Ut;
        }
        if constexpr (model == Model::none)
        {
            (void)uniform01;
            (void)nw;
        }
        checksum += v.z() + (withSpin ? 1e-6*w.z() : 0);
    }
    return checksum;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 8 && argc != 9)
    {
        std::fprintf(stderr, "usage: hitLoop model spin lateral dim alpha Delta hits [foam|foam13]\n");
        return 2;
    }
    const bool foam13 = argc == 9 && std::string(argv[8]) == "foam13";
    const std::string model = argv[1];
    const bool spin = std::atoi(argv[2]);
    const std::string alpha = argv[5];
    const IncidentTable table
    (
        alpha == "mix" ? -1 : std::atof(alpha.c_str()),
        std::atoi(argv[4]) == 2
    );
    roughWall::RoughWallParameters p;
    p.material = glassOnSteel();
    p.lateralTilt = std::atoi(argv[3]);
    p.roughnessAngle = std::atof(argv[6])*roughWall::pi/180;
    const long hits = std::atol(argv[7]);

    double checksum = 0;
    if (model == "rough" && foam13)
    {
        checksum = spin ? loop<true, Model::rough, Foam13Uniform01>(table, p, hits)
                        : loop<false, Model::rough, Foam13Uniform01>(table, p, hits);
    }
    else if (model == "rough")
    {
        checksum = spin ? loop<true, Model::rough>(table, p, hits)
                        : loop<false, Model::rough>(table, p, hits);
    }
    else if (model == "smooth")
    {
        checksum = spin ? loop<true, Model::smooth>(table, p, hits)
                        : loop<false, Model::smooth>(table, p, hits);
    }
    else if (model == "standard")
    {
        checksum = loop<false, Model::standard>(table, p, hits);
    }
    else
    {
        checksum = spin ? loop<true, Model::none>(table, p, hits)
                        : loop<false, Model::none>(table, p, hits);
    }
    std::printf("%.17g\n", checksum);
    return 0;
}
