-- bench/svg/summary.lua -- the table of `make bench-svg` from its results
-- (peer, file, total, seconds[, measure seconds]) and the references.
local res = arg[1]
local ref = {}
for line in io.lines("spec/data/svg_refs.tsv") do
  local f, units, option, _, L = line:match("^([^\t#]+)\t([^\t]+)\t([^\t]+)\t([^\t]+)\t([^\t]+)")
  if f and units == "user" and option == "-" then ref["spec/data/svg/" .. f] = tonumber(L) end
end
-- svgelements measures in px (the root's viewBox mapped onto its width and
-- height): its reference is the user-unit one times arclen's px/user ratio.
local pxscale = {}
for line in io.lines(res) do
  local f, k = line:match("^px%-scale\t([^\t]+)\t([^\t]+)")
  if f then pxscale[f] = tonumber(k) end
end
local peers, order, why = {}, {}, {}
for line in io.lines(res) do
  local name, f, total, t, tm = line:match("^([^\t]+)\t([^\t]+)\t([^\t]+)\t([^\t]+)\t?([^\t]*)$")
  if name == "px-scale" then name = nil end
  if name then
    local p = peers[name]
    if not p then
      p = {name = name, files = 0, time = 0, read = 0, measure = 0, err = 0, skipped = 0, times = {}}
      peers[name] = p
      order[#order + 1] = name
    end
    local L = tonumber(total)
    if L then
      p.files = p.files + 1
      local secs = tonumber(t)
      if tm ~= "" then                  -- arclen: read and measure apart
        p.read = p.read + secs
        p.measure = p.measure + tonumber(tm)
        secs = secs + tonumber(tm)
      end
      p.time = p.time + secs
      p.times[f] = secs
      local R = ref[f] and ref[f] * (name:match("^svgelements") and pxscale[f] or 1)
      if R then p.err = math.max(p.err, math.abs(L - R) / R) end
      p.errs = p.errs or {}
      p.errs[f] = R and math.abs(L - R) / R
    else
      p.skipped = p.skipped + 1
      why[#why + 1] = ("  %s, %s: %s"):format(name, f:match("[^/]+$"), total)
    end
  end
end
local a = peers.arclen
if not a then print("no arclen results") os.exit(1) end
print(("%-34s %6s %12s %12s %12s  %s"):format("peer", "files", "seconds", "its/arclen's", "max rel err", "(worst file)"))
for _, name in ipairs(order) do
  local p = peers[name]
  local mine = 0                         -- arclen's time on the same files
  for f in pairs(p.times) do mine = mine + a.times[f] end
  local ratio = name == "arclen" and "1" or ("%.3g"):format(p.time / mine)
  local wf, we = "", -1
  for f, e in pairs(p.errs or {}) do if e and e > we then wf, we = f, e end end
  print(("%-34s %6d %12.4f %12s %12.2e  %s%s"):format(name, p.files, p.time, ratio, p.err,
    wf:match("[^/]+$") or "", p.skipped > 0 and ("; " .. p.skipped .. " files not measured") or ""))
end
for _, w in ipairs(why) do print(w) end
print(("arclen's split: reader (XML, transforms, path data) %.4f s, measuring %.4f s (reader/measuring %.2f)"):format(
  a.read, a.measure, a.read / a.measure))
