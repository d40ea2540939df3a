-- bench/bench_engines.lua -- the Lua engine (arclen.pure) against the C
-- core (arclen.core) on the same curves and paths, as ratios within one
-- run: length and time of single cubics, resample of whole paths, and the
-- speed evaluations each engine spends on a length.
--   LUA_PATH='lua/?.lua;lua/?/init.lua;;' LUA_CPATH='build/5.3/?.so;;' \
--     lua5.3 bench/bench_engines.lua        (make bench-engines: 5.3 and LuaJIT)
-- Each measurement alternates the engines over 5 rounds and keeps the
-- median time per call; the curves are random cubics with points in the
-- unit square (Park-Miller's generator, the same under every Lua).
local core = require("arclen.core")
local pure = require("arclen.pure")

-- arclen.path on a given engine (as spec/engines_diff_spec.lua loads it).
local function path_on(engine)
  local saved = {}
  for _, n in ipairs({"arclen.engine", "arclen.path", "arclen.svgpath"}) do saved[n] = package.loaded[n] end
  package.loaded["arclen.engine"] = engine
  package.loaded["arclen.path"], package.loaded["arclen.svgpath"] = nil, nil
  local mod = require("arclen.path")
  for n, m in pairs(saved) do package.loaded[n] = m end
  return mod
end

local seed = 20261203
local function rnd()
  seed = (16807 * seed) % 2147483647
  return seed / 2147483647
end

local N = 2000
local cubics = {}
for i = 1, N do
  local c = {}
  for k = 1, 8 do c[k] = rnd() end
  cubics[i] = c
end
local paths = {}                     -- 50 paths of 20 joined cubics
for i = 1, 50 do
  local segs, x, y = {}, rnd(), rnd()
  for k = 1, 20 do
    local c = {x, y}
    for q = 3, 8 do c[q] = rnd() end
    segs[k], x, y = c, c[7], c[8]
  end
  paths[i] = segs
end
local halves = {}
for i = 1, N do halves[i] = core.length(cubics[i]) / 2 end

local function median(t)
  table.sort(t)
  return t[math.floor((#t + 1) / 2)]
end

-- Seconds per call of f(i) for i = 1..n, the median of 5 rounds of each
-- engine in turn.
local function timed(fs, n)
  local times = {}
  for e = 1, #fs do times[e] = {} end
  for _ = 1, 5 do
    for e, f in ipairs(fs) do
      local t0 = os.clock()
      for i = 1, n do f(i) end
      times[e][#times[e] + 1] = (os.clock() - t0) / n
    end
  end
  local out = {}
  for e = 1, #fs do out[e] = median(times[e]) end
  return out
end

local Pc, Pl = path_on(core), path_on(pure)
local rows = {}
local function row(name, fc, fl, n, unit)
  local t = timed({fc, fl}, n)
  rows[#rows + 1] = ("%-28s %10.2f %10.2f %8.1f"):format(name, t[1] * unit, t[2] * unit, t[2] / t[1])
end

for _, tol in ipairs({1e-12, 1e-9}) do
  local o = {tol = tol}
  row(("length, tol %g (us)"):format(tol),
      function(i) core.length(cubics[i], o) end,
      function(i) pure.length(cubics[i], o) end, N, 1e6)
  row(("time at L/2, tol %g (us)"):format(tol),
      function(i) core.time(cubics[i], halves[i], o) end,
      function(i) pure.time(cubics[i], halves[i], o) end, N, 1e6)
  row(("resample 100, 20 cubics (ms)"):format(),
      function(i) Pc(paths[i], o):resample(100) end,
      function(i) Pl(paths[i], o):resample(100) end, #paths, 1e3)
end

local ec, el = 0, 0
for i = 1, N do
  local _, ic = core.length(cubics[i], {info = true})
  local _, il = pure.length(cubics[i], {info = true})
  ec, el = ec + ic.evals, el + il.evals
end

print(("arclen engines, %s: %d random cubics, %d paths of 20"):format(_VERSION ..
  (jit and (" (" .. jit.version .. ")") or ""), N, #paths))
print(("%-28s %10s %10s %8s"):format("", "C core", "Lua", "Lua/C"))
for _, r in ipairs(rows) do print(r) end
print(("%-28s %10.1f %10.1f %8.2f"):format("speed evaluations a length", ec / N, el / N, el / ec))
