"""Running OpenFOAM commands in a case: output to a log file in the case,
timed; mpirun command lines for a shared machine.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import hashlib
import os
import shutil
import subprocess
import time

from .errors import CommandFailed

def run(case, args, log, check_rc=True, timeout=900):
    """Run a command in case, output to case/log; return (rc, seconds).
    check_rc: a non-zero exit (or a timeout) is a CommandFailed."""
    start = time.time()
    with open(os.path.join(case, log), "w") as f:
        env = dict(os.environ, PWD=os.path.abspath(case))
        try:
            rc = subprocess.call(args, cwd=case, stdout=f,
                                 stderr=subprocess.STDOUT, env=env,
                                 timeout=timeout)
        except subprocess.TimeoutExpired:
            rc = "timeout after %d s (stalled?)" % timeout
    elapsed = time.time() - start
    print("ran   %s (%s): rc %s, %.1f s" % (" ".join(args), log, rc, elapsed),
          flush=True)
    if check_rc and rc != 0:
        with open(os.path.join(case, log)) as f:
            print("".join(f.readlines()[-40:]))
        raise CommandFailed("%s failed (rc %s), see %s"
                          % (args[0], rc, os.path.join(case, log)))
    return rc, elapsed


def block_mesh(case, log="log.blockMesh"):
    """blockMesh in case.  Under ctest ($ROUGHWALL_TEST_CACHE) the mesh is
    made once per blockMeshDict and OpenFOAM installation and copied from
    there afterwards (the tests make the same few meshes a few hundred
    times); the log then says where it was copied from."""
    cache = os.environ.get("ROUGHWALL_TEST_CACHE")
    if not cache:
        return run(case, ["blockMesh"], log)
    with open(os.path.join(case, "system", "blockMeshDict"), "rb") as f:
        key = hashlib.sha1(f.read() + os.environ.get(
            "WM_PROJECT_DIR", "").encode()).hexdigest()
    saved = os.path.join(cache, "blockMesh", key)
    mesh = os.path.join(case, "constant", "polyMesh")
    if not os.path.isdir(saved):
        result = run(case, ["blockMesh"], log)
        shutil.copytree(mesh, "%s.%d" % (saved, os.getpid()))
        try:
            os.rename("%s.%d" % (saved, os.getpid()), saved)
        except OSError:     # made at the same time by another test
            shutil.rmtree("%s.%d" % (saved, os.getpid()))
        return result
    start = time.time()
    if os.path.exists(mesh):
        shutil.rmtree(mesh)
    shutil.copytree(saved, mesh)
    with open(os.path.join(case, log), "w") as f:
        f.write("blockMesh: constant/polyMesh copied from %s, made by "
                "blockMesh from the same blockMeshDict\n" % saved)
    print("ran   blockMesh (%s): copied from the test cache" % log,
          flush=True)
    return 0, time.time() - start


def mpirun(nprocs, args):
    """mpirun command line: --allow-run-as-root as root (CI runs as root),
    --oversubscribe with more processes than cores, processes yield when
    idle (the machine is shared with other tests)."""
    cmd = ["mpirun"]
    if os.geteuid() == 0:
        cmd.append("--allow-run-as-root")
    if nprocs > (os.cpu_count() or 1):
        cmd.append("--oversubscribe")
    return cmd + ["--mca", "mpi_yield_when_idle", "1", "-np", str(nprocs)] \
        + args
