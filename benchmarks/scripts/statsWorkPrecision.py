#!/usr/bin/python3
# roughWallInteraction benchmarks: work-precision of roughWallStats,
# quadrature against Monte Carlo (figure 2 of docs/benchmarks.md).
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Error of the restitution statistics against the run time of
bin/roughWallStats: --method quadrature as --tolerance goes from 1e-3 to
1e-13, --method montecarlo as --samples goes from 1e2 to 1e6 per angle
(several seeds; 1e7 with --max-samples 1e7). Reference: quadrature at
--tolerance 1e-14, the tightest the tool allows. One thread, the 89
incidence angles 1, 2, .., 89 deg, the paper's glass-on-steel parameters
(Delta = 8 deg, e = 0.8, mu0 = muD = 0.4). Every run prints 17 significant
digits (--digits 17): the doubles themselves, so the only floor is round-off,
1 ulp of the values (the 'roundoff' row: the spacing of doubles at the
largest reference value over the angles, per statistic).
Time: wall clock of the whole process, the minimum of several runs; the
start-up floor (the same process doing no angle work) is measured and
reported. Writes benchmarks/results/stats-work-precision.csv, stats.md and
docs/figures/bench-stats-work-precision.png.
"""
import argparse
import csv
import io
import math
import os
import subprocess
import time

from foamcase import bench as bc
import foamcase as fc

ALPHAS = "1:1:89"
DIGITS = "17"      # every double exactly: no printing floor
STATS = [("mean_kn", "mean k_n"), ("sd_kn", "sd k_n"),
         ("mean_kt", "mean k_t"), ("p_noslip", "P(no slip)")]


def run(tool, args, repeats):
    """(rows, best wall time) of roughWallStats with args"""
    best = float("inf")
    out = ""
    for _ in range(repeats):
        start = time.perf_counter()
        out = subprocess.run([tool, "--alpha", ALPHAS, "--threads", "1",
                              "--digits", DIGITS]
                             + args, check=True, capture_output=True,
                             text=True).stdout
        best = min(best, time.perf_counter() - start)
    return list(csv.DictReader(io.StringIO(out))), best


def errors(rows, ref):
    return {k: max(abs(float(r[k]) - float(q[k])) for r, q in zip(rows, ref))
            for k, _ in STATS}


def roundoff(ref):
    """Per statistic: 1 ulp of the largest reference value over the angles,
    the smallest error the doubles can show there"""
    return {k: max(math.ulp(float(q[k])) for q in ref) for k, _ in STATS}


def measure(args):
    ref, _ = run(args.tool, ["--tolerance", "1e-14"], 1)
    # Start-up floor: one angle at the loosest tolerance
    start = time.perf_counter()
    for _ in range(20):
        subprocess.run([args.tool, "--alpha", "45", "--tolerance", "1e-3",
                        "--threads", "1"], check=True, capture_output=True)
    floor = (time.perf_counter() - start)/20

    rows = [dict(method="roundoff", parameter="1 ulp", seconds="-", seeds=0,
                 **{k: "%.3g" % v for k, v in roundoff(ref).items()})]
    tolerances = [10.0**-k for k in range(3, 14)]
    for tol in tolerances:
        out, seconds = run(args.tool, ["--tolerance", "%g" % tol], 10)
        e = errors(out, ref)
        rows.append(dict(method="quadrature", parameter="%g" % tol,
                         seconds="%.5g" % seconds, seeds=1,
                         **{k: "%.3g" % v for k, v in e.items()}))
        print("quadrature tol %g: %.4f s, error mean_kn %.3g" % (
            tol, seconds, e["mean_kn"]), flush=True)
    top = 4 if args.quick else int(round(math.log10(args.max_samples)))
    for p in range(2, top + 1):
        n = 10**p
        seeds = 4 if p <= 4 else (2 if p == 5 else 1)
        sq = {k: 0.0 for k, _ in STATS}
        total = 0.0
        for seed in range(1, seeds + 1):
            out, seconds = run(args.tool, ["--method", "montecarlo",
                                           "--samples", str(n),
                                           "--seed", str(seed)],
                               1 if p >= 6 else 3)
            total += seconds
            for k, v in errors(out, ref).items():
                sq[k] += v*v
        rows.append(dict(method="montecarlo", parameter=str(n),
                         seconds="%.5g" % (total/seeds), seeds=seeds,
                         **{k: "%.3g" % math.sqrt(v/seeds)
                            for k, v in sq.items()}))
        print("montecarlo %d: %.4f s, error mean_kn %.2g" % (
            n, total/seeds, math.sqrt(sq["mean_kn"]/seeds)), flush=True)
    # The full operator (--recollide) has no quadrature: its cost only
    out, seconds = run(args.tool, ["--method", "montecarlo", "--recollide",
                                   "--samples", "10000"], 3)
    rows.append(dict(method="montecarlo-recollide", parameter="10000",
                     seconds="%.5g" % seconds, seeds=1,
                     **{k: "nan" for k, _ in STATS}))
    bc.write_csv("stats-work-precision.csv", rows)
    with open(os.path.join(bc.RESULTS, "stats-floor.txt"), "w") as f:
        f.write("%.6g\n" % floor)


def load():
    rows = fc.read_csv(bc.result("stats-work-precision.csv"))
    floor = float(open(os.path.join(bc.RESULTS, "stats-floor.txt")).read())
    return rows, floor


def figure(rows, floor):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(STATS), figsize=(15, 3.9))
    ulp = [r for r in rows if r["method"] == "roundoff"]
    for ax, (key, label) in zip(axes, STATS):
        # round-off: 1 ulp of the largest value (results of a 12-digit run
        # have no such row)
        floor_y = float(ulp[0][key]) if ulp else 1e-16
        for method, color, marker, name in (
                ("quadrature", "C0", "o", "quadrature (--tolerance)"),
                ("montecarlo", "C3", "s", "Monte Carlo (--samples)")):
            pts = [r for r in rows if r["method"] == method]
            x = [float(r["seconds"]) for r in pts]
            # 17 printed digits: 0 only for the reference's own doubles,
            # drawn at half an ulp
            y = [max(float(r[key]), floor_y/2) for r in pts]
            ax.loglog(x, y, marker=marker, color=color, label=name)
            for xi, yi, r in zip(x, y, pts):
                if method == "montecarlo" or r["parameter"] in (
                        "0.001", "0.0001", "1e-05", "1e-06", "1e-13"):
                    ax.annotate(r["parameter"], (xi, yi), fontsize=6,
                                textcoords="offset points", xytext=(3, 3))
        ax.axvline(floor, color="grey", lw=0.8, ls=":")
        ax.set_title(label)
        if ulp:
            ax.axhline(floor_y, color="grey", lw=0.8, ls="--",
                       label="round-off: 1 ulp of the largest value")
        ax.set_xlabel("wall time, 89 angles, 1 thread [s]")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("max over alpha of |error| (vs tolerance 1e-14)")
    axes[0].legend(fontsize=7, loc="center right", bbox_to_anchor=(1, 0.6))
    fig.tight_layout()
    path = os.path.join(bc.FIGURES, "bench-stats-work-precision.png")
    fig.savefig(path, dpi=100)
    print("wrote " + path)


def table(rows, floor):
    out = ["Start-up floor of the process (one angle, loosest "
           "tolerance): %.1f ms. Errors are the largest over the 89 angles, "
           "of numbers printed with 17 significant digits (the doubles "
           "exactly); roundoff: 1 ulp of the largest reference value, the "
           "smallest nonzero error there.\n" % (1e3*floor),
           "| method | tolerance / samples per angle | wall time [s] | "
           + " | ".join("error %s" % label for _, label in STATS) + " |",
           "|---|---|---|" + "---|"*len(STATS)]
    for r in rows:
        out.append("| %s | %s | %s | %s |" % (
            r["method"], r["parameter"], r["seconds"],
            " | ".join(r[k] for k, _ in STATS)))
    text = "\n".join(out) + "\n"
    with open(os.path.join(bc.RESULTS, "stats.md"), "w") as f:
        f.write(text)
    print(text)


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--tool", default=os.path.join(bc.ROOT, "bin",
                                                  "roughWallStats"))
    p.add_argument("--quick", action="store_true")
    p.add_argument("--max-samples", type=float, default=1e6,
                   help="largest Monte Carlo sample count per angle")
    p.add_argument("--plot-only", action="store_true")
    args = p.parse_args()
    bc.ensure_dirs()
    if not args.plot_only:
        info = bc.write_machine("stats")
        print(bc.machine_markdown(info))
        measure(args)
    rows, floor = load()
    figure(rows, floor)
    table(rows, floor)


if __name__ == "__main__":
    main()
