#!/usr/bin/python3
# roughWallInteraction benchmarks: work-precision of the horizontalChannel
# tutorial (figure 3 of docs/benchmarks.md).
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Error of the tutorial's results against the wall-clock time of the run.

The tutorial (tutorials/icoUncoupledKinematicParcelFoam/horizontalChannel) is
copied to a work directory; its carrier flow is computed once, then one
particle case is set up per configuration exactly as its Allrun step 2 does
(same scripts, same parcel seed) and run serially, varying one thing at a
time for one wall model (default rough2.5, 195 um beads):
  parcels   N = 1000 .. 16000, spin-up 2 s, sampling 2 s, dt = 1 ms
  sampling  N = 4000, sampling 0.5 .. 4 s after a 2 s spin-up, dt = 1 ms
  dt        N = 4000, 2 s + 2 s, dt = 2, 1, 0.5, 0.25 ms
Each case is analysed by the tutorial's postProcess.py, whose standard errors
are jackknife estimates over 20 groups of whole parcels. Errors shown:
  - concentration profile: RMS over the 25 bins of its standard error
  - upper-half fraction of the parcels: its standard error
  - lower-wall hits per parcel and metre: difference from the most
    expensive run of the same sweep (no standard error is available)
  - dt: difference of the upper-half fraction and RMS difference of the
    concentration profile from the dt = 0.25 ms run, next to their
    combined standard error (the discretisation error is visible only where
    it exceeds that)
Run cost on the x axes: the solver's CPU time (its last ExecutionTime), less
sensitive to the load of a shared machine than the wall clock (both are
recorded). Writes benchmarks/results/tutorial-work-precision.csv,
tutorial.md and docs/figures/bench-tutorial-work-precision.png. Run time at
the defaults: about 20 min of solver CPU time, 20-40 min of wall clock on
the 2-core machine of the report.
"""
import argparse
import math
import os
import re
import resource
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchCommon as bc  # noqa: E402

TUTORIAL = os.path.join(bc.ROOT, "tutorials", "icoUncoupledKinematicParcelFoam",
                        "horizontalChannel")
PY = "/usr/bin/python3"
SOLVER = "icoUncoupledKinematicParcelFoam"


def sh(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as f:
        subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT,
                       check=True)


def set_entry(path, key, value):
    """'key value;' in a dictionary, keeping a comment after the ';'"""
    lines = open(path).read().splitlines(True)
    done = False
    for i, line in enumerate(lines):
        s = line.lstrip()
        if s.startswith(key) and s[len(key):len(key) + 1].isspace() \
                and ";" in s:
            indent = line[:len(line) - len(s)]
            rest = s[s.index(";") + 1:]
            lines[i] = "%s%s %s;%s" % (indent, key, value, rest)
            done = True
    if not done:
        raise RuntimeError("no %s in %s" % (key, path))
    open(path, "w").write("".join(lines))


def prepare(work):
    """Copy the tutorial (without results) and compute its carrier flow"""
    tut = os.path.join(work, "horizontalChannel")
    if os.path.isdir(tut):
        shutil.rmtree(tut)
    shutil.copytree(TUTORIAL, tut, ignore=shutil.ignore_patterns(
        "run", "results", "log.*", "[1-9]*", "postProcessing", "0"))
    carrier = os.path.join(tut, "carrier")
    shutil.copytree(os.path.join(carrier, "0.orig"), os.path.join(carrier, "0"))
    sh(["blockMesh"], carrier, "log.blockMesh")
    sh(["simpleFoam"], carrier, "log.simpleFoam")
    sh(["postProcess", "-func", "writeCellCentres", "-latestTime"], carrier,
       "log.postProcess")
    times = [d for d in os.listdir(carrier)
             if d.replace(".", "", 1).isdigit() and float(d) > 0]
    carrier_time = max(times, key=float)
    sys.path.insert(0, os.path.join(tut, "scripts"))
    from foamio import read_list
    p = read_list(os.path.join(carrier, "constant", "polyMesh", "points"))
    height = float(p[:, 1].max() - p[:, 1].min())
    return tut, carrier_time, height


def run_case(tut, carrier_time, height, name, variant, diameter, parcels,
             spin_up, end_time, dt, seed=1, nprocs=1):
    """One tracking case as Allrun step 2 sets it up, on nprocs MPI ranks
    (decomposed as Allrun -parallel N does); returns the solver's wall
    seconds, its CPU seconds (rank 0's last ExecutionTime), the summary and
    the profiles of postProcess.py. caseInfo also gets processCpu: the CPU
    time of the solver process(es), all ranks and mpirun together."""
    case = os.path.join(tut, "run", name)
    if os.path.isdir(case):
        shutil.rmtree(case)
    os.makedirs(case)
    parts = os.path.join(tut, "particles")
    shutil.copytree(os.path.join(parts, "constant"),
                    os.path.join(case, "constant"))
    shutil.copytree(os.path.join(parts, "system"), os.path.join(case, "system"))
    shutil.copytree(os.path.join(tut, "carrier", "constant", "polyMesh"),
                    os.path.join(case, "constant", "polyMesh"))
    shutil.copy(os.path.join(parts, "constant", "wallModels", variant),
                os.path.join(case, "constant", "wallModel"))
    shutil.rmtree(os.path.join(case, "constant", "wallModels"))
    os.makedirs(os.path.join(case, "0"))
    scripts = os.path.join(tut, "scripts")
    sh(["transformPoints", "-scale", "(1 %.12g 1)" % (1 - diameter/height)],
       case, "log.transformPoints")
    sh([PY, os.path.join(scripts, "mapCarrierFlow.py"),
        os.path.join(tut, "carrier"), carrier_time, ".", repr(diameter)],
       case, "log.mapCarrierFlow")
    sh([PY, os.path.join(scripts, "makeParcelPositions.py"), ".",
        str(parcels), str(seed)], case, "log.makeParcelPositions")
    set_entry(os.path.join(case, "constant", "kinematicCloudProperties"),
              "value", repr(diameter))
    control = os.path.join(case, "system", "controlDict")
    set_entry(control, "endTime", repr(end_time))
    set_entry(control, "writeInterval", "0.05")
    set_entry(control, "deltaT", repr(dt))

    model = open(os.path.join(case, "constant", "wallModel")).read()

    def entry(key):
        for line in model.splitlines():
            s = line.split("//")[0].split()
            if len(s) >= 2 and s[0] == key:
                return " ".join(s[1:]).rstrip(";")
        return None
    info = ["variant         %s" % variant]
    if entry("roughnessAngle"):
        info += ["wallModel       rough",
                 "roughnessAngle  %s" % entry("roughnessAngle")]
    else:
        info += ["wallModel       smooth", "e               %s" % entry("e"),
                 "mu              %s" % entry("mu")]
    info += ["diameter        %r" % diameter, "height          %r" % height,
             "nParcels        %d" % parcels, "spinUp          %r" % spin_up,
             "endTime         %r" % end_time, "nProcs          %d" % nprocs,
             "carrier         %s" % os.path.join(tut, "carrier"),
             "carrierTime     %s" % carrier_time]
    if nprocs > 1:
        # The tutorial's decomposition (Allrun -parallel N): method simple,
        # n (N 1 1), i.e. N streamwise slabs of the 4-cell-long periodic
        # section, each the full channel height
        decompose = os.path.join(case, "system", "decomposeParDict")
        set_entry(decompose, "numberOfSubdomains", str(nprocs))
        set_entry(decompose, "n", "(%d 1 1)" % nprocs)
        sh(["decomposePar", "-force"], case, "log.decomposePar")
        cmd = ["mpirun", "-np", str(nprocs)]
        if os.geteuid() == 0:
            cmd.append("--allow-run-as-root")
        if nprocs > (os.cpu_count() or 1):
            cmd.append("--oversubscribe")
        cmd += [SOLVER, "-parallel"]
    else:
        cmd = [SOLVER]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    sh(cmd, case, "log." + SOLVER)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = solver_cpu(case)
    info.append("wallClock       %.2f" % wall)
    info.append("processCpu      %.2f" % (
        after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime))
    open(os.path.join(case, "caseInfo"), "w").write("\n".join(info) + "\n")
    sh([PY, os.path.join(scripts, "collectSamples.py"), ".", "--prune"], case,
       "log.collectSamples")
    out = os.path.join(case, "analysis")
    sh([PY, os.path.join(scripts, "postProcess.py"), out, case], tut,
       "run/%s.log.postProcess" % name)
    summary = bc.read_csv(os.path.join(out, "summary.csv"))[0]
    profile = bc.read_csv(os.path.join(out, "profiles.csv"))
    return wall, cpu, summary, profile


def solver_cpu(case):
    """CPU time of the solver's time steps: its last ExecutionTime (the
    start-up before the first step is a fraction of a second)"""
    log = open(os.path.join(case, "log." + SOLVER)).read()
    return float(re.findall(r"ExecutionTime = ([0-9.eE+-]+) s", log)[-1])


def configurations(quick):
    if quick:
        base = dict(parcels=500, spin_up=0.3, sampling=0.3, dt=1e-3)
        sweeps = dict(parcels=[250, 500, 1000], sampling=[0.15, 0.3, 0.6],
                      dt=[2e-3, 1e-3, 5e-4])
    else:
        base = dict(parcels=4000, spin_up=2.0, sampling=2.0, dt=1e-3)
        sweeps = dict(parcels=[1000, 2000, 4000, 8000, 16000],
                      sampling=[0.5, 1.0, 2.0, 4.0],
                      dt=[2e-3, 1e-3, 5e-4, 2.5e-4])
    configs = {}
    for sweep, values in sweeps.items():
        for v in values:
            c = dict(base)
            c[sweep] = v
            key = (c["parcels"], c["spin_up"], c["sampling"], c["dt"])
            configs.setdefault(key, set()).add(sweep)
    return configs


def measure(args):
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    tut, carrier_time, height = prepare(work)
    rows = []
    for (parcels, spin_up, sampling, dt), sweeps in sorted(
            configurations(args.quick).items(), key=lambda kv: kv[0][0]
            * (kv[0][1] + kv[0][2])/kv[0][3]):
        name = "n%d-t%g-dt%g" % (parcels, sampling, dt)
        wall, cpu, s, prof = run_case(tut, carrier_time, height, name,
                                 args.variant, 195e-6, parcels, spin_up,
                                 spin_up + sampling, dt)
        se = [float(p["concentration_se"]) for p in prof
              if p["concentration_se"]]
        row = dict(sweeps=" ".join(sorted(sweeps)), parcels=parcels,
                   spin_up=spin_up, sampling=sampling, dt=dt,
                   wall="%.2f" % wall, cpu="%.2f" % cpu,
                   upperFraction=s["upperFraction"],
                   upperFraction_se=s["upperFraction_se"],
                   concentration_se_rms="%.4g" % math.sqrt(
                       sum(x*x for x in se)/len(se)),
                   hits_lower=s["hitsPerParcelPerMetre_lowerWall"],
                   kn_mean=s["kn_mean"],
                   concentration=" ".join(p["concentration"] for p in prof),
                   concentration_se=" ".join(p["concentration_se"]
                                             for p in prof))
        rows.append(row)
        print({k: v for k, v in row.items()
               if not k.startswith("concentration")}, flush=True)
    bc.write_csv("tutorial-work-precision.csv", rows)


def load():
    return bc.read_csv("tutorial-work-precision.csv")


def vec(s):
    return [float(x) if x else float("nan") for x in s.split(" ")]


def rms(v):
    v = [x for x in v if math.isfinite(x)]
    return math.sqrt(sum(x*x for x in v)/len(v))


def analyse(rows):
    sweep = {k: sorted([r for r in rows if k in r["sweeps"].split()],
                       key=lambda r: float(r["cpu"]))
             for k in ("parcels", "sampling", "dt")}
    out = {}
    for k in ("parcels", "sampling"):
        ref = sweep[k][-1]
        pts = []
        for r in sweep[k]:
            pts.append(dict(
                label="N=%s" % r["parcels"] if k == "parcels"
                else "T=%s s" % r["sampling"],
                wall=float(r["cpu"]),
                conc_se=float(r["concentration_se_rms"]),
                up_se=float(r["upperFraction_se"]),
                hits_diff=abs(float(r["hits_lower"])
                              / float(ref["hits_lower"]) - 1)
                if r is not ref else float("nan")))
        out[k] = pts
    ref = min(sweep["dt"], key=lambda r: float(r["dt"]))
    c_ref, s_ref = vec(ref["concentration"]), vec(ref["concentration_se"])
    pts = []
    for r in sweep["dt"]:
        c, s = vec(r["concentration"]), vec(r["concentration_se"])
        pts.append(dict(
            label="dt=%g ms" % (1e3*float(r["dt"])), wall=float(r["cpu"]),
            up_diff=abs(float(r["upperFraction"])
                        - float(ref["upperFraction"])),
            up_se=math.hypot(float(r["upperFraction_se"]),
                             float(ref["upperFraction_se"])),
            conc_diff=rms([a - b for a, b in zip(c, c_ref)]),
            conc_se=rms([math.hypot(a, b) for a, b in zip(s, s_ref)]),
            hits=float(r["hits_lower"]), is_ref=r is ref))
    out["dt"] = pts
    return out


def figure(a):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    ax = axes[0]
    for k, c in (("parcels", "C0"), ("sampling", "C1")):
        pts = a[k]
        ax.loglog([p["wall"] for p in pts], [p["conc_se"] for p in pts],
                  "o-", color=c, label="concentration, RMS s.e. (%s)" % k)
        ax.loglog([p["wall"] for p in pts], [p["up_se"] for p in pts],
                  "s--", color=c, label="upper-half fraction, s.e. (%s)" % k)
        for p in pts:
            ax.annotate(p["label"], (p["wall"], p["conc_se"]), fontsize=6,
                        textcoords="offset points", xytext=(3, 3))
    ax.set_xlabel("CPU time of the run [s]")
    ax.set_ylabel("standard error (jackknife)")
    ax.set_title("statistical error")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)

    ax = axes[1]
    for k, c in (("parcels", "C0"), ("sampling", "C1")):
        pts = [p for p in a[k] if math.isfinite(p["hits_diff"])]
        ax.loglog([p["wall"] for p in pts],
                  [max(p["hits_diff"], 1e-5) for p in pts], "o-", color=c,
                  label="lower-wall hits per parcel and metre (%s)" % k)
        for p in pts:
            ax.annotate(p["label"], (p["wall"], max(p["hits_diff"], 1e-5)),
                        fontsize=6, textcoords="offset points", xytext=(3, 3))
    ax.set_xlabel("CPU time of the run [s]")
    ax.set_ylabel("relative difference from the longest run")
    ax.set_title("wall-hit statistics")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)

    ax = axes[2]
    pts = [p for p in a["dt"] if not p["is_ref"]]
    w = [p["wall"] for p in pts]
    ax.loglog(w, [max(p["up_diff"], 1e-5) for p in pts], "o-", color="C2",
              label="|upper-half fraction - ref|")
    ax.loglog(w, [p["up_se"] for p in pts], "o:", color="C2",
              label="its combined s.e.")
    ax.loglog(w, [p["conc_diff"] for p in pts], "s-", color="C4",
              label="RMS |concentration - ref|")
    ax.loglog(w, [p["conc_se"] for p in pts], "s:", color="C4",
              label="its combined s.e.")
    for p in pts:
        ax.annotate(p["label"], (p["wall"], p["conc_diff"]), fontsize=6,
                    textcoords="offset points", xytext=(3, 3))
    ax.set_xlabel("CPU time of the run [s]")
    ax.set_ylabel("difference from dt = %s" % [p["label"] for p in a["dt"]
                                               if p["is_ref"]][0])
    ax.set_title("time step (same parcels and sampling)")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    path = os.path.join(bc.FIGURES, "bench-tutorial-work-precision.png")
    fig.savefig(path, dpi=100)
    print("wrote " + path)


def table(rows):
    lines = ["| sweep | parcels | sampling [s] | dt [ms] | CPU [s] | wall [s] | "
             "upper-half fraction | RMS s.e. concentration | lower-wall hits "
             "per parcel per m | mean k_n |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in sorted(rows, key=lambda r: float(r["cpu"])):
        lines.append("| %s | %s | %s | %g | %s | %s | %.4f +- %.4f | %s | "
                     "%.4g | %s |" % (r["sweeps"], r["parcels"], r["sampling"],
                               1e3*float(r["dt"]), r["cpu"], r["wall"],
                               float(r["upperFraction"]),
                               float(r["upperFraction_se"]),
                               r["concentration_se_rms"],
                               float(r["hits_lower"]), r["kn_mean"]))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(bc.RESULTS, "tutorial.md"), "w") as f:
        f.write(text)
    print(text)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--work", default=os.path.join(bc.ROOT, "build",
                                                  "benchmarks", "tutorial"))
    p.add_argument("--variant", default="rough2.5",
                   help="wall model of particles/constant/wallModels")
    p.add_argument("--quick", action="store_true")
    p.add_argument("--plot-only", action="store_true")
    args = p.parse_args()
    bc.ensure_dirs()
    if not args.plot_only:
        if "WM_PROJECT_DIR" not in os.environ:
            sys.exit("tutorialWorkPrecision.py: source etc/setup first")
        info = bc.write_machine("tutorial")
        print(bc.machine_markdown(info))
        measure(args)
    rows = load()
    table(rows)
    figure(analyse(rows))


if __name__ == "__main__":
    main()
