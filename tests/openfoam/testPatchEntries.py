#!/usr/bin/env python3
"""Which patch entry applies, and which Delta a table gives.

--case firstMatch: two entries of patches match lowerWall, a name and a
later regular expression, then the other way round; the first applies
(docs: "The first entry that matches a patch applies"):
  lowerWall {rough} then "(lowerWall|upperWall)" {rebound e 0.5}:
      lowerWall is rough: its columns in the statistics file, every hit
      counted, k_n spread (sd > 0.05; a rebound with e 0.5 gives 0.5 exactly);
  "(lowerWall|upperWall)" {rebound e 0.5} then lowerWall {rough}:
      lowerWall rebounds: k_n = 0.5 and k_t = 1 for every parcel (to 1e-12;
      standardWallInteraction's law, mu 0), no lowerWall columns.

--case group: the patch group wall (every patch of type wall is in it:
OpenFOAM puts a wall patch into its type's group) as the key of the only
entry for lowerWall and upperWall, {rebound e 0.5}: lowerWall rebounds with
k_n = 0.5 and k_t = 1 for every parcel (to 1e-12), as by the name.

--case table: roughnessAngle given as a table of five rows
((50e-6 20) (80e-6 8) (110e-6 5) (140e-6 4) (200e-6 2)), parcels of seven
diameters at 20 deg incidence: below the first row (40 um: 20 deg), between
rows (65, 95, 125, 170 um: 14, 6.5, 4.5, 3 deg), on a row (80 um: 8 deg)
and beyond the last row (250 um: 2 deg).  The expected Delta is numpy's
np.interp of the table (constant beyond the ends); each group's mean and sd
of k_n and k_t agree with the oracle at that Delta (roughWallOracle,
restitution_statistics, 1e6 samples) within 4 combined standard errors.
The table bends at 80 um, so that a bisection that stops one interval too
early (65 um: 16.25 deg, 95 um: 8.75 deg) fails.

Usage: testPatchEntries.py --platform P --case firstMatch|group|table
           [--cloud KIND] [--parcels N] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os

import numpy as np

from foamcase import testing as t
import foamcase as fc

ROUGH = "type rough; e 0.8; mu0 0.4; muD 0.4; roughnessAngle 8;"
REBOUND = "type rebound; e 0.5; mu 0;"

TABLE = ((50e-6, 20), (80e-6, 8), (110e-6, 5), (140e-6, 4), (200e-6, 2))
TABLE_DIAMETERS = (40e-6, 65e-6, 80e-6, 95e-6, 125e-6, 170e-6, 250e-6)
TABLE_ANGLE = 20


def settings(entries):
    return """patchInteractionModel roughWallInteraction;

roughWallInteractionCoeffs
{
    patches
    (
%s
        outlet { type escape; }
    );
}
""" % "\n".join("        %s { %s }" % e for e in entries)


def first_match(args, platform):
    for order, entries in (
            ("name first", (("lowerWall", ROUGH),
                            ('"(lowerWall|upperWall)"', REBOUND))),
            ("regex first", (('"(lowerWall|upperWall)"', REBOUND),
                             ("lowerWall", ROUGH)))):
        case = t.wall_impact_case(platform, os.path.join(
            args.work, order.replace(" ", "")), args.cloud,
            parcels=args.parcels, settings=settings(entries))
        case.mesh()
        case.solve()
        p = case.read_cloud("0.05", ["U", "d"])
        kn = np.empty(len(p["d"]))
        kt = np.empty(len(p["d"]))
        for angle, d in t.ANGLES.items():
            k = np.abs(p["d"] - d) < 1e-9
            v0 = t.incident_velocity(angle)
            kn[k] = p["U"][k, 1] / -v0[1]
            kt[k] = p["U"][k, 0] / v0[0]
        names, rows = case.read_statistics()
        t.check(len(kn) == 3 * args.parcels,
                "%s: all %d parcels in the domain" % (order, len(kn)))
        if order == "name first":
            t.check("lowerWall_hits" in names
                    and fc.column(rows[-1], "lowerWall_hits") == len(kn),
                    "%s: lowerWall is rough: lowerWall_hits = %d"
                    % (order, len(kn)))
            t.check(float(np.std(kn)) > 0.05,
                    "%s: k_n spread by the roughness (sd %.3f)"
                    % (order, float(np.std(kn))))
            t.check("upperWall_hits" not in names,
                    "%s: upperWall (regex only) rebounds: no columns" % order)
        else:
            t.check(float(np.max(np.abs(kn - 0.5))) < 1e-12
                    and float(np.max(np.abs(kt - 1))) < 1e-12,
                    "%s: lowerWall rebounds with e 0.5: k_n = 0.5, k_t = 1 "
                    "for every parcel (max deviation %.2g, %.2g)"
                    % (order, float(np.max(np.abs(kn - 0.5))),
                       float(np.max(np.abs(kt - 1)))))
            t.check("lowerWall_hits" not in names,
                    "%s: no rough-wall columns for lowerWall" % order)


def group(args, platform):
    case = t.wall_impact_case(platform, os.path.join(args.work, "group"),
                              args.cloud, parcels=args.parcels,
                              settings=settings((("wall", REBOUND),)))
    case.mesh()
    boundary = fc.read_text(case.file("constant/polyMesh/boundary"))
    t.check(boundary.count("inGroups") >= 2 and "wall" in boundary,
            "the wall patches are in the group wall (constant/polyMesh/"
            "boundary)")
    rc, _ = case.solve(check_rc=False)
    t.check(rc == 0, "the entry 'wall' covers lowerWall and upperWall: the "
            "run ends normally (rc %d)" % rc)
    p = case.read_cloud("0.05", ["U", "d"])
    t.check(len(p["d"]) == 3 * args.parcels,
            "group: all %d parcels in the domain" % len(p["d"]))
    kn = np.empty(len(p["d"]))
    kt = np.empty(len(p["d"]))
    for angle, d in t.ANGLES.items():
        k = np.abs(p["d"] - d) < 1e-9
        v0 = t.incident_velocity(angle)
        kn[k] = p["U"][k, 1] / -v0[1]
        kt[k] = p["U"][k, 0] / v0[0]
    t.check(float(np.max(np.abs(kn - 0.5))) < 1e-12
            and float(np.max(np.abs(kt - 1))) < 1e-12,
            "group wall {rebound e 0.5}: lowerWall rebounds with k_n = 0.5, "
            "k_t = 1 for every parcel (max deviation %.2g, %.2g)"
            % (float(np.max(np.abs(kn - 0.5))),
               float(np.max(np.abs(kt - 1)))))


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
    p.add_argument("--case", required=True, choices=["firstMatch", "group", "table"])
    p.add_argument("--parcels", type=int, default=3000)
    return p.parse_args()


def test():
    args = parse_args()
    platform = fc.Platform(args.platform)
    {"firstMatch": first_match, "group": group, "table": table}[args.case](
        args, platform)


if __name__ == "__main__":
    t.main(test)
