#!/usr/bin/env python3
"""Write 0/U, the frozen air of horizontalChannelLagrangian: the 1/7
power-law profile of a fully developed turbulent channel flow,
U(y) = U_c (min(y, H - y)/(H/2))^(1/7), with the centre-line velocity U_c
= 8/7 U_b for a bulk velocity U_b = 20 m/s (the bulk velocity of
horizontalChannel), evaluated at the cell centres of system/blockMeshDict's
mesh (4 x 14 x 2 cells, 35 mm high; blockMesh numbers the cells x fastest,
then y, then z).  Run once; its output 0/U is committed.

Usage: scripts/writeCarrierProfile.py   (from the tutorial folder)

SPDX-License-Identifier: GPL-3.0-or-later
"""

H = 0.035           # channel height [m]
UB = 20.0           # bulk velocity [m/s]
NX, NY, NZ = 4, 14, 2

HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  =========                 |
  \\\\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox
   \\\\    /   O peration     | Website:  https://openfoam.org
    \\\\  /    A nd           | Version:  14
     \\\\/     M anipulation  |
\\*---------------------------------------------------------------------------*/
FoamFile
{
    format      ascii;
    class       volVectorField;
    location    "0";
    object      U;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// Written by scripts/writeCarrierProfile.py: the 1/7 power law, bulk %g m/s

dimensions      [0 1 -1 0 0 0 0];

"""

FOOTER = """
boundaryField
{
    #includeEtc "caseDicts/setConstraintTypes"

    "(lower|upper)Wall"
    {
        type            noSlip;
    }
}

// ************************************************************************* //
"""


def main():
    uc = 8.0/7.0*UB
    values = []
    for k in range(NZ):
        for j in range(NY):
            y = (j + 0.5)*H/NY
            u = uc*(min(y, H - y)/(H/2))**(1.0/7.0)
            values.extend(["(%.6f 0 0)" % u]*NX)
    with open("0/U", "w") as f:
        f.write(HEADER % UB)
        f.write("internalField   nonuniform List<vector>\n%d\n(\n%s\n)\n;\n"
                % (len(values), "\n".join(values)))
        f.write(FOOTER)


if __name__ == "__main__":
    main()
