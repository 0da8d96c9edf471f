#!/usr/bin/python3
"""Calibrate the tutorial's steel surface: the Rq and RSm of the library's
synthetic Gaussian profile (roughness { Rq ...; RSm ...; }, rolling-sphere
envelope, docs/roughWallInteraction.md) whose Delta(d_p) is Derevich's
8 deg at 110 um and 5 deg at 460 um (glass beads on steel).

Method: for a given RSm, Delta(460 um) rises with Rq: bisection on Rq gives
Delta(460 um) = 5 deg. Along that curve Delta(110 um) falls as RSm grows
(the 110 um beads fit ever better into the valleys of a profile whose
slopes fall): bisection on RSm gives Delta(110 um) = 8 deg. Every Delta is
roughWallStats' (--Rq --RSm --d: the envelope of the same profile the
library builds, seed 1, 5000 RSm long). The values used by the tutorial are
the result rounded to 3 digits; the file then records the command that
checks them and its output, with two other seeds of the profile beside it
(the spread a different realisation of the same surface gives).

Usage: calibrateRoughness.py [--check] [--stats PATH] [--output FILE]
  --check   only the check of the values used (three roughWallStats runs);
            without it the bisection runs first (about 250 runs of
            roughWallStats, a few minutes)
  --stats   roughWallStats (default: $ROUGHWALL_ROOT/bin/roughWallStats, else
            bin/roughWallStats of the checkout holding this tutorial)
  --output  default: roughnessCalibration.txt beside Allrun
"""
import argparse
import csv
import io
import os
import shlex
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
TUTORIAL = os.path.dirname(HERE)
ROOT = os.environ.get("ROUGHWALL_ROOT") or os.path.join(TUTORIAL, "..", "..", "..")

TARGETS = ((110e-6, 8.0), (460e-6, 5.0))   # (d [m], Delta [deg]): Derevich's paper
TOLERANCE = 0.2                            # [deg], each target
USED = {"Rq": "2.87e-6", "RSm": "122e-6"}  # the tutorial's variants (rounded)
DIAMETERS = "110e-6,195e-6,460e-6"         # the targets and the tutorial's beads


def run(stats, Rq, RSm, d, seed=1):
    cmd = [stats, "--Rq", str(Rq), "--RSm", str(RSm), "--d", d, "--seed", str(seed)]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True)
    return cmd, out


def deltas(stats, Rq, RSm, d):
    _, out = run(stats, repr(Rq), repr(RSm), ",".join(repr(x) for x in d))
    return [float(r["Delta_deg"]) for r in csv.DictReader(io.StringIO(out.stdout))]


def bisect(f, lo, hi, n, geometric=False):
    """x in [lo, hi] with f(x) = 0, f increasing"""
    for _ in range(n):
        mid = (lo*hi)**0.5 if geometric else 0.5*(lo + hi)
        if f(mid) < 0:
            lo = mid
        else:
            hi = mid
    return (lo*hi)**0.5 if geometric else 0.5*(lo + hi)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--stats", default=os.path.join(ROOT, "bin", "roughWallStats"))
    p.add_argument("--output", default=os.path.join(TUTORIAL, "roughnessCalibration.txt"))
    p.add_argument("--check", action="store_true")
    args = p.parse_args()
    (d1, D1), (d2, D2) = TARGETS
    lines = [
        "# Calibration of the horizontalChannel tutorial's steel surface",
        "# (written by scripts/calibrateRoughness.py; its docstring gives the method)",
        "#",
        "# Targets (Derevich's paper, glass beads on steel): Delta(110 um) = 8 deg,",
        "# Delta(460 um) = 5 deg, each within %g deg." % TOLERANCE]
    if not args.check:
        lines += bisection(args, d1, D1, d2, D2)
    lines += ["# Used by the tutorial (rounded): Rq = %s m, RSm = %s m. Check:" % (
        USED["Rq"], USED["RSm"])]
    check_used(args, lines)


def bisection(args, d1, D1, d2, D2):
    """The surface with Delta(d1) = D1 and Delta(d2) = D2 (see the docstring)"""
    def rq_for(RSm):
        return bisect(lambda Rq: deltas(args.stats, Rq, RSm, [d2])[0] - D2,
                      1e-6, 10e-6, 18, geometric=True)

    # Delta(d1) on the curve Delta(d2) = D2 falls with RSm (decreasing in
    # RSm: bisection on its negative)
    RSm = bisect(lambda L: D1 - deltas(args.stats, rq_for(L), L, [d1])[0],
                 80e-6, 200e-6, 12)
    Rq = rq_for(RSm)
    found = deltas(args.stats, Rq, RSm, [d1, d2])
    return ["# Bisection result: Rq = %.4g m, RSm = %.4g m: Delta(110 um) = %.3f deg,"
            % (Rq, RSm, found[0]),
            "# Delta(460 um) = %.3f deg." % found[1]]


def check_used(args, lines):
    worst = 0.0
    for seed in (1, 2, 3):
        cmd, out = run(args.stats, USED["Rq"], USED["RSm"], DIAMETERS, seed)
        rows = list(csv.DictReader(io.StringIO(out.stdout)))
        if seed == 1:
            for (d, D), row in zip(TARGETS, (rows[0], rows[2])):
                worst = max(worst, abs(float(row["Delta_deg"]) - D))
        cmd[0] = "roughWallStats"
        lines += ["", "$ " + " ".join(shlex.quote(c) for c in cmd)
                  + ("   # the library's profile (seed 1)" if seed == 1
                     else "   # another realisation of the same surface")]
        lines += ["# stderr: " + l for l in out.stderr.splitlines()]
        lines += out.stdout.splitlines()
    lines += ["", "# Largest difference to the targets (seed 1): %.3f deg (tolerance %g deg): %s"
              % (worst, TOLERANCE, "ok" if worst <= TOLERANCE else "FAILED")]
    with open(args.output, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    if worst > TOLERANCE:
        raise SystemExit(1)


if __name__ == "__main__":
    main()
