#!/usr/bin/python3
"""Assertions of the horizontalChannel smoke test (Alltest).

Usage: checkResults.py [--record FILE] SHORT_RESULTS_DIR [REFERENCE_RESULTS_DIR]

SHORT_RESULTS_DIR is the result of ./Allrun -test (variants smooth,
rough2.5, rough5, rough5.noSpinForces: fewer parcels and a shorter sampling
window than the default run, the same spin-up); REFERENCE_RESULTS_DIR the committed result
of the default run (results/).

Each check names the faults it is there to catch:

1. Sanity: profiles.csv, summary.csv and the figures exist; every variant
   has N_BINS height bins; every number written is finite; the
   concentration is normalised (mean over the bins = 1).
   Faults: a crash, NaN, lost parcels in a bin, a broken post-processing.
2. Roughness orders the variants: for each statistic of ORDERED the short
   run gives its variants in increasing order, each difference larger than
   MARGIN_SE combined standard errors: smooth < rough2.5 < rough5 for the
   rms wall-normal velocity, smooth < rough2.5 for the fraction in the upper
   half. That fraction saturates at 50 % (uniform) once the beads fill the
   channel, which both rough variants do: rough2.5 and rough5 differ there
   by about one standard error of the short run.
   Faults: no roughness (the facet tilt not sampled or not applied), one
   roughness level lost (Delta read wrongly).
3. Walls at rest and spin from the walls, from physics:
   a. With Delta = 0 every bead ends on the smooth floor, sliding forward:
      friction at a floor at rest holds it back, so it moves slower than the
      air at its centre. The centre hovers at the mean height h above the
      contact height r; the air there is at most u(r) + (h - r) u_tau^2/nu
      (the profile is concave: the wall shear u_tau^2/nu is its steepest
      slope). Faults: moving walls (a floor sliding at u(r) carried the
      beads at 6.8 m/s in the tutorial's old mapping, against a bound of
      6.3 m/s).
   b. Without the spin forces (rough5.noSpinForces) the spin changes only
      at the walls: friction turns a bead moving downstream on the floor
      forward (omega_z < 0; the ceiling turns it the other way), and the
      floor is hit more often, so the mean spin surface speed is negative
      by more than MARGIN_SE standard errors. Faults: the wall model leaves
      the spin alone, a wrong sign of the spin update.
4. Agreement with the committed result: for every variant of the short run
   and every statistic of BAND, |short - reference| <= BAND_SE combined
   standard errors. The short run has the default run's spin-up, so no
   allowance for drift is needed (README.md, "Spin-up").
   Faults: anything that moves a statistic of the tutorial (e, mu, the
   sampler, the spin models, the carrier flow) by more than 4 s.e.
"""
import csv
import math
import os
import sys
from collections import defaultdict

N_BINS = 25
MARGIN_SE = 3.0
ORDER = ("smooth", "rough2.5", "rough5")
#: The statistics that must order the variants (summary.csv columns), and
#: the variants they order
ORDERED = {"upperFraction": ("smooth", "rough2.5"), "UyRms": ORDER}
#: Band of the agreement with the reference, in combined standard errors
BAND_SE = 4.0
BAND = ("upperFraction", "UyRms", "meanUx")
#: The variant whose spin changes at the walls only
WALL_SPIN = "rough5.noSpinForces"
FIGURES = ("concentration.png", "velocity.png", "wallHits.png", "spinUp.png")

failures = []
#: The quantitative checks: (check, measured, required, margin)
records = []


def check(condition, message):
    print(("PASS  " if condition else "FAIL  ") + message, flush=True)
    if not condition:
        failures.append(message)
    return condition


def read_csv(path):
    if not os.path.isfile(path) or os.path.getsize(path) == 0:
        check(False, "%s exists and is not empty" % path)
        sys.exit(1)
    with open(path) as f:
        return list(csv.DictReader(f))


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
    profiles = read_csv(os.path.join(out, "profiles.csv"))
    finite_numbers(profiles, "profiles.csv", {"variant"})
    summary = read_csv(os.path.join(out, "summary.csv"))
    finite_numbers(summary, "summary.csv", {"variant", "wallModel", "spinCoupling"})
    bins = defaultdict(list)
    for row in profiles:
        bins[row["variant"]].append(row)
    for variant, rows in bins.items():
        check(len(rows) == N_BINS, "%s: %d height bins" % (variant, N_BINS))
        c = [float(r["concentration"]) for r in rows if r["concentration"]]
        check(len(c) == N_BINS and abs(sum(c)/len(c) - 1) < 1e-5,
              "%s: concentration given in every bin, mean 1" % variant)
    return {row["variant"]: row for row in summary}


def value(row, key):
    return float(row[key]), float(row[key + "_se"])


def write_records(path, run):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["check", "value", "limit", "margin", "run"])
        for r in records:
            w.writerow(list(r) + [run])


def main():
    args = sys.argv[1:]
    record = None
    if args[:1] == ["--record"]:
        record, args = args[1], args[2:]
    out = args[0]
    reference = args[1] if len(args) > 1 else None
    summary = sanity(out)
    for v in ORDER:
        if not check(v in summary, "variant %s in the short run" % v):
            sys.exit(1)

    # 2. Roughness orders the variants
    for key, ordered in ORDERED.items():
        for a, b in zip(ordered[:-1], ordered[1:]):
            (va, sa), (vb, sb) = value(summary[a], key), value(summary[b], key)
            margin = MARGIN_SE*math.hypot(sa, sb)
            records.append(("%s: %s - %s" % (key, b, a), "%.4g" % (vb - va),
                            "> %.3g (%g s.e.)" % (margin, MARGIN_SE),
                            "%.1f" % ((vb - va)/margin) if margin > 0 else "inf"))
            check(vb - va > margin,
                  "%s: %s %.4f < %s %.4f by %.4f, more than %g combined "
                  "standard errors (%.4f)" % (key, a, va, b, vb, vb - va,
                                              MARGIN_SE, margin))

    # 3a. Smooth floor at rest: the beads slower than the air at their centre
    smooth = summary["smooth"]
    carrier = read_csv(os.path.join(out, "carrier.csv"))[0]
    u_r, u_tau, nu, height = (float(carrier[k]) for k in
                              ("Uradius", "uTau", "nu", "height"))
    hover = float(smooth["meanHeight"])*height - 0.5*float(smooth["diameter"])
    u_air = u_r + max(hover, 0.0)*u_tau**2/nu
    ux = float(smooth["meanUx"])
    records.append(("smooth: velocity / bound of the air at the centre",
                    "%.4g" % ux, "< %.4g" % u_air, "%.3f" % (ux/u_air)))
    check(ux < u_air, "smooth: beads at %.3f m/s, slower than the air at "
          "their centre, at most u(r) + (h - r) u_tau^2/nu = %.3f + %.2g*%.4g "
          "= %.3f m/s" % (ux, u_r, hover, u_tau**2/nu, u_air))

    # 3b. Spin from the walls alone
    if check(WALL_SPIN in summary, "variant %s in the short run" % WALL_SPIN):
        spin, se = value(summary[WALL_SPIN], "meanSpinSpeed")
        records.append(("%s: mean spin surface speed" % WALL_SPIN,
                        "%.3g" % spin, "< -%.3g (%g s.e.)" % (MARGIN_SE*se,
                                                              MARGIN_SE),
                        "%.1f" % (-spin/(MARGIN_SE*se)) if se > 0 else "inf"))
        check(spin < -MARGIN_SE*se, "%s: mean spin surface speed %.3f m/s, "
              "negative (turned forward by the floor) by more than %g s.e. "
              "(%.3f)" % (WALL_SPIN, spin, MARGIN_SE, se))

    # 4. Within the band of the committed result
    if reference:
        ref = {row["variant"]: row for row in
               read_csv(os.path.join(reference, "summary.csv"))}
        for v in ORDER + (WALL_SPIN,):
            if not check(v in ref, "variant %s in the reference %s"
                         % (v, reference)):
                continue
            for key in BAND:
                (x, sx), (r, sr) = value(summary[v], key), value(ref[v], key)
                band = BAND_SE*math.hypot(sx, sr)
                records.append(("%s %s: short - committed" % (v, key),
                                "%.3g" % (x - r), "within +-%.3g" % band,
                                "%.2f" % (abs(x - r)/band) if band > 0
                                else ("0" if x == r else "inf")))
                check(abs(x - r) <= band,
                      "%s %s: short run %.4f, committed %.4f, difference "
                      "%.4f within %g combined s.e. (%.4f)"
                      % (v, key, x, r, x - r, BAND_SE, band))

    if record:
        info = {}
        with open(os.path.join(out, "runInfo")) as f:
            for line in f:
                if line.strip():
                    k, v = line.split(None, 1)
                    info[k] = v.strip()
        write_records(record, "%s, commit %s, %s s" % (
            info.get("date", "?"), info.get("commit", "?"),
            info.get("totalSeconds", "?")))
    if failures:
        print("checkResults: FAILED (%d): %s" % (len(failures),
                                                  "; ".join(failures)))
        sys.exit(1)
    print("checkResults: passed")


if __name__ == "__main__":
    main()
