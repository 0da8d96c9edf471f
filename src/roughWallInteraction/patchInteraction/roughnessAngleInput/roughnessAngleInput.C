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
#include "limitsAndUnits.hpp"
#include "profileFile.hpp"
#include "OSspecific.H"
#include "Tuple2.H"

#include <ctime>

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


//- Delta(d_p) of the envelope of the profile that source describes;
//- dMin, dMax as EnvelopeAngleTable's; keyword names the entry in the
//- messages
roughWall::RoughnessAngle tabulate
(
    const dictionary& rDict,
    const word& keyword,
    const roughWall::SampledProfile& profile,
    const string& source,
    const scalar dMin,
    const scalar dMax
)
{
    const std::clock_t start = std::clock();
    roughWall::EnvelopeAngleTable envelope;
    try
    {
        envelope = roughWall::EnvelopeAngleTable(profile, dMin, dMax);
    }
    catch (const std::exception& err)
    {
        roughWallInput::fatalBadEntry
        (
            rDict, keyword,
            "a profile longer than twice its largest point spacing",
            profileMeaning, source + ": " + err.what()
        );
    }
    const scalar seconds = scalar(std::clock() - start)/CLOCKS_PER_SEC;

    const scalar maxDeg = roughWall::limits::maxRoughnessAngleDeg;
    const scalar maxFound = roughWall::limits::radToDeg(envelope.maxAngle());
    if (maxFound > maxDeg)
    {
        roughWallInput::fatalBadEntry
        (
            rDict, keyword,
            "a profile whose Delta(d_p) is at most " + Foam::name(maxDeg)
          + " deg (the model's limit)",
            profileMeaning,
            source + ": Delta up to " + Foam::name(maxFound) + " deg"
        );
    }

    Info<< "    " << rDict.name().c_str() << ": Delta(d_p) of the "
        << "rolling-sphere envelope of the " << source.c_str()
        << " tabulated at " << label(envelope.rows()) << " diameters from "
        << envelope.dMin() << " to " << envelope.dMax() << " m in "
        << seconds << " s CPU" << endl;

    return roughWall::RoughnessAngle::envelope(envelope, source);
}


//- roughnessAngle: a constant or a List<Tuple2> table [deg]
roughWall::RoughnessAngle readAngle(const dictionary& dict)
{
    const scalar maxDeg = roughWall::limits::maxRoughnessAngleDeg;
    const string allowed =
        "a number in [0, " + Foam::name(maxDeg)
      + "] or a table ((d1 Delta1) (d2 Delta2) ...) with Delta in [0, "
      + Foam::name(maxDeg) + "] and d >= 0 strictly increasing";

    const entry& e = *roughWallCompat::findLiteral(dict, "roughnessAngle");
    const string found =
        "'" + roughWallInput::entryText(dict, "roughnessAngle") + "'";

    auto fatal = [&](const string& what)
    {
        roughWallInput::fatalBadEntry
        (
            dict, "roughnessAngle", allowed, angleMeaning, what
        );
    };

    if (e.isDict())
    {
        fatal("a dictionary");
    }

    // A constant, or a table (d Delta) read by OpenFOAM's List<Tuple2>
    List<Tuple2<scalar, scalar>> table;
    const bool constant = e.stream().size() && e.stream()[0].isNumber();
    if (constant)
    {
        scalar angle = 0;
        if (!roughWallCompat::readAll(e.stream(), angle))
        {
            fatal(found);
        }
        table.setSize(1, Tuple2<scalar, scalar>(0, angle));
    }
    else if (!roughWallCompat::readAll(e.stream(), table) || table.empty())
    {
        fatal(found);
    }

    std::vector<roughWall::RoughnessAngle::Row> rows;
    for (const Tuple2<scalar, scalar>& row : table)
    {
        rows.emplace_back(row.first(), row.second());
    }
    const long bad = roughWall::RoughnessAngle::firstBadRow(rows);
    if (bad >= 0)
    {
        fatal
        (
            constant
          ? found
          : string(found + " (row " + Foam::name(label(bad + 1)) + ")")
        );
    }
    return roughWall::RoughnessAngle::table(rows);
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
            profileMeaning,
            "'" + roughWallInput::entryText(dict, "roughness") + "'"
        );
    }

    // Named after the patch entry, so that the messages point at it (a
    // sub-dictionary of an entry read from a stream loses that name)
    dictionary rDict(e.dict());
    rDict.name() =
        fileName(dict.name() + roughWallCompat::scopeSeparator + "roughness");

    static const wordList names{"profile", "Ra", "Rq", "Rz", "RSm", "estimate"};
    static const char* const meanings[] =
    {
        "arithmetic mean height of the profile [m]",
        "root-mean-square height of the profile [m]",
        "maximum height (peak to valley) of the profile [m]",
        "mean width of the profile elements [m]"
    };

    roughWallInput::checkKeywords(rDict, names, "roughness");

    // A measured trace: the wall itself, nothing else beside it
    if (roughWallCompat::findLiteral(rDict, "profile"))
    {
        for (label i = 1; i < names.size(); ++i)
        {
            if (roughWallCompat::findLiteral(rDict, names[i]))
            {
                roughWallInput::fatalBadEntry
                (
                    rDict, names[i],
                    "no other keyword beside profile (the trace gives the "
                    "wall): either profile or the parameters Ra/Rq/Rz, RSm",
                    profileMeaning,
                    "'" + roughWallInput::entryText(rDict, names[i]) + "'"
                );
            }
        }

        const string allowed =
            "a readable trace of at least "
          + Foam::name(label(roughWall::minProfilePoints))
          + " points, lines 'x z' with finite numbers, x strictly increasing "
            "(docs/roughWallInteraction.md)";
        const fileName given = roughWallInput::read<fileName>
        (
            rDict, "profile", allowed, traceMeaning
        );
        // OpenFOAM's expansion stops at an unset variable with a message
        // that names neither the keyword nor the file: caught
        fileName path(given);
        string error;
        if (!roughWallCompat::callCatching([&]() { path.expand(); }, error))
        {
            roughWallInput::fatalBadEntry
            (
                rDict, "profile", allowed, traceMeaning,
                "'" + given + "': " + error
            );
        }
        if (!path.isAbsolute())
        {
            path = fileName(getEnv("FOAM_CASE"))/path;
        }

        roughWall::SampledProfile trace;
        try
        {
            trace =
                roughWall::levelledProfile(roughWall::readProfileFile(path));
        }
        catch (const std::exception& err)
        {
            roughWallInput::fatalBadEntry
            (
                rDict, "profile", allowed, traceMeaning, string(err.what())
            );
        }
        return tabulate
        (
            rDict, "profile", trace,
            "profile " + path + " (" + Foam::name(label(trace.x.size()))
          + " points, levelled)",
            0, 0
        );
    }

    roughWall::ProfileRoughness parameters;
    double* values[] =
        {&parameters.Ra, &parameters.Rq, &parameters.Rz, &parameters.RSm};
    bool given[4];
    for (label i = 0; i < 4; ++i)
    {
        const word& name = names[i + 1];
        given[i] = roughWallCompat::findLiteral(rDict, name);

        // The signs are checked with the other limits below
        *values[i] =
            given[i]
          ? roughWallInput::readNumber<scalar>
            (
                rDict, name, {-GREAT, GREAT, meanings[i]}
            )
          : 0;
    }

    const roughWall::ProfileRoughnessError error =
        roughWall::checkProfileRoughness
        (
            parameters, given[0], given[1], given[2]
        );

    if (!error.keyword.empty())
    {
        const word key(error.keyword);
        roughWallInput::fatalBadEntry
        (
            rDict, key, error.allowed, profileMeaning,
            roughWallCompat::findLiteral(rDict, key)
          ? "'" + roughWallInput::entryText(rDict, key) + "'"
          : string("missing")
        );
    }

    // How Delta(d) follows from the parameters: the envelope of the
    // synthetic Gaussian profile (default), or the closed-form estimate
    // (docs/roughWallInteraction.md: its figure shows where they differ)
    const bool closedForm = roughWallInput::readChoice
    (
        rDict, "estimate", {"envelope", "closedForm"},
        "how Delta(d_p) follows from the parameters: the rolling-sphere "
        "envelope of a synthetic Gaussian profile (envelope, default) "
        "or atan(2 pi Rq / max(RSm, d_p)) (closedForm)",
        0
    ) == 1;

    if (closedForm)
    {
        return roughWall::RoughnessAngle::closedForm(parameters);
    }

    const roughWall::SyntheticProfileSettings synthetic =
        roughWall::gaussianProfileOf(parameters);
    const roughWall::SampledProfile profile =
        roughWall::syntheticGaussianProfile(synthetic);

    // Below RSm/10 Delta is at its small-sphere limit (to 3e-4 deg); above
    // 100 RSm it has fallen to a tenth of it
    return tabulate
    (
        rDict, given[1] ? "Rq" : given[0] ? "Ra" : "Rz", profile,
        "synthetic Gaussian profile, Rq = " + Foam::name(synthetic.Rq)
      + " m, RSm = " + Foam::name(synthetic.RSm) + " m ("
      + Foam::name(label(profile.x.size())) + " points, seed "
      + Foam::name(label(synthetic.seed)) + ")",
        synthetic.RSm/10, 100*synthetic.RSm
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
