-- arclen.svginput -- documents as users have them, for arclen.svg: a
-- file opened with a clear message (no such file, permission denied, a
-- directory), the first bytes looked at (gzip, Inkscape's .svgz, inflated
-- as a stream; a PNG, a PDF... named as what it is), the chunks handed on.
local M = {}

local format, sub, byte, lower = string.format, string.sub, string.byte, string.lower
local huge = math.huge

-- Magic numbers of the files that are taken for SVG by mistake.
local MAGIC = {
  {"\137PNG\r\n\26\n", "a PNG image"},
  {"%PDF-", "a PDF document"},
  {"\255\216\255", "a JPEG image"},
  {"GIF87a", "a GIF image"}, {"GIF89a", "a GIF image"},
  {"PK\3\4", "a ZIP archive"},
  {"%!PS", "a PostScript document"},
  {"BZh", "bzip2-compressed data"},
  {"\253" .. "7zXZ\0", "xz-compressed data"},
  {"\40\181\47\253", "zstd-compressed data"},
  {"wOFF", "a WOFF font"}, {"wOF2", "a WOFF2 font"},
}
local HEAD = 12                       -- bytes looked at (WebP: 12)

-- What head (the first bytes) is: "gzip", a description of a format that
-- is not SVG, or nil (text: the reader decides).
local function sniff(head)
  if byte(head, 1) == 0x1f and byte(head, 2) == 0x8b then return "gzip" end
  if sub(head, 1, 4) == "RIFF" and sub(head, 9, 12) == "WEBP" then return "a WebP image" end
  for _, m in ipairs(MAGIC) do
    if sub(head, 1, #m[1]) == m[1] then return m[2] end
  end
  return nil
end

-- The chunks of next_chunk's bytes inflated (svgdoc.gunzip); errors name
-- the document.
local function inflated(svgdoc, name, raw)
  if not svgdoc.gzip then
    error(format("%s: gzip-compressed (.svgz): this arclen.svgdoc was built without zlib; "
      .. "install zlib's headers (Debian zlib1g-dev; sh tools/deps.sh) and make again, "
      .. "or gunzip the file first", name), 0)
  end
  local g = svgdoc.gunzip()
  local function step(f, ...)
    local ok, out = pcall(f, g, ...)
    if not ok then error(format("%s: %s", name, tostring(out)), 0) end
    return out
  end
  local done = false
  return function()
    if done then return nil end
    for _ = 1, huge do
      local out = step(g.read)       -- at most 64 KiB: memory stays bounded
      if out then return out end
      local c = raw()
      if c == nil then
        step(g.finish)
        done = true
        return nil
      end
      step(g.feed, c)
    end
  end
end

-- The chunks of a document from next_chunk, its first bytes looked at
-- (at the first call: a file read twice is read in turn): inflated when
-- gzip (info.gzip set then), a located error at 1:1 when another format.
function M.chunks(svgdoc, name, next_chunk)
  local info, it = {}, nil
  local function start()
    local head, eof = "", false
    while #head < HEAD do
      local c = next_chunk()
      if c == nil then eof = true break end
      head = head .. c
    end
    local given = false
    local function raw()
      if not given then
        given = true
        if head ~= "" then return head end
      end
      if eof then return nil end
      local c = next_chunk()
      if c == nil then eof = true end
      return c
    end
    local kind = sniff(head)
    if kind == "gzip" then
      info.gzip = true
      return inflated(svgdoc, name, raw)
    end
    if kind then
      error({line = 1, col = 1, msg = format("not an SVG document (it looks like %s)", kind)}, 0)
    end
    return raw
  end
  return function()
    if it == nil then it = start() end
    return it()
  end, info
end

-- The message of io.open's or read's failure, without the name, said
-- plainly: "no such file", "permission denied", "is a directory".
local function reason(err)
  local m = tostring(err):gsub("^.*: ", "")
  m = lower(sub(m, 1, 1)) .. sub(m, 2)
  if m == "no such file or directory" then return "no such file" end
  return m
end

-- The file opened for reading, its first byte read to show a directory or
-- an unreadable file, then back at the start; an error "NAME: reason".
function M.open(name)
  local f, err = io.open(name, "rb")
  if not f then error(format("%s: %s", name, reason(err)), 0) end
  local c, rerr = f:read(1)
  if c == nil and rerr then
    f:close()
    error(format("%s: %s", name, reason(rerr)), 0)
  end
  f:seek("set", 0)
  return f
end

M.reason = reason
M.sniff = sniff

return M
