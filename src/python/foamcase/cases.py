"""A case made from a template folder for one platform and cloud kind, and
the manualInjection injectors of its parcels.

A template (tests/openfoam/wallImpact, tests/stability/openfoam/closedBox,
benchmarks/openfoam/wallBox) holds the files every platform reads; FoamCase
copies it and writes the few platform-specific files: the cloud properties'
name and type line, the injectors, controlDict's solver entries, and for
OpenFOAM-13 and -14 system/functions, constant/physicalProperties,
constant/momentumTransport and the kinematic pressure 0/p of the frozen
incompressibleFluid carrier.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import os
import re
import shutil

import numpy as np

from .dictionaries import (dict_entry, foam_header, read_text, replace_in_file,
                           set_entry, write_text, write_vectors)
from .errors import FoamError
from .lagrangian import cloud_dirs, cloud_parts, read_cloud
from .logs import STATISTICS, read_statistics, read_steps, statistics_path
from .platforms import SPIN
from .running import block_mesh, mpirun, run

class Injector:
    """A manualInjection: one parcel (of nParticle particles, default 1) at
    each of positions (n, 3) at t = 0 with velocity U0 and diameter d."""

    def __init__(self, name, positions, U0, d, nParticle=1):
        self.name = name
        self.nParticle = nParticle
        self.positions = np.asarray(positions, dtype=float).reshape(-1, 3)
        self.U0 = tuple(float(u) for u in U0)
        self.d = float(d)

    def entry(self, platform):
        """The injectionModels entry in the platform's syntax."""
        if platform.foundation:
            basis = "nParticle       %r;" % self.nParticle
            size = "sizeDistribution\n    {\n        type        fixedValue;" \
                   "\n        value       %r;\n    }" % self.d
        else:
            basis = "massTotal       0;\n    parcelBasisType fixed;\n" \
                    "    nParticle       %r;" % self.nParticle
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
            raise FoamError("controlDict has no application entry")
        write_text(control, text)

    # -- files --------------------------------------------------------------

    def file(self, relpath):
        return os.path.join(self.path, relpath)

    def cloud_properties(self):
        """Path of the cloud properties file of the platform."""
        return self.file("constant/" + self.platform.properties)

    def set_entry(self, relpath, key, value):
        """Replace 'key  value;' (first occurrence) in a dictionary file."""
        set_entry(self.file(relpath), key, value)

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
                   "// Written by foamcase for %s\n\n" % self.platform
                   + "\n".join(inj.entry(self.platform) for inj in injectors))
        return sum(len(inj.positions) for inj in injectors)

    def set_integration(self, scheme):
        """The integration scheme of the parcel velocity."""
        replace_in_file(self.cloud_properties(),
                        r"(integrationSchemes\s*\{\s*U\s+)\w+;",
                        r"\g<1>%s;" % scheme)

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
        block_mesh(self.path)
        self.nprocs = nprocs
        if nprocs > 1:
            self.set_subdomains(nprocs)
            self.run(["decomposePar"], "log.decomposePar")

    def run_args(self):
        """The command line of the platform's solver (parallel after
        mesh(n > 1))."""
        args = [self.solver]
        if self.nprocs > 1:
            args = mpirun(self.nprocs, args + ["-parallel"])
        return args

    def solve(self, log="log.solver", check_rc=True, timeout=900):
        """Run the platform's solver (parallel after mesh(n > 1)).
        Returns (rc, wall-clock seconds)."""
        return self.run(self.run_args(), log, check_rc, timeout)

    def log(self, log="log.solver"):
        return read_text(self.file(log))

    # -- output -------------------------------------------------------------

    def cloud_dirs(self, time_name):
        return cloud_dirs(self.path, time_name, self.platform.cloud)

    def read_cloud(self, time_name, fields):
        return read_cloud(self.path, time_name, fields, self.platform.cloud)

    def cloud_parts(self, time_name, fields=("U", "d", "angularMomentum")):
        return cloud_parts(self.path, time_name, fields, self.platform.cloud)

    def read_statistics(self, name=STATISTICS):
        return read_statistics(self.path, self.platform.cloud, name)

    def statistics_file(self, time_name):
        return statistics_path(self.path, self.platform.cloud, time_name)

    def read_steps(self, log="log.solver"):
        return read_steps(self.file(log))
