#!/usr/bin/env python3
"""roughWallStats --d: Delta(d) from the wall's profile (rolling-sphere envelope).

Oracles (none calls the tool's code for its expectation):
  sinusoid   a trace z = A sin(2 pi x / L) written here, sphere radius r below
             the valley radius of curvature L^2/(4 pi^2 A), the statistics
             covering whole periods: the tilt has the law of atan(z') with x
             uniform (derivation: tests/core/testRollingSphereEnvelope.cc), its
             moments integrated here by numpy's trapezoid rule over one period
             (exact to 1e-12 for a periodic integrand); the same trace in mm/um
             with a header and '# units mm um' gives the same table;
  flat       a flat trace: Delta = 0;
  synthetic  --Rq, --RSm at d = RSm/20: the small-sphere limit, the rms of
             atan(s) for a normal slope s of sd 2 pi Rq / RSm (Gauss-Hermite
             quadrature here), within 2 % (3 sd of the 0.6 % seed spread,
             docs/figures/roughnessProfile-seeds.csv); the closed-form column
             typed here; --Ra, --Rz give the table of --Rq = sqrt(pi/2) Ra,
             Rz / 4.11;
  badInput   exit code 2 and the file and line (or option) named;
  rsm        ISO 4287's RSm, the mean spacing of successive zero
             up-crossings: a trace z = A cos(2 pi x / L) over [-10.3 L,
             10.3 L] (even, so its least-squares line is its mean, which
             moves every crossing alike), starting and ending between
             crossings: 21 up-crossings, RSm = L to 1e-6 (the length per
             crossing would be 0.98 L); the closed-form column is
             atan(2 pi Rq / max(L, d)) with Rq of the levelled samples
             computed here;
  plot       --plot writes a PNG.

Usage: testRoughnessProfile.py --binary PATH --work DIR --case NAME
SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import os
import subprocess
import sys

import numpy as np

from foamcase.checking import expect, finish


def run(binary, *args):
    p = subprocess.run([binary] + [str(a) for a in args], capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def table(text):
    lines = text.strip().splitlines()
    head = lines[0].split(",")
    return [dict(zip(head, (float(x) for x in line.split(",")))) for line in lines[1:]]


def write(path, lines):
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def sinusoid(binary, work):
    L, a, periods, n_per = 100e-6, 0.5, 10, 2000
    A = a * L / (2 * math.pi)
    rho = L / math.pi
    # The moments of atan(a cos phi), phi uniform: trapezoid over a period
    phi = np.linspace(0, 2 * math.pi, 200001)
    t = np.arctan(a * np.cos(phi))
    m2 = np.trapz(t ** 2, phi) / (2 * math.pi)
    m4 = np.trapz(t ** 4, phi) / (2 * math.pi)
    kurtosis = m4 / m2 ** 2 - 3
    for frac in (0.1, 0.5, 0.9):
        r = frac * rho
        # Trace over [0, periods L + 2 r]: the statistics cover [r, periods L + r]
        h = L / n_per
        n = int(round((periods * L + 2 * r) / h)) + 1
        h = (periods * L + 2 * r) / (n - 1)
        x = np.arange(n) * h
        z = A * np.sin(2 * math.pi * x / L)
        path = os.path.join(work, "sinusoid-%g.txt" % frac)
        write(path, ["%.17g %.17g" % p for p in zip(x, z)])
        rc, out, err = run(binary, "--profile", path, "--d", repr(2 * r), "--digits", 17)
        expect(rc == 0, "sinusoid r = %g rho: runs (%s)" % (frac, err.strip()[:200]))
        if rc != 0:
            continue
        row = table(out)[0]
        delta = math.degrees(math.sqrt(m2))
        # O(h^2) polyline error (a k h)^2 and the levelling's residual line
        tol = 2 * (a * 2 * math.pi / L * h) ** 2 / m2 + 1e-5
        expect(abs(row["Delta_deg"] / delta - 1) < tol,
               "sinusoid r = %g rho: Delta %.9f deg = %.9f deg (oracle)"
               % (frac, row["Delta_deg"], delta))
        expect(abs(row["excess_kurtosis"] - kurtosis) < 1e-3,
               "sinusoid r = %g rho: excess kurtosis %.6f = %.6f (oracle)"
               % (frac, row["excess_kurtosis"], kurtosis))
        expect(abs(row["skewness"]) < 1e-3, "sinusoid r = %g rho: skewness %.2g = 0"
               % (frac, row["skewness"]))
        expect(abs(row["length_m"] - periods * L) < 1e-9 * L,
               "sinusoid r = %g rho: covers %d periods" % (frac, periods))
        if frac == 0.5:
            # The same trace in mm and um, with a header and comments
            other = os.path.join(work, "sinusoid-mm.csv")
            write(other, ["Instrument export", "x [mm]; z [um]", "# units mm um",
                          "% comment"]
                  + ["%.17g; %.17g" % (xi * 1e3, zi * 1e6) for xi, zi in zip(x, z)])
            rc2, out2, _ = run(binary, "--profile", other, "--d", repr(2 * r),
                               "--digits", 17)
            row2 = table(out2)[0] if rc2 == 0 else {}
            expect(rc2 == 0 and abs(row2["Delta_deg"] / row["Delta_deg"] - 1) < 1e-12,
                   "sinusoid in mm/um with a header: the same Delta")


def flat(binary, work):
    path = os.path.join(work, "flat.txt")
    write(path, ["%g 2e-6" % (i * 1e-6) for i in range(400)])
    rc, out, err = run(binary, "--profile", path, "--d", "20e-6,100e-6")
    rows = table(out) if rc == 0 else []
    expect(rc == 0 and len(rows) == 2 and all(r["Delta_deg"] == 0 for r in rows),
           "flat trace: Delta = 0 (%s)" % err.strip()[:200])


def synthetic(binary, work):
    Rq, RSm = 2e-6, 60e-6
    sigma = 2 * math.pi * Rq / RSm
    xg, wg = np.polynomial.hermite_e.hermegauss(80)
    limit = math.degrees(math.sqrt(np.sum(wg * np.arctan(sigma * xg) ** 2) / np.sum(wg)))
    ds = "3e-6,60e-6,600e-6"
    rc, out, err = run(binary, "--Rq", Rq, "--RSm", RSm, "--d", ds, "--digits", 17)
    expect(rc == 0, "synthetic: runs")
    rows = table(out)
    expect(abs(rows[0]["Delta_deg"] / limit - 1) < 0.02,
           "synthetic d = RSm/20: Delta %.4f deg = small-sphere limit %.4f deg within 2 %%"
           % (rows[0]["Delta_deg"], limit))
    for row in rows:
        closed = math.degrees(math.atan(2 * math.pi * Rq / max(RSm, row["d_m"])))
        expect(abs(row["closed_form_deg"] - closed) < 1e-12 * closed,
               "synthetic d = %g: closed form %.6f deg (typed)" % (row["d_m"], closed))
    expect(rows[2]["Delta_deg"] < rows[1]["Delta_deg"] < rows[0]["Delta_deg"],
           "synthetic: Delta falls with d")
    expect("5000 RSm" in err and "seed 1" in err, "synthetic: stderr describes the profile")
    for option, value in (("--Ra", Rq / math.sqrt(math.pi / 2)), ("--Rz", Rq * 4.11)):
        rc2, out2, err2 = run(binary, option, "%.17g" % value, "--RSm", RSm, "--d", ds,
                              "--digits", 17)
        rows2 = table(out2) if rc2 == 0 else []
        same = len(rows2) == 3 and all(
            abs(a["Delta_deg"] / b["Delta_deg"] - 1) < 1e-9 for a, b in zip(rows2, rows))
        expect(same and "as for a Gaussian profile" in err2,
               "synthetic %s: the table of --Rq %.3g, conversion stated" % (option, Rq))
    rc3, out3, _ = run(binary, "--Rq", Rq, "--RSm", RSm, "--d", "60e-6", "--seed", 2,
                       "--digits", 17)
    expect(rc3 == 0 and table(out3)[0]["Delta_deg"] != rows[1]["Delta_deg"],
           "synthetic: --seed changes the profile")


def bad_input(binary, work):
    good = os.path.join(work, "good.txt")
    write(good, ["%g %g" % (i * 1e-6, 1e-6 * math.sin(i / 5)) for i in range(100)])
    files = {
        "nonmonotone.txt": (["0 1e-6", "1e-6 2e-6", "1e-6 3e-6"]
                            + ["%g 0" % (i * 1e-6) for i in range(2, 20)],
                            ":3: x = 1e-06 m is not above"),
        "nan.txt": (["%g 0" % (i * 1e-6) for i in range(5)] + ["5e-6 nan"]
                    + ["%g 0" % (i * 1e-6) for i in range(6, 20)],
                    ":6: not a finite number"),
        "few.txt": (["%g 0" % (i * 1e-6) for i in range(5)],
                    ": 5 points in 5 lines, at least 10 needed"),
        "text.txt": (["%g 0" % (i * 1e-6) for i in range(5)] + ["oops"],
                     ":6: expected two numbers"),
    }
    for name, (lines, expected) in files.items():
        path = os.path.join(work, name)
        write(path, lines)
        rc, out, err = run(binary, "--profile", path, "--d", "2e-6")
        expect(rc == 2 and (path + expected) in err,
               "%s: exit 2 and '%s%s' (got %d: %s)" % (name, path, expected, rc,
                                                      err.strip()[:200]))
    missing = os.path.join(work, "missing.txt")
    rc, out, err = run(binary, "--profile", missing, "--d", "2e-6")
    expect(rc == 2 and missing + ": cannot open" in err, "missing file named")
    for args, named in [
        (["--profile", good, "--d", "-1e-6"], "--d values must be"),
        (["--profile", good], "--profile needs --d"),
        (["--profile", good, "--Rq", "1e-6", "--d", "1e-5"], "--Rq is for the synthetic"),
        (["--Rq", "1e-6", "--d", "1e-5"], "--RSm must be"),
        (["--Rq", "1e-6", "--RSm", "6e-5", "--d", "1e-5", "--Delta", "5"],
         "--Delta has no meaning with --d"),
        (["--Rq", "1e-6", "--RSm", "6e-5", "--d", "1e-5", "--length", "5"],
         "--length must be"),
        (["--Rq", "1e-6", "--RSm", "6e-5", "--d", "1e-5,x"], "--d needs a finite number"),
    ]:
        rc, out, err = run(binary, *args)
        expect(rc == 2 and named in err, "%s: exit 2 and '%s' (got %d: %s)"
               % (" ".join(args[-4:]), named, rc, err.strip()[:200]))
    rc, out, err = run(binary, "--profile", good, "--d", "200e-6")
    expect(rc == 1 and "not longer than the diameter" in err,
           "trace shorter than the diameter: exit 1, said (%s)" % err.strip()[:200])


def plot(binary, work):
    png = os.path.join(work, "delta.png")
    if os.path.exists(png):
        os.remove(png)
    rc, out, err = run(binary, "--Rq", "2e-6", "--RSm", "60e-6", "--d", "6e-6,60e-6,6e-4",
                       "--length", "200", "--plot", png)
    ok = rc == 0 and os.path.exists(png)
    if ok:
        with open(png, "rb") as f:
            ok = f.read(8) == b"\x89PNG\r\n\x1a\n"
    expect(ok, "--plot writes a PNG (%s)" % err.strip()[:200])


def rsm(binary, work):
    L, A, h, half = 100e-6, 2e-6, 0.1e-6, 10300
    x = np.arange(-half, half + 1) * h
    z = A * np.cos(2 * math.pi * x / L)
    path = os.path.join(work, "cosine.txt")
    write(path, ["# units um um"] + ["%.17g %.17g" % (xi * 1e6, zi * 1e6)
                                     for xi, zi in zip(x, z)])
    # Levelled here: the least-squares line (zero slope: even trace)
    slope, mean = np.polyfit(x, z, 1)
    Rq = math.sqrt(np.mean((z - mean - slope * x) ** 2))
    ds = (20e-6, 300e-6)
    rc, out, err = run(binary, "--profile", path, "--d", "%r,%r" % ds, "--digits", 17)
    expect(rc == 0, "cosine trace: runs (%s)" % err.strip()[:200])
    if rc != 0:
        return
    rows = table(out)
    for d, row in zip(ds, rows):
        RSm = d / row["d_over_RSm"]
        expect(abs(RSm / L - 1) < 1e-6,
               "cosine trace d = %g: RSm %.12g m = L = %g m (1e-6)" % (d, RSm, L))
        closed = math.degrees(math.atan(2 * math.pi * Rq / max(L, d)))
        expect(abs(row["closed_form_deg"] / closed - 1) < 1e-6,
               "cosine trace d = %g: closed form %.9f deg = %.9f deg (RSm = L)"
               % (d, row["closed_form_deg"], closed))
    expect("21 zero up-crossings" in err, "cosine trace: stderr counts 21 up-crossings")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--case", required=True,
                        choices=["sinusoid", "flat", "synthetic", "badInput", "plot",
                                 "rsm"])
    args = parser.parse_args()
    work = os.path.join(args.work, args.case)
    os.makedirs(work, exist_ok=True)
    {"sinusoid": sinusoid, "flat": flat, "synthetic": synthetic,
     "badInput": bad_input, "plot": plot, "rsm": rsm}[args.case](args.binary, work)
    if finish():
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
