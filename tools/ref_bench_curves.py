#!/usr/bin/python3
"""Reference lengths of the benchmark's random curve set.

bench/bench_util.h draws control points uniform in [0, 10]^2 with
xorshift64* (Vigna) from a fixed seed; this script draws the same numbers
(the same 64-bit integer arithmetic, the same scaling to a double) and
computes each curve's length twice with tools/ref_lengths.py's integrators
(mpmath Gauss-Legendre on a branch-point mesh, and the independent decimal
check); it stops if they disagree beyond 1e-35.  Writes
bench/peers/random3000.tsv: id, the 8 coordinates (repr), L (30 digits).

Run: nice /usr/bin/python3 tools/ref_bench_curves.py [n] [seed]
"""
import os
import sys

import mpmath
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ref_lengths as rl  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "bench", "peers", "random3000.tsv")
MASK = (1 << 64) - 1


def uniform(state):
    """bench_uniform of bench_util.h: returns (value, new state)."""
    s = state
    s ^= s >> 12
    s = (s ^ (s << 25)) & MASK
    s ^= s >> 27
    v = ((s * 2685821657736338717) & MASK) >> 11
    return float(v) * (1.0 / 9007199254740992.0), s


def curves(n, seed):
    s = seed
    out = []
    for _ in range(n):
        c = []
        for _ in range(8):
            u, s = uniform(s)
            c.append(10 * u)
        out.append(c)
    return out


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 3000
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 20261121
    level = rl.LEVELS[0]
    worst = mpf(0)
    with open(OUT, "w") as f:
        f.write("id\tx0\ty0\tx1\ty1\tx2\ty2\tx3\ty3\tL\n")
        for i, c in enumerate(curves(n, seed)):
            cv = rl.Curve(c, 2)
            with mp.workdps(level[1] + 10):
                lp = rl.Primary(cv, level).s_at(mpf(1))
                lc = rl.Check(cv, level).s_at(mpf(1))
                lc = mpf(str(lc))
                rel = abs(lp - lc) / lp
                if rel > mpf("1e-35"):
                    raise SystemExit("curve %d: integrators disagree (%s)" %
                                     (i, mpmath.nstr(rel, 3)))
                worst = max(worst, rel)
                f.write("random-%d\t%s\t%s\n" % (
                    i + 1, "\t".join(repr(x) for x in c),
                    mpmath.nstr(lp, 30, strip_zeros=False)))
    print("%d curves, max rel. difference primary/check %s -> %s" %
          (n, mpmath.nstr(worst, 3), OUT))


if __name__ == "__main__":
    main()
