// roughWallCore: framework-free physics of Derevich's rough-wall collision model.
// Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
//
// Restitution and friction that depend on the impact on the facet.
//
// The facet collision (facetCollision.hpp) takes its coefficients through a
// policy type, Coefficients:
//  - FacetMaterial: constants (the paper's model). The collision is the same
//    code as without policies: no cost for constant coefficients.
//  - any other type with
//        FacetMaterial operator()(const FacetImpact&) const
//    which returns e, mu0, muD for one facet impact. ImpactFunctions below is
//    the one the adapter and roughWallStats use: three functions of a scalar,
//    each of the facet impact angle, e optionally of the normal speed.
//
// The facet impact angle beta is the angle between the incident velocity
// relative to the wall v and the facet plane:
//     beta = atan2(-v.n, |v - (v.n) n|)   in (0, 90] deg,
// in 2-D alpha + gamma. It is the angle that the no-slip/sliding decision of a
// particle without spin sees: the slip |v_t| = |v_n|/tan(beta) is compared
// with (7/2) mu0 (1 + e) |v_n|. The normal impact speed is -v.n > 0.
//
// Bounds: e in [0, 1], mu0 >= 0, muD >= 0, muD <= mu0 at every argument.
// A table can be checked once at start-up (checkTableBounds); any other
// function is checked per call, and a value out of bounds throws
// CoefficientOutOfRange naming the coefficient, the argument and both values
// (never a clamp: the input is wrong, the user must see it).
#pragma once

#include "facetCollision.hpp"
#include "limitsAndUnits.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace roughWall
{

//- Which impact quantity a coefficient is a function of
enum class ImpactArgument { angle, normalSpeed };

inline const char* name(ImpactArgument a)
{
    return a == ImpactArgument::angle ? "angle" : "normalSpeed";
}

inline double argumentOf(const FacetImpact& impact, ImpactArgument a)
{
    return a == ImpactArgument::angle ? impact.angleDeg : impact.normalSpeed;
}

//- A coefficient out of its bounds at one argument
class CoefficientOutOfRange : public std::domain_error
{
public:

    CoefficientOutOfRange
    (
        const std::string& coefficient,
        ImpactArgument argument,
        double argumentValue,
        double value,
        const std::string& bound
    )
    :
        std::domain_error(message(coefficient, argument, argumentValue, value, bound)),
        coefficient_(coefficient),
        argument_(argument),
        argumentValue_(argumentValue),
        value_(value)
    {}

    const std::string& coefficient() const { return coefficient_; }
    ImpactArgument argument() const { return argument_; }
    double argumentValue() const { return argumentValue_; }
    double value() const { return value_; }

private:

    static std::string message
    (
        const std::string& coefficient,
        ImpactArgument argument,
        double argumentValue,
        double value,
        const std::string& bound
    )
    {
        std::ostringstream os;
        os.precision(10);
        os  << coefficient << " = " << value << " at " << name(argument)
            << " = " << argumentValue
            << (argument == ImpactArgument::angle ? " deg" : " m/s")
            << ": outside " << bound;
        return os.str();
    }

    std::string coefficient_;
    ImpactArgument argument_;
    double argumentValue_;
    double value_;
};

//- Throw CoefficientOutOfRange unless e in [0, 1], mu0 >= 0, 0 <= muD <= mu0.
//  eArgument is e's argument; the friction coefficients are of the angle.
//  NaN is out of every bound.
inline void checkBounds
(
    const FacetMaterial& m,
    const FacetImpact& impact,
    ImpactArgument eArgument = ImpactArgument::angle
)
{
    if (!(m.e >= 0 && m.e <= 1))
    {
        throw CoefficientOutOfRange
        (
            "e", eArgument, argumentOf(impact, eArgument), m.e, "[0, 1]"
        );
    }
    if (!(m.mu0 >= 0))
    {
        throw CoefficientOutOfRange
        (
            "mu0", ImpactArgument::angle, impact.angleDeg, m.mu0, "[0, inf)"
        );
    }
    if (!(m.muD >= 0 && m.muD <= m.mu0))
    {
        std::ostringstream bound;
        bound.precision(10);
        bound << "[0, mu0] (mu0 = " << m.mu0 << ")";
        throw CoefficientOutOfRange
        (
            "muD", ImpactArgument::angle, impact.angleDeg, m.muD, bound.str()
        );
    }
}

//- e, mu0, muD as functions of the facet impact: each a callable
//  double(double) (a constant is a function too). e's argument is the angle
//  or the normal speed; mu0 and muD are of the angle. checked: evaluate
//  checkBounds at every call (false only when the bounds were proven at
//  start-up, e.g. by checkTableBounds).
template<class EFunction, class Mu0Function, class MuDFunction>
struct ImpactFunctions
{
    EFunction e;
    Mu0Function mu0;
    MuDFunction muD;
    ImpactArgument eArgument = ImpactArgument::angle;
    bool checked = true;

    FacetMaterial operator()(const FacetImpact& impact) const
    {
        const FacetMaterial m
        {
            e(argumentOf(impact, eArgument)),
            mu0(impact.angleDeg),
            muD(impact.angleDeg)
        };
        if (checked)
        {
            checkBounds(m, impact, eArgument);
        }
        return m;
    }
};

template<class EFunction, class Mu0Function, class MuDFunction>
ImpactFunctions<EFunction, Mu0Function, MuDFunction> impactFunctions
(
    EFunction e,
    Mu0Function mu0,
    MuDFunction muD,
    ImpactArgument eArgument = ImpactArgument::angle,
    bool checked = true
)
{
    return {std::move(e), std::move(mu0), std::move(muD), eArgument, checked};
}

//- A piecewise-linear table (x ascending, y), constant beyond its ends:
//  OpenFOAM's Function1 table with its default outOfBounds clamp and linear
//  interpolation, for roughWallStats and the tests
struct LinearTable
{
    std::vector<std::pair<double, double>> points;

    double operator()(double x) const
    {
        if (x <= points.front().first) return points.front().second;
        if (x >= points.back().first) return points.back().second;
        const auto hi = std::upper_bound
        (
            points.begin(), points.end(), x,
            [](double a, const std::pair<double, double>& p) { return a < p.first; }
        );
        const auto lo = hi - 1;
        const double w = (x - lo->first)/(hi->first - lo->first);
        return lo->second + w*(hi->second - lo->second);
    }
};

//- Check e, mu0 and muD tables once for every argument: between the nodes of
//  a piecewise-linear table (and beyond its ends, where it is constant) a
//  linear bound holds if it holds at the nodes, and muD - mu0 is linear
//  between the union of both tables' nodes. valueAt(name, x) evaluates the
//  named table ("e", "mu0", "muD") at x; the nodes are given per table.
//  Throws CoefficientOutOfRange at the first node out of bounds.
template<class ValueAt>
void checkTableBounds
(
    const std::vector<double>& eNodes,
    const std::vector<double>& mu0Nodes,
    const std::vector<double>& muDNodes,
    ImpactArgument eArgument,
    const ValueAt& valueAt
)
{
    for (const double x : eNodes)
    {
        const double e = valueAt("e", x);
        if (!(e >= 0 && e <= 1))
        {
            throw CoefficientOutOfRange("e", eArgument, x, e, "[0, 1]");
        }
    }
    std::vector<double> frictionNodes = mu0Nodes;
    frictionNodes.insert(frictionNodes.end(), muDNodes.begin(), muDNodes.end());
    for (const double x : frictionNodes)
    {
        FacetImpact impact;
        impact.angleDeg = x;
        checkBounds({0.5, valueAt("mu0", x), valueAt("muD", x)}, impact);
    }
}

} // namespace roughWall
