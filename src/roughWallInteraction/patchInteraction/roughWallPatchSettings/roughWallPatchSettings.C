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
#include "roughnessAngleInput.H"
#include "foamCompat.H"
#include "limitsAndUnits.hpp"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "wallPolyPatch.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

typedef roughWallPatchSettings settings;


//- The names as one space-separated string, for messages
string joined(const DynamicList<word>& names)
{
    string s;
    for (const word& name : names)
    {
        s += (s.empty() ? "" : " ") + name;
    }
    return s;
}


const char* const patchesMeaning =
    "patch names or regular expressions and their interaction settings";

} // End anonymous namespace


// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * * //

// The keywords of each type: read in this order (muD's range is [0, mu0]),
// checked against the dictionary, written in the summary.  The defaults and
// the law of rebound are standardWallInteraction's.
#define ROUGHWALL_READ(member, how)                                            \
    [](settings& s, const dictionary& d) { s.member = how; }
#define ROUGHWALL_WRITE(value)                                                 \
    [](const settings& s, Ostream& os) { os << value; }

const Foam::roughWallPatchSettings::typeEntry
Foam::roughWallPatchSettings::types[5] =
{
    {"rough", {
        {
            // e, mu0, muD: numbers, or Function1s of the facet impact
            "e",
            [](settings& s, const dictionary& d)
            {
                s.coefficients_ =
                    std::make_shared<const facetImpactCoefficients>
                    (
                        d, word(s.patchName_)
                    );
                s.rough_.material = s.coefficients_->constants();
                s.impactDependent_ = s.coefficients_->dependsOnImpact();
            },
            ROUGHWALL_WRITE(s.coefficients_->description("e").c_str())
        },
        {
            "mu0", nullptr,
            ROUGHWALL_WRITE(s.coefficients_->description("mu0").c_str())
        },
        {
            "muD", nullptr,
            ROUGHWALL_WRITE(s.coefficients_->description("muD").c_str())
        },
        {"eArgument", nullptr, nullptr},     // read with e
        {
            "roughnessAngle",
            ROUGHWALL_READ(roughness_, roughnessAngleInput::read(d)),
            ROUGHWALL_WRITE(s.roughness_.describe().c_str())
        },
        {"roughness", nullptr, nullptr},    // read with roughnessAngle
        {
            "lateralTilt",
            ROUGHWALL_READ(rough_.lateralTilt, roughWallInput::readSwitch
            (
                d, "lateralTilt",
                "isotropic 3-D roughness: also tilt facets sideways by "
                "N(0, Delta) (default: false; never applied in 2-D)",
                false
            )),
            ROUGHWALL_WRITE((s.rough_.lateralTilt ? "true" : "false"))
        },
        {
            "maxFacetCollisions",
            ROUGHWALL_READ
            (
                rough_.maxFacetCollisions,
                roughWallInput::readNumber<label>
                (
                    d, "maxFacetCollisions",
                    {
                        roughWall::limits::minMaxFacetCollisions,
                        roughWall::limits::maxMaxFacetCollisions,
                        "bound on facet collisions per wall hit before a "
                        "smooth mean-wall rebound is applied (default: 10)"
                    },
                    roughWall::limits::defaultMaxFacetCollisions
                )
            ),
            ROUGHWALL_WRITE(s.rough_.maxFacetCollisions)
        }
    }},
    {"rebound", {
        {
            "e",
            ROUGHWALL_READ(e_, roughWallInput::readNumber<scalar>(d, "e",
                {0, 1, "normal restitution coefficient (default: 1)"}, 1)),
            ROUGHWALL_WRITE(s.e_)
        },
        {
            "mu",
            ROUGHWALL_READ(mu_, roughWallInput::readNumber<scalar>(d, "mu",
                {0, 1, "fraction of the tangential velocity lost (default: 0)"},
                0)),
            ROUGHWALL_WRITE(s.mu_)
        }
    }},
    {"stick", {}},
    {"escape", {}},
    {"none", {}}
};

#undef ROUGHWALL_READ
#undef ROUGHWALL_WRITE

static_assert
(
    roughWall::limits::defaultMaxFacetCollisions == 10,
    "the meaning of maxFacetCollisions names its default"
);


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::roughWallPatchSettings::warnOutside(const scalar d) const
{
    if (!warnedRange_)
    {
        warnedRange_ = true;
        const roughWall::EnvelopeAngleTable& envelope =
            roughness_.envelopeTable();
        WarningInFunction
            << "Patch entry " << patchName_ << ": a parcel of diameter " << d
            << " m hit the wall, outside the diameters " << envelope.dMin()
            << " to " << envelope.dMax() << " m for which Delta(d_p) of the "
            << roughness_.source().c_str() << " is tabulated;" << nl
            << "    Delta is held at its value at the nearer end (this "
            << "warning is given once for each mesh patch the entry covers, "
            << "on each processor)" << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::roughWallPatchSettings::roughWallPatchSettings()
:
    patchName_(),
    type_(interactionType::none),
    e_(1),
    mu_(0),
    rough_(),
    roughness_(),
    coefficients_(),
    impactDependent_(false),
    warnedRange_(false)
{}


Foam::roughWallPatchSettings::roughWallPatchSettings
(
    const keyType& patchName,
    const dictionary& dict
)
:
    roughWallPatchSettings()
{
    patchName_ = patchName;

    wordList typeNames;
    for (const typeEntry& t : types)
    {
        typeNames.append(t.name);
    }
    const label typei = roughWallInput::readChoice
    (
        dict, "type", typeNames, "what happens to a parcel that hits the patch"
    );
    type_ = interactionType(typei);

    // Read every keyword of the type, then stop at any other keyword
    for (const keyword& k : types[typei].keywords)
    {
        if (k.read)
        {
            k.read(*this, dict);
        }
    }
    wordList used{"type"};
    used.append(keywords(type_));

    roughWallInput::checkKeywords(dict, used, string("type ") + typeName());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::roughWallPatchSettings>
Foam::roughWallPatchSettings::readPatches
(
    const dictionary& coeffs,
    const polyBoundaryMesh& patches
)
{
    // The list of (patch name or regular expression, dictionary): each
    // dictionary read by OpenFOAM's reader, named after its entry so that
    // messages point at it
    auto fatalList = [&](const string& found)
    {
        roughWallInput::fatalBadEntry
        (
            coeffs, "patches",
            "a list ( name { type ...; ... } \"regex\" { ... } ... ) "
            "with at least one entry",
            patchesMeaning, found
        );
    };

    const entry* eptr = roughWallCompat::findLiteral(coeffs, "patches");
    if (!eptr || eptr->isDict())
    {
        fatalList(eptr ? "a dictionary" : "missing");
    }

    const string listText =
        "'" + roughWallInput::entryText(coeffs, "patches") + "'";
    ITstream& is = eptr->stream();
    is.rewind();

    DynamicList<roughWallPatchSettings> entries;
    token t(is);
    if (!t.isPunctuation() || t.pToken() != token::BEGIN_LIST)
    {
        fatalList(listText);
    }
    for
    (
        t = token(is);
        !t.isPunctuation() || t.pToken() != token::END_LIST;
        t = token(is)
    )
    {
        if (!t.isWord() && !t.isString())
        {
            fatalList
            (
                listText
              + " (expected a patch name or a quoted regular expression)"
            );
        }
        const keyType name
        (
            t.isWord() ? keyType(t.wordToken()) : keyType(t.stringToken())
        );

        const token brace(is);
        if (!brace.isPunctuation() || brace.pToken() != token::BEGIN_BLOCK)
        {
            fatalList(listText + " (expected '{' after " + name + ")");
        }
        is.putBack(brace);

        const fileName dictName
        (
            "patches" + (roughWallCompat::scopeSeparator + name)
        );
        entries.append
        (
            roughWallPatchSettings(name, dictionary(dictName, coeffs, is))
        );
    }
    if (entries.empty())
    {
        fatalList("an empty list");
    }

    // The entry ends at its ';': tokens after the list's ')' (an entry
    // written after it, say) would be ignored silently
    if (is.tokenIndex() < is.size())
    {
        fatalList
        (
            listText + " (tokens after the list's closing ')': '"
          + roughWallInput::tokensText(is, is.tokenIndex()) + "')"
        );
    }

    // Each mesh patch gets the first entry that matches it; an entry that
    // matches no patch, or only patches of earlier entries, is never
    // applied (a typo, or the same name twice): warned
    List<roughWallPatchSettings> result(patches.size());
    boolList covered(patches.size(), false);
    forAll(entries, entryi)
    {
        const keyType& name = entries[entryi].patchName();

        // OpenFOAM stops at a bad regular expression without naming the
        // keyword or the file: caught
        labelList ids;
        string error;
        if
        (
            !roughWallCompat::callCatching
            (
                [&]()
                {
                    ids = roughWallCompat::matchingPatches(patches, name);
                },
                error
            )
        )
        {
            fatalList
            (
                listText + " (entry \"" + name + "\": " + error + ")"
            );
        }

        DynamicList<word> taken;
        bool applied = false;
        for (const label patchi : ids)
        {
            if (covered[patchi])
            {
                taken.append(patches[patchi].name());
                continue;
            }
            result[patchi] = entries[entryi];
            covered[patchi] = true;
            applied = true;
        }
        if (ids.empty())
        {
            IOWarningInFunction(coeffs)
                << "No patch matches the patches entry "
                << name << endl;
        }
        else if (!applied)
        {
            IOWarningInFunction(coeffs)
                << "The patches entry " << name << " is never applied: "
                << "every patch it matches (" << joined(taken).c_str()
                << ") takes an earlier entry (the first entry that matches "
                << "a patch applies)" << endl;
        }
    }

    // Parcels never hit coupled patches (OpenFOAM transfers them), empty
    // patches or wedges (tracked in the mid-plane) as walls
    DynamicList<word> uncovered;
    DynamicList<word> noneOnWalls;
    DynamicList<word> keptOnNonWalls;

    Info<< "    Patch interactions:" << nl;
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        const roughWallPatchSettings& s = result[patchi];

        if (pp.coupled() || isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp))
        {
            result[patchi] = roughWallPatchSettings();
            continue;
        }
        if (!covered[patchi])
        {
            uncovered.append(pp.name());
            continue;
        }
        if (s.type() == interactionType::none && isA<wallPolyPatch>(pp))
        {
            noneOnWalls.append(pp.name());
        }
        if
        (
            s.keepsParcels()
         && !isA<wallPolyPatch>(pp)
         && !roughWallCompat::isConstraint(pp)
        )
        {
            keptOnNonWalls.append(pp.name());
        }

        Info<< "        " << pp.name() << ": ";
        s.writeSummary(Info);
        Info<< nl;
    }

    if (noneOnWalls.size())
    {
        roughWallInput::fatalBadEntry
        (
            coeffs, "patches",
            "rough, rebound, stick or escape on wall patches; none only on "
            "other patches (OpenFOAM's own handling: escape through a patch, "
            "reflection on a symmetry plane)",
            patchesMeaning,
            "type none for wall patch(es) " + joined(noneOnWalls)
          + " (OpenFOAM would leave their parcels stuck on the wall)"
        );
    }
    if (uncovered.size())
    {
        roughWallInput::fatalBadEntry
        (
            coeffs, "patches",
            "an entry (name or regular expression) for every patch that is "
            "not coupled, empty or wedge",
            patchesMeaning,
            "no entry for patch(es) " + joined(uncovered)
        );
    }

    // v1912's KinematicParcel::hitPatch counts hits on such patches as
    // escapes before the patch interaction model is called
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


Foam::wordList Foam::roughWallPatchSettings::keywords
(
    const interactionType type
)
{
    wordList names;
    for (const keyword& k : types[label(type)].keywords)
    {
        names.append(k.name);
    }
    return names;
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


void Foam::roughWallPatchSettings::writeSummary(Ostream& os) const
{
    os  << typeName();

    const char* separator = ": ";
    for (const keyword& k : types[label(type_)].keywords)
    {
        if (k.write)
        {
            os  << separator << k.name << " = ";
            k.write(*this, os);
            separator = ", ";
        }
    }
}


// ************************************************************************* //
