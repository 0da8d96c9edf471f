"""Field and list files: lagrangian fields and lists (points, owner), the
internal field of a volField, the values on one patch.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import re

import numpy as np

from .dictionaries import NUMBER, read_text, strip_header
from .errors import FoamError


def read_field(path):
    """An ASCII field or list file: (n,) scalars/labels or (n, k) tuples.
    Uniform lists n{value} too."""
    body = strip_header(read_text(path))
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
        raise FoamError("no list in " + path)
    n = int(m_list.group(1))
    inner = body[m_list.end():body.rindex(")")]
    if n == 0:
        return np.zeros(0)
    if "(" in inner:
        values = np.array([float(t) for t in
                           inner.replace("(", " ").replace(")", " ").split()])
        return values.reshape(n, -1)
    return np.array([float(t) for t in inner.split()])


def internal_field(path, n_cells=None):
    """The internal field of a volScalarField or volVectorField: (n,) or
    (n, 3) (read_field reads list files; a field file's first list is
    followed by its boundaryField). A uniform field needs n_cells."""
    body = strip_header(read_text(path))
    m = re.search(r"internalField\s+uniform\s+(\([^)]*\)|%s)\s*;" % NUMBER,
                  body)
    if m:
        if n_cells is None:
            raise FoamError("%s: uniform internalField, number of cells "
                            "needed" % path)
        v = np.array(m.group(1).strip("()").split(), float)
        return np.tile(v, (n_cells, 1)) if len(v) > 1 \
            else np.full(n_cells, v[0])
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(",
                  body)
    if not m:
        raise FoamError("%s: no internalField" % path)
    width = {"scalar": 1, "vector": 3}[m.group(1)]
    n = int(m.group(2))
    end = body.index("boundaryField", m.end())
    values = np.array(body[m.end():end].replace("(", " ").replace(")", " ")
                      .replace(";", " ").split()[:n*width], float)
    return values.reshape(n, width) if width > 1 else values


def patch_values(path, patch):
    """Values of a volScalarField on one patch: (n,) array (uniform: one
    value)."""
    body = strip_header(read_text(path))
    i = body.index("boundaryField")
    m = re.search(r"\b" + re.escape(patch) + r"\s*\{", body[i:])
    if not m:
        raise FoamError("%s: no patch %s" % (path, patch))
    block = body[i + m.end():]
    block = block[:block.index("}")]
    m = re.search(r"value\s+uniform\s+(\S+?)\s*;", block)
    if m:
        return np.array([float(m.group(1))])
    m = re.search(r"value\s+nonuniform\s+List<scalar>\s*(\d+)\s*\((.*?)\)",
                  block, re.S)
    if not m:
        raise FoamError("%s: no value on patch %s" % (path, patch))
    return np.array(m.group(2).split(), float)
