// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// The shadow-corrected distribution of the facet tilt gamma hit by a particle
// arriving at incidence angle alpha on a wall whose facet tilts are normal
// N(0, Delta), eq. (1.3) of Derevich:
//
//     P(gamma, alpha) = [phi(gamma) - phi(gamma + 2 alpha)] / erf(alpha/(sqrt2 Delta)),
//     gamma > -alpha,
//
// with the moments (1.4) and the corrected (1.6). All angles in radians.
//
// In the standardised variables h = alpha/Delta and b = (alpha + gamma)/Delta
// (the impact angle on the facet over Delta) the density is proportional to
// phi(b - h) - phi(b + h) = phi(b - h) (-expm1(-2 h b)): written that way it
// has no cancellation, and its normalisation gaussianMass(-h, h) = erf(h/sqrt2)
// is exact for every h. At h = 0 the Rayleigh limit is used.
#pragma once

#include "gaussianMass.hpp"

#include <cmath>
#include <limits>

namespace roughWall
{

class CollisionAngleDistribution
{
    //- Standard deviation of the facet tilt, Delta [rad]
    double Delta_;

    //- Below this h = alpha/Delta the Rayleigh limit is exact in double
    //  precision (relative corrections are O(h^2))
    static constexpr double hRayleigh_ = 1e-150;

    double h(double alpha) const { return alpha/Delta_; }

    //- Normalisation erf(h/sqrt2), exact to round-off for every h (1 to
    //  double precision beyond h = 40, where h may also be inf: Delta
    //  subnormal, and -h + 2h would be NaN)
    static double mass(double h) { return h > 40 ? 1.0 : gaussianMassFrom(-h, 2*h); }

    //- A ratio of two masses computed differently, kept a probability
    //  (NaN stays NaN)
    static double probability(double p) { return p > 1 ? 1.0 : p; }

public:

    explicit CollisionAngleDistribution(double Delta) : Delta_(Delta) {}

    double Delta() const { return Delta_; }

    //- Probability density of gamma [1/rad]. Delta = 0: a delta function
    //  at 0, returned as +inf there and 0 elsewhere.
    double pdf(double gamma, double alpha) const
    {
        if (!(Delta_ > 0))
        {
            return gamma == 0 ? std::numeric_limits<double>::infinity() : 0;
        }
        const double hh = h(alpha);
        const double b = (alpha + gamma)/Delta_;
        if (!(b > 0))
        {
            return 0;
        }
        // g = gamma/Delta directly, not b - h: no cancellation for h >> 1
        const double g = gamma/Delta_;
        if (hh < hRayleigh_)
        {
            // Rayleigh: b exp(-b^2/2) in b; 0 where exp underflows (b may
            // overflow to inf for gamma/Delta > 1e308: no inf*0)
            return g < 40 ? b*std::exp(-0.5*g*g)/Delta_ : 0;
        }
        return standardNormalPdf(g)*(-std::expm1(-2*hh*b))/(mass(hh)*Delta_);
    }

    //- Probability that the tilt exceeds gamma
    double sf(double gamma, double alpha) const
    {
        if (!(Delta_ > 0))
        {
            return gamma < 0 ? 1 : 0;
        }
        const double hh = h(alpha);
        const double b = (alpha + gamma)/Delta_;
        if (!(b > 0))
        {
            return 1;
        }
        if (hh < hRayleigh_)
        {
            return std::exp(-0.5*b*b);
        }
        // mass of phi over [g, g + 2h] over mass over [-h, h]
        return probability(gaussianMassFrom(gamma/Delta_, 2*hh)/mass(hh));
    }

    //- Probability that the tilt is at most gamma
    double cdf(double gamma, double alpha) const
    {
        if (!(Delta_ > 0))
        {
            return gamma < 0 ? 0 : 1;
        }
        const double hh = h(alpha);
        const double b = (alpha + gamma)/Delta_;
        if (!(b > 0))
        {
            return 0;
        }
        if (hh < hRayleigh_)
        {
            return -std::expm1(-0.5*b*b);
        }
        const double survival = sf(gamma, alpha);
        if (survival <= 0.5)
        {
            return 1 - survival;
        }
        return probability(lowerMass(b, gamma/Delta_, hh)/mass(hh));
    }

    //- Mean tilt <gamma>, eq. (1.4): alpha erfc(A)/erf(A), A = alpha/(sqrt2 Delta)
    double mean(double alpha) const
    {
        if (!(Delta_ > 0))
        {
            return 0;
        }
        const double A = alpha/(sqrt2*Delta_);
        if (A < hRayleigh_)
        {
            return std::sqrt(0.5*pi)*Delta_;
        }
        return alpha*std::erfc(A)/std::erf(A);
    }

    //- Mean square tilt <gamma^2>, eq. (1.6) as corrected:
    //  Delta^2 {1 + [(2/sqrt(pi)) A exp(-A^2) - 4 A^2 erfc(A)] / erf(A)}
    double meanSquare(double alpha) const
    {
        if (!(Delta_ > 0))
        {
            return 0;
        }
        const double A = alpha/(sqrt2*Delta_);
        if (A < hRayleigh_)
        {
            return 2*Delta_*Delta_;
        }
        if (A > 10)
        {
            // The correction is below 1e-42: none in double precision (and
            // A*A*erfc(A) would be inf*0 = NaN for alpha/Delta > 1e154)
            return Delta_*Delta_;
        }
        const double correction =
            (2/std::sqrt(pi)*A*std::exp(-A*A) - 4*A*A*std::erfc(A))/std::erf(A);
        return Delta_*Delta_*(1 + correction);
    }

    //- Standard deviation of the tilt, eq. (1.5)
    double standardDeviation(double alpha) const
    {
        const double m = mean(alpha);
        return std::sqrt(std::max(0.0, meanSquare(alpha) - m*m));
    }

private:

    //- Unnormalised mass of the standardised density on (0, b), for the
    //  lower half of the distribution: composite quadrature of the
    //  cancellation-free integrand where the density is not a plain normal,
    //  else the difference of the two normal masses (at most a factor 2 lost).
    static double lowerMass(double b, double g, double hh)
    {
        if (hh > 6 && b > 2)
        {
            // [-h, g] and [h, h + b]; g, not b - h, keeps its digits for h >> 1
            return gaussianMass(-hh, g) - gaussianMassFrom(hh, b);
        }
        const auto density = [hh](double x)
        {
            return standardNormalPdf(x - hh)*(-std::expm1(-2*hh*x));
        };
        const int panels = std::max(1, static_cast<int>(std::ceil(b/0.5)));
        const double width = b/panels;
        double sum = 0;
        for (int i = 0; i < panels; ++i)
        {
            sum += gaussLegendre20(density, i*width, (i + 1)*width);
        }
        return sum;
    }
};

} // namespace roughWall
