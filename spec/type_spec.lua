-- polygonType: "convex", "concave", or nil for fewer than 3 points or all points on one line.
-- A turn at vertex B (coming from A, going to C) is cross(B - A, C - B); a convex polygon
-- turns the same way at every vertex, winds around once and never doubles back.
local polygon = require "polygon"
local shapes = require "shapes"

local ptype = polygon.polygonType

-- check a case in the given order and reversed (the other winding)
local function both(expected, points)
  assert.are.equal(expected, ptype(points))
  assert.are.equal(expected, ptype(shapes.reverse(points)))
end

describe("polygonType", function()
  describe("when the polygon is convex", function()
    it('returns "convex" for the square in both windings', function()
      assert.are.equal("convex", ptype({ 0, 0, 10, 0, 10, 10, 0, 10 }))
      assert.are.equal("convex", ptype({ 0, 0, 0, 10, 10, 10, 10, 0 }))
    end)

    it('returns "convex" for the 3-4-5 triangle in both windings', function()
      both("convex", { 0, 0, 4, 0, 0, 3 })
    end)

    it('returns "convex" for a hexagon in both windings', function()
      both("convex", { 5, 0, 15, 0, 20, 8, 15, 16, 5, 16, 0, 8 })
    end)
  end)

  describe("when the polygon is concave", function()
    it('returns "concave" for the L shape in both windings', function()
      both("concave", { 0, 0, 20, 0, 20, 10, 10, 10, 10, 20, 0, 20 })
    end)

    it('returns "concave" for a dart whose reflex vertex comes last', function()
      -- turns: at (10,5): 100, at (0,10): 35, at (3,5): -30, at (0,0): 35
      both("concave", { 0, 0, 10, 5, 0, 10, 3, 5 })
    end)

    it('returns "concave" for a dart whose reflex vertex comes first', function()
      both("concave", { 3, 5, 0, 0, 10, 5, 0, 10 })
    end)

    it('returns "concave" when the first vertex is collinear with its neighbours', function()
      -- the turn at (5,0) is 0, the turn at (5,5) is -50, all others +50
      both("concave", { 5, 0, 10, 0, 10, 10, 5, 5, 0, 10, 0, 0 })
    end)
  end)

  describe("when vertices are collinear going forward", function()
    it('returns "convex" for a square with extra points on its edges', function()
      both("convex", { 0, 0, 5, 0, 10, 0, 10, 5, 10, 10, 0, 10 })
    end)

    it('returns "convex" when the collinear point is the first vertex', function()
      both("convex", { 5, 0, 10, 0, 10, 10, 0, 10, 0, 0 })
    end)
  end)

  describe("when consecutive vertices repeat", function()
    it('returns "convex" for the square with a doubled corner', function()
      both("convex", { 0, 0, 10, 0, 10, 0, 10, 10, 0, 10 })
    end)

    it('returns "convex" when the last vertex repeats the first', function()
      both("convex", { 0, 0, 10, 0, 10, 10, 0, 10, 0, 0 })
    end)

    it('returns "concave" for the L shape with a doubled vertex', function()
      both("concave", { 0, 0, 20, 0, 20, 10, 10, 10, 10, 10, 10, 20, 0, 20 })
    end)
  end)

  describe("when the boundary doubles back (a spike)", function()
    it('returns "concave" although the turn there is zero', function()
      -- (0,0) -> (20,0) -> (10,0): a zero cross product with the path reversing
      both("concave", { 0, 0, 20, 0, 10, 0, 10, 10, 0, 10 })
    end)

    it('returns "concave" for a slit cut into a square although no turn is negative', function()
      -- (10,0) -> (5,5) -> (10,0): turn 0 at (5,5), every other turn is +50 or +100
      both("concave", { 0, 0, 10, 0, 5, 5, 10, 0, 10, 10, 0, 10 })
    end)

    it('returns "concave" for a vertical slit whose edges still turn one way around once', function()
      -- (5,10) -> (5,5) -> (5,10) up from the bottom edge: turn 0 at (5,5), all others
      -- positive (25, 25, 50, 100, 100), and the edges' x directions change sign only twice
      both("concave", { 0, 0, 10, 0, 10, 10, 5, 10, 5, 5, 5, 10, 0, 10 })
    end)
  end)

  describe("when the polygon intersects itself", function()
    it('returns "concave" for the pentagram although every turn has the same sign', function()
      -- turns: 242, 260, 260, 242, 240 (all positive), but it winds around twice
      both("concave", { 10, 0, 16, 20, 0, 7, 20, 7, 4, 20 })
    end)

    it('returns "concave" for the bow-tie', function()
      both("concave", { 0, 0, 10, 10, 10, 0, 0, 10 })
    end)
  end)

  describe("when the polygon winds around more than once", function()
    it('returns "concave" for an octagon visited every second vertex, then the rest', function()
      -- angles 0, 90, 180, 270, 45, 135, 225, 315 degrees around (10,10): all 8 turns are
      -- positive and the boundary winds around twice
      both("concave", { 20, 10, 10, 20, 0, 10, 10, 0, 17, 17, 3, 17, 3, 3, 17, 3 })
    end)

    it('returns "concave" for a square traversed twice', function()
      both("concave", { 0, 0, 10, 0, 10, 10, 0, 10, 0, 0, 10, 0, 10, 10, 0, 10 })
    end)
  end)

  describe("when there are fewer than 3 points", function()
    it("returns nil", function()
      assert.is_nil(ptype({}))
      assert.is_nil(ptype({ 1, 1 }))
      assert.is_nil(ptype({ 0, 0, 10, 0 }))
    end)
  end)

  describe("when all points lie on one line", function()
    it("returns nil for points going forward", function()
      assert.is_nil(ptype({ 0, 0, 5, 5, 10, 10 }))
    end)

    it("returns nil for points going back and forth", function()
      assert.is_nil(ptype({ 0, 0, 10, 0, 5, 0 }))
    end)

    it("returns nil when all points are equal", function()
      assert.is_nil(ptype({ 3, 3, 3, 3, 3, 3, 3, 3 }))
    end)
  end)

  describe("when the coordinates are large integers", function()
    it('returns "convex" for a square of side 2^40 (no 64-bit overflow)', function()
      local s = 1099511627776 -- 2^40
      both("convex", { 0, 0, s, 0, s, s, 0, s })
    end)
  end)
end)
