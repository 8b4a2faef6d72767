-- polygonRotate(points, angle [, ox, oy] [, out]): the polygon turned by angle (radians; positive
-- turns clockwise on screen, y down) about (ox, oy), by default its area centroid.
local polygon = require "polygon"
local shapes = require "shapes"
local oracle = require "oracle"
local garbage = require "garbage"
local callsite = require "callsite"

local rotate = polygon.polygonRotate

local EPS = 2 ^ -53

-- The documented rounding of one rotation, for a vertex at distance r from the pivot landing at
-- coordinate x': 4 eps (r + |x'|) from the five roundings, 2 eps r from cos and sin, plus r times
-- the angle's own error (pi / 2 as a double is off by 6e-17 < eps r): 4 eps (r + |x'|) + 3 eps r.
local function bound(r, x)
  return 4 * EPS * (r + math.abs(x)) + 3 * EPS * r
end

-- asserts that got equals want coordinate by coordinate within bound(r, want)
local function assertRotated(want, got, r)
  assert.are.equal(#want, #got)
  for i = 1, #want do
    assert.is_true(math.abs(got[i] - want[i]) <= bound(r, want[i]),
      ("coordinate %d: got %.17g, want %.17g"):format(i, got[i], want[i]))
  end
end

local SQUARE = { 0, 0, 10, 0, 10, 10, 0, 10 }    -- clockwise on screen

describe("polygonRotate", function()
  describe("when the angle is a quarter turn", function()
    -- about (0, 0) by pi / 2: (x, y) -> (x cos - y sin, x sin + y cos) = (-y, x);
    -- (1, 0) -> (0, 1): from pointing right to pointing down, a clockwise turn on screen
    it("turns (1, 0) to (0, 1), clockwise on screen, in both windings", function()
      local tri = { 1, 0, 0, -1, -1, 0 }          -- (1,0) (0,-1) (-1,0)
      -- (0,-1) -> (1, 0); (-1,0) -> (0, -1)
      assertRotated({ 0, 1, 1, 0, 0, -1 }, rotate(tri, math.pi / 2, 0, 0), 1)
      assertRotated({ 0, -1, 1, 0, 0, 1 }, rotate(shapes.reverse(tri), math.pi / 2, 0, 0), 1)
    end)

    -- the square's centroid is (5, 5); relative to it (x, y) -> (-y, x):
    -- (0,0): (-5,-5) -> (5,-5) + (5,5) = (10, 0); (10,0): (5,-5) -> (5,5) -> (10, 10);
    -- (10,10): (5,5) -> (-5,5) -> (0, 10); (0,10): (-5,5) -> (-5,-5) -> (0, 0). r = 5 sqrt 2
    -- reversed (0,10) (10,10) (10,0) (0,0) by -pi / 2, relative (x, y) -> (y, -x):
    -- (-5,5) -> (5,5) -> (10,10); (5,5) -> (5,-5) -> (10,0); (5,-5) -> (-5,-5) -> (0,0);
    -- (-5,-5) -> (-5,5) -> (0,10)
    it("turns the square about its centroid onto itself, vertices shifted by one", function()
      assertRotated({ 10, 0, 10, 10, 0, 10, 0, 0 }, rotate(SQUARE, math.pi / 2), 7.1)
      assertRotated({ 10, 10, 10, 0, 0, 0, 0, 10 }, rotate(shapes.reverse(SQUARE), -math.pi / 2), 7.1)
    end)
  end)

  describe("when the pivot is given", function()
    -- about (1, 1) by pi: (x, y) -> (2 - x, 2 - y): (0,0) -> (2,2); (4,0) -> (-2,2); (0,2) -> (2,0)
    it("turns a triangle by pi about (1, 1), in both windings", function()
      local tri = { 0, 0, 4, 0, 0, 2 }
      assertRotated({ 2, 2, -2, 2, 2, 0 }, rotate(tri, math.pi, 1, 1), 3.2)
      assertRotated({ 2, 0, -2, 2, 2, 2 }, rotate(shapes.reverse(tri), math.pi, 1, 1), 3.2)
    end)
  end)

  describe("when no pivot is given", function()
    -- triangle (0,0) (6,0) (0,3): centroid (2, 1); by pi (x, y) -> (4 - x, 2 - y):
    -- (4, 2), (-2, 2), (4, -1)
    it("turns about the area centroid", function()
      assertRotated({ 4, 2, -2, 2, 4, -1 }, rotate({ 0, 0, 6, 0, 0, 3 }, math.pi), 4.2)
    end)

    -- parts: square 0..2 (area 4, centroid (1,1)) and square 4..8 x 0..4 (area 16, centroid (6,2)):
    -- pivot ((4*1 + 16*6)/20, (4*1 + 16*2)/20) = (5, 1.8); by pi (x, y) -> (10 - x, 3.6 - y)
    it("turns a list of parts about the centroid of the parts weighted by their areas", function()
      local a, b = { 0, 0, 2, 0, 2, 2, 0, 2 }, { 4, 0, 8, 0, 8, 4, 4, 4 }
      local got = rotate({ a, shapes.reverse(b) }, math.pi)
      assertRotated({ 10, 3.6, 8, 3.6, 8, 1.6, 10, 1.6 }, got[1], 10.2)
      assertRotated({ 6, -0.4, 2, -0.4, 2, 3.6, 6, 3.6 }, got[2], 10.2)
    end)

    -- a segment has no area: (0,0) (4,0) (2,0) turn about their mean (2, 0)
    it("turns about the vertex mean when there is no area", function()
      assertRotated({ 4, 0, 0, 0, 2, 0 }, rotate({ 0, 0, 4, 0, 2, 0 }, math.pi), 2.1)
    end)
  end)

  describe("when the angle is 0", function()
    it("returns the coordinates unchanged, bit for bit", function()
      local p = { 0.1, 0.7, 1e15 + 1, 3, -2.5, 1 / 3 }
      assert.are.same(p, rotate(p, 0))
      assert.are.same(p, rotate(p, 0, 123.25, -7))
      assert.are.same({ p }, rotate({ p }, 0))
    end)
  end)

  describe("when out is given", function()
    it("writes into out (third or fifth argument), returns it, and drops extra entries", function()
      local out = { 9, 9, 9, 9, 9, 9, 9, 9, 9, 9 }
      assert.are.equal(out, rotate({ 0, 0, 6, 0, 0, 3 }, math.pi, out))
      assertRotated({ 4, 2, -2, 2, 4, -1 }, out, 4.2)
      local out2 = {}
      assert.are.equal(out2, rotate({ 0, 0, 4, 0, 0, 2 }, math.pi, 1, 1, out2))
      assertRotated({ 2, 2, -2, 2, 2, 0 }, out2, 3.2)
    end)

    it("turns in place when out is points itself, and keeps the winding", function()
      for _, p in ipairs({ { 0, 0, 6, 0, 0, 3 }, shapes.reverse({ 0, 0, 6, 0, 0, 3 }) }) do
        local winding = oracle.winding(p)
        assert.are.equal(p, rotate(p, 1, p))
        assert.are.equal(winding, oracle.winding(p))
      end
    end)

    it("reuses a list of part tables for a list of parts", function()
      local a, b = {}, {}
      local out = { a, b, {} }
      rotate({ SQUARE, { 0, 0, 6, 0, 0, 3 } }, 0.5, 0, 0, out)
      assert.are.equal(2, #out)
      assert.are.equal(a, out[1])
      assert.are.equal(b, out[2])
      assert.are.equal(8, #a)
    end)
  end)

  describe("without out", function()
    it("leaves the input unchanged and returns a new table", function()
      for _, p in ipairs({ SQUARE, { SQUARE, { 0, 0, 6, 0, 0, 3 } } }) do
        local copy = shapes.deepCopy(p)
        local got = rotate(p, 0.3)
        assert.are_not.equal(p, got)
        assert.are.same(copy, p)
      end
    end)
  end)

  describe("when an argument is wrong", function()
    local inf, nan = math.huge, 0 / 0
    local cases = {
      { { nil, 1 }, "polygonRotate: points must be a table, got nil" },
      { { { 1, 2, 3 }, 1 }, "polygonRotate: points must hold an even number of coordinates, got 3" },
      { { { SQUARE, 4 }, 1 }, "polygonRotate: points[2] must be a table, got number" },
      { { SQUARE, "1" }, "polygonRotate: angle must be a number, got string" },
      { { SQUARE, inf }, "polygonRotate: angle must be finite, got " .. tostring(inf) },
      { { SQUARE, nan }, "polygonRotate: angle must be finite, got " .. tostring(nan) },
      { { SQUARE, 1, 2 }, "polygonRotate: oy must be a number, got nil" },
      { { SQUARE, 1, nil, 2 }, "polygonRotate: ox must be a number, got nil" },
      { { SQUARE, 1, "2", 2 }, "polygonRotate: ox must be a number, got string" },
      { { SQUARE, 1, 2, -inf }, "polygonRotate: oy must be finite, got " .. tostring(-inf) },
      { { SQUARE, 1, 2, 2, 5 }, "polygonRotate: out must be a table, got number" },
      { { { SQUARE }, 1, 2, 2, { 5 } }, "polygonRotate: out[1] must be a table, got number" },
    }
    for _, case in ipairs(cases) do
      it("raises '" .. case[2] .. "'", function()
        local args = case[1]
        assert.has_error(function() rotate(args[1], args[2], args[3], args[4], args[5]) end, case[2])
      end)
    end

    it("raises the errors at the caller's level", function()
      for _, case in ipairs(cases) do
        assert.is_true(callsite.raisesAtCaller(rotate, case[1]))
      end
    end)
  end)

  describe("per call with out", function()
    it("allocates less than 1 KB over 10000 calls, with and without a pivot, flat and parts", function()
      local flatOut, partsOut, pivotOut = {}, {}, {}
      local parts = { SQUARE, { 0, 0, 6, 0, 0, 3 }, { 0, 0, 4, 0, 2, 0 } }
      local kb = garbage.growth(function(i)
        rotate(SQUARE, i * 0.001, flatOut)
        rotate(parts, -i * 0.001, partsOut)
        rotate(SQUARE, 0.5, i, -i, pivotOut)
        rotate(parts, 0, partsOut)
      end, 10000)
      assert.is_true(kb < 1, ("%.3f KB"):format(kb))
    end)
  end)
end)
