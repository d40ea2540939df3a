-- spec/svgbad_spec.lua -- arclen.svg against bad documents: each bad case
-- ends in an error "NAME:LINE:COL: message" that names the file and the
-- place (or, where a renderer draws nothing -- a singular transform --, in
-- a warning that does), never in a NaN, a Lua runtime error or a hang.
-- Then a seeded random mutation of the real documents under spec/data/svg/
-- (as hostile_spec does for path data): every mutant is read to a result
-- with finite lengths or to such an error, within a time limit
-- (ARCLEN_TIME_SCALE stretches it for valgrind and sanitizer runs).
local svg = require("helpers").optional("arclen.svg")   -- #svgdoc specs need it

local TIME_SCALE = tonumber(os.getenv("ARCLEN_TIME_SCALE")) or 1
local H = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 10 10">'
local COL = #H + 1                    -- the column of the first element after H

-- The error message of reading text named name (nil when it reads).
local function err_of(text, name, opts)
  local ok, e = pcall(svg.parse, text, opts, name or "bad.svg")
  if ok then return nil, e end
  return e
end

describe("arclen.svg: bad documents, each a clear error naming the file and place #svgdoc", function()
  local cases = {
    {"malformed XML (line and column from expat)", "<svg xmlns='http://www.w3.org/2000/svg'>\n  <path d='M0 0'>\n</svg>",
     "^bad%.svg:3:3: malformed XML: mismatched tag$"},
    {"an unclosed attribute", H .. '<path d="M0 0/></svg>', "^bad%.svg:1:%d+: malformed XML: "},
    {"an unknown unit", H .. '<rect width="3qq" height="1"/></svg>',
     "^bad%.svg:1:" .. COL .. ": width='3qq': unknown unit 'qq'$"},
    {"a length that is not one", H .. '<circle r="ten"/></svg>', "r='ten' is not a length"},
    {"a negative width", H .. '<rect width="-3" height="1"/></svg>', "width must not be negative"},
    {"a wrong argument count", H .. '<path transform="rotate(1 2)" d="M0 0 L1 0"/></svg>',
     "^bad%.svg:1:" .. COL .. ": transform='rotate%(1 2%)': rotate takes 1 or 3 arguments, got 2"},
    {"an unknown transform", H .. '<g transform="frob(1)"/></svg>', "unknown transform 'frob'"},
    {"an unclosed transform", H .. '<g transform="scale(1"/></svg>', "a number or '%)' expected in scale"},
    {"a comma before ')'", H .. '<g transform="scale(1,)"/></svg>', "comma before '%)'"},
    {"a comma after the last transform", H .. '<g transform="scale(1),"/></svg>', "comma after the last transform"},
    {"a transform that overflows", H .. '<g transform="scale(1e308) scale(1e308)"/></svg>', "overflows"},
    {"coordinates out of range after a transform", H .. '<path transform="scale(1e300)" d="M0 0 L1e10 0"/></svg>',
     "the transform takes a coordinate out of range"},
    {"bad path data, with its position", H .. '<path id="p" d="M0 0 L1e"/></svg>',
     "^bad%.svg:1:" .. COL .. ": <path id='p'>: d: exponent without digits in a number at position 8$"},
    {"an odd number of coordinates", H .. '<polygon points="1 2 3"/></svg>', "points: an odd number of coordinates"},
    {"a bad viewBox", H .. '<svg viewBox="1 2 3"/></svg>', "viewBox='1 2 3' is not four numbers"},
    {"a bad preserveAspectRatio", H .. '<svg viewBox="0 0 1 1" preserveAspectRatio="xMidYMax sliced"/></svg>',
     "preserveAspectRatio='xMidYMax sliced' is not valid"},
    {"a percentage without a viewport", '<svg xmlns="http://www.w3.org/2000/svg"><rect width="50%" height="1"/></svg>',
     "a percentage needs a viewport"},
    {"a use of itself", H .. '<use href="#a" id="a"/></svg>', "^bad%.svg:1:" .. COL .. ": <use> of '#a' refers to itself"},
    {"a use inside its target", H .. '<g id="g"><path d="M0 0 L1 0"/><use href="#g"/></g></svg>', "refers to itself"},
    {"a use cycle", H .. '<g id="a"><use href="#b"/></g><g id="b"><use xlink:href="#a"/></g></svg>',
     "makes a cycle %(b %-> a %-> b%)"},
    {"a use of a missing id", H .. '<use href="#nope"/></svg>', "<use> of '#nope': no element has that id"},
    {"nesting beyond the cap", H .. ("<g>"):rep(1100) .. ("</g>"):rep(1100) .. "</svg>", "elements nested deeper than 1000"},
    {"entity expansion (billion laughs)",
     '<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY a "lol"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;">]><svg>&b;</svg>',
     "^bad%.svg:1:%d+: entity 'b' refers to other entities"},
    {"an empty document", "", "^bad%.svg:1:1: empty document$"},
    {"whitespace only", " \n  ", "^bad%.svg:%d+:%d+: empty document %(no root element%)$"},
    {"not XML", "M0 0 L10 10", "^bad%.svg:1:1: malformed XML: syntax error$"},
    {"XML that is not SVG", '<html xmlns="http://www.w3.org/1999/xhtml"><body/></html>',
     "^bad%.svg:1:1: not an SVG document: the root element is <html>"},
    {"an svg root in another namespace", '<svg xmlns="urn:x"/>', "not an SVG document"},
    -- errors met while measuring: the element's place, in the document's words
    {"a path whose length overflows (its thirds beyond the doubles)", H .. '<path d="M0 0 L1e308 0 L-1e308 0"/></svg>',
     "^bad%.svg:1:" .. COL .. ": <path>: the path's length overflows %(coordinates up to 1e%+308%)$"},
    {"a path of finite control points whose length overflows", H .. '<path id="p" d="M0 0 L1.7e308 0 L0 0 L1.7e308 0"/></svg>',
     "^bad%.svg:1:" .. COL .. ": <path id='p'>: the path's length overflows %(coordinates up to 1%.7e%+308%)$"},
    {"a total that overflows, at the element where it does", H .. '<path d="M0 0 L1.7e308 0"/>\n<path d="M0 0 L1.7e308 0"/></svg>',
     "^bad%.svg:2:1: <path>: the total length overflows here %(1%.7e%+308 before it, 1%.7e%+308 in it%)$"},
    {"a circle of radius 1e308", H .. '<circle r="1e308"/></svg>',
     "^bad%.svg:1:" .. COL .. ": <circle>: the radius is out of range %(r='1e308'%)"},
    {"an ellipse of radius 1e308", H .. '<ellipse rx="1" ry="1e308"/></svg>',
     "^bad%.svg:1:" .. COL .. ": <ellipse>: the radii are out of range %(rx='1' ry='1e308'%)"},
    {"a rect whose corners are beyond the doubles", H .. '<rect width="1e308" height="1e308" rx="1e307"/></svg>',
     "^bad%.svg:1:" .. COL .. ": <rect>: the size is out of range %(width='1e308' height='1e308' rx='1e307'%)"},
    {"skewX(90)", H .. '<path transform="skewX(90)" d="M0 0 L0 1"/></svg>',
     "^bad%.svg:1:" .. COL .. ": transform='skewX%(90%)': skewX%(90%) is undefined %(a skew angle must not be 90 degrees modulo 180%) at character 1$"},
    {"skewY(-90) after another function", H .. '<g transform="translate(1) skewY(-90)"/></svg>',
     "transform='translate%(1%) skewY%(%-90%)': skewY%(%-90%) is undefined .* at character 14$"},
    {"skewX(270)", H .. '<g transform="skewX(270)"/></svg>', "skewX%(270%) is undefined"},
  }
  -- a renderer passes over these (doc/svg.md, "Files, and errors a
  -- renderer passes over"): errors only under strict, warnings otherwise
  -- (below, and spec/svgfiles_spec.lua)
  local STRICT = {["bad path data, with its position"] = true, ["a use of a missing id"] = true,
                  ["a negative width"] = true, ["an odd number of coordinates"] = true}
  for _, c in ipairs(cases) do
    it(c[1], function()
      local e = err_of(c[2], nil, STRICT[c[1]] and {strict = true} or nil)
      assert.is_string(e, "no error")
      assert.matches(c[3], e)
      assert.is_nil(e:find("traceback", 1, true))
    end)
  end

  it("negative sizes and bad points: drawn as a renderer draws them, with a warning", function()
    -- SVG 2 chapter 10 and web-platform-tests (circle-006, ellipse-006,
    -- ellipse-007, rect-007): a negative length is invalid, taken as not
    -- given (r, width, height: 0, not drawn; rx, ry: auto, the other
    -- radius); points with an error: the pairs before it (section 10.6)
    local cases = {
      {'<circle r="-1"/>', 0, "<circle>: r must not be negative %(%-1%); not drawn"},
      {'<rect width="-3" height="1"/>', 0, "<rect>: width must not be negative %(%-3%); not drawn"},
      {'<rect width="3" height="-1"/>', 0, "<rect>: height must not be negative %(%-1%); not drawn"},
      -- rx auto: 1 as ry, so corners of radius 1 on a 4 x 2 rect: 2 (4 - 2) + 2 pi
      {'<rect width="4" height="2" rx="-5" ry="1"/>', 4 + 2 * math.pi, "<rect>: rx must not be negative %(%-5%); taken as auto"},
      -- both negative: both auto, square corners
      {'<rect width="4" height="2" rx="-1" ry="-1"/>', 12, "<rect>: rx must not be negative %(%-1%); taken as auto"},
      -- ry auto: the circle of radius 2
      {'<ellipse rx="2" ry="-1"/>', 4 * math.pi, "<ellipse>: ry must not be negative %(%-1%); taken as auto"},
      {'<ellipse rx="-2" ry="-1"/>', 0, "<ellipse>: rx must not be negative %(%-2%); not drawn"},
      {'<ellipse rx="-2"/>', 0, "<ellipse>: rx must not be negative %(%-2%); not drawn"},
      {'<polyline points="0 0 3 4 9"/>', 5, "<polyline>: points: an odd number of coordinates; the last one left out"},
      {'<polygon points="0 0 3 4 3 x 0"/>', 10, "<polygon>: points: not a number at character 11; drawn up to it"},
      {'<polyline points="0 x"/>', 0, "<polyline>: points: not a number at character 3; nothing drawn"},
      -- a nested viewport's width auto: 100% of the 10 x 10 parent's, so
      -- the path in it as drawn (it was an error)
      {'<svg width="-5" height="4"><path d="M0 0 L3 0"/></svg>', 3, "<svg>: width must not be negative %(%-5%); taken as auto"},
    }
    for _, c in ipairs(cases) do
      local text = H .. c[1] .. '<path d="M0 0 L1 0"/></svg>'
      local e, doc = err_of(text)
      assert.is_nil(e, c[1])
      assert.is_true(math.abs(doc.total - (c[2] + 1)) <= 1e-12 * (c[2] + 1), c[1] .. ": " .. doc.total)
      assert.matches("^bad%.svg:1:" .. COL .. ": " .. c[3] .. "$", doc.warnings[1], 1)
      -- under strict, the error without the consequence, at the same place
      e = err_of(text, nil, {strict = true})
      assert.is_string(e, c[1])
      assert.matches("^bad%.svg:1:" .. COL .. ": " .. c[3]:gsub("; .*$", "") .. "$", e)
    end
  end)

  it("a negative width of a <use> or of the root: auto, with a warning", function()
    -- <use width="-2" height="5"> of a 1 x 1 symbol: width auto, 100% of
    -- the 10 x 10 viewport, so the symbol meets 10 x 5: scale 5
    local use = '<symbol id="s" viewBox="0 0 1 1"><path d="M0 0 L1 0"/></symbol>'
    local at = #H + #use + 1
    local text = H .. use .. '<use href="#s" width="-2" height="5"/></svg>'
    local e, doc = err_of(text)
    assert.is_nil(e)
    assert.is_true(math.abs(doc.total - 5) <= 1e-12 * 5, doc.total)
    assert.matches("^bad%.svg:1:" .. at .. ": <use>: width must not be negative %(%-2%); taken as auto$", doc.warnings[1])
    e = err_of(text, nil, {strict = true})
    assert.matches("^bad%.svg:1:" .. at .. ": <use>: width must not be negative %(%-2%)$", e)
    -- the root's height auto: the viewBox's own size, as without one
    text = '<svg xmlns="http://www.w3.org/2000/svg" width="20" height="-1" viewBox="0 0 10 10"><path d="M0 0 L1 0"/></svg>'
    e, doc = err_of(text)
    assert.is_nil(e)
    assert.are.equal(1, doc.total)
    assert.matches("^bad%.svg:1:1: <svg>: height must not be negative %(%-1%); taken as auto$", doc.warnings[1])
    assert.matches("^bad%.svg:1:1: <svg>: height must not be negative %(%-1%)$", err_of(text, nil, {strict = true}))
  end)

  it("a singular transform: not drawn, with a warning naming the place", function()
    local e, doc = err_of(H .. '<path transform="scale(0)" d="M0 0 L1 0"/><path d="M0 0 L2 0"/></svg>')
    assert.is_nil(e)
    assert.are.equal(2, doc.total)
    assert.matches("^bad%.svg:1:" .. COL .. ": <path>: singular transform, not drawn$", doc.warnings[1])
  end)

  it("an arc of path data near the doubles' end: measured as cubics and as a conic", function()
    -- a quarter of the circle of radius 1e308: pi/2 1e308 (mpmath); as
    -- cubics within tol L + 2 pi arc_tol r (it was an error: half the
    -- chord's square overflowed)
    local text = H .. '<path d="M0 0 A1e308 1e308 0 0 1 1e308 1e308"/></svg>'
    local want = 1.57079632679489661923132169164e308
    local e, doc = err_of(text, nil, {arcs = "cubics"})
    assert.is_nil(e)
    assert.is_true(math.abs(doc.total - want) <= 1e-12 * want + 2 * math.pi * 1e-12 * 1e308, doc.total)
    e, doc = err_of(text)
    assert.is_nil(e)
    assert.is_true(math.abs(doc.total - want) <= 1e-12 * want, doc.total)
    -- a half circle of that radius has no length in doubles: the place
    assert.matches("^bad%.svg:1:" .. COL .. ": <path>: the path's length overflows",
      err_of(H .. '<path d="M-1e308 0 A1e308 1e308 0 0 1 1e308 0"/></svg>', nil, {arcs = "cubics"}))
  end)

  it("no internal words in the errors of the measuring (tol, coordinate n, bad argument)", function()
    for _, t in ipairs{'<path d="M0 0 L1e308 0 L-1e308 0"/>', '<circle r="1e308"/>',
                       '<path d="M-1e308 0 A1e308 1e308 0 0 1 1e308 0"/>'} do
      local e = err_of(H .. t .. "</svg>", nil, {arcs = "cubics"})
      assert.is_string(e)
      assert.is_nil(e:find("tol must", 1, true), e)
      assert.is_nil(e:find("coordinate %d"), e)
      assert.is_nil(e:find("bad argument", 1, true), e)
      assert.is_nil(e:find("path.lua", 1, true), e)
    end
  end)

  it("singular transforms are judged by their singular values, not an underflowing determinant", function()
    -- scale(1e-170): determinant 1e-340 (0 in doubles), singular values 1e-170
    local e, doc = err_of(H .. '<g transform="scale(1e-170)"><path d="M0 0 L1e170 0"/></g></svg>')
    assert.is_nil(e)
    assert.are.same({}, doc.warnings)
    -- the exact product of the doubles 1e170 and 1e-170 is 1 to 1e-16
    assert.is_true(math.abs(doc.total - 1) <= 1e-15, doc.total)
    e, doc = err_of(H .. '<g transform="matrix(0 1e-200 -1e-200 0 0 0)"><path d="M0 0 L3e200 4e200"/></g></svg>')
    assert.is_nil(e)
    assert.is_true(math.abs(doc.total - 5) <= 5e-15, doc.total)
    -- rank one (columns (1, 2) and (2, 4)) and a zero scale stay singular
    for _, t in ipairs{"matrix(1 2 2 4 0 0)", "scale(0 1)", "scale(1e-200) scale(1e-200)"} do
      e, doc = err_of(H .. '<path transform="' .. t .. '" d="M0 0 L1 1"/></svg>')
      assert.is_nil(e)
      assert.are.equal(0, doc.total)
      assert.matches("^bad%.svg:1:" .. COL .. ": <path>: singular transform, not drawn$", doc.warnings[1])
    end
  end)

  it("a skew short of 90 degrees is drawn", function()
    local e, doc = err_of(H .. '<path transform="skewX(89.99)" d="M0 0 L0 1"/></svg>')
    assert.is_nil(e)
    -- the image of (0, 1) is (tan 89.99 deg, 1); mpmath (30 digits):
    -- sqrt(1 + tan(89.99 deg)^2) = 5729.57798039705305762986026573.  The
    -- angle in radians is rounded (1.1e-16 relative), which tan near 90
    -- degrees multiplies by tan(a) a = 9e3: 1e-12 relative, so 1e-11 here.
    assert.is_true(math.abs(doc.total - 5729.57798039705305762986026573) <= 1e-11 * 5729.6, doc.total)
  end)

  it("errors after a token longer than the reader's chunks keep their place", function()
    local d = "M0 0" .. ("l1 0"):rep(60000)            -- 240 kB: one token over four chunks
    local text = H .. '\n<path d="' .. d .. '"/>\n  <circle r="1e308"/></svg>'
    local e = err_of(text)
    assert.matches("^bad%.svg:3:3: <circle>: the radius is out of range", e)
    local e2, doc = err_of(H .. '\n<path d="' .. d .. '"/>\n  <path d="M0 0 L2 0"/></svg>')
    assert.is_nil(e2)
    assert.are.equal(60002, doc.total)
    assert.are.same({2, 1, 3, 3}, {doc.elements[1].line, doc.elements[1].col, doc.elements[2].line, doc.elements[2].col})
  end)

  it("a use bomb (each level uses the previous twice) stops at the cap, quickly", function()
    local b = {H, '<path id="l0" d="M0 0 L1 0"/>'}
    for i = 1, 40 do b[#b + 1] = ('<g id="l%d"><use href="#l%d"/><use href="#l%d"/></g>'):format(i, i - 1, i - 1) end
    b[#b + 1] = "</svg>"
    local t0 = os.clock()
    local e = err_of(table.concat(b))
    assert.matches("<use> expansions replay more than %d+ elements", e)
    assert.is_true(os.clock() - t0 < 30 * TIME_SCALE)
  end)

  it("read: a missing file says so; misuse is 'bad argument'", function()
    local ok, e = pcall(svg.read, "/nonexistent/x.svg")
    assert.is_false(ok)
    assert.are.equal("/nonexistent/x.svg: no such file", e)
    ok, e = pcall(svg.read, 42)
    assert.matches("^bad argument #1 to 'arclen.svg.read'", e)
    ok, e = pcall(function() local d = svg.parse(H .. "</svg>", {units = "furlong"}); return d end)
    assert.matches("^[^:]*svgbad_spec.lua:%d+: bad argument #2 to 'arclen.svg.parse' %(unknown units 'furlong'", e)
    ok, e = pcall(svg.parse, H .. "</svg>", {frob = true})
    assert.matches("unknown option 'frob'", e)
    ok, e = pcall(svg.stat, {})
    assert.matches("^bad argument #1 to 'arclen.svg.stat'", e)
  end)
end)

describe("arclen.svg: seeded random mutations of the real documents #svgdoc", function()
  local files = {}
  for _, row in ipairs(require("helpers").tsv("svg/SOURCES.tsv")) do files[#files + 1] = row.file end
  files[#files + 1] = "hand/css.svg"         -- style sheets: selectors, the cascade, @media
  files[#files + 1] = "hand/em.svg"
  files[#files + 1] = "hand/marker-vertices.svg"   -- markers: vertices, clip, the shorthand
  files[#files + 1] = "hand/marker-clip.svg"
  files[#files + 1] = "hand/marker-css.svg"
  local texts = {}
  for i, f in ipairs(files) do
    local h = assert(io.open("spec/data/svg/" .. f, "rb"))
    texts[i] = h:read("*a")
    h:close()
  end
  -- Park and Miller's generator: exact in doubles, the same on every Lua
  local seed = 19
  local function rnd(n)
    seed = (seed * 16807) % 2147483647
    return seed % n + 1
  end
  local INSERTS = {"<", ">", "&", "&amp;", "&#0;", '"', "'", "/>", "</g>", "<g>", "<use href='#x'/>",
    " transform='scale(0)'", " transform='matrix(1e308 0 0 1e308 0 0)'", " transform='rotate('",
    " width='1e400'", " r='-1'", " d='M1e308 1e308 L-1e308 -1e308'", " d='M0 0 A1e-320 1e-320 0 0 1 1 1'",
    "1e999", "-", ".", "NaN", "inf", "0x10", "]]>", "<!--", "-->", "<![CDATA[", "<?x?>",
    " display='none'", " viewBox='0 0 0 0'", " points='1 2 3'", " style='stroke:none'",
    "\0", "\255\254", "<svg>", "</svg>", "<symbol id='s'>", "<use xlink:href='#s'/>",
    "<style>", "</style>", "{", "}", "/*", "*/", " class='st0'", ".st0{stroke:red}",
    "@media screen{", "* * * *{display:none}", ":first-child", "[id^=a]>", "!important",
    " style='font-size:1e308em'", " font-size='-1'", "\\", "@import 'x';",
    " marker-end='url(#m)'", " marker-mid='url(#curves)'", "marker:url(#a)", " orient='1e308'",
    "<marker id='m' viewBox='0 0 1e-300 1' refX='1e308'>", "</marker>", " markerWidth='1e308'",
    " markerUnits='strokeWidth'", " stroke-width='1e308'", " overflow='visible'", " orient='auto'"}
  local function mutate(text)
    local t = text
    for _ = 1, rnd(4) do
      local n = #t
      local p = rnd(n)
      local kind = rnd(4)
      if kind == 1 then                       -- delete a run
        t = t:sub(1, p - 1) .. t:sub(p + rnd(20))
      elseif kind == 2 then                   -- insert a token
        t = t:sub(1, p) .. INSERTS[rnd(#INSERTS)] .. t:sub(p + 1)
      elseif kind == 3 then                   -- replace a byte
        t = t:sub(1, p - 1) .. string.char(rnd(256) - 1) .. t:sub(p + 1)
      else                                    -- duplicate a run
        local q = math.min(n, p + rnd(200))
        t = t:sub(1, q) .. t:sub(p, q) .. t:sub(q + 1)
      end
    end
    return t
  end
  local RUNS = tonumber(os.getenv("SVG_MUTATIONS")) or 300
  it(("%d mutants: finite results or located errors, never NaN or a crash"):format(RUNS), function()
    local reads, errors = 0, 0
    local t0 = os.clock()
    for run = 1, RUNS do
      local k = rnd(#texts)
      local text = mutate(texts[k])
      local name = files[k] .. "~" .. run
      local ok, res = pcall(svg.parse, text, nil, name)
      if ok then
        reads = reads + 1
        assert(res.total == res.total and res.total < math.huge, name .. ": total " .. tostring(res.total))
        for _, e in ipairs(res.elements) do
          assert(e.length == e.length and e.length < math.huge, name .. ": element length")
        end
      else
        errors = errors + 1
        assert(type(res) == "string", name .. ": error object " .. tostring(res))
        local esc = name:gsub("%p", "%%%0")
        assert(res:match("^" .. esc .. ":%d+:%d+: .+"), name .. ": unlocated error: " .. res)
        assert(not res:find("attempt to", 1, true), name .. ": Lua error: " .. res)
        assert(not res:find("traceback", 1, true), name .. ": " .. res)
      end
    end
    assert.is_true(reads > 0 and errors > 0)
    assert.is_true(os.clock() - t0 < 120 * TIME_SCALE, "too slow")
  end)
end)

-- The C reader's own module is private (arclen.svg is its user), but its
-- misuse is still a named argument error, never a crash.
describe("arclen.svgdoc (the reader arclen.svg drives) #svgdoc", function()
  local svgdoc = require("arclen.svgdoc")
  it("names the bad argument of new, feed and finish", function()
    assert.matches("bad argument #1 to '[^']*' %(table expected", select(2, pcall(svgdoc.new, "x")))
    assert.matches("arc_tol", select(2, pcall(svgdoc.new, {arc_tol = 0 / 0})))
    assert.matches("max_depth", select(2, pcall(svgdoc.new, {max_depth = 0})))
    assert.matches("#1 .*unit_px must be a number", select(2, pcall(svgdoc.new, {unit_px = "mm"})))
    local r = svgdoc.new({})
    assert.matches("bad argument #1 to '[^']*' %(arclen.svgdoc.reader expected", select(2, pcall(r.feed, {}, "<svg/>")))
    assert.matches("bad argument #2 to '[^']*' %(string expected", select(2, pcall(r.feed, r, {})))
    r:feed('<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 0 L3 4"/></svg>')
    local res = r:finish("x.svg")
    assert.are.equal(1, #res.elements)
    local c = require("arclen.core")._cubics(res.elements[1].subpaths.packed)[1]  -- the line
    assert.are.same({0, 0, 3, 4, 0, 0, 0, 0}, c)
    assert.are.equal("L", res.elements[1].subpaths.kinds)
    r = svgdoc.new({arcs = "cubics"})                  -- today's cubics
    r:feed('<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 0 L3 4"/></svg>')
    res = r:finish("x.svg")
    c = require("arclen.core")._cubics(res.elements[1].subpaths.packed)[1]
    assert.are.same({0, 0, 3, 4}, {c[1], c[2], c[7], c[8]})
    assert.is_true(math.abs(c[3] - 1) < 1e-15 and math.abs(c[6] - 8 / 3) < 1e-15)
    assert.is_nil(res.elements[1].subpaths.kinds)
    assert.matches('#1 .*arcs must be "conics" or "cubics"', select(2, pcall(svgdoc.new, {arcs = "lines"})))
    assert.matches("finished", select(2, pcall(r.feed, r, "more")))
    assert.matches("finished", select(2, pcall(r.finish, r, "x.svg")))
  end)
  it("raises located errors as {line, col, msg} and is done after one", function()
    local r = svgdoc.new({strict = true})
    local ok, e = pcall(r.feed, r, "<svg xmlns='http://www.w3.org/2000/svg'>\n <path d='M0 0 Q'/>")
    assert.is_false(ok)
    assert.are.same({line = 2, col = 2, msg = "<path>: d: expected a number (Q x1), got the end of the data at position 7"}, e)
    assert.matches("finished", select(2, pcall(r.feed, r, "</svg>")))
  end)
  it("an unknown method is an argument error of svg.read and svg.parse", function()
    assert.matches("bad argument #2 to 'arclen.svg.parse' %(unknown method 'nope'%)",
      select(2, pcall(svg.parse, H .. "</svg>", {method = "nope"})))
  end)
end)
