-- Carlson's R-functions (src/carlson.c) against mpmath (tools/ref_carlson.py)
-- and the check values published in Carlson (1995), arXiv math/9409227.
-- Errors are measured against the 30-digit reference as (got - hi) - lo,
-- where hi + lo is the reference split into two doubles, so the bound in
-- eps is the function's own error, not the reference's rounding.
local arclen = require("arclen")
local H = require("helpers")
local R = arclen.carlson
local EPS = 2.0 ^ -52

local function args(row)
  local a = {}
  for _, k in ipairs({"x", "y", "z", "p"}) do
    if row[k] ~= "" then a[#a + 1] = assert(tonumber(row[k]), k) end
  end
  return a
end

-- Relative error in units of eps.
local function err_eps(got, row)
  local hi, lo = tonumber(row.ref), tonumber(row.lo)
  if hi == 0 then return got == 0 and 0 or math.huge end
  return math.abs((got - hi) - lo) / math.abs(hi) / EPS
end

describe("carlson", function()
  local checks = H.tsv("carlson_checks.tsv")

  it("reproduces Carlson (1995)'s real-argument check values (14 printed digits)", function()
    assert.are.equal(15, #checks)
    for _, row in ipairs(checks) do
      local got = R[row.fn](table.unpack(args(row)))
      assert.is_true(H.relerr(got, tonumber(row.published)) < 1e-13,
        row.fn .. ": " .. got .. " vs published " .. row.published)
    end
  end)

  it("check values within 5e-16 relative of mpmath", function()
    for _, row in ipairs(checks) do
      local got = R[row.fn](table.unpack(args(row)))
      local e = err_eps(got, row) * EPS
      assert.is_true(e <= 5e-16, ("%s(%s): rel. error %.3g"):format(
        row.fn, table.concat(args(row), ", "), e))
    end
  end)

  local rows = H.tsv("carlson.tsv")
  for _, fn in ipairs({"rf", "rd", "rc", "rj", "rg"}) do
    for _, kind in ipairs({"random", "zero", "pv"}) do
      local n, worst = 0, H.worst()
      -- Principal values come from a reduction (DLMF 19.20.14) that adds
      -- an R_J (<= 4 eps), an R_F and the rounding of its own parameters
      -- (t, r, products: ~4 operations): 8 eps times its condition number
      -- (sum of the terms' magnitudes over the result, from mpmath).
      local limit = kind == "pv" and 8 or 4
      local bound = kind == "pv" and "8 eps times the reduction's condition" or "4 eps"
      local function run()
        for _, row in ipairs(rows) do
          if row.fn == fn and row.kind == kind then
            n = n + 1
            local a = args(row)
            local e = err_eps(R[fn](table.unpack(a)), row)
            worst:add(e / tonumber(row.cond), table.concat(a, ", "))
          end
        end
      end
      if kind ~= "pv" or fn == "rc" or fn == "rj" then
        it(fn .. " " .. kind .. " arguments in [1e-10, 1e10]: max error <= " .. bound, function()
          run()
          assert.is_true(n >= (kind == "random" and 1800 or 200), "too few rows: " .. n)
          assert.is_true(worst.err <= limit, ("worst %s(%s): %.3g eps"):format(
            fn, tostring(worst.id), worst.err))
        end)
      end
    end
  end

  -- One argument from 1e-300 to 1e300 among O(1) ones, and vice versa
  -- (tools/ref_carlson_extreme.py, quadrature over log t).  The same
  -- duplication runs on exactly scaled arguments (powers of 4), and R_J's
  -- closed-form tail for p far above x, y, z (R_J(mu,mu,mu,p), DLMF
  -- 19.20.7) loses at most 1.1x in its subtraction, so the bars are the
  -- random rows' ones: 4 eps, principal values 8 eps times the condition.
  -- A reference below the double range (R_D ~ 1e-447) must come out 0.
  local extreme = H.tsv("carlson_extreme.tsv")
  for _, kind in ipairs({"extreme", "pv"}) do
    local limit = kind == "pv" and 8 or 4
    it(kind .. " ratios up to 1e600 (rj(1, 2, 3, 2^500), rj(1, 2, 3, 1e300), ...): max error <= "
       .. limit .. (kind == "pv" and " eps times the condition" or " eps"), function()
      local n, worst = 0, H.worst()
      for _, row in ipairs(extreme) do
        if row.kind == kind then
          n = n + 1
          local a = args(row)
          local e = err_eps(R[row.fn](table.unpack(a)), row)
          worst:add(e / tonumber(row.cond), row.fn .. "(" .. table.concat(a, ", ") .. ")")
        end
      end
      assert.is_true(n >= (kind == "pv" and 36 or 200), "too few rows: " .. n)
      assert.is_true(worst.err <= limit, ("worst %s: %.3g eps"):format(tostring(worst.id), worst.err))
    end)
  end

  -- R_J's principal value at arguments spread beyond 2^1000
  -- (tools/ref_carlson_pvwide.py, quadrature): a common power of 4 cannot
  -- hold them (the tiniest flushed to 0: rj(5.2e-202, 5.5e273, 8.1e189,
  -- -7.9e-207) was NaN, CHANGELOG's open case); the reduction now runs on
  -- the arguments as they are, each R-function narrowing its own, with its
  -- products formed as products of ratios.  Bar: as for the other principal
  -- values, 8 eps times the reduction's condition.
  it("R_J principal values spread beyond 2^1000: finite, within 8 eps x condition", function()
    local n, worst = 0, H.worst()
    for _, row in ipairs(H.tsv("carlson_pvwide.tsv")) do
      n = n + 1
      local a = args(row)
      local got = R.rj(table.unpack(a))
      assert.is_true(got == got and math.abs(got) < math.huge, "rj(" .. table.concat(a, ", ") .. ") = " .. got)
      worst:add(err_eps(got, row) / tonumber(row.cond), "rj(" .. table.concat(a, ", ") .. ")")
    end
    assert.is_true(n >= 5, "too few rows: " .. n)
    assert.is_true(worst.err <= 8, ("worst %s: %.3g eps"):format(tostring(worst.id), worst.err))
  end)

  -- Arguments anywhere in the double range, subnormals and zeros included
  -- (tools/ref_carlson_spread.py): spreads beyond 2^1000 are first narrowed
  -- by duplication steps in place (C95 (2.3)), so the exact power-of-4
  -- scaling never pushes an argument into the subnormal range: the bar is
  -- the random rows' 4 eps.  Before: rd(2.5e-237, 4e231, 1e-232) 7e-10
  -- off, rd(2.5, 4e200, 1e-300) = inf, rc(1.15e-201, -4.5e170) = 0.
  it("arguments spread over the whole double range (1e-323 .. 1e308): max error <= 4 eps", function()
    local n, worst = 0, H.worst()
    for _, row in ipairs(H.tsv("carlson_spread.tsv")) do
      n = n + 1
      local a = args(row)
      worst:add(err_eps(R[row.fn](table.unpack(a)), row), row.fn .. "(" .. table.concat(a, ", ") .. ")")
    end
    assert.is_true(n >= 200, "too few rows: " .. n)
    assert.is_true(worst.err <= 4, ("worst %s: %.3g eps"):format(tostring(worst.id), worst.err))
  end)

  it("zero arguments with a finite integral", function()
    assert.is_true(math.abs(R.rc(0, 0.25) - math.pi) <= 2 * EPS * math.pi)
    assert.are.equal(0, R.rc(0, -3))          -- principal value at x = 0
    assert.are.equal(2, R.rg(0, 0, 16))       -- R_G(0, 0, z) = sqrt(z)/2
    assert.are.equal(0, R.rg(0, 0, 0))
    assert.is_true(R.rf(0, 1, 1) > 0 and R.rd(0, 1, 1) > 0 and R.rj(0, 1, 1, 1) > 0)
  end)

  it("extreme arguments stay finite and homogeneous (no overflow, no hang)", function()
    local a = R.rf(1e-300, 2e-300, 3e-300)
    local b = R.rf(1, 2, 3)
    assert.is_true(math.abs(a / b / 1e150 - 1) < 4 * EPS)
    assert.is_true(math.abs(R.rd(1e200, 2e200, 3e200) * 1e300 / R.rd(1, 2, 3) - 1) < 4 * EPS)
    assert.is_true(math.abs(R.rj(1e-200, 2e-200, 3e-200, 4e-200) / 1e300 / R.rj(1, 2, 3, 4) - 1) < 4 * EPS)
    local v = R.rj(1e-150, 1e150, 1, 1e-100)
    assert.is_true(v > 0 and v < math.huge)
    v = R.rj(1e-200, 1e-190, 1e-180, 1e-200)
    assert.is_true(v > 0 and v < math.huge)
    v = R.rd(1e200, 1e201, 1e202)
    assert.is_true(v > 0 and v < math.huge)
  end)

  it("domain errors name the argument", function()
    -- called by name (R.rf(...)), so the message can name the function
    -- not tail calls: LuaJIT names only a function called by name from a live frame
    local call = {
      rf = function(...) local v = R.rf(...) return v end, rd = function(...) local v = R.rd(...) return v end,
      rc = function(...) local v = R.rc(...) return v end, rj = function(...) local v = R.rj(...) return v end,
      rg = function(...) local v = R.rg(...) return v end,
    }
    local function msg(f, ...) return H.error_of(call[f], ...) end
    assert.matches("bad argument #2 to 'rf' %(y must be >= 0%)", msg("rf", 1, -1, 2))
    assert.matches("bad argument #3 to 'rf' %(at most one of x, y, z may be 0", msg("rf", 1, 0, 0))
    assert.matches("bad argument #2 to 'rd' %(x and y must not both be 0", msg("rd", 0, 0, 1))
    assert.matches("bad argument #3 to 'rd' %(z must be > 0", msg("rd", 1, 1, 0))
    assert.matches("bad argument #2 to 'rc' %(y must not be 0%)", msg("rc", 1, 0))
    assert.matches("bad argument #4 to 'rj' %(p must not be 0%)", msg("rj", 1, 2, 3, 0))
    assert.matches("bad argument #1 to 'rg' %(x must be >= 0%)", msg("rg", -1, 2, 3))
    assert.matches("bad argument #1 to 'rf' %(x must be finite%)", msg("rf", 0 / 0, 1, 2))
    assert.matches("bad argument #3 to 'rj' %(z must be a number", msg("rj", 1, 2, "a", 1))
  end)
end)
