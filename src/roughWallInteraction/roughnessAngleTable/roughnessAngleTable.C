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
    angles_(1, Zero)
{}


Foam::roughnessAngleTable::roughnessAngleTable
(
    const dictionary& dict,
    const word& keyword
)
:
    diameters_(),
    angles_()
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

Foam::scalar Foam::roughnessAngleTable::value(const scalar d) const
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
    if (constant())
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
