#!/usr/bin/python3
# roughWallInteraction benchmarks: ctest smoke test (label "benchmark").
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Run each benchmark binary briefly and check what it reports.

  - benchRoughWallCore: every benchmark runs (min time 1 ms) and reports a
    finite, positive time; every rough-wall hit makes 1..maxFacetCollisions
    facet collisions on average and never needs the fallback at Delta <= 8 deg.
  - samplerWorkPrecision: 20000 samples per sampler at h = 0, 1, 1e5; the
    three exact samplers are within the 99.9 % Kolmogorov-Smirnov band
    (D < 1.949/sqrt(N)), the no-shadow sampler is detected as wrong at
    h = 0 (D > 0.05), and plain rejection is reported non-terminating at h = 0.
  - hitLoop: prints a finite checksum.
Run time: about 5 s.
"""
import argparse
import csv
import io
import json
import math
import subprocess
import sys

from foamcase.checking import expect, finish


def finite(x):
    return isinstance(x, (int, float)) and math.isfinite(x)


def smoke_bench(binary):
    out = subprocess.run(
        [binary, "--benchmark_min_time=0.001", "--benchmark_format=json"],
        check=True, capture_output=True, text=True).stdout
    runs = json.loads(out)["benchmarks"]
    expect(len(runs) > 150, "benchRoughWallCore ran %d benchmarks" % len(runs))
    for run in runs:
        name = run["name"]
        expect(finite(run["real_time"]) and run["real_time"] > 0
               and finite(run["cpu_time"]) and run["cpu_time"] > 0,
               "%s: time %.4g %s" % (name, run["real_time"], run["time_unit"]))
        if "model:rough" in name:
            fc = run["facetCollisions"]
            expect(finite(fc) and 1 <= fc <= 10,
                   "%s: %.4g facet collisions per hit" % (name, fc))
            delta = float(name.split("Delta:")[1].split("/")[0])
            if delta <= 8:
                expect(run["fallbacks"] == 0, "%s: no fallback" % name)


def smoke_work_precision(binary):
    n = 20000
    out = subprocess.run(
        [binary, "--samples", str(n), "--h", "0,1,1e5",
         "--min-replicates", "1", "--max-replicates", "1",
         "--calibrate", "0.01"],
        check=True, capture_output=True, text=True).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    expect(len(rows) == 12, "samplerWorkPrecision wrote %d rows" % len(rows))
    band = 1.949/math.sqrt(n)
    for r in rows:
        label = "%s h=%s" % (r["sampler"], r["h"])
        if r["status"] == "nonterminating":
            expect(r["sampler"] == "rejection" and float(r["h"]) == 0,
                   label + ": non-terminating only for rejection at h = 0")
            continue
        values = [float(r[k]) for k in ("seconds_median", "ns_per_sample",
                                         "ks_mean", "bias_rms",
                                         "bias_expected")]
        expect(r["status"] == "ok" and all(map(math.isfinite, values)),
               label + ": finite results")
        ks = float(r["ks_mean"])
        if r["sampler"] == "noShadow":
            if float(r["h"]) == 0:
                expect(ks > 0.05, label + ": wrong sampler detected, D = %.3g"
                       % ks)
        else:
            expect(ks < band, label + ": D = %.3g < %.3g" % (ks, band))


def smoke_hit_loop(binary):
    for model in ("rough", "smooth", "standard", "none"):
        out = subprocess.run(
            [binary, model, "1", "0", "3", "mix", "8", "1000"],
            check=True, capture_output=True, text=True).stdout
        expect(math.isfinite(float(out)), "hitLoop %s: checksum %s"
               % (model, out.strip()))


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--bench", required=True)
    parser.add_argument("--work-precision", required=True)
    parser.add_argument("--hit-loop", required=True)
    args = parser.parse_args()
    smoke_bench(args.bench)
    smoke_work_precision(args.work_precision)
    smoke_hit_loop(args.hit_loop)
    if finish():
        sys.exit(1)
    print("all benchmark smoke checks passed")


if __name__ == "__main__":
    main()
