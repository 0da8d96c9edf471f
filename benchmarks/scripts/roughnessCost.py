#!/usr/bin/python3
# roughWallInteraction benchmarks: cost of Delta from the profile parameters.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Per-hit cost of a rough hit whose Delta comes from the wall's profile
parameters and the particle diameter (profileRoughness.hpp, cached per
diameter) against the same hit with a constant Delta.

Runs benchRoughWallCore's roughness/* benchmarks in one process, their
repetitions interleaved at random (so that the load of a shared machine
falls on all of them alike), and writes
benchmarks/results/roughness-cost.{json,csv,md} and
roughness-cost.machine.json: the median CPU time per hit of each case and
its ratio to the constant Delta.
"""
import argparse
import json
import os
import statistics
import subprocess

from foamcase import bench as bc

LABELS = {
    "roughness/delta:constant/alpha:mix": "constant Delta",
    "roughness/delta:profile/sizes:1/alpha:mix":
        "profile, 1 diameter (monodisperse)",
    "roughness/delta:profile/sizes:3/alpha:mix": "profile, 3 diameters in turn",
    "roughness/delta:profile/sizes:8/alpha:mix": "profile, 8 diameters in turn",
    "roughness/delta:profile/sizes:0/alpha:mix":
        "profile, a new diameter every hit (an atan per hit)",
}
CONSTANT = "roughness/delta:constant/alpha:mix"


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--bench", required=True, help="benchRoughWallCore")
    p.add_argument("--min-time", type=float, default=0.1)
    p.add_argument("--repetitions", type=int, default=30)
    args = p.parse_args()
    bc.ensure_dirs()
    json_out = os.path.join(bc.RESULTS, "roughness-cost.json")
    cmd = [args.bench, "--benchmark_filter=^roughness/",
           "--benchmark_min_time=%g" % args.min_time,
           "--benchmark_repetitions=%d" % args.repetitions,
           "--benchmark_enable_random_interleaving=true",
           "--benchmark_format=json", "--benchmark_out_format=json",
           "--benchmark_out=" + json_out]
    print("+ " + " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(json_out) as f:
        data = json.load(f)
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
    runs = {}
    for b in data["benchmarks"]:
        if b.get("run_type") != "iteration":
            continue
        runs.setdefault(b["run_name"], []).append(
            b["cpu_time"] * scale[b["time_unit"]])
    base = statistics.median(runs[CONSTANT])
    rows = []
    for name, label in LABELS.items():
        t = runs[name]
        q = statistics.quantiles(t, n=4)
        rows.append(dict(name=name, case=label, repetitions=len(t),
                         median_ns="%.4g" % statistics.median(t),
                         q1_ns="%.4g" % q[0], q3_ns="%.4g" % q[2],
                         ratio="%.3f" % (statistics.median(t) / base)))
    bc.write_csv("roughness-cost.csv", rows)
    bc.write_machine("roughness-cost")
    lines = ["| case | median CPU ns per hit (quartiles) | ratio to constant Delta |",
             "|---|---|---|"]
    for r in rows:
        lines.append("| %s | %s (%s .. %s) | %s |" % (
            r["case"], r["median_ns"], r["q1_ns"], r["q3_ns"], r["ratio"]))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(bc.RESULTS, "roughness-cost.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()
