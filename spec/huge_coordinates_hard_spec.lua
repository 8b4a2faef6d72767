-- Coordinates beyond the exact range (2^500, about 3.3e150), and below it: signs are no longer
-- guaranteed, but finite input must still give finite (or honestly infinite) numbers, never NaN,
-- and the collision functions rescale so that squares this large still collide with the right
-- depth.
local polygon = require "polygon"

local function isNaN(v) return v ~= v end

describe("coordinates far beyond the exact range", function()
  for _, b in ipairs({ 1e160, 1e200, 1e300 }) do
    describe(("for squares of side %g"):format(b), function()
      -- a = [0, b]^2 (cw on screen), c = the same moved by (b/2, b/2): they overlap by b/2 on
      -- each axis; the least push of c is b/2 along +x or +y
      local a = { 0, 0, b, 0, b, b, 0, b }
      local c = { b / 2, b / 2, 1.5 * b, b / 2, 1.5 * b, 1.5 * b, b / 2, 1.5 * b }

      it("polygonsCollideV returns the depth b/2 and a push of that length, no NaN", function()
        local o, dx, dy = polygon.polygonsCollideV(a, c)
        assert.is_number(o)
        assert.is_false(isNaN(o) or isNaN(dx) or isNaN(dy))
        assert.near(b / 2, o, b * 1e-12)
        assert.near(b / 2, math.abs(dx) + math.abs(dy), b * 1e-12)   -- one of them is 0
        assert.is_true(dx >= 0 and dy >= 0)
      end)

      it("polygonCollidesWithV and polygonCircleCollideV return no NaN", function()
        local o, dx, dy = polygon.polygonCollidesWithV(a, c)
        assert.near(b / 2, o, b * 1e-12)
        assert.is_false(isNaN(dx) or isNaN(dy))
        -- circle of radius b/4 at the centre: pushed out by b/2 + b/4 = 0.75 b
        local co, cdx, cdy = polygon.polygonCircleCollideV(a, b / 2, b / 2, b / 4)
        assert.near(0.75 * b, co, b * 1e-12)
        assert.is_false(isNaN(cdx) or isNaN(cdy))
      end)

      it("the measures keep their signs and give no NaN", function()
        assert.are.equal("cw", polygon.polygonWindingOrder(a))
        assert.are.equal("convex", polygon.polygonType(a))
        assert.is_true(polygon.polygonContains(a, b / 2, b / 2))
        assert.is_true(polygon.polygonsCollide(a, c))
        -- the area b^2 overflows: infinity, not NaN
        assert.are.equal(math.huge, polygon.polygonArea(a))
        assert.are.equal(math.huge, polygon.polygonAreaAccurate(a))
        local cx, cy = polygon.polygonCentroid(a)
        assert.near(b / 2, cx, b * 1e-12)
        assert.near(b / 2, cy, b * 1e-12)
      end)
    end)
  end
end)

-- Below the exact range (nonzero magnitudes under 2^-447) signs are not guaranteed either, but a
-- call must still answer, never stop in a Lua error. A side that rises by 2^-1074 (the least
-- double) along a run of 1 has a slope past the largest double: the ear test's spans of the
-- triangle came out infinite on LuaJIT, and the scan indexed its cells with them.
describe("coordinates below the exact range", function()
  local TINY = 2 ^ -1074
  for _, case in ipairs({
    { "a triangle with a side rising by 2^-1074", { 1, 0, 0, TINY, 0, 0 } },
    { "a quadrilateral with such a side", { 1, 0, 0, TINY, 0, 0, 0.5, -1 } },
    { "a sliver 1e-6 high with vertices at +-1e-323", { 0, 1e-6, 500, 1e-6, 1000, 1e-6, 1000, -1e-323,
      500, 1e-323, 0, -1e-323 } },
  }) do
    it(("polygonTriangulate and polygonConvexParts answer for %s"):format(case[1]), function()
      for _, f in ipairs({ polygon.polygonTriangulate, polygon.polygonConvexParts }) do
        local ok, pieces, message = pcall(f, case[2])
        assert.is_true(ok, tostring(pieces))
        assert.is_true(type(pieces) == "table" or type(message) == "string")
      end
    end)
  end
end)
