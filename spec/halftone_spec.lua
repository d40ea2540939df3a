-- spec/halftone_spec.lua -- a halftone drawing measured as a stream
-- (issue 31: 10^5 circles exact to 1e-15): spec/data/halftone1000.svg,
-- 1000 circles under ten transforms (ellipses under non-uniform scale,
-- skew, matrix), against tools/ref_halftone.py's mpmath perimeters; the
-- lengths computed in C as the reader reads them (src/svgdoc/measure.c)
-- equal to the paths' own, made lazily.
local svg = require("helpers").optional("arclen.svg")
local helpers = require("helpers")

local FILE = "spec/data/halftone1000.svg"
local C = helpers.engine == "c"     -- the Lua engine's paths measure themselves

local function refs()
  local r = {}
  for _, row in ipairs(helpers.tsv("halftone1000.tsv")) do r[row.id] = tonumber(row.length) end
  return r
end

describe("a halftone drawing of 1000 circles #svgdoc", function()
  it("the whole file's length within 1e-15 of mpmath; each circle's within its points' rounding", function()
    local ref, worst = refs(), helpers.worst()
    local doc = svg.read(FILE)
    assert.are.equal(1000, #doc.elements)
    for _, e in ipairs(doc.elements) do
      -- the conics' points are rounded once at up to 2^7 beside radii
      -- from 0.05 (scaled): ~1e-14 of a circle's length at most
      worst:add(helpers.relerr(e.length, ref[e.id]), e.id)
    end
    local err = helpers.relerr(doc.total, ref.total)
    print(("\n  halftone: total %.2e relative, worst circle %.2e (%s)"):format(err, worst.err, worst.id))
    assert.is_true(worst.err <= 1e-13, worst.id .. ": " .. worst.err)
    assert.is_true(err <= 1e-15, "total: " .. err)
  end)
  it("each length is its lazy path's, bit for bit; the element keeps its documented fields", function()
    local n = 0
    svg.each(FILE, function(e)
      n = n + 1
      if C then
        assert.are.equal("number", type(rawget(e, "length")))  -- measured in C
        assert.is_nil(rawget(e, "path"))                       -- not made yet
      end
      local p = e.path
      assert.is_true(require("arclen").path.is_path(p))
      assert.are.equal(p, e.path)                              -- made once, kept
      assert.are.equal(e.length, p:length())
      assert.are.equal("circle", e.tag)
      assert.are.equal(6, #e.ctm)
      assert.matches("^M", e.d)
      assert.is_nil(e.subpaths)                                -- the reader's, not shown
      assert.are.equal("number", type(e.line))
    end)
    assert.are.equal(1000, n)
  end)
  it("every file of spec/data/svg: e.length is e.path:length(), bit for bit", function()
    local seen, n = {}, 0
    for _, row in ipairs(helpers.tsv("svg_refs.tsv")) do
      if not seen[row.file] then
        seen[row.file] = true
        local ok, doc = pcall(svg.read, "spec/data/svg/" .. row.file)
        if ok then
          for _, e in ipairs(doc.elements) do
            assert.are.equal(e.path:length(), e.length, row.file .. ": " .. tostring(e.id))
            n = n + 1
          end
        end
      end
    end
    assert.is_true(n >= 400, "elements: " .. n)     -- 451 on 2026-12-03
  end)
  it("path = false: measured elements come with their numbers only", function()
    local n, total = 0, 0
    local doc = svg.each(FILE, function(e)
      n = n + 1
      total = total + e.length
      assert.are.equal("number", type(e.line))
      assert.are.equal("circle", e.tag)
      if C then
        assert.is_nil(e.path)
        assert.is_nil(e.ctm)
        assert.is_nil(e.d)
      end
    end, {path = false})
    assert.are.equal(1000, n)
    assert.is_true(helpers.relerr(doc.total, refs().total) <= 1e-15)
    -- not measured (measure = false): nothing to leave out
    svg.each(FILE, function(e) assert.is_true(e.path ~= nil and e.ctm ~= nil) end,
      {path = false, measure = false})
    -- an element the reader cannot measure is measured by its path, and reported
    local ok, err = pcall(svg.parse, '<svg xmlns="http://www.w3.org/2000/svg">'
      .. '<path d="M0 0 L1e308 0 L-1e308 0"/></svg>', {path = false})
    assert.is_false(ok)
    assert.matches("<string>:1:%d+: <path>: the path's length overflows", err)
    assert.matches("path must be a boolean", select(2, pcall(svg.each, FILE, print, {path = 1})))
  end)
  it("svg.stats() from the segments in C: the same numbers as from the paths", function()
    local files = {FILE}
    local seen = {}
    for _, row in ipairs(helpers.tsv("svg_refs.tsv")) do
      if not seen[row.file] then
        seen[row.file] = true
        files[#files + 1] = "spec/data/svg/" .. row.file
      end
    end
    for _, f in ipairs(files) do
      local fast, slow = svg.stats(), svg.stats()
      local ok = pcall(svg.each, f, function(e)
        fast:add(e)               -- the reader's segments (C)
        local _ = e.path          -- made: the path's own walk (Lua)
        slow:add(e)
      end)
      if ok then assert.are.same(slow:result(), fast:result(), f) end
    end
  end)
  helpers.c_only(it, "methods elliptic and metapost")("the total with the method elliptic and with metapost (measured by the paths)", function()
    -- a path of another method makes its conics cubics (within tol): its
    -- own length, not the reader's exact one
    local a = svg.read(FILE, {method = "elliptic"})
    local ref = refs()
    assert.is_true(helpers.relerr(a.total, ref.total) <= 1e-12)
    for k = 1, 1000, 37 do
      assert.are.equal(a.elements[k].path:length(), a.elements[k].length)
    end
    local m = svg.read(FILE, {method = "metapost"})
    assert.are.equal(m.elements[1].length, m.elements[1].path:length())
  end)
  -- through a POSIX shell (io.popen): not under Wine's cmd
  local it_sh = package.config:sub(1, 1) == "/" and it or function() end
  it_sh("arclen length and arclen stat print the total within 1e-15", function()
    -- the module where this run found it (an installed rock, a build)
    local lua = ("LUA_PATH=%s LUA_CPATH=%s %s"):format(helpers.shquote(package.path),
      helpers.shquote(package.cpath), helpers.interpreter())
    local h = io.popen(lua .. " bin/arclen length " .. FILE)
    local out = h:read("*a")
    h:close()
    local total = tonumber(out:match("\ntotal\t(%S+)\n$"))
    assert.is_true(helpers.relerr(total, refs().total) <= 1e-15, out:sub(-60))
    h = io.popen(lua .. " bin/arclen stat " .. FILE)
    out = h:read("*a")
    h:close()
    total = tonumber(out:match("Totals.-Length: (%S+)"))
    assert.is_true(helpers.relerr(total, refs().total) <= 1e-15, out:sub(-300))
  end)
end)
