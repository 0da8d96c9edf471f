#!/usr/bin/env python3
"""The figure of horizontalChannelLagrangian, RESULTS/wallNormalVelocity.png,
from RESULTS/statistics.csv and RESULTS/concentration.csv (written by
scripts/postProcess.py; the committed ones are in results/).

(a) rms of the wall-normal particle velocity against time, smooth and rough
    wall, with bands of 2 standard errors (independent particles at each
    time, see postProcess.py); (b) the fraction of the particles in each
    cell layer across the channel at the last write time.

Usage: scripts/plotResults.py RESULTS

SPDX-License-Identifier: GPL-3.0-or-later
"""

import csv
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt   # noqa: E402
import numpy as np                # noqa: E402

STYLE = {"smooth": dict(color="tab:blue", label="smooth (Delta = 0)"),
         "rough": dict(color="tab:red", label="rough (Delta = 5 deg)")}


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    results = sys.argv[1]
    stats = read(os.path.join(results, "statistics.csv"))
    conc = read(os.path.join(results, "concentration.csv"))
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.6))
    for v in ("smooth", "rough"):
        rows = [r for r in stats if r["variant"] == v]
        t = np.array([float(r["time"]) for r in rows])
        s = np.array([float(r["rmsUy"]) for r in rows])
        se = np.array([float(r["seRmsUy"]) for r in rows])
        a.plot(t, s, "o-", ms=3, **STYLE[v])
        a.fill_between(t, s - 2*se, s + 2*se, color=STYLE[v]["color"],
                       alpha=0.25, lw=0)
        rows = [r for r in conc if r["variant"] == v]
        y = np.array([float(r["yByH"]) for r in rows])
        c = np.array([float(r["fraction"]) for r in rows])
        b.plot(c, y, "o-", ms=3, **STYLE[v])
    a.set_xlabel("t [s]")
    a.set_ylabel("rms of wall-normal velocity [m/s]")
    a.set_title("(a) wall-normal velocity, 2 s.e. bands", fontsize=10)
    a.set_ylim(bottom=0)
    a.legend(fontsize=8)
    b.set_xlabel("fraction of particles per cell layer")
    b.set_ylabel("y/H")
    b.set_title("(b) across the channel, t = %s s" % stats[-1]["time"],
                fontsize=10)
    b.set_ylim(0, 1)
    b.set_xlim(left=0)
    fig.tight_layout()
    out = os.path.join(results, "wallNormalVelocity.png")
    fig.savefig(out, dpi=110)
    print("wrote %s" % out)


if __name__ == "__main__":
    main()
