// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later

#include "quadratureStatistics.hh"
#include "numerics.hh"

#include "CollisionAngleDistribution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roughWallStats
{

TiltRange tiltRange(const Model& model, const Incidence& incidence)
{
    const double tail = 40*model.Delta;
    return {std::max(-incidence.alpha, -tail), std::min(0.5*roughWall::pi, tail)};
}

double admissibleMass(const Model& model, const Incidence& incidence)
{
    const roughWall::CollisionAngleDistribution P(model.Delta);
    return P.cdf(0.5*roughWall::pi, incidence.alpha);
}

std::vector<double> smoothPieces(const FacetResponse& response, const TiltRange& range)
{
    std::vector<double> breaks{range.lo};
    for (const double g : response.regimeBoundaries(range.lo, range.hi))
    {
        breaks.push_back(g);
    }
    // The kinks of tabulated coefficients: the table nodes, beta = alpha + gamma
    const double alpha = response.incidence().alpha;
    for (const double betaDeg : response.model().impact.angleKinks)
    {
        const double g = betaDeg*(roughWall::pi/180) - alpha;
        if (g > range.lo && g < range.hi)
        {
            breaks.push_back(g);
        }
    }
    std::sort(breaks.begin(), breaks.end());
    breaks.push_back(range.hi);

    // Zeros of V''_y within each regime piece
    std::vector<double> all = breaks;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
    {
        const double a = breaks[i], b = breaks[i + 1];
        const Regime regime = response.regime(0.5*(a + b));
        const auto vy = [&](double g) { return response.analytic(g, regime).vy; };
        for (const double g : rootsByScan(vy, a, b))
        {
            all.push_back(g);
        }
    }
    std::sort(all.begin(), all.end());
    return all;
}

namespace
{

//- A single value: Delta = 0 (the smooth wall) hits the facet gamma = 0
Statistics deterministic(const FacetResponse& response)
{
    Regime regime;
    const Coefficients k = response.collide(0, &regime);
    Statistics s;
    s.meanKn = k.kn;
    s.meanAbsKn = std::abs(k.kn);
    s.meanKt = k.kt;
    s.meanKOmega = k.kOmega;
    s.pNoSlip = regime == Regime::noSlip;
    s.pWallward = k.kn < 0;
    return s;
}

} // namespace

Statistics quadratureStatistics
(
    const Model& model,
    const Incidence& incidence,
    const QuadratureSettings& settings
)
{
    const FacetResponse response(model, incidence);
    Statistics s;
    if (!(model.Delta > 0))
    {
        s = deterministic(response);
    }
    else
    {
        const roughWall::CollisionAngleDistribution P(model.Delta);
        const std::vector<double> breaks =
            smoothPieces(response, tiltRange(model, incidence));
        const double alpha = incidence.alpha;

        // First moments and the probabilities of the regimes, of the
        // rebound (V''_y, V''_x, r Omega''_z): k_n = V''_y / sin(alpha) etc.
        const auto first = [&](double g)
        {
            const double w = P.pdf(g, alpha);
            Regime regime;
            const Rebound r = response.rebound(g, &regime);
            return Vector<10>
            {
                w,
                w*r.vy,
                w*std::abs(r.vy),
                w*r.vx,
                w*r.rw,
                regime == Regime::noSlip ? w : 0.0,
                r.vy < 0 ? w : 0.0,
                w*r.vy*r.vy,     // for the round-off floor of the variances
                w*r.vx*r.vx,
                w*r.rw*r.rw
            };
        };
        // Probabilities are resolved to 1e-16 absolute at least: a class that
        // lives in the far tail (|gamma| ~ 38 Delta) has denormal densities
        const double Z = admissibleMass(model, incidence);
        Vector<10> probabilityFloor{};
        probabilityFloor[5] = probabilityFloor[6] = 1e-16*Z;
        const auto m = integrateAdaptive<10>
        (
            first, breaks, settings.tolerance, settings.maxIntervals, probabilityFloor
        );
        const double meanVy = m.integral[1]/Z;
        const double meanVx = m.integral[3]/Z;
        const double meanRw = m.integral[4]/Z;
        s.pNoSlip = m.integral[5]/Z;
        s.pWallward = m.integral[6]/Z;

        // Second moments about the means
        const auto second = [&](double g)
        {
            const double w = P.pdf(g, alpha);
            const Rebound r = response.rebound(g);
            const double dy = r.vy - meanVy;
            const double dx = r.vx - meanVx;
            const double dw = r.rw - meanRw;
            return Vector<3>{w*dy*dy, w*dx*dx, w*dw*dw};
        };
        // Round-off floor: k carries an error of ~eps |k| at every node, so
        // (k - mean)^2 carries 2 eps |k| |k - mean|, i.e. ~2 eps sqrt(E k^2) sd
        Vector<3> floor{};
        const double means[3] = {meanVy, meanVx, meanRw};
        for (std::size_t c = 0; c < 3; ++c)
        {
            const double meanSquare = m.integral[7 + c]/Z;
            const double variance = std::max
            (
                meanSquare - means[c]*means[c],
                std::numeric_limits<double>::epsilon()*meanSquare
            );
            floor[c] = 16*std::numeric_limits<double>::epsilon()
                *std::sqrt(meanSquare*variance)*Z;
        }
        const auto v = integrateAdaptive<3>
        (
            second, breaks, settings.tolerance, settings.maxIntervals, floor
        );
        const double sdVy = std::sqrt(std::max(0.0, v.integral[0]/Z));
        const double sdVx = std::sqrt(std::max(0.0, v.integral[1]/Z));
        const double sdRw = std::sqrt(std::max(0.0, v.integral[2]/Z));

        // The coefficients (2.5)
        s.meanKn = meanVy/incidence.sinAlpha;
        s.sdKn = sdVy/incidence.sinAlpha;
        s.meanAbsKn = m.integral[2]/Z/incidence.sinAlpha;
        if (incidence.tangentialDefined())
        {
            s.meanKt = meanVx/incidence.cosAlpha;
            s.sdKt = sdVx/incidence.cosAlpha;
            s.meanKOmega = meanRw/incidence.cosAlpha;
            s.sdKOmega = sdRw/incidence.cosAlpha;
        }

        s.intervals = m.intervals + v.intervals;
        s.converged = v.converged;
        for (std::size_t c = 0; c < 7; ++c)
        {
            s.converged = s.converged
                && m.error[c] <= std::max(settings.tolerance*m.l1[c], probabilityFloor[c]);
        }
        // Largest relative error estimate where no floor applies (components
        // 7-9 of the first pass only set the floor of the second)
        for (std::size_t c = 0; c < 7; ++c)
        {
            if (m.l1[c] > 0 && m.error[c] > probabilityFloor[c])
            {
                s.errorEstimate = std::max(s.errorEstimate, m.error[c]/m.l1[c]);
            }
        }
        for (std::size_t c = 0; c < 3; ++c)
        {
            if (v.l1[c] > 0 && v.error[c] > floor[c])
            {
                s.errorEstimate = std::max(s.errorEstimate, v.error[c]/v.l1[c]);
            }
        }
    }
    s.alphaDeg = incidence.degrees;
    s.tangentialDefined = incidence.tangentialDefined();
    if (!s.tangentialDefined)
    {
        s.meanKt = s.sdKt = s.meanKOmega = s.sdKOmega = 0;
    }
    return s;
}

} // namespace roughWallStats
