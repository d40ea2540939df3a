#!/usr/bin/python3
"""Reference lengths of short sub-ranges [t0, t1] next to (near) cusps.

A sub-range 1e-6 .. 1e-14 wide around the speed's minimum of a near-cusp
has a length many orders below the curve's, and the speed there is a small
difference of large terms: a method that evaluates the whole curve's
hodograph keeps only the digits the cancellation leaves.  These rows check
that a method keeps full relative precision on the sub-range itself.

Curves: the near-cusp and cusp families of spec/data/curves2d.tsv and
curves3d.tsv, plus the near-cusp (0,0) (1,1) (0,1) (1+eps,0) for eps =
1e-2 .. 1e-14.  For each, the foot f of the branch point nearest the real
axis in (0, 1) (the real part of the root of Q = |z'|^2 with the smallest
imaginary part), and ranges [f - w, f + w/3] and [f + w/5, f + w] for
w = 1e-2, 1e-5, 1e-8, 1e-11, 1e-14, each end rounded to a double (the
reference is for those doubles exactly).

Lengths: two independent integrations of |z'| over [t0, t1] as in
tools/ref_lengths.py -- mpmath Gauss-Legendre on sqrt(Q) (exact rational
coefficients, 20 guard digits) and Python's decimal on the Bernstein
hodograph, at 85 and 95 digits (near a cusp the speed cancels ~30 of
them) -- each on a mesh of [t0, t1] split at the real parts of the roots
of Q and refined until every branch point is outside the Bernstein ellipse
rho = 4 (resp. 3) of its piece; the script stops if they differ by more than
1e-35 relative.  Written to spec/data/subranges.tsv with 30 digits.

Run: nice /usr/bin/python3 tools/ref_subranges.py
"""
import os
import sys
from decimal import Decimal, localcontext

from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ref_lengths as R  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "spec", "data")
WIDTHS = [1e-2, 1e-5, 1e-8, 1e-11, 1e-14]
LEVEL = R.LEVELS[1]   # 85 digits: the cancellation near a cusp eats ~30


def read_rows(name, dim):
    rows = []
    with open(os.path.join(DATA, name)) as f:
        head = f.readline().rstrip("\n").split("\t")
        for line in f:
            row = dict(zip(head, line.rstrip("\n").split("\t")))
            if row["family"] in ("nearcusp", "cusp", "nearcusp3d"):
                names = "xyz"[:dim]
                c = [float(row["%s%d" % (n, i)]) for i in range(4)
                     for n in names]
                rows.append((row["id"], dim, c))
    return rows


def curves():
    out = read_rows("curves2d.tsv", 2) + read_rows("curves3d.tsv", 3)
    for k in range(2, 15, 2):
        eps = 10.0 ** -k
        out.append(("vee-1e-%d" % k, 2, [0.0, 0.0, 1.0, 1.0, 0.0, 1.0,
                                         1.0 + eps, 0.0]))
    return out


def foot(cv):
    """Real part of the root of Q nearest the real axis inside (0, 1)."""
    inside = [r for r in cv.roots if 0 < r.real < 1]
    if not inside:
        return None
    return float(min(inside, key=lambda r: abs(r.imag)).real)


def sub_mesh(cv, t0, t1, rho_min):
    """[t0, t1] split at the roots' real parts inside, then bisected until
    every branch point is outside the rho_min ellipse of its piece."""
    pts = sorted(set([t0, t1] + [mpf(r.real) for r in cv.roots
                                 if t0 < r.real < t1]))
    return R.refine(pts, cv, rho_min,
                    lambda lo, hi: hi - lo <= (hi + lo) * mpf("1e-44"))


def length(cv, t0, t1):
    _, dps, _, rho_p, prec, _, rho_c = LEVEL
    with mp.workdps(dps + 10):
        P = R.Primary.__new__(R.Primary)
        P.cv, P.dps = cv, dps
        P.xs, P.ws = R.gl_nodes(LEVEL[2], dps)
        a, b = mpf(t0), mpf(t1)
        m = sub_mesh(cv, a, b, rho_p)
        lp = mp.fsum(P.gl(m[i], m[i + 1]) for i in range(len(m) - 1))
        C = R.Check.__new__(R.Check)
        C.cv, C.prec = cv, prec
        with localcontext() as ctx:
            ctx.prec = prec
            ctx.Emax, ctx.Emin = 10 ** 6, -10 ** 6
            xs, ws = R.gl_nodes(LEVEL[5], prec)
            C.xs = [C.dec(x) for x in xs]
            C.ws = [C.dec(w) for w in ws]
            C.d = [[Decimal(x.numerator) / Decimal(x.denominator) for x in di]
                   for di in cv.d]
            with mp.workdps(prec):
                mc = sub_mesh(cv, a, b, rho_c)
            mc = [C.dec(p) for p in mc]
            lc = mpf(str(sum(C.gl(mc[i], mc[i + 1])
                             for i in range(len(mc) - 1))))
        if lp == 0 or abs(lp - lc) > abs(lp) * mpf("1e-35"):
            raise SystemExit("not verified: %s vs %s" % (lp, lc))
        return lp


def main():
    rows = ["\t".join(["id", "dim", "coords", "t0", "t1", "L"])]
    for cid, dim, c in curves():
        cv = R.Curve(c, dim)
        f = foot(cv)
        if f is None or cv.zero:
            continue
        for w in WIDTHS:
            for lo, hi in ((f - w, f + w / 3), (f + w / 5, f + w)):
                t0, t1 = max(lo, 0.0), min(hi, 1.0)
                if not t0 < t1:
                    continue
                L = length(cv, t0, t1)
                rows.append("\t".join([cid, str(dim),
                                       " ".join(repr(v) for v in c),
                                       repr(t0), repr(t1),
                                       R.mpmath.nstr(L, 30)]))
    path = os.path.join(DATA, "subranges.tsv")
    with open(path + ".tmp", "w") as fh:
        fh.write("\n".join(rows) + "\n")
    os.replace(path + ".tmp", path)
    print("%s: %d rows" % (os.path.relpath(path, ROOT), len(rows) - 1))


if __name__ == "__main__":
    main()
