# roughWallInteraction benchmarks: the OpenFOAM cost benchmark, case set-up.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""The case of the OpenFOAM cost benchmark (openfoamCost.py): the
wall box (benchmarks/openfoam/wallBox, one box or two disjoint boxes), its
parcels, the variants and the libraries each loads, the exact count of
specular wall hits, the checks of the decomposition.
"""
import contextlib
import math
import os
import random
import re
import sys

from foamcase import bench as bc
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


#: The tutorial's variants compared: OpenFOAM alone (standardWallInteraction,
#: no spin models), the model with a smooth wall (roughnessAngle 0) and with
#: Delta = 2.5 deg (both with the library's spin models, as the tutorial
#: runs them)
TUTORIAL_VARIANTS = ("standard", "smooth", "rough2.5")


#: rough2.5 with --baseline-lib's library (the before of a before/after)
TUTORIAL_BASE = "rough2.5-base"


#: standard and rough2.5 with --variant-lib-path's libraries first
TUTORIAL_LIB_VARIANTS = ("standard.lib", "rough2.5.lib")
