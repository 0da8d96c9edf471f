"""Parcels of a cloud: Lagrangian fields (U, d, angularMomentum, active,
...), Cartesian positions (v1912 writes them; OpenFOAM-13 and -14 write
barycentric coordinates only, converted with the mesh), the processor
folders of a decomposed case.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import glob
import os
import re

import numpy as np

from .dictionaries import read_text, strip_header
from .errors import FoamError
from .fields import read_field
from .mesh import MeshGeometry

def processor_roots(case):
    """The case, or its processor* folders when decomposed."""
    procs = sorted(glob.glob(os.path.join(case, "processor[0-9]*")),
                   key=lambda p: int(re.sub(r"\D", "", os.path.basename(p))))
    return procs if procs else [case]


def time_dirs(case):
    """The time folders of the case (of processor0 when decomposed), as
    (value, name), sorted by value."""
    times = []
    for name in os.listdir(processor_roots(case)[0]):
        try:
            times.append((float(name), name))
        except ValueError:
            pass
    return sorted(times)


def cloud_dirs(case, time_name, cloud):
    """The cloud's Lagrangian folders: the case's or each processor's."""
    return [os.path.join(r, time_name, "lagrangian", cloud)
            for r in processor_roots(case)]


def read_cloud(case, time_name, fields, cloud):
    """Fields of all parcels (processors concatenated; missing: empty)."""
    data = {name: [] for name in fields}
    for d in cloud_dirs(case, time_name, cloud):
        if not os.path.isdir(d):
            continue
        for name in fields:
            path = os.path.join(d, name)
            if os.path.exists(path):
                data[name].append(read_field(path))
    result = {}
    for name, parts in data.items():
        parts = [p for p in parts if p.size]
        result[name] = np.concatenate(parts) if parts else np.zeros(0)
    return result


def significant_digits(numbers):
    """The most significant digits among numbers written as text (a file's
    writePrecision, where one of its numbers uses them all)"""
    most = 1
    for group in numbers:
        for text in group:
            mantissa = re.split(r"[eE]", text.lstrip("+-"))[0]
            digits = mantissa.replace(".", "").lstrip("0")
            most = max(most, len(digits))
    return most


def read_positions(path, mesh):
    """Cartesian positions (n, 3) and cells (n,) of the parcels of a
    'positions' file: v1912's holds '(x y z) cell'; OpenFOAM-13's holds the
    barycentric '(a b c d) cell tetFace tetPt', converted with mesh (a
    MeshGeometry, or the case or processor folder whose constant/polyMesh
    is read only then). Barycentric coordinates outside [0, 1] or not
    summing to 1 (beyond the round-off of the file's writePrecision) are a
    FoamError."""
    body = strip_header(read_text(path))
    m = re.search(r"(\d+)\s*\(", body)
    if not m or int(m.group(1)) == 0:
        return np.zeros((0, 3)), np.zeros(0, dtype=int)
    n = int(m.group(1))
    tokens = body[m.end():body.rindex(")")].replace("(", " ") \
        .replace(")", " ").split()
    if len(tokens) % n or len(tokens)//n not in (4, 7):
        raise FoamError("%s: %d parcels but %d numbers (4 or 7 a parcel)"
                        % (path, n, len(tokens)))
    values = np.array(tokens, dtype=float).reshape(n, -1)
    if values.shape[1] == 4:
        return values[:, :3], values[:, 3].astype(int)
    coords = values[:, :4]
    cells, faces, tets = (values[:, k].astype(int) for k in (4, 5, 6))
    # the coordinates as written: round-off of the file's writePrecision
    digits = significant_digits([tokens[k::7] for k in range(4)])
    tol = max(1e-9, 4*10.0**(1 - digits))
    if not (np.all(np.abs(coords.sum(axis=1) - 1) < tol)
            and np.all(coords > -tol)):
        raise FoamError("%s: barycentric coordinates outside [0, 1] or not "
                        "summing to 1 (tolerance %.1e)" % (path, tol))
    if mesh is None:
        raise FoamError("%s: barycentric positions need the mesh" % path)
    if not isinstance(mesh, MeshGeometry):
        mesh = MeshGeometry(os.path.join(mesh, "constant", "polyMesh"))
    return mesh.positions(coords, cells, faces, tets), cells


def cloud_parts(case, time_name, fields, cloud):
    """Positions, cells and fields of every parcel at time_name, one dict
    per processor (or one for a serial case)."""
    result = []
    for root in processor_roots(case):
        d = os.path.join(root, time_name, "lagrangian", cloud)
        part = {"dir": d}
        if not os.path.isdir(d):
            part["positions"] = np.zeros((0, 3))
            part["cells"] = np.zeros(0, dtype=int)
            for name in fields:
                part[name] = np.zeros(0)
            result.append(part)
            continue
        part["positions"], part["cells"] = read_positions(
            os.path.join(d, "positions"), root)
        for name in fields:
            path = os.path.join(d, name)
            part[name] = read_field(path) if os.path.exists(path) \
                else np.zeros(0)
        result.append(part)
    return result
