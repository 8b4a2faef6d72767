-- polygonTriangulate and polygonConvexParts on earcut's test fixtures (spec/support/earcut/,
-- copied under earcut's ISC licence): real map outlines with up to 1,443 holes, holes touching
-- the outline and each other, self-tangent outlines, Steiner points, and some that are no valid
-- polygon at all. The oracle decides which is which (oracle.regionCrossing) and checks every
-- answer (oracle.checkCover); the lists below say what it decides, and each case checks that.

local polygon = require "polygon"
local oracle = require "oracle"
local earcut = require "earcut"

local triangulate, convexParts = polygon.polygonTriangulate, polygon.polygonConvexParts

-- Valid by the oracle: covered exactly, as triangles and as convex parts.
local VALID = {
  "boxy", "building", "dude", "earcut", "eberly-3", "eberly-6", "filtered-bridge-jhl", "hilbert",
  "hole-touching-outer", "hourglass", "issue111", "issue119", "issue16", "issue17", "issue29",
  "issue34", "issue35", "issue45", "issue52", "outside-ring", "rain", "self-tangent-1",
  "self-tangent-2", "self-tangent-3", "self-tangent-4", "self-touching", "shared-points",
  "steiner", "touching-holes", "touching-holes2", "touching-holes3", "touching-holes4",
  "touching-holes5", "touching-holes6", "touching2", "touching3", "touching4", "water-huge3",
}

-- Invalid by the oracle, with the oracle's verdict and the word the message must hold.
local INVALID = {
  { "bad-hole", "cross", "holes%[3%] crosses the outline" },
  { "issue142", "cross", "holes%[1%] crosses the outline" },
  { "simplified-us-border", "cross", "edges cross" },
  { "water", "cross", "edges cross" },
  { "water-huge", "cross", "edges cross" },
  { "water-huge2", "cross", "edges cross" },
  { "degenerate", "degenerate", "zero area" },
  { "issue107", "degenerate", "zero area" },
}

-- Undecided by the oracle (edges running along each other both ways, whose order it does not
-- decide): covered exactly. (water3, holes sharing a stretch of an edge with the outline, was
-- refused with "edges overlap or cross" until the bridges' index of session 22 chose other
-- bridges, after which the ear clipping finds its ears.)
local UNDECIDED_COVERED = {
  "bad-diagonals", "collinear-diagonal", "empty-square", "infinite-loop-jhl", "issue131",
  "issue147", "issue149", "issue186", "issue83", "water2", "water3", "water3b", "water4",
}

local function assertCovers(name, points, holes, pieces, convex, message)
  assert(pieces, name .. ": " .. tostring(message))
  local ok, why = oracle.checkCover(points, holes, pieces, convex)
  assert(ok, name .. ": " .. tostring(why))
end

-- A fixture the oracle finds `verdict`: its triangles and its convex parts cover it exactly.
local function coversFixture(name, verdict)
  local points, holes = earcut.load(name)
  assert.are.equal(verdict, oracle.regionCrossing(points, holes))
  assertCovers(name, points, holes, triangulate(points, holes))
  local parts, message = convexParts(points, holes)
  assertCovers(name, points, holes, parts, true, message)
end

describe("polygonTriangulate and polygonConvexParts on earcut's fixtures", function()
  it("cover the list of every fixture: each is in one list", function()
    local listed = {}
    for _, name in ipairs(VALID) do listed[name] = true end
    for _, case in ipairs(INVALID) do listed[case[1]] = true end
    for _, name in ipairs(UNDECIDED_COVERED) do listed[name] = true end
    for _, name in ipairs(earcut.names()) do assert(listed[name], name .. " is in no list") end
  end)

  describe("when the fixture is valid", function()
    for _, name in ipairs(VALID) do
      it("cover " .. name .. " exactly", function() coversFixture(name, "valid") end)
    end
  end)

  describe("when the fixture is no valid polygon", function()
    for _, case in ipairs(INVALID) do
      local name, verdict, wanted = case[1], case[2], case[3]
      it("refuse " .. name .. ", naming the trouble", function()
        local points, holes = earcut.load(name)
        assert.are.equal(verdict, (oracle.regionCrossing(points, holes)))
        local tris, message = triangulate(points, holes)
        assert.is_nil(tris)
        assert.truthy(message:find(wanted), message)
        local parts, partsMessage = convexParts(points, holes)
        assert.is_nil(parts)
        assert.are.equal(message, partsMessage)
      end)
    end
  end)

  describe("when the oracle does not decide the fixture", function()
    for _, name in ipairs(UNDECIDED_COVERED) do
      it("cover " .. name .. " exactly", function() coversFixture(name, "unknown") end)
    end
  end)
end)
