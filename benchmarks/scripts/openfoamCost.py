#!/usr/bin/python3
# roughWallInteraction benchmarks: end-to-end cost of the rough-wall model in
# OpenFOAM against OpenFOAM's own standardWallInteraction.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""The same case, the same parcels and time steps, run with
  standard  standardWallInteraction (rebound, e = 1, mu = 0)
  rebound   roughWallInteraction, patch type rebound (e = 1, mu = 0):
            the adapter without the rough physics
  rough     roughWallInteraction, patch type rough (e = 1, mu0 = muD = 0,
            Delta = 8 deg): kinetic energy is kept, as in the smooth box
alternated round after round in one script (so that a drift of the machine
load hits every variant alike). Case: benchmarks/openfoam/wallBox, ballistic
parcels (no forces, no gravity, 110 um glass) in a closed 0.1 m box of 2x1x1
cells with maxCo 1, injected at (40 27 13) m/s, icoUncoupledKinematicParcelFoam
(colliding cloud: spin is carried), dt = 1 ms: about 0.8 wall hits per parcel
and time step, the most wall-dominated a particle case gets. Simulated time
0.2 s, or 4000 parcel-seconds over the parcels if that is longer (1000
parcels: 4 s), so that every run takes seconds.

Measured per run: the solver's CPU time for the time steps (the last
ExecutionTime minus the first: start-up and mesh reading excluded), the wall
clock of the whole process, and the wall hits (rough: the model's own count;
standard and rebound: counted exactly from the positions, the velocity and
the box, since specular reflection in a box is an unfolding; the parcels
travel end_time + dt, see specular_hits). Writes
benchmarks/results/openfoam-cost.csv, openfoam-cost.md and
docs/figures/bench-openfoam-scaling.png.

MPI (--mpi 1, the default, also with --quick): the middle parcel count in
a mesh of two identical, disjoint closed boxes (x in [0, 0.1] and
[0.2, 0.3], each 2x1x1 cells, every face a wall: checkMesh counts 2
regions), half the parcels injected in each box, run serial and decomposed
on 2 ranks (simple, n (2 1 1): each rank owns one box, no processor patch),
the six runs (1 and 2 ranks x standard, rebound, rough) alternated round by
round. No parcel ever crosses a processor boundary, so the 2-rank runs
measure the model's parallel behaviour (its per-processor statistics,
reduced in info() every time step, included) and not the parcel transfers
that dominated the single box cut in two (nearly one processor crossing per
wall hit). Checked before the timed runs: the decomposition (processor
faces, each processor's extent and parcels) and, in an untimed run on each
rank count of the rough model with roughnessAngle 0 (specular, and counting
its hits), the exact unfolded hit count and (2 ranks, a write at the end)
that each rank still holds the parcels of its box. Reported: rank 0's CPU
time of the steps, wall clock, hits, hits per second, rough/standard and
rebound/standard (paired rounds) on each rank count and the 1 -> 2 rank
speed-up per variant.

--tutorial: the tutorial's short case (horizontalChannel, 195 um, 4000
parcels, 1 s spin-up + 1 s, dt = 1 ms; --quick: 500 parcels, 0.2 s + 0.2 s)
with its smooth wall (standardWallInteraction) and rough2.5, set up as its
Allrun does (tutorialWorkPrecision.run_case), serial and decomposed on 2
ranks (--ranks) as Allrun -parallel N does (simple, n (N 1 1): streamwise
slabs), all alternated round by round. Each rank has its own random
generator, so the runs on several ranks differ from the serial one in
detail. Writes benchmarks/results/openfoam-tutorial-cost.csv and .md (CPU
and wall time, wall hits per second, rough/smooth ratios at each rank count,
speed-ups over the rank counts), then openfoam-tutorial-profile-<variant>.txt
(perf, serial runs).
"""
import argparse
import math
import os
import random
import re
import resource
import shutil
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchCommon as bc  # noqa: E402

TEMPLATE = os.path.join(bc.ROOT, "benchmarks", "openfoam", "wallBox")
SOLVER = "icoUncoupledKinematicParcelFoam"
L = 0.1
U0 = (40.0, 27.0, 13.0)
VARIANTS = ("standard", "rebound", "rough")
# x of the low corner of each box: the single box, and the two disjoint
# boxes of the MPI comparison (a gap of one box length between them)
ONE_BOX = (0.0,)
TWO_BOXES = (0.0, 2*L)
MESH_NAMES = {ONE_BOX: "box", TWO_BOXES: "twoBoxes"}


def sh(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as f:
        subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT,
                       check=True)


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


def make_case(work, parcels, np, end_time, seed=1, boxes=ONE_BOX):
    """A case directory for `parcels` parcels on `np` processors in the
    boxes (ONE_BOX: the template's; TWO_BOXES: two disjoint boxes, the
    first half of the parcels in the first, the second half in the second;
    the same seed gives the same parcels on every rank count)"""
    case = os.path.join(work, "%s-n%d-np%d" % (MESH_NAMES[boxes], parcels,
                                               np))
    if os.path.isdir(case):
        shutil.rmtree(case)
    shutil.copytree(TEMPLATE, case)
    rng = random.Random(seed)
    positions = []
    for k in range(parcels):
        x0 = boxes[k*len(boxes)//parcels]
        p = [0.005 + 0.09*rng.random() for _ in range(3)]
        positions.append((p[0] + x0, p[1], p[2]))
    with open(os.path.join(case, "constant", "positions"), "w") as f:
        f.write('FoamFile { version 2.0; format ascii; class vectorField; '
                'location "constant"; object positions; }\n')
        f.write("%d\n(\n" % parcels)
        for p in positions:
            f.write("(%.9f %.9f %.9f)\n" % p)
        f.write(")\n")
    control = os.path.join(case, "system", "controlDict")
    text = open(control).read()
    text = re.sub(r"\nendTime\s+[^;]+;", "\nendTime         %g;" % end_time,
                  text)
    open(control, "w").write(text)
    if boxes != ONE_BOX:
        with open(os.path.join(case, "system", "blockMeshDict"), "w") as f:
            f.write(block_mesh_dict(boxes))
    sh(["blockMesh"], case, "log.blockMesh")
    if boxes != ONE_BOX:
        # a mesh of several regions (checkMesh: "Number of regions: 2", a
        # note, not an error); it writes the region fields and sets, which
        # the case does not need
        sh(["checkMesh"], case, "log.checkMesh")
        regions = re.findall(r"Number of regions: (\d+)",
                             open(os.path.join(case, "log.checkMesh")).read())
        if regions != [str(len(boxes))]:
            sys.exit("%s: checkMesh reports %s regions, not %d"
                     % (case, regions, len(boxes)))
        shutil.rmtree(os.path.join(case, "constant", "polyMesh", "sets"),
                      ignore_errors=True)
        for f in ("cellToRegion", "cellToRegion.gz"):
            if os.path.exists(os.path.join(case, "0", f)):
                os.remove(os.path.join(case, "0", f))
    if np > 1:
        sh(["decomposePar", "-force"], case, "log.decomposePar")
    return case, positions


def box_of(p, boxes):
    """The low corner x of the box of boxes that holds position p"""
    for x0 in boxes:
        if x0 <= p[0] <= x0 + L:
            return x0
    raise ValueError("position %s in none of the boxes %s" % (p, boxes))


def delta_t():
    """The template's time step"""
    text = open(os.path.join(TEMPLATE, "system", "controlDict")).read()
    return float(re.search(r"\ndeltaT\s+([^;]+);", text).group(1))


def specular_hits(positions, end_time, boxes=ONE_BOX):
    """Wall hits of specular parcels in the boxes [x0, x0 + L] x [0, L]^2
    up to end_time: in its own box's coordinates, a parcel's unfolded
    straight path crosses floor(q_i/L) planes i = c L, q = p - (x0, 0, 0) +
    U0 t (U0 > 0); the boxes are disjoint, so each parcel stays in its box.
    The parcels travel end_time + deltaT: manualInjection injects at once
    (timeEnd = SOI + ROOTVSMALL), so in the first step InjectionModel::inject
    moves each new parcel by the whole step (time - timeInj = deltaT) before
    the cloud's own move of that step (checked: roughWallInteraction with
    roughnessAngle 0 counts exactly this, see check_two_boxes)"""
    travel = end_time + delta_t()
    hits = 0
    for p in positions:
        q = (p[0] - box_of(p, boxes), p[1], p[2])
        hits += sum(int(math.floor((q[i] + U0[i]*travel)/L))
                    for i in range(3))
    return hits


def foam_list_size(path):
    """The size of the top-level list of an OpenFOAM field file, ASCII or
    binary (the size and the opening bracket are text in both)"""
    data = open(path, "rb").read()
    header = data.index(b"FoamFile")
    body = data[data.index(b"}", header) + 1:]
    m = re.search(rb"^\s*(\d+)\s*[({]", re.sub(rb"//[^\n]*", b"", body[:4096]),
                  re.M)
    return int(m.group(1))


def read_points(path):
    """polyMesh/points, ASCII or binary (label 32, scalar 64): (x, y, z)
    tuples"""
    import struct
    data = open(path, "rb").read()
    header = data.index(b"FoamFile")
    close = data.index(b"}", header) + 1
    binary = b"binary" in data[header:close]
    m = re.compile(rb"^(\d+)\s*\(", re.M).search(data, close)
    n, start = int(m.group(1)), m.end()
    if binary:
        v = struct.unpack("<%dd" % (3*n), data[start:start + 24*n])
    else:
        v = [float(x) for x in data[start:data.index(b"\n)", start)]
             .replace(b"(", b" ").replace(b")", b" ").split()]
    return [tuple(v[3*i:3*i + 3]) for i in range(n)]


def check_boxes(case, nprocs, positions, boxes):
    """The decomposition of the two-box case: each processor owns the cells
    of exactly one box (its points' x extent is that box's), no processor
    faces (decomposePar's count and the processor boundary files) and how
    many of the parcels start on each. Returns (ok, description)"""
    log = open(os.path.join(case, "log.decomposePar")).read()
    proc_faces = re.findall(r"\nNumber of processor faces = (\d+)", log)
    ok = proc_faces == ["0"]
    parts = []
    owned = set()
    for i in range(nprocs):
        polymesh = os.path.join(case, "processor%d" % i, "constant",
                                "polyMesh")
        xs = [p[0] for p in read_points(os.path.join(polymesh, "points"))]
        x0, x1 = min(xs), max(xs)
        box = [b for b in boxes if abs(b - x0) < 1e-9 and
               abs(b + L - x1) < 1e-9]
        n = sum(1 for p in positions if x0 <= p[0] <= x1)
        processor_patches = len(re.findall(
            r"type\s+processor",
            open(os.path.join(polymesh, "boundary")).read()))
        ok = ok and len(box) == 1 and box[0] not in owned \
            and processor_patches == 0
        owned.update(box)
        parts.append("processor%d x %.3g-%.3g, %d parcels, %d processor "
                     "patches" % (i, x0, x1, n, processor_patches))
    ok = ok and len(owned) == len(boxes)
    return ok, "%s: processor faces %s; %s" % (
        "one box per rank" if ok else "NOT one box per rank",
        "/".join(proc_faces) or "?", "; ".join(parts))


def check_two_boxes(case, nprocs, positions, end_time, boxes):
    """One more run (not timed) of a copy of the case on nprocs ranks, the
    rough model with roughnessAngle 0 (specular, and it counts its hits) and
    a write at the last step: the model's hit count against
    specular_hits, and (nprocs > 1) each processor's parcels at the end
    against the parcels that started in its box. Returns (ok,
    description)"""
    check = case + "-check"
    if os.path.isdir(check):
        shutil.rmtree(check)
    shutil.copytree(case, check)
    control = os.path.join(check, "system", "controlDict")
    text = open(control).read()
    text = re.sub(r"\nwriteInterval\s+[^;]+;", "\nwriteInterval   %d;"
                  % int(round(end_time/delta_t())), text)
    open(control, "w").write(text)
    model = os.path.join(check, "constant", "wallModel.")
    text = open(model + "rough").read()
    text, n = re.subn(r"roughnessAngle\s+[^;]+;", "roughnessAngle  0;", text)
    assert n == 1
    open(model + "specular", "w").write(text)
    hits = run(check, "specular", nprocs)["hits"]
    exact = specular_hits(positions, end_time, boxes)
    ok = hits == exact
    out = ["hits with roughnessAngle 0: %d, unfolding: %d%s" % (
        hits, exact, "" if ok else " (DIFFERENT)")]
    if nprocs > 1:
        counts, starts = [], []
        for i in range(nprocs):
            proc = os.path.join(check, "processor%d" % i)
            last = max((d for d in os.listdir(proc)
                        if re.match(r"^[0-9.eE+-]+$", d) and float(d) > 0),
                       key=float)
            counts.append(foam_list_size(os.path.join(
                proc, last, "lagrangian", "kinematicCloud", "positions")))
            xs = [p[0] for p in read_points(os.path.join(
                proc, "constant", "polyMesh", "points"))]
            starts.append(sum(1 for p in positions
                              if min(xs) <= p[0] <= max(xs)))
        ok = ok and counts == starts
        out.append("parcels per rank at t = %s: %s, started in its box: "
                   "%s%s" % (last, "/".join(map(str, counts)),
                             "/".join(map(str, starts)),
                             " (no transfers)" if counts == starts
                             else " (PARCELS CHANGED RANK)"))
    shutil.rmtree(check)
    return ok, "; ".join(out)


def run(case, variant, np):
    shutil.copy(os.path.join(case, "constant", "wallModel." + variant),
                os.path.join(case, "constant", "wallModel"))
    if np > 1:
        # processor directories read constant/ from the case
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np",
               str(np), SOLVER, "-parallel"]
    else:
        cmd = [SOLVER]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    sh(cmd, case, "log.%s" % variant)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime
                                                - before.ru_stime)
    log = open(os.path.join(case, "log.%s" % variant)).read()
    exec_times = [float(x) for x in
                  re.findall(r"ExecutionTime = ([0-9.eE+-]+) s", log)]
    hits = re.findall(r"- hits\s+= (\d+)", log)
    return dict(step_cpu=exec_times[-1] - exec_times[0], wall=wall,
                process_cpu=cpu, hits=int(hits[-1]) if hits else None)


def profile(args):
    """perf (software clock) profiles of the rough and the standard run of
    the middle parcel count: where the extra time of the rough wall goes"""
    if not shutil.which("perf"):
        print("perf not found: no profile")
        return
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    parcels = args.parcels[min(1, len(args.parcels) - 1)]
    case, _ = make_case(work, parcels, 1, args.end_time)
    for variant in ("rough", "standard"):
        shutil.copy(os.path.join(case, "constant", "wallModel." + variant),
                    os.path.join(case, "constant", "wallModel"))
        data = os.path.join(case, "perf.%s.data" % variant)
        sh(["perf", "record", "-e", "cpu-clock", "-F", "2000", "-o", data,
            SOLVER], case, "log.perf." + variant)
        out = []
        for sort in ("dso", "sym"):
            out.append(subprocess.run(
                ["perf", "report", "-i", data, "--stdio", "--no-children",
                 "--sort", sort, "--percent-limit", "0.5"],
                capture_output=True, text=True).stdout)
        path = os.path.join(bc.RESULTS, "openfoam-profile-%s.txt" % variant)
        with open(path, "w") as f:
            f.write("# perf record -e cpu-clock %s, %d parcels, %s\n"
                    % (SOLVER, parcels, variant))
            f.write("\n".join(out))
        print("wrote " + path)


TUTORIAL_VARIANTS = ("smooth", "rough2.5")
TUTORIAL_CSV = os.path.join(bc.RESULTS, "openfoam-tutorial-cost.csv")


def mesh_box(points_path):
    """(xmin, xmax, ymin, ymax) of a polyMesh/points file"""
    from foamio import read_list    # the tutorial's scripts/ (tw.prepare)
    p = read_list(points_path)
    return (float(p[:, 0].min()), float(p[:, 0].max()),
            float(p[:, 1].min()), float(p[:, 1].max()))


def check_slabs(case, nprocs):
    """The decomposition of a case: each processor's extent. The tutorial's
    (Allrun -parallel N, particles/system/decomposeParDict) is method
    simple with n (N 1 1): N streamwise slabs, each the full channel height,
    so that the load is balanced whatever the wall model does to the
    parcels' heights (smooth walls: all on the floor). Returns (streamwise,
    description)."""
    whole = mesh_box(os.path.join(case, "constant", "polyMesh", "points"))
    boxes = [mesh_box(os.path.join(case, "processor%d" % i, "constant",
                                   "polyMesh", "points"))
             for i in range(nprocs)]
    tol = 1e-6*(whole[3] - whole[2])
    streamwise = all(abs(b[2] - whole[2]) < tol and abs(b[3] - whole[3]) < tol
                     and b[1] - b[0] < whole[1] - whole[0] - tol
                     for b in boxes)
    return streamwise, "%s: %s" % (
        "streamwise slabs" if streamwise else "NOT streamwise slabs",
        ", ".join("x %.3g-%.3g y %.3g-%.3g" % b for b in boxes))


def tutorial_measure(args):
    """Rounds of smooth and rough2.5 at each rank count of args.ranks, the
    order reversed every other round; returns the rows"""
    import tutorialWorkPrecision as tw
    if "WM_PROJECT_DIR" not in os.environ:
        sys.exit("openfoamCost.py: source etc/setup first")
    bc.write_machine("openfoam-tutorial-cost")
    work = os.path.abspath(os.path.join(args.work, "tutorial"))
    os.makedirs(work, exist_ok=True)
    tut, carrier_time, height = tw.prepare(work)
    parcels, spin_up, end_time = (500, 0.2, 0.4) if args.quick \
        else (4000, 1.0, 2.0)
    runs = [(n, v) for n in args.ranks for v in TUTORIAL_VARIANTS]
    slabs = {}
    rows = []
    for rnd in range(args.rounds):
        for n, variant in (runs if rnd % 2 == 0 else runs[::-1]):
            name = "cost-%s-np%d" % (variant, n)
            wall, _, summary, _ = tw.run_case(
                tut, carrier_time, height, name, variant, 195e-6, parcels,
                spin_up, end_time, 1e-3, nprocs=n)
            case = os.path.join(tut, "run", name)
            # rank 0's log; the model's counts in it are reduced over the
            # processors (roughWallStatistics::reduced)
            log = open(os.path.join(case, "log." + SOLVER)).read()
            exec_times = [float(x) for x in re.findall(
                r"ExecutionTime = ([0-9.eE+-]+) s", log)]
            hits = sum(int(h) for h in re.findall(
                r"- hits\s+= (\d+)", log.split("ExecutionTime")[-2]))
            info = dict(line.split(None, 1) for line in open(
                os.path.join(case, "caseInfo")).read().splitlines()
                if line.strip())
            x0, x1, _, _ = mesh_box(os.path.join(case, "constant", "polyMesh",
                                                 "points"))
            if n > 1 and n not in slabs:
                slabs[n] = check_slabs(case, n)
                print("decomposition on %d ranks: %s" % (n, slabs[n][1]))
                if not slabs[n][0]:
                    print("WARNING: the slabs are not streamwise")
            ux = abs(float(summary["meanUx"]))
            row = dict(
                round=rnd, variant=variant, ranks=n, parcels=parcels,
                end_time=end_time, wall="%.2f" % wall,
                step_cpu="%.2f" % (exec_times[-1] - exec_times[0]),
                process_cpu=info["processCpu"].strip(), model_hits=hits,
                hits_per_parcel_s="%.2f" % (hits/(parcels*end_time)),
                # N slab boundaries per period (one of them on the cyclic
                # patch): a parcel at the mean Ux crosses N Ux/Lx a second
                crossings_per_parcel_s="%.1f" % (n*ux/(x1 - x0))
                if n > 1 else "0",
                meanUx="%.3f" % ux, upperFraction=summary["upperFraction"],
                decomposition=slabs[n][1] if n > 1 else "serial",
                load=open("/proc/loadavg").read().split()[0])
            rows.append(row)
            print(row, flush=True)
    bc.write_csv(TUTORIAL_CSV, rows)
    return rows, tut


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


def tutorial_table(rows):
    """Medians per variant and rank count, the paired rough/smooth ratios
    and the speed-ups over the rank counts, per round"""
    for r in rows:                      # a CSV from before the MPI runs
        r.setdefault("ranks", "1")
    ranks = sorted({int(r["ranks"]) for r in rows})
    variants = [v for v in TUTORIAL_VARIANTS
                if any(r["variant"] == v for r in rows)]
    rounds = sorted({int(r["round"]) for r in rows})

    def of(variant, n, key):
        return [float(r[key]) for r in rows if r["variant"] == variant
                and int(r["ranks"]) == n and r.get(key, "") not in ("", None)]

    def paired(key, a, b):
        return paired_ratios(rows, "ranks", key, a, b)

    def med(variant, n, key):
        v = of(variant, n, key)
        return statistics.median(v) if v else float("nan")

    r0 = rows[0]
    loads = [float(r["load"]) for r in rows]
    text = ["Tutorial horizontalChannel (195 um, %s parcels, %s s with the "
            "first half spin-up, dt = 1 ms), smooth (standardWallInteraction) "
            "and rough2.5, on %s MPI rank(s), %d rounds, the order reversed "
            "every other round; load average %.1f-%.1f." % (
                r0["parcels"], r0["end_time"],
                ", ".join(str(n) for n in ranks), len(rounds), min(loads),
                max(loads))]
    for n in ranks[1:]:
        d = [r.get("decomposition", "") for r in rows if int(r["ranks"]) == n]
        text.append("\nDecomposition on %d ranks (the tutorial's: simple, "
                    "n (%d 1 1)): %s." % (n, n, d[0] if d and d[0] else "?"))
    text += ["", "| variant | MPI ranks | runs | CPU of the time steps, rank 0 "
             "[s] | wall clock of the solver [s] | CPU of all processes [s] "
             "| wall hits (model) | hits per CPU s (rank 0) | hits per wall "
             "s | hits per parcel s | processor crossings per parcel s "
             "(estimate) |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for v in variants:
        for n in ranks:
            cpu, wall = med(v, n, "step_cpu"), med(v, n, "wall")
            hits = of(v, n, "model_hits")
            h = statistics.median(hits) if hits and max(hits) > 0 else None
            cross = of(v, n, "crossings_per_parcel_s")
            text.append("| %s | %d | %d | %.2f | %.2f | %.2f | %s | %s | %s | "
                        "%s | %s |" % (
                            v, n, len(of(v, n, "step_cpu")), cpu, wall,
                            med(v, n, "process_cpu"),
                            "%d" % h if h else "(not counted)",
                            "%.0f" % (h/cpu) if h else "-",
                            "%.0f" % (h/wall) if h else "-",
                            "%.1f" % (h/(float(r0["parcels"])
                                         * float(r0["end_time"])))
                            if h else "-",
                            "%.0f" % statistics.median(cross) if cross
                            else "-"))
    if len(variants) == 2:
        a, b = variants[1], variants[0]
        text += ["", "| MPI ranks | %s/%s, CPU of the time steps: median of "
                 "the paired rounds (range) | %s/%s, wall clock |" % (
                     a, b, a, b), "|---|---|---|"]
        for n in ranks:
            text.append("| %d | %s | %s |" % (
                n, median_range(paired("step_cpu", (a, n), (b, n))),
                median_range(paired("wall", (a, n), (b, n)))))
    if len(ranks) > 1:
        n1 = ranks[0]
        text += ["", "| variant | ranks | speed-up from %d rank(s), CPU of the "
                 "time steps (rank 0): median of the rounds (range) | "
                 "speed-up, wall clock | parallel efficiency (CPU of the "
                 "steps) |" % n1, "|---|---|---|---|---|"]
        text += speedup_rows(variants, ranks, paired)
    text += ["", "CPU of the time steps: rank 0's last ExecutionTime minus "
             "its first (start-up excluded; OpenMPI polls while it waits, so "
             "on several ranks this is about the elapsed time of the steps). "
             "Wall clock: the solver's process (mpirun and start-up "
             "included). CPU of all processes: getrusage of the solver, all "
             "ranks and mpirun. Hits: the rough model's count at the end, "
             "reduced over the processors (standardWallInteraction counts "
             "none). Processor crossings: N slab boundaries per streamwise "
             "period Lx, N |mean Ux|/Lx per parcel and second (mean Ux of "
             "the sampled parcels)."]
    text = "\n".join(text) + "\n"
    with open(os.path.join(bc.RESULTS, "openfoam-tutorial-cost.md"),
              "w") as f:
        f.write(text)
    print(text)


def tutorial_profile(tut):
    """perf profiles of one more serial run of each variant (the cases of
    the last round): the model's own share of the run"""
    if not shutil.which("perf"):
        print("perf not found: no tutorial profile")
        return
    for variant in TUTORIAL_VARIANTS[::-1]:
        case = os.path.join(tut, "run", "cost-%s-np1" % variant)
        if not os.path.isdir(case):
            continue
        info = dict(line.split(None, 1) for line in open(
            os.path.join(case, "caseInfo")).read().splitlines()
            if line.strip())
        data = os.path.join(case, "perf.data")
        try:
            sh(["perf", "record", "-e", "cpu-clock", "-F", "1000", "-o",
                data, SOLVER], case, "log.perf")
        except subprocess.CalledProcessError:
            print("perf record failed (see %s/log.perf): no profile" % case)
            return
        out = [subprocess.run(
            ["perf", "report", "-i", data, "--stdio", "--no-children",
             "--sort", sort, "--percent-limit", "0.3"],
            capture_output=True, text=True).stdout for sort in ("dso", "sym")]
        path = os.path.join(bc.RESULTS,
                            "openfoam-tutorial-profile-%s.txt" % variant)
        with open(path, "w") as f:
            f.write("# perf record -e cpu-clock %s: tutorial, %s, %s "
                    "parcels, %s s, serial\n" % (
                        SOLVER, variant, info["nParcels"].strip(),
                        info["endTime"].strip()))
            f.write("\n".join(out))
        print("wrote " + path)


def tutorial_cost(args):
    """The tutorial's short case with the smooth (standardWallInteraction)
    and a rough wall model, same parcels and time steps, alternated, serial
    and on MPI ranks (--ranks); then perf profiles of the serial runs"""
    if args.plot_only:
        tutorial_table(bc.read_csv(TUTORIAL_CSV))
        return
    rows, tut = tutorial_measure(args)
    tutorial_table(rows)
    tutorial_profile(tut)


def measure(args):
    """Rounds of the variants in each configuration, the order reversed
    every other round: the single box at each parcel count (serial), then
    (--mpi) the two disjoint boxes with the middle parcel count on 1 and 2
    ranks, the six runs of a round alternated together"""
    work = os.path.abspath(args.work)
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
            cases[np], positions = make_case(work, parcels, np, end_time,
                                             boxes=boxes)
            if boxes == ONE_BOX:
                continue
            ok, text = check_two_boxes(cases[np], np, positions, end_time,
                                       boxes)
            if np > 1:
                ok2, text2 = check_boxes(cases[np], np, positions, boxes)
                ok, text = ok and ok2, "%s; %s" % (text2, text)
            checks[np] = text
            print("two boxes on %d rank(s): %s" % (np, text), flush=True)
            if not ok:
                sys.exit("openfoamCost.py: the two-box case on %d rank(s) "
                         "fails its check (one box per rank, no transfers, "
                         "exact specular hits)" % np)
        smooth_hits = specular_hits(positions, end_time, boxes)
        runs = [(np, v) for np in ranks for v in VARIANTS]
        for rnd in range(args.rounds):
            for np, variant in (runs if rnd % 2 == 0 else runs[::-1]):
                r = run(cases[np], variant, np)
                hits = r["hits"] if variant == "rough" else smooth_hits
                row = dict(mesh=MESH_NAMES[boxes], parcels=parcels, np=np,
                           round=rnd, variant=variant, end_time=end_time,
                           hits=hits, step_cpu="%.3f" % r["step_cpu"],
                           wall="%.3f" % r["wall"],
                           process_cpu="%.3f" % r["process_cpu"],
                           load=open("/proc/loadavg").read().split()[0],
                           check=checks.get(np, ""))
                rows.append(row)
                print(row, flush=True)
    bc.write_csv("openfoam-cost.csv", rows)


def load():
    rows = bc.read_csv("openfoam-cost.csv")
    for r in rows:                      # a CSV from before the two boxes
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
        for v in VARIANTS:
            vs = [r for r in rs if r["variant"] == v]
            if not vs:
                continue
            med[v] = dict(
                step_cpu=statistics.median(float(r["step_cpu"]) for r in vs),
                wall=statistics.median(float(r["wall"]) for r in vs),
                hits=statistics.median(int(r["hits"]) for r in vs))
        rounds = sorted({r["round"] for r in rs})
        ratios, ratios_rebound = [], []
        for rnd in rounds:
            t = {r["variant"]: float(r["step_cpu"]) for r in rs
                 if r["round"] == rnd}
            if t.get("standard", 0) > 0:
                ratios.append(t["rough"]/t["standard"])
                ratios_rebound.append(t["rebound"]/t["standard"])
        out.append(dict(mesh=mesh, parcels=parcels, np=np, med=med,
                        rounds=len(rounds),
                        end_time=float(rs[0].get("end_time", "nan")),
                        ratio=statistics.median(ratios),
                        ratio_min=min(ratios), ratio_max=max(ratios),
                        ratio_rebound=statistics.median(ratios_rebound)))
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

    def of(variant, n, key):
        return [float(r[key]) for r in rows if r["variant"] == variant
                and int(r["np"]) == n]

    def paired(key, a, b):
        return paired_ratios(rows, "np", key, a, b)

    r0 = rows[0]
    parcels = int(r0["parcels"])
    loads = [float(r["load"]) for r in rows]
    text = ["", "MPI: two identical, disjoint closed boxes (x in [0, %g] and "
            "[%g, %g] m, each 2x1x1 cells, all faces walls; checkMesh: %d "
            "regions), %d parcels, the first %d in the first box and the "
            "rest in the second, %g s simulated, dt = 1 ms, the same parcels "
            "and time steps on every rank count; %d rounds of the six runs "
            "(%s ranks x %s), the order reversed every other round; load "
            "average %.1f-%.1f. Checks: an untimed run on each rank count "
            "with roughnessAngle 0 (specular) must count exactly the unfolded "
            "hits; on 2 ranks no processor faces, each processor's mesh one "
            "box, and each rank's parcels at the end those injected into "
            "its box." % (
                L, TWO_BOXES[1], TWO_BOXES[1] + L, len(TWO_BOXES), parcels,
                parcels//2, float(r0["end_time"]), len(rounds),
                "/".join(map(str, ranks)), "/".join(VARIANTS), min(loads),
                max(loads))]
    for n in ranks:
        d = [r["check"] for r in rows if int(r["np"]) == n]
        text.append("\nCheck on %d rank(s)%s: %s." % (
            n, " (simple, n (%d 1 1))" % n if n > 1 else "",
            d[0] if d and d[0] else "?"))
    text += ["", "| variant | MPI ranks | runs | CPU of the time steps, rank "
             "0 [s] | wall clock [s] | CPU of all processes [s] | wall hits "
             "| hits per CPU s (rank 0) [M/s] | hits per wall s [M/s] |",
             "|---|---|---|---|---|---|---|---|---|"]
    for v in VARIANTS:
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
                           "" if v == "rough" else " (exact)",
                           "%.2f" % (h/c/1e6) if c > 0 else "-",
                           h/w/1e6))
    text += ["", "| MPI ranks | rough/standard, CPU of the steps: median of "
             "the paired rounds (range) | rebound/standard, CPU | "
             "rough/standard, wall clock | rebound/standard, wall clock |",
             "|---|---|---|---|---|"]
    for n in ranks:
        text.append("| %d | %s | %s | %s | %s |" % (
            n, median_range(paired("step_cpu", ("rough", n),
                                   ("standard", n))),
            median_range(paired("step_cpu", ("rebound", n),
                                ("standard", n))),
            median_range(paired("wall", ("rough", n), ("standard", n))),
            median_range(paired("wall", ("rebound", n), ("standard", n)))))
    if len(ranks) > 1:
        text += ["", "| variant | ranks | speed-up, CPU of the time steps "
                 "(rank 0): median of the paired rounds (range) | speed-up, "
                 "wall clock | parallel efficiency (CPU of the steps) |",
                 "|---|---|---|---|---|"]
        text += speedup_rows(VARIANTS, ranks, paired)
    text += ["", "CPU of the time steps: rank 0's last ExecutionTime minus "
             "its first (start-up and mesh reading excluded; OpenMPI polls "
             "while it waits, so on 2 ranks this is about the elapsed time "
             "of the steps, and rank 0 tracks half the parcels). Wall clock: "
             "the solver's process (mpirun and start-up included). CPU of "
             "all processes: getrusage of the solver, all ranks and mpirun. "
             "Hits: standard and rebound counted exactly by unfolding each "
             "parcel's path in its own box, rough the model's count at the "
             "end, reduced over the processors. Ranges: min-max over the "
             "runs or the paired rounds."]
    return text


def table(summary, rows=()):
    lines = ["| parcels | simulated s | MPI ranks | rounds | standard: CPU s, hits, Mhits/s"
             " | rebound: CPU s | rough: CPU s, hits, Mhits/s | rough/standard"
             " CPU (median, min-max of rounds) | rebound/standard | rough - "
             "standard per hit [ns] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for s in summary:
        if s["mesh"] != "box":
            continue
        m = s["med"]
        st, rb, ro = m["standard"], m["rebound"], m["rough"]
        extra = (ro["step_cpu"]/ro["hits"] - st["step_cpu"]/st["hits"])*1e9
        lines.append(
            "| %d | %g | %d | %d | %.2f, %d, %.2f | %.2f | %.2f, %d, %.2f | "
            "%.3f (%.3f-%.3f) | %.3f | %.0f |" % (
                s["parcels"], s["end_time"], s["np"], s["rounds"],
                st["step_cpu"],
                st["hits"], st["hits"]/st["step_cpu"]/1e6, rb["step_cpu"],
                ro["step_cpu"], ro["hits"], ro["hits"]/ro["step_cpu"]/1e6,
                s["ratio"], s["ratio_min"], s["ratio_max"],
                s["ratio_rebound"], extra))
    lines += two_box_table(rows)
    text = "\n".join(lines) + "\n"
    with open(os.path.join(bc.RESULTS, "openfoam-cost.md"), "w") as f:
        f.write(text)
    print(text)


def figure(summary):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    serial = [s for s in summary if s["np"] == 1 and s["mesh"] == "box"]
    others = [s for s in summary if s not in serial]
    marker = {("twoBoxes", 1): "D", ("twoBoxes", 2): "s", ("box", 2): "v"}
    # the two-box points a little apart, each side of their parcel count
    shift = {("twoBoxes", 1): 0.94, ("twoBoxes", 2): 1.06}
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    n = [s["parcels"] for s in serial]
    for v, c in zip(VARIANTS, ("k", "C1", "C0")):
        axes[0].loglog(n, [s["med"][v]["hits"]/s["med"][v]["step_cpu"]
                           for s in serial], "o-", color=c, label=v)
    for s in others:
        for v, c in zip(VARIANTS, ("k", "C1", "C0")):
            axes[0].plot(s["parcels"]*shift.get((s["mesh"], s["np"]), 1),
                         s["med"][v]["hits"]
                         / s["med"][v]["step_cpu"],
                         marker.get((s["mesh"], s["np"]), "x"), mfc="none",
                         color=c, ms=9)
    axes[0].set_xlabel("parcels")
    axes[0].set_ylabel("wall hits per CPU second")
    axes[0].set_title("throughput; two disjoint boxes: diamonds 1 rank,\n"
                      "squares 2 ranks (per second of rank 0's CPU time,\n"
                      "about elapsed: MPI polls)", fontsize=9)
    axes[0].legend(fontsize=8)
    axes[0].grid(True, which="both", alpha=0.3)
    axes[1].errorbar(n, [s["ratio"] for s in serial],
                     yerr=[[s["ratio"] - s["ratio_min"] for s in serial],
                           [s["ratio_max"] - s["ratio"] for s in serial]],
                     fmt="o-", color="C0", capsize=3,
                     label="rough / standard (bars: min-max of rounds)")
    axes[1].set_xscale("log")
    axes[1].semilogx(n, [s["ratio_rebound"] for s in serial], "o-",
                     color="C1", label="rebound (adapter) / standard")
    for s in others:
        m = marker.get((s["mesh"], s["np"]), "x")
        x = s["parcels"]*shift.get((s["mesh"], s["np"]), 1)
        axes[1].errorbar(x, s["ratio"],
                         yerr=[[s["ratio"] - s["ratio_min"]],
                               [s["ratio_max"] - s["ratio"]]],
                         fmt=m, mfc="none", color="C0", capsize=3, ms=8)
        axes[1].plot(x, s["ratio_rebound"], m, mfc="none",
                     color="C1", ms=8)
    axes[1].axhline(1.05, color="r", lw=1, label="target +5 %")
    axes[1].set_xlabel("parcels")
    axes[1].set_ylabel("CPU time ratio (paired rounds, median)")
    axes[1].set_title("two disjoint boxes: diamonds 1 rank, squares 2 ranks",
                      fontsize=9)
    axes[1].legend(fontsize=8)
    axes[1].grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    path = os.path.join(bc.FIGURES, "bench-openfoam-scaling.png")
    fig.savefig(path, dpi=110)
    print("wrote " + path)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
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
                   "boxes,\nserial and on 2 ranks, one box each (0: no; "
                   "--quick too)")
    p.add_argument("--quick", action="store_true")
    p.add_argument("--profile", action="store_true",
                   help="only: perf profiles of the rough and standard runs")
    p.add_argument("--tutorial", action="store_true",
                   help="only: the tutorial's short case, smooth against "
                   "rough2.5, alternated,\non each of --ranks MPI ranks, "
                   "then perf profiles of the serial runs")
    p.add_argument("--ranks", default="1,2",
                   help="--tutorial: MPI rank counts (default 1,2)")
    p.add_argument("--plot-only", action="store_true")
    args = p.parse_args()
    args.parcels = [int(float(x)) for x in args.parcels.split(",")]
    args.ranks = sorted({int(x) for x in args.ranks.split(",")})
    if args.quick:
        args.parcels, args.rounds, args.end_time = [500, 5000], 2, 0.05
        args.parcel_seconds = 0
    bc.ensure_dirs()
    if args.profile:
        profile(args)
        return
    if args.tutorial:
        tutorial_cost(args)
        return
    if not args.plot_only:
        if "WM_PROJECT_DIR" not in os.environ:
            sys.exit("openfoamCost.py: source etc/setup first")
        info = bc.write_machine("openfoam-cost")
        print(bc.machine_markdown(info))
        measure(args)
    rows = load()
    summary = summarise(rows)
    table(summary, rows)
    figure(summary)


if __name__ == "__main__":
    main()
