-- arclen -- the module users require: the engine's functions (the C core,
-- arclen.core, where it loads, else the Lua engine, arclen.pure: see
-- lua/arclen/engine.lua) with the Lua parts added to them, the way LPeg's
-- re sits over lpeg and LuaSocket's socket over socket.core.
--
--   local arclen = require "arclen"
--   arclen.engine                              "c" or "lua"
--   arclen.length(c), arclen.time(c, s), ...   the engine (src/, or pure.lua)
--   arclen.path(cubics), arclen.path.svg(d)    paths (lua/arclen/path.lua)
--
-- Modules loaded from here take the engine's functions from arclen.engine,
-- never from arclen itself, so that none of them requires this file in a
-- loop.
local engine = require "arclen.engine"

local arclen = {}
for name, value in pairs(engine) do arclen[name] = value end
arclen.path = require "arclen.path"

return arclen
