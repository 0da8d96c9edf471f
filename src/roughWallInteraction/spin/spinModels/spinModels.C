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

#include "spinModels.H"
#include "roughWallInput.H"
#include "foamCompat.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

// The names of the coefficients, in the order of the core's enumerations
ROUGHWALL_NAMED_ENUM
(
    liftNames, roughWall::spin::LiftCoefficient, 3,
    "RubinowKeller", "OesterleBuiDinh", "Loth"
);
ROUGHWALL_NAMED_ENUM
(
    torqueNames, roughWall::spin::TorqueCoefficient, 2,
    "Stokes", "DennisSinghIngham"
);


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

roughWall::spin::LiftCoefficient Foam::spinModels::readLiftCoefficient
(
    const dictionary& dict
)
{
    using roughWall::spin::LiftCoefficient;

    return roughWallInput::readEnum
    (
        dict, "coefficient", liftNames, LiftCoefficient::OesterleBuiDinh
    );
}


roughWall::spin::TorqueCoefficient
Foam::spinModels::readTorqueCoefficient
(
    const dictionary& dict
)
{
    using roughWall::spin::TorqueCoefficient;

    return roughWallInput::readEnum
    (
        dict, "coefficient", torqueNames, TorqueCoefficient::DennisSinghIngham
    );
}


Foam::word Foam::spinModels::name
(
    const roughWall::spin::LiftCoefficient c
)
{
    return liftNames[c];
}


Foam::word Foam::spinModels::name
(
    const roughWall::spin::TorqueCoefficient c
)
{
    return torqueNames[c];
}


void Foam::spinModels::fatalNoSpin
(
    const dictionary& dict,
    const word& model,
    const word& cloudName,
    const string& cloudType
)
{
    FatalIOErrorInFunction(dict)
        << model.c_str() << " acts on the spin of the parcels, but the parcels"
        << " of cloud " << cloudName.c_str() << " (type "
        << cloudType.c_str() << ") carry no spin." << nl
        << "    Select " << model.c_str() << " in a cloud whose parcels carry"
        << " spin: type collidingCloud (openfoam.org releases) or"
        << " basicKinematicCollidingCloud (ESI releases:"
        << " icoUncoupledKinematicParcelFoam, DPMFoam)," << nl
        << "    or remove it from " << dict.name().c_str()
        << exit(FatalIOError);

    // exit() does not return; keep [[noreturn]] honest for the compiler
    std::abort();
}


void Foam::spinModels::reportOutsideRange
(
    const char* model,
    const word& coefficient,
    const char* range,
    label& nEvaluations,
    label& nOutside
)
{
    reduce(nEvaluations, sumOp<label>());
    reduce(nOutside, sumOp<label>());
    Info<< "    " << model << " (" << coefficient.c_str() << "): " << nOutside
        << " of " << nEvaluations << " evaluations outside the correlation's"
        << " range (" << range << ")" << endl;
    nEvaluations = 0;
    nOutside = 0;
}


// ************************************************************************* //
