// Reference rebound statistics of one wall hit on a flat rough wall, by Monte
// Carlo with the framework-free core (the same operator the OpenFOAM adapter
// calls, but with its own random stream): the oracle of the OpenFOAM
// wall-impact tests.
//
// A particle arrives with velocity (cos alpha, -sin alpha, 0) and no spin on
// the wall y = 0 (normal (0 1 0) into the fluid), 3-D, no lateral tilt unless
// asked. For each sample, k_n = v''_y/sin(alpha), k_t = v''_x/cos(alpha).
//
// Usage:
//   roughWallReference --spin 0|1 --e E --mu0 M0 --muD MD --Delta DEG
//       --alpha DEG[,DEG...] [--lateralTilt 0|1] [--maxFacetCollisions N]
//       [--samples N] [--seed S]
// Prints CSV, one line per alpha:
//   alpha_deg,Delta_deg,samples,mean_kn,se_mean_kn,sd_kn,se_sd_kn,
//   mean_kt,se_mean_kt,sd_kt,se_sd_kt
// Standard errors: sd/sqrt(N) for the mean, sqrt((m4 - s^4)/N)/(2 s) for
// the standard deviation (delta method, any distribution).
//
// SPDX-License-Identifier: GPL-3.0-or-later

#include "roughWallCollision.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{

constexpr double pi = 3.14159265358979323846;

//- Sample moments of one quantity, with standard errors
struct Moments
{
    double mean = 0;
    double seMean = 0;
    double sd = 0;
    double seSd = 0;
};

Moments moments(const std::vector<double>& x)
{
    const double n = static_cast<double>(x.size());
    double sum = 0;
    for (const double xi : x)
    {
        sum += xi;
    }
    Moments m;
    m.mean = sum/n;
    double m2 = 0;
    double m4 = 0;
    for (const double xi : x)
    {
        const double d2 = (xi - m.mean)*(xi - m.mean);
        m2 += d2;
        m4 += d2*d2;
    }
    m2 /= n;
    m4 /= n;
    m.sd = std::sqrt(m2*n/(n - 1));
    m.seMean = m.sd/std::sqrt(n);
    m.seSd = std::sqrt(std::max(m4 - m2*m2, 0.0)/n)/(2*std::sqrt(m2));
    return m;
}

//- The core's uniform01() from a 64-bit Mersenne twister, in [0, 1)
struct Uniform01
{
    std::mt19937_64 engine;
    double operator()()
    {
        // 53 random bits: exactly representable, never 1
        return static_cast<double>(engine() >> 11)*0x1.0p-53;
    }
};

std::vector<double> parseList(const std::string& text)
{
    std::vector<double> values;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ','))
    {
        values.push_back(std::stod(item));
    }
    return values;
}

template<bool withSpin>
void sample
(
    const double alphaDeg,
    const roughWall::RoughWallParameters& p,
    const long samples,
    Uniform01& uniform01,
    std::vector<double>& kn,
    std::vector<double>& kt
)
{
    const double alpha = alphaDeg*pi/180;
    const roughWall::Vec3 normal(0, 1, 0);
    kn.resize(samples);
    kt.resize(samples);
    for (long i = 0; i < samples; ++i)
    {
        roughWall::Vec3 v(std::cos(alpha), -std::sin(alpha), 0);
        roughWall::Vec3 w(roughWall::Vec3::Zero());
        roughWall::collideWithRoughWall<withSpin>
        (
            v, w, normal, 50e-6, p, uniform01
        );
        kn[i] = v.y()/std::sin(alpha);
        kt[i] = v.x()/std::cos(alpha);
    }
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    std::map<std::string, std::string> args
    {
        {"--spin", "1"}, {"--e", "0.8"}, {"--mu0", "0.4"}, {"--muD", ""},
        {"--Delta", "8"}, {"--alpha", "10,30,60"}, {"--lateralTilt", "0"},
        {"--maxFacetCollisions", "10"}, {"--samples", "1000000"},
        {"--seed", "1"}
    };

    for (int i = 1; i < argc; ++i)
    {
        const std::string key(argv[i]);
        if (!args.count(key) || i + 1 == argc)
        {
            std::fprintf(stderr, "roughWallReference: bad argument %s\n", argv[i]);
            return 2;
        }
        args[key] = argv[++i];
    }

    try
    {
        roughWall::RoughWallParameters p;
        p.material.e = std::stod(args["--e"]);
        p.material.mu0 = std::stod(args["--mu0"]);
        p.material.muD =
            args["--muD"].empty() ? p.material.mu0 : std::stod(args["--muD"]);
        p.roughnessAngle = std::stod(args["--Delta"])*pi/180;
        p.lateralTilt = std::stoi(args["--lateralTilt"]) != 0;
        p.maxFacetCollisions = std::stoi(args["--maxFacetCollisions"]);
        const bool withSpin = std::stoi(args["--spin"]) != 0;
        const long samples = std::stol(args["--samples"]);

        Uniform01 uniform01{std::mt19937_64(std::stoull(args["--seed"]))};

        std::printf
        (
            "alpha_deg,Delta_deg,samples,mean_kn,se_mean_kn,sd_kn,se_sd_kn,"
            "mean_kt,se_mean_kt,sd_kt,se_sd_kt\n"
        );

        for (const double alphaDeg : parseList(args["--alpha"]))
        {
            std::vector<double> kn;
            std::vector<double> kt;
            if (withSpin)
            {
                sample<true>(alphaDeg, p, samples, uniform01, kn, kt);
            }
            else
            {
                sample<false>(alphaDeg, p, samples, uniform01, kn, kt);
            }
            const Moments n = moments(kn);
            const Moments t = moments(kt);
            std::printf
            (
                "%g,%s,%ld,%.10g,%.4g,%.10g,%.4g,%.10g,%.4g,%.10g,%.4g\n",
                alphaDeg, args["--Delta"].c_str(), samples,
                n.mean, n.seMean, n.sd, n.seSd,
                t.mean, t.seMean, t.sd, t.seSd
            );
        }
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "roughWallReference: %s\n", e.what());
        return 2;
    }

    return 0;
}
