-- The default method's inverse is one sweep for arclen.time and
-- arclen.times (src/gauss/time.c): the pieces walked in increasing t, by
-- the first pieces' orders straight from the branch points when all of
-- them are to be had, else by the integrator's stack; in a piece the
-- searches chain from the last point evaluated, whose s is a compensated
-- sum.  These check the stack's curves and a long run of distances.
local arclen = require("arclen")
local H = require("helpers")

-- The same double: == but for NaN and the sign of zero (5.1 has no %a).
local function same(a, b)
  if a ~= a then return b ~= b end
  return a == b and (a ~= 0 or 1 / a == 1 / b)
end

local function speed(c, t)
  local d = {arclen.derivative(c, t)}
  local s = 0
  for _, v in ipairs(d) do s = s + v * v end
  return math.sqrt(s)
end

-- |s(t) - s(T)| <= |t - T| max speed (as times_spec.lua).
local function ds(c, t, T)
  return math.abs(t - T) * math.max(speed(c, t), speed(c, T))
end

describe("the inverse's sweep", function()
  -- Near-cusp curves whose later first pieces' orders are not to be had
  -- (found by a scan of random curves at tol 1e-12), at distances past the
  -- first piece: the plain call takes the stack as {info = true} does.
  local no_orders = {
    {{0.60154331709937736, 2.3183290209762877, -2.1736824062716229, 3.111621161943642,
      4.2691572013611605, 1.889374574583762, -1.8694806614378354, -2.4221437358533593}, 0.383},
    {{-2.8452790681099138, -3.3737966347346546, -2.5486605223054792, -4.1536770271341314,
      -4.5926158521472269, 1.83842846600065, 1.4623628940823359, 3.5348104769290032}, 0.688},
    {{0.063912131415930773, 0.36173334329698825, 4.6490025600607634, -0.023488788899623358,
      -3.9448365064106063, 0.17552628298335549, 2.3139145780353871, 3.4313783697901208}, 0.522},
    {{-3.1641382574815813, 1.0596027846273053, -4.5806651422029701, 3.7285128671651648,
      2.8122723807299437, 4.9171181394927714, 0.93786332274249951, 4.5474552522764107}, 0.491},
  }

  it("takes the stack where the first pieces' orders fail, as the report does, to the bit", function()
    for i, case in ipairs(no_orders) do
      local c, u = case[1], case[2]
      local L = arclen.length(c, {tol = 1e-12})
      for _, f in ipairs({u - 0.01, u, u + 0.01}) do
        local plain = arclen.time(c, f * L, {tol = 1e-12})
        local general = arclen.time(c, f * L, {tol = 1e-12, info = true})
        assert.is_true(same(general, plain),
          ("curve %d at %.3f L: %.17g plain, %.17g general"):format(i, f, plain, general))
      end
    end
  end)

  -- A long run of distances: 10^5 of them (2000 on the Lua engine),
  -- evenly spaced, at tol 1e-15, against one arclen.time each.  The
  -- binding hands arclen_times 256 at a time, each run a chain of searches
  -- from the last one's points; the chains add no error of their own: the
  -- two agree to what two searches do (worst 2.2e-16 and 1.9e-16 L on the
  -- C core), a tenth of the guarantee's 1e-14 bounds them.  (In C, one call with 10^6
  -- distances: worst 4.8e-16 L; with plain sums for the carried s values,
  -- no TwoSum, 1.5e-14 -- measured 2026-12-03.)
  it("keeps a long chain of distances within a tenth of tol L", function()
    local k = H.engine == "c" and 100000 or 2000
    for _, c in ipairs({{0, 0, 10, 0, 10, 10, 0, 0}, {0, 0, 1, 3, 2, -3, 3, 0}}) do
      local L = arclen.length(c, {tol = 1e-15})
      local s = {}
      for q = 1, k do s[q] = L * (q - 0.5) / k end
      local ts = arclen.times(c, s, {tol = 1e-15})
      local worst, at = 0, 0
      for q = 1, k, H.engine == "c" and 7 or 1 do
        local e = ds(c, ts[q], arclen.time(c, s[q], {tol = 1e-15})) / L / 2
        if e > worst then worst, at = e, q end
      end
      assert.is_true(worst <= 1e-15, ("worst %.3g L at distance %d"):format(worst, at))
    end
  end)
end)
