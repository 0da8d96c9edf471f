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

#include "roughnessAngleInput.H"
#include "roughWallInput.H"
#include "foamCompat.H"
#include "OSspecific.H"
#include "Tuple2.H"

#include <ctime>

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

ROUGHWALL_NAMED_ENUM
(
    estimateNames, Foam::roughnessAngleInput::estimate, 2,
    "envelope", "closedForm"
);


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

const char* const angleMeaning =
    "roughness angle Delta, standard deviation of the facet tilt [deg]; "
    "a constant or a table ((d1 Delta1) (d2 Delta2) ...) against the "
    "particle diameter d [m]";

const char* const profileMeaning =
    "the wall's profile: a measured trace (profile \"<file>\") or its "
    "roughness parameters (ISO 4287, SI units: one or more of Ra, Rq, Rz, "
    "and RSm); Delta(d_p) from the rolling-sphere envelope of the trace or "
    "of a synthetic Gaussian profile with these parameters (estimate "
    "closedForm: atan(2 pi Rq / max(RSm, d_p)))";

const char* const traceMeaning =
    "measured wall profile: an ASCII file of lines 'x z' [m] (or units "
    "given by a line '# units XU ZU'), x strictly increasing; path "
    "absolute or relative to the case";

//- The parameters: keyword, place and meaning
using P = roughWall::ProfileRoughness;
const struct { const char* name; double P::* value; const char* meaning; }
parameters[4] =
{
    {"Ra", &P::Ra, "arithmetic mean height of the profile [m]"},
    {"Rq", &P::Rq, "root-mean-square height of the profile [m]"},
    {"Rz", &P::Rz, "maximum height (peak to valley) of the profile [m]"},
    {"RSm", &P::RSm, "mean width of the profile elements [m]"}
};


//- make(), the core's construction of Delta(d_p), with its errors as a
//- FatalIOError of dict naming the keyword, what is allowed and what was
//- found; the tabulation of an envelope logged with its CPU time
template<class Make>
roughWall::RoughnessAngle made
(
    const dictionary& dict,
    const char* meaning,
    const Make& make
)
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
        const word key(err.keyword);
        const string wrong(err.what());
        roughWallInput::fatalBadEntry
        (
            dict, key, err.allowed, meaning,
            roughWallInput::entryText(dict, key)
          + (wrong.empty() ? "" : " (" + wrong + ")")
        );
    }
}


//- roughnessAngle: a constant or a List<Tuple2> table [deg]
roughWall::RoughnessAngle readAngle(const dictionary& dict)
{
    const entry& e = *roughWallCompat::findLiteral(dict, "roughnessAngle");
    const string allowed(roughWall::roughnessAngleAllowed());

    // A number, or a table (d Delta) read by OpenFOAM's List<Tuple2>
    scalar angle = 0;
    List<Tuple2<scalar, scalar>> table;
    if (roughWallInput::readWhole(e, [&]() { e.stream() >> angle; }).empty())
    {
        table.setSize(1, Tuple2<scalar, scalar>(0, angle));
    }
    else
    {
        table = roughWallInput::read<List<Tuple2<scalar, scalar>>>
        (
            dict, "roughnessAngle", allowed, angleMeaning
        );
    }

    std::vector<roughWall::RoughnessAngle::Row> rows;
    for (const Tuple2<scalar, scalar>& row : table)
    {
        rows.emplace_back(row.first(), row.second());
    }
    return made
    (
        dict, angleMeaning, [&]() { return roughWall::roughnessOfRows(rows); }
    );
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
            "a dictionary { profile \"<file>\"; } or { Ra ...; RSm ...; }",
            profileMeaning
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
        trace
      ? "roughness with a profile (the trace gives the wall: no parameter "
        "Ra/Rq/Rz, RSm or estimate beside it)"
      : "roughness"
    );

    if (trace)
    {
        const string allowed(roughWall::profileFileAllowed());
        // OpenFOAM's expansion of $VAR stops at an unset variable with a
        // message that names neither the keyword nor the file: caught
        fileName path = roughWallInput::read<fileName>
        (
            rDict, "profile", allowed, traceMeaning,
            [](Istream& is) { fileName f; is >> f; f.expand(); return f; }
        );
        if (!path.isAbsolute())
        {
            path = fileName(getEnv("FOAM_CASE"))/path;
        }
        return made
        (
            rDict, traceMeaning,
            [&]() { return roughWall::roughnessOfTrace(path); }
        );
    }

    // The parameters, of any sign (the core checks them) but NaN
    roughWall::ProfileRoughness p;
    bool given[4];
    for (label i = 0; i < 4; ++i)
    {
        given[i] = roughWallCompat::findLiteral(rDict, parameters[i].name);
        p.*parameters[i].value = roughWallInput::readNumber<scalar>
        (
            rDict, parameters[i].name,
            {-GREAT, GREAT, parameters[i].meaning}, scalar(0)
        );
    }
    const bool closedForm = roughWallInput::readEnum
    (
        rDict, "estimate", estimateNames,
        "how Delta(d_p) follows from the parameters: the rolling-sphere "
        "envelope of a synthetic Gaussian profile (envelope, default) "
        "or atan(2 pi Rq / max(RSm, d_p)) (closedForm)",
        roughnessAngleInput::estimate::envelope
    ) == roughnessAngleInput::estimate::closedForm;

    return made
    (
        rDict, profileMeaning,
        [&]()
        {
            return roughWall::roughnessOfParameters
            (
                p, given[0], given[1], given[2], closedForm
            );
        }
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * //

roughWall::RoughnessAngle Foam::roughnessAngleInput::read
(
    const dictionary& dict
)
{
    const bool angle = roughWallCompat::findLiteral(dict, "roughnessAngle");
    const bool profile = roughWallCompat::findLiteral(dict, "roughness");

    if (angle == profile)
    {
        roughWallInput::fatalBadEntry
        (
            dict, "roughnessAngle",
            "exactly one of the keywords roughnessAngle (a constant or a "
            "table against the diameter) and roughness (a profile file or "
            "the profile parameters)",
            "the wall's roughness",
            angle
          ? "both roughnessAngle and roughness"
          : "missing (neither roughnessAngle nor roughness)"
        );
    }

    return angle ? readAngle(dict) : readProfile(dict);
}


// ************************************************************************* //
