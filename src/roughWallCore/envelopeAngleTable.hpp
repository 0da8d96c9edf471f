// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Delta(d) of a sampled wall profile (the rms tilt of the rolling-sphere
// envelope, rollingSphereEnvelope.hpp) tabulated once and interpolated per
// wall hit, for the OpenFOAM adapter's roughness { profile ...; } and
// roughness { Rq ...; RSm ...; }.
//
// Which diameters: the patch settings are read before any parcel exists and
// do not know the cloud's sizes (an injection model may draw them from a
// continuous distribution), so the table covers every diameter the profile
// can answer for, on a grid uniform in ln d:
//  - dMin = the profile's largest point spacing (a smaller sphere would
//    resolve the polyline between the samples, not the wall), or larger if
//    the caller says so (the adapter: RSm/10 for a synthetic profile, where
//    Delta has reached its small-sphere limit to 3e-4 deg);
//  - dMax = half the trace (trimmed: the statistics then still cover half of
//    it) or a tenth of the period (periodic), or less if the caller says so
//    (the adapter: 100 RSm for a synthetic profile).
// Outside [dMin, dMax] the angle is held at the end value (the caller warns).
// pointsPerDecade = 12 rows per decade: linear interpolation in ln d between
// rows h = ln(10)/12 = 0.19 apart errs by at most h^2/8 max|d^2 Delta/d(ln d)^2|
// (0.0046 times the curvature in ln d); largest where Delta bends from its
// small-sphere plateau, d ~ RSm. Checked at the midpoints of the rows (the
// worst place) against the envelope evaluated there, on a synthetic Gaussian
// profile and on a random trace: tests/core/testEnvelopeAngleTable.cc, at
// most 0.05 deg and 1 % of Delta.
// Cost: one envelope per row, O(N) each (rollingSphereEnvelope.hpp), about
// 12 log10(dMax/dMin) rows; per look-up a comparison when d is the diameter
// of the previous look-up (a monodisperse cloud), else a logarithm and two
// loads. No allocation after construction.
#pragma once

#include "rollingSphereEnvelope.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace roughWall
{

class EnvelopeAngleTable
{
public:

    //- Rows per decade of d
    static constexpr int pointsPerDecade = 12;

private:

    //- Smallest and largest tabulated diameter [m]
    double dMin_ = 0;
    double dMax_ = 0;

    //- ln(dMin)
    double lnMin_ = 0;

    //- Rows per unit of ln d
    double rowsPerLn_ = 0;

    //- Delta [rad] at d_k = dMin exp(k/rowsPerLn_), the last one at dMax
    std::vector<double> angle_;

    //- The last look-up (single-threaded use, as OpenFOAM's clouds)
    mutable double lastD_ = -1;
    mutable double lastAngle_ = 0;

public:

    EnvelopeAngleTable() = default;

    //- Tabulate Delta(d) of the profile on [dMin, dMax], narrowed to the
    //  profile's own limits [largestSpacing, maxDiameter] (0: those limits)
    explicit EnvelopeAngleTable
    (
        const SampledProfile& p,
        const double dMin = 0,
        const double dMax = 0
    )
    {
        checkProfile(p);
        dMin_ = std::max(dMin, largestSpacing(p));
        dMax_ = dMax > 0 ? std::min(dMax, maxDiameter(p)) : maxDiameter(p);
        if (!(dMax_ > dMin_))
        {
            throw std::invalid_argument
            (
                "profile: too short for its spacing (no diameter between "
                "the largest spacing and half the length)"
            );
        }
        lnMin_ = std::log(dMin_);
        const double decades = std::log10(dMax_/dMin_);
        const std::size_t rows =
            static_cast<std::size_t>(std::ceil(decades*pointsPerDecade)) + 1;
        rowsPerLn_ = (rows - 1)/std::log(dMax_/dMin_);
        angle_.resize(rows);
        for (std::size_t k = 0; k < rows; ++k)
        {
            const double d = k + 1 < rows ? dMin_*std::exp(k/rowsPerLn_) : dMax_;
            angle_[k] = tiltStatistics(p, d).rms;
        }
    }

    //- The largest diameter a profile is tabulated for: half the trace
    //  (trimmed), a tenth of the period (periodic)
    static double maxDiameter(const SampledProfile& p)
    {
        return p.ends == ProfileEnds::periodic
          ? 0.1*p.period : 0.5*(p.x.back() - p.x.front());
    }

    //- Delta [rad] for diameter d [m], interpolated linearly in ln d
    double interpolate(const double d) const
    {
        if (!(d > dMin_))
        {
            return angle_.front();
        }
        if (!(d < dMax_))
        {
            return angle_.back();
        }
        const double f = (std::log(d) - lnMin_)*rowsPerLn_;
        std::size_t k = static_cast<std::size_t>(f);
        if (k + 1 >= angle_.size())
        {
            k = angle_.size() - 2;
        }
        const double w = f - k;
        return angle_[k] + w*(angle_[k + 1] - angle_[k]);
    }

    //- Delta [rad] for diameter d [m]: the last look-up's if d is the same
    double angle(const double d) const
    {
        if (d != lastD_)
        {
            lastAngle_ = interpolate(d);
            lastD_ = d;
        }
        return lastAngle_;
    }

    //- Is d inside the tabulated range?
    bool covers(const double d) const
    {
        return d >= dMin_ && d <= dMax_;
    }

    double dMin() const { return dMin_; }
    double dMax() const { return dMax_; }
    std::size_t rows() const { return angle_.size(); }

    //- The largest tabulated Delta [rad]
    double maxAngle() const
    {
        double m = 0;
        for (const double a : angle_) m = std::max(m, a);
        return m;
    }
};

} // End namespace roughWall
