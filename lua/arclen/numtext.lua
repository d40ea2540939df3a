-- arclen.numtext -- numbers as text and back, the same in every locale.
--
-- The C library's printf and strtod follow LC_NUMERIC, and so does Lua on
-- top of them: after os.setlocale("de_DE.UTF-8", "numeric") Lua 5.1-5.4
-- print 1.5 as "1,5" (string.format's %g/%f/%e, tostring, ..), Lua 5.1's
-- tonumber("1.5") is nil, and 5.3+ take "1,5" as well as "1.5" (but no
-- number of more than 200 characters with a '.').  LuaJIT formats and
-- scans numbers itself, in the C locale.  Every number arclen's Lua layer
-- writes as data or reads from text goes through here:
--   format(fmt, ...)  string.format with '.' as the decimal point of %e %f
--                     %g %a (and of numbers given to %s)
--   tostring(x)       tostring, with '.'
--   g17(x)            "%.17g": the double itself
--   format_now(fmt)   a format(fmt, ...) for a loop in which the locale stays
--   shortest(x)       the shortest of %.15g, %.16g, %.17g that reads back as x
--   tonumber(s)       a decimal number (SVG's grammar, surrounded by
--                     whitespace) or a hexadecimal integer, nil for anything
--                     else, "1,5" included; decimals correctly rounded by
--                     arclen's own reader (src/svg/decimal.c), or under
--                     the Lua engine by Lua's (strtod's) with the
--                     locale's decimal point put in
local M = {}

local sformat, find, sub, match, huge = string.format, string.find, string.sub,
  string.match, math.huge
local ltostring, ltonumber, select, type = tostring, tonumber, select, type

-- The decimal point printf writes now ("." in the C locale, "," in
-- de_DE): the locale may change at any time, so it is asked each time.
local function point()
  return sub(sformat("%.1f", 0.5), 2, -2)
end

-- s with the locale's decimal point p (there is at most one) as '.'.
local function dot(s, p)
  local i, j = find(s, p, 1, true)
  if not i then return s end
  return sub(s, 1, i - 1) .. "." .. sub(s, j + 1)
end

function M.tostring(x)
  if type(x) ~= "number" then return ltostring(x) end
  local p = point()
  return p == "." and ltostring(x) or dot(ltostring(x), p)
end

local FLOAT_CONV = {e = true, E = true, f = true, F = true, g = true, G = true,
                    a = true, A = true}

function M.format(fmt, ...)
  local p = point()
  if p == "." then return sformat(fmt, ...) end
  local args, nargs = {...}, select("#", ...)
  local out, pos, k = {}, 1, 0
  while true do
    local i, j, spec, conv = find(fmt, "%%([-+ #0]*%d*%.?%d*)([%a%%])", pos)
    if not i then break end
    out[#out + 1] = sub(fmt, pos, i - 1)
    if conv == "%" then
      out[#out + 1] = "%"
    else
      k = k + 1
      if k > nargs then return sformat(fmt, ...) end     -- Lua's own error
      local a = args[k]
      if FLOAT_CONV[conv] then
        out[#out + 1] = dot(sformat("%" .. spec .. conv, a), p)
      elseif conv == "s" and type(a) == "number" then
        out[#out + 1] = sformat("%" .. spec .. "s", dot(ltostring(a), p))
      else
        out[#out + 1] = sformat("%" .. spec .. conv, a)
      end
    end
    pos = j + 1
  end
  out[#out + 1] = sub(fmt, pos)
  return table.concat(out)
end

function M.g17(x) return M.format("%.17g", x) end

-- format(fmt, ...) as a function, for a loop that does not change the
-- locale (the command line's rows): the decimal point asked once, here,
-- not for each number (that doubled the cost of a row).
function M.format_now(fmt)
  if point() == "." then return function(...) return sformat(fmt, ...) end end
  return function(...) return M.format(fmt, ...) end
end

-- The end of a decimal number of SVG's grammar at s[i], or nil.
local function decimal_end(s, i)
  local e = match(s, "^[+-]?%d+%.?%d*()", i) or match(s, "^[+-]?%.%d+()", i)
  if not e then return nil end
  return match(s, "^[eE][+-]?%d+()", e) or e
end

function M.tonumber(s)
  if type(s) == "number" then return s end
  if type(s) ~= "string" then return nil end
  local body = match(s, "^%s*(.-)%s*$")
  if find(body, "^[+-]?%d+$") or find(body, "^[+-]?0[xX]%x+$") then
    return ltonumber(body)            -- integers: no decimal point to misread
  end
  if decimal_end(body, 1) ~= #body + 1 then return nil end
  -- required here, not on loading: cli.lua run as a script sets
  -- package.cpath after its own requires
  local engine = require("arclen.engine")
  if engine.engine ~= "c" then
    -- the Lua engine (no C core): Lua's own reader, strtod's correct
    -- rounding, given the locale's decimal point for SVG's '.'
    local p = point()
    return ltonumber(p == "." and body or (body:gsub("%.", p)))
  end
  local v, e = engine.svg_number(body, 1)
  if v == nil then                     -- beyond the doubles, as tonumber
    return sub(body, 1, 1) == "-" and -huge or huge
  end
  return e == #body + 1 and v or nil
end

local G = {"%.15g", "%.16g", "%.17g"}

function M.shortest(x)
  -- in the C locale (LuaJIT: always) Lua's own format and tonumber serve
  local fast = point() == "."
  for i = 1, 3 do
    local t = fast and sformat(G[i], x) or M.format(G[i], x)
    if (fast and ltonumber(t) or M.tonumber(t)) == x then return t end
  end
  return M.g17(x)
end

return M
