// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// The CSV tables the tool writes: one row per incidence angle, or one row per
// bin of a pdf. Undefined values (k_t, k_Omega at alpha = 90 deg) are empty
// fields. Numbers have `digits` significant digits (%.<digits>g); 17 prints
// every double exactly (strtod reads back the same double).
#pragma once

#include "coefficientDistribution.hh"
#include "statistics.hh"

#include <ostream>
#include <vector>

namespace roughWallStats
{

struct TableLayout
{
    bool monteCarlo = false;   //!< adds the se_* columns
    bool recollide = false;    //!< adds mean_facet_collisions, p_fallback
    int digits = 12;           //!< significant digits of the numbers (--digits, 1..17)
};

void writeStatisticsTable
(
    std::ostream& os,
    const std::vector<Statistics>& rows,
    const TableLayout& layout
);

//- One bin of a pdf table
struct PdfBin
{
    double lo = 0, hi = 0;
    double pdf = 0;        //!< change-of-variables density at the centre
    double pdfBin = 0;     //!< exact probability of the bin / width
    long long count = 0;   //!< Monte Carlo samples in the bin
};

void writePdfTable
(
    std::ostream& os,
    const std::vector<PdfBin>& bins,
    long long samples,
    bool withDensity,
    int digits = 12            //!< significant digits of the numbers (--digits, 1..17)
);

} // namespace roughWallStats
