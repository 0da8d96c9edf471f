// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// The elementary functions of one wall hit, on the restricted arguments the
// collision operator needs, without libm calls.
//
// glibc's atan2, sincos and log1p handle every argument (range reduction
// for huge angles, infinities, NaN, errno) and cost 60-140 instructions a
// call; here the arguments are known to be tame:
//   atan2FirstQuadrant(y, x)  y, x >= 0, not both 0 (the incidence angle)
//   sinCosHalfPi(x)           |x| <= pi/2 (the facet tilt)
//   log1pMinus(u)             log(1 - u) for u in [0, 1)
// The polynomial kernels are fdlibm's, each with error below 1 ulp; the
// reductions here add at most ~2 ulp (tests/core/testFastMath.cc). fdlibm's
// notice, preserved as it asks:
//
//   Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
//
//   Developed at SunPro, a Sun Microsystems, Inc. business.
//   Permission to use, copy, modify, and distribute this
//   software is freely granted, provided that this notice
//   is preserved.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace roughWall
{
namespace fastMath
{

namespace detail
{

inline std::uint64_t bits(double x)
{
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

inline double fromBits(std::uint64_t b)
{
    double x;
    std::memcpy(&x, &b, sizeof x);
    return x;
}

//- fdlibm __kernel_sin(x, 0, 0), |x| <= pi/4
inline double kernelSin(double x)
{
    constexpr double S1 = -1.66666666666666324348e-01;
    constexpr double S2 = 8.33333333332248946124e-03;
    constexpr double S3 = -1.98412698298579493134e-04;
    constexpr double S4 = 2.75573137070700676789e-06;
    constexpr double S5 = -2.50507602534068634195e-08;
    constexpr double S6 = 1.58969099521155010221e-10;
    const double z = x*x;
    const double w = z*z;
    const double r = S2 + z*(S3 + z*S4) + z*w*(S5 + z*S6);
    const double v = z*x;
    return x + v*(S1 + z*r);
}

//- fdlibm __kernel_cos(x, 0), |x| <= pi/4
inline double kernelCos(double x)
{
    constexpr double C1 = 4.16666666666666019037e-02;
    constexpr double C2 = -1.38888888888741095749e-03;
    constexpr double C3 = 2.48015872894767294178e-05;
    constexpr double C4 = -2.75573143513906633035e-07;
    constexpr double C5 = 2.08757232129817482790e-09;
    constexpr double C6 = -1.13596475577881948265e-11;
    const double z = x*x;
    const double w = z*z;
    const double r = z*(C1 + z*(C2 + z*C3)) + w*w*(C4 + z*(C5 + z*C6));
    const double hz = 0.5*z;
    const double one_hz = 1.0 - hz;
    return one_hz + (((1.0 - one_hz) - hz) + z*r);
}

//- fdlibm atan kernel: atan(z) for |z| <= 7/16
inline double kernelAtan(double z)
{
    constexpr double aT[] = {
        3.33333333333329318027e-01, -1.99999999998764832476e-01,
        1.42857142725034663711e-01, -1.11111104054623557880e-01,
        9.09088713343650656196e-02, -7.69187620504482999495e-02,
        6.66107313738753120669e-02, -5.83357013379057348645e-02,
        4.97687799461593236017e-02, -3.65315727442169155270e-02,
        1.62858201153657823623e-02
    };
    const double z2 = z*z;
    const double w = z2*z2;
    const double s1 = z2*(aT[0] + w*(aT[2] + w*(aT[4] + w*(aT[6] + w*(aT[8] + w*aT[10])))));
    const double s2 = w*(aT[1] + w*(aT[3] + w*(aT[5] + w*(aT[7] + w*aT[9]))));
    return z - z*(s1 + s2);
}

//- fdlibm log kernel: log(1 + f) = f - hfsq + tail, returns tail and hfsq,
//  for sqrt(2)/2 - 1 <= f < sqrt(2) - 1 (e_log.c)
inline double kernelLogTail(double f, double& hfsq)
{
    constexpr double Lg1 = 6.666666666666735130e-01;
    constexpr double Lg2 = 3.999999999940941908e-01;
    constexpr double Lg3 = 2.857142874366239149e-01;
    constexpr double Lg4 = 2.222219843214978396e-01;
    constexpr double Lg5 = 1.818357216161805012e-01;
    constexpr double Lg6 = 1.531383769920937332e-01;
    constexpr double Lg7 = 1.479819860511658591e-01;
    const double s = f/(2.0 + f);
    const double z = s*s;
    const double w = z*z;
    const double t1 = w*(Lg2 + w*(Lg4 + w*Lg6));
    const double t2 = z*(Lg1 + w*(Lg3 + w*(Lg5 + w*Lg7)));
    const double R = t2 + t1;
    hfsq = 0.5*f*f;
    return s*(hfsq + R);
}

constexpr double pio2Hi = 1.57079632679489655800e+00;
constexpr double pio2Lo = 6.12323399573676603587e-17;
constexpr double pio4Hi = 7.85398163397448278999e-01;
constexpr double pio4Lo = 3.06161699786838301793e-17;
constexpr double tanPio8 = 0.41421356237309504880;

} // namespace detail

//- atan2(y, x) for y >= 0, x >= 0, not both zero: an angle in [0, pi/2].
//  fdlibm's three argument ranges (atan(a/b), pi/4 + atan((a - b)/(a + b))
//  with a = min, b = max, and pi/2 minus either when y > x) chosen by
//  selects, not branches: for incidence angles spread over [0, pi/2] the
//  branches were mispredicted in half the hits. One division; the argument
//  of the kernel is at most tan(pi/8) in magnitude.
inline double atan2FirstQuadrant(double y, double x)
{
    using namespace detail;
    const double a = std::min(y, x);
    const double b = std::max(y, x);
    const double middle = a > tanPio8*b ? 1.0 : 0.0;
    const double r =
        middle*pio4Hi + (kernelAtan((a - middle*b)/(b + middle*a)) + middle*pio4Lo);
    const double steep = pio2Hi - (r - pio2Lo);
    return y > x ? steep : r;
}

//- sin and cos of x, |x| <= pi/2
inline void sinCosHalfPi(double x, double& s, double& c)
{
    using namespace detail;
    if (std::abs(x) <= pio4Hi)
    {
        s = kernelSin(x);
        c = kernelCos(x);
        return;
    }
    // x = +-pi/2 + r, |r| <= pi/4; x -+ pio2_1 is exact (Sterbenz)
    constexpr double pio2_1 = 1.57079632673412561417e+00;   // 33 bits
    constexpr double pio2_1t = 6.07710050650619224932e-11;  // pi/2 - pio2_1
    const double sign = x > 0 ? 1.0 : -1.0;
    const double r = (x - sign*pio2_1) - sign*pio2_1t;
    s = sign*kernelCos(r);
    c = -sign*kernelSin(r);
}

//- sin and cos of x, |x| <= pi/2, with one polynomial: the smaller of the
//  two in magnitude by fdlibm's sine kernel (of x, or of x -+ pi/2), the
//  larger, >= sqrt(1/2), as sqrt(1 - smaller^2), which has no cancellation.
//  s^2 + c^2 = 1 to rounding; each within 2 ulp
inline void sinCosHalfPiSqrt(double x, double& s, double& c)
{
    using namespace detail;
    if (std::abs(x) <= pio4Hi)
    {
        s = kernelSin(x);
        c = std::sqrt(1 - s*s);
        return;
    }
    constexpr double pio2_1 = 1.57079632673412561417e+00;   // 33 bits
    constexpr double pio2_1t = 6.07710050650619224932e-11;  // pi/2 - pio2_1
    const double sign = x > 0 ? 1.0 : -1.0;
    const double r = (x - sign*pio2_1) - sign*pio2_1t;
    c = -sign*kernelSin(r);
    s = sign*std::sqrt(1 - c*c);
}

//- log(1 - u) for u in [0, 1), as accurate as log1p(-u): v = 1 - u rounded,
//  c = (1 - u) - v exactly, log(1 - u) = log(v) + c/v
inline double log1pMinus(double u)
{
    using namespace detail;
    constexpr double ln2Hi = 6.93147180369123816490e-01;
    constexpr double ln2Lo = 1.90821492927058770002e-10;
    const double v = 1.0 - u;
    const double c = (1.0 - v) - u;
    // v = 2^k m, sqrt(2)/2 <= m < sqrt(2) (v >= 2^-53 is normal)
    std::uint64_t vb = bits(v);
    std::uint32_t hx = static_cast<std::uint32_t>(vb >> 32);
    hx += 0x3ff00000 - 0x3fe6a09e;
    const int k = static_cast<int>(hx >> 20) - 0x3ff;
    hx = (hx & 0x000fffff) + 0x3fe6a09e;
    vb = (static_cast<std::uint64_t>(hx) << 32) | (vb & 0xffffffff);
    const double f = fromBits(vb) - 1.0;
    const double dk = k;
    double hfsq;
    const double tail = kernelLogTail(f, hfsq);
    // small terms first, as in e_log.c
    return (((tail + (dk*ln2Lo + c/v)) - hfsq) + f) + dk*ln2Hi;
}

} // namespace fastMath
} // namespace roughWall
