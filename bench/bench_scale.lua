-- bench/bench_scale.lua -- the length of 10^6 cubics through the Lua API:
-- arclen.lengths on one flat array (the batch entry point) against one
-- arclen.length call per curve (8 numbers as arguments, the fastest
-- per-call form) and per curve with a table (the common form).  Reports
-- curves per second, the ratio batch / per-call, and peak memory (VmHWM).
--   make bench-scale            (N=1000000 by default; with the C loop)
--   N=100000 lua5.4 bench/bench_scale.lua
local arclen = require("arclen")

local N = tonumber(os.getenv("N")) or 1000000
local TOL = 1e-12

local function vm(key)          -- kB from /proc/self/status, or nil
  local f = io.open("/proc/self/status")
  if not f then return nil end
  for line in f:lines() do
    local v = line:match("^" .. key .. ":%s+(%d+)")
    if v then f:close(); return tonumber(v) end
  end
  f:close()
end

-- The same curves as bench/bench_util.h's generator would be ideal; a
-- seeded LCG in Lua gives a reproducible set without 64-bit tricks:
-- control points uniform in [0, 10)^2 (Park-Miller minimal standard).
local seed = 20261121 % 2147483647
local function uniform()
  seed = (seed * 48271) % 2147483647
  return seed / 2147483647
end

local rss0 = vm("VmRSS")
local coords = {}
for i = 1, 8 * N do coords[i] = 10 * uniform() end
collectgarbage()
local rss_data = vm("VmRSS")

local clock = os.clock
-- per call, 8 numbers as arguments
local t0 = clock()
local per = {}
local length = arclen.length
local opts = {tol = TOL}
for k = 0, N - 1 do
  local b = 8 * k
  per[k + 1] = length(coords[b + 1], coords[b + 2], coords[b + 3], coords[b + 4],
                      coords[b + 5], coords[b + 6], coords[b + 7], coords[b + 8], opts)
end
local t_call = clock() - t0

-- per call, a table per curve
t0 = clock()
local sum_tab = 0
for k = 0, N - 1 do
  local b = 8 * k
  sum_tab = sum_tab + length({coords[b + 1], coords[b + 2], coords[b + 3], coords[b + 4],
                              coords[b + 5], coords[b + 6], coords[b + 7], coords[b + 8]}, opts)
end
local t_tab = clock() - t0
per = nil
collectgarbage()

-- batch, in turn with the C loop over the same curves (bench_scale_c.c,
-- when C_LOOP names it): three rounds, the least of each
local C_LOOP = os.getenv("C_LOOP")
local batch, t_batch, c_ns, ratios = nil, math.huge, {}, {}
for round = 1, 3 do
  if C_LOOP then
    local f = io.popen(C_LOOP .. " " .. N)
    local out = f and f:read("*a") or ""
    if f then f:close() end
    c_ns[round] = tonumber(out:match("(%d+) ns/curve"))
  end
  collectgarbage()
  t0 = clock()
  batch = arclen.lengths(coords, opts)
  local t = clock() - t0
  if t < t_batch then t_batch = t end
  if c_ns[round] then ratios[round] = t / N * 1e9 / c_ns[round] end
end

-- the results agree exactly (same method, same options)
local sum, worst = 0, 0
for k = 1, N do sum = sum + batch[k] end
for k = 0, 99 do
  local i = 1 + (k * 9973) % N
  local b = 8 * (i - 1)
  local l = length(coords[b + 1], coords[b + 2], coords[b + 3], coords[b + 4],
                   coords[b + 5], coords[b + 6], coords[b + 7], coords[b + 8], opts)
  worst = math.max(worst, math.abs(l - batch[i]))
end
local hwm = vm("VmHWM")

local function row(what, t)
  print(("%-40s %9.3f s %12.0f curves/s %8.0f ns/curve"):format(what, t, N / t, t / N * 1e9))
end
print(("%d random cubics in [0,10)^2, tol %g, %s, %s"):format(N, TOL, _VERSION, arclen._VERSION))
row("arclen.length, 8 numbers per call", t_call)
row("arclen.length, a table per call", t_tab)
row("arclen.lengths (batch, one flat array)", t_batch)
print(("batch / per-call time: %.3f (8 numbers), %.3f (table)"):format(t_batch / t_call, t_batch / t_tab))
if #ratios > 0 then
  table.sort(ratios)
  local lo, hi = math.huge, 0
  for _, v in ipairs(c_ns) do lo, hi = math.min(lo, v), math.max(hi, v) end
  print(("C loop (arclen_length over the same array, CPU time): %.0f-%.0f ns/curve; " ..
    "arclen.lengths / C loop, in turn: %s"):format(lo, hi,
    table.concat((function() local t = {} for i, r in ipairs(ratios) do t[i] = ("%.2f"):format(r) end return t end)(), ", ")))
end
print(("batch equals per-call: max |difference| %g on 100 samples; sum of lengths %.10g (tables: %.10g)")
  :format(worst, sum, sum_tab))
if hwm then
  print(("memory: VmHWM %.1f MB (interpreter %.1f MB, flat array of %d numbers %.1f MB)")
    :format(hwm / 1024, (rss0 or 0) / 1024, 8 * N, ((rss_data or 0) - (rss0 or 0)) / 1024))
end
