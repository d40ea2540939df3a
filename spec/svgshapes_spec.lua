-- spec/svgshapes_spec.lua -- the basic shapes built into segments from
-- their numbers (src/svgdoc/shapes.c, the builder of src/svg/pathdata.c),
-- with no path data text between: the same records, kinds, subpaths,
-- transforms and errors, bit for bit, as parsing the path data the reader
-- writes for them (svgdoc.new's shape_text option takes that route), for
-- every shape kind, degenerate ones included, both arcs modes, under
-- transforms; and the d that stays available, written only when read.
local svgdoc = require("helpers").optional("arclen.svgdoc")
local svg = require("helpers").optional("arclen.svg")

local H = '<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100">'

-- The shapes: every kind, the auto and clamping rules of rx and ry, zero
-- and signed-zero numbers, tiny, huge and inexact ones, shapes not drawn.
local SHAPES = {
  '<rect x="1" y="2" width="3" height="4"/>',
  '<rect x="-0" y="-0" width="0.1" height="0.7"/>',
  '<rect width="10" height="6" rx="1"/>',
  '<rect width="10" height="6" ry="2"/>',
  '<rect width="10" height="6" rx="1.5" ry="0.25"/>',
  '<rect width="10" height="6" rx="7" ry="9"/>',           -- clamped to half
  '<rect width="10" height="6" rx="auto" ry="2"/>',
  '<rect width="10" height="6" rx="3" ry="auto"/>',
  '<rect width="10" height="6" rx="0" ry="2"/>',          -- square corners
  '<rect width="10" height="6" rx="2" ry="0"/>',
  '<rect width="0" height="6" rx="2"/>',                  -- not drawn
  '<rect x="0.1" y="0.2" width="0.30000000000000004" height="1e-300" rx="1e-301"/>',
  '<rect x="1e300" y="-1e300" width="3e300" height="1e299" rx="1e298"/>',
  '<rect x="10%" y="5%" width="50%" height="25%" rx="1%"/>',
  '<circle cx="1" cy="2" r="3"/>',
  '<circle cx="-0" cy="-0" r="0.1"/>',
  '<circle r="0"/>',                                      -- not drawn
  '<circle cx="0.3" cy="1e-310" r="4.9406564584124654e-324"/>',
  '<circle cx="1e307" cy="-1e307" r="1e306"/>',
  '<circle cx="50%" cy="50%" r="10%"/>',
  '<ellipse cx="5" cy="6" rx="4" ry="1"/>',
  '<ellipse cx="5" cy="6" rx="4"/>',                      -- ry auto
  '<ellipse cx="5" cy="6" ry="2" rx="auto"/>',
  '<ellipse cx="5" cy="6" rx="0" ry="2"/>',               -- not drawn
  '<ellipse rx="1e-200" ry="1e200"/>',
  '<line x1="0" y1="0" x2="7" y2="9"/>',
  '<line x1="3" y1="3" x2="3" y2="3"/>',                  -- zero length
  '<line x1="-0" y1="-0" x2="-0" y2="1"/>',
  '<line/>',
  '<polyline points="0,0 1,1 2,0 3,1"/>',
  '<polyline points="5 5"/>',                             -- one point
  '<polyline points="1e-5-2e+3.5.5 0,0"/>',
  '<polyline points=""/>',                                -- not drawn
  '<polygon points="5 5 10 5 7 9"/>',
  '<polygon points="5 5 10 5 7 9 5 5"/>',                 -- closed already
  '<polygon points="-0 -0 0 0"/>',
  '<polygon points="0.1 0.2"/>',
}

local TRANSFORMS = {
  "", 'transform="translate(3 -4)"', 'transform="scale(-1 2)"',
  'transform="rotate(30 1 2)"', 'transform="skewX(20)"',
  'transform="matrix(0.3 -0.7 1.1 0.2 1e-3 -5)"', 'transform="scale(1e-170)"',
  'transform="scale(1e150) rotate(45)"',
}

local function doc(inner) return H .. inner .. "</svg>" end

-- The elements of text read with opts, as a list (or the error table).
local function read(text, opts)
  local o = {}
  for k, v in pairs(opts) do o[k] = v end
  local r = svgdoc.new(o)
  local ok, res = pcall(function()
    r:feed(text)
    return r:finish("doc")
  end)
  if not ok then return nil, res end
  return res.elements
end

-- Are x and y the same double, bit for bit (the sign of a zero too)?
local function same_bits(x, y)
  if x ~= x then return y ~= y end
  return x == y and (x ~= 0 or 1 / x == 1 / y)
end

-- Two elements the same: their fields, d, and records to the bit.
local function assert_same(a, b, what)
  assert.are.equal(a.tag, b.tag, what)
  assert.are.equal(a.d, b.d, what)
  local sa, sb = a.subpaths, b.subpaths
  assert.are.equal(sa.n, sb.n, what)
  assert.is_true(sa.packed == sb.packed, what .. ": the records differ")
  assert.are.equal(sa.kinds, sb.kinds, what)
  assert.are.equal(#sa, #sb, what)
  for j = 1, #sa do
    assert.is_true(same_bits(sa[j].x, sb[j].x) and same_bits(sa[j].y, sb[j].y),
      what .. ": subpath " .. j .. "'s start")
    assert.are.equal(sa[j].closed, sb[j].closed, what)
    assert.are.equal(sa[j].n, sb[j].n, what)
  end
  for k = 1, 6 do assert.is_true(same_bits(a.ctm[k], b.ctm[k]), what) end
end

-- Built and through the text: the same elements, or the same error.
local function compare(text, opts, what)
  local shape_text = {shape_text = true}
  for k, v in pairs(opts) do shape_text[k] = v end
  local built, err1 = read(text, opts)
  local parsed, err2 = read(text, shape_text)
  if built == nil or parsed == nil then
    assert.is_table(err1, what .. ": only the text route failed")
    assert.is_table(err2, what .. ": only the builder failed")
    assert.are.same(err2, err1, what)
    return 0, 1
  end
  assert.are.equal(#parsed, #built, what)
  for i = 1, #built do assert_same(built[i], parsed[i], what .. " #" .. i) end
  return #built, 0
end

describe("#svgdoc basic shapes built without text", function()
  it("give the records their path data gives, bit for bit: every kind, both arcs modes, under transforms",
    function()
      local elements, n = 0, 0
      for _, arcs in ipairs({"conics", "cubics"}) do
        for _, arc_tol in ipairs({1e-12, 1e-3}) do
          for _, t in ipairs(TRANSFORMS) do
            for _, s in ipairs(SHAPES) do
              local shape = t == "" and s or s:gsub("^<(%a+)", "<%1 " .. t)
              local what = ("%s, arcs %s, arc_tol %g"):format(shape, arcs, arc_tol)
              local drawn = compare(doc(shape), {arcs = arcs, arc_tol = arc_tol}, what)
              elements, n = elements + drawn, n + 1
            end
          end
        end
      end
      assert.is_true(elements > 0.8 * n)   -- most are drawn: the comparison is real
    end)

  it("under nested groups, viewBox, units and <use>", function()
    local text = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" '
      .. 'width="210mm" height="297mm" viewBox="3 -7 210 297">'
      .. '<g transform="rotate(-17) translate(0.1 0.2)"><g transform="scale(3 0.5)">'
      .. table.concat(SHAPES):gsub('<[^>]*e%-?[23]%d%d[^>]*>', "") .. '</g><use xlink:href="#c" x="0.3" y="-2"/></g>'
      .. '<defs><circle id="c" cx="1.1" cy="2.2" r="0.7"/></defs></svg>'
    for _, arcs in ipairs({"conics", "cubics"}) do
      for _, unit_px in ipairs({0, 96 / 25.4}) do
        local drawn, failed = compare(text, {arcs = arcs, unit_px = unit_px, uses = true}, arcs)
        assert.are.equal(0, failed, select(2, read(text, {arcs = arcs, unit_px = unit_px, uses = true})))
        assert.are.equal(29, drawn)    -- 28 shapes drawn and the use
      end
    end
  end)

  it("fail with the text's errors, in the document's words", function()
    local cases = {
      '<rect x="1e308" width="1e308" height="1"/>',       -- x + width beyond the doubles
      '<rect x="-1e308" width="1e308" height="1" rx="1e308"/>',
      '<circle r="1e308"/>',
      '<circle cx="1e308" r="1e308"/>',
      '<ellipse rx="1e308" ry="1"/>',
      '<line x1="-1e308" x2="1e308"/>',
      '<polyline points="-1e308 0 1e308 0"/>',
      '<circle r="1e300" transform="scale(1e10)"/>',
    }
    for _, arcs in ipairs({"conics", "cubics"}) do
      for _, c in ipairs(cases) do
        -- as cubics a circle of radius 1e308 is read (its quarters' points
        -- are doubles); measuring it says its length overflows (svgbad_spec)
        if not (arcs == "cubics" and c == '<circle r="1e308"/>') then
          local _, failed = compare(doc(c), {arcs = arcs}, c .. ", " .. arcs)
          assert.are.equal(1, failed, c .. ", " .. arcs .. ": no error")
        end
      end
    end
    local _, err = read(doc('<rect x="1e308" width="1e308" height="1"/>'), {})
    assert.are.equal("<rect>: expected a number (H x), got 'i' at position 12", err.msg)
    _, err = read(doc('<circle r="1e308"/>'), {})
    assert.matches("^<circle>: the radius is out of range %(r='1e308'%)", err.msg)
  end)
end)

describe("#svgdoc a basic shape's d", function()
  -- the text the reader has always written (checked against the reader
  -- before the builder, which printed it for every shape)
  local D = {
    {'<rect x="1" y="2" width="3" height="4"/>', "M1 2 H4 V6 H1 Z"},
    {'<rect width="10" height="6" rx="1"/>',
     "M1 0 H9 A1 1 0 0 1 10 1 V5 A1 1 0 0 1 9 6 H1 A1 1 0 0 1 0 5 V1 A1 1 0 0 1 1 0 Z"},
    {'<circle cx="1" cy="2" r="3"/>',
     "M4 2 A3 3 0 0 1 1 5 A3 3 0 0 1 -2 2 A3 3 0 0 1 1 -1 A3 3 0 0 1 4 2 Z"},
    {'<ellipse cx="0.1" rx="2" ry="1"/>',
     "M2.1000000000000001 0 A2 1 0 0 1 0.10000000000000001 1 A2 1 0 0 1 -1.8999999999999999 0"
       .. " A2 1 0 0 1 0.10000000000000001 -1 A2 1 0 0 1 2.1000000000000001 0 Z"},
    {'<line x1="-0" x2="7" y2="9"/>', "M-0 0 L7 9"},
    {'<polyline points="0,0 1,1 2,0"/>', "M 0 0 L1 1 L2 0"},
    {'<polygon points="5 5 10 5 7 9"/>', "M 5 5 L10 5 L7 9 Z"},
    {'<polygon points="1e-5 1e21"/>', "M 1.0000000000000001e-05 1e+21 Z"},
    {'<path d=" M0 0 l1,1 "/>', " M0 0 l1,1 "},
  }

  it("is the text it always was, written when first read", function()
    for _, c in ipairs(D) do
      local els = assert(read(doc(c[1]), {}))
      local e = els[1]
      if e.tag == "path" then
        assert.are.equal(c[2], rawget(e, "d"))
      else
        assert.is_nil(rawget(e, "d"), c[1] .. ": written before it was asked for")
      end
      assert.are.equal(c[2], e.d, c[1])
      assert.are.equal(c[2], rawget(e, "d"), c[1] .. ": kept once written")
      assert.is_nil(e.nothing)                    -- other keys stay absent
      assert.is_nil(e[1])
    end
  end)

  it("stays available through svg.read and svg.each", function()
    local text = doc('<circle cx="1" cy="2" r="3"/><rect x="1" y="2" width="3" height="4"/>')
    local d = svg.parse(text)
    assert.are.equal(D[3][2], d.elements[1].d)
    assert.are.equal(D[1][2], d.elements[2].d)
    local seen = {}
    svg.each(function()
      local t = text
      text = nil
      return t
    end, function(e) seen[#seen + 1] = e.d end)
    assert.are.same({D[3][2], D[1][2]}, seen)
  end)
end)
