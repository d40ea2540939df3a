#!/usr/bin/python3
"""Reference values for Carlson's R-functions with arguments spread over
the whole double range (subnormal 2^-1074 .. 2^1023, and zeros), written
to spec/data/carlson_spread.tsv in the format of spec/data/carlson.tsv
(fn kind x y z p ref lo cond), kind "spread", or "pv" for R_C with y < 0.
Only rows whose value is a finite normal double are kept.

R_F, R_D, R_C, R_G: mpmath's elliprf/elliprd/elliprc/elliprg at 60
digits (their duplication runs to convergence at any spread); every fifth
row, and every R_J row, is also computed by the quadrature over log t of
tools/ref_carlson_extreme.py (mpmath's elliprj is wrong at extreme p), and
a disagreement beyond 1e-25 stops the script.  Takes about 3 minutes.

Run with Debian's python3-mpmath:  /usr/bin/python3 tools/ref_carlson_spread.py
"""
import os
import random
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ref_carlson import fmt  # noqa: E402
import ref_carlson_extreme as Q  # noqa: E402

MPF = {"rf": mp.elliprf, "rd": mp.elliprd, "rc": mp.elliprc,
       "rg": mp.elliprg}
NARGS = {"rf": 3, "rd": 3, "rc": 2, "rg": 3, "rj": 4}


def anywhere(rng):
    """A double anywhere in [0, DBL_MAX]: 5% zero, 10% subnormal, else a
    uniform binary exponent -1022..1023."""
    r = rng.random()
    if r < 0.05:
        return 0.0
    if r < 0.15:
        return rng.randint(1, 2 ** 52) * 2.0 ** -1074
    return rng.uniform(1, 2) * 2.0 ** rng.randint(-1022, 1023)


def fixed():
    """The reported cases (conic engineer) and their relatives."""
    return [("rd", [2.5e-237, 4e231, 1e-232]), ("rd", [2.5, 4e200, 1e-300]),
            ("rd", [4e231, 2.5e-237, 1e-232]), ("rd", [1e-300, 1e-300, 1e300]),
            ("rf", [5e-324, 5e-324, 1e308]), ("rf", [5e-324, 1.0, 1e308]),
            ("rc", [1e308, 5e-324]), ("rc", [5e-324, 1e308]),
            ("rc", [1.15e-201, -4.5e170]), ("rg", [5e-324, 1.0, 1e308]),
            ("rj", [2.5e-237, 4e231, 1e-232, 1.0]),
            ("rj", [5e-324, 1e308, 1.0, 1e-300]),
            ("rj", [1e300, 1e-300, 1.0, 1e300]),
            ("rj", [3.9525251667299724e-323] * 3 + [2.6815910353546649e+154])]


def reference(fn, a, check):
    A = [mp.mpf(v) for v in a]
    if fn == "rc" and A[1] < 0:
        return mp.re(mp.elliprc(*A)), "pv"
    if fn == "rj":
        return Q.rj(*A), "spread"
    v = MPF[fn](*A)
    if check:
        w = Q.QUAD[fn](*A)
        if abs(w - v) > mp.mpf("1e-25") * abs(v):
            sys.exit("%s%r: mpmath %s, quadrature %s" % (
                fn, tuple(a), mp.nstr(v, 20), mp.nstr(w, 20)))
    return v, "spread"


def main():
    mp.mp.dps = 60
    Q.mp.mp.dps = 40
    rng = random.Random(20261122)
    rows = fixed()
    for i in range(300):
        fn = ["rf", "rd", "rc", "rg", "rc"][i % 5]
        a = [anywhere(rng) for _ in range(NARGS[fn])]
        if i % 10 == 4:
            a[1] = -a[1]                                 # R_C's PV
        rows.append((fn, a))
    for i in range(16):
        rows.append(("rj", [anywhere(rng) for _ in range(4)]))
    with open("spec/data/carlson_spread.tsv", "w") as f:
        f.write("fn\tkind\tx\ty\tz\tp\tref\tlo\tcond\n")
        for i, (fn, a) in enumerate(rows):
            try:
                v, kind = reference(fn, a, i % 5 == 0)
            except (ZeroDivisionError, ValueError):
                continue                             # a domain error
            if not mp.isfinite(v) or not (2.0 ** -1022 <= abs(v) <= 1.7e308):
                continue
            c = [repr(float(x)) for x in a] + [""] * (4 - len(a))
            f.write("%s\t%s\t%s\t%s\t%s\t%s\t%s\t1\n" % (fn, kind, *c, fmt(v)))


if __name__ == "__main__":
    main()
