-- Numbers in and out under a comma-decimal locale: a host that calls
-- os.setlocale("de_DE.UTF-8", "numeric") (GUI programs, editors) must get
-- the numbers it gets in the C locale -- path data, attributes, the shapes'
-- path data, p:svg(), the command line's options and output, MetaPost's
-- text.  Each test runs under LC_NUMERIC = de_DE.UTF-8 and puts back the
-- locale it found.  The locale must exist: without it this spec fails.
local arclen = require("arclen")
local svg = require("helpers").optional("arclen.svg")   -- #svgdoc specs need it
local mpost = require("arclen.mpost")

local NAMES = {"de_DE.UTF-8", "de_DE.utf8", "German_Germany.1252"}   -- POSIX, Windows
local HOWTO = "the locale de_DE.UTF-8 is missing: as root, install the Debian package "
  .. "'locales' and run `localedef -i de_DE -f UTF-8 de_DE.UTF-8` "
  .. "(sh tools/deps.sh matrix does both)"

-- Set LC_NUMERIC to the comma locale: its name, and the locale found.
local function comma_locale()
  local before = os.setlocale(nil, "numeric")
  for _, name in ipairs(NAMES) do
    if os.setlocale(name, "numeric") then
      -- the C library's printf must now write ',' (else the test proves nothing)
      local p = ("%.1f"):format(0.5)
      if type(jit) ~= "table" then   -- LuaJIT formats numbers itself
        assert(p == "0,5", "under " .. name .. " %.1f of 0.5 is " .. p)
      end
      return name, before
    end
  end
  error(HOWTO, 0)
end

-- f() under the comma locale; the previous locale back afterwards.
local function under_comma(f)
  return function()
    local name, before = comma_locale()
    local ok, err = pcall(f, name)
    os.setlocale(before, "numeric")
    if not ok then error(err, 0) end
  end
end

local SVG_STROKES = [[<svg xmlns="http://www.w3.org/2000/svg">
  <path id="zero" stroke="black" stroke-width="0.0" d="M0 0 L1 0"/>
  <path id="zero-e" stroke="black" stroke-width="0e1" d="M0 0 L1 0"/>
  <path id="half" stroke="black" stroke-width="0.5" d="M0 0 L2 0"/>
  <path id="thin" stroke="black" stroke-width=".25e-3" d="M0 0 L4 0"/>
</svg>]]

local SVG_SHAPES = [[<svg xmlns="http://www.w3.org/2000/svg">
  <circle id="c" cx="0.5" cy="0.25" r="1.5"/>
  <rect id="r" x="0.125" y="0.5" width="2.5" height="1.25"/>
  <rect id="rr" width="10.5" height="4.5" rx="1.5"/>
  <line id="l" x1="0.5" y1="0" x2="3.25" y2="0"/>
  <polyline id="p" points="0,0 1.5,0 1.5,2.5"/>
</svg>]]

describe("numbers under LC_NUMERIC = de_DE.UTF-8", function()
  it("the locale exists and is put back after each test", function()
    local before = os.setlocale(nil, "numeric")
    under_comma(function() end)()
    assert.are.equal(before, os.setlocale(nil, "numeric"))
  end)

  it("path data: long decimals, exponents, a leading point", under_comma(function()
    local cases = {
      {"M0 0 L1.5e30 0", 1.5e30}, {"M0 0 L0.12345678901234567890 0", 0.12345678901234567890},
      {"M0 0 L1e-5 0", 1e-5}, {"M0 0 L.5e+2 0", 50}, {"M0 0 L2.5 0", 2.5},
      {"M0 0 L0.000000000000000000000000000000000000123456789012345678901 0",
       1.23456789012345678901e-37},
      {"M0 0 L123456789012345678901234567890.5 0", 123456789012345678901234567890.5},
    }
    for _, c in ipairs(cases) do
      local p = arclen.path.svg(c[1])
      local L = p:length()
      assert.is_true(math.abs(L - c[2]) <= 1e-14 * c[2], c[1] .. ": " .. ("%.17g"):format(L))
      assert.are.equal(c[2], p:segment(1)[3])   -- the line's end point, exactly as read
    end
  end))

  it("stroke-width=\"0.0\" draws no stroke ({stroked = true}) #svgdoc", under_comma(function()
    local doc = svg.parse(SVG_STROKES, {stroked = true})
    local ids = {}
    for i, e in ipairs(doc.elements) do ids[i] = e.id end
    assert.are.same({"half", "thin"}, ids)
    assert.are.equal(6, doc.total)
  end))

  it("shapes: circle, rect, rounded rect, line, polyline lengths #svgdoc", under_comma(function()
    local doc = svg.parse(SVG_SHAPES)
    local L = {}
    for _, e in ipairs(doc.elements) do L[e.id] = e.length end
    local rr = 2 * (10.5 - 3) + 2 * (4.5 - 3) + 2 * math.pi * 1.5
    for id, want in pairs({c = 3 * math.pi, r = 7.5, rr = rr, l = 2.75, p = 4}) do
      assert.is_true(L[id] and math.abs(L[id] - want) <= 1e-9 * want,
        id .. ": " .. tostring(L[id]) .. " ~= " .. tostring(want))
    end
  end))

  it("p:svg() writes '.' and reads back to the same path", under_comma(function()
    local d = "M0.5 0.25 C1.5 0 2.125 1 3.0000000000000004 1.1"
    local text = arclen.path.svg(d):svg()
    assert.are.equal("M0.5 0.25 C1.5 0 2.125 1 3.0000000000000004 1.1", text)
    assert.are.equal(arclen.path.svg(d):length(), arclen.path.svg(text):length())
  end))

  it("messages of the C code write '.'", under_comma(function()
    local ok, err = pcall(arclen.length, {0, 0, 1, 0, 2, 0, 3, 0}, {tol = 0.5})
    assert.is_false(ok)
    assert.matches("[1e-15, 0.1]", tostring(err), 1, true)
    local f = arclen.fit({0, 0, 1, 0, 2, 1, 3, 1})
    assert.matches("total %d+%.%d+%)$", tostring(f))
  end))

  it("messages of the document reader write '.' #svgdoc", under_comma(function()
    local text = [[<svg xmlns="http://www.w3.org/2000/svg">
      <rect width="-1.5" height="1"/></svg>]]
    local ok, err = pcall(svg.parse, text, {strict = true})
    assert.is_false(ok)
    assert.matches("(-1.5)", tostring(err), 1, true)
    local doc = svg.parse(text)                  -- the warning, likewise
    assert.matches("(-1.5)", doc.warnings[1], 1, true)
  end))

  it("MetaPost's text: knots in, numbers and paths out", under_comma(function()
    local warn = mpost.warn
    mpost.warn = function() end      -- numbersystem scaled's warning
    local K = "o 0,0,0,0,0.5,0 1.5,0,1,0,1.5,0"
    assert.are.equal("1.5", mpost.run("length", "double", "gauss", 0, K))
    assert.are.equal("1.5000000000000000", mpost.run("length", "scaled", "gauss", 0, K))
    local pts = mpost.run("points", "double", "gauss", 0, K, 3)
    assert.are.equal("(0,0)..controls (0,0) and (0.75,0)..(0.75,0)..controls (0.75,0) and "
      .. "(1.5,0)..(1.5,0)", pts)
    mpost.warn = warn
  end))

  it("numtext: format, tostring, tonumber, shortest", under_comma(function()
    local nt = require("arclen.numtext")
    assert.are.equal("1.5 2.50 3.5e+00 x 4.5 %", nt.format("%g %.2f %.1e %s %s %%", 1.5, 2.5, 3.5, "x", 4.5))
    assert.are.equal("0.1", nt.tostring(0.1))
    assert.are.equal(0.1, nt.tonumber("0.1"))
    assert.are.equal(1.5e-9, nt.tonumber(" 1.5e-9 "))
    assert.is_nil(nt.tonumber("1,5"))
    assert.are.equal(16, nt.tonumber("0x10"))
    assert.are.equal(math.huge, nt.tonumber("1e999"))
    local long = "0." .. ("3"):rep(300)
    assert.are.equal(1 / 3, nt.tonumber(long))
    assert.are.equal("0.1", nt.shortest(0.1))
  end))
end)

-- The command line run as a host with the comma locale would run it: a
-- subprocess whose first act is os.setlocale (lua does not read LC_ALL).
-- It needs a POSIX shell: not on Windows (tools/check-windows.sh leaves
-- cli_spec out for the same reason).
local describe_sh = package.config:sub(1, 1) == "/" and describe or function() end
describe_sh("the command line under LC_NUMERIC = de_DE.UTF-8", function()
  local interpreter, shquote = require("helpers").interpreter, require("helpers").shquote
  local ERR = os.tmpname()

  local function run(args)
    local name, before = comma_locale()
    os.setlocale(before, "numeric")
    local wrapper = os.tmpname()
    local f = assert(io.open(wrapper, "w"))
    f:write(("assert(os.setlocale(%q, 'numeric'))\narg[0] = 'lua/arclen/cli.lua'\n"
      .. "dofile('lua/arclen/cli.lua')\n"):format(name))
    f:close()
    local words = {}
    for i, a in ipairs(args) do words[i] = shquote(a) end
    local cmd = ("LUA_PATH=%s LUA_CPATH=%s %s %s %s 2>%s; echo \"exit=$?\""):format(
      shquote(package.path), shquote(package.cpath), interpreter(), wrapper,
      table.concat(words, " "), ERR)
    local p = assert(io.popen(cmd))
    local out = p:read("*a")
    p:close()
    os.remove(wrapper)
    local e = assert(io.open(ERR))
    local err = e:read("*a")
    e:close()
    local status = tonumber(out:match("exit=(%d+)\n?$"))
    return out:gsub("exit=%d+\n?$", ""), err, status
  end

  it("length of a cubic, of path data, with --tol and --json", function()
    local out, err, status = run({"length", "--tol", "1.5e-9", "0", "0", "0.5", "0", "1", "0", "1.5", "0"})
    assert.are.equal(0, status, err)
    assert.are.equal("1.5\n", out)
    local d = "M0 0 L0.12345678901234567890 0"
    out, err, status = run({"length", d})
    assert.are.equal(0, status, err)
    assert.are.equal(("%.17g\n"):format(arclen.path.svg(d):length()), out)  -- (C locale here)
    assert.is_true(math.abs(tonumber(out) - 0.12345678901234567890) < 1e-16)
    out, err, status = run({"length", "--json", "M0 0 L2.5 0"})
    assert.are.equal(0, status, err)
    assert.matches('"length":2.5', out, 1, true)
  end)

  it("time, point, resample --step: numbers in and out with '.'", function()
    local out, err, status = run({"time", "0.75", "M0 0 L1.5 0"})
    assert.are.equal(0, status, err)
    assert.are.equal("0.5\n", out)
    out = run({"point", "0.75", "M0 0 L1.5 0"})
    assert.are.equal("0.75 0 1 0\n", out)
    out, err, status = run({"resample", "--step", "0.5", "M0 0 L1.5 0"})
    assert.are.equal(0, status, err)
    assert.are.equal("0 0\n0.5 0\n1 0\n1.5 0\n", out)
  end)

  it("a comma is not a decimal point on the command line either", function()
    local _, err, status = run({"length", "--tol", "1,5e-9", "0", "0", "1", "0", "2", "0", "3", "0"})
    assert.are.equal(2, status)
    assert.matches("--tol: '1,5e-9' is not a number", err, 1, true)
  end)
end)
