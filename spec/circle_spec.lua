-- spec/circle_spec.lua -- circular arcs measured in closed form
-- (src/segment/conic_circle.c, the conic segment's fast branch): against
-- mpmath (spec/data/conic_circle.tsv, tools/ref_circle.py: spans from
-- 1e-6 to pi - 1e-6, radii from 1e-200 to 1e200, a drawing's quarters far
-- from the origin, ellipses about the gate) and against the general path,
-- arclen_conic_length.
local helpers = require("helpers")
local arclen = require("arclen")
-- the closed form is the C core's (the Lua engine measures every conic
-- by its general path): its branch and bounds are checked there, the Lua
-- engine's lengths against the references
local C = helpers.engine == "c"
local c_it = C and it or function() end

local function conic(row)
  return {tonumber(row.x0), tonumber(row.y0), tonumber(row.x1), tonumber(row.y1),
          tonumber(row.x2), tonumber(row.y2), tonumber(row.w)}
end

describe("circular arcs in closed form", function()
  c_it("within 4 ulps (4.5e-16) of mpmath, and taken for every circle", function()
    local worst, n = helpers.worst(), 0
    for _, row in ipairs(helpers.tsv("conic_circle.tsv")) do
      local c = conic(row)
      local L, info = arclen.segment_length("conic", c, {info = true})
      if not row.name:find("^ellipse") and not row.name:find("^short arc") then
        assert.are.equal("circle", info.branch, row.name)
      end
      if info.branch == "circle" then
        worst:add(helpers.relerr(L, tonumber(row.length)), row.name)
        n = n + 1
      end
    end
    print(("\n  circular arcs: worst relative error %.2e (%s), %d arcs in closed form"):format(worst.err, worst.id, n))
    assert.is_true(worst.err <= 4.5e-16, worst.id .. ": " .. worst.err)
  end)
  c_it("the gate: ellipses of axes 1 and 1 + 2^-26 or more take the general path, 1 + 2^-30 or less the closed form", function()
    local seen = 0
    for _, row in ipairs(helpers.tsv("conic_circle.tsv")) do
      local k, span = row.name:match("^ellipse 1%+2%^%-(%d+) span (%S+)")
      if k and tonumber(k) <= 26 then
        local _, info = arclen.segment_length("conic", conic(row), {info = true})
        assert.are.equal("ellipse", info.branch, row.name)
        seen = seen + 1
      elseif k and tonumber(k) >= 30 then
        local _, info = arclen.segment_length("conic", conic(row), {info = true})
        assert.are.equal("circle", info.branch, row.name)
      end
    end
    assert.are.equal(12, seen)
    -- short arcs: the gate is D sin(al) <= 2^-30, so an ellipse of 1 + 2^-10
    -- takes the closed form over a span of 1e-6, not of 1e-5
    for _, row in ipairs(helpers.tsv("conic_circle.tsv")) do
      if row.name:find("^short arc") then
        local _, info = arclen.segment_length("conic", conic(row), {info = true})
        local want = row.name == "short arc of 1+2^-10 span 1e-05" and "ellipse" or "circle"
        assert.are.equal(want, info.branch, row.name)
        seen = seen + 1
      end
    end
    assert.are.equal(16, seen)
  end)
  c_it("equal to the general path within both bounds (1e-15)", function()
    local worst = helpers.worst()
    for _, row in ipairs(helpers.tsv("conic_circle.tsv")) do
      local c = conic(row)
      local ok, G = pcall(arclen.conic_length, {c[1], c[2]}, {c[3], c[4]}, {c[5], c[6]}, c[7])
      if ok then worst:add(helpers.relerr(arclen.segment_length("conic", c), G), row.name) end
    end
    assert.is_true(worst.err <= 1e-15, worst.id .. ": " .. worst.err)
  end)
  if not C then
    it("the Lua engine: its general path within 1e-14 of mpmath", function()
      local worst = helpers.worst()
      for _, row in ipairs(helpers.tsv("conic_circle.tsv")) do
        worst:add(helpers.relerr(arclen.segment_length("conic", conic(row)), tonumber(row.length)), row.name)
      end
      assert.is_true(worst.err <= 1e-14, worst.id .. ": " .. worst.err)
    end)
  end
  it("a sub-arc of a circle is a circle: its lengths add up", function()
    local c = {3, 0, 3, 3, 0, 3, math.sqrt(0.5)}          -- a quarter of radius 3
    local whole = arclen.segment_length("conic", c)
    local a = arclen.segment_length("conic", c, {t0 = 0, t1 = 0.3})
    local b = arclen.segment_length("conic", c, {t0 = 0.3, t1 = 1})
    assert.is_true(helpers.relerr(a + b, whole) <= 4e-16)
    assert.is_true(helpers.relerr(whole, 1.5 * math.pi) <= 2.3e-16)
  end)
end)
