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

#include <algorithm>
#include <cmath>
#include <cstdio>
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


// One Ra/Rz -> Rq conversion for the flank-slope check and the synthetic
// profile (issue 45: the check converted as for a sinusoid, the profile as
// for a Gaussian, so a wall given by Ra could pass the check and get a
// profile of rms slope 1.13). A wall at the limit of the check must give a
// profile at that limit, rms slope 2 pi Rq/RSm = 1 (45 deg), and the profile
// must have the Ra or Rz the wall was given. Oracles, none from the code
// under test: the limit found by bisection on the check's verdict alone;
// the profile's rms slope (its chords' slopes, periodic), mean |z| and
// mean peak-to-valley height over windows of 5 RSm measured here; stated
// tolerances: 3 % on the slope and Ra (seed spread of the 5000-RSm
// profile, about 0.6 %), 4 % on Rz (its window-to-window scatter and the
// 4.11 assumption's 3 %).
TEST(RoughnessAngle, WallAtTheSlopeLimitGivesAProfileWithinIt)
{
    const double RSm = 60e-6;
    for (const bool byRa : {true, false})
    {
        // The largest Ra (or Rz) the check accepts at this RSm
        const auto accepted = [&](const double height)
        {
            ProfileRoughness p;
            (byRa ? p.Ra : p.Rz) = height;
            p.RSm = RSm;
            return checkProfileRoughness(p, byRa, false, !byRa).keyword.empty();
        };
        double lo = 1e-9, hi = RSm;
        ASSERT_TRUE(accepted(lo));
        ASSERT_FALSE(accepted(hi));
        for (int k = 0; k < 100; ++k)
        {
            const double mid = 0.5*(lo + hi);
            (accepted(mid) ? lo : hi) = mid;
        }
        ProfileRoughness wall;
        (byRa ? wall.Ra : wall.Rz) = lo;
        wall.RSm = RSm;
        const SampledProfile z = syntheticGaussianProfile(gaussianProfileOf(wall));

        const std::size_t n = z.z.size();
        const double h = z.x[1] - z.x[0];
        double slope2 = 0, absSum = 0;
        for (std::size_t i = 0; i < n; ++i)
        {
            const double dz = z.z[(i + 1) % n] - z.z[i];
            slope2 += dz*dz/(h*h);
            absSum += std::fabs(z.z[i]);
        }
        const double rmsSlope = std::sqrt(slope2/n);
        std::printf("%s at the limit: %.6g m, profile rms slope %.4f, Ra %.4g m\n",
                    byRa ? "Ra" : "Rz", lo, rmsSlope, absSum/n);
        EXPECT_LE(rmsSlope, 1.03) << (byRa ? "Ra" : "Rz") << " at the limit";
        EXPECT_GE(rmsSlope, 0.97) << (byRa ? "Ra" : "Rz")
            << " at the limit: the check is no stricter than the profile";
        if (byRa)
        {
            EXPECT_NEAR(absSum/n/lo, 1, 0.03) << "the profile's Ra";
        }
        else
        {
            // Mean peak-to-valley height over windows of 5 RSm
            const std::size_t w = static_cast<std::size_t>(5*RSm/h);
            double range = 0;
            std::size_t windows = 0;
            for (std::size_t start = 0; start + w <= n; start += w, ++windows)
            {
                const auto [mn, mx] = std::minmax_element
                (
                    z.z.begin() + start, z.z.begin() + start + w
                );
                range += *mx - *mn;
            }
            std::printf("Rz of the profile %.4g m\n", range/windows);
            EXPECT_NEAR(range/windows/lo, 1, 0.04) << "the profile's Rz";
        }
    }
}


// The constructions the adapter hands its input to: a bad input throws
// BadRoughness naming the keyword and, for a table, the row (1-based) that
// breaks the rules stated above; good input gives the form asked for
TEST(RoughnessAngle, ConstructionsNameTheKeywordAndRowOfABadInput)
{
    const auto badRows = [](const std::vector<RoughnessAngle::Row>& rows)
    {
        try
        {
            roughnessOfRows(rows);
        }
        catch (const BadRoughness& err)
        {
            return err.keyword + ":" + err.what();
        }
        return std::string("accepted");
    };
    EXPECT_EQ(badRows({{0, 50}}), "roughnessAngle:");
    EXPECT_EQ(badRows({{1e-4, 8}, {1e-4, 5}}), "roughnessAngle:row 2");
    EXPECT_EQ(badRows({{1e-4, 8}, {2e-4, 5}, {3e-4, -1}}),
              "roughnessAngle:row 3");
    EXPECT_EQ(badRows({{0, 8}}), "accepted");
    EXPECT_EQ(roughnessOfRows({{0, 8}}).form(), RoughnessAngle::Form::constant);

    ProfileRoughness p;
    p.Ra = 1e-6;
    try
    {
        roughnessOfParameters(p, true, false, false, true);
        ADD_FAILURE() << "no RSm accepted";
    }
    catch (const BadRoughness& err)
    {
        EXPECT_EQ(err.keyword, "RSm");
    }
    p.RSm = 50e-6;
    EXPECT_EQ(roughnessOfParameters(p, true, false, false, true).form(),
              RoughnessAngle::Form::closedForm);
}
