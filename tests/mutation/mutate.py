#!/usr/bin/python3
"""Mutation check: do the tests catch deliberate faults in the physics?

For each fault of faults.json (an exact text substitution in src/, or a few
of them) on a private copy of the tracked tree: apply the fault, rebuild what
it touches, run the ctest tests that should catch it, record the tests that
failed ("killed by"), restore the file.  A fault that no test kills survives:
the check fails, since a survivor means a missing test.  A fault whose text
does not occur exactly once in the current source makes the fault list
stale: the check fails before anything is built.

Levels:
  core      the framework-free core (src/roughWallCore): the copy is
            configured with CMake and only the targets of each fault are
            rebuilt, and of those only the files that depend on the fault's
            own edits (the build folder of the unchanged copy is put back
            after each fault; ctest label "mutation", part of the default
            run)
  openfoam  the OpenFOAM adapter (src/roughWallInteraction): the library is
            built by wmake into a private FOAM_USER_LIBBIN (a private HOME in
            the copy) and the OpenFOAM-level tests of one platform are run
            (ctest label "mutationOpenFOAM", disabled unless CMake is given
            -DROUGHWALL_MUTATION_OPENFOAM=ON)

Usage:
  tests/mutation/mutate.py --level core|openfoam [--report FILE]
      [--only NAME,NAME] [--platform openfoam14] [--work DIR] [--keep]
      [--baseline] [--overlay BRANCH] [--jobs N]
      [--incremental] [--record]
  tests/mutation/mutate.py --stale-only     (the fault list's texts only)

Core level, kills kept (killed-core.json): a core fault's kill depends only
on the fault, the files it edits, the test sources of its tests and what
they include (faultInputs.py). --record writes, for every fault killed in
the run, the fingerprint of these (SHA-256) with the commit and the tests
that killed it into tests/mutation/killed-core.json; --incremental runs
only the faults whose fingerprint differs from the recorded one (a fault
or a file it depends on changed since) and reports the others as killed
at the recorded commit. ctest's mutation.core runs --incremental.

With PYTHONPATH=<checkout>/src/python (ctest sets it): the platforms come
from etc/platforms through foamcase.platforms.

The report (markdown) lists fault, file, tests run, killed by and time, with
the commit of the source tree.  Debian's python3 (numpy, as foamcase).

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

try:
    # The platforms and the default one: etc/platforms, read by foamcase
    from foamcase.platforms import DEFAULT_PLATFORM, PLATFORMS
except ImportError:
    print("TEST FAILED: mutate.py imports foamcase: run it with "
          "PYTHONPATH=<checkout>/src/python (ctest sets it)", flush=True)
    sys.exit(1)

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
KILLED = os.path.join(HERE, "killed-core.json")

sys.path.insert(0, HERE)
import faultInputs  # noqa: E402


def read_killed():
    try:
        with open(KILLED) as f:
            return json.load(f)
    except OSError:
        return {}


def write_killed(record):
    with open(KILLED, "w") as f:
        json.dump(dict(sorted(record.items())), f, indent=2)
        f.write("\n")


def fail(message):
    print("TEST FAILED: " + message, flush=True)
    sys.exit(1)


def load_faults(path, level, only):
    with open(path) as f:
        data = json.load(f)
    # faultsUnobserved: the block of issue 34 (behaviour no test looked at)
    faults = data["faults"] + data.get("faultsUnobserved", [])
    for fault in faults:
        if "edits" not in fault:
            fault["edits"] = [{"file": fault["file"], "old": fault["old"],
                               "new": fault["new"]}]
    names = [f["name"] for f in faults]
    if len(set(names)) != len(names):
        fail("faults.json: duplicate fault names")
    if only:
        unknown = set(only) - set(names)
        if unknown:
            fail("unknown faults: " + ", ".join(sorted(unknown)))
        faults = [f for f in faults if f["name"] in only]
    return [f for f in faults if f["level"] == level] if level else faults


def check_stale(faults, tree):
    """Every edit's text must occur exactly once in its file"""
    stale = []
    for fault in faults:
        for edit in fault["edits"]:
            path = os.path.join(tree, edit["file"])
            try:
                with open(path) as f:
                    text = f.read()
            except OSError:
                stale.append((fault["name"], edit["file"], "file missing"))
                continue
            count = text.count(edit["old"])
            if count != 1:
                stale.append((fault["name"], edit["file"],
                              "text found %d times" % count))
            if edit["old"] == edit["new"]:
                stale.append((fault["name"], edit["file"], "no change"))
    return stale


def commit_of(repo):
    run = subprocess.run(["git", "-C", repo, "rev-parse", "--short", "HEAD"],
                         capture_output=True, text=True)
    commit = run.stdout.strip() or "unknown"
    dirty = subprocess.run(["git", "-C", repo, "status", "--porcelain",
                            "--untracked-files=no"],
                           capture_output=True, text=True).stdout.strip()
    return commit + ("+changes" if dirty else "")


def put(target, data, mode=None):
    """Write data to target unless it already holds it; a written file gets
    a new mtime, so that a reused build (--keep) recompiles it"""
    try:
        with open(target, "rb") as f:
            if f.read() == data:
                return
    except OSError:
        pass
    os.makedirs(os.path.dirname(target), exist_ok=True)
    with open(target, "wb") as f:
        f.write(data)
    if mode is not None:
        os.chmod(target, mode)
    now = time.time()
    os.utime(target, (now, now + 1))


def copy_tree(repo, dest, overlays):
    """The tracked files as they are in the working tree, then the files an
    overlay branch changed since its merge base with HEAD (as committed)"""
    files = subprocess.run(["git", "-C", repo, "ls-files", "-z"],
                           capture_output=True, check=True).stdout
    for name in files.decode().split("\0"):
        if not name:
            continue
        src = os.path.join(repo, name)
        if not os.path.isfile(src):
            continue
        with open(src, "rb") as f:
            put(os.path.join(dest, name), f.read(), os.stat(src).st_mode)
    described = []
    for ref in overlays:
        base = subprocess.run(["git", "-C", repo, "merge-base", "HEAD", ref],
                              capture_output=True, text=True,
                              check=True).stdout.strip()
        changed = subprocess.run(["git", "-C", repo, "diff", "--name-only",
                                  "--diff-filter=AM", base, ref],
                                 capture_output=True, text=True,
                                 check=True).stdout.split()
        for name in changed:
            data = subprocess.run(["git", "-C", repo, "show",
                                   "%s:%s" % (ref, name)],
                                  capture_output=True, check=True).stdout
            ours = os.path.join(repo, name)
            original = subprocess.run(["git", "-C", repo, "show",
                                       "%s:%s" % (base, name)],
                                      capture_output=True)
            if os.path.isfile(ours) and original.returncode == 0:
                # Changed here too: a three-way merge (git merge-file)
                with tempfile.TemporaryDirectory() as tmp:
                    files = []
                    for label, text in (("base", original.stdout),
                                        ("theirs", data)):
                        files.append(os.path.join(tmp, label))
                        with open(files[-1], "wb") as f:
                            f.write(text)
                    merged = subprocess.run(["git", "merge-file", "-p", ours,
                                             files[0], files[1]],
                                            capture_output=True)
                    if merged.returncode != 0:
                        fail("--overlay %s: %s does not merge cleanly"
                             % (ref, name))
                    data = merged.stdout
            put(os.path.join(dest, name), data, 0o755
                if name.endswith(".py") else 0o644)
        commit = subprocess.run(["git", "-C", repo, "rev-parse", "--short",
                                 ref], capture_output=True,
                                text=True).stdout.strip()
        described.append("%s %s (%d files: %s)" % (
            ref, commit, len(changed), ", ".join(changed)))
    return described


def run(cmd, log, env=None, cwd=None, timeout=None):
    with open(log, "a") as out:
        out.write("\n$ " + " ".join(cmd) + "\n")
        out.flush()
        proc = subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT,
                              env=env, cwd=cwd, timeout=timeout)
    return proc.returncode


def failed_tests(output):
    """Names from ctest's 'The following tests FAILED:' list"""
    names = []
    block = output.split("The following tests FAILED:", 1)
    if len(block) == 2:
        for line in block[1].splitlines():
            m = re.match(r"\s*\d+ - (\S+) \(", line)
            if m:
                names.append(m.group(1))
    return names


def ctest(build, regex, log, env, jobs, timeout):
    # --output-on-failure: the log keeps why each test failed (a kill is
    # the physics check failing, not a case that does not start)
    cmd = ["ctest", "--test-dir", build, "-R", regex, "-j", str(jobs),
           "--timeout", str(timeout), "--output-on-failure"]
    with open(log, "a") as out:
        out.write("\n$ " + " ".join(cmd) + "\n")
    proc = subprocess.run(cmd, capture_output=True, text=True, env=env)
    with open(log, "a") as out:
        out.write(proc.stdout + proc.stderr)
    ran = len(re.findall(r"Test +#\d+: ", proc.stdout))
    return ran, failed_tests(proc.stdout), proc.returncode


def test_names(build, regex, env):
    proc = subprocess.run(["ctest", "--test-dir", build, "-N", "-R", regex],
                          capture_output=True, text=True, env=env)
    return re.findall(r"Test +#\d+: (\S+)", proc.stdout)


class Builder:
    """Builds the copy for one level"""

    def __init__(self, tree, level, platform, log, jobs):
        self.tree = tree
        self.level = level
        self.platform = platform
        self.log = log
        self.jobs = jobs
        self.build = os.path.join(tree, "build")
        self.env = dict(os.environ)
        if level == "openfoam":
            # A private HOME: FOAM_USER_LIBBIN (and the OpenFOAM user
            # directory) of the copy's own, so that no other library is
            # touched. Beside the copy, not in it: wmake links every header
            # under the folder of Make/ into lnInclude, and the OpenFOAM
            # trees of a cache there would be linked too. The cache of the
            # set-up stays the caller's (no second download of v1912's
            # headers)
            home = os.path.join(os.path.dirname(os.path.abspath(tree)), "home")
            os.makedirs(home, exist_ok=True)
            self.env.setdefault(
                "ROUGHWALL_CACHE",
                os.path.join(os.environ.get("XDG_CACHE_HOME")
                             or os.path.join(os.path.expanduser("~"), ".cache"),
                             "roughWallInteraction"))
            self.env["HOME"] = home

    def configure(self):
        return run(["cmake", "-S", self.tree, "-B", self.build,
                    "-DCMAKE_BUILD_TYPE=Release",
                    "-DROUGHWALL_PLATFORMS=" + (self.platform
                                                or DEFAULT_PLATFORM)],
                   self.log, env=self.env) == 0

    def make(self, targets):
        if self.level == "core":
            cmd = ["cmake", "--build", self.build, "-j", str(self.jobs)]
            for t in targets:
                cmd += ["--target", t]
            return run(cmd, self.log, env=self.env) == 0
        script = ('export WM_OPTIONS="${WM_OPTIONS}OpenFOAM${WM_PROJECT_VERSION}"; '
                  'export WM_NCOMPPROCS=%d; '
                  'wmake -s libso' % self.jobs)
        return run([os.path.join(self.tree, "etc", "openfoamEnv"),
                    self.platform, "bash", "-c", script],
                   self.log, env=self.env, cwd=self.tree) == 0

    def _built(self):
        """The build output of the copy. Core: CMake's build folder (objects,
        dependency files, executables; not ctest's Testing/). OpenFOAM:
        wmake's objects and dependency files (Make/<WM_OPTIONS>) and the
        library in the private FOAM_USER_LIBBIN"""
        if self.level == "core":
            paths = []
            for folder, folders, files in os.walk(self.build):
                if folder == self.build:
                    folders[:] = [f for f in folders if f != "Testing"]
                paths += [os.path.join(folder, name) for name in files]
            return paths
        paths = []
        make = os.path.join(self.tree, "Make")
        for folder, _, files in os.walk(make):
            if folder != make:  # not Make/files, Make/options
                paths += [os.path.join(folder, name) for name in files]
        for folder, _, files in os.walk(os.path.join(self.env["HOME"],
                                                     "OpenFOAM")):
            paths += [os.path.join(folder, name) for name in files
                      if name.startswith("libroughWallInteraction")]
        return paths

    def snapshot(self):
        """Keep the build output of the unchanged copy (both levels).
        Without it, the build of each fault also recompiled every file that
        the previous fault touched (its restored text had a new mtime): with
        reset() after each fault, a fault's build compiles only the files
        that depend on its own edits, as an incremental build of the
        unchanged tree with that one edit would"""
        self.pristine = os.path.join(os.path.dirname(self.tree), "pristine")
        shutil.rmtree(self.pristine, ignore_errors=True)
        for path in self._built():
            target = os.path.join(self.pristine, os.path.relpath(path, "/"))
            os.makedirs(os.path.dirname(target), exist_ok=True)
            shutil.copy2(path, target)

    def reset(self):
        """Put back the build output of the unchanged copy, mtimes included;
        output that the unchanged build did not have is removed"""
        for path in self._built():
            kept = os.path.join(self.pristine, os.path.relpath(path, "/"))
            if not os.path.exists(kept):
                os.remove(path)
        for folder, _, files in os.walk(self.pristine):
            for name in files:
                kept = os.path.join(folder, name)
                path = "/" + os.path.relpath(kept, self.pristine)
                try:
                    now = os.stat(path)
                    then = os.stat(kept)
                    if (now.st_mtime_ns == then.st_mtime_ns
                            and now.st_size == then.st_size):
                        continue
                except OSError:
                    pass
                os.makedirs(os.path.dirname(path), exist_ok=True)
                shutil.copy2(kept, path)
        return True


def apply(tree, edits):
    originals = {}
    for edit in edits:
        path = os.path.join(tree, edit["file"])
        if path not in originals:
            with open(path) as f:
                originals[path] = (f.read(), os.stat(path).st_mtime_ns)
        with open(path) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write(text.replace(edit["old"], edit["new"], 1))
    return originals


def restore(originals, keep_mtime=False):
    for path, (text, mtime) in originals.items():
        with open(path, "w") as f:
            f.write(text)
        if keep_mtime:
            # The unchanged text with its unchanged mtime: older than the
            # objects of the unchanged build that Builder.reset puts back
            os.utime(path, ns=(mtime, mtime))
        else:
            # A new mtime even within the file system's resolution
            now = time.time()
            os.utime(path, (now, now + 1))


def tests_of(fault, platform):
    return fault["tests"].replace("<platform>", platform or DEFAULT_PLATFORM)


def write_report(path, level, platform, commit, rows, total, command,
                 overlays, planned):
    title = {"core": "core (CMake)",
             "openfoam": "OpenFOAM adapter (%s, wmake)" % platform}[level]
    lines = [
        "# Mutation check: %s" % title,
        "",
        "Source commit: %s. Made by: `%s`." % (commit, command),
    ] + (["With the files of " + "; ".join(overlays) + "."]
         if overlays else []) + [
        "",
        "Started %s." % time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime(
            time.time() - total)),
        "Total time %.0f s. Killed %d of %d faults%s%s." % (
            total, sum(1 for r in rows if r["killed"]), len(rows),
            "" if len(rows) == planned else
            " (INCOMPLETE: %d of %d faults run)" % (len(rows), planned),
            "" if all(r["killed"] for r in rows) else
            "; SURVIVORS: " + ", ".join(r["name"] for r in rows
                                        if not r["killed"])),
        "",
        "| fault | file | tests run | killed by | time [s] |",
        "|---|---|---|---|---|",
    ]
    unchanged = [r for r in rows if r["status"] == "unchanged"]
    if unchanged:
        lines[-3:-3] = [
            "%d faults unchanged since their recorded kill (--incremental: "
            "the fault, the files it edits, its tests' sources and what "
            "they include are those of the commit given, "
            "tests/mutation/killed-core.json); %d run." % (
                len(unchanged), len(rows) - len(unchanged)), ""]
    for r in rows:
        killed = ", ".join(r["killed"]) if r["killed"] else (
            "**SURVIVED**" if r["status"] == "ran" else "**" + r["status"] + "**")
        if r["status"] == "unchanged":
            killed += " (at %s)" % r["since"]
        lines.append("| %s | %s | `%s` (%d) | %s | %.0f |" % (
            r["name"], ", ".join(r["files"]),
            r["tests"].replace("|", "\\|"), r["ran"], killed,
            r["time"]))
    lines.append("")
    with open(path, "w") as f:
        f.write("\n".join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--level", choices=["core", "openfoam"])
    parser.add_argument("--faults", default=os.path.join(HERE, "faults.json"))
    parser.add_argument("--report", help="markdown report to write")
    parser.add_argument("--only", help="comma-separated fault names")
    parser.add_argument("--platform", default=DEFAULT_PLATFORM,
                        choices=PLATFORMS,
                        help="default: the default platform of etc/platforms")
    parser.add_argument("--stale-only", action="store_true",
                        help="only check that every fault's text occurs "
                        "exactly once in the current source (no copy, no "
                        "build: a second), e.g. after renaming a file")
    parser.add_argument("--work", help="folder of the copy (default: a new "
                        "temporary folder, removed at the end)")
    parser.add_argument("--keep", action="store_true",
                        help="keep the copy (with --work: reuse its build)")
    parser.add_argument("--baseline", action="store_true",
                        help="first run every selected test on the unchanged "
                        "copy; they must pass")
    parser.add_argument("--overlay", action="append", default=[],
                        help="a branch whose changed files (tests not yet "
                        "merged, e.g. shear) are added to the copy")
    parser.add_argument("--incremental", action="store_true",
                        help="core: run only the faults whose fingerprint "
                        "differs from tests/mutation/killed-core.json")
    parser.add_argument("--record", action="store_true",
                        help="core: write the fingerprints of the faults "
                        "killed in this run to tests/mutation/killed-core.json")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=int, default=900)
    args = parser.parse_args()
    if not args.level and not args.stale_only:
        parser.error("--level is required (but with --stale-only)")

    only = args.only.split(",") if args.only else None
    every = load_faults(args.faults, None, None)
    stale = check_stale(every, REPO)
    if stale:
        fail("the fault list is stale (tests/mutation/faults.json): " +
             "; ".join("%s in %s: %s" % s for s in stale))
    if args.stale_only:
        print("mutation: the fault list is current (%d faults)" % len(every))
        return
    faults = load_faults(args.faults, args.level, only)
    # A fault may name the platforms whose library contains its code (the
    # field-based Lagrangian's condition: OpenFOAM-13 and -14 only)
    if args.level == "openfoam":
        faults = [f for f in faults
                  if args.platform in f.get("platforms", [args.platform])]
    if not faults:
        fail("no fault of level %s selected" % args.level)
    if (args.incremental or args.record) and args.level != "core":
        fail("--incremental and --record are for the core level")

    start = time.time()
    commit = commit_of(REPO)
    killed = read_killed() if args.level == "core" else {}
    prints = {f["name"]: faultInputs.fingerprint(
        REPO, f, tests_of(f, args.platform)) for f in faults} \
        if args.level == "core" else {}
    rows = []
    if args.incremental:
        kept = [f for f in faults
                if killed.get(f["name"], {}).get("fingerprint")
                == prints[f["name"]]]
        for f in kept:
            k = killed[f["name"]]
            rows.append({"name": f["name"],
                         "files": sorted({e["file"] for e in f["edits"]}),
                         "tests": tests_of(f, args.platform), "ran": 0,
                         "killed": k["killedBy"], "status": "unchanged",
                         "since": k["commit"], "time": 0.0})
        faults = [f for f in faults if f not in kept]
        print("mutation: %d faults unchanged since their recorded kill, %d "
              "to run" % (len(kept), len(faults)), flush=True)
        if not faults:
            if args.report:
                write_report(args.report, args.level, args.platform, commit,
                             rows, time.time() - start,
                             "tests/mutation/mutate.py --level core "
                             "--incremental", [], len(rows))
            print("mutation: nothing to run")
            return
    work = args.work or tempfile.mkdtemp(prefix="roughWallMutation.")
    tree = os.path.join(work, "tree")
    log = os.path.join(work, "mutation.log")
    if not (args.keep and os.path.isdir(tree)):
        shutil.rmtree(tree, ignore_errors=True)
        os.makedirs(tree)
    overlays = copy_tree(REPO, tree, args.overlay)
    print("mutation: %s faults of level %s on a copy in %s (log %s)"
          % (len(faults), args.level, tree, log), flush=True)

    builder = Builder(tree, args.level, args.platform, log, args.jobs)
    if not builder.configure():
        fail("cmake of the copy failed (see %s)" % log)
    targets = sorted({t for f in faults for t in f.get("targets", [])})
    if not builder.make(targets):
        fail("build of the unchanged copy failed (see %s)" % log)
    builder.snapshot()

    if args.baseline:
        # One run of the union (ctest's regular expressions allow only a few
        # groups: the union is written as a list of names)
        names = set()
        for regex in {tests_of(f, args.platform) for f in faults}:
            names |= set(test_names(builder.build, regex, builder.env))
        regex = "^(" + "|".join(re.escape(n) for n in sorted(names)) + ")$"
        ran, failed, _ = ctest(builder.build, regex, log, builder.env,
                               args.jobs, args.timeout)
        if failed or ran == 0:
            fail("baseline: %d tests ran, failing without a fault: %s"
                 % (ran, ", ".join(failed)))
        print("baseline: %d tests pass (%.0f s)" % (ran, time.time() - start),
              flush=True)

    command = "tests/mutation/mutate.py --level %s%s%s%s%s%s" % (
        args.level, " --platform " + args.platform
        if args.level == "openfoam" else "",
        " --baseline" if args.baseline else "",
        " --incremental" if args.incremental else "",
        " --only " + args.only if args.only else "",
        "".join(" --overlay " + o for o in args.overlay))
    planned = len(rows) + len(faults)
    for fault in faults:
        t0 = time.time()
        regex = tests_of(fault, args.platform)
        originals = apply(tree, fault["edits"])
        row = {"name": fault["name"],
               "files": sorted({e["file"] for e in fault["edits"]}),
               "tests": regex, "ran": 0, "killed": [], "status": "ran"}
        try:
            if not builder.make(fault.get("targets", [])):
                row["status"] = "build failed"
            else:
                row["build"] = time.time() - t0
                ran, failed, _ = ctest(builder.build, regex, log, builder.env,
                                       args.jobs, args.timeout)
                row["ran"] = ran
                row["killed"] = failed
                if ran == 0:
                    row["status"] = "no test ran"
        finally:
            restore(originals, keep_mtime=builder.reset())
        row["time"] = time.time() - t0
        rows.append(row)
        if args.report:
            # After every fault: an interrupted run keeps what it found
            write_report(args.report, args.level, args.platform, commit,
                         rows, time.time() - start, command, overlays,
                         planned)
        print("%-34s %-12s %4.0f s (build %.0f s)  killed by: %s" % (
            fault["name"], row["status"], row["time"], row.get("build", 0),
            ", ".join(row["killed"]) or "NOTHING"), flush=True)

    total = time.time() - start
    if args.report:
        write_report(args.report, args.level, args.platform, commit, rows,
                     total, command, overlays, planned)
        print("report: " + args.report)
    if args.record:
        for r in rows:
            if r["killed"] and r["status"] == "ran":
                killed[r["name"]] = {"fingerprint": prints[r["name"]],
                                     "commit": commit,
                                     "killedBy": r["killed"]}
        known = {f["name"] for f in load_faults(args.faults, "core", None)}
        write_killed({k: v for k, v in killed.items() if k in known})
        print("recorded: " + KILLED)
    if not args.keep and not args.work:
        shutil.rmtree(work, ignore_errors=True)

    survivors = [r["name"] for r in rows if not r["killed"]]
    if survivors:
        fail("faults not killed by any test: " + ", ".join(survivors))
    print("mutation: all %d faults killed (%.0f s)" % (len(rows), total))


if __name__ == "__main__":
    main()
