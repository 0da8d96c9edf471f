"""What decides whether a core fault is killed, and its fingerprint.

A core fault is killed when one of its tests fails with the fault's edits
applied. Whether that happens depends only on: the fault itself (its
edits and its tests' regular expression), the files it edits, the test
sources that define the tests its regular expression selects, the build
files of those tests, and every project file these include (#include
"...", transitively). The fingerprint is the SHA-256 of all of them. A
fault recorded as killed with the same fingerprint would be killed again:
mutate.py --incremental skips it and reports the recorded kill.

Which test sources a regular expression selects:
  ^core\\.          the Google Test files of tests/core whose TEST(Suite,
                   Name) make a name core.Suite.Name that it matches
  anything else    (roughWallStats.*, oracle.*: command-line tools run by
                   CMake tests) every file of tests/roughWallStats,
                   tests/oracle, applications/roughWallStats and the
                   Python package the tests use (src/python/foamcase)

SPDX-License-Identifier: GPL-3.0-or-later
"""

import glob
import hashlib
import json
import os
import re

#: Where a quoted #include is looked for, after the including file's folder
INCLUDE_DIRS = ("src/roughWallCore", "tests/core", "tests/roughWallStats",
                "tests/oracle", "applications/roughWallStats")
#: The folders of the tools' tests (not Google Test)
TOOL_TESTS = ("tests/roughWallStats", "tests/oracle",
              "applications/roughWallStats", "src/python/foamcase")
SOURCE = re.compile(r"\.(c|cc|cpp|h|hh|hpp|H|C|py|txt|cmake)$")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
GTEST = re.compile(r"^\s*TEST(?:_F|_P)?\s*\(\s*(\w+)\s*,\s*(\w+)\s*\)", re.M)


def _read(repo, rel):
    with open(os.path.join(repo, rel), "rb") as f:
        return f.read()


def include_closure(repo, files):
    """files and every project file they include, transitively (paths
    relative to repo)"""
    seen, todo = set(), list(files)
    while todo:
        rel = todo.pop()
        if rel in seen or not os.path.isfile(os.path.join(repo, rel)):
            continue
        seen.add(rel)
        text = _read(repo, rel).decode("utf-8", "replace")
        for name in INCLUDE.findall(text):
            for folder in (os.path.dirname(rel),) + INCLUDE_DIRS:
                candidate = os.path.normpath(os.path.join(folder, name))
                if os.path.isfile(os.path.join(repo, candidate)):
                    todo.append(candidate)
                    break
    return seen


def test_sources(repo, regex):
    """The test sources that define the tests regex selects (see the
    module's docstring), with their build files"""
    pattern = re.compile(regex)
    if regex.startswith("^core"):
        files = []
        for path in sorted(glob.glob(os.path.join(repo, "tests", "core",
                                                  "*.cc"))):
            text = _read(repo, os.path.relpath(path, repo)).decode(
                "utf-8", "replace")
            if any(pattern.search("core.%s.%s" % m)
                   for m in GTEST.findall(text)):
                files.append(os.path.relpath(path, repo))
        return files + ["tests/core/CMakeLists.txt"]
    files = []
    for folder in TOOL_TESTS:
        for base, _, names in os.walk(os.path.join(repo, folder)):
            files += [os.path.relpath(os.path.join(base, n), repo)
                      for n in names if SOURCE.search(n)]
    return sorted(files)


def inputs(repo, fault, regex):
    """Every file that decides whether the fault is killed"""
    edited = sorted({e["file"] for e in fault["edits"]})
    return sorted(include_closure(repo, edited + test_sources(repo, regex))
                  | {"CMakeLists.txt", "src/roughWallCore/CMakeLists.txt"})


def fingerprint(repo, fault, regex):
    """SHA-256 of the fault and of its inputs' contents"""
    h = hashlib.sha256()
    h.update(json.dumps({"edits": fault["edits"], "tests": regex},
                        sort_keys=True).encode())
    for rel in inputs(repo, fault, regex):
        path = os.path.join(repo, rel)
        h.update(rel.encode() + b"\0")
        h.update(_read(repo, rel) if os.path.isfile(path) else b"(missing)")
        h.update(b"\0")
    return h.hexdigest()
