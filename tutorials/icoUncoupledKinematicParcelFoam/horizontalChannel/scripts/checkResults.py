#!/usr/bin/python3
"""Assertions of the horizontalChannel smoke test (Alltest) on results/.

- profiles.csv, summary.csv and the figures exist; every variant has at
  least 20 height bins; every number written is finite; the concentration
  and its standard error are given in every bin and the concentration is
  normalised (mean over the bins = 1).
- The physical effect: the concentration in the upper half of the channel of
  every rough variant exceeds the smooth variant's by more than
  MARGIN_SE combined standard errors, and the mean concentration over the
  upper half follows the same order as the upper-half fraction of parcels.

Usage: checkResults.py RESULTS_DIR
"""
import csv
import math
import sys
from collections import defaultdict
from pathlib import Path

MIN_BINS = 20
MARGIN_SE = 3.0
FIGURES = ("concentration_d195um.png", "velocity_d195um.png", "wallHits_d195um.png",
           "spinUp_d195um.png")


def fail(msg):
    print("checkResults: FAILED: " + msg)
    sys.exit(1)


def read_csv(path):
    if not path.is_file() or path.stat().st_size == 0:
        fail(f"{path} missing or empty")
    with open(path) as f:
        return list(csv.DictReader(f))


def finite_numbers(rows, path, text_columns):
    for i, row in enumerate(rows):
        for key, value in row.items():
            if key in text_columns or value == "":
                continue
            try:
                v = float(value)
            except ValueError:
                fail(f"{path}: row {i} {key} = '{value}' is not a number")
            if not math.isfinite(v):
                fail(f"{path}: row {i} {key} = {value} is not finite")


def main():
    out = Path(sys.argv[1])
    for fig in FIGURES:
        p = out / fig
        if not p.is_file() or p.stat().st_size < 1000:
            fail(f"figure {p} missing or empty")

    profiles = read_csv(out / "profiles.csv")
    finite_numbers(profiles, "profiles.csv", {"variant"})
    summary = read_csv(out / "summary.csv")
    finite_numbers(summary, "summary.csv", {"variant", "wallModel"})

    bins = defaultdict(list)
    for row in profiles:
        bins[row["variant"]].append(row)
    if "smooth" not in bins:
        fail("no smooth variant in profiles.csv")
    rough = [v for v in bins if v.startswith("rough")]
    if len(rough) < 2:
        fail("fewer than two rough variants in profiles.csv")

    upper = {}
    for variant, rows in bins.items():
        if len(rows) < MIN_BINS:
            fail(f"{variant}: {len(rows)} bins, at least {MIN_BINS} expected")
        for row in rows:
            for key in ("y_over_H", "concentration", "concentration_se"):
                if row[key] == "":
                    fail(f"{variant}: bin {row['bin']} has no {key}")
        c = [float(r["concentration"]) for r in rows]
        if abs(sum(c)/len(c) - 1) > 1e-6:
            fail(f"{variant}: mean normalised concentration {sum(c)/len(c)} != 1")
        top = [r for r in rows if float(r["y_over_H"]) > 0.5]
        mean = sum(float(r["concentration"]) for r in top)/len(top)
        # the jackknife errors of the bins are correlated; their mean is a
        # conservative bound for the error of the mean
        se = sum(float(r["concentration_se"]) for r in top)/len(top)
        upper[variant] = (mean, se)
        print(f"checkResults: {variant:10s} mean concentration in the upper half "
              f"{mean:.4f} +- {se:.4f}")

    smooth, smooth_se = upper["smooth"]
    for variant in rough:
        c, se = upper[variant]
        margin = MARGIN_SE*math.hypot(se, smooth_se)
        if not c > smooth + margin:
            fail(f"{variant}: upper-half concentration {c:.4f} not above the smooth "
                 f"variant's {smooth:.4f} by {MARGIN_SE} standard errors ({margin:.4f})")

    fractions = {row["variant"]: float(row["upperFraction"]) for row in summary}
    for variant in rough:
        if not fractions[variant] > fractions["smooth"]:
            fail(f"{variant}: upper-half parcel fraction {fractions[variant]} not above "
                 f"the smooth variant's {fractions['smooth']}")
    print("checkResults: passed")


if __name__ == "__main__":
    main()
