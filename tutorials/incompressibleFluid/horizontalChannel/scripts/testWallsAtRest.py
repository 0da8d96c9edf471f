#!/usr/bin/python3
"""Test: the tutorial's particle case has walls at rest (ctest
tutorial_horizontalChannel_wallsAtRest).

Oracle: an invariant of hard-sphere collisions. For a wall at rest, a facet
collision with 0 <= e <= 1 and mu >= 0 never increases the particle's
kinetic energy in the lab frame, 1/2 m |u|^2 + 1/2 I |omega|^2 (the normal
impulse removes (1 - e^2) of the normal part, friction only dissipates:
model notes, section 4). A moving wall breaks it: friction drags a slow
particle along with the wall.

What runs: the tutorial's own set-up (./Allrun -setup in a temporary copy:
the carrier flow, the particle-centre mesh, scripts/mapCarrierFlow.py's
boundary conditions) for the default variant steel (3-D slab, lateral
facet tilt, Delta from the surface), with every force and torque between wall hits switched off (no drag, gravity, lift, dispersion, spin
models), so that only wall hits change a parcel's energy. The parcels start
slow, (0.5, -1, 0) m/s, so that a wall sliding downstream would speed them
up. The run writes every step; between two steps no parcel may gain energy
(relative tolerance 1e-9: the files carry 15 digits), parcels are conserved,
and most parcels hit a wall.

It also reads what the model says of the walls (the log line "Wall velocity
(patchData) of patch ...: largest speed S m/s"): S must be 0 on both walls.

Control (--control, also run by the test): the same case with the walls'
velocity condition made fixedValue, the mapping before the walls were put at
rest. There the model must report the walls moving at u(r) and warn, and the
invariant must fail. A control that passes would mean this test cannot see a
moving wall.

Usage: testWallsAtRest.py [--keep]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TUTORIAL = os.path.dirname(HERE)

import foamcase as fc
from foamcase import tutorial as tc

VARIANT = "steel"
PARCELS = 400
U0 = "(0.5 -1 0)"
END_TIME = 0.1
DT = 1e-3
ENERGY_RTOL = 1e-9


def fail(msg):
    print("TEST FAILED: " + msg)
    sys.exit(1)


def replace_block(text, keyword, replacement):
    """Replace the dictionary 'keyword { ... }' (nested braces) of text."""
    m = re.search(r"^\s*%s\s*\{" % re.escape(keyword), text, re.M)
    if not m:
        raise ValueError("no %s block" % keyword)
    depth, i = 1, m.end()
    while depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return text[:m.start()] + "\n" + replacement + text[i:]


def prepare(case, fixed_walls):
    """Forces off, slow parcels, a write every step; the control gets the
    fixedValue walls of the old mapping."""
    cloud = os.path.join(case, "constant", "cloudProperties")
    fc.write_text(cloud, replace_block(fc.read_text(cloud), "particleForces",
                                       "    particleForces\n    {\n    }\n"))
    fc.set_entry(cloud, "dispersionModel", "none")
    # The spin models off too (the fluid torque spins parcels up towards the
    # air's rotation, which would add rotational energy between hits)
    spin = os.path.join(case, "constant", "spinCoupling")
    text = replace_block(fc.read_text(spin), "spinForces", "spinForces\n{\n}\n")
    fc.write_text(spin, replace_block(text, "spinFunctions", "spinFunctions\n{\n}\n"))
    fc.set_entry(cloud, "U0", U0)

    control = os.path.join(case, "system", "controlDict")
    fc.set_entry(control, "endTime", "%g" % END_TIME)
    fc.set_entry(control, "deltaT", "%g" % DT)
    fc.set_entry(control, "writeInterval", "%g" % DT)
    fc.set_entry(control, "writePrecision", "15")

    if fixed_walls:
        path = os.path.join(case, "0", "U")
        text, n = re.subn(r"(lowerWall|upperWall)(\s*\{\s*type\s+)"
                          r"calculated;", r"\1\2fixedValue;",
                          fc.read_text(path))
        if n != 2:
            raise ValueError("0/U: no calculated walls to fix")
        fc.write_text(path, text)


def wall_speeds(log):
    """The model's report: patch -> largest wall speed [m/s]."""
    speeds = {}
    for m in re.finditer(r"Wall velocity \(patchData\) of patch (\w+): "
                         r"largest speed (%s) m/s" % fc.NUMBER, log):
        speeds[m.group(1)] = max(speeds.get(m.group(1), 0.0),
                                 float(m.group(2)))
    return speeds


def energies(case):
    """Per write time: parcel id -> 1/2 m |u|^2 + 1/2 I |omega|^2 [J]."""
    times = sorted((float(t), t) for t in os.listdir(case)
                   if re.fullmatch(fc.NUMBER, t) and float(t) > 0)
    result = []
    for _, t in times:
        cloud = os.path.join(case, t, "lagrangian", tc.CLOUD)
        if not os.path.exists(os.path.join(cloud, "U")):
            result.append({})
            continue
        U = fc.read_field(os.path.join(cloud, "U")).reshape(-1, 3)
        d = fc.read_field(os.path.join(cloud, "d")).reshape(-1)
        rho = fc.read_field(os.path.join(cloud, "rho")).reshape(-1)
        L = fc.read_field(os.path.join(cloud, "angularMomentum")) \
            .reshape(-1, 3)
        ids = fc.read_field(os.path.join(cloud, "origId")).astype(int)
        m = rho*np.pi/6*d**3
        inertia = 0.1*m*d**2
        e = 0.5*m*np.sum(U**2, axis=1) + 0.5*np.sum(L**2, axis=1)/inertia
        result.append(dict(zip(ids, e)))
    return result


def run(work, fixed_walls):
    """Set up and run one case; (wall speeds, the largest relative energy
    gain of a step, parcels that lost energy, parcels in the first snapshot,
    the fewest parcels of a snapshot, log)."""
    tutorial = os.path.join(work, "tutorial")
    os.makedirs(tutorial)
    for name in ("Allrun", "Allclean", "scripts", "carrier", "particles"):
        src = os.path.join(TUTORIAL, name)
        (shutil.copytree if os.path.isdir(src) else shutil.copy)(
            src, os.path.join(tutorial, name))
    env = dict(os.environ, ROUGHWALL_ROOT=tc.REPO)
    subprocess.run(["./Allrun", "-setup", "-variants", VARIANT,
                    "-parcels", str(PARCELS)], cwd=tutorial, env=env,
                   check=True)
    case = os.path.join(tutorial, "run", VARIANT)
    prepare(case, fixed_walls)
    fc.run(case, ["foamRun"], "log.foamRun")
    log = fc.read_text(os.path.join(case, "log.foamRun"))
    if "\nEnd" not in log:
        fail("foamRun did not finish, see " + case)
    # OpenFOAM-13 writes the cloud of the previous step: none at the first
    series = energies(case)
    while series and not series[0]:
        series.pop(0)
    if len(series) < 10:
        fail("only %d snapshots with parcels in %s" % (len(series), case))
    worst, losers = -np.inf, set()
    for before, after in zip(series, series[1:]):
        for i, e1 in after.items():
            e0 = before.get(i)
            if e0 is None:
                continue
            worst = max(worst, (e1 - e0)/e0)
            if e1 < e0*(1 - 1e-6):
                losers.add(i)
    return (wall_speeds(log), worst, len(losers), len(series[0]),
            min(len(e) for e in series), log)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--keep", action="store_true")
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="wallsAtRest.")
    try:
        speeds, worst, losers, n0, n1, log = run(
            os.path.join(work, "atRest"), fixed_walls=False)
        print("walls at rest: model's wall speeds %s m/s; largest relative "
              "energy gain of a step %.3g; %d of %d parcels lost energy at "
              "a wall; parcels %d, at least %d in every snapshot"
              % (speeds, worst, losers, n0, n0, n1))
        if sorted(speeds) != sorted(tc.WALLS):
            fail("the model reported no wall velocity for %s"
                 % sorted(set(tc.WALLS) - set(speeds)))
        if any(s != 0 for s in speeds.values()):
            fail("the model sees moving walls: %s m/s" % speeds)
        if "moves:" in log:
            fail("the model warned of a moving wall")
        if worst > ENERGY_RTOL:
            fail("a parcel gained energy at a wall at rest (relative %.3g)"
                 % worst)
        if n1 != n0 or n0 != PARCELS:
            fail("parcels not conserved: %d injected, %d at start, %d at end"
                 % (PARCELS, n0, n1))
        if losers < 0.5*PARCELS:
            fail("only %d parcels hit a wall: the test saw too few hits"
                 % losers)

        speeds, worst, losers, n0, n1, log = run(
            os.path.join(work, "control"), fixed_walls=True)
        print("control, fixedValue walls: model's wall speeds %s m/s; "
              "largest relative energy gain of a step %.3g" % (speeds, worst))
        if not speeds or min(speeds.values()) < 1:
            fail("control: the model did not report the moving walls")
        if "moves:" not in log:
            fail("control: no warning of a moving wall")
        if worst <= ENERGY_RTOL:
            fail("control: no parcel gained energy at the moving walls, so "
                 "the invariant cannot tell them from walls at rest")
        print("PASSED")
    finally:
        if args.keep:
            print("kept " + work)
        else:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
