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
                        rms wall-normal parcel velocity, mean height, wall
                        hits per parcel per metre, mean k_n and k_t, wall-clock
                        and CPU time of the run
  concentration.png     concentration profiles of all variants
  velocity.png          velocity profiles of all variants
  wallHits.png          wall-hit statistics
  spinUp.png            approach to the statistically steady state
  spinRatios.csv        per variant: quantiles of the spin ratio Gamma, Re_p
                        and Re_R of the beads, and the fraction of samples
                        outside the range of each rotational-lift coefficient
  spinRatios.png        their distributions

Spin ratios: from each parcel sample's velocity and spin and the air at its
height (the mapped RANS profile u(y) and its rotation -0.5 du/dy about z):
U_rel = u(y) x - U_p, Omega_rel = -0.5 du/dy z - omega_p, Re_p = |U_rel| d/nu,
Re_R = |Omega_rel| d^2/nu, Gamma = Re_R/(2 Re_p). The lift in the run uses
the air velocity with the dispersion model's fluctuation, which is not
written: these are the ratios of the mean flow.

Statistics: in the variants without loading the parcels do not interact
(one-way coupling, no parcel-parcel collisions), so they are independent
realisations. They are split into N_GROUPS groups by their id; the standard
error of every statistic is the jackknife (leave-one-group-out) estimate
over the groups. In the loading variants the parcels act on each other,
through the air and through collisions: there the groups are N_BLOCKS
consecutive time blocks of the sampling window instead. The samples of one
parcel at different times are correlated; keeping whole parcels in one group
makes the estimate account for that. The wall statistics (impacts, the
rough-wall model's impulse-weighted k_n and k_t) exist only as totals over
all parcels at each write time: their standard error is the jackknife over
N_BLOCKS consecutive blocks of the sampling window, each a sum over
thousands of independent parcels (the blocks are longer than a bead's
velocity relaxation time, so neighbouring blocks are nearly uncorrelated).

Loading variants (massLoading in caseInfo), also in summary.csv: the mass
loading reached (bead over air mass flux), the collisions between beads
per bead per second (the Sommerfeld model's log line of every step), the
wall impacts per bead per second, and the air's pressure gradient (the
meanVelocityForce's log line of every step), each a mean over the sampling
window with the block-jackknife standard error; loading.png draws their
profiles and the air's velocity at the end of the run.

Usage: postProcess.py OUT_DIR CASE_DIR [CASE_DIR ...]
"""
import csv
import os
import re
import subprocess
import sys

import numpy as np

import foamcase as fc
from foamcase import tutorial as tc

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

N_BINS = 25
N_GROUPS = 20
N_BLOCKS = 10           # time blocks of the wall statistics' jackknife
MODEL_SAMPLES = 20000   # roughWallStats' Monte Carlo samples per angle
#: The columns of the angle file summed over the walls
ANGLE_COLUMNS = ("hits", "ktSamples", "sumVnIn", "sumVnOut", "sumVtIn",
                 "sumVtOut", "rebounds")
QUANTILES = (0.01, 0.1, 0.5, 0.9, 0.99)
# Documented ranges of the rotational-lift coefficients (docs/spin.md)
OESTERLE_RANGE = {"Rep": (10, 140), "Gamma": (1, 6)}
LOTH_RANGE = {"Rep": (0, 2000), "Gamma": (0, 10)}     # Omega* = 2 Gamma < 20
# Range of Mei's (1992) fit of the shear lift (SaffmanMeiLiftForce), as quoted
# with Mei (1992), Crowe et al. (2012) and the Fluent Theory Guide by the
# public Python module lift_laws (J. Aguirre): 0.1 <= Re_p <= 100 and
# 0.005 <= beta <= 0.4, beta = Re_w/(2 Re_p), Re_w = |curl U| d^2/nu
# (OpenFOAM's beta); Mei's paper itself not read (README)
MEI_RANGE = {"Rep": (0.1, 100), "beta": (0.005, 0.4)}
# OpenFOAM's sphereDrag (Amsden et al. 1987, as its header cites):
# C_d Re = 24 (1 + Re^(2/3)/6) up to Re_p = 1000, 0.424 Re_p above (the
# source's CdRe); the fraction of samples above the switch is reported
SPHERE_DRAG_SWITCH = 1000
MIN_SAMPLES = 10        # velocity statistics of a bin need this many samples
WALLS = tc.WALLS
EPS_TIME = 1e-9
MARKERS = ("s", "o", "^", "v", "D", "P")


# ----------------------------------------------------------------------------
# Reading

def read_model_statistics(case):
    """Rows of roughWallInteraction.dat (cumulative totals) as a dict of
    arrays, or None (a variant without the rough-wall model)."""
    try:
        names, rows = fc.read_statistics(case, tc.CLOUD)
    except fc.FoamError:
        return None
    return {n: np.array([r[n] for r in rows]) for n in names}


RANGE_LINE = re.compile(r"^\s*(rotationalLift|fluidTorque) \((\w+)\): (\d+) of (\d+) "
                        r"evaluations outside")
TIME_LINE = re.compile(r"^Time = (%s)s?$" % fc.NUMBER)


def log_lines(case):
    """(time, line) of every line of the case's log.foamRun after its first
    time step's "Time = " line (time: that of the step the line is in)"""
    time = None
    with open(os.path.join(case, "log.foamRun")) as f:
        for line in f:
            m = TIME_LINE.match(line)
            if m:
                time = float(m.group(1))
            elif time is not None:
                yield time, line


def in_run_range_counts(case, t0, t1):
    """How many of the spin models' evaluations the run itself counted
    outside their correlation's range (the log's line at the end of every
    evolve, docs/spin.md), summed over the time steps ending in (t0, t1]:
    {liftEvaluations, liftOutside, torqueEvaluations, torqueOutside}; a
    model that is not selected has no entry."""
    out = {}
    for time, line in log_lines(case):
        m = RANGE_LINE.match(line)
        if m and t0 + EPS_TIME < time <= t1 + EPS_TIME:
            key = "lift" if m.group(1) == "rotationalLift" else "torque"
            out[key + "Outside"] = out.get(key + "Outside", 0) + int(m.group(3))
            out[key + "Evaluations"] = out.get(key + "Evaluations", 0) + int(m.group(4))
    return out


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


def read_angle_bins(case):
    """The angle file of the model (incidenceAngleBins; running totals at
    every write time, per wall and bin) summed over the walls: a dict of
    arrays [write time, bin] and Time, or None (no angle file)."""
    try:
        _, rows = fc.read_statistics(case, tc.CLOUD, fc.ANGLE_STATISTICS)
    except fc.FoamError:
        return None
    times = sorted({r["Time"] for r in rows})
    row_of = {t: i for i, t in enumerate(times)}
    n_bins = int(max(r["bin"] for r in rows)) + 1
    out = {c: np.zeros((len(times), n_bins)) for c in ANGLE_COLUMNS}
    for r in rows:
        if r["patch"] in WALLS:
            for c in ANGLE_COLUMNS:
                out[c][row_of[r["Time"]], int(r["bin"])] += r[c]
    out["Time"] = np.array(times)
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


def angle_bins(case, info, bt):
    """Per bin of the incidence angle (both walls): the impulse-weighted
    k_n = sum v''_n/sum |v'_n| and k_t = sum v''_t/sum |v'_t|, the
    fractions of the hits by incidence angle and by rebound angle, each
    with its block-jackknife error over the time blocks ending at the
    times bt; and the model's values at the run's Delta, e, mu0, muD
    (model_bins).  None without an angle file."""
    a = read_angle_bins(case)
    if a is None:
        return None
    idx = np.searchsorted(a["Time"], bt + EPS_TIME) - 1
    blocks = {}
    for c in ANGLE_COLUMNS:
        running = np.vstack([np.zeros((1, a[c].shape[1])), a[c]])
        blocks[c] = np.diff(running[idx + 1], axis=0)

    def ratio(num, den):
        return lambda t: np.where(t[den] > 0, t[num]/np.where(t[den] > 0, t[den], 1),
                                  np.nan)

    out = {}
    for key, fun in (("kn", ratio("sumVnOut", "sumVnIn")),
                     ("kt", ratio("sumVtOut", "sumVtIn")),
                     ("hitFraction", lambda t: t["hits"]/t["hits"].sum()),
                     ("reboundFraction", lambda t: t["rebounds"]/t["rebounds"].sum())):
        out[key], out[key + "_se"] = jackknife(fun, blocks)
    out["hits"] = blocks["hits"].sum(axis=0)
    n_bins = len(out["hits"])
    out["angleMin"] = 90.0*np.arange(n_bins)/n_bins
    out["angleMax"] = 90.0*np.arange(1, n_bins + 1)/n_bins
    out.update(model_bins(info, n_bins))
    return out


def model_curve(info, alphas):
    """Mean k_n and k_t of the rough-wall model at the incidence angles
    alphas [deg] (no incident spin), at the run's Delta, e, mu0, muD,
    lateral tilt: roughWallStats' Monte Carlo of the full operator
    (--recollide, as the OpenFOAM model: new facets until the particle
    leaves).  A dict of arrays, or None (no roughWallStats, or no
    roughnessAngle)."""
    stats = os.path.join(os.environ.get("ROUGHWALL_ROOT", ""), "bin", "roughWallStats")
    if not os.path.exists(stats) or not info.get("roughnessAngle"):
        return None
    cmd = [stats, "--Delta", str(info["roughnessAngle"]), "--e", str(info["e"]),
           "--mu0", str(info.get("mu0", info["muD"])), "--mud", str(info["muD"]),
           "--alpha", ",".join("%g" % x for x in alphas), "--method", "montecarlo",
           "--recollide", "--samples", str(MODEL_SAMPLES), "--threads", "1",
           "--digits", "8"]
    if str(info.get("lateralTilt")) in ("on", "true", "yes"):
        cmd.append("--lateral")
    out = subprocess.run(cmd, stdout=subprocess.PIPE, check=True, text=True).stdout
    rows = list(csv.DictReader(out.splitlines()))
    return {k: np.array([float(r[k]) for r in rows])
            for k in ("alpha_deg", "mean_kn", "mean_kt", "se_mean_kn", "se_mean_kt")}


def model_bins(info, n_bins):
    """The model's impulse-weighted k_n, k_t per bin: its mean k_n(alpha),
    k_t(alpha) on a 0.25 deg grid, averaged over the bin with the weight
    sin(alpha) (|v'_n| at one incident speed, alpha uniform in the bin:
    the run's own distribution within a bin is not in the file), and the
    curve itself (model_alpha, model_kn, model_kt) for the figure."""
    alphas = np.arange(0.125, 90, 0.25)
    curve = model_curve(info, alphas)
    if curve is None:
        return {}
    w = np.sin(np.radians(alphas))
    b = np.minimum((alphas/(90.0/n_bins)).astype(int), n_bins - 1)
    out = {"model_alpha": alphas, "model_kn": curve["mean_kn"], "model_kt": curve["mean_kt"]}
    for key in ("kn", "kt"):
        out["model_bin_" + key] = np.array([
            np.sum(w[b == i]*curve["mean_" + key][b == i])/np.sum(w[b == i])
            for i in range(n_bins)])
    return out


def air_profile(case, time="0"):
    """(y', u, du/dy) of the air velocity of a tracking case at a time
    (rows of cells; y' the tracking coordinate): at 0 the mapped carrier
    flow."""
    mesh = tc.read_mesh(case)
    y = mesh.cell_centres[:, 1]
    U = fc.internal_field(os.path.join(case, time, "U"))[:, 0]
    rows, inv = np.unique(np.round(y, 12), return_inverse=True)
    u = np.bincount(inv, weights=U)/np.bincount(inv)
    return rows, u, np.gradient(u, rows)


def kinematic_viscosity(case):
    props = fc.read_text(os.path.join(case, "constant", "physicalProperties"))
    return float(re.search(r"^nu\s+([^;]+);", props, re.M).group(1))


def spin_ratios(case, d, y_track, U, omega):
    """Re_p, Re_R and Gamma of parcel samples (see the docstring)."""
    rows, u, dudy = air_profile(case)
    nu = kinematic_viscosity(case)
    uf = np.interp(y_track, rows, u)
    urel = np.stack([uf - U[:, 0], -U[:, 1], -U[:, 2]], axis=1)
    wrel = -omega.copy()
    wrel[:, 2] += -0.5*np.interp(y_track, rows, dudy)
    Rep = np.linalg.norm(urel, axis=1)*d/nu
    ReR = np.linalg.norm(wrel, axis=1)*d*d/nu
    # Shear Reynolds number of Saffman-Mei: |curl U| = |du/dy| of the mapped
    # air profile at the parcel centre (OpenFOAM interpolates the curl of the
    # cell field: cellPoint; this is its row-averaged estimate)
    ReW = np.abs(np.interp(y_track, rows, dudy))*d*d/nu
    with np.errstate(divide="ignore", invalid="ignore"):
        gamma = ReR/(2*Rep)
        beta = ReW/(2*Rep)
    return Rep, ReR, gamma, beta


def outside(rng, Rep, gamma):
    """Fraction of samples outside a coefficient's (Re_p, Gamma) range."""
    out = (Rep < rng["Rep"][0]) | (Rep > rng["Rep"][1]) \
        | ~(gamma >= rng["Gamma"][0]) | ~(gamma <= rng["Gamma"][1])
    return float(np.mean(out))


def is_loading(info):
    """A loading variant: the air solved with the beads (massLoading)."""
    return isinstance(info.get("massLoading"), float) \
        and "trackingOffset" in info and info["trackingOffset"] == 0


def interacting(info):
    """Parcels that act on each other (through the air or collisions)."""
    return info.get("twoWayCoupling", "false") == "true" \
        or info.get("collisions", "none") != "none"


STEP_SERIES = {
    # name: (pattern of a log line, the last match of a step counts)
    "interParticleFrequency":
        re.compile(r"^\s*Sommerfeld collisions: (%s) per particle per second"
                   % fc.NUMBER),
    "pressureGradient":
        re.compile(r"^\s*Pressure gradient source: .*pressure gradient = (%s)"
                   % fc.NUMBER),
}


def step_series(case, name):
    """(times, values) of a quantity the log writes every step (the last
    value written in a step)."""
    pattern = STEP_SERIES[name]
    values = {}
    for time, line in log_lines(case):
        m = pattern.match(line)
        if m:
            values[time] = float(m.group(1))
    t = np.array(sorted(values))
    return t, np.array([values[x] for x in t])


def block_mean(t, v, t0, t1):
    """Mean over the steps in (t0, t1] and its standard error from
    N_BLOCKS consecutive blocks (the steps of a block are correlated, the
    blocks nearly not)."""
    ok = (t > t0 + EPS_TIME) & (t <= t1 + EPS_TIME)
    v = v[ok]
    if len(v) < N_BLOCKS:
        return np.nan, np.nan
    means = np.array([b.mean() for b in np.array_split(v, N_BLOCKS)])
    return float(v.mean()), float(means.std(ddof=1)/np.sqrt(N_BLOCKS))


def loading_statistics(case, info, summary, t0, t1, ubulk):
    """The loading variants' statistics over the window (see the module's
    docstring); ubulk the air's bulk velocity"""
    out = {}
    mesh = tc.read_mesh(case)
    volume = float(np.prod(mesh.hi - mesh.lo))
    props = fc.read_text(os.path.join(case, "constant", "physicalProperties"))
    rho = float(re.search(r"^rho\s+([^;]+);", props, re.M).group(1))
    cloud = fc.read_text(os.path.join(case, "constant", "cloudProperties"))
    rhoP = float(re.search(r"^\s*rho0\s+([^;]+);", cloud, re.M).group(1))
    mass = rhoP*np.pi/6*info["diameter"]**3
    # The beads the air carries: none one-way (loading0)
    coupled = info.get("twoWayCoupling", "false") == "true"
    beads = info["nParcels"]*info["nParticle"] if coupled else 0
    # Bead mass flux over air mass flux through a cross-section:
    # (beads m_p <u_p>/L)/(rho U_bulk A) = beads m_p <u_p>/(rho U_bulk V)
    scale = beads*mass/(rho*ubulk*volume)
    out["massLoadingReached"] = scale*summary["meanUx"]
    out["massLoadingReached_se"] = scale*summary["meanUx_se"]
    out["beadVolumeFraction"] = beads*np.pi/6*info["diameter"]**3/volume
    for name in STEP_SERIES:
        t, v = step_series(case, name)
        out[name], out[name + "_se"] = block_mean(t, v, t0, t1)
    # Wall impacts per bead per second: per metre times the mean speed
    f, u = summary["impactFrequency"], summary["meanUx"]
    out["wallImpactRate"] = f*u
    out["wallImpactRate_se"] = float(np.hypot(summary["impactFrequency_se"]*u,
                                              f*summary["meanUx_se"]))
    if np.isfinite(out["interParticleFrequency"]):
        out["collisionsPerWallImpact"] = out["interParticleFrequency"]/out["wallImpactRate"]
    # The air at the end of the run (the last write time, which the
    # pruning keeps), for loading.png
    last = max((x for x in os.listdir(case) if re.fullmatch(fc.NUMBER, x)
                and os.path.exists(os.path.join(case, x, "U"))), key=float)
    rows, u_air, _ = air_profile(case, last)
    out["airProfile"] = (rows/info["height"], u_air)
    out["airCentreline"] = float(u_air.max())
    return out


def analyse(case):
    info = tc.read_case_info(case)
    H, d = info["height"], info["diameter"]
    r = 0.5*d
    # Channel height - tracking coordinate: r on the particle-centre
    # domain, 0 on the loading variants' whole channel
    offset = info.get("trackingOffset", r)
    s = np.load(os.path.join(case, "parcelSamples.npz"))
    time, count = s["time"], s["count"]
    snap = np.repeat(np.arange(len(time)), count)
    y = s["y"].astype(float) + offset   # tracking coordinate -> channel height
    ux, uy = s["Ux"].astype(float), s["Uy"].astype(float)
    uz = s["Uz"].astype(float) if "Uz" in s else np.zeros_like(ux)
    omega = np.stack([s[k].astype(float) if k in s else np.zeros_like(ux)
                      for k in ("omegaX", "omegaY", "omegaZ")], axis=1)
    spin = 0.5*d*omega[:, 2]     # surface speed of the spin about z [m/s]

    # Spin-up history: every write time
    up = y > 0.5*H
    history = np.array([(t, np.mean(up[snap == i]), np.mean(ux[snap == i]),
                         np.mean(spin[snap == i]), np.std(uy[snap == i]))
                        for i, t in enumerate(time)])

    # Sampling window: write times from the end of the spin-up on
    sampled = np.nonzero(time >= info["spinUp"] - EPS_TIME)[0]
    if len(sampled) < 2:
        raise RuntimeError("%s: fewer than 2 snapshots after the spin-up" % case)
    t0, t1 = time[sampled[0]], time[sampled[-1]]
    mask = snap >= sampled[0]
    y, ux, uy, uz, spin = y[mask], ux[mask], uy[mask], uz[mask], spin[mask]
    omega = omega[mask]
    snap = snap[mask]
    if interacting(info):
        # Time blocks of the window (parcels that act on each other are
        # not independent realisations)
        n_groups = N_BLOCKS
        group = np.minimum((snap - sampled[0])*N_BLOCKS//len(sampled), N_BLOCKS - 1)
    else:
        n_groups = N_GROUPS
        group = s["id"][mask] % N_GROUPS
    Rep, ReR, gamma, beta = spin_ratios(case, d, y - offset,
                                        np.stack([ux, uy, uz], axis=1), omega)

    edges = np.linspace(r, H - r, N_BINS + 1)
    b = np.clip(np.searchsorted(edges, y, side="right") - 1, 0, N_BINS - 1)
    sums = {}
    for k, w in (("n", np.ones_like(y)), ("ux", ux), ("uy", uy),
                 ("ux2", ux*ux), ("uy2", uy*uy)):
        a = np.zeros((n_groups, N_BINS))
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

    prof = {"y_over_H": 0.5*(edges[:-1] + edges[1:])/H,
            "samples": sums["n"].sum(axis=0)}
    prof["concentration"], prof["concentration_se"] = jackknife(concentration, sums)
    for name, fun in (("Ux_mean", mean("ux")), ("Uy_mean", mean("uy")),
                      ("Ux_rms", rms("ux", "ux2")), ("Uy_rms", rms("uy", "uy2"))):
        prof[name], prof[name + "_se"] = jackknife(fun, sums)

    # Scalars over the window and over its first and second halves (drift)
    late = (time[snap] > 0.5*(t0 + t1)).astype(int)
    scal = {}
    for k, w in (("n", np.ones_like(y)), ("up", (y > 0.5*H).astype(float)),
                 ("y", y/H), ("ux", ux), ("uy", uy), ("uy2", uy*uy),
                 ("ux2", ux*ux), ("uz", uz), ("uz2", uz*uz),
                 ("spin", spin), ("spinX", 0.5*d*omega[:, 0]),
                 ("spinY", 0.5*d*omega[:, 1]),
                 ("spin2", (0.5*d)**2*np.sum(omega**2, axis=1))):
        a = np.zeros((n_groups, 2))
        np.add.at(a, (group, late), w)
        scal[k] = a

    def uy_rms(t, i=slice(None)):
        n = t["n"][i].sum()
        m = t["uy"][i].sum()/n
        return np.sqrt(max(t["uy2"][i].sum()/n - m*m, 0))

    def rms(key):
        def f(t):
            n = t["n"].sum()
            m = t[key].sum()/n
            return np.sqrt(max(t[key + "2"].sum()/n - m*m, 0))
        return f

    ubulk = carrier_statistics(info)["Ubulk"]

    summary = dict(info)
    for name, fun in (
            ("upperFraction", lambda t: t["up"].sum()/t["n"].sum()),
            ("upperFractionEarly", lambda t: t["up"][0]/t["n"][0]),
            ("upperFractionLate", lambda t: t["up"][1]/t["n"][1]),
            ("UyRms", uy_rms),
            ("UyRmsEarly", lambda t: uy_rms(t, slice(0, 1))),
            ("UyRmsLate", lambda t: uy_rms(t, slice(1, 2))),
            ("meanHeight", lambda t: t["y"].sum()/t["n"].sum()),
            ("meanUx", lambda t: t["ux"].sum()/t["n"].sum()),
            ("meanUxEarly", lambda t: t["ux"][0]/t["n"][0]),
            ("meanUxLate", lambda t: t["ux"][1]/t["n"][1]),
            ("meanSpinSpeed", lambda t: t["spin"].sum()/t["n"].sum()),
            ("UxRms", rms("ux")),
            ("UzRms", rms("uz")),
            ("meanUxOverBulk", lambda t: t["ux"].sum()/t["n"].sum()/ubulk),
            ("rmsSpinSpeed", lambda t: np.sqrt(t["spin2"].sum()/t["n"].sum()))):
        summary[name], summary[name + "_se"] = (float(v) for v in jackknife(fun, scal))
    summary.update(snapshots=len(sampled), samples=int(mask.sum()),
                   sampleStart=t0, sampleEnd=t1)

    # Spin ratios of the samples, against the lift coefficients' ranges
    ok = np.isfinite(gamma) & (Rep > 0)
    ratios = {"variant": info["variant"], "lift": info.get("lift", ""),
              "samples": int(ok.sum())}
    for key, v in (("Gamma", gamma[ok]), ("Rep", Rep[ok]), ("ReR", ReR[ok])):
        for q in QUANTILES:
            ratios["%s_q%02d" % (key, round(100*q))] = float(np.quantile(v, q))
    ratios["outsideLoth"] = outside(LOTH_RANGE, Rep[ok], gamma[ok])
    ratios["outsideOesterleBuiDinh"] = outside(OESTERLE_RANGE, Rep[ok], gamma[ok])
    ratios["GammaAbove1"] = float(np.mean(gamma[ok] > 1))
    # Saffman-Mei (every variant) and the drag correlation against their ranges
    meiB, meiR = beta[ok], Rep[ok]
    for q in QUANTILES:
        ratios["betaMei_q%02d" % round(100*q)] = float(np.quantile(meiB, q))
    ratios["outsideSaffmanMei"] = float(np.mean(
        (meiR < MEI_RANGE["Rep"][0]) | (meiR > MEI_RANGE["Rep"][1])
        | ~(meiB >= MEI_RANGE["beta"][0]) | ~(meiB <= MEI_RANGE["beta"][1])))
    ratios["MeiRepAbove"] = float(np.mean(meiR > MEI_RANGE["Rep"][1]))
    ratios["MeiBetaBelow"] = float(np.mean(~(meiB >= MEI_RANGE["beta"][0])))
    ratios["MeiBetaAbove"] = float(np.mean(meiB > MEI_RANGE["beta"][1]))
    ratios["RepAboveDragSwitch"] = float(np.mean(meiR > SPHERE_DRAG_SWITCH))
    summary["outsideLiftRange"] = {
        "Loth": ratios["outsideLoth"],
        "OesterleBuiDinh": ratios["outsideOesterleBuiDinh"]}.get(
            info.get("lift"), np.nan)
    hist = {"gamma": gamma[ok], "Rep": Rep[ok], "ReR": ReR[ok]}

    # Wall hits in the window, per parcel and metre travelled
    travelled = info["nParcels"]*summary["meanUx"]*(t1 - t0)
    # (patchCollisionDensity counts a parcel's hit as nParticle impacts)
    impacts = s["wallImpacts"]/info.get("nParticle", 1)
    model = read_model_statistics(case)
    mstats = window_model_statistics(model, t0, t1) if model is not None else {}

    # Time blocks of the window: impacts per parcel per metre (both walls and
    # each), impulse-weighted k_n, k_t, with their block-jackknife errors
    edges_b = np.unique(np.linspace(0, len(sampled) - 1, N_BLOCKS + 1).round().astype(int))
    bt = time[sampled[edges_b]]
    bsnap = sampled[edges_b]
    nb = len(bt) - 1
    ux_snap = history[:, 2]
    blocks = {"dist": np.array([
        info["nParcels"]*np.trapz(ux_snap[bsnap[i]:bsnap[i + 1] + 1],
                                  time[bsnap[i]:bsnap[i + 1] + 1])
        for i in range(nb)])}
    for j, wall in enumerate(WALLS):
        blocks["imp_" + wall] = np.diff(impacts[bsnap, j])
    if model is not None:
        mt = model["Time"]
        idx = np.maximum(np.searchsorted(mt, bt + EPS_TIME) - 1, 0)
        for wall in WALLS:
            for col in ("sumVnIn", "sumVnOut", "sumVtIn", "sumVtOut"):
                name = "%s_%s" % (wall, col)
                if name in model:
                    blocks[name] = np.diff(model[name][idx])
    for name, fun in (
            ("impactFrequency", lambda t: (t["imp_lowerWall"] + t["imp_upperWall"])/t["dist"]),
            ("impactFrequency_lowerWall", lambda t: t["imp_lowerWall"]/t["dist"]),
            ("impactFrequency_upperWall", lambda t: t["imp_upperWall"]/t["dist"])):
        summary[name], summary[name + "_se"] = (float(v) for v in jackknife(fun, blocks))
    summary["angleBins"] = angle_bins(case, info, bt)
    if "lowerWall_sumVnIn" in blocks:
        def impulse(out, inc, walls=WALLS):
            def f(t):
                den = sum(t["%s_%s" % (w, inc)] for w in walls)
                return sum(t["%s_%s" % (w, out)] for w in walls)/den if den > 0 else np.nan
            return f
        for key, out_, in_ in (("knImpulse", "sumVnOut", "sumVnIn"),
                               ("ktImpulse", "sumVtOut", "sumVtIn")):
            summary[key], summary[key + "_se"] = (
                float(v) for v in jackknife(impulse(out_, in_), blocks))
            for wall in WALLS:
                summary["%s_%s" % (key, wall)], summary["%s_%s_se" % (key, wall)] = (
                    float(v) for v in jackknife(impulse(out_, in_, (wall,)), blocks))
    for j, wall in enumerate(WALLS):
        summary["impactsPerParcelPerMetre_" + wall] = \
            (impacts[sampled[-1], j] - impacts[sampled[0], j])/travelled
        if wall + "_modelHits" in mstats:
            summary["hitsPerParcelPerMetre_" + wall] = \
                mstats[wall + "_modelHits"]/travelled
            for key in ("kn", "kt", "gammaDeg", "facetPerHit"):
                summary["%s_%s" % (key, wall)] = mstats["%s_%s" % (wall, key)]
    if mstats:
        w = np.array([mstats.get(wall + "_modelHits", 0) for wall in WALLS])
        for key in ("kn", "kt"):
            v = np.array([mstats.get("%s_%s" % (wall, key), np.nan) for wall in WALLS])
            ok = w > 0
            summary[key + "_mean"] = float(np.sum(w[ok]*v[ok])/w[ok].sum()) \
                if ok.any() else np.nan
    # The spin models' own count of evaluations outside their range, in the
    # sampling window (every particle and sub-step, with the air's
    # fluctuation: the run's count, not the samples' estimate above)
    counts = in_run_range_counts(case, t0, t1)
    summary.update(counts)
    for key in ("lift", "torque"):
        if counts.get(key + "Evaluations"):
            summary[key + "OutsideInRun"] = counts[key + "Outside"]/counts[key + "Evaluations"]
    summary["spinRatios"] = ratios
    summary["spinHistograms"] = hist
    if is_loading(info):
        summary.update(loading_statistics(case, info, summary, t0, t1, ubulk))
    return info, prof, summary, history


# ----------------------------------------------------------------------------
# Output

PROFILE_COLUMNS = ["y_over_H", "concentration", "concentration_se",
                   "Ux_mean", "Ux_mean_se", "Uy_mean", "Uy_mean_se",
                   "Ux_rms", "Ux_rms_se", "Uy_rms", "Uy_rms_se", "samples"]

SUMMARY_COLUMNS = [
    "variant", "geometry", "wallModel", "roughness", "roughnessAngle", "lateralTilt", "e",
    "mu0", "muD", "lift", "torque", "shearLift", "dispersion",
    "diameter", "nParcels", "deltaT",
    "sampleStart", "sampleEnd", "snapshots", "samples",
    "upperFraction", "upperFraction_se", "upperFractionEarly", "upperFractionEarly_se",
    "upperFractionLate", "upperFractionLate_se", "UyRms", "UyRms_se",
    "UyRmsEarly", "UyRmsEarly_se", "UyRmsLate", "UyRmsLate_se",
    "meanHeight", "meanHeight_se",
    "meanUx", "meanUx_se", "meanUxEarly", "meanUxEarly_se", "meanUxLate", "meanUxLate_se",
    "meanSpinSpeed", "meanSpinSpeed_se", "rmsSpinSpeed", "rmsSpinSpeed_se",
    "UxRms", "UxRms_se", "UzRms", "UzRms_se", "meanUxOverBulk", "meanUxOverBulk_se",
    "impactFrequency", "impactFrequency_se", "impactFrequency_lowerWall",
    "impactFrequency_lowerWall_se", "impactFrequency_upperWall",
    "impactFrequency_upperWall_se",
    "knImpulse", "knImpulse_se", "ktImpulse", "ktImpulse_se",
    "knImpulse_lowerWall", "knImpulse_lowerWall_se", "knImpulse_upperWall",
    "knImpulse_upperWall_se", "ktImpulse_lowerWall", "ktImpulse_lowerWall_se",
    "ktImpulse_upperWall", "ktImpulse_upperWall_se", "outsideLiftRange",
    "hitsPerParcelPerMetre_lowerWall", "hitsPerParcelPerMetre_upperWall",
    "impactsPerParcelPerMetre_lowerWall", "impactsPerParcelPerMetre_upperWall",
    "kn_mean", "kt_mean", "kn_lowerWall", "kt_lowerWall", "kn_upperWall", "kt_upperWall",
    "gammaDeg_lowerWall", "gammaDeg_upperWall", "facetPerHit_lowerWall",
    "facetPerHit_upperWall", "liftEvaluations", "liftOutside", "liftOutsideInRun",
    "torqueEvaluations", "torqueOutside", "torqueOutsideInRun",
    "massLoading", "twoWayCoupling", "collisions", "nParticle", "trackingOffset",
    "massLoadingReached", "massLoadingReached_se", "beadVolumeFraction",
    "interParticleFrequency", "interParticleFrequency_se",
    "wallImpactRate", "wallImpactRate_se", "collisionsPerWallImpact",
    "pressureGradient", "pressureGradient_se", "airCentreline",
    "wallClock", "cpuTime"]


def fmt(v):
    if isinstance(v, str):
        return v
    if isinstance(v, (int, np.integer)):
        return str(v)
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


ANGLE_CSV_COLUMNS = ["angleMin", "angleMax", "hits", "hitFraction", "hitFraction_se",
                     "reboundFraction", "reboundFraction_se", "kn", "kn_se",
                     "model_bin_kn", "kt", "kt_se", "model_bin_kt"]


def write_angles(path, results):
    """angles.csv: the binned wall statistics of every variant with an
    angle file, beside the model's values (model_bin_*)."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["variant", "bin"] + ANGLE_CSV_COLUMNS)
        for info, _, s, _ in results:
            a = s.get("angleBins")
            if not a:
                continue
            for i in range(len(a["hits"])):
                w.writerow([info["variant"], i]
                           + [fmt(float(a[c][i])) if c in a else ""
                              for c in ANGLE_CSV_COLUMNS])


def plot_angles(path, result, d):
    """k_n(alpha), k_t(alpha) of the run per bin of the incidence angle
    (+-1 s.e.) with the model's curves (the paper's figure 2 made from the
    run), and the distributions of the incidence and rebound angles."""
    info, _, s, _ = result
    a = s["angleBins"]
    mid = 0.5*(a["angleMin"] + a["angleMax"])
    half = 0.5*(a["angleMax"] - a["angleMin"])
    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    for k, (key, name) in enumerate((("kn", "$k_n$"), ("kt", "$k_t$"))):
        ok = np.isfinite(a[key])
        ax[k].errorbar(mid[ok], a[key][ok], xerr=half[ok], yerr=a[key + "_se"][ok],
                       fmt="o", ms=4, capsize=2, label="OpenFOAM run (impulse-weighted, per bin)")
        if "model_alpha" in a:
            ax[k].plot(a["model_alpha"], a["model_" + key], "-", lw=1,
                       label="model, no incident spin (roughWallStats)")
            ax[k].plot(mid, a["model_bin_" + key], "x", ms=6,
                       label="model, bin average")
        ax[k].set_xlabel("incidence angle $\\alpha$ [deg]")
        ax[k].set_ylabel(name)
        ax[k].set_xlim(0, 90)
    ax[0].set_yscale("log")
    ax[0].legend(fontsize=7)
    width = a["angleMax"] - a["angleMin"]
    for key, name, m in (("hitFraction", "incidence", "o"), ("reboundFraction", "rebound", "s")):
        ax[2].errorbar(mid, a[key]/width, yerr=a[key + "_se"]/width, fmt=m + "-", ms=4,
                       capsize=2, label=name)
    ax[2].set_xlabel("angle from the mean wall [deg]")
    ax[2].set_ylabel("fraction of the hits per degree")
    ax[2].set_xlim(0, 90)
    ax[2].legend(fontsize=8)
    fig.suptitle("%s: %s, Delta = %s deg" % (title(d), info["variant"], info.get("roughnessAngle")),
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def label(info):
    return info["variant"]


def title(d):
    return "glass beads %d $\\mu$m, air 20 m/s, H = 35 mm" % round(d*1e6)


def plot_concentration(path, results, d):
    fig, ax = plt.subplots(figsize=(5.8, 5.4))
    floor = []
    for k, (info, prof, s, _) in enumerate(results):
        c, se, y = prof["concentration"], prof["concentration_se"], prof["y_over_H"]
        ok = c > 0
        ax.errorbar(c[ok], y[ok], xerr=se[ok], marker=MARKERS[k % len(MARKERS)],
                    ms=3.5 + 2.5*(k == 0), mfc="none" if k == 0 else None, capsize=2,
                    lw=1.2, label="%s: %.1f %% in upper half"
                    % (label(info), 100*s["upperFraction"]))
        if ok.sum() <= 2:
            floor.append((c[ok][0], y[ok][0]))
    if floor:
        ax.annotate("on the smooth floors every bead\nslides in the lowest bin",
                    floor[0], xytext=(-20, 60), textcoords="offset points",
                    ha="right", fontsize=7.5, arrowprops=dict(arrowstyle="->", lw=0.8))
    ax.set_xscale("log")
    ax.axvline(1, color="0.6", lw=0.8, ls=":")
    ax.axhline(0.5, color="0.6", lw=0.8, ls=":")
    ax.set_xlabel("normalised number concentration $n/\\bar{n}$  (log scale)")
    ax.set_ylabel("$y/H$")
    ax.set_ylim(0, 1)
    ax.set_title("Concentration, " + title(d), fontsize=9)
    ax.legend(fontsize=7, loc="upper right")
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
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
    axs[0].legend(fontsize=7)
    fig.suptitle("Parcel velocity, " + title(d) + " (bins with at least %d samples)"
                 % MIN_SAMPLES, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def plot_wall_hits(path, results, d):
    names = [info["variant"] for info, _, _, _ in results]
    x = np.arange(len(names))
    fig, axs = plt.subplots(1, 3, figsize=(14, 4.4))
    top = 0
    for i, wall in enumerate(WALLS):
        impacts = [s.get("impactsPerParcelPerMetre_" + wall, np.nan) for _, _, s, _ in results]
        model = [s.get("hitsPerParcelPerMetre_" + wall, np.nan) for _, _, s, _ in results]
        top = max([top] + [v for v in impacts if np.isfinite(v)])
        axs[0].bar(x + (i - 0.5)*0.38, impacts, 0.38, label=wall)
        axs[0].plot(x + (i - 0.5)*0.38, model, "k_", ms=14, mew=2,
                    label="roughWallInteraction's count" if i == 0 else None)
        for xi, m, imp in zip(x + (i - 0.5)*0.38, model, impacts):
            # Beads resting on a smooth floor touch it every track step:
            # the model counts those contacts, the impact count does not
            if np.isfinite(m) and m > 2*max(top, 1e-9) and m > 1.5*np.nan_to_num(imp):
                axs[0].annotate("model: %.0f\n(resting\ncontacts)" % m, (xi, 1.5*max(top, 0.1)),
                                ha="center", va="top", fontsize=6.5)
    axs[0].set_ylim(0, 1.6*max(top, 0.1))
    axs[0].set_ylabel("wall impacts per parcel per metre")
    axs[0].set_title("impacts faster than 5 cm/s (bars)", fontsize=9)
    for j, (key, name) in enumerate((("kn", "mean $k_n$"), ("kt", "mean $k_t$"))):
        ax = axs[1 + j]
        for i, wall in enumerate(WALLS):
            vals = [s.get("%s_%s" % (key, wall), np.nan) for _, _, s, _ in results]
            ax.bar(x + (i - 0.5)*0.38, vals, 0.38, label=wall)
        ax.set_ylabel(name)
        ax.set_title(name + " per hit (rough-wall model's statistics)", fontsize=9)
    for ax in axs:
        ax.set_xticks(x)
        ax.set_xticklabels(names, fontsize=7, rotation=20, ha="right")
        ax.grid(alpha=0.3, axis="y")
        ax.legend(fontsize=7)
    fig.suptitle("Wall-hit statistics over the sampling window, " + title(d), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def plot_spin_up(path, results, d):
    fig, axs = plt.subplots(1, 4, figsize=(16, 4))
    for info, _, s, hist in results:
        line, = axs[0].plot(hist[:, 0], 100*hist[:, 1], label=label(info))
        axs[1].plot(hist[:, 0], hist[:, 4], color=line.get_color())
        axs[2].plot(hist[:, 0], hist[:, 2], color=line.get_color())
        axs[3].plot(hist[:, 0], hist[:, 3], color=line.get_color())
    for ax in axs:
        ax.axvline(results[0][2]["sampleStart"], color="k", ls=":", lw=1)
        ax.set_xlabel("time [s]")
        ax.grid(alpha=0.3)
    axs[0].set_ylabel("parcels in the upper half [%]")
    axs[1].set_ylabel("rms wall-normal parcel velocity [m/s]")
    axs[2].set_ylabel("mean streamwise parcel velocity [m/s]")
    axs[3].set_ylabel("mean spin, surface speed $\\omega_z d/2$ [m/s]")
    axs[0].legend(fontsize=7)
    fig.suptitle("Spin-up (dotted: start of sampling), " + title(d), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def carrier_profile(info):
    """(y/H, U) of the air, from the carrier run."""
    try:
        carrier, time = info["carrier"], "%d" % info["carrierTime"]
        mesh = tc.read_mesh(carrier)
        y = mesh.cell_centres[:, 1] - mesh.lo[1]
        U = fc.internal_field(os.path.join(carrier, time, "U"))[:, 0]
        order = np.argsort(y)
        return y[order]/info["height"], U[order]
    except (KeyError, OSError, ValueError, fc.FoamError):
        return None


def carrier_statistics(info):
    """The converged carrier flow: friction velocity (from the viscous
    sublayer: u_tau^2 = nu U_1/y_1 at the first cell, y+ < 1), Re_tau,
    centreline and bulk velocity, kinematic pressure gradient (the
    meanVelocityForce's last report), y+ of the first cell centre, air
    velocity at one bead radius from the wall."""
    carrier, time = info["carrier"], "%d" % info["carrierTime"]
    mesh = tc.read_mesh(carrier)
    y = mesh.cell_centres[:, 1] - mesh.lo[1]
    U = fc.internal_field(os.path.join(carrier, time, "U"))[:, 0]
    rows, inv = np.unique(np.round(y, 12), return_inverse=True)
    u = np.bincount(inv, weights=U)/np.bincount(inv)
    H = mesh.hi[1] - mesh.lo[1]
    props = fc.read_text(os.path.join(carrier, "constant",
                                          "physicalProperties"))
    nu = float(re.search(r"^nu\s+([^;]+);", props, re.M).group(1))
    lower = rows < 0.5*H
    u_tau = np.sqrt(nu*u[0]/rows[0])
    heights = np.diff(np.r_[0, 0.5*(rows[1:] + rows[:-1]), H])
    log = fc.read_text(os.path.join(carrier, "log.foamRun"))
    grad = re.findall(r"pressure gradient = (%s)" % fc.NUMBER, log)
    r = 0.5*info["diameter"]
    return {
        "uTau": u_tau, "ReTau": u_tau*0.5*H/nu, "Ucentreline": u.max(),
        "Ubulk": float(np.sum(u*heights)/H),
        "pressureGradient": float(grad[-1]) if grad else np.nan,
        "yPlusFirstCell": rows[0]*u_tau/nu,
        "Uradius": float(np.interp(r, np.r_[0, rows[lower]], np.r_[0, u[lower]])),
        "yPlusRadius": r*u_tau/nu, "iterations": info["carrierTime"],
        "nu": nu, "height": H}


def write_carrier(path, stats):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(list(stats))
        w.writerow([fmt(float(v)) for v in stats.values()])


RATIO_COLUMNS = (["variant", "lift", "samples"]
                 + ["%s_q%02d" % (k, round(100*q)) for k in ("Gamma", "Rep", "ReR")
                    for q in QUANTILES]
                 + ["outsideLoth", "outsideOesterleBuiDinh", "GammaAbove1"]
                 + ["betaMei_q%02d" % round(100*q) for q in QUANTILES]
                 + ["outsideSaffmanMei", "MeiRepAbove", "MeiBetaBelow",
                    "MeiBetaAbove", "RepAboveDragSwitch"])


def write_spin_ratios(path, results):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(RATIO_COLUMNS)
        for _, _, s, _ in results:
            w.writerow([fmt(s["spinRatios"].get(c)) for c in RATIO_COLUMNS])


def plot_spin_ratios(path, results, d):
    fig, axs = plt.subplots(1, 3, figsize=(14, 4.2))
    bins = {"gamma": np.logspace(-5, 2, 71), "Rep": np.logspace(-1, 3.5, 46),
            "ReR": np.logspace(-4, 3, 71)}
    names = {"gamma": "spin ratio $\\Gamma = |\\Omega_{rel}| d/(2|U_{rel}|)$",
             "Rep": "$Re_p = |U_{rel}| d/\\nu$",
             "ReR": "$Re_R = |\\Omega_{rel}| d^2/\\nu$"}
    for info, _, s, _ in results:
        for ax, key in zip(axs, ("gamma", "Rep", "ReR")):
            v = s["spinHistograms"][key]
            ax.hist(v[v > 0], bins=bins[key], histtype="step", density=False,
                    weights=np.full(np.count_nonzero(v > 0), 1/len(v)), label=label(info))
    for lo, hi in (OESTERLE_RANGE["Gamma"],):
        axs[0].axvspan(lo, hi, color="0.85", zorder=0, label="Oesterle & Bui Dinh's fit")
    axs[1].axvspan(*OESTERLE_RANGE["Rep"], color="0.85", zorder=0)
    for ax, key in zip(axs, ("gamma", "Rep", "ReR")):
        ax.set_xscale("log")
        ax.set_xlabel(names[key])
        ax.set_ylabel("fraction of samples per bin")
        ax.grid(alpha=0.3)
    axs[0].legend(fontsize=7)
    fig.suptitle("Spin ratio and Reynolds numbers of the beads (mean air flow at the "
                 "bead), " + title(d), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def plot_loading(path, results, d, reference):
    """The loading variants (and the reference, steel): concentration, mean
    streamwise and rms wall-normal bead velocity, and the air's streamwise
    velocity at the end of each run."""
    fig, axs = plt.subplots(1, 4, figsize=(15, 4.8), sharey=True)
    for k, (info, prof, s, _) in enumerate(reference + results):
        y = prof["y_over_H"]
        name = label(info)
        if is_loading(info):
            name += " (loading %.2f)" % s.get("massLoadingReached", np.nan)
        style = dict(marker=MARKERS[k % len(MARKERS)], ms=3.5, capsize=2, lw=1.1)
        c = prof["concentration"]
        ok = c > 0
        line = axs[0].errorbar(c[ok], y[ok], xerr=prof["concentration_se"][ok],
                               label=name, **style)[0]
        for ax, col in zip(axs[1:3], ("Ux_mean", "Uy_rms")):
            v = prof[col]
            ok = np.isfinite(v)
            ax.errorbar(v[ok], y[ok], xerr=prof[col + "_se"][ok], **style)
        if "airProfile" in s:
            yy, ua = s["airProfile"]
            axs[3].plot(ua, yy, color=line.get_color(), lw=1.2, label=name)
    axs[0].set_xlabel("normalised number concentration $n/\\bar{n}$")
    axs[1].set_xlabel("mean streamwise bead velocity [m/s]")
    axs[2].set_xlabel("rms wall-normal bead velocity [m/s]")
    axs[3].set_xlabel("air velocity at the end of the run [m/s]")
    axs[0].set_ylabel("$y/H$")
    axs[0].set_ylim(0, 1)
    axs[0].legend(fontsize=7)
    axs[3].legend(fontsize=7)
    for ax in axs:
        ax.grid(alpha=0.3, which="both")
    fig.suptitle("Loading variants: two-way coupling and collisions between "
                 "beads, " + title(d), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def print_summary(results):
    print("\nhorizontalChannel: statistics over the sampling window (standard errors in "
          "brackets)")
    head = ("%-19s %8s %15s %13s %15s %14s %7s %7s %10s %10s %6s %6s %8s"
            % ("variant", "samples", "upper half [%]", "drift [%]", "rms V_p [m/s]",
               "<y>/H", "<Up>", "<spin>", "hits/m low", "hits/m up", "k_n", "k_t",
               "wall [s]"))
    print(head)
    print("-"*len(head))
    for info, prof, s, _ in results:
        drift = s["upperFractionLate"] - s["upperFractionEarly"]
        drift_se = np.hypot(s["upperFractionLate_se"], s["upperFractionEarly_se"])
        print("%-19s %8d %7.2f (%4.2f) %6.2f (%4.2f) %7.4f (%5.4f) %6.3f (%5.3f) %7.2f "
              "%7.2f %10.3g %10.3g %6.3g %6.3g %8.1f" % (
                  info["variant"], s["samples"],
                  100*s["upperFraction"], 100*s["upperFraction_se"], 100*drift,
                  100*drift_se, s["UyRms"], s["UyRms_se"],
                  s["meanHeight"], s["meanHeight_se"], s["meanUx"],
                  s["meanSpinSpeed"], s["impactsPerParcelPerMetre_lowerWall"],
                  s["impactsPerParcelPerMetre_upperWall"],
                  s.get("kn_mean", np.nan), s.get("kt_mean", np.nan),
                  s.get("wallClock", np.nan)))
    print("upper half: parcels above y = H/2 (50 % = uniform); drift: second half of "
          "the sampling window minus first half;\nrms V_p: rms wall-normal parcel "
          "velocity; <Up>: mean streamwise parcel velocity [m/s]; <spin>: mean surface "
          "speed\nof the spin, omega_z d/2 [m/s]; hits/m: wall impacts (faster than "
          "5 cm/s) per parcel per metre travelled;\nk_n, k_t: mean restitution ratios "
          "per hit (rough-wall model); wall: wall-clock time of the tracking run [s].")


def main():
    out = sys.argv[1]
    cases = sys.argv[2:]
    os.makedirs(out, exist_ok=True)
    results = [analyse(c) for c in cases]
    diameters = sorted({r[0]["diameter"] for r in results})
    if len(diameters) != 1:
        raise SystemExit("postProcess: one bead diameter per results directory")
    d = diameters[0]
    write_profiles(os.path.join(out, "profiles.csv"), results)
    write_summary(os.path.join(out, "summary.csv"), results)
    write_angles(os.path.join(out, "angles.csv"), results)
    # The figures of the frozen-air variants, and loading.png of the
    # loading variants beside the default
    frozen = [x for x in results if not is_loading(x[0])]
    loading = [x for x in results if is_loading(x[0])]
    if frozen:
        plot_concentration(os.path.join(out, "concentration.png"), frozen, d)
        plot_velocity(os.path.join(out, "velocity.png"), frozen, d,
                      carrier_profile(frozen[0][0]))
        plot_wall_hits(os.path.join(out, "wallHits.png"), frozen, d)
        plot_spin_up(os.path.join(out, "spinUp.png"), frozen, d)
        plot_spin_ratios(os.path.join(out, "spinRatios.png"), frozen, d)
        binned = [x for x in frozen if x[2].get("angleBins")]
        if binned:
            plot_angles(os.path.join(out, "wallAngles.png"), binned[0], d)
    if loading:
        plot_loading(os.path.join(out, "loading.png"), loading, d, frozen[:1])
    write_spin_ratios(os.path.join(out, "spinRatios.csv"), results)
    write_carrier(os.path.join(out, "carrier.csv"), carrier_statistics(results[0][0]))
    print_summary(results)


if __name__ == "__main__":
    main()
