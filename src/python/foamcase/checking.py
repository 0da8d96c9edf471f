"""The assertions of every test script of the project: one check().

check(condition, message) prints "PASS  message" or "FAIL  message" (the
ctest FAIL_REGULAR_EXPRESSION of the Python tests matches "FAIL  ") and
raises TestFailure when the condition is false; expect() is the same check
that keeps going: the failure is kept in FAILED and finish() reports all of
them at the end (the scripts that list every failed value, as gtest's EXPECT
beside ASSERT).  Checker groups expect()s under a title (the oracle tests).

SPDX-License-Identifier: GPL-3.0-or-later
"""

import sys
import time


class TestFailure(Exception):
    """A failed assertion, or a test that cannot run."""


#: Messages of the failed expect()s, and the number of passed checks
FAILED = []
PASSED = [0]


def check(condition, message, stop=True):
    """Record one assertion: print it; if it fails, raise TestFailure
    (stop) or keep it in FAILED.  Returns the condition."""
    print(("PASS  " if condition else "FAIL  ") + message, flush=True)
    if condition:
        PASSED[0] += 1
    elif stop:
        raise TestFailure(message)
    else:
        FAILED.append(message)
    return condition


def expect(condition, message):
    """check() that keeps going after a failure (finish() reports it)."""
    return check(condition, message, stop=False)


def finish():
    """End of a script of expect()s: 1 (after "TEST FAILED") if one failed,
    else 0."""
    if FAILED:
        print("TEST FAILED: %d check(s)" % len(FAILED))
        return 1
    return 0


class Checker:
    """The expect()s of one test, with their count and time: within() and
    within_se() compare a value with its reference, finish() exits."""

    def __init__(self, title):
        self.title = title
        self.failures = []
        self.count = 0
        self.start = time.time()
        print(f"== {title}", flush=True)

    def check(self, name, ok, detail=""):
        self.count += 1
        if not expect(ok, f"{name}: {detail}"):
            self.failures.append(name)
        return ok

    def within(self, name, value, expected, tol, unit=""):
        """|value - expected| <= tol."""
        diff = abs(value - expected)
        return self.check(
            name, diff <= tol,
            f"{value:.6g} vs {expected:.6g}, |diff| {diff:.3g} <= {tol:.3g}{unit}")

    def within_se(self, name, value, expected, se, k=4.0):
        """|value - expected| <= k se."""
        diff = abs(value - expected)
        z = diff/se if se > 0 else (0.0 if diff == 0 else float("inf"))
        return self.check(
            name, diff <= k*se,
            f"{value:.6g} vs {expected:.6g}, |diff| {diff:.3g} = {z:.2f} se"
            f" (limit {k:g} se, se {se:.3g})")

    def finish(self):
        took = time.time() - self.start
        if self.failures:
            print(f"TEST FAILED: {len(self.failures)} of {self.count} checks "
                  f"failed ({', '.join(self.failures[:10])}) [{took:.1f} s]")
            sys.exit(1)
        print(f"all {self.count} checks passed [{took:.1f} s]")
        sys.exit(0)
