-- arclen.svg -- SVG documents measured as a renderer draws them.
--
--   local svg = require "arclen.svg"
--   local doc = svg.read("drawing.svg" [, opts])    -- a file, streamed
--   local doc = svg.parse(text [, opts [, name]])   -- a string
--   doc.total, doc.elements[i].{id, tag, path, length, layer, line, col, use,
--                               d, ctm}  (d: the shape's path data in its own
--                               coordinates, ctm: {a, b, c, d, e, f} onto the
--                               document's)
--   svg.stat(doc) -> per layer: length, pen-up travel, paths, segments, bbox
--
-- The document is read by LuaExpat in streaming mode (callbacks; nothing
-- like a DOM is built).  Every basic shape becomes path data as SVG 2
-- defines it (section 10, "Basic shapes"), mapped by the element's current
-- transformation matrix (nested transform attributes, nested viewports) and
-- measured by arclen.path.  <use> may point forwards: when the document
-- contains a <use> element, the subtrees of elements with an id are kept as
-- their start/end events and the uses are expanded once the document has
-- been read; a document without <use> keeps nothing but its results.
-- Errors are "NAME:LINE:COL: message"; misuse is "bad argument #n to 'f'".
-- doc/svg.md lists the semantic choices made where the specification leaves
-- room.
local path = require("arclen.path")
local core = require("arclen.core")

local M = {}

local format, find, sub, match, gsub, lower = string.format, string.find,
  string.sub, string.match, string.gsub, string.lower
local abs, sqrt, huge, floor = math.abs, math.sqrt, math.huge, math.floor
local rad, cos, sin, tan = math.rad, math.cos, math.sin, math.tan

local SVG_NS = "http://www.w3.org/2000/svg"
local XLINK_NS = "http://www.w3.org/1999/xlink"
local INKSCAPE_NS = "http://www.inkscape.org/namespaces/inkscape"
local SEP = "\1"                      -- lxp's namespace separator

-- Caps (every loop and recursion has one).
local MAX_DEPTH = 1000                -- element nesting
local MAX_USE_DEPTH = 64              -- <use> inside used content
local MAX_ELEMENTS = 1000000          -- drawn elements, uses expanded
local MAX_REPLAYED = 250000           -- element events replayed by <use> (use bombs)
local MAX_ENTITIES = 1000             -- entity declarations
local MAX_ENTITY_LEN = 65536          -- an entity's replacement text
local CHUNK = 65536                   -- bytes per read of a file

-- CSS absolute units in px (CSS Values 3 section 5.2: 1in = 96px).
local PX = {px = 1, ["in"] = 96, cm = 96 / 2.54, mm = 96 / 25.4,
            pt = 96 / 72, pc = 96 / 6, q = 96 / 101.6}
-- Output units: "user" (the root's user units) or one of these.
local UNITS = {px = 1, ["in"] = 96, cm = 96 / 2.54, mm = 96 / 25.4,
               pt = 96 / 72, pc = 96 / 6}
local FONT_SIZE = 16                  -- em (CSS "medium"); ex is half of it

-- ---- errors --------------------------------------------------------------

-- A located error: raised as a table, turned into "NAME:L:C: msg" by read.
local function fail(line, col, msg)
  error({line = line, col = col, msg = msg}, 0)
end

-- level: the user's call (3: argerror's caller is the API function).
local function argerror(n, fname, msg, level)
  error(format("bad argument #%d to '%s' (%s)", n, fname, msg), level or 3)
end

local function isfinite(x)
  return x == x and x ~= huge and x ~= -huge
end

-- ---- numbers, lengths ------------------------------------------------------

-- A number of SVG's grammar (SVG 2 section 4.2: CSS number syntax, an
-- exponent allowed) at position i of s; value and position after, or nil
-- (also beyond the doubles).  The scanner of path data's numbers, in C.
local scan_number = core.svg_number

-- A <length> attribute (SVG 2 section 4.3) in user units.  kind: "x",
-- "y" or "o" (other), for percentages of the viewport vp = {w, h}
-- (SVG 2 section 8.9: diagonal / sqrt(2) for "other").
local function length(ctx, s, kind, vp, what)
  local v, i = scan_number(s, (find(s, "%S") or 1))
  local unit = v and match(s, "^(%a*%%?)%s*$", i)
  if not unit then
    fail(ctx.line, ctx.col, format("%s='%s' is not a length", what, s))
  end
  unit = lower(unit)
  if unit == "" or unit == "px" then return v end
  if PX[unit] then return v * PX[unit] end
  if unit == "em" then return v * FONT_SIZE end
  if unit == "ex" then return v * FONT_SIZE / 2 end
  if unit == "%" then
    if not vp then
      fail(ctx.line, ctx.col, format("%s='%s': a percentage needs a viewport "
        .. "(the root has neither viewBox nor width and height)", what, s))
    end
    local ref
    if kind == "x" then ref = vp.w elseif kind == "y" then ref = vp.h
    else ref = sqrt((vp.w * vp.w + vp.h * vp.h) / 2) end
    return v / 100 * ref
  end
  fail(ctx.line, ctx.col, format("%s='%s': unknown unit '%s'", what, s, unit))
end

-- An attribute as a length, its default when absent.
local function len_attr(ctx, attrs, name, kind, vp, default)
  local s = attrs[name]
  if s == nil or find(s, "^%s*$") then return default end
  return length(ctx, s, kind, vp, name)
end

-- A list of numbers separated by comma-wsp (points, viewBox), and the
-- position of the first byte that starts no number (nil when none).
local function numbers(ctx, s, what, cap)
  local out, bad = core.svg_numbers(s, cap)
  if out == nil then fail(ctx.line, ctx.col, what .. ": too many numbers") end
  return out, bad
end

-- ---- matrices: {a, b, c, d, e, f} is SVG's matrix(a b c d e f) -------------

local IDENTITY = {1, 0, 0, 1, 0, 0}

-- P Q: Q applied first (a child's CTM is the parent's times its own).
local function mul(P, Q)
  return {P[1] * Q[1] + P[3] * Q[2], P[2] * Q[1] + P[4] * Q[2],
          P[1] * Q[3] + P[3] * Q[4], P[2] * Q[3] + P[4] * Q[4],
          P[1] * Q[5] + P[3] * Q[6] + P[5], P[2] * Q[5] + P[4] * Q[6] + P[6]}
end

local function translate(tx, ty) return {1, 0, 0, 1, tx, ty} end

local TRANSFORM_ARGS = {matrix = {6}, translate = {1, 2}, scale = {1, 2},
  rotate = {1, 3}, skewX = {1}, skewY = {1}}

-- One transform function to a matrix (SVG 1.1 section 7.6; angles in
-- degrees).
local function transform_function(name, a)
  if name == "matrix" then return {a[1], a[2], a[3], a[4], a[5], a[6]} end
  if name == "translate" then return translate(a[1], a[2] or 0) end
  if name == "scale" then return {a[1], 0, 0, a[2] or a[1], 0, 0} end
  if name == "rotate" then
    local t = rad(a[1])
    local c, s = cos(t), sin(t)
    -- exact at multiples of 90 degrees, as a renderer's matrix is meant to be
    if a[1] % 90 == 0 then
      local q = floor(a[1] / 90) % 4
      c = ({1, 0, -1, 0})[q + 1]
      s = ({0, 1, 0, -1})[q + 1]
    end
    local R = {c, s, -s, c, 0, 0}
    if a[2] then        -- rotate(a cx cy) = translate(cx cy) rotate(a) translate(-cx -cy)
      return mul(mul(translate(a[2], a[3]), R), translate(-a[2], -a[3]))
    end
    return R
  end
  if name == "skewX" then return {1, 0, tan(rad(a[1])), 1, 0, 0} end
  return {1, tan(rad(a[1])), 0, 1, 0, 0}     -- skewY
end

-- The transform attribute (SVG 1.1 section 7.6's grammar, read as
-- browsers do: functions separated by optional whitespace and at most one
-- comma, arguments by comma-wsp, spaces allowed around the parentheses;
-- a comma before ')' or after the last function is an error) as one matrix.
local function parse_transform(ctx, s)
  local T = IDENTITY
  local n = #s
  local function bad(j, why)
    fail(ctx.line, ctx.col, format("transform='%s': %s at character %d", s, why, j))
  end
  local i = find(s, "%S") or n + 1
  for _ = 1, n do                       -- each turn reads one function
    if i > n then break end
    local name = match(s, "^(%a+)", i)
    if not name then bad(i, "a transform function expected") end
    if not TRANSFORM_ARGS[name] then bad(i, "unknown transform '" .. name .. "'") end
    i = i + #name
    local _, e = find(s, "^%s*%(%s*", i)
    if not e then bad(i, "'(' expected after " .. name) end
    i = e + 1
    local a = {}
    for _ = 1, 7 do
      if sub(s, i, i) == ")" then break end
      local v, j = scan_number(s, i)
      if not v then bad(i, "a number or ')' expected in " .. name .. "(...)") end
      a[#a + 1] = v
      local _, e2 = find(s, "^%s*,?%s*", j)
      if sub(s, e2 + 1, e2 + 1) == ")" and find(sub(s, j, e2), ",", 1, true) then
        bad(e2 + 1, "comma before ')'")
      end
      i = e2 + 1
    end
    if sub(s, i, i) ~= ")" then bad(i, "too many arguments to " .. name) end
    local ok = false
    for _, k in ipairs(TRANSFORM_ARGS[name]) do if #a == k then ok = true end end
    if not ok then
      bad(i, format("%s takes %s arguments, got %d", name,
        table.concat(TRANSFORM_ARGS[name], " or "), #a))
    end
    T = mul(T, transform_function(name, a))
    local _, e3 = find(s, "^%s*,?%s*", i + 1)
    if e3 >= n and find(sub(s, i + 1, e3), ",", 1, true) then
      bad(i + 1, "comma after the last transform")
    end
    i = e3 + 1
  end
  for k = 1, 6 do
    if not isfinite(T[k]) then fail(ctx.line, ctx.col, format("transform='%s' overflows", s)) end
  end
  return T
end

-- The viewBox-to-viewport transform (SVG 2 section 8.2), vb = {x, y, w,
-- h} onto the viewport (ex, ey, ew, eh) with preserveAspectRatio par.
local function viewbox_matrix(ctx, vb, par, ex, ey, ew, eh)
  local align, slice = "xMidYMid", false
  if par and not find(par, "^%s*$") then
    local words = {}
    for w in par:gmatch("%S+") do words[#words + 1] = w end
    if words[1] == "defer" then table.remove(words, 1) end
    align = words[1]
    local ok = align == "none" or (align and match(align, "^x(M%a%a)Y(M%a%a)$"))
    if ok and align ~= "none" then
      local ax, ay = match(align, "^x(M%a%a)Y(M%a%a)$")
      local M3 = {Min = true, Mid = true, Max = true}
      ok = M3[ax] and M3[ay]
    end
    if not ok or #words > 2 or (words[2] and words[2] ~= "meet" and words[2] ~= "slice") then
      fail(ctx.line, ctx.col, format("preserveAspectRatio='%s' is not valid", par))
    end
    slice = words[2] == "slice"
  end
  local sx, sy = ew / vb[3], eh / vb[4]
  if align ~= "none" then
    if slice then sx = math.max(sx, sy) else sx = math.min(sx, sy) end
    sy = sx
  end
  local tx, ty = ex - vb[1] * sx, ey - vb[2] * sy
  if align ~= "none" then
    local ax, ay = match(align, "^x(M%a%a)Y(M%a%a)$")
    if ax == "Mid" then tx = tx + (ew - vb[3] * sx) / 2 end
    if ax == "Max" then tx = tx + (ew - vb[3] * sx) end
    if ay == "Mid" then ty = ty + (eh - vb[4] * sy) / 2 end
    if ay == "Max" then ty = ty + (eh - vb[4] * sy) end
  end
  return {sx, 0, 0, sy, tx, ty}
end

local function parse_viewbox(ctx, s)
  if s == nil or find(s, "^%s*$") then return nil end
  local v, bad = numbers(ctx, s, "viewBox", 8)
  if bad or #v ~= 4 then fail(ctx.line, ctx.col, format("viewBox='%s' is not four numbers", s)) end
  if v[3] < 0 or v[4] < 0 then
    fail(ctx.line, ctx.col, format("viewBox='%s': negative width or height", s))
  end
  return v
end

-- ---- style -----------------------------------------------------------------

-- The properties this reader uses, from the style attribute (CSS
-- declarations, which win) or the presentation attribute (SVG 2 section 6.6).
local function property(attrs, style, name)
  local v = style and style[name]
  if v == nil then v = attrs[name] end
  if v == nil then return nil end
  v = lower(match(v, "^%s*(.-)%s*$"))
  return v
end

-- Only the declarations this reader uses are looked for (display,
-- visibility, stroke, stroke-width): a style attribute is mostly fill and
-- font properties.
local STYLE_PROPS = {"display", "visibility", "stroke", "stroke-width"}

-- Bytes that may not precede a property's name (it must be whole).
local NAME_BYTE = {}
for c = 0, 255 do NAME_BYTE[c] = find(string.char(c), "[%w%-]") ~= nil end
local byte = string.byte

local function parse_style(s)
  if s == nil then return nil end
  local out = nil
  for _, k in ipairs(STYLE_PROPS) do
    -- every whole occurrence of the name followed by ':' (the last
    -- declaration wins, as in CSS); the value runs to the next ';'
    local init = 1
    for _ = 1, #s do
      local a, b = find(s, k, init, true)
      if not a then break end
      local e, v
      if a == 1 or not NAME_BYTE[byte(s, a - 1)] then
        _, e, v = find(s, "^%s*:%s*([^;]*)", b + 1)
      end
      if e then
        out = out or {}
        out[k] = gsub(gsub(v, "%s*!%s*important%s*$", ""), "%s+$", "")
        init = e + 1
      else
        init = a + 1
      end
    end
  end
  return out
end

-- ---- shapes to path data (SVG 2 chapter 10) ----------------------------

local function num(x) return format("%.17g", x) end

local function points_data(ctx, attrs, close)
  local s = attrs.points or ""
  local v, bad = numbers(ctx, s, "points", #s + 1)
  if bad then
    fail(ctx.line, ctx.col, format("points: not a number at character %d", bad))
  end
  -- SVG 2 section 10.6: an odd count is an error
  if #v % 2 == 1 then fail(ctx.line, ctx.col, "points: an odd number of coordinates") end
  if #v < 2 then return nil end
  local out = {"M", num(v[1]), num(v[2])}
  for k = 3, #v, 2 do
    out[#out + 1] = format("L%.17g %.17g", v[k], v[k + 1])    -- num, num
  end
  if close then out[#out + 1] = "Z" end
  return table.concat(out, " ")
end

local function nonneg(ctx, v, what)
  if v < 0 then fail(ctx.line, ctx.col, format("%s must not be negative (%s)", what, num(v))) end
  return v
end

-- The path data of a shape, or nil when the shape is not rendered (a zero
-- width, radius...: SVG 2 chapter 10).
local function shape_data(ctx, tag, attrs, vp)
  if tag == "path" then
    local d = attrs.d
    if d == nil or find(d, "^%s*$") then return nil end   -- SVG 2 9.3.9: no rendering
    return d
  elseif tag == "rect" then                   -- SVG 2 section 10.2
    local x = len_attr(ctx, attrs, "x", "x", vp, 0)
    local y = len_attr(ctx, attrs, "y", "y", vp, 0)
    local w = nonneg(ctx, len_attr(ctx, attrs, "width", "x", vp, 0), "width")
    local h = nonneg(ctx, len_attr(ctx, attrs, "height", "y", vp, 0), "height")
    local rx = attrs.rx and not find(attrs.rx, "^%s*auto%s*$") and len_attr(ctx, attrs, "rx", "x", vp, nil)
    local ry = attrs.ry and not find(attrs.ry, "^%s*auto%s*$") and len_attr(ctx, attrs, "ry", "y", vp, nil)
    if rx then nonneg(ctx, rx, "rx") end
    if ry then nonneg(ctx, ry, "ry") end
    if w == 0 or h == 0 then return nil end
    -- auto: the other radius, else 0; then each clamped to half the side
    rx, ry = rx or ry or 0, ry or rx or 0
    if rx > w / 2 then rx = w / 2 end
    if ry > h / 2 then ry = h / 2 end
    if rx == 0 or ry == 0 then
      return format("M%s %s H%s V%s H%s Z", num(x), num(y), num(x + w), num(y + h), num(x))
    end
    local a = format("A%s %s 0 0 1 ", num(rx), num(ry))
    return table.concat({
      format("M%s %s H%s", num(x + rx), num(y), num(x + w - rx)),
      a .. num(x + w) .. " " .. num(y + ry), "V" .. num(y + h - ry),
      a .. num(x + w - rx) .. " " .. num(y + h), "H" .. num(x + rx),
      a .. num(x) .. " " .. num(y + h - ry), "V" .. num(y + ry),
      a .. num(x + rx) .. " " .. num(y), "Z"}, " ")
  elseif tag == "circle" or tag == "ellipse" then  -- SVG 2 sections 10.3, 10.4
    local cx = len_attr(ctx, attrs, "cx", "x", vp, 0)
    local cy = len_attr(ctx, attrs, "cy", "y", vp, 0)
    local rx, ry
    if tag == "circle" then
      rx = nonneg(ctx, len_attr(ctx, attrs, "r", "o", vp, 0), "r")
      ry = rx
    else
      rx = attrs.rx and not find(attrs.rx, "^%s*auto%s*$") and len_attr(ctx, attrs, "rx", "x", vp, nil)
      ry = attrs.ry and not find(attrs.ry, "^%s*auto%s*$") and len_attr(ctx, attrs, "ry", "y", vp, nil)
      if rx then nonneg(ctx, rx, "rx") end
      if ry then nonneg(ctx, ry, "ry") end
      rx, ry = rx or ry or 0, ry or rx or 0      -- auto: the other one
    end
    if rx == 0 or ry == 0 then return nil end
    -- four arcs from (cx + rx, cy) in the positive angle direction
    local a = format("A%s %s 0 0 1 ", num(rx), num(ry))
    return table.concat({"M" .. num(cx + rx) .. " " .. num(cy),
      a .. num(cx) .. " " .. num(cy + ry), a .. num(cx - rx) .. " " .. num(cy),
      a .. num(cx) .. " " .. num(cy - ry), a .. num(cx + rx) .. " " .. num(cy), "Z"}, " ")
  elseif tag == "line" then                   -- SVG 2 section 10.5
    return format("M%s %s L%s %s",
      num(len_attr(ctx, attrs, "x1", "x", vp, 0)), num(len_attr(ctx, attrs, "y1", "y", vp, 0)),
      num(len_attr(ctx, attrs, "x2", "x", vp, 0)), num(len_attr(ctx, attrs, "y2", "y", vp, 0)))
  elseif tag == "polyline" then               -- SVG 2 section 10.6
    return points_data(ctx, attrs, false)
  elseif tag == "polygon" then                -- SVG 2 section 10.7
    return points_data(ctx, attrs, true)
  end
end

local SHAPES = {path = true, rect = true, circle = true, ellipse = true,
  line = true, polyline = true, polygon = true}
local GROUPS = {g = true, a = true, switch = true, svg = true}
-- Never rendered directly (SVG 2 section 5.6 and the chapters of each);
-- their content is drawn only through <use> (symbol) or not at all.
local NOT_RENDERED = {defs = true, symbol = true, clipPath = true, mask = true,
  marker = true, pattern = true, linearGradient = true, radialGradient = true,
  filter = true, style = true, script = true, title = true, desc = true,
  metadata = true, view = true, font = true, ["font-face"] = true,
  cursor = true, hatch = true, solidcolor = true, meshgradient = true}
-- Rendered, but not measured by this reader (no outline geometry).
local NOT_MEASURED = {text = true, image = true, foreignObject = true, video = true,
  audio = true, canvas = true, iframe = true, mesh = true}

-- ---- the reader ------------------------------------------------------------

-- A frame per open element: ctm, vp (viewport size in the element's user
-- units), visible, stroked, layer, skip (nothing drawn inside), depth.

local Reader = {}
Reader.__index = Reader

local function split_name(name)
  local ns, loc = match(name, "^(.-)\1(.*)$")
  if ns then return ns, loc end
  return nil, name
end

-- Attribute access by namespace: lxp names them "URI\1local".
local function xlink_href(attrs)
  return attrs.href or attrs[XLINK_NS .. SEP .. "href"]
end

function Reader:warn(line, col, msg)
  local w = self.warnings
  if #w < 1000 then w[#w + 1] = format("%s:%d:%d: %s", self.name, line, col, msg) end
end

-- The child frame of element (tag, attrs) under parent; nil to skip the
-- subtree.  shadow: the use that instantiates this element (its root).
function Reader:open(parent, svgns, tag, attrs, line, col, shadow)
  local ctx = {line = line, col = col}
  local depth = parent.depth + 1
  if depth > self.max_depth then
    fail(line, col, format("elements nested deeper than %d", self.max_depth))
  end
  if parent.skip then return {skip = true, depth = depth} end
  if not svgns then return {skip = true, depth = depth} end   -- a foreign element
  if parent.switch then            -- SVG 2 section 5.8: the first child that passes
    if parent.switch_done or attrs.requiredExtensions then
      return {skip = true, depth = depth}
    end
    parent.switch_done = true
  end
  local style = parse_style(attrs.style)
  local f = {depth = depth, ctm = parent.ctm, vp = parent.vp,
             visible = parent.visible, stroked = parent.stroked,
             layer = parent.layer, top = false}
  local disp = property(attrs, style, "display")
  if disp == "none" and not self.hidden then return {skip = true, depth = depth} end
  local vis = property(attrs, style, "visibility")
  if vis == "hidden" or vis == "collapse" then f.visible = false
  elseif vis == "visible" then f.visible = true end
  local st = property(attrs, style, "stroke")
  if st == "none" then f.stroked = false
  elseif st and st ~= "inherit" then f.stroked = true end
  local sw = property(attrs, style, "stroke-width")
  if sw and tonumber(match(sw, "^[%d%.eE+-]+")) == 0 then f.stroked = false end
  if NOT_RENDERED[tag] and not (shadow and shadow.root and tag == "symbol") then
    return {skip = true, depth = depth}
  end
  if NOT_MEASURED[tag] then
    self.skipped[tag] = (self.skipped[tag] or 0) + 1
    return {skip = true, depth = depth}
  end
  if not SHAPES[tag] and not GROUPS[tag] and tag ~= "use" and tag ~= "symbol" then
    return {skip = true, depth = depth}                 -- unknown: SVG 2 section 5.x, not rendered
  end
  if attrs.transform and tag ~= "svg" and tag ~= "symbol" then
    f.ctm = mul(f.ctm, parse_transform(ctx, attrs.transform))
  end
  if tag == "svg" or tag == "symbol" then      -- a new viewport (SVG 2 section 8)
    local vp = parent.vp
    local x = len_attr(ctx, attrs, "x", "x", vp, 0)
    local y = len_attr(ctx, attrs, "y", "y", vp, 0)
    local uw = shadow and shadow.root and shadow.width
    local uh = shadow and shadow.root and shadow.height
    local w = uw or len_attr(ctx, attrs, "width", "x", vp, nil)
    local h = uh or len_attr(ctx, attrs, "height", "y", vp, nil)
    if (w == nil or h == nil) and not vp then
      fail(line, col, "<" .. tag .. "> without width and height needs a viewport")
    end
    w, h = w or vp.w, h or vp.h
    nonneg(ctx, w, "width")
    nonneg(ctx, h, "height")
    if w == 0 or h == 0 then return {skip = true, depth = depth} end
    local vb = parse_viewbox(ctx, attrs.viewBox)
    local V = translate(x, y)
    f.vp = {w = w, h = h}
    if vb then
      if vb[3] == 0 or vb[4] == 0 then return {skip = true, depth = depth} end
      V = viewbox_matrix(ctx, vb, attrs.preserveAspectRatio, x, y, w, h)
      f.vp = {w = vb[3], h = vb[4]}
    end
    f.ctm = mul(f.ctm, V)
  end
  local C = f.ctm
  if C[1] * C[4] - C[2] * C[3] == 0 then       -- SVG 2 section 8.5: not rendered
    self:warn(line, col, format("<%s>: singular transform, not drawn", tag))
    return {skip = true, depth = depth}
  end
  for k = 1, 6 do
    if not isfinite(C[k]) then fail(line, col, "the transforms overflow") end
  end
  if tag == "g" then
    if attrs[INKSCAPE_NS .. SEP .. "groupmode"] == "layer" then
      f.layer = attrs[INKSCAPE_NS .. SEP .. "label"] or attrs.id or f.layer
      f.inklayer = true
    elseif parent.top and not shadow then
      self.ngroups = self.ngroups + 1
      f.layer = attrs.id or ("g" .. self.ngroups)
    end
  elseif tag == "switch" then
    f.switch = true
  end
  if SHAPES[tag] then
    local d = shape_data(ctx, tag, attrs, f.vp)
    if d and (f.visible or self.hidden) and (f.stroked or not self.stroked) then
      local identity = C[1] == 1 and C[2] == 0 and C[3] == 0 and C[4] == 1
        and C[5] == 0 and C[6] == 0
      local ok, p = pcall(path.svg, d, {tol = self.tol, arc_tol = self.arc_tol,
        method = self.method, transform = not identity and C or nil})
      if not ok then
        local m = tostring(p):gsub("^bad argument #1 to 'arclen.path.svg' %((.*)%)$", "%1")
        fail(line, col, format("<%s%s>: %s", tag, attrs.id and (" id='" .. attrs.id .. "'") or "",
          tag == "path" and ("d: " .. m) or m))
      end
      self:emit({id = attrs.id, tag = tag, path = p, layer = f.layer, line = line,
                 col = col, stroked = f.stroked, use = shadow and shadow.id, d = d, ctm = C})
    end
    f.skip = true        -- shapes have no rendered children
  elseif tag == "use" then
    local href = xlink_href(attrs)
    local vp = f.vp
    local ux = len_attr(ctx, attrs, "x", "x", vp, 0)
    local uy = len_attr(ctx, attrs, "y", "y", vp, 0)
    local uw = len_attr(ctx, attrs, "width", "x", vp, nil)
    local uh = len_attr(ctx, attrs, "height", "y", vp, nil)
    if href == nil or not find(href, "^%s*#") then
      if href == nil then
        self:warn(line, col, "<use> without href, nothing drawn")
      else
        self:warn(line, col, format("<use href='%s'>: only same-document references "
          .. "(#id) are read, nothing drawn", href))
      end
    else
      local u = {use = true, href = match(href, "^%s*#(.-)%s*$"), line = line, col = col,
        ctm = mul(C, translate(ux, uy)), vp = vp, visible = f.visible,
        stroked = f.stroked, layer = f.layer, width = uw, height = uh,
        id = attrs.id, chain = shadow and shadow.chain}
      if shadow then self:expand(u) else self:emit(u) end
    end
    f.skip = true        -- use's children are not rendered
  end
  return f
end

-- An element drawn (or a use to expand later) in document order.
function Reader:emit(e)
  local out = self.out
  if #out >= MAX_ELEMENTS then
    fail(e.line, e.col, format("more than %d drawn elements", MAX_ELEMENTS))
  end
  out[#out + 1] = e
end

-- Expand the use u now (the whole document has been read): replay its
-- target's events under a frame made from the use.
function Reader:expand(u)
  local start = self.ids[u.href]
  local chain = u.chain or {}
  if not start then
    fail(u.line, u.col, format("<use> of '#%s': no element has that id", u.href))
  end
  for i = 1, #chain do
    if chain[i] == u.href then
      if i == #chain then
        fail(u.line, u.col, format("<use> of '#%s' refers to itself "
          .. "(or to an element that contains it)", u.href))
      end
      fail(u.line, u.col, format("<use> of '#%s' makes a cycle (%s)", u.href,
        table.concat(chain, " -> ", i) .. " -> " .. u.href))
    end
  end
  if #chain >= MAX_USE_DEPTH then
    fail(u.line, u.col, format("<use> nested deeper than %d", MAX_USE_DEPTH))
  end
  local newchain = {}
  for i = 1, #chain do newchain[i] = chain[i] end
  newchain[#newchain + 1] = u.href
  local ev = self.events
  local base = {depth = 0, ctm = u.ctm, vp = u.vp, visible = u.visible,
                stroked = u.stroked, layer = u.layer, top = false}
  local stack = {base}
  local i, last = start, ev[start].close
  self.replayed = self.replayed + (last - start + 1)
  if self.replayed > MAX_REPLAYED then
    fail(u.line, u.col, format("<use> expansions replay more than %d elements", MAX_REPLAYED))
  end
  local shadow_root = {root = true, id = u.href, chain = newchain,
                       width = u.width, height = u.height}
  local shadow = {root = false, id = u.href, chain = newchain}
  while i <= last do
    local x = ev[i]
    if x then
      local parent = stack[#stack]
      local fr = self:open(parent, x.svgns, x.tag, x.attrs, x.line, x.col,
                           i == start and shadow_root or shadow)
      stack[#stack + 1] = fr
    else
      stack[#stack] = nil
    end
    i = i + 1
  end
end

-- ---- the streaming pass ------------------------------------------------

local function new_reader(opts, name)
  local r = setmetatable({name = name, out = {}, warnings = {}, skipped = {},
    ngroups = 0, ids = {}, events = {}, replayed = 0, tol = opts.tol, arc_tol = opts.arc_tol,
    method = opts.method, hidden = opts.hidden, stroked = opts.stroked,
    max_depth = opts.max_depth or MAX_DEPTH, units = opts.units or "user"}, Reader)
  return r
end

-- The root element: the document's coordinate system (SVG 2 section 8.2).
function Reader:root(attrs, line, col)
  local ctx = {line = line, col = col}
  local vb = parse_viewbox(ctx, attrs.viewBox)
  local w = attrs.width and not find(attrs.width, "%%") and len_attr(ctx, attrs, "width", "x", nil, nil)
  local h = attrs.height and not find(attrs.height, "%%") and len_attr(ctx, attrs, "height", "y", nil, nil)
  if w then nonneg(ctx, w, "width") end
  if h then nonneg(ctx, h, "height") end
  local vp
  if vb then vp = {w = vb[3], h = vb[4]}
  elseif w and h then vp = {w = w, h = h} end
  local ctm = IDENTITY
  if self.units ~= "user" then
    -- the viewBox onto width x height (a missing or percentage width: the
    -- viewBox's own size, one user unit per px), then px into the unit
    local V = IDENTITY
    if vb and vb[3] > 0 and vb[4] > 0 then
      V = viewbox_matrix(ctx, vb, attrs.preserveAspectRatio, 0, 0, w or vb[3], h or vb[4])
    end
    local k = 1 / UNITS[self.units]
    ctm = mul({k, 0, 0, k, 0, 0}, V)
  end
  self.info = {width = w or nil, height = h or nil, viewbox = vb, units = self.units}
  if vb and (vb[3] == 0 or vb[4] == 0) then
    self:warn(line, col, "viewBox of zero width or height: nothing drawn")
    return {skip = true, depth = 1}
  end
  if (w == 0 or h == 0) then
    self:warn(line, col, "width or height zero: nothing drawn")
    return {skip = true, depth = 1}
  end
  local f = {depth = 1, ctm = ctm, vp = vp, visible = true, stroked = false,
             layer = "(root)", top = true}
  local style = parse_style(attrs.style)
  if property(attrs, style, "display") == "none" and not self.hidden then
    return {skip = true, depth = 1}
  end
  local vis = property(attrs, style, "visibility")
  if vis == "hidden" or vis == "collapse" then f.visible = false end
  local st = property(attrs, style, "stroke")
  if st and st ~= "none" and st ~= "inherit" then f.stroked = true end
  if attrs.transform then          -- SVG 2 allows it on the root
    f.ctm = mul(f.ctm, parse_transform(ctx, attrs.transform))
  end
  return f
end

-- Does the text contain what could be a <use> element?  (Decides whether
-- subtrees with ids are kept; a false alarm costs memory, not results.)
local function may_use(s)
  return find(s, "<use", 1, true) or find(s, ":use", 1, true)
end

-- Read the document from next_chunk() (nil at the end).
local function run(opts, name, next_chunk, uses)
  local lxp_ok, lxp = pcall(require, "lxp")
  if not lxp_ok then
    error("arclen.svg needs LuaExpat (module 'lxp'): install the Debian package "
      .. "lua-expat or the rock luaexpat", 0)
  end
  local r = new_reader(opts, name)
  local stack = {}
  local root_seen = false
  local record = uses           -- keep subtrees with ids (the document has <use>)
  local rec = 0                 -- depth inside kept subtrees
  local open_ev = {}            -- the event of each open element being kept
  local nent = 0
  local parser
  local cb = {}
  local bytes = 0
  function cb.EntityDecl(p, ename, _, value, _, system)
    nent = nent + 1
    local line, col = p:pos()
    if nent > MAX_ENTITIES then fail(line, col, format("more than %d entity declarations", MAX_ENTITIES)) end
    if system then return end   -- external: expat does not read it
    if value and (find(value, "&", 1, true) or #value > MAX_ENTITY_LEN) then
      fail(line, col, format("entity '%s' refers to other entities or is longer than %d bytes "
        .. "(entity expansion is refused)", ename, MAX_ENTITY_LEN))
    end
    if value and may_use(value) then record = true end
  end
  function cb.StartElement(p, qname, attrs)
    if #stack >= r.max_depth then
      local line, col = p:pos()
      fail(line, col, format("elements nested deeper than %d", r.max_depth))
    end
    local parent = stack[#stack]
    -- inside a subtree that draws nothing and is not kept for <use>, only
    -- the depth counts (the position is asked for by the error alone)
    if parent and parent.skip and not (record and (rec > 0 or attrs.id)) then
      stack[#stack + 1] = {skip = true, depth = parent.depth + 1}
      return
    end
    local line, col = p:pos()
    local ns, tag = split_name(qname)
    local svgns = ns == SVG_NS or ns == nil
    if not root_seen then
      root_seen = true
      if tag ~= "svg" or not svgns then
        fail(line, col, format("not an SVG document: the root element is <%s>%s", tag,
          ns and (" in namespace " .. ns) or ""))
      end
      stack[1] = r:root(attrs, line, col)
      return
    end
    local id = attrs.id
    if record and (rec > 0 or id) then
      local e = {svgns = svgns, tag = tag, attrs = attrs, line = line, col = col}
      local ev = r.events
      ev[#ev + 1] = e
      rec = rec + 1
      open_ev[rec] = e
      e.index = #ev
      if id and not r.ids[id] then r.ids[id] = #ev end    -- the first of a duplicate id
    end
    stack[#stack + 1] = r:open(stack[#stack], svgns, tag, attrs, line, col, nil)
  end
  function cb.EndElement()
    if rec > 0 then
      local ev = r.events
      ev[#ev + 1] = false
      open_ev[rec].close = #ev
      open_ev[rec] = nil
      rec = rec - 1
    end
    stack[#stack] = nil
  end
  parser = lxp.new(cb, SEP)
  local function xml_error(msg, line, col)
    fail(line or 0, col or 0, "malformed XML: " .. tostring(msg))
  end
  for _ = 1, huge do
    local chunk = next_chunk()
    if chunk == nil then break end
    bytes = bytes + #chunk
    local ok, msg, line, col = parser:parse(chunk)
    if not ok then xml_error(msg, line, col) end
  end
  local ok, msg, line, col = parser:parse()
  if not ok then
    if bytes == 0 then fail(1, 1, "empty document") end
    if not root_seen and msg == "no element found" then
      fail(line, col, "empty document (no root element)")
    end
    xml_error(msg, line, col)
  end
  parser:close()
  if not root_seen then fail(1, 1, "empty document (no root element)") end
  -- expand the uses, in document order
  local drawn = {}
  local out = r.out
  for i = 1, #out do
    local e = out[i]
    if e.use then
      r.out = drawn
      r:expand(e)
    else
      if #drawn >= MAX_ELEMENTS then fail(e.line, e.col, format("more than %d drawn elements", MAX_ELEMENTS)) end
      drawn[#drawn + 1] = e
    end
  end
  r.out = drawn
  r.kept = #r.events
  r.events, r.ids = nil, nil
  return r
end

-- The options of read and parse: tol, arc_tol, method, units, hidden,
-- stroked, measure, max_depth.
local function argerror4(n, fname, msg) argerror(n, fname, msg, 5) end

local function read_opts(opts, fname)
  local o = {tol = 1e-12, method = "gauss", measure = true}
  if opts == nil then return o end
  if type(opts) ~= "table" then argerror4(2, fname, "options table expected, got " .. type(opts)) end
  for k, v in pairs(opts) do
    if k == "tol" or k == "arc_tol" then
      if type(v) ~= "number" or not (v >= core.tol_min and v <= core.tol_max) then
        argerror4(2, fname, ("%s must be in [%g, %g]"):format(k, core.tol_min, core.tol_max))
      end
    elseif k == "method" then
      if type(v) ~= "string" then argerror4(2, fname, "method must be a string") end
    elseif k == "units" then
      if v ~= "user" and not UNITS[v] then
        argerror4(2, fname, format("unknown units '%s' (user, px, mm, cm, in, pt, pc)", tostring(v)))
      end
    elseif k == "hidden" or k == "stroked" or k == "measure" then
      if type(v) ~= "boolean" then argerror4(2, fname, k .. " must be a boolean") end
    elseif k == "max_depth" then
      if type(v) ~= "number" or v ~= floor(v) or v < 1 or v > MAX_DEPTH then
        argerror4(2, fname, format("max_depth must be an integer in [1, %d]", MAX_DEPTH))
      end
    else
      argerror4(2, fname, format("unknown option '%s'", tostring(k)))
    end
    o[k] = v
  end
  return o
end

-- The document object from the reader's results.
local function finish(r, o)
  local doc = {name = r.name, elements = r.out, warnings = r.warnings,
    skipped = r.skipped, units = r.units, kept = r.kept, total = nil}
  for k, v in pairs(r.info or {}) do doc[k] = v end
  doc.units = r.units
  if o.measure then
    local total = 0
    for _, e in ipairs(r.out) do
      local L, err = e.path:length()
      if L == nil or not isfinite(L) then
        fail(e.line, e.col, format("<%s>: length: %s", e.tag, tostring(err or "overflows")))
      end
      e.length = L
      total = total + L
    end
    if not isfinite(total) then fail(1, 1, "the total length overflows") end
    doc.total = total
  end
  return doc
end

-- A located error table into "NAME:LINE:COL: message".
local function located(name, e)
  if type(e) == "table" and e.msg then
    return format("%s:%d:%d: %s", name, e.line or 0, e.col or 0, e.msg)
  end
  return e
end

-- svg.parse(text [, opts [, name]]) -> doc.  name (default "<string>")
-- names the document in messages.
function M.parse(text, opts, name)
  if type(text) ~= "string" then argerror(1, "arclen.svg.parse", "SVG text (a string) expected, got " .. type(text)) end
  local o = read_opts(opts, "arclen.svg.parse")
  if name ~= nil and type(name) ~= "string" then argerror(3, "arclen.svg.parse", "name must be a string") end
  name = name or "<string>"
  local pos = 1
  local ok, res = pcall(function()
    local r = run(o, name, function()
      if pos > #text then return nil end
      local c = sub(text, pos, pos + CHUNK - 1)
      pos = pos + CHUNK
      return c
    end, may_use(text) and true or false)
    return finish(r, o)
  end)
  if not ok then error(located(name, res), 0) end
  return res
end

-- svg.read(filename [, opts]) -> doc: the file read in chunks of 64 KiB.
function M.read(filename, opts)
  if type(filename) ~= "string" then argerror(1, "arclen.svg.read", "a file name expected, got " .. type(filename)) end
  local o = read_opts(opts, "arclen.svg.read")
  local f, err = io.open(filename, "rb")
  if not f then error(tostring(err), 0) end
  -- first pass: only a byte scan for <use (decides what is kept)
  local uses, tail = false, ""
  for _ = 1, huge do
    local c = f:read(CHUNK)
    if c == nil then break end
    if may_use(tail .. sub(c, 1, 8)) or may_use(c) then uses = true break end
    tail = sub(c, -8)
  end
  f:seek("set", 0)
  local ok, res = pcall(function()
    local r = run(o, filename, function() return f:read(CHUNK) end, uses)
    return finish(r, o)
  end)
  f:close()
  if not ok then error(located(filename, res), 0) end
  return res
end

-- ---- stat: what vpype stat prints ----------------------------------------

-- The extremes of one coordinate of a cubic (p0..p3) on [0, 1].
local function cubic_range(p0, p1, p2, p3)
  local lo, hi = math.min(p0, p3), math.max(p0, p3)
  -- B'(t)/3 = a t^2 + b t + c
  local a = -p0 + 3 * p1 - 3 * p2 + p3
  local b = 2 * (p0 - 2 * p1 + p2)
  local c = p1 - p0
  local function at(t)
    if t > 0 and t < 1 then
      local u = 1 - t
      local v = u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3
      if v < lo then lo = v end
      if v > hi then hi = v end
    end
  end
  if abs(a) < 1e-300 then
    if b ~= 0 then at(-c / b) end
  else
    local disc = b * b - 4 * a * c
    if disc >= 0 then
      local q = -0.5 * (b + (b >= 0 and 1 or -1) * sqrt(disc))
      at(q / a)
      if q ~= 0 then at(c / q) end
    end
  end
  return lo, hi
end

-- svg.stat(doc) -> {layers = {{name, length, travel, paths, elements,
-- segments, bbox = {x0, y0, x1, y1}}...}, total = {same fields}}.  paths
-- counts subpaths (vpype reads each subpath as a line), elements the drawn
-- elements, segments the cubics.  Pen-up travel: from each subpath's end
-- to the next subpath's start in the layer, in document order (vpype's
-- pen-up length).  bbox: the exact bounding box of the curves.
function M.stat(doc)
  if type(doc) ~= "table" or type(doc.elements) ~= "table" then
    argerror(1, "arclen.svg.stat", "a document (from arclen.svg.read or parse) expected")
  end
  local layers, by = {}, {}
  local function box_add(b, x0, y0, x1, y1)
    if b[1] == nil then b[1], b[2], b[3], b[4] = x0, y0, x1, y1 return end
    if x0 < b[1] then b[1] = x0 end
    if y0 < b[2] then b[2] = y0 end
    if x1 > b[3] then b[3] = x1 end
    if y1 > b[4] then b[4] = y1 end
  end
  for _, e in ipairs(doc.elements) do
    local L = by[e.layer]
    if not L then
      L = {name = e.layer, length = 0, travel = 0, paths = 0, elements = 0, segments = 0, box = {}}
      by[e.layer] = L
      layers[#layers + 1] = L
    end
    local p = e.path
    L.length = L.length + (e.length or p:length())
    L.elements = L.elements + 1
    L.paths = L.paths + p.nsub
    L.segments = L.segments + p.n
    for j = 1, p.nsub do
      local first, last = p.segs[p.first[j]], p.segs[p.first[j + 1] - 1]
      if L.endx then
        local dx, dy = first[1] - L.endx, first[2] - L.endy
        L.travel = L.travel + sqrt(dx * dx + dy * dy)
      end
      L.endx, L.endy = last[7], last[8]
    end
    for k = 1, p.n do
      local c = p.segs[k]
      local x0, x1 = cubic_range(c[1], c[3], c[5], c[7])
      local y0, y1 = cubic_range(c[2], c[4], c[6], c[8])
      box_add(L.box, x0, y0, x1, y1)
    end
  end
  local total = {name = "total", length = 0, travel = 0, paths = 0, elements = 0, segments = 0, box = {}}
  local out = {}
  for i, L in ipairs(layers) do
    total.length = total.length + L.length
    total.travel = total.travel + L.travel
    total.paths = total.paths + L.paths
    total.elements = total.elements + L.elements
    total.segments = total.segments + L.segments
    if L.box[1] then box_add(total.box, L.box[1], L.box[2], L.box[3], L.box[4]) end
    out[i] = {name = L.name, length = L.length, travel = L.travel, paths = L.paths,
              elements = L.elements, segments = L.segments, bbox = L.box[1] and L.box or nil}
  end
  total.bbox = total.box[1] and total.box or nil
  total.box = nil
  return {layers = out, total = total}
end

M.UNITS = UNITS

return M
