#!/usr/bin/python3
"""Map the fully developed RANS carrier flow onto the particle-centre domain.

OpenFOAM tracks a parcel as a point, its centre. A real particle touching a
wall has its centre one radius r = d/2 away from it, where the air moves at
u(r) (y+ ~ 6 for 195 um beads), not at zero. The tracking case therefore
uses the region the particle centres can reach: the channel less r at each
wall, height H - d (Allrun meshes it with the carrier's blockMeshDict, H set
to H - d). The flow is fully developed, a function of y only, so the carrier
fields are mapped exactly: a tracking-mesh point at y' takes the carrier
value at y = y' + r. A wall collision then happens when the centre is one
radius from the real wall, and the parcel feels the air there.

Writes 0/U, 0/k, 0/omega, 0/nut of the tracking case from its templates
(the case's 0/ files): the internal field, and on each wall the value at
y = r and y = H - r as a `calculated` condition.

Why `calculated` and not `fixedValue`: the cloud takes a fixed-value
velocity on a wall patch as the velocity of the wall itself
(MomentumCloud::patchData), so a fixed u(r) would make every wall slide
downstream at u(r). A `calculated` patch fixes nothing: patchData hands the
wall model a wall at rest, while the interpolation to the parcel centre
(cellPoint: cell centres and the points, whose values on the wall come from
the patch faces) still sees the air at y = r near the wall. The other
fields get the same condition so that no wall value looks imposed.

With --whole-channel (the loading variants, which solve the air with the
beads): the case's mesh is the carrier's whole channel (height H) and its
0/ files are the carrier's own (../carrier/0: the carrier's wall
conditions); only the internal fields of U, k, omega, nut and p are
written, the carrier's converged flow row by row, the start of the
coupled run.

Usage: mapCarrierFlow.py CARRIER_CASE CARRIER_TIME TRACKING_CASE DIAMETER
                         [--whole-channel]
"""
import os
import re
import sys

import numpy as np

import foamcase as fc
from foamcase import tutorial as tc

FIELDS = ("U", "k", "omega", "nut")
SOLVED_FIELDS = FIELDS + ("p",)


def carrier_profile(carrier, time, name, mesh):
    """(y, value) of a carrier field across the channel, cells averaged per
    row (the flow is uniform in x), with the wall values where the particle
    centres never are (U = 0, k = 0 on the walls; omega and nut are taken
    constant from the first cell: they are used at y >= r only, beyond the
    first cell centre, see main)."""
    y = mesh.cell_centres[:, 1]
    v = fc.internal_field(os.path.join(carrier, time, name))
    v = v[:, 0] if v.ndim == 2 else v          # U: streamwise component
    rows, inv = np.unique(np.round(y, 12), return_inverse=True)
    values = np.bincount(inv, weights=v)/np.bincount(inv)
    if name in ("U", "k"):
        lo, hi = 0.0, 0.0
    else:
        lo, hi = values[0], values[-1]
    return np.r_[mesh.lo[1], rows, mesh.hi[1]], np.r_[lo, values, hi]


def fmt(name, v):
    return "(%.9g 0 0)" % v if name == "U" else "%.9g" % v


def replace_internal_field(path, name, values):
    """The text of the field file path with its uniform internalField
    replaced by the values."""
    text = fc.read_text(path)
    internal = "internalField   nonuniform List<%s>\n%d\n(\n%s\n)\n;" % (
        "vector" if name == "U" else "scalar", len(values),
        "\n".join(fmt(name, v) for v in values))
    text, n = re.subn(r"internalField\s+uniform[^;]*;", lambda m: internal,
                      text, count=1)
    if n != 1:
        raise RuntimeError(path + ": no uniform internalField to replace")
    return text


def write_field(case, name, values, walls, diameter):
    """The case's 0/<name> with the mapped internal field and one entry per
    wall."""
    path = os.path.join(case, "0", name)
    text = replace_internal_field(path, name, values)
    block = "".join(
        "    %s\n    {\n        type            calculated;\n"
        "        value           uniform %s;\n    }\n\n" % (wall, fmt(name, v))
        for wall, v in zip(tc.WALLS, walls))
    text, n = re.subn(r'    "\(lowerWall\|upperWall\)"\s*\{[^}]*\}\s*\n',
                      lambda m: block, text, count=1)
    if n != 1:
        raise RuntimeError(path + ": no \"(lowerWall|upperWall)\" entry")
    text = text.replace(
        "// The carrier flow of ../carrier on the particle-centre domain: the "
        "internal\n// field and the wall values are written by "
        "scripts/mapCarrierFlow.py",
        "// The carrier flow of ../carrier on the particle-centre domain of "
        "%g m\n// particles, written by scripts/mapCarrierFlow.py" % diameter)
    with open(path, "w") as f:
        f.write(text)


def map_whole_channel(carrier, time, case, cmesh, tmesh):
    """The carrier's converged flow as the internal fields of the case's
    0/ (the carrier's own files, wall conditions kept)."""
    height = cmesh.hi[1] - cmesh.lo[1]
    if abs((tmesh.hi[1] - tmesh.lo[1]) - height) > 1e-9*height:
        raise SystemExit("mapCarrierFlow: --whole-channel needs the "
                         "carrier's height %.9g m" % height)
    y = tmesh.cell_centres[:, 1]
    for name in SOLVED_FIELDS:
        yp, vp = carrier_profile(carrier, time, name, cmesh)
        path = os.path.join(case, "0", name)
        text = replace_internal_field(path, name, np.interp(y, yp, vp))
        with open(path, "w") as f:
            f.write(text)
    # The carrier's driving pressure gradient, read by meanVelocityForce at
    # the start (else it starts from 0 and the first steps jump)
    gradients = re.findall(r"pressure gradient = (%s)" % fc.NUMBER,
                           fc.read_text(os.path.join(carrier, "log.foamRun")))
    if not gradients:
        raise SystemExit("mapCarrierFlow: no pressure gradient in the "
                         "carrier's log.foamRun")
    os.makedirs(os.path.join(case, "0", "uniform"), exist_ok=True)
    with open(os.path.join(case, "0", "uniform",
                           "drivingPressureGradientProperties"), "w") as f:
        f.write("FoamFile\n{\n    format      ascii;\n    class       "
                "dictionary;\n    object      "
                "drivingPressureGradientProperties;\n}\n\ngradient        "
                "%s;\n" % gradients[-1])
    print("mapCarrierFlow: the carrier's flow at %s on the whole channel "
          "(H = %g m), pressure gradient %s m/s2" % (time, height,
                                                      gradients[-1]))


def main():
    carrier, time, case = sys.argv[1], sys.argv[2], sys.argv[3]
    diameter = float(sys.argv[4])
    r = 0.5*diameter
    cmesh = tc.read_mesh(carrier)
    tmesh = tc.read_mesh(case)
    if sys.argv[5:] == ["--whole-channel"]:
        map_whole_channel(carrier, time, case, cmesh, tmesh)
        return
    if sys.argv[5:]:
        raise SystemExit("mapCarrierFlow: unknown option %s" % sys.argv[5])
    height = cmesh.hi[1] - cmesh.lo[1]
    theight = tmesh.hi[1] - tmesh.lo[1]
    if abs(theight - (height - diameter)) > 1e-9*height:
        raise SystemExit("mapCarrierFlow: the tracking mesh is %.9g m high, "
                         "not H - d = %.9g m" % (theight, height - diameter))
    y_first = np.min(cmesh.cell_centres[:, 1]) - cmesh.lo[1]
    if r < y_first:
        raise SystemExit("mapCarrierFlow: particle radius %g m inside the "
                         "first carrier cell (centre at %g m): refine the "
                         "carrier mesh" % (r, y_first))
    y = tmesh.cell_centres[:, 1] - tmesh.lo[1] + r
    for name in FIELDS:
        yp, vp = carrier_profile(carrier, time, name, cmesh)
        yp = yp - cmesh.lo[1]
        write_field(case, name, np.interp(y, yp, vp),
                    np.interp([r, height - r], yp, vp), diameter)
    yp, up = carrier_profile(carrier, time, "U", cmesh)
    print("mapCarrierFlow: H = %g m, d = %g m, u(r) = %.3f m/s, centreline "
          "u = %.3f m/s" % (height, diameter, np.interp(r, yp - yp[0], up),
                            up.max()))


if __name__ == "__main__":
    main()
