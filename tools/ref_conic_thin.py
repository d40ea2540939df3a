#!/usr/bin/python3
"""References for the thin-hyperbola family of the exact conic length.

Writes spec/data/conic_thin.tsv: conics (p0, p1, p2; w) with w > 1 whose
control triangle is nearly flat with the apex angle near pi (the arc runs
far out on one arm of a hyperbola, where the semi-diameters U - V and
U + V of conic_length.c are far apart), for
  w      = 1 + 2^-k (k = 52, 40, 26, 12, 6, 3), 1.1598, 1.5, 2, 6.77, 18,
           30, 50, 80, 200, 1000;
  theta  = the turning angle at p1 (pi minus the apex angle),
           1e-1, 1e-3, 1e-5, 1e-7, 1e-9, 1e-11;
  ratio  = |p1 - p0| / |p2 - p1|: 1e-8 .. 1e8, and E^2, E^-2, E^2 (1 + 1e-4)
           with E = w + sqrt(w^2 - 1), where U + V (or U - V) is
           E^2 c - a (or c - E^2 a) over a common factor and cancels most;
plus the conic where conic_length was 1.3e-14 off (w = 1.1598) and, for
every w, ratio E^2 at theta 3e-3 and 3e-4 (where that sum cancelled by 4
.. 2^10, the old code's worst band).  Every (w, theta) above gets the ratio
E^2 and three others drawn with a fixed seed;
orientation, size and offset are drawn too, then rounded to doubles: the
reference is the length of the conic of those doubles.

Each row: the whole length L, the lengths over three sub-ranges [t0, t1]
(doubles), and for the inverse the parameters T1, T2 where the length from
0 is L/3 and 2L/3, with the speed V1, V2 there (a spec measures
|t - T| V / L).

Method: int |C'(t)| dt by Gauss-Legendre on panels clustered geometrically
about every complex singularity of the speed (the roots of |P(t)|^2 and of
the denominator D(t), P and D as in tools/conic_speed.py), the
legs formed exactly from the doubles; each length twice, at 60 and 70
digits with other panel ratios, the two agreeing to 1e-40 relative (else
the script stops).  The values are written with 40 digits.  Independent of
the C code (no Carlson form, no semi-axes).
Run: nice python3 tools/ref_conic_thin.py   (about 25 minutes; with
`resume`, the rows already in the file are kept; with `times`, only the
T and V columns are recomputed)

With `short` it writes spec/data/conic_short.tsv instead: for every conic
of conic_thin.tsv (by name) four short pieces [t0, t0 + h], h = 1e-4,
1e-7, 1e-10 and 1e-13, t0 drawn from SHORT_STARTS with a fixed seed (the
ends, the middle, where a piece's control points rounded at the whole
arc's scale lose most), the same two-precision check (about 3 minutes).
"""
import os
import random
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from conic_speed import ConicSpeed  # noqa: E402  (shared with ref_conic)

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "spec", "data")

WEIGHTS = [("1+2^-52", 1 + 2.0 ** -52), ("1+2^-40", 1 + 2.0 ** -40),
           ("1+2^-26", 1 + 2.0 ** -26), ("1+2^-12", 1 + 2.0 ** -12),
           ("1+2^-6", 1 + 2.0 ** -6), ("1+2^-3", 1 + 2.0 ** -3),
           ("1.5", 1.5), ("1.1598", 1.1598), ("2", 2.0), ("6.77", 6.77),
           ("18", 18.0), ("30", 30.0), ("50", 50.0), ("80", 80.0),
           ("200", 200.0), ("1000", 1000.0)]
THETAS = [1e-1, 1e-3, 1e-5, 1e-7, 1e-9, 1e-11]
RATIOS = [1e-8, 1e-6, 1e-4, 1e-2, 1.0, 1e2, 1e4, 1e6, 1e8]
SUBRANGES = [(0.25, 0.75), (0.0, 0.3), (0.6, 1.0), (0.001, 0.002),
             (0.5, 0.5001), (0.9, 0.999), (0.1, 0.9)]

SHORT_WIDTHS = [1e-4, 1e-7, 1e-10, 1e-13]
SHORT_STARTS = [1e-9, 1e-3, 0.1, 0.3, 0.5, 0.7, 0.9, 0.999, None]   # None: 1 - 2h


class Conic(ConicSpeed):
    """The speed of (p0, p1, p2; w) from the exact legs and its
    singularities for one precision (tools/conic_speed.py)."""

    def length(self, t0, t1, ratio):
        """int_t0^t1 of the speed, t0 < t1 (mpf)."""
        with mp.workdps(self.dps):
            return mp.quad(self.speed, self.panels(t0, t1, ratio),
                           method="gauss-legendre")


def checked_length(c60, c70, t0, t1):
    t0, t1 = mp.mpf(t0), mp.mpf(t1)
    L1 = c60.length(t0, t1, 2)
    L2 = c70.length(t0, t1, 3)
    with mp.workdps(70):
        if abs(L1 - L2) > abs(L2) * mp.mpf(10) ** -40:
            raise RuntimeError("lengths disagree: %s %s" % (L1, L2))
    return L2


def time_at(c, s):
    """T in [0, 1] with int_0^T speed = s: Newton from bisection, at the
    conic's precision (only ~20 digits of T are used)."""
    with mp.workdps(c.dps):
        lo, hi = mp.mpf(0), mp.mpf(1)
        for _ in range(20):                  # bisect to a start
            mid = (lo + hi) / 2
            if c.length(mp.mpf(0), mid, 2) < s:
                lo = mid
            else:
                hi = mid
        t = (lo + hi) / 2
        for _ in range(40):
            f = c.length(mp.mpf(0), t, 2) - s
            tn = t - f / c.speed(t)
            tn = min(max(tn, lo), hi)
            if abs(tn - t) <= mp.mpf(10) ** -30:
                return tn
            t = tn
        raise RuntimeError("Newton did not converge")


def times(p, w, L):
    """T1, V1, T2, V2 (25 digits): where the length from 0 is L/3, 2L/3."""
    c30 = Conic(p, w, 30)
    tv = []
    with mp.workdps(30):
        for frac in (mp.mpf(1) / 3, mp.mpf(2) / 3):
            T = time_at(c30, frac * L)
            tv += [num(T, 25), num(c30.speed(T), 25)]
    return tv


def retime(path):
    """`ref_conic_thin.py times`: the T and V columns again from the
    points, w and L of the file (at first s = L/3 was formed at 15 digits)."""
    lines = open(path).read().splitlines()
    out = [lines[0]]
    for line in lines[1:]:
        f = line.split("\t")
        p = ((float(f[1]), float(f[2])), (float(f[3]), float(f[4])),
             (float(f[5]), float(f[6])))
        with mp.workdps(45):
            L = mp.mpf(f[9])
        out.append("\t".join(f[:11] + times(p, float(f[7]), L)))
    with open(path, "w") as fo:
        fo.write("\n".join(out) + "\n")


def triangle(rnd, w, theta, ratio):
    """p0, p1, p2 as doubles: legs |a| = ratio |c|, the longer of size in
    [0.5, 20], turning by theta (either sign) at p1, p0 off the origin."""
    big = rnd.uniform(0.5, 20)
    la, lc = (big, big / ratio) if ratio >= 1 else (big * ratio, big)
    phi = rnd.uniform(-mp.pi, mp.pi)
    sg = rnd.choice([-1, 1])
    with mp.workdps(40):
        ax, ay = la * mp.cos(phi), la * mp.sin(phi)
        cx, cy = lc * mp.cos(phi + sg * theta), lc * mp.sin(phi + sg * theta)
        ox, oy = rnd.uniform(-10, 10), rnd.uniform(-10, 10)
        p0 = (ox, oy)
        p1 = (float(ox + ax), float(oy + ay))
        p2 = (float(p1[0] + cx), float(p1[1] + cy))
    return p0, p1, p2


def turning(p):
    """The actual turning angle of the double triangle (mpmath)."""
    with mp.workdps(40):
        P = [[mp.mpf(x) for x in q] for q in p]
        a = [P[1][k] - P[0][k] for k in range(2)]
        c = [P[2][k] - P[1][k] for k in range(2)]
        cr = a[0] * c[1] - a[1] * c[0]
        dt = a[0] * c[0] + a[1] * c[1]
        return mp.atan2(cr, dt)


def cases():
    rnd = random.Random(20261203)
    out = [("brief: w=1.1598, ratio E^2, 1.3e-14 off",
            (0.0, 0.0), (-4.025882701788625, 6.144861889904947),
            (-5.350731513768052, 8.153345454837519), 1.1598)]
    for wname, w in WEIGHTS:
        E2 = float((mp.mpf(w) + mp.sqrt(mp.mpf(w) ** 2 - 1)) ** 2)
        extra = [("E^2", E2), ("E^-2", 1 / E2), ("E^2(1+1e-4)", E2 * (1 + 1e-4))]
        for theta in THETAS:
            picks = [extra[0]] + rnd.sample(
                [("%g" % r, r) for r in RATIOS] + extra[1:], 3)
            for rname, ratio in picks:
                p0, p1, p2 = triangle(rnd, w, theta, ratio)
                out.append(("w=%s theta=%g ratio=%s" % (wname, theta, rname),
                            p0, p1, p2, w))
    # the band where U + V cancels by 4 .. 2^10 (the old code's worst,
    # as the w = 1.1598 conic): ratio E^2, theta 3e-3 and 3e-4; drawn last
    # so that the rows above do not change
    rnd = random.Random(31)
    for wname, w in WEIGHTS:
        E2 = float((mp.mpf(w) + mp.sqrt(mp.mpf(w) ** 2 - 1)) ** 2)
        for theta in (3e-3, 3e-4):
            p0, p1, p2 = triangle(rnd, w, theta, E2)
            out.append(("w=%s theta=%g ratio=E^2 (band)" % (wname, theta),
                        p0, p1, p2, w))
    return out


def num(x, digits=40):
    return mp.nstr(x, digits, min_fixed=-mp.inf, max_fixed=mp.inf)


def main():
    path = os.path.join(DATA, "conic_thin.tsv")
    rnd = random.Random(7)
    # `ref_conic_thin.py resume`: rows already in the file are kept (the
    # draws are repeated, so the rest is what a full run writes)
    done = {}
    if sys.argv[1:] == ["resume"] and os.path.exists(path):
        for line in open(path).read().splitlines()[1:]:
            done[line.split("\t")[0]] = line + "\n"
    with open(path, "w") as f:
        f.write("name\tx0\ty0\tx1\ty1\tx2\ty2\tw\tturn\tL\tsub\tT1\tV1\tT2\tV2\n")
        for name, p0, p1, p2, w in cases():
            p = (p0, p1, p2)
            th = turning(p)
            if abs(mp.sin(th)) <= 64 * 2.0 ** -52:
                continue          # flat to rounding: not a conic
            subs = [SUBRANGES[0]] + rnd.sample(SUBRANGES[1:], 2)
            if name in done:
                f.write(done[name])
                continue
            c60, c70 = Conic(p, w, 60), Conic(p, w, 70)
            L = checked_length(c60, c70, 0, 1)
            sub = " ".join("%r:%r:%s" % (t0, t1, num(checked_length(c60, c70, t0, t1)))
                           for t0, t1 in subs)
            tv = times(p, w, L)
            f.write("%s\t%s\t%s\t%s\t%s\t%s\t%s\n" % (
                name, "\t".join(repr(float(x)) for x in p0 + p1 + p2),
                repr(float(w)), mp.nstr(th, 5), num(L), sub, "\t".join(tv)))
            f.flush()
            print(name, mp.nstr(L, 20), file=sys.stderr)


def short():
    """spec/data/conic_short.tsv: name, then t0:t1:L for four short pieces."""
    rnd = random.Random(31)
    rows = open(os.path.join(DATA, "conic_thin.tsv")).read().splitlines()[1:]
    with open(os.path.join(DATA, "conic_short.tsv"), "w") as f:
        f.write("name\tsub\n")
        for line in rows:
            col = line.split("\t")
            xs = [float(x) for x in col[1:7]]
            p, w = ((xs[0], xs[1]), (xs[2], xs[3]), (xs[4], xs[5])), float(col[7])
            c60, c70 = Conic(p, w, 60), Conic(p, w, 70)
            subs = []
            for h in SHORT_WIDTHS:
                t0 = rnd.choice(SHORT_STARTS)
                t0 = 1 - 2 * h if t0 is None else t0
                t1 = t0 + h
                subs.append("%r:%r:%s" % (t0, t1, num(checked_length(c60, c70, t0, t1))))
            f.write("%s\t%s\n" % (col[0], " ".join(subs)))
            f.flush()


if __name__ == "__main__":
    if sys.argv[1:] == ["times"]:
        retime(os.path.join(DATA, "conic_thin.tsv"))
    elif sys.argv[1:] == ["short"]:
        short()
    else:
        main()
