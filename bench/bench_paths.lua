-- bench/bench_paths.lua -- `make bench-paths`: many points along paths in
-- one run.  Random paths of 10, 100 and 10 000 cubic segments (joined end
-- to start), k = 10 .. 10^5 points evenly spaced by length: p:resample(k),
-- p:points(distances) (flat arrays, with tangents), p:dash (k dashes), and
-- k sorted p:point(s) calls; each as microseconds per point and as the
-- ratio to one arclen.length(c) call measured in the same run, with its
-- growth (time per point as n and k grow: flat = linear in n + k).  Then
-- the worst error of resample's points against the tol-1e-15 answer, and
-- the peers' (bench/peers/paths/run.sh writes their points) against it.
-- Then the segment kinds: one segment_length per kind against one cubic's
-- length, and paths mixing lines, conic arcs and cubics (a third each)
-- beside the cubic-only paths of the same n: length (from scratch),
-- time, resample, dash, each in microseconds and in length calls.
--   make bench-paths          QUICK=1 for n <= 100, k <= 10^4
local arclen = require("arclen")
local path = arclen.path

local clock = os.clock
local QUICK = os.getenv("QUICK")
local PEERS = os.getenv("PEERS_OUT")        -- where the peers' runs go
local TOL = 1e-12

local seed = 20261201
local function uniform()
  seed = (seed * 48271) % 2147483647
  return seed / 2147483647
end

-- A random path: each segment from the last end, controls within 10.
local function random_segments(n)
  local segs, x, y = {}, 0, 0
  for k = 1, n do
    local c = {x, y}
    for q = 3, 8 do c[q] = (q % 2 == 1 and x or y) + 10 * uniform() - 5 end
    segs[k] = c
    x, y = c[7], c[8]
  end
  return segs
end

-- Seconds per run of f, the least over repeats of at least 0.05 s each.
local function timed(f)
  local best = math.huge
  for _ = 1, 3 do
    local reps, t0, t = 0, clock(), 0
    repeat
      f()
      reps = reps + 1
      t = clock() - t0
    until t >= 0.05
    if t / reps < best then best = t / reps end
  end
  return best
end

-- One arclen.length call, on the bench's segments (table form).
local len_segs = random_segments(1000)
local opts = {tol = TOL}
local t_len = timed(function()
  for k = 1, #len_segs do arclen.length(len_segs[k], opts) end
end) / #len_segs
print(("one arclen.length(c) call: %.3f us (tol %g, Lua %s)"):format(t_len * 1e6, TOL,
  _VERSION))

local NS = QUICK and {10, 100} or {10, 100, 10000}
local KS = QUICK and {10, 100, 1000, 10000} or {10, 100, 1000, 10000, 100000}

local function distances(L, k)
  local ds = {}
  for i = 0, k - 1 do ds[i + 1] = L * i / (k - 1) end
  return ds
end

print()
print("| n segments | k points | resample us/pt | ratio | points us/pt | ratio | dash us/dash | ratio | point(s) us/pt | ratio |")
print("|---|---|---|---|---|---|---|---|---|---|")
local per, per_pts = {}, {}
local paths = {}
for _, n in ipairs(NS) do
  local segs = random_segments(n)
  local p = path(segs, {tol = TOL})
  local L = p:length()                     -- the segments' lengths, cached
  paths[n] = {p = p, segs = segs, L = L}
  per[n], per_pts[n] = {}, {}
  for _, k in ipairs(KS) do
    local ds = distances(L, k)
    local t_res = timed(function() p:resample(k) end) / k
    local t_pts = timed(function() p:points(ds, {tangents = true}) end) / k
    local h = L / (2 * k)                  -- k dashes on, k gaps
    local t_dash = timed(function() p:dash({h, h}) end) / k
    local t_one = math.huge
    if k <= 1000 then
      t_one = timed(function()
        for i = 1, k do p:point(ds[i]) end
      end) / k
    end
    per[n][k] = t_res
    per_pts[n][k] = t_pts
    print(("| %d | %d | %.3f | %.2f | %.3f | %.2f | %.3f | %.2f | %s | %s |"):format(
      n, k, t_res * 1e6, t_res / t_len, t_pts * 1e6, t_pts / t_len, t_dash * 1e6,
      t_dash / t_len, t_one < math.huge and ("%.3f"):format(t_one * 1e6) or "-",
      t_one < math.huge and ("%.2f"):format(t_one / t_len) or "-"))
  end
end

-- The goal's figure, resample at n = 100, k = 1000 in length calls a point,
-- taken in turn with the length calls themselves: five rounds, each a
-- ratio of its own two timings (the one t_len above, taken once at the
-- start, moves the table's ratios by the machine's state then).
do
  local P, k, ratios = paths[100], 1000, {}
  for r = 1, 5 do
    local tl = timed(function()
      for q = 1, #len_segs do arclen.length(len_segs[q], opts) end
    end) / #len_segs
    local tr = timed(function() P.p:resample(k) end) / k
    ratios[r] = tr / tl
  end
  table.sort(ratios)
  print()
  print(("resample, n = 100, k = 1000, in turn with arclen.length: %.2f length calls a point "
    .. "(median of 5 rounds; %.2f-%.2f)"):format(ratios[3], ratios[1], ratios[5]))
end

-- The core's share at n = 100, k = 1000: arclen.times (times only, flat)
-- on each segment's run of the same distances, as the walk hands them
-- over -- the time finding that resample and points both pay, set-up a
-- segment included; what they cost beyond it is the binding's.
do
  local n, k = 100, 1000
  local P = paths[n]
  local cum = {[0] = 0}
  for i = 1, n do cum[i] = cum[i - 1] + arclen.length(P.segs[i], opts) end
  local ds, runs, j = distances(P.L, k), {}, 1
  for seg = 1, n do
    local r = {}
    while j <= k and (seg == n or ds[j] < cum[seg]) do
      local s = ds[j] - cum[seg - 1]
      r[#r + 1] = s < 0 and 0 or s
      j = j + 1
    end
    runs[seg] = r
  end
  local t_times = timed(function()
    for seg = 1, n do
      if #runs[seg] > 0 then arclen.times(P.segs[seg], runs[seg], opts) end
    end
  end) / k
  -- and what a 6-field table costs by itself, made k at a time in Lua
  -- (the C API's createtable and rawsets cost the same within noise)
  local t_tab = timed(function()
    local out = {}
    for i = 1, k do
      local v = i + 0.5
      out[i] = {x = v, y = v, s = v, time = v, tx = v, ty = v}
    end
  end) / k
  print()
  print(("the core's share, n = %d, k = %d: arclen.times on each segment's run %.3f us/pt (%.2f length calls); "
    .. "resample %.2f and points %.2f length calls beyond it"):format(n, k, t_times * 1e6, t_times / t_len,
    (per[n][k] - t_times) / t_len, (per_pts[n][k] - t_times) / t_len))
  print(("a 6-field table, %d made in a Lua loop: %.3f us each (%.2f length calls): resample's floor is about "
    .. "%.2f length calls a point"):format(k, t_tab * 1e6, t_tab / t_len, (per_pts[n][k] + t_tab) / t_len))
end

-- Growth: resample's time per point against n = 10 at the largest k.
print()
print("resample, time per point relative to n = " .. NS[1] .. ", k = " .. KS[#KS] ..
  " (rows: n; columns: k = " .. table.concat(KS, ", ") .. "):")
for _, n in ipairs(NS) do
  local row = {}
  for _, k in ipairs(KS) do row[#row + 1] = ("%.2f"):format(per[n][k] / per[NS[1]][KS[#KS]]) end
  print(("  n = %5d: %s"):format(n, table.concat(row, "  ")))
end
print("  (constant = linear in n + k; small k pays each segment's set-up and the walk, ~n/k)")

-- Accuracy: resample at tol 1e-12 against the tol-1e-15 answer.
print()
local function worst_error(n, k, pts)
  local P = paths[n]
  local ref = path(P.segs, {tol = 1e-15}):points(distances(P.L, k))
  local w = 0
  for i = 1, k do
    local e = math.sqrt((pts[2 * i - 1] - ref[2 * i - 1]) ^ 2 + (pts[2 * i] - ref[2 * i]) ^ 2)
    if e > w then w = e end
  end
  return w / P.L
end
for _, n in ipairs(NS) do
  local P = paths[n]
  local k = 1000
  local pts = P.p:points(distances(P.L, k))
  print(("arclen (tol %g) on n = %d, k = %d: worst |point - tol-1e-15 point| / L = %.2g"):format(
    TOL, n, k, worst_error(n, k, pts)))
end

-- The peers: the n = 100 path as SVG path data, k = 1000 distances.
if PEERS then
  local P = paths[100]
  local f = assert(io.open(PEERS .. "/path.txt", "w"))
  local d = {("M%.17g %.17g"):format(P.segs[1][1], P.segs[1][2])}
  for _, c in ipairs(P.segs) do
    d[#d + 1] = ("C%.17g %.17g %.17g %.17g %.17g %.17g"):format(c[3], c[4], c[5], c[6], c[7], c[8])
  end
  f:write(table.concat(d, " "), "\n", ("%.17g"):format(P.L), "\n1000\n")
  f:close()
  local ok = os.execute("sh bench/peers/paths/run.sh " .. PEERS)
  print()
  for line in io.lines(PEERS .. "/results.txt") do
    local name, ns = line:match("^(%S+)%s+(%S+)")
    if name and tonumber(ns) then
      local pts = {}
      for v in io.lines(PEERS .. "/" .. name .. ".pts") do
        for x in v:gmatch("%S+") do pts[#pts + 1] = tonumber(x) end
      end
      print(("%s on n = 100, k = 1000: %.3f us per point (%.2f length calls), worst error %.2g L"):format(
        name, tonumber(ns) / 1e3, tonumber(ns) * 1e-9 / t_len, worst_error(100, 1000, pts)))
    else
      print(line)
    end
  end
  local pts = P.p:points(distances(P.L, 1000))
  print(("arclen p:resample on n = 100, k = 1000: %.3f us per point (%.2f length calls), worst error %.2g L"):format(
    per[100][1000] * 1e6, per[100][1000] / t_len, worst_error(100, 1000, pts)))
  if ok == false then print("(peers' run.sh failed)") end
end

-- ---- segments of four kinds ----------------------------------------------

-- One segment's length by kind, against one cubic's (arclen.length).
print()
print(("one segment's length by kind (%s engine, tol %g):"):format(arclen.engine or "?", TOL))
print("| kind | us | length calls |")
print("|---|---|---|")
do
  local kinds = {
    {"line", function(c) return {c[1], c[2], c[7], c[8]} end},
    {"quad", function(c) return {c[1], c[2], c[3], c[4], c[7], c[8]} end},
    {"conic (w = 0.7)", function(c) return {c[1], c[2], c[3], c[4], c[7], c[8], 0.7} end, "conic"},
    {"conic (circle)", function(c)
      local r = math.sqrt((c[7] - c[1]) ^ 2 + (c[8] - c[2]) ^ 2) / 2
      return {c[1], c[2], c[1] + r, c[2], c[1] + r, c[2] + r, math.sqrt(0.5)}
    end, "conic"},
    {"cubic", function(c) return c end},
  }
  for _, kd in ipairs(kinds) do
    local name, make, kind = kd[1], kd[2], kd[3] or kd[1]
    local segs = {}
    for i = 1, #len_segs do segs[i] = make(len_segs[i]) end
    local t = timed(function()
      for i = 1, #segs do arclen.segment_length(kind, segs[i], opts) end
    end) / #segs
    print(("| %s | %.3f | %.2f |"):format(name, t * 1e6, t / t_len))
  end
end

-- A random path of n segments: a third lines, a third conic arcs (circle
-- arcs and ellipse arcs up to 120 degrees: w = cos(half the span), the
-- middle point off the chord), a third cubics, joined end to start.
local function mixed_segments(n)
  local segs, x, y = {}, 0, 0
  for k = 1, n do
    local c
    local pick = k % 3
    if pick == 1 then
      c = {kind = "line", x, y, x + 10 * uniform() - 5, y + 10 * uniform() - 5}
      x, y = c[3], c[4]
    elseif pick == 2 then
      local half = (0.1 + 0.9 * uniform()) * math.pi / 3
      local x2, y2 = x + 10 * uniform() - 5, y + 10 * uniform() - 5
      local mx, my = (x + x2) / 2, (y + y2) / 2
      local h = math.tan(half) * math.sqrt((x2 - x) ^ 2 + (y2 - y) ^ 2) / 2
      local nx, ny = -(y2 - y), x2 - x
      local nl = math.sqrt(nx * nx + ny * ny)
      local squash = uniform() < 0.5 and 1 or 0.3   -- a circle arc, or an ellipse's
      c = {kind = "conic", x, y, mx + squash * h * nx / nl, my + squash * h * ny / nl, x2, y2,
           math.cos(half)}
      x, y = x2, y2
    else
      c = {x, y}
      for q = 3, 8 do c[q] = (q % 2 == 1 and x or y) + 10 * uniform() - 5 end
      x, y = c[7], c[8]
    end
    segs[k] = c
  end
  return segs
end

print()
print(("paths of n segments, k = 1000 points: cubics only, and mixed (a third lines, conic arcs, "
  .. "cubics); us per call or per point, and length calls (%s engine)"):format(arclen.engine or "?"))
print("| n | path | length us | ratio/seg | time us/call | ratio | resample us/pt | ratio | dash us/dash | ratio |")
print("|---|---|---|---|---|---|---|---|---|---|")
for _, n in ipairs(NS) do
  for _, which in ipairs({"cubic", "mixed"}) do
    local segs = which == "cubic" and random_segments(n) or mixed_segments(n)
    local p = path(segs, {tol = TOL})
    local t_length = timed(function()
      p.cum = nil                      -- from scratch: every segment measured again
      p:length()
    end)
    local L = p:length()
    local k = 1000
    local ds = distances(L, k)
    local m = math.min(k, 200)
    local t_time = timed(function()
      for i = 1, m do p:time(ds[math.floor((i - 1) * k / m) + 1]) end
    end) / m
    local t_res = timed(function() p:resample(k) end) / k
    local h = L / (2 * k)
    local t_dash = timed(function() p:dash({h, h}) end) / k
    print(("| %d | %s | %.1f | %.2f | %.3f | %.2f | %.3f | %.2f | %.3f | %.2f |"):format(
      n, which, t_length * 1e6, t_length / n / t_len, t_time * 1e6, t_time / t_len,
      t_res * 1e6, t_res / t_len, t_dash * 1e6, t_dash / t_len))
  end
end
