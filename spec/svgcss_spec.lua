-- spec/svgcss_spec.lua -- <style> sheets in arclen.svg: what each selector
-- kind matches, the cascade's order (SVG 2 section 6.3), @media and
-- @import, what the stream does with a late sheet, the font-size behind
-- em/ex/rem, and bad input (malformed CSS, selectors we refuse, huge
-- sheets, pathological selectors: warnings and caps, never a hang).  The
-- whole documents hand/css.svg, hand/em.svg and real/rust-favicon.svg are
-- checked against tools/ref_svg.py (tinycss2 + cssselect2) by svgdoc_spec.
local svg = require("helpers").optional("arclen.svg")   -- #svgdoc specs need it
-- time limits stretched for valgrind and sanitizer runs
local TIME_SCALE = tonumber(os.getenv("ARCLEN_TIME_SCALE")) or 1

local HEAD = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" ' ..
             'viewBox="0 0 100 100">'

local function doc(body, opts)
  return svg.parse(HEAD .. body .. "</svg>", opts, "t.svg")
end

-- the ids drawn, in order
local function ids(d)
  local t = {}
  for i, e in ipairs(d.elements) do t[i] = e.id or e.tag end
  return table.concat(t, " ")
end

local function warned(d, pattern)
  for _, w in ipairs(d.warnings) do
    if w:find(pattern, 1, true) then return true end
  end
  return false
end

describe("arclen.svg: style sheets #svgdoc", function()
  it("Illustrator's export: classes stroke the cut lines, .st2 hides the guides", function()
    local body = [[<style>.st0{fill:none;stroke:#000;stroke-width:0.25} .st2{display:none}</style>
      <g id="Cut"><path id="p" class="st0" d="M0 0h10"/><circle id="c" class="st0" r="1"/></g>
      <g id="Guides" class="st2"><rect id="r" width="10" height="10"/></g>]]
    assert.are.equal("p c", ids(doc(body, {stroked = true})))
    assert.are.equal("p c", ids(doc(body)))
    assert.are.equal("p c r", ids(doc(body, {hidden = true})))
  end)

  it("orders attribute < sheet < style < sheet !important < style !important", function()
    local d = doc([[<style>.s{stroke:red} .n{stroke:none} .I{stroke:red !important}
        .N{stroke:none !important}</style>
      <path id="sheet-over-attr" class="s" stroke="none" d="M0 0h1"/>
      <path id="style-over-sheet" class="s" style="stroke:none" d="M0 0h1"/>
      <path id="imp-over-style" class="I" style="stroke:none" d="M0 0h1"/>
      <path id="styleimp-over-imp" class="N" style="stroke:red!important" d="M0 0h1"/>
      <path id="attr-under-sheet" class="n" stroke="red" d="M0 0h1"/>]], {stroked = true})
    assert.are.equal("sheet-over-attr imp-over-style styleimp-over-imp", ids(d))
  end)

  it("carries every property of the reader's list: the paint's too", function()
    local body = [[<style>.t{stroke:transparent} .o{opacity:0} .so{stroke-opacity:0}
        .f{fill:red} .nf{fill:none} g.c{color:red} .cc{stroke:currentColor}</style>
      <path id="t" class="t" stroke="black" d="M0 0h1"/><path id="o" class="o" stroke="black" d="M0 0h1"/>
      <path id="so" class="so" stroke="black" d="M0 0h1"/><rect id="f" class="f nf" width="1" height="1"/>
      <rect id="nf" class="nf" width="1" height="1"/><g class="c"><path id="cc" class="cc" d="M0 0h1"/></g>]]
    assert.are.equal("cc", ids(doc(body, {stroked = true})))
    -- painted: t and so fill (black, the initial fill); .nf wins over .f (later)
    assert.are.equal("t so cc", ids(doc(body, {painted = true})))
    assert.are.equal("t o so f nf cc", ids(doc(body)))
  end)

  it("specificity first (id > class > type), then the later rule", function()
    local d = doc([[<style>#a{stroke:red} .c{stroke:none} path.c{stroke:red} .c{stroke:none}
        .x{stroke:none} .y{stroke:red} path{stroke:none} *{stroke:red}</style>
      <path id="a" class="c" d="M0 0h1"/><path id="b" class="c" d="M0 0h1"/>
      <path id="xy" class="y x" d="M0 0h1"/><path id="t" d="M0 0h1"/>]], {stroked = true})
    assert.are.equal("a b xy", ids(d))
  end)

  it("matches type, *, #id, .class, attributes, descendants, children, :first-child, :root", function()
    local d = doc([[<style>
        :root > g > line:first-child { stroke: red }
        svg g.k line + line { stroke: red }
        [data-x] { stroke: red }  [data-y="a b"] { stroke: red }  [data-z~=b] { stroke: red }
        [lang|=en] { stroke: red } [data-p^=ab] { stroke: red } [data-s$=yz] { stroke: red }
        [data-m*=mm] { stroke: red } #q\:r { stroke: red } .\31 23 { stroke: red }
        LINE { stroke: red } line:hover { stroke: red } line::before { stroke: red }</style>
      <g class="k"><line id="first" x2="1"/><line id="second" x2="1"/></g>
      <line id="x" data-x="" x2="1"/><line id="y" data-y="a b" x2="1"/>
      <line id="z" data-z="a b c" x2="1"/><line id="en" lang="en-US" x2="1"/>
      <line id="eng" lang="eng" x2="1"/><line id="p" data-p="abc" x2="1"/>
      <line id="s" data-s="xyz" x2="1"/><line id="m" data-m="ummm" x2="1"/>
      <line id="q:r" x2="1"/><line id="num" class="123" x2="1"/>]], {stroked = true})
    -- the sibling rule is refused whole; LINE does not match <line> (XML is
    -- case-sensitive); :hover and ::before match nothing in a drawing
    assert.are.equal("first x y z en p s m q:r num", ids(d))
    assert.is_true(warned(d, "t.svg:1:"))
    assert.is_true(warned(d, "sibling combinators (+, ~) are not supported"))
  end)

  it("finds ancestors by any class word, id or type, and forgets closed ones", function()
    local d = doc([[<style>.c3 .x{stroke:red} #i g .y{stroke:red} defs ~ .z{stroke:red}
        switch .w{stroke:red}</style>
      <g class="c1 c2  c3"><g><path id="a" class="x" d="M0 0h1"/></g></g>
      <path id="b" class="x" d="M0 0h1"/>
      <g id="i"><g><g><path id="c" class="y" d="M0 0h1"/></g></g></g>
      <g id="i2"><g><path id="d" class="y" d="M0 0h1"/></g></g>
      <switch><path id="e" class="w" d="M0 0h1"/></switch>]], {stroked = true})
    assert.are.equal("a c e", ids(d))
  end)

  it("refuses what a stream cannot decide, with a warning, and keeps the other rules", function()
    for _, sel in ipairs({"line:last-child", "line:only-child", "line:nth-child(2)",
                          "line:not(.a)", "g:empty", "line:last-of-type", "a ~ line",
                          "svg|line", "[xlink|href]"}) do
      local d = doc("<style>" .. sel .. "{display:none} line{stroke:red}</style><g><line x2='1'/></g>",
        {stroked = true})
      assert.are.equal(1, #d.elements, sel)
      assert.are.equal(1, #d.warnings, sel)
      assert.matches("t.svg:1:%d+: style sheet: rule '.*' ignored: ", d.warnings[1])
    end
  end)

  it("@media for a plain screen: all and screen hold; print, features and dark do not", function()
    local d = doc([[<style>@media screen { #a{stroke:red} } @media all and (min-width: 1px) { #b{stroke:red} }
        @media print { #c{stroke:red} } @media not print { #d{stroke:red} }
        @media only screen, print { #e{stroke:red} } @media (prefers-color-scheme: dark) { #f{stroke:red} }
        @media not (color) { #g{stroke:red} }</style>
      <style media="print">#h{stroke:red}</style><style media="screen, print">#i{stroke:red}</style>
      <style type="text/plain">#j{stroke:red}</style>
      <path id="a" d="M0 0h1"/><path id="b" d="M0 0h1"/><path id="c" d="M0 0h1"/>
      <path id="d" d="M0 0h1"/><path id="e" d="M0 0h1"/><path id="f" d="M0 0h1"/>
      <path id="g" d="M0 0h1"/><path id="h" d="M0 0h1"/><path id="i" d="M0 0h1"/>
      <path id="j" d="M0 0h1"/>]], {stroked = true})
    assert.are.equal("a d e i", ids(d))
  end)

  it("the CSS transform property is not read: a warning says so", function()
    local d = doc([[<style>path{transform:scale(2)} g{transform:rotate(9deg)}</style>
      <path d="M0 0h1"/>]])
    assert.are.equal(1, d.total)
    assert.are.equal(1, #d.warnings)
    assert.matches("t.svg:1:%d+: style sheet: the CSS transform property is not read", d.warnings[1])
  end)

  it("@import is a warning; its rules are left out", function()
    local d = doc([[<style>@import url("more.css"); path{stroke:red}</style><path d="M0 0h1"/>]],
      {stroked = true})
    assert.are.equal(1, #d.elements)
    assert.is_true(warned(d, "t.svg:1:") and warned(d, "@import is not read"))
  end)

  it("a <use> copy takes the rules that match the referenced element where it is", function()
    local d = doc([[<style>defs .p{stroke:red} .g path{display:none} use{stroke:none}</style>
      <defs><path id="p" class="p" d="M0 0h2"/></defs>
      <g class="g"><use id="u" xlink:href="#p"/></g><use href="#later"/>
      <g id="later"><path class="p" id="q" d="M0 0h3"/></g>]], {stroked = true})
    -- #p is drawn through the use, stroked by its own rule (not the use's);
    -- #later's path is under no <defs>: the use's stroke:none is inherited
    assert.are.equal("p", ids(d))
    assert.are.equal(2, d.total)
  end)

  it("a sheet after the elements it styles: later elements only, with a warning", function()
    local text = HEAD .. [[<path id="before" class="s" d="M0 0h1"/>
      <style>.s{stroke:red}</style><path id="after" class="s" d="M0 0h1"/></svg>]]
    local d = svg.parse(text, {stroked = true}, "t.svg")
    assert.are.equal("after", ids(d))
    assert.is_true(warned(d, "t.svg:2:7: style sheet after 1 shapes or uses: it applies only"))
    local seen = {}
    local sum = svg.each(function() local t = text; text = nil; return t end,
      function(e) seen[#seen + 1] = e.id end, {stroked = true})
    assert.are.equal("after", table.concat(seen, " "))
    assert.are.equal(1, sum.count)
  end)

  it("reads malformed CSS as CSS does: bad parts dropped, the rest kept, no error", function()
    for _, sheet in ipairs({
      "path{stroke:red}  }}} {{ ; @ ",                   -- stray braces, an empty at-rule
      "path{stroke:red} /* unclosed comment",
      "path{color:'unclosed\n;stroke:red}",
      "path{stroke red; stroke:red}",                   -- a bad declaration, then a good one
      "path{stroke:red} @media screen { path{stroke:red",   -- unclosed blocks
      "<!-- path{stroke:red} -->",
      "p/**/ath, path{stroke:red}",                     -- a comment between tokens
      "@font-face { src: url(x) } @namespace x url(y); path{stroke:red}",
    }) do
      local d = doc("<style><![CDATA[" .. sheet .. "]]></style><path d='M0 0h1'/>", {stroked = true})
      assert.are.equal(1, #d.elements, sheet)
    end
    -- nothing of a garbage sheet applies
    local d = doc("<style>#%! {{{ ((( [[[ ''' \"\"\" \\</style><path d='M0 0h1'/>", {stroked = true})
    assert.are.equal(0, #d.elements)
  end)

  it("caps: a huge sheet, long selectors, many selectors, deep documents stay fast", function()
    -- more than 4 MiB of sheets: that sheet is ignored, with a warning
    local big = ("a{stroke:red}"):rep(400000)
    local d = doc("<style>" .. big .. "</style><style>path{stroke:red}</style><path d='M0 0h1'/>",
      {stroked = true})
    assert.is_true(warned(d, "style sheets longer than 4194304 bytes in all"))
    assert.are.equal(1, #d.elements)        -- the next sheet, within the cap, applies
    -- 33 compounds: refused
    d = doc("<style>" .. ("g "):rep(32) .. "path{stroke:red}</style><path d='M0 0h1'/>", {stroked = true})
    assert.is_true(warned(d, "too many compounds in one selector"))
    -- 31 descendant compounds over 900 nested groups: each (compound, ancestor)
    -- pair is tried once, not every way of choosing ancestors
    local t0 = os.clock()
    local deep = ("<g>"):rep(900) .. "<path d='M0 0h1'/>" .. ("</g>"):rep(900)
    d = doc("<style>" .. ("g "):rep(30) .. "path{stroke:red} " .. ("* "):rep(30) ..
            "rect{stroke:red}</style>" .. deep, {stroked = true})
    assert.are.equal(1, #d.elements)
    assert.is_true(os.clock() - t0 < 5 * TIME_SCALE, "deep descendant matching took " .. (os.clock() - t0))
    -- selectors that fail only at the root, on 990 nested groups (their keys are all
    -- there: no g holds the root): matching stops at the cap (2e8 tests and 200 a
    -- byte), an error at the element, in about a second
    local sels = {}
    for i = 1, 2000 do sels[i] = "g svg " .. ("* "):rep(29) .. "*" end
    t0 = os.clock()
    local ok, err = pcall(doc, "<style>" .. table.concat(sels, ",") .. "{stroke:red}</style>" ..
      ("<g>"):rep(990) .. "<path d='M0 0h1'/>" .. ("</g>"):rep(990))
    assert.is_false(ok)
    assert.matches("^t%.svg:1:%d+: style sheet: matching its selectors takes more than %d+ tests", err)
    assert.is_true(os.clock() - t0 < 30 * TIME_SCALE, "the cap took " .. (os.clock() - t0))
    -- more than 65536 selectors: the rest are left out, with a warning
    local many = {}
    for i = 1, 70000 do many[i] = ".c" .. i end
    d = doc("<style>" .. table.concat(many, ",") .. "{stroke:red} path{stroke:red}</style>" ..
            "<path class='c1' d='M0 0h1'/>", {stroked = true})
    assert.is_true(warned(d, "more than 65536 selectors"))
  end)
end)

describe("arclen.svg: em, ex and rem from font-size #svgdoc", function()
  it("the issue's rect: 2em x 1em at font-size 10px is 20 x 10", function()
    local d = doc('<rect width="2em" height="1em" style="font-size:10px"/>')
    assert.are.equal(60, d.total)
  end)
  it("inherits, from attributes, style and sheets; rem is the root's", function()
    local d = svg.parse([[<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9" style="font-size:8px">
      <style>g{font-size:150%}</style><g><line x2="1em"/><line x2="1rem" font-size="3"/>
      <line x2="2ex"/><g style="font-size:0.5em"><line x2="1em"/></g></g></svg>]])
    local L = {}
    for i, e in ipairs(d.elements) do L[i] = e.length end
    assert.are.same({12, 8, 12, 6}, L)
  end)
  it("an invalid font-size is warned of and the parent's is used", function()
    local d = doc('<g font-size="20"><line x2="1em" style="font-size:huge"/></g>')
    assert.are.equal(20, d.total)
    assert.is_true(warned(d, "font-size 'huge' is not a valid value: ignored"))
  end)
  it("a linked sheet (<?xml-stylesheet?>) is not fetched, and is warned of", function()
    local d = svg.parse('<?xml version="1.0"?>\n<?xml-stylesheet type="text/css" href="a.css"?>\n'
      .. HEAD .. '<line x2="3" stroke="red"/></svg>', {}, "t.svg")
    assert.are.equal(3, d.total)
    assert.is_true(warned(d, "2:1: <?xml-stylesheet type=\"text/css\" href=\"a.css\"?> is not read"))
    assert.has_error(function()
      svg.parse('<?xml-stylesheet href="a.css"?>' .. HEAD .. '</svg>', {strict = true}, "t.svg")
    end)
  end)
  it("an invalid declaration is dropped: the next origin of the cascade applies", function()
    -- CSS Syntax 3 section 5 and SVG 2 section 6.6: an invalid style or sheet value
    -- does not hide the presentation attribute or a weaker sheet rule
    local d = doc('<style>.a{stroke:blue} .b{stroke:nonsense} .c{stroke-width:-2 !important}</style>'
      .. '<line id="attr" x2="1" stroke="red" style="stroke: nonsense"/>'
      .. '<line id="sheet" x2="2" class="a" style="stroke: #12"/>'
      .. '<line id="weaker" x2="4" class="a b"/>'
      .. '<line id="none" x2="8" stroke="none" style="stroke: bogus"/>'
      .. '<line id="width" x2="16" stroke="red" class="c" stroke-width="0"/>'
      .. '<line id="size" x2="1em" stroke="red" font-size="5" style="font-size: huge"/>', {stroked = true})
    assert.are.equal("attr sheet weaker size", ids(d))
    assert.are.equal(1 + 2 + 4 + 5, d.total)
    assert.is_true(warned(d, "stroke 'nonsense' is not a valid value: ignored"))
    assert.is_true(warned(d, "stroke-width '-2' is not a valid value: ignored"))
  end)
end)
