#!/usr/bin/python3
"""tools/ref_svg.py -- reference lengths of whole SVG documents
(spec/data/svg_refs.tsv).

An independent reading of each document under spec/data/svg/, following the
SVG specification (and the choices doc/svg.md documents where it leaves
room), into exact primitives in document coordinates -- lines, quadratic
and cubic Beziers, elliptical arcs, each with the affine map of its element
-- measured with mpmath at 32 digits:
  - the tree by xml.etree (a DOM: a reference need not stream);
  - basic shapes as SVG 2 chapter 10 defines them (rect with the rx/ry
    auto and clamping rules, circle, ellipse, line, polyline, polygon) and
    path data by tools/ref_paths.py's reader;
  - transforms (SVG 1.1 section 7.6) and viewports (viewBox,
    preserveAspectRatio, SVG 2 section 8.2) as exact matrices (angles by
    mpmath), units by CSS (96 px per inch);
  - <use> of elements and symbols (SVG 2 section 5.6); a <use> of an id no
    element has draws nothing; path data with an error is drawn up to the
    command that holds it (SVG 2 section 9.5.4), nothing if that is the
    first;
  - <style> sheets parsed by tinycss2 and matched by cssselect2 (python3-
    tinycss2, python3-cssselect2: WeasyPrint's and CairoSVG's, not ours),
    cascaded as SVG 2 section 6.3 says (style !important, sheet !important,
    style, sheet, presentation attribute), @media for a plain screen;
    font-size (CSS Fonts 4 section 2.5) for em, ex (em / 2) and rem;
  - lines exactly, Beziers by quadrature of the speed split at its minima
    (B' . B'' = 0) and in 4 (or 16), where Gauss-Legendre and tanh-sinh
    must agree to 1e-24 relative (at a cusp, whose double root polyroots
    gives with an imaginary part of ~1e-16, also at the roots within 1e-8
    of the real line, and in up to 64), each arc by the SVG 1.1 F.6.5
    endpoint-to-centre conversion (F.6.6 radius correction) and the
    integral over its parametric angle of |A R(phi) (-rx sin t, ry cos t)|
    -- the image of the ellipse arc, not a cubic approximation.
svgelements (python3-svgelements) is asked for a second opinion on the
structure only: the number of drawn shapes is printed next to ours (it also
draws what unused symbols, masks and markers hold; its lengths are ~1e-10 off).

Columns: file, units, options (hidden / stroked / painted / -), elements (drawn
shapes), L (total length, 30 digits), arcs, arcscale (sum over arcs of
max(rx', ry', chord'/2), the size of the arc's image in the output units:
arclen's arc tolerance is arc_tol times it, so an arc's length is within
2 pi arc_tol arcscale of the truth).

Values carry 30 digits, of which the quadrature check vouches for 24.

Usage: /usr/bin/python3 tools/ref_svg.py   (from the repository root;
       REF_JOBS=2 runs two processes, the largest files first)
"""
import os
import re
import sys
import xml.etree.ElementTree as ET

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ref_paths  # noqa: E402  (its path-data reader and quadrature)

mp.mp.dps = 32

SVG_NS = "http://www.w3.org/2000/svg"
XLINK = "{http://www.w3.org/1999/xlink}href"
INK = "{http://www.inkscape.org/namespaces/inkscape}"
PX = {"": 1, "px": 1, "in": 96, "cm": mp.mpf(96) / mp.mpf("2.54"),
      "mm": mp.mpf(96) / mp.mpf("25.4"), "pt": mp.mpf(96) / 72,
      "pc": mp.mpf(96) / 6, "q": mp.mpf(96) / mp.mpf("101.6")}
OUT = {"user": None, "px": 1, "in": 96, "cm": PX["cm"], "mm": PX["mm"],
       "pt": PX["pt"], "pc": PX["pc"]}
NOT_RENDERED = {"defs", "symbol", "clipPath", "mask", "marker", "pattern",
                "linearGradient", "radialGradient", "filter", "style",
                "script", "title", "desc", "metadata", "view", "font",
                "font-face", "cursor", "hatch", "solidcolor", "meshgradient"}
SHAPES = {"path", "rect", "circle", "ellipse", "line", "polyline", "polygon"}
MARKABLE = {"path", "line", "polyline", "polygon"}    # SVG 2 11.6: markable elements
MK = ("marker-start", "marker-mid", "marker-end")
CONTAINERS = {"g", "a", "switch", "svg"}
NUM = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")

# ---- the files and the variants measured --------------------------------
VARIANTS = {
    "hand/units.svg": [("user", "-"), ("px", "-"), ("mm", "-"), ("cm", "-"),
                       ("in", "-"), ("pt", "-"), ("pc", "-")],
    "hand/par-none.svg": [("user", "-"), ("px", "-"), ("mm", "-")],
    "hand/par-slice.svg": [("user", "-"), ("px", "-"), ("in", "-")],
    "hand/display.svg": [("user", "-"), ("user", "hidden"), ("user", "stroked")],
    "hand/switch.svg": [("user", "-"), ("user", "stroked"), ("user", "painted")],
    "hand/paint.svg": [("user", "-"), ("user", "stroked"), ("user", "painted")],
    "graphviz/pipeline.svg": [("user", "-"), ("user", "stroked"), ("user", "painted")],
    "graphviz/records.svg": [("user", "-"), ("user", "stroked"), ("user", "painted")],
    "real/vim-gvim.svg": [("user", "-"), ("px", "-"), ("user", "stroked"), ("user", "painted")],
    "real/inkscape-org.inkscape.Inkscape.svg": [("user", "-"), ("user", "stroked"),
                                                ("user", "painted")],
    "real/inkscape-org.inkscape.Inkscape-symbolic.svg": [("user", "-"), ("user", "stroked"),
                                                         ("user", "painted")],
    "real/inkscape-tutorials-making_markers.svg": [("user", "-"), ("mm", "-")],
    "hand/css.svg": [("user", "-"), ("user", "hidden"), ("user", "stroked"), ("user", "painted")],
    "hand/em.svg": [("user", "-"), ("mm", "-")],
    "real/rust-favicon.svg": [("user", "-"), ("user", "stroked"), ("user", "painted")],
    "hand/marker-css.svg": [("user", "-"), ("user", "stroked"), ("user", "painted")],
    "hand/marker-vertices.svg": [("user", "-"), ("user", "painted"), ("mm", "-")],
    "hand/marker-clip.svg": [("user", "-"), ("in", "-")],
    "real/openclipart-right_top_corner_tribal_.svg": [("user", "-"), ("user", "stroked"),
                                                      ("user", "painted")],
    "hand/missing-ref.svg": [("user", "-"), ("user", "stroked"), ("user", "painted")],
    "hand/path-error.svg": [("user", "-"), ("user", "stroked"), ("user", "painted")],
}
for _f in ("openclipart-sim_borja_bravo_01", "openclipart-ukrainian_map_stepan_kli_01",
           "openclipart-glass_buttons_lumen_desi_01", "openclipart-crop_marks_mo_01",
           "openclipart-recycle_water_saint_", "openclipart-hen_01", "elementary-text-x-go",
           "elementary-payment-card-diners-club", "breeze-draw-spiral",
           "breeze-tool_elliptical_selection"):           # styled by their sheets
    VARIANTS["real/%s.svg" % _f] = [("user", "-"), ("user", "stroked"), ("user", "painted")]


def split(tag):
    if tag.startswith("{"):
        ns, name = tag[1:].split("}", 1)
        return ns, name
    return None, tag


def mul(P, Q):
    a, b, c, d, e, f = P
    A, B, C, D, E, F = Q
    return (a * A + c * B, b * A + d * B, a * C + c * D, b * C + d * D,
            a * E + c * F + e, b * E + d * F + f)


ID = tuple(mp.mpf(x) for x in (1, 0, 0, 1, 0, 0))


def tr(x, y):
    return (mp.mpf(1), mp.mpf(0), mp.mpf(0), mp.mpf(1), x, y)


def transform(s):
    """SVG 1.1 section 7.6, exact (mpmath angles)."""
    T = ID
    for name, args in re.findall(r"(matrix|translate|scale|rotate|skewX|skewY)\s*\(([^)]*)\)", s):
        a = [mp.mpf(x) for x in NUM.findall(args)]
        if name == "matrix":
            M = tuple(a)
        elif name == "translate":
            M = tr(a[0], a[1] if len(a) > 1 else 0)
        elif name == "scale":
            M = (a[0], 0, 0, a[1] if len(a) > 1 else a[0], 0, 0)
        elif name == "rotate":
            t = mp.radians(a[0])
            R = (mp.cos(t), mp.sin(t), -mp.sin(t), mp.cos(t), 0, 0)
            M = mul(mul(tr(a[1], a[2]), R), tr(-a[1], -a[2])) if len(a) == 3 else R
        elif name == "skewX":
            M = (1, 0, mp.tan(mp.radians(a[0])), 1, 0, 0)
        else:
            M = (1, mp.tan(mp.radians(a[0])), 0, 1, 0, 0)
        T = mul(T, tuple(mp.mpf(x) for x in M))
    return T


def styles(el, important):
    out = {}
    for decl in (el.get("style") or "").split(";"):
        if ":" in decl:
            k, v = decl.split(":", 1)
            imp = re.search(r"!\s*important\s*$", v, re.I)
            if bool(imp) == important:
                k = k.strip().lower()
                for name in (MK if k == "marker" else (k,)):   # the shorthand's longhands
                    out[name] = v[:imp.start()].strip() if imp else v.strip()
    return out


SHEET = {}       # element -> (normal, important) declarations of the sheets
FONT = [16, 16]  # the font-size of the element whose lengths are read, the root's


def media_ok(text):
    """A media query list for a plain screen: media types only."""
    text = text.strip().lower()
    if not text:
        return True
    for q in text.split(","):
        words = q.split()
        if "(" in q or "and" in words:
            continue                            # a media feature: false
        neg = words[:1] == ["not"]
        words = [w for w in words if w not in ("not", "only")]
        if len(words) == 1 and (words[0] in ("all", "screen")) != neg:
            return True
    return False


def read_sheets(root):
    import cssselect2
    import tinycss2
    matcher = cssselect2.Matcher()

    def add(rules):
        for r in rules:
            if r.type == "qualified-rule":
                try:
                    sels = cssselect2.compile_selector_list(r.prelude)
                except cssselect2.SelectorError:
                    continue
                decls = [(n, tinycss2.serialize(d.value).strip(), d.important)
                         for d in tinycss2.parse_declaration_list(r.content, True, True)
                         if d.type == "declaration"
                         for n in (MK if d.lower_name == "marker" else (d.lower_name,))]
                for sel in sels:
                    matcher.add_selector(sel, decls)
            elif r.type == "at-rule" and r.lower_at_keyword == "media" and r.content is not None:
                if media_ok(tinycss2.serialize(r.prelude)):
                    add(tinycss2.parse_rule_list(r.content, True, True))

    for el in root.iter():
        if isinstance(el.tag, str) and split(el.tag) in ((SVG_NS, "style"), (None, "style")):
            if (el.get("type") or "text/css").strip() == "text/css" and media_ok(el.get("media") or ""):
                add(tinycss2.parse_stylesheet(el.text or "", True, True))
    out = {}
    for w in cssselect2.ElementWrapper.from_xml_root(root).iter_subtree():
        normal, imp = {}, {}
        for spec, order, pseudo, decls in sorted(matcher.match(w), key=lambda m: (m[0], m[1])):
            if pseudo is None:
                for name, value, important in decls:
                    (imp if important else normal)[name] = value
        out[w.etree_element] = (normal, imp)
    return out


def lowered(v):
    """v trimmed and lower-cased but inside url(...): ids keep their case."""
    parts, at = [], 0
    for m in re.finditer(r"url\([^)]*\)?", v, re.I):
        parts.append(v[at:m.start()].lower() + "url" + m.group(0)[3:])
        at = m.end()
    return ("".join(parts) + v[at:].lower()).strip()


def valid(name, v):
    """Is v a value property name takes?  CSS drops an invalid declaration
    (CSS Syntax 3 section 5), so the next origin's applies."""
    if v in ("inherit", "initial", "unset"):
        return True
    if name == "display":
        return re.fullmatch(r"[a-z\- \t\n\r]+", v) is not None
    if name == "visibility":
        return v in ("visible", "hidden", "collapse")
    if name == "font-size":
        m = re.match(r"^(%s)\s*([a-z%%]*)$" % NUMBER, v)
        return v in SIZES or v in ("larger", "smaller") or (
            m is not None and float(m.group(1)) >= 0 and
            (m.group(2) in ("%", "em", "ex", "rem") or m.group(2) in PX))
    if name in ("fill", "stroke"):
        return paint_kind(v, None) is not None
    if name == "color":
        return v == "currentcolor" or color_shows(v) is not None
    if name in ("fill-opacity", "stroke-opacity", "opacity"):
        return re.fullmatch("(%s)%%?" % NUMBER, v) is not None
    if name == "stroke-width":
        m = re.fullmatch("(%s)(%%|[a-z]*)" % NUMBER, v)
        return m is not None and float(m.group(1)) >= 0
    return True


def prop(el, name, cased=False):
    normal, imp = SHEET.get(el, ({}, {}))
    for v in (styles(el, True).get(name), imp.get(name), styles(el, False).get(name),
              normal.get(name), el.get(name)):
        if v is not None and valid(name, lowered(v)):
            return v.strip() if cased else lowered(v)
    return None


SIZES = {"xx-small": mp.mpf(3) / 5, "x-small": mp.mpf(3) / 4, "small": mp.mpf(8) / 9,
         "medium": 1, "large": mp.mpf(6) / 5, "x-large": mp.mpf(3) / 2, "xx-large": 2,
         "xxx-large": 3}


def font_size(v, parent, root):
    """CSS Fonts 4 section 2.5: the computed font-size in px."""
    if v is None or v == "inherit":
        return parent
    if v in SIZES:
        return 16 * SIZES[v]
    if v in ("larger", "smaller"):
        return parent * mp.mpf("1.2") if v == "larger" else parent / mp.mpf("1.2")
    m = re.match(r"^([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*([a-zA-Z%]*)$", v)
    x, u = mp.mpf(m.group(1)), m.group(2).lower()
    if u == "%":
        return x / 100 * parent
    return x * {"em": parent, "ex": parent / 2, "rem": root}.get(u, PX.get(u))


# ---- what shows: conditional processing and paint -----------------------
# SVG 2 section 5.8 and section 13, CSS Color 4, as doc/svg.md reads them:
# the paint of an element as a dict of flags, every colour reduced to
# "shows" (alpha > 0) or not; a value that does not parse is ignored.
LANG = ["en"]                                   # the reader's default language
SERVERS = set()                                 # the document's paint servers' ids
CSS_NAMED = {
    "aliceblue", "antiquewhite", "aqua", "aquamarine", "azure", "beige",
    "bisque", "black", "blanchedalmond", "blue", "blueviolet", "brown",
    "burlywood", "cadetblue", "chartreuse", "chocolate", "coral",
    "cornflowerblue", "cornsilk", "crimson", "cyan", "darkblue", "darkcyan",
    "darkgoldenrod", "darkgray", "darkgreen", "darkgrey", "darkkhaki",
    "darkmagenta", "darkolivegreen", "darkorange", "darkorchid", "darkred",
    "darksalmon", "darkseagreen", "darkslateblue", "darkslategray",
    "darkslategrey", "darkturquoise", "darkviolet", "deeppink", "deepskyblue",
    "dimgray", "dimgrey", "dodgerblue", "firebrick", "floralwhite",
    "forestgreen", "fuchsia", "gainsboro", "ghostwhite", "gold", "goldenrod",
    "gray", "green", "greenyellow", "grey", "honeydew", "hotpink",
    "indianred", "indigo", "ivory", "khaki", "lavender", "lavenderblush",
    "lawngreen", "lemonchiffon", "lightblue", "lightcoral", "lightcyan",
    "lightgoldenrodyellow", "lightgray", "lightgreen", "lightgrey",
    "lightpink", "lightsalmon", "lightseagreen", "lightskyblue",
    "lightslategray", "lightslategrey", "lightsteelblue", "lightyellow",
    "lime", "limegreen", "linen", "magenta", "maroon", "mediumaquamarine",
    "mediumblue", "mediumorchid", "mediumpurple", "mediumseagreen",
    "mediumslateblue", "mediumspringgreen", "mediumturquoise",
    "mediumvioletred", "midnightblue", "mintcream", "mistyrose", "moccasin",
    "navajowhite", "navy", "oldlace", "olive", "olivedrab", "orange",
    "orangered", "orchid", "palegoldenrod", "palegreen", "paleturquoise",
    "palevioletred", "papayawhip", "peachpuff", "peru", "pink", "plum",
    "powderblue", "purple", "rebeccapurple", "red", "rosybrown", "royalblue",
    "saddlebrown", "salmon", "sandybrown", "seagreen", "seashell", "sienna",
    "silver", "skyblue", "slateblue", "slategray", "slategrey", "snow",
    "springgreen", "steelblue", "tan", "teal", "thistle", "tomato",
    "turquoise", "violet", "wheat", "white", "whitesmoke", "yellow",
    "yellowgreen"}
NUMBER = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"


def cond_pass(el):
    if el.get("requiredExtensions") is not None:
        return False
    v = el.get("systemLanguage")
    if v is None:
        return True
    for t in (t.strip().lower() for t in v.split(",")):
        for u in LANG:
            if t == u or (t.startswith(u + "-") and len(t) > len(u) + 1):
                return True
    return False


def alpha_of(v):
    """An <alpha-value> or colour component: its value (percent / 100,
    none 0), or None when it is neither."""
    v = v.strip()
    if v == "none":
        return mp.mpf(0)
    m = re.fullmatch("(%s)(%%|[a-z]*)" % NUMBER, v)
    if not m:
        return None
    return mp.mpf(m.group(1)) / (100 if m.group(2) == "%" else 1)


def color_shows(v):
    """True / False (alpha > 0 or not) for a colour, None if v is none."""
    if v == "transparent":
        return False
    if v in CSS_NAMED or v in ("canvastext", "windowtext", "buttontext"):
        return True
    m = re.fullmatch(r"#([0-9a-f]+)", v)
    if m:
        h = m.group(1)
        if len(h) in (3, 6):
            return True
        if len(h) in (4, 8):
            return int(h[len(h) // 4 * 3:], 16) != 0
        return None
    m = re.fullmatch(r"(rgba?|hsla?|hwb|lab|lch|oklab|oklch)\s*\((.*)\)", v)
    if not m:
        return None
    inner = m.group(2)
    if "," in inner:
        parts = inner.split(",")
        alpha = parts[3] if len(parts) == 4 else "1"
        comps = parts[:3] if len(parts) in (3, 4) else None
    else:
        left, _, right = inner.partition("/")
        comps = left.split() if len(left.split()) == 3 else None
        alpha = right if "/" in inner else "1"
    if comps is None or any(alpha_of(c) is None for c in comps) or alpha_of(alpha) is None:
        return None
    return alpha_of(alpha) > 0


def paint_kind(v, context):
    """"shown", "none", "current", or None (not a paint)."""
    if v == "none":
        return "none"
    if v == "currentcolor":
        return "current"
    if v in ("context-fill", "context-stroke"):
        return context[v[8:]] if context else "none"
    if v.startswith("url("):
        rest = v[v.index(")") + 1:].strip() if ")" in v else None
        if rest is None or (rest and rest not in ("none", "currentcolor") and color_shows(rest) is None):
            return None
        ref = v[4:v.index(")")].strip().strip("'\"")
        if ref.startswith("#") and ref[1:] not in SERVERS:
            # names no paint server: the fallback, or none (SVG 2 section 13.2)
            return paint_kind(rest or "none", context)
        return "shown"
    c = color_shows(v)
    return None if c is None else ("shown" if c else "none")


INITIAL = {"fill": "shown", "stroke": "none", "color": True, "fill-opacity": True,
           "stroke-opacity": True, "stroke-width": True, "opacity": True}


def paint_of(el, parent, context):
    """The element's paint from its parent's (each flag True: shows)."""
    p = dict(parent)
    for k in ("color", "fill", "stroke", "fill-opacity", "stroke-opacity", "stroke-width", "opacity"):
        v = prop(el, k)
        if v is None or v in ("inherit", "unset"):
            continue
        if v == "initial":
            if k != "opacity":
                p[k] = INITIAL[k]
            continue
        if k == "color":
            c = None if v == "currentcolor" else color_shows(v)
        elif k in ("fill", "stroke"):
            c = paint_kind(v, context)
        elif k == "stroke-width":
            m = re.fullmatch("(%s)(%%|[a-z]*)" % NUMBER, v)
            c = None if not m or mp.mpf(m.group(1)) < 0 else mp.mpf(m.group(1)) != 0
        else:
            a = alpha_of(v) if v != "none" else None
            c = None if a is None else a > 0
        if c is not None and not (k == "opacity" and c):
            p[k] = c                               # opacity only ever turns off
    return p


def shows(p, which):
    k = p[which]
    ok = k == "shown" or (k == "current" and p["color"])
    return ok and p[which + "-opacity"] and p["opacity"]


def stroke_shows(p):
    return shows(p, "stroke") and p["stroke-width"]


def fill_shows(p, tag):
    return tag != "line" and shows(p, "fill")


def context_of(p):
    """What context-fill / context-stroke give inside a use of paint p."""
    return {"fill": "shown" if shows(dict(p, opacity=True), "fill") else "none",
            "stroke": "shown" if stroke_shows(dict(p, opacity=True)) else "none"}


def length(s, kind, vp):
    s = s.strip()
    m = re.match(r"^([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*([a-zA-Z%]*)$", s)
    v, u = mp.mpf(m.group(1)), m.group(2).lower()
    if u in PX:
        return v * PX[u]
    if u == "em":
        return v * FONT[0]
    if u == "ex":
        return v * FONT[0] / 2
    if u == "rem":
        return v * FONT[1]
    assert u == "%", s
    ref = vp[0] if kind == "x" else vp[1] if kind == "y" else mp.sqrt((vp[0] ** 2 + vp[1] ** 2) / 2)
    return v / 100 * ref


def attr_len(el, name, kind, vp, default):
    s = el.get(name)
    if s is None or not s.strip() or s.strip() == "auto":
        return default
    return length(s, kind, vp)


def viewbox(vb, par, ex, ey, ew, eh):
    """SVG 2 section 8.2."""
    words = (par or "").split()
    if words and words[0] == "defer":
        words = words[1:]
    align = words[0] if words else "xMidYMid"
    slice_ = len(words) > 1 and words[1] == "slice"
    sx, sy = ew / vb[2], eh / vb[3]
    if align != "none":
        sx = sy = max(sx, sy) if slice_ else min(sx, sy)
    tx, ty = ex - vb[0] * sx, ey - vb[1] * sy
    if align != "none":
        ax, ay = align[1:4], align[5:8]
        tx += {"Min": 0, "Mid": (ew - vb[2] * sx) / 2, "Max": ew - vb[2] * sx}[ax]
        ty += {"Min": 0, "Mid": (eh - vb[3] * sy) / 2, "Max": eh - vb[3] * sy}[ay]
    return (sx, mp.mpf(0), mp.mpf(0), sy, tx, ty)


def vbox(el):
    s = el.get("viewBox")
    if not s or not s.strip():
        return None
    return [mp.mpf(x) for x in NUM.findall(s)]


def d_of(tag, el, vp):
    """SVG 2 chapter 10: the path equivalent of a shape (None: not rendered)."""
    n = lambda x: mp.nstr(x, 40, min_fixed=-mp.inf, max_fixed=mp.inf)
    if tag == "path":
        d = el.get("d")
        return d if d and d.strip() else None
    if tag == "rect":
        x, y = attr_len(el, "x", "x", vp, 0), attr_len(el, "y", "y", vp, 0)
        w, h = attr_len(el, "width", "x", vp, 0), attr_len(el, "height", "y", vp, 0)
        rx, ry = attr_len(el, "rx", "x", vp, None), attr_len(el, "ry", "y", vp, None)
        if w == 0 or h == 0:
            return None
        if rx is None:
            rx = ry if ry is not None else 0
        if ry is None:
            ry = rx
        rx, ry = min(rx, w / 2), min(ry, h / 2)
        x, y, w, h = [mp.mpf(v) for v in (x, y, w, h)]
        if rx == 0 or ry == 0:
            return "M%s %s H%s V%s H%s Z" % (n(x), n(y), n(x + w), n(y + h), n(x))
        a = "A%s %s 0 0 1 " % (n(rx), n(ry))
        return " ".join(["M%s %s H%s" % (n(x + rx), n(y), n(x + w - rx)),
                         a + "%s %s" % (n(x + w), n(y + ry)), "V" + n(y + h - ry),
                         a + "%s %s" % (n(x + w - rx), n(y + h)), "H" + n(x + rx),
                         a + "%s %s" % (n(x), n(y + h - ry)), "V" + n(y + ry),
                         a + "%s %s" % (n(x + rx), n(y)), "Z"])
    if tag in ("circle", "ellipse"):
        cx, cy = mp.mpf(attr_len(el, "cx", "x", vp, 0)), mp.mpf(attr_len(el, "cy", "y", vp, 0))
        if tag == "circle":
            rx = ry = attr_len(el, "r", "o", vp, 0)
        else:
            rx, ry = attr_len(el, "rx", "x", vp, None), attr_len(el, "ry", "y", vp, None)
            rx, ry = (rx if rx is not None else ry or 0), (ry if ry is not None else rx or 0)
        if rx == 0 or ry == 0:
            return None
        a = "A%s %s 0 0 1 " % (n(rx), n(ry))
        return " ".join(["M%s %s" % (n(cx + rx), n(cy)), a + "%s %s" % (n(cx), n(cy + ry)),
                         a + "%s %s" % (n(cx - rx), n(cy)), a + "%s %s" % (n(cx), n(cy - ry)),
                         a + "%s %s" % (n(cx + rx), n(cy)), "Z"])
    if tag == "line":
        v = [n(mp.mpf(attr_len(el, k, k[0], vp, 0))) for k in ("x1", "y1", "x2", "y2")]
        return "M%s %s L%s %s" % tuple(v)
    pts = NUM.findall(el.get("points") or "")
    if len(pts) < 2:
        return None
    d = "M" + " ".join(pts[:2]) + "".join(" L%s %s" % (pts[k], pts[k + 1])
                                         for k in range(2, len(pts) - 1, 2))
    return d + (" Z" if tag == "polygon" else "")


# ---- measuring a primitive under the 2x2 part A of a matrix ---------------

def apply(A, p):
    return (A[0] * p[0] + A[2] * p[1], A[1] * p[0] + A[3] * p[1])


def sing(p, q, r, s):
    """Singular values of [[p r] [q s]]."""
    M = mp.matrix([[p, r], [q, s]])
    return sorted(mp.svd_r(M, compute_uv=False), reverse=True)


def integrate(f, cuts, levels=(4, 16)):
    """The integral of f over [cuts[0], cuts[-1]], split at the cuts and each
    piece in 4 (then 16 if needed): Gauss-Legendre and tanh-sinh must agree
    to 1e-24 relative."""
    pts = sorted(set(cuts))

    def split(k):
        out = []
        for a, b in zip(pts, pts[1:]):
            out += list(mp.linspace(a, b, k + 1))[:-1]
        return out + [pts[-1]]
    for k in levels:
        v1 = mp.quad(f, split(k), method="gauss-legendre")
        v2 = mp.quad(f, split(k), method="tanh-sinh")
        if abs(v1 - v2) <= mp.mpf(10) ** -24 * (abs(v2) + mp.mpf(10) ** -300):
            return v2
    raise AssertionError("quadratures disagree: %s %s" % (v1, v2))


def speed_minima(ctrl, imag=mp.mpf(10) ** -20):
    """Parameters in (0, 1) where |B'|^2 has a critical point (B' . B'' = 0):
    the speed's minima, near-cusps among them, where quadrature is split."""
    n = len(ctrl) - 1
    d = [[n * (ctrl[i + 1][k] - ctrl[i][k]) for k in (0, 1)] for i in range(n)]
    # B'(t) as a polynomial in t, coefficients highest first, per coordinate
    if n == 3:
        polys = [[d[0][k] - 2 * d[1][k] + d[2][k], 2 * (d[1][k] - d[0][k]), d[0][k]] for k in (0, 1)]
    else:
        polys = [[d[1][k] - d[0][k], d[0][k]] for k in (0, 1)]
    out = []
    prod = None
    for p in polys:
        dp = [c * (len(p) - 1 - i) for i, c in enumerate(p[:-1])]
        q = [mp.mpf(0)] * (len(p) + len(dp) - 1)
        for i, a in enumerate(p):
            for j, b in enumerate(dp):
                q[i + j] += a * b
        prod = q if prod is None else [x + y for x, y in zip(prod, q)]
    while prod and prod[0] == 0:
        prod = prod[1:]
    if len(prod) >= 2:
        try:
            roots = mp.polyroots(prod, maxsteps=200, extraprec=200)
        except mp.libmp.libhyper.NoConvergence:
            roots = []
        for r in roots:
            if abs(mp.im(r)) < imag and 0 < mp.re(r) < 1:
                out.append(mp.re(r))
    return out


def arc_centre(rx, ry, phi, fa, fs, x1, y1, x2, y2):
    """SVG 1.1 F.6.5, F.6.6: the centre parametrisation of an arc with
    non-zero radii, (c, s, rx, ry, cx, cy, th1, dth): cos and sin of its
    rotation, the radii scaled up if too small, the centre, the start angle
    and the signed sweep.  F.6.5.2 takes the square root of a difference
    that cancels for half ellipses (k ~ sqrt(rounding)): the conversion runs
    at twice the digits."""
    with mp.workdps(2 * mp.mp.dps):
        ph = mp.radians(phi)
        c, s = mp.cos(ph), mp.sin(ph)
        dx, dy = (x1 - x2) / 2, (y1 - y2) / 2        # F.6.5.1
        xp, yp = c * dx + s * dy, -s * dx + c * dy
        lam = xp ** 2 / rx ** 2 + yp ** 2 / ry ** 2  # F.6.6
        if lam > 1:
            rx, ry = mp.sqrt(lam) * rx, mp.sqrt(lam) * ry
        num = rx ** 2 * ry ** 2 - rx ** 2 * yp ** 2 - ry ** 2 * xp ** 2
        den = rx ** 2 * yp ** 2 + ry ** 2 * xp ** 2
        k = mp.sqrt(max(num / den, 0)) * (-1 if fa == fs else 1)
        cxp, cyp = k * rx * yp / ry, -k * ry * xp / rx
        cx = c * cxp - s * cyp + (x1 + x2) / 2
        cy = s * cxp + c * cyp + (y1 + y2) / 2
    ang = lambda ux, uy, vx, vy: mp.atan2(ux * vy - uy * vx, ux * vx + uy * vy)
    th1 = ang(1, 0, (xp - cxp) / rx, (yp - cyp) / ry)   # F.6.5.5, F.6.5.6
    dth = ang((xp - cxp) / rx, (yp - cyp) / ry, (-xp - cxp) / rx, (-yp - cyp) / ry)
    if not fs and dth > 0:
        dth -= 2 * mp.pi
    elif fs and dth < 0:
        dth += 2 * mp.pi
    return c, s, rx, ry, cx, cy, th1, dth


def measure(prim, A):
    """Length of the primitive's image; for arcs also the image's size."""
    kind = prim[0]
    if kind == "line":
        d = apply(A, (prim[2][0] - prim[1][0], prim[2][1] - prim[1][1]))
        return mp.sqrt(d[0] ** 2 + d[1] ** 2), None
    if kind in ("quad", "cubic"):
        ctrl = [apply(A, p) for p in ref_paths.cubic_of(prim)]
        cuts = [mp.mpf(0)] + speed_minima(ctrl) + [mp.mpf(1)]
        try:
            return integrate(lambda u: ref_paths.speed(ctrl, u), cuts), None
        except AssertionError:
            # a cusp: the double root of B'.B'' comes out of polyroots with an
            # imaginary part ~1e-16; cut at the near-real roots too, finer
            cuts = [mp.mpf(0)] + speed_minima(ctrl, mp.mpf(10) ** -8) + [mp.mpf(1)]
            return integrate(lambda u: ref_paths.speed(ctrl, u), cuts, (4, 16, 64)), None
    _, rx, ry, phi, fa, fs, (x1, y1), (x2, y2) = prim
    if (x1, y1) == (x2, y2):
        return mp.mpf(0), None
    with mp.workdps(2 * mp.mp.dps):
        ph = mp.radians(phi)
        c, s = mp.cos(ph), mp.sin(ph)
    rx, ry = abs(rx), abs(ry)
    ch = apply(A, (x2 - x1, y2 - y1))
    chord2 = mp.sqrt(ch[0] ** 2 + ch[1] ** 2) / 2
    if rx == 0 or ry == 0:                       # F.6.2: a straight line
        return 2 * chord2, None
    size = max(sing(rx * (A[0] * c + A[2] * s), rx * (A[1] * c + A[3] * s),
                    ry * (-A[0] * s + A[2] * c), ry * (-A[1] * s + A[3] * c))[0], chord2)
    c, s, rx, ry, _, _, th1, dth = arc_centre(rx, ry, phi, fa, fs, x1, y1, x2, y2)

    def speed(t):
        v = apply(A, (c * (-rx * mp.sin(t)) - s * (ry * mp.cos(t)),
                      s * (-rx * mp.sin(t)) + c * (ry * mp.cos(t))))
        return mp.sqrt(v[0] ** 2 + v[1] ** 2)
    a, b = (th1, th1 + dth) if dth > 0 else (th1 + dth, th1)
    return integrate(speed, [a, b]), size


# ---- markers (SVG 2 section 11.6) ----------------------------------------------
# Written from the specification, not from src/svgdoc/marker.c: the vertices
# of the path's commands, directions as derivatives of each primitive on
# [0, 1] (the first non-zero one), the placement as a product of exact
# matrices, and the clip to the marker's viewport by sampling each mapped
# primitive and refining every sign change of x - side, y - side with
# mpmath's root finder, measuring the sub-ranges inside.

def marker_ref(v, parent):
    """A marker property's value: the id, None (none), or the parent's."""
    if v is None:
        return parent
    if v.lower() in ("none", "initial"):
        return None
    m = re.fullmatch(r"url\(\s*(['\"]?)#([^'\")\s]+)\1\s*\)", v.strip(), re.I)
    return m.group(2) if m else parent


def stroke_width(v, parent, vp):
    if v is None:
        return parent
    if v == "initial":
        return mp.mpf(1)
    try:
        w = length(v, "o", vp)
    except (AttributeError, AssertionError, TypeError):
        return parent                               # invalid: ignored
    return parent if w < 0 else w


def prim_param(prim):
    """(P, dP): a primitive as a function of t in [0, 1] and its derivative;
    None for an arc that SVG omits (equal ends)."""
    kind = prim[0]
    if kind == "arc":
        _, rx, ry, phi, fa, fs, (x1, y1), (x2, y2) = prim
        if (x1, y1) == (x2, y2):
            return None
        rx, ry = abs(rx), abs(ry)
        if rx == 0 or ry == 0:
            prim = ("line", (x1, y1), (x2, y2))
            kind = "line"
        else:
            c, s, rx, ry, cx, cy, th1, dth = arc_centre(rx, ry, phi, fa, fs, x1, y1, x2, y2)

            def P(t):
                th = th1 + t * dth
                return (cx + c * rx * mp.cos(th) - s * ry * mp.sin(th),
                        cy + s * rx * mp.cos(th) + c * ry * mp.sin(th))

            def dP(t):
                th = th1 + t * dth
                return (dth * (-c * rx * mp.sin(th) - s * ry * mp.cos(th)),
                        dth * (-s * rx * mp.sin(th) + c * ry * mp.cos(th)))
            return P, dP
    if kind == "line":
        p0, p1 = prim[1], prim[2]
        return ((lambda t: (p0[0] + t * (p1[0] - p0[0]), p0[1] + t * (p1[1] - p0[1]))),
                (lambda t: (p1[0] - p0[0], p1[1] - p0[1])))
    ctrl = list(prim[1:])
    n = len(ctrl) - 1
    d = [(n * (ctrl[i + 1][0] - ctrl[i][0]), n * (ctrl[i + 1][1] - ctrl[i][1])) for i in range(n)]
    return (lambda t: ref_paths.bezier(ctrl, t)), (lambda t: ref_paths.bezier(d, t))


def direction(prim, end):
    """The angle of the path's direction at the primitive's start (end 0)
    or end (1): of its first non-zero derivative there; None when it is a
    point (SVG 2 9.5)."""
    pts = [prim[1], prim[2]] if prim[0] == "line" else list(prim[1:])
    if all(p == pts[0] for p in pts):
        return None
    if prim[0] in ("quad", "cubic"):
        # B^(k)(0) is a combination of P0 .. Pk: the first Pk - P0 not zero
        seq = pts if end == 0 else pts[::-1]
        for q in seq[1:]:
            v = (q[0] - seq[0][0], q[1] - seq[0][1])
            if v != (0, 0):
                return mp.atan2(v[1], v[0]) if end == 0 else mp.atan2(-v[1], -v[0])
    v = prim_param(prim)[1](mp.mpf(end))
    return mp.atan2(v[1], v[0])


def vertices(d):
    """[(x, y, auto angle)] of path data d: each moveto and each segment's
    end (an arc, a zero-length segment or Z included), the angle bisecting
    the directions in and out (SVG 2 11.6.2)."""
    subs = []                                       # [start, [(end, a0, a1)], closed]
    after_z = True

    def seg(prim, begin, end):
        nonlocal after_z
        if after_z:                                 # drawing after Z: a new subpath
            subs.append([begin, [], False])
            after_z = False
        subs[-1][1].append((end, direction(prim, 0), direction(prim, 1)))

    for up, before, after, prim in ref_paths.commands(d):
        if up == "Z":
            if not after_z:
                seg(("line", before, after), before, after)
                subs[-1][2] = True
                after_z = True
        elif up == "M":
            subs.append([after, [], False])
            after_z = False
        elif up != "A" or after != before:          # equal ends: omitted (F.6.2)
            seg(prim, before, after)

    def bisect(a, b):
        if a is None:
            return b if b is not None else mp.mpf(0)
        if b is None:
            return a
        t = b - a
        if t > mp.pi:
            t -= 2 * mp.pi
        if t <= -mp.pi:
            t += 2 * mp.pi
        return a + t / 2
    out = []
    for st, segs, closed in subs:
        ins = [next((s[2] for s in segs[k::-1] if s[1] is not None), None) for k in range(len(segs))]
        outs = [next((s[1] for s in segs[k:] if s[1] is not None), None) for k in range(len(segs))]
        first_out = outs[0] if segs else None
        out.append((st[0], st[1], bisect(ins[-1] if closed else None, first_out)))
        for k, s in enumerate(segs):
            o = outs[k + 1] if k + 1 < len(segs) else (first_out if closed else None)
            out.append((s[0][0], s[0][1], bisect(ins[k], o)))
    return out


def orient_deg(o):
    m = re.fullmatch(r"(%s)(deg|grad|rad|turn)?" % NUMBER, o.strip())
    if not m:
        return mp.mpf(0)
    v = mp.mpf(m.group(1))
    return v * {None: 1, "deg": 1, "grad": mp.mpf("0.9"), "rad": 180 / mp.pi, "turn": 360}[m.group(2)]


def clipped_length(prim, inner, A, box):
    """The length under A of the part of the primitive (mapped by inner)
    inside box (x0, y0, x1, y1)."""
    pp = prim_param(prim)
    if pp is None:
        return mp.mpf(0)
    P, dP = pp
    Q = lambda t: (inner[0] * P(t)[0] + inner[2] * P(t)[1] + inner[4],
                   inner[1] * P(t)[0] + inner[3] * P(t)[1] + inner[5])
    N = 128
    grid = [mp.mpf(i) / N for i in range(N + 1)]
    pts = [Q(t) for t in grid]
    cuts = {mp.mpf(0), mp.mpf(1)}
    for axis, side in ((0, box[0]), (1, box[1]), (0, box[2]), (1, box[3])):
        vals = [p[axis] - side for p in pts]
        for i in range(N):
            if vals[i] == 0:
                cuts.add(grid[i])
            elif vals[i] * vals[i + 1] < 0:
                f = lambda t: Q(t)[axis] - side
                cuts.add(mp.findroot(f, (grid[i], grid[i + 1]), solver="anderson"))
    cuts = sorted(cuts)
    total = mp.mpf(0)
    for a, b in zip(cuts, cuts[1:]):
        m = Q((a + b) / 2)
        if box[0] <= m[0] <= box[2] and box[1] <= m[1] <= box[3]:
            total += integrate(lambda t: mp.sqrt(apply(A, dP(t))[0] ** 2 + apply(A, dP(t))[1] ** 2),
                               [a, (a + b) / 2, b])
    return total


# ---- the document ------------------------------------------------------------

class Doc:
    def __init__(self, path, units, option):
        self.tree = ET.parse(path)
        self.root = self.tree.getroot()
        SHEET.clear()
        SHEET.update(read_sheets(self.root))
        self.ids = {}
        SERVERS.clear()
        self.parent = {c: p for p in self.root.iter() for c in p}
        for el in self.root.iter():
            i = el.get("id")
            if i is not None and i not in self.ids:
                self.ids[i] = el
            if i is not None and isinstance(el.tag, str) and split(el.tag) in [
                    (ns, t) for ns in (SVG_NS, None)
                    for t in ("linearGradient", "radialGradient", "pattern")]:
                SERVERS.add(i)
        self.units, self.option = units, option
        self.total, self.count, self.arcs, self.arcscale = mp.mpf(0), 0, 0, mp.mpf(0)

    def run(self):
        r = self.root
        FONT[0] = FONT[1] = font_size(prop(r, "font-size"), 16, 16)
        vb = vbox(r)
        w = r.get("width")
        h = r.get("height")
        w = length(w, "x", None) if w and "%" not in w else None
        h = length(h, "y", None) if h and "%" not in h else None
        vp = (vb[2], vb[3]) if vb else (w, h) if w is not None and h is not None else None
        ctm = ID
        if self.units != "user":
            V = viewbox(vb, r.get("preserveAspectRatio"), 0, 0,
                        w if w is not None else vb[2], h if h is not None else vb[3]) if vb else ID
            k = 1 / mp.mpf(OUT[self.units])
            ctm = mul((k, 0, 0, k, 0, 0), V)
        if r.get("transform"):
            ctm = mul(ctm, transform(r.get("transform")))
        visible = prop(r, "visibility") not in ("hidden", "collapse")
        paint = paint_of(r, INITIAL, None)
        if not cond_pass(r):
            return
        ext = {"sw": stroke_width(prop(r, "stroke-width"), mp.mpf(1), vp),
               "mk": [marker_ref(prop(r, k, True), None) for k in MK], "outer": None,
               "box": None}
        for ch in r:
            self.walk(ch, ctm, vp, visible, paint, [], None, FONT[1], ext)

    def marker_env(self, m):
        """What a marker's content inherits: the marker's properties over
        its ancestors' from the root, whatever their display (SVG 2
        11.6.2), and whether it clips (overflow hidden or scroll)."""
        chain, e = [], m
        while e is not None:
            chain.append(e)
            e = self.parent.get(e)
        paint, visible, fs, sw = INITIAL, True, FONT[1], mp.mpf(1)
        for el in reversed(chain):
            fs = font_size(prop(el, "font-size"), fs, FONT[1])
            FONT[0] = fs
            v = prop(el, "visibility")
            visible = False if v in ("hidden", "collapse") else True if v == "visible" else visible
            paint = paint_of(el, paint, None)
            sw = stroke_width(prop(el, "stroke-width"), sw, None)
        return {"paint": paint, "visible": visible, "fs": fs, "sw": sw,
                "clip": prop(m, "overflow") not in ("visible", "auto")}

    def markers(self, el, tag, vp, ctm, paint, ext, chain):
        """The marker instances of a drawn shape, drawn after it."""
        vs = vertices(d_of(tag, el, vp))
        for which, name in enumerate(MK):
            m = self.ids.get(ext["mk"][which])
            if m is None or split(m.tag) not in ((SVG_NS, "marker"), (None, "marker")):
                continue
            at = [vs[0]] if which == 0 else vs[1:-1] if which == 1 else [vs[-1]]
            if not vs:
                at = []
            env = self.marker_env(m)
            for x, y, ang in at:
                FONT[0] = env["fs"]
                mw = attr_len(m, "markerWidth", "x", vp, 3)
                mh = attr_len(m, "markerHeight", "y", vp, 3)
                vb = vbox(m)
                if mw == 0 or mh == 0 or (vb and (vb[2] <= 0 or vb[3] <= 0)):
                    continue
                V = viewbox(vb, m.get("preserveAspectRatio"), 0, 0, mw, mh) if vb else ID
                vbr = vb or (0, 0, mw, mh)
                cvp = (vbr[2], vbr[3])
                ref = []
                for axis, kw in ((0, ("left", "center", "right")), (1, ("top", "center", "bottom"))):
                    v = (m.get("refX" if axis == 0 else "refY") or "").strip()
                    ref.append(vbr[axis] + vbr[axis + 2] * kw.index(v) / 2 if v in kw
                               else length(v, "xy"[axis], cvp) if v else mp.mpf(0))
                sc = mp.mpf(1) if m.get("markerUnits") == "userSpaceOnUse" else ext["sw"]
                if sc == 0:
                    continue
                o = (m.get("orient") or "").strip()
                if o == "auto" or o == "auto-start-reverse":
                    a = ang + (mp.pi if o == "auto-start-reverse" and which == 0 else 0)
                else:
                    a = mp.radians(orient_deg(o))
                R = (mp.cos(a) * sc, mp.sin(a) * sc, -mp.sin(a) * sc, mp.cos(a) * sc, 0, 0)
                rp = (V[0] * ref[0] + V[4], V[3] * ref[1] + V[5])
                outer = mul(ctm, mul(tr(x, y), mul(R, mul(tr(-rp[0], -rp[1]), V))))
                box = ((-V[4]) / V[0], (-V[5]) / V[3], (mw - V[4]) / V[0], (mh - V[5]) / V[3]) \
                    if env["clip"] else None
                sub = {"sw": env["sw"], "mk": [None, None, None], "outer": outer, "box": box}
                use = {"root": None, "w": None, "h": None, "context": context_of(paint)}
                for ch in m:
                    self.walk(ch, ID, cvp, env["visible"], env["paint"], chain, use, env["fs"], sub)

    def walk(self, el, ctm, vp, visible, paint, chain, use, fs, ext):
        if not isinstance(el.tag, str):
            return                                  # comments, processing instructions
        ns, tag = split(el.tag)
        if ns not in (None, SVG_NS):
            return
        if prop(el, "display") == "none" and self.option != "hidden":
            return
        fs = font_size(prop(el, "font-size"), fs, FONT[1])
        FONT[0] = fs
        v = prop(el, "visibility")
        if v in ("hidden", "collapse"):
            visible = False
        elif v == "visible":
            visible = True
        if not cond_pass(el):
            return
        paint = paint_of(el, paint, use and use["context"])
        ext = dict(ext, sw=stroke_width(prop(el, "stroke-width"), ext["sw"], vp),
                   mk=[marker_ref(prop(el, k, True), ext["mk"][i]) for i, k in enumerate(MK)])
        via_use = use is not None and use["root"] is el
        if tag in NOT_RENDERED and not (tag == "symbol" and via_use):
            return
        if tag not in SHAPES and tag not in CONTAINERS and tag not in ("use", "symbol"):
            return                                  # text, image, unknown: not measured
        if el.get("transform") and tag not in ("svg", "symbol"):
            ctm = mul(ctm, transform(el.get("transform")))
        if tag in ("svg", "symbol"):
            x, y = attr_len(el, "x", "x", vp, 0), attr_len(el, "y", "y", vp, 0)
            w = use["w"] if via_use and use["w"] is not None else attr_len(el, "width", "x", vp, None)
            h = use["h"] if via_use and use["h"] is not None else attr_len(el, "height", "y", vp, None)
            w = vp[0] if w is None else w
            h = vp[1] if h is None else h
            vb = vbox(el)
            if w == 0 or h == 0 or (vb and (vb[2] == 0 or vb[3] == 0)):
                return
            if vb:
                ctm = mul(ctm, viewbox(vb, el.get("preserveAspectRatio"), x, y, w, h))
                vp = (vb[2], vb[3])
            else:
                ctm = mul(ctm, tr(x, y))
                vp = (w, h)
        if ctm[0] * ctm[3] - ctm[1] * ctm[2] == 0:
            return
        if tag in SHAPES:
            d = d_of(tag, el, vp)
            if d is None or not (visible or self.option == "hidden"):
                return
            prims = parse_prefix(d)
            if prims is None:                       # the first command holds an error
                return
            shown = not (self.option == "stroked" and not stroke_shows(paint)) and \
                not (self.option == "painted" and not (stroke_shows(paint) or fill_shows(paint, tag)))
            outer = ext["outer"]
            A = (mul(outer, ctm) if outer else ctm)[:4]
            if shown and ext["box"] is not None:
                # a marker's clip: what it leaves; a shape it removes whole
                # is not drawn (one of no length at all is, as unclipped)
                L = sum(clipped_length(prim, ctm, A, ext["box"]) for prim in prims)
                if L > 0 or all(measure(prim, A)[0] == 0 for prim in prims):
                    self.count += 1
                    self.total += L
            elif shown:
                self.count += 1
                for prim in prims:
                    L, size = measure(prim, A)
                    self.total += L
                    if size is not None:
                        self.arcs += 1
                        self.arcscale += size
            if tag in MARKABLE and ext["outer"] is None and any(ext["mk"]):
                self.markers(el, tag, vp, ctm, paint, ext, chain)
            return
        if tag == "use":
            href = el.get("href", el.get(XLINK))
            if not href or not href.startswith("#"):
                return
            target = self.ids.get(href[1:])
            if target is None:                      # SVG 2 section 5.6: not rendered
                return
            assert href[1:] not in chain, "use cycle"
            u = {"root": target, "w": attr_len(el, "width", "x", vp, None),
                 "h": attr_len(el, "height", "y", vp, None), "context": context_of(paint)}
            m = mul(ctm, tr(attr_len(el, "x", "x", vp, 0), attr_len(el, "y", "y", vp, 0)))
            self.walk(target, m, vp, visible, paint, chain + [href[1:]], u, fs, ext)
            return
        children = [c for c in el if isinstance(c.tag, str)]
        if tag == "switch":                         # SVG 2 section 5.8: the first that passes
            first = [c for c in children if split(c.tag)[0] in (None, SVG_NS) and cond_pass(c)]
            children = first[:1]
        for ch in children:
            self.walk(ch, ctm, vp, visible, paint, chain, use and dict(use, root=None), fs, ext)


def parse_prefix(d):
    """Path data as SVG 2 section 9.5.4 (SVG 1.1 F.2) renders it: up to the
    command that holds an error -- the longest prefix, cut after a token,
    that starts with a moveto and parses; None if there is none."""
    if d.strip()[:1] not in ("M", "m"):           # ref_paths would start at (0, 0)
        return None
    try:
        return ref_paths.parse(d)
    except (AssertionError, ValueError, IndexError, TypeError):
        pass
    ends = [m.end() for m in re.finditer(r"[A-Za-z]|" + NUM.pattern, d)]
    for e in reversed(ends):
        head = d[:e].strip()
        if head[:1] not in ("M", "m"):
            continue
        try:
            return ref_paths.parse(head)
        except (AssertionError, ValueError, IndexError, TypeError):
            continue
    return None


def second_opinion(path):
    """svgelements' count of drawn shapes (None if it is not installed)."""
    try:
        import svgelements as se
    except ImportError:
        return None
    n = 0
    try:
        elements = list(se.SVG.parse(path).elements())
    except Exception as e:                          # e.g. em units it cannot place
        return "failed: %s" % e
    for e in elements:
        if isinstance(e, se.Shape) and not isinstance(e, se.Group) and e.values.get("display") != "none":
            n += 1
    return n


def fmt(x):
    return mp.nstr(x, 30, min_fixed=-mp.inf, max_fixed=mp.inf) if x != 0 else "0"


def job(args):
    base, f, units, option = args
    mp.mp.dps = 32
    doc = Doc(os.path.join(base, f), units, option)
    doc.run()
    row = [f, units, option, str(doc.count), fmt(doc.total), str(doc.arcs), fmt(doc.arcscale)]
    note = None
    if units == "user" and option == "-":
        note = "%-58s %4d shapes (svgelements %s)  L = %s" % (
            f, doc.count, second_opinion(os.path.join(base, f)), mp.nstr(doc.total, 20))
        print(note, flush=True)
    return row


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    base = os.path.join(root, "spec", "data", "svg")
    files = []
    for sub in ("hand", "real", "graphviz"):
        files += sorted(sub + "/" + f for f in os.listdir(os.path.join(base, sub)) if f.endswith(".svg"))
    jobs = [(base, f, units, option) for f in files for units, option in VARIANTS.get(f, [("user", "-")])]
    # REF_JOBS processes (default 1), the largest files first
    n = int(os.environ.get("REF_JOBS", "1"))
    order = sorted(range(len(jobs)), key=lambda i: -os.path.getsize(os.path.join(base, jobs[i][1])))
    if n > 1:
        import multiprocessing
        with multiprocessing.Pool(n) as pool:
            done = dict(zip(order, pool.map(job, [jobs[i] for i in order], chunksize=1)))
    else:
        done = {i: job(jobs[i]) for i in order}
    rows = [done[i] for i in range(len(jobs))]
    out = os.path.join(root, "spec", "data", "svg_refs.tsv")
    ref_paths.write_table(out, "tools/ref_svg.py",
                          ["file", "units", "option", "elements", "L", "arcs", "arcscale"], rows)


if __name__ == "__main__":
    main()
