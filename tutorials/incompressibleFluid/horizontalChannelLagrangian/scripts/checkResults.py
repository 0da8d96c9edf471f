#!/usr/bin/env python3
"""The smoke test's assertions on RESULTS/statistics.csv (variants smooth
and rough, written by scripts/postProcess.py), at the last write time.

Usage: scripts/checkResults.py RESULTS N

1. No particle lost: both variants hold the N injected particles (the walls
   reflect every particle that reaches them; the other patches are cyclic).
   Fails if the condition lets a particle through the wall or removes it.
2. The rough wall raises the wall-normal rms velocity: rough minus smooth
   exceeds 3 combined standard errors (independent particles, see
   postProcess.py).  Fails if the roughness is ignored (Delta read as 0)
   or the rebound loses its normal component.
3. The smooth wall keeps the particles in their plane: rms Uz = 0 exactly
   (injection, air and gravity have no z component and a flat wall of
   normal y without spin gives none), while the rough wall's facets tilt
   in every direction: rms Uz > 3 standard errors.  Fails if the smooth
   wall is not flat or the rough one only tilts in the flow direction.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import csv
import math
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    n = int(sys.argv[2])
    last = {}
    with open(sys.argv[1] + "/statistics.csv") as f:
        for r in csv.DictReader(f):
            if r["variant"] not in last or \
                    float(r["time"]) >= float(last[r["variant"]]["time"]):
                last[r["variant"]] = r
    s, r = last["smooth"], last["rough"]
    checks = []
    checks.append((int(s["n"]) == n and int(r["n"]) == n,
                   "particles kept: smooth %s, rough %s of %d"
                   % (s["n"], r["n"], n)))
    d = float(r["rmsUy"]) - float(s["rmsUy"])
    se = math.hypot(float(r["seRmsUy"]), float(s["seRmsUy"]))
    checks.append((d > 3*se,
                   "rms Uy rough %s - smooth %s = %.4g m/s > 3 se = %.3g"
                   % (r["rmsUy"], s["rmsUy"], d, 3*se)))
    checks.append((float(s["rmsUz"]) == 0.0,
                   "smooth: rms Uz = %s (0 expected)" % s["rmsUz"]))
    checks.append((float(r["rmsUz"]) > 3*float(r["seRmsUz"]),
                   "rough: rms Uz %s > 3 se = %.3g"
                   % (r["rmsUz"], 3*float(r["seRmsUz"]))))
    for ok, msg in checks:
        print("%s: %s" % ("pass" if ok else "FAIL", msg))
    if not all(ok for ok, _ in checks):
        print("TEST FAILED")
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
