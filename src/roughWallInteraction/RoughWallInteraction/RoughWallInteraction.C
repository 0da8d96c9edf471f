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
#include "cloudUniform01.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "wallPolyPatch.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
namespace roughWallAdapter
{

//- OpenFOAM vector to the core's vector
inline roughWall::Vec3 toCore(const vector& v)
{
    return roughWall::Vec3(v.x(), v.y(), v.z());
}

//- The core's vector to an OpenFOAM vector
inline vector toFoam(const roughWall::Vec3& v)
{
    return vector(v.x(), v.y(), v.z());
}

} // End namespace roughWallAdapter
} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::List<Foam::roughWallPatchData>
Foam::RoughWallInteraction<CloudType>::readPatchData(const dictionary& dict)
{
    const char* const allowed =
        "a list ( name { type ...; ... } \"regex\" { ... } ... ) "
        "with at least one entry";
    const char* const meaning =
        "patch names or regular expressions and their interaction settings";

    const entry* eptr = dict.findEntry("patches", keyType::LITERAL);

    if (!eptr || eptr->isDict())
    {
        roughWallInput::fatalBadEntry
        (
            dict, "patches", allowed, meaning,
            eptr ? "a dictionary" : "missing"
        );
    }

    ITstream& is = eptr->stream();
    is.rewind();

    auto fatalList = [&](const string& found)
    {
        roughWallInput::fatalBadEntry(dict, "patches", allowed, meaning, found);
    };

    token t(is);
    if (!(t.isPunctuation() && t.pToken() == token::BEGIN_LIST))
    {
        fatalList("'" + roughWallInput::entryText(dict, "patches") + "'");
    }

    DynamicList<roughWallPatchData> patchData;

    while (true)
    {
        token keyToken(is);

        if (keyToken.isPunctuation() && keyToken.pToken() == token::END_LIST)
        {
            break;
        }
        if (!keyToken.isWord() && !keyToken.isString())
        {
            fatalList
            (
                "'" + roughWallInput::entryText(dict, "patches")
              + "' (expected a patch name or a quoted regular expression)"
            );
        }

        const keyType patchName
        (
            keyToken.isWord()
          ? keyType(keyToken.wordToken())
          : keyType(keyToken.stringToken())
        );

        token blockToken(is);
        if
        (
            !blockToken.isPunctuation()
         || blockToken.pToken() != token::BEGIN_BLOCK
        )
        {
            fatalList
            (
                "'" + roughWallInput::entryText(dict, "patches")
              + "' (expected '{' after " + patchName + ")"
            );
        }
        is.putBack(blockToken);

        // Named after the entry, so that messages point at it
        dictionary patchDict
        (
            fileName("patches." + patchName),
            dict,
            is
        );

        patchData.append(roughWallPatchData(patchName, patchDict));
    }

    if (patchData.empty())
    {
        fatalList("an empty list");
    }

    return List<roughWallPatchData>(std::move(patchData));
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::mapPatches()
{
    const polyBoundaryMesh& bMesh = mesh_.boundaryMesh();

    patchEntry_ = -1;

    // The first entry that matches a patch applies
    forAllReverse(patchData_, entryi)
    {
        const labelList ids(bMesh.indices(patchData_[entryi].patchName()));

        if (ids.empty())
        {
            IOWarningInFunction(this->coeffDict())
                << "No patch matches the patches entry "
                << patchData_[entryi].patchName() << endl;
        }

        for (const label patchi : ids)
        {
            patchEntry_[patchi] = entryi;
        }
    }

    // Particles never reach coupled patches (OpenFOAM transfers them),
    // empty patches or wedges (tracked in the mid-plane)
    DynamicList<word> uncovered;

    forAll(bMesh, patchi)
    {
        const polyPatch& pp = bMesh[patchi];

        if
        (
            pp.coupled()
         || isA<emptyPolyPatch>(pp)
         || isA<wedgePolyPatch>(pp)
        )
        {
            patchEntry_[patchi] = -1;
        }
        else if (patchEntry_[patchi] < 0)
        {
            uncovered.append(pp.name());
        }
    }

    // type none hands the hit back to OpenFOAM, whose hitWallPatch does
    // nothing: the parcel would stay on the wall face for ever (v1912's
    // standardWallInteraction hangs the same way)
    forAll(bMesh, patchi)
    {
        const label entryi = patchEntry_[patchi];
        if
        (
            entryi >= 0
         && patchData_[entryi].type() == interactionType::none
         && isA<wallPolyPatch>(bMesh[patchi])
        )
        {
            roughWallInput::fatalBadEntry
            (
                this->coeffDict(), "patches",
                "rough, rebound, stick or escape on wall patches; none only "
                "on other patches (OpenFOAM's own handling: escape through "
                "a patch, reflection on a symmetry plane)",
                "patch names or regular expressions and their interaction "
                "settings",
                "type none for wall patch " + bMesh[patchi].name()
              + " (OpenFOAM would leave its parcels stuck on the wall)"
            );
        }
    }

    if (uncovered.size())
    {
        string names;
        for (const word& name : uncovered)
        {
            names += (names.empty() ? "" : " ") + name;
        }

        roughWallInput::fatalBadEntry
        (
            this->coeffDict(), "patches",
            "an entry (name or regular expression) for every patch that is "
            "not coupled, empty or wedge",
            "patch names or regular expressions and their interaction "
            "settings",
            "no entry for patch(es) " + names
        );
    }

    // Report the settings
    Info<< "    Patch interactions:" << nl;
    DynamicList<word> keptOnNonWalls;

    forAll(bMesh, patchi)
    {
        const label entryi = patchEntry_[patchi];
        if (entryi < 0)
        {
            continue;
        }

        const roughWallPatchData& data = patchData_[entryi];
        const polyPatch& pp = bMesh[patchi];

        Info<< "        " << pp.name() << ": ";
        data.writeSummary(Info);
        Info<< nl;

        const bool keepsParcels =
            data.type() == interactionType::rough
         || data.type() == interactionType::rebound
         || data.type() == interactionType::stick;

        if
        (
            keepsParcels
         && !isA<wallPolyPatch>(pp)
         && !polyPatch::constraintType(pp.type())
        )
        {
            keptOnNonWalls.append(pp.name());
        }
    }

    // KinematicParcel::hitPatch counts hits on such patches as escapes
    // before the patch interaction model is called
    if (keptOnNonWalls.size())
    {
        WarningInFunction
            << "Patches " << keptOnNonWalls << " are not of type wall but "
            << "keep the parcels that hit them (rough, rebound or stick):"
            << nl << "    OpenFOAM counts every hit on them as an escape in"
            << " the 'Parcel fate: system' line." << endl;
    }
}


template<class CloudType>
Foam::label Foam::RoughWallInteraction<CloudType>::findEmptyComponent() const
{
    if (mesh_.nSolutionD() == 3)
    {
        return -1;
    }

    const Vector<label>& solutionD = mesh_.solutionD();

    if (mesh_.nSolutionD() == 2)
    {
        for (direction cmpt = 0; cmpt < vector::nComponents; ++cmpt)
        {
            if (solutionD[cmpt] == -1)
            {
                return cmpt;
            }
        }
    }

    FatalErrorInFunction
        << "roughWallInteraction needs a 2-D or 3-D mesh; this mesh solves "
        << mesh_.nSolutionD() << " direction(s) (solutionD = " << solutionD
        << ")." << exit(FatalError);

    return -1;
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::constrainToPlane(vector& v) const
{
    if (twoD())
    {
        v[emptyComponent_] = 0;
    }
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::constrainSpinToPlane
(
    vector& omega
) const
{
    // Only spin about the empty direction keeps the motion in the plane
    if (twoD())
    {
        const scalar omegaEmpty = omega[emptyComponent_];
        omega = Zero;
        omega[emptyComponent_] = omegaEmpty;
    }
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::rebound
(
    parcelType& p,
    const polyPatch& pp,
    const roughWallPatchData& data
) const
{
    // standardWallInteraction's rebound, term for term
    vector& U = p.U();

    vector nw;
    vector Up;
    this->owner().patchData(p, pp, nw, Up);

    // Calculate motion relative to patch velocity
    U -= Up;

    const scalar Un = U & nw;
    const vector Ut = U - Un*nw;

    if (Un > 0)
    {
        U -= (1.0 + data.e())*Un*nw;
    }

    U -= data.mu()*Ut;

    // Return velocity to global space
    U += Up;
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::roughRebound
(
    parcelType& p,
    const polyPatch& pp,
    const roughWallPatchData& data
)
{
    using roughWallAdapter::toCore;
    using roughWallAdapter::toFoam;

    vector nw;
    vector Up;
    this->owner().patchData(p, pp, nw, Up);

    // The core's wall normal points into the fluid, OpenFOAM's out of it
    vector n = -nw;
    vector U0 = p.U() - Up;

    if (twoD())
    {
        constrainToPlane(n);
        n /= mag(n);
        constrainToPlane(U0);
    }

    const scalar Un0 = U0 & n;

    // Only parcels moving into the wall are changed
    if (!(Un0 < 0))
    {
        return;
    }

    roughWall::Vec3 v(toCore(U0));
    roughWall::Vec3 omega(roughWall::Vec3::Zero());
    scalar I = 0;

    if constexpr (withSpin)
    {
        I = p.momentOfInertia();
        if (I > 0)
        {
            vector omega0(p.angularMomentum()/I);
            constrainSpinToPlane(omega0);
            omega = toCore(omega0);
        }
    }

    const roughWall::Vec3 omega0(omega);

    vector emptyDirection(Zero);
    if (twoD())
    {
        emptyDirection[emptyComponent_] = 1;
    }

    cloudUniform01 uniform01(this->owner().rndGen());

    const roughWall::RoughWallReport report =
        roughWall::collideWithRoughWall<withSpin>
        (
            v,
            omega,
            toCore(n),
            0.5*p.d(),
            data.parameters(p.d()),
            uniform01,
            toCore(emptyDirection)
        );

    if (!std::isfinite(v.squaredNorm()) || !std::isfinite(omega.squaredNorm()))
    {
        FatalErrorInFunction
            << "Non-finite rebound on patch " << pp.name()
            << " for a parcel of diameter " << p.d()
            << " with velocity " << p.U() << " relative to the wall " << U0
            << " (core result: velocity " << toFoam(v) << ", spin "
            << toFoam(omega) << ")." << exit(FatalError);
    }

    vector U1(toFoam(v));
    constrainToPlane(U1);
    p.U() = U1 + Up;

    scalar rotationalEnergyLoss = 0;

    if constexpr (withSpin)
    {
        vector omega1(toFoam(omega));
        constrainSpinToPlane(omega1);
        p.angularMomentum() = I*omega1;

        rotationalEnergyLoss =
            0.5*I*(omega0.squaredNorm() - magSqr(omega1));
    }

    // Statistics, relative to the wall
    const scalar kn = -(U1 & n)/Un0;

    const vector Ut0 = U0 - Un0*n;
    const scalar magUt0 = mag(Ut0);
    const bool hasKt = magUt0 > SMALL*mag(U0);
    const scalar kt = hasKt ? (U1 & Ut0)/sqr(magUt0) : 0;

    const scalar energyLoss =
        p.nParticle()
       *(
            0.5*p.mass()*(magSqr(U0) - magSqr(U1))
          + rotationalEnergyLoss
        );

    stats_.addHit(pp.index(), report, kn, hasKt, kt, energyLoss);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::writeFileHeader(Ostream& os)
{
    PatchInteractionModel<CloudType>::writeFileHeader(os);

    const wordList roughColumns(roughWallStatistics::roughColumnNames());

    // Processor patches come last and have no statistics
    for (label patchi = 0; patchi < stats_.nPatches(); ++patchi)
    {
        const label entryi = patchEntry_[patchi];
        if (entryi < 0)
        {
            continue;
        }

        const word& patchName = mesh_.boundaryMesh()[patchi].name();

        switch (patchData_[entryi].type())
        {
            case interactionType::escape:
            {
                this->writeTabbed(os, patchName + "_nEscape");
                this->writeTabbed(os, patchName + "_massEscape");
                break;
            }
            case interactionType::stick:
            {
                this->writeTabbed(os, patchName + "_nStick");
                this->writeTabbed(os, patchName + "_massStick");
                break;
            }
            case interactionType::rough:
            {
                for (const word& column : roughColumns)
                {
                    this->writeTabbed(os, patchName + "_" + column);
                }
                break;
            }
            default:
            {}
        }
    }
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
    mesh_(cloud.mesh()),
    patchData_(readPatchData(this->coeffDict())),
    patchEntry_(mesh_.boundaryMesh().size(), -1),
    emptyComponent_(-1),
    stats_(mesh_.boundaryMesh().nNonProcessor())
{
    mapPatches();

    bool anyRough = false;
    for (const roughWallPatchData& data : patchData_)
    {
        anyRough = anyRough || data.type() == interactionType::rough;
    }

    if (anyRough)
    {
        emptyComponent_ = findEmptyComponent();

        Info<< "    Rough-wall parcels carry spin: "
            << (withSpin ? "yes (angularMomentum)" : "no") << nl;

        if (twoD())
        {
            Info<< "    2-D case: no lateral facet tilt, no velocity or spin "
                << "out of the plane normal to "
                << vector::componentNames[emptyComponent_] << nl;
        }
    }

    // Catch settings put at the wrong level (e.g. e or lateralTilt outside
    // the patches entries): they would be ignored silently
    const wordList coeffsKeywords
    {
        "patches", "writeToFile", "writePrecision", "useUserTime", "U"
    };
    for (const entry& e : this->coeffDict())
    {
        if (!coeffsKeywords.found(e.keyword()))
        {
            IOWarningInFunction(this->coeffDict())
                << "Keyword '" << e.keyword().c_str() << "' is not used here;"
                << " used keywords: " << coeffsKeywords
                << ". Settings of a patch go inside its entry of patches."
                << endl;
        }
    }

    // The statistics go to postProcessing/ unless writeToFile is false
    // (the base class does not write by default)
    this->writeToFile_ =
        Pstream::master()
     && roughWallInput::readSwitchOrDefault
        (
            this->coeffDict(), "writeToFile",
            "write the statistics under postProcessing/ (default: true)",
            true
        );

    if (this->writeToFile_ && !this->filePtr_.valid())
    {
        this->filePtr_ = this->createFile(this->fileName_);
    }
}


template<class CloudType>
Foam::RoughWallInteraction<CloudType>::RoughWallInteraction
(
    const RoughWallInteraction<CloudType>& pim
)
:
    PatchInteractionModel<CloudType>(pim),
    mesh_(pim.mesh_),
    patchData_(pim.patchData_),
    patchEntry_(pim.patchEntry_),
    emptyComponent_(pim.emptyComponent_),
    stats_(pim.stats_)
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
    const label patchi = pp.index();
    const label entryi =
        patchi < patchEntry_.size() ? patchEntry_[patchi] : -1;

    // Coupled, empty and wedge patches: OpenFOAM's own handling
    if (entryi < 0)
    {
        return false;
    }

    const roughWallPatchData& data = patchData_[entryi];
    vector& U = p.U();

    switch (data.type())
    {
        case interactionType::none:
        {
            return false;
        }
        case interactionType::escape:
        {
            keepParticle = false;
            p.active(false);
            U = Zero;
            stats_.addEscape(patchi, p.nParticle()*p.mass());
            return true;
        }
        case interactionType::stick:
        {
            keepParticle = true;
            p.active(false);
            U = Zero;
            stats_.addStick(patchi, p.nParticle()*p.mass());
            return true;
        }
        case interactionType::rebound:
        {
            keepParticle = true;
            p.active(true);
            rebound(p, pp, data);
            return true;
        }
        case interactionType::rough:
        {
            keepParticle = true;
            p.active(true);
            roughRebound(p, pp, data);
            return true;
        }
    }

    return false;
}


template<class CloudType>
void Foam::RoughWallInteraction<CloudType>::info(Ostream& os)
{
    // System escapes; writes the file header and the time column
    PatchInteractionModel<CloudType>::info(os);

    // This run's counters of all processors plus the totals stored at the
    // last write time (restart)
    roughWallStatistics total(stats_.reduced());
    {
        roughWallStatistics stored(stats_.nPatches());
        const label nCounts = stored.counts().size();
        const label nSums = stored.sums().size();

        this->getModelProperty("counts", stored.counts());
        this->getModelProperty("sums", stored.sums());

        if
        (
            stored.counts().size() == nCounts
         && stored.sums().size() == nSums
        )
        {
            total += stored;
        }
        else
        {
            WarningInFunction
                << "Ignoring stored statistics of a different patch layout"
                << endl;
        }
    }

    for (label patchi = 0; patchi < total.nPatches(); ++patchi)
    {
        const label entryi = patchEntry_[patchi];
        if (entryi < 0)
        {
            continue;
        }

        const word& patchName = mesh_.boundaryMesh()[patchi].name();
        typedef roughWallStatistics stat;

        switch (patchData_[entryi].type())
        {
            case interactionType::escape:
            {
                os  << "    Parcel fate: patch " << patchName
                    << " (number, mass)" << nl
                    << "      - escape                      = "
                    << total.count(patchi, stat::ESCAPED) << ", "
                    << total.sum(patchi, stat::ESCAPED_MASS) << nl;

                this->file()
                    << tab << total.count(patchi, stat::ESCAPED)
                    << tab << total.sum(patchi, stat::ESCAPED_MASS);
                break;
            }
            case interactionType::stick:
            {
                os  << "    Parcel fate: patch " << patchName
                    << " (number, mass)" << nl
                    << "      - stick                       = "
                    << total.count(patchi, stat::STUCK) << ", "
                    << total.sum(patchi, stat::STUCK_MASS) << nl;

                this->file()
                    << tab << total.count(patchi, stat::STUCK)
                    << tab << total.sum(patchi, stat::STUCK_MASS);
                break;
            }
            case interactionType::rough:
            {
                total.writeRoughLog(os, patchi, patchName);
                total.writeRoughColumns(this->file(), patchi);
                break;
            }
            default:
            {}
        }
    }

    this->file() << endl;

    if (this->writeTime())
    {
        this->setModelProperty("counts", total.counts());
        this->setModelProperty("sums", total.sums());
        stats_.reset();
    }
}


// ************************************************************************* //
