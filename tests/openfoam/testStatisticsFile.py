#!/usr/bin/env python3
"""Every column of the statistics file against values computed from the
parcels; hits at exactly normal incidence; parcels of nParticle != 1; a run
that writes in mid-run and goes on, and a restart from that write.

The wall-impact box with five groups of parcels (told apart by diameter):

  group  wall       incidence            nParticle  d [um]
  A      lowerWall  60 deg, along +x     1          100
  B      lowerWall  75 deg, along +x+z   2          120
  N      upperWall  exactly normal       3          110
  U      upperWall  60 deg, along +x     1          130
  E      none       (5, 0, 0): escapes   2          140

Part 1 (lowerWall, upperWall rough: Delta 6 deg, e 0.8, mu0 = muD = 0.1,
so that both regimes occur and no hit needs a second facet; outlet escape),
run to t = 0.05, when every parcel of A, B, N and U has hit its wall once
and flies away and E has left: each column of the file is
computed from the parcels:
  hits         the parcels of the wall's groups
  noSlip, sliding, facetPerHit, fallbacks, meanGamma
               from each parcel's facet, recovered from its incident and
               rebound velocity: a facet collision without spin (model notes
               section 4) gives dv = j_n n + j_t with j_t = -(2/7) u (no
               slip: n || dv + (2/7) v) or |j_t| = muD j_n along the slip
               (sliding: n is dv turned by atan(muD)); the candidate is kept
               whose collision, computed by the oracle's facet_collision
               (src/python/foamcase/roughWallOracle.py), reproduces the parcel's
               rebound to 1e-9; gamma = atan2(-n.t, n.N) in DEGREES.  At
               normal incidence the tilt direction t is drawn by the model,
               so only |gamma| is known there: upperWall's meanGamma is
               checked statistically (the signed sum of N implied by the
               file within 5 sd of zero), lowerWall's exactly;
  meanKn       -V''.N/V'.N over every hit, normal incidence included;
  meanKt       V''.t/|V'_t| over the hits that have a tangential part only
               (upperWall: the mean of group U, not the sum over N + U);
  sumVnIn, sumVnOut, impulseKn
               sum |V'.N|, sum V''.N over every hit (upperWall: normal
               incidence included) and their ratio;
  sumVtIn, sumVtOut, impulseKt
               sum |V'_t|, sum V''.t over the hits with a tangential part;
  energyLoss   sum of nParticle (0.5 m (|V'|^2 - |V''|^2) - 0.5 I w''^2);
  nEscape, massEscape (outlet)  group E: parcels and nParticle m;
and group N's mean k_n against the oracle at alpha = 90 deg (4 SE).

Part 2 (upperWall stick): three runs to t = 0.3, when all but a few
parcels have stuck on upperWall (nStick, massStick: nParticle m of the
parcels at rest) or escaped (nEscape, massEscape: the parcels missing):
  uninterrupted   written at 0.3 only;
  midRun          written every 0.05 s: its last row equals the
                  uninterrupted run's, column for column (the means and sums
                  to 1e-10 relative: at a write the totals are stored in the
                  cloud properties, which rounds them to the case's
                  writePrecision, 12 here), and the parcels are identical
                  (a counter not reset at a write would count the hits
                  before it again);
  restart         the midRun case restarted from its write at 0.05: the last
                  row equals the uninterrupted run's.
Part 2 writes the case at writePrecision 6 (controlDict: the parcels and the
cloud properties) and the statistics file with 17 digits (the model's
writePrecision), and asks the columns to agree exactly where every
term was summed before the first write (lowerWall's: all its hits are before
t = 0.01: the stored sums, 17 digits, read back bit for bit; 15 digits would
not), to 1e-11 where the sums go on over the writes (upperWall's
massStick, outlet's massEscape: a sum that is stored and goes on adds its
thousands of terms in another grouping, n eps ~ 3e-13 seen).  The stored
totals must be the sums themselves (exactSums, 17 digits), not their
rounding to the case's 6 digits (1e-6, caught either way).  After the
restart only parcels of diameters and nParticle that 6 digits write exactly
stick or escape, so the uninterrupted run's own file is the oracle; massStick
is also checked against nParticle m of the stuck parcels.

Usage: testStatisticsFile.py --platform P [--cloud colliding|kinematic]
           [--parcels N] [--work DIR]

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os
import shutil

import numpy as np

from foamcase import testing as t
import foamcase as fc
from foamcase import roughWallOracle as oracle
from foamcase.testConstants import parcel_mass, sphere_mass

E, MU0, MUD, DELTA_DEG = 0.8, 0.1, 0.1, 6.0

#: Bins of the angle statistics (incidenceAngleBins): 12.86 deg wide, so
#: that the groups' incidence angles (60, 75, 90 deg) lie inside bins 4, 5
#: and 6, not on an edge
BINS = 7

#: The write the restart starts from: after every rough-wall hit (t < 0.01)
#: and every escape of group E (t < 0.03), before the first parcel reaches
#: upperWall from below (t > 0.1). (On OpenFOAM-13's functions solver the
#: cloud written at a time has not yet made that time's step, while the
#: totals stored then include it: a parcel that escapes in that very step
#: is counted again after a restart from there; seen restarting from 0.1.)
RESTART = "0.05"

#: name -> (wall, velocity, nParticle, d, start y); x in [-0.06, -0.02]
#: (E: [-0.04, 0]), z in [-0.015, 0.015]
GROUPS = {
    "A": ("lowerWall", (math.cos(math.radians(60)), -math.sin(math.radians(60)), 0.0), 1, 100e-6, 0.005),
    "B": ("lowerWall", (math.cos(math.radians(75)) * 0.8, -math.sin(math.radians(75)),
                        math.cos(math.radians(75)) * 0.6), 2, 120e-6, 0.005),
    "N": ("upperWall", (0.0, 1.0, 0.0), 3, 110e-6, 0.095),
    "U": ("upperWall", (math.cos(math.radians(60)), math.sin(math.radians(60)), 0.0), 1, 130e-6, 0.095),
    "E": (None, (5.0, 0.0, 0.0), 2, 140e-6, 0.05),
}

#: Mean-wall normals into the fluid
NORMAL = {"lowerWall": np.array([0.0, 1.0, 0.0]),
          "upperWall": np.array([0.0, -1.0, 0.0])}


def settings(upper, extra=""):
    return """patchInteractionModel roughWallInteraction;

roughWallInteractionCoeffs
{
    %s
    patches
    (
        lowerWall
        {
            type            rough;
            e               %g;
            mu0             %g;
            muD             %g;
            roughnessAngle  %g;
        }
        upperWall
        {
            %s
        }
        outlet { type escape; }
    );
}
""" % (extra, E, MU0, MUD, DELTA_DEG, upper)


ROUGH_UPPER = "type rough; e %g; mu0 %g; muD %g; roughnessAngle %g;" % (
    E, MU0, MUD, DELTA_DEG)


def make_case(platform, path, kind, parcels, upper, seed=7, extra=""):
    case = fc.FoamCase(platform, t.WALL_IMPACT, path, kind)
    rng = np.random.default_rng(seed)
    injectors = []
    for name, (_, U0, nP, d, y0) in GROUPS.items():
        x = rng.uniform(-0.04, 0.0, parcels) if name == "E" \
            else rng.uniform(-0.06, -0.02, parcels)
        z = rng.uniform(-0.015, 0.015, parcels)
        injectors.append(fc.Injector(name, np.column_stack(
            [x, np.full(parcels, y0), z]), U0, d, nParticle=nP))
    case.write_injectors(injectors)
    case.write_settings(settings(upper, extra))
    return case


def group_of(d):
    """Group names of the parcels by diameter."""
    names = np.full(len(d), "", dtype=object)
    for name, (_, _, _, dg, _) in GROUPS.items():
        names[np.abs(d - dg) < 1e-3 * dg] = name
    return names


def unit(a):
    return a / np.linalg.norm(a, axis=1)[:, None]


def rotate(v, axis, angle):
    """Rodrigues: v rotated by angle about the unit axis (rows)."""
    c, s = math.cos(angle), math.sin(angle)
    return v * c + np.cross(axis, v) * s \
        + axis * np.einsum("ij,ij->i", axis, v)[:, None] * (1 - c)


def recover_facets(v0, v1, N):
    """The facet normal and regime of each single-facet hit from its
    incident v0 and rebound v1 (rows), or fail.  Returns (n, no_slip)."""
    dv = v1 - v0
    axis = np.cross(v0, dv)
    axis = unit(axis)
    candidates = [(unit(dv + 2.0 / 7.0 * v0), True),
                  (rotate(unit(dv), axis, math.atan(MUD)), False),
                  (rotate(unit(dv), axis, -math.atan(MUD)), False)]
    n = np.full_like(v0, np.nan)
    no_slip = np.zeros(len(v0), dtype=bool)
    found = np.zeros(len(v0), dtype=int)
    for cand, regime in candidates:
        ok = np.einsum("ij,ij->i", v0, cand) < 0
        pred = np.full_like(v0, np.nan)
        pred_ns = np.zeros(len(v0), dtype=bool)
        if np.any(ok):
            res = oracle.facet_collision(v0[ok], None, cand[ok], 1.0, E, MU0,
                                         MUD)
            pred[ok], pred_ns[ok] = res.v, res.no_slip
        match = ok & (np.linalg.norm(pred - v1, axis=1) < 1e-9) \
            & (pred_ns == regime)
        n[match] = cand[match]
        no_slip[match] = regime
        found += match
    t.check(bool(np.all(found == 1)),
            "every hit is one facet collision whose facet is recovered from "
            "the parcel (%d of %d; %d ambiguous)"
            % (np.count_nonzero(found == 1), len(v0),
               np.count_nonzero(found > 1)))
    return n, no_slip


def read_parcels(case, time_name, fields):
    p = case.read_cloud(time_name, fields)
    return p, group_of(p["d"])


def close(a, b, rel=1e-8, absolute=1e-300):
    return abs(a - b) <= max(rel * max(abs(a), abs(b)), absolute)


def write_tolerance(key):
    """Relative tolerance of a column of part 2 against the uninterrupted
    run: lowerWall's terms all precede the first write, so its sums are the
    same sums, stored and read back: equal exactly when stored with 17
    significant digits (15 would change most of them in the last digits,
    about 1e-16 to 1e-15 relative); the others' sums go on over the writes
    (another grouping of the same terms)."""
    return 0 if key.startswith("lowerWall") else 1e-11


def part1(args, platform):
    """Every column at t = 0.05 against the parcels."""
    n = args.parcels
    spin = fc.SPIN[args.cloud]
    case = make_case(platform, os.path.join(args.work, "columns"),
                     args.cloud, n, ROUGH_UPPER,
                     extra="incidenceAngleBins %d;" % BINS)
    case.mesh()
    case.solve()
    fields = ["U", "d", "nParticle"] + (["angularMomentum"] if spin else [])
    p, groups = read_parcels(case, "0.05", fields)
    for name in "ANBU":
        t.check(np.count_nonzero(groups == name) == n,
                "group %s: all %d parcels in the domain" % (name, n))
    t.check(np.count_nonzero(groups == "E") == 0, "group E has left")
    _, rows = case.read_statistics()
    last = rows[-1]
    _, angle_rows = case.read_statistics(fc.ANGLE_STATISTICS)

    def col(name):
        return fc.column(last, name)

    mass = sphere_mass(p["d"])
    t.check(bool(np.all(p["nParticle"][groups == "B"] == 2))
            and bool(np.all(p["nParticle"][groups == "N"] == 3)),
            "the parcels carry the nParticle of their injector (2, 3)")

    for wall in ("lowerWall", "upperWall"):
        names = [g for g in GROUPS if GROUPS[g][0] == wall]
        k = np.isin(groups, names)
        v1 = p["U"][k]
        v0 = np.array([GROUPS[g][1] for g in groups[k]], dtype=float)
        Nw = np.broadcast_to(NORMAL[wall], v0.shape)
        nfacet, no_slip = recover_facets(v0, v1, Nw)
        hits = int(k.sum())
        vn0 = np.einsum("ij,ij->i", v0, Nw)
        vt0 = v0 - vn0[:, None] * Nw
        lt = np.linalg.norm(vt0, axis=1)
        normal = lt == 0
        tdir = vt0 / np.where(normal, 1, lt)[:, None]
        kn = -np.einsum("ij,ij->i", v1, Nw) / vn0
        kt = np.einsum("ij,ij->i", v1, tdir)[~normal] / lt[~normal]
        cosg = np.einsum("ij,ij->i", nfacet, Nw)
        sing = -np.einsum("ij,ij->i", nfacet, tdir)
        gamma = np.degrees(np.arctan2(sing, cosg))
        abs_gamma = np.degrees(np.arccos(np.clip(cosg, -1, 1)))
        nP = p["nParticle"][k]
        loss = nP * 0.5 * mass[k] * (np.sum(v0**2, 1) - np.sum(v1**2, 1))
        if spin:
            inertia = 0.1 * mass[k] * p["d"][k]**2
            loss -= nP * 0.5 * np.sum(p["angularMomentum"][k]**2, 1) / inertia

        t.check(col(wall + "_hits") == hits,
                "%s_hits = %d parcels" % (wall, hits))
        t.check(col(wall + "_noSlip") == np.count_nonzero(no_slip)
                and col(wall + "_sliding") == np.count_nonzero(~no_slip)
                and 0 < np.count_nonzero(~no_slip) < hits,
                "%s_noSlip, _sliding = %d, %d recovered from the parcels"
                % (wall, np.count_nonzero(no_slip),
                   np.count_nonzero(~no_slip)))
        t.check(col(wall + "_facetPerHit") == 1
                and col(wall + "_fallbacks") == 0,
                "%s_facetPerHit = 1, _fallbacks = 0 (single facets)" % wall)
        t.check(close(col(wall + "_meanKn"), kn.mean()),
                "%s_meanKn %.10g = parcels' %.10g (every hit)"
                % (wall, col(wall + "_meanKn"), kn.mean()))
        t.check(close(col(wall + "_meanKt"), kt.mean()),
                "%s_meanKt %.10g = parcels' %.10g over the %d hits with a "
                "tangential part (of %d)" % (wall, col(wall + "_meanKt"),
                                            kt.mean(), kt.size, hits))
        # The sums of the impulse-weighted ratios: |V'.N| and V''.N over
        # every hit, normal incidence included (upperWall: groups N and U);
        # |V'_t| and V''.t over the hits with a tangential part
        vn_in = np.abs(vn0).sum()
        vn_out = np.einsum("ij,ij->i", v1, Nw).sum()
        vt_in = lt[~normal].sum()
        vt_out = np.einsum("ij,ij->i", v1, tdir)[~normal].sum()
        for name, value in (("sumVnIn", vn_in), ("sumVnOut", vn_out),
                            ("sumVtIn", vt_in), ("sumVtOut", vt_out),
                            ("impulseKn", vn_out / vn_in),
                            ("impulseKt", vt_out / vt_in)):
            t.check(close(col(wall + "_" + name), value),
                    "%s_%s %.10g = parcels' %.10g%s"
                    % (wall, name, col(wall + "_" + name), value,
                       " (normal incidence included)"
                       if np.any(normal) and "Vn" in name else ""))
        t.check_angle_bins(angle_rows, wall, v0, v1, Nw, last, BINS)
        t.check(close(col(wall + "_energyLoss"), loss.sum(), 1e-6),
                "%s_energyLoss %.10g = parcels' %.10g (nParticle counted)"
                % (wall, col(wall + "_energyLoss"), loss.sum()))
        if not np.any(normal):
            t.check(close(col(wall + "_meanGamma"), gamma.mean(), 1e-8, 1e-9),
                    "%s_meanGamma %.10g deg = parcels' %.10g deg"
                    % (wall, col(wall + "_meanGamma"), gamma.mean()))
        else:
            # Signed tilts known off normal incidence only: the sum over
            # the normal-incidence hits implied by the file must be a
            # sample of a symmetric distribution around 0
            known = gamma[~normal].sum()
            implied = col(wall + "_meanGamma") * hits - known
            sd = math.sqrt(np.sum(abs_gamma[normal]**2))
            t.check(abs(implied) <= 5 * sd,
                    "%s_meanGamma %.6g deg: the implied sum of the signed "
                    "tilts at normal incidence %.4g deg is within 5 sd "
                    "(%.4g deg) of 0; mean |gamma| there %.4f deg"
                    % (wall, col(wall + "_meanGamma"), implied, 5 * sd,
                       abs_gamma[normal].mean()))
            # Normal incidence against the oracle
            ref = t.reference(spin, DELTA_DEG, [90], e=E, mu0=MU0,
                              muD=MUD)[90]
            x = kn[normal]
            mean, se, _, _ = t.sd_and_se(x)
            z = (mean - ref["mean_kn"]) / math.hypot(se, ref["se_mean_kn"])
            t.check(abs(z) <= t.TOLERANCE_SE,
                    "%s, normal incidence: mean k_n %.5f, oracle %.5f, |z| = "
                    "%.2f" % (wall, mean, ref["mean_kn"], abs(z)))

    mass_e = parcel_mass(GROUPS["E"][3], 2) * n
    t.check(col("outlet_nEscape") == n
            and close(col("outlet_massEscape"), mass_e, 1e-9),
            "outlet_nEscape = %d, _massEscape %.10g = nParticle m of group E "
            "%.10g" % (col("outlet_nEscape"), col("outlet_massEscape"),
                       mass_e))


def last_row_and_fields(case, end):
    _, rows = case.read_statistics()
    fields = {}
    for d in case.cloud_dirs(end):
        for field in ("U", "d", "nParticle"):
            text = fc.read_text(os.path.join(d, field))
            fields[field] = text[text.index("// * *"):]
    return rows, fields


def part2(args, platform):
    """Mid-run writes and a restart against the uninterrupted run."""
    n = args.parcels
    stick = "type stick;"
    end = "0.3"

    def run(name, interval):
        case = make_case(platform, os.path.join(args.work, name), args.cloud,
                         n, stick, extra="writePrecision 17; "
                         "incidenceAngleBins %d;" % BINS)
        case.mesh()
        case.set_control(endTime=end, writeInterval=interval,
                         writePrecision="6")
        return case

    uninterrupted = run("uninterrupted", "300")
    uninterrupted.solve()
    mid = run("midRun", "50")
    mid.solve()
    rows_u, fields_u = last_row_and_fields(uninterrupted, end)
    rows_m, fields_m = last_row_and_fields(mid, end)
    last_u = rows_u[-1]

    # Stick and escape columns against the parcels of the uninterrupted run
    p, groups = read_parcels(uninterrupted, end,
                             ["U", "d", "nParticle", "active"])
    stuck = p["active"] == 0
    mass = parcel_mass(p["d"], p["nParticle"])
    t.check(np.count_nonzero(stuck) > 3 * n
            and bool(np.all(p["U"][stuck] == 0)),
            "uninterrupted: %d parcels stuck on upperWall, at rest"
            % np.count_nonzero(stuck))
    t.check(fc.column(last_u, "upperWall_nStick") == np.count_nonzero(stuck)
            and close(fc.column(last_u, "upperWall_massStick"),
                      mass[stuck].sum(), 1e-9),
            "upperWall_nStick = %d, _massStick %.10g = nParticle m of the "
            "stuck parcels %.10g" % (fc.column(last_u, "upperWall_nStick"),
                                     fc.column(last_u, "upperWall_massStick"),
                                     mass[stuck].sum()))
    injected = {g: n * parcel_mass(GROUPS[g][3], GROUPS[g][2])
                for g in GROUPS}
    escaped = sum(n - np.count_nonzero(groups == g) for g in GROUPS)
    mass_escaped = sum(injected.values()) - mass.sum()
    t.check(fc.column(last_u, "outlet_nEscape") == escaped
            and close(fc.column(last_u, "outlet_massEscape"), mass_escaped,
                      1e-9),
            "outlet_nEscape = %d, _massEscape %.10g = the parcels missing "
            "(%.10g)" % (escaped, fc.column(last_u, "outlet_massEscape"),
                         mass_escaped))
    t.check(fc.column(last_u, "lowerWall_hits") == 2 * n,
            "uninterrupted: lowerWall_hits = %d" % (2 * n))

    times_m = sorted({r["Time"] for r in rows_m})
    t.check(any(abs(x - 0.05) < 1e-9 for x in times_m)
            and os.path.isdir(mid.file("0.1")),
            "midRun wrote in mid-run (0.05, 0.1, ...) and went on")
    for key in last_u:
        a, b = rows_m[-1].get(key), last_u[key]
        t.check(a is not None and close(a, b, write_tolerance(key), 1e-300),
                "midRun: last row %s = %r, uninterrupted %r" % (key, a, b))
    t.check(fields_m == fields_u,
            "midRun: parcels at %s identical to the uninterrupted run's" % end)

    # Restart from the midRun write at RESTART: a fresh case with that time
    restart = run("restart", "50")
    shutil.copytree(mid.file(RESTART), restart.file(RESTART))
    restart.solve()
    t.check(os.path.exists(restart.statistics_file(RESTART)),
            "restart: a new statistics file in %s/" % RESTART)
    _, rows_r = restart.read_statistics()
    last_r = rows_r[-1]
    for key in last_u:
        a, b = last_r.get(key), last_u[key]
        t.check(a is not None and close(a, b, write_tolerance(key), 1e-300),
                "restart: last row %s = %r, uninterrupted %r" % (key, a, b))

    # The angle bins (lowerWall's hits, all before the first write) at the
    # end: the same in the three runs, exactly (stored with 17 digits)
    def last_bins(case):
        _, rows = case.read_statistics(fc.ANGLE_STATISTICS)
        return [r for r in rows if abs(r["Time"] - float(end)) < 1e-9]
    bins_u = last_bins(uninterrupted)
    t.check(len(bins_u) == BINS and all(r["patch"] == "lowerWall"
                                         for r in bins_u)
            and sum(r["hits"] for r in bins_u) == 2 * n,
            "uninterrupted: the %d rows of lowerWall's bins at %s (the rough "
            "patch) hold its %d hits" % (BINS, end, 2 * n))
    for name, case in (("midRun", mid), ("restart", restart)):
        t.check(last_bins(case) == bins_u,
                "%s: lowerWall's angle bins at %s equal the uninterrupted "
                "run's, exactly" % (name, end))


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    t.add_platform_args(p)
    p.add_argument("--parcels", type=int, default=3000)
    return p.parse_args()


def test():
    args = parse_args()
    platform = fc.Platform(args.platform)
    part1(args, platform)
    part2(args, platform)


if __name__ == "__main__":
    t.main(test)
