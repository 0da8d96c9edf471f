"""Shared helpers of the horizontalChannel tutorial's scripts.

The OpenFOAM readers are the project's one module for OpenFOAM output,
tests/openfoam/foamTestCase.py (read_field for list files, MeshGeometry,
read_statistics). What it does not read is here: the internal field and the
values on one patch of a field file (read_field reads list files), and the
positions of many parcels at once (the barycentric formula of
foamTestCase.MeshGeometry.positions, vectorised: that one loops over the
parcels in Python, too slow for 10^5 samples per snapshot series).

SPDX-License-Identifier: GPL-3.0-or-later
"""
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TUTORIAL = os.path.dirname(HERE)
# The repository: $ROUGHWALL_ROOT (set by Alltest, which runs a copy of the
# tutorial elsewhere), else three levels up
REPO = os.environ.get("ROUGHWALL_ROOT") or \
    os.path.abspath(os.path.join(TUTORIAL, "..", "..", ".."))
sys.path.insert(0, os.path.join(REPO, "tests", "openfoam"))

import foamTestCase as ftc  # noqa: E402

#: Name of the cloud (the clouds fvModel's default)
CLOUD = "cloud"
WALLS = ("lowerWall", "upperWall")

read_field = ftc.read_field       # lists: lagrangian fields, points
MeshGeometry = ftc.MeshGeometry
read_statistics = ftc.read_statistics


def internal_field(path, n_cells=None):
    """The internal field of a volScalarField or volVectorField: (n,) or
    (n, 3) (foamTestCase.read_field reads list files; a field file's first
    list is followed by its boundaryField)."""
    body = ftc._body(ftc.read_text(path))
    m = re.search(r"internalField\s+uniform\s+(\([^)]*\)|%s)\s*;" % ftc.NUMBER,
                  body)
    if m:
        if n_cells is None:
            raise ValueError("%s: uniform internalField, number of cells "
                             "needed" % path)
        v = np.array(m.group(1).strip("()").split(), float)
        return np.tile(v, (n_cells, 1)) if len(v) > 1 else np.full(n_cells, v[0])
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(",
                  body)
    if not m:
        raise ValueError("%s: no internalField" % path)
    width = {"scalar": 1, "vector": 3}[m.group(1)]
    n = int(m.group(2))
    end = body.index("boundaryField", m.end())
    values = np.array(body[m.end():end].replace("(", " ").replace(")", " ")
                      .replace(";", " ").split()[:n*width], float)
    return values.reshape(n, width) if width > 1 else values


def patch_values(path, patch):
    """Values of a volScalarField on one patch: (n,) array (uniform: one
    value)."""
    body = ftc._body(ftc.read_text(path))
    i = body.index("boundaryField")
    m = re.search(r"\b" + re.escape(patch) + r"\s*\{", body[i:])
    if not m:
        raise ValueError("%s: no patch %s" % (path, patch))
    block = body[i + m.end():]
    block = block[:block.index("}")]
    m = re.search(r"value\s+uniform\s+(\S+?)\s*;", block)
    if m:
        return np.array([float(m.group(1))])
    m = re.search(r"value\s+nonuniform\s+List<scalar>\s*(\d+)\s*\((.*?)\)",
                  block, re.S)
    if not m:
        raise ValueError("%s: no value on patch %s" % (path, patch))
    return np.array(m.group(2).split(), float)


class Mesh:
    """The geometry of one polyMesh, read once: cell centres, bounding box,
    and the conversion of barycentric parcel coordinates to positions."""

    def __init__(self, case):
        self.geometry = MeshGeometry(os.path.join(case, "constant",
                                                  "polyMesh"))
        g = self.geometry
        self.points = g.points
        self.cell_centres = g.cell_centres
        self.lo = g.points.min(axis=0)
        self.hi = g.points.max(axis=0)
        # Face i's points as a padded array (all faces of these hex meshes
        # have 4 points)
        n = max(len(f) for f in g.faces)
        self.face_points = np.full((len(g.faces), n), -1, dtype=int)
        self.face_size = np.array([len(f) for f in g.faces])
        for i, f in enumerate(g.faces):
            self.face_points[i, :len(f)] = f

    def positions(self, coords, cells, faces, tet_pts):
        """Cartesian positions of barycentric coordinates (a b c d) in the
        tets (cell, face, tetPt): tetIndices with the tet base point 0 of
        every face, as foamTestCase.MeshGeometry.positions, for all parcels
        at once."""
        g = self.geometry
        size = self.face_size[faces]
        i = tet_pts % size
        j = (i + 1) % size
        swap = g.owner[faces] != cells
        i, j = np.where(swap, j, i), np.where(swap, i, j)
        fp = self.face_points[faces]
        rows = np.arange(len(faces))
        p0 = self.points[fp[:, 0]]
        pi = self.points[fp[rows, i]]
        pj = self.points[fp[rows, j]]
        return (coords[:, :1]*self.cell_centres[cells] + coords[:, 1:2]*p0
                + coords[:, 2:3]*pi + coords[:, 3:4]*pj)


_NUMBER = ftc.NUMBER


def read_positions(path, mesh):
    """Cartesian positions (n, 3) of the parcels of an OpenFOAM-13
    'positions' file ('(a b c d) cell tetFace tetPt' per parcel)."""
    body = ftc._body(ftc.read_text(path))
    m = re.search(r"(\d+)\s*\(", body)
    if not m or int(m.group(1)) == 0:
        return np.zeros((0, 3))
    n = int(m.group(1))
    inner = body[m.end():body.rindex(")")]
    values = np.array(inner.replace("(", " ").replace(")", " ").split(),
                      dtype=float).reshape(n, 7)
    coords = values[:, :4]
    cells, faces, tets = (values[:, k].astype(int) for k in (4, 5, 6))
    if not (np.all(np.abs(coords.sum(axis=1) - 1) < 1e-6)
            and np.all(coords > -1e-6)):
        raise ValueError("%s: barycentric coordinates outside [0, 1] or not "
                         "summing to 1" % path)
    return mesh.positions(coords, cells, faces, tets)


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
