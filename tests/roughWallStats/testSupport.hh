// Shared helpers of the roughWallStats tests.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "model.hh"

#include <cmath>

namespace roughWallStatsTest
{

constexpr double deg = 3.14159265358979323846/180;

//- A model in the tool's units: angles in degrees
inline roughWallStats::Model model
(
    double DeltaDeg,
    double AOmega = 0,
    double e = 0.8,
    double mu0 = 0.4,
    double muD = 0.4
)
{
    roughWallStats::Model m;
    m.Delta = DeltaDeg*deg;
    m.AOmega = AOmega;
    m.material = {e, mu0, muD};
    return m;
}

inline double relativeError(double value, double reference)
{
    return std::abs(value - reference)/std::abs(reference);
}

//- The oracle of one facet collision, written here from the model notes, section 4 (the
//  vector form of Derevich's (2.1)-(2.4) as corrected), in the 2-D wall frame
//  x = t, y = N, z = t x N, with V'_x = 1 (V'_y = -tan alpha) and r = 1 (so
//  Omega'_z = A_Omega): nothing from src/. Facet normal n = (-sin g, cos g).
//    c = v - r (w x n),  u_t = c - (c.n) n,  j_n = -(1 + e) v.n
//    no-slip if |u_t| <= (7/2) mu0 (1 + e) |v.n|:  j_t = -(2/7) u_t
//    else j_t = -muD j_n u_t/|u_t|
//    v'' = v + j_n n + j_t,  w'' = w - (5/(2 r)) (n x j_t)
//  and eq. (2.5): k_t = V''_x/V'_x, k_n = -V''_y/V'_y, k_Omega = r Omega''_z/V'_x.
//  Valid for muD <= mu0, where the sliding impulse needs no cap.
struct FacetRebound
{
    double kn, kt, kOmega;
    bool noSlip;
};

inline FacetRebound facetRebound(double g, double alpha, double AOmega, const roughWall::FacetMaterial& m)
{
    const double z = std::tan(alpha);
    const double nx = -std::sin(g), ny = std::cos(g);
    const double vx = 1, vy = -z, w = AOmega;   // w along z, r = 1
    // w x n for w = (0, 0, w): (-w ny, w nx)
    const double cx = vx + w*ny, cy = vy - w*nx;
    const double cn = cx*nx + cy*ny;
    const double ux = cx - cn*nx, uy = cy - cn*ny;
    const double slip = std::hypot(ux, uy);
    const double vn = vx*nx + vy*ny;
    const double jn = -(1 + m.e)*vn;
    FacetRebound r;
    double jx, jy;
    r.noSlip = slip <= 3.5*m.mu0*(1 + m.e)*std::abs(vn);
    if (r.noSlip)
    {
        jx = -2.0/7.0*ux;
        jy = -2.0/7.0*uy;
    }
    else
    {
        jx = -m.muD*jn*ux/slip;
        jy = -m.muD*jn*uy/slip;
    }
    const double vx2 = vx + jn*nx + jx, vy2 = vy + jn*ny + jy;
    // (n x j)_z = nx jy - ny jx
    const double w2 = w - 2.5*(nx*jy - ny*jx);
    r.kt = vx2/vx;
    r.kn = -vy2/vy;
    r.kOmega = w2/vx;
    return r;
}

} // namespace roughWallStatsTest
