-- polygonContains and Polygon:contains: Franklin's crossing rule with the tutorial's
-- half-open boundary. An edge (x1,y1)-(x2,y2) is crossed when (y1 >= y) ~= (y2 >= y) and x is
-- at most the edge's x at height y; the point is inside when the crossings are odd.
-- For the axis-aligned square 0..10 this makes the left and top edges outside and the right
-- and bottom edges inside (screen coordinates, y down).
local polygon = require "polygon"
local shapes = require "shapes"

local contains = polygon.polygonContains
local Polygon = polygon.Polygon

local SQUARE_CW = { 0, 0, 10, 0, 10, 10, 0, 10 }
local SQUARE_CCW = { 0, 0, 0, 10, 10, 10, 10, 0 }

describe("polygonContains", function()
  for _, case in ipairs({ { "cw", SQUARE_CW }, { "ccw", SQUARE_CCW } }) do
    local winding, square = case[1], case[2]

    describe("when the square is listed " .. winding, function()
      it("contains its middle (5,5)", function()
        assert.is_true(contains(square, 5, 5))
      end)

      it("does not contain points beyond each side", function()
        assert.is_false(contains(square, 15, 5))
        assert.is_false(contains(square, -1, 5))
        assert.is_false(contains(square, 5, -1))
        assert.is_false(contains(square, 5, 11))
      end)

      it("does not contain a point level with an edge but outside it", function()
        -- y = 0 and y = 10 are vertex heights: the half-open rule must still give false
        assert.is_false(contains(square, -5, 0))
        assert.is_false(contains(square, 15, 10))
        assert.is_false(contains(square, -5, 10))
      end)

      it("contains points on the right edge (x = 10) but not on the left edge (x = 0)", function()
        -- at y = 5 both vertical edges are crossed; x = 10 is <= 10 but not <= 0: 1 crossing
        -- x = 0 is <= 10 and <= 0: 2 crossings
        assert.is_true(contains(square, 10, 5))
        assert.is_false(contains(square, 0, 5))
      end)

      it("contains points on the bottom edge (y = 10) but not on the top edge (y = 0)", function()
        -- at y = 0 neither vertical edge is crossed ((0 >= 0) == (10 >= 0));
        -- at y = 10 both are ((0 >= 10) ~= (10 >= 10)) and only x <= 10 holds
        assert.is_true(contains(square, 5, 10))
        assert.is_false(contains(square, 5, 0))
      end)

      it("contains the corner (10,10) only", function()
        assert.is_true(contains(square, 10, 10))
        assert.is_false(contains(square, 0, 0))
        assert.is_false(contains(square, 10, 0))
        assert.is_false(contains(square, 0, 10))
      end)
    end)
  end

  describe("when two squares share a vertical edge", function()
    local left = { 0, 0, 10, 0, 10, 10, 0, 10 }
    local right = { 10, 0, 20, 0, 20, 10, 10, 10 }

    it("gives each point inside the shared edge to exactly one of them", function()
      for _, y in ipairs({ 0.5, 2.5, 5, 7.25, 9.5, 10 }) do
        assert.are_not.equal(contains(left, 10, y), contains(right, 10, y))
      end
    end)

    it("never gives a point of the shared edge to both, in either winding", function()
      local rright = shapes.reverse(right)
      for _, y in ipairs({ 0, 0.5, 5, 10 }) do
        assert.is_false(contains(left, 10, y) and contains(right, 10, y))
        assert.is_false(contains(left, 10, y) and contains(rright, 10, y))
      end
    end)
  end)

  describe("when two squares share a horizontal edge", function()
    local upper = { 0, 0, 10, 0, 10, 10, 0, 10 }
    local lower = { 0, 10, 10, 10, 10, 20, 0, 20 }

    it("gives each point inside the shared edge to exactly one of them", function()
      for _, x in ipairs({ 0.5, 2.5, 5, 9.5 }) do
        assert.are_not.equal(contains(upper, x, 10), contains(lower, x, 10))
      end
    end)
  end)

  describe("when two triangles share a slanted edge", function()
    -- the hypotenuse (10,0)-(0,10) lies on x + y = 10
    local a = { 0, 0, 10, 0, 0, 10 }
    local b = { 10, 0, 10, 10, 0, 10 }

    it("gives each point inside the shared edge to exactly one of them", function()
      -- at y = 5 the edge's x is (0 - 10) * (5 - 0) / (10 - 0) + 10 = 5
      for _, y in ipairs({ 1, 3, 5, 7, 9 }) do
        local x = 10 - y
        assert.are_not.equal(contains(a, x, y), contains(b, x, y))
        assert.are_not.equal(contains(shapes.reverse(a), x, y), contains(shapes.reverse(b), x, y))
      end
    end)

    it("gives the point (5,5) to the left triangle", function()
      -- a: the hypotenuse is crossed at x = 5 and 5 <= 5; the left edge at x = 0 is not (5 > 0)
      assert.is_true(contains(a, 5, 5))
      assert.is_false(contains(b, 5, 5))
    end)
  end)

  describe("when the polygon is concave", function()
    local L = { 0, 0, 20, 0, 20, 10, 10, 10, 10, 20, 0, 20 }

    it("contains points in both arms of the L in both windings", function()
      assert.is_true(contains(L, 15, 5))
      assert.is_true(contains(L, 5, 15))
      assert.is_true(contains(shapes.reverse(L), 15, 5))
      assert.is_true(contains(shapes.reverse(L), 5, 15))
    end)

    it("does not contain the notch", function()
      assert.is_false(contains(L, 15, 15))
      assert.is_false(contains(shapes.reverse(L), 15, 15))
    end)
  end)

  describe("when the polygon intersects itself", function()
    local star = { 10, 0, 16, 20, 0, 7, 20, 7, 4, 20 }

    it("contains a tip of the pentagram", function()
      -- the ray to the right of (10,3) crosses only (10,0)-(16,20), at x = 10 + 6*3/20 = 10.9
      assert.is_true(contains(star, 10, 3))
    end)

    it("does not contain the pentagram's middle (even-odd rule)", function()
      -- the ray to the right of (10,11) crosses (10,0)-(16,20) at x = 13.3 and
      -- (20,7)-(4,20) at x = 20 - 16*4/13 = 15.08: 2 crossings
      assert.is_false(contains(star, 10, 11))
    end)
  end)

  describe("when there are fewer than 3 points", function()
    it("returns false", function()
      assert.is_false(contains({}, 0, 0))
      assert.is_false(contains({ 0, 0 }, 0, 0))
      assert.is_false(contains({ 0, 0, 10, 10 }, 5, 5))
    end)
  end)

  describe("when the coordinates are large integers", function()
    it("contains the middle of a square of side 2^40 (no 64-bit overflow)", function()
      local s = 1099511627776 -- 2^40
      local h = 549755813888 -- 2^39
      assert.is_true(contains({ 0, 0, s, 0, s, s, 0, s }, h, h))
      assert.is_false(contains({ 0, 0, s, 0, s, s, 0, s }, s + h, h))
    end)
  end)

  describe("when the point lies within rounding error of a slanted edge", function()
    -- edge (18,18)-(4,0); at y = 3.6 (the double 3.6000000000000000888...) its exact x is
    -- 4 + 14 * y / 18 = 6.80000000000000006911..., while the double x below is
    -- 6.8000000000000007105..., so the point lies strictly to the right of the edge
    local y = 3.6
    local x = 6.8000000000000007
    local left = { 18, 18, 4, 0, 0, 18 } -- lies left of the edge
    local right = { 4, 0, 18, 18, 22, 0 } -- lies right of the edge

    it("puts the point in the right-hand triangle only", function()
      assert.is_false(contains(left, x, y))
      assert.is_true(contains(right, x, y))
    end)
  end)
end)

describe("Polygon", function()
  local points = { 0, 0, 10, 0, 10, 10, 0, 10 }

  it("is the class exported as polygon.Polygon", function()
    assert.are.equal("table", type(Polygon))
    assert.are.equal("function", type(Polygon.new))
  end)

  describe("when built with Polygon.new(points)", function()
    it("keeps the caller's table as .points (not a copy)", function()
      local p = Polygon.new(points)
      assert.are.equal(points, p.points)
    end)

    it("contains (5,5) and not (15,5)", function()
      local p = Polygon.new(points)
      assert.is_true(p:contains(5, 5))
      assert.is_false(p:contains(15, 5))
    end)

    it("follows the boundary rule of polygonContains", function()
      local p = Polygon.new(points)
      assert.is_true(p:contains(10, 5))
      assert.is_false(p:contains(0, 5))
      assert.is_true(p:contains(5, 10))
      assert.is_false(p:contains(5, 0))
    end)

    it("answers for the counter-clockwise square too", function()
      local p = Polygon.new({ 0, 0, 0, 10, 10, 10, 10, 0 })
      assert.is_true(p:contains(5, 5))
      assert.is_false(p:contains(5, -5))
    end)

    it("sees later changes to the caller's table", function()
      local own = { 0, 0, 10, 0, 10, 10, 0, 10 }
      local p = Polygon.new(own)
      for i = 1, #own, 2 do own[i] = own[i] + 100 end
      assert.is_false(p:contains(5, 5))
      assert.is_true(p:contains(105, 5))
    end)
  end)

  describe("when built by calling Polygon(points)", function()
    it("keeps the caller's table and answers contains", function()
      local p = Polygon(points)
      assert.are.equal(points, p.points)
      assert.is_true(p:contains(5, 5))
      assert.is_false(p:contains(-5, 5))
    end)

    it("builds independent objects", function()
      local other = { 20, 0, 30, 0, 30, 10, 20, 10 }
      local p, q = Polygon(points), Polygon(other)
      assert.is_true(p:contains(5, 5))
      assert.is_false(q:contains(5, 5))
      assert.is_true(q:contains(25, 5))
    end)
  end)
end)
