#!/usr/bin/env python3
"""A bad wall profile (roughness { profile "<file>"; } of a rough patch)
stops the run with a FatalIOError naming the dictionary, the keyword
profile, the file and, for a bad line, its number.

Control: a valid trace (foamcase/roughnessProfileOracle.py's) given by a path
relative to the case runs, and so does one given as $FOAM_CASE/...; the
profile parameters with an unknown estimate stop.  Then one run per bad
file: unreadable (missing), fewer than 10 points, x not increasing, NaN, a
third column; a path through an unset environment variable (OpenFOAM's
expansion stopped without naming the keyword or the file before
2026-11-27); and profile together with RSm.  Same harness and checks as
testPatchSettingsBadInput.py (FOAM FATAL IO ERROR, the settings file, the patches entry,
the keyword; no crash).  The expected line numbers are those of the files
written here.

Last, a diameter outside the tabulated range: a trace of 101 points 1 um
apart (written here) is tabulated from its largest spacing to half its
length, 1 to 50 um (the rule, stated in docs/roughWallInteraction.md), and
every parcel (100-120 um) is larger and only lowerWall is hit: the run goes
on (rc 0, every parcel still in the domain: none is lost) and warns once,
naming the mesh patch, the entry, the smallest and largest diameter that
hit in the first step with such a hit (the steepest injection's, which
arrives first, alone in its step) and that range (parsed from the log,
within 0.1 %).  Then the same on two processors split at x = 0, with every parcel
(80 um) injected and hitting at x > 0: processor 1's hits are warned of
once, by the master (OpenFOAM prints no warning of another processor).

Usage: testRoughnessProfileBadInput.py --platform openfoam13|openfoam1912
           [--cloud KIND] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math
import os
import re

from foamcase import testing as t
import foamcase as fc
from foamcase import roughnessProfileOracle as profileOracle
import testPatchSettingsBadInput as b


def profile(name):
    """Settings with roughness { profile "constant/<name>"; }."""
    return b.settings({"roughnessAngle": None,
                       "roughness": '{ profile "constant/%s"; }' % name})


def points(n, start=0):
    return "".join("%g %g\n" % (1e-6 * i, 1e-7 * (i % 3))
                   for i in range(start, start + n))


#: file name -> content (None: not written)
FILES = {
    "tooFew": "# x z\n" + points(9),
    "notIncreasing": points(5) + "4e-6 0\n" + points(10, 5),
    "nan": points(7) + "7e-6 nan\n" + points(10, 8),
    "threeColumns": "x z\n" + points(3) + "3e-6 0 1\n" + points(10, 4),
}

IN = b.IN_PATCH
PROFILE = b.key("profile")

#: name, settings, fragments of the error message: the keyword, the scope
#: and the reason (the file and line, what is wrong there)
CASES = [
    ("file missing", profile("missing"),
     [PROFILE, IN, "constant/missing", "cannot open"]),
    ("fewer than 10 points", profile("tooFew"),
     [PROFILE, IN, "constant/tooFew", "9 points", "10"]),
    ("x not increasing", profile("notIncreasing"),
     [PROFILE, IN, "constant/notIncreasing:6", "4e-06"]),
    ("NaN", profile("nan"),
     [PROFILE, IN, "constant/nan:8", "finite", "'7e-6 nan'"]),
    ("three columns", profile("threeColumns"),
     [PROFILE, IN, "constant/threeColumns:5", "two numbers", "'3e-6 0 1'"]),
    ("unset variable in the path",
     b.settings({"roughnessAngle": None,
                 "roughness": '{ profile "$ROUGHWALL_TEST_UNSET/wallProfile"; }'}),
     [PROFILE, IN, "$ROUGHWALL_TEST_UNSET/wallProfile",
      "ROUGHWALL_TEST_UNSET"]),
    ("profile and RSm",
     b.settings({"roughnessAngle": None,
                 "roughness": '{ profile "constant/wallProfile"; RSm 1e-4; }'}),
     [b.key("RSm"), IN, "profile"]),
    ("unknown estimate",
     b.settings({"roughnessAngle": None,
                 "roughness": "{ Rq 1e-6; RSm 1e-4; estimate closedform; }"}),
     [b.key("estimate"), IN, "envelope closedForm", "'closedform'"]),
]


def test():
    args = b.parse_args()
    platform = fc.Platform(args.platform)
    case = t.wall_impact_case(platform, os.path.join(args.work, "case"),
                              args.cloud, two_d=True, parcels=10)
    case.set_control(endTime="0.001")
    case.mesh()
    profileOracle.write_profile(case.file("constant/wallProfile"))
    for name, content in FILES.items():
        with open(case.file("constant/" + name), "w") as f:
            f.write(content)

    # Controls: a valid trace, relative to the case and through $FOAM_CASE
    for i, where in enumerate(("constant/wallProfile",
                               "$FOAM_CASE/constant/wallProfile")):
        case.write_settings(b.settings(
            {"roughnessAngle": None,
             "roughness": '{ profile "%s"; }' % where}))
        log = "log.good%d" % i
        rc, _ = case.solve(log, check_rc=False)
        text = case.log(log)
        t.check(rc == 0 and "envelope of the profile " + case.path
                + "/constant/wallProfile (%d points, levelled)"
                % profileOracle.POINTS in text,
                "control: profile \"%s\" runs (rc %d) and the log names %s"
                % (where, rc, case.file("constant/wallProfile")))

    b.check_bad_cases(case, platform, CASES)
    diameter_outside_the_table(case)
    outside_the_table_on_another_processor(platform, args)


#: The warning of diameters outside the tabulated range: mesh patch, entry,
#: the diameters that hit, the table's range
OUTSIDE = re.compile(r"Patch (\S+) \(entry (\S+)\): parcels of diameters "
                     r"(\S+) to (\S+) m hit the wall, outside the diameters "
                     r"(\S+) to (\S+) m")


def check_outside_warning(text, what, diameters):
    """One warning, on lowerWall, naming the entry, the smallest and largest
    of diameters (those of the parcels that hit in the first step with such
    a hit) and 1 to 50 um."""
    warned = OUTSIDE.findall(text)
    t.check(len(warned) == 1, "%s: warned once (%d warnings)"
            % (what, len(warned)))
    if warned:
        patch, entry = warned[0][:2]
        d = [float(x) for x in warned[0][2:]]
        expected = [min(diameters), max(diameters), 1e-6, 50e-6]
        t.check(patch == "lowerWall" and entry.strip('"')
                == "(lowerWall|upperWall)"
                and all(abs(a/b - 1) < 1e-3 for a, b in zip(d, expected)),
                "%s: the warning names lowerWall, the entry, the parcels' "
                "diameters %g to %g m and 1 to 50 um (%s, %s, %s)"
                % (what, expected[0], expected[1], patch, entry, d))


def diameter_outside_the_table(case):
    with open(case.file("constant/shortTrace"), "w") as f:
        f.write(points(101))
    case.write_settings(profile("shortTrace"))
    case.set_control(endTime="0.05")
    rc, _ = case.solve("log.outsideRange", check_rc=False)
    t.check(rc == 0, "a diameter above the table: the run goes on (rc %d)"
            % rc)
    # Warned at the end of the first step with such a hit: the parcels of
    # the steepest injection arrive first (from y = 5 mm at speed sin(alpha)
    # of 1 m/s: 5.8, 10 and 29 ms; drag changes this by far less than the
    # 1 ms step), alone in that step
    arrival = {d: 0.005/math.sin(math.radians(a)) for a, d in t.ANGLES.items()}
    step = int(min(arrival.values())/0.001)
    check_outside_warning(case.log("log.outsideRange"),
                          "a diameter above the table",
                          [d for d, ta in arrival.items()
                           if int(ta/0.001) == step])
    n = len(case.read_cloud("0.05", ["d"])["d"])
    t.check(n == 3*10, "every parcel is still in the domain (%d of 30)" % n)


def outside_the_table_on_another_processor(platform, args):
    """The same on two processors (x < 0 and x > 0): every parcel starts
    and hits the wall at x > 0, on processor 1, where a warning is not
    printed; the master prints it, once."""
    case = t.wall_impact_case(platform, os.path.join(args.work, "parallel"),
                              args.cloud, two_d=True, parcels=10)
    x = [0.01 + 0.004*i for i in range(10)]
    case.write_injectors([fc.Injector(
        "steep", [(xi, 0.005, 0.0) for xi in x], (0.1, -1.0, 0.0), 80e-6)])
    with open(case.file("constant/shortTrace"), "w") as f:
        f.write(points(101))
    case.write_settings(profile("shortTrace"))
    case.set_control(endTime="0.02")
    case.mesh(2)
    rc, _ = case.solve("log.outsideRange", check_rc=False)
    t.check(rc == 0, "on processor 1 only: the run goes on (rc %d)" % rc)
    check_outside_warning(case.log("log.outsideRange"),
                          "on processor 1 only", [80e-6])


if __name__ == "__main__":
    t.main(test)
