-- arclen.mpost -- the Lua side of mp/arclen.mp: MetaPost's runscript calls
-- run(op, numbersystem, method, tol, knots, ...) and gets MetaPost code
-- back (a number, a pair, a path or a picture expression).
--
-- The path arrives as text, 6 numbers a knot written by MetaPost's decimal
-- (17 significant digits in double mode, so every double is the one
-- MetaPost holds); numbers go back with 17 significant digits too.  Under
-- numbersystem scaled MetaPost holds multiples of 2^-16 below 4096 only:
-- results are rounded to that grid (a warning, once), and a result beyond
-- it is an errmessage.  Every failure becomes a MetaPost errmessage with a
-- placeholder value of the expected type, never a Lua error inside mplib.
local arclen = require("arclen")
local path = require("arclen.path")

local numtext = require("arclen.numtext")
-- '.' as the decimal point in any locale (MetaPost reads only that)
local format, tonumber = numtext.format, numtext.tonumber
local floor, abs, huge = math.floor, math.abs, math.huge
local atan2 = math.atan2 or math.atan
local unpack = table.unpack or unpack
local M = {}

-- ---- numbers out ------------------------------------------------------------

local function fail(msg) error({msg = msg}, 0) end

local SCALED_MAX = 4096 - 2 ^ -16
local warned_scaled = false

local function warn(msg)
  if texio and texio.write_nl then
    texio.write_nl("term and log", "arclen warning: " .. msg)
    texio.write_nl("term and log", "")
  else
    io.stderr:write("arclen warning: ", msg, "\n")
  end
end
M.warn = warn     -- replaceable (the specs silence it)

-- x as MetaPost reads it: %.17g in double (and binary, decimal), whose
-- scanners take exponents; rounded to 2^-16 and fixed-point under scaled.
local function num(x, sys)
  if x ~= x or x == huge or x == -huge then fail("result is not finite") end
  if sys ~= "scaled" then return format("%.17g", x) end
  local v = floor(x * 65536 + 0.5) / 65536
  if abs(v) > SCALED_MAX then
    fail(format("%.10g is beyond numbersystem scaled's range (|x| < 4096); "
      .. "use \\mplibnumbersystem{double}", x))
  end
  return format("%.16f", v)        -- 2^-16 has 16 decimals: exact
end
M.num = num

local function pair(x, y, sys) return "(" .. num(x, sys) .. "," .. num(y, sys) .. ")" end

-- ---- paths in -----------------------------------------------------------

-- The knots' text ("c" or "o", then x,y,lx,ly,rx,ry per knot) as mplib
-- knot tables, for arclen.path.mplib.
local function knots_of(text)
  local kind, rest = text:match("^([co])(.*)$")
  if not kind then fail("malformed path text") end
  local knots = {cycle = kind == "c"}
  for k in rest:gmatch("%S+") do
    local v = {}
    for x in k:gmatch("[^,]+") do v[#v + 1] = tonumber(x) end
    if #v ~= 6 then fail("malformed knot " .. k) end
    knots[#knots + 1] = {x_coord = v[1], y_coord = v[2], left_x = v[3],
      left_y = v[4], right_x = v[5], right_y = v[6]}
  end
  if #knots == 0 then fail("the path has no knots") end
  return knots
end

-- The paths met so far, by their text and options: a figure that asks many
-- questions of one path measures its segments once.
local cache, cached = {}, 0
local CACHE_MAX = 256

local function path_of(text, method, tol)
  local key = method .. " " .. tol .. " " .. text
  local p = cache[key]
  if p then return p end
  local ok, res = pcall(path.mplib, knots_of(text), {method = method, tol = tol})
  if not ok then fail(type(res) == "table" and res.msg or tostring(res)) end
  if cached >= CACHE_MAX then cache, cached = {}, 0 end
  cache[key], cached = res, cached + 1
  return res
end

-- ---- the operations -------------------------------------------------------

local ops = {}

local function need_number(x, what)
  if type(x) ~= "number" then fail(what .. " must be a known numeric") end
  return x
end

function ops.length(p, sys)
  local L, err = p:length()
  if L == nil then fail(err) end
  return num(L, sys)
end

function ops.time(p, sys, s)
  return num(p:time(need_number(s, "the length")), sys)
end

-- The times at two lengths, as a pair for MetaPost's subpath; lengths
-- clamp to [0, L] as arclen's p:sub does (and MetaPost's arctime on an
-- open path), so s1 <= s0 gives a one-point subpath.
function ops.subpath(p, sys, s0, s1)
  need_number(s0, "s0"); need_number(s1, "s1")
  local L = p:length()
  local a = s0 < 0 and 0 or (s0 > L and L or s0)
  local b = s1 < 0 and 0 or (s1 > L and L or s1)
  if b < a then b = a end
  return pair(p:time(a), p:time(b), sys)
end

-- The n points as a path of straight pieces through them (the knots are
-- the points: point k of it is the (k+1)-th).
local function polyline(pts, sys)
  local s = {}
  for i, q in ipairs(pts) do
    local z = pair(q.x, q.y, sys)
    if i == 1 then s[1] = z
    else s[#s + 1] = "..controls " .. pair(pts[i - 1].x, pts[i - 1].y, sys) .. " and " .. z .. ".." .. z end
  end
  return table.concat(s)
end

-- n points: both ends of an open path, n points L/n apart from the start
-- on a cycle (no repeat), as arclen's p:resample.
function ops.points(p, sys, n)
  need_number(n, "n")
  if n ~= floor(n) or n < 1 or n > 100000 then fail("n must be an integer in [1, 100000]") end
  if n == 1 then
    local x, y = p:point(0)
    return pair(x, y, sys)
  end
  return polyline(p:resample(n), sys)
end

-- A piece (an arclen path) as a MetaPost path literal with explicit
-- controls: the cubics arclen cut, 17 digits each.
local function path_code(q, sys)
  local n = q:segments()
  if n == 0 then return pair(q.x0, q.y0, sys) end
  local s = {}
  for k = 1, n do
    local c = q:segment(k)
    if k == 1 then s[1] = pair(c[1], c[2], sys) end
    s[#s + 1] = "..controls " .. pair(c[3], c[4], sys) .. " and "
      .. pair(c[5], c[6], sys) .. ".." .. pair(c[7], c[8], sys)
  end
  return table.concat(s)
end

function ops.dashed(p, sys, offset, pattern)
  need_number(offset, "the offset")
  if type(pattern) ~= "table" then fail("a dash pattern (on, off, ...) expected") end
  for i = 1, #pattern do
    if type(pattern[i]) ~= "number" then fail("dash pattern entry " .. i .. " must be a known numeric") end
  end
  local ok, dashes = pcall(p.dash, p, pattern, offset)
  if not ok then
    local msg = tostring(dashes):gsub("^bad argument #%d to 'dash' %((.*)%)$", "%1")
    fail(msg)
  end
  local s = {"image("}
  for _, d in ipairs(dashes) do
    s[#s + 1] = "draw " .. path_code(d, sys) .. ";"
  end
  s[#s + 1] = ")"
  return table.concat(s)
end

-- ---- text along a path ---------------------------------------------------

-- TeX boxes are measured in sp; MetaPost (luamplib) works in bp.
local SP_PER_BP = 65536 * 7227 / 7200

-- The units a typeset hbox places: glyphs (a ligature is one), rules and
-- nested boxes, each with its left edge x (sp) on the baseline; kerns,
-- glue and math surround only move x.
local function units_of(box)
  local units, x = {}, 0
  local id = node.id
  local GLYPH, KERN, GLUE, HLIST, VLIST, RULE, MATH, DISC =
    id("glyph"), id("kern"), id("glue"), id("hlist"), id("vlist"),
    id("rule"), id("math"), id("disc")
  local function walk(head)
    for n in node.traverse(head) do
      local t = n.id
      if t == GLYPH or t == HLIST or t == VLIST or t == RULE then
        local w, sh = n.width or 0, (t == HLIST or t == VLIST) and n.shift or 0
        -- a box's shift (\lower, \raise) moves it in its textext box too
        units[#units + 1] = {node = node.copy(n), x = x, w = w,
          h = (n.height or 0) - sh, d = (n.depth or 0) + sh}
        x = x + w
      elseif t == KERN then
        x = x + n.kern
      elseif t == GLUE then
        x = x + node.effective_glue(n, box)
      elseif t == MATH then
        x = x + (n.surround or 0)
      elseif t == DISC then
        walk(n.replace)
      end
    end
  end
  walk(box.head)
  return units, x
end

local stash, stashed = {}, 0    -- the units' nodes, until textext copies them

-- Called from TeX inside luamplib's textext box: write unit k's node there.
function M.glyph(k)
  local n = stash[k]
  if n then node.write(node.copy(n)) end
end

-- Typeset text in an hbox (the document's current font) and return its
-- units; the scratch box 0 is restored afterwards.
local function typeset(text)
  if not (tex and tex.runtoks and node) then
    fail("text along a path needs LuaTeX (tex.runtoks)")
  end
  local saved = tex.getbox(0)
  saved = saved and node.copy(saved)
  local cat = luatexbase and luatexbase.registernumber
    and luatexbase.registernumber("catcodetable@latex") or nil
  tex.runtoks(function()
    if cat then tex.sprint(cat, "\\setbox0\\hbox{" .. text .. "}")
    else tex.sprint("\\setbox0\\hbox{" .. text .. "}") end
  end)
  local box = tex.getbox(0)
  local units, width = {}, 0
  if box then units, width = units_of(box) end
  tex.setbox(0, saved)
  return units, width
end

M.placed = {}    -- the last followtext's placements (for checks and tools)

local ALIGN = {start = true, centre = true, center = true, ["end"] = true, fit = true}

function ops.followtext(p, sys, offset, align, text)
  need_number(offset, "the offset")
  if not ALIGN[align] then
    fail("align must be \"start\", \"centre\", \"end\" or \"fit\", got \"" .. tostring(align) .. "\"")
  end
  if type(text) ~= "string" then fail("the text must be a string") end
  local L = p:length()
  if text:match("^%s*$") then M.placed = {}; return "nullpicture" end
  if not (L > 0) then fail("the path has length 0: no room for text") end
  local units, width = typeset(text)
  M.placed = {}
  if #units == 0 then return "nullpicture" end
  local W = width / SP_PER_BP
  -- the distance of the text's left end, and the extra room per gap (fit)
  local start, gap = offset, 0
  if align == "centre" or align == "center" then start = (L - W) / 2 + offset
  elseif align == "end" then start = L - W - offset
  elseif align == "fit" then
    if #units > 1 then gap = (L - 2 * offset - W) / (#units - 1)
    else start = (L - W) / 2 end
  end
  local s = {"image("}
  local dropped = 0
  for i, u in ipairs(units) do
    local w = u.w / SP_PER_BP
    local c = start + u.x / SP_PER_BP + w / 2 + (i - 1) * gap
    if not p.cyclic and (c < 0 or c > L) then
      dropped = dropped + 1
    else
      local x, y = p:point(c)
      local tx, ty = p:tangent(c)
      local a = math.deg(atan2(ty, tx))
      stashed = stashed + 1
      stash[stashed] = u.node
      M.placed[#M.placed + 1] = {i = i, s = c, x = x, y = y, angle = a,
        w = w, h = u.h / SP_PER_BP, d = u.d / SP_PER_BP}
      s[#s + 1] = format("addto currentpicture also (rawtextext(\"\\directlua{"
        .. "package.loaded['arclen.mpost'].glyph(%d)}\") shifted (%s,0) rotated %s "
        .. "shifted %s);", stashed, num(-w / 2, sys), num(a, sys), pair(x, y, sys))
    end
  end
  if dropped > 0 then
    M.warn(format("arclen_followtext: %d of %d glyphs fall beyond the ends of the "
      .. "path (text %.2fbp, path %.2fbp) and are left out", dropped, #units, W, L))
  end
  s[#s + 1] = ")"
  return table.concat(s)
end

-- ---- the entry point ------------------------------------------------------

-- A placeholder of the type each operation returns, after an error.
local DUMMY = {length = "0", time = "0", subpath = "(0,0)", points = "(0,0)",
  dashed = "nullpicture", followtext = "nullpicture"}

local function errcode(op, msg)
  msg = tostring(msg):gsub("^[^\n]-:%d+: ", ""):gsub("^bad argument #%d+ to '[^']*' %((.*)%)$", "%1")
  msg = msg:gsub("[\r\n]+", " "):gsub('"', "'")
  return format('begingroup errmessage "arclen_%s: %s"; %s endgroup', op, msg,
    DUMMY[op] or "0")
end

-- run(op, numbersystem, method, tol, knots, ...) -> MetaPost code.
function M.run(op, sys, method, tol, knots, ...)
  local args = {...}
  local nargs = select("#", ...)
  local ok, res = pcall(function()
    local f = ops[op]
    if not f then fail("unknown operation " .. tostring(op)) end
    if sys == "scaled" and not warned_scaled then
      warned_scaled = true
      M.warn("MetaPost runs with numbersystem scaled: arclen's results are "
        .. "rounded to 2^-16 (1.5e-5) and must stay below 4096; for full "
        .. "precision use \\mplibnumbersystem{double}")
    end
    if type(tol) ~= "number" or tol == 0 then tol = 1e-12 end
    if not (tol >= arclen.tol_min and tol <= arclen.tol_max) then
      fail(format("arclen_tol must be 0 (the default) or in [%g, %g]", arclen.tol_min, arclen.tol_max))
    end
    local p = path_of(knots, method, tol)
    return f(p, sys, unpack(args, 1, nargs))
  end)
  if ok then return res end
  return errcode(op, type(res) == "table" and res.msg or res)
end

return M
