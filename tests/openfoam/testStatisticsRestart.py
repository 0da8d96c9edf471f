#!/usr/bin/env python3
"""The statistics survive a restart, as localInteraction's do.

Runs the wall-impact case to t = 0.025 (after the 30 and 60 deg parcels have
hit the wall, before the 10 deg ones), then restarts it to t = 0.05.  The
statistics file of the restarted run (postProcessing/.../0.025/) must go on
from the stored totals: its first row already counts the hits before the
restart, its last row counts every parcel once, and its mean k_n, k_t and
energy loss equal those of all parcels at the end; the same from restart
files in the older forms (counts without patch names, sums instead of
exactSums).  (OpenFOAM-13's functions
solver reads the frozen carrier at subSolverTime 0: the restart time holds
no carrier fields.)

Usage: testStatisticsRestart.py --platform openfoam13|openfoam1912 [--cloud KIND]
           [--parcels N] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import glob
import math
import os
import re

import numpy as np

from foamcase import testing as t
import foamcase as fc


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p)
    p.add_argument("--parcels", type=int, default=2000)
    return p.parse_args()


def test():
    args = parse_args()
    n = args.parcels
    platform = fc.Platform(args.platform)
    case = t.wall_impact_case(platform, os.path.join(args.work, "case"),
                              args.cloud, parcels=n)
    case.mesh()

    case.set_control(endTime="0.025", writeInterval="25")
    case.solve("log.run1")
    t.check("stored statistics" not in case.log("log.run1"),
            "first run: nothing stored, nothing ignored or dropped")
    _, rows1 = case.read_statistics()
    hits1 = fc.column(rows1[-1], "lowerWall_hits")
    t.check(hits1 == 2 * n,
            "first run: the 30 and 60 deg parcels hit before t = 0.025 "
            "(%d hits)" % hits1)

    case.set_control(endTime="0.05")
    case.solve("log.run2")
    t.check(os.path.exists(case.statistics_file("0.025")),
            "restart writes a new file in 0.025/")
    _, rows = case.read_statistics()
    rows2 = rows[len(rows1):]
    t.check(len(rows2) > 0, "restart: %d rows after the restart" % len(rows2))
    t.check(rows2[0]["Time"] > 0.025 and rows2[0]["lowerWall_hits"] >= hits1,
            "restart: the first row (t = %g) goes on from the stored %d hits "
            "(%d)" % (rows2[0]["Time"], hits1, rows2[0]["lowerWall_hits"]))
    last = rows2[-1]
    t.check(last["lowerWall_hits"] == 3 * n,
            "restart: every parcel counted once (%d hits)"
            % last["lowerWall_hits"])

    parcels = case.read_cloud("0.05", ["U", "d"])
    U = parcels["U"]
    t.check(len(U) == 3 * n, "restart: no parcel injected twice or lost "
            "(%d parcels)" % len(U))
    kn = np.empty(len(U))
    kt = np.empty(len(U))
    for angle, d in t.ANGLES.items():
        group = np.abs(parcels["d"] - d) < 1e-9
        kn[group] = U[group, 1] / math.sin(math.radians(angle))
        kt[group] = U[group, 0] / math.cos(math.radians(angle))
    t.check(abs(last["lowerWall_meanKn"] - kn.mean()) < 1e-8,
            "restart: meanKn %.10g = all parcels' %.10g"
            % (last["lowerWall_meanKn"], kn.mean()))
    t.check(abs(last["lowerWall_meanKt"] - kt.mean()) < 1e-8,
            "restart: meanKt %.10g = all parcels' %.10g"
            % (last["lowerWall_meanKt"], kt.mean()))

    renamed_restart(args, platform, n)
    large_count_restart(args, platform, n)
    old_format_restart(args, platform, n)


def old_format_restart(args, platform, n):
    """Restart files written by earlier versions, still read: the counts as
    a labelList 'counts' without the patch names (placed by index), and the
    sums as a scalarList 'sums' instead of the strings of 'exactSums'.  The
    first run's stored entries are rewritten in the older form (the same
    numbers, 17 digits); the restart must go on from them as from the
    current form: lowerWall's 3n hits and mean k_n equal to the current
    form's restart (exactly: the same numbers), no stored statistics
    ignored."""
    results = {}
    for form in ("current", "countsWithoutPatches", "sums"):
        case = t.wall_impact_case(platform, os.path.join(args.work, form),
                                  args.cloud, parcels=n)
        case.mesh()
        case.set_control(endTime="0.025", writeInterval="25")
        case.solve("log.run1")
        paths = glob.glob(case.file(
            "0.025/uniform/lagrangian/*/*OutputProperties"))
        text = fc.read_text(paths[0])

        def strings(key):
            m = re.search(r"\b%s\s+\d+\s*\(([^)]*)\)\s*;" % key, text)
            if not m:
                raise t.TestFailure("%s: no %s in %s" % (form, key, paths[0]))
            return m, re.findall(r'"([^"]*)"', m.group(1))

        if form == "countsWithoutPatches":
            m, counts = strings("exactCounts")
            text = text.replace(m.group(0), "counts %d (%s);" % (
                len(counts), " ".join(counts)))
            text, k = re.subn(r"\n\s*patches\s+\d+\s*\([^)]*\)\s*;", "",
                              text)
            t.check(k == 1, "%s: stored counts rewritten as a labelList, "
                    "the patch names removed" % form)
        elif form == "sums":
            m, sums = strings("exactSums")
            text = text.replace(m.group(0), "sums %d (%s);" % (
                len(sums), " ".join(sums)))
            t.check("exactSums" not in text and "sums %d (" % len(sums)
                    in text, "%s: stored sums rewritten as a scalarList "
                    "'sums'" % form)
        with open(paths[0], "w") as f:
            f.write(text)
        case.set_control(endTime="0.05")
        rc, _ = case.solve("log.run2", check_rc=False)
        _, rows = case.read_statistics()
        results[form] = rows[-1]
        t.check(rc == 0 and "stored statistics" not in case.log("log.run2"),
                "%s: the restart runs (rc %d), no stored statistics ignored"
                % (form, rc))
    ref = results["current"]
    for form in ("countsWithoutPatches", "sums"):
        last = results[form]
        t.check(last["lowerWall_hits"] == 3 * n
                and all(last[k] == ref[k] for k in ref),
                "%s: the restart goes on from the stored totals: %d hits, "
                "every column equal to the current form's restart (mean k_n "
                "%.12g vs %.12g)" % (form, last["lowerWall_hits"],
                                     last["lowerWall_meanKn"],
                                     ref["lowerWall_meanKn"]))


def large_count_restart(args, platform, n):
    """Counters beyond a 32-bit label: the stored lowerWall hits set to
    2^31 - 48 before the restart; the n hits of the second run must take
    the total to 2^31 - 48 + n exactly (a 32-bit counter would wrap to a
    negative number), and a second restart reads that total back."""
    case = t.wall_impact_case(platform, os.path.join(args.work, "large"),
                              args.cloud, parcels=n)
    case.mesh()
    case.set_control(endTime="0.025", writeInterval="25")
    case.solve("log.run1")
    stored = 2**31 - 48
    paths = glob.glob(case.file("0.025/uniform/lagrangian/*/*OutputProperties"))
    t.check(len(paths) == 1, "large: one cloud properties file (%s)" % paths)
    text = fc.read_text(paths[0])
    # exactCounts: the first counter is lowerWall's hits (2n after the
    # first run), as text
    edited, k = re.subn(r'(exactCounts\s+\d+\s*\(\s*)"%d"' % (2 * n),
                        lambda m: m.group(1) + '"%d"' % stored, text)
    t.check(k == 1, "large: lowerWall's stored hits set to %d" % stored)
    with open(paths[0], "w") as f:
        f.write(edited)
    # The restart counts on; a second restart, from 0.05, reads it back
    for end, log, what in (("0.05", "log.run2", "the restart counts on past "
                            "2^31 - 1 to"),
                           ("0.075", "log.run3", "a second restart reads "
                            "back")):
        case.set_control(endTime=end)
        rc, _ = case.solve(log, check_rc=False)
        _, rows = case.read_statistics()
        hits = rows[-1]["lowerWall_hits"]
        t.check(rc == 0 and hits == stored + n,
                "large: %s %d + %d = %d (%d)"
                % (what, stored, n, stored + n, hits))


def rename_patches(boundary, new_names):
    """constant/polyMesh/boundary with the patches renamed (old: new)."""
    text = fc.read_text(boundary)
    names = re.compile(r"^(\s*)(%s)(\s*)$" % "|".join(new_names), re.M)
    renamed, count = names.subn(
        lambda m: m.group(1) + new_names[m.group(2)] + m.group(3), text)
    with open(boundary, "w") as f:
        f.write(renamed)
    return count


def renamed_restart(args, platform, n):
    """The same restart with lowerWall and upperWall renamed into each other
    in the mesh between the runs (the same number of patches): the stored
    totals follow the names.  The wall that was lowerWall, hit by every
    parcel, is now upperWall; lowerWall (the old upper wall) is hit by
    none.  So lowerWall keeps the first run's totals and upperWall counts
    the n parcels of the second run only.  Placed by index, as before
    2026-11-27, upperWall would show 3n hits and lowerWall none.  Then a
    patch renamed to a new name: its stored totals are dropped, warned."""
    case = t.wall_impact_case(platform, os.path.join(args.work, "renamed"),
                              args.cloud, parcels=n)
    case.mesh()
    case.set_control(endTime="0.025", writeInterval="25")
    case.solve("log.run1")
    _, rows1 = case.read_statistics()
    first = rows1[-1]
    boundary = case.file("constant/polyMesh/boundary")
    t.check(rename_patches(boundary, {"lowerWall": "upperWall",
                                      "upperWall": "lowerWall"}) == 2,
            "renamed: lowerWall and upperWall exchanged in the mesh")

    case.set_control(endTime="0.05")
    rc, _ = case.solve("log.run2", check_rc=False)
    t.check(rc == 0, "renamed: the restart runs (rc %d)" % rc)
    _, rows = case.read_statistics()
    last = rows[-1]
    t.check(last["lowerWall_hits"] == 2 * n
            and last["lowerWall_meanKn"] == first["lowerWall_meanKn"],
            "renamed: lowerWall keeps the first run's %d hits and mean k_n "
            "(%d, %.12g vs %.12g)" % (2 * n, last["lowerWall_hits"],
                                      last["lowerWall_meanKn"],
                                      first["lowerWall_meanKn"]))
    t.check(last["upperWall_hits"] == n,
            "renamed: upperWall counts the second run's %d hits only (%d)"
            % (n, last["upperWall_hits"]))
    t.check("stored statistics" not in case.log("log.run2"),
            "renamed: no stored statistics ignored or dropped")

    # Then lowerWall renamed floorWall (the entry's expression with it):
    # its stored totals have no patch left and are dropped, with a warning
    # naming it, once; floorWall starts from zero, upperWall goes on
    rename_patches(boundary, {"lowerWall": "floorWall"})
    for time_dir in ("0", "0.05"):      # v1912 writes the carrier fields
        folder = case.file(time_dir)
        for name in os.listdir(folder):
            path = os.path.join(folder, name)
            if os.path.isfile(path):
                text = fc.read_text(path)
                with open(path, "w") as f:
                    f.write(re.sub(r"\blowerWall\b", "floorWall", text))
    case.write_settings(t.DEFAULT_SETTINGS.replace(
        "(lowerWall|upperWall)", "(floorWall|upperWall)"))
    case.set_control(endTime="0.075")
    rc, _ = case.solve("log.run3", check_rc=False)
    out = case.log("log.run3")
    warning = ("Dropping the stored statistics of patches not in this "
               "mesh: 1(lowerWall)")
    t.check(rc == 0 and out.count(warning) == 1,
            "dropped: the run (rc %d) warns once '%s' (%d times)"
            % (rc, warning, out.count(warning)))
    _, rows = case.read_statistics()
    last = rows[-1]
    t.check(last["floorWall_hits"] == 0 and last["upperWall_hits"] == n,
            "dropped: floorWall starts from 0 hits (%d), upperWall goes on "
            "from %d (%d)" % (last["floorWall_hits"], n,
                              last["upperWall_hits"]))


if __name__ == "__main__":
    t.main(test)
