#!/usr/bin/python3
"""Assertions of the horizontalChannel smoke test (Alltest).

Usage: checkResults.py [--record FILE] SHORT_RESULTS_DIR [REFERENCE_RESULTS_DIR]

SHORT_RESULTS_DIR is the result of ./Allrun -test (the 3-D default variant
steel and the loading variant loading1.collisions, with a shorter sampling
window than the default run, the same spin-up); REFERENCE_RESULTS_DIR the
committed result of the default run (results/).

Each check names the faults it is there to catch:

1. Sanity: profiles.csv, summary.csv, spinRatios.csv and the figures exist;
   N_BINS height bins; every number written is finite; the concentration is
   normalised (mean over the bins = 1).
   Faults: a crash, NaN, lost parcels in a bin, a broken post-processing.
2. The set-up is the default one, as the run itself reports it: geometry 3D
   (caseInfo, from the variant), Delta from the calibrated surface (its Rq
   and RSm), lateral facet tilt on, the Saffman-Mei lift and the turbulent
   dispersion on, the rotational lift with Loth's coefficient and the fluid
   torque of Dennis, Singh & Ingham as the solver printed them at start-up;
   and the spanwise motion is there: rms spanwise velocity above MARGIN_SE
   standard errors (exactly 0 in 2-D).
   Faults: the 2-D set-up, a constant Delta or another surface, the lift or
   the torque switched off or another coefficient, lateral tilt lost, the
   shear lift or the dispersion switched off.
3. Agreement with the committed result: every statistic of BAND within
   BAND_SE combined standard errors of the committed steel (the short run
   has the default run's spin-up, so no allowance for drift is needed;
   README.md, "Spin-up").
   Faults: anything that moves a statistic of the tutorial (e, mu, Delta,
   the sampler, the spin models, the carrier flow, 2-D scattering) by more
   than BAND_SE s.e.
4. The loading variant LOADING_VARIANT: its set-up as the run reports it
   (LOADING_SETUP: two-way coupled, collisions between beads by the
   Sommerfeld model, nominal loading 1) and every statistic of
   LOADING_BAND within BAND_SE combined standard errors of the committed
   one, the collisions between beads and the air's pressure gradient among
   them.
   Faults: coupling or the collision model off or without effect, a wrong
   nParticle (the loading), a broken loading set-up (mesh, wall functions,
   fvModels), a change of the collision model's frequency or of the
   momentum the beads give the air.
"""
import csv
import math
import os
import sys

# The project's package (src/python): its check that keeps going, and its
# CSV reader: that of $ROUGHWALL_ROOT (Allrun and Alltest set it), else of
# the checkout holding this tutorial, as Allrun finds it; so that Alltest,
# writeReadme.py (which imports this script) and a user run it alike
sys.path.append(os.path.join(
    os.environ.get("ROUGHWALL_ROOT")
    or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                    "..", ".."),
    "src", "python"))
from foamcase.checking import FAILED as failures
from foamcase.checking import expect as check
from foamcase.tables import read_csv

N_BINS = 25
MARGIN_SE = 3.0
VARIANT = "steel"
#: The set-up the default variant must report (summary.csv columns)
SETUP = {"geometry": "3D", "roughness": "Rq=2.87e-6,RSm=122e-6",
         "lateralTilt": "on", "lift": "Loth", "torque": "DennisSinghIngham",
         "shearLift": "SaffmanMei", "dispersion": "stochasticDispersionRAS"}
#: Band of the agreement with the reference, in combined standard errors
BAND_SE = 4.0
BAND = ("upperFraction", "UyRms", "UxRms", "UzRms", "meanUxOverBulk",
        "impactFrequency", "knImpulse", "ktImpulse")
LOADING_VARIANT = "loading1.collisions"
LOADING_SETUP = {"twoWayCoupling": "true", "collisions": "Sommerfeld",
                 "massLoading": "1"}
LOADING_BAND = ("upperFraction", "UyRms", "UxRms", "meanUxOverBulk",
                "impactFrequency", "massLoadingReached",
                "interParticleFrequency", "pressureGradient")
FIGURES = ("concentration.png", "velocity.png", "wallHits.png", "spinUp.png",
           "spinRatios.png", "loading.png")
TEXT = {"variant", "wallModel", "geometry", "roughness", "lateralTilt", "e", "muD",
        "lift", "torque", "shearLift", "dispersion", "twoWayCoupling",
        "collisions"}

#: The quantitative checks: (check, measured, required, margin)
records = []


def read_results(path):
    """The rows of a results table (foamcase's read_csv); a missing or empty
    file is a failed check and the end of the script."""
    if not (os.path.isfile(path) and os.path.getsize(path) > 0):
        check(False, "%s exists and is not empty" % path)
        sys.exit(1)
    return read_csv(path)


def finite_numbers(rows, name, text_columns):
    bad = []
    for i, row in enumerate(rows):
        for key, value in row.items():
            if key in text_columns or value == "":
                continue
            try:
                v = float(value)
            except ValueError:
                bad.append("row %d %s = %r" % (i, key, value))
                continue
            if not math.isfinite(v):
                bad.append("row %d %s = %r" % (i, key, value))
    check(not bad, "%s: every number finite%s" % (name, ": " + ", ".join(bad[:5])
                                                  if bad else ""))


def sanity(out):
    for fig in FIGURES:
        p = os.path.join(out, fig)
        check(os.path.isfile(p) and os.path.getsize(p) > 1000,
              "figure %s written" % fig)
    profiles = read_results(os.path.join(out, "profiles.csv"))
    finite_numbers(profiles, "profiles.csv", {"variant"})
    summary = read_results(os.path.join(out, "summary.csv"))
    finite_numbers(summary, "summary.csv", TEXT)
    ratios = read_results(os.path.join(out, "spinRatios.csv"))
    finite_numbers(ratios, "spinRatios.csv", TEXT)
    for row in summary:
        rows = [r for r in profiles if r["variant"] == row["variant"]]
        check(len(rows) == N_BINS, "%s: %d height bins" % (row["variant"], N_BINS))
        c = [float(r["concentration"]) for r in rows if r["concentration"]]
        check(len(c) == N_BINS and abs(sum(c)/len(c) - 1) < 1e-5,
              "%s: concentration given in every bin, mean 1" % row["variant"])
    return {row["variant"]: row for row in summary}


def value(row, key):
    return float(row[key]), float(row[key + "_se"])


def write_records(path, run):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["check", "value", "limit", "margin", "run"])
        for r in records:
            w.writerow(list(r) + [run])


def check_setup(variant, row, wanted):
    """The set-up a variant reports (summary.csv) is the wanted one"""
    for key, value_wanted in wanted.items():
        records.append(("%s %s" % (variant, key), row.get(key, ""),
                        value_wanted,
                        "ok" if row.get(key) == value_wanted else "wrong"))
        check(row.get(key) == value_wanted, "%s: %s %s (required %s)"
              % (variant, key, row.get(key), value_wanted))


def check_band(variant, row, ref, keys):
    """Every statistic of keys within BAND_SE combined standard errors of
    the committed one"""
    for key in keys:
        (x, sx), (r, sr) = value(row, key), value(ref, key)
        band = BAND_SE*math.hypot(sx, sr)
        records.append(("%s %s: short - committed" % (variant, key),
                        "%.3g" % (x - r), "within +-%.3g" % band,
                        "%.2f" % (abs(x - r)/band) if band > 0
                        else ("0" if x == r else "inf")))
        check(abs(x - r) <= band,
              "%s %s: short run %.4f, committed %.4f, difference "
              "%.4f within %g combined s.e. (%.4f)"
              % (variant, key, x, r, x - r, BAND_SE, band))


def main():
    args = sys.argv[1:]
    record = None
    if args[:1] == ["--record"]:
        record, args = args[1], args[2:]
    out = args[0]
    reference = args[1] if len(args) > 1 else None
    summary = sanity(out)
    if not check(VARIANT in summary, "variant %s in the short run" % VARIANT):
        sys.exit(1)
    row = summary[VARIANT]

    # 2. The default set-up, as the run reports it
    check_setup(VARIANT, row, SETUP)
    uz, se = value(row, "UzRms")
    records.append(("%s UzRms: spanwise motion" % VARIANT, "%.4g" % uz,
                    "> %.3g (%g s.e.)" % (MARGIN_SE*se, MARGIN_SE),
                    "%.1f" % (uz/(MARGIN_SE*se)) if se > 0 else "0"))
    check(se > 0 and uz > MARGIN_SE*se, "%s: rms spanwise velocity %.4f m/s "
          "above %g standard errors (%.4f)" % (VARIANT, uz, MARGIN_SE, se))

    # 3. Within the band of the committed result
    if reference:
        ref = {r["variant"]: r for r in
               read_results(os.path.join(reference, "summary.csv"))}
        if check(VARIANT in ref, "variant %s in the reference %s"
                 % (VARIANT, reference)):
            check_band(VARIANT, row, ref[VARIANT], BAND)

    # 4. The loading variant
    if check(LOADING_VARIANT in summary, "variant %s in the short run"
             % LOADING_VARIANT):
        loaded = summary[LOADING_VARIANT]
        check_setup(LOADING_VARIANT, loaded, LOADING_SETUP)
        if reference and check(LOADING_VARIANT in ref,
                               "variant %s in the reference %s"
                               % (LOADING_VARIANT, reference)):
            check_band(LOADING_VARIANT, loaded, ref[LOADING_VARIANT],
                       LOADING_BAND)

    if record:
        info = {}
        with open(os.path.join(out, "runInfo")) as f:
            for line in f:
                if line.strip():
                    k, v = line.split(None, 1)
                    info[k] = v.strip()
        write_records(record, "%s, OpenFOAM %s, commit %s, %s s" % (
            info.get("date", "?"), info.get("openfoam", "?").split()[0],
            info.get("commit", "?"), info.get("totalSeconds", "?")))
    if failures:
        print("checkResults: FAILED (%d): %s" % (len(failures),
                                                  "; ".join(failures)))
        sys.exit(1)
    print("checkResults: passed")


if __name__ == "__main__":
    main()
