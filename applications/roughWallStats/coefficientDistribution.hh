// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// The distribution of one restitution coefficient k = phi(gamma) after one
// facet collision at incidence alpha: the change of variables (2.8) as
// corrected,
//     Phi(k, alpha) = sum over the roots gamma_i of phi(gamma_i) = k of
//                     P(gamma_i, alpha) / |phi'(gamma_i)|  / Z,
// Z = cdf(pi/2, alpha) (facets beyond the vertical are excluded). The tilt
// range is cut into pieces on which phi is smooth and monotone (at the regime
// boundaries and the zeros of phi'), so every root is bracketed. On a piece
// where phi is constant (k_Omega while sliding without friction) the
// distribution has an atom, which the density leaves out and the bin
// probabilities include. Needs Delta > 0.
//
// Next to an extremum k* of phi the density is P/sqrt(2 |phi''| |k - k*|);
// within 1e-10 (relative) of k* the root k(gamma) = k is lost in the
// round-off of k(gamma), and that local form is used instead.
#pragma once

#include "facetResponse.hh"

#include "CollisionAngleDistribution.hpp"

#include <utility>
#include <vector>

namespace roughWallStats
{

class CoefficientDistribution
{
public:

    struct Atom
    {
        double k;
        double probability;
    };

    CoefficientDistribution(const Model& model, const Incidence& incidence, Coefficient which);

    //- Probability density of k [1/unit of k]
    double density(double k) const;

    //- Exact probability of lo <= k < hi, from the distribution of gamma
    double probability(double lo, double hi) const;

    //- The k range over the tilts between the quantiles q and 1 - q of
    //  gamma: it holds at least 1 - 2 q of the probability
    std::pair<double, double> essentialRange(double q) const;

    const std::vector<Atom>& atoms() const { return atoms_; }

    //- Values of k where the density is singular or jumps: the ends of the
    //  monotone pieces (extrema of phi, regime boundaries, range ends)
    std::vector<double> criticalValues() const;

private:

    struct Piece
    {
        double gLo, gHi;   //!< tilt interval
        Regime regime;
        double kLo, kHi;   //!< k at gLo and gHi (the piece's own regime)
        bool constant;
        //- k'' at an end that is an extremum of k (phi' = 0), else 0
        double curvatureLo = 0, curvatureHi = 0;
    };

    double k(double gamma, Regime regime) const;
    double dk(double gamma, Regime regime) const;

    //- Probability of gamma in [g1, g2] over Z
    double mass(double g1, double g2) const;

    //- The tilt in the piece where k takes the value kv (clipped to its range)
    double preimage(const Piece& piece, double kv) const;

    //- Second derivative of k in gamma, by a central difference of phi'
    double curvature(double gamma, Regime regime) const;

    FacetResponse response_;
    Coefficient which_;
    roughWall::CollisionAngleDistribution P_;
    double Z_;
    std::vector<Piece> pieces_;
    std::vector<Atom> atoms_;
};

//- Monte Carlo histogram of one coefficient on the given bin edges
struct Histogram
{
    std::vector<long long> counts;
    long long below = 0, above = 0, samples = 0;
};

struct MonteCarloSettings;

Histogram sampleHistogram
(
    const Model& model,
    const Incidence& incidence,
    Coefficient which,
    const std::vector<double>& edges,
    const MonteCarloSettings& settings
);

} // namespace roughWallStats
