// Tallies of a stability sweep, by the value of each factor, written as a
// markdown table (copied into docs/stability.md).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "wallHitInvariants.hh"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace roughWallStability
{

//- What a group of cases did
struct Tally
{
    long cases = 0;          //!< calls checked (each also re-run for reproducibility)
    long intoWall = 0;       //!< of which moving into the wall
    long recollisions = 0;   //!< more than one facet collision
    long fallbacks = 0;      //!< bound reached: mean-wall rebound
    long failures = 0;       //!< invariant violations
    int maxCollisions = 0;
    long maxDraws = 0;
    double maxEnergyGain = -1;   //!< largest E1/E0 - 1 (negative: always lost)

    void add(const WallHitInput& in, const WallHitResult& out, bool failed)
    {
        ++cases;
        failures += failed;
        if (!(in.velocity.dot(in.wallNormal) < 0))
        {
            return;
        }
        ++intoWall;
        recollisions += out.report.facetCollisions > 1;
        fallbacks += out.report.fallback;
        maxCollisions = std::max(maxCollisions, out.report.facetCollisions);
        maxDraws = std::max(maxDraws, out.draws);
        maxEnergyGain = std::max(maxEnergyGain, energyGain(in, out));
    }
};

//- Tallies by factor and value of the factor
class SweepSummary
{
    std::vector<std::string> factors_;
    std::vector<std::vector<std::string>> values_;
    std::vector<std::vector<Tally>> tallies_;
    Tally total_;
    std::vector<std::string> failures_;

public:

    //- Declare a factor and the names of its values; returns its index
    int addFactor(const std::string& name, const std::vector<std::string>& values)
    {
        factors_.push_back(name);
        values_.push_back(values);
        tallies_.push_back(std::vector<Tally>(values.size()));
        return static_cast<int>(factors_.size()) - 1;
    }

    //- Check one case: invariants and reproducibility. level[i] is the value
    //  of factor i in this case (-1: the factor does not apply).
    template<class MakeSource>
    void check
    (
        const WallHitInput& in,
        MakeSource makeSource,
        const std::vector<int>& level,
        long drawLimit = drawsPerFacetLimit
    )
    {
        auto source = makeSource();
        const WallHitResult out = hitWall(in, source);
        std::string what = violation(in, out, drawLimit);
        if (what.empty())
        {
            auto again = makeSource();
            if (!sameResult(out, hitWall(in, again)))
            {
                what = "not reproducible from the seed";
            }
        }
        const bool failed = !what.empty();
        if (failed && failures_.size() < 20)
        {
            std::string where;
            for (std::size_t i = 0; i < level.size(); ++i)
            {
                if (level[i] >= 0) where += factors_[i] + "=" + values_[i][level[i]] + " ";
            }
            failures_.push_back(what + "\n    case: " + where + "\n    input: " + describe(in));
        }
        total_.add(in, out, failed);
        for (std::size_t i = 0; i < level.size(); ++i)
        {
            if (level[i] >= 0) tallies_[i][level[i]].add(in, out, failed);
        }
    }

    const Tally& total() const { return total_; }

    //- Markdown table, one row per factor value
    void write(const std::string& path, const std::string& title, double seconds) const
    {
        std::ofstream os(path);
        char buf[512];
        os << "### " << title << "\n\n";
        std::snprintf(buf, sizeof buf,
            "%ld cases (each run twice from its seed), %ld moving into the wall, "
            "%ld with re-collisions, %ld fallbacks, %ld failures; %.1f s.\n\n",
            total_.cases, total_.intoWall, total_.recollisions, total_.fallbacks,
            total_.failures, seconds);
        os << buf;
        os << "| factor | value | cases | into wall | re-collisions | fallbacks "
              "| max facet collisions | max draws | max E1/E0 - 1 | failures |\n"
              "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (std::size_t f = 0; f < factors_.size(); ++f)
        {
            for (std::size_t v = 0; v < values_[f].size(); ++v)
            {
                const Tally& t = tallies_[f][v];
                std::snprintf(buf, sizeof buf,
                    "| %s | %s | %ld | %ld | %ld | %ld | %d | %ld | %.1e | %ld |\n",
                    factors_[f].c_str(), values_[f][v].c_str(), t.cases, t.intoWall,
                    t.recollisions, t.fallbacks, t.maxCollisions, t.maxDraws,
                    t.maxEnergyGain, t.failures);
                os << buf;
            }
        }
    }

    //- GoogleTest verdict: every failure printed with its input
    void expectNoFailures() const
    {
        for (const auto& f : failures_)
        {
            ADD_FAILURE() << f;
        }
        EXPECT_EQ(total_.failures, 0) << "of " << total_.cases << " cases";
    }
};

//- Where a summary goes: the test's working directory (build/tests/stability)
inline std::string summaryPath(const std::string& name)
{
    return name + ".md";
}

} // namespace roughWallStability
