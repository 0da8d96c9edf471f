"""Small harness shared by the oracle tests: locating the built tools of
the repository (their checks are foamcase.checking.Checker)."""

import argparse
import os
from pathlib import Path

REPO = Path(__file__).resolve().parents[3]


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
REFERENCE_CANDIDATES = ["build/tests/oracle/roughWallReference"]
