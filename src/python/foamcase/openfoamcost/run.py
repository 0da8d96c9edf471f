# roughWallInteraction benchmarks: the OpenFOAM cost benchmark, running.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Running the OpenFOAM cost benchmark: the timed runs of the variants,
alternated round by round, the untimed check of the hit count, callgrind,
perf, the tutorial's variants.
"""
import copy
import os
import re
import resource
import shutil
import subprocess
import sys

from foamcase import bench as bc
import foamcase as fc

from .case import (MESH_NAMES, MODEL_FILE, ONE_BOX, TUTORIAL_BASE,
                   TUTORIAL_LIB_VARIANTS, TUTORIAL_VARIANTS, TWO_BOXES,
                   check_boxes, delta_t, library_path, make_case,
                   specular_hits, travel_time)
from .parse import (MODEL_ENTRY, PROFILE_MODEL, baseline_name,
                    callgrind_profile, perf_shares)
from .report import PLATFORM_NAMES, callgrind_table, command_of, tutorial_stem


def check_specular(runner, case, positions, end_time, boxes):
    """One more run (not timed) of a copy of the case, the rough model with
    roughnessAngle 0 (specular, and it counts its hits) and a write at the
    last step: the model's hit count against specular_hits, and (nprocs >
    1) each processor's parcels at the end against the parcels that started
    in its box. Returns (ok, description)"""
    check = copy.copy(case)
    check.path = case.path + "-check"
    if os.path.isdir(check.path):
        shutil.rmtree(check.path)
    shutil.copytree(case.path, check.path)
    check.set_control(writeInterval="%d" % int(round(end_time/delta_t())))
    text = fc.read_text(check.file("constant/wallModel.rough"))
    text, n = re.subn(r"roughnessAngle\s+[^;]+;", "roughnessAngle  0;", text)
    assert n == 1
    fc.write_text(check.file("constant/wallModel.specular"), text)
    hits = run(runner, check, "specular")["hits"]
    exact = specular_hits(positions, travel_time(runner.platform, end_time),
                          boxes)
    ok = hits == exact
    out = ["hits with roughnessAngle 0: %d, unfolding: %d%s" % (
        hits, exact, "" if ok else " (DIFFERENT)")]
    if check.nprocs > 1:
        counts, starts = [], []
        for i in range(check.nprocs):
            proc = check.file("processor%d" % i)
            last = max((d for d in os.listdir(proc)
                        if re.match(r"^[0-9.eE+-]+$", d) and float(d) > 0),
                       key=float)
            cloud = os.path.join(proc, last, "lagrangian",
                                 runner.platform.cloud)
            counts.append(len(fc.read_field(os.path.join(cloud, "d"))))
            xs = fc.read_field(os.path.join(
                proc, "constant", "polyMesh", "points"))[:, 0]
            starts.append(sum(1 for p in positions
                              if xs.min() <= p[0] <= xs.max()))
        ok = ok and counts == starts
        out.append("parcels per rank at t = %s: %s, started in its box: "
                   "%s%s" % (last, "/".join(map(str, counts)),
                             "/".join(map(str, starts)),
                             " (no transfers)" if counts == starts
                             else " (PARCELS CHANGED RANK)"))
    shutil.rmtree(check.path)
    return ok, "; ".join(out)


def run(runner, case, variant, log=None):
    """Run the case with a variant's wall model (and libraries): CPU time of
    the time steps, wall clock, CPU of all processes, the model's hits"""
    shutil.copy(case.file("constant/wallModel." + MODEL_FILE[variant]),
                case.file("constant/wallModel"))
    log = log or "log." + variant
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with library_path(runner.library_dirs(variant)):
        _, wall = case.solve(log)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime
                                                - before.ru_stime)
    steps = case.read_steps(log)
    exec_times = [s["executionTime"] for s in steps
                  if s["executionTime"] is not None]
    hits = steps[-1]["hits"] if steps else 0
    return dict(step_cpu=exec_times[-1] - exec_times[0], wall=wall,
                process_cpu=cpu, hits=hits if hits else None,
                steps=len(steps))


def measure(runner, args):
    """Rounds of the variants in each configuration, the order reversed
    every other round: the single box at each parcel count (serial), then
    (--mpi) the two disjoint boxes with the middle parcel count on 1 and 2
    ranks, the runs of a round alternated together"""
    work = os.path.abspath(os.path.join(args.work, runner.tag))
    os.makedirs(work, exist_ok=True)
    rows = []
    groups = [(n, ONE_BOX, (1,)) for n in args.parcels]
    if args.mpi:
        groups.append((args.parcels[min(1, len(args.parcels) - 1)],
                       TWO_BOXES, (1, 2)))
    for parcels, boxes, ranks in groups:
        # at least parcel_seconds of parcel time per run: small runs long
        # enough for the 0.01 s resolution of ExecutionTime
        end_time = max(args.end_time, args.parcel_seconds/parcels)
        cases, checks = {}, {}
        for np in ranks:
            cases[np], positions = make_case(runner, work, parcels, np,
                                             end_time, boxes=boxes)
            ok, text = check_specular(runner, cases[np], positions, end_time,
                                      boxes)
            if np > 1:
                ok2, text2 = check_boxes(cases[np], positions, boxes)
                ok, text = ok and ok2, "%s; %s" % (text2, text)
            checks[np] = text
            print("%s, %d parcels on %d rank(s): %s" % (
                MESH_NAMES[boxes], parcels, np, text), flush=True)
            if not ok:
                sys.exit("openfoamCost.py: the %s case on %d rank(s) fails "
                         "its check (exact specular hits%s)" % (
                             MESH_NAMES[boxes], np,
                             "; one box per rank, no transfers"
                             if np > 1 else ""))
        smooth_hits = specular_hits(
            positions, travel_time(runner.platform, end_time), boxes)
        runs = [(np, v) for np in ranks for v in runner.variants]
        for rnd in range(args.rounds):
            for np, variant in (runs if rnd % 2 == 0 else runs[::-1]):
                r = run(runner, cases[np], variant)
                hits = r["hits"] if MODEL_FILE[variant] == "rough" \
                    else smooth_hits
                row = dict(platform=runner.platform.name, tag=runner.tag,
                           baseline=bc.portable_path(runner.baseline)
                           if runner.baseline else "",
                           mesh=MESH_NAMES[boxes], parcels=parcels, np=np,
                           round=rnd, variant=variant, end_time=end_time,
                           steps=r["steps"], hits=hits,
                           step_cpu="%.3f" % r["step_cpu"],
                           wall="%.3f" % r["wall"],
                           process_cpu="%.3f" % r["process_cpu"],
                           load=open("/proc/loadavg").read().split()[0],
                           check=checks.get(np, ""))
                rows.append(row)
                print(row, flush=True)
    bc.write_csv(runner.result("openfoam-cost", "csv"), rows)
    return rows


def callgrind(runner, args):
    """callgrind of a short run of the box with each variant"""
    if not shutil.which("valgrind"):
        print("valgrind not found: no instruction counts")
        return
    work = os.path.abspath(os.path.join(args.work, runner.tag, "callgrind"))
    os.makedirs(work, exist_ok=True)
    parcels, end_time = args.callgrind_parcels, args.callgrind_end_time
    case, positions = make_case(runner, work, parcels, 1, end_time)
    specular = specular_hits(positions,
                             travel_time(runner.platform, end_time))
    rows = []
    for variant in runner.variants:
        out = case.file("callgrind.%s.out" % variant)
        shutil.copy(case.file("constant/wallModel." + MODEL_FILE[variant]),
                    case.file("constant/wallModel"))
        with library_path(runner.library_dirs(variant)):
            case.run(["valgrind", "--tool=callgrind",
                      "--callgrind-out-file=" + out, case.solver],
                     "log.callgrind." + variant, timeout=3600)
        steps = case.read_steps("log.callgrind." + variant)
        hits = steps[-1]["hits"] if MODEL_FILE[variant] == "rough" else specular
        total, calls, parts, callees = callgrind_profile(
            out, MODEL_ENTRY[variant])
        row = dict(platform=runner.platform.name, tag=runner.tag,
                   baseline=bc.portable_path(runner.baseline)
                   if runner.baseline else "",
                   variant=variant, parcels=parcels, end_time=end_time,
                   hits=hits, total=total, correct_calls=calls,
                   correct_inclusive=int(sum(parts.values())))
        for p, x in parts.items():
            row["part: " + p] = int(round(x))
        rows.append(row)
        print({k: v for k, v in row.items() if not k.startswith("part")},
              flush=True)
        os.remove(out)
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    for r in rows:
        for k in keys:
            r.setdefault(k, 0)
    bc.write_csv(runner.result("openfoam-callgrind", "csv"), rows)
    callgrind_table(runner.tag, rows)


def profile(runner, args):
    """perf (software clock) profiles of the rough and the standard run of
    the middle parcel count: where the extra time of the rough wall goes,
    and the time per wall hit in the models' own code (their share of the
    samples times the run's CPU time over its hits)"""
    if not shutil.which("perf"):
        print("perf not found: no profile")
        return
    work = os.path.abspath(os.path.join(args.work, runner.tag, "profile"))
    os.makedirs(work, exist_ok=True)
    parcels = args.parcels[min(1, len(args.parcels) - 1)]
    end_time = max(args.end_time, args.parcel_seconds/parcels)
    case, positions = make_case(runner, work, parcels, 1, end_time)
    summary = []
    for variant in ("rough", "standard"):
        shutil.copy(case.file("constant/wallModel." + variant),
                    case.file("constant/wallModel"))
        data = case.file("perf.%s.data" % variant)
        log = "log.perf." + variant
        with library_path(runner.library_dirs(variant)):
            case.run(["perf", "record", "-e", "cpu-clock", "-F", "2000",
                      "-o", data, case.solver], log)
        out = []
        for sort in ("dso", "sym"):
            out.append(subprocess.run(
                ["perf", "report", "-i", data, "--stdio", "--no-children",
                 "--sort", sort, "--percent-limit", "0.5"],
                capture_output=True, text=True).stdout)
        path = os.path.join(bc.RESULTS, "openfoam-profile-%s.%s.txt"
                            % (variant, runner.tag))
        with open(path, "w") as f:
            f.write("# perf record -e cpu-clock %s, %d parcels, %s, %s\n"
                    % (case.solver, parcels, variant, runner.tag))
            f.write("\n".join(out))
        print("wrote " + path)
        steps = case.read_steps(log)
        cpu = steps[-1]["executionTime"]
        hits = steps[-1]["hits"] if variant == "rough" else specular_hits(
            positions, travel_time(runner.platform, end_time))
        shares = perf_shares(data)
        model = sum(p for p, dso, sym in shares
                    if PROFILE_MODEL[variant](dso, sym))
        patch = sum(p for p, dso, sym in shares if "::patchData(" in sym)
        summary.append(dict(variant=variant, hits=hits, cpu=cpu,
                            model_percent=model, patchData_percent=patch,
                            model_ns=model/100*cpu/hits*1e9,
                            patchData_ns=patch/100*cpu/hits*1e9))
    lines = ["%s (%s), perf record -e cpu-clock -F 2000 of `%s`, the box "
             "with %d parcels, %g s (`%s`, its `--profile` step): the "
             "models' own code per wall hit = its share of the samples x "
             "the run's CPU time (last ExecutionTime) / the run's wall "
             "hits." % (PLATFORM_NAMES[runner.platform.name], runner.tag,
                        case.solver, parcels, end_time,
                        command_of(runner.tag, runner.platform.name)), "",
             "| variant | wall hits | CPU [s] | model's own code: share, "
             "ns per hit | patchData (OpenFOAM, both): share, ns per hit |",
             "|---|---|---|---|---|"]
    for r in summary:
        lines.append("| %s | %d | %.2f | %.1f %%, %.0f | %.1f %%, %.0f |" % (
            r["variant"], r["hits"], r["cpu"], r["model_percent"],
            r["model_ns"], r["patchData_percent"], r["patchData_ns"]))
    lines += ["", "rough: all of libroughWallInteraction.so (the adapter and "
              "the core, inlined into it)%s; standard: "
              "StandardWallInteraction::correct." % (
                  " and OpenFOAM's Random::sample01 it calls"
                  if not runner.platform.foundation else ""),
              "Extra per rough hit in the models' own code: %.0f ns." % (
                  summary[0]["model_ns"] - summary[1]["model_ns"])]
    text = "\n".join(lines) + "\n"
    with open(os.path.join(bc.RESULTS, "openfoam-profile.%s.md"
                           % runner.tag), "w") as f:
        f.write(text)
    print(text)


def tutorial_measure(args):
    """Rounds of the TUTORIAL_VARIANTS, each run by the tutorial's Allrun
    (foamcase.bench.run_tutorial: one variant, -jobs 1, serial: the
    tutorial has no parallel option), the order reversed every other round;
    returns the rows"""
    bc.write_machine(tutorial_stem(args.tag))
    work = os.path.abspath(os.path.join(args.work, "tutorial"))
    os.makedirs(work, exist_ok=True)
    tut = bc.prepare_tutorial(work)
    # The tutorial's own 3 s spin-up: the beads are spread over the channel
    # as in its results, not still falling or dispersing
    parcels, spin_up, sampling = (500, 0.2, 0.2) if args.quick \
        else (4000, 3.0, 1.0)
    # variant: (the tutorial's wall model, directories first on
    # LD_LIBRARY_PATH; the Allrun runs in this environment)
    variants = {v: (v, []) for v in TUTORIAL_VARIANTS}
    if args.baseline_lib:
        variants[TUTORIAL_BASE] = ("rough2.5",
                                   [os.path.abspath(args.baseline_lib)])
    if args.variant_lib_path:
        # other OpenFOAM libraries: standard and rough2.5 with and without
        dirs = [os.path.abspath(d) for d in args.variant_lib_path]
        variants = {v: (v.replace(".lib", ""), dirs if ".lib" in v else [])
                    for v in ("standard", "rough2.5") + TUTORIAL_LIB_VARIANTS}
    order = list(variants)
    rows = []
    for rnd in range(args.rounds):
        for variant in (order if rnd % 2 == 0 else order[::-1]):
            name = "cost-%s-%d" % (variant, rnd)
            config, dirs = variants[variant]
            with library_path(dirs):
                summary, _ = bc.run_tutorial(tut, args.platform, name, config,
                                           parcels, spin_up, sampling, 1e-3)
            row = dict(platform=args.platform, round=rnd, variant=variant,
                       parcels=parcels,
                       spin_up=spin_up, sampling=sampling,
                       cpu="%.2f" % float(summary["cpuTime"]),
                       wall="%.2f" % float(summary["wallClock"]),
                       hits_lower=summary.get(
                           "hitsPerParcelPerMetre_lowerWall", ""),
                       upperFraction=summary["upperFraction"],
                       baseline=baseline_name(args.baseline_lib)
                       if variant == TUTORIAL_BASE else "",
                       lib_path=":".join(bc.portable_path(d)
                                         for d in variants[variant][1]),
                       load=open("/proc/loadavg").read().split()[0])
            rows.append(row)
            print(row, flush=True)
    bc.write_csv(tutorial_stem(args.tag) + ".csv", rows)
    return rows, tut
