// roughWallInteraction benchmarks: work-precision of the samplers of the
// collision-angle distribution P(gamma, alpha), eq. (1.3) (figure 1 of
// docs/benchmarks.md).
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// For each sampler, each h = alpha/Delta and each sample count N it draws N
// samples (timed with a steady clock, the samples stored in a vector), then
// measures the error of the sample against the exact distribution:
//   ks    Kolmogorov-Smirnov distance to CollisionAngleDistribution::cdf
//   bias  (sample mean - <gamma> of (1.4))/Delta
// over several independent replicates (mean KS, RMS bias, median time).
// An exact sampler's errors are statistical: E[ks] ~ 0.8687/sqrt(N),
// RMS bias = sd(gamma)/(Delta sqrt(N)) (printed as bias_expected); a wrong
// sampler levels off. Output: CSV on stdout.
//
// Usage: samplerWorkPrecision [--h 0,1e-3,...] [--samples 100,1000,...]
//        [--samplers exact,inversion,rejection,noShadow] [--seed 1]
//        [--budget seconds] [--target-samples n] [--max-replicates r]
//        [--min-replicates r] [--calibrate seconds]

#include "benchRandom.hh"
#include "referenceSamplers.hh"

#include "CollisionAngleDistribution.hpp"
#include "facetAngleSampler.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace roughWallBench;

namespace
{

constexpr double deg = roughWall::pi/180;

std::vector<std::string> split(const std::string& s)
{
    std::vector<std::string> parts;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ','))
    {
        parts.push_back(item);
    }
    return parts;
}

std::vector<double> numbers(const std::string& s)
{
    std::vector<double> values;
    for (const std::string& item : split(s))
    {
        values.push_back(std::stod(item));
    }
    return values;
}

struct Options
{
    std::vector<double> h{0, 1e-3, 1e-2, 1e-1, 1, 10, 1e3, 1e5};
    std::vector<double> samples{1e2, 1e3, 1e4, 1e5, 1e6};
    std::vector<std::string> samplers{"exact", "inversion", "rejection", "noShadow"};
    unsigned seed = 1;
    double budget = 30;          //!< max seconds of sampling per (sampler, h, N)
    double targetSamples = 4e6;  //!< replicates ~ targetSamples/N
    int maxReplicates = 64;
    int minReplicates = 4;
    double calibrate = 0.2;      //!< seconds of sampling to measure the cost
};

Options parse(int argc, char** argv)
{
    Options o;
    for (int i = 1; i < argc; ++i)
    {
        const std::string key = argv[i];
        if (i + 1 >= argc)
        {
            std::cerr << "missing value after " << key << '\n';
            std::exit(2);
        }
        const std::string value = argv[++i];
        if (key == "--h") o.h = numbers(value);
        else if (key == "--samples") o.samples = numbers(value);
        else if (key == "--samplers") o.samplers = split(value);
        else if (key == "--seed") o.seed = std::stoul(value);
        else if (key == "--budget") o.budget = std::stod(value);
        else if (key == "--target-samples") o.targetSamples = std::stod(value);
        else if (key == "--max-replicates") o.maxReplicates = std::stoi(value);
        else if (key == "--min-replicates") o.minReplicates = std::stoi(value);
        else if (key == "--calibrate") o.calibrate = std::stod(value);
        else
        {
            std::cerr << "unknown option " << key << '\n';
            std::exit(2);
        }
    }
    return o;
}

//- alpha and Delta for a given h: Delta = 8 deg while alpha <= 45 deg, then
//  alpha = 45 deg and Delta = alpha/h (the standardised distribution depends
//  on h only; this keeps both angles physical)
void anglesFor(double h, double& alpha, double& Delta)
{
    Delta = 8*deg;
    alpha = h*Delta;
    if (alpha > 45*deg)
    {
        alpha = 45*deg;
        Delta = alpha/h;
    }
}

//- Fill the vector with samples; returns the seconds it took
double draw
(
    const std::string& sampler,
    double alpha,
    double Delta,
    FoamUniform01& uniform01,
    std::vector<double>& out
)
{
    const auto start = std::chrono::steady_clock::now();
    // One branch on the sampler name per call of draw, not per sample
    if (sampler == "exact")
    {
        for (double& x : out) x = roughWall::sampleFacetAngle(alpha, Delta, uniform01);
    }
    else if (sampler == "inversion")
    {
        for (double& x : out) x = roughWall::sampleFacetAngleByInversion(alpha, Delta, uniform01);
    }
    else if (sampler == "rejection")
    {
        for (double& x : out) x = sampleFacetAngleByRejection(alpha, Delta, uniform01);
    }
    else
    {
        for (double& x : out) x = sampleFacetAngleWithoutShadow(alpha, Delta, uniform01);
    }
    const auto stop = std::chrono::steady_clock::now();
    return std::chrono::duration<double>(stop - start).count();
}

//- Kolmogorov-Smirnov distance of the (sorted in place) sample to P
double ksDistance
(
    std::vector<double>& x,
    const roughWall::CollisionAngleDistribution& P,
    double alpha
)
{
    std::sort(x.begin(), x.end());
    const double n = static_cast<double>(x.size());
    double D = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        const double F = P.cdf(x[i], alpha);
        D = std::max({D, F - i/n, (i + 1)/n - F});
    }
    return D;
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size()/2;
    return v.size() % 2 ? v[m] : 0.5*(v[m - 1] + v[m]);
}

} // namespace

int main(int argc, char** argv)
{
    const Options o = parse(argc, argv);

    std::printf
    (
        "sampler,h,alpha,Delta,N,replicates,seconds_median,seconds_min,"
        "ns_per_sample,ks_mean,ks_rms,bias_rms,bias_expected,status\n"
    );
    unsigned stream = 0;
    for (const std::string& sampler : o.samplers)
    {
        for (const double h : o.h)
        {
            double alpha, Delta;
            anglesFor(h, alpha, Delta);
            const roughWall::CollisionAngleDistribution P(Delta);
            const double mean = P.mean(alpha);
            const double sd = P.standardDeviation(alpha);

            if (sampler == "rejection" && !(h > 0))
            {
                for (const double Nd : o.samples)
                {
                    std::printf
                    (
                        "%s,%.6g,%.17g,%.17g,%.0f,0,nan,nan,inf,nan,nan,nan,nan,"
                        "nonterminating\n",
                        sampler.c_str(), h, alpha, Delta, Nd
                    );
                }
                continue;
            }

            // Cost per sample: batches of 1000 until `calibrate` seconds
            FoamUniform01 calibration(o.seed + 7919*(++stream));
            std::vector<double> batch(1000);
            double seconds = 0;
            long drawn = 0;
            while (seconds < o.calibrate)
            {
                seconds += draw(sampler, alpha, Delta, calibration, batch);
                drawn += batch.size();
            }
            const double nsPerSample = 1e9*seconds/drawn;

            for (const double Nd : o.samples)
            {
                const std::size_t N = static_cast<std::size_t>(Nd);
                int replicates = static_cast<int>
                (
                    std::clamp
                    (
                        o.targetSamples/Nd,
                        double(o.minReplicates),
                        double(o.maxReplicates)
                    )
                );
                const double perReplicate = 1e-9*nsPerSample*Nd;
                if (replicates*perReplicate > o.budget)
                {
                    replicates = std::max
                    (
                        o.minReplicates,
                        static_cast<int>(o.budget/perReplicate)
                    );
                }
                if (replicates*perReplicate > o.budget)
                {
                    std::printf
                    (
                        "%s,%.6g,%.17g,%.17g,%zu,0,nan,nan,%.6g,nan,nan,nan,nan,"
                        "budget\n",
                        sampler.c_str(), h, alpha, Delta, N, nsPerSample
                    );
                    continue;
                }

                std::vector<double> times, x(N);
                double ksSum = 0, ksSquares = 0, biasSquares = 0;
                for (int r = 0; r < replicates; ++r)
                {
                    FoamUniform01 uniform01(o.seed + 7919*(++stream));
                    times.push_back(draw(sampler, alpha, Delta, uniform01, x));
                    double sum = 0;
                    for (const double g : x) sum += g;
                    const double bias = (sum/Nd - mean)/Delta;
                    biasSquares += bias*bias;
                    const double ks = ksDistance(x, P, alpha);
                    ksSum += ks;
                    ksSquares += ks*ks;
                }
                std::printf
                (
                    "%s,%.6g,%.17g,%.17g,%zu,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,ok\n",
                    sampler.c_str(), h, alpha, Delta, N, replicates,
                    median(times), *std::min_element(times.begin(), times.end()),
                    nsPerSample, ksSum/replicates,
                    std::sqrt(ksSquares/replicates),
                    std::sqrt(biasSquares/replicates),
                    sd/(Delta*std::sqrt(Nd))
                );
                std::fflush(stdout);
            }
        }
    }
    return 0;
}
