// roughWallInteraction benchmarks: cost of one wall hit in the core, and of
// one sample of the facet-tilt distribution (Google Benchmark).
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark names are "/"-separated key:value pairs, parsed by
// benchmarks/scripts/hitCost.py:
//   hit/model:rough/spin:1/lateral:0/dim:3/alpha:5/Delta:8/rng:foam
//       collideWithRoughWall<spin> (sample, tilt, collide, re-collide);
//       rng:foam is v1912's Random (Rand48 through uniform_real_distribution),
//       rng:foam13 OpenFOAM-13's randomGenerator, rng:mt19937 the tests'
//       source
//   hit/model:smooth/spin:1/dim:3/alpha:5/rng:foam
//       collideWithFacet<spin> with the mean-wall normal: a smooth hard-sphere
//       rebound with the same friction law
//   hit/model:standard/alpha:5
//       the rebound arithmetic of OpenFOAM's StandardWallInteraction (e, mu)
//   uniform01/rng:foam             one uniform draw (also rng:foam13, mt19937)
//   sampler/method:exact/h:1       one sample of P(gamma, alpha), h = alpha/Delta
//   roughness/delta:constant/alpha:mix   a hit with the constant Delta
//   roughness/delta:profile/sizes:N/alpha:mix   the same hit with Delta from
//       the wall's profile (profileRoughness.hpp) for a cloud of N diameters
//       met in turn (N = 0: every hit a new diameter, no cache hit)
// alpha:mix draws alpha ~ U(0, 90 deg) per hit. Counters: facetCollisions
// (mean per hit), fallbacks (fraction of hits), proposals (rejection sampler).

#include "benchRandom.hh"
#include "incidentTable.hh"
#include "referenceSamplers.hh"

#include "roughWallCollision.hpp"
#include "profileRoughness.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace roughWallBench;
using roughWall::Vec3;

namespace
{

constexpr double deg = roughWall::pi/180;

std::string alphaName(double alphaDeg)
{
    std::ostringstream os;
    if (alphaDeg < 0)
    {
        os << "mix";
    }
    else
    {
        os << alphaDeg;
    }
    return os.str();
}

template<bool withSpin, class Uniform>
void roughHit
(
    benchmark::State& state,
    double alphaDeg,
    double DeltaDeg,
    bool lateral,
    bool twoD
)
{
    const IncidentTable table(alphaDeg, twoD);
    roughWall::RoughWallParameters p;
    p.material = glassOnSteel();
    p.roughnessAngle = DeltaDeg*deg;
    p.lateralTilt = lateral;
    Uniform uniform01(1);

    std::size_t i = 0;
    long facetCollisions = 0, fallbacks = 0;
    for (auto _ : state)
    {
        Vec3 v = table.velocity[i];
        Vec3 w = table.spin[i];
        i = (i + 1) & IncidentTable::mask;
        const roughWall::RoughWallReport report =
            roughWall::collideWithRoughWall<withSpin>
            (
                v, w, table.wallNormal, IncidentTable::radius, p, uniform01,
                table.emptyDirection
            );
        benchmark::DoNotOptimize(v);
        benchmark::DoNotOptimize(w);
        facetCollisions += report.facetCollisions;
        fallbacks += report.fallback;
    }
    const double hits = static_cast<double>(state.iterations());
    state.SetItemsProcessed(state.iterations());
    state.counters["facetCollisions"] = facetCollisions/hits;
    state.counters["fallbacks"] = fallbacks/hits;
}

//- A rough hit whose Delta comes from the profile parameters and the
//  particle diameter (nSizes > 0: nSizes diameters met in turn; 0: a new
//  diameter every hit) or, with nSizes < 0, the constant Delta of the same
//  profile; everything else as roughHit (3-D, spin, FoamUniform01, alpha
//  uniform in (0, 90 deg))
void profileHit(benchmark::State& state, int nSizes)
{
    const IncidentTable table(-1, false);
    roughWall::ProfileRoughness profile;
    profile.Rq = 2e-6;
    profile.RSm = 60e-6;
    const roughWall::RoughnessCorrelation correlation(profile);

    roughWall::RoughWallParameters p;
    p.material = glassOnSteel();
    p.roughnessAngle = correlation.angleUncached(30e-6);
    FoamUniform01 uniform01(1);

    // Diameters in (10, 60] um, all at or below RSm: every size has the
    // same Delta as the constant case, so that only the look-up differs
    std::vector<double> diameters(IncidentTable::mask + 1);
    for (std::size_t k = 0; k < diameters.size(); ++k)
    {
        const double f =
            nSizes > 0
          ? static_cast<double>(k % nSizes + 1)/nSizes
          : static_cast<double>(k + 1)/diameters.size();
        diameters[k] = 10e-6 + 50e-6*f;
    }

    std::size_t i = 0;
    for (auto _ : state)
    {
        Vec3 v = table.velocity[i];
        Vec3 w = table.spin[i];
        if (nSizes >= 0)
        {
            p.roughnessAngle = correlation.angle(diameters[i]);
        }
        i = (i + 1) & IncidentTable::mask;
        roughWall::collideWithRoughWall<true>
        (
            v, w, table.wallNormal, IncidentTable::radius, p, uniform01,
            table.emptyDirection
        );
        benchmark::DoNotOptimize(v);
        benchmark::DoNotOptimize(w);
    }
    state.SetItemsProcessed(state.iterations());
}

template<bool withSpin>
void smoothHit(benchmark::State& state, double alphaDeg, bool twoD)
{
    const IncidentTable table(alphaDeg, twoD);
    const roughWall::FacetMaterial material = glassOnSteel();

    std::size_t i = 0;
    for (auto _ : state)
    {
        Vec3 v = table.velocity[i];
        Vec3 w = table.spin[i];
        i = (i + 1) & IncidentTable::mask;
        roughWall::collideWithFacet<withSpin>
        (
            v, w, table.wallNormal, IncidentTable::radius, material
        );
        benchmark::DoNotOptimize(v);
        benchmark::DoNotOptimize(w);
    }
    state.SetItemsProcessed(state.iterations());
}

//- StandardWallInteraction::correct, rebound branch (OpenFOAM v1912), with
//  e = 0.8, mu = 0 (read at run time, as OpenFOAM reads them from its
//  dictionary, so that the compiler cannot drop the mu term): nw is
//  OpenFOAM's outward patch normal
void standardHit(benchmark::State& state, double alphaDeg)
{
    const IncidentTable table(alphaDeg, false);
    const Vec3 nw = -table.wallNormal;
    volatile double eIn = 0.8, muIn = 0;
    const double e = eIn, mu = muIn;

    std::size_t i = 0;
    for (auto _ : state)
    {
        Vec3 U = table.velocity[i];
        i = (i + 1) & IncidentTable::mask;
        const double Un = U.dot(nw);
        const Vec3 Ut = U - Un*nw;
        if (Un > 0)
        {
            U -= (1.0 + e)*Un*nw;
        }
        U -= mu*Ut;
        benchmark::DoNotOptimize(U);
    }
    state.SetItemsProcessed(state.iterations());
}

template<class Uniform>
void uniformDraw(benchmark::State& state)
{
    Uniform uniform01(1);
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(uniform01());
    }
    state.SetItemsProcessed(state.iterations());
}

enum class Sampler { exact, inversion, rejection, noShadow };

void facetAngleSample(benchmark::State& state, Sampler method, double h)
{
    // Standardised: the cost depends on h = alpha/Delta only
    const double Delta = 8*deg;
    const double alpha = h*Delta;
    FoamUniform01 uniform01(1);
    for (auto _ : state)
    {
        double gamma = 0;
        switch (method)
        {
            case Sampler::exact:
                gamma = roughWall::sampleFacetAngle(alpha, Delta, uniform01);
                break;
            case Sampler::inversion:
                gamma = roughWall::sampleFacetAngleByInversion(alpha, Delta, uniform01);
                break;
            case Sampler::rejection:
                gamma = sampleFacetAngleByRejection(alpha, Delta, uniform01);
                break;
            case Sampler::noShadow:
                gamma = sampleFacetAngleWithoutShadow(alpha, Delta, uniform01);
                break;
        }
        benchmark::DoNotOptimize(gamma);
    }
    state.SetItemsProcessed(state.iterations());
    if (method == Sampler::rejection)
    {
        state.counters["proposals"] = rejectionProposalsPerSample(h);
    }
}

void registerAll()
{
    // Delta from the profile parameters against a constant Delta
    benchmark::RegisterBenchmark
    (
        "roughness/delta:constant/alpha:mix", profileHit, -1
    );
    for (const int n : {1, 3, 8, 0})
    {
        benchmark::RegisterBenchmark
        (
            ("roughness/delta:profile/sizes:" + std::to_string(n) + "/alpha:mix").c_str(),
            profileHit, n
        );
    }

    const std::vector<double> alphas{-1, 1, 5, 15, 45, 85};
    const std::vector<double> Deltas{0, 2, 8, 20, 45};

    for (const double a : alphas)
    {
        const std::string an = alphaName(a);
        for (const double D : Deltas)
        {
            std::ostringstream Dn;
            Dn << D;
            const std::string tail = "/alpha:" + an + "/Delta:" + Dn.str();
            benchmark::RegisterBenchmark
            (
                ("hit/model:rough/spin:1/lateral:0/dim:3" + tail + "/rng:foam").c_str(),
                roughHit<true, FoamUniform01>, a, D, false, false
            );
            // OpenFOAM-13's random source (the first platform)
            benchmark::RegisterBenchmark
            (
                ("hit/model:rough/spin:1/lateral:0/dim:3" + tail + "/rng:foam13").c_str(),
                roughHit<true, Foam13Uniform01>, a, D, false, false
            );
            benchmark::RegisterBenchmark
            (
                ("hit/model:rough/spin:0/lateral:0/dim:3" + tail + "/rng:foam").c_str(),
                roughHit<false, FoamUniform01>, a, D, false, false
            );
            benchmark::RegisterBenchmark
            (
                ("hit/model:rough/spin:1/lateral:1/dim:3" + tail + "/rng:foam").c_str(),
                roughHit<true, FoamUniform01>, a, D, true, false
            );
            benchmark::RegisterBenchmark
            (
                ("hit/model:rough/spin:0/lateral:0/dim:2" + tail + "/rng:foam").c_str(),
                roughHit<false, FoamUniform01>, a, D, false, true
            );
        }
        // The random source: the core tests' mt19937_64 at Delta = 8 deg
        benchmark::RegisterBenchmark
        (
            ("hit/model:rough/spin:1/lateral:0/dim:3/alpha:" + an + "/Delta:8/rng:mt19937").c_str(),
            roughHit<true, Mt19937Uniform01>, a, 8.0, false, false
        );

        benchmark::RegisterBenchmark
        (
            ("hit/model:smooth/spin:1/dim:3/alpha:" + an + "/rng:none").c_str(),
            smoothHit<true>, a, false
        );
        benchmark::RegisterBenchmark
        (
            ("hit/model:smooth/spin:0/dim:3/alpha:" + an + "/rng:none").c_str(),
            smoothHit<false>, a, false
        );
        benchmark::RegisterBenchmark
        (
            ("hit/model:smooth/spin:0/dim:2/alpha:" + an + "/rng:none").c_str(),
            smoothHit<false>, a, true
        );
        benchmark::RegisterBenchmark
        (
            ("hit/model:standard/alpha:" + an).c_str(), standardHit, a
        );
    }

    benchmark::RegisterBenchmark("uniform01/rng:foam", uniformDraw<FoamUniform01>);
    benchmark::RegisterBenchmark("uniform01/rng:foam13", uniformDraw<Foam13Uniform01>);
    benchmark::RegisterBenchmark("uniform01/rng:mt19937", uniformDraw<Mt19937Uniform01>);

    const std::vector<std::pair<Sampler, std::string>> samplers{
        {Sampler::exact, "exact"},
        {Sampler::inversion, "inversion"},
        {Sampler::rejection, "rejection"},
        {Sampler::noShadow, "noShadow"}
    };
    const std::vector<std::pair<double, std::string>> hs{
        {0, "0"}, {1e-3, "1e-3"}, {1e-2, "1e-2"}, {1e-1, "1e-1"}, {1, "1"},
        {10, "10"}, {1e3, "1e3"}, {1e5, "1e5"}
    };
    for (const auto& [method, name] : samplers)
    {
        for (const auto& [h, hn] : hs)
        {
            if (method == Sampler::rejection && !(h > 0))
            {
                continue;   // acceptance probability 0: never terminates
            }
            benchmark::RegisterBenchmark
            (
                ("sampler/method:" + name + "/h:" + hn).c_str(),
                facetAngleSample, method, h
            );
        }
    }
}

} // namespace

int main(int argc, char** argv)
{
    registerAll();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
    {
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
