-- The rockspecs list every C source and Lua module (LuaRocks' builtin
-- backend builds only what is listed): they must match the tree.  The core
-- rock needs nothing optional (no dkjson, no expat); the document reader is
-- the rock arclen-svg.  The release is arclen._VERSION.
local arclen = require("arclen")

local read = require("helpers").read

local RELEASE = arclen._VERSION:match("^arclen (%d+%.%d+%.%d+)$")

describe("rockspec/*.rockspec", function()
  it("the release is arclen._VERSION", function()
    assert.truthy(RELEASE, arclen._VERSION)
    local out = io.popen("lua5.4 tools/gen_rockspec.lua --release 2>&1"):read("*a")
    assert.are.equal(RELEASE .. "\n", out)
  end)

  for _, package in ipairs({"arclen", "arclen-svg"}) do
    for _, version in ipairs({"scm-1", (RELEASE or "?") .. "-1"}) do
      local file = ("rockspec/%s-%s.rockspec"):format(package, version)
      it(file .. " is what tools/gen_rockspec.lua writes for the current tree", function()
        local want = io.popen(("lua5.4 tools/gen_rockspec.lua %s %s 2>&1"):format(package, version)):read("*a")
        assert.are.equal(want, read(file), "regenerate: lua5.4 tools/gen_rockspec.lua --write")
      end)
    end
  end

  it("the core rock needs neither expat nor dkjson; arclen-svg has the reader", function()
    for _, file in ipairs({"rockspec/arclen-scm-1.rockspec", ("rockspec/arclen-%s-1.rockspec"):format(RELEASE)}) do
      local s = read(file)
      assert.is_nil(s:find("EXPAT"), file)
      assert.is_nil(s:find("expat\""), file)
      assert.is_nil(s:find("dkjson\""), file)
      assert.is_nil(s:find("svgdoc"), file)
      assert.truthy(s:find('["arclen.core"]', 1, true), file)
      assert.truthy(s:find('["arclen.svg"] = "lua/arclen/svg.lua"', 1, true), file)
    end
    local s = read(("rockspec/arclen-svg-%s-1.rockspec"):format(RELEASE))
    assert.truthy(s:find('external_dependencies = { EXPAT = { header = "expat.h" },', 1, true))
    assert.truthy(s:find('platforms = { unix = { ZLIB = { header = "zlib.h" } } } }', 1, true))
    assert.truthy(s:find('"arclen == ' .. RELEASE .. '"', 1, true))
    assert.truthy(s:find('["arclen.svgdoc"]', 1, true))
    assert.is_nil(s:find('["arclen.core"]', 1, true))   -- one module, one rock
  end)
end)
