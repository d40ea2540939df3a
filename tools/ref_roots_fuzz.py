#!/usr/bin/python3
"""Reference roots for the quartics that fuzz/fuzz_roots found wrong in
src/roots/roots.c, from exact arithmetic.

Writes spec/data/roots_fuzz.tsv: per quartic (coefficients as doubles,
highest first) the roots of THAT double polynomial to 30 digits relative
to each root (roots_of: mpmath at 1100 digits, as the cases mix subnormal
and 1e9-sized coefficients, whose small roots an absolute error of 1e-60
would lose; sympy's CRootOf takes minutes on such rationals), and per
root the accuracy attainable once the coefficients carry relative errors of
2^-53 (bound_of), so that a near-double root, whose position only
sqrt(eps) fixes, gets a bound of that size.  Each row names what went
wrong before the fix.
Run: /usr/bin/python3 tools/ref_roots_fuzz.py   (about 10 s)
"""
import mpmath as mp

mp.mp.dps = 60
U = mp.mpf(2) ** -53

# (id, coefficients a4..a0, what went wrong)
CASES = [
    ("near-double-complex-pair", [-4.0000000000000009, -4.0, -5.0, -2.0, -1.0],
     "-(2x^2+x+1)^2 rounded: resolvent's double root made complex, garbage roots"),
    ("factor-spread-group2", [5.9371814131736755e-07, -2.9999994062818587,
                              -1.9999994062818587, -0.99999940628185868,
                              5.9371814131736755e-07],
     "degree-2 group taken from its own coefficients: factor residual 8e-8"),
    ("factor-subnormal-a0", [3.0517578125e-05, 2.2344314905741404e-23, 78.0, -1.0,
                             -4.9406564584124654e-324],
     "degree-2 group's own coefficients: factor roots 3e-12 relative"),
    ("skip-block-example", [4.5e-10, 4.5e-10, -3.0, -2.0, -1.0],
     "the FUZZ_SKIP_KNOWN example: factor roots 1e-11 relative"),
    ("near-double-in-group", [3.7516656447603894e-12, -1.0, -2.0, -1.0,
                              2.4030797671877772e-306],
     "per-root Newton stalled at the group's double root -1 (3.8e-13)"),
    ("factor-beyond-range", [1.1875006745610309e-308, 1.0, -2.0000000000000036,
                             -2.0, -1.0],
     "roots 2.83 and -8.4e307 must pair: q1 = -inf by contract"),
    ("factor-polish-underflow", [-1.4103081061443981e-278, 3.0, 84.0,
                                 -4503599627370496.0, -4503599627370496.0],
     "a factor Newton in one scale with an underflowed coefficient"),
    ("bairstow-yardstick-1", [-786067.36523627513, -7824475133.1416616,
                              -7824475132.1416616, 0.039060800336301327,
                              3.9525251667299724e-323],
     "Bairstow judged by a remainder rounded against larger terms"),
    ("bairstow-yardstick-2", [0.97917914390563965, 7.4509803904220462,
                              7.4509803904220462, -1.8325506472120096e-06,
                              3.9525251667299724e-323],
     "the same, 2e-13 relative in a factor's root"),
    ("subnormal-residual-1", [7.0, 1.1808168935605792e-321, 126.0, 0.0, 122.0],
     "subnormal sums counted as relative error 1: a double root listed twice"),
    ("subnormal-residual-2", [9.3006902933120728, 3.7944241600607735e-321, 84.0,
                              0.0, 0.11732941726222634],
     "the same class"),
    ("u-resolvent", [1.0, -5.4132150151793517e-12, 2.0, 1.3449746190525877e-284,
                     1.0],
     "y-resolvent rounds g^2 away: factors stuck at the symmetric point"),
    ("y-resolvent", [3.0517578125e-05, 9.0, -43.0, 51.0, 1.0],
     "u-resolvent's three roots crowd about a^2/4: wrong pairing"),
    ("bairstow-best-iterate", [3.0517578125e-05, 25.0, -115.0, -1.0,
                               1.6437564037138273e-320],
     "Bairstow stopped at its first step, which overshoots"),
    ("near-triple-3+1", [2.9103830456733704e-11, -1.0, -3.0, -3.0, -1.0],
     "-(x+1)^3 + tiny x^4: the cubic group's own coefficients kept -1"),
    ("near-triple-1+3", [-1.0, -3.0, -3.0, -1.0, 2.9103830456733704e-11],
     "the same reversed: the lone root is the smallest"),
    ("double-root-jump", [-4.0, -4.0, -1.0, 5.07565169729921e-116,
                          -2.0215873059760975e-174],
     "per-root Newton left the double root -1/2 for the tiny pair: 2 roots lost"),
    ("exact-zero-attracts", [-1.0, -2.0, -1.0, 7.4184123070967245e-68, 0.0],
     "the double root -1 fell into the exact zero root: 2 roots lost"),
    ("underflow-attracts", [-1.0, -2.0, -1.0, 1.10543037414606e-75,
                            -3.9525251667299724e-323],
     "the same where the scaled constant term underflows to 0"),
    ("bairstow-beside-zero", [-80.0, -5446574.9843752114, -5446645.9843752114,
                              105.0, 3.9525251667299724e-323],
     "Bairstow failed beside an underflowed root: factor roots 1.3e10 eps"),
    ("polish-blind-underflow", [1.1873202966621318e-308, 1.4055112613812138e-149,
                                0.0, 1.0, 0.0],
     "the spread factors' Newton in one scale underflowed: a factor root 6e-11"),
]


def roots_of(coeffs):
    """the 4 roots, each to 1100 digits absolute, so to 700 relative for
    roots down to the least subnormal; checked by their residual"""
    with mp.workdps(1100):
        cf = [mp.mpf(a) for a in coeffs]   # exact: doubles are dyadic
        roots = mp.polyroots(cf, maxsteps=3000, extraprec=3000)
        for r in roots:
            s = sum(abs(a) * abs(r) ** (4 - k) for k, a in enumerate(cf))
            assert abs(mp.polyval(cf, r)) <= mp.mpf(10) ** -1000 * s
        return [+r for r in roots]


def bound_of(coeffs, r):
    """How far r moves when each coefficient moves by up to 2^-53
    relatively: |p(r + d)| = eps s with p(r + d) ~ p'(r) d + p''(r) d^2 / 2
    and s = sum |a_k| |r|^k.  First order, eps s / |p'|, while that is well
    inside the neighbour's distance (~ 2 |p'/p''|); past it (a near-double
    root) the quadratic term rules: up to |p'/p''| + 2 sqrt(eps s / |p''|).
    Times 4, plus 4 ulp of r, as tools/ref_roots.py does, and 4 of the
    least subnormal for a root that small."""
    cf = [mp.mpf(a) for a in coeffs]
    n = len(cf) - 1
    s = sum(abs(a) * abs(r) ** (n - k) for k, a in enumerate(cf))
    d1 = sum((n - k) * a * r ** (n - k - 1) for k, a in enumerate(cf[:-1]))
    d2 = sum((n - k) * (n - k - 1) * a * r ** (n - k - 2)
             for k, a in enumerate(cf[:-2]))
    p1, p2 = abs(d1), abs(d2)
    first = U * s / p1 if p1 > 0 else mp.inf
    if p2 == 0 or first <= p1 / (4 * p2):
        b = 2 * first
    else:
        b = p1 / p2 + 2 * mp.sqrt(U * s / p2)
    return 4 * b + 4 * 2 * U * abs(r) + 4 * mp.mpf(2) ** -1074


def main():
    with open("spec/data/roots_fuzz.tsv", "w") as f:
        f.write("id\ta4\ta3\ta2\ta1\ta0\troots\tbounds\tnote\n")
        for cid, coeffs, note in CASES:
            truth = roots_of(coeffs)
            assert len(truth) == 4, cid
            f.write("%s\t%s\t%s\t%s\t%s\n" % (
                cid, "\t".join(repr(float(v)) for v in coeffs),
                ";".join("%s,%s" % (mp.nstr(mp.re(r), 30), mp.nstr(mp.im(r), 30))
                         for r in truth),
                ";".join(mp.nstr(bound_of(coeffs, r), 6) for r in truth),
                note))


if __name__ == "__main__":
    main()
