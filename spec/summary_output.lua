-- spec/summary_output.lua -- busted's plain terminal output, then one
-- line "N passed, N failed", which CI reads.  Errors and pending specs
-- count as failed: a spec that could not run has not passed.
return function(options)
  local busted = require("busted")
  local handler = require("busted.outputHandlers.plainTerminal")(options)
  busted.subscribe({"suite", "end"}, function()
    io.write(string.format("\n%d passed, %d failed\n", handler.successesCount,
      handler.failuresCount + handler.errorsCount + handler.pendingsCount))
    io.flush()
    return nil, true
  end)
  return handler
end
