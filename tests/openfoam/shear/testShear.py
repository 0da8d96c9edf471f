#!/usr/bin/env python3
"""The spin models in a flow with vorticity: parcels in the linear shear flow
U = (G y, 0, 0) (G = 1000 1/s, so the fluid rotates at 0.5 curl U = -G/2 z =
-500 rad/s z), checked against an oracle written here, which does not call
the code under test.

The carrier is set as the internal field, with the same linear profile as
fixed values on the boundary (all of it non-wall patches: a fixed value on a
wall would be that wall's velocity to the cloud; the parcels reach no
boundary anyway), so that the cloud's cellPoint interpolation gives the
parcel exactly U = G y and the Gauss linear curl is exactly -G z in every
cell.  Three parcels of light spheres (rho_p = 1000 kg/m^3) in air
(rho = 1.2 kg/m^3, nu = 1.5e-5 m^2/s), injected with a slip velocity and
given a spin after two time steps (spinCase.restart_with_spin):

  d [mm]  slip [m/s]       spin [rad/s]      Omega_rel         Re_p  Re_R
  1.0     (2, 0, 0.5)      (0, 0, 500)       (0, 0, -1000)     137   67 (DSI)
  0.5     (-1.5, 0, 0.3)   (400, 0, -900)    (-400, 0, 400)    51    9.4
  0.4     (1, 0, -0.5)     (0, 300, -250)    (0, -300, -250)   30    4.2

chosen so that the fluid's rotation is as large as the spin: the slip spin
Omega_rel = 0.5 curl(U) - omega_p changes by 50 % to 300 % (one parcel: its
sign) if the 1/2 is lost or the vorticity is dropped.  Before comparing, the
test evaluates each of these faults (and a reversed lift or torque) with its
own oracle and asserts that it would move the compared value by more than
ten times the tolerance: the checks can fail.

--check lift:       rotationalLift alone (OesterleBuiDinh, then
                    RubinowKeller); the spin stays constant.
--check torque:     fluidTorque (DennisSinghIngham) with rotationalLift
                    (OesterleBuiDinh): the spin relaxes to the fluid's
                    rotation while the lift moves the parcel.
--check saffmanMei: OpenFOAM's SaffmanMeiLiftForce with both of ours.

Each check: (a) the first time step: the force m dU/dt (and the torque
I d(omega)/dt) from the parcel's change over the step against the value
derived by hand at the start of the step (tolerance 1e-3 relative; measured
2e-5 to 1.5e-4 for the force, 8e-5 to 3.4e-4 for the torque: the code's
spin update is the exact decay over the step, dt/(2 tau_omega) from the
torque at its start); (b) the trajectory over 200 steps of 1e-4 s:
position, velocity and spin against a classical Runge-Kutta integration
(step 2e-5 s) of the equations below (tolerances: 5e-3 of the displacement
the forces cause, measured 1.4e-3, OpenFOAM moving the parcel with the
velocity of the start of each step; 5e-4 of the velocity change, measured
5e-6 to 7e-5; 1e-6 of the spin change, measured 1e-12: the spin update is
exact for a uniform vorticity).  The smallest shift a fault causes is 0.1 of
the compared change (the 1/2 lost in the lift of the 1 mm parcel, whose
Oesterle-Bui Dinh coefficient is near its plateau), the largest error 0.3
of its tolerance.

The oracle (typed here from the papers, not from src/):
  slip           U_rel = U_f - U_p,  Omega_rel = 0.5 curl(U_f) - omega_p
  Oesterle & Bui Dinh (1998), Exp. Fluids 25, 16-22, their correlation in
    their notation: spin parameter Gamma = |Omega_rel| d / (2 |U_rel|),
    C_L = 0.45 + (2 Gamma - 0.45) exp(-0.075 Gamma^0.4 Re_p^0.7),
    F = (1/2) rho_f (pi d^2/4) C_L |U_rel|^2 (Omega_rel x U_rel)
        / (|Omega_rel| |U_rel|)           (lift coefficient definition)
  Rubinow & Keller (1961), J. Fluid Mech. 11, 447-459:
    F = pi a^3 rho_f (Omega_rel x U_rel),  a = d/2
  fluid torque: Stokes (Re_R <= 32): T = 8 pi mu a^3 Omega_rel;
    Dennis, Singh & Ingham (1980), J. Fluid Mech. 101, 257-279, in the form
    of Crowe et al. (2011) ch. 4: T = (rho_f/2) a^5 C_R |Omega_rel|
    Omega_rel, C_R = 12.9/sqrt(Re_R) + 128.4/Re_R for Re_R > 32,
    Re_R = |Omega_rel| d^2/nu
  SaffmanMeiLiftForce as OpenFOAM implements it (SaffmanMeiLiftForce.C and
    LiftForce.C, the same formula in v1912 and OpenFOAM-13), after Mei
    (1992), Int. J. Multiphase Flow 18, 145-147 (his constants 0.3314,
    0.0524, the Re = 40 switch): with the full vorticity w = curl(U_f),
    Re = |U_rel| d/nu, Re_w = |w| d^2/nu, beta = Re_w/(2 Re),
    f = (1 - 0.3314 sqrt(beta)) exp(-0.1 Re) + 0.3314 sqrt(beta),
    Cld = 6.46 f (Re < 40), 6.46 * 0.0524 sqrt(beta Re) (Re >= 40),
    Cl = 3 Cld / (2 pi sqrt(Re_w)),  F = (m/rho_p) rho_f Cl (U_rel x w)
  motion: m dU_p/dt = sum of the forces (no drag, no gravity),
    I d(omega_p)/dt = T,  m = (pi/6) rho_p d^3,  I = m d^2/10.

Usage: testShear.py --platform P --check lift|torque|saffmanMei [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os
import re

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))

from foamcase import spinCase as s
from foamcase import testing as t
from foamcase.testConstants import sphere_mass
import foamcase as fc

#: Shear rate [1/s] of U = (G y, 0, 0)
G = 1000.0

#: Carrier (the spin template's air) and the parcels' density
RHO_F = 1.2
NU_F = 1.5e-5
MU_F = RHO_F * NU_F
RHO_P = 1000.0

#: Parcels: diameter [m], position [m], slip U_f - U_p [m/s], spin [rad/s]
PARCELS = [
    (1.0e-3, (0.045, 0.003, 0.002), (2.0, 0.0, 0.5), (0.0, 0.0, 500.0)),
    (0.5e-3, (0.005, -0.004, -0.003), (-1.5, 0.0, 0.3), (400.0, 0.0, -900.0)),
    (0.4e-3, (-0.055, 0.002, 0.004), (1.0, 0.0, -0.5), (0.0, 300.0, -250.0)),
]

#: Time step [s] and steps of the trajectory
DT = 1e-4
STEPS = 200

#: Tolerances (see the docstring)
TOL_FIRST = 1e-3
TOL_POSITION = 5e-3
TOL_VELOCITY = 5e-4
TOL_SPIN = 1e-6


# ---------------------------------------------------------------------------
# The oracle
# ---------------------------------------------------------------------------

def cross(a, b):
    """a x b of 3-vectors (np.cross is slow on single vectors)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                     a[0] * b[1] - a[1] * b[0]])


def norm(a):
    return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])


def fluid_velocity(x):
    return np.array([G * x[1], 0.0, 0.0])


#: curl(U) of U = (G y, 0, 0): (dw/dy - dv/dz, du/dz - dw/dx, dv/dx - du/dy)
CURL = np.array([0.0, 0.0, -G])


def mass(d):
    return sphere_mass(d, RHO_P)


def inertia(d):
    return mass(d) * d * d / 10


class Model:
    """The forces and the torque selected in a case, and the faults the
    check must be able to see: half (the 1/2 of the fluid rotation lost:
    curl instead of 0.5 curl), vorticity (the fluid rotation dropped),
    sign (the force or torque reversed); each for 'lift' or 'torque'."""

    def __init__(self, lift=None, torque=None, saffman=False, fault=None):
        self.lift = lift            # OesterleBuiDinh, RubinowKeller, None
        self.torque = torque        # DennisSinghIngham, None
        self.saffman = saffman
        self.fault = fault          # (model, kind) or None

    def fluid_rotation(self, model):
        kind = self.fault[1] if self.fault and self.fault[0] == model \
            else None
        if kind == "half":
            return CURL
        if kind == "vorticity":
            return np.zeros(3)
        return 0.5 * CURL

    def sign(self, model):
        return -1.0 if self.fault == (model, "sign") else 1.0

    def lift_force(self, d, Urel, Orel):
        """The rotational lift (the papers' forms, see the docstring)."""
        W, U = norm(Orel), norm(Urel)
        if W == 0 or U == 0:
            return np.zeros(3)
        if self.lift == "RubinowKeller":
            return math.pi * (d / 2)**3 * RHO_F * cross(Orel, Urel)
        Gamma = W * d / (2 * U)
        Rep = U * d / NU_F
        CL = 0.45 + (2 * Gamma - 0.45) \
            * math.exp(-0.075 * Gamma**0.4 * Rep**0.7)
        return 0.5 * RHO_F * math.pi * d * d / 4 * CL * U * U \
            * cross(Orel, Urel) / (W * U)

    def torque_value(self, d, Orel):
        W = norm(Orel)
        ReR = W * d * d / NU_F
        if ReR <= 32:
            return 8 * math.pi * MU_F * (d / 2)**3 * Orel
        CR = 12.9 / math.sqrt(ReR) + 128.4 / ReR
        return RHO_F / 2 * (d / 2)**5 * CR * W * Orel

    def saffman_force(self, d, Urel):
        Re = norm(Urel) * d / NU_F
        Rew = norm(CURL) * d * d / NU_F
        beta = 0.5 * Rew / Re
        alpha = 0.3314 * math.sqrt(beta)
        f = (1 - alpha) * math.exp(-0.1 * Re) + alpha
        Cld = 6.46 * f if Re < 40 else 6.46 * 0.0524 * math.sqrt(beta * Re)
        Cl = 3 / (2 * math.pi * math.sqrt(Rew)) * Cld
        return mass(d) / RHO_P * RHO_F * Cl * cross(Urel, CURL)

    def force(self, d, x, U, omega):
        Urel = fluid_velocity(x) - U
        F = np.zeros(3)
        if self.lift:
            F += self.sign("lift") * self.lift_force(
                d, Urel, self.fluid_rotation("lift") - omega)
        if self.saffman:
            F += self.saffman_force(d, Urel)
        return F

    def torque_on(self, d, omega):
        if not self.torque:
            return np.zeros(3)
        return self.sign("torque") * self.torque_value(
            d, self.fluid_rotation("torque") - omega)

    def rates(self, d, y):
        x, U, omega = y[0:3], y[3:6], y[6:9]
        return np.concatenate([U, self.force(d, x, U, omega) / mass(d),
                               self.torque_on(d, omega) / inertia(d)])

    def trajectory(self, d, x, U, omega, duration, h=2e-5):
        """Classical Runge-Kutta of the motion over duration."""
        n = max(1, int(math.ceil(duration / h)))
        h = duration / n
        y = np.concatenate([x, U, omega]).astype(float)
        for _ in range(n):
            k1 = self.rates(d, y)
            k2 = self.rates(d, y + h / 2 * k1)
            k3 = self.rates(d, y + h / 2 * k2)
            k4 = self.rates(d, y + h * k3)
            y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        return y[0:3], y[3:6], y[6:9]


#: The faults each check must see (the ones of its models)
FAULTS = [("lift", "sign"), ("lift", "half"), ("lift", "vorticity"),
          ("torque", "sign"), ("torque", "half"), ("torque", "vorticity")]


# ---------------------------------------------------------------------------
# The case
# ---------------------------------------------------------------------------

BLOCK_MESH = """scale   1;

vertices
(
    (-0.1 -0.05 -0.05)
    ( 0.1 -0.05 -0.05)
    ( 0.1  0.05 -0.05)
    (-0.1  0.05 -0.05)
    (-0.1 -0.05  0.05)
    ( 0.1 -0.05  0.05)
    ( 0.1  0.05  0.05)
    (-0.1  0.05  0.05)
);

blocks
(
    hex (0 1 2 3 4 5 6 7) (20 10 10) simpleGrading (1 1 1)
);

boundary
(
    sides
    {
        type patch;
        faces
        (
            (0 4 7 3)
            (1 2 6 5)
            (0 1 5 4)
            (3 7 6 2)
            (0 3 2 1)
            (4 5 6 7)
        );
    }
);
"""


def patch_faces(poly_mesh):
    """{patch: (startFace, nFaces)} of a polyMesh boundary file."""
    body = fc.strip_header(fc.read_text(os.path.join(poly_mesh, "boundary")))
    return {m.group(1): (int(m.group(3)), int(m.group(2))) for m in re.finditer(
        r"(\w+)\s*\{[^}]*?nFaces\s+(\d+);[^}]*?startFace\s+(\d+);", body)}


def write_shear_carrier(case):
    """0/U = (G y, 0, 0) at the cell centres and at the boundary faces."""
    poly = case.file("constant/polyMesh")
    mesh = fc.MeshGeometry(poly)

    def vectors(points):
        rows = "\n".join(s.foam_vector(fluid_velocity(p)) for p in points)
        return "nonuniform List<vector>\n%d\n(\n%s\n)" % (len(points), rows)

    patches = []
    for name, (start, n) in patch_faces(poly).items():
        centres = [mesh.points[mesh.faces[f]].mean(axis=0)
                   for f in range(start, start + n)]
        patches.append("    %s\n    {\n        type            fixedValue;\n"
                       "        value           %s;\n    }\n"
                       % (name, vectors(centres)))
    t.check(len(patches) == 1, "one boundary patch (%d)" % len(patches))
    fc.write_text(case.file("0/U"), fc.foam_header("volVectorField", "U", "0")
                  + "dimensions      [0 1 -1 0 0 0 0];\n\ninternalField   %s;"
                   "\n\nboundaryField\n{\n%s}\n"
                  % (vectors(mesh.cell_centres), "".join(patches)))


def forces_entry(model):
    entries = []
    if model.lift:
        entries.append("rotationalLift\n{\n    coefficient     %s;\n}"
                       % model.lift)
    if model.saffman:
        entries.append("SaffmanMeiLiftForce\n{\n    U               U;\n}")
    return "\n".join(entries)


def functions_entry(model):
    if not model.torque:
        return ""
    return "fluidTorque1\n{\n    type            fluidTorque;\n" \
           "    coefficient     %s;\n}" % model.torque


def shear_case(platform, path, model):
    parcels = [dict(d=d, position=x,
                    U0=fluid_velocity(np.array(x)) - np.array(slip))
               for d, x, slip, _ in PARCELS]
    case = s.spin_case(platform, path, parcels, forces=forces_entry(model),
                       functions=functions_entry(model), deltaT=DT)
    fc.write_text(case.file("system/blockMeshDict"),
                  fc.foam_header("dictionary", "blockMeshDict", "system")
                  + BLOCK_MESH)
    properties = case.cloud_properties()
    fc.replace_in_file(properties, r"^(\s*rho0\s+)[^;]*;", r"\g<1>%r;" % RHO_P)
    # cellPoint: exact for the linear carrier (cell would give the cell
    # centre's velocity); curlUcDt is the vorticity field of OpenFOAM's
    # lift forces
    fc.replace_in_file(properties, r"^(\s*U\s+)cell;",
                       r"\g<1>cellPoint;\n        curlUcDt        cellPoint;")
    s.mesh(case, 1, write_shear_carrier)
    return case


def states(case, time_name):
    """{d: dict(x, U, omega, age)} of the parcels at time_name."""
    parts = case.cloud_parts(time_name, ("U", "d", "angularMomentum", "age"))
    x = np.concatenate([p["positions"] for p in parts if len(p["d"])])
    fields = {f: np.concatenate([np.atleast_1d(p[f]) if f in ("d", "age")
                                 else np.atleast_2d(p[f])
                                 for p in parts if len(p["d"])])
              for f in ("U", "d", "angularMomentum", "age")}
    result = {}
    for d, _, _, _ in PARCELS:
        k = np.nonzero(np.abs(fields["d"] - d) < 1e-6 * d)[0]
        t.check(len(k) == 1, "parcel d = %g mm found once at t = %s"
                % (d * 1e3, time_name))
        k = k[0]
        result[d] = dict(x=x[k], U=fields["U"][k], age=fields["age"][k],
                         omega=fields["angularMomentum"][k] / inertia(d))
    return result


def run_on(case, steps_from_start, log):
    """Run on to time index steps_from_start, written there."""
    end = steps_from_start * DT
    case.set_control(endTime=repr(end), writeControl="timeStep",
                     writeInterval=str(steps_from_start))
    case.solve(log)
    last = fc.time_dirs(case.path)[-1]
    t.check(abs(last[0] - end) < 1e-9, "%s: ran to t = %s" % (log, last[1]))
    return last[1]


# ---------------------------------------------------------------------------
# The checks
# ---------------------------------------------------------------------------

def relative(a, b):
    return np.linalg.norm(a - b) / np.linalg.norm(b)


def check_sensitive(model, what, values, tolerance, scale, faults_of):
    """Each fault of the model faults_of ("lift" or "torque"), if the case
    has it, moves the compared value by more than ten times the tolerance.
    values(model) -> vector; scale: the size the tolerance applies to."""
    reference = values(model)
    for fault in FAULTS:
        if fault[0] != faults_of or not getattr(model, faults_of):
            continue
        faulty = values(Model(model.lift, model.torque, model.saffman, fault))
        shift = np.linalg.norm(faulty - reference) / scale
        t.check(shift > 10 * tolerance,
                "%s: the fault %s %s would move it by %.3g (> 10 x %.1g)"
                % (what, *fault, shift, tolerance))


def run_model(args, platform, model, name):
    case = shear_case(platform, os.path.join(args.work, name), model)
    spins = {d: np.array(w) for d, _, _, w in PARCELS}
    # The spins set at t1 = 2 DT (spinCase writes I omega with the spin
    # template's density: scaled to these parcels'); one step after it
    t1, _ = s.restart_with_spin(case, lambda d: spins[min(
        spins, key=lambda x: abs(x - d))] * inertia(d) / s.inertia(d), DT,
        3 * DT, "log.%s" % name)
    start = states(case, t1)
    first = states(case, fc.time_dirs(case.path)[-1][1])
    if all(first[d]["age"] == start[d]["age"] for d in spins):
        # OpenFOAM-13's frozen carrier writes a time before evolving the
        # cloud for it (and a run that stops there drops that evolution):
        # two steps from the restart hold the first step
        first = states(case, run_on(case, 5, "log.%s.3" % name))
    last = states(case, run_on(case, 2 + STEPS, "log.%s.4" % name))
    for key, label in (("lift", "rotationalLift: coefficient %s"),
                       ("torque", "fluidTorque: coefficient %s")):
        if getattr(model, key):
            t.check(label % getattr(model, key) in case.log("log.%s.2" % name),
                    "%s: the log names %s" % (name, label % getattr(model, key)))

    for d, _, slip, w in PARCELS:
        tag = "%s %s, d = %g mm" % (platform, name, d * 1e3)
        p0, p1, p2 = start[d], first[d], last[d]
        t.check(np.allclose(p0["omega"], w, rtol=1e-12, atol=0),
                "%s: spin %s set at t = %s" % (tag, w, t1))
        Urel = fluid_velocity(p0["x"]) - p0["U"]
        Orel = 0.5 * CURL - p0["omega"]
        print("      %s: U_rel %s (Re_p %.3g), Omega_rel %s (Re_R %.3g)"
              % (tag, np.round(Urel, 4), np.linalg.norm(Urel) * d / NU_F,
                 np.round(Orel, 3), np.linalg.norm(Orel) * d * d / NU_F))

        # (a) the first step: force and torque against the hand values
        step = p1["age"] - p0["age"]
        t.check(abs(step - DT) < 1e-3 * DT or abs(step - 2 * DT) < 1e-3 * DT,
                "%s: the first step tracked the parcel for %.6g s" % (tag, step))
        F = mass(d) * (p1["U"] - p0["U"]) / step

        def force(m, p=p0):
            return m.force(d, p["x"], p["U"], p["omega"])
        expected = force(model)
        check_sensitive(model, "%s: first-step force" % tag, force,
                        TOL_FIRST, np.linalg.norm(expected), "lift")
        t.check(relative(F, expected) < TOL_FIRST,
                "%s: first-step force m dU/dt = %s N, by hand %s N (relative "
                "error %.1e)" % (tag, np.array2string(F, precision=6),
                                 np.array2string(expected, precision=6),
                                 relative(F, expected)))
        T = inertia(d) * (p1["omega"] - p0["omega"]) / step
        if model.torque:
            def torque(m, p=p0):
                return m.torque_on(d, p["omega"])
            expected = torque(model)
            check_sensitive(model, "%s: first-step torque" % tag, torque,
                            TOL_FIRST, np.linalg.norm(expected), "torque")
            t.check(relative(T, expected) < TOL_FIRST,
                    "%s: first-step torque I d(omega)/dt = %s N m, by hand "
                    "%s N m (relative error %.1e)"
                    % (tag, np.array2string(T, precision=6),
                       np.array2string(expected, precision=6),
                       relative(T, expected)))
        else:
            t.check(np.all(T == 0), "%s: no torque model, spin unchanged"
                    % tag)

        # (b) the trajectory against Runge-Kutta
        duration = p2["age"] - p0["age"]
        t.check(abs(duration - STEPS * DT) < 5 * DT,
                "%s: tracked for %.6g s" % (tag, duration))

        cache = {}

        def trajectory(m, p=p0):
            if m.fault not in cache:
                cache[m.fault] = np.concatenate(m.trajectory(
                    d, p["x"], p["U"], p["omega"], duration))
            return cache[m.fault]
        ode = trajectory(model)
        x_ballistic = p0["x"] + p0["U"] * duration
        dx = np.linalg.norm(ode[0:3] - x_ballistic)
        dU = np.linalg.norm(ode[3:6] - p0["U"])
        dw = np.linalg.norm(ode[6:9] - p0["omega"])
        # The spin does not depend on the lift (uniform vorticity); the
        # lift's dependence on the torque is weak over 0.02 s
        for part, lo, scale, tol, of in (
                ("position", 0, dx, TOL_POSITION, "lift"),
                ("velocity", 3, dU, TOL_VELOCITY, "lift"),
                ("spin", 6, dw, TOL_SPIN, "torque")):
            check_sensitive(model, "%s: %s after %d steps" % (tag, part, STEPS),
                            lambda m: trajectory(m)[lo:lo + 3], tol, scale, of)
        errors = dict(
            position=(np.linalg.norm(p2["x"] - ode[0:3]), dx, TOL_POSITION,
                      p2["x"], ode[0:3]),
            velocity=(np.linalg.norm(p2["U"] - ode[3:6]), dU, TOL_VELOCITY,
                      p2["U"], ode[3:6]),
            spin=(np.linalg.norm(p2["omega"] - ode[6:9]), dw, TOL_SPIN,
                  p2["omega"], ode[6:9]))
        for part, (error, scale, tol, got, want) in errors.items():
            if part == "spin" and not model.torque:
                t.check(np.all(p2["omega"] == p0["omega"]),
                        "%s: no torque model, spin constant" % tag)
                continue
            t.check(error <= tol * scale,
                    "%s: %s after %.4g s = %s, Runge-Kutta %s (error %.2e of "
                    "the change %.3g, tolerance %.1g)"
                    % (tag, part, duration, np.array2string(got, precision=8),
                       np.array2string(want, precision=8), error / scale,
                       scale, tol))


def test():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p, kinds=False)
    p.add_argument("--check", required=True,
                   choices=("lift", "torque", "saffmanMei"))
    args = p.parse_args()
    platform = fc.Platform(args.platform)
    if args.check == "lift":
        for coefficient in ("OesterleBuiDinh", "RubinowKeller"):
            run_model(args, platform, Model(lift=coefficient),
                      "lift" + coefficient)
    elif args.check == "torque":
        run_model(args, platform, Model(lift="OesterleBuiDinh",
                                        torque="DennisSinghIngham"),
                  "torque")
    else:
        run_model(args, platform, Model(lift="OesterleBuiDinh",
                                        torque="DennisSinghIngham",
                                        saffman=True), "saffmanMei")


if __name__ == "__main__":
    t.main(test)
