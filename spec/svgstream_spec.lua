-- spec/svgstream_spec.lua -- arclen.svg as a stream (issue 31, items 3 and
-- 6): svg.each hands over the same elements as svg.read, in the same
-- order, bit for bit, whatever the chunks; each element as soon as it is
-- complete (those after a <use> of an element not read yet once it is);
-- the cap of svg.read checked as elements arrive; what is kept for <use>;
-- errors with their place; the command line's progress line.
local svg = require("helpers").optional("arclen.svg")   -- #svgdoc specs need it
local helpers = require("helpers")

local H = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">'

-- Every .svg under spec/data/svg/ (the real files and the hand-written).
-- Every document of spec/data/svg/: the files svg_refs.tsv has references
-- for (tools/ref_svg.py walks the folder), without a shell to list them.
local function data_files()
  local list, seen = {}, {}
  for _, row in ipairs(helpers.tsv("svg_refs.tsv")) do
    if not seen[row.file] then
      seen[row.file] = true
      list[#list + 1] = "spec/data/svg/" .. row.file
    end
  end
  table.sort(list)
  return list
end

-- A function source giving text in chunks of n bytes, and how many it gave.
local function chunks(text, n)
  local pos, given = 1, 0
  return function()
    if pos > #text then return nil end
    local c = text:sub(pos, pos + n - 1)
    pos = pos + n
    given = given + 1
    return c
  end, function() return given end
end

-- What an element is, to the bit: its fields and its cubics.
local function signature(e)
  local t = {tostring(e.id), e.tag, tostring(e.layer), e.line, e.col, tostring(e.use),
    tostring(e.stroked), ("%.17g"):format(e.length or -1), e.d, table.concat(e.ctm, ",")}
  local p = e.path
  for k = 1, p.n do
    local c, kind = p:segment(k)
    t[#t + 1] = tostring(kind)
    for j = 1, #c do t[#t + 1] = ("%.17g"):format(c[j]) end
  end
  return table.concat(t, " ")
end

local function signatures(list)
  local t = {}
  for i, e in ipairs(list) do t[i] = signature(e) end
  return t
end

describe("svg.each: the same elements as svg.read, as they complete #svgdoc", function()
  it("every file of spec/data/svg/, by name and in chunks of 1 KiB and 61 bytes", function()
    local files = data_files()
    assert.is_true(#files >= 28)
    for _, f in ipairs(files) do
      for _, opts in ipairs({{}, {hidden = true}, {stroked = true, units = "mm"}}) do
        local doc = svg.read(f, opts)
        local got = {}
        local sum = svg.each(f, function(e) got[#got + 1] = e end, opts)
        assert.are.same(signatures(doc.elements), signatures(got), f)
        assert.are.equal(doc.total, sum.total)
        assert.are.equal(#doc.elements, sum.count)
        assert.are.same(doc.warnings, sum.warnings)
        assert.is_nil(sum.elements)
        local text = helpers.read(f)
        -- a stream read once cannot know that a url() names no paint server (the
        -- file's ids are scanned first): it takes it to paint, says e.stroked, and
        -- under stroked = true draws more
        local unknowable = helpers.any(doc.warnings, "names no paint server")
        for _, n in ipairs({1024, 61}) do
          local o = {name = f}
          for k, v in pairs(opts) do o[k] = v end
          local got2 = {}
          svg.each((chunks(text, n)), function(e) got2[#got2 + 1] = e end, o)
          if unknowable and opts.stroked then
            assert.is_true(#got2 > #doc.elements, f)
          elseif unknowable then
            assert.are.equal(#doc.elements, #got2, f)
          else
            assert.are.same(signatures(doc.elements), signatures(got2), f .. " in chunks of " .. n)
          end
        end
      end
    end
  end)

  it("hands each element over before the document ends (nothing is collected)", function()
    local b = {H}
    for i = 1, 300 do b[#b + 1] = ('<path id="p%d" d="M0 0 L%d 0"/>\n'):format(i, i) end
    b[#b + 1] = "</svg>"
    local source, given = chunks(table.concat(b), 100)
    local seen_at = {}
    local sum = svg.each(source, function(e) seen_at[#seen_at + 1] = given() end)
    assert.are.equal(300, sum.count)
    assert.are.equal(300 * 301 / 2, sum.total)
    -- each path is ~30 bytes: the 10th is complete after ~3 chunks of 100
    assert.is_true(seen_at[10] <= 4, "element 10 after chunk " .. seen_at[10])
    assert.is_true(seen_at[150] < given() / 2 + 2)
    -- from a stream read once every subtree with an id is kept (a <use>
    -- could come); from text or a file with no <use>, nothing
    assert.are.equal(600, sum.kept)
    assert.are.equal(0, svg.parse(table.concat(b)).kept)
  end)

  it("a forward <use>: what follows it waits until its target is read, then comes in order", function()
    local text = H .. '<path id="a" d="M0 0 L1 0"/>\n<use id="u" href="#later"/>\n' ..
      '<path id="b" d="M0 0 L2 0"/>\n' .. ("<!-- padding -->\n"):rep(40) ..
      '<g id="later"><path id="c" d="M0 0 L4 0"/></g>\n' .. ("<!-- padding -->\n"):rep(40) ..
      '<path id="d" d="M0 0 L8 0"/></svg>'
    local source, given = chunks(text, 64)
    local order, at = {}, {}
    svg.each(source, function(e)
      order[#order + 1] = (e.use and "use:" or "") .. e.id
      at[#order] = given()
    end)
    assert.are.same({"a", "use:c", "b", "c", "d"}, order)
    assert.are.same(order, (function()
      local t = {}
      for i, e in ipairs(svg.parse(text).elements) do t[i] = (e.use and "use:" or "") .. e.id end
      return t
    end)())
    local later = text:find('<g id="later">', 1, true)
    -- b waited for the target; a did not
    assert.is_true(at[1] * 64 < later)
    assert.is_true(at[3] * 64 >= later)
    assert.is_true(at[5] > at[4])
  end)

  it("the queue behind a forward <use> is capped (max_held of the reader; a million by default)", function()
    local svgdoc = require("arclen.svgdoc")
    local function read(n, cap)
      local b = {H, '\n<use href="#t"/>'}
      for i = 1, n do b[#b + 1] = ('<path d="M0 0 L%d 0"/>'):format(i) end
      b[#b + 1] = '<path id="t" d="M0 0 L1 1"/></svg>'
      local r = svgdoc.new({uses = true, stream = true, max_held = cap})
      local got = {}
      for _, e in ipairs(r:feed(table.concat(b)) or {}) do got[#got + 1] = e end
      for _, e in ipairs(r:finish("q.svg").elements) do got[#got + 1] = e end
      return got
    end
    -- behind the use: the paths and t itself (drawn before it ends)
    assert.are.equal(1 + 2 + 1, #read(2, 3))           -- the use's copy, 2 paths, t
    local ok, e = pcall(read, 3, 3)
    assert.is_false(ok)
    assert.are.same({line = 2, col = 1, msg = "<use> of '#t' waits for an element not read yet, "
      .. "with more than 3 drawn elements behind it"}, e)
    assert.matches("max_held out of range", select(2, pcall(svgdoc.new, {max_held = 0})))
  end)

  it("a backward <use> is expanded at once; a missing target (strict) fails at the end, with the use's place", function()
    local text = H .. '<path id="a" d="M0 0 L1 0"/>\n<use href="#a"/>\n' ..
      ("<!-- padding -->\n"):rep(40) .. "</svg>"
    local source, given = chunks(text, 64)
    local at = {}
    svg.each(source, function() at[#at + 1] = given() end)
    assert.are.equal(2, #at)
    assert.is_true(at[2] * 64 < #text / 2)
    local ok, e = pcall(svg.each, (chunks(H .. '\n<use href="#nope"/>\n<path d="M0 0 L1 0"/></svg>', 10)),
      function() end, {name = "m.svg", strict = true})
    assert.is_false(ok)
    assert.are.equal("m.svg:2:1: <use> of '#nope': no element has that id", e)
    local n = 0
    local doc = svg.each((chunks(H .. '\n<use href="#nope"/>\n<path d="M0 0 L1 0"/></svg>', 10)),
      function() n = n + 1 end, {name = "m.svg"})
    assert.are.equal(1, n)
    assert.are.same({"m.svg:2:1: <use> of '#nope': no element has that id; nothing drawn"}, doc.warnings)
  end)

  it("keeps for <use> only the subtrees that a use refers to (a scan of the file first)", function()
    local b = {H}
    for i = 1, 2000 do b[#b + 1] = ('<path id="p%d" d="M0 0 L1 0"/>'):format(i) end
    b[#b + 1] = '<use href="#p7"/></svg>'
    local text = table.concat(b)
    local doc = svg.parse(text)
    assert.are.equal(2001, #doc.elements)
    assert.are.equal(2, doc.kept)                       -- p7's start and end
    local name = os.tmpname()
    local f = assert(io.open(name, "wb"))
    f:write(text)
    f:close()
    assert.are.equal(2, svg.read(name).kept)
    -- from a stream that cannot be read twice, every subtree with an id
    local sum = svg.each((chunks(text, 4096)), function() end)
    assert.are.equal(4000, sum.kept)
    assert.are.equal(2001, sum.count)
    os.remove(name)
  end)

  it("the cap of svg.read is checked as elements arrive: the first one beyond it fails, at its place", function()
    local b = {H}
    for i = 1, 50 do b[#b + 1] = ('\n<path d="M0 0 L%d 0"/>'):format(i) end
    b[#b + 1] = "</svg>"
    local text = table.concat(b)
    local ok, e = pcall(svg.parse, text, {max_elements = 20}, "cap.svg")
    assert.is_false(ok)
    assert.are.equal("cap.svg:22:1: more than 20 drawn elements", e)
    assert.are.equal(50, #svg.parse(text, {max_elements = 50}).elements)
    -- an endless document stops at the cap, long before its end
    local n = 0
    local endless = function()
      n = n + 1
      if n == 1 then return H end
      return ('<path d="M0 0 L1 0"/>'):rep(100)
    end
    local seen = 0
    ok, e = pcall(svg.each, endless, function() seen = seen + 1 end, {max_elements = 1000})
    assert.is_false(ok)
    assert.matches("^<stream>:1:%d+: more than 1000 drawn elements$", e)
    assert.are.equal(1000, seen)
    assert.is_true(n <= 12)
    -- svg.read's default cap is 10^6, each has none
    assert.matches("max_elements", select(2, pcall(svg.read, "x.svg", {max_elements = -1})))
  end)

  it("errors keep the file, line and column; the elements before them were handed over", function()
    local text = H .. '\n<path id="ok" d="M0 0 L1 0"/>\n  <path d="M0 0 L1e308 0 L-1e308 0"/></svg>'
    local got = {}
    local ok, e = pcall(svg.each, (chunks(text, 16)), function(x) got[#got + 1] = x.id end, {name = "e.svg"})
    assert.is_false(ok)
    assert.matches("^e%.svg:3:3: <path>: the path's length overflows", e)
    assert.are.same({"ok"}, got)
    ok, e = pcall(svg.each, (chunks(H .. "\n<path d='M0 0'>\n</svg>", 7)), function() end)
    assert.is_false(ok)
    assert.matches("^<stream>:3:3: malformed XML: mismatched tag", e)
    -- the callback's own errors are its own
    ok, e = pcall(svg.each, (chunks(H .. '<path d="M0 0 L1 0"/></svg>', 4096)), function() error("mine", 0) end)
    assert.are.equal("mine", e)
  end)

  it("reads an open file to its end, and names the bad argument", function()
    local f = assert(io.open("spec/data/svg/hand/shapes.svg", "rb"))
    local n = 0
    local sum = svg.each(f, function() n = n + 1 end, {name = "shapes"})
    f:close()
    assert.are.equal(#svg.read("spec/data/svg/hand/shapes.svg").elements, n)
    assert.are.equal("shapes", sum.name)
    assert.matches("bad argument #1 to 'arclen.svg.each' %(a file name, an open file or a function expected, got nil",
      select(2, pcall(svg.each)))
    assert.matches("bad argument #2 to 'arclen.svg.each' %(a function expected",
      select(2, pcall(svg.each, "x.svg")))
    assert.matches("bad argument #3 to 'arclen.svg.each' %(unknown option 'nope'",
      select(2, pcall(svg.each, "x.svg", print, {nope = 1})))
    assert.matches("progress must be a function", select(2, pcall(svg.each, "x.svg", print, {progress = 1})))
  end)

  it("a source function that returns no string: an error naming it and what it returned", function()
    -- (a number was read as text, or failed inside the reader)
    for _, case in ipairs({{42, "number"}, {{}, "table"}, {false, "boolean"}}) do
      for _, first in ipairs({true, false}) do     -- the first chunk, or a later one
        local calls = 0
        local function src()
          calls = calls + 1
          if calls == 1 and not first then return H end
          if calls <= 2 then return case[1] end
        end
        local seen = 0
        local ok, e = pcall(svg.each, src, function() seen = seen + 1 end)
        assert.is_false(ok)
        assert.are.equal(("bad argument #1 to 'arclen.svg.each' (the source function returned a %s: "
          .. "it must return strings, then nil at the end)"):format(case[2]), e)
        assert.are.equal(0, seen)
      end
    end
  end)

  it("progress: called after each chunk with the bytes, the file's size and the elements so far", function()
    local name = "spec/data/svg/real/vim-gvim.svg"
    local size = #helpers.read(name)
    local calls = {}
    local sum = svg.each(name, function() end, {progress = function(b, s, n) calls[#calls + 1] = {b, s, n} end})
    assert.is_true(#calls >= 1)
    assert.are.same({size, size}, {calls[#calls][1], calls[#calls][2]})
    assert.is_true(calls[#calls][3] <= sum.count)
  end)
end)

describe("svg.stats: svg.stat one element at a time #svgdoc", function()
  it("gives svg.stat's numbers on every file of spec/data/svg/", function()
    for _, f in ipairs(data_files()) do
      local st = svg.stats()
      svg.each(f, function(e) st:add(e) end)
      assert.are.same(svg.stat(svg.read(f)), st:result(), f)
    end
  end)
end)

-- The command line: its progress line (ARCLEN_PROGRESS=1 shows it whatever
-- stderr is, from the first chunk; a pipe is not a terminal).
-- The command line through a POSIX shell: not on Windows (tools/check-windows.sh).
local describe_sh = package.config:sub(1, 1) == "/" and describe or function() end

describe_sh("arclen length/stat: the progress line #svgdoc", function()
  local shquote = helpers.shquote
  local ERR, MAIN = os.tmpname(), os.tmpname()
  do
    local f = assert(io.open(MAIN, "w"))
    f:write('require("arclen.cli").main(arg)\n')
    f:close()
  end
  local function run(env, args)
    local cmd = ("%s LUA_PATH=%s LUA_CPATH=%s %s %s %s 2>%s"):format(env, shquote(package.path),
      shquote(package.cpath), helpers.interpreter(), shquote(MAIN), table.concat(args, " "), ERR)
    local p = assert(io.popen(cmd))
    local out = p:read("*a")
    p:close()
    local f = assert(io.open(ERR))
    local err = f:read("*a")
    f:close()
    return out, err
  end
  local big = os.tmpname()
  do
    local f = assert(io.open(big, "wb"))
    f:write(H)
    for i = 1, 4000 do f:write(('<path id="p%d" d="M0 0 L1 0"/>\n'):format(i)) end
    f:write("</svg>")
    f:close()
  end
  it("is shown with ARCLEN_PROGRESS=1, rewritten with \\r and cleared at the end", function()
    for _, cmd in ipairs({"length", "stat"}) do
      local out, err = run("ARCLEN_PROGRESS=1", {cmd, big})
      assert.matches("\r" .. "arclen: [^\n]*: 0%.%d of 0%.%d MB %(%d+%%%), [%d.]+ MB/s, %d+ elements", err)
      assert.matches("\r +\r$", err)                    -- cleared: blanks, back to the start
      assert.is_nil(err:find("\n"))
      assert.matches(cmd == "length" and "total\t4000\n$" or "Length: 4000", out)
    end
  end)
  it("is not shown with --quiet, with ARCLEN_PROGRESS=0, or when stderr is not a terminal", function()
    assert.are.equal("", select(2, run("ARCLEN_PROGRESS=1", {"length", "--quiet", big})))
    assert.are.equal("", select(2, run("ARCLEN_PROGRESS=0", {"stat", big})))
    assert.are.equal("", select(2, run("", {"length", big})))
  end)
  it("arclen.svgdoc.isatty says whether stderr is a terminal", function()
    local svgdoc = require("arclen.svgdoc")
    assert.is_boolean(svgdoc.isatty())
    assert.is_boolean(svgdoc.isatty("stdout"))
    assert.matches("invalid option 'stdin'", select(2, pcall(svgdoc.isatty, "stdin")))
    os.remove(big)
    os.remove(ERR)
    os.remove(MAIN)
  end)
end)
