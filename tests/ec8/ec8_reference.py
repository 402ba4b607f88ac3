#!/usr/bin/env python3
"""Reference values of DEFI_PRES_EC8 for tests/ec8/defi_pres_ec8.comm, computed here
independently of parasol from the formulas of Eurocode 8-4 annex A as Code_Aster's
DEFI_PRES_EC8 (U4.44.31) applies them: scipy's modified Bessel functions (iv, ivp), J1 (jv)
and its adaptive quadrature for the flexible impulsive mode's integrals over the height
(parasol forms them in closed form, with its own series for I0 and I1).

    ec8_reference.py            prints each case's value (17 digits)
    ec8_reference.py --check D  checks that the VALE_REFE of deck D marked '# ec8ref' are
                                these values, in order, within 1e-11 relative
"""
import math
import re
import sys

from scipy import integrate, special

R, H, RHO = 4.820, 9.250, 1000.0
G = 9.81
EP, RHO_S = 0.006, 7800.0


def lam(n):
    return (2 * n + 1) * math.pi / (2.0 * H)


def pressure(x, y, z, arh=0.0, afhn=0.0, afv=0.0, arv=0.0, ac1=0.0, g=0.0, p0=0.0,
             newmark=0.4, z0=0.0, ep=EP, rho_s=RHO_S):
    """The total pressure, z the global coordinate."""
    if z - z0 > H:
        return p0
    z = z - z0
    r = math.hypot(x, y)
    cos_t = x / r if r * r > 1e-6 else 1.0
    # rigid impulsive, 21 terms
    c0 = sum(8.0 / math.pi ** 2 * (-1) ** n / (2 * n + 1) ** 2
             * special.iv(1, lam(n) * r) / special.ivp(1, lam(n) * R) * math.cos(lam(n) * z)
             for n in range(21))
    pir = c0 * RHO * arh * H * cos_t
    # flexible impulsive, 2 terms; psi as the ratio of two integrals over the height
    f = lambda s: math.sin(math.pi * s / (2.0 * H))
    ratio = lambda n: special.iv(1, lam(n) * R) / special.ivp(1, lam(n) * R)
    d = [4.0 / math.pi * integrate.quad(lambda s: f(s) * math.cos(lam(n) * s), 0, H,
                                        epsabs=0.0, epsrel=1e-13, limit=200)[0]
         * ratio(n) / (2 * n + 1) / H for n in range(2)]
    b = [8.0 / math.pi ** 2 * (-1) ** n * ratio(n) / (2 * n + 1) ** 2 for n in range(2)]
    m = rho_s * ep / RHO / H
    num = integrate.quad(lambda s: f(s) * (m + sum(b[n] * math.cos(lam(n) * s)
                                                   for n in range(2))), 0, H,
                         epsabs=0.0, epsrel=1e-13, limit=200)[0]
    den = integrate.quad(lambda s: f(s) * (m * f(s) + sum(d[n] * math.cos(lam(n) * s)
                                                          for n in range(2))), 0, H,
                         epsabs=0.0, epsrel=1e-13, limit=200)[0]
    psi = num / den
    pif = (r / R * cos_t * RHO * H * psi * (afhn - arh)
           * sum(d[n] * math.cos(lam(n) * z) for n in range(2)))
    # convective, first mode
    pc1 = (0.8371 * RHO * R * math.cosh(1.841 * z / R) / math.cosh(1.841 * H / R)
           * special.jv(1, 1.841 * r / R) / special.jv(1, 1.841) * ac1 * cos_t)
    prv = RHO * arv * (H - z)
    f2 = 1.078 + 0.274 * math.log(H / R) if H / R > 0.8 else 1.0
    pfv = 0.815 * f2 * H * RHO * math.cos(math.pi * z / (2.0 * H)) * (afv - arv)
    horizontal = math.copysign(math.hypot(pir + pif, pc1), cos_t)
    return horizontal + newmark * (prv + pfv) + p0 + RHO * g * (H - z)


A = 2.5          # the acceleration of the one-part cases
S30 = math.sqrt(3.0) / 2.0
# the sslv305c earthquake
FULL = dict(arh=0.241 * G, afhn=0.51252007 * G, afv=0.33572503 * G, arv=0.1606700 * G,
            ac1=0.085 * G, g=G)

CASES = [
    # rigid impulsive alone (A_fhn = A_rh, so that p_if = 0): bottom, middle, at 30 deg,
    # at 180 deg (opposite sign), inside the tank
    ((R, 0.0, 0.0), dict(arh=A, afhn=A)),
    ((R, 0.0, H / 2), dict(arh=A, afhn=A)),
    ((R * S30, R / 2, 0.0), dict(arh=A, afhn=A)),
    ((-R, 0.0, 0.0), dict(arh=A, afhn=A)),
    ((R / 2, 0.0, 1.0), dict(arh=A, afhn=A)),
    # convective alone: bottom, free surface, inside
    ((R, 0.0, 0.0), dict(ac1=A)),
    ((R, 0.0, H), dict(ac1=A)),
    ((R / 3, R / 3, 2.0), dict(ac1=A)),
    # flexible impulsive alone (A_rh = 0)
    ((R, 0.0, 0.0), dict(afhn=A)),
    ((R, 0.0, 3.0), dict(afhn=A)),
    # flexible vertical alone (A_rv = 0), PC+
    ((R, 0.0, 0.0), dict(afv=A)),
    ((0.0, R, 4.0), dict(afv=A)),
    # the sslv305c earthquake: wall at 0, 90, 180 deg, bottom centre and near the wall
    ((R, 0.0, 1.0), FULL),
    ((0.0, R, 5.0), FULL),
    ((-R, 0.0, 8.0), FULL),
    ((0.0, 0.0, 0.0), FULL),
    ((R * 0.9, 0.3, 0.0), FULL),
    # EVAL's LIST_R_FOND: rigid impulsive on the bottom at r = R/2 (PIR of the table)
    ((R / 2, 0.0, 0.0), dict(arh=A, afhn=A)),
]


def values():
    return [pressure(*p, **kw) for (p, kw) in CASES]


def main():
    vals = values()
    if len(sys.argv) == 3 and sys.argv[1] == "--check":
        text = open(sys.argv[2], encoding="utf-8").read()
        found = [float(v) for v in re.findall(r"VALE_REFE=([-+0-9.eE]+),\s*# ec8ref", text)]
        if len(found) != len(vals):
            print("FAIL: %d VALE_REFE marked '# ec8ref' in %s, %d cases here"
                  % (len(found), sys.argv[2], len(vals)))
            return 1
        bad = 0
        for k, (a, b) in enumerate(zip(found, vals)):
            if abs(a - b) > 1e-11 * max(abs(b), 1e-300):
                print("FAIL case %d: deck %.17g, reference %.17g" % (k + 1, a, b))
                bad += 1
        print("%d of %d reference values agree" % (len(vals) - bad, len(vals)))
        return 1 if bad else 0
    for k, v in enumerate(vals):
        print("%2d %s %r" % (k + 1, CASES[k][0], v))
    return 0


if __name__ == "__main__":
    sys.exit(main())
