#!/usr/bin/python3
"""tools/check_markers_rsvg.py -- where librsvg puts each marker instance,
against arclen.svg, on spec/data/svg/hand/marker-*.svg (doc/svg.md,
"Markers").

Each document is given stroke="black" on its <marker> elements and
fill="none" on its root, so that only the markers' content paints a
stroke; librsvg (python3-gi, gir1.2-rsvg-2.0) renders it at its own size
onto a cairo SVG surface, which writes each stroked path with its matrix;
arclen.svg reads the same text with stroked = true, and each instance's CTM
(e.ctm) is compared with librsvg's matrix, in order, to 1e-4 relative.
Prints per file the instances of each and how many agree, and each one
that does not.

Usage: /usr/bin/python3 tools/check_markers_rsvg.py   (from the repository
       root, after make)
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

import cairo
import gi
gi.require_version("Rsvg", "2.0")
from gi.repository import Rsvg  # noqa: E402

OURS = r'''
local svg = require "arclen.svg"
for _, e in ipairs(svg.read(arg[1], {stroked = true}).elements) do
  if e.marker then print(("%.17g %.17g %.17g %.17g %.17g %.17g"):format(table.unpack(e.ctm))) end
end
'''


def librsvg(path, out):
    h = Rsvg.Handle.new_from_file(path)
    _, w, hh = h.get_intrinsic_size_in_pixels()
    surf = cairo.SVGSurface(out, w, hh)
    vp = Rsvg.Rectangle()
    vp.x, vp.y, vp.width, vp.height = 0, 0, w, hh
    h.render_document(cairo.Context(surf), vp)
    surf.finish()
    text = open(out).read()
    return [[float(x) for x in m.split(",")]
            for m in re.findall(r'<path[^>]*transform="matrix\(([^)]*)\)"', text)]


def ours(path):
    env = dict(os.environ, LUA_PATH="lua/?.lua;lua/?/init.lua;;", LUA_CPATH="build/5.4/?.so;;")
    out = subprocess.run(["lua5.4", "-", path], input=OURS, capture_output=True, text=True,
                         env=env, check=True).stdout
    return [[float(x) for x in line.split()] for line in out.splitlines()]


def main():
    tmp = tempfile.mkdtemp()
    for f in sorted(glob.glob("spec/data/svg/hand/marker-*.svg")):
        text = open(f).read().replace("<marker ", '<marker stroke="black" ')
        text = text.replace("<svg ", '<svg fill="none" ', 1)
        src = os.path.join(tmp, os.path.basename(f))
        open(src, "w").write(text)
        a, b = ours(src), librsvg(src, src + ".out.svg")
        eq = lambda x, y: all(abs(p - q) <= 1e-4 * max(1, abs(p)) for p, q in zip(x, y))
        # the longest common subsequence of the two lists: an instance one of
        # them leaves out shifts the rest
        L = [[0] * (len(b) + 1) for _ in range(len(a) + 1)]
        for i in range(len(a) - 1, -1, -1):
            for j in range(len(b) - 1, -1, -1):
                L[i][j] = L[i + 1][j + 1] + 1 if eq(a[i], b[j]) else max(L[i + 1][j], L[i][j + 1])
        i = j = 0
        while i < len(a) or j < len(b):
            if i < len(a) and j < len(b) and eq(a[i], b[j]):
                i, j = i + 1, j + 1
            elif j == len(b) or (i < len(a) and L[i + 1][j] >= L[i][j + 1]):
                print("  arclen %d: %s (librsvg: none there)" % (i + 1, a[i]))
                i += 1
            else:
                print("  librsvg %d: %s (arclen: none there)" % (j + 1, b[j]))
                j += 1
        same = L[0][0]
        print("%-40s arclen %2d, librsvg %2d, the same %2d" % (os.path.basename(f), len(a), len(b), same))
    return 0


if __name__ == "__main__":
    sys.exit(main())
