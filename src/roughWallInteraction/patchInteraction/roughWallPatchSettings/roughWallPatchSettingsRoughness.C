/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | roughWallInteraction: rough-wall particle
   \\    /   O peration     | collisions for OpenFOAM's Lagrangian clouds
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
    Copyright (C) 2026 The roughWallInteraction authors
-------------------------------------------------------------------------------
License
    This file is part of roughWallInteraction.

    roughWallInteraction is free software: you can redistribute it and/or
    modify it under the terms of the GNU General Public License as published
    by the Free Software Foundation, either version 3 of the License, or
    (at your option) any later version.

    roughWallInteraction is distributed in the hope that it will be useful,
    but WITHOUT ANY WARRANTY; without even the implied warranty of
    MERCHANTABILITY or FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General
    Public License for more details.

    You should have received a copy of the GNU General Public License along
    with roughWallInteraction.  If not, see <http://www.gnu.org/licenses/>.

    SPDX-License-Identifier: GPL-3.0-or-later

\*---------------------------------------------------------------------------*/

#include "roughWallPatchSettings.H"
#include "roughWallInput.H"
#include "OSspecific.H"
#include "Tuple2.H"

#include <ctime>

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

namespace
{

//- How Delta(d_p) follows from the profile parameters (keyword estimate)
enum class estimate { envelope, closedForm };

}

ROUGHWALL_NAMED_ENUM(estimateNames, estimate, 2, "envelope", "closedForm");


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The profile parameters (ISO 4287, SI units): keywords and places
using P = roughWall::ProfileRoughness;
const char* const parameterNames[4] = {"Ra", "Rq", "Rz", "RSm"};
double P::* const parameters[4] = {&P::Ra, &P::Rq, &P::Rz, &P::RSm};


//- make(), the core's construction of Delta(d_p), with its errors as a
//- FatalIOError of dict naming the keyword, what is allowed and what was
//- found; the tabulation of an envelope logged with its CPU time
template<class Make>
roughWall::RoughnessAngle made(const dictionary& dict, const Make& make)
{
    const std::clock_t start = std::clock();
    try
    {
        const roughWall::RoughnessAngle r(make());
        const roughWall::EnvelopeAngleTable& envelope = r.envelopeTable();
        if (r.form() == roughWall::RoughnessAngle::Form::envelope)
        {
            Info<< "    " << dict.name().c_str() << ": Delta(d_p) of the "
                << "rolling-sphere envelope of the " << r.source().c_str()
                << " tabulated at " << label(envelope.rows())
                << " diameters from " << envelope.dMin() << " to "
                << envelope.dMax() << " m in "
                << scalar(std::clock() - start)/CLOCKS_PER_SEC << " s CPU"
                << endl;
        }
        return r;
    }
    catch (const roughWall::BadRoughness& err)
    {
        roughWallInput::fatalBadEntry
        (
            dict, err.keyword, err.allowed, err.what()
        );
    }
}


//- roughnessAngle: a constant or a List<Tuple2> table [deg]
roughWall::RoughnessAngle readAngle(const dictionary& dict)
{
    const entry& e = *roughWallCompat::findLiteral(dict, "roughnessAngle");

    // A number (one row, at any diameter), or a table (d Delta) read by
    // OpenFOAM's List<Tuple2>
    List<Tuple2<scalar, scalar>> table(1, Tuple2<scalar, scalar>(0, 0));
    scalar& angle = table[0].second();
    if (!roughWallInput::readWhole(e, [&]() { e.stream() >> angle; }).empty())
    {
        table = roughWallInput::read<List<Tuple2<scalar, scalar>>>
        (
            dict, "roughnessAngle", roughWall::roughnessAngleAllowed()
        );
    }
    std::vector<roughWall::RoughnessAngle::Row> rows;
    for (const Tuple2<scalar, scalar>& row : table)
    {
        rows.emplace_back(row.first(), row.second());
    }
    return made(dict, [&]() { return roughWall::roughnessOfRows(rows); });
}


//- roughness: a profile file, or the profile parameters (envelope of the
//- synthetic Gaussian profile, or the closed-form estimate)
roughWall::RoughnessAngle readProfile(const dictionary& dict)
{
    const entry& e = *roughWallCompat::findLiteral(dict, "roughness");
    if (!e.isDict())
    {
        roughWallInput::fatalBadEntry
        (
            dict, "roughness",
            "a dictionary { profile \"<file>\"; } or { Ra ...; RSm ...; }"
        );
    }

    // Named after the patch entry, so that the messages point at it (a
    // sub-dictionary of an entry read from a stream loses that name).  A
    // measured trace is the wall itself: nothing else beside it
    dictionary rDict(e.dict());
    rDict.name() =
        fileName(dict.name() + roughWallCompat::scopeSeparator + "roughness");
    const bool trace = roughWallCompat::findLiteral(rDict, "profile");
    roughWallInput::checkKeywords
    (
        rDict,
        trace ? wordList{"profile"}
      : wordList{"profile", "Ra", "Rq", "Rz", "RSm", "estimate"},
        trace ? "roughness with a profile (nothing beside it)" : "roughness"
    );

    if (trace)
    {
        // OpenFOAM's expansion of $VAR stops at an unset variable with a
        // message that names neither the keyword nor the file: caught
        fileName path = roughWallInput::read<fileName>
        (
            rDict, "profile", roughWall::profileFileAllowed(), std::nullopt,
            [](Istream& is) { fileName f; is >> f; f.expand(); return f; }
        );
        if (!path.isAbsolute())
        {
            path = fileName(getEnv("FOAM_CASE"))/path;
        }
        return made(rDict, [&]() { return roughWall::roughnessOfTrace(path); });
    }

    // The parameters, of any sign (the core checks them) but NaN
    roughWall::ProfileRoughness p;
    bool given[4];
    for (label i = 0; i < 4; ++i)
    {
        given[i] = roughWallCompat::findLiteral(rDict, parameterNames[i]);
        p.*parameters[i] = roughWallInput::readNumber<scalar>
        (
            rDict, parameterNames[i], {-GREAT, GREAT}, scalar(0)
        );
    }
    const bool closedForm = roughWallInput::readEnum
    (
        rDict, "estimate", estimateNames, estimate::envelope
    ) == estimate::closedForm;

    return made(rDict, [&]()
    {
        return roughWall::roughnessOfParameters
        (
            p, given[0], given[1], given[2], closedForm
        );
    });
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

roughWall::RoughnessAngle Foam::roughWallPatchSettings::readRoughness
(
    const dictionary& dict
)
{
    const entry* e = roughWallCompat::findLiteral(dict, "roughnessAngle");
    const bool profile = roughWallCompat::findLiteral(dict, "roughness");

    if (bool(e) == profile)
    {
        roughWallInput::fatalBadEntry
        (
            dict, "roughnessAngle",
            "exactly one of roughnessAngle (a constant or a table against "
            "the diameter) and roughness (a profile file or parameters)",
            e ? "both" : "neither roughnessAngle nor roughness"
        );
    }
    return e ? readAngle(dict) : readProfile(dict);
}


// ************************************************************************* //
