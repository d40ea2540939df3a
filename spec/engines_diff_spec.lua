-- spec/engines_diff_spec.lua -- the Lua engine (arclen.pure) against the C
-- core on random plane paths: every length, time and point of the one
-- within the guarantee of the other.  Each engine is within tol * L of the
-- truth, so two lengths differ by at most 2 tol L, and two points at one
-- distance by at most 2 tol L (the chord is shorter than the arc); a time
-- t from the Lua engine is measured back by the C core at tol 1e-15
-- (itself within 1e-14 L): |s(t) - s| <= (tol + 1e-14) L.  Points are
-- coordinates, rounded at their own size: the bound on them adds 4 eps
-- times the largest coordinate (a curve 1e-3 long at x = 100).
-- The paths: random cubics and lines, and the cases that break methods --
-- degenerate handles (a control point on its end point), coincident
-- points, zero-length segments, cusps and near-cusps, straight reversals.
-- Then SVG path data: the Lua reader against the C reader, bit for bit.
local H = require("helpers")
local pure = require("arclen.pure")
local has_core, core = pcall(require, "arclen.core")

local path_on = require("helpers").path_on

-- A random cubic from p0 of one of the kinds above, scaled by 10^k.
local function random_cubic(r, x0, y0)
  local kind = math.floor(r() * 9)
  local s = 10 ^ math.floor(r() * 7 - 3)
  local function pt() return x0 + s * (2 * r() - 1), y0 + s * (2 * r() - 1) end
  local x1, y1 = pt()
  local x2, y2 = pt()
  local x3, y3 = pt()
  if kind == 1 then x1, y1 = x0, y0                      -- handle on its end
  elseif kind == 2 then x2, y2 = x3, y3
  elseif kind == 3 then x1, y1, x2, y2, x3, y3 = x0, y0, x0, y0, x0, y0   -- a point
  elseif kind == 4 then                                   -- a cusp: (0,0) (1,1) (0,1) (1,0)
    x1, y1, x2, y2, x3, y3 = x0 + s, y0 + s, x0, y0 + s, x0 + s, y0
  elseif kind == 5 then                                   -- a near-cusp
    local e = 10 ^ -(2 + math.floor(r() * 10))
    x1, y1, x2, y2, x3, y3 = x0 + s, y0 + s, x0 + e * s, y0 + s, x0 + s, y0
  elseif kind == 6 then                                   -- a straight reversal
    local dx, dy = s * (2 * r() - 1), s * (2 * r() - 1)
    x1, y1, x2, y2, x3, y3 = x0 + 2 * dx, y0 + 2 * dy, x0 - dx, y0 - dy, x0 + dx, y0 + dy
  elseif kind == 7 then x2, y2 = x1, y1                   -- coincident handles
  elseif kind == 8 then                                   -- a line, as path data makes it
    local dx, dy = x3 - x0, y3 - y0
    x1, y1, x2, y2 = x0 + dx / 3, y0 + dy / 3, x3 - dx / 3, y3 - dy / 3
  end
  return {x0, y0, x1, y1, x2, y2, x3, y3}
end

local function random_path(r)
  local segs, x, y = {}, 100 * r(), 100 * r()
  for k = 1, 1 + math.floor(r() * 4) do
    segs[k] = random_cubic(r, x, y)
    x, y = segs[k][7], segs[k][8]
  end
  return segs
end

local NOTE = has_core and "" or " [no C core here to compare with: checked where it loads]"

describe("the Lua engine against the C core on random paths" .. NOTE, function()
  if not has_core then
    it("needs both engines", function() end)
    return
  end
  local Pc, Pl = path_on(core), path_on(pure)

  for _, tol in ipairs({1e-12, 1e-9}) do
    it(("3000 paths: lengths, times and points within 2 tol L (tol %g)"):format(tol), function()
      local r = H.rng(tol == 1e-12 and 20261203 or 777)
      local wl, wt, wp, wr = H.worst(), H.worst(), H.worst(), H.worst()
      local cubics = 0
      for i = 1, 3000 do
        local segs = random_path(r)
        local pc, pl = Pc(segs, {tol = tol}), Pl(segs, {tol = tol})
        local L = pc:length()
        local scale = math.max(L, 1e-300)
        wl:add(math.abs(pl:length() - L) / scale / (2 * tol), "path " .. i)
        local big = 0
        for _, c in ipairs(segs) do
          for q = 1, 8 do big = math.max(big, math.abs(c[q])) end
        end
        local slack = 4 * 2.220446049250313e-16 * big
        for _, c in ipairs(segs) do           -- each cubic: length and time
          cubics = cubics + 1
          local lc = core.length(c, {tol = tol})
          local ll = pure.length(c, {tol = tol})
          wl:add(math.abs(ll - lc) / math.max(lc, 1e-300) / (2 * tol), "path " .. i .. " cubic")
          if lc > 0 then
            local s = lc * r()
            local t = pure.time(c, s, {tol = tol})
            local back = t == 0 and 0 or core.length(c, {tol = 1e-15, t1 = t})
            wt:add(math.abs(back - s) / lc / (tol + 1e-14), "path " .. i .. " s " .. s)
          end
        end
        if L > 0 then
          for _ = 1, 3 do                     -- points at distances
            local s = L * (1.1 * r() - 0.05)
            local xc, yc = pc:point(s)
            local xl, yl = pl:point(s)
            wp:add(math.sqrt((xc - xl) ^ 2 + (yc - yl) ^ 2) / (2 * tol * L + slack), "path " .. i .. " s " .. s)
          end
          local rc, rl = pc:resample(7), pl:resample(7)
          for q = 1, 7 do
            local d = math.sqrt((rc[q].x - rl[q].x) ^ 2 + (rc[q].y - rl[q].y) ^ 2)
            wr:add(d / (2 * tol * L + slack), "path " .. i .. " resample " .. q)
          end
        end
      end
      assert.is_true(cubics >= 6000, "cubics: " .. cubics)
      -- each ratio is the difference over what the guarantee allows
      for name, w in pairs({length = wl, time = wt, point = wp, resample = wr}) do
        assert.is_true(w.err <= 1, ("%s: worst %s at %.3g of the bound"):format(name, tostring(w.id), w.err))
      end
    end)
  end

  it("lengths of curves and sub-ranges at every scale, 1e-305 to 1e305 (tol 1e-12)", function()
    -- found by fuzzing: Veltkamp's split overflowed for a sub-range of a
    -- curve near 1e300, and the NaN hodograph measured 0
    local r = H.rng(1305)
    local worst = H.worst()
    for i = 1, 2000 do
      local sc, c = 10 ^ (math.floor(r() * 611) - 305), {}
      for k = 1, 8 do c[k] = sc * (2 * r() - 1) end
      local o = i % 2 == 0 and {t0 = r(), t1 = r()} or nil
      local lc, ll = core.length(c, o), pure.length(c, o)
      if lc ~= 0 then worst:add(math.abs(ll - lc) / math.abs(lc) / 2e-12, "curve " .. i) end
    end
    local big = {-9e299, 0, 9e299, 1e299, -9e299, 3e299, 9e299, 0}
    worst:add(math.abs(pure.length(big, {t1 = 0.3}) / core.length(big, {t1 = 0.3}) - 1) / 2e-12, "near 1e300")
    assert.is_true(worst.err <= 1, ("worst %s at %.3g of the bound"):format(tostring(worst.id), worst.err))
  end)

  it("SVG path data without arcs: the same cubics, subpaths and messages (3000 strings)", function()
    local EPS = 2 ^ -52
    local r = H.rng(5150)
    local function pick(s) local k = math.floor(r() * #s) + 1; return s:sub(k, k) end
    local function number()
      local n = ("%.6g"):format((r() - 0.5) * 10 ^ math.floor(r() * 8 - 3))
      if r() < 0.1 then n = n:gsub("^0%.", ".") end            -- ".5"
      if r() < 0.05 then n = n .. "e" .. math.floor(r() * 6 - 3) end
      return n
    end
    local bad, nerr = {}, 0
    for i = 1, 3000 do
      -- commands with their arguments; now and then one too few, a
      -- command with none (a repeat), or a stray byte
      local ARGS = {M = 2, L = 2, H = 1, V = 1, C = 6, S = 4, Q = 4, T = 2, Z = 0}
      local parts = {}
      for k = 1, 1 + math.floor(r() * 8) do
        local cmd = k == 1 and (r() < 0.97 and "M" or "L") or pick("MLHVCSQTZ")
        parts[#parts + 1] = r() < 0.5 and cmd or cmd:lower()
        local n = ARGS[cmd] * (r() < 0.2 and 2 or 1) - (r() < 0.03 and 1 or 0)
        for q = 1, n do
          parts[#parts + 1] = number()
          if q < n or r() < 0.5 then parts[#parts + 1] = pick(" ,  \t") end
        end
      end
      if r() < 0.03 then parts[#parts + 1] = pick(",eX.") end
      local d = table.concat(parts)
      local a, am, ap = core.svg_pathdata(d, 1e-12)
      local b, bm, bp = pure.svg_pathdata(d, 1e-12)
      if not a or not b then
        nerr = nerr + 1
        if a or b or am ~= bm or ap ~= bp then
          bad[#bad + 1] = ("%q: C %s %s, Lua %s %s"):format(d, tostring(am), tostring(ap), tostring(bm), tostring(bp))
        end
      else
        -- the same cubics to the bit where the C reader is built without
        -- contraction (the Makefile's); a build that fuses its a*b+c (the
        -- quadratics raised, the reflections) may differ by an ulp or two
        -- of the path's size (make check-builds runs this spec so)
        local ca = core._cubics(a.packed)
        local same = a.n == b.n and #a == #b
        local size = 0
        for k = 1, same and a.n or 0 do
          for q = 1, 8 do size = math.max(size, math.abs(ca[k][q])) end
        end
        for k = 1, same and a.n or 0 do
          for q = 1, 8 do
            same = same and math.abs(ca[k][q] - b.packed[8 * (k - 1) + q]) <= 4 * EPS * size
          end
        end
        for j = 1, same and #a or 0 do
          local u, v = a[j], b[j]
          same = same and u.x == v.x and u.y == v.y and u.closed == v.closed and u.n == v.n
        end
        if not same then bad[#bad + 1] = ("%q: different cubics or subpaths"):format(d) end
      end
    end
    assert.are.same({}, bad)
    assert.is_true(nerr > 30 and nerr < 2500, "errors: " .. nerr)    -- both kinds were tried
  end)

  it("dashes and sub-paths agree (tol 1e-12)", function()
    local r = H.rng(4242)
    for i = 1, 300 do
      local segs = random_path(r)
      local pc, pl = Pc(segs), Pl(segs)
      local L = pc:length()
      local big = 0
      for _, c in ipairs(segs) do
        for q = 1, 8 do big = math.max(big, math.abs(c[q])) end
      end
      -- each end within 2 tol L of the other engine's, the parts measured
      -- on control points rounded at the coordinates' size
      local bound = 4e-12 * L + 8 * 2.220446049250313e-16 * big
      if L > 0 then
        local pat = {L * (0.05 + 0.2 * r()), L * (0.02 + 0.1 * r())}
        local dc, dl = pc:dash(pat), pl:dash(pat)
        assert.are.equal(#dc, #dl, "path " .. i)
        for q = 1, #dc do
          assert.is_true(math.abs(dc[q]:length() - dl[q]:length()) <= bound, "path " .. i .. " dash " .. q)
        end
        local a, b = L * r(), L * r()
        assert.is_true(math.abs(pc:sub(a, b):length() - pl:sub(a, b):length()) <= bound, "path " .. i)
      end
    end
  end)
end)
