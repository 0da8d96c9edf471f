#!/usr/bin/python3
# roughWallStats: plots of the restitution-coefficient statistics.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Plot roughWallStats CSV tables with matplotlib (Debian's python3-matplotlib).

  plotRoughWallStats.py stats A.csv [B.csv ...] --output fig.png [--labels LA LB ...]
      mean k_t and mean k_n against alpha with +-1 sd bands (the paper's
      figure 2), one curve per table. The k_t axis shows the bands up to
      alpha = 75 deg (sd k_t ~ 1/cos alpha), the k_n axis up to --kn-max.
  plotRoughWallStats.py pdf A.csv [B.csv ...] --output fig.png [--labels ...]
      [--quantity kn|kt|kOmega ...] [--alpha A ...]
      the change-of-variables density (2.8) against the Monte Carlo histogram
      (the paper's figure 3), one panel per table.
  plotRoughWallStats.py delta A.csv [B.csv ...] --output fig.png [--labels ...]
      Delta(d) of the rolling-sphere envelope against d_p/RSm (log axis),
      with the closed-form estimate atan(2 pi Rq / max(RSm, d_p)) dashed,
      and the tilt's excess kurtosis and skewness below.
"""
import argparse
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SYMBOL = {"kn": r"k_n", "kt": r"k_t", "kOmega": r"k_\Omega"}


def read(path):
    data = np.genfromtxt(path, delimiter=",", names=True)
    return np.atleast_1d(data)


def per_table(values, n, default):
    values = list(values or [])
    return [values[i] if i < len(values) else default(i) for i in range(n)]


def band_limits(tables, key, alpha_max, top=None):
    """Axis limits holding the mean +- sd bands where alpha <= alpha_max:
    sd k_t grows like 1/cos(alpha) near 90 deg and k_n like 1/alpha near 0."""
    lo, hi = [], []
    for data in tables:
        keep = (data["alpha_deg"] <= alpha_max) & np.isfinite(data["sd_" + key])
        mean, sd = data["mean_" + key][keep], data["sd_" + key][keep]
        if mean.size:
            lo.append(np.min(mean - sd))
            hi.append(np.max(mean + sd))
    if not lo:
        return None
    lo, hi = min(lo), max(hi)
    if top is not None:
        hi = min(hi, top)
    pad = 0.05 * (hi - lo)
    return lo - pad, hi + pad


def plot_stats(tables, labels, output, kn_max):
    fig, (ax_t, ax_n) = plt.subplots(1, 2, figsize=(11, 4.4))
    for i, (data, label) in enumerate(zip(tables, labels)):
        colour = "C%d" % i
        a = data["alpha_deg"]
        for ax, key in ((ax_t, "kt"), (ax_n, "kn")):
            mean, sd = data["mean_" + key], data["sd_" + key]
            ok = np.isfinite(mean) & np.isfinite(sd)
            ax.plot(a[ok], mean[ok], color=colour, lw=1.8, label=label)
            ax.fill_between(a[ok], (mean - sd)[ok], (mean + sd)[ok], color=colour,
                            alpha=0.18, lw=0)
        ax_n.plot(a, data["mean_abs_kn"], color=colour, lw=1, ls="--")
    ax_t.set_ylabel(r"mean $k_t$ $\pm$ 1 sd")
    ax_n.set_ylabel(r"mean $k_n$ $\pm$ 1 sd  (dashed: mean $|k_n|$)")
    ax_n.axhline(1, color="0.4", lw=0.8, ls=":")
    limits = band_limits(tables, "kt", 75)
    if limits:
        ax_t.set_ylim(*limits)
    limits = band_limits(tables, "kn", 90, top=kn_max)
    if limits:
        ax_n.set_ylim(min(0, limits[0]), limits[1])
    for ax, title in ((ax_t, "(a) tangential"), (ax_n, "(b) normal")):
        ax.set_xlabel(r"incidence angle $\alpha$ [deg]")
        ax.set_xlim(0, 90)
        ax.set_title(title)
        ax.grid(alpha=0.3)
    ax_t.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    fig.savefig(output, dpi=130)


def plot_pdf(tables, labels, quantities, alphas, output):
    n = len(tables)
    fig, axes = plt.subplots(1, n, figsize=(5.2*n, 4.2), squeeze=False)
    for ax, data, label, quantity, alpha in zip(axes[0], tables, labels, quantities, alphas):
        lo, hi = data["k_lo"], data["k_hi"]
        edges = np.append(lo, hi[-1])
        ax.stairs(data["pdf_montecarlo"], edges, fill=True, color="0.8",
                  label="Monte Carlo histogram")
        names = data.dtype.names
        if "pdf_bin" in names:
            ax.plot(data["k"], data["pdf_bin"], "s", ms=3.5, color="C3",
                    label="(2.8): bin probability / width")
            ax.plot(data["k"], data["pdf"], "-", lw=1, color="C0",
                    label="(2.8): density at bin centre")
        symbol = SYMBOL.get(quantity, "k")
        ax.set_xlabel(r"$%s$" % symbol)
        ax.set_ylabel(r"probability density of $%s$" % symbol)
        title = r"$%s$" % symbol + (r", $\alpha$ = %s deg" % alpha if alpha else "")
        ax.set_title(title + "\n" + label, fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(output, dpi=130)


def plot_delta(tables, labels, output):
    fig, (ax, ax_shape) = plt.subplots(2, 1, figsize=(7, 7.2), sharex=True,
                                       gridspec_kw={"height_ratios": [2.2, 1]})
    for i, (data, label) in enumerate(zip(tables, labels)):
        colour = "C%d" % i
        x = data["d_over_RSm"]
        ax.plot(x, data["Delta_deg"], "o-", color=colour, ms=3.5, lw=1.6,
                label=label + ": envelope")
        ax.plot(x, data["closed_form_deg"], "--", color=colour, lw=1.2,
                label=label + r": atan(2$\pi$ Rq / max(RSm, $d_p$))")
        ax_shape.plot(x, data["excess_kurtosis"], "o-", color=colour, ms=3, lw=1.2,
                      label=label + ": excess kurtosis")
        ax_shape.plot(x, data["skewness"], "s:", color=colour, ms=3, lw=1,
                      label=label + ": skewness")
    ax.set_xscale("log")
    ax.set_ylabel(r"$\Delta(d_p)$ = rms tilt [deg]")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    ax_shape.axhline(0, color="0.4", lw=0.8)
    ax_shape.set_xlabel(r"$d_p$ / RSm")
    ax_shape.set_ylabel("shape of the tilt")
    ax_shape.grid(alpha=0.3, which="both")
    ax_shape.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(output, dpi=130)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("kind", choices=["stats", "pdf", "delta"])
    parser.add_argument("tables", nargs="+", help="CSV files written by roughWallStats")
    parser.add_argument("--output", required=True, help="figure file (.png, .pdf, .svg)")
    parser.add_argument("--labels", nargs="+", help="one label per table")
    parser.add_argument("--quantity", nargs="+", help="pdf: kn, kt or kOmega per table")
    parser.add_argument("--alpha", nargs="+", help="pdf: incidence angle per table [deg]")
    parser.add_argument("--kn-max", type=float, default=3,
                        help="stats: upper limit of the k_n axis (default 3; k_n ~ 1/alpha)")
    args = parser.parse_args(argv)

    tables = [read(path) for path in args.tables]
    labels = per_table(args.labels, len(tables), lambda i: args.tables[i])
    if args.kind == "stats":
        plot_stats(tables, labels, args.output, args.kn_max)
    elif args.kind == "delta":
        plot_delta(tables, labels, args.output)
    else:
        quantities = per_table(args.quantity, len(tables), lambda i: "k")
        alphas = per_table(args.alpha, len(tables), lambda i: "")
        plot_pdf(tables, labels, quantities, alphas, args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
