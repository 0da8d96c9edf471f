"""Shared helpers of the horizontalChannel tutorial's scripts.

The OpenFOAM readers are the project's package foamcase (src/python of the
checkout; Allrun puts it on PYTHONPATH, see there); what is the tutorial's
own is here.

SPDX-License-Identifier: GPL-3.0-or-later
"""
import os

import foamcase as fc

#: The checkout whose foamcase the scripts use (its tutorial is copied by
#: the tests that run it elsewhere)
REPO = os.path.abspath(os.path.join(os.path.dirname(fc.__file__), "..", "..",
                                    ".."))

#: Name of the cloud (the clouds fvModel's default)
CLOUD = "cloud"
WALLS = ("lowerWall", "upperWall")


def read_mesh(case):
    """The geometry of a case's constant/polyMesh."""
    return fc.MeshGeometry(os.path.join(case, "constant", "polyMesh"))


def read_case_info(case):
    """caseInfo of a tracking case (written by Allrun): key -> number or
    string."""
    info = {}
    with open(os.path.join(case, "caseInfo")) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                key, value = line.split(None, 1)
                value = value.strip()
                try:
                    info[key] = float(value)
                except ValueError:
                    info[key] = value
    return info
