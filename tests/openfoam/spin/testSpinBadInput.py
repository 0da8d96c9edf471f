#!/usr/bin/env python3
"""Bad settings of the spin models stop the run with a clear FatalIOError.

--model lift:   rotationalLift in particleForces; --model torque:
fluidTorque in cloudFunctions.  Each bad case must fail (non-zero exit, no
crash) with "FOAM FATAL IO ERROR", the cloud properties file and the expected
text in the log:
  - the model in a cloud whose parcels carry no spin (OpenFOAM-13
    "type cloud;" and "type MPPICCloud;", v1912 uncoupledKinematicParcelFoam's
    basicKinematicCloud): the message names the model and the cloud type and
    says where it can be used;
  - an unknown coefficient, a coefficient that is not one word, a misspelt
    keyword: the keyword and the allowed values.
Controls: the valid settings of each coefficient run and the log names the
coefficient; without the libs entry OpenFOAM does not know the model.

Usage: testSpinBadInput.py --platform openfoam13|openfoam1912
           --model lift|torque [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import os
import re

from foamcase import spinCase as s
from foamcase import testing as t
import foamcase as fc

#: Signs of a crash instead of a clean fatal error (a stack trace)
CRASH_SIGNS = ["sigSegv", "sigFpe", "Segmentation fault", "core dumped",
               "printStack"]

MODELS = {
    # model: (type name, settings of a coefficient, coefficients)
    "lift": ("rotationalLift",
             lambda body: ("rotationalLift\n{\n%s\n}" % body, ""),
             ("OesterleBuiDinh", "RubinowKeller", "Loth")),
    "torque": ("fluidTorque",
               lambda body: ("", "fluidTorque1\n{\n    type fluidTorque;"
                                 "\n%s\n}" % body),
               ("DennisSinghIngham", "Stokes")),
}


#: The file (included by the cloud properties) that holds the entries
INCLUDE = {"rotationalLift": "spinForces", "fluidTorque": "spinFunctions"}

#: The allowed coefficients as the message lists them
ALLOWED = {"lift": "RubinowKeller OesterleBuiDinh Loth",
           "torque": "Stokes DennisSinghIngham"}


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p, kinds=False)
    p.add_argument("--model", required=True, choices=sorted(MODELS))
    return p.parse_args()


def run(args, platform, name, body, kind="colliding", with_libs=True):
    """The case with the model's entry body, run for one step.
    Returns (rc, log text)."""
    model, entries, _ = MODELS[args.model]
    forces, functions = entries(body)
    case = s.spin_case(platform, os.path.join(args.work, name),
                       [dict(d=1e-4, position=(0.005, 0.055, 0.005))],
                       forces=forces, functions=functions, kind=kind,
                       deltaT=1e-3)
    s.write_carrier(case, "uniform (1 0 0)", "fixedValue")
    if not with_libs:
        path = case.file("system/controlDict")
        fc.write_text(path, "\n".join(
            line for line in fc.read_text(path).splitlines()
            if not line.startswith("libs")) + "\n")
    fc.block_mesh(case.path)
    rc, _ = case.solve("log.solver", check_rc=False)
    return rc, case.log("log.solver")


def check_fatal(platform, model, name, rc, out, expected):
    """A clean FatalIOError with the expected text and the file of the
    entry: the cloud properties (v1912 names the dictionary from its top
    file) or the included file that holds the entry (OpenFOAM-13)."""
    files = [platform.properties, "constant/" + INCLUDE[model]]
    missing = [e for e in ["FOAM FATAL IO ERROR"] + expected if e not in out]
    if not any(f in out for f in files):
        missing.append(" or ".join(files))
    # The start-up banner says "sigFpe : Enabling floating point exception
    # trapping": only a stack trace or a signal is a crash
    body = re.sub(r"(?m)^sig\w+\s*:.*$", "", out)
    crashed = [c for c in CRASH_SIGNS if c in body]
    t.check(rc != 0 and not missing and not crashed,
            "%s: rc %d, %s%s" % (name, rc, "missing text %s" % missing
                                 if missing else "error names %s"
                                 % ", ".join(expected),
                                 ", CRASH %s" % crashed if crashed else ""))


def test():
    args = parse_args()
    platform = fc.Platform(args.platform)
    model, _, coefficients = MODELS[args.model]

    # Controls: each coefficient runs and is named in the log
    for c in coefficients:
        rc, out = run(args, platform, "good" + c,
                      "    coefficient %s;" % c)
        t.check(rc == 0 and "%s: coefficient %s" % (model, c) in out,
                "control: %s with coefficient %s runs (rc %d)" % (model, c,
                                                                  rc))
    rc, out = run(args, platform, "goodDefault", "")
    t.check(rc == 0 and "%s: coefficient %s" % (model, coefficients[0])
            in out, "control: %s without settings runs with the default "
            "coefficient %s (rc %d)" % (model, coefficients[0], rc))

    # Clouds without spin
    spinless = [("kinematic", "cloud" if platform.foundation
                 else "basicKinematicCloud")]
    if platform.foundation:
        spinless.append(("MPPIC", "MPPICCloud"))
    for kind, cloud_type in spinless:
        rc, out = run(args, platform, "noSpin" + kind, "", kind=kind)
        check_fatal(platform, model, "%s in a %s cloud" % (model, cloud_type),
                    rc, out, ["%s acts on the spin of the parcels" % model,
                              "(type %s) carry no spin" % cloud_type,
                              "collidingCloud",
                              "basicKinematicCollidingCloud"])

    # Bad coefficients and keywords
    bad = [
        ("unknown coefficient", "    coefficient Saffman;",
         ["'coefficient'", "'Saffman'", "one of " + ALLOWED[args.model]]),
        ("coefficient not one word", "    coefficient (1 2);",
         ["'coefficient'", "one of"]),
        ("misspelt keyword", "    coeficient %s;" % coefficients[1],
         ["'coeficient'", "keywords of %s" % model]),
    ]
    for i, (name, body, expected) in enumerate(bad):
        rc, out = run(args, platform, "bad%d" % i, body)
        check_fatal(platform, model, "%s: %s" % (model, name), rc, out,
                    expected)

    # Control: without libs OpenFOAM does not know the model
    rc, out = run(args, platform, "noLibs", "", with_libs=False)
    t.check(rc != 0 and "Unknown" in out and model in out,
            "without libs: OpenFOAM does not know %s (rc %d)" % (model, rc))


if __name__ == "__main__":
    t.main(test)
