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

#include "roughVelocityLagrangianPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "LagrangianMesh.H"
#include "LagrangianFields.H"
#include "roughWallInput.H"
#include "coreBridge.H"

#include <cstdint>
#include <cstring>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
namespace
{

//- SplitMix64's finaliser: a bijective mix of 64 bits
inline uint64_t mix64(uint64_t x)
{
    x += UINT64_C(0x9e3779b97f4a7c15);
    x = (x ^ (x >> 30))*UINT64_C(0xbf58476d1ce4e5b9);
    x = (x ^ (x >> 27))*UINT64_C(0x94d049bb133111eb);
    return x ^ (x >> 31);
}

//- Fold a value into a hash
inline uint64_t combine(const uint64_t h, const uint64_t x)
{
    return mix64(h ^ mix64(x));
}

//- The bits of a double, as a number to hash
inline uint64_t bits(const double x)
{
    uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

//- The core's uniform01(): a SplitMix64 stream from a seed, values in
//  [0, 1) with 53 random bits.  A counter-based generator: the draws of a
//  hit depend on its seed only, not on how many hits or evaluations came
//  before
class hitUniform01
{
    uint64_t state_;

public:

    explicit hitUniform01(const uint64_t seed)
    :
        state_(seed)
    {}

    double operator()()
    {
        state_ += UINT64_C(0x9e3779b97f4a7c15);
        uint64_t z = state_;
        z = (z ^ (z >> 30))*UINT64_C(0xbf58476d1ce4e5b9);
        z = (z ^ (z >> 27))*UINT64_C(0x94d049bb133111eb);
        z ^= z >> 31;
        return double(z >> 11)*0x1.0p-53;
    }
};

} // End anonymous namespace
} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary
Foam::roughVelocityLagrangianPatchVectorField::coeffsDict
(
    const dictionary& dict
)
{
    // A copy keeps the dictionary's name: messages name the file and entry
    dictionary coeffs(dict);
    coeffs.remove("type");
    coeffs.remove("patchType");

    // The keywords of this condition (type rough's and d), checked here so
    // that the message names this condition's, not the parcel model's
    wordList used(roughWallPatchSettings::roughKeywords);
    used.append("d");
    roughWallInput::checkKeywords(coeffs, used, string("type ") + typeName);

    return coeffs;
}


Foam::dictionary
Foam::roughVelocityLagrangianPatchVectorField::roughDict
(
    const dictionary& coeffs
)
{
    dictionary rough(coeffs);
    rough.remove("d");
    rough.add("type", word("rough"));
    return rough;
}


Foam::scalar Foam::roughVelocityLagrangianPatchVectorField::readDiameter
(
    const dictionary& coeffs
)
{
    if (!roughWallCompat::findLiteral(coeffs, "d"))
    {
        return -1;
    }

    return roughWallInput::readNumber<scalar>(coeffs, "d", {1e-9, 1});
}


Foam::tmp<Foam::scalarField>
Foam::roughVelocityLagrangianPatchVectorField::diameters() const
{
    const LagrangianSubMesh& subMesh = patch().mesh();

    if (d_ > 0)
    {
        return tmp<scalarField>(new scalarField(subMesh.size(), d_));
    }

    const LagrangianMesh& mesh = subMesh.mesh();

    if (!mesh.foundObject<LagrangianScalarDynamicField>("d"))
    {
        FatalErrorInFunction
            << "Patch " << patch().name() << " of field "
            << internalField().name() << " of cloud " << mesh.name()
            << " has type " << typeName << ", which needs the particle"
            << " diameter, but the cloud has no field d (a spherical cloud"
            << " reads it from 0/Lagrangian/" << mesh.name() << "/d)."
            << " Use a spherical cloud, or give the diameter in the"
            << " condition: d <diameter [m]>;" << exit(FatalError);
    }

    const LagrangianScalarDynamicField& d =
        mesh.lookupObject<LagrangianScalarDynamicField>("d");

    return tmp<scalarField>(new scalarField(subMesh.sub(d.primitiveField())));
}


uint64_t Foam::roughVelocityLagrangianPatchVectorField::hitSeed
(
    const label i
) const
{
    const LagrangianMesh& mesh = patch().mesh().mesh();

    uint64_t h = mix64(Hash<word>()(patch().name()));
    h = combine(h, uint64_t(db().time().timeIndex()));
    h = combine(h, uint64_t(Pstream::myProcNo()));

    // The particle's identity: where it hits.  Not where it started the
    // step: the mesh's old-time positions are in the order of the start of
    // the step while partitioning has reordered the particles since, and
    // the final outer corrector clears them before it tracks
    // (LagrangianMesh::reset).  Outer correctors reach the same hit, and so
    // draw the same, unless the carrier moved the particle before it
    const barycentric& c = mesh.coordinates()[i];

    h = combine(h, uint64_t(mesh.celli()[i]));
    for (direction cmpt = 0; cmpt < barycentric::nComponents; ++cmpt)
    {
        h = combine(h, bits(c[cmpt]));
    }

    // The face hit: a particle that hits two faces in one step draws anew
    h = combine(h, uint64_t(mesh.facei()[i]));

    return h;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::roughVelocityLagrangianPatchVectorField::
roughVelocityLagrangianPatchVectorField
(
    const LagrangianPatch& p,
    const regIOobject& iIo,
    const dictionary& dict
)
:
    cloudVelocityLagrangianPatchVectorField(p, iIo, dict),
    coeffs_(coeffsDict(dict)),
    rough_(keyType(p.name()), roughDict(coeffs_)),
    d_(readDiameter(coeffs_))
{
    const polyMesh& mesh = roughWallCompat::polyMeshOf(p.boundaryMesh().mesh());
    if (roughWallCompat::emptyComponent(mesh) >= 0)
    {
        rough_.warnLateralTiltIn2D(p.name());
    }
}


Foam::roughVelocityLagrangianPatchVectorField::
roughVelocityLagrangianPatchVectorField
(
    const roughVelocityLagrangianPatchVectorField& ptf
)
:
    cloudVelocityLagrangianPatchVectorField(ptf),
    coeffs_(ptf.coeffs_),
    rough_(ptf.rough_),
    d_(ptf.d_)
{}


Foam::roughVelocityLagrangianPatchVectorField::
roughVelocityLagrangianPatchVectorField
(
    const roughVelocityLagrangianPatchVectorField& ptf,
    const regIOobject& iIo
)
:
    cloudVelocityLagrangianPatchVectorField(ptf, iIo),
    coeffs_(ptf.coeffs_),
    rough_(ptf.rough_),
    d_(ptf.d_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::roughVelocityLagrangianPatchVectorField::evaluate
(
    PstreamBuffers& pBufs,
    const ROUGHWALL_LAGRANGIAN_FRACTION& fraction
)
{
    cloudVelocityLagrangianPatchVectorField::evaluate(pBufs, fraction);

    const LagrangianSubMesh& subMesh = patch().mesh();

    // Checked on every evaluation, hit or not: a cloud without d stops at
    // its first step, not at its first wall hit
    const tmp<scalarField> td(diameters());

    if (!subMesh.empty())
    {
        hit(td(), fraction);
    }

    // Every processor evaluates every patch: the warning of diameters
    // outside an envelope's range is gathered here
    rough_.reportOutsideRange(patch().name());
}


void Foam::roughVelocityLagrangianPatchVectorField::hit
(
    const scalarField& d,
    const ROUGHWALL_LAGRANGIAN_FRACTION& fraction
)
{
    const LagrangianSubMesh& subMesh = patch().mesh();
    const vectorField nf(subMesh.nf<vectorField>(fraction));
    const vectorField Uf(subMesh.Uf<vectorField>(fraction));
    const label emptyCmpt = roughWallCompat::emptyComponent
    (
        roughWallCompat::polyMeshOf(subMesh.mesh())
    );

    vectorField U1(primitiveSubField());

    forAll(U1, subi)
    {
        // No spin in this library: the core's spin-free path
        vector spin(Zero);
        hitUniform01 uniform01(hitSeed(subi + subMesh.start()));

        rough_.hit<false>
        (
            U1[subi], spin, Uf[subi], nf[subi], d[subi], emptyCmpt,
            uniform01, patch().name()
        );
    }

    LagrangianPatchVectorField::operator=(U1);
}


void Foam::roughVelocityLagrangianPatchVectorField::write(Ostream& os) const
{
    cloudVelocityLagrangianPatchVectorField::write(os);

    // The entries as given, so that a written field reads back the same
    forAllConstIter(dictionary, coeffs_, iter)
    {
        os  << *iter;
    }
}


Foam::LagrangianState
Foam::roughVelocityLagrangianPatchVectorField::state() const
{
    return LagrangianState::inCell;
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makeLagrangianPatchTypeField
    (
        LagrangianPatchVectorField,
        roughVelocityLagrangianPatchVectorField
    );
}


// ************************************************************************* //
