"""The solver log's cloud reports and the model's statistics file
postProcessing/lagrangian/<cloud>/patchInteractionModel/<time>/roughWallInteraction.dat.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import glob
import os
import re

from .dictionaries import NUMBER, read_text
from .errors import FoamError


#: The statistics file of roughWallInteraction, and its file of the angle
#: bins (incidenceAngleBins)
STATISTICS = "roughWallInteraction.dat"
ANGLE_STATISTICS = "roughWallInteractionAngles.dat"


def statistics_path(case, cloud, time_name="*", name=STATISTICS):
    return os.path.join(case, "postProcessing", "lagrangian", cloud,
                        "patchInteractionModel", time_name, name)


def number_or_word(text):
    try:
        return float(text)
    except ValueError:
        return text


def read_statistics(case, cloud, name=STATISTICS):
    """Rows of the statistics file(s) (or of the angle file: name
    ANGLE_STATISTICS, whose patch column is a word), oldest start time
    first.  Returns (column names, list of rows as dicts)."""
    pattern = statistics_path(case, cloud, name=name)
    files = sorted(glob.glob(pattern),
                   key=lambda p: float(os.path.basename(os.path.dirname(p))))
    if not files:
        elsewhere = glob.glob(os.path.join(case, "postProcessing", "**",
                                           "roughWallInteraction*"),
                              recursive=True)
        raise FoamError("no statistics file %s%s" % (
            pattern, " (found %s)" % elsewhere if elsewhere else ""))
    names = None
    rows = []
    for path in files:
        with open(path) as f:
            for line in f:
                if line.startswith("# Time"):
                    names = line[1:].split()
                elif line.strip() and not line.startswith("#"):
                    rows.append(dict(zip(names, map(number_or_word,
                                                    line.split()))))
    return names, rows


def column(row, name):
    """A column of a statistics row; a missing column is a failure."""
    if name not in row:
        raise FoamError("statistics file has no column %s (columns: %s)"
                        % (name, " ".join(row)))
    return row[name]


def read_steps(log_path):
    """The cloud report of every time step of a solver log, as dicts: time,
    parcels, mass, linearKE, rotationalKE, executionTime, escape, stick
    (numbers, summed over the 'Parcel fate' lines), hits, fallbacks
    (summed over the rough patches), facetPerHit, energyLoss (per rough
    patch), warnings."""
    text = read_text(log_path)
    steps = []
    for block in re.split(r"\nTime = ", text)[1:]:
        step = {"time": float(re.match(NUMBER, block).group(0))}

        def grab(pattern, cast=float):
            m = re.search(pattern, block)
            return cast(m.group(1)) if m else None

        value = "(" + NUMBER + ")"
        step["parcels"] = grab(r"Current number of parcels\s*=\s*(\d+)", int)
        step["mass"] = grab(r"Current mass in system\s*=\s*" + value)
        step["linearKE"] = grab(r"Linear kinetic energy\s*=\s*" + value)
        step["rotationalKE"] = grab(r"Rotational kinetic energy\s*=\s*"
                                    + value)
        step["executionTime"] = grab(r"ExecutionTime = " + value)
        step["escape"] = sum(int(n) for n in re.findall(
            r"- escape\s*=\s*(\d+),", block))
        step["stick"] = sum(int(n) for n in re.findall(
            r"- stick\s*=\s*(\d+),", block))
        step["hits"] = sum(int(n) for n in re.findall(
            r"- hits\s*=\s*(\d+)", block))
        step["fallbacks"] = sum(int(n) for n in re.findall(
            r"- hits at the re-collision bound\s*=\s*(\d+)", block))
        step["facetPerHit"] = [float(x) for x in re.findall(
            r"- facet collisions per hit\s*=\s*" + value, block)]
        step["energyLoss"] = [float(x) for x in re.findall(
            r"- kinetic energy loss \[J\]\s*=\s*" + value, block)]
        step["warnings"] = block.count("FOAM Warning")
        steps.append(step)
    return [s for s in steps if s["parcels"] is not None]


def system_escapes(log):
    """v1912's 'Parcel fate: system' escape count at the last time step
    (-1 if there is none: OpenFOAM-13 has no such count)."""
    counts = re.findall(r"Parcel fate: system \(number, mass\)\s*\n"
                        r"\s*- escape\s*=\s*(\d+)", log)
    return int(counts[-1]) if counts else -1


def parcel_counts(log):
    """The parcel counts of the cloud reports of a log."""
    return [int(n) for n in
            re.findall(r"Current number of parcels\s*=\s*(\d+)", log)]


def final_parcels(log):
    """The parcel count of the last cloud report of a log (-1: none)."""
    counts = parcel_counts(log)
    return counts[-1] if counts else -1
