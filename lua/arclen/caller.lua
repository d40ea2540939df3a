-- arclen.caller -- the level at which an argument error is raised so that
-- its "file:line:" is the user's call, not a line of arclen's own Lua: the
-- first frame outside lua/arclen/*.lua (a C function such as pcall gives
-- no place, as luaL_argerror's would not).  A C function reports its
-- caller's line by being one frame; our checks sit one to three frames
-- below the user's call, so a fixed level named our own lines.
--   error(message, caller(fallback))   inside the function that raises;
-- fallback is the level used without the debug library (a sandbox).
local getinfo = debug and debug.getinfo
local find = string.find

local MAX_DEPTH = 50    -- frames searched; past them, the fallback

return function(fallback)
  if not getinfo then return fallback end
  -- level 1 is this function, 2 the one that raises, 3 its caller
  for level = 3, MAX_DEPTH do
    local info = getinfo(level, "S")
    if info == nil then return fallback end
    if not find(info.source, "[/\\]arclen[/\\][%w_]+%.lua$") then
      return level - 1     -- as error() counts, from the raising function
    end
  end
  return fallback
end
