#!/usr/bin/env python3
"""Cost of roughVelocity against OpenFOAM's reboundVelocity in the
field-based Lagrangian: the closed box of the LagrangianRoughVelocity tests
(src/python/foamcase/lagrangianCase.py; 2000 particles under gravity, all six
walls with the condition, 400 steps of 1 ms), run alternately with each
condition, the CPU time of foamRun (its last ExecutionTime) per run.

Usage (in the platform's environment, PYTHONPATH with src/python and
tests/openfoam, as ctest sets it):
    lagrangianCost.py --platform openfoam14 --runs 3 --work DIR \
        --out benchmarks/results/lagrangian-cost.openfoam14.md

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import os
import re
import statistics
import subprocess
import time

import numpy as np

import foamcase as fc
from foamcase import lagrangianCase as lc

CONDITIONS = {
    "roughVelocity": "type roughVelocity; e 0.9; mu0 0.3; muD 0.2; "
                     "roughnessAngle 10;",
    "reboundVelocity": "type reboundVelocity; e 0.9; mu 0.2;",
}


def groups():
    rng = np.random.default_rng(4)
    n = 2000
    pos = 0.005 + 0.09*rng.random((n, 3))
    out = []
    for k in range(20):
        v = rng.normal(size=3)
        v *= 3/np.linalg.norm(v)
        out.append(lc.Group("g%d" % k, pos[k*n//20:(k + 1)*n//20], v,
                            100e-6 + 20e-6*k))
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--platform", required=True)
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--work", required=True)
    p.add_argument("--out", required=True)
    args = p.parse_args()
    cases = {}
    for name, cond in CONDITIONS.items():
        cases[name] = lc.make_case(
            os.path.join(os.path.abspath(args.work), name), groups(), cond,
            box=((0, 0, 0), (0.1, 0.1, 0.1)), cells=(10, 10, 10),
            end_time=0.4, delta_t=1e-3, gravity=True)
        fc.run(cases[name], ["blockMesh"], "log.blockMesh")
    times = {name: [] for name in CONDITIONS}
    loads = []
    for i in range(args.runs):
        for name in CONDITIONS:
            fc.run(cases[name], ["foamRun"], "log.foamRun.%d" % i)
            log = fc.read_text(os.path.join(cases[name],
                                            "log.foamRun.%d" % i))
            times[name].append(float(re.findall(
                r"ExecutionTime = (%s) s" % fc.NUMBER, log)[-1]))
            loads.append(os.getloadavg()[0])
    med = {k: statistics.median(v) for k, v in times.items()}
    ratio = med["roughVelocity"]/med["reboundVelocity"]
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True,
                            cwd=os.path.dirname(__file__)).stdout.strip()
    lines = [
        "# roughVelocity against reboundVelocity (%s)" % args.platform, "",
        "Closed box, 2000 particles, gravity, six walls with the condition, "
        "400 steps; foamRun's CPU time (ExecutionTime) per run, runs "
        "alternating. Commit %s, %s UTC; 1-min load average during the "
        "runs %.1f-%.1f on %d cores (other jobs running)."
        % (commit, time.strftime("%Y-%m-%d %H:%M", time.gmtime()),
           min(loads), max(loads), os.cpu_count()), "",
        "| condition | CPU time per run [s] | median [s] |", "|---|---|---|"]
    for name in CONDITIONS:
        lines.append("| %s | %s | %.2f |" % (
            name, ", ".join("%.2f" % x for x in times[name]), med[name]))
    lines += ["", "Ratio of the medians, roughVelocity / reboundVelocity: "
              "%.3f" % ratio, "",
              "Command: `benchmarks/scripts/lagrangianCost.py --platform %s "
              "--runs %d`" % (args.platform, args.runs), ""]
    fc.write_text(args.out, "\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
