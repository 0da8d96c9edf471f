#!/usr/bin/env python3
"""Rebound statistics of parcels fired at a flat rough wall.

Fires N parcels per incidence angle (10, 30, 60 deg, 1 m/s, no forces) at
lowerWall (e 0.8, mu0 = muD = 0.4, lateral tilt off) and reads their
velocities at the end time, when each has hit the wall exactly once.
Checks:
  - no parcel is lost, every parcel leaves the wall (v_y > 0);
  - mean and sd of k_n = -v''_y/v'_y and k_t = v''_x/v'_x (relative to the
    wall) per angle agree with the oracle (src/python/foamcase/roughWallOracle.py,
    an independent numpy Monte Carlo of the operator, 1e6 samples) within 4
    combined standard errors;
  - the statistics file (reduced over processors in parallel) counts every
    hit and its mean k_n, k_t, the impulse-weighted sum(v''_n)/sum|v'_n|,
    sum(v''_t)/sum|v'_t| with their four sums, and the energy loss equal
    those computed from the parcels (to 1e-8 relative, 1e-6 for the energy:
    the file has 12 digits);
  - spin: written for the colliding cloud, absent for the kinematic cloud;
  - --repeat: the meshed (and decomposed) case run once more writes the
    same parcels and statistics file, digit for digit (reproducible for a
    given decomposition).

With --wallVelocity u the wall moves at (u, 0, 0): the incidence angles
relative to the wall change (u = -0.5: 6.7, 20.1 and 40.9 deg) and k_n, k_t,
the energy loss and the reference are all taken relative to the wall.

Usage: testWallImpact.py --platform openfoam13|openfoam1912
           --cloud colliding|kinematic|DPM|MPPIC
           [--roughness "8" | --roughness "((100e-6 8) (120e-6 4))"]
           [--roughnessParameters "Rq 2.35e-6; RSm 105e-6; estimate closedForm;"]
           [--profile]
           [--parcels N] [--np N] [--wallVelocity u] [--repeat] [--work DIR]
--roughnessParameters: the wall given by its profile parameters
(roughness { ... } instead of roughnessAngle); the reference of each size
class is that of the constant Delta = atan(2 pi Rq / max(RSm, d)) of its
diameter (docs/roughWallInteraction.md, equation (1), evaluated here; so
the parameters must say estimate closedForm).
--profile: the wall given by a measured trace, roughness { profile
"constant/wallProfile"; } (a path relative to the case), the trace of
foamcase/roughnessProfileOracle.py; the reference of each size class is that of the
constant Delta(d) the rolling-sphere envelope gives for its diameter,
computed by that module's brute force (not by the library); the log must
state the tabulation.
--cloud: colliding (spin) and kinematic clouds in the frozen carrier
(openfoam13: foamRun, functions solver, collidingCloud / cloud; openfoam1912:
icoUncoupledKinematicParcelFoam / uncoupledKinematicParcelFoam); MPPIC
(openfoam13: MPPICCloud in the frozen carrier; openfoam1912: MPPICFoam,
air at rest, no forces on the parcels); DPM (openfoam1912 only: DPMFoam).
With --np N the case is split into N slabs along x; for
N = 2 at x = 0, through the injection region (x in [-0.04, 0]) and the
10 deg impact zone, so parcels cross the processor boundary and hit the wall
on both processors.  N = 3 gives the middle processor two processor patches
and the others one: the statistics must not depend on that.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os
import re
import shutil

import numpy as np

from foamcase import testing as t
from foamcase.testConstants import parcel_mass
import foamcase as fc
from foamcase import roughnessProfileOracle as profileOracle

END_TIME = "0.05"


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p)
    p.add_argument("--roughness", default="8")
    p.add_argument("--roughnessParameters", default=None,
                   help="roughness { Rq ...; RSm ...; estimate closedForm; }"
                        " (Rq and RSm only)")
    p.add_argument("--profile", action="store_true",
                   help="roughness { profile \"constant/wallProfile\"; }")
    p.add_argument("--parcels", type=int, default=10000)
    p.add_argument("--np", type=int, default=1)
    p.add_argument("--wallVelocity", type=float, default=0.0,
                   help="lowerWall moves at (wallVelocity 0 0)")
    p.add_argument("--incidenceAngleBins", type=int, default=0,
                   help="set incidenceAngleBins and check the angle file "
                   "against the parcels (t.check_angle_bins)")
    p.add_argument("--repeat", action="store_true",
                   help="run the meshed (and decomposed) case a second time "
                        "and require the same parcels and statistics file")
    return p.parse_args()


def roughness_at(text, d):
    """Delta [deg] of the roughnessAngle entry for diameter d."""
    numbers = [float(x) for x in text.replace("(", " ").replace(")", " ").split()]
    if len(numbers) == 1:
        return numbers[0]
    table = np.array(numbers).reshape(-1, 2)
    return float(np.interp(d, table[:, 0], table[:, 1]))


def settings(roughness, parameters=None, profile=False):
    if profile:
        return t.DEFAULT_SETTINGS.replace(
            "roughnessAngle  8;",
            'roughness { profile "constant/wallProfile"; }')
    if parameters:
        return t.DEFAULT_SETTINGS.replace("roughnessAngle  8;",
                                          "roughness { %s }" % parameters)
    return t.DEFAULT_SETTINGS.replace("roughnessAngle  8;",
                                      "roughnessAngle  %s;" % roughness)


def profile_delta(parameters, d):
    """Delta [deg] of roughness { Rq ...; RSm ...; } for diameter d:
    atan(2 pi Rq / max(RSm, d)), typed from docs/roughWallInteraction.md"""
    values = dict(item.split() for item in parameters.split(";")
                  if item.strip())
    assert values.get("estimate") == "closedForm"
    Rq = float(values["Rq"])
    RSm = float(values["RSm"])
    return math.degrees(math.atan(2 * math.pi * Rq / max(RSm, d)))


def test():
    args = parse_args()
    platform = fc.Platform(args.platform)
    spin = fc.SPIN[args.cloud]
    case = t.wall_impact_case(platform, os.path.join(args.work, "case"),
                              args.cloud, parcels=args.parcels,
                              settings=settings(args.roughness,
                                                args.roughnessParameters,
                                                args.profile))
    if args.profile:
        profileOracle.write_profile(case.file("constant/wallProfile"))
    if args.wallVelocity:
        t.set_wall_velocity(case, args.wallVelocity)
    if args.incidenceAngleBins:
        fc.replace_in_file(case.file("constant/roughWallSettings"),
                           r"^roughWallInteractionCoeffs\n\{\n",
                           "roughWallInteractionCoeffs\n{\n    "
                           "incidenceAngleBins %d;\n"
                           % args.incidenceAngleBins)
    case.mesh(args.np)
    if args.repeat:
        repeat = os.path.join(args.work, "repeat")
        if os.path.exists(repeat):
            shutil.rmtree(repeat)
        shutil.copytree(case.path, repeat)
    case.solve()
    # The compile-time choice of spin, as the log states it (fc.SPIN: the
    # test's own table of the clouds whose parcels carry angularMomentum)
    carries = ("Rough-wall parcels carry spin: "
               + ("yes (angularMomentum)" if spin else "no"))
    t.check(carries in case.log(), "the log says '%s'" % carries)
    if args.profile:
        t.check(bool(re.search(r"roughness: Delta\(d_p\) of the rolling-sphere "
                               r"envelope of the profile \S*wallProfile "
                               r"\(%d points, levelled\) tabulated at \d+ "
                               r"diameters" % profileOracle.POINTS,
                               case.log())),
                "the log states the profile's tabulation")

    if args.np > 1:
        t.check(bool(re.search(r"nProcs\s*:\s*%d\b" % args.np, case.log())),
                "the run was parallel on %d processors" % args.np)
        counts = [len(fc.read_field(os.path.join(dd, "d")))
                  if os.path.exists(os.path.join(dd, "d")) else 0
                  for dd in case.cloud_dirs(END_TIME)]
        t.check(len(counts) == args.np and min(counts) > 0,
                "every processor holds parcels at the end (%s)" % counts)

    fields = ["U", "d", "rho", "nParticle"]
    if spin:
        fields.append("angularMomentum")
    parcels = case.read_cloud(END_TIME, fields)
    U = parcels["U"]
    d = parcels["d"]
    n_total = len(t.ANGLES) * args.parcels

    t.check(len(U) == n_total,
            "all %d parcels are still in the domain (found %d)"
            % (n_total, len(U)))
    t.check(bool(np.all(U[:, 1] > 0)),
            "every parcel leaves the wall (min v_y = %.3g)" % U[:, 1].min())
    t.check(bool(np.all(U[:, 2] == 0)),
            "no out-of-plane velocity without lateral tilt (max |v_z| = %.3g)"
            % np.abs(U[:, 2]).max())

    spin_files = [os.path.join(dd, "angularMomentum")
                  for dd in case.cloud_dirs(END_TIME)]
    if spin:
        L = parcels["angularMomentum"]
        t.check(np.count_nonzero(L[:, 2]) > 0.9 * n_total,
                "spin is written (non-zero for %d of %d parcels)"
                % (np.count_nonzero(L[:, 2]), n_total))
    else:
        t.check(not any(os.path.exists(f) for f in spin_files),
                "a kinematic cloud stores no spin")

    # Rebound statistics per angle against the oracle
    def reference_of_angle(angle, d_angle):
        if args.profile:
            delta = math.degrees(profileOracle.delta(d_angle))
            print("Delta(%g m) of the profile (brute-force envelope): %.4f deg"
                  % (d_angle, delta))
        elif args.roughnessParameters:
            delta = profile_delta(args.roughnessParameters, d_angle)
        else:
            delta = roughness_at(args.roughness, d_angle)
        return t.reference(spin, delta, [angle])[angle], delta

    kn_all, kt_all = t.check_rebound_statistics(
        U, d, args.parcels, reference_of_angle,
        wall_velocity=args.wallVelocity)

    # The statistics file against the parcels
    mass = parcel_mass(d, parcels["nParticle"], parcels["rho"])
    # Relative to the wall
    U_rel = U - np.array([args.wallVelocity, 0, 0])
    incident = np.empty_like(U)
    for angle, d_angle in t.ANGLES.items():
        incident[np.abs(d - d_angle) < 1e-9] = \
            t.incident_velocity(angle, args.wallVelocity)
    energy_loss = 0.5 * mass * (np.sum(incident**2, axis=1)
                                - np.sum(U_rel**2, axis=1))
    if spin:
        inertia = 0.1 * mass * d**2
        energy_loss -= 0.5 * np.sum(L**2, axis=1) / inertia
    _, rows = case.read_statistics()
    last = rows[-1]

    def col(name):
        return fc.column(last, name)

    def close(a, b, rel=1e-8):
        return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)

    t.check(col("lowerWall_hits") == n_total,
            "statistics file: lowerWall_hits = %d" % col("lowerWall_hits"))
    escaped = col("outlet_nEscape") + last.get("escapedParcels", 0)
    t.check(col("upperWall_hits") == 0 and escaped == 0,
            "statistics file: no hits on upperWall, no escapes")
    t.check(close(col("lowerWall_meanKn"), kn_all.mean()),
            "statistics file: meanKn %.10g = parcels' %.10g"
            % (col("lowerWall_meanKn"), kn_all.mean()))
    t.check(close(col("lowerWall_meanKt"), kt_all.mean()),
            "statistics file: meanKt %.10g = parcels' %.10g"
            % (col("lowerWall_meanKt"), kt_all.mean()))
    # Impulse-weighted ratios: oracle from the parcels' incident and rebound
    # velocities (relative to the wall, n = y, t = the incident tangential
    # direction, here x; every incidence of the test has a k_t)
    vn_in = np.abs(incident[:, 1]).sum()
    vn_out = U_rel[:, 1].sum()
    vt_in = np.abs(incident[:, 0]).sum()
    vt_out = (U_rel[:, 0]*np.sign(incident[:, 0])).sum()
    for name, value in (("sumVnIn", vn_in), ("sumVnOut", vn_out),
                        ("sumVtIn", vt_in), ("sumVtOut", vt_out),
                        ("impulseKn", vn_out/vn_in),
                        ("impulseKt", vt_out/vt_in)):
        t.check(close(col("lowerWall_" + name), value),
                "statistics file: %s %.10g = parcels' %.10g"
                % (name, col("lowerWall_" + name), value))
    t.check(abs(col("lowerWall_impulseKn") - col("lowerWall_meanKn"))
            > 1e-3*col("lowerWall_meanKn"),
            "impulse-weighted k_n %.6g differs from the mean of k_n %.6g "
            "(the test tells them apart)"
            % (col("lowerWall_impulseKn"), col("lowerWall_meanKn")))
    t.check(close(col("lowerWall_energyLoss"), energy_loss.sum(), 1e-6),
            "statistics file: energyLoss %.10g = parcels' %.10g"
            % (col("lowerWall_energyLoss"), energy_loss.sum()))
    per_hit = (col("lowerWall_noSlip") + col("lowerWall_sliding")) / n_total
    t.check(close(col("lowerWall_facetPerHit"), per_hit, 1e-10)
            and 1 <= per_hit < 1.5,
            "statistics file: facetPerHit %.6f = (noSlip + sliding)/hits"
            % per_hit)

    if args.incidenceAngleBins:
        # (summed over the processors: each holds some of the hits)
        _, angle_rows = case.read_statistics(fc.ANGLE_STATISTICS)
        Nw = np.broadcast_to([0.0, 1.0, 0.0], U.shape)
        t.check_angle_bins(angle_rows, "lowerWall", incident, U_rel, Nw,
                           last, args.incidenceAngleBins)

    if args.repeat:
        check_repeat(case, repeat)


def check_repeat(case, repeat):
    """The same case run again on the same decomposition gives the same
    parcels and statistics file, digit for digit: the draws depend on the
    processor, the parcels and their order, which a repeat keeps (oracle:
    the first run's files)."""
    fc.run(repeat, case.run_args(), "log.solver")
    files = [os.path.relpath(os.path.join(root, name), case.path)
             for root, _, names in os.walk(case.path) for name in names
             if os.sep + END_TIME + os.sep in os.path.join(root, name) + os.sep
             and os.sep + "lagrangian" + os.sep in root + os.sep]
    files.append(os.path.relpath(case.statistics_file("0"), case.path))
    differ = [f for f in files
              if fc.read_text(os.path.join(case.path, f))
              != fc.read_text(os.path.join(repeat, f))]
    t.check(len(files) > 4 and not differ,
            "the repeat on %d processor(s) writes the same %d files "
            "(parcels at t = %s, statistics)%s"
            % (case.nprocs, len(files), END_TIME,
               ": these differ: %s" % differ if differ else ""))


if __name__ == "__main__":
    t.main(test)
