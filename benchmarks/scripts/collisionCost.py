#!/usr/bin/python3
# roughWallInteraction benchmarks: the cost of the inter-particle collision
# model (stochasticCollisionModel Sommerfeld) beside none.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Cost of the stochastic collision model Sommerfeld in the granular-gas box
of its test (tests/openfoam/testSommerfeldCollision.py: the closed 0.1 m
box, 2 x 2 x 2 cells, no carrier forces, specular walls, 256 Maxwellian
injector groups of 0.25 mm parcels), beside `stochasticCollisionModel
none` in the same box.

The box's number density of real particles is held at the test's (a
collision frequency of about 20 per particle and second, a step
probability of about 0.05 at dt = 2.5 ms): with more parcels each carries
fewer real particles, so that the model does the same work per parcel.

Two measures:
  callgrind: valgrind's instruction counts of the whole run at two lengths
            (--steps), for Sommerfeld and none; the difference of the two
            divided by the difference of the steps is the cost of a time
            step without the start-up. The collision model's own cost per
            parcel-step is the inclusive count of
            SommerfeldCollision<...>::collide over its calls, divided by
            the parcels (noise-free).
  rounds:   alternated wall-clock rounds (Sommerfeld, none, none,
            Sommerfeld, ...) at each number of parcels (--parcels, e.g.
            10^4 and 10^5): the CPU time of the time steps (last
            ExecutionTime minus the first), per parcel-step. Linear cost:
            the same per parcel-step at both sizes. Noisy on a shared
            machine: ratios per round, their median and range.

Writes benchmarks/results/collision-cost.<platform>.csv and .md.

Usage: etc/openfoamEnv openfoam14 /usr/bin/python3 \\
           benchmarks/scripts/collisionCost.py --platform openfoam14 \\
           [--steps 10 20] [--callgrind-per-group 40 400] \\
           [--per-group 40 400] [--rounds-steps 40] [--rounds 3]
"""
import argparse
import itertools
import os
import re
import shutil
import statistics
import sys

from foamcase import bench as bc
import foamcase as fc
from foamcase.openfoamcost.parse import callgrind_profile

# The granular-gas case of the model's test: one definition of the box
sys.path.insert(0, os.path.join(bc.ROOT, "tests", "openfoam"))
import testSommerfeldCollision as gas  # noqa: E402

MODELS = ("Sommerfeld", "none")
ENTRY = "SommerfeldCollision<"


def make_box(platform, path, per_group, steps):
    """The test's box with per_group parcels per injector group, the real
    particles' number density of the test, `steps` steps of its dt"""
    if os.path.exists(path):
        shutil.rmtree(path)
    case = gas.make_case(platform, path, per_group=per_group)
    parcels = per_group*gas.NGROUPS
    fc.replace_in_file(case.file("constant/injectors"),
                       r"nParticle\s+[^;]+;",
                       "nParticle       %r;" % (gas.N_PARTICLE*gas.PARCELS/parcels),
                       count=gas.NGROUPS)
    dt = 0.0025
    case.set_control(deltaT=repr(dt), endTime=repr(steps*dt),
                     writeControl="runTime", writeInterval=repr(steps*dt))
    case.mesh()
    return case, parcels


def set_model(case, model):
    gas.set_model(case, gas.model_entry() if model == "Sommerfeld"
                  else "stochasticCollisionModel none;")


def step_cpu(log_text):
    """CPU time of the time steps: last ExecutionTime minus the first"""
    times = [float(x) for x in re.findall(
        r"^ExecutionTime = (%s) s" % fc.NUMBER, log_text, re.M)]
    return times[-1] - times[0], len(times) - 1


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--platform", choices=fc.PLATFORMS, required=True)
    p.add_argument("--steps", type=int, nargs=2, default=(10, 20))
    p.add_argument("--callgrind-per-group", type=int, nargs="+", default=(40,))
    p.add_argument("--per-group", type=int, nargs="+", default=(40, 400))
    p.add_argument("--rounds-steps", type=int, default=40)
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--work", default=os.path.join(bc.ROOT, "build",
                                                  "collisionCost"))
    args = p.parse_args()
    platform = fc.Platform(args.platform)
    work = os.path.join(os.path.abspath(args.work), args.platform)
    os.makedirs(work, exist_ok=True)
    commit = bc.head_commit()
    rows = []

    # callgrind: each size at two lengths
    instr, per_parcel_step = {}, {}
    for per_group, steps in itertools.product(args.callgrind_per_group,
                                              args.steps):
        case, parcels = make_box(platform, os.path.join(
            work, "callgrind-%d-steps%d" % (per_group, steps)), per_group,
            steps)
        for model in MODELS:
            set_model(case, model)
            out = case.file("callgrind.%s.out" % model)
            case.run(["valgrind", "--tool=callgrind",
                      "--callgrind-out-file=" + out, case.solver],
                     "log.callgrind." + model, timeout=7200)
            total, calls, parts, _ = callgrind_profile(out, ENTRY, "::collide(")
            instr[(parcels, steps, model)] = total
            collide = sum(parts.values())
            row = dict(platform=args.platform, commit=commit,
                       kind="callgrind", model=model, parcels=parcels,
                       steps=steps, total_instructions=total,
                       collide_calls=calls, collide_instructions=collide)
            if model == "Sommerfeld" and calls:
                row["collide_per_parcel_step"] = "%.1f" % (
                    collide/(calls*parcels))
                per_parcel_step[parcels] = collide/(calls*parcels)
            rows.append(row)
            print(row, flush=True)
            os.remove(out)
    s0, s1 = args.steps
    cg_sizes = [n*gas.NGROUPS for n in args.callgrind_per_group]
    per_step = {(n, m): (instr[(n, s1, m)] - instr[(n, s0, m)])/(s1 - s0)
                for n in cg_sizes for m in MODELS}

    # alternated rounds at each size
    cpu = {}
    loads = []
    for per_group in args.per_group:
        case, parcels = make_box(platform, os.path.join(
            work, "rounds-%d" % per_group), per_group, args.rounds_steps)
        for rnd in range(args.rounds):
            for model in (MODELS if rnd % 2 == 0 else MODELS[::-1]):
                set_model(case, model)
                log = "log.%s.%d" % (model, rnd)
                case.run([case.solver], log, timeout=7200)
                seconds, steps = step_cpu(fc.read_text(case.file(log)))
                load = bc.load_average()
                loads.append(load)
                cpu.setdefault((parcels, model), []).append(
                    seconds/(steps*parcels))
                row = dict(platform=args.platform, commit=commit,
                           kind="round", model=model, parcels=parcels,
                           round=rnd, steps=steps,
                           step_cpu="%.3f" % seconds, load=load)
                rows.append(row)
                print(row, flush=True)

    stem = os.path.join(bc.ROOT, "benchmarks", "results",
                        "collision-cost.%s" % args.platform)
    bc.write_csv(stem + ".csv", rows)

    command = ("etc/openfoamEnv %s /usr/bin/python3 benchmarks/scripts/"
               "collisionCost.py --platform %s --steps %d %d "
               "--callgrind-per-group %s --per-group %s --rounds-steps %d "
               "--rounds %d" % (args.platform, args.platform, s0, s1,
                                " ".join(map(str, args.callgrind_per_group)),
                                " ".join(map(str, args.per_group)),
                                args.rounds_steps, args.rounds))
    lines = [
        "# The inter-particle collision model's cost (%s)" % args.platform, "",
        bc.provenance_line(commit, loads, command), "",
        "The granular-gas box of `tests/openfoam/testSommerfeldCollision.py` "
        "(2 x 2 x 2 cells, no carrier forces, about 20 collisions per "
        "particle and second, a step probability of about 0.05), "
        "`stochasticCollisionModel Sommerfeld` against `none`.", "",
        "## Instructions (callgrind)", "",
        "| parcels | model | instructions per step [10^6] | per "
        "parcel-step | the model's `collide` per parcel-step |",
        "|---|---|---|---|---|"]
    for n in cg_sizes:
        for m in MODELS:
            lines.append("| %d | %s | %.2f | %.0f | %s |" % (
                n, m, per_step[(n, m)]/1e6, per_step[(n, m)]/n,
                "%.0f" % per_parcel_step[n] if m == "Sommerfeld"
                and n in per_parcel_step else "-"))
    lines += [
        "",
        "Per time step: (whole run at %d steps - at %d steps)/%d, the "
        "start-up removed. `collide`: the model's statistics, partners, "
        "collisions and log line, inclusive, over its calls. "
        "Sommerfeld/none per step: %s." % (
            s1, s0, s1 - s0, ", ".join(
                "%.3f at %d parcels" % (per_step[(n, "Sommerfeld")]
                                        / per_step[(n, "none")], n)
                for n in cg_sizes)), "",
        "## Alternated rounds (CPU time of the time steps, %d steps, %d "
        "rounds)" % (args.rounds_steps, args.rounds), "",
        "| parcels | model | CPU per parcel-step per round [us] | median "
        "[us] |", "|---|---|---|---|"]
    sizes = sorted({k[0] for k in cpu})
    for n in sizes:
        for m in MODELS:
            v = cpu[(n, m)]
            lines.append("| %d | %s | %s | %.3f |" % (
                n, m, ", ".join("%.3f" % (1e6*x) for x in v),
                1e6*statistics.median(v)))
    lines += ["", "| parcels | Sommerfeld/none per round: median (min-max) "
              "|", "|---|---|"]
    for n in sizes:
        r = [a/b for a, b in zip(cpu[(n, "Sommerfeld")], cpu[(n, "none")])]
        lines.append("| %d | %.3f (%.3f-%.3f) |" % (
            n, statistics.median(r), min(r), max(r)))
    if len(sizes) > 1:
        a, b = sizes[0], sizes[-1]
        extra = [statistics.median(cpu[(n, "Sommerfeld")])
                 - statistics.median(cpu[(n, "none")]) for n in (a, b)]
        lines += ["", "The model's own CPU per parcel-step (median "
                  "Sommerfeld - median none): %.3f us at %d parcels, %.3f us "
                  "at %d: ratio %.2f (1 for a cost linear in parcels)." % (
                      1e6*extra[0], a, 1e6*extra[1], b, extra[1]/extra[0])]
    lines.append("")
    fc.write_text(stem + ".md", "\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
