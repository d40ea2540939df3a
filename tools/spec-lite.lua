-- tools/spec-lite.lua SPEC... -- run busted spec files without busted, for
-- a Lua that has none of busted's C modules (a Windows Lua under Wine,
-- tools/check-windows.sh).  Only what arclen's specs use: describe and it
-- (collected while a file loads, run after it, in order, as busted does)
-- and the luassert forms below.  Prints each failure and ends with
-- "N passed, N failed" (a file that fails to load counts as one failure).
local real_assert = assert

local function show(v)
  if type(v) == "string" then return ("%q"):format(v) end
  if type(v) == "number" then return ("%.17g"):format(v) end
  return tostring(v)
end

local function fail(msg, what)
  error((msg and msg .. "\n" or "") .. what, 3)
end

local function same(a, b)            -- luassert's deep comparison
  if a == b then return true end
  if type(a) ~= "table" or type(b) ~= "table" then return false end
  for k, v in pairs(a) do if not same(v, b[k]) then return false end end
  for k in pairs(b) do if a[k] == nil then return false end end
  return true
end

local checks = {
  equal = function(e, a, msg)
    if e ~= a then fail(msg, "expected " .. show(e) .. ", got " .. show(a)) end
  end,
  same = function(e, a, msg)
    if not same(e, a) then fail(msg, "expected the same as " .. show(e) .. ", got " .. show(a)) end
  end,
  -- luassert's (pattern, s, init, plain), or (pattern, s, message)
  matches = function(pat, s, msg, plain)
    local init = 1
    if type(msg) == "number" then init, msg = msg, nil end
    if type(s) ~= "string" or not s:find(pat, init, plain) then
      fail(msg, "expected a match of " .. show(pat) .. ", got " .. show(s))
    end
  end,
  is_true = function(v, msg) if v ~= true then fail(msg, "expected true, got " .. show(v)) end end,
  is_false = function(v, msg) if v ~= false then fail(msg, "expected false, got " .. show(v)) end end,
  is_nil = function(v, msg) if v ~= nil then fail(msg, "expected nil, got " .. show(v)) end end,
  is_not_nil = function(v, msg) if v == nil then fail(msg, "expected a value, got nil") end end,
  is_truthy = function(v, msg) if not v then fail(msg, "expected truthy, got " .. show(v)) end end,
  is_table = function(v, msg)
    if type(v) ~= "table" then fail(msg, "expected a table, got " .. show(v)) end
  end,
  is_boolean = function(v, msg)
    if type(v) ~= "boolean" then fail(msg, "expected a boolean, got " .. show(v)) end
  end,
  is_string = function(v, msg)
    if type(v) ~= "string" then fail(msg, "expected a string, got " .. show(v)) end
  end,
  is_number = function(v, msg)
    if type(v) ~= "number" then fail(msg, "expected a number, got " .. show(v)) end
  end,
  -- the message compared without a "file:line: " prefix, as luassert does
  has_error = function(f, want)
    local ok, err = pcall(f)
    if ok then fail(nil, "expected an error") end
    if want ~= nil and type(err) == "string" then err = err:gsub("^.-:%d+: ", "", 1) end
    if want ~= nil and err ~= want then
      fail(nil, "expected the error " .. show(want) .. ", got " .. show(err))
    end
  end,
  no_errors = function(f)
    local ok, err = pcall(f)
    if not ok then fail(nil, "expected no error, got " .. show(err)) end
  end,
}
-- assert.are.equal, assert.is_true, assert.has_no.errors, ...; assert(...)
-- itself is still Lua's
local A = setmetatable({}, {__call = function(_, ...) return real_assert(...) end})
for k, f in pairs(checks) do A[k] = f end
A.truthy = checks.is_truthy
A.are, A.is, A.has = A, A, A
A.has_no = {errors = checks.no_errors}
A.has_errors = checks.has_error

local passed, failed = 0, 0
local tests, path = {}, {}

function describe(name, body)
  path[#path + 1] = name
  body()
  path[#path] = nil
end

function it(name, body)
  tests[#tests + 1] = {table.concat(path, " ") .. " " .. name, body}
end

function pending() end

-- setup and teardown of a describe: run around the file's tests (the
-- specs' blocks only make and remove temporary files)
local setups, teardowns = {}, {}
function setup(f) setups[#setups + 1] = f end
function teardown(f) teardowns[#teardowns + 1] = f end

assert = A
-- Each file with the modules as they were before the first (busted's
-- insulation): a module's state, such as mpost's warning given once,
-- starts afresh for every file.
local preloaded = {}
for name, m in pairs(package.loaded) do preloaded[name] = m end
for _, file in ipairs(arg) do
  for name in pairs(package.loaded) do
    if preloaded[name] == nil then package.loaded[name] = nil end
  end
  tests, path, setups, teardowns = {}, {}, {}, {}
  local chunk, err = loadfile(file)
  local ok = chunk ~= nil
  if ok then ok, err = xpcall(chunk, debug.traceback) end
  if not ok then
    failed = failed + 1
    print("FAIL " .. file .. " (loading): " .. tostring(err))
  end
  for _, f in ipairs(setups) do f() end
  for _, t in ipairs(tests) do
    local tok, terr = xpcall(t[2], debug.traceback)
    if tok then
      passed = passed + 1
    else
      failed = failed + 1
      print("FAIL " .. file .. ": " .. t[1] .. "\n" .. tostring(terr))
    end
  end
  for _, f in ipairs(teardowns) do pcall(f) end
end
print(("%d passed, %d failed"):format(passed, failed))
os.exit(failed == 0 and 0 or 1)
