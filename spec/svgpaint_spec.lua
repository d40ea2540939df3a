-- spec/svgpaint_spec.lua -- what is drawn, as a renderer decides it:
-- conditional processing (SVG 2 section 5.8: <switch>, systemLanguage,
-- requiredExtensions, requiredFeatures) and paint that shows (--stroked,
-- --painted: none, alpha 0, opacities 0, stroke-width 0).  Each rule has a
-- hand-written document, read in the three modes; the expected ids are
-- what the specifications cited say a renderer draws.
local svg = require("helpers").optional("arclen.svg")   -- #svgdoc specs need it
-- time limits stretched for valgrind and sanitizer runs
local TIME_SCALE = tonumber(os.getenv("ARCLEN_TIME_SCALE")) or 1

local HEAD = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">'

-- The ids of the drawn elements of body (inside the root), in order.
local function ids(body, opts, head)
  local doc = svg.parse((head or HEAD) .. body .. "</svg>", opts)
  local t = {}
  for _, e in ipairs(doc.elements) do t[#t + 1] = e.id or "?" end
  return t
end

-- The same through the stream (svg.each), to check that both agree.
local function stream_ids(body, opts, head)
  local t, text = {}, (head or HEAD) .. body .. "</svg>"
  svg.each(function()
    local s = text
    text = nil
    return s
  end, function(e) t[#t + 1] = e.id or "?" end, opts)
  return t
end

local function line(id, attrs)
  return ('<path id="%s" d="M0 0 L10 0" %s/>'):format(id, attrs or "")
end

describe("conditional processing (SVG 2 section 5.8) #svgdoc", function()
  it("<switch> draws its first child element whose tests pass, nothing after it", function()
    local body = '<switch>' .. line("fr", 'systemLanguage="fr"') .. line("en-us", 'systemLanguage="en-US"')
      .. line("en", 'systemLanguage="en"') .. line("any") .. '</switch>'
    assert.are.same({"en-us"}, ids(body))                    -- "en" is a prefix of en-US
    assert.are.same({"fr"}, ids(body, {lang = "fr"}))
    assert.are.same({"any"}, ids(body, {lang = "ja"}))
    -- en-GB passes neither en-US nor en (the user's tag must be the prefix)
    assert.are.same({"any"}, ids(body, {lang = "en-GB"}))
    assert.are.same({"en-us"}, ids(body, {lang = "en-GB,en"}))   -- en passes en-US first
    assert.are.same({"en-us"}, ids(body, {lang = "EN-us"}))  -- without case
    assert.are.same(ids(body), stream_ids(body))
  end)

  it("the issue's small test: 13, not 103", function()
    local body = '<switch><path id="de" systemLanguage="de" d="M0 0 L90 0"/>'
      .. '<path id="en" systemLanguage="en" d="M0 0 L13 0"/><path id="other" d="M0 0 L100 0"/></switch>'
    local doc = svg.parse(HEAD .. body .. "</svg>")
    assert.are.equal(13, doc.total)
  end)

  it("systemLanguage: a comma-separated list; the user's languages a list too", function()
    local t = {line("a", 'systemLanguage="fr, de-LU"'), line("b", 'systemLanguage="en-US,fr"'),
               line("c", 'systemLanguage="en-"'), line("d", 'systemLanguage=""'),
               line("e", 'systemLanguage=" , "'), line("f", 'systemLanguage="english"')}
    local body = table.concat(t)
    assert.are.same({"b"}, ids(body))                        -- en: b only (en- and english are not en-...)
    assert.are.same({"a", "b"}, ids(body, {lang = "de,en-US"}))
    assert.are.same({"a"}, ids(body, {lang = "de-LU"}))
    assert.are.same({"a", "b"}, ids(body, {lang = " fr "}))
    assert.are.same({}, ids(body, {lang = "de-DE"}))         -- de-DE is no prefix of de-LU
  end)

  it("requiredExtensions: none is supported, any value fails, the empty one too", function()
    local body = '<switch>' .. line("ext", 'requiredExtensions="http://example.org/x"')
      .. line("empty", 'requiredExtensions=""') .. line("plain") .. '</switch>'
      .. line("outside", 'requiredExtensions="http://www.w3.org/1999/xhtml"')
    assert.are.same({"plain"}, ids(body))
  end)

  it("requiredFeatures is ignored (SVG 2 removed it), whatever its value", function()
    local body = '<switch>' .. line("feat", 'requiredFeatures="http://www.w3.org/TR/SVG11/feature#NotExisting"')
      .. line("next") .. '</switch>' .. line("empty", 'requiredFeatures=""')
    assert.are.same({"feat", "empty"}, ids(body))
  end)

  it("outside <switch> too: the element and its subtree are not rendered", function()
    local body = line("fr", 'systemLanguage="fr"') .. '<g systemLanguage="de"><circle id="c" r="3"/></g>'
      .. '<g id="gen" systemLanguage="en">' .. line("in-en") .. '</g>'
      .. '<rect id="r" width="2" height="2" requiredExtensions="x"/>'
    assert.are.same({"in-en"}, ids(body))
    assert.are.same({"fr"}, ids(body, {lang = "fr"}))
    -- hidden = true draws display:none, not the alternatives that fail their tests
    assert.are.same({"in-en"}, ids(body, {hidden = true}))
  end)

  it("on the root: a document whose root fails draws nothing", function()
    local head = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9" systemLanguage="fr">'
    assert.are.same({}, ids(line("x"), nil, head))
    assert.are.same({"x"}, ids(line("x"), {lang = "fr"}, head))
  end)

  it("a switch's choice skips foreign elements and text nodes; a failing group is passed over", function()
    local body = '<switch xmlns:f="http://example.org/f"><f:thing/>'
      .. '<g id="g-fr" systemLanguage="fr">' .. line("in-fr") .. '</g>'
      .. '<g id="g-any">' .. line("in-any") .. '<switch>' .. line("inner-x", 'requiredExtensions="x"')
      .. line("inner") .. line("inner-2") .. '</switch></g>' .. line("after") .. '</switch>'
    assert.are.same({"in-any", "inner"}, ids(body))
  end)

  it("through <use>: the used element's tests, and a switch inside it", function()
    local body = '<defs><switch id="s">' .. line("s-de", 'systemLanguage="de"') .. line("s-en", 'systemLanguage="en"')
      .. '</switch>' .. line("p-de", 'systemLanguage="de"') .. '</defs>'
      .. '<use href="#s"/><use href="#p-de"/><use href="#s" systemLanguage="fr"/>'
    assert.are.same({"s-en"}, ids(body))
    assert.are.same({"s-de", "p-de"}, ids(body, {lang = "de"}))
    assert.are.same(ids(body, {lang = "de"}), stream_ids(body, {lang = "de"}))
  end)

  it("the lang option must be language tags", function()
    for _, bad in ipairs({"", "en_US", "de;en", 5, ("a"):rep(300), " , "}) do
      local ok, err = pcall(svg.parse, HEAD .. "</svg>", {lang = bad})
      assert.is_false(ok)
      assert.matches("bad argument #2 to 'arclen.svg.parse' %(lang must be language tags", err)
    end
  end)
end)

describe("paint that shows (stroked, painted) #svgdoc", function()
  -- every shape under a stroke; those whose stroke paints nothing say so
  local STROKES = '<g stroke="black" fill="none">'
    .. line("black") .. line("none", 'stroke="none"') .. line("transparent", 'stroke="transparent"')
    .. line("rgba0", 'stroke="rgba(0, 0, 0, 0)"') .. line("rgba-half", 'stroke="rgba(0,0,0,0.5)"')
    .. line("rgb-slash0", 'stroke="rgb(10 20 30 / 0%)"') .. line("rgb-slash", 'stroke="rgb(10 20 30 / 1%)"')
    .. line("hsla0", 'stroke="hsla(120, 100%, 50%, 0)"') .. line("hsl", 'stroke="hsl(120deg 100% 50%)"')
    .. line("hex4-0", 'stroke="#fff0"') .. line("hex4", 'stroke="#FFF1"') .. line("hex8-0", 'stroke="#12345600"')
    .. line("hex8", 'stroke="#12345601"') .. line("hex6", 'stroke="#123456"') .. line("hex3", 'stroke="#123"')
    .. line("sop0", 'stroke-opacity="0"') .. line("sop0pc", 'style="stroke-opacity: 0%"')
    .. line("sop-neg", 'stroke-opacity="-2"') .. line("sop-small", 'stroke-opacity="1e-9"')
    .. line("op0", 'opacity="0"') .. line("sw0", 'stroke-width="0"') .. line("sw0mm", 'stroke-width="0mm"')
    .. line("sw-small", 'stroke-width="0.001"') .. line("sw-pc", 'stroke-width="5%"')
    .. line("named", 'stroke="RebeccaPurple"') .. line("system", 'stroke="CanvasText"')
    .. line("url", 'stroke="url(#grad)"') .. line("url-fallback", 'stroke="url(#missing) none"')
    .. line("style-wins", 'stroke="red" style="stroke: none"')
    .. line("url-missing", 'stroke="url(#missing)"') .. line("url-red", 'stroke="url(#missing) red"')
    .. line("url-not-server", 'stroke="url(#black)"') .. line("url-later", "stroke=\"url('#Later')\"")
    .. '</g><defs><linearGradient id="grad"/><pattern id="Later"/></defs>'
  local STROKED = {"black", "rgba-half", "rgb-slash", "hsl", "hex4", "hex8", "hex6", "hex3",
    "sop-small", "sw-small", "sw-pc", "named", "system", "url", "url-red", "url-later"}

  it("stroked: not none, not transparent, alpha > 0, stroke-opacity > 0, opacity > 0, width > 0", function()
    assert.are.same(STROKED, ids(STROKES, {stroked = true}))
  end)

  it("a url() that names no paint server paints its fallback, or nothing (SVG 2 section 13.2)", function()
    -- known when the ids were scanned first (a file, a string); a stream read once
    -- (a function, stdin) cannot know, and takes every url() to paint
    local stream = stream_ids(STROKES, {stroked = true})
    local expect = {}
    for _, id in ipairs(STROKED) do expect[#expect + 1] = id end
    table.insert(expect, 15, "url-fallback")
    table.insert(expect, 16, "url-missing")
    table.insert(expect, 18, "url-not-server")
    assert.are.same(expect, stream)
    local f = os.tmpname()
    local h = assert(io.open(f, "wb"))
    h:write(HEAD .. STROKES .. "</svg>")
    h:close()
    local got = {}
    svg.each(f, function(e) got[#got + 1] = e.id end, {stroked = true})
    os.remove(f)
    assert.are.same(STROKED, got)
  end)

  it("the default counts every shape whatever its paint; elements say stroked and filled", function()
    local doc = svg.parse(HEAD .. STROKES .. "</svg>")
    assert.are.equal(33, #doc.elements)
    local stroked = {}
    for _, e in ipairs(doc.elements) do
      if e.stroked then stroked[#stroked + 1] = e.id end
      assert.is_false(e.filled)                              -- fill="none" on the group
    end
    assert.are.same(STROKED, stroked)
  end)

  it("the graphviz background: stroke=\"transparent\" is not stroked, but its white fill paints", function()
    local name = "spec/data/svg/graphviz/pipeline.svg"
    local all, stroked, painted = svg.read(name), svg.read(name, {stroked = true}), svg.read(name, {painted = true})
    assert.are.equal(#all.elements - 1, #stroked.elements)
    assert.are.equal(#all.elements, #painted.elements)
    local bg = all.elements[1]
    assert.are.same({false, true}, {bg.stroked, bg.filled})
    -- the background's perimeter: 2 (485.18 + 90)
    assert.is_true(math.abs(all.total - stroked.total - 2 * (485.18 + 90)) < 1e-9)
  end)

  it("opacity is not inherited, but a group of opacity 0 hides its content", function()
    local body = '<g stroke="black">'
      .. '<g opacity="0">' .. line("under0", 'opacity="1"') .. '</g>'
      .. '<g style="opacity:0%"><g>' .. line("deep") .. '</g></g>'
      .. '<g opacity="0.5">' .. line("half", 'opacity="0.5"') .. '</g>'
      .. '<g opacity="x">' .. line("invalid") .. '</g>' .. '</g>'
    assert.are.same({"half", "invalid"}, ids(body, {stroked = true}))
    assert.are.same({"half", "invalid"}, ids(body, {painted = true}))
    assert.are.same({"under0", "deep", "half", "invalid"}, ids(body))
  end)

  it("stroke-width and the opacities inherit apart from the stroke (a child's stroke does not revive them)", function()
    local body = '<g stroke-width="0">' .. line("w0", 'stroke="red"') .. line("w1", 'stroke="red" stroke-width="1"') .. '</g>'
      .. '<g stroke-opacity="0">' .. line("o0", 'stroke="red"') .. line("o1", 'stroke="red" stroke-opacity=".5"') .. '</g>'
      .. '<g stroke="red">' .. line("inherits") .. '<g stroke="none">' .. line("restroked", 'stroke="blue"') .. '</g></g>'
    assert.are.same({"w1", "o1", "inherits", "restroked"}, ids(body, {stroked = true}))
  end)

  it("currentColor takes the element's color (inherited), transparent or not", function()
    local body = '<g stroke="currentColor" fill="none">' .. line("black")
      .. '<g color="transparent">' .. line("clear") .. line("blue", 'color="blue"')
      .. line("inherit", 'color="inherit"') .. line("bad", 'color="nonsense"') .. '</g>'
      .. '<g style="color: rgba(1,2,3,0)">' .. line("clear2") .. '</g>'
      .. line("current-color", 'color="currentColor"') .. '</g>'
    assert.are.same({"black", "blue", "current-color"}, ids(body, {stroked = true}))
  end)

  it("a value that does not parse is ignored: the inherited value stays", function()
    local body = '<g stroke="red">' .. line("bogus", 'stroke="bogus"') .. line("bad-hex", 'stroke="#12"')
      .. line("bad-fn", 'stroke="rgb(1,2)"') .. line("bad-fn2", 'stroke="rgb(1 2 3 4)"')
      .. line("neg-width", 'stroke-width="-1"') .. line("width-word", 'stroke-width="thick"')
      .. line("sop-word", 'stroke-opacity="none"') .. '</g>'
      .. '<g stroke="none">' .. line("n-bogus", 'stroke="bogus"') .. line("n-url", 'stroke="url(#a) bogus"') .. '</g>'
    assert.are.same({"bogus", "bad-hex", "bad-fn", "bad-fn2", "neg-width", "width-word", "sop-word"},
      ids(body, {stroked = true}))
  end)

  it("CSS's global keywords: inherit and unset keep the parent's, initial the initial value", function()
    local body = '<g stroke="red" stroke-width="0" fill="none">'
      .. line("inh", 'stroke="inherit"') .. line("ini-w", 'stroke-width="initial"')
      .. line("unset-w", 'stroke-width="unset"') .. line("ini-s", 'stroke="initial" stroke-width="2"')
      .. '</g>'
    assert.are.same({"ini-w"}, ids(body, {stroked = true}))
  end)

  it("painted: the stroke or the fill paints; fill is black by default; a <line> has no interior", function()
    local body = line("default-fill") .. line("no-fill", 'fill="none"')
      .. line("fill-op0", 'fill-opacity="0"') .. line("fill-clear", 'fill="transparent"')
      .. line("clear-stroked", 'fill="transparent" stroke="black"')
      .. '<line id="line-fill" x2="5" fill="red"/><line id="line-stroked" x2="5" stroke="red"/>'
      .. '<rect id="rect" width="1" height="1" fill="url(#p)"/><pattern id="p"/>'
      .. '<g fill="none" stroke="none">' .. '<circle id="invisible" r="1"/>' .. '</g>'
      .. '<g fill-opacity="0">' .. line("fop-child", 'fill="red"') .. '</g>'
      .. '<g opacity="0">' .. line("op0", 'fill="red" stroke="red"') .. '</g>'
    assert.are.same({"default-fill", "clear-stroked", "line-stroked", "rect"}, ids(body, {painted = true}))
    assert.are.same({"clear-stroked", "line-stroked"}, ids(body, {stroked = true}))
    assert.are.same(ids(body, {painted = true}), stream_ids(body, {painted = true}))
    local doc = svg.parse(HEAD .. body .. "</svg>")
    assert.are.equal(11, #doc.elements)
    assert.is_false(doc.elements[6].filled)                  -- line-fill
  end)

  it("context-fill and context-stroke: the <use>'s paint; none outside a use", function()
    local body = '<defs>' .. line("ctx", 'stroke="context-stroke" fill="context-fill"') .. '</defs>'
      .. '<use id="u1" href="#ctx" stroke="red" fill="none"/>'
      .. '<use id="u2" href="#ctx" stroke="transparent" fill="none"/>'
      .. '<use id="u3" href="#ctx" stroke="none" fill="blue"/>'
      .. line("outside", 'stroke="context-stroke" fill="context-fill"')
    local function uses(opts)
      local t = {}
      for _, e in ipairs(svg.parse(HEAD .. body .. "</svg>", opts).elements) do
        t[#t + 1] = e.use and ("use-" .. e.id) or e.id
      end
      return t
    end
    assert.are.same({"use-ctx"}, uses({stroked = true}))     -- u1 only
    assert.are.same({"use-ctx", "use-ctx"}, uses({painted = true}))   -- u1, u3
    assert.are.same({"use-ctx", "use-ctx", "use-ctx", "outside"}, uses())
  end)

  it("every CSS named colour (148) and system colour paints; transparent does not", function()
    local src = assert(io.open("src/svgdoc/paint.c")):read("*a")
    for _, list in ipairs({"NAMED", "SYSTEM"}) do
      local names = {}
      for n in src:match(list .. "%[%] = (%b{})"):gmatch('"([a-z]+)"') do names[#names + 1] = n end
      assert.are.equal(list == "NAMED" and 148 or 42, #names)
      for k = 2, #names do assert.is_true(names[k - 1] < names[k], names[k]) end   -- sorted for bsearch
      local t = {}
      for k, n in ipairs(names) do t[k] = line(n, ('stroke="%s"'):format(n:upper())) end
      assert.are.same(names, ids('<g fill="none">' .. table.concat(t) .. line("t", 'stroke="transparent"') .. "</g>",
        {painted = true}))
    end
  end)

  it("stroked and painted exclude each other; painted must be a boolean", function()
    local ok, err = pcall(svg.parse, HEAD .. "</svg>", {stroked = true, painted = true})
    assert.is_false(ok)
    assert.matches("stroked and painted exclude each other", err)
    ok, err = pcall(svg.read, "x.svg", {painted = 1})
    assert.is_false(ok)
    assert.matches("painted must be a boolean", err)
  end)

  it("colour syntax: long and odd values stay linear and never hang", function()
    local long = ("0 "):rep(100000)
    local body = '<g stroke="red">' .. line("a", ('stroke="rgb(%s)"'):format(long))
      .. line("b", ('stroke="#%s"'):format(("f"):rep(100000))) .. line("c", 'stroke="rgb(((("')
      .. line("d", 'stroke="url(#x"') .. line("e", 'stroke="rgba(1,2,3,4,5)"') .. '</g>'
    local t0 = os.clock()
    assert.are.same({"a", "b", "c", "d", "e"}, ids(body, {stroked = true}))   -- all invalid: red stays
    assert.is_true(os.clock() - t0 < 2 * TIME_SCALE, "colours took " .. (os.clock() - t0))
  end)
end)

-- The command line through a POSIX shell: not on Windows (tools/check-windows.sh).
local describe_sh = package.config:sub(1, 1) == "/" and describe or function() end

describe_sh("the command line: --painted, --stroked, --lang #svgdoc", function()
  local helpers = require("helpers")
  local MAIN = os.tmpname()   -- arclen.cli from this Lua's search paths
  local f = assert(io.open(MAIN, "w"))
  f:write('require("arclen.cli").main(arg)\n')
  f:close()
  teardown(function() os.remove(MAIN) end)
  -- stdout and stderr of the command line under this Lua, then "rc=N"
  local function run(args)
    local p = assert(io.popen(("LUA_PATH=%s LUA_CPATH=%s %s %s %s 2>&1; echo \"rc=$?\""):format(
      helpers.shquote(package.path), helpers.shquote(package.cpath), helpers.interpreter(),
      helpers.shquote(MAIN), args)))
    local out = p:read("*a")
    p:close()
    return out
  end
  it("counts by mode, and refuses both modes at once", function()
    local f = "spec/data/svg/graphviz/pipeline.svg"
    local n_all = select(2, run("length " .. f):gsub("\n", "")) - 2
    local n_str = select(2, run("length --stroked " .. f):gsub("\n", "")) - 2
    local n_pai = select(2, run("length --painted " .. f):gsub("\n", "")) - 2
    assert.are.same({n_all - 1, n_all}, {n_str, n_pai})
    assert.matches("%-%-stroked and %-%-painted exclude each other.*rc=2", run("length --stroked --painted " .. f))
  end)
  it("--lang picks the switch's child", function()
    local f = os.tmpname()
    local h = assert(io.open(f, "w"))
    h:write(HEAD, '<switch>', line("de", 'systemLanguage="de"'), '<path id="en" d="M0 0 L3 0"/></switch></svg>')
    h:close()
    assert.matches("^en\t3\n", run("length " .. f))
    assert.matches("^de\t10\n", run("length --lang de-CH,de " .. f))
    assert.matches("%-%-lang: 'de_CH' is not a list of language tags.*rc=2", run("length --lang de_CH " .. f))
    os.remove(f)
  end)
end)
