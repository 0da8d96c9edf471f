// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later

#include "commandLine.hh"
#include "profileRoughness.hpp"
#include "rollingSphereEnvelope.hpp"
#include "limitsAndUnits.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace roughWallStats
{

//- A limit as the usage text shows it (integers without a decimal point)
std::string limitText(const double x)
{
    std::ostringstream os;
    os << x;
    return os.str();
}

std::string usage()
{
    const std::string maxDelta = limitText(roughWall::limits::maxRoughnessAngleDeg);
    const std::string minCollisions = limitText(roughWall::limits::minMaxFacetCollisions);
    const std::string maxCollisions = limitText(roughWall::limits::maxMaxFacetCollisions);
    const std::string defaultCollisions =
        limitText(roughWall::limits::defaultMaxFacetCollisions);
    return R"(Usage: roughWallStats [options]

Restitution-coefficient statistics of Derevich's rough-wall collision model
(the paper's figures 2 and 3). Angles in degrees. CSV on stdout or --output.

Model (defaults: glass beads on steel, the paper's d_p = 110 um case):
  --Delta D        sd of the facet tilt [deg], 0 <= D <= )" + maxDelta + R"(        (8)
  or, instead of --Delta, the wall's profile (ISO 4287, metres) and a particle:
  --Ra, --Rq, --Rz H  one or more heights: mean, rms, peak-to-valley [m]
  --RSm L          mean width of the profile elements [m]
  --diameter D     particle diameter [m]; Delta = atan(2 pi Rq / max(L, D)),
                   Rq = sqrt(pi/2) Ra or Rz/4.11 if not given (as for
                   a Gaussian profile, the same Rq as below)
                   (docs/roughWallInteraction.md; Delta printed on stderr)
  --e E            normal restitution of a facet, 0 <= E <= 1      (0.8)
  --mu0 M          static friction, M >= 0                         (0.4)
  --mud M          dynamic friction, 0 <= M <= mu0                 (0.4)
  e, mu0, mud as functions of the facet impact (docs/roughWallInteraction.md),
  each instead of its constant:
  --e-table FILE   pairs "argument value" (two columns, or OpenFOAM's
                   ((x y) ...); '#' and '//' comments), argument ascending,
                   linear in between, constant beyond the ends
  --e-polynomial C0,C1,...  e = C0 + C1 x + C2 x^2 + ...
  --mu0-table, --mu0-polynomial, --mud-table, --mud-polynomial: the same
                   for the friction; their argument is the facet impact angle
  --e-argument A   angle (facet impact angle [deg], (0, 90]) or normalSpeed
                   (normal impact speed on the facet [m/s])      (angle)
  --speed V        incident speed [m/s], with --e-argument normalSpeed (1)
                   Bounds (e in [0, 1], mu0 >= 0, 0 <= mud <= mu0) are
                   checked at every table node and on a 0.01 deg (or V/9000)
                   grid at start-up, and at every collision.
  --spin A         incident spin A_Omega = r Omega'_z / V'_x,
                   Omega_z along t x N (any real)                   (0)
  --alpha LIST     incidence angles in (0, 90]: a,b,c and/or
                   start:step:stop                     (1,2,5,10,15,30,45,89)
What is computed:
  --method M       quadrature (deterministic, one facet collision) or
                   montecarlo (exact sampler, standard errors se_*) (quadrature)
  --recollide      the full operator: new facets until the particle leaves,
                   as the OpenFOAM model does (Monte Carlo only)
  --max-collisions N  bound on facet collisions with --recollide,
                   )" + minCollisions + " <= N <= " + maxCollisions + R"( ()" + defaultCollisions + R"()
  --lateral        isotropic 3-D roughness: extra sideways facet tilt
                   (Monte Carlo only)
  --samples N      Monte Carlo samples per angle, >= 2              (1e6)
  --seed S         Monte Carlo seed, integer 0 .. 2^64-1           (1)
  --tolerance T    quadrature tolerance (error / integral of |f|),
                   1e-14 <= T <= 1e-3                               (1e-11)
  --threads N      threads for the angles, 0 = one per core        (0)
Distribution of one coefficient (one --alpha):
  --pdf K          K = kn, kt or kOmega: density by the change of variables
                   (2.8) at bin centres and per bin, next to the Monte Carlo
                   histogram of the same bins
  --bins N         number of bins, 1 .. 100000                      (50)
  --range LO,HI    bin range (default: covers all but 2e-4 of the probability)
Output:
  --output FILE    write the CSV to FILE instead of stdout
  --digits N       significant digits of the numbers, 1 .. 17      (12)
                   (17: exact, every double reads back unchanged)
  --plot FILE      draw it (means +-1 sd against alpha, or pdf against
                   histogram, or with --d Delta against d/RSm) with
                   matplotlib; FILE.png, .pdf or .svg
  --help           this text
Delta(d) of the wall itself (a table, no restitution statistics):
  --d LIST         particle diameters [m] > 0: a,b,c and/or start:step:stop;
                   prints Delta(d) = rms tilt of the rolling-sphere envelope,
                   its mean, sd, skewness, excess kurtosis, and the estimate
                   atan(2 pi Rq / max(RSm, d)) beside it, for either
  --profile FILE   a measured trace: two columns x z [m] (or '# units XU ZU'),
                   levelled by its least-squares line; Rq and RSm (mean
                   spacing of its zero up-crossings) measured on it, or
  --Rq/--Ra/--Rz H and --RSm L: a synthetic Gaussian profile with that rms
                   height and Rice width (Rq = sqrt(pi/2) Ra, Rq = Rz/4.11:
                   Gaussian, Rz over sampling lengths of 5 RSm); --seed S
                   (1) and --length N (5000: length in RSm, 10 .. 1e6)
Documentation: docs/roughWallStats.md
)";
}

namespace
{

[[noreturn]] void fail(const std::string& message)
{
    throw UsageError(message);
}

std::string quoted(const std::string& s)
{
    return "'" + s + "'";
}

double number(const std::string& option, const std::string& text)
{
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(begin, &end);
    if (text.empty() || end != begin + text.size() || errno == ERANGE || !std::isfinite(value))
    {
        fail(option + " needs a finite number, got " + quoted(text));
    }
    return value;
}

long long integer
(
    const std::string& option,
    const std::string& text,
    long long lo,
    long long hi
)
{
    const double value = number(option, text);
    if (value != std::floor(value) || value < lo || value > hi)
    {
        std::ostringstream message;
        message << option << " must be an integer in [" << lo << ", " << hi
                << "], got " << quoted(text);
        fail(message.str());
    }
    return static_cast<long long>(value);
}

std::vector<std::string> split(const std::string& text, char separator)
{
    std::vector<std::string> parts;
    std::string part;
    std::istringstream stream(text);
    while (std::getline(stream, part, separator))
    {
        parts.push_back(part);
    }
    if (!text.empty() && text.back() == separator)
    {
        parts.push_back("");
    }
    return parts;
}

//- Numbers and start:step:stop ranges separated by commas, for an option
//  whose values are counted as noun (at most maxCount in one range)
std::vector<double> numberList
(
    const std::string& option,
    const std::string& text,
    const double maxCount,
    const std::string& noun
)
{
    std::vector<double> values;
    for (const std::string& item : split(text, ','))
    {
        const std::vector<std::string> range = split(item, ':');
        if (range.size() == 1)
        {
            values.push_back(number(option, item));
        }
        else if (range.size() == 3)
        {
            const double start = number(option, range[0]);
            const double step = number(option, range[1]);
            const double stop = number(option, range[2]);
            if (!(step > 0) || stop < start)
            {
                fail(option + " range " + quoted(item)
                     + " must be start:step:stop with step > 0 and stop >= start");
            }
            const double count = std::floor((stop - start)/step*(1 + 1e-12)) + 1;
            if (count > maxCount)
            {
                std::ostringstream message;
                message << option << " range " << quoted(item) << " has more than "
                        << maxCount << ' ' << noun;
                fail(message.str());
            }
            for (long long i = 0; i < static_cast<long long>(count); ++i)
            {
                values.push_back(std::min(stop, start + i*step));
            }
        }
        else
        {
            fail(option + " needs numbers or start:step:stop ranges separated by commas, got "
                 + quoted(item));
        }
    }
    return values;
}

std::vector<double> angleList(const std::string& text)
{
    const std::vector<double> angles = numberList("--alpha", text, 100000, "angles");
    for (const double a : angles)
    {
        if (!(a > 0 && a <= 90))
        {
            std::ostringstream message;
            message << "--alpha values must be in (0, 90] degrees, got " << a;
            fail(message.str());
        }
        if (a < 1e-300)
        {
            std::ostringstream message;
            message << "--alpha values must be at least 1e-300 degrees (k_n ~ 1/alpha "
                    << "overflows below), got " << a;
            fail(message.str());
        }
    }
    return angles;
}

//- Diameters [m] > 0: numbers and start:step:stop ranges
std::vector<double> diameterList(const std::string& text)
{
    const std::vector<double> ds = numberList("--d", text, 10000, "diameters");
    for (const double d : ds)
    {
        if (!(d > 0))
        {
            std::ostringstream message;
            message << "--d values must be particle diameters > 0 [m], got " << d;
            fail(message.str());
        }
    }
    if (ds.empty())
    {
        fail("--d needs at least one diameter");
    }
    return ds;
}

//- A table file: pairs of numbers, parentheses and commas as spaces, '#'
//  and '//' comments; the argument strictly ascending
roughWall::LinearTable readTable(const std::string& option, const std::string& file)
{
    std::ifstream in(file);
    if (!in)
    {
        fail(option + " cannot read " + quoted(file));
    }
    std::vector<double> numbers;
    std::string line;
    for (int lineNo = 1; std::getline(in, line); ++lineNo)
    {
        for (const char* comment : {"#", "//"})
        {
            const auto at = line.find(comment);
            if (at != std::string::npos) line.erase(at);
        }
        for (char& c : line)
        {
            if (c == '(' || c == ')' || c == ',' || c == ';') c = ' ';
        }
        std::istringstream words(line);
        std::string word;
        while (words >> word)
        {
            numbers.push_back
            (
                number(option + " " + file + " line " + std::to_string(lineNo), word)
            );
        }
    }
    if (numbers.size() < 2 || numbers.size() % 2)
    {
        fail(option + " " + quoted(file) + " needs pairs 'argument value' (at least one), "
             "got " + std::to_string(numbers.size()) + " numbers");
    }
    roughWall::LinearTable table;
    for (std::size_t i = 0; i < numbers.size(); i += 2)
    {
        if (!table.points.empty() && !(numbers[i] > table.points.back().first))
        {
            std::ostringstream message;
            message << option << " " << quoted(file) << ": the arguments must ascend, got "
                    << numbers[i] << " after " << table.points.back().first;
            fail(message.str());
        }
        table.points.emplace_back(numbers[i], numbers[i + 1]);
    }
    return table;
}

//- C0,C1,... : C0 + C1 x + C2 x^2 + ... (Horner)
std::function<double(double)> readPolynomial(const std::string& option, const std::string& text)
{
    std::vector<double> c;
    for (const std::string& item : split(text, ','))
    {
        c.push_back(number(option, item));
    }
    if (c.empty())
    {
        fail(option + " needs coefficients C0,C1,...");
    }
    return [c](double x)
    {
        double y = 0;
        for (auto i = c.rbegin(); i != c.rend(); ++i) y = y*x + *i;
        return y;
    };
}

//- --e-table, --e-polynomial, ... into o.model.impact, and their bounds
//  checked on the table nodes and a fine grid of the argument
void readImpactDependence(Options& o, std::map<std::string, std::string>& given)
{
    const auto has = [&](const std::string& option) { return given.count(option) > 0; };
    ImpactDependence& f = o.model.impact;
    std::vector<double> eNodes;
    const auto read = [&]
    (
        const std::string& name,            // e, mu0, mud
        std::function<double(double)>& function,
        std::vector<double>* nodes
    )
    {
        const std::string table = "--" + name + "-table";
        const std::string polynomial = "--" + name + "-polynomial";
        if (has(table) && has(polynomial))
        {
            fail("give " + table + " or " + polynomial + ", not both");
        }
        if ((has(table) || has(polynomial)) && has("--" + name))
        {
            fail("give --" + name + " (a constant) or " + (has(table) ? table : polynomial)
                 + " (a function), not both");
        }
        if (has(table))
        {
            const roughWall::LinearTable t = readTable(table, given[table]);
            for (const auto& point : t.points) nodes->push_back(point.first);
            function = t;
        }
        else if (has(polynomial))
        {
            function = readPolynomial(polynomial, given[polynomial]);
        }
    };
    read("e", f.e, &eNodes);
    read("mu0", f.mu0, &f.angleKinks);
    read("mud", f.muD, &f.angleKinks);

    if (has("--e-argument"))
    {
        const std::string& a = given["--e-argument"];
        if (a == "angle") f.eArgument = roughWall::ImpactArgument::angle;
        else if (a == "normalSpeed") f.eArgument = roughWall::ImpactArgument::normalSpeed;
        else fail("--e-argument must be angle or normalSpeed, got " + quoted(a));
        if (!f.e) fail("--e-argument needs --e-table or --e-polynomial");
    }
    const bool ofSpeed = f.eArgument == roughWall::ImpactArgument::normalSpeed;
    if (has("--speed"))
    {
        f.speed = number("--speed", given["--speed"]);
        if (!(f.speed > 0)) fail("--speed must be an incident speed > 0 [m/s], got " + given["--speed"]);
        if (!ofSpeed) fail("--speed needs --e-argument normalSpeed");
    }
    if (!ofSpeed)
    {
        f.angleKinks.insert(f.angleKinks.end(), eNodes.begin(), eNodes.end());
    }
    if (!f.any())
    {
        return;
    }

    // The bounds at the nodes and on a grid: the per-collision check stays
    // (a polynomial can leave them between the grid points)
    std::vector<double> angles = f.angleKinks;
    std::vector<double> speeds = ofSpeed ? eNodes : std::vector<double>{};
    for (int i = 0; i <= 9000; ++i)
    {
        angles.push_back(std::max(1e-3, 0.01*i));
        speeds.push_back(f.speed*std::max(1e-6, i/9000.0));
    }
    const Model& model = o.model;
    try
    {
        for (const double a : angles)
        {
            roughWall::FacetImpact impact;
            impact.angleDeg = a;
            impact.normalSpeed = ofSpeed ? f.speed : std::sin(a*(roughWall::pi/180));
            ModelCoefficients{&model}({impact.angleDeg, impact.normalSpeed/f.speed});
        }
        for (const double w : ofSpeed ? speeds : std::vector<double>{})
        {
            ModelCoefficients{&model}({90, w/f.speed});
        }
    }
    catch (const roughWall::CoefficientOutOfRange& error)
    {
        // The options that gave the coefficient (and mu0 for muD <= mu0)
        const auto optionOf = [&](const std::string& name)
        {
            for (const char* kind : {"-table", "-polynomial"})
            {
                if (has("--" + name + kind)) return "--" + name + kind;
            }
            return "--" + name;
        };
        const std::string& c = error.coefficient();
        const std::string options = c == "muD"
            ? optionOf("mud") + " with " + optionOf("mu0") : optionOf(c);
        fail(options + ": " + error.what());
    }
}

} // namespace

Options parseCommandLine(int argc, const char* const argv[])
{
    // Options taking a value, and flags
    static const std::set<std::string> valued
    {
        "--Delta", "--e", "--mu0", "--mud", "--spin", "--alpha", "--method",
        "--samples", "--seed", "--max-collisions", "--tolerance", "--threads",
        "--pdf", "--bins", "--range", "--plot", "--output", "--digits",
        "--Ra", "--Rq", "--Rz", "--RSm", "--diameter", "--d", "--profile", "--length",
        "--e-table", "--mu0-table", "--mud-table",
        "--e-polynomial", "--mu0-polynomial", "--mud-polynomial",
        "--e-argument", "--speed"
    };
    static const std::set<std::string> flags{"--recollide", "--lateral", "--help", "-h"};

    std::map<std::string, std::string> given;
    for (int i = 1; i < argc; ++i)
    {
        std::string option = argv[i];
        std::string value;
        bool hasValue = false;
        const auto equals = option.find('=');
        if (option.rfind("--", 0) == 0 && equals != std::string::npos)
        {
            value = option.substr(equals + 1);
            option = option.substr(0, equals);
            hasValue = true;
        }
        if (flags.count(option))
        {
            if (hasValue)
            {
                fail(option + " takes no value");
            }
        }
        else if (valued.count(option))
        {
            if (!hasValue)
            {
                if (i + 1 >= argc)
                {
                    fail(option + " needs a value");
                }
                value = argv[++i];
            }
        }
        else
        {
            fail("unknown option " + quoted(option) + " (see --help)");
        }
        if (given.count(option))
        {
            fail(option + " given twice");
        }
        given[option] = value;
    }

    Options o;
    const auto has = [&](const char* option) { return given.count(option) > 0; };

    // The output options, the same for the Delta(d) table and the statistics
    const auto readOutputOptions = [&]()
    {
        if (has("--digits"))
        {
            o.digits = static_cast<int>(integer("--digits", given["--digits"], 1, 17));
        }
        if (has("--plot")) o.plotFile = given["--plot"];
        if (has("--output")) o.outputFile = given["--output"];
        for (const auto* option : {"--plot", "--output"})
        {
            if (has(option) && given[option].empty())
            {
                fail(std::string(option) + " needs a file name");
            }
        }
    };
    if (has("--help") || has("-h"))
    {
        o.help = true;
        return o;
    }

    if (has("--Delta"))
    {
        o.DeltaDeg = number("--Delta", given["--Delta"]);
        if (!(o.DeltaDeg >= 0 && o.DeltaDeg <= roughWall::limits::maxRoughnessAngleDeg))
        {
            fail("--Delta must be in [0, " + limitText(roughWall::limits::maxRoughnessAngleDeg)
               + "] degrees (the roughness sd; beyond that too many facets are overhangs), got "
               + given["--Delta"]);
        }
    }

    // The Delta(d) table of the wall's profile
    if (has("--d") || has("--profile") || has("--length"))
    {
        if (!has("--d"))
        {
            fail(std::string(has("--profile") ? "--profile" : "--length")
               + " needs --d LIST (the particle diameters of the Delta(d) table)");
        }
        for (const char* other :
             {"--Delta", "--diameter", "--e", "--mu0", "--mud", "--spin", "--alpha",
              "--method", "--samples", "--max-collisions", "--tolerance", "--threads",
              "--pdf", "--bins", "--range", "--recollide", "--lateral"})
        {
            if (has(other))
            {
                fail(std::string(other) + " has no meaning with --d (the Delta(d) table of "
                     "the wall's profile, no restitution statistics)");
            }
        }
        o.envelope = true;
        EnvelopeSettings& e = o.envelopeSettings;
        e.diameters = diameterList(given["--d"]);
        if (has("--profile"))
        {
            for (const char* other : {"--Ra", "--Rq", "--Rz", "--RSm", "--length", "--seed"})
            {
                if (has(other))
                {
                    fail(std::string(other) + " is for the synthetic profile: give either "
                         "--profile FILE or --Rq/--Ra/--Rz and --RSm");
                }
            }
            e.profileFile = given["--profile"];
            if (e.profileFile.empty())
            {
                fail("--profile needs a file name");
            }
        }
        else
        {
            roughWall::ProfileRoughness p;
            if (has("--Ra")) p.Ra = number("--Ra", given["--Ra"]);
            if (has("--Rq")) p.Rq = number("--Rq", given["--Rq"]);
            if (has("--Rz")) p.Rz = number("--Rz", given["--Rz"]);
            if (has("--RSm")) p.RSm = number("--RSm", given["--RSm"]);
            const roughWall::ProfileRoughnessError error =
                roughWall::checkProfileRoughness(p, has("--Ra"), has("--Rq"), has("--Rz"));
            if (!error.keyword.empty())
            {
                fail("--" + error.keyword + " must be " + error.allowed
                   + (has(("--" + error.keyword).c_str())
                      ? ", got " + given["--" + error.keyword] : ", missing")
                   + " (or --profile FILE)");
            }
            // The Rq that the check above bounds (as for a Gaussian
            // profile, the synthetic profile's own conversion)
            e.Rq = p.rmsHeight();
            e.RSm = p.RSm;
            if (p.Rq <= 0)
            {
                std::ostringstream note;
                note.precision(6);
                note << "Rq = " << e.Rq << " m from "
                     << (p.Ra > 0 ? "Ra as for a Gaussian profile (Rq = sqrt(pi/2) Ra)"
                                  : "Rz as for a Gaussian profile with Rz over sampling "
                                    "lengths of 5 RSm (Rq = Rz/4.11)");
                o.notes.push_back(note.str());
            }
            if (has("--length"))
            {
                e.lengthPerRSm = number("--length", given["--length"]);
                if (!(e.lengthPerRSm >= 10 && e.lengthPerRSm <= 1e6))
                {
                    fail("--length must be the synthetic profile's length in RSm, in [10, 1e6], "
                         "got " + given["--length"]);
                }
            }
            if (has("--seed"))
            {
                const std::string& text = given["--seed"];
                char* end = nullptr;
                errno = 0;
                const unsigned long long seed = std::strtoull(text.c_str(), &end, 10);
                if (text.empty() || text[0] == '-' || end != text.c_str() + text.size()
                 || errno == ERANGE)
                {
                    fail("--seed must be an integer in [0, 2^64 - 1], got " + quoted(text));
                }
                e.seed = seed;
            }
        }
        readOutputOptions();
        return o;
    }

    // Or Delta from the wall's profile parameters and the particle diameter
    const bool profile =
        has("--Ra") || has("--Rq") || has("--Rz") || has("--RSm") || has("--diameter");
    if (profile)
    {
        if (has("--Delta"))
        {
            fail("give either --Delta or the profile parameters --Ra/--Rq/--Rz, --RSm "
                 "and --diameter, not both");
        }
        roughWall::ProfileRoughness p;
        if (has("--Ra")) p.Ra = number("--Ra", given["--Ra"]);
        if (has("--Rq")) p.Rq = number("--Rq", given["--Rq"]);
        if (has("--Rz")) p.Rz = number("--Rz", given["--Rz"]);
        if (has("--RSm")) p.RSm = number("--RSm", given["--RSm"]);
        const roughWall::ProfileRoughnessError error =
            roughWall::checkProfileRoughness(p, has("--Ra"), has("--Rq"), has("--Rz"));
        if (!error.keyword.empty())
        {
            fail("--" + error.keyword + " must be " + error.allowed
               + (has(("--" + error.keyword).c_str())
                  ? ", got " + given["--" + error.keyword] : ", missing"));
        }
        if (!has("--diameter"))
        {
            fail("--diameter (the particle diameter [m], > 0) is needed with the profile "
                 "parameters");
        }
        const double d = number("--diameter", given["--diameter"]);
        if (!(d > 0))
        {
            fail("--diameter must be a particle diameter > 0 [m], got " + given["--diameter"]);
        }
        const roughWall::RoughnessCorrelation correlation(p);
        o.DeltaDeg = roughWall::limits::radToDeg(correlation.angleUncached(d));
        std::ostringstream note;
        note.precision(6);
        note << "Delta = " << o.DeltaDeg << " deg = atan(2 pi Rq / max(RSm, d)) with Rq = "
             << p.rmsHeight() << " m" << (p.Rq > 0 ? "" : " (from " + std::string(
                    p.Ra > 0 ? "Ra" : "Rz") + ", as for a Gaussian profile)")
             << ", RSm = " << p.RSm << " m, d = " << d << " m ("
             << (d > p.RSm ? "d > RSm: the particle bridges the roughness"
                           : "d <= RSm: the particle meets the flanks")
             << ")";
        o.notes.push_back(note.str());
    }
    o.model.Delta = roughWall::limits::degToRad(o.DeltaDeg);

    FacetMaterial& m = o.model.material;
    if (has("--e"))
    {
        m.e = number("--e", given["--e"]);
        if (!(m.e >= 0 && m.e <= 1))
        {
            fail("--e must be in [0, 1], got " + given["--e"]);
        }
    }
    if (has("--mu0"))
    {
        m.mu0 = number("--mu0", given["--mu0"]);
        if (!(m.mu0 >= 0))
        {
            fail("--mu0 must be >= 0, got " + given["--mu0"]);
        }
    }
    if (has("--mud"))
    {
        m.muD = number("--mud", given["--mud"]);
        if (!(m.muD >= 0))
        {
            fail("--mud must be >= 0, got " + given["--mud"]);
        }
    }
    if (m.muD > m.mu0)
    {
        std::ostringstream message;
        message << "--mud must be in [0, mu0] (dynamic friction cannot exceed static "
                << "friction), got mud = " << m.muD << " > mu0 = " << m.mu0;
        fail(message.str());
    }
    readImpactDependence(o, given);
    if (has("--spin"))
    {
        o.model.AOmega = number("--spin", given["--spin"]);
    }
    if (has("--alpha"))
    {
        o.alphaDeg = angleList(given["--alpha"]);
        if (o.alphaDeg.empty())
        {
            fail("--alpha needs at least one angle in (0, 90]");
        }
    }

    if (has("--method"))
    {
        const std::string& method = given["--method"];
        if (method == "quadrature") o.method = Method::quadrature;
        else if (method == "montecarlo") o.method = Method::montecarlo;
        else fail("--method must be quadrature or montecarlo, got " + quoted(method));
    }
    o.monteCarlo.recollide = has("--recollide");
    o.monteCarlo.lateral = has("--lateral");
    if (o.monteCarlo.recollide || o.monteCarlo.lateral)
    {
        const char* which = o.monteCarlo.recollide ? "--recollide" : "--lateral";
        if (has("--method") && o.method == Method::quadrature)
        {
            fail(std::string(which) + " needs --method montecarlo: the quadrature is of one "
                 "in-plane facet collision (repeated collisions are nested integrals of "
                 "unbounded depth; see docs/roughWallStats.md)");
        }
        if (!has("--method") && !has("--pdf"))
        {
            o.notes.push_back(std::string(which) + " is Monte Carlo only: using --method montecarlo");
        }
        o.method = Method::montecarlo;
    }
    if (has("--max-collisions"))
    {
        o.monteCarlo.maxFacetCollisions =
            static_cast<int>(integer("--max-collisions", given["--max-collisions"],
                                     roughWall::limits::minMaxFacetCollisions,
                                     roughWall::limits::maxMaxFacetCollisions));
        if (!o.monteCarlo.recollide)
        {
            fail("--max-collisions needs --recollide");
        }
    }
    if (has("--samples"))
    {
        o.monteCarlo.samples = integer("--samples", given["--samples"], 2, 100000000000LL);
    }
    if (has("--seed"))
    {
        const std::string& text = given["--seed"];
        char* end = nullptr;
        errno = 0;
        const unsigned long long seed = std::strtoull(text.c_str(), &end, 10);
        if (text.empty() || text[0] == '-' || end != text.c_str() + text.size() || errno == ERANGE)
        {
            fail("--seed must be an integer in [0, 2^64 - 1], got " + quoted(text));
        }
        o.monteCarlo.seed = seed;
    }
    if (has("--tolerance"))
    {
        o.quadrature.tolerance = number("--tolerance", given["--tolerance"]);
        if (!(o.quadrature.tolerance >= 1e-14 && o.quadrature.tolerance <= 1e-3))
        {
            fail("--tolerance must be in [1e-14, 1e-3], got " + given["--tolerance"]);
        }
    }
    if (has("--threads"))
    {
        o.threads = static_cast<int>(integer("--threads", given["--threads"], 0, 1024));
    }

    if (has("--pdf"))
    {
        const std::string& k = given["--pdf"];
        o.pdf = true;
        if (k == "kn") o.pdfOf = Coefficient::kn;
        else if (k == "kt") o.pdfOf = Coefficient::kt;
        else if (k == "kOmega") o.pdfOf = Coefficient::kOmega;
        else fail("--pdf must be kn, kt or kOmega, got " + quoted(k));
        if (o.alphaDeg.size() != 1 || !has("--alpha"))
        {
            fail("--pdf needs exactly one incidence angle: --alpha A");
        }
        if (o.pdfOf != Coefficient::kn && o.alphaDeg[0] == 90)
        {
            fail("--pdf " + k + " is undefined at --alpha 90 (V'_x = 0): use an angle below 90");
        }
        if (o.model.impact.any())
        {
            fail("--pdf needs constant e, mu0, mud (the change of variables (2.8) "
                 "has no derivative of a table); give the statistics of a table "
                 "without --pdf");
        }
        if (!(o.model.Delta > 0) && !o.monteCarlo.recollide && !o.monteCarlo.lateral)
        {
            fail("--pdf needs --Delta > 0 (with Delta = 0 every coefficient has a single value)");
        }
        if (has("--method"))
        {
            o.notes.push_back("--method has no effect with --pdf (both the density and the "
                              "histogram are written)");
        }
    }
    if (has("--bins"))
    {
        if (!o.pdf) fail("--bins needs --pdf");
        o.bins = static_cast<int>(integer("--bins", given["--bins"], 1, 100000));
    }
    if (has("--range"))
    {
        if (!o.pdf) fail("--range needs --pdf");
        const std::vector<std::string> ends = split(given["--range"], ',');
        if (ends.size() != 2)
        {
            fail("--range must be LO,HI, got " + quoted(given["--range"]));
        }
        o.rangeLo = number("--range", ends[0]);
        o.rangeHi = number("--range", ends[1]);
        if (!(o.rangeHi > o.rangeLo))
        {
            fail("--range must be LO,HI with LO < HI, got " + quoted(given["--range"]));
        }
        o.rangeGiven = true;
    }

    const bool sampling = o.pdf || o.method == Method::montecarlo;
    if (!sampling && (has("--samples") || has("--seed")))
    {
        o.notes.push_back("--samples and --seed have no effect with --method quadrature");
    }
    if ((o.method == Method::montecarlo || o.pdf) && has("--tolerance"))
    {
        o.notes.push_back("--tolerance is used only by the quadrature statistics");
    }
    readOutputOptions();
    return o;
}

} // namespace roughWallStats
