#!/usr/bin/python3
"""Reference values for Carlson's R-functions at extreme argument ratios:
one argument from 1e-300 to 1e300 with the others O(1), and the others
extreme with one O(1).  Writes spec/data/carlson_extreme.tsv in the format
of spec/data/carlson.tsv (fn kind x y z p ref lo cond), kind = "extreme"
or "pv" (R_J with p < 0, R_C with y < 0).

mpmath's elliprj is wrong at such ratios (elliprj(1, 2, 3, 1e-300) at 50
digits gives 160.9; the integral is 422.96, about 3/2 log(1/p) / sqrt(6)),
so every value with an integral definition (DLMF 19.16.1-19.16.5, 19.16.3
for R_G) is computed by quadrature; the mpmath
function, where it agrees, is a second check (a warning on stderr when it
does not).  The quadrature runs over u = log t (logquad), where the
integrand is smooth at every scale.  R_C's principal value: mpmath's
closed form.

Run with Debian's python3-mpmath:  /usr/bin/python3 tools/ref_carlson_extreme.py
"""
import os
import random
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ref_carlson import fmt  # noqa: E402  (30 digits + residual)

mp.mp.dps = 40
EXT = [1e300, 1e200, 2.0 ** 500, 1e100, 1e50, 1e20,
       1e-20, 1e-50, 1e-100, 2.0 ** -500, 1e-200, 1e-300]


def logquad(f, lo, hi, vals):
    """int_lo^hi f(t) dt (0 <= lo < hi <= inf) as int f(e^u) e^u du: over
    u the integrand is smooth, bending only near log of each argument, so
    cuts there and every 4 units around them keep every scale."""
    logs = [mp.log(mp.mpf(v)) for v in vals if v > 0]
    ulo = mp.log(lo) if lo > 0 else -mp.inf
    uhi = mp.log(hi) if hi < mp.inf else mp.inf
    grid = set(logs)
    u = min(logs) - 80
    while u < max(logs) + 160:
        grid.add(u)
        u += 4
    pts = [ulo] + sorted(g for g in grid if ulo < g < uhi) + [uhi]
    return sum(scaled_quad(lambda u: f(mp.exp(u)) * mp.exp(u), a, b)
               for a, b in zip(pts, pts[1:]))


def scaled_quad(h, a, b):
    """int_a^b h: mp.quad stops on an absolute error of eps, so 1e-169
    came out with 5e-5 relative error: h is divided by its size first."""
    m = (a + b) / 2 if a > -mp.inf and b < mp.inf else (
        b - 1 if b < mp.inf else a + 1)
    s = abs(h(m))
    if s == 0:
        s = mp.mpf(1)
    return s * mp.quad(lambda u: h(u) / s, [a, b])


def quad(f, vals):
    return logquad(f, 0, mp.inf, vals)


def s3(t, x, y, z):
    return mp.sqrt((t + x) * (t + y) * (t + z))


def rf(x, y, z):
    return quad(lambda t: 1 / s3(t, x, y, z), [x, y, z]) / 2


def rd(x, y, z):
    return quad(lambda t: 1 / ((t + z) * s3(t, x, y, z)), [x, y, z]) * 3 / 2


def rj(x, y, z, p):
    return quad(lambda t: 1 / ((t + p) * s3(t, x, y, z)), [x, y, z, p]) * 3 / 2


def rc(x, y):
    return quad(lambda t: 1 / ((t + y) * mp.sqrt(t + x)), [x, y]) / 2


def rg(x, y, z):
    # DLMF 19.16.3: R_G = 1/4 int t / s(t) (x/(t+x) + y/(t+y) + z/(t+z)) dt
    return quad(lambda t: t / s3(t, x, y, z) * (x / (t + x) + y / (t + y)
                + z / (t + z)), [x, y, z]) / 4


def rj_pv(x, y, z, p):
    """PV of R_J's integral (pole at q = -p): g/(t - q) on [0, q/2] and
    [3q/2, inf) by logquad, (g - g(q))/(t - q) on [q/2, 3q/2] (the
    subtracted g(q)/(t - q) has principal value 0 there, by symmetry)."""
    q = -p
    g = lambda t: 1 / s3(t, x, y, z)
    gq = g(q)
    vals = [x, y, z, q]
    a = logquad(lambda t: g(t) / (t - q), 0, q / 2, vals)
    b = (scaled_quad(lambda t: (g(t) - gq) / (t - q), q / 2, q)
         + scaled_quad(lambda t: (g(t) - gq) / (t - q), q, 3 * q / 2))
    c = logquad(lambda t: g(t) / (t - q), 3 * q / 2, mp.inf, vals)
    return 1.5 * (a + b + c)


QUAD = {"rf": rf, "rd": rd, "rj": rj, "rc": rc, "rg": rg}
MPF = {"rf": mp.elliprf, "rd": mp.elliprd, "rc": mp.elliprc,
       "rj": mp.elliprj, "rg": mp.elliprg}


def pv_cond(x, y, z, p):
    """The condition of src/carlson.c's reduction (DLMF 19.20.14), as in
    tools/ref_carlson.py, with quadrature for every R_J."""
    x, y, z = sorted([x, y, z])
    q = -p
    t = (z - x) * (z - y) / (z + q)
    r = z - t
    terms = abs(t * rj(x, y, z, r)) + 3 * rf(x, y, z)
    if x > 0:
        terms += abs(3 * mp.sqrt(x * y * z / (x * y + r * q))
                     * mp.elliprc(x * y + r * q, r * q))
    return terms / abs((z + q) * rj_pv(x, y, z, p))


def reference(fn, args):
    a = [mp.mpf(v) for v in args]
    if fn == "rc" and a[1] < 0:
        return mp.re(mp.elliprc(*a)), "pv", mp.mpf(1)
    if fn == "rj" and a[3] < 0:
        return rj_pv(*a), "pv", pv_cond(*a)
    v = QUAD[fn](*a)
    try:
        w = MPF[fn](*a)
        if abs(w - v) > mp.mpf("1e-25") * abs(v):
            sys.stderr.write("mpmath %s%r: %s, quadrature %s\n" % (
                fn, tuple(args), mp.nstr(w, 15), mp.nstr(v, 15)))
    except (ZeroDivisionError, ValueError):
        pass
    return v, "extreme", mp.mpf(1)


def cases(rng):
    """(fn, args): one extreme argument among O(1) ones, and vice versa."""
    out = []
    for e in EXT:
        o = [rng.uniform(0.5, 4) for _ in range(4)]
        for i in range(3):
            a = o[:3]
            a[i] = e
            out.append(("rf", a))
            out.append(("rg", a))
            out.append(("rd", a))
            out.append(("rj", a + [o[3]]))
        out.append(("rd", [e, e * o[1], o[2]]))           # z alone O(1)
        out.append(("rf", [e, e * o[1], o[2]]))
        out.append(("rj", o[:3] + [e]))                  # p extreme
        out.append(("rj", o[:3] + [-e]))
        out.append(("rj", [e * o[0], e * o[1], e * o[2], o[3]]))
        out.append(("rj", [e * o[0], e * o[1], e * o[2], -o[3]]))
        out.append(("rc", [e, o[0]]))
        out.append(("rc", [o[0], e]))
        out.append(("rc", [o[0], -e]))
    out.append(("rj", [1.0, 2.0, 3.0, 2.0 ** 500]))      # a large p
    out.append(("rj", [1.0, 2.0, 3.0, 1e300]))
    return out


def main():
    rng = random.Random(20261122)
    with open("spec/data/carlson_extreme.tsv", "w") as f:
        f.write("fn\tkind\tx\ty\tz\tp\tref\tlo\tcond\n")
        for fn, args in cases(rng):
            v, kind, cond = reference(fn, args)
            a = [repr(float(x)) for x in args] + [""] * (4 - len(args))
            f.write("%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" % (
                fn, kind, *a, fmt(v), mp.nstr(cond, 6)))


if __name__ == "__main__":
    main()
