# roughWallInteraction benchmarks: the OpenFOAM cost benchmark.
# Copyright (C) 2026 roughWallInteraction authors. SPDX-License-Identifier: GPL-3.0-or-later
"""The OpenFOAM cost benchmark behind openfoamCost.py, by concern: case
(the wall box and its variants), run (the timed, callgrind and perf runs,
the tutorial's variants), parse (tool output, stored rows), report (tables
and figures)."""
