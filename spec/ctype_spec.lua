-- spec/ctype_spec.lua -- the SVG document reader under LC_CTYPE =
-- tr_TR.UTF-8, where the C library's tolower('I') is 'I' (Turkish has a
-- dotless i): units, style values and messages must read as in the C
-- locale.  A host may set it (os.setlocale("tr_TR.UTF-8") sets every
-- category).  Each test puts back the locale it found.  The locale must
-- exist: without it this spec fails.
local svg = require("helpers").optional("arclen.svg")   -- #svgdoc specs need it

local NAMES = {"tr_TR.UTF-8", "tr_TR.utf8"}
local HOWTO = "the locale tr_TR.UTF-8 is missing: as root, install the Debian package "
  .. "'locales' and run `localedef -i tr_TR -f UTF-8 tr_TR.UTF-8`"
local H = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">'

-- f() under LC_CTYPE = tr_TR.UTF-8; the previous locale back afterwards.
local function under_turkish(f)
  return function()
    local before = os.setlocale(nil, "ctype")
    local found
    for _, name in ipairs(NAMES) do
      if os.setlocale(name, "ctype") then found = name break end
    end
    if not found then error(HOWTO, 0) end
    -- Lua's string.lower is the C library's tolower: under this locale it
    -- must leave 'I' alone, else the test proves nothing (LuaJIT lowers
    -- ASCII itself)
    local ok, err = pcall(function()
      if type(jit) ~= "table" then
        assert(("I"):lower() == "I", "under " .. found .. " tolower('I') is not 'I'")
      end
      f()
    end)
    os.setlocale(before, "ctype")
    if not ok then error(err, 0) end
  end
end

describe("arclen.svg under LC_CTYPE = tr_TR.UTF-8 #svgdoc", function()
  it("reads units in capitals: 1IN is 96 user units, 2MM and 3PT as in C", under_turkish(function()
    local d = svg.parse(H .. '<rect width="1IN" height="2MM"/><line x2="3PT"/></svg>')
    assert.equal(2, #d.elements)
    assert.near(2 * (96 + 2 * 96 / 25.4), d.elements[1].length, 1e-12 * 200)
    assert.near(3 * 96 / 72, d.elements[2].length, 1e-12 * 4)
  end))

  it("reads style values in capitals: VISIBILITY:HIDDEN hides", under_turkish(function()
    local d = svg.parse(H .. '<path d="M0 0 H1" style="visibility:HIDDEN"/>'
      .. '<path d="M0 0 H2" display="INLINE"/></svg>')
    assert.equal(1, #d.elements)
    assert.equal(2, d.elements[1].length)
  end))

  it("names an unknown unit in lower case, as in C", under_turkish(function()
    local ok, e = pcall(svg.parse, H .. '<rect width="3INCH" height="1"/></svg>', nil, "bad.svg")
    assert.is_false(ok)
    assert.matches("width='3INCH': unknown unit 'inch'$", e)
  end))
end)
