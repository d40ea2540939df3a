#!/usr/bin/python3
"""References for each branch of the quadratic Bezier's closed-form length
(src/segment/quad.c): the vertex inside the range or not (and reflected,
both ends before it), the log's argument at least 2 (libm's log) or below
(log1p of an argument formed without cancellation), no cross term (K = 0,
collinear control points), nearly straight (the 10-point Gauss rule), and
scales that need the halving and the power-of-two scaling; 2D and 3D.

Writes spec/data/quad_branches.tsv: name, the branch the row is meant to
reach (checked here in doubles, as quad.c decides it), dim, the control
points (exact doubles, written with repr), t0, t1 and the length over
[t0, t1].  Each length is mpmath's quad (tanh-sinh, 40 digits) of the
speed 2|(1-t)(P1-P0) + t(P2-P1)| from the definition, split at the vertex
(where |B'| is least) and checked against the textbook closed form
(U S + K^2 asinh(U/K))/|b| at 80 digits: independent of quad.c's forms.
Run: /usr/bin/python3 tools/ref_quad_branches.py   (a few seconds)
"""
import math
import os

import mpmath as mp

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "spec", "data", "quad_branches.tsv")

ROWS = [
    # name, branch, points, t0, t1
    ("arch, whole", "vertex-log", [0, 0, 1, 2, 2, 0], 0.0, 1.0),
    ("arch, short at the vertex", "vertex-log1p", [0, 0, 1, 2, 2, 0], 0.44, 0.565),
    ("tall arch, short at the vertex", "vertex-log1p", [0, 0, 1, 100, 2, 0], 0.499, 0.502),
    ("skew arch, whole", "vertex-log", [0.5, 1, 7, 9.25, 3, -2], 0.0, 1.0),
    ("arch, after the vertex", "after-log", [0, 0, 1, 2, 2, 0], 0.55, 1.0),
    ("arch, short after the vertex", "after-log1p", [0, 0, 1, 2, 2, 0], 0.7, 0.85),
    ("arch, before the vertex", "before-log", [0, 0, 1, 2, 2, 0], 0.0, 0.45),
    ("arch, short before the vertex", "before-log1p", [0, 0, 1, 2, 2, 0], 0.2, 0.4),
    ("hook, whole (vertex before 0)", "after-log", [0, 0, 1, 0, 3, 1], 0.0, 1.0),
    ("hook, reversed (vertex after 1)", "before-log", [3, 1, 1, 0, 0, 0], 0.0, 1.0),
    ("turn back on a line, whole", "vertex-K0", [0, 0, 2, 0, 1, 0], 0.0, 1.0),
    ("on a line, no turn", "after-K0", [0, 0, 1, 0, 5, 0], 0.0, 1.0),
    ("nearly straight", "gauss", [0, 0, 1.01, 1, 2, 2], 0.0, 1.0),
    ("nearly straight, a piece", "gauss", [1, 2, 3.5, 2.25, 6, 3], 0.1, 0.9),
    ("arch at 1e300", "vertex-log", [0, 0, 1e300, 2e300, 2e300, 0], 0.0, 1.0),
    ("arch at 1e-300", "vertex-log", [0, 0, 1e-300, 2e-300, 2e-300, 0], 0.0, 1.0),
    ("arch past DBL_MAX/2 (halved)", "vertex-log",
     [-9e307, 0, 9e307, 0, -3e307, 3e307], 0.0, 1.0),
    ("3D arch, whole", "vertex-log", [0, 0, 0, 1, 2, 3, 2, 0, 1], 0.0, 1.0),
    ("3D arch, short at the vertex", "vertex-log1p",
     [0, 0, 0, 1, 2, 0, 2, 0, 0], 0.45, 0.56),
    ("3D hook", "after-log", [0, 0, 0, 1, 0, 0.5, 3, 1, 2], 0.0, 1.0),
    ("3D short after the vertex", "after-log1p", [0, 0, 0, 1, 2, 3, 2, 0, 1], 0.8, 0.95),
]


def branch(p, dim, t0, t1):
    """quad.c's choice, in doubles (the rows keep away from its edges)."""
    a = [p[dim + k] - p[k] for k in range(dim)]
    c = [p[2 * dim + k] - p[dim + k] for k in range(dim)]
    if any(math.isinf(x) for x in a + c):
        a = [p[dim + k] / 2 - p[k] / 2 for k in range(dim)]
        c = [p[2 * dim + k] / 2 - p[dim + k] / 2 for k in range(dim)]
    e = math.frexp(max(abs(x) for x in a + c))[1]
    a = [math.ldexp(x, -e) for x in a]
    c = [math.ldexp(x, -e) for x in c]
    b = [c[k] - a[k] for k in range(dim)]
    B = sum(x * x for x in b)
    h = t1 - t0
    v0 = [(1 - t0) * a[k] + t0 * c[k] for k in range(dim)]
    v1 = [(1 - t1) * a[k] + t1 * c[k] for k in range(dim)]
    if dim == 2:
        kk = abs(a[0] * c[1] - a[1] * c[0])
    else:
        kk = math.sqrt((a[1] * c[2] - a[2] * c[1]) ** 2 + (a[2] * c[0] - a[0] * c[2]) ** 2
                       + (a[0] * c[1] - a[1] * c[0]) ** 2)
    u0 = sum(v0[k] * b[k] for k in range(dim))
    u1 = u0 + h * B
    S0 = math.sqrt(sum(x * x for x in v0))
    S1 = math.sqrt(sum(x * x for x in v1))
    q = math.sqrt(B)
    inside = u0 < 0 < u1
    m = kk * kk / B if inside else min(S0, S1) ** 2
    if m >= 16 * h * h * B:
        return "gauss"
    if inside:
        if kk == 0:
            return "vertex-K0"
        N = (u1 + q * S1) * (-u0 + q * S0)
        return "vertex-log" if N >= 2 * kk * kk else "vertex-log1p"
    side = "after" if u1 > 0 else "before"
    if u1 <= 0:
        u0, u1, S0, S1 = -u1, -u0, S1, S0
    if kk == 0:
        return side + "-K0"
    N, D = u1 + q * S1, u0 + q * S0
    return side + ("-log" if N >= 2 * D else "-log1p")


def length(p, dim, t0, t1):
    """The length, on the points scaled by a power of two (exact) to near 1:
    mpmath's error estimate of quad is absolute."""
    e = math.frexp(max(abs(x) for x in p))[1]
    L = unit_length([mp.ldexp(mp.mpf(x), -e) for x in p], dim, t0, t1)
    return mp.ldexp(L, e)


def legs(p, dim):
    """a = P1 - P0, c = P2 - P1, b = c - a and B = |b|^2 at the current
    precision (the quadrature and the closed form each form their own)."""
    P = [[mp.mpf(p[i * dim + k]) for k in range(dim)] for i in range(3)]
    a = [P[1][k] - P[0][k] for k in range(dim)]
    c = [P[2][k] - P[1][k] for k in range(dim)]
    b = [c[k] - a[k] for k in range(dim)]
    return a, c, b, sum(x * x for x in b)


def unit_length(p, dim, t0, t1):
    mp.mp.dps = 40
    a, c, b, B = legs(p, dim)
    T0, T1 = mp.mpf(t0), mp.mpf(t1)

    def speed(t):
        return 2 * mp.sqrt(sum(((1 - t) * a[k] + t * c[k]) ** 2 for k in range(dim)))
    cuts = [T0, T1]
    if B > 0:
        tv = -sum(a[k] * b[k] for k in range(dim)) / B
        if T0 < tv < T1:
            cuts = [T0, tv, T1]
    L, err = mp.quad(speed, cuts, error=True)
    assert err < mp.mpf(10) ** -36 * abs(L), (p, err)
    # the textbook closed form at 80 digits, as a second opinion
    mp.mp.dps = 80
    a, c, b, B = legs(p, dim)
    if B > 0:
        q = mp.sqrt(B)
        ab = sum(a[k] * b[k] for k in range(dim))
        aa = sum(x * x for x in a)
        K = mp.sqrt(max(aa - ab * ab / B, 0))

        def F(t):
            U = (ab + t * B) / q
            S = mp.sqrt(U * U + K * K)
            return U * S + (K * K * mp.asinh(U / K) if K > 0 else 0)
        L2 = (F(mp.mpf(t1)) - F(mp.mpf(t0))) / q
        assert abs(L2 - L) <= mp.mpf(10) ** -35 * abs(L), (p, L, L2)
    mp.mp.dps = 40
    return L


def main():
    with open(OUT, "w") as f:
        f.write("# tools/ref_quad_branches.py: mpmath quad of the speed, 40 digits\n")
        f.write("name\tbranch\tdim\tseg\tt0\tt1\tL\n")
        for name, want, p, t0, t1 in ROWS:
            p = [float(x) for x in p]
            dim = len(p) // 3
            got = branch(p, dim, t0, t1)
            assert got == want, (name, got, want)
            L = length(p, dim, t0, t1)
            f.write("%s\t%s\t%d\t%s\t%r\t%r\t%s\n" % (
                name, want, dim, " ".join(repr(x) for x in p), t0, t1,
                mp.nstr(L, 40, min_fixed=-1, max_fixed=1)))


if __name__ == "__main__":
    main()
