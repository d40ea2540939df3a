-- examples/luatex_arclen.lua -- arclen from Lua alone inside a LuaTeX
-- document (examples/luatex_arclen.tex runs it with \directlua): a path
-- from SVG path data, measured, dashed and lettered by arc length, drawn
-- with PDF operators -- no MetaPost.  Lengths are in bp (PDF units).
local path = require("arclen.path")

local d = "M0 0 C40 60 80 60 120 0 S200 -60 240 0"
local p = path.svg(d)
local L = p:length()
local BP = 65536 * 7227 / 7200           -- sp per bp

local function f4(x) return ("%.4f"):format(x) end
local function lit(s) return "\\pdfextension literal{" .. s .. "}" end

-- The dashes (8 on, 3 off, by length) as PDF path operators.
local ops = {}
for _, dash in ipairs(p:dash({8, 3})) do
  for k = 1, dash:segments() do
    local c = dash:segment(k)
    if k == 1 then ops[#ops + 1] = f4(c[1]) .. " " .. f4(c[2]) .. " m" end
    ops[#ops + 1] = table.concat({f4(c[3]), f4(c[4]), f4(c[5]), f4(c[6]), f4(c[7]), f4(c[8]), "c"}, " ")
  end
end

-- The text's glyphs with the font's kerns and ligatures (node.kerning,
-- node.ligaturing), each centred at its arc length 3bp above the path
-- (on the normal), rotated to the tangent there.
local word = "Lettered by arc length, from Lua alone"
local fid = font.current()
local head, last
for _, code in utf8.codes(word) do
  local n
  if code == 32 then
    n = node.new("glue")
    local fp = font.getfont(fid).parameters
    n.width = fp.space or 0
  else
    n = node.new("glyph")
    n.font, n.char, n.subtype = fid, code, 1
  end
  if head then last.next, n.prev = n, last else head = n end
  last = n
end
head = node.ligaturing(head)
head = node.kerning(head)
local box = node.hpack(head)
local W = box.width / BP
local placed, x = {}, 0
for n in node.traverse(box.head) do
  if n.id == node.id("glyph") then
    local w = n.width / BP
    local s = (L - W) / 2 + x / BP + w / 2            -- centred on the path
    local px, py = p:point(s)
    local tx, ty = p:tangent(s)
    placed[#placed + 1] = {char = n.char, s = s, x = px - 3 * ty, y = py + 3 * tx,
      tx = tx, ty = ty, w = w}
    x = x + n.width
  elseif n.id == node.id("kern") then x = x + n.kern
  elseif n.id == node.id("glue") then x = x + node.effective_glue(n, box) end
end

-- The figure: a box 250bp wide whose origin is the path's (0, 0).
local out = {"\\hbox to 250bp{\\vrule width 0pt height 70bp depth 55bp"}
out[#out + 1] = lit("q 0.8 w 0 0 0.6 RG " .. table.concat(ops, " ") .. " S Q")
for _, g in ipairs(placed) do
  out[#out + 1] = ("\\rlap{\\kern%sbp\\raise%sbp\\hbox{\\pdfextension save"
    .. "\\pdfextension setmatrix{%s %s %s %s}\\rlap{\\kern%sbp\\char%d}\\pdfextension restore}}"):format(
    f4(g.x), f4(g.y), ("%.6f"):format(g.tx), ("%.6f"):format(g.ty),
    ("%.6f"):format(-g.ty), ("%.6f"):format(g.tx), f4(-g.w / 2), g.char)
end
out[#out + 1] = "\\hss}"
tex.sprint(table.concat(out))   -- one line: no spaces between the boxes
tex.print(("\\par The path is %.6fbp long; %d dashes, %d glyphs placed.\\par"):format(
  L, #p:dash({8, 3}), #placed))

-- What make luatex checks: the length, digit for digit, and each glyph.
local data = os.getenv("ARCLEN_DATA")
if data then
  local f = assert(io.open(data .. "-plain", "w"))
  f:write(("SVGLEN %.17g %s\n"):format(L, d))
  for _, g in ipairs(placed) do
    f:write(("SVGGLYPH %.17g %.17g %.17g %.17g %.17g\n"):format(g.s, g.x, g.y, g.tx, g.ty))
  end
  f:close()
end
