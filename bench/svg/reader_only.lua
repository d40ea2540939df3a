-- bench/svg/reader_only.lua FILE -- the C document reader alone: FILE fed
-- to arclen.svgdoc in 64 KiB chunks as a stream, each drawn element pushed
-- as the Lua table arclen.svg receives (no path built, nothing measured);
-- prints the number of elements.  For callgrind and GNU time
-- (doc/benchmarks.md, "Basic shapes without text"):
--   LUA_CPATH='build/5.4/?.so' lua5.4 bench/svg/reader_only.lua FILE
local svgdoc = require("arclen.svgdoc")
local f = assert(io.open(assert(arg[1], "usage: reader_only.lua FILE"), "rb"))
local r = svgdoc.new({stream = true})
local n = 0
for _ = 1, math.huge do
  local chunk = f:read(65536)
  if chunk == nil then break end
  local list = r:feed(chunk)
  if list then n = n + #list end
end
f:close()
n = n + #r:finish(arg[1]).elements
print(n)
