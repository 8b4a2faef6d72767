-- polygonCircleCollideV(points, cx, cy, radius): overlap, dx, dy or false. The axes are the
-- polygon's edge normals plus the axis from the polygon vertex NEAREST (by distance) to the
-- centre; (dx, dy) moves the circle out of the polygon so that they just touch.
local polygon = require "polygon"
local shapes = require "shapes"
local oracle = require "oracle"

local circleV = polygon.polygonCircleCollideV
local isnumber = shapes.isNumber

local A = { 0, 0, 10, 0, 10, 10, 0, 10 } -- clockwise on screen
local WINDINGS = { A, shapes.reverse(A) }

-- The overlap is exact here; the push has the expected direction and is longer by a few ulps
-- at most (8 eps M, M the largest coordinate magnitude involved, the moved centre's included),
-- so that the moved circle clears for certain: the exact oracle sees no overlap at the moved
-- centre.
local EPS = 2 ^ -53
local function assertPush(points, cx, cy, r, overlap, ex, ey)
  local o, dx, dy = circleV(points, cx, cy, r)
  assert.are.equal(overlap, o)
  local m = math.max(math.abs(cx), math.abs(cy), math.abs(cx + dx), math.abs(cy + dy))
  for i = 1, #points do m = math.max(m, math.abs(points[i])) end
  assert.is_true(math.abs(dx - ex) <= 8 * EPS * m and math.abs(dy - ey) <= 8 * EPS * m,
    ("push (%.17g, %.17g), expected (%.17g, %.17g)"):format(dx, dy, ex, ey))
  assert.is_false(oracle.discMeetsPolygon(points, cx + dx, cy + dy, r))
end

-- after moving the centre by (dx, dy) the circle touches without colliding; pushed back
-- by a millionth of the way it collides again
local function assertJustTouch(points, cx, cy, r, dx, dy)
  assert.are.equal(false, circleV(points, cx + dx, cy + dy, r))
  assert.is_truthy(circleV(points, cx + dx - dx * 1e-6, cy + dy - dy * 1e-6, r))
end

describe("polygonCircleCollideV", function()
  describe("when the circle overlaps the right edge", function()
    -- circle (12,5) r 3: on x it is [9,15] against [0,10]: min(10 - 9, 15 - 0) = 1 (push +x);
    -- on y [2,8]: min(10 - 2, 8 - 0) = 8; the vertex axis from (10,0) or (10,10) is 6.9
    it("returns overlap 1 and pushes the circle by (1, 0) in both windings", function()
      for _, p in ipairs(WINDINGS) do
        assertPush(p, 12, 5, 3, 1, 1, 0)
        assertJustTouch(p, 12, 5, 3, 1, 0)
      end
    end)
  end)

  describe("when the circle overlaps the top edge", function()
    -- circle (4,-2) r 3: on y [-5,1] against [0,10]: min(10 + 5, 1 - 0) = 1, push -y
    it("returns overlap 1 and pushes the circle by (0, -1) in both windings", function()
      for _, p in ipairs(WINDINGS) do
        assertPush(p, 4, -2, 3, 1, 0, -1)
        assertJustTouch(p, 4, -2, 3, 0, -1)
      end
    end)
  end)

  describe("when the circle only touches or is apart", function()
    it("returns false for a circle touching the right edge", function()
      for _, p in ipairs(WINDINGS) do
        assert.are.equal(false, circleV(p, 13, 5, 3))
      end
    end)

    it("returns false for a circle beyond the right edge", function()
      for _, p in ipairs(WINDINGS) do
        assert.are.equal(false, circleV(p, 14, 5, 3))
      end
    end)

    it("returns false near a corner when only the vertex axis separates", function()
      -- centre (13,14) r 4.9: on x [8.1,17.9] and on y [9.1,18.9] both overlap [0,10],
      -- but the nearest vertex (10,10) is 5 away (3-4-5), more than 4.9
      for _, p in ipairs(WINDINGS) do
        assert.are.equal(false, circleV(p, 13, 14, 4.9))
      end
    end)
  end)

  describe("when the circle overlaps a corner", function()
    -- centre (13,14) r 6: nearest vertex (10,10) at distance 5 on the unit axis (3,4)/5;
    -- the square projects to [-14, 0] from (10,10), the circle to [5 - 6, 5 + 6] = [-1, 11]:
    -- min(0 + 1, 11 + 14) = 1, push along +(0.6, 0.8). Edge axes: x: min(10 - 7, 19) = 3,
    -- y: min(10 - 8, 20) = 2
    it("returns overlap 1 and pushes the circle by (0.6, 0.8)", function()
      -- 0.6 and 0.8 are not doubles: the tolerance covers their rounding only
      for _, p in ipairs(WINDINGS) do
        local overlap, dx, dy = circleV(p, 13, 14, 6)
        assert.near(1, overlap, 1e-12)
        assert.near(0.6, dx, 1e-12)
        assert.near(0.8, dy, 1e-12)
        assert.are.equal(false, circleV(p, 13 + dx * (1 + 1e-9), 14 + dy * (1 + 1e-9), 6))
        assert.is_truthy(circleV(p, 13 + dx * (1 - 1e-6), 14 + dy * (1 - 1e-6), 6))
      end
    end)
  end)

  describe("when the nearest vertex by distance is not the one with the least dot product", function()
    -- square 0..100, centre (120,110) r 22: the nearest vertex (100,100) is sqrt(500) = 22.36
    -- away, so the circle is apart; the vertex minimising 120*px + 110*py is (0,0), whose
    -- axis does not separate (see tutorial_defects_spec.lua)
    local big = { 0, 0, 100, 0, 100, 100, 0, 100 }

    it("returns false", function()
      assert.are.equal(false, circleV(big, 120, 110, 22))
      assert.are.equal(false, circleV(shapes.reverse(big), 120, 110, 22))
    end)

    it("collides once the radius reaches past the nearest vertex", function()
      -- r 23 > 22.36: on the axis from (100,100) the overlap is 23 - sqrt(500) = 0.639;
      -- edge axes: x: 100 - 97 = 3, y: 100 - 87 = 13
      local overlap = circleV(big, 120, 110, 23)
      assert.near(23 - math.sqrt(500), overlap, 1e-12)
    end)
  end)

  describe("when the circle lies deep inside the polygon", function()
    -- centre (7,4) r 1: on x [6,8]: min(10 - 6, 8 - 0) = 4 (push +x); on y [3,5]:
    -- min(10 - 3, 5 - 0) = 5; nearest vertex (10,0) at distance 5 on (-3,4)/5: the square
    -- projects to [0,14], the circle to [4,6]: min(14 - 4, 6 - 0) = 6
    it("returns overlap 4 and resolves in one step with (4, 0)", function()
      for _, p in ipairs(WINDINGS) do
        assertPush(p, 7, 4, 1, 4, 4, 0)
        assertJustTouch(p, 7, 4, 1, 4, 0)
      end
    end)

    it("returns an overlap larger than the diameter for a small circle near the middle", function()
      -- centre (5,4) r 0.5: x: min(10 - 4.5, 5.5) = 5.5, y: min(10 - 3.5, 4.5) = 4.5 (push -y)
      -- vertex axes from (0,0) or (10,0) at distance sqrt(41): far larger
      for _, p in ipairs(WINDINGS) do
        assertPush(p, 5, 4, 0.5, 4.5, 0, -4.5)
        assertJustTouch(p, 5, 4, 0.5, 0, -4.5)
      end
    end)
  end)

  describe("when the circle contains the polygon", function()
    -- centre (6,5) r 100: x: [-94,106]: min(10 + 94, 106 - 0) = 104 (push +x);
    -- y: [-95,105]: min(105, 105) = 105; vertex axis from (10,0): 106.4
    it("returns overlap 104 and pushes the circle by (104, 0)", function()
      for _, p in ipairs(WINDINGS) do
        assertPush(p, 6, 5, 100, 104, 104, 0)
        assertJustTouch(p, 6, 5, 100, 104, 0)
      end
    end)
  end)

  describe("when the centre sits exactly on a vertex", function()
    -- centre (10,10) r 2: the vertex axis is skipped; x: min(10 - 8, 12) = 2, y: the same
    it("returns overlap 2, a push of length 2 along x or y, and no NaN", function()
      for _, p in ipairs(WINDINGS) do
        local overlap, dx, dy = circleV(p, 10, 10, 2)
        assert.is_true(isnumber(overlap) and isnumber(dx) and isnumber(dy))
        assert.are.equal(2, overlap)
        assert.is_true(math.abs(math.abs(dx) + math.abs(dy) - 2) <= 8 * EPS * 10)
        assert.are.equal(0, dx * dy)
        assertJustTouch(p, 10, 10, 2, dx, dy)
      end
    end)

    it("returns no NaN for the first vertex (0,0) either", function()
      for _, p in ipairs(WINDINGS) do
        local overlap, dx, dy = circleV(p, 0, 0, 3)
        assert.is_true(isnumber(overlap) and isnumber(dx) and isnumber(dy))
        assert.are.equal(3, overlap)
      end
    end)
  end)

  describe("when the polygon repeats a vertex", function()
    it("skips the zero-length edge and returns overlap 1, push (1, 0), no NaN", function()
      local rep = { 0, 0, 10, 0, 10, 0, 10, 10, 0, 10 }
      for _, p in ipairs({ rep, shapes.reverse(rep), { 0, 0, 10, 0, 10, 10, 0, 10, 0, 0 } }) do
        assertPush(p, 12, 5, 3, 1, 1, 0)
      end
    end)

    it("returns no NaN when the centre sits on the repeated vertex", function()
      local rep = { 0, 0, 10, 0, 10, 0, 10, 10, 0, 10 }
      local overlap, dx, dy = circleV(rep, 10, 0, 2)
      assert.is_true(isnumber(overlap) and isnumber(dx) and isnumber(dy))
      assert.are.equal(2, overlap)
    end)
  end)

  describe("when the polygon is a triangle", function()
    -- triangle (0,0), (12,0), (0,12); circle (3,-1) r 2 over the top edge y = 0:
    -- y: [-3,1] against [0,12]: min(12 + 3, 1 - 0) = 1, push -y; x: min(12 - 1, 5 - 0) = 5;
    -- hypotenuse normal (1,1)/sqrt(2): triangle [0, 8.49], circle [-0.59, 3.41]: 3.41;
    -- nearest vertex (0,0) on (3,-1)/sqrt(10): triangle [-3.79, 11.38], circle [1.16, 5.16]: 8.95
    it("returns overlap 1 and pushes the circle by (0, -1) in both windings", function()
      local tri = { 0, 0, 12, 0, 0, 12 }
      for _, p in ipairs({ tri, shapes.reverse(tri) }) do
        assertPush(p, 3, -1, 2, 1, 0, -1)
      end
    end)
  end)

  describe("when the scene is scaled by a power of two", function()
    -- the deep-inside case times k = 2^e (exact): overlap 4k, push (4k, 0)
    for _, e in ipairs({ -440, -200, 200, 490 }) do
      it("returns overlap 4 * 2^" .. e .. " and push (4 * 2^" .. e .. ", 0)", function()
        local k = 2 ^ e
        local p = { 0, 0, 10 * k, 0, 10 * k, 10 * k, 0, 10 * k }
        assertPush(p, 7 * k, 4 * k, k, 4 * k, 4 * k, 0)
      end)
    end
  end)

  describe("when the polygon has zero area", function()
    it("never collides", function()
      for _, p in ipairs({ { 0, 5, 10, 5, 20, 5 }, { 5, 5, 5, 5, 5, 5 } }) do
        assert.are.equal(false, circleV(p, 5, 5, 3))
      end
    end)
  end)

  describe("when the polygon has fewer than 3 points", function()
    it("raises the argument error (spec/refusals_spec.lua has every message)", function()
      for _, p in ipairs({ { 0, 0, 10, 0 }, { 5, 5 }, {} }) do
        assert.has_error(function() circleV(p, 5, 5, 3) end)
      end
    end)
  end)
end)
