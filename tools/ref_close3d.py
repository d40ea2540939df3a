#!/usr/bin/python3
"""Reference lengths of space cubics whose |z'|^2 has roots close together.

These are the curves where the 3D elliptic length (src/elliptic3d.c) and
the 3D branch points of the default method (src/branch.c) used to lose
digits: Newton on Q = |z'|^2 places each of two roots a distance d apart
only to eps/d, and a stop (a quadruple root of Q) comes out of Q's
coefficients to eps^(1/4).  Families and their param column:
  pair3d    a hodograph with a double root s (z' = A (t - s)^2, a planar
            cubic with integer points, put in 3D by an orthogonal integer
            frame) moved by eps out of its plane or inside it: Q has two
            complex roots ~sqrt(eps) apart.                           eps
  line3d    points on a line without reversal (Q = |u|^2 p(t)^2, p > 0:
            a double complex pair), moved off the line by eps.        eps
  stop3d    collinear stops: P1 = P2 = P3 (quadruple root of Q at
            t = 1) and 0, u, 0, u (quadruple root at t = 1/2), exact
            (eps 0) and moved off the line by eps.                    eps
  spread3d  components of very different sizes: a collinear reversal or
            a stop with a transverse part 2^-k times smaller (reference:
            the collinear twin, within 6 2^-k, see main()).           k
  fuzz3d    space cubics found by fuzz/fuzz_length where elliptic or the
            default method erred (3D stops at 1e-179 ... 1e72).         -
Columns: id family param x0 y0 z0 ... z3, L25 L50 L75 L T25 T50 T75 as in
spec/data/curves3d.tsv (tools/ref_lengths.py computes them: two
independent integrators at 45 and 60 digits that must agree), then a
sub-range t0 t1 next to the cluster and its length Lsub = s(t1) - s(t0),
computed by both integrators of ref_lengths.py, which must agree to 1e-30
relative.

Run: nice /usr/bin/python3 tools/ref_close3d.py   (about a minute)
"""
import os
import sys
import time
from fractions import Fraction

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ref_lengths as R  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "spec", "data", "close3d.tsv")
EPS = [10.0 ** -k for k in range(1, 16)]

# Orthogonal integer frames (u, v, normal w), |u| = |v| = |w| = n.
FRAMES = [((2, 2, 1), (2, -1, -2), (-1, 2, -2), 3),
          ((2, 3, 6), (6, 2, -3), (-3, 6, -2), 7)]


def embed(xy, frame):
    """2D integer points (multiples of n) into 3D: exact doubles."""
    u, v, _, n = frame
    out = []
    for j in range(4):
        a, b = xy[2 * j], xy[2 * j + 1]
        out += [(a * u[k] + b * v[k]) / n for k in range(3)]
    return out


def double_root_cubic(sr, si, A):
    """Control points (P0 = 0) of z' = A (t - s)^2, s = sr + i si, in exact
    rationals: x, y per point."""
    s2 = (sr * sr - si * si, 2 * sr * si)
    a0 = (A * s2[0], A * s2[1])
    a1 = (-2 * A * sr, -2 * A * si)
    d1 = (a0[0] / 3, a0[1] / 3)
    d2 = (d1[0] + a1[0] / 6, d1[1] + a1[1] / 6)
    d3 = (Fraction(A) / 3 + 2 * d2[0] - d1[0], 2 * d2[1] - d1[1])
    out, x, y = [Fraction(0), Fraction(0)], Fraction(0), Fraction(0)
    for d in (d1, d2, d3):
        x, y = x + d[0], y + d[1]
        out += [x, y]
    return out


def moved(c, i, k, eps):
    c = list(c)
    c[3 * i + k] += eps
    return c


def curves():
    rows = []

    def add(family, param, c, t0, t1):
        n = sum(1 for r in rows if r[1] == family) + 1
        rows.append(("%s-%d" % (family, n), family, param,
                     [float(x) for x in c], t0, t1))

    # pair3d: s = 1/2 + i/4 with A = 48 gives the integer points
    # 0, 3+4i, -2+4i, 1; s = 0.3 + 0.5i, A = 400: 0, -64+40i, ...
    bases = [(Fraction(1, 2), Fraction(1, 4), 48),
             (Fraction(3, 10), Fraction(1, 2), 300)]
    for j, (sr, si, A) in enumerate(bases):
        frame = FRAMES[j]
        n, w = frame[3], frame[2]
        xy = [x * n for x in double_root_cubic(sr, si, A)]
        assert all(x.denominator == 1 for x in xy), xy
        c = embed([int(x) for x in xy], frame)
        mid = float(sr)
        add("pair3d", "0.0", c, 0.25, 0.75)
        for e in EPS[:14]:
            # out of the plane (P2 along the normal) and inside it (P1)
            c1 = list(c)
            for k in range(3):
                c1[6 + k] += e * w[k]
            add("pair3d", repr(e), c1, mid - 0.1, mid + 0.1)
            add("pair3d", repr(e), moved(c, 1, j, e), mid - 0.1, mid + 0.1)

    # line3d: 0, 1, 1, 2 along u: x' = 3 ((1 - t)^2 + t^2), roots 1/2 +- i/2
    u = (3, 4, 12)
    base = [k * u[i] for k in (0, 1, 1, 2) for i in range(3)]
    add("line3d", "0.0", base, 0.4, 0.6)
    for e in EPS[:14]:
        add("line3d", repr(e), moved(base, 2, 0, e), 0.4, 0.6)

    # stop3d: P1 = P2 = P3 = 0 (Q = 9 |P0|^2 (1 - t)^4) and 0, u, 0, u
    # (z' = 3 u (1 - 2t)^2), then off the line
    P0 = [116.0, 114.0, 223.0]
    end = P0 + [0.0] * 9
    add("stop3d", "0.0", end, 0.99, 1.0)
    for e in EPS:
        add("stop3d", repr(e), [*P0, e, 0.0, 0.0] + [0.0] * 6, 0.99, 1.0)
        add("stop3d", repr(e), P0 + [0.0] * 3 + [0.0, e, 0.0] + [0.0] * 3,
            0.999, 1.0)
    v = (2.0, -3.0, 6.0)
    mid = [0.0] * 3 + list(v) + [0.0] * 3 + list(v)
    add("stop3d", "0.0", mid, 0.49, 0.51)
    for e in EPS:
        add("stop3d", repr(e), moved(mid, 2, 0, e), 0.49, 0.51)
        add("stop3d", repr(e), moved(mid, 3, 2, e), 0.45, 0.5)

    # spread3d: a collinear reversal (x: 0, 3, -2, 1) and a stop, with a
    # transverse part 2^-k of the size
    for k in (100, 200, 266, 332, 400, 466, 530):
        t = 2.0 ** -k
        add("spread3d", str(k), [0, 0, 0, 3, t, 0, -2, 0, t, 1, 0, 0],
            0.2, 0.4)
        add("spread3d", str(k), [t, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0],
            0.99, 1.0)
        add("spread3d", str(k), [0, 0, 0, 1, t, 0, 0, 0, 0, 1, 0, t],
            0.4, 0.6)

    # fuzz3d: found by fuzz/fuzz_length (the no-skip build)
    for c in FUZZ:
        add("fuzz3d", "-", c, 0.9, 1.0)
    return rows


FUZZ = [
    [-2.4099198651028841e-181, 2.8196062421703744e-179,
     2.8196062421703772e-179, 7.3544917758266727e-186] + [0.0] * 8,
    [116.0, 114.0, 223.0, 1.8089627018547105e-12] + [0.0] * 8,
    [2.612597891257826e-179, 1.4017988820040707e+72] + [0.0] * 10,
    [-67.265625, -13.0, 14.0, -1.1920928955078125e-07] + [0.0] * 8,
    [0.0, -113.0, -112.99999999999989, 0.00927734375] + [0.0] * 8,
    [-3.015625, -0.015625, 126.984375, 0.0390625] + [0.0] * 8,
    [1.542348713665846e-179, 0.0, 2.6991102489152302e-179,
     -9.413749473058141e-184, -9.413749473058141e-184] + [0.0] * 7,
    [2.7955070435193456e-179, -2251799813685248.0, -8388608.0, -8388608.0,
     -8388608.0] + [0.0] * 7,
    [77.0, -49.0, -52.0, 0.038940852973610163] + [0.0] * 8,
    [1.430222333808547e-247, 97.0, 104.0, 0.0099039077758789062] + [0.0] * 8,
    [3.3718765014782548] + [0.0] * 11,
    [-1.0, -1.0000000000000018, -1.0000000000000018] + [0.0] * 9,
    [114.0, 118.0, 3.697038081771171e-273, 0.161285400390625] + [0.0] * 8,
]


def subrange(c, t0, t1):
    """s(t1) - s(t0) by both integrators of ref_lengths.py."""
    return R.range_length(c, 3, t0, t1)


def main():
    t_start = time.time()
    head = ["id", "family", "param"]
    head += ["%s%d" % (c, i) for i in range(4) for c in "xyz"]
    head += ["L25", "L50", "L75", "L", "T25", "T50", "T75", "t0", "t1",
             "Lsub"]
    out = ["\t".join(head)]
    rows = curves()
    for cid, fam, param, c, t0, t1 in rows:
        t0, t1 = float(t0), float(t1)
        twin = c
        if fam == "spread3d":
            # the transverse part t = 2^-k (k >= 100) moves z' by at most
            # 6 t, so the length by at most 6 t (|L(h + dh) - L(h)| <=
            # int |dh|): below 1e-29 of these lengths (>= 1/3).  The
            # collinear twin is the reference (mpmath's polyroots does not
            # converge on Q with roots 2^-400 apart).
            assert int(param) >= 100
            twin = [0.0 if 0 < abs(x) < 2.0 ** -99 else x for x in c]
        ref = R.reference(twin, 3)
        sub = subrange(twin, t0, t1)
        out.append("\t".join([cid, fam, param] + [repr(x) for x in c] +
                             [R.fmt(v) for v in ref] +
                             [repr(t0), repr(t1), R.fmt(sub)]))
    tmp = OUT + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(out) + "\n")
    os.replace(tmp, OUT)
    print("%s: %d rows in %.1fs" % (os.path.relpath(OUT, ROOT), len(rows),
                                    time.time() - t_start))


if __name__ == "__main__":
    main()
