"""oracle.core: the oracle's full operator (repeated facet collisions until
the particle leaves, fallback at the bound, spin, lateral tilt) against the
C++ core's own Monte Carlo: two independent implementations.

1. roughWallReference (tests/oracle/roughWallReference.cc: the core's
   collideWithRoughWall, 3-D, v = (cos a, -sin a, 0) on the wall y = 0,
   mt19937_64): mean and sd of k_n and k_t. Cases (spin; lateral; Delta; e,
   mu0, muD; max facet collisions; alpha):
     0/1; 0; 8;  0.8, 0.4, 0.4; 10; 5, 12, 30, 60
     0;   1; 8;  0.8, 0.4, 0.4; 10; 12, 45
     1;   1; 30; 0.8, 0.4, 0.4; 10; 10, 45
     1;   0; 45; 0.9, 0.1, 0.1; 10; 5, 20
     0;   0; 20; 0.0, 0.4, 0.4; 10; 10, 40        (e = 0)
     1;   0; 20; 0.8, 0.4, 0.4;  1; 10, 30        (fallback after 1 facet)
     1;   1; 15; 0.5, 0.3, 0.2; 10; 8, 25         (muD < mu0)
     0/1; 0; 30; 0.8, 0.4, 0.4; 10; 40            (12 % re-collide: the spin
                                                   convention matters)
2. roughWallStats --method montecarlo --recollide (the core's operator with
   spin, 2-D unless --lateral): additionally the mean number of facet
   collisions, the fallback fraction, the no-slip fraction of all facet
   collisions, mean and sd of k_Omega. Cases: Delta 8 alpha 12; Delta 20
   alpha 30 with --max-collisions 2; Delta 45 alpha 20 --lateral.
Each statistic within 4 combined standard errors sqrt(se_oracle^2 +
se_core^2); 500 000 samples per angle on each side, fixed seeds.
Controls: the same comparison must reject the oracle run with e 1 % lower
(0.792 instead of 0.8) at Delta 8, alpha 30, and the oracle carrying the
spin between the facet collisions of one hit (spin=True) against the core
without spin (withSpin = false: every facet collision starts without spin)
at Delta 30, alpha 40.
Fails (not skips) when the tools are not built.
"""

import sys
sys.dont_write_bytecode = True   # keep the source tree clean

import math
import io
import subprocess

import numpy as np

from foamcase.checking import Checker
from foamcase.tables import read_csv
from foamcase.oracleTesting import (tool_arguments, find_tool, STATS_CANDIDATES, REFERENCE_CANDIDATES)
from foamcase import roughWallOracle as rwo

SAMPLES = 500_000

REFERENCE_CASES = [
    # spin, lateral, Delta, e, mu0, muD, max facet, alphas
    (0, 0, 8, 0.8, 0.4, 0.4, 10, [5, 12, 30, 60]),
    (1, 0, 8, 0.8, 0.4, 0.4, 10, [5, 12, 30, 60]),
    (0, 1, 8, 0.8, 0.4, 0.4, 10, [12, 45]),
    (1, 1, 30, 0.8, 0.4, 0.4, 10, [10, 45]),
    (1, 0, 45, 0.9, 0.1, 0.1, 10, [5, 20]),
    (0, 0, 20, 0.0, 0.4, 0.4, 10, [10, 40]),
    (1, 0, 20, 0.8, 0.4, 0.4, 1, [10, 30]),
    (1, 1, 15, 0.5, 0.3, 0.2, 10, [8, 25]),
    (0, 0, 30, 0.8, 0.4, 0.4, 10, [40]),   # spin convention visible here
    (1, 0, 30, 0.8, 0.4, 0.4, 10, [40]),
]

STATS_CASES = [
    # Delta, alpha, max collisions, lateral
    (8, 12, 10, False),
    (20, 30, 2, False),
    (45, 20, 10, True),
]

KEYS = [("mean_kn", "se_mean_kn"), ("sd_kn", "se_sd_kn"),
        ("mean_kt", "se_mean_kt"), ("sd_kt", "se_sd_kt")]


def run_reference(ref, spin, lateral, Delta, e, mu0, muD, mf, alphas, seed):
    cmd = [ref, "--spin", str(spin), "--e", repr(e), "--mu0", repr(mu0),
           "--muD", repr(muD), "--Delta", repr(Delta),
           "--alpha", ",".join(str(a) for a in alphas),
           "--lateralTilt", str(lateral), "--maxFacetCollisions", str(mf),
           "--samples", str(SAMPLES), "--seed", str(seed)]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True)
    return read_csv(io.StringIO(out.stdout), numbers=True)


def run_stats_mc(stats, Delta, alpha, mf, lateral, seed):
    cmd = [stats, "--method", "montecarlo", "--recollide", "--Delta",
           repr(Delta), "--alpha", str(alpha), "--max-collisions", str(mf),
           "--samples", str(SAMPLES), "--seed", str(seed), "--threads", "1",
           "--digits", "15"]
    if lateral:
        cmd.append("--lateral")
    out = subprocess.run(cmd, capture_output=True, text=True, check=True)
    return read_csv(io.StringIO(out.stdout), numbers=True)[0]


def compare(c, tag, o, r, keys):
    for key, se in keys:
        c.within_se(f"{key} {tag}", o[key], r[key], math.hypot(o[se], r[se]))


def main():
    args = tool_arguments(__doc__)
    c = Checker("oracle.core: oracle operator vs the core's Monte Carlo")
    ref = find_tool(args.reference, "roughWallReference", REFERENCE_CANDIDATES)
    stats = find_tool(args.stats, "roughWallStats", STATS_CANDIDATES)
    ok = c.check("roughWallReference is built", ref is not None,
                 str(ref or "not found: build target roughWallReference"))
    ok &= c.check("roughWallStats is built", stats is not None,
                  str(stats or "not found: build target roughWallStats"))
    if not ok:
        c.finish()

    seed = 500
    for spin, lateral, Delta, e, mu0, muD, mf, alphas in REFERENCE_CASES:
        seed += 1
        rows = run_reference(ref, spin, lateral, Delta, e, mu0, muD, mf,
                             alphas, seed)
        for r, alpha in zip(rows, alphas):
            seed += 1
            o = rwo.restitution_statistics(
                [alpha], Delta, e, mu0, muD, SAMPLES,
                np.random.default_rng(seed), spin=bool(spin),
                lateral=bool(lateral), max_facet=mf)[0]
            tag = (f"spin={spin} lateral={lateral} Delta={Delta} e={e} "
                   f"mu0={mu0} muD={muD} max={mf} alpha={alpha}")
            compare(c, tag, o, r, KEYS)

    for Delta, alpha, mf, lateral in STATS_CASES:
        seed += 1
        r = run_stats_mc(stats, Delta, alpha, mf, lateral, seed)
        o = rwo.restitution_statistics(
            [alpha], Delta, 0.8, 0.4, 0.4, SAMPLES, np.random.default_rng(seed),
            spin=True, lateral=lateral, max_facet=mf,
            plane_normal=None if lateral else (0.0, 0.0, 1.0))[0]
        tag = f"roughWallStats --recollide Delta={Delta} alpha={alpha} " \
              f"max={mf} lateral={int(lateral)}"
        compare(c, tag, o, r, KEYS + [("mean_kOmega", "se_mean_kOmega"),
                                      ("sd_kOmega", "se_sd_kOmega")])
        se_nf = float(np.sqrt(max(o["mean_facet_collisions"] - 1, 1/SAMPLES)
                              / SAMPLES))
        c.within_se(f"mean facet collisions {tag}", o["mean_facet_collisions"],
                    r["mean_facet_collisions"],
                    math.hypot(se_nf, r["se_mean_facet_collisions"]))
        for key in ["p_fallback"]:
            p = 0.5*(o[key] + r[key])
            se = math.sqrt(2*max(p*(1 - p), 1/SAMPLES)/SAMPLES)
            c.within_se(f"{key} {tag}", o[key], r[key], se)
        p = r["p_noslip"]
        se = math.sqrt(2*max(p*(1 - p), 1/SAMPLES)/SAMPLES)
        c.within_se(f"p_noslip (all facet collisions) {tag}",
                    o["p_noslip_all"], p, se)
        if mf == 2:
            c.check(f"fallback exercised {tag}", o["p_fallback"] > 1e-3
                    and r["p_fallback"] > 1e-3,
                    f"oracle {o['p_fallback']:.4f}, core {r['p_fallback']:.4f}")

    # control: a 1 % error in e must be seen
    r = run_reference(ref, 0, 0, 8, 0.8, 0.4, 0.4, 10, [30], 999)[0]
    o = rwo.restitution_statistics([30], 8, 0.792, 0.4, 0.4, SAMPLES,
                                   np.random.default_rng(999))[0]
    se = math.hypot(o["se_mean_kn"], r["se_mean_kn"])
    diff = abs(o["mean_kn"] - r["mean_kn"])
    c.check("control: e 1 % low is rejected", diff > 4*se,
            f"|diff| {diff:.4g} = {diff/se:.1f} se > 4 se")
    r = run_reference(ref, 0, 0, 30, 0.8, 0.4, 0.4, 10, [40], 998)[0]
    o = rwo.restitution_statistics([40], 30, 0.8, 0.4, 0.4, SAMPLES,
                                   np.random.default_rng(998), spin=True)[0]
    se = math.hypot(o["se_mean_kn"], r["se_mean_kn"])
    diff = abs(o["mean_kn"] - r["mean_kn"])
    c.check("control: spin carried between facets differs from withSpin=false",
            diff > 4*se, f"|diff| {diff:.4g} = {diff/se:.1f} se > 4 se")
    c.finish()


if __name__ == "__main__":
    main()
