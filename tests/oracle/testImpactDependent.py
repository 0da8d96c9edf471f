"""oracle.impactDependent: restitution and friction as functions of the facet
impact (issue 31) in roughWallStats (which runs the core) against the numpy
oracle's quadrature with the same functions (roughWallOracle.py:
single_facet_quadrature, facet_collision with coefficient functions; nothing
from the C++).

Functions (the shape of glass on steel, not its numbers), of the facet
impact angle b [deg]:
  e(b)   table ((0 0.95) (30 0.8) (60 0.65) (90 0.6))       --e-table
  mu0(b) table ((0 0.5) (20 0.35) (45 0.2) (90 0.15))      --mu0-table
  muD(b) 0.3 - 0.004 b + 0.00002 b^2 (below mu0 everywhere) --mud-polynomial
and e of the normal speed w [m/s] 0.95 - 0.05 w (speed 4 m/s) with the
constants mu0 = muD = 0.3.
1. roughWallStats --method quadrature (one facet collision) at alpha 10, 30,
   60 deg, Delta 8: mean k_n and k_t within 2e-6 of the oracle's quadrature
   (the oracle's kinks are not resolved: its error is below 1e-6).
2. roughWallStats --method montecarlo --recollide --max-collisions 1
   (the core's operator with spin: one facet, then the mean wall, which
   sees the spin of the first collision) at 20, 45 deg: within 4 standard
   errors (+1e-6) of the oracle's quadrature with fallback=True, spin=True;
   400 000 samples, fixed seed.
3. e(normal speed) by quadrature at 15, 50 deg: 2e-6.
Control: the oracle's quadrature with the constants at the incidence angle
(e(alpha), mu0(alpha), muD(alpha)) must differ from roughWallStats by more
than 1e-3 at one angle at least (the functions matter at these settings).
Fails (not skips) when the tool is not built.
"""

import sys
sys.dont_write_bytecode = True   # keep the source tree clean

import os
import io
import subprocess
import tempfile

import numpy as np

from foamcase.checking import Checker
from foamcase.tables import read_csv
from foamcase.oracleTesting import (tool_arguments, find_tool, STATS_CANDIDATES)
from foamcase import roughWallOracle as rwo

E_TABLE = [(0, 0.95), (30, 0.8), (60, 0.65), (90, 0.6)]
MU0_TABLE = [(0, 0.5), (20, 0.35), (45, 0.2), (90, 0.15)]
MUD_POLY = [0.3, -0.004, 0.00002]


def interp(table):
    x = np.array([p[0] for p in table], dtype=float)
    y = np.array([p[1] for p in table], dtype=float)
    return lambda b: np.interp(b, x, y)


def poly(c):
    return lambda b: sum(ci*np.asarray(b, dtype=float)**i for i, ci in enumerate(c))


def run(stats, args):
    out = subprocess.run([stats, "--threads", "1", "--digits", "15"] + args,
                         capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"roughWallStats {' '.join(args)}: {out.stderr}")
    return read_csv(io.StringIO(out.stdout), numbers=True)


def main():
    args = tool_arguments(__doc__)
    c = Checker("oracle.impactDependent: roughWallStats with e(b), mu(b) "
                "vs the oracle's quadrature")
    stats = find_tool(args.stats, "roughWallStats", STATS_CANDIDATES)
    if not c.check("roughWallStats is built", stats is not None,
                   str(stats or "not found: build target roughWallStats")):
        c.finish()

    e, mu0, muD = interp(E_TABLE), interp(MU0_TABLE), poly(MUD_POLY)
    with tempfile.TemporaryDirectory() as work:
        e_file = os.path.join(work, "e.dat")
        with open(e_file, "w") as f:
            f.write("# facet impact angle [deg]  e\n")
            f.writelines(f"{x} {y}\n" for x, y in E_TABLE)
        mu0_file = os.path.join(work, "mu0.dat")
        with open(mu0_file, "w") as f:   # OpenFOAM's list form
            f.write("(\n" + "".join(f"    ({x} {y})\n" for x, y in MU0_TABLE)
                    + ")\n")
        functions = ["--Delta", "8", "--e-table", e_file,
                     "--mu0-table", mu0_file,
                     "--mud-polynomial", ",".join(repr(x) for x in MUD_POLY)]

        # 1. quadrature against quadrature
        alphas = [10, 30, 60]
        rows = run(stats, functions + ["--alpha", "10,30,60"])
        oracle = rwo.single_facet_quadrature(alphas, 8, e, mu0, muD)
        rejected = 0
        for row, o, a in zip(rows, oracle, alphas):
            for key in ("mean_kn", "mean_kt"):
                c.within(f"quadrature {key} alpha={a}", row[key], o[key], 2e-6)
            const = rwo.single_facet_quadrature(
                [a], 8, float(e(a)), float(mu0(a)), float(muD(a)))[0]
            rejected += max(abs(row["mean_kn"] - const["mean_kn"]),
                            abs(row["mean_kt"] - const["mean_kt"])) > 1e-3
        c.check("control: constants at the incidence angle are rejected",
                rejected >= 1, f"{rejected} of {len(alphas)} angles")

        # 2. the core's operator (one facet, then the mean wall), Monte Carlo
        alphas = [20, 45]
        rows = run(stats, functions + [
            "--alpha", "20,45", "--method", "montecarlo", "--recollide",
            "--max-collisions", "1", "--samples", "400000", "--seed", "31"])
        oracle = rwo.single_facet_quadrature(alphas, 8, e, mu0, muD,
                                             fallback=True, spin=True)
        for row, o, a in zip(rows, oracle, alphas):
            for key in ("mean_kn", "mean_kt"):
                c.within(f"operator {key} alpha={a} (p_wallward "
                         f"{o['p_wallward']:.3f})", row[key], o[key],
                         4*row["se_" + key] + 1e-6)

        # 3. e of the normal speed
        alphas = [15, 50]
        e_speed = rwo.ImpactFunction(lambda w: 0.95 - 0.05*w, "normalSpeed")
        rows = run(stats, ["--Delta", "8", "--e-polynomial", "0.95,-0.05",
                           "--e-argument", "normalSpeed", "--speed", "4",
                           "--mu0", "0.3", "--mud", "0.3", "--alpha", "15,50"])
        oracle = rwo.single_facet_quadrature(alphas, 8, e_speed, 0.3, 0.3,
                                             speed=4.0)
        for row, o, a in zip(rows, oracle, alphas):
            for key in ("mean_kn", "mean_kt"):
                c.within(f"e(normalSpeed) {key} alpha={a}", row[key], o[key],
                         2e-6)
    c.finish()


if __name__ == "__main__":
    main()
