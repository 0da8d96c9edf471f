#!/usr/bin/env python3
"""The tutorial incompressibleFluid/hopperParticles of OpenFOAM-13 or -14
(the release the test runs on) with roughWallInteraction, on 2 ranks.

The tutorial (two stages: hopperInitialState fills a hopper with 3300
parcels of 6 mm, a collidingCloud with pairCollision and the wall model
wallLocalSpringSliderDashpot; hopperEmptying opens the hopper and lets them
fall out) is copied at test time from $WM_PROJECT_DIR/tutorials (the
project does not commit OpenFOAM's case files) into <work>/hopperParticles
and changed only in:

  - system/controlDict: libs ("libroughWallInteraction.so"); endTime
    0.05 s and 0.13 s instead of 0.25 s and 5 s (writeInterval = endTime);
  - system/decomposeParDict: 2 subdomains (simple, (2 1 1));
  - constant/cloudPositions: only the lowest 6 rows of the 3300 positions
    (276 parcels, --rows).  The collision model sub-cycles 4 to 18 times
    per time step: measured on the shared 2-core machine, ~80 ms of CPU
    per step for all 3300 parcels on 2 ranks (~10-20 ms for 276 in
    serial), and a parcel needs 0.155 s (3100 steps) to fall from the
    hopper out through the outlet;
  - system/blockMeshDict: the patch `walls` (the hopper's side walls and
    slopes) is of type `patch` instead of `wall`, and
    constant/cloudProperties drops its entry of the wall model
    (wallLocalSpringSliderDashpotCoeffs.walls).  OpenFOAM-13's pairCollision
    applies its wall model to every wall-type patch (InteractionLists.C,
    WallLocalSpringSliderDashpot.C: isA<wallPolyPatch>) and pushes a parcel
    back when the wall is closer than its radius; the patch interaction
    model is only called when the parcel's centre reaches a boundary face
    (particle::hitFace -> MomentumParcel::hitPatch).  With the tutorial's
    wall-type `walls` roughWallInteraction never sees a hit there (the
    control run shows it).  frontAndBack (the two plates 6.2 mm apart)
    stays a wall of the wall model, as in the tutorial;
  - constant/cloudProperties: patchInteractionModel roughWallInteraction:
    walls and frontAndBack rough (e 0.8, mu0 0.3, roughnessAngle 5),
    inlet and outlet (hopperEmptying) escape.

Both stages run as the tutorial's Allrun: blockMesh, decomposePar,
mpirun -np 2 foamRun -parallel, reconstructPar; hopperEmptying maps the
parcels with mpirun -np 2 mapFieldsPar ../hopperInitialState -sourceTime
latestTime -parallel before its foamRun.

Checks: every step ends well (exit status 0, "End", no "FOAM FATAL");
parcels are conserved in each stage: injected (hopperInitialState: entries
of cloudPositions = the log's "Added N new parcels" = the injector's
"number of parcels added") or mapped (hopperEmptying: the parcels of time 0
on all processors = mapFieldsPar's "mapped N parcels" = the parcels of
hopperInitialState's last time) equal the parcels in every processor's
lagrangian output of the last time + the escaped ones (the sum of the
<patch>_nEscape columns of the last row of the statistics file
postProcessing/lagrangian/cloud/patchInteractionModel/0/
roughWallInteraction.dat);
in hopperEmptying mass too (<patch>_massEscape); the log's last cloud
report and the reconstructed case agree; the rough walls were hit
(walls_hits > 0) and parcels left through the outlet (outlet_nEscape > 0);
the running foamRun processes mapped no OpenFOAM library from /usr/lib
(Debian's v1912), read from /proc/<pid>/maps, and ldd of foamRun and of the
loaded libroughWallInteraction.so and liblagrangianParcel.so resolves none
there.  Control (serial, --no-control skips it): hopperInitialState with
the tutorial's wall-type `walls`, same settings: walls_hits = 0.

Usage: testHopperParticles.py [--platform openfoam13|openfoam14] [--work DIR]
           [--rows N] [--endTime1 T] [--endTime2 T] [--no-control]
Run it in the release's environment, as ctest does:
    etc/openfoamEnv openfoam13 /usr/bin/python3 testHopperParticles.py
        --platform openfoam13 --work DIR

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import glob
import math
import os
import re
import shutil
import subprocess
import sys
import textwrap
import time

import numpy as np

sys.dont_write_bytecode = True

from foamcase import testing as t
import foamcase as fc
from foamcase.testConstants import parcel_mass

#: The tutorial, relative to $WM_PROJECT_DIR
TUTORIAL = os.path.join("tutorials", "incompressibleFluid", "hopperParticles")

#: The cloud of the tutorial (constant/cloudProperties)
CLOUD = "cloud"

#: Ranks
NPROCS = 2

#: Parcel density of the tutorial (cloudProperties constantProperties rho0)
RHO0 = 964.0

#: Patches of each stage and their type after the change of `walls`
PATCHES = {
    "hopperInitialState": {"walls": "patch", "frontAndBack": "wall"},
    "hopperEmptying": {"walls": "patch", "frontAndBack": "wall",
                       "inlet": "patch", "outlet": "patch"},
    "control": {"walls": "wall", "frontAndBack": "wall"},
}

#: The rough walls' settings
ROUGH = """{
    type            rough;
    e               0.8;
    mu0             0.3;
    roughnessAngle  5;
}
"""

#: What each patch of the tutorial gets
ENTRIES = {"walls": ROUGH, "frontAndBack": ROUGH,
           "inlet": "{ type escape; }\n", "outlet": "{ type escape; }\n"}

#: Comments in the settings by patch type
COMMENTS = {
    "wall": "// a wall: the collision model's wall model keeps parcel\n"
            "// centres off it (rough if one ever reaches it)\n",
    "patch": "// type patch: not seen by the wall model, ours\n",
}


#: OpenFOAM libraries that must not come from Debian's v1912 in /usr/lib
SYSTEM_OPENFOAM = re.compile(
    r"^/usr/lib/(x86_64-linux-gnu/)?"
    r"lib(OpenFOAM\w*|finiteVolume\w*|lagrangian\w*|meshTools|Pstream|"
    r"OSspecific|fileFormats|surfMesh|triSurface|\w*[Mm]omentumTransport\w*|"
    r"physicalProperties|fvModels|fvConstraints|sampling|dynamicMesh|"
    r"distributionModels|genericFvFields|specie|thermophysicalModels)\.so")


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--platform", default=fc.DEFAULT_PLATFORM,
                   choices=fc.FOUNDATION_PLATFORMS)
    p.add_argument("--work", default=".")
    p.add_argument("--rows", type=int, default=6,
                   help="keep the lowest ROWS rows of the tutorial's 3300 "
                        "injection positions (46 per row); 0: all")
    p.add_argument("--no-control", dest="control", action="store_false",
                   help="skip the control run (tutorial's wall-type walls)")
    p.add_argument("--endTime1", default="0.05",
                   help="endTime of hopperInitialState (tutorial: 0.25)")
    p.add_argument("--endTime2", default="0.13",
                   help="endTime of hopperEmptying (tutorial: 5)")
    return p.parse_args()


# ---------------------------------------------------------------------------
# The case
# ---------------------------------------------------------------------------

def tutorial_path():
    """The tutorial in the OpenFOAM installation, or a clear failure."""
    project = os.environ.get("WM_PROJECT_DIR", "")
    path = os.path.join(project, TUTORIAL)
    if not os.path.isfile(os.path.join(path, "Allrun")):
        raise t.TestFailure(
            "OpenFOAM's tutorial %s is not there: %s does not exist "
            "($WM_PROJECT_DIR = %r). This test copies it from the OpenFOAM "
            "installation at run time; use an installation with its "
            "tutorials/ folder (the source tree has it)"
            % (TUTORIAL, path, project))
    return path


def edit(path, pattern, replacement, count=1, flags=re.M):
    """Replace pattern in a file of the copied tutorial exactly count times;
    anything else means the tutorial is not the one this test knows."""
    try:
        fc.replace_in_file(path, pattern, replacement, count, flags)
    except fc.FoamError as e:
        raise t.TestFailure("%s: the tutorial differs from the one this test "
                            "was written for" % e)


def prepare_stage(stage, end_time, walls_to_us=True):
    """The changes to one stage before blockMesh (see the module doc).
    walls_to_us False (the control): `walls` stays a wall of the wall
    model, as in the tutorial."""
    control = os.path.join(stage, "system", "controlDict")
    edit(control, r"^(solver\s+functions;)",
         'libs            ("libroughWallInteraction.so");\n\n\\1')
    edit(control, r"^endTime\s+[^;]+;", "endTime         %s;" % end_time)
    edit(control, r"^writeInterval\s+[^;]+;",
         "writeInterval   %s;" % end_time)

    decompose = os.path.join(stage, "system", "decomposeParDict")
    edit(decompose, r"^numberOfSubdomains\s+\d+;",
         "numberOfSubdomains %d;" % NPROCS)
    edit(decompose, r"^(\s*n\s+)\(\s*\d+\s+1\s+1\s*\);",
         r"\g<1>(%d 1 1);" % NPROCS, count=2)

    if not walls_to_us:
        return
    edit(os.path.join(stage, "system", "blockMeshDict"),
         r"^(\s*walls\s*\{\s*type\s+)wall;", r"\g<1>patch;")

    properties = os.path.join(stage, "constant", "cloudProperties")
    edit(properties, r"\n\s*walls\s*\{[^{}]*\}\n", "\n", flags=0)


def thin_cloud(stage, rows):
    """Keep the lowest rows of constant/cloudPositions (all if rows is 0).
    Returns (kept, of)."""
    path = os.path.join(stage, "constant", "cloudPositions")
    lines = fc.read_text(path).splitlines(keepends=True)
    row = re.compile(r"^\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)\s*$")
    ys = {i: float(m.group(2)) for i, m in
          ((i, row.match(line)) for i, line in enumerate(lines)) if m}
    if not ys:
        raise t.TestFailure("%s: no positions" % path)
    if rows <= 0:
        return len(ys), len(ys)
    levels = sorted(set(round(y, 9) for y in ys.values()))
    top = levels[min(rows, len(levels)) - 1] + 1e-9
    keep = [line for i, line in enumerate(lines)
            if i not in ys or ys[i] <= top]
    fc.write_text(path, "".join(keep))
    return sum(1 for y in ys.values() if y <= top), len(ys)


def read_boundary(stage):
    """{patch name: type} of constant/polyMesh/boundary."""
    text = fc.read_text(os.path.join(stage, "constant", "polyMesh",
                                     "boundary"))
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    return {name: kind for name, kind in re.findall(
        r"(\w+)\s*\{\s*type\s+(\w+);", body)}


def write_settings(stage, name):
    """The patch interaction model, for the patches of the stage's mesh."""
    patches = read_boundary(stage)
    t.check(patches == PATCHES[name],
            "%s: mesh patches %s" % (name, ", ".join(
                "%s %s" % kv for kv in sorted(patches.items()))))
    entries = "".join(
        (COMMENTS[kind] if patch in ("walls", "frontAndBack") else "")
        + patch + ("\n" if ENTRIES[patch].startswith("{\n") else " ")
        + ENTRIES[patch] for patch, kind in patches.items())
    settings = ("patchInteractionModel roughWallInteraction;\n\n"
                "    roughWallInteractionCoeffs\n    {\n"
                "        patches\n        (\n"
                + textwrap.indent(entries, " "*12)
                + "        );\n    }")
    edit(os.path.join(stage, "constant", "cloudProperties"),
         r"patchInteractionModel\s+none;", settings)


# ---------------------------------------------------------------------------
# Running
# ---------------------------------------------------------------------------

def check_log(stage_name, path):
    """A step ended well: "End" in its log, no FOAM FATAL."""
    text = fc.read_text(path)
    name = os.path.basename(path)
    t.check("FOAM FATAL" not in text,
            "%s/%s: no FOAM FATAL" % (stage_name, name))
    t.check(re.search(r"^End\s*$", text, flags=re.M) is not None,
            "%s/%s: ends with End" % (stage_name, name))
    warnings = text.count("FOAM Warning")
    if warnings:
        print("note  %s/%s: %d FOAM Warning(s), first: %s" % (
            stage_name, name, warnings,
            text[text.index("FOAM Warning"):][:300].replace("\n", " | ")))
    return text


def step(stage, args, log):
    """Run one step of the Allrun (exit status checked)."""
    rc, elapsed = fc.run(stage, args, log, timeout=900)
    check_log(os.path.basename(stage), os.path.join(stage, log))
    return elapsed


def descendants(root_pid, comm):
    """Pids of the processes named comm below root_pid."""
    parent = {}
    names = {}
    for stat in glob.glob("/proc/[0-9]*/stat"):
        try:
            text = fc.read_text(stat)
        except OSError:
            continue
        pid = int(stat.split("/")[2])
        name = text[text.index("(") + 1:text.rindex(")")]
        fields = text[text.rindex(")") + 2:].split()
        parent[pid] = int(fields[1])
        names[pid] = name
    found = []
    for pid, name in names.items():
        if name != comm:
            continue
        p = pid
        while p in parent and p > 1:
            p = parent[p]
            if p == root_pid:
                found.append(pid)
                break
    return found


def mapped_libraries(pid):
    """Shared objects mapped by a process (/proc/<pid>/maps)."""
    libs = set()
    try:
        for line in fc.read_text("/proc/%d/maps" % pid).splitlines():
            fields = line.split(None, 5)
            if len(fields) == 6 and ".so" in os.path.basename(fields[5]):
                libs.add(fields[5].strip())
    except OSError:
        pass
    return libs


def solve(stage, log="log.foamRun", timeout=900):
    """mpirun -np 2 foamRun -parallel, watching the shared objects the
    foamRun processes map while they run.  Returns (seconds, {pid: libs},
    executable of a foamRun process)."""
    args = fc.mpirun(NPROCS, ["foamRun", "-parallel"])
    start = time.time()
    seen = {}
    exe = None
    with open(os.path.join(stage, log), "w") as f:
        env = dict(os.environ, PWD=os.path.abspath(stage))
        proc = subprocess.Popen(args, cwd=stage, stdout=f,
                                stderr=subprocess.STDOUT, env=env)
        rc = None
        started = False
        next_sample = 0.0
        while rc is None:
            time.sleep(0.5)
            rc = proc.poll()
            if rc is not None:
                break
            now = time.time()
            if now - start > timeout:
                proc.kill()
                proc.wait()
                rc = "timeout after %d s" % timeout
                break
            # The libraries are loaded before the time loop: sample from
            # the first time step on, every 5 s
            if not started:
                started = "\nTime = " in fc.read_text(os.path.join(stage,
                                                                   log))
            if not started or now < next_sample:
                continue
            next_sample = now + 5
            for pid in descendants(proc.pid, "foamRun"):
                libs = mapped_libraries(pid)
                if libs:
                    seen.setdefault(pid, set()).update(libs)
                if exe is None:
                    try:
                        exe = os.readlink("/proc/%d/exe" % pid)
                    except OSError:
                        pass
    elapsed = time.time() - start
    print("ran   %s (%s): rc %s, %.1f s" % (" ".join(args), log, rc, elapsed),
          flush=True)
    if rc != 0:
        with open(os.path.join(stage, log)) as f:
            print("".join(f.readlines()[-40:]))
        raise t.TestFailure("foamRun failed (rc %s), see %s"
                            % (rc, os.path.join(stage, log)))
    check_log(os.path.basename(stage), os.path.join(stage, log))
    return elapsed, seen, exe


def check_loaded_libraries(name, seen, exe):
    """The running foamRun processes mapped the release's libraries only;
    ldd of the binary and of the parcel and rough-wall libraries they
    mapped resolves none to /usr/lib."""
    t.check(len(seen) == NPROCS,
            "%s: shared objects of %d running foamRun processes read from "
            "/proc/<pid>/maps (%d)" % (name, NPROCS, len(seen)))
    mapped = set().union(*seen.values())
    bad = sorted(p for p in mapped if SYSTEM_OPENFOAM.match(p))
    t.check(not bad, "%s: foamRun mapped %d shared objects, none an "
            "OpenFOAM library from /usr/lib%s"
            % (name, len(mapped), ": " + ", ".join(bad) if bad else ""))
    wanted = {}
    for lib in ("libroughWallInteraction.so", "liblagrangianParcel.so",
                "libOpenFOAM.so", "libfiniteVolume.so"):
        paths = sorted(p for p in mapped if os.path.basename(p) == lib)
        t.check(len(paths) == 1 and not paths[0].startswith("/usr/"),
                "%s: foamRun loaded %s from %s" % (name, lib, paths))
        wanted[lib] = paths[0]
    bad = []
    for binary in [exe] + [wanted["libroughWallInteraction.so"],
                           wanted["liblagrangianParcel.so"]]:
        for lib, path in fc.ldd(binary).items():
            if SYSTEM_OPENFOAM.match(path) or (
                    path == "not found" and not lib.startswith("libmpi")):
                bad.append("%s: %s => %s" % (os.path.basename(binary), lib,
                                             path))
    t.check(exe is not None and not bad,
            "%s: ldd of %s, libroughWallInteraction.so, "
            "liblagrangianParcel.so: no OpenFOAM library from /usr/lib, none "
            "missing%s" % (name, exe, ": " + "; ".join(bad) if bad else ""))


# ---------------------------------------------------------------------------
# Reading the output
# ---------------------------------------------------------------------------

def latest_time(stage):
    """The latest time folder of processor0 (name, value)."""
    times = []
    for d in os.listdir(os.path.join(stage, "processor0")):
        try:
            times.append((float(d), d))
        except ValueError:
            pass
    value, name = max(times)
    return name, value


def read_list_length(path):
    """Entries of an OpenFOAM list file: its size, checked against the
    number of entries ('(...)' rows of positions, numbers or '(...)' of
    fields; uniform lists N{value} too)."""
    text = fc.read_text(path)
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    body = re.sub(r"//.*", "", re.sub(r"/\*.*?\*/", "", body, flags=re.S))
    m = re.search(r"(\d+)\s*(\(|\{)", body)
    if not m:
        raise t.TestFailure("%s: no list" % path)
    n = int(m.group(1))
    if m.group(2) == "{":
        return n
    inner = body[m.end():body.rindex(")")]
    rows = len([line for line in inner.splitlines() if line.strip()])
    if rows != n:
        raise t.TestFailure("%s: list size %d but %d entries" % (path, n,
                                                                  rows))
    return n


def parcels(stage, time_name):
    """Parcels at a time in every processor's lagrangian output: the count
    per processor (positions, with d and nParticle of the same length) and
    all parcels' d and nParticle."""
    counts = []
    d = []
    n_particle = []
    for root in sorted(glob.glob(os.path.join(stage, "processor[0-9]*")),
                       key=lambda p: int(re.sub(r"\D", "", p[-3:]))):
        cloud = os.path.join(root, time_name, "lagrangian", CLOUD)
        if not os.path.exists(os.path.join(cloud, "positions")):
            counts.append(0)
            continue
        n = read_list_length(os.path.join(cloud, "positions"))
        part = {name: np.atleast_1d(fc.read_field(os.path.join(cloud, name)))
                for name in ("d", "nParticle")}
        for name, values in part.items():
            if len(values) != n:
                raise t.TestFailure("%s: %d positions but %d values of %s"
                                    % (cloud, n, len(values), name))
        counts.append(n)
        d.append(part["d"])
        n_particle.append(part["nParticle"])
    if len(counts) != NPROCS:
        raise t.TestFailure("%s: %d processor folders (expected %d)"
                            % (stage, len(counts), NPROCS))
    d = np.concatenate(d) if d else np.zeros(0)
    n_particle = np.concatenate(n_particle) if n_particle else np.zeros(0)
    return counts, d, n_particle


def mass(d, n_particle):
    return float(np.sum(parcel_mass(d, n_particle, RHO0)))


def reconstructed_count(stage, time_name):
    """Parcels of the reconstructed case at a time."""
    path = os.path.join(stage, time_name, "lagrangian", CLOUD, "positions")
    return read_list_length(path) if os.path.exists(path) else 0


def positions_in_file(path):
    """Entries of a vectorField file (manualInjection's positionsFile)."""
    return len(re.findall(r"^\s*\(\s*\S+\s+\S+\s+\S+\s*\)\s*$",
                          fc.read_text(path), flags=re.M))


def last_statistics(stage):
    """The last row of roughWallInteraction.dat and its column names."""
    names, rows = fc.read_statistics(stage, CLOUD)
    t.check(len(rows) > 0, "%s: statistics file has %d rows"
            % (os.path.basename(stage), len(rows)))
    return names, rows[-1]


def escapes(names, row):
    """Escaped parcels and mass: the sum of the <patch>_nEscape and
    <patch>_massEscape columns."""
    n = sum(row[c] for c in names if c.endswith("_nEscape"))
    m = sum(row[c] for c in names if c.endswith("_massEscape"))
    return int(round(n)), m


def check_rough_statistics(name, row, wall="walls"):
    hits = fc.column(row, wall + "_hits")
    t.check(hits > 0, "%s: the rough walls were hit: %s_hits = %d"
            % (name, wall, hits))
    per_hit = fc.column(row, wall + "_facetPerHit")
    loss = fc.column(row, wall + "_energyLoss")
    fallbacks = fc.column(row, wall + "_fallbacks")
    t.check(per_hit >= 1 and math.isfinite(loss) and loss >= 0
            and 0 <= fallbacks <= hits,
            "%s: %s: %.4g facet collisions per hit, %d hits at the bound, "
            "mean k_n %.4g, k_t %.4g, energy loss %.4g J (finite, >= 0)"
            % (name, wall, per_hit, fallbacks, fc.column(row, wall + "_meanKn"),
               fc.column(row, wall + "_meanKt"), loss))
    return hits


def log_reports(path):
    """(final 'Current number of parcels', final escapes of the 'Parcel
    fate' lines, final 'number of parcels added' per injector, sum of the
    'Added N new parcels' lines)."""
    text = fc.read_text(path)
    steps = fc.read_steps(path)
    added = [int(n) for n in re.findall(
        r"number of parcels added\s*=\s*(\d+)", text)]
    new = sum(int(n) for n in re.findall(r"Added (\d+) new parcels", text))
    return steps, (added[-1] if added else None), new


# ---------------------------------------------------------------------------
# The control: the tutorial's walls
# ---------------------------------------------------------------------------

def run_control(root, source, end_time, rows, hits):
    """hopperInitialState with `walls` left a wall of the wall model (the
    tutorial's set-up), everything else as in the test, serial: the
    parcels that hit `walls` hits times in the test never reach our model
    here, because the wall model repels them first.
    Returns (seconds, walls_hits)."""
    name = "control"
    case = os.path.join(root, "controlWallModel")
    shutil.copytree(os.path.join(source, "hopperInitialState"), case)
    prepare_stage(case, end_time, walls_to_us=False)
    injected, _ = thin_cloud(case, rows)
    elapsed = step(case, ["blockMesh"], "log.blockMesh")
    write_settings(case, name)
    elapsed += step(case, ["foamRun"], "log.foamRun")
    last = os.path.join(case, end_time, "lagrangian", CLOUD, "positions")
    in_domain = read_list_length(last) if os.path.exists(last) else 0
    _, row = last_statistics(case)
    control_hits = int(fc.column(row, "walls_hits"))
    t.check(in_domain == injected and control_hits == 0
            and fc.column(row, "frontAndBack_hits") == 0,
            "%s: with the tutorial's wall-type walls (wall model on them) "
            "our model sees walls_hits = %d (the test: %d) and "
            "frontAndBack_hits = %d; %d parcels of %d in the domain at t = %s"
            % (name, control_hits, hits, fc.column(row, "frontAndBack_hits"),
               in_domain, injected, end_time))
    return elapsed, control_hits


# ---------------------------------------------------------------------------
# The test
# ---------------------------------------------------------------------------

def test():
    args = parse_args()
    start = time.time()
    source = tutorial_path()
    root = os.path.join(os.path.abspath(args.work), "hopperParticles")
    if os.path.exists(root):
        shutil.rmtree(root)
    shutil.copytree(source, root)
    print("copied %s to %s" % (source, root), flush=True)
    initial = os.path.join(root, "hopperInitialState")
    emptying = os.path.join(root, "hopperEmptying")
    prepare_stage(initial, args.endTime1)
    kept, of = thin_cloud(initial, args.rows)
    print("hopperInitialState: injecting %d of the tutorial's %d parcels "
          "(--rows %d)" % (kept, of, args.rows), flush=True)
    prepare_stage(emptying, args.endTime2)
    times = {}

    # -- hopperInitialState ------------------------------------------------
    name = "hopperInitialState"
    times["blockMesh+decomposePar 1"] = step(initial, ["blockMesh"],
                                             "log.blockMesh")
    write_settings(initial, name)
    times["blockMesh+decomposePar 1"] += step(initial, ["decomposePar"],
                                              "log.decomposePar")
    times["foamRun 1"], seen, exe = solve(initial)
    check_loaded_libraries(name, seen, exe)
    times["reconstructPar 1"] = step(initial, ["reconstructPar"],
                                     "log.reconstructPar")

    last, value = latest_time(initial)
    t.check(abs(value - float(args.endTime1)) < 1e-9,
            "%s: last time written %s = endTime" % (name, last))
    injected_file = positions_in_file(
        os.path.join(initial, "constant", "cloudPositions"))
    steps, added, new = log_reports(os.path.join(initial, "log.foamRun"))
    t.check(added == injected_file and new == injected_file,
            "%s: injected %d parcels (cloudPositions %d; log: 'Added %d new "
            "parcels', 'number of parcels added = %s')"
            % (name, injected_file, injected_file, new, added))
    counts, d1, np1 = parcels(initial, last)
    in_domain = sum(counts)
    names, row = last_statistics(initial)
    escaped, _ = escapes(names, row)
    t.check(injected_file == in_domain + escaped,
            "%s: parcels conserved: injected %d = in the domain at t = %s %d "
            "(processors %s) + escaped %d" % (name, injected_file, last,
                                              in_domain, counts, escaped))
    t.check(steps and steps[-1]["parcels"] == in_domain
            and reconstructed_count(initial, last) == in_domain,
            "%s: the log's last cloud report (%s) and the reconstructed case "
            "(%d) hold the same %d parcels"
            % (name, steps[-1]["parcels"] if steps else None,
               reconstructed_count(initial, last), in_domain))
    hits1 = check_rough_statistics(name, row)
    print("info  %s: frontAndBack_hits = %d (the wall model's wall)"
          % (name, fc.column(row, "frontAndBack_hits")))

    # -- hopperEmptying ----------------------------------------------------
    name = "hopperEmptying"
    times["blockMesh+decomposePar 2"] = step(emptying, ["blockMesh"],
                                             "log.blockMesh")
    write_settings(emptying, name)
    times["blockMesh+decomposePar 2"] += step(emptying, ["decomposePar"],
                                              "log.decomposePar")
    times["mapFieldsPar"] = step(
        emptying, fc.mpirun(NPROCS, ["mapFieldsPar", "../hopperInitialState",
                                     "-sourceTime", "latestTime",
                                     "-parallel"]), "log.mapFieldsPar")
    text = fc.read_text(os.path.join(emptying, "log.mapFieldsPar"))
    read = re.findall(r"read (\d+) parcels from source mesh", text)
    mapped = re.findall(r"mapped (\d+) parcels to the target mesh", text)
    t.check(read == [str(in_domain)] and mapped == [str(in_domain)],
            "%s: mapFieldsPar read %s and mapped %s parcels: all %d of "
            "hopperInitialState" % (name, read, mapped, in_domain))
    counts0, d0, np0 = parcels(emptying, "0")
    start_parcels = sum(counts0)
    start_mass = mass(d0, np0)
    t.check(start_parcels == in_domain,
            "%s: time 0 holds the %d mapped parcels (processors %s)"
            % (name, start_parcels, counts0))

    times["foamRun 2"], seen, exe = solve(emptying)
    check_loaded_libraries(name, seen, exe)
    times["reconstructPar 2"] = step(emptying, ["reconstructPar"],
                                     "log.reconstructPar")

    last, value = latest_time(emptying)
    t.check(abs(value - float(args.endTime2)) < 1e-9,
            "%s: last time written %s = endTime" % (name, last))
    steps, _, _ = log_reports(os.path.join(emptying, "log.foamRun"))
    counts, d2, np2 = parcels(emptying, last)
    in_domain2 = sum(counts)
    names, row = last_statistics(emptying)
    escaped2, escaped_mass = escapes(names, row)
    outlet = int(fc.column(row, "outlet_nEscape"))
    t.check(outlet > 0, "%s: parcels left through the outlet: "
            "outlet_nEscape = %d (inlet_nEscape = %d)"
            % (name, outlet, fc.column(row, "inlet_nEscape")))
    t.check(start_parcels == in_domain2 + escaped2,
            "%s: parcels conserved: mapped %d = in the domain at t = %s %d "
            "(processors %s) + escaped %d" % (name, start_parcels, last,
                                              in_domain2, counts, escaped2))
    end_mass = mass(d2, np2)
    t.check(abs(end_mass + escaped_mass - start_mass) <= 1e-5*start_mass,
            "%s: mass conserved: %.6g kg at 0 = %.6g in the domain + %.6g "
            "escaped (relative difference %.1e)"
            % (name, start_mass, end_mass, escaped_mass,
               abs(end_mass + escaped_mass - start_mass)/start_mass))
    t.check(steps and steps[-1]["parcels"] == in_domain2
            and steps[-1]["escape"] == escaped2
            and reconstructed_count(emptying, last) == in_domain2,
            "%s: the log's last cloud report (%s parcels, %s escaped) and "
            "the reconstructed case (%d) agree"
            % (name, steps[-1]["parcels"] if steps else None,
               steps[-1]["escape"] if steps else None,
               reconstructed_count(emptying, last)))
    hits2 = check_rough_statistics(name, row)
    print("info  %s: frontAndBack_hits = %d (the wall model's wall)"
          % (name, fc.column(row, "frontAndBack_hits")))

    control = None
    if args.control:
        times["control (serial)"], control = run_control(
            root, source, args.endTime1, args.rows, hits1)

    print("\nsummary: hopperInitialState to t = %s: injected %d, in domain "
          "%d, escaped %d, walls_hits %d; hopperEmptying to t = %s: mapped "
          "%d, in domain %d, escaped %d (outlet %d), walls_hits %d"
          % (args.endTime1, injected_file, in_domain, escaped, hits1,
             args.endTime2, start_parcels, in_domain2, escaped2, outlet,
             hits2))
    if control is not None:
        print("control: the tutorial's wall-type walls, same settings, "
              "serial, to t = %s: walls_hits %d" % (args.endTime1, control))
    print("times: " + ", ".join("%s %.1f s" % kv for kv in times.items())
          + "; total %.1f s" % (time.time() - start), flush=True)


if __name__ == "__main__":
    t.main(test, parse_args().platform)
