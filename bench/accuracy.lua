-- bench/accuracy.lua -- the README's accuracy table: for each reference
-- family (spec/data/curves2d.tsv, curves3d.tsv, and the hard curves of
-- hard2d.tsv, hard3d.tsv: reversals, coincident points, near-cusps to 1e-15;
-- 40-digit
-- mpmath), the largest relative error of each method at t = 1/4, 1/2,
-- 3/4, 1.  Run: make accuracy
local arclen = require("arclen")
package.path = "spec/?.lua;" .. package.path
local H = require("helpers")

local methods = {
  {"gauss 1e-12", {tol = 1e-12}},
  {"gauss 1e-15", {tol = 1e-15}},
  {"elliptic", {method = "elliptic"}},
  {"gravesen-richardson 1e-12", {method = "gravesen-richardson", tol = 1e-12}},
}

local function available(name)
  for _, m in ipairs(arclen.methods()) do if m == name then return true end end
  return false
end

local function report(file)
  local rows = H.tsv(file)
  local order, by = {}, {}
  for _, row in ipairs(rows) do
    if not by[row.family] then
      by[row.family] = {}
      order[#order + 1] = row.family
    end
    table.insert(by[row.family], row)
  end
  local header = ("%-14s %5s"):format("family", "n")
  local active = {}
  for _, m in ipairs(methods) do
    if available(m[2].method or "gauss") then
      active[#active + 1] = m
      header = header .. ("  %26s"):format(m[1])
    end
  end
  print(file)
  print(header)
  for _, fam in ipairs(order) do
    local line = ("%-14s %5d"):format(fam, #by[fam])
    for _, m in ipairs(active) do
      local worst = 0
      for _, row in ipairs(by[fam]) do
        local c = H.curve(row)
        for _, p in ipairs({{0.25, "L25"}, {0.5, "L50"}, {0.75, "L75"}, {1, "L"}}) do
          local want = tonumber(row[p[2]])
          local opts = {t1 = p[1]}
          for k, v in pairs(m[2]) do opts[k] = v end
          local got = arclen.length(c, opts)
          local e = H.relerr(got, want)
          if e ~= e then e = math.huge end
          if e > worst then worst = e end
        end
      end
      line = line .. ("  %26.2e"):format(worst)
    end
    print(line)
  end
  print()
end

report("curves2d.tsv")
report("curves3d.tsv")
report("hard2d.tsv")
report("hard3d.tsv")
