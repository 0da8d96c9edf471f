#!/usr/bin/python3
# roughWallInteraction benchmarks: what roughness { profile "<file>"; } costs
# in OpenFOAM: the start-up tabulation of Delta(d) for a 1e5-point trace, and
# the cost per wall hit against a constant Delta, in the wall box.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Cost of a wall given by a measured trace (issue 32), in the wall box of
openfoamCost.py (benchmarks/openfoam/wallBox: 110 um parcels, a colliding
cloud, e = 1, no friction).

Variants, alternated round by round (the order reversed every other round):
  rough:   roughnessAngle = the Delta the trace gives at 110 um (a brute
           force here, so that both variants scatter alike);
  profile: roughness { profile "constant/wallProfile"; }, a trace of 1e5
           points (a Gaussian random profile made here with numpy: Rq 2 um,
           correlation length 10 um, spacing 0.5 um, seed 1).
Per variant: the CPU time of the time steps (last ExecutionTime minus the
first: the start-up, and so the tabulation, excluded), the model's hits,
CPU per hit; the tabulation's CPU time as the log states it.  With
--callgrind also valgrind's instruction counts of a short run: the model's
correct() per call (one per wall hit), inclusive.

With --polydisperse (Foundation releases) the parcels' diameters are drawn
from OpenFOAM's normal distribution (number based, mean 110 um, standard
deviation 15 um, 80 to 140 um) instead of all 110 um: each hit then looks up
Delta(d) of a new diameter (the table's cache of the last diameter misses),
as with a real powder; the constant-Delta variant keeps the Delta of 110 um.

Writes benchmarks/results/<output>.<platform>.csv (default output:
profile-cost; --rounds 0 --callgrind --output profile-callgrind: the
instruction counts alone).

Usage: etc/openfoamEnv openfoam13 /usr/bin/python3 \\
           benchmarks/scripts/profileCost.py --platform openfoam13 \\
           [--parcels 10000] [--end-time 0.4] [--rounds 3] [--callgrind]
"""
import argparse
import os
import re
import shutil

import numpy as np

from foamcase import bench as bc
import foamcase as fc
from foamcase.openfoamcost.case import Runner, make_case
from foamcase.openfoamcost.parse import callgrind_profile
from foamcase.openfoamcost.run import run

POINTS = 100000
SPACING = 0.5e-6


def write_trace(path):
    """A Gaussian random profile: white noise smoothed by a Gaussian kernel
    (FFT, periodic), rms height 2 um, correlation length 10 um"""
    rng = np.random.default_rng(1)
    noise = rng.standard_normal(POINTS)
    x = np.arange(POINTS) * SPACING
    k = np.fft.rfftfreq(POINTS, SPACING) * 2 * np.pi
    ell = 10e-6
    z = np.fft.irfft(np.fft.rfft(noise) * np.exp(-(k * ell) ** 2 / 4), POINTS)
    z *= 2e-6 / z.std()
    np.savetxt(path, np.column_stack([x, z]), fmt="%.9e")


def model(roughness):
    return """FoamFile { version 2.0; format ascii; class dictionary;
    location "constant"; object wallModel; }
patchInteractionModel roughWallInteraction;
roughWallInteractionCoeffs
{
    patches
    (
        walls
        {
            type            rough;
            e               1;
            mu0             0;
            muD             0;
            %s
        }
    );
}
""" % roughness


def envelope_delta(trace, d):
    """Delta [deg] of the levelled trace at d: the rms of the tilt
    -asin((x - x_foot)/r) of a sphere resting on the highest sample within r
    of each sample (a brute force, vertex contacts only: close enough to
    make the constant-Delta variant scatter like the profile)"""
    x, z = np.loadtxt(trace, unpack=True)
    z = z - np.polyval(np.polyfit(x, z, 1), x)
    r = 0.5 * d
    w = int(np.ceil(r / SPACING))
    inside = np.arange(w, len(x) - w)
    best = np.full(len(inside), -np.inf)
    foot = np.zeros(len(inside))
    for k in range(-w, w + 1):
        u = x[inside] - x[inside + k]
        h = z[inside + k] + np.sqrt(np.maximum(r * r - u * u, 0))
        h[np.abs(u) > r] = -np.inf
        better = h > best
        best[better] = h[better]
        foot[better] = u[better]
    return float(np.degrees(np.sqrt(np.mean(np.arcsin(foot / r) ** 2))))


def prepare(case, trace_delta):
    trace = case.file("constant/wallProfile")
    write_trace(trace)
    delta = envelope_delta(trace, 110e-6) if trace_delta is None \
        else trace_delta
    fc.write_text(case.file("constant/wallModel.rough"),
                  model("roughnessAngle  %.6f;" % delta))
    fc.write_text(case.file("constant/wallModel.profile"),
                  model('roughness { profile "constant/wallProfile"; }'))
    return delta


POLYDISPERSE = """sizeDistribution
    {
        type        normal;
        Q           0;
        min         80e-6;
        max         140e-6;
        mu          110e-6;
        sigma       15e-6;
    }"""


def make_polydisperse(case, platform):
    """The injectors' fixed 110 um replaced by the normal distribution"""
    if not platform.foundation:
        raise SystemExit("profileCost: --polydisperse needs a Foundation "
                         "release (its distribution syntax)")
    path = case.file("constant/injectors")
    text = fc.read_text(path)
    fixed = re.search(r"sizeDistribution\s*\{[^}]*\}", text)
    if not fixed or "110" not in fixed.group(0).replace("0.00011", "110"):
        raise SystemExit("profileCost: no fixed 110 um sizeDistribution in "
                         + path)
    fc.write_text(path, text[:fixed.start()] + POLYDISPERSE
                  + text[fixed.end():])


def tabulation(case, log):
    m = re.search(r"tabulated at (\d+) diameters from (\S+) to (\S+) m in "
                  r"(\S+) s CPU", case.log(log))
    return (int(m.group(1)), m.group(2), m.group(3), float(m.group(4))) \
        if m else None


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--platform", choices=fc.PLATFORMS, required=True)
    p.add_argument("--parcels", type=int, default=10000)
    p.add_argument("--end-time", type=float, default=0.4)
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--callgrind", action="store_true")
    p.add_argument("--callgrind-parcels", type=int, default=2000)
    p.add_argument("--callgrind-end-time", type=float, default=0.05)
    p.add_argument("--polydisperse", action="store_true",
                   help="diameters from a normal distribution, 80-140 um")
    p.add_argument("--output", default="profile-cost",
                   help="stem of the result file in benchmarks/results")
    p.add_argument("--work", default=os.path.join(bc.ROOT, "build",
                                                  "profileCost"))
    args = p.parse_args()
    args.tag = args.platform
    args.lib_path, args.baseline_lib, args.variant_lib_path = [], None, []
    runner = Runner(args)
    runner.check_environment()
    from foamcase.openfoamcost import case as oc
    oc.MODEL_FILE.update(rough="rough", profile="profile")
    work = os.path.join(os.path.abspath(args.work), args.platform)
    os.makedirs(work, exist_ok=True)

    case, _ = make_case(runner, work, args.parcels, 1, args.end_time)
    if args.polydisperse:
        make_polydisperse(case, fc.Platform(args.platform))
    delta = prepare(case, None)
    print("Delta of the trace at 110 um: %.4f deg" % delta, flush=True)
    rows = []
    variants = ("rough", "profile")
    for rnd in range(args.rounds):
        for variant in (variants if rnd % 2 == 0 else variants[::-1]):
            log = "log.%s.%d" % (variant, rnd)
            r = run(runner, case, variant, log)
            tab = tabulation(case, log) if variant == "profile" else None
            row = dict(platform=args.platform, round=rnd, variant=variant,
                       polydisperse=args.polydisperse, parcels=args.parcels, end_time=args.end_time,
                       delta_deg="%.4f" % delta, steps=r["steps"],
                       hits=r["hits"], step_cpu="%.3f" % r["step_cpu"],
                       ns_per_hit="%.1f" % (1e9 * r["step_cpu"] / r["hits"]),
                       process_cpu="%.3f" % r["process_cpu"],
                       tabulation_rows=tab[0] if tab else "",
                       tabulation_cpu_s=tab[3] if tab else "",
                       load=open("/proc/loadavg").read().split()[0])
            rows.append(row)
            print(row, flush=True)

    if args.callgrind and shutil.which("valgrind"):
        cg_work = os.path.join(work, "callgrind")
        os.makedirs(cg_work, exist_ok=True)
        cg, _ = make_case(runner, cg_work, args.callgrind_parcels, 1,
                          args.callgrind_end_time)
        if args.polydisperse:
            make_polydisperse(cg, fc.Platform(args.platform))
        prepare(cg, delta)
        for variant in variants:
            out = cg.file("callgrind.%s.out" % variant)
            shutil.copy(cg.file("constant/wallModel." + variant),
                        cg.file("constant/wallModel"))
            cg.run(["valgrind", "--tool=callgrind",
                    "--callgrind-out-file=" + out, cg.solver],
                   "log.callgrind." + variant, timeout=3600)
            steps = cg.read_steps("log.callgrind." + variant)
            total, calls, parts, _ = callgrind_profile(
                out, "RoughWallInteraction<")
            row = dict(platform=args.platform, round="callgrind",
                       variant=variant, polydisperse=args.polydisperse,
                       parcels=args.callgrind_parcels,
                       end_time=args.callgrind_end_time,
                       delta_deg="%.4f" % delta, steps=len(steps),
                       hits=steps[-1]["hits"], total_instructions=total,
                       correct_calls=calls,
                       correct_per_call="%.1f" % (sum(parts.values())
                                                  / max(calls, 1)))
            rows.append(row)
            print(row, flush=True)
            os.remove(out)

    stem = os.path.join(bc.ROOT, "benchmarks", "results",
                        "%s.%s" % (args.output, args.platform))
    bc.write_csv(stem + ".csv", rows)
    print("wrote %s.csv" % stem)


if __name__ == "__main__":
    main()
