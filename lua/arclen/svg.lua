-- arclen.svg -- SVG documents measured as a renderer draws them.
--
--   local svg = require "arclen.svg"
--   local doc = svg.read("drawing.svg" [, opts])    -- a file, streamed
--   local doc = svg.parse(text [, opts [, name]])   -- a string
--   doc.total, doc.elements[i].{id, tag, path, length, layer, line, col, use,
--                               d, ctm}  (d: the shape's path data in its own
--                               coordinates, ctm: {a, b, c, d, e, f} onto the
--                               document's)
--   local sum = svg.each(src, function(e) ... end [, opts])   -- a stream:
--     each element as soon as it is complete, none kept; src a file name,
--     an open file or a function giving chunks; sum: doc without elements
--   svg.stat(doc) -> per layer: length, pen-up travel, paths, segments, bbox
--   svg.stats() -> st: st:add(e) per element, st:result() (svg.stat's)
--
-- The reader is C over expat (src/svgdoc/, the module arclen.svgdoc):
-- streaming, nothing like a DOM is built.  Every basic shape becomes path
-- data as SVG 2 defines it (section 10, "Basic shapes"), mapped by the
-- element's current transformation matrix (nested transform attributes,
-- nested viewports) and read into segments; the reader measures each
-- drawn element as it hands it over (src/svgdoc/measure.c: the double
-- e.path:length() gives), and e.path is made when first read.
-- <use> may point forwards: when the document may contain a <use>
-- element, the subtrees of the elements with an id that uses refer to are
-- kept (a scan of the file first; from a stream, every subtree with an id),
-- and what follows a use of an element not read yet waits until it is.
-- Errors are "NAME:LINE:COL: message"; misuse is "bad argument #n to 'f'".
-- doc/svg.md lists the semantic choices made where the specification leaves
-- room.
local path = require("arclen.path")
local input = require("arclen.svginput")
local svgpath = require("arclen.svgpath")
local core = require("arclen.engine")

-- The reader is an optional part (it links libexpat; the core does not):
-- without it this module does not load, and says what to install.
local has_reader, svgdoc = pcall(require, "arclen.svgdoc")
if not has_reader then
  error("arclen.svg needs its document reader, the C module arclen.svgdoc over libexpat: "
    .. "install the rock arclen-svg (luarocks install arclen-svg), or expat's headers "
    .. "(Debian libexpat1-dev, Homebrew expat; sh tools/deps.sh) and make again ["
    .. tostring(svgdoc):match("^[^\n]*"):gsub(":$", "") .. "]", 0)
end

local M = {}

local numtext = require("arclen.numtext")
local caller = require("arclen.caller")
local format, shortest = numtext.format, numtext.shortest   -- '.' in any locale
local find, sub, floor, huge = string.find, string.sub, math.floor, math.huge
local abs, sqrt = math.abs, math.sqrt

-- Is s a list of language tags, as the lang option takes (ASCII letters,
-- digits and '-', separated by commas and spaces; under 256 bytes)?  The
-- reader's own check (cond.c), in Lua for the messages.
function M.lang_ok(s)
  return type(s) == "string" and #s > 0 and #s < 256 and find(s, "^[A-Za-z0-9%-, ]+$") ~= nil
    and find(s, "[A-Za-z0-9]") ~= nil
end

local MAX_DEPTH = 1000                -- element nesting (the reader's cap)
local MAX_ELEMENTS = 1000000          -- drawn elements svg.read keeps (default)
local CHUNK = 65536                   -- bytes per read of a file

-- Output units: "user" (the root's user units) or one of these, in CSS px
-- (CSS Values 3 section 5.2: 1in = 96px).
local UNITS = {px = 1, ["in"] = 96, cm = 96 / 2.54, mm = 96 / 25.4,
               pt = 96 / 72, pc = 96 / 6}

-- A located error: raised as a table, turned into "NAME:L:C: msg" by read.
local function fail(line, col, msg)
  error({line = line, col = col, msg = msg}, 0)
end

-- level: where the user's call is without the debug library (3:
-- argerror's caller is the API function); with it, the first frame
-- outside arclen's Lua (arclen.caller).
local function argerror(n, fname, msg, level)
  error(format("bad argument #%d to '%s' (%s)", n, fname, msg), caller(level or 3))
end

local function isfinite(x)
  return x == x and x ~= huge and x ~= -huge
end

-- Does the text contain what could be a <use> or <marker> element?  (Decides
-- whether subtrees with ids are kept; a false alarm costs memory, not results.)
local function may_use(s)
  return find(s, "<use", 1, true) or find(s, ":use", 1, true)
    or find(s, "<marker", 1, true) or find(s, ":marker", 1, true)
end

-- Might s refer to a paint server?  Then the scan for the ids is worth
-- its pass: a fill or stroke of url(#id) that names none paints nothing.
local function may_refer(s)
  return find(s, "url(", 1, true)
end

-- The largest magnitude among p's control points (for messages).
local function largest_coordinate(p)
  local top = 0
  for k = 1, p.n do
    local c, kind = p:segment(k)
    for j = 1, #c - (kind == "conic" and 1 or 0) do   -- a conic's weight is no coordinate
      local v = abs(c[j])
      if v > top and v ~= huge then top = v end
    end
  end
  return top
end


-- An error met while measuring element e, located at e and said in the
-- document's terms: "<tag id='..'>: what".  err: an error value of the
-- path layer ("...: bad argument #1 to 'lengths' (why)") or nil when the
-- length overflows.
local function element_fail(e, err)
  local what = e.id and format("<%s id='%s'>", e.tag, e.id) or format("<%s>", e.tag)
  if err == nil then
    fail(e.line, e.col, format("%s: the path's length overflows (coordinates up to %s)",
      what, shortest(largest_coordinate(e.path))))
  end
  local m = tostring(type(err) == "table" and err.msg or err)
  m = m:gsub("^[^\n]-:%d+: ", ""):gsub("^bad argument #%d+ to '[^']*' %((.*)%)$", "%1")
  fail(e.line, e.col, what .. ": " .. m)
end

-- The stream: the document from next_chunk() (nil at the end), scanned
-- first from scan() (a second source of the same bytes, or nil) for the ids
-- <use> and paint refer to; each drawn element made an arclen.path (and measured,
-- when o.measure) and given to on_element as soon as the reader hands it
-- over.  Returns the document without its elements.
local function stream(o, name, next_chunk, uses, scan, on_element, size)
  -- gzip inflated, other formats refused by their first bytes (svginput)
  local info
  next_chunk, info = input.chunks(svgdoc, name, next_chunk)
  if scan then scan = input.chunks(svgdoc, name, scan) end
  local from_subpaths, tol, method = path._from_subpaths, o.tol, o.method
  -- each element's length computed in C as it is read (with the C core
  -- and the default method: the Lua engine's paths, and paths of other
  -- methods, which make their conics cubics, measure their own), its path
  -- made when first asked for (e.path)
  local r = svgdoc.new({arc_tol = o.arc_tol or o.tol, hidden = o.hidden, arcs = o.arcs,
    stroked = o.stroked, painted = o.painted, lang = o.lang, strict = o.strict,
    max_depth = o.max_depth or MAX_DEPTH, uses = uses,
    unit_px = o.units ~= "user" and UNITS[o.units] or 0, stream = true,
    tol = tol, method = o.measure and core.engine == "c" and method == "gauss" and method or nil,
    path = function(subpaths) return from_subpaths(subpaths, tol, method) end,
    bare = o.path == false})
  if scan then
    for _ = 1, huge do
      local chunk = scan()
      if chunk == nil then break end
      r:scan(chunk)
    end
  end
  local measure, cap, progress = o.measure, o.max_elements, o.progress
  local count, total, comp, bytes = 0, 0, 0, 0
  local function take(list)
    for k = 1, #list do
      local e = list[k]
      count = count + 1
      if count > cap then         -- checked as they come, not at the end
        fail(e.line, e.col, format("more than %d drawn elements", cap))
      end
      if measure then
        local L = rawget(e, "length")
        if L == nil then          -- the reader's measure failed: the path's own, and its error
          local ok, p = pcall(function() return e.path end)
          if not ok then element_fail(e, p) end
          local ok2, err
          ok2, L, err = pcall(p.length, p)
          if not ok2 then element_fail(e, L) end
          if L == nil then element_fail(e, err) end
          if not isfinite(L) then element_fail(e, nil) end
          e.length = L
        end
        local t = total + L
        if t == huge then         -- lengths are finite and >= 0: only this overflow
          fail(e.line, e.col, format("<%s>: the total length overflows here (%s before it, %s in it)",
            e.tag, shortest(total), shortest(L)))
        end
        -- Neumaier's compensated sum (terms >= 0): 10^5 lengths within an
        -- ulp or two, where the plain sum lost 2.3e-14 on 10^5 circles
        if total >= L then comp = comp + ((total - t) + L)
        else comp = comp + ((L - t) + total) end
        total = t
      end
      on_element(e)
    end
  end
  for _ = 1, huge do
    local chunk = next_chunk()
    if chunk == nil then break end
    bytes = bytes + #chunk
    local list = r:feed(chunk)
    if list then take(list) end
    if progress then progress(bytes, not info.gzip and size or nil, count) end  -- inflated bytes
  end
  local res = r:finish(name)
  take(res.elements)
  return {name = name, warnings = res.warnings, skipped = res.skipped, units = o.units,
    kept = res.kept, total = measure and total + comp or nil, count = count, bytes = bytes,
    width = res.width, height = res.height, viewbox = res.viewbox}
end

-- The options of read, parse and each: tol, arc_tol, method, units,
-- hidden, stroked, painted, lang, strict (the reader's warnings are errors),
-- measure, max_depth, arcs, max_elements, progress, path (false: the
-- elements the reader measures come without path, ctm and a basic shape's
-- d: the command line's rows need their numbers only); each's name.
-- n: the options' argument position.
local function read_opts(opts, fname, cap, n)
  n = n or 2
  local function argerror4(_, f, msg) argerror(n, f, msg, 5) end
  local o = {tol = 1e-12, method = "gauss", measure = true, units = "user", max_elements = cap}
  if opts == nil then return o end
  if type(opts) ~= "table" then argerror4(2, fname, "options table expected, got " .. type(opts)) end
  for k, v in pairs(opts) do
    if k == "tol" or k == "arc_tol" then
      if type(v) ~= "number" or not (v >= core.tol_min and v <= core.tol_max) then
        argerror4(2, fname, format("%s must be in [%g, %g]", k, core.tol_min, core.tol_max))
      end
    elseif k == "method" then
      if type(v) ~= "string" then argerror4(2, fname, "method must be a string") end
      if not core.method(v) then argerror4(2, fname, format("unknown method '%s'", v)) end
    elseif k == "units" then
      if v ~= "user" and not UNITS[v] then
        argerror4(2, fname, format("unknown units '%s' (user, px, mm, cm, in, pt, pc)", tostring(v)))
      end
    elseif k == "arcs" then
      if v ~= "conics" and v ~= "cubics" then argerror4(2, fname, 'arcs must be "conics" or "cubics"') end
    elseif k == "hidden" or k == "stroked" or k == "painted" or k == "measure"
        or k == "strict" then
      if type(v) ~= "boolean" then argerror4(2, fname, k .. " must be a boolean") end
      if (k == "stroked" and v and opts.painted) or (k == "painted" and v and opts.stroked) then
        argerror4(2, fname, "stroked and painted exclude each other")
      end
    elseif k == "lang" then
      if type(v) ~= "string" or not M.lang_ok(v) then
        argerror4(2, fname, 'lang must be language tags separated by commas ("en", "de,en-US")')
      end
    elseif k == "max_depth" then
      if type(v) ~= "number" or v ~= floor(v) or v < 1 or v > MAX_DEPTH then
        argerror4(2, fname, format("max_depth must be an integer in [1, %d]", MAX_DEPTH))
      end
    elseif k == "max_elements" then
      if type(v) ~= "number" or not (v >= 0) or (v ~= floor(v) and v ~= huge) then
        argerror4(2, fname, "max_elements must be a whole number >= 0 (or math.huge)")
      end
    elseif k == "path" then
      if type(v) ~= "boolean" then argerror4(2, fname, "path must be a boolean") end
    elseif k == "progress" then
      if type(v) ~= "function" then argerror4(2, fname, "progress must be a function") end
    elseif k == "name" and fname == "arclen.svg.each" then
      if type(v) ~= "string" then argerror4(2, fname, "name must be a string") end
    else
      argerror4(2, fname, format("unknown option '%s'", tostring(k)))
    end
    o[k] = v
  end
  return o
end

-- A located error table into "NAME:LINE:COL: message".
local function located(name, e)
  if type(e) == "table" and e.msg then
    return format("%s:%d:%d: %s", name, e.line or 0, e.col or 0, e.msg)
  end
  return e
end

-- The chunks of text, CHUNK bytes each.
local function text_chunks(text)
  local pos = 1
  return function()
    if pos > #text then return nil end
    local c = sub(text, pos, pos + CHUNK - 1)
    pos = pos + CHUNK
    return c
  end
end

-- Run f (the stream) with the located errors made "NAME:LINE:COL: msg".
local function located_call(name, f)
  local ok, res = pcall(f)
  if not ok then error(located(name, res), 0) end
  return res
end

-- The document with its elements collected (read and parse).
local function collect(o, name, next_chunk, uses, scan, size)
  local els = {}
  local doc = stream(o, name, next_chunk, uses, scan, function(e) els[#els + 1] = e end, size)
  doc.elements, doc.count, doc.bytes = els, nil, nil
  return doc
end

-- Chunks (inflated when the file is gzip): do they contain what could be
-- a <use> element?
-- Does the text of next_chunk() have a <use>, a url( ?  (Read to the end
-- only when it has not both.)
local function chunks_may_use(next_chunk)
  local tail, uses, refers = "", false, false
  for _ = 1, huge do
    local c = next_chunk()
    if c == nil then return uses, refers end
    local edge = tail .. sub(c, 1, 8)
    uses = uses or (may_use(edge) or may_use(c)) and true or false
    refers = refers or (may_refer(edge) or may_refer(c)) and true or false
    if uses and refers then return true, true end
    tail = sub(c, -8)
  end
end

-- svg.parse(text [, opts [, name]]) -> doc.  name (default "<string>")
-- names the document in messages.
function M.parse(text, opts, name)
  if type(text) ~= "string" then argerror(1, "arclen.svg.parse", "SVG text (a string) expected, got " .. type(text)) end
  local o = read_opts(opts, "arclen.svg.parse", MAX_ELEMENTS)
  if name ~= nil and type(name) ~= "string" then argerror(3, "arclen.svg.parse", "name must be a string") end
  name = name or "<string>"
  return located_call(name, function()
    local uses, refers = may_use(text) and true or false, may_refer(text) and true or false
    if input.sniff(sub(text, 1, 12)) == "gzip" then   -- what it inflates to
      uses, refers = chunks_may_use((input.chunks(svgdoc, name, text_chunks(text))))
    end
    local scan = (uses or refers) and text_chunks(text) or nil
    return collect(o, name, text_chunks(text), uses, scan, #text)
  end)
end

-- The stream of a file by name: three passes when it may contain <use> or
-- url( (the byte scan, the scan for the ids, the reading), else two; each
-- from the file's start (and through the inflater, a gzip file).
local function stream_file(o, filename, on_element)
  local f = input.open(filename)        -- "NAME: permission denied" ...
  local size = f:seek("end")
  local function from_start()
    f:seek("set", 0)
    return function() return f:read(CHUNK) end
  end
  local ok, res = pcall(function()
    local uses, refers = chunks_may_use((input.chunks(svgdoc, filename, from_start())))
    -- the scan reads the whole file first, then the reading: each starts
    -- over at its first call
    local scanning, reading
    local function scan()
      if scanning == nil then scanning = from_start() end
      return scanning()
    end
    local function next_chunk()
      if reading == nil then reading = from_start() end
      return reading()
    end
    return stream(o, filename, next_chunk, uses, (uses or refers) and scan or nil, on_element, size)
  end)
  f:close()
  if not ok then error(located(filename, res), 0) end
  return res
end

-- svg.read(filename [, opts]) -> doc: the file read in chunks of 64 KiB.
function M.read(filename, opts)
  if type(filename) ~= "string" then argerror(1, "arclen.svg.read", "a file name expected, got " .. type(filename)) end
  local o = read_opts(opts, "arclen.svg.read", MAX_ELEMENTS)
  local els = {}
  local doc = stream_file(o, filename, function(e) els[#els + 1] = e end)
  doc.elements, doc.count, doc.bytes = els, nil, nil
  return doc
end

-- svg.each(src, fn [, opts]) -> the document without its elements
-- ({name, total, count, warnings, skipped, kept, units, width, height,
-- viewbox, bytes}): fn(e) for each drawn element, in svg.read's order, as
-- soon as it is complete; nothing of it is kept.  src: a file name, an
-- open file (read to its end from where it is; not closed) or a function
-- that returns the next chunk of the document (nil at the end).  From an
-- open file or a function, which cannot be read twice, every subtree with
-- an id is kept while the document is read (what <use> could refer to).
-- opts: svg.read's, and name (the document's in messages; default the file
-- name, "<stream>"), max_elements (default none), progress (a function
-- called after each chunk with the bytes read, the file's size or nil,
-- and the elements so far).
function M.each(src, fn, opts)
  local fname = "arclen.svg.each"
  local kind = type(src) == "string" and "name" or io.type(src) == "file" and "file"
    or type(src) == "function" and "function" or nil
  if not kind then argerror(1, fname, "a file name, an open file or a function expected, got " .. type(src)) end
  if type(fn) ~= "function" then argerror(2, fname, "a function expected, got " .. type(fn)) end
  local o = read_opts(opts, fname, huge, 3)
  if kind == "name" then return stream_file(o, src, fn) end
  local name = o.name or "<stream>"
  local next_chunk = kind == "file" and function() return src:read(CHUNK) end or src
  if kind == "function" then
    -- a chunk that is no string would be read as text (a number) or fail
    -- deep in the reader under its names
    next_chunk = function()
      local chunk = src()
      if chunk ~= nil and type(chunk) ~= "string" then
        error(format("bad argument #1 to '%s' (the source function returned a %s: "
          .. "it must return strings, then nil at the end)", fname, type(chunk)), 0)
      end
      return chunk
    end
  end
  return located_call(name, function()
    return stream(o, name, next_chunk, true, nil, fn, nil)
  end)
end

-- ---- stat: what vpype stat prints ----------------------------------------

local function box_add(b, x0, y0, x1, y1)
  if b[1] == nil then b[1], b[2], b[3], b[4] = x0, y0, x1, y1 return end
  if x0 < b[1] then b[1] = x0 end
  if y0 < b[2] then b[2] = y0 end
  if x1 > b[3] then b[3] = x1 end
  if y1 > b[4] then b[4] = y1 end
end

-- svg.stats() -> st: svg.stat's numbers gathered one element at a time
-- (st:add(e), in document order), so that a stream keeps only one row per
-- layer; st:result() -> what svg.stat returns.
local Stats = {}
Stats.__index = Stats
local stat_add = svgdoc.stat_add

-- s + x as Neumaier's compensated sum: the new sum and compensation (the
-- result is sum + comp); 10^5 terms within an ulp or two.
local function neumaier(sum, comp, x)
  local t = sum + x
  if abs(sum) >= abs(x) then return t, comp + ((sum - t) + x) end
  return t, comp + ((x - t) + sum)
end

function M.stats()
  return setmetatable({layers = {}, by = {}}, Stats)
end

function Stats:add(e)
  local L = self.by[e.layer]
  if not L then
    L = {name = e.layer, length = 0, travel = 0, paths = 0, elements = 0, segments = 0, box = {},
         lc = 0, tc = 0}                     -- the sums' compensations
    self.by[e.layer] = L
    self.layers[#self.layers + 1] = L
  end
  -- the reader's element whose path is not made yet: the same numbers in
  -- C from its segments (`arclen stat` spent most of its time on the paths)
  if stat_add(e, L) then return end
  local p = e.path
  L.length, L.lc = neumaier(L.length, L.lc, e.length or p:length())
  L.elements = L.elements + 1
  L.paths = L.paths + p.nsub
  L.segments = L.segments + p.n
  for j = 1, p.nsub do
    local first = p:segment(p.first[j])
    local last, lastkind = p:segment(p.first[j + 1] - 1)
    if L.endx then
      local dx, dy = first[1] - L.endx, first[2] - L.endy
      L.travel, L.tc = neumaier(L.travel, L.tc, sqrt(dx * dx + dy * dy))
    end
    L.endx, L.endy = svgpath.segment_end(last, lastkind)
  end
  for k = 1, p.n do
    box_add(L.box, svgpath.segment_box(p:segment(k)))
  end
end

function Stats:result()
  local total = {name = "total", length = 0, travel = 0, paths = 0, elements = 0, segments = 0, box = {}}
  local out, lc, tc = {}, 0, 0
  for i, L in ipairs(self.layers) do
    local length, travel = L.length + L.lc, L.travel + L.tc
    total.length, lc = neumaier(total.length, lc, L.length)
    total.length, lc = neumaier(total.length, lc, L.lc)
    total.travel, tc = neumaier(total.travel, tc, L.travel)
    total.travel, tc = neumaier(total.travel, tc, L.tc)
    total.paths = total.paths + L.paths
    total.elements = total.elements + L.elements
    total.segments = total.segments + L.segments
    if L.box[1] then box_add(total.box, L.box[1], L.box[2], L.box[3], L.box[4]) end
    out[i] = {name = L.name, length = length, travel = travel, paths = L.paths,
              elements = L.elements, segments = L.segments,
              bbox = L.box[1] and {L.box[1], L.box[2], L.box[3], L.box[4]} or nil}
  end
  total.length, total.travel = total.length + lc, total.travel + tc
  total.bbox = total.box[1] and total.box or nil
  total.box = nil
  return {layers = out, total = total}
end

-- svg.stat(doc) -> {layers = {{name, length, travel, paths, elements,
-- segments, bbox = {x0, y0, x1, y1}}...}, total = {same fields}}.  paths
-- counts subpaths (vpype reads each subpath as a line), elements the drawn
-- elements, segments the segments as drawn (a circle: four conics).
-- Pen-up travel: from each subpath's end to the next subpath's start in
-- the layer, in document order (vpype's pen-up length).  bbox: the exact bounding box of the curves.
function M.stat(doc)
  if type(doc) ~= "table" or type(doc.elements) ~= "table" then
    argerror(1, "arclen.svg.stat", "a document (from arclen.svg.read or parse) expected")
  end
  local st = M.stats()
  for _, e in ipairs(doc.elements) do st:add(e) end
  return st:result()
end

M.UNITS = UNITS

return M
