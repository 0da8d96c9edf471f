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
#include "processorPolyPatch.H"
#include "foamCompat.H"
#include "Time.H"
#include "OSspecific.H"
#include "limitsAndUnits.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::roughWallStatistics::roughWallStatistics
(
    const polyBoundaryMesh& patches,
    const label nBins
)
:
    patchNames_(patches.names()),
    nPatches_(0),
    counts_(),
    sums_(),
    nBins_(nBins),
    binCounts_(),
    binSums_()
{
    while
    (
        nPatches_ < patches.size()
     && !isA<processorPolyPatch>(patches[nPatches_])
    )
    {
        ++nPatches_;
    }
    patchNames_.setSize(nPatches_);
    counts_.setSize(nPatches_*nCountTypes, int64_t(0));
    sums_.setSize(nPatches_*nSumTypes, 0);
    binCounts_.setSize(nPatches_*nBins_*nBinCountTypes, int64_t(0));
    binSums_.setSize(nPatches_*nBins_*nBinSumTypes, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

namespace
{

//- Integers as text (v1912 writes a 64-bit integer through a 32-bit label)
Foam::stringList integerText(const Foam::List<int64_t>& values)
{
    Foam::stringList text(values.size());
    forAll(values, i)
    {
        text[i] = std::to_string(values[i]);
    }
    return text;
}


//- Integers from integerText's text; false if a text is not one
bool integersFromText
(
    const Foam::stringList& text,
    Foam::List<int64_t>& values
)
{
    Foam::List<int64_t> read(text.size());
    forAll(text, i)
    {
        char* end = nullptr;
        errno = 0;
        read[i] = std::strtoll(text[i].c_str(), &end, 10);
        if (end == text[i].c_str() || *end != '\0' || errno == ERANGE)
        {
            return false;
        }
    }
    values.transfer(read);
    return true;
}


//- Numbers as text of 17 significant digits: the shortest that gives back
//- every double
Foam::stringList exactText(const Foam::scalarList& values)
{
    Foam::stringList text(values.size());
    char buffer[32];
    forAll(values, i)
    {
        std::snprintf(buffer, sizeof(buffer), "%.17g", values[i]);
        text[i] = buffer;
    }
    return text;
}


//- Numbers from exactText's text; false if a text is not one
bool numbersFromText(const Foam::stringList& text, Foam::scalarList& values)
{
    Foam::scalarList read(text.size());
    forAll(text, i)
    {
        char* end = nullptr;
        read[i] = std::strtod(text[i].c_str(), &end);
        if (end == text[i].c_str() || *end != '\0')
        {
            return false;
        }
    }
    values.transfer(read);
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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


void Foam::roughWallStatistics::addAngles
(
    const label patchi,
    const roughWall::WallHitCoefficients& k,
    const vector& Ur,
    const vector& nw
)
{
    const label first = patchi*nBins_;
    const label bini = first + angleBin(std::atan2(k.vnIn, k.vtIn));
    int64_t* c = &binCounts_[bini*nBinCountTypes];
    scalar* s = &binSums_[bini*nBinSumTypes];

    ++c[BIN_HITS];
    s[BIN_VN_IN] += k.vnIn;
    s[BIN_VN_OUT] += k.vnOut;
    if (k.hasKt)
    {
        ++c[BIN_KT_SAMPLES];
        s[BIN_VT_IN] += k.vtIn;
        s[BIN_VT_OUT] += k.vtOut;
    }

    // The rebound angle from the mean wall; the rebound leaves the wall
    const scalar vn = -(Ur & nw);
    const scalar reboundAngle = std::atan2(vn, mag(Ur + vn*nw));
    ++binCounts_
    [
        (first + angleBin(reboundAngle))*nBinCountTypes + BIN_REBOUNDS
    ];
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
    forAll(binCounts_, i)
    {
        binCounts_[i] += other.binCounts_[i];
    }
    forAll(binSums_, i)
    {
        binSums_[i] += other.binSums_[i];
    }
}


void Foam::roughWallStatistics::reset()
{
    counts_ = int64_t(0);
    sums_ = Zero;
    binCounts_ = int64_t(0);
    binSums_ = Zero;
}


Foam::roughWallStatistics Foam::roughWallStatistics::reduced() const
{
    roughWallStatistics total(*this);

    roughWallCompat::sumOverProcessors(total.counts_);
    roughWallCompat::sumOverProcessors(total.sums_);
    if (nBins_)
    {
        roughWallCompat::sumOverProcessors(total.binCounts_);
        roughWallCompat::sumOverProcessors(total.binSums_);
    }

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


Foam::scalar Foam::roughWallStatistics::impulseKn(const label patchi) const
{
    return ratio(sum(patchi, VN_OUT), sum(patchi, VN_IN));
}


Foam::scalar Foam::roughWallStatistics::impulseKt(const label patchi) const
{
    return ratio(sum(patchi, VT_OUT), sum(patchi, VT_IN));
}


std::vector<Foam::roughWallStatistics::reportLine>
Foam::roughWallStatistics::report
(
    const label patchi,
    const roughWallPatchSettings::interactionType t,
    std::string& heading
) const
{
    typedef roughWallPatchSettings::interactionType interactionType;

    auto n = [&](const countType c){ return scalar(count(patchi, c)); };

    switch (t)
    {
        case interactionType::escape:
        {
            heading = "Parcel fate: patch %s (number, mass)";
            return
            {
                {
                    "escape", {"nEscape", "massEscape"},
                    {n(ESCAPED), sum(patchi, ESCAPED_MASS)}, 1
                }
            };
        }
        case interactionType::stick:
        {
            heading = "Parcel fate: patch %s (number, mass)";
            return
            {
                {
                    "stick", {"nStick", "massStick"},
                    {n(STUCK), sum(patchi, STUCK_MASS)}, 1
                }
            };
        }
        case interactionType::rough:
        {
            heading = "Rough wall: patch %s";
            return
            {
                {"hits", {"hits"}, {n(HITS)}, 1},
                {
                    "facet collisions (no-slip, sliding)",
                    {"noSlip", "sliding"}, {n(NO_SLIP), n(SLIDING)}, 2
                },
                {
                    "facet collisions per hit", {"facetPerHit"},
                    {facetCollisionsPerHit(patchi)}, 0
                },
                {
                    "hits at the re-collision bound", {"fallbacks"},
                    {n(FALLBACKS)}, 1
                },
                {
                    "mean facet tilt gamma [deg]", {"meanGamma"},
                    {meanGammaDeg(patchi)}, 0
                },
                {
                    "mean k_n, k_t", {"meanKn", "meanKt"},
                    {meanKn(patchi), meanKt(patchi)}, 0
                },
                {
                    "impulse-weighted k_n, k_t", {"impulseKn", "impulseKt"},
                    {impulseKn(patchi), impulseKt(patchi)}, 0
                },
                {
                    "sums |v'_n|, v''_n, |v'_t|, v''_t",
                    {"sumVnIn", "sumVnOut", "sumVtIn", "sumVtOut"},
                    {
                        sum(patchi, VN_IN), sum(patchi, VN_OUT),
                        sum(patchi, VT_IN), sum(patchi, VT_OUT)
                    },
                    0
                },
                {
                    "kinetic energy loss [J]", {"energyLoss"},
                    {sum(patchi, ENERGY_LOSS)}, 0
                }
            };
        }
        default:
        {
            return {};
        }
    }
}


Foam::stringList Foam::roughWallStatistics::exactCounts() const
{
    return integerText(counts_);
}


bool Foam::roughWallStatistics::setExactCounts(const stringList& text)
{
    return integersFromText(text, counts_);
}


Foam::stringList Foam::roughWallStatistics::exactSums() const
{
    return exactText(sums_);
}


bool Foam::roughWallStatistics::setExactSums(const stringList& text)
{
    return numbersFromText(text, sums_);
}


Foam::stringList Foam::roughWallStatistics::exactBinCounts() const
{
    return integerText(binCounts_);
}


Foam::stringList Foam::roughWallStatistics::exactBinSums() const
{
    return exactText(binSums_);
}


bool Foam::roughWallStatistics::setExactBins
(
    const label nBins,
    const stringList& countText,
    const stringList& sumText,
    const wordList& names
)
{
    binCounts_ = int64_t(0);
    binSums_ = Zero;

    List<int64_t> counts;
    scalarList sums;
    const label nStored = names.size()*nBins;
    if
    (
        nBins != nBins_
     || !integersFromText(countText, counts)
     || !numbersFromText(sumText, sums)
     || counts.size() != nStored*nBinCountTypes
     || sums.size() != nStored*nBinSumTypes
    )
    {
        return false;
    }

    forAll(names, storedi)
    {
        const label patchi =
            std::find(patchNames_.begin(), patchNames_.end(), names[storedi])
          - patchNames_.begin();
        if (patchi == nPatches_)
        {
            continue;
        }
        for (label i = 0; i < nBins_*nBinCountTypes; ++i)
        {
            binCounts_[patchi*nBins_*nBinCountTypes + i] =
                counts[storedi*nBins_*nBinCountTypes + i];
        }
        for (label i = 0; i < nBins_*nBinSumTypes; ++i)
        {
            binSums_[patchi*nBins_*nBinSumTypes + i] =
                sums[storedi*nBins_*nBinSumTypes + i];
        }
    }
    return true;
}


bool Foam::roughWallStatistics::placeByName
(
    const wordList& names,
    DynamicList<word>& dropped
)
{
    // Without names the stored lists are taken as this layout
    const label nStored = names.empty() ? nPatches_ : names.size();
    if
    (
        counts_.size() != nStored*nCountTypes
     || sums_.size() != nStored*nSumTypes
    )
    {
        return false;
    }
    if (names.empty())
    {
        return true;
    }

    List<int64_t> counts(nPatches_*nCountTypes, int64_t(0));
    scalarList sums(nPatches_*nSumTypes, scalar(0));
    forAll(names, storedi)
    {
        const label patchi =
            std::find(patchNames_.begin(), patchNames_.end(), names[storedi])
          - patchNames_.begin();
        if (patchi == nPatches_)
        {
            dropped.append(names[storedi]);
            continue;
        }
        for (label c = 0; c < nCountTypes; ++c)
        {
            counts[patchi*nCountTypes + c] = counts_[storedi*nCountTypes + c];
        }
        for (label s = 0; s < nSumTypes; ++s)
        {
            sums[patchi*nSumTypes + s] = sums_[storedi*nSumTypes + s];
        }
    }
    counts_.transfer(counts);
    sums_.transfer(sums);
    return true;
}


Foam::autoPtr<Foam::OFstream> Foam::roughWallStatistics::newFile
(
    const polyMesh& mesh,
    const word& cloudName,
    const word& name,
    const label precision
)
{
    if (!Pstream::master())
    {
        return autoPtr<OFstream>();
    }

    const Time& time = mesh.time();

    // Where v1912's writeFile puts a sub-model's file: the undecomposed
    // case, the start time of this run
    fileName dir(time.rootPath()/time.globalCaseName()/"postProcessing");
    if (mesh.name() != polyMesh::defaultRegion)
    {
        dir = dir/mesh.name();
    }
    dir = dir/"lagrangian"/cloudName/"patchInteractionModel"
        /Time::timeName(time.startTime().value());

    mkDir(dir);
    autoPtr<OFstream> filePtr(new OFstream(dir/name));
    filePtr().precision(precision);
    return filePtr;
}


Foam::autoPtr<Foam::OFstream> Foam::roughWallStatistics::openFile
(
    const polyMesh& mesh,
    const word& cloudName,
    const UList<roughWallPatchSettings>& patches,
    const label precision
)
{
    autoPtr<OFstream> filePtr
    (
        newFile(mesh, cloudName, "roughWallInteraction.dat", precision)
    );
    if (!filePtr.valid())
    {
        return filePtr;
    }
    OFstream& os = filePtr();

    os  << "# Particle patch interaction" << nl
        << "# Model : roughWallInteraction" << nl
        << "# Time";

    const roughWallStatistics none(roughWallCompat::boundary(mesh));
    for (label patchi = 0; patchi < none.nPatches(); ++patchi)
    {
        std::string heading;
        for
        (
            const reportLine& line
          : none.report(patchi, patches[patchi].type(), heading)
        )
        {
            for (const std::string& column : line.columns)
            {
                os  << tab << none.patchName(patchi) << '_' << column.c_str();
            }
        }
    }
    os  << endl;

    return filePtr;
}


Foam::autoPtr<Foam::OFstream> Foam::roughWallStatistics::openAnglesFile
(
    const polyMesh& mesh,
    const word& cloudName,
    const label precision
) const
{
    autoPtr<OFstream> filePtr
    (
        newFile(mesh, cloudName, "roughWallInteractionAngles.dat", precision)
    );
    if (!filePtr.valid())
    {
        return filePtr;
    }
    OFstream& os = filePtr();

    os  << "# Rough-wall hits per bin of the incidence angle and histogram"
        << " of the rebound angle (angles from the mean wall) [deg]" << nl
        << "# Model : roughWallInteraction" << nl
        << "# Bins : " << nBins_ << nl
        << "# Time" << tab << "patch" << tab << "bin" << tab << "angleMin"
        << tab << "angleMax" << tab << "hits" << tab << "ktSamples" << tab
        << "sumVnIn" << tab << "sumVnOut" << tab << "sumVtIn" << tab
        << "sumVtOut" << tab << "impulseKn" << tab << "impulseKt" << tab
        << "rebounds" << endl;

    return filePtr;
}


void Foam::roughWallStatistics::writeAngles
(
    OFstream& file,
    const UList<roughWallPatchSettings>& patches,
    const Time& time
) const
{
    typedef roughWallPatchSettings::interactionType interactionType;

    const word timeName(Time::timeName(time.value()));
    for (label patchi = 0; patchi < nPatches_; ++patchi)
    {
        if (patches[patchi].type() != interactionType::rough)
        {
            continue;
        }
        for (label bini = 0; bini < nBins_; ++bini)
        {
            auto n = [&](const binCountType c)
            {
                // (as text: v1912 writes an int64_t as a label)
                return std::to_string(binCount(patchi, bini, c));
            };
            auto s = [&](const binSumType t)
            {
                return binSum(patchi, bini, t);
            };
            file<< timeName << tab << patchNames_[patchi] << tab << bini
                << tab << 90.0*bini/nBins_ << tab << 90.0*(bini + 1)/nBins_
                << tab << n(BIN_HITS).c_str()
                << tab << n(BIN_KT_SAMPLES).c_str()
                << tab << s(BIN_VN_IN) << tab << s(BIN_VN_OUT)
                << tab << s(BIN_VT_IN) << tab << s(BIN_VT_OUT)
                << tab << ratio(s(BIN_VN_OUT), s(BIN_VN_IN))
                << tab << ratio(s(BIN_VT_OUT), s(BIN_VT_IN))
                << tab << n(BIN_REBOUNDS).c_str() << nl;
        }
    }
    file.flush();
}


void Foam::roughWallStatistics::write
(
    Ostream& log,
    OFstream* file,
    const UList<roughWallPatchSettings>& patches,
    const Time& time
) const
{
    if (file)
    {
        *file << Time::timeName(time.value());
    }

    for (label patchi = 0; patchi < nPatches_; ++patchi)
    {
        std::string heading;
        const std::vector<reportLine> lines
        (
            report(patchi, patches[patchi].type(), heading)
        );

        if (lines.empty())
        {
            continue;
        }

        const std::string::size_type at = heading.find("%s");
        log << "    " << heading.substr(0, at).c_str()
            << patchNames_[patchi] << heading.substr(at + 2).c_str() << nl;

        for (const reportLine& line : lines)
        {
            // Labels aligned as in OpenFOAM's own "Parcel fate" lines
            const std::string::size_type width = 28;
            log << "      - " << line.label.c_str()
                << std::string
                   (
                       line.label.size() < width
                     ? width - line.label.size() : 1,
                       ' '
                   ).c_str()
                << "= ";

            for (std::size_t i = 0; i < line.values.size(); ++i)
            {
                const scalar v = line.values[i];
                log << (i ? ", " : "");
                const bool isCount = i < line.nCounts;
                // (a count as text: v1912 writes an int64_t as a label)
                if (isCount) log << std::to_string(int64_t(v)).c_str();
                else log << v;

                if (file)
                {
                    *file << tab;
                    if (isCount)
                    {
                        *file << std::to_string(int64_t(v)).c_str();
                    }
                    else
                    {
                        *file << v;
                    }
                }
            }
            log << nl;
        }
    }

    if (file)
    {
        *file << endl;
    }
}


// ************************************************************************* //
