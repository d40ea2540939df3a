#!/usr/bin/python3
"""tools/ref_path_kinds.py -- references for paths of the four segment kinds
(spec/data/path_kinds.tsv, read by spec/path_kinds_spec.lua).

Paths mixing lines, quadratic and cubic Beziers and conics (rational
quadratics with weights (1, w, 1), Floater's eq. 1) in 2D and 3D, each
segment starting where the previous one ends, the numbers exactly the
doubles written (the conics' weights included: a circle's w = cos(angle)
rounded to a double).  For each segment, independently of arclen: its
length L, and at a few parameters t the length from 0 to t, the point and
the unit tangent -- by mpmath at 40 digits, the speed |P'(t)| written from
the definitions (the conic's derivative by the quotient rule on
N(t)/D(t), N = (1-t)^2 P0 + 2 w t (1-t) P1 + t^2 P2, D likewise), the
integrals by Gauss-Legendre and by tanh-sinh, split where the speed
vanishes inside; the script stops if the two differ by more than 1e-30
relative.

Columns: path, k (segment index), kind, dim, nums (the segment's numbers,
%.17g), L, ts (parameters), ls (lengths from 0 to each t), pts (the points,
dim numbers each), tans (the unit tangents, dim numbers each).

Run: /usr/bin/python3 tools/ref_path_kinds.py   (from the repository root)
"""
import math
import os

import mpmath as mp

mp.mp.dps = 40
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "spec", "data", "path_kinds.tsv")
TS = [0.125, 0.5, 0.875]
NPTS = {"line": 2, "quad": 3, "cubic": 4, "conic": 3}


def circle_arc(cx, cy, r, a0, a1):
    """The conic of the circle arc from angle a0 to a1 (|a1 - a0| < pi), as
    doubles: ends on the circle, P1 where the end tangents meet, w = cos of
    half the span."""
    h = (a1 - a0) / 2
    m = (a0 + a1) / 2
    p0 = (cx + r * math.cos(a0), cy + r * math.sin(a0))
    p2 = (cx + r * math.cos(a1), cy + r * math.sin(a1))
    p1 = (cx + r / math.cos(h) * math.cos(m), cy + r / math.cos(h) * math.sin(m))
    return [p0[0], p0[1], p1[0], p1[1], p2[0], p2[1], math.cos(h)]


def chain(start, specs):
    """Segments from specs (kind, rest-of-numbers), each starting at the
    previous end (the start point prepended)."""
    out, cur = [], list(start)
    for kind, rest in specs:
        nums = cur + list(rest)
        out.append((kind, nums))
        d = len(cur)
        end = (NPTS[kind] - 1) * d
        cur = nums[end:end + d]
    return out


def mix2():
    segs = chain((0.0, 0.0), [
        ("line", (3.0, 4.0)),
        ("quad", (6.0, 8.0, 9.0, 4.0)),
        ("conic", (9.0, 6.0, 11.0, 6.0, math.sqrt(0.5))),     # quarter circle r = 2
        ("cubic", (12.0, 9.0, 15.0, 3.0, 16.0, 6.0)),
        ("conic", (20.0, 6.0, 20.0, 4.0, 0.3)),               # elliptic, w < 1
        ("conic", (21.0, 0.0, 24.0, 4.0, 2.5)),               # hyperbolic, w > 1
        ("conic", (25.0, 6.0, 26.0, 4.0, 1.0)),               # parabolic, w = 1
        ("quad", (27.0, 4.000000001, 28.0, 4.0)),            # nearly straight
        ("quad", (31.0, 4.0, 29.0, 4.0)),                     # straight, turning back
        ("quad", (29.0, 4.0, 30.0, 5.0)),                     # P1 on P0
        ("line", (30.0, 5.0)),                                # a point
        ("conic", (30.0, 5.0, 33.0, 1.0, 1e-3)),              # P1 on P0, w small
        ("cubic", (34.0, 2.0, 35.0, 0.0, 36.0, 1.0)),
    ])
    return segs


def mix3():
    return chain((0.0, 0.0, 0.0), [
        ("line", (1.0, 2.0, 2.0)),
        ("quad", (2.0, 3.0, 1.0, 4.0, 2.0, 0.5)),
        ("conic", (5.0, 3.0, 1.0, 5.0, 4.0, 3.0, 0.6)),
        ("conic", (5.0, 5.0, 5.0, 3.0, 6.0, 4.0, 1.7)),
        ("quad", (2.0, 5.0, 3.0, 2.0, 5.0, 3.0)),             # P2 on P1
        ("line", (0.0, 0.0, 0.0)),
    ])


def circle():
    """A circle of radius 10 as four quarter conics (cyclic), the ends
    exactly the axis points."""
    w = math.sqrt(0.5)
    return [("conic", [10.0, 0.0, 10.0, 10.0, 0.0, 10.0, w]),
            ("conic", [0.0, 10.0, -10.0, 10.0, -10.0, 0.0, w]),
            ("conic", [-10.0, 0.0, -10.0, -10.0, 0.0, -10.0, w]),
            ("conic", [0.0, -10.0, 10.0, -10.0, 10.0, 0.0, w])]


def arcs():
    """Arcs of a circle and of a rotated ellipse, spans up to 170 degrees."""
    segs = [("conic", circle_arc(1.0, 2.0, 3.0, 0.3, 0.3 + math.radians(170)))]
    # an ellipse rx 5, ry 1 rotated by 30 degrees: the affine image of a circle arc
    c = circle_arc(0.0, 0.0, 1.0, -0.2, 1.9)
    ca, sa = math.cos(math.radians(30)), math.sin(math.radians(30))

    def f(x, y):
        x, y = 5 * x, y
        return (7 + ca * x - sa * y, -1 + sa * x + ca * y)
    p0, p1, p2 = f(c[0], c[1]), f(c[2], c[3]), f(c[4], c[5])
    segs.append(("conic", [p0[0], p0[1], p1[0], p1[1], p2[0], p2[1], c[6]]))
    return segs


PATHS = [("mix2", mix2()), ("mix3", mix3()), ("circle", circle()), ("arcs", arcs())]


def dimension(kind, nums):
    n = len(nums) - (1 if kind == "conic" else 0)
    return n // NPTS[kind]


def points(kind, nums, d):
    return [[mp.mpf(nums[i * d + j]) for j in range(d)] for i in range(NPTS[kind])]


def point(kind, nums, d, t):
    P = points(kind, nums, d)
    t = mp.mpf(t)
    s = 1 - t
    if kind == "line":
        return [s * P[0][j] + t * P[1][j] for j in range(d)]
    if kind == "quad":
        return [s * s * P[0][j] + 2 * s * t * P[1][j] + t * t * P[2][j] for j in range(d)]
    if kind == "cubic":
        return [s ** 3 * P[0][j] + 3 * s * s * t * P[1][j] + 3 * s * t * t * P[2][j]
                + t ** 3 * P[3][j] for j in range(d)]
    w = mp.mpf(nums[-1])
    den = s * s + 2 * w * s * t + t * t
    return [(s * s * P[0][j] + 2 * w * s * t * P[1][j] + t * t * P[2][j]) / den
            for j in range(d)]


def derivative(kind, nums, d, t):
    P = points(kind, nums, d)
    t = mp.mpf(t)
    s = 1 - t
    if kind == "line":
        return [P[1][j] - P[0][j] for j in range(d)]
    if kind == "quad":
        return [2 * (s * (P[1][j] - P[0][j]) + t * (P[2][j] - P[1][j])) for j in range(d)]
    if kind == "cubic":
        return [3 * (s * s * (P[1][j] - P[0][j]) + 2 * s * t * (P[2][j] - P[1][j])
                     + t * t * (P[3][j] - P[2][j])) for j in range(d)]
    w = mp.mpf(nums[-1])
    den = s * s + 2 * w * s * t + t * t
    dden = -2 * s + 2 * w * (s - t) + 2 * t
    out = []
    for j in range(d):
        num = s * s * P[0][j] + 2 * w * s * t * P[1][j] + t * t * P[2][j]
        dnum = -2 * s * P[0][j] + 2 * w * (s - t) * P[1][j] + 2 * t * P[2][j]
        out.append((dnum * den - num * dden) / den ** 2)
    return out


def speed(kind, nums, d, t):
    v = derivative(kind, nums, d, t)
    return mp.sqrt(sum(x * x for x in v))


def zeros(kind, nums, d):
    """Parameters in (0, 1) where a quadratic's speed vanishes (a straight
    reversal)."""
    if kind != "quad":
        return []
    P = points(kind, nums, d)
    A = [P[1][j] - P[0][j] for j in range(d)]
    B = [P[2][j] - 2 * P[1][j] + P[0][j] for j in range(d)]
    bb = sum(x * x for x in B)
    if bb == 0:
        return []
    t = -sum(A[j] * B[j] for j in range(d)) / bb
    res = [A[j] + t * B[j] for j in range(d)]
    if 0 < t < 1 and sum(x * x for x in res) < mp.mpf(10) ** -60:
        return [t]
    return []


def length(kind, nums, d, t):
    if t == 0:
        return mp.mpf(0)
    cuts = [0] + [z for z in zeros(kind, nums, d) if z < t] + [mp.mpf(t)]
    f = lambda u: speed(kind, nums, d, u)  # noqa: E731
    a = mp.quad(f, cuts, method="gauss-legendre", maxdegree=10)
    b = mp.quad(f, cuts, method="tanh-sinh", maxdegree=10)
    if abs(a - b) > mp.mpf(10) ** -30 * max(abs(a), mp.mpf(10) ** -30):
        raise SystemExit("quadratures disagree: %s %s %s %s" % (kind, nums, a, b))
    return a


def unit_tangent(kind, nums, d, t):
    v = derivative(kind, nums, d, t)
    n = mp.sqrt(sum(x * x for x in v))
    if n == 0:
        return [mp.mpf(0)] * d
    return [x / n for x in v]


def g(x, digits=30):
    return mp.nstr(x, digits, min_fixed=-5, max_fixed=30) if x != 0 else "0"


def main():
    rows = ["path\tk\tkind\tdim\tnums\tL\tts\tls\tpts\ttans"]
    for name, segs in PATHS:
        for k, (kind, nums) in enumerate(segs, 1):
            d = dimension(kind, nums)
            L = length(kind, nums, d, 1)
            ls, pts, tans = [], [], []
            for t in TS:
                ls.append(g(length(kind, nums, d, t)))
                pts += [g(x, 25) for x in point(kind, nums, d, t)]
                tans += [g(x, 25) for x in unit_tangent(kind, nums, d, t)]
            rows.append("\t".join([name, str(k), kind, str(d),
                                   " ".join("%.17g" % x for x in nums), g(L),
                                   " ".join(repr(t) for t in TS), " ".join(ls),
                                   " ".join(pts), " ".join(tans)]))
    with open(OUT, "w") as f:
        f.write("# generated by tools/ref_path_kinds.py -- do not edit\n")
        f.write("\n".join(rows) + "\n")
    print("wrote", OUT, len(rows) - 1, "segments")


if __name__ == "__main__":
    main()
