-- arclen.pure_svgpath -- SVG path data for the Lua engine: the grammar of
-- SVG 1.1 section 8.3.9 as SVG 2 section 9.3.9 reads it (commands M L H V
-- C S Q T A Z, lower case relative, repeated argument lists, numbers
-- separated by whitespace and at most one comma or by their own signs and
-- dots), with the C reader's result and messages (src/svg/pathdata.c).
--
-- svg_pathdata(d, arc_tol [, T [, arcs]]) -> {packed = {8 numbers a
-- segment}, n = segments, kinds = string or nil, [j] = {x =, y =, closed
-- =, n =}}; or nil, message, byte position.  (The C reader packs the
-- records in a string of doubles; here they are a flat table, which the
-- Lua engine's functions take.)  arcs "conics" (nil too): the C reader's
-- records -- L H V Z lines, Q T quadratics, C S cubics, A at most four
-- conics (P0 P1 P2 w) by SVG 1.1 F.6.5-6 as src/conic/conic_arc.c computes
-- them (equal to it but for the last bits of the libm functions);
-- arcs "cubics": lines and quadratics raised to cubics exactly, and arcs,
-- which need Floater's cubics of the C core, an error that says so.
local M = {}

local format, byte, sub, find = string.format, string.byte, string.sub, string.find
local huge, abs, sqrt, cos, sin = math.huge, math.abs, math.sqrt, math.cos, math.sin
local ceil, fmod, max = math.ceil, math.fmod, math.max
local PI = math.pi
local EPS = 2.220446049250313e-16           -- DBL_EPSILON
local DBL_MAX = 1.7976931348623157e308
local atan2 = math.atan2 or math.atan       -- Lua 5.1 / 5.3+

local function finite(x) return x == x and x > -huge and x < huge end

-- sqrt(a^2 + b^2) without overflow or underflow in the squares.
local function hypot(a, b)
  a, b = abs(a), abs(b)
  local m = max(a, b)
  if m == 0 or m == huge or a ~= a or b ~= b then return m + (a + b) * 0 end
  a, b = a / m, b / m
  return m * sqrt(a * a + b * b)
end

-- ---- arcs as conics (src/conic/conic_arc.c, step by step) -------------

-- The point of the ellipse e = {cx, cy, rx, ry, phi} at unit-frame (X, Y),
-- halved and doubled where the terms overflow; nil beyond the doubles.
local function ellipse_map(e, X, Y)
  local cp, sp = cos(e[5]), sin(e[5])
  local x = e[1] + (e[3] * X) * cp - (e[4] * Y) * sp
  local y = e[2] + (e[3] * X) * sp + (e[4] * Y) * cp
  if finite(x) and finite(y) then return x, y end
  x = 2 * (e[1] / 2 + (e[3] / 2 * X) * cp - (e[4] / 2 * Y) * sp)
  y = 2 * (e[2] / 2 + (e[3] / 2 * X) * sp + (e[4] / 2 * Y) * cp)
  if finite(x) and finite(y) then return x, y end
  return nil
end

-- SVG 1.1 F.6.5 with F.6.6: "none", "line", or the centre form {cx, cy,
-- rx, ry, phi (radians), theta1, dtheta}; nil, why on overflow.
local function arc_center(x1, y1, rx, ry, phi_deg, large, sweep, x2, y2)
  if x1 == x2 and y1 == y2 then return "none" end            -- F.6.2
  rx, ry = abs(rx), abs(ry)
  if rx == 0 or ry == 0 then return "line" end
  local phi = fmod(phi_deg, 360.0) * (PI / 180)
  local cp, sp = cos(phi), sin(phi)
  local dx, dy = x1 / 2 - x2 / 2, y1 / 2 - y2 / 2
  local x1p, y1p = cp * dx + sp * dy, -sp * dx + cp * dy        -- F.6.5.1
  local u, v = x1p / rx, y1p / ry
  local h = hypot(u, v)
  if h == 0 then return "line" end
  local lam, coef, rest = h * h, nil, nil
  if lam > 1 then                                               -- F.6.6.3
    rx, ry = rx * h, ry * h
    if not (finite(rx) and finite(ry)) then return nil, "overflow" end
    u, v, h = u / h, v / h, 1
    coef, rest = 0, 0
  else
    rest = 1 - lam
    coef = sqrt(rest)
    if large == sweep then coef = -coef end
  end
  local cxp, cyp = coef * (rx * (v / h)), coef * -(ry * (u / h))
  local cx = 2 * ((cp * (cxp / 2) - sp * (cyp / 2)) + (x1 / 2 + x2 / 2) / 2)
  local cy = 2 * ((sp * (cxp / 2) + cp * (cyp / 2)) + (y1 / 2 + y2 / 2) / 2)
  if not (finite(cx) and finite(cy)) then return nil, "overflow" end
  -- the ends U = A + coef n, V = -A + coef n (A = (u, v), n its unit
  -- normal): U x V = 2 coef h and U . V = 1 - 2 h^2, which do not cancel
  local ux, uy = u - coef * (v / h), v + coef * (u / h)
  local t1 = atan2(uy, ux)
  local dt = atan2(2 * coef * h, rest - h * h)
  if not sweep and dt > 0 then dt = dt - 2 * PI
  elseif sweep and dt < 0 then dt = dt + 2 * PI end
  return {cx, cy, rx, ry, phi, t1, dt}
end

-- The control point of a piece of angle 2h about the unit-frame angle m
-- from its ends: the chord's midpoint plus M (cos m, sin m) sin h tan h
-- (M the ellipse's linear part), not the centre's image of (cos m, sin m) /
-- cos h: a flat arc of a large ellipse has its centre ~R away, and its
-- rounding would move the control point far more than the arc's sag.
local function control_point(e, m, h, p0x, p0y, p2x, p2y)
  local cp, sp, sh = cos(e[5]), sin(e[5]), sin(h)
  local f = sh * (sh / cos(h))
  local X, Y = e[3] * (cos(m) * f), e[4] * (sin(m) * f)
  local x = (p0x / 2 + p2x / 2) + (X * cp - Y * sp)
  local y = (p0y / 2 + p2y / 2) + (X * sp + Y * cp)
  if finite(x) and finite(y) then return x, y end
  return nil
end

-- The arc's conics {x0, y0, x1, y1, x2, y2, w} (at most 4, of at most 90
-- degrees: w = cos h for a piece of angle 2h, Floater's eq. 1), the first
-- starting and the last ending at the arc's own end points, each control
-- point from its piece's ends; or "none", "line", or nil, "overflow".
local function arc_conics(x1, y1, rx, ry, phi_deg, large, sweep, x2, y2)
  local e, why = arc_center(x1, y1, rx, ry, phi_deg, large, sweep, x2, y2)
  if type(e) ~= "table" then return e, why end
  local theta, dtheta = e[6], e[7]
  if dtheta == 0 then return nil, "einval" end     -- arclen_ellipse_conics: no pieces
  local n = ceil(abs(dtheta) / (PI / 2) * (1 - 8 * EPS))
  if n < 1 then n = 1 end
  if n > 4 then n = 4 end
  local out = {}
  for k = 0, n - 1 do
    local a = theta + dtheta * k / n
    local b = k + 1 == n and theta + dtheta or theta + dtheta * (k + 1) / n
    local h = dtheta / (2 * n)     -- not (b - a) / 2: that keeps eps pi of it
    local p0x, p0y, p2x, p2y
    if k == 0 then p0x, p0y = x1, y1 else p0x, p0y = ellipse_map(e, cos(a), sin(a)) end
    if k + 1 == n then p2x, p2y = x2, y2 else p2x, p2y = ellipse_map(e, cos(b), sin(b)) end
    if not (p0x and p2x) then return nil, "overflow" end
    local p1x, p1y = control_point(e, a + h, h, p0x, p0y, p2x, p2y)
    if not p1x then return nil, "overflow" end
    out[k + 1] = {p0x, p0y, p1x, p1y, p2x, p2y, cos(h)}
  end
  return out
end

-- Are p0 p1 p2 (c[1..6]) flat: coincident or collinear to rounding (as
-- arclen_conic_degenerate)?
local function flat(c)
  for i = 1, 6 do if not finite(c[i]) then return true end end
  local v = {c[3] - c[1], c[4] - c[2], c[5] - c[3], c[6] - c[4]}
  for i = 1, 4 do
    if not finite(v[i]) then
      v = {c[3] / 2 - c[1] / 2, c[4] / 2 - c[2] / 2, c[5] / 2 - c[3] / 2, c[6] / 2 - c[4] / 2}
      break
    end
  end
  local l1, l2 = hypot(v[1], v[2]), hypot(v[3], v[4])
  if not (l1 > 0) or not (l2 > 0) then return true end
  local s = (v[1] / l1) * (v[4] / l2) - (v[2] / l1) * (v[3] / l2)
  return not (abs(s) > 16 * EPS)
end

-- Is |b - a| exactly r (TwoSum leaves no error)?
local function exact_gap(a, b, r)
  local d = b - a
  local bb = d - b
  return (b - (d - bb)) + (-a - bb) == 0 and abs(d) == r
end

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
local function check_args(d, arc_tol, T, arcs)
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
  if arcs ~= nil and arcs ~= "conics" and arcs ~= "cubics" then
    argerror(4, 'arcs must be "conics" or "cubics"')
  end
  return d
end

local ARC_WHY = {
  overflow = "the arc's radii, centre or control points lie beyond the largest double",
  einval = "coordinates and arguments must be finite numbers",
}

function M.svg_pathdata(d, arc_tol, T, arcs)
  d = check_args(d, arc_tol, T, arcs)
  local cubics_only = arcs == "cubics"
  local n = #d
  local packed, subpaths, nc, kinds = {}, {}, 0, {}
  local overflow = false              -- a mapped point beyond the doubles
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
  -- One record: the kind's numbers v (mapped), zeros to 8.
  local function put(kind, v)
    local k = 8 * nc
    for i = 1, 8 do packed[k + i] = v[i] or 0 end
    nc = nc + 1
    kinds[nc] = kind
    sp.n = sp.n + 1
  end
  -- A segment of kind with npts points v (then w for a conic), mapped by T
  -- as it comes (pathdata.c's emit: exact for every kind; a conic that
  -- rounding made flat is its chord, one a singular T folded is two lines
  -- to its farthest point and back).
  local function emit(kind, v, npts)
    if kind == "R" and flat(v) then
      kind, npts, v = "L", 2, {v[1], v[2], v[5], v[6]}
    end
    if T then
      local A, B, C, D, E, F = T[1], T[2], T[3], T[4], T[5], T[6]
      for k = 1, npts do
        local x, y = v[2 * k - 1], v[2 * k]
        v[2 * k - 1], v[2 * k] = A * x + C * y + E, B * x + D * y + F
        if not (abs(v[2 * k - 1]) <= DBL_MAX and abs(v[2 * k]) <= DBL_MAX) then
          overflow = true
        end
      end
    end
    if kind == "R" and not overflow and flat(v) then
      if (v[3] - v[1]) * (v[5] - v[3]) + (v[4] - v[2]) * (v[6] - v[4]) >= 0 then
        return put("L", {v[1], v[2], v[5], v[6]})
      end
      -- the derivative's numerator along the line changes sign once in (0, 1)
      local ux, uy = v[3] - v[1], v[4] - v[2]
      if ux == 0 and uy == 0 then ux, uy = v[5] - v[3], v[6] - v[4] end
      local a = ux * (v[3] - v[1]) + uy * (v[4] - v[2])
      local b = ux * (v[5] - v[3]) + uy * (v[6] - v[4])
      local c = ux * (v[5] - v[1]) + uy * (v[6] - v[2])
      local w, lo, hi = v[7], 0, 1
      for _ = 1, 64 do
        local t = (lo + hi) / 2
        local s = 1 - t
        local f = w * a * s * s + c * t * s + w * b * t * t
        if (f > 0) == (a > 0) then lo = t else hi = t end
      end
      local t = (lo + hi) / 2
      local b0, b1, b2 = (1 - t) * (1 - t), 2 * t * (1 - t) * w, t * t
      local den = b0 + b1 + b2
      local mx = v[1] + (b1 * (v[3] - v[1]) + b2 * (v[5] - v[1])) / den
      local my = v[2] + (b1 * (v[4] - v[2]) + b2 * (v[6] - v[2])) / den
      put("L", {v[1], v[2], mx, my})
      return put("L", {mx, my, v[5], v[6]})
    end
    return put(kind, v)
  end
  local function cubic(x0, y0, x1, y1, x2, y2, x3, y3)
    local v = {x0, y0, x1, y1, x2, y2, x3, y3}
    if cubics_only then return put("C", v) end   -- mapped at the end, as ever
    return emit("C", v, 4)
  end
  local function line(x0, y0, x1, y1)
    if not cubics_only then return emit("L", {x0, y0, x1, y1}, 2) end
    local dx, dy = x1 - x0, y1 - y0
    cubic(x0, y0, x0 + dx / 3, y0 + dy / 3, x1 - dx / 3, y1 - dy / 3, x1, y1)
  end
  local function quadratic(x0, y0, qx, qy, x1, y1)
    if not cubics_only then return emit("Q", {x0, y0, qx, qy, x1, y1}, 3) end
    cubic(x0, y0, x0 + 2.0 / 3 * (qx - x0), y0 + 2.0 / 3 * (qy - y0),
          x1 + 2.0 / 3 * (qx - x1), y1 + 2.0 / 3 * (qy - y1), x1, y1)
  end
  -- An arc (a: rx ry rotation large sweep x y) from (x0, y0) to (x1, y1):
  -- its conics; nil, message on failure (pathdata.c's arc_conics).
  local function arc(x0, y0, a, x1, y1)
    local coord = {"x1", "y1", "x2", "y2"}
    for i, c in ipairs({x0, y0, x1, y1}) do
      if not finite(c) then return nil, "elliptical arc: " .. coord[i] .. " must be finite" end
    end
    local rx, ry = abs(a[1]), abs(a[2])
    if a[3] == 0 and a[4] == 0 and rx ~= 0 and ry ~= 0 and exact_gap(x0, x1, rx)
       and exact_gap(y0, y1, ry) then
      -- a quarter: centre and control point the corners of the ends' box
      local centre_first = ((x0 - x1) * (y1 - y0) > 0) == (a[5] ~= 0)
      emit("R", {x0, y0, centre_first and x0 or x1, centre_first and y1 or y0, x1, y1,
        sqrt(0.5)}, 3)
      return true
    end
    local cs, why = arc_conics(x0, y0, rx, ry, a[3], a[4] ~= 0, a[5] ~= 0, x1, y1)
    if cs == "none" then return true end
    if cs == "line" then line(x0, y0, x1, y1) return true end
    if cs == nil then return nil, "elliptical arc: " .. ARC_WHY[why] end
    for _, c in ipairs(cs) do emit("R", c, 3) end
    return true
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
      if cmd == "A" and cubics_only then
        return nil, "elliptical arc: as cubics (arcs = \"cubics\"), arcs need the C core "
          .. "(arclen.core), which is not loaded: in plain Lua build it (make, or luarocks "
          .. "make); in LuaTeX run lualatex --shell-escape; or read them as conics", cmdpos
      end
      local a = {}
      for k = 1, ARGS[cmd] do
        if k > 1 then i = skip_sep(i) end
        if cmd == "A" and (k == 4 or k == 5) then   -- a flag needs no separator
          local c = sub(d, i, i)
          if c ~= "0" and c ~= "1" then
            return nil, format("expected %s (0 or 1)", NAMES.A[k]), i
          end
          a[k], i = c == "1" and 1 or 0, i + 1
        else
          local v, nxt, pos = number(i, cmd, k)
          if not v then return nil, nxt, pos end
          a[k], i = v, nxt
        end
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
        elseif cmd == "Q" or cmd == "T" then
          local qx, qy
          if cmd == "Q" then
            qx, qy, x, y = a[1] + ox, a[2] + oy, a[3] + ox, a[4] + oy
          else
            if lastq then qx, qy = 2 * cx - lqx, 2 * cy - lqy else qx, qy = cx, cy end
            x, y = a[1] + ox, a[2] + oy
          end
          quadratic(cx, cy, qx, qy, x, y)
          lqx, lqy = qx, qy
        else                          -- A
          x, y = a[6] + ox, a[7] + oy
          local ok, msg = arc(cx, cy, a, x, y)
          if not ok then return nil, msg, cmdpos end
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
  if T then                           -- an affine map: the subpaths' starts, the cubics' images
    local A, B, C, D, E, F = T[1], T[2], T[3], T[4], T[5], T[6]
    for _, s in ipairs(subpaths) do
      s.x, s.y = A * s.x + C * s.y + E, B * s.x + D * s.y + F
    end
    if overflow then return nil, "the transform takes a coordinate out of range" end
    for k = 1, cubics_only and 4 * nc or 0 do
      local x, y = packed[2 * k - 1], packed[2 * k]
      local u, v = A * x + C * y + E, B * x + D * y + F
      if not (u > -huge and u < huge and v > -huge and v < huge) then
        return nil, "the transform takes a coordinate out of range"
      end
      packed[2 * k - 1], packed[2 * k] = u, v
    end
  end
  subpaths.packed, subpaths.n = packed, nc
  for k = 1, nc do
    if kinds[k] ~= "C" then subpaths.kinds = table.concat(kinds) break end
  end
  return subpaths
end

return M
