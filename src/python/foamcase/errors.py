"""The errors of foamcase.

SPDX-License-Identifier: GPL-3.0-or-later
"""


class FoamError(Exception):
    """Output that is missing or not what OpenFOAM writes, or a platform or
    case that cannot be set up as asked."""


class CommandFailed(FoamError):
    """An OpenFOAM command exited non-zero or timed out."""
