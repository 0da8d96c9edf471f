// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later

#include "tables.hh"

#include <cmath>
#include <cstdio>
#include <string>

namespace roughWallStats
{

namespace
{

std::string field(double value, int digits)
{
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    return buffer;
}

//- A field that is empty where undefined
std::string field(double value, int digits, bool defined)
{
    return defined ? field(value, digits) : std::string();
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

    const int d = layout.digits;
    for (const Statistics& s : rows)
    {
        const bool t = s.tangentialDefined;
        os << field(s.alphaDeg, d) << ',' << field(s.meanKn, d) << ',' << field(s.sdKn, d)
           << ',' << field(s.meanAbsKn, d) << ',' << field(s.meanKt, d, t) << ','
           << field(s.sdKt, d, t) << ',' << field(s.meanKOmega, d, t) << ','
           << field(s.sdKOmega, d, t) << ',' << field(s.pNoSlip, d) << ','
           << field(s.pWallward, d);
        if (layout.recollide)
        {
            os << ',' << field(s.meanFacetCollisions, d) << ',' << field(s.pFallback, d);
        }
        if (layout.monteCarlo)
        {
            os << ',' << s.samples << ',' << field(s.seMeanKn, d) << ','
               << field(s.seSdKn, d) << ',' << field(s.seMeanAbsKn, d) << ','
               << field(s.seMeanKt, d, t) << ',' << field(s.seSdKt, d, t) << ','
               << field(s.seMeanKOmega, d, t) << ',' << field(s.seSdKOmega, d, t) << ','
               << field(s.sePNoSlip, d) << ',' << field(s.sePWallward, d);
            if (layout.recollide)
            {
                os << ',' << field(s.seMeanFacetCollisions, d);
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
    bool withDensity,
    int d
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
        os << field(b.lo, d) << ',' << field(b.hi, d) << ',' << field(0.5*(b.lo + b.hi), d);
        if (withDensity)
        {
            os << ',' << field(b.pdf, d) << ',' << field(b.pdfBin, d);
        }
        os << ',' << field(b.count*scale, d) << ','
           << field(std::sqrt(static_cast<double>(b.count))*scale, d) << ',' << b.count << '\n';
    }
}

} // namespace roughWallStats
