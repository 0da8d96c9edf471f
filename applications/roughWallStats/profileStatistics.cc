// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later

#include "profileStatistics.hh"
#include "profileFile.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace roughWallStats
{

EnvelopeResult envelopeStatistics(const EnvelopeSettings& s)
{
    EnvelopeResult result;
    roughWall::SampledProfile profile;
    std::ostringstream d;
    d.precision(6);
    if (!s.profileFile.empty())
    {
        profile = roughWall::levelledProfile(roughWall::readProfileFile(s.profileFile));
        const roughWall::ProfileParameters q = roughWall::profileParameters(profile);
        result.Rq = q.Rq;
        // Fewer than two up-crossings (a flat or monotone trace, or less
        // than one element): no spacing, so no RSm and no estimate
        result.RSm = q.RSm > 0 ? q.RSm : std::nan("");
        d << "profile " << s.profileFile << ": " << profile.x.size() << " points over "
          << q.length << " m, levelled by its least-squares line; Rq = " << q.Rq
          << " m, RSm = " << q.RSm << " m (" << q.upCrossings
          << " zero up-crossings" << (q.RSm > 0 ? "" : ": no RSm, d/RSm and the "
                                      "closed form are nan") << "); statistics where the sphere lies wholly over the trace";
    }
    else
    {
        roughWall::SyntheticProfileSettings set;
        set.Rq = s.Rq;
        set.RSm = s.RSm;
        set.lengthPerRSm = s.lengthPerRSm;
        set.seed = s.seed;
        profile = roughWall::syntheticGaussianProfile(set);
        result.Rq = s.Rq;
        result.RSm = s.RSm;
        d << "synthetic Gaussian profile: Rq = " << s.Rq << " m, RSm = " << s.RSm
          << " m (Gaussian autocorrelation, Rice width), periodic, length "
          << profile.period << " m = " << s.lengthPerRSm << " RSm, " << profile.x.size()
          << " points, seed " << s.seed;
    }
    result.description = d.str();
    const double twoPiRq = 2*roughWall::pi*result.Rq;
    for (const double dp : s.diameters)
    {
        EnvelopeRow row;
        row.tilt = roughWall::tiltStatistics(profile, dp);
        row.closedForm = std::isnan(result.RSm) ? result.RSm
                       : std::atan(twoPiRq/std::max(result.RSm, dp));
        result.rows.push_back(row);
    }
    return result;
}


void writeEnvelopeTable(std::ostream& os, const EnvelopeResult& r, const int digits)
{
    const double deg = 180/roughWall::pi;
    const auto num = [digits](double x)
    {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
        return std::string(buffer);
    };
    os << "d_m,d_over_RSm,Delta_deg,mean_deg,sd_deg,skewness,excess_kurtosis,"
          "closed_form_deg,length_m,points\n";
    for (const EnvelopeRow& row : r.rows)
    {
        const roughWall::TiltStatistics& t = row.tilt;
        os << num(t.diameter) << ',' << num(t.diameter/r.RSm) << ',' << num(t.rms*deg)
           << ',' << num(t.mean*deg) << ',' << num(t.sd*deg) << ','
           << num(t.skewness) << ',' << num(t.excessKurtosis) << ','
           << num(row.closedForm*deg) << ',' << num(t.length) << ',' << t.points << '\n';
    }
}

} // namespace roughWallStats
