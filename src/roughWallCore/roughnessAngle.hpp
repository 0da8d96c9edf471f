// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Delta(d_p), the roughness angle that a particle of diameter d_p sees, in the
// four forms a patch can give it (docs/roughWallInteraction.md, "Three ways to
// give a rough wall"):
//   constant     roughnessAngle 8;
//   table        roughnessAngle ((110e-6 8) (460e-6 5)); linear in d_p between
//                the rows, held at the end rows beyond them (the paper's
//                comparison uses a smaller Delta for larger beads: they bridge
//                the small asperities)
//   closedForm   roughness { Ra ...; RSm ...; estimate closedForm; }:
//                equation (1), profileRoughness.hpp
//   envelope     roughness { profile "<file>"; } or the profile parameters:
//                the rolling-sphere envelope, tabulated (envelopeAngleTable.hpp)
// One object per patch, asked once per wall hit. The checks and the
// construction of every form are here as well (roughnessOfRows,
// roughnessOfTrace, roughnessOfParameters, which throw BadRoughness naming
// the keyword, what is allowed and what is wrong): the adapter only reads
// the numbers and words the message.
#pragma once

#include "envelopeAngleTable.hpp"
#include "profileFile.hpp"
#include "profileRoughness.hpp"
#include "rollingSphereEnvelope.hpp"
#include "limitsAndUnits.hpp"

#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace roughWall
{

class RoughnessAngle
{
public:

    //- How Delta(d_p) was given
    enum class Form { constant, table, closedForm, envelope };

    //- A table row: diameter d [m], Delta [deg] (as the user writes it)
    using Row = std::pair<double, double>;

private:

    Form form_ = Form::constant;

    //- constant: one row; table: the rows, d strictly increasing [m, rad]
    std::vector<double> d_{0}, angle_{0};

    //- closedForm: equation (1)
    RoughnessCorrelation correlation_;

    //- envelope: the tabulated envelope and what it is the envelope of
    EnvelopeAngleTable envelope_;
    std::string source_;

    //- table: linear in d between the rows, the end rows beyond them
    double tableAngle(const double d) const
    {
        const std::size_t n = d_.size();
        if (!(d > d_.front())) return angle_.front();
        if (d >= d_.back()) return angle_.back();

        // Bisection for d_[lo] <= d < d_[hi], hi = lo + 1
        std::size_t lo = 0, hi = n - 1;
        while (hi - lo > 1)
        {
            const std::size_t mid = (lo + hi)/2;
            (d_[mid] <= d ? lo : hi) = mid;
        }
        const double f = (d - d_[lo])/(d_[hi] - d_[lo]);
        return angle_[lo] + f*(angle_[hi] - angle_[lo]);
    }

public:

    //- Delta = 0: a smooth wall
    RoughnessAngle() = default;

    //- The index of the first row of a table that is not allowed (d >= 0
    //  strictly increasing, Delta in [0, maxRoughnessAngleDeg]; NaN fails),
    //  or -1 if every row is
    static long firstBadRow(const std::vector<Row>& rows)
    {
        for (std::size_t i = 0; i < rows.size(); ++i)
        {
            const double d = rows[i].first, deg = rows[i].second;
            if
            (
                !(d >= 0 && deg >= 0 && deg <= limits::maxRoughnessAngleDeg)
             || (i > 0 && !(d > rows[i - 1].first))
            )
            {
                return long(i);
            }
        }
        return -1;
    }

    //- From rows that firstBadRow accepts (at least one); one row is the
    //  constant Delta of that row
    static RoughnessAngle table(const std::vector<Row>& rows)
    {
        RoughnessAngle r;
        r.form_ = rows.size() > 1 ? Form::table : Form::constant;
        r.d_.clear();
        r.angle_.clear();
        for (const Row& row : rows)
        {
            r.d_.push_back(row.first);
            r.angle_.push_back(limits::degToRad(row.second));
        }
        return r;
    }

    //- Equation (1) of the profile parameters
    static RoughnessAngle closedForm(const ProfileRoughness& p)
    {
        RoughnessAngle r;
        r.form_ = Form::closedForm;
        r.correlation_ = RoughnessCorrelation(p);
        r.angle_ = {r.correlation_.angleUncached(0)};
        return r;
    }

    //- The envelope table of the profile that source describes
    static RoughnessAngle envelope(EnvelopeAngleTable t, std::string source)
    {
        RoughnessAngle r;
        r.form_ = Form::envelope;
        r.envelope_ = std::move(t);
        r.source_ = std::move(source);
        return r;
    }

    Form form() const { return form_; }

    //- Delta [rad] for a particle of diameter d [m]
    double operator()(const double d) const
    {
        switch (form_)
        {
            case Form::constant: return angle_.front();
            case Form::table: return tableAngle(d);
            case Form::closedForm: return correlation_.angle(d);
            case Form::envelope: return envelope_.angle(d);
        }
        return 0;
    }

    //- Is d inside the diameters Delta is known for? (false only outside
    //  an envelope's tabulated range, where Delta is held at its end value)
    bool covers(const double d) const
    {
        return form_ != Form::envelope || envelope_.covers(d);
    }

    const EnvelopeAngleTable& envelopeTable() const { return envelope_; }

    //- envelope: what the table is the envelope of
    const std::string& source() const { return source_; }

    //- Delta as text, for the log's summary of a patch
    std::string describe() const
    {
        std::ostringstream os;
        const auto deg = [](const double rad) { return limits::radToDeg(rad); };
        switch (form_)
        {
            case Form::constant:
                os << deg(angle_.front()) << " deg";
                break;
            case Form::table:
                os  << "table of " << d_.size() << " rows, "
                    << deg(angle_.front()) << " deg at d = " << d_.front()
                    << " m to " << deg(angle_.back()) << " deg at d = "
                    << d_.back() << " m";
                break;
            case Form::closedForm:
                os  << "atan(2 pi Rq/max(RSm, d)) with Rq = "
                    << correlation_.rmsHeight() << " m, RSm = "
                    << correlation_.regimeChangeDiameter() << " m: "
                    << deg(angle_.front()) << " deg for d <= RSm";
                break;
            case Form::envelope:
                os  << "envelope of the " << source_ << ": "
                    << deg(envelope_.interpolate(envelope_.dMin()))
                    << " deg at d = " << envelope_.dMin() << " m to "
                    << deg(envelope_.interpolate(envelope_.dMax()))
                    << " deg at d = " << envelope_.dMax() << " m";
                break;
        }
        return os.str();
    }
};

//- The synthetic Gaussian profile of a wall given by its parameters (0: not
//  given): its rms height is the one the flank-slope check bounds
//  (ProfileRoughness::rmsHeight: Rq, else of a Gaussian profile of that Ra,
//  exact, else of that Rz over sampling lengths of 5 RSm)
inline SyntheticProfileSettings gaussianProfileOf(const ProfileRoughness& p)
{
    SyntheticProfileSettings s;
    s.Rq = p.rmsHeight();
    s.RSm = p.RSm;
    return s;
}

//- A bad roughness input: the keyword, what is allowed there and what is
//  wrong (what(); empty if only the value given is)
struct BadRoughness : std::invalid_argument
{
    std::string keyword, allowed;

    BadRoughness(std::string k, std::string a, const std::string& wrong = "")
    :
        std::invalid_argument(wrong), keyword(std::move(k)),
        allowed(std::move(a))
    {}
};

//- A number as text, as the messages write it
inline std::string numberText(const double x)
{
    std::ostringstream os;
    os << x;
    return os.str();
}

//- What roughnessAngle must be, for the messages
inline std::string roughnessAngleAllowed()
{
    const std::string max = numberText(limits::maxRoughnessAngleDeg);
    return
        "a number in [0, " + max + "] or a table ((d1 Delta1) (d2 Delta2) "
        "...) with Delta in [0, " + max + "] and d >= 0 strictly increasing";
}

//- roughnessAngle: a constant (one row, d = 0) or a table of rows (d [m],
//  Delta [deg]); throws BadRoughness naming the first bad row of a table
inline RoughnessAngle roughnessOfRows
(
    const std::vector<RoughnessAngle::Row>& rows
)
{
    const long bad = RoughnessAngle::firstBadRow(rows);
    if (bad >= 0)
    {
        throw BadRoughness
        (
            "roughnessAngle", roughnessAngleAllowed(),
            rows.size() > 1 ? "row " + std::to_string(bad + 1) : ""
        );
    }
    return RoughnessAngle::table(rows);
}

//- Delta(d_p) of the rolling-sphere envelope of the profile that source
//  describes, tabulated on [dMin, dMax] as EnvelopeAngleTable's; keyword
//  names the input in the errors (a profile too short, Delta above the
//  model's limit)
inline RoughnessAngle roughnessOfProfile
(
    const SampledProfile& profile,
    const std::string& source,
    const double dMin,
    const double dMax,
    const std::string& keyword
)
{
    EnvelopeAngleTable envelope;
    try
    {
        envelope = EnvelopeAngleTable(profile, dMin, dMax);
    }
    catch (const std::exception& err)
    {
        throw BadRoughness
        (
            keyword, "a profile longer than twice its largest point spacing",
            source + ": " + err.what()
        );
    }
    const double maxFound = limits::radToDeg(envelope.maxAngle());
    if (maxFound > limits::maxRoughnessAngleDeg)
    {
        throw BadRoughness
        (
            keyword,
            "a profile whose Delta(d_p) is at most "
          + numberText(limits::maxRoughnessAngleDeg) + " deg (the model's "
            "limit)",
            source + ": Delta up to " + numberText(maxFound) + " deg"
        );
    }
    return RoughnessAngle::envelope(envelope, source);
}

//- What a profile file must be, for the messages
inline std::string profileFileAllowed()
{
    return
        "a readable trace of at least " + std::to_string(minProfilePoints)
      + " points, lines 'x z' with finite numbers, x strictly increasing "
        "(docs/roughWallInteraction.md)";
}

//- roughness { profile "<file>"; }: Delta(d_p) of the envelope of the
//  levelled trace in the file (profileFile.hpp's format)
inline RoughnessAngle roughnessOfTrace(const std::string& file)
{
    SampledProfile trace;
    try
    {
        trace = levelledProfile(readProfileFile(file));
    }
    catch (const std::exception& err)
    {
        throw BadRoughness("profile", profileFileAllowed(), err.what());
    }
    return roughnessOfProfile
    (
        trace,
        "profile " + file + " (" + std::to_string(trace.x.size())
      + " points, levelled)",
        0, 0, "profile"
    );
}

//- roughness { Ra ...; Rq ...; Rz ...; RSm ...; estimate ...; }: Delta(d_p)
//  of the parameters (given*: whether each height was given), the envelope
//  of their synthetic Gaussian profile, tabulated from RSm/10 (where Delta
//  is at its small-sphere limit, to 3e-4 deg) to 100 RSm (where it has
//  fallen to a tenth of it), or equation (1) if closedForm
inline RoughnessAngle roughnessOfParameters
(
    const ProfileRoughness& p,
    const bool givenRa,
    const bool givenRq,
    const bool givenRz,
    const bool closedForm
)
{
    const ProfileRoughnessError error =
        checkProfileRoughness(p, givenRa, givenRq, givenRz);
    if (!error.keyword.empty())
    {
        throw BadRoughness(error.keyword, error.allowed);
    }
    if (closedForm)
    {
        return RoughnessAngle::closedForm(p);
    }
    const SyntheticProfileSettings s = gaussianProfileOf(p);
    const SampledProfile profile = syntheticGaussianProfile(s);
    return roughnessOfProfile
    (
        profile,
        "synthetic Gaussian profile, Rq = " + numberText(s.Rq) + " m, RSm = "
      + numberText(s.RSm) + " m (" + std::to_string(profile.x.size())
      + " points, seed " + std::to_string(s.seed) + ")",
        s.RSm/10, 100*s.RSm, givenRq ? "Rq" : givenRa ? "Ra" : "Rz"
    );
}

} // End namespace roughWall
