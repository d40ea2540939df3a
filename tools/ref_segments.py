#!/usr/bin/python3
"""References for the segments of four kinds (issue 31): lines, quadratic
Beziers and conics (rational quadratics, weights 1, w, 1), 2D and 3D.

Writes spec/data/segments_lengths.tsv: per segment its kind, dimension and
numbers (the doubles as written, 17 digits), the lengths from t = 0 to 1/4,
1/2, 3/4 and 1, the length over [0.2, 0.7], and for s = L/3 and 2L/3 the
time T (len(0, T) = s) and the speed V there.

Independent of the C code: each length is mpmath's quad (tanh-sinh, 40
digits) of the speed |B'(t)| written from the definitions (quadratic:
2|(1-t)(P1-P0) + t(P2-P1)|; conic: the quotient rule on the homogeneous
form), on pieces split at the speed's zeros and sampled extrema, each
piece's error estimate checked; times by Newton's method on that length.
Run: nice /usr/bin/python3 tools/ref_segments.py   (about a minute)
"""
import os

import mpmath as mp

mp.mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "spec", "data")


def points(seg, dim, n):
    return [[mp.mpf(seg[i * dim + k]) for k in range(dim)] for i in range(n)]


def speed_fn(kind, seg, dim):
    """t -> |C'(t)| (mpf), from the definitions."""
    if kind == "line":
        p = points(seg, dim, 2)
        v = mp.sqrt(sum((p[1][k] - p[0][k]) ** 2 for k in range(dim)))
        return lambda t: v
    if kind == "quad":
        p = points(seg, dim, 3)

        def f(t):
            return 2 * mp.sqrt(sum(((1 - t) * (p[1][k] - p[0][k])
                                    + t * (p[2][k] - p[1][k])) ** 2
                                   for k in range(dim)))
        return f
    p = points(seg, dim, 3)
    w = mp.mpf(seg[3 * dim])

    def g(t):
        # C = N/D, N = (1-t)^2 P0 + 2 w t (1-t) P1 + t^2 P2, D likewise
        D = (1 - t) ** 2 + 2 * w * t * (1 - t) + t ** 2
        Dp = -2 * (1 - t) + 2 * w * (1 - 2 * t) + 2 * t
        s = 0
        for k in range(dim):
            N = (1 - t) ** 2 * p[0][k] + 2 * w * t * (1 - t) * p[1][k] + t ** 2 * p[2][k]
            Np = -2 * (1 - t) * p[0][k] + 2 * w * (1 - 2 * t) * p[1][k] + 2 * t * p[2][k]
            s += ((Np * D - N * Dp) / D ** 2) ** 2
        return mp.sqrt(s)
    return g


def splits(kind, seg, dim, speed):
    """Where the integrand needs a break: a quadratic's speed minimum (a
    kink when it is zero) and the sampled extrema of any speed."""
    ts = set()
    if kind == "quad":
        p = points(seg, dim, 3)
        a = [p[1][k] - p[0][k] for k in range(dim)]
        b = [p[2][k] - 2 * p[1][k] + p[0][k] for k in range(dim)]
        bb = sum(x * x for x in b)
        if bb > 0:
            t = -sum(a[k] * b[k] for k in range(dim)) / bb
            if 0 < t < 1:
                ts.add(t)
    if kind == "conic":
        # the numerator of C' (w (1-t)^2 a + t (1-t) k + w t^2 c) per
        # coordinate: a collinear conic's speed is zero (a kink) at its roots
        p = points(seg, dim, 3)
        w = mp.mpf(seg[3 * dim])
        for k in range(dim):
            a, c = p[1][k] - p[0][k], p[2][k] - p[1][k]
            kk = p[2][k] - p[0][k]
            # w a - 2 w a t + w a t^2 + kk t - kk t^2 + w c t^2
            co = [w * a - kk + w * c, kk - 2 * w * a, w * a]
            if co[0] == 0 and co[1] == 0:
                continue
            try:
                roots = mp.polyroots(co if co[0] != 0 else co[1:], maxsteps=200, extraprec=100)
            except mp.NoConvergence:
                continue
            for r in roots:
                if abs(mp.im(r)) < mp.mpf(10) ** -30 and 0 < mp.re(r) < 1:
                    ts.add(mp.re(r))
    n = 100
    vals = [speed(mp.mpf(i) / n) for i in range(n + 1)]
    for i in range(1, n):
        if (vals[i] - vals[i - 1]) * (vals[i + 1] - vals[i]) <= 0:
            ts.add(mp.mpf(i) / n)
    return sorted(ts)


def integral(speed, brk, a, b, scale):
    """int_a^b speed, on the pieces between the breaks; speed / scale is
    integrated (mp.quad's error target is absolute), so that scale ~ the
    segment's size makes every check relative."""
    pts = [a] + [t for t in brk if a < t < b] + [b]
    total = 0
    for lo, hi in zip(pts, pts[1:]):
        v, err = mp.quad(lambda t: speed(t) / scale, [lo, hi], error=True,
                         maxdegree=10)
        assert err <= mp.mpf(10) ** -32, (lo, hi, v, err)
        total += v
    return total * scale


def time_at(speed, brk, s, scale):
    """T in [0, 1] with int_0^T speed = s: Newton's method kept in a
    bracket (bisection when a step leaves it)."""
    lo, hi, t = mp.mpf(0), mp.mpf(1), mp.mpf(1) / 2
    for _ in range(200):
        f = integral(speed, brk, 0, t, scale) - s
        if f < 0:
            lo = t
        else:
            hi = t
        v = speed(t)
        nt = t - f / v if v > 0 else (lo + hi) / 2
        if not lo < nt < hi:
            nt = (lo + hi) / 2
        if abs(nt - t) < mp.mpf(10) ** -36:
            return nt
        t = nt
    raise RuntimeError("no convergence")


def affine(seg, dim, n, m, off):
    """The points of seg mapped by x -> m x + off (doubles), tail kept."""
    out = []
    for i in range(n):
        x = seg[i * dim:(i + 1) * dim]
        out += [sum(m[r][c] * x[c] for c in range(dim)) + off[r] for r in range(dim)]
    return out + list(seg[n * dim:])


def cases():
    r = 0.5 ** 0.5
    qc = [1.0, 0.0, 1.0, 1.0, 0.0, 1.0, r]          # quarter circle
    c = []
    # lines
    c.append(("line 2d", "line", 2, [0.0, 0.0, 3.0, 4.0]))
    c.append(("line 3d", "line", 3, [1.0, 2.0, 3.0, 4.0, 6.0, 15.0]))
    c.append(("line huge", "line", 2, [1e300, -1e300, -1e300, 1e300]))
    c.append(("line tiny", "line", 2, [3e-300, 1e-300, 4e-300, -2e-300]))
    c.append(("line far", "line", 3, [1e8 + 0.1, 1e8, -1e8, 1e8 + 0.3, 1e8 + 0.2, -1e8 + 0.1]))
    # quadratics
    c.append(("quad ordinary", "quad", 2, [0.0, 0.0, 1.0, 2.0, 2.0, 0.0]))
    c.append(("quad skew", "quad", 2, [0.0, 0.0, 5.0, 1.0, 1.0, 3.0]))
    c.append(("quad a perp b", "quad", 2, [0.0, 0.0, 1.0, 0.0, 2.0, 0.5]))
    c.append(("quad nearly straight", "quad", 2, [0.0, 0.0, 1.0, 1e-9, 2.0, 0.0]))
    c.append(("quad straight", "quad", 2, [0.0, 0.0, 1.0, 1.0, 2.0, 2.0]))
    c.append(("quad near-mid control", "quad", 2, [0.0, 0.0, 1.0 + 1e-7, 1e-7, 2.0, 0.0]))
    c.append(("quad control near end", "quad", 2, [0.0, 0.0, 1e-8, 1e-8, 1.0, 0.0]))
    c.append(("quad control at end", "quad", 2, [0.0, 0.0, 0.0, 0.0, 1.0, 1.0]))
    c.append(("quad reversal", "quad", 2, [0.0, 0.0, 2.0, 0.0, 1.0, 0.0]))
    c.append(("quad near reversal", "quad", 2, [0.0, 0.0, 2.0, 1e-9, 1.0, 0.0]))
    c.append(("quad cusp mid", "quad", 2, [0.0, 0.0, 1.0, 1.0, 0.0, 0.0]))
    c.append(("quad huge", "quad", 2, [1e150, 0.0, 3e150, 2e150, 2e150, -1e150]))
    c.append(("quad tiny", "quad", 2, [1e-150, 0.0, 3e-150, 2e-150, 2e-150, -1e-150]))
    c.append(("quad far", "quad", 2, [1e7, 1e7, 1e7 + 1.0, 1e7 + 2.0, 1e7 + 2.0, 1e7]))
    c.append(("quad 3d", "quad", 3, [0.0, 0.0, 0.0, 1.0, 2.0, 0.5, 2.0, 0.0, 3.0]))
    c.append(("quad 3d reversal", "quad", 3, [0.0, 0.0, 0.0, 2.0, 2.0, 2.0, 1.0, 1.0, 1.0]))
    c.append(("quad 3d nearly straight", "quad", 3, [0.0, 0.0, 0.0, 1.0, 1.0, 1e-8, 2.0, 2.0, 0.0]))
    # conics
    c.append(("conic quarter circle", "conic", 2, qc))
    c.append(("conic circle r=1e5 far", "conic", 2,
              affine(qc, 2, 3, [[1e5, 0.0], [0.0, 1e5]], [3e6, -2e6])))
    c.append(("conic sheared circle", "conic", 2,
              affine(qc, 2, 3, [[2.0, 0.7], [0.3, 0.5]], [1.0, -1.0])))
    c.append(("conic ellipse w=0.5", "conic", 2, [1.0, 0.0, 1.0, 1.0, 0.0, 1.0, 0.5]))
    c.append(("conic ellipse w=0.01", "conic", 2, [0.0, 0.0, 3.0, 2.0, 5.0, -1.0, 0.01]))
    c.append(("conic parabola", "conic", 2, [0.0, 0.0, 1.0, 2.0, 3.0, 0.0, 1.0]))
    # just above the parabola: acosh w ~ 1.3e-6, the hyperbolic form's
    # angle tiny (its t -> angle map must not cancel)
    c.append(("conic near-parabolic w=1+2^-40", "conic", 2, [0.0, 0.0, 5.0, 9.0, 10.0, 0.0, 1.0 + 2.0 ** -40]))
    c.append(("conic hyperbola w=2", "conic", 2, [0.0, 0.0, 1.0, 1.0, 2.0, 0.0, 2.0]))
    c.append(("conic hyperbola w=100", "conic", 2, [0.0, 0.0, 1.0, 1.0, 3.0, 0.5, 100.0]))
    # nearly parallel legs with |a| ~ E^2 |c| (E = w + sqrt(w^2 - 1)): a thin
    # hyperbola whose U + V cancels (fuzz/fuzz_segment), and the conic of
    # w = 38272 whose pieces made it
    c.append(("conic thin hyperbola", "conic", 2,
              [0.0, 0.0, -38.57211758922945, -69.23200592938619, -38.784879665046418,
               -69.613886069034223, 6.7693903785997485]))
    c.append(("conic hyperbola w=38272", "conic", 2, [0.0, 0.0, -39.0, -70.0, -70.0, -109.0, 38272.0]))
    c.append(("conic collinear reversal", "conic", 2, [0.0, 0.0, 2.0, 0.0, 1.0, 0.0, 0.7]))
    c.append(("conic collinear hyperbola", "conic", 2, [0.0, 0.0, 1.0, 1.0, 3.0, 3.0, 3.0]))
    c.append(("conic 3d quarter circle", "conic", 3,
              [1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0, r]))
    # the quarter circle on the plane x + y + z = 1, rotated and moved
    m3 = [[0.36, 0.48, -0.8], [-0.8, 0.6, 0.0], [0.48, 0.64, 0.6]]
    c.append(("conic 3d rotated circle", "conic", 3,
              affine([1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0, r], 3, 3, m3, [5.0, -2.0, 1.0])))
    c.append(("conic 3d ellipse", "conic", 3, [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, -1.0, 2.0, 0.3]))
    c.append(("conic 3d hyperbola", "conic", 3, [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, -1.0, 2.0, 5.0]))
    return c


def fmt(x):
    return mp.nstr(x, 30, min_fixed=-mp.inf, max_fixed=mp.inf) if x != 0 else "0"


def main():
    rows = []
    for name, kind, dim, seg in cases():
        seg = [float(x) for x in seg]
        sp = speed_fn(kind, seg, dim)
        brk = splits(kind, seg, dim, sp)
        scale = max(abs(mp.mpf(x)) for x in seg[:3 * dim]) or 1
        Ls, acc = [], 0
        for k in range(4):
            acc += integral(sp, brk, mp.mpf(k) / 4, mp.mpf(k + 1) / 4, scale)
            Ls.append(acc)
        L = Ls[3]
        sub = integral(sp, brk, mp.mpf("0.2"), mp.mpf("0.7"), scale)
        T = []
        for frac in (mp.mpf(1) / 3, mp.mpf(2) / 3):
            t = time_at(sp, brk, frac * L, scale) if L > 0 else mp.mpf(0)
            T += [t, sp(t)]
        rows.append([name, kind, str(dim), " ".join(repr(x) for x in seg)]
                    + [fmt(x) for x in Ls + [sub] + T])
        print(name, mp.nstr(L, 20))
    path = os.path.join(DATA, "segments_lengths.tsv")
    with open(path, "w") as f:
        f.write("# tools/ref_segments.py: mpmath quad of the speed, 40 digits\n")
        f.write("\t".join(["name", "kind", "dim", "seg", "L25", "L50", "L75", "L",
                           "L2070", "T33", "V33", "T67", "V67"]) + "\n")
        for r in rows:
            f.write("\t".join(r) + "\n")


if __name__ == "__main__":
    main()
