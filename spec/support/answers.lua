--- polygonTriangulate's and polygonConvexParts' answers on one outline with holes, held to the
-- oracle's verdict on it (oracle.regionCrossing), for the specs that generate such cases. A
-- valid case, or an undecided one whose pieces came back, must be covered exactly by the
-- triangles and by the parts (oracle.checkCover); an invalid one refused by both, with one
-- message naming the trouble; an undecided one refused, by both.

local oracle = require "oracle"

local answers = {}

-- What the message must name for each kind of invalid input.
local EXPECTED = { cross = { "cross" }, outside = { "outside" }, inside = { "inside" },
  degenerate = { "zero area", "cross" } }

--- The case as Lua source, for a failure's message.
function answers.describe(points, list)
  local parts = {}
  for h, hole in ipairs(list) do parts[h] = "{" .. table.concat(hole, ",") .. "}" end
  return "{" .. table.concat(points, ",") .. "}, {" .. table.concat(parts, ",") .. "}"
end

--- Asserts that the answers agree with the verdict; `where` names the case in a failure.
-- @return "covered" (pieces came back, covering the case), or "refused"
function answers.check(points, list, verdict, tris, message, parts, partsMessage, where)
  if verdict == "valid" or (verdict == "unknown" and tris) then
    assert(tris, where .. " refused: " .. tostring(message))
    local ok, why = oracle.checkCover(points, list, tris)
    assert(ok, where .. " triangles: " .. tostring(why))
    assert(parts, where .. " parts refused: " .. tostring(partsMessage))
    ok, why = oracle.checkCover(points, list, parts, true)
    assert(ok, where .. " parts: " .. tostring(why))
    return "covered"
  end
  assert(tris == nil and parts == nil, where .. " accepted")
  assert(type(message) == "string" and message == partsMessage, where)
  local named = EXPECTED[verdict] == nil   -- (undecided: any message)
  for _, word in ipairs(EXPECTED[verdict] or {}) do named = named or message:find(word) ~= nil end
  assert(named, where .. " message: " .. message)
  return "refused"
end

return answers
