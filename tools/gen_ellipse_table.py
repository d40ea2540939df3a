#!/usr/bin/python3
"""Write src/gauss/ellipse_table.c: the Bernstein-ellipse quantities of the error
bound in gauss_bound.c as lines on short cells, each a bound on its cell,
and the constants of the rules' aliasing that the bound uses.

Aliasing: the n-point rule's error on T_k is 0 for odd k (the rule is
symmetric), about pi/2 in size for k = 2n and 2n + 2, tiny for larger k up
to about 4n, and never above 2 + 2/(k^2 - 1) <= 32/15.  ALIAS[0], ALIAS[1]
and ALIAS[2] bound |E_n(T_2n)|, |E_n(T_2n+2)| and |E_n(T_k)| for even k in
[2n + 4, 3n], for every rule of src/gauss/gauss_tables.c as stored (n = 2..128),
computed at 50 digits from the stored doubles.  With rho^-2 = r, the tail
sum_{k even >= 2n} |E_n(T_k)| rho^(2n - k) is then at most
    C(n) = ALIAS[0] + ALIAS[1] r + (ALIAS[2] r^2 + (32/15) rho^-(n+1)) / (1 - r),
falling with n: C(2) bounds it for every order, C(32) from the estimates'
reference order on (gauss_bound.c's REF_ORDER).

For a branch point whose ellipse has semi-major axis a = 1 + x, the bound
needs lam = log2(rho^2) (from below), its reciprocal (from above), C(2) and
C(32) (from above) and sqrt(a) (from above), rho = a + sqrt(a^2 - 1).
The cells split each octave of x in [2^EMIN, 2^EMAX) into CELLS_PER_OCTAVE
equal parts, so a cell is found from the bits of x.  On a cell [x0, x1]:
- lam = (2 / ln 2) acosh(1 + x) is concave: the chord through values rounded
  down lies below it;
- 1/L for that chord L (a positive line) is convex: the chord through values
  of 1/L rounded up lies above it (gauss_bound.c takes the order from lam and
  1/lam together, so 1/lam must bound the reciprocal of the lam it uses);
- each term of C(n) is convex and falling in rho (r, r^2/(1 - r) =
  1/(rho^2 (rho^2 - 1)), rho^(1-n)/(rho^2 - 1)), and rho is concave in x, so
  C(n) is convex in x: its chord lies above it;
- sqrt(1 + x) is concave: its tangent at x0 lies above it.
Each line is then scaled by 1 -+ 2^-44 (away from the true value), which
covers the few roundings of evaluating it in double precision and the 2^-47
by which gauss_bound.c's x may sit below the true one.  main() checks every
cell at its ends and at interior points against 50-digit values before
writing.  Run: /usr/bin/python3 tools/gen_ellipse_table.py > src/gauss/ellipse_table.c
"""
import math
import re

import mpmath as mp

mp.mp.dps = 50
EMIN, EMAX = -36, 12        # ellipse_table.h: ARCLEN_ELLIPSE_EMIN, _EMAX
CELLS_PER_OCTAVE = 4        # ellipse_table.h: ARCLEN_ELLIPSE_SHIFT = 52 - 2
MARGIN = mp.mpf(2) ** -44
REF_ORDER = 32              # gauss_bound.c: REF_ORDER
RULES = 'src/gauss/gauss_tables.c'


def up(v):
    """The least double >= v."""
    f = float(v)
    return f if mp.mpf(f) >= v else math.nextafter(f, math.inf)


def down(v):
    """The greatest double <= v."""
    f = float(v)
    return f if mp.mpf(f) <= v else math.nextafter(f, -math.inf)


def stored_rules():
    """{n: [(x, w)]} of the non-negative nodes as stored, exactly."""
    text = open(RULES).read()
    arrays = {}
    for name, n, body in re.findall(r'static const double (g[xw])(\d+)\[\] = \{([^}]*)\}', text):
        arrays[name, int(n)] = [mp.mpf(float(v)) for v in body.split(',')]
    return {n: list(zip(arrays['gx', n], arrays['gw', n]))
            for (name, n) in arrays if name == 'gx'}


def aliasing():
    """Upper bounds of |E_n(T_2n)|, |E_n(T_2n+2)| and |E_n(T_k)| over even k
    in [2n + 4, 3n], over the stored rules n = 2..128."""
    worst = [mp.mpf(0)] * 3
    for n, pts in stored_rules().items():
        if n < 2:
            continue
        top = 3 * n + 2
        quad = [mp.mpf(0)] * (top + 1)
        for x, w in pts:
            wt = w if x == 0 else 2 * w          # the node and its mirror
            t0, t1 = mp.mpf(1), x
            quad[0] += wt
            for k in range(1, top + 1):
                quad[k] += wt * t1
                t0, t1 = t1, 2 * x * t1 - t0
        def err(k):
            return abs(mp.mpf(2) / (1 - k * k) - quad[k])
        worst[0] = max(worst[0], err(2 * n))
        worst[1] = max(worst[1], err(2 * n + 2))
        for k in range(2 * n + 4, 3 * n + 1, 2):
            worst[2] = max(worst[2], err(k))
    return [up(v * (1 + mp.mpf(10) ** -20)) for v in worst]


def rho(x):
    return 1 + x + mp.sqrt(x * (x + 2))


def lam(x):
    return 2 * mp.log(rho(x), 2)


def tail(x, n, alias):
    """C(n) at x (the module's doc)."""
    p = rho(x)
    r = 1 / (p * p)
    return (alias[0] + alias[1] * r +
            (alias[2] * r * r + mp.mpf(32) / 15 * p ** -(n + 1)) / (1 - r))


def cell(k):
    """The ends of cell k (exact doubles)."""
    e, j = divmod(k, CELLS_PER_OCTAVE)
    step = mp.mpf(2) ** (EMIN + e) / CELLS_PER_OCTAVE
    x0 = mp.mpf(2) ** (EMIN + e) + j * step
    return x0, x0 + step


def entry(x0, x1, alias):
    w = x1 - x0
    shrink, grow = 1 - MARGIN, 1 + MARGIN
    l0, l1 = down(lam(x0) * shrink), down(lam(x1) * shrink)
    dl = down((mp.mpf(l1) - l0) / w)
    line_at_x1 = mp.mpf(l0) + w * dl              # the L that 1/L bounds
    i0, i1 = up(grow / mp.mpf(l0)), up(grow / line_at_x1)
    di = up((mp.mpf(i1) - i0) / w)
    out = [l0, dl, i0, di]
    for n in (2, REF_ORDER):
        c0, c1 = up(tail(x0, n, alias) * grow), up(tail(x1, n, alias) * grow)
        out += [c0, up((mp.mpf(c1) - c0) / w)]
    s0 = up(mp.sqrt(1 + x0) * grow)
    ds = up(grow / (2 * mp.sqrt(1 + x0)))
    return out + [s0, ds]


def check(x0, x1, ent, alias):
    """The lines, evaluated as gauss_bound.c does (in doubles), bound the
    true values on the cell; x may lie 2^-47 relative below the true one."""
    l0, dl, i0, di, c0, dc, r0, dr, s0, ds = ent
    for k in range(65):
        x = float(x0 + (x1 - x0) * k / 64)
        if x >= x1:
            x = math.nextafter(float(x1), 0)
        dx = x - float(x0)                   # exact (Sterbenz)
        lrun = l0 + dx * dl
        irun = i0 + dx * di
        assert lrun <= lam(mp.mpf(x)), (x, lrun)
        assert mp.mpf(irun) * lrun >= 1, (x, irun, lrun)
        assert c0 + dx * dc >= tail(mp.mpf(x), 2, alias), x
        assert r0 + dx * dr >= tail(mp.mpf(x), REF_ORDER, alias), x
        xt = mp.mpf(x) * (1 + mp.mpf(2) ** -47) + mp.mpf(2) ** -47
        assert s0 + dx * ds >= mp.sqrt(1 + xt), x


def main():
    ncell = (EMAX - EMIN) * CELLS_PER_OCTAVE
    alias = aliasing()
    out = ['/* Generated by tools/gen_ellipse_table.py -- do not edit. */',
           '#include "gauss/ellipse_table.h"', '',
           'const double arclen_gauss_alias[3] = {%s};' % ', '.join(repr(v) for v in alias),
           '',
           'const arclen_ellipse_cell arclen_ellipse_cells[%d] = {' % ncell]
    for k in range(ncell):
        x0, x1 = cell(k)
        ent = entry(x0, x1, alias)
        check(x0, x1, ent, alias)
        out.append('  {%s},' % ', '.join(repr(v) for v in ent))
    out.append('};')
    print('\n'.join(out))


main()
