#!/usr/bin/env python3
"""tools/ref_tex.py -- the references of make luatex's TeX documents
(examples/tex/), with mpmath at 40 digits, independent of arclen:

  spec/data/tex_marks.tsv  points and unit tangents at arc lengths on the
                           curves of examples/tex/tikz_marks.tex (pt)
  spec/data/tex_bend.tsv   points at distances from the end of the
                           #1079-style curve (bending arrow tips), and |z'|
  spec/data/tex_mp.tsv     lengths, points and dash ends of
                           examples/tex/mp_arclen.tex and plain_mp.tex

The curves are listed here and in the documents, with coordinates that are
whole points (so TeX holds them exactly).  Run: python3 tools/ref_tex.py
"""
import os
from mpmath import mp, mpf, sqrt, quad, floor

mp.dps = 40

# name: (x0, y0, x1, y1, x2, y2, x3, y3), as in examples/tex/tikz_marks.tex
CURVES = {
    "wave": (0, 0, 100, 150, 200, -150, 300, 0),
    "arch": (0, 0, 20, 90, 120, 90, 140, 0),
    "scurve": (0, 0, 350, 300, -50, 300, 300, 0),
    "tight": (0, 0, 50, 100, 98, 2, 100, 0),       # a short end handle (pgf #1079)
}
# the lengths and fractions marked (tikz_marks.tex), the step
LENGTHS = [10, 100]
FRACTIONS = [mpf(1) / 4, mpf(1) / 2, mpf(3) / 4]
STEP = 5
TEXT_GLYPHS, TEXT_WIDTH = 40, mpf("5.25")
# distances from the end for the bending check
BEND = [1, 2, 5, 10, 20]


def point(c, t):
    s = 1 - t
    b = (s ** 3, 3 * t * s * s, 3 * t * t * s, t ** 3)
    return (sum(b[i] * c[2 * i] for i in range(4)), sum(b[i] * c[2 * i + 1] for i in range(4)))


def deriv(c, t):
    s = 1 - t
    d = lambda k: 3 * (s * s * (c[k + 2] - c[k]) + 2 * t * s * (c[k + 4] - c[k + 2])
                       + t * t * (c[k + 6] - c[k + 4]))
    return d(0), d(1)


def speed(c, t):
    dx, dy = deriv(c, t)
    return sqrt(dx * dx + dy * dy)


def length(c, t0=0, t1=1):
    return quad(lambda t: speed(c, t), [t0 + (t1 - t0) * k / 8 for k in range(9)])


def time_at(c, s):
    """The time at arc length s: bisection to 2^-12, then Newton (quadratic)."""
    L = length(c)
    if s <= 0:
        return mpf(0)
    if s >= L:
        return mpf(1)
    lo, hi = mpf(0), mpf(1)
    for _ in range(12):
        mid = (lo + hi) / 2
        if length(c, 0, mid) < s:
            lo = mid
        else:
            hi = mid
    t = (lo + hi) / 2
    for _ in range(6):
        t = t - (length(c, 0, t) - s) / speed(c, t)
    assert abs(length(c, 0, t) - s) < mpf(10) ** -30
    return t


def row(*cols):
    return "\t".join(mp.nstr(v, 20) if not isinstance(v, str) else v for v in cols) + "\n"


def mark(c, s):
    t = time_at(c, s)
    x, y = point(c, t)
    dx, dy = deriv(c, t)
    n = sqrt(dx * dx + dy * dy)
    return x, y, dx / n, dy / n


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "spec", "data")
    with open(os.path.join(root, "tex_marks.tsv"), "w") as f:
        f.write("# tools/ref_tex.py: curve, label, k, s (pt), x, y, cos, sin of the tangent\n")
        for name, c in CURVES.items():
            c = [mpf(v) for v in c]
            L = length(c)
            f.write(row(name, "length", "0", L, 0, 0, 0, 0))
            for s in LENGTHS:
                f.write(row(name, "len%d" % s, "0", mpf(s), *mark(c, mpf(s))))
            for fr in FRACTIONS:
                f.write(row(name, "frac%s" % mp.nstr(fr, 3), "0", fr * L, *mark(c, fr * L)))
            if name == "wave":
                # text along path: 40 glyphs of Latin Modern Mono (5.25pt)
                # from the start, each centre half a width into its box
                for k in range(TEXT_GLYPHS):
                    sk = (k + mpf(1) / 2) * TEXT_WIDTH
                    f.write(row(name, "text", str(k), sk, *mark(c, sk)))
            n = int(floor(L / STEP))
            for k in range(n + 1):
                f.write(row(name, "step", str(k), mpf(k * STEP), *mark(c, mpf(k * STEP))))
    with open(os.path.join(root, "tex_bend.tsv"), "w") as f:
        f.write("# tools/ref_tex.py: curve, d (pt from the end), x, y, |z'| there\n")
        for name in ("tight", "wave"):
            c = [mpf(v) for v in CURVES[name]]
            L = length(c)
            for d in BEND:
                t = time_at(c, L - d)
                x, y = point(c, t)
                f.write(row(name, str(d), x, y, speed(c, t)))
    with open(os.path.join(root, "tex_mp.tsv"), "w") as f:
        f.write("# tools/ref_tex.py: MetaPost (bp): curve, label, x, y, t, cos, sin; label -1:\n"
                "# the length (in x); a length s: the point, time and direction there;\n"
                "# pts:k the k-th of arclen_points(p, 11), at k L / 10\n")
        for name in ("wave", "scurve"):
            c = [mpf(v) for v in CURVES[name]]
            L = length(c)
            f.write(row(name, "-1", L, 0, 0, 0, 0))
            # points, and on the wave the ends of the first four dashes of
            # arclen_dashed(wave, 0)(12, 4, 2, 4)
            extra = (12, 16, 18, 22, 34, 38, 40) if name == "wave" else ()
            for s in sorted((0, 50, 100, 200) + extra):
                t = time_at(c, mpf(s))
                x, y, ca, sa = mark(c, mpf(s))
                f.write(row(name, str(s), x, y, t, ca, sa))
            for k in range(11):
                x, y, _, _ = mark(c, k * L / 10)
                f.write(row(name, "pts:%d" % k, x, y, 0, 0, 0))

if __name__ == "__main__":
    main()
