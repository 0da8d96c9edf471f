#!/usr/bin/python3
"""Map the fully developed RANS carrier flow onto the particle-centre domain.

A parcel is tracked as a point, its centre. A real particle touching a wall
has its centre one radius r = d/2 away from it, where the air moves at
u(r) (y+ ~ 6 for 195 um beads), not at zero. The tracking case therefore
uses the region the particle centres can reach: the channel shrunk by r at
each wall, height H - d (Allrun scales the carrier mesh by (H - d)/H). The
flow is fully developed, a function of y only, so the carrier fields are
mapped exactly: a tracking-mesh point at y' takes the carrier value at
y = y' + r. A wall collision then happens when the centre is one radius from
the real wall, and the parcel feels the air there.

Writes 0/U, 0/k, 0/omega, 0/nut of the tracking case (fixed values on the
walls: the value at y = r and y = H - r).

Usage: mapCarrierFlow.py CARRIER_CASE CARRIER_TIME TRACKING_CASE DIAMETER
"""
import sys
from pathlib import Path

import numpy as np

from foamio import read_list, read_patch_values

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
    class       %s;
    location    "0";
    object      %s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// Frozen carrier flow, mapped from the RANS run by scripts/mapCarrierFlow.py
// onto the particle-centre domain (particle diameter %g m)

"""

DIMENSIONS = {
    "U": "[0 1 -1 0 0 0 0]",
    "k": "[0 2 -2 0 0 0 0]",
    "omega": "[0 0 -1 0 0 0 0]",
    "nut": "[0 2 -1 0 0 0 0]",
}


def profile(carrier, time, name, height):
    """(y, value) of a carrier field across the channel, walls included."""
    y = read_list(carrier / time / "Cy")
    v = read_list(carrier / time / name)
    v = v[:, 0] if v.ndim == 2 else v          # U: streamwise component
    order = np.argsort(y, kind="stable")
    y, v = y[order], v[order]
    # The flow is uniform in x: average the cells of each row
    yu, inv = np.unique(np.round(y, 12), return_inverse=True)
    vu = np.bincount(inv, weights=v)/np.bincount(inv)

    walls = []
    for patch in ("lowerWall", "upperWall"):
        if name == "U":
            walls.append(0.0)                  # no-slip
        else:
            walls.append(float(np.mean(read_patch_values(carrier / time / name, patch))))
    return np.r_[0.0, yu, height], np.r_[walls[0], vu, walls[1]]


def write_field(case, name, values, wall_values, diameter):
    vector = name == "U"
    cls = "volVectorField" if vector else "volScalarField"

    def fmt(v):
        return "(%.9g 0 0)" % v if vector else "%.9g" % v

    with open(case / "0" / name, "w") as f:
        f.write(HEADER % (cls, name, diameter))
        f.write(f"dimensions      {DIMENSIONS[name]};\n\n")
        f.write(f"internalField   nonuniform List<{'vector' if vector else 'scalar'}>\n")
        f.write(f"{len(values)}\n(\n")
        f.write("\n".join(fmt(v) for v in values))
        f.write("\n)\n;\n\nboundaryField\n{\n")
        for patch, v in zip(("lowerWall", "upperWall"), wall_values):
            f.write(f"    {patch}\n    {{\n        type            fixedValue;\n"
                    f"        value           uniform {fmt(v)};\n    }}\n")
        f.write("    \"periodic.*\"\n    {\n        type            cyclic;\n    }\n")
        f.write("    frontAndBack\n    {\n        type            empty;\n    }\n}\n")
        f.write("\n\n// " + "*"*73 + " //\n")


def main():
    carrier, time = Path(sys.argv[1]), sys.argv[2]
    case, diameter = Path(sys.argv[3]), float(sys.argv[4])
    r = 0.5*diameter

    # Channel height from the carrier's cell centres and walls
    pts = read_list(carrier / "constant/polyMesh/points")
    height = pts[:, 1].max() - pts[:, 1].min()
    scale = (height - diameter)/height

    # Tracking mesh = carrier mesh scaled in y by (H - d)/H: same cell order
    yc = read_list(carrier / time / "Cy")
    y_track = scale*yc
    for name in ("U", "k", "omega", "nut"):
        yp, vp = profile(carrier, time, name, height)
        values = np.interp(y_track + r, yp, vp)
        walls = np.interp([r, height - r], yp, vp)
        write_field(case, name, values, walls, diameter)

    yp, up = profile(carrier, time, "U", height)
    print("mapCarrierFlow: H = %g m, d = %g m, u(r) = %.3f m/s, centreline u = %.3f m/s"
          % (height, diameter, np.interp(r, yp, up), up.max()))


if __name__ == "__main__":
    main()
