#!/usr/bin/env python3
"""rebound, stick and rough on a moving wall against standardWallInteraction.

lowerWall moves at (-0.5, 0, 0) (a fixedValue carrier velocity on the wall:
the cloud's patchData hands it to the models).  Each type runs twice, with
roughWallInteraction and with OpenFOAM's standardWallInteraction, whose
rebound works on the velocity relative to the wall (U -= Up; U -= (1 + e)
U_n n; U -= mu U_t; U += Up):
  rebound e 0.7, mu 0.1   parcel fields U, active, positions identical bit
                          for bit (mu > 0: the tangential loss differs
                          between absolute and relative velocity)
  stick                   identical bit for bit
  rough, roughnessAngle 0, e 0.8, mu0 = muD = 10
                          against standard rebound e 0.8, mu 2/7: on a flat
                          wall a sphere without incident spin that ends
                          rolling keeps 5/7 of its tangential velocity
                          relative to the wall (model notes section 4:
                          j_t = -(2/7) u), which is standardWallInteraction's
                          law with mu = 2/7; U equal to 1e-12 m/s.

Usage: testMovingWallTypes.py --platform P [--cloud KIND] [--parcels N]
           [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import os

import numpy as np

from foamcase import testing as t
import foamcase as fc

WALL_VELOCITY = -0.5

#: label, roughWallInteraction entry, standardWallInteraction coefficients,
#: exact comparison
TYPES = [
    ("rebound", "type rebound; e 0.7; mu 0.1;", "type rebound; e 0.7; mu 0.1;",
     True),
    ("stick", "type stick;", "type stick;", True),
    ("rough", "type rough; e 0.8; mu0 10; muD 10; roughnessAngle 0;",
     "type rebound; e 0.8; mu %r;" % (2.0 / 7.0), False),
]


def rough_settings(entry):
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


def standard_settings(coeffs):
    return """patchInteractionModel standardWallInteraction;

standardWallInteractionCoeffs
{
    %s
}
""" % coeffs


def run(args, name, settings):
    case = t.wall_impact_case(fc.Platform(args.platform),
                              os.path.join(args.work, name), args.cloud,
                              parcels=args.parcels, settings=settings)
    t.set_wall_velocity(case, WALL_VELOCITY)
    case.mesh()
    case.solve()
    texts = {}
    for d in case.cloud_dirs("0.05"):
        for field in ("U", "active", "positions"):
            text = fc.read_text(os.path.join(d, field))
            texts[field] = text[text.index("// * *"):]
    return case, texts


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p)
    p.add_argument("--parcels", type=int, default=1000)
    return p.parse_args()


def test():
    args = parse_args()
    for label, rough, standard, exact in TYPES:
        case_r, texts_r = run(args, "rough_" + label, rough_settings(rough))
        case_s, texts_s = run(args, "standard_" + label,
                              standard_settings(standard))
        t.check("moves" in case_r.log() or label == "stick",
                "%s: the model reports the moving wall" % label)
        if exact:
            t.check(texts_r.keys() == texts_s.keys() and len(texts_r) == 3,
                    "%s: the same parcel fields written" % label)
            for field in texts_r:
                t.check(texts_r[field] == texts_s[field],
                        "%s on the moving wall: parcel field %s identical "
                        "to standardWallInteraction's" % (label, field))
        else:
            U_r = case_r.read_cloud("0.05", ["U"])["U"]
            U_s = case_s.read_cloud("0.05", ["U"])["U"]
            t.check(U_r.shape == U_s.shape and len(U_r) == 3 * args.parcels,
                    "%s: %d parcels in both runs" % (label, len(U_r)))
            diff = float(np.max(np.abs(U_r - U_s)))
            t.check(diff < 1e-12,
                    "%s on the moving wall: U equals standardWallInteraction's"
                    " rebound e 0.8, mu 2/7 relative to the wall (max |dU| "
                    "%.2g m/s)" % (label, diff))
            rel = U_r[:, 0] - WALL_VELOCITY
            t.check(bool(np.all(rel > 0)),
                    "%s: every parcel still moves along +x relative to the "
                    "wall" % label)


if __name__ == "__main__":
    t.main(test)
