#!/usr/bin/python3
"""Write spec/data/roots_exact.tsv: quartics whose coefficients are exact
doubles (integers or dyadic rationals of at most 53 bits), built from known
roots, so that the roots are exactly those of the polynomial a solver is
handed (Algorithm 1010's case 8 is such a quartic).

Families (seeded; a candidate is kept only if every coefficient of its
exact product is a double):
  spread      four real roots, one scaled by 10^k, k = 2 ... 12
  pair        a conjugate pair a +- bi beside reals, spreads 10^2 ... 10^12
  close       a close real pair r, r + 2^-j (j = 4 ... 20), or a close pair
              of conjugate pairs, beside other roots
  case8       Algorithm 1010's case 8 and its sign/scale variants
Each root is checked by mpmath (60 digits: |p(r)| = 0 exactly for the exact
rational root, and mpmath.polyroots finds it) and given the error the
refinement guarantees: one rounding of each part, u |r| with u = 2^-53, plus
the error of a residual summed in double-double, 8 n u^2 sum |a_k| |r|^k /
|p'(r)|, plus 4 u |r| for the step's own rounding:
    bound = 6 u |r| + 8 n u^2 sum |a_k| |r|^k / |p'(r)|.
Run: /usr/bin/python3 tools/ref_roots_exact.py > spec/data/roots_exact.tsv
"""
import random
from fractions import Fraction as F

import mpmath as mp

mp.mp.dps = 60
U = mp.mpf(2) ** -53


def is_double(q):
    return float(q) == q


def product(roots):
    """Coefficients a4..a0 of prod (x - r) for roots (re, im) Fractions,
    conjugate pairs given once with im > 0."""
    c = [F(1)]
    for re, im in roots:
        if im == 0:
            fac = [F(1), -re]
        else:
            fac = [F(1), -2 * re, re * re + im * im]
        out = [F(0)] * (len(c) + len(fac) - 1)
        for i, x in enumerate(c):
            for j, y in enumerate(fac):
                out[i + j] += x * y
        c = out
    return c


def all_roots(roots):
    out = []
    for re, im in roots:
        out.append((re, im))
        if im != 0:
            out.append((re, -im))
    return out


def candidates(rng):
    for k in range(2, 13):                       # spread
        for _ in range(3):
            big = rng.choice([-1, 1]) * rng.randint(1, 9) * 10 ** k
            yield "spread", [(F(big), 0)] + [(F(rng.randint(-99, 99)), 0)
                                              for _ in range(3)]
    for k in range(2, 13):                       # pair
        for _ in range(3):
            s = 10 ** k
            a, b = F(rng.randint(-9, 9)), F(rng.randint(1, 9))
            if rng.random() < 0.5:
                yield "pair", [(a * s, b), (F(rng.randint(-99, 99)), 0),
                               (F(rng.randint(-99, 99)), 0)]
            else:
                yield "pair", [(a, b), (F(rng.randint(1, 9) * s), 0),
                               (F(rng.randint(-99, 99)), 0)]
    for j in range(4, 21, 2):                    # close
        for _ in range(2):
            r = F(rng.randint(1, 999))
            d = F(1, 2 ** j)
            yield "close", [(r, 0), (r + d, 0), (F(rng.randint(-99, 99)), 0),
                            (F(rng.randint(1, 9) * 10 ** rng.randint(3, 8)), 0)]
            a, b = F(rng.randint(-99, 99)), F(rng.randint(1, 99))
            yield "close", [(a, b), (a + d, b + d)]
    for s, t in [(1, 1), (-1, 1), (1, -1), (2, 1), (1, 4), (-8, 1)]:
        yield "case8", [(F(10 ** 8 * s), 0), (F(11 * s), 0), (F(1000 * t), F(abs(t)))]


def bound(a, r):
    n = len(a) - 1
    z = mp.mpc(mp.mpf(r[0].numerator) / r[0].denominator,
               mp.mpf(r[1].numerator) / r[1].denominator)
    a = [mp.mpf(x.numerator) / x.denominator for x in a]
    size = sum(abs(a[i]) * abs(z) ** (n - i) for i in range(n + 1))
    dp = abs(mp.polyval([a[i] * (n - i) for i in range(n)], z))
    return 6 * U * abs(z) + 8 * n * U * U * size / dp


def main():
    rng = random.Random(2323)
    print("id\tfamily\ta4\ta3\ta2\ta1\ta0\troot_re\troot_im\tbound")
    count = {}
    for fam, roots in candidates(rng):
        a = product(roots)
        if not all(is_double(x) for x in a):
            continue
        rts = all_roots(roots)
        if len(set(rts)) < 4:
            continue
        af = [mp.mpf(float(x)) for x in a]
        found = mp.polyroots(af, maxsteps=500, extraprec=300)
        for re, im in rts:
            z = mp.mpc(mp.mpf(re.numerator) / re.denominator,
                       mp.mpf(im.numerator) / im.denominator)
            if mp.polyval(af, z) != 0:
                raise SystemExit("not a root: %s" % z)
            if min(abs(w - z) for w in found) > mp.mpf(10) ** -40 * (1 + abs(z)):
                raise SystemExit("mpmath.polyroots disagrees: %s" % z)
        count[fam] = count.get(fam, 0) + 1
        cid = "%s-%d" % (fam, count[fam])
        for re, im in rts:
            print("%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s" % (
                cid, fam, *[repr(float(x)) for x in a], repr(float(re)),
                repr(float(im)), mp.nstr(bound(a, (re, im)), 6)))


main()
