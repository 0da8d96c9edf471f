// Delta(d) tabulated on a log grid (envelopeAngleTable.hpp), as the OpenFOAM
// adapter uses it for roughness { profile ...; } and { Rq ...; RSm ...; }.
// Oracles: the envelope's tilt statistics evaluated directly at the
// diameter (rollingSphereEnvelope.hpp, tested on its own in
// testRollingSphereEnvelope.cc against closed forms and a brute force): at
// the rows the table must return them exactly, at the midpoints of the rows
// (where linear interpolation errs most) within the stated bound, 0.05 deg
// and 1 % of Delta; the grid's range and spacing computed here from the
// header's rules; end values held outside the range; the look-up cache
// returning the value of the diameter asked, whatever was asked before.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "envelopeAngleTable.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace roughWall;

namespace
{

constexpr double degPerRad = 180/3.14159265358979323846;

//- A random trace: AR(1) heights, uniform spacing h
SampledProfile randomTrace(int n, double h, unsigned seed)
{
    std::mt19937_64 g(seed);
    std::normal_distribution<double> normal(0, 1);
    SampledProfile p;
    double z = 0;
    for (int i = 0; i < n; ++i)
    {
        z = 0.95*z + 0.05*h*normal(g);
        p.x.push_back(i*h);
        p.z.push_back(z + 0.2*h*std::sin(0.05*i));
    }
    return p;
}

//- The row diameters, from the header's rule (12 per decade, uniform in ln d)
std::vector<double> rows(double dMin, double dMax)
{
    const int n = static_cast<int>(std::ceil(std::log10(dMax/dMin)*12)) + 1;
    std::vector<double> d(n);
    for (int k = 0; k < n; ++k)
    {
        d[k] = dMin*std::pow(dMax/dMin, double(k)/(n - 1));
    }
    return d;
}

void checkTable(const SampledProfile& p, double dMin, double dMax, const char* what)
{
    const EnvelopeAngleTable table(p, dMin, dMax);
    const std::vector<double> d = rows(table.dMin(), table.dMax());
    ASSERT_EQ(table.rows(), d.size()) << what;
    double worst = 0;
    for (std::size_t k = 0; k < d.size(); ++k)
    {
        // Rows: exactly the envelope's value (up to the rounding of d_k)
        const double atRow = tiltStatistics(p, d[k]).rms;
        EXPECT_NEAR(table.interpolate(d[k]), atRow, 1e-9*atRow + 1e-12)
            << what << ", row " << k << " d = " << d[k];
        if (k + 1 == d.size()) break;
        // Midpoints in ln d: the stated interpolation error
        const double dm = std::sqrt(d[k]*d[k + 1]);
        const double exact = tiltStatistics(p, dm).rms;
        const double error = std::fabs(table.interpolate(dm) - exact);
        worst = std::max(worst, error*degPerRad);
        EXPECT_LE(error*degPerRad, 0.05) << what << ", d = " << dm;
        EXPECT_LE(error, 0.01*exact) << what << ", d = " << dm;
    }
    std::printf("%s: %zu rows from %g to %g m, worst midpoint error %.2g deg\n",
                what, table.rows(), table.dMin(), table.dMax(), worst);
}

} // namespace


TEST(EnvelopeAngleTable, syntheticProfileWithinStatedError)
{
    SyntheticProfileSettings s;
    s.Rq = 2e-6;
    s.RSm = 100e-6;
    s.lengthPerRSm = 300;   // shorter than the adapter's: the same curve, noisier
    const SampledProfile p = syntheticGaussianProfile(s);
    checkTable(p, s.RSm/10, 100*s.RSm, "synthetic");
}


TEST(EnvelopeAngleTable, randomTraceWithinStatedError)
{
    const SampledProfile p = randomTrace(20000, 1e-6, 7);
    checkTable(p, 0, 0, "trace");
}


TEST(EnvelopeAngleTable, rangeFromTheProfile)
{
    // Trimmed: [largest spacing, half the trace]; periodic: a tenth of the
    // period; a caller's range is narrowed to these
    SampledProfile p = randomTrace(1001, 2e-6, 3);
    p.x[500] += 1e-6;   // largest spacing 3e-6
    const EnvelopeAngleTable a(p);
    EXPECT_NEAR(a.dMin(), 3e-6, 1e-15);
    EXPECT_NEAR(a.dMax(), 1e-3, 1e-15);
    const EnvelopeAngleTable b(p, 1e-5, 1);
    EXPECT_DOUBLE_EQ(b.dMin(), 1e-5);
    EXPECT_NEAR(b.dMax(), 1e-3, 1e-15);
    SampledProfile q = randomTrace(1000, 2e-6, 3);
    q.ends = ProfileEnds::periodic;
    q.period = 2e-3;
    EXPECT_NEAR(EnvelopeAngleTable(q).dMax(), 2e-4, 1e-15);
}


TEST(EnvelopeAngleTable, endValuesHeldAndCacheFollowsTheDiameter)
{
    const SampledProfile p = randomTrace(5000, 1e-6, 11);
    const EnvelopeAngleTable table(p);
    const double first = tiltStatistics(p, table.dMin()).rms;
    const double last = tiltStatistics(p, table.dMax()).rms;
    EXPECT_NEAR(table.angle(0.1*table.dMin()), first, 1e-12);
    EXPECT_NEAR(table.angle(0), first, 1e-12);
    EXPECT_NEAR(table.angle(10*table.dMax()), last, 1e-12);
    EXPECT_FALSE(table.covers(0.5*table.dMin()));
    EXPECT_FALSE(table.covers(2*table.dMax()));
    EXPECT_TRUE(table.covers(std::sqrt(table.dMin()*table.dMax())));
    // Alternating diameters: each look-up gives its own diameter's value
    const double d1 = 20e-6, d2 = 200e-6;
    const double a1 = table.interpolate(d1), a2 = table.interpolate(d2);
    ASSERT_GT(std::fabs(a1 - a2), 1e-3);
    for (int i = 0; i < 4; ++i)
    {
        EXPECT_EQ(table.angle(d1), a1);
        EXPECT_EQ(table.angle(d1), a1);
        EXPECT_EQ(table.angle(d2), a2);
    }
}


TEST(EnvelopeAngleTable, tooShortProfileThrows)
{
    SampledProfile p;
    p.x = {0, 1e-6, 2e-6};
    p.z = {0, 1e-7, 0};
    // half the trace (1e-6) is not above the spacing (1e-6)
    EXPECT_THROW(EnvelopeAngleTable{p}, std::invalid_argument);
}


// A trace steeper than 45 deg must be refused (the adapter stops the run
// when the table's largest Delta exceeds maxRoughnessAngleDeg), so the
// table's maximum must be its largest angle, not its smallest. Oracle: a
// triangle wave of flank slope s = 2 (63.43 deg), period P = 100 um; a
// sphere of radius r << P lies on a flank except over an arc of width
// 2 r sin(atan s) at each crest, so its rms tilt is atan(s) to a fraction
// 2 r sin(atan s)/P (below 1 % at the table's smallest diameter); as the
// sphere grows it bridges the valleys and Delta falls, so the largest angle
// is that of the smallest diameter, and every diameter of the table has an
// angle at most the maximum.
TEST(EnvelopeAngleTable, steepTraceMaximumIsItsLargestAngle)
{
    const double P = 100e-6, s = 2, h = 0.5e-6;
    SampledProfile p;
    for (int i = 0; i <= 4000; ++i)
    {
        const double x = i*h;
        const double f = std::fmod(x, P)/P;     // phase in [0, 1)
        p.x.push_back(x);
        p.z.push_back(s*P*(f < 0.5 ? f : 1 - f));
    }
    const EnvelopeAngleTable table(p, 0, 0);
    const double steep = std::atan(s);
    EXPECT_NEAR(table.interpolate(table.dMin()), steep, 0.01*steep);
    EXPECT_GT(table.maxAngle()*degPerRad, 45) << "the adapter refuses it";
    EXPECT_NEAR(table.maxAngle(), steep, 0.01*steep);
    double largest = 0, smallest = 10;
    for (const double d : rows(table.dMin(), table.dMax()))
    {
        largest = std::max(largest, table.interpolate(d));
        smallest = std::min(smallest, table.interpolate(d));
    }
    std::printf("triangle wave: Delta %.4f deg at d = %g m, %.4f deg at d = %g m\n",
                table.interpolate(table.dMin())*degPerRad, table.dMin(),
                smallest*degPerRad, table.dMax());
    EXPECT_EQ(table.maxAngle(), largest);
    EXPECT_LT(smallest, 0.5*largest) << "the test tells the maximum from the minimum";
}
