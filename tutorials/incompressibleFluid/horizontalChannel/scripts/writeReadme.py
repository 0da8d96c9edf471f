#!/usr/bin/python3
"""Write the numbers of README.md from the committed results (results/).

Every number of the tutorial's README that comes from a run sits between
markers

    <!-- begin generated: NAME -->
    ...
    <!-- end generated: NAME -->

and is written by this script from results/summary.csv, profiles.csv,
carrier.csv, spinRatios.csv, runInfo, smokeTest-openfoam*.csv and
timeStep/*/summary.csv; nothing between the markers is
edited by hand. With --check it writes nothing and fails (exit 1) if the
README differs from what it would write: the README's numbers are those of
the committed results (ctest tutorial_horizontalChannel_readme).

Usage: writeReadme.py [--check] [--results DIR] [--readme FILE]
"""
import argparse
import csv
import difflib
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TUTORIAL = os.path.dirname(HERE)

import checkResults  # the smoke test's criteria

BEGIN = "<!-- begin generated: %s -->"
END = "<!-- end generated: %s -->"


# ----------------------------------------------------------------------------
# Reading the results

def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def number(row, key):
    v = row.get(key, "")
    return float(v) if v not in ("", None) else math.nan


def read_info(path):
    info = {}
    with open(path) as f:
        for line in f:
            if line.strip():
                key, value = line.split(None, 1)
                info[key] = value.strip()
    return info


class Results:
    def __init__(self, directory):
        self.dir = directory
        rows = read_rows(os.path.join(directory, "summary.csv"))
        self.summary = {r["variant"]: r for r in rows}
        self.variants = [r["variant"] for r in rows]
        self.carrier = read_rows(os.path.join(directory, "carrier.csv"))[0]
        self.info = read_info(os.path.join(directory, "runInfo"))
        self.ratios = {r["variant"]: r for r in
                       read_rows(os.path.join(directory, "spinRatios.csv"))}
        self.angles = {}
        for row in read_rows(os.path.join(directory, "angles.csv")):
            self.angles.setdefault(row["variant"], []).append(row)
        self.smoke = {}
        for version in ("14", "13"):
            path = os.path.join(directory, "smokeTest-openfoam%s.csv" % version)
            if os.path.exists(path):
                self.smoke[version] = read_rows(path)
        self.timestep = {}
        tdir = os.path.join(directory, "timeStep")
        if os.path.isdir(tdir):
            for name in sorted(os.listdir(tdir)):
                path = os.path.join(tdir, name, "summary.csv")
                if os.path.exists(path):
                    self.timestep[name] = (
                        {r["variant"]: r for r in read_rows(path)},
                        read_info(os.path.join(tdir, name, "runInfo")))

    def s(self, variant, key):
        return number(self.summary[variant], key)


#: The default variant and the controls, each changing one modelling choice
#: against its reference: (variant, reference, what changes)
DEFAULT = "steel"
CHOICES = (
    ("steel.noLateralTilt", DEFAULT,
     "no sideways facet tilt (facets tilted in the x-y plane only), still 3-D"),
    ("steel.2D", "steel.noLateralTilt",
     "2-D domain (one-cell slab, no spanwise motion) instead of the 3-D slab, both "
     "without sideways tilt"),
    ("steel.OesterleBuiDinh", DEFAULT,
     "rotational lift: Oesterle & Bui Dinh (old) instead of Loth"),
    ("steel.noLift", DEFAULT, "rotational lift off (fluid torque on)"),
    ("steel.eTable", DEFAULT, "e a table of the facet impact angle (illustrative, 0.8 "
     "at 10 deg) instead of the constant 0.8"),
    ("steel.muDTable", DEFAULT, "muD a table of the facet impact angle (illustrative, "
     "0.4 up to 10 deg) instead of the constant 0.4"),
    ("steel.noSaffmanMei", DEFAULT, "Saffman-Mei shear lift off"),
    ("steel.noDispersion", DEFAULT, "turbulent dispersion off"),
    ("rough5", DEFAULT, "a constant Delta = 5 deg instead of the surface's"),
    ("loading0", DEFAULT, "the loading variants' set-up, still one-way: the air "
     "solved on the whole channel with wall functions (cells of 9 bead diameters), "
     "a bead hitting the wall at its centre"),
    ("loading0.3", "loading0", "two-way coupling at a mass loading of 0.3"),
    ("loading1", "loading0", "two-way coupling at a mass loading of 1"),
    ("loading0.3.collisions", "loading0.3", "collisions between beads at a mass "
     "loading of 0.3"),
    ("loading1.collisions", "loading1", "collisions between beads at a mass "
     "loading of 1"),
)
#: The loading variants, in the order of the loading table
LOADING = ("loading0", "loading0.3", "loading0.3.collisions", "loading1",
           "loading1.collisions")
#: The statistics of the sensitivity table: (column, text, format, scale)
STATS = (
    ("upperFraction", "parcels in the upper half [%]", "%.2f", 100),
    ("UyRms", "rms wall-normal velocity [m/s]", "%.3f", 1),
    ("UxRms", "rms streamwise velocity [m/s]", "%.3f", 1),
    ("meanUxOverBulk", "mean streamwise velocity / bulk air velocity", "%.4f", 1),
    ("impactFrequency", "wall impacts per parcel per metre (both walls)", "%.3f", 1),
)
#: The roughness trend, smooth end first (Delta = 0 is not part of it); the
#: surface's Delta at 195 um (7.0 deg) is its rough end
TREND = ("rough1", "rough2.5", "rough5", "steel")
SMOOTH = "smooth"


# ----------------------------------------------------------------------------
# Formatting

def pm(value, se, fmt="%.3f", scale=1):
    if not math.isfinite(value):
        return "-"
    return (fmt + " +- " + fmt) % (scale*value, scale*se)


def num(value, fmt="%.3f"):
    return fmt % value if math.isfinite(value) else "-"


def table(head, rows):
    lines = ["| " + " | ".join(head) + " |",
             "|" + "---|"*len(head)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def z(a, sa, b, sb):
    se = math.hypot(sa, sb)
    return abs(b - a)/se if se > 0 else (0.0 if a == b else math.inf)


# ----------------------------------------------------------------------------
# The generated blocks

def relative_command(command):
    """The command of runInfo, run in this folder"""
    i = command.find("Allrun")
    return "./" + command[i:] if i >= 0 else command


def provenance(r):
    i = r.info
    v0 = r.variants[0]
    return ("Made by `%s` (in this folder) on %s, OpenFOAM %s, %s, %s variants at a "
            "time; %d parcels of %g um per variant, sampled every 0.05 s from %g s to %g s "
            "(%d snapshots, %d samples per variant), time step %g ms. Files: "
            "`results/summary.csv`, `results/profiles.csv`, `results/spinRatios.csv`, "
            "`results/carrier.csv`, `results/runInfo` (with the commit the run was "
            "made at)." % (
                relative_command(i["command"]),
                i["date"], i["openfoam"], i["machine"], i["jobs"],
                r.s(v0, "nParcels"), 1e6*r.s(v0, "diameter"),
                r.s(v0, "sampleStart"), r.s(v0, "sampleEnd"),
                r.s(v0, "snapshots"), r.s(v0, "samples"),
                1e3*r.s(v0, "deltaT")))


def carrier(r):
    c = {k: float(v) for k, v in r.carrier.items()}
    return ("Converged in %d iterations: friction velocity u_tau = %.3f m/s "
            "(Re_tau = %.0f), bulk velocity %.2f m/s, centreline velocity "
            "%.2f m/s (%.2f x bulk), kinematic pressure gradient %.1f m/s2 "
            "(%.0f Pa/m), first cell centre at y+ = %.2f. At one bead radius "
            "from the wall (y+ = %.1f) the air moves at %.2f m/s." % (
                c["iterations"], c["uTau"], c["ReTau"], c["Ubulk"],
                c["Ucentreline"], c["Ucentreline"]/c["Ubulk"],
                c["pressureGradient"], 1.2*c["pressureGradient"],
                c["yPlusFirstCell"], c["yPlusRadius"], c["Uradius"]))


def setup(r, v):
    x = r.summary[v]
    delta = number(x, "roughnessAngle")
    wall = ("Delta %.2f deg of the surface" % delta if x.get("roughness")
            else "Delta %g deg" % delta)
    parts = [x["geometry"], wall]
    if x.get("trackingOffset") == "0":
        parts = ["3D whole channel, wall functions", wall]
        if x.get("twoWayCoupling") == "true":
            parts.append("two-way, loading %s" % x["massLoading"])
        else:
            parts.append("one-way")
        if x.get("collisions", "none") != "none":
            parts.append("collisions between beads")
    if x["geometry"] == "3D" and x["lateralTilt"] != "on" and delta > 0:
        parts.append("no sideways tilt")
    parts.append("lift %s" % x["lift"])
    if x["torque"] != "DennisSinghIngham":
        parts.append("torque %s" % x["torque"])
    for key in ("e", "muD"):
        if x.get(key, "").startswith("table"):
            parts.append("%s table of the impact angle" % key)
    if x.get("shearLift") == "none":
        parts.append("no Saffman-Mei")
    if x.get("dispersion") == "none":
        parts.append("no dispersion")
    return ", ".join(parts)


def results_table(r):
    head = ["variant", "set-up", "upper half [%]", "rms v [m/s]", "rms u [m/s]",
            "rms w [m/s]", "mean u / U_bulk", "impacts per parcel per metre: lower / upper"]
    rows = []
    for v in r.variants:
        def s(k):
            return r.s(v, k)
        label = "`%s`" % v + (" (resting on the floor)" if v == SMOOTH else "")
        rows.append([
            label, setup(r, v), pm(s("upperFraction"), s("upperFraction_se"), "%.2f", 100),
            pm(s("UyRms"), s("UyRms_se")), pm(s("UxRms"), s("UxRms_se")),
            pm(s("UzRms"), s("UzRms_se")),
            pm(s("meanUxOverBulk"), s("meanUxOverBulk_se"), "%.4f"),
            "%s / %s" % (pm(s("impactFrequency_lowerWall"), s("impactFrequency_lowerWall_se")),
                         pm(s("impactFrequency_upperWall"), s("impactFrequency_upperWall_se")))])
    return table(head, rows) + (
        "\n\n(+- one standard error: the parcel statistics by the jackknife over 20 "
        "groups of whole parcels (the two-way coupled variants, whose parcels act on "
        "each other: over 10 time blocks of the sampling window), the impacts by "
        "the jackknife over 10 time blocks of the sampling window. v wall-normal, u streamwise, w spanwise. Impacts: "
        "patchCollisionDensity, wall-normal impact speed above 5 cm/s, per parcel "
        "per metre travelled. `%s`: Delta = 0, the beads end on the floor and its "
        "rms wall-normal velocity, %.4f m/s, is resting contact resolved as "
        "micro-bounces of one time step, of the order of g dt/2 = %.4f m/s: not "
        "physics.)" % ((SMOOTH, r.s(SMOOTH, "UyRms"), 9.81*r.s(SMOOTH, "deltaT")/2)
                       if SMOOTH in r.summary else (SMOOTH, math.nan, math.nan)))


def sensitivity(r):
    head = ["modelling choice (variant)"] + [t for _, t, _, _ in STATS]
    rows = []
    for v, ref, text in CHOICES:
        if v not in r.summary or ref not in r.summary:
            continue
        row = ["%s (`%s` - `%s`)" % (text, v, ref)]
        for key, _, fmt, scale in STATS:
            a, sa = r.s(ref, key), r.s(ref, key + "_se")
            b, sb = r.s(v, key), r.s(v, key + "_se")
            row.append("%s (%.0f s.e.)" % (pm(b - a, math.hypot(sa, sb), fmt, scale),
                                            z(a, sa, b, sb)))
        rows.append(row)
    base = ["**`%s` itself** (%s)" % (DEFAULT, setup(r, DEFAULT))] + [
        pm(r.s(DEFAULT, key), r.s(DEFAULT, key + "_se"), fmt, scale)
        for key, _, fmt, scale in STATS]
    return table(head, [base] + rows) + (
        "\n\n(Each row: the variant minus its reference, which differs from it in "
        "that one choice only (`%s` for all but the 2-D row), +- the combined standard "
        "error of the two runs (taken as independent: the parcels start at the same "
        "places, but their random walks differ), and the difference in combined "
        "standard errors.)" % DEFAULT)


def sensitivity_reading(r):
    """What each row of the sensitivity table shows, from the numbers"""
    lines = []
    for v, ref, text in CHOICES:
        if v not in r.summary or ref not in r.summary:
            continue
        zs = []
        for key, name, fmt, scale in STATS:
            a, sa = r.s(ref, key), r.s(ref, key + "_se")
            b, sb = r.s(v, key), r.s(v, key + "_se")
            zs.append((z(a, sa, b, sb), name, (b - a)/a if a else math.nan))
        zs.sort(reverse=True)
        big = [x for x in zs if x[0] > 3]
        if not big:
            lines.append("- `%s`, %s: every statistic within 3 combined standard "
                         "errors of `%s` (largest: %s, %.1f s.e.)."
                         % (v, text, ref, zs[0][1], zs[0][0]))
        else:
            lines.append("- `%s`, %s: moves %s." % (v, text, "; ".join(
                "%s by %+.0f %% (%.0f s.e.)" % (name, 100*rel, zz)
                for zz, name, rel in big)))
    return ("Each control against its reference, from the table (beyond 3 combined "
            "standard errors, relative change):\n\n" + "\n".join(lines))


def trends(r):
    vs = [v for v in TREND if v in r.summary]
    rows = []
    for key, text, fmt, scale in STATS + (("meanSpinSpeed", "mean spin omega_z d/2 [m/s]", "%.3f", 1),):
        vals = [r.s(v, key) for v in vs]
        ses = [r.s(v, key + "_se") for v in vs]
        steps = [(b - a)/math.hypot(sa, sb) if math.hypot(sa, sb) > 0 else 0
                 for a, b, sa, sb in zip(vals[:-1], vals[1:], ses[:-1], ses[1:])]
        mono = "rises" if all(x > 3 for x in steps) else (
            "falls" if all(x < -3 for x in steps) else "not monotonic beyond 3 s.e.")
        rows.append([text, " -> ".join(pm(a, b, fmt, scale) for a, b in zip(vals, ses)),
                     mono + " (steps: %s s.e.)" % ", ".join("%.0f" % x for x in steps)])
    return ("Delta = %s deg (`%s`):\n\n" % (" -> ".join(
        "%.3g" % r.s(v, "roughnessAngle") for v in vs), "`, `".join(vs))
        + table(["statistic", "value", "with growing Delta"], rows))


def spin_ratios(r):
    rows = []
    for v in r.variants:
        x = r.ratios[v]

        def q(key):
            return " / ".join("%.3g" % float(x["%s_q%02d" % (key, p)]) for p in (1, 10, 50, 90, 99))
        n, out = r.s(v, "liftEvaluations"), r.s(v, "liftOutside")
        inrun = ("{:,} of {:,} ({:.4f} %)".format(int(out), int(n), 100*out/n)
                 if math.isfinite(n) and n > 0 else "-")
        rows.append(["`%s`" % v, x["lift"], q("Gamma"), q("Rep"), q("ReR"),
                     "%.1f %%" % (100*float(x["GammaAbove1"])),
                     "%.2f %%" % (100*float(x["outsideLoth"])),
                     "%.1f %%" % (100*float(x["outsideOesterleBuiDinh"])), inrun])
    return table(["variant", "lift coefficient", "Gamma: 1 / 10 / 50 / 90 / 99 % quantiles",
                  "Re_p: quantiles", "Re_R: quantiles", "samples with Gamma > 1",
                  "outside Loth's range (Re_p < 2000, Gamma < 10)",
                  "outside Oesterle & Bui Dinh's (10 < Re_p < 140, 1 < Gamma < 6)",
                  "the run's own count: lift evaluations outside its coefficient's "
                  "range, sampling window"], rows) + (
        "\n\n(Last column: `summary.csv` columns `liftOutside`, `liftEvaluations`, "
        "summed from the `rotationalLift` log line of every time step of the sampling "
        "window: every parcel, with the air's fluctuation; the fluid torque's count "
        "is in `torqueOutside`, `torqueEvaluations`.)")


def force_ranges(r):
    """Saffman-Mei and the drag correlation against their ranges"""
    rows = []
    for v in r.variants:
        x = r.ratios[v]
        if "outsideSaffmanMei" not in x:
            continue

        def pc(key, fmt="%.1f %%"):
            return fmt % (100*float(x[key]))
        rows.append(["`%s`" % v,
                     " / ".join("%.3g" % float(x["betaMei_q%02d" % p])
                                for p in (1, 10, 50, 90, 99)),
                     pc("outsideSaffmanMei"), pc("MeiRepAbove"), pc("MeiBetaBelow"),
                     pc("MeiBetaAbove"), pc("RepAboveDragSwitch", "%.2f %%")])
    return table(["variant", "shear parameter beta = Re_w/(2 Re_p): 1 / 10 / 50 / 90 / 99 % "
                  "quantiles", "outside Mei's range (0.1 <= Re_p <= 100, 0.005 <= beta <= 0.4)",
                  "of which Re_p > 100", "beta < 0.005", "beta > 0.4",
                  "sphereDrag: Re_p > 1000"], rows)


def wall_statistics(r):
    rows = []
    for v in r.variants:
        if not math.isfinite(r.s(v, "knImpulse")):
            continue
        rows.append(["`%s`" % v] + [
            "%s / %s" % (num(r.s(v, "kn_lowerWall")), num(r.s(v, "kn_upperWall"))),
            "%s / %s" % (pm(r.s(v, "knImpulse_lowerWall"), r.s(v, "knImpulse_lowerWall_se")),
                         pm(r.s(v, "knImpulse_upperWall"), r.s(v, "knImpulse_upperWall_se"))),
            "%s / %s" % (num(r.s(v, "kt_lowerWall")), num(r.s(v, "kt_upperWall"))),
            "%s / %s" % (pm(r.s(v, "ktImpulse_lowerWall"), r.s(v, "ktImpulse_lowerWall_se")),
                         pm(r.s(v, "ktImpulse_upperWall"), r.s(v, "ktImpulse_upperWall_se")))])
    return table(["variant", "mean k_n per hit, lower / upper",
                  "impulse-weighted k_n = sum v''_n / sum abs(v'_n), lower / upper",
                  "mean k_t per hit, lower / upper",
                  "impulse-weighted k_t = sum v''_t / sum abs(v'_t), lower / upper"], rows) + (
        "\n\n(The rough-wall model's statistics file, hits in the sampling window; "
        "impulse-weighted ratios +- the jackknife over 10 time blocks. The mean of "
        "the ratio per hit has no standard error: it is dominated by a few grazing "
        "hits and does not converge like a mean. `-`: no hits on that wall.)")


def wall_angles(r):
    """k_n, k_t per bin of the incidence angle of the default variant
    against the model's bin averages, and the angle distributions."""
    rows = []
    for a in r.angles[DEFAULT]:
        n = lambda k: number(a, k)
        rows.append(["%g-%g" % (n("angleMin"), n("angleMax")),
                     pm(n("hitFraction"), n("hitFraction_se"), "%.2f", 100),
                     pm(n("reboundFraction"), n("reboundFraction_se"), "%.2f", 100),
                     pm(n("kn"), n("kn_se")), num(n("model_bin_kn")),
                     num(z(n("kn"), n("kn_se"), n("model_bin_kn"), 0), "%.1f"),
                     pm(n("kt"), n("kt_se")), num(n("model_bin_kt")),
                     num(z(n("kt"), n("kt_se"), n("model_bin_kt"), 0), "%.1f")])
    return table(["incidence angle [deg]", "hits in the bin [%]",
                  "rebounds at these angles [%]", "k_n run", "k_n model",
                  "difference / s.e.", "k_t run", "k_t model", "difference / s.e."],
                 rows) + (
        "\n\n(`%s`, both walls, sampling window; results/angles.csv. Run: the "
        "impulse-weighted ratios of the bin, +- the jackknife over 10 time blocks. "
        "Model: roughWallStats' Monte Carlo of the full operator (new facets until "
        "the bead leaves) at Delta = %s deg, e = %s, mu0 = %s, muD = %s, with "
        "sideways tilt, no incident spin, 20000 samples per 0.25 deg, averaged "
        "over the bin with the weight sin(alpha).)"
        % (DEFAULT, r.summary[DEFAULT]["roughnessAngle"], r.summary[DEFAULT]["e"],
           r.summary[DEFAULT]["mu0"], r.summary[DEFAULT]["muD"]))


def spin_up(r):
    """First against second half of the sampling window, every variant"""
    rows, worst, worst_rough = [], 0.0, 0.0
    for v in r.variants:
        for key, text, fmt, scale in (
                ("upperFraction", "parcels in the upper half [%]", "%.2f", 100),
                ("UyRms", "rms wall-normal velocity [m/s]", "%.4f", 1),
                ("meanUx", "mean streamwise velocity [m/s]", "%.3f", 1)):
            a, b = r.s(v, key + "Early"), r.s(v, key + "Late")
            sa, sb = r.s(v, key + "Early_se"), r.s(v, key + "Late_se")
            zz = z(a, sa, b, sb)
            worst = max(worst, zz)
            if v != SMOOTH:
                worst_rough = max(worst_rough, zz)
            rows.append(["`%s`" % v, text, pm(a, sa, fmt, scale), pm(b, sb, fmt, scale),
                         "%.1f" % zz])
    v0 = r.variants[0]
    t0, t1 = r.s(v0, "sampleStart"), r.s(v0, "sampleEnd")
    return ("Sampling window %g-%g s, halves %g-%g s and %g-%g s:\n\n"
            % (t0, t1, t0, 0.5*(t0 + t1), 0.5*(t0 + t1), t1)
            + table(["variant", "statistic", "first half", "second half",
                     "difference / combined s.e."], rows)
            + "\n\nThe largest difference is %.1f combined standard errors over all "
            "variants, %.1f without `%s`." % (worst, worst_rough, SMOOTH))


def time_step(r):
    if not r.timestep:
        return "(no time-step study in results/timeStep/)"
    keys = STATS + (("knImpulse", "impulse-weighted k_n", "%.3f", 1),
                    ("ktImpulse", "impulse-weighted k_t", "%.3f", 1))
    rows, worst = [], (0.0, "")
    for name, (summary, info) in sorted(r.timestep.items()):
        for v in summary:
            if v not in r.summary:
                continue
            for key, text, fmt, scale in keys:
                a, sa = r.s(v, key), r.s(v, key + "_se")
                b, sb = number(summary[v], key), number(summary[v], key + "_se")
                zz = z(a, sa, b, sb)
                dt = "%g ms" % (1e3*number(summary[v], "deltaT"))
                if zz > worst[0]:
                    worst = (zz, "`%s`, %s, %s" % (v, dt, text))
                rows.append(["`%s`" % v, dt, text, pm(a, sa, fmt, scale),
                             pm(b, sb, fmt, scale), "%.1f" % zz])
    cmds = "; ".join("`%s` (`results/timeStep/%s/runInfo`)"
                     % (relative_command(info["command"]), name)
                     for name, (_, info) in sorted(r.timestep.items()))
    return (table(["variant", "time step", "statistic", "at 1 ms (results/)",
                   "at this time step", "difference / combined s.e."], rows)
            + "\n\nLargest difference: %.1f combined standard errors (%s), over %d "
            "comparisons; %s. Runs: %s." % (
                worst[0], worst[1], len(rows),
                "no time-step error is resolved above the standard errors"
                if worst[0] < 3 else "a time-step error is resolved where the "
                "difference exceeds 3 standard errors", cmds))


def runtimes(r):
    rows = []
    for v in r.variants:
        rows.append(["`%s`" % v, "%.0f" % r.s(v, "wallClock"),
                     "%.0f" % r.s(v, "cpuTime")])
    cpu = sum(r.s(v, "cpuTime") for v in r.variants)
    return (table(["variant", "wall clock [s]", "CPU (ExecutionTime) [s]"], rows)
            + "\n\nWhole `./Allrun`: %s s wall clock on the machine of the "
            "results, shared with other jobs (%s, %s at a time); the tracking "
            "runs took %.0f s of CPU time in all (%.0f s on each of two idle "
            "cores), the carrier flow %.0f s."
            % (r.info["totalSeconds"], r.info["machine"], r.info["jobs"], cpu,
               cpu/2, float(r.info["carrierSeconds"])))


def smoke_test(r):
    c = checkResults
    text = ("Criteria (`scripts/checkResults.py`, its docstring names the faults "
            "each catches): the set-up the run reports for `%s` is %s; its rms "
            "spanwise velocity is above %g standard errors (0 in 2-D); %s within "
            "%g combined standard errors of the committed `results/`."
            % (c.VARIANT, ", ".join("%s %s" % kv for kv in c.SETUP.items()),
               c.MARGIN_SE, ", ".join("`%s`" % k for k in c.BAND), c.BAND_SE)
            + " The loading variant `%s` reports %s, and its %s are within %g "
            "combined standard errors of the committed ones."
            % (c.LOADING_VARIANT,
               ", ".join("%s %s" % kv for kv in c.LOADING_SETUP.items()),
               ", ".join("`%s`" % k for k in c.LOADING_BAND), c.BAND_SE))
    out = [text]
    for version, rows in sorted(r.smoke.items(), reverse=True):
        # the run's commit stays in the CSV (its "run" column)
        run = re.sub(r",? ?commit [0-9a-f]+( \(with local changes\))?", "",
                     rows[0]["run"])
        out.append("OpenFOAM-%s (`results/smokeTest-openfoam%s.csv`, which "
                   "records the commit; %s):\n\n"
                   % (version, version, run)
                   + table(["check", "measured", "required", "margin (bands: "
                            "abs(difference) / band, below 1)"],
                           [[x["check"], x["value"], x["limit"], x["margin"]]
                            for x in rows]))
    return "\n\n".join(out)


G = 9.81
RHO_GLASS = 2500.0
RHO_AIR = 1.2
SLAB_WIDTH = 0.01      # [m], the 3-D slab (Allrun)


def wall(r):
    """The default wall: Delta of the calibrated surface at the beads' size"""
    x = r.summary[DEFAULT]
    rough = dict(kv.split("=") for kv in x["roughness"].split(","))
    return ("The default variant `%s` runs on the surface Rq = %g um, RSm = %g um: "
            "for its %g um beads the run's Delta (roughWallStats at that diameter, "
            "as Allrun records it in `summary.csv`) is **%.2f deg**, against the "
            "former default's constant 5 deg (`rough5`)." % (
                DEFAULT, 1e6*float(rough["Rq"]), 1e6*float(rough["RSm"]),
                1e6*r.s(DEFAULT, "diameter"), r.s(DEFAULT, "roughnessAngle")))


def impact_rates(r):
    """The default variant's impact rate by hand against the run"""
    v = DEFAULT
    H = float(r.carrier["height"])
    vrms, u = r.s(v, "UyRms"), r.s(v, "meanUx")
    period = 2*H/vrms
    return ("**Impact rates**: a bead that crosses the channel back and forth with "
            "a wall-normal speed v hits each wall once per 2H/v; for `%s` (rms v = "
            "%.2f m/s, mean u = %.1f m/s, results table) that is every %.0f ms or "
            "%.2f m, about %.1f impacts per metre on each wall. The run gives %.2f "
            "on the floor and %.2f on the ceiling: the same order, lower because not "
            "every bead crosses the whole channel, and more on the floor because "
            "gravity brings beads back to it. With less roughness the ceiling is "
            "reached less often (`rough1`: %.2f against %.2f), as it should be when "
            "the beads' wall-normal speed approaches the %.2f m/s it takes to get "
            "there." % (v, vrms, u, 1e3*period, u*period, 1/(u*period),
                        r.s(v, "impactFrequency_lowerWall"),
                        r.s(v, "impactFrequency_upperWall"),
                        r.s("rough1", "impactFrequency_lowerWall"),
                        r.s("rough1", "impactFrequency_upperWall"),
                        math.sqrt(2*G*H)))


def crossings(r):
    """How often a bead of the default variant crosses the cyclic faces"""
    w = r.s(DEFAULT, "UzRms")
    dt = r.s(DEFAULT, "deltaT")
    return ("At the beads' rms spanwise velocity (`%s`: %.2f m/s) a bead crosses "
            "the %g mm slab, and so the cyclic faces, about every %.0f ms, once per "
            "%.0f time steps." % (DEFAULT, w, 1e3*SLAB_WIDTH, 1e3*SLAB_WIDTH/w,
                                  SLAB_WIDTH/w/dt))


def loading(r):
    """Bead-bead collisions (kinetic theory) against wall impacts"""
    v = DEFAULT
    d = r.s(v, "diameter")
    T = (r.s(v, "UxRms")**2 + r.s(v, "UyRms")**2 + r.s(v, "UzRms")**2)/3
    u = r.s(v, "meanUx")
    ubulk = float(r.carrier["Ubulk"])
    fwall = r.s(v, "impactFrequency")*u          # wall impacts per bead per second
    per_n = 4*d*d*math.sqrt(math.pi*T)           # bead-bead collisions per bead per second, / n
    mp = RHO_GLASS*math.pi/6*d**3
    # mass loading eta = (n m_p u)/(rho_air U_bulk): collisions equal wall impacts at
    n_equal = fwall/per_n
    eta_equal = n_equal*mp*u/(RHO_AIR*ubulk)
    return ("For `%s`: granular temperature T = (u'^2 + v'^2 + w'^2)/3 = %.2f m2/s2 "
            "from its rms velocities; a bead collides with others f = 4 n d^2 "
            "sqrt(pi T) = %.3g n times per second (n beads per m3, kinetic theory of "
            "a dilute gas of equal spheres, taken as isotropic), and hits a wall %.2f "
            "impacts per metre x "
            "%.1f m/s = %.1f times per second. The two rates are equal at n = %.3g "
            "per m3, a mass loading eta = n m_p u_p/(rho_air U_bulk) = **%.2f** "
            "(m_p = %.3g kg, u_p = %.1f m/s, U_bulk = %.2f m/s). At a loading eta the "
            "bead-bead rate is eta/%.2f of the wall rate: %.0f %% at eta = 0.1, "
            "%.0f %% at eta = 0.01." % (
                v, T, per_n, r.s(v, "impactFrequency"), u, fwall, n_equal, eta_equal,
                mp, u, ubulk, eta_equal, 100*0.1/eta_equal, 100*0.01/eta_equal))


def one_way_reach(r):
    """Which statistics of the one-way set-up (loading0) hold at each
    loading with coupling and collisions together (beyond 3 combined
    standard errors: moved)"""
    if "loading0" not in r.summary:
        return ""
    out = []
    for v, loading in (("loading0.3.collisions", "0.3"),
                       ("loading1.collisions", "1")):
        if v not in r.summary:
            continue
        held, moved = [], []
        for key, name, fmt, scale in STATS:
            a, sa = r.s("loading0", key), r.s("loading0", key + "_se")
            b, sb = r.s(v, key), r.s(v, key + "_se")
            zz = z(a, sa, b, sb)
            if zz > 3:
                moved.append("%s by %+.0f %%" % (name, 100*(b - a)/a))
            else:
                held.append(name)
        out.append("at a loading of %s (`%s` against `loading0`) %s; %s" % (
            loading, v, "moved: " + ", ".join(moved) if moved
            else "nothing moved", "held: " + ", ".join(held) if held
            else "nothing held"))
    return ("\n\nWith coupling and collisions together, beyond 3 combined "
            "standard errors of the one-way set-up, " + "; ".join(out) + ".")


def loading_series(r):
    """The loading variants: loading reached, collisions between beads
    against wall impacts, the air's pressure gradient"""
    vs = [v for v in LOADING if v in r.summary]
    if not vs:
        return "(no loading variant in the results)"
    rows = []
    for v in vs:
        def s(k):
            return r.s(v, k)
        rows.append([
            "`%s`" % v,
            pm(s("massLoadingReached"), s("massLoadingReached_se"), "%.3f"),
            num(s("beadVolumeFraction"), "%.2g"),
            pm(s("upperFraction"), s("upperFraction_se"), "%.1f", 100),
            pm(s("UyRms"), s("UyRms_se"), "%.2f"),
            pm(s("meanUxOverBulk"), s("meanUxOverBulk_se"), "%.3f"),
            pm(s("wallImpactRate"), s("wallImpactRate_se"), "%.1f"),
            pm(s("interParticleFrequency"), s("interParticleFrequency_se"), "%.1f")
            if math.isfinite(s("interParticleFrequency")) else "(off)",
            num(s("collisionsPerWallImpact"), "%.2f")
            if math.isfinite(s("interParticleFrequency")) else "-",
            pm(s("pressureGradient"), s("pressureGradient_se"), "%.1f"),
            num(s("airCentreline"), "%.2f")])
    head = ["variant", "mass loading reached", "bead volume fraction",
            "upper half [%]", "rms v [m/s]", "mean u / U_bulk",
            "wall impacts per bead per s", "bead-bead collisions per bead per s",
            "collisions per wall impact", "air pressure gradient [m/s2]",
            "air centreline velocity at the end [m/s]"]
    ref = r.s("loading0", "pressureGradient") if "loading0" in r.summary else math.nan
    return table(head, rows) + one_way_reach(r) + (
        "\n\n(Means over the sampling window +- one standard error, all from 10 "
        "time blocks: the loading reached is the beads' mass flux over the air's, "
        "n m_p <u_p>/(rho U_bulk), `loading0` one-way and so 0 for the air; "
        "bead-bead collisions are the Sommerfeld model's count in the log; the "
        "pressure gradient is the meanVelocityForce's, which holds the air's bulk "
        "velocity at 20 m/s: %.0f m/s2 without load on this mesh, against %.1f of "
        "the wall-resolved carrier.)" % (ref, float(r.carrier["pressureGradient"])))


def lift_budget(r):
    """How much of the wall-normal momentum budget the rotational lift carries"""
    a, sa = r.s(DEFAULT, "knImpulse"), r.s(DEFAULT, "knImpulse_se")
    b, sb = r.s("steel.noLift", "knImpulse"), r.s("steel.noLift", "knImpulse_se")
    share = 1 - (a - 1)/(b - 1)
    share_se = math.hypot(sa/(b - 1), (a - 1)*sb/(b - 1)**2)
    return ("Impulse-weighted k_n: %.3f +- %.3f with the rotational lift (`%s`), "
            "%.3f +- %.3f without it (`steel.noLift`). The walls' net upward "
            "momentum per unit of incident wall-normal momentum, k_n - 1, is %.3f "
            "with the lift and %.3f without: the lift carries **%.0f +- %.1f %%** of "
            "what the walls must supply without it." % (
                a, sa, DEFAULT, b, sb, a - 1, b - 1, 100*share, 100*share_se))


BLOCKS = {
    "wall": wall,
    "impactRates": impact_rates,
    "crossings": crossings,
    "loading": loading,
    "liftBudget": lift_budget,
    "loadingSeries": loading_series,
    "sensitivityReading": sensitivity_reading,
    "provenance": provenance,
    "carrier": carrier,
    "results": results_table,
    "sensitivity": sensitivity,
    "trends": trends,
    "spinRatios": spin_ratios,
    "forceRanges": force_ranges,
    "wallStatistics": wall_statistics,
    "wallAngles": wall_angles,
    "spinUp": spin_up,
    "timeStep": time_step,
    "runtimes": runtimes,
    "smokeTest": smoke_test,
}


def render(text, r):
    for key, fun in BLOCKS.items():
        pattern = re.compile(re.escape(BEGIN % key) + r".*?" + re.escape(END % key),
                             re.S)
        if not pattern.search(text):
            raise SystemExit("writeReadme: README has no block %s" % key)
        body = fun(r)
        text = pattern.sub(lambda m: "%s\n%s\n%s" % (BEGIN % key, body, END % key),
                           text)
    return text


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--check", action="store_true")
    p.add_argument("--results", default=os.path.join(TUTORIAL, "results"))
    p.add_argument("--readme", default=os.path.join(TUTORIAL, "README.md"))
    args = p.parse_args()
    with open(args.readme) as f:
        old = f.read()
    new = render(old, Results(args.results))
    if args.check:
        if new != old:
            sys.stdout.writelines(difflib.unified_diff(
                old.splitlines(True), new.splitlines(True), "README.md",
                "README.md from results/"))
            print("writeReadme: README.md differs from the committed results: "
                  "run scripts/writeReadme.py")
            sys.exit(1)
        print("writeReadme: README.md matches %s" % args.results)
        return
    if new != old:
        with open(args.readme, "w") as f:
            f.write(new)
    print("writeReadme: %s %s" % (args.readme, "updated" if new != old
                                  else "unchanged"))


if __name__ == "__main__":
    main()
