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

HEADER = ("alpha_deg,mean_kn,sd_kn,mean_abs_kn,mean_kt,sd_kt,mean_kOmega,sd_kOmega,"
          "p_noslip,p_wallward").split(",")


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)
    print("ok:", message)


def run(binary, *args, expect=0):
    result = subprocess.run([binary, *args], capture_output=True, text=True, timeout=300)
    if result.returncode != expect:
        raise Failure("%s %s: exit code %d, expected %d\nstdout: %s\nstderr: %s" % (
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
    except Failure as failure:
        print("TEST FAILED:", failure)
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
