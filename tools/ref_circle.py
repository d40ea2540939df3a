#!/usr/bin/python3
"""tools/ref_circle.py -- references for the circular arcs' closed form
(src/segment/conic_circle.c): spec/data/conic_circle.tsv, read by
spec/circle_spec.lua.

Conics (P0, P1, P2; w), Floater's eq. 1, as doubles: circular arcs of
central angles from 1e-6 to pi - 1e-6, radii from 1e-200 to 1e200, rotated,
centred far from the origin (the points' roundings make them slightly
non-circular, as a drawing's circles are), ellipses on both sides of the
closed form's gate (axes 1 and 1 + e, e from 2^-34 to 2^-8) and short
arcs of ellipses up to 1 + 2^-10.  For each,
independently of arclen: the exact length of the conic the doubles
describe, by mpmath at 30 digits -- the speed |N'D - ND'|/D^2 of N(t)/D(t)
from the definition, integrated by tanh-sinh on [0, 1] split at points
clustered geometrically about t = 1/2 (a near-semicircle's speed peaks
there) and at 1/4, 3/4; the script stops if Gauss-Legendre disagrees by
more than 1e-25 relative.

Columns: name, x0 y0 x1 y1 x2 y2 w (repr of the doubles), length.
Run: /usr/bin/python3 tools/ref_circle.py   (from the repository root; ~1 min)
"""
import math
import os
import random

import mpmath as mp

mp.mp.dps = 30
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "spec", "data", "conic_circle.tsv")


def arc(cx, cy, r, a0, span, ry=None, rot=0.0):
    """The conic of the arc of the ellipse (semi-axes r, ry, rotated by
    rot) from parameter a0 over span (< pi), as doubles: ends on the curve,
    P1 where the end tangents meet, w = cos(span/2)."""
    ry = r if ry is None else ry
    h = span / 2
    cr, sr = math.cos(rot), math.sin(rot)

    def onto(u, v):
        return cx + cr * u - sr * v, cy + sr * u + cr * v

    am = a0 + h
    p0 = onto(r * math.cos(a0), ry * math.sin(a0))
    p1 = onto(r * math.cos(am) / math.cos(h), ry * math.sin(am) / math.cos(h))
    p2 = onto(r * math.cos(a0 + span), ry * math.sin(a0 + span))
    return [p0[0], p0[1], p1[0], p1[1], p2[0], p2[1], math.cos(h)]


def splits():
    pts = {mp.mpf(0), mp.mpf(1), mp.mpf(1) / 4, mp.mpf(3) / 4}
    for k in range(1, 60):
        d = mp.mpf(2) ** -k / 2
        pts.add(mp.mpf(1) / 2 - d)
        pts.add(mp.mpf(1) / 2 + d)
    pts.add(mp.mpf(1) / 2)
    return sorted(pts)


SPLITS = splits()


def length(c, method):
    """The conic moved to P0 = 0 and scaled by a power of two (both exact
    here), measured, and scaled back: quad's error estimate is absolute."""
    x0, y0, x1, y1, x2, y2, w = [mp.mpf(v) for v in c]
    big = max(abs(x1 - x0), abs(y1 - y0), abs(x2 - x0), abs(y2 - y0))
    e = int(mp.floor(mp.log(big, 2)))
    sc = mp.mpf(2) ** -e
    x1, y1, x2, y2 = (x1 - x0) * sc, (y1 - y0) * sc, (x2 - x0) * sc, (y2 - y0) * sc
    x0 = y0 = mp.mpf(0)
    return quad_length(x0, y0, x1, y1, x2, y2, w, method) / sc


def quad_length(x0, y0, x1, y1, x2, y2, w, method):

    def speed(t):
        s = 1 - t
        nx = s * s * x0 + 2 * w * t * s * x1 + t * t * x2
        ny = s * s * y0 + 2 * w * t * s * y1 + t * t * y2
        d = s * s + 2 * w * t * s + t * t
        dnx = -2 * s * x0 + 2 * w * (1 - 2 * t) * x1 + 2 * t * x2
        dny = -2 * s * y0 + 2 * w * (1 - 2 * t) * y1 + 2 * t * y2
        dd = -2 * s + 2 * w * (1 - 2 * t) + 2 * t
        return mp.hypot(dnx * d - nx * dd, dny * d - ny * dd) / (d * d)

    return mp.quad(speed, SPLITS, method=method)


def cases():
    rnd = random.Random(31)
    out = []
    for span in [1e-6, 1e-3, 0.1, 1.0, math.pi / 2, 2.0, 3.0, 3.1, math.pi - 1e-3,
                 math.pi - 1e-6]:
        out.append(("span %.9g" % span, arc(0, 0, 1, -span / 2, span)))
        out.append(("span %.9g rotated" % span, arc(0.5, -2, 3.25, rnd.uniform(0, 6), span)))
    for r in [1e-200, 1e-30, 1e-8, 0.2, 1e8, 1e30, 1e200]:
        out.append(("radius %g" % r, arc(r / 3, -r / 7, r, 0.3, math.pi / 2)))
    # a drawing's quarter circles: small radii far from the origin
    for cx, cy, r in [(987.123, 456.789, 0.2), (1000, 1000, 0.237), (-5e4, 3e4, 1.5),
                      (1e6, 1e6, 0.01)]:
        for q in range(4):
            out.append(("quarter %d at %g %g r %g" % (q, cx, cy, r),
                        arc(cx, cy, r, q * math.pi / 2, math.pi / 2)))
    for _ in range(12):
        out.append(("random", arc(rnd.uniform(-100, 100), rnd.uniform(-100, 100),
                                  10 ** rnd.uniform(-3, 3), rnd.uniform(0, 6.3),
                                  rnd.uniform(0.01, 3.1))))
    # ellipses about the gate: axes 1 and 1 + e
    for k in [34, 31, 30, 29, 26, 20, 14, 8]:
        e = 2.0 ** -k
        for span in [0.2, math.pi / 2, 3.0]:
            out.append(("ellipse 1+2^-%d span %g" % (k, span),
                        arc(0.25, 0.75, 1.0, 0.1, span, ry=1 + e, rot=0.7)))
    # short arcs of eccentric ellipses: D up to 2^-10 passes when D sin(al)
    # stays below 2^-30 (the bound is second order in D sin(al), not in D)
    for k, span in [(10, 1e-6), (10, 1e-5), (12, 2e-6), (16, 1e-4)]:
        out.append(("short arc of 1+2^-%d span %g" % (k, span),
                    arc(-3.5, 2.0, 2.0, 0.4, span, ry=2 * (1 + 2.0 ** -k), rot=-0.3)))
    return out


def main():
    rows = []
    for name, c in cases():
        a = length(c, "tanh-sinh")
        b = length(c, "gauss-legendre")
        if abs(a - b) > mp.mpf(10) ** -25 * abs(a):
            raise SystemExit("quadratures disagree for %s: %s %s" % (name, a, b))
        rows.append("\t".join([name] + [repr(float(v)) for v in c] + [mp.nstr(a, 25)]))
    with open(OUT, "w") as f:
        f.write("# generated by tools/ref_circle.py -- do not edit\n")
        f.write("name\tx0\ty0\tx1\ty1\tx2\ty2\tw\tlength\n")
        f.write("\n".join(rows) + "\n")
    print("wrote %d rows to %s" % (len(rows), OUT))


if __name__ == "__main__":
    main()
