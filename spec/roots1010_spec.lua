-- The 24 test quartics of Orellana & De Michele's Algorithm 1010 (ACM TOMS
-- 2020, Table 1): every root within the error attainable after the
-- coefficients are rounded to double (tools/ref_roots1010.py, mpmath).
local arclen = require("arclen")
local H = require("helpers")

local U = 2 ^ -53

-- All orderings of {1, 2, 3, 4}.
local function permutations(n)
  local out = {}
  local function gen(prefix, used)
    if #prefix == n then
      local copy = {}
      for i = 1, n do copy[i] = prefix[i] end
      out[#out + 1] = copy
      return
    end
    for i = 1, n do
      if not used[i] then
        used[i] = true
        prefix[#prefix + 1] = i
        gen(prefix, used)
        prefix[#prefix] = nil
        used[i] = false
      end
    end
  end
  gen({}, {})
  return out
end
local PERMS = permutations(4)

local cases, order = {}, {}
for _, row in ipairs((H.tsv("roots1010.tsv"))) do
  local k = tonumber(row.case)
  if not cases[k] then
    cases[k] = {coef = {tonumber(row.a4), tonumber(row.a3), tonumber(row.a2),
                        tonumber(row.a1), tonumber(row.a0)}, roots = {}}
    order[#order + 1] = k
  end
  table.insert(cases[k].roots, {tonumber(row.root_re), tonumber(row.root_im),
                                tonumber(row.bound)})
end

describe("Algorithm 1010's Table 1 quartics", function()
  it("has all 24 cases", function() assert.are.equal(24, #order) end)
  for _, k in ipairs(order) do
    local case = cases[k]
    it("case " .. k .. ": every root within the attainable error", function()
      local got = arclen.quartic(case.coef[1], case.coef[2], case.coef[3], case.coef[4], case.coef[5])
      assert.are.equal(4, #got)
      local best, worst_msg = math.huge, nil
      for _, p in ipairs(PERMS) do
        local excess, msg = 0, nil
        for i, want in ipairs(case.roots) do
          local g = got[p[i]]
          local err = math.sqrt((g[1] - want[1]) ^ 2 + (g[2] - want[2]) ^ 2)
          local allowed = want[3] + 4 * U * math.sqrt(want[1] ^ 2 + want[2] ^ 2)
          local ratio = err / allowed
          if ratio > excess then
            excess = ratio
            msg = ("root %.17g%+.17gi: got %.17g%+.17gi, error %.3g > %.3g"):format(
              want[1], want[2], g[1], g[2], err, allowed)
          end
        end
        if excess < best then best, worst_msg = excess, msg end
      end
      assert.is_true(best <= 1, worst_msg)
    end)
  end
end)
