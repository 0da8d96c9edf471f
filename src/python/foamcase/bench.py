# roughWallInteraction benchmarks: shared helpers of the benchmark scripts.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Paths, machine description, running Google Benchmark binaries (the
benchmark scripts import it as bc)."""
import datetime
import json
import os
import platform
import re
import shutil
import subprocess
import time

from .tables import read_csv

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
RESULTS = os.path.join(ROOT, "benchmarks", "results")
FIGURES = os.path.join(ROOT, "docs", "figures")


def portable_path(path):
    """path as the committed results record it, never this machine's
    absolute path: relative to the checkout, or $ROUGHWALL_CACHE/...,
    $HOME/..., else .../<last folder>"""
    p = os.path.abspath(path)
    if p == ROOT or p.startswith(ROOT + os.sep):
        return os.path.relpath(p, ROOT)
    for var in ("ROUGHWALL_CACHE", "HOME"):
        base = os.environ.get(var)
        if base and p.startswith(os.path.abspath(base) + os.sep):
            return "$%s/%s" % (var, os.path.relpath(p, base))
    return ".../" + os.path.basename(p)


def portable_text(text):
    """Tool output (profiles) with the checkout's absolute path removed"""
    return text.replace(ROOT + os.sep, "")


def write_csv(name, rows):
    """rows (dicts) to benchmarks/results/name (or to name if it is an
    absolute path); the columns are every key of any row, in the order they
    first appear, empty where a row has none"""
    import csv
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(os.path.join(RESULTS, name), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys, restval="")
        w.writeheader()
        w.writerows(rows)


def result(name):
    """The path of benchmarks/results/name (name itself if absolute); read
    it with foamcase.read_csv."""
    return os.path.join(RESULTS, name)


def ensure_dirs():
    os.makedirs(RESULTS, exist_ok=True)
    os.makedirs(FIGURES, exist_ok=True)


def _run(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True,
                              check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return ""


def machine():
    """What the numbers were measured on (lscpu, nproc, load, compiler)."""
    info = {}
    lscpu = _run(["lscpu"])
    for key in ("Model name", "CPU(s)", "Thread(s) per core",
                "Hypervisor vendor", "L2 cache", "L3 cache"):
        m = re.search(r"^%s:\s*(.+)$" % re.escape(key), lscpu, re.M)
        if m:
            info[key] = m.group(1).strip()
    mhz = re.search(r"^cpu MHz\s*:\s*(.+)$",
                    open("/proc/cpuinfo").read(), re.M)
    if mhz:
        info["cpu MHz"] = mhz.group(1).strip()
    info["nproc"] = _run(["nproc"]).strip()
    info["load average (1, 5, 15 min)"] = " ".join(
        open("/proc/loadavg").read().split()[:3])
    info["kernel"] = platform.release()
    info["compiler"] = _run(["c++", "--version"]).splitlines()[0] \
        if _run(["c++", "--version"]) else "?"
    info["git commit"] = _run(["git", "-C", ROOT, "rev-parse", "--short",
                               "HEAD"]).strip()
    dirty = _run(["git", "-C", ROOT, "status", "--porcelain",
                  "src/roughWallCore"])
    if dirty.strip():
        info["git commit"] += " (src/roughWallCore modified)"
    info["date"] = datetime.datetime.now().isoformat(timespec="seconds")
    return info


def head_commit():
    """The short commit of the checkout's HEAD"""
    return _run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"]).strip()


def load_average():
    """The 1-minute load average"""
    return float(open("/proc/loadavg").read().split()[0])


def provenance_line(commit, loads, command):
    """A side-by-side result's line of what it was measured at: commit,
    date, cores, the load during its rounds, the command"""
    return ("Commit %s, %s UTC, %d cores shared with other jobs (1-min load "
            "average %.1f-%.1f during the rounds). Command: `%s`." % (
                commit, time.strftime("%Y-%m-%d %H:%M", time.gmtime()),
                os.cpu_count(), min(loads), max(loads), command))


def machine_markdown(info):
    return "\n".join("| %s | %s |" % (k, v) for k, v in info.items())


def write_machine(name):
    """Record the machine next to a result file; returns the dict."""
    info = machine()
    with open(os.path.join(RESULTS, name + ".machine.json"), "w") as f:
        json.dump(info, f, indent=1)
    return info


def run_google_benchmark(binary, regex, min_time, repetitions, json_out):
    """Run a Google Benchmark binary; returns {name: median run} (times in
    ns) and writes the raw JSON to json_out."""
    cmd = [binary, "--benchmark_filter=" + regex,
           "--benchmark_min_time=%g" % min_time,
           "--benchmark_repetitions=%d" % repetitions,
           "--benchmark_report_aggregates_only=true",
           "--benchmark_format=json", "--benchmark_out_format=json",
           "--benchmark_out=" + json_out]
    print("+ " + " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(json_out) as f:
        data = json.load(f)
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
    runs = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" and \
                b.get("aggregate_name") not in ("median", "stddev"):
            continue
        name = b.get("run_name", b["name"])
        kind = b.get("aggregate_name", "median")
        entry = runs.setdefault(name, {})
        factor = scale[b["time_unit"]]
        entry[kind] = dict(b)
        entry[kind]["real_ns"] = b["real_time"]*factor
        entry[kind]["cpu_ns"] = b["cpu_time"]*factor
    return {name: dict(v["median"], stddev_ns=v.get("stddev", {}).get(
        "cpu_ns", float("nan"))) for name, v in runs.items()}


def parse_name(name):
    """'hit/model:rough/spin:1/alpha:5' -> {'kind': 'hit', 'model': ...}"""
    parts = name.split("/")
    fields = {"kind": parts[0]}
    for p in parts[1:]:
        if ":" in p:
            k, v = p.split(":", 1)
            fields[k] = v
    return fields


#: The main tutorial, copied by prepare_tutorial and run by run_tutorial
TUTORIAL = os.path.join(ROOT, "tutorials", "incompressibleFluid",
                        "horizontalChannel")
OPENFOAM_ENV = os.path.join(ROOT, "etc", "openfoamEnv")


def prepare_tutorial(work):
    """A clean copy of the tutorial (no runs, no results)"""
    tut = os.path.join(work, "horizontalChannel")
    if os.path.isdir(tut):
        shutil.rmtree(tut)
    os.makedirs(tut)
    for name in ("Allrun", "Allclean", "scripts", "carrier", "particles"):
        src = os.path.join(TUTORIAL, name)
        if os.path.isdir(src):
            shutil.copytree(src, os.path.join(tut, name),
                            ignore=shutil.ignore_patterns(
                                "log.*", "[1-9]*", "polyMesh", "__pycache__"))
        else:
            shutil.copy(src, tut)
    return tut


def run_tutorial(tut, platform, name, variant, parcels, spin_up, sampling, dt):
    """One run of the tutorial's Allrun; returns its summary row and
    profile rows"""
    out = os.path.join(tut, "results", name)
    env = dict(os.environ, ROUGHWALL_ROOT=ROOT)
    cmd = [OPENFOAM_ENV, platform, os.path.join(tut, "Allrun"),
           "-variants", variant, "-parcels", str(parcels),
           "-spinup", repr(spin_up), "-sample", repr(sampling),
           "-dt", repr(dt), "-results", out, "-jobs", "1"]
    with open(os.path.join(tut, "log.%s" % name), "w") as f:
        subprocess.run(cmd, cwd=tut, stdout=f, stderr=subprocess.STDOUT,
                       env=env, check=True)
    summary = read_csv(os.path.join(out, "summary.csv"))[0]
    profile = read_csv(os.path.join(out, "profiles.csv"))
    return summary, profile
