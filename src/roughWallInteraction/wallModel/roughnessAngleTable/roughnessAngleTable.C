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

#include "roughnessAngleTable.H"
#include "roughWallInput.H"
#include "foamCompat.H"
#include "roughWallLimits.hpp"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * * //

const Foam::scalar Foam::roughnessAngleTable::maxAngleDeg =
    roughWall::limits::maxRoughnessAngleDeg;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

const char* const meaning =
    "roughness angle Delta, standard deviation of the facet tilt [deg]; "
    "a constant or a table ((d1 Delta1) (d2 Delta2) ...) against the "
    "particle diameter d [m]";


bool isPunct(const Foam::token& t, const Foam::token::punctuationToken p)
{
    return t.isPunctuation() && t.pToken() == p;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::roughnessAngleTable::roughnessAngleTable()
:
    diameters_(),
    angles_(1, Zero),
    fromProfile_(false),
    profile_(),
    correlation_()
{}


Foam::roughnessAngleTable::roughnessAngleTable
(
    const dictionary& dict,
    const word& keyword
)
:
    diameters_(),
    angles_(),
    fromProfile_(false),
    profile_(),
    correlation_()
{
    readAngle(dict, keyword);
}


Foam::roughnessAngleTable::roughnessAngleTable(const dictionary& dict)
:
    diameters_(),
    angles_(),
    fromProfile_(false),
    profile_(),
    correlation_()
{
    const bool angle = roughWallCompat::findLiteral(dict, "roughnessAngle");
    const bool profile = roughWallCompat::findLiteral(dict, "roughness");

    if (angle == profile)
    {
        roughWallInput::fatalBadEntry
        (
            dict, "roughnessAngle",
            "exactly one of the keywords roughnessAngle (a constant or a "
            "table against the diameter) and roughness (the profile "
            "parameters)",
            "the wall's roughness",
            angle
          ? "both roughnessAngle and roughness"
          : "missing (neither roughnessAngle nor roughness)"
        );
    }

    if (angle)
    {
        readAngle(dict, "roughnessAngle");
    }
    else
    {
        readProfile(dict, "roughness");
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::roughnessAngleTable::readProfile
(
    const dictionary& dict,
    const word& keyword
)
{
    using namespace roughWallInput;

    static const char* const profileMeaning =
        "profile roughness parameters of the wall (ISO 4287, SI units): "
        "one or more of Ra, Rq, Rz, and RSm; Delta(d_p) = "
        "atan(2 pi Rq / max(RSm, d_p))";

    const entry* eptr = roughWallCompat::findLiteral(dict, keyword);
    if (!eptr->isDict())
    {
        fatalBadEntry
        (
            dict, keyword, "a dictionary { Ra ...; RSm ...; }",
            profileMeaning, "'" + entryText(dict, keyword) + "'"
        );
    }
    // Named after the patch entry, so that the messages point at it (a
    // sub-dictionary of an entry read from a stream loses that name)
    dictionary rDict(eptr->dict());
    rDict.name() =
        fileName
        (
            dict.name() + (roughWallCompat::esi ? "." : "/") + keyword
        );

    static const wordList names{"Ra", "Rq", "Rz", "RSm"};
    static const char* const meanings[] =
    {
        "arithmetic mean height of the profile [m]",
        "root-mean-square height of the profile [m]",
        "maximum height (peak to valley) of the profile [m]",
        "mean width of the profile elements [m]"
    };

    checkKeywords(rDict, names, keyword);

    scalar values[4] = {0, 0, 0, 0};
    bool given[4] = {false, false, false, false};
    for (label i = 0; i < 4; ++i)
    {
        given[i] = roughWallCompat::findLiteral(rDict, names[i]);
        if (given[i])
        {
            // The signs are checked with the other limits below
            values[i] =
                readScalar(rDict, names[i], {-GREAT, GREAT, meanings[i]});
        }
    }

    profile_.Ra = values[0];
    profile_.Rq = values[1];
    profile_.Rz = values[2];
    profile_.RSm = values[3];

    const roughWall::ProfileRoughnessError error =
        roughWall::checkProfileRoughness
        (
            profile_, given[0], given[1], given[2]
        );

    if (!error.keyword.empty())
    {
        const word key(error.keyword);
        const bool present = roughWallCompat::findLiteral(rDict, key);
        fatalBadEntry
        (
            rDict, key, error.allowed, profileMeaning,
            present ? "'" + entryText(rDict, key) + "'" : string("missing")
        );
    }

    fromProfile_ = true;
    correlation_ = roughWall::RoughnessCorrelation(profile_);
    angles_.setSize(1, correlation_.angleUncached(0));
}


void Foam::roughnessAngleTable::readAngle
(
    const dictionary& dict,
    const word& keyword
)
{
    using namespace roughWallInput;

    const string allowed =
        "a number in [0, " + Foam::name(maxAngleDeg)
      + "] or a table ((d1 Delta1) (d2 Delta2) ...) with Delta in [0, "
      + Foam::name(maxAngleDeg) + "] and d >= 0 strictly increasing";

    const entry* eptr = roughWallCompat::findLiteral(dict, keyword);

    if (!eptr)
    {
        fatalBadEntry(dict, keyword, allowed, meaning, "missing");
    }
    if (eptr->isDict())
    {
        fatalBadEntry(dict, keyword, allowed, meaning, "a dictionary");
    }

    const string found = "'" + entryText(dict, keyword) + "'";
    const ITstream& is = eptr->stream();

    // Constant
    if (is.size() == 1 && is[0].isNumber())
    {
        const scalar angle = is[0].number();
        if (!(angle >= 0 && angle <= maxAngleDeg))
        {
            fatalBadEntry(dict, keyword, allowed, meaning, found);
        }
        angles_.setSize(1, roughWall::limits::degToRad(angle));
        return;
    }

    // Table: ( (d Delta) (d Delta) ... ), at least one row
    const label nTokens = is.size();
    const bool framed =
        nTokens >= 6
     && isPunct(is[0], token::BEGIN_LIST)
     && isPunct(is[nTokens - 1], token::END_LIST)
     && (nTokens - 2) % 4 == 0;

    if (!framed)
    {
        fatalBadEntry(dict, keyword, allowed, meaning, found);
    }

    const label nRows = (nTokens - 2)/4;
    diameters_.setSize(nRows);
    angles_.setSize(nRows);

    for (label rowi = 0; rowi < nRows; ++rowi)
    {
        const label t = 1 + 4*rowi;

        const bool goodRow =
            isPunct(is[t], token::BEGIN_LIST)
         && is[t + 1].isNumber()
         && is[t + 2].isNumber()
         && isPunct(is[t + 3], token::END_LIST);

        if (!goodRow)
        {
            fatalBadEntry(dict, keyword, allowed, meaning, found);
        }

        const scalar d = is[t + 1].number();
        const scalar angle = is[t + 2].number();

        const bool goodValues =
            d >= 0
         && angle >= 0
         && angle <= maxAngleDeg
         && (rowi == 0 || d > diameters_[rowi - 1]);

        if (!goodValues)
        {
            fatalBadEntry
            (
                dict, keyword, allowed, meaning,
                found + " (row " + Foam::name(rowi + 1) + ")"
            );
        }

        diameters_[rowi] = d;
        angles_[rowi] = roughWall::limits::degToRad(angle);
    }

    // A one-row table is a constant
    if (nRows == 1)
    {
        diameters_.clear();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::roughnessAngleTable::tableValue(const scalar d) const
{
    if (constant())
    {
        return angles_[0];
    }

    const label n = diameters_.size();

    if (!(d > diameters_[0]))
    {
        return angles_[0];
    }
    if (d >= diameters_[n - 1])
    {
        return angles_[n - 1];
    }

    // Bisection for diameters_[lo] <= d < diameters_[lo + 1]
    label lo = 0;
    label hi = n - 1;
    while (hi - lo > 1)
    {
        const label mid = (lo + hi)/2;
        if (diameters_[mid] <= d)
        {
            lo = mid;
        }
        else
        {
            hi = mid;
        }
    }

    const scalar f = (d - diameters_[lo])/(diameters_[hi] - diameters_[lo]);
    return angles_[lo] + f*(angles_[hi] - angles_[lo]);
}


Foam::string Foam::roughnessAngleTable::description() const
{
    OStringStream os;
    if (fromProfile_)
    {
        os  << "atan(2 pi Rq/max(RSm, d)) with Rq = "
            << correlation_.rmsHeight() << " m, RSm = " << profile_.RSm
            << " m: " << roughWall::limits::radToDeg(angles_[0])
            << " deg for d <= RSm";
    }
    else if (constant())
    {
        os  << roughWall::limits::radToDeg(angles_[0]) << " deg";
    }
    else
    {
        os  << "table of " << diameters_.size() << " rows, "
            << roughWall::limits::radToDeg(angles_[0]) << " deg at d = " << diameters_[0]
            << " m to " << roughWall::limits::radToDeg(angles_.last()) << " deg at d = "
            << diameters_.last() << " m";
    }
    return os.str();
}


// ************************************************************************* //
