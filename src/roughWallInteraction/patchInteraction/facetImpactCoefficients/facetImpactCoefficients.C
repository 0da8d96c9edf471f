/*---------------------------------------------------------------------------*\
  roughWallInteraction: Derevich's rough-wall collision model for OpenFOAM
  Copyright (C) 2026 roughWallInteraction authors
  SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "facetImpactCoefficients.H"
#include "roughWallInput.H"
#include "foamCompat.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

ROUGHWALL_NAMED_ENUM
(
    argumentNames, roughWall::ImpactArgument, 2, "angle", "normalSpeed"
);

namespace
{

//- The coefficients' keywords, places among the constants and meanings
using M = roughWall::FacetMaterial;
const char* const names[3] = {"e", "mu0", "muD"};
double M::* const members[3] = {&M::e, &M::mu0, &M::muD};
const char* const meanings[3] =
{
    "normal restitution coefficient of a facet collision",
    "static friction coefficient (no-slip criterion)",
    "dynamic (sliding) friction coefficient; must not exceed mu0 "
    "(default: mu0)"
};

const char* const eArgumentMeaning =
    "what e is a function of: angle (facet impact angle [deg]) "
    "or normalSpeed (normal impact speed [m/s])";

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::facetImpactCoefficients::facetImpactCoefficients
(
    const dictionary& dict,
    const word& patchName
)
:
    patchName_(patchName),
    eArgument_(roughWall::ImpactArgument::angle),
    checkPerCall_(false)
{
    // Each coefficient a Function1 (OpenFOAM's reader, its stops caught,
    // every token used); a constant kept as its number, in its range.
    // muD's range is [0, mu0] for a constant mu0 (sliding friction above
    // the static one could reverse the slip), its default mu0.  Tables:
    // the bounds at their nodes (linear in between, constant beyond the
    // ends); any other function (a spline table too): at every call.  A
    // constant's nodes: one argument
    std::vector<double> nodes[3] = {{45}, {45}, {45}};
    for (label i = 0; i < 3; ++i)
    {
        const word keyword(names[i]);
        const entry* e = roughWallCompat::findLiteral(dict, keyword);
        if (i == 2 && !e)
        {
            constants_.muD = constants_.mu0;
            if (functions_[1].valid())
            {
                functions_[2].reset(functions_[1]->clone().ptr());
            }
            nodes[2] = nodes[1];
            break;
        }
        const roughWallInput::range r
        {
            0,
            i == 0 ? 1 : i == 2 && !functions_[1].valid()
          ? constants_.mu0 : GREAT,
            meanings[i]
        };
        const string allowed =
            r.allowed() + ", or an OpenFOAM Function1 of the facet impact, "
            "e.g. table ((0 0.95) (90 0.75)), with values in that range and "
            "nothing after it";
        const auto fatal = [&](const string& why)
        {
            roughWallInput::fatalBadEntry
            (
                dict, keyword, allowed, r.meaning,
                roughWallInput::entryText(dict, keyword) + why
            );
        };

        autoPtr<Function1<scalar>>& f = functions_[i];
        const auto newF =
            [&]() { f = roughWallCompat::newScalarFunction1(keyword, dict); };
        string why;
        if (!e || !roughWallCompat::readWhole(*e, newF, why))
        {
            fatal(e ? " (" + why + ")" : "");
        }

        tmp<scalarField> x;
        if (f->type() == "constant")
        {
            const scalar c = constants_.*members[i] = f->value(0);
            f.clear();
            if (!(c >= r.min && c <= r.max))
            {
                fatal("");
            }
        }
        else if
        (
            // Its settings: its own sub-dictionary, or the entry (ESI's
            // inline table)
            roughWallCompat::tableNodes(f(), e->isDict() ? e->dict() : dict, x)
        )
        {
            nodes[i].assign(x().begin(), x().end());
        }
        else
        {
            checkPerCall_ = true;
        }
    }

    const bool eArgumentGiven = roughWallCompat::findLiteral(dict, "eArgument");
    if (eArgumentGiven && !functions_[0].valid())
    {
        roughWallInput::fatalBadEntry
        (
            dict, "eArgument", "only with e as a Function1",
            eArgumentMeaning, "e is the constant " + name(constants_.e)
        );
    }
    eArgument_ = roughWallInput::readEnum
    (
        dict, "eArgument", argumentNames, eArgumentMeaning, eArgument_
    );

    if (!dependsOnImpact() || checkPerCall_)
    {
        return;
    }
    try
    {
        roughWall::checkTableBounds
        (
            nodes[0], nodes[1], nodes[2], eArgument_,
            [&](const std::string& name, const double x)
            {
                return value(name == "e" ? 0 : name == "mu0" ? 1 : 2, x);
            }
        );
    }
    catch (const roughWall::CoefficientOutOfRange& error)
    {
        FatalIOErrorInFunction(dict)
            << "Patch " << patchName_ << " in " << dict.name() << ": "
            << error.what() << " (keyword " << error.coefficient()
            << ")" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::facetImpactCoefficients::value
(
    const label i,
    const scalar x
) const
{
    const autoPtr<Function1<scalar>>& f = functions_[i];
    return f.valid() ? f->value(x) : constants_.*members[i];
}


void Foam::facetImpactCoefficients::writeSummary(Ostream& os) const
{
    for (label i = 0; i < 3; ++i)
    {
        os  << (i ? ", " : "") << names[i] << " = ";
        if (functions_[i].valid())
        {
            os  << functions_[i]->type() << " of the facet impact "
                << (
                       i == 0
                    && eArgument_ == roughWall::ImpactArgument::normalSpeed
                     ? "normal speed [m/s]" : "angle [deg]"
                   );
        }
        else
        {
            os  << constants_.*members[i];
        }
    }
}


roughWall::FacetMaterial Foam::facetImpactCoefficients::at
(
    const roughWall::FacetImpact& impact
) const
{
    const roughWall::FacetMaterial m
    {
        value(0, roughWall::argumentOf(impact, eArgument_)),
        value(1, impact.angleDeg),
        value(2, impact.angleDeg)
    };
    if (checkPerCall_)
    {
        try
        {
            roughWall::checkBounds(m, impact, eArgument_);
        }
        catch (const roughWall::CoefficientOutOfRange& error)
        {
            FatalErrorInFunction
                << "Patch " << patchName_ << ": " << error.what()
                << exit(FatalError);
        }
    }
    return m;
}


// ************************************************************************* //
