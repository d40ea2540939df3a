-- tools/gen_rockspec.lua -- write arclen's rockspecs from the files in src/
-- and lua/arclen/ (LuaRocks' builtin backend needs every source listed;
-- spec/rockspec_spec.lua checks that the committed ones are current).
--   lua5.4 tools/gen_rockspec.lua PACKAGE VERSION [URL]
-- prints the rockspec of PACKAGE ("arclen", the core, or "arclen-svg", the
-- SVG document reader over expat) at VERSION ("scm-1" or "1.0.0-1"); URL
-- replaces the release archive's name as its source (tools/pack-rock.sh).
--   lua5.4 tools/gen_rockspec.lua --write
-- writes all four: rockspec/arclen{,-svg}-{scm-1,VERSION-1}.rockspec, the
-- release at the version of src/arclen.h's ARCLEN_VERSION.
local function ls(cmd)
  local out = {}
  for name in io.popen(cmd):lines() do out[#out + 1] = name end
  table.sort(out)
  return out
end

-- "1.0.0" from src/arclen.h (arclen._VERSION is "arclen 1.0.0").
local function release_version()
  local f = assert(io.open("src/arclen.h"))
  local v = f:read("*a"):match('#define ARCLEN_VERSION "arclen ([%d.]+)"')
  f:close()
  return assert(v, "src/arclen.h: no ARCLEN_VERSION")
end

-- A C module: its sources (lists, in order), libraries and directories.
local function c_module(lines, name, sources, libraries, incdirs, libdirs)
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

-- Each rock's description, as the rockspec writes it.
local DESCRIPTION = {
  arclen = [==[description = {
  summary = "Arc length of cubic Bezier curves: exact, elliptic, MetaPost-faithful",
  detailed = [[A C99 core bound for Lua: error-controlled length and its inverse,
  Carlson elliptic integrals, MetaPost arclength/arctime bit for bit, Gravesen
  subdivision, Walter & Fournier length fits, Floater conic approximations,
  paths from SVG path data. SVG documents need the rock arclen-svg; the
  command line's --json needs dkjson.]],
  license = "MIT",
}]==],
  ["arclen-svg"] = [==[description = {
  summary = "SVG documents for arclen: the reader arclen.svg drives (over expat)",
  detailed = [[The C module arclen.svgdoc, a streaming SVG document reader over
  libexpat: require "arclen.svg" (in the rock arclen) needs it.]],
  license = "MIT",
}]==],
}

local function rockspec(package, version, url)
  local scm = version:match("^scm") ~= nil
  local base = version:match("^(.-)%-%d+$")          -- "1.0.0" of "1.0.0-1"
  -- The source: a clone for scm (luarocks make builds the work tree); for a
  -- release, the archive tools/pack-rock.sh makes of the tagged tree: arclen
  -- has no download site, so the release is the .src.rock that make rock
  -- packs with the archive inside (luarocks build of this rockspec finds
  -- the archive in the current directory).
  local source
  if scm then
    source = 'source = { url = "git+file://." }'
  else
    source = ('source = { url = "%s", dir = "arclen-%s" }'):format(
      url or ("arclen-" .. base .. ".tar.gz"), base)
  end
  -- The areas of the core and the binding: every .c under src/ but the
  -- document reader's (src/svgdoc/ and its binding), a module of its own.
  local csrc = ls("find src -name '*.c' ! -path 'src/svgdoc/*' ! -name 'svgdoc*.c'")
  local core = ls("find src -name '*.c' ! -path 'src/svgdoc/*' ! -path 'src/lua/*'")
  local docsrc = ls("find src/svgdoc -name '*.c'")
  local lmods = ls("find lua/arclen -name '*.lua'")
  local lines = {('package = "%s"'):format(package), ('version = "%s"'):format(version), source}
  lines[#lines + 1] = DESCRIPTION[package]
  if package == "arclen" then
    -- Nothing but Lua and libm: dkjson (the command line's --json) and the
    -- document reader (arclen-svg, over expat) are optional, and say so.
    lines[#lines + 1] = 'dependencies = { "lua >= 5.1" }'
  else
    lines[#lines + 1] = ('dependencies = { "lua >= 5.1", "%s" }'):format(
      scm and "arclen" or ("arclen == " .. base))
    -- zlib (gzip input, .svgz) where it is at home: on Unix; a Windows
    -- build reads uncompressed documents and says so of gzip ones
    lines[#lines + 1] = 'external_dependencies = { EXPAT = { header = "expat.h" },'
    lines[#lines + 1] = '  platforms = { unix = { ZLIB = { header = "zlib.h" } } } }'
  end
  lines[#lines + 1] = 'build = {'
  lines[#lines + 1] = '  type = "builtin",'
  lines[#lines + 1] = '  modules = {'
  if package == "arclen" then
    c_module(lines, "arclen.core", {csrc}, nil, '"src"')
    for _, f in ipairs(lmods) do
      local mod = f:match("^lua/(.*)%.lua$"):gsub("/", "."):gsub("%.init$", "")
      lines[#lines + 1] = ('    ["%s"] = "%s",'):format(mod, f)
    end
    lines[#lines + 1] = '  },'
    lines[#lines + 1] = '  install = { bin = { arclen = "bin/arclen" } },'
  else
    c_module(lines, "arclen.svgdoc", {{"src/lua/svgdoc.c", "src/lua/svgdoc_gzip.c", "src/lua/subpaths.c"},
      docsrc, core},
      '"expat"', '"src", "$(EXPAT_INCDIR)"', '"$(EXPAT_LIBDIR)"')
    lines[#lines + 1] = '  },'
  end
  -- libm is a library of its own on Unix only; on Windows it is part of
  -- the C runtime, and MSVC would look for an m.lib.  (LuaRocks merges
  -- these lists into the modules' element by element: the whole list.)
  lines[#lines + 1] = '  platforms = {'
  lines[#lines + 1] = '    unix = {'
  lines[#lines + 1] = '      modules = {'
  if package == "arclen" then
    lines[#lines + 1] = '        ["arclen.core"] = { libraries = { "m" } },'
  else
    lines[#lines + 1] = '        ["arclen.svgdoc"] = { libraries = { "expat", "z", "m" },'
    lines[#lines + 1] = '          defines = { "_POSIX_C_SOURCE=200809L", "ARCLEN_HAVE_ZLIB" },'
    lines[#lines + 1] = '          incdirs = { "src", "$(EXPAT_INCDIR)", "$(ZLIB_INCDIR)" },'
    lines[#lines + 1] = '          libdirs = { "$(EXPAT_LIBDIR)", "$(ZLIB_LIBDIR)" } },'
  end
  lines[#lines + 1] = '      },'
  lines[#lines + 1] = '    },'
  lines[#lines + 1] = '  },'
  lines[#lines + 1] = '}'
  return table.concat(lines, "\n") .. "\n"
end

local PACKAGES = {"arclen", "arclen-svg"}

if arg[1] == "--write" then
  for _, package in ipairs(PACKAGES) do
    for _, version in ipairs({"scm-1", release_version() .. "-1"}) do
      local name = ("rockspec/%s-%s.rockspec"):format(package, version)
      local f = assert(io.open(name, "w"))
      f:write(rockspec(package, version))
      f:close()
    end
  end
elseif arg[1] == "--release" then   -- the release version, for scripts
  io.write(release_version(), "\n")
else
  local package, version, url = arg[1], arg[2], arg[3]
  local known = false
  for _, p in ipairs(PACKAGES) do known = known or p == package end
  if not known or not version or not (version:match("^scm%-%d+$") or version:match("^[%d.]+%-%d+$")) then
    io.stderr:write("usage: lua tools/gen_rockspec.lua (arclen|arclen-svg) (scm-1|X.Y.Z-1) [URL]\n",
      "       lua tools/gen_rockspec.lua --write | --release\n")
    os.exit(2)
  end
  io.write(rockspec(package, version, url))
end
