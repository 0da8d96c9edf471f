"""Independent numpy oracle of the rough-wall collision operator.

I. V. Derevich's probabilistic model of a particle hitting a randomly rough
wall (model notes section 1-4, docs/theory.md for the conventions), written
from the equations, not from the C++ core (src/roughWallCore), so that the two
implementations can check each other. Only /usr/bin/python3 and Debian's
numpy are needed.

Conventions (the same as the core's, docs/theory.md section 1)
----------------------------------------------------------------
* ``wall_normal`` N: unit normal of the mean wall pointing INTO the fluid
  (OpenFOAM's patch normal is -N).
* Plane of incidence: t = tangential part of v / its length,
  alpha = atan2(-v.N, |v_t|) in [0, pi/2]. At normal incidence (no
  tangential velocity) t is drawn uniformly in the wall plane (in 2-D: +- the
  in-plane wall direction).
* Facet tilt gamma ~ P(gamma, alpha) (eq. 1.3, shadow corrected), restricted to
  gamma < pi/2 (a facet beyond the vertical is an overhang: redrawn).
  Facet outward normal n = cos(gamma) N - sin(gamma) t.
* Lateral tilt (``lateral=True``, 3-D only): n is rotated by
  delta ~ N(0, Delta), |delta| < pi/2, about the incidence direction v/|v|
  (keeps v.n, hence the shadow condition).
* Facet collision: hard sphere, radius r = d/2, I = m d^2/10, restitution e,
  static friction mu0 (no-slip criterion), dynamic friction muD (model notes
  section 4). The sliding impulse is capped at the no-slip impulse (only
  active for muD > mu0), as the core does.
* One wall hit: collide with new facets (new gamma for the new incidence)
  while v.N < 0, at most ``max_facet`` facet collisions; if the particle still
  moves into the wall then, the fallback is one collision with the mean wall
  (gamma = 0), after which v.N >= 0.
* Without spin (``omega_in=None``; the core's ``withSpin=false``): the sphere
  arrives at EVERY facet collision without spin (spin is neither read nor
  written, spin produced by a facet collision is not carried to the next
  one), but the no-slip impulse keeps the factor 2/7 of a solid sphere.
* Angles are radians in the functions operating on vectors; the statistics
  helpers (``restitution_statistics``) take degrees, like roughWallStats.

Sampling method (deliberately NOT the core's)
---------------------------------------------
With h = alpha/Delta and x = beta/Delta = (alpha + gamma)/Delta > 0 the density
of x is proportional to f(x) = phi(x - h) - phi(x + h)
= 2 phi(0) exp(-(x^2 + h^2)/2) sinh(x h).
* h <= 1.2: proposal x = sqrt(-4 ln U) (Rayleigh with sigma^2 = 2, density
  (x/2) exp(-x^2/4)); f / proposal is proportional to
  exp(-x^2/4) sinh(x h)/(x h) <= exp(-x^2 (1/4 - h^2/6)) <= 1 (because
  sinh(y)/y <= exp(y^2/6)), so accept with that probability. Acceptance
  sqrt(pi/2) exp(h^2/2) erf(h/sqrt 2)/(2h), >= 0.5.
* h > 1.2: proposal x = |h + Z| (folded normal, density phi(x-h) + phi(x+h)),
  accept with probability f/proposal = tanh(x h). Acceptance erf(h/sqrt 2)
  >= 0.77.
Normals are Box-Muller from numpy's uniform numbers (no ziggurat).
The independent check of the sampler is quadrature of (1.3) itself
(``facet_tilt_pdf``, ``facet_tilt_cdf``).

Main API (angles in radians unless the name says _deg)
------------------------------------------------------
sample_facet_tilt(alpha, Delta, rng, truncate=True)        -> gamma (N,)
standard_normal(rng, size)                                  -> Box-Muller N(0,1)
facet_tilt_pdf(gamma, alpha, Delta)                         -> P(gamma, alpha)
facet_tilt_cdf(gamma, alpha, Delta, truncate=True)          -> CDF by quadrature
facet_tilt_mass(alpha, Delta, upper=inf)                    -> integral of the pdf
facet_tilt_moments(alpha, Delta, truncate=True)             -> (mean, sd) by quadrature
overhang_fraction(alpha, Delta)                             -> P(gamma >= pi/2)
facet_collision(v, omega, n, d, e, mu0, muD)                -> FacetResult
    (e, mu0, muD: numbers, or coefficient functions of the facet impact:
     a callable of the facet impact angle [deg], or ImpactFunction(f,
     "normalSpeed") for e of the normal impact speed; issue 31)
facet_impact(v, n)                                          -> (beta_deg, normal_speed)
single_facet_quadrature(alpha_deg, Delta_deg, e, mu0, muD, speed=1,
        fallback=False)                                     -> dict per angle
    (mean k_n, k_t of one facet collision, no spin, by quadrature over
     P(gamma, alpha); fallback=True adds the mean-wall collision of the
     operator with max_facet=1 where the particle still moves into the wall)
    (v, omega, no_slip, jn, jt)
rebound(v_in, omega_in=None, wall_normal=(0,1,0), d=1, e=0.8, mu0=0.4,
        muD=None, Delta=0, lateral=False, max_facet=10, rng=None,
        plane_normal=None, recollide=True)                  -> Rebound
    (v, omega, n_facet, fallback, first_gamma, first_no_slip, n_no_slip)
restitution_statistics(alpha_deg, Delta_deg, e=0.8, mu0=0.4, muD=None,
        samples=10**6, rng=None, spin=False, lateral=False, max_facet=10,
        recollide=True, d=1, plane_normal=None)             -> list of dict
    (per angle: mean/sd of k_n and k_t with standard errors, mean |k_n|,
     k_Omega (spin), p_multi, p_wallward, mean_facet_collisions, p_fallback,
     mean_first_gamma_deg, p_noslip, p_noslip_all)
kolmogorov_smirnov(samples, cdf)                            -> (D, p-value)

Cost: about 0.5 s per 10^6 single-collision samples, 0.6-0.9 s per 10^6
wall hits with re-collision (one core).
"""

from __future__ import annotations

import math
from typing import NamedTuple, Optional

import numpy as np

HALF_PI = 0.5*math.pi

#: h = alpha/Delta at which the sampler switches from the Rayleigh proposal
#: to the folded normal; the Rayleigh bound needs h <= sqrt(1.5) = 1.2247
H_SPLIT = 1.2

#: attempts of every rejection loop before giving up (acceptance >= 0.43,
#: so the probability to need more is below 1e-48)
MAX_ATTEMPTS = 200


# --------------------------------------------------------------------------
# Random variates
# --------------------------------------------------------------------------

def _uniform_open(rng: np.random.Generator, size) -> np.ndarray:
    """Uniform numbers in (0, 1] (safe for logarithms)."""
    return 1.0 - rng.random(size)


def standard_normal(rng: np.random.Generator, size) -> np.ndarray:
    """N(0, 1) by Box-Muller (cosine branch only): independent of the
    ziggurat used by the core and by numpy's own standard_normal."""
    u1 = _uniform_open(rng, size)
    u2 = rng.random(size)
    return np.sqrt(-2.0*np.log(u1))*np.cos(2.0*math.pi*u2)


def _shinc(y: np.ndarray) -> np.ndarray:
    """sinh(y)/y, 1 at y = 0."""
    out = np.ones_like(y)
    nz = y != 0
    out[nz] = np.sinh(y[nz])/y[nz]
    return out


def _sample_x(h: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Draw g = gamma/Delta for each h = alpha/Delta (>= 0), untruncated.

    Returns g (not x = g + h: for large h, x - h would lose the digits of
    g)."""
    h = np.asarray(h, dtype=float)
    g = np.empty_like(h)
    pending = np.arange(h.size)
    for _ in range(MAX_ATTEMPTS):
        if pending.size == 0:
            return g
        hp = h[pending]
        small = hp <= H_SPLIT
        accepted = np.zeros(pending.size, dtype=bool)
        gp = np.empty(pending.size)

        # Rayleigh proposal, sigma^2 = 2
        i = np.flatnonzero(small)
        if i.size:
            x = np.sqrt(-4.0*np.log(_uniform_open(rng, i.size)))
            hs = hp[i]
            p = np.exp(-0.25*x*x)*_shinc(x*hs)
            accepted[i] = rng.random(i.size) < p
            gp[i] = x - hs

        # folded normal proposal, tanh acceptance
        j = np.flatnonzero(~small)
        if j.size:
            z = standard_normal(rng, j.size)
            hl = hp[j]
            s = hl + z
            x = np.abs(s)
            accepted[j] = rng.random(j.size) < np.tanh(x*hl)
            # g = x - h: = z if h + z > 0, else -(2h + z)
            gp[j] = np.where(s > 0, z, -(2.0*hl + z))

        g[pending[accepted]] = gp[accepted]
        pending = pending[~accepted]
    raise RuntimeError("facet tilt sampler: rejection did not terminate")


def sample_facet_tilt(alpha, Delta: float, rng: np.random.Generator,
                      truncate: bool = True) -> np.ndarray:
    """Facet tilts gamma [rad] ~ P(gamma, alpha), eq. (1.3).

    alpha: array (or scalar) of incidence angles [rad], in [0, pi/2];
    Delta: standard deviation of the facet tilt [rad], >= 0 (0: gamma = 0);
    truncate: restrict to gamma < pi/2 (redraw beyond), as the operator does.
    """
    alpha = np.atleast_1d(np.asarray(alpha, dtype=float))
    if np.any(alpha < 0) or np.any(alpha > HALF_PI + 1e-15):
        raise ValueError("alpha must lie in [0, pi/2]")
    if not Delta > 0:
        return np.zeros_like(alpha)
    h = alpha/Delta
    gamma = Delta*_sample_x(h, rng)
    if truncate:
        bad = np.flatnonzero(gamma >= HALF_PI)
        for _ in range(MAX_ATTEMPTS):
            if bad.size == 0:
                break
            gamma[bad] = Delta*_sample_x(h[bad], rng)
            bad = bad[gamma[bad] >= HALF_PI]
        else:
            raise RuntimeError("facet tilt truncation did not terminate")
    return gamma


# --------------------------------------------------------------------------
# The density (1.3) and its integrals by quadrature
# --------------------------------------------------------------------------

def facet_tilt_pdf(gamma, alpha: float, Delta: float) -> np.ndarray:
    """P(gamma, alpha) of eq. (1.3), untruncated, normalised with erf:
    [phi(gamma) - phi(gamma + 2 alpha)] / erf(alpha/(sqrt 2 Delta)),
    evaluated as phi(gamma) (1 - exp(-2 alpha beta/Delta^2)) / erf(...)
    (the same expression without cancellation). alpha = 0: Rayleigh."""
    gamma = np.asarray(gamma, dtype=float)
    g = gamma/Delta
    h = alpha/Delta
    b = g + h
    phi = np.exp(-0.5*g*g)/(math.sqrt(2*math.pi)*Delta)
    if h == 0:
        out = np.where(b > 0, b*np.exp(-0.5*g*g)/Delta, 0.0)
    else:
        out = np.where(b > 0, phi*(-np.expm1(-2*h*np.maximum(b, 0)))
                       / math.erf(h/math.sqrt(2)), 0.0)
    return out


_GL_X, _GL_W = np.polynomial.legendre.leggauss(10)


class _CdfTable:
    """Composite 10-point Gauss-Legendre integral of facet_tilt_pdf on a
    uniform grid from max(-alpha, -14 Delta) to min(pi/2, alpha + 14 Delta)
    (truncate) or 14 Delta; values between nodes integrated exactly by the
    same rule on the partial cell."""

    def __init__(self, alpha, Delta, truncate, cells=3000):
        self.alpha, self.Delta = alpha, Delta
        self.lo = max(-alpha, -14*Delta)
        hi = 14*Delta
        if truncate:
            hi = min(hi, HALF_PI)
        self.hi = hi
        self.edges = np.linspace(self.lo, hi, cells + 1)
        self.cum = np.concatenate(([0.0], np.cumsum(
            self._integral(self.edges[:-1], self.edges[1:]))))
        self.total = self.cum[-1]

    def _integral(self, a, b):
        a = np.asarray(a, dtype=float)[..., None]
        b = np.asarray(b, dtype=float)[..., None]
        x = 0.5*(a + b) + 0.5*(b - a)*_GL_X
        f = facet_tilt_pdf(x, self.alpha, self.Delta)
        return (0.5*(b - a)[..., 0])*(f @ _GL_W)

    def integral_to(self, gamma):
        gamma = np.clip(np.asarray(gamma, dtype=float), self.lo, self.hi)
        k = np.clip(np.searchsorted(self.edges, gamma, side="right") - 1,
                    0, self.edges.size - 2)
        return self.cum[k] + self._integral(self.edges[k], gamma)


def facet_tilt_cdf(gamma, alpha: float, Delta: float,
                   truncate: bool = True) -> np.ndarray:
    """CDF of gamma by quadrature of facet_tilt_pdf; with truncate the
    distribution restricted to gamma < pi/2 (renormalised)."""
    table = _CdfTable(alpha, Delta, truncate)
    norm = table.total if truncate else 1.0
    return table.integral_to(gamma)/norm


def facet_tilt_mass(alpha: float, Delta: float, upper: float = math.inf):
    """Integral of facet_tilt_pdf from -alpha to min(upper, 14 Delta) by
    quadrature: 1 up to the quadrature error for upper = inf (the check
    of the normalisation of (1.3))."""
    table = _CdfTable(alpha, Delta, truncate=False)
    return float(table.integral_to(min(upper, table.hi)))


def overhang_fraction(alpha: float, Delta: float) -> float:
    """P(gamma >= pi/2) under the untruncated P(gamma, alpha) (facets
    beyond the vertical, which the operator redraws), by quadrature of the
    density from pi/2 to pi/2 + 14 Delta."""
    lo, hi = HALF_PI, HALF_PI + 14*Delta
    n = 2000
    edges = np.linspace(lo, hi, n + 1)
    a, b = edges[:-1, None], edges[1:, None]
    x = 0.5*(a + b) + 0.5*(b - a)*_GL_X
    return float(np.sum(0.5*(b - a)[:, 0]*(facet_tilt_pdf(x, alpha, Delta)
                                           @ _GL_W)))


def facet_tilt_moments(alpha: float, Delta: float, truncate: bool = True):
    """(mean, sd) of gamma by quadrature (truncated to gamma < pi/2 or
    not)."""
    table = _CdfTable(alpha, Delta, truncate, cells=2000)
    a, b = table.edges[:-1, None], table.edges[1:, None]
    x = 0.5*(a + b) + 0.5*(b - a)*_GL_X
    w = 0.5*(b - a)*_GL_W*facet_tilt_pdf(x, alpha, Delta)
    m0 = w.sum()
    m1 = (w*x).sum()/m0
    m2 = (w*x*x).sum()/m0
    return m1, math.sqrt(max(m2 - m1*m1, 0.0))


def kolmogorov_smirnov(samples, cdf) -> tuple:
    """One-sample KS statistic D and its asymptotic p-value.
    cdf: callable mapping sorted samples to the model CDF."""
    x = np.sort(np.asarray(samples, dtype=float))
    n = x.size
    F = cdf(x)
    i = np.arange(1, n + 1)
    D = max(np.max(i/n - F), np.max(F - (i - 1)/n))
    lam = (math.sqrt(n) + 0.12 + 0.11/math.sqrt(n))*D
    k = np.arange(1, 101)
    p = float(np.clip(2*np.sum((-1.0)**(k - 1)*np.exp(-2*(k*lam)**2)), 0, 1))
    return float(D), p


# --------------------------------------------------------------------------
# The hard-sphere facet collision (model notes section 4)
# --------------------------------------------------------------------------

def _dot(a, b):
    return np.einsum("ij,ij->i", a, b)


class FacetResult(NamedTuple):
    v: np.ndarray          #: (N, 3) velocity after
    omega: Optional[np.ndarray]  #: (N, 3) angular velocity after (None: no spin)
    no_slip: np.ndarray    #: (N,) bool: ended rolling (no-slip branch)
    jn: np.ndarray         #: (N,) normal impulse per unit mass (>= 0)
    jt: np.ndarray         #: (N, 3) tangential impulse per unit mass


class ImpactFunction:
    """A coefficient as a function of the facet impact: f(x), x the facet
    impact angle beta [deg] (the angle between the incident velocity and the
    facet plane, 90 deg - the angle between -v and n) or, with
    argument="normalSpeed", the normal impact speed -v.n. A plain callable
    passed as e, mu0 or muD is a function of the angle."""

    def __init__(self, f, argument="angle"):
        if argument not in ("angle", "normalSpeed"):
            raise ValueError(f"ImpactFunction: argument {argument!r}")
        self.f = f
        self.argument = argument

    def __call__(self, beta_deg, normal_speed):
        return np.asarray(self.f(beta_deg if self.argument == "angle"
                                 else normal_speed), dtype=float)


def facet_impact(v, n):
    """The facet impact angle [deg] and normal speed of velocities v (N,3) on
    facets of unit outward normal n (N,3), v.n < 0: beta = 90 deg minus the
    angle between -v and n."""
    v = np.asarray(v, dtype=float)
    n = np.asarray(n, dtype=float)
    speed = np.sqrt(_dot(v, v))
    normal_speed = -_dot(v, n)
    cos_to_normal = np.clip(normal_speed/np.where(speed > 0, speed, 1.0),
                            -1.0, 1.0)
    return 90.0 - np.degrees(np.arccos(cos_to_normal)), normal_speed


def _coefficient(c, beta_deg, normal_speed):
    """A coefficient at the impacts: numbers as they are, functions evaluated"""
    if isinstance(c, ImpactFunction):
        return c(beta_deg, normal_speed)
    if callable(c):
        return np.asarray(c(beta_deg), dtype=float)
    return np.asarray(c, dtype=float)


def facet_collision(v, omega, n, d, e, mu0, muD) -> FacetResult:
    """Collide spheres (velocity v (N,3), angular velocity omega (N,3) or
    None for a sphere without spin, diameter d) with facets of unit outward
    normal n (N,3); v.n < 0 is required. d, e, mu0, muD: scalars or (N,)
    arrays. Impulses per unit mass:

      contact velocity c = v - r omega x n (c = v without spin)
      slip u = c - (c.n) n,  jn = -(1 + e) v.n
      |u| <= 3.5 mu0 jn: jt = -(2/7) u (ends rolling), else
      jt = -min(muD jn, (2/7)|u|) u/|u|   (capped: never reverses the slip)
      v'' = v + jn n + jt,  omega'' = omega - 5/(2 r) n x jt
    """
    v = np.asarray(v, dtype=float)
    n = np.asarray(n, dtype=float)
    if any(callable(x) for x in (e, mu0, muD)):
        beta_deg, normal_speed = facet_impact(v, n)
        e, mu0, muD = (_coefficient(x, beta_deg, normal_speed)
                       for x in (e, mu0, muD))
        if np.any(~(e >= 0) | (e > 1) | ~(mu0 >= 0) | ~(muD >= 0)
                  | (muD > mu0)):
            raise ValueError("facet_collision: a coefficient function is "
                             "out of its bounds")
    e, mu0, muD = (np.asarray(x, dtype=float) for x in (e, mu0, muD))
    rc = 0.5*np.asarray(d, dtype=float)   # radius, scalar or (N,)
    if rc.ndim:
        rc = rc[:, None]
    vn = _dot(v, n)
    if np.any(vn >= 0):
        raise ValueError("facet_collision: v.n must be negative")
    jn = -(1.0 + e)*vn
    if omega is None:
        c = v
    else:
        c = v - rc*np.cross(omega, n)
    u = c - _dot(c, n)[:, None]*n
    speed = np.sqrt(_dot(u, u))
    no_slip = speed <= 3.5*mu0*jn
    scale = np.where(no_slip, 2.0/7.0,
                     np.minimum(muD*jn, (2.0/7.0)*speed)
                     / np.where(speed > 0, speed, 1.0))
    jt = -scale[:, None]*u
    v2 = v + jn[:, None]*n + jt
    w2 = None if omega is None else omega - (2.5/rc)*np.cross(n, jt)
    return FacetResult(v2, w2, no_slip, jn, jt)


# --------------------------------------------------------------------------
# One wall hit: the rough-wall operator
# --------------------------------------------------------------------------

class Rebound(NamedTuple):
    v: np.ndarray                 #: (N, 3) velocity after the wall hit
    omega: Optional[np.ndarray]   #: (N, 3) spin after (None without spin)
    n_facet: np.ndarray           #: (N,) int: facet collisions (0: not hitting)
    fallback: np.ndarray          #: (N,) bool: bound reached, mean-wall rebound
    first_gamma: np.ndarray       #: (N,) tilt of the first facet [rad] (nan: none)
    first_no_slip: np.ndarray     #: (N,) bool: first facet collision ended rolling
    n_no_slip: np.ndarray         #: (N,) int: facet collisions ending rolling


def _unit(a):
    return a/np.sqrt(_dot(a, a))[:, None]


def _broadcast_rows(a, N):
    a = np.asarray(a, dtype=float)
    if a.ndim == 1:
        a = np.broadcast_to(a, (N, 3))
    return np.array(a, dtype=float)


def _incidence_frame(v, N, plane_normal, rng):
    """Unit tangent t and incidence angle alpha of each velocity."""
    vn = _dot(v, N)
    vt = v - vn[:, None]*N
    if plane_normal is not None:
        vt = vt - _dot(vt, plane_normal)[:, None]*plane_normal
    vt = vt - _dot(vt, N)[:, None]*N
    lt = np.sqrt(_dot(vt, vt))
    speed = np.sqrt(_dot(v, v))
    normal = ~(lt > 1e-13*speed)
    t = np.empty_like(v)
    ok = ~normal
    t[ok] = vt[ok]/lt[ok, None]
    alpha = np.arctan2(np.maximum(-vn, 0.0), lt)
    k = np.flatnonzero(normal)
    if k.size:
        alpha[k] = HALF_PI
        Nk = N[k]
        if plane_normal is not None:
            inplane = _unit(np.cross(plane_normal[k], Nk))
            sign = np.where(rng.random(k.size) < 0.5, 1.0, -1.0)
            t[k] = sign[:, None]*inplane
        else:
            # any unit vector orthogonal to N, then a uniform angle
            trial = np.where(np.abs(Nk[:, [0]]) < 0.9,
                             np.array([1.0, 0, 0]), np.array([0, 1.0, 0]))
            a = _unit(trial - _dot(trial, Nk)[:, None]*Nk)
            b = np.cross(Nk, a)
            phi = 2*math.pi*rng.random(k.size)
            t[k] = np.cos(phi)[:, None]*a + np.sin(phi)[:, None]*b
    return t, alpha


def _lateral_tilt(Delta, size, rng):
    """delta ~ N(0, Delta) restricted to |delta| < pi/2."""
    delta = Delta*standard_normal(rng, size)
    bad = np.flatnonzero(np.abs(delta) >= HALF_PI)
    while bad.size:
        delta[bad] = Delta*standard_normal(rng, bad.size)
        bad = bad[np.abs(delta[bad]) >= HALF_PI]
    return delta


def _leave_mean_wall(v, N):
    """After a collision with the mean wall v.N = -e v.N >= 0 up to
    round-off: remove a negative normal part, and where rounding still
    leaves v.N < 0 lift it by a few ulps of |v| (the particle must leave)."""
    v = v.copy()
    margin = 16*np.finfo(float).eps*np.max(np.abs(v), axis=1)
    for i in range(4):
        vn = _dot(v, N)
        k = vn < 0
        if not np.any(k):
            break
        v[k] -= (vn[k] - i*margin[k])[:, None]*N[k]
    return v


def rebound(v_in, omega_in=None, wall_normal=(0.0, 1.0, 0.0), d=1.0,
            e=0.8, mu0=0.4, muD=None, Delta=0.0, lateral=False,
            max_facet=10, rng=None, plane_normal=None,
            recollide=True) -> Rebound:
    """One wall hit of N particles on the rough wall.

    v_in:        (N, 3) velocities relative to the wall
    omega_in:    (N, 3) angular velocities [rad/s], or None: a cloud without
                 spin (each facet collision starts without spin; the returned
                 omega is None)
    wall_normal: unit mean-wall normal INTO the fluid, (3,) or (N, 3)
    d:           particle diameter (only matters with spin)
    e, mu0, muD: restitution, static and dynamic friction (muD None: mu0)
    Delta:       standard deviation of the facet tilt [rad] (0: smooth wall)
    lateral:     sideways tilt about v/|v| (ignored in 2-D)
    max_facet:   bound on facet collisions, >= 0
    rng:         numpy Generator (default: np.random.default_rng(1))
    plane_normal: unit normal of a 2-D case's plane (the empty direction),
                 None in 3-D. Then t lies in the plane and there is no lateral
                 tilt; v_in and omega_in must have no out-of-plane velocity
                 and no in-plane spin.
    recollide:   False: exactly one facet collision (the paper's statistics:
                 the result may still point into the wall), no fallback.

    Particles with v.N >= 0 are returned unchanged (n_facet = 0).
    """
    if muD is None:
        muD = mu0
    if rng is None:
        rng = np.random.default_rng(1)
    v = np.array(np.atleast_2d(v_in), dtype=float)
    Np = v.shape[0]
    w = None if omega_in is None else _broadcast_rows(omega_in, Np)
    N = _broadcast_rows(wall_normal, Np)
    P = None if plane_normal is None else _broadcast_rows(plane_normal, Np)
    use_lateral = lateral and P is None and Delta > 0

    n_facet = np.zeros(Np, dtype=int)
    fallback = np.zeros(Np, dtype=bool)
    first_gamma = np.full(Np, np.nan)
    first_no_slip = np.zeros(Np, dtype=bool)
    n_no_slip = np.zeros(Np, dtype=int)
    done = np.zeros(Np, dtype=bool)   # left the wall on a gamma = 0 facet

    draws = max_facet if recollide else 1
    for _ in range(draws):
        k = np.flatnonzero((_dot(v, N) < 0) & ~done)
        if k.size == 0:
            break
        vk = v[k]
        Nk = N[k]
        Pk = None if P is None else P[k]
        t, alpha = _incidence_frame(vk, Nk, Pk, rng)
        gamma = sample_facet_tilt(alpha, Delta, rng)
        n = np.cos(gamma)[:, None]*Nk - np.sin(gamma)[:, None]*t
        if use_lateral:
            delta = _lateral_tilt(Delta, k.size, rng)
            u = _unit(vk)
            cd, sd = np.cos(delta)[:, None], np.sin(delta)[:, None]
            n = cd*n + sd*np.cross(u, n) + (1 - cd)*_dot(u, n)[:, None]*u
        hit = _dot(vk, n) < 0   # grazing a facet at round-off: draw again
        k, n, gamma = k[hit], n[hit], gamma[hit]
        if k.size == 0:
            continue
        res = facet_collision(v[k], None if w is None else w[k], n, d,
                              e, mu0, muD)
        v[k] = res.v
        if w is not None:
            w[k] = res.omega
        first = n_facet[k] == 0
        first_gamma[k[first]] = gamma[first]
        first_no_slip[k[first]] = res.no_slip[first]
        n_facet[k] += 1
        n_no_slip[k] += res.no_slip
        flat = (gamma == 0) & ~use_lateral
        if np.any(flat):
            kf = k[flat]
            v[kf] = _leave_mean_wall(v[kf], N[kf])
            done[kf] = True

    if recollide:
        k = np.flatnonzero(_dot(v, N) < 0)
        if k.size:
            res = facet_collision(v[k], None if w is None else w[k], N[k], d,
                                  e, mu0, muD)
            v[k] = _leave_mean_wall(res.v, N[k])
            if w is not None:
                w[k] = res.omega
            fallback[k] = True
    return Rebound(v, w, n_facet, fallback, first_gamma, first_no_slip,
                   n_no_slip)


# --------------------------------------------------------------------------
# Statistics compared by the tests
# --------------------------------------------------------------------------

def _moments(x):
    """mean, se of the mean, sd, se of the sd (delta method), as
    roughWallReference computes them."""
    n = x.size
    m = x.mean()
    dx = x - m
    m2 = np.mean(dx*dx)
    m4 = np.mean(dx**4)
    sd = math.sqrt(m2*n/(n - 1))
    se_sd = math.sqrt(max(m4 - m2*m2, 0.0)/n)/(2*math.sqrt(m2)) if m2 > 0 \
        else 0.0
    return float(m), sd/math.sqrt(n), sd, se_sd


def restitution_statistics(alpha_deg, Delta_deg, e=0.8, mu0=0.4, muD=None,
                           samples=1_000_000, rng=None, spin=False,
                           lateral=False, max_facet=10, recollide=True,
                           d=1.0, chunk=250_000, plane_normal=None):
    """Rebound statistics per incidence angle, the quantities the OpenFOAM
    and roughWallStats tests compare.

    The particle arrives with v = (cos alpha, -sin alpha, 0) on the wall
    y = 0 (N = (0, 1, 0), t = (1, 0, 0)), no incident spin; spin=True tracks
    the spin produced by a facet collision into the following ones (the
    core's withSpin = true), spin=False does not. recollide=False: one facet
    collision only (roughWallStats' default statistics). plane_normal
    (0, 0, 1): the 2-D operator (roughWallStats --recollide without --lateral
    runs the core so).

    Returns one dict per angle with: alpha_deg, Delta_deg, samples,
      mean_kn, se_mean_kn, sd_kn, se_sd_kn      k_n = -v''.N / v'.N (signed)
      mean_kt, se_mean_kt, sd_kt, se_sd_kt      k_t = v''.t / |v'_t|
      mean_abs_kn, se_mean_abs_kn
      mean_kOmega, se_mean_kOmega, sd_kOmega, se_sd_kOmega (spin only)
                               k_Omega = r Omega''.(t x N) / |v'_t|
      p_multi, se_p_multi      fraction of hits with more than one facet collision
      p_wallward               fraction still moving into the wall after the
                               first facet collision (with recollide: a second
                               facet collision or the fallback followed)
      mean_facet_collisions, p_fallback
      mean_first_gamma_deg, se_mean_first_gamma_deg
      p_noslip                 first facet collision ended rolling
      p_noslip_all             fraction of all facet collisions ending rolling
    """
    if rng is None:
        rng = np.random.default_rng(1)
    Delta = math.radians(Delta_deg)
    out = []
    for a_deg in np.atleast_1d(alpha_deg):
        a = math.radians(float(a_deg))
        kn_all, kt_all, nf_all, fb_all, g_all, ns_all = [], [], [], [], [], []
        ko_all, nns_all = [], []
        done = 0
        while done < samples:
            m = min(chunk, samples - done)
            v = np.tile([math.cos(a), -math.sin(a), 0.0], (m, 1))
            w = np.zeros((m, 3)) if spin else None
            res = rebound(v, w, (0.0, 1.0, 0.0), d, e, mu0, muD, Delta,
                          lateral=lateral, max_facet=max_facet, rng=rng,
                          recollide=recollide, plane_normal=plane_normal)
            kn_all.append(res.v[:, 1]/math.sin(a))
            kt_all.append(res.v[:, 0]/math.cos(a) if a_deg < 90
                          else np.full(m, np.nan))
            if spin:
                # k_Omega = r Omega''.z / V'_x, z = t x N = (0, 0, 1)
                ko_all.append(0.5*d*res.omega[:, 2]/math.cos(a) if a_deg < 90
                              else np.full(m, np.nan))
            nf_all.append(res.n_facet)
            fb_all.append(res.fallback)
            g_all.append(res.first_gamma)
            ns_all.append(res.first_no_slip)
            nns_all.append(res.n_no_slip)
            done += m
        kn, kt = np.concatenate(kn_all), np.concatenate(kt_all)
        nf, fb = np.concatenate(nf_all), np.concatenate(fb_all)
        g, ns = np.concatenate(g_all), np.concatenate(ns_all)
        row = dict(alpha_deg=float(a_deg), Delta_deg=float(Delta_deg),
                   samples=samples)
        (row["mean_kn"], row["se_mean_kn"], row["sd_kn"],
         row["se_sd_kn"]) = _moments(kn)
        (row["mean_kt"], row["se_mean_kt"], row["sd_kt"],
         row["se_sd_kt"]) = _moments(kt)
        row["mean_abs_kn"] = float(np.mean(np.abs(kn)))
        row["se_mean_abs_kn"] = float(np.std(np.abs(kn))/math.sqrt(samples))
        if spin:
            (row["mean_kOmega"], row["se_mean_kOmega"], row["sd_kOmega"],
             row["se_sd_kOmega"]) = _moments(np.concatenate(ko_all))
        multi = nf > 1
        row["p_multi"] = float(multi.mean())
        row["se_p_multi"] = math.sqrt(max(row["p_multi"]*(1 - row["p_multi"]),
                                          1.0/samples)/samples)
        # still moving into the wall after the first facet collision: a
        # second one followed, or the fallback did (recollide); k_n < 0
        row["p_wallward"] = float(np.mean(multi | (fb & (nf == 1)))) \
            if recollide else float(np.mean(kn < 0))
        row["mean_facet_collisions"] = float(nf.mean())
        row["p_fallback"] = float(fb.mean())
        gd = np.degrees(g)
        row["mean_first_gamma_deg"] = float(np.mean(gd))
        row["se_mean_first_gamma_deg"] = float(np.std(gd)/math.sqrt(samples))
        row["p_noslip"] = float(ns.mean())
        nns = np.concatenate(nns_all)
        row["p_noslip_all"] = float(nns.sum()/max(nf.sum(), 1))
        out.append(row)
    return out


# --------------------------------------------------------------------------
# Quadrature of one facet collision with coefficient functions (issue 31)
# --------------------------------------------------------------------------

def single_facet_quadrature(alpha_deg, Delta_deg, e=0.8, mu0=0.4, muD=None,
                            speed=1.0, fallback=False, cells=20000,
                            refine=400, spin=False):
    """Mean k_n and k_t of one facet collision of a sphere without spin,
    v = speed (cos alpha, -sin alpha, 0) on the wall y = 0, averaged over
    P(gamma, alpha) (eq. 1.3, facet_tilt_pdf) truncated to gamma < pi/2:
    composite 4-point Gauss-Legendre on `cells` equal cells of
    (-alpha, min(pi/2, 40 Delta)); a cell whose nodes see both regimes (the
    rebound jumps there when muD < mu0) or, with fallback, both signs of
    the rebound's v.N, is integrated again on `refine` subcells. e, mu0, muD
    as for facet_collision (numbers or functions of the facet impact).
    fallback=True: where the rebound still moves into the wall, one more
    collision with the mean wall (the operator with max_facet=1); spin=True:
    that collision sees the spin the first one gave (a cloud with spin, the
    core's withSpin = true; the sphere arrives without spin). The error
    is below 1e-7 for the tests' functions (checked against 4x the cells).
    Returns one dict per angle: alpha_deg, mean_kn, mean_kt, mass (the
    integral of the truncated pdf, 1 up to the quadrature error), p_wallward
    (probability that the first collision leaves v.N < 0)."""
    if muD is None:
        muD = mu0
    Delta = math.radians(Delta_deg)
    x, w = np.polynomial.legendre.leggauss(4)

    def nodes(edges):
        mid = 0.5*(edges[1:] + edges[:-1])[:, None]
        half = 0.5*(edges[1:] - edges[:-1])[:, None]
        return (mid + half*x[None, :]).ravel(), (half*w[None, :]).ravel()

    def rebound_at(g, a):
        m = g.size
        v = np.tile([speed*math.cos(a), -speed*math.sin(a), 0.0], (m, 1))
        n = np.stack([-np.sin(g), np.cos(g), np.zeros(m)], axis=1)
        res = facet_collision(v, np.zeros((m, 3)) if spin else None, n, 1.0,
                              e, mu0, muD)
        v2 = res.v
        into = v2[:, 1] < 0
        if fallback and np.any(into):
            N = np.tile([0.0, 1.0, 0.0], (int(into.sum()), 1))
            v2[into] = facet_collision(
                v2[into], res.omega[into] if spin else None, N, 1.0,
                e, mu0, muD).v
        return v2, into, res.no_slip

    out = []
    for a_deg in np.atleast_1d(alpha_deg):
        a = math.radians(float(a_deg))
        lo, hi = -a, min(HALF_PI, 40*Delta)
        edges = np.linspace(lo, hi, cells + 1)
        g, wq = nodes(edges)
        v2, into, no_slip = rebound_at(g, a)
        state = (no_slip.astype(int) + 2*into.astype(int)).reshape(cells, 4)
        mixed = np.any(state != state[:, :1], axis=1)
        keep = np.repeat(~mixed, 4)
        weight = wq[keep]*facet_tilt_pdf(g[keep], a, Delta)
        sums = [np.sum(weight*v2[keep, 1]), np.sum(weight*v2[keep, 0]),
                np.sum(weight), np.sum(weight*into[keep])]
        for k in np.flatnonzero(mixed):
            gf, wf = nodes(np.linspace(edges[k], edges[k + 1], refine + 1))
            vf, intof, _ = rebound_at(gf, a)
            wf = wf*facet_tilt_pdf(gf, a, Delta)
            sums[0] += np.sum(wf*vf[:, 1])
            sums[1] += np.sum(wf*vf[:, 0])
            sums[2] += np.sum(wf)
            sums[3] += np.sum(wf*intof)
        mass = float(sums[2])
        out.append(dict(
            alpha_deg=float(a_deg),
            mean_kn=float(sums[0]/mass/(speed*math.sin(a))),
            mean_kt=float(sums[1]/mass/(speed*math.cos(a)))
            if a_deg < 90 else float("nan"),
            mass=mass,
            p_wallward=float(sums[3]/mass)))
    return out
