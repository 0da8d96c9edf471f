#!/usr/bin/env python3
"""Inter-particle collisions (SommerfeldCollision, the stochastic collision
model `Sommerfeld`) in a granular gas, against dilute kinetic theory.

The case: the closed 0.1 m box of the stability suite with 2 x 2 x 2 cells,
no carrier forces (no drag, no gravity), specular walls (`rebound`, e = 1,
mu = 0: a homogeneous gas stays homogeneous, as in a periodic box), and
NGROUPS injectors whose velocities are drawn from a Maxwellian of
temperature T_START per component; PARCELS parcels of d = 0.25 mm,
nParticle (2.9) chosen for a collision frequency of about 20 per second.
The momentum cloud on OpenFOAM-13 and -14, the colliding cloud (with
mu = 0, no spin) on v1912, whose kinematic solver needs thermophysical
properties.  A first run with
e_pp = 1 and mu_pp = 0 relaxes the gas to a Maxwellian; a restart with
e_pp = 0.8 lets it cool.

Oracles (closed forms written here; none calls the library):
  - collision frequency: the log's collisions per particle per second,
    averaged over the elastic run after its first quarter, equal
    f = 4 n d^2 sqrt(pi T) (n the number density of real particles, T the
    parcels' temperature per component), within 3 standard errors (those
    of the per-step frequencies and of T);
  - an anisotropic start (serial: temperatures 2, 0.5, 0.5 per
    component) relaxing to isotropy: T_xx - T falls as exp(-(4/5) f t),
    kinetic theory's rate for elastic smooth spheres, between the writes
    at 0.05 and 0.1 s within 0.1 (about 2.5 times its sampling error);
  - elastic, smooth: T at the end of the first run within 4 % of T at its
    first write (energy is kept in expectation, not per collision: the
    collisions' random changes make T a random walk whose sd is about
    0.7 sqrt(c/N) after c collisions per particle of N, 1.1 % here);
  - Haff's law: after the restart T(t) = T1/(1 + (t - t1)/t0)^2 with
    t0 = 6/((1 - e^2) f1), f1 = 4 n d^2 sqrt(pi T1), within 8 % at every
    write, and the gas cooled to below 0.4 T1 (Haff: 0.21).  The model's T
    stays 1-5 % above Haff's law as the gas cools (the same core model with
    20,000 particles in one cell, six seeds: +1.5 to +3.3 % at T = 0.21 T1):
    the real particles drift from a Maxwellian while their partners are
    drawn Gaussian; the sampling error of T is 0.7 % here;
  - the correlation: a last restart, elastic again, with correlation on in
    a frozen RAS carrier whose epsilon puts the parcels' Kolmogorov Stokes
    number at ST_K (0.01): the partner's fluctuation is correlated with the
    parcel's by R = exp(-0.55 St_K^0.4) = 0.92, the relative velocity's
    variance falls by 1 - R, and so the frequency to
    sqrt(1 - R) 4 n d^2 sqrt(pi T), within 3 standard errors (the same
    relation as the core's test, derived there for a Maxwellian gas;
    St_K from tau_p = rho_p d^2/(18 mu) and tau_K = sqrt(nu/epsilon));
  - parcels conserved: the parcel count of every step equals the injected,
    and the log's real particles of every step are the whole cloud's;
  - --parallel: the elastic run on 2 ranks (the statistics and the log's
    counts reduced over processors), and the run repeated gives the same
    parcels bit for bit;
  - --badInput: out-of-range e, an unknown keyword (its closest match
    named), sizeClassBounds not ascending, and correlation on without a
    turbulent carrier each stop with a message naming the keyword.

  - --spin: the colliding cloud: with mu = 0.4 nearly every parcel spins
    after about five collisions, at kinetic theory's frequency; with
    mu = 0 every spin stays exactly zero.

Usage: testSommerfeldCollision.py --platform P [--parallel | --badInput |
           --spin]
           [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os
import re

import numpy as np

from foamcase import testing as t
import foamcase as fc

PARCELS_PER_GROUP = 60
NGROUPS = 256
PARCELS = PARCELS_PER_GROUP*NGROUPS
D = 0.25e-3                 # (nParticle >= 1: v1912 drops parcels of fewer)
T_START = 1.0               # m^2/s^2 per component
VOLUME = 0.1**3
F_TARGET = 20.0             # collisions per particle and second
N_DENSITY = F_TARGET/(4*D*D*math.sqrt(math.pi*T_START))
N_PARTICLE = N_DENSITY*VOLUME/PARCELS
E_COOLING = 0.8
T1, T2 = "0.25", "1.25"     # end of the elastic run, of the cooling run
T3 = "1.5"                  # end of the correlated elastic run
ANISOTROPY = 0.5            # the serial gas starts at T (2, 0.5, 0.5) T_START
ST_K = 0.01                 # the parcels' Kolmogorov Stokes number there
RHO_P = 2500.0              # the box's rho0
NU, RHO = 1.5e-5, 1.2       # the box's carrier
TAU_P = RHO_P*D*D/(18*NU*RHO)
EPSILON = NU/(TAU_P/ST_K)**2    # tau_K = sqrt(nu/epsilon) = tau_p/St_K

SPECULAR = """patchInteractionModel roughWallInteraction;

roughWallInteractionCoeffs
{
    patches
    (
        walls { type rebound; e 1; mu 0; }
    );
}
"""

COLLISIONS = """stochasticCollisionModel Sommerfeld;

    SommerfeldCoeffs
    {
%s
    }
"""


def model_entry(e=1.0, mu=0.0, extra=""):
    body = "        e               %r;\n        mu              %r;\n" \
           "        correlation     false;\n" % (e, mu)
    return COLLISIONS % (body + extra)


def make_case(platform, path, kind="kinematic", seed=3,
              per_group=PARCELS_PER_GROUP, anisotropy=0.0):
    """The box; anisotropy a: the groups' velocities drawn with the
    temperatures T_START (1 + 2a, 1 - a, 1 - a) per component"""
    if not platform.foundation and kind == "kinematic":
        # v1912's kinematic solver needs thermophysical properties the
        # box has not: its colliding cloud (mu 0: no spin)
        kind = "colliding"
    rng = np.random.default_rng(seed)
    scale = np.sqrt(T_START*np.array([1 + 2*anisotropy, 1 - anisotropy,
                                      1 - anisotropy]))
    groups = [{"name": "g%d" % i, "n": per_group, "d": D,
               "U0": tuple(scale*rng.normal(0, 1, 3)),
               "box": ((0.002, 0.002, 0.002), (0.098, 0.098, 0.098))}
              for i in range(NGROUPS)]
    case, parcels, _ = t.closed_box_case(platform, path, groups, kind, seed)
    t.check(parcels == per_group*NGROUPS, "%d parcels injected" % parcels)
    # nParticle of every injector, no forces, 2 x 2 x 2 cells
    fc.replace_in_file(case.file("constant/injectors"),
                       r"nParticle\s+1;", "nParticle       %r;" % N_PARTICLE,
                       count=NGROUPS)
    fc.replace_in_file(case.cloud_properties(),
                       r"particleForces\s*\{[^}]*\}", "particleForces\n    {}")
    fc.replace_in_file(case.file("system/blockMeshDict"),
                       r"\(10 10 10\)", "(2 2 2)")
    case.write_settings(SPECULAR)
    set_model(case, model_entry())
    case.set_control(deltaT="0.0025", endTime=T1, writeControl="runTime",
                     writeInterval="0.05")
    return case


def frozen_ras_carrier(case, platform):
    """A turbulent carrier at rest for the correlation: kEpsilon with
    uniform k and epsilon (EPSILON), read and never solved"""
    if platform.foundation:
        fc.write_text(case.file("constant/momentumTransport"),
                      fc.foam_header("dictionary", "momentumTransport")
                      + "simulationType  RAS;\n\nRAS\n{\n    model           "
                        "kEpsilon;\n    turbulence      on;\n}\n")
    else:
        fc.write_text(case.file("constant/turbulenceProperties"),
                      fc.foam_header("dictionary", "turbulenceProperties")
                      + "simulationType  RAS;\n\nRAS\n{\n    RASModel        "
                        "kEpsilon;\n    turbulence      on;\n}\n")
    for name, dims, value, patch in (
            ("k", "[0 2 -2 0 0 0 0]", 1e-4, "zeroGradient"),
            ("epsilon", "[0 2 -3 0 0 0 0]", EPSILON, "zeroGradient"),
            ("nut", "[0 2 -1 0 0 0 0]", 0, "calculated")):
        fc.write_text(case.file("0/" + name),
                      fc.foam_header("volScalarField", name, "0")
                      + "dimensions      %s;\n\ninternalField   uniform %r;"
                        "\n\nboundaryField\n{\n    walls\n    {\n"
                        "        type            %s;\n        value           "
                        "uniform %r;\n    }\n}\n" % (dims, value, patch, value))


def set_model(case, entry):
    text = fc.read_text(case.cloud_properties())
    text, n = re.subn(r"stochasticCollisionModel\s+\w+;(\s*SommerfeldCoeffs"
                      r"\s*\{[^}]*\})?", entry.strip(), text)
    if n != 1:
        raise fc.FoamError("no stochasticCollisionModel entry")
    fc.write_text(case.cloud_properties(), text)


def temperature(case, time_name):
    """T per component of the parcels (mean of the three variances) and the
    parcel count"""
    U = case.read_cloud(time_name, ["U"])["U"].reshape(-1, 3)
    return float(np.mean(np.var(U, axis=0))), len(U)


def temperatures(case, time_name):
    """The parcels' variances of the three velocity components"""
    U = case.read_cloud(time_name, ["U"])["U"].reshape(-1, 3)
    return np.var(U, axis=0)


def frequencies(case, log):
    """The model's collisions per particle per second of every step; the
    real particles it counts are the whole cloud's at every step (summed
    over processors): PARCELS nParticle"""
    rows = re.findall(r"Sommerfeld collisions: (\S+) per particle per "
                      r"second \(\S+ of (\S+) particles", case.log(log))
    t.check(len(rows) > 10, "%s: %d steps report their collisions"
            % (log, len(rows)))
    totals = sorted(set(float(n) for _, n in rows))
    expected = PARCELS*N_PARTICLE
    t.check(all(abs(n/expected - 1) < 1e-9 for n in totals),
            "%s: every step counts %s real particles (the cloud's: %.9g)"
            % (log, totals[:3], expected))
    return np.array([float(f) for f, _ in rows])


def check_parcels(case, log):
    steps = case.read_steps(log)
    counts = sorted(set(s["parcels"] for s in steps))
    t.check(counts == [PARCELS], "%s: parcel count %s at every one of %d "
            "steps (injected %d)" % (log, counts, len(steps), PARCELS))


def kinetic_frequency(T):
    return 4*N_DENSITY*D*D*math.sqrt(math.pi*T)


def check_isotropy(case, label, f):
    """An anisotropic start relaxes to isotropy at kinetic theory's rate:
    T_xx - T decays as exp(-(4/5) f t) for elastic smooth spheres (the
    core's test of the same model). Between the writes at 0.05 and 0.1 s
    (about one collision per particle each) the ratio is exp(-0.04 f),
    0.45 at f = 20 /s. Its sampling error is about 0.04 for 15,360
    independent parcels (T_xx - T of about 0.45 and 0.2 m^2/s^2, each
    +- 0.016); the groups of 60 parcels that start alike make it somewhat
    larger: within 0.1"""
    d1, d2 = (temperatures(case, x) for x in ("0.05", "0.1"))
    ratio = (d2[0] - d2.mean())/(d1[0] - d1.mean())
    expected = math.exp(-0.8*f*0.05)
    t.check(abs(ratio - expected) < 0.1,
            "%s: the anisotropy T_xx - T falls by %.3f from t = 0.05 to "
            "0.1 s, kinetic theory's exp(-(4/5) f dt) = %.3f (T_xx - T = "
            "%.3f, %.3f m^2/s^2)" % (label, ratio, expected,
                                     d1[0] - d1.mean(), d2[0] - d2.mean()))


def check_gas(case, label, cooling=True, anisotropic=False):
    """The elastic run (anisotropic: its start relaxing to isotropy), then
    (cooling) the cooling run (a restart)"""
    case.solve("log.elastic")
    check_parcels(case, "log.elastic")
    times = [name for value, name in fc.time_dirs(case.path)
             if 0 < value <= float(T1) + 1e-9]
    temps = [temperature(case, x)[0] for x in times]
    T_first, T_last = temps[0], temps[-1]
    t.check(abs(T_last/T_first - 1) < 0.04,
            "%s: e = 1, mu = 0 keeps the energy: T %.4f at t = %s, %.4f at "
            "t = %s" % (label, T_first, times[0], T_last, times[-1]))

    f = frequencies(case, "log.elastic")
    f = f[len(f)//4:]
    T_mean = float(np.mean(temps[1:]))
    f_mean = float(np.mean(f))
    se_f = float(np.std(f, ddof=1))/math.sqrt(len(f))
    expected = kinetic_frequency(T_mean)
    # T's sampling error sqrt(2/(3N)) enters f as half of it
    se_T = 0.5*expected*math.sqrt(2/(3*PARCELS))
    se = math.hypot(se_f, se_T)
    t.check(abs(f_mean - expected) < 3*se,
            "%s: collision frequency %.3f /s against kinetic theory's "
            "4 n d^2 sqrt(pi T) = %.3f /s (T = %.4f m^2/s^2, s.e. %.3f, "
            "z = %.2f)" % (label, f_mean, expected, T_mean, se,
                           (f_mean - expected)/se))
    if anisotropic:
        check_isotropy(case, label, f_mean)

    if not cooling:
        return
    # Cooling: e = 0.8 from T1 on
    T_1 = temperature(case, T1)[0]
    set_model(case, model_entry(e=E_COOLING))
    case.set_control(startFrom="latestTime", endTime=T2, writeInterval="0.25")
    case.solve("log.cooling")
    check_parcels(case, "log.cooling")
    t0 = 6/((1 - E_COOLING**2)*kinetic_frequency(T_1))
    times = [name for value, name in fc.time_dirs(case.path)
             if float(T1) + 1e-9 < value <= float(T2) + 1e-9]
    t.check(len(times) == 4, "%s: cooling written at %s" % (label, times))
    for x in times:
        T = temperature(case, x)[0]
        haff = T_1/(1 + (float(x) - float(T1))/t0)**2
        t.check(abs(T/haff - 1) < 0.08,
                "%s: Haff's law at t = %s: T = %.4f, T1/(1 + t/t0)^2 = %.4f "
                "(t0 = %.3f s)" % (label, x, T, haff, t0))
    t.check(T < 0.4*T_1, "%s: the gas cooled to %.3f of T1" % (label, T/T_1))


def check_correlation(case, label):
    """The correlated elastic restart (see the docstring)"""
    T_2 = temperature(case, T2)[0]
    set_model(case, model_entry().replace("correlation     false",
                                          "correlation     true"))
    case.set_control(startFrom="latestTime", endTime=T3, writeInterval="0.25")
    case.solve("log.correlation")
    check_parcels(case, "log.correlation")
    t.check(re.search(r"correlation on", case.log("log.correlation"))
            is not None, "%s: the restart runs with correlation on" % label)
    T_3 = temperature(case, T3)[0]
    T_mean = 0.5*(T_2 + T_3)
    f = frequencies(case, "log.correlation")
    f_mean = float(np.mean(f))
    se_f = float(np.std(f, ddof=1))/math.sqrt(len(f))
    R = math.exp(-0.55*ST_K**0.4)
    expected = math.sqrt(1 - R)*kinetic_frequency(T_mean)
    se = math.hypot(se_f, 0.5*expected*math.sqrt(2/(3*PARCELS)))
    t.check(abs(f_mean - expected) < 3*se,
            "%s: with the correlation at St_K = %g (R = %.4f) the collision "
            "frequency %.3f /s against sqrt(1 - R) 4 n d^2 sqrt(pi T) = "
            "%.3f /s (T = %.4f m^2/s^2, s.e. %.3f, z = %.2f; %.3f /s "
            "without the correlation)" % (
                label, ST_K, R, f_mean, expected, T_mean, se,
                (f_mean - expected)/se, kinetic_frequency(T_mean)))


def test_gas(args, platform):
    case = make_case(platform, os.path.join(args.work, "gas"),
                     anisotropy=ANISOTROPY)
    # The carrier of the correlated restart (no force acts on the parcels)
    frozen_ras_carrier(case, platform)
    case.mesh()
    check_gas(case, "serial", anisotropic=True)
    check_correlation(case, "serial")


def test_spin(args, platform):
    """The colliding cloud, whose parcels carry spin: elastic collisions
    with friction (mu 0.4) spin the parcels up from rest, at the collision
    frequency of kinetic theory (friction does not change it); smooth ones
    (mu 0) leave every spin exactly zero (no tangential impulse)"""
    for mu in (0.0, 0.4):
        case = make_case(platform, os.path.join(args.work, "mu%g" % mu),
                         kind="colliding")
        set_model(case, model_entry(mu=mu))
        case.mesh()
        case.solve("log.elastic")
        check_parcels(case, "log.elastic")
        L = case.read_cloud(T1, ["angularMomentum"])["angularMomentum"]
        L = np.asarray(L).reshape(-1, 3)
        t.check(len(L) == PARCELS and np.all(np.isfinite(L)),
                "mu %g: %d finite angular momenta" % (mu, len(L)))
        spinning = float(np.mean(np.linalg.norm(L, axis=1) > 0))
        if mu == 0:
            t.check(spinning == 0, "mu 0: no parcel spins (%.3f spin)"
                    % spinning)
            continue
        # Five collisions per particle: nearly every parcel has collided
        t.check(spinning > 0.95, "mu %g: %.3f of the parcels spin after "
                "about five collisions each" % (mu, spinning))
        # The gas cools (friction): each write's T against the frequencies
        # of the 11 steps around it
        f = frequencies(case, "log.elastic")
        ratios = []
        for value, name in fc.time_dirs(case.path):
            if not 0.1 - 1e-9 <= value <= float(T1) - 0.0125 + 1e-9:
                continue
            k = int(round(value/0.0025))
            window = f[k - 6:k + 5]
            ratios.append(float(np.mean(window))
                          / kinetic_frequency(temperature(case, name)[0]))
        ratio = float(np.mean(ratios))
        # Each window: ~11 x 0.05 x 2800 = 1,500 collisions, 2.6 %
        se = 0.026/math.sqrt(len(ratios))
        t.check(len(ratios) >= 3 and abs(ratio - 1) < 3*se + 0.01,
                "mu %g: collision frequency / 4 n d^2 sqrt(pi T) = %.4f at "
                "%d writes as the gas cools (s.e. %.4f)"
                % (mu, ratio, len(ratios), se))


def test_parallel(args, platform):
    runs = []
    for name in ("first", "repeat"):
        case = make_case(platform, os.path.join(args.work, name))
        case.mesh(nprocs=2)
        runs.append(case)
    # The elastic run: frequency, energy and counts reduced over the two
    # ranks (the cooling adds nothing a decomposition could break, and
    # two ranks on two cores are slow beside any other load)
    check_gas(runs[0], "2 ranks", cooling=False)
    runs[1].solve("log.elastic")
    for proc in ("processor0", "processor1"):
        a, b = (fc.read_cloud(os.path.join(c.path, proc), T1, ["U"],
                              platform.cloud)["U"] for c in runs)
        a, b = np.asarray(a), np.asarray(b)
        t.check(a.size > 0 and a.shape == b.shape and np.array_equal(a, b),
                "%s: the repeated run's parcels equal the first's bit for "
                "bit (%d values)" % (proc, a.size))


BAD = [
    ("e 1.2", model_entry(e=1.2), [r"\be\b", r"\[0, 1\]", r"1\.2"]),
    ("unknown keyword", model_entry(extra="        sizeClasses (1e-3);\n"),
     ["sizeClasses", "sizeClassBounds"]),
    ("bounds not ascending",
     model_entry(extra="        sizeClassBounds (2e-3 1e-3);\n"),
     ["sizeClassBounds", "ascending"]),
    ("correlation without turbulence",
     model_entry().replace("correlation     false", "correlation     true"),
     ["correlation", "turbulent carrier"]),
]


def test_bad_input(args, platform):
    for label, entry, patterns in BAD:
        case = make_case(platform, os.path.join(args.work, re.sub(
            r"\W+", "_", label)), per_group=1)
        set_model(case, entry)
        case.set_control(endTime="0.005")
        case.mesh()
        rc, _ = case.solve(check_rc=False)
        log = case.log()
        t.check(rc != 0, "%s: the run stops (exit code %d)" % (label, rc))
        for pattern in patterns:
            t.check(re.search(pattern, log) is not None,
                    "%s: the message names %r" % (label, pattern))
        t.check("Sommerfeld" in log or "SommerfeldCoeffs" in log,
                "%s: the message names the model's dictionary" % label)
    # The control: the same case with good input runs
    case = make_case(platform, os.path.join(args.work, "control"),
                     per_group=1)
    case.set_control(endTime="0.005")
    case.mesh()
    case.solve()
    t.check(re.search(r"Sommerfeld: e = 1, mu = 0, correlation off, size "
                      r"classes 1", case.log()) is not None,
            "control: the settings line of the log")


def test():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p, kinds=False)
    p.add_argument("--parallel", action="store_true")
    p.add_argument("--badInput", action="store_true")
    p.add_argument("--spin", action="store_true")
    args = p.parse_args()
    platform = fc.Platform(args.platform)
    if args.badInput:
        test_bad_input(args, platform)
    elif args.parallel:
        test_parallel(args, platform)
    elif args.spin:
        test_spin(args, platform)
    else:
        test_gas(args, platform)


if __name__ == "__main__":
    t.main(test)
