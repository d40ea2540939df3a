-- spec/svgfiles_spec.lua -- documents as users have them (issue 32, items 4
-- and 7): the errors a renderer passes over (a <use> of a missing id, an
-- error in path data) are warnings with their place and the rest is
-- measured, errors under strict; compressed files (gzip, .svgz) read
-- transparently, and what is not an SVG document named as what it is.
local svg = require("helpers").optional("arclen.svg")   -- #svgdoc specs need it
local arclen = require("arclen")

local H = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 100 100">'
local COL = #H + 1                    -- the column of the first element after H

local function lengths(doc)
  local t = {}
  for i, e in ipairs(doc.elements) do t[i] = e.length end
  return t
end

describe("errors a renderer passes over #svgdoc", function()
  -- SVG 2 section 9.5.4 (SVG 1.1 F.2): rendered up to the command that holds
  -- the error.  Each length is that of the correct prefix, by hand.
  local cases = {
    -- d, the length of what is drawn, the message, where the prefix ends
    {"M0 0 L10 0 L10 10 L 5", 20, "expected a number %(L y%), got the end of the data at position 22", 17},
    {"M0 0 L3 4 6 8 9", 10, "expected a number %(L y%)", 13},        -- an implicit repetition
    {"M0 0 L3 4 L1e", 5, "exponent without digits", 9},
    {"M0 0 L3 4 # L 9 9", 5, "position 11", 9},
    {"M0 0 L3 4 Z 7", 10, "position 13", 11},
    {"M0 0 H 3, V", 3, "expected a number %(V y%)", 8},                 -- the comma dropped
    {"M0 0 L3 4,L6 8", 5, "comma not followed by a number at position 10", 9},
    {"M0 0 L3 4 Z Z", 10, "position 13", 11},
    {"M 67.78348 1090.127 A 5.868683 5.868652 0 1 ", 0, "expected sweep%-flag %(0 or 1%) at position 45", 19},
  }
  for _, c in ipairs(cases) do
    it("d='" .. c[1] .. "': " .. c[2] .. ", with a warning", function()
      local doc = svg.parse(H .. '<path id="p" d="' .. c[1] .. '"/><path d="M0 0 L0 1"/></svg>', nil, "w.svg")
      assert.are.same({c[2], 1}, lengths(doc))
      assert.are.equal(1, #doc.warnings)
      assert.matches("^w%.svg:1:" .. COL .. ": <path id='p'>: d: ", doc.warnings[1])
      assert.matches(c[3], doc.warnings[1])
      assert.matches("; drawn up to position " .. c[4] .. "$", doc.warnings[1])
      assert.are.equal(c[1]:sub(1, c[4]), doc.elements[1].d)
      -- the same prefix as path data of its own measures the same
      assert.are.equal(arclen.path.svg(c[1]:sub(1, c[4])):length(), c[2])
      -- strict: the error, where it was before issue 32
      local ok, e = pcall(svg.parse, H .. '<path id="p" d="' .. c[1] .. '"/></svg>', {strict = true}, "w.svg")
      assert.is_false(ok)
      assert.matches("^w%.svg:1:" .. COL .. ": <path id='p'>: d: ", e)
      assert.is_nil(e:find("drawn up to", 1, true))
      -- arclen.path.svg keeps raising
      assert.is_false((pcall(arclen.path.svg, c[1])))
    end)
  end

  it("an error in the first command: nothing drawn", function()
    local doc = svg.parse(H .. '<path d="L1 1"/><path d="M0,"/><path d="M0 0 L0 2"/></svg>', nil, "w.svg")
    assert.are.same({2}, lengths(doc))
    assert.are.equal(2, #doc.warnings)
    assert.matches("^w%.svg:1:" .. COL .. ": <path>: d: .*; nothing drawn$", doc.warnings[1])
    assert.matches("; nothing drawn$", doc.warnings[2])
  end)

  it("numbers beyond the doubles and arcs that cannot be built stay errors (no grammar error)", function()
    assert.matches("out of range", select(2, pcall(svg.parse, H .. '<path d="M0 0 L1e999 0"/></svg>')))
    assert.matches("overflows", select(2, pcall(svg.parse, H .. '<path d="M0 0 L1e308 0 L-1e308 0"/></svg>')))
  end)

  it("a <use> of a missing id: a warning at the use, the rest drawn in order", function()
    local text = H .. '<path id="a" d="M0 0 L1 0"/>\n<use xlink:href="#nope"/>\n<path d="M0 0 L2 0"/>\n' ..
      '<g id="g"><use href="#gone"/><path d="M0 0 L3 0"/></g><use href="#g" x="5"/></svg>'
    local doc = svg.parse(text, nil, "u.svg")
    assert.are.same({1, 2, 3, 3}, lengths(doc))
    assert.are.same({"u.svg:2:1: <use> of '#nope': no element has that id; nothing drawn",
      "u.svg:4:11: <use> of '#gone': no element has that id; nothing drawn",
      "u.svg:4:11: <use> of '#gone': no element has that id; nothing drawn"}, doc.warnings)
    local ok, e = pcall(svg.parse, text, {strict = true}, "u.svg")
    assert.is_false(ok)
    assert.matches("^u%.svg:%d+:%d+: <use> of '#[a-z]+': no element has that id$", e)
  end)

  it("after a scan, a <use> of a missing id holds nothing back (a stream goes on)", function()
    local svgdoc = require("arclen.svgdoc")
    local text = H .. '<use href="#nope"/>\n' .. ('<path d="M0 0 L1 0"/>\n'):rep(50) .. "</svg>"
    for _, scanned in ipairs({true, false}) do
      local r = svgdoc.new({uses = true, stream = true})
      if scanned then r:scan(text) end
      local early = 0
      for k = 1, #text, 100 do
        local list = r:feed(text:sub(k, k + 99))
        if list and k + 99 < #text then early = early + #list end
      end
      local res = r:finish("n.svg")
      if scanned then
        assert.is_true(early >= 45, "handed over before the end: " .. early)
      else                           -- the target could still come
        assert.are.equal(0, early)
        assert.are.equal(50, #res.elements)
      end
      assert.are.same({"n.svg:1:" .. COL .. ": <use> of '#nope': no element has that id; nothing drawn"},
        res.warnings)
    end
  end)

  it("strict turns every warning into an error, and is a boolean", function()
    local text = H .. '<path transform="scale(0)" d="M0 0 L1 0"/></svg>'
    assert.are.equal(1, #svg.parse(text).warnings)
    assert.matches("singular transform", select(2, pcall(svg.parse, text, {strict = true})))
    assert.matches("strict must be a boolean", select(2, pcall(svg.parse, text, {strict = 1})))
  end)
end)

describe("documents as users have them #svgdoc", function()
  local DIR = "spec/data/svgfiles/"
  local svgdoc = require("arclen.svgdoc")
  local input = require("arclen.svginput")

  local function read_all(name)
    local f = assert(io.open(name, "rb"))
    local s = f:read("*a")
    f:close()
    return s
  end

  -- A function source giving text in chunks of n bytes.
  local function chunks(text, n)
    local pos = 1
    return function()
      if pos > #text then return nil end
      local c = text:sub(pos, pos + n - 1)
      pos = pos + n
      return c
    end
  end

  local function signature(doc)
    local t = {}
    for i, e in ipairs(doc.elements) do
      t[i] = table.concat({tostring(e.id), e.tag, e.line, e.col, ("%.17g"):format(e.length), e.d}, " ")
    end
    return t
  end

  it("errors.svg: what renderers pass over, measured by hand (0 + 50 + 40 + 60 + 7 + 7)", function()
    local doc = svg.read(DIR .. "errors.svg")
    assert.are.same({0, 90, 60, 7, 7}, lengths(doc))
    assert.are.equal(164, doc.total)
    local where = {}
    for i, w in ipairs(doc.warnings) do where[i] = w:match("^[^:]*:(%d+:%d+): ") end
    table.sort(where)
    assert.are.same({"4:3", "5:3", "6:3", "8:13", "8:13"}, where)
    assert.matches("errors%.svg:4:3: <use> of '#path%-in%-another%-file': no element has that id", table.concat(doc.warnings, "\n"))
    assert.are.same(where, (function()     -- in document order (the scan knows the ids)
      local t = {}
      for i, w in ipairs(doc.warnings) do t[i] = w:match("^[^:]*:(%d+:%d+): ") end
      return t
    end)())
    -- strict: the first error met
    assert.matches("^" .. DIR:gsub("%p", "%%%0") .. "errors%.svg:4:3: <use> of '#path%-in%-another%-file': "
      .. "no element has that id$", select(2, pcall(svg.read, DIR .. "errors.svg", {strict = true})))
    -- from a stream, not scanned, the use waits for the end: the path first
    local f = assert(io.open(DIR .. "errors.svg", "rb"))
    local ok, e = pcall(svg.each, f, function() end, {strict = true, name = "s"})
    f:close()
    assert.is_false(ok)
    assert.matches("^s:5:3: <path id='ocal'>: d: expected sweep%-flag", e)
  end)

  it(".svgz (two gzip members) reads as the document it holds, by name, as text and as a stream", function()
    if not svgdoc.gzip then return pending("arclen.svgdoc built without zlib") end
    local plain = svg.read(DIR .. "errors.svg")
    local z = svg.read(DIR .. "errors.svgz")
    assert.are.same(signature(plain), signature(z))
    assert.are.equal(#plain.warnings, #z.warnings)
    assert.matches("^" .. DIR:gsub("%p", "%%%0") .. "errors%.svgz:%d+:%d+: ", z.warnings[1])
    local text = read_all(DIR .. "errors.svgz")
    assert.are.same(signature(plain), signature(svg.parse(text)))
    for _, n in ipairs({1, 7, 100}) do
      local got = {}
      svg.each(chunks(text, n), function(e) got[#got + 1] = e end)
      assert.are.same(signature(plain), signature({elements = got}))
    end
    -- zeros after the last member are padding (gzip(1) ignores them too)
    assert.are.equal(164, svg.parse(text .. ("\0"):rep(50)).total)
  end)

  it("broken gzip: truncated, corrupt, or followed by other data: an error naming the file", function()
    if not svgdoc.gzip then return pending("arclen.svgdoc built without zlib") end
    local text = read_all(DIR .. "errors.svgz")
    local function err(s) return select(2, pcall(svg.parse, s, nil, "z.svgz")) end
    assert.matches("^z%.svgz: truncated gzip data: the file ends inside the compressed stream %(byte 100 ",
      err(text:sub(1, 100)))
    assert.matches("^z%.svgz: corrupt gzip data %(byte %d+ of the compressed data: ",
      err(text:sub(1, 30) .. ("x"):rep(40) .. text:sub(71)))
    assert.matches("^z%.svgz: data after the end of the gzip stream %(byte " .. #text .. " ",
      err(text .. "garbage"))
  end)

  it("a gzip bomb (64 MiB of spaces in 64 KiB) is read in bounded memory", function()
    if not svgdoc.gzip then return pending("arclen.svgdoc built without zlib") end
    assert.are.equal(5, svg.read(DIR .. "bomb.svgz").total)
    -- the peak below is Linux's (a Windows Lua under Wine opens the file
    -- too); under a preloaded sanitizer the freed chunks sit in its
    -- quarantine, which measures the sanitizer, not the reader
    local status = package.config:sub(1, 1) == "/" and (os.getenv("LD_PRELOAD") or "") == ""
      and io.open("/proc/self/status")
    if not status then return end
    status:close()
    local helpers = require("helpers")
    -- the peak of reading a file, in a process of its own
    local function peak(file)
      local script = ([[
        local svg = require("arclen.svg")
        assert(svg.read(%q).total == 5)
        for line in io.lines("/proc/self/status") do
          local kb = line:match("^VmHWM:%%s*(%%d+)")
          if kb then print(kb) end
        end]]):format(file)
      -- a script file, not -e: texlua takes no -e
      local name = os.tmpname()
      local sf = assert(io.open(name, "w"))
      sf:write(script)
      sf:close()
      local p = assert(io.popen(("LUA_PATH=%s LUA_CPATH=%s %s %s"):format(helpers.shquote(package.path),
        helpers.shquote(package.cpath), helpers.interpreter(), helpers.shquote(name))))
      local kb = tonumber(p:read("*a"))
      p:close()
      os.remove(name)
      assert.is_true(type(kb) == "number", "no VmHWM")
      return kb
    end
    local small = os.tmpname()
    local f = assert(io.open(small, "w"))
    f:write(H .. '<path d="M0 0 L3 4"/></svg>')
    f:close()
    local base, kb = peak(small), peak(DIR .. "bomb.svgz")
    os.remove(small)
    assert.is_true(kb - base < 16 * 1024, ("peak resident memory %d KiB for 64 MiB inflated, %d for a "
      .. "small file"):format(kb, base))
  end)

  it("without zlib, gzip input says what to do", function()
    local it_ = input.chunks({gzip = false}, "a.svgz", chunks("\31\139\8\0\0\0\0\0", 4))
    local ok, e = pcall(it_)
    assert.is_false(ok)
    assert.matches("^a%.svgz: gzip%-compressed %(%.svgz%): this arclen%.svgdoc was built without zlib; "
      .. "install zlib's headers %(Debian zlib1g%-dev", e)
  end)

  it("other formats are named by their magic numbers, at 1:1", function()
    local cases = {
      {"\137PNG\r\n\26\n\0\0\0\rIHDR", "a PNG image"},
      {"%PDF-1.7\n", "a PDF document"},
      {"\255\216\255\224\0\16JFIF", "a JPEG image"},
      {"GIF89a\1\0", "a GIF image"},
      {"PK\3\4\20\0", "a ZIP archive"},
      {"RIFF\0\0\0\0WEBPVP8 ", "a WebP image"},
    }
    for _, c in ipairs(cases) do
      assert.are.equal("x.bin:1:1: not an SVG document (it looks like " .. c[2] .. ")",
        select(2, pcall(svg.parse, c[1], nil, "x.bin")))
      -- in chunks of one byte too (the first bytes gathered)
      assert.are.equal("x.bin:1:1: not an SVG document (it looks like " .. c[2] .. ")",
        select(2, pcall(svg.each, chunks(c[1], 1), function() end, {name = "x.bin"})))
    end
    -- text is the reader's: a BOM, a short document
    assert.are.equal(1, svg.parse("\239\187\191" .. H .. '<line x2="1"/></svg>').total)
    assert.are.equal(0, svg.parse("<svg/>").total)
  end)

  it("a file that cannot be read says why: no such file, is a directory, permission denied", function()
    assert.are.equal(DIR .. "nope.svg: no such file", select(2, pcall(svg.read, DIR .. "nope.svg")))
    local e = select(2, pcall(svg.read, "spec/data"))
    if package.config:sub(1, 1) == "/" then
      assert.are.equal("spec/data: is a directory", e)
    else                                          -- Windows refuses to open it
      assert.matches("^spec/data: [ip]", e)
    end
    local name = os.tmpname()
    local f = assert(io.open(name, "w"))
    f:write(H .. "</svg>")
    f:close()
    if package.config:sub(1, 1) == "/" and os.execute("chmod 000 " .. name) then
      local g = io.open(name, "rb")
      if g then g:close()                         -- root reads it anyway
      else
        assert.are.equal(name .. ": permission denied", select(2, pcall(svg.read, name)))
      end
    end
    os.remove(name)
  end)
end)
