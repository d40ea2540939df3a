-- spec/cli_spec.lua -- the command-line tool run as a shell user runs it:
-- a subprocess of this Lua running arclen.cli with the same modules as
-- this process (LUA_PATH and LUA_CPATH are this process's package.path and
-- package.cpath, so it tests the build under test -- a contracted or clang
-- build too; lua/arclen/cli.lua run as a script would put the clone's
-- build/<version> first), checked for its output, its messages on stderr
-- and its exit status.
local arclen = require("arclen")

local interpreter, shquote = require("helpers").interpreter, require("helpers").shquote


local ERR = os.tmpname()
local MAIN = os.tmpname()   -- a script that runs arclen.cli from the search paths
do
  local f = assert(io.open(MAIN, "w"))
  f:write('require("arclen.cli").main(arg)\n')
  f:close()
end

-- Run the CLI with args (a list); returns stdout, stderr, exit status.
local function run(args, stdin)
  local words = {}
  for i, a in ipairs(args) do words[i] = shquote(a) end
  local cmd = ("LUA_PATH=%s LUA_CPATH=%s %s %s %s 2>%s"):format(
    shquote(package.path), shquote(package.cpath), interpreter(), shquote(MAIN),
    table.concat(words, " "), ERR)
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
<svg xmlns="http://www.w3.org/2000/svg" xmlns:svg="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
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

  it("length of every drawn shape of an SVG file, and the total #svgdoc", function()
    local out, err, status = run({"length", svgfile})
    assert.are.equal(0, status, err)
    local lines = {}
    for l in out:gmatch("[^\n]+") do lines[#lines + 1] = l end
    assert.are.equal(6, #lines)
    assert.are.equal("side\t5", lines[1])
    assert.are.equal("path2\t2", lines[2])     -- &#10; is a newline (a separator)
    assert.are.equal("rect3\t20", lines[3])    -- no id: tag and index
    local L = arclen.length({0, 0, 10, 0, 10, 10, 0, 0})
    assert.are.equal("curve\t" .. ("%.17g"):format(L), lines[4])
    assert.are.equal("ns\t1", lines[5])        -- <svg:path>, not <pathology>
    assert.are.equal(28 + L, tonumber(lines[6]:match("^total\t(.*)$")))
  end)

  it("--json for a file, a path and a cubic (dkjson; numbers round-trip) #svgdoc", function()
    local dk = require("dkjson")
    local out = run({"length", "--json", svgfile})
    local v = dk.decode(out)
    assert.are.same({id = "side", tag = "path", layer = "(root)", length = 5, segments = 1},
                    v.paths[1])
    assert.are.equal(28 + arclen.length({0, 0, 10, 0, 10, 10, 0, 0}), v.total)
    assert.are.equal("user", v.units)
    out = run({"length", "--json", "M0 0 L3 4"})
    assert.are.same({id = "path", length = 5, segments = 1}, dk.decode(out))
    out = run({"length", "--json", "0", "0", "1", "0", "2", "0", "3", "0"})
    v = dk.decode(out)
    assert.are.equal(3, v.length)
    assert.is_true(v.evals > 0 and v.err >= 0)
  end)

  it("what the old pattern scanner got wrong: attributes with '>', CDATA, references #svgdoc", function()
    local name = os.tmpname()
    local f = assert(io.open(name, "w"))
    f:write([==[<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">
<path title="a>b" id="after" d="M0 0 L3 4"/>
<style><![CDATA[ <path d="M0 0 L100 0"/> ]]></style>
<path id="&#x2212;&#38;lt;" d="M0 0 L0 1"/>
</svg>]==])
    f:close()
    local out, err, status = run({"length", "--json", name})
    os.remove(name)
    assert.are.equal(0, status, err)
    local v = require("dkjson").decode(out)
    assert.are.equal(2, #v.paths)
    assert.are.equal("after", v.paths[1].id)
    assert.are.equal("\226\136\146&lt;", v.paths[2].id)   -- U+2212 in UTF-8, &lt; once
    assert.are.equal(6, v.total)
  end)

  it("--units: the viewBox onto width/height, then mm, in, pt ... #svgdoc", function()
    local name = os.tmpname()
    local f = assert(io.open(name, "w"))
    f:write([[<svg xmlns="http://www.w3.org/2000/svg" width="20mm" height="10mm" viewBox="0 0 200 100">
<path d="M0 0 L200 0"/></svg>]])
    f:close()
    local want = {user = 200, mm = 20, cm = 2, ["in"] = 20 / 25.4, px = 20 / 25.4 * 96,
                  pt = 20 / 25.4 * 72, pc = 20 / 25.4 * 6}
    for u, L in pairs(want) do
      local out, err, status = run({"length", "--units", u, name})
      assert.are.equal(0, status, err)
      local got = tonumber(out:match("total\t(%S+)"))
      assert.is_true(math.abs(got - L) <= 1e-13 * L, u .. ": " .. tostring(got))
    end
    local _, err, status = run({"length", "--units", "furlong", name})
    os.remove(name)
    assert.are.equal(2, status)
    assert.matches("unknown unit 'furlong'", err)
  end)

  it("stat: per layer and totals, for several files; --json #svgdoc", function()
    local name = os.tmpname()
    local f = assert(io.open(name, "w"))
    f:write([[<svg xmlns="http://www.w3.org/2000/svg"
  xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" viewBox="0 0 100 100">
<g inkscape:groupmode="layer" inkscape:label="cut"><path d="M0 0 L10 0 M20 0 L30 0"/>
  <rect x="40" y="0" width="10" height="10"/></g>
<g inkscape:groupmode="layer" inkscape:label="engrave"><line x1="0" y1="50" x2="0" y2="60"/></g>
</svg>]])
    f:close()
    local out, err, status = run({"stat", name, name})
    assert.are.equal(0, status, err)
    assert.matches("Layer cut\n  Length: 60\n  Pen%-up length: 20\n  Path count: 3\n", out)
    assert.matches("Layer engrave\n  Length: 10\n  Pen%-up length: 0\n  Path count: 1\n", out)
    assert.matches("Bounding box: %(0, 0, 50, 10%)", out)
    assert.matches("== 2 files", out)
    out = run({"stat", "--json", name})
    os.remove(name)
    local v = require("dkjson").decode(out)
    assert.are.equal(70, v.total.length)
    assert.are.equal(20, v.total.travel)
    assert.are.equal(4, v.total.paths)
    assert.are.equal(3, v.total.elements)
    assert.are.equal(7, v.total.segments)
    assert.are.same({0, 0, 50, 60}, v.total.bbox)
    assert.are.equal("cut", v.files[1].layers[1].name)
  end)

  it("reads path data or an SVG document from stdin (-) #svgdoc", function()
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
    assert.matches('^{"time":1%.5', out)
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
    assert.matches('^%[{"s":0,"time":0,"tx":1,"ty":0,"x":0,"y":0},', out)
  end)

  it("--arcs applies to path data as to documents", function()
    local d = "M0,0A1,1,0,0,1,2,0"
    local out, err, status = run({"length", d})
    assert.are.equal(0, status, err)
    assert.are.equal(arclen.path.svg(d):length(), num(out))
    out, err, status = run({"length", "--arcs", "cubics", d})
    if arclen.engine == "c" then
      assert.are.equal(0, status, err)
      local cubics = arclen.path.svg(d, {arcs = "cubics"})
      assert.are.equal(cubics:length(), num(out))
      assert.are_not.equal(arclen.path.svg(d):length(), cubics:length())
    else                             -- the Lua engine reads arcs as conics only
      assert.are.equal(1, status)
      assert.matches('^arclen: elliptical arc: as cubics %(arcs = "cubics"%), arcs need the C core', err)
    end
  end)

  it("fit: the length-versus-t fit's summary", function()
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

-- #clone: the clone's own build (tools/check-rock.sh, testing an installed
-- copy from a source tree without one, leaves these out).
describe("arclen CLI: bin/arclen runs from the clone (no LUA_PATH, no LUA_CPATH) #clone", function()
  local function clean(cmd)
    local p = assert(io.popen("env -u LUA_PATH -u LUA_CPATH -u LUA_PATH_5_4 -u LUA_CPATH_5_4 "
      .. cmd .. " 2>&1; echo \"exit=$?\""))
    local out = p:read("*a")
    p:close()
    return out
  end
  it("./bin/arclen (sh picks a Lua with a build) #svgdoc", function()
    assert.are.equal("5\nexit=0\n", clean("./bin/arclen length 'M0 0 L3 4'"))
    assert.matches("^loop\t.*\ntotal\t352%.44204368407674\nexit=0\n$",
      clean("./bin/arclen length examples/drawing.svg"))
  end)
  it("<this Lua> bin/arclen", function()
    assert.are.equal("5\nexit=0\n", clean(interpreter() .. " bin/arclen length 'M0 0 L3 4'"))
    assert.are.equal("5\nexit=0\n", clean(interpreter() .. " lua/arclen/cli.lua length 'M0 0 L3 4'"))
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
    -- --arcs is checked whatever WHAT is
    {{"length", "--arcs", "bogus", "M0,0A1,1,0,0,1,2,0"}, 2,
      "^arclen: %-%-arcs: 'bogus' is neither conics nor cubics\n"},
    {{"time", "--arcs", "bogus", "1", "0", "0", "1", "0", "2", "0", "3", "0"}, 2, "%-%-arcs: 'bogus'"},
    -- a coordinate nan or inf as 1e400: the coordinate named
    {{"length", "0", "0", "1", "1", "2", "nan", "3", "3"}, 2,
      "^arclen: cubic 1: coordinate 6 must be a finite number\n"},
    {{"length", "0", "0", "1", "1", "2", "-Inf", "3", "3"}, 2,
      "^arclen: cubic 1: coordinate 6 must be a finite number\n"},
    {{"length", "0", "0", "1", "1", "2", "1e400", "3", "3"}, 2,
      "^arclen: cubic 1: coordinate 6 must be a finite number\n"},
    {{"fit", "0", "0", "1", "1", "2", "x", "3", "3"}, 2, "^arclen: fit: 'x' is not a number\n"},
    -- a distance that is no finite number: a usage error, however written
    {{"time", "1e400", "M0 0 L1 0"}, 2,
      "^arclen: time: the distance S must be a finite number, got '1e400'\n"},
    {{"time", "inf", "M0 0 L1 0"}, 2, "^arclen: time: the distance S must be a finite number, got 'inf'\n"},
    {{"point", "-1e400", "M0 0 L1 0"}, 2, "^arclen: point: the distance S must be a finite number"},
    {{"point", "NaN", "M0 0 L1 0"}, 2, "^arclen: point: the distance S must be a finite number"},
    -- --tol out of its range: a usage error naming --tol, whatever WHAT is
    {{"length", "--tol", "1e-16", "M0 0 L1 0"}, 2,
      "^arclen: %-%-tol must be in %[1e%-15, 0%.1%], got '1e%-16'\nTry"},
    {{"length", "--tol", "0.5", "M0 0 L1 0"}, 2, "^arclen: %-%-tol must be in %[1e%-15, 0%.1%], got '0%.5'"},
    {{"length", "--tol", "nan", "M0 0 L1 0"}, 2, "^arclen: %-%-tol must be in %[1e%-15, 0%.1%], got 'nan'"},
    {{"length", "--tol", "1e-16", "0", "0", "1", "0", "2", "0", "3", "0"}, 2, "^arclen: %-%-tol must be in"},
    {{"resample", "--step", "inf", "M0 0 L1 0"}, 2, "step must be a positive finite number"},
    -- a length beyond the doubles: a failure, not a number inf
    {{"length", "M-1e308 0 L1e308 0"}, 1,
      "^arclen: length: the path's length overflows %(beyond the doubles%)\n$"},
    {{"time", "1", "M-1e308 0 L1e308 0"}, 1,
      "^arclen: 'time': arithmetic overflow %(the path's length is beyond the doubles%)\n$"},
    {{"resample", "3", "M-1e308 0 L1e308 0"}, 1,
      "^arclen: 'resample': arithmetic overflow %(the path's length is beyond the doubles%)\n$"},
  }
  for _, case in ipairs(cases) do
    -- #svgdoc: needs the document reader (tools/check-rock.sh runs the
    -- specs on the core rock alone without them)
    local name = table.concat(case[1], " ")
    it(name .. (name:find("%.svg") and " #svgdoc" or ""), function()
      local out, err, status = run(case[1])
      assert.are.equal(case[2], status, err)
      assert.are.equal("", out)
      assert.matches(case[3], err)
      if #case[1] > 0 then assert.matches("^arclen: ", err) end
      assert.is_nil(err:find("traceback", 1, true))
    end)
  end

  it("time on a file of several paths asks for one path #svgdoc", function()
    local name = os.tmpname()
    local f = assert(io.open(name, "w"))
    f:write(SVG)
    f:close()
    local out, err, status = run({"time", "1", name})
    os.remove(name)
    assert.are.equal(2, status)
    assert.are.equal("", out)
    assert.matches("time needs one path; the file has 5", err)
  end)

  it("a document that draws nothing: total 0 and a warning #svgdoc", function()
    local name = os.tmpname()
    local f = assert(io.open(name, "w"))
    f:write("<svg><rect/></svg>")
    f:close()
    local out, err, status = run({"length", name})
    os.remove(name)
    assert.are.equal(0, status)
    assert.are.equal("total\t0\n", out)
    assert.matches("warning: .*nothing drawn", err)
  end)

  it("a malformed document: the file, line and column #svgdoc", function()
    local name = os.tmpname()
    local f = assert(io.open(name, "w"))
    f:write("<svg xmlns='http://www.w3.org/2000/svg'>\n  <path d='M0 0 L1 1'>\n</svg>")
    f:close()
    local out, err, status = run({"length", name})
    os.remove(name)
    assert.are.equal(1, status)
    assert.are.equal("", out)
    assert.matches("^arclen: " .. name:gsub("%p", "%%%0") .. ":3:3: malformed XML: mismatched tag", err)
  end)

  it("a length that overflows: length and stat (second file) name the file, line and column #svgdoc", function()
    local good, bad = os.tmpname(), os.tmpname()
    local f = assert(io.open(good, "w"))
    f:write("<svg xmlns='http://www.w3.org/2000/svg'><path d='M0 0 L1 0'/></svg>")
    f:close()
    f = assert(io.open(bad, "w"))
    f:write("<svg xmlns='http://www.w3.org/2000/svg'>\n\n    <path d='M0 0 L1e308 0 L-1e308 0'/>\n</svg>")
    f:close()
    local want = "^arclen: " .. bad:gsub("%p", "%%%0")
      .. ":3:5: <path>: the path's length overflows %(coordinates up to 1e%+308%)\n$"
    local out1, err1, status1 = run({"length", bad})
    local out2, err2, status2 = run({"stat", good, bad})
    os.remove(good)
    os.remove(bad)
    assert.are.same({"", 1}, {out1, status1})
    assert.matches(want, err1)
    assert.are.equal(1, status2)
    -- the batch goes on: the good file measured, the failures counted
    assert.matches(want:sub(1, -2) .. "arclen: stat: 1 of 2 files failed\n$", err2)
    assert.matches("^== " .. good:gsub("%p", "%%%0") .. " .*\n  Length: 1\n", out2)
  end)
end)

describe("arclen CLI: files as users have them (issue 32) #svgdoc", function()
  local DIR = "spec/data/svgfiles/"
  it("errors a renderer passes over: warnings with their place; --strict makes them errors", function()
    local out, err, status = run({"length", DIR .. "errors.svg"})
    assert.are.equal(0, status, err)
    assert.matches("\ntotal\t164\n$", out)
    assert.matches("arclen: warning: " .. DIR:gsub("%p", "%%%0") .. "errors%.svg:4:3: <use> of '#path%-in%-another%-file': "
      .. "no element has that id; nothing drawn\n", err)
    assert.matches("errors%.svg:5:3: <path id='ocal'>: d: expected sweep%-flag %(0 or 1%) at position 45; "
      .. "drawn up to position 19\n", err)
    out, err, status = run({"length", "--strict", DIR .. "errors.svg"})
    assert.are.same({1, ""}, {status, out})
    assert.are.equal("arclen: " .. DIR .. "errors.svg:4:3: <use> of '#path-in-another-file': no element has that id\n", err)
  end)

  it("a .svgz is read as the document it holds", function()
    if not require("arclen.svgdoc").gzip then return pending("built without zlib") end
    local out, err, status = run({"length", "--quiet", DIR .. "errors.svgz"})
    assert.are.equal(0, status, err)
    assert.matches("\ntotal\t164\n$", out)
    -- on stdin too (gzip bytes need not contain '<')
    local p = assert(io.popen(("LUA_PATH=%s LUA_CPATH=%s %s %s length - < %s 2>/dev/null"):format(
      shquote(package.path), shquote(package.cpath), interpreter(), shquote(MAIN),
      shquote(DIR .. "errors.svgz"))))
    out = p:read("*a")
    p:close()
    assert.matches("\ntotal\t164\n$", out)
  end)

  it("stat of several files: each that fails is reported, the others measured, exit 1", function()
    local png = os.tmpname()
    local f = assert(io.open(png, "wb"))
    f:write("\137PNG\r\n\26\n\0\0\0\rIHDR")
    f:close()
    local good = DIR .. "errors.svg"
    local out, err, status = run({"stat", good, png, "spec/data", good})
    os.remove(png)
    assert.are.equal(1, status)
    assert.matches("^== " .. good:gsub("%p", "%%%0") .. " %(units: user%)\n", out)
    assert.matches("== 2 files", out)
    assert.matches("\n  Length: 328\n", out)                   -- the two good ones
    assert.matches("arclen: " .. png:gsub("%p", "%%%0") .. ":1:1: not an SVG document %(it looks like a PNG image%)\n", err)
    assert.matches("arclen: spec/data: is a directory\n", err)
    assert.matches("arclen: stat: 2 of 4 files failed\n$", err)
    out, err, status = run({"stat", "--json", good, "spec/data"})
    assert.are.equal(1, status)
    local v = require("dkjson").decode(out)
    assert.are.equal(164, v.total.length)
    assert.are.same({{file = "spec/data", error = "spec/data: is a directory"}}, v.failed)
  end)

  it("length of several files: each under its name, then the sum; one that fails is reported", function()
    local good = DIR .. "errors.svg"
    local one = run({"length", good})
    local out, err, status = run({"length", good, "spec/data", good})
    assert.are.equal(1, status)
    local q = good:gsub("%p", "%%%0")
    assert.matches("^== " .. q .. "\n" .. one:gsub("%p", "%%%0") .. "== spec/data\n== " .. q .. "\n", out)
    assert.matches("\n== 2 of 3 files\ntotal\t328\n$", out)
    assert.matches("arclen: spec/data: is a directory\n", err)
    assert.matches("arclen: length: 1 of 3 files failed\n$", err)
    out, err, status = run({"length", "--json", good, "spec/data", good})
    assert.are.equal(1, status)
    local v = require("dkjson").decode(out)
    assert.are.equal(328, v.total)
    assert.are.equal(3, #v.files)
    assert.are.same({"spec/data", "spec/data: is a directory"}, {v.files[2].file, v.files[2].error})
    assert.are.equal(164, v.files[3].total)
    assert.are.equal(good, v.files[1].file)
  end)

  it("a file whose name starts with m is a file, not path data", function()
    local name = "map_cli_spec.svg"             -- relative, as a user types it
    local f = assert(io.open(name, "wb"))
    f:write('<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 0 L3 4"/></svg>')
    f:close()
    local out, _, status = run({"length", name})
    local out2, _, status2 = run({"length", name, name})
    os.remove(name)
    assert.are.same({0, "path1\t5\ntotal\t5\n"}, {status, out})
    assert.are.equal(0, status2)
    assert.matches("\ntotal\t10\n$", out2)
    out = run({"length", "m1 1 l3 4"})
    assert.are.equal(5, num(out))
  end)

  it("length of a directory says so", function()
    local _, err, status = run({"length", "spec/data"})
    assert.are.same({1, "arclen: spec/data: is a directory\n"}, {status, err})
  end)
end)

describe("arclen CLI: the documented commands", function()
  -- The ```sh block of doc/api.md's "Command line" section, and README.md's
  -- `./bin/arclen` lines: every command runs (exit 0, some output); where
  -- the comment is numbers, the output's first line is those numbers.
  local read = require("helpers").read
  local section = read("doc/api.md"):match("\n## Command line\n(.-)\n## ") or ""
  local block = section:match("```sh\n(.-)```") or ""
  local lines, readme = {}, 0
  for line in block:gmatch("[^\n]+") do
    if line:match("^arclen") then lines[#lines + 1] = line end
  end
  for line in read("README.md"):gmatch("[^\n]+") do
    if line:match("^%./bin/arclen ") then
      lines[#lines + 1] = line:gsub("^%./bin/", "")
      readme = readme + 1
    end
  end
  it("has them", function() assert.is_true(#lines >= 12 and readme >= 3) end)
  for _, line in ipairs(lines) do
    it(line .. (line:find("%.svg") and " #svgdoc" or ""), function()
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
                         tonumber(out:match('"total": ?([%d%.e%-+]+)')))
      end
    end)
  end
end)
