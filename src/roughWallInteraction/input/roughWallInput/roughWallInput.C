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

#include "roughWallInput.H"
#include "OStringStream.H"

#include <algorithm>
#include <numeric>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Levenshtein distance of two words (for the closest valid keyword)
std::size_t editDistance(const std::string& a, const std::string& b)
{
    std::vector<std::size_t> row(b.size() + 1);
    std::iota(row.begin(), row.end(), 0);
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const std::size_t above = row[j];
            row[j] = std::min
            (
                {row[j] + 1, row[j - 1] + 1, diagonal + (a[i-1] != b[j-1])}
            );
            diagonal = above;
        }
    }
    return row[b.size()];
}


//- The entry keyword of dict as text: its tokens in quotes, "a
//- dictionary" or "missing"
string entryText(const dictionary& dict, const word& keyword)
{
    const entry* e = roughWallCompat::findLiteral(dict, keyword);
    if (!e || e->isDict())
    {
        return e ? "a dictionary" : "missing";
    }
    OStringStream os;
    const ITstream& is = e->stream();
    forAll(is, toki)
    {
        os  << (toki ? " " : "") << is[toki];
    }
    return "'" + os.str() + "'";
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::roughWallInput::range::allowed(const bool integer) const
{
    // OpenFOAM's form of a bound, "inf" and "-inf" for none
    const auto text = [](const scalar x)
    {
        return x >= GREAT ? "inf" : x <= -GREAT ? "-inf" : string(name(x));
    };
    return
        (integer ? "an integer in [" : "a number in [")
      + text(min) + ", " + text(max) + "]";
}


void Foam::roughWallInput::fatalBadEntry
(
    const dictionary& dict,
    const word& keyword,
    const string& allowed,
    const string& why
)
{
    FatalIOErrorInFunction(dict)
        << "Bad entry for keyword '" << keyword.c_str() << "' in dictionary "
        << dict.name().c_str() << nl
        << "    found:   " << entryText(dict, keyword).c_str()
        << (why.empty() ? string() : " (" + why + ")").c_str() << nl
        << "    allowed: " << allowed.c_str() << nl
        << exit(FatalIOError);

    // exit() does not return; keep [[noreturn]] honest for the compiler
    std::abort();
}


void Foam::roughWallInput::checkKeywords
(
    const dictionary& dict,
    const wordList& used,
    const string& where
)
{
    for (const entry& e : dict)
    {
        const word& key = e.keyword();
        if (std::find(used.begin(), used.end(), key) == used.end())
        {
            // With the closest used keyword
            const auto closest = std::min_element
            (
                used.begin(), used.end(),
                [&](const word& a, const word& b)
                {
                    return editDistance(key, a) < editDistance(key, b);
                }
            );
            fatalBadEntry
            (
                dict, key,
                "the keywords of " + where + ": " + joined(used)
              + (closest == used.end() ? "" : " (closest: " + *closest + ")")
            );
        }
    }
}


Foam::string Foam::roughWallInput::joined(const UList<word>& names)
{
    string s;
    for (const word& name : names)
    {
        s += (s.empty() ? "" : " ") + name;
    }
    return s;
}


Foam::string Foam::roughWallInput::readWhole
(
    const entry& e,
    const std::function<void()>& read
)
{
    // OpenFOAM's FatalError and FatalIOError thrown for the call only (every
    // release has throwExceptions(), off by default)
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();
    string why;
    try
    {
        read();
        const string left =
            e.isDict() ? string() : roughWallCompat::unreadTokens(e);
        if (!left.empty())
        {
            why = "tokens left over after reading: '" + left + "'";
        }
    }
    catch (const error& err)
    {
        // Its first line: what is wrong (not the lists of valid names)
        why = err.message();
        why = why.empty() ? "stopped" : why.substr(0, why.find('\n'));
    }
    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
    return why;
}


// ************************************************************************* //
