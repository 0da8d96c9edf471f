"""Small harness shared by the oracle tests: PASS/FAIL lines, exit status,
locating the built tools of the repository."""

import argparse
import os
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]


class Checker:
    """Collects checks; ``finish()`` prints a summary and exits 1 on any
    failure. Each check prints ``PASS  name: detail`` or ``FAIL  name:
    detail`` (ctest's FAIL_REGULAR_EXPRESSION is "FAIL  ")."""

    def __init__(self, title):
        self.title = title
        self.failures = []
        self.count = 0
        self.start = time.time()
        print(f"== {title}", flush=True)

    def check(self, name, ok, detail=""):
        self.count += 1
        tag = "PASS" if ok else "FAIL"
        print(f"{tag}  {name}: {detail}", flush=True)
        if not ok:
            self.failures.append(name)
        return ok

    def within(self, name, value, expected, tol, unit=""):
        """|value - expected| <= tol."""
        diff = abs(value - expected)
        return self.check(
            name, diff <= tol,
            f"{value:.6g} vs {expected:.6g}, |diff| {diff:.3g} <= {tol:.3g}{unit}")

    def within_se(self, name, value, expected, se, k=4.0):
        """|value - expected| <= k se."""
        diff = abs(value - expected)
        z = diff/se if se > 0 else (0.0 if diff == 0 else float("inf"))
        return self.check(
            name, diff <= k*se,
            f"{value:.6g} vs {expected:.6g}, |diff| {diff:.3g} = {z:.2f} se"
            f" (limit {k:g} se, se {se:.3g})")

    def finish(self):
        took = time.time() - self.start
        if self.failures:
            print(f"TEST FAILED: {len(self.failures)} of {self.count} checks "
                  f"failed ({', '.join(self.failures[:10])}) [{took:.1f} s]")
            sys.exit(1)
        print(f"all {self.count} checks passed [{took:.1f} s]")
        sys.exit(0)


def tool_arguments(description):
    """Command line of the tests that call built tools."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--stats", help="roughWallStats binary")
    p.add_argument("--reference", help="roughWallReference binary")
    return p.parse_args()


def find_tool(given, name, candidates):
    """The tool path: as given, else the first existing candidate below the
    repository; None if absent."""
    if given:
        return given if os.access(given, os.X_OK) else None
    for c in candidates:
        path = REPO/c
        if os.access(path, os.X_OK):
            return str(path)
    return None


STATS_CANDIDATES = ["build/applications/roughWallStats/roughWallStats",
                    "bin/roughWallStats"]
REFERENCE_CANDIDATES = ["build/tests/openfoam/roughWallReference"]


def read_csv(text):
    """CSV with a header line -> list of dicts of floats."""
    lines = [line for line in text.strip().splitlines() if line]
    keys = lines[0].split(",")
    rows = []
    for line in lines[1:]:
        values = line.split(",")
        rows.append({k: (float(v) if v != "" else float("nan"))
                     for k, v in zip(keys, values)})
    return rows
