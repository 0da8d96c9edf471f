// The CSV tables of roughWallStats and their --digits: with 17 significant
// digits every number reads back as the very double the quadrature (or Monte
// Carlo, or the pdf) computed in-process, in the table writer and through the
// built tool (ROUGHWALLSTATS_BINARY); 12 digits (the default) are the tool's
// historical format and agree to 5e-12 relative.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "commandLine.hh"
#include "monteCarloStatistics.hh"
#include "quadratureStatistics.hh"
#include "tables.hh"

#include "testSupport.hh"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdio.h>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace roughWallStats;
using namespace roughWallStatsTest;

namespace
{

std::vector<std::string> splitCsv(const std::string& line)
{
    std::vector<std::string> fields;
    std::string field;
    std::istringstream stream(line);
    while (std::getline(stream, field, ','))
    {
        fields.push_back(field);
    }
    if (!line.empty() && line.back() == ',')
    {
        fields.push_back("");
    }
    return fields;
}

//- The table as one map column -> text per row
std::vector<std::map<std::string, std::string>> readCsv(const std::string& text)
{
    std::istringstream stream(text);
    std::string line;
    std::getline(stream, line);
    const std::vector<std::string> header = splitCsv(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(stream, line))
    {
        const std::vector<std::string> fields = splitCsv(line);
        EXPECT_EQ(fields.size(), header.size()) << line;
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i)
        {
            row[header[i]] = fields[i];
        }
        rows.push_back(row);
    }
    return rows;
}

//- The whole field as a double (fails the test if it is not one)
double read(const std::string& text)
{
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    EXPECT_TRUE(!text.empty() && end == text.c_str() + text.size()) << "'" << text << "'";
    return value;
}

//- Significant digits written in a %g field (trailing zeros are dropped by %g)
int significantDigits(const std::string& text)
{
    std::string mantissa = text.substr(0, text.find_first_of("eE"));
    std::string digits;
    for (const char c : mantissa)
    {
        if (c >= '0' && c <= '9') digits += c;
    }
    const auto first = digits.find_first_not_of('0');
    return first == std::string::npos ? 0 : static_cast<int>(digits.size() - first);
}

//- Every column of the statistics table from the struct, and whether defined
std::map<std::string, std::pair<double, bool>> columns(const Statistics& s)
{
    const bool t = s.tangentialDefined;
    return
    {
        {"alpha_deg", {s.alphaDeg, true}}, {"mean_kn", {s.meanKn, true}},
        {"sd_kn", {s.sdKn, true}}, {"mean_abs_kn", {s.meanAbsKn, true}},
        {"mean_kt", {s.meanKt, t}}, {"sd_kt", {s.sdKt, t}},
        {"mean_kOmega", {s.meanKOmega, t}}, {"sd_kOmega", {s.sdKOmega, t}},
        {"p_noslip", {s.pNoSlip, true}}, {"p_wallward", {s.pWallward, true}},
        {"mean_facet_collisions", {s.meanFacetCollisions, true}},
        {"p_fallback", {s.pFallback, true}},
        {"samples", {static_cast<double>(s.samples), true}},
        {"se_mean_kn", {s.seMeanKn, true}}, {"se_sd_kn", {s.seSdKn, true}},
        {"se_mean_abs_kn", {s.seMeanAbsKn, true}}, {"se_mean_kt", {s.seMeanKt, t}},
        {"se_sd_kt", {s.seSdKt, t}}, {"se_mean_kOmega", {s.seMeanKOmega, t}},
        {"se_sd_kOmega", {s.seSdKOmega, t}}, {"se_p_noslip", {s.sePNoSlip, true}},
        {"se_p_wallward", {s.sePWallward, true}},
        {"se_mean_facet_collisions", {s.seMeanFacetCollisions, true}},
    };
}

std::string table(const std::vector<Statistics>& rows, TableLayout layout, int digits)
{
    layout.digits = digits;
    std::ostringstream os;
    writeStatisticsTable(os, rows, layout);
    return os.str();
}

//- The arguments of the quadrature cases, for the tool and in-process
const std::vector<std::string> quadratureArgs
{
    "--Delta", "8", "--spin", "0.3", "--alpha", "0.01,1,5,11.6,30,45,89,90", "--threads", "1"
};

//- The quadrature rows computed here, from the options as the tool parses them
//  (so the model is the same double for double)
std::vector<Statistics> quadratureRows()
{
    std::vector<std::string> args = quadratureArgs;
    args.insert(args.begin(), "roughWallStats");
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    const Options o = parseCommandLine(static_cast<int>(argv.size()), argv.data());
    std::vector<Statistics> rows;
    for (const double alphaDeg : o.alphaDeg)
    {
        rows.push_back(quadratureStatistics(o.model, Incidence::fromDegrees(alphaDeg), o.quadrature));
    }
    return rows;
}

//- stdout of the built tool with these arguments (stderr dropped)
std::string runTool(const std::vector<std::string>& args)
{
    std::string command = ROUGHWALLSTATS_BINARY;
    for (const std::string& a : args) command += " '" + a + "'";
    command += " 2>/dev/null";
    std::string out;
    if (FILE* pipe = popen(command.c_str(), "r"))
    {
        char buffer[4096];
        for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
        {
            out.append(buffer, n);
        }
        EXPECT_EQ(pclose(pipe), 0) << command;
    }
    else
    {
        ADD_FAILURE() << "cannot run " << command;
    }
    return out;
}

} // namespace

TEST(Tables, DefaultIsTwelveSignificantDigits)
{
    EXPECT_EQ(TableLayout().digits, 12);
    const std::vector<Statistics> rows = quadratureRows();
    std::ostringstream os;
    writeStatisticsTable(os, rows, TableLayout());
    EXPECT_EQ(os.str(), table(rows, TableLayout(), 12));

    // The fields are printf's %.12g, as before --digits existed
    const auto parsed = readCsv(os.str());
    char expected[40];
    std::snprintf(expected, sizeof expected, "%.12g", rows[1].meanKn);
    EXPECT_EQ(parsed[1].at("mean_kn"), expected);
}

// The quadrature computed here, written with 17 digits and read back: the
// same doubles, bit for bit; with 12 digits within 5e-12 and, for some
// values, not the same double (so the comparison can tell them apart)
TEST(Tables, SeventeenDigitsRoundTripTheQuadratureExactly)
{
    const std::vector<Statistics> rows = quadratureRows();
    const auto exact = readCsv(table(rows, TableLayout(), 17));
    const auto rounded = readCsv(table(rows, TableLayout(), 12));
    ASSERT_EQ(exact.size(), rows.size());
    ASSERT_EQ(rounded.size(), rows.size());

    int checked = 0, notExactAt12 = 0, with17Digits = 0;
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        const auto expected = columns(rows[i]);
        for (const auto& [column, text] : exact[i])
        {
            const auto [value, defined] = expected.at(column);
            if (!defined)
            {
                EXPECT_EQ(text, "") << column << " at alpha = " << rows[i].alphaDeg;
                EXPECT_EQ(rounded[i].at(column), "");
                continue;
            }
            EXPECT_EQ(read(text), value) << column << " at alpha = " << rows[i].alphaDeg
                                         << ": '" << text << "'";
            const double at12 = read(rounded[i].at(column));
            EXPECT_LE(std::abs(at12 - value), 5e-12*std::abs(value)) << column;
            EXPECT_LE(significantDigits(rounded[i].at(column)), 12) << column;
            EXPECT_LE(significantDigits(text), 17) << column;
            notExactAt12 += at12 != value;
            with17Digits += significantDigits(text) == 17;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 8*10 - 4);         // 8 rows x 10 columns, 4 undefined at 90 deg
    EXPECT_GT(notExactAt12, checked/2);   // 12 digits lose most of the doubles
    EXPECT_GT(with17Digits, checked/2);   // %g drops trailing zeros: most have all 17
}

// The same through the command line: the built tool with --digits 17 prints
// the doubles computed here exactly; without --digits it prints the 12-digit
// table, byte for byte
TEST(Tables, ToolWithDigits17PrintsTheInProcessQuadratureExactly)
{
    const std::vector<Statistics> rows = quadratureRows();
    std::vector<std::string> args = quadratureArgs;
    args.insert(args.end(), {"--digits", "17"});
    const std::string out17 = runTool(args);
    EXPECT_EQ(out17, table(rows, TableLayout(), 17));
    const auto parsed = readCsv(out17);
    ASSERT_EQ(parsed.size(), rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        for (const auto& [column, text] : parsed[i])
        {
            const auto [value, defined] = columns(rows[i]).at(column);
            if (defined)
            {
                EXPECT_EQ(read(text), value) << column << " at alpha = " << rows[i].alphaDeg;
            }
        }
    }
    EXPECT_EQ(runTool(quadratureArgs), table(rows, TableLayout(), 12));
}

TEST(Tables, SeventeenDigitsRoundTripMonteCarloAndRecollideColumns)
{
    MonteCarloSettings settings;
    settings.samples = 3000;
    settings.recollide = true;
    std::vector<Statistics> rows;
    for (const double alphaDeg : {3.0, 12.0, 60.0})
    {
        rows.push_back(monteCarloStatistics(model(8), Incidence::fromDegrees(alphaDeg), settings));
    }
    TableLayout layout;
    layout.monteCarlo = true;
    layout.recollide = true;
    const auto parsed = readCsv(table(rows, layout, 17));
    ASSERT_EQ(parsed.size(), rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        const auto expected = columns(rows[i]);
        EXPECT_EQ(parsed[i].size(), expected.size());   // every column is in the table
        for (const auto& [column, text] : parsed[i])
        {
            EXPECT_EQ(read(text), expected.at(column).first) << column << ": '" << text << "'";
        }
        EXPECT_EQ(parsed[i].at("samples"), "3000");
    }
}

TEST(Tables, PdfTableHonoursTheDigits)
{
    const double tiny = std::numeric_limits<double>::denorm_min();
    const std::vector<PdfBin> bins
    {
        {1.0/3, 0.5, 2*std::acos(-1.0), 0.1, 7},
        {0.5, 0.7000000000000001, 1e-300, tiny, 0},
        {0.7000000000000001, 1.9, 123456789.123456789, 5e-17, 123},
    };
    const long long samples = 130;
    for (const int digits : {1, 12, 17})
    {
        std::ostringstream os;
        writePdfTable(os, bins, samples, true, digits);
        const auto parsed = readCsv(os.str());
        ASSERT_EQ(parsed.size(), bins.size());
        for (std::size_t i = 0; i < bins.size(); ++i)
        {
            const PdfBin& b = bins[i];
            const double scale = 1/(static_cast<double>(samples)*(b.hi - b.lo));
            const std::map<std::string, double> expected
            {
                {"k_lo", b.lo}, {"k_hi", b.hi}, {"k", 0.5*(b.lo + b.hi)}, {"pdf", b.pdf},
                {"pdf_bin", b.pdfBin}, {"pdf_montecarlo", b.count*scale},
                {"se_pdf_montecarlo", std::sqrt(static_cast<double>(b.count))*scale},
            };
            for (const auto& [column, value] : expected)
            {
                char text[40];
                std::snprintf(text, sizeof text, "%.*g", digits, value);
                EXPECT_EQ(parsed[i].at(column), text) << column << ", digits " << digits;
                if (digits == 17)
                {
                    EXPECT_EQ(read(parsed[i].at(column)), value) << column;
                }
            }
            EXPECT_EQ(parsed[i].at("count"), std::to_string(b.count));   // an integer, always whole
        }
    }
    // The default is 12 digits
    std::ostringstream byDefault, twelve;
    writePdfTable(byDefault, bins, samples, false);
    writePdfTable(twelve, bins, samples, false, 12);
    EXPECT_EQ(byDefault.str(), twelve.str());
}
