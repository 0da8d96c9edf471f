// roughWallInteraction benchmarks: a plain loop of wall hits with e and muD
// as tables of the facet impact angle (issue 31) or as constants, for
// instruction counts under callgrind, like hitLoop.cc (which stays as it is,
// so that benchmarks/scripts/compareInstructions.sh can compare it across
// commits):
//   valgrind --tool=callgrind --callgrind-out-file=/dev/null
//       impactHitLoop table 1 8 200000
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Usage: impactHitLoop coefficients spin Delta hits
//   coefficients  constant (e 0.85, mu0 0.4, muD 0.22) | table (e, muD:
//                 docs/impactDependent/eAngle.dat, muDAngle.dat typed in;
//                 mu0 0.4; bounds proven at start-up, not per call)
//   spin 0 | 1, Delta [deg], hits; 3-D, alpha U(0, 90 deg), no lateral tilt
// Prints a checksum of the outgoing velocities.

#include "benchRandom.hh"
#include "incidentTable.hh"

#include "impactCoefficients.hpp"
#include "roughWallCollision.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace roughWallBench;
using roughWall::Vec3;

namespace
{

template<bool withSpin, class Coefficients>
double loop
(
    const IncidentTable& table,
    const roughWall::RoughWallParametersOf<Coefficients>& p,
    long hits
)
{
    FoamUniform01 uniform01(1);
    double checksum = 0;
    for (long n = 0; n < hits; ++n)
    {
        const std::size_t i = n & IncidentTable::mask;
        Vec3 v = table.velocity[i];
        Vec3 w = table.spin[i];
        roughWall::collideWithRoughWall<withSpin>
        (
            v, w, table.wallNormal, IncidentTable::radius, p, uniform01,
            table.emptyDirection
        );
        checksum += v.z() + (withSpin ? 1e-6*w.z() : 0);
    }
    return checksum;
}

template<class Coefficients>
double run(const IncidentTable& table, const Coefficients& c, bool spin, double Delta, long hits)
{
    roughWall::RoughWallParametersOf<Coefficients> p{c};
    p.roughnessAngle = Delta*roughWall::pi/180;
    return spin ? loop<true>(table, p, hits) : loop<false>(table, p, hits);
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 5)
    {
        std::fprintf(stderr, "usage: impactHitLoop constant|table spin Delta hits\n");
        return 2;
    }
    const IncidentTable table(-1, false);
    const bool spin = std::atoi(argv[2]);
    const double Delta = std::atof(argv[3]);
    const long hits = std::atol(argv[4]);
    double checksum = 0;
    if (std::string(argv[1]) == "table")
    {
        const roughWall::LinearTable e{{{0, 0.95}, {10, 0.90}, {20, 0.85}, {40, 0.78}, {90, 0.75}}};
        const roughWall::LinearTable muD{{{0, 0.40}, {10, 0.30}, {20, 0.22}, {40, 0.15}, {90, 0.15}}};
        const auto mu0 = [](double) { return 0.4; };
        checksum = run
        (
            table,
            roughWall::impactFunctions(e, mu0, muD, roughWall::ImpactArgument::angle, false),
            spin, Delta, hits
        );
    }
    else
    {
        checksum = run(table, roughWall::FacetMaterial{0.85, 0.4, 0.22}, spin, Delta, hits);
    }
    std::printf("%.17g\n", checksum);
    return 0;
}
