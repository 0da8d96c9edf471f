"""oracle.operator: the oracle's rough-wall operator (one wall hit) on its
own: conventions of docs/theory.md section 5 and the known values.

Checks (fixed seeds):
 - every hit leaves the wall (v.N >= 0 exactly) for random 3-D walls,
   velocities and spins, Delta 8/30/45 deg, e 0/0.5/1, lateral on/off,
   max_facet 0/1/3/10; energy never grows (relative 1e-12); 1 <= n_facet
   <= max_facet; the fallback only at the bound; first gamma < pi/2;
 - a particle not moving into the wall is returned unchanged;
 - Delta = 0 is the smooth-wall hard-sphere rebound (k_n = e; k_t = 5/7 or
   1 - mu(1+e) tan alpha) to 1e-14;
 - 2-D (plane normal z, and a plane normal tilted in x-z): no out-of-plane
   velocity, no in-plane spin (1e-15), the lateral flag is ignored;
 - single-collision mean k_n at alpha 12, Delta 8, e 0.8, mu 0.4 within
   4 se of the known 0.9741 (10^6 samples);
 - mean first gamma within 4 se of (1.4);
 - lateral-tilt convention at alpha 45, Delta 8: mean k_n 0.772 in-plane and
   0.765 with the lateral tilt (within 0.002, the model notes' values) and the
   shift in-plane - lateral larger than 4 se;
 - at normal incidence the tangential rebound has zero mean (4 se).
"""

import sys
sys.dont_write_bytecode = True   # keep the source tree clean

import math

import numpy as np

from foamcase.checking import Checker
from foamcase import roughWallOracle as rwo


def dot(a, b):
    return np.einsum("ij,ij->i", a, b)


def main():
    c = Checker("oracle.operator: the rough-wall operator")
    rad = math.radians
    rng = np.random.default_rng(77)

    # leaving the wall, energy, counts
    M = 40_000
    worst_vn, worst_E = 0.0, -1.0
    bad_count = 0
    for Dd in [8, 30, 45]:
        for e in [0.0, 0.5, 1.0]:
            for lateral in [False, True]:
                for mf in [0, 1, 3, 10]:
                    Nw = rng.normal(size=(M, 3))
                    Nw /= np.sqrt(dot(Nw, Nw))[:, None]
                    v = rng.normal(size=(M, 3))
                    vn = dot(v, Nw)
                    v -= np.where(vn > 0, 2*vn, 0)[:, None]*Nw
                    # a tenth at grazing incidence (v.N 1e-6 of what it was)
                    g = slice(0, M//10)
                    v[g] -= ((1 - 1e-6)*dot(v[g], Nw[g]))[:, None]*Nw[g]
                    d = 0.1
                    w = rng.normal(size=(M, 3))*10
                    res = rwo.rebound(v, w, Nw, d, e, 0.4, 0.3, rad(Dd),
                                      lateral=lateral, max_facet=mf, rng=rng)
                    vout_n = dot(res.v, Nw)
                    worst_vn = min(worst_vn, float(vout_n.min()))
                    r = 0.5*d
                    E1 = 0.5*dot(v, v) + 0.2*r*r*dot(w, w)
                    E2 = 0.5*dot(res.v, res.v) + 0.2*r*r*dot(res.omega, res.omega)
                    worst_E = max(worst_E, float(np.max((E2 - E1)/E1)))
                    hit = dot(v, Nw) < 0
                    ok = np.all(res.n_facet[hit] <= mf) \
                        and np.all(res.n_facet[hit] >= min(mf, 1)) \
                        and np.all(res.fallback <= (res.n_facet == mf)) \
                        and np.all(res.first_gamma[res.n_facet > 0] < rwo.HALF_PI)
                    bad_count += 0 if ok else 1
    c.check("always leaves the wall", worst_vn >= 0.0,
            f"smallest v.N after = {worst_vn:.3g}")
    c.check("energy never grows", worst_E <= 1e-12,
            f"largest relative change {worst_E:.3g}")
    c.check("facet counts, fallback, gamma < pi/2", bad_count == 0,
            f"{bad_count} of 72 configurations inconsistent")

    # not moving into the wall
    v = np.array([[1.0, 0.2, 0.0], [0.3, 0.0, 0.1]])
    res = rwo.rebound(v, None, (0, 1, 0), 1, 0.8, 0.4, 0.4, rad(8), rng=rng)
    c.check("away from the wall: unchanged",
            bool(np.array_equal(res.v, v) and np.all(res.n_facet == 0)), "")

    # smooth wall
    a = np.radians(np.linspace(1, 90, 90))
    v = np.stack([np.cos(a), -np.sin(a), 0*a], axis=1)
    e, mu = 0.7, 0.3
    res = rwo.rebound(v, None, (0, 1, 0), 1, e, mu, mu, 0.0, rng=rng)
    kn = res.v[:, 1]/np.sin(a)
    kt = res.v[:, 0]/np.maximum(np.cos(a), 1e-300)
    noslip = np.cos(a) <= 3.5*mu*(1 + e)*np.sin(a)
    kt_hs = np.where(noslip, 5/7, 1 - mu*(1 + e)*np.tan(a))
    err = max(float(np.max(np.abs(kn - e))),
              float(np.max(np.abs(kt - kt_hs)[:-1])))
    c.check("Delta = 0: hard-sphere rebound", err <= 1e-14
            and np.all(res.n_facet == 1), f"largest error {err:.3g}")

    # 2-D
    for label, P in [("z", np.array([0, 0, 1.0])),
                     ("tilted", np.array([math.sin(0.3), 0, math.cos(0.3)]))]:
        M = 50_000
        inplane = np.cross(P, [0, 1.0, 0])
        inplane /= np.linalg.norm(inplane)
        a = rng.uniform(0, 0.5*math.pi, M)
        s = np.where(rng.random(M) < 0.5, 1.0, -1.0)
        v = (s*np.cos(a))[:, None]*inplane - np.sin(a)[:, None]*np.array([0, 1.0, 0])
        w = rng.normal(size=M)[:, None]*P*20
        r1 = rwo.rebound(v, w, (0, 1, 0), 0.1, 0.8, 0.4, 0.4, rad(20),
                         lateral=True, rng=np.random.default_rng(5),
                         plane_normal=P)
        r2 = rwo.rebound(v, w, (0, 1, 0), 0.1, 0.8, 0.4, 0.4, rad(20),
                         lateral=False, rng=np.random.default_rng(5),
                         plane_normal=P)
        out_v = float(np.max(np.abs(r1.v @ P)))
        out_w = float(np.max(np.linalg.norm(np.cross(r1.omega, P), axis=1)))
        c.check(f"2-D ({label}): stays in the plane", out_v <= 1e-15*4
                and out_w <= 1e-15*20*4,
                f"|v.P| <= {out_v:.2g}, |w x P| <= {out_w:.2g}")
        c.check(f"2-D ({label}): lateral flag ignored",
                bool(np.array_equal(r1.v, r2.v)), "")

    # known value: single collision mean k_n
    row = rwo.restitution_statistics([12], 8, 0.8, 0.4, 0.4, 1_000_000,
                                     np.random.default_rng(12),
                                     recollide=False)[0]
    c.within_se("single-collision mean k_n (12, 8, 0.8, 0.4) = 0.9741",
                row["mean_kn"], 0.9741, row["se_mean_kn"])
    A = rad(12)/(math.sqrt(2)*rad(8))
    g14 = math.degrees(rad(12)*math.erfc(A)/math.erf(A))
    c.within_se("mean first gamma = (1.4)", row["mean_first_gamma_deg"], g14,
                row["se_mean_first_gamma_deg"])

    # lateral tilt convention
    plain = rwo.restitution_statistics([45], 8, 0.8, 0.4, 0.4, 1_000_000,
                                       np.random.default_rng(45))[0]
    lat = rwo.restitution_statistics([45], 8, 0.8, 0.4, 0.4, 1_000_000,
                                     np.random.default_rng(46), lateral=True)[0]
    c.within("in-plane mean k_n (45, 8) = 0.772", plain["mean_kn"], 0.772, 0.002)
    c.within("lateral mean k_n (45, 8) = 0.765", lat["mean_kn"], 0.765, 0.002)
    se = math.hypot(plain["se_mean_kn"], lat["se_mean_kn"])
    c.check("lateral tilt shifts mean k_n",
            plain["mean_kn"] - lat["mean_kn"] > 4*se,
            f"shift {plain['mean_kn'] - lat['mean_kn']:.4f} > 4 se = {4*se:.4f}")

    # normal incidence: isotropic tilt direction
    M = 200_000
    v = np.tile([0, -1.0, 0], (M, 1))
    res = rwo.rebound(v, None, (0, 1, 0), 1, 0.8, 0.4, 0.4, rad(8), rng=rng)
    for k, name in [(0, "x"), (2, "z")]:
        x = res.v[:, k]
        c.within_se(f"normal incidence: mean v_{name} = 0", float(x.mean()), 0.0,
                    float(x.std()/math.sqrt(M)))

    c.finish()


if __name__ == "__main__":
    main()
