"""The spin cases of the OpenFOAM tests and benchmark of rotationalLift and
fluidTorque (tests/openfoam/spin, benchmarks/scripts/benchSpin.py), on top
of the shared harness foamcase.testing: a 0.2 x 0.1 x 0.1 m box of 1 cm cells
(template tests/openfoam/spin/case), a few parcels near its middle that
never reach a wall, no forces but the spin models, a frozen carrier (uniform
stream, still air or solid-body rotation about z through (0, 0.05, 0)).

A parcel's initial spin is set by a restart: the case runs two time steps
with the parcels injected at rest without spin, the angularMomentum files of
that time (of every processor) are rewritten, and the run goes on from there.
Durations are the parcels' age differences (what each parcel was tracked
for): v1912 tracks parcels injected at SOI 0 for two steps in the first time
step, OpenFOAM-13's frozen carrier writes a time before evolving the cloud.

The closed forms the tests compare with, written from the equations of
docs/spin.md, independently of the C++ core:
  lift_velocity   the parcel velocity under the rotational lift alone in a
                  uniform stream with constant spin: the slip velocity
                  rotates about the spin axis (Rodrigues' formula)
  spin_decay      |Omega_rel(t)|/|Omega_rel(0)| under the fluid torque
                  alone (exponential, then the Bernoulli solution above
                  Re_R = 32, joined at the crossing), checked against
                  rk4_spin_decay, a Runge-Kutta integration of the torque's
                  definition.

numpy only.  SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import os

import numpy as np

#: The folder of the spin tests and their case template
HERE = os.path.join(os.path.abspath(os.path.join(
    os.path.dirname(__file__), "..", "..", "..")), "tests", "openfoam", "spin")

from foamcase import testing as t
import foamcase as fc
from foamcase import testConstants

#: The case template
TEMPLATE = os.path.join(HERE, "case")

#: Carrier (air) and particles (glass) of the template
RHO_F = 1.2
NU_F = 1.5e-5
MU_F = RHO_F * NU_F
RHO_P = testConstants.RHO_P

#: Centre of the solid-body rotation
CENTRE = np.array([0.0, 0.05, 0.0])


def inertia(d):
    """Moment of inertia of one particle: 0.1 m d^2 = (pi/60) rho_p d^5."""
    return testConstants.sphere_inertia(d, RHO_P)


def tau_omega(d):
    """Stokes spin relaxation time rho_p d^2/(60 mu)."""
    return RHO_P * d * d / (60 * MU_F)


# ---------------------------------------------------------------------------
# Case set-up
# ---------------------------------------------------------------------------

def foam_vector(v):
    return "(%r %r %r)" % tuple(float(x) for x in v)


def spin_case(platform, path, parcels, forces="", functions="",
              kind="colliding", deltaT=1e-4):
    """A case with one manualInjection per parcel (dict(d, position, U0));
    forces: the particleForces entries; functions: the cloudFunctions
    entries."""
    case = fc.FoamCase(platform, TEMPLATE, path, kind)
    case.write_injectors([fc.Injector("p%d" % i, [p["position"]],
                                      p.get("U0", (0, 0, 0)), p["d"])
                          for i, p in enumerate(parcels)])
    fc.write_text(case.file("constant/spinForces"), forces + "\n")
    fc.write_text(case.file("constant/spinFunctions"), functions + "\n")
    case.set_control(deltaT=repr(deltaT), endTime=repr(deltaT))
    return case


def write_carrier(case, internal, boundary="zeroGradient"):
    """0/U: internal 'uniform (x y z)' or an (nCells, 3) array; boundary:
    zeroGradient or fixedValue (with the uniform value)."""
    if isinstance(internal, str):
        field = "internalField   %s;" % internal
        value = "\n        value           %s;" % internal \
            if boundary == "fixedValue" else ""
    else:
        rows = "\n".join(foam_vector(u) for u in internal)
        field = "internalField   nonuniform List<vector>\n%d\n(\n%s\n);" \
            % (len(internal), rows)
        value = ""
        boundary = "zeroGradient"
    fc.write_text(case.file("0/U"), fc.foam_header("volVectorField", "U", "0")
                 + """dimensions      [0 1 -1 0 0 0 0];

%s

boundaryField
{
    ".*"
    {
        type            %s;%s
    }
}
""" % (field, boundary, value))


def rotating_carrier(case, omega_f):
    """Solid-body rotation omega_f about z through CENTRE (needs the mesh):
    U = omega_f z x (x - CENTRE), 0.5 curl U = omega_f z."""
    mesh = fc.MeshGeometry(case.file("constant/polyMesh"))
    r = mesh.cell_centres - CENTRE
    U = omega_f * np.column_stack([-r[:, 1], r[:, 0], np.zeros(len(r))])
    write_carrier(case, U)


def mesh(case, nprocs, before_decompose=None):
    """blockMesh, then before_decompose(case), then decomposePar if
    nprocs > 1."""
    fc.block_mesh(case.path)
    if before_decompose:
        before_decompose(case)
    case.nprocs = nprocs
    if nprocs > 1:
        case.set_subdomains(nprocs)
        case.run(["decomposePar"], "log.decomposePar")


def set_spins(case, time_name, spin_of_d):
    """Rewrite angularMomentum at time_name in every cloud folder: the parcel
    of diameter d gets I(d) spin_of_d(d).  Returns the number of parcels."""
    count = 0
    for d_dir in case.cloud_dirs(time_name):
        path = os.path.join(d_dir, "angularMomentum")
        if not os.path.exists(path):
            continue
        d = np.atleast_1d(fc.read_field(os.path.join(d_dir, "d")))
        text = fc.read_text(path)
        head = text[:text.index("}", text.index("FoamFile")) + 1]
        rows = "\n".join(foam_vector(inertia(di) * np.asarray(spin_of_d(di)))
                         for di in d)
        fc.write_text(path, head + "\n\n%d\n(\n%s\n)\n" % (len(d), rows))
        count += len(d)
    return count


def restart_with_spin(case, spin_of_d, deltaT, end_time, log):
    """Run two steps (parcels injected at rest, no spin), give the parcels
    their spin at the time written, run on to end_time (written there).
    Returns the names of the two times.  (Two steps: OpenFOAM-13's frozen
    carrier, solver functions, evolves the cloud of a time step after that
    step's write, so the first written time holds no parcels yet; compare
    durations with the parcels' age.)"""
    case.set_control(endTime=repr(2 * deltaT), writeControl="timeStep",
                     writeInterval="2")
    case.solve(log + ".1")
    (_, t1_name), = [x for x in fc.time_dirs(case.path) if x[0] > 0]
    n = set_spins(case, t1_name, spin_of_d)
    t.check(n > 0, "%s: spin of %d parcels set at t = %s" % (log, n, t1_name))
    # Written at the end only: time index (steps from 0) of end_time
    case.set_control(endTime=repr(end_time), writeControl="timeStep",
                     writeInterval=str(int(round(end_time / deltaT))))
    case.solve(log + ".2")
    last = fc.time_dirs(case.path)[-1]
    t.check(abs(last[0] - end_time) < 1e-9 * end_time,
            "%s: ran to t = %s" % (log, last[1]))
    return t1_name, last[1]


def check_processors(case, time_name, what):
    """Decomposed cases: every processor holds parcels at time_name."""
    if case.nprocs < 2:
        return
    counts = []
    for d_dir in case.cloud_dirs(time_name):
        path = os.path.join(d_dir, "d")
        counts.append(len(np.atleast_1d(fc.read_field(path)))
                      if os.path.exists(path) else 0)
    t.check(len(counts) == case.nprocs and min(counts) > 0,
            "%s: parcels on every processor at t = %s (%s)"
            % (what, time_name, counts))


def parcels_by_diameter(case, time_name, diameters,
                        fields=("U", "d", "angularMomentum", "age")):
    """{d: {field: value}} of the parcels at time_name (every processor),
    each d found exactly once."""
    data = case.read_cloud(time_name, list(fields))
    d_all = np.atleast_1d(data["d"])
    result = {}
    for d in diameters:
        k = np.nonzero(np.abs(d_all - d) < 1e-6 * d)[0]
        t.check(len(k) == 1, "parcel d = %g m found once at t = %s (%d)"
                % (d, time_name, len(k)))
        result[d] = {f: np.atleast_2d(data[f])[k[0]] if data[f].ndim > 1
                     else data[f][k[0]] for f in fields}
    return result


# ---------------------------------------------------------------------------
# Closed forms
# ---------------------------------------------------------------------------

def lift_factor(coefficient, slip_speed, spin, d):
    """(Re_p/Re_R) C_LR of the rotational lift."""
    if coefficient == "RubinowKeller":
        return 1.0
    Rep = slip_speed * d / NU_F
    ReR = spin * d * d / NU_F
    C = 0.45 + (ReR / Rep - 0.45) * math.exp(-0.05684 * ReR**0.4 * Rep**0.3)
    return Rep / ReR * C


def rodrigues(v, axis, angle):
    """v rotated by angle about the unit vector axis."""
    return v * math.cos(angle) + np.cross(axis, v) * math.sin(angle) \
        + axis * np.dot(axis, v) * (1 - math.cos(angle))


def lift_velocity(coefficient, Uf, Up0, omega_p, d, t_):
    """Velocity after t_ of a parcel of diameter d with constant spin
    omega_p in the uniform stream Uf (no other force):
        m dU_p/dt = (pi/8) rho_f d^3 f (Omega_rel x U_rel),
        Omega_rel = -omega_p,  f = (Re_p/Re_R) C_LR,
    so dU_rel/dt = k x U_rel with k = (3 rho_f f/(4 rho_p)) omega_p:
    U_rel rotates about k at the rate |k| (|U_rel| and f stay constant)."""
    Urel0 = np.asarray(Uf, float) - np.asarray(Up0, float)
    spin = np.linalg.norm(omega_p)
    if spin == 0:
        return np.asarray(Up0, float)
    f = lift_factor(coefficient, np.linalg.norm(Urel0), spin, d)
    k = 3 * RHO_F * f / (4 * RHO_P) * np.asarray(omega_p, float)
    return np.asarray(Uf, float) - rodrigues(Urel0, k / np.linalg.norm(k),
                                             np.linalg.norm(k) * t_)


def spin_decay(W0, t_, d, coefficient="DennisSinghIngham"):
    """|Omega_rel(t)|/|Omega_rel(0)| under the fluid torque alone.
    I dW/dt = -(rho/2)(d/2)^5 C_R W^2, I = (pi/60) rho_p d^5:
      Re_R <= 32 (or Stokes): W = W0 exp(-t/tau), tau = rho_p d^2/(60 mu);
      Re_R > 32: dW/dt = -(A sqrt(W) + B) W with c0 = 15 rho/(16 pi rho_p),
        A = 12.9 c0 sqrt(nu)/d, B = 128.4 c0 nu/d^2; u = W^-1/2 obeys
        du/dt = (B u + A)/2, so u(t) = (u0 + A/B) exp(B t/2) - A/B,
      until Re_R = 32 (u = d/sqrt(32 nu)), Stokes after."""
    if W0 == 0:
        return 1.0
    tau = tau_omega(d)
    if coefficient == "Stokes" or W0 * d * d / NU_F <= 32:
        return math.exp(-t_ / tau)
    c0 = 15 * RHO_F / (16 * math.pi * RHO_P)
    A = 12.9 * c0 * math.sqrt(NU_F) / d
    B = 128.4 * c0 * NU_F / d**2
    u0 = W0**-0.5
    u32 = d / math.sqrt(32 * NU_F)
    t32 = 2 / B * math.log((u32 + A / B) / (u0 + A / B))
    if t_ <= t32:
        u = (u0 + A / B) * math.exp(B * t_ / 2) - A / B
        return (u0 / u)**2
    return (u0 / u32)**2 * math.exp(-(t_ - t32) / tau)


def rk4_spin_decay(W0, t_, d, n=20000):
    """The same by classical Runge-Kutta on the torque's definition
    (C_R = 64 pi/Re_R up to 32, 12.9/sqrt(Re_R) + 128.4/Re_R above)."""
    I = inertia(d)

    def rate(W):
        if W <= 0:
            return 0.0
        ReR = W * d * d / NU_F
        CR = 64 * math.pi / ReR if ReR <= 32 \
            else 12.9 / math.sqrt(ReR) + 128.4 / ReR
        return -(RHO_F / 2) * (d / 2)**5 * CR * W * W / I

    h = t_ / n
    W = W0
    for _ in range(n):
        k1 = rate(W)
        k2 = rate(W + h / 2 * k1)
        k3 = rate(W + h / 2 * k2)
        k4 = rate(W + h * k3)
        W += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return W / W0
