#!/usr/bin/env python3
"""The types rebound, stick, escape and none behave exactly like
standardWallInteraction's.

For each type, runs the wall-impact case twice: with roughWallInteraction
(the type on both walls; escape or none on the outlet) and with
standardWallInteraction (the same type and coefficients; it hands non-wall
patches back to OpenFOAM, which lets parcels escape there).  The parcel
fields U, active and positions must be identical, bit for bit, and so must
OpenFOAM's system escape count.  The per-patch escape/stick counts of
roughWallInteraction must equal the parcels that escaped/stuck.  none is
tested on the outlet, with an end time late enough for parcels to reach it
(none on a wall is refused: see testBadInput.py).

Usage: testStandardTypes.py --solver NAME [--parcels N] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import os
import re

import numpy as np

import ofTestTools as t

#: wall type, its coefficients, outlet type, end time
TYPES = [
    ("rebound", "e 0.7; mu 0.1;", "escape", "0.05"),
    ("rebound", "", "none", "0.15"),
    ("stick", "", "escape", "0.05"),
    ("escape", "", "escape", "0.05"),
]


def rough_settings(kind, coeffs, outlet):
    return """
patchInteractionModel roughWallInteraction;

roughWallInteractionCoeffs
{
    patches
    (
        "(lowerWall|upperWall)" { type %s; %s }
        outlet { type %s; }
    );
}
""" % (kind, coeffs, outlet)


def standard_settings(kind, coeffs):
    return """
patchInteractionModel standardWallInteraction;

standardWallInteractionCoeffs
{
    type %s;
    %s
}
""" % (kind, coeffs)


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--solver", required=True)
    p.add_argument("--parcels", type=int, default=1000)
    p.add_argument("--work", default=".")
    return p.parse_args()


def system_escapes(log):
    """OpenFOAM's system escape count at the last time step."""
    counts = re.findall(r"Parcel fate: system \(number, mass\)\s*\n"
                        r"\s*- escape\s*=\s*(\d+)", log)
    return int(counts[-1]) if counts else -1


def run(args, name, settings, end_time):
    case = os.path.abspath(os.path.join(args.work, name))
    t.make_case(case, parcels=args.parcels, settings=settings)
    t.set_control(case, endTime=end_time)
    t.run(case, ["blockMesh"], "log.blockMesh")
    t.run(case, [args.solver], "log." + args.solver)
    with open(os.path.join(case, "log." + args.solver)) as f:
        log = f.read()
    d = os.path.join(case, end_time, "lagrangian", "kinematicCloud")
    fields = {}
    if os.path.isdir(d):
        for name in ("U", "active", "positions"):
            path = os.path.join(d, name)
            with open(path) as f:
                text = f.read()
            # Compare the data, not the header
            fields[name] = text[text.index("// * *"):]
    return case, log, fields


def test():
    args = parse_args()
    n_total = 3 * args.parcels
    for i, (kind, coeffs, outlet, end_time) in enumerate(TYPES):
        label = "%s%s, outlet %s" % (kind, " (%s)" % coeffs if coeffs else "",
                                     outlet)
        case_r, log_r, fields_r = run(args, "rough%d" % i,
                                      rough_settings(kind, coeffs, outlet),
                                      end_time)
        _, log_s, fields_s = run(args, "standard%d" % i,
                                 standard_settings(kind, coeffs), end_time)
        t.check(fields_r.keys() == fields_s.keys(),
                "%s: the same parcel fields are written" % label)
        for name in fields_r:
            t.check(fields_r[name] == fields_s[name],
                    "%s: parcel field %s identical to standardWallInteraction"
                    % (label, name))
        t.check(system_escapes(log_r) == system_escapes(log_s) >= 0,
                "%s: system escapes %d, standardWallInteraction %d"
                % (label, system_escapes(log_r), system_escapes(log_s)))

        _, rows = t.read_statistics(case_r)
        last = rows[-1]
        if kind == "stick":
            active = t.read_field(os.path.join(case_r, end_time, "lagrangian",
                                               "kinematicCloud", "active"))
            stuck = int(np.count_nonzero(active == 0))
            t.check(stuck == n_total and last["lowerWall_nStick"] == stuck,
                    "stick: statistics file lowerWall_nStick = %d stuck "
                    "parcels" % last["lowerWall_nStick"])
        if outlet == "none":
            t.check(0 < system_escapes(log_r) < n_total and fields_r,
                    "none: some parcels left through the outlet (%d of %d)"
                    % (system_escapes(log_r), n_total))
        if kind == "escape":
            t.check(not fields_r and last["lowerWall_nEscape"] == n_total,
                    "escape: all parcels left, lowerWall_nEscape = %d"
                    % last["lowerWall_nEscape"])


if __name__ == "__main__":
    t.main(test)
