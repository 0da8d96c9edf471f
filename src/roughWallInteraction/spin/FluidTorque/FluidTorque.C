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

#include "FluidTorque.H"
#include "spinModels.H"
#include "roughWallInput.H"
#include "foamCompat.H"
#include "coreBridge.H"
#include "fvcCurl.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::FluidTorque<CloudType>::clearFields()
{
    vorticityInterpPtr_.clear();
    rhoInterpPtr_.clear();
    muInterpPtr_.clear();
    vorticityPtr_.clear();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::FluidTorque<CloudType>::FluidTorque
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    CloudFunctionObject<CloudType>(dict, owner, modelName, typeName),
    coefficient_(roughWall::spin::TorqueCoefficient::DennisSinghIngham),
    vorticityPtr_(),
    vorticityInterpPtr_(),
    rhoInterpPtr_(),
    muInterpPtr_(),
    nEvaluations_(0),
    nOutside_(0)
{
    if constexpr (!withSpin)
    {
        spinModels::fatalNoSpin
        (
            dict, typeName, owner.name(),
            roughWallCompat::cloudTypeName(owner)
        );
    }

    roughWallInput::checkKeywords(dict, {"type", "coefficient"}, typeName);

    coefficient_ = spinModels::readTorqueCoefficient(dict);

    Info<< "    fluidTorque: coefficient "
        << spinModels::name(coefficient_).c_str() << endl;
}


template<class CloudType>
Foam::FluidTorque<CloudType>::FluidTorque
(
    const FluidTorque<CloudType>& ft
)
:
    CloudFunctionObject<CloudType>(ft),
    coefficient_(ft.coefficient_),
    vorticityPtr_(),
    vorticityInterpPtr_(),
    rhoInterpPtr_(),
    muInterpPtr_(),
    nEvaluations_(0),
    nOutside_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::FluidTorque<CloudType>::preEvolve(ROUGHWALL_EVOLVE_PARAMETERS)
{
    clearFields();

    const CloudType& cloud = this->owner();
    const volVectorField& Uc = cloud.U();
    const dictionary& schemes = cloud.solution().interpolationSchemes();

    vorticityPtr_.reset
    (
        new volVectorField
        (
            IOobject::groupName
            (
                cloud.name() + ":fluidTorqueVorticity",
                Uc.group()
            ),
            0.5*fvc::curl(Uc)
        )
    );

    // The cloud's interpolation of the carrier velocity
    const word scheme(schemes.lookup(Uc.name()));

    vorticityInterpPtr_.reset
    (
        interpolation<vector>::New(scheme, vorticityPtr_()).ptr()
    );

    // Density and viscosity as the cloud interpolates them
    rhoInterpPtr_.reset
    (
        interpolation<scalar>::New(schemes, cloud.rho()).ptr()
    );
    muInterpPtr_.reset
    (
        interpolation<scalar>::New(schemes, cloud.mu()).ptr()
    );
}


template<class CloudType>
void Foam::FluidTorque<CloudType>::postEvolve(ROUGHWALL_EVOLVE_PARAMETERS)
{
    // No file output (the base class would call write() at write
    // times); the log says how much of the evolve the coefficient covered
    // (model notes: a correlation outside its range says so)
    clearFields();

    spinModels::reportOutsideRange
    (
        "fluidTorque", spinModels::name(coefficient_),
        roughWall::spin::torqueRange(coefficient_), nEvaluations_, nOutside_
    );
}


template<class CloudType>
ROUGHWALL_POST_MOVE_RESULT Foam::FluidTorque<CloudType>::postMove
(
    parcelType& p,
    const scalar dt,
    const point&,
    ROUGHWALL_POST_MOVE_LAST
)
{
    if constexpr (withSpin)
    {
        const scalar I = p.momentOfInertia();

        if
        (
            !ROUGHWALL_POST_MOVE_KEPT || !(dt > 0) || !(I > 0)
         || !vorticityInterpPtr_.valid()
        )
        {
            return ROUGHWALL_POST_MOVE_KEEP;
        }

        const tetIndices tetIs =
            roughWallCompat::currentTetIndices(p, this->owner().mesh());

        const vector vorticity =
            vorticityInterpPtr_->interpolate(p.coordinates(), tetIs);
        const scalar rhoc = rhoInterpPtr_->interpolate(p.coordinates(), tetIs);
        const scalar muc = muInterpPtr_->interpolate(p.coordinates(), tetIs);

        const vector slip = vorticity - p.angularMomentum()/I;
        const scalar magSlip =
            roughWall::spin::magnitude(roughWallCompat::toCore(slip));

        // Every evaluation with a slip spin, against the range (at the
        // start of the step)
        if (magSlip > 0)
        {
            ++nEvaluations_;
            if
            (
                !roughWall::spin::torqueInRange
                (
                    coefficient_,
                    roughWall::spin::rotationalReynolds
                    (
                        magSlip, p.d(), muc/rhoc
                    )
                )
            )
            {
                ++nOutside_;
            }
        }

        const scalar decay = roughWall::spin::slipSpinDecay
        (
            magSlip,
            dt,
            p.d(),
            p.rho(),
            rhoc,
            muc/rhoc,
            coefficient_
        );

        p.angularMomentum() = I*(vorticity - decay*slip);
    }

    return ROUGHWALL_POST_MOVE_KEEP;
}


// ************************************************************************* //
