-- arclen.cli -- the command-line tool: `arclen COMMAND [options] ARGS`.
-- Run as a script (lua lua/arclen/cli.lua ...) or through the installed
-- `arclen` wrapper.  Exit status: 0 success, 1 failure, 2 usage error.
local cli = {}

local USAGE = [[
usage: arclen COMMAND [options] ARGS

commands:
  henkel                      Henkel's six arcs by every method (the main job)
  length X0 Y0 ... X3 Y3      length of a cubic (8 numbers, or 12 for 3D)
  time S X0 Y0 ... X3 Y3      parameter t where the length from t = 0 is S
  methods                     list the length methods
  help                        this text

options:
  --method NAME   length method (default gauss; see `arclen methods`)
  --tol T         relative tolerance in [1e-15, 0.1] (default 1e-12)
  --json          print results as JSON

examples:
  arclen henkel
  arclen length 0 0 10 0 10 10 0 0
  arclen length --method elliptic --tol 1e-15 0 0 10 10 0 10 10 0
  arclen time 5 0 0 10 0 10 10 0 0
]]

local function fail(msg, status)
  io.stderr:write("arclen: ", msg, "\n")
  os.exit(status or 1)
end

-- Split argv into options and positional arguments.
local function parse(argv)
  local opts, args, i = {}, {}, 1
  while i <= #argv do
    local a = argv[i]
    if a == "--method" or a == "--tol" then
      local v = argv[i + 1]
      if v == nil then fail(a .. " needs a value", 2) end
      opts[a:sub(3)] = v
      i = i + 2
    elseif a == "--json" then
      opts.json = true
      i = i + 1
    elseif a:match("^%-%-") then
      fail("unknown option " .. a .. " (see arclen help)", 2)
    else
      args[#args + 1] = a
      i = i + 1
    end
  end
  return opts, args
end

local function numbers(args, from, what)
  local out = {}
  for i = from, #args do
    local v = tonumber(args[i])
    if v == nil then fail(("%s: '%s' is not a number"):format(what, args[i]), 2) end
    out[#out + 1] = v
  end
  if #out ~= 8 and #out ~= 12 then
    fail(("%s: a cubic needs 8 (2D) or 12 (3D) numbers, got %d"):format(what, #out), 2)
  end
  return out
end

local function method_opts(opts)
  local o = {info = true}
  if opts.method then o.method = opts.method end
  if opts.tol then
    o.tol = tonumber(opts.tol)
    if o.tol == nil then fail("--tol: '" .. opts.tol .. "' is not a number", 2) end
  end
  return o
end

local function call(f, ...)
  local ok, a, b = pcall(f, ...)
  if not ok then fail(tostring(a):gsub("^bad argument #%d+ to '[%w%.]+' %((.*)%)$", "%1")) end
  if a == nil then fail(tostring(b)) end
  return a, b
end

local commands = {}

function commands.henkel()
  io.write(require("arclen.henkel").report())
end

function commands.length(opts, args)
  local arclen = require("arclen")
  local c = numbers(args, 2, "length")
  local L, info = call(arclen.length, c, method_opts(opts))
  if opts.json then
    print(('{"length": %.17g, "evals": %d, "err": %.3g}'):format(L, info.evals, info.err))
  else
    print(("%.17g"):format(L))
  end
end

function commands.time(opts, args)
  local arclen = require("arclen")
  local s = tonumber(args[2])
  if s == nil then fail("time: the length S must be a number", 2) end
  local c = numbers(args, 3, "time")
  local o = method_opts(opts)
  local t = call(arclen.time, c, s, o)
  if opts.json then print(('{"time": %.17g}'):format(t)) else print(("%.17g"):format(t)) end
end

function commands.methods()
  for _, m in ipairs(require("arclen").methods()) do print(m) end
end

function commands.help()
  io.write(USAGE)
end

function cli.main(argv)
  local opts, args = parse(argv)
  local name = args[1] or "help"
  local cmd = commands[name]
  if not cmd then fail("unknown command '" .. name .. "' (see arclen help)", 2) end
  cmd(opts, args)
end

-- Run when executed as a script, not when required.
if arg and arg[0] and arg[0]:match("cli%.lua$") then
  cli.main(arg)
end

return cli
