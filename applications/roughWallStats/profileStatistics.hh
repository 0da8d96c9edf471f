// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Delta(d_p) from the wall's profile (roughWallStats --profile FILE or
// --Rq/--Ra/--Rz with --RSm, and --d LIST): the rolling-sphere envelope of
// the measured trace (levelled by its least-squares line) or of the
// synthetic Gaussian profile with that Rq and Rice width RSm
// (rollingSphereEnvelope.hpp), one row per diameter with the tilt's shape
// statistics and the closed-form estimate atan(2 pi Rq / max(RSm, d)).
#pragma once

#include "rollingSphereEnvelope.hpp"

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace roughWallStats
{

struct EnvelopeSettings
{
    std::string profileFile;        //!< measured trace; empty: synthetic
    double Rq = 0, RSm = 0;         //!< synthetic: rms height, Rice width [m]
    std::vector<double> diameters;  //!< [m]
    double lengthPerRSm = 5000;     //!< synthetic profile length / RSm
    std::uint64_t seed = 1;         //!< synthetic profile seed
};

struct EnvelopeRow
{
    roughWall::TiltStatistics tilt;
    double closedForm = 0;          //!< atan(2 pi Rq / max(RSm, d)) [rad]
};

struct EnvelopeResult
{
    std::string description;        //!< the profile, for stderr
    double Rq = 0, RSm = 0;         //!< of the profile used [m]
    std::vector<EnvelopeRow> rows;
};

//- Read or make the profile and compute the rows; throws
//  roughWall::ProfileFileError or std::invalid_argument
EnvelopeResult envelopeStatistics(const EnvelopeSettings& s);

void writeEnvelopeTable(std::ostream& os, const EnvelopeResult& r, int digits);

} // namespace roughWallStats
