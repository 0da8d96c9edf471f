#!/usr/bin/env python3
"""A 2-D case (one cell thick, empty front and back) gets nothing out of its
plane.

Fires N parcels per incidence angle (10, 30, 60 deg, in the x-y plane) at a
rough lowerWall with lateralTilt ON, in a one-cell-thick mesh.  Checks:
  - the log warns, for each wall, that lateralTilt has no effect in 2-D;
  - every parcel is kept, hits the wall once and leaves it;
  - v_z == 0 and (cloud with spin) omega_x == omega_y == 0 exactly for every
    parcel, while the spin about z is non-zero.  (OpenFOAM itself also zeroes
    v_z after every sub-step in KinematicParcel::calc; it does not constrain
    the spin, so the spin check is the one that sees the adapter.);
  - the in-plane statistics of k_n, k_t agree within 4 standard errors with
    the reference WITHOUT lateral tilt: a lateral tilt leaking into 2-D would
    shift mean k_n by about 5.5 standard errors at 30 and 60 deg with the
    default N = 30000.
Control on the 3-D mesh with the same settings: no such warning, v_z (and
omega_x) are non-zero for most parcels and the statistics agree with the
reference WITH lateral tilt.

--oneD: a 1-D mesh instead (one cell in x and z, empty on four sides): a
rough patch there has no plane to keep the parcels in, and the run must
stop at start-up with a message saying that the rough wall needs a 2-D or
3-D mesh and that this one solves 1 direction (as a 3-D mesh it would run
with rebounds out of the column; as a 2-D one it would keep one of its two
empty directions).

Usage: testTwoD.py --platform openfoam13|openfoam1912 --cloud colliding|kinematic
           [--parcels N] [--parcels3D N] [--oneD] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import os
import re

import numpy as np

from foamcase import testing as t
import foamcase as fc

END_TIME = "0.05"

# The warning for lateralTilt true on a 2-D mesh (roughWallPatchSettings)
NO_EFFECT = "lateralTilt true has no effect on this 2-D mesh"

SETTINGS = t.DEFAULT_SETTINGS.replace(
    "roughnessAngle  8;", "roughnessAngle  8;\n            lateralTilt     true;")


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p)
    p.add_argument("--parcels", type=int, default=30000)
    p.add_argument("--parcels3D", type=int, default=10000)
    p.add_argument("--oneD", action="store_true")
    return p.parse_args()


ONE_D_MESH = """
scale   1;

vertices
(
    (-0.005 0   -0.005) ( 0.005 0   -0.005) ( 0.005 0.1 -0.005)
    (-0.005 0.1 -0.005) (-0.005 0    0.005) ( 0.005 0    0.005)
    ( 0.005 0.1  0.005) (-0.005 0.1  0.005)
);

blocks
(
    hex (0 1 2 3 4 5 6 7) (1 10 1) simpleGrading (1 1 1)
);

boundary
(
    lowerWall { type wall; faces ((0 1 5 4)); }
    upperWall { type wall; faces ((3 7 6 2)); }
    sides
    {
        type empty;
        faces ((0 4 7 3) (1 2 6 5) (0 3 2 1) (4 5 6 7));
    }
);
"""


def one_d_refused(args):
    platform = fc.Platform(args.platform)
    case = fc.FoamCase(platform, t.WALL_IMPACT,
                       os.path.join(args.work, "case1D"), args.cloud)
    fc.write_text(case.file("system/blockMeshDict"),
                  fc.foam_header("dictionary", "blockMeshDict", "system")
                  + ONE_D_MESH)
    case.write_injectors([fc.Injector("down", [(0.0, 0.05, 0.0)],
                                      (0.0, -1.0, 0.0), 100e-6)])
    case.write_settings(t.DEFAULT_SETTINGS)
    case.mesh()
    rc, _ = case.solve(check_rc=False)
    log = case.log()
    message = "needs a 2-D or 3-D mesh; this mesh solves 1 direction(s)"
    t.check(rc != 0 and message in log,
            "1-D mesh: the run stops (rc %d) with '... %s'" % (rc, message))


def run_case(args, two_d, parcels):
    name = "case2D" if two_d else "case3D"
    case = t.wall_impact_case(fc.Platform(args.platform),
                              os.path.join(args.work, name), args.cloud,
                              two_d=two_d, parcels=parcels, settings=SETTINGS)
    case.mesh()
    case.solve()
    fields = ["U", "d"] + (["angularMomentum"] if fc.SPIN[args.cloud] else [])
    return case, case.read_cloud(END_TIME, fields)


def reference_function(args, lateral_tilt):
    rows = t.reference(fc.SPIN[args.cloud], 8, sorted(t.ANGLES),
                       lateral_tilt=lateral_tilt)
    return lambda angle, d: (rows[angle], 8)


def test():
    args = parse_args()
    if args.oneD:
        one_d_refused(args)
        return
    n_total = 3 * args.parcels

    case, parcels = run_case(args, True, args.parcels)
    t.check("2-D case: no lateral facet tilt" in case.log(),
            "the model reports the 2-D treatment in the log")
    warned = sorted(re.findall(r"Patch (\w+) \(entry .*?\): " + NO_EFFECT,
                               case.log()))
    t.check(warned == ["lowerWall", "upperWall"],
            "2-D: lateralTilt true warned of, once for each wall the rough "
            "entry covers and for no other patch (warned: %s)" % warned)

    U = parcels["U"]
    t.check(len(U) == n_total, "2-D: all %d parcels kept" % n_total)
    t.check(bool(np.all(U[:, 1] > 0)), "2-D: every parcel leaves the wall")
    _, rows = case.read_statistics()
    t.check(fc.column(rows[-1], "lowerWall_hits") == n_total,
            "2-D: every parcel hit the wall once")
    t.check(bool(np.all(U[:, 2] == 0)),
            "2-D: v_z == 0 exactly for every parcel (max |v_z| = %g)"
            % np.abs(U[:, 2]).max())
    if fc.SPIN[args.cloud]:
        L = parcels["angularMomentum"]
        t.check(bool(np.all(L[:, 0] == 0) and np.all(L[:, 1] == 0)),
                "2-D: omega_x == omega_y == 0 exactly for every parcel "
                "(max %g)" % np.abs(L[:, :2]).max())
        t.check(np.count_nonzero(L[:, 2]) > 0.9 * n_total,
                "2-D: spin about z is non-zero for %d of %d parcels"
                % (np.count_nonzero(L[:, 2]), n_total))
    t.check_rebound_statistics(U, parcels["d"], args.parcels,
                               reference_function(args, False),
                               "2-D, lateralTilt on, vs in-plane reference: ")

    # Control: the lateral tilt does act in 3-D
    case3, parcels3 = run_case(args, False, args.parcels3D)
    t.check(NO_EFFECT not in case3.log(),
            "3-D control: no warning that lateralTilt has no effect")
    U3 = parcels3["U"]
    t.check(len(U3) == 3 * args.parcels3D, "3-D control: all parcels kept")
    t.check(np.count_nonzero(U3[:, 2]) > 0.9 * len(U3),
            "3-D control with lateralTilt: v_z != 0 for %d of %d parcels"
            % (np.count_nonzero(U3[:, 2]), len(U3)))
    if fc.SPIN[args.cloud]:
        L3 = parcels3["angularMomentum"]
        t.check(np.count_nonzero(L3[:, 0]) > 0.9 * len(L3),
                "3-D control with lateralTilt: omega_x != 0 for %d of %d"
                % (np.count_nonzero(L3[:, 0]), len(L3)))
    t.check_rebound_statistics(U3, parcels3["d"], args.parcels3D,
                               reference_function(args, True),
                               "3-D, lateralTilt on, vs lateral reference: ")


if __name__ == "__main__":
    t.main(test)
