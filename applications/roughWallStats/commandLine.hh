// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Command-line options of roughWallStats, validated: every bad input is a
// UsageError naming the option and its allowed range (exit code 2).
#pragma once

#include "model.hh"
#include "profileStatistics.hh"
#include "monteCarloStatistics.hh"
#include "quadratureStatistics.hh"

#include <stdexcept>
#include <string>
#include <vector>

namespace roughWallStats
{

struct UsageError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

enum class Method { quadrature, montecarlo };

struct Options
{
    Model model;                  //!< Delta in radians
    double DeltaDeg = 8;
    std::vector<double> alphaDeg{1, 2, 5, 10, 15, 30, 45, 89};

    Method method = Method::quadrature;
    QuadratureSettings quadrature;
    MonteCarloSettings monteCarlo;

    bool pdf = false;
    Coefficient pdfOf = Coefficient::kn;
    int bins = 50;
    bool rangeGiven = false;
    double rangeLo = 0, rangeHi = 0;

    std::string plotFile;
    std::string outputFile;
    int digits = 12;              //!< significant digits of the numbers in the CSV
    int threads = 0;              //!< 0: one per core
    bool help = false;

    bool envelope = false;        //!< --d: the Delta(d) table of the wall's profile
    EnvelopeSettings envelopeSettings;
    std::string plotLabel;        //!< --plot label of the Delta(d) figure

    std::vector<std::string> notes;   //!< remarks for stderr (options that do nothing)
};

//- Parse and validate; throws UsageError
Options parseCommandLine(int argc, const char* const argv[]);

std::string usage();

} // namespace roughWallStats
