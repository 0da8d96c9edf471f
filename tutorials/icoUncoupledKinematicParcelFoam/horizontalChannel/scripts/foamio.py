"""Minimal readers for the ASCII OpenFOAM files this tutorial post-processes.

Only what the tutorial writes is supported: ASCII lists of scalars, labels or
vectors (multi-line, "N(...)" on one line, or the uniform "N{value}"), the
lagrangian "positions" file ("(x y z) celli" per entry), and the boundary
values of a volScalarField; plain or compressed (.gz).
"""
import gzip
import os
import re

import numpy as np

# The size of a list: a line holding only a number, or a number directly
# followed by the list ("N(...)" for short lists, "N{value}" for uniform ones)
_COUNT = re.compile(r"^\s*(\d+)\s*(?=[({]|$)", re.M)


def read_text(path):
    """Text of an OpenFOAM file, also when it was written compressed (.gz)."""
    path = str(path)
    if not os.path.exists(path) and os.path.exists(path + ".gz"):
        path += ".gz"
    if path.endswith(".gz"):
        with gzip.open(path, "rt") as f:
            return f.read()
    with open(path) as f:
        return f.read()


def exists(path):
    """True if the file exists, plain or compressed."""
    return os.path.exists(str(path)) or os.path.exists(str(path) + ".gz")


def _strip_header(text):
    """Text after the FoamFile header dictionary."""
    i = text.find("FoamFile")
    if i >= 0:
        i = text.index("}", i) + 1
        text = text[i:]
    # Drop C++ comments
    text = re.sub(r"//.*", "", text)
    return re.sub(r"/\*.*?\*/", "", text, flags=re.S)


def _list_body(text, path):
    """Size and body of the first list of text: (n, body, uniform)."""
    m = _COUNT.search(text)
    if not m:
        raise ValueError(f"{path}: no list found")
    n = int(m.group(1))
    rest = text[m.end():].lstrip()
    if rest.startswith("{"):                       # N{value}
        return n, rest[1: rest.index("}")], True
    if not rest.startswith("("):
        raise ValueError(f"{path}: no list after the size {n}")
    line_end = rest.find("\n")
    first_line = rest if line_end < 0 else rest[:line_end]
    if first_line.rstrip().endswith(")") and first_line.count("(") == first_line.count(")"):
        return n, first_line.strip()[1:-1], False  # N(...) on one line
    return n, rest[1: rest.index("\n)")], False    # multi-line list


def read_list(path):
    """A top-level ASCII list: returns an (N,) or (N, 3) float array."""
    n, body, uniform = _list_body(_strip_header(read_text(path)), path)
    values = np.array(body.replace("(", " ").replace(")", " ").split(), float)
    if uniform:
        values = np.tile(values, (n, 1))
        return values[:, 0] if values.shape[1] == 1 else values
    if n == 0:
        return np.zeros(0)
    width = len(values)//n
    if width*n != len(values):
        raise ValueError(f"{path}: {len(values)} values for {n} entries")
    return values.reshape(n, width) if width > 1 else values


def read_positions(path):
    """Lagrangian 'positions' (ASCII, '(x y z) celli' per entry): (N, 3) array."""
    n, body, _ = _list_body(_strip_header(read_text(path)), path)
    num = r"([-+0-9.eE]+)"
    rows = re.findall(r"\(\s*" + num + r"\s+" + num + r"\s+" + num + r"\s*\)", body)
    if len(rows) != n:
        raise ValueError(f"{path}: {len(rows)} positions, header says {n}")
    return np.array(rows, float).reshape(n, 3)


def read_patch_values(path, patch):
    """Values of a volScalarField on one patch (nonuniform or uniform)."""
    text = _strip_header(read_text(path))
    i = text.index("boundaryField")
    m = re.search(r"\b" + re.escape(patch) + r"\s*\{", text[i:])
    if not m:
        raise ValueError(f"{path}: no patch {patch}")
    block = text[i + m.end():]
    block = block[: block.index("}")]
    m_uni = re.search(r"value\s+uniform\s+(\S+?)\s*;", block)
    if m_uni:
        return np.array([float(m_uni.group(1))])
    m_non = re.search(r"value\s+nonuniform\s+List<scalar>\s*(\d+)\s*\((.*?)\)", block, re.S)
    if not m_non:
        raise ValueError(f"{path}: no value for patch {patch}")
    return np.array(m_non.group(2).split(), float)
