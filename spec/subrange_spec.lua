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
  local c = {}
  for v in row.coords:gmatch("%S+") do c[#c + 1] = assert(tonumber(v)) end
  return c
end

local function check(opts, bound)
  local worst = H.worst()
  for _, row in ipairs(rows) do
    local o = {t0 = tonumber(row.t0), t1 = tonumber(row.t1)}
    for k, v in pairs(opts) do o[k] = v end
    local got = arclen.length(coords(row), o)
    worst:add(H.relerr(got, tonumber(row.L)), ("%s [%s, %s]"):format(row.id, row.t0, row.t1))
  end
  assert.is_true(worst.err <= bound,
    ("worst %s: %.3g > %.3g"):format(tostring(worst.id), worst.err, bound))
end

describe("sub-ranges next to cusps (" .. #rows .. " ranges 1e-2 .. 1e-14 wide)", function()
  it("has the reference rows", function()
    assert.is_true(#rows >= 200)
  end)
  it("default method, tol 1e-12: relative error <= 1e-12", function()
    check({tol = 1e-12}, 1e-12)
  end)
  it("default method, tol 1e-15: relative error <= 1e-14", function()
    check({tol = 1e-15}, 1e-14)
  end)
  it("elliptic: relative error <= 1e-13", function()
    check({method = "elliptic"}, 1e-13)
  end)
end)
