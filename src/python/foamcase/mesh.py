"""The geometry of a polyMesh: points, faces, owners, neighbours, cell
centres computed as OpenFOAM's primitiveMesh does, and the conversion of
OpenFOAM-13's barycentric parcel coordinates into positions.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import os
import re

import numpy as np

from .dictionaries import read_text, strip_header
from .fields import read_field


class MeshGeometry:
    """Points, faces, owners and cell centres of a polyMesh (ASCII), enough
    to turn barycentric parcel coordinates into positions."""

    def __init__(self, poly_mesh):
        self.points = read_field(os.path.join(poly_mesh, "points"))
        body = strip_header(read_text(os.path.join(poly_mesh, "faces")))
        self.faces = [[int(i) for i in f.split()]
                      for f in re.findall(r"\d+\(([\d\s]+)\)", body)]
        self.owner = read_field(os.path.join(poly_mesh, "owner")).astype(int)
        neighbour = read_field(os.path.join(poly_mesh, "neighbour"))
        self.neighbour = neighbour.astype(int)
        self.n_cells = int(self.owner.max()) + 1 if len(self.owner) else 0
        self.cell_centres = self._cell_centres()
        #: The bounding box
        self.lo = self.points.min(axis=0)
        self.hi = self.points.max(axis=0)
        # Face i's points as a padded array, for positions() of many parcels
        width = max(len(f) for f in self.faces)
        self.face_points = np.full((len(self.faces), width), -1, dtype=int)
        self.face_size = np.array([len(f) for f in self.faces])
        for i, f in enumerate(self.faces):
            self.face_points[i, :len(f)] = f

    def _cell_centres(self):
        """OpenFOAM's face and cell centres (primitiveMesh)."""
        nf = len(self.faces)
        fc = np.zeros((nf, 3))
        fa = np.zeros((nf, 3))
        # The faces of one size at a time, as arrays (meshes have one or
        # two sizes; a loop over faces took half a second per mesh)
        sizes = np.array([len(f) for f in self.faces])
        for size in np.unique(sizes):
            which = np.flatnonzero(sizes == size)
            p = self.points[np.array([self.faces[i] for i in which])]
            if size == 3:
                fc[which] = p.mean(axis=1)
                fa[which] = 0.5*np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
                continue
            est = p.mean(axis=1, keepdims=True)
            q = np.roll(p, -1, axis=1)
            c = p + q + est
            n = np.cross(q - p, est - p)
            a = np.linalg.norm(n, axis=2)
            fc[which] = (a[:, :, None]*c).sum(axis=1)/(3*a.sum(axis=1))[:, None]
            fa[which] = 0.5*n.sum(axis=1)
        nc = self.n_cells
        nn = len(self.neighbour)
        count = np.zeros(nc)
        est = np.zeros((nc, 3))
        np.add.at(est, self.owner, fc)
        np.add.at(count, self.owner, 1)
        np.add.at(est, self.neighbour, fc[:nn])
        np.add.at(count, self.neighbour, 1)
        est /= count[:, None]
        vol = np.zeros(nc)
        ctr = np.zeros((nc, 3))
        v = np.einsum("ij,ij->i", fa, fc - est[self.owner])
        np.add.at(vol, self.owner, v)
        np.add.at(ctr, self.owner,
                  v[:, None]*(0.75*fc + 0.25*est[self.owner]))
        own = self.neighbour
        v = np.einsum("ij,ij->i", fa[:nn], est[own] - fc[:nn])
        np.add.at(vol, own, v)
        np.add.at(ctr, own, v[:, None]*(0.75*fc[:nn] + 0.25*est[own]))
        return ctr/vol[:, None]

    def positions(self, coords, cells, faces, tet_pts):
        """Cartesian positions (n, 3) of barycentric coordinates (a b c d)
        (n, 4) in the tets (cell, face, tetPt): OpenFOAM's
        tetIndices::faceTriIs with the tet base point 0 of every face (the
        first valid one for the convex faces of these meshes)."""
        coords = np.asarray(coords, dtype=float).reshape(-1, 4)
        cells = np.asarray(cells, dtype=int)
        faces = np.asarray(faces, dtype=int)
        size = self.face_size[faces]
        i = np.asarray(tet_pts, dtype=int) % size
        j = (i + 1) % size
        swap = self.owner[faces] != cells
        i, j = np.where(swap, j, i), np.where(swap, i, j)
        fp = self.face_points[faces]
        rows = np.arange(len(faces))
        return (coords[:, :1]*self.cell_centres[cells]
                + coords[:, 1:2]*self.points[fp[:, 0]]
                + coords[:, 2:3]*self.points[fp[rows, i]]
                + coords[:, 3:4]*self.points[fp[rows, j]])
