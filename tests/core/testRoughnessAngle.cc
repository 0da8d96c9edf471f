// Delta(d_p) in the forms a patch gives it (roughnessAngle.hpp).
// Oracles, none of which calls the code under test to get its expectation:
//  - a table of 5 rows: linear interpolation written out here by hand for
//    diameters between every pair of rows, exactly on each row, and beyond
//    both ends (held at the end rows), so that a bisection that stops in the
//    wrong interval or interpolates the wrong way fails;
//  - the rules of the rows (d >= 0 strictly increasing, Delta in [0, 45] deg,
//    NaN refused) against the index of the row that breaks them;
//  - the closed form: equation (1) typed in, atan(2 pi Rq / max(RSm, d));
//  - the Gaussian profile's Rq from Ra (sqrt(pi/2) Ra) and from Rz (Rz/4.11)
//    typed in, and the precedence Rq, else Ra, else Rz.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "roughnessAngle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace roughWall;

namespace
{

constexpr double degree = 3.14159265358979323846/180;

//- Rows (d [m], Delta [deg]): unequal spacings and a non-monotonic Delta, so
//  that every interval has its own slope
const std::vector<RoughnessAngle::Row> fiveRows
{
    {50e-6, 10}, {100e-6, 8}, {110e-6, 9}, {300e-6, 5}, {1000e-6, 2}
};

//- Linear interpolation between rows i and i + 1 at fraction f, in radians
double between(const std::size_t i, const double f)
{
    const double a = fiveRows[i].second, b = fiveRows[i + 1].second;
    return (a + f*(b - a))*degree;
}

} // namespace


TEST(RoughnessAngle, TableOfFiveRowsBetweenOnAndBeyondTheRows)
{
    const RoughnessAngle delta = RoughnessAngle::table(fiveRows);
    ASSERT_EQ(delta.form(), RoughnessAngle::Form::table);

    for (std::size_t i = 0; i + 1 < fiveRows.size(); ++i)
    {
        const double d0 = fiveRows[i].first, d1 = fiveRows[i + 1].first;
        for (const double f : {0.25, 0.5, 0.9})
        {
            EXPECT_NEAR(delta(d0 + f*(d1 - d0)), between(i, f), 1e-12)
                << "between rows " << i + 1 << " and " << i + 2 << ", f = " << f;
        }
    }
    for (const RoughnessAngle::Row& row : fiveRows)
    {
        EXPECT_NEAR(delta(row.first), row.second*degree, 1e-12)
            << "on the row d = " << row.first;
    }
    EXPECT_NEAR(delta(0), 10*degree, 1e-12);
    EXPECT_NEAR(delta(20e-6), 10*degree, 1e-12);
    EXPECT_NEAR(delta(5e-3), 2*degree, 1e-12);
    EXPECT_TRUE(delta.covers(5e-3));
}


TEST(RoughnessAngle, OneRowOrAConstantIsTheSameForEveryDiameter)
{
    const RoughnessAngle one = RoughnessAngle::table({{200e-6, 7}});
    EXPECT_EQ(one.form(), RoughnessAngle::Form::constant);
    for (const double d : {0.0, 1e-6, 200e-6, 1e-2})
    {
        EXPECT_NEAR(one(d), 7*degree, 1e-15);
    }
    EXPECT_EQ(RoughnessAngle()(1e-4), 0);
}


TEST(RoughnessAngle, FirstBadRowNamesTheRowThatBreaksTheRules)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(RoughnessAngle::firstBadRow(fiveRows), -1);
    EXPECT_EQ(RoughnessAngle::firstBadRow({{0, 0}, {1e-3, 45}}), -1);
    EXPECT_EQ(RoughnessAngle::firstBadRow({{-1e-6, 5}}), 0);
    EXPECT_EQ(RoughnessAngle::firstBadRow({{1e-4, 5}, {1e-4, 6}}), 1);
    EXPECT_EQ(RoughnessAngle::firstBadRow({{1e-4, 5}, {2e-4, 6}, {1e-4, 7}}), 2);
    EXPECT_EQ(RoughnessAngle::firstBadRow({{1e-4, 5}, {2e-4, 45.001}}), 1);
    EXPECT_EQ(RoughnessAngle::firstBadRow({{1e-4, -0.1}}), 0);
    EXPECT_EQ(RoughnessAngle::firstBadRow({{1e-4, 5}, {nan, 6}}), 1);
    EXPECT_EQ(RoughnessAngle::firstBadRow({{1e-4, nan}}), 0);
}


TEST(RoughnessAngle, ClosedFormIsEquationOne)
{
    ProfileRoughness p;
    p.Rq = 2e-6;
    p.RSm = 60e-6;
    const RoughnessAngle delta = RoughnessAngle::closedForm(p);
    const double twoPiRq = 2*3.14159265358979323846*2e-6;
    for (const double d : {10e-6, 60e-6, 200e-6})
    {
        EXPECT_NEAR(delta(d), std::atan(twoPiRq/std::max(60e-6, d)), 1e-14);
    }
    EXPECT_NE(delta.describe().find("Rq = 2e-06 m, RSm = 6e-05 m"), std::string::npos)
        << delta.describe();
}


TEST(RoughnessAngle, GaussianProfileTakesRqElseRaElseRz)
{
    ProfileRoughness p;
    p.RSm = 100e-6;
    p.Rz = 8.22e-6;
    EXPECT_NEAR(gaussianProfileOf(p).Rq, 2e-6, 1e-15);            // Rz/4.11
    p.Ra = 1e-6;
    EXPECT_NEAR(gaussianProfileOf(p).Rq, 1.2533141373155003e-6, 1e-18); // sqrt(pi/2) Ra
    p.Rq = 3e-6;
    EXPECT_EQ(gaussianProfileOf(p).Rq, 3e-6);
    EXPECT_EQ(gaussianProfileOf(p).RSm, 100e-6);
}
