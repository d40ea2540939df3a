-- spec/svgpath_spec.lua -- SVG path data: the grammar (commands, implicit
-- repeats, numbers, separators, arc flags), the segments' kinds and
-- records (lines, quadratics, cubics, conics: exactly what the data says),
-- transforms, degenerate arcs, errors that give the position in the
-- string, and arcs = "cubics" (today's cubics, bit for bit against
-- spec/data/svg_cubics.tsv, recorded by tools/ref_svg_cubics.lua from the
-- reader before it kept the kinds, and again when arcs' control points came
-- from their ends).  Lengths against spec/data/paths.tsv
-- (mpmath, tools/ref_paths.py, which reads the path data independently).
local arclen = require("arclen")
local H = require("helpers")
local path = require("arclen.path")
local svgpath = require("arclen.svgpath")

local EPS = 2 ^ -52
local COUNT = {L = 4, Q = 6, C = 8, R = 7}     -- numbers of a record, by kind

-- Does this build fuse a*b + c (the contracted builds of make check-builds)?
-- Lua rounds every operation; the C reader maps a point as a*x + c*y + e.
-- Where it fuses, "to the bit" below becomes "to a few ulps of the path's
-- size" (ULPS * size; measured: at most 2 ulps on the contracted GCC build).
local CONTRACTED = false
for i = 1, 64 do
  local x, y = i / 7 + 0.013, 0.37 - i / 11
  local T = {0.1 + i / 97, 0.7, 0.3 - i / 89, 0.9, 0.1, 0}
  local R = arclen.svg_pathdata(("M%.17g %.17g"):format(x, y), 1e-12, T)
  if R[1].x ~= T[1] * x + T[3] * y + T[5] or R[1].y ~= T[2] * x + T[4] * y + T[6] then
    CONTRACTED = true
  end
end
-- Windows' C runtime (MinGW's msvcrt) computes sin, cos and atan2 with
-- other roundings than glibc, where the recorded cubics come from: there
-- too "to the bit" becomes "to a few ulps of the path's size".
local OTHER_LIBM = package.config:sub(1, 1) == "\\"
local ULPS = (CONTRACTED or OTHER_LIBM) and 8 * EPS or 0

-- a and b equal, or within the ulps of a build that fuses (size: the
-- path's largest coordinate).
local function near(a, b, size) return a == b or math.abs(a - b) <= ULPS * size end

-- The reader's records as {kind = letter, numbers...}, checking the
-- format: n records of 8 numbers, the kind's first and the rest 0, kinds a
-- string of n letters (nil when all are cubics), subpaths tiling them.
local function records(R)
  local raw = R.packed                          -- 8 numbers each, any kind
  if type(raw) == "string" then
    raw = arclen._cubics(raw)
  else                                          -- the Lua engine's flat table
    local t = {}
    for k = 1, #raw / 8 do t[k] = {(table.unpack or unpack)(raw, 8 * k - 7, 8 * k)} end
    raw = t
  end
  assert.are.equal(R.n, #raw)
  local count = 0
  for j = 1, #R do count = count + R[j].n end
  assert.are.equal(R.n, count)
  if R.kinds ~= nil then
    assert.are.equal(R.n, #R.kinds)
    assert.is_truthy(R.kinds:find("^[LQCR]*$"))
    assert.is_truthy(R.kinds:find("[LQR]"), "kinds must be nil when all are cubics")
  end
  local out = {}
  for k = 1, R.n do
    local kind = R.kinds and R.kinds:sub(k, k) or "C"
    local r = {kind = kind}
    for i = 1, 8 do
      if i <= COUNT[kind] then r[i] = raw[k][i] else assert.are.equal(0, raw[k][i]) end
    end
    out[k] = r
  end
  return out
end

local function recs(d, T, arcs, atol) return records(svgpath.parse(d, atol or 1e-12, T, arcs)) end

local function kinds_of(d, T)
  local s = {}
  for k, r in ipairs(recs(d, T)) do s[k] = r.kind end
  return table.concat(s)
end

-- A record equal to kind and numbers, to the bit (size given: near).
local function same(got, kind, want, size)
  assert.are.equal(kind, got.kind)
  assert.are.equal(#want, #got)
  for i = 1, #want do
    assert.is_true(want[i] == got[i] or (size ~= nil and near(got[i], want[i], size)),
      ("number %d: %.17g vs %.17g"):format(i, got[i], want[i]))
  end
end

local function size_of(list)
  local m = 0
  for _, r in ipairs(list) do for i = 1, #r do m = math.max(m, math.abs(r[i])) end end
  return m
end

-- The cubics of arcs = "cubics", as tables of 8 numbers.
local function cubics(d, atol) return arclen._cubics(svgpath.parse(d, atol or 1e-12, nil, "cubics").packed) end

local function same_cubic(got, want)
  assert.are.equal(#want, #got)
  for i = 1, #want do assert.are.equal(want[i], got[i]) end
end

-- Equal within rounding of the few operations that made them.
local function near_cubic(got, want)
  assert.are.equal(#want, #got)
  for i = 1, #want do
    assert.is_true(math.abs(want[i] - got[i]) <= 4e-16 * math.max(1, math.abs(want[i])),
      ("coordinate %d: %.17g vs %.17g"):format(i, got[i], want[i]))
  end
end

-- The point of a conic record at t: the rational quadratic with weights
-- 1, w, 1 (Floater's eq. 1).
local function conic_point(r, t)
  local b0, b1, b2 = (1 - t) ^ 2, 2 * t * (1 - t) * r[7], t * t
  local den = b0 + b1 + b2
  return (b0 * r[1] + b1 * r[3] + b2 * r[5]) / den, (b0 * r[2] + b1 * r[4] + b2 * r[6]) / den
end

describe("svg path data: the segments' kinds and records", function()
  it("keeps every command's kind: L H V Z lines, Q T quadratics, C S cubics", function()
    local r = recs("M1 2 L4 6 H10 V0 C11 1 12 1 13 0 Q14 3 15 0 T17 0 Z")
    assert.are.equal(7, #r)
    same(r[1], "L", {1, 2, 4, 6})
    same(r[2], "L", {4, 6, 10, 6})
    same(r[3], "L", {10, 6, 10, 0})
    same(r[4], "C", {10, 0, 11, 1, 12, 1, 13, 0})
    same(r[5], "Q", {13, 0, 14, 3, 15, 0})
    same(r[6], "Q", {15, 0, 16, -3, 17, 0})      -- T reflects (14, 3) about (15, 0)
    same(r[7], "L", {17, 0, 1, 2})               -- Z's closing line
  end)

  it("reads relative commands into the same records", function()
    local a = recs("M1 2 L4 6 H10 V0 C11 1 12 1 13 0 Q14 3 15 0 Z")
    local b = recs("m1 2 l3 4 h6 v-6 c1 1 2 1 3 0 q1 3 2 0 z")
    assert.are.equal(#a, #b)
    for k = 1, #a do same(b[k], a[k].kind, a[k]) end
  end)

  it("reflects the previous control point for S and T, and not after other commands", function()
    same(recs("M0 0 C1 2 3 2 4 0 S7 -2 8 0")[2], "C", {4, 0, 5, -2, 7, -2, 8, 0})
    same(recs("M0 0 L4 0 S7 -2 8 0")[2], "C", {4, 0, 4, 0, 7, -2, 8, 0})
    same(recs("M0 0 Q2 3 4 0 T8 0")[2], "Q", {4, 0, 6, -3, 8, 0})
    same(recs("M0 0 L4 0 T8 0")[2], "Q", {4, 0, 4, 0, 8, 0})
    same(recs("M0 0 C1 2 3 2 4 0 T8 0")[2], "Q", {4, 0, 4, 0, 8, 0})
  end)

  it("repeats a command for further argument lists; after M they are lines", function()
    assert.are.equal("LL", kinds_of("M0 0 1 0 1 1"))
    same(recs("m1 1 2 0 0 2")[2], "L", {3, 1, 3, 3})
    assert.are.equal("CCC", (svgpath.parse("M0 0 C1 1 2 1 3 0 4 -1 5 -1 6 0 7 1 8 1 9 0", 1e-12).kinds or "CCC"))
  end)

  it("gives kinds = nil when every segment is a cubic (the format of old callers)", function()
    local R = svgpath.parse("M0 0 C1 1 2 1 3 0 S5 -1 6 0", 1e-12)
    assert.is_nil(R.kinds)
    assert.are.equal(2, R.n)
    assert.are.equal("LC", svgpath.parse("M0 0 L1 0 C1 1 2 1 3 0", 1e-12).kinds)
  end)

  it("reads numbers with exponents, signs and dots as separators", function()
    local r = recs("M1e1-.5.5.5L1E-1,2e+0 l-.5.5.5.5")
    same(r[1], "L", {10, -0.5, 0.5, 0.5})
    same(r[2], "L", {0.5, 0.5, 0.1, 2})
    assert.are.equal(4, #r)
    assert.are.equal(2, #recs("M 0 , 0 L\t1\n,\r1  ,2 2"))
  end)

  it("closes a subpath with a line only where the current point is elsewhere", function()
    assert.are.equal("LLL", kinds_of("M0 0 L1 0 L1 1 Z"))
    assert.are.equal("LL", kinds_of("M0 0 L1 0 L0 0 Z"))
    local sp = svgpath.parse("M0 0 L1 0 Z L0 5", 1e-12)
    assert.are.equal(2, #sp)                          -- drawing after Z: a new subpath
    assert.is_true(sp[1].closed)
    assert.are.equal(0, sp[2].x)
    assert.are.equal(0, sp[2].y)
  end)
end)

describe("svg path data: arcs as conics", function()
  it("makes a quarter whose ends are rx, ry apart the conic through the corner, w = sqrt(1/2)", function()
    -- F.6.5: Lambda = 1/2, the centre is a corner of the ends' box, the
    -- control point the other (the tangents' intersection); w = cos 45
    same(recs("M10 0 A10 5 0 0 1 0 5")[1], "R", {10, 0, 10, 5, 0, 5, math.sqrt(0.5)})
    same(recs("M10 0 A10 5 0 0 0 0 5")[1], "R", {10, 0, 0, 0, 0, 5, math.sqrt(0.5)})
    same(recs("M0.25 -3 a-2 4 0 0 1 -2 4")[1], "R", {0.25, -3, 0.25, 1, -1.75, 1, math.sqrt(0.5)})
    -- a full ellipse of four quarters, closed exactly
    local r = recs("M20 10 A10 5 0 0 1 10 15 A10 5 0 0 1 0 10 A10 5 0 0 1 10 5 A10 5 0 0 1 20 10 Z")
    assert.are.equal(4, #r)
    same(r[2], "R", {10, 15, 0, 15, 0, 10, math.sqrt(0.5)})
    same(r[4], "R", {10, 5, 20, 5, 20, 10, math.sqrt(0.5)})
  end)

  -- arcs whose centre is known: the implicit equation of the ellipse
  -- ((x, y) - c, rotated by -phi, scaled by the radii) at every end and at
  -- t = k/16 of every piece
  local ARCS = {
    {"M10 0 A10 10 0 1 1 -10 0", 0, 0, 10, 10, 0},
    {"M10 0 A10 10 0 1 1 10 -0.001", 10 - math.sqrt(100 - 0.0005 ^ 2), -0.0005, 10, 10, 0},
    {"M10 0 A10 5 30 1 1 -10 0", 0, 0, 10 * math.sqrt(1.75), 5 * math.sqrt(1.75), 30},
    {"M3 4 A7 2 0 0 0 10 6", 10, 4, 7, 2, 0},
    {"M-1e300 0 A1e300 1e300 0 0 1 1e300 0", 0, 0, 1e300, 1e300, 0},
  }
  it("puts the conics exactly on the ellipse (four pieces at most, none over 90 degrees)", function()
    local worst = 0
    for _, a in ipairs(ARCS) do
      local d, cx, cy, rx, ry, phi = a[1], a[2], a[3], a[4], a[5], math.rad(a[6])
      local r = recs(d)
      assert.is_true(#r >= 1 and #r <= 4, d)
      local c, s = math.cos(phi), math.sin(phi)
      for k, q in ipairs(r) do
        assert.are.equal("R", q.kind)
        assert.is_true(q[7] >= math.sqrt(0.5) * (1 - 4 * EPS) and q[7] < 1, d)   -- <= 90 degrees
        if k > 1 then assert.are.equal(r[k - 1][5], q[1]); assert.are.equal(r[k - 1][6], q[2]) end
        for i = 0, 16 do
          local x, y = conic_point(q, i / 16)
          local u, v = (x - cx) * c + (y - cy) * s, -(x - cx) * s + (y - cy) * c
          local e = math.abs(math.sqrt((u / rx) ^ 2 + (v / ry) ^ 2) - 1)
          worst = math.max(worst, e)
        end
      end
    end
    print(("  conics on their ellipses: worst |implicit - 1| %.3g"):format(worst))
    assert.is_true(worst <= 16 * EPS, worst)
  end)

  it("joins the arc's ends exactly to the path's points", function()
    local r = recs("M10 0 A10 7 20 1 1 -10 0 L0 0")
    same({kind = r[1].kind, r[1][1], r[1][2]}, "R", {10, 0})
    assert.are.equal(-10, r[#r - 1][5])
    assert.are.equal(0, r[#r - 1][6])
    assert.are.equal("L", r[#r].kind)
  end)

  it("follows F.6.2: equal end points omit the arc, a zero radius is a line", function()
    assert.are.equal(0, svgpath.parse("M1 1 A5 5 0 0 1 1 1", 1e-12).n)
    same(recs("M0 0 A0 5 0 0 1 3 3")[1], "L", {0, 0, 3, 3})
    same(recs("M0 0 A5 0 0 0 1 3 3")[1], "L", {0, 0, 3, 3})
  end)

  it("makes a conic that rounding made flat the line of its ends", function()
    -- a unit radius between ends 1e-320 apart: the conic's control points
    -- are collinear in double precision; the arc is its chord to rounding
    local r = recs("M0 0 A1 1 0 0 1 1e-320 0")
    assert.are.equal(1, #r)
    same(r[1], "L", {0, 0, 1e-320, 0})
  end)
end)

describe("svg path data: transforms", function()
  local D = "M1 2 L4 6 H10 Q12 4 11 0 C10 -1 8 -1 7 0 A3 2 15 0 1 2 1 A2 1 0 0 1 0 0 Z"
  local TS = {{2, 0, 0, 3, 5, -7}, {0.6, 0.8, -0.8, 0.6, 1, 2}, {1, 0, 0.5, 1, 0, 0},
    {-1e-3, 2e-4, -3e-4, 5e-3, 1e5, 0}}
  it("maps every record's control points and keeps a conic's weight (exact for every kind)", function()
    local plain = recs(D)
    assert.are.equal("LLQCRRL", kinds_of(D):gsub("RR+", "RR"))
    for _, T in ipairs(TS) do
      local mapped = recs(D, T)
      assert.are.equal(#plain, #mapped)
      for k, p in ipairs(plain) do
        local want = {}
        for i = 1, COUNT[p.kind] - (p.kind == "R" and 1 or 0), 2 do
          want[i] = T[1] * p[i] + T[3] * p[i + 1] + T[5]
          want[i + 1] = T[2] * p[i] + T[4] * p[i + 1] + T[6]
        end
        if p.kind == "R" then want[7] = p[7] end
        same(mapped[k], p.kind, want, size_of(mapped))
      end
      local R = svgpath.parse(D, 1e-12, T)
      assert.is_true(near(T[1] * 1 + T[3] * 2 + T[5], R[1].x, size_of(mapped)))
      assert.is_true(near(T[2] * 1 + T[4] * 2 + T[6], R[1].y, size_of(mapped)))
    end
  end)

  it("folds a conic that a singular transform flattens into lines out and back", function()
    -- the quarter from (1, 0) to (0, 1) seen along x + y: out to sqrt(2)
    -- (the largest x + y on the unit circle) and back to 1
    local r = recs("M1 0 A1 1 0 0 1 0 1", {1, 0, 1, 0, 0, 0})
    assert.are.equal(2, #r)
    assert.are.equal("L", r[1].kind)
    assert.are.equal("L", r[2].kind)
    assert.are.equal(1, r[1][1])
    assert.are.equal(r[1][3], r[2][1])
    assert.are.equal(1, r[2][3])
    assert.is_true(math.abs(r[1][3] - math.sqrt(2)) <= 4 * EPS, ("%.17g"):format(r[1][3]))
    for _, q in ipairs(r) do assert.are.equal(0, q[2]); assert.are.equal(0, q[4]) end
    -- one way only: each half of the circle seen along x is one line
    r = recs("M10 0 A10 10 0 1 1 -10 0", {1, 0, 0, 0, 0, 0})
    assert.are.equal(2, #r)
    same(r[1], "L", {10, 0, r[1][3], 0})
    same(r[2], "L", {r[1][3], 0, -10, 0})
    assert.is_true(math.abs(r[1][3]) <= 1e-14)
  end)

  it("reports a mapped point beyond the doubles as before", function()
    local R, msg, pos = arclen.svg_pathdata("M1e300 0 L2e300 0 Q1 1 0 0", 1e-12, {1e10, 0, 0, 1, 0, 0})
    assert.is_nil(R)
    assert.are.equal("the transform takes a coordinate out of range", msg)
    assert.is_nil(pos)
  end)
end)

describe("svg path data: arcs = \"cubics\" gives today's cubics", function()
  it("turns lines into cubics with control points at thirds", function()
    same_cubic(cubics("M0 0 L3 6")[1], {0, 0, 1, 2, 2, 4, 3, 6})
    assert.is_nil(svgpath.parse("M0 0 L3 6 Q1 1 0 0 A1 1 0 0 1 1 1", 1e-12, nil, "cubics").kinds)
  end)

  it("elevates quadratics exactly: C1 = Q0 + 2/3 (Q1 - Q0), C2 = Q2 + 2/3 (Q1 - Q2)", function()
    same_cubic(cubics("M0 0 Q3 6 6 0")[1], {0, 0, 2, 4, 4, 4, 6, 0})
    local c = cubics("M1 1 Q7 -2 3 5")[1]
    for _, t in ipairs({0.1, 0.3, 0.5, 0.9}) do
      local u = 1 - t
      local qx = u * u * 1 + 2 * u * t * 7 + t * t * 3
      local qy = u * u * 1 + 2 * u * t * -2 + t * t * 5
      local x, y = arclen.point(c, t)
      assert.is_true(math.abs(x - qx) <= 1e-14 * 8 and math.abs(y - qy) <= 1e-14 * 8)
    end
    near_cubic(cubics("m1 1 2 0 0 2")[2], {3, 1, 3, 1 + 2 / 3, 3, 1 + 4 / 3, 3, 3})
  end)

  it("stays within arc_tol * max(rx, ry, chord/2) of the true circle", function()
    for _, atol in ipairs({1e-3, 1e-6, 1e-9, 1e-12}) do
      local s = cubics("M10 0 A10 10 0 1 1 -10 0", atol)
      local worst = 0
      for _, c in ipairs(s) do
        for i = 0, 16 do
          local x, y = arclen.point(c, i / 16)
          worst = math.max(worst, math.abs(math.sqrt(x * x + y * y) - 10))
        end
      end
      assert.is_true(worst <= atol * 10, ("arc_tol %g: %g"):format(atol, worst))
    end
  end)

  it("keeps its tolerance at every scale of the arc and of the transform", function()
    -- a semicircle of radius r (L = pi r) within tol L + 2 pi arc_tol r;
    -- scale(1e-170) squared to 0 in the singular values (level 0, 1.4e-4
    -- off), radii from 1.3e154 overflowed the chord's square (an error)
    local tol = 1e-12
    local cases = {
      {"M1e170 0 A1e170 1e170 0 0 1 -1e170 0", {1e-170, 0, 0, 1e-170, 0, 0}, 1},
      {"M1e-150 0 A1e-150 1e-150 0 0 1 -1e-150 0", {1e150, 0, 0, 1e150, 0, 0}, 1},
      {"M1e154 0 A1e154 1e154 0 0 1 -1e154 0", nil, 1e154},
      {"M1e300 0 A1e300 1e300 0 0 1 -1e300 0", nil, 1e300},
      {"M1e307 0 A1e307 1e307 0 0 1 -1e307 0", {0.5, 0, 0, 0.5, 0, 0}, 5e306},
    }
    for _, c in ipairs(cases) do
      local L = path.svg(c[1], {tol = tol, arcs = "cubics", transform = c[2]}):length()
      local want = math.pi * c[3]
      assert.is_true(math.abs(L - want) <= (tol + 2 * tol) * want, c[1])
    end
    -- a flat arc of a large circle: it failed as outside a function's domain
    local L = path.svg("M0 0 A1e9 1e9 0 0 1 10 0", {tol = tol, arcs = "cubics"}):length()
    assert.is_true(math.abs(L - 10) <= 1e-14 * 10, ("%.17g"):format(L))
  end)

  local rows = H.tsv("svg_cubics.tsv")
  local worst = 0                    -- in ulps of the row's size (contracted builds)
  local function check_row(row, R)
    local n = 0
    local want, k = {}, 0
    for v in row.packed:gmatch("%S+") do if v ~= "-" then want[#want + 1] = tonumber(v) end end
    local size = size_of({want})
    if row.subpaths ~= "-" then
      for sp in row.subpaths:gmatch("[^;]+") do
        n = n + 1
        local x, y, closed, count = sp:match("^(%S+) (%S+) (%d) (%d+)$")
        assert.is_true(near(R[n].x, tonumber(x), size), row.id)
        assert.is_true(near(R[n].y, tonumber(y), size), row.id)
        assert.are.equal(closed == "1", R[n].closed, row.id)
        assert.are.equal(tonumber(count), R[n].n, row.id)
      end
    end
    assert.are.equal(n, #R, row.id)
    assert.is_nil(R.kinds, row.id)
    assert.are.equal(#want, 8 * R.n, row.id)
    for _, c in ipairs(R.n > 0 and arclen._cubics(R.packed) or {}) do
      for i = 1, 8 do
        k = k + 1
        if c[i] ~= want[k] then
          worst = math.max(worst, math.abs(c[i] - want[k]) / (EPS * size))
          if not near(c[i], want[k], size) then
            error(("%s: number %d is %.17g, was %.17g"):format(row.id, k, c[i], want[k]))
          end
        end
      end
    end
  end

  it("equals the recorded cubics of every command, arc and transform, to the bit", function()
    local count = 0
    for _, row in ipairs(rows) do
      if row.src == "d" then
        local T = nil
        if row.T ~= "-" then
          T = H.numbers(row.T)
        end
        local R, msg = arclen.svg_pathdata(row.input, tonumber(row.arc_tol), T, "cubics")
        if row.subpaths == "error" then
          assert.are.equal(row.packed, msg, row.id)
        else
          assert.is_not_nil(R, row.id .. ": " .. tostring(msg))
          check_row(row, R)
        end
        count = count + 1
      end
    end
    assert.is_true(count >= 300, count)
    if CONTRACTED then
      print(("  a build that fuses a*b + c: the cubics within %.3g ulps of their size"):format(worst))
    end
  end)

  local has_doc, svgdoc = pcall(require, "arclen.svgdoc")
  it("equals the recorded cubics of the basic shapes (arclen.svgdoc), to the bit", function()
    if not has_doc then
      print("  (arclen.svgdoc not built: the document rows are not checked)")
      return
    end
    local docs, count = {}, 0
    for _, row in ipairs(rows) do
      if row.src == "doc" then
        local key = row.id
        if not docs[key] then
          local r = svgdoc.new({arc_tol = tonumber(row.arc_tol), uses = true, arcs = "cubics"})
          r:feed(row.input)
          docs[key] = r:finish("fixture").elements
        end
        local k, tag = row.elem:match("^(%d+) (%a+)$")
        local e = docs[key][tonumber(k)]
        assert.are.equal(tag, e.tag, row.id)
        check_row(row, e.subpaths)
        count = count + 1
      end
    end
    assert.is_true(count >= 40, count)
  end)
end)

-- Does arclen.path measure records of every kind (the path object of the
-- segment kinds)?  Else the conics' lengths are measured here, record by
-- record, by the engine's single-curve functions.
local function path_has_kinds()
  local ok, p = pcall(path.svg, "M0 0 L3 4")
  return ok and math.abs(p:length() - 5) < 1e-12
end

local function record_length(r, tol)
  if r.kind == "L" then return math.sqrt((r[3] - r[1]) ^ 2 + (r[4] - r[2]) ^ 2) end
  if r.kind == "C" then return arclen.length(r, {tol = tol}) end
  if r.kind == "Q" then
    return arclen.length({r[1], r[2], r[1] + 2 / 3 * (r[3] - r[1]), r[2] + 2 / 3 * (r[4] - r[2]),
      r[5] + 2 / 3 * (r[3] - r[5]), r[6] + 2 / 3 * (r[4] - r[6]), r[5], r[6]}, {tol = tol})
  end
  return arclen.conic_length({r[1], r[2]}, {r[3], r[4]}, {r[5], r[6]}, r[7])
end

describe("svg path data: lengths against mpmath (spec/data/paths.tsv)", function()
  local rows = H.tsv("paths.tsv")
  it("has the reference paths", function() assert.is_true(#rows >= 20) end)
  for _, tol in ipairs({1e-12, 1e-8}) do
    it(("arcs as cubics: within tol * L, plus 2 pi arc_tol * scale per arc (tol %g)"):format(tol), function()
      local w = H.worst()
      for _, row in ipairs(rows) do
        local want = tonumber(row.L)
        local atol = tol
        local got = path.svg(row.d, {tol = tol, arc_tol = atol, arcs = "cubics"}):length()
        -- an arc within Hausdorff distance delta of the ellipse has a length
        -- within (turning angle <= 2 pi) * delta of the ellipse arc's
        local bound = tol * want + 2 * math.pi * atol * tonumber(row.arcscale)
        local err = math.abs(got - want)
        assert.is_true(err <= bound, ("%s: error %g > %g"):format(row.id, err, bound))
        w:add(err / want, row.id)
      end
      print(("  svg lengths, arcs as cubics (tol %g): worst relative error %.3g (%s)"):format(tol, w.err, w.id))
    end)
    it(("the kinds as read: within tol * L, arcs exact (tol %g)"):format(tol), function()
      local w, by_path = H.worst(), path_has_kinds()
      for _, row in ipairs(rows) do
        local want = tonumber(row.L)
        local got = 0
        if by_path then
          got = path.svg(row.d, {tol = tol}):length()
        else
          for _, r in ipairs(recs(row.d)) do got = got + record_length(r, tol) end
        end
        local err = math.abs(got - want)
        assert.is_true(err <= tol * want, ("%s: error %g > %g"):format(row.id, err, tol * want))
        w:add(err / want, row.id)
      end
      print(("  svg lengths, kinds as read%s (tol %g): worst relative error %.3g (%s)"):format(
        by_path and "" or " (measured record by record)", tol, w.err, w.id))
    end)
  end
end)

describe("svg path data: flat arcs of large ellipses (spec/data/svg_flat_arcs.tsv)", function()
  -- radii up to 1e12 against a chord of ~10, and turns at the tip of thin
  -- ellipses (tools/ref_flat_arcs.py, mpmath's incomplete E).  The conic's
  -- control point comes from the arc's ends, its half angle from the sweep:
  -- from the centre, ~R away, they were 5.6e-11 of the length off.  Bound:
  -- tol L plus the conic's own rounding (its numbers within a few ulps,
  -- each moving these lengths by at most 4e-16 of them), 8 eps L.
  local rows = H.tsv("svg_flat_arcs.tsv")
  it("has the reference arcs", function() assert.is_true(#rows >= 60) end)
  for _, tol in ipairs({1e-15, 1e-12}) do
    it(("are within tol * L of the ellipse arc (tol %g)"):format(tol), function()
      local w = H.worst()
      for _, row in ipairs(rows) do
        local want = tonumber(row.L)
        local got = path.svg(row.d, {tol = tol}):length()
        local err = math.abs(got - want)
        assert.is_true(err <= (tol + 8 * EPS) * want,
                       ("%s: error %g of L"):format(row.d, err / want))
        w:add(err / want, row.d)
      end
      print(("  flat arcs (tol %g): worst relative error %.3g"):format(tol, w.err))
    end)
  end

  it("read back from p:svg() of a nearly parabolic conic, the same length", function()
    -- w = 1 - 1.8e-11: p:svg() writes an A of radii ~1e11 (read back, it
    -- was 8e-7 of the length off)
    local c = {"conic", -2.7229164320616595, -4.0564736603090878, 2.8471911851536436,
               -7.2577511227027287, -1.0231192647587128, 4.4345172003072308, 0.99999999998242162}
    local p = path({c})
    local q = path.svg(p:svg())
    local L = p:length({tol = 1e-15})
    assert.is_true(math.abs(q:length({tol = 1e-15}) - L) <= (1e-15 + 8 * EPS) * L)
  end)
end)

describe("the basic shapes' records (arclen.svgdoc)", function()
  local has_doc, svgdoc = pcall(require, "arclen.svgdoc")
  local function elements(body, arcs)
    local r = svgdoc.new({arcs = arcs})
    r:feed('<svg xmlns="http://www.w3.org/2000/svg">' .. body .. "</svg>")
    return r:finish("shapes.svg").elements
  end
  local W = math.sqrt(0.5)
  -- the quarters of the ellipse (cx, cy, rx, ry) from (cx + rx, cy) the
  -- positive way: each point a correctly rounded sum of the attributes
  -- (IEEE addition: the exact value rounded once), w = sqrt(1/2) rounded
  local function quarters(cx, cy, rx, ry)
    local E, N, Wx, S = cx + rx, cy + ry, cx - rx, cy - ry
    return {{E, cy, E, N, cx, N, W}, {cx, N, Wx, N, Wx, cy, W},
            {Wx, cy, Wx, S, cx, S, W}, {cx, S, E, S, E, cy, W}}
  end
  local M = {2, 0.5, -0.3, 1.2, 5, -7}
  local function mapped(q)
    local out = {}
    for i = 1, 5, 2 do
      out[i] = M[1] * q[i] + M[3] * q[i + 1] + M[5]
      out[i + 1] = M[2] * q[i] + M[4] * q[i + 1] + M[6]
    end
    out[7] = q[7]
    return out
  end

  it("circle and ellipse: four quarter conics through their boxes' corners, exact", function()
    if not has_doc then return print("  (arclen.svgdoc not built)") end
    local E = elements('<circle cx="0.1" cy="-0.7" r="0.2"/><ellipse cx="1" cy="2" rx="7" ry="2"/>'
      .. '<ellipse rx="1e6" ry="1e-6" cy="0.3"/>')
    local want = {quarters(0.1, -0.7, 0.2, 0.2), quarters(1, 2, 7, 2), quarters(0, 0.3, 1e6, 1e-6)}
    for k, e in ipairs(E) do
      assert.are.equal("RRRR", e.subpaths.kinds)
      assert.is_true(e.subpaths[1].closed)
      local r = records(e.subpaths)
      for j = 1, 4 do same(r[j], "R", want[k][j]) end
    end
    -- on the circle: |p - c| = r at every t, to rounding
    local worst = 0
    for _, q in ipairs(records(E[1].subpaths)) do
      for i = 0, 16 do
        local x, y = conic_point(q, i / 16)
        worst = math.max(worst, math.abs(math.sqrt((x - 0.1) ^ 2 + (y + 0.7) ^ 2) - 0.2))
      end
    end
    assert.is_true(worst <= 4 * EPS, worst)
  end)

  it("rect with rounded corners: lines and quarter conics; line, polyline, polygon: lines", function()
    if not has_doc then return print("  (arclen.svgdoc not built)") end
    local E = elements('<rect x="1" y="2" width="10" height="6" rx="2" ry="1"/><rect width="3" height="4"/>'
      .. '<line x1="1" y1="2" x2="7" y2="-3"/><polyline points="0,0 1,1 2,0"/><polygon points="0 0 4 0 4 3"/>')
    assert.are.equal("LRLRLRLR", E[1].subpaths.kinds)
    local r = records(E[1].subpaths)
    same(r[1], "L", {3, 2, 9, 2})
    same(r[2], "R", {9, 2, 11, 2, 11, 3, W})
    same(r[4], "R", {11, 7, 11, 8, 9, 8, W})
    same(r[8], "R", {1, 3, 1, 2, 3, 2, W})
    assert.are.equal("LLLL", E[2].subpaths.kinds)
    same(records(E[3].subpaths)[1], "L", {1, 2, 7, -3})
    assert.are.equal("LL", E[4].subpaths.kinds)
    assert.are.equal("LLL", E[5].subpaths.kinds)
  end)

  it("under a transform: the mapped records, and lengths against mpmath", function()
    if not has_doc then return print("  (arclen.svgdoc not built)") end
    local E = elements('<g transform="matrix(2 0.5 -0.3 1.2 5 -7)"><ellipse cx="1" cy="2" rx="7" ry="2"/>'
      .. '<rect x="1" y="2" width="10" height="6" rx="2" ry="1"/><circle cx="0.1" cy="-0.7" r="0.2"/></g>')
    local r = records(E[1].subpaths)
    for j, q in ipairs(quarters(1, 2, 7, 2)) do same(r[j], "R", mapped(q), size_of(r)) end
    -- the images' perimeters (mpmath, 40 digits: 4 a E(1 - b^2/a^2) of the
    -- image's semi-axes, the singular values of M diag(rx, ry), plus the
    -- rect's mapped sides); the conics' lengths are exact (Carlson)
    local REF = {59.990719654954277182771412567845954, 52.7176577364810619171985217609811}
    for k, want in ipairs(REF) do
      local got = 0
      for _, q in ipairs(records(E[k].subpaths)) do got = got + record_length(q, 1e-15) end
      assert.is_true(math.abs(got - want) <= 4e-15 * want, ("%d: %.17g vs %.17g"):format(k, got, want))
    end
  end)
end)

describe("svg path data: errors give the position in the string", function()
  local function E(d) return H.error_of(path.svg, d) end
  local cases = {
    {"", "empty at position 1"},
    {"   ", "empty at position 1"},
    {"L0 0", "must begin with a moveto.*position 1"},
    {"  5 5", "must begin with a moveto.*position 3"},
    {"M", "expected a number %(M x%).*position 2"},
    {"M0", "expected a number %(M y%).*position 3"},
    {"M0 0 X", "unknown command 'X' at position 6"},
    {"M0 0 L1e 2", "exponent without digits.*position 8"},
    {"M0,0,L1 1", "comma not followed by a number at position 5"},
    {"M0 0 A1 1 0 2 0 1 1", "large%-arc%-flag %(0 or 1%) at position 13"},
    {"M0 0 A1 1 0 0 x 1 1", "sweep%-flag %(0 or 1%) at position 15"},
    {"M 0 0 L 1 1 2", "%(L y%), got the end of the data at position 14"},
    {"M0 0 L1 1 Z 3", "after Z.*position 13"},
    {"M0 0 C1 1 2 2", "C x.*position 14"},
    {"M0 0 L1e999 0", "out of range '1e999' at position 7"},
    {"M0 0 L 1 1 #", "unknown command '#' at position 12"},
  }
  for _, case in ipairs(cases) do
    it(("'%s'"):format(case[1]), function()
      for _, arcs in ipairs({"conics", "cubics"}) do
        local msg = H.error_of(path.svg, case[1], {arcs = arcs})
        assert.is_not_nil(msg)
        assert.matches("bad argument #1 to 'arclen.path.svg'", msg)
        assert.matches(case[2], msg)
        assert.are.equal(E(case[1]), msg)
      end
    end)
  end
  it("names bad options and non-string data", function()
    assert.matches("#1.*path data %(a string%) expected, got number", H.error_of(path.svg, 5))
    assert.matches("#2.*unknown option 'bogus'", H.error_of(path.svg, "M0 0", {bogus = 1}))
    assert.matches("#2.*tol must be in", H.error_of(path.svg, "M0 0", {tol = 0}))
    assert.matches("#2.*arc_tol must be in", H.error_of(path.svg, "M0 0", {arc_tol = -1}))
    assert.matches("#2.*unknown method 'nope'", H.error_of(path.svg, "M0 0", {method = "nope"}))
    assert.matches('#2.*arcs must be "conics" or "cubics"', H.error_of(path.svg, "M0 0", {arcs = "arcs"}))
    assert.matches("bad argument #4 to '[^']*' %(arcs must be \"conics\" or \"cubics\"%)",
      H.error_of(arclen.svg_pathdata, "M0 0", 1e-12, nil, 3))
  end)
end)

describe("svg path data: the Lua engine's reader gives the C reader's records", function()
  local ok_pure, pure = pcall(require, "arclen.pure_svgpath")
  it("the same kinds, subpaths and numbers (arcs to a few ulps: libm), the same errors", function()
    assert.is_true(ok_pure, tostring(pure))
    local DS = {
      "M1 2 L4 6 H10 V0 C11 1 12 1 13 0 Q14 3 15 0 T 17 0 Z m1 1 q1 1 2 0 t2 0 s1 1 2 0",
      "M10 0 A10 10 0 1 1 -10 0", "M10 0 A10 5 0 0 1 0 5", "M0 0 A1 1 0 0 1 1e-320 0",
      "M0 0 A0 1 0 0 1 1 0", "M0 0 A5 3 30 0 0 4 4", "M0 0 A5 3 30 1 1 4 4",
      "M1 1 a5,5 0 01 10,0 a2 7 -45 1 0 -3 -3", "M0 0 A1 1 0 0 1 10 0 A0.5 2 60 1 1 0 7",
      "M3 4 A7 2 400 1 0 -6 2 A3 3 -720 0 1 0 0", "M-1e307 0 A1e307 1e307 0 0 1 1e307 0",
      "M10 0 A10 10 0 1 1 10 -0.001", "M1e308 0 A1e-300 1e-300 0 0 1 -1e308 0",
      "M0 0 A1 1 0 0 2 1 1", "M0 0 A1 1 0 0 1 1 1 Z m 5 5 a 1 2 0 0 0 -1 -2",
    }
    local TS = {false, {2, 0, 0, 3, 5, -7}, {0.6, 0.8, -0.8, 0.6, 1, 2}, {1, 1, 0, 0, 0, 0},
      {1e300, 0, 0, 1e300, 0, 0}}
    local worst = 0
    for _, d in ipairs(DS) do
      for _, T in ipairs(TS) do
        local a, am, ap = arclen.svg_pathdata(d, 1e-12, T or nil)
        local b, bm, bp = pure.svg_pathdata(d, 1e-12, T or nil)
        assert.are.equal(am, bm, d)
        assert.are.equal(ap, bp, d)
        if a then
          local ra, rb = records(a), records(b)
          assert.are.equal(a.kinds, b.kinds, d)
          assert.are.equal(#a, #b, d)
          local size = size_of(ra)
          for j = 1, #a do
            assert.is_true(near(a[j].x, b[j].x, size) and near(a[j].y, b[j].y, size), d)
            assert.are.equal(a[j].n, b[j].n); assert.are.equal(a[j].closed, b[j].closed)
          end
          for k, r in ipairs(ra) do
            for i = 1, #r do
              local e = math.abs(r[i] - rb[k][i]) / size
              worst = math.max(worst, e)
              assert.is_true(e <= 8 * EPS, ("%s: record %d number %d: %.17g vs %.17g"):format(
                d, k, i, r[i], rb[k][i]))
            end
          end
        end
      end
    end
    print(("  Lua reader against C: worst difference %.3g of the path's size"):format(worst))
    local _, msg = pure.svg_pathdata("M0 0 A1 1 0 0 1 1 1", 1e-12, nil, "cubics")
    assert.matches("arcs need the C core", msg)
  end)
end)

describe("svg path data: random input never crashes, hangs or gives NaN", function()
  -- MINSTD (Park & Miller): products stay below 2^53, so every Lua, with
  -- integers or doubles, makes the same strings.
  local state = 12345
  local function rand(n)
    state = (state * 48271) % 2147483647
    return state % n + 1
  end
  local ALPHABET = {"M", "m", "L", "l", "H", "h", "V", "v", "C", "c", "S", "s", "Q", "q",
    "T", "t", "A", "a", "Z", "z", "0", "1", "2", "5", "9", ".", "-", "+", "e", "E", " ",
    ",", "\n", "x", "10", "3.5", "-.5", "1e3", "0 0", " 1 1 "}
  local NARGS = {M = 2, L = 2, H = 1, V = 1, C = 6, S = 4, Q = 4, T = 2, A = 7, Z = 0}
  local CMDS = {"M", "L", "H", "V", "C", "S", "Q", "T", "A", "Z"}
  local NUMS = {"0", "1", "-2", "3.5", ".5", "-.25", "1e1", "2E-1", "10", "-7", "0.0"}
  local SEPS = {" ", ",", " , ", "\n", ""}
  -- Path data of random commands with the right number of arguments, one
  -- time in three with one byte changed or dropped.
  local function structured()
    local parts = {"M" .. NUMS[rand(#NUMS)] .. " " .. NUMS[rand(#NUMS)]}
    for _ = 1, rand(6) do
      local c = CMDS[rand(#CMDS)]
      if rand(2) == 1 then c = c:lower() end
      parts[#parts + 1] = c
      for k = 1, NARGS[c:upper()] do
        local v = NUMS[rand(#NUMS)]
        if c:upper() == "A" and (k == 4 or k == 5) then v = tostring(rand(2) - 1) end
        if k == 1 and c:upper() == "A" then v = tostring(rand(9)) end
        parts[#parts + 1] = (k > 1 and SEPS[rand(#SEPS)] or " ") .. v
      end
      parts[#parts + 1] = " "
    end
    local d = table.concat(parts)
    if rand(3) == 1 then
      local i = rand(#d)
      d = d:sub(1, i - 1) .. (rand(2) == 1 and ALPHABET[rand(#ALPHABET)] or "") .. d:sub(i + 1)
    end
    return d
  end
  it("4000 random strings: records of the four kinds with a finite length, or a positioned error", function()
    local ok_count, err_count, by_path = 0, 0, path_has_kinds()
    local seen = {}
    for n = 1, 4000 do
      local d
      if n % 2 == 0 then
        d = structured()
      else
        local parts = {rand(3) == 1 and "" or "M0 0"}
        for _ = 1, rand(24) do parts[#parts + 1] = ALPHABET[rand(#ALPHABET)] end
        d = table.concat(parts)
      end
      local arcs = n % 5 == 0 and "cubics" or "conics"
      local ok, res = pcall(path.svg, d, {arcs = arcs})
      if ok then
        ok_count = ok_count + 1
        local R = svgpath.parse(d, 1e-12, nil, arcs)
        local L = 0
        for _, r in ipairs(records(R)) do
          seen[r.kind] = true
          for i = 1, COUNT[r.kind] do assert.is_true(r[i] == r[i], d) end
          L = L + record_length(r, 1e-12)
        end
        if by_path or arcs == "cubics" then L = res:length() end
        assert.is_true(L >= 0 and L < math.huge, d)
        local x, y = res:point(L / 3)
        assert.is_true(x == x and y == y, d)
      else
        err_count = err_count + 1
        local pos = tonumber(tostring(res):match("^bad argument #1 to 'arclen%.path%.svg' %(.* at position (%d+)%)$"))
        assert.is_not_nil(pos, ("%q: %s"):format(d, tostring(res)))
        assert.is_true(pos >= 1 and pos <= #d + 1, d)
      end
    end
    assert.is_true(ok_count > 500 and err_count > 500, ok_count .. " parsed, " .. err_count .. " errors")
    assert.is_true(seen.L and seen.Q and seen.C and seen.R, "all four kinds met")
  end)
end)
