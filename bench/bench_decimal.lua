-- bench/bench_decimal.lua -- SVG's numbers read by arclen (src/svg/decimal.c:
-- the fast path, else decimal_exact.c) against Lua's tonumber (the C
-- library's strtod in the C locale) on the same strings: CPU time per number,
-- best of 5, and the ratio.  Classes: few digits (the fast path), 17
-- significant digits (what %.17g and the shapes' path data write) near 1,
-- 17 digits at exponents of +-300, and the hard rows of
-- spec/data/decimal_hard.tsv (halfway points, hundreds of digits).
--   LUA_CPATH='build/5.4/?.so' lua5.4 bench/bench_decimal.lua
local svg_number = require("arclen.core").svg_number

local seed = 12345
local function rnd()
  seed = (seed * 1103515245 + 12345) % 2147483648
  return seed / 2147483648
end

local function make(n, fmt, scale)
  local out = {}
  for i = 1, n do
    local e = scale and (i % 2 == 0 and scale or -scale) or 0
    out[i] = fmt:format((rnd() + 0.1) * 10 ^ e)
  end
  return out
end

local function hard()
  local out = {}
  for line in io.lines("spec/data/decimal_hard.tsv") do
    local kind, text = line:match("^([^\t#]+)\t([^\t]+)")
    if kind and kind ~= "kind" then out[#out + 1] = text end
  end
  return out
end

local function best(list, f)
  local t = math.huge
  for _ = 1, 5 do
    local c = os.clock()
    for i = 1, #list do f(list[i]) end
    t = math.min(t, os.clock() - c)
  end
  return t / #list * 1e9
end

print(("%-34s %10s %10s %7s"):format("numbers", "arclen ns", "strtod ns", "ratio"))
for _, c in ipairs({{"6 digits", make(40000, "%.6g")},
                    {"17 digits near 1", make(40000, "%.17g")},
                    {"17 digits, 1e+300 and 1e-300", make(20000, "%.17g", 300)},
                    {"decimal_hard.tsv rows", hard()}}) do
  local a = best(c[2], function(s) return svg_number(s, 1) end)
  local s = best(c[2], function(t) return tonumber(t) end)
  print(("%-34s %10.0f %10.0f %7.2f"):format(c[1], a, s, a / s))
end
