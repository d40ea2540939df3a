-- arclen.pure_svgpath -- SVG path data for the Lua engine: the grammar of
-- SVG 1.1 section 8.3.9 as SVG 2 section 9.3.9 reads it (commands M L H V
-- C S Q T Z, lower case relative, repeated argument lists, numbers
-- separated by whitespace and at most one comma or by their own signs and
-- dots), with the C reader's result and messages (src/svg/pathdata.c).
-- Lines become cubics with the control points at thirds, quadratics are
-- degree-elevated (the same curves).  Elliptical arcs (A) need the conics
-- of the C core: they raise an error that says so.
--
-- svg_pathdata(d, arc_tol [, T]) -> {packed = {x0, y0, ..., 8 numbers a
-- cubic}, n = cubics, [j] = {x =, y =, closed =, n =}}; or nil, message,
-- byte position.  (The C reader packs the cubics in a string of doubles;
-- here they are a flat table, which the Lua engine's functions take.)
local M = {}

local format, byte, sub, find = string.format, string.byte, string.sub, string.find
local huge = math.huge

local ARGS = {M = 2, L = 2, T = 2, H = 1, V = 1, C = 6, S = 4, Q = 4, A = 7, Z = 0}
local NAMES = {M = {"x", "y"}, L = {"x", "y"}, T = {"x", "y"}, H = {"x"}, V = {"y"},
  C = {"x1", "y1", "x2", "y2", "x", "y"}, S = {"x2", "y2", "x", "y"},
  Q = {"x1", "y1", "x", "y"}, A = {"rx", "ry", "x-axis-rotation", "large-arc-flag",
  "sweep-flag", "x", "y"}}

-- The decimal point of the C locale, whatever the host's (Lua 5.1's
-- tonumber follows LC_NUMERIC): a token tonumber refuses is read again
-- with the locale's point.
local function to_number(tok)
  local v = tonumber(tok)
  if v == nil then
    local point = format("%.1f", 0.5):sub(2, 2)
    v = tonumber((tok:gsub("%.", point)))
  end
  return v and v * 1.0
end

local function what(d, i)
  if i > #d then return "the end of the data" end
  return "'" .. sub(d, i, i) .. "'"
end

-- lauxlib's checks, as the C binding makes them (src/lua/svg.c).
local function check_args(d, arc_tol, T)
  local function argerror(n, msg)
    error(format("bad argument #%d to 'svg_pathdata' (%s)", n, msg), 0)
  end
  if type(d) == "number" then d = tostring(d)
  elseif type(d) ~= "string" then argerror(1, "string expected, got " .. type(d)) end
  if type(arc_tol) ~= "number" and not (type(arc_tol) == "string" and tonumber(arc_tol)) then
    argerror(2, "number expected, got " .. type(arc_tol))
  end
  if T ~= nil then
    if type(T) ~= "table" or #T ~= 6 then argerror(3, "transform must be {a, b, c, d, e, f}") end
    for k = 1, 6 do
      local v = T[k]
      if type(v) ~= "number" or v ~= v or v == huge or v == -huge then
        argerror(3, "transform entries must be finite numbers")
      end
    end
  end
  return d
end

function M.svg_pathdata(d, arc_tol, T)
  d = check_args(d, arc_tol, T)
  local n = #d
  local packed, subpaths, nc = {}, {}, 0
  local sp = nil                      -- the open subpath
  local cx, cy, sx, sy = 0, 0, 0, 0   -- current point, subpath start
  local lcx, lcy, lqx, lqy, lastc, lastq = 0, 0, 0, 0, false, false

  local function skip_space(i)
    local _, e = find(d, "^[ \t\n\r\f]*", i)
    return e + 1
  end
  local function skip_sep(i)
    i = skip_space(i)
    if sub(d, i, i) == "," then i = skip_space(i + 1) end
    return i
  end
  local function open(x, y)
    sp = {x = x, y = y, closed = false, n = 0}
    subpaths[#subpaths + 1] = sp
  end
  local function cubic(x0, y0, x1, y1, x2, y2, x3, y3)
    local k = 8 * nc
    packed[k + 1], packed[k + 2], packed[k + 3], packed[k + 4] = x0, y0, x1, y1
    packed[k + 5], packed[k + 6], packed[k + 7], packed[k + 8] = x2, y2, x3, y3
    nc = nc + 1
    sp.n = sp.n + 1
  end
  local function line(x0, y0, x1, y1)
    local dx, dy = x1 - x0, y1 - y0
    cubic(x0, y0, x0 + dx / 3, y0 + dy / 3, x1 - dx / 3, y1 - dy / 3, x1, y1)
  end

  -- The number at i (argument k of cmd): value and the index after it,
  -- or nil, message, position.
  local function number(i, cmd, k)
    local _, e = find(d, "^[+-]?%d*", i)
    local _, f = find(d, "^%.%d*", e + 1)
    local digits = sub(d, i, f or e):find("%d")
    if not digits then
      return nil, format("expected a number (%s %s), got %s", cmd, NAMES[cmd][k], what(d, i)), i
    end
    e = f or e
    if find(d, "^[eE]", e + 1) then
      local _, x = find(d, "^[eE][+-]?%d+", e + 1)
      if not x then return nil, "exponent without digits in a number", e + 1 end
      e = x
    end
    local tok = sub(d, i, e)
    local v = to_number(tok)
    if not (v and v > -huge and v < huge) then
      return nil, format("number out of range '%s'", tok), i
    end
    return v, e + 1
  end

  local i = skip_space(1)
  if i > n then return nil, "path data is empty", 1 end
  local cmd, rel = nil, false
  for _ = 1, n + 1 do                 -- each turn reads at least one byte
    if i > n then break end
    local c = sub(d, i, i)
    local up = c:upper()
    local cmdpos = i
    if c:find("^%a$") and ARGS[up] then
      if cmd == nil and up ~= "M" then
        return nil, "path data must begin with a moveto (M or m), got " .. what(d, i), i
      end
      cmd, rel = up, c ~= up
      i = skip_space(i + 1)
    elseif cmd == nil then
      return nil, "path data must begin with a moveto (M or m), got " .. what(d, i), i
    elseif cmd == "Z" then
      return nil, "expected a command after Z, got " .. what(d, i), i
    elseif not c:find("^[%d%.+-]$") then
      return nil, "unknown command " .. what(d, i), i
    end
    if cmd == "Z" then
      if not sp then return nil, "closepath before any moveto", cmdpos end
      if cx ~= sx or cy ~= sy then line(cx, cy, sx, sy) end
      sp.closed = true
      cx, cy, sp = sx, sy, nil
      lastc, lastq = false, false
      i = skip_space(i)
    else
      if cmd == "A" then
        return nil, "elliptical arc: arcs need the C core (arclen.core), which is not "
          .. "loaded: in plain Lua build it (make, or luarocks make); in LuaTeX run "
          .. "lualatex --shell-escape", cmdpos
      end
      local a = {}
      for k = 1, ARGS[cmd] do
        if k > 1 then i = skip_sep(i) end
        local v, nxt, pos = number(i, cmd, k)
        if not v then return nil, nxt, pos end
        a[k], i = v, nxt
      end
      local ox, oy = rel and cx or 0, rel and cy or 0
      local x, y
      if cmd == "M" then
        cx, cy = a[1] + ox, a[2] + oy
        sx, sy = cx, cy
        open(cx, cy)
        cmd = "L"                     -- further pairs are implicit linetos
        lastc, lastq = false, false
      else
        if not sp then open(cx, cy) end   -- drawing after Z
        if cmd == "L" then
          x, y = a[1] + ox, a[2] + oy
          line(cx, cy, x, y)
        elseif cmd == "H" then
          x, y = a[1] + (rel and cx or 0), cy
          line(cx, cy, x, y)
        elseif cmd == "V" then
          x, y = cx, a[1] + (rel and cy or 0)
          line(cx, cy, x, y)
        elseif cmd == "C" or cmd == "S" then
          local x1, y1, x2, y2
          if cmd == "C" then
            x1, y1, x2, y2 = a[1] + ox, a[2] + oy, a[3] + ox, a[4] + oy
            x, y = a[5] + ox, a[6] + oy
          else
            if lastc then x1, y1 = 2 * cx - lcx, 2 * cy - lcy else x1, y1 = cx, cy end
            x2, y2, x, y = a[1] + ox, a[2] + oy, a[3] + ox, a[4] + oy
          end
          cubic(cx, cy, x1, y1, x2, y2, x, y)
          lcx, lcy = x2, y2
        else                          -- Q, T
          local qx, qy
          if cmd == "Q" then
            qx, qy, x, y = a[1] + ox, a[2] + oy, a[3] + ox, a[4] + oy
          else
            if lastq then qx, qy = 2 * cx - lqx, 2 * cy - lqy else qx, qy = cx, cy end
            x, y = a[1] + ox, a[2] + oy
          end
          cubic(cx, cy, cx + 2.0 / 3 * (qx - cx), cy + 2.0 / 3 * (qy - cy),
                x + 2.0 / 3 * (qx - x), y + 2.0 / 3 * (qy - y), x, y)
          lqx, lqy = qx, qy
        end
        lastc, lastq = cmd == "C" or cmd == "S", cmd == "Q" or cmd == "T"
        cx, cy = x, y
      end
      i = skip_sep(i)
      -- a trailing comma must be followed by another argument list
      if sub(d, i - 1, i - 1) == "," and (i > n or sub(d, i, i):find("^%a$")) then
        return nil, "comma not followed by a number", i - 1
      end
    end
  end
  if T then                           -- an affine map: the cubics' images
    local A, B, C, D, E, F = T[1], T[2], T[3], T[4], T[5], T[6]
    for _, s in ipairs(subpaths) do
      s.x, s.y = A * s.x + C * s.y + E, B * s.x + D * s.y + F
    end
    for k = 1, 4 * nc do
      local x, y = packed[2 * k - 1], packed[2 * k]
      local u, v = A * x + C * y + E, B * x + D * y + F
      if not (u > -huge and u < huge and v > -huge and v < huge) then
        return nil, "the transform takes a coordinate out of range"
      end
      packed[2 * k - 1], packed[2 * k] = u, v
    end
  end
  subpaths.packed, subpaths.n = packed, nc
  return subpaths
end

return M
