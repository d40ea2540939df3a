#!/usr/bin/python3
"""Write spec/data/roots1010.tsv: the 24 test quartics of Orellana & De
Michele, ACM TOMS Algorithm 1010 (2020), Table 1 -- cases 1-22 given by their
roots, 23 and 24 by their coefficients -- with, for each root of the
double-rounded polynomial, the truth at 60 digits and the error attainable
in double.

The coefficients are formed exactly from the roots (mpmath, 80 digits) and
rounded to double: that polynomial is what any double solver is handed, so
its roots (mpmath.polyroots at 60 digits) are the truth.  The attainable
error of a root r of multiplicity m (roots within 1e-6 relative form a
cluster) is the first non-vanishing term of the perturbation expansion for
relative coefficient changes of u = 2^-53:
    (m! u sum_k |a_k| |r|^k / |p^(m)(r)|)^(1/m),
times 8 for the rounding of a solver's own arithmetic; a spec accepts an
error below that bound plus 4 u |r|.
Run: /usr/bin/python3 tools/ref_roots1010.py > spec/data/roots1010.tsv
"""
import mpmath as mp

mp.mp.dps = 80
U = mp.mpf(2) ** -53
C = mp.mpc

# Table 1's roots (cases 1-22) and coefficients (23, 24), from the paper.
ROOTS = {
    1: ["1e9", "1e6", "1e3", "1"],
    2: ["2.003", "2.002", "2.001", "2"],
    3: ["1e53", "1e50", "1e49", "1e47"],
    4: ["1e14", "2", "1", "-1"],
    5: ["-2e7", "1e7", "1", "-1"],
    6: ["1e7", "-1e6", ("1", "1"), ("1", "-1")],
    7: ["-7", "-4", ("-1e6", "1e5"), ("-1e6", "-1e5")],
    8: ["1e8", "11", ("1e3", "1"), ("1e3", "-1")],
    9: [("1e7", "1e6"), ("1e7", "-1e6"), ("1", "2"), ("1", "-2")],
    10: [("1e4", "3"), ("1e4", "-3"), ("-7", "1e3"), ("-7", "-1e3")],
    11: [("1.001", "4.998"), ("1.001", "-4.998"), ("1.000", "5.001"), ("1.000", "-5.001")],
    12: [("1e3", "3"), ("1e3", "-3"), ("1e3", "1"), ("1e3", "-1")],
    13: [("2", "1e4"), ("2", "-1e4"), ("1", "1e3"), ("1", "-1e3")],
    14: ["1000", "1000", "1000", "1000"],
    15: ["1000", "1000", "1000", mp.mpf(2) ** -48],
    16: [("1e16", "1e7"), ("1e16", "-1e7"), ("1", "0.1"), ("1", "-0.1")],
    17: ["10000", "10001", "10010", "10100"],
    18: [("4e5", "3e2"), ("4e5", "-3e2"), ("3e4", "7e3"), ("3e4", "-7e3")],
    19: ["1e44", "1e30", "1e30", "1"],
    20: ["1e14", "1e7", "1e7", "1"],
    21: ["1e15", "1e7", "1e7", "1"],
    22: ["1e154", "1e152", "10", "1"],
}


def root(spec):
    if isinstance(spec, tuple):
        return C(mp.mpf(spec[0]), mp.mpf(spec[1]))
    return C(mp.mpf(spec), 0)


def coefficients(case):
    """a4..a0 (descending), exact in mpmath."""
    if case == 23:
        return [mp.mpf(1), mp.mpf(1), mp.mpf(1), mp.mpf(3) / 8, mp.mpf("0.001")]
    if case == 24:
        s = mp.mpf("1e30")
        return [mp.mpf(1), -(1 + 1 / s), 1 / s - s * s, s * s + s, -s]
    r = [root(x) for x in ROOTS[case]]
    c = [C(1)]
    for x in r:                               # multiply by (t - x)
        c = [a - x * b for a, b in zip(c + [C(0)], [C(0)] + c)]
    return [mp.re(a) for a in c]


def deriv(a, m):
    n = len(a) - 1
    d = a[:]
    for _ in range(m):
        n = len(d) - 1
        d = [d[i] * (n - i) for i in range(n)]
    return d


def attainable(a, r, mult):
    n = len(a) - 1
    size = sum(abs(a[i]) * abs(r) ** (n - i) for i in range(n + 1))
    pm = abs(mp.polyval(deriv(a, mult), r))
    if pm == 0:
        return mp.inf
    return 8 * (mp.factorial(mult) * U * size / pm) ** (mp.mpf(1) / mult)


def main():
    print("case\ta4\ta3\ta2\ta1\ta0\troot_re\troot_im\tbound")
    for case in range(1, 25):
        exact = coefficients(case)
        a = [mp.mpf(float(x)) for x in exact]           # what a solver gets
        if case in ROOTS and all(x == y for x, y in zip(a, exact)):
            rts = [root(x) for x in ROOTS[case]]   # rounding changed nothing
        else:                                      # (polyroots is slow on
            with mp.workdps(60):                   # multiple roots)
                rts = mp.polyroots(a, maxsteps=2000, extraprec=600)
        for r in rts:
            mult = sum(1 for q in rts if abs(q - r) <= mp.mpf("1e-6") * abs(r))
            b = attainable(a, r, mult)
            print("%d\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s" % (
                case, *[repr(float(x)) for x in a],
                mp.nstr(mp.re(r), 25), mp.nstr(mp.im(r), 25), mp.nstr(b, 6)))


main()
