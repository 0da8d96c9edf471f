/*---------------------------------------------------------------------------*\
  roughWallInteraction: Derevich's rough-wall collision model for OpenFOAM
  Copyright (C) 2026 roughWallInteraction authors
  SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "facetImpactCoefficients.H"
#include "roughWallInput.H"

#include <algorithm>

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

//- The index of the coefficient called name
Foam::label indexOf(const std::string& name)
{
    return std::find(names, names + 3, name) - names;
}

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
    // e in [0, 1], mu0 >= 0, muD in [0, mu0] (sliding friction above the
    // static one could reverse the slip)
    const coefficient& mu0 = coefficients_.mu0;
    const auto allowed = [&](const label i)
    {
        return
            roughWallInput::range
            {
                0, i == 0 ? 1 : i == 2 && !mu0.function ? mu0.constant : GREAT
            }.allowed()
          + (i == 2 ? " (at most mu0)" : "")
          + ", or an OpenFOAM Function1 of the facet impact, e.g. table "
            "((0 0.95) (90 0.75)), with values in that range and nothing "
            "after it";
    };

    // Each coefficient a Function1 (OpenFOAM's reader, its stops caught,
    // every token used), muD's default mu0.  The bounds are checked at
    // start-up (the core's checkTableBounds) at the nodes of a constant (any
    // one) and of a table interpolated linearly, held or repeated beyond
    // its ends: they hold everywhere if they hold there.  Any other function
    // (a spline table too) has no such nodes: checked at every call
    std::vector<double> nodes[3];
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
        autoPtr<Function1<scalar>>& f = functions_[i];
        const string why = e ? roughWallInput::readWhole(*e, [&]()
        {
            f = roughWallCompat::newScalarFunction1(names[i], dict);
        }) : "";
        if (!e || !why.empty())
        {
            roughWallInput::fatalBadEntry(dict, names[i], allowed(i), why);
        }

        // A table's settings: its own sub-dictionary, or the entry's
        // dictionary (ESI's inline table)
        const dictionary& settings = e->isDict() ? e->dict() : dict;
        const auto* t = dynamic_cast<const roughWallCompat::scalarTable*>(&f());
        if (f->type() == "constant")
        {
            c.constant = f->value(0);
            f.clear();
            nodes[i] = {45};
        }
        else if
        (
            t
         && settings.lookupOrDefault<word>("interpolationScheme", "linear")
         == "linear"
         && settings.lookupOrDefault<word>("outOfBounds", "clamp") != "zero"
        )
        {
            const tmp<scalarField> x(t->x());
            nodes[i].assign(x().begin(), x().end());
        }
        else
        {
            coefficients_.checked = true;
        }
        c.function = f.valid() ? &f() : nullptr;
    }

    coefficients_.eArgument = roughWallInput::readEnum
    (
        dict, "eArgument", argumentNames, roughWall::ImpactArgument::angle
    );
    const coefficient& e = coefficients_.e;
    if (!e.function && roughWallCompat::findLiteral(dict, "eArgument"))
    {
        roughWallInput::fatalBadEntry
        (
            dict, "eArgument", "only with e as a Function1",
            "e is the constant " + name(e.constant)
        );
    }

    // The value out of range, and for a function its argument
    try
    {
        roughWall::checkTableBounds
        (
            nodes[0], nodes[1], nodes[2], coefficients_.eArgument,
            [&](const std::string& name, const double x)
            {
                return (coefficients_.*members[indexOf(name)])(x);
            }
        );
    }
    catch (const roughWall::CoefficientOutOfRange& error)
    {
        const label i = indexOf(error.coefficient());
        roughWallInput::fatalBadEntry
        (
            dict, names[i], allowed(i),
            (coefficients_.*members[i]).function ? error.what() : ""
        );
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


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * //

Foam::Ostream& Foam::operator<<(Ostream& os, const facetImpactCoefficients& f)
{
    const bool eOfSpeed = f.coefficients_.eArgument != ImpactArgument::angle;
    for (label i = 0; i < 3; ++i)
    {
        const auto& c = f.coefficients_.*members[i];
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
    return os;
}


// ************************************************************************* //
