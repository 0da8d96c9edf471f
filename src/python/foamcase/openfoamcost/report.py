# roughWallInteraction benchmarks: the OpenFOAM cost benchmark, report writing.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""Report writing of the OpenFOAM cost benchmark: the summaries, the
tables (benchmarks/results/openfoam-cost.<tag>.md,
openfoam-callgrind.<tag>.md, openfoam-tutorial-cost[.tag].md) and the
figure docs/figures/bench-openfoam-scaling-<tag>.png.
"""
import os
import statistics

from foamcase import bench as bc
import foamcase as fc

from .case import (BASE, L, MODEL_FILE, TUTORIAL_BASE, TUTORIAL_LIB_VARIANTS,
                   TUTORIAL_VARIANTS, TWO_BOXES, variants_of)
from .parse import baseline_name


PLATFORM_NAMES = {p: fc.platforms.display_name(p) for p in fc.PLATFORMS}
#: Tags of results taken on openfoam.org's packaged OpenFOAM (/opt/openfoamNN,
#: OpenFOAM's own -O3), run by openfoamCost.py directly
PACKAGE_TAG = "-package"


def write_markdown(name, lines):
    """A table's lines to benchmarks/results/name and to the terminal"""
    text = "\n".join(lines) + "\n"
    with open(os.path.join(bc.RESULTS, name), "w") as f:
        f.write(text)
    print(text)


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


def command_of(tag, platform, baseline=""):
    """The benchmarks/run command of a result (baseline: the directory of
    the rough-base library, build/benchmarks/baseline-<rev>/lib/...)"""
    if tag.endswith(PACKAGE_TAG):
        return ("PYTHONPATH=src/python etc/openfoamEnv %s /usr/bin/python3 "
                "benchmarks/scripts/openfoamCost.py --platform %s --tag %s "
                "--parcels 10000 --rounds 3 --mpi 0" % (platform, platform, tag))
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
                "collidingCloud" if fc.Platform(platform).foundation else
                "%s (colliding cloud)" % fc.Platform(platform).solver("colliding"),
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
    if tag.endswith(PACKAGE_TAG):
        lines += ["", "%s is openfoam.org's package (/opt/%s, OpenFOAM's own "
                  "-O3 build, as users install it); libroughWallInteraction.so "
                  "is -O3." % (PLATFORM_NAMES.get(platform, platform), platform)]
    elif platform == "openfoam13":
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
    write_markdown("openfoam-cost.%s.md" % tag, lines)


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
    # Only the results with several parcel counts draw a line: each of them
    # gets a line style
    lines = []
    for tag, summary in sorted(summaries.items()):
        serial = [s for s in summary if s["np"] == 1 and s["mesh"] == "box"]
        if len(serial) >= 2:
            lines.append((tag, serial))
    if not lines:
        # (a run of one parcel count, e.g. a --tag of its own, must not
        # overwrite the figure of the full runs with an empty one)
        plt.close(fig)
        return
    for (tag, serial), ls in zip(lines, styles):
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


def callgrind_table(tag, rows):
    """Instructions per wall hit: whole run and the model's correct()"""
    platform = rows[0]["platform"]
    by = {r["variant"]: r for r in rows}
    st = by.get("standard")
    lines = ["%s (%s): callgrind of `%s` in the box, %s parcels, %s s "
             "simulated (`%s`, its `--callgrind` step). Instructions per "
             "wall hit; correct() is called once per hit." % (
                 PLATFORM_NAMES.get(platform, platform), tag,
                 fc.Platform(platform).solver("colliding"),
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
    write_markdown("openfoam-callgrind.%s.md" % tag, lines)


def tutorial_stem(tag):
    """Name of the tutorial's results in benchmarks/results (without .csv,
    .md): openfoam-tutorial-cost[.tag]"""
    return "openfoam-tutorial-cost" + ("." + tag if tag else "")


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
    platform = r0.get("platform") or fc.platforms.UNRECORDED_PLATFORM
    if tag and tag.endswith(PACKAGE_TAG):
        command = ("`PYTHONPATH=src/python etc/openfoamEnv %s /usr/bin/python3 "
                   "benchmarks/scripts/openfoamCost.py --platform %s --tag %s "
                   "--tutorial --rounds %d`" % (platform, platform, tag,
                                                len({r["round"] for r in rows})))
        build = ("openfoam.org's package (/opt/%s, OpenFOAM's own -O3)"
                 % platform)
    else:
        command = ("`benchmarks/run --platform %s openfoam`, its "
                   "`openfoamCost.py --tutorial` step" % platform)
        build = "the project's build"
    text = ["%s (%s), tutorial incompressibleFluid/horizontalChannel "
            "(195 um, %s parcels, %s s spin-up + %s s sampled, dt = 1 ms), "
            "each variant by the tutorial's Allrun, serial, %d rounds, the "
            "order reversed every other round; load average %.1f-%.1f "
            "(%s)." % (
                PLATFORM_NAMES.get(platform, platform), build,
                r0["parcels"], r0["spin_up"], r0["sampling"],
                len({r["round"] for r in rows}), min(loads), max(loads),
                command), "",
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
    write_markdown(tutorial_stem(tag) + ".md", text)
