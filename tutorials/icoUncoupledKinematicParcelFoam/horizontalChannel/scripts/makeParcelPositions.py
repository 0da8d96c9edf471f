#!/usr/bin/python3
"""Write constant/kinematicCloudPositions for the manualInjection model.

Parcels are placed uniformly at random over the channel section (fixed seed,
so every wall-model variant starts from the same parcels), in the mid-plane
of the one-cell-thick 2-D slab. The bounding box is read from the case's
constant/polyMesh/points, so the script follows blockMeshDict.

Usage: makeParcelPositions.py CASE_DIR N_PARCELS SEED
"""
import sys
from pathlib import Path

import numpy as np

from foamio import read_list

HEADER = r"""/*--------------------------------*- C++ -*----------------------------------*\
| =========                 |                                                 |
| \\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox           |
|  \\    /   O peration     | Version:  v1912                                 |
|   \\  /    A nd           | Website:  www.openfoam.com                      |
|    \\/     M anipulation  |                                                 |
\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       vectorField;
    location    "constant";
    object      kinematicCloudPositions;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""


def mesh_bounds(case):
    """Bounding box of constant/polyMesh/points (ASCII)."""
    pts = read_list(case / "constant/polyMesh/points")
    return pts.min(axis=0), pts.max(axis=0)


def main():
    case, n, seed = Path(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
    lo, hi = mesh_bounds(case)
    rng = np.random.default_rng(seed)
    # Keep clear of the walls and the periodic faces by a tiny margin
    margin = 1e-3*(hi - lo)
    x = rng.uniform(lo[0] + margin[0], hi[0] - margin[0], n)
    y = rng.uniform(lo[1] + margin[1], hi[1] - margin[1], n)
    z = np.full(n, 0.5*(lo[2] + hi[2]))

    with open(case / "constant/kinematicCloudPositions", "w") as f:
        f.write(HEADER)
        f.write(f"{n}\n(\n")
        for p in zip(x, y, z):
            f.write("(%.9g %.9g %.9g)\n" % p)
        f.write(")\n\n// " + "*"*73 + " //\n")


if __name__ == "__main__":
    main()
