// Long chains of wall hits, each hit fed with the previous one's output (its
// spin included), as a tracker does:
//  - a particle bouncing between two walls: after each rough-wall hit the
//    normal velocity is mirrored (the opposite wall, energy-neutral) and a
//    small kick toward the wall is added, so that even e = 0 returns;
//  - a particle resting or sliding on a floor under gravity: each time step
//    adds g dt toward the wall and the rough wall is hit whenever the particle
//    moves into it (the grazing, near-zero normal speeds a settled parcel has).
// Every hit is checked for the invariants of wallHitInvariants.hh and re-run
// from its seed; over the chain, sqrt(2 E) (E: kinetic energy per unit mass,
// spin included) may grow by at most the kicks: hits never add energy.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "sweepSummary.hh"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#ifndef ROUGHWALL_STABILITY_STRIDE
#define ROUGHWALL_STABILITY_STRIDE 1   // the sanitizer build runs shorter chains
#endif

using namespace roughWall;
using namespace roughWallStability;

namespace
{

constexpr double deg = pi/180;

struct Geometry { std::string name; Vec3 N, t, E; bool lateral; };

std::vector<Geometry> geometries()
{
    const Vec3 oblique = Vec3(0.3, -0.8, 0.52).normalized();
    const double theta = 0.7;
    const Vec3 tilted2D = Vec3(-std::sin(theta), std::cos(theta), 0).normalized();
    return
    {
        {"3-D", Vec3::UnitY(), Vec3::UnitX(), Vec3::Zero(), false},
        {"3-D oblique wall, lateral tilt", oblique, oblique.unitOrthogonal(), Vec3::Zero(), true},
        {"2-D tilted wall", tilted2D, Vec3(std::cos(theta), std::sin(theta), 0), Vec3::UnitZ(), false},
    };
}

const std::vector<std::pair<std::string, double>> Deltas{{"0", 0}, {"8 deg", 8*deg}, {"45 deg", 45*deg}};
const std::vector<double> restitutions{0, 0.5, 0.9, 1};
const std::vector<std::pair<double, double>> frictions{{0, 0}, {0.4, 0.4}, {10, 10}};

//- sqrt(2 E): the length of (v, sqrt(2/5) r w)
double energyNorm(const Vec3& v, const Vec3& w, double r, bool withSpin)
{
    return std::sqrt(v.squaredNorm() + (withSpin ? 0.4*r*r*w.squaredNorm() : 0.0));
}

double seconds(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

TEST(RepeatedHits, BouncingBetweenTwoWalls)
{
    const auto start = std::chrono::steady_clock::now();
    const int hits = 5000/ROUGHWALL_STABILITY_STRIDE;
    const double kick = 1e-3;   // [m/s] toward the wall after each return
    const auto frames = geometries();
    SweepSummary summary;
    std::vector<std::string> frameNames;
    for (const auto& g : frames) frameNames.push_back(g.name);
    summary.addFactor("geometry", frameNames);
    summary.addFactor("Delta", {"0", "8 deg", "45 deg"});
    summary.addFactor("e", {"0", "0.5", "0.9", "1"});
    summary.addFactor("(mu0 = muD)", {"0", "0.4", "10"});
    summary.addFactor("spin model", {"with spin", "without spin"});

    long chains = 0;
    double largestGrowth = -std::numeric_limits<double>::infinity();
    for (std::size_t g = 0; g < frames.size(); ++g)
    for (std::size_t d = 0; d < Deltas.size(); ++d)
    for (std::size_t ie = 0; ie < restitutions.size(); ++ie)
    for (std::size_t m = 0; m < frictions.size(); ++m)
    for (int spinModel = 0; spinModel < 2; ++spinModel)
    {
        const Geometry& f = frames[g];
        WallHitInput in;
        in.wallNormal = f.N;
        in.emptyDirection = f.E;
        in.radius = 5e-5;
        in.withSpin = spinModel == 0;
        in.parameters.material = {restitutions[ie], frictions[m].first, frictions[m].second};
        in.parameters.roughnessAngle = Deltas[d].second;
        in.parameters.lateralTilt = f.lateral;
        in.velocity = 10*(std::cos(30*deg)*f.t - std::sin(30*deg)*f.N);
        in.spin = in.withSpin ? Vec3(Vec3::Zero()) : Vec3::Constant(std::nan(""));

        const double E0 = energyNorm(in.velocity, in.spin, in.radius, in.withSpin);
        double added = 0;
        for (int k = 0; k < hits; ++k)
        {
            const unsigned long seed = 1000003ul*chains + k;
            const auto makeSource = [seed]() { return StdUniform01<std::mt19937_64>(seed); };
            in.seed = seed;
            summary.check(in, makeSource, {int(g), int(d), int(ie), int(m), spinModel});
            auto source = makeSource();
            const WallHitResult out = hitWall(in, source);
            // The opposite wall: mirror the normal velocity, then the kick
            in.velocity = out.velocity - 2*out.velocity.dot(f.N)*f.N - kick*f.N;
            in.spin = out.spin;
            added += kick;
            const double E = energyNorm(in.velocity, in.spin, in.radius, in.withSpin);
            const double growth = (E - E0 - added)/E0;
            largestGrowth = std::max(largestGrowth, growth);
            ASSERT_LE(growth, 1e-12*(k + 1)) << "hit " << k << ": " << describe(in);
        }
        ++chains;
    }
    summary.write(summaryPath("bouncingChains"), "Bouncing between two walls (testRepeatedHits.cc)", seconds(start));
    std::printf("[stability] %ld bouncing chains of %d hits, largest energy growth beyond the kicks %.2e\n",
                chains, hits, largestGrowth);
    summary.expectNoFailures();
}

TEST(RepeatedHits, RestingAndSlidingOnAFloorUnderGravity)
{
    // Gravity g = 9.81 m/s^2 with time steps from 1e-5 to 1e-3 s: normal
    // speeds from 1e-4 m/s at a hit, tangential speeds from 0 (resting) to
    // 1 m/s (sliding, grazing incidence down to 1e-4 rad)
    const auto start = std::chrono::steady_clock::now();
    const int steps = 4000/ROUGHWALL_STABILITY_STRIDE;
    const double g = 9.81;
    const auto frames = geometries();
    const std::vector<double> timeSteps{1e-5, 1e-4, 1e-3};
    const std::vector<double> slideSpeeds{0, 1e-2, 1};
    SweepSummary summary;
    std::vector<std::string> frameNames;
    for (const auto& f : frames) frameNames.push_back(f.name);
    summary.addFactor("geometry", frameNames);
    summary.addFactor("Delta", {"0", "8 deg", "45 deg"});
    summary.addFactor("e", {"0", "0.5", "0.9", "1"});
    summary.addFactor("time step [s]", {"1e-5", "1e-4", "1e-3"});
    summary.addFactor("initial sliding speed [m/s]", {"0", "0.01", "1"});

    long chains = 0, totalHits = 0, totalFacetCollisions = 0, totalDraws = 0;
    for (std::size_t gi = 0; gi < frames.size(); ++gi)
    for (std::size_t d = 0; d < Deltas.size(); ++d)
    for (std::size_t ie = 0; ie < restitutions.size(); ++ie)
    for (std::size_t it = 0; it < timeSteps.size(); ++it)
    for (std::size_t is = 0; is < slideSpeeds.size(); ++is)
    {
        const Geometry& f = frames[gi];
        const double dt = timeSteps[it];
        WallHitInput in;
        in.wallNormal = f.N;
        in.emptyDirection = f.E;
        in.radius = 5e-5;
        in.parameters.material = {restitutions[ie], 0.4, 0.4};
        in.parameters.roughnessAngle = Deltas[d].second;
        in.parameters.lateralTilt = f.lateral;
        in.velocity = slideSpeeds[is]*f.t;
        in.spin = Vec3::Zero();

        const double E0 = energyNorm(in.velocity, in.spin, in.radius, true);
        int hits = 0;
        for (int k = 0; k < steps; ++k)
        {
            in.velocity -= g*dt*f.N;
            if (!(in.velocity.dot(f.N) < 0)) continue;
            const unsigned long seed = 1000003ul*chains + k;
            const auto makeSource = [seed]() { return StdUniform01<std::mt19937_64>(seed); };
            in.seed = seed;
            summary.check(in, makeSource, {int(gi), int(d), int(ie), int(it), int(is)});
            auto source = makeSource();
            const WallHitResult out = hitWall(in, source);
            in.velocity = out.velocity;
            in.spin = out.spin;
            ++hits;
            totalFacetCollisions += out.report.facetCollisions;
            totalDraws += out.draws;
            const double E = energyNorm(in.velocity, in.spin, in.radius, true);
            ASSERT_LE(E, (E0 + (k + 1)*g*dt)*(1 + 1e-12*(k + 1)) + 1e-300)
                << "step " << k << ": " << describe(in);
        }
        totalHits += hits;
        ++chains;
    }
    summary.write(summaryPath("floorChains"), "Resting and sliding on a floor under gravity (testRepeatedHits.cc)", seconds(start));
    const double collisionsPerHit = double(totalFacetCollisions)/totalHits;
    const double drawsPerHit = double(totalDraws)/totalHits;
    std::printf("[stability] %ld floor chains, %ld hits, %.3f facet collisions and %.2f uniform draws per hit\n",
                chains, totalHits, collisionsPerHit, drawsPerHit);
    summary.expectNoFailures();
    // The cost of a hit stays that of a few facet collisions
    EXPECT_LT(collisionsPerHit, 3);
    EXPECT_LT(drawsPerHit, 15);
}
