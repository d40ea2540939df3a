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

-- Quartics with exact double coefficients (tools/ref_roots_exact.py): root
-- spreads 10^2 .. 10^12, conjugate pairs beside far reals, close real pairs and
-- close pairs of conjugate pairs (splits 2^-4 .. 2^-20), Algorithm 1010's
-- case 8 and variants.  The roots are those of the coefficients as given, so
-- the bound is what a residual in double-double guarantees (the column:
-- 6 u |r| + 8 n u^2 sum |a_k| |r|^k / |p'(r)|), not the double-rounded
-- coefficients' condition.  quartic_factor's factors must multiply out to a
-- pairing of the true roots within 4 u of each coefficient's terms.
describe("quartics with exact coefficients (roots_exact.tsv)", function()
  local cases, ids = {}, {}
  for _, row in ipairs((H.tsv("roots_exact.tsv"))) do
    if not cases[row.id] then
      cases[row.id] = {coef = {tonumber(row.a4), tonumber(row.a3), tonumber(row.a2),
                               tonumber(row.a1), tonumber(row.a0)}, roots = {}}
      ids[#ids + 1] = row.id
    end
    table.insert(cases[row.id].roots, {tonumber(row.root_re), tonumber(row.root_im),
                                       tonumber(row.bound)})
  end
  it("has the four families", function() assert.is_true(#ids >= 80) end)
  for _, id in ipairs(ids) do
    local case = cases[id]
    it(id .. ": roots within the double-double bound", function()
      local got = arclen.quartic(table.unpack(case.coef))
      assert.are.equal(4, #got)
      local used = {}
      for _, want in ipairs(case.roots) do
        local best, bi = math.huge, nil
        for j, g in ipairs(got) do
          local e = math.sqrt((g[1] - want[1]) ^ 2 + (g[2] - want[2]) ^ 2)
          if not used[j] and e < best then best, bi = e, j end
        end
        used[bi] = true
        assert.is_true(best <= want[3], ("root %.17g%+.17gi: error %.3g > %.3g"):format(
          want[1], want[2], best, want[3]))
      end
    end)
    it(id .. ": quartic_factor's factors are a pairing of the true roots", function()
      local q = {arclen.quartic_factor(table.unpack(case.coef))}
      local r = case.roots
      local best = math.huge
      for _, pr in ipairs({{1, 2, 3, 4}, {1, 3, 2, 4}, {1, 4, 2, 3}}) do
        local excess = 0
        for f = 0, 1 do
          local a, b = r[pr[2 * f + 1]], r[pr[2 * f + 2]]
          -- (x - a)(x - b) = x^2 - (a + b) x + a b, real for a pairing that
          -- keeps conjugates together (the others are not real: skipped)
          local sr, si = a[1] + b[1], a[2] + b[2]
          local pr_, pi_ = a[1] * b[1] - a[2] * b[2], a[1] * b[2] + a[2] * b[1]
          if si ~= 0 or pi_ ~= 0 then excess = math.huge break end
          local best_f = math.huge
          for g = 0, 1 do
            local e1 = math.abs(q[2 * g + 1] + sr) / (4 * U * (math.abs(a[1]) + math.abs(b[1])) + 1e-300)
            local e2 = math.abs(q[2 * g + 2] - pr_) /
              (4 * U * (math.abs(a[1] * b[1]) + math.abs(a[2] * b[2])) + 1e-300)
            best_f = math.min(best_f, math.max(e1, e2))
          end
          excess = math.max(excess, best_f)
        end
        best = math.min(best, excess)
      end
      assert.is_true(best <= 1, ("factors %.17g %.17g %.17g %.17g: %.3g x the bound"):format(
        q[1], q[2], q[3], q[4], best))
    end)
  end
end)
