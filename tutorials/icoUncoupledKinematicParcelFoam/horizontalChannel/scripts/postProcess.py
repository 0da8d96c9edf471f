#!/usr/bin/python3
"""Profiles, wall-hit statistics, figures and the summary of horizontalChannel.

Reads, for each tracking case, the parcel samples collected by
collectSamples.py (CASE/parcelSamples.npz), the roughWallInteraction
statistics under CASE/postProcessing/ and CASE/caseInfo (written by Allrun),
and writes into OUT_DIR:

  profiles.csv          per variant and height bin: y/H, normalised number
                        concentration, mean and rms of the streamwise and
                        wall-normal parcel velocity, standard error of each
  summary.csv           per variant: fraction of parcels in the upper half,
                        mean height, wall hits per parcel per metre, mean k_n
                        and k_t, wall-clock time of the run
  concentration_d*.png  concentration profiles of all variants
  velocity_d*.png       velocity profiles of all variants
  wallHits_d*.png       wall-hit statistics
  spinUp_d*.png         approach to the statistically steady state

Statistics: the parcels do not interact (one-way coupling, no parcel-parcel
collisions), so they are independent realisations. They are split into
N_GROUPS groups by their id; the standard error of every statistic is the
jackknife (leave-one-group-out) estimate over the groups. The samples of one
parcel at different times are correlated; keeping whole parcels in one group
makes the estimate account for that.

Usage: postProcess.py OUT_DIR CASE_DIR [CASE_DIR ...]
"""
import csv
import sys
from pathlib import Path

import numpy as np

from foamio import read_list

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

N_BINS = 25
N_GROUPS = 20
MIN_SAMPLES = 10        # velocity statistics of a bin need this many samples
WALLS = ("lowerWall", "upperWall")
EPS_TIME = 1e-9


# ----------------------------------------------------------------------------
# Reading

def read_case_info(case):
    info = {}
    for line in (case / "caseInfo").read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            key, value = line.split(None, 1)
            try:
                info[key] = float(value)
            except ValueError:
                info[key] = value.strip()
    return info


def read_model_statistics(case):
    """Rows of roughWallInteraction.dat (cumulative totals) as a dict of arrays."""
    files = sorted(case.glob("postProcessing/lagrangian/kinematicCloud/"
                             "patchInteractionModel/*/roughWallInteraction.dat"))
    if not files:
        return None
    names, rows = None, []
    for f in files:                 # restarts write one directory per start time
        for line in f.read_text().splitlines():
            if line.startswith("# Time"):
                names = line[1:].split()
            elif line.strip() and not line.startswith("#"):
                rows.append([float(v) for v in line.split()])
    data = np.array(rows)
    return {n: data[:, i] for i, n in enumerate(names)}


def window_model_statistics(stats, t0, t1):
    """Hits, mean k_n, k_t and facet tilt of the hits between t0 and t1.

    The file holds running totals and running means over all hits; the
    window values follow from the differences of hits x mean.
    """
    time = stats["Time"]
    i0 = max(np.searchsorted(time, t0 + EPS_TIME) - 1, 0)
    i1 = max(np.searchsorted(time, t1 + EPS_TIME) - 1, 0)
    out = {}
    for wall in WALLS:
        if f"{wall}_hits" not in stats:
            continue
        h = stats[f"{wall}_hits"]
        dh = h[i1] - h[i0]
        out[f"{wall}_modelHits"] = dh
        for col, key in (("meanKn", "kn"), ("meanKt", "kt"), ("meanGamma", "gammaDeg"),
                         ("facetPerHit", "facetPerHit")):
            m = stats[f"{wall}_{col}"]
            out[f"{wall}_{key}"] = (m[i1]*h[i1] - m[i0]*h[i0])/dh if dh > 0 else np.nan
    return out


# ----------------------------------------------------------------------------
# Statistics

def jackknife(stat, sums):
    """Value and jackknife standard error of stat(sums) over the groups.

    sums: dict of arrays with a leading group axis; stat maps a dict of
    arrays without that axis (the pooled sums) to the statistic.
    """
    total = {k: v.sum(axis=0) for k, v in sums.items()}
    value = np.asarray(stat(total), float)
    g = next(iter(sums.values())).shape[0]
    loo = np.array([stat({k: total[k] - v[i] for k, v in sums.items()}) for i in range(g)],
                   float)
    with np.errstate(invalid="ignore"):
        centred = loo - np.mean(loo, axis=0)
        se = np.sqrt((g - 1)/g*np.sum(centred**2, axis=0))
    se = np.where(np.isfinite(value), se, np.nan)
    return value, se


def analyse(case):
    info = read_case_info(case)
    H, d = info["height"], info["diameter"]
    r = 0.5*d
    s = np.load(case / "parcelSamples.npz")
    time, count = s["time"], s["count"]
    snap = np.repeat(np.arange(len(time)), count)
    y = s["y"].astype(float) + r        # tracking coordinate -> channel height
    ux, uy = s["Ux"].astype(float), s["Uy"].astype(float)
    spin = 0.5*d*s["omegaZ"].astype(float)     # surface speed of the spin [m/s]
    group = s["id"] % N_GROUPS

    # Spin-up history: every write time
    up = y > 0.5*H
    history = np.array([(t, np.mean(up[snap == i]), np.mean(ux[snap == i]),
                         np.mean(spin[snap == i])) for i, t in enumerate(time)])

    # Sampling window: write times from the end of the spin-up on
    sampled = np.nonzero(time >= info["spinUp"] - EPS_TIME)[0]
    if len(sampled) < 2:
        raise RuntimeError(f"{case}: fewer than 2 snapshots after the spin-up")
    t0, t1 = time[sampled[0]], time[sampled[-1]]
    mask = snap >= sampled[0]
    y, ux, uy, spin = y[mask], ux[mask], uy[mask], spin[mask]
    group, snap = group[mask], snap[mask]

    edges = np.linspace(r, H - r, N_BINS + 1)
    b = np.clip(np.searchsorted(edges, y, side="right") - 1, 0, N_BINS - 1)
    sums = {}
    for k, w in (("n", np.ones_like(y)), ("ux", ux), ("uy", uy),
                 ("ux2", ux*ux), ("uy2", uy*uy)):
        a = np.zeros((N_GROUPS, N_BINS))
        np.add.at(a, (group, b), w)
        sums[k] = a
    width = edges[1] - edges[0]

    def concentration(t):
        return t["n"]/t["n"].sum()*(H - d)/width

    def mean(key):
        def f(t):
            with np.errstate(invalid="ignore", divide="ignore"):
                return np.where(t["n"] >= MIN_SAMPLES, t[key]/t["n"], np.nan)
        return f

    def rms(key, key2):
        def f(t):
            with np.errstate(invalid="ignore", divide="ignore"):
                n = t["n"]
                m = t[key]/n
                var = np.maximum(t[key2]/n - m*m, 0)*n/(n - 1)
                return np.where(n >= MIN_SAMPLES, np.sqrt(var), np.nan)
        return f

    prof = {"y_over_H": 0.5*(edges[:-1] + edges[1:])/H, "samples": sums["n"].sum(axis=0)}
    prof["concentration"], prof["concentration_se"] = jackknife(concentration, sums)
    for name, fun in (("Ux_mean", mean("ux")), ("Uy_mean", mean("uy")),
                      ("Ux_rms", rms("ux", "ux2")), ("Uy_rms", rms("uy", "uy2"))):
        prof[name], prof[name + "_se"] = jackknife(fun, sums)

    # Upper-half fraction, mean height and mean streamwise velocity, over the
    # window and over its first and second halves (drift check)
    late = (time[snap] > 0.5*(t0 + t1)).astype(int)
    scal = {}
    for k, w in (("n", np.ones_like(y)), ("up", (y > 0.5*H).astype(float)),
                 ("y", y/H), ("ux", ux), ("spin", spin)):
        a = np.zeros((N_GROUPS, 2))
        np.add.at(a, (group, late), w)
        scal[k] = a
    summary = dict(info)
    for name, fun in (
            ("upperFraction", lambda t: t["up"].sum()/t["n"].sum()),
            ("upperFractionEarly", lambda t: t["up"][0]/t["n"][0]),
            ("upperFractionLate", lambda t: t["up"][1]/t["n"][1]),
            ("meanHeight", lambda t: t["y"].sum()/t["n"].sum()),
            ("meanUx", lambda t: t["ux"].sum()/t["n"].sum()),
            ("meanUxEarly", lambda t: t["ux"][0]/t["n"][0]),
            ("meanUxLate", lambda t: t["ux"][1]/t["n"][1]),
            ("meanSpinSpeed", lambda t: t["spin"].sum()/t["n"].sum())):
        summary[name], summary[name + "_se"] = (float(v) for v in jackknife(fun, scal))
    summary.update(snapshots=len(sampled), samples=int(mask.sum()), sampleStart=t0,
                   sampleEnd=t1)

    # Wall hits in the window, per parcel and metre travelled
    travelled = info["nParcels"]*summary["meanUx"]*(t1 - t0)
    hits = s["wallHits"]
    model = read_model_statistics(case)
    mstats = window_model_statistics(model, t0, t1) if model is not None else {}
    for j, wall in enumerate(WALLS):
        summary[f"impactsPerParcelPerMetre_{wall}"] = \
            (hits[sampled[-1], j] - hits[sampled[0], j])/travelled
        if f"{wall}_modelHits" in mstats:
            summary[f"hitsPerParcelPerMetre_{wall}"] = mstats[f"{wall}_modelHits"]/travelled
            for key in ("kn", "kt", "gammaDeg", "facetPerHit"):
                summary[f"{key}_{wall}"] = mstats[f"{wall}_{key}"]
    if mstats:
        w = np.array([mstats.get(f"{wall}_modelHits", 0) for wall in WALLS])
        for key in ("kn", "kt"):
            v = np.array([mstats.get(f"{wall}_{key}", np.nan) for wall in WALLS])
            ok = w > 0
            summary[f"{key}_mean"] = float(np.sum(w[ok]*v[ok])/w[ok].sum()) if ok.any() \
                else np.nan
    elif info.get("wallModel") == "smooth":
        # standardWallInteraction rebound: k_n = e, k_t = 1 - mu by construction
        summary["kn_mean"] = info["e"]
        summary["kt_mean"] = 1 - info["mu"]
    return info, prof, summary, history


# ----------------------------------------------------------------------------
# Output

PROFILE_COLUMNS = ["y_over_H", "concentration", "concentration_se",
                   "Ux_mean", "Ux_mean_se", "Uy_mean", "Uy_mean_se",
                   "Ux_rms", "Ux_rms_se", "Uy_rms", "Uy_rms_se", "samples"]

SUMMARY_COLUMNS = [
    "variant", "wallModel", "roughnessAngle", "diameter", "nParcels", "nProcs",
    "sampleStart", "sampleEnd", "snapshots", "samples",
    "upperFraction", "upperFraction_se", "upperFractionEarly", "upperFractionEarly_se",
    "upperFractionLate", "upperFractionLate_se", "meanHeight", "meanHeight_se",
    "meanUx", "meanUx_se", "meanUxEarly", "meanUxEarly_se", "meanUxLate", "meanUxLate_se",
    "meanSpinSpeed", "meanSpinSpeed_se",
    "hitsPerParcelPerMetre_lowerWall", "hitsPerParcelPerMetre_upperWall",
    "impactsPerParcelPerMetre_lowerWall", "impactsPerParcelPerMetre_upperWall",
    "kn_mean", "kt_mean", "kn_lowerWall", "kt_lowerWall", "kn_upperWall", "kt_upperWall",
    "gammaDeg_lowerWall", "gammaDeg_upperWall", "facetPerHit_lowerWall",
    "facetPerHit_upperWall", "wallClock"]


def fmt(v):
    if isinstance(v, str):
        return v
    return "" if v is None or not np.isfinite(v) else "%.6g" % v


def write_profiles(path, results):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["variant", "diameter_m", "bin"] + PROFILE_COLUMNS)
        for info, prof, _, _ in results:
            for i in range(N_BINS):
                w.writerow([info["variant"], "%g" % info["diameter"], i]
                           + [fmt(prof[c][i]) for c in PROFILE_COLUMNS])


def write_summary(path, results):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(SUMMARY_COLUMNS)
        for _, _, s, _ in results:
            w.writerow([fmt(s.get(c)) for c in SUMMARY_COLUMNS])


def label(info):
    if info.get("wallModel") == "rough":
        return "rough, $\\Delta$ = %g$^\\circ$" % info["roughnessAngle"]
    return "smooth"


def tag(d):
    return "d%dum" % round(d*1e6)


def title(d):
    return "glass beads %d $\\mu$m, air 20 m/s, H = 35 mm" % round(d*1e6)


def plot_concentration(path, results, d):
    fig, ax = plt.subplots(figsize=(5.6, 5.4))
    for info, prof, s, _ in results:
        c, se, y = prof["concentration"], prof["concentration_se"], prof["y_over_H"]
        ok = c > 0
        ax.errorbar(c[ok], y[ok], xerr=se[ok], marker="o", ms=3.5, capsize=2, lw=1.2,
                    label="%s: %.1f %% in upper half" % (label(info), 100*s["upperFraction"]))
        if info.get("wallModel") == "smooth" and s["upperFraction"] == 0 and ok.sum() <= 2:
            ax.annotate("smooth: every parcel\nslides along the\nlower wall", (c[ok][0], y[ok][0]),
                        xytext=(-10, 40), textcoords="offset points", ha="right", fontsize=7.5,
                        arrowprops=dict(arrowstyle="->", lw=0.8))
    ax.set_xscale("log")
    ax.axvline(1, color="0.6", lw=0.8, ls=":")
    ax.axhline(0.5, color="0.6", lw=0.8, ls=":")
    ax.set_xlabel("normalised number concentration $n/\\bar{n}$  (log scale)")
    ax.set_ylabel("$y/H$")
    ax.set_ylim(0, 1)
    ax.set_title("Concentration, " + title(d), fontsize=9)
    ax.legend(fontsize=7.5, loc="upper right")
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_velocity(path, results, d, carrier):
    fig, axs = plt.subplots(1, 4, figsize=(13, 4.6), sharey=True)
    panels = [("Ux_mean", "mean streamwise $U_{p}$ [m/s]"),
              ("Uy_mean", "mean wall-normal $V_{p}$ [m/s]"),
              ("Ux_rms", "rms $u'_{p}$ [m/s]"), ("Uy_rms", "rms $v'_{p}$ [m/s]")]
    for ax, (col, xlabel) in zip(axs, panels):
        for info, prof, _, _ in results:
            v, se, y = prof[col], prof[col + "_se"], prof["y_over_H"]
            ok = np.isfinite(v)
            ax.errorbar(v[ok], y[ok], xerr=se[ok], marker="o", ms=3, capsize=2, lw=1.1,
                        label=label(info))
        ax.set_xlabel(xlabel)
        ax.grid(alpha=0.3)
    if carrier is not None:
        axs[0].plot(carrier[1], carrier[0], "k--", lw=1, label="air (RANS)")
    axs[0].set_ylabel("$y/H$")
    axs[0].set_ylim(0, 1)
    axs[0].legend(fontsize=8)
    fig.suptitle("Parcel velocity, " + title(d) + " (bins with at least %d samples)"
                 % MIN_SAMPLES, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_wall_hits(path, results, d):
    names = [label(info) for info, _, _, _ in results]
    x = np.arange(len(names))
    fig, axs = plt.subplots(1, 3, figsize=(14, 4.2))
    for i, wall in enumerate(WALLS):
        model = [s.get(f"hitsPerParcelPerMetre_{wall}", np.nan) for _, _, s, _ in results]
        impacts = [s.get(f"impactsPerParcelPerMetre_{wall}", np.nan)
                   for _, _, s, _ in results]
        axs[0].bar(x + (i - 0.5)*0.38, model, 0.38, label=wall + " (model)")
        axs[0].plot(x + (i - 0.5)*0.38, impacts, "k_", ms=14, mew=2,
                    label="impacts > 5 cm/s" if i == 0 else None)
    axs[0].set_ylabel("wall hits per parcel per metre")
    axs[0].set_title("hits (bars: roughWallInteraction's count)", fontsize=9)
    for j, (key, name) in enumerate((("kn", "mean $k_n$"), ("kt", "mean $k_t$"))):
        ax = axs[1 + j]
        for i, wall in enumerate(WALLS):
            vals = [s.get(f"{key}_{wall}", s.get(f"{key}_mean", np.nan))
                    for _, _, s, _ in results]
            ax.bar(x + (i - 0.5)*0.38, vals, 0.38, label=wall)
        ax.set_ylabel(name)
        ax.set_title(name + " per hit (smooth: e and 1 - mu, by construction)", fontsize=9)
    for ax in axs:
        ax.set_xticks(x)
        ax.set_xticklabels(names, fontsize=8)
        ax.grid(alpha=0.3, axis="y")
        ax.legend(fontsize=7.5)
    fig.suptitle("Wall-hit statistics over the sampling window, " + title(d), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_spin_up(path, results, d):
    fig, axs = plt.subplots(1, 3, figsize=(14, 4))
    for info, _, s, hist in results:
        line, = axs[0].plot(hist[:, 0], 100*hist[:, 1], label=label(info))
        axs[1].plot(hist[:, 0], hist[:, 2], color=line.get_color())
        axs[2].plot(hist[:, 0], hist[:, 3], color=line.get_color())
    for ax in axs:
        ax.axvline(results[0][2]["sampleStart"], color="k", ls=":", lw=1)
        ax.set_xlabel("time [s]")
        ax.grid(alpha=0.3)
    axs[0].set_ylabel("parcels in the upper half [%]")
    axs[1].set_ylabel("mean streamwise parcel velocity [m/s]")
    axs[2].set_ylabel("mean spin, surface speed $\\omega_z d/2$ [m/s]")
    axs[0].legend(fontsize=8)
    fig.suptitle("Spin-up (dotted: start of sampling), " + title(d), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def carrier_profile(info):
    """(y/H, U) of the air, from the carrier run."""
    try:
        carrier, time = Path(info["carrier"]), "%s" % info["carrierTime"]
        if not (carrier / time).is_dir():
            time = "%g" % info["carrierTime"]
        y = read_list(carrier / time / "Cy")
        U = read_list(carrier / time / "U")[:, 0]
        order = np.argsort(y)
        return y[order]/info["height"], U[order]
    except (KeyError, OSError, ValueError):
        return None


def print_summary(results):
    print("\nhorizontalChannel: statistics over the sampling window (standard errors in "
          "brackets)")
    head = ("%-9s %4s %8s %15s %15s %14s %7s %12s %7s %10s %10s %6s %6s %8s"
            % ("variant", "d", "samples", "upper half [%]", "drift [%]", "<y>/H",
               "<Up>", "drift [m/s]", "<spin>", "hits/m low", "hits/m up", "k_n", "k_t",
               "wall [s]"))
    print(head)
    print("-"*len(head))
    for info, prof, s, _ in results:
        drift = s["upperFractionLate"] - s["upperFractionEarly"]
        drift_se = np.hypot(s["upperFractionLate_se"], s["upperFractionEarly_se"])
        hl = s.get("hitsPerParcelPerMetre_lowerWall", s["impactsPerParcelPerMetre_lowerWall"])
        hu = s.get("hitsPerParcelPerMetre_upperWall", s["impactsPerParcelPerMetre_upperWall"])
        udrift = s["meanUxLate"] - s["meanUxEarly"]
        udrift_se = np.hypot(s["meanUxLate_se"], s["meanUxEarly_se"])
        print("%-9s %4.0f %8d %7.2f (%4.2f) %7.2f (%4.2f) %6.3f (%5.3f) %7.2f %5.2f (%4.2f) "
              "%7.2f %10.3g %10.3g %6.3g %6.3g %8.1f" % (
                  info["variant"], 1e6*info["diameter"], s["samples"],
                  100*s["upperFraction"], 100*s["upperFraction_se"], 100*drift,
                  100*drift_se, s["meanHeight"], s["meanHeight_se"], s["meanUx"],
                  udrift, udrift_se, s["meanSpinSpeed"], hl, hu,
                  s.get("kn_mean", np.nan), s.get("kt_mean", np.nan),
                  s.get("wallClock", np.nan)))
    print("d: bead diameter [um]; upper half: parcels above y = H/2 (50 % = uniform);\n"
          "drift: second half of the sampling window minus first half; <Up>: mean "
          "streamwise parcel velocity [m/s];\n<spin>: mean surface speed of the spin, "
          "omega_z d/2 [m/s]; hits/m: wall hits per parcel per metre travelled\n(smooth: "
          "impacts faster than 5 cm/s); k_n, k_t: mean restitution ratios per hit; wall: "
          "wall-clock time of the tracking run [s].")


def main():
    out = Path(sys.argv[1])
    cases = [Path(c) for c in sys.argv[2:]]
    out.mkdir(parents=True, exist_ok=True)
    results = [analyse(c) for c in cases]
    write_profiles(out / "profiles.csv", results)
    write_summary(out / "summary.csv", results)
    for d in sorted({r[0]["diameter"] for r in results}):
        sub = [r for r in results if r[0]["diameter"] == d]
        plot_concentration(out / f"concentration_{tag(d)}.png", sub, d)
        plot_velocity(out / f"velocity_{tag(d)}.png", sub, d, carrier_profile(sub[0][0]))
        plot_wall_hits(out / f"wallHits_{tag(d)}.png", sub, d)
        plot_spin_up(out / f"spinUp_{tag(d)}.png", sub, d)
    print_summary(results)


if __name__ == "__main__":
    main()
