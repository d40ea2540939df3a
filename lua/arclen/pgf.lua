-- arclen.pgf -- the Lua side of TikZ's arclen library
-- (tex/tikzlibraryarclen.code.tex): exact answers for the few pgf macros
-- that measure curves, so that every decoration built on them is exact.
--
-- TeX hands over coordinates as integers in scaled points (sp, 2^-16 pt:
-- the dimensions pgf holds, \number\dimen), so nothing here parses "pt"
-- or depends on the locale; answers go back in TeX's own units: dimension
-- registers in sp (tex.setdimen) and macros holding decimals printed the
-- way TeX prints a dimension (print_scaled, tex.web section 103), which
-- read back to the same sp.  Times travel as fixed-point decimals with 17
-- digits, which TeX's \ifdim and Lua both read.
--
-- Every entry point is called from \directlua with numbers only, and
-- never raises: a problem becomes a TeX error (tex.error) naming what was
-- asked and a value in range, so no "Dimension too large" comes from here.
local arclen = require("arclen")

local floor, sqrt, atan2 = math.floor, math.sqrt, math.atan2 or math.atan
local format = string.format
local numtext = require("arclen.numtext")   -- numbers with '.' in any locale
local deg = 180 / math.pi
local SP = 65536
local MAXDIMEN = 1073741823          -- \maxdimen in sp: 16383.99998pt

local M = {tol = 1e-12}

-- ---- TeX's units -------------------------------------------------------------

-- A number of pt as TeX prints a dimension (tex.web section 103): the
-- shortest decimal that reads back to the same sp.
local function scaled(pt)
  local n = floor(pt * SP + 0.5)
  local out = {}
  if n < 0 then out[1] = "-"; n = -n end
  out[#out + 1] = format("%d.", floor(n / SP))
  n = 10 * (n % SP) + 5
  local delta = 10
  for _ = 1, 6 do                     -- at most 5 digits follow the point
    if delta > SP then n = n + 32768 - 50000 end
    out[#out + 1] = format("%d", floor(n / SP))
    n = 10 * (n % SP)
    delta = delta * 10
    if n <= delta then break end
  end
  return table.concat(out)
end
M.scaled = scaled

local function err(what, help)
  if tex and tex.error then tex.error("arclen: " .. what, {help}) else error(what, 0) end
end

-- A dimension register (local assignment, as pgf's own \pgf@x=...), its
-- value clamped to TeX's range with an error instead of an overflow.
local function setdimen(name, pt, what)
  local n = floor(pt * SP + 0.5)
  if n ~= n then n = 0 end
  if n > MAXDIMEN or n < -MAXDIMEN then
    err(numtext.format("%s is %.6gpt, beyond TeX's largest dimension (16383.99998pt)", what, pt),
      "The picture is too large for TeX's dimensions; scale it down.")
    n = n > 0 and MAXDIMEN or -MAXDIMEN
  end
  tex.setdimen(name, n)
end

local function setmacro(name, text)
  token.set_macro(name, text)
end

-- ---- curves ------------------------------------------------------------------

-- The last curves asked about, by their coordinates in sp: a decoration
-- asks many questions of one input segment.
local cache, cache_n, CACHE_MAX = {}, 0, 64

local function curve(x0, y0, x1, y1, x2, y2, x3, y3)
  local key = format("%d,%d,%d,%d,%d,%d,%d,%d", x0, y0, x1, y1, x2, y2, x3, y3)
  local c = cache[key]
  if c then return c end
  local pts = {x0 / SP, y0 / SP, x1 / SP, y1 / SP, x2 / SP, y2 / SP, x3 / SP, y3 / SP}
  c = {pts = pts, len = arclen.length(pts, {tol = M.tol}), t = 0, s = 0}
  if cache_n >= CACHE_MAX then cache, cache_n = {}, 0 end
  cache[key] = c
  cache_n = cache_n + 1
  return c
end

-- The arc length from 0 to t, reusing the last time the curve was at.
local function length_to(c, t)
  if t <= 0 then return 0 end
  if t >= 1 then return c.len end
  if t == c.t then return c.s end
  return arclen.length(c.pts, {tol = M.tol, t0 = 0, t1 = t})
end

-- The time at arc length s, in [0, 1] (clamped at the ends).
local function time_at(c, s)
  if s <= 0 or c.len == 0 then return 0 end
  if s >= c.len then return 1 end
  return arclen.time(c.pts, s, {tol = M.tol})
end

-- The unit tangent at t: z'(t); where it vanishes (a handle on its knot)
-- the limit from z'' (reversed at t = 1), then z''', then the chord;
-- (1, 0) for a curve that is one point.
local function tangent(c, t)
  local p = c.pts
  local vx, vy = arclen.derivative(p, t)
  if vx * vx + vy * vy == 0 then
    local u = 1 - t
    vx = u * (p[5] - 2 * p[3] + p[1]) + t * (p[7] - 2 * p[5] + p[3])
    vy = u * (p[6] - 2 * p[4] + p[2]) + t * (p[8] - 2 * p[6] + p[4])
    if t == 1 then vx, vy = -vx, -vy end
  end
  if vx * vx + vy * vy == 0 then
    vx, vy = p[7] - 3 * p[5] + 3 * p[3] - p[1], p[8] - 3 * p[6] + 3 * p[4] - p[2]
  end
  if vx * vx + vy * vy == 0 then vx, vy = p[7] - p[1], p[8] - p[2] end
  local n = sqrt(vx * vx + vy * vy)
  if n == 0 then return 1, 0 end
  return vx / n, vy / n
end

local function time_text(t) return numtext.format("%.17f", t) end

-- \pgf@decorate@curvelength: \pgfmathresult = the length (a number of pt).
function M.curvelength(x0, y0, x1, y1, x2, y2, x3, y3)
  local c = curve(x0, y0, x1, y1, x2, y2, x3, y3)
  if c.len * SP > MAXDIMEN then
    err(format("a curve of the path is %.6gpt long, beyond TeX's largest dimension "
      .. "(16383.99998pt)", c.len), "Decorations cannot measure it; scale the path down.")
    setmacro("pgfmathresult", "16383.99998")
    return
  end
  setmacro("pgfmathresult", scaled(c.len))
end

-- \pgf@decorate@linelength: the same for a straight segment.
function M.linelength(x0, y0, x1, y1)
  local dx, dy = (x1 - x0) / SP, (y1 - y0) / SP
  local len = sqrt(dx * dx + dy * dy)
  if len * SP > MAXDIMEN then
    err(format("a line of the path is %.6gpt long, beyond TeX's largest dimension "
      .. "(16383.99998pt)", len), "Decorations cannot measure it; scale the path down.")
    len = 16383.99998
  end
  setmacro("pgfmathresult", scaled(len))
end

-- \pgf@decorate@movealonginputsegment@curve: from the time t the segment
-- is at, d sp further along it; sets \pgf@decorate@inputsegmenttime (never
-- past 1: the segment's length is exact, so pgf's "t > 1" repair never
-- runs) and \pgfdecoratedangle (degrees, the tangent there).
function M.move(x0, y0, x1, y1, x2, y2, x3, y3, t, d)
  local c = curve(x0, y0, x1, y1, x2, y2, x3, y3)
  if t > 1 then t = 1 elseif t < 0 then t = 0 end
  local s = length_to(c, t) + d / SP
  local t1 = time_at(c, s)
  c.t, c.s = t1, (t1 == 1 and c.len) or (t1 == 0 and 0) or s
  local tx, ty = tangent(c, t1)
  setmacro("pgf@decorate@inputsegmenttime", time_text(t1))
  setmacro("pgfdecoratedangle", scaled(atan2(ty, tx) * deg))
end

-- \pgf@decorate@transformtoinputsegment@curve: the point at time t in
-- \pgf@x, \pgf@y and the tangent's cosine and sine in \arclen@cos,
-- \arclen@sin, \arclen@msin (its negative) for \pgftransformcm.
function M.at(x0, y0, x1, y1, x2, y2, x3, y3, t)
  local c = curve(x0, y0, x1, y1, x2, y2, x3, y3)
  if t > 1 then t = 1 elseif t < 0 then t = 0 end
  local x, y = arclen.point(c.pts, t)
  local tx, ty = tangent(c, t)
  setdimen("pgf@x", x, "a point of the decoration")
  setdimen("pgf@y", y, "a point of the decoration")
  setmacro("arclen@cos", scaled(tx))
  setmacro("arclen@sin", scaled(ty))
  setmacro("arclen@msin", scaled(-ty))
end

-- \pgf@decorate@transformtoinputsegment@line: the point d sp along the
-- line from (x0, y0) towards (x1, y1), and the line's direction.
function M.lineat(x0, y0, x1, y1, d)
  local dx, dy = (x1 - x0) / SP, (y1 - y0) / SP
  local len = sqrt(dx * dx + dy * dy)
  local ux, uy = 1, 0
  if len > 0 then ux, uy = dx / len, dy / len end
  local s = d / SP
  setdimen("pgf@x", x0 / SP + s * ux, "a point of the decoration")
  setdimen("pgf@y", y0 / SP + s * uy, "a point of the decoration")
  setmacro("arclen@cos", scaled(ux))
  setmacro("arclen@sin", scaled(uy))
  setmacro("arclen@msin", scaled(-uy))
end

-- ---- the bending library's curvilinear coordinates -----------------------------

local curvilinear

-- \pgfsetcurvilinearbeziercurve: the curve later distances are on.
function M.setcurvilinear(x0, y0, x1, y1, x2, y2, x3, y3)
  curvilinear = curve(x0, y0, x1, y1, x2, y2, x3, y3)
end

-- \pgfcurvilineardistancetotime: \pgf@x = the time (in pt) at d sp along
-- the curve.  Outside [0, L] the time goes on linearly at the end's rate
-- (as pgf's table does), kept within [-1, 2]; a curve of length 0 gives 0.
function M.curvilineartime(d)
  local c = curvilinear
  if not c then
    err("\\pgfcurvilineardistancetotime before \\pgfsetcurvilinearbeziercurve",
      "pgf's bending library sets the curve first; this is a bug.")
    tex.setdimen("pgf@x", 0)
    return
  end
  local s, t = d / SP, 0
  if c.len > 0 then
    if s < 0 then t = s / c.len
    elseif s > c.len then t = 1 + (s - c.len) / c.len
    else t = time_at(c, s) end
  end
  if t < -1 then t = -1 elseif t > 2 then t = 2 end
  tex.setdimen("pgf@x", floor(t * SP + 0.5))
end

-- ---- the package -------------------------------------------------------------

-- arclen.sty's options: the tolerance (relative, as everywhere in arclen).
function M.settol(tol)
  if type(tol) ~= "number" or not (tol >= 1e-15 and tol <= 0.1) then
    err(format("tol must be in [1e-15, 0.1], got %s", tostring(tol)),
      "\\usepackage[tol=1e-12]{arclen}: the relative tolerance of every length.")
    return
  end
  M.tol = tol
  cache, cache_n = {}, 0
end

return M
