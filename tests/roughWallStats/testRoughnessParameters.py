#!/usr/bin/env python3
"""roughWallStats with the wall's profile parameters and a diameter.

Oracle: equation (1) of docs/roughWallInteraction.md, typed here,
Delta = atan(2 pi Rq / max(RSm, d)) (Rq = sqrt(pi/2) Ra, or Rz/4.11, as for
a Gaussian profile when Rq is not given; Ra before Rz).  For diameters below and above the regime change
d = RSm the table printed with --Rq/--Ra, --RSm, --diameter must equal the
table printed with --Delta set to the hand-computed angle (to 1e-9
relative: the two differ only by the rounding of the degrees), and stderr
must state that Delta.  Bad input: exit code 2, the option named.

Usage: testRoughnessParameters.py --binary PATH
SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import math
import subprocess
import sys

from foamcase.checking import expect, finish


def run(binary, *args):
    p = subprocess.run([binary] + list(args), capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def table(text):
    rows = [line.split(",") for line in text.strip().splitlines()]
    return rows[0], [[float(x) for x in row] for row in rows[1:]]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    binary = parser.parse_args().binary
    alphas = "5,10,30,60"

    # (options, diameter, Delta by hand [deg])
    cases = [
        (["--Rq", "2e-6", "--RSm", "60e-6"], 30e-6,
         math.degrees(math.atan(2 * math.pi * 2e-6 / 60e-6))),
        (["--Rq", "2e-6", "--RSm", "60e-6"], 195e-6,
         math.degrees(math.atan(2 * math.pi * 2e-6 / 195e-6))),
        (["--Ra", "1.5e-6", "--RSm", "40e-6"], 110e-6,
         math.degrees(math.atan(2 * math.pi * math.sqrt(math.pi / 2)
                                * 1.5e-6 / 110e-6))),
        # Rz alone: Rq = Rz/4.11
        (["--Rz", "6e-6", "--RSm", "40e-6"], 30e-6,
         math.degrees(math.atan(2 * math.pi * 6e-6 / 4.11 / 40e-6))),
        # Ra and Rz without Rq: Rq from Ra (Rz, inconsistent with Ra here,
        # would give 4.87e-6 instead of 1.25e-6)
        (["--Ra", "1e-6", "--Rz", "20e-6", "--RSm", "40e-6"], 30e-6,
         math.degrees(math.atan(2 * math.pi * math.sqrt(math.pi / 2)
                                * 1e-6 / 40e-6))),
    ]
    for options, d, delta in cases:
        rc, out, err = run(binary, *options, "--diameter", repr(d),
                           "--alpha", alphas)
        rc_ref, out_ref, _ = run(binary, "--Delta", "%.17g" % delta,
                                 "--alpha", alphas)
        expect(rc == 0 and rc_ref == 0, "%s d = %g: runs" % (options, d))
        head, rows = table(out)
        head_ref, rows_ref = table(out_ref)
        worst = max(abs(a - b) / max(abs(b), 1e-12)
                    for row, ref in zip(rows, rows_ref)
                    for a, b in zip(row, ref))
        expect(head == head_ref and len(rows) == len(rows_ref)
               and worst < 1e-9,
               "%s d = %g: the table of Delta = %.6f deg (largest relative "
               "difference %.2g)" % (options, d, delta, worst))
        expect("Delta = %.6g deg" % delta in err,
               "%s d = %g: stderr states Delta = %.6g deg" % (options, d, delta))

    for options, named in [
        (["--Ra", "-1e-6", "--RSm", "60e-6", "--diameter", "1e-4"], "--Ra"),
        (["--Rq", "0", "--RSm", "60e-6", "--diameter", "1e-4"], "--Rq"),
        (["--Ra", "2e-6", "--Rq", "1e-6", "--RSm", "60e-6",
          "--diameter", "1e-4"], "--Rq"),
        (["--Ra", "2e-6", "--RSm", "1e-6", "--diameter", "1e-4"], "--RSm"),
        (["--Ra", "2e-6", "--diameter", "1e-4"], "--RSm"),
        (["--Ra", "2e-6", "--RSm", "60e-6"], "--diameter"),
        (["--Ra", "2e-6", "--RSm", "60e-6", "--diameter", "0"], "--diameter"),
        (["--Delta", "5", "--Ra", "2e-6", "--RSm", "60e-6",
          "--diameter", "1e-4"], "--Delta"),
        # Flanks steeper than 45 deg with Rq from Ra (2 pi 1.25e-6/6e-6 =
        # 1.31) or from Rz (2 pi 1.22e-6/6e-6 = 1.27)
        (["--Ra", "1e-6", "--RSm", "6e-6", "--diameter", "1e-4"], "--RSm"),
        (["--Rz", "5e-6", "--RSm", "6e-6", "--diameter", "1e-4"], "--RSm"),
    ]:
        rc, _, err = run(binary, *options)
        expect(rc == 2 and named in err,
               "%s: exit code 2 (%d), names %s" % (" ".join(options), rc, named))

    sys.exit(finish())


if __name__ == "__main__":
    main()
