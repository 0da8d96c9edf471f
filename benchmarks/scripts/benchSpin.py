#!/usr/bin/env python3
"""Cost per parcel-step of rotationalLift and fluidTorque, side by side with
the same cloud without them.

One colliding cloud of N parcels (d = 200 um, at rest at random positions
in the box interior) in a solid-body rotation of 5 rad/s (vorticity and slip
everywhere, so every parcel takes the full path of each model), sphereDrag
in every variant:
  none         sphereDrag only
  lift         + rotationalLift (OesterleBuiDinh)
  torque       + fluidTorque (DennisSinghIngham)
  lift+torque  both
Each variant runs S time steps R times (serial); the cost of a step is the
ExecutionTime difference between the last and the first step of the log
(start-up excluded), the best of the R runs.  Writes a CSV: platform,
variant, parcels, steps, s/step, ns per parcel-step and the extra ns per
parcel-step over "none".

Usage (in one platform's environment):
  PYTHONPATH=src/python etc/openfoamEnv openfoam13 python3 \\
      benchmarks/scripts/benchSpin.py \\
      --platform openfoam13 --work build/benchSpin --output spin-cost.csv

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import csv
import os
import re

import numpy as np

from foamcase import spinCase as s
from foamcase import testing as t
import foamcase as fc

VARIANTS = {
    "none": ("sphereDrag;", ""),
    "lift": ("sphereDrag;\nrotationalLift { coefficient OesterleBuiDinh; }",
             ""),
    "torque": ("sphereDrag;",
               "fluidTorque1 { type fluidTorque; coefficient "
               "DennisSinghIngham; }"),
    "lift+torque": ("sphereDrag;\nrotationalLift { coefficient "
                    "OesterleBuiDinh; }",
                    "fluidTorque1 { type fluidTorque; coefficient "
                    "DennisSinghIngham; }"),
}


def step_seconds(log, steps):
    """(ExecutionTime of the last step - of the first)/(steps - 1)."""
    times = [float(x) for x in re.findall(r"ExecutionTime = ([0-9.eE+-]+)",
                                          log)]
    if len(times) < steps:
        raise t.TestFailure("log holds %d steps of %d" % (len(times), steps))
    return (times[-1] - times[0]) / (len(times) - 1)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p, kinds=False)
    p.add_argument("--parcels", type=int, default=20000)
    p.add_argument("--steps", type=int, default=101)
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--output", default="spin-cost.csv")
    args = p.parse_args()
    platform = fc.Platform(args.platform)
    t.check_environment(platform)

    rng = np.random.default_rng(1)
    positions = np.column_stack([rng.uniform(-0.08, 0.08, args.parcels),
                                 rng.uniform(0.02, 0.08, args.parcels),
                                 rng.uniform(-0.03, 0.03, args.parcels)])
    rows = []
    for variant, (forces, functions) in VARIANTS.items():
        case = s.spin_case(platform, os.path.join(args.work, variant), [],
                           forces=forces, functions=functions, deltaT=1e-3)
        case.write_injectors([fc.Injector("cloud", positions, (0, 0, 0),
                                          200e-6)])
        s.mesh(case, 1, lambda c: s.rotating_carrier(c, 5.0))
        case.set_control(endTime=repr(args.steps * 1e-3),
                         startFrom="startTime", writeControl="runTime",
                         writeInterval="1")
        costs = []
        for r in range(args.repeats):
            case.solve("log.%d" % r)
            costs.append(step_seconds(case.log("log.%d" % r), args.steps))
        best = min(costs)
        rows.append(dict(platform=platform.name, variant=variant,
                         parcels=args.parcels, steps=args.steps,
                         seconds_per_step="%.6g" % best,
                         ns_per_parcel_step="%.1f" % (best / args.parcels
                                                      * 1e9)))
        print("%-12s %8.4f s/step  %7.1f ns per parcel-step"
              % (variant, best, best / args.parcels * 1e9), flush=True)
    base = float(rows[0]["ns_per_parcel_step"])
    for row in rows:
        row["extra_ns_per_parcel_step"] = "%.1f" % (
            float(row["ns_per_parcel_step"]) - base)
    with open(args.output, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print("wrote %s" % args.output)


if __name__ == "__main__":
    main()
