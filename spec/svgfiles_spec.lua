-- spec/svgfiles_spec.lua -- documents as users have them (issue 32, items 4
-- and 7): the errors a renderer passes over (a <use> of a missing id, an
-- error in path data) are warnings with their place and the rest is
-- measured, errors under strict; compressed files (gzip, .svgz) read
-- transparently, and what is not an SVG document named as what it is.
local svg = require("helpers").optional("arclen.svg")   -- #svgdoc specs need it
local arclen = require("arclen")

local H = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 100 100">'
local COL = #H + 1                    -- the column of the first element after H

local function lengths(doc)
  local t = {}
  for i, e in ipairs(doc.elements) do t[i] = e.length end
  return t
end

describe("errors a renderer passes over #svgdoc", function()
  -- SVG 2 section 9.5.4 (SVG 1.1 F.2): rendered up to the command that holds
  -- the error.  Each length is that of the correct prefix, by hand.
  local cases = {
    -- d, the length of what is drawn, the message, where the prefix ends
    {"M0 0 L10 0 L10 10 L 5", 20, "expected a number %(L y%), got the end of the data at position 22", 17},
    {"M0 0 L3 4 6 8 9", 10, "expected a number %(L y%)", 13},        -- an implicit repetition
    {"M0 0 L3 4 L1e", 5, "exponent without digits", 9},
    {"M0 0 L3 4 # L 9 9", 5, "position 11", 9},
    {"M0 0 L3 4 Z 7", 10, "position 13", 11},
    {"M0 0 H 3, V", 3, "expected a number %(V y%)", 8},                 -- the comma dropped
    {"M0 0 L3 4,L6 8", 5, "comma not followed by a number at position 10", 9},
    {"M0 0 L3 4 Z Z", 10, "position 13", 11},
    {"M 67.78348 1090.127 A 5.868683 5.868652 0 1 ", 0, "expected sweep%-flag %(0 or 1%) at position 45", 19},
  }
  for _, c in ipairs(cases) do
    it("d='" .. c[1] .. "': " .. c[2] .. ", with a warning", function()
      local doc = svg.parse(H .. '<path id="p" d="' .. c[1] .. '"/><path d="M0 0 L0 1"/></svg>', nil, "w.svg")
      assert.are.same({c[2], 1}, lengths(doc))
      assert.are.equal(1, #doc.warnings)
      assert.matches("^w%.svg:1:" .. COL .. ": <path id='p'>: d: ", doc.warnings[1])
      assert.matches(c[3], doc.warnings[1])
      assert.matches("; drawn up to position " .. c[4] .. "$", doc.warnings[1])
      assert.are.equal(c[1]:sub(1, c[4]), doc.elements[1].d)
      -- the same prefix as path data of its own measures the same
      assert.are.equal(arclen.path.svg(c[1]:sub(1, c[4])):length(), c[2])
      -- strict: the error, where it was before issue 32
      local ok, e = pcall(svg.parse, H .. '<path id="p" d="' .. c[1] .. '"/></svg>', {strict = true}, "w.svg")
      assert.is_false(ok)
      assert.matches("^w%.svg:1:" .. COL .. ": <path id='p'>: d: ", e)
      assert.is_nil(e:find("drawn up to", 1, true))
      -- arclen.path.svg keeps raising
      assert.is_false((pcall(arclen.path.svg, c[1])))
    end)
  end

  it("an error in the first command: nothing drawn", function()
    local doc = svg.parse(H .. '<path d="L1 1"/><path d="M0,"/><path d="M0 0 L0 2"/></svg>', nil, "w.svg")
    assert.are.same({2}, lengths(doc))
    assert.are.equal(2, #doc.warnings)
    assert.matches("^w%.svg:1:" .. COL .. ": <path>: d: .*; nothing drawn$", doc.warnings[1])
    assert.matches("; nothing drawn$", doc.warnings[2])
  end)

  it("numbers beyond the doubles and arcs that cannot be built stay errors (no grammar error)", function()
    assert.matches("out of range", select(2, pcall(svg.parse, H .. '<path d="M0 0 L1e999 0"/></svg>')))
    assert.matches("overflows", select(2, pcall(svg.parse, H .. '<path d="M0 0 L1e308 0 L-1e308 0"/></svg>')))
  end)

  it("a <use> of a missing id: a warning at the use, the rest drawn in order", function()
    local text = H .. '<path id="a" d="M0 0 L1 0"/>\n<use xlink:href="#nope"/>\n<path d="M0 0 L2 0"/>\n' ..
      '<g id="g"><use href="#gone"/><path d="M0 0 L3 0"/></g><use href="#g" x="5"/></svg>'
    local doc = svg.parse(text, nil, "u.svg")
    assert.are.same({1, 2, 3, 3}, lengths(doc))
    assert.are.same({"u.svg:2:1: <use> of '#nope': no element has that id; nothing drawn",
      "u.svg:4:11: <use> of '#gone': no element has that id; nothing drawn",
      "u.svg:4:11: <use> of '#gone': no element has that id; nothing drawn"}, doc.warnings)
    local ok, e = pcall(svg.parse, text, {strict = true}, "u.svg")
    assert.is_false(ok)
    assert.matches("^u%.svg:%d+:%d+: <use> of '#[a-z]+': no element has that id$", e)
  end)

  it("strict turns every warning into an error, and is a boolean", function()
    local text = H .. '<path transform="scale(0)" d="M0 0 L1 0"/></svg>'
    assert.are.equal(1, #svg.parse(text).warnings)
    assert.matches("singular transform", select(2, pcall(svg.parse, text, {strict = true})))
    assert.matches("strict must be a boolean", select(2, pcall(svg.parse, text, {strict = 1})))
  end)
end)
