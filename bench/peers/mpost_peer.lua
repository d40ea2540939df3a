-- bench/peers/mpost_peer.lua -- MetaPost's arclength as a peer: one mpost
-- job (-numbersystem=double) measures every curve of the curves file
-- (kind, 8 coordinates, reference length; one a line) and prints the
-- lengths; a second job builds the same paths without measuring them.  The
-- time per call is the difference of the two wall-clock times over the
-- number of curves (mpost's start-up and parsing cancel), the errors come
-- from the printed lengths.  mpost reports arithmetic overflow for legs of
-- 16384 or more: such curves are counted, not measured.
--   lua5.4 bench/peers/mpost_peer.lua CURVES WORKDIR
local curves_file, dir = arg[1], arg[2] or "."

-- A decimal mpost can scan (it has no exponent notation), or nil when 99
-- decimals cannot hold the number's digits (|x| < 1e-80): such curves
-- cannot be written in MetaPost source and are counted, not measured.
local function num(x)
  local s = ("%.17g"):format(x)
  if not s:find("e") then return s end
  if x ~= 0 and math.abs(x) < 1e-80 then return nil end
  s = ("%.99f"):format(x):gsub("0+$", ""):gsub("%.$", "")
  return s
end

local curves = {}
for line in io.lines(curves_file) do
  local f = {}
  for w in line:gmatch("%S+") do f[#f + 1] = w end
  if #f >= 10 then
    local c = {}
    for i = 2, 9 do c[#c + 1] = tonumber(f[i]) end
    curves[#curves + 1] = {random = f[1] == "r", c = c, ref = tonumber(f[10])}
  end
end

local function job(name, measure)
  local src = dir .. "/" .. name .. ".mp"
  local out = assert(io.open(src, "w"))
  out:write("delimiters ();\npath p; numeric L;\n")
  for i, k in ipairs(curves) do
    local c, ok = {}, true
    for j = 1, 8 do
      c[j] = num(k.c[j])
      if not c[j] then ok, c[j] = false, "0" end
    end
    k.skip = not ok
    out:write(("p := (%s,%s)..controls (%s,%s) and (%s,%s)..(%s,%s);\n"):format(table.unpack(c)))
    if measure and ok then
      out:write(('L := arclength p; message "V %d " & decimal L;\n'):format(i))
    else
      out:write('L := 0;\n')
    end
  end
  out:write("end\n")
  out:close()
  local now = io.popen("date +%s.%N"):read("*l")
  os.execute(("cd %s && max_print_line=1000 mpost -ini -numbersystem=double " ..
              "-interaction=batchmode %s.mp >/dev/null 2>&1"):format(dir, name))
  local t = tonumber(io.popen("date +%s.%N"):read("*l")) - tonumber(now)
  local vals = {}
  local log = io.open(dir .. "/" .. name .. ".log")
  if log then
    for line in log:lines() do
      local i, v = line:match("^V (%d+) (%S+)")
      if i then vals[tonumber(i)] = tonumber(v) end
    end
    log:close()
  end
  return t, vals
end

local t_base = job("base", false)
local t_full, vals = job("full", true)
local er, ea, over, skipped = 0, 0, 0, 0
for i, k in ipairs(curves) do
  local L = vals[i]
  if k.skip then
    skipped = skipped + 1
  elseif L == nil or L > 8e307 then
    over = over + 1                -- "Arithmetic overflow" in mpost
  else
    local e = k.ref == 0 and math.abs(L) or math.abs(L - k.ref) / k.ref
    if e ~= e then e = math.huge end
    if k.random then er = math.max(er, e) else ea = math.max(ea, e) end
  end
end
local ns = (t_full - t_base) / #curves * 1e9
io.stderr:write(("mpost: %d curves, batch %.2f s, paths only %.2f s, %d overflowed, %d not writable (|coordinate| < 1e-80)\n")
  :format(#curves, t_full, t_base, over, skipped))
print(("MetaPost arclength, double (mpost, per call from a batch)\t%.1f\t%.3g\t%.3g")
  :format(ns, er, ea))
