-- spec/cli_spec.lua -- the command-line tool run as a shell user runs it:
-- a subprocess `<this Lua> lua/arclen/cli.lua ...` that finds the same
-- modules as this process (LUA_PATH and LUA_CPATH are this process's
-- package.path and package.cpath, so it tests the fresh build), checked for
-- its output, its messages on stderr and its exit status.
local arclen = require("arclen")

-- This Lua: texlua and texluajit (LuaTeX's, with kpse built in) or a plain one.
local function interpreter()
  local tex = type(kpse) == "table"
  if type(jit) == "table" then return tex and "texluajit" or "luajit" end
  return tex and "texlua" or "lua" .. _VERSION:match("%d+%.%d+")
end

local function shquote(s) return "'" .. s:gsub("'", "'\\''") .. "'" end

local ERR = os.tmpname()

-- Run the CLI with args (a list); returns stdout, stderr, exit status.
local function run(args, stdin)
  local words = {}
  for i, a in ipairs(args) do words[i] = shquote(a) end
  local cmd = ("LUA_PATH=%s LUA_CPATH=%s %s lua/arclen/cli.lua %s 2>%s"):format(
    shquote(package.path), shquote(package.cpath), interpreter(), table.concat(words, " "), ERR)
  if stdin then cmd = "printf '%s' " .. shquote(stdin) .. " | " .. cmd end
  local p = assert(io.popen(cmd .. "; echo \"exit=$?\""))
  local out = p:read("*a")
  p:close()
  local f = assert(io.open(ERR))
  local err = f:read("*a")
  f:close()
  local status = tonumber(out:match("exit=(%d+)\n?$"))
  out = out:gsub("exit=%d+\n?$", "")
  return out, err, status
end

local function num(s) return tonumber((s:gsub("%s+$", ""))) end

local SVG = [[<?xml version="1.0"?>
<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
  <!-- <path d="M0 0 L100 0"/> is a comment, not a path -->
  <path id="side" d="M0 0 L3 4"/>
  <g><path fill="none"
      d = 'M0 0 h 1&#10;v1' /></g>
  <rect width="5" height="5"/>
  <path id="curve" d="M0 0 C10 0 10 10 0 0"></path>
  <pathology d="M0 0 L100 0"/>
  <svg:path id="ns" d="M0 0 L0 1"/>
</svg>
]]

describe("arclen CLI: results", function()
  local svgfile = os.tmpname()
  local f = assert(io.open(svgfile, "w"))
  f:write(SVG)
  f:close()

  it("length of a cubic given as numbers, as the library computes it", function()
    local out, err, status = run({"length", "0", "0", "10", "0", "10", "10", "0", "0"})
    assert.are.equal(0, status, err)
    assert.are.equal(arclen.length({0, 0, 10, 0, 10, 10, 0, 0}), num(out))
  end)

  it("length of SVG path data", function()
    local out, _, status = run({"length", "M0 0 C10 0 10 10 0 0"})
    assert.are.equal(0, status)
    assert.are.equal(arclen.length({0, 0, 10, 0, 10, 10, 0, 0}), num(out))
    out = run({"length", "--method", "metapost", "M0 0 C10 0 10 10 0 0"})
    assert.are.equal(arclen.metapost.arclength({0, 0, 10, 0, 10, 10, 0, 0}), num(out))
  end)

  it("length of every <path d=...> of an SVG file, and the total", function()
    local out, err, status = run({"length", svgfile})
    assert.are.equal(0, status, err)
    local lines = {}
    for l in out:gmatch("[^\n]+") do lines[#lines + 1] = l end
    assert.are.equal(5, #lines)
    assert.are.equal("side\t5", lines[1])
    assert.are.equal("path2\t2", lines[2])     -- &#10; is a newline (a separator)
    local L = arclen.length({0, 0, 10, 0, 10, 10, 0, 0})
    assert.are.equal("curve\t" .. ("%.17g"):format(L), lines[3])
    assert.are.equal("ns\t1", lines[4])        -- <svg:path>, not <pathology>
    assert.are.equal(8 + L, tonumber(lines[5]:match("^total\t(.*)$")))
  end)

  it("--json for a file, a path and a cubic", function()
    local out = run({"length", "--json", svgfile})
    assert.matches('^{"paths": %[{"id": "side", "length": 5, "segments": 1}, ', out)
    assert.matches('"total": ', out)
    out = run({"length", "--json", "M0 0 L3 4"})
    assert.are.equal('{"id": "path", "length": 5, "segments": 1}\n', out)
    out = run({"length", "--json", "0", "0", "1", "0", "2", "0", "3", "0"})
    assert.matches('^{"err": [^,]+, "evals": %d+, "length": 3}\n$', out)
  end)

  it("reads path data or an SVG document from stdin (-)", function()
    local out, _, status = run({"length", "-"}, "M0 0 L3 4")
    assert.are.equal(0, status)
    assert.are.equal(5, num(out))
    out = run({"length", "-"}, SVG)
    assert.matches("^side\t5\n", out)
  end)

  it("time: MetaPost's path time at a distance; t for one cubic", function()
    local out, _, status = run({"time", "15", "M0 0 L10 0 L10 10"})
    assert.are.equal(0, status)
    assert.is_true(math.abs(num(out) - 1.5) <= 1e-12)
    out = run({"time", "5", "0", "0", "10", "0", "10", "10", "0", "0"})
    local c = {0, 0, 10, 0, 10, 10, 0, 0}
    assert.is_true(math.abs(num(out) - arclen.time(c, 5)) <= 1e-12)
    out = run({"time", "--json", "15", "M0 0 L10 0 L10 10"})
    assert.matches('^{"time": 1%.5', out)
  end)

  it("point: the point and the unit tangent", function()
    local out, _, status = run({"point", "15", "M0 0 L10 0 L10 10"})
    assert.are.equal(0, status)
    local v = {}
    for w in out:gmatch("%S+") do v[#v + 1] = tonumber(w) end
    assert.are.equal(4, #v)
    assert.is_true(math.abs(v[1] - 10) + math.abs(v[2] - 5) <= 1e-11)
    assert.are.same({0, 1}, {v[3], v[4]})
  end)

  it("resample: N points, or points --step apart, as the library gives them", function()
    local out, _, status = run({"resample", "5", "M10 0 A10 10 0 1 1 -10 0"})
    assert.are.equal(0, status)
    local pts = arclen.path.svg("M10 0 A10 10 0 1 1 -10 0"):resample(5)
    local i = 0
    for line in out:gmatch("[^\n]+") do
      i = i + 1
      local x, y = line:match("^(%S+) (%S+)$")
      assert.are.equal(pts[i].x, tonumber(x))
      assert.are.equal(pts[i].y, tonumber(y))
    end
    assert.are.equal(5, i)
    out = run({"resample", "--step", "2.5", "M0 0 L10 0"})
    local n = select(2, out:gsub("\n", ""))
    assert.are.equal(5, n)
    out = run({"resample", "--json", "3", "M0 0 L10 0"})
    assert.matches('^%[{"s": 0, "time": 0, "tx": 1, "ty": 0, "x": 0, "y": 0}, ', out)
  end)

  it("fit: the length-versus-t fit's summary", function()
    if type(arclen.fit) ~= "function" then return pending("arclen.fit is not built") end
    local out, err, status = run({"fit", "--tol", "1e-6", "0", "0", "10", "0", "10", "10", "0", "0"})
    assert.are.equal(0, status, err)
    local f = arclen.fit({0, 0, 10, 0, 10, 10, 0, 0}, {tol = 1e-6})
    assert.matches(("^method\thermite\nspans\t%d\n"):format(f.nspans), out)
    assert.are.equal(f.total, tonumber(out:match("total\t(%S+)")))
    assert.is_true(tonumber(out:match("max_error\t(%S+)")) <= 1e-6)
  end)

  it("methods, henkel and help", function()
    local out = run({"methods"})
    assert.are.equal(table.concat(arclen.methods(), "\n") .. "\n", out)
    local h, _, status = run({"henkel"})
    assert.are.equal(0, status)
    assert.is_true(#h > 500)
    for _, a in ipairs({"help", "--help", "-h"}) do
      local u, _, st = run({a})
      assert.are.equal(0, st)
      assert.matches("^usage: arclen COMMAND", u)
      assert.matches("examples:", u)
    end
  end)
end)

describe("arclen CLI: errors (stderr, exit 2 for usage, 1 for failures)", function()
  local cases = {
    {{}, 2, "usage: arclen"},
    {{"frob"}, 2, "arclen: unknown command 'frob'\nTry 'arclen %-%-help'%."},
    {{"length", "--bogus"}, 2, "unknown option %-%-bogus"},
    {{"length"}, 2, "nothing to measure"},
    {{"length", "1", "2", "3"}, 2, "a cubic needs 8 %(2D%) or 12 %(3D%) numbers, got 3"},
    {{"length", "--tol", "x", "M0 0 L1 1"}, 2, "%-%-tol: 'x' is not a number"},
    {{"length", "--tol"}, 2, "%-%-tol needs a value"},
    {{"length", "--tol", "1", "0", "0", "1", "0", "2", "0", "3", "0"}, 2, "tol must be in"},
    {{"length", "--method", "nope", "M0 0 L1 1"}, 1, "unknown method 'nope'"},
    {{"length", "M0 0 L1e 2"}, 1, "exponent without digits in a number at position 8"},
    {{"length", "/nonexistent/x.svg"}, 1, "no such file"},
    {{"time", "x", "M0 0 L1 1"}, 2, "distance S must be a number"},
    {{"time", "1", "0", "0", "1", "1", "2", "2", "3", "3", "--method", "polyline"}, 1, "has no time"},
    {{"resample", "M0 0 L1 1"}, 2, "count N must be a number"},
    {{"resample", "1", "M0 0 L1 1"}, 2, "n must be an integer in %[2,"},
    {{"fit", "0", "0", "1"}, 2, "a cubic needs 8"},
    {{"length", "M0 0 L1 1", "M2 2"}, 2, "expected one path"},
  }
  for _, case in ipairs(cases) do
    it(table.concat(case[1], " "), function()
      local out, err, status = run(case[1])
      assert.are.equal(case[2], status, err)
      assert.are.equal("", out)
      assert.matches(case[3], err)
      if #case[1] > 0 then assert.matches("^arclen: ", err) end
      assert.is_nil(err:find("traceback", 1, true))
    end)
  end

  it("time on a file of several paths asks for one path", function()
    local name = os.tmpname()
    local f = assert(io.open(name, "w"))
    f:write(SVG)
    f:close()
    local out, err, status = run({"time", "1", name})
    os.remove(name)
    assert.are.equal(2, status)
    assert.are.equal("", out)
    assert.matches("time needs one path; the file has 4", err)
  end)

  it("a file without paths is a failure", function()
    local name = os.tmpname()
    local f = assert(io.open(name, "w"))
    f:write("<svg><rect/></svg>")
    f:close()
    local _, err, status = run({"length", name})
    os.remove(name)
    assert.are.equal(1, status)
    assert.matches("no <path d=...> elements", err)
  end)
end)

describe("arclen CLI: the README's commands", function()
  -- The ```sh block of README.md's "Command line" section: every `arclen`
  -- line runs (exit 0, some output); where the comment is numbers, the
  -- output's first line is those numbers.
  local f = assert(io.open("README.md"))
  local text = f:read("*a")
  f:close()
  local section = text:match("\n## Command line\n(.-)\n## ") or ""
  local block = section:match("```sh\n(.-)```") or ""
  local lines = {}
  for line in block:gmatch("[^\n]+") do
    if line:match("^arclen") then lines[#lines + 1] = line end
  end
  it("has them", function() assert.is_true(#lines >= 10) end)
  for _, line in ipairs(lines) do
    it(line, function()
      local cmd, comment = line:match("^arclen%s+(.-)%s*#%s*(.-)%s*$")
      cmd = cmd or line:match("^arclen%s+(.-)%s*$")
      local args = {}
      local rest = cmd
      while rest ~= "" do                         -- words and '...' quotes
        local q, r = rest:match("^'([^']*)'%s*(.*)$")
        if not q then q, r = rest:match("^(%S+)%s*(.*)$") end
        args[#args + 1] = q
        rest = r
      end
      local out, err, status = run(args)
      assert.are.equal(0, status, err)
      assert.is_true(#out > 0)
      local want = {}
      for w in (comment or ""):gmatch("%S+") do want[#want + 1] = tonumber(w) or false end
      local numeric = #want > 0
      for _, w in ipairs(want) do if not w then numeric = false end end
      if numeric then
        local got = {}
        for w in out:match("[^\n]*"):gmatch("%S+") do got[#got + 1] = tonumber(w) end
        assert.are.same(want, got)
      elseif comment and comment:match("%d+%.%d+}$") then  -- a JSON total
        assert.are.equal(tonumber(comment:match("([%d%.]+)}$")),
                         tonumber(out:match('"total": ([%d%.e%-+]+)')))
      end
    end)
  end
end)
