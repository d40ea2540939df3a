-- arclen.lengths / lengths3: many curves from one flat array, the same
-- lengths to the bit as one arclen.length call each, and errors that name
-- the coordinate.
local arclen = require("arclen")

-- The same double: == but for NaN and the sign of zero (5.1 has no %a).
local function same(a, b)
  if a ~= a then return b ~= b end
  return a == b and (a ~= 0 or 1 / a == 1 / b)
end

local H = require("helpers")
local rng = H.rng

describe("arclen.lengths", function()
  for _, dim in ipairs({2, 3}) do
    local it = dim == 3 and H.c_only(it, "3D curves (arclen.lengths3)") or it
    it(("equals arclen.length curve by curve (%dD, across chunks)"):format(dim), function()
      local r, flat, n = rng(42 + dim), {}, 600      -- more than one chunk of 256
      for i = 1, 4 * dim * n do flat[i] = 10 * r() end
      local f = dim == 2 and arclen.lengths or arclen.lengths3
      for _, tol in ipairs({1e-12, 1e-15}) do
        local out = f(flat, {tol = tol})
        assert.are.equal(n, #out)
        for i = 1, n do
          local c = {}
          for q = 1, 4 * dim do c[q] = flat[4 * dim * (i - 1) + q] end
          local one = arclen.length(c, {tol = tol})
          assert.is_true(same(one, out[i]), ("curve %d: %.17g, batch %.17g"):format(i, one, out[i]))
        end
      end
    end)
  end
  it("names the bad coordinate", function()
    local flat = {}
    for i = 1, 8 * 300 do flat[i] = i % 7 end
    flat[8 * 280 + 3] = "x"
    local ok, msg = pcall(arclen.lengths, flat)
    assert.is_false(ok)
    assert.matches("bad argument #1 to '[^']*' %(coordinate 2243 must be a number, got string%)", msg)
    flat[8 * 280 + 3] = 0 / 0
    ok, msg = pcall(arclen.lengths, flat)
    assert.matches("coordinate 2243 must be finite", msg)
    flat[8 * 280 + 3] = math.huge
    ok, msg = pcall(arclen.lengths, flat)
    assert.matches("coordinate 2243 must be finite", msg)
    ok, msg = pcall(arclen.lengths, {1, 2, 3})
    assert.matches("multiple of 8, got 3", msg)
  end)
  H.c_only(it, "3D curves (arclen.lengths3)")("names the bad coordinate in 3D", function()
    local ok, msg = pcall(arclen.lengths3, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, true})
    assert.is_false(ok)
    assert.matches("coordinate 12 must be a number, got boolean", msg)
  end)
end)
