#!/usr/bin/env python3
"""Which patch entry applies.

Two entries of patches match lowerWall, a name and a later regular
expression, then the other way round; the first applies (docs: "The first
entry that matches a patch applies"):
  lowerWall {rough} then "(lowerWall|upperWall)" {rebound e 0.5}:
      lowerWall is rough: its columns in the statistics file, every hit
      counted, k_n spread (sd > 0.05; a rebound with e 0.5 gives 0.5 exactly);
  "(lowerWall|upperWall)" {rebound e 0.5} then lowerWall {rough}:
      lowerWall rebounds: k_n = 0.5 and k_t = 1 for every parcel (to 1e-12;
      standardWallInteraction's law, mu 0), no lowerWall columns.
(ctest <platform>.patchEntries.firstMatch, --case firstMatch; the five-row
Delta(d) table is testRoughnessTable.py.)

--case group: the patch group wall (every patch of type wall is in it:
OpenFOAM puts a wall patch into its type's group) as the key of the only
entry for lowerWall and upperWall, {rebound e 0.5}: lowerWall rebounds with
k_n = 0.5 and k_t = 1 for every parcel (to 1e-12), as by the name
(ctest <platform>.patchEntries.group).

Usage: testPatchEntries.py --platform P [--case firstMatch|group]
           [--cloud KIND] [--parcels N] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import os

import numpy as np

from foamcase import testing as t
import foamcase as fc

ROUGH = "type rough; e 0.8; mu0 0.4; muD 0.4; roughnessAngle 8;"
REBOUND = "type rebound; e 0.5; mu 0;"

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


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p)
    p.add_argument("--case", default="firstMatch",
                   choices=["firstMatch", "group"])
    p.add_argument("--parcels", type=int, default=3000)
    return p.parse_args()


def test():
    args = parse_args()
    platform = fc.Platform(args.platform)
    {"firstMatch": first_match, "group": group}[args.case](args, platform)


if __name__ == "__main__":
    t.main(test)
