#!/usr/bin/env python3
"""Cost of roughVelocity against OpenFOAM's reboundVelocity in the
field-based Lagrangian: the closed box of the LagrangianRoughVelocity tests
(src/python/foamcase/lagrangianCase.py; 2000 particles under gravity, all six
walls with the condition, 400 steps of 1 ms), run alternately with each
condition, the CPU time of foamRun (its last ExecutionTime) per run; the
ratio per round (rough/rebound of the same round), its median and range.
With --callgrind-steps N1 N2 also valgrind's instruction counts of foamRun
with each condition at N1 and N2 steps (a smaller box of the same kind,
--callgrind-particles): the difference divided by N2 - N1 is the cost of a
time step without the start-up, noise-free.

Usage (in the platform's environment, PYTHONPATH with src/python and
tests/openfoam, as ctest sets it):
    lagrangianCost.py --platform openfoam14 --runs 3 --work DIR \
        --out benchmarks/results/lagrangian-cost.openfoam14.md \
        [--callgrind-steps 50 100] [--callgrind-particles 2000]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import os
import re
import statistics
import time

import numpy as np

import foamcase as fc
from foamcase import bench as bc
from foamcase import lagrangianCase as lc

CONDITIONS = {
    "roughVelocity": "type roughVelocity; e 0.9; mu0 0.3; muD 0.2; "
                     "roughnessAngle 10;",
    "reboundVelocity": "type reboundVelocity; e 0.9; mu 0.2;",
}


def groups(n=2000):
    rng = np.random.default_rng(4)
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
    p.add_argument("--callgrind-steps", type=int, nargs=2)
    p.add_argument("--callgrind-particles", type=int, default=2000)
    args = p.parse_args()
    commit = bc.head_commit()
    instr = {}
    if args.callgrind_steps:
        for steps in args.callgrind_steps:
            for name, cond in CONDITIONS.items():
                path = os.path.join(os.path.abspath(args.work),
                                    "callgrind-steps%d" % steps, name)
                lc.make_case(path, groups(args.callgrind_particles), cond,
                             box=((0, 0, 0), (0.1, 0.1, 0.1)),
                             cells=(10, 10, 10), end_time=steps*1e-3,
                             delta_t=1e-3, gravity=True)
                fc.run(path, ["blockMesh"], "log.blockMesh")
                out = os.path.join(path, "callgrind.out")
                fc.run(path, ["valgrind", "--tool=callgrind",
                              "--callgrind-out-file=" + out, "foamRun"],
                       "log.callgrind", timeout=3600)
                total = None
                for line in open(out):
                    if line.startswith("summary:") \
                            or line.startswith("totals:"):
                        total = int(line.split()[1])
                instr[(steps, name)] = total
                print(steps, name, total, flush=True)
                os.remove(out)
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
    paired = [a/b for a, b in zip(times["roughVelocity"],
                                  times["reboundVelocity"])]
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
              "Ratio per round (same round): median %.3f, range %.3f-%.3f"
              % (statistics.median(paired), min(paired), max(paired)), ""]
    if instr:
        s0, s1 = args.callgrind_steps
        per = {name: (instr[(s1, name)] - instr[(s0, name)])/(s1 - s0)
               for name in CONDITIONS}
        lines += [
            "Instructions (callgrind of foamRun, %d particles, the same box"
            "): per time step = (whole run at %d steps - at %d steps)/%d, "
            "the start-up removed." % (args.callgrind_particles, s1, s0,
                                       s1 - s0), "",
            "| condition | whole run, %d steps | whole run, %d steps | "
            "per step [10^6] |" % (s0, s1), "|---|---|---|---|"]
        for name in CONDITIONS:
            lines.append("| %s | %d | %d | %.3f |" % (
                name, instr[(s0, name)], instr[(s1, name)], per[name]/1e6))
        lines += ["", "Per step, roughVelocity / reboundVelocity: %.4f"
                  % (per["roughVelocity"]/per["reboundVelocity"]), ""]
    lines += ["Command: `benchmarks/scripts/lagrangianCost.py --platform %s "
              "--runs %d%s`" % (args.platform, args.runs,
                                " --callgrind-steps %d %d "
                                "--callgrind-particles %d"
                                % (tuple(args.callgrind_steps)
                                   + (args.callgrind_particles,))
                                if instr else ""), ""]
    fc.write_text(args.out, "\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
