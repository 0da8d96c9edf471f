"""foamcase: set up, run and read the OpenFOAM cases of roughWallInteraction.

One package for the tests (tests/openfoam, tests/stability/openfoam), the
benchmarks (benchmarks/scripts) and the tutorial's scripts
(tutorials/incompressibleFluid/horizontalChannel/scripts), on the three
platforms (OpenFOAM-13 and -14, openfoam.org; v1912, ESI):

  platforms   the platforms and the default one (read from etc/platforms),
              what differs between them (solvers, cloud names), where the
              loader finds the library
  dictionaries  reading and writing dictionary files
  fields      field and list files (lagrangian fields, internal fields,
              values on a patch)
  mesh        the geometry of a polyMesh (barycentric parcel coordinates
              to positions)
  lagrangian  parcels: fields, positions, processor folders
  logs        the solver log's cloud reports, the model's statistics file
  running     running an OpenFOAM command (serial, mpirun)
  cases       a case made from a template for one platform and cloud kind
  tables      read_csv: CSV tables (benchmark results, the tools' output)

and the modules of the project's test harness, benchmarks and tutorial,
imported by name (import foamcase.testing as t):

  checking    check/expect/Checker: the assertions of every test script
  testing     the harness of the OpenFOAM tests (tests/openfoam,
              tests/stability/openfoam): environment checks, main(), the
              wall-impact and closed-box cases, statistics against the oracle
  spinCase, lagrangianCase   the cases of the spin tests and of the
              Lagrangian-module tests (OpenFOAM-13/14 lagrangian clouds)
  testConstants  the test cases' bead density and the sphere's mass and
              moment of inertia, defined once
  roughWallOracle, roughnessProfileOracle   the independent numpy oracles
  oracleTesting  the built tools the oracle tests call (tests/oracle)
  bench, openfoamcost   the benchmark scripts' paths, machine description
              and the OpenFOAM cost runs (benchmarks/scripts)
  tutorial    the horizontalChannel tutorial scripts' shared helpers

Callers find it through PYTHONPATH=<checkout>/src/python, the one root of
the project's Python (ctest, the tutorial's Allrun and benchmarks/run set
it). Debian's python3 with numpy.  Errors are FoamError; a failed test
assertion is checking.TestFailure.

SPDX-License-Identifier: GPL-3.0-or-later
"""

from .errors import FoamError, CommandFailed
from .platforms import (PLATFORMS, DEFAULT_PLATFORM, FOUNDATION_PLATFORMS,
                        SPIN, LIBRARY, Platform, find_library,
                        library_search_path, ldd, environment_library)
from .dictionaries import (NUMBER, read_text, write_text, replace_in_file,
                           strip_header, write_text_atomic,
                           foam_header, write_vectors, dict_entry, set_entry)
from .fields import read_field, internal_field, patch_values
from .mesh import MeshGeometry
from .lagrangian import (processor_roots, time_dirs, cloud_dirs, read_cloud,
                         read_positions, cloud_parts)
from .logs import (STATISTICS, ANGLE_STATISTICS, statistics_path,
                   read_statistics, column, read_steps,
                   system_escapes, parcel_counts, final_parcels)
from .running import run, mpirun, block_mesh
from .tables import read_csv
from .cases import Injector, FoamCase

__all__ = [
    "FoamError", "CommandFailed",
    "PLATFORMS", "DEFAULT_PLATFORM", "FOUNDATION_PLATFORMS", "SPIN", "LIBRARY", "Platform", "find_library",
    "library_search_path", "ldd", "environment_library",
    "NUMBER", "read_text", "write_text", "replace_in_file", "strip_header",
    "write_text_atomic",
    "foam_header",
    "write_vectors", "dict_entry", "set_entry",
    "read_field", "internal_field", "patch_values",
    "MeshGeometry",
    "processor_roots", "time_dirs", "cloud_dirs", "read_cloud", "read_positions",
    "cloud_parts",
    "STATISTICS", "ANGLE_STATISTICS",
    "statistics_path", "read_statistics", "column", "read_steps",
    "system_escapes", "parcel_counts", "final_parcels",
    "run", "mpirun",
    "read_csv",
    "Injector", "FoamCase",
]
