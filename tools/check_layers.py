#!/usr/bin/env python3
"""tools/check_layers.py OBJDIR -- the dependencies between the core's
object files, read with nm: every undefined symbol of an object is matched
with the object that defines it.  Fails (and says where) when two objects
depend on each other through any chain (a cycle), or when an object needs
one of an area that comes later in the order of doc/architecture.md:

  curve -> roots -> gauss -> elliptic -> metapost, fit, conic, baseline
        -> segment, methods, svg -> svgdoc (the document reader, over expat)

Prints "N passed, N failed" (one check per object)."""
import collections
import os
import subprocess
import sys

ORDER = {"curve": 0, "roots": 1, "gauss": 2, "elliptic": 3, "metapost": 4,
         "fit": 4, "conic": 4, "baseline": 4, "segment": 5, "methods": 5,
         "svg": 5,
         "svgdoc": 6}


def objects(top):
    for area in sorted(os.listdir(top)):
        d = os.path.join(top, area)
        if os.path.isdir(d):
            for f in sorted(os.listdir(d)):
                if f.endswith(".o"):
                    yield area, os.path.join(d, f)


def main():
    top = sys.argv[1] if len(sys.argv) > 1 else "build/core"
    defs, uses, area_of = {}, collections.defaultdict(set), {}
    for area, path in objects(top):
        name = area + "/" + os.path.basename(path)[:-2]
        area_of[name] = area
        out = subprocess.run(["nm", path], capture_output=True, text=True,
                             check=True).stdout
        for line in out.splitlines():
            f = line.split()
            if len(f) == 3 and f[1] in "TDBRC":
                defs[f[2]] = name
            elif len(f) == 2 and f[0] == "U":
                uses[name].add(f[1])
    if not area_of:
        print("check_layers: no objects under %s (run make lib)" % top)
        print("0 passed, 1 failed")
        return 1
    graph = {n: {} for n in area_of}
    for n, syms in uses.items():
        for s in syms:
            d = defs.get(s)
            if d and d != n:
                graph[n].setdefault(d, s)
    passed = failed = 0
    for n in sorted(graph):
        bad = []
        for d, sym in sorted(graph[n].items()):
            if area_of[n] not in ORDER or area_of[d] not in ORDER:
                bad.append("%s is in no area of the order" %
                           (n if area_of[n] not in ORDER else d))
            elif ORDER[area_of[d]] > ORDER[area_of[n]]:
                bad.append("needs %s (%s), a later area" % (d, sym))
        # a cycle through n: n reachable from one of its dependencies
        seen, stack = set(), list(graph[n])
        while stack:
            m = stack.pop()
            if m == n:
                bad.append("is on a cycle of object files")
                break
            if m not in seen:
                seen.add(m)
                stack.extend(graph[m])
        if bad:
            failed += 1
            for b in bad:
                print("FAIL %s: %s" % (n, b))
        else:
            passed += 1
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
