#!/usr/bin/python3
"""References for a quadratic's time at a length (src/segment/quad_time.c,
spec/quad_time_spec.lua), two kinds of rows in spec/data/quad_times.tsv:

  time      a quadratic (hostile ones: cusps, straight, a zero leg, a thin
            hairpin, tiny and huge scales, 3D, one for each branch of
            quad_time.c's first guess; and seeded random ones), a
            fraction f, its length L and the time T with s(T) = f L, and
            the speed V = |B'(T)| there over L (VL, finite where V is
            not): the spec's answer t misses by about |t - T| VL of L.
  rounding  a quadratic whose legs a = P1 - P0, c = P2 - P1 are exact in
            doubles (dyadic coordinates; 2D and 3D, hairpins, collinear
            legs, sharp vertices), a t and s(t): the closed form's
            own rounding, which quad_time.c's certificate counts (its
            FORM_ROUNDING), measured without the legs' rounding.

Each s(t) is the textbook closed form of the parabola's length,
(U S + K^2 asinh(U/K))/|b| between the ends (U = v.b/|b|, K = |a x c|/|b|,
S = |v|), at 60 digits from the decimal points themselves, checked against
mpmath's quad of the speed 2|(1-t) a + t c| split at the vertex: independent
of quad.c's forms.  T is its root by mpmath's findroot (anderson, bracketed).
Run: /usr/bin/python3 tools/ref_quad_times.py   (a few seconds)
"""
import os
import random

import mpmath as mp

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "spec", "data", "quad_times.tsv")
mp.mp.dps = 60

HOSTILE = [
    ("cusp: P2 = P0", [0, 0, 1, 0, 0, 0]),
    ("cusp: collinear, turns back", [0, 0, 2, 0, 1, 0]),
    ("collinear, no turn", [0, 0, 1, 0, 5, 0]),
    ("straight, uniform speed", [0, 0, 1, 1, 2, 2]),
    ("first leg 0", [0, 0, 0, 0, 3, 1]),
    ("second leg 0", [0, 0, 3, 1, 3, 1]),
    ("nearly straight", [0, 0, 1.01, 1, 2, 2]),
    ("tall arch", [0, 0, 1, 100, 2, 0]),
    ("thin hairpin", [0, 0, 50, 1e-6, 0, 2e-6]),
    ("skew arch", [0.5, 1, 7, 9.25, 3, -2]),
    ("arch at 1e-300", [0, 0, 1e-300, 2e-300, 2e-300, 0]),
    ("arch at 1e300", [0, 0, 1e300, 2e300, 2e300, 0]),
    ("past DBL_MAX/2", [-9e307, 0, 9e307, 0, -3e307, 3e307]),
    ("3D arch", [0, 0, 0, 1, 2, 3, 2, 0, 1]),
    ("3D cusp", [0, 0, 0, 1, 1, 1, 0, 0, 0]),
    # quad_time.c's first guess, branch by branch (the table's: the rest)
    ("hairpin, k^2 below DBL_MIN", [0, 0, 1, 1e-160, 0, 2e-160]),
    ("far from the vertex, U ~ 2e9", [0, 0, 1, 1e-9, 3, 2.5e-9]),
    ("symmetric arch, vertex at L/2", [0, 0, 1, 1, 2, 0]),
    # far from the origin: legs exact differences of large coordinates
    ("far from the origin",
     [1e6, 1e6, 1000003.5, 1000001.25, 1000004.75, 999997.5]),
]
FRACTIONS = ["1e-9", "0.01", "0.25", "0.5", "0.7", "0.999", "0.999999999"]


def legs(p, dim):
    P = [mp.mpf(x) for x in p]
    a = [P[dim + k] - P[k] for k in range(dim)]
    c = [P[2 * dim + k] - P[dim + k] for k in range(dim)]
    return a, c


def length_fn(p, dim):
    """s(t) over [0, t] by the closed form, exact arithmetic on the points."""
    a, c = legs(p, dim)
    b = [c[k] - a[k] for k in range(dim)]
    B = mp.fsum(x * x for x in b)
    if B == 0:
        sa = mp.sqrt(mp.fsum(x * x for x in a))
        return lambda t: 2 * t * sa
    q = mp.sqrt(B)
    u0 = mp.fsum(a[k] * b[k] for k in range(dim))
    aa = mp.fsum(x * x for x in a)
    K2 = max(aa - u0 * u0 / B, mp.mpf(0))   # |v|^2 = U^2 + K^2 at t = 0

    def F(U):
        S = mp.sqrt(U * U + K2)
        if K2 == 0:
            return U * abs(U)
        return U * S + K2 * mp.asinh(U / mp.sqrt(K2))

    U0 = u0 / q
    return lambda t: (F(U0 + t * q) - F(U0)) / q


def speed(p, dim, t):
    a, c = legs(p, dim)
    return 2 * mp.sqrt(mp.fsum(((1 - t) * a[k] + t * c[k]) ** 2 for k in range(dim)))


def by_quadrature(p, dim, t):
    """mpmath's quad of the speed, on the legs scaled near 1 by a power of
    two (its tolerance is absolute) and scaled back."""
    a, c = legs(p, dim)
    m = max(abs(x) for x in a + c)
    if m == 0:
        return mp.mpf(0)
    sc = mp.mpf(2) ** -int(mp.floor(mp.log(m, 2)))
    a = [x * sc for x in a]
    c = [x * sc for x in c]
    b = [c[k] - a[k] for k in range(dim)]
    B = mp.fsum(x * x for x in b)
    pts = [mp.mpf(0), mp.mpf(t)]
    if B > 0:
        tv = -mp.fsum(a[k] * b[k] for k in range(dim)) / B
        if 0 < tv < t:
            pts = [mp.mpf(0), tv, mp.mpf(t)]
    def sp(x):
        return 2 * mp.sqrt(mp.fsum(((1 - x) * a[k] + x * c[k]) ** 2 for k in range(dim)))
    return mp.quad(sp, pts) / sc


def time_at(s, goal):
    """T in [0, 1] with s(T) = goal (s increasing): bisection to 60 digits,
    then the answer polished by findroot inside the bracket."""
    lo, hi = mp.mpf(0), mp.mpf(1)
    for _ in range(80):
        mid = (lo + hi) / 2
        if s(mid) < goal:
            lo = mid
        else:
            hi = mid
    try:
        T = mp.findroot(lambda x: s(x) - goal, (lo, hi), solver="anderson")
        if lo <= T <= hi:
            return T
    except (ValueError, ZeroDivisionError):
        pass
    return (lo + hi) / 2


def main():
    rnd = random.Random(20261203)
    curves = list(HOSTILE)
    for i in range(30):
        curves.append(("random %d" % (i + 1), [rnd.uniform(-5, 5) for _ in range(6)]))
    for i in range(6):
        curves.append(("random 3D %d" % (i + 1), [rnd.uniform(-5, 5) for _ in range(9)]))
    # more for quad_time.c's answer from its table (direct_bound), a
    # generator of their own so that the rows above stay as they were:
    # plain, nearly collinear legs, hairpins, far from the origin, nearly
    # straight (where the table's answer loses digits to cancellation and
    # its bound must say so)
    more = random.Random(20261204)
    for i in range(60):
        kind = i % 5
        p = [more.uniform(-5, 5) for _ in range(6)]
        if kind == 1:
            p[3] = p[1] + (p[5] - p[1]) * (p[2] - p[0]) / (p[4] - p[0]) + more.uniform(-1e-6, 1e-6)
        elif kind == 2:
            p[4], p[5] = p[0] + more.uniform(-1e-3, 1e-3), p[1] + more.uniform(-1e-3, 1e-3)
        elif kind == 3:
            p = [x + 1e6 for x in p]
        elif kind == 4:
            p[2] = (p[0] + p[4]) / 2 + more.uniform(-1e-2, 1e-2)
            p[3] = (p[1] + p[5]) / 2 + more.uniform(-1e-2, 1e-2)
        curves.append(("random B %d" % (i + 1), p))
    rows = []
    for name, p in curves:
        dim = 3 if len(p) == 9 else 2
        s = length_fn(p, dim)
        L = s(mp.mpf(1))
        check = by_quadrature(p, dim, 1)
        assert L == 0 or abs(check - L) <= mp.mpf(10) ** -35 * L, (name, L, check)
        for f in FRACTIONS:
            T = time_at(s, mp.mpf(f) * L)
            rows.append(["time", name, str(dim), " ".join(repr(float(x)) for x in p),
                         f, mp.nstr(L, 40), mp.nstr(T, 40),
                         mp.nstr(speed(p, dim, T) / L if L else 0, 40)])
    for i in range(600):
        # exact legs: dyadic coordinates, P0 = 0; 2D and 3D; sharp vertices,
        # hairpins, collinear legs and plain ones
        dim = 3 if i % 3 == 0 else 2
        a = [rnd.randint(-2 ** 20, 2 ** 20) / 2 ** 18 for _ in range(dim)]
        kind = i % 5
        if kind == 0:       # a hairpin: c within 2^-14 of -a
            c = [-x + rnd.randint(-2 ** 4, 2 ** 4) / 2 ** 18 for x in a]
        elif kind == 1:     # collinear legs (k = 0), a turn or none
            lam = rnd.randint(-2 ** 10, 2 ** 10) / 2 ** 8
            c = [x * lam for x in a]
        elif kind == 2:     # a sharp vertex
            c = [-x + rnd.randint(-2 ** 10, 2 ** 10) / 2 ** 18 for x in a]
        else:
            c = [rnd.randint(-2 ** 20, 2 ** 20) / 2 ** 18 for _ in range(dim)]
        p = [0.0] * dim + a + [a[k] + c[k] for k in range(dim)]
        t = rnd.random()
        s = length_fn(p, dim)(mp.mpf(t))
        if s == 0:
            continue
        rows.append(["rounding", "exact legs %d" % (i + 1), str(dim), " ".join(repr(x) for x in p),
                     repr(t), mp.nstr(s, 40), "", ""])
    with open(OUT, "w") as fh:
        fh.write("# tools/ref_quad_times.py: a quadratic's times at f L (kind time) and\n")
        fh.write("# lengths over [0, t] of quadratics with exact legs (kind rounding)\n")
        fh.write("kind\tname\tdim\tseg\tf_or_t\tL_or_s\tT\tVL\n")
        for r in rows:
            fh.write("\t".join(r) + "\n")


if __name__ == "__main__":
    main()
