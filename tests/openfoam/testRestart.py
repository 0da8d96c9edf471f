#!/usr/bin/env python3
"""The statistics survive a restart, as localInteraction's do.

Runs the wall-impact case to t = 0.025 (after the 30 and 60 deg parcels have
hit the wall, before the 10 deg ones), then restarts it to t = 0.05.  The
statistics file of the restarted run (postProcessing/.../0.025/) must go on
from the stored totals: its first row already counts the hits before the
restart, its last row counts every parcel once, and its mean k_n, k_t and
energy loss equal those of all parcels at the end.  (OpenFOAM-13's functions
solver reads the frozen carrier at subSolverTime 0: the restart time holds
no carrier fields.)

Usage: testRestart.py --platform openfoam13|openfoam1912 [--cloud KIND]
           [--parcels N] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os

import numpy as np

from foamcase import testing as t
import foamcase as fc


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p)
    p.add_argument("--parcels", type=int, default=2000)
    return p.parse_args()


def test():
    args = parse_args()
    n = args.parcels
    case = t.wall_impact_case(fc.Platform(args.platform),
                              os.path.join(args.work, "case"), args.cloud,
                              parcels=n)
    case.mesh()

    case.set_control(endTime="0.025", writeInterval="25")
    case.solve("log.run1")
    _, rows1 = case.read_statistics()
    hits1 = fc.column(rows1[-1], "lowerWall_hits")
    t.check(hits1 == 2 * n,
            "first run: the 30 and 60 deg parcels hit before t = 0.025 "
            "(%d hits)" % hits1)

    case.set_control(endTime="0.05")
    case.solve("log.run2")
    t.check(os.path.exists(case.statistics_file("0.025")),
            "restart writes a new file in 0.025/")
    _, rows = case.read_statistics()
    rows2 = rows[len(rows1):]
    t.check(len(rows2) > 0, "restart: %d rows after the restart" % len(rows2))
    t.check(rows2[0]["Time"] > 0.025 and rows2[0]["lowerWall_hits"] >= hits1,
            "restart: the first row (t = %g) goes on from the stored %d hits "
            "(%d)" % (rows2[0]["Time"], hits1, rows2[0]["lowerWall_hits"]))
    last = rows2[-1]
    t.check(last["lowerWall_hits"] == 3 * n,
            "restart: every parcel counted once (%d hits)"
            % last["lowerWall_hits"])

    parcels = case.read_cloud("0.05", ["U", "d"])
    U = parcels["U"]
    t.check(len(U) == 3 * n, "restart: no parcel injected twice or lost "
            "(%d parcels)" % len(U))
    kn = np.empty(len(U))
    kt = np.empty(len(U))
    for angle, d in t.ANGLES.items():
        group = np.abs(parcels["d"] - d) < 1e-9
        kn[group] = U[group, 1] / math.sin(math.radians(angle))
        kt[group] = U[group, 0] / math.cos(math.radians(angle))
    t.check(abs(last["lowerWall_meanKn"] - kn.mean()) < 1e-8,
            "restart: meanKn %.10g = all parcels' %.10g"
            % (last["lowerWall_meanKn"], kn.mean()))
    t.check(abs(last["lowerWall_meanKt"] - kt.mean()) < 1e-8,
            "restart: meanKt %.10g = all parcels' %.10g"
            % (last["lowerWall_meanKt"], kt.mean()))


if __name__ == "__main__":
    t.main(test)
