-- spec/path_spec.lua -- arclen.path: construction (cubics, SVG, mplib knot
-- tables), length, time (MetaPost's path time), point, tangent, split, sub,
-- resample, dash; the cumulative cache and the O(log n) search; method =
-- "metapost" against real MetaPost (mpost and LuaTeX's mplib).
-- References: spec/data/paths.tsv (mpmath, tools/ref_paths.py),
-- spec/data/mpost_paths.tsv (mpost, tools/ref_mpost.py),
-- spec/data/mplib_knots.tsv (texlua's mplib, tools/ref_mplib.lua).
local arclen = require("arclen")
local H = require("helpers")
local path = require("arclen.path")
local unpack = table.unpack or unpack

local function hypot(x, y) return math.sqrt(x * x + y * y) end

local SQ = "M0 0 L10 0 L10 10 L0 10 Z"   -- a square: every answer is exact

describe("arclen.path: construction", function()
  it("is reached from the module as arclen.path", function()
    assert.are.equal(path, arclen.path)
    assert.are.equal(path.svg, arclen.path.svg)
  end)

  H.c_only(it, "3D curves")("takes a list of cubics (8 numbers or 4 points), 2D or 3D", function()
    local p = arclen.path({{0, 0, 1, 0, 2, 0, 3, 0}, {{3, 0}, {3, 1}, {3, 2}, {3, 3}}})
    assert.are.equal(2, p:segments())
    assert.are.equal(6, p:length())
    local q = arclen.path({{0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}})
    assert.are.equal(3, q.dim)
    assert.is_true(math.abs(q:length() - 3 * math.sqrt(3)) <= 1e-12 * 6)
    local x, y, z = q:point(math.sqrt(3))
    assert.is_true(math.abs(x - 1) + math.abs(y - 1) + math.abs(z - 1) <= 1e-12)
  end)

  it("starts a new subpath where a cubic does not start at the previous end", function()
    local p = arclen.path({{0, 0, 1, 0, 2, 0, 3, 0}, {5, 0, 6, 0, 7, 0, 8, 0}})
    assert.are.equal(2, p.nsub)
    assert.are.equal(6, p:length())
    -- distances skip the gap: 3 is the end of the first part / start of the next
    assert.are.equal(5, (p:point(3)))
  end)

  it("makes a cyclic path only where it closes", function()
    local c = arclen.path({{0, 0, 1, 0, 2, 0, 3, 0}, {3, 0, 2, 0, 1, 0, 0, 0}}, {cyclic = true})
    assert.is_true(c.cyclic)
    assert.matches("#1.*must end where it starts",
      H.error_of(arclen.path, {{0, 0, 1, 0, 2, 0, 3, 0}}, {cyclic = true}))
    assert.matches("#1.*must not have gaps",
      H.error_of(arclen.path, {{0, 0, 1, 0, 2, 0, 3, 0}, {5, 0, 6, 0, 7, 0, 0, 0}}, {cyclic = true}))
  end)

  it("names the argument for bad input", function()
    local E = H.error_of
    assert.matches("#1 to 'arclen.path' %(a list of segments expected, got string", E(arclen.path, "x"))
    assert.matches("#1.*at least one segment", E(arclen.path, {}))
    assert.matches("#1.*cubic 2 must have 8 %(2D%) or 12 %(3D%) numbers, got 3",
      E(arclen.path, {{0, 0, 1, 0, 2, 0, 3, 0}, {1, 2, 3}}))
    assert.matches("#1.*cubic 1: coordinate 3 must be a finite number",
      E(arclen.path, {{0, 0, 0 / 0, 0, 2, 0, 3, 0}}))
    assert.matches("#1.*cubic 2 is 3D, the first is 2D",
      E(arclen.path, {{0, 0, 1, 0, 2, 0, 3, 0}, {3, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}}))
    assert.matches("#2.*unknown option 'x'", E(arclen.path, {{0, 0, 1, 0, 2, 0, 3, 0}}, {x = 1}))
    assert.matches("#2.*cyclic must be a boolean", E(arclen.path, {{0, 0, 1, 0, 2, 0, 3, 0}}, {cyclic = 1}))
    local p = path.svg(SQ)
    assert.matches("#1 to 'point' %(distance must be a number, got nil", E(p.point, p))
    assert.matches("#1 to 'time' %(distance must be finite", E(p.time, p, 0 / 0))
    assert.matches("#1 to 'tangent' %(distance must be finite", E(p.tangent, p, math.huge))
    assert.matches("calling 'length' on bad self", E(p.length, {}))
    assert.matches("#1 to 'resample' %(n must be an integer in %[2,", E(p.resample, path.svg("M0 0 L1 0"), 1))
    assert.matches("#1 to 'resample' %(n must be an integer", E(p.resample, p, 2.5))
    assert.matches("#1 to 'resample' %(step must be a positive", E(p.resample, p, {step = 0}))
    assert.matches("#1 to 'resample' %(step too small", E(p.resample, p, {step = 1e-9}))
    assert.matches("#1 to 'resample' %(unknown option 'stp'", E(p.resample, p, {stp = 1}))
    assert.matches("#1 to 'dash' %(dash pattern must not be all zero", E(p.dash, p, {0, 0}))
    assert.matches("#1 to 'dash' %(dash pattern entry 2 must be", E(p.dash, p, {1, -1}))
    assert.matches("#2 to 'dash' %(offset must be finite", E(p.dash, p, {1, 1}, 0 / 0))
    assert.matches("pattern too fine", E(p.dash, p, {1e-8, 1e-8}))
    assert.matches("#1 to 'segment' %(k must be an integer in %[1, 4%]", E(p.segment, p, 5))
    assert.matches("has no time", E(p.point, path.svg(SQ, {method = "elliptic"}), 1))
  end)
end)

describe("arclen.path: distances on a square (exact answers)", function()
  local p = path.svg(SQ)
  it("length, time (MetaPost's segment index + parameter), point, tangent", function()
    assert.are.equal(40, p:length())
    assert.is_true(p.cyclic)
    assert.are.equal(0, p:time(0))
    assert.is_true(math.abs(p:time(15) - 1.5) <= 1e-12)
    local x, y = p:point(15)
    assert.is_true(math.abs(x - 10) + math.abs(y - 5) <= 1e-12 * 40)
    local tx, ty = p:tangent(15)
    assert.are.equal(0, tx)
    assert.are.equal(1, ty)
    -- at a joint the direction leaving it; at the end of an open path the arriving one
    tx, ty = p:tangent(10)
    assert.are.equal(0, tx)
    assert.are.equal(1, ty)
    local o = path.svg("M0 0 L10 0 L10 10")
    tx, ty = o:tangent(20)
    assert.are.equal(0, tx)
    assert.are.equal(1, ty)
  end)

  it("wraps distances on a cyclic path (MetaPost: n + time, negative backwards)", function()
    assert.is_true(math.abs(p:time(55) - 5.5) <= 1e-12)
    assert.is_true(math.abs(p:time(-5) - (-0.5)) <= 1e-12)
    local x, y = p:point(-5)
    assert.is_true(math.abs(x - 0) + math.abs(y - 5) <= 1e-12 * 40)
  end)

  it("clamps distances on an open path (times 0 and n)", function()
    local o = path.svg("M0 0 L10 0 L10 10")
    assert.are.equal(0, o:time(-3))
    assert.are.equal(2, o:time(100))
    local x, y = o:point(100)
    assert.are.equal(10, x)
    assert.are.equal(10, y)
  end)

  it("splits at a distance into two paths whose lengths add up", function()
    local a, b = p:split(15)
    assert.are.equal(2, a:segments())
    assert.are.equal(3, b:segments())
    assert.is_true(math.abs(a:length() - 15) <= 1e-12 * 40)
    assert.is_true(math.abs(b:length() - 25) <= 1e-12 * 40)
    local x, y = b:point(0)
    assert.is_true(math.abs(x - 10) + math.abs(y - 5) <= 1e-12 * 40)
    local e0, e1 = p:split(0)
    assert.are.equal(0, e0:segments())
    assert.are.equal(40, e1:length())
    local w0, w1 = p:split(40)
    assert.are.equal(40, w0:length())
    assert.are.equal(0, w1:segments())
    local x1, y1 = w1:point(0)
    assert.are.equal(0, x1)
    assert.are.equal(0, y1)
  end)

  it("sub(s0, s1) is the part between two distances; s1 <= s0 is a point", function()
    local s = p:sub(5, 25)
    assert.is_true(math.abs(s:length() - 20) <= 1e-12 * 40)
    assert.are.equal(3, s:segments())
    assert.are.equal(0, p:sub(7, 7):segments())
    assert.are.equal(0, p:sub(7, 3):segments())
  end)

  it("resamples n points (open: both ends; cyclic: n points L/n apart) or by step", function()
    local pts = p:resample(8)
    assert.are.equal(8, #pts)
    for i, q in ipairs(pts) do
      assert.is_true(math.abs(q.s - 5 * (i - 1)) <= 1e-12)
      local x, y = p:point(q.s)
      assert.are.equal(x, q.x)
      assert.are.equal(y, q.y)
      assert.is_true(math.abs(hypot(q.tx, q.ty) - 1) <= 1e-15)
    end
    local o = path.svg("M0 0 L10 0 L10 10")
    local ends = o:resample(3)
    assert.are.same({0, 10, 20}, {ends[1].s, ends[2].s, ends[3].s})
    assert.are.equal(10, ends[3].x)
    assert.are.equal(10, ends[3].y)
    local st = o:resample({step = 3})
    assert.are.equal(7, #st)                 -- 0, 3, ..., 18
    assert.are.equal(18, st[7].s)
    assert.are.equal(8, #p:resample({step = 5}))   -- cyclic: 40 is the start again
  end)

  it("dashes: SVG's dasharray (odd counts repeat) and dashoffset", function()
    local d = p:dash({10, 5})
    local lens = {}
    for i, dash in ipairs(d) do lens[i] = dash:length() end
    assert.are.same({10, 10, 10}, lens)      -- at 0, 15, 30 (30..40)
    local x, y = d[2]:point(0)
    assert.is_true(math.abs(x - 10) + math.abs(y - 5) <= 1e-12 * 40)
    local odd = p:dash({4})                  -- = {4, 4}
    assert.are.equal(5, #odd)
    local off = p:dash({10, 5}, 3)           -- starts 3 into the first dash
    assert.is_true(math.abs(off[1]:length() - 7) <= 1e-12 * 40)
    assert.is_true(math.abs(off[2]:length() - 10) <= 1e-12 * 40)
    local neg = p:dash({10, 5}, -2)          -- 2 before the pattern: a gap of 2 first
    local nx = neg[1]:point(0)
    assert.is_true(math.abs(nx - 2) <= 1e-12 * 40)
    local dots = path.svg("M0 0 L10 0"):dash({0, 2.5})
    assert.are.equal(4, #dots)               -- points at 0, 2.5, 5, 7.5
    assert.are.equal(0, dots[2]:segments())
    assert.is_true(math.abs(dots[2]:point(0) - 2.5) <= 1e-12)
  end)

  it("restarts the dash pattern at each subpath", function()
    local two = path.svg("M0 0 L7 0 M0 5 L7 5")
    local d = two:dash({5, 5})
    assert.are.equal(2, #d)
    for _, dash in ipairs(d) do assert.is_true(math.abs(dash:length() - 5) <= 1e-12 * 5) end
    local _, y = d[2]:point(0)
    assert.are.equal(5, y)
  end)

  it("writes SVG path data that reads back to the same segments", function()
    local q = path.svg("M0.1 0.2 C1 2 3 4 5 6 Q7 8 9 1 M3 3 L4 4")
    local back = path.svg(q:svg())
    assert.are.equal(q:segments(), back:segments())
    for k = 1, q:segments() do assert.are.same(q:segment(k), back:segment(k)) end
    assert.matches("Z$", p:svg())
  end)
end)

describe("arclen.path: against mpmath (spec/data/paths.tsv)", function()
  local rows = {}
  for _, row in ipairs(H.tsv("paths.tsv")) do
    if row.arcs == "0" then rows[#rows + 1] = row end
  end
  local nums = H.numbers
  for _, tol in ipairs({1e-12, 1e-9, 1e-6}) do
    it(("points at distances within tol * L, right segment of the time (tol %g)"):format(tol), function()
      assert.is_true(#rows >= 14)
      local w = H.worst()
      for _, row in ipairs(rows) do
        local p = path.svg(row.d, {tol = tol})
        local L = tonumber(row.L)
        assert.is_true(math.abs(p:length() - L) <= tol * L, row.id)
        local goals, times, xs, ys = nums(row.goals), nums(row.times), nums(row.xs), nums(row.ys)
        for i, s in ipairs(goals) do
          local x, y = p:point(s)
          local T = p:time(s)
          -- the point is within tol * L along the path of the true one (the
          -- chord is shorter), plus the rounding of its coordinates
          local scale = math.max(math.abs(xs[i]), math.abs(ys[i]))
          local err = hypot(x - xs[i], y - ys[i])
          assert.is_true(err <= tol * L + 8 * 2.2e-16 * scale,
            ("%s at %g: point off by %g"):format(row.id, s, err))
          assert.are.equal(math.floor(times[i]), math.floor(T))
          w:add(err / L, row.id)
        end
      end
      print(("  path points (tol %g): worst distance / L %.3g (%s)"):format(tol, w.err, w.id))
    end)
  end
end)

describe("arclen.path: the cache and the search", function()
  local parts = {"M0 0"}
  for i = 1, 1000 do
    parts[#parts + 1] = ("C%d 10 %d -10 %d 0"):format(10 * i - 7, 10 * i - 3, 10 * i)
  end
  local p = path.svg(table.concat(parts, " "))

  it("measures each segment once", function()
    -- the path layer calls the engine (arclen.engine) directly: a path read
    -- from path data measures its packed cubics (a string of doubles; a
    -- flat table on the Lua engine) in one arclen.lengths call
    local core = require "arclen.engine"
    local real, real_batch, calls = core.length, core.lengths, 0
    core.length = function(...) calls = calls + 1; return real(...) end
    core.lengths = function(packed, ...)
      calls = calls + (type(packed) == "string" and #packed / 64 or #packed / 8)
      return real_batch(packed, ...)
    end
    local ok, err = pcall(function()
      p:length(); p:time(5000); p:point(123); p:resample(50)
    end)
    core.length, core.lengths = real, real_batch
    assert(ok, err)
    assert.are.equal(1000, calls)
  end)

  it("finds the segment of a distance in O(log n) lookups of the cumulative lengths", function()
    -- the C core reads them raw (lua_rawgeti, no __index to count: its
    -- search is the walk's gallop and bisection); the Lua engine's reads
    -- are counted here, and the path layer's own on either engine
    p:length()
    local real = p.cum
    local reads = 0
    p.cum = setmetatable({}, {__index = function(_, k) reads = reads + 1; return real[k] end})
    local worst = 0
    for _, s in ipairs({1, 777.7, 5000, 9999, 15000}) do
      reads = 0
      p:time(s)
      worst = math.max(worst, reads)
    end
    p.cum = real
    -- 10 halvings for 1000 segments, two reads each, plus the segment's ends
    assert.is_true(worst <= 2 * 10 + 6, "cumulative lengths read " .. worst .. " times")
    assert.is_true(worst > (H.engine == "lua" and 10 or 0))
  end)

  it("gives a distance's time, point and tangent as the walk gives them alone, to the bit", function()
    -- (a walk's run of distances in one segment shares the tolerance
    -- between them: bits then differ, each within tol L)
    local mixed = path.svg("M0 0 L10 0 Q15 5 10 10 A5 5 0 0 1 0 10 C-5 5 -5 0 0 0")
    for _, q in ipairs({p, mixed}) do
      local L = q:length()
      for _, f in ipairs({0, 1e-9, 1e-3, 0.1, 0.25, 1 / 3, 0.5, 0.61, 0.8, 1 - 1e-9, 1}) do
        local s = f * L
        local pts, tans, times = q:points({s}, {times = true, tangents = true})
        assert.are.equal(times[1], q:time(s), "time at " .. s)
        local x, y = q:point(s)
        assert.are.equal(pts[1], x, "x at " .. s)
        assert.are.equal(pts[2], y, "y at " .. s)
        local tx, ty = q:tangent(s)
        assert.are.equal(tans[1], tx, "tx at " .. s)
        assert.are.equal(tans[2], ty, "ty at " .. s)
      end
    end
  end)

  it("gives times that increase with the distance and end at n", function()
    local last = -1
    for _, q in ipairs(p:resample(2001)) do
      assert.is_true(q.time >= last)
      last = q.time
    end
    assert.are.equal(1000, last)
  end)
end)

describe("arclen.path: resample spacing", function()
  it("makes its distances L i / (n - 1) (cyclic: L i / n) as a list of them gives", function()
    for _, d in ipairs({"M0 0 L10 0 Q15 5 10 10 A5 5 0 0 1 0 10 C-5 5 -5 0 3 1",
                        "M0 0 C10 10 20 -10 30 0 L30 7 Z"}) do
      local p = path.svg(d, {tol = 1e-12})
      local L, n = p:length(), 37
      local div = p.cyclic and n or n - 1
      local ds = {}
      for i = 0, n - 1 do ds[i + 1] = i == div and L or L * i / div end
      local a, b = p:resample(n), p:samples(ds)
      assert.are.equal(n, #a)
      for i = 1, n do
        for _, key in ipairs({"x", "y", "s", "time", "tx", "ty"}) do
          assert.are.equal(b[i][key], a[i][key], ("%s, point %d: %s"):format(d, i, key))
        end
      end
      if not p.cyclic then assert.are.equal(L, a[n].s) end
    end
  end)

  it("spaces points evenly along the path to tol * L", function()
    local p = path.svg("M100 100 C300 0 0 0 200 100 C250 200 -100 300 100 100", {tol = 1e-12})
    local L = p:length()
    local pts = p:resample(100)
    for i = 2, #pts do
      local piece = p:sub(pts[i - 1].s, pts[i].s):length()
      assert.is_true(math.abs(piece - L / 99) <= 3e-12 * L, ("gap %d: %.17g"):format(i, piece))
    end
  end)

  it("gives unit tangents, also where a control point sits on its end (limit direction)", function()
    local p = path.svg("M0 0 C0 0 10 0 10 10")   -- z'(0) = 0: leaves along +x
    local tx, ty = p:tangent(0)
    assert.is_true(math.abs(tx - 1) <= 1e-15 and math.abs(ty) <= 1e-15)
    local q = path.svg("M0 0 C10 0 10 10 10 10") -- z'(1) = 0: arrives along +y
    tx, ty = q:tangent(q:length())
    assert.is_true(math.abs(tx) <= 1e-15 and math.abs(ty - 1) <= 1e-15)
    local pt = path.svg("M3 3 L3 3")
    tx, ty = pt:tangent(0)
    assert.are.equal(0, tx)
    assert.are.equal(0, ty)
  end)
end)

describe("arclen.path: paths without segments", function()
  it("are points: length 0, time 0, the point itself", function()
    local p = path.svg("M3 4")
    assert.are.equal(0, p:length())
    assert.are.equal(0, p:time(5))
    local x, y = p:point(1)
    assert.are.equal(3, x)
    assert.are.equal(4, y)
    assert.are.equal(2, #p:resample(2))
    assert.are.same({}, p:dash({1, 1}))
  end)
end)

-- mplib's knot tables, as LuaTeX hands them over (spec/data/mplib_knots.tsv)
local FIELDS = {"x_coord", "y_coord", "left_x", "left_y", "right_x", "right_y"}
local function knots_of(row)
  local knots = {}
  for cell in row.knots:gmatch("[^;]+") do
    local v = {}
    for w in cell:gmatch("%S+") do v[#v + 1] = w end
    local kn = {}
    for i, f in ipairs(FIELDS) do kn[f] = tonumber(v[i]) end
    if v[7] ~= "-" then kn.left_type = v[7] end
    if v[8] ~= "-" then kn.right_type = v[8] end
    knots[#knots + 1] = kn
  end
  return knots
end

describe("arclen.path.mplib: knot tables from LuaTeX's mplib", function()
  local rows = H.tsv("mplib_knots.tsv")

  H.c_only(it, "method 'metapost'")("reads every path (open, cyclic, a lone point) and agrees with MetaPost bit for bit", function()
    assert.is_true(#rows >= 10)
    local bad, cyc = {}, 0
    for _, row in ipairs(rows) do
      local knots = knots_of(row)
      local p = path.mplib(knots, {method = "metapost"})
      assert.are.equal(row.cyclic == "true", p.cyclic)
      if p.cyclic then cyc = cyc + 1 end
      assert.are.equal(p.cyclic and #knots or #knots - 1, p:segments())
      if p:length() ~= tonumber(row.L) then bad[#bad + 1] = row.id .. " L" end
      local gs, ts = H.numbers(row.goals), H.numbers(row.times)
      for i, g in ipairs(gs) do
        if p:time(g) ~= ts[i] then bad[#bad + 1] = row.id .. " time " .. i end
      end
    end
    assert.are.same({}, bad)
    assert.is_true(cyc >= 4)
  end)

  it("measures mplib paths with the default method to tol (MetaPost itself is ~1e-5)", function()
    for _, row in ipairs(rows) do
      local p = path.mplib(knots_of(row))
      local want = 0
      for k = 1, p:segments() do want = want + arclen.length(p:segment(k), {tol = 1e-15}) end
      assert.is_true(math.abs(p:length() - want) <= 1e-12 * want, row.id)
      -- MetaPost's +2^-17 per segment and absolute 1/4096 tolerance
      assert.is_true(math.abs(p:length() - tonumber(row.L)) <= 1e-3, row.id)
    end
  end)

  it("takes a figure object's path field, and the cycle field of newer LuaTeX", function()
    local knots = knots_of(rows[1])
    assert.are.equal(path.mplib(knots):length(), path.mplib({path = knots}):length())
    local open = knots_of(rows[1])
    open.cycle = true
    assert.is_true(path.mplib(open).cyclic)
  end)

  it("names what is wrong with a knot", function()
    local E = H.error_of
    assert.matches("#1 to 'arclen.path.mplib' %(knot 2: right_y must be a number, got nil",
      E(path.mplib, {{x_coord = 0, y_coord = 0, left_x = 0, left_y = 0, right_x = 1, right_y = 1},
                     {x_coord = 0, y_coord = 0, left_x = 0, left_y = 0, right_x = 1}}))
    assert.matches("#1.*has no knots", E(path.mplib, {}))
    assert.matches("#1.*a table of knots%) expected, got number", E(path.mplib, 3))
    assert.matches("#1.*knot 1: x_coord must be finite",
      E(path.mplib, {{x_coord = 1 / 0, y_coord = 0, left_x = 0, left_y = 0, right_x = 1, right_y = 1}}))
  end)
end)

describe("arclen.path with method = 'metapost' (spec/data/mpost_paths.tsv)", function()
  local it = H.c_only(it, "method 'metapost'")
  local function csv(s)
    local out = {}
    for v in s:gmatch("[^,]+") do out[#out + 1] = tonumber(v) end
    return out
  end
  it("has mpost's path length and path time bit for bit", function()
    local bad, n = {}, 0
    for _, row in ipairs(H.tsv("mpost_paths.tsv")) do
      local v, segs = csv(row.coords), {}
      for k = 1, tonumber(row.n) do segs[k] = {unpack(v, 8 * k - 7, 8 * k)} end
      local ok, p = pcall(arclen.path, segs, {method = "metapost", cyclic = row.cyclic == "1"})
      if ok and p.nsub == 1 then
        n = n + 1
        local L = p:length()
        if L ~= tonumber(row.L) then bad[#bad + 1] = row.id .. " L" end
        local goals, times = csv(row.goals), csv(row.times)
        for i, g in ipairs(goals) do
          if L and p:time(g) ~= times[i] then bad[#bad + 1] = row.id .. " goal " .. g end
        end
      end
    end
    assert.are.same({}, bad)
    assert.is_true(n >= 20)
  end)

  it("returns nil and MetaPost's message on arithmetic overflow", function()
    local p = arclen.path({{0, 0, 20000, 0, 20000, 0, 40000, 0}}, {method = "metapost"})
    local L, msg = p:length()
    assert.is_nil(L)
    assert.matches("overflow", msg)
    assert.matches("overflow", H.error_of(p.point, p, 1))
  end)
end)
