-- spec/tex_pgf_spec.lua -- arclen.pgf's numbers as TeX prints them
-- (print_scaled, tex.web section 103): what \the\dimen writes for the same
-- number of sp, so the decimals arclen hands to pgf read back unchanged.
local pgf = require("arclen.pgf")

describe("arclen.pgf.scaled", function()
  it("prints as TeX's \\the does", function()
    -- \the\dimen0 after \dimen0=Nsp, from TeX itself
    local cases = {
      {0, "0.0"}, {1, "0.00002"}, {65536, "1.0"}, {32768, "0.5"},
      {-81920, "-1.25"}, {1073741823, "16383.99998"}, {6553, "0.09999"},
      {6554, "0.1"}, {23405263, "357.13597"},
    }
    for _, c in ipairs(cases) do
      assert.are.equal(c[2], pgf.scaled(c[1] / 65536))
    end
  end)

  it("reads back to the same sp, for every sp in a range", function()
    for n = -70000, 70000, 7 do
      local s = pgf.scaled(n / 65536)
      -- TeX's decimal reading (tex.web section 452): round(d * 2^16)
      local v = tonumber(s)
      assert.are.equal(n, math.floor(v * 65536 + 0.5))
    end
  end)
end)
