#!/usr/bin/python3
"""Reference values for Carlson's R-functions (src/carlson.c), from mpmath.

Writes
  spec/data/carlson_checks.tsv  the real-argument check values published in
      B. C. Carlson, "Numerical computation of real or complex elliptic
      integrals", Numer. Algorithms 10 (1995), arXiv math/9409227, Sec. 3
      (column 'published', 14 digits as printed there), each with its
      mpmath value (column 'ref').  The paper's complex-argument checks are
      outside arclen's real-argument API.
  spec/data/carlson.tsv  random argument sets, log-uniform over
      [1e-10, 1e10], 10% with one zero argument (where the integral stays
      finite), plus Cauchy principal values (R_C with y < 0: the real part
      of mpmath's elliprc; R_J with p < 0: quadrature, see rj_pv_quad).
      Column lo: ref - double(ref); cond: the condition of the
      principal-value reduction (1 elsewhere).

Run with Debian's python3-mpmath:  /usr/bin/python3 tools/ref_carlson.py
"""
import random
import mpmath as mp

mp.mp.dps = 40
N = 2000          # random sets per function
NPV = 300         # principal-value sets per function
FN = {"rf": mp.elliprf, "rd": mp.elliprd, "rc": mp.elliprc,
      "rj": mp.elliprj, "rg": mp.elliprg}
NARGS = {"rf": 3, "rd": 3, "rc": 2, "rj": 4, "rg": 3}
# Argument positions that may be zero with a finite integral.
ZERO_OK = {"rf": [0, 1, 2], "rd": [0, 1], "rc": [0], "rj": [0, 1, 2],
           "rg": [0, 1, 2]}

# Carlson (1995), Sec. 3: the check values with real arguments.
CHECKS = [
    ("rf", (1, 2, 0), "1.3110287771461"),
    ("rf", (0.5, 1, 0), "1.8540746773014"),
    ("rf", (2, 3, 4), "0.58408284167715"),
    ("rc", (0, 0.25), "3.1415926535898"),
    ("rc", (2.25, 2), "0.69314718055995"),
    ("rc", (0.25, -2), "0.23104906018665"),
    ("rj", (0, 1, 2, 3), "0.77688623778582"),
    ("rj", (2, 3, 4, 5), "0.14297579667157"),
    ("rj", (2, 3, 4, -0.5), "0.24723819703052"),
    ("rj", (2, 3, 4, -5), "-0.12711230042964"),
    ("rd", (0, 2, 1), "1.7972103521034"),
    ("rd", (2, 3, 4), "0.16510527294261"),
    ("rg", (0, 16, 16), "3.1415926535898"),
    ("rg", (2, 3, 4), "1.7255030280692"),
    ("rg", (0, 0.0796, 4), "1.0284758090288"),
]


def rj_pv_quad(x, y, z, p):
    """R_J principal value (p < 0) by direct quadrature of its definition,
    R_J = 3/2 PV int_0^inf dt / ((t + p) sqrt((t+x)(t+y)(t+z))), with the
    pole at q = -p removed by subtracting g(q) on [0, 2q].  Used instead of
    mpmath's elliprj, whose real part is off by up to 1e-7 relative when an
    argument is zero or tiny (x = 0, y = 6e6, z = 7e4, p = -7e-9: elliprj
    -1.850848280561e-08, quadrature and DLMF 19.20.14 -1.850848279791e-08)."""
    x, y, z, q = mp.mpf(x), mp.mpf(y), mp.mpf(z), -mp.mpf(p)
    g = lambda t: 1 / mp.sqrt((t + x) * (t + y) * (t + z))
    gq = g(q)
    pts = sorted(set([mp.mpf(0), q, 2 * q] + [v for v in (x, y, z) if v > 2 * q]))
    a = mp.quad(lambda t: (g(t) - gq) / (t - q), [0, q, 2 * q])
    b = mp.quad(lambda t: g(t) / (t - q), pts[pts.index(2 * q):] + [mp.inf])
    return 1.5 * (a + b)


def ref(fn, args):
    if fn == "rj" and args[3] < 0:
        return rj_pv_quad(*args)
    v = FN[fn](*[mp.mpf(a) for a in args])
    return mp.re(v)          # principal value for R_C(y < 0)


def pv_cond(fn, args):
    """Condition of the principal-value reduction (DLMF 19.20.14, as in
    src/carlson.c): sum of the magnitudes of its terms over the magnitude
    of the result.  Rounding errors of a few eps in each term become
    cond * eps in the result; the spec allows 4 eps * cond."""
    a = [mp.mpf(v) for v in args]
    if fn == "rc":
        return mp.mpf(1)
    x, y, z = sorted(a[:3])
    q = -a[3]
    t = (z - x) * (z - y) / (z + q)
    r = z - t
    terms = abs(t * mp.elliprj(x, y, z, r)) + 3 * mp.elliprf(x, y, z)
    if x > 0:
        terms += abs(3 * mp.sqrt(x * y * z / (x * y + r * q))
                     * mp.elliprc(x * y + r * q, r * q))
    return terms / abs((z + q) * rj_pv_quad(x, y, z, -q))


def fmt(v):
    """30 digits, then a tab and the rounding residual v - double(v), so a
    spec measures got - v as (got - hi) - lo without the reference's own
    half-ulp rounding."""
    hi = float(v)
    return "%s\t%r" % (mp.nstr(v, 30, min_fixed=-5, max_fixed=5),
                        float(v - mp.mpf(hi)))


def loguni(rng):
    return 10.0 ** rng.uniform(-10, 10)


def main():
    rng = random.Random(20261121)
    with open("spec/data/carlson_checks.tsv", "w") as f:
        f.write("fn\tx\ty\tz\tp\tpublished\tref\tlo\n")
        for fn, args, pub in CHECKS:
            a = list(args) + [""] * (4 - len(args))
            f.write("%s\t%s\t%s\t%s\t%s\t%s\t%s\n" % (
                fn, *[repr(float(v)) if v != "" else "" for v in a], pub,
                fmt(ref(fn, args))))
    with open("spec/data/carlson.tsv", "w") as f:
        f.write("fn\tkind\tx\ty\tz\tp\tref\tlo\tcond\n")
        for fn in ("rf", "rd", "rc", "rj", "rg"):
            n = NARGS[fn]
            for i in range(N):
                args = [loguni(rng) for _ in range(n)]
                kind = "random"
                if i % 10 == 0:
                    args[rng.choice(ZERO_OK[fn])] = 0.0
                    kind = "zero"
                a = args + [""] * (4 - n)
                f.write("%s\t%s\t%s\t%s\t%s\t%s\t%s\t1\n" % (
                    fn, kind, *[repr(v) if v != "" else "" for v in a],
                    fmt(ref(fn, args))))
            if fn in ("rc", "rj"):
                for i in range(NPV):
                    args = [loguni(rng) for _ in range(n)]
                    args[-1] = -args[-1]
                    if i % 10 == 0:
                        args[rng.choice(ZERO_OK[fn])] = 0.0
                    a = args + [""] * (4 - n)
                    f.write("%s\tpv\t%s\t%s\t%s\t%s\t%s\t%s\n" % (
                        fn, *[repr(v) if v != "" else "" for v in a],
                        fmt(ref(fn, args)),
                        mp.nstr(pv_cond(fn, args), 6)))


if __name__ == "__main__":
    main()
