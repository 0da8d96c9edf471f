#!/usr/bin/python3
# roughWallInteraction benchmarks: work-precision of the samplers of
# P(gamma, alpha) (figure 1 of docs/benchmarks.md).
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Error against run time of the samplers of the collision-angle
distribution (1.3): the core's exact sampler, inverse-CDF (Newton) sampler,
plain rejection from N(0, Delta), and a no-shadow sampler that is NOT (1.3).

Runs samplerWorkPrecision (error and time per run of N samples) and
benchRoughWallCore's sampler benchmarks (cost per sample, Google Benchmark),
writes benchmarks/results/sampler-work-precision.csv, sampler-cost.csv and
the figures docs/figures/bench-sampler-ks.png, bench-sampler-bias.png and
bench-sampler-cost.png.
"""
import argparse
import math
import os
import subprocess

from foamcase import bench as bc
import foamcase as fc

SAMPLERS = [  # name, label, color, marker
    ("exact", "exact (core sampleFacetAngle)", "C0", "o"),
    ("inversion", "inverse CDF (core, Newton)", "C1", "s"),
    ("rejection", "plain rejection from N(0, Delta)", "C2", "^"),
    ("noShadow", "no shadow: N(0, Delta) redrawn while gamma <= -alpha "
     "(not (1.3))",
     "C3", "x"),
]
H_LABELS = {"0": "0", "0.001": "1e-3", "0.01": "1e-2", "0.1": "1e-1",
            "1": "1", "10": "10", "1000": "1e3", "100000": "1e5"}


def measure(args):
    wp_csv = os.path.join(bc.RESULTS, "sampler-work-precision.csv")
    cmd = [args.work_precision, "--samples", args.samples, "--h", args.h,
           "--budget", str(args.budget)]
    print("+ " + " ".join(cmd), flush=True)
    with open(wp_csv, "w") as f:
        subprocess.run(cmd, check=True, stdout=f)

    runs = bc.run_google_benchmark(
        args.bench, "^sampler/", args.min_time, args.repetitions,
        os.path.join(bc.RESULTS, "sampler-cost.json"))
    rows = []
    for name, r in runs.items():
        f = bc.parse_name(name)
        rows.append(dict(sampler=f["method"], h=f["h"],
                         ns_per_sample="%.4g" % r["cpu_ns"],
                         stddev_ns="%.2g" % r["stddev_ns"],
                         proposals="%.6g" % r.get("proposals", float("nan"))))
    bc.write_csv("sampler-cost.csv", rows)


def load(name):
    return fc.read_csv(bc.result(name))


def hkey(h):
    return "%g" % float(h)


def figures():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    wp = load("sampler-work-precision.csv")
    hs = sorted({hkey(r["h"]) for r in wp}, key=float)

    for quantity, ylabel, fname, expected in (
            ("ks_mean", "Kolmogorov-Smirnov distance to the exact CDF",
             "bench-sampler-ks.png", lambda n, r: 0.8687/math.sqrt(n)),
            ("bias_rms", "RMS of (sample mean - <gamma> of (1.4)) / Delta",
             "bench-sampler-bias.png",
             lambda n, r: float(r["bias_expected"]))):
        ncol = 4
        nrow = math.ceil(len(hs)/ncol)
        fig, axes = plt.subplots(nrow, ncol, figsize=(14, 3.4*nrow),
                                 squeeze=False)
        for ax, h in zip(axes.flat, hs):
            ref_x, ref_y = [], []
            for name, label, color, marker in SAMPLERS:
                pts = [r for r in wp if r["sampler"] == name
                       and hkey(r["h"]) == h and r["status"] == "ok"]
                if not pts:
                    if any(r["sampler"] == name and hkey(r["h"]) == h
                           and r["status"] == "nonterminating" for r in wp):
                        ax.text(0.03, 0.03, "plain rejection: never ends "
                                "(acceptance 0)", transform=ax.transAxes,
                                fontsize=7, color=color)
                    continue
                x = [float(r["seconds_median"]) for r in pts]
                y = [float(r[quantity]) for r in pts]
                ax.loglog(x, y, marker=marker, color=color, label=label)
                if name == "exact":
                    ref_x = x
                    ref_y = [expected(float(r["N"]), r) for r in pts]
                    for xi, yi, r in zip(x, y, pts):
                        ax.annotate("N=%s" % r["N"], (xi, yi), fontsize=6,
                                    textcoords="offset points",
                                    xytext=(3, 3))
            if ref_x:
                ax.loglog(ref_x, ref_y, "k:", lw=1,
                          label="statistical error of an exact sampler")
            ax.set_title("alpha/Delta = %s" % H_LABELS.get(h, h))
            ax.grid(True, which="both", alpha=0.3)
            ax.set_xlabel("run time for N samples [s]")
        for ax in axes[:, 0]:
            ax.set_ylabel(ylabel, fontsize=8)
        for ax in list(axes.flat)[len(hs):]:
            ax.axis("off")
        legend = {}
        for ax in axes.flat:   # every sampler, also those absent at h = 0
            for h_, l_ in zip(*ax.get_legend_handles_labels()):
                legend.setdefault(l_, h_)
        fig.legend(list(legend.values()), list(legend.keys()),
                   loc="lower center", ncol=3, fontsize=8)
        fig.tight_layout(rect=(0, 0.06, 1, 1))
        path = os.path.join(bc.FIGURES, fname)
        fig.savefig(path, dpi=100)
        print("wrote " + path)

    cost = load("sampler-cost.csv")
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for name, label, color, marker in SAMPLERS:
        pts = sorted((float(r["h"]), float(r["ns_per_sample"]))
                     for r in cost if r["sampler"] == name)
        # h = 0 is drawn at the left edge of the log axis
        x = [h if h > 0 else 1e-4 for h, _ in pts]
        ax.loglog(x, [v for _, v in pts], marker=marker, color=color,
                  label=label)
    ax.axvline(1e-4, color="grey", lw=0.5)
    ax.text(1.1e-4, ax.get_ylim()[1]*0.6, "h = 0", fontsize=7)
    ax.set_xlabel("alpha/Delta")
    ax.set_ylabel("CPU time per sample [ns]")
    ax.set_title("Cost of one sample of P(gamma, alpha)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    path = os.path.join(bc.FIGURES, "bench-sampler-cost.png")
    fig.savefig(path, dpi=110)
    print("wrote " + path)


def table():
    cost = {(r["sampler"], hkey(r["h"])): r
            for r in load("sampler-cost.csv")}
    wp = load("sampler-work-precision.csv")
    hs = sorted({hkey(r["h"]) for r in wp}, key=float)
    out = ["| sampler | " + " | ".join("h = %s" % H_LABELS.get(h, h)
                                       for h in hs) + " |",
           "|---|" + "---|"*len(hs)]
    for name, label, _, _ in SAMPLERS:
        cells = []
        for h in hs:
            r = cost.get((name, h))
            cells.append("%.3g" % float(r["ns_per_sample"]) if r
                         else "never ends")
        out.append("| %s | %s |" % (label, " | ".join(cells)))
    out.append("")
    nmax = max(float(r["N"]) for r in wp if r["status"] == "ok")
    out.append("KS distance at the largest N of each sampler (statistical "
               "level 0.87/sqrt(N) = %.2g at N = %.0e):\n" % (
                   0.8687/math.sqrt(nmax), nmax))
    out.append("| sampler | " + " | ".join("h = %s" % H_LABELS.get(h, h)
                                           for h in hs) + " |")
    out.append("|---|" + "---|"*len(hs))
    for name, label, _, _ in SAMPLERS:
        cells = []
        for h in hs:
            pts = [r for r in wp if r["sampler"] == name
                   and hkey(r["h"]) == h and r["status"] == "ok"]
            if not pts:
                cells.append("-")
                continue
            best = max(pts, key=lambda r: float(r["N"]))
            cells.append("%.2g (N=%.0e)" % (float(best["ks_mean"]),
                                            float(best["N"])))
        out.append("| %s | %s |" % (label, " | ".join(cells)))
    text = "\n".join(out) + "\n"
    with open(os.path.join(bc.RESULTS, "sampler.md"), "w") as f:
        f.write(text)
    print(text)


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--bench", required=True, help="benchRoughWallCore")
    p.add_argument("--work-precision", required=True,
                   help="samplerWorkPrecision")
    p.add_argument("--samples", default="100,1000,10000,100000,1000000")
    p.add_argument("--h", default="0,1e-3,1e-2,1e-1,1,10,1e3,1e5")
    p.add_argument("--budget", type=float, default=30,
                   help="max seconds of sampling per (sampler, h, N)")
    p.add_argument("--min-time", type=float, default=0.2)
    p.add_argument("--repetitions", type=int, default=5)
    p.add_argument("--plot-only", action="store_true")
    args = p.parse_args()
    bc.ensure_dirs()
    if not args.plot_only:
        info = bc.write_machine("sampler")
        print(bc.machine_markdown(info))
        measure(args)
    figures()
    table()


if __name__ == "__main__":
    main()
