-- SVG's numbers to doubles (src/svg/decimal.c, decimal_exact.c), bit for
-- bit against tools/ref_decimal.py (exact rounding of the text as a
-- fraction, checked there against Python's float()): halfway points
-- between doubles and one digit past them, mantissas of hundreds of
-- digits, subnormals, the ends of the range, random numbers.  Reached as
-- users reach it: the moveto of path data (arclen.svg_pathdata, the reader
-- of arclen.path.svg) and arclen.svg_number (the documents' attributes).
local core = require("arclen.core")
local helpers = require("helpers")

-- 2^e exactly: powers of two are doubles from 2^-1074 to 2^1023, and
-- each step of the loop is exact.
local function pow2(e)
  local v, f = 1.0, e < 0 and 0.5 or 2.0
  for _ = 1, math.abs(e) do v = v * f end
  return v
end

-- The row's double: sign * m * 2^e (m < 2^53 odd, so the product is exact).
local function expected(row)
  if row.m == "inf" then return row.sign == "-" and -math.huge or math.huge end
  local v = (tonumber(row.m) + 0.0) * pow2(tonumber(row.e))
  if row.sign == "-" then v = -v end
  return v
end

-- The same double: == and, for zero, the same sign (5.1 has no %a).
local function same(a, b)
  return a == b and (a ~= 0 or 1 / a == 1 / b)
end

local function show(row)
  local t = row.text
  if #t > 60 then t = t:sub(1, 30) .. "..." .. t:sub(-25) .. " (" .. #t .. " chars)" end
  return row.kind .. " " .. t .. " -> " .. row.hex
end

-- Each row through path data and through svg_number; the failures listed.
local function check(file)
  local rows = helpers.tsv(file)
  local bad = {}
  for _, row in ipairs(rows) do
    local want = expected(row)
    local sub, msg = core.svg_pathdata("M" .. row.text .. " 0", 1e-9)
    local v, next = core.svg_number(row.text, 1)
    if want == math.huge or want == -math.huge then
      -- beyond the doubles: path data rejects it, the scanner finds none
      if sub ~= nil or not tostring(msg):find("number out of range", 1, true) then
        bad[#bad + 1] = show(row) .. ": path data accepted it"
      end
      if v ~= nil then bad[#bad + 1] = show(row) .. ": svg_number gave " .. tostring(v) end
    else
      if sub == nil then
        bad[#bad + 1] = show(row) .. ": path data: " .. tostring(msg)
      elseif sub[1].x ~= want then    -- by ==: points drop the sign of zero
        bad[#bad + 1] = ("%s: path data gave %.17g"):format(show(row), sub[1].x)
      end
      if not (v and same(v, want) and next == #row.text + 1) then
        bad[#bad + 1] = ("%s: svg_number gave %s, next %s"):format(show(row),
          v and ("%.17g"):format(v) or "nil", tostring(next))
      end
    end
  end
  return #rows, bad
end

describe("SVG numbers read as the nearest double, bit for bit", function()
  for _, file in ipairs({"decimal_hard.tsv", "decimal_random.tsv"}) do
    it(file, function()
      local n, bad = check(file)
      assert.is_true(n > 800, file .. ": too few rows")
      assert.are.equal(0, #bad, #bad .. " of " .. n .. " wrong:\n"
        .. table.concat(bad, "\n", 1, math.min(#bad, 20)))
    end)
  end

  it("the check can fail: a double one unit off is told apart", function()
    local x = core.svg_number("0.1", 1)
    assert.is_false(same(x, 0.1 + 2 ^ -56 * 2))
    assert.is_false(same(core.svg_number("-0", 1), 0.0))
  end)
end)
