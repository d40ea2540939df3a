-- arclen -- the module users require: the C core (arclen.core) with the
-- Lua parts added to it, the way LPeg's re sits over lpeg and LuaSocket's
-- socket over socket.core.
--
--   local arclen = require "arclen"
--   arclen.length(c), arclen.time(c, s), ...   the C core (src/)
--   arclen.path(cubics), arclen.path.svg(d)    paths (lua/arclen/path.lua)
--
-- Modules loaded from here take the C functions from arclen.core, never
-- from arclen itself, so that none of them requires this file in a loop.
local core = require "arclen.core"

local arclen = {}
for name, value in pairs(core) do arclen[name] = value end
arclen.path = require "arclen.path"

return arclen
