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

#include "roughWallPatchData.H"
#include "roughWallInput.H"
#include "foamCompat.H"
#include "roughWallLimits.hpp"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * * //

const char* const Foam::roughWallPatchData::interactionTypeNames
[
    Foam::roughWallPatchData::nInteractionTypes
] =
{
    "none", "rebound", "stick", "escape", "rough"
};


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::roughWallPatchData::readRough(const dictionary& dict)
{
    using namespace roughWallInput;

    rough_.material.e = readScalar
    (
        dict, "e",
        {0, 1, "normal restitution coefficient of a facet collision"}
    );

    rough_.material.mu0 = readScalar
    (
        dict, "mu0",
        {0, GREAT, "static friction coefficient (no-slip criterion)"}
    );

    // Sliding friction above the static one could reverse the slip
    rough_.material.muD = readScalarOrDefault
    (
        dict, "muD",
        {
            0, rough_.material.mu0,
            "dynamic (sliding) friction coefficient; must not exceed mu0 "
            "(default: mu0)"
        },
        rough_.material.mu0
    );

    // Exactly one of roughnessAngle and roughness
    roughnessAngle_ = roughnessAngleTable(dict);

    // A constant Delta is set once (parameters(d) sets a diameter-dependent
    // one per call)
    rough_.roughnessAngle = roughnessAngle_.value(0);

    rough_.lateralTilt = readSwitchOrDefault
    (
        dict, "lateralTilt",
        "isotropic 3-D roughness: also tilt facets sideways by N(0, Delta) "
        "(default: false; never applied in 2-D)",
        false
    );

    static const std::string maxFacetMeaning =
        "bound on facet collisions per wall hit before a smooth mean-wall "
        "rebound is applied (default: "
      + std::to_string(roughWall::limits::defaultMaxFacetCollisions) + ")";

    rough_.maxFacetCollisions = readLabelOrDefault
    (
        dict, "maxFacetCollisions",
        {
            roughWall::limits::minMaxFacetCollisions,
            roughWall::limits::maxMaxFacetCollisions,
            maxFacetMeaning.c_str()
        },
        roughWall::limits::defaultMaxFacetCollisions
    );
}


void Foam::roughWallPatchData::readRebound(const dictionary& dict)
{
    using namespace roughWallInput;

    // The defaults and the law are standardWallInteraction's
    e_ = readScalarOrDefault
    (
        dict, "e",
        {0, 1, "normal restitution coefficient (default: 1)"},
        1
    );

    mu_ = readScalarOrDefault
    (
        dict, "mu",
        {0, 1, "fraction of the tangential velocity lost (default: 0)"},
        0
    );
}


void Foam::roughWallPatchData::checkUnusedKeywords
(
    const dictionary& dict
) const
{
    wordList used{"type"};
    switch (type_)
    {
        case interactionType::rough:
        {
            used.append
            (
                wordList
                {
                    "e", "mu0", "muD", "roughnessAngle", "roughness",
                    "lateralTilt",
                    "maxFacetCollisions"
                }
            );
            break;
        }
        case interactionType::rebound:
        {
            used.append(wordList{"e", "mu"});
            break;
        }
        default:
        {}
    }

    roughWallInput::checkKeywords(dict, used, string("type ") + name(type_));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::roughWallPatchData::roughWallPatchData()
:
    patchName_(),
    type_(interactionType::none),
    e_(1),
    mu_(0),
    rough_(),
    roughnessAngle_()
{}


Foam::roughWallPatchData::roughWallPatchData
(
    const keyType& patchName,
    const dictionary& dict
)
:
    patchName_(patchName),
    type_(interactionType::none),
    e_(1),
    mu_(0),
    rough_(),
    roughnessAngle_()
{
    const entry* typePtr = roughWallCompat::findLiteral(dict, "type");

    label typei = -1;
    if
    (
        typePtr
     && !typePtr->isDict()
     && typePtr->stream().size() == 1
     && typePtr->stream()[0].isWord()
    )
    {
        const word& typeWord = typePtr->stream()[0].wordToken();
        for (label i = 0; i < nInteractionTypes; ++i)
        {
            if (typeWord == interactionTypeNames[i])
            {
                typei = i;
            }
        }
    }
    const bool knownType = typei >= 0;

    if (!knownType)
    {
        roughWallInput::fatalBadEntry
        (
            dict, "type",
            "one of " + Foam::name(nInteractionTypes)
          + " words: rough rebound stick escape none",
            "what happens to a parcel that hits the patch",
            typePtr
          ? "'" + roughWallInput::entryText(dict, "type") + "'"
          : string("missing")
        );
    }

    type_ = static_cast<interactionType>(typei);

    switch (type_)
    {
        case interactionType::rough:
        {
            readRough(dict);
            break;
        }
        case interactionType::rebound:
        {
            readRebound(dict);
            break;
        }
        default:
        {}
    }

    checkUnusedKeywords(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::roughWallPatchData::writeSummary(Ostream& os) const
{
    os  << name(type_);

    switch (type_)
    {
        case interactionType::rough:
        {
            os  << ": e = " << rough_.material.e
                << ", mu0 = " << rough_.material.mu0
                << ", muD = " << rough_.material.muD
                << ", roughnessAngle = " << roughnessAngle_.description().c_str()
                << ", lateralTilt = "
                << (rough_.lateralTilt ? "true" : "false")
                << ", maxFacetCollisions = " << rough_.maxFacetCollisions;
            break;
        }
        case interactionType::rebound:
        {
            os  << ": e = " << e_ << ", mu = " << mu_;
            break;
        }
        default:
        {}
    }
}


// ************************************************************************* //
