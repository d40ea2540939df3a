-- examples/arclen-check.lua -- what the example documents use to write
-- their data files for tools/check-luatex.lua (make luatex sets
-- ARCLEN_DATA; without it nothing is written).  Lua functions called from
-- MetaPost (examples/arclen-check.mp) through runscript.
local Q = string.char(34)      -- a MetaPost string's quote

-- The data file of one figure (each mplibcode is a new MetaPost, which
-- would start a shared file afresh), as a MetaPost string literal.
function arclen_data_open(fig)
  local name = os.getenv("ARCLEN_DATA")
  if not name then return Q .. Q end
  return Q .. name .. "-" .. fig .. Q
end

-- arclen.mpost's record of the last text's placements, as MetaPost
-- statements writing one PLACED line per glyph.
function arclen_placed(name)
  local out = {}
  for _, g in ipairs(package.loaded["arclen.mpost"].placed) do
    out[#out + 1] = "rec " .. Q .. ("PLACED %s %d %.17g %.17g %.17g %.17g"):format(
      name, g.i, g.s, g.w, g.h, g.d) .. Q .. ";"
  end
  return table.concat(out)
end
