// roughWallStats: restitution-coefficient statistics of Derevich's rough-wall model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// The statistics of the restitution coefficients at one incidence angle: one
// row of the tool's table.
#pragma once

namespace roughWallStats
{

struct Statistics
{
    double alphaDeg = 0;
    bool tangentialDefined = true;   //!< false at alpha = 90 deg: no k_t, k_Omega

    double meanKn = 0, sdKn = 0, meanAbsKn = 0;
    double meanKt = 0, sdKt = 0;
    double meanKOmega = 0, sdKOmega = 0;
    double pNoSlip = 0;      //!< probability of rolling/no-slip (per facet collision)
    double pWallward = 0;    //!< probability that V''_y < 0 after the first facet

    //- Monte Carlo: sample size and standard errors
    long long samples = 0;
    double seMeanKn = 0, seSdKn = 0, seMeanAbsKn = 0;
    double seMeanKt = 0, seSdKt = 0;
    double seMeanKOmega = 0, seSdKOmega = 0;
    double sePNoSlip = 0, sePWallward = 0;

    //- Repeated facet collisions (--recollide)
    double meanFacetCollisions = 1, seMeanFacetCollisions = 0;
    double pFallback = 0;    //!< the bound was reached: mean-wall rebound

    //- Quadrature diagnostics
    int intervals = 0;
    double errorEstimate = 0;   //!< largest estimated error / integral of |f|
    bool converged = true;
};

} // namespace roughWallStats
