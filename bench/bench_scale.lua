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
-- when C_LOOP names it: one pass of arclen_length per curve, as
-- arclen.lengths calls it) and with the floor (bench_scale_floor.c, when
-- FLOOR names it: the binding measuring no length).  Five rounds, one run
-- of each a round, the order turning; ratios within a round.
local C_LOOP, FLOOR = os.getenv("C_LOOP"), os.getenv("FLOOR")
local floor_lengths
if FLOOR then
  local open = assert(package.loadlib(FLOOR, "luaopen_bench_scale_floor"))
  floor_lengths = open().lengths
end
local ROUNDS = 5
local batch, t_batch = nil, math.huge
local c_ns, b_ns, f_ns, ratios, fratios = {}, {}, {}, {}, {}
local function run_c(round)
  if not C_LOOP then return end
  local f = io.popen(C_LOOP .. " " .. N .. " 1")
  local out = f and f:read("*a") or ""
  if f then f:close() end
  c_ns[round] = tonumber(out:match("(%d+) ns/curve"))
end
local function run_batch(round)
  collectgarbage()
  t0 = clock()
  batch = arclen.lengths(coords, opts)
  local t = clock() - t0
  if t < t_batch then t_batch = t end
  b_ns[round] = t / N * 1e9
end
local function run_floor(round)
  if not floor_lengths then return end
  collectgarbage()
  t0 = clock()
  local r = floor_lengths(coords, opts)
  f_ns[round] = (clock() - t0) / N * 1e9
  assert(#r == N)
end
-- batch on the same curves packed in one string of doubles (Lua 5.3+:
-- string.pack), as paths read from path data keep them: no Lua call a
-- number
local packed, p_ns, pratios, pbatch = nil, {}, {}, nil
if string.pack then
  local parts, fmt8 = {}, ("d"):rep(8)
  for k = 0, N - 1 do
    local b = 8 * k
    parts[k + 1] = string.pack(fmt8, coords[b + 1], coords[b + 2], coords[b + 3], coords[b + 4],
                               coords[b + 5], coords[b + 6], coords[b + 7], coords[b + 8])
  end
  packed = table.concat(parts)
  parts = nil
end
local function run_packed(round)
  if not packed then return end
  collectgarbage()
  t0 = clock()
  pbatch = arclen.lengths(packed, opts)
  p_ns[round] = (clock() - t0) / N * 1e9
end
local steps = {run_c, run_batch, run_floor, run_packed}
for round = 1, ROUNDS do
  for s = 0, 3 do steps[(s + round) % 4 + 1](round) end
  if c_ns[round] then
    ratios[round] = b_ns[round] / c_ns[round]
    if f_ns[round] then fratios[round] = (c_ns[round] + f_ns[round]) / c_ns[round] end
    if p_ns[round] then pratios[round] = p_ns[round] / c_ns[round] end
  end
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
local function fmt(t)
  local r = {}
  for i, v in ipairs(t) do r[i] = ("%.2f"):format(v) end
  return table.concat(r, ", ")
end
local function median(t)
  local c = {}
  for i, v in ipairs(t) do c[i] = v end
  table.sort(c)
  return c[math.floor((#c + 1) / 2)]
end
if #ratios > 0 then
  print(("C loop (arclen_length over the same array, CPU time, one pass a round): %.0f ns/curve (median)"):format(
    median(c_ns)))
  print(("arclen.lengths / C loop, round by round: %s; median %.2f"):format(fmt(ratios), median(ratios)))
end
if #pratios > 0 then
  print(("arclen.lengths on a packed string / C loop, round by round: %s; median %.2f"):format(
    fmt(pratios), median(pratios)))
end
if pbatch then
  local same = #pbatch == N
  for k = 1, N do if pbatch[k] ~= batch[k] then same = false break end end
  print(("packed equals flat: %s (all %d lengths)"):format(same and "yes" or "NO", N))
end
if #f_ns > 0 then
  print(("floor (the binding measuring no length: reading, checks, result): %.0f ns/curve (median)"):format(
    median(f_ns)))
  if #fratios > 0 then
    print(("(C loop + floor) / C loop, round by round: %s; median %.2f -- the least ratio the public API allows"):format(
      fmt(fratios), median(fratios)))
  end
end
print(("batch equals per-call: max |difference| %g on 100 samples; sum of lengths %.10g (tables: %.10g)")
  :format(worst, sum, sum_tab))
if hwm then
  print(("memory: VmHWM %.1f MB (interpreter %.1f MB, flat array of %d numbers %.1f MB)")
    :format(hwm / 1024, (rss0 or 0) / 1024, 8 * N, ((rss_data or 0) - (rss0 or 0)) / 1024))
end
