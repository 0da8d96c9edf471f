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

using roughWall::ImpactArgument;

const char* const names[3] = {"e", "mu0", "muD"};

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
    policy_
    {
        {nullptr, 0}, {nullptr, 0}, {nullptr, 0},
        roughWall::ImpactArgument::angle, false
    }
{
    // Each coefficient a Function1 (OpenFOAM's reader, its stops caught,
    // every token used); a constant kept as its number, in its range:
    // e in [0, 1], mu0 >= 0, muD in [0, mu0] for a constant mu0 (sliding
    // friction above the static one could reverse the slip), muD's default
    // mu0.  Linear tables: the bounds checked at their nodes here; any other
    // function (a spline table too): at every call.  A constant: one node
    coefficient* c[3] = {&policy_.e, &policy_.mu0, &policy_.muD};
    std::vector<double> nodes[3] = {{45}, {45}, {45}};
    for (label i = 0; i < 3; ++i)
    {
        const entry* e = roughWallCompat::findLiteral(dict, names[i]);
        if (i == 2 && !e)
        {
            policy_.muD = policy_.mu0;
            nodes[2] = nodes[1];
            break;
        }
        const roughWallInput::range r
        {
            0, i == 0 ? 1 : i == 2 && !c[1]->function ? c[1]->constant : GREAT,
            meanings[i]
        };
        const string allowed =
            r.allowed() + ", or an OpenFOAM Function1 of the facet impact, "
            "e.g. table ((0 0.95) (90 0.75)), with values in that range and "
            "nothing after it";

        autoPtr<Function1<scalar>>& f = functions_[i];
        const string why = e ? roughWallCompat::readWhole(*e, [&]()
        {
            f = roughWallCompat::newScalarFunction1(names[i], dict);
        }) : "";
        if (!e || !why.empty())
        {
            roughWallInput::fatalBadEntry
            (
                dict, names[i], allowed, r.meaning,
                e ? roughWallInput::entryText(dict, names[i]) + " (" + why + ")"
                  : string()
            );
        }

        // Its settings: its own sub-dictionary, or the entry's dictionary
        // (ESI's inline table)
        tmp<scalarField> x;
        if (f->type() == "constant")
        {
            c[i]->constant = f->value(0);
            f.clear();
            if (!(c[i]->constant >= r.min && c[i]->constant <= r.max))
            {
                roughWallInput::fatalBadEntry
                (
                    dict, names[i], allowed, r.meaning
                );
            }
        }
        else if
        (
            roughWallCompat::tableNodes(f(), e->isDict() ? e->dict() : dict, x)
        )
        {
            nodes[i].assign(x().begin(), x().end());
        }
        else
        {
            policy_.checked = true;
        }
        c[i]->function = f.valid() ? &f() : nullptr;
    }

    const bool eArgument = roughWallCompat::findLiteral(dict, "eArgument");
    if (eArgument && !policy_.e.function)
    {
        roughWallInput::fatalBadEntry
        (
            dict, "eArgument", "only with e as a Function1", eArgumentMeaning,
            "e is the constant " + name(policy_.e.constant)
        );
    }
    policy_.eArgument = roughWallInput::readEnum
    (
        dict, "eArgument", argumentNames, eArgumentMeaning,
        roughWall::ImpactArgument::angle
    );

    if (!dependsOnImpact() || policy_.checked)
    {
        return;
    }
    try
    {
        roughWall::checkTableBounds
        (
            nodes[0], nodes[1], nodes[2], policy_.eArgument,
            [&](const std::string& name, const double x)
            {
                return (*c[name == "e" ? 0 : name == "mu0" ? 1 : 2])(x);
            }
        );
    }
    catch (const roughWall::CoefficientOutOfRange& error)
    {
        FatalIOErrorInFunction(dict)
            << "Patch " << patchName << " in " << dict.name() << ": "
            << error.what() << " (keyword " << error.coefficient()
            << ")" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::facetImpactCoefficients::writeSummary(Ostream& os) const
{
    const coefficient c[3] = {policy_.e, policy_.mu0, policy_.muD};
    for (label i = 0; i < 3; ++i)
    {
        os  << (i ? ", " : "") << names[i] << " = ";
        if (c[i].function)
        {
            os  << c[i].function->type() << " of the facet impact "
                << (
                       i == 0 && policy_.eArgument != ImpactArgument::angle
                     ? "normal speed [m/s]" : "angle [deg]"
                   );
        }
        else
        {
            os  << c[i].constant;
        }
    }
}


// ************************************************************************* //
