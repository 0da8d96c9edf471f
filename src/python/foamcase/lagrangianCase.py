"""A case of OpenFOAM-13's and -14's field-based Lagrangian (libLagrangian,
libLagrangianCloud) for the roughVelocity tests: a box above a flat wall
(lowerWall, y = 0), or a closed box, with a one-way kinematicParticle cloud
in air at rest (the functions solver with the incompressibleFluid
sub-solver, never solved: the carrier is frozen), particles placed at t = 0
by manualInjection with their own velocities (one injection, and one
velocity source, per group), no forces unless asked for.

Written from Python, file by file: nothing in it comes from the parcel
library's cases.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import os

import numpy as np

import foamcase as fc

CLOUD = "cloud"


def header(cls, obj, location):
    return "FoamFile\n{\n    format      ascii;\n    class       %s;\n" \
           "    location    \"%s\";\n    object      %s;\n}\n\n" \
           % (cls, location, obj)


def write(root, relpath, cls, text):
    path = os.path.join(root, relpath)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    location, obj = os.path.split(relpath)
    fc.write_text(path, header(cls, obj, location) + text)


BLOCK_MESH = """convertToMeters 1;

vertices
(
    (%(x0)g %(y0)g %(z0)g) (%(x1)g %(y0)g %(z0)g)
    (%(x1)g %(y1)g %(z0)g) (%(x0)g %(y1)g %(z0)g)
    (%(x0)g %(y0)g %(z1)g) (%(x1)g %(y0)g %(z1)g)
    (%(x1)g %(y1)g %(z1)g) (%(x0)g %(y1)g %(z1)g)
);

blocks
(
    hex (0 1 2 3 4 5 6 7) (%(nx)d %(ny)d %(nz)d) simpleGrading (1 1 1)
);

boundary
(
    lowerWall { type wall; faces ((0 1 5 4)); }
    upperWall { type wall; faces ((3 7 6 2)); }
    sides { type wall; faces ((0 4 7 3) (1 2 6 5)); }
    frontAndBack { type %(frontAndBack)s; faces ((0 3 2 1) (4 5 6 7)); }
);
"""


class Group:
    """Particles placed at t = 0: positions (n, 3), one velocity U0 and
    diameter d for all."""

    def __init__(self, name, positions, U0, d):
        self.name = name
        self.positions = np.asarray(positions, float)
        self.U0 = tuple(float(u) for u in U0)
        self.d = float(d)


def make_case(path, groups, walls, box=((-0.1, 0, -0.05), (0.1, 0.1, 0.05)),
              cells=(20, 10, 10), end_time=0.05, delta_t=1e-3,
              two_d=False, write_d=True, gravity=False, lowerWall=None,
              n_procs=1, outer_correctors=None, drag=False):
    """Write the case in path (created).  walls: the U condition of the
    walls (a dictionary body, e.g. 'type roughVelocity; e 0.8; ...');
    lowerWall: another condition for lowerWall only.  write_d: the cloud's
    d field.  outer_correctors N: the carrier solved by incompressibleFluid
    (at rest; without drag nothing moves it) with the cloud as an fvModel, N
    PIMPLE outer correctors and the cloud's outerCorrectors on (the cloud
    re-tracks each step N times from its start).  drag: Schiller-Naumann
    drag on the particles (with outer_correctors, the cloud's momentum
    source then changes the carrier from one corrector to the next)."""
    os.makedirs(path, exist_ok=True)
    (x0, y0, z0), (x1, y1, z1) = box
    nx, ny, nz = cells
    write(path, "system/blockMeshDict", "dictionary", BLOCK_MESH % dict(
        x0=x0, y0=y0, z0=z0, x1=x1, y1=y1, z1=z1, nx=nx, ny=ny,
        nz=1 if two_d else nz, frontAndBack="empty" if two_d else "wall"))
    solver = "solver          functions;\n\nsubSolver       " \
        "incompressibleFluid;\n\nsubSolverTime   0;" \
        if not outer_correctors else "solver          incompressibleFluid;"
    functions = ("functions\n{\n    %s\n    {\n        type            "
                 "kinematicParticleCloud;\n        libs            "
                 "(\"libLagrangianCloud.so\");\n    }\n}\n" % CLOUD) \
        if not outer_correctors else ""
    write(path, "system/controlDict", "dictionary", """
libs            ("libroughWallInteraction.so");

%s

startFrom       startTime;

startTime       0;

stopAt          endTime;

endTime         %g;

deltaT          %g;

writeControl    timeStep;

writeInterval   %d;

writeFormat     ascii;

writePrecision  15;

timeFormat      general;

timePrecision   8;

runTimeModifiable no;

%s""" % (solver, end_time, delta_t, int(round(end_time/delta_t)),
           functions))
    if not outer_correctors:
        write(path, "system/fvSchemes", "dictionary", """
ddtSchemes { default none; }
gradSchemes { default none; }
divSchemes { default none; }
laplacianSchemes { default none; }
interpolationSchemes { default linear; }
snGradSchemes { default none; }
""")
        write(path, "system/fvSolution", "dictionary",
              "PIMPLE\n{\n    pRefCell 0;\n    pRefValue 0;\n}\n")
    else:
        write(path, "constant/fvModels", "dictionary",
              "%s\n{\n    type            kinematicParticleCloud;\n"
              "    libs            (\"libLagrangianCloud.so\");\n}\n"
              % CLOUD)
        write(path, "system/fvSchemes", "dictionary", """
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes
{
    default none;
    div(phi,U) Gauss linear;
    div((nuEff*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
""")
        write(path, "system/fvSolution", "dictionary", """
solvers
{
    p { solver PCG; preconditioner DIC; tolerance 1e-8; relTol 0; }
    pFinal { $p; }
    "U.*" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-8;
            relTol 0; }
}

PIMPLE
{
    nOuterCorrectors %d;
    nCorrectors 1;
    nNonOrthogonalCorrectors 0;
    pRefCell 0;
    pRefValue 0;
}
""" % outer_correctors)
    write(path, "system/decomposeParDict", "dictionary",
          "numberOfSubdomains %d;\n\ndecomposer simple;\n\n"
          "distributor none;\n\nsimpleCoeffs\n{\n    n (%d 1 1);\n}\n"
          % (n_procs, n_procs))
    lag = "Lagrangian/" + CLOUD
    write(path, "system/" + lag + "/LagrangianSchemes", "dictionary", """
tracking    linear;

ddtSchemes
{
    default     Euler;
}

SpSchemes
{
    default     %s;
}

averagingSchemes
{}

interpolationSchemes
{
    default     cell;
}

accumulationSchemes
{
    default     cell;
}
""" % ("implicit" if drag else "none"))
    write(path, "system/" + lag + "/LagrangianSolution", "dictionary",
          "maxTimeStepFraction 1;\n\nmaxCellLengthScaleFraction 1;\n\n"
          "nCorrectors     0;\n\nouterCorrectors %s;\n"
          % ("true" if outer_correctors else "false"))
    write(path, "constant/physicalProperties", "dictionary",
          "viscosityModel  constant;\n\nnu              1.5e-05;\n\n"
          "rho             1.2;\n")
    write(path, "constant/momentumTransport", "dictionary",
          "simulationType  laminar;\n")
    write(path, "constant/g", "uniformDimensionedVectorField",
          "dimensions [0 1 -2 0 0 0 0];\nvalue (0 %g 0);\n"
          % (-9.81 if gravity else 0))
    write(path, "constant/" + lag + "/physicalProperties", "dictionary",
          "rhoByRhoc       2083.3333333333335;\n")
    models = []
    for g in groups:
        models.append("%s\n{\n    type        manualInjection;\n"
                      "    file        \"%sPositions\";\n}\n"
                      % (g.name, g.name))
        fc.write_vectors(os.path.join(path, "constant", lag,
                                      g.name + "Positions"),
                         g.name + "Positions", g.positions)
    if gravity:
        models.append("gravity\n{\n    type        gravity;\n}\n")
    if drag:
        models.append("drag\n{\n    type        SchillerNaumannDrag;\n}\n")
    write(path, "constant/" + lag + "/LagrangianModels", "dictionary",
          "\n".join(models))
    write(path, "0/U", "volVectorField", """
dimensions      [0 1 -1 0 0 0 0];

internalField   uniform (0 0 0);

boundaryField
{
    #includeEtc "caseDicts/setConstraintTypes"

    ".*"
    {
        type            noSlip;
    }
}
""")
    write(path, "0/p", "volScalarField", """
dimensions      [0 2 -2 0 0 0 0];

internalField   uniform 0;

boundaryField
{
    #includeEtc "caseDicts/setConstraintTypes"

    ".*"
    {
        type            zeroGradient;
    }
}
""")
    lower = "" if lowerWall is None else \
        "    lowerWall\n    {\n        %s\n    }\n" % lowerWall
    write(path, "0/" + lag + "/U", "LagrangianVectorField", """
dimensions      [velocity];

internalField   uniform (0 0 0);

boundaryField
{
    #includeEtc "caseDicts/setConstraintTypes"

    ".*"
    {
        %s
    }
%s}

sources
{
%s}
""" % (walls, lower, "".join(
        "    %s\n    {\n        type            uniformFixedValue;\n"
        "        uniformValue    (%.17g %.17g %.17g);\n    }\n"
        % ((g.name,) + g.U0) for g in groups)))
    if write_d:
        write(path, "0/" + lag + "/d", "LagrangianScalarField", """
dimensions      [length];

internalField   uniform 0;

boundaryField
{
    #includeEtc "caseDicts/setConstraintTypes"

    ".*"
    {
        type            calculated;
    }
}

sources
{
%s}
""" % "".join("    %s\n    {\n        type            uniformFixedValue;\n"
              "        uniformValue    %.17g;\n    }\n" % (g.name, g.d)
              for g in groups))
    return path


def read_particles(path, time_name, fields=("U", "d"), processors=None):
    """The cloud's fields at time_name: {name: array}, in the order of the
    files; with processors, the processor folders' concatenated."""
    roots = [path] if not processors else \
        [os.path.join(path, "processor%d" % i) for i in range(processors)]
    out = {}
    for name in fields:
        parts = []
        for root in roots:
            folder = os.path.join(root, time_name, "Lagrangian", CLOUD)
            f = os.path.join(folder, name)
            if not os.path.exists(f):
                continue
            if "internalField" in fc.read_text(f):
                # A field written uniform: as many as the coordinates
                n = len(fc.read_field(os.path.join(folder, "coordinates")))
                parts.append(fc.internal_field(f, n))
            else:
                parts.append(fc.read_field(f))
        out[name] = np.concatenate([p for p in parts if len(p)]) \
            if any(len(p) for p in parts) else np.zeros((0,))
    return out
