"""Helpers of the OpenFOAM-level stability cases: copy the closedBox template,
write injectors and settings, run OpenFOAM commands with logs, and read the
per-time-step cloud report of the log and the Lagrangian fields.  numpy only.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import glob
import math
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TEMPLATE = os.path.join(HERE, "closedBox")

HEADER = """FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    location    "constant";
    object      %s;
}
"""


class TestFailure(Exception):
    """A failed assertion."""


def check(condition, message):
    """One assertion: printed, TestFailure if it fails."""
    print(("PASS  " if condition else "FAIL  ") + message, flush=True)
    if not condition:
        raise TestFailure(message)


def main(test):
    """Run test(): exit 0 on success, 1 on a failed check."""
    start = time.time()
    try:
        if not os.environ.get("WM_PROJECT_DIR"):
            raise TestFailure("no OpenFOAM environment: source etc/setup "
                              "first (./Alltest does)")
        lib = os.path.join(os.environ.get("FOAM_USER_LIBBIN", ""),
                           "libroughWallInteraction.so")
        if not os.path.exists(lib):
            raise TestFailure("%s not built: run ./Allwmake" % lib)
        test()
    except TestFailure as failure:
        print("TEST FAILED: %s (%.1f s)" % (failure, time.time() - start))
        sys.exit(1)
    print("TEST PASSED (%.1f s)" % (time.time() - start))


def make_case(dest):
    """A fresh copy of the closedBox template."""
    if os.path.exists(dest):
        shutil.rmtree(dest)
    shutil.copytree(TEMPLATE, dest)
    return dest


def write_injectors(case, groups, seed=1):
    """Injectors, one per group: dict(name, n, d [m], U0 (vector),
    box ((x0 y0 z0), (x1 y1 z1)) where the positions are drawn uniformly).
    Returns the total number of parcels and their total mass [kg]."""
    rng = np.random.default_rng(seed)
    text = []
    total, mass = 0, 0.0
    for g in groups:
        lo, hi = np.array(g["box"][0]), np.array(g["box"][1])
        pos = lo + (hi - lo)*rng.random((g["n"], 3))
        path = os.path.join(case, "constant", "positions_" + g["name"])
        with open(path, "w") as f:
            f.write(HEADER % ("vectorField", "positions_" + g["name"]))
            f.write("%d\n(\n" % g["n"])
            for p in pos:
                f.write("(%.9g %.9g %.9g)\n" % tuple(p))
            f.write(")\n")
        text.append("""%s
{
    type            manualInjection;
    massTotal       0;
    parcelBasisType fixed;
    nParticle       1;
    SOI             0;
    positionsFile   "positions_%s";
    U0              (%r %r %r);
    sizeDistribution
    {
        type        fixedValue;
        fixedValueDistribution { value %r; }
    }
}
""" % (g["name"], g["name"], *g["U0"], g["d"]))
        total += g["n"]
        mass += g["n"]*2500*math.pi/6*g["d"]**3
    with open(os.path.join(case, "constant", "injectors"), "w") as f:
        f.write("\n".join(text))
    return total, mass


#: OpenFOAM's own smooth-wall model with the same e and mu: the reference cost
SMOOTH_SETTINGS = """patchInteractionModel standardWallInteraction;

standardWallInteractionCoeffs
{
    type            rebound;
    e               0.8;
    mu              0.4;
}
"""


def use_smooth_walls(case):
    """Replace the rough walls by standardWallInteraction (rebound)."""
    with open(os.path.join(case, "constant", "roughWallSettings"), "w") as f:
        f.write(HEADER % ("dictionary", "roughWallSettings"))
        f.write(SMOOTH_SETTINGS)


def set_entry(case, relpath, key, value):
    """Replace 'key  value;' (first occurrence) in a dictionary file."""
    path = os.path.join(case, relpath)
    with open(path) as f:
        text = f.read()
    text, n = re.subn(r"^(\s*)%s\s+[^;]*;" % re.escape(key),
                      r"\g<1>%s %s;" % (key, value), text, count=1,
                      flags=re.M)
    if n != 1:
        raise RuntimeError("%s has no entry %s" % (relpath, key))
    with open(path, "w") as f:
        f.write(text)


def run(case, args, log, timeout=900):
    """Run a command in case, output to case/log; fail on a non-zero exit."""
    start = time.time()
    with open(os.path.join(case, log), "w") as f:
        env = dict(os.environ, PWD=os.path.abspath(case))
        try:
            rc = subprocess.call(args, cwd=case, stdout=f,
                                 stderr=subprocess.STDOUT, env=env,
                                 timeout=timeout)
        except subprocess.TimeoutExpired:
            rc = "timeout after %d s (stalled?)" % timeout
    elapsed = time.time() - start
    print("ran   %s (%s): rc %s, %.1f s" % (" ".join(args), log, rc, elapsed),
          flush=True)
    if rc != 0:
        with open(os.path.join(case, log)) as f:
            print("".join(f.readlines()[-40:]))
        raise TestFailure("%s failed (rc %s), see %s"
                          % (args[0], rc, os.path.join(case, log)))
    return elapsed


def mpirun(nprocs, args):
    """mpirun as root (CI runs as root)."""
    return ["mpirun", "--allow-run-as-root", "--mca", "mpi_yield_when_idle", "1",
            "-np", str(nprocs)] + args


_FLOAT = r"([-+0-9.eE]+|nan|-nan|inf|-inf)"


def read_log(case, log):
    """The cloud report of every time step of a solver log, as a list of
    dicts: time, parcels, mass, escape (number), hits, fallbacks,
    facetPerHit, energyLoss (cumulative, summed over the rough patches),
    linearKE, rotationalKE, executionTime."""
    with open(os.path.join(case, log)) as f:
        text = f.read()
    steps = []
    for block in re.split(r"\nTime = ", text)[1:]:
        step = {"time": float(block.split()[0])}

        def grab(pattern, cast=float, default=None):
            m = re.search(pattern, block)
            return cast(m.group(1)) if m else default

        step["parcels"] = grab(r"Current number of parcels\s*=\s*(\d+)", int)
        step["mass"] = grab(r"Current mass in system\s*=\s*" + _FLOAT)
        step["linearKE"] = grab(r"Linear kinetic energy\s*=\s*" + _FLOAT)
        step["rotationalKE"] = grab(r"Rotational kinetic energy\s*=\s*"
                                    + _FLOAT)
        step["executionTime"] = grab(r"ExecutionTime = " + _FLOAT)
        step["escape"] = sum(int(n) for n in re.findall(
            r"- escape\s*=\s*(\d+),", block))
        step["stick"] = sum(int(n) for n in re.findall(
            r"- stick\s*=\s*(\d+),", block))
        step["hits"] = sum(int(n) for n in re.findall(
            r"- hits\s*=\s*(\d+)", block))
        step["fallbacks"] = sum(int(n) for n in re.findall(
            r"- hits at the re-collision bound\s*=\s*(\d+)", block))
        step["facetPerHit"] = [float(x) for x in re.findall(
            r"- facet collisions per hit\s*=\s*" + _FLOAT, block)]
        step["energyLoss"] = [float(x) for x in re.findall(
            r"- kinetic energy loss \[J\]\s*=\s*" + _FLOAT, block)]
        step["warnings"] = block.count("FOAM Warning")
        steps.append(step)
    return [s for s in steps if s["parcels"] is not None]


# One reader of Lagrangian fields for all the OpenFOAM-level tests
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "openfoam"))
from ofTestTools import _NUMBER, read_field  # noqa: E402


def read_positions(path):
    """Cartesian positions and cells of the 'positions' file: (n, 3), (n,)."""
    with open(path) as f:
        text = f.read()
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    rows = re.findall(r"\(\s*(" + _NUMBER + r")\s+(" + _NUMBER + r")\s+("
                      + _NUMBER + r")\s*\)\s*(-?\d+)", body)
    xyz = np.array([[float(r[0]), float(r[1]), float(r[2])] for r in rows])
    cells = np.array([int(r[3]) for r in rows])
    return xyz.reshape(-1, 3), cells


def cloud_dirs(case, time_name, cloud="kinematicCloud"):
    """The cloud's Lagrangian directories: the case or each processor."""
    procs = sorted(glob.glob(os.path.join(case, "processor*")))
    roots = procs if procs else [case]
    return [os.path.join(r, time_name, "lagrangian", cloud) for r in roots]


def final_cloud(case, time_name, fields=("U", "d", "angularMomentum")):
    """Positions, cells and fields of every parcel at time_name, per
    processor (a list with one dict per processor or one for serial)."""
    result = []
    for d in cloud_dirs(case, time_name):
        part = {"dir": d}
        if not os.path.isdir(d):
            part["positions"], part["cells"] = np.zeros((0, 3)), np.zeros(0)
            for name in fields:
                part[name] = np.zeros(0)
            result.append(part)
            continue
        part["positions"], part["cells"] = read_positions(
            os.path.join(d, "positions"))
        for name in fields:
            path = os.path.join(d, name)
            part[name] = read_field(path) if os.path.exists(path) \
                else np.zeros(0)
        result.append(part)
    return result


def check_conservation(steps, parcels, mass, label):
    """Parcel count and mass equal the injected ones at every time step,
    nothing escaped or stuck, the energy lost at the walls never negative."""
    check(len(steps) > 0, "%s: the log holds %d time steps" % (label,
                                                             len(steps)))
    counts = sorted(set(s["parcels"] for s in steps))
    check(counts == [parcels], "%s: parcel count %s at every one of %d "
          "steps (injected %d)" % (label, counts, len(steps), parcels))
    worst = max(abs(s["mass"] - mass)/mass for s in steps)
    check(worst < 1e-9, "%s: mass in system equals the injected %.6e kg at "
          "every step (largest relative deviation %.1e)" % (label, mass,
                                                            worst))
    check(all(s["escape"] == 0 and s["stick"] == 0 for s in steps),
          "%s: no parcel escaped or stuck" % label)
    losses = [x for s in steps for x in s["energyLoss"]]
    check(all(x >= 0 and math.isfinite(x) for x in losses),
          "%s: kinetic energy lost at the rough walls is finite and >= 0 "
          "(final %s J)" % (label, steps[-1]["energyLoss"]))


def check_inside_box(parts, parcels, lo, hi, label):
    """Every parcel inside the box, in a valid cell, finite velocity/spin."""
    total = sum(len(p["cells"]) for p in parts)
    check(total == parcels, "%s: %d parcels in the written cloud (expected "
          "%d)" % (label, total, parcels))
    xyz = np.concatenate([p["positions"] for p in parts])
    cells = np.concatenate([p["cells"] for p in parts])
    tol = 1e-9
    inside = np.all((xyz >= lo - tol) & (xyz <= hi + tol), axis=1)
    check(bool(np.all(inside)) and bool(np.all(cells >= 0)),
          "%s: every parcel inside the box and in a cell (%d outside)"
          % (label, int(np.count_nonzero(~inside))))
    U = np.concatenate([p["U"] for p in parts if len(p["U"])])
    check(bool(np.all(np.isfinite(U))), "%s: every velocity finite" % label)
    spins = [p["angularMomentum"] for p in parts if len(p["angularMomentum"])]
    if spins:
        check(bool(np.all(np.isfinite(np.concatenate(spins)))),
              "%s: every angular momentum finite" % label)
    return xyz, U
