#!/usr/bin/python3
"""tools/ref_rsvg.py -- librsvg's opinion on what an SVG document draws
(spec/data/svg_rsvg.tsv).

librsvg (GNOME's renderer, Debian librsvg2, through python3-gi with
gir1.2-rsvg-2.0) renders each document onto a cairo SVG surface
(python3-cairo, python3-gi-cairo); cairo writes every fill and every stroke
it is asked for as a <path d> with shapes, <use>, CSS, <switch>, units and
transforms already resolved.  Counting those paths and measuring them gives
a second opinion, independent of ours and of tools/ref_svg.py, on the
structure -- which shapes are drawn, with which paint -- not on digits.

The choices, each forced by how librsvg and cairo work:
  - Text is removed before rendering (<text>, Inkscape's <flowRoot>):
    librsvg draws glyph outlines, which arclen does not measure.
  - The page.  librsvg maps the document into the viewport given to
    render_document and makes every intermediate surface (opacity groups,
    masks) the size of that viewport, and cairo drops what falls outside a
    surface.  So the document's root becomes a nested <svg> (x = y = 0,
    width and height its viewBox's, so one user unit is one unit of the new
    root; without a viewBox its width and height are kept: user units are
    px either way) inside a new root, turned by atan(21/20) about the
    document's centre (a fill of an axis-parallel line has no extent, and
    cairo drops it; lengths do not change) and whose viewBox is the extent
    of librsvg's ink (get_geometry_for_layer on a page 2001 document sizes
    wide, the document scaled to 1000 units so that librsvg's extents stay
    inside cairo's fixed point) and an eighth more; the old root's
    font-size goes with it.  The
    nested <svg>, every <svg> and <symbol>, get overflow:visible, and every
    element clip-path, mask and filter none (arclen applies none of them; a
    filter would make a raster image of the geometry), as !important
    declarations at the end of each element's style attribute (the
    strongest place in the cascade, SVG 2 section 6.3).  The DPI is CSS's
    96 (librsvg's default is 90).
  - Fixed point.  cairo keeps device coordinates in 24.8 fixed point
    (1/256) and prints a stroke's path in the user space of the stroke with
    6 decimals; its fill paths come out off by up to ~1e-8 of their
    coordinates (measured: 0.027 device units at 2.6e6, where the stroke of
    the same path is exact).  The page is 2^22 device units wide; the
    column quant bounds what all three do to the total: each point moves
    by at most d = sqrt(2) (1/512 + 5e-7 |map| + 2^-26 |point|) device
    units, a line's length by 2 d, a cubic's by 6 d (B' is 3 times a
    convex combination of differences of control points, each off by at
    most 2 d).
  - Arcs.  librsvg makes each elliptical arc (and circles, ellipses,
    rounded corners) cubics of at most 90 degrees (+0.001 rad) with the
    handle length 4/3 tan(theta/4): a quarter circle's cubic is 1.41e-4
    longer than the arc, 60 degrees 1.23e-5, 45 degrees 2.2e-6; under a
    map of aspect ratio up to 1e6, 7.62e-4 (--arcs).  Lengths of documents
    with arcs agree with arclen to that, not to its 1e-12.
  - Three modes, as doc/svg.md defines them:
    * default (all geometry whatever its paint): a copy in which every
      shape says stroke:#000; stroke-opacity:1; stroke-width:1 and every
      element opacity:1 (!important at the end of its style attribute, so
      no sheet or attribute can take them back); display, visibility,
      conditional processing, <use>, the sheets' other rules are kept as
      they are.  visibility is NOT made visible: arclen's default mode does
      not draw visibility:hidden (only `hidden` does).  The strokes cairo
      writes are counted.
    * stroked: the document itself; the strokes are counted.
    * painted: the document itself, each element (shapes, g, use, a,
      switch) shifted by a translation of its own below 1e-3 of the size
      (lengths do not change); cairo writes a shape's fill and its stroke
      as two paths (or one path with both), in the order paint-order
      gives: a fill and a stroke next to each other with the same number
      of points, the same length (to 1e-7 and the rounding) and the same
      start (to 1e-7 of the page) are one shape; two drawings of one
      shape (two uses of it) differ by their shifts.  A <line>'s fill is
      none here: librsvg hands it to cairo, but a line has no interior
      (SVG 2 section 10.5) and paints nothing.
  - What is not geometry: the content of <pattern> (a pattern's tile is
    paint), <mask>, <clipPath> and <filter> in the output; <image> (a
    raster) is counted in the column images, and must be 0.
  - Markers are drawn by librsvg.  Each mode is also rendered with
    marker-start/mid/end none on every shape (columns shapes_nomarkers,
    length_nomarkers): what a reader that does not draw markers must match.
    In default mode the stroke-width forced on every shape would scale its
    markers (markerUnits="strokeWidth"): the row is the rendering without
    markers plus one where the shapes outside markers keep their own
    stroke-width but paint nothing (stroke and fill none) and the markers'
    content (a <marker>'s descendants and what its <use>s draw) is stroked
    as above.  In painted mode a marker's content, and a <symbol>'s or a
    nested <svg>'s, is not shifted (a shift would move it against the
    clip).
  - Clips.  cairo writes a marker's clip (its viewport under overflow
    hidden; librsvg's also at a <symbol>'s or nested <svg>'s viewBox) as
    nested <clipPath>s of closed polylines and the path whole: each path is
    cut here to the intersection of the clips above it (each side a line:
    the crossings of a Bezier coordinate, split where it is monotone, by
    bisection; a piece is kept when its middle is within 4 d of the inside),
    and quant takes, for each end a clip makes, 2 d / sin(the angle between
    the curve and the side).  A path the clips leave nothing of is not
    counted: cairo writes it or drops it by its extents against the clip's.
  - Languages: librsvg 2.54 passes every systemLanguage whatever the
    locale (tried: LANGUAGE, LANG, LC_ALL, LC_MESSAGES set to en, de, C),
    and tests conditional attributes only on the children of a <switch>;
    the script sets LANGUAGE=en, arclen's default, all the same.
  - What the script cannot see: a fill whose path has no extent at all (a
    polygon of one point) is dropped by cairo, not by librsvg.

Columns: file, mode (default / stroked / painted), shapes, length (total,
in the root's user units), quant (the fixed-point and printing bound on
the total), shapes_nomarkers, length_nomarkers, quant_nomarkers, images.

Usage: /usr/bin/python3 tools/ref_rsvg.py [FILE...]   (from the repository
root; with no FILE every document under spec/data/svg/ and the TSV is
written; with files, their rows are printed; --arcs: the arcs' bound)
"""
import math
import os
import re
import sys

os.environ["LANGUAGE"] = "en"                   # before glib reads it

import cairo                                    # noqa: E402
import gi                                       # noqa: E402
gi.require_version("Rsvg", "2.0")
from gi.repository import Rsvg                  # noqa: E402
from lxml import etree                          # noqa: E402
import xml.etree.ElementTree as ET              # noqa: E402

SVG_NS = "http://www.w3.org/2000/svg"
XLINK = "{http://www.w3.org/1999/xlink}href"
SHAPES = {"path", "rect", "circle", "ellipse", "line", "polyline", "polygon"}
TEXT = {"text", "flowRoot"}
NUM = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
DEVICE = 2.0 ** 22                              # the page's width in device units
NORM = 1000.0                                   # the document's size in the page's units
MARGIN = 1000                                   # the first page around the document, in its sizes
TURN = math.degrees(math.atan2(21, 20))         # the page's turn: no axis-parallel fills
MODES = ("default", "stroked", "painted")


def local(tag):
    return tag.split("}", 1)[1] if isinstance(tag, str) and tag.startswith("{") else tag


def add_style(el, decls):
    old = (el.get("style") or "").strip()
    if old and not old.endswith(";"):
        old += ";"
    el.set("style", old + ";".join(d + " !important" for d in decls))


def marker_content(root):
    """The elements a <marker> draws: its descendants and what its <use>
    elements refer to (and their descendants), to a depth of 32 uses."""
    ids = {}
    for el in root.iter():
        if isinstance(el.tag, str) and el.get("id") is not None:
            ids.setdefault(el.get("id"), el)
    seen = set()
    todo = [m for m in root.iter() if isinstance(m.tag, str) and local(m.tag) == "marker"]
    for _ in range(32):
        nxt = []
        for top in todo:
            for el in top.iter():
                if el in seen or not isinstance(el.tag, str):
                    continue
                seen.add(el)
                if local(el.tag) == "use":
                    ref = (el.get(XLINK) or el.get("href") or "")[1:]
                    if ref in ids:
                        nxt.append(ids[ref])
        todo = nxt
    return seen


def prepare(data, mode, markers, box=None, only_markers=False):
    """The document as it is rendered: text removed, the page, the mode;
    only_markers (default mode): the shapes paint nothing, their markers'
    content is stroked."""
    parser = etree.XMLParser(resolve_entities=True, huge_tree=False, no_network=True)
    root = etree.fromstring(data, parser)
    for el in list(root.iter()):
        if local(el.tag) in TEXT and el.getparent() is not None:
            el.getparent().remove(el)
    vb = [float(x) for x in NUM.findall(root.get("viewBox") or "")]
    if len(vb) == 4 and vb[2] > 0 and vb[3] > 0:
        root.set("width", repr(vb[2]))
        root.set("height", repr(vb[3]))
        size = max(vb[2], vb[3])
    else:                                       # user units are px
        size = 0
        for k in ("width", "height"):
            m = re.match(r"\s*([0-9.eE+-]+)\s*([a-z%]*)", root.get(k) or "")
            if m and m.group(2) != "%":
                size = max(size, float(m.group(1)) * {"": 1, "px": 1, "in": 96, "mm": 96 / 25.4,
                                                       "cm": 96 / 2.54, "pt": 4 / 3, "pc": 16}[m.group(2)])
        size = size or 1000.0
    for k in ("x", "y"):
        root.attrib.pop(k, None)
    outer = etree.Element("{%s}svg" % SVG_NS, nsmap={None: SVG_NS,
                                                     "xlink": "http://www.w3.org/1999/xlink"})
    if box is None:                             # a page to find the drawing's extent on
        x0 = y0 = -MARGIN * NORM
        page = (2 * MARGIN + 1) * NORM
    else:                                       # the drawing's extent and an eighth more
        page = max(box[2] - box[0], box[3] - box[1], NORM / 1e3) * 1.25
        x0 = (box[0] + box[2]) / 2 - page / 2
        y0 = (box[1] + box[3]) / 2 - page / 2
    outer.set("viewBox", "%r %r %r %r" % (x0, y0, page, page))
    outer.set("width", repr(page))
    outer.set("height", repr(page))
    if root.get("font-size") is not None:
        outer.set("font-size", root.get("font-size"))
    m = re.search(r"font-size\s*:\s*([^;]+)", root.get("style") or "")
    if m:
        outer.set("style", "font-size:" + m.group(1))
    turn = etree.SubElement(outer, "{%s}g" % SVG_NS)
    k = NORM / size                             # the page's units: the document is NORM wide
    turn.set("transform", "scale(%r) rotate(%r %r %r)" % (k, TURN, size / 2, size / 2))
    turn.append(root)
    content = marker_content(root)
    still = set(content)                        # what painted mode does not shift
    # cairo's output has a clip at a <symbol>'s or nested <svg>'s viewBox
    # even under overflow:visible (hand/use.svg), which the content may
    # touch: not shifted either, a shift would move it across that clip
    for vp in root.iter():
        if isinstance(vp.tag, str) and local(vp.tag) in ("symbol", "svg") and vp is not root:
            still.update(x for x in vp.iter() if x is not vp)
    nth = 0
    for el in root.iter():
        if not isinstance(el.tag, str) or (el.tag.startswith("{") and not el.tag.startswith("{%s}" % SVG_NS)):
            continue                            # no namespace: SVG to librsvg and to arclen
        name = local(el.tag)
        if mode == "painted" and name in SHAPES | {"g", "use", "a", "switch"} and el not in still:
            # a shift of its own for each element, below 1e-3 of the size:
            # the fill and the stroke of one drawing share it, two drawings
            # (two uses of one shape) differ by more than cairo's rounding;
            # not a marker's content, which its viewport clips (a shift
            # there would move the cuts) and its instances place apart
            nth += 1
            dx, dy = (size * 1e-3 * ((nth * x) % 1) for x in (0.6180339887, 0.4142135624))
            el.set("transform", "translate(%r %r) %s" % (dx, dy, el.get("transform") or ""))
        decls = ["clip-path:none", "mask:none", "filter:none"]
        if name in ("svg", "symbol"):
            decls.append("overflow:visible")
        if mode == "default":
            decls.append("opacity:1")
            if only_markers and name in SHAPES and el not in content:
                # the shape's own width scales its markers: kept; the
                # shape itself paints nothing (the rendering without
                # markers counts it)
                decls += ["stroke:none", "fill:none"]
            elif name in SHAPES:
                decls += ["stroke:#000", "stroke-opacity:1", "stroke-width:1"]
        if name == "line":
            decls.append("fill:none")           # no interior (SVG 2 section 10.5)
        if not markers and name in SHAPES:
            decls += ["marker-start:none", "marker-mid:none", "marker-end:none"]
        add_style(el, decls)
    return etree.tostring(outer), (x0, y0, page), DEVICE / page * k


def render(svgtext, page, scale):
    """librsvg onto a cairo SVG surface; the SVG cairo writes."""
    import io
    handle = Rsvg.Handle.new_from_data(svgtext)
    handle.set_dpi(96)                          # CSS: 96 px to the inch
    out = io.BytesIO()
    surf = cairo.SVGSurface(out, DEVICE, DEVICE)
    cr = cairo.Context(surf)
    vp = Rsvg.Rectangle()
    vp.x, vp.y, vp.width, vp.height = 0, 0, DEVICE, DEVICE
    if not handle.render_document(cr, vp):
        raise RuntimeError("librsvg failed to render")
    surf.finish()
    return out.getvalue()


def extent(svgtext, page):
    """The box (in the page's user units) that librsvg's ink covers."""
    handle = Rsvg.Handle.new_from_data(svgtext)
    handle.set_dpi(96)
    vp = Rsvg.Rectangle()
    vp.x, vp.y, vp.width, vp.height = 0, 0, DEVICE, DEVICE     # within cairo's fixed point
    size = page[2] / (2 * MARGIN + 1)
    try:
        ok, ink, logical = handle.get_geometry_for_layer(None, vp)
    except gi.repository.GLib.Error:           # e.g. InvalidSize: a page of 33 sizes
        return (-16 * size, -16 * size, 17 * size, 17 * size)
    # the ink and the geometry: a fill of a line (a path of no area) has no
    # ink, but cairo writes it where the geometry is
    rects = [r for r in (ink, logical) if r.width > 0 or r.height > 0]
    if not ok or not rects:
        return (0, 0, size, size)
    # the extents are in the page's user units, from the corner of its viewBox
    return (page[0] + min(r.x for r in rects), page[1] + min(r.y for r in rects),
            page[0] + max(r.x + r.width for r in rects), page[1] + max(r.y + r.height for r in rects))


# ---- the paths cairo wrote ---------------------------------------------------

def mat(s):
    if not s:
        return (1, 0, 0, 1, 0, 0)
    m = re.fullmatch(r"\s*matrix\(([^)]*)\)\s*", s)
    assert m, "unexpected transform %r" % s
    v = [float(x) for x in NUM.findall(m.group(1))]
    assert len(v) == 6
    return tuple(v)


def mul(P, Q):
    a, b, c, d, e, f = P
    A, B, C, D, E, F = Q
    return (a * A + c * B, b * A + d * B, a * C + c * D, b * C + d * D,
            a * E + c * F + e, b * E + d * F + f)


def gl_nodes(n=16):
    """Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n)."""
    xs, ws = [], []
    for i in range(1, n + 1):
        x = math.cos(math.pi * (i - 0.25) / (n + 0.5))
        for _ in range(100):
            p0, p1 = 1.0, x
            for k in range(2, n + 1):
                p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
            dp = n * (x * p1 - p0) / (x * x - 1)
            dx = p1 / dp
            x -= dx
            if abs(dx) < 1e-16:
                break
        xs.append((1 - x) / 2)
        ws.append(1 / ((1 - x * x) * dp * dp))
    return list(zip(xs, ws))


GL = gl_nodes()


def cubic_len(p):
    """A cubic's length by 16-point Gauss-Legendre on pieces halved until
    each piece's halves agree with it to 1e-14 of the whole curve's length
    (absolute, so that a cusp's pieces converge too; 30 halvings at most)."""
    def quad(q):
        d = [(3 * (q[i + 1][0] - q[i][0]), 3 * (q[i + 1][1] - q[i][1])) for i in range(3)]
        s = 0.0
        for t, w in GL:
            u = 1 - t
            x = u * u * d[0][0] + 2 * u * t * d[1][0] + t * t * d[2][0]
            y = u * u * d[0][1] + 2 * u * t * d[1][1] + t * t * d[2][1]
            s += w * math.hypot(x, y)
        return s

    def halves(q):
        m = lambda a, b: ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        a, b, c = m(q[0], q[1]), m(q[1], q[2]), m(q[2], q[3])
        ab, bc = m(a, b), m(b, c)
        mid = m(ab, bc)
        return (q[0], a, ab, mid), (mid, bc, c, q[3])

    chord = sum(math.dist(p[i], p[i + 1]) for i in range(3))
    tol = 1e-14 * chord

    def rec(q, whole, depth):
        h1, h2 = halves(q)
        a, b = quad(h1), quad(h2)
        if abs(a + b - whole) <= tol or depth >= 30:
            return a + b
        return rec(h1, a, depth + 1) + rec(h2, b, depth + 1)
    return rec(p, quad(p), 0)


def bez(q, t):
    """The point at t of the Bezier curve of control points q (de Casteljau)."""
    q = list(q)
    while len(q) > 1:
        q = [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])) for a, b in zip(q, q[1:])]
    return q[0]


def sub(q, t0, t1):
    """The control points of q's piece from t0 to t1 (de Casteljau twice)."""
    def split(q, t):                            # the part from t to 1
        rows = [list(q)]
        while len(rows[-1]) > 1:
            r = rows[-1]
            rows.append([(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])) for a, b in zip(r, r[1:])])
        return [row[-1] for row in reversed(rows)]
    right = split(q, t0)
    if t1 >= 1:
        return right
    u = (t1 - t0) / (1 - t0)
    rev = split(list(reversed(right)), 1 - u)   # the part from 0 to u, reversed
    return list(reversed(rev))


def edges(poly):
    """A convex polygon's edges as (point, unit direction, unit inward normal)."""
    n = len(poly)
    area = sum(poly[i][0] * poly[(i + 1) % n][1] - poly[(i + 1) % n][0] * poly[i][1] for i in range(n))
    out = []
    for i in range(n):
        a, b = poly[i], poly[(i + 1) % n]
        L = math.dist(a, b)
        if L == 0:
            continue
        u = ((b[0] - a[0]) / L, (b[1] - a[1]) / L)
        nrm = (-u[1], u[0]) if area > 0 else (u[1], -u[0])
        out.append((a, u, nrm))
    return out


def crossings(f):
    """The t in (0, 1) where the Bernstein polynomial f (degree <= 3) is 0:
    split where it is monotone (the roots of its derivative), bisection to
    the last bit on each piece whose ends differ in sign."""
    k = len(f) - 1
    d = [k * (f[i + 1] - f[i]) for i in range(k)]
    cuts = [0.0, 1.0]
    if len(d) == 2:
        if d[0] != d[1]:
            cuts.append(d[0] / (d[0] - d[1]))
    elif len(d) == 3:                           # d0 (1-t)^2 + 2 d1 t (1-t) + d2 t^2
        a, b, c = d[0] - 2 * d[1] + d[2], 2 * (d[1] - d[0]), d[0]
        if a == 0:
            if b != 0:
                cuts.append(-c / b)
        else:
            disc = b * b - 4 * a * c
            if disc >= 0:
                r = math.sqrt(disc)
                cuts += [(-b - r) / (2 * a), (-b + r) / (2 * a)]
    cuts = sorted(t for t in cuts if 0 <= t <= 1)
    val = lambda t: bez([(x, 0) for x in f], t)[0]
    roots = []
    for lo, hi in zip(cuts, cuts[1:]):
        flo, fhi = val(lo), val(hi)
        if flo == 0 or fhi == 0 or (flo > 0) == (fhi > 0):
            continue
        for _ in range(200):
            mid = (lo + hi) / 2
            if mid <= lo or mid >= hi:
                break
            fm = val(mid)
            if (fm > 0) == (flo > 0):
                lo, flo = mid, fm
            else:
                hi = mid
        roots.append((lo + hi) / 2)
    return roots


def clipped(q, clips, dev):
    """The length of the Bezier q (device units) inside every polygon of
    clips, and the bound on what the clip's rounding does to it: each kept
    end at a crossing moves along the curve by (the displacement of the
    point and of the side) / sin(the angle between them)."""
    if not clips:
        return (cubic_len(q) if len(q) == 4 else math.dist(q[0], q[1])), 0.0, 1
    sides = [e for poly in clips for e in edges(poly)]
    ts = [0.0, 1.0]
    for a, u, nrm in sides:
        ts += crossings([(p[0] - a[0]) * nrm[0] + (p[1] - a[1]) * nrm[1] for p in q])
    ts = sorted(set(ts))
    # on a side is inside: the sides' corners are printed to 1/512 or so
    tol = 4 * dev(q[0])
    inside = lambda p: all((p[0] - a[0]) * nrm[0] + (p[1] - a[1]) * nrm[1] >= -tol for a, u, nrm in sides)
    keep = [inside(bez(q, (t0 + t1) / 2)) for t0, t1 in zip(ts, ts[1:])]
    total, err = 0.0, 0.0
    for i, (t0, t1) in enumerate(zip(ts, ts[1:])):
        if not keep[i]:
            continue
        piece = sub(q, t0, t1)
        total += cubic_len(piece) if len(piece) == 4 else math.dist(piece[0], piece[1])
        for t, other in ((t0, i - 1), (t1, i + 1)):
            if not 0 < t < 1 or keep[other]:
                continue                        # an end of the curve, or both sides kept
            c = bez(q, t)
            a, u, nrm = min(sides, key=lambda e: abs((c[0] - e[0][0]) * e[2][0] + (c[1] - e[0][1]) * e[2][1]))
            p0, p1 = bez(q, max(t - 1e-7, 0)), bez(q, min(t + 1e-7, 1))
            v = (p1[0] - p0[0], p1[1] - p0[1])
            sin = abs(v[0] * nrm[0] + v[1] * nrm[1]) / (math.hypot(*v) or 1.0)
            err += 2 * dev(c) / max(sin, 1e-9)
    return total, err, sum(keep)


def measure(d, M, eps_local, clips=()):
    """Length in device units of path data d (cairo's M, L, C, Z) under M;
    its rounding bound (2 d per line, 6 d per cubic); its start; points."""
    tok = re.findall(r"[MLCZ]|" + NUM.pattern, d)
    pt = lambda x, y: (M[0] * x + M[2] * y + M[4], M[1] * x + M[3] * y + M[5])
    norm = math.hypot(M[0], M[1]) + math.hypot(M[2], M[3])
    # one point's displacement (device units): the fixed point's 1/512, the
    # printing's eps_local (times the map), and 2^-26 of the point's size:
    # cairo's fill paths come out off by up to ~1e-8 of their coordinates
    # (0.027 at 2.6e6, where the stroke of the same path is exact)
    dev = lambda q: math.sqrt(2) * (1 / 512 + eps_local * norm + 2.0 ** -26 * max(abs(q[0]), abs(q[1])))
    i, cur, start, first = 0, None, None, None
    pieces = []                                 # point lists: [p, q] a line, [p, c1, c2, q] a cubic
    while i < len(tok):
        c = tok[i]
        i += 1
        if c == "M":
            cur = start = pt(float(tok[i]), float(tok[i + 1]))
            first = first or cur
            i += 2
        elif c == "L":
            q = pt(float(tok[i]), float(tok[i + 1]))
            pieces.append([cur, q])
            cur = q
            i += 2
        elif c == "C":
            v = [float(x) for x in tok[i:i + 6]]
            q = [cur, pt(v[0], v[1]), pt(v[2], v[3]), pt(v[4], v[5])]
            pieces.append(q)
            cur = q[3]
            i += 6
        elif c == "Z":
            pieces.append([cur, start])
            cur = start
        else:
            raise AssertionError("unexpected path data %r" % c)
    total, quant, npts, kept = 0.0, 0.0, 0, 0
    for q in pieces:
        L, e, k = clipped(q, clips, dev)
        total += L
        kept += k
        quant += 2 * (len(q) - 1) * max(dev(x) for x in q) + e     # 2 d a line, 6 d a cubic
        npts += len(q) - 1
    return total, quant, first, npts, kept


def outputs(svg_bytes):
    """The fills and strokes cairo wrote, in order: (kind, length, quant,
    start, points), device units; and the number of raster images."""
    root = ET.fromstring(svg_bytes)
    ids = {el.get("id"): el for el in root.iter() if el.get("id")}
    out, images = [], [0]
    skip = {"pattern", "mask", "clipPath", "filter", "defs"}

    def polygons(ref, M):
        """A clip-path's polygons (device units): cairo writes a marker's
        clip (its viewport, under overflow hidden) as a <clipPath> of
        closed polylines, the path itself whole."""
        cp = ids.get(ref)
        assert cp is not None and local(cp.tag) == "clipPath", "clip-path %r" % ref
        assert cp.get("clipPathUnits", "userSpaceOnUse") == "userSpaceOnUse"
        C = mul(M, mat(cp.get("transform")))
        polys = []
        for ch in cp:
            assert local(ch.tag) in ("path", "rect"), "a clip of a <%s>" % local(ch.tag)
            K = mul(C, mat(ch.get("transform")))
            d = ch.get("d", "")
            if local(ch.tag) == "rect":             # a device-aligned clip: x, y, width, height
                x, y, w, h = (float(ch.get(k)) for k in ("x", "y", "width", "height"))
                d = "M %r %r L %r %r L %r %r L %r %r Z" % (x, y, x + w, y, x + w, y + h, x, y + h)
            tok = re.findall(r"[MLCZ]|" + NUM.pattern, d)
            assert "C" not in tok, "a clip with curves"
            nums = [float(x) for x in tok if x not in "MLZ"]
            pts = [(K[0] * x + K[2] * y + K[4], K[1] * x + K[3] * y + K[5])
                   for x, y in zip(nums[0::2], nums[1::2])]
            while len(pts) > 1 and pts[-1] == pts[0]:
                pts.pop()                       # the closing point and the moveto after Z
            assert tok.count("M") <= 2 and len(pts) >= 3, "clip path %r" % ch.get("d")
            polys.append(pts)
        assert len(polys) == 1, "a clip of %d paths" % len(polys)
        return polys

    def walk(el, M, depth, clips=()):
        assert depth < 64, "use nesting"
        name = local(el.tag)
        if name in skip:
            return
        M = mul(M, mat(el.get("transform")))
        cref = re.fullmatch(r"url\(#([^)]*)\)", el.get("clip-path") or "")
        if cref:
            clips = tuple(clips) + tuple(polygons(cref.group(1), M))
        if name == "path":
            st = dict(kv.split(":", 1) for kv in (x.strip() for x in el.get("style", "").split(";"))
                      if ":" in kv)
            st = {k.strip(): v.strip() for k, v in st.items()}
            fill = st.get("fill", "rgb(0%,0%,0%)") != "none"
            stroke = st.get("stroke", "none") != "none"
            if not (fill or stroke):
                return
            L, q, start, n, kept = measure(el.get("d", ""), M, 0.5e-6, clips)
            if clips and not kept:
                # a marker's content its viewport clips away: cairo writes
                # it or not by its extents against the clip's (arclen lists
                # it with no segments; spec/svgrsvg_spec.lua leaves it out)
                return
            kinds = ([("fill",) if fill else ()] + [("stroke",) if stroke else ()])
            for k in kinds:
                if k:
                    out.append((k[0], L, q, start, n, bool(fill and stroke)))
        elif name == "use":
            target = ids.get((el.get(XLINK) or el.get("href") or "#")[1:])
            if target is not None:
                walk(target, M, depth + 1, clips)
        elif name == "image":
            images[0] += 1
        elif name in ("g", "svg"):
            for ch in el:
                walk(ch, M, depth, clips)
        elif name == "rect":
            raise AssertionError("cairo painted a rectangle outside a mask")

    walk(root, (1, 0, 0, 1, 0, 0), 0)
    return out, images[0]


def count(outs, mode, size):
    """Shapes and their total (device units) from cairo's outputs."""
    if mode in ("default", "stroked"):
        sel = [o for o in outs if o[0] == "stroke"]
        return len(sel), sum(o[1] for o in sel), sum(o[2] for o in sel)
    n, L, Q, i = 0, 0.0, 0.0, 0
    while i < len(outs):
        o = outs[i]
        if o[5]:                                  # one path element, filled and stroked
            n, L, Q, i = n + 1, L + o[1], Q + o[2], i + 2
            continue
        if i + 1 < len(outs):
            p = outs[i + 1]
            if (p[0] != o[0] and not p[5] and p[4] == o[4] and abs(p[1] - o[1]) <= 1e-7 * o[1] + o[2] + p[2]
                    and math.dist(p[3], o[3]) <= 1e-7 * size):
                n, L, Q, i = n + 1, L + o[1], Q + o[2], i + 2
                continue
        n, L, Q, i = n + 1, L + o[1], Q + o[2], i + 1
    return n, L, Q


def rows_of(path, name):
    with open(path, "rb") as fh:
        data = fh.read()
    rows = []
    for mode in MODES:
        row = [name, mode]
        images = 0
        res = {}
        for part in ("markers", "shapes", "all"):
            if part == "markers" and mode != "default":
                continue
            markers = part != "shapes"
            if part == "all" and mode == "default":
                # the shapes stroked with width 1 (without markers) and their
                # markers scaled by the shapes' own widths (markerUnits)
                res["all"] = tuple(a + b for a, b in zip(res["shapes"], res["markers"]))
                continue
            only = part == "markers"
            text, page, scale = prepare(data, mode, markers, only_markers=only)
            text, page, scale = prepare(data, mode, markers, extent(text, page), only_markers=only)
            outs, im = outputs(render(text, page, scale))
            images = max(images, im)
            n, L, Q = count(outs, mode, DEVICE)
            res[part] = (n, L / scale, Q / scale)
        for part in ("all", "shapes"):
            n, L, Q = res[part]
            row += [str(n), repr(L), "%.3g" % Q]
        rows.append(row + [str(images)])
    return rows


def arc_bound():
    """The worst relative length error of librsvg's arc cubics (up to 90
    degrees + 0.001 rad, handles 4/3 tan(theta/4)) on a unit circle and
    under scale(r, 1), r from 1 to 1e6, start angles every 0.05 rad, the
    arcs' lengths by mpmath: what spec/svgrsvg_spec.lua's ARC_BAR covers."""
    import mpmath as mp
    dth = math.pi / 2 + 0.001
    h = 4 / 3 * math.tan(dth / 4)
    for r in (1, 1.5, 3, 10, 100, 1e4, 1e6):
        worst = 0.0
        for i in range(126):
            a, b = 0.05 * i, 0.05 * i + dth
            c0, c3 = (math.cos(a), math.sin(a)), (math.cos(b), math.sin(b))
            q = [c0, (c0[0] - h * c0[1], c0[1] + h * c0[0]), (c3[0] + h * c3[1], c3[1] - h * c3[0]), c3]
            Lc = cubic_len([(r * x, y) for x, y in q])
            f = lambda t: mp.sqrt((r * mp.sin(t)) ** 2 + mp.cos(t) ** 2)
            cuts = [a] + [k * mp.pi for k in range(int(a // math.pi) + 1, int(b // math.pi) + 1)] + [b]
            Le = float(mp.quad(f, cuts))
            worst = max(worst, abs(Lc - Le) / Le)
        print("aspect %-8g worst relative error %.4g" % (r, worst))


def main():
    if sys.argv[1:] == ["--arcs"]:
        return arc_bound()
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    base = os.path.join(repo, "spec", "data", "svg")
    if len(sys.argv) > 1:
        for f in sys.argv[1:]:
            for r in rows_of(f, f):
                print("\t".join(r))
        return
    files = []
    for sub in ("hand", "real", "graphviz"):
        files += sorted(sub + "/" + f for f in os.listdir(os.path.join(base, sub)) if f.endswith(".svg"))
    out = os.path.join(repo, "spec", "data", "svg_rsvg.tsv")
    with open(out, "w") as fh:
        fh.write("# generated by tools/ref_rsvg.py (librsvg %d.%d.%d, cairo %s)\n" % (
            Rsvg.MAJOR_VERSION, Rsvg.MINOR_VERSION, Rsvg.MICRO_VERSION, cairo.cairo_version_string()))
        fh.write("file\tmode\tshapes\tlength\tquant\tshapes_nomarkers\tlength_nomarkers\t"
                 "quant_nomarkers\timages\n")
        for f in files:
            for r in rows_of(os.path.join(base, f), f):
                fh.write("\t".join(r) + "\n")
                print("\t".join(r), flush=True)


if __name__ == "__main__":
    main()
