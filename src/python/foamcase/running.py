"""Running OpenFOAM commands in a case: output to a log file in the case,
timed; mpirun command lines for a shared machine.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import os
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
