#!/usr/bin/env python3
"""Bad profile roughness parameters (the roughness { Ra ...; RSm ...; }
entry of a rough patch) stop the run with a FatalIOError naming the
dictionary, the keyword and the allowed range.

Control: valid parameters run.  Then one run per bad entry: negative or
zero values, Rq < Ra, RSm < Ra, flanks steeper than 45 deg, no height,
no RSm, an unknown keyword inside roughness, roughness not a dictionary,
and roughnessAngle and roughness together.  Same harness and checks as
testPatchSettingsBadInput.py (FOAM FATAL IO ERROR, the settings file, the patches entry,
the keyword, the allowed range; no crash).

Usage: testRoughnessTableBadInput.py --platform openfoam13|openfoam1912
           [--cloud KIND] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import os

from foamcase import testing as t
import foamcase as fc
import testPatchSettingsBadInput as b


def rough(body, angle=None):
    """Settings with roughness { body } instead of roughnessAngle (or with
    both if angle is given)."""
    return b.settings({"roughnessAngle": angle,
                       "roughness": "{ %s }" % body})


IN = b.IN_PATCH
key = b.key
POSITIVE = "> 0"

#: name, settings, fragments of the error message: the keyword, the scope
#: and the reason (the bound or rule broken, the value found, the closest
#: keyword)
CASES = [
    ("Ra negative", rough("Ra -1e-6; RSm 50e-6;"),
     [key("Ra"), IN, POSITIVE, "'-1e-06'"]),
    ("Ra zero", rough("Ra 0; RSm 50e-6;"),
     [key("Ra"), IN, POSITIVE, "'0'"]),
    ("Rq negative", rough("Rq -2e-6; RSm 50e-6;"),
     [key("Rq"), IN, POSITIVE, "'-2e-06'"]),
    ("Rz zero", rough("Rz 0; RSm 50e-6;"),
     [key("Rz"), IN, POSITIVE, "'0'"]),
    # Not a number: read as a number of any sign (the sign is checked
    # next), so "-inf", not -GREAT's digits, for the open lower bound
    ("Ra not a number", rough("Ra abc; RSm 50e-6;"),
     [key("Ra"), IN, "'abc'", b.NUMBER, "[-inf, inf]"]),
    ("RSm zero", rough("Ra 1e-6; RSm 0;"),
     [key("RSm"), IN, POSITIVE, "'0'"]),
    ("RSm missing", rough("Ra 1e-6;"),
     [key("RSm"), IN, "mandatory", "missing"]),
    ("no height", rough("RSm 50e-6;"),
     [key("Ra"), IN, "Ra, Rq, Rz", "missing"]),
    ("Rq below Ra", rough("Ra 2e-6; Rq 1.5e-6; RSm 50e-6;"),
     [key("Rq"), IN, "Rq >= Ra"]),
    ("RSm below Ra", rough("Ra 2e-6; RSm 1e-6;"),
     [key("RSm"), IN, "RSm > Ra"]),
    ("flanks too steep", rough("Rq 2e-6; RSm 10e-6;"),
     [key("RSm"), IN, "RSm >= 2 pi Rq", "45"]),
    ("unknown keyword", rough("Ra 1e-6; Rsm 50e-6;"),
     [key("Rsm"), IN, "roughness", b.closest("RSm")]),
    ("roughness not a dictionary",
     b.settings({"roughnessAngle": None, "roughness": "1e-6"}),
     [key("roughness"), IN, "dictionary", "'1e-06'"]),
    ("roughnessAngle and roughness", rough("Ra 1e-6; RSm 50e-6;", angle="8"),
     [key("roughnessAngle"), IN, "roughness", "both"]),
]


def test():
    args = b.parse_args()
    platform = fc.Platform(args.platform)
    case = t.wall_impact_case(platform, os.path.join(args.work, "case"),
                              args.cloud, two_d=True, parcels=10)
    case.set_control(endTime="0.001")
    case.mesh()

    # Controls: valid parameters run and the log states the Delta they
    # give: by default the envelope of the synthetic Gaussian profile of
    # their Rq (Ra given: Rq = sqrt(pi/2) Ra = 1.25331e-06 m), on request
    # the closed-form estimate
    for i, (body, text) in enumerate([
            ("Ra 1e-6; Rz 6e-6; RSm 50e-6;",
             "envelope of the synthetic Gaussian profile, Rq = 1.25331e-06 m,"
             " RSm = 5e-05 m"),
            ("Ra 1e-6; Rz 6e-6; RSm 50e-6; estimate closedForm;",
             "atan(2 pi Rq/max(RSm, d))")]):
        case.write_settings(rough(body))
        log = "log.good%d" % i
        rc, _ = case.solve(log, check_rc=False)
        t.check(rc == 0 and text in case.log(log),
                "control: roughness { %s } runs (rc %d) and the log says '%s'"
                % (body, rc, text))

    b.check_bad_cases(case, platform, CASES)


if __name__ == "__main__":
    t.main(test)
