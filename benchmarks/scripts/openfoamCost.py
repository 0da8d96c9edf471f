#!/usr/bin/python3
# roughWallInteraction benchmarks: end-to-end cost of the rough-wall model in
# OpenFOAM against OpenFOAM's own standardWallInteraction, on OpenFOAM-13 and
# on v1912.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""The same case, the same parcels and time steps, run with
  standard   standardWallInteraction (rebound, e = 1, mu = 0)
  rebound    roughWallInteraction, patch type rebound (e = 1, mu = 0):
             the adapter without the rough physics
  rough      roughWallInteraction, patch type rough (e = 1, mu0 = muD = 0,
             Delta = 8 deg): kinetic energy is kept, as in the smooth box
  rough-base (--baseline-lib DIR only) rough with the libroughWallInteraction.so
             of DIR first on LD_LIBRARY_PATH: an earlier build of the model,
             for a before/after comparison in the same run
alternated round after round in one script (so that a drift of the machine
load hits every variant alike), on one platform (--platform):
  openfoam13    OpenFOAM-13: foamRun, `solver functions; subSolver
                incompressibleFluid;` (a frozen carrier) with the `clouds`
                fvModel function object, `type collidingCloud;` in
                constant/cloudProperties (spin is carried)
  openfoam1912  v1912 (Debian's package): icoUncoupledKinematicParcelFoam
                (colliding cloud, spin is carried)
Run it in the platform's environment only (benchmarks/run does):
  etc/openfoamEnv openfoam13 /usr/bin/python3 openfoamCost.py --platform openfoam13

Case: benchmarks/openfoam/wallBox, made and run with the
package foamcase (src/python/foamcase; the template is shared by the two
platforms; FoamCase writes the platform's files, the injector, the solver
entries). Ballistic parcels (no forces, no gravity, 110 um glass) in a
closed 0.1 m box of 2x1x1 cells with maxCo 1, injected at (40 27 13) m/s,
dt = 1 ms: about 0.8 wall hits per parcel and time step, the most
wall-dominated a particle case gets. Simulated time 0.2 s, or 4000
parcel-seconds over the parcels if that is longer (1000 parcels: 4 s), so
that every run takes seconds.

Measured per run: the solver's CPU time for the time steps (the last
ExecutionTime minus the first: start-up and mesh reading excluded), the wall
clock of the whole process, and the wall hits (rough: the model's own count;
standard and rebound: counted exactly from the positions, the velocity and
the box, since specular reflection in a box is an unfolding; the parcels
travel end_time + dt on v1912, end_time on OpenFOAM-13, see travel_time;
checked on every platform and mesh by an untimed run of the rough model with
roughnessAngle 0, which is specular and counts its hits). Writes
benchmarks/results/openfoam-cost.<tag>.csv and .md (tag: --tag, default the
platform) and docs/figures/bench-openfoam-scaling-<tag>.png.

MPI (--mpi 1, the default, also with --quick): the middle parcel count in
a mesh of two identical, disjoint closed boxes (x in [0, 0.1] and
[0.2, 0.3], each 2x1x1 cells, every face a wall: two regions of cells, no
face between them), half the parcels injected in each box, run serial and
decomposed on 2 ranks (simple, n (2 1 1): each rank owns one box, no
processor patch), the runs (1 and 2 ranks x the variants) alternated round
by round. No parcel ever crosses a processor boundary, so the 2-rank runs
measure the model's parallel behaviour (its per-processor statistics,
reduced in info() every time step, included) and not the parcel transfers
that dominated the single box cut in two (nearly one processor crossing per
wall hit). Checked before the timed runs: the decomposition (processor
faces, each processor's extent and parcels) and, in an untimed run on each
rank count of the rough model with roughnessAngle 0, the exact unfolded hit
count and (2 ranks, a write at the end) that each rank still holds the
parcels of its box.

--callgrind: instruction counts (valgrind's callgrind: noise free on a
shared machine) of a short run of the box (--callgrind-parcels, default
2000, 0.05 s) with each variant: the whole run, and the inclusive count of
the patch interaction model's correct() per call (one call per wall hit),
split by the source file the instructions come from (the core's headers,
the adapter, OpenFOAM's random generator, ...). Writes
benchmarks/results/openfoam-callgrind.<tag>.md and .csv.

--profile: perf (software clock) profiles of the rough and the standard run
of the middle parcel count: openfoam-profile-<variant>.<tag>.txt.

--tutorial (openfoam13 only: the tutorial is OpenFOAM-13's): the tutorial
tutorials/incompressibleFluid/horizontalChannel (195 um, 4000 parcels, 1 s
spin-up + 1 s sampled, dt = 1 ms; --quick: 500 parcels, 0.2 s + 0.2 s),
each variant run by its own Allrun (tutorialWorkPrecision.run_config), with
OpenFOAM's standardWallInteraction (standard) and the library's smooth and
rough2.5 walls, alternated round by round, serial (the tutorial has no
parallel option); with --baseline-lib also rough2.5-base (rough2.5 with
that library: before/after); with --variant-lib-path instead standard and
rough2.5 with and without those libraries. Writes
benchmarks/results/openfoam-tutorial-cost[.tag].csv and .md.

--lib-path DIR: DIR first on LD_LIBRARY_PATH for every variant; give the
results another --tag.

--variant-lib-path DIR: also the variants standard.lib and rough.lib (the
tutorial: standard.lib, rough2.5.lib), standard and rough with DIR first on
LD_LIBRARY_PATH, alternated with the others (benchmarks/run --openfoam-o3:
OpenFOAM-13's hot libraries at -O3 against the project's -O1 build).
"""
import argparse
import collections
import contextlib
import copy
import math
import os
import random
import re
import resource
import shutil
import statistics
import subprocess
import sys

import benchCommon as bc

import foamcase as fc

TEMPLATE = os.path.join(bc.ROOT, "benchmarks", "openfoam", "wallBox")
L = 0.1
U0 = (40.0, 27.0, 13.0)
DIAMETER = 110e-6
VARIANTS = ("standard", "rebound", "rough")
BASE = "rough-base"
# --variant-lib-path: standard and rough again with other libraries first
LIB_VARIANTS = ("standard.lib", "rough.lib")
# the wall model file of each variant (constant/wallModel.<file>)
MODEL_FILE = {"standard": "standard", "rebound": "rebound", "rough": "rough",
              BASE: "rough", "specular": "specular",
              "standard.lib": "standard", "rough.lib": "rough"}
# x of the low corner of each box: the single box, and the two disjoint
# boxes of the MPI comparison (a gap of one box length between them)
ONE_BOX = (0.0,)
TWO_BOXES = (0.0, 2*L)
MESH_NAMES = {ONE_BOX: "box", TWO_BOXES: "twoBoxes"}
PLATFORM_NAMES = {"openfoam13": "OpenFOAM-13", "openfoam1912": "OpenFOAM v1912"}


def variants_of(rows):
    """The variants present in rows, in the order of VARIANTS (+ BASE)"""
    present = {r["variant"] for r in rows}
    return [v for v in VARIANTS + (BASE,) + LIB_VARIANTS if v in present]


class Runner:
    """The platform, the libraries each variant loads, the result names"""

    def __init__(self, args):
        self.platform = fc.Platform(args.platform)
        self.tag = args.tag or args.platform
        self.lib_path = [os.path.abspath(d) for d in args.lib_path]
        self.baseline = os.path.abspath(args.baseline_lib) \
            if args.baseline_lib else None
        self.variant_lib_path = [os.path.abspath(d)
                                 for d in args.variant_lib_path]
        self.variants = VARIANTS + ((BASE,) if self.baseline else ()) \
            + (LIB_VARIANTS if self.variant_lib_path else ())

    def library_dirs(self, variant):
        """Directories put first on LD_LIBRARY_PATH for a variant"""
        dirs = list(self.lib_path)
        if variant == BASE:
            dirs.insert(0, self.baseline)
        if variant in LIB_VARIANTS:
            dirs = self.variant_lib_path + dirs
        return dirs

    def result(self, stem, ext):
        return "%s.%s.%s" % (stem, self.tag, ext)

    def check_environment(self):
        """The platform's environment, the library (and the baseline's)"""
        try:
            fc.environment_library(self.platform)
        except fc.FoamError as failure:
            sys.exit("openfoamCost.py: %s" % failure)
        if self.baseline and not os.path.isfile(
                os.path.join(self.baseline, fc.LIBRARY)):
            sys.exit("openfoamCost.py: no %s in --baseline-lib %s"
                     % (fc.LIBRARY, self.baseline))


@contextlib.contextmanager
def library_path(dirs):
    """dirs first on LD_LIBRARY_PATH (the harness runs the solver with
    os.environ)"""
    old = os.environ.get("LD_LIBRARY_PATH")
    if dirs:
        os.environ["LD_LIBRARY_PATH"] = ":".join(dirs + ([old] if old else []))
    try:
        yield
    finally:
        if old is None:
            os.environ.pop("LD_LIBRARY_PATH", None)
        else:
            os.environ["LD_LIBRARY_PATH"] = old


def block_mesh_dict(boxes):
    """The template's blockMeshDict with one block of 2x1x1 cells per box
    (low corner x0 of boxes, the template's scale 0.1 = L), every face of
    every block in the one wall patch"""
    text = open(os.path.join(TEMPLATE, "system", "blockMeshDict")).read()
    head = text[:text.index("scale")]
    cube = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
            (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    faces = [(0, 4, 7, 3), (1, 2, 6, 5), (0, 1, 5, 4), (3, 7, 6, 2),
             (0, 3, 2, 1), (4, 5, 6, 7)]
    vertices, blocks, walls = [], [], []
    for b, x0 in enumerate(boxes):
        vertices += ["    (%g %g %g)" % (x + x0/L, y, z) for x, y, z in cube]
        blocks.append("    hex (%s) (2 1 1) simpleGrading (1 1 1)"
                      % " ".join(str(8*b + i) for i in range(8)))
        walls += ["            (%s)" % " ".join(str(8*b + i) for i in f)
                  for f in faces]
    return head + (
        "scale   %g;\n\nvertices\n(\n%s\n);\n\nblocks\n(\n%s\n);\n\n"
        "boundary\n(\n    walls\n    {\n        type wall;\n        faces\n"
        "        (\n%s\n        );\n    }\n);\n\n// %s //\n" % (
            L, "\n".join(vertices), "\n".join(blocks), "\n".join(walls),
            "*"*73))


def cell_regions(case):
    """Number of regions of cells connected through internal faces (what
    checkMesh reports; OpenFOAM-13's minimal build has no checkMesh, and
    Debian's v1912 one must not run on its meshes)"""
    poly = case.file("constant/polyMesh")
    owner = fc.read_field(os.path.join(poly, "owner")).astype(int)
    neighbour = fc.read_field(os.path.join(poly, "neighbour")).astype(int)
    parent = list(range(int(owner.max()) + 1))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for a, b in zip(owner[:len(neighbour)], neighbour):
        parent[root(a)] = root(b)
    return len({root(i) for i in range(len(parent))})


def make_case(runner, work, parcels, np, end_time, seed=1, boxes=ONE_BOX):
    """A case directory for `parcels` parcels on `np` processors in the
    boxes (ONE_BOX: the template's; TWO_BOXES: two disjoint boxes, the
    first half of the parcels in the first, the second half in the second;
    the same seed gives the same parcels on every rank count and platform).
    Returns the FoamCase and the positions (as written)."""
    path = os.path.join(work, "%s-n%d-np%d" % (MESH_NAMES[boxes], parcels,
                                               np))
    case = fc.FoamCase(runner.platform, TEMPLATE, path, "colliding")
    rng = random.Random(seed)
    positions = []
    for k in range(parcels):
        x0 = boxes[k*len(boxes)//parcels]
        p = [0.005 + 0.09*rng.random() for _ in range(3)]
        # as the positions file holds them (%.9g), for the exact unfolding
        positions.append(tuple(float("%.9g" % x)
                               for x in (p[0] + x0, p[1], p[2])))
    case.write_injectors([fc.Injector("box", positions, U0, DIAMETER)])
    case.set_control(endTime="%g" % end_time)
    if boxes != ONE_BOX:
        fc.write_text(case.file("system/blockMeshDict"),
                      block_mesh_dict(boxes))
    case.run(["blockMesh"], "log.blockMesh")
    regions = cell_regions(case)
    if regions != len(boxes):
        sys.exit("%s: %d regions of cells, not %d" % (path, regions,
                                                      len(boxes)))
    if np > 1:
        case.nprocs = np
        case.set_subdomains(np)
        case.run(["decomposePar"], "log.decomposePar")
    return case, positions


def box_of(p, boxes):
    """The low corner x of the box of boxes that holds position p"""
    for x0 in boxes:
        if x0 <= p[0] <= x0 + L:
            return x0
    raise ValueError("position %s in none of the boxes %s" % (p, boxes))


def delta_t():
    """The template's time step"""
    return float(fc.dict_entry(os.path.join(TEMPLATE, "system",
                                            "controlDict"), "deltaT"))


def travel_time(platform, end_time):
    """How long the parcels of the box travel in a run to end_time. v1912:
    end_time + deltaT, since manualInjection injects at once (timeEnd = SOI
    + ROOTVSMALL) and in the first step InjectionModel::inject moves each
    new parcel by the whole step before the cloud's own move of that step;
    OpenFOAM-13: end_time, the injected parcels move from t = 0 on (checked
    on each platform: roughWallInteraction with roughnessAngle 0 counts
    exactly the unfolded hits, see check_specular)"""
    return end_time + (0 if platform.foundation else delta_t())


def specular_hits(positions, travel, boxes=ONE_BOX):
    """Wall hits of specular parcels in the boxes [x0, x0 + L] x [0, L]^2
    in a travel time: in its own box's coordinates, a parcel's unfolded
    straight path crosses floor(q_i/L) planes i = c L, q = p - (x0, 0, 0) +
    U0 t (U0 > 0); the boxes are disjoint, so each parcel stays in its box"""
    hits = 0
    for p in positions:
        q = (p[0] - box_of(p, boxes), p[1], p[2])
        hits += sum(int(math.floor((q[i] + U0[i]*travel)/L))
                    for i in range(3))
    return hits


def check_boxes(case, positions, boxes):
    """The decomposition of the two-box case: each processor owns the cells
    of exactly one box (its points' x extent is that box's), no processor
    faces (decomposePar's count and the processor boundary files) and how
    many of the parcels start on each. Returns (ok, description)"""
    log = fc.read_text(case.file("log.decomposePar"))
    proc_faces = re.findall(r"\nNumber of processor faces = (\d+)", log)
    ok = proc_faces == ["0"]
    parts = []
    owned = set()
    for i in range(case.nprocs):
        polymesh = case.file("processor%d/constant/polyMesh" % i)
        xs = fc.read_field(os.path.join(polymesh, "points"))[:, 0]
        x0, x1 = float(xs.min()), float(xs.max())
        box = [b for b in boxes if abs(b - x0) < 1e-9 and
               abs(b + L - x1) < 1e-9]
        n = sum(1 for p in positions if x0 <= p[0] <= x1)
        processor_patches = len(re.findall(
            r"type\s+processor",
            fc.read_text(os.path.join(polymesh, "boundary"))))
        ok = ok and len(box) == 1 and box[0] not in owned \
            and processor_patches == 0
        owned.update(box)
        parts.append("processor%d x %.3g-%.3g, %d parcels, %d processor "
                     "patches" % (i, x0, x1, n, processor_patches))
    ok = ok and len(owned) == len(boxes)
    return ok, "%s: processor faces %s; %s" % (
        "one box per rank" if ok else "NOT one box per rank",
        "/".join(proc_faces) or "?", "; ".join(parts))


def check_specular(runner, case, positions, end_time, boxes):
    """One more run (not timed) of a copy of the case, the rough model with
    roughnessAngle 0 (specular, and it counts its hits) and a write at the
    last step: the model's hit count against specular_hits, and (nprocs >
    1) each processor's parcels at the end against the parcels that started
    in its box. Returns (ok, description)"""
    check = copy.copy(case)
    check.path = case.path + "-check"
    if os.path.isdir(check.path):
        shutil.rmtree(check.path)
    shutil.copytree(case.path, check.path)
    check.set_control(writeInterval="%d" % int(round(end_time/delta_t())))
    text = fc.read_text(check.file("constant/wallModel.rough"))
    text, n = re.subn(r"roughnessAngle\s+[^;]+;", "roughnessAngle  0;", text)
    assert n == 1
    fc.write_text(check.file("constant/wallModel.specular"), text)
    hits = run(runner, check, "specular")["hits"]
    exact = specular_hits(positions, travel_time(runner.platform, end_time),
                          boxes)
    ok = hits == exact
    out = ["hits with roughnessAngle 0: %d, unfolding: %d%s" % (
        hits, exact, "" if ok else " (DIFFERENT)")]
    if check.nprocs > 1:
        counts, starts = [], []
        for i in range(check.nprocs):
            proc = check.file("processor%d" % i)
            last = max((d for d in os.listdir(proc)
                        if re.match(r"^[0-9.eE+-]+$", d) and float(d) > 0),
                       key=float)
            cloud = os.path.join(proc, last, "lagrangian",
                                 runner.platform.cloud)
            counts.append(len(fc.read_field(os.path.join(cloud, "d"))))
            xs = fc.read_field(os.path.join(
                proc, "constant", "polyMesh", "points"))[:, 0]
            starts.append(sum(1 for p in positions
                              if xs.min() <= p[0] <= xs.max()))
        ok = ok and counts == starts
        out.append("parcels per rank at t = %s: %s, started in its box: "
                   "%s%s" % (last, "/".join(map(str, counts)),
                             "/".join(map(str, starts)),
                             " (no transfers)" if counts == starts
                             else " (PARCELS CHANGED RANK)"))
    shutil.rmtree(check.path)
    return ok, "; ".join(out)


def run(runner, case, variant, log=None):
    """Run the case with a variant's wall model (and libraries): CPU time of
    the time steps, wall clock, CPU of all processes, the model's hits"""
    shutil.copy(case.file("constant/wallModel." + MODEL_FILE[variant]),
                case.file("constant/wallModel"))
    log = log or "log." + variant
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with library_path(runner.library_dirs(variant)):
        _, wall = case.solve(log)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime
                                                - before.ru_stime)
    steps = case.read_steps(log)
    exec_times = [s["executionTime"] for s in steps
                  if s["executionTime"] is not None]
    hits = steps[-1]["hits"] if steps else 0
    return dict(step_cpu=exec_times[-1] - exec_times[0], wall=wall,
                process_cpu=cpu, hits=hits if hits else None,
                steps=len(steps))


def measure(runner, args):
    """Rounds of the variants in each configuration, the order reversed
    every other round: the single box at each parcel count (serial), then
    (--mpi) the two disjoint boxes with the middle parcel count on 1 and 2
    ranks, the runs of a round alternated together"""
    work = os.path.abspath(os.path.join(args.work, runner.tag))
    os.makedirs(work, exist_ok=True)
    rows = []
    groups = [(n, ONE_BOX, (1,)) for n in args.parcels]
    if args.mpi:
        groups.append((args.parcels[min(1, len(args.parcels) - 1)],
                       TWO_BOXES, (1, 2)))
    for parcels, boxes, ranks in groups:
        # at least parcel_seconds of parcel time per run: small runs long
        # enough for the 0.01 s resolution of ExecutionTime
        end_time = max(args.end_time, args.parcel_seconds/parcels)
        cases, checks = {}, {}
        for np in ranks:
            cases[np], positions = make_case(runner, work, parcels, np,
                                             end_time, boxes=boxes)
            ok, text = check_specular(runner, cases[np], positions, end_time,
                                      boxes)
            if np > 1:
                ok2, text2 = check_boxes(cases[np], positions, boxes)
                ok, text = ok and ok2, "%s; %s" % (text2, text)
            checks[np] = text
            print("%s, %d parcels on %d rank(s): %s" % (
                MESH_NAMES[boxes], parcels, np, text), flush=True)
            if not ok:
                sys.exit("openfoamCost.py: the %s case on %d rank(s) fails "
                         "its check (exact specular hits%s)" % (
                             MESH_NAMES[boxes], np,
                             "; one box per rank, no transfers"
                             if np > 1 else ""))
        smooth_hits = specular_hits(
            positions, travel_time(runner.platform, end_time), boxes)
        runs = [(np, v) for np in ranks for v in runner.variants]
        for rnd in range(args.rounds):
            for np, variant in (runs if rnd % 2 == 0 else runs[::-1]):
                r = run(runner, cases[np], variant)
                hits = r["hits"] if MODEL_FILE[variant] == "rough" \
                    else smooth_hits
                row = dict(platform=runner.platform.name, tag=runner.tag,
                           baseline=bc.portable_path(runner.baseline)
                           if runner.baseline else "",
                           mesh=MESH_NAMES[boxes], parcels=parcels, np=np,
                           round=rnd, variant=variant, end_time=end_time,
                           steps=r["steps"], hits=hits,
                           step_cpu="%.3f" % r["step_cpu"],
                           wall="%.3f" % r["wall"],
                           process_cpu="%.3f" % r["process_cpu"],
                           load=open("/proc/loadavg").read().split()[0],
                           check=checks.get(np, ""))
                rows.append(row)
                print(row, flush=True)
    bc.write_csv(runner.result("openfoam-cost", "csv"), rows)
    return rows


def median_range(values, digits=3):
    if not values:
        return "-"
    f = "%%.%df" % digits
    return (f + " (" + f + "-" + f + ")") % (statistics.median(values),
                                             min(values), max(values))


def paired_ratios(rows, rank_key, key, a, b):
    """The ratio of key between runs a and b, each (variant, ranks), round by
    round (rank_key: the CSV column of the rank count)"""
    out = []
    for rnd in sorted({int(r["round"]) for r in rows}):
        t = {(r["variant"], int(r[rank_key])): float(r[key]) for r in rows
             if int(r["round"]) == rnd}
        if a in t and b in t and t[b] > 0:
            out.append(t[a]/t[b])
    return out


def paired_extra_ns(rows, a, b):
    """Per round: (T_a - T_b)/H_a [ns], the extra CPU time of the steps of
    run a over run b per wall hit of a"""
    out = []
    for rnd in sorted({int(r["round"]) for r in rows}):
        t = {r["variant"]: r for r in rows if int(r["round"]) == rnd}
        if a in t and b in t:
            out.append((float(t[a]["step_cpu"]) - float(t[b]["step_cpu"]))
                       / int(t[a]["hits"])*1e9)
    return out


def speedup_rows(variants, ranks, paired):
    """Table rows of the speed-up from the first rank count to the others:
    paired(key, (variant, n1), (variant, n)) gives the paired ratios"""
    n1 = ranks[0]
    rows = []
    for v in variants:
        for n in ranks[1:]:
            s = paired("step_cpu", (v, n1), (v, n))
            rows.append("| %s | %d -> %d | %s | %s | %s |" % (
                v, n1, n, median_range(s, 2),
                median_range(paired("wall", (v, n1), (v, n)), 2),
                "%.2f" % (statistics.median(s)*n1/n) if s else "-"))
    return rows


def load_rows(tag):
    rows = bc.read_csv("openfoam-cost.%s.csv" % tag)
    for r in rows:
        r.setdefault("mesh", "box")
        r.setdefault("check", "")
    return rows


def summarise(rows):
    """Per (mesh, parcels, np): medians per variant and paired ratios per
    round"""
    groups = {}
    for r in rows:
        groups.setdefault((r["mesh"], int(r["parcels"]), int(r["np"])),
                          []).append(r)
    out = []
    for (mesh, parcels, np), rs in sorted(groups.items(),
                                          key=lambda g: (g[0][0] != "box",
                                                         g[0][1:])):
        med = {}
        for v in variants_of(rs):
            vs = [r for r in rs if r["variant"] == v]
            med[v] = dict(
                step_cpu=statistics.median(float(r["step_cpu"]) for r in vs),
                wall=statistics.median(float(r["wall"]) for r in vs),
                hits=statistics.median(int(r["hits"]) for r in vs))
        ratios = {v: paired_ratios(rs, "np", "step_cpu", (v, np),
                                   ("standard", np))
                  for v in med if v != "standard"}
        out.append(dict(mesh=mesh, parcels=parcels, np=np, med=med,
                        rounds=len({r["round"] for r in rs}),
                        steps=int(rs[0].get("steps") or 0),
                        end_time=float(rs[0].get("end_time", "nan")),
                        ratios=ratios,
                        extra=paired_extra_ns(rs, "rough", "standard"),
                        extra_base=paired_extra_ns(rs, BASE, "standard"),
                        loads=[float(r["load"]) for r in rs]))
    return out


def two_box_table(rows):
    """Markdown of the two-box runs: per variant and rank count the medians,
    the paired rough/standard and rebound/standard ratios on each rank
    count, the paired 1 -> N rank speed-ups per variant"""
    rows = [r for r in rows if r["mesh"] == "twoBoxes"]
    if not rows:
        return []
    ranks = sorted({int(r["np"]) for r in rows})
    rounds = sorted({int(r["round"]) for r in rows})
    variants = variants_of(rows)

    def of(variant, n, key):
        return [float(r[key]) for r in rows if r["variant"] == variant
                and int(r["np"]) == n]

    def paired(key, a, b):
        return paired_ratios(rows, "np", key, a, b)

    r0 = rows[0]
    parcels = int(r0["parcels"])
    loads = [float(r["load"]) for r in rows]
    text = ["", "MPI: two identical, disjoint closed boxes (x in [0, %g] and "
            "[%g, %g] m, each 2x1x1 cells, all faces walls; %d regions of "
            "cells), %d parcels, the first %d in the first box and the "
            "rest in the second, %g s simulated, dt = 1 ms, the same parcels "
            "and time steps on every rank count; %d rounds of the %d runs "
            "(%s ranks x %s), the order reversed every other round; load "
            "average %.1f-%.1f. Checks: an untimed run on each rank count "
            "with roughnessAngle 0 (specular) must count exactly the unfolded "
            "hits; on 2 ranks no processor faces, each processor's mesh one "
            "box, and each rank's parcels at the end those injected into "
            "its box." % (
                L, TWO_BOXES[1], TWO_BOXES[1] + L, len(TWO_BOXES), parcels,
                parcels//2, float(r0["end_time"]), len(rounds),
                len(ranks)*len(variants), "/".join(map(str, ranks)),
                "/".join(variants), min(loads), max(loads))]
    for n in ranks:
        d = [r["check"] for r in rows if int(r["np"]) == n]
        text.append("\nCheck on %d rank(s)%s: %s." % (
            n, " (simple, n (%d 1 1))" % n if n > 1 else "",
            d[0] if d and d[0] else "?"))
    text += ["", "| variant | MPI ranks | runs | CPU of the time steps, rank "
             "0 [s] | wall clock [s] | CPU of all processes [s] | wall hits "
             "| hits per CPU s (rank 0) [M/s] | hits per wall s [M/s] |",
             "|---|---|---|---|---|---|---|---|---|"]
    for v in variants:
        for n in ranks:
            cpu, wall = of(v, n, "step_cpu"), of(v, n, "wall")
            if not cpu:
                continue
            h = statistics.median(of(v, n, "hits"))
            c, w = statistics.median(cpu), statistics.median(wall)
            text.append("| %s | %d | %d | %s | %s | %.2f | %d%s | %s | %.2f |"
                        % (v, n, len(cpu), median_range(cpu, 2),
                           median_range(wall, 2),
                           statistics.median(of(v, n, "process_cpu")), h,
                           "" if MODEL_FILE[v] == "rough" else " (exact)",
                           "%.2f" % (h/c/1e6) if c > 0 else "-",
                           h/w/1e6))
    others = [v for v in variants if v != "standard"]
    text += ["", "| MPI ranks | %s |" % " | ".join(
        "%s/standard, CPU of the steps: median of the paired rounds (range)"
        % v for v in others) + " rough/standard, wall clock |",
        "|---|" + "---|"*(len(others) + 1)]
    for n in ranks:
        text.append("| %d | %s | %s |" % (
            n, " | ".join(median_range(paired("step_cpu", (v, n),
                                              ("standard", n)))
                          for v in others),
            median_range(paired("wall", ("rough", n), ("standard", n)))))
    if len(ranks) > 1:
        text += ["", "| variant | ranks | speed-up, CPU of the time steps "
                 "(rank 0): median of the paired rounds (range) | speed-up, "
                 "wall clock | parallel efficiency (CPU of the steps) |",
                 "|---|---|---|---|---|"]
        text += speedup_rows(variants, ranks, paired)
    text += ["", "CPU of the time steps: rank 0's last ExecutionTime minus "
             "its first (start-up and mesh reading excluded; on 2 ranks "
             "OpenMPI polls while it waits (yielding the core, "
             "mpi_yield_when_idle), so this is about the elapsed time of the "
             "steps, and rank 0 tracks half the parcels). Wall clock: the "
             "solver's process (mpirun and start-up included). CPU of all "
             "processes: getrusage of the solver, all ranks and mpirun. "
             "Hits: standard and rebound counted exactly by unfolding each "
             "parcel's path in its own box, rough the model's count at the "
             "end, reduced over the processors. Ranges: min-max over the "
             "runs or the paired rounds."]
    return text


def baseline_name(path):
    """The revision of a baseline library's directory
    (build/benchmarks/baseline-<rev>/lib/...), else the path"""
    m = re.search(r"baseline-(\w+)", path or "")
    return m.group(1) if m else (path or "")


def command_of(tag, platform, baseline=""):
    """The benchmarks/run command of a result (baseline: the directory of
    the rough-base library, build/benchmarks/baseline-<rev>/lib/...)"""
    extra = " --openfoam-o3" if tag.endswith("-O3") else ""
    if baseline:
        extra += " --baseline " + baseline_name(baseline)
    return "benchmarks/run --platform %s%s openfoam" % (platform, extra)


def table(tag, summary, rows):
    platform = rows[0].get("platform") or tag
    variants = variants_of(rows)
    loads = [float(r["load"]) for r in rows]
    box = [s for s in summary if s["mesh"] == "box"]
    head = ["%s (%s), `%s`; %s; %d rounds, the order reversed every other "
            "round; load average %.1f-%.1f during the runs." % (
                PLATFORM_NAMES.get(platform, platform), tag,
                command_of(tag, platform, rows[0].get("baseline")),
                "foamRun (functions + incompressibleFluid, clouds fvModel), "
                "collidingCloud" if platform == "openfoam13" else
                "icoUncoupledKinematicParcelFoam (colliding cloud)",
                box[0]["rounds"] if box else 0, min(loads), max(loads)), ""]
    others = [v for v in variants if v != "standard"]
    lines = head + [
        "| parcels | simulated s (steps) | standard: CPU s, hits, Mhits/s | "
        + " | ".join("%s: CPU s%s" % (v, ", hits, Mhits/s"
                                      if MODEL_FILE[v] == "rough" else "")
                     for v in others)
        + " | " + " | ".join("%s/standard CPU (median, min-max of rounds)"
                             % v for v in others)
        + " | extra per rough hit (T_rough - T_standard)/H_rough [ns] | "
        "T/H rough - T/H standard [ns] |",
        "|---|---|---|" + "---|"*(2*len(others) + 2)]
    for s in box:
        m = s["med"]
        st = m["standard"]
        cells = ["%.2f, %d, %.2f" % (st["step_cpu"], st["hits"],
                                     st["hits"]/st["step_cpu"]/1e6)]
        for v in others:
            x = m[v]
            cells.append("%.2f, %d, %.2f" % (x["step_cpu"], x["hits"],
                                             x["hits"]/x["step_cpu"]/1e6)
                         if MODEL_FILE[v] == "rough"
                         else "%.2f" % x["step_cpu"])
        cells += [median_range(s["ratios"][v]) for v in others]
        cells.append(median_range(s["extra"], 0))
        ro = m["rough"]
        cells.append("%.0f" % ((ro["step_cpu"]/ro["hits"]
                                - st["step_cpu"]/st["hits"])*1e9))
        lines.append("| %d | %g (%d) | %s |" % (
            s["parcels"], s["end_time"], s["steps"], " | ".join(cells)))
    lines += ["", "CPU: the solver's CPU time of the time steps (last "
              "ExecutionTime minus the first), median over the rounds; "
              "ratios and the extra per hit: median (range) over the rounds "
              "of the paired values. Hits: standard and rebound counted "
              "exactly by unfolding the straight paths (checked: the rough "
              "model with roughnessAngle 0 counts the same), rough the "
              "model's count."]
    if platform == "openfoam13":
        lines += ["", "OpenFOAM-13 is the project's own build, compiled at "
                  "-O1 (docs/openfoam13.md; %s); libroughWallInteraction.so "
                  "is -O3 on both platforms, v1912 is Debian's -O3 build." % (
                      "standard.lib and rough.lib here with OpenFOAM-13's "
                      "libOpenFOAM, libmeshTools, libtracking, "
                      "liblagrangian and liblagrangianParcel (not "
                      "libfiniteVolume) "
                      "compiled at OpenFOAM's -O3 first on LD_LIBRARY_PATH, "
                      "the other variants with the -O1 build"
                      if tag.endswith("-O3") else
                      "the tracking, the cloud and the parcel library run at "
                      "-O1")]
    lines += two_box_table(rows)
    text = "\n".join(lines) + "\n"
    with open(os.path.join(bc.RESULTS, "openfoam-cost.%s.md" % tag),
              "w") as f:
        f.write(text)
    print(text)


def figure(summaries):
    """Throughput and the rough/standard ratio against the parcels, one
    colour per variant, one line style per platform (tag)"""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    styles = ["-", "--", ":", "-."]
    colours = {"standard": "k", "rebound": "C1", "rough": "C0", BASE: "C2",
               "standard.lib": "C7", "rough.lib": "C4"}
    for (tag, summary), ls in zip(sorted(summaries.items()), styles):
        serial = [s for s in summary if s["np"] == 1 and s["mesh"] == "box"]
        if len(serial) < 2:     # a single parcel count: no line to draw
            continue
        n = [s["parcels"] for s in serial]
        for v in serial[0]["med"]:
            axes[0].loglog(n, [s["med"][v]["hits"]/s["med"][v]["step_cpu"]
                               for s in serial], "o" + ls,
                           color=colours[v], label="%s, %s" % (tag, v))
        for v in serial[0]["ratios"]:
            r = [statistics.median(s["ratios"][v]) for s in serial]
            lo = [x - min(s["ratios"][v]) for x, s in zip(r, serial)]
            hi = [max(s["ratios"][v]) - x for x, s in zip(r, serial)]
            axes[1].errorbar(n, r, yerr=[lo, hi], fmt="o" + ls, capsize=3,
                             color=colours[v],
                             label="%s, %s/standard" % (tag, v))
    axes[0].set_xlabel("parcels")
    axes[0].set_ylabel("wall hits per CPU second")
    axes[0].set_title("throughput (CPU time of the time steps)", fontsize=9)
    axes[0].legend(fontsize=7)
    axes[0].grid(True, which="both", alpha=0.3)
    axes[1].set_xscale("log")
    axes[1].axhline(1.05, color="r", lw=1, label="target +5 %")
    axes[1].axhline(1.03, color="r", lw=1, ls=":", label="target +3 %")
    axes[1].set_xlabel("parcels")
    axes[1].set_ylabel("CPU time ratio (paired rounds; bars min-max)")
    axes[1].legend(fontsize=7)
    axes[1].grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    path = os.path.join(bc.FIGURES, "bench-openfoam-scaling.png")
    fig.savefig(path, dpi=110)
    print("wrote " + path)


# ---------------------------------------------------------------------------
# Instruction counts (callgrind)
# ---------------------------------------------------------------------------

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
    ("roughness angle of the parcel (roughnessAngleTable)", "function",
     "roughnessAngleTable"),
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


def callgrind_profile(path, entry):
    """Parse a callgrind output file: the total instructions, and for the
    functions whose name contains entry, the calls and the inclusive
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
               if f and entry in f and "::correct(" in f]
    calls = sum(edge_calls[caller][f] for caller in edge_calls
                for f in entries)
    parts = collections.Counter()
    callees = collections.Counter()
    for f in entries:
        parts.update(inclusive(f))
        for c, cost in edges[f].items():
            callees[re.sub(r"\(.*", "", c)] += cost
    return total, calls, parts, callees


def callgrind(runner, args):
    """callgrind of a short run of the box with each variant"""
    if not shutil.which("valgrind"):
        print("valgrind not found: no instruction counts")
        return
    work = os.path.abspath(os.path.join(args.work, runner.tag, "callgrind"))
    os.makedirs(work, exist_ok=True)
    parcels, end_time = args.callgrind_parcels, args.callgrind_end_time
    case, positions = make_case(runner, work, parcels, 1, end_time)
    specular = specular_hits(positions,
                             travel_time(runner.platform, end_time))
    rows = []
    for variant in runner.variants:
        out = case.file("callgrind.%s.out" % variant)
        shutil.copy(case.file("constant/wallModel." + MODEL_FILE[variant]),
                    case.file("constant/wallModel"))
        with library_path(runner.library_dirs(variant)):
            case.run(["valgrind", "--tool=callgrind",
                      "--callgrind-out-file=" + out, case.solver],
                     "log.callgrind." + variant, timeout=3600)
        steps = case.read_steps("log.callgrind." + variant)
        hits = steps[-1]["hits"] if MODEL_FILE[variant] == "rough" else specular
        total, calls, parts, callees = callgrind_profile(
            out, MODEL_ENTRY[variant])
        row = dict(platform=runner.platform.name, tag=runner.tag,
                   baseline=bc.portable_path(runner.baseline)
                   if runner.baseline else "",
                   variant=variant, parcels=parcels, end_time=end_time,
                   hits=hits, total=total, correct_calls=calls,
                   correct_inclusive=int(sum(parts.values())))
        for p, x in parts.items():
            row["part: " + p] = int(round(x))
        rows.append(row)
        print({k: v for k, v in row.items() if not k.startswith("part")},
              flush=True)
        os.remove(out)
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    for r in rows:
        for k in keys:
            r.setdefault(k, 0)
    bc.write_csv(runner.result("openfoam-callgrind", "csv"), rows)
    callgrind_table(runner.tag, rows)


def callgrind_table(tag, rows):
    """Instructions per wall hit: whole run and the model's correct()"""
    platform = rows[0]["platform"]
    by = {r["variant"]: r for r in rows}
    st = by.get("standard")
    lines = ["%s (%s): callgrind of `%s` in the box, %s parcels, %s s "
             "simulated (`%s`, its `--callgrind` step). Instructions per "
             "wall hit; correct() is called once per hit." % (
                 PLATFORM_NAMES.get(platform, platform), tag,
                 "foamRun" if platform == "openfoam13"
                 else "icoUncoupledKinematicParcelFoam",
                 rows[0]["parcels"], rows[0]["end_time"],
                 command_of(tag, platform, rows[0].get("baseline"))), "",
             "| variant | wall hits | correct() calls | whole run [10^6 "
             "instructions] | whole run - standard's, per wall hit of the "
             "variant | correct() per call (inclusive) | correct() per call - "
             "standard's |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        h, c = int(r["hits"]), int(r["correct_calls"])
        per_call = int(r["correct_inclusive"])/c if c else float("nan")
        st_call = int(st["correct_inclusive"])/int(st["correct_calls"]) \
            if st and int(st["correct_calls"]) else float("nan")
        lines.append("| %s | %d | %d | %.1f | %s | %.0f | %s |" % (
            r["variant"], h, c, int(r["total"])/1e6,
            "%.0f" % ((int(r["total"]) - int(st["total"]))/h)
            if st and r is not st else "-",
            per_call, "%.0f" % (per_call - st_call)
            if st and r is not st else "-"))
    parts = sorted({k for r in rows for k in r if k.startswith("part: ")},
                   key=lambda k: -max(float(r.get(k, 0)) for r in rows))
    lines += ["", "correct() per call, by part [instructions]:", "",
              "| part | " + " | ".join(r["variant"] for r in rows) + " |",
              "|---|" + "---|"*len(rows)]
    def per_call(r, k):
        c = int(r["correct_calls"])
        return float(r.get(k, 0))/c if c else 0.0

    small = [k for k in parts if max(per_call(r, k) for r in rows) < 2]
    for k in parts:
        if k not in small:
            lines.append("| %s | %s |" % (k[6:], " | ".join(
                "%.0f" % per_call(r, k) for r in rows)))
    if small:
        lines.append("| other (%d functions, each < 2 per call) | %s |" % (
            len(small), " | ".join("%.0f" % sum(per_call(r, k)
                                                for k in small)
                                   for r in rows)))
    lines.append("| **all** | %s |" % " | ".join(
        "%.0f" % (int(r["correct_inclusive"])/int(r["correct_calls"]))
        if int(r["correct_calls"]) else "-" for r in rows))
    lines += ["", "Parts: instructions by the source file they were "
              "compiled from (inlined code keeps its file) or by the "
              "function they are in (OpenFOAM's random generator, "
              "statistics, patchData); callees' shares by their own "
              "breakdown."]
    text = "\n".join(lines) + "\n"
    with open(os.path.join(bc.RESULTS, "openfoam-callgrind.%s.md" % tag),
              "w") as f:
        f.write(text)
    print(text)


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


def profile(runner, args):
    """perf (software clock) profiles of the rough and the standard run of
    the middle parcel count: where the extra time of the rough wall goes,
    and the time per wall hit in the models' own code (their share of the
    samples times the run's CPU time over its hits)"""
    if not shutil.which("perf"):
        print("perf not found: no profile")
        return
    work = os.path.abspath(os.path.join(args.work, runner.tag, "profile"))
    os.makedirs(work, exist_ok=True)
    parcels = args.parcels[min(1, len(args.parcels) - 1)]
    end_time = max(args.end_time, args.parcel_seconds/parcels)
    case, positions = make_case(runner, work, parcels, 1, end_time)
    summary = []
    for variant in ("rough", "standard"):
        shutil.copy(case.file("constant/wallModel." + variant),
                    case.file("constant/wallModel"))
        data = case.file("perf.%s.data" % variant)
        log = "log.perf." + variant
        with library_path(runner.library_dirs(variant)):
            case.run(["perf", "record", "-e", "cpu-clock", "-F", "2000",
                      "-o", data, case.solver], log)
        out = []
        for sort in ("dso", "sym"):
            out.append(subprocess.run(
                ["perf", "report", "-i", data, "--stdio", "--no-children",
                 "--sort", sort, "--percent-limit", "0.5"],
                capture_output=True, text=True).stdout)
        path = os.path.join(bc.RESULTS, "openfoam-profile-%s.%s.txt"
                            % (variant, runner.tag))
        with open(path, "w") as f:
            f.write("# perf record -e cpu-clock %s, %d parcels, %s, %s\n"
                    % (case.solver, parcels, variant, runner.tag))
            f.write("\n".join(out))
        print("wrote " + path)
        steps = case.read_steps(log)
        cpu = steps[-1]["executionTime"]
        hits = steps[-1]["hits"] if variant == "rough" else specular_hits(
            positions, travel_time(runner.platform, end_time))
        shares = perf_shares(data)
        model = sum(p for p, dso, sym in shares
                    if PROFILE_MODEL[variant](dso, sym))
        patch = sum(p for p, dso, sym in shares if "::patchData(" in sym)
        summary.append(dict(variant=variant, hits=hits, cpu=cpu,
                            model_percent=model, patchData_percent=patch,
                            model_ns=model/100*cpu/hits*1e9,
                            patchData_ns=patch/100*cpu/hits*1e9))
    lines = ["%s (%s), perf record -e cpu-clock -F 2000 of `%s`, the box "
             "with %d parcels, %g s (`%s`, its `--profile` step): the "
             "models' own code per wall hit = its share of the samples x "
             "the run's CPU time (last ExecutionTime) / the run's wall "
             "hits." % (PLATFORM_NAMES[runner.platform.name], runner.tag,
                        case.solver, parcels, end_time,
                        command_of(runner.tag, runner.platform.name)), "",
             "| variant | wall hits | CPU [s] | model's own code: share, "
             "ns per hit | patchData (OpenFOAM, both): share, ns per hit |",
             "|---|---|---|---|---|"]
    for r in summary:
        lines.append("| %s | %d | %.2f | %.1f %%, %.0f | %.1f %%, %.0f |" % (
            r["variant"], r["hits"], r["cpu"], r["model_percent"],
            r["model_ns"], r["patchData_percent"], r["patchData_ns"]))
    lines += ["", "rough: all of libroughWallInteraction.so (the adapter and "
              "the core, inlined into it)%s; standard: "
              "StandardWallInteraction::correct." % (
                  " and OpenFOAM's Random::sample01 it calls"
                  if not runner.platform.foundation else ""),
              "Extra per rough hit in the models' own code: %.0f ns." % (
                  summary[0]["model_ns"] - summary[1]["model_ns"])]
    text = "\n".join(lines) + "\n"
    with open(os.path.join(bc.RESULTS, "openfoam-profile.%s.md"
                           % runner.tag), "w") as f:
        f.write(text)
    print(text)


# ---------------------------------------------------------------------------
# The tutorial's case (tutorials/incompressibleFluid/horizontalChannel,
# OpenFOAM-13)
# ---------------------------------------------------------------------------

#: The tutorial's variants compared: OpenFOAM alone (standardWallInteraction,
#: no spin models), the model with a smooth wall (roughnessAngle 0) and with
#: Delta = 2.5 deg (both with the library's spin models, as the tutorial
#: runs them)
TUTORIAL_VARIANTS = ("standard", "smooth", "rough2.5")
#: rough2.5 with --baseline-lib's library (the before of a before/after)
TUTORIAL_BASE = "rough2.5-base"
#: standard and rough2.5 with --variant-lib-path's libraries first
TUTORIAL_LIB_VARIANTS = ("standard.lib", "rough2.5.lib")


def tutorial_stem(tag):
    """Name of the tutorial's results in benchmarks/results (without .csv,
    .md): openfoam-tutorial-cost[.tag]"""
    return "openfoam-tutorial-cost" + ("." + tag if tag else "")


def tutorial_measure(args):
    """Rounds of the TUTORIAL_VARIANTS, each run by the tutorial's Allrun
    (tutorialWorkPrecision.run_config: one variant, -jobs 1, serial: the
    tutorial has no parallel option), the order reversed every other round;
    returns the rows"""
    import tutorialWorkPrecision as tw
    bc.write_machine(tutorial_stem(args.tag))
    work = os.path.abspath(os.path.join(args.work, "tutorial"))
    os.makedirs(work, exist_ok=True)
    tut = tw.prepare(work)
    parcels, spin_up, sampling = (500, 0.2, 0.2) if args.quick \
        else (4000, 1.0, 1.0)
    # variant: (the tutorial's wall model, directories first on
    # LD_LIBRARY_PATH; the Allrun runs in this environment)
    variants = {v: (v, []) for v in TUTORIAL_VARIANTS}
    if args.baseline_lib:
        variants[TUTORIAL_BASE] = ("rough2.5",
                                   [os.path.abspath(args.baseline_lib)])
    if args.variant_lib_path:
        # other OpenFOAM libraries: standard and rough2.5 with and without
        dirs = [os.path.abspath(d) for d in args.variant_lib_path]
        variants = {v: (v.replace(".lib", ""), dirs if ".lib" in v else [])
                    for v in ("standard", "rough2.5") + TUTORIAL_LIB_VARIANTS}
    order = list(variants)
    rows = []
    for rnd in range(args.rounds):
        for variant in (order if rnd % 2 == 0 else order[::-1]):
            name = "cost-%s-%d" % (variant, rnd)
            config, dirs = variants[variant]
            with library_path(dirs):
                summary, _ = tw.run_config(tut, name, config, parcels,
                                           spin_up, sampling, 1e-3)
            row = dict(round=rnd, variant=variant, parcels=parcels,
                       spin_up=spin_up, sampling=sampling,
                       cpu="%.2f" % float(summary["cpuTime"]),
                       wall="%.2f" % float(summary["wallClock"]),
                       hits_lower=summary.get(
                           "hitsPerParcelPerMetre_lowerWall", ""),
                       upperFraction=summary["upperFraction"],
                       baseline=baseline_name(args.baseline_lib)
                       if variant == TUTORIAL_BASE else "",
                       lib_path=":".join(bc.portable_path(d)
                                         for d in variants[variant][1]),
                       load=open("/proc/loadavg").read().split()[0])
            rows.append(row)
            print(row, flush=True)
    bc.write_csv(tutorial_stem(args.tag) + ".csv", rows)
    return rows, tut


def tutorial_table(rows, tag=None):
    """Medians per variant and the paired ratios to standard and smooth"""
    variants = [v for v in TUTORIAL_VARIANTS + (TUTORIAL_BASE,)
                + TUTORIAL_LIB_VARIANTS
                if any(r["variant"] == v for r in rows)]

    def of(variant, key):
        return [float(r[key]) for r in rows if r["variant"] == variant
                and r.get(key, "") not in ("", None)]

    def paired(a, b):
        out = []
        for rnd in sorted({int(r["round"]) for r in rows}):
            t = {r["variant"]: float(r["cpu"]) for r in rows
                 if int(r["round"]) == rnd}
            if a in t and b in t and t[b] > 0:
                out.append(t[a]/t[b])
        return out

    r0 = rows[0]
    loads = [float(r["load"]) for r in rows]
    text = ["OpenFOAM-13, tutorial incompressibleFluid/horizontalChannel "
            "(195 um, %s parcels, %s s spin-up + %s s sampled, dt = 1 ms), "
            "each variant by the tutorial's Allrun, serial, %d rounds, the "
            "order reversed every other round; load average %.1f-%.1f "
            "(`benchmarks/run --platform openfoam13 openfoam`, its "
            "`openfoamCost.py --tutorial` step)." % (
                r0["parcels"], r0["spin_up"], r0["sampling"],
                len({r["round"] for r in rows}), min(loads), max(loads)), "",
            "| variant | runs | solver CPU [s] (range) | wall clock [s] | "
            "lower-wall hits per parcel and metre | upper-half fraction |",
            "|---|---|---|---|---|---|"]
    for v in variants:
        cpu = of(v, "cpu")
        hits = of(v, "hits_lower")
        text.append("| %s | %d | %s | %.1f | %s | %.3f |" % (
            v, len(cpu), median_range(cpu, 1),
            statistics.median(of(v, "wall")),
            "%.3g" % statistics.median(hits) if hits else "-",
            statistics.median(of(v, "upperFraction"))))
    text += ["", "| ratio of the solver CPU, paired rounds | median "
             "(range) |", "|---|---|"]
    for a, b in (("rough2.5", "standard"), ("smooth", "standard"),
                 ("rough2.5", "smooth"), ("rough2.5", TUTORIAL_BASE),
                 ("standard.lib", "standard"),
                 ("rough2.5.lib", "rough2.5")):
        if a in variants and b in variants:
            text.append("| %s/%s | %s |" % (a, b,
                                            median_range(paired(a, b))))
    text += ["", "Solver CPU: the tutorial's cpuTime (the particle run's "
             "last ExecutionTime; the carrier flow is computed once, "
             "before the rounds). standard is OpenFOAM alone; smooth and "
             "rough2.5 run the library's patch interaction model and its "
             "spin models (rotational lift, fluid torque), so "
             "rough2.5/smooth is the rough wall alone."]
    lib = [r.get("lib_path", "") for r in rows
           if r["variant"] in TUTORIAL_LIB_VARIANTS]
    if lib:
        text += ["", "standard.lib, rough2.5.lib: the same with %s first on "
                 "LD_LIBRARY_PATH." % lib[0]]
    base = [r.get("baseline", "") for r in rows
            if r["variant"] == TUTORIAL_BASE]
    if base:
        text += ["", "%s: rough2.5 with the library of %s first on "
                 "LD_LIBRARY_PATH (the same case, parcels and time steps): "
                 "rough2.5/%s is the run time after against before." % (
                     TUTORIAL_BASE, base[0], TUTORIAL_BASE)]
    text = "\n".join(text) + "\n"
    with open(os.path.join(bc.RESULTS, tutorial_stem(tag) + ".md"),
              "w") as f:
        f.write(text)
    print(text)


def tutorial_cost(args):
    """The tutorial's short case with OpenFOAM's wall model and the
    library's smooth and rough walls, same parcels and time steps,
    alternated"""
    if args.plot_only:
        tutorial_table(bc.read_csv(tutorial_stem(args.tag) + ".csv"),
                       args.tag)
        return
    rows, _ = tutorial_measure(args)
    tutorial_table(rows, args.tag)


def plot_only(args):
    """Tables and the figure again from the stored CSVs of every tag (or
    of --tag)"""
    tags = sorted(re.match(r"openfoam-cost\.(.+)\.csv$", f).group(1)
                  for f in os.listdir(bc.RESULTS)
                  if re.match(r"openfoam-cost\.(.+)\.csv$", f))
    if args.tag:
        tags = [t for t in tags if t == args.tag]
    summaries = {}
    for tag in tags:
        rows = load_rows(tag)
        summaries[tag] = summarise(rows)
        table(tag, summaries[tag], rows)
        cg = "openfoam-callgrind.%s.csv" % tag
        if os.path.exists(os.path.join(bc.RESULTS, cg)):
            callgrind_table(tag, bc.read_csv(cg))
    if summaries:
        figure(summaries)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--platform", choices=fc.PLATFORMS,
                   help="the platform whose environment this runs in")
    p.add_argument("--tag", help="name of the results (default: the "
                   "platform)")
    p.add_argument("--work", default=os.path.join(bc.ROOT, "build",
                                                  "benchmarks", "openfoam"))
    p.add_argument("--parcels", default="1000,10000,100000")
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--end-time", type=float, default=0.2,
                   help="simulated time, at least (see --parcel-seconds)")
    p.add_argument("--parcel-seconds", type=float, default=4000,
                   help="end time at least this over the parcels")
    p.add_argument("--mpi", type=int, default=1, choices=(0, 1),
                   help="also run the middle parcel count in two disjoint "
                   "boxes,\nserial and on 2 ranks, one box each (0: no)")
    p.add_argument("--baseline-lib", metavar="DIR",
                   help="also run variant rough-base: the rough model with "
                   "DIR's\nlibroughWallInteraction.so")
    p.add_argument("--lib-path", metavar="DIR", action="append", default=[],
                   help="DIR first on LD_LIBRARY_PATH for every variant")
    p.add_argument("--variant-lib-path", metavar="DIR", action="append",
                   default=[], help="also run standard.lib and rough.lib: "
                   "standard and rough\nwith DIR first on LD_LIBRARY_PATH")
    p.add_argument("--quick", action="store_true")
    p.add_argument("--callgrind", action="store_true",
                   help="only: instruction counts of a short run per variant")
    p.add_argument("--callgrind-parcels", type=int, default=2000)
    p.add_argument("--callgrind-end-time", type=float, default=0.05)
    p.add_argument("--profile", action="store_true",
                   help="only: perf profiles of the rough and standard runs")
    p.add_argument("--tutorial", action="store_true",
                   help="only (openfoam13): the tutorial's short case, "
                   "standard, smooth\nand rough2.5, alternated, serial")
    p.add_argument("--plot-only", action="store_true")
    args = p.parse_args()
    args.parcels = [int(float(x)) for x in args.parcels.split(",")]
    if args.quick:
        args.parcels, args.rounds, args.end_time = [500, 5000], 2, 0.05
        args.parcel_seconds = 0
        args.callgrind_parcels, args.callgrind_end_time = 500, 0.02
    bc.ensure_dirs()
    if args.tutorial:
        if args.platform != "openfoam13" and not args.plot_only:
            sys.exit("openfoamCost.py --tutorial: the tutorial is "
                     "OpenFOAM-13's (--platform openfoam13)")
        tutorial_cost(args)
        return
    if args.plot_only:
        plot_only(args)
        return
    if not args.platform:
        sys.exit("openfoamCost.py: --platform is needed (or --plot-only)")
    runner = Runner(args)
    runner.check_environment()
    if args.profile:
        profile(runner, args)
        return
    if args.callgrind:
        callgrind(runner, args)
        return
    info = bc.write_machine("openfoam-cost.%s" % runner.tag)
    print(bc.machine_markdown(info))
    measure(runner, args)
    args.tag = None
    plot_only(args)


if __name__ == "__main__":
    main()
