// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Inter-particle collisions by Sommerfeld's stochastic fictitious-partner
// model (Sommerfeld 2001, Int. J. Multiphase Flow 27, 1829-1858): a particle
// collides, within a time step dt, with a partner drawn from the local
// statistics of the particles around it, without any search for neighbours.
//
//   partner diameter d2   drawn from the cell's size distribution (real
//                         particles: each parcel weighs nParticle)
//   partner velocity u2   the cell's mean of d2's size class plus a
//                         fluctuation correlated with the real particle's,
//                         per component k:
//                           u2'_k = R s2_k/s1_k u1'_k + s2_k sqrt(1 - R^2) xi_k
//                         s the rms of a class, xi ~ N(0, 1), and
//                         R(St_K) = exp(-0.55 St_K^0.4) with St_K the
//                         particle relaxation time over the carrier's
//                         Kolmogorov time (R = 0: no correlation)
//   probability           P = pi/4 (d1 + d2)^2 |u1 - u2| n dt, n the cell's
//                         number density of the real particles of the other
//                         parcels: a parcel's own weight is left out, since
//                         with k parcels scattered at random over the cells
//                         a parcel finds on average k/nCells others in its
//                         cell, not k/nCells + 1 (counted in, it would add
//                         one parcel's weight to n: +33 % at 3 parcels per
//                         cell)
//   impact point          uniform over the projected disc of radius
//                         (d1 + d2)/2 normal to u1 - u2
//   collision             hard spheres of one material density, restitution
//                         e and friction mu (no-slip or sliding, as the wall's
//                         facet collision): only the real particle changes
//
// A step whose P for a typical partner exceeds maxProbability is split
// into sub-steps with fresh partners, so that at most about one collision
// per sub-step is assumed.
// Cells with fewer than minCellParcels parcels of a class take that class's
// mean and rms from the whole cloud (their own are noise); the caller is
// told how often.
#pragma once

#include "vectorAndPi.hpp"
#include "standardNormal.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace roughWall
{

//- Material of a particle-particle collision
struct PairMaterial
{
    double e = 1;    //!< normal restitution, [0, 1]
    double mu = 0;   //!< friction coefficient (static = dynamic), >= 0
};

//- Sommerfeld's correlation of the partner's fluctuation with the real
//  particle's: R = exp(-0.55 St_K^0.4), St_K >= 0
inline double partnerCorrelation(double kolmogorovStokes)
{
    return std::exp(-0.55*std::pow(kolmogorovStokes, 0.4));
}

//- Probability of a collision within dt: pi/4 (d1 + d2)^2 |u_rel| n dt
inline double collisionProbability
(
    double d1,
    double d2,
    double relativeSpeed,
    double numberDensity,
    double dt
)
{
    const double sumD = d1 + d2;
    return 0.25*pi*sumD*sumD*relativeSpeed*numberDensity*dt;
}

//- The unit normal of the contact, pointing from the partner to the real
//  particle, for an impact point uniform over the projected disc normal to
//  the relative velocity g = u1 - u2 (g != 0): the impact parameter b/R is
//  sqrt(U) (uniform over the disc's area) at a uniform azimuth. n.g < 0.
template<class Uniform01>
Vec3 partnerContactNormal(const Vec3& g, Uniform01& uniform01)
{
    const Vec3 along = g.normalized();
    // Any unit vector normal to g, then the second by the cross product
    const Vec3 helper =
        std::abs(along.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    const Vec3 across1 = along.cross(helper).normalized();
    const Vec3 across2 = along.cross(across1);

    const double b2 = uniform01();                     // (b/R)^2
    const double phi = 2*pi*uniform01();
    const double sinTheta = std::sqrt(b2);
    const double cosTheta = std::sqrt(1 - b2);

    // The partner's centre seen from the real particle at contact
    const Vec3 toPartner =
        cosTheta*along
      + sinTheta*(std::cos(phi)*across1 + std::sin(phi)*across2);
    return -toPartner;
}

//- Hard-sphere collision of the real particle (u1, w1, radius r1) with the
//  partner (u2, w2, r2) along the contact normal n (partner -> particle,
//  (u1 - u2).n < 0). massRatio = m2/(m1 + m2) = mu_red/m1. The impulses are
//  those of the wall's facet collision (facetCollision.hpp) for the
//  contact's relative velocity and reduced mass: the tangential effective
//  mass of two solid spheres is 2/7 of the reduced mass whatever their
//  sizes, so no-slip holds while |slip| <= 7/2 mu (1 + e) |g.n|. Only the
//  real particle's velocity (and, withSpin, spin) changes.
template<bool withSpin>
void collideWithPartner
(
    Vec3& u1,
    Vec3& w1,
    double r1,
    const Vec3& u2,
    const Vec3& w2,
    double r2,
    double massRatio,
    const Vec3& n,
    const PairMaterial& material
)
{
    const Vec3 g = u1 - u2;
    const double gn = g.dot(n);
    const double jn = -(1 + material.e)*gn*massRatio;    // per unit mass m1

    Vec3 contactVelocity = g;
    if constexpr (withSpin)
    {
        contactVelocity -= (r1*w1 + r2*w2).cross(n);
    }
    const Vec3 slip = contactVelocity - contactVelocity.dot(n)*n;
    const double slipSpeed = slip.norm();
    const double noSlipImpulse = (2.0/7.0)*massRatio*slipSpeed;

    // Sliding impulse capped at the no-slip one: the slip never reverses
    const double jt = std::min(material.mu*jn, noSlipImpulse);
    const Vec3 tangential =
        slipSpeed > 0 ? Vec3(-(jt/slipSpeed)*slip) : Vec3::Zero();

    u1 += jn*n + tangential;
    if constexpr (withSpin)
    {
        w1 -= (2.5/r1)*n.cross(tangential);
    }
}


//- Per-cell statistics of the particles of one step, gathered in O(N):
//  number density, and per size class the mean and rms velocity (and mean
//  spin) of the real particles, with the whole cloud's per class beside
//  them; and the cell's parcels for drawing a partner's diameter.
class ParticleCellStatistics
{
public:

    //- Moments of one size class (weights: real particles)
    struct Moments
    {
        double weight = 0;
        Vec3 sum = Vec3::Zero();
        Vec3 sumSquares = Vec3::Zero();
        Vec3 spinSum = Vec3::Zero();
        double parcels = 0;

        void add(double w, const Vec3& u, const Vec3& spin)
        {
            weight += w;
            sum += w*u;
            sumSquares += w*u.cwiseProduct(u);
            spinSum += w*spin;
            parcels += 1;
        }
    };

    //- What a partner is drawn from: the mean and rms velocity and the mean
    //  spin of one class, and whether they are the cloud's (pooled)
    struct ClassState
    {
        Vec3 mean = Vec3::Zero();
        Vec3 rms = Vec3::Zero();
        Vec3 meanSpin = Vec3::Zero();
        bool pooled = false;
    };

    //- Size classes by their inner bounds (ascending diameters; empty: one
    //  class); a class needs minCellParcels parcels in a cell to use the
    //  cell's own mean and rms
    ParticleCellStatistics(std::vector<double> classBounds, int minCellParcels)
    :
        bounds_(std::move(classBounds)),
        minCellParcels_(minCellParcels)
    {
        if (!std::is_sorted(bounds_.begin(), bounds_.end()))
        {
            throw std::invalid_argument("size class bounds not ascending");
        }
    }

    int nClasses() const { return int(bounds_.size()) + 1; }

    //- The size class of diameter d
    int sizeClass(double d) const
    {
        return int(std::upper_bound(bounds_.begin(), bounds_.end(), d)
                   - bounds_.begin());
    }

    //- Start a step on a mesh of nCells cells
    void clear(int nCells)
    {
        nCells_ = nCells;
        records_.clear();
        cloud_.assign(nClasses(), Moments());
    }

    //- Add a parcel of nParticle real particles
    void add(int cell, double d, double nParticle, const Vec3& u, const Vec3& spin)
    {
        const int cls = sizeClass(d);
        records_.push_back({cell, cls, d, nParticle, u, spin});
        cloud_[cls].add(nParticle, u, spin);
    }

    //- The cloud's moments per class: the caller sums them over processors
    //  between the adds and finish
    std::vector<Moments>& cloudMoments() { return cloud_; }

    //- Sort the parcels by cell and compute every cell's statistics;
    //  cellVolume(i) gives the volume of cell i
    template<class CellVolume>
    void finish(const CellVolume& cellVolume)
    {
        const int nc = nClasses();
        cellStart_.assign(nCells_ + 1, 0);
        for (const Record& r : records_)
        {
            ++cellStart_[r.cell + 1];
        }
        for (int i = 0; i < nCells_; ++i)
        {
            cellStart_[i + 1] += cellStart_[i];
        }
        sorted_.resize(records_.size());
        std::vector<int> next(cellStart_.begin(), cellStart_.end() - 1);
        for (const Record& r : records_)
        {
            sorted_[next[r.cell]++] = r;
        }

        cloudState_.resize(nc);
        for (int c = 0; c < nc; ++c)
        {
            cloudState_[c] = state(cloud_[c], true);
        }

        cellSlot_.assign(nCells_, -1);
        cellState_.clear();
        numberDensity_.clear();
        occupiedVolume_.clear();
        cumulativeWeight_.resize(sorted_.size());
        std::vector<Moments> moments(nc);
        for (int cell = 0; cell < nCells_; ++cell)
        {
            const int begin = cellStart_[cell], end = cellStart_[cell + 1];
            if (begin == end) continue;

            std::fill(moments.begin(), moments.end(), Moments());
            double weight = 0;
            for (int i = begin; i < end; ++i)
            {
                const Record& r = sorted_[i];
                moments[r.cls].add(r.weight, r.u, r.spin);
                weight += r.weight;
                cumulativeWeight_[i] = weight;
            }
            cellSlot_[cell] = int(numberDensity_.size());
            numberDensity_.push_back(weight/cellVolume(cell));
            occupiedVolume_.push_back(cellVolume(cell));
            for (int c = 0; c < nc; ++c)
            {
                cellState_.push_back
                (
                    moments[c].parcels >= minCellParcels_
                  ? state(moments[c], false)
                  : cloudState_[c]
                );
            }
        }
    }

    //- Number density of real particles in a cell (0 if it has no parcel)
    double numberDensity(int cell) const
    {
        const int slot = cellSlot_[cell];
        return slot < 0 ? 0 : numberDensity_[slot];
    }

    //- Number density, in an occupied cell, of the real particles of the
    //  parcels other than one of ownWeight real particles in it
    double othersNumberDensity(int cell, double ownWeight) const
    {
        const int slot = cellSlot_[cell];
        return std::max
        (
            0.0,
            numberDensity_[slot] - ownWeight/occupiedVolume_[slot]
        );
    }

    //- The statistics of class cls in an occupied cell
    const ClassState& classState(int cell, int cls) const
    {
        return cellState_[cellSlot_[cell]*nClasses() + cls];
    }

    //- A partner's diameter drawn from an occupied cell's real particles;
    //  its class through sizeClass
    template<class Uniform01>
    double drawPartnerDiameter(int cell, Uniform01& uniform01) const
    {
        const int begin = cellStart_[cell], end = cellStart_[cell + 1];
        const double target = uniform01()*cumulativeWeight_[end - 1];
        const auto first = cumulativeWeight_.begin() + begin;
        const auto last = cumulativeWeight_.begin() + end;
        const auto it = std::upper_bound(first, last, target);
        return sorted_[std::min(int(it - cumulativeWeight_.begin()), end - 1)].d;
    }

private:

    struct Record
    {
        int cell = 0;
        int cls = 0;
        double d = 0;
        double weight = 0;
        Vec3 u = Vec3::Zero();
        Vec3 spin = Vec3::Zero();
    };

    static ClassState state(const Moments& m, bool pooled)
    {
        ClassState s;
        s.pooled = pooled;
        if (m.weight > 0)
        {
            s.mean = m.sum/m.weight;
            s.meanSpin = m.spinSum/m.weight;
            const Vec3 variance =
                m.sumSquares/m.weight - s.mean.cwiseProduct(s.mean);
            s.rms = variance.cwiseMax(0.0).cwiseSqrt();
        }
        return s;
    }

    std::vector<double> bounds_;
    int minCellParcels_;
    int nCells_ = 0;
    std::vector<Record> records_;
    std::vector<Record> sorted_;
    std::vector<int> cellStart_;
    std::vector<int> cellSlot_;
    std::vector<double> numberDensity_;
    std::vector<double> occupiedVolume_;
    std::vector<double> cumulativeWeight_;
    std::vector<ClassState> cellState_;
    std::vector<ClassState> cloudState_;
    std::vector<Moments> cloud_;
};


//- Settings of the fictitious-partner model
struct FictitiousPartnerSettings
{
    PairMaterial material;
    double maxProbability = 0.1;   //!< above it a step is split
};

//- What one particle's step did
struct PartnerCollisionOutcome
{
    int collisions = 0;           //!< collisions with fictitious partners
    int draws = 0;                //!< partners drawn
    int pooledDraws = 0;          //!< of which from the cloud's statistics
    int subSteps = 1;             //!< sub-steps of the step (> 1: split)
    double largestProbability = 0;   //!< the step's P for a typical partner,
                                     //!< before any split
};

//- One particle's step of the fictitious-partner model: the particle
//  (u, w, diameter d, of a parcel of ownWeight real particles in an
//  occupied cell of the statistics) may collide
//  with partners drawn from its cell; R is the correlation of its
//  fluctuation with the partner's (0 for none)
template<bool withSpin, class Uniform01>
PartnerCollisionOutcome collideWithFictitiousPartners
(
    Vec3& u,
    Vec3& w,
    double d,
    double ownWeight,
    int cell,
    double dt,
    double R,
    const ParticleCellStatistics& statistics,
    const FictitiousPartnerSettings& settings,
    Uniform01& uniform01
)
{
    PartnerCollisionOutcome outcome;
    const double n = statistics.othersNumberDensity(cell, ownWeight);
    const int ownClass = statistics.sizeClass(d);
    const auto& own = statistics.classState(cell, ownClass);
    const double uncorrelated = std::sqrt(std::max(0.0, 1 - R*R));

    // The step's probability for a typical partner (one of the particle's
    // own size, at the particle's fluctuation plus its class's rms speed)
    // decides the split before any partner is drawn: a split decided on
    // the first partner's own P would under-weight fast partners (at a
    // mean P of 0.05 that loses 2 % of the collisions and 5 % of the
    // energy of an elastic gas in 100 steps)
    const Vec3 fluctuation = u - own.mean;
    outcome.largestProbability = collisionProbability
    (
        d, d, fluctuation.norm() + own.rms.norm(), n, dt
    );
    if (outcome.largestProbability > settings.maxProbability)
    {
        // (bounded: a P of 1e3 means a dense bed, not a dilute gas)
        outcome.subSteps = int(std::min
        (
            std::ceil(outcome.largestProbability/settings.maxProbability),
            1e4
        ));
    }
    const double dtSub = dt/outcome.subSteps;

    for (int sub = 0; sub < outcome.subSteps; ++sub)
    {
        const double d2 = statistics.drawPartnerDiameter(cell, uniform01);
        const auto& partner =
            statistics.classState(cell, statistics.sizeClass(d2));

        // (the fluctuation of the particle as it is now: sub-steps after a
        // collision see its new velocity)
        const Vec3 fluctuationNow = u - own.mean;
        Vec3 u2 = partner.mean;
        for (int k = 0; k < 3; ++k)
        {
            const double xi = standardNormal(uniform01);
            u2[k] +=
                own.rms[k] > 0
              ? R*partner.rms[k]/own.rms[k]*fluctuationNow[k]
              + partner.rms[k]*uncorrelated*xi
              : partner.rms[k]*xi;
        }
        ++outcome.draws;
        outcome.pooledDraws += partner.pooled;

        const Vec3 g = u - u2;
        const double speed = g.norm();
        const double P = collisionProbability(d, d2, speed, n, dtSub);
        if (speed > 0 && uniform01() < P)
        {
            const Vec3 normal = partnerContactNormal(g, uniform01);
            const double d23 = d2*d2*d2;
            const double massRatio = d23/(d*d*d + d23);
            collideWithPartner<withSpin>
            (
                u, w, 0.5*d, u2, partner.meanSpin, 0.5*d2, massRatio,
                normal, settings.material
            );
            ++outcome.collisions;
        }
    }
    return outcome;
}

} // namespace roughWall
