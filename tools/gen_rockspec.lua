-- tools/gen_rockspec.lua -- write rockspec/arclen-scm-1.rockspec from the
-- files in src/ and lua/arclen/ (LuaRocks' builtin backend needs every
-- source listed; spec/rockspec_spec.lua checks the list is current).
-- Run: lua5.4 tools/gen_rockspec.lua > rockspec/arclen-scm-1.rockspec
local function ls(cmd)
  local out = {}
  for name in io.popen(cmd):lines() do out[#out + 1] = name end
  table.sort(out)
  return out
end
-- The areas of the core and the binding: every .c under src/ but the
-- document reader's (src/svgdoc/ and its binding), a module of its own.
local csrc = ls("find src -name '*.c' ! -path 'src/svgdoc/*' ! -name svgdoc.c")
local core = ls("find src -name '*.c' ! -path 'src/svgdoc/*' ! -path 'src/lua/*'")
local docsrc = ls("find src/svgdoc -name '*.c'")
local lmods = ls("find lua/arclen -name '*.lua'")
local lines = {
  'package = "arclen"',
  'version = "scm-1"',
  'source = { url = "git+file://." }',
  'description = {',
  '  summary = "Arc length of cubic Bezier curves: exact, elliptic, MetaPost-faithful",',
  '  detailed = [[A C99 core bound for Lua: error-controlled length and its inverse,',
  '  Carlson elliptic integrals, MetaPost arclength/arctime bit for bit, Gravesen',
  '  subdivision, Walter & Fournier length fits, Floater conic approximations.]],',
  '  license = "MIT",',
  '}',
  -- dkjson is needed by the command line's --json only, loaded when first
  -- used.  The SVG document reader (arclen.svgdoc) links libexpat; the
  -- core and path data parsing need nothing but libm.
  'dependencies = { "lua >= 5.1", "dkjson >= 2.5" }',
  'external_dependencies = { EXPAT = { header = "expat.h" } }',
  'build = {',
  '  type = "builtin",',
  '  modules = {',
}
-- A C module: its sources (lists, in order), libraries and directories.
local function c_module(name, sources, libraries, incdirs, libdirs)
  lines[#lines + 1] = ('    ["%s"] = {'):format(name)
  lines[#lines + 1] = '      sources = {'
  for _, list in ipairs(sources) do
    for _, f in ipairs(list) do lines[#lines + 1] = ('        "%s",'):format(f) end
  end
  lines[#lines + 1] = '      },'
  lines[#lines + 1] = '      defines = { "_POSIX_C_SOURCE=200809L" },'
  if libraries then lines[#lines + 1] = ('      libraries = { %s },'):format(libraries) end
  lines[#lines + 1] = ('      incdirs = { %s },'):format(incdirs)
  if libdirs then lines[#lines + 1] = ('      libdirs = { %s },'):format(libdirs) end
  lines[#lines + 1] = '    },'
end
c_module("arclen.core", {csrc}, nil, '"src"')
c_module("arclen.svgdoc", {{"src/lua/svgdoc.c", "src/lua/subpaths.c"}, docsrc, core},
  '"expat"', '"src", "$(EXPAT_INCDIR)"', '"$(EXPAT_LIBDIR)"')
for _, f in ipairs(lmods) do
  local mod = f:match("^lua/(.*)%.lua$"):gsub("/", "."):gsub("%.init$", "")
  lines[#lines + 1] = ('    ["%s"] = "%s",'):format(mod, f)
end
lines[#lines + 1] = '  },'
-- libm is a library of its own on Unix only; on Windows it is part of the
-- C runtime, and MSVC would look for an m.lib.  (LuaRocks merges these
-- lists into the modules' element by element: the whole list is given.)
lines[#lines + 1] = '  platforms = {'
lines[#lines + 1] = '    unix = {'
lines[#lines + 1] = '      modules = {'
lines[#lines + 1] = '        ["arclen.core"] = { libraries = { "m" } },'
lines[#lines + 1] = '        ["arclen.svgdoc"] = { libraries = { "expat", "m" } },'
lines[#lines + 1] = '      },'
lines[#lines + 1] = '    },'
lines[#lines + 1] = '  },'
lines[#lines + 1] = '  install = { bin = { arclen = "bin/arclen" } },'
lines[#lines + 1] = '}'
io.write(table.concat(lines, "\n"), "\n")
