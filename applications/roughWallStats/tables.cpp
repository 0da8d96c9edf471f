// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later

#include "tables.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace roughWallStats
{

namespace
{

std::string field(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.12g", value);
    return buffer;
}

//- A field that is empty where undefined
std::string field(double value, bool defined)
{
    return defined ? field(value) : std::string();
}

} // namespace

void writeStatisticsTable
(
    std::ostream& os,
    const std::vector<Statistics>& rows,
    const TableLayout& layout
)
{
    os << "alpha_deg,mean_kn,sd_kn,mean_abs_kn,mean_kt,sd_kt,mean_kOmega,sd_kOmega,"
          "p_noslip,p_wallward";
    if (layout.recollide)
    {
        os << ",mean_facet_collisions,p_fallback";
    }
    if (layout.monteCarlo)
    {
        os << ",samples,se_mean_kn,se_sd_kn,se_mean_abs_kn,se_mean_kt,se_sd_kt,"
              "se_mean_kOmega,se_sd_kOmega,se_p_noslip,se_p_wallward";
        if (layout.recollide)
        {
            os << ",se_mean_facet_collisions";
        }
    }
    os << '\n';

    for (const Statistics& s : rows)
    {
        const bool t = s.tangentialDefined;
        os << field(s.alphaDeg) << ',' << field(s.meanKn) << ',' << field(s.sdKn) << ','
           << field(s.meanAbsKn) << ',' << field(s.meanKt, t) << ',' << field(s.sdKt, t) << ','
           << field(s.meanKOmega, t) << ',' << field(s.sdKOmega, t) << ','
           << field(s.pNoSlip) << ',' << field(s.pWallward);
        if (layout.recollide)
        {
            os << ',' << field(s.meanFacetCollisions) << ',' << field(s.pFallback);
        }
        if (layout.monteCarlo)
        {
            os << ',' << s.samples << ',' << field(s.seMeanKn) << ',' << field(s.seSdKn) << ','
               << field(s.seMeanAbsKn) << ',' << field(s.seMeanKt, t) << ','
               << field(s.seSdKt, t) << ',' << field(s.seMeanKOmega, t) << ','
               << field(s.seSdKOmega, t) << ',' << field(s.sePNoSlip) << ','
               << field(s.sePWallward);
            if (layout.recollide)
            {
                os << ',' << field(s.seMeanFacetCollisions);
            }
        }
        os << '\n';
    }
}

void writePdfTable
(
    std::ostream& os,
    const std::vector<PdfBin>& bins,
    long long samples,
    bool withDensity
)
{
    os << "k_lo,k_hi,k";
    if (withDensity)
    {
        os << ",pdf,pdf_bin";
    }
    os << ",pdf_montecarlo,se_pdf_montecarlo,count\n";
    for (const PdfBin& b : bins)
    {
        const double width = b.hi - b.lo;
        const double scale = 1/(static_cast<double>(samples)*width);
        os << field(b.lo) << ',' << field(b.hi) << ',' << field(0.5*(b.lo + b.hi));
        if (withDensity)
        {
            os << ',' << field(b.pdf) << ',' << field(b.pdfBin);
        }
        os << ',' << field(b.count*scale) << ','
           << field(std::sqrt(static_cast<double>(b.count))*scale) << ',' << b.count << '\n';
    }
}

} // namespace roughWallStats
