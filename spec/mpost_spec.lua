-- arclen.mpost, the Lua side of mp/arclen.mp, without TeX: what it answers
-- MetaPost's runscript for a path written as arclen_knots_ writes it.
-- (The real runs are make luatex: tools/check-luatex.sh.)
local mpost = require("arclen.mpost")
local path = require("arclen.path")
local arclen = require("arclen")
local H = require("helpers")

-- An open wave of three segments, as "o x,y,lx,ly,rx,ry ..." (17 digits).
local segs = {{0, 0, 10, 20, 30, 20, 40, 0}, {40, 0, 50, -20, 70, -20, 80, 0},
  {80, 0, 90, 20, 110, 1 / 3, 120, 0}}
local function knots_text(cs, cyc)
  local out = {cyc and "c" or "o"}
  local n = #cs
  for k = 1, (cyc and n or n + 1) do
    local c, prev = cs[k] or cs[n], cs[k - 1] or (cyc and cs[n])
    local x, y = (cs[k] and c[1] or c[7]), (cs[k] and c[2] or c[8])
    local lx, ly = prev and prev[5] or x, prev and prev[6] or y
    local rx, ry = cs[k] and c[3] or x, cs[k] and c[4] or y
    out[#out + 1] = ("%.17g,%.17g,%.17g,%.17g,%.17g,%.17g"):format(x, y, lx, ly, rx, ry)
  end
  return table.concat(out, " ")
end
local K = knots_text(segs)
local P = path(segs)

describe("arclen.mpost", function()
  local warnings = {}
  mpost.warn = function(msg) warnings[#warnings + 1] = msg end

  it("length: arclen's, with 17 significant digits", function()
    local got = mpost.run("length", "double", "gauss", 0, K)
    assert.are.equal(("%.17g"):format(P:length()), got)
    assert.are.equal(P:length(), tonumber(got))
  end)

  it("time: MetaPost's arctime convention on an open path (clamped)", function()
    assert.are.equal(P:time(50), tonumber(mpost.run("time", "double", "gauss", 0, K, 50)))
    assert.are.equal("3", mpost.run("time", "double", "gauss", 0, K, 1e6))
    assert.are.equal("0", mpost.run("time", "double", "gauss", 0, K, -1))
  end)

  H.c_only(it, "method 'metapost'")("method metapost: arclen.metapost's values", function()
    local L = arclen.metapost.path_arclength(segs)
    assert.are.equal(L, tonumber(mpost.run("length", "double", "metapost", 0, K)))
    local t = arclen.metapost.path_arctime(segs, 70)
    assert.are.equal(t, tonumber(mpost.run("time", "double", "metapost", 0, K, 70)))
  end)

  it("a cycle wraps: n * turns + the time of the rest", function()
    local c = {{0, 0, 10, 0, 10, 10, 5, 12}, {5, 12, 0, 10, -3, 4, 0, 0}}
    local kc = knots_text(c, true)
    local pc = path(c, {cyclic = true})
    local L = pc:length()
    local t = tonumber(mpost.run("time", "double", "gauss", 0, kc, 2.5 * L))
    assert.is_true(math.abs(t - (4 + pc:time(0.5 * L))) < 1e-12)
  end)

  it("subpath: the times of two lengths, as a pair", function()
    local got = mpost.run("subpath", "double", "gauss", 0, K, 20, 60)
    assert.are.equal(("(%.17g,%.17g)"):format(P:time(20), P:time(60)), got)
  end)

  it("points: a path through n points, p:resample's", function()
    local got = mpost.run("points", "double", "gauss", 0, K, 5)
    local n = 0
    for _ in got:gmatch("%.%.controls") do n = n + 1 end
    assert.are.equal(4, n)
    local q = P:resample(5)
    assert.is_truthy(got:find(("(%.17g,%.17g)"):format(q[3].x, q[3].y), 1, true))
  end)

  it("dashed: one draw per dash of p:dash", function()
    local got = mpost.run("dashed", "double", "gauss", 0, K, 0, {6, 3})
    local n = 0
    for _ in got:gmatch("draw ") do n = n + 1 end
    assert.are.equal(#P:dash({6, 3}), n)
    assert.are.equal("image(", got:sub(1, 6))
  end)

  it("numbersystem scaled: rounded to 2^-16, fixed point; 4096 and over an error", function()
    local got = mpost.run("length", "scaled", "gauss", 0, K)
    local v = tonumber(got)
    mpost.run("length", "scaled", "gauss", 0, K)
    assert.are.equal(1, #warnings)          -- once
    assert.matches("numbersystem scaled", warnings[1])
    assert.is_nil(got:find("e"))
    assert.are.equal(v * 65536, math.floor(v * 65536))
    assert.is_true(math.abs(v - P:length()) <= 2 ^ -17)
    local big = knots_text({{0, 0, 1000, 0, 3000, 0, 4000, 0}, {4000, 0, 3000, 1, 1000, 1, 0, 1}})
    assert.matches("errmessage \"arclen_length: .*beyond numbersystem scaled", mpost.run("length", "scaled", "gauss", 0, big))
  end)

  it("bad arguments: an errmessage and a value of the expected type", function()
    assert.matches('^begingroup errmessage "arclen_time: the length must be a known numeric"; 0 endgroup$',
      mpost.run("time", "double", "gauss", 0, K, nil))
    assert.matches("unknown method 'bogus'", mpost.run("length", "double", "bogus", 0, K))
    assert.matches("arclen_tol must be", mpost.run("length", "double", "gauss", 1, K))
    assert.matches("dash pattern must not be all zero.*nullpicture", mpost.run("dashed", "double", "gauss", 0, K, 0, {0, 0}))
    assert.matches("n must be an integer.*%(0,0%) endgroup", mpost.run("points", "double", "gauss", 0, K, 0))
    assert.matches("align must be", mpost.run("followtext", "double", "gauss", 0, K, 0, "middle", "x"))
    assert.matches("malformed", mpost.run("length", "double", "gauss", 0, "x 1,2"))
  end)

  it("a one-point path: length 0, time 0, no room for text", function()
    local k1 = "o 3,4,3,4,3,4"
    assert.are.equal("0", mpost.run("length", "double", "gauss", 0, k1))
    assert.are.equal("0", mpost.run("time", "double", "gauss", 0, k1, 5))
    assert.matches("length 0", mpost.run("followtext", "double", "gauss", 0, k1, 0, "start", "x"))
    assert.are.equal("nullpicture", mpost.run("followtext", "double", "gauss", 0, K, 0, "start", ""))
  end)

  it("messages carry no double quote (MetaPost strings cannot)", function()
    local got = mpost.run("followtext", "double", "gauss", 0, K, 0, 'say "hi"', "x")
    assert.is_nil(got:match('errmessage ".*".*"'))
  end)
end)
