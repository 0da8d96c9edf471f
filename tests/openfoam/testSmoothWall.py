#!/usr/bin/env python3
"""Rough patches with roughnessAngle 0 (a smooth wall: one facet collision,
the wall itself, per hit), where the rebound of every parcel is a closed
form: the hard-sphere collision of the model notes, section 4, written in
this test (no call into the library or the oracle).

For a sphere of radius r = d/2 without incident spin meeting the wall
(normal N = +y into the fluid) with velocity V' = V'_t + V'_n, u_n = -V'.N:
  no slip  if |V'_t| <= (7/2) mu0 (1 + e) u_n:  V''_t = (5/7) V'_t,
           w'' = -(5/7) (N x V'_t)/r        (the contact point stops);
  sliding  otherwise:  V''_t = V'_t - muD (1 + e) u_n t,  t = V'_t/|V'_t|,
           w'' = -(5/2) muD (1 + e) u_n (N x t)/r;
  and V''.N = e u_n.  I = 0.1 m d^2 = (2/5) m r^2 (OpenFOAM's).
With spin w' about z only (2-D), the contact slip is u = V'_x + r w'_z
(N = +y): no slip if |u| <= (7/2) mu0 (1 + e) u_n, then
V''_x = V'_x - (2/7) u and w''_z = w'_z - (5/7) u/r.

--case impact (colliding cloud: the parcels carry spin), the parcels at
  10, 30 and 60 deg (1 m/s; 100, 110, 120 um):
  normalSpeed  e a table of the normal impact speed,
               e(s) = 0.95 - 0.4 s for s in [0, 1] m/s (eArgument
               normalSpeed), mu0 = muD = 0.4: k_n = e(sin alpha) = 0.8805,
               0.75, 0.6036; evaluated at the facet angle (10, 30, 60, beyond
               the table) e would be 0.55 for all three.  The 10 deg group
               slides, 30 and 60 deg roll.  The spin after the hit is the
               closed form with r = d/2 (the Function1 path of the
               coefficients with spin: a diameter handed over as the radius
               halves it).
  muDDefault   e 0.8, mu0 0.2 and no muD: the documented default is
               muD = mu0; the 10 and 30 deg groups slide (|V'_t| > (7/2)
               mu0 (1 + e) u_n), so their k_t = 1 - 0.36 tan(alpha) depends
               on it (muD 0 would give k_t = 1).
--case twoDSpin (colliding cloud, one cell thick): parcels at 30 deg given
  the spin w = (300, -200, -4000) rad/s after two steps (about all three
  axes), e 0.8, mu0 10 (no slip): the rough wall keeps the spin about z
  only (the docs' 2-D rule): V'' and w''_z are the closed form with w'_z,
  w''_x = w''_y = 0 exactly, and the log warns once, naming the patch, that
  the in-plane components were dropped.  Control: a group with spin about
  z only in a second run: the same closed form, no warning.  Then the first
  run on two processors with every parcel on the second one: one warning
  (OpenFOAM prints no warning of a processor other than the master).

Tolerance: 1e-11 m/s (relative 1e-10 for the spin).

Usage: testSmoothWall.py --platform P --case impact|twoDSpin
           [--parcels N] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os

import numpy as np

from foamcase import testing as t
import foamcase as fc

RHO_P = 2500.0
DT = 0.001
END = 0.05

#: e(s) of the normalSpeed case: 0.95 at 0, 0.55 at 1 m/s, linear
E_TABLE = ((0.0, 0.95), (1.0, 0.55))


def e_of_speed(s):
    return float(np.interp(s, [r[0] for r in E_TABLE],
                           [r[1] for r in E_TABLE]))


def settings(entry):
    return """patchInteractionModel roughWallInteraction;

roughWallInteractionCoeffs
{
    patches
    (
        "(lowerWall|upperWall)" { %s }
        outlet { type escape; }
    );
}
""" % entry


def velocity(angle):
    a = math.radians(angle)
    return np.array([math.cos(a), -math.sin(a), 0.0])


def inertia(d):
    return 0.1 * RHO_P * math.pi / 6 * d**3 * d**2


def smooth_rebound(v, w, d, e, mu0, muD):
    """The hard-sphere rebound on the flat wall y = 0 (N = +y), incident
    spin w about z only (the other components are not used): V'', w''."""
    r = 0.5 * d
    N = np.array([0.0, 1.0, 0.0])
    un = -v[1]
    vt = np.array([v[0], 0.0, v[2]])
    # slip of the contact point: V'_t + w x (-r N)
    slip = vt + np.cross(np.array([0.0, 0.0, w[2]]), -r * N)
    ls = np.linalg.norm(slip)
    if ls <= 3.5 * mu0 * (1 + e) * un:
        jt = -(2.0 / 7.0) * slip
    else:
        jt = -muD * (1 + e) * un * slip / ls
    v1 = vt + jt + e * un * N
    # angular impulse about the centre: (-r N) x J / I, I = (2/5) m r^2
    w1 = np.array([0.0, 0.0, w[2]]) + np.cross(-r * N, jt) / (0.4 * r * r)
    return v1, w1


def run_case(args, platform, name, entry, groups, two_d=False, spins=None,
             x_range=(-0.04, 0.0), nprocs=1):
    """groups: {name: (angle, d)}; spins: {name: w} set after two steps;
    the parcels start at y = 5 mm, x in x_range; nprocs > 1: decomposed
    into x slabs (2: split at x = 0)."""
    case = fc.FoamCase(platform, t.WALL_IMPACT,
                       os.path.join(args.work, name), "colliding",
                       two_d=two_d)
    rng = np.random.default_rng(3)
    injectors = []
    for g, (angle, d) in groups.items():
        x = rng.uniform(x_range[0], x_range[1], args.parcels)
        z = np.zeros(args.parcels) if two_d \
            else rng.uniform(-0.015, 0.015, args.parcels)
        injectors.append(fc.Injector(g, np.column_stack(
            [x, np.full(args.parcels, 0.005), z]), velocity(angle), d))
    case.write_injectors(injectors)
    case.write_settings(settings(entry))
    case.mesh(nprocs)
    logs = ["log.solver"]
    if spins:
        case.set_control(deltaT=repr(DT), endTime=repr(2 * DT),
                         writeControl="timeStep", writeInterval="2")
        case.solve("log.solver.1")
        n = set_spins(case, "0.002", groups, spins)
        t.check(n == len(groups) * args.parcels,
                "%s: the spin of all %d parcels set at t = 0.002%s"
                % (name, n, "" if nprocs == 1 else ", all on processor%d"
                   % (nprocs - 1)))
        case.set_control(endTime=repr(END),
                         writeInterval=str(int(round(END / DT))))
        logs = ["log.solver.1", "log.solver.2"]
    case.solve(logs[-1])
    p = case.read_cloud(repr(END) if spins else "0.05",
                        ["U", "d", "angularMomentum"])
    t.check(len(p["d"]) == len(groups) * args.parcels,
            "%s: all %d parcels in the domain" % (name, len(p["d"])))
    return case, p, "".join(case.log(x) for x in logs)


def set_spins(case, time_name, groups, spins):
    count = 0
    for d_dir in case.cloud_dirs(time_name):
        path = os.path.join(d_dir, "angularMomentum")
        if not os.path.exists(path):
            continue
        d = np.atleast_1d(fc.read_field(os.path.join(d_dir, "d")))
        rows = []
        for di in d:
            g = [k for k in groups if abs(groups[k][1] - di) < 1e-3 * di]
            if len(g) != 1:
                raise t.TestFailure("parcel of d = %g in no group" % di)
            rows.append("(%r %r %r)" % tuple(inertia(di)
                                             * np.asarray(spins[g[0]])))
        text = fc.read_text(path)
        head = text[:text.index("}", text.index("FoamFile")) + 1]
        fc.write_text(path, head + "\n\n%d\n(\n%s\n)\n"
                      % (len(d), "\n".join(rows)))
        count += len(d)
    return count


def check_group(label, p, d, v0, w0, e, mu0, muD):
    k = np.abs(p["d"] - d) < 1e-3 * d
    v1, w1 = smooth_rebound(v0, w0, d, e, mu0, muD)
    U = p["U"][k]
    w = p["angularMomentum"][k] / inertia(d)
    err_v = float(np.abs(U - v1).max())
    err_w = float(np.abs(w - w1).max()) / max(np.abs(w1).max(), 1e-300)
    t.check(np.count_nonzero(k) > 0 and err_v < 1e-11 and err_w < 1e-10,
            "%s: V'' = (%.6f, %.6f, %.6f), w''_z r/V = %.6f for all %d "
            "parcels (largest deviations %.1e m/s, %.1e relative)"
            % (label, v1[0], v1[1], v1[2], w1[2] * 0.5 * d,
               np.count_nonzero(k), err_v, err_w))
    return w


def test_impact(args, platform):
    groups = {"a10": (10, 100e-6), "a30": (30, 110e-6), "a60": (60, 120e-6)}
    table = "table ((%r %r) (%r %r))" % (E_TABLE[0] + E_TABLE[1])
    # e of the normal speed, mu0 = muD = 0.4
    _, p, _ = run_case(args, platform, "normalSpeed",
                       "type rough; e %s; eArgument normalSpeed; mu0 0.4; "
                       "muD 0.4; roughnessAngle 0;" % table, groups)
    for g, (angle, d) in groups.items():
        v0 = velocity(angle)
        e = e_of_speed(-v0[1])
        check_group("e(normal speed), alpha = %d deg: e(%.4f m/s) = %.4f"
                    % (angle, -v0[1], e), p, d, v0, np.zeros(3), e, 0.4, 0.4)
    # muD omitted: muD = mu0 (the docs)
    _, p, log = run_case(args, platform, "muDDefault",
                         "type rough; e 0.8; mu0 0.2; roughnessAngle 0;",
                         groups)
    for g, (angle, d) in groups.items():
        v0 = velocity(angle)
        sliding = -v0[1] * 3.5 * 0.2 * 1.8 < v0[0]
        check_group("muD omitted (= mu0 = 0.2), alpha = %d deg (%s)"
                    % (angle, "sliding" if sliding else "no slip"),
                    p, d, v0, np.zeros(3), 0.8, 0.2, 0.2)


def test_two_d_spin(args, platform):
    warning = "Patch lowerWall: parcels arrive with spin about an axis in " \
              "the plane of this 2-D case"
    w_in_plane = (300.0, -200.0, -4000.0)
    # parallel: two processors split at x = 0, every parcel on processor1
    # (x from 10 to 30 mm, hits at x + 8.7 mm): the warning is given once
    # all the same (a warning of processor1 alone would not be printed)
    for name, w0, nprocs, x_range in (
            ("inPlane", w_in_plane, 1, (-0.04, 0.0)),
            ("aboutZ", (0, 0, -4000.0), 1, (-0.04, 0.0)),
            ("inPlaneParallel", w_in_plane, 2, (0.01, 0.03))):
        groups = {"a30": (30, 110e-6)}
        case, p, log = run_case(args, platform, name,
                                "type rough; e 0.8; mu0 10; muD 10; "
                                "roughnessAngle 0;", groups, two_d=True,
                                spins={"a30": w0}, nprocs=nprocs,
                                x_range=x_range)
        if nprocs > 1:
            on_last = case.read_cloud("0.002", ["d"])
            t.check(not any(os.path.exists(os.path.join(d, "d"))
                            for d in case.cloud_dirs("0.002")[:-1]),
                    "%s: all %d parcels on the last processor at t = 0.002"
                    % (name, len(on_last["d"])))
        w = check_group("2-D, spin %s rad/s at 30 deg: the closed form with "
                        "the spin about z only" % (w0,), p, 110e-6,
                        velocity(30), np.asarray(w0, float), 0.8, 10, 10)
        t.check(bool(np.all(w[:, :2] == 0)),
                "%s: w''_x = w''_y = 0 exactly after the hit" % name)
        count = log.count(warning)
        if name != "aboutZ":
            t.check(count == 1,
                    "%s: the log warns once, naming lowerWall, that the "
                    "in-plane spin is dropped (%d times)" % (name, count))
        else:
            t.check(count == 0, "%s: no warning without in-plane spin (%d)"
                    % (name, count))


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p, kinds=False)
    p.add_argument("--case", required=True, choices=["impact", "twoDSpin"])
    p.add_argument("--parcels", type=int, default=100)
    return p.parse_args()


def test():
    args = parse_args()
    platform = fc.Platform(args.platform)
    {"impact": test_impact, "twoDSpin": test_two_d_spin}[args.case](
        args, platform)


if __name__ == "__main__":
    t.main(test)
