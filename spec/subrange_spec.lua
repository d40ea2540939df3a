-- Short sub-ranges next to (near) cusps against tools/ref_subranges.py
-- (mpmath and decimal at 85+ digits): the length of [t0, t1] must keep its
-- own relative precision however small it is against the whole curve's --
-- the speed there is a small difference of large terms, so a method has to
-- form it about the sub-range (the default method's bounds: tol at
-- 1e-12, 1e-14 at 1e-15; the elliptic method's: 1e-13).
local arclen = require("arclen")
local H = require("helpers")

local rows = H.tsv("subranges.tsv")

local function coords(row)
  return H.numbers(row.coords)
end

-- The Lua engine measures plane cubics: its run takes the 2D rows (3D
-- needs the C core), and says so in the specs' names.
local only2d = H.engine == "lua"
local NOTE = only2d and " [Lua engine: the 2D rows; 3D needs the C core]" or ""

local function check(opts, bound)
  local worst, n = H.worst(), 0
  for _, row in ipairs(rows) do
    local c = coords(row)
    if not (only2d and #c ~= 8) then
      local o = {t0 = tonumber(row.t0), t1 = tonumber(row.t1)}
      for k, v in pairs(opts) do o[k] = v end
      worst:add(H.relerr(arclen.length(c, o), tonumber(row.L)),
                ("%s [%s, %s]"):format(row.id, row.t0, row.t1))
      n = n + 1
    end
  end
  assert.is_true(n >= 200, "rows measured: " .. n)
  assert.is_true(worst.err <= bound,
    ("worst %s: %.3g > %.3g"):format(tostring(worst.id), worst.err, bound))
end

describe("sub-ranges next to cusps (" .. #rows .. " ranges 1e-2 .. 1e-14 wide)", function()
  it("has the reference rows", function()
    assert.is_true(#rows >= 200)
  end)
  it("default method, tol 1e-12: relative error <= 1e-12" .. NOTE, function()
    check({tol = 1e-12}, 1e-12)
  end)
  it("default method, tol 1e-15: relative error <= 1e-14" .. NOTE, function()
    check({tol = 1e-15}, 1e-14)
  end)
  H.c_only(it, "method 'elliptic'")("elliptic: relative error <= 1e-13", function()
    check({method = "elliptic"}, 1e-13)
  end)
end)
