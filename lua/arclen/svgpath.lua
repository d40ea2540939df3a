-- arclen.svgpath -- SVG path data (the `d` attribute, SVG 1.1 section 8.3
-- and SVG 2 section 9.3) to cubic Bezier segments.
--
-- parse(d, arc_tol) returns a list of subpaths; each is
--   {x = x0, y = y0, closed = bool, [1] = cubic, [2] = cubic, ...}
-- with every cubic a table of 8 numbers.  Lines become cubics with the
-- control points at thirds (the same curve, speed constant); quadratics are
-- degree-elevated (C1 = Q0 + 2/3 (Q1 - Q0), C2 = Q2 + 2/3 (Q1 - Q2): the same
-- curve); elliptical arcs go through arclen.svg_arc (Floater's mid-point
-- scheme) at a Hausdorff distance of at most arc_tol * max(rx, ry, chord/2).
-- Errors are raised as {pos = byte position, msg = text} tables; the caller
-- turns them into "bad argument" messages.
local arclen = require("arclen.core")

local M = {}

local byte, sub, find = string.byte, string.sub, string.find

-- Characters (bytes) of the grammar.
local SPACE = {[32] = true, [9] = true, [10] = true, [13] = true, [12] = true}
local COMMA = 44
local ARGS = {M = 2, L = 2, H = 1, V = 1, C = 6, S = 4, Q = 4, T = 2, A = 7, Z = 0}

local function fail(pos, msg)
  error({pos = pos, msg = msg}, 0)
end

-- The parser's state: the string, the position of the next byte.
local function skip_space(d, i)
  while SPACE[byte(d, i)] do i = i + 1 end
  return i
end

-- Whitespace, at most one comma, whitespace (the comma-wsp production).
local function skip_sep(d, i)
  i = skip_space(d, i)
  if byte(d, i) == COMMA then i = skip_space(d, i + 1) end
  return i
end

-- A number at i (after separators): [+-] (digits [. digits] | . digits)
-- [e|E [+-] digits].  Returns the value and the position after it.
local function number(d, i, what)
  local s = i
  local _, e = find(d, "^[+-]?%d+%.?%d*", i)
  if not e then _, e = find(d, "^[+-]?%.%d+", i) end
  if not e then
    local c = sub(d, i, i)
    fail(i, ("expected %s, got %s"):format(what,
      c == "" and "the end of the data" or ("'" .. c .. "'")))
  end
  local _, x = find(d, "^[eE][+-]?%d+", e + 1)
  if x then
    e = x
  elseif find(d, "^[eE]", e + 1) then
    fail(e + 1, "exponent without digits in a number")
  end
  local v = tonumber(sub(d, s, e))
  if v == nil or v ~= v then fail(s, "bad number '" .. sub(d, s, e) .. "'") end
  if v == math.huge or v == -math.huge then
    fail(s, "number out of range '" .. sub(d, s, e) .. "'")
  end
  return v, e + 1
end

-- An arc flag: the single character 0 or 1 (it needs no separator after it).
local function flag(d, i, what)
  local c = byte(d, i)
  if c == 48 then return 0, i + 1 end
  if c == 49 then return 1, i + 1 end
  fail(i, "expected " .. what .. " (0 or 1)")
end

local NAMES = {
  M = {"x", "y"}, L = {"x", "y"}, H = {"x"}, V = {"y"},
  C = {"x1", "y1", "x2", "y2", "x", "y"}, S = {"x2", "y2", "x", "y"},
  Q = {"x1", "y1", "x", "y"}, T = {"x", "y"},
  A = {"rx", "ry", "x-axis-rotation", "large-arc-flag", "sweep-flag", "x", "y"},
}

-- A separator and a number without exponent in one match: the fast path
-- (most numbers); anything else goes through number() and its messages.
local NUM_AFTER = "^[ \t\n\r\f]*,?[ \t\n\r\f]*([+-]?%d*%.?%d*)()"
local NUM_HERE = "^([+-]?%d*%.?%d*)()"
local huge = math.huge

-- Read the arguments of one command instance (ARGS[up] numbers) into a.
local function arguments(d, i, up, a)
  for k = 1, ARGS[up] do
    if up == "A" and (k == 4 or k == 5) then
      i = skip_sep(d, i)
      a[k], i = flag(d, i, NAMES[up][k])
    else
      local _, _, s, j = find(d, k > 1 and NUM_AFTER or NUM_HERE, i)
      local c = byte(d, j)
      local v = c ~= 101 and c ~= 69 and tonumber(s)
      if v and v == v and v ~= huge and v ~= -huge then
        a[k], i = v, j
      else
        if k > 1 then i = skip_sep(d, i) end
        a[k], i = number(d, i, "a number (" .. up .. " " .. NAMES[up][k] .. ")")
      end
    end
  end
  return i
end

local function line(x0, y0, x1, y1)
  local dx, dy = x1 - x0, y1 - y0
  return {x0, y0, x0 + dx / 3, y0 + dy / 3, x1 - dx / 3, y1 - dy / 3, x1, y1}
end

local function quadratic(x0, y0, qx, qy, x1, y1)
  return {x0, y0, x0 + 2 / 3 * (qx - x0), y0 + 2 / 3 * (qy - y0),
          x1 + 2 / 3 * (qx - x1), y1 + 2 / 3 * (qy - y1), x1, y1}
end

-- The arc's size after the transform T = {a, b, c, d, e, f} (SVG's
-- matrix(a b c d e f)) and T's largest singular value: the image of the
-- ellipse is the ellipse of the 2x2 matrix A R(phi) diag(rx, ry), whose
-- semi-axes are that matrix's singular values; the chord maps by A.
local function singular(p, q, r, s)       -- of [[p r] [q s]], largest first
  local e, f = (p + s) / 2, (p - s) / 2
  local g, h = (q - r) / 2, (q + r) / 2
  local u, v = math.sqrt(e * e + g * g), math.sqrt(f * f + h * h)
  return u + v, math.abs(u - v)
end

local function image_scale(T, rx, ry, phi, dx, dy)
  local c, s = math.cos(math.rad(phi)), math.sin(math.rad(phi))
  local A, B, C, D = T[1], T[2], T[3], T[4]
  local s1 = singular(rx * (A * c + C * s), rx * (B * c + D * s),
                      ry * (-A * s + C * c), ry * (-B * s + D * c))
  local cx, cy = A * dx + C * dy, B * dx + D * dy
  return math.max(s1, 0.5 * math.sqrt(cx * cx + cy * cy)), (singular(A, B, C, D))
end

-- Append the cubics of an elliptical arc (F.6 of SVG 1.1) to sp.  The
-- Hausdorff tolerance is arc_tol times the arc's size; under a transform T
-- the cubics are built in the local coordinates at the tolerance that,
-- multiplied by T's largest singular value (the most T can stretch a
-- distance), is arc_tol times the size of the arc's image.
local function arc(sp, x0, y0, a, x1, y1, arc_tol, pos, T)
  local rx, ry = math.abs(a[1]), math.abs(a[2])
  local scale = math.max(rx, ry, 0.5 * math.sqrt((x1 - x0) ^ 2 + (y1 - y0) ^ 2))
  if T and scale > 0 then
    local size, smax = image_scale(T, rx, ry, a[3], x1 - x0, y1 - y0)
    scale = smax > 0 and size / smax or 0
  end
  local opts = nil
  if scale > 0 and rx > 0 and ry > 0 then opts = {tol = arc_tol * scale} end
  local ok, cubics = pcall(arclen.svg_arc, x0, y0, rx, ry, a[3], a[4], a[5],
                           x1, y1, opts)
  if not ok then
    fail(pos, "elliptical arc: " .. tostring(cubics):gsub("^.-%((.*)%)$", "%1"))
  end
  for _, c in ipairs(cubics) do sp[#sp + 1] = c end
end

-- Map every point of the subpaths by T (exact for cubics: an affine image
-- of a Bezier curve is the Bezier curve of the images of its control
-- points); a coordinate that overflows is an error.
local function transform(subpaths, T)
  local A, B, C, D, E, F = T[1], T[2], T[3], T[4], T[5], T[6]
  local huge = math.huge
  for _, sp in ipairs(subpaths) do
    local x, y = sp.x, sp.y
    sp.x, sp.y = A * x + C * y + E, B * x + D * y + F
    for _, c in ipairs(sp) do
      for k = 1, 7, 2 do
        x, y = c[k], c[k + 1]
        local u, v = A * x + C * y + E, B * x + D * y + F
        if not (u > -huge and u < huge and v > -huge and v < huge) then
          fail(nil, "the transform takes a coordinate out of range")
        end
        c[k], c[k + 1] = u, v
      end
    end
  end
  return subpaths
end

-- The subpaths of d, mapped by the transform T ({a, b, c, d, e, f} as SVG's
-- matrix(a b c d e f), optional).  Caps: the data's length bounds every loop.
function M.parse(d, arc_tol, T)
  local subpaths = {}
  local sp = nil                 -- the current subpath
  local cx, cy = 0, 0            -- current point
  local sx, sy = 0, 0            -- start of the current subpath
  local lastc, lastq = nil, nil  -- reflected control points for S and T
  local prev = nil               -- previous command (upper case)
  local a = {}
  local n = #d
  local i = skip_space(d, 1)
  if i > n then fail(1, "path data is empty") end
  local cmd, rel = nil, false
  while i <= n do
    local c = sub(d, i, i)
    local up = c:upper()
    local cmdpos = i
    if ARGS[up] and find(c, "%a") then
      if cmd == nil and up ~= "M" then
        fail(i, "path data must begin with a moveto (M or m), got '" .. c .. "'")
      end
      cmd, rel = up, c ~= up
      i = skip_space(d, i + 1)
    elseif cmd == nil then
      fail(i, "path data must begin with a moveto (M or m), got '" .. c .. "'")
    elseif cmd == "Z" then
      fail(i, "expected a command after Z, got '" .. c .. "'")
    elseif not find(c, "[%d%.%+%-]") then
      fail(i, "unknown command '" .. c .. "'")
    end
    if cmd == "Z" then
      if sp == nil then fail(cmdpos, "closepath before any moveto") end
      if cx ~= sx or cy ~= sy then sp[#sp + 1] = line(cx, cy, sx, sy) end
      sp.closed = true
      cx, cy = sx, sy
      sp = nil                     -- a drawing command now opens a new subpath at (sx, sy)
      lastc, lastq, prev = nil, nil, "Z"
      i = skip_space(d, i)
    else
      i = arguments(d, i, cmd, a)
      local ox, oy = 0, 0
      if rel then ox, oy = cx, cy end
      if cmd == "M" then
        cx, cy = a[1] + ox, a[2] + oy
        sx, sy = cx, cy
        sp = {x = cx, y = cy, closed = false}
        subpaths[#subpaths + 1] = sp
        cmd = "L"                  -- further pairs are implicit linetos
        lastc, lastq = nil, nil
      else
        if sp == nil then          -- drawing after Z: a new subpath at its start
          sp = {x = cx, y = cy, closed = false}
          subpaths[#subpaths + 1] = sp
        end
        local x, y
        if cmd == "L" then
          x, y = a[1] + ox, a[2] + oy
          sp[#sp + 1] = line(cx, cy, x, y)
        elseif cmd == "H" then
          x, y = a[1] + (rel and cx or 0), cy
          sp[#sp + 1] = line(cx, cy, x, y)
        elseif cmd == "V" then
          x, y = cx, a[1] + (rel and cy or 0)
          sp[#sp + 1] = line(cx, cy, x, y)
        elseif cmd == "C" or cmd == "S" then
          local x1, y1, x2, y2
          if cmd == "C" then
            x1, y1, x2, y2, x, y = a[1] + ox, a[2] + oy, a[3] + ox, a[4] + oy, a[5] + ox, a[6] + oy
          else
            if lastc then x1, y1 = 2 * cx - lastc[1], 2 * cy - lastc[2] else x1, y1 = cx, cy end
            x2, y2, x, y = a[1] + ox, a[2] + oy, a[3] + ox, a[4] + oy
          end
          sp[#sp + 1] = {cx, cy, x1, y1, x2, y2, x, y}
          lastc = {x2, y2}
        elseif cmd == "Q" or cmd == "T" then
          local qx, qy
          if cmd == "Q" then
            qx, qy, x, y = a[1] + ox, a[2] + oy, a[3] + ox, a[4] + oy
          else
            if lastq then qx, qy = 2 * cx - lastq[1], 2 * cy - lastq[2] else qx, qy = cx, cy end
            x, y = a[1] + ox, a[2] + oy
          end
          sp[#sp + 1] = quadratic(cx, cy, qx, qy, x, y)
          lastq = {qx, qy}
        else -- "A"
          x, y = a[6] + ox, a[7] + oy
          arc(sp, cx, cy, a, x, y, arc_tol, cmdpos, T)
        end
        if cmd ~= "C" and cmd ~= "S" then lastc = nil end
        if cmd ~= "Q" and cmd ~= "T" then lastq = nil end
        cx, cy = x, y
      end
      prev = cmd
      i = skip_sep(d, i)
      -- a trailing comma must be followed by another argument list
      if byte(d, i - 1) == COMMA and (i > n or find(sub(d, i, i), "%a")) then
        fail(i - 1, "comma not followed by a number")
      end
    end
  end
  assert(prev ~= nil)
  if T then return transform(subpaths, T) end
  return subpaths
end

return M
