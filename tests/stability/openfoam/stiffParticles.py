#!/usr/bin/env python3
"""Stiff and very inert particles in the same gas flow, with rough walls.

In the closed box of closedBox.py (all sides rough, gravity -y) the gas
moves at (3, -2, 1) m/s everywhere (the carrier is frozen: v1912's
icoUncoupledKinematicParcelFoam and OpenFOAM-13's functions solver read the
gas velocity, they do not solve for it), so it pushes parcels into three of
the walls. Two kinds of glass parcels share it:
  tiny   1 um: response time rho d^2/(18 mu) = 7.7e-6 s, 130 times shorter
         than the time step 1e-3 s (stiff drag): they follow the gas into
         the corner x = 0.1, y = 0, z = 0.1 m and are driven into its three
         walls again at every step;
  huge   5 mm: response time 190 s, they cross the box ballistically and
         bounce, faster than the gas (launched at 4 m/s).
Run with the implicit Euler and the analytical integration schemes, and
once with OpenFOAM's standardWallInteraction (rebound, same e and mu) for the
reference cost. Checks: parcel count and mass constant, nothing escapes or
sticks, every parcel inside the box with finite velocity and spin; no
velocity above the largest of the gas and launch speeds plus g t (the walls
add no energy); at most 20 hits per parcel per step (OpenFOAM splits a step
into sub-steps of at most maxCo = 0.3, and a stiff parcel driven into a
corner hits its three walls in every sub-step: about 10 hits per step, with
smooth walls too); hits at the re-collision bound below 1 %; CPU time at
most 3 times that of the smooth-wall run plus 0.5 s.

Usage: stiffParticles.py --platform openfoam13|openfoam1912 --work DIR
                         [--integration Euler|analytical] [--end-time T]
                         [--parcels-per-group N]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import os

import numpy as np

from foamcase import testing as t
import foamcase as fc

BOX = t.BOX
GAS = (3.0, -2.0, 1.0)
LAUNCH = (-2.0, 3.0, -2.0)   # |LAUNCH| = 4.1 m/s


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p, kinds=False)
    p.add_argument("--integration", default="Euler")
    p.add_argument("--end-time", type=float, default=0.3)
    p.add_argument("--parcels-per-group", type=int, default=1000)
    return p.parse_args()


def setup(path, args, smooth):
    """The case at path, run; returns it, its parcel count and mass."""
    inner = ((0.005, 0.005, 0.005), (0.095, 0.095, 0.095))
    groups = [
        {"name": "tiny", "n": args.parcels_per_group, "d": 1e-6,
         "U0": GAS, "box": inner},
        {"name": "huge", "n": args.parcels_per_group, "d": 5e-3,
         "U0": LAUNCH, "box": inner},
    ]
    case, parcels, mass = t.closed_box_case(fc.Platform(args.platform), path,
                                            groups)
    case.set_entry("0/U", "internalField", "uniform (%g %g %g)" % GAS)
    case.set_integration(args.integration)
    case.set_control(endTime="%g" % args.end_time,
                     writeInterval="%g" % args.end_time)
    if smooth:
        case.write_settings(t.SMOOTH_SETTINGS)
    case.mesh()
    case.solve()
    return case, parcels, mass


def test():
    args = parse_args()
    label = "stiff and inert particles, %s integration" % args.integration
    work = os.path.abspath(args.work)
    smooth, _, _ = setup(os.path.join(work, "smooth"), args, True)
    smooth_cpu = smooth.read_steps()[-1]["executionTime"]
    case, parcels, mass = setup(os.path.join(work, "rough"), args, False)

    steps = case.read_steps()
    t.check_conservation(steps, parcels, mass, label)
    hits = steps[-1]["hits"]
    per_step = np.diff([0] + [s["hits"] for s in steps])
    t.check(per_step.max() <= 20*parcels and hits > 0,
            "%s: %d hits, at most %d in a step (<= 20 per parcel)"
            % (label, hits, per_step.max()))
    rough_cpu = steps[-1]["executionTime"]
    t.check(rough_cpu <= 3*smooth_cpu + 0.5,
            "%s: CPU time %.2f s rough, %.2f s smooth (rough <= 3 x smooth "
            "+ 0.5 s)" % (label, rough_cpu, smooth_cpu))
    fallbacks = steps[-1]["fallbacks"]
    t.check(fallbacks <= 0.01*hits, "%s: %d hits at the re-collision bound "
            "(<= 1 %% of the hits)" % (label, fallbacks))

    parts = case.cloud_parts("%g" % args.end_time)
    xyz, U = t.check_inside_box(parts, parcels, *BOX, label=label)
    d = np.concatenate([p["d"] for p in parts])
    limit = max(np.linalg.norm(GAS), np.linalg.norm(LAUNCH)) \
        + 9.81*args.end_time
    for name, group in (("tiny", d < 1e-5), ("huge", d > 1e-3)):
        speed = np.linalg.norm(U[group], axis=1)
        t.check(group.sum() == args.parcels_per_group
                and float(speed.max()) <= limit,
                "%s: %d %s parcels, fastest %.3f m/s (<= %.3f m/s)"
                % (label, group.sum(), name, float(speed.max()), limit))
    # The stiff parcels followed the gas into the corner it drives them to
    # (x = 0.1, y = 0, z = 0.1 m) and stay there, pressed into three walls
    corner = xyz[d < 1e-5]
    cornered = (corner[:, 0] > 0.099) & (corner[:, 1] < 0.001) \
        & (corner[:, 2] > 0.099)
    t.check(bool(np.all(cornered)),
            "%s: %d of %d tiny parcels in the corner the gas drives them to"
            % (label, np.count_nonzero(cornered), len(corner)))


if __name__ == "__main__":
    t.main(test)
