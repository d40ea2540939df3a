#!/usr/bin/python3
"""References for the conic specs (Floater 1996), from mpmath.

Writes
  spec/data/conic_hausdorff.tsv  Hausdorff distance of each scheme's spline
      to the conic, levels 0..5, for a quarter circle, an ellipse (w = 0.5)
      and a hyperbola (w = 2); with this script's own Theorem 1 bound
      (max |g| found by sampling and golden-section search, not Prop 13).
  spec/data/conic_length.tsv  exact arc lengths of conics (mpmath quad of
      the rational curve's speed) and the lengths of the mid-point splines.
  spec/data/conic_length_extreme.tsv  lengths at the ends of the double
      range (legs 1e-300 beside O(1), w = 1e+-300, points near DBL_MAX, the
      fuzz findings), by quadrature on panels clustered at the speed's
      singularities (wide_length); `ref_conic.py extreme` alone: ~12 min.
  spec/data/conic_length_flat.tsv  nearly flat triangles with w = 1 +- 2^-k
      (flat_cases), by wide_length; `ref_conic.py flat` alone: ~1.5 min.

Independent of the C code: the schemes are the paper's formulas as printed
(with the corrections of doc/papers.md), at 30 digits.
Run: nice /usr/bin/python3 tools/ref_conic.py   (about a minute or two)
"""
import os
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from conic_speed import ConicSpeed  # noqa: E402  (shared with ref_conic_thin)

mp.mp.dps = 30
HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "spec", "data")


def lam(scheme, w):
    """lambda(w) as printed in Props 3, 4, 5, 8, 9 (negative root)."""
    w = mp.mpf(w)
    if scheme == "quadratic":
        return mp.mpf(2) / 3
    if scheme == "g2":
        return mp.mpf(2) / 3 * w * (mp.sqrt(w * w + 3) - w)
    if scheme == "midpoint":
        return mp.mpf(4) / 3 * w / (1 + w)
    if scheme == "c2":
        return 2 * w * w / (1 + 2 * w * w)
    if scheme == "g4":
        return 2 * (6 * w * w + 1 - mp.sqrt(3 * w * w + 1)) / (12 * w * w + 3)
    raise ValueError(scheme)


SCHEMES = ["quadratic", "g2", "midpoint", "c2", "g4"]


def subdivide(pieces, w):
    """Eq. (4): every piece (a, b, c) split at its mid-point."""
    out = []
    for a, b, c in pieces:
        l1 = [(a[k] + w * b[k]) / (1 + w) for k in range(2)]
        r1 = [(w * b[k] + c[k]) / (1 + w) for k in range(2)]
        m = [(a[k] + 2 * w * b[k] + c[k]) / (2 * (1 + w)) for k in range(2)]
        out.append((a, l1, m))
        out.append((m, r1, c))
    return out, mp.sqrt((1 + w) / 2)


def level_pieces(p, w, r):
    pieces = [tuple([mp.mpf(x) for x in q] for q in p)]
    w = mp.mpf(w)
    for _ in range(r):
        pieces, w = subdivide(pieces, w)
    return pieces, w


def cubic_of(piece, l):
    a, b, c = piece
    return [a, [a[k] + l * (b[k] - a[k]) for k in range(2)],
            [c[k] + l * (b[k] - c[k]) for k in range(2)], c]


def conic_pt(piece, w, t):
    """Eq. (1) with its first and second derivatives."""
    a, b, c = piece
    # N = n0 + n1 t + n2 t^2, D = d0 + d1 t + d2 t^2 (Bernstein expanded)
    n0 = a
    n1 = [2 * (w * b[k] - a[k]) for k in range(2)]
    n2 = [a[k] - 2 * w * b[k] + c[k] for k in range(2)]
    d0, d1, d2 = 1, 2 * (w - 1), 2 - 2 * w
    D = d0 + d1 * t + d2 * t * t
    D1 = d1 + 2 * d2 * t
    D2 = 2 * d2
    P, P1, P2 = [], [], []
    for k in range(2):
        N = n0[k] + n1[k] * t + n2[k] * t * t
        N1 = n1[k] + 2 * n2[k] * t
        N2 = 2 * n2[k]
        U = N1 * D - N * D1
        U1 = N2 * D - N * D2
        P.append(N / D)
        P1.append(U / (D * D))
        P2.append((U1 * D - 2 * U * D1) / D ** 3)
    return P, P1, P2


def cubic_pt(c, t):
    s = 1 - t
    P = [s**3 * c[0][k] + 3 * s * s * t * c[1][k] + 3 * s * t * t * c[2][k]
         + t**3 * c[3][k] for k in range(2)]
    P1 = [3 * (s * s * (c[1][k] - c[0][k]) + 2 * s * t * (c[2][k] - c[1][k])
               + t * t * (c[3][k] - c[2][k])) for k in range(2)]
    P2 = [6 * (s * (c[2][k] - 2 * c[1][k] + c[0][k])
               + t * (c[3][k] - 2 * c[2][k] + c[1][k])) for k in range(2)]
    return P, P1, P2


def nearest(curve, grid, X):
    """min over t in [0,1] of |curve(t) - X|: grid start, then Newton on
    (C - X).C' = 0, clamped to [0, 1]."""
    best = min(range(len(grid)), key=lambda i: (grid[i][1][0] - X[0]) ** 2
               + (grid[i][1][1] - X[1]) ** 2)
    t = grid[best][0]
    for _ in range(30):
        P, P1, P2 = curve(t)
        e = [P[0] - X[0], P[1] - X[1]]
        f = e[0] * P1[0] + e[1] * P1[1]
        df = P1[0] ** 2 + P1[1] ** 2 + e[0] * P2[0] + e[1] * P2[1]
        tn = t - f / df
        tn = min(max(tn, mp.mpf(0)), mp.mpf(1))
        if abs(tn - t) < mp.mpf(10) ** (-24):
            t = tn
            break
        t = tn
    P = curve(t)[0]
    d = mp.sqrt((P[0] - X[0]) ** 2 + (P[1] - X[1]) ** 2)
    # the grid sample itself is a fallback against a wrong basin
    g = grid[best][1]
    dg = mp.sqrt((g[0] - X[0]) ** 2 + (g[1] - X[1]) ** 2)
    return min(d, dg)


def golden_max(f, lo, hi, it=40):
    g = (mp.sqrt(5) - 1) / 2
    x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
    f1, f2 = f(x1), f(x2)
    for _ in range(it):
        if f1 > f2:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - g * (hi - lo)
            f1 = f(x1)
        else:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + g * (hi - lo)
            f2 = f(x2)
    return max(f1, f2)


def one_sided(src, dst, n=32):
    """max over s of min over t |src(s) - dst(t)|."""
    grid = [(mp.mpf(i) / 96, dst(mp.mpf(i) / 96)[0]) for i in range(97)]
    ss = [mp.mpf(i) / n for i in range(n + 1)]
    vals = [nearest(dst, grid, src(s)[0]) for s in ss]
    best = max(vals)
    for i in range(1, n):
        if vals[i] >= vals[i - 1] and vals[i] >= vals[i + 1] and vals[i] > 0:
            v = golden_max(lambda s: nearest(dst, grid, src(s)[0]),
                           ss[i - 1], ss[i + 1])
            best = max(best, v)
    return best


def hausdorff(p, w, scheme, r):
    pieces, wr = level_pieces(p, w, r)
    l = lam(scheme, wr)
    d = mp.mpf(0)
    for pc in pieces:
        c = cubic_of(pc, l)
        fq = lambda t, c=c: cubic_pt(c, t)
        fr = lambda t, pc=pc: conic_pt(pc, wr, t)
        d = max(d, one_sided(fq, fr), one_sided(fr, fq))
    return d


def g_norm(wr, l):
    """max |f_r(q(t))| by sampling + golden section (not Prop 13)."""
    A = 9 * l * l - 12 * wr * wr * (1 - l)
    B = 18 * l * l - 4 * wr * wr * (9 * (1 - l) ** 2 + 1)
    g = lambda t: abs((1 - t) ** 2 * t * t * (A * (1 - t) ** 2
                                             + B * (1 - t) * t + A * t * t))
    n = 64
    ts = [mp.mpf(i) / n for i in range(n + 1)]
    vals = [g(t) for t in ts]
    best = max(vals)
    for i in range(1, n):
        if vals[i] >= vals[i - 1] and vals[i] >= vals[i + 1]:
            best = max(best, golden_max(g, ts[i - 1], ts[i + 1]))
    return best


def bound(p, w, scheme, r):
    pieces, wr = level_pieces(p, w, r)
    l = lam(scheme, wr)
    if l > 1:
        return mp.inf
    d2 = max(mp.sqrt(sum((a[k] - 2 * b[k] + c[k]) ** 2 for k in range(2)))
             for a, b, c in pieces)
    return mp.mpf(1) / 4 * max(1 / wr ** 2, 1) * g_norm(wr, l) * d2


def speed_conic(p, w):
    return lambda t: mp.norm(conic_pt(p, mp.mpf(w), t)[1])


def conic_length(p, w):
    """quad of the speed, with breaks clustered at the ends (for w >> 1 and
    w << 1 the speed changes on a scale of min(w, 1/w) there), checked by
    a second evaluation at 45 digits with other breaks."""
    p = tuple([mp.mpf(x) for x in q] for q in p)
    ends = [mp.mpf(10) ** -k for k in range(12, 0, -1)]
    pts = [0] + ends + [mp.mpf(1) / 2] + [1 - e for e in reversed(ends)] + [1]
    L = mp.quad(speed_conic(p, w), pts)
    with mp.workdps(45):
        pts2 = [0] + [mp.mpf(3) ** -k for k in range(30, 0, -1)]
        pts2 = pts2 + [1 - e for e in reversed(pts2[1:])] + [1]
        L2 = mp.quad(speed_conic(p, w), pts2)
    if abs(L - L2) > abs(L) * mp.mpf(10) ** -26:
        raise RuntimeError("quadrature disagrees: %s %s" % (L, L2))
    return L


def half_length(p, w, dps, ratio):
    """int_0^(1/2) of the speed of eq. (1) by Gauss-Legendre on panels
    clustered geometrically (factor `ratio`) about every singularity of the
    speed (tools/conic_speed.py), so that each panel is smooth on its own
    scale however close to t = 0 the features are (a leg of 1e-300 beside
    O(1) legs, w = 1e300); the panel points are placed at 3 dps digits."""
    cs = ConicSpeed(p, w, dps)
    with mp.workdps(dps):
        with mp.workdps(3 * dps):
            pts = cs.panels(mp.mpf(0), mp.mpf(1) / 2, ratio)
        return mp.quad(cs.speed, pts, method="gauss-legendre")


def wide_length(p, w):
    """Both halves, the second as the first half of the reversed conic (t
    within 1e-100 of 1 has no digits left at the working precision); two
    runs with other panels and precision must agree to 1e-28."""
    rev = (p[2], p[1], p[0])
    with mp.workdps(50):
        L1 = half_length(p, w, 40, 4) + half_length(rev, w, 40, 4)
        L2 = half_length(p, w, 50, 3) + half_length(rev, w, 50, 3)
        if abs(L1 - L2) > abs(L2) * mp.mpf(10) ** -28:
            raise RuntimeError("wide_length disagrees: %s %s" % (L1, L2))
        return L2


def spline_length(p, w, scheme, r):
    pieces, wr = level_pieces(p, w, r)
    l = lam(scheme, wr)
    tot = mp.mpf(0)
    for pc in pieces:
        c = cubic_of(pc, l)
        tot += mp.quad(lambda t: mp.norm(cubic_pt(c, t)[1]), [0, 1])
    return tot


def s(x, digits=25):
    return mp.nstr(x, digits, min_fixed=-mp.inf, max_fixed=mp.inf) \
        if x != mp.inf else "inf"


QUARTER = ((1, 0), (1, 1), (0, 1))
CONICS = [("circle", QUARTER, mp.mpf(0.7071067811865476)),  # double of sqrt(1/2)
          ("ellipse", QUARTER, mp.mpf("0.5")),
          ("hyperbola", QUARTER, mp.mpf(2))]


def write_hausdorff():
    path = os.path.join(DATA, "conic_hausdorff.tsv")
    with open(path, "w") as f:
        f.write("conic\tx0\ty0\tx1\ty1\tx2\ty2\tw\tscheme\tlevel\thausdorff"
                "\tbound\n")
        for name, p, w in CONICS:
            for sc in SCHEMES:
                for r in range(6):
                    h = hausdorff(p, w, sc, r)
                    b = bound(p, w, sc, r)
                    f.write("%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%d\t%s\t%s\n" % (
                        name, *[repr(float(x)) for q in p for x in q],
                        repr(float(w)), sc, r, s(h), s(b)))
                    f.flush()
                    print(name, sc, r, mp.nstr(h, 5), mp.nstr(b, 5),
                          file=sys.stderr)


# Conics for the exact lengths: (name, p0, p1, p2, w).  Weights are exact
# doubles; the file gives them with repr, so Lua reads the same numbers.
LENGTH_CASES = [
    ("quarter circle", (1, 0), (1, 1), (0, 1), 0.7071067811865476),
    ("ellipse w=0.5", (1, 0), (1, 1), (0, 1), 0.5),
    ("ellipse w=0.1", (0, 0), (3, 2), (5, -1), 0.1),
    ("ellipse w=1e-3", (0, 0), (1, 1e3), (2, 0), 1e-3),
    ("ellipse thin", (0, 0), (1, 1e-4), (2, 0), 0.9),
    ("ellipse w=0.999999", (0, 0), (1, 1), (3, 0), 0.999999),
    ("ellipse w=1-2^-40", (0, 0), (1, 1), (3, 0), 1 - 2.0 ** -40),
    ("parabola", (0, 0), (1, 2), (3, 0), 1.0),
    ("parabola skew", (-2, 1), (5, 7), (3, -4), 1.0),
    ("hyperbola w=1+2^-40", (0, 0), (1, 1), (3, 0), 1 + 2.0 ** -40),
    ("hyperbola w=1.000001", (0, 0), (1, 1), (3, 0), 1.000001),
    ("hyperbola w=2", (1, 0), (1, 1), (0, 1), 2.0),
    ("hyperbola w=10", (0, 0), (3, 2), (5, -1), 10.0),
    ("hyperbola w=1e4", (0, 0), (1, 1), (2, 0), 1e4),
    ("far ellipse", (1e8, 1e8), (1e8 + 1, 1e8 + 1), (1e8, 1e8 + 2), 0.3),
    ("tiny hyperbola", (0, 0), (1e-9, 2e-9), (3e-9, 0), 3.0),
    ("huge ellipse", (0, 0), (1e12, 1e12), (3e12, 0), 0.6),
]


def random_cases(n=40, seed=6):
    """Random triangles in [-10, 10]^2 (not too flat) and weights
    log-uniform in [1e-3, 1e3], one in four near 1."""
    import random
    rnd = random.Random(seed)
    out = []
    while len(out) < n:
        pts = [(rnd.uniform(-10, 10), rnd.uniform(-10, 10)) for _ in range(3)]
        (x0, y0), (x1, y1), (x2, y2) = pts
        cr = (x1 - x0) * (y2 - y1) - (y1 - y0) * (x2 - x1)
        if abs(cr) < 1:
            continue
        if len(out) % 4 == 3:
            w = 1 + rnd.choice([-1, 1]) * 10 ** rnd.uniform(-12, -2)
        else:
            w = 10 ** rnd.uniform(-3, 3)
        out.append(("random %d" % len(out), pts[0], pts[1], pts[2], w))
    return out


def write_lengths():
    path = os.path.join(DATA, "conic_length.tsv")
    with open(path, "w") as f:
        f.write("name\tx0\ty0\tx1\ty1\tx2\ty2\tw\tlength\n")
        for name, a, b, c, w in LENGTH_CASES + random_cases():
            L = conic_length((a, b, c), w)
            f.write("%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" % (
                name, *[repr(float(x)) for x in a + b + c], repr(float(w)),
                s(L)))
    path = os.path.join(DATA, "conic_spline_length.tsv")
    with open(path, "w") as f:
        f.write("conic\tscheme\tlevel\tlength\texact\n")
        for name, p, w in CONICS:
            L = conic_length(p, w)
            for sc in SCHEMES:
                for r in range(5):
                    f.write("%s\t%s\t%d\t%s\t%s\n" % (
                        name, sc, r, s(spline_length(p, w, sc, r)), s(L)))


# Conics at the ends of the double range (fuzz/fuzz_conic's open
# classes), with the length by wide_length.  "overflow" rows have a length
# beyond DBL_MAX: conic_length must refuse them.
EXTREME_CASES = [
    ("leg 1e-300 beside O(1), w=0.5", (0, 0), (1e-300, 0), (1, 1), 0.5),
    ("leg 1e-300 beside O(1), w=2", (0, 0), (0, 1), (1e-300, 1), 2.0),
    ("leg 1e-300 beside O(1), w=1", (0, 0), (1e-300, 1e-300), (1, -2), 1.0),
    ("w=1.5e8, p1 one ulp from p0", (1, 1), (1.0000000000000002, 1), (3, 2),
     1.5e8),
    ("w=2e5, p1 p2 1e-10 apart", (0, 0), (1, 1), (1 + 1e-10, 1), 2e5),
    ("w=1e-160", (0, 0), (3, 2), (5, -1), 1e-160),
    ("w=1e-300", (0, 0), (3, 2), (5, -1), 1e-300),
    ("w=1e160", (0, 0), (3, 2), (5, -1), 1e160),
    ("w=1e300", (0, 0), (3, 2), (5, -1), 1e300),
    ("quarter circle of radius 1.1e308", (-8e307, 0), (0, 8e307), (8e307, 0),
     0.7071067811865476),
    ("near DBL_MAX, w=75", (15, -1.3486981934093403e+308), (-1, 98),
     (1, 0.99999999999999989), 75.0),
    ("spread 2^1300, w=0.3", (1e-200, 1e-200), (1e190, 0), (0, 1e190), 0.3),
    # hyperbolic parameter b = acosh w ~ 31: cosh(b + th0) from e^b e^th0
    ("w=1e13, leg 1e-14", (0, 0), (1, 1), (1, 1.00000000000001), 1e13),
    ("w=3e13", (0, 0), (3, 2), (5, -1), 3e13),
    ("w=3, leg 3e-14", (0, 0), (3e-14, 0), (1, 1), 3.0),
    # fuzz/fuzz_conic findings (first failing inputs of the no-skip run)
    ("fuzz: p0 at 2.4e220, short leg 1e-14", (3.9525251667299724e-323,
     2.4070306476177068e+220), (9.9998731398954988, 9.999873139895513),
     (9.9998731398955272, 9.9998731398955414), 9.9998731398955556),
    ("fuzz: leg 1e236 beside O(1), w=26", (-1, 40), (-41, -2),
     (-1.0174582569701926e+236, -1.0174582569701926e+236), 26.0),
    ("fuzz: ellipse B/A 5e-23, w=1-2^-50", (36, 36.000000000000014),
     (36.000000000000021, 36.000000000000078), (35.000000000000078, 1),
     0.99999999999999911),
    ("fuzz: parabola, leg 1e-15 of the other", (3.0346760614651183e-86,
     -2.0215873059760975e-174), (-1, -1), (-0.99999999999999911,
     -0.999999999999999), 1.0),
    ("fuzz: parabola, legs 1e115 and 1e99", (7.291122026346784e-304,
     -4.4681967109995408e+105), (-1.9190760541073831e+115,
     -1.9190760541073831e+115), (-1.9190760541073813e+115,
     -1.9190760541073813e+115), 1.0),
]
OVERFLOW_CASES = [
    ("overflow: chord 3e308", (-1.5e308, 0), (0, 1.5e308), (1.5e308, 0), 0.7),
]


def write_extreme():
    path = os.path.join(DATA, "conic_length_extreme.tsv")
    with open(path, "w") as f:
        f.write("name\tx0\ty0\tx1\ty1\tx2\ty2\tw\tlength\n")
        for name, a, b, c, w in EXTREME_CASES + OVERFLOW_CASES:
            L = wide_length((a, b, c), w)
            if name.startswith("overflow") != (L > sys.float_info.max):
                raise RuntimeError("%s: length %s" % (name, L))
            f.write("%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" % (
                name, *[repr(float(x)) for x in a + b + c], repr(float(w)),
                s(L)))
            f.flush()
            print(name, mp.nstr(L, 20), file=sys.stderr)


def flat_cases():
    """Nearly flat triangles with w near 1 (a near-parabolic conic hugging
    its chord): the first is the case where conic_length was off by 1.2e-11
    (the triangle's area taken from a x c while the semi-diameters came
    from a and p2 - p0, a rounding apart); around it w = 1 +- 2^-k and
    apexes 10^-j off the chord, with ends a few ulps off the line so that
    the legs' roundings differ (an apex over the chord's middle is where
    the old code lost up to 3e-11)."""
    out = [("w=1-2^-53, apex 2.4e-6 off the chord (issue 31)",
            (-1, -1.0000000000000018), (0, 2.3818574845790863e-06),
            (1, 0.99999999999999989), 0.99999999999999989)]
    ends = [((-1, -1.0000000000000018), (1, 0.99999999999999989)),
            ((-3, 1.0000000000000004), (5, -2.9999999999999996)),
            ((0.1, 0.30000000000000004), (0.7000000000000001, 0.9))]
    weights = [("1-2^-53", 1 - 2.0 ** -53), ("1-2^-50", 1 - 2.0 ** -50),
               ("1-2^-40", 1 - 2.0 ** -40), ("1-2^-26", 1 - 2.0 ** -26),
               ("1-2^-12", 1 - 2.0 ** -12), ("1", 1.0),
               ("1+2^-52", 1 + 2.0 ** -52), ("1+2^-40", 1 + 2.0 ** -40),
               ("1+2^-26", 1 + 2.0 ** -26), ("1+2^-12", 1 + 2.0 ** -12)]
    for e, (p0, p2) in enumerate(ends):
        mx, my = (p0[0] + p2[0]) / 2, (p0[1] + p2[1]) / 2
        nx, ny = -(p2[1] - p0[1]), p2[0] - p0[0]     # a normal of the chord
        for j in (3, 5, 6, 7):      # 1e-8 and below: sandwich() answers
            off = 1.2360679774997898 * 10.0 ** -j
            for sh in (0, 0.3819660112501051):   # apex over the middle or not
                p1 = (mx + off * nx + sh * (p2[0] - p0[0]),
                      my + off * ny + sh * (p2[1] - p0[1]))
                for wname, w in weights:
                    out.append(("flat %d, apex 1.2e-%d off, shift %.2f, w=%s"
                                % (e, j, sh, wname), p0, p1, p2, w))
    return out


def write_flat():
    path = os.path.join(DATA, "conic_length_flat.tsv")
    with open(path, "w") as f:
        f.write("name\tx0\ty0\tx1\ty1\tx2\ty2\tw\tlength\n")
        for name, a, b, c, w in flat_cases():
            L = wide_length((a, b, c), w)
            f.write("%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" % (
                name, *[repr(float(x)) for x in a + b + c], repr(float(w)),
                s(L)))
            f.flush()


def write_perimeters():
    """Ellipse perimeters 4 a E(1 - b^2/a^2) (mpmath's ellipe takes m)."""
    path = os.path.join(DATA, "conic_perimeter.tsv")
    with open(path, "w") as f:
        f.write("rx\try\tperimeter\n")
        for a, b in [(2.0, 1.0), (1.0, 1.0), (5.0, 0.01), (1e-3, 7e-4),
                     (3.0, 2.9999)]:
            A, B = max(a, b), min(a, b)
            P = 4 * A * mp.ellipe(1 - (mp.mpf(B) / A) ** 2)
            f.write("%r\t%r\t%s\n" % (a, b, s(P)))


def write_fullcircle_mpost():
    """MetaPost's fullcircle control points, from real mpost (double mode).
    Skipped (no file) when mpost is missing."""
    import shutil
    import subprocess
    import tempfile
    if shutil.which("mpost") is None:
        print("mpost not found: fullcircle reference skipped", file=sys.stderr)
        return
    # -ini needs no plain.mp: plain's fullcircle is makepath pencircle
    lines = ["delimiters ();", "path fullcircle;",
             "fullcircle = makepath pencircle;"]
    for i in range(8):
        for what in ("point %d" % i, "postcontrol %d" % i,
                     "precontrol %d" % (i + 1), "point %d" % (i + 1)):
            lines.append("show xpart(%s of fullcircle); show ypart(%s of "
                         "fullcircle);" % (what, what))
    src = "\n".join(lines) + "\nend\n"
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "fc.mp"), "w") as f:
            f.write(src)
        subprocess.run(["mpost", "-ini", "-numbersystem=double",
                        "-interaction=nonstopmode", "fc.mp"], cwd=tmp,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       timeout=120)
        try:
            log = open(os.path.join(tmp, "fc.log")).read()
        except OSError:
            log = ""
    vals = [l[3:].strip().rstrip(")").strip() for l in log.splitlines()
            if l.startswith(">> ")]
    if len(vals) != 64:
        print("mpost gave %d values: fullcircle reference skipped" %
              len(vals), file=sys.stderr)
        return
    path = os.path.join(DATA, "conic_fullcircle_mpost.tsv")
    with open(path, "w") as f:
        f.write("segment\tx0\ty0\tx1\ty1\tx2\ty2\tx3\ty3\n")
        for i in range(8):
            f.write("%d\t%s\n" % (i, "\t".join(vals[8 * i:8 * i + 8])))


if __name__ == "__main__":
    what = sys.argv[1:] or ["lengths", "extreme", "flat", "mpost", "hausdorff"]
    if "lengths" in what:
        write_lengths()
        write_perimeters()
    if "extreme" in what:
        write_extreme()
    if "flat" in what:
        write_flat()
    if "mpost" in what:
        write_fullcircle_mpost()
    if "hausdorff" in what:
        write_hausdorff()
