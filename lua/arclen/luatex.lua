-- arclen/luatex.lua -- load arclen inside a LuaTeX run (\directlua, or a
-- Lua file run by luatex/lualatex), from a clone or an unpacked copy:
--
--   \directlua{dofile("lua/arclen/luatex.lua")(".")}   % root = the clone
--   local arclen = dofile(ROOT .. "/lua/arclen/luatex.lua")(ROOT [, BUILD])
--
-- Returns the module (require "arclen" works afterwards, and so do
-- arclen.path, arclen.mpost, ...).  BUILD defaults to ROOT/build/5.3:
-- LuaTeX's Lua is 5.3 (texlua), so `make LUA=5.3` builds what it loads.
-- LuaTeX loads binary modules only with --shell-escape (or a restricted
-- shell escape that allows it); without it this raises a clear error.
--
-- All of arclen's module-finding inside TeX is this one function.
return function(root, build)
  root = root or "."
  build = build or (root .. "/build/5.3")
  local lpath = root .. "/lua/?.lua;" .. root .. "/lua/?/init.lua"
  local cpath = build .. "/?.so"
  package.path = lpath .. ";" .. package.path
  package.cpath = cpath .. ";" .. package.cpath
  -- LuaTeX's require asks kpathsea before package.path/cpath and could find
  -- an installed arclen first: search this copy's paths ahead of it.
  local searchers = package.searchers or package.loaders
  local key = "arclen.luatex searcher " .. lpath .. ";" .. cpath
  if not package.loaded[key] then
    package.loaded[key] = true
    table.insert(searchers, 2, function(name)
      if name ~= "arclen" and name:sub(1, 7) ~= "arclen." then return nil end
      local file = package.searchpath(name, lpath)
      if file then return assert(loadfile(file)), file end
      file = package.searchpath(name, cpath)
      if not file then return "\n\tno arclen file for '" .. name .. "' under " .. root end
      -- luaopen_arclen_core for arclen/core.so; the one-file build (and the
      -- loadlib route) exports luaopen_arclen
      local open, err = package.loadlib(file, "luaopen_" .. name:gsub("%.", "_"))
      if not open then open = package.loadlib(file, "luaopen_arclen") end
      if not open then
        error(("arclen: cannot load %s (%s); LuaTeX loads binary modules only "
          .. "with --shell-escape"):format(file, tostring(err or "loading refused")), 0)
      end
      return open, file
    end)
  end
  return require("arclen")
end
