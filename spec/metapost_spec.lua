-- The "metapost" method and arclen.metapost against real MetaPost:
-- spec/data/mpost.tsv and mpost_paths.tsv are what `mpost -numbersystem=double`
-- printed (tools/ref_mpost.py, %.17g, so the doubles round-trip).  The bar is
-- bit-identity: numbers are compared with ==.
local arclen = require("arclen")
local H = require("helpers")
local mp = arclen.metapost
local unpack = table.unpack or unpack

local function csv(s)
  local out = {}
  for v in s:gmatch("[^,]+") do out[#out + 1] = assert(tonumber(v), v) end
  return out
end

local function segments(row)
  local v, segs = csv(row.coords), {}
  for k = 1, tonumber(row.n) do
    segs[k] = {unpack(v, 8 * k - 7, 8 * k)}
  end
  return segs
end

local function henkel(k)
  return H.curve(H.curves("curves2d.tsv", "henkel")[k])
end

describe("metapost: bit-identical to mpost -numbersystem=double", function()
  local rows = H.tsv("mpost.tsv")

  it("has >= 200 curves from real mpost, some over the 16384 limit", function()
    local over = 0
    for _, row in ipairs(rows) do if row.L == "overflow" then over = over + 1 end end
    assert.is_true(#rows >= 200)
    assert.is_true(over >= 3)
  end)

  it("arclength of every curve", function()
    local bad = {}
    for _, row in ipairs(rows) do
      if row.L ~= "overflow" then
        local c = H.curve(row)
        local L = mp.arclength(c)
        if L ~= tonumber(row.L) then bad[#bad + 1] = row.id .. " " .. row.family end
        local L2 = arclen.length(c, {method = "metapost"})
        if L2 ~= L then bad[#bad + 1] = row.id .. " (method)" end
      end
    end
    assert.are.same({}, bad)
  end)

  it("arctime at L/4, L/2, 3L/4 of every curve", function()
    local bad = {}
    for _, row in ipairs(rows) do
      if row.L ~= "overflow" then
        local c = H.curve(row)
        for q = 1, 3 do
          local g, want = tonumber(row["g" .. q]), tonumber(row["t" .. q])
          if mp.arctime(c, g) ~= want then bad[#bad + 1] = row.id .. " t" .. q end
          if arclen.time(c, g, {method = "metapost"}) ~= want then
            bad[#bad + 1] = row.id .. " t" .. q .. " (method)"
          end
        end
      end
    end
    assert.are.same({}, bad)
  end)

  it("legs of 16384 or more: nil, 'arithmetic overflow', where mpost errs", function()
    local n = 0
    for _, row in ipairs(rows) do
      if row.L == "overflow" then
        local c = H.curve(row)
        local v, msg = mp.arclength(c)
        assert.is_nil(v)
        assert.are.equal("arithmetic overflow", msg)
        v, msg = arclen.length(c, {method = "metapost"})
        assert.is_nil(v)
        assert.are.equal("arithmetic overflow", msg)
        v, msg = mp.arctime(c, 1)
        assert.is_nil(v)
        assert.are.equal("arithmetic overflow", msg)
        n = n + 1
      end
    end
    assert.is_true(n > 0)
  end)

  it("open and cyclic paths: arclength and arctime at negative, zero, inner and past-the-end goals", function()
    local bad, cyc = {}, 0
    for _, row in ipairs(H.tsv("mpost_paths.tsv")) do
      local segs, cyclic = segments(row), row.cyclic == "1"
      if cyclic then cyc = cyc + 1 end
      if mp.path_arclength(segs, cyclic) ~= tonumber(row.L) then
        bad[#bad + 1] = "path " .. row.id .. " L"
      end
      local goals, times = csv(row.goals), csv(row.times)
      for i, g in ipairs(goals) do
        if mp.path_arctime(segs, g, cyclic) ~= times[i] then
          bad[#bad + 1] = "path " .. row.id .. " goal " .. g
        end
      end
    end
    assert.are.same({}, bad)
    assert.is_true(cyc >= 10)
  end)
end)

describe("metapost: what the note explains", function()
  it("collinear arcs 4 and 5 are off by exactly 2^-17 (the fixed-point rounding constant)", function()
    for _, k in ipairs({4, 5}) do
      local ref = tonumber(H.curves("curves2d.tsv", "henkel")[k].L)
      local err = mp.arclength(henkel(k)) - ref
      assert.is_true(math.abs(err - 2^-17) < 1e-14, "arc " .. k .. ": " .. err)
    end
  end)

  it("the bias is 2^-17 per segment: three collinear segments give 3 * 2^-17", function()
    local p = {{0, 0, 1, 1, 2, 2, 3, 3}, {3, 3, 4, 4, 5, 5, 6, 6}, {6, 6, 7, 7, 8, 8, 9, 9}}
    local err = mp.path_arclength(p) - 9 * math.sqrt(2)
    assert.is_true(math.abs(err - 3 * 2^-17) < 1e-13, tostring(err))
  end)

  it("the tolerance is absolute: the error stays ~1e-5 as arc 1 is scaled by 2^-6 .. 2^8", function()
    local c = henkel(1)
    local ref = tonumber(H.curves("curves2d.tsv", "henkel")[1].L)
    local rel = {}
    for k = -6, 8 do
      local s, sc = 2^k, {}
      for i = 1, 8 do sc[i] = c[i] * s end     -- exact scaling
      local err = mp.arclength(sc) - s * ref
      assert.is_true(math.abs(err - 2^-17) < 1e-4, "scale 2^" .. k .. ": " .. err)
      rel[k] = math.abs(err) / (s * ref)
    end
    -- so the relative error falls as the curve grows
    assert.is_true(rel[8] < rel[-6] / 1000)
  end)

  it("survives the ~1100-level recursion of a collinear reversal (arc 5)", function()
    local L, info = arclen.length(henkel(5), {method = "metapost", info = true})
    assert.is_true(info.depth > 1000, tostring(info.depth))
    assert.are.equal(L, mp.arclength(henkel(5)))
  end)

  it("cyclic goals past the length wrap as MetaPost 2.11: n + arctime(rest)", function()
    local p = {{0, 0, 10, 0, 10, 10, 5, 12}, {5, 12, 0, 10, -3, 4, 0, 0}}
    local L = mp.path_arclength(p, true)
    for _, turns in ipairs({1, 3, 10}) do
      local g = 0.3 * L
      local t = mp.path_arctime(p, turns * L + g, true)
      local want = 2 * turns + mp.path_arctime(p, g, true)
      assert.is_true(math.abs(t - want) < 1e-9, turns .. ": " .. t .. " vs " .. want)
    end
  end)

  it("open paths: negative goals give 0, goals past the end the number of segments", function()
    local p = {{0, 0, 1, 2, 3, 2, 4, 0}, {4, 0, 5, -1, 6, 0, 7, 1}}
    assert.are.equal(0, mp.path_arctime(p, -3))
    assert.are.equal(2, mp.path_arctime(p, 1e6))
    assert.are.equal(0, mp.arctime({0, 0, 1, 2, 3, 2, 4, 0}, -1))
    assert.are.equal(1, mp.arctime({0, 0, 1, 2, 3, 2, 4, 0}, 100))
  end)
end)

describe("metapost: bad input", function()
  it("names the argument", function()
    if _VERSION >= "Lua 5.3" and not jit then   -- lauxlib finds the name in package.loaded
      assert.matches("bad argument #1 to 'arclen.metapost.arclength'",
                     H.error_of(mp.arclength, {1, 2, 3}))
    else                                        -- 5.1, 5.2, LuaJIT: only a call by name
      assert.matches("bad argument #1 to 'arclength'",
                     H.error_of(function(c) local v = mp.arclength(c) return v end, {1, 2, 3}))
    end
    assert.matches("2D", H.error_of(mp.arclength, {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}))
    assert.matches("bad argument #2 .*goal", H.error_of(mp.arctime, {0, 0, 1, 1, 2, 2, 3, 3}, 0 / 0))
    assert.matches("segment 2 does not start where segment 1 ends",
                   H.error_of(mp.path_arclength, {{0, 0, 1, 1, 2, 2, 3, 3}, {9, 9, 1, 1, 2, 2, 3, 3}}))
    assert.matches("cyclic", H.error_of(mp.path_arclength, {{0, 0, 1, 1, 2, 2, 3, 3}}, true))
    assert.matches("does not support this dimension",
                   H.error_of(arclen.length, {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}, {method = "metapost"}))
  end)
end)
