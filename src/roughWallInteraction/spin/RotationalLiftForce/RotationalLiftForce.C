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

#include "RotationalLiftForce.H"
#include "spinModels.H"
#include "roughWallInput.H"
#include "foamCompat.H"
#include "coreBridge.H"
#include "fvcCurl.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RotationalLiftForce<CloudType>::RotationalLiftForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    coefficient_(roughWall::spin::LiftCoefficient::OesterleBuiDinh),
    vorticityPtr_(),
    vorticityInterpPtr_(),
    nEvaluations_(0),
    nOutside_(0)
{
    if constexpr (!withSpin)
    {
        spinModels::fatalNoSpin
        (
            this->coeffs(), typeName, owner.name(),
            roughWallCompat::cloudTypeName(owner)
        );
    }

    roughWallInput::checkKeywords(this->coeffs(), {"coefficient"}, typeName);

    coefficient_ = spinModels::readLiftCoefficient(this->coeffs());

    Info<< "    rotationalLift: coefficient "
        << spinModels::name(coefficient_).c_str() << endl;
}


template<class CloudType>
Foam::RotationalLiftForce<CloudType>::RotationalLiftForce
(
    const RotationalLiftForce& lf
)
:
    ParticleForce<CloudType>(lf),
    coefficient_(lf.coefficient_),
    vorticityPtr_(),
    vorticityInterpPtr_(),
    nEvaluations_(0),
    nOutside_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::RotationalLiftForce<CloudType>::cacheFields(const bool store)
{
    vorticityInterpPtr_.clear();
    vorticityPtr_.clear();

    if (!store)
    {
        // The end of an evolve: how much of it the correlation covered
        // (model notes: a correlation outside its range says so)
        spinModels::reportOutsideRange
        (
            "rotationalLift", spinModels::name(coefficient_),
            roughWall::spin::liftRange(coefficient_), nEvaluations_,
            nOutside_
        );
        return;
    }

    const volVectorField& Uc = this->owner().U();

    vorticityPtr_.reset
    (
        new volVectorField
        (
            IOobject::groupName
            (
                this->owner().name() + ":rotationalLiftVorticity",
                Uc.group()
            ),
            0.5*fvc::curl(Uc)
        )
    );

    // The cloud's interpolation of the carrier velocity
    const word scheme
    (
        this->owner().solution().interpolationSchemes().lookup(Uc.name())
    );

    vorticityInterpPtr_.reset
    (
        interpolation<vector>::New(scheme, vorticityPtr_()).ptr()
    );
}


template<class CloudType>
Foam::forceSuSp Foam::RotationalLiftForce<CloudType>::calcCoupled
(
    const parcelType& p,
    const typename parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    forceSuSp value(Zero, 0);

    if constexpr (withSpin)
    {
        const scalar I = p.momentOfInertia();

        if (I > 0 && vorticityInterpPtr_.valid())
        {
            using roughWallCompat::toCore;

            const vector vorticity =
                vorticityInterpPtr_->interpolate
                (
                    p.coordinates(),
                    roughWallCompat::currentTetIndices(p, this->mesh())
                );

            const scalar rhoc = td.rhoc();
            const vector slipU = td.Uc() - p.U();
            const vector slipOmega = vorticity - p.angularMomentum()/I;

            value.Su() = roughWallCompat::toFoam
            (
                roughWall::spin::rotationalLift
                (
                    toCore(slipU),
                    toCore(slipOmega),
                    p.d(),
                    rhoc,
                    muc/rhoc,
                    coefficient_
                )
            );

            // Every evaluation with a force, against the range: Re_p the
            // cloud's (Re), the spin ratio Omega* = |Omega_rel| d/|U_rel|
            const scalar magSlipU = mag(slipU);
            const scalar magSlipOmega = mag(slipOmega);
            if (magSlipU > 0 && magSlipOmega > 0)
            {
                ++nEvaluations_;
                if
                (
                    !roughWall::spin::liftInRange
                    (
                        coefficient_, Re, magSlipOmega*p.d()/magSlipU
                    )
                )
                {
                    ++nOutside_;
                }
            }
        }
    }

    return value;
}


// ************************************************************************* //
