#!/usr/bin/python3
"""References for the length-versus-t fit (spec/fit_spec.lua).

1. spec/data/lenfit_published.tsv -- Walter & Fournier's published numbers,
   parsed from the seed text (nothing typed): the worst curve's control
   points (Sec. 5) and Table 1 (max of set, avg of max errors, avg of
   averages for Cooper, Zurich, Random; n = 10).
2. spec/data/gauss_legendre.tsv -- n-point Gauss-Legendre rules on [0, 1]
   for a few n, by mpmath at 40 digits (roots of P_n by Newton, checked
   with mpmath.legendre; weights 2/((1-x^2) P_n'(x)^2), mapped to [0, 1]).
3. spec/data/lenfit_worst.tsv -- for the paper's worst curve, at 40 digits:
   the true s(t)/s(1) at t = k/20 (mpmath quad, split at the speed's
   critical points), the paper's n = 10 span ordinates (Eqns 4-5 on
   mpmath Gauss-Legendre lengths) and its max and mean error on the
   paper's grid t = 0, ..., 0.95 against that truth.

Usage: /usr/bin/python3 tools/ref_lenfit.py WALTER_FOURNIER.txt (the paper's text)
"""
import os
import re
import sys

import mpmath as mp

mp.mp.dps = 40
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "spec", "data")
GL_NS = [1, 2, 3, 4, 10, 24, 64]


def published(text):
    rows = []
    m = re.search(r"control vertices\s+defined by\s*(.*?)\.\s", text, re.S)
    nums = re.findall(r"\d+\.\d+", m.group(1))
    if len(nums) != 8:
        raise ValueError("worst curve: expected 8 numbers, got %r" % nums)
    for i, v in enumerate(nums):
        rows.append(("worst_curve", "c%d" % (i + 1), v))
    for label, key in [("max of set", "max"), ("avg of maxerrors", "avgmax"),
                       ("avg of averages", "avgavg")]:
        m = re.search(re.escape(label) + r"[\s|]+([\d.]+)\s*\|\s*([\d.]+)\s*\|\s*([\d.]+)", text)
        if not m:
            raise ValueError("Table 1 row not found: " + label)
        for setname, v in zip(["cooper", "zurich", "random"], m.groups()):
            rows.append(("table1_" + setname, key, v))
    m = re.search(r"number of curves\s+(\d+)\s+(\d+)\s+(\d+)", text)
    for setname, v in zip(["cooper", "zurich", "random"], m.groups()):
        rows.append(("table1_" + setname, "curves", v))
    return rows


def legendre(n, x):
    """P_n(x) and P_n'(x) at 40 digits (three-term recurrence)."""
    p0, p1 = mp.mpf(1), x
    if n == 0:
        return p0, mp.mpf(0)
    for k in range(2, n + 1):
        p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
    return p1, n * (x * p1 - p0) / (x * x - 1)


def gauss_legendre(n):
    """Nodes and weights on [0, 1], ascending (Newton at 40 digits)."""
    out = []
    for i in range(n):
        x = mp.cos(mp.pi * (i + mp.mpf(3) / 4) / (n + mp.mpf(1) / 2))
        for _ in range(100):
            p, dp = legendre(n, x)
            dx = p / dp
            x -= dx
            if abs(dx) < mp.mpf(10) ** -38:
                break
        # mpmath's own P_n confirms the root independently of the recurrence.
        assert abs(mp.legendre(n, x)) < mp.mpf(10) ** -30
        _, dp = legendre(n, x)
        out.append(((1 - x) / 2, 1 / ((1 - x * x) * dp * dp)))
    out.sort()
    return out


def hodograph(c):
    p = [(mp.mpf(c[2 * i]), mp.mpf(c[2 * i + 1])) for i in range(4)]
    a0 = [3 * (p[1][k] - p[0][k]) for k in range(2)]
    a1 = [6 * (p[2][k] - 2 * p[1][k] + p[0][k]) for k in range(2)]
    a2 = [3 * (p[3][k] - 3 * p[2][k] + 3 * p[1][k] - p[0][k]) for k in range(2)]
    return a2, a1, a0


def worst(c):
    a2, a1, a0 = hodograph(c)

    def speed(t):
        return mp.sqrt(sum(((a2[k] * t + a1[k]) * t + a0[k]) ** 2 for k in range(2)))

    # Q'.Q'' roots in (0, 1): split points for the quadrature.
    cub = [2 * sum(a2[k] ** 2 for k in range(2)), 3 * sum(a2[k] * a1[k] for k in range(2)),
           sum(a1[k] ** 2 + 2 * a2[k] * a0[k] for k in range(2)),
           sum(a1[k] * a0[k] for k in range(2))]
    crit = sorted(mp.re(r) for r in mp.polyroots(cub, maxsteps=200, extraprec=200)
                  if abs(mp.im(r)) < mp.mpf(10) ** -30 and 0 < mp.re(r) < 1)

    def length(t):
        pts = [mp.mpf(0)] + [r for r in crit if r < t] + [t]
        return mp.quad(speed, pts)

    total = length(mp.mpf(1))
    rows = [("critical", str(i + 1), mp.nstr(r, 30)) for i, r in enumerate(crit)]
    truth = {}
    for k in range(21):
        t = mp.mpf(k) / 20
        truth[k] = length(t) / total
        rows.append(("truth", str(k), mp.nstr(truth[k], 30)))
    # The paper's fit with n = 10: one span when at most one critical point.
    assert len(crit) <= 1
    nodes = gauss_legendre(10)

    def gl(b):
        return b * sum(w * speed(b * x) for x, w in nodes)

    l1, l2, l3 = gl(mp.mpf(1) / 3), gl(mp.mpf(2) / 3), gl(mp.mpf(1))
    ya, yb = l1 / l3, l2 / l3
    v1 = (18 * ya - 9 * yb + 2) / 6
    v2 = (-9 * ya + 18 * yb - 5) / 6
    y = [mp.mpf(0), v1, v2, mp.mpf(1)]
    for i, v in enumerate(y):
        rows.append(("paper10_y", str(i), mp.nstr(v, 30)))
    rows.append(("paper10_total", "0", mp.nstr(l3, 30)))
    errs = []
    for k in range(20):
        t = mp.mpf(k) / 20
        u = 1 - t
        yt = u ** 3 * y[0] + 3 * u * u * t * y[1] + 3 * u * t * t * y[2] + t ** 3 * y[3]
        errs.append(abs(truth[k] - yt))
    rows.append(("paper10_err", "max", mp.nstr(max(errs), 30)))
    rows.append(("paper10_err", "mean", mp.nstr(sum(errs) / 20, 30)))
    return rows


def write(name, header, rows):
    with open(os.path.join(OUT, name), "w") as f:
        f.write("\t".join(header) + "\n")
        for r in rows:
            f.write("\t".join(str(v) for v in r) + "\n")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: tools/ref_lenfit.py WALTER_FOURNIER.txt (the paper's text)")
    seed = sys.argv[1]
    with open(seed) as f:
        text = f.read()
    pub = published(text)
    write("lenfit_published.tsv", ["what", "key", "value"], pub)
    gl = []
    for n in GL_NS:
        for i, (x, w) in enumerate(gauss_legendre(n)):
            gl.append((n, i + 1, mp.nstr(x, 30), mp.nstr(w, 30)))
    write("gauss_legendre.tsv", ["n", "i", "node", "weight"], gl)
    c = [float(v) for (what, _, v) in pub if what == "worst_curve"]
    write("lenfit_worst.tsv", ["what", "key", "value"], worst(c))


if __name__ == "__main__":
    main()
