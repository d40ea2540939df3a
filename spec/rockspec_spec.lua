-- The rockspec lists every C source and Lua module (LuaRocks' builtin
-- backend builds only what is listed): it must match the tree.
describe("rockspec/arclen-scm-1.rockspec", function()
  it("is what tools/gen_rockspec.lua writes for the current tree", function()
    local want = io.popen("lua5.4 tools/gen_rockspec.lua 2>&1"):read("*a")
    local f = assert(io.open("rockspec/arclen-scm-1.rockspec"))
    local have = f:read("*a")
    f:close()
    assert.are.equal(want, have,
      "regenerate: lua5.4 tools/gen_rockspec.lua > rockspec/arclen-scm-1.rockspec")
  end)
end)
