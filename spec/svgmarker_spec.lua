-- spec/svgmarker_spec.lua -- markers drawn as SVG 2 section 11.6 says:
-- marker-start / -mid / -end and the shorthand (sheets and style="" only),
-- the vertices and their directions (11.6.2, the path directionality of
-- 9.5), orient, markerUnits, markerWidth/Height, viewBox with
-- preserveAspectRatio, refX/refY, the clip to the marker's viewport, what
-- the content inherits, forward references, missing ids and the caps.
-- The hand-written documents of spec/data/svg/hand/marker-*.svg are also
-- measured against tools/ref_svg.py by spec/svgdoc_spec.lua; here each
-- rule is checked on its own, with values worked out by hand.
local svg = require("helpers").optional("arclen.svg")   -- #svgdoc specs need it

local DIR = "spec/data/svg/"
local pi, sqrt = math.pi, math.sqrt
local HEAD = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200">'

local function close(a, b, rel, what)
  local err = math.abs(a - b)
  assert(err <= rel * math.max(math.abs(b), 1e-300), ("%s: %.17g vs %.17g"):format(what or "value", a, b))
end

-- The elements that a marker drew (e.marker set), in order.
local function instances(doc, marker)
  local t = {}
  for _, e in ipairs(doc.elements) do
    if e.marker and (marker == nil or e.marker == marker) then t[#t + 1] = e end
  end
  return t
end

local function same_ctm(e, want, what)
  for k = 1, 6 do close(e.ctm[k], want[k], 1e-15, (what or "ctm") .. "[" .. k .. "]") end
end

-- The angle (degrees) of an instance's x axis, from its CTM.
local atan2 = math.atan2 or math.atan              -- Lua 5.1 and LuaJIT: atan2
local function angle(e) return math.deg(atan2(e.ctm[2], e.ctm[1])) end

-- The error of f(...) as raised (busted's has_error drops the place).
local function err_of(f, ...)
  local ok, e = pcall(f, ...)
  assert.is_false(ok)
  return e
end

local function parse(body, opts)
  return svg.parse(HEAD .. body .. "</svg>", opts)
end

describe("markers: orient (SVG 2 11.6.2) #svgdoc", function()
  local doc = svg.read(DIR .. "hand/marker-orient.svg")
  it("auto: the direction at the ends, the bisector between", function()
    local m = instances(doc, "auto")
    assert.are.equal(3, #m)
    same_ctm(m[1], {1, 0, 0, 1, 10, 10})
    local h = sqrt(0.5)
    same_ctm(m[2], {h, h, -h, h, 50, 10})                  -- east in, south out: 45 degrees
    close(angle(m[3]), 90, 1e-15)
    assert.are.same({50, 50}, {m[3].ctm[5], m[3].ctm[6]})
  end)
  it("auto-start-reverse turns marker-start only", function()
    local m = instances(doc, "rev")
    same_ctm(m[1], {-1, 0, 0, -1, 10, 100})
    close(angle(m[2]), 45, 1e-15)
    close(angle(m[3]), 90, 1e-15)
  end)
  it("angles in deg (a bare number), grad, turn, rad; none is 0", function()
    same_ctm(instances(doc, "deg")[1], {0, 1, -1, 0, 100, 10})      -- exact at 90
    same_ctm(instances(doc, "grad")[1], {0, 1, -1, 0, 140, 10})     -- 100grad
    same_ctm(instances(doc, "turn")[1], {-1, 0, 0, -1, 140, 50})    -- 0.5turn
    same_ctm(instances(doc, "rad")[1], {0, -1, 1, 0, 100, 100})     -- -pi/2 rad
    same_ctm(instances(doc, "none")[1], {1, 0, 0, 1, 140, 100})
  end)
  it("the instances are drawn right after their shape, start, mids, end", function()
    local tags = {}
    for _, e in ipairs(doc.elements) do tags[#tags + 1] = e.id or e.marker end
    assert.are.same({"p-auto", "auto", "auto", "auto", "p-rev", "rev", "rev", "rev",
                     "p-angles", "deg", "grad", "turn", "p-rad", "rad", "none"}, tags)
  end)
end)

describe("markers: markerUnits #svgdoc", function()
  local doc = svg.read(DIR .. "hand/marker-units.svg")
  local by = {}
  for i, e in ipairs(doc.elements) do
    if e.marker then by[doc.elements[i - 1].id] = e end
  end
  it("strokeWidth (the default) scales by the shape's computed stroke-width", function()
    close(by.inherited.length, 12, 1e-15)                 -- 4 x 3, inherited from the group
    close(by.own.length, 2, 1e-15)
    close(by.mm.length, 4 * 2 * 96 / 25.4, 1e-15)         -- stroke-width 2mm
    close(by.css.length, 16, 1e-15)                       -- style="stroke-width: 4"
    close(by.badunits.length, 12, 1e-15)                  -- an invalid markerUnits: the default
    close(by.scaled.length, 8, 1e-15)                     -- and the CTM: scale(2), width 1
  end)
  it("userSpaceOnUse does not; a zero stroke-width draws no marker", function()
    close(by.user.length, 4, 1e-15)
    assert.is_nil(by.zero)
  end)
end)

describe("markers: markerWidth/Height, viewBox, preserveAspectRatio, refX/refY #svgdoc", function()
  local doc = svg.read(DIR .. "hand/marker-viewbox.svg")
  it("the viewBox onto the viewport, refX/refY in the viewBox's coordinates", function()
    local sq = instances(doc, "square")
    same_ctm(sq[1], {0.5, 0, 0, 0.5, 57.5, 17.5})         -- (5, 5) -> (2.5, 2.5) at (60, 20)
    close(sq[1].length, 20, 1e-15)
  end)
  it("meet: centred; the clip is the viewport, larger than the viewBox", function()
    local m = instances(doc, "meet")
    same_ctm(m[1], {0.5, 0, 0, 0.5, 55, 57.5})
    close(m[1].length, 10, 1e-15)
    close(m[2].length, 8, 1e-15)                          -- y from -3 to 13: inside [-5, 15]
    close(m[3].length, 10, 1e-15)                         -- y from -8 to 18, cut to [-5, 15]
  end)
  it("slice: the viewBox cut to the viewport", function()
    close(instances(doc, "slice")[1].length, 10, 1e-15)   -- x from 0 to 20, cut to [0, 10]
  end)
  it("refX/refY keywords: center and bottom of the viewBox", function()
    local e = instances(doc, "keywords")[1]
    assert.are.same({56, 134}, {e.ctm[5], e.ctm[6]})
  end)
  it("markerWidth/Height default to 3; 0 draws nothing", function()
    close(instances(doc, "default-size")[1].length, 3, 1e-15)  -- x from -1 to 5, cut to [0, 3]
    assert.are.equal(0, #instances(doc, "zero-size"))
  end)
  it("a negative markerWidth is an error at the marker", function()
    assert.are.equal("<string>:1:63: markerWidth must not be negative (-1)", err_of(parse,
      '<marker id="m" markerWidth="-1"><path d="M0 0 H1"/></marker><path d="M0 0 H10" marker-end="url(#m)"/>'))
  end)
end)

describe("markers: overflow, the clip to the viewport #svgdoc", function()
  local doc = svg.read(DIR .. "hand/marker-clip.svg")
  it("hidden (the UA sheet's) and scroll clip; visible and auto do not", function()
    close(instances(doc, "hidden")[1].length, 5 * pi, 1e-14)     -- the half circle inside
    close(instances(doc, "scroll")[1].length, 5 * pi, 1e-14)
    close(instances(doc, "visible")[1].length, 10 * pi, 1e-14)
    close(instances(doc, "auto")[1].length, 10 * pi, 1e-14)
  end)
  it("clipped curves are cut into their parts inside", function()
    local h = instances(doc, "hidden")
    -- the cubic from (-5, 5) to (15, 5) is inside x in [0, 10] only: shorter than unclipped
    assert.is_true(h[2].length < instances(doc, "visible")[2].length)
    assert.is_true(h[2].length > 0)
    assert.are.equal(1, h[2].path.nsub)
    assert.is_true(h[3].path.nsub >= 1 and h[3].path.n >= h[3].path.nsub)
  end)
  it("a rotated content shape is clipped in the marker's coordinates", function()
    local e = instances(doc, "rotated")[1]
    assert.is_true(e.length > 0 and e.length < 10 * pi)
  end)
end)

describe("markers: the properties, sheets and the shorthand #svgdoc", function()
  local doc = svg.read(DIR .. "hand/marker-css.svg")
  local count = {}
  local last
  for _, e in ipairs(doc.elements) do
    if e.marker then count[last] = (count[last] or 0) + 1 else last = e.id end
  end
  it("the shorthand in a sheet sets all three; an id rule beats a class rule", function()
    assert.are.equal(3, count.cls)
    assert.are.equal(2, count.onlyend)     -- marker-start: none by #onlyend
    assert.are.equal(2, count.override)    -- marker-mid: none after the shorthand
  end)
  it("in style=\"\" the later declaration wins, shorthand or longhand", function()
    assert.are.equal(2, count.styled)
    assert.is_nil(count.later)
  end)
  it("marker is no presentation attribute (SVG 2 11.6.3)", function()
    assert.is_nil(count.attr)
  end)
  it("inherited, and drawn whatever the marker's display", function()
    assert.are.equal(1, count.inherit)
  end)
  it("the content inherits from the marker's ancestors, not from the shape", function()
    local s = svg.read(DIR .. "hand/marker-css.svg", {stroked = true})
    local ids = {}
    for _, e in ipairs(s.elements) do ids[e.id] = (ids[e.id] or 0) + 1 end
    -- a-content: stroke blue from g.blue marker; red-content: stroke red from a group
    -- around the marker inside <defs>, display:none (no matter); plain-content has none
    -- although the group around the shape that uses it has stroke black (which draws
    -- that shape, "inherit")
    assert.are.same({["a-content"] = 9, ["red-content"] = 1, inherit = 1}, ids)
    local r = instances(svg.read(DIR .. "hand/marker-css.svg"), "red")[1]
    close(r.length, 6, 1e-15)
  end)
  it("ids keep their case", function()
    local d = parse('<defs><marker id="Arrow" overflow="visible"><path d="M0 0 H2"/></marker>'
      .. '<marker id="arrow" overflow="visible"><path d="M0 0 H5"/></marker></defs>'
      .. '<path d="M0 0 H10" marker-end="URL(#Arrow)"/>')
    assert.are.equal("Arrow", instances(d)[1].marker)
    close(instances(d)[1].length, 2, 1e-15)
  end)
  it("context-stroke in a marker's content is the shape's stroke", function()
    local body = '<defs><marker id="m" overflow="visible"><path d="M0 0 H2" fill="none" stroke="context-stroke"/></marker></defs>'
      .. '<path id="s" d="M0 0 H10" stroke="red" marker-end="url(#m)"/><path id="n" d="M0 5 H10" marker-end="url(#m)"/>'
    local d = parse(body, {stroked = true})
    assert.are.equal(2, #d.elements)                      -- s and its marker; not n's marker
    assert.are.equal("m", d.elements[2].marker)
  end)
  it("em in the content is the marker's font-size", function()
    local d = parse('<g font-size="10"><marker id="m" overflow="visible" markerUnits="userSpaceOnUse">'
      .. '<path d="M0 0 H1" transform="scale(1)"/><rect width="1em" height="1em"/></marker></g>'
      .. '<path d="M0 0 H10" font-size="40" marker-end="url(#m)"/>')
    close(instances(d)[2].length, 40, 1e-15)
  end)
end)

describe("markers: vertices and directions (SVG 2 11.6.2, 9.5) #svgdoc", function()
  local doc = svg.read(DIR .. "hand/marker-vertices.svg")
  local of, last = {}, nil
  for _, e in ipairs(doc.elements) do
    if e.marker then table.insert(of[last], e) else last = e.id; of[last] = {} end
  end
  local function angles(id)
    local t = {}
    for k, e in ipairs(of[id]) do t[k] = angle(e) end
    return t
  end
  local function near(a, b)
    assert.are.equal(#b, #a)
    for k = 1, #b do close(a[k], b[k], 1e-13, "angle " .. k) end
  end
  it("every segment kind; an arc is one segment whatever its conics", function()
    -- the arcs' tangents from their centre parametrisation (SVG 1.1 F.6.5), worked out
    -- by tools/ref_svg.py's vertices() at 32 digits: 138.238955991795960 and
    -- -135.499661226462060 degrees at (70, 30) and (90, 40)
    near(angles("curves"), {0, 90, -90, 138.23895599179596, -135.49966122646206})
  end)
  it("zero-length segments take the direction of the nearest segment with a length", function()
    near(angles("degenerate"), {0, 0, 22.5, 22.5, 90, 90})
  end)
  it("a closed subpath: the start and the end bisect the closing segment and the first", function()
    -- M10 100 H30 V120 Z: the Z runs to the south-west (-135), then east (0)
    near(angles("closed"), {-67.5, 45, 157.5, -67.5,
                            -67.5, 45, 157.5, -135, -67.5,      -- "L40 100 Z": Z of length 0
                            0, 0})                                -- "l10 0" after Z: a new subpath
  end)
  it("polyline, polygon, line; none on rect and circle", function()
    near(angles("polyline"), {45, 90})
    near(angles("polygon"), {-67.5, 45, 157.5, -67.5})
    near(angles("line"), {45, 45})
    assert.are.equal(0, #of.rect)
    assert.are.equal(0, #of.circle)
  end)
  it("a marker read after the shape (forward reference) is drawn in its place", function()
    assert.are.equal(5, #of.curves)
    assert.are.equal("m", of.curves[1].marker)
  end)
  it("a missing id, or one of no marker, is a warning; strict makes it an error", function()
    assert.are.same({DIR .. "hand/marker-vertices.svg:15:3: marker-end of '#nowhere': no <marker> has that id; nothing drawn",
                     DIR .. "hand/marker-vertices.svg:16:3: marker-end of '#curves': no <marker> has that id; nothing drawn"},
                    doc.warnings)
    assert.are.equal(DIR .. "hand/marker-vertices.svg:15:3: marker-end of '#nowhere': no <marker> has that id",
      err_of(svg.read, DIR .. "hand/marker-vertices.svg", {strict = true}))
  end)
  it("markers are not drawn inside markers", function()
    assert.are.equal(1, #of.nested)
    assert.are.equal("outer-content", of.nested[1].id)
  end)
  it("the stream gives the same elements in the same order", function()
    local t = {}
    svg.each(DIR .. "hand/marker-vertices.svg", function(e) t[#t + 1] = e.marker or e.id end)
    local r = {}
    for _, e in ipairs(doc.elements) do r[#r + 1] = e.marker or e.id end
    assert.are.same(r, t)
    -- from a function (no scan: every id kept), in chunks of 100 bytes
    local h = assert(io.open(DIR .. "hand/marker-vertices.svg", "rb"))
    local text = h:read("*a")
    h:close()
    local pos, u = 1, {}
    svg.each(function()
      if pos > #text then return nil end
      pos = pos + 100
      return text:sub(pos - 100, pos - 1)
    end, function(e) u[#u + 1] = e.marker or e.id end)
    assert.are.same(r, u)
  end)
  it("arcs as cubics measure the same within the tolerance", function()
    local c = svg.read(DIR .. "hand/marker-vertices.svg", {arcs = "cubics", arc_tol = 1e-12})
    close(c.total, doc.total, 1e-10)
    assert.are.equal(#doc.elements, #c.elements)
  end)
end)

describe("markers: where they are drawn, and the caps #svgdoc", function()
  local M = '<defs><marker id="m" overflow="visible"><path d="M0 0 H1"/></marker></defs>'
  it("on the shapes a <use> draws, with the use's properties", function()
    local d = parse(M .. '<defs><g id="g"><path d="M0 0 H10"/></g></defs><use href="#g" marker-end="url(#m)" stroke-width="3"/>')
    assert.are.equal(2, #d.elements)
    assert.are.equal("g", d.elements[1].use)
    close(d.elements[2].length, 3, 1e-15)
  end)
  it("not on a shape that is not rendered: display none, visibility hidden (unless hidden)", function()
    assert.are.equal(0, #parse(M .. '<path d="M0 0 H10" display="none" marker-end="url(#m)"/>').elements)
    assert.are.equal(0, #parse(M .. '<path d="M0 0 H10" visibility="hidden" marker-end="url(#m)"/>').elements)
    assert.are.equal(2, #parse(M .. '<path d="M0 0 H10" visibility="hidden" marker-end="url(#m)"/>',
                               {hidden = true}).elements)
  end)
  it("a path with an error in its data: markers up to the command that holds it", function()
    local d = parse(M .. '<path d="M0 0 H10 V10 L 5" marker-mid="url(#m)" marker-end="url(#m)"/>')
    assert.are.equal(3, #d.elements)                      -- the path, a mid at (10, 0), the end
    assert.are.same({10, 10}, {d.elements[3].ctm[5], d.elements[3].ctm[6]})
  end)
  it("instances count against max_elements", function()
    local body = M .. '<polyline points="0 0 1 0 2 0 3 0" marker-mid="url(#m)"/>'
    assert.are.equal(3, #parse(body, {max_elements = 3}).elements)
    assert.has_error(function() parse(body, {max_elements = 2}) end)
  end)
  it("many vertices: linear, not bound by the cap of uses", function()
    local pts = {}
    for k = 0, 70000 do pts[#pts + 1] = k .. " 0" end
    local body = M .. '<polyline points="' .. table.concat(pts, " ") .. '" marker-mid="url(#m)"/>'
    assert.are.equal(70000, #parse(body, {measure = false}).elements)   -- the polyline, 69999 mids
  end)
  it("many vertices times a big marker: an error at the shape, never a blow-up", function()
    local pts = {}
    for k = 0, 1100 do pts[#pts + 1] = k .. " 0" end
    local big = '<defs><marker id="b"><g display="none">' .. ('<g/>'):rep(2000) .. '</g></marker></defs>'
    local body = big .. '<polyline points="' .. table.concat(pts, " ") .. '" marker-mid="url(#b)"/>'
    local t0 = os.clock()
    local e = err_of(parse, body)
    assert.are.equal("<string>:1:" .. (63 + #big) .. ": markers replay more than 4000000 elements "
      .. "(their content's start and end events, per vertex)", e)
    assert.is_true(os.clock() - t0 < 10 * (tonumber(os.getenv("ARCLEN_TIME_SCALE")) or 1))
  end)
end)

describe("markers: references that are no marker #svgdoc", function()
  it("an id of another element (kept for a <use>) is a warning, also inside that element", function()
    local d = svg.parse(HEAD .. '<g id="g"><path id="p" d="M0 0 H10" marker-end="url(#g)"/></g>'
      .. '<use href="#g"/></svg>', nil, "x.svg")
    assert.are.equal(2, #d.elements)
    assert.are.same({"x.svg:1:73: marker-end of '#g': the element with that id is not a <marker>; nothing drawn",
                     "x.svg:1:73: marker-end of '#g': the element with that id is not a <marker>; nothing drawn"},
                    d.warnings)
  end)
end)
