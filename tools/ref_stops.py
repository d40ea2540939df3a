#!/usr/bin/python3
"""Times on cubics whose speed nearly stops, with 30-digit references.

A stop deeper than the double range can see: y0 = y3 = Y with Y up to
2^1000 times the other coordinates, so the hodograph is nearly linear
(z'' ~ 2^-530 of z' after scaling, a root of z' at ~2^530) and its near
root sits ~2^-530 off the real axis at t ~ 1/2: the speed falls to nearly
0 there.  The far root and the near one both test how the inverse's error
bound reads the branch points (a far root dropped with the lead left at
|z''|^2 once certified Newton steps 2e-4 L off).  Rows: every curve at the
distances u L for the fractions U, near 1/2 most densely.

Values: mpmath at 250 digits (the speed cancels 530 bits at the stop).
The hodograph's coefficients are exact (the control points' differences
at 2400 bits).  t* is the speed's minimum (Newton on z'.z'' = 0); the
mesh is geometric towards t* from both sides, t* (1 - 2^-k) and t* +
(1 - t*) 2^-k for k = 1 .. 600 (what lies nearer weighs < 2^-1100 L),
so every piece's nearest branch point (t* +- i eps) is its own width
away: Bernstein's rho >= 3 + sqrt 8 and Gauss-Legendre's error with 40
nodes <= rho^-80 ~ 1e-61 (Trefethen, ATAP Thm 19.3).  The check: a mesh of
ratio 3 (rho >= 2 + sqrt 3) and 56 nodes (~1e-64); both must agree to
1e-45 L at t*, 1 and every point of the ratio-3 mesh; the times
solve s(T) = u L by bracketed Newton inside the piece that holds the
goal (Gauss-Legendre on the piece's start to T), to 1e-45.

Run: nice /usr/bin/python3 tools/ref_stops.py -> spec/data/deep_stops.tsv
"""
import os
import random
import sys

import mpmath
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ref_lengths  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "spec", "data", "deep_stops.tsv")
U = ["0.05", "0.25", "0.4", "0.45", "0.49", "0.495", "0.499", "0.5",
     "0.501", "0.505", "0.51", "0.55", "0.6", "0.75", "0.95"]

# The cubic fuzz/fuzz_times found (2D, scale-invariant, a stop 2^-529 off).
FUZZ = tuple(float.fromhex(h) for h in (
    "0x1.84p+315", "0x1.161fffdff6161p+844", "0x1.84p+315", "0x1.6p+314",
    "0x1.58p+314", "0x1.6cp+315", "0x1p+315", "0x1.161fffdff6161p+844"))


def curves():
    rows = [("fuzz-deep-stop", 2, FUZZ),
            ("fuzz-deep-stop-xy", 2, tuple(FUZZ[i ^ 1] for i in range(8)))]
    r = random.Random(2611)
    for ex in (531, 600, 700, 844, 1000):
        y = float.fromhex("0x1p%d" % ex) * (1 + r.random())
        c = [r.uniform(-1, 1) for _ in range(8)]
        c[1] = c[7] = y
        rows.append(("stop2d-%d" % ex, 2, tuple(c)))
    for ex in (531, 844):
        y = float.fromhex("0x1p%d" % ex) * (1 + r.random())
        c = [r.uniform(-1, 1) for _ in range(12)]
        c[1] = c[10] = y
        rows.append(("stop3d-%d" % ex, 3, tuple(c)))
    return rows


DPS = 250
MESH_K = 600
GL_N = 40
CHECK_N = 56


class Cubic:
    """The speed |z'(t)| from the exact Bernstein differences."""

    def __init__(self, coords, dim):
        with mp.workprec(2400):
            pts = [[mpf(coords[i * dim + k]) for k in range(dim)] for i in range(4)]
            d = [[pts[i + 1][k] - pts[i][k] for k in range(dim)] for i in range(3)]
            # z'(t) = 3 (a t^2 + b t + c), exact
            self.a = [d[0][k] - 2 * d[1][k] + d[2][k] for k in range(dim)]
            self.b = [2 * (d[1][k] - d[0][k]) for k in range(dim)]
            self.c = [d[0][k] for k in range(dim)]
        self.dim = dim

    def hodo(self, t):
        return [3 * ((self.a[k] * t + self.b[k]) * t + self.c[k]) for k in range(self.dim)]

    def speed(self, t):
        return mp.sqrt(sum(v * v for v in self.hodo(t)))

    def stop(self):
        """The speed's minimum near 1/2: Newton on g(t) = z'.z''."""
        t = mpf("0.5")
        for _ in range(400):
            h = self.hodo(t)
            h1 = [3 * (2 * self.a[k] * t + self.b[k]) for k in range(self.dim)]
            h2 = [6 * self.a[k] for k in range(self.dim)]
            g = sum(x * y for x, y in zip(h, h1))
            dg = sum(y * y for y in h1) + sum(x * z for x, z in zip(h, h2))
            step = g / dg
            t -= step
            if abs(step) < mpf(10) ** -(DPS - 10):
                return t
        raise SystemExit("stop: no convergence")


def times(coords, dim):
    """L and [(u, T)] for the fractions U."""
    with mp.workdps(DPS):
        cv = Cubic(coords, dim)
        xs, ws = ref_lengths.gl_nodes(GL_N, DPS)

        def gl(a, b):
            h, m = (b - a) / 2, (a + b) / 2
            return h * sum(w * cv.speed(m + h * x) for x, w in zip(xs, ws))

        ts = cv.stop()
        if not mpf("0.25") < ts < mpf("0.75"):
            raise SystemExit("stop at %s" % ts)
        two = mpf(2)
        mesh = [mpf(0)] + [ts * (1 - two ** -k) for k in range(1, MESH_K + 1)]
        mesh += [ts] + [ts + (1 - ts) * two ** -k for k in range(MESH_K, 0, -1)]
        mesh += [mpf(1)]
        cum = [mpf(0)]
        for a, b in zip(mesh, mesh[1:]):
            cum.append(cum[-1] + gl(a, b))
        L = cum[-1]
        # the check: its own mesh and rule, compared at each of its points
        cx, cw = ref_lengths.gl_nodes(CHECK_N, DPS)
        three = mpf(3)
        m3 = [mpf(0)] + [ts * (1 - three ** -k) for k in range(1, MESH_K * 2 // 3)]
        m3 += [ts] + [ts + (1 - ts) * three ** -k for k in range(MESH_K * 2 // 3 - 1, 0, -1)]
        m3 += [mpf(1)]
        acc, worst = mpf(0), mpf(0)
        for a, b in zip(m3, m3[1:]):
            h, m = (b - a) / 2, (a + b) / 2
            acc += h * sum(w * cv.speed(m + h * x) for x, w in zip(cx, cw))
            j = max(j for j in range(len(mesh)) if mesh[j] <= b)
            ref = cum[j] + (gl(mesh[j], b) if mesh[j] < b else 0)
            worst = max(worst, abs(acc - ref) / L)
        if worst > mpf("1e-45"):
            raise SystemExit("rules disagree by %s L" % mpmath.nstr(worst, 3))
        out = []
        for u in U:
            goal = L * mpf(u)
            i = max(j for j in range(len(mesh) - 1) if cum[j] <= goal)
            lo, hi, t = mesh[i], mesh[i + 1], None
            t = lo + (hi - lo) * (goal - cum[i]) / (cum[i + 1] - cum[i])
            for _ in range(200):
                g = cum[i] + gl(mesh[i], t) - goal
                if g < 0:
                    lo = t
                else:
                    hi = t
                f = cv.speed(t)
                tn = t - g / f if f > 0 else (lo + hi) / 2
                if not lo < tn < hi:
                    tn = (lo + hi) / 2
                if abs(tn - t) < mpf("1e-45") * tn or abs(g) < mpf("1e-48") * L:
                    t = tn
                    break
                t = tn
            else:
                raise SystemExit("time: no convergence")
            out.append((u, t))
        return L, out


def main():
    head = ["id", "dim"] + ["c%d" % i for i in range(12)] + ["u", "L", "T"]
    lines = ["\t".join(head)]
    for cid, dim, c in curves():
        L, ts = times(c, dim)
        cs = [repr(float(v)) for v in c] + ["-"] * (12 - len(c))
        for u, T in ts:
            lines.append("\t".join([cid, str(dim)] + cs +
                                   [u, mpmath.nstr(L, 30), mpmath.nstr(T, 30)]))
        print(cid, "L", mpmath.nstr(L, 20), flush=True)
    with open(OUT + ".tmp", "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(OUT + ".tmp", OUT)
    print("%s: %d rows" % (os.path.relpath(OUT, ROOT), len(lines) - 1))


if __name__ == "__main__":
    main()
