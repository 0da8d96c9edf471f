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

//- The coefficients' keywords and places in the core's ImpactFunctions
const char* const names[3] = {"e", "mu0", "muD"};
using F = Foam::facetImpactCoefficients::functions;
Foam::facetImpactCoefficients::coefficient F::* const members[3] =
    {&F::e, &F::mu0, &F::muD};

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
    coefficients_
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
    std::vector<double> nodes[3] = {{45}, {45}, {45}};
    const coefficient& mu0 = coefficients_.mu0;
    for (label i = 0; i < 3; ++i)
    {
        coefficient& c = coefficients_.*members[i];
        const entry* e = roughWallCompat::findLiteral(dict, names[i]);
        if (i == 2 && !e)
        {
            c = mu0;
            nodes[2] = nodes[1];
            break;
        }
        const roughWallInput::range r
        {
            0, i == 0 ? 1 : i == 2 && !mu0.function ? mu0.constant : GREAT,
            meanings[i]
        };
        const string allowed =
            r.allowed() + ", or an OpenFOAM Function1 of the facet impact, "
            "e.g. table ((0 0.95) (90 0.75)), with values in that range and "
            "nothing after it";

        autoPtr<Function1<scalar>>& f = functions_[i];
        const string why = e ? roughWallInput::readWhole(*e, [&]()
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
            c.constant = f->value(0);
            f.clear();
            if (!(c.constant >= r.min && c.constant <= r.max))
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
            coefficients_.checked = true;
        }
        c.function = f.valid() ? &f() : nullptr;
    }

    const bool eArgument = roughWallCompat::findLiteral(dict, "eArgument");
    if (eArgument && !coefficients_.e.function)
    {
        roughWallInput::fatalBadEntry
        (
            dict, "eArgument", "only with e as a Function1", eArgumentMeaning,
            "e is the constant " + name(coefficients_.e.constant)
        );
    }
    coefficients_.eArgument = roughWallInput::readEnum
    (
        dict, "eArgument", argumentNames, eArgumentMeaning,
        roughWall::ImpactArgument::angle
    );

    if (!dependsOnImpact() || coefficients_.checked)
    {
        return;
    }
    try
    {
        roughWall::checkTableBounds
        (
            nodes[0], nodes[1], nodes[2], coefficients_.eArgument,
            [&](const std::string& name, const double x)
            {
                const label i = name == "e" ? 0 : name == "mu0" ? 1 : 2;
                return (coefficients_.*members[i])(x);
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

roughWall::FacetMaterial Foam::facetImpactCoefficients::at
(
    const roughWall::FacetImpact& impact
) const
{
    try
    {
        return coefficients_(impact);
    }
    catch (const roughWall::CoefficientOutOfRange& error)
    {
        FatalErrorInFunction
            << "Patch " << patchName_ << ": " << error.what()
            << exit(FatalError);
        return {};
    }
}


void Foam::facetImpactCoefficients::writeSummary(Ostream& os) const
{
    const bool eOfSpeed = coefficients_.eArgument != ImpactArgument::angle;
    for (label i = 0; i < 3; ++i)
    {
        const coefficient& c = coefficients_.*members[i];
        os  << (i ? ", " : "") << names[i] << " = ";
        if (c.function)
        {
            os  << c.function->type() << " of the facet impact "
                << (i == 0 && eOfSpeed ? "normal speed [m/s]" : "angle [deg]");
        }
        else
        {
            os  << c.constant;
        }
    }
}


// ************************************************************************* //
