// roughWallInteraction benchmarks: accuracy of fastMath.hpp against long
// double libm references, in ulps of the double result, over random
// arguments of the ranges the collision operator uses and their edges.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Usage: fastMathAccuracy [samples]   (default 10^7 per function)
// Prints the largest error of each function, and of glibc's double version
// for comparison; exits 1 if any fast function errs by more than 4 ulp.

#include "fastMath.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>

namespace
{

//- |value - reference| in ulps of the reference rounded to double
double ulps(double value, long double reference)
{
    const double r = static_cast<double>(reference);
    if (r == 0)
    {
        return value == 0 ? 0 : std::abs(value)/std::numeric_limits<double>::denorm_min();
    }
    const double ulp = std::nextafter(std::abs(r), INFINITY) - std::abs(r);
    return static_cast<double>(std::abs(static_cast<long double>(value) - reference)/ulp);
}

struct Worst
{
    const char* name;
    double fast = 0, libm = 0;
    double at = 0;
    void add(double fastUlps, double libmUlps, double x)
    {
        if (fastUlps > fast) { fast = fastUlps; at = x; }
        libm = std::max(libm, libmUlps);
    }
    void print() const
    {
        std::printf("%-28s max error %.3f ulp (at %.17g); glibc double %.3f ulp\n",
                    name, fast, at, libm);
    }
};

} // namespace

int main(int argc, char** argv)
{
    using namespace roughWall::fastMath;
    const long n = argc > 1 ? std::atol(argv[1]) : 10000000;
    std::mt19937_64 engine(2026);
    std::uniform_real_distribution<double> U(0, 1);
    const double pi = 3.14159265358979323846;

    Worst atanW{"atan2FirstQuadrant"}, sinW{"sinCosHalfPi: sin"},
        cosW{"sinCosHalfPi: cos"}, acW{"absCosSinTwoPi: |cos|"},
        asW{"absCosSinTwoPi: |sin|"}, logW{"log1pMinus"};

    for (long i = 0; i < n; ++i)
    {
        // directions: uniform angle, and log-uniform small components
        const double phi = 0.5*pi*U(engine);
        double y = std::sin(phi), x = std::cos(phi);
        if (i % 4 == 1) y *= std::pow(10.0, -12*U(engine));
        if (i % 4 == 2) x *= std::pow(10.0, -12*U(engine));
        const long double ref = std::atan2(static_cast<long double>(y), static_cast<long double>(x));
        atanW.add(ulps(atan2FirstQuadrant(y, x), ref), ulps(std::atan2(y, x), ref), y/x);

        double g = pi*(U(engine) - 0.5);
        if (i % 3 == 1) g *= std::pow(10.0, -10*U(engine));
        double s, c;
        sinCosHalfPi(g, s, c);
        const long double gl = g;
        sinW.add(ulps(s, std::sin(gl)), ulps(std::sin(g), std::sin(gl)), g);
        cosW.add(ulps(c, std::cos(gl)), ulps(std::cos(g), std::cos(gl)), g);

        // Reference: 2 pi u = q pi/2 + r pi/2 reduced exactly in long double
        // (2 pi u itself in long double loses digits near the zeros)
        const double u = U(engine);
        const long double t = 4.0L*u;
        const long double q = std::nearbyint(t);
        const long double xr = (t - q)*1.57079632679489661923132169163975144L;
        const bool odd = static_cast<long>(q) % 2;
        const long double refCos = std::abs(odd ? std::sin(xr) : std::cos(xr));
        const long double refSin = std::abs(odd ? std::cos(xr) : std::sin(xr));
        double ac, as;
        absCosSinTwoPi(u, ac, as);
        const double thetaD = 2*pi*u;
        acW.add(ulps(ac, refCos), ulps(std::abs(std::cos(thetaD)), refCos), u);
        asW.add(ulps(as, refSin), ulps(std::abs(std::sin(thetaD)), refSin), u);

        double v = U(engine);
        if (i % 3 == 1) v *= std::pow(10.0, -15*U(engine));
        if (i % 3 == 2) v = 1 - std::pow(10.0, -15*U(engine));
        const long double lref = std::log1p(-static_cast<long double>(v));
        logW.add(ulps(log1pMinus(v), lref), ulps(std::log1p(-v), lref), v);
    }
    // edges
    atanW.add(ulps(atan2FirstQuadrant(1, 0), std::atan2(1.0L, 0.0L)), 0, 0);
    atanW.add(ulps(atan2FirstQuadrant(0, 1), 0.0L), 0, 0);
    logW.add(ulps(log1pMinus(0), 0.0L), 0, 0);
    logW.add(ulps(log1pMinus(std::nextafter(1.0, 0.0)),
                  std::log1p(-static_cast<long double>(std::nextafter(1.0, 0.0)))), 0, 0);

    int failed = 0;
    for (const Worst* w : {&atanW, &sinW, &cosW, &acW, &asW, &logW})
    {
        w->print();
        failed += !(w->fast <= 4);
    }
    std::printf("%s\n", failed ? "FAILED: an error above 4 ulp" : "all within 4 ulp");
    return failed ? 1 : 0;
}
