#!/usr/bin/python3
# roughWallInteraction benchmarks: what e and muD as tables of the facet
# impact angle cost in the wall box, beside constants and beside OpenFOAM's
# standardWallInteraction.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Cost of e(angle) and muD(angle) as Function1 tables (issue 31) in the
wall box of openfoamCost.py (benchmarks/openfoam/wallBox: 110 um parcels,
a colliding cloud, e = 1, no friction, roughnessAngle 8).

Variants, in one run of this script:
  standard: OpenFOAM's standardWallInteraction, rebound, e = 1, mu = 0;
  rough:    roughWallInteraction with the constants e 1, mu0 0, muD 0;
  table:    the same with e and muD as Function1 tables of the facet impact
            angle with the five rows of docs/impactDependent's tables
            (0, 10, 20, 40, 90 deg) and the values of the constants (e 1,
            muD 0): the table is looked up at every facet collision but the
            physics, and so the parcels' paths and hits, stay those of
            `rough`, so that any difference is the cost of the look-up.

Two measures:
  callgrind: valgrind's instruction counts of the whole solver run at two
            lengths (--steps, e.g. 50 and 100 steps of the template's 1 ms);
            the difference of the two divided by the difference of the
            steps is the cost of a time step without the start-up; the
            per-step ratios against `rough` and `standard` are noise-free.
            Also the model's correct() per call (inclusive).
  rounds:   alternated wall-clock rounds (A, B, C, A, B, C, ... the order
            reversed every other round) of a longer run: the CPU time of the
            time steps (last ExecutionTime minus the first); ratios per
            round, their median and range. Noisy on a shared machine.

Writes benchmarks/results/<output>.<platform>.csv and .md (default output
table-cost).

Usage: etc/openfoamEnv openfoam14 /usr/bin/python3 \\
           benchmarks/scripts/tableCost.py --platform openfoam14 \\
           [--steps 50 100] [--callgrind-parcels 2000] \\
           [--parcels 2000] [--end-time 0.3] [--rounds 5]
"""
import argparse
import os
import shutil
import statistics

from foamcase import bench as bc
import foamcase as fc
from foamcase.openfoamcost.case import Runner, delta_t, make_case
from foamcase.openfoamcost.parse import callgrind_profile
from foamcase.openfoamcost.run import run

VARIANTS = ("standard", "rough", "table")

ANGLES = (0, 10, 20, 40, 90)


def table(value):
    return "table (%s)" % " ".join("(%g %g)" % (a, value) for a in ANGLES)


def rough_model(e, mud):
    return """FoamFile { version 2.0; format ascii; class dictionary;
    location "constant"; object wallModel; }
patchInteractionModel roughWallInteraction;
roughWallInteractionCoeffs
{
    patches
    (
        walls
        {
            type            rough;
            e               %s;
            mu0             0;
            muD             %s;
            roughnessAngle  8;
        }
    );
}
""" % (e, mud)


def prepare(case):
    """The wall model file of each variant (standard: the template's)"""
    fc.write_text(case.file("constant/wallModel.rough"), rough_model("1", "0"))
    fc.write_text(case.file("constant/wallModel.table"),
                  rough_model(table(1), table(0)))


def ratios(values, a, b):
    r = [x/y for x, y in zip(values[a], values[b])]
    return statistics.median(r), min(r), max(r)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--platform", choices=fc.PLATFORMS, required=True)
    p.add_argument("--steps", type=int, nargs=2, default=(50, 100))
    p.add_argument("--callgrind-parcels", type=int, default=2000)
    p.add_argument("--parcels", type=int, default=2000)
    p.add_argument("--end-time", type=float, default=0.3)
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--output", default="table-cost")
    p.add_argument("--work", default=os.path.join(bc.ROOT, "build",
                                                  "tableCost"))
    args = p.parse_args()
    args.tag = args.platform
    args.lib_path, args.baseline_lib, args.variant_lib_path = [], None, []
    runner = Runner(args)
    runner.check_environment()
    import foamcase.openfoamcost.case as oc
    oc.MODEL_FILE.update(table="table")
    work = os.path.join(os.path.abspath(args.work), args.platform)
    os.makedirs(work, exist_ok=True)
    commit = bc.head_commit()
    rows = []

    # callgrind: the same case at two lengths
    instr = {}
    for steps in args.steps:
        cg_work = os.path.join(work, "callgrind-steps%d" % steps)
        os.makedirs(cg_work, exist_ok=True)
        end_time = steps*delta_t()
        cg, _ = make_case(runner, cg_work, args.callgrind_parcels, 1,
                          end_time)
        prepare(cg)
        for variant in VARIANTS:
            out = cg.file("callgrind.%s.out" % variant)
            shutil.copy(cg.file("constant/wallModel." + variant),
                        cg.file("constant/wallModel"))
            log = "log.callgrind." + variant
            cg.run(["valgrind", "--tool=callgrind",
                    "--callgrind-out-file=" + out, cg.solver], log,
                   timeout=3600)
            found = cg.read_steps(log)
            entry = "StandardWallInteraction<" if variant == "standard" \
                else "RoughWallInteraction<"
            total, calls, parts, _ = callgrind_profile(out, entry)
            instr[(steps, variant)] = total
            row = dict(platform=args.platform, commit=commit,
                       kind="callgrind", variant=variant,
                       parcels=args.callgrind_parcels, steps=len(found),
                       hits=found[-1]["hits"] if found else "",
                       total_instructions=total, correct_calls=calls,
                       correct_per_call="%.1f" % (sum(parts.values())
                                                  / max(calls, 1)))
            rows.append(row)
            print(row, flush=True)
            os.remove(out)
    s0, s1 = args.steps
    per_step = {v: (instr[(s1, v)] - instr[(s0, v)])/(s1 - s0)
                for v in VARIANTS}

    # alternated rounds
    case, _ = make_case(runner, work, args.parcels, 1, args.end_time)
    prepare(case)
    cpu = {v: [] for v in VARIANTS}
    loads = []
    for rnd in range(args.rounds):
        for variant in (VARIANTS if rnd % 2 == 0 else VARIANTS[::-1]):
            r = run(runner, case, variant, "log.%s.%d" % (variant, rnd))
            load = bc.load_average()
            loads.append(load)
            cpu[variant].append(r["step_cpu"])
            row = dict(platform=args.platform, commit=commit, kind="round",
                       round=rnd, variant=variant, parcels=args.parcels,
                       steps=r["steps"], hits=r["hits"],
                       step_cpu="%.3f" % r["step_cpu"],
                       wall="%.3f" % r["wall"], load=load)
            rows.append(row)
            print(row, flush=True)

    stem = os.path.join(bc.ROOT, "benchmarks", "results",
                        "%s.%s" % (args.output, args.platform))
    bc.write_csv(stem + ".csv", rows)

    command = ("etc/openfoamEnv %s /usr/bin/python3 benchmarks/scripts/"
               "tableCost.py --platform %s --steps %d %d "
               "--callgrind-parcels %d --parcels %d --end-time %g "
               "--rounds %d" % (args.platform, args.platform, s0, s1,
                                args.callgrind_parcels, args.parcels,
                                args.end_time, args.rounds))
    cg_rows = {r["variant"]: r for r in rows
               if r["kind"] == "callgrind" and r["steps"] == s1}
    lines = [
        "# e and muD as tables of the impact angle: cost in the wall box "
        "(%s)" % args.platform, "",
        bc.provenance_line(commit, loads, command), "",
        "`table`: e and muD as Function1 tables of the facet impact angle "
        "(five rows, values those of the constants, so the same paths and "
        "hits as `rough`).", "",
        "## Instructions (callgrind, %d parcels)" % args.callgrind_parcels,
        "",
        "Per time step: (whole run at %d steps - at %d steps)/%d, the "
        "start-up removed." % (s1, s0, s1 - s0), "",
        "| variant | wall hits at %d steps | instructions per step "
        "[10^6] | / rough | / standard | correct() per call |" % s1,
        "|---|---|---|---|---|---|"]
    for v in VARIANTS:
        lines.append("| %s | %s | %.3f | %.4f | %.4f | %s |" % (
            v, cg_rows[v]["hits"], per_step[v]/1e6,
            per_step[v]/per_step["rough"], per_step[v]/per_step["standard"],
            cg_rows[v]["correct_per_call"]))
    lines += [
        "", "## Alternated rounds (CPU time of the time steps, %d parcels, "
        "%g s simulated, %d rounds)" % (args.parcels, args.end_time,
                                        args.rounds), "",
        "| variant | CPU of the steps per round [s] | median [s] |",
        "|---|---|---|"]
    for v in VARIANTS:
        lines.append("| %s | %s | %.3f |" % (
            v, ", ".join("%.2f" % x for x in cpu[v]),
            statistics.median(cpu[v])))
    lines += ["", "| ratio | per-round median (min-max) | callgrind per "
              "step |", "|---|---|---|"]
    for a, b in (("table", "rough"), ("rough", "standard"),
                 ("table", "standard")):
        m, lo, hi = ratios(cpu, a, b)
        lines.append("| %s/%s | %.3f (%.3f-%.3f) | %.4f |" % (
            a, b, m, lo, hi, per_step[a]/per_step[b]))
    lines.append("")
    fc.write_text(stem + ".md", "\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
