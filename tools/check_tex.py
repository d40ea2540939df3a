#!/usr/bin/env python3
"""tools/check_tex.py MODE POSFILE [OTHER_POSFILE] -- make luatex's check of
examples/tex/tikz_marks.tex: the marks it wrote (POSFILE, sp) against the
mpmath references of tools/ref_tex.py (spec/data/tex_marks.tsv,
tex_bend.tsv).  MODE "exact": every mark within 1e-4 pt, every tangent's
cosine and sine within 1e-4, no mark missing or extra, the bending
library's points within |z'| 2^-17 + 1e-4 pt (its contract returns the
time as a dimension, 2^-16 apart); with OTHER_POSFILE, the two runs agree
within 1e-4 pt.  MODE "mp": MetaPost's numbers (check_mp).  MODE "stock": the same numbers for stock pgf, reported.
Prints "ok"/"FAIL" lines and ends "N passed, N failed"."""
import os
import sys

SP = 65536.0
TOL = 1e-4
SHIFT = {"arch": 320.0, "tight": 320.0}   # the pictures' shift={(320pt,0pt)}
DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "spec", "data")


widths = set()


def read_pos(path):
    marks, bends = {}, {}
    for line in open(path):
        f = line.split()
        if len(f) < 7:
            continue
        curve, label = f[0], f[1]
        x, y = int(f[3]) / SP - SHIFT.get(curve, 0.0), int(f[4]) / SP
        if label == "bend":
            bends[(curve, f[2])] = (int(f[3]) / SP, int(f[4]) / SP)
        elif label == "text":
            # a glyph box's origin: its centre is half its width along (a, b)
            a, b, w = float(f[5]), float(f[6]), int(f[7])
            widths.add(w)
            marks.setdefault((curve, label), []).append(
                (x + 0.5 * w / SP * a, y + 0.5 * w / SP * b, a, b))
        else:
            marks.setdefault((curve, label), []).append((x, y, float(f[5]), float(f[6])))
    return marks, bends


def read_tsv(name):
    rows = []
    for line in open(os.path.join(DATA, name)):
        if not line.startswith("#"):
            rows.append(line.rstrip("\n").split("\t"))
    return rows


def check_mp(path):
    """MODE "mp": what examples/tex/mp_record.mp wrote (bp) against
    spec/data/tex_mp.tsv: lengths and points within 1e-8, times and unit
    directions within 1e-9 (arclen's tol is 1e-12 of a few hundred bp);
    the ends of dashes (dash:s) and of a subpath (sub:s) are the points at
    s; every reference row is asked for."""
    ref = {}
    for r in read_tsv("tex_mp.tsv"):
        ref[(r[0], r[1])] = [float(v) for v in r[2:7]]
    seen = set()
    passed = failed = 0
    for line in open(path):
        f = line.split()
        if len(f) != 7:
            continue
        name, label = f[0], f[1]
        got = [float(v) for v in f[2:7]]
        key = (name, label.split(":", 1)[1] if label.startswith(("dash:", "sub:")) else label)
        want = ref.get(key)
        what = "MetaPost %s %s" % (name, label)
        if want is None:
            ok, msg = False, "no reference"
        else:
            seen.add(key)
            d = max(abs(got[0] - want[0]), abs(got[1] - want[1]))
            msg = "point (length) error %.2e (<= 1e-8)" % d
            ok = d <= 1e-8
            if label == key[1] and label != "-1" and not label.startswith("pts:"):
                e = max(abs(g - w) for g, w in zip(got[2:], want[2:]))
                msg += ", time and direction error %.2e (<= 1e-9)" % e
                ok = ok and e <= 1e-9
        print(("ok   " if ok else "FAIL ") + what + ": " + msg)
        passed, failed = passed + ok, failed + (not ok)
    missing = sorted(set(ref) - seen)
    ok = not missing
    print(("ok   " if ok else "FAIL ") + "every reference asked for" + ("" if ok else ": missing %s" % missing))
    passed, failed = passed + ok, failed + (not ok)
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


def main():
    mode, pos = sys.argv[1], sys.argv[2]
    if mode == "mp":
        return check_mp(pos)
    marks, bends = read_pos(pos)
    ref = {}
    for r in read_tsv("tex_marks.tsv"):
        if r[1] != "length":
            ref.setdefault((r[0], r[1]), []).append(tuple(float(v) for v in r[4:8]))
    passed = failed = 0

    def check(ok, what):
        nonlocal passed, failed
        if mode == "stock":
            print("     " + what)
            return
        print(("ok   " if ok else "FAIL ") + what)
        if ok:
            passed += 1
        else:
            failed += 1

    for key in sorted(ref):
        want, got = ref[key], marks.get(key, [])
        name = "%s %s" % key
        check(len(got) == len(want), "%s: %d marks (mpmath: %d)" % (name, len(got), len(want)))
        n = min(len(got), len(want))
        if n == 0:
            continue
        dpos = max(((g[0] - w[0]) ** 2 + (g[1] - w[1]) ** 2) ** 0.5 for g, w in zip(got, want))
        dtan = max(max(abs(g[2] - w[2]), abs(g[3] - w[3])) for g, w in zip(got, want))
        check(dpos <= TOL, "%s: worst position error %.2e pt (<= %g)" % (name, dpos, TOL))
        check(dtan <= TOL, "%s: worst tangent (cos, sin) error %.2e (<= %g)" % (name, dtan, TOL))
    if ("wave", "text") in ref:
        check(widths == {344064}, "text along path: every glyph 5.25pt (344064sp) wide, as "
              "the reference assumes (Latin Modern Mono): %s" % sorted(widths))
    for r in read_tsv("tex_bend.tsv"):
        got = bends.get((r[0], r[1]))
        name = "bending %s, %spt from the end" % (r[0], r[1])
        if got is None:
            check(False, name + ": not written")
            continue
        d = ((got[0] - float(r[2])) ** 2 + (got[1] - float(r[3])) ** 2) ** 0.5
        tol = float(r[4]) * 2 ** -17 + TOL
        check(d <= tol, "%s: error %.2e pt (<= %.2e)" % (name, d, tol))
    if len(sys.argv) > 3:
        other, obends = read_pos(sys.argv[3])
        worst = 0.0
        for key, got in marks.items():
            for g, o in zip(got, other.get(key, [])):
                worst = max(worst, ((g[0] - o[0]) ** 2 + (g[1] - o[1]) ** 2) ** 0.5)
        same = all(len(other.get(k, [])) == len(v) for k, v in marks.items())
        check(same and worst <= TOL, "C engine against Lua engine: same marks, worst "
              "difference %.2e pt (<= %g)" % (worst, TOL))
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
