#!/usr/bin/env python3
"""Parcels that arrive at the rough wall already spinning.

The wall-impact box (colliding cloud: parcels carry angularMomentum), lowerWall
rough (Delta 8 deg, e 0.8, mu0 = muD = 0.4).  The parcels are injected
without spin; after two time steps (before any reaches the wall) their
angularMomentum is rewritten (I w, I = 0.1 m d^2, m = rho pi d^3/6) and the
run goes on from that time to t = 0.05, when each has hit the wall once.
Groups, told apart by diameter, with the spin parameter A = r w_z / V'_x of
the paper (x = t along the incident tangential velocity, y = N, z = t x N):

  top30   30 deg, A = -1.5 (topspin: more than rolling forward)
  back30  30 deg, A = +1.5 (backspin)
  top60   60 deg, A = -1
  back60  60 deg, A = +2
  3-D only: skew45  45 deg, w = (0.7, 0.5, -0.6) V/r (about all three axes)

--twoD: the one-cell-thick case (spin about z only, no lateral tilt);
otherwise 3-D with lateralTilt on.  Oracle: roughWallOracle.rebound
(src/python/foamcase/roughWallOracle.py, an independent numpy Monte Carlo written
from the model notes) with the same incident velocity and angular velocity,
4e5 samples per group (PCG64, seed 11).  Compared per group, within 4
combined standard errors: mean and sd of k_n = -V''.N/V'.N,
k_t = V''_x/V'_x and k_Omega = r w''_z/V'_x; in 3-D also the means of
V''_z/|V'| and r w''_x/|V'|, r w''_y/|V'|.  A diameter handed to the
collision where the radius belongs doubles the spin's part of the contact
slip and halves the spin change; an angular momentum read as the angular
velocity makes the incident spin vanish: both move these statistics by
many standard errors.

Usage: testSpinAtWall.py --platform P [--twoD] [--parcels N] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os

import numpy as np

from foamcase import testing as t
import foamcase as fc
from foamcase import roughWallOracle as oracle
from foamcase.testConstants import sphere_inertia

E, MU0, MUD, DELTA_DEG = 0.8, 0.4, 0.4, 8.0
DT = 0.001
END = 0.05

#: name -> (incidence [deg], spin: ("A", A) about z or ("w", vector in V/r), d)
GROUPS = {
    "top30": (30, ("A", -1.5), 100e-6),
    "back30": (30, ("A", 1.5), 110e-6),
    "top60": (60, ("A", -1.0), 120e-6),
    "back60": (60, ("A", 2.0), 130e-6),
    "skew45": (45, ("w", (0.7, 0.5, -0.6)), 140e-6),
}


def settings(lateral):
    return """patchInteractionModel roughWallInteraction;

roughWallInteractionCoeffs
{
    patches
    (
        "(lowerWall|upperWall)"
        {
            type            rough;
            e               %g;
            mu0             %g;
            muD             %g;
            roughnessAngle  %g;
            lateralTilt     %s;
        }
        outlet { type escape; }
    );
}
""" % (E, MU0, MUD, DELTA_DEG, "true" if lateral else "false")


def velocity(angle):
    a = math.radians(angle)
    return np.array([math.cos(a), -math.sin(a), 0.0])


def spin_of(name):
    """Angular velocity [rad/s] of a group's parcels."""
    angle, (kind, value), d = GROUPS[name]
    r = 0.5 * d
    v = velocity(angle)
    if kind == "A":
        return np.array([0.0, 0.0, value * v[0] / r])
    return np.asarray(value) * np.linalg.norm(v) / r


def inertia(d):
    return sphere_inertia(d)


def set_spins(case, time_name, names):
    count = 0
    for d_dir in case.cloud_dirs(time_name):
        path = os.path.join(d_dir, "angularMomentum")
        if not os.path.exists(path):
            continue
        d = np.atleast_1d(fc.read_field(os.path.join(d_dir, "d")))
        rows = []
        for di in d:
            name = [g for g in names if abs(GROUPS[g][2] - di) < 1e-3 * di]
            if len(name) != 1:
                raise t.TestFailure("parcel of d = %g in no group" % di)
            rows.append("(%r %r %r)" % tuple(inertia(di) * spin_of(name[0])))
        text = fc.read_text(path)
        head = text[:text.index("}", text.index("FoamFile")) + 1]
        fc.write_text(path, head + "\n\n%d\n(\n%s\n)\n"
                      % (len(d), "\n".join(rows)))
        count += len(d)
    return count


def statistics(name, v1, w1, two_d):
    """The compared statistics of one group: {label: samples}."""
    angle, _, d = GROUPS[name]
    v0 = velocity(angle)
    r = 0.5 * d
    out = {"k_n": v1[:, 1] / -v0[1],
           "k_t": v1[:, 0] / v0[0],
           "k_Omega": r * w1[:, 2] / v0[0]}
    if not two_d:
        out["V''_z/V'"] = v1[:, 2]
        out["r w''_x/V'"] = r * w1[:, 0]
        out["r w''_y/V'"] = r * w1[:, 1]
    return out


def reference_statistics(names, two_d, samples=400000):
    """{group: {label: (mean, its s.e., sd, its s.e.)}} of the oracle's
    rebounds, samples per group (numpy's PCG64, seed 11)."""
    rng = np.random.default_rng(11)
    rows = {}
    for name in names:
        angle, _, d = GROUPS[name]
        ref = oracle.rebound(np.tile(velocity(angle), (samples, 1)),
                             np.tile(spin_of(name), (samples, 1)),
                             (0.0, 1.0, 0.0), d, E, MU0, MUD,
                             math.radians(DELTA_DEG), lateral=not two_d,
                             rng=rng,
                             plane_normal=(0.0, 0.0, 1.0) if two_d else None)
        want = statistics(name, ref.v, ref.omega, two_d)
        rows[name] = {label: t.sd_and_se(x) for label, x in want.items()}
    return rows


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p, kinds=False)
    p.add_argument("--twoD", action="store_true")
    p.add_argument("--parcels", type=int, default=4000)
    return p.parse_args()


def test():
    args = parse_args()
    platform = fc.Platform(args.platform)
    two_d = args.twoD
    names = [g for g in GROUPS if not (two_d and g == "skew45")]
    case = fc.FoamCase(platform, t.WALL_IMPACT,
                       os.path.join(args.work, "case"), "colliding",
                       two_d=two_d)
    rng = np.random.default_rng(5)
    injectors = []
    for name in names:
        angle, _, d = GROUPS[name]
        x = rng.uniform(-0.04, 0.0, args.parcels)
        z = np.zeros(args.parcels) if two_d \
            else rng.uniform(-0.015, 0.015, args.parcels)
        injectors.append(fc.Injector(name, np.column_stack(
            [x, np.full(args.parcels, 0.005), z]), velocity(angle), d))
    case.write_injectors(injectors)
    case.write_settings(settings(lateral=not two_d))
    case.mesh()

    # Two steps without spin, then the spin, then on to the end
    case.set_control(deltaT=repr(DT), endTime=repr(2 * DT),
                     writeControl="timeStep", writeInterval="2")
    case.solve("log.solver.1")
    t1 = "0.002"
    n = set_spins(case, t1, names)
    t.check(n == len(names) * args.parcels,
            "spin of all %d parcels set at t = %s" % (n, t1))
    before = case.read_cloud(t1, ["U", "d"])
    t.check(bool(np.all(before["U"][:, 1] < 0)),
            "no parcel has reached the wall at t = %s" % t1)
    case.set_control(endTime=repr(END), writeInterval=str(int(round(END / DT))))
    case.solve("log.solver.2")

    if two_d:
        # Control of testTwoD's warning: rough, lateralTilt false, 2-D
        t.check("lateralTilt true has no effect" not in
                case.log("log.solver.1") + case.log("log.solver.2"),
                "2-D without lateralTilt: no warning about it")

    p = case.read_cloud(repr(END), ["U", "d", "angularMomentum"])
    t.check(len(p["d"]) == len(names) * args.parcels,
            "all parcels in the domain at t = %g" % END)
    t.check(bool(np.all(p["U"][:, 1] > 0)), "every parcel left the wall")
    references = t.cached("spinAtWall", dict(names=names, two_d=two_d,
                                              test=t.source_hash(__file__)),
                          lambda: reference_statistics(names, two_d))
    for name in names:
        angle, _, d = GROUPS[name]
        k = np.abs(p["d"] - d) < 1e-3 * d
        t.check(np.count_nonzero(k) == args.parcels,
                "%s: %d parcels" % (name, args.parcels))
        v1 = p["U"][k]
        w1 = p["angularMomentum"][k] / inertia(d)
        if two_d:
            t.check(bool(np.all(v1[:, 2] == 0))
                    and bool(np.all(w1[:, :2] == 0)),
                    "%s: 2-D: no out-of-plane velocity, spin about z only"
                    % name)
        got = statistics(name, v1, w1, two_d)
        for label in got:
            mean, se, sd, se_sd = t.sd_and_se(got[label])
            rmean, rse, rsd, rse_sd = references[name][label]
            z = (mean - rmean) / max(math.hypot(se, rse), 1e-300)
            t.check(abs(z) <= t.TOLERANCE_SE,
                    "%s: mean %s = %.5f, oracle %.5f, |z| = %.2f"
                    % (name, label, mean, rmean, abs(z)))
            if label in ("k_n", "k_t", "k_Omega"):
                z = (sd - rsd) / max(math.hypot(se_sd, rse_sd), 1e-300)
                t.check(abs(z) <= t.TOLERANCE_SE,
                        "%s: sd %s = %.5f, oracle %.5f, |z| = %.2f"
                        % (name, label, sd, rsd, abs(z)))


if __name__ == "__main__":
    t.main(test)
