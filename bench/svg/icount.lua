-- bench/svg/icount.lua -- the driver of bench/svg/icount.sh: one pass of
-- arclen.svg over the files, up to a stage, so that callgrind's totals of
-- successive stages give each stage's instructions.
--   lua5.4 bench/svg/icount.lua STAGE FILE...
-- STAGE: load (the modules only), read (every file read, measure =
-- false), measure (read, then every element's p:length()).
local svg = require("arclen.svg")
local stage = arg[1]
local docs = {}
if stage == "read" or stage == "measure" then
  for i = 2, #arg do docs[#docs + 1] = svg.read(arg[i], {measure = false}) end
end
if stage == "measure" then
  for _, doc in ipairs(docs) do
    for _, e in ipairs(doc.elements) do e.path:length() end
  end
end
