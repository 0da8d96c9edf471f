#!/usr/bin/env python3
"""roughVelocity, the rough wall of OpenFOAM-13's and -14's field-based
Lagrangian (a velocity condition of the cloud, libLagrangianCloud), in a
kinematicParticle cloud without forces (src/python/foamcase/lagrangianCase.py).

--test flatWall: 10000 particles per incidence angle (10, 30, 60 deg,
    1 m/s, one diameter per angle: 100, 110, 120 um) fired from y = 5 mm at
    lowerWall (e 0.8, mu0 = muD = 0.4, Delta 8 deg; --roughness gives
    another roughnessAngle, e.g. a table against the diameter), read at
    t = 0.05 s when each has hit the wall once.  Checks: no particle lost,
    every one leaves the wall; mean and sd of k_n and k_t per angle against
    the oracle (src/python/foamcase/roughWallOracle.py, an independent numpy Monte
    Carlo of the operator without spin, 1e6 samples) within 4 combined
    standard errors; --twoD: the case is 2-D (empty front and back), the
    condition says lateralTilt true, which the log warns has no effect,
    and U_z = 0 exactly (statistics against the reference without it).
--test smooth: Delta = 0 (roughnessAngle 0) against reboundVelocity's law
    U'' = -e U_n n + (1 - mu) U_t written in this test, with mu derived by
    hand for the spin-free facet collision (docs/theory.md, model notes
    section 4): rolling while |U_t| <= 3.5 mu0 (1 + e)|U_n|, then
    mu = 2/7; else sliding, mu = muD (1 + e)|U_n|/|U_t|.  The 60 deg group
    rolls, the 10 deg group slides.  And OpenFOAM's own reboundVelocity
    with e 0.8 and mu 2/7 run on the 60 deg group gives the same velocities
    and positions (1e-12).
--test energy: 4000 particles in random directions towards a wall at rest
    (speeds 0.2 to 2 m/s, d 50 to 500 um), Delta 20 deg: no particle gains
    kinetic energy at the wall (|U''| <= |U'|(1 + 1e-12)); with e 1 and
    mu0 = muD = 0 (no tangential impulse, elastic facets) energy is kept
    exactly (1e-12).
--test closedBox: 2000 particles with random velocities under gravity in
    a box whose six walls are all rough, 400 steps: the particle count at
    every step of the log and in the written cloud equals the injected one,
    every particle inside the box; --np 2: the same run split in two.
--test outerCorrectors: the cloud as an fvModel of incompressibleFluid
    (air at rest, no drag) with 2 and then 3 PIMPLE outer correctors and the
    cloud's outerCorrectors on: each step is re-tracked from its start and
    the condition evaluated again for the same particles; the flat-wall
    groups (2000 per angle, Delta 8 deg) end identical (bit for bit) in
    both runs, and their rebounds are random: the draws depend on the
    particle and the step, not on how often the patch is evaluated.
    Then (OpenFOAM-14; -13's cloud fvModel cannot couple this cloud to
    incompressibleFluid) with the air coupled by drag (it changes from one
    corrector to the next) and every particle hitting in the first step
    before any face crossing: 2 and 3 correctors give the same rebounds to
    1e-6 m/s.
--test movingWall: the whole mesh translates at Uw = (-0.5, 0, 0) (a mover
    of the test's own, tests/openfoam/translatingMesh, built on first use:
    the project's OpenFOAM-13 and -14 have no mesh-motion library), so
    that lowerWall moves along itself; roughnessAngle 0 (a smooth wall),
    e 0.8, mu0 = muD = 0.4, the three flat-wall groups (500 each, from
    y = 4.7 mm: none hits the wall at the end of a time step).  The
    rebound is the hard-sphere one relative to the wall, written in this
    test: V' = U' - Uw, then rolling (|V'_t| <= 3.5 mu0 (1 + e) |V'_n|:
    V''_t = 5/7 V'_t) or sliding (V''_t = V'_t - muD (1 + e) |V'_n|),
    V''_n = e |V'_n|, U'' = V'' + Uw: 10 and 30 deg slide and 60 deg rolls
    relative to the wall (30 deg would roll relative to the mesh's frame).
    Every particle's U'' to 1e-9 m/s.
--test outsideRange: a profile's envelope tabulated for 1 to 50 um on
    lowerWall, 80 um particles hitting it on processor 1 of 2 only: the
    log warns once of the diameters outside the range.
--test badInput: e 1.5, muD > mu0, an unknown keyword, a non-positive d,
    and neither roughnessAngle nor roughness: each stops with a message
    naming the file, the keyword and the allowed values; a cloud without a
    field d (a tracer cloud, whose particles have no size) stops with a
    message naming the patch, the condition and the missing field d, and
    runs once the condition gives a d; a d given in the condition replaces
    the cloud's (the Delta(d) table then gives every particle the Delta of
    that d).

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os
import re
import shutil

import numpy as np

from foamcase import testing as t
import foamcase as fc
from foamcase import lagrangianCase as lc

ROUGH = "type roughVelocity; e 0.8; mu0 0.4; muD 0.4; roughnessAngle %s;"
ESCAPE = "type escapeVelocity;"
ANGLES = {10: 100e-6, 30: 110e-6, 60: 120e-6}


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p, kinds=False)
    p.add_argument("--test", required=True,
                   choices=["flatWall", "smooth", "energy", "closedBox",
                            "badInput", "outerCorrectors", "movingWall",
                            "outsideRange"])
    p.add_argument("--particles", type=int, default=10000)
    p.add_argument("--roughness", default="8")
    p.add_argument("--twoD", action="store_true")
    p.add_argument("--np", type=int, default=1)
    return p.parse_args()


def incident(angle):
    a = math.radians(angle)
    return (math.cos(a), -math.sin(a), 0.0)


def flat_wall_groups(n, rng, two_d=False):
    """One group per angle: x in [-0.04, 0], y = 5 mm, z in [-0.02, 0.02]
    (0 in 2-D)."""
    groups = []
    for angle, d in sorted(ANGLES.items()):
        pos = np.column_stack([
            -0.04 + 0.04*rng.random(n), np.full(n, 0.005),
            np.zeros(n) if two_d else -0.02 + 0.04*rng.random(n)])
        groups.append(lc.Group("a%d" % angle, pos, incident(angle), d))
    return groups


def run(case, n_procs=1):
    fc.block_mesh(case)
    if n_procs > 1:
        fc.run(case, ["decomposePar"], "log.decomposePar")
        fc.run(case, fc.mpirun(n_procs, ["foamRun", "-parallel"]),
               "log.foamRun")
    else:
        fc.run(case, ["foamRun"], "log.foamRun")


def particles(case, time_name, n_procs=1, fields=("U", "d")):
    out = lc.read_particles(case, time_name, fields,
                            n_procs if n_procs > 1 else None)
    return out


def diameters(case, time_name, n):
    """The cloud's d at time_name (written uniform when all are equal)."""
    path = os.path.join(case, time_name, "Lagrangian", lc.CLOUD, "d")
    text = fc.read_text(path)
    m = re.search(r"internalField\s+uniform\s+(%s)" % fc.NUMBER, text)
    if m:
        return np.full(n, float(m.group(1)))
    return fc.internal_field(path)


def test_flat_wall(args, work):
    rng = np.random.default_rng(1)
    n = args.particles
    # 2-D: with lateralTilt true, which has no effect there (warned)
    lower = ROUGH % args.roughness + (" lateralTilt true;" if args.twoD else "")
    case = lc.make_case(os.path.join(work, "case"),
                        flat_wall_groups(n, rng, args.twoD), ESCAPE,
                        lowerWall=lower, two_d=args.twoD)
    run(case)
    if args.twoD:
        log = fc.read_text(os.path.join(case, "log.foamRun"))
        t.check("Patch lowerWall (entry lowerWall): lateralTilt true has no "
                "effect on this 2-D mesh" in log,
                "2-D, lateralTilt true: warned of in the log")
    p = particles(case, "0.05")
    U = p["U"]
    t.check(len(U) == 3*n, "all %d particles in the cloud at t = 0.05 s "
            "(%d)" % (3*n, len(U)))
    d = diameters(case, "0.05", len(U))
    t.check(bool(np.all(U[:, 1] > 0)), "every particle leaves the wall "
            "(U_y > 0; smallest %.3g)" % U[:, 1].min())
    if args.twoD:
        t.check(bool(np.all(U[:, 2] == 0)), "2-D: U_z = 0 exactly "
                "(largest |U_z| %.3g)" % np.abs(U[:, 2]).max())

    table = None
    if args.roughness.strip().startswith("("):
        pairs = re.findall(r"\(\s*(%s)\s+(%s)\s*\)" % (fc.NUMBER, fc.NUMBER),
                           args.roughness)
        table = (np.array([float(a) for a, _ in pairs]),
                 np.array([float(b) for _, b in pairs]))

    def delta_of(diameter):
        # Linear interpolation in d, constant outside (numpy, not the code)
        if table is None:
            return float(args.roughness)
        return float(np.interp(diameter, table[0], table[1]))

    cache = {}

    def reference_of_angle(angle, diameter):
        delta = delta_of(diameter)
        key = (round(angle, 6), delta)
        if key not in cache:
            cache[key] = t.reference(False, delta, [angle])[angle]
        return cache[key], delta

    t.check_rebound_statistics(U, d, n, reference_of_angle,
                               label="roughVelocity: ")


def test_smooth(args, work):
    rng = np.random.default_rng(2)
    n = 2000
    groups = flat_wall_groups(n, rng)
    case = lc.make_case(os.path.join(work, "rough"), groups, ESCAPE,
                        lowerWall=ROUGH % "0")
    run(case)
    p = particles(case, "0.05")
    U = p["U"]
    d = diameters(case, "0.05", len(U))
    e, mu0, muD = 0.8, 0.4, 0.4
    for angle, dg in sorted(ANGLES.items()):
        g = np.abs(d - dg) < 1e-9
        v = np.array(incident(angle))
        un, ut = -v[1], v[0]     # |U_n|, |U_t| (wall normal +y)
        rolling = ut <= 3.5*mu0*(1 + e)*un
        mu = 2/7 if rolling else muD*(1 + e)*un/ut
        expected = np.array([(1 - mu)*v[0], e*un, 0.0])
        err = np.abs(U[g] - expected).max()
        t.check(np.count_nonzero(g) == n and err < 1e-12,
                "Delta = 0, alpha = %d deg (%s, mu = %.6f by hand): "
                "U'' = (%.6f, %.6f, 0) for all %d particles "
                "(largest deviation %.2e < 1e-12)"
                % (angle, "rolling" if rolling else "sliding", mu,
                   expected[0], expected[1], np.count_nonzero(g), err))
    # OpenFOAM's reboundVelocity with the hand-derived mu of the rolling
    # group gives the same particles
    g60 = [g for g in groups if g.name == "a60"]
    cases = {}
    for name, cond in (("rough60", ROUGH % "0"),
                       ("rebound60", "type reboundVelocity; e 0.8; "
                                     "mu %.17g;" % (2/7))):
        cases[name] = lc.make_case(os.path.join(work, name), g60, ESCAPE,
                                   lowerWall=cond)
        run(cases[name])
    a = particles(cases["rough60"], "0.05", fields=("U", "coordinates"))
    b = particles(cases["rebound60"], "0.05", fields=("U", "coordinates"))
    err_U = np.abs(a["U"] - b["U"]).max()
    err_c = np.abs(a["coordinates"] - b["coordinates"]).max()
    t.check(len(a["U"]) == n and err_U < 1e-12 and err_c < 1e-12,
            "Delta = 0 equals reboundVelocity (e 0.8, mu 2/7) at 60 deg: "
            "velocities (%.1e) and barycentric coordinates (%.1e) of all "
            "%d particles < 1e-12" % (err_U, err_c, len(a["U"])))


def random_towards_wall(rng, n):
    """Directions with U_y < 0 (uniform on the half sphere), speeds in
    [0.2, 2] m/s."""
    v = rng.normal(size=(n, 3))
    v[:, 1] = -np.abs(v[:, 1]) - 0.05
    v /= np.linalg.norm(v, axis=1)[:, None]
    return v*(0.2 + 1.8*rng.random(n))[:, None]


def test_energy(args, work):
    rng = np.random.default_rng(3)
    n_groups, n = 40, 100
    groups = []
    incoming = []
    for k in range(n_groups):
        v = random_towards_wall(rng, 1)[0]
        # Start at y such that the wall is reached within 0.02 s
        y = min(0.004, 0.8*0.02*(-v[1]))
        pos = np.column_stack([-0.02 + 0.04*rng.random(n), np.full(n, y),
                               -0.02 + 0.04*rng.random(n)])
        groups.append(lc.Group("g%d" % k, pos, v,
                               50e-6 + 450e-6*rng.random()))
        incoming.append(np.tile(v, (n, 1)))
    incoming = np.concatenate(incoming)
    speed0 = {g.name: np.linalg.norm(g.U0) for g in groups}
    for name, cond, exact in (
            ("dissipative", "type roughVelocity; e 0.8; mu0 0.4; muD 0.3; "
                            "roughnessAngle 20;", False),
            ("elastic", "type roughVelocity; e 1; mu0 0; muD 0; "
                        "roughnessAngle 20;", True)):
        case = lc.make_case(os.path.join(work, name), groups, ESCAPE,
                            lowerWall=cond, end_time=0.02, delta_t=1e-3,
                            cells=(20, 10, 20),
                            box=((-0.1, 0, -0.1), (0.1, 0.1, 0.1)))
        run(case)
        p = particles(case, "0.02", fields=("U", "d"))
        U = p["U"]
        t.check(len(U) == len(incoming),
                "%s: all %d particles kept" % (name, len(incoming)))
        d = diameters(case, "0.02", len(U))
        # The particles' incoming speeds, by group (their diameters)
        speed_in = np.empty(len(U))
        for g in groups:
            speed_in[np.abs(d - g.d) < 1e-12] = speed0[g.name]
        speed_out = np.linalg.norm(U, axis=1)
        hit = U[:, 1] > 0
        t.check(bool(np.all(hit)), "%s: every particle hit the wall and "
                "left it (%d of %d)" % (name, np.count_nonzero(hit), len(U)))
        ratio = speed_out/speed_in
        if exact:
            t.check(bool(np.all(np.abs(ratio - 1) < 1e-12)),
                    "%s (e 1, no friction): |U''| = |U'| to 1e-12 for "
                    "every particle (largest |ratio - 1| %.1e)"
                    % (name, np.abs(ratio - 1).max()))
        else:
            t.check(bool(np.all(ratio <= 1 + 1e-12)),
                    "%s: no particle gains energy at the wall at rest "
                    "(largest |U''|/|U'| %.6f)" % (name, ratio.max()))


def test_closed_box(args, work):
    rng = np.random.default_rng(4)
    n = 2000
    pos = 0.005 + 0.09*rng.random((n, 3))
    groups = []
    for k in range(20):
        sl = slice(k*n//20, (k + 1)*n//20)
        groups.append(lc.Group("g%d" % k, pos[sl],
                               random_towards_wall(rng, 1)[0]*3,
                               100e-6 + 20e-6*k))
    case = lc.make_case(os.path.join(work, "box"), groups,
                        "type roughVelocity; e 0.9; mu0 0.3; muD 0.2; "
                        "roughnessAngle 10;",
                        box=((0, 0, 0), (0.1, 0.1, 0.1)), cells=(10, 10, 10),
                        end_time=0.4, delta_t=1e-3, gravity=True,
                        n_procs=args.np)
    run(case, args.np)
    log = fc.read_text(os.path.join(case, "log.foamRun"))
    # The cloud's table: after "complete inInternalMesh <patches>
    # toBeRemoved", rows of counts; the last row of each step: all complete
    rows = re.findall(r"complete inInternalMesh[^\n]*\n((?:\s+\d+(?:\s+\d+)+"
                      r"\n)+)", log)
    finals = [[int(x) for x in r.strip().split("\n")[-1].split()]
              for r in rows]
    t.check(len(finals) >= 400, "the log holds %d steps of the cloud"
            % len(finals))
    # Particles on the six walls (the patch columns) during the steps
    on_walls = sum(sum(int(x) for x in line.split()[2:8])
                   for r in rows for line in r.strip().split("\n"))
    t.check(on_walls > n, "the walls were hit (%d particle-wall events "
            "in the log's tables)" % on_walls)
    bad = [f for f in finals if f[0] != n or any(f[1:])]
    t.check(not bad, "%d particles complete at the end of every step, none "
            "removed (%d steps differ)" % (n, len(bad)))
    time_name = "0.4"
    p = particles(case, time_name, args.np, fields=("U", "coordinates",
                                                    "cell"))
    t.check(len(p["U"]) == n, "%d particles in the written cloud at t = 0.4 "
            "s%s" % (len(p["U"]), " (%d processors)" % args.np
                     if args.np > 1 else ""))
    c = p["coordinates"]
    t.check(bool(np.all(c >= -1e-9)) and bool(np.all(p["cell"] >= 0)),
            "every particle in a cell with barycentric coordinates >= 0")
    hits = np.count_nonzero(np.any(np.abs(p["U"]) > 0, axis=1))
    t.check(hits == n, "velocities finite and non-zero (%d)" % hits)


def test_outer_correctors(args, work):
    rng = np.random.default_rng(6)
    n = 2000
    groups = flat_wall_groups(n, rng)
    results = {}
    for n_outer in (2, 3):
        case = lc.make_case(os.path.join(work, "outer%d" % n_outer), groups,
                            ESCAPE, lowerWall=ROUGH % "8", end_time=0.04,
                            outer_correctors=n_outer)
        run(case)
        log = fc.read_text(os.path.join(case, "log.foamRun"))
        solves = log.count("Solving cloud")
        t.check(solves == 40*n_outer, "%d outer correctors: the cloud is "
                "solved %d times in 40 steps (%d)"
                % (n_outer, 40*n_outer, solves))
        results[n_outer] = particles(case, "0.04",
                                     fields=("U", "coordinates"))
    a, b = results[2], results[3]
    t.check(len(a["U"]) == 3*n and len(b["U"]) == 3*n,
            "all %d particles kept" % (3*n))
    sd = float(np.std(a["U"][:, 1]))
    t.check(sd > 0.01, "the rebounds are random (sd of U_y %.3f)" % sd)
    err_U = float(np.abs(a["U"] - b["U"]).max())
    err_c = float(np.abs(a["coordinates"] - b["coordinates"]).max())
    t.check(err_U == 0 and err_c == 0,
            "2 and 3 outer correctors (each step re-tracked from its start, "
            "the condition evaluated again for the same particles) give "
            "identical particles: the draws are a function of particle and "
            "step (largest differences: U %.1e, coordinates %.1e)"
            % (err_U, err_c))
    if args.platform == "openfoam13":
        # OpenFOAM-13's cloud fvModel stops (FOAM FATAL ERROR "Different
        # dimensions for +=" in CarrierEqn, fvModels::sourceTerm) when drag
        # couples this cloud to incompressibleFluid; -14 reworked it
        print("coupled correctors: not run on OpenFOAM-13 (its cloud "
              "fvModel cannot couple a kinematicParticle cloud to "
              "incompressibleFluid)")
    else:
        coupled_correctors(work)


def coupled_correctors(work):
    """The carrier moves between the correctors: Schiller-Naumann drag
    couples the cloud to the air, which the cloud's momentum source sets
    moving, so that each corrector's drag differs.  Every particle starts
    within one step of lowerWall (y0 in (0.1, 0.9) v_n dt) and hits it in
    the first step, before it crosses any cell face (the mesh is one cell
    across x and z): the hit point is the start point plus the step's first
    displacement, the same in every corrector.  Oracle: the facets are a
    function of the hit, not of the corrector that reaches it, so 2 and 3
    correctors give the same rebounds up to the carrier's effect on the
    velocity (measured 2e-10 m/s; bound 1e-6 m/s), while the rebounds
    themselves are random (sd of U_y well above the bound) and the air did
    change between correctors (the particles' velocities differ, not 0)."""
    rng = np.random.default_rng(7)
    n = 1000
    groups = []
    for angle, d in sorted(ANGLES.items()):
        v_n = math.sin(math.radians(angle))
        pos = np.column_stack([
            -0.04 + 0.04*rng.random(n),
            (0.1 + 0.8*rng.random(n))*v_n*1e-3,
            -0.02 + 0.04*rng.random(n)])
        groups.append(lc.Group("a%d" % angle, pos, incident(angle), d))
    results = {}
    for n_outer in (2, 3):
        case = lc.make_case(os.path.join(work, "coupled%d" % n_outer),
                            groups, ESCAPE, lowerWall=ROUGH % "8",
                            cells=(1, 10, 1), end_time=0.002,
                            outer_correctors=n_outer, drag=True)
        run(case)
        results[n_outer] = particles(case, "0.002", fields=("U",))
    a, b = results[2]["U"], results[3]["U"]
    t.check(len(a) == 3*n and len(b) == 3*n, "coupled: all %d particles "
            "kept" % (3*n))
    t.check(bool(np.all(a[:, 1] > 0)), "coupled: every particle rebounded "
            "from lowerWall in the first step (U_y > 0)")
    sd = float(np.std(a[:, 1]))
    err = float(np.abs(a - b).max())
    t.check(sd > 0.01, "coupled: the rebounds are random (sd of U_y %.3f)"
            % sd)
    t.check(0 < err < 1e-6,
            "coupled: the air changes between the correctors (the "
            "particles' velocities differ between 2 and 3 correctors: %.1e "
            "> 0) but the facets do not: the draws are a function of the "
            "hit (largest difference %.1e m/s < 1e-6)" % (err, err))


def translating_mesh_library(work):
    """libroughWallTranslatingMesh.so for this platform (built once with
    wmake beside the test's work folder, from a copy of the source)."""
    root = os.path.join(os.path.dirname(work), "translatingMesh")
    lib = os.path.join(root, "lib", "libroughWallTranslatingMesh.so")
    source = os.path.join(t.HERE, "translatingMesh")
    stamp = os.path.join(root, "source")
    text = "".join(fc.read_text(os.path.join(dirpath, f))
                   for dirpath, _, files in sorted(os.walk(source))
                   for f in sorted(files))
    if os.path.exists(lib) and os.path.exists(stamp) \
            and fc.read_text(stamp) == text:
        return lib
    if os.path.exists(root):
        shutil.rmtree(root)
    shutil.copytree(source, os.path.join(root, "src"))
    env = dict(os.environ, ROUGHWALL_TEST_LIBBIN=os.path.join(root, "lib"))
    import subprocess
    out = subprocess.run(["wmake", "libso"], cwd=os.path.join(root, "src"),
                         env=env, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, universal_newlines=True)
    if out.returncode != 0 or not os.path.exists(lib):
        raise t.TestFailure("building the test's mesh mover failed:\n%s"
                            % out.stdout[-3000:])
    fc.write_text(stamp, text)
    return lib


def test_moving_wall(args, work):
    lib = translating_mesh_library(work)
    rng = np.random.default_rng(7)
    n = 500
    groups = flat_wall_groups(n, rng)
    # From y = 4.7 mm: no hit at the end of a time step (from 5 mm the
    # 30 deg group, U_y = -0.5 m/s, reaches the wall at t = 0.01 exactly,
    # where OpenFOAM-14 hands a few of them a wall velocity of zero)
    for g in groups:
        g.positions[:, 1] = 0.0047
    e, mu0, muD = 0.8, 0.4, 0.4
    Uw = np.array([-0.5, 0.0, 0.0])
    case = lc.make_case(os.path.join(work, "moving"), groups, ESCAPE,
                        lowerWall=ROUGH % "0")
    lc.write(case, "constant/dynamicMeshDict", "dictionary",
             "mover\n{\n    type            roughWallTranslatingMesh;\n"
             "    libs            (\"%s\");\n    velocity        "
             "(%r %r %r);\n}\n" % ((lib,) + tuple(Uw)))
    # The library in controlDict too: its stitcher is chosen before the
    # mover is read
    fc.replace_in_file(os.path.join(case, "system", "controlDict"),
                       r'^libs\s+\(', 'libs            ("%s" ' % lib)
    run(case)
    p = particles(case, "0.05")
    U = p["U"]
    d = diameters(case, "0.05", len(U))
    t.check(len(U) == 3*n, "moving wall: all %d particles kept (%d)"
            % (3*n, len(U)))
    # The mesh moved: the points at 0.05 are those at 0 + Uw t
    moved = os.path.exists(os.path.join(case, "0.05", "polyMesh", "points"))
    t.check(moved, "the mesh moved (0.05/polyMesh/points written)")
    for angle, dg in sorted(ANGLES.items()):
        g = np.abs(d - dg) < 1e-9
        v = np.array(incident(angle)) - Uw      # relative to the wall
        un, ut = -v[1], v[0]
        rolling = ut <= 3.5*mu0*(1 + e)*un
        vt = (5/7)*ut if rolling else ut - muD*(1 + e)*un
        expected = np.array([vt, e*un, 0.0]) + Uw
        err = np.abs(U[g] - expected).max()
        t.check(np.count_nonzero(g) == n and err < 1e-9,
                "moving wall, alpha = %d deg (%.2f deg relative to the wall, "
                "%s): U'' = V'' + Uw = (%.6f, %.6f, 0) for all %d particles "
                "(largest deviation %.1e < 1e-9)"
                % (angle, math.degrees(math.atan2(un, ut)),
                   "rolling" if rolling else "sliding", expected[0],
                   expected[1], np.count_nonzero(g), err))


SKIPPED = []


def test_outside_range(args, work):
    """lowerWall's Delta from the envelope of a trace of 101 points 1 um
    apart (tabulated for 1 to 50 um: docs/roughWallInteraction.md), 80 um
    particles injected and hitting it at x > 0 only: on two processors
    (x-slabs split at x = 0) every hit is on processor 1, whose warnings
    OpenFOAM does not print.  The master warns once, naming the patch and
    the diameters (80 to 80 um) and the range (1 to 50 um)."""
    n = 10
    pos = np.column_stack([0.01 + 0.004*np.arange(n), np.full(n, 0.005),
                           np.zeros(n)])
    case = lc.make_case(os.path.join(work, "outsideRange"),
                        [lc.Group("steep", pos, (0.1, -1.0, 0.0), 80e-6)],
                        ROUGH % "8",
                        lowerWall="type roughVelocity; e 0.8; mu0 0.4; "
                        "roughness { profile \"constant/shortTrace\"; }",
                        end_time=0.02, n_procs=2)
    fc.write_text(os.path.join(case, "constant", "shortTrace"), "".join(
        "%g %g\n" % (1e-6*i, 1e-7*(i % 3)) for i in range(101)))
    run(case, 2)
    log = fc.read_text(os.path.join(case, "log.foamRun"))
    warned = re.findall(r"Patch lowerWall \(entry lowerWall\): parcels of "
                        r"diameters (\S+) to (\S+) m hit the wall, outside "
                        r"the diameters (\S+) to (\S+) m", log)
    expected = [80e-6, 80e-6, 1e-6, 50e-6]
    t.check(len(warned) == 1 and all(
        abs(float(a)/b - 1) < 1e-3 for a, b in zip(warned[0], expected)),
        "hits on processor 1 only: warned once, 80 um outside 1 to 50 um "
        "(%s)" % warned)


def run_expect_error(case, label, patterns, skip=None):
    """foamRun stops with a message matching every pattern; skip (regex,
    reason): if the log matches regex the check is reported skipped (and
    recorded in SKIPPED) instead."""
    rc, _ = fc.run(case, ["foamRun"], "log.foamRun", check_rc=False)
    text = fc.read_text(os.path.join(case, "log.foamRun"))
    if skip and re.search(skip[0], text):
        print("skipped: %s" % skip[1], flush=True)
        SKIPPED.append(label)
        return
    found = [p for p in patterns if re.search(p, text)]
    t.check(rc != 0 and len(found) == len(patterns),
            "%s: foamRun stops (rc %s), the message names %s%s"
            % (label, rc, ", ".join(patterns),
               "" if len(found) == len(patterns) else
               " -- missing: %s; log tail:\n%s"
               % ([p for p in patterns if p not in found], text[-1500:])))


def test_bad_input(args, work):
    rng = np.random.default_rng(5)
    groups = flat_wall_groups(20, rng)
    base = "type roughVelocity; mu0 0.4; roughnessAngle 8; "
    cases = (
        ("e", base + "e 1.5;", [r"\be\b", r"\[0, 1\]", r"0/Lagrangian/cloud/U",
                                "lowerWall"]),
        ("muD", base + "e 0.8; muD 0.6;", [r"\bmuD\b", r"mu0", r"0/Lagrangian/cloud/U"]),
        ("unknown", base + "e 0.8; roughnesAngle 3;",
         [r"roughnesAngle", r"type roughVelocity", r"closest: roughnessAngle",
          r"0/Lagrangian/cloud/U"]),
        ("d", base + "e 0.8; d -1e-4;", [r"\bd\b", r"\[1e-09, 1\]",
                                         r"0/Lagrangian/cloud/U"]),
        ("noRoughness", "type roughVelocity; e 0.8; mu0 0.4;",
         [r"roughnessAngle", r"roughness", r"0/Lagrangian/cloud/U"]),
    )
    for name, cond, patterns in cases:
        case = lc.make_case(os.path.join(work, name), groups, ESCAPE,
                            lowerWall=cond, end_time=0.002)
        fc.block_mesh(case)
        run_expect_error(case, name, patterns)
    # A cloud without d: OpenFOAM-14's tracer cloud (no size, no mass; no
    # 0/Lagrangian/cloud/d). The condition is evaluated at the first step
    # (the tracers follow the air at rest and never reach the wall), so
    # the run stops there with the message naming the field, not later with
    # the registry's generic lookup failure; with d in the condition the
    # same case runs to its end. OpenFOAM-13 has no tracer cloud: every
    # cloud type of 13 is spherical and has d, the check cannot be reached
    # there and this part is skipped (it runs on 14).
    no_d = (
        ("noField", "", True),
        ("noFieldGivenD", " d 1e-4;", False),
    )
    for name, extra, fails in no_d:
        case = lc.make_case(os.path.join(work, name), groups, ESCAPE,
                            lowerWall=base + "e 0.8;" + extra,
                            end_time=0.002, write_d=False)
        fc.replace_in_file(os.path.join(case, "system", "controlDict"),
                           "kinematicParticleCloud", "tracerCloud")
        fc.block_mesh(case)
        if fails:
            # run_expect_error runs foamRun and checks its message; a
            # release without the tracer cloud stops before the condition
            run_expect_error(case, "tracer cloud without d",
                             [r"Patch lowerWall", r"type roughVelocity",
                              r"needs the particle diameter",
                              r"no field d",
                              r"0/Lagrangian/cloud/d",
                              r"d <diameter \[m\]>"],
                             skip=(r"Unknown function type tracerCloud",
                                   "a cloud without d (this release has no "
                                   "tracer cloud: every cloud type has d)"))
            if SKIPPED:
                break
        else:
            rc, _ = fc.run(case, ["foamRun"], "log.foamRun",
                           check_rc=False)
            text = fc.read_text(os.path.join(case, "log.foamRun"))
            t.check(rc == 0 and re.search(r"^End", text, re.M),
                    "tracer cloud without d, d 1e-4 in the condition: "
                    "foamRun runs to the end (rc %s)" % rc)
    # d in the condition replaces the cloud's field: with the table
    # ((100e-6 0) (300e-6 0)) -> Delta 0 and a d of 200 um the 60 deg group
    # rolls as in the smooth test, whatever the cloud's d
    check_smooth_rolling(
        work, groups, "dGiven",
        "type roughVelocity; e 0.8; mu0 0.4; roughnessAngle ((100e-6 20) "
        "(150e-6 20) (200e-6 0) (300e-6 0)); d 200e-6;",
        "d 200e-6 in the condition: the table's Delta(200 um) = 0 for the "
        "120 um particles (smooth rolling rebound, ")

    # eArgument is a keyword of type rough, so of this condition too: e a
    # Function1 of the normal impact speed, 0.8 at every speed of the hits
    # (0.5 to 0.87 m/s), on a smooth wall: the 60 deg group rolls as above
    # (oracle: the same closed form)
    check_smooth_rolling(
        work, groups, "eArgument",
        "type roughVelocity; mu0 0.4; e table ((0 0.8) (10 0.8)); "
        "eArgument normalSpeed; roughnessAngle 0;",
        "e as a Function1 of eArgument normalSpeed: accepted, and the smooth "
        "rolling rebound with e = 0.8 (")


def check_smooth_rolling(work, groups, name, lowerWall, what):
    """The 60 deg group on a wall that is smooth for it, e = 0.8, mu0 0.4:
    the rolling rebound's closed form, u_t (1 - 2/7) and 0.8 u_n, to 1e-12
    (the 20 particles of the group)"""
    case = lc.make_case(os.path.join(work, name), groups, ESCAPE,
                        lowerWall=lowerWall)
    run(case)
    U = particles(case, "0.05")["U"]
    d = diameters(case, "0.05", len(U))
    g = np.abs(d - ANGLES[60]) < 1e-9
    expected = np.array([(1 - 2/7)*0.5, 0.8*math.sin(math.radians(60)), 0])
    err = np.abs(U[g] - expected).max()
    t.check(np.count_nonzero(g) == 20 and err < 1e-12,
            "%sdeviation %.1e)" % (what, err))


def main():
    args = parse_args()
    work = os.path.abspath(args.work)
    for entry in os.listdir(work):
        path = os.path.join(work, entry)
        if os.path.isdir(path):
            shutil.rmtree(path)
    {"flatWall": test_flat_wall, "smooth": test_smooth,
     "energy": test_energy, "closedBox": test_closed_box,
     "badInput": test_bad_input,
     "outerCorrectors": test_outer_correctors,
     "movingWall": test_moving_wall,
     "outsideRange": test_outside_range}[args.test](args, work)


if __name__ == "__main__":
    t.main(main)
