-- spec/svgpath_spec.lua -- SVG path data: the grammar (commands, implicit
-- repeats, numbers, separators, arc flags), exact conversions (lines,
-- quadratics), arcs within the stated tolerance, and errors that give the
-- position in the string.  Lengths against spec/data/paths.tsv (mpmath,
-- tools/ref_paths.py, which reads the path data independently).
local arclen = require("arclen")
local H = require("helpers")
local path = require("arclen.path")
local svgpath = require("arclen.svgpath")

-- The reader's packed cubics, as tables of 8 numbers.
local function cubics_of(R) return arclen._cubics(R.packed) end

local function segs(d, atol)
  local R = svgpath.parse(d, atol or 1e-12)
  local count = 0
  for j = 1, #R do count = count + R[j].n end
  assert.are.equal(R.n, count)                    -- the subpaths tile the cubics
  assert.are.equal(64 * R.n, #R.packed)
  return cubics_of(R)
end

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

describe("svg path data: commands", function()
  it("reads absolute and relative commands into the same segments", function()
    local a = segs("M1 2 L4 6 H10 V0 C11 1 12 1 13 0 Q14 3 15 0 Z")
    local r = segs("m1 2 l3 4 h6 v-6 c1 1 2 1 3 0 q1 3 2 0 z")
    assert.are.equal(#a, #r)
    for k = 1, #a do
      for i = 1, 8 do assert.is_true(math.abs(a[k][i] - r[k][i]) <= 1e-14 * 16) end
    end
    assert.are.equal(6, #a)          -- L H V C Q and the closing line
  end)

  it("turns lines into cubics with control points at thirds", function()
    same_cubic(segs("M0 0 L3 6")[1], {0, 0, 1, 2, 2, 4, 3, 6})
  end)

  it("elevates quadratics exactly: C1 = Q0 + 2/3 (Q1 - Q0), C2 = Q2 + 2/3 (Q1 - Q2)", function()
    same_cubic(segs("M0 0 Q3 6 6 0")[1], {0, 0, 2, 4, 4, 4, 6, 0})
    -- the elevated cubic is the quadratic: same points at every t
    local c = segs("M1 1 Q7 -2 3 5")[1]
    for _, t in ipairs({0.1, 0.3, 0.5, 0.9}) do
      local u = 1 - t
      local qx = u * u * 1 + 2 * u * t * 7 + t * t * 3
      local qy = u * u * 1 + 2 * u * t * -2 + t * t * 5
      local x, y = arclen.point(c, t)
      assert.is_true(math.abs(x - qx) <= 1e-14 * 8 and math.abs(y - qy) <= 1e-14 * 8)
    end
  end)

  it("reflects the previous control point for S and T, and not after other commands", function()
    same_cubic(segs("M0 0 C1 2 3 2 4 0 S7 -2 8 0")[2], {4, 0, 5, -2, 7, -2, 8, 0})
    same_cubic(segs("M0 0 L4 0 S7 -2 8 0")[2], {4, 0, 4, 0, 7, -2, 8, 0})
    -- T after Q: control (4,0) + ((4,0) - (2,3)) = (6,-3)
    local t = segs("M0 0 Q2 3 4 0 T8 0")[2]
    same_cubic(t, {4, 0, 4 + 2 / 3 * 2, 0 + 2 / 3 * -3, 8 + 2 / 3 * (6 - 8), 2 / 3 * -3, 8, 0})
    local t2 = segs("M0 0 L4 0 T8 0")[2]
    same_cubic(t2, {4, 0, 4, 0, 8 + 2 / 3 * (4 - 8), 0, 8, 0})
  end)

  it("repeats a command for further argument lists; after M they are linetos", function()
    local s = segs("M0 0 1 0 1 1")
    assert.are.equal(2, #s)
    near_cubic(s[2], {1, 0, 1, 1 / 3, 1, 2 / 3, 1, 1})
    local r = segs("m1 1 2 0 0 2")          -- relative: implicit l
    near_cubic(r[2], {3, 1, 3, 1 + 2 / 3, 3, 1 + 4 / 3, 3, 3})
    assert.are.equal(3, #segs("M0 0 C1 1 2 1 3 0 4 -1 5 -1 6 0 7 1 8 1 9 0"))
  end)

  it("reads numbers with exponents, signs and dots as separators", function()
    local s = segs("M1e1-.5.5.5L1E-1,2e+0 l-.5.5.5.5")
    assert.are.equal(10, s[1][1])
    assert.are.equal(-0.5, s[1][2])
    same_cubic({s[1][7], s[1][8]}, {0.5, 0.5})
    same_cubic({s[2][7], s[2][8]}, {0.1, 2})
    near_cubic({s[3][7], s[3][8]}, {0.1 - 0.5, 2.5})
    near_cubic({s[4][7], s[4][8]}, {0.1, 3})
    assert.are.equal(2, #segs("M 0 , 0 L\t1\n,\r1  ,2 2"))
  end)

  it("reads arc flags without separators", function()
    local a = segs("M0 0a5,5 0 01 10,0")
    local b = segs("M0 0 a 5 5 0 0 1 10 0")
    assert.are.equal(#b, #a)
    for k = 1, #a do same_cubic(a[k], b[k]) end
    assert.is_true(#segs("M0 0A10 10 0 1120 0") > 0)
  end)

  it("closes a subpath with a line only where the current point is elsewhere", function()
    assert.are.equal(3, #segs("M0 0 L1 0 L1 1 Z"))
    assert.are.equal(2, #segs("M0 0 L1 0 L0 0 Z"))
    local sp = svgpath.parse("M0 0 L1 0 Z L0 5", 1e-12)
    assert.are.equal(2, #sp)                          -- drawing after Z: a new subpath
    assert.is_true(sp[1].closed)
    assert.are.equal(0, sp[2].x)
    assert.are.equal(0, sp[2].y)
  end)
end)

describe("svg path data: arcs", function()
  it("follows F.6.2: equal end points omit the arc, a zero radius is a line", function()
    assert.are.equal(0, #segs("M1 1 A5 5 0 0 1 1 1"))
    local l = segs("M0 0 A0 5 0 0 1 3 3")
    assert.are.equal(1, #l)
    assert.are.equal(3, l[1][7])
  end)

  it("joins the arc's ends exactly to the path's points", function()
    local s = segs("M10 0 A10 7 20 1 1 -10 0 L0 0")
    local last_arc = s[#s - 1]
    assert.are.equal(10, s[1][1])
    assert.are.equal(0, s[1][2])
    assert.are.equal(-10, last_arc[7])
    assert.are.equal(0, last_arc[8])
  end)

  it("stays within arc_tol * max(rx, ry, chord/2) of the true circle", function()
    for _, atol in ipairs({1e-3, 1e-6, 1e-9, 1e-12}) do
      local s = segs("M10 0 A10 10 0 1 1 -10 0", atol)
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
end)

describe("svg path data: lengths against mpmath (spec/data/paths.tsv)", function()
  local rows = H.tsv("paths.tsv")
  it("has the reference paths", function() assert.is_true(#rows >= 20) end)
  for _, tol in ipairs({1e-12, 1e-8}) do
    it(("within tol * L, plus 2 pi arc_tol * scale per arc (tol %g)"):format(tol), function()
      local w = H.worst()
      for _, row in ipairs(rows) do
        local want = tonumber(row.L)
        local atol = tol
        local got = path.svg(row.d, {tol = tol, arc_tol = atol}):length()
        -- an arc within Hausdorff distance delta of the ellipse has a length
        -- within (turning angle <= 2 pi) * delta of the ellipse arc's
        local bound = tol * want + 2 * math.pi * atol * tonumber(row.arcscale)
        local err = math.abs(got - want)
        assert.is_true(err <= bound, ("%s: error %g > %g"):format(row.id, err, bound))
        w:add(err / want, row.id)
      end
      print(("  svg lengths (tol %g): worst relative error %.3g (%s)"):format(tol, w.err, w.id))
    end)
  end
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
      local msg = E(case[1])
      assert.is_not_nil(msg)
      assert.matches("bad argument #1 to 'arclen.path.svg'", msg)
      assert.matches(case[2], msg)
    end)
  end
  it("names bad options and non-string data", function()
    assert.matches("#1.*path data %(a string%) expected, got number", H.error_of(path.svg, 5))
    assert.matches("#2.*unknown option 'bogus'", H.error_of(path.svg, "M0 0", {bogus = 1}))
    assert.matches("#2.*tol must be in", H.error_of(path.svg, "M0 0", {tol = 0}))
    assert.matches("#2.*arc_tol must be in", H.error_of(path.svg, "M0 0", {arc_tol = -1}))
    assert.matches("#2.*unknown method 'nope'", H.error_of(path.svg, "M0 0", {method = "nope"}))
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
  it("4000 random strings: a path with a finite length or a positioned error", function()
    local ok_count, err_count = 0, 0
    for n = 1, 4000 do
      local d
      if n % 2 == 0 then
        d = structured()
      else
        local parts = {rand(3) == 1 and "" or "M0 0"}
        for _ = 1, rand(24) do parts[#parts + 1] = ALPHABET[rand(#ALPHABET)] end
        d = table.concat(parts)
      end
      local ok, res = pcall(path.svg, d)
      if ok then
        ok_count = ok_count + 1
        local L = res:length()
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
  end)
end)
