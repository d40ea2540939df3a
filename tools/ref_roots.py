#!/usr/bin/python3
"""Reference roots for the polynomial solvers (src/roots.c), from mpmath.

Writes spec/data/roots.tsv: one polynomial per line, its coefficients as
doubles (highest first), the 30-digit roots of THAT double polynomial (not of
the ideal one: the coefficients' rounding is part of the problem), and per
root the accuracy attainable after rounding the coefficients to double: the
largest root displacement over 16 random relative perturbations of the
coefficients by up to 2^-53, times 4, plus 4 ulp of the root.

Test sets:
 - Flocke (2015), ACM TOMS Algorithm 954, quartic test cases given by their
   roots (widely spread magnitudes, clusters, close complex pairs) and two
   given by their coefficients (cases 17, 18);
 - Flocke's two cubic cases (1, 1e7, 1e14) and (1, 1.000001, 1.000002);
 - multiple roots: (x-1)^4, (x-1)^2 (x-2)^2, (x-1)^3 (x+2), (x^2+1)^2, ...;
 - in place of Algorithm 1010's (Orellana & De Michele 2020) Table 1, whose
   24 polynomials we could not obtain here, an equivalent hard set built the
   same way: clustered roots 1 +- 1e-k, magnitudes 1e-k..1e+k, complex pairs
   near the real axis and near each other, with mpmath truths.
 - hostile coefficients (a subnormal leading one, +-1e308 in the middle)
   and root groups spread up to 2^1330 apart, some roots beyond the double
   range (the spec expects those as +-inf): exact roots by sympy, bounds by
   the roots' condition numbers (see condition_bounds).
Run: /usr/bin/python3 tools/ref_roots.py
"""
import random
from fractions import Fraction
import mpmath as mp
import sympy as sp

mp.mp.dps = 60
S2 = mp.sqrt(2)

def c(re, im=0):
    return mp.mpc(mp.mpf(re), mp.mpf(im))

def pair(re, im):
    return [c(re, im), c(re, -mp.mpf(im))]

CASES = []   # (id, roots or None, coefficients or None)

# Flocke, Algorithm 954, quartics by their roots
CASES += [
    ("flocke-q1", [c("1e9"), c("1e6"), c("1e3"), c(1)], None),
    ("flocke-q2", [c("1.003"), c("1.002"), c("1.001"), c("1.000")], None),
    ("flocke-q4", [c("1e14"), c(2), c(1), c(-1)], None),
    ("flocke-q5", [c("1e7"), c(1), c(-1), c("-2e7")], None),
    ("flocke-q6", [c("1e7"), c("-1e6")] + pair(1, 1), None),
    ("flocke-q7", [c(-4), c(-7)] + pair("-1e6", "1e5"), None),
    ("flocke-q8", pair("1e3", 1) + [c(11), c("1e8")], None),
    ("flocke-q9", pair("1e7", "1e6") + pair(1, 2), None),
    ("flocke-q10", pair("1e4", 3) + pair(-7, "1e3"), None),
    ("flocke-q11", pair("1.002", "4.998") + pair("1.001", "5.001"), None),
    ("flocke-q12", pair("1e3", 3) + pair("1e3", 1), None),
    ("flocke-q13", pair(2, "1e4") + pair(1, "1e3"), None),
    ("flocke-q15", [c(0), c(S2), c(S2), c(S2)], None),
    ("flocke-q16", [c(-S2), c(-S2), c(-S2), c(0)], None),
    ("flocke-q17", None, [0.000158925, -0.00657522, 0.0801029, -0.2, 0.01]),
    ("flocke-q18", None, [2.25, 36, 113.698199211166496525038382969796657562255859375,
                          -242.41440631066808464311179704964160919189453125,
                          102.0221256717945692571447580121457576751708984375]),
    ("flocke-c1", [c(1), c("1e7"), c("1e14")], None),
    ("flocke-c2", [c(1), c("1.000001"), c("1.000002")], None),
]
# multiple roots
CASES += [
    ("mult-(x-1)^4", [c(1)] * 4, None),
    ("mult-(x-1)^2(x-2)^2", [c(1), c(1), c(2), c(2)], None),
    ("mult-(x-1)^3(x+2)", [c(1)] * 3 + [c(-2)], None),
    ("mult-(x^2+1)^2", pair(0, 1) * 2, None),
    ("mult-(x-1)^2(x^2+1)", [c(1), c(1)] + pair(0, 1), None),
    ("mult-(x-3)^3", [c(3)] * 3, None),
    ("mult-(x-5)^2", [c(5)] * 2, None),
]
# hard set in the manner of Algorithm 1010's Table 1
for k in (2, 4, 6, 8):
    e = mp.mpf(10) ** -k
    CASES.append(("hard-cluster-1e-%d" % k, [c(1 - e), c(1), c(1 + e), c(1 + 2 * e)], None))
    CASES.append(("hard-cpair-near-axis-1e-%d" % k, pair(1, e) + pair(2, e), None))
    CASES.append(("hard-cpairs-close-1e-%d" % k, pair(1, 1) + pair(1 + e, 1 + e), None))
for k in (3, 6, 9):
    s = mp.mpf(10) ** k
    CASES.append(("hard-spread-1e%d" % k, [c(1 / s), c(1), c(s), c(-s * s)], None))
    CASES.append(("hard-spread-complex-1e%d" % k, pair(1 / s, 1 / s) + pair(s, s), None))
# hostile: coefficients at the ends of the double range (the monic
# normalisation a_k / a_n overflowed: NaN roots) and root groups spread
# beyond one scaled solve (Newton polygon split in roots.c); roots beyond
# the double range are written as they are (> 1.8e308) and expected as inf
HOSTILE = [
    ("hostile-subnormal-lead-cubic", None, [5e-324, -6.0, 11.0, -6.0]),
    ("hostile-subnormal-lead-quartic", None, [5e-324, 0.0, -5.0, 0.0, 4.0]),
    ("hostile-subnormal-lead-quartic2", None, [5e-324, 1.0, -6.0, 11.0, -6.0]),
    ("hostile-1e308-a2-cubic", None, [1.0, 1e308, 11.0, -6.0]),
    ("hostile--1e308-a2-cubic", None, [1.0, -1e308, 11.0, -6.0]),
    ("hostile-1e308-a1-cubic", None, [1.0, -6.0, 1e308, -6.0]),
    ("hostile-1e308-a3-quartic", None, [1.0, 1e308, -5.0, 0.0, 4.0]),
    ("hostile-1e308-a2-quartic", None, [1.0, 0.0, 1e308, 0.0, 4.0]),
    ("hostile--1e308-a2-quartic", None, [1.0, 0.0, -1e308, 0.0, 4.0]),
    ("hostile-overflowing-pair", None, [5e-324, 0.0, 1e308, 0.0, 4.0]),
    ("hostile-overflowing-real-pair", None, [5e-324, 0.0, -1e308, 1.0, 4.0]),
    ("spread-cubic-1e200", [c("1e-200"), c(1), c("1e200")], None),
    ("spread-quartic-1e100", [c("1e-100"), c(1), c("1e100"), c("1e200")], None),
    ("spread-complex-1e100", pair("1e-100", "1e-100") + pair("1e100", "3e100"), None),
    ("spread-mixed-1e150", [c("-1e-150"), c("2e-150")] + pair("1e150", "1e140"), None),
]
for k in (30, 45, 60, 90):
    s = mp.mpf(10) ** k
    HOSTILE.append(("spread-cubic-1e%d" % k, [c(1 / s), c(-1), c(s)], None))
    HOSTILE.append(("spread-quartic-1e%d" % k, [c(-1 / s), c(1), c(s), c(-s * s)], None))
CASES.append(("quad-1e8-1e-8", [c("1e8"), c("1e-8")], None))
CASES.append(("quad-complex", pair(3, "1e-7"), None))
CASES.append(("quad-near-double", [c(1), c("1.0000001")], None))


def coeffs_from_roots(roots):
    p = [mp.mpc(1)]
    for r in roots:
        q = [mp.mpc(0)] * (len(p) + 1)
        for i, a in enumerate(p):
            q[i] += a
            q[i + 1] -= a * r
        p = q
    return [float(mp.re(a)) for a in p]


def roots_of(coeffs):
    cf = [mp.mpf(a) for a in coeffs]  # exact: doubles are rationals
    while cf and cf[0] == 0:
        cf = cf[1:]
    return mp.polyroots(cf, maxsteps=4000, extraprec=3000)


def exact_roots_of(coeffs):
    """the roots of the double polynomial as exact algebraic numbers (sympy
    CRootOf: isolating intervals on the rational coefficients), to 30 digits
    RELATIVE to each root: mpmath's polyroots stops on an absolute error,
    which loses the small roots of a polynomial whose roots spread over
    2^600 and more"""
    x = sp.symbols("x")
    cf = [sp.Rational(Fraction(a).numerator, Fraction(a).denominator) for a in coeffs]
    while cf and cf[0] == 0:
        cf = cf[1:]
    out = []
    for r in sp.Poly(cf, x).all_roots():
        v = sp.N(r, 40, maxn=8000)
        re, im = v.as_real_imag()
        out.append(mp.mpc(mp.mpf(str(sp.N(re, 40, maxn=8000))),
                          mp.mpf(str(sp.N(im, 40, maxn=8000)))))
    return out


def condition_bounds(coeffs, truth):
    """the first-order displacement of each simple root when every
    coefficient moves by up to 2^-53 relatively (Wilkinson's condition
    number sum |a_k| |r|^k / |p'(r)|), times 4, plus 4 ulp of the root: the
    perturbation experiment's bound, without the perturbed solves that
    CRootOf makes slow"""
    cf = [mp.mpf(a) for a in coeffs]
    n = len(cf) - 1
    out = []
    for r in truth:
        s = sum(abs(a) * abs(r) ** (n - k) for k, a in enumerate(cf))
        dp = sum((n - k) * a * r ** (n - k - 1) for k, a in enumerate(cf[:-1]))
        out.append(4 * 2.0 ** -53 * s / abs(dp) + 4 * 2.0 ** -52 * abs(r))
    return out


def match(ref, got):
    """displacement of each ref root to its nearest unmatched got root"""
    left = list(got)
    out = []
    for r in ref:
        j = min(range(len(left)), key=lambda i: abs(left[i] - r))
        out.append(abs(left[j] - r))
        left.pop(j)
    return out


def main():
    rng = random.Random(954)
    with open("spec/data/roots.tsv", "w") as f:
        f.write("id\tdeg\ta4\ta3\ta2\ta1\ta0\troots\tbounds\n")
        for cid, roots, coeffs in CASES:
            if coeffs is None:
                coeffs = coeffs_from_roots(roots)
            deg = len(coeffs) - 1
            truth = roots_of(coeffs)
            worst = [mp.mpf(0)] * len(truth)
            for _ in range(16):
                pert = [a * (1 + rng.uniform(-1, 1) * 2.0 ** -53) for a in
                        [mp.mpf(v) for v in coeffs]]
                d = match(truth, roots_of(pert))
                worst = [max(w, x) for w, x in zip(worst, d)]
            bounds = [4 * w + 4 * 2.0 ** -52 * abs(r) for w, r in zip(worst, truth)]
            write_row(f, cid, coeffs, truth, bounds)
        for cid, roots, coeffs in HOSTILE:
            if coeffs is None:
                coeffs = coeffs_from_roots(roots)
            truth = exact_roots_of(coeffs)
            write_row(f, cid, coeffs, truth, condition_bounds(coeffs, truth))


def write_row(f, cid, coeffs, truth, bounds):
    deg = len(coeffs) - 1
    cols = [""] * (4 - deg) + [repr(float(v)) for v in coeffs]
    f.write("%s\t%d\t%s\t%s\t%s\n" % (
        cid, deg, "\t".join(cols),
        ";".join("%s,%s" % (mp.nstr(mp.re(r), 30), mp.nstr(mp.im(r), 30))
                 for r in truth),
        ";".join(mp.nstr(b, 6) for b in bounds)))


if __name__ == "__main__":
    main()
