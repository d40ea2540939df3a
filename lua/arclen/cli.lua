-- arclen.cli -- the command-line tool: `arclen COMMAND [options] ARGS`.
-- Run as a script (lua lua/arclen/cli.lua ...) or through the installed
-- `arclen` wrapper.  Exit status: 0 success, 1 failure (unreadable file, bad
-- path data, a computation that fails), 2 usage error (unknown command or
-- option, missing or malformed arguments).
local cli = {}

local USAGE = [[
usage: arclen COMMAND [options] ARGS

commands:
  henkel                     Henkel's six arcs by every method (the main job)
  length WHAT                length of WHAT:
                               X0 Y0 X1 Y1 X2 Y2 X3 Y3  a cubic (12 numbers for 3D)
                               'M0 0 C10 0 10 10 0 0'   SVG path data
                               FILE.svg                 every <path d=...> in the file
                               -                        SVG file or path data on stdin
  time S WHAT                path time at distance S (MetaPost's convention: segment
                             index + parameter; for one cubic, t in [0, 1])
  point S WHAT               the point and unit tangent at distance S
  resample N WHAT            N points evenly spaced along WHAT (or --step H)
  fit X0 Y0 ... X3 Y3        Walter & Fournier's length-versus-t fit of a cubic
  methods                    list the length methods
  help                       this text

options:
  --method NAME   length method (default gauss; see `arclen methods`);
                  for fit: hermite (default) or paper
  --tol T         relative tolerance in [1e-15, 0.1] (default 1e-12)
  --step H        resample: points H apart instead of N points
  --n N           fit: Gauss-Legendre points per span
  --json          print results as JSON
  -h, --help      this text

WHAT of several paths (a file) is measured path by path; time, point and
resample need a single path.  Coordinates are the path's own (transform
attributes are not applied).

examples:
  arclen henkel
  arclen length 0 0 10 0 10 10 0 0
  arclen length 'M0 0 C10 0 10 10 0 0'
  arclen length --json drawing.svg
  arclen length --method elliptic --tol 1e-15 0 0 10 10 0 10 10 0
  arclen time 5 'M0 0 L10 0 L10 10'
  arclen point 15 'M0 0 L10 0 L10 10'
  arclen resample 5 'M10 0 A10 10 0 1 1 -10 0'
  arclen resample --step 2.5 'M0 0 L10 0'
  arclen fit --tol 1e-6 0 0 10 0 10 10 0 0
]]

local function fail(msg, status)
  io.stderr:write("arclen: ", msg, "\n")
  if status == 2 then io.stderr:write("Try 'arclen --help'.\n") end
  os.exit(status or 1)
end

local VALUED = {["--method"] = true, ["--tol"] = true, ["--step"] = true, ["--n"] = true}

-- Split argv into options and positional arguments.
local function parse(argv)
  local opts, args, i = {}, {}, 1
  while i <= #argv do
    local a = argv[i]
    if VALUED[a] then
      local v = argv[i + 1]
      if v == nil then fail(a .. " needs a value", 2) end
      opts[a:sub(3)] = v
      i = i + 2
    elseif a == "--json" then
      opts.json = true
      i = i + 1
    elseif a == "--help" or a == "-h" then
      opts.help = true
      i = i + 1
    elseif a:match("^%-%-.") then
      fail("unknown option " .. a, 2)
    else
      args[#args + 1] = a
      i = i + 1
    end
  end
  return opts, args
end

local function method_opts(opts)
  local o = {}
  if opts.method then o.method = opts.method end
  if opts.tol then
    o.tol = tonumber(opts.tol)
    if o.tol == nil then fail("--tol: '" .. opts.tol .. "' is not a number", 2) end
  end
  return o
end

-- The message of a Lua error without the "bad argument #n to 'f'" frame.
local function message(e)
  e = tostring(e):gsub("^[^:]*:%d+: ", "")
  return (e:gsub("^bad argument #%d+ to '[%w%.]+' %((.*)%)$", "%1"))
end

-- Call f; a raised error is a failure (status), nil + message too.
local function call(status, f, ...)
  local ok, a, b = pcall(f, ...)
  if not ok then fail(message(a), status) end
  if a == nil then fail(tostring(b)) end
  return a, b
end

local function g17(x) return ("%.17g"):format(x) end

-- ---- JSON (numbers round-trip with %.17g) -------------------------------

local function json_string(s)
  return '"' .. s:gsub('[%c"\\]', function(c)
    local esc = {['"'] = '\\"', ["\\"] = "\\\\", ["\n"] = "\\n", ["\t"] = "\\t", ["\r"] = "\\r"}
    return esc[c] or ("\\u%04x"):format(c:byte())
  end) .. '"'
end

local function json(v)
  local t = type(v)
  if t == "number" then return g17(v) end
  if t == "string" then return json_string(v) end
  if t == "boolean" then return tostring(v) end
  if v == nil then return "null" end
  if v[1] ~= nil or next(v) == nil then
    local out = {}
    for i = 1, #v do out[i] = json(v[i]) end
    return "[" .. table.concat(out, ", ") .. "]"
  end
  local keys = {}
  for k in pairs(v) do keys[#keys + 1] = k end
  table.sort(keys)
  local out = {}
  for _, k in ipairs(keys) do out[#out + 1] = json_string(k) .. ": " .. json(v[k]) end
  return "{" .. table.concat(out, ", ") .. "}"
end

-- ---- what to measure: a cubic, path data, an SVG file -------------------

local ENTITIES = {amp = "&", lt = "<", gt = ">", quot = '"', apos = "'"}

local function unescape(s)
  s = s:gsub("&#[xX](%x+);", function(h) return string.char(tonumber(h, 16) % 256) end)
  s = s:gsub("&#(%d+);", function(d) return string.char(tonumber(d) % 256) end)
  return (s:gsub("&(%a+);", function(n) return ENTITIES[n] end))
end

-- Every <path ... d="..."> (or <svg:path ...>) of an SVG document:
-- {d =, id =} in order.
-- A simple scan: comments are dropped, attributes are name="value" or
-- name='value'; elements other than path are ignored.
function cli.svg_paths(text)
  text = text:gsub("<!%-%-.-%-%->", "")
  local out = {}
  for tag, attrs in text:gmatch("<([%w_:%-]+)([%s/][^>]*)>") do
    if tag ~= "path" and not tag:match(":path$") then attrs = "" end   -- svg:path too
    local a = {}
    for name, _, value in attrs:gmatch("([%w:_%-]+)%s*=%s*([\"'])(.-)%2") do
      a[name] = unescape(value)
    end
    if a.d then out[#out + 1] = {d = a.d, id = a.id} end
  end
  return out
end

local function read_file(name)
  local f, err
  if name == "-" then f = io.stdin else f, err = io.open(name, "rb") end
  if not f then fail(err or ("cannot open " .. name)) end
  local text = f:read("*a")
  if f ~= io.stdin then f:close() end
  if text == nil then fail("cannot read " .. name) end
  return text
end

-- The paths named by args[from..]: {{label =, path =}...}, or a cubic.
local function targets(args, from, opts, what)
  local arclen = require("arclen")
  local rest = {}
  for i = from, #args do rest[#rest + 1] = args[i] end
  if #rest == 0 then fail(what .. ": nothing to measure (a cubic, path data or an SVG file)", 2) end
  local o = method_opts(opts)
  local nums, allnum = {}, true
  for i, a in ipairs(rest) do
    nums[i] = tonumber(a)
    if nums[i] == nil then allnum = false end
  end
  if allnum then
    if #nums ~= 8 and #nums ~= 12 then
      fail(("%s: a cubic needs 8 (2D) or 12 (3D) numbers, got %d"):format(what, #nums), 2)
    end
    return {{label = "cubic", path = call(2, arclen.path, {nums}, o)}}, nums
  end
  if #rest > 1 then
    fail(("%s: expected one path (quote path data), got %d arguments"):format(what, #rest), 2)
  end
  local a = rest[1]
  local text, source = nil, nil
  if a == "-" then
    text, source = read_file("-"), "stdin"
  elseif not a:find("^%s*[Mm]") then
    local f = io.open(a, "rb")
    if not f then fail(a .. ": no such file (and not SVG path data, which starts with M)") end
    f:close()
    text, source = read_file(a), a
  end
  if text == nil then
    return {{label = "path", path = call(1, arclen.path.svg, a, o)}}
  end
  if not text:find("<") then   -- path data on stdin
    return {{label = "path", path = call(1, arclen.path.svg, text, o)}}
  end
  local found = cli.svg_paths(text)
  if #found == 0 then fail(source .. ": no <path d=...> elements") end
  local out = {}
  for i, p in ipairs(found) do
    local ok, res = pcall(arclen.path.svg, p.d, o)
    if not ok then
      fail(("%s: path %d%s: %s"):format(source, i, p.id and (" (id " .. p.id .. ")") or "", message(res)))
    end
    out[i] = {label = p.id or ("path" .. i), index = i, path = res}
  end
  return out
end

local function one(list, what)
  if #list ~= 1 then
    fail(("%s needs one path; the file has %d (extract one, e.g. by its d attribute)"):format(what, #list), 2)
  end
  return list[1].path
end

local function distance(args, i, what)
  local s = tonumber(args[i] or "")
  if s == nil then fail(("%s: the distance S must be a number, got '%s'"):format(what, tostring(args[i])), 2) end
  return s
end

-- ---- commands -----------------------------------------------------------

local commands = {}

function commands.henkel()
  io.write(require("arclen.repro.henkel").report())
end

function commands.length(opts, args)
  local arclen = require("arclen")
  local list, nums = targets(args, 2, opts, "length")
  if nums then                    -- one cubic: also the cost and error estimate
    local o = method_opts(opts)
    o.info = true
    local L, info = call(2, arclen.length, nums, o)
    if opts.json then
      print(json({length = L, evals = info.evals, err = info.err}))
    else
      print(g17(L))
    end
    return
  end
  local total, rows = 0, {}
  for i, t in ipairs(list) do
    local L, err = t.path:length()
    if L == nil then fail(t.label .. ": " .. tostring(err)) end
    total = total + L
    rows[i] = {id = t.label, length = L, segments = t.path:segments()}
  end
  if opts.json then
    if #list == 1 and not list[1].index then
      print(json(rows[1]))
    else
      print(json({paths = rows, total = total}))
    end
  elseif #list == 1 and not list[1].index then
    print(g17(total))
  else
    for _, r in ipairs(rows) do print(("%s\t%s"):format(r.id, g17(r.length))) end
    print("total\t" .. g17(total))
  end
end

function commands.time(opts, args)
  local s = distance(args, 2, "time")
  local p = one(targets(args, 3, opts, "time"), "time")
  local T = call(1, p.time, p, s)
  if opts.json then print(json({time = T})) else print(g17(T)) end
end

function commands.point(opts, args)
  local s = distance(args, 2, "point")
  local p = one(targets(args, 3, opts, "point"), "point")
  local x, y = call(1, p.point, p, s)
  local tx, ty = p:tangent(s)
  if opts.json then
    print(json({x = x, y = y, tx = tx, ty = ty, time = p:time(s)}))
  else
    print(("%s %s %s %s"):format(g17(x), g17(y), g17(tx), g17(ty)))
  end
end

function commands.resample(opts, args)
  local spec, from
  if opts.step then
    spec = {step = tonumber(opts.step)}
    if spec.step == nil then fail("--step: '" .. opts.step .. "' is not a number", 2) end
    from = 2
  else
    spec = tonumber(args[2] or "")
    if spec == nil then fail("resample: the count N must be a number (or give --step H)", 2) end
    from = 3
  end
  local p = one(targets(args, from, opts, "resample"), "resample")
  local pts = call(2, p.resample, p, spec)
  if opts.json then
    local out = {}
    for i, q in ipairs(pts) do
      out[i] = {x = q.x, y = q.y, s = q.s, time = q.time, tx = q.tx, ty = q.ty}
    end
    print(json(out))
  else
    for _, q in ipairs(pts) do print(("%s %s"):format(g17(q.x), g17(q.y))) end
  end
end

function commands.fit(opts, args)
  local arclen = require("arclen")
  if type(arclen.fit) ~= "function" then fail("fit: this build has no arclen.fit") end
  local nums = {}
  for i = 2, #args do
    nums[#nums + 1] = tonumber(args[i])
    if nums[#nums] == nil then fail(("fit: '%s' is not a number"):format(args[i]), 2) end
  end
  if #nums ~= 8 and #nums ~= 12 then
    fail(("fit: a cubic needs 8 (2D) or 12 (3D) numbers, got %d"):format(#nums), 2)
  end
  local o = {}
  if opts.method then o.method = opts.method end
  if opts.tol then
    o.tol = tonumber(opts.tol)
    if o.tol == nil then fail("--tol: '" .. opts.tol .. "' is not a number", 2) end
  end
  if opts.n then
    o.n = tonumber(opts.n)
    if o.n == nil then fail("--n: '" .. opts.n .. "' is not a number", 2) end
  end
  local f = call(2, arclen.fit, nums, o)
  local max, mean = f:errors()
  local r = {method = f.method, spans = f.nspans, total = f.total,
             max_error = max, mean_error = mean, evals = f.evals}
  if opts.json then
    local spans = {}
    for i, sp in ipairs(f:spans()) do spans[i] = {t0 = sp.t0, t1 = sp.t1, y = sp.y} end
    r.span = spans
    print(json(r))
  else
    print(("method\t%s\nspans\t%d\ntotal\t%s\nmax_error\t%.3g\nmean_error\t%.3g"):format(
      r.method, r.spans, g17(r.total), max, mean))
  end
end

function commands.methods(opts)
  local list = require("arclen").methods()
  if opts.json then print(json(list)) return end
  for _, m in ipairs(list) do print(m) end
end

function commands.help()
  io.write(USAGE)
end

function cli.main(argv)
  local opts, args = parse(argv)
  if opts.help then return commands.help() end
  local name = args[1]
  if name == nil then
    io.stderr:write(USAGE)
    os.exit(2)
  end
  local cmd = commands[name]
  if not cmd then fail("unknown command '" .. name .. "'", 2) end
  cmd(opts, args)
end

-- Run when executed as a script, not when required.
if arg and arg[0] and arg[0]:match("cli%.lua$") then
  cli.main(arg)
end

return cli
