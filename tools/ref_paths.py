#!/usr/bin/python3
"""tools/ref_paths.py -- reference lengths of SVG paths (spec/data/paths.tsv).

An independent reading of SVG path data (SVG 1.1 section 8.3, arcs by the
endpoint-to-center conversion of appendix F.6.5/F.6.6) into exact primitives
-- lines, quadratic and cubic Beziers, elliptical arcs -- measured with mpmath
at 40 digits: Gauss-Legendre/tanh-sinh quadrature of the speed, checked by
two quadrature degrees; the ellipse arc by the integral of
sqrt(rx^2 sin^2 th + ry^2 cos^2 th) over its parametric angles (the arc
itself, not a cubic approximation).

For paths without arcs every primitive is one segment of arclen's path, so
the path time (segment index + parameter, MetaPost's convention) at a
distance is defined independently of arclen: the file also gives, for a few
distances s, the time and the point (mpmath findroot on the length).

Columns: id, d, L, arcs (number of arcs), arcscale (sum over arcs of
max(|rx|, |ry|, chord/2), the scale arclen.path.svg applies arc_tol to),
goals, times, xs, ys (space-separated; empty for paths with arcs).

Usage: /usr/bin/python3 tools/ref_paths.py   (from the repository root)
"""
import os
import re

import mpmath as mp

mp.mp.dps = 40

PATHS = [
    ("henkel1", "M0 0 C10 0 10 10 0 0"),
    ("lines", "m10 10 h 5 v-5 l-2-2-3,3z"),
    ("lines-abs", "M 1 1 L 4 5 H -2 V 0 L 1 1"),
    ("quads", "M0 0 Q5 10 10 0 T20 0 t10 0"),
    ("quads-rel", "M0,0 q 3,8 6,0 t 6,0 T 20,-3"),
    ("smooth", "M0 0 C0 5 5 5 5 0 S10 -5 10 0 s5 5 5 0"),
    ("s-first", "M0 0 S5 5 10 0"),
    ("numbers", "M1e1-.5.5.5L1E-1,2e+0 l-.5.5.5.5"),
    ("subpaths", "M0 0 L10 0 L10 10 Z M20 0 C25 5 30 -5 35 0 m5 5 l1 1"),
    ("closed-relative", "M5 5 l10 0 l0 10 z l-5 -5"),
    ("loop", "M100 100 C300 0 0 0 200 100 C250 200 -100 300 100 100"),
    ("far", "M100000000 100000000 C100000010 100000000 100000010 100000010 100000000 100000000"),
    ("tiny", "M0 0 C1e-8 0 1e-8 1e-8 0 2e-8 L-1e-8 0"),
    ("huge", "M0 0 C1e20 0 1e20 1e20 0 2e20"),
    ("glyph-like", "M 71 0 L 71 700 L 250 700 Q 360 700 415 652 Q 470 604 470 515 "
                   "Q 470 426 415 378 Q 360 330 250 330 L 165 330 L 165 0 Z "
                   "M 165 410 L 245 410 Q 310 410 343 440 Q 376 470 376 515 "
                   "T 343 590 T 245 620 L 165 620 Z"),
    # arcs
    ("circle-half", "M10 0 A10 10 0 1 1 -10 0"),
    ("circle-full", "M10 0 A10 10 0 1 1 -10 0 A10 10 0 1 1 10 0"),
    ("ellipse-rot", "M10 0 A10 5 30 1 1 -10 0"),
    ("ellipse-small", "M0 0 A40 25 -45 0 0 30 20"),
    ("arc-flags", "M0 0a5,5 0 01 10,0a5 5 0 1010 0"),
    ("arc-scaled", "M0 0 A1 2 0 0 1 20 10"),
    ("arc-mixed", "M0 0 L10 0 A5 5 0 0 1 15 5 Q15 15 5 15 Z"),
]

NUM = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
SEP = re.compile(r"[\s,]*")


class Reader:
    def __init__(self, d):
        self.d, self.i = d, 0

    def skip(self):
        self.i = SEP.match(self.d, self.i).end()

    def number(self):
        self.skip()
        m = NUM.match(self.d, self.i)
        assert m, "number expected at %d in %r" % (self.i, self.d)
        self.i = m.end()
        return mp.mpf(m.group(0))

    def flag(self):
        self.skip()
        c = self.d[self.i]
        assert c in "01"
        self.i += 1
        return int(c)

    def command(self):
        self.skip()
        if self.i < len(self.d) and self.d[self.i].isalpha():
            c = self.d[self.i]
            self.i += 1
            return c
        return None

    def more(self):
        self.skip()
        return self.i < len(self.d) and not self.d[self.i].isalpha()

    def done(self):
        self.skip()
        return self.i >= len(self.d)


def commands(d):
    """Each command of path data d as (C, before, after, prim): C the command
    letter in upper case, before and after the current point around it,
    prim its primitive -- ('line', p0, p1), ('quad', p0, q, p1),
    ('cubic', p0..p3), ('arc', rx, ry, phi_deg, large, sweep, p0, p1) --
    or None for M and Z (Z: after is the subpath's start).  Relative
    coordinates and the reflected control points of S and T resolved (SVG
    1.1 section 8.3); parse() here and ref_svg.py's vertices() read it."""
    r = Reader(d)
    cur = start = (mp.mpf(0), mp.mpf(0))
    lastc = lastq = None
    cmd = None
    while not r.done():
        c = r.command()
        if c is not None:
            cmd = c
        elif cmd in "Mm":
            cmd = "l" if cmd == "m" else "L"
        up, rel = cmd.upper(), cmd.islower()
        ox, oy = cur if rel else (0, 0)
        newc = newq = None
        prim = None
        if up == "Z":
            p = start
        elif up == "M":
            p = start = (r.number() + ox, r.number() + oy)
        elif up == "L":
            p = (r.number() + ox, r.number() + oy)
            prim = ("line", cur, p)
        elif up == "H":
            p = (r.number() + (cur[0] if rel else 0), cur[1])
            prim = ("line", cur, p)
        elif up == "V":
            p = (cur[0], r.number() + (cur[1] if rel else 0))
            prim = ("line", cur, p)
        elif up in "CS":
            if up == "C":
                c1 = (r.number() + ox, r.number() + oy)
            else:
                c1 = (2 * cur[0] - lastc[0], 2 * cur[1] - lastc[1]) if lastc else cur
            c2 = (r.number() + ox, r.number() + oy)
            p = (r.number() + ox, r.number() + oy)
            prim = ("cubic", cur, c1, c2, p)
            newc = c2
        elif up in "QT":
            if up == "Q":
                q = (r.number() + ox, r.number() + oy)
            else:
                q = (2 * cur[0] - lastq[0], 2 * cur[1] - lastq[1]) if lastq else cur
            p = (r.number() + ox, r.number() + oy)
            prim = ("quad", cur, q, p)
            newq = q
        elif up == "A":
            rx, ry, phi = r.number(), r.number(), r.number()
            fa, fs = r.flag(), r.flag()
            p = (r.number() + ox, r.number() + oy)
            prim = ("arc", rx, ry, phi, fa, fs, cur, p)
        else:
            raise ValueError(cmd)
        yield up, cur, p, prim
        cur = p
        lastc, lastq = newc, newq


def parse(d):
    """Primitives of path data d, as commands() gives them; Z draws a line
    back to the subpath's start unless already there."""
    prims = []
    for up, before, after, prim in commands(d):
        if up == "Z":
            if before != after:
                prims.append(("line", before, after))
        elif prim is not None:
            prims.append(prim)
    return prims


def cubic_of(prim):
    if prim[0] == "line":
        p0, p1 = prim[1], prim[2]
        return [p0, p0, p1, p1]     # same point set; speed differs, length not
    if prim[0] == "quad":
        p0, q, p1 = prim[1:]
        return [p0, q, p1]          # degree 2 Bernstein
    return list(prim[1:])


def bezier(ctrl, t):
    n = len(ctrl) - 1
    x = y = mp.mpf(0)
    for i, p in enumerate(ctrl):
        b = mp.binomial(n, i) * t ** i * (1 - t) ** (n - i)
        x += b * p[0]
        y += b * p[1]
    return x, y


def speed(ctrl, t):
    n = len(ctrl) - 1
    d = [(n * (ctrl[i + 1][0] - ctrl[i][0]), n * (ctrl[i + 1][1] - ctrl[i][1]))
         for i in range(n)]
    x, y = bezier(d, t) if n > 1 else d[0]
    return mp.sqrt(x * x + y * y)


def integrate(f, a, b):
    pts = mp.linspace(a, b, 9)
    v1 = mp.quad(f, pts, method="gauss-legendre")
    v2 = mp.quad(f, pts, method="tanh-sinh")
    assert abs(v1 - v2) <= mp.mpf(10) ** -28 * (abs(v1) + mp.mpf(10) ** -300), (v1, v2)
    return v2


def seg_length(prim, t=1):
    if prim[0] == "line":
        (x0, y0), (x1, y1) = prim[1], prim[2]
        return t * mp.sqrt((x1 - x0) ** 2 + (y1 - y0) ** 2)
    ctrl = cubic_of(prim)
    return integrate(lambda u: speed(ctrl, u), 0, t) if t > 0 else mp.mpf(0)


def arc_length(prim):
    """SVG F.6.5 (endpoint to center) and F.6.6 (radii correction)."""
    _, rx, ry, phi, fa, fs, (x1, y1), (x2, y2) = prim
    if (x1, y1) == (x2, y2):
        return mp.mpf(0), mp.mpf(0)
    chord2 = mp.sqrt((x2 - x1) ** 2 + (y2 - y1) ** 2) / 2
    scale = max(abs(rx), abs(ry), chord2)
    rx, ry = abs(rx), abs(ry)
    if rx == 0 or ry == 0:
        return 2 * chord2, mp.mpf(0)
    ph = mp.radians(phi)
    c, s = mp.cos(ph), mp.sin(ph)
    dx, dy = (x1 - x2) / 2, (y1 - y2) / 2
    xp, yp = c * dx + s * dy, -s * dx + c * dy
    lam = xp ** 2 / rx ** 2 + yp ** 2 / ry ** 2
    if lam > 1:
        rx, ry = mp.sqrt(lam) * rx, mp.sqrt(lam) * ry
    num = rx ** 2 * ry ** 2 - rx ** 2 * yp ** 2 - ry ** 2 * xp ** 2
    den = rx ** 2 * yp ** 2 + ry ** 2 * xp ** 2
    k = mp.sqrt(max(num / den, 0))
    if fa == fs:
        k = -k
    cxp, cyp = k * rx * yp / ry, -k * ry * xp / rx

    def ang(ux, uy, vx, vy):
        a = mp.atan2(ux * vy - uy * vx, ux * vx + uy * vy)
        return a

    th1 = ang(1, 0, (xp - cxp) / rx, (yp - cyp) / ry)
    dth = ang((xp - cxp) / rx, (yp - cyp) / ry, (-xp - cxp) / rx, (-yp - cyp) / ry)
    if not fs and dth > 0:
        dth -= 2 * mp.pi
    elif fs and dth < 0:
        dth += 2 * mp.pi
    f = lambda th: mp.sqrt((rx * mp.sin(th)) ** 2 + (ry * mp.cos(th)) ** 2)
    a, b = (th1, th1 + dth) if dth > 0 else (th1 + dth, th1)
    return integrate(f, a, b), scale


def point_at(prims, lens, s):
    """Path time and point at distance s (arc-free paths)."""
    acc = mp.mpf(0)
    for k, (prim, L) in enumerate(zip(prims, lens)):
        if s <= acc + L or k == len(prims) - 1:
            goal = s - acc
            if prim[0] == "line":
                t = goal / L
                (x0, y0), (x1, y1) = prim[1], prim[2]
                return k + t, x0 + t * (x1 - x0), y0 + t * (y1 - y0)
            ctrl = cubic_of(prim)
            t = mp.findroot(lambda u: seg_length(prim, u) - goal, goal / L,
                            tol=mp.mpf(10) ** -32)
            x, y = bezier(ctrl, t)
            return k + t, x, y
        acc += L
    raise ValueError


def fmt(x):
    return mp.nstr(x, 30, min_fixed=-mp.inf, max_fixed=mp.inf) if x != 0 else "0"


def write_table(path, script, columns, rows):
    """A table of spec/data as this script and ref_svg.py write it: a
    comment naming the script and mpmath (version, digits now), the column
    names, then the rows (lists of strings), tab-separated."""
    with open(path, "w") as f:
        f.write("# generated by %s (mpmath %s, %d digits)\n" % (script, mp.__version__, mp.mp.dps))
        f.write("\t".join(columns) + "\n")
        for r in rows:
            f.write("\t".join(r) + "\n")


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    rows = []
    for pid, d in PATHS:
        prims = parse(d)
        lens, arcs, arcscale = [], 0, mp.mpf(0)
        for prim in prims:
            if prim[0] == "arc":
                L, sc = arc_length(prim)
                arcs += 1
                arcscale += sc
            else:
                L = seg_length(prim)
            lens.append(L)
        total = mp.fsum(lens)
        goals, times, xs, ys = [], [], [], []
        if arcs == 0:
            for frac in ("0.1", "0.37", "0.5", "0.81", "0.999"):
                s = total * mp.mpf(frac)
                T, x, y = point_at(prims, lens, s)
                goals.append(fmt(s)); times.append(fmt(T))
                xs.append(fmt(x)); ys.append(fmt(y))
        rows.append([pid, d, fmt(total), str(arcs), fmt(arcscale),
                     " ".join(goals), " ".join(times), " ".join(xs), " ".join(ys)])
    out = os.path.join(root, "spec", "data", "paths.tsv")
    write_table(out, "tools/ref_paths.py",
                ["id", "d", "L", "arcs", "arcscale", "goals", "times", "xs", "ys"], rows)
    print("wrote", out, len(rows), "paths")


if __name__ == "__main__":
    main()
