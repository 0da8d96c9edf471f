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
Run it in the platform's environment only, with src/python on PYTHONPATH
(benchmarks/run does both):
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

--tutorial (openfoam13 or openfoam14, the tutorial's releases): the tutorial
tutorials/incompressibleFluid/horizontalChannel (195 um, 4000 parcels, 3 s
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

This file is the command line; the work is in the package openfoamcost
beside it: case (set-up), run (running), parse (tool output), report
(tables and figures).
"""
import argparse
import os
import re
import sys

from foamcase import bench as bc
import foamcase as fc
from foamcase.openfoamcost.case import Runner
from foamcase.openfoamcost.parse import load_rows
from foamcase.openfoamcost.report import (callgrind_table, figure, summarise, table,
                                 tutorial_stem, tutorial_table)
from foamcase.openfoamcost.run import callgrind, measure, profile, tutorial_measure


def tutorial_cost(args):
    """The tutorial's short case with OpenFOAM's wall model and the
    library's smooth and rough walls, same parcels and time steps,
    alternated"""
    if args.plot_only:
        tutorial_table(fc.read_csv(bc.result(tutorial_stem(args.tag) + ".csv")),
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
            callgrind_table(tag, fc.read_csv(bc.result(cg)))
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
    p.add_argument("--variants", help="only these variants, comma-separated "
                   "(standard, rebound,\nrough, rough-base, ...)")
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
        if not fc.Platform(args.platform).foundation and not args.plot_only:
            sys.exit("openfoamCost.py --tutorial: the tutorial runs on the "
                     "Foundation releases (--platform openfoam14 or openfoam13)")
        tutorial_cost(args)
        return
    if args.plot_only:
        plot_only(args)
        return
    if not args.platform:
        sys.exit("openfoamCost.py: --platform is needed (or --plot-only)")
    runner = Runner(args)
    if args.variants:
        runner.variants = tuple(v for v in runner.variants
                                if v in args.variants.split(","))
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
