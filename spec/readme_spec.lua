-- spec/readme_spec.lua -- every ```lua block of README.md and of doc/*.md
-- runs against the fresh build, and every `print(...) --> value` line
-- prints that value (numbers compared as numbers, so 10 and 10.0 agree
-- across Lua versions).  The examples cannot rot.
local DOCS = {"README.md", "doc/api.md", "doc/method.md", "doc/accuracy.md",
              "doc/benchmarks.md", "doc/papers.md", "doc/reproductions.md",
              "doc/testing.md", "doc/architecture.md"}
for _, extra in ipairs({"doc/svg.md", "doc/luatex.md"}) do
  local f = io.open(extra)
  if f then f:close(); DOCS[#DOCS + 1] = extra end
end

local function blocks(file)
  local f = assert(io.open(file))
  local text = f:read("*a")
  f:close()
  local out, n = {}, 0
  for _ in text:gmatch("```lua\n") do n = n + 1 end
  local pos = 1
  while true do
    local s, e = text:find("```lua\n", pos, true)
    if not s then break end
    local close = assert(text:find("\n```", e, true), file .. ": unclosed ```lua block")
    local first_line = select(2, text:sub(1, e):gsub("\n", "")) + 1
    out[#out + 1] = {code = text:sub(e + 1, close), line = first_line}
    pos = close + 4
  end
  assert(#out == n)
  return out
end

-- The expected values of annotated lines: {[line in block] = "value"}.
local function annotations(code)
  local want, i = {}, 0
  for line in (code .. "\n"):gmatch("([^\n]*)\n") do
    i = i + 1
    local v = line:match("^%s*print%(.*%)%s*%-%->%s*(.-)%s*$")
    if v then want[i] = v:gsub("%s*%b()$", "") end   -- "--> 0.5 (a remark)"
  end
  return want
end

local function same_output(got, want)
  local g, w = {}, {}
  for t in got:gmatch("%S+") do g[#g + 1] = t end
  for t in want:gmatch("%S+") do w[#w + 1] = t end
  if #g ~= #w then return false end
  for i = 1, #w do
    local a, b = tonumber(g[i]), tonumber(w[i])
    if a and b then
      if a ~= b then return false end
    elseif g[i] ~= w[i] then
      return false
    end
  end
  return true
end

local function run(code, name)
  local printed = {}
  local env = setmetatable({}, {__index = _G})
  env.print = function(...)
    local info = debug.getinfo(2, "Sl")
    local parts = {}
    for i = 1, select("#", ...) do parts[i] = tostring((select(i, ...))) end
    if info and info.source == "=" .. name then
      local l = info.currentline
      printed[l] = printed[l] or {}
      table.insert(printed[l], table.concat(parts, "\t"))
    end
  end
  local chunk, err
  if setfenv then
    chunk, err = loadstring(code, "=" .. name)
    if chunk then setfenv(chunk, env) end
  else
    chunk, err = load(code, "=" .. name, "t", env)
  end
  assert(chunk, err)
  chunk()
  return printed
end

for _, file in ipairs(DOCS) do
describe(file, function()
  local list = blocks(file)
  if file == "README.md" or file == "doc/api.md" then
    it("has Lua examples", function() assert.is_true(#list >= 2) end)
  end
  for _, b in ipairs(list) do
    local name = file .. ":" .. b.line
    -- #svgdoc: a block that reads SVG documents needs the reader (the
    -- core rock alone leaves it out: tools/check-rock.sh)
    local tag = b.code:find("arclen.svg\"", 1, true) and " #svgdoc" or ""
    it("runs the ```lua block at line " .. b.line .. " and prints what it says" .. tag, function()
      local printed = run(b.code, name)
      local bad = {}
      for l, want in pairs(annotations(b.code)) do
        local got = printed[l]
        if not got then
          bad[#bad + 1] = ("line %d printed nothing (says %s)"):format(b.line + l - 1, want)
        end
        for _, out in ipairs(got or {}) do
          if not same_output(out, want) then
            bad[#bad + 1] = ("line %d printed '%s', says '%s'"):format(b.line + l - 1, out, want)
          end
        end
      end
      table.sort(bad)
      assert.are.same({}, bad)
    end)
  end
end)
end
