-- Henkel's six worked arcs (2014, section 6) across all methods, as
-- arclen.henkel reports them: every method within its own guarantee of the
-- 40-digit reference, the published table parsed correctly, his MetaPost
-- column reproduced digit for digit.
local arclen = require("arclen")
local H = require("helpers")
local henkel = require("arclen.repro.henkel")

local have_elliptic = false
for _, m in ipairs(arclen.methods()) do
  if m == "elliptic" then have_elliptic = true end
end

-- What each method guarantees on these arcs (relative): the adaptive ones
-- their tolerance (default 1e-12), the N = 10^6 rules their O(h^2) error,
-- MetaPost its absolute 1/4096-based test plus 2^-17 (~1e-5).
local BOUND = {
  gravesen = 1e-12, ["gravesen-richardson"] = 1e-12, gauss = 1e-12,
  elliptic = 1e-12, polyline = 1e-11, trapezoid = 1e-11,
  ["trapezoid-factored"] = 1e-11, metapost = 1e-5,
}

describe("henkel: the six tables", function()
  local all = henkel.rows()

  it("are six arcs of Henkel's seven rows (plus Richardson), in his order", function()
    assert.are.equal(6, #all)
    for k, a in ipairs(all) do
      assert.are.equal(#henkel.ROWS + #henkel.EXTRA, #a.rows)
      for i, r in ipairs(henkel.ROWS) do
        assert.are.equal(r.method, a.rows[i].method)
        assert.is_not_nil(a.rows[i].published, "arc " .. k .. " row " .. i)
      end
      assert.is_not_nil(a.ref)
    end
  end)

  it("the published data is Henkel's text: arc 1 Gravesen 18.355664405651 in 55493 steps", function()
    -- spot check of the parser (the values are read from the seed, not typed)
    local rows = H.tsv("henkel_published.tsv")
    assert.are.equal(42, #rows)
    assert.are.equal("18.355664405651", rows[1].value)
    assert.are.equal("55493", rows[1].steps)
    assert.are.equal("invalid arguments", rows[13].value)
  end)

  it("the arcs are the reference file's henkel family", function()
    local ref = H.curves("curves2d.tsv", "henkel")
    for k, a in ipairs(all) do
      assert.are.same(H.curve(ref[k]), a.curve)
    end
  end)

  it("every method is within its guarantee of the 40-digit reference", function()
    for k, a in ipairs(all) do
      for _, e in ipairs(a.rows) do
        if e.method ~= "elliptic" or have_elliptic then
          assert.is_not_nil(e.value, "arc " .. k .. " " .. e.method .. ": " .. tostring(e.failure))
          assert.is_true(e.err <= BOUND[e.method],
                         string.format("arc %d %s: %.3g", k, e.method, e.err))
        else
          assert.matches("not available yet", e.failure)
        end
      end
    end
  end)

  it("MetaPost: Henkel's column is mpost's double result cut to 12 decimals, on all six", function()
    for k, a in ipairs(all) do
      local e = a.rows[7]
      assert.are.equal("metapost", e.method)
      assert.are.equal("= mpost", e.flag, "arc " .. k)
    end
  end)

  it("elliptic, default and Gravesen agree with each other to their tolerances", function()
    for k, a in ipairs(all) do
      local v = {}
      for _, e in ipairs(a.rows) do v[e.method] = e.value end
      local L = tonumber(a.ref)
      local pairs_ = {{"gauss", "gravesen"}, {"gauss", "gravesen-richardson"}}
      if have_elliptic then
        pairs_[#pairs_ + 1] = {"elliptic", "gauss"}
        pairs_[#pairs_ + 1] = {"elliptic", "gravesen"}
      end
      for _, p in ipairs(pairs_) do
        local d = math.abs(v[p[1]] - v[p[2]]) / L
        assert.is_true(d <= BOUND[p[1]] + BOUND[p[2]],
                       string.format("arc %d %s vs %s: %.3g", k, p[1], p[2], d))
      end
    end
  end)

  it("where Henkel's published value is off (> 1e-10 from the reference), arclen's is 100x closer", function()
    local flagged = 0
    for _, a in ipairs(all) do
      for _, e in ipairs(a.rows) do
        if e.flag == "off" then
          flagged = flagged + 1
          if e.method ~= "elliptic" or have_elliptic then
            assert.is_true(e.err <= BOUND[e.method] and e.err < e.pub_err / 100,
                           e.method .. " " .. e.err)
          end
        end
      end
    end
    assert.is_true(flagged > 0)
  end)

  it("report() prints the six tables", function()
    local text = henkel.report()
    for k = 1, 6 do assert.matches("Arc " .. k, text) end
    for _, r in ipairs(henkel.ROWS) do assert.matches(r.label, text, 1, true) end
  end)
end)
