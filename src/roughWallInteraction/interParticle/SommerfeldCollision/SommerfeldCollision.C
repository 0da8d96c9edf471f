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

#include "SommerfeldCollision.H"
#include "roughWallInput.H"
#include "coreBridge.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::SommerfeldCollision<CloudType>::readSettings(const dictionary& dict)
{
    roughWallInput::checkKeywords
    (
        dict,
        {
            "e", "mu", "correlation", "sizeClassBounds", "minCellParcels",
            "maxProbability"
        },
        typeName
    );

    settings_.material.e =
        roughWallInput::readNumber<scalar>(dict, "e", {0, 1});
    settings_.material.mu =
        roughWallInput::readNumber<scalar>(dict, "mu", {0, 10});
    correlation_ = roughWallInput::readSwitch(dict, "correlation");
    settings_.maxProbability = roughWallInput::readNumber<scalar>
    (
        dict, "maxProbability", {1e-6, 1}, scalar(0.1)
    );
    const label minCellParcels = roughWallInput::readNumber<label>
    (
        dict, "minCellParcels", {1, 1e6}, label(5)
    );

    const scalarList bounds = roughWallInput::read<scalarList>
    (
        dict, "sizeClassBounds",
        "a list of ascending positive diameters [m], e.g. (1e-4 2e-4)",
        scalarList()
    );
    for (label i = 0; i < bounds.size(); ++i)
    {
        if (!(bounds[i] > 0) || (i > 0 && !(bounds[i] > bounds[i - 1])))
        {
            roughWallInput::fatalBadEntry
            (
                dict, "sizeClassBounds",
                "a list of ascending positive diameters [m], e.g. (1e-4 2e-4)"
            );
        }
    }

    statistics_ = roughWall::ParticleCellStatistics
    (
        std::vector<double>(bounds.begin(), bounds.end()),
        int(minCellParcels)
    );

    Info<< "    " << typeName << ": e = " << settings_.material.e
        << ", mu = " << settings_.material.mu
        << ", correlation " << (correlation_ ? "on" : "off")
        << ", size classes " << statistics_.nClasses()
        << " (sizeClassBounds " << bounds << ")"
        << ", minCellParcels = " << minCellParcels
        << ", maxProbability = " << settings_.maxProbability << endl;
}


template<class CloudType>
roughWall::Vec3 Foam::SommerfeldCollision<CloudType>::spinOf
(
    const typename CloudType::parcelType& p
)
{
    if constexpr (parcelCarriesSpin<typename CloudType::parcelType>::value)
    {
        return roughWallCompat::toCore
        (
            p.angularMomentum()/p.momentOfInertia()
        );
    }
    return roughWall::Vec3::Zero();
}


template<class CloudType>
void Foam::SommerfeldCollision<CloudType>::gatherStatistics()
{
    CloudType& cloud = this->owner();
    const fvMesh& mesh = cloud.mesh();

    statistics_.clear(int(mesh.nCells()));
    forAllIter(typename CloudType, cloud, iter)
    {
        const auto& p = iter();
        statistics_.add
        (
            int(p.cell()), p.d(), p.nParticle(),
            roughWallCompat::toCore(p.U()), spinOf(p)
        );
    }

    // The cloud's moments per class, summed over processors
    auto& cloudMoments = statistics_.cloudMoments();
    const label nc = label(cloudMoments.size());
    scalarList packed(11*nc, scalar(0));
    for (label c = 0; c < nc; ++c)
    {
        const auto& m = cloudMoments[c];
        scalar* x = &packed[11*c];
        x[0] = m.weight;
        x[10] = m.parcels;
        for (label k = 0; k < 3; ++k)
        {
            x[1 + k] = m.sum[k];
            x[4 + k] = m.sumSquares[k];
            x[7 + k] = m.spinSum[k];
        }
    }
    roughWallCompat::sumOverProcessors(packed);
    for (label c = 0; c < nc; ++c)
    {
        auto& m = cloudMoments[c];
        const scalar* x = &packed[11*c];
        m.weight = x[0];
        m.parcels = x[10];
        for (label k = 0; k < 3; ++k)
        {
            m.sum[k] = x[1 + k];
            m.sumSquares[k] = x[4 + k];
            m.spinSum[k] = x[7 + k];
        }
    }

    const scalarField& V = mesh.V();
    statistics_.finish([&V](int cell) { return V[cell]; });
}


template<class CloudType>
Foam::tmp<Foam::volScalarField>
Foam::SommerfeldCollision<CloudType>::kolmogorovTime() const
{
    const CloudType& cloud = this->owner();
    tmp<volScalarField> tEpsilon =
        roughWallCompat::carrierEpsilon(cloud.mesh(), cloud.U().group());
    if (!tEpsilon.valid() || gMax(tEpsilon().primitiveField()) <= 0)
    {
        FatalIOErrorInFunction(roughWallCompat::coeffs(*this))
            << "correlation true needs a turbulent carrier (a RAS or LES "
            << "momentum transport model whose epsilon is not zero "
            << "everywhere): Sommerfeld's R(St_K) takes St_K from the "
            << "carrier's Kolmogorov time sqrt(nu/epsilon); "
            << (tEpsilon.valid() ? "its epsilon is zero everywhere"
                                 : "none was found")
            << ". Set correlation false for a laminar or absent carrier."
            << exit(FatalIOError);
    }
    const volScalarField nu(cloud.mu()/cloud.rho());
    const dimensionedScalar small("small", tEpsilon().dimensions(), 1e-300);
    return sqrt(nu/max(tEpsilon(), small));
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::SommerfeldCollision<CloudType>::collide
(
    ROUGHWALL_STOCHASTIC_COLLIDE_PARAMETERS
)
{
    using parcelType = typename CloudType::parcelType;
    constexpr bool withSpin = parcelCarriesSpin<parcelType>::value;

    const scalar dt = ROUGHWALL_STOCHASTIC_COLLIDE_DT;
    CloudType& cloud = this->owner();

    gatherStatistics();

    tmp<volScalarField> tauK;
    if (correlation_)
    {
        tauK = kolmogorovTime();
    }

    using randomGenerator =
        typename std::remove_reference<decltype(cloud.rndGen())>::type;
    cloudUniform01<randomGenerator> uniform01(cloud.rndGen());

    // Real particles: collisions, and weights; parcels: draws, pooled draws,
    // split steps
    scalar weightedCollisions = 0, weight = 0;
    scalar draws = 0, pooledDraws = 0, splitParcels = 0;
    scalar stepLargest = 0;

    forAllIter(typename CloudType, cloud, iter)
    {
        parcelType& p = iter();
        const label celli = p.cell();

        scalar R = 0;
        if (correlation_)
        {
            const scalar tauP =
                p.rho()*sqr(p.d())/(18*cloud.mu()[celli]);
            R = roughWall::partnerCorrelation(tauP/tauK()[celli]);
        }

        roughWall::Vec3 u = roughWallCompat::toCore(p.U());
        roughWall::Vec3 w = spinOf(p);

        const roughWall::PartnerCollisionOutcome outcome =
            roughWall::collideWithFictitiousPartners<withSpin>
            (
                u, w, p.d(), p.nParticle(), int(celli), dt, R, statistics_,
                settings_,
                uniform01
            );

        if (outcome.collisions > 0)
        {
            p.U() = roughWallCompat::toFoam(u);
            if constexpr (withSpin)
            {
                p.angularMomentum() =
                    p.momentOfInertia()*roughWallCompat::toFoam(w);
            }
        }

        weightedCollisions += p.nParticle()*outcome.collisions;
        weight += p.nParticle();
        draws += outcome.draws;
        pooledDraws += outcome.pooledDraws;
        splitParcels += outcome.subSteps > 1;
        stepLargest = max(stepLargest, outcome.largestProbability);
    }

    scalarList sums
    (
        {weightedCollisions, weight, draws, pooledDraws, splitParcels}
    );
    roughWallCompat::sumOverProcessors(sums);
    reduce(stepLargest, maxOp<scalar>());
    largestProbability_ = max(largestProbability_, stepLargest);

    if (stepLargest > settings_.maxProbability && !warnedSplit_)
    {
        warnedSplit_ = true;
        WarningInFunction
            << typeName << ": a collision probability of " << stepLargest
            << " in one step exceeds maxProbability "
            << settings_.maxProbability << "; such steps are split into "
            << "sub-steps with fresh partners (the log gives the largest "
            << "probability of the run at every step)" << endl;
    }

    Info<< "    " << typeName << " collisions: "
        << (sums[1] > 0 ? sums[0]/(sums[1]*dt) : 0)
        << " per particle per second (" << sums[0] << " of "
        << sums[1] << " particles in " << dt << " s)"
        << ", pooled statistics for "
        << (sums[2] > 0 ? 100*sums[3]/sums[2] : 0) << " % of partners"
        << ", largest P " << largestProbability_
        << ", split steps " << label(sums[4]) << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::SommerfeldCollision<CloudType>::SommerfeldCollision
(
    const dictionary& dict,
    CloudType& owner
)
:
    StochasticCollisionModel<CloudType>(dict, owner, typeName),
    settings_(),
    correlation_(false),
    statistics_({}, 5),
    largestProbability_(0),
    warnedSplit_(false)
{
    readSettings(roughWallCompat::coeffs(*this));
}


template<class CloudType>
Foam::SommerfeldCollision<CloudType>::SommerfeldCollision
(
    const SommerfeldCollision<CloudType>& cm
)
:
    StochasticCollisionModel<CloudType>(cm),
    settings_(cm.settings_),
    correlation_(cm.correlation_),
    statistics_(cm.statistics_),
    largestProbability_(cm.largestProbability_),
    warnedSplit_(cm.warnedSplit_)
{}


// ************************************************************************* //
