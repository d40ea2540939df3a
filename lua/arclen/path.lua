-- arclen.path -- paths of cubic Bezier segments: length, time (MetaPost's
-- path time: segment index + parameter), point, tangent, split, sub,
-- resample and dash at distances along the path.
--
--   local path = require "arclen.path"     (also arclen.path)
--   path(cubics [, opts]), path.svg(d [, opts]), path.mplib(knots [, opts])
--
-- A path is a list of segments in one or more subpaths, each of one of
-- four kinds (lines, quadratic and cubic Beziers, conics: rational
-- quadratics with weights (1, w, 1)), 2D or 3D, the kinds in a string of
-- letters (L, Q, C, R; nil when all are cubics); the engine's segment_*
-- functions measure them.  Its subpaths (a segment that does not start where the previous one ends
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

local floor, abs, sqrt, log, huge = math.floor, math.abs, math.sqrt, math.log, math.huge
local numtext = require("arclen.numtext")
local caller = require("arclen.caller")
local format = numtext.format     -- '.' as the decimal point in any locale

local Path = {}
Path.__index = Path

local MAX_POINTS = 1000000    -- resample and dash produce at most this many

-- ---- errors in the style of luaL_argerror ---------------------------------

local function argerror(n, fname, msg)
  error(format("bad argument #%d to '%s' (%s)", n, fname, msg), caller(3))
end

local function isfinite(x)
  return type(x) == "number" and x == x and x ~= huge and x ~= -huge
end

local function check_number(x, n, fname, what)
  if type(x) ~= "number" then
    argerror(n, fname, format("%s must be a number, got %s", what, type(x)))
  end
  if x - x ~= 0 then argerror(n, fname, what .. " must be finite") end  -- inf, NaN
  return x
end

local function check_self(self, fname)
  if getmetatable(self) ~= Path then
    error(format("calling '%s' on bad self (a path expected, got %s)", fname,
                 type(self)), caller(3))
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
local function build(subpaths, o, dim)
  local self = setmetatable({n = 0, dim = dim or 2, cyclic = false, tol = o.tol,
    method = o.method, segs = {}, first = {}, nsub = 0}, Path)
  local letters, mixed = {}, false
  for _, sp in ipairs(subpaths) do
    if self.x0 == nil then self.x0, self.y0, self.z0 = sp.x, sp.y, sp.z end
    if #sp > 0 then
      self.nsub = self.nsub + 1
      self.first[self.nsub] = self.n + 1
      for i, c in ipairs(sp) do
        self.n = self.n + 1
        self.segs[self.n] = c
        local l = sp.kinds and sp.kinds[i] or "C"
        letters[self.n] = l
        if l ~= "C" then mixed = true end
      end
    end
  end
  if not dim and self.n > 0 then self.dim = #self.segs[1] == 12 and 3 or 2 end
  if mixed then self.kindstr = table.concat(letters) end
  self.first[self.nsub + 1] = self.n + 1
  self.cyclic = #subpaths == 1 and subpaths[1].closed and self.n > 0 or false
  return self
end

local new_array = arclen._array      -- a table with room for n items

local unpack_cubics = arclen._cubics    -- packed cubics into tables, in C

-- The segments as tables of numbers, made from the packed records on
-- first need (paths from build_flat); other paths have them from the start.
local function segs_of(self)
  local segs = self.segs
  if segs then return segs end
  if self.kindstr then segs = arclen._segments(self.packed, self.kindstr, self.dim)
  else segs = unpack_cubics(self.packed) end
  self.segs = segs
  return segs
end

-- ---- the kinds --------------------------------------------------------------

local KIND_OF = {L = "line", Q = "quad", C = "cubic", R = "conic"}
local LETTER = {line = "L", quad = "Q", cubic = "C", conic = "R"}
local NPTS = {line = 2, quad = 3, cubic = 4, conic = 3}
local WMAX = arclen.conic_wmax   -- the engine's largest conic weight (nil: any finite)
local function count_of(kind, d) return NPTS[kind] * d + (kind == "conic" and 1 or 0) end

-- The kind name of segment k.
local function kind_of(self, k)
  local kinds = self.kindstr
  if not kinds then return "cubic" end
  return KIND_OF[kinds:sub(k, k)]
end

-- The last point's offset in a segment's numbers (its first coordinate
-- is at offset + 1).
local function end_offset(kind, d) return (NPTS[kind] - 1) * d end

-- Point, derivative and sub-range of segment c of the given kind.
local function seg_point(kind, c, t)
  if kind == "cubic" then return arclen.point(c, t) end
  return arclen.segment_point(kind, c, t)
end
local function seg_derivative(kind, c, t)
  if kind == "cubic" then return arclen.derivative(c, t) end
  return arclen.segment_derivative(kind, c, t)
end
local function seg_sub(kind, c, t0, t1)
  if kind == "cubic" then return arclen.subcurve(c, t0, t1) end
  return arclen.segment_sub(kind, c, t0, t1)
end

-- A line and a quadratic as the same curve in cubic form (Bernstein
-- degree elevation: P0, (2 P0 + P1)/3, ... for a line).
local function raise(kind, c, d)
  local out = {}
  for j = 1, d do
    local p0, p1 = c[j], c[d + j]
    if kind == "line" then
      out[j], out[d + j] = p0, p0 + (p1 - p0) / 3
      out[2 * d + j], out[3 * d + j] = p1 + (p0 - p1) / 3, p1
    else
      local p2 = c[2 * d + j]
      out[j], out[d + j] = p0, p0 + 2 * (p1 - p0) / 3
      out[2 * d + j], out[3 * d + j] = p2 + 2 * (p1 - p2) / 3, p2
    end
  end
  return out
end

-- A conic as cubics within the Hausdorff distance tol * its size (the
-- longer leg): Floater's scheme (arclen.conic) where the C core has it;
-- else (the Lua engine, 3D) halving the conic until each piece's cubic
-- with the handles k = 4w/(3(1+w)) along its legs (which meets the
-- conic's midpoint) stays within the distance at 33 samples, a
-- distance at equal parameters bounding the Hausdorff one.
local function conic_cubics(c, d, tol)
  local size = 0
  for j = 1, d do
    size = math.max(size, abs(c[d + j] - c[j]), abs(c[2 * d + j] - c[d + j]))
  end
  local dist = tol * size
  if d == 2 and arclen.engine == "c" and dist > 0 then
    local ok, cubics = pcall(arclen.conic, {c[1], c[2]}, {c[3], c[4]}, {c[5], c[6]}, c[7],
                             {tol = dist})
    if ok and type(cubics) == "table" then return cubics end
  end
  local function approx(q)
    local w, k, out = q[3 * d + 1], nil, {}
    k = 4 * w / (3 * (1 + w))
    for j = 1, d do
      local p0, p1, p2 = q[j], q[d + j], q[2 * d + j]
      out[j], out[d + j] = p0, p0 + k * (p1 - p0)
      out[2 * d + j], out[3 * d + j] = p2 + k * (p1 - p2), p2
    end
    return out
  end
  -- the largest distance from the cubic's points to the conic, each
  -- point's nearest conic point by Gauss-Newton steps from the same t
  local function err(q, cub)
    local worst = 0
    for i = 1, 31 do
      local t = i / 32
      local b = {arclen.segment_point("cubic", cub, t)}
      local u, e = t, 0
      for _ = 1, 4 do
        local a = {seg_point("conic", q, u)}
        local v = {seg_derivative("conic", q, u)}
        local g, vv = 0, 0
        e = 0
        for j = 1, d do
          g = g + v[j] * (a[j] - b[j])
          vv = vv + v[j] * v[j]
          e = e + (a[j] - b[j]) ^ 2
        end
        if vv == 0 then break end
        u = u - g / vv
        if u < 0 then u = 0 elseif u > 1 then u = 1 end
      end
      local a = {seg_point("conic", q, u)}
      e = 0
      for j = 1, d do e = e + (a[j] - b[j]) ^ 2 end
      if e > worst then worst = e end
    end
    return sqrt(worst)
  end
  for level = 0, 12 do
    local m, out, ok = 2 ^ level, {}, true
    for i = 1, m do
      local q = level == 0 and c or arclen.segment_sub("conic", c, (i - 1) / m, i / m)
      local cub = approx(q)
      if level < 12 and err(q, cub) > dist / 2 then ok = false break end
      out[i] = cub
    end
    if ok then return out end
  end
end

-- Segment k of arclen.path's list: a cubic as before (8 or 12 numbers, or
-- 4 points), or tagged with its kind: {kind = "line", x0, y0, x1, y1} or
-- {"line", x0, y0, x1, y1}, the numbers flat or as points ({kind =
-- "conic", {x0, y0}, {x1, y1}, {x2, y2}, w}; a conic's w may also be the
-- field w).  Returns the kind, the flat numbers (checked), the dimension
-- and the segment's name for messages.
local function read_segment(c, k, fname)
  if type(c) ~= "table" then
    argerror(1, fname, format("segment %d must be a table, got %s", k, type(c)))
  end
  local kind, from = c.kind, 1
  if kind == nil and type(c[1]) == "string" then kind, from = c[1], 2 end
  if kind ~= nil and (type(kind) ~= "string" or not NPTS[kind]) then
    argerror(1, fname, format("segment %d: unknown kind %s (line, quad, cubic or conic)", k,
      type(kind) == "string" and "'" .. kind .. "'" or type(kind)))
  end
  local tagged = kind ~= nil
  kind = kind or "cubic"
  local what = tagged and format("segment %d (%s)", k, kind) or format("cubic %d", k)
  local flat = {}
  if type(c[from]) == "table" then                -- points {x, y[, z]}
    local last = #c
    local npts = last - from + 1
    if kind == "conic" and type(c[last]) == "number" then npts = npts - 1 end
    if npts ~= NPTS[kind] then
      argerror(1, fname, format("%s must have %d points", what, NPTS[kind]))
    end
    for i = from, from + npts - 1 do
      local q = c[i]
      if type(q) ~= "table" or (#q ~= 2 and #q ~= 3) then
        argerror(1, fname, format("%s: point %d must be {x, y} or {x, y, z}", what, i - from + 1))
      end
      for j = 1, #q do flat[#flat + 1] = q[j] end
    end
    if kind == "conic" then flat[#flat + 1] = c[from + npts] end
  else
    for i = from, #c do flat[#flat + 1] = c[i] end
  end
  if kind == "conic" and c.w ~= nil then
    if #flat == 6 or #flat == 9 then flat[#flat + 1] = c.w
    else argerror(1, fname, format("%s: w given twice", what)) end
  end
  local n2, n3 = count_of(kind, 2), count_of(kind, 3)
  if #flat ~= n2 and #flat ~= n3 then
    argerror(1, fname, format("%s must have %d (2D) or %d (3D) numbers, got %d", what, n2, n3,
      #flat))
  end
  for i = 1, #flat do
    if not isfinite(flat[i]) then
      argerror(1, fname, format("%s: coordinate %d must be a finite number", what, i))
    end
  end
  if kind == "conic" and not (flat[#flat] > 0) then
    argerror(1, fname, format("%s: the weight w must be > 0", what))
  end
  -- the Lua engine's limit (pure.lua), here rather than at the first query
  if kind == "conic" and WMAX and not (flat[#flat] < WMAX) then
    argerror(1, fname, format("%s: the weight w must be below 2^%d on the Lua engine", what,
      floor(log(WMAX) / log(2) + 0.5)))
  end
  return kind, flat, #flat == n3 and 3 or 2, what
end

-- The subpaths' segments as cubics only (paths whose method is not
-- "gauss"): lines and quadratics raised exactly, conics within tol.
local function cubics_only(subpaths, dim, tol)
  for _, sp in ipairs(subpaths) do
    if sp.kinds then
      local segs = {}
      for i, c in ipairs(sp) do
        local kind = KIND_OF[sp.kinds[i]]
        if kind == "cubic" then segs[#segs + 1] = c
        elseif kind == "conic" then
          for _, q in ipairs(conic_cubics(c, dim, tol)) do segs[#segs + 1] = q end
        else segs[#segs + 1] = raise(kind, c, dim) end
      end
      for i = 1, math.max(#sp, #segs) do sp[i] = segs[i] end
      sp.kinds = nil
    end
  end
end

-- A path on the C readers' result R = {packed = the cubics as a string of
-- doubles, n = cubics, [j] = {x =, y =, closed =, n = its cubics}}
-- (svgpath.lua): no table per cubic until a query needs them (segs_of).
-- A packed path of mixed kinds made cubics only (methods other than gauss).
local function flat_cubics_only(self, o)
  local segs, subpaths = segs_of(self), {}
  for j = 1, self.nsub do
    local a, b = self.first[j], self.first[j + 1] - 1
    local sp = {x = segs[a][1], y = segs[a][2], closed = self.cyclic, kinds = {}}
    for k = a, b do
      sp[#sp + 1] = segs[k]
      sp.kinds[#sp] = self.kindstr:sub(k, k)
    end
    subpaths[j] = sp
  end
  if #subpaths == 0 then return self end
  cubics_only(subpaths, self.dim, o.tol)
  return build(subpaths, o, self.dim)
end

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
  local self = setmetatable({n = n, dim = 2, tol = o.tol, method = o.method, packed = R.packed,
    kindstr = R.kinds, first = first, nsub = nsub, x0 = sp and sp.x, y0 = sp and sp.y,
    cyclic = #R == 1 and sp.closed and n > 0 or false}, Path)
  if self.kindstr and o.method ~= "gauss" then return flat_cubics_only(self, o) end
  return self
end

-- arclen.path(segments [, opts]): segments joined end to start; a gap
-- starts a new subpath.  opts: tol, method, cyclic (the last segment ends
-- where the first starts, and distances wrap around).
local function from_cubics(_, cubics, opts)
  local fname = "arclen.path"
  local o, msg = read_opts(opts, {tol = true, method = true, cyclic = true})
  if not o then argerror(2, fname, msg) end
  if type(cubics) ~= "table" then
    argerror(1, fname, "a list of segments expected, got " .. type(cubics))
  end
  if #cubics == 0 then argerror(1, fname, "a path needs at least one segment") end
  local subpaths, sp, dim, prev_kind = {}, nil, nil, nil
  local any = false
  for k = 1, #cubics do
    local kind, flat, d, what = read_segment(cubics[k], k, fname)
    dim = dim or d
    if d ~= dim then
      argerror(1, fname, format("%s is %dD, the first is %dD", what, d, dim))
    end
    local joined = sp ~= nil
    if sp then
      local prev, off = sp[#sp], end_offset(prev_kind, d)
      for j = 1, d do
        if flat[j] ~= prev[off + j] then joined = false end
      end
    end
    if not joined then
      sp = {x = flat[1], y = flat[2], z = d == 3 and flat[3] or nil, closed = false, kinds = {}}
      subpaths[#subpaths + 1] = sp
    end
    sp[#sp + 1] = flat
    sp.kinds[#sp] = LETTER[kind]
    if kind ~= "cubic" then any = true end
    prev_kind = kind
  end
  if o.cyclic then
    if #subpaths ~= 1 then argerror(1, fname, "a cyclic path must not have gaps") end
    local first, last = subpaths[1][1], subpaths[1][#subpaths[1]]
    local off = end_offset(prev_kind, dim)
    for j = 1, dim do
      if first[j] ~= last[off + j] then
        argerror(1, fname, "a cyclic path must end where it starts")
      end
    end
    subpaths[1].closed = true
  end
  if not any then
    for _, q in ipairs(subpaths) do q.kinds = nil end
  elseif o.method ~= "gauss" then
    cubics_only(subpaths, dim, o.tol)
  end
  return build(subpaths, o, dim)
end

-- Turn a parser's error {pos =, msg =} into "bad argument #1 to ...".
local function parse_with(fname, parse, ...)
  local ok, res = pcall(parse, ...)
  if ok then return res end
  if type(res) == "table" then
    local where = res.pos and format(" at position %d", res.pos) or ""
    error(format("bad argument #1 to '%s' (%s%s)", fname, res.msg, where), caller(3))
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
    if self.kindstr then lopts.kinds = self.kindstr end
    local lens = arclen.lengths(self.packed, lopts)
    lopts.kinds = nil
    if lens then          -- nil: a segment's length overflowed (below, one by one)
      for k = 1, self.n do
        total = total + lens[k]
        cum[k] = total
      end
      self.cum = cum
      return cum
    end
  end
  local segs = segs_of(self)
  for k = 1, self.n do
    local len, err
    local kind = kind_of(self, k)
    if mp then len, err = arclen.metapost.arclength(segs[k])
    elseif kind == "cubic" then len, err = arclen.length(segs[k], lopts)
    else
      -- nil: arithmetic overflow, a length beyond the doubles (as a cubic's inf)
      len = arclen.segment_length(kind, segs[k], lopts) or huge
    end
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
  local cum = self.cum
  -- measured by the default method: known, with a time, not MetaPost's
  if cum and self.method == "gauss" and cum[self.n] < huge then return cum[self.n] end
  method_known(self.method)
  if self.n > 0 and not HAS_TIME[self.method] then
    error(format("bad argument #1 to '%s' (method '%s' has no time (inverse): "
      .. "distances need gauss or metapost)", fname, self.method), caller(3))
  end
  if self.n > 0 and is_metapost(self) and self.nsub > 1 then
    error(format("'%s': method 'metapost' measures paths without gaps "
      .. "(this one has %d subpaths)", fname, self.nsub), caller(3))
  end
  local L, err = total_length(self)
  if L == nil then error(format("'%s': %s", fname, err), caller(3)) end
  -- p:length() may be inf, but a distance along it has no double to be
  -- (the walks would fail inside, under their own names)
  if L == huge then
    error(format("'%s': arithmetic overflow (the path's length is beyond the doubles)", fname), caller(3))
  end
  return L
end

local walk_times = arclen._walk_times       -- locate_many's walk, in C
local walk_samples = arclen._walk_samples   -- the walk and the samples, in C
local reduce_queries = arclen._queries      -- read_queries' loop, in C
local walk_locate = arclen._locate          -- one distance as the walk takes it

-- Whether distances go through the one-pass walk (arclen.times per
-- segment): the default method's paths; others take one time per distance.
local function walks(self)
  return self.method == "gauss" and self.n > 0
end

-- One distance s (in [0, L]) by the walk: segment k and time t, or with
-- what "point" or "tangent" those at s (arclen._locate).
local function walk_at(self, s, at_end, what)
  return walk_locate(self.packed or self.segs, self.cum, s, self.tol, at_end, self.kindstr, what)
end

-- Segment k in 1..n and parameter t for distance s (already in [0, L]):
-- the first segment whose end is beyond s (at_end: at or beyond s, so that
-- a distance at a joint belongs to the segment that ends there).
local function locate(self, s, at_end)
  if walks(self) then return walk_at(self, s, at_end) end  -- no table made
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
  local kind, opts = kind_of(self, lo), {tol = self.tol, method = self.method}
  if kind == "cubic" then return lo, arclen.time(segs_of(self)[lo], goal, opts) end
  return lo, arclen.segment_time(kind, segs_of(self)[lo], goal, opts)
end

-- ---- many distances in one walk -------------------------------------------


-- The segments ks[] and times ts[] of the ascending distances ds (in
-- [0, L]), as locate() gives them one by one (at_end: a distance at a
-- joint belongs to the segment that ends there); the walk is C's.
local function locate_many(self, ds, at_end)
  local ks, ts = {}, {}
  if not walks(self) then
    for i = 1, #ds do ks[i], ts[i] = locate(self, ds[i], at_end) end
    return ks, ts
  end
  if self.kindstr then
    walk_times(self.packed or self.segs, self.cum, ds, self.tol, at_end, ks, ts, self.kindstr)
  else
    walk_times(self.packed or self.segs, self.cum, ds, self.tol, at_end, ks, ts)
  end
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

local function norm_of(v, d)
  local m = 0
  for i = 1, d do if abs(v[i]) > m then m = abs(v[i]) end end
  if m == 0 then return 0 end
  local s = 0
  for i = 1, d do s = s + (v[i] / m) ^ 2 end
  return m * sqrt(s)
end

-- The unit tangent of a line, quadratic or conic at t: where the
-- derivative vanishes, a quadratic's second derivative (negated at t = 1,
-- approached from the left), a conic's chord P2 - P0 (P1 on an end point:
-- the curve leaves along the chord); a point (a line of length 0) none.
local function other_direction(kind, c, d, t)
  local v = {seg_derivative(kind, c, t)}
  local len = norm_of(v, d)
  if len == 0 then
    for j = 1, d do
      if kind == "quad" then
        v[j] = c[2 * d + j] - 2 * c[d + j] + c[j]
        if t == 1 then v[j] = -v[j] end
      elseif kind == "conic" then
        v[j] = c[2 * d + j] - c[j]
      else
        v[j] = 0
      end
    end
    len = norm_of(v, d)
  end
  for j = 1, d do v[j] = len > 0 and v[j] / len or 0 end
  return v
end

-- The derivative's direction at (k, t), unit length; a zero derivative
-- (a cusp, or a control point on its end point) takes the limit from the
-- next derivatives: z'' (its negative at t = 1, approached from the left),
-- then z'''.  A segment that is a single point has no direction: zeros.
local function direction(self, k, t)
  local c, d, kind = segs_of(self)[k], self.dim, kind_of(self, k)
  if kind ~= "cubic" then return other_direction(kind, c, d, t) end
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
  if walks(self) then return walk_at(self, (reduce(self, s, L)), false, "point") end
  local k, t = locate(self, (reduce(self, s, L)))
  return seg_point(kind_of(self, k), segs_of(self)[k], t)
end

-- p:tangent(s) -> the unit tangent tx, ty[, tz] at distance s (at a joint,
-- the direction leaving it; at the end, the direction arriving).
function Path:tangent(s)
  check_self(self, "tangent")
  check_number(s, 1, "tangent", "distance")
  local L = usable(self, "tangent")
  if self.n == 0 then return unpack_dim({0, 0, 0}, self.dim) end
  if walks(self) then return walk_at(self, (reduce(self, s, L)), false, "tangent") end
  local k, t = locate(self, (reduce(self, s, L)))
  return unpack_dim(direction(self, k, t), self.dim)
end

-- A new path with the same options from a fresh list of segments (its
-- own: it becomes the path's segment list) with gap marks pieces.gap[k]
-- (nil when there are none).  Three tables a path: dash makes one a dash.
local function from_pieces(self, pieces, x0, y0, z0)
  local n, gap, kinds = #pieces, pieces.gap, pieces.kinds
  pieces.gap, pieces.kinds = nil, nil
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
    kindstr = kinds and n > 0 and table.concat(kinds) or nil, x0 = x0, y0 = y0, z0 = z0}, Path)
end

-- The segments from (k0, t0) to (k1, t1) -- distances a <= b (in [0, L])
-- located -- as a list with gap marks, and the start point.
local function pieces_located(self, k0, t0, k1, t1)
  local out = {}                 -- out.gap made at the first gap
  local d, segs = self.dim, segs_of(self)
  if k1 < k0 or (k1 == k0 and t1 <= t0) then
    local x, y, z = seg_point(kind_of(self, k0), segs[k0], t0)
    return out, x, y, z
  end
  local kinds = self.kindstr and {}
  local isgap = self.isgap
  if not isgap then
    isgap = {}
    for j = 2, self.nsub do isgap[self.first[j]] = true end
    self.isgap = isgap
  end
  for k = k0, k1 do
    local c, kind = segs[k], kind_of(self, k)
    local ta, tb = k == k0 and t0 or 0, k == k1 and t1 or 1
    if ta ~= 0 or tb ~= 1 then c = seg_sub(kind, c, ta, tb) end
    if tb > ta or (ta == 0 and tb == 1) then
      out[#out + 1] = c
      if kinds then kinds[#out] = LETTER[kind] end
      if isgap[k] and k > k0 then
        out.gap = out.gap or {}
        out.gap[#out] = true
      end
    end
  end
  if #out == 0 then
    local x, y, z = seg_point(kind_of(self, k0), segs[k0], t0)
    return out, x, y, z
  end
  out.kinds = kinds
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
  local x, y, z = seg_point(kind_of(self, k), segs_of(self)[k], t)
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
    local div = self.cyclic and n or n - 1
    if walks(self) then
      dists = {n = n, div = div}     -- the walk makes them: L i / div, L at i = div
    else
      dists = new_array(n)
      for i = 0, n - 1 do dists[i + 1] = i == div and L or L * i / div end
    end
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
  local out = new_array(dists.n or #dists)
  if self.n == 0 then
    for i = 1, #dists do
      out[i] = {x = self.x0, y = self.y0, z = self.z0, s = 0, time = 0,
                tx = 0, ty = 0, tz = self.dim == 3 and 0 or nil}
    end
    return out
  end
  if walks(self) then
    if self.kindstr then
      walk_samples(self.packed or self.segs, self.cum, dists, self.tol, out, nil, nil, self.kindstr)
    else
      walk_samples(self.packed or self.segs, self.cum, dists, self.tol, out)
    end
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
    if pts then
      walk_samples(self.packed or self.segs, self.cum, ds, self.tol, pts, tans or false,
                   times or false, self.kindstr)
    else
      walk_samples(self.packed or self.segs, self.cum, ds, self.tol, out, nil, nil, self.kindstr)
    end
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
      error(format("'dash': more than %d dashes (pattern too fine)", MAX_POINTS), caller(2))
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

-- p:segments() -> the number of segments; p:segment(k) -> a copy of
-- segment k's numbers and its kind name ("line", "quad", "cubic",
-- "conic").
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
  return out, kind_of(self, k)
end

-- The shortest of %.15g, %.16g, %.17g that reads back as x.
local num = numtext.shortest

-- An elliptic conic (w < 1) as SVG's arc: the conic is c + U cos th + V
-- sin th, th in [-al, al] (pure_segment.lua's derivation: U = D w/(1 -
-- w^2), V = h/sqrt(1 - w^2)); the matrix [U V] = Rot(phi) diag(rx, +-ry)
-- Rot(g) gives the semi-axes rx >= ry (its singular values, ry = |det|/rx
-- so that a thin ellipse keeps its digits) and the x-axis rotation phi;
-- the span 2 al < pi (large-arc 0); th runs the positive way when det > 0
-- (sweep 1).  nil when the conic is degenerate (det 0, or P0 = P2).
local function conic_arc(c)
  local w = c[7]
  local one = (1 - w) * (1 + w)
  local hx, hy = (c[5] - c[1]) / 2, (c[6] - c[2]) / 2
  local dx, dy = (c[3] - c[1]) - hx, (c[4] - c[2]) - hy
  local ux, uy = dx * w / one, dy * w / one
  local s = sqrt(one)
  local vx, vy = hx / s, hy / s
  local det = ux * vy - uy * vx
  if not (det ~= 0) or (hx == 0 and hy == 0) then return nil end
  local E, F = (ux + vy) / 2, (ux - vy) / 2
  local G, H = (uy + vx) / 2, (uy - vx) / 2
  local Q, R = sqrt(E * E + H * H), sqrt(F * F + G * G)
  local rx = Q + R
  local ry = abs(det) / rx
  local atan2 = math.atan2 or math.atan       -- Lua 5.1's name, 5.4's
  local phi = (atan2(G, F) + atan2(H, E)) / 2
  local deg = phi * (180 / math.pi)
  if not (rx > 0 and ry > 0 and rx < huge) then return nil end
  if rx - ry <= 4 * 2.220446049250313e-16 * rx then   -- a circle to rounding: no axis
    rx = sqrt(abs(det))
    ry, deg = rx, 0
  end
  return rx, ry, deg, det > 0 and 1 or 0
end

-- Is the conic the straight segment P0 P2 (P1 on it, ends included)?
-- Its points are then weighted means of 0, lambda, 1 along it (variation
-- diminishing: the segment, once).
local function straight_conic(c)
  local ex, ey = c[5] - c[1], c[6] - c[2]
  local px, py = c[3] - c[1], c[4] - c[2]
  if ex * py - ey * px ~= 0 then return false end
  local ee = ex * ex + ey * ey
  local lam = ee > 0 and (px * ex + py * ey) / ee or -1
  return lam >= 0 and lam <= 1
end

-- p:svg() -> SVG path data (absolute commands, Z on a cyclic path) that
-- reads back to the same segments (2D paths): a line as L, a quadratic
-- as Q, a cubic as C, an elliptic conic (w < 1) as A (exact: an SVG arc
-- is the same ellipse, read back to rounding), a parabolic one (w = 1) as
-- Q, a straight one as L; a hyperbolic one (w > 1) has no SVG command:
-- cubics within tol (Hausdorff distance tol times its longer leg).
function Path:svg()
  check_self(self, "svg")
  if self.dim ~= 2 then error("'svg': SVG path data is 2D; this path is 3D", caller(2)) end
  local out = {}
  if self.n == 0 then return "M" .. num(self.x0) .. " " .. num(self.y0) end
  local isgap = {}
  for j = 1, self.nsub do isgap[self.first[j]] = true end
  local segs = segs_of(self)
  local function cubic(c)
    out[#out + 1] = format("C%s %s %s %s %s %s", num(c[3]), num(c[4]), num(c[5]),
                           num(c[6]), num(c[7]), num(c[8]))
  end
  for k = 1, self.n do
    local c, kind = segs[k], kind_of(self, k)
    if isgap[k] then out[#out + 1] = "M" .. num(c[1]) .. " " .. num(c[2]) end
    if kind == "cubic" then cubic(c)
    elseif kind == "line" then out[#out + 1] = format("L%s %s", num(c[3]), num(c[4]))
    elseif kind == "quad" or (kind == "conic" and c[7] == 1) then
      out[#out + 1] = format("Q%s %s %s %s", num(c[3]), num(c[4]), num(c[5]), num(c[6]))
    else
      local rx, ry, deg, sweep
      if c[7] < 1 then rx, ry, deg, sweep = conic_arc(c) end
      if not rx and straight_conic(c) then
        out[#out + 1] = format("L%s %s", num(c[5]), num(c[6]))
      elseif rx then
        out[#out + 1] = format("A%s %s %s 0 %d %s %s", num(rx), num(ry), num(deg), sweep,
                               num(c[5]), num(c[6]))
      else
        for _, q in ipairs(conic_cubics(c, 2, self.tol)) do cubic(q) end
      end
    end
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
  if R.kinds ~= nil and (type(R.kinds) ~= "string" or #R.kinds ~= R.n
                         or R.kinds:find("[^LQCR]")) then
    argerror(1, fname, "kinds must be a string of one letter (L, Q, C, R) per segment")
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
