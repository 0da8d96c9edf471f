// Shared helpers of the core tests.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <limits>

namespace roughWallTest
{

constexpr double deg = 3.14159265358979323846/180;

//- Adaptive Gauss-Kronrod (61 points, Boost.Math): independent of the core's
//  fixed Gauss-Legendre rules
template<class F>
double integrate(const F& f, double a, double b, double tol = 1e-12)
{
    return boost::math::quadrature::gauss_kronrod<double, 61>::integrate
    (
        f, a, b, 12, tol
    );
}

inline double relativeError(double value, double reference)
{
    return std::abs(value - reference)/std::abs(reference);
}

} // namespace roughWallTest
