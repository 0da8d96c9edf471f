#!/usr/bin/python3
# roughWallInteraction benchmarks: cost of one wall hit in the core.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Per-hit cost of collideWithRoughWall against a smooth-wall rebound.

Runs benchRoughWallCore (Google Benchmark; the median CPU time of the
repetitions), writes benchmarks/results/hit-cost.{json,csv,md} and
docs/figures/bench-hit-cost.png. With --instructions it also counts the
instructions per hit under callgrind (hitLoop at two hit counts; needs
valgrind) into benchmarks/results/hit-instructions.{csv,md}.
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess

from foamcase import bench as bc
import foamcase as fc

TARGET_NS = 60
CONFIGS = [  # (label, spin, lateral, dim)
    ("3-D, spin", "1", "0", "3"),
    ("3-D, spin, lateral tilt", "1", "1", "3"),
    ("3-D, no spin", "0", "0", "3"),
    ("2-D, no spin", "0", "0", "2"),
]
ALPHAS = ["mix", "1", "5", "15", "45", "85"]
DELTAS = ["0", "2", "8", "20", "45"]
# The core before the speed work of issue 7 (libm's atan2/sincos/log1p,
# Box-Muller proposals, a second normalisation of the tangent), measured at
# commit 22b71b2 (on the machine its hit-cost.machine.json names) and kept
# for the comparison
BASELINE = "baseline-beforeSpeedWork"


def alpha_label(a):
    return "U(0, 90)" if a == "mix" else a


def measure(args):
    runs = bc.run_google_benchmark(
        args.bench, "^(hit|uniform01)/", args.min_time, args.repetitions,
        os.path.join(bc.RESULTS, "hit-cost.json"))
    rows = []
    for name, r in runs.items():
        f = bc.parse_name(name)
        rows.append(dict(
            name=name, kind=f["kind"], model=f.get("model", ""),
            spin=f.get("spin", ""), lateral=f.get("lateral", ""),
            dim=f.get("dim", ""), alpha=f.get("alpha", ""),
            Delta=f.get("Delta", ""), rng=f.get("rng", ""),
            ns_per_hit="%.4g" % r["cpu_ns"],
            stddev_ns="%.2g" % r["stddev_ns"],
            facetCollisions="%.5g" % r.get("facetCollisions", float("nan")),
            fallbacks="%.3g" % r.get("fallbacks", float("nan"))))
    bc.write_csv("hit-cost.csv", rows)
    return rows


def load():
    return fc.read_csv(bc.result("hit-cost.csv"))


def baseline(filename, key):
    """The stored results of the earlier core, indexed by key"""
    path = os.path.join(bc.RESULTS, BASELINE, filename)
    if not os.path.exists(path):
        return {}
    return {r[key]: r for r in fc.read_csv(bc.result(path))
            if r.get("model", "rough") == "rough"}


def index(rows):
    table = {}
    for r in rows:
        table[r["name"]] = r
    return table


def ns(table, name):
    r = table.get(name)
    return float(r["ns_per_hit"]) if r else float("nan")


def rough_name(spin, lateral, dim, alpha, Delta, rng="foam", model="rough"):
    return ("hit/model:%s/spin:%s/lateral:%s/dim:%s/alpha:%s/Delta:%s/"
            "rng:%s" % (model, spin, lateral, dim, alpha, Delta, rng))


def smooth_name(spin, dim, alpha):
    return "hit/model:smooth/spin:%s/dim:%s/alpha:%s/rng:none" % (
        spin, dim, alpha)


def markdown(rows, machine):
    t = index(rows)
    out = []
    out.append("Median CPU time per hit [ns] (Google Benchmark); smooth = "
               "`collideWithFacet` with the mean-wall normal and the same "
               "friction law; ratio = rough/smooth; facet collisions per hit "
               "in brackets.\n")
    out.append("Incidence alpha ~ U(0, 90 deg), glass on steel (e = 0.8, "
               "mu0 = muD = 0.4):\n")
    out.append("| configuration | smooth | " + " | ".join(
        "Delta = %s deg" % d for d in DELTAS) + " |")
    out.append("|---|---|" + "---|"*len(DELTAS))
    for label, spin, lateral, dim in CONFIGS:
        smooth = ns(t, smooth_name(spin, dim, "mix"))
        cells = []
        for d in DELTAS:
            r = t.get(rough_name(spin, lateral, dim, "mix", d))
            if not r:
                cells.append("-")
                continue
            v = float(r["ns_per_hit"])
            cells.append("%.0f (x%.1f) [%.3f]" % (
                v, v/smooth, float(r["facetCollisions"])))
        out.append("| %s | %.1f | %s |" % (label, smooth, " | ".join(cells)))
    smooth = ns(t, smooth_name("1", "3", "mix"))
    cells = []
    for d in DELTAS:
        r = t.get(rough_name("1", "0", "3", "mix", d, "foam13"))
        if not r:
            cells.append("-")
            continue
        v = float(r["ns_per_hit"])
        cells.append("%.0f (x%.1f) [%.3f]" % (v, v/smooth,
                                              float(r["facetCollisions"])))
    out.append("| 3-D, spin, OpenFOAM-13's random source | %.1f | %s |"
               % (smooth, " | ".join(cells)))
    std = ns(t, "hit/model:standard/alpha:mix")
    u_foam = ns(t, "uniform01/rng:foam")
    u_foam13 = ns(t, "uniform01/rng:foam13")
    u_mt = ns(t, "uniform01/rng:mt19937")
    out.append("\nRandom source: v1912's `Random` (Rand48 through "
               "`uniform_real_distribution`, what the model draws from on "
               "v1912) in every row but the last, OpenFOAM-13's "
               "`randomGenerator::scalar01()` in the last. "
               "OpenFOAM's StandardWallInteraction rebound arithmetic: "
               "%.1f ns per hit. One uniform draw: %.1f ns (v1912's Random), "
               "%.1f ns (OpenFOAM-13's randomGenerator), %.1f ns "
               "(mt19937_64)." % (std, u_foam, u_foam13, u_mt))
    mt = ns(t, rough_name("1", "0", "3", "mix", "8", "mt19937"))
    out.append("3-D with spin at Delta = 8 deg with mt19937_64 instead of "
               "Rand48: %.0f ns.\n" % mt)

    base = baseline("hit-cost.csv", "name")
    if base:
        try:
            with open(os.path.join(bc.RESULTS, BASELINE,
                                   "hit-cost.machine.json")) as f:
                where = "on an %s" % json.load(f)["Model name"]
        except (OSError, KeyError, ValueError):
            where = "on a machine not recorded"
        out.append("Against the core before the speed work (commit 22b71b2, "
                   "measured then %s: %s; the factors include the change of "
                   "machine), alpha ~ U(0, 90 deg) [ns per hit, before -> "
                   "now (speed-up)]:\n" % (where, BASELINE))
        out.append("| configuration | " + " | ".join(
            "Delta = %s deg" % d for d in DELTAS) + " |")
        out.append("|---|" + "---|"*len(DELTAS))
        for label, spin, lateral, dim in CONFIGS:
            cells = []
            for d in DELTAS:
                name = rough_name(spin, lateral, dim, "mix", d)
                a, b = ns(base, name), ns(t, name)
                cells.append("%.0f -> %.0f (x%.2f)" % (a, b, a/b))
            out.append("| %s | %s |" % (label, " | ".join(cells)))
        out.append("")

    out.append("By incidence angle, 3-D with spin [ns per hit]:\n")
    out.append("| alpha [deg] | smooth | " + " | ".join(
        "Delta = %s" % d for d in DELTAS) + " |")
    out.append("|---|---|" + "---|"*len(DELTAS))
    for a in ALPHAS:
        smooth = ns(t, smooth_name("1", "3", a))
        out.append("| %s | %.1f | %s |" % (alpha_label(a), smooth, " | ".join(
            "%.0f" % ns(t, rough_name("1", "0", "3", a, d)) for d in DELTAS)))
    return "\n".join(out) + "\n"


def figure(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    t = index(rows)
    base = baseline("hit-cost.csv", "name")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    colors = ["C0", "C1", "C2", "C3"]
    ax = axes[0]
    Ds = [float(d) for d in DELTAS]
    for (label, spin, lateral, dim), c in zip(CONFIGS, colors):
        ax.plot(Ds, [ns(t, rough_name(spin, lateral, dim, "mix", d))
                     for d in DELTAS], "o-", color=c, label="rough, " + label)
        ax.plot(Ds, [ns(base, rough_name(spin, lateral, dim, "mix", d))
                     for d in DELTAS], "x--", color=c, lw=1)
        ax.axhline(ns(t, smooth_name(spin, dim, "mix")), color=c, ls=":",
                   lw=1)
    ax.axhline(ns(t, "hit/model:standard/alpha:mix"), color="k", ls="--",
               lw=1, label="StandardWallInteraction rebound")
    ax.axhline(TARGET_NS, color="r", lw=1, label="target 60 ns")
    ax.set_yscale("log")
    ax.set_xlabel("roughness angle Delta [deg]")
    ax.set_ylabel("CPU time per wall hit [ns]")
    ax.set_title("alpha ~ U(0, 90 deg); dashed: the core before (22b71b2);\n"
                 "dotted: smooth rebound", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)

    ax = axes[1]
    alphas = [a for a in ALPHAS if a != "mix"]
    x = [float(a) for a in alphas]
    for d, c in zip(DELTAS, ["C7", "C0", "C1", "C2", "C3"]):
        ax.plot(x, [ns(t, rough_name("1", "0", "3", a, d)) for a in alphas],
                "o-", color=c, label="rough, Delta = %s deg" % d)
    ax.plot(x, [ns(t, smooth_name("1", "3", a)) for a in alphas], "s:",
            color="k", label="smooth rebound")
    ax.axhline(TARGET_NS, color="r", lw=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("incidence angle alpha [deg]")
    ax.set_title("3-D, with spin")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    path = os.path.join(bc.FIGURES, "bench-hit-cost.png")
    fig.savefig(path, dpi=110)
    print("wrote " + path)


def collected(hit_loop, argv, hits, rng="foam"):
    out = subprocess.run(
        ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
         hit_loop] + argv + [str(hits), rng],
        capture_output=True, text=True, check=True).stderr
    return int(re.search(r"Collected : (\d+)", out).group(1))


def instruction_row(hit_loop, case):
    """Instructions per hit of hitLoop: the difference of two hit counts.
    case: (model, spin, lateral, dim, alpha, Delta[, rng])"""
    argv, rng = list(case[:6]), (case[6] if len(case) > 6 else "foam")
    n1, n2 = 50000, 150000
    per_hit = (collected(hit_loop, argv, n2, rng)
               - collected(hit_loop, argv, n1, rng))/(n2 - n1)
    print("%s %s: %.1f instructions per hit" % (" ".join(argv), rng,
                                                per_hit), flush=True)
    return dict(model=case[0], spin=case[1], lateral=case[2], dim=case[3],
                alpha=case[4], Delta=case[5], rng=rng,
                instructions_per_hit="%.1f" % per_hit)


#: The configurations of the side-by-side comparison (--compare)
COMPARE = [(spin, d, rng) for rng in ("foam", "foam13") for d in ("2", "8")
           for spin in ("1",)] + [("0", "8", "foam")]


def compare(args):
    """The core against an earlier build of it (--compare-bench,
    --compare-hit-loop: the same benchmark sources compiled with the earlier
    core headers), side by side: the Google Benchmark of each configuration
    of COMPARE, the two binaries alternated over --rounds rounds (median of
    the rounds), and the instructions per hit of both. Writes
    benchmarks/results/hit-cost-compare.csv and .md"""
    regex = "^(%s)$" % "|".join(
        re.escape(rough_name(spin, "0", "3", "mix", d, rng))
        for spin, d, rng in COMPARE)
    times = {}
    for rnd in range(args.rounds):
        for label, binary in (("before", args.compare_bench),
                              ("after", args.bench))[::1 if rnd % 2 == 0
                                                     else -1]:
            runs = bc.run_google_benchmark(
                binary, regex, args.min_time, 3,
                os.path.join(bc.RESULTS, "hit-cost-compare.json"))
            for name, r in runs.items():
                times.setdefault((label, name), []).append(r["cpu_ns"])
    os.remove(os.path.join(bc.RESULTS, "hit-cost-compare.json"))
    rows = []
    for spin, d, rng in COMPARE:
        name = rough_name(spin, "0", "3", "mix", d, rng)
        case = ("rough", spin, "0", "3", "mix", d, rng)
        row = dict(spin=spin, Delta=d, rng=rng)
        for label, hit_loop in (("before", args.compare_hit_loop),
                                ("after", args.hit_loop)):
            t = times.get((label, name), [])
            row[label + "_ns"] = "%.1f" % statistics.median(t) if t else ""
            row[label + "_ns_rounds"] = " ".join("%.1f" % x for x in t)
            row[label + "_instructions"] = \
                instruction_row(hit_loop, case)["instructions_per_hit"] \
                if hit_loop and shutil.which("valgrind") else ""
        rows.append(row)
    bc.write_csv("hit-cost-compare.csv", rows)
    compare_table(rows, args.rounds)


def compare_table(rows, rounds=None):
    lines = ["Side by side, the core before and after (the same benchmark "
             "sources, the two builds alternated%s; alpha ~ U(0, 90 deg), "
             "3-D; median CPU time per hit of the rounds (range), and "
             "instructions per hit, callgrind of hitLoop):" % (
                 " over %d rounds" % rounds if rounds else ""), "",
             "| spin | Delta [deg] | random source | before [ns] | after "
             "[ns] | after/before | before [instructions] | after "
             "[instructions] |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        b = [float(x) for x in r["before_ns_rounds"].split()]
        a = [float(x) for x in r["after_ns_rounds"].split()]
        lines.append("| %s | %s | %s | %s (%.0f-%.0f) | %s (%.0f-%.0f) | "
                     "%.2f | %s | %s |" % (
                         "yes" if r["spin"] == "1" else "no", r["Delta"],
                         {"foam": "v1912 Random",
                          "foam13": "OpenFOAM-13 randomGenerator"}[r["rng"]],
                         r["before_ns"], min(b), max(b), r["after_ns"],
                         min(a), max(a),
                         float(r["after_ns"])/float(r["before_ns"]),
                         r["before_instructions"], r["after_instructions"]))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(bc.RESULTS, "hit-cost-compare.md"), "w") as f:
        f.write(text)
    print(text)


def instructions(args):
    if not shutil.which("valgrind"):
        print("valgrind not found: no instruction counts")
        return
    cases = [("rough", "1", "0", "3", "mix", d) for d in DELTAS] + [
        ("rough", "1", "0", "3", "mix", d, "foam13") for d in ("2", "8")
    ] + [
        ("rough", s, l, dim, "mix", "8")
        for s, l, dim in (("1", "1", "3"), ("0", "0", "3"), ("0", "0", "2"))
    ] + [
        ("smooth", "1", "0", "3", "mix", "8"),
        ("smooth", "0", "0", "3", "mix", "8"),
        ("standard", "0", "0", "3", "mix", "8"),
        ("none", "1", "0", "3", "mix", "8"),
    ]
    rows = []
    for case in cases:
        rows.append(instruction_row(args.hit_loop, case))
    bc.write_csv("hit-instructions.csv", rows)
    lines = ["| model | spin | lateral | dim | alpha | Delta | random source "
             "| instructions per hit |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s |" % " | ".join(r.values()))
    with open(os.path.join(bc.RESULTS, "hit-instructions.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


def profile(args):
    """Where the time and the instructions of one configuration go: perf
    (software clock) on the Google Benchmark, callgrind on hitLoop"""
    name = "hit/model:rough/spin:1/lateral:0/dim:3/alpha:mix/Delta:8/rng:foam"
    out = []
    if shutil.which("perf"):
        data = os.path.join(bc.RESULTS, "..", "..", "build", "perf.hit.data")
        subprocess.run(["perf", "record", "-e", "cpu-clock", "-F", "10000",
                        "-o", data, args.bench,
                        "--benchmark_filter=^" + name + "$",
                        "--benchmark_min_time=2"], check=True,
                       capture_output=True)
        out.append("# perf record -e cpu-clock: " + name)
        out.append(subprocess.run(
            ["perf", "report", "-i", data, "--stdio", "--no-children",
             "--percent-limit", "0.5"], capture_output=True,
            text=True).stdout)
    if shutil.which("valgrind") and args.hit_loop:
        cg = os.path.join(bc.ROOT, "build", "callgrind.hit")
        subprocess.run(["valgrind", "--tool=callgrind",
                        "--callgrind-out-file=" + cg, args.hit_loop, "rough",
                        "1", "0", "3", "mix", "8", "200000"], check=True,
                       capture_output=True)
        out.append("# callgrind, hitLoop rough 1 0 3 mix 8 200000 "
                   "(inclusive counts; divide by 2e5 for per hit)")
        out.append(subprocess.run(
            ["callgrind_annotate", "--inclusive=yes", cg],
            capture_output=True, text=True).stdout[:12000])
    path = os.path.join(bc.RESULTS, "hit-profile.txt")
    with open(path, "w") as f:
        f.write(bc.portable_text("\n".join(out)))
    print("wrote " + path)


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--bench", required=True, help="benchRoughWallCore")
    p.add_argument("--hit-loop", help="hitLoop (for --instructions)")
    p.add_argument("--min-time", type=float, default=0.2)
    p.add_argument("--repetitions", type=int, default=5)
    p.add_argument("--instructions", action="store_true",
                   help="also count instructions per hit with callgrind")
    p.add_argument("--plot-only", action="store_true",
                   help="redo table and figure from the stored CSV")
    p.add_argument("--profile", action="store_true",
                   help="only: perf and callgrind profiles of one hit")
    p.add_argument("--compare-bench", help="only: side by side with this "
                   "benchRoughWallCore (an earlier core)")
    p.add_argument("--compare-hit-loop", help="--compare-bench: its hitLoop")
    p.add_argument("--rounds", type=int, default=6,
                   help="--compare-bench: rounds of the alternation")
    args = p.parse_args()
    bc.ensure_dirs()
    if args.profile:
        profile(args)
        return
    if args.compare_bench:
        compare(args)
        return
    if args.plot_only:
        rows = load()
    else:
        info = bc.write_machine("hit-cost")
        print(bc.machine_markdown(info))
        rows = measure(args)
    text = markdown(rows, None)
    with open(os.path.join(bc.RESULTS, "hit-cost.md"), "w") as f:
        f.write(text)
    print(text)
    figure(rows)
    if args.instructions:
        instructions(args)


if __name__ == "__main__":
    main()
