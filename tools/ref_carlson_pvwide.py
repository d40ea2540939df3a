#!/usr/bin/python3
"""R_J's principal value (p < 0) at arguments spread beyond 2^1000 (issue
23; CHANGELOG's open case rj(5.2e-202, 5.5e273, 8.1e189, -7.9e-207)).
Writes spec/data/carlson_pvwide.tsv in the format of carlson_extreme.tsv
(fn kind x y z p ref lo cond, kind "pvwide").

The values by the reduction DLMF 19.20.14 at 40 digits, with R_J and R_F
(positive arguments) by the log-scaled quadrature of
tools/ref_carlson_extreme.py and R_C by mpmath's closed form, and
r = (z (x + q) + y (z - x))/(z + q) in the sum form; its condition (the
terms over the value) goes with each row.  Not the principal-value
quadrature of ref_carlson_extreme (rj_pv): at these spreads it gave
2.7e-156 where the reduction's three terms give 8.1e-219 (its last term
alone: 3 sqrt(xyz/w) R_C(w, rq)/(z + q), w ~ rq); the first row, where it
holds, is checked against it.  Nor its pv_cond: r = z - (z - x)(z - y)/(z + q)
cancels to 0 at 40 digits here (R_C(xy, 0) = inf).  Seeded: x, y, z, -p
log-uniform over 1e-300 .. 1e300, kept when the largest over the smallest
passes 2^1000, plus the CHANGELOG case (each row costs minutes of
quadrature: N is small).

Run with Debian's python3-mpmath:  /usr/bin/python3 tools/ref_carlson_pvwide.py
"""
import os
import random
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ref_carlson_extreme as R  # noqa: E402
from ref_carlson import fmt  # noqa: E402

mp.mp.dps = 40
N = 8


def cases():
    yield (5.2e-202, 5.5e273, 8.1e189, -7.9e-207)
    rng = random.Random(2304)
    n = 0
    while n < N:
        v = [10.0 ** rng.uniform(-300, 300) for _ in range(4)]
        if max(v) / min(v) <= 2.0 ** 1000:
            continue
        n += 1
        yield (v[0], v[1], v[2], -v[3])


def reduction(x, y, z, p):
    """(value, condition) of DLMF 19.20.14 for R_J(x, y, z, p), p < 0."""
    x, y, z = sorted([x, y, z])
    q = -p
    zq = z + q
    t = (z - x) * (z - y) / zq
    r = (z * (x + q) + y * (z - x)) / zq
    terms = [-t * R.rj(x, y, z, r), -3 * R.rf(x, y, z)]
    if x > 0:
        w = x * y + r * q
        terms.append(3 * mp.sqrt(x * y * z / w) * mp.elliprc(w, r * q))
    v = sum(terms) / zq
    return v, sum(abs(u) for u in terms) / abs(zq * v)


def main():
    out = os.path.join(R.__dict__.get("DATA", os.path.join(
        os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
        "spec", "data")), "carlson_pvwide.tsv")
    rows = ["fn\tkind\tx\ty\tz\tp\tref\tlo\tcond"]
    for x, y, z, p in cases():
        a = [mp.mpf(t) for t in (x, y, z, p)]
        v, c = reduction(*a)
        if not rows[1:]:                # the CHANGELOG case: both ways
            w = R.rj_pv(*a)
            if abs(w - v) > mp.mpf("1e-18") * abs(v):   # (they agree to 2e-20)
                raise SystemExit("reduction %s vs quadrature %s" % (v, w))
        rows.append("rj\tpvwide\t%r\t%r\t%r\t%r\t%s\t%s" % (
            x, y, z, p, fmt(v), mp.nstr(c, 6)))
        print(rows[-1], flush=True)
        with open(out, "w") as f:            # as it goes: rows are slow
            f.write("\n".join(rows) + "\n")


main()
