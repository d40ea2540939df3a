-- Gravesen's adaptive subdivision ("gravesen", "gravesen-richardson")
-- against the 40-digit references of tools/ref_lengths.py.  The contract:
-- relative error <= tol on every reference curve for tol in [1e-12, 1e-3].
local arclen = require("arclen")
local H = require("helpers")

local METHODS = {"gravesen", "gravesen-richardson"}
local TOLS = {1e-3, 1e-6, 1e-9, 1e-12}

local function check_file(file)
  local rows = H.tsv(file)
  for _, method in ipairs(METHODS) do
    for _, tol in ipairs(TOLS) do
      it(method .. ": every curve of " .. file .. " within tol " .. tol, function()
        local worst = H.worst()
        for _, row in ipairs(rows) do
          local c = H.curve(row)
          -- the whole curve and the sub-ranges [0, 1/4], [0, 1/2], [0, 3/4]
          for _, p in ipairs({{1, "L"}, {0.25, "L25"}, {0.5, "L50"}, {0.75, "L75"}}) do
            local L = arclen.length(c, {method = method, tol = tol, t1 = p[1]})
            worst:add(H.relerr(L, tonumber(row[p[2]])), row.id .. " t1=" .. p[1])
          end
        end
        assert.is_true(worst.err <= tol, string.format("%s: %.3g at %s", method,
                                                       worst.err, tostring(worst.id)))
      end)
    end
  end
end

describe("gravesen: relative tolerance honoured", function()
  check_file("curves2d.tsv")
  local f = io.open("spec/data/curves3d.tsv")
  if f then f:close(); check_file("curves3d.tsv") end
end)

describe("gravesen: ranges and counts", function()
  local rows = H.curves("curves2d.tsv", "random")

  it("lengths of [0, 1/4], [0, 1/2], [1/4, 3/4] and reversed ranges", function()
    local worst = H.worst()
    for i = 1, 50 do
      local row, c = rows[i], H.curve(rows[i])
      local L25, L50, L75 = tonumber(row.L25), tonumber(row.L50), tonumber(row.L75)
      worst:add(H.relerr(arclen.length(c, {method = "gravesen", t1 = 0.25}), L25), row.id)
      worst:add(H.relerr(arclen.length(c, {method = "gravesen", t1 = 0.5}), L50), row.id)
      worst:add(H.relerr(arclen.length(c, {method = "gravesen", t0 = 0.25, t1 = 0.75}), L75 - L25), row.id)
      worst:add(H.relerr(arclen.length(c, {method = "gravesen", t0 = 0.5, t1 = 0}), -L50), row.id)
    end
    assert.is_true(worst.err <= 1e-11, worst.err .. " at " .. tostring(worst.id))
  end)

  it("info.pieces counts subdivisions: 1 for Henkel's straight arc 4, as his table", function()
    local c = H.curve(H.curves("curves2d.tsv", "henkel")[4])
    local _, info = arclen.length(c, {method = "gravesen", info = true})
    assert.are.equal(1, info.pieces)
  end)

  it("needs far fewer subdivisions than Henkel's 55493, 27102, 27118 (arcs 1-3) at rtol 1e-12", function()
    local henkel = H.curves("curves2d.tsv", "henkel")
    for k, his in ipairs({55493, 27102, 27118}) do
      local _, info = arclen.length(H.curve(henkel[k]), {method = "gravesen", info = true})
      assert.is_true(info.pieces < his / 5, k .. ": " .. info.pieces)
    end
  end)

  it("Richardson's step saves subdivisions at rtol 1e-12 (random curves)", function()
    local plain, rich = 0, 0
    for i = 1, 100 do
      local c = H.curve(rows[i])
      local _, a = arclen.length(c, {method = "gravesen", info = true})
      local _, b = arclen.length(c, {method = "gravesen-richardson", info = true})
      plain, rich = plain + a.pieces, rich + b.pieces
    end
    assert.is_true(rich < plain / 2, rich .. " vs " .. plain)
  end)

  it("huge and tiny coordinates keep full accuracy (exact power-of-two scaling)", function()
    local row = H.curves("curves2d.tsv", "henkel")[1]
    local c, ref = H.curve(row), tonumber(row.L)
    for _, k in ipairs({-1000, -500, 500, 1000}) do
      local s, sc = 2^k, {}
      for i = 1, 8 do sc[i] = c[i] * s end
      local L = arclen.length(sc, {method = "gravesen"})
      assert.is_true(H.relerr(L / s, ref) <= 1e-12, k .. ": " .. L / s)
    end
  end)
end)

describe("gravesen: fuzz_length finds (tools/ref_gravesen_fuzz.py, mpmath)", function()
  -- pre-asymptotic pieces the old acceptance trusted: a turn at 1e-3 of a
  -- piece's width, stops beside collinear reversals, E and S (or R1 and R2)
  -- equally off; were 1.02 .. 5.2 rtol off
  local rows = H.tsv("gravesen_fuzz.tsv")
  for _, method in ipairs(METHODS) do
    it(method .. ": within tol at the fuzzer's rtol and at 1e-3 .. 1e-12", function()
      local worst = H.worst()
      for _, row in ipairs(rows) do
        local c = H.numbers(row.c)
        local t0, t1, L = tonumber(row.t0), tonumber(row.t1), tonumber(row.L)
        for _, tol in ipairs({tonumber(row.rtol), 1e-3, 1e-6, 1e-9, 1e-12}) do
          local got = arclen.length(c, {method = method, tol = tol, t0 = t0, t1 = t1})
          worst:add(H.relerr(got, L) / tol, row.id .. " tol " .. tol)
        end
      end
      assert.is_true(worst.err <= 1, string.format("%.3g tol at %s", worst.err, tostring(worst.id)))
    end)
  end
end)
