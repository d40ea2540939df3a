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
-- shell escape that allows it); without it arclen answers with its Lua
-- engine (arclen.engine = "lua", lua/arclen/engine.lua), and
-- arclen.core_error says why the C core did not load.
--
-- All of arclen's module-finding inside TeX is this one function.
return function(root, build)
  root = root or "."
  build = build or (root .. "/build/5.3")
  local lpath = root .. "/lua/?.lua;" .. root .. "/lua/?/init.lua"
  local cpath = build .. "/?.so"
  package.path = lpath .. ";" .. package.path
  package.cpath = cpath .. ";" .. package.cpath
  -- arclen and arclen.* come from this copy only: LuaTeX asks kpathsea
  -- first, and LuaLaTeX's lualibs tries ./?.so before package.path, either
  -- of which could find another arclen.  package.preload is asked before
  -- any search, by every require: answer there, through its __index.
  local function loader(name)
    if name ~= "arclen" and name:sub(1, 7) ~= "arclen." then return nil end
    local file = package.searchpath(name, lpath)
    if file then return assert(loadfile(file)) end
    file = package.searchpath(name, cpath)
    if not file then return nil end
    -- luaopen_arclen_core for arclen/core.so; the one-file build (and the
    -- loadlib route) exports luaopen_arclen
    local open, err = package.loadlib(file, "luaopen_" .. name:gsub("%.", "_"))
    if not open then open = package.loadlib(file, "luaopen_arclen") end
    if not open then
      error(("arclen: cannot load %s (%s); LuaTeX loads binary modules only "
        .. "with --shell-escape"):format(file, tostring(err or "loading refused")), 0)
    end
    return open
  end
  local mt = getmetatable(package.preload) or {}
  local prev = mt.__index
  mt.__index = function(t, name)
    local f = loader(name)
    if f then return f end
    if type(prev) == "function" then return prev(t, name) end
    if type(prev) == "table" then return prev[name] end
  end
  setmetatable(package.preload, mt)
  return require("arclen")
end
