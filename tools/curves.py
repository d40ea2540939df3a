#!/usr/bin/python3
"""The reference curve sets of arclen: deterministic, seeded, plain doubles.

curves2d() and curves3d() return lists of (id, family, param, coords) where
coords are Python floats (x0 y0 x1 y1 x2 y2 x3 y3, or the 12 numbers of a 3D
cubic).  tools/ref_lengths.py computes the 40-digit references from exactly
these doubles and writes spec/data/curves2d.tsv and curves3d.tsv.

Families and their param column:
  henkel      Henkel's six arcs, in his order.                        param -
  random      8 coordinates uniform in [0, 10).                         -
  nearcusp    exact cusps (integer/dyadic points) moved by eps*D, D the
              extent of the control polygon, eps = 1e-1 ... 1e-12.      eps
  cusp        exact cusps: z'(t*) = 0 at t* = 1/2, 1/4, 0.3, ... and the
              endpoint cusps P0 = P1, P2 = P3.                          t*
  collinear   four points on a line, 0, 1 or 2 direction reversals
              (and a momentary stop).                                   reversals
  coincident  P0=P1, P2=P3, P1=P2, P0=P1&P2=P3, P0=P3, three equal.     which
  point       all four points equal (length 0).                         -
  scale       random (and near-cusp) curves times 10^k.                 k
  offset      random and near-cusp curves translated far away.          offset
  nearquad    degree-elevated quadratics (exact), moved by eps*D;
              straight lines with unequal spacing.                      eps
  planar      2D twins of the planar3d curves (coordinates multiples of
              the frame's norm, so the 3D embedding is exact).          frame
3D: random3d, nearcusp3d, collinear3d, planar3d, scale3d, offset3d, point3d.

A cubic has a cusp (in the speed sense) at t* = p/q when its hodograph
vanishes there: (q-p)^2 d1 + 2p(q-p) d2 + p^2 d3 = 0 with d_i = P_i - P_(i-1).
Choosing d2 = (q-p)^2 a, d3 = (q-p)^2 b and d1 = -(2p(q-p) a + p^2 b) for
integers a, b solves it exactly in integers (see exact_cusp).
"""
import math
import random

EPS_CUSP = [10.0 ** -k for k in range(1, 13)]    # 1e-1 ... 1e-12
EPS_QUAD = [10.0 ** -k for k in range(1, 16)]    # 1e-1 ... 1e-15
SCALES = [-150, -100, -50, -20, -10, 0, 10, 20, 50, 100, 150]

HENKEL = [
    (0, 0, 10, 0, 10, 10, 0, 0),
    (0, 0, 10, 10, 0, 10, 10, 0),
    (0, 0, 10, 10, 0, 9.999, 10, 0),
    (0, 0, 1, 1, 9, 9, 10, 10),
    (0, 0, 20, 20, -10, -10, 10, 10),
    (0, 0, 20.001, 20, -10, -10, 10, 10),
]


def fl(seq):
    return tuple(float(v) for v in seq)


def points(c, dim):
    return [list(c[i * dim:(i + 1) * dim]) for i in range(4)]


def flat(pts):
    return fl(v for p in pts for v in p)


def extent(c, dim):
    """Largest coordinate range of the control polygon (the curve's size D)."""
    pts = points(c, dim)
    return max(max(p[k] for p in pts) - min(p[k] for p in pts)
               for k in range(dim))


def unit(rng, dim):
    while True:
        v = [rng.gauss(0, 1) for _ in range(dim)]
        n = math.sqrt(sum(x * x for x in v))
        if n > 1e-3:
            return [x / n for x in v]


def exact_cusp(rng, p, q, dim, span=4, den=1):
    """Integer (or /den dyadic) control points with z'(p/q) = 0 exactly."""
    P0 = [rng.randint(-span, span) for _ in range(dim)]
    a = [rng.randint(-span, span) for _ in range(dim)]
    b = [rng.randint(-span, span) for _ in range(dim)]
    if all(x == 0 for x in a) or all(x == 0 for x in b):
        a[0], b[-1] = span, -span
    m = (q - p) ** 2
    d1 = [-(2 * p * (q - p) * a[k] + p * p * b[k]) for k in range(dim)]
    d2 = [m * a[k] for k in range(dim)]
    d3 = [m * b[k] for k in range(dim)]
    # Bring the curve to size ~10: divide by a power of two (exact).
    size = max(abs(v) for v in d1 + d2 + d3) or 1
    den = den * 2 ** max(0, math.ceil(math.log2(size / 8)))
    P1 = [P0[k] + d1[k] for k in range(dim)]
    P2 = [P1[k] + d2[k] for k in range(dim)]
    P3 = [P2[k] + d3[k] for k in range(dim)]
    return flat([[v / den for v in P] for P in (P0, P1, P2, P3)])


def is_collinear(c, dim):
    pts = points(c, dim)
    d = [[pts[i][k] - pts[0][k] for k in range(dim)] for i in range(1, 4)]
    for i in range(3):
        for j in range(i + 1, 3):
            for k in range(dim):
                for m in range(k + 1, dim):
                    if d[i][k] * d[j][m] != d[i][m] * d[j][k]:
                        return False
    return True


def cusp_base(rng, p, q, dim):
    """An exact cusp that is not a straight line (that would be 'collinear')."""
    while True:
        c = exact_cusp(rng, p, q, dim)
        if not is_collinear(c, dim):
            return c


def perturb(c, dim, eps, rng, which=(1, 2)):
    """Move control points `which` by eps*D in random directions."""
    pts = points(c, dim)
    D = extent(c, dim)
    for i in which:
        u = unit(rng, dim)
        pts[i] = [pts[i][k] + eps * D * u[k] for k in range(dim)]
    return flat(pts)


def symmetric_cusp(rng, swap):
    """A loop symmetric under t -> 1-t, with its cusp exactly at t = 1/2.

    Mirror x -> -x: P0=(-a,b0), P3=(a,b0), P1=(-c,b1), P2=(c,b1); the
    hodograph at 1/2 is 3/4 (P3+P2-P1-P0) = 3/4 (2a+2c, 0): a cusp iff c=-a.
    Returns a function eps -> curve with c = -a + eps*D, which keeps the
    symmetry, so the speed minimum stays at the bisection point t = 1/2."""
    a = rng.randint(2, 6)
    b0 = rng.randint(-3, 3)
    b1 = b0 + rng.choice([-1, 1]) * rng.randint(4, 10)

    def make(eps):
        D = max(2 * a, abs(b1 - b0))
        cc = -a + eps * D
        pts = [(-a, b0), (-cc, b1), (cc, b1), (a, b0)]
        if swap:
            pts = [(y, x) for x, y in pts]
        return flat(pts)
    return make


def random_curve(rng, dim):
    return fl(10 * rng.random() for _ in range(4 * dim))


def translate(c, dim, off):
    return fl(c[i] + off[i % dim] for i in range(4 * dim))


def scaled(c, k):
    f = 10.0 ** k
    return fl(v * f for v in c)


def elevated_quadratic(rng, dim):
    """Exact degree elevation of an integer quadratic Q0 Q1 Q2:
    P1 = Q0 + 2/3 (Q1-Q0), P2 = Q2 + 2/3 (Q1-Q2); Q1-Q0 and Q1-Q2 are
    multiples of 3 so every coordinate is an integer."""
    while True:
        Q1 = [rng.randint(-6, 6) for _ in range(dim)]
        Q0 = [Q1[k] - 3 * rng.randint(-3, 3) for k in range(dim)]
        Q2 = [Q1[k] - 3 * rng.randint(-3, 3) for k in range(dim)]
        P1 = [Q0[k] + 2 * (Q1[k] - Q0[k]) // 3 for k in range(dim)]
        P2 = [Q2[k] + 2 * (Q1[k] - Q2[k]) // 3 for k in range(dim)]
        c = flat([Q0, P1, P2, Q2])
        if not is_collinear(c, dim):
            return c


def on_line(origin, direction, lams):
    dim = len(origin)
    return flat([[origin[k] + lam * direction[k] for k in range(dim)]
                 for lam in lams])


# Positions along a line; the param is the number of direction reversals
# (or "stop": the speed touches zero without reversing).  The hodograph's
# Bernstein coefficients are d1 d2 d3 = differences of the positions; the
# motion reverses where d1(1-t)^2 + 2 d2 t(1-t) + d3 t^2 changes sign.
LINE_LAMS = [
    (0, 1, 9, 10),                 # Henkel 4
    (0, 5, 5, 10), (0, 7, 8, 9), (0, 0.5, 1, 16),
    (0, 10, 12, 5), (0, 8, 8, -4), (3, -5, 0, 2),
    (0, 20, -10, 10),              # Henkel 5
    (0, 6, -2, 4), (0, 16, -16, 1), (-1, 7, -3, 9),
    (0, 4, 0, 4),                  # d = (4, -4, 4): speed ~ (1-2t)^2
]
LINE_DIRS2 = [(1, 0), (0, 1), (1, 1), (0.75, 1), (-1.25, 0.5), (0.375, -0.125)]


def reversals(lams):
    """Sign changes of the 1D hodograph in (0, 1), exactly (Fractions)."""
    from fractions import Fraction as F
    d1, d2, d3 = (F(lams[i + 1]) - F(lams[i]) for i in range(3))
    a, b, c = d1 - 2 * d2 + d3, 2 * (d2 - d1), d1

    def val(t):
        return (a * t + b) * t + c
    # Sample between the roots: the roots of a quadratic are separated by
    # its vertex, so the signs at 0, vertex, 1 (clipped) decide.
    ts = [F(0), F(1)]
    if a != 0 and 0 < -b / (2 * a) < 1:
        ts.insert(1, -b / (2 * a))
    signs = [val(t) for t in ts]
    if any(s == 0 for s in signs[1:-1]):
        return "stop"
    nz = [s > 0 for s in signs if s != 0]
    return str(sum(1 for i in range(len(nz) - 1) if nz[i] != nz[i + 1]))


def collinear2d(rng):
    out = []
    for j, lams in enumerate(LINE_LAMS):
        for d in (LINE_DIRS2[j % len(LINE_DIRS2)],
                  LINE_DIRS2[(j + 3) % len(LINE_DIRS2)]):
            o = (rng.randint(-8, 8) / 4, rng.randint(-8, 8) / 4)
            out.append((reversals(lams), on_line(o, d, lams)))
    return out


def coincident(rng, dim):
    out = []
    kinds = ["P0=P1", "P2=P3", "P1=P2", "P0=P1,P2=P3", "P0=P3",
             "P0=P1=P2", "P1=P2=P3", "P0=P2=P3"]
    for kind in kinds:
        for rep in range(3):
            if rep == 0:
                pts = [[rng.randint(0, 10) for _ in range(dim)]
                       for _ in range(4)]
            else:
                pts = [[10 * rng.random() for _ in range(dim)]
                       for _ in range(4)]
            groups = [g.split("=") for g in kind.split(",")]
            for g in groups:
                first = int(g[0][1])
                for name in g[1:]:
                    pts[int(name[1])] = list(pts[first])
            out.append((kind, flat(pts)))
    return out


def curves2d():
    rng = random.Random(20240611)
    rows = []

    def add(family, param, c):
        n = sum(1 for r in rows if r[1] == family) + 1
        rows.append(("%s-%d" % (family, n), family, param, fl(c)))

    for c in HENKEL:
        add("henkel", "-", c)
    r = random.Random(1)
    for _ in range(1000):
        add("random", "-", random_curve(r, 2))

    # nearcusp: bases (exact cusps) and perturbation directions.
    r = random.Random(2)
    bases = []
    hc = HENKEL[1]
    # Henkel's direction: P2 moved down (as in his curve 3).
    bases.append(lambda e: (0, 0, 10, 10, 0, 10 - 10 * e, 10, 0))
    # Symmetric (x1 + x2 = 10 exactly: 10 - x1 is exact by Sterbenz): the
    # speed minimum stays exactly at the bisection point t = 1/2.
    bases.append(lambda e: (0, 0, 10 - 10 * e, 10, 10 - (10 - 10 * e), 10,
                            10, 0))
    bases.append(lambda e, c=hc, s=r.random(): perturb(c, 2, e, random.Random(s)))
    bases.append(symmetric_cusp(r, False))
    bases.append(symmetric_cusp(r, True))
    for p, q in [(1, 2), (1, 4), (3, 10), (3, 4), (1, 16), (15, 16),
                 (1, 64), (63, 64), (1, 1024), (1, 3)]:
        c = cusp_base(r, p, q, 2)
        bases.append(lambda e, c=c, s=r.random(): perturb(c, 2, e, random.Random(s)))
    for make in bases:
        for e in EPS_CUSP:
            add("nearcusp", repr(e), make(e))

    # cusp: exact.
    r = random.Random(3)
    add("cusp", "0.5", HENKEL[1])
    add("cusp", "0.5", symmetric_cusp(r, False)(0.0))
    add("cusp", "0.5", symmetric_cusp(r, True)(0.0))
    for p, q in [(1, 2), (1, 2), (1, 4), (1, 4), (3, 10), (3, 10), (3, 4),
                 (7, 10), (1, 8), (5, 8), (1, 16), (15, 16), (1, 3), (2, 3),
                 (1, 1000), (999, 1000)]:
        add("cusp", repr(p / q), cusp_base(r, p, q, 2))
    for i in range(3):   # endpoint cusps: zero speed at t = 0, 1, both
        c = list(random_curve(r, 2))
        c[2:4] = c[0:2]
        add("cusp", "0.0", c)
        c = list(random_curve(r, 2))
        c[4:6] = c[6:8]
        add("cusp", "1.0", c)
    c = list(random_curve(r, 2))
    c[2:4], c[4:6] = c[0:2], c[6:8]
    add("cusp", "0.0,1.0", c)

    r = random.Random(4)
    for rev, c in collinear2d(r):
        add("collinear", rev, c)
    add("collinear", reversals((0, 20, -10, 10)), HENKEL[4])

    r = random.Random(5)
    for kind, c in coincident(r, 2):
        add("coincident", kind, c)

    for x, y in [(0.0, 0.0), (3.7, -2.1), (1e8, -1e8), (-1.5e300, 2.5e-300),
                 (1e-300, 1e-300)]:
        add("point", "-", (x, y) * 4)

    r = random.Random(6)
    cuspy = bases[2](1e-6)
    for k in SCALES:
        for _ in range(5):
            add("scale", str(k), scaled(random_curve(r, 2), k))
        add("scale", str(k), scaled(cuspy, k))
        add("scale", str(k), scaled(HENKEL[1], k))

    r = random.Random(7)
    offsets = [(1e8, -1e8), (1e8, 1e8), (-3e8, 2e8), (1e8, 0.0),
               (0.0, -1e8), (12345678.9, -98765432.1), (4.5e9, 4.5e9)]
    for off in offsets:
        for _ in range(3):
            add("offset", "%r,%r" % off, translate(random_curve(r, 2), 2, off))
        add("offset", "%r,%r" % off, translate(bases[0](1e-4), 2, off))
        add("offset", "%r,%r" % off, translate(bases[1](1e-8), 2, off))

    r = random.Random(8)
    for _ in range(6):
        base = elevated_quadratic(r, 2)
        add("nearquad", "0.0", base)
        s = r.random()
        for e in EPS_QUAD:
            add("nearquad", repr(e), perturb(base, 2, e, random.Random(s)))
    for lams in [(0, 1, 2, 3), (0, 0.25, 0.5, 4), (0, 2.5, 2.75, 3),
                 (0, 0.125, 7.5, 8), (-2, -1.5, 3, 3.5)]:
        add("nearquad", "line", on_line((r.randint(-4, 4), r.randint(-4, 4)),
                                        r.choice(LINE_DIRS2), lams))

    for i, (frame, c2, _) in enumerate(planar_pairs()):
        add("planar", frame, c2)
    return rows


# Orthogonal integer vectors u, v of equal norm n: (x, y) -> x u/n + y v/n
# keeps lengths; the 2D coordinates are multiples of n (times a power of two),
# so x/n and y/n are exact and the 3D coordinates are exact doubles.
FRAMES = [
    ("u=(2,2,1)/3,v=(2,-1,-2)/3", (2, 2, 1), (2, -1, -2), 3),
    ("u=(1,2,2)/3,v=(2,1,-2)/3", (1, 2, 2), (2, 1, -2), 3),
    ("u=(2,3,6)/7,v=(6,2,-3)/7", (2, 3, 6), (6, 2, -3), 7),
    ("u=(4,4,7)/9,v=(1,-8,4)/9", (4, 4, 7), (1, -8, 4), 9),
]


def planar_pairs():
    """(frame, 2D curve, 3D curve) with equal length."""
    r = random.Random(9)
    out = []
    for i in range(24):
        name, u, v, n = FRAMES[i % len(FRAMES)]
        kind = i % 3
        if kind == 0:      # random, grid 2^-20
            xy = [r.randint(0, 10 * 2 ** 20) / 2 ** 20 for _ in range(8)]
        elif kind == 1:    # exact cusp
            xy = list(cusp_base(r, r.choice([1, 3]), 4, 2))
        else:              # near cusp (dyadic perturbation 2^-30)
            xy = list(cusp_base(r, 1, 2, 2))
            xy[2] += 2.0 ** -30
        xy = [x * n for x in xy]                  # multiples of n: exact
        off = (r.randint(-5, 5), r.randint(-5, 5), r.randint(-5, 5))
        c3 = []
        for j in range(4):
            a, b = xy[2 * j] / n, xy[2 * j + 1] / n
            c3 += [off[k] + a * u[k] + b * v[k] for k in range(3)]
        out.append((name, fl(xy), fl(c3)))
    return out


def curves3d():
    rows = []

    def add(family, param, c):
        n = sum(1 for r in rows if r[1] == family) + 1
        rows.append(("%s-%d" % (family, n), family, param, fl(c)))

    r = random.Random(11)
    for _ in range(300):
        add("random3d", "-", random_curve(r, 3))

    r = random.Random(12)
    for p, q in [(1, 2), (1, 4), (3, 10), (15, 16)]:
        c = cusp_base(r, p, q, 3)
        s = r.random()
        for e in EPS_CUSP:
            add("nearcusp3d", repr(e), perturb(c, 3, e, random.Random(s)))
    for p, q in [(1, 2), (3, 10)]:   # exact cusps (param eps = 0)
        add("nearcusp3d", "0.0", cusp_base(r, p, q, 3))

    r = random.Random(13)
    dirs3 = [(1, 0, 0), (0, 0, 1), (1, 1, 1), (0.5, -0.75, 1.25), (3, 4, 12)]
    for j, lams in enumerate(LINE_LAMS):
        o = tuple(r.randint(-8, 8) / 4 for _ in range(3))
        add("collinear3d", reversals(lams), on_line(o, dirs3[j % len(dirs3)], lams))

    for frame, _, c3 in planar_pairs():
        add("planar3d", frame, c3)

    r = random.Random(14)
    for k in SCALES:
        for _ in range(2):
            add("scale3d", str(k), scaled(random_curve(r, 3), k))

    r = random.Random(15)
    offs = [(1e8, -1e8, 1e8), (-3e8, 2e8, 0.0), (0.0, 0.0, 1e8),
            (12345678.9, -98765432.1, 5e8), (1e9, 1e9, -1e9)]
    for off in offs:
        add("offset3d", "%r,%r,%r" % off, translate(random_curve(r, 3), 3, off))
        c = perturb(cusp_base(r, 1, 2, 3), 3, 1e-6, r)
        add("offset3d", "%r,%r,%r" % off, translate(c, 3, off))

    for p in [(0.0, 0.0, 0.0), (1e8, -2.5, 3e-7), (-7.25e200, 1.0, 0.5)]:
        add("point3d", "-", p * 4)
    return rows


if __name__ == "__main__":
    from collections import Counter
    for rows in (curves2d(), curves3d()):
        print(sorted(Counter(r[1] for r in rows).items()), len(rows))
