-- arclen.mplib -- LuaTeX's mplib knot tables to cubic segments.
--
-- mplib gives a path (the `path` field of a figure object, or the result
-- of mp:solvepath) as an array of knots, each a table with the fields
--   x_coord, y_coord          the knot,
--   left_x, left_y            the control point before it,
--   right_x, right_y          the control point after it,
--   left_type, right_type     "endpoint" at the ends of an open path (and
--                             "explicit", "curl", ... in unsolved paths).
-- Segment k runs from knot k over right_k and left_{k+1} to knot k+1; a
-- cyclic path (no "endpoint" ends, or the field cycle = true in newer
-- LuaTeX) has a last segment from the last knot back to the first.
local M = {}

local FIELDS = {"x_coord", "y_coord", "left_x", "left_y", "right_x", "right_y"}

local function fail(msg)
  error({msg = msg}, 0)
end

local function coords(knot, k)
  if type(knot) ~= "table" then
    fail(("knot %d must be a table, got %s"):format(k, type(knot)))
  end
  local v = {}
  for i, name in ipairs(FIELDS) do
    local x = knot[name]
    if type(x) ~= "number" then
      fail(("knot %d: %s must be a number, got %s"):format(k, name, type(x)))
    end
    if x ~= x or x == math.huge or x == -math.huge then
      fail(("knot %d: %s must be finite"):format(k, name))
    end
    v[i] = x
  end
  return v
end

-- Is the knot list cyclic?  The cycle field when present, else the ends'
-- types: mplib marks the ends of an open path "endpoint".
local function cyclic(knots, n)
  if knots.cycle ~= nil then return knots.cycle and true or false end
  local first, last = knots[1], knots[n]
  local open = first.left_type == "endpoint" or last.right_type == "endpoint"
  for k = 1, n do
    local kn = knots[k]
    if (kn.right_type == "endpoint" and k < n) or (kn.left_type == "endpoint" and k > 1) then
      fail(("knot %d is an endpoint inside the path"):format(k))
    end
  end
  return not open
end

-- The subpath {x =, y =, closed =, cubic...} of a knot list (or of an
-- mplib object with a path field).
function M.subpath(knots)
  if type(knots) == "table" and type(knots.path) == "table" then knots = knots.path end
  if type(knots) ~= "table" then
    fail("mplib path (a table of knots) expected, got " .. type(knots))
  end
  local n = #knots
  if n < 1 then fail("mplib path has no knots") end
  local kv = {}
  for k = 1, n do kv[k] = coords(knots[k], k) end
  local closed = cyclic(knots, n)
  local sp = {x = kv[1][1], y = kv[1][2], closed = closed}
  local last = closed and n or n - 1
  for k = 1, last do
    local a, b = kv[k], kv[k % n + 1]
    sp[k] = {a[1], a[2], a[5], a[6], b[3], b[4], b[1], b[2]}
  end
  return sp
end

return M
