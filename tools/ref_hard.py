#!/usr/bin/python3
"""Hard curves for the elliptic method, with 40-digit references.

Three families that lose digits in a chain of closed forms (they do not in
the data: the default method is within 1.2e-15 on them):
  reversal    near-collinear curves that fold back on themselves: four
              points on a line with one or two direction reversals, P1 and
              P2 moved off the line by eps*D, eps = 1e-2 ... 1e-12.     eps
  coincident  a pair or a triple of equal control points (P0=P1, P1=P2,
              P2=P3, P0=P3, P0=P1=P2, P1=P2=P3, P0=P2=P3, P0=P1&P2=P3)
              of random points, and such a curve moved by eps*D off the
              coincidence, eps = 1e-4 ... 1e-15.                 kind[,eps]
  nearcusp    exact cusps moved by eps*D, eps = 1e-9 ... 1e-15 (the
              reference set of curves2d.tsv stops at 1e-12).           eps
Same columns and integrators as tools/ref_lengths.py (its reference()).
Where the times cannot be verified at 110 digits (a stop exactly at a
quarter of the length), the row keeps its lengths (range_length, both
integrators to 1e-30) and gives its times as "-".

3D (hard3d.tsv): the same three families in space (reversal3d,
coincident3d, nearcusp3d), fewer of each: the quartic |z'|^2 is split by
the quartic solver there, so the roots are not the 2D ones.

Run: nice /usr/bin/python3 tools/ref_hard.py [2d|3d|all]
     -> spec/data/hard2d.tsv, spec/data/hard3d.tsv
"""
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import curves  # noqa: E402
import ref_lengths  # noqa: E402

EPS_REV = [10.0 ** -k for k in range(2, 13)]
EPS_COIN = [10.0 ** -k for k in (4, 6, 8, 10, 12, 13, 14, 15)]
EPS_CUSP = [10.0 ** -k for k in range(9, 16)]
REV_LAMS = [(0, 10, -4, 6), (0, 6, -2, 4), (0, 16, -16, 1), (-1, 7, -3, 9),
            (0, 20, -10, 10), (0, 10, 12, 5), (0, 8, 8, -4), (3, -5, 0, 2),
            (0, 3, -1, 1), (0, 12, -9, 2)]


def row_adder(rows):
    """add(family, param, c) appends the row "family-n", n counting that
    family's rows from 1 (the ids both files use)."""
    def add(family, param, c):
        n = sum(1 for r in rows if r[1] == family) + 1
        rows.append(("%s-%d" % (family, n), family, param, curves.fl(c)))
    return add


def hard2d():
    rows = []
    add = row_adder(rows)
    r = random.Random(2301)
    for j, lams in enumerate(REV_LAMS):
        d = curves.LINE_DIRS2[j % len(curves.LINE_DIRS2)]
        o = (r.randint(-8, 8) / 4, r.randint(-8, 8) / 4)
        base = curves.on_line(o, d, lams)
        s = r.random()
        for e in EPS_REV:
            add("reversal", repr(e), curves.perturb(base, 2, e, random.Random(s)))

    r = random.Random(2302)
    for rep in range(4):
        for kind, c in curves.coincident(r, 2):
            add("coincident", kind, c)
            if rep < 2:
                continue
            # the coincident points moved apart by eps*D
            moved = [int(g.split("=")[1][1]) for g in kind.split(",")]
            s = r.random()
            for e in EPS_COIN[rep % 2::2]:
                add("coincident", "%s,%r" % (kind, e),
                    curves.perturb(c, 2, e, random.Random(s), which=moved))

    r = random.Random(2303)
    bases = [lambda e: (0, 0, 10, 10, 0, 10 - 10 * e, 10, 0)]
    bases.append(curves.symmetric_cusp(r, False))
    for p, q in [(1, 2), (1, 4), (3, 10), (3, 4), (1, 16), (1, 3), (7, 8)]:
        c = curves.cusp_base(r, p, q, 2)
        bases.append(lambda e, c=c, s=r.random():
                     curves.perturb(c, 2, e, random.Random(s)))
    for make in bases:
        for e in EPS_CUSP:
            add("nearcusp", repr(e), make(e))
    return rows


DIRS3 = [(1, 0, 0), (0, 0, 1), (1, 1, 1), (0.5, -0.75, 1.25), (3, 4, 12)]


def hard3d():
    rows = []
    add = row_adder(rows)
    r = random.Random(2311)
    for j, lams in enumerate(REV_LAMS[:5]):
        o = tuple(r.randint(-8, 8) / 4 for _ in range(3))
        base = curves.on_line(o, DIRS3[j % len(DIRS3)], lams)
        s = r.random()
        for e in EPS_REV[::2]:
            add("reversal3d", repr(e), curves.perturb(base, 3, e, random.Random(s)))

    r = random.Random(2312)
    for rep in range(2):
        for kind, c in curves.coincident(r, 3):
            add("coincident3d", kind, c)
            moved = [int(g.split("=")[1][1]) for g in kind.split(",")]
            s = r.random()
            for e in EPS_COIN[rep::4]:
                add("coincident3d", "%s,%r" % (kind, e),
                    curves.perturb(c, 3, e, random.Random(s), which=moved))

    r = random.Random(2313)
    for p, q in [(1, 2), (1, 4), (3, 10), (7, 8)]:
        c = curves.cusp_base(r, p, q, 3)
        s = r.random()
        for e in EPS_CUSP[::2]:
            add("nearcusp3d", repr(e), curves.perturb(c, 3, e, random.Random(s)))
    return rows


def reference(coords, dim):
    try:
        return PLAIN_REFERENCE(coords, dim)
    except SystemExit as e:
        print("  times not verified (%s): lengths only" % str(e)[:60], flush=True)
        return [ref_lengths.range_length(coords, dim, 0, t)
                for t in ("0.25", "0.5", "0.75", "1")] + [None] * 3


PLAIN_REFERENCE = ref_lengths.reference


def main():
    which = sys.argv[1] if len(sys.argv) > 1 else "all"
    os.makedirs(ref_lengths.DATA, exist_ok=True)
    ref_lengths.reference = reference      # write() looks it up by name
    if which in ("2d", "all"):
        ref_lengths.write(os.path.join(ref_lengths.DATA, "hard2d.tsv"),
                          hard2d(), 2)
    if which in ("3d", "all"):
        ref_lengths.write(os.path.join(ref_lengths.DATA, "hard3d.tsv"),
                          hard3d(), 3)


if __name__ == "__main__":
    main()
