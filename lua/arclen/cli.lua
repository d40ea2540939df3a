-- arclen.cli -- the command-line tool: `arclen COMMAND [options] ARGS`.
-- Run as a script (lua lua/arclen/cli.lua ...) or through the installed
-- `arclen` wrapper.  Exit status: 0 success, 1 failure (unreadable file, bad
-- path data, a computation that fails), 2 usage error (unknown command or
-- option, missing or malformed arguments).
local cli = {}

-- Executed as a script, not required: from a clone (lua5.4
-- lua/arclen/cli.lua), the clone's modules and build come first -- set
-- before the requires below.
local as_script = arg and arg[0] and arg[0]:match("cli%.lua$")
if as_script then
  local root = (arg[0]:match("^(.*)[/\\][^/\\]*$") or ".") .. "/../.."
  local version = type(jit) == "table" and "jit" or _VERSION:match("%d+%.%d+")
  package.path = root .. "/lua/?.lua;" .. root .. "/lua/?/init.lua;" .. package.path
  package.cpath = root .. "/build/" .. version .. "/?.so;" .. package.cpath
end

-- Numbers in and out the same in every locale (arclen.numtext).
local numtext = require("arclen.numtext")
local tonumber, format = numtext.tonumber, numtext.format

local USAGE = [[
usage: arclen COMMAND [options] ARGS

commands:
  henkel                     Henkel's six arcs by every method (the main job)
  length WHAT                length of WHAT:
                               X0 Y0 X1 Y1 X2 Y2 X3 Y3  a cubic (12 numbers for 3D)
                               'M0 0 C10 0 10 10 0 0'   SVG path data
                               FILE.svg                 every drawn shape of the document
                                                        (see doc/svg.md), and the total
                               FILE.svg FILE.svg ...    each file so, then the sum; a file
                                                        that fails is reported (exit 1)
                               -                        SVG file or path data on stdin
  stat FILE.svg ...          per layer (Inkscape layers, else top-level groups) and in
                             total: length, pen-up travel, paths (subpaths), elements,
                             segments, bounding box -- what vpype stat prints; a file
                             that fails is reported and the others measured (exit 1)
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
  --units U       SVG documents: user (the root's user units, default), px (the
                  viewBox mapped onto width/height, 96 px per inch), mm, cm, in, pt, pc
  --stroked       SVG documents: only shapes whose stroke paints (for plotters:
                  not none, not transparent, opacity above 0, width above 0)
  --painted       SVG documents: only shapes whose stroke or fill paints
                  (without either: every shape, whatever its paint)
  --lang L        SVG documents: the user languages systemLanguage is matched
                  against (default en; a list: de,en-US)
  --hidden        SVG documents: also display:none and visibility:hidden shapes
  --strict        SVG documents: warnings are errors (a <use> of a missing id,
                  an error in path data: by default the rest is measured)
  --quiet         no progress line (length and stat show one on a terminal
                  when a document takes more than a second)
  --arcs A        SVG documents and path data: conics (default: segments as
                  drawn, arcs exact) or cubics (cubics only, arcs within the
                  tolerance)
  --json          print results as JSON
  -h, --help      this text

WHAT of several paths (a file) is measured element by element; time, point
and resample need a single path.  SVG documents are read as a renderer draws
them: basic shapes, transforms, viewports, <use>; lengths in the root's user
units unless --units says otherwise.  Gzip-compressed documents (.svgz) are
read as the document they hold.  A <use> of a missing id and an error in
path data are warnings (the path drawn up to the error), errors with --strict.  length and stat read a document as a
stream: each element is measured (and length prints its row) as soon as it
is read, so that their memory does not grow with the file.

examples:
  arclen henkel
  arclen length 0 0 10 0 10 10 0 0
  arclen length 'M0 0 C10 0 10 10 0 0'
  arclen length --json drawing.svg
  arclen length --units mm drawing.svg
  arclen stat --stroked a.svg b.svg
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

local VALUED = {["--method"] = true, ["--tol"] = true, ["--step"] = true, ["--n"] = true,
                ["--units"] = true, ["--arcs"] = true, ["--lang"] = true}
local FLAGS = {["--json"] = "json", ["--stroked"] = "stroked", ["--hidden"] = "hidden",
                ["--quiet"] = "quiet", ["--painted"] = "painted", ["--strict"] = "strict"}

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
    elseif FLAGS[a] then
      opts[FLAGS[a]] = true
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

-- A number argument: numtext's, and also nan, inf, infinity (either
-- sign, any case), which it does not read: as 1e400 (inf), they are
-- numbers that the checks of finite then refuse, each with its message.
local NONFINITE = {nan = 0 / 0, inf = math.huge, infinity = math.huge}
local function number_arg(a)
  local v = tonumber(a)
  if v ~= nil or type(a) ~= "string" then return v end
  local sign, word = a:lower():match("^%s*([+-]?)(%a+)%s*$")
  v = word and NONFINITE[word]
  if v and sign == "-" then v = -v end
  return v
end

local function isfinite(x) return x == x and x ~= math.huge and x ~= -math.huge end

-- --method and --tol as an options table (the library checks the method;
-- --tol out of its range is a usage error here, whatever WHAT is).
local function method_opts(opts)
  local o = {}
  if opts.method then o.method = opts.method end
  if opts.tol then
    o.tol = number_arg(opts.tol)
    if o.tol == nil then fail("--tol: '" .. opts.tol .. "' is not a number", 2) end
    local engine = require("arclen.engine")
    if not (o.tol >= engine.tol_min and o.tol <= engine.tol_max) then
      fail(format("--tol must be in [%g, %g], got '%s'", engine.tol_min, engine.tol_max,
        opts.tol), 2)
    end
  end
  return o
end

-- --arcs: conics or cubics, checked whatever the command and WHAT.
local function check_arcs(opts)
  if opts.arcs and opts.arcs ~= "conics" and opts.arcs ~= "cubics" then
    fail(format("--arcs: '%s' is neither conics nor cubics", opts.arcs), 2)
  end
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

local g17 = numtext.g17

-- ---- JSON: dkjson (lua-dkjson) --------------------------------------------
-- dkjson writes numbers with 14 digits, as lua-cjson 2.1 does at most; a
-- number is passed as a table whose __tojson gives the shortest of %.15g,
-- %.16g, %.17g that reads back as the same double, so JSON output
-- round-trips.  Object keys are sorted.

local function json_lib()
  local ok, dk = pcall(require, "dkjson")
  if not ok then
    fail("--json needs dkjson: luarocks install dkjson (Debian: apt-get install lua-dkjson)")
  end
  return dk
end

local function shortest(x)
  if x ~= x or x == math.huge or x == -math.huge then return "null" end
  return numtext.shortest(x)
end

local NUMBER = {__tojson = function(self) return self[1] end}
local ARRAY = {__jsontype = "array"}

-- A copy of v with numbers wrapped, arrays marked, and the keys in order.
local function prepare(v, keys)
  if type(v) == "number" then return setmetatable({shortest(v)}, NUMBER) end
  if type(v) ~= "table" then return v end
  local out = {}
  if v[1] ~= nil or next(v) == nil then
    for i = 1, #v do out[i] = prepare(v[i], keys) end
    return setmetatable(out, ARRAY)
  end
  for k, x in pairs(v) do
    out[k] = prepare(x, keys)
    keys[#keys + 1] = k
  end
  return out
end

local function json(v)
  local dk = json_lib()
  local keys = {}
  local w = prepare(v, keys)
  table.sort(keys)
  local seen, order = {}, {}
  for _, k in ipairs(keys) do
    if not seen[k] then seen[k] = true; order[#order + 1] = k end
  end
  return dk.encode(w, {keyorder = order})
end

-- ---- what to measure: a cubic, path data, an SVG file -------------------

local UNIT_NAMES = "user, px, mm, cm, in, pt, pc"

-- arclen.svg, or a failure that says what to install (the document reader
-- is an optional part: the rock arclen-svg, or make with expat's headers).
local function svg_lib()
  return call(1, require, "arclen.svg")
end

-- The reader's options from the command line's.
local function svg_opts(opts)
  local o = method_opts(opts)
  if opts.units then
    if opts.units ~= "user" and not svg_lib().UNITS[opts.units] then
      fail(format("--units: unknown unit '%s' (%s)", opts.units, UNIT_NAMES), 2)
    end
    o.units = opts.units
  end
  if opts.stroked and opts.painted then fail("--stroked and --painted exclude each other", 2) end
  if opts.stroked then o.stroked = true end
  if opts.painted then o.painted = true end
  if opts.hidden then o.hidden = true end
  if opts.lang then
    if not svg_lib().lang_ok(opts.lang) then
      fail(format("--lang: '%s' is not a list of language tags (en, de,en-US)", opts.lang), 2)
    end
    o.lang = opts.lang
  end
  if opts.strict then o.strict = true end
  if opts.arcs then
    check_arcs(opts)
    o.arcs = opts.arcs
  end
  return o
end

-- Read an SVG document (a file name, or text from stdin): the doc; its
-- warnings go to stderr.
local function read_svg(name, text, opts)
  local svg = svg_lib()
  local o = svg_opts(opts)
  local ok, doc
  if text then ok, doc = pcall(svg.parse, text, o, name)
  else ok, doc = pcall(svg.read, name, o) end
  if not ok then fail(message(doc)) end
  for _, w in ipairs(doc.warnings) do io.stderr:write("arclen: warning: ", w, "\n") end
  return doc
end

local CHUNK = 65536
local stdin_first               -- stdin's first chunk, once looked at

-- The first chunk of stdin (read once; read_file("-") starts with it).
local function stdin_peek()
  if stdin_first == nil then stdin_first = io.stdin:read(CHUNK) or "" end
  return stdin_first
end

local function read_file(name)
  local f, err
  if name == "-" then f = io.stdin else f, err = io.open(name, "rb") end
  if not f then fail(err or ("cannot open " .. name)) end
  local text = f:read("*a")
  if f ~= io.stdin then f:close() end
  if text == nil then fail("cannot read " .. name) end
  if name == "-" then text = stdin_peek() .. text end
  return text
end

-- ---- progress: a line on stderr while a document is read ----------------
-- Shown when stderr is a terminal (arclen.svgdoc.isatty) and the reading
-- has taken more than PROGRESS_AFTER seconds of CPU, rewritten in place
-- with \r and cleared at the end; never with --quiet.  ARCLEN_PROGRESS=1
-- shows it whatever stderr is and from the first chunk (for tests), =0
-- never.
local PROGRESS_AFTER, PROGRESS_EVERY = 1, 0.25

local function progress_for(name, opts)
  local env = os.getenv("ARCLEN_PROGRESS")
  if opts.quiet or env == "0" then return nil end
  local after, ok, svgdoc = PROGRESS_AFTER, pcall(require, "arclen.svgdoc")
  if env == "1" then
    after = 0
  elseif not (ok and svgdoc.isatty()) then
    return nil
  end
  local clock = os.clock
  local t0, last, width = clock(), nil, 0
  local P = {tty_out = env == "1" or (ok and svgdoc.isatty("stdout"))}
  function P.update(bytes, size, count)
    local now = clock()
    if now - t0 < after or (last and now - last < PROGRESS_EVERY) then return end
    last = now
    local MB, secs = 1e6, math.max(now - t0, 1e-3)
    local line = size and format("arclen: %s: %.1f of %.1f MB (%d%%), %.1f MB/s, %d elements",
        name, bytes / MB, size / MB, math.floor(100 * bytes / math.max(size, 1)), bytes / MB / secs, count)
      or format("arclen: %s: %.1f MB, %.1f MB/s, %d elements", name, bytes / MB, bytes / MB / secs, count)
    io.stderr:write("\r", line, string.rep(" ", width - #line))
    io.stderr:flush()
    width = math.max(width, #line)
  end
  function P.shown() return width > 0 end
  function P.clear()
    if width > 0 then
      io.stderr:write("\r", string.rep(" ", width), "\r")
      io.stderr:flush()
      width = 0
    end
  end
  return P
end

-- Stream the document src (a file name or a function of chunks) through
-- svg.each, on_element(e) per drawn element; its warnings go to stderr.
-- prints: on_element writes to stdout (when stdout is the terminal too,
-- the progress line is cleared first, lest they mix).  Returns the document without its
-- elements; when it fails, exits, or with soft returns nil and the message.
local function each_svg(src, name, opts, on_element, prints, soft, bare)
  local svg = svg_lib()
  local o = svg_opts(opts)
  if bare then o.path = false end
  local P = progress_for(name, opts)
  local fn = on_element
  if P then
    o.progress = P.update
    if prints and P.tty_out then
      fn = function(e)
        if P.shown() then P.clear() end
        on_element(e)
      end
    end
  end
  if type(src) ~= "string" then o.name = name end
  local ok, doc = pcall(svg.each, src, fn, o)
  if P then P.clear() end
  if not ok and soft then return nil, message(doc) end
  if not ok then fail(message(doc)) end
  for _, w in ipairs(doc.warnings) do io.stderr:write("arclen: warning: ", w, "\n") end
  return doc
end

-- Is text (stdin's first chunk) a document rather than path data: markup,
-- gzip, or another format's magic bytes (which the reader names)?
local function markup(text)
  return text:find("<") ~= nil or require("arclen.svginput").sniff(text:sub(1, 12)) ~= nil
end

-- Is argument a path data rather than a file name?  Path data starts with
-- a moveto and its first number (SVG 2 section 9.3.9), so "map.svg" is a file.
local function path_data(a)
  return a:find("^%s*[Mm][%s,]*[%d%.%+%-]") ~= nil
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
    nums[i] = number_arg(a)          -- nan, inf: a cubic's coordinates, refused as 1e400
    if nums[i] == nil then allnum = false end
  end
  if allnum then
    if #nums ~= 8 and #nums ~= 12 then
      fail(format("%s: a cubic needs 8 (2D) or 12 (3D) numbers, got %d", what, #nums), 2)
    end
    return {{label = "cubic", path = call(2, arclen.path, {nums}, o)}}, nums
  end
  if #rest > 1 then
    fail(format("%s: expected one path (quote path data), got %d arguments", what, #rest), 2)
  end
  local a = rest[1]
  local text, source = nil, nil
  if a == "-" then
    text, source = read_file("-"), "stdin"
  elseif not path_data(a) then
    local f, err, code = io.open(a, "rb")
    if not f and code ~= 2 then     -- not ENOENT: permission denied...
      fail(a .. ": " .. require("arclen.svginput").reason(err))
    end
    if not f then fail(a .. ": no such file (and not SVG path data, which starts with M)") end
    f:close()
    text, source = "<", a       -- read by the document reader itself
  end
  o.arcs = opts.arcs            -- path data's arcs, as a document's
  if text == nil then
    return {{label = "path", path = call(1, arclen.path.svg, a, o)}}
  end
  if not markup(text) then     -- path data on stdin
    return {{label = "path", path = call(1, arclen.path.svg, text, o)}}
  end
  local doc = read_svg(source, a == "-" and text or nil, opts)
  local out = {}
  for i, e in ipairs(doc.elements) do
    out[i] = {label = e.id or (e.tag .. i), index = i, path = e.path, element = e}
  end
  out.doc = doc
  return out
end

local function one(list, what)
  if #list ~= 1 then
    fail(format("%s needs one path; the file has %d (extract one, e.g. by its d attribute)", what, #list), 2)
  end
  return list[1].path
end

local function distance(args, i, what)
  local s = number_arg(args[i] or "")
  if s == nil then fail(format("%s: the distance S must be a number, got '%s'", what, tostring(args[i])), 2) end
  if not isfinite(s) then
    fail(format("%s: the distance S must be a finite number, got '%s'", what, args[i]), 2)
  end
  return s
end

-- ---- commands -----------------------------------------------------------

local commands = {}

function commands.henkel()
  io.write(require("arclen.repro.henkel").report())
end

-- length of a document, streamed: a row per element as it is read.  In a
-- batch (several files) the JSON object is one of a list, and a file that
-- fails returns nil and its message instead of ending the run.
local function length_doc(src, name, opts, batch)
  local n, rows_json, dk = 0, opts.json, nil
  local json_open = false
  if rows_json then dk = json_lib() end
  -- a row in one string, one write: "id\tlength\n", or "tagN\tlength\n"
  local write, with_id, with_tag = io.write, numtext.format_now("%s\t%.17g\n"),
    numtext.format_now("%s%d\t%.17g\n")
  local head = rows_json and (batch and "{\"file\":" .. dk.encode(name) .. ",\"paths\":[" or "{\"paths\":[")
  local function row(e)
    n = n + 1
    local id = rawget(e, "id")        -- never made lazily: no __index
    if rows_json then
      write(json_open and "," or head, json({id = id or (e.tag .. n), tag = e.tag,
        layer = e.layer, length = e.length, segments = e.path:segments(), use = e.use,
        marker = e.marker}))
      json_open = true
    elseif id then
      write(with_id(id, e.length))
    else
      write(with_tag(e.tag, n, e.length))
    end
  end
  if batch and not rows_json then write("== ", name, "\n") end
  -- the rows need each element's numbers only (JSON: its segments too)
  local doc, err = each_svg(src, name, opts, row, true, batch, not rows_json)
  if doc == nil then
    io.stderr:write("arclen: ", err, "\n")
    if rows_json then
      write(json_open and "" or head, "],\"error\":", dk.encode(err), "}")
    end
    return nil, err
  end
  if n == 0 then io.stderr:write("arclen: warning: ", doc.name, ": nothing drawn\n") end
  if rows_json then
    -- the keys in order, as json() writes a whole object: paths, total, units
    write(json_open and "" or head, "],\"total\":", shortest(doc.total),
      ",\"units\":", dk.encode(doc.units), batch and "}" or "}\n")
  else
    print("total\t" .. g17(doc.total))
  end
  return doc
end

-- length of several documents: each as one alone, under its name, then
-- the sum of those measured; a file that fails is reported with its place
-- and the others are still measured (exit status 1, as stat).
local function length_docs(files, opts)
  local sum, sum_c, failed, units = 0, 0, 0, nil
  if opts.json then io.write("{\"files\":[") end
  for i, f in ipairs(files) do
    if opts.json and i > 1 then io.write(",") end
    local doc = length_doc(f, f, opts, true)
    if doc then
      -- Neumaier's sum, as the documents' own totals
      local t = sum + doc.total
      if math.abs(sum) >= math.abs(doc.total) then sum_c = sum_c + ((sum - t) + doc.total)
      else sum_c = sum_c + ((doc.total - t) + sum) end
      sum, units = t, doc.units
    else
      failed = failed + 1
    end
  end
  sum = sum + sum_c
  if opts.json then
    io.write("],\"total\":", shortest(sum), ",\"units\":", json_lib().encode(units or "user"), "}\n")
  else
    io.write("== ", numtext.tostring(#files - failed), " of ", numtext.tostring(#files), " files\n")
    print("total\t" .. g17(sum))
  end
  if failed > 0 then
    io.stderr:write(format("arclen: length: %d of %d files failed\n", failed, #files))
    os.exit(1)
  end
end

-- Is WHAT (args[from..]) one SVG document: a file that is not path data,
-- or stdin with markup?  Returns the source for svg.each and its name.
local function document_arg(args, from)
  if #args ~= from then return nil end
  local a = args[from]
  if tonumber(a) then return nil end
  if a == "-" then
    local first = stdin_peek()
    if not markup(first) then return nil end
    local given = false
    return function()
      if not given then given = true return first end
      return io.stdin:read(CHUNK)
    end, "stdin"
  end
  if path_data(a) then return nil end
  local f = io.open(a, "rb")
  if not f then return nil end
  f:close()
  return a, a
end

function commands.length(opts, args)
  local arclen = require("arclen")
  local src, name = document_arg(args, 2)
  if src then return length_doc(src, name, opts) end
  if #args > 2 then                 -- several documents (not numbers, not path data)
    local files = {}
    for i = 2, #args do
      if tonumber(args[i]) or path_data(args[i]) or args[i] == "-" then files = nil break end
      files[#files + 1] = args[i]
    end
    if files then return length_docs(files, opts) end
  end
  local list, nums = targets(args, 2, opts, "length")
  if nums then                    -- one cubic: also the cost and error estimate
    local o = method_opts(opts)
    o.info = true
    local L, info = call(2, arclen.length, nums, o)
    if L == math.huge then fail("length: the cubic's length overflows (beyond the doubles)") end
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
    -- inf is no length to print (a document's element fails so too)
    if L == math.huge then fail("length: the path's length overflows (beyond the doubles)") end
    total = total + L
    rows[i] = {id = t.label, length = L, segments = t.path:segments()}
  end
  if opts.json then
    print(json(rows[1]))
  else
    print(g17(total))
  end
end

-- What vpype stat prints, per layer and in total, for each file.
local function stat_lines(name, st, units)
  local out = {"== " .. name .. " (units: " .. units .. ")"}
  local function block(title, r, layers)
    out[#out + 1] = title
    if layers then out[#out + 1] = "  Layer count: " .. numtext.tostring(layers) end
    out[#out + 1] = "  Length: " .. g17(r.length)
    out[#out + 1] = "  Pen-up length: " .. g17(r.travel)
    out[#out + 1] = "  Path count: " .. numtext.tostring(r.paths)
    out[#out + 1] = "  Element count: " .. numtext.tostring(r.elements)
    out[#out + 1] = "  Segment count: " .. numtext.tostring(r.segments)
    out[#out + 1] = "  Mean segment length: " .. (r.segments > 0 and g17(r.length / r.segments) or "n/a")
    local b = r.bbox
    out[#out + 1] = "  Bounding box: " .. (b and format("(%s, %s, %s, %s)",
      g17(b[1]), g17(b[2]), g17(b[3]), g17(b[4])) or "n/a")
  end
  for _, L in ipairs(st.layers) do block("Layer " .. L.name, L) end
  block("Totals", st.total, #st.layers)
  return out
end

function commands.stat(opts, args)
  local svg = svg_lib()
  if #args < 2 then fail("stat: no file (one or more SVG files)", 2) end
  local files, all = {}, {length = 0, travel = 0, paths = 0, elements = 0, segments = 0}
  local units, failed = svg_opts(opts).units or "user", {}
  -- a file that fails is reported (its place in the message) and the
  -- others are still measured; the exit status says that one failed
  local function add(file, st)
    for _, k in ipairs({"length", "travel", "paths", "elements", "segments"}) do
      all[k] = all[k] + st.total[k]
    end
    local b = st.total.bbox
    if b then
      if not all.bbox then all.bbox = {b[1], b[2], b[3], b[4]}
      else
        local a = all.bbox
        a[1], a[2] = math.min(a[1], b[1]), math.min(a[2], b[2])
        a[3], a[4] = math.max(a[3], b[3]), math.max(a[4], b[4])
      end
    end
    files[#files + 1] = {file = file, layers = st.layers, total = st.total}
  end
  for i = 2, #args do
    local acc = svg.stats()     -- one row per layer, whatever the file's size
    local doc, err = each_svg(args[i], args[i], opts, function(e) acc:add(e) end, false, true)
    if doc == nil then
      io.stderr:write("arclen: ", err, "\n")
      failed[#failed + 1] = {file = args[i], error = err}
    else
      units = doc.units
      add(args[i], acc:result())
    end
  end
  local function done()
    if #failed == 0 then return end
    io.stderr:write(format("arclen: stat: %d of %d files failed\n", #failed, #args - 1))
    os.exit(1)
  end
  if opts.json then
    print(json({files = files, total = all, units = units, failed = failed[1] and failed or nil}))
    return done()
  end
  for _, f in ipairs(files) do
    for _, line in ipairs(stat_lines(f.file, f, units)) do print(line) end
  end
  if #files > 1 then
    for _, line in ipairs(stat_lines(#files .. " files", {layers = {}, total = all}, units)) do
      if not line:match("Layer count") then print(line) end
    end
  end
  done()
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
    print(format("%s %s %s %s", g17(x), g17(y), g17(tx), g17(ty)))
  end
end

function commands.resample(opts, args)
  local spec, from
  if opts.step then
    spec = {step = number_arg(opts.step)}
    if spec.step == nil then fail("--step: '" .. opts.step .. "' is not a number", 2) end
    from = 2
  else
    spec = number_arg(args[2] or "")
    if spec == nil then fail("resample: the count N must be a number (or give --step H)", 2) end
    from = 3
  end
  local p = one(targets(args, from, opts, "resample"), "resample")
  -- N or H refused: a usage error; a path that cannot answer: a failure
  local ok, pts = pcall(p.resample, p, spec)
  if not ok then fail(message(pts), tostring(pts):find("bad argument", 1, true) and 2 or 1) end
  if opts.json then
    local out = {}
    for i, q in ipairs(pts) do
      out[i] = {x = q.x, y = q.y, s = q.s, time = q.time, tx = q.tx, ty = q.ty}
    end
    print(json(out))
  else
    for _, q in ipairs(pts) do print(format("%s %s", g17(q.x), g17(q.y))) end
  end
end

function commands.fit(opts, args)
  local arclen = require("arclen")
  local nums = {}
  for i = 2, #args do
    local v = number_arg(args[i])
    if v == nil then fail(format("fit: '%s' is not a number", args[i]), 2) end
    nums[#nums + 1] = v
  end
  if #nums ~= 8 and #nums ~= 12 then
    fail(format("fit: a cubic needs 8 (2D) or 12 (3D) numbers, got %d", #nums), 2)
  end
  local o = method_opts(opts)
  if opts.n then
    o.n = number_arg(opts.n)
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
    print(format("method\t%s\nspans\t%d\ntotal\t%s\nmax_error\t%.3g\nmean_error\t%.3g",
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
  check_arcs(opts)
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
if as_script then cli.main(arg) end

return cli
