-- spec/makefile_spec.lua -- the Makefile's choices by system, read from
-- `make -n -B` (nothing is built): a Lua module is a bundle that leaves
-- lua_* undefined on macOS (Apple's ld refuses -shared with undefined
-- symbols), a shared object elsewhere; LUA_INC given wins over pkg-config.
local function gnu_make()
  for _, m in ipairs({"gmake", "make"}) do
    local p = io.popen(m .. " --version 2>/dev/null")
    local v = p:read("*a")
    p:close()
    if v:find("GNU Make", 1, true) then return m end
  end
end

local MAKE = gnu_make()

-- The commands make would run for the Lua 5.4 module and the reader.
local function dry(vars)
  local p = assert(io.popen(MAKE .. " -n -B LUA=5.4 " .. vars .. " 2>/dev/null"))
  local out = p:read("*a")
  p:close()
  return out
end

describe("Makefile", function()
  if not MAKE then
    pending("GNU make not found")
    return
  end

  it("links a bundle with dynamic lookup on Darwin", function()
    local out = dry("UNAME_S=Darwin")
    assert.truthy(out:find("-bundle -undefined dynamic_lookup -o build/5.4/arclen/core.so ", 1, true), out)
    assert.is_nil(out:find("-shared", 1, true))
  end)

  it("links with -shared elsewhere (Linux, FreeBSD)", function()
    for _, sys in ipairs({"Linux", "FreeBSD"}) do
      local out = dry("UNAME_S=" .. sys)
      assert.truthy(out:find("-shared -o build/5.4/arclen/core.so ", 1, true), sys)
      assert.is_nil(out:find("-bundle", 1, true), sys)
    end
  end)

  it("LUA_INC given on the command line is the include directory", function()
    local out = dry("LUA_INC=/opt/lua-headers/include/lua")
    assert.truthy(out:find("-I/opt/lua-headers/include/lua -c src/lua/module.c", 1, true), out)
  end)
end)
