-- arclen.path -- paths of cubic Bezier segments: length, time (MetaPost's
-- path time: segment index + parameter), point, tangent, split, sub,
-- resample and dash at distances along the path.
--
--   local path = require "arclen.path"     (also arclen.path)
--   path(cubics [, opts]), path.svg(d [, opts]), path.mplib(knots [, opts])
--
-- A path is a list of segments (8 or 12 numbers each) in one or more
-- subpaths (a segment that does not start where the previous one ends
-- begins a new subpath, as an SVG moveto does).  A path read from SVG path
-- data (or by arclen.svg) keeps its cubics packed in one string of
-- doubles and makes the list of segment tables only when a query needs
-- single cubics (segs_of).  The segments' lengths are computed once, on
-- first need, into a cumulative array (a packed path's in one
-- arclen.lengths call); a distance is
-- then found by binary search (O(log n)) and one call of arclen.time inside
-- its segment.  Every distance is within tol * length of the truth: each
-- segment's length is within tol of its own (a relative bound, so the sum is
-- too), and the time inside a segment is within tol of the segment's length.
local arclen = require("arclen.engine")
local svgpath = require("arclen.svgpath")
local mplibpath = require("arclen.mplib")

local floor, abs, sqrt, huge = math.floor, math.abs, math.sqrt, math.huge
local numtext = require("arclen.numtext")
local format = numtext.format     -- '.' as the decimal point in any locale

local Path = {}
Path.__index = Path

local MAX_POINTS = 1000000    -- resample and dash produce at most this many

-- ---- errors in the style of luaL_argerror ---------------------------------

local function argerror(n, fname, msg)
  error(format("bad argument #%d to '%s' (%s)", n, fname, msg), 3)
end

local function isfinite(x)
  return type(x) == "number" and x == x and x ~= huge and x ~= -huge
end

local function check_number(x, n, fname, what)
  if type(x) ~= "number" then
    argerror(n, fname, format("%s must be a number, got %s", what, type(x)))
  end
  if not isfinite(x) then argerror(n, fname, what .. " must be finite") end
  return x
end

local function check_self(self, fname)
  if getmetatable(self) ~= Path then
    error(format("calling '%s' on bad self (a path expected, got %s)", fname,
                 type(self)), 3)
  end
end

-- ---- options ----------------------------------------------------------------

local HAS_TIME = {}   -- method name -> has it a time (inverse)?

-- Does the method exist?  The registry also says whether it has a time.
local function method_known(name)
  if HAS_TIME[name] == nil then
    local m = arclen.method(name)
    if not m then return false end
    HAS_TIME[name] = m.time
  end
  return true
end

local TOL_RANGE = format("[%g, %g]", arclen.tol_min, arclen.tol_max)
local function tol_ok(v)
  return type(v) == "number" and v >= arclen.tol_min and v <= arclen.tol_max
end

-- The options table: returns {tol, method, arc_tol, cyclic} or nil, message.
local function read_opts(opts, allowed)
  local o = {tol = 1e-12, method = "gauss"}
  if opts == nil then return o end
  if type(opts) ~= "table" then
    return nil, "options table expected, got " .. type(opts)
  end
  for k, v in pairs(opts) do
    if not allowed[k] then return nil, format("unknown option '%s'", tostring(k)) end
    if k == "tol" or k == "arc_tol" then
      if not tol_ok(v) then return nil, k .. " must be in " .. TOL_RANGE end
    elseif k == "method" then
      if type(v) ~= "string" then return nil, "method must be a string" end
      if not method_known(v) then return nil, format("unknown method '%s'", v) end
    elseif k == "cyclic" then
      if type(v) ~= "boolean" then return nil, "cyclic must be a boolean" end
    elseif k == "arcs" then
      if v ~= "conics" and v ~= "cubics" then return nil, 'arcs must be "conics" or "cubics"' end
    elseif k == "transform" then
      if type(v) ~= "table" or #v ~= 6 then
        return nil, "transform must be {a, b, c, d, e, f} (SVG's matrix(a b c d e f))"
      end
      for i = 1, 6 do
        if not isfinite(v[i]) then return nil, "transform entries must be finite numbers" end
      end
    end
    o[k] = v
  end
  return o
end

-- ---- construction -------------------------------------------------------

-- A path from subpaths {x =, y =, closed =, cubic...} (see svgpath.lua).
local function build(subpaths, o)
  local self = setmetatable({n = 0, dim = 2, cyclic = false, tol = o.tol,
    method = o.method, segs = {}, first = {}, nsub = 0}, Path)
  for _, sp in ipairs(subpaths) do
    if self.x0 == nil then self.x0, self.y0, self.z0 = sp.x, sp.y, sp.z end
    if #sp > 0 then
      self.nsub = self.nsub + 1
      self.first[self.nsub] = self.n + 1
      for _, c in ipairs(sp) do
        self.n = self.n + 1
        self.segs[self.n] = c
      end
    end
  end
  if self.n > 0 then self.dim = #self.segs[1] == 12 and 3 or 2 end
  self.first[self.nsub + 1] = self.n + 1
  self.cyclic = #subpaths == 1 and subpaths[1].closed and self.n > 0 or false
  return self
end

-- A path on the C readers' result R = {packed = the cubics as a string of
-- doubles, n = cubics, [j] = {x =, y =, closed =, n = its cubics}}
-- (svgpath.lua): no table per cubic until a query needs them (segs_of).
local function build_flat(R, o)
  local n, first, nsub, k = R.n, {}, 0, 1
  for j = 1, #R do
    local c = R[j].n
    if c > 0 then
      nsub = nsub + 1
      first[nsub] = k
      k = k + c
    end
  end
  first[nsub + 1] = k
  local sp = R[1]
  return setmetatable({n = n, dim = 2, tol = o.tol, method = o.method, packed = R.packed,
    first = first, nsub = nsub, x0 = sp and sp.x, y0 = sp and sp.y,
    cyclic = #R == 1 and sp.closed and n > 0 or false}, Path)
end

local new_array = arclen._array      -- a table with room for n items

local unpack_cubics = arclen._cubics    -- packed cubics into tables, in C

-- The segments as tables of 8 numbers, made from the packed cubics on
-- first need (paths from build_flat); other paths have them from the start.
local function segs_of(self)
  local segs = self.segs
  if segs then return segs end
  segs = unpack_cubics(self.packed)
  self.segs = segs
  return segs
end

-- arclen.path(cubics [, opts]): cubics joined end to start; a gap starts a
-- new subpath.  opts: tol, method, cyclic (the last segment ends where the
-- first starts, and distances wrap around).
local function from_cubics(_, cubics, opts)
  local fname = "arclen.path"
  local o, msg = read_opts(opts, {tol = true, method = true, cyclic = true})
  if not o then argerror(2, fname, msg) end
  if type(cubics) ~= "table" then
    argerror(1, fname, "a list of cubics expected, got " .. type(cubics))
  end
  if #cubics == 0 then argerror(1, fname, "a path needs at least one cubic") end
  local subpaths, sp, dim = {}, nil, nil
  for k = 1, #cubics do
    local c = cubics[k]
    if type(c) ~= "table" then
      argerror(1, fname, format("cubic %d must be a table, got %s", k, type(c)))
    end
    local flat = {}
    if type(c[1]) == "table" then                -- 4 points {x, y[, z]}
      if #c ~= 4 then argerror(1, fname, format("cubic %d must have 4 points", k)) end
      for i = 1, 4 do
        local p = c[i]
        if type(p) ~= "table" or (#p ~= 2 and #p ~= 3) then
          argerror(1, fname, format("cubic %d: point %d must be {x, y} or {x, y, z}", k, i))
        end
        for j = 1, #p do flat[#flat + 1] = p[j] end
      end
    else
      for i = 1, #c do flat[i] = c[i] end
    end
    if #flat ~= 8 and #flat ~= 12 then
      argerror(1, fname, format("cubic %d must have 8 (2D) or 12 (3D) numbers, got %d", k, #flat))
    end
    for i = 1, #flat do
      if not isfinite(flat[i]) then
        argerror(1, fname, format("cubic %d: coordinate %d must be a finite number", k, i))
      end
    end
    local d = #flat == 12 and 3 or 2
    dim = dim or d
    if d ~= dim then argerror(1, fname, format("cubic %d is %dD, the first is %dD", k, d, dim)) end
    local joined = sp ~= nil
    if sp then
      local prev = sp[#sp]
      for j = 1, d do
        if flat[j] ~= prev[3 * d + j] then joined = false end
      end
    end
    if not joined then
      sp = {x = flat[1], y = flat[2], z = d == 3 and flat[3] or nil, closed = false}
      subpaths[#subpaths + 1] = sp
    end
    sp[#sp + 1] = flat
  end
  if o.cyclic then
    if #subpaths ~= 1 then argerror(1, fname, "a cyclic path must not have gaps") end
    local first, last = subpaths[1][1], subpaths[1][#subpaths[1]]
    for j = 1, dim do
      if first[j] ~= last[3 * dim + j] then
        argerror(1, fname, "a cyclic path must end where it starts")
      end
    end
    subpaths[1].closed = true
  end
  return build(subpaths, o)
end

-- Turn a parser's error {pos =, msg =} into "bad argument #1 to ...".
local function parse_with(fname, parse, ...)
  local ok, res = pcall(parse, ...)
  if ok then return res end
  if type(res) == "table" then
    local where = res.pos and format(" at position %d", res.pos) or ""
    error(format("bad argument #1 to '%s' (%s%s)", fname, res.msg, where), 3)
  end
  error(res, 0)
end

-- arclen.path.svg(d [, opts]): SVG path data.  opts: tol, method, arc_tol
-- (arcs become cubics within a Hausdorff distance of arc_tol * max(rx, ry,
-- chord / 2); default: tol), transform ({a, b, c, d, e, f}: the path's
-- points mapped by SVG's matrix(a b c d e f); arcs keep their tolerance
-- after the mapping, relative to the size of the arc's image), arcs
-- ("conics", the default: lines, quadratics, cubics and arcs as conics,
-- exactly; "cubics": cubics only, arcs within arc_tol; svgpath.lua).
local SVG_OPTS = {tol = true, method = true, arc_tol = true, transform = true, arcs = true}
local function from_svg(d, opts)
  local fname = "arclen.path.svg"
  if type(d) ~= "string" then
    argerror(1, fname, "path data (a string) expected, got " .. type(d))
  end
  local o, msg = read_opts(opts, SVG_OPTS)
  if not o then argerror(2, fname, msg) end
  return build_flat(parse_with(fname, svgpath.parse, d, o.arc_tol or o.tol, o.transform,
    o.arcs), o)
end

-- arclen.path.mplib(knots [, opts]): an mplib path (a list of knots, or
-- a figure object with a path field).  opts: tol, method.
local function from_mplib(knots, opts)
  local fname = "arclen.path.mplib"
  local o, msg = read_opts(opts, {tol = true, method = true})
  if not o then argerror(2, fname, msg) end
  local sp = parse_with(fname, mplibpath.subpath, knots)
  return build({sp}, o)
end

-- ---- lengths and the search -----------------------------------------

local function is_metapost(self) return self.method == "metapost" end

-- The cumulative lengths cum[0..n] (cached); nil, message on MetaPost's
-- arithmetic overflow.
local function cumulative(self)
  if self.cum then return self.cum end
  local cum, total = {[0] = 0}, 0
  local lopts = {tol = self.tol, method = self.method}
  local mp = is_metapost(self)
  if self.packed and not mp and self.n > 0 then  -- one batch call, no table a cubic
    local lens = arclen.lengths(self.packed, lopts)
    for k = 1, self.n do
      total = total + lens[k]
      cum[k] = total
    end
    self.cum = cum
    return cum
  end
  local segs = segs_of(self)
  for k = 1, self.n do
    local len, err
    if mp then len, err = arclen.metapost.arclength(segs[k])
    else len, err = arclen.length(segs[k], lopts) end
    if len == nil then return nil, err end
    total = total + len
    cum[k] = total
  end
  self.cum = cum
  return cum
end

-- The segments of the (single) subpath as MetaPost's path functions take them.
local function mp_total(self)
  if self.mp_len == nil then
    local len, err = arclen.metapost.path_arclength(segs_of(self), self.cyclic)
    self.mp_len, self.mp_err = len or false, err
  end
  if self.mp_len then return self.mp_len end
  return nil, self.mp_err
end

local function total_length(self)
  if self.n == 0 then return 0 end
  if is_metapost(self) and self.nsub == 1 then return mp_total(self) end
  local cum, err = cumulative(self)
  if not cum then return nil, err end
  return cum[self.n]
end

-- Raise for what a query cannot do on this path (level: the user's call).
local function usable(self, fname)
  method_known(self.method)
  if self.n > 0 and not HAS_TIME[self.method] then
    error(format("bad argument #1 to '%s' (method '%s' has no time (inverse): "
      .. "distances need gauss or metapost)", fname, self.method), 3)
  end
  if self.n > 0 and is_metapost(self) and self.nsub > 1 then
    error(format("'%s': method 'metapost' measures paths without gaps "
      .. "(this one has %d subpaths)", fname, self.nsub), 3)
  end
  local L, err = total_length(self)
  if L == nil then error(format("'%s': %s", fname, err), 3) end
  return L
end

-- Segment k in 1..n and parameter t for distance s (already in [0, L]):
-- the first segment whose end is beyond s (at_end: at or beyond s, so that
-- a distance at a joint belongs to the segment that ends there).
local function locate(self, s, at_end)
  local n = self.n
  if is_metapost(self) then
    local T = assert(arclen.metapost.path_arctime(segs_of(self), s, self.cyclic))
    local k = floor(T)
    if k >= n then return n, 1 end
    if at_end and T == k and k > 0 then return k, 1 end
    return k + 1, T - k
  end
  local cum = self.cum
  if s >= cum[n] then return n, 1 end
  local lo, hi = 1, n            -- smallest k with cum[k] > s (>= s at_end)
  local k = self.cursor          -- the last query's segment: sorted queries
  if k and (at_end and cum[k - 1] < s and cum[k] >= s
            or not at_end and cum[k - 1] <= s and cum[k] > s) then
    lo = k
  else
    while lo < hi do
      local mid = floor((lo + hi) / 2)
      if cum[mid] > s or (at_end and cum[mid] >= s) then
        hi = mid
      else
        lo = mid + 1
      end
    end
    self.cursor = lo
  end
  local goal = s - cum[lo - 1]
  if goal <= 0 then return lo, 0 end
  if goal >= cum[lo] - cum[lo - 1] then return lo, 1 end
  return lo, arclen.time(segs_of(self)[lo], goal, {tol = self.tol, method = self.method})
end

-- ---- many distances in one walk -------------------------------------------

local walk_times = arclen._walk_times       -- locate_many's walk, in C
local walk_samples = arclen._walk_samples   -- the walk and the samples, in C
local reduce_queries = arclen._queries      -- read_queries' loop, in C

-- Whether distances go through the one-pass walk (arclen.times per
-- segment): the default method's paths; others take one time per distance.
local function walks(self)
  return self.method == "gauss" and self.n > 0
end

-- The segments ks[] and times ts[] of the ascending distances ds (in
-- [0, L]), as locate() gives them one by one (at_end: a distance at a
-- joint belongs to the segment that ends there); the walk is C's.
local function locate_many(self, ds, at_end)
  local ks, ts = {}, {}
  if not walks(self) then
    for i = 1, #ds do ks[i], ts[i] = locate(self, ds[i], at_end) end
    return ks, ts
  end
  walk_times(self.packed or self.segs, self.cum, ds, self.tol, at_end, ks, ts)
  return ks, ts
end

-- A distance into [0, L]: clamped on an open path, wrapped on a cyclic one.
local function reduce(self, s, L)
  if self.cyclic and L > 0 then
    local q = floor(s / L)
    return s - q * L, q
  end
  if s < 0 then return 0, 0 end
  if s > L then return L, 0 end
  return s, 0
end

-- ---- the methods --------------------------------------------------------

-- p:length() -> the arc length (nil, "arithmetic overflow" as MetaPost).
function Path:length()
  check_self(self, "length")
  if self.n > 0 and is_metapost(self) and self.nsub > 1 then
    local total, all = 0, segs_of(self)  -- MetaPost measures each subpath alone
    for j = 1, self.nsub do
      local segs = {}
      for k = self.first[j], self.first[j + 1] - 1 do segs[#segs + 1] = all[k] end
      local len, err = arclen.metapost.path_arclength(segs, false)
      if len == nil then return nil, err end
      total = total + len
    end
    return total
  end
  return total_length(self)
end

-- p:time(s) -> MetaPost's path time (k - 1 + t on segment k) at distance s.
-- An open path clamps s to [0, L] (times 0 and n); a cyclic one wraps, so
-- s = L + a gives n + time(a) and s < 0 a negative time.
function Path:time(s)
  check_self(self, "time")
  check_number(s, 1, "time", "distance")
  local L = usable(self, "time")
  if self.n == 0 then return 0 end
  if is_metapost(self) then
    return assert(arclen.metapost.path_arctime(segs_of(self), s, self.cyclic))
  end
  local r, turns = reduce(self, s, L)
  local k, t = locate(self, r)
  return turns * self.n + (k - 1) + t
end

-- The derivative's direction at (k, t), unit length; a zero derivative
-- (a cusp, or a control point on its end point) takes the limit from the
-- next derivatives: z'' (its negative at t = 1, approached from the left),
-- then z'''.  A segment that is a single point has no direction: zeros.
local function direction(self, k, t)
  local c, d = segs_of(self)[k], self.dim
  local v = {arclen.derivative(c, t)}
  local function norm(w)
    local s = 0
    for i = 1, d do s = s + w[i] * w[i] end
    return sqrt(s)
  end
  local len = norm(v)
  if len == 0 then
    local u = 1 - t
    for i = 1, d do
      local p0, p1, p2, p3 = c[i], c[d + i], c[2 * d + i], c[3 * d + i]
      v[i] = u * (p2 - 2 * p1 + p0) + t * (p3 - 2 * p2 + p1)
      if t == 1 then v[i] = -v[i] end
    end
    len = norm(v)
  end
  if len == 0 then
    for i = 1, d do
      v[i] = c[3 * d + i] - 3 * c[2 * d + i] + 3 * c[d + i] - c[i]
    end
    len = norm(v)
  end
  if len == 0 then
    for i = 1, d do v[i] = 0 end
    return v
  end
  for i = 1, d do v[i] = v[i] / len end
  return v
end

local function unpack_dim(v, d)
  if d == 3 then return v[1], v[2], v[3] end
  return v[1], v[2]
end

local function start_point(self)
  if self.dim == 3 then return self.x0, self.y0, self.z0 end
  return self.x0, self.y0
end

-- p:point(s) -> x, y[, z] at distance s (clamped, or wrapped when cyclic).
function Path:point(s)
  check_self(self, "point")
  check_number(s, 1, "point", "distance")
  local L = usable(self, "point")
  if self.n == 0 then return start_point(self) end
  local k, t = locate(self, (reduce(self, s, L)))
  return arclen.point(segs_of(self)[k], t)
end

-- p:tangent(s) -> the unit tangent tx, ty[, tz] at distance s (at a joint,
-- the direction leaving it; at the end, the direction arriving).
function Path:tangent(s)
  check_self(self, "tangent")
  check_number(s, 1, "tangent", "distance")
  local L = usable(self, "tangent")
  if self.n == 0 then return unpack_dim({0, 0, 0}, self.dim) end
  local k, t = locate(self, (reduce(self, s, L)))
  return unpack_dim(direction(self, k, t), self.dim)
end

-- A new path with the same options from a fresh list of segments (its
-- own: it becomes the path's segment list) with gap marks pieces.gap[k]
-- (nil when there are none).  Three tables a path: dash makes one a dash.
local function from_pieces(self, pieces, x0, y0, z0)
  local n, gap = #pieces, pieces.gap
  pieces.gap = nil
  local first, nsub
  if n == 0 then
    first, nsub = {1}, 0
  elseif not gap then
    first, nsub = {1, n + 1}, 1
  else
    first, nsub = {}, 0
    for k = 1, n do
      if k == 1 or gap[k] then
        nsub = nsub + 1
        first[nsub] = k
      end
    end
    first[nsub + 1] = n + 1
  end
  return setmetatable({n = n, dim = self.dim, cyclic = false,
    tol = self.tol, method = self.method, segs = pieces, first = first, nsub = nsub,
    x0 = x0, y0 = y0, z0 = z0}, Path)
end

-- The segments from (k0, t0) to (k1, t1) -- distances a <= b (in [0, L])
-- located -- as a list with gap marks, and the start point.
local function pieces_located(self, k0, t0, k1, t1)
  local out = {}                 -- out.gap made at the first gap
  local d, segs = self.dim, segs_of(self)
  if k1 < k0 or (k1 == k0 and t1 <= t0) then
    local x, y, z = arclen.point(segs[k0], t0)
    return out, x, y, z
  end
  local isgap = self.isgap
  if not isgap then
    isgap = {}
    for j = 2, self.nsub do isgap[self.first[j]] = true end
    self.isgap = isgap
  end
  for k = k0, k1 do
    local c = segs[k]
    local ta, tb = k == k0 and t0 or 0, k == k1 and t1 or 1
    if ta ~= 0 or tb ~= 1 then c = arclen.subcurve(c, ta, tb) end
    if tb > ta or (ta == 0 and tb == 1) then
      out[#out + 1] = c
      if isgap[k] and k > k0 then
        out.gap = out.gap or {}
        out.gap[#out] = true
      end
    end
  end
  if #out == 0 then
    local x, y, z = arclen.point(segs[k0], t0)
    return out, x, y, z
  end
  local c = out[1]
  return out, c[1], c[2], d == 3 and c[3] or nil
end

local function pieces_between(self, a, b)
  local k0, t0 = locate(self, a)
  local k1, t1 = locate(self, b, true)
  return pieces_located(self, k0, t0, k1, t1)
end

-- p:sub(s0, s1) -> the part of the path from distance s0 to s1 (clamped to
-- [0, L]; s1 <= s0 gives the point at s0, a path of no segments).
function Path:sub(s0, s1)
  check_self(self, "sub")
  check_number(s0, 1, "sub", "s0")
  check_number(s1, 2, "sub", "s1")
  local L = usable(self, "sub")
  if self.n == 0 then return from_pieces(self, {}, self.x0, self.y0, self.z0) end
  local a = s0 < 0 and 0 or (s0 > L and L or s0)
  local b = s1 < 0 and 0 or (s1 > L and L or s1)
  return from_pieces(self, pieces_between(self, a, b))
end

-- p:split(s) -> the path before distance s and the path after it.
function Path:split(s)
  check_self(self, "split")
  check_number(s, 1, "split", "distance")
  local L = usable(self, "split")
  if self.n == 0 then
    return from_pieces(self, {}, self.x0, self.y0, self.z0),
           from_pieces(self, {}, self.x0, self.y0, self.z0)
  end
  local a = s < 0 and 0 or (s > L and L or s)
  return from_pieces(self, pieces_between(self, 0, a)),
         from_pieces(self, pieces_between(self, a, L))
end

-- One sample at distance s in [0, L].
local function sample(self, s)
  local k, t = locate(self, s)
  local x, y, z = arclen.point(segs_of(self)[k], t)
  local v = direction(self, k, t)
  return {x = x, y = y, z = z, s = s, time = (k - 1) + t,
          tx = v[1], ty = v[2], tz = v[3]}
end

-- p:resample(n) or p:resample{step = h} -> points evenly spaced along the
-- path, each {x =, y =, s = distance, time = path time, tx =, ty = unit
-- tangent}.  n points include both ends of an open path; a cyclic path
-- gets n points L/n apart from its start (no repeat of the start).  A step
-- gives the points at 0, h, 2h, ... <= L.
function Path:resample(spec)
  check_self(self, "resample")
  local fname = "resample"
  local L = usable(self, fname)
  local dists
  if type(spec) == "number" then
    local n = spec
    local low = self.cyclic and 1 or 2
    if n ~= floor(n) or n < low or n > MAX_POINTS then
      argerror(1, fname, format("n must be an integer in [%d, %d]", low, MAX_POINTS))
    end
    dists = new_array(n)
    local div = self.cyclic and n or n - 1
    for i = 0, n - 1 do dists[i + 1] = i == div and L or L * i / div end
  elseif type(spec) == "table" then
    for key in pairs(spec) do
      if key ~= "step" then argerror(1, fname, format("unknown option '%s'", tostring(key))) end
    end
    local h = spec.step
    if type(h) ~= "number" or not (h > 0) or h == huge then
      argerror(1, fname, "step must be a positive finite number")
    end
    if L / h >= MAX_POINTS then
      argerror(1, fname, format("step too small: more than %d points", MAX_POINTS))
    end
    local m = floor(L / h)
    dists = new_array(m + 1)
    for i = 0, m do
      local s = i * h
      if s > L then s = L end
      if not (self.cyclic and i > 0 and s >= L) then dists[#dists + 1] = s end
    end
  else
    argerror(1, fname, "a count n or {step = h} expected, got " .. type(spec))
  end
  local out = new_array(#dists)
  if self.n == 0 then
    for i = 1, #dists do
      out[i] = {x = self.x0, y = self.y0, z = self.z0, s = 0, time = 0,
                tx = 0, ty = 0, tz = self.dim == 3 and 0 or nil}
    end
    return out
  end
  if walks(self) then
    walk_samples(self.packed or self.segs, self.cum, dists, self.tol, out)
    return out
  end
  for i, s in ipairs(dists) do out[i] = sample(self, s) end
  return out
end

-- The distances of a query list as numbers reduced into [0, L] (clamped,
-- or wrapped when cyclic), ascending; order[q] = the query's index of the
-- q-th (nil when the list was ascending already).
local function read_queries(self, ds, fname, L)
  if type(ds) ~= "table" then
    argerror(1, fname, "a list of distances expected, got " .. type(ds))
  end
  if getmetatable(ds) ~= nil then         -- the C loop reads raw: copy a proxy
    local plain = {}
    for i = 1, #ds do plain[i] = ds[i] end
    ds = plain
  end
  local r, ascending = reduce_queries(ds, L, self.cyclic and L > 0)
  if not r then argerror(1, fname, ascending) end
  if ascending then return r, nil end
  local order = {}
  for i = 1, #r do order[i] = i end
  table.sort(order, function(a, b) return r[a] < r[b] end)
  local sorted = {}
  for q = 1, #r do sorted[q] = r[order[q]] end
  return sorted, order
end

-- The samples at the ascending distances ds: tables into out (pts == nil),
-- or flat arrays pts, tans, times (tans, times: a table or false).
local function fill_samples(self, ds, out, pts, tans, times)
  local d = self.dim
  if self.n == 0 then
    for q = 1, #ds do
      if pts then
        for c = 1, d do
          pts[d * (q - 1) + c] = c == 1 and self.x0 or c == 2 and self.y0 or self.z0
          if tans then tans[d * (q - 1) + c] = 0 end
        end
        if times then times[q] = 0 end
      else
        out[q] = {x = self.x0, y = self.y0, z = self.z0, s = ds[q], time = 0,
                  tx = 0, ty = 0, tz = d == 3 and 0 or nil}
      end
    end
  elseif walks(self) then
    walk_samples(self.packed or self.segs, self.cum, ds, self.tol, pts or out,
                 pts and (tans or false), pts and (times or false))
  else
    for q = 1, #ds do
      local smp = sample(self, ds[q])
      if pts then
        local p, v = {smp.x, smp.y, smp.z}, {smp.tx, smp.ty, smp.tz}
        for c = 1, d do
          pts[d * (q - 1) + c] = p[c]
          if tans then tans[d * (q - 1) + c] = v[c] end
        end
        if times then times[q] = smp.time end
      else
        out[q] = smp
      end
    end
  end
end

-- p:samples(distances) -> a list of samples {x =, y =, s =, time =, tx =,
-- ty =} (as resample's) at the given distances (clamped, or wrapped when
-- cyclic; any order, ascending is the fastest).
function Path:samples(ds)
  check_self(self, "samples")
  local L = usable(self, "samples")
  local r, order = read_queries(self, ds, "samples", L)
  local out = new_array(#r)
  fill_samples(self, r, out)
  if not order then return out end
  local res = {}
  for q = 1, #r do res[order[q]] = out[q] end
  return res
end

-- p:points(distances [, opts]) -> pts [, tans [, times]]: flat arrays, the
-- points (x1, y1, x2, y2, ... -- 3 numbers each in 3D) at the distances
-- (clamped, or wrapped when cyclic; any order), with opts.tangents the
-- unit tangents (flat too) and opts.times the path times; a result not
-- asked for is nil.
function Path:points(ds, opts)
  check_self(self, "points")
  local fname = "points"
  local want_tans, want_times = false, false
  if opts ~= nil then
    if type(opts) ~= "table" then
      argerror(2, fname, "options table expected, got " .. type(opts))
    end
    for key, v in pairs(opts) do
      if key == "tangents" then want_tans = v and true or false
      elseif key == "times" then want_times = v and true or false
      else argerror(2, fname, format("unknown option '%s'", tostring(key))) end
    end
  end
  local L = usable(self, fname)
  local r, order = read_queries(self, ds, fname, L)
  local d = self.dim
  local pts = new_array(d * #r)
  local tans, times = want_tans and new_array(d * #r) or false, want_times and new_array(#r) or false
  fill_samples(self, r, nil, pts, tans, times)
  if order then
    local p2, v2, t2 = new_array(d * #r), tans and new_array(d * #r), times and new_array(#r)
    for q = 1, #r do
      local i = order[q]
      for c = 1, d do
        p2[d * (i - 1) + c] = pts[d * (q - 1) + c]
        if v2 then v2[d * (i - 1) + c] = tans[d * (q - 1) + c] end
      end
      if t2 then t2[i] = times[q] end
    end
    pts, tans, times = p2, v2, t2
  end
  return pts, tans or nil, times or nil
end

-- The dash pattern {on, off, ...}: non-negative numbers, not all zero; an
-- odd count is repeated (SVG's stroke-dasharray).  nil, message if bad.
local function read_pattern(pattern)
  if type(pattern) ~= "table" or #pattern == 0 then
    return nil, "a dash pattern {on, off, ...} expected"
  end
  local pat, total = {}, 0
  for i = 1, #pattern do
    local v = pattern[i]
    if type(v) ~= "number" or not (v >= 0) or v == huge then
      return nil, format("dash pattern entry %d must be a finite number >= 0", i)
    end
    pat[i] = v
    total = total + v
  end
  if #pat % 2 == 1 then
    for i = 1, #pattern do pat[#pat + 1] = pat[i] end
    total = 2 * total
  end
  if not (total > 0) then return nil, "dash pattern must not be all zero" end
  return pat, total
end

-- p:dash(pattern [, offset]) -> the list of dashes (paths): the "on"
-- stretches of the pattern laid along the path from distance -offset, as
-- SVG's stroke-dasharray and stroke-dashoffset; the pattern starts again at
-- each subpath.  Zero-length dashes are paths of no segments (a point).
function Path:dash(pattern, offset)
  check_self(self, "dash")
  local fname = "dash"
  local pat, P = read_pattern(pattern)
  if not pat then argerror(1, fname, P) end
  offset = offset == nil and 0 or check_number(offset, 2, fname, "offset")
  local L = usable(self, fname)
  local dashes = {}
  if self.n == 0 then return dashes end
  local mp = is_metapost(self)
  local starts, ends = {}, {}        -- the dashes' ends, ascending
  for j = 1, self.nsub do
    local a, b = 0, L               -- the subpath's range of distances
    if not mp then a, b = self.cum[self.first[j] - 1], self.cum[self.first[j + 1] - 1] end
    local span = b - a
    if span / P * #pat > 2 * MAX_POINTS then
      error(format("'dash': more than %d dashes (pattern too fine)", MAX_POINTS), 2)
    end
    -- where the pattern stands at the subpath's start: entry i, phase into it
    local phase = offset - floor(offset / P) * P
    if not (phase >= 0 and phase < P) then phase = 0 end   -- |offset| >> P: rounding
    local i = 1
    while i < #pat and (phase > pat[i] or (phase == pat[i] and pat[i] > 0)) do
      phase = phase - pat[i]
      i = i + 1
    end
    local left = pat[i] - phase
    if left < 0 then left = 0 end
    local rel = 0                     -- distance from the subpath's start
    for _ = 1, 4 * MAX_POINTS do      -- each step ends an entry or the subpath
      local e = rel + left
      if e > span then e = span end
      if i % 2 == 1 then
        starts[#starts + 1], ends[#ends + 1] = a + rel, a + e
      end
      rel = e
      if rel >= span then break end
      i = i % #pat + 1
      left = pat[i]
    end
  end
  local k0, t0 = locate_many(self, starts, false)
  local k1, t1 = locate_many(self, ends, true)
  for q = 1, #starts do
    dashes[q] = from_pieces(self, pieces_located(self, k0[q], t0[q], k1[q], t1[q]))
  end
  return dashes
end

-- p:segments() -> the number of segments; p:segment(k) -> a copy of cubic k.
function Path:segments()
  check_self(self, "segments")
  return self.n
end

function Path:segment(k)
  check_self(self, "segment")
  if type(k) ~= "number" or k ~= floor(k) or k < 1 or k > self.n then
    argerror(1, "segment", format("k must be an integer in [1, %d]", self.n))
  end
  local c, out = segs_of(self)[k], {}
  for i = 1, #c do out[i] = c[i] end
  return out
end

-- The shortest of %.15g, %.16g, %.17g that reads back as x.
local num = numtext.shortest

-- p:svg() -> SVG path data (absolute M and C, Z on a cyclic path) that
-- reads back to the same segments (2D paths).
function Path:svg()
  check_self(self, "svg")
  if self.dim ~= 2 then error("'svg': SVG path data is 2D; this path is 3D", 2) end
  local out = {}
  if self.n == 0 then return "M" .. num(self.x0) .. " " .. num(self.y0) end
  local isgap = {}
  for j = 1, self.nsub do isgap[self.first[j]] = true end
  local segs = segs_of(self)
  for k = 1, self.n do
    local c = segs[k]
    if isgap[k] then out[#out + 1] = "M" .. num(c[1]) .. " " .. num(c[2]) end
    out[#out + 1] = format("C%s %s %s %s %s %s", num(c[3]), num(c[4]), num(c[5]),
                           num(c[6]), num(c[7]), num(c[8]))
  end
  if self.cyclic then out[#out + 1] = "Z" end
  return table.concat(out, " ")
end

Path.__tostring = function(self)
  return format("arclen.path: %d segment%s in %d subpath%s%s", self.n,
    self.n == 1 and "" or "s", self.nsub, self.nsub == 1 and "" or "s",
    self.cyclic and ", cyclic" or "")
end

-- The module: callable as arclen.path(cubics [, opts]).
local M = {svg = from_svg, mplib = from_mplib, Path = Path}

-- path._from_subpaths(R, tol, method): a path on the C readers' result
-- (svgpath.lua's format): arclen.svg's drawn elements.  The numbers are
-- the readers' own (finite); the structure is checked.
function M._from_subpaths(R, tol, method)
  local fname = "arclen.path._from_subpaths"
  -- packed: a string of doubles (the C readers), a flat table (the Lua engine's)
  local pk = type(R) == "table" and R.packed
  if type(R) ~= "table" or (type(pk) ~= "string" and type(pk) ~= "table")
     or type(R.n) ~= "number" then
    argerror(1, fname, "the readers' subpaths {packed =, n =, ...} expected")
  end
  local count = 0
  for j = 1, #R do
    local sp = R[j]
    if type(sp) ~= "table" or type(sp.n) ~= "number" or type(sp.x) ~= "number"
       or type(sp.y) ~= "number" then
      argerror(1, fname, format("subpath %d must be {x =, y =, closed =, n =}", j))
    end
    count = count + sp.n
  end
  if count ~= R.n or #pk ~= (type(pk) == "string" and 64 or 8) * R.n then
    argerror(1, fname, "the subpaths' counts do not match the packed cubics")
  end
  if not tol_ok(tol) then argerror(2, fname, "tol must be in " .. TOL_RANGE) end
  if type(method) ~= "string" or not method_known(method) then
    argerror(3, fname, "method must be the name of a known method")
  end
  return build_flat(R, {tol = tol, method = method})
end
setmetatable(M, {__call = from_cubics})

-- Is x a path?
function M.is_path(x) return getmetatable(x) == Path end

return M
