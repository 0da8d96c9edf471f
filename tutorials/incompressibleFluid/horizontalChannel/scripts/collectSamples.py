#!/usr/bin/python3
"""Collect the parcel snapshots of one tracking run into parcelSamples.npz.

At every write time the run wrote all parcels (lagrangian/cloud: positions,
U, d, rho, angularMomentum, origId, origProcId, ...) and the wall impacts
counted by the patchCollisionDensity cloud function
(cloud:numberCollisionDensity). This script keeps what the statistics need
(time, height, the three velocity components, the spin vector, parcel key;
impacts per wall) in CASE/parcelSamples.npz. The snapshots are the bulk of a run's
output (about 2 MB per 10000 parcels per write time), so with --prune it then
removes every write time except the last one, which stays complete for a
restart and for viewing.

Usage: collectSamples.py CASE [--prune]
"""
import os
import re
import shutil
import sys

import numpy as np

import foamcase as fc
from foamcase import lagrangian
from foamcase import tutorial as tc


def write_times(case):
    """Write times (> 0) of a case, as (name, value), sorted by value."""
    return [(name, value) for value, name in lagrangian.time_dirs(case)
            if value > 0]


def read_snapshot(case, time, mesh):
    """Parcels at one write time: y' (tracking mesh), U (3 components),
    spin (3 components) [rad/s] and a parcel key."""
    cloud = os.path.join(case, time, "lagrangian", tc.CLOUD)
    if not os.path.exists(os.path.join(cloud, "positions")):
        return (np.zeros(0), np.zeros((0, 3)), np.zeros((0, 3)),
                np.zeros(0, np.int64))
    pos = fc.read_positions(os.path.join(cloud, "positions"), mesh)[0]
    U = fc.read_field(os.path.join(cloud, "U")).reshape(-1, 3)
    d = fc.read_field(os.path.join(cloud, "d")).reshape(-1)
    rho = fc.read_field(os.path.join(cloud, "rho")).reshape(-1)
    # Spin: angular momentum / moment of inertia (0.1 m d^2, a sphere)
    inertia = 0.1*rho*np.pi/6*d**5
    L = fc.read_field(os.path.join(cloud, "angularMomentum")).reshape(-1, 3)
    orig_id = fc.read_field(os.path.join(cloud, "origId")).astype(np.int64)
    orig_proc = fc.read_field(os.path.join(cloud, "origProcId")) \
        .astype(np.int64)
    if not len(pos) == len(U) == len(d) == len(L) == len(orig_id):
        raise ValueError("%s: fields of different lengths" % cloud)
    # Parcel key: only its remainder modulo the number of statistics groups
    # is used; the same parcel keeps it for the whole run
    return (pos[:, 1], U, L/inertia[:, None],
            orig_proc.reshape(-1)*100003 + orig_id.reshape(-1))


def wall_face_area(case, mesh):
    """Area of one wall face: period length x slab thickness / faces."""
    text = fc.read_text(os.path.join(case, "constant", "polyMesh",
                                         "boundary"))
    m = re.search(r"lowerWall\s*\{[^}]*nFaces\s+(\d+);", text)
    size = mesh.hi - mesh.lo
    return size[0]*size[2]/int(m.group(1))


def wall_impacts(case, time, area):
    """Cumulative wall impacts per wall at a write time (patchCollisionDensity:
    impacts per unit area on each face; the wall faces are equal)."""
    path = os.path.join(case, time, tc.CLOUD + ":numberCollisionDensity")
    if not os.path.exists(path):
        return [np.nan, np.nan]
    return [fc.patch_values(path, wall).sum()*area for wall in tc.WALLS]


def prune(case, keep):
    """Remove every write time except 0 and keep."""
    for name, _ in write_times(case):
        if name != keep:
            shutil.rmtree(os.path.join(case, name))


def main():
    case = sys.argv[1]
    times = write_times(case)
    if not times:
        raise SystemExit("%s: no write times" % case)
    mesh = tc.read_mesh(case)
    area = wall_face_area(case, mesh)

    t, counts, y, ids, impacts = [], [], [], [], []
    u, w = [], []
    for name, value in times:
        yp, U, omega, key = read_snapshot(case, name, mesh)
        t.append(value)
        counts.append(len(yp))
        y.append(yp)
        u.append(U)
        w.append(omega)
        ids.append(key)
        impacts.append(wall_impacts(case, name, area))

    np.savez_compressed(
        os.path.join(case, "parcelSamples.npz"),
        time=np.array(t), count=np.array(counts),
        y=np.concatenate(y).astype(np.float32),
        Ux=np.concatenate([a[:, 0] for a in u]).astype(np.float32),
        Uy=np.concatenate([a[:, 1] for a in u]).astype(np.float32),
        Uz=np.concatenate([a[:, 2] for a in u]).astype(np.float32),
        omegaX=np.concatenate([a[:, 0] for a in w]).astype(np.float32),
        omegaY=np.concatenate([a[:, 1] for a in w]).astype(np.float32),
        omegaZ=np.concatenate([a[:, 2] for a in w]).astype(np.float32),
        id=np.concatenate(ids).astype(np.int64),
        wallImpacts=np.array(impacts), walls=np.array(tc.WALLS))
    print("collectSamples: %s: %d snapshots, %d parcel samples"
          % (case, len(t), sum(counts)))

    if "--prune" in sys.argv[2:]:
        prune(case, times[-1][0])


if __name__ == "__main__":
    main()
