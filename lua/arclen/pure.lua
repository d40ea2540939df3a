-- arclen.pure -- the Lua engine: what arclen.core gives the path layer,
-- in plain Lua (5.1-5.4, LuaJIT), for where the C core cannot load (LuaTeX
-- without --shell-escape, a platform without a binary).  Same names, same
-- argument checks and messages, same guarantee (every distance within tol *
-- L): the default method on plane cubics (pure_gauss.lua), lines,
-- quadratics and conics in 2D and 3D (pure_segment.lua), SVG path data
-- without arcs (pure_svgpath.lua).  3D cubics, the other methods
-- (elliptic, metapost, ...), Floater's conics, elliptical arcs, the root solvers and
-- the speed's critical points stay in the C core: asked for here, they
-- raise an error that says so and how to get it.
--
--   local core = require "arclen.engine"   -- this module or arclen.core
local G = require("arclen.pure_gauss")
local numtext = require("arclen.numtext")

local floor, sqrt, huge = math.floor, math.sqrt, math.huge
local format = string.format
local unpack = table.unpack or unpack

local M = {engine = "lua", _VERSION = "arclen 1.0.0", tol_min = 1e-15, tol_max = 0.1}

local NEEDS_C = "needs the C core (arclen.core), which is not loaded: in plain Lua "
  .. "build it (make, or luarocks make); in LuaTeX run lualatex --shell-escape"

-- The largest conic weight the Lua engine's set-up takes: its angle form
-- squares w (pure_segment.lua, conic_setup: (1 - w)(1 + w) and |U x V|^2
-- at a scale of 1/w), which leaves the double range at 2^512; the C core
-- scales by 1/w and takes every finite w.
local PURE_WMAX = 2 ^ 510
M.conic_wmax = PURE_WMAX    -- arclen.path refuses such a conic when it is built

local OVERFLOW = "arithmetic overflow"   -- the C core's ARCLEN_EOVERFLOW

-- "bad argument #n to 'fname' (msg)", as luaL_argerror raises it from a C
-- function: without a position.
local function argerror(n, fname, msg)
  error(format("bad argument #%d to '%s' (%s)", n, fname, msg), 0)
end

local function isfinite(x)
  return x == x and x ~= huge and x ~= -huge
end

-- lauxlib's checks of a table and of a number (or numeric string)
-- argument, with its messages.
local function check_table(v, arg, fname)
  if type(v) ~= "table" then argerror(arg, fname, "table expected, got " .. type(v)) end
  return v
end
local function check_number(v, arg, fname)
  local x = tonumber(v)
  if type(v) ~= "number" and not (type(v) == "string" and x) then
    argerror(arg, fname, "number expected, got " .. type(v))
  end
  return x
end

-- ---- arguments ---------------------------------------------------------------

-- The curve at argument 1 of fname: a table of 8 numbers or of 4 points
-- {x, y}, or 8 numbers in a row; returns the 8 coordinates and the index
-- of the argument after the curve.  3D curves raise: they need the C core.
local EXTRA = {time = 1, point = 1, derivative = 1, split = 1, subcurve = 2}
local function check_curve(fname, ...)
  local a1 = ...
  local c = {}
  if type(a1) == "number" then
    local n, extra, k = select("#", ...), EXTRA[fname] or 0, 0
    while k < n and k < 12 + extra and type((select(k + 1, ...))) == "number" do k = k + 1 end
    if k - extra == 12 then argerror(1, fname, "a 3D curve " .. NEEDS_C) end
    for i = 1, 8 do
      local v = select(i, ...)
      if type(v) ~= "number" then
        argerror(i, fname, format("coordinate must be a number, got %s",
          v == nil and "no value" or type(v)))
      end
      if not isfinite(v) then argerror(i, fname, "coordinate must be finite") end
      c[i] = v * 1.0       -- a float: integer arithmetic (5.3+) could wrap
    end
    return c, 9
  end
  if type(a1) ~= "table" then
    argerror(1, fname, format("curve expected (a table of 8 or 12 numbers or of 4 points), got %s",
      a1 == nil and "no value" or type(a1)))
  end
  if type(a1[1]) == "table" then
    local dim = #a1[1]
    if #a1 ~= 4 or (dim ~= 2 and dim ~= 3) then
      argerror(1, fname, "curve must have 4 points of 2 or 3 coordinates")
    end
    if dim == 3 then argerror(1, fname, "a 3D curve " .. NEEDS_C) end
    for i = 1, 4 do
      local p = a1[i]
      if type(p) ~= "table" or #p ~= dim then
        argerror(1, fname, format("point %d must be a table of %d numbers", i, dim))
      end
      for k = 1, 2 do
        local v = p[k]
        if type(v) ~= "number" then
          argerror(1, fname, format("coordinate of point %d must be a number", i))
        end
        if not isfinite(v) then
          argerror(1, fname, format("coordinate of point %d must be finite", i))
        end
        c[2 * (i - 1) + k] = v * 1.0
      end
    end
    return c, 2
  end
  local n = #a1
  if n ~= 8 and n ~= 12 then
    argerror(1, fname, format("curve must have 8 (2D) or 12 (3D) numbers, got %d", n))
  end
  if n == 12 then argerror(1, fname, "a 3D curve " .. NEEDS_C) end
  for i = 1, 8 do
    local v = a1[i]
    if type(v) ~= "number" then
      argerror(1, fname, format("curve coordinate %d must be a number", i))
    end
    if not isfinite(v) then argerror(1, fname, format("curve coordinate %d must be finite", i)) end
    c[i] = v * 1.0
  end
  return c, 2
end

local function check_tol(v, arg, fname)
  if not (v >= M.tol_min and v <= M.tol_max) then
    argerror(arg, fname, "tol must be in [1e-15, 0.1]")
  end
  return v
end

-- The methods of the C core's registry: known names, each with or
-- without a time (inverse); only "gauss" runs here.
local C_METHODS = {["gravesen"] = false, ["gravesen-richardson"] = false,
  metapost = true, polyline = false, trapezoid = false,
  ["trapezoid-factored"] = false, elliptic = false}

local function c_method_error(arg, fname, name)
  argerror(arg, fname, format("method '%s' %s", name, NEEDS_C))
end

-- The ranges in the C binding's messages, "%.14g" in any locale.
local function range(lo, hi)
  return "[" .. numtext.format("%.14g", lo) .. ", " .. numtext.format("%.14g", hi) .. "]"
end
local RANGE_T, RANGE_STEPS = range(0, 1), range(1, 1e9)

-- The common options: tol, method, t0, t1, steps, info (as the C
-- binding's arclenL_checkopts).  Returns rtol, t0, t1, info.
local function check_opts(opts, arg, fname)
  local rtol, t0, t1, info = 1e-12, 0, 1, false
  if opts == nil then return rtol, t0, t1, info end
  if type(opts) ~= "table" then
    argerror(arg, fname, "options table expected, got " .. type(opts))
  end
  for key, v in pairs(opts) do
    if type(key) ~= "string" then argerror(arg, fname, "option names must be strings") end
    if key == "tol" then
      if type(v) ~= "number" then argerror(arg, fname, "tol must be a number") end
      rtol = check_tol(v, arg, fname)
    elseif key == "method" then
      if type(v) ~= "string" then argerror(arg, fname, "method must be a string") end
      if C_METHODS[v] ~= nil then c_method_error(arg, fname, v) end
      if v ~= "gauss" then argerror(arg, fname, format("unknown method '%s'", v)) end
    elseif key == "t0" or key == "t1" or key == "steps" then
      if type(v) ~= "number" then argerror(arg, fname, key .. " must be a number") end
      if key == "steps" then
        if not (v >= 1 and v <= 1e9) then
          argerror(arg, fname, "steps must be in " .. RANGE_STEPS)
        end
        if v ~= floor(v) then argerror(arg, fname, "steps must be an integer") end
      elseif not (v >= 0 and v <= 1) then
        argerror(arg, fname, key .. " must be in " .. RANGE_T)
      elseif key == "t0" then t0 = v else t1 = v end
    elseif key == "info" then
      info = v and true or false
    else
      argerror(arg, fname, format("unknown option '%s'", key))
    end
  end
  return rtol, t0, t1, info
end

-- ---- the curve functions ---------------------------------------------------

-- arclen.length(c [, opts]) -> L [, info]
function M.length(...)
  local c, next = check_curve("length", ...)
  local rtol, t0, t1, want = check_opts((select(next, ...)), next, "length")
  local len, info = G.length(c, t0, t1, rtol, want)
  if want then return len, info end
  return len
end

-- arclen.time(c, s [, opts]) -> t with |s(t) - s| <= tol L; 0 for s <= 0,
-- 1 for s at or past the length.
function M.time(...)
  local c, next = check_curve("time", ...)
  local s = select(next, ...)
  if type(s) ~= "number" or s ~= s then
    argerror(next, "time", "length must be a number (not NaN)")
  end
  local rtol, t0, t1, want = check_opts((select(next + 1, ...)), next + 1, "time")
  if t0 ~= 0 or t1 ~= 1 then argerror(next + 1, "time", "t0 and t1 do not apply to time") end
  local ts, evals = G.times(c, {s}, rtol)
  if want then
    return ts[1], {evals = evals, pieces = 0, depth = 0, err = 0, calls = 0}
  end
  return ts[1]
end

local function check_t(t, arg, fname)
  if type(t) ~= "number" then
    argerror(arg, fname, format("t must be a number, got %s", t == nil and "no value" or type(t)))
  end
  if not isfinite(t) then argerror(arg, fname, "t must be finite") end
  if not (t >= 0 and t <= 1) then argerror(arg, fname, "t must be in [0, 1]") end
  return t
end

-- The point at t (Bernstein form, as the C core: exact at the ends).
local function point_at(c, t)
  local s = 1 - t
  local b0, b1, b2, b3 = s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t
  return b0 * c[1] + b1 * c[3] + b2 * c[5] + b3 * c[7],
         b0 * c[2] + b1 * c[4] + b2 * c[6] + b3 * c[8]
end

-- z'(t) = 3 [(1-t)^2 (P1-P0) + 2t(1-t) (P2-P1) + t^2 (P3-P2)]
local function derivative_at(c, t)
  local s = 1 - t
  local function d(k)
    local d0, d1, d2 = c[k + 2] - c[k], c[k + 4] - c[k + 2], c[k + 6] - c[k + 4]
    return 3 * (s * s * d0 + 2 * t * s * d1 + t * t * d2)
  end
  return d(1), d(2)
end

-- The unit tangent at t: z'(t) normalised; where z' vanishes the limit
-- from z'' (its negative at t = 1, approached from the left), then z''';
-- a point has none (zeros).
local function unit_tangent(c, t)
  local vx, vy = derivative_at(c, t)
  local len = sqrt(vx * vx + vy * vy)
  if len == 0 then
    local u = 1 - t
    vx = u * (c[5] - 2 * c[3] + c[1]) + t * (c[7] - 2 * c[5] + c[3])
    vy = u * (c[6] - 2 * c[4] + c[2]) + t * (c[8] - 2 * c[6] + c[4])
    if t == 1 then vx, vy = -vx, -vy end
    len = sqrt(vx * vx + vy * vy)
  end
  if len == 0 then
    vx = c[7] - 3 * c[5] + 3 * c[3] - c[1]
    vy = c[8] - 3 * c[6] + 3 * c[4] - c[2]
    len = sqrt(vx * vx + vy * vy)
  end
  if len == 0 then return 0, 0 end
  return vx / len, vy / len
end

function M.point(...)
  local c, next = check_curve("point", ...)
  return point_at(c, check_t((select(next, ...)), next, "point"))
end

function M.derivative(...)
  local c, next = check_curve("derivative", ...)
  return derivative_at(c, check_t((select(next, ...)), next, "derivative"))
end

-- The blossom b(u1, u2, u3) by three de Casteljau steps.
local function blossom(c, u1, u2, u3)
  local out = {}
  for k = 1, 2 do
    local p0, p1, p2, p3 = c[k], c[k + 2], c[k + 4], c[k + 6]
    local q0, q1, q2 = p0 + u1 * (p1 - p0), p1 + u1 * (p2 - p1), p2 + u1 * (p3 - p2)
    local r0, r1 = q0 + u2 * (q1 - q0), q1 + u2 * (q2 - q1)
    out[k] = r0 + u3 * (r1 - r0)
  end
  return out[1], out[2]
end

-- arclen.subcurve(c, t0, t1): b(t0,t0,t0), b(t0,t0,t1), b(t0,t1,t1),
-- b(t1,t1,t1), the ends kept exact at 0 and 1.
function M.subcurve(...)
  local c, next = check_curve("subcurve", ...)
  local t0 = check_t((select(next, ...)), next, "subcurve")
  local t1 = check_t((select(next + 1, ...)), next + 1, "subcurve")
  local out = {}
  out[1], out[2] = blossom(c, t0, t0, t0)
  out[3], out[4] = blossom(c, t0, t0, t1)
  out[5], out[6] = blossom(c, t0, t1, t1)
  out[7], out[8] = blossom(c, t1, t1, t1)
  if t0 == 0 then out[1], out[2] = c[1], c[2] end
  if t1 == 1 then out[7], out[8] = c[7], c[8] end
  return out
end

-- arclen.split(c, t) -> left, right (de Casteljau).
function M.split(...)
  local c, next = check_curve("split", ...)
  local t = check_t((select(next, ...)), next, "split")
  local l, r = {}, {}
  for k = 1, 2 do
    local p0, p1, p2, p3 = c[k], c[k + 2], c[k + 4], c[k + 6]
    local q0, q1, q2 = p0 + t * (p1 - p0), p1 + t * (p2 - p1), p2 + t * (p3 - p2)
    local r0, r1 = q0 + t * (q1 - q0), q1 + t * (q2 - q1)
    local s = r0 + t * (r1 - r0)
    l[k], l[k + 2], l[k + 4], l[k + 6] = p0, q0, r0, s
    r[k], r[k + 2], r[k + 4], r[k + 6] = s, r1, q2, p3
  end
  return l, r
end

-- arclen.methods() and arclen.method(name): the registry as this engine
-- sees it -- gauss runs here; the C core's other methods are known (so
-- that a path may name them) and raise when used.
function M.methods() return {"gauss"} end

function M.method(name)
  if type(name) ~= "string" then
    argerror(1, "method", "string expected, got " .. (name == nil and "no value" or type(name)))
  end
  if name == "gauss" then return {name = "gauss", time = true} end
  if C_METHODS[name] ~= nil then return {name = name, time = C_METHODS[name]} end
  return nil
end

-- ---- many curves, many distances ------------------------------------------

-- Packed doubles (a string, as the C readers make them) need string.unpack
-- (Lua 5.3+); they only come from the C readers anyway.
local function unpack_doubles(s, fname, arg)
  if not string.unpack then
    argerror(arg, fname, "packed coordinates need Lua 5.3+ or the C core")
  end
  if #s % 8 ~= 0 then argerror(arg, fname, "packed coordinates: a multiple of 8 bytes expected") end
  local out, pos = {}, 1
  for i = 1, #s / 8 do out[i], pos = string.unpack("d", s, pos) end
  return out
end

local lengths_by_kind      -- (below) lengths and lengths3 with opts.kinds

-- arclen.lengths(coords [, opts]) -> {L1, L2, ...}: 8 numbers a curve.
function M.lengths(coords, opts)
  local fname = "lengths"
  if type(opts) == "table" and opts.kinds ~= nil then
    return lengths_by_kind(coords, opts, 2, fname)
  end
  if type(coords) == "string" then coords = unpack_doubles(coords, fname, 1)
  elseif type(coords) ~= "table" then
    argerror(1, fname, format("table of coordinates expected (8 numbers per curve), got %s",
      coords == nil and "no value" or type(coords)))
  end
  local rtol, t0, t1, info = check_opts(opts, 2, fname)
  if info then argerror(2, fname, "info does not apply to lengths") end
  local n = #coords
  if n % 8 ~= 0 then
    argerror(1, fname, format("number of coordinates must be a multiple of 8, got %d", n))
  end
  local out, c = {}, {}
  for k = 1, n / 8 do
    for i = 1, 8 do
      local v = coords[8 * (k - 1) + i]
      if type(v) ~= "number" then
        argerror(1, fname, format("coordinate %d must be a number, got %s", 8 * (k - 1) + i,
          v == nil and "nil" or type(v)))
      end
      if not isfinite(v) then
        argerror(1, fname, format("coordinate %d must be finite", 8 * (k - 1) + i))
      end
      c[i] = v * 1.0
    end
    out[k] = G.length(c, t0, t1, rtol)
  end
  return out
end

-- The ascending distances of a table, checked (arg names it).
local function read_distances(ds, arg, fname)
  local s, prev = {}, -huge
  for i = 1, #ds do
    local v = ds[i]
    if type(v) ~= "number" then
      argerror(arg, fname, format("distance %d must be a number, got %s", i,
        v == nil and "nil" or type(v)))
    end
    if v ~= v then argerror(arg, fname, format("distance %d is NaN", i)) end
    if v < prev then argerror(arg, fname, "distances must be sorted (ascending)") end
    prev = v
    s[i] = v
  end
  return s
end

-- G.times' results made ascending: each is within tol L of its distance,
-- so the larger of two neighbours is too (s is monotone).
local function times_of(c, s, rtol)
  local ts = G.times(c, s, rtol)
  for q = 2, #ts do
    if ts[q] < ts[q - 1] then ts[q] = ts[q - 1] end
  end
  return ts
end

-- arclen.times(c, distances [, opts]) -> ts [, points [, tangents]]
function M.times(c, ds, opts)
  local fname = "times"
  c = check_curve(fname, c)
  if type(ds) ~= "table" then
    argerror(2, fname, format("table expected, got %s", ds == nil and "no value" or type(ds)))
  end
  local rtol, want_p, want_v = 1e-12, false, false
  if opts ~= nil then
    if type(opts) ~= "table" then
      argerror(3, fname, "options table expected, got " .. type(opts))
    end
    for key, v in pairs(opts) do
      if type(key) ~= "string" then argerror(3, fname, "option names must be strings") end
      if key == "tol" then
        if type(v) ~= "number" then argerror(3, fname, "tol must be a number") end
        rtol = check_tol(v, 3, fname)
      elseif key == "points" then want_p = v and true or false
      elseif key == "tangents" then want_v = v and true or false
      else argerror(3, fname, format("unknown option '%s'", key)) end
    end
  end
  local ts = times_of(c, read_distances(ds, 2, fname), rtol)
  local pts, tans = want_p and {} or nil, want_v and {} or nil
  for q = 1, #ts do
    if pts then pts[2 * q - 1], pts[2 * q] = point_at(c, ts[q]) end
    if tans then tans[2 * q - 1], tans[2 * q] = unit_tangent(c, ts[q]) end
  end
  if pts and tans then return ts, pts, tans end
  if pts then return ts, pts end
  if tans then return ts, tans end
  return ts
end

-- arclen._array(n) -> a table for n items (the C core presizes it).
function M._array(n)
  if type(n) ~= "number" or not (n >= 0 and n <= 715827882 and n == floor(n)) then
    argerror(1, "_array", "size must be an integer in [0, 715827882]")
  end
  return {}
end

-- arclen._cubics(packed) -> the packed cubics as tables of 8 numbers.
function M._cubics(packed)
  local v, out = packed, {}
  if type(packed) == "string" then v = unpack_doubles(packed, "_cubics", 1)
  elseif type(packed) ~= "table" then
    argerror(1, "_cubics", "packed cubics (a string or a flat table) expected")
  else
    if #v % 8 ~= 0 then
      argerror(1, "_cubics", "packed cubics: a multiple of 8 numbers expected")
    end
    for i = 1, #v do
      if type(v[i]) ~= "number" or not isfinite(v[i]) then
        argerror(1, "_cubics", format("cubic %d: coordinate %d must be finite",
          floor((i - 1) / 8) + 1, (i - 1) % 8 + 1))
      end
    end
  end
  for k = 1, #v / 8 do out[k] = {unpack(v, 8 * k - 7, 8 * k)} end
  return out
end

-- arclen._queries(ds, L, wrap) -> r, ascending | nil, message: each
-- distance a finite number, wrapped into [0, L) or clamped to [0, L].
function M._queries(ds, L, wrap)
  check_table(ds, 1, "_queries")
  L = check_number(L, 2, "_queries")
  local r, prev, ascending = {}, -huge, true
  for i = 1, #ds do
    local v = ds[i]
    if type(v) ~= "number" then
      return nil, format("distance %d must be a number, got %s", i, v == nil and "nil" or type(v))
    end
    if not isfinite(v) then return nil, format("distance %d must be finite", i) end
    local x = v
    if wrap then x = v - floor(v / L) * L
    elseif v < 0 then x = 0
    elseif v > L then x = L end
    r[i] = x
    if x < prev then ascending = false end
    prev = x
  end
  return r, ascending
end

-- ---- segments of four kinds (lines, quadratics, cubics, conics) ---------

local S = require("arclen.pure_segment")

-- The kind name at argument arg.
local function check_kind(kind, arg, fname)
  if type(kind) ~= "string" then
    argerror(arg, fname, format("segment kind expected (line, quad, cubic or conic), got %s",
      kind == nil and "no value" or type(kind)))
  end
  if S.KINDS[kind] == nil then
    argerror(arg, fname, format("unknown segment kind '%s' (line, quad, cubic or conic)", kind))
  end
  return kind
end

-- The segment's numbers at argument arg, as floats, and its dimension:
-- the kind's count in 2D or 3D, finite; a conic's w > 0.
local function check_segment(kind, seg, arg, fname)
  local n2, n3 = S.count(kind, 2), S.count(kind, 3)
  if type(seg) ~= "table" then
    argerror(arg, fname, format("segment expected (a table of %d or %d numbers), got %s", n2, n3,
      seg == nil and "no value" or type(seg)))
  end
  local n = #seg
  if n ~= n2 and n ~= n3 then
    argerror(arg, fname, format("a %s has %d (2D) or %d (3D) numbers, got %d", kind, n2, n3, n))
  end
  local c = {}
  for i = 1, n do
    local v = seg[i]
    if type(v) ~= "number" then
      argerror(arg, fname, format("number %d must be a number, got %s", i, type(v)))
    end
    c[i] = v * 1.0
  end
  for i = 1, n do
    if not isfinite(c[i]) then argerror(arg, fname, format("number %d must be finite", i)) end
  end
  if kind == "conic" and not (c[n] > 0) then
    argerror(arg, fname, format("conic weight (number %d) must be positive", n))
  end
  if kind == "conic" and not (c[n] < PURE_WMAX) then
    argerror(arg, fname, format("conic weight (number %d) must be below 2^510 on the Lua engine", n))
  end
  return c, n == n2 and 2 or 3
end

local function needs_c_3d(kind, d, arg, fname)
  if kind == "cubic" and d == 3 then argerror(arg, fname, "a 3D cubic " .. NEEDS_C) end
end

-- The options of the segment functions: as arclen.length's (tol, method,
-- t0, t1, info; method applies to cubics).
local function segment_opts(opts, arg, fname)
  return check_opts(opts, arg, fname)
end

-- The info table of a segment's length or time (as arclen.length's).
local function seg_info(evals)
  return {evals = evals, pieces = 1, depth = 0, err = 0, calls = 1}
end

-- The length of a checked segment; from t0 to t1 (negative when t0 > t1)
-- when given; the second result counts the evaluations.
local function seg_length(kind, c, d, rtol, t0, t1)
  t0, t1 = t0 or 0, t1 or 1
  if t0 > t1 then
    local len, e = seg_length(kind, c, d, rtol, t1, t0)
    return -len, e
  end
  if kind == "cubic" then
    local len, info = G.length(c, t0, t1, rtol, true)
    return len, info and info.evals or 0
  end
  if t0 == 0 and t1 == 1 then return S.length(kind, c, d, rtol) end
  return S.length_range(kind, c, d, rtol, t0, t1)
end

-- The times of ascending distances s (in [0, L]) on a checked segment.
local function seg_times(kind, c, d, L, s, rtol)
  if kind == "cubic" then return times_of(c, s, rtol) end
  local ts = S.times(kind, c, d, L, s, rtol)
  for q = 2, #ts do
    if ts[q] < ts[q - 1] then ts[q] = ts[q - 1] end
  end
  return ts
end

-- The point and derivative of a cubic in d dimensions.
local function cubic_point(c, d, t)
  local s, out = 1 - t, {}
  local b0, b1, b2, b3 = s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t
  for j = 1, d do
    out[j] = b0 * c[j] + b1 * c[d + j] + b2 * c[2 * d + j] + b3 * c[3 * d + j]
  end
  return out
end
local function cubic_derivative(c, d, t)
  local s, out = 1 - t, {}
  for j = 1, d do
    local d0, d1, d2 = c[d + j] - c[j], c[2 * d + j] - c[d + j], c[3 * d + j] - c[2 * d + j]
    out[j] = 3 * (s * s * d0 + 2 * t * s * d1 + t * t * d2)
  end
  return out
end

local function seg_point(kind, c, d, t)
  if kind == "cubic" then return cubic_point(c, d, t) end
  return S.point(kind, c, d, t)
end

local function seg_derivative(kind, c, d, t)
  if kind == "cubic" then return cubic_derivative(c, d, t) end
  return S.derivative(kind, c, d, t)
end

-- The unit tangent of a checked segment at t (a list of d numbers); where
-- the derivative vanishes, the limit (unit_tangent's rules for a cubic).
local function seg_tangent(kind, c, d, t)
  if kind == "cubic" and d == 2 then
    local x, y = unit_tangent(c, t)
    return {x, y}
  end
  local v = seg_derivative(kind, c, d, t)
  local len = S.norm(v, d)
  if len == 0 then
    if kind == "cubic" then
      local u = 1 - t
      for j = 1, d do
        local p0, p1, p2, p3 = c[j], c[d + j], c[2 * d + j], c[3 * d + j]
        v[j] = u * (p2 - 2 * p1 + p0) + t * (p3 - 2 * p2 + p1)
        if t == 1 then v[j] = -v[j] end
      end
      len = S.norm(v, d)
      if len == 0 then
        for j = 1, d do v[j] = c[3 * d + j] - 3 * c[2 * d + j] + 3 * c[d + j] - c[j] end
        len = S.norm(v, d)
      end
    else
      v = S.fallback_direction(kind, c, d, t)
      len = S.norm(v, d)
    end
  end
  for j = 1, d do v[j] = len > 0 and v[j] / len or 0 end
  return v
end

local function check_t_named(t, arg, fname, what)
  if type(t) ~= "number" then
    argerror(arg, fname, format("%s must be a number, got %s", what,
      t == nil and "no value" or type(t)))
  end
  if not isfinite(t) then argerror(arg, fname, what .. " must be finite") end
  if not (t >= 0 and t <= 1) then argerror(arg, fname, what .. " must be in [0, 1]") end
  return t
end

local function unpack_d(v, d)
  if d == 3 then return v[1], v[2], v[3] end
  return v[1], v[2]
end

-- arclen.segment_length(kind, seg [, opts]) -> L
function M.segment_length(kind, seg, opts)
  local fname = "segment_length"
  check_kind(kind, 1, fname)
  local c, d = check_segment(kind, seg, 2, fname)
  needs_c_3d(kind, d, 2, fname)
  local rtol, t0, t1, want = segment_opts(opts, 3, fname)
  if kind == "cubic" then
    local len, info = G.length(c, t0, t1, rtol, want)
    if want then return len, info end
    return len
  end
  local len, evals = seg_length(kind, c, d, rtol, t0, t1)
  -- as the C core: a length beyond the doubles is no number
  if not isfinite(len) then return nil, OVERFLOW end
  if want then return len, seg_info(evals) end
  return len
end

-- arclen.segment_time(kind, seg, s [, opts]) -> t, |s(t) - s| <= tol L
function M.segment_time(kind, seg, s, opts)
  local fname = "segment_time"
  check_kind(kind, 1, fname)
  local c, d = check_segment(kind, seg, 2, fname)
  needs_c_3d(kind, d, 2, fname)
  if type(s) ~= "number" or s ~= s then
    argerror(3, fname, "length must be a number (not NaN)")
  end
  local rtol, t0, t1, want = segment_opts(opts, 4, fname)
  if t0 ~= 0 or t1 ~= 1 then argerror(4, fname, "t0 and t1 do not apply to time") end
  local L = seg_length(kind, c, d, rtol)
  -- as the C core: a line's or quadratic's time needs its length; a
  -- conic's is searched on it scaled down (pure_segment.lua, M.times)
  if kind ~= "cubic" and kind ~= "conic" and not isfinite(L) then return nil, OVERFLOW end
  local t = 0.0
  if s >= L then t = 1.0
  elseif s > 0 then t = seg_times(kind, c, d, L, {s}, rtol)[1] end
  if want then return t, seg_info(0) end
  return t
end

-- arclen.segment_point(kind, seg, t) -> x, y [, z]
function M.segment_point(kind, seg, t)
  local fname = "segment_point"
  check_kind(kind, 1, fname)
  local c, d = check_segment(kind, seg, 2, fname)
  return unpack_d(seg_point(kind, c, d, check_t(t, 3, fname)), d)
end

-- arclen.segment_derivative(kind, seg, t) -> dx, dy [, dz]
function M.segment_derivative(kind, seg, t)
  local fname = "segment_derivative"
  check_kind(kind, 1, fname)
  local c, d = check_segment(kind, seg, 2, fname)
  return unpack_d(seg_derivative(kind, c, d, check_t(t, 3, fname)), d)
end

-- arclen.segment_sub(kind, seg, t0, t1) -> the piece from t0 to t1
function M.segment_sub(kind, seg, t0, t1)
  local fname = "segment_sub"
  check_kind(kind, 1, fname)
  local c, d = check_segment(kind, seg, 2, fname)
  t0, t1 = check_t_named(t0, 3, fname, "t0"), check_t_named(t1, 4, fname, "t1")
  if kind ~= "cubic" then return S.sub(kind, c, d, t0, t1) end
  local out = {}
  local function blossom(u1, u2, u3, i)
    for j = 1, d do
      local p0, p1, p2, p3 = c[j], c[d + j], c[2 * d + j], c[3 * d + j]
      local q0, q1, q2 = p0 + u1 * (p1 - p0), p1 + u1 * (p2 - p1), p2 + u1 * (p3 - p2)
      local r0, r1 = q0 + u2 * (q1 - q0), q1 + u2 * (q2 - q1)
      out[(i - 1) * d + j] = r0 + u3 * (r1 - r0)
    end
  end
  blossom(t0, t0, t0, 1)
  blossom(t0, t0, t1, 2)
  blossom(t0, t1, t1, 3)
  blossom(t1, t1, t1, 4)
  for j = 1, d do
    if t0 == 0 then out[j] = c[j] elseif t0 == 1 then out[j] = c[3 * d + j] end
    if t1 == 0 then out[3 * d + j] = c[j] elseif t1 == 1 then out[3 * d + j] = c[3 * d + j] end
  end
  return out
end

-- The kinds string at argument arg (n letters of L, Q, C, R), or nil.
local function check_kinds(kinds, n, arg, fname, lazy)
  if kinds == nil then return nil end
  if type(kinds) ~= "string" then
    argerror(arg, fname, "kinds must be a string of letters L, Q, C, R, got " .. type(kinds))
  end
  if n and #kinds ~= n then
    argerror(arg, fname, format("kinds must have one letter per segment (%d), got %d", n, #kinds))
  end
  if lazy then return kinds end      -- each letter checked as it is read (kind_at)
  local bad = kinds:find("[^LQCR]")
  if bad then
    argerror(arg, fname, format("kinds: letter %d is not L, Q, C or R", bad))
  end
  return kinds
end

-- The kind name of segment k of the kinds (nil: a cubic), its letter
-- checked (arg names the kinds).
local function kind_at(kinds, k, arg, fname)
  if not kinds then return "cubic" end
  local kind = S.NAME[kinds:sub(k, k)]
  if not kind then argerror(arg, fname, format("kinds: letter %d is not L, Q, C or R", k)) end
  return kind
end

-- Records of stride 4d from packed doubles (a string or a flat table):
-- record k as the checked numbers of kind kinds[k]; returns n, rec(k).
local function records(packed, kinds, d, arg, fname, kinds_arg)
  local v = packed
  if type(packed) == "string" then v = unpack_doubles(packed, fname, arg)
  elseif type(packed) ~= "table" then
    argerror(arg, fname, format("packed segments expected (a string or a flat table), got %s",
      packed == nil and "no value" or type(packed)))
  end
  local stride = 4 * d
  if #v % stride ~= 0 then
    argerror(arg, fname, format("packed segments: a multiple of %d numbers expected, got %d",
      stride, #v))
  end
  local n = #v / stride
  n = floor(n)
  if kinds and #kinds ~= n then
    argerror(kinds_arg or 2, fname, format("kinds must have one letter per segment (%d), got %d",
      n, #kinds))
  end
  return n, function(k)
    local kind = kind_at(kinds, k, kinds_arg or 2, fname)
    local cnt, base, c = S.count(kind, d), stride * (k - 1), {}
    for i = 1, cnt do
      local x = v[base + i]
      if type(x) ~= "number" or not isfinite(x) then
        argerror(arg, fname, format("segment %d: coordinates and arguments must be finite numbers", k))
      end
      c[i] = x * 1.0
    end
    if kind == "conic" and not (c[cnt] > 0) then
      argerror(arg, fname, format("segment %d: conic weight must be positive", k))
    end
    if kind == "conic" and not (c[cnt] < PURE_WMAX) then
      argerror(arg, fname, format("segment %d: conic weight must be below 2^510 on the Lua engine", k))
    end
    return c, kind
  end
end

-- The lengths of packed records by kind (lengths and lengths3 with kinds).
function lengths_by_kind(packed, opts, d, fname)
  local o = {}
  for key, v in pairs(opts) do if key ~= "kinds" then o[key] = v end end
  local rtol, t0, t1, info = segment_opts(o, 2, fname)
  if info then argerror(2, fname, "info does not apply to " .. fname) end
  local kinds = check_kinds(opts.kinds, nil, 2, fname)
  local n, rec = records(packed, kinds, d, 1, fname)
  local out = {}
  for k = 1, n do
    local c, kind = rec(k)
    if kind == "cubic" and d == 3 then argerror(1, fname, "a 3D cubic " .. NEEDS_C) end
    out[k] = (seg_length(kind, c, d, rtol, t0, t1))
  end
  return out
end

-- arclen._segments(packed, kinds, dim) -> the records as tables
function M._segments(packed, kinds, dim)
  local fname = "_segments"
  if dim ~= 2 and dim ~= 3 then argerror(3, fname, "dim must be 2 or 3") end
  if kinds == nil and dim == 2 then return M._cubics(packed) end
  check_kinds(kinds, nil, 2, fname)
  local n, rec = records(packed, kinds, dim, 1, fname)
  local out = {}
  for k = 1, n do out[k] = (rec(k)) end
  return out
end

-- The path's segments: a list of tables, or packed records (a string, or
-- a flat table: 8 numbers a cubic; with kinds, records of stride 4d, d
-- from the count); returns their count and seg(k) -> numbers, kind, d.
-- lazy: each kind letter checked when its segment is read, not all now.
local function segments_of(segs, kinds, arg, lazy)
  check_kinds(kinds, nil, arg, "_walk", lazy)
  if type(segs) == "string" then segs = unpack_doubles(segs, "_walk", 1) end
  if type(segs) ~= "table" then
    argerror(1, "_walk", "a list of segments or packed segments expected")
  end
  if type(segs[1]) ~= "number" then
    local n = #segs
    check_kinds(kinds, n, arg, "_walk", lazy)
    return n, function(k)
      local kind = kind_at(kinds, k, arg, "_walk")
      local c, d = check_segment(kind, segs[k], 1, "_walk")
      return c, kind, d
    end
  end
  if not kinds then
    if #segs % 8 ~= 0 then argerror(1, "_walk", "packed cubics: a multiple of 8 numbers expected") end
    return floor(#segs / 8), function(k)
      return (check_curve("_walk", {unpack(segs, 8 * k - 7, 8 * k)})), "cubic", 2
    end
  end
  local d = (#kinds > 0 and #segs == 12 * #kinds) and 3 or 2
  local n, rec = records(segs, kinds, d, 1, "_walk", arg)
  return n, function(k)
    local c, kind = rec(k)
    return c, kind, d
  end
end

-- The times of the ascending distances xs, each inside (0, seglen), on a
-- segment of the walk (seglen: its length as the path has it).
local function segment_times(kind, c, dim, seglen, xs, tol, fname)
  if kind ~= "cubic" then return seg_times(kind, c, dim, seglen, xs, tol) end
  if dim == 3 then argerror(1, fname, "a 3D cubic " .. NEEDS_C) end
  return times_of(c, xs, tol)
end

-- The walk: for the ascending distances ds (in [0, cum[n]]; or {n =, div
-- =}: the n distances cum[n] i / div, resample's) on the path of segments
-- with cumulative lengths cum[0..n], call emit(q, k, t, c, kind, d, s) with
-- the segment k and time t of the q-th distance s -- a distance at a joint
-- belongs to the segment that starts there (at_end: that ends there) --
-- each run of distances in one segment solved in one sweep.
local function walk(segs, cum, ds, tol, at_end, emit, kinds, kinds_arg)
  local n, segment = segments_of(segs, kinds, kinds_arg)
  check_table(cum, 2, "_walk")
  check_table(ds, 3, "_walk")
  check_tol(check_number(tol, 4, "_walk"), 4, "_walk")
  local d
  if ds.div ~= nil then              -- {n =, div =}: resample's, len i / div
    local m, div = ds.n, ds.div
    if not (type(m) == "number" and m >= 0 and m == floor(m) and m <= 715827882
            and type(div) == "number" and div >= 1 and div == floor(div)) then
      argerror(3, "_walk", "evenly spaced distances: n an integer in [0, 715827882], "
        .. "div a positive integer")
    end
    local len = n > 0 and (tonumber(cum[n]) or 0) or 0
    d = {}
    for i = 0, m - 1 do d[i + 1] = i == div and len or len * i / div end
  else
    d = read_distances(ds, 3, "_walk")
  end
  local nd = #d
  if n == 0 or nd == 0 then return end
  local cums = {}                   -- cum[0..n] as numbers (lua_tonumber: else 0)
  for k = 0, n do
    cums[k] = tonumber(cum[k]) or 0
    if not isfinite(cums[k]) then argerror(2, "_walk", "cumulative lengths must be finite") end
  end
  cum = cums
  local function past(x, k)         -- is x beyond segment k's end?
    if at_end then return cum[k] < x end
    return cum[k] <= x
  end
  local k, i = 1, 1
  while i <= nd do
    while k < n and past(d[i], k) do k = k + 1 end
    local j = i
    if k == n then j = nd
    else while j < nd and not past(d[j + 1], k) do j = j + 1 end end
    local c, kind, dim = segment(k)
    local shift = cum[k - 1]
    local seglen = cum[k] - shift
    local s, inner, first = {}, {}, nil
    for q = i, j do
      local x = d[q] - shift
      s[q - i + 1] = x
      if x > 0 and x < seglen then
        first = first or q
        inner[#inner + 1] = x
      end
    end
    local ts = #inner > 0 and segment_times(kind, c, dim, seglen, inner, tol, "_walk") or {}
    for q = i, j do
      local x, t = s[q - i + 1], nil
      if x <= 0 then t = 0 elseif x >= seglen then t = 1 else t = ts[q - first + 1] end
      emit(q, k, t, c, kind, dim, d[q])
    end
    i = j + 1
  end
end

-- arclen._walk_times(segs, cum, ds, tol, at_end, ks, ts [, kinds])
function M._walk_times(segs, cum, ds, tol, at_end, ks, ts, kinds)
  check_table(ks, 6, "_walk_times")
  check_table(ts, 7, "_walk_times")
  walk(segs, cum, ds, tol, at_end, function(q, k, t)
    ks[q], ts[q] = k, t
  end, kinds, 8)
end

-- arclen._locate(segs, cum, s, tol, at_end [, kinds [, what]]) -> k, t: one
-- distance s in [0, cum[n]] as the walk takes it, in O(log n) reads of cum
-- (p:time, p:point, p:tangent); what "point" or "tangent": the point or
-- unit tangent there instead, d numbers (nothing on a path of no segments).
function M._locate(segs, cum, s, tol, at_end, kinds, what)
  local fname = "_locate"
  if what ~= nil and what ~= "time" and what ~= "point" and what ~= "tangent" then
    argerror(7, fname, format("invalid option '%s'", tostring(what)))
  end
  check_table(cum, 2, fname)
  check_number(s, 3, fname)
  check_tol(check_number(tol, 4, fname), 4, fname)
  local n, segment = segments_of(segs, kinds, 6, true)
  if n == 0 then return end
  local function cum_at(k)            -- lua_tonumber's reading, as the walk's
    local v = tonumber(cum[k]) or 0
    if not isfinite(v) then argerror(2, fname, "cumulative lengths must be finite") end
    return v
  end
  local lo, hi = 1, n                 -- the first segment whose end is past s
  while lo < hi do
    local mid = floor((lo + hi) / 2)
    local e = cum_at(mid)
    if at_end and e >= s or not at_end and e > s then hi = mid else lo = mid + 1 end
  end
  local c, kind, dim = segment(lo)
  local shift = cum_at(lo - 1)
  local x, seglen, t = s - shift, cum_at(lo) - shift, nil
  if x <= 0 then t = 0
  elseif x >= seglen then t = 1
  else t = segment_times(kind, c, dim, seglen, {x}, tol, fname)[1] end
  if what == "point" then return unpack(seg_point(kind, c, dim, t)) end
  if what == "tangent" then return unpack(seg_tangent(kind, c, dim, t)) end
  return lo, t
end

-- arclen._walk_samples(segs, cum, ds, tol, out [, tans, times [, kinds]]):
-- samples {x =, y =, [z =,] s =, time =, tx =, ty = [, tz =]} into out, or
-- (tans a table or false) flat arrays of points, unit tangents and path
-- times.
function M._walk_samples(segs, cum, ds, tol, out, tans, times, kinds)
  check_table(out, 5, "_walk_samples")
  local flat = tans ~= nil
  if type(tans) ~= "table" then tans = nil end      -- flat, no tangents
  if type(times) ~= "table" then times = nil end
  walk(segs, cum, ds, tol, false, function(q, k, t, c, kind, d, s)
    local p = seg_point(kind, c, d, t)
    local v = seg_tangent(kind, c, d, t)
    if flat then
      for j = 1, d do
        out[d * (q - 1) + j] = p[j]
        if tans then tans[d * (q - 1) + j] = v[j] end
      end
      if times then times[q] = (k - 1) + t end
    else
      out[q] = {x = p[1], y = p[2], z = p[3], s = s, time = (k - 1) + t,
                tx = v[1], ty = v[2], tz = v[3]}
    end
  end, kinds, 8)
end

-- arclen.svg_pathdata(d, arc_tol [, T]): SVG path data without arcs
-- (pure_svgpath.lua), the cubics in a flat table rather than a string.
M.svg_pathdata = require("arclen.pure_svgpath").svg_pathdata

-- ---- what stays in the C core -----------------------------------------------

local function c_only(name)
  return function()
    error(format("arclen.%s %s", name, NEEDS_C), 0)
  end
end

for _, name in ipairs({"carlson", "conic", "conic_length", "conic_scheme", "critical",
    "cubic", "ellipse_arc", "ellipse_conics", "fit", "fullcircle", "gauss_legendre",
    "quadratic", "quartic", "quartic_factor", "svg_arc", "svg_number",
    "svg_numbers"}) do
  M[name] = c_only(name)
end
-- arclen.lengths3(packed, opts): 3D records; here only with kinds (no cubics).
local lengths3_c = c_only("lengths3")
function M.lengths3(packed, opts)
  if type(opts) == "table" and opts.kinds ~= nil then
    return lengths_by_kind(packed, opts, 3, "lengths3")
  end
  return lengths3_c()
end
M.metapost = {}
for _, name in ipairs({"arclength", "arctime", "path_arclength", "path_arctime"}) do
  M.metapost[name] = c_only("metapost." .. name)
end
M.carlson = {}
for _, name in ipairs({"rc", "rd", "rf", "rg", "rj"}) do
  M.carlson[name] = c_only("carlson." .. name)
end
M.NEEDS_C = NEEDS_C

return M
