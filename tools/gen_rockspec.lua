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
-- The areas of the core and the binding: every .c under src/.
local csrc = ls("find src -name '*.c'")
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
  -- LuaExpat is needed by the SVG document reader (arclen.svg) only and
  -- dkjson by the command line's --json only; both are loaded when first
  -- used, and the core and path data parsing need neither.
  'dependencies = { "lua >= 5.1", "luaexpat >= 1.3", "dkjson >= 2.5" }',
  'build = {',
  '  type = "builtin",',
  '  modules = {',
  '    ["arclen.core"] = {',
  '      sources = {',
}
for _, f in ipairs(csrc) do lines[#lines + 1] = ('        "%s",'):format(f) end
lines[#lines + 1] = '      },'
lines[#lines + 1] = '      defines = { "_POSIX_C_SOURCE=200809L" },'
lines[#lines + 1] = '      libraries = { "m" },'
lines[#lines + 1] = '      incdirs = { "src" },'
lines[#lines + 1] = '    },'
for _, f in ipairs(lmods) do
  local mod = f:match("^lua/(.*)%.lua$"):gsub("/", "."):gsub("%.init$", "")
  lines[#lines + 1] = ('    ["%s"] = "%s",'):format(mod, f)
end
lines[#lines + 1] = '  },'
lines[#lines + 1] = '  install = { bin = { arclen = "bin/arclen" } },'
lines[#lines + 1] = '}'
io.write(table.concat(lines, "\n"), "\n")
