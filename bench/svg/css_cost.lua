-- bench/svg/css_cost.lua -- what a <style> sheet costs the reader: the same
-- document (N paths, each with a class) read with its sheet as CSS and with
-- the same bytes in a <style type="text/plain"> (not read as CSS), for
-- sheets of 1 to 1024 KB of Illustrator-style class rules (.stK{...}) and,
-- apart, of descendant selectors (#gK .stK path).  CPU seconds, best of 5;
-- the difference per KB of CSS.  Usage: lua5.4 bench/svg/css_cost.lua [N]
package.cpath = "build/5.4/?.so;" .. package.cpath
package.path = "lua/?.lua;lua/?/init.lua;" .. package.path
local svg = require("arclen.svg")
local N = tonumber(arg[1]) or 2000

local function sheet(kb, descendant)
  local t, size, k = {}, 0, 0
  while size < kb * 1024 do
    k = k + 1
    local r = descendant and ("#g%d .st%d path{stroke:#%06x;stroke-width:0.25}\n"):format(k, k, k)
              or (".st%d{fill:none;stroke:#%06x;stroke-width:0.25}\n"):format(k, k)
    t[#t + 1] = r
    size = size + #r
  end
  return table.concat(t), k
end

local function document(css, type, rules)
  local t = {'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><style type="', type,
             '">', css, '</style><g id="g1">'}
  for i = 1, N do
    t[#t + 1] = ('<path class="st%d" d="M0 0h1"/>'):format(i % rules + 1)
  end
  t[#t + 1] = "</g></svg>"
  return table.concat(t)
end

local function best(text)
  local b = math.huge
  for _ = 1, 5 do
    local t0 = os.clock()
    if not pcall(svg.parse, text, {measure = false}) then return nil end   -- the cap
    b = math.min(b, os.clock() - t0)
  end
  return b
end

print(("%d paths; CPU s best of 5"):format(N))
print("sheet\tKB\trules\tas CSS\tas text\tper KB (ms)")
for _, descendant in ipairs({false, true}) do
  for _, kb in ipairs({16, 64, 256, 1024}) do
    local css, rules = sheet(kb, descendant)
    local a = best(document(css, "text/css", rules))
    local b = best(document(css, "text/plain", rules))
    local kind = descendant and "descendant" or "class"
    if a then
      print(("%s\t%d\t%d\t%.4f\t%.4f\t%.4f"):format(kind, kb, rules, a, b, (a - b) / kb * 1000))
    else
      print(("%s\t%d\t%d\terror: the matching cap\t%.4f"):format(kind, kb, rules, b))
    end
  end
end
