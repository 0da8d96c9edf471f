"""A test wall profile and its roughness angle Delta(d), computed here by
brute force, independently of the library (rollingSphereEnvelope.hpp).

The profile: a long wave (800 um, slope amplitude 0.05) plus a short one
(40 um, slope amplitude 0.35) with a random-phase ripple and a linear trend
of slope 0.1 (a tilted specimen, 5.7 deg: the levelling must remove it),
sampled every 1 um over 4 mm, written in micrometres with a header line and
a '# units um um' line (the reader's documented format).
Spheres of 100-120 um bridge the short wave, so Delta(d) there is well below
its small-sphere value: a wrong diameter shows in the rebound statistics.

The oracle: the trace levelled by its least-squares line (as documented
for roughness { profile ...; }), its polyline resampled 10 times finer; the
sphere's centre above each query abscissa x (spacing 0.25 um) is the highest
of z_j + sqrt(r^2 - (x - x_j)^2) over every fine point within r (brute
force), the tilt -asin((x - x_foot)/r) at the highest one, and Delta the rms
tilt over the queries with the whole sphere over the trace,
x in [x_0 + r, x_N-1 - r].  Resting on the fine points instead of the
polyline sweeps the tilt by the chord angle (0.1 um / r) over each point:
an rms error below 1e-3 rad, 0.06 deg, a hundredth of Delta here.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import math

import numpy as np

SPACING = 1e-6
POINTS = 4001


def profile():
    """x, z [m] of the test trace."""
    rng = np.random.default_rng(20261126)
    x = np.arange(POINTS) * SPACING
    z = (0.05 * 800e-6 / (2 * math.pi)) * np.sin(2 * math.pi * x / 800e-6 + 0.3)
    z += (0.35 * 40e-6 / (2 * math.pi)) * np.sin(2 * math.pi * x / 40e-6)
    for wavelength in (23e-6, 61e-6, 170e-6):
        z += 0.15e-6 * np.sin(2 * math.pi * x / wavelength
                              + rng.uniform(0, 2 * math.pi))
    z += 0.1 * x
    return x, z


def write_profile(path):
    """Write the trace in micrometres, with a header and a units line."""
    x, z = profile()
    with open(path, "w") as f:
        f.write("# test trace of foamcase/roughnessProfileOracle.py\n")
        f.write("# units um um\n")
        f.write("x_um z_um\n")
        for xi, zi in zip(x, z):
            f.write("%.6f %.9f\n" % (xi * 1e6, zi * 1e6))


def delta(d, refine=10, query_spacing=0.25e-6):
    """Delta(d) [rad] of the levelled trace, by brute force (module text)."""
    x, z = profile()
    # The file holds 9 decimals of um: round as the reader will see it
    x = np.round(x * 1e6, 6) * 1e-6
    z = np.round(z * 1e6, 9) * 1e-6
    slope, intercept = np.polyfit(x, z, 1)
    z = z - (slope * x + intercept)
    xf = np.linspace(x[0], x[-1], (len(x) - 1) * refine + 1)
    zf = np.interp(xf, x, z)
    r = 0.5 * d
    q = np.arange(x[0] + r, x[-1] - r, query_spacing)
    h = xf[1] - xf[0]
    w = int(math.ceil(r / h))
    tilt = np.empty(len(q))
    chunk = 256
    offsets = np.arange(-w, w + 1)
    for start in range(0, len(q), chunk):
        qc = q[start:start + chunk]
        centre = np.rint((qc - xf[0]) / h).astype(int)
        idx = centre[:, None] + offsets[None, :]
        valid = (idx >= 0) & (idx < len(xf))
        idx = np.clip(idx, 0, len(xf) - 1)
        u = qc[:, None] - xf[idx]
        inside = valid & (np.abs(u) <= r)
        height = np.where(inside,
                          zf[idx] + np.sqrt(np.maximum(r * r - u * u, 0)),
                          -np.inf)
        best = np.argmax(height, axis=1)
        ub = u[np.arange(len(qc)), best]
        tilt[start:start + chunk] = -np.arcsin(ub / r)
    return float(np.sqrt(np.mean(tilt ** 2)))
