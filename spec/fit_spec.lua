-- spec/fit_spec.lua -- the length-versus-t fits: Walter &
-- Fournier's method reproduced, the default Hermite fit's bounds, the
-- inverse, monotonicity, and bad input.  References: spec/data/
-- lenfit_published.tsv (parsed from the seed), lenfit_worst.tsv and
-- gauss_legendre.tsv (mpmath, 40 digits) by tools/ref_lenfit.py.
local arclen = require "arclen"
local helpers = require "helpers"
local fitstats = require "arclen.repro.fitstats"

local EPS = 2 ^ -52

local function keyed(name)
  local out = {}
  for _, r in ipairs((helpers.tsv(name))) do
    out[r.what] = out[r.what] or {}
    out[r.what][r.key] = r.value
  end
  return out
end

local published = keyed("lenfit_published.tsv")
local worstref = keyed("lenfit_worst.tsv")
local WORST = {}
for i = 1, 8 do WORST[i] = tonumber(published.worst_curve["c" .. i]) end

-- The paper's random set (Table 1): 3000 curves, NR ran1, fixed seed.
local RANDOM = fitstats.random_set(3000, 1)

describe("arclen.gauss_legendre", function()
  it("matches mpmath's rules: nodes to 1 ulp, weights to their conditioning", function()
    -- A node x in [-1, 1] is stored to eps/2 absolute; the weight
    -- 2/((1-x^2) P_n'^2) moves by ~ 4/(1-x^2) times that, plus the
    -- recurrence's ~n rounding errors.
    for _, r in ipairs((helpers.tsv("gauss_legendre.tsv"))) do
      local n, i = tonumber(r.n), tonumber(r.i)
      local x, w = arclen.gauss_legendre(n)
      local node, weight = tonumber(r.node), tonumber(r.weight)
      assert.is_true(math.abs(x[i] - node) <= EPS,
                     ("n=%d i=%d node off by %g"):format(n, i, x[i] - node))
      local one_minus_x2 = 4 * node * (1 - node)
      local bound = EPS * (4 / one_minus_x2 + 2 * n)
      assert.is_true(math.abs(w[i] - weight) / weight <= bound,
                     ("n=%d i=%d weight rel err %g > %g"):format(n, i,
                       math.abs(w[i] - weight) / weight, bound))
    end
  end)

  it("integrates t^k exactly for k <= 2n - 1 (n = 1..64)", function()
    for n = 1, 64 do
      local x, w = arclen.gauss_legendre(n)
      for k = 0, 2 * n - 1 do
        local s = 0
        for i = 1, n do s = s + w[i] * x[i] ^ k end
        assert.is_true(math.abs(s - 1 / (k + 1)) <= 4 * n * EPS,
                       ("n=%d k=%d: %g"):format(n, k, s - 1 / (k + 1)))
      end
    end
  end)
end)

describe("method 'paper' on the paper's worst curve", function()
  local fit = arclen.fit(WORST, {method = "paper", n = 10})

  it("finds its one inflexion point and uses one span, 3 rules of 10 points", function()
    assert.are.equal(1, #fit.critical)
    assert.is_true(math.abs(fit.critical[1] - tonumber(worstref.critical["1"])) <= 1e-12)
    assert.are.equal(1, fit.nspans)
    assert.are.equal(30, fit.evals)
  end)

  it("has mpmath's ordinates (Eqns 4-5 on 10-point lengths) and total", function()
    local y = fit:spans()[1].y
    for i = 0, 3 do
      assert.is_true(math.abs(y[i + 1] - tonumber(worstref.paper10_y[tostring(i)])) <= 1e-14)
    end
    assert.is_true(helpers.relerr(fit.total, tonumber(worstref.paper10_total["0"])) <= 1e-14)
  end)

  it("reproduces the published max error 0.087392 with the paper's qsimp truth", function()
    local max = fit:errors{truth = "simpson"}
    -- Table 1 prints 6 decimals: within half a unit of the last one.
    assert.is_true(math.abs(max - tonumber(published.table1_random.max)) <= 5e-7,
                   "max " .. max)
  end)

  it("gives mpmath's 0.0873625... against the exact length", function()
    local max, mean = fit:errors{truth = "exact"}
    -- The truth is good to ~1e-13 relative; the fit's ordinates to 1e-14.
    assert.is_true(math.abs(max - tonumber(worstref.paper10_err.max)) <= 1e-12)
    assert.is_true(math.abs(mean - tonumber(worstref.paper10_err.mean)) <= 1e-12)
  end)
end)

describe("method 'paper' on the random set (3000 curves, ran1 seed 1)", function()
  -- Independent random sets land in these ranges (doc/papers.md);
  -- the published row is 0.087392 / 0.019202 / 0.007405.
  local r10 = fitstats.stats(RANDOM, {method = "paper", n = 10}, {truth = "simpson"})
  local r3 = fitstats.stats(RANDOM, {method = "paper", n = 3}, {truth = "simpson"})

  it("n = 10: max, avg of max, avg of averages inside the reproduction ranges", function()
    assert.is_true(r10.max >= 0.0815 and r10.max <= 0.0918, "max " .. r10.max)
    assert.is_true(r10.avgmax >= 0.0190 and r10.avgmax <= 0.0199, "avgmax " .. r10.avgmax)
    assert.is_true(r10.avgavg >= 0.0073 and r10.avgavg <= 0.0077, "avgavg " .. r10.avgavg)
  end)

  it("n = 10 costs 30 or 60 speed evaluations; n = 3 costs 9 or 18 and errs more", function()
    assert.is_true(r10.evals >= 30 and r10.evals <= 60)
    assert.is_true(r3.evals >= 9 and r3.evals <= 18)
    assert.is_true(r3.avgmax > r10.avgmax and r3.avgavg > r10.avgavg)
  end)

  it("is not always monotone (the paper's caveat; about 1.2% of fits)", function()
    local share = r10.nonmono / r10.curves
    assert.is_true(share > 0.005 and share < 0.025, "non-monotone share " .. share)
  end)

  it("monotone = true projects every span onto the monotone set, least squares", function()
    local rm = fitstats.stats(RANDOM, {method = "paper", n = 10, monotone = true},
                              {truth = "simpson"})
    assert.are.equal(0, rm.nonmono)
    assert.are.equal(r10.evals, rm.evals)
    assert.is_true(rm.max <= r10.max + 1e-12 and rm.avgmax <= r10.avgmax)
    -- Against a brute-force scan of the feasible (d0, d2) grid: the
    -- projection is feasible and at least as close as every grid point.
    local G = 200
    local function check(c, n, curved_only)
      local raw = arclen.fit(c, {method = "paper", n = n})
      if raw:monotone() then return 0 end
      local proj = arclen.fit(c, {method = "paper", n = n, monotone = true})
      local rs, ps, checked = raw:spans(), proj:spans(), 0
      for i, sp in ipairs(rs) do
        local y, q = sp.y, ps[i].y
        assert.are.equal(y[1], q[1]); assert.are.equal(y[4], q[4])
        local D, p0, p2 = y[4] - y[1], y[2] - y[1], y[4] - y[3]
        if not sp.monotone and (not curved_only or (p0 > 0 and p2 > 0)) then
          local got = math.sqrt((q[2] - y[2]) ^ 2 + (q[3] - y[3]) ^ 2)
          local best = math.huge
          for a = 0, G do
            for b = 0, G do
              local d0, d2 = D * a / G, D * b / G
              local d1 = D - d0 - d2
              if d1 >= 0 or d1 * d1 <= d0 * d2 then
                best = math.min(best, (d0 - p0) ^ 2 + (d2 - p2) ^ 2)
              end
            end
          end
          best = math.sqrt(best)
          assert.is_true(got <= best + 1e-12, ("projection %g > grid %g"):format(got, best))
          assert.is_true(ps[i].monotone)
          checked = checked + 1
        end
      end
      return checked
    end
    local checked = 0
    for _, c in ipairs(RANDOM) do checked = checked + check(c, 10) end
    assert.is_true(checked >= 30)
    -- Spans below the curved part of the boundary (d0, d2 > 0, d1 too
    -- negative) are rarer: about 1 in 2500 n = 3 fits.
    local curved = 0
    for _, c in ipairs(fitstats.random_set(30000, 7)) do curved = curved + check(c, 3, true) end
    assert.is_true(curved >= 5)
  end)

  it("splits as Sec. 3.4 says: mean of two roots, middle of three", function()
    local seen = {}
    for _, c in ipairs(RANDOM) do
      local f = arclen.fit(c, {method = "paper", n = 3})
      local crit, spans = f.critical, f:spans()
      if #crit <= 1 then
        assert.are.equal(1, #spans)
      else
        assert.are.equal(2, #spans)
        local want = #crit == 2 and (crit[1] + crit[2]) / 2 or crit[2]
        assert.is_true(math.abs(spans[1].t1 - want) <= 1e-15)
      end
      seen[#crit] = true
    end
    assert.is_true(seen[0] and seen[1] and seen[2] and seen[3])
  end)
end)

describe("the default method 'hermite'", function()
  local paper = fitstats.stats(RANDOM, {method = "paper", n = 10}, {truth = "exact"})
  local herm = fitstats.stats(RANDOM, {}, {truth = "exact"})
  local inv = fitstats.stats(RANDOM, {}, {truth = "exact", inverse = true})

  it("is the default", function()
    assert.are.equal("hermite", arclen.fit(WORST).method)
  end)

  it("on the random set: max <= 0.01, avg of max <= 0.002, fewer evaluations than the paper", function()
    assert.is_true(herm.max <= 0.01, "max " .. herm.max)
    assert.is_true(herm.avgmax <= 0.002, "avgmax " .. herm.avgmax)
    assert.is_true(herm.evals <= paper.evals, herm.evals .. " > " .. paper.evals)
    assert.are.equal(0, herm.failed)
  end)

  it("its inverse t(s) has s-errors within the same bounds", function()
    assert.is_true(inv.max <= 0.01, "max " .. inv.max)
    assert.is_true(inv.avgmax <= 0.002, "avgmax " .. inv.avgmax)
  end)

  it("is monotone on every random curve and every font curve", function()
    assert.are.equal(0, herm.nonmono)
    for _, font in ipairs(fitstats.font_sets()) do
      for _, c in ipairs(font.curves) do
        local f = arclen.fit(c)
        assert.is_true(f:monotone(), font.name .. ": " .. table.concat(c, " "))
      end
    end
  end)

  it("stays within its bounds between the grid points too (401 points, 300 curves)", function()
    for i = 1, 300 do
      local max = arclen.fit(RANDOM[i]):errors{truth = "exact", npts = 400}
      assert.is_true(max <= 0.01, "curve " .. i .. ": " .. max)
    end
  end)

  it("with tol = 1e-4: max <= 1e-4 on the random set, forward and inverse", function()
    local r = fitstats.stats(RANDOM, {tol = 1e-4}, {truth = "exact"})
    local ri = fitstats.stats(RANDOM, {tol = 1e-4}, {truth = "exact", inverse = true})
    assert.are.equal(0, r.failed)
    assert.is_true(r.max <= 1e-4, "max " .. r.max)
    assert.is_true(ri.max <= 1e-4, "inverse max " .. ri.max)
    assert.are.equal(0, r.nonmono)
  end)

  it("honours tol between the grid points and at tighter tolerances", function()
    for _, tol in ipairs{1e-3, 1e-4, 1e-6, 1e-8} do
      for i = 1, 60 do
        local f = assert(arclen.fit(RANDOM[i], {tol = tol}))
        local max = f:errors{truth = "exact", npts = 400}
        assert.is_true(max <= tol, ("tol %g curve %d: %g"):format(tol, i, max))
        assert.is_true(f:monotone())
      end
    end
  end)
end)

describe("fit objects", function()
  local fit = arclen.fit(WORST)

  it("evaluate in O(1): no integrand evaluations after construction", function()
    local evals = fit.evals
    for k = 0, 1000 do fit:length(k / 1000); fit:time(fit.total * k / 1000) end
    assert.are.equal(evals, fit.evals)
  end)

  it("have spans covering [0, 1] continuously from 0 to 1", function()
    for _, c in ipairs({WORST, RANDOM[7], RANDOM[8]}) do
      for _, m in ipairs({"paper", "hermite"}) do
        local spans = arclen.fit(c, {method = m}):spans()
        assert.are.equal(0, spans[1].t0)
        assert.are.equal(0, spans[1].y[1])
        assert.are.equal(1, spans[#spans].t1)
        assert.are.equal(1, spans[#spans].y[4])
        for i = 2, #spans do
          assert.are.equal(spans[i - 1].t1, spans[i].t0)
          assert.are.equal(spans[i - 1].y[4], spans[i].y[1])
        end
      end
    end
  end)

  it("length(t) is total * value(t), ends exact", function()
    assert.are.equal(0, fit:length(0))
    assert.are.equal(fit.total, fit:length(1))
    assert.are.equal(fit.total * fit:value(0.3), fit:length(0.3))
  end)

  it("invert themselves: time(length(t)) = t and length(time(s)) = s", function()
    for i = 1, 200 do
      local f = arclen.fit(RANDOM[i])
      for k = 0, 20 do
        local s = f.total * k / 20
        assert.is_true(math.abs(f:length(f:time(s)) - s) <= 1e-13 * f.total)
        local t = k / 20
        -- t from s is as well-conditioned as the fit's slope allows.
        local dt = math.abs(f:time(f:length(t)) - t)
        assert.is_true(dt <= 1e-9, ("curve %d t %g: %g"):format(i, t, dt))
      end
    end
    assert.are.equal(0, fit:time(0))
    assert.are.equal(0, fit:time(-5))
    assert.are.equal(1, fit:time(fit.total))
    assert.are.equal(1, fit:time(2 * fit.total))
  end)

  it("have fields and a readable tostring", function()
    assert.are.equal(2, fit.dim)
    assert.are.equal("hermite", fit.method)
    assert.are.equal(8, #fit.curve)
    assert.are.equal(fit.nspans, #fit:spans())
    assert.is_truthy(tostring(fit):match("^arclen%.fit%(hermite, %d+ spans, total "))
    assert.is_nil(fit.nonsense)
  end)
end)

describe("awkward curves", function()
  it("a cusp (speed 0 at t = 1/2) is fitted monotone and within bounds", function()
    local c = {0, 0, 1, 1, -1, 1, 2, 0}   -- P2 = P0 + P1 - P3: Q'(1/2) = 0
    local f = arclen.fit(c)
    local near = false
    for _, t in ipairs(f.critical) do near = near or math.abs(t - 0.5) <= 1e-12 end
    assert.is_true(near, "the cusp is a critical point of the speed")
    assert.is_true(f:monotone())
    assert.is_true(f:errors{truth = "exact", npts = 400} <= 0.01)
    assert.is_true(arclen.fit(c, {tol = 1e-6}):errors{truth = "exact", npts = 400} <= 1e-6)
  end)

  it("a line that doubles back (speed 0 twice) is monotone and within tol", function()
    local c = {0, 0, 3, 0, -1, 0, 2, 0}
    local f = arclen.fit(c, {tol = 1e-5})
    assert.is_true(f:monotone())
    assert.is_true(f:errors{truth = "exact", npts = 400} <= 1e-5)
  end)

  it("a uniformly parametrized line is fitted exactly: s/L = t", function()
    local f = arclen.fit({0, 0, 1, 2, 2, 4, 3, 6})
    assert.is_true(math.abs(f.total - math.sqrt(45)) <= 4 * EPS * f.total)
    for k = 0, 10 do assert.is_true(math.abs(f:value(k / 10) - k / 10) <= 4 * EPS) end
  end)

  it("a point has total 0, length 0 and time 0", function()
    for _, m in ipairs({"hermite", "paper"}) do
      local f = arclen.fit({1, 2, 1, 2, 1, 2, 1, 2}, {method = m})
      assert.are.equal(0, f.total)
      assert.are.equal(0, f:length(0.5))
      assert.are.equal(0, f:time(1))
      assert.is_true(f:monotone())
    end
  end)

  it("scale and translation change nothing but the total (huge, tiny, far away)", function()
    local base = arclen.fit(WORST)
    for _, tr in ipairs({{2 ^ 400, 0}, {2 ^ -400, 0}, {1, 1e9}, {2 ^ 500, 2 ^ 520}}) do
      local c = {}
      for i = 1, 8 do c[i] = WORST[i] * tr[1] + tr[2] end
      local f = arclen.fit(c)
      -- Far from the origin, the coordinates themselves carry only
      -- |offset| * eps / size of relative accuracy.
      local tolerance = 64 * EPS * (1 + math.abs(tr[2]) / tr[1])
      assert.is_true(helpers.relerr(f.total, base.total * tr[1]) <= tolerance)
      for k = 0, 10 do
        assert.is_true(math.abs(f:value(k / 10) - base:value(k / 10)) <= tolerance)
      end
    end
  end)

  it("a length beyond DBL_MAX: total inf, but finite lengths before it, never NaN", function()
    local big = 1e308
    local f = arclen.fit({big, big, -big, big, big, -big, -big, -big})
    assert.are.equal(math.huge, f.total)
    assert.are.equal(0, f:length(0))
    local s = f:length(0.1)
    assert.is_true(s > 0 and s < math.huge)
    local t = f:time(s)
    assert.is_true(math.abs(t - 0.1) <= 1e-9)
    assert.is_true(f:errors{truth = "exact", npts = 100} <= 0.01)
  end)

  it("3D: a planar 3D curve fits like its 2D twin; a twisted one within bounds", function()
    local c3 = {}
    for i = 0, 3 do c3[3 * i + 1], c3[3 * i + 2], c3[3 * i + 3] = WORST[2 * i + 1], WORST[2 * i + 2], 0 end
    for _, m in ipairs({"hermite", "paper"}) do
      local f2, f3 = arclen.fit(WORST, {method = m}), arclen.fit(c3, {method = m})
      assert.are.equal(3, f3.dim)
      assert.is_true(helpers.relerr(f3.total, f2.total) <= 1e-15)
      for k = 0, 10 do assert.is_true(math.abs(f3:value(k / 10) - f2:value(k / 10)) <= 1e-15) end
    end
    local twisted = {0, 0, 0, 1, 2, 3, 4, -1, 2, 5, 5, -3}
    local f = arclen.fit(twisted, {tol = 1e-5})
    assert.is_true(f:errors{truth = "exact", npts = 200} <= 1e-5)
    assert.is_true(arclen.fit(twisted):errors{truth = "exact", npts = 200} <= 0.01)
  end)
end)

describe("bad input", function()
  local function fails(pattern, f, ...)
    local ok, err = pcall(f, ...)
    assert.is_false(ok)
    assert.is_truthy(tostring(err):find(pattern, 1, true), tostring(err))
  end
  local fit = arclen.fit(WORST)

  it("curve: wrong type, wrong size, NaN, infinity", function()
    fails("bad argument #1", arclen.fit, "x")
    fails("bad argument #1", arclen.fit, {1, 2, 3})
    fails("must be finite", arclen.fit, {0 / 0, 0, 1, 1, 2, 2, 3, 3})
    fails("must be finite", arclen.fit, {math.huge, 0, 1, 1, 2, 2, 3, 3})
    fails("bad argument #1", arclen.fit)
  end)

  it("options: not a table, unknown method or option, bad n, bad tol", function()
    fails("bad argument #2", arclen.fit, WORST, 5)
    fails("unknown method 'gauss'", arclen.fit, WORST, {method = "gauss"})
    fails("method must be a string", arclen.fit, WORST, {method = 1})
    fails("unknown option 'tolerance'", arclen.fit, WORST, {tolerance = 1e-3})
    for _, n in ipairs({0, 65, 2.5, -1, 0 / 0}) do
      fails("n must be an integer in [1, 64]", arclen.fit, WORST, {method = "paper", n = n})
    end
    fails("n must be a number", arclen.fit, WORST, {n = "10"})
    for _, tol in ipairs({0, 1e-12, 0.5, -1e-3, 0 / 0, math.huge}) do
      fails("tol must be in [1e-9, 0.1]", arclen.fit, WORST, {tol = tol})
    end
    fails("tol must be a number", arclen.fit, WORST, {tol = "1e-3"})
    fails("tol applies to method 'hermite' only", arclen.fit, WORST,
          {method = "paper", tol = 1e-3})
    fails("monotone must be a boolean", arclen.fit, WORST, {method = "paper", monotone = 1})
    fails("monotone applies to method 'paper' only", arclen.fit, WORST, {monotone = true})
  end)

  it("evaluation: t outside [0, 1] or NaN, s NaN or not a number", function()
    fails("t must be in [0, 1]", fit.length, fit, 1.5)
    fails("t must be in [0, 1]", fit.value, fit, -0.1)
    fails("t must be finite", fit.length, fit, 0 / 0)
    fails("t must be a number", fit.length, fit, "a")
    fails("length must be finite", fit.time, fit, 0 / 0)
    fails("length must be a number", fit.time, fit, {})
    fails("arclen.fit expected", fit.length, {}, 0.5)
  end)

  it("errors(): unknown truth or option, bad npts", function()
    fails("unknown truth 'mpmath'", fit.errors, fit, {truth = "mpmath"})
    fails("unknown option 'grid'", fit.errors, fit, {grid = 3})
    fails("npts must be an integer", fit.errors, fit, {npts = -1})
  end)

  it("gauss_legendre: n outside [1, 64]", function()
    fails("n must be an integer in [1, 64]", arclen.gauss_legendre, 0)
    fails("n must be an integer in [1, 64]", arclen.gauss_legendre, 65)
    fails("n must be a number", arclen.gauss_legendre, nil)
  end)
end)

describe("pictures (arclen.repro.svgplot, arclen.plot)", function()
  local svg = require "arclen.repro.svgplot"
  local plot = require "arclen.repro.plot"

  it("svg.histogram bins every value once, linear or log", function()
    local values = {}
    for i = 1, 1000 do values[i] = (i / 1000) ^ 3 end
    for _, log in ipairs({false, true}) do
      local edges, counts = svg.histogram(values, {bins = 17, log = log})
      assert.are.equal(18, #edges)
      local sum = 0
      for _, c in ipairs(counts) do sum = sum + c end
      assert.are.equal(1000, sum)
      for i = 2, #edges do assert.is_true(edges[i] > edges[i - 1]) end
    end
  end)

  it("a figure renders a complete SVG document with its items and legend", function()
    local fig = svg.figure{title = "T <&>", xlabel = "x", ylabel = "y", ylog = true}
    fig:line({{1, 1}, {2, 10}, {3, 0}, {4, 100}}, {label = "a"})   -- 0 leaves a gap
    fig:markers({1, 2}, {1, 10}, {label = "m", shape = "square"})
    fig:vline(2.5, {text = "v"})
    local text = fig:render()
    assert.is_truthy(text:match("^<svg xmlns=\"http://www.w3.org/2000/svg\""))
    assert.is_truthy(text:match("</svg>\n$"))
    assert.is_truthy(text:find("T &lt;&amp;&gt;", 1, true))
    assert.is_nil(text:find("nan", 1, true))
    assert.is_nil(text:find("inf", 1, true))
    local _, paths = text:gsub("<path d=\"M", "")
    assert.are.equal(1, paths)           -- one line, split by the gap into 2 runs
    local _, moves = text:match("<path d=\"([^\"]*)\""):gsub("M", "")
    assert.are.equal(2, moves)
  end)

  it("plot.fit and plot.fit_error draw the truth, both fits and the marks", function()
    local text = plot.fit(WORST, {samples = 50})
    assert.is_truthy(text:find("true s(t)/s(1)", 1, true))
    assert.is_truthy(text:find("paper, n = 10 (max error 0.087)", 1, true))
    assert.is_truthy(text:find("inflexion t = 0.6982", 1, true))
    assert.is_truthy(plot.fit_error(WORST, {samples = 50}):find("span ends", 1, true))
    local hist = plot.histogram({{label = "x", values = {0.1, 0.01, 0.001}}})
    assert.is_truthy(hist:find("<rect", 1, true))
  end)
end)
