-- Lua 5.3+ integers beyond 2^53: a coordinate counts as the double it converts to, in
-- comparisons as well as in arithmetic. Raw comparisons of integers with converted doubles are
-- exact for neither (2^53 + 1 > 2^53.0 as integers, equal as doubles). The integers are made with
-- load() so that this file still loads on Lua 5.1, 5.2 and LuaJIT, where it is skipped.
local polygon = require "polygon"

local loader = rawget(_G, "loadstring") or load
local chunk = loader("return 1 << 53")
local mathType = rawget(math, "type")   -- Lua 5.3+ only
local B = chunk and mathType and chunk()

-- the same points as doubles
local function converted(points)
  local out = {}
  for i = 1, #points do out[i] = points[i] + 0.0 end
  return out
end

local describeIntegers = B and describe or pending

describeIntegers("integer coordinates beyond 2^53", function()
  it("are integers here (the spec is not vacuous)", function()
    assert.are.equal("integer", mathType(B - 4))
  end)

  it("make polygonType concave both as integers and as the doubles they convert to", function()
    -- As doubles: (B-4, B), (B-1, B+4), (B+4, B-1), (B, B), (B, B) (B+3 rounds to B+4 and
    -- B+1 to B). Turns (e x f): at (B-1, B+4) (3, 4) x (5, -5) = -35, at (B+4, B-1)
    -- (5, -5) x (-4, 1) = -15, at (B, B) (-4, 1) x (-4, 0) = +4: concave.
    -- As integers: at (B-1, B+3) (3, 3) x (4, -4) = -24, at (B+3, B-1) (4, -4) x (-3, 2) = -4,
    -- at (B, B+1) (-3, 2) x (0, -1) = +3: concave.
    local p = { B - 4, B, B - 1, B + 3, B + 3, B - 1, B, B + 1, B, B }
    assert.are.equal("concave", polygon.polygonType(converted(p)))
    assert.are.equal("concave", polygon.polygonType(p))
  end)

  it("give polygonContains the answer of the converted polygon", function()
    -- B + 3 converts to B + 4: the converted square's top edge is at y = B + 4, and the point
    -- (8, B + 4) lies on its half-open boundary, inside (the right edge crosses its ray)
    local p = { 0, B - 8, 16, B - 8, 16, B + 3, 0, B + 3 }
    local y = (B + 4) + 0.0
    assert.is_true(polygon.polygonContains(converted(p), 8, y))
    assert.is_true(polygon.polygonContains(p, 8, y))
    assert.are.equal(polygon.polygonContains(converted(p), 8, B + 3), polygon.polygonContains(p, 8, B + 3))
  end)

  it("give the measures the values of the converted polygon", function()
    local p = { B - 4, B, B - 1, B + 3, B + 3, B - 1, B, B + 1 }
    local q = converted(p)
    assert.are.equal(polygon.polygonWindingOrder(q), polygon.polygonWindingOrder(p))
    assert.are.equal(polygon.polygonArea(q), polygon.polygonArea(p))
    assert.are.equal(polygon.polygonAreaAccurate(q), polygon.polygonAreaAccurate(p))
    assert.are.same({ polygon.polygonCentroid(q) }, { polygon.polygonCentroid(p) })
    assert.are.same({ polygon.polygonCenter(q) }, { polygon.polygonCenter(p) })
  end)
end)
