-- tools/check-luatex.lua -- check what the LuaTeX example documents wrote
-- (tools/check-luatex.sh runs them first), against arclen computed here,
-- in a separate run, and against MetaPost's own arclength/arctime.
--   texlua tools/check-luatex.lua BUILD DATAFILE...
-- Data lines (see examples/luamplib_arclen.tex): PATH name knots; LEN, TIME,
-- POINT, MPLEN, MPTIME; POINTS/PT; DASHPATH/DASHED/DASH; SUB; GLYPH/PLACED;
-- and ERR/VAL lines of the bad-input document.  Ends "N passed, N failed".
local build = assert(arg[1], "usage: texlua tools/check-luatex.lua BUILD DATA...")
local setup = dofile("lua/arclen/luatex.lua")
local arclen = setup(".", build)
local apath = require("arclen.path")

local TOL = 1e-12              -- the documents' tolerance (arclen_tol 0)
-- Where two sides evaluate a point differently (MetaPost's point t of p
-- against arclen's, luamplib's box transform), the bound adds rounding: a
-- few ulps (16 EPS, 64 EPS through a transform) of the coordinates' size.
local EPS = 2 ^ -52
local abs, sqrt, max, floor = math.abs, math.sqrt, math.max, math.floor
local atan2 = math.atan2 or math.atan
local passed, failed = 0, 0

local function check(name, ok, detail)
  if ok then passed = passed + 1 else failed = failed + 1 end
  print(("%-4s %s%s"):format(ok and "ok" or "FAIL", name, detail and ("  " .. detail) or ""))
end

-- ---- read the data -----------------------------------------------------

local lines = {}
for i = 2, #arg do
  local f = io.open(arg[i])
  if not f then check("data file " .. arg[i] .. " exists", false)
  else
    for l in f:lines() do lines[#lines + 1] = l end
    f:close()
  end
end

local function words(l)
  local w = {}
  for x in l:gmatch("%S+") do w[#w + 1] = x end
  return w
end

-- The knots' text as arclen_knots_ writes it, as an arclen path.
local function path_of(kind, knots, opts)
  local t = {cycle = kind == "c"}
  for _, k in ipairs(knots) do
    local v = {}
    for x in k:gmatch("[^,]+") do v[#v + 1] = assert(tonumber(x), x) end
    t[#t + 1] = {x_coord = v[1], y_coord = v[2], left_x = v[3], left_y = v[4],
      right_x = v[5], right_y = v[6]}
  end
  return apath.mplib(t, opts), t
end

local paths, scale = {}, {}
local function def_path(name, w, from)
  local knots = {}
  for i = from + 1, #w do knots[#knots + 1] = w[i] end
  paths[name] = {
    p = path_of(w[from], knots, {tol = TOL}),
    ref = path_of(w[from], knots, {tol = 1e-15}),
    mp = path_of(w[from], knots, {method = "metapost"})}
  local c = 0
  for _, k in ipairs(knots) do
    for x in k:gmatch("[^,]+") do c = max(c, abs(tonumber(x))) end
  end
  scale[name] = c
  return paths[name]
end

-- The distance along p (at tol 1e-15) of path time T (wrapping on a cycle).
local function dist_at(P, T)
  local p, n = P.ref, P.ref:segments()
  local L = p:length()
  local turns = 0
  if p.cyclic then turns = floor(T / n); T = T - turns * n end
  local k = floor(T)
  local d = 0
  for j = 1, k do d = d + arclen.length(p:segment(j), {tol = 1e-15}) end
  if k < n and T > k then
    d = d + arclen.length(p:segment(k + 1), {tol = 1e-15, t0 = 0, t1 = T - k})
  end
  return turns * L + d
end

-- The unit derivative of p at path time T (the direction MetaPost takes).
local function dir_at(p, T)
  local n = p:segments()
  if p.cyclic then T = T - floor(T / n) * n end
  local k = floor(T)
  if k >= n then k, T = n - 1, n end
  local dx, dy = arclen.derivative(p:segment(k + 1), T - k)
  local l = sqrt(dx * dx + dy * dy)
  return dx / l, dy / l
end

-- ---- the checks ---------------------------------------------------------

local mp_len_err, mp_len_rel, mp_time_err = 0, 0, 0
local times = {}                       -- name -> s -> the document's time
local glyphs, placed = {}, {}
local dashpath, dashspec, dashes = nil, nil, {}
local npoints, pts = {}, {}
local vals = {}
local svg, mpversion

for _, l in ipairs(lines) do repeat
  local w = words(l)
  local tag, name = w[1], w[2]
  local P = paths[name]
  if tag == "PATH" then
    def_path(name, w, 3)
  elseif tag == "LEN" then
    local L, mpL = tonumber(w[3]), tonumber(w[4])
    local ref = P.ref:length()
    check(("%s: arclen_length is arclen's length, digit for digit"):format(name),
      L == P.p:length(), ("%.17g"):format(L))
    check(("%s: within tol of the length (tol 1e-15 reference)"):format(name),
      abs(L - ref) <= TOL * ref, ("error %.2g"):format(L - ref))
    mp_len_err = max(mp_len_err, abs(mpL - ref))
    mp_len_rel = max(mp_len_rel, abs(mpL - ref) / ref)
    print(("     MetaPost's arclength of %s: %.17g, error %.3g (relative %.2g)"):format(
      name, mpL, mpL - ref, (mpL - ref) / ref))
  elseif tag == "TIME" then
    local s, T, mpT = tonumber(w[3]), tonumber(w[4]), tonumber(w[5])
    times[name] = times[name] or {}
    times[name][s] = T
    check(("%s: arclen_time at %s is arclen's p:time"):format(name, w[3]),
      T == P.p:time(s), ("%.17g"):format(T))
    local L, n = P.ref:length(), P.ref:segments()
    local want = s
    if not P.ref.cyclic then want = s < 0 and 0 or (s > L and L or s) end
    local e = dist_at(P, T) - want
    check(("%s: the time at %s is within tol * L of the length"):format(name, w[3]),
      abs(e) <= TOL * L + 16 * EPS * max(L, abs(s)), ("distance error %.2g"):format(e))
    local me = dist_at(P, mpT) - want
    if P.ref.cyclic and abs(s) > L then
      -- MetaPost before 2.11 wraps a length past one turn of a cycle to a
      -- wrong time (n * (s/L - 1) and the like); 2.11 and arclen: n * turns
      -- + the time of the rest
      print(("     MetaPost %s: arctime %s of %s is %.17g, %.4g from the length%s"):format(
        mpversion or "?", w[3], name, mpT, me, abs(me) > 1 and " (its wrapping bug)" or ""))
      break      -- out of the repeat: the next line
    end
    mp_time_err = max(mp_time_err, abs(me))
    -- MetaPost's bisection: 1/4096 absolute plus 2^-17 a segment (and the
    -- turns of a cycle); a different wrapping rule would be off by ~L
    local turns = P.ref.cyclic and abs(floor(s / L)) + 1 or 1
    check(("%s: MetaPost's arctime %s follows the same convention"):format(name, w[3]),
      abs(me) <= turns * (n * 2 ^ -17 + 1 / 4096), ("arctime %.17g, its distance error %.3g"):format(mpT, me))
  elseif tag == "POINT" then
    local s, x, y, dx, dy = tonumber(w[3]), tonumber(w[4]), tonumber(w[5]), tonumber(w[6]), tonumber(w[7])
    local L = P.ref:length()
    local rx, ry = P.ref:point(s)
    local e = sqrt((x - rx) ^ 2 + (y - ry) ^ 2)
    check(("%s: arclen_point at %s within tol * L"):format(name, w[3]),
      e <= TOL * L + 16 * EPS * scale[name], ("off by %.2g"):format(e))
    local tx, ty = dir_at(P.p, times[name][s])
    local de = sqrt((dx - tx) ^ 2 + (dy - ty) ^ 2)
    check(("%s: arclen_direction at %s is the unit tangent there"):format(name, w[3]),
      de <= 16 * EPS, ("off by %.2g"):format(de))
  elseif tag == "MPLEN" then
    check(("%s: method 'metapost' gives MetaPost's arclength bit for bit"):format(name),
      tonumber(w[3]) == tonumber(w[4]), w[3] .. " vs " .. w[4])
    check(("%s: ... and arclen.metapost agrees"):format(name),
      tonumber(w[3]) == P.mp:length())
  elseif tag == "MPTIME" then
    local s, L = tonumber(w[3]), P.ref:length()
    if P.ref.cyclic and abs(s) > L then
      check(("%s: method 'metapost' past one turn (%s) follows MetaPost 2.11"):format(name, w[3]),
        tonumber(w[4]) == arclen.metapost.path_arctime(P.p.segs, s, true),
        ("arclen %s, this MetaPost (%s) %s"):format(w[4], mpversion or "?", w[5]))
    else
      check(("%s: method 'metapost' gives MetaPost's arctime %s bit for bit"):format(name, w[3]),
        tonumber(w[4]) == tonumber(w[5]), w[4] .. " vs " .. w[5])
    end
  elseif tag == "MPVERSION" then
    mpversion = w[2]
  elseif tag == "POINTS" then
    npoints[name] = tonumber(w[3]); pts[name] = {}
  elseif tag == "PT" then
    pts[name][#pts[name] + 1] = {tonumber(w[4]), tonumber(w[5])}
  elseif tag == "DASHPATH" then
    dashpath = def_path(name, w, 3)
  elseif tag == "DASHED" then
    dashspec = {offset = tonumber(w[3])}
    for i = 4, #w do dashspec[#dashspec + 1] = tonumber(w[i]) end
  elseif tag == "DASH" then
    dashes[#dashes + 1] = {tonumber(w[3]), tonumber(w[4]), tonumber(w[5]), tonumber(w[6]), tonumber(w[7])}
  elseif tag == "SUB" then
    local p = path_of(w[3], {table.unpack(w, 4, #w - 4)}, {tol = 1e-15})
    local L = p:length()
    local x0, y0 = p:point(40)
    local x1, y1 = p:point(160)
    local e = max(sqrt((tonumber(w[#w - 3]) - x0) ^ 2 + (tonumber(w[#w - 2]) - y0) ^ 2),
                  sqrt((tonumber(w[#w - 1]) - x1) ^ 2 + (tonumber(w[#w]) - y1) ^ 2))
    check("arclen_subpath(p, 40, 160) ends at the points at lengths 40 and 160",
      e <= TOL * L + 16 * EPS * 400, ("off by %.2g"):format(e))
  elseif tag == "GLYPH" then
    glyphs[name] = glyphs[name] or {}
    local v = {}
    for i = 3, 8 do v[#v + 1] = tonumber(w[i]) end
    table.insert(glyphs[name], v)
  elseif tag == "PLACED" then
    placed[name] = placed[name] or {}
    table.insert(placed[name], {i = tonumber(w[3]), s = tonumber(w[4]),
      w = tonumber(w[5]), h = tonumber(w[6]), d = tonumber(w[7])})
  elseif tag == "SVGLEN" then
    svg = {L = tonumber(w[2]), d = l:match("^SVGLEN %S+ (.*)$"), glyphs = {}}
  elseif tag == "SVGGLYPH" then
    table.insert(svg.glyphs, {tonumber(w[2]), tonumber(w[3]), tonumber(w[4]), tonumber(w[5]), tonumber(w[6])})
  elseif tag == "VAL" then
    vals[name] = {table.unpack(w, 3)}
  end
until true end

-- Evenly spaced points: arclen's resample, to tol.
for name, n in pairs(npoints) do
  local P = paths[name:match("^%a+")]
  local p = P.ref
  local shifted = {}
  local q = p:resample(n)
  local worst = 0
  for i, z in ipairs(pts[name]) do
    -- the document's points are on the path shifted by (0,-70)
    worst = max(worst, sqrt((z[1] - q[i].x) ^ 2 + (z[2] + 70 - q[i].y) ^ 2))
  end
  check(("%s: %d points evenly spaced by length, to tol * L"):format(name, n),
    #pts[name] == n and worst <= TOL * p:length() + 16 * EPS * 400,
    ("%d points, worst %.2g"):format(#pts[name], worst))
end

-- Dashes: the same dashes as arclen's p:dash (SVG dasharray), each on-length
-- exact (even dashes), MetaPost's arclength of each within its error.
if dashpath then
  local ref = dashpath.ref:dash({table.unpack(dashspec)}, dashspec.offset)
  check("arclen_dashed: as many dashes as arclen's p:dash", #ref == #dashes,
    ("%d dashes, p:dash %d"):format(#dashes, #ref))
  local worst, worstlen, mpworst = 0, 0, 0
  local L = dashpath.ref:length()
  for i = 1, math.min(#ref, #dashes) do
    local r = ref[i]
    local x0, y0 = r:point(0)
    local x1, y1 = r:point(r:length())
    local d = dashes[i]
    worst = max(worst, sqrt((d[1] - x0) ^ 2 + (d[2] - y0) ^ 2), sqrt((d[3] - x1) ^ 2 + (d[4] - y1) ^ 2))
    if i > 1 and i < #ref then
      local want = (i % 2 == 0) and 2 or 12    -- offset 3 into 12,4,2,4: 9, then 2, 12, ...
      worstlen = max(worstlen, abs(r:length() - want))
      mpworst = max(mpworst, abs(d[5] - want))
    end
  end
  check("arclen_dashed: dash ends at arclen's distances, to tol * L",
    worst <= TOL * L + 16 * EPS * 400, ("worst %.2g"):format(worst))
  check("arclen_dashed: inner dashes are 12 and 2 long, to tol * L (even dashes)",
    worstlen <= TOL * L, ("worst %.2g"):format(worstlen))
  print(("     MetaPost's arclength of the dashes: worst error %.3g"):format(mpworst))
end

-- Glyphs: each text box's baseline centre on the path at its length, its
-- baseline along the tangent there; the alignment's ends where it says.
local ALIGN = {wave = {"wave", "centre", 0}, circle = {"circle", "fit", 0},
  start = {"s", "start", 10}, centre = {"s45", "centre", 0},
  plainmp = {"plainmp", "start", 5},
  ["end"] = {"s90", "end", 10}, fit = {"s135", "fit", 0}}
for name, a in pairs(ALIGN) do
  local G, Q, P = glyphs[name] or {}, placed[name] or {}, paths[a[1]]
  check(("text %s: glyphs placed and recorded"):format(name), #G > 0 and #G == #Q,
    ("%d boxes, %d records"):format(#G, #Q))
  if P and #G > 0 and #G == #Q then
    local p, L = P.ref, P.ref:length()
    local worst, worstang, worstw, wmin = 0, 0, 0, math.huge
    for i, g in ipairs(G) do
      if Q[i].w > 0 then wmin = math.min(wmin, Q[i].w) end
      local q = Q[i]
      local ux, uy = g[5] - g[1], g[6] - g[2]          -- up the box
      local ul = sqrt(ux * ux + uy * uy)
      -- luamplib writes a box's sizes with %f (textext): its depth and width
      -- are those rounded to 1e-6; the glyph's centre is w/2 from the left
      local d6, w6 = tonumber(("%f"):format(q.d)), tonumber(("%f"):format(q.w))
      local bx, by = g[1] + ux / ul * d6, g[2] + uy / ul * d6    -- baseline left
      local vx, vy = g[3] - g[1], g[4] - g[2]
      local vl = sqrt(vx * vx + vy * vy)
      local cx, cy = bx + vx / vl * q.w / 2, by + vy / vl * q.w / 2
      local rx, ry = p:point(q.s)
      worst = max(worst, sqrt((cx - rx) ^ 2 + (cy - ry) ^ 2))
      local tx, ty = p:tangent(q.s)
      local ang = atan2(g[4] - g[2], g[3] - g[1]) - atan2(ty, tx)
      ang = abs((ang + math.pi) % (2 * math.pi) - math.pi)
      worstang = max(worstang, ang)
      worstw = max(worstw, abs(vl - w6))
    end
    check(("text %s: %d glyph centres on the path at their lengths, to tol * L"):format(name, #G),
      worst <= TOL * L + 64 * EPS * scale[a[1]], ("worst %.2g"):format(worst))
    check(("text %s: each glyph along the tangent at its centre"):format(name),
      -- the corners' rounding over the narrowest glyph's baseline
      worstang <= 64 * EPS * scale[a[1]] / wmin, ("worst %.2g rad"):format(worstang))
    check(("text %s: the boxes are the glyphs' widths"):format(name), worstw <= 64 * EPS * scale[a[1]],
      ("worst %.2g"):format(worstw))
    local first, last = Q[1].s - Q[1].w / 2, Q[#Q].s + Q[#Q].w / 2
    local how, off = a[2], a[3]
    local e
    if how == "start" then e = first - off
    elseif how == "end" then e = last - (L - off)
    elseif how == "centre" then e = (first + last) / 2 - L / 2
    else e = max(abs(first - off), abs(last - (L - off))) end
    check(("text %s: aligned %s (offset %g)"):format(name, how, off), abs(e) <= TOL * L + 16 * EPS * L,
      ("off by %.2g"):format(e))
  end
end

-- Plain LuaTeX, Lua alone: the length digit for digit, each glyph 3bp
-- above the path at its length, along the tangent.
if svg then
  local p = apath.svg(svg.d)
  check("plain LuaTeX: the SVG path's length, digit for digit", p:length() == svg.L,
    ("%.17g"):format(svg.L))
  local worst = 0
  for _, g in ipairs(svg.glyphs) do
    local x, y = p:point(g[1])
    local tx, ty = p:tangent(g[1])
    worst = max(worst, abs(g[2] - (x - 3 * ty)), abs(g[3] - (y + 3 * tx)), abs(g[4] - tx), abs(g[5] - ty))
  end
  check(("plain LuaTeX: %d glyphs at their lengths, on the tangent"):format(#svg.glyphs),
    #svg.glyphs > 0 and worst == 0, ("worst %.2g"):format(worst))
end

-- The bad-input document's documented values (VAL name v...).
local VALS = {
  point_length = {"0"},                  -- a one-point path is 0 long
  point_time = {"0"},                    -- ... and its time is 0
  point_at = {"3", "4"},                 -- ... every length is the point
  beyond_time = {"2"},                   -- open path: arctime's clamp, time n
  beyond_neg = {"0"},                    -- ... and 0 below 0
  empty_text = {"0"},                    -- an empty text: an empty picture
  pair_length = {"0"},                   -- a pair is a one-point path
  scaled_length = {"6.28313"},           -- scaled: rounded to 2^-16 (below)
}
for name, want in pairs(VALS) do
  local got = vals[name]
  if next(vals) then
    check(("bad input %s: %s"):format(name, table.concat(want, " ")),
      got and table.concat(got, " ") == table.concat(want, " "),
      got and table.concat(got, " ") or "missing")
  end
end

if #lines > 0 then
  print(("     MetaPost's arclength: worst error %.3g (relative %.2g); arctime: worst distance error %.3g"):format(
    mp_len_err, mp_len_rel, mp_time_err))
end
print(("%d passed, %d failed"):format(passed, failed))
os.exit(failed == 0 and 0 or 1)
