#!/usr/bin/python3
# roughWallInteraction benchmarks: work-precision of the horizontalChannel
# tutorial (figure 3 of docs/benchmarks.md).
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Error of the tutorial's results against the cost of the run.

The tutorial (tutorials/incompressibleFluid/horizontalChannel, OpenFOAM-14
or -13 (--platform), foamRun) is copied to a work directory and run by its own Allrun, one wall
model (default rough5, the tutorial's default variant: 195 um beads,
Delta = 5 deg), one variant at a time (-jobs 1), varying one thing at a
time from the tutorial's own set-up (2000 parcels, 1 s spin-up, 1.5 s
sampled, dt = 1 ms):
  parcels   N = 500 .. 16000, spin-up 1 s, sampling 1.5 s, dt = 1 ms
  sampling  N = 2000, sampling 0.75 .. 6 s after the 1 s spin-up, dt = 1 ms
  dt        N = 2000, 1 s + 1.5 s, dt = 2, 1, 0.5, 0.25 ms
The spin-up is the tutorial's default, 1 s: its README shows the two halves
of the sampling window after it agree (a shorter one would measure the
approach to the steady state, not the error of the steady statistics).
The carrier flow is computed by the first run and reused by the others
(RunFunctions skip it). Each run is analysed by the tutorial's
postProcess.py (its -results directory), whose standard errors are jackknife
estimates over 20 groups of whole parcels. Errors shown:
  - concentration profile: RMS over the 25 bins of its standard error
  - upper-half fraction of the parcels and rms wall-normal parcel velocity
    (the smoke test's statistics): their standard errors
  - lower-wall impacts per parcel and metre: difference from the most
    expensive run of the same sweep (no standard error is available)
  - dt: difference of the upper-half fraction, of the rms wall-normal
    velocity and RMS difference of the concentration profile from the
    dt = 0.25 ms run, next to their combined standard error (the
    discretisation error is visible only where it exceeds that)
Run cost on the x axes: the solver's CPU time (its last ExecutionTime), less
sensitive to the load of a shared machine than the wall clock (both are
recorded). Every OpenFOAM command runs in the environment of --platform
(etc/openfoamEnv, default openfoam14), whatever the calling shell has sourced.
Writes benchmarks/results/tutorial-work-precision.csv, tutorial.md and
docs/figures/bench-tutorial-work-precision.png. Run time at the defaults:
about 30 min of solver CPU time.
"""
import argparse
import math
import os

from foamcase import bench as bc
import foamcase as fc

def configurations(quick):
    if quick:
        base = dict(parcels=500, spin_up=0.3, sampling=0.3, dt=1e-3)
        sweeps = dict(parcels=[250, 500, 1000], sampling=[0.15, 0.3, 0.6],
                      dt=[2e-3, 1e-3, 5e-4])
    else:
        base = dict(parcels=2000, spin_up=1.0, sampling=1.5, dt=1e-3)
        sweeps = dict(parcels=[500, 1000, 2000, 4000, 8000, 16000],
                      sampling=[0.75, 1.5, 3.0, 6.0],
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
    tut = bc.prepare_tutorial(work)
    rows = []
    for (parcels, spin_up, sampling, dt), sweeps in sorted(
            configurations(args.quick).items(), key=lambda kv: kv[0][0]
            * (kv[0][1] + kv[0][2])/kv[0][3]):
        name = "n%d-t%g-dt%g" % (parcels, sampling, dt)
        s, prof = bc.run_tutorial(tut, args.platform, name, args.variant, parcels, spin_up,
                             sampling, dt)
        se = [float(p["concentration_se"]) for p in prof
              if p["concentration_se"]]
        row = dict(platform=args.platform, variant=args.variant,
                   sweeps=" ".join(sorted(sweeps)), parcels=parcels,
                   spin_up=spin_up, sampling=sampling, dt=dt,
                   wall=s["wallClock"], cpu=s["cpuTime"],
                   upperFraction=s["upperFraction"],
                   upperFraction_se=s["upperFraction_se"],
                   UyRms=s["UyRms"], UyRms_se=s["UyRms_se"],
                   concentration_se_rms="%.4g" % math.sqrt(
                       sum(x*x for x in se)/len(se)),
                   impacts_lower=s["impactsPerParcelPerMetre_lowerWall"],
                   kn_mean=s["kn_mean"],
                   load=open("/proc/loadavg").read().split()[0],
                   concentration=" ".join(p["concentration"] for p in prof),
                   concentration_se=" ".join(p["concentration_se"]
                                             for p in prof))
        rows.append(row)
        print({k: v for k, v in row.items()
               if not k.startswith("concentration")}, flush=True)
    bc.write_csv("tutorial-work-precision.csv", rows)


def load():
    return fc.read_csv(bc.result("tutorial-work-precision.csv"))


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
                cpu=float(r["cpu"]),
                conc_se=float(r["concentration_se_rms"]),
                up_se=float(r["upperFraction_se"]),
                uy_se=float(r["UyRms_se"]),
                hits_diff=abs(float(r["impacts_lower"])
                              / float(ref["impacts_lower"]) - 1)
                if r is not ref else float("nan")))
        out[k] = pts
    ref = min(sweep["dt"], key=lambda r: float(r["dt"]))
    c_ref, s_ref = vec(ref["concentration"]), vec(ref["concentration_se"])
    pts = []
    for r in sweep["dt"]:
        c, s = vec(r["concentration"]), vec(r["concentration_se"])
        pts.append(dict(
            label="dt=%g ms" % (1e3*float(r["dt"])), cpu=float(r["cpu"]),
            up_diff=abs(float(r["upperFraction"])
                        - float(ref["upperFraction"])),
            up_se=math.hypot(float(r["upperFraction_se"]),
                             float(ref["upperFraction_se"])),
            uy_diff=abs(float(r["UyRms"]) - float(ref["UyRms"])),
            uy_se=math.hypot(float(r["UyRms_se"]), float(ref["UyRms_se"])),
            conc_diff=rms([a - b for a, b in zip(c, c_ref)]),
            conc_se=rms([math.hypot(a, b) for a, b in zip(s, s_ref)]),
            is_ref=r is ref))
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
        x = [p["cpu"] for p in pts]
        ax.loglog(x, [p["conc_se"] for p in pts], "o-", color=c,
                  label="concentration, RMS s.e. (%s)" % k)
        ax.loglog(x, [p["up_se"] for p in pts], "s--", color=c,
                  label="upper-half fraction, s.e. (%s)" % k)
        ax.loglog(x, [p["uy_se"] for p in pts], "^:", color=c,
                  label="rms wall-normal velocity [m/s], s.e. (%s)" % k)
        for p in pts:
            ax.annotate(p["label"], (p["cpu"], p["conc_se"]), fontsize=6,
                        textcoords="offset points", xytext=(3, 3))
    ax.set_xlabel("CPU time of the run [s]")
    ax.set_ylabel("standard error (jackknife)")
    ax.set_title("statistical error")
    ax.legend(fontsize=6.5)
    ax.grid(True, which="both", alpha=0.3)

    ax = axes[1]
    for k, c in (("parcels", "C0"), ("sampling", "C1")):
        pts = [p for p in a[k] if math.isfinite(p["hits_diff"])]
        ax.loglog([p["cpu"] for p in pts],
                  [max(p["hits_diff"], 1e-5) for p in pts], "o-", color=c,
                  label="lower-wall impacts per parcel and metre (%s)" % k)
        for p in pts:
            ax.annotate(p["label"], (p["cpu"], max(p["hits_diff"], 1e-5)),
                        fontsize=6, textcoords="offset points", xytext=(3, 3))
    ax.set_xlabel("CPU time of the run [s]")
    ax.set_ylabel("relative difference from the longest run")
    ax.set_title("wall-hit statistics")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)

    ax = axes[2]
    pts = [p for p in a["dt"] if not p["is_ref"]]
    x = [p["cpu"] for p in pts]
    for key, se, marker, color, text in (
            ("up_diff", "up_se", "o", "C2", "upper-half fraction"),
            ("uy_diff", "uy_se", "^", "C3", "rms wall-normal velocity"),
            ("conc_diff", "conc_se", "s", "C4", "concentration (RMS)")):
        ax.semilogy(x, [max(p[key], 1e-5) for p in pts], marker + "-",
                    color=color, label="|%s - ref|" % text)
        ax.semilogy(x, [p[se] for p in pts], marker + ":", color=color,
                    label="its combined s.e.")
    for p in pts:
        ax.annotate(p["label"], (p["cpu"], p["conc_diff"]), fontsize=6,
                    textcoords="offset points", xytext=(3, 3))
    ax.set_xlabel("CPU time of the run [s]")
    ax.set_ylabel("difference from %s" % [p["label"] for p in a["dt"]
                                          if p["is_ref"]][0])
    ax.set_title("time step (same parcels and sampling)")
    ax.legend(fontsize=6.5)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    path = os.path.join(bc.FIGURES, "bench-tutorial-work-precision.png")
    fig.savefig(path, dpi=100)
    print("wrote " + path)


def table(rows):
    platforms = sorted({r.get("platform", fc.platforms.UNRECORDED_PLATFORM)
                        for r in rows})
    spin_ups = sorted({str(r["spin_up"]) for r in rows})
    variants = sorted({r.get("variant", "rough2.5") for r in rows})
    lines = ["horizontalChannel, variant %s, on %s, spin-up "
             "%s s, one variant at a time "
             "(`PYTHONPATH=src/python /usr/bin/python3 "
             "benchmarks/scripts/tutorialWorkPrecision.py --platform %s`, or "
             "`benchmarks/run tutorial`). CPU: the solver's last ExecutionTime; "
             "+- one standard error (jackknife over groups of whole parcels)."
             % (", ".join(variants), ", ".join(platforms), ", ".join(spin_ups),
                platforms[0]), "",
             "| sweep | parcels | sampling [s] | dt [ms] | CPU [s] | wall [s] | "
             "upper-half fraction | rms wall-normal velocity [m/s] | RMS s.e. "
             "concentration | lower-wall impacts per parcel per m | mean k_n |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in sorted(rows, key=lambda r: float(r["cpu"])):
        lines.append("| %s | %s | %s | %g | %.1f | %.1f | %.4f +- %.4f | "
                     "%.4f +- %.4f | %s | %.4g | %.3g |" % (
                         r["sweeps"], r["parcels"], r["sampling"],
                         1e3*float(r["dt"]), float(r["cpu"]), float(r["wall"]),
                         float(r["upperFraction"]), float(r["upperFraction_se"]),
                         float(r["UyRms"]), float(r["UyRms_se"]),
                         r["concentration_se_rms"], float(r["impacts_lower"]),
                         float(r["kn_mean"])))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(bc.RESULTS, "tutorial.md"), "w") as f:
        f.write(text)
    print(text)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--work", default=os.path.join(bc.ROOT, "build",
                                                  "benchmarks", "tutorial"))
    p.add_argument("--platform", default=fc.DEFAULT_PLATFORM,
                   choices=fc.FOUNDATION_PLATFORMS)
    p.add_argument("--variant", default="rough5",
                   help="file of the tutorial's particles/constant/variants")
    p.add_argument("--quick", action="store_true")
    p.add_argument("--plot-only", action="store_true")
    args = p.parse_args()
    bc.ensure_dirs()
    if not args.plot_only:
        info = bc.write_machine("tutorial")
        print(bc.machine_markdown(info))
        measure(args)
    elif not os.path.exists(os.path.join(bc.RESULTS,
                                         "tutorial-work-precision.csv")):
        print("tutorialWorkPrecision: no stored results "
              "(benchmarks/run tutorial measures them)")
        return
    rows = load()
    table(rows)
    figure(analyse(rows))


if __name__ == "__main__":
    main()
