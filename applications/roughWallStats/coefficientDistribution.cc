// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later

#include "coefficientDistribution.hh"
#include "monteCarloStatistics.hh"
#include "numerics.hh"
#include "quadratureStatistics.hh"

#include "facetAngleSampler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace roughWallStats
{

CoefficientDistribution::CoefficientDistribution
(
    const Model& model,
    const Incidence& incidence,
    Coefficient which
)
:
    response_(model, incidence),
    which_(which),
    P_(model.Delta),
    Z_(admissibleMass(model, incidence))
{
    if (!(model.Delta > 0))
    {
        throw std::invalid_argument("the pdf needs Delta > 0 (Delta = 0: a single value)");
    }
    if (which != Coefficient::kn && !incidence.tangentialDefined())
    {
        throw std::invalid_argument("k_t and k_Omega are undefined at alpha = 90 deg");
    }

    const TiltRange range = tiltRange(model, incidence);
    std::vector<double> breaks{range.lo};
    for (const double g : response_.regimeBoundaries(range.lo, range.hi))
    {
        breaks.push_back(g);
    }
    breaks.push_back(range.hi);

    constexpr int scan = 256;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
    {
        const double a = breaks[i], b = breaks[i + 1];
        const Regime regime = response_.regime(0.5*(a + b));
        const auto derivative = [&](double g) { return dk(g, regime); };

        bool constant = true;
        for (int j = 0; j <= scan && constant; ++j)
        {
            constant = derivative(a + (b - a)*j/scan) == 0;
        }
        if (constant)
        {
            const double kc = k(0.5*(a + b), regime);
            pieces_.push_back({a, b, regime, kc, kc, true});
            atoms_.push_back({kc, mass(a, b)});
            continue;
        }
        std::vector<double> ends{a};
        for (const double g : rootsByScan(derivative, a, b, scan))
        {
            ends.push_back(g);
        }
        ends.push_back(b);
        for (std::size_t j = 0; j + 1 < ends.size(); ++j)
        {
            const double lo = ends[j], hi = ends[j + 1];
            Piece piece{lo, hi, regime, k(lo, regime), k(hi, regime), false};
            if (j > 0) piece.curvatureLo = curvature(lo, regime);
            if (j + 2 < ends.size()) piece.curvatureHi = curvature(hi, regime);
            pieces_.push_back(piece);
        }
    }
}

double CoefficientDistribution::k(double gamma, Regime regime) const
{
    return select(response_.analytic(gamma, regime).k, which_);
}

double CoefficientDistribution::dk(double gamma, Regime regime) const
{
    return select(response_.analytic(gamma, regime).dk, which_);
}

double CoefficientDistribution::curvature(double gamma, Regime regime) const
{
    const double h = 1e-6;
    return (dk(gamma + h, regime) - dk(gamma - h, regime))/(2*h);
}

double CoefficientDistribution::mass(double g1, double g2) const
{
    if (!(g2 > g1))
    {
        return 0;
    }
    const double alpha = response_.incidence().alpha;
    const double upper = P_.cdf(g2, alpha);
    if (upper <= 0.5)
    {
        return (upper - P_.cdf(g1, alpha))/Z_;
    }
    return (P_.sf(g1, alpha) - P_.sf(g2, alpha))/Z_;
}

double CoefficientDistribution::preimage(const Piece& piece, double kv) const
{
    const double kMin = std::min(piece.kLo, piece.kHi);
    const double kMax = std::max(piece.kLo, piece.kHi);
    const bool increasing = piece.kHi > piece.kLo;
    if (kv <= kMin) return increasing ? piece.gLo : piece.gHi;
    if (kv >= kMax) return increasing ? piece.gHi : piece.gLo;
    const auto f = [&](double g) { return k(g, piece.regime) - kv; };
    return bracketedRoot(f, piece.gLo, piece.gHi, piece.kLo - kv, piece.kHi - kv);
}

double CoefficientDistribution::density(double kv) const
{
    const double alpha = response_.incidence().alpha;
    double sum = 0;
    for (const Piece& piece : pieces_)
    {
        if (piece.constant) continue;
        const double kMin = std::min(piece.kLo, piece.kHi);
        const double kMax = std::max(piece.kLo, piece.kHi);
        if (!(kv > kMin && kv < kMax)) continue;
        // next to an extremum end: the local form P/sqrt(2 |k''| |k - k*|)
        bool local = false;
        for (const auto& [gEnd, kEnd, curvature] :
            {
                std::tuple{piece.gLo, piece.kLo, piece.curvatureLo},
                std::tuple{piece.gHi, piece.kHi, piece.curvatureHi}
            })
        {
            const double distance = std::abs(kv - kEnd);
            if (curvature != 0 && distance < 1e-10*(1 + std::abs(kEnd)))
            {
                sum += P_.pdf(gEnd, alpha)/std::sqrt(2*std::abs(curvature)*distance);
                local = true;
            }
        }
        if (local) continue;
        const double g = preimage(piece, kv);
        sum += P_.pdf(g, alpha)/std::abs(dk(g, piece.regime));
    }
    return sum/Z_;
}

double CoefficientDistribution::probability(double lo, double hi) const
{
    double sum = 0;
    for (const Piece& piece : pieces_)
    {
        if (piece.constant)
        {
            if (piece.kLo >= lo && piece.kLo < hi)
            {
                sum += mass(piece.gLo, piece.gHi);
            }
            continue;
        }
        const double g1 = preimage(piece, lo), g2 = preimage(piece, hi);
        sum += mass(std::min(g1, g2), std::max(g1, g2));
    }
    return sum;
}

std::pair<double, double> CoefficientDistribution::essentialRange(double q) const
{
    const double alpha = response_.incidence().alpha;
    const double Delta = P_.Delta();
    const auto quantile = [&](double U)
    {
        auto fixed = [U]() { return U; };
        return roughWall::sampleFacetAngleByInversion(alpha, Delta, fixed);
    };
    const double gLo = quantile(q*Z_), gHi = quantile((1 - q)*Z_);

    double kMin = HUGE_VAL, kMax = -HUGE_VAL;
    for (const Piece& piece : pieces_)
    {
        const double a = std::max(piece.gLo, gLo), b = std::min(piece.gHi, gHi);
        if (!(b >= a)) continue;
        for (const double g : {a, b})
        {
            const double kv = piece.constant ? piece.kLo : k(g, piece.regime);
            kMin = std::min(kMin, kv);
            kMax = std::max(kMax, kv);
        }
    }
    if (!(kMax > kMin))
    {
        kMin -= 0.5;
        kMax += 0.5;
    }
    return {kMin, kMax};
}

std::vector<double> CoefficientDistribution::criticalValues() const
{
    std::vector<double> values;
    for (const Piece& piece : pieces_)
    {
        values.push_back(piece.kLo);
        values.push_back(piece.kHi);
    }
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    return values;
}

Histogram sampleHistogram
(
    const Model& model,
    const Incidence& incidence,
    Coefficient which,
    const std::vector<double>& edges,
    const MonteCarloSettings& settings
)
{
    Histogram h;
    const std::size_t bins = edges.size() - 1;
    h.counts.assign(bins, 0);
    const double lo = edges.front(), hi = edges.back();
    const double width = (hi - lo)/bins;
    const WallHitSampler sample(model, incidence, settings);
    Uniform01 uniform01(settings.seed, incidence.degrees);
    for (long long i = 0; i < settings.samples; ++i)
    {
        const double kv = select(coefficientsOf(sample(uniform01).rebound, incidence), which);
        if (kv < lo)
        {
            ++h.below;
            continue;
        }
        if (kv >= hi)
        {
            ++h.above;
            continue;
        }
        std::size_t bin = std::min(bins - 1, static_cast<std::size_t>((kv - lo)/width));
        // settle round-off at a bin edge: bins are [edges[i], edges[i+1])
        while (bin > 0 && kv < edges[bin]) --bin;
        while (bin + 1 < bins && kv >= edges[bin + 1]) ++bin;
        ++h.counts[bin];
    }
    h.samples = settings.samples;
    return h;
}

} // namespace roughWallStats
