"""Dictionary files: reading and writing text, the FoamFile header, entries.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import os
import re

from .errors import FoamError

#: A number as OpenFOAM writes it (nan and inf included)
NUMBER = r"[-+]?(?:[0-9.]+(?:[eE][-+]?[0-9]+)?|nan|inf)"


def read_text(path):
    with open(path) as f:
        return f.read()


def write_text(path, text):
    with open(path, "w") as f:
        f.write(text)


def write_text_atomic(path, text):
    """Write path whole or not at all (a temporary file of this process,
    renamed): tests running at the same time may share the file (the
    caches of the test run)."""
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    tmp = "%s.%d" % (path, os.getpid())
    write_text(tmp, text)
    os.replace(tmp, path)


def replace_in_file(path, pattern, replacement, count=1, flags=re.M):
    """Replace the regular expression pattern in a file, exactly count
    times; any other number of matches is a FoamError (the file is not the
    one the caller was written for)."""
    text, n = re.subn(pattern, replacement, read_text(path), flags=flags)
    if n != count:
        raise FoamError("%s: %d matches of %r instead of %d"
                        % (path, n, pattern, count))
    write_text(path, text)


def strip_header(text):
    """The text after the FoamFile header, comments removed."""
    start = text.index("}", text.index("FoamFile")) + 1 \
        if "FoamFile" in text else 0
    body = text[start:]
    body = re.sub(r"/\*.*?\*/", "", body, flags=re.S)
    return re.sub(r"//.*", "", body)


def foam_header(cls, obj, location="constant"):
    """The FoamFile header of a file of class cls, object obj."""
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


def set_entry(path, key, value):
    """Replace the first 'key  value;' of a dictionary file."""
    text, n = re.subn(r"^(\s*)%s\s+[^;]*;" % re.escape(key),
                      lambda m: "%s%s %s;" % (m.group(1), key, value),
                      read_text(path), count=1, flags=re.M)
    if n != 1:
        raise FoamError("%s has no entry %s" % (path, key))
    write_text(path, text)
