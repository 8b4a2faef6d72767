--- Counting mismatches over many generated cases, keeping the first few for the failure message.

local tally = {}
tally.__index = tally

function tally.new(what)
  return setmetatable({ what = what, count = 0, total = 0, examples = {} }, tally)
end

-- Format numbers so that every double reads back exactly.
local function show(v)
  if type(v) == "number" then
    return ("%.17g"):format(v)
  elseif type(v) == "table" then
    local parts = {}
    for i = 1, #v do
      parts[i] = show(v[i])
    end
    return "{" .. table.concat(parts, ", ") .. "}"
  end
  return tostring(v)
end
tally.show = show

--- Record one case: ok is whether it matched; the rest describe it (shown when it did not).
function tally:check(ok, ...)
  self.total = self.total + 1
  if not ok then
    self.count = self.count + 1
    if #self.examples < 5 then
      local parts = {}
      for i = 1, select("#", ...) do
        parts[i] = show((select(i, ...)))
      end
      self.examples[#self.examples + 1] = table.concat(parts, " ")
    end
  end
  return ok
end

--- With the environment variable POLYGON_SPEC_COUNTS set, print the count (for measuring how
-- often a naive formula fails); silent otherwise.
function tally:report(extra)
  if os.getenv("POLYGON_SPEC_COUNTS") then
    print(("\n[count] %s: %d of %d wrong%s"):format(self.what, self.count, self.total, extra or ""))
  end
end

function tally:message()
  return ("%s: %d of %d cases wrong, first ones:\n  %s"):format(self.what, self.count, self.total,
    table.concat(self.examples, "\n  "))
end

return tally
