// roughWallInteraction benchmarks: the random sources of the benchmarks.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// FoamUniform01 reproduces what the OpenFOAM model draws from: OpenFOAM
// v1912's Foam::Random (src/OpenFOAM/primitives/random/Random) is the 48-bit
// linear congruential generator of lrand48 (a = 0x5DEECE66D, c = 0xB,
// m = 2^48, 31 output bits) fed to std::uniform_real_distribution<double>,
// which needs two engine calls per double; the model's cloudUniform01 then
// maps the (rare) rounding to 1 back below 1. Timing the core with it gives
// the cost the model pays inside OpenFOAM v1912 (less one out-of-line call).
// Foam13Uniform01 reproduces OpenFOAM-13's randomGenerator::scalar01(), the
// source of the model on OpenFOAM-13 (and -12). Mt19937Uniform01 is the
// core tests' source, for comparison.
#pragma once

#include <cstdint>
#include <random>

namespace roughWallBench
{

//- Same sequence as OpenFOAM v1912's Rand48
class Rand48
{
    std::linear_congruential_engine
    <
        std::uint64_t, 0x5DEECE66DULL, 0xBULL, (std::uint64_t(1) << 48)
    > engine_;

public:

    using result_type = std::uint32_t;

    explicit Rand48(std::uint32_t seed = 1)
    :
        engine_((static_cast<std::uint64_t>(seed) << 16) | 0x330e)
    {}

    static constexpr result_type min() { return 0; }
    static constexpr result_type max() { return 0x7FFFFFFF; }

    result_type operator()()
    {
        return static_cast<result_type>(engine_() >> 17);
    }
};

//- Random::sample01<scalar>() as the OpenFOAM model calls it
class FoamUniform01
{
    Rand48 generator_;
    std::uniform_real_distribution<double> uniform01_{0.0, 1.0};

public:

    explicit FoamUniform01(std::uint32_t seed = 1) : generator_(seed) {}

    double operator()()
    {
        const double u = uniform01_(generator_);
        return u < 1 ? u : 0.99999999999999989;
    }
};

//- randomGenerator::scalar01() of OpenFOAM-13 (and -12) as the OpenFOAM
//  model calls it: the same 48-bit LCG, its 31 high bits over 2^31 (inline
//  in OpenFOAM, no long double); seed as randomGenerator(seed) on one
//  processor
class Foam13Uniform01
{
    std::uint64_t x_;

public:

    explicit Foam13Uniform01(std::uint64_t seed = 1)
    :
        x_((seed << 16) + 0x330E)
    {}

    double operator()()
    {
        x_ = (0x5DEECE66DULL*x_ + 0xBULL) & ((std::uint64_t(1) << 48) - 1);
        const double u = double(x_ >> 17)/double(std::uint64_t(1) << 31);
        return u < 1 ? u : 0.99999999999999989;
    }
};

//- std::mt19937_64 through uniform_real_distribution (the core tests' source)
class Mt19937Uniform01
{
    std::mt19937_64 engine_;
    std::uniform_real_distribution<double> uniform01_{0.0, 1.0};

public:

    explicit Mt19937Uniform01(std::uint64_t seed = 1) : engine_(seed) {}

    double operator()() { return uniform01_(engine_); }
};

} // namespace roughWallBench
