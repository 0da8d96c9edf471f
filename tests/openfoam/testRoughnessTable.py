#!/usr/bin/env python3
"""Which Delta a roughnessAngle table gives: a table of five rows.

roughnessAngle given as a table of five rows
((50e-6 20) (80e-6 8) (110e-6 5) (140e-6 4) (200e-6 2)), parcels of seven
diameters at 20 deg incidence: below the first row (40 um: 20 deg), between
rows (65, 95, 125, 170 um: 14, 6.5, 4.5, 3 deg), on a row (80 um: 8 deg)
and beyond the last row (250 um: 2 deg).  The expected Delta is numpy's
np.interp of the table (constant beyond the ends); each group's mean and sd
of k_n and k_t agree with the oracle at that Delta (roughWallOracle,
restitution_statistics, 1e6 samples) within 4 combined standard errors.
The table bends at 80 um, so that a bisection that stops one interval too
early (65 um: 16.25 deg, 95 um: 8.75 deg) fails.  (ctest
<platform>.roughnessTable.fiveRows; the other roughnessTable.* tests:
testRoughnessTableBadInput.py, and testWallImpact.py with --roughness or
--roughnessParameters.)

Usage: testRoughnessTable.py --platform P [--cloud KIND] [--parcels N]
           [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os

import numpy as np

from foamcase import testing as t
import foamcase as fc

TABLE = ((50e-6, 20), (80e-6, 8), (110e-6, 5), (140e-6, 4), (200e-6, 2))
TABLE_DIAMETERS = (40e-6, 65e-6, 80e-6, 95e-6, 125e-6, 170e-6, 250e-6)
TABLE_ANGLE = 20


def table(args, platform):
    text = "(%s)" % " ".join("(%r %r)" % row for row in TABLE)
    case = fc.FoamCase(platform, t.WALL_IMPACT,
                       os.path.join(args.work, "case"), args.cloud)
    rng = np.random.default_rng(3)
    a = math.radians(TABLE_ANGLE)
    injectors = []
    for i, d in enumerate(TABLE_DIAMETERS):
        x = rng.uniform(-0.04, 0.0, args.parcels)
        z = rng.uniform(-0.015, 0.015, args.parcels)
        injectors.append(fc.Injector("d%d" % i, np.column_stack(
            [x, np.full(args.parcels, 0.005), z]),
            (math.cos(a), -math.sin(a), 0.0), d))
    case.write_injectors(injectors)
    case.write_settings(t.DEFAULT_SETTINGS.replace(
        "roughnessAngle  8;", "roughnessAngle  %s;" % text))
    case.mesh()
    case.solve()
    p = case.read_cloud("0.05", ["U", "d"])
    table_d = np.array([row[0] for row in TABLE])
    table_a = np.array([row[1] for row in TABLE])
    for d in TABLE_DIAMETERS:
        delta = float(np.interp(d, table_d, table_a))
        k = np.abs(p["d"] - d) < 1e-3 * d
        t.check(np.count_nonzero(k) == args.parcels,
                "d = %g um: %d parcels" % (d * 1e6, args.parcels))
        v = p["U"][k]
        kn = v[:, 1] / math.sin(a)
        kt = v[:, 0] / math.cos(a)
        ref = t.reference(fc.SPIN[args.cloud], delta, [TABLE_ANGLE])[
            TABLE_ANGLE]
        for name, x in (("kn", kn), ("kt", kt)):
            mean, se, sd, se_sd = t.sd_and_se(x)
            for what, value, err, rv, rerr in (
                    ("mean", mean, se, ref["mean_" + name],
                     ref["se_mean_" + name]),
                    ("sd", sd, se_sd, ref["sd_" + name],
                     ref["se_sd_" + name])):
                z = (value - rv) / math.hypot(err, rerr)
                t.check(abs(z) <= t.TOLERANCE_SE,
                        "d = %g um, Delta = %g deg: %s %s = %.5f, oracle "
                        "%.5f, |z| = %.2f" % (d * 1e6, delta, what, name,
                                              value, rv, abs(z)))


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p)
    p.add_argument("--parcels", type=int, default=3000)
    return p.parse_args()


def test():
    args = parse_args()
    table(args, fc.Platform(args.platform))


if __name__ == "__main__":
    t.main(test)
