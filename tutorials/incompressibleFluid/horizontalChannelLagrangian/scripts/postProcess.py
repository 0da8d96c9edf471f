#!/usr/bin/env python3
"""Statistics of horizontalChannelLagrangian's particles at every write
time of each variant's case (run/<variant>).

Usage: scripts/postProcess.py RESULTS CASE...

Writes RESULTS/statistics.csv, per variant and write time: the particle
count, the mean streamwise velocity, and the rms of the wall-normal (y) and
spanwise (z) velocity fluctuations with their standard errors, and
RESULTS/concentration.csv, the fraction of the particles in each of the 14
cell layers across the channel at the last write time.

The particles do not interact (one-way coupling, no collisions between
them), so at one time they are independent samples: the standard error of
an rms s from n particles is, by the delta method, sqrt((m4 - s^4)/n)/(2 s)
with m4 the fourth central moment.  Write times of one variant are not
independent of each other (the particles' velocities decorrelate over their
relaxation time, about 0.2 s).

SPDX-License-Identifier: GPL-3.0-or-later
"""

import csv
import math
import os
import sys

import numpy as np

import foamcase as fc

CLOUD = "cloud"
NX, NY = 4, 14          # cells along and across the channel (blockMeshDict)


def rms_and_se(u):
    """rms of the fluctuation of u about its mean, and its standard error."""
    f = u - u.mean()
    s2 = float(np.mean(f**2))
    m4 = float(np.mean(f**4))
    s = math.sqrt(s2)
    se = math.sqrt(max(m4 - s2**2, 0.0)/len(u))/(2*s) if s > 0 else 0.0
    return s, se


def write_times(case):
    times = []
    for entry in os.listdir(case):
        try:
            t = float(entry)
        except ValueError:
            continue
        if t > 0 and os.path.isdir(os.path.join(case, entry, "Lagrangian",
                                                CLOUD)):
            times.append((t, entry))
    return sorted(times)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    results = sys.argv[1]
    os.makedirs(results, exist_ok=True)
    rows, conc = [], []
    for case in sys.argv[2:]:
        variant = os.path.basename(os.path.normpath(case))
        times = write_times(case)
        if not times:
            sys.exit("postProcess.py: no cloud written in %s" % case)
        for t, name in times:
            folder = os.path.join(case, name, "Lagrangian", CLOUD)
            n = len(fc.read_field(os.path.join(folder, "cell")))
            U = fc.internal_field(os.path.join(folder, "U"), n)
            ry, sey = rms_and_se(U[:, 1])
            rz, sez = rms_and_se(U[:, 2])
            rows.append([variant, "%g" % t, n, "%.6g" % U[:, 0].mean(),
                         "%.6g" % ry, "%.3g" % sey, "%.6g" % rz,
                         "%.3g" % sez])
        cells = fc.read_field(os.path.join(folder, "cell")).astype(int)
        layer = (cells // NX) % NY
        counts = np.bincount(layer, minlength=NY)
        for j in range(NY):
            conc.append([variant, j, "%.6g" % ((j + 0.5)/NY),
                         "%.6g" % (counts[j]/len(cells))])
    with open(os.path.join(results, "statistics.csv"), "w",
              newline="") as f:
        w = csv.writer(f)
        w.writerow(["variant", "time", "n", "meanUx", "rmsUy", "seRmsUy",
                    "rmsUz", "seRmsUz"])
        w.writerows(rows)
    with open(os.path.join(results, "concentration.csv"), "w",
              newline="") as f:
        w = csv.writer(f)
        w.writerow(["variant", "layer", "yByH", "fraction"])
        w.writerows(conc)
    for r in rows:
        if r[1] == "%g" % times[-1][0]:
            print("%-8s t = %s s: %d particles, mean Ux %s m/s, rms Uy %s "
                  "+- %s m/s, rms Uz %s +- %s m/s" % tuple(r))


if __name__ == "__main__":
    main()
