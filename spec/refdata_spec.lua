-- spec/refdata_spec.lua -- the reference curve sets (spec/data/curves2d.tsv,
-- curves3d.tsv, written by tools/ref_lengths.py) are well-formed, complete
-- and consistent with what can be computed independently in doubles:
-- collinear curves have closed-form lengths, planar 3D curves have their
-- 2D twins' lengths.
local helpers = require "helpers"

local HEAD2 = "id family param x0 y0 x1 y1 x2 y2 x3 y3 L25 L50 L75 L T25 T50 T75"
local HEAD3 = "id family param x0 y0 z0 x1 y1 z1 x2 y2 z2 x3 y3 z3 L25 L50 L75 L T25 T50 T75"

-- Minimum rows per family: each family must stay large enough to mean something.
local MIN2 = {henkel = 6, random = 1000, nearcusp = 120, cusp = 20, collinear = 20,
              coincident = 15, point = 3, scale = 60, offset = 30, nearquad = 90}
local MIN3 = {random3d = 300, nearcusp3d = 40, collinear3d = 10, planar3d = 20,
              scale3d = 20, offset3d = 10, point3d = 2}

local function num(row, key)
  local v = tonumber(row[key])
  assert(v and v == v and v > -math.huge and v < math.huge,
         row.id .. ": " .. key .. " is not a finite number: " .. tostring(row[key]))
  return v
end

-- The well-formedness checks shared by both files.
local function check_file(name, head, min)
  local rows, header = helpers.tsv(name)
  assert.are.equal(head, table.concat(header, " "))
  local counts, seen = {}, {}
  for _, row in ipairs(rows) do
    local fam = row.family
    counts[fam] = (counts[fam] or 0) + 1
    assert.are.equal(fam .. "-" .. counts[fam], row.id)
    assert.is_nil(seen[row.id], "duplicate id " .. row.id)
    seen[row.id] = true
    assert.is_true(row.param ~= "", row.id .. ": empty param")
    helpers.curve(row)   -- every coordinate parses
    local l25, l50, l75, l = num(row, "L25"), num(row, "L50"), num(row, "L75"), num(row, "L")
    assert.is_true(0 <= l25 and l25 <= l50 and l50 <= l75 and l75 <= l,
                   row.id .. ": lengths not nondecreasing")
    if l == 0 then
      assert.is_true(row.T25 == "-" and row.T50 == "-" and row.T75 == "-",
                     row.id .. ": zero length needs times '-'")
    else
      assert.is_true(l25 > 0, row.id .. ": a curve of positive length moves in [0, 1/4]")
      local t25, t50, t75 = num(row, "T25"), num(row, "T50"), num(row, "T75")
      assert.is_true(0 < t25 and t25 < t50 and t50 < t75 and t75 < 1,
                     row.id .. ": times not increasing in (0, 1)")
    end
  end
  for fam, k in pairs(min) do
    assert.is_true((counts[fam] or 0) >= k,
                   name .. ": family " .. fam .. " has " .. (counts[fam] or 0) .. " < " .. k)
  end
  return rows
end

-- Length of a curve whose control points lie on one line: the position
-- along the line is a cubic lambda(t); the length is the sum of
-- |lambda(t_k+1) - lambda(t_k)| between the roots of lambda'(t) in (0, 1).
local function collinear_length(c, dim, t1)
  local p0 = {}
  for k = 1, dim do p0[k] = c[k] end
  -- direction: the control point farthest from P0
  local dir, best = nil, -1
  for i = 1, 3 do
    local d2, v = 0, {}
    for k = 1, dim do v[k] = c[i * dim + k] - p0[k]; d2 = d2 + v[k] * v[k] end
    if d2 > best then best, dir = d2, v end
  end
  local n = math.sqrt(best)
  local lam = {}
  for i = 0, 3 do
    local s = 0
    for k = 1, dim do s = s + (c[i * dim + k] - p0[k]) * dir[k] end
    lam[i + 1] = s / n
  end
  local function at(t)
    local u = 1 - t
    return u * u * u * lam[1] + 3 * u * u * t * lam[2] + 3 * u * t * t * lam[3] + t * t * t * lam[4]
  end
  -- lambda'(t)/3 = a t^2 + b t + d in the power basis
  local d1, d2, d3 = lam[2] - lam[1], lam[3] - lam[2], lam[4] - lam[3]
  local a, b, d = d1 - 2 * d2 + d3, 2 * (d2 - d1), d1
  local ts = {}
  if a == 0 then
    if b ~= 0 then ts[#ts + 1] = -d / b end
  else
    local disc = b * b - 4 * a * d
    if disc >= 0 then
      local q = -(b + (b >= 0 and 1 or -1) * math.sqrt(disc)) / 2
      ts[#ts + 1] = q / a
      if q ~= 0 then ts[#ts + 1] = d / q end
    end
  end
  table.sort(ts)
  local prev, len = 0, 0
  for _, t in ipairs(ts) do
    if t > prev and t < t1 then len = len + math.abs(at(t) - at(prev)); prev = t end
  end
  return len + math.abs(at(t1) - at(prev))
end

describe("reference data", function()
  local rows2, rows3

  it("curves2d.tsv is well-formed and has every family", function()
    rows2 = check_file("curves2d.tsv", HEAD2, MIN2)
  end)

  it("curves3d.tsv is well-formed and has every family", function()
    rows3 = check_file("curves3d.tsv", HEAD3, MIN3)
  end)

  it("Henkel's arcs are his six curves, in his order", function()
    local h = helpers.curves("curves2d.tsv", "henkel")
    assert.are.equal(6, #h)
    assert.are.same({0, 0, 10, 10, 0, 10, 10, 0}, helpers.curve(h[2]))
    assert.are.same({0, 0, 20.001, 20, -10, -10, 10, 10}, helpers.curve(h[6]))
  end)

  it("points have length 0 exactly", function()
    for _, name in ipairs({"curves2d.tsv", "curves3d.tsv"}) do
      for _, row in ipairs(helpers.tsv(name)) do
        if row.family == "point" or row.family == "point3d" then
          assert.are.equal(0, tonumber(row.L), row.id)
        end
      end
    end
  end)

  it("collinear curves have their closed-form lengths", function()
    local w = helpers.worst()
    for _, set in ipairs({{"curves2d.tsv", 2, "collinear"}, {"curves3d.tsv", 3, "collinear3d"},
                          {"curves2d.tsv", 2, "nearquad", "line"}}) do
      for _, row in ipairs(helpers.curves(set[1], set[3])) do
        if set[4] == nil or row.param == set[4] then
          local c = helpers.curve(row)
          for _, q in ipairs({{0.25, "L25"}, {0.5, "L50"}, {0.75, "L75"}, {1, "L"}}) do
            w:add(helpers.relerr(collinear_length(c, set[2], q[1]), tonumber(row[q[2]])),
                  row.id .. " " .. q[2])
          end
        end
      end
    end
    -- doubles: a few roundings of lambda and of the reversal times
    assert.is_true(w.err <= 1e-14, ("worst %.3g at %s"):format(w.err, tostring(w.id)))
  end)

  it("planar 3D curves have the lengths of their 2D twins", function()
    local twins = {}
    for _, row in ipairs(helpers.curves("curves2d.tsv", "planar")) do twins[row.id] = row end
    local n = 0
    for _, row in ipairs(helpers.curves("curves3d.tsv", "planar3d")) do
      local twin = assert(twins[row.id:gsub("planar3d", "planar")], row.id)
      for _, key in ipairs({"L25", "L50", "L75", "L", "T25", "T50", "T75"}) do
        assert.is_true(helpers.relerr(tonumber(row[key]), tonumber(twin[key])) <= 1e-15,
                       row.id .. " " .. key)
      end
      n = n + 1
    end
    assert.is_true(n >= 20)
  end)

  it("symmetric curves reach half their length at t = 1/2", function()
    -- Henkel's cusp, symmetric loops and their symmetric perturbations
    -- (nearcusp 13-24, 37-60: tools/curves.py): the mirror symmetry
    -- t -> 1-t gives s(1/2) = L/2.
    local ids = {["henkel-2"] = true, ["cusp-1"] = true, ["cusp-2"] = true, ["cusp-3"] = true}
    for i = 13, 24 do ids["nearcusp-" .. i] = true end
    for i = 37, 60 do ids["nearcusp-" .. i] = true end
    local n = 0
    for _, row in ipairs(helpers.tsv("curves2d.tsv")) do
      if ids[row.id] then
        assert.is_true(helpers.relerr(2 * tonumber(row.L50), tonumber(row.L)) <= 1e-15, row.id)
        assert.is_true(helpers.relerr(tonumber(row.T50), 0.5) <= 1e-15, row.id)
        n = n + 1
      end
    end
    assert.are.equal(40, n)
  end)
end)
