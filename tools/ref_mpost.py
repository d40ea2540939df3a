#!/usr/bin/python3
"""Reference values for the "metapost" method from real MetaPost.

Runs `mpost -ini -numbersystem=double` (Debian texlive-binaries) on Henkel's six
arcs and a few hundred random and adversarial cubics (near-cusps, collinear
reversals, tiny, huge up to and over the 16384 leg limit, far from the origin)
plus open and cyclic multi-segment paths, and writes what mpost prints:

  spec/data/mpost.tsv        one cubic per row: arclength and arctime at
                             L/4, L/2, 3L/4 (the goals as mpost computed them)
  spec/data/mpost_paths.tsv  paths: arclength and arctime at several goals
                             (negative, zero, inside, beyond the end)

In double mode mpost prints numbers with %.17g, so every value round-trips.
-ini mode with `delimiters ();` needs no plain.mp (Debian ships plain.mp in
texlive-metapost, not in texlive-base); arclength and arctime are primitives.

Usage: /usr/bin/python3 tools/ref_mpost.py   (from the repository root)
"""
import os
import random
import subprocess
import sys
import tempfile

EL_GORDO_TEXT = "8.9884656743115785e+307"   # mpost's overflowed arclength


def num(x):
    """A coordinate as MetaPost reads it back to the same double."""
    s = repr(float(x))
    if s in ("inf", "-inf", "nan"):
        raise ValueError(s)
    return s


def pt(x, y):
    return "(%s,%s)" % (num(x), num(y))


def path_text(segs, cyclic):
    """segs: list of 8-tuples that join; cyclic: last one closes the path."""
    out = pt(segs[0][0], segs[0][1])
    for k, s in enumerate(segs):
        end = "cycle" if (cyclic and k == len(segs) - 1) else pt(s[6], s[7])
        out += "..controls %s and %s..%s" % (pt(s[2], s[3]), pt(s[4], s[5]), end)
    return out


# ---- the curves -----------------------------------------------------------

HENKEL = [
    ("henkel1", (0, 0, 10, 0, 10, 10, 0, 0)),
    ("henkel2", (0, 0, 10, 10, 0, 10, 10, 0)),
    ("henkel3", (0, 0, 10, 10, 0, 9.999, 10, 0)),
    ("henkel4", (0, 0, 1, 1, 9, 9, 10, 10)),
    ("henkel5", (0, 0, 20, 20, -10, -10, 10, 10)),
    ("henkel6", (0, 0, 20.001, 20, -10, -10, 10, 10)),
]


def from_hodograph(p0, a0, a1, a2):
    """Control points of the cubic with z'(t) = a2 t^2 + a1 t + a0 (complex)."""
    d0 = a0 / 3
    d1 = d0 + a1 / 6
    d2 = a2 / 3 - d0 + 2 * d1
    p1 = p0 + d0
    p2 = p1 + d1
    p3 = p2 + d2
    return tuple(v for z in (p0, p1, p2, p3) for v in (z.real, z.imag))


def curves(rng):
    out = list(HENKEL)
    rnd = lambda lo, hi: rng.uniform(lo, hi)
    for i in range(100):                       # ordinary random, [0,10]^2
        out.append(("random", tuple(rnd(0, 10) for _ in range(8))))
    for scale in (1e-6, 1e-3, 0.1, 100.0, 1000.0):
        for i in range(6):
            out.append(("scale", tuple(scale * rnd(-1, 1) for _ in range(8))))
    for i in range(6):                         # far from the origin
        ox, oy = rnd(1e5, 1e7), rnd(-1e7, -1e5)
        c = [rnd(0, 10) for _ in range(8)]
        out.append(("far", tuple(c[j] + (ox if j % 2 == 0 else oy) for j in range(8))))
    for i in range(12):                        # large: legs up to ~15500
        out.append(("large", tuple(rnd(0, 10900) for _ in range(8))))
    for eps in (1e-1, 1e-2, 1e-3, 1e-5, 1e-7, 1e-9, 1e-12):   # Henkel 3 family
        out.append(("nearcusp", (0, 0, 10, 10, 0, 10 - eps, 10, 0)))
        out.append(("nearcusp", (0, 0, 20 + eps, 20, -10, -10, 10, 10)))
    for i in range(20):                        # cusps and near-cusps at random t*
        ts = rnd(0.05, 0.95)
        al = complex(rnd(-20, 20), rnd(-20, 20))
        be = complex(rnd(-20, 20), rnd(-20, 20))
        a2, a1, a0 = be, al - be * ts, -al * ts
        eps = 0.0 if i % 4 == 0 else 10.0 ** (-rng.randint(1, 12))
        a0 += complex(eps, eps / 3)
        out.append(("cusp", from_hodograph(complex(rnd(-5, 5), rnd(-5, 5)), a0, a1, a2)))
    dirs = [(1, 1), (1, 0), (0, 1), (3, -2), (-1, 2), (1, -1)]
    for i in range(18):                        # collinear, most reversing
        dx, dy = dirs[i % len(dirs)]
        s = [0.0] + [rnd(-10, 20) for _ in range(3)]
        bx, by = rnd(-5, 5), rnd(-5, 5)
        out.append(("collinear", tuple(v for si in s for v in (bx + si * dx, by + si * dy))))
    for i in range(6):                         # degenerate: repeated points
        a, b = (rnd(0, 10), rnd(0, 10)), (rnd(0, 10), rnd(0, 10))
        pick = [(a, a, b, b), (a, b, b, b), (a, a, a, b), (a, b, a, b), (a, a, a, a), (a, b, b, a)][i]
        out.append(("degenerate", tuple(v for p in pick for v in p)))
    # over and at the 16384 leg limit: mpost reports "Arithmetic overflow"
    out.append(("overflow", (0, 0, 16384, 0, 16384, 1, 16384, 2)))
    out.append(("overflow", (0, 0, 1, 1, 20000, 1, 20001, 1)))
    out.append(("overflow", (0, 0, 10, 0, 10, 10, 12000, 12000)))
    out.append(("overflow", (5, 5, 6, 6, 7, 7, -20000, 7)))
    out.append(("limit", (0, 0, 16383.99, 0, 16383.99, 1, 16383.99, 2)))
    out.append(("limit", (0, 0, 11585, 11585, 11585, 11586, 0, 11586)))
    return out


def paths(rng):
    out = []
    rnd = lambda lo, hi: rng.uniform(lo, hi)
    for i in range(24):
        n = rng.randint(1, 5)
        cyclic = i % 2 == 1
        pts = [(rnd(0, 10), rnd(0, 10))]
        segs = []
        for k in range(n):
            p0 = pts[-1]
            p3 = pts[0] if (cyclic and k == n - 1) else (rnd(0, 10), rnd(0, 10))
            segs.append((p0[0], p0[1], rnd(0, 10), rnd(0, 10), rnd(0, 10), rnd(0, 10), p3[0], p3[1]))
            pts.append(p3)
        out.append((segs, cyclic))
    # a cyclic path with a collinear reversal, and Henkel's arc 1 as a cycle
    out.append(([(0, 0, 20, 20, -10, -10, 10, 10), (10, 10, 5, 0, 0, 5, 0, 0)], True))
    out.append(([(0, 0, 10, 0, 10, 10, 0, 0)], True))
    return out


# ---- running mpost --------------------------------------------------------

def run_mpost(lines):
    with tempfile.TemporaryDirectory() as d:
        src = os.path.join(d, "ref.mp")
        with open(src, "w") as f:
            f.write("delimiters ();\npath p; numeric L, g;\n")
            f.write("\n".join(lines))
            f.write("\nend\n")
        env = dict(os.environ, max_print_line="1000")
        subprocess.run(["mpost", "-ini", "-numbersystem=double",
                        "-interaction=batchmode", "ref.mp"],
                       cwd=d, env=env, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, check=False)
        with open(os.path.join(d, "ref.log")) as f:
            log = f.read()
    vals = {}
    for line in log.splitlines():
        if line.startswith("V "):
            _, key, v = line.split()[:3]      # the last one ends in " )"
            vals[key] = v
    return vals


def version():
    r = subprocess.run(["mpost", "--version"], capture_output=True, text=True)
    first = r.stdout.splitlines()[0]          # "MetaPost 2.02 (TeX Live ...)"
    return first.split()[1]


def main():
    rng = random.Random(20140514)             # Henkel's date
    cs = curves(rng)
    ps = paths(rng)
    lines = []
    for i, (_, c) in enumerate(cs):
        lines.append("p := %s;" % path_text([c], False))
        lines.append('L := arclength p; message "V c%dL " & decimal L;' % i)
        for q, expr in ((1, "L/4"), (2, "L/2"), (3, "0.75L")):
            lines.append('g := %s; message "V c%dg%d " & decimal g;' % (expr, i, q))
            lines.append('message "V c%dt%d " & decimal (arctime g of p);' % (i, q))
    goals_of = {}
    for i, (segs, cyclic) in enumerate(ps):
        lines.append("p := %s;" % path_text(segs, cyclic))
        lines.append('L := arclength p; message "V p%dL " & decimal L;' % i)
        # goals as fractions of L: MetaPost 2.02 wraps cyclic goals >= L wrongly
        # (fixed in 2.11), so cyclic goals stay inside (-L, L) here.
        fr = [-0.6, -0.25, 0, 0.1, 0.37, 0.5, 0.9] + ([] if cyclic else [1, 1.5])
        goals_of[i] = fr
        for q, f in enumerate(fr):
            lines.append('g := %s*L; message "V p%dg%d " & decimal g;' % (num(f), i, q))
            lines.append('message "V p%dt%d " & decimal (arctime g of p);' % (i, q))
    vals = run_mpost(lines)
    ver = version()
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    with open(os.path.join(root, "spec", "data", "mpost.tsv"), "w") as f:
        f.write("id\tfamily\tx0\ty0\tx1\ty1\tx2\ty2\tx3\ty3\tL\tg1\tt1\tg2\tt2\tg3\tt3\tmpost\n")
        for i, (fam, c) in enumerate(cs):
            L = vals["c%dL" % i]
            row = [str(i), fam] + [num(v) for v in c]
            if L == EL_GORDO_TEXT:             # Arithmetic overflow
                row += ["overflow"] + ["-"] * 6
            else:
                row += [L] + [vals["c%d%s%d" % (i, k, q)] for q in (1, 2, 3) for k in "gt"]
            f.write("\t".join(row + [ver]) + "\n")
    with open(os.path.join(root, "spec", "data", "mpost_paths.tsv"), "w") as f:
        f.write("id\tcyclic\tn\tcoords\tL\tgoals\ttimes\tmpost\n")
        for i, (segs, cyclic) in enumerate(ps):
            coords = ",".join(num(v) for s in segs for v in s)
            fr = goals_of[i]
            goals = ",".join(vals["p%dg%d" % (i, q)] for q in range(len(fr)))
            times = ",".join(vals["p%dt%d" % (i, q)] for q in range(len(fr)))
            f.write("\t".join([str(i), "1" if cyclic else "0", str(len(segs)), coords,
                               vals["p%dL" % i], goals, times, ver]) + "\n")
    print("%d curves, %d paths from MetaPost %s" % (len(cs), len(ps), ver), file=sys.stderr)


if __name__ == "__main__":
    main()
