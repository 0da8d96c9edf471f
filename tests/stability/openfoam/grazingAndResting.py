#!/usr/bin/env python3
"""Grazing, sliding and resting parcels on a rough floor: the run must advance
at the cost per step of a smooth wall, without endless hits on one face.

In the closed box of closedBox.py (all sides rough, gravity -y, gas at rest,
500 um glass) three groups of parcels start on or just above the floor:
  grazing  launched at 1 m/s, 0.1 deg below the floor's plane;
  sliding  moving at 0.36 m/s exactly parallel to the floor (alpha = 0 until
           gravity adds the normal component);
  resting  at rest 10-50 um above the floor: from the first step on, gravity
           pushes them into it by g dt at every step.
The same case is run with OpenFOAM's standardWallInteraction (rebound, same
e and mu) for the reference cost. Checks:
  - parcel count and mass constant, no escape or stick, all parcels inside
    the box with finite velocity and spin at the end;
  - on average at most 1.5 hits per parcel per step, at most 4 in any step;
  - at most 2 facet collisions per hit, hits at the re-collision bound below
    1 % of the hits;
  - CPU time of the rough run at most 3 times that of the smooth run plus
    0.5 s (the rough-wall hit itself is a few microseconds).

Usage: grazingAndResting.py --platform openfoam13|openfoam1912 --work DIR
                            [--end-time T] [--delta-t DT]
                            [--parcels-per-group N]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os

import numpy as np

from foamcase import testing as t
import foamcase as fc

BOX = t.BOX


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p, kinds=False)
    p.add_argument("--end-time", type=float, default=0.3)
    p.add_argument("--delta-t", type=float, default=1e-3)
    p.add_argument("--parcels-per-group", type=int, default=1000)
    return p.parse_args()


def setup(path, args, smooth):
    n = args.parcels_per_group
    a = math.radians(0.1)
    groups = [
        {"name": "grazing", "n": n, "d": 500e-6,
         "U0": (math.cos(a), -math.sin(a), 0.0),
         "box": ((0.005, 0.0005, 0.01), (0.02, 0.001, 0.09))},
        {"name": "sliding", "n": n, "d": 500e-6, "U0": (0.3, 0.0, 0.2),
         "box": ((0.01, 1e-5, 0.01), (0.09, 5e-5, 0.09))},
        {"name": "resting", "n": n, "d": 500e-6, "U0": (0.0, 0.0, 0.0),
         "box": ((0.01, 1e-5, 0.01), (0.09, 5e-5, 0.09))},
    ]
    case, parcels, mass = t.closed_box_case(fc.Platform(args.platform), path,
                                            groups)
    if smooth:
        case.write_settings(t.SMOOTH_SETTINGS)
    case.set_control(endTime="%g" % args.end_time,
                     writeInterval="%g" % args.end_time,
                     deltaT="%g" % args.delta_t)
    case.mesh()
    return case, parcels, mass


def test():
    args = parse_args()
    work = os.path.abspath(args.work)
    steps_total = int(round(args.end_time/args.delta_t))

    smooth, parcels, mass = setup(os.path.join(work, "smooth"), args, True)
    smooth.solve()
    smooth_cpu = smooth.read_steps()[-1]["executionTime"]

    rough, parcels, mass = setup(os.path.join(work, "rough"), args, False)
    rough.solve()
    steps = rough.read_steps()
    label = "grazing/sliding/resting, dt = %g s" % args.delta_t
    t.check(len(steps) == steps_total, "%s: %d of %d time steps done"
            % (label, len(steps), steps_total))
    t.check_conservation(steps, parcels, mass, label)

    hits = steps[-1]["hits"]
    per_step = np.diff([0] + [s["hits"] for s in steps])
    t.check(hits <= 1.5*parcels*steps_total and per_step.max() <= 4*parcels,
            "%s: %d hits, %.2f per parcel per step on average, at most %d "
            "in a step (<= 1.5 per parcel per step, <= 4 in a step)"
            % (label, hits, hits/(parcels*steps_total), per_step.max()))
    resting = args.parcels_per_group
    t.check(hits >= 0.25*resting*steps_total,
            "%s: the floor is hit (%d hits >= a quarter of the resting "
            "parcels at every step)" % (label, hits))
    facet = max(steps[-1]["facetPerHit"])
    t.check(facet <= 2, "%s: %.3f facet collisions per hit (<= 2)"
            % (label, facet))
    fallbacks = steps[-1]["fallbacks"]
    t.check(fallbacks <= 0.01*hits, "%s: %d hits at the re-collision bound "
            "(<= 1 %% of the hits)" % (label, fallbacks))
    rough_cpu = steps[-1]["executionTime"]
    t.check(rough_cpu <= 3*smooth_cpu + 0.5,
            "%s: CPU time %.2f s rough, %.2f s smooth (rough <= 3 x smooth "
            "+ 0.5 s)" % (label, rough_cpu, smooth_cpu))

    parts = rough.cloud_parts("%g" % args.end_time)
    xyz, U = t.check_inside_box(parts, parcels, *BOX, label=label)
    t.check(float(np.abs(U).max()) <= 1.5,
            "%s: largest velocity component %.3f m/s (<= 1.5: no energy "
            "from the walls)" % (label, float(np.abs(U).max())))


if __name__ == "__main__":
    t.main(test)
