"""CSV tables with a header line (results of the benchmarks, output of
roughWallStats and roughWallReference).

SPDX-License-Identifier: GPL-3.0-or-later
"""

import csv


def read_csv(source, numbers=False):
    """The rows of a CSV table as dicts keyed by the header: source is a
    file name or an open text stream (io.StringIO of a tool's output).
    Values are strings, or floats with numbers=True (empty: nan)."""
    if isinstance(source, str):
        with open(source) as f:
            return read_csv(f, numbers)
    rows = [row for row in csv.DictReader(source) if row]
    if numbers:
        rows = [{k: (float(v) if v != "" else float("nan"))
                 for k, v in row.items()} for row in rows]
    return rows
