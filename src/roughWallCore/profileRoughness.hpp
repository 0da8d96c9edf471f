// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// The roughness angle Delta (standard deviation of the facet tilt) from the
// profile parameters a profilometer gives (ISO 4287: Ra arithmetic mean
// height, Rq rms height, Rz maximum height, RSm mean width of the profile
// elements) and the particle diameter d_p:
//
//     Delta(d_p) = atan( 2 pi Rq / max(RSm, d_p) )                      (1)
//
// - d_p <= RSm: the particle fits into the valleys and meets the flanks
//   themselves; their slope is that of a sinusoidal profile of rms height
//   Rq and wavelength RSm, whose rms slope is 2 pi Rq / RSm;
// - d_p > RSm: the particle bridges the valleys and rests on the peaks
//   under it; the height differences of order Rq are now spread over the
//   particle's own diameter instead of the profile's wavelength.
// Delta is continuous at d_p = RSm (the regime change), constant below it
// and falls like 1/d_p above it.  This is the picture of Sommerfeld & Huber
// (1999, Int. J. Multiphase Flow 25, 1457-1489: a small particle feels
// the steep flanks of the roughness, a large one bridges them, so that
// Delta falls with the particle size); equation (1) is this project's
// geometric estimate of that picture (docs/roughWallInteraction.md), not
// an equation taken from that paper.
//
// Without Rq, Rq is taken from Ra or Rz as for a Gaussian profile
// (limitsAndUnits.hpp): the one conversion of the model, used by the
// flank-slope check, by equation (1) and by the synthetic profile of the
// envelope (roughnessAngle.hpp).
// Validity: gentle flanks, 2 pi Rq / RSm <= maxProfileSlope (Delta <= 45
// deg); Rq >= Ra (true of every profile); RSm > Ra.
#pragma once

#include "gaussianMass.hpp"
#include "limitsAndUnits.hpp"

#include <cmath>
#include <string>

namespace roughWall
{

//- Profile roughness parameters [m]; 0 means "not given"
struct ProfileRoughness
{
    double Ra = 0;    //!< arithmetic mean height
    double Rq = 0;    //!< root-mean-square height
    double Rz = 0;    //!< maximum height (peak to valley)
    double RSm = 0;   //!< mean width of the profile elements

    //- The rms height: Rq, else from Ra, else from Rz, as for a Gaussian
    //  profile (limitsAndUnits.hpp). The only Ra/Rz -> Rq conversion: the
    //  flank-slope check, equation (1) and the synthetic profile use it
    double rmsHeight() const
    {
        if (Rq > 0) return Rq;
        if (Ra > 0) return limits::rqPerRaGaussian*Ra;
        return Rz/limits::rzPerRqGaussian;
    }
};


//- What is wrong with a set of profile parameters, for the messages
struct ProfileRoughnessError
{
    std::string keyword;   //!< the offending keyword (empty: none)
    std::string allowed;   //!< what is allowed
};


//- Check the parameters; an empty keyword means they are valid.
//  given*: whether the keyword was given (a given value must be positive).
inline ProfileRoughnessError checkProfileRoughness
(
    const ProfileRoughness& p,
    const bool givenRa,
    const bool givenRq,
    const bool givenRz
)
{
    const auto positive = [](const double x) { return x > 0 && std::isfinite(x); };

    if (givenRa && !positive(p.Ra)) return {"Ra", "a length > 0 [m]"};
    if (givenRq && !positive(p.Rq)) return {"Rq", "a length > 0 [m]"};
    if (givenRz && !positive(p.Rz)) return {"Rz", "a length > 0 [m]"};
    if (!positive(p.RSm)) return {"RSm", "a length > 0 [m] (mandatory)"};
    if (!givenRa && !givenRq && !givenRz)
    {
        return {"Ra", "at least one of Ra, Rq, Rz (a length > 0 [m])"};
    }
    if (givenRa && givenRq && p.Rq < p.Ra)
    {
        return {"Rq", "Rq >= Ra (the rms height is never below the mean "
                      "absolute height)"};
    }
    if (givenRa && p.RSm <= p.Ra)
    {
        return {"RSm", "RSm > Ra (the profile elements are wider than high)"};
    }
    if (2*pi*p.rmsHeight() > limits::maxProfileSlope*p.RSm)
    {
        return
        {
            "RSm",
            "RSm >= 2 pi Rq / " + std::to_string(limits::maxProfileSlope)
          + " (rms profile slope at most "
          + std::to_string(limits::maxProfileSlope)
          + ", roughness angle at most "
          + std::to_string(limits::maxRoughnessAngleDeg)
          + " deg; Rq = sqrt(pi/2) Ra or Rz/4.11 if not given)"
        };
    }
    return {};
}


//- Delta(d_p) of equation (1), with the angles of the last few diameters
//  cached: a cloud of up to cacheSize sizes costs a few comparisons per hit,
//  not an atan; a continuous size distribution costs an atan per hit
class RoughnessCorrelation
{
public:

    //- Number of diameters cached
    static constexpr int cacheSize = 8;

private:

    //- 2 pi Rq [m]
    double twoPiRq_ = 0;

    //- RSm [m]
    double RSm_ = 1;

    //- Cached diameters (-1: empty) and their angles; replaced round-robin
    //  (single-threaded use, as OpenFOAM's clouds)
    mutable double cachedDiameter_[cacheSize] = {-1, -1, -1, -1, -1, -1, -1, -1};
    mutable double cachedAngle_[cacheSize] = {};
    mutable int next_ = 0;

public:

    RoughnessCorrelation() = default;

    explicit RoughnessCorrelation(const ProfileRoughness& p)
    :
        twoPiRq_(2*pi*p.rmsHeight()),
        RSm_(p.RSm)
    {}

    //- Equation (1) [rad], evaluated
    double angleUncached(const double d) const
    {
        return std::atan(twoPiRq_/(d > RSm_ ? d : RSm_));
    }

    //- Equation (1) [rad], from the cache when d is one of the last
    //  cacheSize diameters
    double angle(const double d) const
    {
        for (int i = 0; i < cacheSize; ++i)
        {
            if (cachedDiameter_[i] == d)
            {
                return cachedAngle_[i];
            }
        }
        const double a = angleUncached(d);
        cachedDiameter_[next_] = d;
        cachedAngle_[next_] = a;
        next_ = (next_ + 1) % cacheSize;
        return a;
    }

    //- The diameter of the regime change [m]
    double regimeChangeDiameter() const { return RSm_; }

    //- The rms height of equation (1) [m]
    double rmsHeight() const { return twoPiRq_/(2*pi); }
};

} // End namespace roughWall
