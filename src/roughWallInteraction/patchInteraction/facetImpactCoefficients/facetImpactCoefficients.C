/*---------------------------------------------------------------------------*\
  roughWallInteraction: Derevich's rough-wall collision model for OpenFOAM
  Copyright (C) 2026 roughWallInteraction authors
  SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "facetImpactCoefficients.H"
#include "roughWallInput.H"
#include "foamCompat.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A number in r, checked as every constant of the settings is, or a
//- Function1 (null, with the number in value)
Foam::autoPtr<Foam::Function1<Foam::scalar>> readCoefficient
(
    const Foam::dictionary& dict,
    const Foam::word& keyword,
    const Foam::roughWallInput::range& r,
    Foam::scalar& value
)
{
    using namespace Foam;
    if (!Foam::facetImpactCoefficients::isFunction(dict, keyword))
    {
        value = roughWallInput::readNumber<scalar>(dict, keyword, r);
        return autoPtr<Function1<scalar>>();
    }

    // OpenFOAM's Function1 reader, with its errors caught so that the
    // message names the keyword and file; and every token of the entry
    // used: the reader stops after the function's data and would leave the
    // rest unread, without a message ("table (...) 0.5" ran with the table)
    const string allowed =
        r.allowed() + ", or an OpenFOAM Function1 of the facet impact, e.g. "
        "table ((0 0.95) (90 0.75)), with values in that range and nothing "
        "after it";

    autoPtr<Function1<scalar>> f;
    string error;
    if
    (
        !roughWallCompat::callCatching
        (
            [&]() { f = roughWallCompat::newScalarFunction1(keyword, dict); },
            error
        )
    )
    {
        roughWallInput::fatalBadEntry
        (
            dict, keyword, allowed, r.meaning,
            "'" + roughWallInput::entryText(dict, keyword) + "' ("
          + error + ")"
        );
    }

    const entry& e = *roughWallCompat::findLiteral(dict, keyword);
    if (!e.isDict())
    {
        // The entry's own tokens, where the reader left them (stream()
        // would rewind them), and the token a reader peeked at and put
        // back (OpenFOAM-14's constant looks for units after its value):
        // the entry's stream is read in place (peekBack is not const on
        // every release), as OpenFOAM's own primitiveEntry::stream() does
        ITstream& is =
            const_cast<ITstream&>(dynamic_cast<const ITstream&>(e));
        token back;
        const bool hasBack = roughWallCompat::peekBack(is, back);
        if (hasBack || is.tokenIndex() < is.size())
        {
            OStringStream putBack;
            if (hasBack)
            {
                putBack<< back;
            }
            const string after =
                roughWallInput::tokensText(is, is.tokenIndex());
            const string rest =
                putBack.str()
              + (hasBack && !after.empty() ? " " : "") + after;
            roughWallInput::fatalBadEntry
            (
                dict, keyword, allowed, r.meaning,
                "'" + roughWallInput::entryText(dict, keyword)
              + "' (tokens after the " + f->type() + ": '" + rest + "')"
            );
        }
    }
    return f;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * * //

const char* const Foam::facetImpactCoefficients::eArgumentMeaning =
    "what e is a function of: angle (facet impact angle [deg]) "
    "or normalSpeed (normal impact speed [m/s])";


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::facetImpactCoefficients::facetImpactCoefficients
(
    const dictionary& dict,
    const word& patchName
)
:
    patchName_(patchName),
    eArgument_(roughWall::ImpactArgument::angle),
    dependsOnImpact_(false),
    checkPerCall_(false)
{
    e_ = readCoefficient
    (
        dict, "e",
        {0, 1, "normal restitution coefficient of a facet collision"},
        constants_.e
    );
    mu0_ = readCoefficient
    (
        dict, "mu0",
        {0, GREAT, "static friction coefficient (no-slip criterion)"},
        constants_.mu0
    );
    // Sliding friction above the static one could reverse the slip (a
    // function mu0 is compared with muD at the nodes below)
    if (roughWallCompat::findLiteral(dict, "muD"))
    {
        muD_ = readCoefficient
        (
            dict, "muD",
            {
                0, mu0_.valid() ? GREAT : constants_.mu0,
                "dynamic (sliding) friction coefficient; must not exceed "
                "mu0 (default: mu0)"
            },
            constants_.muD
        );
    }
    else if (mu0_.valid())
    {
        muD_.reset(mu0_->clone().ptr());
    }
    else
    {
        constants_.muD = constants_.mu0;
    }
    dependsOnImpact_ = e_.valid() || mu0_.valid() || muD_.valid();

    if (roughWallCompat::findLiteral(dict, "eArgument"))
    {
        if (!e_.valid())
        {
            roughWallInput::fatalBadEntry
            (
                dict, "eArgument", "only with e as a Function1",
                eArgumentMeaning,
                "e is the constant " + Foam::name(constants_.e)
            );
        }
        eArgument_ = roughWall::ImpactArgument
        (
            roughWallInput::readChoice
            (
                dict, "eArgument", {"angle", "normalSpeed"},
                eArgumentMeaning
            )
        );
    }
    if (!dependsOnImpact_)
    {
        return;
    }

    // Tables: the bounds at their nodes (linear in between, constant
    // beyond the ends); constants: at one argument. Anything else (a spline
    // table too): at every call
    std::vector<double> nodes[3];
    const autoPtr<Function1<scalar>>* functions[3] = {&e_, &mu0_, &muD_};
    const word names[3] =
    {
        "e", "mu0", roughWallCompat::findLiteral(dict, "muD") ? "muD" : "mu0"
    };
    for (int i = 0; i < 3; ++i)
    {
        if (functions[i]->valid())
        {
            // Where the function read its settings: its own sub-dictionary,
            // or the entry (ESI's inline table)
            const dictionary& coeffs =
                dict.isDict(names[i]) ? dict.subDict(names[i]) : dict;
            tmp<scalarField> x;
            if
            (
                roughWallCompat::startupCheckNodes
                (
                    (*functions[i])(), coeffs, x
                )
            )
            {
                nodes[i].assign(x().begin(), x().end());
            }
            else
            {
                checkPerCall_ = true;
            }
        }
    }
    if (!checkPerCall_)
    {
        if (nodes[1].empty() && nodes[2].empty())
        {
            nodes[1].push_back(45);   // constant friction: one argument
        }
        const auto valueAt = [&](const std::string& name, double x)
        {
            const autoPtr<Function1<scalar>>& f = function(name);
            return f.valid() ? f->value(x) : constant(name);
        };
        try
        {
            if (nodes[0].empty()) nodes[0].push_back(45);
            roughWall::checkTableBounds
            (
                nodes[0], nodes[1], nodes[2], eArgument_, valueAt
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
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::facetImpactCoefficients::isFunction
(
    const dictionary& dict,
    const word& keyword
)
{
    if (!dict.found(keyword))
    {
        return false;
    }
    if (dict.isDict(keyword))
    {
        return true;
    }
    // A Function1 is a type name followed by its data ("table ((0 0.9)
    // ...)"): anything else (a number, a lone word, two numbers) is read
    // as a number and refused with the constant's message and range
    const ITstream& is = dict.lookup(keyword);
    return is.size() > 1 && is[0].isWord();
}


const Foam::autoPtr<Foam::Function1<Foam::scalar>>&
Foam::facetImpactCoefficients::function(const std::string& name) const
{
    return name == "e" ? e_ : name == "mu0" ? mu0_ : muD_;
}


Foam::scalar Foam::facetImpactCoefficients::constant
(
    const std::string& name
) const
{
    return
        name == "e" ? constants_.e
      : name == "mu0" ? constants_.mu0 : constants_.muD;
}


Foam::string Foam::facetImpactCoefficients::description
(
    const word& name
) const
{
    const autoPtr<Function1<scalar>>& f = function(name);
    OStringStream os;
    if (f.valid())
    {
        os  << f->type() << " of the facet impact "
            << (
                   name == "e"
                && eArgument_ == roughWall::ImpactArgument::normalSpeed
                 ? "normal speed [m/s]" : "angle [deg]"
               );
    }
    else
    {
        os  << constant(name);
    }
    return os.str();
}


roughWall::FacetMaterial Foam::facetImpactCoefficients::at
(
    const roughWall::FacetImpact& impact
) const
{
    const scalar eArgument = roughWall::argumentOf(impact, eArgument_);
    const roughWall::FacetMaterial m
    {
        e_.valid() ? e_->value(eArgument) : constants_.e,
        mu0_.valid() ? mu0_->value(impact.angleDeg) : constants_.mu0,
        muD_.valid() ? muD_->value(impact.angleDeg) : constants_.muD
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
