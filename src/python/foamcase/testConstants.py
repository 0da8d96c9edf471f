"""The constants the OpenFOAM tests share, defined once.

RHO_P is the density of the glass beads of the test cases' templates
(rho0 in tests/openfoam/wallImpact/constant/cloudProperties, in the spin
case tests/openfoam/spin/case and in the closed box
tests/stability/openfoam/closedBox); the masses and moments of inertia a
test derives by hand use the sphere's formulas below.  A case with another
density (the shear test's light spheres, the hopper tutorial's) passes its
own rho.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math

#: Density of the glass beads of the test cases [kg/m^3]
RHO_P = 2500.0


def sphere_mass(d, rho=RHO_P):
    """Mass of one sphere of diameter d [m]: (pi/6) rho d^3 (numpy arrays
    too)."""
    return math.pi / 6 * rho * d**3


def parcel_mass(d, n_particle, rho=RHO_P):
    """Mass of a parcel of n_particle spheres of diameter d."""
    return n_particle * sphere_mass(d, rho)


def sphere_inertia(d, rho=RHO_P):
    """Moment of inertia of one sphere about its centre: m d^2/10 =
    (pi/60) rho d^5."""
    return 0.1 * sphere_mass(d, rho) * d**2
