// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later

#include "monteCarloStatistics.hh"

#include "roughWallCollision.hpp"

#include <cmath>
#include <cstring>

namespace roughWallStats
{

Uniform01::Uniform01(std::uint64_t seed, double alphaDeg)
{
    std::uint64_t bits;
    std::memcpy(&bits, &alphaDeg, sizeof bits);
    std::seed_seq sequence
    {
        static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
        static_cast<std::uint32_t>(bits), static_cast<std::uint32_t>(bits >> 32)
    };
    engine_.seed(sequence);
}

WallHitSampler::WallHitSampler
(
    const Model& model,
    const Incidence& incidence,
    const MonteCarloSettings& settings
)
:
    model_(model),
    in_(incidence),
    settings_(settings)
{}

Outcome WallHitSampler::operator()(Uniform01& uniform01) const
{
    const Vec3 N(0, 1, 0);
    Vec3 v = in_.velocity();
    Vec3 w = in_.spin(model_.AOmega);
    Outcome outcome;

    if (settings_.recollide)
    {
        // In-plane model: a 2-D wall (no sideways tilt, no out-of-plane motion)
        const Vec3 emptyDirection = settings_.lateral ? Vec3::Zero() : Vec3(0, 0, 1);
        const auto hit = [&](auto coefficients)
        {
            roughWall::RoughWallParametersOf<decltype(coefficients)> p;
            p.material = coefficients;
            p.roughnessAngle = model_.Delta;
            p.lateralTilt = settings_.lateral;
            p.maxFacetCollisions = settings_.maxFacetCollisions;
            return roughWall::collideWithRoughWall<true>
            (
                v, w, N, 1.0, p, uniform01, emptyDirection
            );
        };
        const roughWall::RoughWallReport report = model_.impact.any()
            ? hit(ModelCoefficients{&model_}) : hit(model_.material);
        outcome.facetCollisions = report.facetCollisions;
        outcome.noSlip = report.noSlip;
        outcome.fallback = report.fallback;
        outcome.rebound = Rebound::of(v, w);
        outcome.firstWallward = v.y() < 0;   // never: the operator's guarantee
        return outcome;
    }

    // One facet collision: the operator's steps 2-4 (roughWallCollision.hpp)
    const Vec3 direction = v.normalized();
    for (;;)
    {
        const double gamma =
            roughWall::detail::sampleFacetTilt(in_.alpha, model_.Delta, uniform01);
        Vec3 n(-std::sin(gamma), std::cos(gamma), 0);
        if (settings_.lateral && model_.Delta > 0)
        {
            const double delta =
                roughWall::detail::sampleLateralTilt(model_.Delta, uniform01);
            n = Eigen::AngleAxisd(delta, direction)*n;
        }
        if (v.dot(n) < 0)
        {
            const Regime regime = model_.impact.any()
                ? roughWall::collideWithFacet<true>(v, w, n, 1.0, ModelCoefficients{&model_})
                : roughWall::collideWithFacet<true>(v, w, n, 1.0, model_.material);
            outcome.noSlip = regime == Regime::noSlip;
            break;
        }
        // alpha + gamma ~ 0 at round-off level: a grazed facet, draw another
    }
    outcome.rebound = Rebound::of(v, w);
    outcome.firstWallward = v.y() < 0;
    return outcome;
}

namespace
{

//- Running mean and central moments up to the fourth (Pebay's updates),
//  for the standard errors of a mean and of a standard deviation
class Moments
{
    long long n_ = 0;
    double mean_ = 0, M2_ = 0, M3_ = 0, M4_ = 0;

public:

    void add(double x)
    {
        const double n1 = static_cast<double>(n_);
        ++n_;
        const double n = static_cast<double>(n_);
        const double delta = x - mean_;
        const double dn = delta/n;
        const double dn2 = dn*dn;
        const double term = delta*dn*n1;
        mean_ += dn;
        M4_ += term*dn2*(n*n - 3*n + 3) + 6*dn2*M2_ - 4*dn*M3_;
        M3_ += term*dn*(n - 2) - 3*dn*M2_;
        M2_ += term;
    }

    double mean() const { return mean_; }

    double variance() const { return n_ > 1 ? M2_/(n_ - 1) : 0; }

    double sd() const { return std::sqrt(variance()); }

    double seMean() const { return n_ > 1 ? std::sqrt(variance()/n_) : 0; }

    //- Delta-method standard error of the sample standard deviation:
    //  var(s) ~ (m4 - s^4)/(4 s^2 n)
    double seSd() const
    {
        if (n_ < 2 || !(M2_ > 0)) return 0;
        const double m2 = M2_/n_, m4 = M4_/n_;
        return std::sqrt(std::max(0.0, m4 - m2*m2)/(4*m2*n_));
    }
};

double seProportion(double p, long long n)
{
    return std::sqrt(std::max(0.0, p*(1 - p))/static_cast<double>(n));
}

} // namespace

Statistics monteCarloStatistics
(
    const Model& model,
    const Incidence& incidence,
    const MonteCarloSettings& settings
)
{
    const WallHitSampler sample(model, incidence, settings);
    Uniform01 uniform01(settings.seed, incidence.degrees);

    // moments of the rebound; divided by sin(alpha), cos(alpha) at the end
    Moments vy, absVy, vx, rw, collisions;
    long long wallward = 0, fallbacks = 0;
    // no-slip fraction of the facet collisions: ratio estimator sum X / sum Y
    double sumX = 0, sumY = 0, sumXX = 0, sumYY = 0, sumXY = 0;
    for (long long i = 0; i < settings.samples; ++i)
    {
        const Outcome o = sample(uniform01);
        vy.add(o.rebound.vy);
        absVy.add(std::abs(o.rebound.vy));
        vx.add(o.rebound.vx);
        rw.add(o.rebound.rw);
        collisions.add(o.facetCollisions);
        wallward += o.firstWallward;
        fallbacks += o.fallback;
        const double X = o.noSlip, Y = o.facetCollisions;
        sumX += X; sumY += Y; sumXX += X*X; sumYY += Y*Y; sumXY += X*Y;
    }

    const long long n = settings.samples;
    Statistics s;
    s.alphaDeg = incidence.degrees;
    s.tangentialDefined = incidence.tangentialDefined();
    s.samples = n;
    const double sinAlpha = incidence.sinAlpha;
    s.meanKn = vy.mean()/sinAlpha;        s.seMeanKn = vy.seMean()/sinAlpha;
    s.sdKn = vy.sd()/sinAlpha;            s.seSdKn = vy.seSd()/sinAlpha;
    s.meanAbsKn = absVy.mean()/sinAlpha;  s.seMeanAbsKn = absVy.seMean()/sinAlpha;
    if (incidence.tangentialDefined())
    {
        const double cosAlpha = incidence.cosAlpha;
        s.meanKt = vx.mean()/cosAlpha;        s.seMeanKt = vx.seMean()/cosAlpha;
        s.sdKt = vx.sd()/cosAlpha;            s.seSdKt = vx.seSd()/cosAlpha;
        s.meanKOmega = rw.mean()/cosAlpha;    s.seMeanKOmega = rw.seMean()/cosAlpha;
        s.sdKOmega = rw.sd()/cosAlpha;        s.seSdKOmega = rw.seSd()/cosAlpha;
    }

    s.pWallward = static_cast<double>(wallward)/n;
    s.sePWallward = seProportion(s.pWallward, n);
    s.pFallback = static_cast<double>(fallbacks)/n;
    s.meanFacetCollisions = collisions.mean();
    s.seMeanFacetCollisions = collisions.seMean();

    const double R = sumY > 0 ? sumX/sumY : 0;
    s.pNoSlip = R;
    if (sumY > 0 && n > 1)
    {
        // var(X - R Y)/(n Ybar^2), the delta method for a ratio of means
        const double Ybar = sumY/n;
        const double varResidual =
            (sumXX - 2*R*sumXY + R*R*sumYY)/(n - 1);
        s.sePNoSlip = std::sqrt(std::max(0.0, varResidual)/n)/Ybar;
    }
    return s;
}

} // namespace roughWallStats
