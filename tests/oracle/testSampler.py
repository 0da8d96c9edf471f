"""oracle.sampler: the oracle's facet-tilt sampler against P(gamma, alpha)
(eq. 1.3) integrated independently by Gauss-Legendre quadrature.

Checks (fixed seeds, deterministic):
 - the density (1.3) integrates to 1 (quadrature vs its erf normalisation),
   |1 - mass| < 1e-10; at alpha = 0 its CDF is the Rayleigh CDF (1e-10);
 - the rejection bound of the Rayleigh proposal, exp(-x^2/4) sinh(xh)/(xh)
   <= 1 for h <= 1.2 (grid, 1 + 1e-12);
 - Kolmogorov-Smirnov of 200 000 draws against the quadrature CDF
   (truncated to gamma < pi/2) at alpha/Delta from 0 to 20 (Delta = 0.5, 2,
   8 and 45 deg, both proposals and their boundary h = 1.2): p-value > 0.001;
 - sample mean and sd of gamma within 4 standard errors of the corrected
   closed forms (1.4) and (1.6) (Delta = 8 deg, where the truncation is
   below 1e-28) or of the truncated quadrature moments (Delta = 45 deg);
 - the overhang fraction P(gamma >= pi/2) by quadrature against the
   erfc closed form (1e-9) and the known values 13.5 % (Delta 45 deg,
   grazing: e^-2) and 6.1 % (Delta 45 deg, alpha 20 deg) within 0.05 %;
   the untruncated sampler's fraction within 4 se of it; the truncated
   sampler never returns gamma >= pi/2;
 - negative controls: the same KS test must reject (p < 1e-3) a sampler
   without shadow correction, a sampler with Delta 3 % too large and an
   untruncated sampler at Delta = 45 deg.
"""

import sys
sys.dont_write_bytecode = True   # keep the source tree clean

import math

import numpy as np

from foamcase.checking import Checker
from foamcase import roughWallOracle as rwo

KS_SAMPLES = 200_000
KS_LEVEL = 1e-3


def ks_against_quadrature(gamma, alpha, Delta, truncate=True):
    return rwo.kolmogorov_smirnov(
        gamma, lambda x: rwo.facet_tilt_cdf(x, alpha, Delta, truncate))


def closed_form_moments(alpha, Delta):
    """(1.4) and the corrected (1.6)."""
    A = alpha/(math.sqrt(2)*Delta)
    mean = alpha*math.erfc(A)/math.erf(A)
    m2 = Delta**2*(1 + (2/math.sqrt(math.pi)*A*math.exp(-A*A)
                        - 4*A*A*math.erfc(A))/math.erf(A))
    return mean, math.sqrt(m2 - mean*mean)


def overhang_closed_form(alpha, Delta):
    """Mass of N(0,1) on [g, g + 2h] / erf(h/sqrt 2), g = (pi/2)/Delta."""
    g, h = rwo.HALF_PI/Delta, alpha/Delta
    s2 = math.sqrt(2)
    return 0.5*(math.erfc(g/s2) - math.erfc((g + 2*h)/s2))/math.erf(h/s2)


def main():
    c = Checker("oracle.sampler: facet tilt sampler vs quadrature of (1.3)")
    rad = math.radians

    # normalisation of (1.3) by quadrature
    for Dd, h in [(8, 0.05), (8, 1.0), (8, 11.25), (45, 0.05), (45, 2.0),
                  (2, 20.0)]:
        D = rad(Dd)
        mass = rwo.facet_tilt_mass(h*D, D)
        c.within(f"normalised Delta={Dd} h={h}", mass, 1.0, 1e-10)

    # alpha = 0: Rayleigh
    D = rad(8)
    x = np.linspace(0, 6*D, 50)
    c.within("alpha=0 cdf is Rayleigh",
             float(np.max(np.abs(rwo.facet_tilt_cdf(x, 0.0, D)
                                 - (1 - np.exp(-x*x/(2*D*D)))))), 0.0, 1e-10)

    # the rejection bound of the Rayleigh proposal
    xg = np.linspace(0, 60, 6001)[:, None]
    hg = np.linspace(0, rwo.H_SPLIT, 241)[None, :]
    y = xg*hg
    ratio = np.exp(-0.25*xg*xg)*np.where(y > 0, np.sinh(y)/np.where(y > 0, y, 1), 1)
    c.check("Rayleigh proposal bound", float(ratio.max()) <= 1 + 1e-12,
            f"max exp(-x^2/4) sinh(xh)/(xh) = {ratio.max():.15f} for h <= "
            f"{rwo.H_SPLIT}")

    # KS and moments
    cases = [(8, 0.0), (8, 0.05), (8, 0.2), (8, 0.5), (8, 1.0), (8, 1.19),
             (8, 1.21), (8, 2.0), (8, 5.0), (8, 11.25),
             (2, 20.0), (0.5, 20.0),
             (45, 0.05), (45, 0.5), (45, 1.0), (45, 1.5), (45, 2.0)]
    for seed, (Dd, h) in enumerate(cases, start=100):
        D = rad(Dd)
        alpha = h*D
        rng = np.random.default_rng(seed)
        g = rwo.sample_facet_tilt(np.full(KS_SAMPLES, alpha), D, rng)
        Dks, p = ks_against_quadrature(g, alpha, D)
        c.check(f"KS Delta={Dd} alpha/Delta={h}", p > KS_LEVEL,
                f"D = {Dks:.5f}, p = {p:.4f} (> {KS_LEVEL})")
        if Dd == 45:
            mean, sd = rwo.facet_tilt_moments(alpha, D, truncate=True)
        elif h == 0:
            mean, sd = math.sqrt(math.pi/2)*D, D*math.sqrt(2 - math.pi/2)
        else:
            mean, sd = closed_form_moments(alpha, D)
        n = g.size
        m2 = np.mean((g - g.mean())**2)
        m4 = np.mean((g - g.mean())**4)
        c.within_se(f"mean gamma Delta={Dd} alpha/Delta={h}", float(g.mean()),
                    mean, sd/math.sqrt(n))
        c.within_se(f"sd gamma Delta={Dd} alpha/Delta={h}", float(g.std()),
                    sd, math.sqrt((m4 - m2*m2)/n)/(2*math.sqrt(m2)))

    # Delta = 0: a smooth wall
    g0 = rwo.sample_facet_tilt(np.full(10, 0.3), 0.0, np.random.default_rng(1))
    c.check("Delta=0 gives gamma=0", bool(np.all(g0 == 0)), "")

    # overhangs at Delta = 45 deg
    D = rad(45)
    grazing = rwo.overhang_fraction(0.0, D)
    c.within("overhang Delta=45 grazing = e^-2", grazing, math.exp(-2), 1e-9)
    c.within("overhang Delta=45 grazing ~ 13.5 %", 100*grazing, 13.5, 0.05, " %")
    for ad in [1e-3, 5, 20, 45, 90]:
        q = rwo.overhang_fraction(rad(ad), D)
        c.within(f"overhang Delta=45 alpha={ad} quadrature vs erfc", q,
                 overhang_closed_form(rad(ad), D), 1e-9)
    at20 = rwo.overhang_fraction(rad(20), D)
    c.within("overhang Delta=45 alpha=20 ~ 6.1 %", 100*at20, 6.1, 0.05, " %")
    for seed, ad in [(7, 0.0), (8, 20.0)]:
        rng = np.random.default_rng(seed)
        n = 400_000
        g = rwo.sample_facet_tilt(np.full(n, rad(ad)), D, rng, truncate=False)
        frac = float(np.mean(g >= rwo.HALF_PI))
        q = rwo.overhang_fraction(rad(ad), D)
        c.within_se(f"sampled overhang fraction Delta=45 alpha={ad}", frac, q,
                    math.sqrt(q*(1 - q)/n))
        gt = rwo.sample_facet_tilt(np.full(n, rad(ad)), D, rng, truncate=True)
        c.check(f"truncated sampler below pi/2, alpha={ad}",
                bool(gt.max() < rwo.HALF_PI), f"max {math.degrees(gt.max()):.4f} deg")

    # negative controls: the test must reject wrong samplers
    rng = np.random.default_rng(11)
    D = rad(8)
    alpha = 0.5*D
    z = D*rwo.standard_normal(rng, 4*KS_SAMPLES)
    unshadowed = z[z > -alpha][:KS_SAMPLES]
    Dks, p = ks_against_quadrature(unshadowed, alpha, D)
    c.check("KS rejects a sampler without shadow correction", p < KS_LEVEL,
            f"D = {Dks:.4f}, p = {p:.3g}")
    alpha = 2*D
    wide = rwo.sample_facet_tilt(np.full(KS_SAMPLES, alpha), 1.03*D, rng)
    Dks, p = ks_against_quadrature(wide, alpha, D)
    c.check("KS rejects Delta 3 % too large", p < KS_LEVEL,
            f"D = {Dks:.4f}, p = {p:.3g}")
    D = rad(45)
    alpha = 0.05*D
    untr = rwo.sample_facet_tilt(np.full(KS_SAMPLES, alpha), D, rng,
                                 truncate=False)
    Dks, p = ks_against_quadrature(untr, alpha, D)
    c.check("KS rejects an untruncated sampler at Delta=45", p < KS_LEVEL,
            f"D = {Dks:.4f}, p = {p:.3g}")

    c.finish()


if __name__ == "__main__":
    main()
