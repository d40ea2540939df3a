-- arclen.engine -- which engine answers: the C core (arclen.core) where
-- it loads, else the Lua engine (arclen.pure), chosen once, when first
-- required.  Every module of the Lua layer takes its functions from here.
--
-- To force the Lua engine (tests, TeX documents that should not depend on
-- a binary):
--   ARCLEN_ENGINE=lua in the environment (read once, here), or
--   package.loaded["arclen.core"] = false before the first require of
--   arclen: "the C core is not to be had".
-- ARCLEN_ENGINE=c insists on the C core (an error when it does not load).
-- The result reports engine = "c" or "lua"; when the C core was tried and
-- failed, core_error says why.
local wanted = os.getenv and os.getenv("ARCLEN_ENGINE") or nil
if wanted == "" then wanted = nil end
if wanted ~= nil and wanted ~= "c" and wanted ~= "lua" then
  error(("arclen: ARCLEN_ENGINE must be 'c' or 'lua', got '%s'"):format(wanted), 0)
end

local core, why
if wanted ~= "lua" and package.loaded["arclen.core"] ~= false then
  local ok, res = pcall(require, "arclen.core")
  if ok and type(res) == "table" then core = res else why = tostring(res) end
  if not core and wanted == "c" then
    error("arclen: ARCLEN_ENGINE=c, but the C core does not load: " .. why, 0)
  end
end

if core then
  core.engine = "c"          -- the core's own table: what patches it sees
  return core
end
local engine = require("arclen.pure")
engine.core_error = why
return engine
