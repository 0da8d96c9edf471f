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

#include "roughWallPatchList.H"
#include "roughWallInput.H"
#include "foamCompat.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "wallPolyPatch.H"
#include "processorPolyPatch.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

const char* const patchesMeaning =
    "patch names or regular expressions and their interaction settings";


//- The names as one space-separated string, for messages
Foam::string joined(const Foam::DynamicList<Foam::word>& names)
{
    Foam::string s;
    for (const Foam::word& name : names)
    {
        s += (s.empty() ? "" : " ") + name;
    }
    return s;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<Foam::roughWallPatchData>
Foam::roughWallPatchList::readEntries(const dictionary& coeffs)
{
    const char* const allowed =
        "a list ( name { type ...; ... } \"regex\" { ... } ... ) "
        "with at least one entry";

    const entry* eptr = roughWallCompat::findLiteral(coeffs, "patches");

    if (!eptr || eptr->isDict())
    {
        roughWallInput::fatalBadEntry
        (
            coeffs, "patches", allowed, patchesMeaning,
            eptr ? "a dictionary" : "missing"
        );
    }

    auto fatalList = [&](const string& found)
    {
        roughWallInput::fatalBadEntry
        (
            coeffs, "patches", allowed, patchesMeaning, found
        );
    };

    const string listText =
        "'" + roughWallInput::entryText(coeffs, "patches") + "'";

    ITstream& is = eptr->stream();
    is.rewind();

    token t(is);
    if (!(t.isPunctuation() && t.pToken() == token::BEGIN_LIST))
    {
        fatalList(listText);
    }

    DynamicList<roughWallPatchData> entries;

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
                listText
              + " (expected a patch name or a quoted regular expression)"
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
                listText + " (expected '{' after " + patchName + ")"
            );
        }
        is.putBack(blockToken);

        // Named after the entry, so that messages point at it (scopes are
        // joined by '.' on v1912, by '/' on the Foundation releases)
        const dictionary entryDict
        (
            fileName
            (
                string("patches") + (roughWallCompat::esi ? "." : "/")
              + patchName
            ),
            coeffs,
            is
        );

        entries.append(roughWallPatchData(patchName, entryDict));
    }

    if (entries.empty())
    {
        fatalList("an empty list");
    }

    List<roughWallPatchData> result;
    result.transfer(entries);
    return result;
}


void Foam::roughWallPatchList::mapPatches
(
    const dictionary& coeffs,
    const polyBoundaryMesh& bm
)
{
    // The first entry that matches a patch applies
    forAllReverse(entries_, entryi)
    {
        const labelList ids
        (
            roughWallCompat::matchingPatches(bm, entries_[entryi].patchName())
        );

        if (ids.empty())
        {
            IOWarningInFunction(coeffs)
                << "No patch matches the patches entry "
                << entries_[entryi].patchName() << endl;
        }

        for (const label patchi : ids)
        {
            patchEntry_[patchi] = entryi;
        }
    }

    // Parcels never hit coupled patches (OpenFOAM transfers them), empty
    // patches or wedges (tracked in the mid-plane) as walls
    DynamicList<word> uncovered;
    DynamicList<word> noneOnWalls;

    forAll(bm, patchi)
    {
        const polyPatch& pp = bm[patchi];

        if (pp.coupled() || isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp))
        {
            patchEntry_[patchi] = -1;
        }
        else if (patchEntry_[patchi] < 0)
        {
            uncovered.append(pp.name());
        }
        else if
        (
            type(patchi) == interactionType::none
         && isA<wallPolyPatch>(pp)
        )
        {
            noneOnWalls.append(pp.name());
        }
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
}


Foam::label Foam::roughWallPatchList::findEmptyComponent(const polyMesh& mesh)
{
    if (mesh.nSolutionD() == 3)
    {
        return -1;
    }

    const Vector<label>& solutionD = mesh.solutionD();

    if (mesh.nSolutionD() == 2)
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
        << mesh.nSolutionD() << " direction(s) (solutionD = " << solutionD
        << ")." << exit(FatalError);

    return -1;
}


void Foam::roughWallPatchList::report(const polyBoundaryMesh& bm) const
{
    Info<< "    Patch interactions:" << nl;
    DynamicList<word> keptOnNonWalls;

    forAll(bm, patchi)
    {
        const roughWallPatchData* data = find(patchi);
        if (!data)
        {
            continue;
        }

        Info<< "        " << bm[patchi].name() << ": ";
        data->writeSummary(Info);
        Info<< nl;

        const bool keepsParcels =
            data->type() == interactionType::rough
         || data->type() == interactionType::rebound
         || data->type() == interactionType::stick;

        if
        (
            keepsParcels
         && !isA<wallPolyPatch>(bm[patchi])
         && !roughWallCompat::isConstraint(bm[patchi])
        )
        {
            keptOnNonWalls.append(bm[patchi].name());
        }
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
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::roughWallPatchList::roughWallPatchList
(
    const dictionary& coeffs,
    const polyMesh& mesh
)
:
    entries_(readEntries(coeffs)),
    patchEntry_(roughWallCompat::boundary(mesh).size(), -1),
    patchNames_(roughWallCompat::boundary(mesh).names()),
    nNonProcessor_(roughWallCompat::boundary(mesh).size()),
    emptyComponent_(-1)
{
    // OpenFOAM puts the processor patches last
    forAll(roughWallCompat::boundary(mesh), patchi)
    {
        if (isA<processorPolyPatch>(roughWallCompat::boundary(mesh)[patchi]))
        {
            nNonProcessor_ = patchi;
            break;
        }
    }

    mapPatches(coeffs, roughWallCompat::boundary(mesh));
    report(roughWallCompat::boundary(mesh));

    if (anyRough())
    {
        emptyComponent_ = findEmptyComponent(mesh);

        if (emptyComponent_ >= 0)
        {
            Info<< "    2-D case: no lateral facet tilt, no velocity or spin "
                << "out of the plane normal to "
                << vector::componentNames[emptyComponent_] << nl;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::roughWallPatchList::anyRough() const
{
    for (const roughWallPatchData& data : entries_)
    {
        if (data.type() == interactionType::rough)
        {
            return true;
        }
    }
    return false;
}


// ************************************************************************* //
