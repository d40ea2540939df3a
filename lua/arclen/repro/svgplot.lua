-- arclen.repro.svgplot -- a small pure-Lua SVG plotting library (no dependencies).
--
-- A figure has one pair of axes (linear or log10 on each), ticks with
-- labels, a title, axis labels, a legend, and any number of items drawn in
-- data coordinates, clipped to the plot area:
--
--   local svg = require "arclen.repro.svgplot"
--   local fig = svg.figure{title = "s(t)", xlabel = "t", ylabel = "s/L",
--                          xrange = {0, 1}, yrange = {0, 1}}
--   fig:line({{0, 0}, {0.5, 0.4}, {1, 1}}, {label = "fit", color = "#d62728"})
--   fig:markers({{0.5, 0.4}}, {shape = "circle", size = 4})
--   fig:vline(0.69, {dash = "4 3", text = "inflexion"})
--   fig:bars(edges, counts, {label = "paper"})      -- histogram bars
--   local text = fig:render()                        -- the SVG document
--   svg.write("out.svg", text)
--
-- Figure options: width, height (pixels; 720 x 450), title, xlabel, ylabel,
-- xrange, yrange ({lo, hi}; default: the data's extent, widened to ticks),
-- xlog, ylog (log10 axes; values <= 0 are dropped), legend ("topleft",
-- "topright", "bottomleft", "bottomright" or false; default "topleft"),
-- font (px, 13).
-- Item styles: color, width (stroke px), dash (SVG dasharray, e.g. "4 3"),
-- opacity, label (enters the legend), and for markers shape ("circle",
-- "square", "diamond", "cross") and size (px); vline/hline take text
-- (written along the line's top/right end).
--
-- Shortcuts: svg.lineplot{title=, xlabel=, ylabel=, xrange=, yrange=,
-- xlog=, ylog=, series = {{label=, points={{x,y},...}, color=, dash=}, ...},
-- marks = {{x=, label=}, ...}} returns SVG text; svg.histogram(values,
-- {bins=, range=, log=}) returns edges, counts.

local numtext = require("arclen.numtext")   -- numbers in any locale
local M = {}

-- A colour-blind-safe cycle (Okabe & Ito 2008).
M.palette = {"#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00",
             "#56b4e9", "#000000", "#f0e442"}

local fmt = numtext.format
local floor = math.floor
-- math.log has no base argument in Lua 5.1 and LuaJIT; 5.4 has no log10.
local log10 = math.log10 or function(x) return math.log(x, 10) end

local function esc(s)
  return (tostring(s):gsub("[&<>\"]", {["&"] = "&amp;", ["<"] = "&lt;",
                                      [">"] = "&gt;", ['"'] = "&quot;"}))
end

-- Numbers in SVG attributes: short, no exponent.
local function num(v) return fmt("%.2f", v) end

-- Tick positions 1-2-5 times a power of ten covering [lo, hi].
local function linear_ticks(lo, hi, want)
  local span = hi - lo
  if span <= 0 then return {lo} end
  local raw = span / (want or 6)
  local p = 10 ^ floor(log10(raw))
  local step = p
  for _, m in ipairs{1, 2, 2.5, 5, 10} do
    if m * p >= raw then step = m * p; break end
  end
  local ticks, first = {}, math.ceil(lo / step - 1e-9)
  for k = first, first + 1000 do
    local v = k * step
    if v > hi + step * 1e-9 then break end
    if math.abs(v) < step * 1e-12 then v = 0 end
    ticks[#ticks + 1] = v
  end
  return ticks, step
end

local function log_ticks(lo, hi)
  local ticks = {}
  for e = math.floor(log10(lo) + 1e-9), math.ceil(log10(hi) - 1e-9) do
    local v = 10 ^ e
    if v >= lo * (1 - 1e-9) and v <= hi * (1 + 1e-9) then ticks[#ticks + 1] = v end
  end
  return ticks
end

local function tick_label(v, step, islog)
  if islog then
    local e = floor(log10(v) + 0.5)
    if e >= -2 and e <= 3 then return fmt("%g", v) end
    return fmt("1e%d", e)
  end
  if v == 0 then return "0" end
  local a = math.abs(v)
  if a >= 1e5 or a < 1e-3 then return fmt("%.3g", v) end
  local decimals = math.max(0, -floor(log10(step) + 1e-9))
  if step / 10 ^ -decimals ~= floor(step / 10 ^ -decimals) then
    decimals = decimals + 1   -- steps of 2.5
  end
  -- ("%d"): LuaJIT's math.max can return -0, which prints as "-0"
  return fmt("%." .. ("%d"):format(decimals) .. "f", v)
end

-- Widen [lo, hi] to tick marks (linear) or decades (log); fix empty ranges.
local function nice_range(lo, hi, islog)
  if islog then
    if not lo then return 0.1, 10 end
    if lo == hi then lo, hi = lo / 10, hi * 10 end
    return 10 ^ floor(log10(lo) + 1e-9), 10 ^ math.ceil(log10(hi) - 1e-9)
  end
  if not lo then return 0, 1 end
  if lo == hi then
    local d = lo == 0 and 1 or math.abs(lo) * 0.1
    lo, hi = lo - d, hi + d
  end
  local _, step = linear_ticks(lo, hi)
  return floor(lo / step + 1e-9) * step, math.ceil(hi / step - 1e-9) * step
end

local Figure = {}
Figure.__index = Figure

function M.figure(opts)
  opts = opts or {}
  local fig = setmetatable({
    width = opts.width or 720, height = opts.height or 450,
    title = opts.title, xlabel = opts.xlabel, ylabel = opts.ylabel,
    xrange = opts.xrange, yrange = opts.yrange,
    xlog = opts.xlog, ylog = opts.ylog, font = opts.font or 13,
    legend = opts.legend == nil and "topleft" or opts.legend,
    items = {}, ncolor = 0,
  }, Figure)
  return fig
end

local function next_color(fig, style)
  if style.color then return style.color end
  fig.ncolor = fig.ncolor + 1
  return M.palette[(fig.ncolor - 1) % #M.palette + 1]
end

-- Points as {{x, y}, ...} or as two arrays xs, ys.
local function as_points(a, b)
  if type(b) == "table" then
    local pts = {}
    for i = 1, math.min(#a, #b) do pts[i] = {a[i], b[i]} end
    return pts
  end
  return a
end

local function add(fig, kind, style, fields)
  style = style or {}
  local item = {kind = kind, style = style, color = next_color(fig, style)}
  for k, v in pairs(fields) do item[k] = v end
  fig.items[#fig.items + 1] = item
  return fig
end

function Figure:line(a, b, style)
  if type(b) ~= "table" or b[1] == nil then style, b = b, nil end
  return add(self, "line", style, {points = as_points(a, b)})
end

function Figure:markers(a, b, style)
  if type(b) ~= "table" or b[1] == nil then style, b = b, nil end
  return add(self, "markers", style, {points = as_points(a, b)})
end

function Figure:vline(x, style) return add(self, "vline", style, {x = x}) end
function Figure:hline(y, style) return add(self, "hline", style, {y = y}) end

-- Histogram bars: #edges == #counts + 1.
function Figure:bars(edges, counts, style)
  return add(self, "bars", style, {edges = edges, counts = counts})
end

function Figure:text(x, y, s, style)
  return add(self, "text", style, {x = x, y = y, s = s})
end

-- Bin values into bins equal bins over range (default: their extent), or
-- log-spaced bins when log is true (values <= 0 are left out).
function M.histogram(values, opts)
  opts = opts or {}
  local bins, lo, hi = opts.bins or 30, nil, nil
  for _, v in ipairs(values) do
    if v == v and (not opts.log or v > 0) then
      lo = (lo == nil or v < lo) and v or lo
      hi = (hi == nil or v > hi) and v or hi
    end
  end
  if opts.range then lo, hi = opts.range[1], opts.range[2] end
  lo, hi = lo or 0, hi or 1
  if hi <= lo then hi = lo + (lo == 0 and 1 or math.abs(lo)) end
  local edges, counts = {}, {}
  for i = 0, bins do
    edges[i + 1] = opts.log and 10 ^ (log10(lo) + (log10(hi) - log10(lo)) * i / bins)
                   or lo + (hi - lo) * i / bins
    if i < bins then counts[i + 1] = 0 end
  end
  for _, v in ipairs(values) do
    if v == v and v >= lo and v <= hi and (not opts.log or v > 0) then
      local u = opts.log and (log10(v) - log10(lo)) / (log10(hi) - log10(lo))
                or (v - lo) / (hi - lo)
      local i = math.min(bins, floor(u * bins) + 1)
      counts[i] = counts[i] + 1
    end
  end
  return edges, counts
end

-- The data extent of the items, per axis, skipping what a log axis cannot show.
local function extent(fig)
  local xlo, xhi, ylo, yhi
  local function seex(x)
    if x == x and math.abs(x) < math.huge and (not fig.xlog or x > 0) then
      xlo = (xlo == nil or x < xlo) and x or xlo
      xhi = (xhi == nil or x > xhi) and x or xhi
    end
  end
  local function seey(y)
    if y == y and math.abs(y) < math.huge and (not fig.ylog or y > 0) then
      ylo = (ylo == nil or y < ylo) and y or ylo
      yhi = (yhi == nil or y > yhi) and y or yhi
    end
  end
  for _, it in ipairs(fig.items) do
    if it.points then
      for _, p in ipairs(it.points) do seex(p[1]); seey(p[2]) end
    elseif it.kind == "vline" then seex(it.x)
    elseif it.kind == "hline" then seey(it.y)
    elseif it.kind == "bars" then
      seex(it.edges[1]); seex(it.edges[#it.edges])
      for _, c in ipairs(it.counts) do seey(c) end
      if not fig.ylog then seey(0) end
    elseif it.kind == "text" then seex(it.x); seey(it.y)
    end
  end
  return xlo, xhi, ylo, yhi
end

local function stroke(it)
  local s = it.style
  return fmt('stroke="%s" stroke-width="%s"%s%s', it.color, num(s.width or 1.6),
             s.dash and fmt(' stroke-dasharray="%s"', s.dash) or "",
             s.opacity and fmt(' stroke-opacity="%s"', num(s.opacity)) or "")
end

local function marker(out, shape, x, y, r, color)
  if shape == "square" then
    out[#out + 1] = fmt('<rect x="%s" y="%s" width="%s" height="%s" fill="%s"/>',
                        num(x - r), num(y - r), num(2 * r), num(2 * r), color)
  elseif shape == "diamond" then
    out[#out + 1] = fmt('<path d="M%s %sL%s %sL%s %sL%s %sZ" fill="%s"/>',
                        num(x), num(y - r), num(x + r), num(y), num(x),
                        num(y + r), num(x - r), num(y), color)
  elseif shape == "cross" then
    out[#out + 1] = fmt('<path d="M%s %sL%s %sM%s %sL%s %s" stroke="%s" stroke-width="1.5"/>',
                        num(x - r), num(y - r), num(x + r), num(y + r),
                        num(x - r), num(y + r), num(x + r), num(y - r), color)
  else
    out[#out + 1] = fmt('<circle cx="%s" cy="%s" r="%s" fill="%s"/>',
                        num(x), num(y), num(r), color)
  end
end

function Figure:render()
  local W, H, fs = self.width, self.height, self.font
  local left, right = 70, 30
  local top, bottom = self.title and 40 or 16, self.xlabel and 52 or 34
  local pw, ph = W - left - right, H - top - bottom
  local xlo, xhi, ylo, yhi = extent(self)
  if self.xrange then xlo, xhi = self.xrange[1], self.xrange[2]
  else xlo, xhi = nice_range(xlo, xhi, self.xlog) end
  if self.yrange then ylo, yhi = self.yrange[1], self.yrange[2]
  else ylo, yhi = nice_range(ylo, yhi, self.ylog) end
  local fx = self.xlog and log10 or function(v) return v end
  local fy = self.ylog and log10 or function(v) return v end
  local X0, X1, Y0, Y1 = fx(xlo), fx(xhi), fy(ylo), fy(yhi)
  local function px(x) return left + (fx(x) - X0) / (X1 - X0) * pw end
  local function py(y) return top + ph - (fy(y) - Y0) / (Y1 - Y0) * ph end
  local function okx(x) return x == x and (not self.xlog or x > 0) end
  local function oky(y) return y == y and (not self.ylog or y > 0) end

  local out = {}
  out[1] = fmt('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" ' ..
               'viewBox="0 0 %d %d" font-family="DejaVu Sans, Helvetica, Arial, sans-serif" ' ..
               'font-size="%d">', W, H, W, H, fs)
  out[#out + 1] = fmt('<rect width="%d" height="%d" fill="white"/>', W, H)
  out[#out + 1] = fmt('<defs><clipPath id="plotarea"><rect x="%s" y="%s" ' ..
                      'width="%s" height="%s"/></clipPath></defs>',
                      num(left), num(top), num(pw), num(ph))
  -- Grid and ticks.
  local xt, xstep, yt, ystep
  if self.xlog then xt = log_ticks(xlo, xhi) else xt, xstep = linear_ticks(xlo, xhi) end
  if self.ylog then yt = log_ticks(ylo, yhi) else yt, ystep = linear_ticks(ylo, yhi) end
  for _, v in ipairs(xt) do
    local x = px(v)
    out[#out + 1] = fmt('<line x1="%s" y1="%s" x2="%s" y2="%s" stroke="#e5e5e5"/>',
                        num(x), num(top), num(x), num(top + ph))
    out[#out + 1] = fmt('<line x1="%s" y1="%s" x2="%s" y2="%s" stroke="#333"/>',
                        num(x), num(top + ph), num(x), num(top + ph + 5))
    out[#out + 1] = fmt('<text x="%s" y="%s" text-anchor="middle">%s</text>',
                        num(x), num(top + ph + 8 + fs), esc(tick_label(v, xstep, self.xlog)))
  end
  for _, v in ipairs(yt) do
    local y = py(v)
    out[#out + 1] = fmt('<line x1="%s" y1="%s" x2="%s" y2="%s" stroke="#e5e5e5"/>',
                        num(left), num(y), num(left + pw), num(y))
    out[#out + 1] = fmt('<line x1="%s" y1="%s" x2="%s" y2="%s" stroke="#333"/>',
                        num(left - 5), num(y), num(left), num(y))
    out[#out + 1] = fmt('<text x="%s" y="%s" text-anchor="end">%s</text>',
                        num(left - 8), num(y + fs * 0.35), esc(tick_label(v, ystep, self.ylog)))
  end
  -- Items, clipped to the plot area.
  out[#out + 1] = '<g clip-path="url(#plotarea)">'
  for _, it in ipairs(self.items) do
    local s = it.style
    if it.kind == "line" then
      local d, pen = {}, "M"
      for _, p in ipairs(it.points) do
        if okx(p[1]) and oky(p[2]) then
          d[#d + 1] = pen .. num(px(p[1])) .. " " .. num(py(p[2]))
          pen = "L"
        else
          pen = "M"   -- a gap where the value cannot be shown
        end
      end
      if #d > 0 then
        out[#out + 1] = fmt('<path d="%s" fill="none" %s stroke-linejoin="round"/>',
                            table.concat(d), stroke(it))
      end
    elseif it.kind == "markers" then
      for _, p in ipairs(it.points) do
        if okx(p[1]) and oky(p[2]) then
          marker(out, s.shape, px(p[1]), py(p[2]), s.size or 3.5, it.color)
        end
      end
    elseif it.kind == "vline" and okx(it.x) then
      out[#out + 1] = fmt('<line x1="%s" y1="%s" x2="%s" y2="%s" %s/>', num(px(it.x)),
                          num(top), num(px(it.x)), num(top + ph), stroke(it))
      if s.text then
        out[#out + 1] = fmt('<text x="%s" y="%s" fill="%s" font-size="%d" ' ..
                            'transform="rotate(-90 %s %s)" text-anchor="end">%s</text>',
                            num(px(it.x) - 4), num(top + 4), it.color, fs - 2,
                            num(px(it.x) - 4), num(top + 4), esc(s.text))
      end
    elseif it.kind == "hline" and oky(it.y) then
      out[#out + 1] = fmt('<line x1="%s" y1="%s" x2="%s" y2="%s" %s/>', num(left),
                          num(py(it.y)), num(left + pw), num(py(it.y)), stroke(it))
      if s.text then
        out[#out + 1] = fmt('<text x="%s" y="%s" fill="%s" font-size="%d" ' ..
                            'text-anchor="end">%s</text>', num(left + pw - 4),
                            num(py(it.y) - 4), it.color, fs - 2, esc(s.text))
      end
    elseif it.kind == "bars" then
      local base = self.ylog and ylo or math.max(ylo, 0)
      for i, c in ipairs(it.counts) do
        local a, b = it.edges[i], it.edges[i + 1]
        if c > 0 and okx(a) and okx(b) and oky(c) then
          local x0, x1, y = px(a), px(b), py(c)
          out[#out + 1] = fmt('<rect x="%s" y="%s" width="%s" height="%s" fill="%s" ' ..
                              'fill-opacity="%s" stroke="%s" stroke-width="0.6"/>',
                              num(x0), num(y), num(math.max(x1 - x0, 0.5)),
                              num(math.max(py(base) - y, 0)), it.color,
                              num(s.opacity or 0.55), it.color)
        end
      end
    elseif it.kind == "text" and okx(it.x) and oky(it.y) then
      out[#out + 1] = fmt('<text x="%s" y="%s" fill="%s"%s>%s</text>', num(px(it.x)),
                          num(py(it.y)), s.color or "#333",
                          s.anchor and fmt(' text-anchor="%s"', s.anchor) or "",
                          esc(it.s))
    end
  end
  out[#out + 1] = '</g>'
  -- Frame, title and axis labels.
  out[#out + 1] = fmt('<rect x="%s" y="%s" width="%s" height="%s" fill="none" stroke="#333"/>',
                      num(left), num(top), num(pw), num(ph))
  if self.title then
    out[#out + 1] = fmt('<text x="%s" y="%s" text-anchor="middle" font-size="%d" ' ..
                        'font-weight="bold">%s</text>', num(left + pw / 2), 24, fs + 2,
                        esc(self.title))
  end
  if self.xlabel then
    out[#out + 1] = fmt('<text x="%s" y="%s" text-anchor="middle">%s</text>',
                        num(left + pw / 2), num(H - 12), esc(self.xlabel))
  end
  if self.ylabel then
    out[#out + 1] = fmt('<text x="16" y="%s" text-anchor="middle" ' ..
                        'transform="rotate(-90 16 %s)">%s</text>', num(top + ph / 2),
                        num(top + ph / 2), esc(self.ylabel))
  end
  -- Legend: one row per labelled item.
  local rows = {}
  for _, it in ipairs(self.items) do
    if it.style.label then rows[#rows + 1] = it end
  end
  if self.legend and #rows > 0 then
    local lw = 0
    for _, it in ipairs(rows) do lw = math.max(lw, #it.style.label) end
    local bw, bh = 40 + lw * fs * 0.58, #rows * (fs + 6) + 8
    local corner = self.legend
    local bx = corner:find("right") and left + pw - bw - 8 or left + 8
    local by = corner:find("bottom") and top + ph - bh - 8 or top + 8
    out[#out + 1] = fmt('<rect x="%s" y="%s" width="%s" height="%s" fill="white" ' ..
                        'fill-opacity="0.88" stroke="#999"/>', num(bx), num(by), num(bw), num(bh))
    for i, it in ipairs(rows) do
      local y = by + 4 + (i - 0.5) * (fs + 6)
      if it.kind == "markers" then
        marker(out, it.style.shape, bx + 18, y, it.style.size or 3.5, it.color)
      elseif it.kind == "bars" then
        out[#out + 1] = fmt('<rect x="%s" y="%s" width="20" height="10" fill="%s" ' ..
                            'fill-opacity="%s"/>', num(bx + 8), num(y - 5), it.color,
                            num(it.style.opacity or 0.55))
      else
        out[#out + 1] = fmt('<line x1="%s" y1="%s" x2="%s" y2="%s" %s/>', num(bx + 6),
                            num(y), num(bx + 30), num(y), stroke(it))
      end
      out[#out + 1] = fmt('<text x="%s" y="%s">%s</text>', num(bx + 36),
                          num(y + fs * 0.35), esc(it.style.label))
    end
  end
  out[#out + 1] = '</svg>\n'
  return table.concat(out, "\n")
end

-- One call for the common case: labelled series of {x, y} points and
-- labelled vertical marks.
function M.lineplot(o)
  local fig = M.figure(o)
  for _, s in ipairs(o.series or {}) do
    fig:line(s.points, {label = s.label, color = s.color, dash = s.dash, width = s.width})
  end
  for _, m in ipairs(o.marks or {}) do
    fig:vline(m.x, {text = m.label, color = m.color or "#777", dash = m.dash or "4 3", width = 1})
  end
  return fig:render()
end

function M.write(path, text)
  local f = assert(io.open(path, "w"))
  f:write(text)
  f:close()
  return path
end

return M
