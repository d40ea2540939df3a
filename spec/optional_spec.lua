-- spec/optional_spec.lua -- the optional parts: the SVG document reader
-- (arclen.svgdoc over libexpat, the rock arclen-svg) and dkjson (the command
-- line's --json).  Without them the core works, and whatever needs them
-- fails with a message that says what to install.  Their absence is
-- simulated: a stand-in module that raises as a missing one does, found
-- first (package.preload in this process; LUA_PATH for the command line).
require("arclen")


local interpreter, shquote = require("helpers").interpreter, require("helpers").shquote

describe("without the SVG document reader", function()
  it("require 'arclen.svg' fails with what to install", function()
    local saved_svg, saved_doc = package.loaded["arclen.svg"], package.loaded["arclen.svgdoc"]
    package.loaded["arclen.svg"], package.loaded["arclen.svgdoc"] = nil, nil
    package.preload["arclen.svgdoc"] = function()
      error("module 'arclen.svgdoc' not found:\n\tno field package.preload['arclen.svgdoc']", 0)
    end
    local ok, e = pcall(require, "arclen.svg")
    package.preload["arclen.svgdoc"] = nil
    package.loaded["arclen.svg"], package.loaded["arclen.svgdoc"] = saved_svg, saved_doc
    assert.is_false(ok)
    assert.matches("^arclen.svg needs its document reader", e)
    assert.matches("luarocks install arclen%-svg", e)
    assert.matches("libexpat1%-dev", e)
    assert.matches("%[module 'arclen.svgdoc' not found%]$", e)
    -- and the core goes on
    assert.are.equal(5, require("arclen").path.svg("M0 0 L3 4"):length())
  end)
end)

describe("the command line without an optional part", function()
  -- A directory of stand-ins: dkjson and arclen.svgdoc that raise as a
  -- missing module does.
  local dir = os.tmpname()
  os.remove(dir)
  assert(os.execute("mkdir -p " .. shquote(dir .. "/arclen")))
  local function stub(name, module)
    local f = assert(io.open(dir .. "/" .. name, "w"))
    f:write(("error(\"module '%s' not found (stand-in of spec/optional_spec.lua)\", 0)\n"):format(module))
    f:close()
  end
  stub("dkjson.lua", "dkjson")
  stub("arclen/svgdoc.lua", "arclen.svgdoc")
  local ERR = os.tmpname()

  local function run(args)
    local words = {}
    for i, a in ipairs(args) do words[i] = shquote(a) end
    local cmd = ("LUA_PATH=%s LUA_CPATH=%s %s lua/arclen/cli.lua %s 2>%s; echo \"exit=$?\""):format(
      shquote(dir .. "/?.lua;" .. package.path), shquote(package.cpath), interpreter(),
      table.concat(words, " "), ERR)
    local p = assert(io.popen(cmd))
    local out = p:read("*a")
    p:close()
    local f = assert(io.open(ERR))
    local err = f:read("*a")
    f:close()
    return out, err
  end

  it("--json without dkjson: exit 1, what to install", function()
    local out, err = run({"length", "--json", "M0 0 L3 4"})
    assert.are.equal("exit=1\n", out)
    assert.are.equal("arclen: --json needs dkjson: luarocks install dkjson "
      .. "(Debian: apt-get install lua-dkjson)\n", err)
  end)

  it("an SVG document without the reader: exit 1, what to install; path data still works", function()
    local out, err = run({"length", "examples/drawing.svg"})
    assert.are.equal("exit=1\n", out)
    assert.matches("^arclen: arclen.svg needs its document reader", err)
    assert.matches("luarocks install arclen%-svg", err)
    assert.is_nil(err:find("traceback", 1, true))
    out, err = run({"stat", "examples/drawing.svg"})
    assert.are.equal("exit=1\n", out)
    assert.matches("luarocks install arclen%-svg", err)
    out, err = run({"length", "M0 0 L3 4"})
    assert.are.equal("5\nexit=0\n", out, err)
  end)

  it("cleans up", function()
    os.remove(dir .. "/dkjson.lua")
    os.remove(dir .. "/arclen/svgdoc.lua")
    os.remove(dir .. "/arclen")
    os.remove(dir)
    os.remove(ERR)
  end)
end)
