-- arclen.times (arclen_times: many distances on one cubic in one pass) and
-- the path layer's walk over it (resample, dash, points, samples).  Every
-- t must be within tol * L of the truth, as arclen.time's: checked against
-- the 40-digit references of tools/ref_lengths.py and tools/ref_paths.py,
-- and against arclen.time at tol 1e-15.
local arclen = require("arclen")
local H = require("helpers")
local path = require("arclen.path")

-- Relative error bound for a requested tolerance (as length_spec.lua).
local function bound(tol) return tol < 1e-14 and 1e-14 or tol end

local function speed(c, t)
  local d = {arclen.derivative(c, t)}
  local s = 0
  for _, v in ipairs(d) do s = s + v * v end
  return math.sqrt(s)
end

-- |s(t) - s(T)| <= |t - T| max speed (s is monotone; the speed is a
-- quadratic's norm, its ends bound it for |t - T| this small).
local function ds(c, t, T)
  return math.abs(t - T) * math.max(speed(c, t), speed(c, T))
end

local rng = require("helpers").rng

for _, file in ipairs({"curves2d.tsv", "curves3d.tsv"}) do
  describe("arclen.times against mpmath (" .. file .. ")", function()
    local rows = H.tsv(file)
    local it = file:find("3d") and H.c_only(it, "3D curves") or it
    for _, tol in ipairs({1e-12, 1e-15}) do
      it(("L/4, L/2, 3L/4 in one call: |s(t) - s| <= %g L (tol %g)"):format(bound(tol), tol), function()
        local worst = H.worst()
        for _, row in ipairs(rows) do
          local L = tonumber(row.L)
          if L > 0 then
            local c = H.curve(row)
            local ts = arclen.times(c, {0.25 * L, 0.5 * L, 0.75 * L}, {tol = tol})
            for q, key in ipairs({"T25", "T50", "T75"}) do
              assert.is_true(ts[q] >= 0 and ts[q] <= 1, row.id)
              worst:add(ds(c, ts[q], tonumber(row[key])) / L, row.id .. " " .. key)
            end
          end
        end
        assert.is_true(worst.err <= bound(tol),
          ("worst %s: %.3g > %.3g"):format(tostring(worst.id), worst.err, bound(tol)))
      end)
    end
    it("many distances (dense, random, repeated) agree with arclen.time at tol 1e-15", function()
      local r = rng(2718)
      local worst = H.worst()
      for _, row in ipairs(rows) do
        local L = tonumber(row.L)
        if L > 0 then
          local c = H.curve(row)
          local s = {}
          for q = 1, 60 do s[q] = L * (q - 1) / 59 end     -- evenly spaced
          for q = 61, 90 do s[q] = L * (1.2 * r() - 0.1) end
          s[91], s[92] = s[70], s[70]
          table.sort(s)
          local ts = arclen.times(c, s, {tol = 1e-15})
          for q = 1, #s do
            local t1 = arclen.time(c, s[q], {tol = 1e-15})
            -- each within bound(1e-15) L of the truth
            worst:add(ds(c, ts[q], t1) / L / 2, row.id)
            if q > 1 then assert.is_true(ts[q] >= ts[q - 1], row.id .. ": monotone") end
            if s[q] <= 0 then assert.are.equal(0, ts[q]) end
            if s[q] >= L * (1 + 1e-9) then assert.are.equal(1, ts[q]) end
          end
        end
      end
      assert.is_true(worst.err <= bound(1e-15),
        ("worst %s: %.3g > %.3g"):format(tostring(worst.id), worst.err, bound(1e-15)))
    end)
  end)
end

describe("arclen.times: points and tangents", function()
  local c = {0, 0, 10, 0, 10, 10, 0, 0}
  it("returns the points and unit tangents of its times", function()
    local ts, pts, tans = arclen.times(c, {1, 5, 9}, {points = true, tangents = true})
    assert.are.equal(3, #ts)
    assert.are.equal(6, #pts)
    assert.are.equal(6, #tans)
    for q = 1, 3 do
      local x, y = arclen.point(c, ts[q])
      assert.are.equal(x, pts[2 * q - 1])
      assert.are.equal(y, pts[2 * q])
      local dx, dy = arclen.derivative(c, ts[q])
      local n = math.sqrt(dx * dx + dy * dy)
      assert.are.equal(dx / n, tans[2 * q - 1])
      assert.are.equal(dy / n, tans[2 * q])
    end
    local ts2, tans2 = arclen.times(c, {1, 5, 9}, {tangents = true})
    assert.are.same(ts, ts2)
    assert.are.same(tans, tans2)
    assert.are.same({}, arclen.times(c, {}))
  end)
  it("takes the limit direction at a cusp and gives zeros on a point", function()
    local _, _, tans = arclen.times({0, 0, 0, 0, 1, 0, 1, 0}, {0}, {points = true, tangents = true})
    assert.are.same({1, 0}, tans)
    local _, pts, v = arclen.times({2, 3, 2, 3, 2, 3, 2, 3}, {0, 1}, {points = true, tangents = true})
    assert.are.same({2, 3, 2, 3}, pts)
    assert.are.same({0, 0, 0, 0}, v)
  end)
  H.c_only(it, "3D curves")("measures 3D curves", function()
    local q = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}
    local ts, pts = arclen.times(q, {math.sqrt(3)}, {points = true})
    assert.is_true(math.abs(ts[1] - 1 / 3) < 1e-12)
    assert.are.equal(3, #pts)
  end)
end)

describe("arclen.times: bad input", function()
  local c = {0, 0, 10, 0, 10, 10, 0, 0}
  local function err(...)
    local ok, msg = pcall(arclen.times, ...)
    assert.is_false(ok)
    return msg
  end
  it("names the argument", function()
    assert.matches("bad argument #2 to '[^']*' %(distances must be sorted %(ascending%)%)",
      err(c, {2, 1}))
    assert.matches("bad argument #2 to '[^']*' %(distance 2 must be a number, got string%)",
      err(c, {1, "x"}))
    assert.matches("bad argument #2 to '[^']*' %(distance 1 is NaN%)", err(c, {0 / 0}))
    assert.matches("bad argument #2 to '[^']*' %(table expected", err(c, 5))
    assert.matches("bad argument #1 to '[^']*'", err({1, 2, 3}, {1}))
    assert.matches("bad argument #3 to '[^']*' %(tol must be in %[1e%-15, 0.1%]%)",
      err(c, {1}, {tol = 0}))
    assert.matches("bad argument #3 to '[^']*' %(unknown option 'foo'%)", err(c, {1}, {foo = 1}))
  end)
  it("takes infinite distances as the ends", function()
    assert.are.same({0, 0, 1}, arclen.times(c, {-math.huge, 0, math.huge}))
  end)
end)

-- A path of n random segments joined end to start.
local function random_path(n, seed, opts)
  local r, segs, x, y = rng(seed), {}, 0, 0
  for k = 1, n do
    local c = {x, y}
    for q = 3, 8 do c[q] = (q % 2 == 1 and x or y) + 10 * r() - 3 end
    segs[k] = c
    x, y = c[7], c[8]
  end
  return path(segs, opts), segs
end

describe("arclen.path: the one-pass walk", function()
  it("resample agrees with one point at a time (tol 1e-15)", function()
    local p = random_path(30, 99, {tol = 1e-15})
    local L = p:length()
    local pts = p:resample(257)
    assert.are.equal(257, #pts)
    for q, smp in ipairs(pts) do
      local x, y = p:point(smp.s)
      assert.is_true(math.abs(x - smp.x) + math.abs(y - smp.y) <= 4 * bound(1e-15) * L, "point " .. q)
      assert.are.equal(math.floor(p:time(smp.s)), math.floor(smp.time))
      local tx, ty = p:tangent(smp.s)
      assert.is_true(math.abs(tx - smp.tx) + math.abs(ty - smp.ty) <= 1e-6, "tangent " .. q)
    end
    assert.are.equal(L, pts[257].s)
  end)
  it("points, samples: flat arrays, any order, clamped; the same as resample", function()
    local p = random_path(12, 7)
    local L = p:length()
    local ds = {L / 3, 0, L, -1, L + 5, L / 2, L / 2}
    local pts, tans, times = p:points(ds, {tangents = true, times = true})
    local smp = p:samples(ds)
    assert.are.equal(14, #pts)
    for q = 1, #ds do
      assert.are.equal(smp[q].x, pts[2 * q - 1])
      assert.are.equal(smp[q].y, pts[2 * q])
      assert.are.equal(smp[q].tx, tans[2 * q - 1])
      assert.are.equal(smp[q].time, times[q])
    end
    assert.are.equal(0, times[2])
    assert.are.equal(0, times[4])
    assert.are.equal(12, times[3])
    local only = p:points({L / 3})
    assert.are.equal(pts[1], only[1])
    local a, b, c = p:points({1})
    assert.are.equal(2, #a)
    assert.is_nil(b)
    assert.is_nil(c)
  end)
  it("few distances on many segments: the segments the search finds", function()
    local p = random_path(300, 11)
    local L = p:length()
    local ds = {0, L * 0.001, L * 0.3, L * 0.3000001, L * 0.77, L}
    local pts = p:points(ds, {times = true})
    local _, _, times = p:points(ds, {times = true})
    for q, s in ipairs(ds) do
      local x, y = p:point(s)
      assert.is_true(math.abs(x - pts[2 * q - 1]) + math.abs(y - pts[2 * q]) <= 1e-9 * L, "point " .. q)
      assert.are.equal(math.floor(p:time(s)), math.floor(times[q]), "segment " .. q)
    end
    local d = p:dash({L / 7, L / 7})
    assert.are.equal(4, #d)
  end)
  it("points on a cyclic path wrap around", function()
    local p = path.svg("M0 0 L10 0 L10 10 L0 10 Z")
    local pts = p:points({45, 5, -5})
    assert.are.same({5, 0, 5, 0, 0, 5}, pts)
  end)
  it("dash lays the same dashes as one distance at a time", function()
    local p = random_path(20, 5)
    local d = p:dash({3, 1.5, 0, 2})
    local L = p:length()
    local total = 0
    for _, q in ipairs(d) do total = total + q:length() end
    -- on stretches 3 and 0 of every 6.5: about 3/6.5 of L
    assert.is_true(math.abs(total - L * 3 / 6.5) <= 3, total)
    local s = 0
    for q = 1, 5 do
      local x, y = d[q]:point(0)
      local ex, ey = p:point(s)
      assert.is_true(math.abs(x - ex) + math.abs(y - ey) <= 1e-9 * L)
      s = s + (q % 2 == 1 and 3 + 1.5 or 0 + 2)
    end
  end)
  it("points against mpmath (spec/data/paths.tsv), tol 1e-12", function()
    for _, row in ipairs(H.tsv("paths.tsv")) do
      if row.arcs == "0" then
        local p = path.svg(row.d, {tol = 1e-12})
        local L = tonumber(row.L)
        local goals, xs, ys = H.numbers(row.goals), H.numbers(row.xs), H.numbers(row.ys)
        local pts = p:points(goals)
        for q = 1, #goals do
          local scale = math.max(math.abs(xs[q]), math.abs(ys[q]))
          local e = math.sqrt((pts[2 * q - 1] - xs[q]) ^ 2 + (pts[2 * q] - ys[q]) ^ 2)
          assert.is_true(e <= 1e-12 * L + 8 * 2.2e-16 * scale, row.id .. " " .. q)
        end
      end
    end
  end)
  it("points: bad input names the argument", function()
    local p = random_path(3, 1)
    local ok, msg = pcall(p.points, p, {1, "a"})
    assert.is_false(ok)
    assert.matches("bad argument #1 to 'points' %(distance 2 must be a number, got string%)", msg)
    ok, msg = pcall(p.points, p, {1}, {foo = true})
    assert.matches("bad argument #2 to 'points' %(unknown option 'foo'%)", msg)
    ok, msg = pcall(p.samples, p, 5)
    assert.matches("bad argument #1 to 'samples' %(a list of distances expected, got number%)", msg)
    ok, msg = pcall(p.points, p, {0 / 0})
    assert.matches("distance 1 must be finite", msg)
  end)
end)

-- Cubics whose speed nearly stops deeper than doubles resolve (z'' ~ 2^-530
-- of z' after scaling: a root of z' at ~2^530 and one 2^-530 off the axis
-- at t ~ 1/2), from tools/ref_stops.py: the far root once went missing
-- from the inverse's bound of the speed, which then certified Newton steps
-- 2e-4 L off.  Coordinates to 2^1001: the speed is taken scaled.
describe("arclen.time and arclen.times where the speed nearly stops", function()
  local rows = H.tsv("deep_stops.tsv")
  local function cubic(row)
    local c = {}
    for i = 0, 4 * tonumber(row.dim) - 1 do c[#c + 1] = tonumber(row["c" .. i]) end
    return c
  end
  local function scaled_speed(c, t)
    local d, m, s = {arclen.derivative(c, t)}, 0, 0
    for _, v in ipairs(d) do m = math.max(m, math.abs(v)) end
    if m == 0 then return 0 end
    for _, v in ipairs(d) do s = s + (v / m) ^ 2 end
    return m * math.sqrt(s)
  end
  local curves, only2d = {}, H.engine == "lua"  -- the Lua engine: 3D needs the C core
  for _, row in ipairs(rows) do
    local cv = curves[#curves]
    if not (only2d and row.dim ~= "2") then
      if not cv or cv.id ~= row.id then
        cv = {id = row.id, c = cubic(row), L = tonumber(row.L), u = {}, T = {}}
        curves[#curves + 1] = cv
      end
      cv.u[#cv.u + 1] = tonumber(row.u)
      cv.T[#cv.T + 1] = tonumber(row.T)
    end
  end
  it("the reference holds the curves and the distances", function()
    assert.are.equal(9 * 15, #rows)
    assert.is_true(#curves == 9 or only2d and #curves >= 3)
  end)
  for _, tol in ipairs({1e-6, 1e-9, 1e-12, 1e-15}) do
    it(("every distance within %g L (tol %g), one at a time and in one pass%s"):format(bound(tol), tol,
        only2d and " [Lua engine: the 2D curves; 3D needs the C core]" or ""), function()
      local worst = H.worst()
      for _, cv in ipairs(curves) do
        local s = {}
        for q, u in ipairs(cv.u) do s[q] = u * cv.L end
        local ts = arclen.times(cv.c, s, {tol = tol})
        for q = 1, #s do
          local t = arclen.time(cv.c, s[q], {tol = tol})
          local T = cv.T[q]
          for _, got in ipairs({t, ts[q]}) do
            local e = math.abs(got - T) * math.max(scaled_speed(cv.c, got), scaled_speed(cv.c, T))
            worst:add(e / cv.L, cv.id .. " u " .. cv.u[q])
          end
        end
      end
      assert.is_true(worst.err <= bound(tol),
        ("worst %s: %.3g > %.3g"):format(tostring(worst.id), worst.err, bound(tol)))
    end)
  end
end)
