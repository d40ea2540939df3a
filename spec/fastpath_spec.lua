-- The default method keeps a fast path beside its general one for speed:
-- a plain call (no report) takes length_fast or the first pieces' orders
-- straight from the branch points (arclen_cut_orders); a call with
-- {info = true} takes the pieces' cut records (cut_prepare, cut_bound,
-- cut_order) and the stack.  Both are one algorithm: the same pieces, the
-- same orders, the same sums in the same order, so the results must agree
-- to the bit -- lengths (2D, 3D, sub-ranges) and times.
local arclen = require("arclen")

local rng = require("helpers").rng   -- the same curves under every Lua

local function curves(n, dim, seed)
  local r, out = rng(seed), {}
  for i = 1, n do
    local c = {}
    for k = 1, 4 * dim do c[k] = 10 * r() - 5 end
    if i % 7 == 3 then                      -- near-cusps: P1 ~ P2
      for k = 1, dim do c[dim + k] = c[2 * dim + k] + 1e-3 * r() end
    elseif i % 11 == 5 then                 -- a control point on its end
      for k = 1, dim do c[dim + k] = c[k] + 1e-7 * r() end
    end
    out[i] = c
  end
  return out, r
end

-- The same double: == but for NaN and the sign of zero (5.1 has no %a).
local function same(a, b)
  if a ~= a then return b ~= b end
  return a == b and (a ~= 0 or 1 / a == 1 / b)
end

local function same_lengths(dim, tol, ranged)
  local cs, r = curves(400, dim, ranged and 977 or 4711)
  for i, c in ipairs(cs) do
    local o1, o2 = {tol = tol}, {tol = tol, info = true}
    if ranged then
      local a, b = r(), r()
      o1.t0, o1.t1, o2.t0, o2.t1 = a, b, a, b
    end
    local plain = arclen.length(c, o1)
    local general = arclen.length(c, o2)
    assert.is_true(same(general, plain), ("curve %d: %.17g plain, %.17g general"):format(i, plain, general))
  end
end

local function same_times(dim, tol)
  local cs, r = curves(300, dim, 31337)
  for i, c in ipairs(cs) do
    local s = arclen.length(c, {tol = tol}) * (1.1 * r() - 0.05)
    local plain = arclen.time(c, s, {tol = tol})
    local general = arclen.time(c, s, {tol = tol, info = true})
    assert.is_true(same(general, plain),
      ("curve %d, s %.17g: %.17g plain, %.17g general"):format(i, s, plain, general))
  end
end

describe("the default method's fast and general paths agree to the bit", function()
  for _, tol in ipairs({1e-9, 1e-12, 1e-15}) do
    it("2D lengths, tol " .. tol, function() same_lengths(2, tol, false) end)
    it("3D lengths, tol " .. tol, function() same_lengths(3, tol, false) end)
    it("2D sub-ranges, tol " .. tol, function() same_lengths(2, tol, true) end)
    it("3D sub-ranges, tol " .. tol, function() same_lengths(3, tol, true) end)
    it("2D times, tol " .. tol, function() same_times(2, tol) end)
    it("3D times, tol " .. tol, function() same_times(3, tol) end)
  end
end)
