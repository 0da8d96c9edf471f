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

#include "envelopeRangeWarning.H"
#include "foamCompat.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::envelopeRangeWarning::report
(
    const word& patch,
    const wordRe& entry,
    const roughWall::RoughnessAngle& roughness
)
{
    if
    (
        warned_
     || roughness.form() != roughWall::RoughnessAngle::Form::envelope
    )
    {
        return;
    }

    // Gathered from every processor: a warning given on another processor
    // than the master would not be printed
    scalarList outside({-min_, max_});
    roughWallCompat::maxOverProcessors(outside);
    if (outside[1] > 0)
    {
        warned_ = true;
        const roughWall::EnvelopeAngleTable& envelope =
            roughness.envelopeTable();
        WarningInFunction
            << "Patch " << patch << " (entry " << entry << "): parcels "
            << "of diameters " << -outside[0] << " to " << outside[1]
            << " m hit the wall, outside the diameters " << envelope.dMin()
            << " to " << envelope.dMax() << " m for which Delta(d_p) of the "
            << roughness.source().c_str() << " is tabulated;" << nl
            << "    Delta is held at its value at the nearer end (warned "
            << "once per mesh patch)" << endl;
    }
}


// ************************************************************************* //
