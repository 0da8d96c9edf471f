#!/usr/bin/python3
"""Collect the parcel snapshots of one tracking run into parcelSamples.npz.

At every write time the run wrote all parcels (lagrangian/kinematicCloud:
positions, U, angularMomentum, d, rho, origId, origProcId) and the wall hits
counted by the patchCollisionDensity cloud function. This script keeps what the statistics
need (time, height, streamwise and wall-normal velocity, spin, parcel id;
wall hits per wall) in CASE/parcelSamples.npz. The snapshots are the bulk of a run's
output (about 1 MB per 10000 parcels per write time, compressed), so with
--prune it then removes every write time except the last one (serial or
decomposed), which stays complete for restarts and for viewing.

Usage: collectSamples.py CASE [--prune]
"""
import shutil
import sys
from pathlib import Path

import numpy as np

from foamio import exists, read_list, read_patch_values, read_positions

WALLS = ("lowerWall", "upperWall")


def processor_dirs(case):
    procs = sorted(case.glob("processor[0-9]*"), key=lambda p: int(p.name[9:]))
    return procs if procs else [case]


def time_dirs(case):
    """Write times (> 0) of a case, as (name, value), sorted."""
    times = []
    for d in processor_dirs(case)[0].iterdir():
        try:
            value = float(d.name)
        except ValueError:
            continue
        if value > 0 and d.is_dir():
            times.append((d.name, value))
    return sorted(times, key=lambda t: t[1])


def read_snapshot(case, time):
    """Parcels at one write time: y' (tracking mesh), Ux, Uy, spin about z
    [rad/s] and a parcel key."""
    ys, us, ws, ids = [], [], [], []
    for proc in processor_dirs(case):
        cloud = proc / time / "lagrangian/kinematicCloud"
        if not exists(cloud / "positions"):
            continue
        pos = read_positions(cloud / "positions")
        if len(pos) == 0:
            continue
        U = read_list(cloud / "U").reshape(-1, 3)
        orig_id = read_list(cloud / "origId").astype(np.int64).reshape(-1)
        orig_proc = read_list(cloud / "origProcId").astype(np.int64).reshape(-1)
        # Spin: angular momentum / moment of inertia (0.1 m d^2, a sphere)
        d = read_list(cloud / "d").reshape(-1)
        rho = read_list(cloud / "rho").reshape(-1)
        inertia = 0.1*rho*np.pi/6*d**5
        omega_z = read_list(cloud / "angularMomentum").reshape(-1, 3)[:, 2]/inertia
        ys.append(pos[:, 1])
        us.append(U[:, :2])
        ws.append(omega_z)
        # Parcel key: only its remainder modulo the number of statistics
        # groups is used; the same parcel keeps it for the whole run
        ids.append(orig_proc*100003 + orig_id)
    if not ys:
        return np.zeros(0), np.zeros((0, 2)), np.zeros(0), np.zeros(0, np.int64)
    return np.concatenate(ys), np.concatenate(us), np.concatenate(ws), np.concatenate(ids)


def wall_hits(case, time, face_area):
    """Cumulative wall hits per wall at a write time (patchCollisionDensity:
    hits per unit area on each face; the wall faces of this mesh are equal)."""
    hits = []
    for patch in WALLS:
        total = 0.0
        for proc in processor_dirs(case):
            f = proc / time / "kinematicCloud:collisionDensity"
            if not exists(f):
                return [np.nan, np.nan]
            total += read_patch_values(f, patch).sum()
        hits.append(total*face_area)
    return hits


def wall_face_area(case):
    """Area of one wall face: period length x slab thickness / faces."""
    pts = read_list(case / "constant/polyMesh/points")
    length = np.ptp(pts[:, 0])
    width = np.ptp(pts[:, 2])
    boundary = (case / "constant/polyMesh/boundary").read_text()
    i = boundary.index("lowerWall")
    n_faces = int(boundary[i:].split("nFaces", 1)[1].split(";", 1)[0])
    return length*width/n_faces


def prune(case, keep):
    """Remove every write time except 0 and keep."""
    for proc in processor_dirs(case):
        for name, _ in time_dirs(proc):
            if name != keep:
                shutil.rmtree(proc / name)


def main():
    case = Path(sys.argv[1])
    times = time_dirs(case)
    if not times:
        raise SystemExit(f"{case}: no write times")
    area = wall_face_area(case)

    t, counts, y, ux, uy, wz, ids, hits = [], [], [], [], [], [], [], []
    for name, value in times:
        yp, U, omega_z, key = read_snapshot(case, name)
        t.append(value)
        counts.append(len(yp))
        y.append(yp)
        ux.append(U[:, 0])
        uy.append(U[:, 1])
        wz.append(omega_z)
        ids.append(key)
        hits.append(wall_hits(case, name, area))

    np.savez_compressed(
        case / "parcelSamples.npz",
        time=np.array(t), count=np.array(counts),
        y=np.concatenate(y).astype(np.float32), Ux=np.concatenate(ux).astype(np.float32),
        Uy=np.concatenate(uy).astype(np.float32),
        omegaZ=np.concatenate(wz).astype(np.float32),
        id=np.concatenate(ids).astype(np.int32),
        wallHits=np.array(hits), walls=np.array(WALLS))
    print(f"collectSamples: {case}: {len(t)} snapshots, {sum(counts)} parcel samples")

    if "--prune" in sys.argv[2:]:
        prune(case, times[-1][0])


if __name__ == "__main__":
    main()
