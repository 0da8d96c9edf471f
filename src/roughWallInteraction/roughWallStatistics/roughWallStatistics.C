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

#include "roughWallStatistics.H"
#include "Pstream.H"
#include "PstreamCombineReduceOps.H"
#include "unitConversion.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::roughWallStatistics::roughWallStatistics(const label nPatches)
:
    nPatches_(nPatches),
    counts_(nPatches*nCountTypes, Zero),
    sums_(nPatches*nSumTypes, Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::roughWallStatistics::addHit
(
    const label patchi,
    const roughWall::RoughWallReport& report,
    const scalar kn,
    const bool hasKt,
    const scalar kt,
    const scalar energyLoss
)
{
    label* c = &counts_[patchi*nCountTypes];
    scalar* s = &sums_[patchi*nSumTypes];

    ++c[HITS];
    c[NO_SLIP] += report.noSlip;
    c[SLIDING] += report.sliding;
    c[FALLBACKS] += report.fallback ? 1 : 0;

    s[GAMMA] += radToDeg(report.firstGamma);
    s[KN] += kn;
    s[ENERGY_LOSS] += energyLoss;

    if (hasKt)
    {
        ++c[KT_SAMPLES];
        s[KT] += kt;
    }
}


void Foam::roughWallStatistics::addEscape
(
    const label patchi,
    const scalar mass
)
{
    ++counts_[patchi*nCountTypes + ESCAPED];
    sums_[patchi*nSumTypes + ESCAPED_MASS] += mass;
}


void Foam::roughWallStatistics::addStick
(
    const label patchi,
    const scalar mass
)
{
    ++counts_[patchi*nCountTypes + STUCK];
    sums_[patchi*nSumTypes + STUCK_MASS] += mass;
}


void Foam::roughWallStatistics::operator+=(const roughWallStatistics& other)
{
    forAll(counts_, i)
    {
        counts_[i] += other.counts_[i];
    }
    forAll(sums_, i)
    {
        sums_[i] += other.sums_[i];
    }
}


void Foam::roughWallStatistics::reset()
{
    counts_ = Zero;
    sums_ = Zero;
}


Foam::roughWallStatistics Foam::roughWallStatistics::reduced() const
{
    roughWallStatistics total(*this);

    Pstream::listCombineGather(total.counts_, plusEqOp<label>());
    Pstream::listCombineScatter(total.counts_);

    Pstream::listCombineGather(total.sums_, plusEqOp<scalar>());
    Pstream::listCombineScatter(total.sums_);

    return total;
}


Foam::scalar Foam::roughWallStatistics::facetCollisionsPerHit
(
    const label patchi
) const
{
    return ratio
    (
        count(patchi, NO_SLIP) + count(patchi, SLIDING),
        count(patchi, HITS)
    );
}


Foam::scalar Foam::roughWallStatistics::meanGammaDeg(const label patchi) const
{
    return ratio(sum(patchi, GAMMA), count(patchi, HITS));
}


Foam::scalar Foam::roughWallStatistics::meanKn(const label patchi) const
{
    return ratio(sum(patchi, KN), count(patchi, HITS));
}


Foam::scalar Foam::roughWallStatistics::meanKt(const label patchi) const
{
    return ratio(sum(patchi, KT), count(patchi, KT_SAMPLES));
}


Foam::wordList Foam::roughWallStatistics::roughColumnNames()
{
    return wordList
    {
        "hits", "noSlip", "sliding", "facetPerHit", "fallbacks",
        "meanGamma", "meanKn", "meanKt", "energyLoss"
    };
}


void Foam::roughWallStatistics::writeRoughColumns
(
    Ostream& os,
    const label patchi
) const
{
    os  << tab << count(patchi, HITS)
        << tab << count(patchi, NO_SLIP)
        << tab << count(patchi, SLIDING)
        << tab << facetCollisionsPerHit(patchi)
        << tab << count(patchi, FALLBACKS)
        << tab << meanGammaDeg(patchi)
        << tab << meanKn(patchi)
        << tab << meanKt(patchi)
        << tab << sum(patchi, ENERGY_LOSS);
}


void Foam::roughWallStatistics::writeRoughLog
(
    Ostream& os,
    const label patchi,
    const word& patchName
) const
{
    os  << "    Rough wall: patch " << patchName << nl
        << "      - hits                        = "
        << count(patchi, HITS) << nl
        << "      - facet collisions (no-slip, sliding) = "
        << count(patchi, NO_SLIP) << ", " << count(patchi, SLIDING) << nl
        << "      - facet collisions per hit    = "
        << facetCollisionsPerHit(patchi) << nl
        << "      - hits at the re-collision bound = "
        << count(patchi, FALLBACKS) << nl
        << "      - mean facet tilt gamma [deg] = "
        << meanGammaDeg(patchi) << nl
        << "      - mean k_n, k_t               = "
        << meanKn(patchi) << ", " << meanKt(patchi) << nl
        << "      - kinetic energy loss [J]     = "
        << sum(patchi, ENERGY_LOSS) << nl;
}


// ************************************************************************* //
