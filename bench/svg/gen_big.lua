-- bench/svg/gen_big.lua -- generated documents for `make bench-svg` and
-- `make bench-svg-big` (never committed: the benchmark writes them into a
-- temporary directory).  Deterministic (a 32-bit LCG), '.' in any locale.
--   lua5.4 bench/svg/gen_big.lua KIND SIZE OUT.svg
-- KIND halftone: SIZE circles (r 0.2 .. 1) on a grid, as a stippled drawing;
--      plotter:  about SIZE MB of paths (lines and cubics) in groups under
--                translate/rotate/scale, in four Inkscape layers;
--      paths:    about SIZE MB of <path> elements at the root, no transforms.
-- Prints the number of drawn elements.
local kind, size, name = arg[1], tonumber(arg[2]), arg[3]
assert(kind and size and name, "usage: gen_big.lua halftone|plotter|paths SIZE OUT.svg")
local f = assert(io.open(name, "wb"))
local seed = 12345
local function rnd()                    -- in [0, 1): Numerical Recipes' LCG
  seed = (seed * 1664525 + 1013904223) % 4294967296
  return seed / 4294967296
end
-- numbers with 3 decimals, written without the locale's decimal point
local function num(x)
  local v = math.floor(x * 1000 + 0.5)
  local s = v < 0 and "-" or ""
  v = math.abs(v)
  return ("%s%d.%03d"):format(s, math.floor(v / 1000), v % 1000)
end
local buf, nbuf, bytes, count = {}, 0, 0, 0
local function put(s)
  nbuf = nbuf + 1
  buf[nbuf] = s
  bytes = bytes + #s
  if nbuf >= 4096 then f:write(table.concat(buf, "", 1, nbuf)) nbuf = 0 end
end
local function path_d(x, y, n)
  local t = {"M", num(x), num(y)}
  for _ = 1, n do
    if rnd() < 0.5 then
      x, y = x + 20 * rnd() - 10, y + 20 * rnd() - 10
      t[#t + 1] = "L" .. num(x) .. " " .. num(y)
    else
      local x1, y1 = x + 10 * rnd() - 5, y + 10 * rnd() - 5
      local x2, y2 = x + 20 * rnd() - 10, y + 20 * rnd() - 10
      x, y = x + 20 * rnd() - 10, y + 20 * rnd() - 10
      t[#t + 1] = "C" .. num(x1) .. " " .. num(y1) .. " " .. num(x2) .. " " .. num(y2) ..
        " " .. num(x) .. " " .. num(y)
    end
  end
  return table.concat(t, " ")
end
put('<?xml version="1.0" encoding="UTF-8"?>\n')
put('<svg xmlns="http://www.w3.org/2000/svg" ' ..
  'xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" ' ..
  'width="1000mm" height="1000mm" viewBox="0 0 1000 1000">\n')
if kind == "halftone" then
  put('<g stroke="black" fill="none">\n')
  local side = math.ceil(math.sqrt(size))
  for i = 0, size - 1 do
    local x, y = (i % side + 0.5) * 1000 / side, (math.floor(i / side) + 0.5) * 1000 / side
    put('<circle cx="' .. num(x) .. '" cy="' .. num(y) .. '" r="' .. num(0.2 + 0.8 * rnd()) .. '"/>\n')
    count = count + 1
  end
  put('</g>\n')
elseif kind == "plotter" or kind == "paths" then
  local target = size * 1e6
  local layer, group = 0, 0
  while bytes < target do
    if kind == "plotter" then
      if group % 250 == 0 then
        if layer > 0 then put('</g>\n') end
        layer = layer % 4 + 1
        put(('<g inkscape:groupmode="layer" inkscape:label="pen %d" stroke="black">\n'):format(layer))
      end
      group = group + 1
      put('<g transform="translate(' .. num(1000 * rnd()) .. ' ' .. num(1000 * rnd()) ..
        ') rotate(' .. num(360 * rnd()) .. ') scale(' .. num(0.5 + rnd()) .. ')">\n')
      for _ = 1, 100 do
        put('<path d="' .. path_d(100 * rnd(), 100 * rnd(), 4 + math.floor(8 * rnd())) .. '"/>\n')
        count = count + 1
      end
      put('</g>\n')
    else
      for _ = 1, 100 do
        put('<path d="' .. path_d(1000 * rnd(), 1000 * rnd(), 4 + math.floor(8 * rnd())) .. '"/>\n')
        count = count + 1
      end
    end
  end
  if kind == "plotter" and layer > 0 then put('</g>\n') end
else
  error("unknown kind " .. kind)
end
put('</svg>\n')
f:write(table.concat(buf, "", 1, nbuf))
f:close()
print(count)
