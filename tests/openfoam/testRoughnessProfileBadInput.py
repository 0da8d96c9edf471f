#!/usr/bin/env python3
"""A bad wall profile (roughness { profile "<file>"; } of a rough patch)
stops the run with a FatalIOError naming the dictionary, the keyword
profile, the file and, for a bad line, its number.

Control: a valid trace (foamcase/roughnessProfileOracle.py's) given by a path
relative to the case runs, and so does one given as $FOAM_CASE/...; the
profile parameters with an unknown estimate stop.  Then one run per bad
file: unreadable (missing), fewer than 10 points, x not increasing, NaN, a
third column; and profile together with RSm.  Same harness and checks as
testBadInput.py (FOAM FATAL IO ERROR, the settings file, the patches entry,
the keyword; no crash).  The expected line numbers are those of the files
written here.

Usage: testRoughnessProfileBadInput.py --platform openfoam13|openfoam1912
           [--cloud KIND] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import os

from foamcase import testing as t
import foamcase as fc
from foamcase import roughnessProfileOracle as profileOracle
import testBadInput as b


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
PROFILE = "keyword 'profile'"

#: name, settings, texts that the log must contain
CASES = [
    ("file missing", profile("missing"),
     [PROFILE, IN, "constant/missing: cannot open the profile file"]),
    ("fewer than 10 points", profile("tooFew"),
     [PROFILE, IN, "constant/tooFew: 9 points in 10 lines, at least 10 needed"]),
    ("x not increasing", profile("notIncreasing"),
     [PROFILE, IN, "constant/notIncreasing:6: x = 4e-06 m is not above the "
      "previous x = 4e-06 m"]),
    ("NaN", profile("nan"),
     [PROFILE, IN, "constant/nan:8: not a finite number: '7e-6 nan'"]),
    ("three columns", profile("threeColumns"),
     [PROFILE, IN, "constant/threeColumns:5: expected two numbers 'x z', "
      "got '3e-6 0 1'"]),
    ("profile and RSm",
     b.settings({"roughnessAngle": None,
                 "roughness": '{ profile "constant/wallProfile"; RSm 1e-4; }'}),
     ["keyword 'RSm'", IN, "no other keyword beside profile"]),
    ("unknown estimate",
     b.settings({"roughnessAngle": None,
                 "roughness": "{ Rq 1e-6; RSm 1e-4; estimate closedform; }"}),
     ["keyword 'estimate'", IN, "envelope closedForm", "'closedform'"]),
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


if __name__ == "__main__":
    t.main(test)
