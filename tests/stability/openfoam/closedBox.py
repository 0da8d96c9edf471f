#!/usr/bin/env python3
"""Parcel conservation in a closed box whose six sides are one rough wall.

Parcels of glass (500 um, 2500 kg/m^3) are shot in four directions at 2-3 m/s
inside a closed 0.1 m box under gravity (colliding cloud: spin on; lateral
tilt on; openfoam13: foamRun with the functions solver and the clouds
fvModel, openfoam1912: icoUncoupledKinematicParcelFoam). They bounce between the rough walls, lose energy
and settle on the floor, where they hit it again at every time step (a
settled parcel is a point that gravity pushes into the floor). Checks, from
the log at every time step and from the written cloud:
  - the parcel count and the mass in the system never change, nothing
    escapes or sticks (serial, and in parallel across the processor
    boundary, which parcels cross both ways);
  - at least --min-hits wall hits in all, at most 4 hits per parcel per time
    step (no endless hits on one face), no time step 100 times slower than
    the median (no stall);
  - the kinetic energy (linear + rotational) never exceeds the initial
    energy plus the potential energy of falling the box height, the energy
    lost at the walls is >= 0;
  - every parcel ends inside the box, in a cell, with finite velocity and
    spin.

Usage: closedBox.py --platform openfoam13|openfoam1912 --work DIR [--np N]
                    [--Delta DEG] [--end-time T] [--parcels-per-group N]
                    [--min-hits N]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import os
import statistics

import numpy as np

from foamcase import testing as t
import foamcase as fc

BOX = t.BOX
G = 9.81


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p, kinds=False)
    p.add_argument("--np", type=int, default=1)
    p.add_argument("--Delta", type=float, default=8, help="[deg]")
    p.add_argument("--end-time", type=float, default=0.4)
    p.add_argument("--parcels-per-group", type=int, default=500)
    p.add_argument("--min-hits", type=int, default=100000)
    return p.parse_args()


def test():
    args = parse_args()
    label = "closed box, Delta = %g deg, %d process%s" % (
        args.Delta, args.np, "" if args.np == 1 else "es")
    inner = ((0.01, 0.01, 0.01), (0.09, 0.09, 0.09))
    groups = [
        {"name": "a", "n": args.parcels_per_group, "d": 500e-6,
         "U0": (2.0, 1.0, 0.5), "box": inner},
        {"name": "b", "n": args.parcels_per_group, "d": 500e-6,
         "U0": (-1.5, 2.0, -1.0), "box": inner},
        {"name": "c", "n": args.parcels_per_group, "d": 500e-6,
         "U0": (0.5, -2.0, 1.5), "box": inner},
        {"name": "e", "n": args.parcels_per_group, "d": 500e-6,
         "U0": (-1.0, -1.0, -2.0), "box": inner},
    ]
    case, parcels, mass = t.closed_box_case(
        fc.Platform(args.platform), os.path.join(args.work, "case"), groups)
    case.set_entry("constant/roughWallSettings", "roughnessAngle",
                   "%g" % args.Delta)
    case.set_control(endTime="%g" % args.end_time,
                     writeInterval="%g" % args.end_time)
    case.mesh(args.np)
    _, elapsed = case.solve()

    steps = case.read_steps()
    t.check_conservation(steps, parcels, mass, label)

    hits = steps[-1]["hits"]
    t.check(hits >= args.min_hits, "%s: %d wall hits in all (>= %d)"
            % (label, hits, args.min_hits))
    per_step = np.diff([0] + [s["hits"] for s in steps])
    t.check(per_step.max() <= 4*parcels,
            "%s: at most %d hits in one step (<= 4 per parcel: no endless "
            "hits)" % (label, per_step.max()))
    fallbacks = steps[-1]["fallbacks"]
    t.check(fallbacks <= 1e-3*hits, "%s: %d hits at the re-collision bound "
            "(<= 1e-3 of the hits)" % (label, fallbacks))

    # A stall shows as a step far slower than the others (the hits per step
    # above are the direct check; the time is loose: CI machines are shared)
    times = np.diff([0] + [s["executionTime"] for s in steps])
    typical = max(statistics.median(times), 0.01)
    t.check(times.max() <= max(100*typical, 10.0),
            "%s: slowest step %.2f s, median %.3f s (no stall); %.1f s wall "
            "clock" % (label, times.max(), typical, elapsed))

    kinetic = [s["linearKE"] + (s["rotationalKE"] or 0) for s in steps]
    bound = kinetic[0] + mass*G*BOX[1][1]
    t.check(max(kinetic) <= bound*(1 + 1e-9),
            "%s: kinetic energy at most %.3e J (initial %.3e J + m g H = "
            "%.3e J); final %.3e J" % (label, max(kinetic), kinetic[0],
                                       bound, kinetic[-1]))

    parts = case.cloud_parts("%g" % args.end_time, fields=(
        "U", "d", "angularMomentum", "origProcId"))
    t.check_inside_box(parts, parcels, *BOX, label=label)
    if args.np > 1:
        # Parcels crossed the processor boundary both ways
        for i, part in enumerate(parts):
            foreign = int(np.count_nonzero(part["origProcId"] != i))
            t.check(foreign > 0, "%s: processor %d holds %d parcels injected "
                    "on another processor" % (label, i, foreign))


if __name__ == "__main__":
    t.main(test)
