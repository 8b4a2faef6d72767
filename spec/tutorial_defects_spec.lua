-- One describe per defect of the tutorial's code. Each case first runs the tutorial's formula
-- (bench/baseline.lua, the one transcription of the tutorial, which the benchmark times too) and
-- asserts that it gives the wrong answer there, so the case provably exercises the defect; then it
-- asserts that polygon.lua is right.
local polygon = require "polygon"
local shapes = require "shapes"
local tutorial = require "bench.baseline"

local translate = shapes.translate

local A = { 0, 0, 10, 0, 10, 10, 0, 10 } -- clockwise on screen

local tutorialType = tutorial.polygonType
local tutorialCollidesWithV = tutorial.polygonCollidesWithV
local tutorialCollide = tutorial.polygonsCollide
local tutorialCircle = tutorial.polygonCircleCollideV
local tutorialContains = tutorial.polygonContains

local function isnan(x) return x ~= x end

---------------------------------------------------------------------------------------------

describe("defect: the tutorial's polygonType skips vertices and misses non-simple polygons", function()
  local ptype = polygon.polygonType

  it("calls a dart concave although its reflex vertex comes last", function()
    -- turns 100, 35, -30 at the last vertex (3,5), which the tutorial never checks
    local dart = { 0, 0, 10, 5, 0, 10, 3, 5 }
    assert.are.equal("convex", tutorialType(dart))
    assert.are.equal("concave", ptype(dart))
  end)

  it("calls a polygon concave although its first vertex is collinear", function()
    -- the first turn is 0, so the tutorial's products are all 0 and never negative
    -- turn at (5,0) between (0,0) -> (5,0) and (5,0) -> (10,0): 5 * 0 - 0 * 5 = 0
    local p = { 5, 0, 10, 0, 10, 10, 5, 5, 0, 10, 0, 0 }
    assert.are.equal("convex", tutorialType(p))
    assert.are.equal("concave", ptype(p))
  end)

  it("calls a square with a slit cut into it (a spike) concave", function()
    -- (10,0) -> (5,5) -> (10,0): the turn at (5,5) is 0 but the path doubles back;
    -- every other turn is +50 or +100
    local p = { 0, 0, 10, 0, 5, 5, 10, 0, 10, 10, 0, 10 }
    assert.are.equal("convex", tutorialType(p))
    assert.are.equal("concave", ptype(p))
  end)

  it("calls a square with a vertical slit up from its bottom edge concave", function()
    -- (5,10) -> (5,5) -> (5,10): the turn at (5,5) is 0 with the path reversing
    local p = { 0, 0, 10, 0, 10, 10, 5, 10, 5, 5, 5, 10, 0, 10 }
    assert.are.equal("convex", tutorialType(p))
    assert.are.equal("concave", ptype(p))
  end)

  it("calls the pentagram concave although every turn has the same sign", function()
    local star = { 10, 0, 16, 20, 0, 7, 20, 7, 4, 20 }
    assert.are.equal("convex", tutorialType(star))
    assert.are.equal("concave", ptype(star))
  end)

  it("calls a polygon that winds around twice concave", function()
    -- octagon points visited at 0, 90, 180, 270, 45, 135, 225, 315 degrees
    local twice = { 20, 10, 10, 20, 0, 10, 10, 0, 17, 17, 3, 17, 3, 3, 17, 3 }
    assert.are.equal("convex", tutorialType(twice))
    assert.are.equal("concave", ptype(twice))
  end)
end)

describe("defect: the tutorial's SAT fails on repeated vertices and degenerate polygons", function()
  local B = translate(A, 8, 2)

  it("still finds the collision when a polygon repeats a vertex", function()
    -- the zero-length edge gives the normal (0,0): both ranges are [0,0] and max1 <= min2
    local rep = { 0, 0, 10, 0, 10, 0, 10, 10, 0, 10 }
    assert.is_false(tutorialCollide(rep, B))
    assert.is_true(polygon.polygonsCollide(rep, B))
    assert.is_true(polygon.polygonCollidesWith(rep, B))
    assert.is_truthy(polygon.polygonsCollideV(rep, B))
  end)

  it("reports no collision with a zero-area polygon lying across a square", function()
    local segment = { 2, 5, 8, 5, 5, 5 }
    assert.is_true(tutorialCollide(A, segment))
    assert.is_false(polygon.polygonsCollide(A, segment))
    assert.are.equal(false, polygon.polygonsCollideV(A, segment))
  end)

  it("refuses a two-point polygon lying across a square (it is not a polygon)", function()
    local two = { 2, 5, 8, 5 }
    assert.is_true(tutorialCollide(A, two))
    assert.has_error(function() polygon.polygonsCollide(A, two) end,
      "polygonsCollide: points2 has 2 points: a segment; a polygon needs at least 3; "
        .. "for line of sight use polygonRayCast")
    assert.has_error(function() polygon.polygonsCollideV(two, A) end,
      "polygonsCollideV: points1 has 2 points: a segment; a polygon needs at least 3; "
        .. "for line of sight use polygonRayCast")
  end)
end)

describe("defect: the tutorial's overlap is wrong when one polygon contains the other", function()
  -- S is 6..8 by 3..5 inside A; on x the tutorial gives min(10, 8) - max(0, 6) = 2, the
  -- penetration depth is min(10 - 6, 8 - 0) = 4
  local S = { 6, 3, 8, 3, 8, 5, 6, 5 }

  it("returns the penetration depth 4", function()
    local overlap = tutorialCollidesWithV(A, S)
    assert.are.equal(2, overlap)
    -- moving S by the tutorial's 2 does not separate it
    assert.is_true(polygon.polygonsCollide(A, translate(S, 2, 0)))
    local o, dx, dy = polygon.polygonsCollideV(A, S)
    assert.are.same({ 4, 4, 0 }, { o, dx, dy })
    assert.is_false(polygon.polygonsCollide(A, translate(S, dx, dy)))
  end)
end)

describe("defect: the tutorial's displacement can point the wrong way", function()
  -- B = A moved by (8,2); the tutorial's first axis is the edge (0,10)->(0,0) with normal
  -- (-10, 0): overlap 20/100 * 10 = 2, displacement (-10 * 0.2, 0) = (-2, 0), into A
  local B = translate(A, 8, 2)

  it("moves the second polygon out of the first", function()
    local _, tdx, tdy = tutorialCollidesWithV(A, B)
    assert.are.same({ -2, 0 }, { tdx, tdy })
    assert.is_true(polygon.polygonsCollide(A, translate(B, tdx, tdy)))
    local _, dx, dy = polygon.polygonsCollideV(A, B)
    assert.are.same({ 2, 0 }, { dx, dy })
    assert.is_false(polygon.polygonsCollide(A, translate(B, dx, dy)))
  end)

  it("is right in the other argument order too", function()
    local _, dx, dy = polygon.polygonsCollideV(B, A)
    assert.are.same({ -2, 0 }, { dx, dy })
    assert.is_false(polygon.polygonsCollide(B, translate(A, dx, dy)))
  end)

  it("separates polygons whose centres coincide", function()
    -- a 4 by 20 bar centred on A's centre (5,5): any centre-based flip has no direction here
    local bar = { 3, -5, 7, -5, 7, 15, 3, 15 }
    local _, dx, dy = polygon.polygonsCollideV(A, bar)
    assert.is_false(polygon.polygonsCollide(A, translate(bar, dx, dy)))
  end)
end)

describe("defect: the tutorial's circle test picks the wrong vertex, caps the overlap, gives NaN", function()
  local circleV = polygon.polygonCircleCollideV

  it("takes the vertex nearest by distance", function()
    -- square 0..100, centre (120,110) r 22: the tutorial's vertex minimises 120px + 110py,
    -- which is (0,0) (value 0); the nearest by distance is (100,100) at sqrt(500) = 22.36 > 22
    local big = { 0, 0, 100, 0, 100, 100, 0, 100 }
    assert.is_truthy(tutorialCircle(big, 120, 110, 22))
    assert.are.equal(false, circleV(big, 120, 110, 22))
  end)

  it("resolves a deeply embedded circle in one step", function()
    -- centre (7,4) r 1 in A: every tutorial overlap is min(max1, max2) - max(min1, min2)
    -- <= 2 (the diameter); the penetration depth on x is min(10 - 6, 8 - 0) = 4
    local o, tdx, tdy = tutorialCircle(A, 7, 4, 1)
    assert.is_true(o <= 2 + 1e-12)
    assert.is_truthy(circleV(A, 7 + tdx, 4 + tdy, 1))
    local overlap, dx, dy = circleV(A, 7, 4, 1)
    -- the push is longer than the overlap by a few ulps, so that the moved circle clears
    assert.are.same({ 4, 0 }, { overlap, dy })
    assert.is_true(dx >= 4 and dx <= 4 + 1e-14)
    assert.are.equal(false, circleV(A, 7 + dx, 4 + dy, 1))
  end)

  it("returns no NaN when the centre sits on a vertex", function()
    -- the tutorial normalises the axis from the vertex (0,0) to the centre (0,0): 0/0
    local nx = (0 - A[1]) / math.sqrt(0)
    assert.is_true(isnan(nx))
    local overlap, dx, dy = circleV(A, 0, 0, 3)
    assert.is_false(isnan(overlap) or isnan(dx) or isnan(dy))
    assert.are.equal(3, overlap)
  end)

  it("returns no NaN when the polygon repeats a vertex", function()
    -- the closing edge (0,0)->(0,0) has length 0; its unit normal is NaN and the tutorial
    -- records that NaN overlap first, where no later comparison can replace it
    local closed = { 0, 0, 10, 0, 10, 10, 0, 10, 0, 0 }
    local to, tdx, tdy = tutorialCircle(closed, 12, 5, 3)
    assert.is_true(isnan(to) and isnan(tdx) and isnan(tdy))
    local overlap, dx, dy = circleV(closed, 12, 5, 3)
    assert.are.same({ 1, 0 }, { overlap, dy })
    assert.is_true(dx >= 1 and dx <= 1 + 1e-14)
  end)
end)

describe("defect: the tutorial's crossing test can give a point of a shared edge to both polygons", function()
  local contains = polygon.polygonContains

  it("never gives the shared vertex (7.3,1.3) to both triangles", function()
    -- shared edge P = (7.3,1.3), Q = (2.1,0.1); left lies left of it, right lies right of it.
    -- In right the edge's x at y = 1.3, computed from Q, rounds below 7.3, so the tutorial
    -- misses that crossing and counts the point in both
    local left = { 7.3, 1.3, 2.1, 0.1, -100, 5 }
    local right = { 2.1, 0.1, 7.3, 1.3, 100, 5 }
    assert.is_true(tutorialContains(left, 7.3, 1.3) and tutorialContains(right, 7.3, 1.3))
    assert.is_false(contains(left, 7.3, 1.3) and contains(right, 7.3, 1.3))
  end)

  it("gives a point within an ulp of a shared slanted edge to exactly one triangle", function()
    -- edge (18,18)-(4,0): at y = 3.6 the exact x is 6.80000000000000006911...; the tutorial
    -- computes 6.8000000000000007105 from (18,18) and 6.7999999999999998224 from (4,0)
    local x, y = 6.8000000000000007, 3.6
    local left = { 18, 18, 4, 0, 0, 18 }
    local right = { 4, 0, 18, 18, 22, 0 }
    assert.is_true(tutorialContains(left, x, y) and tutorialContains(right, x, y))
    assert.are_not.equal(contains(left, x, y), contains(right, x, y))
    assert.is_false(contains(left, x, y))
  end)
end)
