"""oracle.facetCollision: invariants of the oracle's hard-sphere facet
collision (model notes section 4) and its reduction to the corrected closed
forms (2.6)/(2.7) (docs/theory.md section 6).

Checks on 10^6 random 3-D inputs (random facet normal, velocity, spin,
radius 1e-3..1, e in [0, 1], mu0 in [0, 1], muD in [0, mu0]; fixed seed),
with round-off tolerances relative to the input scale:
 - kinetic energy v^2/2 + r^2 w^2/5 never increases (relative 1e-12);
 - v''.n = -e v.n (1e-12 |v|);
 - angular momentum about the contact point (2/5) r^2 w + r n x v is
   conserved (1e-12 (r|v| + r^2|w|));
 - a no-slip collision ends in exact rolling: contact slip after
   <= 1e-12 (|v| + r|w|);
 - |j_t| <= mu0 j_n (no-slip) and |j_t| <= muD j_n (sliding), 1e-12;
 - sliding never reverses the slip;
 - the same with muD in (mu0, 3 mu0] (the cap must keep energy and slip);
 - without spin the velocity equals the one with w = 0 exactly;
 - 2-D in-plane spin: k_n, k_t, k_Omega equal the closed forms (2.6)/(2.7)
   (100 000 cases, both regimes, relative 1e-11), regimes agree;
 - negative controls: the same invariant checks must flag a collision with
   2/5 instead of 2/7 (no rolling), with the sign of the spin update
   flipped (angular momentum), and without the cap for muD = 3 mu0
   (slip reversal / energy).
"""

import sys
sys.dont_write_bytecode = True   # keep the source tree clean

import math

import numpy as np

from foamcase.checking import Checker
from foamcase import roughWallOracle as rwo

TOL = 1e-12


def dot(a, b):
    return np.einsum("ij,ij->i", a, b)


def norm(a):
    return np.sqrt(dot(a, a))


def random_inputs(rng, n, muD_above=False):
    nvec = rng.normal(size=(n, 3))
    nvec /= norm(nvec)[:, None]
    v = rng.normal(size=(n, 3))*np.exp(rng.uniform(-3, 3, n))[:, None]
    vn = dot(v, nvec)
    v -= (np.where(vn > 0, 2*vn, 0.0) + 1e-3*norm(v))[:, None]*nvec
    d = 2*np.exp(rng.uniform(math.log(1e-3), 0, n))
    # spins up to a few times |v|/r
    w = rng.normal(size=(n, 3))*(norm(v)/(0.5*d))[:, None] \
        * rng.uniform(0, 3, n)[:, None]
    e = rng.uniform(0, 1, n)
    e[: n//20] = 0.0
    e[n//20: n//10] = 1.0
    mu0 = rng.uniform(0, 1, n)
    mu0[: n//50] = 0.0
    mu0[n//20: n//20 + n//50] = 0.0    # e = 1, frictionless: energy kept
    if muD_above:
        muD = mu0*rng.uniform(1, 3, n)
    else:
        muD = mu0*rng.uniform(0, 1, n)
        muD[n//10: n//5] = mu0[n//10: n//5]
    return v, w, nvec, d, e, mu0, muD


def violations(v, w, n, d, e, mu0, muD, res):
    """Largest violation of each invariant (<= 0 or <= TOL means fine)."""
    r = 0.5*d
    scale_v = norm(v)
    scale_w = norm(w)
    E1 = 0.5*dot(v, v) + 0.2*r*r*dot(w, w)
    E2 = 0.5*dot(res.v, res.v) + 0.2*r*r*dot(res.omega, res.omega)
    out = {}
    out["energy"] = float(np.max((E2 - E1)/E1))
    out["restitution"] = float(np.max(np.abs(dot(res.v, n) + e*dot(v, n))
                                      / scale_v))
    L1 = 0.4*(r*r)[:, None]*w + r[:, None]*np.cross(n, v)
    L2 = 0.4*(r*r)[:, None]*res.omega + r[:, None]*np.cross(n, res.v)
    out["angular momentum"] = float(np.max(norm(L2 - L1)
                                           / (r*scale_v + r*r*scale_w)))
    c2 = res.v - r[:, None]*np.cross(res.omega, n)
    u2 = c2 - dot(c2, n)[:, None]*n
    c1 = v - r[:, None]*np.cross(w, n)
    u1 = c1 - dot(c1, n)[:, None]*n
    ns = res.no_slip
    out["rolling"] = float(np.max(norm(u2[ns])/(scale_v[ns] + r[ns]*scale_w[ns]),
                                  initial=0.0))
    jt = norm(res.jt)
    lim = np.where(ns, mu0, muD)*res.jn
    out["friction"] = float(np.max((jt - lim)/(res.jn*np.maximum(mu0, muD)
                                               + 1e-300)))
    sl = ~ns
    out["slip reversal"] = float(np.max(-dot(u2[sl], u1[sl])
                                        / (norm(u1[sl])**2), initial=0.0))
    return out


def check_invariants(c, label, v, w, n, d, e, mu0, muD, res):
    viol = violations(v, w, n, d, e, mu0, muD, res)
    for key, val in viol.items():
        c.check(f"{label}: {key}", val <= TOL, f"largest violation {val:.3g}")
    return viol


# ---- deliberately broken collisions for the negative controls ------------

def broken_collision(v, w, n, d, e, mu0, muD, kind):
    r = (0.5*d)[:, None]
    vn = dot(v, n)
    jn = -(1 + e)*vn
    c = v - r*np.cross(w, n)
    u = c - dot(c, n)[:, None]*n
    s = norm(u)
    ns = s <= 3.5*mu0*jn
    k_noslip = 0.4 if kind == "2/5" else 2/7
    if kind == "no cap":
        slide = muD*jn/np.where(s > 0, s, 1)
    else:
        slide = np.minimum(muD*jn, 2/7*s)/np.where(s > 0, s, 1)
    jt = -np.where(ns, k_noslip, slide)[:, None]*u
    v2 = v + jn[:, None]*n + jt
    sign = -1.0 if kind == "spin sign" else 1.0
    w2 = w - sign*(2.5/r)*np.cross(n, jt)
    return rwo.FacetResult(v2, w2, ns, jn, jt)


def closed_forms(gamma, alpha, A, e, mu0, muD):
    """docs/theory.md section 6 (corrected (2.6)/(2.7))."""
    z = np.tan(alpha)
    cg, sg = np.cos(gamma), np.sin(gamma)
    slip = cg - z*sg + A
    approach = z*cg + sg
    noslip = np.abs(slip) <= 3.5*mu0*(1 + e)*np.abs(approach)
    kt_ns = (5/7*(cg - z*sg) - 2/7*A)*cg - e*approach*sg
    kn_ns = e*(cg + sg/z)*cg + (5/7*(cg/z - sg) - 2/7*A/z)*sg
    ko_ns = -5/7*(cg - z*sg) + 2/7*A
    eps0 = np.where(slip > 0, 1.0, -1.0)
    f = muD*(1 + e)*eps0
    kt_sl = ((cg - z*sg) - f*(sg + z*cg))*cg - e*approach*sg
    kn_sl = e*(sg/z + cg)*cg + ((cg/z - sg) - f*(sg/z + cg))*sg
    ko_sl = A - 2.5*f*(sg + z*cg)
    return (np.where(noslip, kn_ns, kn_sl), np.where(noslip, kt_ns, kt_sl),
            np.where(noslip, ko_ns, ko_sl), noslip,
            np.abs(np.abs(slip) - 3.5*mu0*(1 + e)*np.abs(approach)))


def main():
    c = Checker("oracle.facetCollision: invariants and closed forms")
    rng = np.random.default_rng(2024)

    N = 1_000_000
    v, w, n, d, e, mu0, muD = random_inputs(rng, N)
    res = rwo.facet_collision(v, w, n, d, e, mu0, muD)
    c.check("both regimes present", 0.05 < res.no_slip.mean() < 0.95,
            f"no-slip fraction {res.no_slip.mean():.3f}")
    check_invariants(c, "muD <= mu0", v, w, n, d, e, mu0, muD, res)

    # without spin: the same velocity as with w = 0
    r0 = rwo.facet_collision(v, np.zeros_like(w), n, d, e, mu0, muD)
    r1 = rwo.facet_collision(v, None, n, d, e, mu0, muD)
    c.check("no spin = zero spin", bool(np.array_equal(r0.v, r1.v))
            and r1.omega is None, "velocities identical, omega None")
    check_invariants(c, "zero incident spin", v, np.zeros_like(w), n, d, e,
                     mu0, muD, r0)

    # the cap for muD > mu0
    v, w, n, d, e, mu0, muD = random_inputs(rng, 200_000, muD_above=True)
    res = rwo.facet_collision(v, w, n, d, e, mu0, muD)
    viol = violations(v, w, n, d, e, mu0, muD, res)
    for key in ["energy", "rolling", "slip reversal", "angular momentum"]:
        c.check(f"muD > mu0 (capped): {key}", viol[key] <= TOL,
                f"largest violation {viol[key]:.3g}")

    # negative controls
    v, w, n, d, e, mu0, muD = random_inputs(rng, 200_000)
    bad = violations(v, w, n, d, e, mu0, muD,
                     broken_collision(v, w, n, d, e, mu0, muD, "2/5"))
    c.check("control: 2/5 instead of 2/7 is caught", bad["rolling"] > 1e-3,
            f"rolling violation {bad['rolling']:.3g}")
    bad = violations(v, w, n, d, e, mu0, muD,
                     broken_collision(v, w, n, d, e, mu0, muD, "spin sign"))
    c.check("control: flipped spin update is caught",
            bad["angular momentum"] > 1e-3 and bad["rolling"] > 1e-3,
            f"angular momentum violation {bad['angular momentum']:.3g}")
    v, w, n, d, e, mu0, muD = random_inputs(rng, 200_000, muD_above=True)
    bad = violations(v, w, n, d, e, mu0, muD,
                     broken_collision(v, w, n, d, e, mu0, muD, "no cap"))
    c.check("control: uncapped muD > mu0 is caught",
            bad["slip reversal"] > 1e-3 and bad["energy"] > 1e-6,
            f"slip reversal {bad['slip reversal']:.3g}, energy {bad['energy']:.3g}")

    # closed forms (2.6)/(2.7), 2-D with in-plane spin
    M = 100_000
    alpha = rng.uniform(0.01, 0.5*math.pi - 0.01, M)
    gamma = rng.uniform(-1, 1, M)*np.minimum(alpha, 1.2) + 0.3*rng.uniform(0, 1, M)
    gamma = np.maximum(gamma, -alpha + 0.01)
    A = rng.uniform(-3, 3, M)
    e = rng.uniform(0, 1, M)
    mu0 = rng.uniform(0, 0.8, M)
    muD = mu0*rng.uniform(0.5, 1, M)
    r = 0.5
    vin = np.stack([np.cos(alpha), -np.sin(alpha), np.zeros(M)], axis=1)
    win = np.zeros((M, 3))
    win[:, 2] = A*np.cos(alpha)/r          # z = t x N = x x y
    nf = np.stack([-np.sin(gamma), np.cos(gamma), np.zeros(M)], axis=1)
    out = rwo.facet_collision(vin, win, nf, 2*r, e, mu0, muD)
    kn = out.v[:, 1]/np.sin(alpha)
    kt = out.v[:, 0]/np.cos(alpha)
    ko = r*out.omega[:, 2]/np.cos(alpha)
    kn_c, kt_c, ko_c, ns_c, margin = closed_forms(gamma, alpha, A, e, mu0, muD)
    clear = margin > 1e-9
    c.check("closed forms: both regimes tested",
            0.1 < ns_c[clear].mean() < 0.9, f"no-slip {ns_c[clear].mean():.3f}")
    c.check("closed forms: same regime",
            bool(np.all(out.no_slip[clear] == ns_c[clear])),
            f"{np.sum(out.no_slip[clear] != ns_c[clear])} differ of {clear.sum()}")
    for name, a, b in [("k_n", kn, kn_c), ("k_t", kt, kt_c), ("k_Omega", ko, ko_c)]:
        rel = np.abs(a - b)[clear]/(1 + np.abs(b[clear]))
        c.check(f"closed forms: {name}", float(rel.max()) <= 1e-11,
                f"largest relative difference {rel.max():.3g}")
    c.check("2-D stays in plane", bool(np.all(out.v[:, 2] == 0)
                                       and np.all(out.omega[:, :2] == 0)), "")

    c.finish()


if __name__ == "__main__":
    main()
