// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Reader of a measured wall profile (a profilometer's trace) for the
// rolling-sphere envelope (rollingSphereEnvelope.hpp). Framework-free, so
// that roughWallStats and the OpenFOAM adapter read the same files.
//
// Accepted format (ASCII, as profilometers export a trace):
//  - one point per line: x z, two numbers separated by blanks, tabs, a
//    comma or a semicolon (decimal point, not decimal comma); x strictly
//    increasing, spacing need not be uniform;
//  - blank lines and comment lines (first non-blank character # or %, or
//    //) anywhere;
//  - header lines (column names, instrument data) before the first point:
//    any line before the first point whose first field is not a number is
//    skipped; after the first point every line must be a point;
//  - units: metres, unless a line "# units XU ZU" (or "% units", "units:"
//    accepted after the #) before the first point gives them; XU, ZU each
//    one of m, mm, um (also µm, micron), nm. E.g. "# units mm um".
// Errors (ProfileFileError, message "FILE:LINE: what"): the file cannot be
// opened; a line that is not two finite numbers (NaN, inf, a third column,
// text); a number a double cannot hold (1e400, 1e-400); x not strictly
// increasing; fewer than minPoints points.
#pragma once

#include "rollingSphereEnvelope.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace roughWall
{

//- Fewest points of a profile file
constexpr std::size_t minProfilePoints = 10;


//- A bad profile file: the message names the file and the line (0: none)
struct ProfileFileError : std::runtime_error
{
    std::string file;
    std::size_t line;

    ProfileFileError(const std::string& f, const std::size_t l, const std::string& what)
    :
        std::runtime_error
        (
            f + (l > 0 ? ":" + std::to_string(l) : std::string()) + ": " + what
        ),
        file(f),
        line(l)
    {}
};


namespace detail
{

//- The fields of a line split at blanks, tabs, commas and semicolons
inline std::vector<std::string> profileFields(const std::string& line)
{
    std::vector<std::string> fields;
    std::string field;
    for (const char c : line)
    {
        if (c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r')
        {
            if (!field.empty()) fields.push_back(field);
            field.clear();
        }
        else
        {
            field += c;
        }
    }
    if (!field.empty()) fields.push_back(field);
    return fields;
}

//- What a field is: a number, text, or a number that a double cannot hold
//  (strtod's ERANGE: beyond 1.8e308 in magnitude, or nonzero below 2.2e-308,
//  e.g. 1e400, 1e-400)
enum class ProfileField { number, text, outOfRange };

//- Parse a whole field as a number
inline ProfileField profileNumber(const std::string& text, double& value)
{
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    value = std::strtod(begin, &end);
    if (text.empty() || end != begin + text.size())
    {
        return ProfileField::text;
    }
    return errno == ERANGE ? ProfileField::outOfRange : ProfileField::number;
}

//- Metres per unit; 0 if unknown
inline double profileUnit(const std::string& u)
{
    if (u == "m") return 1;
    if (u == "mm") return 1e-3;
    if (u == "um" || u == "\xC2\xB5m" || u == "micron") return 1e-6;
    if (u == "nm") return 1e-9;
    return 0;
}

} // End namespace detail


//- Read a profile from a stream; name is the file name for the messages
inline SampledProfile readProfile
(
    std::istream& in,
    const std::string& name,
    const std::size_t minPoints = minProfilePoints
)
{
    SampledProfile p;
    p.ends = ProfileEnds::trimmed;
    double xUnit = 1, zUnit = 1;
    std::string line;
    std::size_t lineNo = 0;
    bool data = false;
    while (std::getline(in, line))
    {
        ++lineNo;
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos)
        {
            continue;
        }
        const bool comment = line[first] == '#' || line[first] == '%'
            || line.compare(first, 2, "//") == 0;
        if (comment)
        {
            std::vector<std::string> f =
                detail::profileFields(line.substr(first + (line[first] == '/' ? 2 : 1)));
            if (!f.empty() && (f[0] == "units" || f[0] == "units:"))
            {
                if (data)
                {
                    throw ProfileFileError
                    (
                        name, lineNo, "units must be given before the first point"
                    );
                }
                if (f.size() != 3 || !detail::profileUnit(f[1]) || !detail::profileUnit(f[2]))
                {
                    throw ProfileFileError
                    (
                        name, lineNo,
                        "units line must be '# units XU ZU' with XU, ZU one of "
                        "m, mm, um, nm"
                    );
                }
                xUnit = detail::profileUnit(f[1]);
                zUnit = detail::profileUnit(f[2]);
            }
            continue;
        }
        using detail::ProfileField;
        const std::vector<std::string> f = detail::profileFields(line);
        double x = 0, z = 0;
        const ProfileField fx =
            f.empty() ? ProfileField::text : detail::profileNumber(f[0], x);
        if (!data && fx == ProfileField::text)
        {
            continue;   // a header line before the first point
        }
        const ProfileField fz =
            f.size() < 2 ? ProfileField::text : detail::profileNumber(f[1], z);
        if (fx == ProfileField::outOfRange || fz == ProfileField::outOfRange)
        {
            throw ProfileFileError
            (
                name, lineNo,
                "a number out of the range of a double (magnitude 2.2e-308 "
                "to 1.8e308, or 0): '" + line.substr(first) + "'"
            );
        }
        if (f.size() != 2 || fx != ProfileField::number || fz != ProfileField::number)
        {
            throw ProfileFileError
            (
                name, lineNo,
                "expected two numbers 'x z', got '" + line.substr(first) + "'"
            );
        }
        if (!std::isfinite(x) || !std::isfinite(z))
        {
            throw ProfileFileError
            (
                name, lineNo, "not a finite number: '" + line.substr(first) + "'"
            );
        }
        x *= xUnit;
        z *= zUnit;
        if (!p.x.empty() && !(x > p.x.back()))
        {
            std::ostringstream what;
            what.precision(12);
            what << "x = " << x << " m is not above the previous x = "
                 << p.x.back() << " m (x must increase strictly)";
            throw ProfileFileError(name, lineNo, what.str());
        }
        data = true;
        p.x.push_back(x);
        p.z.push_back(z);
    }
    if (in.bad())
    {
        throw ProfileFileError(name, lineNo, "read error");
    }
    if (p.x.size() < minPoints)
    {
        throw ProfileFileError
        (
            name, 0,
            std::to_string(p.x.size()) + " points in " + std::to_string(lineNo)
          + " lines, at least " + std::to_string(minPoints) + " needed"
        );
    }
    return p;
}


//- Read a profile file
inline SampledProfile readProfileFile
(
    const std::string& file,
    const std::size_t minPoints = minProfilePoints
)
{
    std::ifstream in(file);
    if (!in)
    {
        throw ProfileFileError(file, 0, "cannot open the profile file");
    }
    return readProfile(in, file, minPoints);
}

} // End namespace roughWall
