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


#include "roughWallPatchSettings.H"
#include "roughWallInput.H"
#include "Tuple2.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "wallPolyPatch.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

ROUGHWALL_NAMED_ENUM
(
    typeNames, Foam::roughWallPatchSettings::interactionType, 5,
    "rough", "rebound", "stick", "escape", "none"
);


// e, mu0, muD, eArgument: facetImpactCoefficients'; roughnessAngle and
// roughness: readRoughness's
const Foam::wordList Foam::roughWallPatchSettings::roughKeywords
{
    "type", "e", "mu0", "muD", "eArgument", "roughnessAngle", "roughness",
    "lateralTilt", "maxFacetCollisions"
};


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
using roughWallInput::joined;

//- An entry of the patches list, read as OpenFOAM-14's LocalInteraction
//- reads its own: a patch name or regular expression, then a dictionary
struct patchEntry
:
    public Tuple2<wordRe, dictionary>
{};

Istream& operator>>(Istream& is, patchEntry& e)
{
    e.first() = wordRe(is);
    e.second() = dictionary(is);
    return is;
}


const char* const patchesAllowed =
    "a list ( name { type ...; ... } \"regex\" { ... } ... ) with an entry "
    "for every patch that is not coupled, empty or wedge; none (OpenFOAM's "
    "own handling of the patch type) only on patches that are not walls";

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::roughWallPatchSettings::roughWallPatchSettings
(
    const wordRe& patchName,
    const dictionary& dict
)
:
    patchName_(patchName),
    type_(roughWallInput::readEnum(dict, "type", typeNames))
{
    // The keywords of the type (the defaults and the law of rebound are
    // standardWallInteraction's), then a stop at any other keyword
    if (type_ == interactionType::rough)
    {
        coefficients_ =
            std::make_shared<const facetImpactCoefficients>(dict, patchName);
        rough_.material = coefficients_->constants();
        impactDependent_ = coefficients_->dependsOnImpact();
        roughness_ = readRoughness(dict);
        rough_.lateralTilt =
            roughWallInput::readSwitch(dict, "lateralTilt", false);
        using namespace roughWall::limits;
        rough_.maxFacetCollisions = roughWallInput::readNumber<label>
        (
            dict, "maxFacetCollisions",
            {minMaxFacetCollisions, maxMaxFacetCollisions},
            defaultMaxFacetCollisions
        );
    }
    else if (type_ == interactionType::rebound)
    {
        e_ = roughWallInput::readNumber<scalar>(dict, "e", {0, 1}, 1);
        mu_ = roughWallInput::readNumber<scalar>(dict, "mu", {0, 1}, 0);
    }
    roughWallInput::checkKeywords
    (
        dict,
        type_ == interactionType::rough ? roughKeywords
      : type_ == interactionType::rebound ? wordList{"type", "e", "mu"}
      : wordList{"type"},
        "type " + word(typeNames[type_])
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::roughWallPatchSettings>
Foam::roughWallPatchSettings::readPatches
(
    const dictionary& coeffs,
    const polyBoundaryMesh& patches
)
{
    // The list of (patch name or regular expression, dictionary), read by
    // OpenFOAM's List, wordRe and dictionary readers
    const List<patchEntry> entries = roughWallInput::read<List<patchEntry>>
    (
        coeffs, "patches", patchesAllowed
    );

    // Each mesh patch gets the first entry that matches it; an entry that
    // matches no patch, or only patches of earlier entries, is never
    // applied (a typo, or the same name twice): warned.  Each dictionary is
    // named after its entry, so that messages point at it
    List<roughWallPatchSettings> result(patches.size());
    boolList covered(patches.size(), false);
    for (const patchEntry& entry : entries)
    {
        const wordRe& name = entry.first();
        dictionary dict(entry.second());
        dict.name() =
            coeffs.name() + roughWallCompat::scopeSeparator + "patches"
          + roughWallCompat::scopeSeparator + name;
        const roughWallPatchSettings settings(name, dict);

        const labelList ids(roughWallCompat::matchingPatches(patches, name));
        DynamicList<word> taken;
        for (const label patchi : ids)
        {
            if (covered[patchi])
            {
                taken.append(patches[patchi].name());
            }
            result[patchi] = covered[patchi] ? result[patchi] : settings;
            covered[patchi] = true;
        }
        if (taken.size() == ids.size())
        {
            IOWarningInFunction(coeffs)
                << "The patches entry " << name << " is never applied: "
                << (
                       ids.empty() ? string("no patch matches it")
                     : "every patch it matches (" + joined(taken)
                     + ") takes an earlier entry (the first entry that "
                       "matches a patch applies)"
                   ).c_str() << endl;
        }
    }

    // Parcels never hit coupled patches (OpenFOAM transfers them), empty
    // patches or wedges (tracked in the mid-plane) as walls.  v1912's
    // KinematicParcel::hitPatch counts hits on a patch that is not a wall
    // as escapes before the patch interaction model is called: warned
    DynamicList<word> uncovered, noneOnWalls, keptOnNonWalls;
    Info<< "    Patch interactions:" << nl;
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        const roughWallPatchSettings& s = result[patchi];
        const bool wall = isA<wallPolyPatch>(pp);
        if (pp.coupled() || isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp))
        {
            result[patchi] = roughWallPatchSettings();
        }
        else if (!covered[patchi])
        {
            uncovered.append(pp.name());
        }
        else
        {
            if (s.type() == interactionType::none && wall)
            {
                noneOnWalls.append(pp.name());
            }
            if (s.keepsParcels() && !wall && !roughWallCompat::isConstraint(pp))
            {
                keptOnNonWalls.append(pp.name());
            }
            Info<< "        " << pp.name() << ": " << s << nl;
        }
    }

    if (entries.empty() || uncovered.size() || noneOnWalls.size())
    {
        roughWallInput::fatalBadEntry
        (
            coeffs, "patches", patchesAllowed,
            entries.empty() ? "an empty list"
          : uncovered.size() ? "no entry for patch(es) " + joined(uncovered)
          : "type none for wall patch(es) " + joined(noneOnWalls)
          + ": OpenFOAM would leave their parcels stuck on the wall"
        );
    }
    if (roughWallCompat::esi && keptOnNonWalls.size())
    {
        WarningInFunction
            << "Patches " << keptOnNonWalls << " are not of type wall but "
            << "keep the parcels that hit them (rough, rebound or stick):"
            << nl << "    OpenFOAM v1912 counts every hit on them as an escape"
            << " in the 'Parcel fate: system' line." << endl;
    }

    return result;
}


void Foam::roughWallPatchSettings::warnLateralTiltIn2D(const word& patch) const
{
    if (type_ == interactionType::rough && rough_.lateralTilt)
    {
        WarningInFunction
            << "Patch " << patch << " (entry " << patchName_ << "): "
            << "lateralTilt true has no effect on this 2-D mesh: its facets "
            << "are tilted in the plane of the mesh only" << endl;
    }
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * //

Foam::Ostream& Foam::operator<<(Ostream& os, const roughWallPatchSettings& s)
{
    os  << typeNames[s.type_];
    if (s.type_ == roughWallPatchSettings::interactionType::rough)
    {
        os  << ": " << *s.coefficients_
            << ", roughnessAngle = " << s.roughness_.describe().c_str()
            << ", lateralTilt = " << (s.rough_.lateralTilt ? "true" : "false")
            << ", maxFacetCollisions = " << s.rough_.maxFacetCollisions;
    }
    else if (s.type_ == roughWallPatchSettings::interactionType::rebound)
    {
        os  << ": e = " << s.e_ << ", mu = " << s.mu_;
    }
    return os;
}


// ************************************************************************* //
