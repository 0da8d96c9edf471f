#!/usr/bin/python3
"""Write the numbers of README.md from the committed results (results/).

Every number of the tutorial's README that comes from a run sits between
markers

    <!-- begin generated: NAME -->
    ...
    <!-- end generated: NAME -->

and is written by this script from results/summary.csv, profiles.csv,
carrier.csv, runInfo and smokeTest.csv; nothing between the markers is
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
        self.summary = {r["variant"]: r for r in
                        read_rows(os.path.join(directory, "summary.csv"))}
        self.variants = [r["variant"] for r in
                         read_rows(os.path.join(directory, "summary.csv"))]
        self.profiles = {}
        for r in read_rows(os.path.join(directory, "profiles.csv")):
            self.profiles.setdefault(r["variant"], []).append(r)
        self.carrier = read_rows(os.path.join(directory, "carrier.csv"))[0]
        self.info = read_info(os.path.join(directory, "runInfo"))
        path = os.path.join(directory, "smokeTest.csv")
        self.smoke = read_rows(path) if os.path.exists(path) else None

    def s(self, variant, key):
        return number(self.summary[variant], key)

    def spin(self, variant):
        return self.summary[variant].get("spinCoupling") == "yes"

    def model(self, spin=True):
        """The rough-wall model's variants (with or without the spin
        forces), by Delta"""
        v = [x for x in self.variants
             if self.summary[x]["wallModel"] == "roughWallInteraction"
             and self.spin(x) == spin]
        return sorted(v, key=lambda x: self.s(x, "roughnessAngle"))

    def rough(self):
        """The rough-wall model's variants with Delta > 0 and the spin
        forces, by Delta."""
        return [x for x in self.model() if self.s(x, "roughnessAngle") > 0]

    def smooth(self):
        return [x for x in self.model() if self.s(x, "roughnessAngle") == 0]


# ----------------------------------------------------------------------------
# Formatting

def pm(value, se, digits):
    return "%.*f +- %.*f" % (digits, value, digits, se)


def pct(value, se=None, digits=1):
    if se is None:
        return "%.*f %%" % (digits, 100*value)
    return "%.*f +- %.*f %%" % (digits, 100*value, digits, 100*se)


def name(r, v):
    model = r.summary[v]["wallModel"]
    if model == "standardWallInteraction":
        return "`%s`: standardWallInteraction, e = 0.8, mu = 0" % v
    delta = r.s(v, "roughnessAngle")
    extra = " (smooth)" if delta == 0 else ""
    if not r.spin(v):
        extra += ", no spin forces"
    return "`%s`: rough-wall model, Delta = %g deg%s" % (v, delta, extra)


def table(head, rows):
    lines = ["| " + " | ".join(head) + " |",
             "|" + "---|"*len(head)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


# ----------------------------------------------------------------------------
# The generated blocks

def relative_command(command):
    """The command of runInfo, run in this folder"""
    i = command.find("Allrun")
    return "./" + command[i:] if i >= 0 else command


def provenance(r):
    i = r.info
    v0 = r.variants[0]
    return ("Made by `%s` (in this folder) at commit %s on %s, OpenFOAM %s, %s, %s variants at a "
            "time; %d parcels of %g um, sampled every 0.05 s from %g s to %g s "
            "(%d snapshots, %d samples per variant), time step %g ms. Files: "
            "`results/summary.csv`, `results/profiles.csv`, "
            "`results/carrier.csv`, `results/runInfo`." % (
                relative_command(i["command"]),
                i["commit"], i["date"], i["openfoam"], i["machine"], i["jobs"],
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


def results_table(r):
    head = ["variant", "parcels in upper half", "rms wall-normal parcel "
            "velocity [m/s]", "mean height y/H", "mean streamwise parcel "
            "velocity [m/s]", "mean spin omega d/2 [m/s]", "wall impacts per "
            "parcel per metre, lower / upper", "mean k_n, lower / upper",
            "mean k_t, lower / upper"]
    rows = []
    for v in r.variants:
        def s(k):
            return r.s(v, k)

        def walls(key, fmt):
            a, b = s(key + "_lowerWall"), s(key + "_upperWall")
            if math.isnan(a) and math.isnan(b):
                return "(no statistics)"
            return " / ".join("-" if math.isnan(x) else fmt % x for x in (a, b))
        rows.append([
            name(r, v), pct(s("upperFraction"), s("upperFraction_se"), 2),
            pm(s("UyRms"), s("UyRms_se"), 4), pm(s("meanHeight"),
                                                 s("meanHeight_se"), 4),
            "%.2f" % s("meanUx"), "%.2f" % s("meanSpinSpeed"),
            walls("impactsPerParcelPerMetre", "%.3f"), walls("kn", "%.2f"),
            walls("kt", "%.3f")])
    return table(head, rows) + (
        "\n\n(+- one standard error, jackknife over 20 groups of whole "
        "parcels. A uniform profile puts 50 % of the parcels in the upper "
        "half. Impacts: patchCollisionDensity, wall-normal impact speed above "
        "5 cm/s. k_n, k_t: the rough-wall model's statistics of the hits in "
        "the sampling window.)")


def observations(r):
    out = []
    flat = [v for v in r.variants if r.s(v, "upperFraction") < 0.01]
    if flat:
        out.append(
            "- %s: %s of the parcels in the upper half, rms wall-normal "
            "velocity %s m/s: the beads move along the floor at %s m/s (the "
            "air at one radius from the wall: %.2f m/s). Drag, the lift "
            "forces and the random walk do not lift a bead off a smooth "
            "floor once it has settled." % (
                " and ".join("`%s`" % v for v in flat),
                " and ".join(pct(r.s(v, "upperFraction"), digits=2) for v in flat),
                " and ".join("%.4f" % r.s(v, "UyRms") for v in flat),
                " and ".join("%.2f" % r.s(v, "meanUx") for v in flat),
                float(r.carrier["Uradius"])))
    rough = r.rough()
    if rough:
        prof = []
        for v in rough:
            c = [float(p["concentration"]) for p in r.profiles[v]]
            prof.append("%.2f to %.2f times the mean for Delta = %g deg"
                        % (min(c), max(c), r.s(v, "roughnessAngle")))
        out.append(
            "- Rough walls keep the beads in the whole channel: %s of the "
            "parcels in the upper half (Delta = %s deg); the concentration "
            "ranges from %s." % (
                ", ".join(pct(r.s(v, "upperFraction"), digits=1) for v in rough),
                ", ".join("%g" % r.s(v, "roughnessAngle") for v in rough),
                "; ".join(prof)))
        out.append(
            "- The rms wall-normal parcel velocity grows with Delta (%s m/s), "
            "paid for by the mean streamwise velocity (%s m/s)." % (
                ", ".join("%.3f" % r.s(v, "UyRms") for v in rough),
                ", ".join("%.2f" % r.s(v, "meanUx") for v in rough)))
        gammas = ", ".join("%.2f" % r.s(v, "gammaDeg_lowerWall") for v in rough)
        out.append(
            "- Mean k_n per hit is above 1 (%s on the lower wall): a grazing "
            "hit can leave with a larger wall-normal velocity than it came "
            "with, and the mean of the ratio is dominated by such hits. The "
            "mean facet tilt of the hits on the lower wall is positive (%s "
            "deg): the shadow effect." % (
                ", ".join("%.2f" % r.s(v, "kn_lowerWall") for v in rough), gammas))
    suspended = [v for v in r.variants if v not in flat]

    def worst(vs, key):
        z = [0.0]
        for v in vs:
            d = r.s(v, key + "Late") - r.s(v, key + "Early")
            se = math.hypot(r.s(v, key + "Late_se"), r.s(v, key + "Early_se"))
            z.append(abs(d)/se if se > 0 else 0.0)
        return max(z)
    if suspended:
        out.append(
            "- Steady state: for %s the difference between the second and "
            "the first half of the sampling window is at most %.1f standard "
            "errors for the upper-half fraction and %.1f for the rms "
            "wall-normal velocity (the spin-up figure shows the approach)."
            % (", ".join("`%s`" % v for v in suspended),
               worst(suspended, "upperFraction"), worst(suspended, "UyRms")))
    if flat:
        out.append(
            "- The beads on the smooth floors (%s) have settled: between the "
            "two halves of the sampling window their mean velocity changed "
            "by %s m/s, at most %.1f standard errors." % (
                ", ".join("`%s`" % v for v in flat),
                " and ".join("%.4f" % (r.s(v, "meanUxLate") - r.s(v, "meanUxEarly"))
                             for v in flat),
                max(worst(flat, "meanUx"), worst(flat, "UyRms"))))
    return "\n".join(out)


def trends(r):
    rough = r.rough()
    seq = r.smooth() + rough
    if not seq:
        return ""

    def series(key, fmt, scale=1):
        return " -> ".join(fmt % (scale*r.s(v, key)) for v in seq)
    label = "Delta = " + " -> ".join("%g" % r.s(v, "roughnessAngle")
                                     for v in seq) + " deg"
    def agree(key, rising):
        def ordered(vs):
            x = [r.s(v, key) for v in vs]
            return all((b > a) if rising else (b < a) for a, b in zip(x, x[1:]))
        if ordered(seq):
            return "yes"
        if ordered(rough):
            return ("between the rough walls; the smooth-wall beads slide on "
                    "the floor, not conveyed in suspension")
        return "no"
    rows = [
        ["gravitational settling is counteracted by roughness: the "
         "concentration profile becomes more uniform",
         "parcels in the upper half: " + series("upperFraction", "%.1f %%", 100),
         agree("upperFraction", True)],
        ["the wall-normal particle velocity fluctuation grows with roughness",
         "rms wall-normal parcel velocity [m/s]: " + series("UyRms", "%.3f"),
         agree("UyRms", True)],
        ["the mean particle velocity falls with roughness (momentum lost in "
         "more frequent, more oblique wall collisions)",
         "mean streamwise parcel velocity [m/s]: " + series("meanUx", "%.2f"),
         agree("meanUx", False)],
        ["(no trend cited from the experiments) the beads' spin",
         "mean spin surface speed omega d/2 [m/s]: "
         + series("meanSpinSpeed", "%.2f"), "-"],
        ["the wall collision frequency grows with roughness",
         "lower-wall impacts per parcel per metre: "
         + series("impactsPerParcelPerMetre_lowerWall", "%.3f"),
         agree("impactsPerParcelPerMetre_lowerWall", True)],
    ]
    return ("Tutorial: " + label + ".\n\n"
            + table(["trend (Kussin & Sommerfeld 2002; see the text for what "
                     "was checked)", "this tutorial", "agrees?"], rows))


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


def spin_up(r):
    """First against second half of the sampling window, every variant"""
    rows, worst = [], 0.0
    for v in r.variants:
        for key, text, fmt, scale in (
                ("upperFraction", "parcels in the upper half", "%.2f %%", 100),
                ("UyRms", "rms wall-normal velocity [m/s]", "%.4f", 1),
                ("meanUx", "mean streamwise velocity [m/s]", "%.3f", 1)):
            a, b = r.s(v, key + "Early"), r.s(v, key + "Late")
            se = math.hypot(r.s(v, key + "Early_se"), r.s(v, key + "Late_se"))
            z = abs(b - a)/se if se > 0 else (0.0 if a == b else math.inf)
            worst = max(worst, z)
            rows.append(["`%s`" % v, text,
                         (fmt + " +- " + fmt) % (scale*a, scale*r.s(v, key + "Early_se")),
                         (fmt + " +- " + fmt) % (scale*b, scale*r.s(v, key + "Late_se")),
                         "%.1f" % z])
    v0 = r.variants[0]
    t0, t1 = r.s(v0, "sampleStart"), r.s(v0, "sampleEnd")
    return ("Sampling window %g-%g s, halves %g-%g s and %g-%g s:\n\n"
            % (t0, t1, t0, 0.5*(t0 + t1), 0.5*(t0 + t1), t1)
            + table(["variant", "statistic", "first half", "second half",
                     "difference / combined s.e."], rows)
            + "\n\nThe largest difference is %.1f combined standard errors%s."
            % (worst, " (agreement: at most %g)" % SPIN_UP_SE))


def smoke_test(r):
    c = checkResults
    text = ("Criteria (`scripts/checkResults.py`), each named after the "
            "faults it catches: the variants ordered by %s, each "
            "difference larger than %g combined standard errors (no "
            "roughness, a roughness level lost; the fraction in the upper "
            "half saturates at 50 %%, uniform, in both rough variants, so it "
            "orders only the smooth one below them); on the smooth floor the "
            "beads slower than the air at their centre, u(r) + (h - r) "
            "u_tau^2/nu (moving walls); in `%s`, whose spin changes at the "
            "walls only, a negative mean spin by more than %g standard errors "
            "(spin not changed at the walls, a wrong sign of the spin "
            "update); %s of each variant within %g combined standard errors "
            "of the committed result `results/` (anything that moves a "
            "statistic)."
            % ("; ".join("`%s` (%s)" % (k, " < ".join(v))
                         for k, v in c.ORDERED.items()), c.MARGIN_SE,
               c.WALL_SPIN, c.MARGIN_SE, ", ".join("`%s`" % k for k in c.BAND),
               c.BAND_SE))
    if not r.smoke:
        return text
    rows = [[x["check"], x["value"], x["limit"], x["margin"]] for x in r.smoke]
    return (text + "\n\nThe last recorded smoke test (`results/smokeTest.csv`, "
            "%s):\n\n" % r.smoke[0]["run"]
            + table(["check", "measured", "required", "measured / required "
                     "(orderings: above 1; bands: below 1)"], rows))


def spin_effect(r):
    """Each variant without the spin forces against the same variant with
    them"""
    rows = []
    for v in r.model(spin=False):
        ref = v.split(".")[0]
        if ref not in r.summary:
            continue
        for key, text, fmt, scale in (
                ("upperFraction", "parcels in the upper half", "%.2f %%", 100),
                ("UyRms", "rms wall-normal parcel velocity [m/s]", "%.4f", 1),
                ("meanUx", "mean streamwise parcel velocity [m/s]", "%.2f", 1),
                ("meanSpinSpeed", "mean spin omega d/2 [m/s]", "%.2f", 1),
                ("impactsPerParcelPerMetre_lowerWall",
                 "lower-wall impacts per parcel per metre", "%.3f", 1)):
            a, b = r.s(ref, key), r.s(v, key)
            se_a, se_b = r.s(ref, key + "_se"), r.s(v, key + "_se")
            z = abs(a - b)/math.hypot(se_a, se_b) \
                if math.isfinite(se_a) and math.isfinite(se_b) and (se_a or se_b) \
                else math.nan
            rows.append(["`%s` / `%s`" % (ref, v), text, fmt % (scale*a),
                         fmt % (scale*b), "%.0f" % z if math.isfinite(z) else "-"])
    if not rows:
        return "(no variant without the spin forces in this run)"
    return table(["variants", "statistic", "with the spin forces",
                  "without", "difference / combined s.e."], rows)


#: Two halves of the sampling window agree: within this many combined
#: standard errors
SPIN_UP_SE = 3.0

def platforms(r):
    """The same run on the other Foundation release (results/openfoam13/)
    against the committed results: the largest difference of each
    statistic that has a standard error, in combined standard errors"""
    other_dir = os.path.join(r.dir, "openfoam13")
    other = {x["variant"]: x for x in
             read_rows(os.path.join(other_dir, "summary.csv"))}
    info = read_info(os.path.join(other_dir, "runInfo"))
    keys = [k for k in r.summary[r.variants[0]]
            if k + "_se" in r.summary[r.variants[0]]]
    rows = []
    for v in r.variants:
        if v not in other:
            continue
        z_max, key_max = 0.0, ""
        for k in keys:
            a, b = r.s(v, k), number(other[v], k)
            se = math.hypot(r.s(v, k + "_se"), number(other[v], k + "_se"))
            if not all(math.isfinite(x) for x in (a, b, se)):
                continue
            z = abs(a - b)/se if se > 0 else (0.0 if a == b else math.inf)
            if z > z_max:
                z_max, key_max = z, k
        rows.append([name(r, v), "%.2f" % z_max, "`%s`" % key_max if key_max
                     else "-"])
    return ("OpenFOAM-%s at commit %s (`%s`), against these results of "
            "OpenFOAM-%s: per variant, the largest difference of the %d "
            "statistics with a standard error, in combined standard errors:\n\n"
            % (info["openfoam"].split()[0], info["commit"], info["command"],
               r.info["openfoam"].split()[0], len(keys))
            + table(["variant", "largest difference / combined s.e.",
                     "statistic"], rows))


BLOCKS = {
    "provenance": provenance,
    "spinUp": spin_up,
    "carrier": carrier,
    "results": results_table,
    "observations": observations,
    "trends": trends,
    "spinEffect": spin_effect,
    "runtimes": runtimes,
    "smokeTest": smoke_test,
    "platforms": platforms,
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
