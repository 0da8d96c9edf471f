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

Description
    Registers roughWallInteraction, rotationalLift and fluidTorque for the
    momentum cloud, whose parcels carry no spin: cloudProperties type cloud
    (Foundation), basicKinematicCloud (v1912: uncoupledKinematicParcelFoam).
    Selecting a spin model for it stops with a FatalIOError naming the cloud
    type.

\*---------------------------------------------------------------------------*/

#include "foamCompat.H"
#include ROUGHWALL_CLOUD_HEADER(ROUGHWALL_MOMENTUM_CLOUD)
#include "makeRoughWallModels.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeRoughWallModels(ROUGHWALL_MOMENTUM_CLOUD)


// ************************************************************************* //
