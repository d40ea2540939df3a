-- spec/svgdoc_spec.lua -- arclen.svg, the SVG document reader: whole
-- documents (real files from Debian packages and hand-written ones under
-- spec/data/svg/) against tools/ref_svg.py's mpmath references, then each
-- shape, transform, unit, viewport, <use> and display case on its own.
--
-- The tolerance of a total is what the method guarantees: every cubic's
-- length within tol of its own (relative), every arc's cubics within a
-- Hausdorff distance of arc_tol times the size of the arc's image, so its
-- length within 2 pi times that (README, "Paths"): |L - ref| <= tol * ref +
-- 2 pi arc_tol arcscale, arcscale from the reference file.
local arclen = require("arclen")
local svg = require("helpers").optional("arclen.svg")   -- #svgdoc specs need it
local helpers = require("helpers")

local DIR = "spec/data/svg/"
local pi = math.pi

local function by_id(doc)
  local t = {}
  for _, e in ipairs(doc.elements) do
    if e.id and not t[e.id] then t[e.id] = e end
  end
  return t
end

local function ids(doc)
  local t = {}
  for i, e in ipairs(doc.elements) do t[i] = e.id or e.tag end
  return t
end

local function close(a, b, rel, what)
  local err = math.abs(a - b)
  assert(err <= rel * math.abs(b), ("%s: %.17g vs %.17g (error %.3g > %.3g)"):format(
    what or "value", a, b, err / math.abs(b), rel))
end

describe("arclen.svg: documents against the mpmath reference #svgdoc", function()
  local rows = helpers.tsv("svg_refs.tsv")
  it("has the real and the hand-written files", function()
    local real, seen = 0, {}
    for _, r in ipairs(rows) do
      if r.file:match("^real/") or r.file:match("^graphviz/") then
        if not seen[r.file] then real = real + 1 end
      end
      seen[r.file] = true
    end
    assert.is_true(real >= 20, "real files: " .. real)
    -- every file in SOURCES.tsv is measured
    for _, s in ipairs(helpers.tsv("svg/SOURCES.tsv")) do
      assert.is_true(seen[s.file], s.file .. " has no reference")
    end
  end)
  for _, tol in ipairs({1e-12, 1e-8}) do
    for _, r in ipairs(rows) do
      local o = {tol = tol, units = r.units}
      if r.option ~= "-" then o[r.option] = true end
      it(("%s (units %s, %s) at tol %g"):format(r.file, r.units, r.option, tol), function()
        local doc = svg.read(DIR .. r.file, o)
        local ref, scale = tonumber(r.L), tonumber(r.arcscale)
        assert.are.equal(tonumber(r.elements), #doc.elements)
        local bound = tol * ref + 2 * pi * tol * scale
        local err = math.abs(doc.total - ref)
        assert(err <= bound, ("total %.17g, reference %s: error %.3g > bound %.3g"):format(
          doc.total, r.L, err, bound))
      end)
    end
  end
end)

describe("arclen.svg: shapes (SVG 2 chapter 10) #svgdoc", function()
  local doc = svg.read(DIR .. "hand/shapes.svg")
  local e = by_id(doc)
  local tol = 1e-12
  it("draws every shape and none of the empty ones", function()
    assert.are.same({"path-all", "rect-plain", "rect-rx", "rect-ry", "rect-rxry", "rect-clamped",
      "rect-auto", "rect-zero-rx", "circle", "ellipse", "ellipse-auto", "line", "line-default",
      "polyline", "polygon", "polygon-one"}, ids(doc))
  end)
  it("rect: plain, rx only, ry only (auto: the other), clamped to half a side, rx = 0", function()
    local q = 2 * pi                      -- four quarter arcs make a whole ellipse
    close(e["rect-plain"].length, 100, tol)
    close(e["rect-rx"].length, 100 - 8 * 4 + q * 4, 2 * pi * tol)
    close(e["rect-ry"].length, 100 - 8 * 3 + q * 3, 2 * pi * tol)
    close(e["rect-auto"].length, 100 - 8 * 5 + q * 5, 2 * pi * tol)
    close(e["rect-zero-rx"].length, 100, tol)   -- one radius zero: square corners
    assert.are.equal(4, e["rect-plain"].path:segments())
  end)
  it("rect: rx = 100 on a width of 30 is 15; the corners are quarter ellipses", function()
    -- the perimeter of the 15 x 4 ellipse, exact (Carlson), plus the straight sides
    local E = arclen.conic_length and nil
    local straight = 2 * (20 - 8)
    local d = svg.parse([[<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
      <ellipse rx="15" ry="4"/></svg>]])
    E = d.total
    close(e["rect-clamped"].length, straight + E, 4 * pi * tol)
    close(e["rect-rxry"].length, 2 * (30 - 12) + 2 * (20 - 4) + svg.parse(
      [[<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9"><ellipse rx="6" ry="2"/></svg>]]).total,
      4 * pi * tol)
  end)
  it("circle, ellipse (one radius auto), line, polyline, polygon", function()
    close(e.circle.length, 2 * pi * 15, 2 * pi * tol)
    close(e["ellipse-auto"].length, 2 * pi * 6, 2 * pi * tol)
    close(e.line.length, 50, tol)
    close(e.polyline.length, 3 * math.sqrt(100 + 1600), tol)
    close(e.polygon.length, 30 + 2 * math.sqrt(225 + 900), tol)
    assert.are.equal(0, e["line-default"].length)
    assert.are.equal(0, e["polygon-one"].length)
    -- a circle starts at (cx + r, cy) and turns in the positive angle direction
    local x, y = e.circle.path:point(0)
    assert.are.same({45, 120}, {x, y})
    local _, y2 = e.circle.path:point(e.circle.length / 4)
    assert.is_true(math.abs(y2 - 135) < 1e-9)
  end)
  it("every path method works on a drawn element", function()
    local p = e["path-all"].path
    assert.is_true(arclen.path.is_path(p))
    local L = p:length()
    assert.are.equal(e["path-all"].length, L)
    assert.is_true(#p:dash({5, 5}) > 10)
    assert.are.equal(11, #p:resample(11))
    local a, b = p:split(L / 2)
    close(a:length() + b:length(), L, 1e-12)
    assert.are.equal(2, p.nsub)
  end)
end)

describe("arclen.svg: transforms (SVG 1.1 section 7.6) #svgdoc", function()
  local doc = svg.read(DIR .. "hand/transforms.svg")
  local e = by_id(doc)
  local path = arclen.path
  local tol = 1e-12
  it("control points mapped exactly: matrix", function()
    local c = e.matrix.path:segment(1)
    -- matrix(1 0.5 -0.25 2 3 4) of (10, 10): (10 - 2.5 + 3, 5 + 20 + 4)
    assert.are.same({3, 4}, {c[1], c[2]})
    assert.are.same({10.5, 29}, {c[5], c[6]})
  end)
  it("translate (one and two arguments), rotate (with centre), rotate(90) exact", function()
    assert.are.equal(10, e.translate1.length)
    local c = e.translate1.path:segment(1)
    assert.are.same({5, 0, 15, 0}, c)            -- a line, its two points
    close(e.translate2.length, math.sqrt(200), tol)
    close(e["rotate-centre"].length, 20, tol)
    local x, y = e["rotate-centre"].path:point(0)
    -- rotate(-45 5 5) keeps (5, 5); (0, 0) goes to (5 - 5 sqrt 2, 5)
    assert.is_true(math.abs(x - (5 - 5 * math.sqrt(2))) < 1e-14 and math.abs(y - 5) < 1e-14)
    local r = e.rotate90.path:segment(1)
    assert.are.same({0, 0, 0, 3, -3, 3, -3, 6}, r)
    close(e.rotate90.length, path.svg("M0 0 C3 0 3 3 6 3"):length(), tol)
  end)
  it("scale (one and two arguments): lengths scale; arcs keep their tolerance after it", function()
    close(e.scale1.length, 3 * path.svg("M0 0 Q5 5 10 0"):length(), 2 * tol)
    -- half a circle of radius 5 under scale(2 0.5): half the 10 x 2.5 ellipse
    local half = svg.parse([[<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9">
      <ellipse rx="10" ry="2.5"/></svg>]]).total / 2
    close(e.scale2.length, half, 4 * pi * tol)
  end)
  it("the squashed circle is measured to the tolerance of its image", function()
    -- matrix(1 0 0 0.001 0 0) of a circle r = 10: the 10 x 0.01 ellipse
    local want = svg.parse([[<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9">
      <ellipse rx="10" ry="0.01"/></svg>]]).total
    close(e["ellipse-squashed"].length, want, 2 * 2 * pi * tol)
  end)
  it("nested groups compose (scale(4.1667) outside translate rotate)", function()
    local inner = svg.parse([[<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9">
      <path d="M0 0 C1 2 3 2 4 0 A2 1 0 0 1 8 0"/></svg>]]).total
    close(e.nested.length, 4.1667 * inner, 2 * pi * tol)
  end)
  it("lists with commas and whitespace read as the grammar says", function()
    local a = svg.parse([[<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9">
      <path transform="translate(10 20) rotate(15) scale(1.5 .5) skewX(10)" d="M0 0 A3 3 0 1 1 0 6"/></svg>]])
    assert.are.same(e.list.path:segment(1), a.elements[1].path:segment(1))
  end)
end)

describe("arclen.svg: viewports and units #svgdoc", function()
  local function total(f, u) return svg.read(DIR .. f, {units = u}).total end
  it("lengths with units inside the document are user units (96 px per inch)", function()
    local e = by_id(svg.read(DIR .. "hand/units.svg"))
    for _, k in ipairs({"mm", "cm", "in", "pt", "pc", "pxu"}) do
      close(e[k].length, 96, 1e-15, k)
    end
    assert.are.equal(32, e.em.length)            -- 1em = 16px (CSS medium)
    assert.are.equal(200, e["percent-x"].length) -- 50% of the viewBox width
    assert.are.equal(50, e["percent-y"].length)
  end)
  it("--units: the viewBox onto width x height (meet), then px, mm, cm, in, pt, pc", function()
    -- viewBox 400 x 200 into 210mm x 99mm, meet: 99mm / 200 per user unit
    local user = total("hand/units.svg", "user")
    local k = 99 / 200                           -- mm per user unit
    close(total("hand/units.svg", "mm"), user * k, 1e-13)
    close(total("hand/units.svg", "cm"), user * k / 10, 1e-13)
    close(total("hand/units.svg", "in"), user * k / 25.4, 1e-13)
    close(total("hand/units.svg", "px"), user * k / 25.4 * 96, 1e-13)
    close(total("hand/units.svg", "pt"), user * k / 25.4 * 72, 1e-13)
    close(total("hand/units.svg", "pc"), user * k / 25.4 * 6, 1e-13)
  end)
  it("preserveAspectRatio none stretches; slice and the alignments move", function()
    local d = svg.read(DIR .. "hand/par-none.svg", {units = "in"})
    local e = by_id(d)
    close(e.diag.length, math.sqrt(16 + 1), 1e-15)
    local s = svg.read(DIR .. "hand/par-slice.svg", {units = "pt"})
    -- 50 x 50 into 144 x 72 pt, slice: 144/50 pt per unit, aligned xMax YMin
    local p = by_id(s).p.path
    local x, y = p:point(0)
    assert.is_true(math.abs(x - 0) < 1e-12 and math.abs(y - 0) < 1e-12)
    close(s.total, svg.read(DIR .. "hand/par-slice.svg").total * 144 / 50, 1e-13)
  end)
  it("nested <svg>: x, y, width, height and its viewBox", function()
    local e = by_id(svg.read(DIR .. "hand/display.svg"))
    close(e["inner-line"].length, 10 * math.sqrt(5), 1e-15)
    local x, y = e["inner-line"].path:point(0)
    assert.are.same({10, 10}, {x, y})
  end)
end)

describe("arclen.svg: <use>, defs and the non-rendered containers #svgdoc", function()
  local doc = svg.read(DIR .. "hand/use.svg")
  it("draws uses in document order, forward references too; nothing of defs, clipPath, mask, marker, pattern", function()
    -- (the marker's content only as the marker of the path that refers to it: its last element)
    assert.are.same({"tick", "tick", "tick", "rect", "rect", "circle", "later-c", "ellipse",
      "tick", "later-c", "ellipse", "marked", "path"}, ids(doc))
    assert.are.equal("arrow", doc.elements[13].marker)
    local uses = {}
    for i, e in ipairs(doc.elements) do uses[i] = e.use or "-" end
    -- the target of the innermost use (u-pair draws pair's uses of tick)
    assert.are.same({"tick", "tick", "tick", "box", "box", "star", "later", "later", "tick",
      "-", "-", "-", "-"}, uses)
  end)
  it("x/y, transform, symbol viewBox onto the use's width/height (100% when absent)", function()
    local E = doc.elements
    local c = E[1].path:segment(1)
    assert.are.same({10, 10}, {c[1], c[2]})                -- x = 10, y = 10
    assert.are.same({40, 0}, {E[2].path:segment(1)[1], E[2].path:segment(1)[2]})   -- scale(2) x = 20
    assert.are.same({50, 0}, {E[3].path:segment(1)[1], E[3].path:segment(1)[2]})   -- + the inner x = 5
    assert.are.equal(120, E[4].length)                     -- 10 x 10 box into 30 x 30
    assert.are.equal(800, E[5].length)                     -- into 100% = 200 x 200
    close(E[6].length, 2 * pi * 10, 2 * pi * 1e-12)        -- slice: 2 per unit
    assert.are.equal(1, #doc.warnings)
    assert.matches("use.svg:22:3: <use> without href", doc.warnings[1])
  end)
  it("a document without <use> keeps nothing for later; one with <use> keeps subtrees with ids", function()
    assert.is_true(doc.kept > 0)
    assert.are.equal(0, svg.read(DIR .. "hand/shapes.svg").kept)
    local big = {'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9">'}
    for i = 1, 2000 do big[#big + 1] = ('<path id="p%d" d="M0 0 L1 0"/>'):format(i) end
    big[#big + 1] = "</svg>"
    local d = svg.parse(table.concat(big))
    assert.are.equal(0, d.kept)
    assert.are.equal(2000, d.total)
  end)
end)

describe("arclen.svg: display, visibility, stroke, layers #svgdoc", function()
  local path = DIR .. "hand/display.svg"
  it("display:none (attribute, style, ancestors) and visibility:hidden are not drawn", function()
    assert.are.same({"shown", "visible-child", "unstroked", "unstroked-style", "restroked", "sub",
      "in-group", "switch-first", "inner-line"}, ids(svg.read(path)))
  end)
  it("hidden = true draws them too; stroked = true keeps the stroked shapes", function()
    local all = ids(svg.read(path, {hidden = true}))
    assert.are.same({"shown", "none-attr", "none-style", "inside-none", "hidden", "hidden-child",
      "visible-child", "unstroked", "unstroked-style", "restroked", "sub", "in-group",
      "switch-first", "inner-line"}, all)
    assert.are.same({"shown", "visible-child", "restroked", "sub", "in-group", "switch-first",
      "inner-line"}, ids(svg.read(path, {stroked = true})))
  end)
  it("layers: Inkscape's (innermost), else the top-level group, else (root)", function()
    local layer = {}
    for _, e in ipairs(svg.read(path).elements) do layer[e.id] = e.layer end
    assert.are.same({shown = "Cut", ["visible-child"] = "Cut", unstroked = "Engrave",
      ["unstroked-style"] = "Engrave", restroked = "Engrave", sub = "Sub",
      ["in-group"] = "plain-group", ["switch-first"] = "(root)", ["inner-line"] = "(root)"}, layer)
  end)
  it("text is counted as skipped, not measured; foreign elements are ignored", function()
    local d = svg.read(path)
    assert.are.equal(1, d.skipped.text)
  end)
  it("stat: per layer length, pen-up travel, paths, segments, bounding box", function()
    local st = svg.stat(svg.read(path))
    local cut = st.layers[1]
    assert.are.equal("Cut", cut.name)
    assert.are.equal(17, cut.length)
    -- shown ends at (10, 0); visible-child starts at (0, 0)
    assert.are.equal(10, cut.travel)
    assert.are.same({0, 0, 10, 0}, cut.bbox)
    assert.are.equal(2, cut.paths)
    local sub = st.layers[3]
    assert.are.equal("Sub", sub.name)
    assert.are.same({-2, -2, 2, 2}, sub.bbox)                -- the circle's extremes, exact
    assert.are.equal(#st.layers, 5)
    -- the segments the drawing has: a circle is four conics, not cubics
    local c = svg.stat(svg.parse([[<svg xmlns="http://www.w3.org/2000/svg"><circle r="10"/>
      <rect width="10" height="8" rx="2"/><polyline points="0 0 1 1 2 0"/></svg>]]))
    assert.are.equal(4 + 8 + 2, c.total.segments)
    local n = 0
    for _, L in ipairs(st.layers) do n = n + L.elements end
    assert.are.equal(9, n)
    assert.are.equal(st.total.elements, 9)
  end)
end)

describe("arclen.path.svg(d, {transform = ...})", function()
  local path = arclen.path
  it("maps every control point by matrix(a b c d e f); default: no map", function()
    local p = path.svg("M1 2 C3 4 5 6 7 8", {transform = {2, 0.5, -1, 3, 10, 20}})
    assert.are.same({2 - 2 + 10, 0.5 + 6 + 20, 6 - 4 + 10, 1.5 + 12 + 20,
                     10 - 6 + 10, 2.5 + 18 + 20, 14 - 8 + 10, 3.5 + 24 + 20}, p:segment(1))
    assert.are.same({1, 2, 3, 4, 5, 6, 7, 8}, path.svg("M1 2 C3 4 5 6 7 8"):segment(1))
  end)
  it("an arc keeps its tolerance relative to the size of its image #svgdoc", function()
    local d = "M10 0 A10 10 0 1 1 -10 0"
    local n0 = path.svg(d, {arcs = "cubics"}):segments()
    local n1 = path.svg(d, {arcs = "cubics", transform = {1, 0, 0, 1e-3, 0, 0}}):segments()
    assert.is_true(n1 >= n0)
    assert.are.equal(2, path.svg(d, {transform = {1, 0, 0, 1e-3, 0, 0}}):segments())  -- conics
    -- the image is half the 10 x 0.01 ellipse
    local half = svg.parse([[<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9">
      <ellipse rx="10" ry="0.01"/></svg>]]).total / 2
    close(path.svg(d, {transform = {1, 0, 0, 1e-3, 0, 0}}):length(), half, 2 * 2 * pi * 1e-12)
  end)
  it("a bad transform is a bad argument", function()
    local ok, e = pcall(path.svg, "M0 0 L1 1", {transform = {1, 2}})
    assert.is_false(ok)
    assert.matches("bad argument #2 to 'arclen.path.svg' %(transform must be", e)
    ok, e = pcall(path.svg, "M0 0 L1 1", {transform = {1, 0, 0, 1, 0, 0 / 0}})
    assert.matches("transform entries must be finite numbers", e)
  end)
end)
