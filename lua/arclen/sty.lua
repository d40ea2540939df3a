-- arclen.sty -- the Lua side of arclen.sty (tex/arclen.sty): loads arclen
-- through kpathsea with the engine the document asked for and reports it.
--
-- In LuaTeX's default mode (shell_escape = p) binary modules are refused:
-- package.loadlib is a no-op and the C searchers are gone.  Then, and
-- with engine=lua, arclen answers with its Lua engine (arclen.pure).
-- With --shell-escape and engine=auto or c, the C core is looked for by
-- kpathsea as scripts/arclen/core.so (make install-tex puts it there) and
-- then along package.cpath.
local M = {}

local function tex_error(msg, help)
  tex.error("arclen: " .. msg, {help})
end

-- The C core's loader: kpathsea's TEXMF trees, then package.cpath.
local function core_loader()
  local file
  if kpse and kpse.find_file then
    file = kpse.find_file("arclen/core.so", "texmfscripts")
  end
  if not file then file = package.searchpath("arclen.core", package.cpath) end
  if not file then return nil, "no arclen/core.so in scripts/arclen/ or package.cpath" end
  local open, why = package.loadlib(file, "luaopen_arclen_core")
  if not open then return nil, ("%s: %s"):format(file, tostring(why or "loading refused")) end
  return open
end

-- load(engine, tol): engine "auto", "lua" or "c", tol a number's text
-- (the package options); returns the module.
function M.load(engine, tol)
  if engine ~= "auto" and engine ~= "lua" and engine ~= "c" then
    tex_error(("engine must be auto, lua or c, got '%s'; using auto"):format(engine),
      "\\usepackage[engine=auto]{arclen}: auto takes the C core where it loads.")
    engine = "auto"
  end
  local tolnum = tonumber(tol)
  if tol and not tolnum then
    tex_error(("tol must be a number, got '%s'; using 1e-12"):format(tol),
      "\\usepackage[tol=1e-12]{arclen}: the relative tolerance, in [1e-15, 0.1].")
  end
  tol = tolnum
  local loaded = package.loaded["arclen"]
  if loaded then
    if engine ~= "auto" and loaded.engine ~= engine then
      tex_error(("engine=%s asked, but arclen is already loaded with engine %s")
        :format(engine, tostring(loaded.engine)),
        "Load arclen.sty before anything else that loads arclen.")
    end
  else
    if engine == "lua" or status.shell_escape ~= 1 then
      if engine == "c" then
        tex_error("engine=c needs --shell-escape (LuaTeX loads binary modules only then); "
          .. "using the Lua engine",
          "Run lualatex --shell-escape, or use engine=auto or engine=lua.")
      end
      package.loaded["arclen.core"] = false      -- arclen.engine: use arclen.pure
    elseif not package.loaded["arclen.core"] then
      local open, why = core_loader()
      if open then
        package.preload["arclen.core"] = open
      else
        if engine == "c" then
          tex_error("engine=c, but the C core does not load (" .. why .. "); using the Lua engine",
            "make install-tex puts the core under scripts/arclen/ (make LUA=5.3 first).")
        end
        package.loaded["arclen.core"] = false
      end
    end
  end
  local arclen = require("arclen")
  if tol then require("arclen.pgf").settol(tol) end
  local reason = ""
  if arclen.engine == "lua" then
    reason = (status.shell_escape ~= 1) and " (binary modules need --shell-escape)"
      or (engine == "lua") and " (engine=lua)" or " (the C core did not load)"
  end
  texio.write_nl("log", ("Package arclen Info: engine %s%s, tol %s."):format(
    arclen.engine, reason, tostring(require("arclen.pgf").tol)))
  return arclen
end

return M
