#!/usr/bin/python3
# Tests of the roughWallStats binary: its interface, exit codes, CSV tables,
# speed, pdf output and plots. Each --case is one ctest test.
# SPDX-License-Identifier: GPL-3.0-or-later
import argparse
import csv
import io
import math
import os
import subprocess
import sys

from foamcase.checking import TestFailure, check
HEADER = ("alpha_deg,mean_kn,sd_kn,mean_abs_kn,mean_kt,sd_kt,mean_kOmega,sd_kOmega,"
          "p_noslip,p_wallward").split(",")


def run(binary, *args, expect=0):
    result = subprocess.run([binary, *args], capture_output=True, text=True, timeout=300)
    if result.returncode != expect:
        raise TestFailure("%s %s: exit code %d, expected %d\nstdout: %s\nstderr: %s" % (
            binary, " ".join(args), result.returncode, expect, result.stdout[-2000:],
            result.stderr[-2000:]))
    return result


def table(text):
    rows = list(csv.reader(io.StringIO(text)))
    return rows[0], [dict(zip(rows[0], r)) for r in rows[1:]]


def case_table(binary, work):
    """Default run: the issue's columns, 8 rows (its speed is a benchmark:
    docs/benchmarks.md)."""
    result = run(binary)
    header, rows = table(result.stdout)
    check(header == HEADER, "quadrature header is the issue's column list")
    check([float(r["alpha_deg"]) for r in rows] == [1, 2, 5, 10, 15, 30, 45, 89],
          "one row per default angle")
    small = rows[0]
    check(float(small["mean_kn"]) > 1, "mean k_n > 1 at alpha = 1 deg (Delta = 8)")
    check(all(0 <= float(r["p_noslip"]) <= 1 and 0 <= float(r["p_wallward"]) <= 1 for r in rows),
          "probabilities in [0, 1]")
    check(all(float(r["mean_abs_kn"]) >= float(r["mean_kn"]) for r in rows), "mean |kn| >= mean kn")

    # alpha = 90: k_t, k_Omega undefined -> empty fields, a note on stderr
    result = run(binary, "--alpha", "89.999,90", "--Delta", "5")
    header, rows = table(result.stdout)
    check(rows[1]["mean_kt"] == "" and rows[1]["sd_kOmega"] == "", "k_t, k_Omega empty at 90 deg")
    check(rows[0]["mean_kt"] != "", "k_t defined at 89.999 deg")
    check("undefined at alpha = 90" in result.stderr, "note on stderr at 90 deg")
    D = math.radians(5)
    plateau = 0.8 * (1 + math.exp(-2 * D * D)) / 2 - 5 / 7 * (1 - math.exp(-2 * D * D)) / 2
    check(abs(float(rows[1]["mean_kn"]) - plateau) < 1e-10, "mean k_n at 90 deg is its closed form")

    # --output writes the file, stdout stays empty
    path = os.path.join(work, "table.csv")
    result = run(binary, "--alpha", "5,10", "--output", path)
    check(result.stdout == "" and open(path).readline().strip() == ",".join(HEADER),
          "--output writes the table to the file")


def case_badInput(binary, work):
    """Bad input: exit code 2, a message naming the option."""
    for args, option in [
            (["--Delta", "-1"], "--Delta"), (["--e", "1.5"], "--e"), (["--mud", "0.5"], "--mud"),
            (["--alpha", "0"], "--alpha"), (["--alpha", "95"], "--alpha"),
            (["--Delta", "eight"], "--Delta"), (["--frobnicate"], "--frobnicate"),
            (["--method", "simpson"], "--method"), (["--samples", "-5"], "--samples"),
            (["--pdf", "kn", "--alpha", "1,2"], "--pdf"),
            (["--recollide", "--method", "quadrature"], "--recollide")]:
        result = run(binary, *args, expect=2)
        check(option in result.stderr and result.stdout == "",
              "%s -> exit 2, message names %s" % (" ".join(args), option))
    result = run(binary, "--help")
    check("--Delta" in result.stdout and "--pdf" in result.stdout, "--help prints the usage")


def case_impactDependent(binary, work):
    """e, mu0, mud as functions of the facet impact (issue 31): bad input
    exits 2 with a message naming the option, the argument and the value;
    a table of one constant value gives the constant's statistics exactly
    (oracle: the constant run of the same tool, whose own oracles are
    tests/roughWallStats and oracle.roughWallStats); a table that falls
    with the angle lowers mean k_n below e = its largest value."""
    os.makedirs(work, exist_ok=True)

    def write(name, text):
        path = os.path.join(work, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    e_above = write("eAbove.dat", "0 0.9\n45 1.2\n90 0.8\n")
    mud_above = write("mudAbove.dat", "# angle mud\n0 0.2\n60 0.5\n90 0.1\n")
    descending = write("descending.dat", "0 0.9\n50 0.8\n40 0.7\n")
    odd = write("odd.dat", "0 0.9 45\n")
    for args, words in [
            (["--e-table", e_above], ["--e-table", "e = 1.2", "angle = 45"]),
            (["--mud-table", mud_above, "--mu0", "0.4"],
             ["--mud-table with --mu0", "muD = 0.5", "angle = 60", "[0, mu0] (mu0 = 0.4)"]),
            (["--mu0-polynomial", "0.4,-0.01", "--mud", "0"],
             ["--mu0-polynomial", "mu0 = -", "outside [0, inf)"]),
            (["--mu0-polynomial", "0.4,-0.01"],
             ["--mud with --mu0-polynomial", "muD = 0.4", "outside [0, mu0]"]),
            (["--e-polynomial", "0.5,0.1", "--e-argument", "normalSpeed",
              "--speed", "10"], ["--e-polynomial", "normalSpeed", "outside [0, 1]"]),
            (["--e-table", descending], ["--e-table", "ascend", "40 after 50"]),
            (["--e-table", odd], ["--e-table", "pairs"]),
            (["--e-table", os.path.join(work, "missing.dat")], ["--e-table", "cannot read"]),
            (["--e", "0.8", "--e-table", e_above], ["--e", "not both"]),
            (["--e-table", e_above, "--e-polynomial", "0.8"], ["--e-table", "not both"]),
            (["--e-argument", "speed", "--e-polynomial", "0.8"], ["--e-argument", "'speed'"]),
            (["--speed", "3"], ["--speed", "normalSpeed"]),
            (["--e-polynomial", "0.8", "--pdf", "kn", "--alpha", "10"], ["--pdf", "constant"])]:
        result = run(binary, *args, expect=2)
        check(all(w in result.stderr for w in words) and result.stdout == "",
              "%s -> exit 2, message has %s (got %r)"
              % (" ".join(args), words, result.stderr.strip()))

    flat = write("flat.dat", "((0 0.7) (90 0.7))\n")
    args = ["--alpha", "5,30,80", "--mu0", "0.3", "--mud", "0.2", "--digits", "17"]
    _, constant = table(run(binary, *args, "--e", "0.7").stdout)
    _, tabulated = table(run(binary, *args, "--e-table", flat).stdout)
    for a, b in zip(constant, tabulated):
        for key in ("mean_kn", "mean_kt", "sd_kn", "sd_kt"):
            x, y = float(a[key]), float(b[key])
            check(abs(x - y) <= 1e-9*abs(x),
                  "alpha %s: %s of a flat table %r = the constant's %r"
                  % (a["alpha_deg"], key, y, x))
    falling = write("falling.dat", "0 0.9\n90 0.5\n")
    _, rows = table(run(binary, "--alpha", "30", "--e-table", falling).stdout)
    _, rows9 = table(run(binary, "--alpha", "30", "--e", "0.9").stdout)
    check(float(rows[0]["mean_kn"]) < float(rows9[0]["mean_kn"]) - 0.05,
          "a falling e(angle) lowers mean k_n below the constant e = 0.9")


def significant_digits(text):
    """Significant digits written in a %g field"""
    mantissa = text.lower().split("e")[0].lstrip("-").replace(".", "")
    return len(mantissa.lstrip("0"))


def case_digits(binary, work):
    """--digits N: %.Ng numbers (17: every double exactly), 12 by default;
    bad values exit 2 naming the option and its range."""
    args = ["--alpha", "0.5,5,11.6,45,89,90", "--spin", "0.3"]
    default = run(binary, *args).stdout
    d12 = run(binary, *args, "--digits", "12").stdout
    d17 = run(binary, *args, "--digits=17").stdout
    check(default == d12, "default output is --digits 12, byte for byte")
    h12, rows12 = table(d12)
    h17, rows17 = table(d17)
    check(h12 == h17 == HEADER and len(rows12) == len(rows17) == 6, "same header and rows")
    values = 0
    longer = 0
    for r12, r17 in zip(rows12, rows17):
        for key in HEADER:
            a, b = r12[key], r17[key]
            if a == "" or b == "":
                check(a == b == "", "alpha %s: %s empty in both" % (r12["alpha_deg"], key))
                continue
            x = float(b)
            # %.17g identifies the double: printing it again gives the same
            # text, and rounding it to 12 digits gives the default's text
            if "%.17g" % x != b or "%.12g" % x != a:
                raise TestFailure("alpha %s, %s: '%s' is not %%.17g, or not '%s' at 12 digits" % (
                    r12["alpha_deg"], key, b, a))
            if abs(float(a) - x) > 5e-12 * abs(x):
                raise TestFailure("alpha %s, %s: 12 digits %s against 17 digits %s" % (
                    r12["alpha_deg"], key, a, b))
            values += 1
            longer += significant_digits(b) > 12
    check(values == 6 * 10 - 4, "%d values: 17-digit text is %%.17g and rounds to the 12-digit "
          "text (agree within 5e-12 relative)" % values)
    check(longer > values // 2, "%d of %d values have more than 12 significant digits" % (
        longer, values))
    mean_kn = [r["mean_kn"] for r in rows17[:4]]
    check(all(significant_digits(v) >= 16 for v in mean_kn),
          "mean k_n printed with 16-17 significant digits: " + ", ".join(mean_kn))

    _, rows3 = table(run(binary, *args, "--digits", "3").stdout)
    check(all("%.3g" % float(r17[k]) == r3[k] for r3, r17 in zip(rows3, rows17) for k in HEADER
              if r3[k] != ""), "--digits 3 prints %.3g")

    # The pdf and Monte Carlo tables follow --digits too (integers stay whole)
    pdf = ["--pdf", "kt", "--alpha", "5", "--bins", "8", "--samples", "2000", "--seed", "3"]
    _, p12 = table(run(binary, *pdf).stdout)
    _, p17 = table(run(binary, *pdf, "--digits", "17").stdout)
    check(all("%.12g" % float(b[k]) == a[k] and (k == "count" or "%.17g" % float(b[k]) == b[k])
              for a, b in zip(p12, p17) for k in a), "pdf table with --digits 17")
    check(all(a["count"] == b["count"] and "." not in b["count"] for a, b in zip(p12, p17)),
          "pdf counts unchanged integers")
    mc = ["--alpha", "20", "--method", "montecarlo", "--samples", "2000"]
    _, m17 = table(run(binary, *mc, "--digits", "17").stdout)
    check(m17[0]["samples"] == "2000" and significant_digits(m17[0]["se_mean_kn"]) > 12,
          "Monte Carlo table with --digits 17")

    for value in ["0", "18", "12.5", "-1"]:
        result = run(binary, "--digits", value, expect=2)
        check("--digits must be an integer in [1, 17]" in result.stderr and result.stdout == "",
              "--digits %s -> exit 2, names --digits and [1, 17]" % value)
    for extra, message in [(["--digits", "many"], "--digits needs a finite number"),
                           (["--digits"], "--digits needs a value")]:
        result = run(binary, *extra, expect=2)
        check(message in result.stderr and result.stdout == "",
              "%s -> exit 2: %s" % (" ".join(extra), message))
    result = run(binary, "--help")
    check("--digits N" in result.stdout and "1 .. 17" in result.stdout, "--help lists --digits")


def case_monteCarlo(binary, work):
    """Monte Carlo: se_* columns, reproducible by seed, agrees with quadrature."""
    args = ["--alpha", "3,20,60", "--spin", "0.3", "--method", "montecarlo", "--samples", "200000"]
    a = run(binary, *args, "--seed", "4").stdout
    b = run(binary, *args, "--seed", "4").stdout
    c = run(binary, *args, "--seed", "5").stdout
    check(a == b, "same seed, same table")
    check(a != c, "another seed, another table")
    header, mc = table(a)
    for column in ["se_mean_kn", "se_mean_abs_kn", "se_mean_kt", "se_mean_kOmega",
                   "se_p_noslip", "se_p_wallward"]:
        check(column in header, "column " + column)
    # a row does not depend on the other angles asked for
    _, single = table(run(binary, *args[2:], "--alpha", "20", "--seed", "4").stdout)
    check(single[0] == mc[1], "a row is reproducible on its own")
    _, quad = table(run(binary, "--alpha", "3,20,60", "--spin", "0.3").stdout)
    for q, m in zip(quad, mc):
        for key in ["kn", "abs_kn", "kt", "kOmega"]:
            z = abs(float(q["mean_" + key]) - float(m["mean_" + key])) / float(m["se_mean_" + key])
            check(z < 4, "alpha %s: mean %s within 4 se (z = %.2f)" % (q["alpha_deg"], key, z))

    header, rows = table(run(binary, "--recollide", "--alpha", "5,12", "--samples", "100000").stdout)
    check("mean_facet_collisions" in header and "p_fallback" in header,
          "--recollide adds mean_facet_collisions, p_fallback")
    check(all(float(r["p_wallward"]) == 0 and float(r["mean_facet_collisions"]) > 1 for r in rows),
          "--recollide: p_wallward = 0 and more than one facet collision on average")
    header, rows = table(run(binary, "--lateral", "--alpha", "45", "--samples", "100000").stdout)
    check(abs(float(rows[0]["mean_kn"]) - 0.765) < 0.003, "--lateral at 45 deg: mean k_n ~ 0.765")


def case_pdf(binary, work):
    """--pdf: density by (2.8), exact bin probabilities and histogram, same bins."""
    result = run(binary, "--pdf", "kn", "--alpha", "5", "--bins", "40", "--samples", "400000",
                 "--seed", "9")
    header, rows = table(result.stdout)
    check(header == ["k_lo", "k_hi", "k", "pdf", "pdf_bin", "pdf_montecarlo",
                     "se_pdf_montecarlo", "count"], "pdf header")
    check(len(rows) == 40, "40 bins")
    width = [float(r["k_hi"]) - float(r["k_lo"]) for r in rows]
    exact = sum(float(r["pdf_bin"]) * w for r, w in zip(rows, width))
    check(1 - 2.1e-4 < exact <= 1 + 1e-12, "exact probability in the default range %.6f" % exact)
    worst = 0
    for r, w in zip(rows, width):
        expected = 400000 * float(r["pdf_bin"]) * w
        if expected > 20:
            worst = max(worst, abs(int(r["count"]) - expected) / math.sqrt(expected))
    check(worst < 4.5, "histogram within 4.5 sd of the exact bin probabilities (worst %.2f)" % worst)
    check("probability in range" in result.stderr, "summary on stderr")

    result = run(binary, "--pdf", "kt", "--alpha", "10", "--range", "0,1.5", "--bins", "30",
                 "--recollide", "--samples", "50000")
    header, rows = table(result.stdout)
    check("pdf" not in header and "pdf_montecarlo" in header,
          "--recollide pdf: histogram only (the change of variables is of one collision)")
    check(float(rows[0]["k_lo"]) == 0 and float(rows[-1]["k_hi"]) == 1.5, "--range sets the bins")


def case_plot(binary, work):
    """--plot: PNG figures of the statistics and of a pdf."""
    for name, args in [("stats.png", ["--alpha", "0.5:0.5:89.5"]),
                       ("pdf.png", ["--pdf", "kt", "--alpha", "5", "--samples", "100000"])]:
        path = os.path.join(work, name)
        if os.path.exists(path):
            os.remove(path)
        run(binary, *args, "--plot", path)
        with open(path, "rb") as f:
            signature = f.read(8)
        check(signature == b"\x89PNG\r\n\x1a\n" and os.path.getsize(path) > 10000,
              "--plot wrote the PNG figure " + name)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--case", required=True)
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    try:
        globals()["case_" + args.case](args.binary, args.work)
    except TestFailure as failure:
        print("TEST FAILED:", failure)
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
