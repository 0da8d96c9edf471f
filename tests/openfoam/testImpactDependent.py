#!/usr/bin/env python3
"""e and muD as tables of the facet impact angle on a flat rough wall
(issue 31): mean k_n and k_t at three incidence angles against the test's
own quadrature.

Fires N parcels per incidence angle (10, 30, 60 deg, 1 m/s, no forces, a
kinematic cloud: no spin) at lowerWall with Delta = 8 deg,
maxFacetCollisions 1 and
    e    table ((0 0.95) (10 0.90) (20 0.85) (40 0.78) (90 0.75));
    mu0  0.4;
    muD  table ((0 0.40) (10 0.30) (20 0.22) (40 0.15) (90 0.15));
(OpenFOAM's Function1 table, of the facet impact angle in degrees).
Oracle: roughWallOracle.single_facet_quadrature with the same tables
interpolated by numpy: one facet collision averaged over P(gamma, alpha)
(eq. 1.3), then, where the particle still moves into the wall, the
collision with the mean wall that maxFacetCollisions 1 makes (nothing from
the C++). Mean k_n and k_t per angle within 4 standard errors of the
parcels' means (+1e-6 for the quadrature).
The settings' summary in the log names each keyword with its value (the
functions by type and argument) and the outlet's type.
Control: the constants of the tables at 20 deg (e 0.85, muD 0.22) give a
quadrature that the parcels must miss by more than 4 standard errors at one
angle at least (the functions are used, not their value at one angle).

With --badInput: bad functions stop the run (non-zero exit, no crash):
  - e table reaching 1.2: FOAM FATAL IO ERROR at start-up naming the patch
    entry, "e = 1.2 at angle = 90 deg" and the range [0, 1];
  - eArgument with a constant e: FOAM FATAL IO ERROR naming eArgument;
  - beside a function e, the constants are checked as on a patch of
    constants: mu0 '0.4 0.5' (two numbers) and muD 0.5 above mu0 0.4, each a FOAM FATAL IO ERROR naming the
    keyword, the text found and its range;
  - e a table followed by a token ('0.5', which OpenFOAM's reader leaves
    unread), e 'constant 0.5 0.6' (OpenFOAM-14's reader puts the 0.6 back
    after looking for units) and e a table
    out of order (OpenFOAM's "out-of-order value", which names no keyword):
    FOAM FATAL IO ERROR naming the keyword, the patch entry, the token
    left over or OpenFOAM's message, and the allowed forms;
  - e the Function1 constant 1.5: kept as the number 1.5 and checked at
    start-up as every constant is: FOAM FATAL IO ERROR naming the keyword,
    the patch entry, 'constant 1.5' and [0, 1];
  - muD a polynomial beside the constant mu0 0.4: 0.1 + 0.01 beta (0.55 at
    45 deg, the constant's node where the bounds are checked at start-up):
    FOAM FATAL IO ERROR naming the keyword and "muD = 0.55 at angle = 45
    deg"; 0.8 - 0.01 beta (0.35 at 45 deg, above mu0 below 40 deg): FOAM
    FATAL ERROR at the first such facet collision naming the patch,
    "muD = ", "at angle = " and "[0, mu0]".

Usage: testImpactDependent.py --platform openfoam13|openfoam14|openfoam1912
           [--parcels N] [--badInput] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os

import numpy as np

from foamcase import testing as t
import foamcase as fc
from foamcase import roughWallOracle

END_TIME = "0.05"

E_TABLE = [(0, 0.95), (10, 0.90), (20, 0.85), (40, 0.78), (90, 0.75)]
MUD_TABLE = [(0, 0.40), (10, 0.30), (20, 0.22), (40, 0.15), (90, 0.15)]


def foam_table(table):
    return "table (%s)" % " ".join("(%g %g)" % p for p in table)


SETTINGS = """patchInteractionModel roughWallInteraction;

roughWallInteractionCoeffs
{
    patches
    (
        "(lowerWall|upperWall)"
        {
            type            rough;
            e               %s;
            mu0             0.4;
            muD             %s;
            roughnessAngle  8;
            maxFacetCollisions 1;
        }
        outlet { type escape; }
    );
}
""" % (foam_table(E_TABLE), foam_table(MUD_TABLE))


def interp(table):
    x = np.array([p[0] for p in table], dtype=float)
    y = np.array([p[1] for p in table], dtype=float)
    return lambda b: np.interp(b, x, y)


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p, kinds=False)
    p.add_argument("--parcels", type=int, default=10000)
    p.add_argument("--badInput", action="store_true")
    return p.parse_args()


def bad_input(platform, args):
    case = t.wall_impact_case(platform, os.path.join(args.work, "badCase"),
                              "kinematic", parcels=100, settings=SETTINGS)
    case.mesh(1)
    # muD = 0.1 + 0.01 beta is 0.55 at 45 deg, above mu0 = 0.4: a constant's
    # node (any one: 45 deg), where the bounds are checked at start-up.
    # muD = 0.8 - 0.01 beta is 0.35 there, above mu0 below 40 deg and
    # negative above 80 deg: found at the first such facet impact
    def polynomial(c0, c1):
        return ("polynomial (%g %g)" % (c0, c1) if platform.foundation
                else "polynomial ((%g 0) (%g 1))" % (c0, c1))
    table = foam_table(E_TABLE)
    # A Catmull-Rom spline through these nodes overshoots 1 between 10 and
    # 20 deg (e = 1 + 1/8 at 15 deg: weights (-1, 9, 9, -1)/16 at the
    # midpoint): the nodes alone do not bound it.  v1912's table reads its
    # values from the entry named after the function, with the type word
    spline = "((0 0) (10 1) (20 1) (30 0))"
    spline = ("{ type table; values %s; interpolationScheme spline; }"
              % spline if platform.foundation else
              "{ type table; e table %s; interpolationScheme spline; }"
              % spline)
    cases = [
        ("e spline table above 1 between its nodes", SETTINGS.replace(
            "e               %s;" % table, "e               %s" % spline),
         ["FOAM FATAL ERROR", "lowerWall|upperWall", "e = 1.", "[0, 1]"]),
        ("e table above 1", SETTINGS.replace(table, foam_table(
            [(0, 0.9), (90, 1.2)])),
         ["FOAM FATAL IO ERROR", "lowerWall|upperWall",
          "e = 1.2 at angle = 90 deg", "[0, 1]"]),
        ("eArgument with a constant e", SETTINGS.replace(
            "e               %s;" % table,
            "e               0.8;\n            eArgument normalSpeed;"),
         ["FOAM FATAL IO ERROR", "eArgument", "e as a Function1"]),
        ("mu0 two numbers beside a function e", SETTINGS.replace(
            "mu0             0.4;", "mu0             0.4 0.5;"),
         ["FOAM FATAL IO ERROR", "'mu0'", "'0.4 0.5'",
          "a number in [0, inf]"]),
        ("muD constant above mu0 beside a function e", SETTINGS.replace(
            foam_table(MUD_TABLE), "0.5"),
         ["FOAM FATAL IO ERROR", "'muD'", "'0.5'", "a number in [0, 0.4]"]),
        ("a token after the e table", SETTINGS.replace(table, table + " 0.5"),
         ["FOAM FATAL IO ERROR", "keyword 'e'", "lowerWall|upperWall",
          "left over", "'0.5'", "a number in [0, 1], or an "
          "OpenFOAM Function1"]),
        ("a number after the constant e", SETTINGS.replace(
            table, "constant 0.5 0.6"),
         ["FOAM FATAL IO ERROR", "keyword 'e'", "lowerWall|upperWall",
          "left over", "'0.6'"]),
        ("e table out of order", SETTINGS.replace(table, foam_table(
            [(0, 0.9), (40, 0.8), (20, 0.85)])),
         ["FOAM FATAL IO ERROR", "keyword 'e'", "lowerWall|upperWall",
          "out-of-order value: 20", "a number in [0, 1], or an "
          "OpenFOAM Function1"]),
        ("e constant above 1", SETTINGS.replace(
            "e               %s;" % table, "e               constant 1.5;"),
         ["FOAM FATAL IO ERROR", "keyword 'e'", "lowerWall|upperWall",
          "'constant 1.5'", "[0, 1]"]),
        ("muD polynomial above mu0 at 45 deg", SETTINGS.replace(
            foam_table(MUD_TABLE), polynomial(0.1, 0.01)),
         ["FOAM FATAL IO ERROR", "keyword 'muD'", "lowerWall|upperWall",
          "muD = 0.55 at angle = 45 deg", "[0, mu0]"]),
        ("muD polynomial above mu0 below 40 deg", SETTINGS.replace(
            foam_table(MUD_TABLE), polynomial(0.8, -0.01)),
         ["FOAM FATAL ERROR", "lowerWall|upperWall", "muD = ",
          "at angle = ", "[0, mu0]"]),
    ]
    if platform.foundation:
        # outOfBounds zero (OpenFOAM-13, -14): mu0 is 0 below the table's
        # first node, under the constant muD, which the nodes do not show
        cases.append(
            ("mu0 table zero below its nodes, under muD", SETTINGS.replace(
                "mu0             0.4;",
                "mu0             { type table; values ((20 0.4) (90 0.4)); "
                "outOfBounds zero; }").replace(foam_table(MUD_TABLE), "0.2"),
             ["FOAM FATAL ERROR", "lowerWall|upperWall", "muD = 0.2",
              "[0, mu0]"]))
    for i, (name, text, expected) in enumerate(cases):
        t.check(text != SETTINGS, "%s: the settings were changed" % name)
        case.write_settings(text)
        log = "log.bad%d" % i
        rc, _ = case.solve(log, check_rc=False)
        out = case.log(log)
        missing = [e for e in expected if e not in out]
        # (testPatchSettingsBadInput.py's signs: v1912 prints "Floating point exception
        # trapping enabled" in every log)
        crashed = rc < 0 or any(sign in out for sign in (
            "sigSegv::sigHandler", "sigFpe::sigHandler", "Segmentation fault",
            "core dumped", "printStack"))
        t.check(rc != 0 and not missing and not crashed,
                "%s: rc %d, %s" % (name, rc, "missing %s" % missing
                                   if missing else "message has %s"
                                   % expected))


def test():
    args = parse_args()
    platform = fc.Platform(args.platform)
    if args.badInput:
        bad_input(platform, args)
        return
    case = t.wall_impact_case(platform, os.path.join(args.work, "case"),
                              "kinematic", parcels=args.parcels,
                              settings=SETTINGS)
    case.mesh(1)
    case.solve()

    # The settings' summary in the log: each keyword of type rough with its
    # value as SETTINGS gives it (a function by its type and argument), the
    # default lateralTilt, and the outlet's type
    function = "table of the facet impact angle [deg]"
    t.check_summary(case, "log.solver", [
        "%s: rough: e = %s, mu0 = 0.4, muD = %s, roughnessAngle = 8 deg, "
        "lateralTilt = false, maxFacetCollisions = 1"
        % (patch, function, function)
        for patch in ("lowerWall", "upperWall")] + ["outlet: escape"])

    parcels = case.read_cloud(END_TIME, ["U", "d"])
    U, d = parcels["U"], parcels["d"]
    n_total = len(t.ANGLES)*args.parcels
    t.check(len(U) == n_total, "all %d parcels are in the domain (found %d)"
            % (n_total, len(U)))
    t.check(bool(np.all(U[:, 1] > 0)), "every parcel leaves the wall")

    e, muD = interp(E_TABLE), interp(MUD_TABLE)
    rejected = 0
    for angle in sorted(t.ANGLES):
        group = np.abs(d - t.ANGLES[angle]) < 1e-9
        t.check(np.count_nonzero(group) == args.parcels,
                "alpha = %d deg: %d parcels" % (angle, args.parcels))
        a = math.radians(angle)
        kn = U[group, 1]/math.sin(a)
        kt = U[group, 0]/math.cos(a)
        q = roughWallOracle.single_facet_quadrature(
            [angle], 8, e, 0.4, muD, fallback=True)[0]
        c = roughWallOracle.single_facet_quadrature(
            [angle], 8, 0.85, 0.4, 0.22, fallback=True)[0]
        missed = False
        for name, x in (("kn", kn), ("kt", kt)):
            mean, se, _, _ = t.sd_and_se(x)
            t.check(abs(mean - q["mean_" + name]) <= 4*se + 1e-6,
                    "alpha = %d deg: mean %s = %.5f, quadrature %.5f, "
                    "|diff| %.2g <= 4 se = %.2g (p_wallward %.3f)"
                    % (angle, name, mean, q["mean_" + name],
                       abs(mean - q["mean_" + name]), 4*se, q["p_wallward"]))
            missed = missed or abs(mean - c["mean_" + name]) > 4*se
        rejected += missed
    t.check(rejected >= 1, "control: the constants at 20 deg are rejected at "
            "%d of %d angles" % (rejected, len(t.ANGLES)))


if __name__ == "__main__":
    t.main(test)
