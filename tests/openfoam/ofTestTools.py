"""Helpers of the OpenFOAM tests of roughWallInteraction.

Case set-up (copy of the wallImpact template, parcel positions, settings),
running OpenFOAM commands with logs, and reading ASCII Lagrangian fields and
the statistics file.  numpy only.

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
TEMPLATE = os.path.join(HERE, "wallImpact")

#: Files that DPMFoam and MPPICFoam need instead (carrier phase "air")
DPM_OVERLAY = os.path.join(HERE, "wallImpactDPM")

#: Incidence angle [deg] -> parcel diameter [m] of its injector
ANGLES = {10: 100e-6, 30: 110e-6, 60: 120e-6}

FOAM_HEADER = """FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    location    "constant";
    object      %s;
}
"""

DEFAULT_SETTINGS = """
patchInteractionModel roughWallInteraction;

roughWallInteractionCoeffs
{
    patches
    (
        "(lowerWall|upperWall)"
        {
            type            rough;
            e               0.8;
            mu0             0.4;
            muD             0.4;
            roughnessAngle  8;
        }
        outlet { type escape; }
    );
}
"""


class TestFailure(Exception):
    """A failed assertion of a test."""


def check(condition, message):
    """Record one assertion: print it, raise TestFailure if it fails."""
    print(("PASS  " if condition else "FAIL  ") + message, flush=True)
    if not condition:
        raise TestFailure(message)


def check_environment():
    """The OpenFOAM environment and the library must be there."""
    if not os.environ.get("WM_PROJECT_DIR"):
        raise TestFailure("no OpenFOAM environment: source etc/setup first "
                          "(./Alltest does)")
    lib = os.path.join(os.environ.get("FOAM_USER_LIBBIN", ""),
                       "libroughWallInteraction.so")
    if not os.path.exists(lib):
        raise TestFailure("%s not built: run ./Allwmake" % lib)


def main(test):
    """Run test(), exit 0 on success, 1 on a failed check or error."""
    start = time.time()
    try:
        check_environment()
        test()
    except TestFailure as failure:
        print("TEST FAILED: %s (%.1f s)" % (failure, time.time() - start))
        sys.exit(1)
    print("TEST PASSED (%.1f s)" % (time.time() - start))


def make_case(dest, two_d=False, parcels=10000, seed=1, settings=None,
              with_libs=True, dpm=False):
    """Copy the wall-impact template to dest with parcel positions.

    parcels per incidence angle, injected at y = 5 mm over
    x in [-0.04, 0], z in [-0.015, 0.015] (z = 0 in 2-D).
    dpm: set up for DPMFoam/MPPICFoam (wallImpactDPM overlay).
    """
    if os.path.exists(dest):
        shutil.rmtree(dest)
    shutil.copytree(TEMPLATE, dest)
    if dpm:
        for root, _, files in os.walk(DPM_OVERLAY):
            for name in files:
                src = os.path.join(root, name)
                dst = os.path.join(dest, os.path.relpath(src, DPM_OVERLAY))
                shutil.copyfile(src, dst)
        for name in ("U", "p", "T"):
            if os.path.exists(os.path.join(dest, "0", name)) and name != "p":
                os.remove(os.path.join(dest, "0", name))
    if two_d:
        shutil.move(os.path.join(dest, "system", "blockMeshDict.2D"),
                    os.path.join(dest, "system", "blockMeshDict"))
    else:
        os.remove(os.path.join(dest, "system", "blockMeshDict.2D"))

    rng = np.random.default_rng(seed)
    for angle in ANGLES:
        x = rng.uniform(-0.04, 0.0, parcels)
        z = np.zeros(parcels) if two_d else rng.uniform(-0.015, 0.015, parcels)
        path = os.path.join(dest, "constant", "positions%d" % angle)
        with open(path, "w") as f:
            f.write(FOAM_HEADER % ("vectorField", "positions%d" % angle))
            f.write("%d\n(\n" % parcels)
            for xi, zi in zip(x, z):
                f.write("(%.9f 0.005 %.9f)\n" % (xi, zi))
            f.write(")\n")

    write_settings(dest, settings if settings is not None else DEFAULT_SETTINGS)

    if not with_libs:
        control = os.path.join(dest, "system", "controlDict")
        with open(control) as f:
            text = f.read()
        text = re.sub(r'^libs\s.*\n', "", text, flags=re.M)
        with open(control, "w") as f:
            f.write(text)


def set_wall_velocity(case, wall_velocity):
    """Move lowerWall at (wall_velocity, 0, 0) (fixedValue carrier velocity
    on the wall: OpenFOAM's patchData takes the wall velocity from it)."""
    for name in ("U", "U.air"):
        path = os.path.join(case, "0", name)
        if not os.path.exists(path):
            continue
        with open(path) as f:
            text = f.read()
        text = text.replace("boundaryField\n{", """boundaryField
{
    lowerWall
    {
        type            fixedValue;
        value           uniform (%r 0 0);
    }""" % wall_velocity, 1)
        with open(path, "w") as f:
            f.write(text)


def write_settings(case, settings):
    """Write the patch interaction settings (constant/roughWallSettings)."""
    with open(os.path.join(case, "constant", "roughWallSettings"), "w") as f:
        f.write(FOAM_HEADER % ("dictionary", "roughWallSettings"))
        f.write(settings)


def set_control(case, **entries):
    """Change entries of system/controlDict (keyword value;)."""
    path = os.path.join(case, "system", "controlDict")
    with open(path) as f:
        text = f.read()
    for key, value in entries.items():
        text, n = re.subn(r"^%s\s+[^;]*;" % key, "%s %s;" % (key, value),
                          text, flags=re.M)
        if n != 1:
            raise RuntimeError("controlDict has no entry " + key)
    with open(path, "w") as f:
        f.write(text)


def run(case, args, log, check_rc=True):
    """Run an OpenFOAM command in case, output to case/log; return rc."""
    start = time.time()
    with open(os.path.join(case, log), "w") as f:
        env = dict(os.environ, PWD=os.path.abspath(case))
        rc = subprocess.call(args, cwd=case, stdout=f, stderr=subprocess.STDOUT,
                             env=env)
    print("ran   %s (%s): rc %d, %.1f s" % (" ".join(args), log, rc,
                                            time.time() - start), flush=True)
    if check_rc and rc != 0:
        with open(os.path.join(case, log)) as f:
            tail = f.readlines()[-30:]
        print("".join(tail))
        raise TestFailure("%s failed (rc %d), see %s"
                          % (args[0], rc, os.path.join(case, log)))
    return rc


def mpirun(nprocs, args):
    """mpirun command line (root allowed, as in CI; more processes than
    cores allowed)."""
    extra = ["--oversubscribe"] if nprocs > (os.cpu_count() or 1) else []
    return ["mpirun", "--allow-run-as-root"] + extra + ["-np", str(nprocs)] \
        + args


def set_subdomains(case, nprocs):
    """Split the case into nprocs slabs along x (simple decomposition)."""
    path = os.path.join(case, "system", "decomposeParDict")
    with open(path) as f:
        text = f.read()
    text = re.sub(r"numberOfSubdomains\s+\d+;",
                  "numberOfSubdomains %d;" % nprocs, text)
    text = re.sub(r"n\s+\(\d+ 1 1\);", "n               (%d 1 1);" % nprocs,
                  text)
    with open(path, "w") as f:
        f.write(text)


_NUMBER = r"[-+0-9.eE]+|nan|-nan|inf|-inf"


def read_field(path):
    """Read an ASCII Lagrangian field: (n,) scalars or (n, 3) vectors."""
    with open(path) as f:
        text = f.read()
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    body = re.sub(r"//.*", "", body)
    m = re.search(r"(\d+)\s*\{\s*(\([^)]*\)|" + _NUMBER + r")\s*\}", body)
    m_list = re.search(r"(\d+)\s*\(", body)
    if m and (not m_list or m.start() <= m_list.start()):
        # Uniform list: n{value}
        n = int(m.group(1))
        value = m.group(2)
        if value.startswith("("):
            v = np.array([float(t) for t in value.strip("()").split()])
            return np.tile(v, (n, 1))
        return np.full(n, float(value))
    if not m_list:
        raise ValueError("no list in " + path)
    n = int(m_list.group(1))
    inner = body[m_list.end():body.rindex(")")]
    if n == 0:
        return np.zeros(0)
    if "(" in inner:
        values = np.array([float(t) for t in
                           inner.replace("(", " ").replace(")", " ").split()])
        return values.reshape(n, 3)
    return np.array([float(t) for t in inner.split()])


def cloud_dirs(case, time_name, cloud="kinematicCloud"):
    """The Lagrangian directories of the cloud: serial or per processor."""
    procs = sorted(glob.glob(os.path.join(case, "processor*")))
    if procs:
        dirs = [os.path.join(p, time_name, "lagrangian", cloud) for p in procs]
    else:
        dirs = [os.path.join(case, time_name, "lagrangian", cloud)]
    return dirs


def read_cloud(case, time_name, fields, cloud="kinematicCloud"):
    """Fields of all parcels (processors concatenated); missing dirs: empty."""
    data = {name: [] for name in fields}
    for d in cloud_dirs(case, time_name, cloud):
        if not os.path.isdir(d):
            continue
        for name in fields:
            data[name].append(read_field(os.path.join(d, name)))
    result = {}
    for name, parts in data.items():
        parts = [p for p in parts if p.size]
        result[name] = np.concatenate(parts) if parts else np.zeros(0)
    return result


def read_statistics(case, cloud="kinematicCloud"):
    """Rows of the statistics file(s), oldest start time first.

    Returns (column names, list of rows as dicts)."""
    pattern = os.path.join(case, "postProcessing", "lagrangian", cloud,
                           "patchInteractionModel", "*",
                           "roughWallInteraction*.dat")
    files = sorted(glob.glob(pattern),
                   key=lambda p: float(os.path.basename(os.path.dirname(p))))
    if not files:
        raise TestFailure("no statistics file " + pattern)
    names = None
    rows = []
    for path in files:
        with open(path) as f:
            for line in f:
                if line.startswith("# Time"):
                    names = line[1:].split()
                elif line.strip() and not line.startswith("#"):
                    values = line.split()
                    rows.append(dict(zip(names, map(float, values))))
    return names, rows


def sd_and_se(x):
    """Mean, its standard error, sd and its standard error (delta method)."""
    n = len(x)
    mean = float(np.mean(x))
    d = x - mean
    m2 = float(np.mean(d**2))
    m4 = float(np.mean(d**4))
    sd = math.sqrt(m2*n/(n - 1))
    return mean, sd/math.sqrt(n), sd, math.sqrt(max(m4 - m2*m2, 0)/n)/(2*math.sqrt(m2))


def reference(binary, spin, delta_deg, alphas, samples=1000000, seed=1,
              e=0.8, mu0=0.4, muD=0.4, lateral_tilt=False):
    """Reference statistics from roughWallReference: {alpha: row dict}."""
    args = [binary, "--spin", "1" if spin else "0", "--e", str(e),
            "--mu0", str(mu0), "--muD", str(muD), "--Delta", str(delta_deg),
            "--alpha", ",".join(str(a) for a in alphas),
            "--lateralTilt", "1" if lateral_tilt else "0",
            "--samples", str(samples), "--seed", str(seed)]
    out = subprocess.check_output(args, text=True).strip().splitlines()
    names = out[0].split(",")
    rows = {}
    for alpha, line in zip(alphas, out[1:]):
        rows[alpha] = dict(zip(names, map(float, line.split(","))))
    return rows


#: Agreement required between a measured statistic and the reference, in
#: combined standard errors
TOLERANCE_SE = 4


def incident_velocity(angle, wall_velocity=0.0):
    """Incident velocity of the parcels of an injection angle [deg]
    relative to the wall moving at (wall_velocity, 0, 0)."""
    a = math.radians(angle)
    return np.array([math.cos(a) - wall_velocity, -math.sin(a), 0.0])


def relative_angle(angle, wall_velocity=0.0):
    """Incidence angle [deg] relative to the wall moving along x."""
    if wall_velocity == 0:
        return angle
    v = incident_velocity(angle, wall_velocity)
    return math.degrees(math.atan2(-v[1], v[0]))


def check_rebound_statistics(U, d, parcels_per_angle, reference_of_angle,
                             label="", wall_velocity=0.0):
    """Compare mean and sd of k_n and k_t per angle with the reference.

    U: rebound velocities (incident speed 1, wall y = 0 moving at
    (wall_velocity, 0, 0), incidence in the x-y plane);
    reference_of_angle(relative angle, d) -> (reference row, Delta [deg]).
    k_n = -v''.n/v'.n and k_t = v''_x/v'_x relative to the wall.
    Returns the k_n and k_t samples of all angles."""
    kn_all = []
    kt_all = []
    for angle in sorted(ANGLES):
        d_angle = ANGLES[angle]
        group = np.abs(d - d_angle) < 1e-9
        check(np.count_nonzero(group) == parcels_per_angle,
              "%salpha = %d deg: %d parcels" % (label, angle, parcels_per_angle))
        v0 = incident_velocity(angle, wall_velocity)
        kn = U[group, 1] / -v0[1]
        kt = (U[group, 0] - wall_velocity) / v0[0]
        kn_all.append(kn)
        kt_all.append(kt)
        ref, delta = reference_of_angle(relative_angle(angle, wall_velocity),
                                        d_angle)
        for name, x in (("kn", kn), ("kt", kt)):
            mean, se_mean, sd, se_sd = sd_and_se(x)
            for what, value, se, ref_value, ref_se in (
                ("mean", mean, se_mean, ref["mean_" + name],
                 ref["se_mean_" + name]),
                ("sd", sd, se_sd, ref["sd_" + name], ref["se_sd_" + name]),
            ):
                z = (value - ref_value) / math.hypot(se, ref_se)
                check(abs(z) <= TOLERANCE_SE,
                      "%salpha = %.4g deg, Delta = %g deg: %s %s = %.5f, "
                      "reference %.5f, |z| = %.2f <= %d"
                      % (label, relative_angle(angle, wall_velocity), delta,
                         what, name, value, ref_value, abs(z), TOLERANCE_SE))
    return np.concatenate(kn_all), np.concatenate(kt_all)
