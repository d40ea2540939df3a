-- spec/hostile_spec.lua -- every Lua entry point of arclen against hostile
-- input: wrong types, missing and extra arguments, NaN/inf/huge/subnormal
-- numbers, empty and enormous tables, malformed SVG path data and mplib
-- knots.  Each call must end in one of three ways: a result with no NaN in
-- it, a documented nil-plus-message, or an error "bad argument #n to 'f'
-- (...)" that names an argument (lauxlib's style; the Lua parts use the
-- same words, methods on a wrong self say "calling 'f' on bad self").  The
-- process lives on.  Then the worst inputs known for termination run under
-- a wall-clock limit (os.clock; ARCLEN_TIME_SCALE stretches it for
-- valgrind and sanitizer runs).
local arclen = require("arclen")
local path = arclen.path
-- On the Lua engine what only the C core has raises an error naming it:
-- the outcome "c-only", accepted there (helpers.c_only for whole specs).
local lua_engine = require("helpers").engine == "lua"

local TIME_SCALE = tonumber(os.getenv("ARCLEN_TIME_SCALE")) or 1
local NAN, INF = 0 / 0, math.huge

local C2 = {0, 0, 10, 0, 10, 10, 0, 0}             -- Henkel's arc 1
local C3 = {0, 0, 0, 1, 2, 0, 3, 1, 1, 4, 0, 2}
local SEGS = {{0, 0, 10, 0, 10, 10, 5, 12}, {5, 12, 0, 10, -3, 4, 0, 0}}

-- Any NaN among the results (numbers, or numbers in result tables one or
-- two levels down)?
local function has_nan(v, depth)
  if type(v) == "number" then return v ~= v end
  if type(v) == "table" and (depth or 0) < 2 then
    for _, x in pairs(v) do
      if has_nan(x, (depth or 0) + 1) then return true end
    end
  end
  return false
end

-- The outcome of f(...): "ok" (no NaN), "nilmsg", "argerror" (with the
-- argument number), or "bad: <why>".
local function outcome(f, ...)
  local n = select("#", ...)
  local args = {...}
  local res = table.pack(pcall(function() return f(table.unpack(args, 1, n)) end))
  if res[1] then
    if res.n >= 2 and res[2] == nil and res.n >= 3 and type(res[3]) == "string" then
      return "nilmsg"
    end
    for i = 2, res.n do
      if has_nan(res[i]) then return "bad: NaN in result " .. (i - 1) end
    end
    return "ok"
  end
  local msg = res[2]
  if type(msg) ~= "string" then return "bad: error object " .. tostring(msg) end
  if lua_engine and msg:find("needs the C core", 1, true) then return "c-only", nil, msg end
  local k = msg:match("bad argument #(%d+) to '[^']*' %(.+%)")
  if k then return "argerror", tonumber(k), msg end
  if msg:match("calling '[^']+' on bad self") then return "argerror", 0, msg end
  return "bad: unexpected message: " .. msg
end

-- ---- every entry point and a valid call of it -----------------------------

local fit = not lua_engine and arclen.fit(C2) or nil
local P = path.svg("M0 0 C 10 0 10 10 0 10 L 5 5 Z")

-- name -> {function, valid arguments}
local VALID = {
  ["length"] = {arclen.length, {C2}},
  ["time"] = {arclen.time, {C2, 5}},
  ["point"] = {arclen.point, {C2, 0.5}},
  ["derivative"] = {arclen.derivative, {C2, 0.5}},
  ["split"] = {arclen.split, {C2, 0.5}},
  ["subcurve"] = {arclen.subcurve, {C2, 0.2, 0.7}},
  ["critical"] = {arclen.critical, {C2}},
  ["methods"] = {arclen.methods, {}},
  ["method"] = {arclen.method, {"gauss"}},
  ["lengths"] = {arclen.lengths, {{0, 0, 1, 0, 2, 0, 3, 0, 0, 0, 10, 0, 10, 10, 0, 0}}},
  ["lengths3"] = {arclen.lengths3, {C3}},
  ["times"] = {arclen.times, {C2, {1, 5}, {points = true, tangents = true}}},
  ["_walk_times"] = {arclen._walk_times, {{C2}, {[0] = 0, 14}, {1, 5}, 1e-12, false, {}, {}}},
  ["_locate"] = {arclen._locate, {{C2}, {[0] = 0, 14}, 5, 1e-12, false}},
  ["_array"] = {arclen._array, {4}},
  ["_queries"] = {arclen._queries, {{1, 5}, 14, false}},
  ["_walk_samples"] = {arclen._walk_samples, {{C2}, {[0] = 0, 14}, {1, 5}, 1e-12, {}}},
  ["conic"] = {arclen.conic, {{1, 0}, {1, 1}, {0, 1}, 0.7}},
  ["conic_length"] = {arclen.conic_length, {{1, 0}, {1, 1}, {0, 1}, 0.7}},
  ["conic_scheme"] = {arclen.conic_scheme, {"midpoint", 0.7}},
  ["ellipse_arc"] = {arclen.ellipse_arc, {0, 0, 2, 1, 0.3, 0, 2}},
  ["ellipse_conics"] = {arclen.ellipse_conics, {0, 0, 2, 1, 0.3, 0, 2}},
  ["svg_arc"] = {arclen.svg_arc, {0, 0, 5, 3, 30, 0, 1, 8, 2}},
  ["svg_pathdata"] = {arclen.svg_pathdata, {lua_engine and "M0 0 L1 1 Q2 2 3 0" or "M0 0 L1 1 A1 1 0 0 1 2 2",
                                             1e-12, {1, 0, 0, 1, 0, 0}}},
  ["_cubics"] = {arclen._cubics, {arclen.svg_pathdata("M0 0 L1 1 Q2 2 3 0", 1e-12).packed}},
  ["segment_length"] = {arclen.segment_length, {"conic", {1, 0, 1, 1, 0, 1, 0.7}, {tol = 1e-9}}},
  ["segment_time"] = {arclen.segment_time, {"quad", {0, 0, 1, 2, 2, 0}, 1, {tol = 1e-9}}},
  ["segment_point"] = {arclen.segment_point, {"conic", {1, 0, 1, 1, 0, 1, 0.7}, 0.5}},
  ["segment_derivative"] = {arclen.segment_derivative, {"quad", {0, 0, 1, 2, 2, 0}, 0.5}},
  ["segment_sub"] = {arclen.segment_sub, {"line", {0, 0, 3, 4}, 0.2, 0.7}},
  ["_segments"] = {arclen._segments, {arclen.svg_pathdata("M0 0 L1 1 Q2 2 3 0", 1e-12).packed, nil, 2}},
  ["svg_number"] = {arclen.svg_number, {"x 1.5e3", 3}},
  ["svg_numbers"] = {arclen.svg_numbers, {"0 0 10,10 1e1", 8}},
  ["fullcircle"] = {arclen.fullcircle, {}},
  ["fit"] = {arclen.fit, {C2}},
  ["gauss_legendre"] = {arclen.gauss_legendre, {5}},
  ["quadratic"] = {arclen.quadratic, {1, -3, 2}},
  ["cubic"] = {arclen.cubic, {1, -6, 11, -6}},
  ["quartic"] = {arclen.quartic, {1, 0, -5, 0, 4}},
  ["quartic_factor"] = {arclen.quartic_factor, {1, 0, -5, 0, 4}},
  ["carlson.rf"] = {arclen.carlson.rf, {1, 2, 3}},
  ["carlson.rd"] = {arclen.carlson.rd, {1, 2, 3}},
  ["carlson.rc"] = {arclen.carlson.rc, {1, 2}},
  ["carlson.rj"] = {arclen.carlson.rj, {1, 2, 3, 4}},
  ["carlson.rg"] = {arclen.carlson.rg, {1, 2, 3}},
  ["metapost.arclength"] = {arclen.metapost.arclength, {C2}},
  ["metapost.arctime"] = {arclen.metapost.arctime, {C2, 5}},
  ["metapost.path_arclength"] = {arclen.metapost.path_arclength, {SEGS, false}},
  ["metapost.path_arctime"] = {arclen.metapost.path_arctime, {SEGS, 10, false}},
  ["path"] = {path, {{C2}}},
  ["path.svg"] = {path.svg, {"M0 0 C 10 0 10 10 0 10"}},
  ["path.mplib"] = {path.mplib, {{{x_coord = 0, y_coord = 0, right_x = 10, right_y = 0,
                                   left_x = 10, left_y = 10, type = "endpoint"},
                                  {x_coord = 0, y_coord = 10, left_x = 10, left_y = 10,
                                   right_x = 0, right_y = 10, type = "endpoint"}}}},
  ["path.is_path"] = {path.is_path, {P}},
  ["path._from_subpaths"] = {path._from_subpaths, {arclen.svg_pathdata("M0 0 L1 1 Z", 1e-12), 1e-12, "gauss"}},
  -- methods, called as f(self, ...)
  [":length"] = {P.length, {P}},
  [":time"] = {P.time, {P, 5}},
  [":point"] = {P.point, {P, 5}},
  [":tangent"] = {P.tangent, {P, 5}},
  [":sub"] = {P.sub, {P, 1, 9}},
  [":split"] = {P.split, {P, 5}},
  [":resample"] = {P.resample, {P, 10}},
  [":dash"] = {P.dash, {P, {2, 1}, 0}},
  [":points"] = {P.points, {P, {1, 5}, {tangents = true, times = true}}},
  [":samples"] = {P.samples, {P, {1, 5}}},
  [":segments"] = {P.segments, {P}},
  [":segment"] = {P.segment, {P, 1}},
  [":svg"] = {P.svg, {P}},
}
if fit then                              -- a fit needs the C core
  VALID["fit:length"] = {fit.length, {fit, 0.5}}
  VALID["fit:value"] = {fit.value, {fit, 0.5}}
  VALID["fit:time"] = {fit.time, {fit, 5}}
  VALID["fit:spans"] = {fit.spans, {fit}}
  VALID["fit:monotone"] = {fit.monotone, {fit}}
  VALID["fit:errors"] = {fit.errors, {fit}}
end

-- Everything reachable from the module, so that a new function without a
-- row above fails here (and gets one).
local function reachable()
  local names = {}
  for k, v in pairs(arclen) do
    if type(v) == "function" then
      names[#names + 1] = k
    elseif type(v) == "table" and k ~= "path" then
      for k2, v2 in pairs(v) do
        if type(v2) == "function" then names[#names + 1] = k .. "." .. k2 end
      end
    end
  end
  names[#names + 1] = "path"
  for k, v in pairs(path) do
    if type(v) == "function" then names[#names + 1] = "path." .. k end
  end
  for k, v in pairs(getmetatable(P).__index) do
    if type(v) == "function" and not k:match("^__") then names[#names + 1] = ":" .. k end
  end
  for k, v in pairs(fit and getmetatable(fit).methods or {}) do
    if type(v) == "function" and not k:match("^__") then names[#names + 1] = "fit:" .. k end
  end
  table.sort(names)
  return names
end

local HOSTILE = {
  {"nil", nil}, {"a string", "x"}, {"a numeric string", "1"}, {"true", true},
  {"an empty table", {}}, {"a function", print}, {"a coroutine", coroutine.create(function() end)},
  {"a file", io.stdout}, {"NaN", NAN}, {"inf", INF}, {"-inf", -INF},
  {"1e308", 1e308}, {"-1e308", -1e308}, {"a subnormal", 5e-324}, {"-0", -0.0},
  {"2^53+1", 2^53 + 1}, {"a nested table", {{}, {{}}}}, {"a table of NaN", {NAN, NAN, NAN, NAN, NAN, NAN, NAN, NAN}},
}

local function sorted_keys(t)
  local ks = {}
  for k in pairs(t) do ks[#ks + 1] = k end
  table.sort(ks)
  return ks
end

describe("hostile input", function()
  it("every entry point has a valid call here, and it succeeds", function()
    local missing = {}
    for _, name in ipairs(reachable()) do
      if not VALID[name] then missing[#missing + 1] = name end
    end
    assert.are.same({}, missing)
    for _, name in ipairs(sorted_keys(VALID)) do
      local e = VALID[name]
      local r = outcome(e[1], table.unpack(e[2]))
      if not (lua_engine and r == "c-only") then assert.are.equal("ok", r, name) end
    end
  end)

  it("no arguments: a named argument error or a result without NaN", function()
    local bad = {}
    for _, name in ipairs(sorted_keys(VALID)) do
      local r = outcome(VALID[name][1])
      if r ~= "ok" and r ~= "argerror" and r ~= "nilmsg" and r ~= "c-only" then bad[#bad + 1] = name .. ": " .. r end
    end
    assert.are.same({}, bad)
  end)

  -- one case per entry point, so that a failure names its function
  for _, name in ipairs(sorted_keys(VALID)) do
    it(name .. ": each argument replaced by each hostile value", function()
      local f, args = VALID[name][1], VALID[name][2]
      local bad = {}
      for i = 1, #args do
        for _, h in ipairs(HOSTILE) do
          local a = {table.unpack(args)}
          a[i] = h[2]
          local r, k, msg = outcome(f, table.unpack(a, 1, #args))
          if r:match("^bad") then
            bad[#bad + 1] = ("argument %d = %s: %s"):format(i, h[1], r)
          elseif r == "argerror" and k == 0 and i ~= 1 then
            bad[#bad + 1] = ("argument %d = %s: blames self: %s"):format(i, h[1], msg)
          end
        end
      end
      assert.are.same({}, bad)
    end)
  end

  it("extra arguments are ignored or named", function()
    local bad = {}
    for _, name in ipairs(sorted_keys(VALID)) do
      local f, args = VALID[name][1], VALID[name][2]
      for _, extra in ipairs({"extra", {}, NAN, true}) do
        local a = {table.unpack(args)}
        a[#args + 1] = extra
        a[#args + 2] = extra
        local r, k = outcome(f, table.unpack(a, 1, #args + 2))
        -- the Lua methods number arguments after self
        local last = name:match("^:") and #args - 1 or #args
        if r:match("^bad") then
          bad[#bad + 1] = name .. ": " .. r
        elseif r == "argerror" and k <= last and k > 0 then
          bad[#bad + 1] = name .. ": an extra argument blamed #" .. k
        end
      end
    end
    assert.are.same({}, bad)
  end)

  it("NaN or inf at any coordinate of a curve is an argument error", function()
    local takes_curve = {"length", "time", "point", "derivative", "split", "subcurve",
                         "critical", "fit", "metapost.arclength", "metapost.arctime"}
    for _, name in ipairs(takes_curve) do
      local f, args = (VALID[name] or {})[1], (VALID[name] or {})[2]
      if lua_engine and (not f or outcome(f, table.unpack(args)) == "c-only") then f = nil end
      for i = 1, f and 8 or 0 do
        for _, v in ipairs({NAN, INF, -INF}) do
          local c = {table.unpack(C2)}
          c[i] = v
          local r, k = outcome(f, c, table.unpack(args, 2))
          assert.are.equal("argerror", r, name .. " coordinate " .. i .. " = " .. tostring(v))
          assert.are.equal(1, k, name)
          -- the 8 numbers given directly
          if name ~= "fit" and not name:match("^metapost") then
            local a = {table.unpack(c)}
            for j = 2, #args do a[#a + 1] = args[j] end
            r, k = outcome(f, table.unpack(a))
            assert.are.equal("argerror", r, name .. " (numbers) coordinate " .. i)
            assert.are.equal(i, k, name .. " (numbers) coordinate " .. i)
          end
        end
      end
    end
  end)

  it("huge, tiny and subnormal coordinates give finite lengths by every method", function()
    local curves = {
      {0, 0, 1e300, 0, 1e300, 1e300, 0, 0}, {-1e300, 1e300, 1e300, -1e300, 1e300, 1e300, -1e300, -1e300},
      {0, 0, 5e-324, 0, 1e-323, 5e-324, 0, 1e-323}, {1e-310, 0, 0, 1e-310, -1e-310, 0, 0, -1e-310},
      {1e8, 1e8, 1e8 + 1e-8, 1e8, 1e8, 1e8 + 1e-8, 1e8 + 1e-8, 1e8 + 1e-8},
    }
    for _, m in ipairs(arclen.methods()) do
      for j, c in ipairs(curves) do
        local r, k, msg = outcome(arclen.length, c, {method = m, steps = 1000})
        assert.is_true(r == "ok" or r == "nilmsg", m .. " curve " .. j .. ": " .. r .. " " .. tostring(msg))
        if r == "ok" then
          local L = arclen.length(c, {method = m, steps = 1000})
          assert.is_true(L >= 0 and L < INF, m .. " curve " .. j .. ": " .. L)
        end
      end
    end
  end)

  it("empty and enormous tables", function()
    local big = {}
    for i = 1, 800000 do big[i] = (i * 7919) % 1000 / 100 end
    assert.are.equal("argerror", (outcome(arclen.length, {})))
    assert.are.equal("argerror", (outcome(arclen.length, big)))
    local mp = lua_engine and "c-only" or "argerror"      -- MetaPost's method: the C core
    assert.are.equal(mp, (outcome(arclen.metapost.path_arclength, {}, false)))
    assert.are.equal(mp, (outcome(arclen.metapost.path_arclength, {{}}, false)))
    assert.are.same({}, arclen.lengths({}))
    local t0 = os.clock()
    local L = arclen.lengths(big)
    assert.are.equal(100000, #L)
    assert.is_true(os.clock() - t0 < 20 * TIME_SCALE)
    for i = 1, #L, 997 do assert.is_true(L[i] >= 0 and L[i] < INF) end
    -- a path of 10^5 segments from SVG data
    local d = {"M0 0"}
    for i = 1, 100000 do d[#d + 1] = ("C%d 1 %d 2 %d 0"):format(i, i + 1, i + 1) end
    local p = path.svg(table.concat(d, " "))
    local len = p:length()
    assert.is_true(len > 0 and len < INF)
    local r = outcome(path, {})
    assert.is_true(r == "ok" or r == "argerror" or r == "nilmsg", r)
    r = outcome(path.svg, "")
    assert.is_true(r == "ok" or r == "argerror" or r == "nilmsg", r)
    r = outcome(path.mplib, {})
    assert.is_true(r == "ok" or r == "argerror" or r == "nilmsg", r)
  end)

  it("malformed SVG path data: a named error (with a position) or a finite path", function()
    local cases = {
      "M", "M0", "M0,", "M 0 0 C", "M0 0 C1 2 3", "M0 0 L1e400 0", "M0 0 Lnan 0",
      "M0 0 Linf 0", "C1 2 3 4 5 6", "M0 0 X1 2", "M0 0 A5 5 0 2 0 1 1",
      "M0 0 A5 5 0 0 0 1e308 1e308", "M0 0 A1e-320 1e-320 0 0 0 1 1", "M0 0 A0 0 0 0 0 1 1",
      "M0 0 A5 5 1e308 0 0 1 1", "M0 0 Q", "M0 0 T", "M0 0 S1 1", "M1e308 1e308 l1e308 1e308",
      "M0 0 H", "M0 0 V", ("M0 0 " .. ("L1 1 "):rep(10000)), "\0\1\2", ("M"):rep(100000),
      "M0 0 z z z z", "M0 0 c1-2-3-4-5-6", "M.1.2.3.4", "M0 0 L1e-320 1e-320",
    }
    local bad = {}
    for _, d in ipairs(cases) do
      local r, _, msg = outcome(function(s) local p = path.svg(s); return p:length() end, d)
      if r:match("^bad") then bad[#bad + 1] = ("%q: %s"):format(d:sub(1, 40), r) end
      if r == "argerror" and not msg:match("position") and not msg:match("%d") then
        bad[#bad + 1] = ("%q: no position in %s"):format(d:sub(1, 40), msg)
      end
    end
    -- random strings over the grammar's alphabet (bounded, seeded)
    local alphabet = "MmLlHhVvCcSsQqTtAaZz0123456789.,-+eE \t\n"
    local seed = 12345
    local function rand(n)          -- Park-Miller, the same on every Lua
      seed = seed * 48271 % 2147483647
      return seed % n + 1
    end
    for _ = 1, 2000 do
      local s = {}
      for j = 1, rand(40) do
        local k = rand(#alphabet)
        s[j] = alphabet:sub(k, k)
      end
      local d = table.concat(s)
      local r = outcome(function(x) local p = path.svg(x); return p:length(), p:point(p:length() / 2) end, d)
      if r:match("^bad") then bad[#bad + 1] = ("%q: %s"):format(d, r) end
    end
    assert.are.same({}, bad)
  end)

  it("malformed mplib knot lists: a named error or a finite path", function()
    local k = {x_coord = 0, y_coord = 0, right_x = 1, right_y = 0, left_x = 0, left_y = 0}
    local cases = {
      {{}}, {k}, {k, "x"}, {k, {x_coord = NAN, y_coord = 0}}, {{x_coord = "a"}},
      {k, {x_coord = INF, y_coord = 0, left_x = 0, left_y = 0, right_x = 0, right_y = 0}},
      setmetatable({}, {__index = function() error("boom") end}),
      {k, k, k, cycle = true}, {{x_coord = 1e308, y_coord = -1e308, left_x = -1e308,
        left_y = 1e308, right_x = 1e308, right_y = 1e308}, k},
    }
    local bad = {}
    for i, knots in ipairs(cases) do
      local r = outcome(function(x) local p = path.mplib(x); return p:length() end, knots)
      if r:match("^bad") and not r:match("boom") then bad[#bad + 1] = i .. ": " .. r end
    end
    assert.are.same({}, bad)
  end)
end)

describe("termination: the worst known inputs finish in time", function()
  local function within(limit, what, f)
    local t0 = os.clock()
    local r, k, msg = outcome(f)
    local dt = os.clock() - t0
    assert.is_true(r == "ok" or r == "nilmsg", what .. ": " .. r .. " " .. tostring(msg))
    assert.is_true(dt < limit * TIME_SCALE, ("%s took %.2f s (limit %g s)"):format(what, dt, limit * TIME_SCALE))
    return dt
  end

  local H = require("helpers")
  H.c_only(it, "method 'metapost'")("MetaPost's ~1100-level recursion on a collinear reversal (Henkel's arc 5)", function()
    local c = {0, 0, 20, 20, -10, -10, 10, 10}
    within(2, "metapost arclength", function()
      local L, info = arclen.length(c, {method = "metapost", info = true})
      assert.is_true(info.depth > 1000)
      return L
    end)
    within(2, "metapost arctime", function() return arclen.metapost.arctime(c, 10) end)
    -- the same at every scale MetaPost accepts
    for e = -20, 13, 3 do
      local s = {}
      for i = 1, 8 do s[i] = c[i] * 2^e / 20 end
      within(2, "metapost arclength at 2^" .. e, function() return arclen.metapost.arclength(s) end)
    end
  end)

  it("near-cusps at 1e-15 and exact cusps, every method, every tolerance", function()
    local cusp = {0, 0, 1, 1, 0, 1, 1, 0}         -- z'(1/2) = 0: a cusp
    local curves = {cusp}
    for _, eps in ipairs({1e-15, 1e-13, 1e-10}) do
      curves[#curves + 1] = {0, 0, 1, 1 + eps, 0, 1, 1, 0}
      curves[#curves + 1] = {0, 0, 1, 1, eps, 1, 1, 0}
    end
    for _, m in ipairs(arclen.methods()) do
      for j, c in ipairs(curves) do
        for _, tol in ipairs({1e-3, 1e-9, 1e-12, 1e-15}) do
          local gravesen = m:match("^gravesen")
          if not (gravesen and tol < 1e-12) then
            within(gravesen and 30 or 2, ("%s curve %d tol %g"):format(m, j, tol), function()
              return arclen.length(c, {method = m, tol = tol, steps = 1000})
            end)
          end
        end
      end
    end
    for j, c in ipairs(curves) do
      within(2, "time curve " .. j, function() return arclen.time(c, 0.5, {tol = 1e-15}) end)
    end
  end)

  H.c_only(it, "method 'gravesen'")("Gravesen at tol 1e-12 on a cusp", function()
    local c = {0, 0, 1, 1, 0, 1, 1, 0}
    within(60, "gravesen 1e-12 cusp", function()
      return arclen.length(c, {method = "gravesen", tol = 1e-12})
    end)
    within(60, "gravesen-richardson 1e-12 cusp", function()
      return arclen.length(c, {method = "gravesen-richardson", tol = 1e-12})
    end)
  end)

  H.c_only(it, "3D curves and fits")("inputs the fuzzers found (a bisection that never ended, the cubic's 2^60 pieces)", function()
    within(2, "3D cusp at t = 0 with a 1e-300 component", function()
      return arclen.length({0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1e-300, 0})
    end)
    within(2, "3D collinear reversal with a 1e-179 transverse part", function()
      return arclen.length({-1.7592415015251054e-179, -3.5184830030502108e-179,
        -5.2777245045753162e-179, -3.5184830030502108e-179, -3.5425822017012397e-179,
        5.2202435743988196e-54, -5.474095318583309e-180, -5.7150873050935975e-180,
        5.2202435743988196e-54, 0, 0, 0}, {tol = 1e-14})
    end)
    within(2, "fit of a subnormal segment", function()
      local u = 5e-324
      return arclen.fit({-8 * u, -16 * u, -24 * u, -32 * u, -40 * u, -48 * u, -56 * u, -64 * u},
                        {tol = 2^-9}):value(0.3)
    end)
  end)
end)
