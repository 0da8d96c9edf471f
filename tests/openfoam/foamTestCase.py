"""The one harness of the OpenFOAM-level tests of roughWallInteraction, for
both platforms:

  openfoam13    OpenFOAM-13 (Foundation), and openfoam14, OpenFOAM-14, the
                same: `foamRun` with `solver functions;
                subSolver incompressibleFluid;` (frozen carrier) and the
                `clouds` fvModel function object; constant/cloudProperties
                with `type cloud;` (kinematic, no spin), `collidingCloud;`
                (spin) or `MPPICCloud;`; cloud name "cloud".
  openfoam1912  OpenFOAM v1912 (ESI, Debian's package): the solvers
                icoUncoupledKinematicParcelFoam (colliding cloud, spin),
                uncoupledKinematicParcelFoam (kinematic cloud), DPMFoam
                (colliding cloud, carrier solved) and MPPICFoam (MPPIC cloud,
                carrier solved); constant/kinematicCloudProperties; cloud name
                "kinematicCloud".

A case is a shared template folder (tests/openfoam/wallImpact,
tests/stability/openfoam/closedBox) holding the files both platforms read;
FoamCase copies it and writes the few platform-specific files (the cloud
properties' name and type line, the injectors, controlDict's solver entries,
and for openfoam13 system/functions, constant/physicalProperties,
constant/momentumTransport and the kinematic pressure 0/p of the frozen
incompressibleFluid carrier).

Readers, the same on both platforms: Lagrangian fields (U, d,
angularMomentum, active, ...), Cartesian parcel positions (v1912 writes
them; OpenFOAM-13 writes barycentric coordinates only, converted here with
the mesh), the statistics file
postProcessing/lagrangian/<cloud>/patchInteractionModel/<time>/roughWallInteraction.dat
and the per-time-step cloud report of the log.

Tests run as  etc/openfoamEnv <platform> /usr/bin/python3 <script>
--platform <platform> ...: one platform's environment only; main() checks it
(and, on openfoam13, that no OpenFOAM library comes from Debian's /usr/lib).

numpy only.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import glob
import hashlib
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

# ---------------------------------------------------------------------------
# Assertions
# ---------------------------------------------------------------------------


class TestFailure(Exception):
    """A failed assertion of a test."""


_checks = {"passed": 0}


def check(condition, message):
    """Record one assertion: print it, raise TestFailure if it fails."""
    print(("PASS  " if condition else "FAIL  ") + message, flush=True)
    if not condition:
        raise TestFailure(message)
    _checks["passed"] += 1


# ---------------------------------------------------------------------------
# Platforms
# ---------------------------------------------------------------------------

#: The platforms, first the project's first platform
PLATFORMS = ("openfoam13", "openfoam14", "openfoam1912")

#: Cloud kinds: does the parcel carry spin (angularMomentum)?
SPIN = {"colliding": True, "kinematic": False, "DPM": True, "MPPIC": False}


class Platform:
    """What differs between the platforms, in one place."""

    def __init__(self, name):
        if name not in PLATFORMS:
            raise ValueError("unknown platform %r (%s)"
                             % (name, " or ".join(PLATFORMS)))
        self.name = name
        self.foundation = name in ("openfoam13", "openfoam14")
        #: $WM_PROJECT_VERSION of the platform's environment
        self.version = name[len("openfoam"):] if self.foundation else "v1912"
        #: Name of the (only) cloud, its properties file
        self.cloud = "cloud" if self.foundation else "kinematicCloud"
        self.properties = self.cloud + "Properties"
        #: Which cloud report of the log (counted from the end) describes
        #: the cloud written at the end time: OpenFOAM-13's clouds function
        #: object moves the cloud at the start of the next time step, after
        #: the write, so the last step is reported but not written
        self.written_report = -2 if self.foundation else -1

    def __str__(self):
        return self.name

    def kinds(self):
        """The cloud kinds this platform can run."""
        if self.foundation:
            # DPMFoam's equivalent, the incompressibleDenseParticleFluid
            # module, is not part of the project's OpenFOAM-13 build
            return ("colliding", "kinematic", "MPPIC")
        return ("colliding", "kinematic", "DPM", "MPPIC")

    def solver(self, kind):
        """The solver executable for a cloud kind."""
        if kind not in self.kinds():
            raise TestFailure("cloud kind %s is not available on %s"
                              % (kind, self.name))
        if self.foundation:
            return "foamRun"
        return {"colliding": "icoUncoupledKinematicParcelFoam",
                "kinematic": "uncoupledKinematicParcelFoam",
                "DPM": "DPMFoam",
                "MPPIC": "MPPICFoam"}[kind]

    def cloud_type(self, kind):
        """OpenFOAM-13's cloudProperties type of a cloud kind."""
        return {"colliding": "collidingCloud", "kinematic": "cloud",
                "MPPIC": "MPPICCloud"}[kind]

    def dense(self, kind):
        """Is the carrier phase solved (v1912's DPMFoam, MPPICFoam)?"""
        return not self.foundation and kind in ("DPM", "MPPIC")

    def unknown_model_message(self, model="roughWallInteraction"):
        """OpenFOAM's message for a patch interaction model that is not
        loaded (the troubleshooting symptom of a missing libs entry)."""
        if self.foundation:
            return "Unknown patch interaction model type " + model
        return "Unknown patchInteractionModel type " + model


def add_platform_args(parser, kinds=True, default_kind="colliding"):
    """--platform, --work (and --cloud) of every test script."""
    parser.add_argument("--platform", required=True, choices=PLATFORMS)
    parser.add_argument("--work", default=".")
    if kinds:
        parser.add_argument("--cloud", default=default_kind,
                            choices=sorted(SPIN),
                            help="colliding (spin), kinematic, DPM (v1912 "
                                 "DPMFoam), MPPIC (v1912 MPPICFoam, "
                                 "OpenFOAM-13 MPPICCloud)")


# ---------------------------------------------------------------------------
# Environment
# ---------------------------------------------------------------------------

LIBRARY = "libroughWallInteraction.so"

#: OpenFOAM libraries that must never come from Debian's v1912 in /usr/lib
#: when running OpenFOAM-13
_SYSTEM_OPENFOAM = re.compile(
    r"^/usr/lib/(x86_64-linux-gnu/)?(openfoam/)?"
    r"lib(OpenFOAM\w*|finiteVolume|meshTools|lagrangian\w*|Pstream|"
    r"OSspecific|fileFormats|surfMesh|triSurface|momentumTransportModels|"
    r"incompressibleMomentumTransportModels|physicalProperties|"
    r"fvModels|fvConstraints|sampling|tracking|dynamicMesh|"
    r"distributionModels)\.so")


def library_search_path():
    """The directories the dynamic loader searches first
    ($LD_LIBRARY_PATH; OpenFOAM's libs are found through it)."""
    return [d for d in os.environ.get("LD_LIBRARY_PATH", "").split(":") if d]


def find_library(name):
    """The file the loader would open for dlopen(name), or None."""
    for d in library_search_path():
        path = os.path.join(d, name)
        if os.path.isfile(path):
            return path
    return None


def ldd(path):
    """{library name: resolved path or 'not found'} of a binary."""
    out = subprocess.run(["ldd", path], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True).stdout
    deps = {}
    for line in out.splitlines():
        m = re.match(r"\s*(\S+)\s+=>\s+(\S+(?: found)?)", line)
        if m:
            deps[m.group(1)] = m.group(2)
    return deps


def check_foundation_libraries(platform):
    """OpenFOAM-13 or -14 runs: foamRun, the modules it loads, the parcel library
    and libroughWallInteraction.so resolve no OpenFOAM library to Debian's
    v1912 in /usr/lib (a known OpenFOAM library name, or any library of
    /usr/lib whose name is also one of $FOAM_LIBBIN's), and none is
    missing."""
    foam_libs = set()
    for root, _, files in os.walk(os.environ.get("FOAM_LIBBIN", "/none")):
        if os.path.basename(root) != "dummy":   # stand-ins of metis, scotch
            foam_libs.update(f for f in files if f.endswith(".so"))
    foam_run = shutil.which("foamRun")
    check(foam_run is not None, "%s: foamRun is on the PATH" % platform)
    binaries = [foam_run]
    # The solver modules' libraries: lib<module>Solver.so from OpenFOAM-14
    modules = ("libincompressibleFluid.so", "libfunctions.so") \
        if platform.version == "13" \
        else ("libincompressibleFluidSolver.so", "libfunctionsSolver.so")
    for name in (LIBRARY, "liblagrangianParcel.so") + modules \
            + ("libfiniteVolume.so",):
        path = find_library(name)
        check(path is not None and not path.startswith("/usr/lib"),
              "%s: %s found at %s" % (platform, name, path))
        binaries.append(path)
    bad = []
    for binary in binaries:
        for name, path in ldd(binary).items():
            system_copy = path.startswith("/usr/lib/") \
                and os.path.basename(path) in foam_libs
            if _SYSTEM_OPENFOAM.match(path) or system_copy or (
                    path == "not found" and name.startswith("lib")
                    and not name.startswith("libmpi")):
                bad.append("%s: %s => %s" % (os.path.basename(binary), name,
                                             path))
    check(not bad, "%s: no OpenFOAM library from /usr/lib or missing "
          % platform +
          "(ldd of %s)%s" % (", ".join(os.path.basename(b) for b in binaries),
                            ": " + "; ".join(bad) if bad else ""))


def check_environment(platform):
    """The platform's environment (and only it) and the library."""
    version = os.environ.get("WM_PROJECT_VERSION")
    if not os.environ.get("WM_PROJECT_DIR") or version != platform.version:
        raise TestFailure(
            "not in the %s environment (WM_PROJECT_VERSION %r): run the test "
            "as etc/openfoamEnv %s python3 <script> (ctest does)"
            % (platform, version, platform))
    lib = find_library(LIBRARY)
    if lib is None:
        raise TestFailure("%s not found in $LD_LIBRARY_PATH of %s "
                          "($FOAM_USER_LIBBIN = %s): build it first "
                          "(./Allwmake)"
                          % (LIBRARY, platform,
                             os.environ.get("FOAM_USER_LIBBIN")))
    print("using %s: %s (%s)" % (platform, lib, os.environ["WM_PROJECT_DIR"]),
          flush=True)
    if platform.foundation:
        check_foundation_libraries(platform)


def main(test, platform_name=None):
    """Run test(), exit 0 on success, 1 on a failed check or error.

    platform_name: the --platform of the script (read from sys.argv if not
    given).  A test that made no check fails: every test must be able to."""
    start = time.time()
    if platform_name is None:
        argv = sys.argv[1:]
        platform_name = next((argv[i + 1] for i, a in enumerate(argv[:-1])
                              if a == "--platform"), None)
        platform_name = platform_name or next(
            (a.split("=", 1)[1] for a in argv if a.startswith("--platform=")),
            None)
    try:
        if platform_name is None:
            raise TestFailure("no --platform given")
        check_environment(Platform(platform_name))
        before = _checks["passed"]
        test()
        if _checks["passed"] == before:
            raise TestFailure("the test made no check")
    except TestFailure as failure:
        print("TEST FAILED: %s (%.1f s)" % (failure, time.time() - start))
        sys.exit(1)
    print("TEST PASSED: %d checks (%.1f s)" % (_checks["passed"],
                                               time.time() - start))


# ---------------------------------------------------------------------------
# Running commands
# ---------------------------------------------------------------------------

def run(case, args, log, check_rc=True, timeout=900):
    """Run a command in case, output to case/log; return (rc, seconds).
    check_rc: a non-zero exit (or a timeout) is a TestFailure."""
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
        raise TestFailure("%s failed (rc %s), see %s"
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


# ---------------------------------------------------------------------------
# Dictionaries
# ---------------------------------------------------------------------------

def foam_header(cls, obj, location="constant"):
    return """FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    location    "%s";
    object      %s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

""" % (cls, location, obj)


def read_text(path):
    with open(path) as f:
        return f.read()


def write_text(path, text):
    with open(path, "w") as f:
        f.write(text)


def write_vectors(path, obj, points):
    """A vectorField file (manualInjection's positionsFile)."""
    lines = ["%d\n(\n" % len(points)]
    lines += ["(%.9g %.9g %.9g)\n" % tuple(p) for p in points]
    write_text(path, foam_header("vectorField", obj) + "".join(lines) + ")\n")


def dict_entry(path, key):
    """The value of the first 'key value;' of a dictionary file, or None."""
    m = re.search(r"^\s*%s\s+([^;]*);" % re.escape(key), read_text(path),
                  flags=re.M)
    return m.group(1).strip() if m else None


class Injector:
    """A manualInjection: one parcel (nParticle 1) at each of positions
    (n, 3) at t = 0 with velocity U0 and diameter d."""

    def __init__(self, name, positions, U0, d):
        self.name = name
        self.positions = np.asarray(positions, dtype=float).reshape(-1, 3)
        self.U0 = tuple(float(u) for u in U0)
        self.d = float(d)

    def entry(self, platform):
        """The injectionModels entry in the platform's syntax."""
        if platform.foundation:
            basis = "nParticle       1;"
            size = "sizeDistribution\n    {\n        type        fixedValue;" \
                   "\n        value       %r;\n    }" % self.d
        else:
            basis = "massTotal       0;\n    parcelBasisType fixed;\n" \
                    "    nParticle       1;"
            size = "sizeDistribution\n    {\n        type        fixedValue;" \
                   "\n        fixedValueDistribution { value %r; }\n    }" \
                   % self.d
        return """%s
{
    type            manualInjection;
    %s
    SOI             0;
    positionsFile   "positions_%s";
    U0              (%r %r %r);
    %s
}
""" % (self.name, basis, self.name, *self.U0, size)


# ---------------------------------------------------------------------------
# Cases
# ---------------------------------------------------------------------------

#: Files of the shared templates that only v1912's solvers read
_V1912_ONLY = ("0/T", "constant/thermophysicalProperties",
               "constant/transportProperties", "constant/turbulenceProperties")


class FoamCase:
    """A case made from a shared template for one platform and cloud kind.

    template: folder with 0/, constant/ (cloudProperties without type line,
    including "injectors"), system/ (controlDict with an application entry);
    dense_overlay: files for v1912's DPMFoam/MPPICFoam (carrier phase air),
    copied over the template for those; two_d: use system/blockMeshDict.2D.
    """

    def __init__(self, platform, template, path, kind="colliding",
                 two_d=False, dense_overlay=None, with_libs=True):
        self.platform = platform
        self.kind = kind
        self.path = os.path.abspath(path)
        self.spin = SPIN[kind]
        self.solver = platform.solver(kind)
        self.nprocs = 1
        if os.path.exists(self.path):
            shutil.rmtree(self.path)
        shutil.copytree(template, self.path)
        blockMesh2D = self.file("system/blockMeshDict.2D")
        if two_d:
            shutil.move(blockMesh2D, self.file("system/blockMeshDict"))
        elif os.path.exists(blockMesh2D):
            os.remove(blockMesh2D)
        if platform.dense(kind):
            for root, _, files in os.walk(dense_overlay):
                for name in files:
                    src = os.path.join(root, name)
                    shutil.copyfile(src, self.file(os.path.relpath(
                        src, dense_overlay)))
            for name in ("0/U", "0/T"):
                if os.path.exists(self.file(name)):
                    os.remove(self.file(name))
        if platform.foundation:
            self._openfoam13_files()
        else:
            os.rename(self.file("constant/cloudProperties"),
                      self.file("constant/" + platform.properties))
            self.set_control(application=self.solver)
        if not with_libs:
            text = re.sub(r'^libs\s.*\n', "", read_text(self.file(
                "system/controlDict")), flags=re.M)
            write_text(self.file("system/controlDict"), text)

    def _openfoam13_files(self):
        """The frozen incompressibleFluid carrier with the clouds fvModel."""
        transport = self.file("constant/transportProperties")
        nu = dict_entry(transport, "nu")
        rho = dict_entry(transport, "rhoInf")
        for name in _V1912_ONLY:
            if os.path.exists(self.file(name)):
                os.remove(self.file(name))
        properties = self.file("constant/cloudProperties")
        text = read_text(properties)
        body = text.index("}", text.index("FoamFile")) + 1
        write_text(properties, text[:body] + "\n\ntype            %s;\n"
                   % self.platform.cloud_type(self.kind) + text[body:])
        write_text(self.file("constant/physicalProperties"),
                   foam_header("dictionary", "physicalProperties")
                   + "viscosityModel  constant;\n\nnu              %s;\n\n"
                     "rho             %s;\n" % (nu, rho))
        write_text(self.file("constant/momentumTransport"),
                   foam_header("dictionary", "momentumTransport")
                   + "simulationType  laminar;\n")
        write_text(self.file("0/p"), foam_header("volScalarField", "p", "0")
                   + """dimensions      [0 2 -2 0 0 0 0];

internalField   uniform 0;

boundaryField
{
    #includeEtc "caseDicts/setConstraintTypes"

    ".*"
    {
        type            zeroGradient;
    }
}
""")
        solution = self.file("system/fvSolution")
        write_text(solution, read_text(solution).rstrip()
                   + "\n\nPIMPLE\n{\n    pRefCell        0;\n"
                     "    pRefValue       0;\n}\n")
        write_text(self.file("system/functions"),
                   foam_header("dictionary", "functions", "system")
                   + "clouds\n{\n    type            fvModel;\n"
                     "    #includeModel clouds(name=fvModel)\n}\n")
        control = self.file("system/controlDict")
        text, n = re.subn(r"^application\s+\w+;",
                          "solver          functions;\n\n"
                          "subSolver       incompressibleFluid;\n\n"
                          "// The carrier fields are read at this time "
                          "(restarts: later times hold none)\n"
                          "subSolverTime   0;",
                          read_text(control), flags=re.M)
        if n != 1:
            raise RuntimeError("controlDict has no application entry")
        write_text(control, text)

    # -- files --------------------------------------------------------------

    def file(self, relpath):
        return os.path.join(self.path, relpath)

    def cloud_properties(self):
        """Path of the cloud properties file of the platform."""
        return self.file("constant/" + self.platform.properties)

    def set_entry(self, relpath, key, value):
        """Replace 'key  value;' (first occurrence) in a dictionary file."""
        path = self.file(relpath)
        text, n = re.subn(r"^(\s*)%s\s+[^;]*;" % re.escape(key),
                          lambda m: "%s%s %s;" % (m.group(1), key, value),
                          read_text(path), count=1, flags=re.M)
        if n != 1:
            raise RuntimeError("%s has no entry %s" % (relpath, key))
        write_text(path, text)

    def set_control(self, **entries):
        """Change entries of system/controlDict."""
        for key, value in entries.items():
            self.set_entry("system/controlDict", key, value)

    def write_settings(self, settings):
        """The patch interaction settings (constant/roughWallSettings,
        included by the cloud properties)."""
        write_text(self.file("constant/roughWallSettings"),
                   foam_header("dictionary", "roughWallSettings") + settings)

    def write_injectors(self, injectors):
        """constant/injectors (included by the cloud properties) and the
        positions files.  Returns the number of parcels."""
        for inj in injectors:
            write_vectors(self.file("constant/positions_" + inj.name),
                          "positions_" + inj.name, inj.positions)
        write_text(self.file("constant/injectors"),
                   "// Written by foamTestCase.py for %s\n\n" % self.platform
                   + "\n".join(inj.entry(self.platform) for inj in injectors))
        return sum(len(inj.positions) for inj in injectors)

    def set_integration(self, scheme):
        """The integration scheme of the parcel velocity."""
        path = self.cloud_properties()
        text, n = re.subn(r"(integrationSchemes\s*\{\s*U\s+)\w+;",
                          r"\g<1>%s;" % scheme, read_text(path))
        if n != 1:
            raise RuntimeError("no integrationSchemes U entry in " + path)
        write_text(path, text)

    def set_subdomains(self, nprocs):
        """Split the case into nprocs slabs along x (simple)."""
        self.set_entry("system/decomposeParDict", "numberOfSubdomains",
                       str(nprocs))
        self.set_entry("system/decomposeParDict", "n", "(%d 1 1)" % nprocs)

    # -- running ------------------------------------------------------------

    def run(self, args, log, check_rc=True, timeout=900):
        return run(self.path, args, log, check_rc, timeout)

    def mesh(self, nprocs=1):
        """blockMesh, and decomposePar into nprocs x-slabs if nprocs > 1."""
        self.run(["blockMesh"], "log.blockMesh")
        self.nprocs = nprocs
        if nprocs > 1:
            self.set_subdomains(nprocs)
            self.run(["decomposePar"], "log.decomposePar")

    def solve(self, log="log.solver", check_rc=True, timeout=900):
        """Run the platform's solver (parallel after mesh(n > 1)).
        Returns (rc, wall-clock seconds)."""
        args = [self.solver]
        if self.nprocs > 1:
            args = mpirun(self.nprocs, args + ["-parallel"])
        return self.run(args, log, check_rc, timeout)

    def log(self, log="log.solver"):
        return read_text(self.file(log))

    # -- output -------------------------------------------------------------

    def cloud_dirs(self, time_name):
        return cloud_dirs(self.path, time_name, self.platform.cloud)

    def read_cloud(self, time_name, fields):
        return read_cloud(self.path, time_name, fields, self.platform.cloud)

    def cloud_parts(self, time_name, fields=("U", "d", "angularMomentum")):
        return cloud_parts(self.path, time_name, fields, self.platform.cloud)

    def read_statistics(self):
        return read_statistics(self.path, self.platform.cloud)

    def statistics_file(self, time_name):
        return statistics_path(self.path, self.platform.cloud, time_name)

    def read_steps(self, log="log.solver"):
        return read_steps(self.file(log))


# ---------------------------------------------------------------------------
# Readers
# ---------------------------------------------------------------------------

NUMBER = r"[-+]?(?:[0-9.]+(?:[eE][-+]?[0-9]+)?|nan|inf)"


def _body(text):
    """The text after the FoamFile header, comments removed."""
    start = text.index("}", text.index("FoamFile")) + 1 \
        if "FoamFile" in text else 0
    body = text[start:]
    body = re.sub(r"/\*.*?\*/", "", body, flags=re.S)
    return re.sub(r"//.*", "", body)


def read_field(path):
    """An ASCII field or list file: (n,) scalars/labels or (n, k) tuples.
    Uniform lists n{value} too."""
    body = _body(read_text(path))
    m = re.search(r"(\d+)\s*\{\s*(\([^)]*\)|" + NUMBER + r")\s*\}", body)
    m_list = re.search(r"(\d+)\s*\(", body)
    if m and (not m_list or m.start() <= m_list.start()):
        n = int(m.group(1))
        value = m.group(2)
        if value.startswith("("):
            v = np.array([float(t) for t in value.strip("()").split()])
            return np.tile(v, (n, 1))
        return np.full(n, float(value))
    if not m_list:
        raise ValueError("no list in " + path)
    n = int(m_list.group(1))
    inner = body[m_list.end():body.rindex(")")]
    if n == 0:
        return np.zeros(0)
    if "(" in inner:
        values = np.array([float(t) for t in
                           inner.replace("(", " ").replace(")", " ").split()])
        return values.reshape(n, -1)
    return np.array([float(t) for t in inner.split()])


def processor_roots(case):
    """The case, or its processor* folders when decomposed."""
    procs = sorted(glob.glob(os.path.join(case, "processor[0-9]*")),
                   key=lambda p: int(re.sub(r"\D", "", os.path.basename(p))))
    return procs if procs else [case]


def cloud_dirs(case, time_name, cloud):
    """The cloud's Lagrangian folders: the case's or each processor's."""
    return [os.path.join(r, time_name, "lagrangian", cloud)
            for r in processor_roots(case)]


def read_cloud(case, time_name, fields, cloud):
    """Fields of all parcels (processors concatenated; missing: empty)."""
    data = {name: [] for name in fields}
    for d in cloud_dirs(case, time_name, cloud):
        if not os.path.isdir(d):
            continue
        for name in fields:
            path = os.path.join(d, name)
            if os.path.exists(path):
                data[name].append(read_field(path))
    result = {}
    for name, parts in data.items():
        parts = [p for p in parts if p.size]
        result[name] = np.concatenate(parts) if parts else np.zeros(0)
    return result


class MeshGeometry:
    """Points, faces, owners and cell centres of a polyMesh (ASCII), enough
    to turn barycentric parcel coordinates into positions."""

    def __init__(self, poly_mesh):
        self.points = read_field(os.path.join(poly_mesh, "points"))
        body = _body(read_text(os.path.join(poly_mesh, "faces")))
        self.faces = [[int(i) for i in f.split()]
                      for f in re.findall(r"\d+\(([\d\s]+)\)", body)]
        self.owner = read_field(os.path.join(poly_mesh, "owner")).astype(int)
        neighbour = read_field(os.path.join(poly_mesh, "neighbour"))
        self.neighbour = neighbour.astype(int)
        self.n_cells = int(self.owner.max()) + 1 if len(self.owner) else 0
        self.cell_centres = self._cell_centres()

    def _cell_centres(self):
        """OpenFOAM's face and cell centres (primitiveMesh)."""
        nf = len(self.faces)
        fc = np.zeros((nf, 3))
        fa = np.zeros((nf, 3))
        for i, f in enumerate(self.faces):
            p = self.points[f]
            if len(f) == 3:
                fc[i] = p.mean(axis=0)
                fa[i] = 0.5*np.cross(p[1] - p[0], p[2] - p[0])
                continue
            est = p.mean(axis=0)
            q = np.roll(p, -1, axis=0)
            c = p + q + est
            n = np.cross(q - p, est - p)
            a = np.linalg.norm(n, axis=1)
            fc[i] = (a[:, None]*c).sum(axis=0)/(3*a.sum())
            fa[i] = 0.5*n.sum(axis=0)
        nc = self.n_cells
        nn = len(self.neighbour)
        count = np.zeros(nc)
        est = np.zeros((nc, 3))
        np.add.at(est, self.owner, fc)
        np.add.at(count, self.owner, 1)
        np.add.at(est, self.neighbour, fc[:nn])
        np.add.at(count, self.neighbour, 1)
        est /= count[:, None]
        vol = np.zeros(nc)
        ctr = np.zeros((nc, 3))
        v = np.einsum("ij,ij->i", fa, fc - est[self.owner])
        np.add.at(vol, self.owner, v)
        np.add.at(ctr, self.owner,
                  v[:, None]*(0.75*fc + 0.25*est[self.owner]))
        own = self.neighbour
        v = np.einsum("ij,ij->i", fa[:nn], est[own] - fc[:nn])
        np.add.at(vol, own, v)
        np.add.at(ctr, own, v[:, None]*(0.75*fc[:nn] + 0.25*est[own]))
        return ctr/vol[:, None]

    def positions(self, coords, cells, faces, tet_pts):
        """Cartesian positions of barycentric (a b c d) in the tets
        (cell, face, tetPt): OpenFOAM's tetIndices::faceTriIs with the tet
        base point 0 of every face (the first valid one for the convex
        faces of these meshes)."""
        xyz = np.empty((len(cells), 3))
        for k, (y, c, f, t) in enumerate(zip(coords, cells, faces, tet_pts)):
            face = self.faces[f]
            i = t % len(face)
            j = (i + 1) % len(face)
            if self.owner[f] != c:
                i, j = j, i
            xyz[k] = y[0]*self.cell_centres[c] + y[1]*self.points[face[0]] \
                + y[2]*self.points[face[i]] + y[3]*self.points[face[j]]
        return xyz


def significant_digits(numbers):
    """The most significant digits among numbers written as text (a file's
    writePrecision, where one of its numbers uses them all)"""
    most = 1
    for group in numbers:
        for text in group:
            mantissa = re.split(r"[eE]", text.lstrip("+-"))[0]
            digits = mantissa.replace(".", "").lstrip("0")
            most = max(most, len(digits))
    return most


def read_positions(root, cloud_dir):
    """Cartesian positions (n, 3) and cells (n,) of the parcels in
    cloud_dir (of the case or processor folder root): v1912's 'positions'
    holds '(x y z) cell'; OpenFOAM-13's holds the barycentric
    '(a b c d) cell tetFace tetPt', converted with root's mesh."""
    body = _body(read_text(os.path.join(cloud_dir, "positions")))
    number = "(" + NUMBER + ")"
    rows = re.findall(r"\(\s*" + r"\s+".join([number]*3) + r"\s*\)\s*(-?\d+)",
                      body)
    if rows:
        xyz = np.array([[float(r[0]), float(r[1]), float(r[2])] for r in rows])
        return xyz.reshape(-1, 3), np.array([int(r[3]) for r in rows])
    rows = re.findall(r"\(\s*" + r"\s+".join([number]*4)
                      + r"\s*\)\s*(-?\d+)\s+(-?\d+)\s+(-?\d+)", body)
    if not rows:
        return np.zeros((0, 3)), np.zeros(0, dtype=int)
    coords = np.array([[float(x) for x in r[:4]] for r in rows])
    cells = np.array([int(r[4]) for r in rows])
    faces = np.array([int(r[5]) for r in rows])
    tets = np.array([int(r[6]) for r in rows])
    # the coordinates as written: round-off of the file's writePrecision
    tol = max(1e-9, 4*10.0**(1 - significant_digits(r[:4] for r in rows)))
    check(bool(np.all(np.abs(coords.sum(axis=1) - 1) < tol)
               and np.all(coords > -tol)),
          "%s: barycentric coordinates of every parcel in [0, 1] summing to 1"
          % os.path.relpath(cloud_dir, os.path.dirname(root)))
    mesh = MeshGeometry(os.path.join(root, "constant", "polyMesh"))
    return mesh.positions(coords, cells, faces, tets), cells


def cloud_parts(case, time_name, fields, cloud):
    """Positions, cells and fields of every parcel at time_name, one dict
    per processor (or one for a serial case)."""
    result = []
    for root in processor_roots(case):
        d = os.path.join(root, time_name, "lagrangian", cloud)
        part = {"dir": d}
        if not os.path.isdir(d):
            part["positions"] = np.zeros((0, 3))
            part["cells"] = np.zeros(0, dtype=int)
            for name in fields:
                part[name] = np.zeros(0)
            result.append(part)
            continue
        part["positions"], part["cells"] = read_positions(root, d)
        for name in fields:
            path = os.path.join(d, name)
            part[name] = read_field(path) if os.path.exists(path) \
                else np.zeros(0)
        result.append(part)
    return result


def statistics_path(case, cloud, time_name="*"):
    return os.path.join(case, "postProcessing", "lagrangian", cloud,
                        "patchInteractionModel", time_name,
                        "roughWallInteraction.dat")


def read_statistics(case, cloud):
    """Rows of the statistics file(s), oldest start time first.
    Returns (column names, list of rows as dicts)."""
    pattern = statistics_path(case, cloud)
    files = sorted(glob.glob(pattern),
                   key=lambda p: float(os.path.basename(os.path.dirname(p))))
    if not files:
        elsewhere = glob.glob(os.path.join(case, "postProcessing", "**",
                                           "roughWallInteraction*"),
                              recursive=True)
        raise TestFailure("no statistics file %s%s" % (
            pattern, " (found %s)" % elsewhere if elsewhere else ""))
    names = None
    rows = []
    for path in files:
        with open(path) as f:
            for line in f:
                if line.startswith("# Time"):
                    names = line[1:].split()
                elif line.strip() and not line.startswith("#"):
                    rows.append(dict(zip(names, map(float, line.split()))))
    return names, rows


def column(row, name):
    """A column of a statistics row; a missing column is a failure."""
    if name not in row:
        raise TestFailure("statistics file has no column %s (columns: %s)"
                          % (name, " ".join(row)))
    return row[name]


def read_steps(log_path):
    """The cloud report of every time step of a solver log, as dicts: time,
    parcels, mass, linearKE, rotationalKE, executionTime, escape, stick
    (numbers, summed over the 'Parcel fate' lines), hits, fallbacks
    (summed over the rough patches), facetPerHit, energyLoss (per rough
    patch), warnings."""
    text = read_text(log_path)
    steps = []
    for block in re.split(r"\nTime = ", text)[1:]:
        step = {"time": float(re.match(NUMBER, block).group(0))}

        def grab(pattern, cast=float):
            m = re.search(pattern, block)
            return cast(m.group(1)) if m else None

        value = "(" + NUMBER + ")"
        step["parcels"] = grab(r"Current number of parcels\s*=\s*(\d+)", int)
        step["mass"] = grab(r"Current mass in system\s*=\s*" + value)
        step["linearKE"] = grab(r"Linear kinetic energy\s*=\s*" + value)
        step["rotationalKE"] = grab(r"Rotational kinetic energy\s*=\s*"
                                    + value)
        step["executionTime"] = grab(r"ExecutionTime = " + value)
        step["escape"] = sum(int(n) for n in re.findall(
            r"- escape\s*=\s*(\d+),", block))
        step["stick"] = sum(int(n) for n in re.findall(
            r"- stick\s*=\s*(\d+),", block))
        step["hits"] = sum(int(n) for n in re.findall(
            r"- hits\s*=\s*(\d+)", block))
        step["fallbacks"] = sum(int(n) for n in re.findall(
            r"- hits at the re-collision bound\s*=\s*(\d+)", block))
        step["facetPerHit"] = [float(x) for x in re.findall(
            r"- facet collisions per hit\s*=\s*" + value, block)]
        step["energyLoss"] = [float(x) for x in re.findall(
            r"- kinetic energy loss \[J\]\s*=\s*" + value, block)]
        step["warnings"] = block.count("FOAM Warning")
        steps.append(step)
    return [s for s in steps if s["parcels"] is not None]


def system_escapes(log):
    """v1912's 'Parcel fate: system' escape count at the last time step
    (-1 if there is none: OpenFOAM-13 has no such count)."""
    counts = re.findall(r"Parcel fate: system \(number, mass\)\s*\n"
                        r"\s*- escape\s*=\s*(\d+)", log)
    return int(counts[-1]) if counts else -1


def parcel_counts(log):
    """The parcel counts of the cloud reports of a log."""
    return [int(n) for n in
            re.findall(r"Current number of parcels\s*=\s*(\d+)", log)]


def final_parcels(log):
    """The parcel count of the last cloud report of a log (-1: none)."""
    counts = parcel_counts(log)
    return counts[-1] if counts else -1


# ---------------------------------------------------------------------------
# Statistics against the oracle
# ---------------------------------------------------------------------------

#: Agreement required between a measured statistic and the reference, in
#: combined standard errors
TOLERANCE_SE = 4


def sd_and_se(x):
    """Mean, its standard error, sd and its standard error (delta method)."""
    n = len(x)
    mean = float(np.mean(x))
    d = x - mean
    m2 = float(np.mean(d**2))
    m4 = float(np.mean(d**4))
    sd = math.sqrt(m2*n/(n - 1))
    return mean, sd/math.sqrt(n), sd, \
        math.sqrt(max(m4 - m2*m2, 0)/n)/(2*math.sqrt(m2))


#: The oracle: tests/oracle/roughWallOracle.py, an independent numpy Monte
#: Carlo of the collision operator (its own sampler, no C++ core)
ORACLE_DIR = os.path.join(REPO, "tests", "oracle")


def reference(spin, delta_deg, alphas, samples=1000000, seed=1, e=0.8,
              mu0=0.4, muD=0.4, lateral_tilt=False):
    """Reference rebound statistics {alpha: row} (mean_kn, se_mean_kn,
    sd_kn, se_sd_kn, the same for kt) of one hit at alpha [deg] on a flat
    rough wall: roughWallOracle.restitution_statistics, samples per angle,
    numpy's PCG64 seeded with seed; spin: spin produced by a facet collision
    carried into the next (a cloud with spin).

    Results are deterministic; with $ROUGHWALL_ORACLE_CACHE (set by ctest)
    each angle's row is kept there, keyed by the arguments and the oracle's
    source, and reused by the other tests and platforms."""
    if ORACLE_DIR not in sys.path:
        sys.path.insert(0, ORACLE_DIR)
    import roughWallOracle
    cache = os.environ.get("ROUGHWALL_ORACLE_CACHE")
    source = hashlib.sha1(read_text(roughWallOracle.__file__).encode())
    rows = {}
    for alpha in alphas:
        args = dict(alpha_deg=float(alpha), Delta_deg=float(delta_deg),
                    e=e, mu0=mu0, muD=muD, samples=int(samples), seed=seed,
                    spin=bool(spin), lateral=bool(lateral_tilt),
                    oracle=source.hexdigest())
        key = hashlib.sha1(json.dumps(args, sort_keys=True).encode())
        path = os.path.join(cache, key.hexdigest() + ".json") if cache \
            else None
        if path and os.path.exists(path):
            rows[alpha] = json.loads(read_text(path))["row"]
            how = "cached"
        else:
            start = time.time()
            rows[alpha] = roughWallOracle.restitution_statistics(
                [alpha], delta_deg, e=e, mu0=mu0, muD=muD, samples=samples,
                rng=np.random.default_rng(seed), spin=bool(spin),
                lateral=bool(lateral_tilt))[0]
            how = "%.1f s" % (time.time() - start)
            if path:
                os.makedirs(cache, exist_ok=True)
                tmp = "%s.%d" % (path, os.getpid())
                write_text(tmp, json.dumps({"args": args,
                                            "row": rows[alpha]}))
                os.replace(tmp, path)
        print("oracle: alpha = %.4g deg, Delta = %g deg, %s%s, %d samples "
              "(%s)" % (alpha, delta_deg, "spin" if spin else "no spin",
                        ", lateral tilt" if lateral_tilt else "", samples,
                        how), flush=True)
    return rows


# ---------------------------------------------------------------------------
# The wall-impact case (tests/openfoam/wallImpact)
# ---------------------------------------------------------------------------

WALL_IMPACT = os.path.join(HERE, "wallImpact")

#: Files that v1912's DPMFoam and MPPICFoam need instead (carrier phase air)
WALL_IMPACT_DENSE = os.path.join(HERE, "wallImpactDPM")

#: Incidence angle [deg] -> parcel diameter [m] of its injector
ANGLES = {10: 100e-6, 30: 110e-6, 60: 120e-6}

DEFAULT_SETTINGS = """patchInteractionModel roughWallInteraction;

roughWallInteractionCoeffs
{
    patches
    (
        "(lowerWall|upperWall)"
        {
            type            rough;
            e               0.8;
            mu0             0.4;
            muD             0.4;
            roughnessAngle  8;
        }
        outlet { type escape; }
    );
}
"""


def wall_impact_case(platform, path, kind="colliding", two_d=False,
                     parcels=10000, seed=1, settings=None, with_libs=True):
    """The wall-impact case: parcels per incidence angle injected at
    y = 5 mm over x in [-0.04, 0], z in [-0.015, 0.015] (z = 0 in 2-D)."""
    case = FoamCase(platform, WALL_IMPACT, path, kind, two_d=two_d,
                    dense_overlay=WALL_IMPACT_DENSE, with_libs=with_libs)
    rng = np.random.default_rng(seed)
    injectors = []
    for angle, d in ANGLES.items():
        x = rng.uniform(-0.04, 0.0, parcels)
        z = np.zeros(parcels) if two_d \
            else rng.uniform(-0.015, 0.015, parcels)
        a = math.radians(angle)
        y = np.full(parcels, 0.005)
        injectors.append(Injector("alpha%d" % angle,
                                  np.column_stack([x, y, z]),
                                  (math.cos(a), -math.sin(a), 0.0), d))
    case.write_injectors(injectors)
    case.write_settings(settings if settings is not None else DEFAULT_SETTINGS)
    return case


def set_wall_velocity(case, wall_velocity):
    """Move lowerWall at (wall_velocity, 0, 0) (fixedValue carrier velocity
    on the wall: OpenFOAM's patchData takes the wall velocity from it)."""
    for name in ("0/U", "0/U.air"):
        path = case.file(name)
        if not os.path.exists(path):
            continue
        moving = """boundaryField
{
    lowerWall
    {
        type            fixedValue;
        value           uniform (%r 0 0);
    }""" % wall_velocity
        write_text(path, read_text(path).replace("boundaryField\n{", moving,
                                                 1))


def incident_velocity(angle, wall_velocity=0.0):
    """Incident velocity of the parcels of an injection angle [deg]
    relative to the wall moving at (wall_velocity, 0, 0)."""
    a = math.radians(angle)
    return np.array([math.cos(a) - wall_velocity, -math.sin(a), 0.0])


def relative_angle(angle, wall_velocity=0.0):
    """Incidence angle [deg] relative to the wall moving along x."""
    if wall_velocity == 0:
        return angle
    v = incident_velocity(angle, wall_velocity)
    return math.degrees(math.atan2(-v[1], v[0]))


def check_rebound_statistics(U, d, parcels_per_angle, reference_of_angle,
                             label="", wall_velocity=0.0):
    """Compare mean and sd of k_n and k_t per angle with the reference.

    U: rebound velocities (incident speed 1, wall y = 0 moving at
    (wall_velocity, 0, 0), incidence in the x-y plane);
    reference_of_angle(relative angle, d) -> (reference row, Delta [deg]).
    k_n = -v''.n/v'.n and k_t = v''_x/v'_x relative to the wall.
    Returns the k_n and k_t samples of all angles."""
    kn_all = []
    kt_all = []
    for angle in sorted(ANGLES):
        d_angle = ANGLES[angle]
        group = np.abs(d - d_angle) < 1e-9
        check(np.count_nonzero(group) == parcels_per_angle,
              "%salpha = %d deg: %d parcels" % (label, angle,
                                                parcels_per_angle))
        v0 = incident_velocity(angle, wall_velocity)
        kn = U[group, 1] / -v0[1]
        kt = (U[group, 0] - wall_velocity) / v0[0]
        kn_all.append(kn)
        kt_all.append(kt)
        ref, delta = reference_of_angle(relative_angle(angle, wall_velocity),
                                        d_angle)
        for name, x in (("kn", kn), ("kt", kt)):
            mean, se_mean, sd, se_sd = sd_and_se(x)
            for what, value, se, ref_value, ref_se in (
                ("mean", mean, se_mean, ref["mean_" + name],
                 ref["se_mean_" + name]),
                ("sd", sd, se_sd, ref["sd_" + name], ref["se_sd_" + name]),
            ):
                z = (value - ref_value) / math.hypot(se, ref_se)
                check(abs(z) <= TOLERANCE_SE,
                      "%salpha = %.4g deg, Delta = %g deg: %s %s = %.5f, "
                      "reference %.5f, |z| = %.2f <= %d"
                      % (label, relative_angle(angle, wall_velocity), delta,
                         what, name, value, ref_value, abs(z), TOLERANCE_SE))
    return np.concatenate(kn_all), np.concatenate(kt_all)


# ---------------------------------------------------------------------------
# The closed box of the stability cases (tests/stability/openfoam/closedBox)
# ---------------------------------------------------------------------------

CLOSED_BOX = os.path.join(REPO, "tests", "stability", "openfoam", "closedBox")

#: The box [m]
BOX = (np.zeros(3), np.full(3, 0.1))

#: Density of the parcels of the closed box (its cloud properties' rho0)
RHO_PARTICLE = 2500


def closed_box_case(platform, path, groups, kind="colliding", seed=1):
    """The closed box with injectors, one per group: dict(name, n, d [m],
    U0, box ((x0 y0 z0), (x1 y1 z1)) where positions are drawn uniformly).
    Returns the case, the number of parcels and their total mass [kg]."""
    case = FoamCase(platform, CLOSED_BOX, path, kind)
    rng = np.random.default_rng(seed)
    injectors = []
    mass = 0.0
    for g in groups:
        lo, hi = np.array(g["box"][0]), np.array(g["box"][1])
        injectors.append(Injector(g["name"],
                                  lo + (hi - lo)*rng.random((g["n"], 3)),
                                  g["U0"], g["d"]))
        mass += g["n"]*RHO_PARTICLE*math.pi/6*g["d"]**3
    return case, case.write_injectors(injectors), mass


#: OpenFOAM's own smooth-wall model with the same e and mu: the reference cost
SMOOTH_SETTINGS = """patchInteractionModel standardWallInteraction;

standardWallInteractionCoeffs
{
    type            rebound;
    e               0.8;
    mu              0.4;
}
"""


def check_conservation(steps, parcels, mass, label):
    """Parcel count and mass equal the injected ones at every time step,
    nothing escaped or stuck, the energy lost at the walls never negative."""
    check(len(steps) > 0, "%s: the log holds %d time steps"
          % (label, len(steps)))
    counts = sorted(set(s["parcels"] for s in steps))
    check(counts == [parcels], "%s: parcel count %s at every one of %d "
          "steps (injected %d)" % (label, counts, len(steps), parcels))
    worst = max(abs(s["mass"] - mass)/mass for s in steps)
    check(worst < 1e-9, "%s: mass in system equals the injected %.6e kg at "
          "every step (largest relative deviation %.1e)"
          % (label, mass, worst))
    check(all(s["escape"] == 0 and s["stick"] == 0 for s in steps),
          "%s: no parcel escaped or stuck" % label)
    losses = [x for s in steps for x in s["energyLoss"]]
    check(all(x >= 0 and math.isfinite(x) for x in losses),
          "%s: kinetic energy lost at the rough walls is finite and >= 0 "
          "(final %s J)" % (label, steps[-1]["energyLoss"]))


def check_inside_box(parts, parcels, lo, hi, label):
    """Every parcel inside the box, in a valid cell, finite velocity/spin.
    Returns the positions and velocities of all parcels."""
    total = sum(len(p["cells"]) for p in parts)
    check(total == parcels, "%s: %d parcels in the written cloud (expected "
          "%d)" % (label, total, parcels))
    xyz = np.concatenate([p["positions"] for p in parts])
    cells = np.concatenate([p["cells"] for p in parts])
    tol = 1e-9
    inside = np.all((xyz >= lo - tol) & (xyz <= hi + tol), axis=1)
    check(bool(np.all(inside)) and bool(np.all(cells >= 0)),
          "%s: every parcel inside the box and in a cell (%d outside)"
          % (label, int(np.count_nonzero(~inside))))
    U = np.concatenate([p["U"] for p in parts if len(p["U"])])
    check(bool(np.all(np.isfinite(U))), "%s: every velocity finite" % label)
    spins = [p["angularMomentum"] for p in parts
             if len(p.get("angularMomentum", []))]
    if spins:
        check(bool(np.all(np.isfinite(np.concatenate(spins)))),
              "%s: every angular momentum finite" % label)
    return xyz, U
