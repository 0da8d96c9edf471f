#!/usr/bin/python3
"""Write constant/cloudPositions for the manualInjection model.

Parcels are placed uniformly at random over the channel section (fixed seed,
so every variant starts from the same parcels), in the mid-plane of the
one-cell-thick 2-D slab. The bounding box is that of the case's mesh, so the
script follows blockMeshDict.

Usage: makeParcelPositions.py CASE_DIR N_PARCELS SEED
"""
import os
import sys

import numpy as np

import foamcase as fc
from foamcase import tutorial as tc


def main():
    case, n, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    mesh = tc.read_mesh(case)
    lo, hi = mesh.lo, mesh.hi
    rng = np.random.default_rng(seed)
    # Keep clear of the walls and the periodic faces by a tiny margin
    margin = 1e-3*(hi - lo)
    x = rng.uniform(lo[0] + margin[0], hi[0] - margin[0], n)
    y = rng.uniform(lo[1] + margin[1], hi[1] - margin[1], n)
    z = np.full(n, 0.5*(lo[2] + hi[2]))
    fc.write_vectors(os.path.join(case, "constant", "cloudPositions"),
                         "cloudPositions", np.column_stack((x, y, z)))


if __name__ == "__main__":
    main()
