# roughWallInteraction benchmarks: the OpenFOAM cost benchmark, parsing.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Parsing the output of the OpenFOAM cost benchmark's tools: callgrind's
inclusive counts of the patch interaction model per hit, split by source
file; perf's share of the model; the stored result rows.
"""
import collections
import re
import subprocess

from foamcase import bench as bc
import foamcase as fc

from .case import BASE


def load_rows(tag):
    rows = fc.read_csv(bc.result("openfoam-cost.%s.csv" % tag))
    for r in rows:
        r.setdefault("mesh", "box")
        r.setdefault("check", "")
    return rows


def baseline_name(path):
    """The revision of a baseline library's directory
    (build/benchmarks/baseline-<rev>/lib/...), else the path"""
    m = re.search(r"baseline-(\w+)", path or "")
    return m.group(1) if m else (path or "")


#: The patch interaction models' per-hit entry points
MODEL_ENTRY = {"rough": "RoughWallInteraction<", BASE: "RoughWallInteraction<",
               "rebound": "RoughWallInteraction<",
               "standard": "StandardWallInteraction<"}


#: Parts of a hit: by the source file the instructions were compiled from
#: (inlined code keeps its file), then by the function they are in (its name
#: without template arguments); first match wins
PARTS = [
    ("core: facet collision (facetCollision.hpp)", "file", "facetCollision"),
    ("core: sampler of the tilt (facetAngleSampler.hpp)", "file",
     "facetAngleSampler"),
    ("core: normal variates (standardNormal.hpp)", "file", "standardNormal"),
    ("core: arc tangent, sine, cosine, log (fastMath.hpp)", "file",
     "fastMath"),
    ("core: operator, frame (roughWallCollision.hpp)", "file",
     "roughWallCollision"),
    ("random numbers (OpenFOAM's generator, cloudUniform01)", "file",
     r"cloudUniform01|/Random|randomGenerator|bits/random"),
    ("statistics (roughWallStatistics)", "file", "roughWallStatistics"),
    ("core: Eigen vector arithmetic (inlined from the core and adapter)",
     "file", "/eigen3/"),
    ("random numbers (OpenFOAM's generator, cloudUniform01)", "function",
     r"Random::|randomGenerator::|cloudUniform01::|uniform01$"),
    ("statistics (roughWallStatistics)", "function", "roughWallStatistics"),
    ("roughness angle of the parcel (roughnessAngle.hpp)", "function",
     "RoughnessAngle::|RoughnessCorrelation|EnvelopeAngleTable"),
    ("patchData (wall normal and velocity: OpenFOAM)", "function",
     "patchData"),
    ("core: facet collision (facetCollision.hpp)", "function",
     "collideWithFacet"),
    ("core: sampler of the tilt (facetAngleSampler.hpp)", "function",
     "sampleFacet|acceptOneMinusExp|twoExponential"),
    ("core: normal variates (standardNormal.hpp)", "function",
     "standardNormal|normalTail"),
    ("core: operator, frame (roughWallCollision.hpp)", "function",
     "collideWithRoughWall|incidenceFrame|leaveMeanWall|randomWallTangent"),
    ("adapter (RoughWallInteraction.C and the classes it calls)",
     "function", r"RoughWallInteraction::|roughWallPatch|roughWallCompat"),
    ("standardWallInteraction (OpenFOAM)", "function",
     "StandardWallInteraction::"),
]


def base_name(function):
    """A demangled name without its template arguments, parameters and
    return type: 'double ns::f<A<B> >(int) const' -> 'ns::f'"""
    name, previous = function, None
    while name != previous:
        previous, name = name, re.sub(r"<[^<>]*>", "", name)
    name = re.sub(r"\(.*", "", name)
    return name.split()[-1] if name.split() else name


def callgrind_profile(path, entry, member="::correct("):
    """Parse a callgrind output file: the total instructions, and for the
    functions whose name contains entry and member, the calls and the inclusive
    instructions split into PARTS (self costs by the file they come from,
    callees by PARTS applied to the callee's own breakdown). Returns (total,
    calls, {part: instructions}, {callee: instructions})"""
    names = {"fn": {}, "file": {}}
    self_cost = collections.defaultdict(lambda: collections.Counter())
    edges = collections.defaultdict(collections.Counter)   # caller -> callee
    edge_calls = collections.defaultdict(collections.Counter)
    total = None
    fn = file = fn_file = callee = None
    pending = None
    compressed = re.compile(r"^\((\d+)\)(?: (.*))?$")

    def name(kind, text):
        m = compressed.match(text.strip())
        if not m:
            return text.strip()
        if m.group(2) is not None:
            names[kind][m.group(1)] = m.group(2)
        return names[kind].get(m.group(1), "?")

    with open(path, errors="replace") as f:
        for line in f:
            c = line[:1]
            if c.isdigit() or c in "+-*":
                parts = line.split()
                cost = int(parts[1]) if len(parts) > 1 else 0
                if pending:
                    edges[fn][pending[0]] += cost
                    edge_calls[fn][pending[0]] += pending[1]
                    pending = None
                else:
                    self_cost[fn][file] += cost
            elif line.startswith("fn="):
                fn = name("fn", line[3:])
                file = fn_file
            elif line.startswith("fl="):
                fn_file = file = name("file", line[3:])
            elif line.startswith(("fi=", "fe=")):
                file = name("file", line[3:])
            elif line.startswith(("cfi=", "cfl=")):
                name("file", line[4:])
            elif line.startswith("cfn="):
                callee = name("fn", line[4:])
            elif line.startswith("calls="):
                pending = (callee, int(line[6:].split()[0]))
            elif line.startswith(("summary:", "totals:")):
                total = int(line.split()[1])

    def part_of(function, source):
        base = base_name(function or "")
        for label, kind, pattern in PARTS:
            if re.search(pattern, base if kind == "function"
                         else source or ""):
                return label
        return "other: " + base[:60]

    memo = {}

    def inclusive(function, depth=0):
        """{part: instructions} of all calls of function"""
        if function in memo:
            return memo[function]
        out = collections.Counter()
        memo[function] = out    # recursion: counted once
        for source, cost in self_cost[function].items():
            out[part_of(function, source)] += cost
        for c, cost in edges[function].items():
            sub = inclusive(c, depth + 1) if depth < 60 else {}
            whole = sum(sub.values())
            if whole > 0:
                for p, x in sub.items():
                    # this edge's share of the callee's inclusive cost
                    out[p] += cost*x/whole
            else:
                out[part_of(c, "")] += cost
        return out

    entries = [f for f in set(self_cost) | set(edges)
               if f and entry in f and member in f]
    calls = sum(edge_calls[caller][f] for caller in edge_calls
                for f in entries)
    parts = collections.Counter()
    callees = collections.Counter()
    for f in entries:
        parts.update(inclusive(f))
        for c, cost in edges[f].items():
            callees[re.sub(r"\(.*", "", c)] += cost
    return total, calls, parts, callees


#: Symbols of the patch interaction models' own work in a perf profile:
#: the rough model is all of libroughWallInteraction.so and, on v1912, the
#: out-of-line Random::sample01 it calls; standardWallInteraction is its
#: correct(); both call the cloud's patchData (OpenFOAM's)
PROFILE_MODEL = {
    "rough": lambda dso, sym: dso.startswith("libroughWallInteraction")
    or "Random::sample01" in sym,
    "standard": lambda dso, sym: "StandardWallInteraction" in sym,
}


def perf_shares(data):
    """[(percent, dso, symbol)] of a perf.data file (self time)"""
    out = subprocess.run(
        ["perf", "report", "-i", data, "--stdio", "--no-children",
         "--sort", "dso,sym", "--percent-limit", "0"],
        capture_output=True, text=True).stdout
    rows = []
    for line in out.splitlines():
        m = re.match(r"\s*([0-9.]+)%\s+(\S+)\s+\[.\]\s+(.*)$", line)
        if m:
            rows.append((float(m.group(1)), m.group(2), m.group(3).strip()))
    return rows
