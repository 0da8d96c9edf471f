"""The platforms: what differs between OpenFOAM-13/-14 (openfoam.org) and
v1912 (ESI), in one place, and where the dynamic loader finds a library.

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

SPDX-License-Identifier: GPL-3.0-or-later
"""

import hashlib
import os
import re
import subprocess

from .dictionaries import write_text_atomic
from .errors import FoamError

#: etc/platforms of the checkout holding this package: the platforms and
#: the default one, named once for the shell scripts, CMake and Python
PLATFORMS_FILE = os.path.join(
    os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))), "etc", "platforms")


def read_platforms(path=PLATFORMS_FILE):
    """(platforms, default platform) of etc/platforms: the shell
    assignments ROUGHWALL_PLATFORMS="..." and ROUGHWALL_DEFAULT_PLATFORM=..."""
    values = {}
    with open(path) as f:
        for line in f:
            m = re.match(r'\s*(ROUGHWALL_(?:DEFAULT_)?PLATFORMS?)='
                         r'"?([^"#]*)"?\s*(#.*)?$', line)
            if m:
                values[m.group(1)] = m.group(2).split()
    platforms = tuple(values.get("ROUGHWALL_PLATFORMS", ()))
    default = values.get("ROUGHWALL_DEFAULT_PLATFORM", [None])[0]
    if not platforms or default not in platforms:
        raise FoamError("%s: no ROUGHWALL_PLATFORMS, or a "
                        "ROUGHWALL_DEFAULT_PLATFORM not among them" % path)
    return platforms, default


#: The platforms of ./Alltest, and the platform where none is named
PLATFORMS, DEFAULT_PLATFORM = read_platforms()


def is_foundation(name):
    """openfoam.org's releases (openfoamNN) against ESI's (openfoamYYMM)"""
    return len(name[len("openfoam"):]) <= 2


#: The openfoam.org platforms (foamRun; the field-based Lagrangian)
FOUNDATION_PLATFORMS = tuple(p for p in PLATFORMS if is_foundation(p))

#: The platform of benchmark results written before their files had a
#: platform column: every one of them was measured on OpenFOAM-13
UNRECORDED_PLATFORM = "openfoam13"


def display_name(name):
    """'OpenFOAM-14' for openfoam14, 'OpenFOAM v1912' for openfoam1912"""
    version = name[len("openfoam"):]
    return ("OpenFOAM-" + version if is_foundation(name)
            else "OpenFOAM v" + version)

#: Cloud kinds: does the parcel carry spin (angularMomentum)?
SPIN = {"colliding": True, "kinematic": False, "DPM": True, "MPPIC": False}


class Platform:
    """What differs between the platforms, in one place."""

    def __init__(self, name):
        if name not in PLATFORMS:
            raise ValueError("unknown platform %r (%s)"
                             % (name, " or ".join(PLATFORMS)))
        self.name = name
        self.foundation = is_foundation(name)
        #: $WM_PROJECT_VERSION of the platform's environment
        self.version = (name[len("openfoam"):] if self.foundation
                        else "v" + name[len("openfoam"):])
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
            raise FoamError("cloud kind %s is not available on %s"
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



LIBRARY = "libroughWallInteraction.so"

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
    """{library name: resolved path or 'not found'} of a binary.

    Under ctest ($ROUGHWALL_TEST_CACHE) ldd's output is kept there, keyed by
    the binary's path, size and time and the loader's search path: each test
    checks its libraries, and a binary rebuilt or a search path changed gives
    a new key."""
    cache = os.environ.get("ROUGHWALL_TEST_CACHE")
    out = None
    if cache:
        stat = os.stat(path)
        key = hashlib.sha1(repr((os.path.abspath(path), stat.st_size,
                                 stat.st_mtime_ns,
                                 library_search_path())).encode())
        saved = os.path.join(cache, "ldd", key.hexdigest())
        if os.path.exists(saved):
            with open(saved) as f:
                out = f.read()
    if out is None:
        out = subprocess.run(["ldd", path], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True).stdout
        if cache:
            write_text_atomic(saved, out)
    deps = {}
    for line in out.splitlines():
        m = re.match(r"\s*(\S+)\s+=>\s+(\S+(?: found)?)", line)
        if m:
            deps[m.group(1)] = m.group(2)
    return deps


def environment_library(platform):
    """The path of libroughWallInteraction.so in the environment of
    platform (a Platform), which must be the only one sourced: a FoamError
    names what is wrong (another OpenFOAM, the library not built)."""
    version = os.environ.get("WM_PROJECT_VERSION")
    if not os.environ.get("WM_PROJECT_DIR") or version != platform.version:
        raise FoamError(
            "not in the %s environment (WM_PROJECT_VERSION %r): run it as "
            "etc/openfoamEnv %s /usr/bin/python3 <script> (ctest does)"
            % (platform, version, platform))
    lib = find_library(LIBRARY)
    if lib is None:
        raise FoamError("%s not found in $LD_LIBRARY_PATH of %s "
                        "($FOAM_USER_LIBBIN = %s): build it first "
                        "(./Allwmake)"
                        % (LIBRARY, platform,
                           os.environ.get("FOAM_USER_LIBBIN")))
    return lib
