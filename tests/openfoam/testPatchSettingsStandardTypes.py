#!/usr/bin/env python3
"""The types rebound, stick, escape and none behave exactly like
standardWallInteraction's.

For each type, runs the wall-impact case twice: with roughWallInteraction
(the type on both walls; escape or none on the outlet) and with
standardWallInteraction (the same type and coefficients; it hands non-wall
patches back to OpenFOAM).  The parcel fields U, active and positions must be
identical, bit for bit, and so must the parcel count at the end.  The
per-patch escape/stick counts of roughWallInteraction must equal the parcels
that escaped/stuck.  none is tested on the outlet, with an end time late
enough for parcels to reach it (none on a wall is refused: see
testPatchSettingsBadInput.py); a parcel that hits it leaves the domain on both platforms,
but they count it differently:
  openfoam1912  KinematicParcel::hitPatch counts a hit on a non-wall patch as
                a 'Parcel fate: system' escape before calling the model: the
                system escape counts of the two runs must be equal and
                between 0 and all parcels;
  openfoam13    there is no system count: particle::hitBasicPatch removes
                the parcel after the model returns false.  The parcels
                missing at the end (log) must be equal in the two runs and
                between 0 and all parcels, and the written cloud must hold
                the log's count of the written step (the clouds function
                object moves the cloud after the write: the step before
                the last).

Usage: testPatchSettingsStandardTypes.py --platform openfoam13|openfoam1912 [--cloud KIND]
           [--parcels N] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import os

import numpy as np

from foamcase import testing as t
import foamcase as fc

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
    t.add_platform_args(p)
    p.add_argument("--parcels", type=int, default=1000)
    return p.parse_args()


def run(args, name, settings, end_time):
    case = t.wall_impact_case(fc.Platform(args.platform),
                              os.path.join(args.work, name), args.cloud,
                              parcels=args.parcels, settings=settings)
    case.set_control(endTime=end_time)
    case.mesh()
    case.solve()
    fields = {}
    for d in case.cloud_dirs(end_time):
        if os.path.isdir(d):
            for field in ("U", "active", "positions"):
                text = fc.read_text(os.path.join(d, field))
                # Compare the data, not the header
                fields[field] = text[text.index("// * *"):]
    return case, case.log(), fields


def test():
    args = parse_args()
    platform = fc.Platform(args.platform)
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
        left_r, left_s = fc.final_parcels(log_r), fc.final_parcels(log_s)
        t.check(left_r == left_s >= 0,
                "%s: %d parcels at the end, standardWallInteraction %d"
                % (label, left_r, left_s))
        if not platform.foundation:
            t.check(fc.system_escapes(log_r) == fc.system_escapes(log_s) >= 0,
                    "%s: system escapes %d, standardWallInteraction %d"
                    % (label, fc.system_escapes(log_r),
                       fc.system_escapes(log_s)))

        _, rows = case_r.read_statistics()
        last = rows[-1]
        if kind == "stick":
            active = case_r.read_cloud(end_time, ["active"])["active"]
            stuck = int(np.count_nonzero(active == 0))
            t.check(stuck == n_total
                    and fc.column(last, "lowerWall_nStick") == stuck,
                    "stick: statistics file lowerWall_nStick = %d stuck "
                    "parcels" % fc.column(last, "lowerWall_nStick"))
        if outlet == "none":
            if platform.foundation:
                written = len(case_r.read_cloud(end_time, ["d"])["d"])
                reported = fc.parcel_counts(log_r)[platform.written_report]
                removed = n_total - left_r
                t.check(0 < removed < n_total and written == reported,
                        "none: some parcels left through the outlet (%d of "
                        "%d removed; %d written = the log's count of the "
                        "written step)" % (removed, n_total, written))
            else:
                escapes = fc.system_escapes(log_r)
                t.check(0 < escapes < n_total and fields_r
                        and left_r == n_total - escapes,
                        "none: some parcels left through the outlet (%d of "
                        "%d system escapes)" % (escapes, n_total))
        if kind == "escape":
            written = len(case_r.read_cloud(end_time, ["d"])["d"])
            t.check(written == 0 and left_r == 0
                    and fc.column(last, "lowerWall_nEscape") == n_total,
                    "escape: all parcels left (%d written), lowerWall_nEscape "
                    "= %d" % (written, fc.column(last, "lowerWall_nEscape")))


if __name__ == "__main__":
    t.main(test)
