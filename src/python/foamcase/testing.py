"""The harness of the OpenFOAM-level tests of roughWallInteraction, for
all platforms (openfoam13, openfoam14, openfoam1912): assertions (check,
TestFailure from foamcase.checking; main), the checks of a platform's
environment, the oracle's reference statistics, and the test cases (the
wall-impact case tests/openfoam/wallImpact, the closed box
tests/stability/openfoam/closedBox) with the checks made on them.

Setting up, running and reading cases is the rest of the package
foamcase: the tests import it as fc, and this module as t.

Tests run as  etc/openfoamEnv <platform> /usr/bin/python3 <script>
--platform <platform> ...: one platform's environment only; main() checks it
(and, on openfoam13 and openfoam14, that no OpenFOAM library comes from
Debian's /usr/lib). ctest sets PYTHONPATH to src/python.

numpy only.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import hashlib
import json
import math
import os
import re
import shutil
import sys
import time

import numpy as np

# The oracle: src/python/foamcase/roughWallOracle.py, an independent numpy Monte
# Carlo of the collision operator (its own sampler, no C++ core)
from foamcase import roughWallOracle
# One check for every test script (foamcase.checking); the tests call
# them as t.check, t.TestFailure
from foamcase.checking import PASSED, TestFailure, check  # noqa: F401
from foamcase.testConstants import parcel_mass
from foamcase import (LIBRARY, PLATFORMS, SPIN, FoamCase, FoamError,
                      Injector, Platform, environment_library, find_library,
                      column, ldd, read_text, write_text, write_text_atomic)

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
#: The folder of the OpenFOAM tests and their case templates
HERE = os.path.join(REPO, "tests", "openfoam")

# ---------------------------------------------------------------------------
# Platforms
# ---------------------------------------------------------------------------

def add_platform_args(parser, kinds=True, default_kind="colliding"):
    """--platform, --work (and --cloud) of every test script."""
    parser.add_argument("--platform", required=True, choices=PLATFORMS)
    parser.add_argument("--work", default=".")
    if kinds:
        parser.add_argument("--cloud", default=default_kind,
                            choices=sorted(SPIN),
                            help="colliding (spin), kinematic, DPM (v1912 "
                                 "DPMFoam), MPPIC (v1912 MPPICFoam, "
                                 "OpenFOAM-13 MPPICCloud)")


# ---------------------------------------------------------------------------
# Environment
# ---------------------------------------------------------------------------

#: OpenFOAM libraries that must never come from Debian's v1912 in /usr/lib
#: when running OpenFOAM-13
_SYSTEM_OPENFOAM = re.compile(
    r"^/usr/lib/(x86_64-linux-gnu/)?(openfoam/)?"
    r"lib(OpenFOAM\w*|finiteVolume|meshTools|lagrangian\w*|Pstream|"
    r"OSspecific|fileFormats|surfMesh|triSurface|momentumTransportModels|"
    r"incompressibleMomentumTransportModels|physicalProperties|"
    r"fvModels|fvConstraints|sampling|tracking|dynamicMesh|"
    r"distributionModels)\.so")


def check_foundation_libraries(platform):
    """OpenFOAM-13 or -14 runs: foamRun, the modules it loads, the parcel library
    and libroughWallInteraction.so resolve no OpenFOAM library to Debian's
    v1912 in /usr/lib (a known OpenFOAM library name, or any library of
    /usr/lib whose name is also one of $FOAM_LIBBIN's), and none is
    missing."""
    foam_libs = set()
    for root, _, files in os.walk(os.environ.get("FOAM_LIBBIN", "/none")):
        if os.path.basename(root) != "dummy":   # stand-ins of metis, scotch
            foam_libs.update(f for f in files if f.endswith(".so"))
    foam_run = shutil.which("foamRun")
    check(foam_run is not None, "%s: foamRun is on the PATH" % platform)
    binaries = [foam_run]
    # The solver modules' libraries: lib<module>Solver.so from OpenFOAM-14
    modules = ("libincompressibleFluid.so", "libfunctions.so") \
        if platform.version == "13" \
        else ("libincompressibleFluidSolver.so", "libfunctionsSolver.so")
    for name in (LIBRARY, "liblagrangianParcel.so") + modules \
            + ("libfiniteVolume.so",):
        path = find_library(name)
        check(path is not None and not path.startswith("/usr/lib"),
              "%s: %s found at %s" % (platform, name, path))
        binaries.append(path)
    bad = []
    for binary in binaries:
        for name, path in ldd(binary).items():
            system_copy = path.startswith("/usr/lib/") \
                and os.path.basename(path) in foam_libs
            if _SYSTEM_OPENFOAM.match(path) or system_copy or (
                    path == "not found" and name.startswith("lib")
                    and not name.startswith("libmpi")):
                bad.append("%s: %s => %s" % (os.path.basename(binary), name,
                                             path))
    check(not bad, "%s: no OpenFOAM library from /usr/lib or missing "
          % platform +
          "(ldd of %s)%s" % (", ".join(os.path.basename(b) for b in binaries),
                            ": " + "; ".join(bad) if bad else ""))


def check_environment(platform):
    """The platform's environment (and only it), the library, and on
    openfoam13 and openfoam14 no OpenFOAM library from /usr/lib."""
    lib = environment_library(platform)
    print("using %s: %s (%s)" % (platform, lib, os.environ["WM_PROJECT_DIR"]),
          flush=True)
    if platform.foundation:
        check_foundation_libraries(platform)


def main(test, platform_name=None):
    """Run test(), exit 0 on success, 1 on a failed check or error.

    platform_name: the --platform of the script (read from sys.argv if not
    given).  A test that made no check fails: every test must be able to."""
    start = time.time()
    if platform_name is None:
        argv = sys.argv[1:]
        platform_name = next((argv[i + 1] for i, a in enumerate(argv[:-1])
                              if a == "--platform"), None)
        platform_name = platform_name or next(
            (a.split("=", 1)[1] for a in argv if a.startswith("--platform=")),
            None)
    try:
        if platform_name is None:
            raise TestFailure("no --platform given")
        check_environment(Platform(platform_name))
        before = PASSED[0]
        test()
        if PASSED[0] == before:
            raise TestFailure("the test made no check")
    except (TestFailure, FoamError) as failure:
        print("TEST FAILED: %s (%.1f s)" % (failure, time.time() - start))
        sys.exit(1)
    print("TEST PASSED: %d checks (%.1f s)" % (PASSED[0],
                                               time.time() - start))


# ---------------------------------------------------------------------------
# Statistics against the oracle
# ---------------------------------------------------------------------------

#: Agreement required between a measured statistic and the reference, in
#: combined standard errors
TOLERANCE_SE = 4


def sd_and_se(x):
    """Mean, its standard error, sd and its standard error (delta method)."""
    n = len(x)
    mean = float(np.mean(x))
    d = x - mean
    m2 = float(np.mean(d**2))
    m4 = float(np.mean(d**4))
    sd = math.sqrt(m2*n/(n - 1))
    return mean, sd/math.sqrt(n), sd, \
        math.sqrt(max(m4 - m2*m2, 0)/n)/(2*math.sqrt(m2))


def source_hash(path):
    """SHA-1 of a source file's text, for the keys of cached()."""
    return hashlib.sha1(read_text(path).encode()).hexdigest()


def cached(name, args, compute, label=None):
    """compute(), a JSON value, kept in $ROUGHWALL_ORACLE_CACHE (set by
    ctest) under name and args (a JSON dict; with the oracle's source hash
    added) and reused by the other tests and platforms: for oracle results
    that are deterministic and take seconds to compute.  Tuples come back
    as lists.  label: what the line in the output calls it (name)."""
    cache = os.environ.get("ROUGHWALL_ORACLE_CACHE")
    args = dict(args, oracle=source_hash(roughWallOracle.__file__))
    key = hashlib.sha1(json.dumps([name, args], sort_keys=True).encode())
    path = os.path.join(cache, "%s.%s.json" % (name, key.hexdigest())) \
        if cache else None
    if path and os.path.exists(path):
        value = json.loads(read_text(path))["value"]
        how = "cached"
    else:
        start = time.time()
        value = compute()
        how = "%.1f s" % (time.time() - start)
        if path:
            write_text_atomic(path, json.dumps({"args": args,
                                                "value": value}))
    print("oracle: %s (%s)" % (label or name, how), flush=True)
    return value


def reference(spin, delta_deg, alphas, samples=1000000, seed=1, e=0.8,
              mu0=0.4, muD=0.4, lateral_tilt=False):
    """Reference rebound statistics {alpha: row} (mean_kn, se_mean_kn,
    sd_kn, se_sd_kn, the same for kt) of one hit at alpha [deg] on a flat
    rough wall: roughWallOracle.restitution_statistics, samples per angle,
    numpy's PCG64 seeded with seed; spin: spin produced by a facet collision
    carried into the next (a cloud with spin).

    Results are deterministic; each angle's row is cached() and reused by
    the other tests and platforms."""
    rows = {}
    for alpha in alphas:
        args = dict(alpha_deg=float(alpha), Delta_deg=float(delta_deg),
                    e=e, mu0=mu0, muD=muD, samples=int(samples), seed=seed,
                    spin=bool(spin), lateral=bool(lateral_tilt))
        rows[alpha] = cached(
            "restitution", args,
            lambda: roughWallOracle.restitution_statistics(
                [alpha], delta_deg, e=e, mu0=mu0, muD=muD, samples=samples,
                rng=np.random.default_rng(seed), spin=bool(spin),
                lateral=bool(lateral_tilt))[0],
            label="alpha = %.4g deg, Delta = %g deg, %s%s, %d samples"
            % (alpha, delta_deg, "spin" if spin else "no spin",
               ", lateral tilt" if lateral_tilt else "", samples))
    return rows


# ---------------------------------------------------------------------------
# The wall-impact case (tests/openfoam/wallImpact)
# ---------------------------------------------------------------------------

WALL_IMPACT = os.path.join(HERE, "wallImpact")

#: Files that v1912's DPMFoam and MPPICFoam need instead (carrier phase air)
WALL_IMPACT_DENSE = os.path.join(HERE, "wallImpactDPM")

#: Incidence angle [deg] -> parcel diameter [m] of its injector
ANGLES = {10: 100e-6, 30: 110e-6, 60: 120e-6}

DEFAULT_SETTINGS = """patchInteractionModel roughWallInteraction;

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


def wall_impact_case(platform, path, kind="colliding", two_d=False,
                     parcels=10000, seed=1, settings=None, with_libs=True):
    """The wall-impact case: parcels per incidence angle injected at
    y = 5 mm over x in [-0.04, 0], z in [-0.015, 0.015] (z = 0 in 2-D)."""
    case = FoamCase(platform, WALL_IMPACT, path, kind, two_d=two_d,
                    dense_overlay=WALL_IMPACT_DENSE, with_libs=with_libs)
    rng = np.random.default_rng(seed)
    injectors = []
    for angle, d in ANGLES.items():
        x = rng.uniform(-0.04, 0.0, parcels)
        z = np.zeros(parcels) if two_d \
            else rng.uniform(-0.015, 0.015, parcels)
        a = math.radians(angle)
        y = np.full(parcels, 0.005)
        injectors.append(Injector("alpha%d" % angle,
                                  np.column_stack([x, y, z]),
                                  (math.cos(a), -math.sin(a), 0.0), d))
    case.write_injectors(injectors)
    case.write_settings(settings if settings is not None else DEFAULT_SETTINGS)
    return case


def set_wall_velocity(case, wall_velocity):
    """Move lowerWall at (wall_velocity, 0, 0) (fixedValue carrier velocity
    on the wall: OpenFOAM's patchData takes the wall velocity from it)."""
    for name in ("0/U", "0/U.air"):
        path = case.file(name)
        if not os.path.exists(path):
            continue
        moving = """boundaryField
{
    lowerWall
    {
        type            fixedValue;
        value           uniform (%r 0 0);
    }""" % wall_velocity
        write_text(path, read_text(path).replace("boundaryField\n{", moving,
                                                 1))


def incident_velocity(angle, wall_velocity=0.0):
    """Incident velocity of the parcels of an injection angle [deg]
    relative to the wall moving at (wall_velocity, 0, 0)."""
    a = math.radians(angle)
    return np.array([math.cos(a) - wall_velocity, -math.sin(a), 0.0])


def check_summary(case, log, lines):
    """Check that the log has each of lines as a whole line (stripped): the
    model's summary of the patch settings ("lowerWall: rough: e = 0.8,
    ..."), where a substring would let "maxFacetCollisions = 1" match
    "= 10"."""
    out = [line.strip() for line in case.log(log).splitlines()]
    for line in lines:
        check(line in out, "log summary: '%s'" % line)


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
              "%salpha = %d deg: %d parcels" % (label, angle,
                                                parcels_per_angle))
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


# ---------------------------------------------------------------------------
# The closed box of the stability cases (tests/stability/openfoam/closedBox)
# ---------------------------------------------------------------------------

CLOSED_BOX = os.path.join(REPO, "tests", "stability", "openfoam", "closedBox")

#: The box [m]
BOX = (np.zeros(3), np.full(3, 0.1))



def check_angle_bins(rows, wall, v0, v1, Nw, last, bins):
    """The rows of wall in the angle file (incidenceAngleBins bins) at the
    last write against the parcels' incident v0 and rebound v1 velocities
    (rows, relative to the wall; Nw the mean-wall normals into the fluid;
    one hit per parcel).  Oracle: the incidence angle atan(|V'.N|/|V'_t|)
    and rebound angle atan(V''.N/|V''_t|) of each parcel, binned here (bins
    of 90/bins deg; the caller's incidence angles lie inside bins, not on
    an edge); per bin the hits, the hits with a tangential part, the four
    sums and their ratios, and the rebound histogram; and an invariant: the
    bins add up to the totals of the statistics file (row last)."""
    mine = [r for r in rows if r["patch"] == wall
            and r["Time"] == rows[-1]["Time"]]
    check([int(r["bin"]) for r in mine] == list(range(bins)),
          "%s: %d rows of the angle file at t = %g, bins 0..%d"
          % (wall, len(mine), rows[-1]["Time"], bins - 1))
    vn0 = np.abs(np.einsum("ij,ij->i", v0, Nw))
    vt0 = v0 - np.einsum("ij,ij->i", v0, Nw)[:, None]*Nw
    lt0 = np.linalg.norm(vt0, axis=1)
    tdir = vt0/np.where(lt0 == 0, 1, lt0)[:, None]
    vn1 = np.einsum("ij,ij->i", v1, Nw)
    lt1 = np.linalg.norm(v1 - vn1[:, None]*Nw, axis=1)
    width = 90.0/bins
    incidence = np.minimum(np.degrees(np.arctan2(vn0, lt0))//width,
                           bins - 1)
    rebound = np.minimum(np.degrees(np.arctan2(vn1, lt1))//width, bins - 1)
    for b, row in enumerate(mine):
        k = incidence == b
        tang = k & (lt0 > 0)
        expected = {
            "angleMin": b*width, "angleMax": (b + 1)*width,
            "hits": np.count_nonzero(k), "ktSamples": np.count_nonzero(tang),
            "sumVnIn": vn0[k].sum(), "sumVnOut": vn1[k].sum(),
            "sumVtIn": lt0[tang].sum(),
            "sumVtOut": np.einsum("ij,ij->i", v1, tdir)[tang].sum(),
            "rebounds": np.count_nonzero(rebound == b)}
        expected["impulseKn"] = expected["sumVnOut"]/expected["sumVnIn"] \
            if expected["sumVnIn"] > 0 else 0
        expected["impulseKt"] = expected["sumVtOut"]/expected["sumVtIn"] \
            if expected["sumVtIn"] > 0 else 0
        bad = [key for key, value in expected.items()
               if not _close(column(row, key), value)]
        check(not bad, "%s, bin %d [%g, %g) deg: %d hits, %d rebounds; "
              "every column equals the parcels'%s"
              % (wall, b, b*width, (b + 1)*width, expected["hits"],
                 expected["rebounds"],
                 "" if not bad else " (differ: %s)" % ", ".join(
                     "%s %r != %r" % (key, column(row, key), expected[key])
                     for key in bad)))
    check(any(r["hits"] > 0 and r["rebounds"] < r["hits"] for r in mine),
          "%s: the rebound histogram is not the incidence one" % wall)
    for key, total in (("hits", "hits"), ("sumVnIn", "sumVnIn"),
                       ("sumVnOut", "sumVnOut"), ("sumVtIn", "sumVtIn"),
                       ("sumVtOut", "sumVtOut"), ("rebounds", "hits")):
        check(_close(sum(r[key] for r in mine), column(last, wall + "_"
                                                          + total)),
              "%s: the bins' %s add up to the file's %s_%s"
              % (wall, key, wall, total))


def _close(a, b, rel=1e-8):
    return abs(a - b) <= rel*max(abs(a), abs(b), 1e-300)


def closed_box_case(platform, path, groups, kind="colliding", seed=1):
    """The closed box with injectors, one per group: dict(name, n, d [m],
    U0, box ((x0 y0 z0), (x1 y1 z1)) where positions are drawn uniformly).
    Returns the case, the number of parcels and their total mass [kg]."""
    case = FoamCase(platform, CLOSED_BOX, path, kind)
    rng = np.random.default_rng(seed)
    injectors = []
    mass = 0.0
    for g in groups:
        lo, hi = np.array(g["box"][0]), np.array(g["box"][1])
        injectors.append(Injector(g["name"],
                                  lo + (hi - lo)*rng.random((g["n"], 3)),
                                  g["U0"], g["d"]))
        mass += parcel_mass(g["d"], g["n"])  # the box's rho0: RHO_P
    return case, case.write_injectors(injectors), mass


#: OpenFOAM's own smooth-wall model with the same e and mu: the reference cost
SMOOTH_SETTINGS = """patchInteractionModel standardWallInteraction;

standardWallInteractionCoeffs
{
    type            rebound;
    e               0.8;
    mu              0.4;
}
"""


def check_conservation(steps, parcels, mass, label):
    """Parcel count and mass equal the injected ones at every time step,
    nothing escaped or stuck, the energy lost at the walls never negative."""
    check(len(steps) > 0, "%s: the log holds %d time steps"
          % (label, len(steps)))
    counts = sorted(set(s["parcels"] for s in steps))
    check(counts == [parcels], "%s: parcel count %s at every one of %d "
          "steps (injected %d)" % (label, counts, len(steps), parcels))
    worst = max(abs(s["mass"] - mass)/mass for s in steps)
    check(worst < 1e-9, "%s: mass in system equals the injected %.6e kg at "
          "every step (largest relative deviation %.1e)"
          % (label, mass, worst))
    check(all(s["escape"] == 0 and s["stick"] == 0 for s in steps),
          "%s: no parcel escaped or stuck" % label)
    losses = [x for s in steps for x in s["energyLoss"]]
    check(all(x >= 0 and math.isfinite(x) for x in losses),
          "%s: kinetic energy lost at the rough walls is finite and >= 0 "
          "(final %s J)" % (label, steps[-1]["energyLoss"]))


def check_inside_box(parts, parcels, lo, hi, label):
    """Every parcel inside the box, in a valid cell, finite velocity/spin.
    Returns the positions and velocities of all parcels."""
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
    spins = [p["angularMomentum"] for p in parts
             if len(p.get("angularMomentum", []))]
    if spins:
        check(bool(np.all(np.isfinite(np.concatenate(spins)))),
              "%s: every angular momentum finite" % label)
    return xyz, U
