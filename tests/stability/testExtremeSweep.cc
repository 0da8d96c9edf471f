// Stability sweep of the rough-wall operator over the extremes of every input,
// alone and combined (full Cartesian product): incidence angle, roughness
// angle, restitution, friction, incident spin, speed, diameter, wall
// orientation, 2-D/3-D, lateral tilt, spin on/off and the collision bound.
// Every case is checked for the invariants of wallHitInvariants.hh and run
// twice from its seed. The tallies go to extremeSweep.md (docs/stability.md).
// SPDX-License-Identifier: GPL-3.0-or-later

#include "sweepSummary.hh"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <random>
#include <string>
#include <vector>

#ifndef ROUGHWALL_STABILITY_STRIDE
#define ROUGHWALL_STABILITY_STRIDE 1   // the sanitizer build runs every k-th case
#endif

using namespace roughWall;
using namespace roughWallStability;

namespace
{

constexpr double deg = pi/180;

//- A wall frame: mean-wall normal N (into the fluid), tangent t of the plane
//  of incidence, z = t x N, and the empty direction of a 2-D case
struct Frame
{
    Vec3 N, t, z, E;
};

Frame axisFrame(bool twoD)
{
    Frame f{Vec3::UnitY(), Vec3::UnitX(), Vec3::UnitZ(), Vec3::Zero()};
    if (twoD) f.E = Vec3::UnitZ();
    return f;
}

//- Oblique 3-D walls (random orientations) and, for 2-D, walls tilted in the
//  x-y plane with the empty direction z; normals normalised as an adapter does
std::vector<Frame> obliqueFrames(bool twoD)
{
    std::mt19937_64 engine(twoD ? 2 : 3);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> unit;
    std::vector<Frame> frames;
    for (int i = 0; i < 7; ++i)
    {
        Frame f;
        if (twoD)
        {
            const double theta = 2*pi*unit(engine);
            f.N = Vec3(-std::sin(theta), std::cos(theta), 0).normalized();
            f.t = Vec3(std::cos(theta), std::sin(theta), 0);
            f.E = Vec3::UnitZ();
        }
        else
        {
            f.N = Vec3(normal(engine), normal(engine), normal(engine)).normalized();
            f.t = f.N.unitOrthogonal();
            f.t = Eigen::AngleAxisd(2*pi*unit(engine), f.N)*f.t;
            f.E = Vec3::Zero();
        }
        f.z = f.t.cross(f.N);
        frames.push_back(f);
    }
    return frames;
}

struct Geometry { std::string name; bool twoD, oblique, lateral; };
const std::vector<Geometry> geometries
{
    {"3-D", false, false, false},
    {"3-D oblique wall", false, true, false},
    {"3-D lateral tilt", false, false, true},
    {"3-D lateral tilt, oblique wall", false, true, true},
    {"2-D", true, false, false},
    {"2-D tilted wall", true, true, false},
};

//- Incidence: angle from the mean wall, or exactly normal (no tangential part)
struct Incidence { std::string name; double alpha; bool exactlyNormal; };
const std::vector<Incidence> incidences
{
    {"0 (along the wall)", 0, false},
    {"1e-300", 1e-300, false},
    {"1e-12", 1e-12, false},
    {"1e-6", 1e-6, false},
    {"1 deg", 1*deg, false},
    {"45 deg", 45*deg, false},
    {"90 deg - 1e-12", 0.5*pi - 1e-12, false},
    {"90 deg (cos = 6e-17)", 0.5*pi, false},
    {"exactly normal", 0.5*pi, true},
};

const std::vector<std::pair<std::string, double>> roughnessAngles
{
    {"0", 0}, {"1e-12", 1e-12}, {"1 deg", 1*deg}, {"8 deg", 8*deg},
    {"30 deg", 30*deg}, {"45 deg", 45*deg},
};

const std::vector<double> restitutions{0, 0.5, 1};

//- (mu0, muD) with muD <= mu0, from {0, 0.4, 10}
const std::vector<std::pair<double, double>> frictions
{
    {0, 0}, {0.4, 0}, {0.4, 0.4}, {10, 0}, {10, 0.4}, {10, 10},
};

//- Incident spin: none, exact rolling on the mean wall (zero slip), or
//  |A_Omega| = r |Omega| / |V| about an axis
enum class SpinAxis { none, rolling, z, N, t, random };
struct Spin { std::string name; SpinAxis axis; double A; };
const std::vector<Spin> spins
{
    {"0", SpinAxis::none, 0},
    {"rolling (zero slip)", SpinAxis::rolling, 0},
    {"A=+1 about t x N", SpinAxis::z, 1},
    {"A=-1 about t x N", SpinAxis::z, -1},
    {"A=+1e3 about t x N", SpinAxis::z, 1e3},
    {"A=-1e3 about t x N", SpinAxis::z, -1e3},
    {"A=+1e6 about t x N", SpinAxis::z, 1e6},
    {"A=-1e6 about t x N", SpinAxis::z, -1e6},
    {"A=1e6 about N", SpinAxis::N, 1e6},
    {"A=1e6 about t", SpinAxis::t, 1e6},
    {"A=1e6 random axis", SpinAxis::random, 1e6},
    {"not modelled (withSpin=false)", SpinAxis::none, 0},
};
const int noSpinModel = static_cast<int>(spins.size()) - 1;

const std::vector<double> speeds{1e-12, 1e-6, 1e-2, 1, 1e4};
const std::vector<double> diameters{1e-7, 1e-5, 1e-3, 1e-2};
const std::vector<int> bounds{1, 10};

template<class T, class F>
std::vector<std::string> names(const std::vector<T>& x, F f)
{
    std::vector<std::string> n;
    for (const auto& v : x) n.push_back(f(v));
    return n;
}

std::string number(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", x);
    return buf;
}

} // namespace

TEST(ExtremeSweep, EveryCombinationKeepsTheInvariants)
{
    const auto start = std::chrono::steady_clock::now();
    SweepSummary summary;
    summary.addFactor("geometry", names(geometries, [](const auto& g) { return g.name; }));
    summary.addFactor("alpha", names(incidences, [](const auto& a) { return a.name; }));
    summary.addFactor("Delta", names(roughnessAngles, [](const auto& d) { return d.first; }));
    summary.addFactor("e", names(restitutions, number));
    summary.addFactor("(mu0, muD)", names(frictions,
        [](const auto& m) { return "(" + number(m.first) + ", " + number(m.second) + ")"; }));
    summary.addFactor("spin", names(spins, [](const auto& s) { return s.name; }));
    summary.addFactor("speed [m/s]", names(speeds, number));
    summary.addFactor("diameter [m]", names(diameters, number));
    summary.addFactor("maxFacetCollisions", names(bounds, [](int b) { return std::to_string(b); }));

    const std::vector<Frame> oblique3D = obliqueFrames(false), oblique2D = obliqueFrames(true);
    std::mt19937_64 axisEngine(4);
    std::normal_distribution<double> normal;

    std::vector<int> level(9);
    unsigned long index = 0;
    for (std::size_t g = 0; g < geometries.size(); ++g)
    for (std::size_t a = 0; a < incidences.size(); ++a)
    for (std::size_t d = 0; d < roughnessAngles.size(); ++d)
    for (std::size_t ie = 0; ie < restitutions.size(); ++ie)
    for (std::size_t m = 0; m < frictions.size(); ++m)
    for (std::size_t s = 0; s < spins.size(); ++s)
    for (std::size_t v = 0; v < speeds.size(); ++v)
    for (std::size_t dp = 0; dp < diameters.size(); ++dp)
    for (std::size_t b = 0; b < bounds.size(); ++b)
    {
        const Geometry& geometry = geometries[g];
        const Spin& spin = spins[s];
        // 2-D cases carry spin about the empty direction only (the adapter
        // removes the rest)
        if (geometry.twoD && (spin.axis == SpinAxis::N || spin.axis == SpinAxis::t
                           || spin.axis == SpinAxis::random))
        {
            continue;
        }
        if (index++ % ROUGHWALL_STABILITY_STRIDE != 0)
        {
            continue;
        }
        const Frame frame = !geometry.oblique ? axisFrame(geometry.twoD)
            : (geometry.twoD ? oblique2D : oblique3D)[index % 7];
        const Incidence& incidence = incidences[a];
        const double V = speeds[v];
        const double r = 0.5*diameters[dp];

        WallHitInput in;
        in.wallNormal = frame.N;
        in.emptyDirection = frame.E;
        in.radius = r;
        in.withSpin = static_cast<int>(s) != noSpinModel;
        in.seed = index;
        in.parameters.material = {restitutions[ie], frictions[m].first, frictions[m].second};
        in.parameters.roughnessAngle = roughnessAngles[d].second;
        in.parameters.lateralTilt = geometry.lateral;
        in.parameters.maxFacetCollisions = bounds[b];

        double Vt = V*std::cos(incidence.alpha);
        const double Vn = V*std::sin(incidence.alpha);
        if (incidence.exactlyNormal) Vt = 0;

        in.spin = Vec3::Zero();
        switch (spin.axis)
        {
            case SpinAxis::none: break;
            case SpinAxis::rolling:
            {
                // Omega = N x v_t / r: the contact point does not slip on the
                // mean wall. In the axis frame r*(Vt/r) is used as Vt so that
                // the slip is exactly zero, not just to round-off.
                const double W = Vt/r;
                in.spin = -W*frame.z;
                if (!geometry.oblique) Vt = r*W;
                break;
            }
            case SpinAxis::z: in.spin = (spin.A*V/r)*frame.z; break;
            case SpinAxis::N: in.spin = (spin.A*V/r)*frame.N; break;
            case SpinAxis::t: in.spin = (spin.A*V/r)*frame.t; break;
            case SpinAxis::random:
                in.spin = (spin.A*V/r)
                    *Vec3(normal(axisEngine), normal(axisEngine), normal(axisEngine)).normalized();
                break;
        }
        if (!in.withSpin)
        {
            // Must be neither read nor written
            in.spin = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
        }
        in.velocity = incidence.exactlyNormal ? Vec3(-V*frame.N) : Vec3(Vt*frame.t - Vn*frame.N);

        level = {int(g), int(a), int(d), int(ie), int(m), int(s), int(v), int(dp), int(b)};
        summary.check(in, [index]() { return StdUniform01<std::mt19937_64>(index); }, level);
    }

    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    summary.write(summaryPath("extremeSweep"), "Extreme sweep (testExtremeSweep.cc)", seconds);
    const Tally& t = summary.total();
    std::printf("[stability] extreme sweep: %ld cases, %ld into the wall, %ld re-collisions, "
                "%ld fallbacks, max energy gain %.2e, max draws %ld, %.1f s\n",
                t.cases, t.intoWall, t.recollisions, t.fallbacks, t.maxEnergyGain, t.maxDraws, seconds);
    summary.expectNoFailures();
    // The sweep reached the paths it is meant to stress
    EXPECT_GT(t.recollisions, 1000 / ROUGHWALL_STABILITY_STRIDE);
    EXPECT_GT(t.fallbacks, 1000 / ROUGHWALL_STABILITY_STRIDE);
}
