#!/usr/bin/python3
# roughWallInteraction benchmarks: end-to-end cost of the rough-wall model in
# OpenFOAM against OpenFOAM's own standardWallInteraction.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""The same case, the same parcels and time steps, run with
  standard  standardWallInteraction (rebound, e = 1, mu = 0)
  rebound   roughWallInteraction, patch type rebound (e = 1, mu = 0):
            the adapter without the rough physics
  rough     roughWallInteraction, patch type rough (e = 1, mu0 = muD = 0,
            Delta = 8 deg): kinetic energy is kept, as in the smooth box
alternated round after round in one script (so that a drift of the machine
load hits every variant alike). Case: benchmarks/openfoam/wallBox, ballistic
parcels (no forces, no gravity, 110 um glass) in a closed 0.1 m box of 2x1x1
cells with maxCo 1, injected at (40 27 13) m/s, icoUncoupledKinematicParcelFoam
(colliding cloud: spin is carried), dt = 1 ms: about 0.8 wall hits per parcel
and time step, the most wall-dominated a particle case gets. Simulated time
0.2 s, or 4000 parcel-seconds over the parcels if that is longer (1000
parcels: 4 s), so that every run takes seconds.

Measured per run: the solver's CPU time for the time steps (the last
ExecutionTime minus the first: start-up and mesh reading excluded), the wall
clock of the whole process, and the wall hits (rough: the model's own count;
standard and rebound: counted exactly from the positions, the velocity and
the box, since specular reflection in a box is an unfolding). Writes
benchmarks/results/openfoam-cost.csv, openfoam-cost.md and
docs/figures/bench-openfoam-scaling.png.
"""
import argparse
import csv
import math
import os
import random
import re
import resource
import shutil
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchCommon as bc  # noqa: E402

TEMPLATE = os.path.join(bc.ROOT, "benchmarks", "openfoam", "wallBox")
SOLVER = "icoUncoupledKinematicParcelFoam"
L = 0.1
U0 = (40.0, 27.0, 13.0)
VARIANTS = ("standard", "rebound", "rough")


def sh(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as f:
        subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT,
                       check=True)


def make_case(work, parcels, np, end_time, seed=1):
    """A case directory for `parcels` parcels on `np` processors"""
    case = os.path.join(work, "box-n%d-np%d" % (parcels, np))
    if os.path.isdir(case):
        shutil.rmtree(case)
    shutil.copytree(TEMPLATE, case)
    rng = random.Random(seed)
    positions = [tuple(0.005 + 0.09*rng.random() for _ in range(3))
                 for _ in range(parcels)]
    with open(os.path.join(case, "constant", "positions"), "w") as f:
        f.write('FoamFile { version 2.0; format ascii; class vectorField; '
                'location "constant"; object positions; }\n')
        f.write("%d\n(\n" % parcels)
        for p in positions:
            f.write("(%.9f %.9f %.9f)\n" % p)
        f.write(")\n")
    control = os.path.join(case, "system", "controlDict")
    text = open(control).read()
    text = re.sub(r"\nendTime\s+[^;]+;", "\nendTime         %g;" % end_time,
                  text)
    open(control, "w").write(text)
    sh(["blockMesh"], case, "log.blockMesh")
    if np > 1:
        sh(["decomposePar", "-force"], case, "log.decomposePar")
    return case, positions


def specular_hits(positions, end_time):
    """Wall hits of specular parcels in the box [0, L]^3 up to end_time"""
    return sum(int(math.floor((p[i] + U0[i]*end_time)/L))
               for p in positions for i in range(3))


def run(case, variant, np):
    shutil.copy(os.path.join(case, "constant", "wallModel." + variant),
                os.path.join(case, "constant", "wallModel"))
    if np > 1:
        # processor directories read constant/ from the case
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np",
               str(np), SOLVER, "-parallel"]
    else:
        cmd = [SOLVER]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    sh(cmd, case, "log.%s" % variant)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime
                                                - before.ru_stime)
    log = open(os.path.join(case, "log.%s" % variant)).read()
    exec_times = [float(x) for x in
                  re.findall(r"ExecutionTime = ([0-9.eE+-]+) s", log)]
    hits = re.findall(r"- hits\s+= (\d+)", log)
    return dict(step_cpu=exec_times[-1] - exec_times[0], wall=wall,
                process_cpu=cpu, hits=int(hits[-1]) if hits else None)


def profile(args):
    """perf (software clock) profiles of the rough and the standard run of
    the middle parcel count: where the extra time of the rough wall goes"""
    if not shutil.which("perf"):
        print("perf not found: no profile")
        return
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    parcels = args.parcels[min(1, len(args.parcels) - 1)]
    case, _ = make_case(work, parcels, 1, args.end_time)
    for variant in ("rough", "standard"):
        shutil.copy(os.path.join(case, "constant", "wallModel." + variant),
                    os.path.join(case, "constant", "wallModel"))
        data = os.path.join(case, "perf.%s.data" % variant)
        sh(["perf", "record", "-e", "cpu-clock", "-F", "2000", "-o", data,
            SOLVER], case, "log.perf." + variant)
        out = []
        for sort in ("dso", "sym"):
            out.append(subprocess.run(
                ["perf", "report", "-i", data, "--stdio", "--no-children",
                 "--sort", sort, "--percent-limit", "0.5"],
                capture_output=True, text=True).stdout)
        path = os.path.join(bc.RESULTS, "openfoam-profile-%s.txt" % variant)
        with open(path, "w") as f:
            f.write("# perf record -e cpu-clock %s, %d parcels, %s\n"
                    % (SOLVER, parcels, variant))
            f.write("\n".join(out))
        print("wrote " + path)


def tutorial_cost(args):
    """The tutorial's short case with the smooth (standardWallInteraction)
    and a rough wall model, same parcels and time steps, alternated"""
    import tutorialWorkPrecision as tw
    work = os.path.abspath(os.path.join(args.work, "tutorial"))
    os.makedirs(work, exist_ok=True)
    tut, carrier_time, height = tw.prepare(work)
    parcels, spin_up, end_time = (500, 0.2, 0.4) if args.quick \
        else (4000, 1.0, 2.0)
    rows = []
    for rnd in range(args.rounds if not args.quick else 2):
        order = ("smooth", "rough2.5") if rnd % 2 == 0 \
            else ("rough2.5", "smooth")
        for variant in order:
            wall, _, summary, _ = tw.run_case(
                tut, carrier_time, height, "cost-%s" % variant, variant,
                195e-6, parcels, spin_up, end_time, 1e-3)
            case = os.path.join(tut, "run", "cost-%s" % variant)
            log = open(os.path.join(case, "log." + SOLVER)).read()
            exec_times = [float(x) for x in re.findall(
                r"ExecutionTime = ([0-9.eE+-]+) s", log)]
            hits = sum(int(h) for h in re.findall(
                r"- hits\s+= (\d+)", log.split("ExecutionTime")[-2]))
            row = dict(round=rnd, variant=variant, parcels=parcels,
                       end_time=end_time, wall="%.2f" % wall,
                       step_cpu="%.2f" % (exec_times[-1] - exec_times[0]),
                       model_hits=hits,
                       upperFraction=summary["upperFraction"],
                       load=open("/proc/loadavg").read().split()[0])
            rows.append(row)
            print(row, flush=True)
    with open(os.path.join(bc.RESULTS, "openfoam-tutorial-cost.csv"), "w",
              newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    ratios = []
    for rnd in sorted({r["round"] for r in rows}):
        t = {r["variant"]: float(r["step_cpu"]) for r in rows
             if r["round"] == rnd}
        ratios.append(t["rough2.5"]/t["smooth"])
    med = {v: statistics.median(float(r["step_cpu"]) for r in rows
                                if r["variant"] == v)
           for v in ("smooth", "rough2.5")}
    text = ("Tutorial (195 um, %d parcels, %g s, dt = 1 ms, %d rounds): CPU "
            "time of the time steps, median: smooth %.2f s, rough2.5 %.2f s; "
            "rough/smooth per round: median %.3f (%.3f-%.3f)\n" % (
                parcels, end_time, len(ratios), med["smooth"],
                med["rough2.5"], statistics.median(ratios), min(ratios),
                max(ratios)))
    with open(os.path.join(bc.RESULTS, "openfoam-tutorial-cost.md"),
              "w") as f:
        f.write(text)
    print(text)
    # The model's own share of the rough run: a perf profile of one more run
    if shutil.which("perf"):
        case = os.path.join(tut, "run", "cost-rough2.5")
        data = os.path.join(case, "perf.data")
        sh(["perf", "record", "-e", "cpu-clock", "-F", "1000", "-o", data,
            SOLVER], case, "log.perf")
        out = [subprocess.run(
            ["perf", "report", "-i", data, "--stdio", "--no-children",
             "--sort", sort, "--percent-limit", "0.3"],
            capture_output=True, text=True).stdout for sort in ("dso", "sym")]
        path = os.path.join(bc.RESULTS, "openfoam-tutorial-profile-rough.txt")
        with open(path, "w") as f:
            f.write("# perf record -e cpu-clock %s: tutorial, rough2.5, %d "
                    "parcels, %g s\n" % (SOLVER, parcels, end_time))
            f.write("\n".join(out))
        print("wrote " + path)


def measure(args):
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    rows = []
    configs = [(n, 1) for n in args.parcels] + [
        (args.parcels[min(1, len(args.parcels) - 1)], 2)] * args.mpi
    for parcels, np in configs:
        # at least parcel_seconds of parcel time per run: small runs long
        # enough for the 0.01 s resolution of ExecutionTime
        end_time = max(args.end_time, args.parcel_seconds/parcels)
        case, positions = make_case(work, parcels, np, end_time)
        smooth_hits = specular_hits(positions, end_time)
        for rnd in range(args.rounds):
            order = VARIANTS if rnd % 2 == 0 else VARIANTS[::-1]
            for variant in order:
                r = run(case, variant, np)
                hits = r["hits"] if variant == "rough" else smooth_hits
                row = dict(parcels=parcels, np=np, round=rnd,
                           variant=variant, end_time=end_time, hits=hits,
                           step_cpu="%.3f" % r["step_cpu"],
                           wall="%.3f" % r["wall"],
                           process_cpu="%.3f" % r["process_cpu"],
                           load=open("/proc/loadavg").read().split()[0])
                rows.append(row)
                print(row, flush=True)
    with open(os.path.join(bc.RESULTS, "openfoam-cost.csv"), "w",
              newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


def load():
    with open(os.path.join(bc.RESULTS, "openfoam-cost.csv")) as f:
        return list(csv.DictReader(f))


def summarise(rows):
    """Per (parcels, np): medians per variant and paired ratios per round"""
    groups = {}
    for r in rows:
        groups.setdefault((int(r["parcels"]), int(r["np"])), []).append(r)
    out = []
    for (parcels, np), rs in sorted(groups.items()):
        med = {}
        for v in VARIANTS:
            vs = [r for r in rs if r["variant"] == v]
            if not vs:
                continue
            med[v] = dict(
                step_cpu=statistics.median(float(r["step_cpu"]) for r in vs),
                wall=statistics.median(float(r["wall"]) for r in vs),
                hits=int(vs[0]["hits"]))
        rounds = sorted({r["round"] for r in rs})
        ratios, ratios_rebound = [], []
        for rnd in rounds:
            t = {r["variant"]: float(r["step_cpu"]) for r in rs
                 if r["round"] == rnd}
            if t.get("standard", 0) > 0:
                ratios.append(t["rough"]/t["standard"])
                ratios_rebound.append(t["rebound"]/t["standard"])
        out.append(dict(parcels=parcels, np=np, med=med, rounds=len(rounds),
                        end_time=float(rs[0].get("end_time", "nan")),
                        ratio=statistics.median(ratios),
                        ratio_min=min(ratios), ratio_max=max(ratios),
                        ratio_rebound=statistics.median(ratios_rebound)))
    return out


def table(summary):
    lines = ["| parcels | simulated s | MPI ranks | rounds | standard: CPU s, hits, Mhits/s"
             " | rebound: CPU s | rough: CPU s, hits, Mhits/s | rough/standard"
             " CPU (median, min-max of rounds) | rebound/standard | rough - "
             "standard per hit [ns] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for s in summary:
        m = s["med"]
        st, rb, ro = m["standard"], m["rebound"], m["rough"]
        extra = (ro["step_cpu"]/ro["hits"] - st["step_cpu"]/st["hits"])*1e9
        lines.append(
            "| %d | %g | %d | %d | %.2f, %d, %.2f | %.2f | %.2f, %d, %.2f | "
            "%.3f (%.3f-%.3f) | %.3f | %.0f |" % (
                s["parcels"], s["end_time"], s["np"], s["rounds"],
                st["step_cpu"],
                st["hits"], st["hits"]/st["step_cpu"]/1e6, rb["step_cpu"],
                ro["step_cpu"], ro["hits"], ro["hits"]/ro["step_cpu"]/1e6,
                s["ratio"], s["ratio_min"], s["ratio_max"],
                s["ratio_rebound"], extra))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(bc.RESULTS, "openfoam-cost.md"), "w") as f:
        f.write(text)
    print(text)


def figure(summary):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    serial = [s for s in summary if s["np"] == 1]
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    n = [s["parcels"] for s in serial]
    for v, c in zip(VARIANTS, ("k", "C1", "C0")):
        axes[0].loglog(n, [s["med"][v]["hits"]/s["med"][v]["step_cpu"]
                           for s in serial], "o-", color=c, label=v)
    for s in summary:
        if s["np"] > 1:
            for v, c in zip(VARIANTS, ("k", "C1", "C0")):
                axes[0].plot(s["parcels"], s["med"][v]["hits"]
                             / s["med"][v]["step_cpu"], "s", mfc="none",
                             color=c, ms=9)
    axes[0].set_xlabel("parcels")
    axes[0].set_ylabel("wall hits per CPU second")
    axes[0].set_title("throughput; squares: 2 MPI ranks, per second of\n"
                      "rank 0's CPU time (about elapsed: MPI polls)",
                      fontsize=9)
    axes[0].legend(fontsize=8)
    axes[0].grid(True, which="both", alpha=0.3)
    axes[1].errorbar(n, [s["ratio"] for s in serial],
                     yerr=[[s["ratio"] - s["ratio_min"] for s in serial],
                           [s["ratio_max"] - s["ratio"] for s in serial]],
                     fmt="o-", color="C0", capsize=3,
                     label="rough / standard (bars: min-max of rounds)")
    axes[1].set_xscale("log")
    axes[1].semilogx(n, [s["ratio_rebound"] for s in serial], "o-",
                     color="C1", label="rebound (adapter) / standard")
    axes[1].axhline(1.05, color="r", lw=1, label="target +5 %")
    axes[1].set_xlabel("parcels")
    axes[1].set_ylabel("CPU time ratio (paired rounds, median)")
    axes[1].legend(fontsize=8)
    axes[1].grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    path = os.path.join(bc.FIGURES, "bench-openfoam-scaling.png")
    fig.savefig(path, dpi=110)
    print("wrote " + path)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--work", default=os.path.join(bc.ROOT, "build",
                                                  "benchmarks", "openfoam"))
    p.add_argument("--parcels", default="1000,10000,100000")
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--end-time", type=float, default=0.2,
                   help="simulated time, at least (see --parcel-seconds)")
    p.add_argument("--parcel-seconds", type=float, default=4000,
                   help="end time at least this over the parcels")
    p.add_argument("--mpi", type=int, default=1,
                   help="also run the middle parcel count on 2 ranks (0: no)")
    p.add_argument("--quick", action="store_true")
    p.add_argument("--profile", action="store_true",
                   help="only: perf profiles of the rough and standard runs")
    p.add_argument("--tutorial", action="store_true",
                   help="only: the tutorial's short case, smooth against "
                   "rough2.5, alternated")
    p.add_argument("--plot-only", action="store_true")
    args = p.parse_args()
    args.parcels = [int(float(x)) for x in args.parcels.split(",")]
    if args.quick:
        args.parcels, args.rounds, args.end_time = [500, 5000], 2, 0.05
        args.parcel_seconds = 0
    bc.ensure_dirs()
    if args.profile:
        profile(args)
        return
    if args.tutorial:
        tutorial_cost(args)
        return
    if not args.plot_only:
        if "WM_PROJECT_DIR" not in os.environ:
            sys.exit("openfoamCost.py: source etc/setup first")
        info = bc.write_machine("openfoam-cost")
        print(bc.machine_markdown(info))
        measure(args)
    summary = summarise(load())
    table(summary)
    figure(summary)


if __name__ == "__main__":
    main()
