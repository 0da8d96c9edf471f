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

#include "RoughWallInteraction.H"
#include "roughWallInput.H"
#include "foamCompat.H"
#include "coreBridge.H"

#include <type_traits>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
inline void Foam::RoughWallInteraction<CloudType>::watchWallVelocity
(
    const label patchi,
    const vector& Up
)
{
    const scalar speedSqr = magSqr(Up);
    if (speedSqr > wallSpeedSqr_[patchi])
    {
        wallSpeedSqr_[patchi] = speedSqr;
    }
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::watchInPlaneSpin
(
    const label patchi,
    const vector& L
)
{
    if (inPlaneSpin_[patchi] != 0)
    {
        // Seen since the last report, or warned of
        return;
    }
    for (direction cmpt = 0; cmpt < vector::nComponents; ++cmpt)
    {
        if (cmpt != emptyComponent_ && L[cmpt] != 0)
        {
            inPlaneSpin_[patchi] = 1;
        }
    }
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::reportInPlaneSpin()
{
    if (emptyComponent_ < 0 || !withSpin)
    {
        return;
    }

    // Gathered from every processor: a non-master warning would be lost
    scalarList seen(inPlaneSpin_);
    roughWallCompat::maxOverProcessors(seen);

    forAll(seen, patchi)
    {
        if (seen[patchi] > 0 && inPlaneSpin_[patchi] >= 0)
        {
            WarningInFunction
                << "Patch " << stats_.patchName(patchi) << ": parcels arrive"
                << " with spin about an axis in the plane of this 2-D case."
                << " The rough wall keeps only the spin about "
                << vector::componentNames[emptyComponent_] << " and sets"
                << " the other components to zero. Warned once per patch."
                << endl;
        }
        if (seen[patchi] > 0)
        {
            // Warned: never again
            inPlaneSpin_[patchi] = -1;
        }
    }
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::rebound
(
    parcelType& p,
    const polyPatch& pp,
    const roughWallPatchSettings& settings
)
{
    // standardWallInteraction's rebound, term for term
    vector& U = p.U();

    vector nw;
    vector Up;
    this->owner().patchData(p, pp, nw, Up);
    watchWallVelocity(pp.index(), Up);

    // Calculate motion relative to patch velocity
    U -= Up;

    const scalar Un = U & nw;
    const vector Ut = U - Un*nw;

    if (Un > 0)
    {
        U -= (1.0 + settings.e())*Un*nw;
    }

    U -= settings.mu()*Ut;

    // Return velocity to global space
    U += Up;
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::roughRebound
(
    parcelType& p,
    const polyPatch& pp,
    const roughWallPatchSettings& settings
)
{
    vector nw;
    vector Up;
    this->owner().patchData(p, pp, nw, Up);
    watchWallVelocity(pp.index(), Up);

    vector omega(Zero);
    scalar I = 0;
    if constexpr (withSpin)
    {
        I = p.momentOfInertia();
        if (I > 0)
        {
            omega = p.angularMomentum()/I;
            // 2-D: the hit keeps only the spin about the empty direction;
            // in-plane spin is noted here for the one-time warning
            if (emptyComponent_ >= 0)
            {
                watchInPlaneSpin(pp.index(), p.angularMomentum());
            }
        }
    }

    auto& rndGen = this->owner().rndGen();
    cloudUniform01<std::remove_reference_t<decltype(rndGen)>> uniform01(rndGen);

    const roughWall::WallHit hit = settings.hit<withSpin>
    (
        p.U(), omega, Up, nw, p.d(), emptyComponent_, uniform01, pp.name()
    );

    if (!hit.intoWall)
    {
        return;
    }

    // Statistics: the core's k_n, k_t and velocities of the hit, and the
    // energy lost, translational and rotational
    scalar energyLoss = 0.5*p.mass()*hit.speedSqrLoss;
    if constexpr (withSpin)
    {
        p.angularMomentum() = I*omega;
        energyLoss += 0.5*I*hit.spinSqrLoss;
    }

    stats_.addHit(pp.index(), hit, p.nParticle()*energyLoss);

    if (stats_.nBins())
    {
        stats_.addAngles(pp.index(), hit.coefficients, p.U() - Up, nw);
    }
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::reportWallVelocity(Ostream& os)
{
    scalarList speedSqr(wallSpeedSqr_);
    roughWallCompat::maxOverProcessors(speedSqr);

    forAll(speedSqr, patchi)
    {
        const scalar reported = wallSpeedSqrReported_[patchi];

        // A first hit, or a wall faster than reported by more than 1 %
        if (speedSqr[patchi] < 0 || speedSqr[patchi] <= reported*sqr(1.01))
        {
            continue;
        }
        wallSpeedSqrReported_[patchi] = speedSqr[patchi];

        const word& name = stats_.patchName(patchi);
        const scalar speed = sqrt(speedSqr[patchi]);

        os  << "    Wall velocity (patchData) of patch " << name.c_str()
            << ": largest speed " << speed << " m/s"
            << (speed > 0 ? ", the wall moves" : ", at rest") << nl;

        if (speed > 0)
        {
            WarningInFunction
                << "Patch " << name << " moves: the cloud hands "
                << typeName << " a wall velocity of up to " << speed
                << " m/s there, and the parcels rebound from the moving"
                << " wall. A fixedValue velocity condition on a wall patch"
                << " is the wall's own velocity to a cloud. If the wall is"
                << " at rest, give the velocity a condition that fixes no"
                << " non-zero value there (noSlip, slip, zeroGradient,"
                << " calculated)." << endl;
        }
    }
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::readStored()
{
    // The totals stored at the last write time (restart), each patch's by
    // its name; read once: they change only at this run's write times
    roughWallStatistics& stored = stored_;

    stringList exactCounts;
    this->getModelProperty("exactCounts", exactCounts);
    labelList counts;
    if (exactCounts.empty())
    {
        // Restart files written before the counters had 64 bits
        this->getModelProperty("counts", counts);
    }
    if (exactCounts.empty() && counts.empty())
    {
        // Nothing stored: a run from its start
        return;
    }
    if (exactCounts.empty())
    {
        stored.counts().setSize(counts.size());
        forAll(counts, i)
        {
            stored.counts()[i] = counts[i];
        }
    }
    else if (!stored.setExactCounts(exactCounts))
    {
        stored.counts().clear();
    }
    stringList exact;
    this->getModelProperty("exactSums", exact);
    if (exact.empty())
    {
        // Restart files written before the sums were kept exact
        this->getModelProperty("sums", stored.sums());
    }
    else if (!stored.setExactSums(exact))
    {
        stored.sums().clear();
    }
    wordList names;
    this->getModelProperty("patches", names);

    DynamicList<word> dropped;
    const bool placed = stored.placeByName(names, dropped);
    if (!placed || dropped.size())
    {
        WarningInFunction
            << (
                   placed
                 ? "Dropping the stored statistics of patches not in "
                   "this mesh: "
                 : "Ignoring the stored statistics: they do not fit "
                   "their patch names, or (older restart files without "
                   "names) this mesh's patches "
               )
            << dropped << endl;
    }
    if (!placed)
    {
        stored = stats_;
        return;
    }

    // The angle bins (incidenceAngleBins), stored with the totals
    if (stats_.nBins())
    {
        label nBins = 0;
        this->getModelProperty("incidenceAngleBins", nBins);
        stringList binCounts;
        stringList binSums;
        this->getModelProperty("exactBinCounts", binCounts);
        this->getModelProperty("exactBinSums", binSums);
        if (!stored.setExactBins(nBins, binCounts, binSums, names))
        {
            WarningInFunction
                << "The stored statistics hold no angle bins of "
                << stats_.nBins() << " (incidenceAngleBins "
                << nBins << " stored): the bins start from zero, and hold"
                << " the hits since this restart only" << endl;
        }
    }
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::checkCoeffsKeywords() const
{
    // Settings put at the wrong level (e.g. e or lateralTilt outside the
    // patches entries) would be ignored silently. (The base class also
    // reads the name of the velocity field, U, which this model never uses)
    roughWallInput::checkKeywords
    (
        roughWallCompat::coeffs(*this),
        {"patches", "writeToFile", "writePrecision", "incidenceAngleBins"},
        string
        (
            typeName + "Coeffs (the settings of a patch go inside its entry"
            " of patches)"
        )
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RoughWallInteraction<CloudType>::RoughWallInteraction
(
    const dictionary& dict,
    CloudType& cloud
)
:
    PatchInteractionModel<CloudType>(dict, cloud, typeName),
    patches_
    (
        roughWallPatchSettings::readPatches
        (
            roughWallCompat::coeffs(*this),
            roughWallCompat::boundary(cloud.mesh())
        )
    ),
    emptyComponent_(-1),
    stats_
    (
        roughWallCompat::boundary(cloud.mesh()),
        roughWallInput::readNumber<label>
        (
            roughWallCompat::coeffs(*this), "incidenceAngleBins",
            {1, 900},
            0
        )
    ),
    file_(),
    anglesFile_(),
    wallSpeedSqr_(stats_.nPatches(), scalar(-1)),
    wallSpeedSqrReported_(stats_.nPatches(), scalar(-1)),
    stored_(stats_),
    inPlaneSpin_(stats_.nPatches(), scalar(0))
{
    readStored();

    bool anyRough = false;
    for (const roughWallPatchSettings& settings : patches_)
    {
        anyRough = anyRough || settings.type() == interactionType::rough;
    }

    if (anyRough)
    {
        emptyComponent_ = roughWallCompat::emptyComponent(cloud.mesh());

        if (emptyComponent_ >= 0)
        {
            Info<< "    2-D case: no lateral facet tilt, no velocity or spin "
                << "out of the plane normal to "
                << vector::componentNames[emptyComponent_] << nl;

            const polyBoundaryMesh& meshPatches =
                roughWallCompat::boundary(cloud.mesh());
            forAll(patches_, i)
            {
                patches_[i].warnLateralTiltIn2D(meshPatches[i].name());
            }
        }

        Info<< "    Rough-wall parcels carry spin: "
            << (withSpin ? "yes (angularMomentum)" : "no") << nl;
    }

    checkCoeffsKeywords();

    // ESI's base class would write a file of its own when the
    // coefficients say writeToFile: the statistics file replaces it
    if constexpr (roughWallCompat::esi)
    {
        this->writeToFile_ = false;
    }

    const bool writeToFile = roughWallInput::readSwitch
    (
        roughWallCompat::coeffs(*this), "writeToFile", true
    );

    const label precision = roughWallInput::readNumber<label>
    (
        roughWallCompat::coeffs(*this), "writePrecision",
        {1, 17},
        IOstream::defaultPrecision()
    );

    if (writeToFile)
    {
        file_ = roughWallStatistics::openFile
        (
            cloud.mesh(), cloud.name(), patches_, precision
        );
        if (stats_.nBins())
        {
            anglesFile_ =
                stats_.openAnglesFile(cloud.mesh(), cloud.name(), precision);
        }
    }
}


template<class CloudType>
Foam::RoughWallInteraction<CloudType>::RoughWallInteraction
(
    const RoughWallInteraction<CloudType>& pim
)
:
    PatchInteractionModel<CloudType>(pim),
    patches_(pim.patches_),
    emptyComponent_(pim.emptyComponent_),
    stats_(pim.stats_),
    file_(),
    anglesFile_(),
    wallSpeedSqr_(pim.wallSpeedSqr_),
    wallSpeedSqrReported_(pim.wallSpeedSqrReported_),
    stored_(pim.stored_),
    inPlaneSpin_(pim.inPlaneSpin_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
bool Foam::RoughWallInteraction<CloudType>::correct
(
    parcelType& p,
    const polyPatch& pp,
    bool& keepParticle
)
{
    const roughWallPatchSettings& settings = patches_[pp.index()];

    switch (settings.type())
    {
        case interactionType::none:
        {
            return false;
        }
        case interactionType::escape:
        {
            keepParticle = false;
            roughWallCompat::setMoving(p, false);
            p.U() = Zero;
            stats_.addEscape(pp.index(), p.nParticle()*p.mass());
            return true;
        }
        case interactionType::stick:
        {
            keepParticle = true;
            roughWallCompat::setMoving(p, false);
            p.U() = Zero;
            stats_.addStick(pp.index(), p.nParticle()*p.mass());
            return true;
        }
        case interactionType::rebound:
        {
            keepParticle = true;
            roughWallCompat::setMoving(p, true);
            rebound(p, pp, settings);
            return true;
        }
        case interactionType::rough:
        {
            keepParticle = true;
            roughWallCompat::setMoving(p, true);
            roughRebound(p, pp, settings);
            return true;
        }
    }

    return false;
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::info(ROUGHWALL_INFO_PARAMETERS)
{
    // ESI: the system escapes
    PatchInteractionModel<CloudType>::info(ROUGHWALL_INFO_ARGUMENTS);

    // This run's counters of all processors plus the totals stored at the
    // last write time
    roughWallStatistics total(stats_.reduced());
    total += stored_;

    total.write
    (
        ROUGHWALL_INFO_STREAM,
        file_.valid() ? &file_() : nullptr,
        patches_,
        this->owner().mesh().time()
    );

    reportWallVelocity(ROUGHWALL_INFO_STREAM);
    reportInPlaneSpin();
    forAll(patches_, patchi)
    {
        patches_[patchi].reportOutsideRange(stats_.patchName(patchi));
    }

    if (this->writeTime())
    {
        this->setModelProperty("exactCounts", total.exactCounts());
        this->setModelProperty("exactSums", total.exactSums());
        this->setModelProperty("patches", total.patchNames());
        if (total.nBins())
        {
            this->setModelProperty("incidenceAngleBins", total.nBins());
            this->setModelProperty("exactBinCounts", total.exactBinCounts());
            this->setModelProperty("exactBinSums", total.exactBinSums());
            if (anglesFile_.valid())
            {
                total.writeAngles
                (
                    anglesFile_(), patches_, this->owner().mesh().time()
                );
            }
        }
        stored_ = total;
        stats_.reset();
    }
}


// ************************************************************************* //
