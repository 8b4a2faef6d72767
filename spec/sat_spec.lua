-- Separating-axis tests: polygonCollidesWith / polygonCollidesWithV (axes of points1 only),
-- polygonsCollide / polygonsCollideV (axes of both). Per axis with edge normal n:
-- overlap = min(max1 - min2, max2 - min1) / |n|; the result is the axis of least overlap, and
-- (dx, dy) moves the SECOND polygon out of the first so that they just touch.
-- Every case runs with both polygons in both windings (shapes.reverse gives the other one).
local polygon = require "polygon"
local shapes = require "shapes"

local collidesWith, collide = polygon.polygonCollidesWith, polygon.polygonsCollide
local collidesWithV, collideV = polygon.polygonCollidesWithV, polygon.polygonsCollideV
local translate, reverse = shapes.translate, shapes.reverse

-- screen coordinates: this order is clockwise
local A = { 0, 0, 10, 0, 10, 10, 0, 10 }

-- fn(a, b) for a in {p1, reversed p1} and b in {p2, reversed p2}
local function windings(p1, p2, fn)
  for _, a in ipairs({ p1, reverse(p1) }) do
    for _, b in ipairs({ p2, reverse(p2) }) do
      fn(a, b)
    end
  end
end

local function call3(fn, a, b)
  local overlap, dx, dy = fn(a, b)
  return { overlap, dx, dy }
end

-- after adding (dx, dy) to every vertex of p2 the polygons touch without colliding, and
-- pushed back by a millionth of the way they collide again
local function assertJustTouch(p1, p2, dx, dy)
  assert.is_false(collide(p1, translate(p2, dx, dy)))
  assert.is_true(collide(p1, translate(p2, dx - dx * 1e-6, dy - dy * 1e-6)))
end

-- the V variants return false exactly when the booleans do
local function assertConsistent(a, b)
  assert.are.equal(collidesWith(a, b), collidesWithV(a, b) ~= false)
  assert.are.equal(collide(a, b), collideV(a, b) ~= false)
end

describe("polygonsCollide and polygonsCollideV", function()
  describe("when a square overlaps the right part of another", function()
    -- B = A moved by (8,2): on x A is [0,10], B is [8,18]: min(10 - 8, 18 - 0) = 2;
    -- on y A is [0,10], B is [2,12]: min(10 - 2, 12 - 0) = 8; least is 2 along x
    local B = translate(A, 8, 2)

    it("reports a collision in both argument orders", function()
      windings(A, B, function(a, b)
        assert.is_true(collide(a, b))
        assert.is_true(collide(b, a))
        assertConsistent(a, b)
        assertConsistent(b, a)
      end)
    end)

    it("returns overlap 2 and pushes the second square by (2, 0)", function()
      windings(A, B, function(a, b)
        assert.are.same({ 2, 2, 0 }, call3(collideV, a, b))
        assertJustTouch(a, b, 2, 0)
      end)
    end)

    it("pushes the first square by (-2, 0) when the arguments are swapped", function()
      windings(A, B, function(a, b)
        assert.are.same({ 2, -2, 0 }, call3(collideV, b, a))
        assertJustTouch(b, a, -2, 0)
      end)
    end)
  end)

  describe("when polygons only touch", function()
    it("reports no collision for a shared edge", function()
      local C = { 10, 0, 20, 0, 20, 10, 10, 10 }
      windings(A, C, function(a, c)
        assert.is_false(collide(a, c))
        assert.is_false(collide(c, a))
        assert.are.equal(false, collideV(a, c))
        assert.are.equal(false, collideV(c, a))
      end)
    end)

    it("reports no collision for a shared corner", function()
      local D = { 10, 10, 20, 10, 20, 20, 10, 20 }
      windings(A, D, function(a, d)
        assert.is_false(collide(a, d))
        assert.is_false(collide(d, a))
        assert.are.equal(false, collideV(a, d))
        assert.are.equal(false, collideV(d, a))
      end)
    end)

    it("reports no collision for a triangle whose corner touches the square's edge", function()
      -- apex (5,10) on the bottom edge of A
      local T = { 5, 10, 10, 20, 0, 20 }
      windings(A, T, function(a, t)
        assert.is_false(collide(a, t))
        assert.are.equal(false, collideV(t, a))
      end)
    end)
  end)

  describe("when polygons are apart", function()
    it("reports no collision", function()
      local E = { 20, 0, 30, 0, 30, 10, 20, 10 }
      windings(A, E, function(a, e)
        assert.is_false(collide(a, e))
        assert.are.equal(false, collideV(a, e))
        assert.are.equal(false, collideV(e, a))
      end)
    end)
  end)

  describe("when one polygon contains the other", function()
    -- S is 6..8 by 3..5 inside A: on x min(10 - 6, 8 - 0) = 4 (push +x);
    -- on y min(10 - 3, 5 - 0) = 5 (push -y); least is 4 along +x
    local S = { 6, 3, 8, 3, 8, 5, 6, 5 }

    it("returns the penetration depth 4 and pushes the inner square out by (4, 0)", function()
      windings(A, S, function(a, s)
        assert.are.same({ 4, 4, 0 }, call3(collideV, a, s))
        assertJustTouch(a, s, 4, 0)
      end)
    end)

    it("pushes the outer square by (-4, 0) when the arguments are swapped", function()
      -- S as first: on x S is [6,8], A is [0,10]: max1 - min2 = 8, max2 - min1 = 4, so A
      -- moves along -x by 4 to [-4,6]
      windings(A, S, function(a, s)
        assert.are.same({ 4, -4, 0 }, call3(collideV, s, a))
        assertJustTouch(s, a, -4, 0)
      end)
    end)
  end)

  describe("when the centres coincide", function()
    -- R is 3..7 by -5..15, centred on A's centre (5,5): on x min(10 - 3, 7 - 0) = 7,
    -- on y min(10 + 5, 15 - 0) = 15; least is 7 along x, either way
    local R = { 3, -5, 7, -5, 7, 15, 3, 15 }

    it("returns overlap 7 and a displacement of length 7 along x that separates them", function()
      windings(A, R, function(a, r)
        local overlap, dx, dy = collideV(a, r)
        assert.are.equal(7, overlap)
        assert.are.equal(7, math.abs(dx))
        assert.are.equal(0, dy)
        assertJustTouch(a, r, dx, dy)
      end)
    end)

    it("separates them in the other argument order too", function()
      windings(A, R, function(a, r)
        local overlap, dx, dy = collideV(r, a)
        assert.are.equal(7, overlap)
        assert.are.equal(7, math.abs(dx))
        assert.are.equal(0, dy)
        assertJustTouch(r, a, dx, dy)
      end)
    end)

    it("separates two equal squares on top of each other by 10", function()
      windings(A, A, function(a, b)
        local overlap, dx, dy = collideV(a, b)
        assert.are.equal(10, overlap)
        assert.are.equal(10, math.abs(dx) + math.abs(dy))
        assert.are.equal(0, dx * dy)
        assertJustTouch(a, b, dx, dy)
      end)
    end)
  end)

  describe("when the least overlap lies on a diagonal edge of the second polygon", function()
    -- U has the edge (5,13)-(12,6) on x + y = 18; A reaches x + y = 20, so on the unit
    -- normal (1,1)/sqrt(2) the overlap is (20 - 18)/sqrt(2) = sqrt(2), pushing U by (1, 1).
    -- Other axes: x: min(10 - 5, 15 - 0) = 5, y: min(10 - 6, 15 - 0) = 4,
    -- (3,-1)/sqrt(10): 28/sqrt(10) = 8.85, (1,-5)/sqrt(26): 32/sqrt(26) = 6.28
    local U = { 5, 13, 12, 6, 15, 15 }

    it("returns overlap sqrt(2) and pushes the triangle by (1, 1)", function()
      -- sqrt(2) is irrational: the tolerance covers its rounding only
      windings(A, U, function(a, u)
        local overlap, dx, dy = collideV(a, u)
        assert.near(math.sqrt(2), overlap, 1e-12)
        assert.near(1, dx, 1e-12)
        assert.near(1, dy, 1e-12)
        assert.is_false(collide(a, translate(u, dx * (1 + 1e-9), dy * (1 + 1e-9))))
        assert.is_true(collide(a, translate(u, dx * (1 - 1e-6), dy * (1 - 1e-6))))
      end)
    end)

    it("pushes the square by (-1, -1) when the arguments are swapped", function()
      windings(A, U, function(a, u)
        local overlap, dx, dy = collideV(u, a)
        assert.near(math.sqrt(2), overlap, 1e-12)
        assert.near(-1, dx, 1e-12)
        assert.near(-1, dy, 1e-12)
      end)
    end)

    it("has |(dx, dy)| equal to the overlap", function()
      windings(A, U, function(a, u)
        local overlap, dx, dy = collideV(a, u)
        assert.near(overlap, math.sqrt(dx * dx + dy * dy), 1e-12)
      end)
    end)
  end)

  describe("when the exact displacement is not a double", function()
    -- W's edge (0,15)-(15,0) lies on x + y = 15, A reaches x + y = 20: overlap 5/sqrt(2), and
    -- the exact push is (2.5, 2.5); its rounding must not leave the polygons overlapping
    local W = { 0, 15, 15, 0, 20, 20 }

    it("moves the second polygon to touching, up to a rounding overlap one more push clears", function()
      -- The contract: moving by (dx, dy) leaves the shapes touching, "not overlapping by
      -- more than rounding". The rounded push here is 2.4999999999999996, an ulp short, so the
      -- exact test may still see a collision; its depth must then be rounding-sized and the next
      -- push must clear it.
      windings(A, W, function(a, w)
        local overlap, dx, dy = collideV(a, w)
        assert.near(5 / math.sqrt(2), overlap, 1e-12)
        assert.near(2.5, dx, 1e-12)
        assert.near(2.5, dy, 1e-12)
        local moved = translate(w, dx, dy)
        local rest, rx, ry = collideV(a, moved)
        if rest then
          assert.is_true(rest < 1e-12, "left overlapping by " .. rest)
          assert.is_false(collide(a, translate(moved, rx, ry)))
        end
      end)
    end)

    it("never answers a collision with a zero displacement", function()
      -- W moved by the double just below 2.5 (15 + d and 20 + d round to 17.5 and 22.5): its
      -- edge lies on x + y = 20 - 2^-51, past A's corner (10,10), so the polygons do collide
      local d = 2.5 - 2 ^ -51 -- 2.4999999999999996
      local near = translate(W, d, d)
      assert.is_true(collide(A, near))
      local overlap, dx, dy = collideV(A, near)
      assert.is_true(overlap > 0 and (dx ~= 0 or dy ~= 0), ("%s, %s, %s"):format(overlap, dx, dy))
      assert.is_false(collide(A, translate(near, dx, dy)))
    end)
  end)

  describe("when a polygon repeats a vertex", function()
    -- the zero-length edge has no axis and is skipped; the result is that of the plain square
    local Arep = { 0, 0, 10, 0, 10, 0, 10, 10, 0, 10 }
    local Aclosed = { 0, 0, 10, 0, 10, 10, 0, 10, 0, 0 }
    local B = translate(A, 8, 2)

    it("still collides and returns overlap 2, push (2, 0)", function()
      for _, p in ipairs({ Arep, Aclosed }) do
        windings(p, B, function(a, b)
          assert.is_true(collide(a, b))
          assert.is_true(collide(b, a))
          assert.are.same({ 2, 2, 0 }, call3(collideV, a, b))
          assert.are.same({ 2, -2, 0 }, call3(collideV, b, a))
        end)
      end
    end)

    it("still reports touching as no collision", function()
      local C = { 10, 0, 20, 0, 20, 10, 10, 10 }
      windings(Arep, C, function(a, c)
        assert.is_false(collide(a, c))
        assert.are.equal(false, collideV(c, a))
      end)
    end)
  end)

  describe("when a polygon has zero area", function()
    local degenerate = {
      { 2, 5, 8, 5, 5, 5 }, -- a segment across the middle of A
      { 5, 5, 5, 5, 5, 5 }, -- one point three times
    }

    it("never collides, in either argument order", function()
      for _, z in ipairs(degenerate) do
        windings(A, z, function(a, d)
          assert.is_false(collide(a, d))
          assert.is_false(collide(d, a))
          assert.is_false(collidesWith(a, d))
          assert.is_false(collidesWith(d, a))
          assert.are.equal(false, collideV(a, d))
          assert.are.equal(false, collideV(d, a))
          assert.are.equal(false, collidesWithV(a, d))
          assert.are.equal(false, collidesWithV(d, a))
        end)
      end
    end)
  end)

  describe("when the coordinates are large integers", function()
    it("returns the displacement of a square of side 2^40 without 64-bit overflow", function()
      local s = 1099511627776 -- 2^40
      local h = 549755813888 -- 2^39
      local big = { 0, 0, s, 0, s, s, 0, s }
      local moved = { h, 0, s + h, 0, s + h, s, h, s } -- overlap 2^39 along x, s along y
      assert.is_true(collide(big, moved))
      assert.are.same({ 2 ^ 39, 2 ^ 39, 0 }, call3(collideV, big, moved))
    end)
  end)
end)

describe("polygonsCollideV and polygonCollidesWithV at extreme scales", function()
  -- the hand cases above scaled by powers of two (exact), all within the contract's
  -- exactness range [2^-447, 2^500]: every result scales by the same factor k
  local scaled = shapes.scale
  local B = translate(A, 8, 2)
  local S = { 6, 3, 8, 3, 8, 5, 6, 5 }
  local T = { 7, 15, 14, 8, 16, 16 }

  for _, e in ipairs({ -440, -400, -200, -60, 60, 200, 260, 400, 490 }) do
    local k = 2 ^ e

    describe("when every coordinate is multiplied by 2^" .. e, function()
      it("returns overlap 2k and pushes the second square by (2k, 0)", function()
        assert.are.same({ 2 * k, 2 * k, 0 }, call3(collideV, scaled(A, k), scaled(B, k)))
        assert.are.same({ 2 * k, -2 * k, 0 }, call3(collideV, scaled(B, k), scaled(A, k)))
      end)

      it("returns the penetration depth 4k for the contained square", function()
        assert.are.same({ 4 * k, 4 * k, 0 }, call3(collideV, scaled(A, k), scaled(S, k)))
      end)

      it("returns overlap 2k and push (0, 2k) over the first polygon's axes", function()
        assert.are.same({ 2 * k, 0, 2 * k }, call3(collidesWithV, scaled(A, k), scaled(T, k)))
      end)
    end)
  end
end)

describe("polygonCollidesWith and polygonCollidesWithV", function()
  -- T's edge (7,15)-(14,8) lies on x + y = 22, beyond A's x + y <= 20: only T's own axis
  -- separates them. On A's axes: x: T is [7,16], min(10 - 7, 16 - 0) = 3;
  -- y: T is [8,16], min(10 - 8, 16 - 0) = 2
  local T = { 7, 15, 14, 8, 16, 16 }

  it("uses the axes of the first polygon only", function()
    windings(A, T, function(a, t)
      assert.is_true(collidesWith(a, t))
      assert.is_false(collidesWith(t, a))
      assert.is_false(collide(a, t))
      assert.is_false(collide(t, a))
    end)
  end)

  it("returns overlap 2 and push (0, 2) over the first polygon's axes", function()
    windings(A, T, function(a, t)
      assert.are.same({ 2, 0, 2 }, call3(collidesWithV, a, t))
      -- on A's axes the moved triangle now only touches: y range [10,18]
      assert.is_false(collidesWith(a, translate(t, 0, 2)))
    end)
  end)

  it("returns false where the first polygon's axes separate", function()
    windings(A, T, function(a, t)
      assert.are.equal(false, collidesWithV(t, a))
      assert.are.equal(false, collideV(a, t))
      assert.are.equal(false, collideV(t, a))
      assertConsistent(a, t)
      assertConsistent(t, a)
    end)
  end)

  it("returns the exact least overlap 4 on A's axes for the diagonal triangle U", function()
    -- U: x: min(10 - 5, 15 - 0) = 5, y: min(10 - 6, 15 - 0) = 4 -> push (0, 4)
    local U = { 5, 13, 12, 6, 15, 15 }
    windings(A, U, function(a, u)
      assert.are.same({ 4, 0, 4 }, call3(collidesWithV, a, u))
    end)
  end)

  it("agrees with polygonsCollideV for two axis-aligned squares", function()
    local B = translate(A, 8, 2)
    windings(A, B, function(a, b)
      assert.are.same({ 2, 2, 0 }, call3(collidesWithV, a, b))
      assert.are.same({ 2, -2, 0 }, call3(collidesWithV, b, a))
    end)
  end)

  it("reports touching as no collision", function()
    local C = { 10, 0, 20, 0, 20, 10, 10, 10 }
    windings(A, C, function(a, c)
      assert.is_false(collidesWith(a, c))
      assert.are.equal(false, collidesWithV(a, c))
    end)
  end)
end)
