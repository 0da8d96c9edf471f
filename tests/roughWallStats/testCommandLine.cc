// Command-line parsing of roughWallStats: defaults, angle lists, and every
// bad input rejected with a message naming the option.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "commandLine.hh"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace roughWallStats;

namespace
{

Options parse(std::vector<std::string> args)
{
    args.insert(args.begin(), "roughWallStats");
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    return parseCommandLine(static_cast<int>(argv.size()), argv.data());
}

//- The message of the UsageError thrown, or "" if none
std::string error(const std::vector<std::string>& args)
{
    try
    {
        parse(args);
    }
    catch (const UsageError& e)
    {
        return e.what();
    }
    return "";
}

} // namespace

TEST(CommandLine, DefaultsAreThePapersSmallParticleCase)
{
    const Options o = parse({});
    EXPECT_EQ(o.DeltaDeg, 8);
    EXPECT_EQ(o.model.material.e, 0.8);
    EXPECT_EQ(o.model.material.mu0, 0.4);
    EXPECT_EQ(o.model.material.muD, 0.4);
    EXPECT_EQ(o.model.AOmega, 0);
    EXPECT_EQ(o.alphaDeg, (std::vector<double>{1, 2, 5, 10, 15, 30, 45, 89}));
    EXPECT_EQ(o.method, Method::quadrature);
    EXPECT_EQ(o.monteCarlo.samples, 1000000);
    EXPECT_FALSE(o.pdf);
    EXPECT_EQ(o.digits, 12);
}

TEST(CommandLine, AnglesAndOptionForms)
{
    const Options o = parse({"--alpha", "0.5:0.5:2,10,90", "--Delta=5", "--samples", "1e5",
                             "--method", "montecarlo", "--seed", "18446744073709551615"});
    EXPECT_EQ(o.alphaDeg, (std::vector<double>{0.5, 1, 1.5, 2, 10, 90}));
    EXPECT_EQ(o.DeltaDeg, 5);
    EXPECT_EQ(o.monteCarlo.samples, 100000);
    EXPECT_EQ(o.monteCarlo.seed, 18446744073709551615ULL);
    EXPECT_EQ(parse({"--alpha", "1:0.1:1.3"}).alphaDeg.size(), 4u);

    // --recollide alone switches to Monte Carlo, with a note
    const Options r = parse({"--recollide"});
    EXPECT_EQ(r.method, Method::montecarlo);
    EXPECT_TRUE(r.monteCarlo.recollide);
    EXPECT_EQ(r.notes.size(), 1u);

    const Options p = parse({"--pdf", "kt", "--alpha", "5", "--bins", "30", "--range", "0.2,1.4"});
    EXPECT_TRUE(p.pdf);
    EXPECT_EQ(p.pdfOf, Coefficient::kt);
    EXPECT_EQ(p.bins, 30);
    EXPECT_EQ(p.rangeLo, 0.2);
    EXPECT_EQ(p.rangeHi, 1.4);

    // --digits: 1..17, for the statistics and the pdf tables alike
    EXPECT_EQ(parse({"--digits", "17"}).digits, 17);
    EXPECT_EQ(parse({"--digits=1"}).digits, 1);
    EXPECT_EQ(parse({"--method", "montecarlo", "--digits", "16"}).digits, 16);
    EXPECT_EQ(parse({"--pdf", "kn", "--alpha", "5", "--digits", "15"}).digits, 15);
    EXPECT_TRUE(parse({"--digits", "17"}).notes.empty());
}

// Every rejection names the option (and its range where it has one)
TEST(CommandLine, BadInputIsRejectedNamingTheOption)
{
    const std::vector<std::pair<std::vector<std::string>, std::string>> bad
    {
        {{"--Delta", "-1"}, "--Delta must be in [0, 45]"},
        {{"--Delta", "46"}, "--Delta must be in [0, 45]"},
        {{"--Delta", "abc"}, "--Delta needs a finite number"},
        {{"--Delta", "nan"}, "--Delta needs a finite number"},
        {{"--Delta", "8x"}, "--Delta needs a finite number"},
        {{"--Delta"}, "--Delta needs a value"},
        {{"--e", "1.5"}, "--e must be in [0, 1]"},
        {{"--e", "-0.1"}, "--e must be in [0, 1]"},
        {{"--mu0", "-0.1"}, "--mu0 must be >= 0"},
        {{"--mud", "0.5"}, "--mud must be in [0, mu0]"},
        {{"--mu0", "0.2", "--mud", "0.3"}, "--mud must be in [0, mu0]"},
        {{"--alpha", "0"}, "--alpha values must be in (0, 90]"},
        {{"--alpha", "90.5"}, "--alpha values must be in (0, 90]"},
        {{"--alpha", "1e-301"}, "--alpha values must be at least 1e-300"},
        {{"--alpha", "1,-2"}, "--alpha values must be in (0, 90]"},
        {{"--alpha", "1,,2"}, "--alpha needs numbers or start:step:stop"},
        {{"--alpha", "1,x"}, "--alpha needs a finite number"},
        {{"--alpha", "5:0:10"}, "--alpha range"},
        {{"--alpha", "1:2"}, "--alpha needs numbers or start:step:stop"},
        {{"--spin", "inf"}, "--spin needs a finite number"},
        {{"--method", "euler"}, "--method must be quadrature or montecarlo"},
        {{"--samples", "1.5"}, "--samples must be an integer"},
        {{"--samples", "1"}, "--samples must be an integer in [2,"},
        {{"--seed", "-3"}, "--seed must be an integer"},
        {{"--recollide", "--method", "quadrature"}, "--recollide needs --method montecarlo"},
        {{"--lateral", "--method", "quadrature"}, "--lateral needs --method montecarlo"},
        {{"--max-collisions", "3"}, "--max-collisions needs --recollide"},
        {{"--recollide", "--max-collisions", "0"}, "--max-collisions must be an integer in [1,"},
        {{"--pdf", "kz", "--alpha", "5"}, "--pdf must be kn, kt or kOmega"},
        {{"--pdf", "kn"}, "--pdf needs exactly one incidence angle"},
        {{"--pdf", "kn", "--alpha", "5,6"}, "--pdf needs exactly one incidence angle"},
        {{"--pdf", "kt", "--alpha", "90"}, "--pdf kt is undefined at --alpha 90"},
        {{"--pdf", "kn", "--alpha", "5", "--Delta", "0"}, "--pdf needs --Delta > 0"},
        {{"--bins", "10"}, "--bins needs --pdf"},
        {{"--pdf", "kn", "--alpha", "5", "--bins", "0"}, "--bins must be an integer in [1,"},
        {{"--pdf", "kn", "--alpha", "5", "--range", "2,1"}, "--range must be LO,HI with LO < HI"},
        {{"--tolerance", "1e-20"}, "--tolerance must be in [1e-14, 1e-3]"},
        {{"--output", ""}, "--output needs a file name"},
        {{"--digits", "0"}, "--digits must be an integer in [1, 17], got '0'"},
        {{"--digits", "18"}, "--digits must be an integer in [1, 17], got '18'"},
        {{"--digits", "12.5"}, "--digits must be an integer in [1, 17], got '12.5'"},
        {{"--digits", "-3"}, "--digits must be an integer in [1, 17]"},
        {{"--digits", "twelve"}, "--digits needs a finite number"},
        {{"--digits", ""}, "--digits needs a finite number"},
        {{"--digits"}, "--digits needs a value"},
        {{"--alpha", "5", "--digits"}, "--digits needs a value"},
        {{"--digits", "17", "--digits", "12"}, "--digits given twice"},
        {{"--frobnicate"}, "unknown option '--frobnicate'"},
        {{"--e", "0.5", "--e", "0.6"}, "--e given twice"},
        {{"--recollide=1"}, "--recollide takes no value"},
    };
    for (const auto& [args, expected] : bad)
    {
        const std::string message = error(args);
        EXPECT_NE(message.find(expected), std::string::npos)
            << "args: " << args[0] << " ... got: '" << message << "', expected: '" << expected << "'";
    }
}
