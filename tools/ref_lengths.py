#!/usr/bin/python3
"""Reference arc lengths and times of the curve sets of tools/curves.py.

For every curve (exact double coordinates): L25, L50, L75, L = s(t) at
t = 1/4, 1/2, 3/4, 1 with s(t) = int_0^t |z'(u)| du, and T25, T50, T75 with
s(T) = L/4, L/2, 3L/4.  Written with 30 significant digits to
spec/data/curves2d.tsv and spec/data/curves3d.tsv.

How (two independent evaluations, the script stops if they disagree):
  primary  mpmath, 45 digits: sqrt of the power-basis quartic Q = |z'|^2
           (exact rational coefficients), Gauss-Legendre with 40 nodes on a
           mesh where every branch point of sqrt(Q) (complex root of Q) is
           outside the Bernstein ellipse rho = 4 of its piece (error of the
           rule ~ rho^(-2n) = 4^-80 ~ 1e-48, Trefethen, ATAP Thm 19.3).
  check    Python's decimal (libmpdec), 60 digits: sqrt(|z'|^2) from the
           Bernstein form of the hodograph, 48 nodes, rho = 3 (3^-96 ~ 1e-46),
           a mesh that is also split at the speed's critical points.
Both meshes are split at 1/4, 1/2, 3/4 and at the real parts of the roots of
Q near [0, 1] (hodograph zeros: a kink when the root is real, i.e. a cusp),
and refined by bisection until the ellipse condition holds, so near-cusps at
any distance (1e-1 ... 1e-12) and cusps at bisection points are integrated to
full precision.  Times: safeguarded Newton (bracketed, bisection fallback) on
the primary s(t); each T is then verified by the check integrator:
s(T - d) < target < s(T + d) with d = 1e-32 T.  When the speed vanishes at T
(a cusp or a stop exactly at a quarter of the length), both integrators are
rerun at higher precision (80, then 120 digits) until the bracket holds.

Run: nice /usr/bin/python3 tools/ref_lengths.py [2d|3d|all]
"""
import os
import sys
import time
from collections import Counter
from decimal import Decimal, localcontext
from fractions import Fraction

import mpmath
from mpmath import mp, mpf, mpc

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import curves  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "spec", "data")
QUARTERS = [Fraction(1, 4), Fraction(1, 2), Fraction(3, 4)]
MAX_PIECES = 20000      # cap on mesh pieces per curve (nothing may hang)
MAX_NEWTON = 3000       # cap on time-solver iterations
mp.dps = 110            # roots and split points: far beyond the 45 digits
REAL_IM = mpf("1e-30")  # |Im root| below this: a real root (kink, cusp)

# Precision levels: (digits claimed for s, primary dps, primary nodes,
# primary rho, check prec, check nodes, check rho).  GL error ~ rho^(-2n).
LEVELS = [
    (40, 45, 40, 4, 60, 48, 3),
    (75, 85, 70, 4, 95, 90, 3),
    (110, 120, 100, 4, 130, 125, 3),
]

_nodes = {}


def gl_nodes(n, dps):
    """Gauss-Legendre nodes/weights on [-1, 1] (Newton on P_n, A&S 25.4.29)."""
    key = (n, dps)
    if key not in _nodes:
        with mp.workdps(dps + 20):
            xs, ws = [], []
            for i in range(1, n + 1):
                x = mp.cos(mp.pi * (4 * i - 1) / (4 * n + 2))
                for _ in range(100):
                    p0, p1 = mpf(1), x
                    for k in range(2, n + 1):
                        p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
                    dp = n * (x * p1 - p0) / (x * x - 1)
                    dx = p1 / dp
                    x -= dx
                    if abs(dx) < mpf(10) ** -(dps + 15):
                        break
                else:
                    raise SystemExit("Legendre nodes: Newton failed, n=%d" % n)
                p0, p1 = mpf(1), x
                for k in range(2, n + 1):
                    p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
                dp = n * (x * p1 - p0) / (x * x - 1)
                xs.append(x)
                ws.append(2 / ((1 - x * x) * dp * dp))
            _nodes[key] = (xs, ws)
    return _nodes[key]


# ---- exact polynomial algebra (Fractions; coordinates are exact dyadics) ----

def pmul(a, b):
    out = [Fraction(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


def padd(a, b):
    n = max(len(a), len(b))
    a = a + [Fraction(0)] * (n - len(a))
    b = b + [Fraction(0)] * (n - len(b))
    return [x + y for x, y in zip(a, b)]


def ptrim(a):
    a = list(a)
    while len(a) > 1 and a[-1] == 0:
        a.pop()
    return a


def pderiv(a):
    return ptrim([i * a[i] for i in range(1, len(a))] or [Fraction(0)])


def pdivmod(a, b):
    a, b = ptrim(a), ptrim(b)
    q = [Fraction(0)] * max(1, len(a) - len(b) + 1)
    r = list(a)
    while len(r) >= len(b) and any(r):
        k = len(r) - len(b)
        f = r[-1] / b[-1]
        q[k] = f
        for i, y in enumerate(b):
            r[i + k] -= f * y
        r.pop()
        r = ptrim(r) if r else [Fraction(0)]
        if len(r) < len(b):
            break
    return ptrim(q), ptrim(r)


def pgcd(a, b):
    a, b = ptrim(a), ptrim(b)
    while any(b):
        _, r = pdivmod(a, b)
        a, b = b, r
    return [x / a[-1] for x in a]


def squarefree(a):
    """Yun's algorithm: factors f_1, f_2, ... with a = prod f_i^i."""
    a = ptrim(a)
    if len(a) <= 1:
        return []
    out = []
    g = pgcd(a, pderiv(a))
    w = pdivmod(a, g)[0]
    i = 1
    while len(w) > 1:
        y = pgcd(w, g)
        f = pdivmod(w, y)[0]
        if len(f) > 1:
            out.append((f, i))
        w = y
        g = pdivmod(g, y)[0]
        i += 1
        if i > 10:
            raise SystemExit("squarefree: no progress")
    return out


def exact_mpf(fr):
    """fr as an mpf: exact for dyadic fractions (all data are doubles),
    else rounded at the current precision."""
    with mp.workprec(max(fr.numerator.bit_length(), 53) + 10):
        num = mpf(fr.numerator)
    den = fr.denominator
    if den & (den - 1) == 0:
        return mp.ldexp(num, -(den.bit_length() - 1))
    return num / den


def poly_roots(a):
    """All complex roots of the exact polynomial a (ascending), with
    multiplicity, at 100+ digits (Durand-Kerner on square-free factors)."""
    roots = []
    for f, m in squarefree(a):
        with mp.workdps(110):
            c = [exact_mpf(x) for x in reversed(f)]
            if len(c) == 2:
                rs = [mpc(-c[1] / c[0])]
            else:
                rs = mpmath.polyroots(c, maxsteps=2000, extraprec=400)
            roots += [mpc(r) for r in rs] * m
    return roots


# ---- a curve ----

class Curve:
    def __init__(self, coords, dim):
        self.dim = dim
        P = [[Fraction(coords[i * dim + k]) for k in range(dim)]
             for i in range(4)]
        self.d = [[P[i + 1][k] - P[i][k] for k in range(dim)]
                  for i in range(3)]
        # z'(t) = A t^2 + B t + C (power basis), per coordinate
        d1, d2, d3 = self.d
        self.A = [3 * (d1[k] - 2 * d2[k] + d3[k]) for k in range(dim)]
        self.B = [6 * (d2[k] - d1[k]) for k in range(dim)]
        self.C = [3 * d1[k] for k in range(dim)]
        Q = [Fraction(0)]
        for k in range(dim):
            h = [self.C[k], self.B[k], self.A[k]]
            Q = padd(Q, pmul(h, h))
        self.Q = ptrim(Q)               # ascending, exact
        self.zero = not any(self.Q)
        self.qc = [exact_mpf(x) for x in reversed(self.Q)]   # descending
        self.roots = [] if self.zero else self.hodograph_roots()
        self.branch = [r for r in self.roots if abs(r.imag) > REAL_IM]
        self.splits = sorted(set(
            [mpf(r.real) for r in self.roots if 0 < r.real < 1]))
        crit = []
        if not self.zero and len(self.Q) > 2:
            for r in poly_roots(pderiv(self.Q)):
                if abs(r.imag) <= REAL_IM and 0 < r.real < 1:
                    crit.append(mpf(r.real))
        self.crit = sorted(set(crit))

    def hodograph_roots(self):
        """Roots of Q = |z'|^2.  2D: the zeros s of the complex quadratic
        z'(t) and their conjugates; 3D: the roots of the real quartic."""
        if self.dim == 3:
            return poly_roots(self.Q)
        with mp.workdps(110):
            a = mpc(exact_mpf(self.A[0]), exact_mpf(self.A[1]))
            b = mpc(exact_mpf(self.B[0]), exact_mpf(self.B[1]))
            c = mpc(exact_mpf(self.C[0]), exact_mpf(self.C[1]))
            if a == 0:
                rs = [] if b == 0 else [-c / b]
            else:
                sq = mp.sqrt(b * b - 4 * a * c)
                if (b.conjugate() * sq).real < 0:
                    sq = -sq
                q = -(b + sq) / 2
                rs = [q / a, c / q] if q != 0 else [mpc(0), mpc(0)]
            out = []
            for r in rs:
                out += [r, r.conjugate()]
            return out


def rho(s, l, r):
    """Bernstein ellipse parameter of the point s for the interval [l, r]."""
    z = (2 * s - l - r) / (r - l)
    w = z + mp.sqrt(z - 1) * mp.sqrt(z + 1)
    m = abs(w)
    return m if m >= 1 else 1 / m


def mesh(cv, extra, rho_min):
    """Breakpoints: 0, quarters, `extra`, refined by bisection until every
    branch point lies outside the rho_min ellipse of its piece."""
    pts = sorted(set([mpf(0), mpf(1)] + [mpf(q.numerator) / q.denominator
                                         for q in QUARTERS] + list(extra)))
    # merge breakpoints closer than 1e-40 (double roots computed as pairs)
    merged = [pts[0]]
    for p in pts[1:]:
        if p - merged[-1] > mpf("1e-40"):
            merged.append(p)
        elif p == 1:
            merged[-1] = p
    return refine(merged, cv, rho_min, lambda l, r: r - l <= mpf("1e-36"))


def refine(pts, cv, rho_min, too_small):
    """The breakpoints pts (ascending), each piece bisected until every
    branch point lies outside its rho_min ellipse or too_small(l, r)."""
    out = [pts[0]]
    stack = [(pts[i], pts[i + 1]) for i in range(len(pts) - 1)]
    stack.reverse()
    pieces = 0
    while stack:
        l, r = stack.pop()
        bad = (not too_small(l, r) and
               any(rho(s, l, r) < rho_min for s in cv.branch))
        if bad:
            m = (l + r) / 2
            stack.append((m, r))
            stack.append((l, m))
        else:
            out.append(r)
            pieces += 1
            if pieces > MAX_PIECES:
                raise SystemExit("mesh: more than %d pieces" % MAX_PIECES)
    return out


class Primary:
    """mpmath: sqrt(Q(t)), Q by Horner from exact coefficients."""

    def __init__(self, cv, level):
        _, self.dps, n, rho_min, _, _, _ = level
        self.cv = cv
        with mp.workdps(self.dps):
            self.xs, self.ws = gl_nodes(n, self.dps)
            self.mesh = mesh(cv, cv.splits, rho_min)
            self.cum = [mpf(0)]
            for i in range(len(self.mesh) - 1):
                self.cum.append(self.cum[-1] +
                                self.gl(self.mesh[i], self.mesh[i + 1]))

    def speed(self, t):
        # Horner with 20 guard digits: Q has double roots at cusps, where
        # the power basis cancels.
        with mp.workdps(self.dps + 20):
            q = mpf(0)
            for c in self.cv.qc:
                q = q * t + c
        return mp.sqrt(q) if q > 0 else mpf(0)

    def gl(self, l, r):
        h = (r - l) / 2
        m = (l + r) / 2
        return h * mp.fsum(w * self.speed(m + h * x)
                           for x, w in zip(self.xs, self.ws))

    def s_at(self, t):
        with mp.workdps(self.dps):
            i = max(j for j in range(len(self.mesh)) if self.mesh[j] <= t)
            if self.mesh[i] == t:
                return self.cum[i]
            return self.cum[i] + self.gl(self.mesh[i], t)

    def time(self, target):
        """t in [0, 1] with s(t) = target: bracketed Newton, bisection when
        Newton leaves the bracket or stalls (speed 0 at a cusp)."""
        with mp.workdps(self.dps):
            i = 0
            while i + 1 < len(self.mesh) - 1 and self.cum[i + 1] < target:
                i += 1
            l0 = self.mesh[i]
            lo, hi = self.mesh[i], self.mesh[i + 1]
            tol = mpf(10) ** -(self.dps - 3)
            span = self.cum[i + 1] - self.cum[i]
            t = lo + (hi - lo) * (target - self.cum[i]) / span if span > 0 \
                else (lo + hi) / 2
            if not lo < t < hi:
                t = (lo + hi) / 2
            width = hi - lo
            for it in range(MAX_NEWTON):
                F = self.cum[i] + self.gl(l0, t) - target
                if F == 0:
                    return t
                if F < 0:
                    lo = t
                else:
                    hi = t
                sp = self.speed(t)
                tn = t - F / sp if sp > 0 else None
                if tn is None or not (lo < tn < hi) or (
                        it % 3 == 2 and hi - lo > width / 4):
                    tn = (lo + hi) / 2
                    width = hi - lo
                if abs(tn - t) <= tol * t or hi - lo <= tol * t:
                    return tn
                t = tn
            raise SystemExit("time: no convergence in %d steps" % MAX_NEWTON)


class Check:
    """decimal (libmpdec): sqrt(sum h_k^2) with the Bernstein hodograph."""

    def __init__(self, cv, level):
        _, _, _, _, self.prec, n, rho_min = level
        self.cv = cv
        with localcontext() as ctx:
            ctx.prec = self.prec
            ctx.Emax, ctx.Emin = 10 ** 6, -10 ** 6
            xs, ws = gl_nodes(n, self.prec)
            self.xs = [self.dec(x) for x in xs]
            self.ws = [self.dec(w) for w in ws]
            self.d = [[Decimal(x.numerator) / Decimal(x.denominator)
                       for x in di] for di in cv.d]
            with mp.workdps(self.prec):
                # Kinks (real roots of Q) are zeros of Q' too: taking them
                # from Q' keeps this mesh independent of cv.splits.
                m = mesh(cv, [mpf(r.real) for r in cv.branch
                              if 0 < r.real < 1] + cv.crit, rho_min)
            self.mesh = [self.dec(p) for p in m]
            self.cum = [Decimal(0)]
            for i in range(len(self.mesh) - 1):
                self.cum.append(self.cum[-1] +
                                self.gl(self.mesh[i], self.mesh[i + 1]))

    def dec(self, x):
        return Decimal(mpmath.nstr(x, self.prec + 10, min_fixed=-10 ** 9,
                                   max_fixed=10 ** 9, strip_zeros=False))

    def speed(self, t):
        u = 1 - t
        a, b, c = u * u, 2 * t * u, t * t
        s = Decimal(0)
        for k in range(self.cv.dim):
            h = 3 * (a * self.d[0][k] + b * self.d[1][k] + c * self.d[2][k])
            s += h * h
        return s.sqrt()

    def gl(self, l, r):
        h = (r - l) / 2
        m = (l + r) / 2
        return h * sum(w * self.speed(m + h * x)
                       for x, w in zip(self.xs, self.ws))

    def s_at(self, t):
        with localcontext() as ctx:
            ctx.prec = self.prec
            ctx.Emax, ctx.Emin = 10 ** 6, -10 ** 6
            t = self.dec(t)
            i = max(j for j in range(len(self.mesh)) if self.mesh[j] <= t)
            if self.mesh[i] == t:
                return mpf(str(self.cum[i]))
            return mpf(str(self.cum[i] + self.gl(self.mesh[i], t)))


def collinear_lengths(cv, ts):
    """Closed form when all control points lie on one line (a third,
    quadrature-free check): the position along the line is a cubic lam(t),
    the length is the sum of |lam(t_k+1) - lam(t_k)| between the zeros of
    lam'(t).  None when the curve is not collinear."""
    P = [[Fraction(0)] * cv.dim]
    for d in cv.d:
        P.append([P[-1][k] + d[k] for k in range(cv.dim)])
    far = max(P[1:], key=lambda p: sum(x * x for x in p))
    if not any(far):
        return None
    for p in P[1:]:
        for k in range(cv.dim):
            for m in range(k + 1, cv.dim):
                if p[k] * far[m] != p[m] * far[k]:
                    return None
    with mp.workdps(70):
        n = mp.sqrt(exact_mpf(sum(x * x for x in far)))
        lam = [exact_mpf(sum(p[k] * far[k] for k in range(cv.dim))) / n
               for p in P]

        def at(t):
            u = 1 - t
            return (u ** 3 * lam[0] + 3 * u * u * t * lam[1] +
                    3 * u * t * t * lam[2] + t ** 3 * lam[3])
        zeros = [r.real for r, _ in
                 [(r, 0) for r in poly_roots(pderiv([sum(p[k] * far[k]
                  for k in range(cv.dim)) for p in power_basis(P)]))]
                 if abs(r.imag) <= REAL_IM and 0 < r.real < 1]
        out = []
        for t1 in ts:
            knots = [mpf(0)] + sorted(z for z in zeros if z < t1) + [t1]
            out.append(mp.fsum(abs(at(knots[i + 1]) - at(knots[i]))
                               for i in range(len(knots) - 1)))
        return out


def power_basis(P):
    """Power-basis coefficients (ascending) of the Bezier points P."""
    dim = len(P[0])
    return [[P[0][k] for k in range(dim)],
            [3 * (P[1][k] - P[0][k]) for k in range(dim)],
            [3 * (P[2][k] - 2 * P[1][k] + P[0][k]) for k in range(dim)],
            [P[3][k] - 3 * P[2][k] + 3 * P[1][k] - P[0][k]
             for k in range(dim)]]


STATS = {"len": mpf(0), "time": mpf(0), "escalated": 0,
         "collinear": mpf(0), "ncollinear": 0}


def reference(coords, dim):
    """(L25, L50, L75, L, T25, T50, T75) as mpf; times None if L = 0."""
    cv = Curve(coords, dim)
    if cv.zero:
        return [mpf(0)] * 4 + [None] * 3
    for li, level in enumerate(LEVELS):
        digits = level[0]
        with mp.workdps(level[1] + 10):
            P, C = Primary(cv, level), Check(cv, level)
            ts = [mpf(q.numerator) / q.denominator for q in QUARTERS] + [1]
            lp = [P.s_at(t) for t in ts]
            lc = [C.s_at(t) for t in ts]
            for a, b in zip(lp, lc):
                rel = abs(a - b) / abs(a)
                if rel > mpf(10) ** -(digits - 5):
                    raise SystemExit("length not verified: %s vs %s" % (a, b))
                if li == 0:
                    STATS["len"] = max(STATS["len"], rel)
            if li == 0:
                exact = collinear_lengths(cv, ts)
                if exact is not None:
                    STATS["ncollinear"] += 1
                    for a, b in zip(lp, exact):
                        rel = abs(a - b) / abs(a)
                        if rel > mpf(10) ** -(digits - 5):
                            raise SystemExit("collinear closed form: %s vs %s"
                                             % (a, b))
                        STATS["collinear"] = max(STATS["collinear"], rel)
            L = lp[3]
            err = mpf(10) ** -(digits - 5) * L     # what s is trusted to
            times, ok = [], True
            for q in QUARTERS:
                target = L * q.numerator / q.denominator
                T = P.time(target)
                d = T * mpf("1e-32")
                below, above = C.s_at(T - d), C.s_at(T + d)
                if not (below < target - err and above > target + err):
                    ok = False
                    break
                if li == 0:
                    STATS["time"] = max(STATS["time"],
                                        abs(C.s_at(T) - target) / L)
                times.append(T)
            if ok:
                if li > 0:
                    STATS["escalated"] += 1
                return lp + times
    raise SystemExit("time not verified at %d digits" % LEVELS[-1][0])


def range_length(coords, dim, t0, t1):
    """s(t1) - s(t0) for the curve's exact doubles, by both integrators
    (40 digits claimed); stops if they differ by more than 1e-30."""
    cv = Curve(coords, dim)
    if cv.zero:
        return mpf(0)
    level = LEVELS[0]
    with mp.workdps(level[1] + 10):
        P, C = Primary(cv, level), Check(cv, level)
        a, b = mpf(t0), mpf(t1)
        lp = P.s_at(b) - P.s_at(a)
        lc = C.s_at(b) - C.s_at(a)
        if abs(lp - lc) > mpf("1e-30") * abs(lp):
            raise SystemExit("range not verified: %s vs %s" % (lp, lc))
        return lp


def fmt(v):
    return "-" if v is None else mpmath.nstr(v, 30)


def write(path, rows, dim):
    names = "xyz"[:dim]
    head = ["id", "family", "param"]
    head += ["%s%d" % (c, i) for i in range(4) for c in names]
    head += ["L25", "L50", "L75", "L", "T25", "T50", "T75"]
    t0 = time.time()
    out = ["\t".join(head)]
    results = {}
    for n, (cid, fam, param, c) in enumerate(rows):
        ref = reference(c, dim)
        results[cid] = ref
        out.append("\t".join([cid, fam, param] + [repr(float(v)) for v in c] +
                             [fmt(v) for v in ref]))
        if n % 100 == 99:
            print("  %d/%d  %.0fs" % (n + 1, len(rows), time.time() - t0),
                  flush=True)
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(out) + "\n")
    os.replace(tmp, path)
    print("%s: %d rows in %.1fs" % (os.path.relpath(path, ROOT), len(rows),
                                    time.time() - t0))
    for fam, k in Counter(r[1] for r in rows).items():
        print("  %-12s %5d" % (fam, k))
    return results


def main():
    which = sys.argv[1] if len(sys.argv) > 1 else "all"
    start = time.time()
    os.makedirs(DATA, exist_ok=True)
    if which in ("2d", "all"):
        write(os.path.join(DATA, "curves2d.tsv"), curves.curves2d(), 2)
    if which in ("3d", "all"):
        res3 = write(os.path.join(DATA, "curves3d.tsv"), curves.curves3d(), 3)
        # planar3d-k lies in a tilted plane and has planar-k's length.
        rows2 = {r[0]: r for r in curves.curves2d() if r[1] == "planar"}
        worst = mpf(0)
        for cid, ref in res3.items():
            if cid.startswith("planar3d-"):
                twin = rows2[cid.replace("planar3d-", "planar-")]
                ref2 = reference(twin[3], 2)
                for a, b in zip(ref, ref2):
                    rel = abs(a - b) / abs(a)
                    if rel > mpf("1e-34"):
                        raise SystemExit("planar3d %s != 2D twin" % cid)
                    worst = max(worst, rel)
        print("planar3d vs 2D twin: max rel. difference %s" %
              mpmath.nstr(worst, 3))
    print("max rel. difference primary/check: lengths %s, |s(T)-target|/L %s;"
          " curves needing higher precision for times: %d" %
          (mpmath.nstr(STATS["len"], 3), mpmath.nstr(STATS["time"], 3),
           STATS["escalated"]))
    print("collinear curves (%d) vs closed form: max rel. difference %s" %
          (STATS["ncollinear"], mpmath.nstr(STATS["collinear"], 3)))
    print("total run time %.1fs" % (time.time() - start))


if __name__ == "__main__":
    main()
