-- polygonArea (float, relative to the first vertex) and polygonAreaAccurate (the exact
-- area of the given doubles, rounded within 1 ulp).
local polygon = require "polygon"
local shapes = require "shapes"

local SQUARE_CW = { 0, 0, 10, 0, 10, 10, 0, 10 }
local SQUARE_CCW = { 0, 0, 0, 10, 10, 10, 10, 0 }
local TRIANGLE_CW = { 0, 0, 4, 0, 0, 3 }
local TRIANGLE_CCW = { 0, 0, 0, 3, 4, 0 }
local DART_CW = { 0, 0, 10, 5, 0, 10, 3, 5 }
local L_CW = { 0, 0, 20, 0, 20, 10, 10, 10, 10, 20, 0, 20 }

for _, name in ipairs({ "polygonArea", "polygonAreaAccurate" }) do
  local area = polygon[name]

  describe(name, function()
    describe("when the polygon is a 10 by 10 square", function()
      it("returns 100 in clockwise order", function()
        assert.are.equal(100, area(SQUARE_CW))
      end)

      it("returns 100 in counter-clockwise order", function()
        assert.are.equal(100, area(SQUARE_CCW))
      end)
    end)

    describe("when the polygon is the 3-4-5 right triangle", function()
      it("returns 6 in both orders", function()
        -- 3 * 4 / 2 = 6
        assert.are.equal(6, area(TRIANGLE_CW))
        assert.are.equal(6, area(TRIANGLE_CCW))
      end)
    end)

    describe("when the polygon is concave", function()
      it("returns 35 for the dart {0,0, 10,5, 0,10, 3,5} in both orders", function()
        -- triangle (0,0),(10,5),(0,10): 10*10/2 = 50, minus the notch (0,0),(3,5),(0,10):
        -- base 10 on x = 0, height 3: 10*3/2 = 15; 50 - 15 = 35
        assert.are.equal(35, area(DART_CW))
        assert.are.equal(35, area(shapes.reverse(DART_CW)))
      end)

      it("returns 300 for the L shape in both orders", function()
        -- 20*20 - 10*10 = 300
        assert.are.equal(300, area(L_CW))
        assert.are.equal(300, area(shapes.reverse(L_CW)))
      end)
    end)

    describe("when a vertex is collinear or repeated", function()
      it("returns the area of the square", function()
        assert.are.equal(100, area({ 0, 0, 5, 0, 10, 0, 10, 10, 0, 10 }))
        assert.are.equal(100, area({ 0, 0, 10, 0, 10, 0, 10, 10, 0, 10, 0, 0 }))
      end)
    end)

    describe("when all points lie on one line", function()
      it("returns 0", function()
        assert.are.equal(0, area({ 0, 0, 5, 5, 10, 10 }))
        assert.are.equal(0, area({ 7, 7, 7, 7, 7, 7 }))
      end)
    end)

    describe("when there are fewer than 3 points", function()
      it("returns nil", function()
        assert.is_nil(area({}))
        assert.is_nil(area({ 1, 2 }))
        assert.is_nil(area({ 1, 2, 3, 4 }))
      end)
    end)

    describe("when the polygon lies far from the origin", function()
      it("returns the exact area of a 10 by 10 square at 1e15", function()
        -- relative to the first vertex every difference is 0 or 10 (exact), so 100 exactly;
        -- shoelace on absolute coordinates would lose everything to products near 1e30
        local o = 1e15
        assert.are.equal(100, area({ o, o, o + 10, o, o + 10, o + 10, o, o + 10 }))
        assert.are.equal(100, area({ o, o, o, o + 10, o + 10, o + 10, o + 10, o }))
      end)
    end)

    describe("when the area exceeds the largest double", function()
      it("returns infinity, not NaN, for a square of side 2^520", function()
        -- 2^1040 > 2^1024: the exact area rounds to infinity
        local s = 2 ^ 520
        assert.are.equal(math.huge, area({ 0, 0, s, 0, s, s, 0, s }))
        assert.are.equal(math.huge, area({ 0, 0, 0, s, s, s, s, 0 }))
      end)
    end)

    describe("when the coordinates are large integers", function()
      it("returns 2^80 for a square of side 2^40 (no 64-bit integer overflow on Lua 5.3+)", function()
        local s = 1099511627776 -- 2^40, an integer literal on Lua 5.3+
        assert.are.equal(2 ^ 80, area({ 0, 0, s, 0, s, s, 0, s }))
        assert.are.equal(2 ^ 80, area({ 0, 0, 0, s, s, s, s, 0 }))
      end)
    end)
  end)
end

describe("polygonAreaAccurate", function()
  local area = polygon.polygonAreaAccurate

  describe("when the cross product cancels catastrophically", function()
    -- triangle (0,0), (2^27+1, 2^27), (2^27, 2^27-1): twice the signed area is
    -- (2^27+1)*(2^27-1) - 2^27*2^27 = 2^54 - 1 - 2^54 = -1, so the area is 1/2;
    -- in doubles (2^27+1)*(2^27-1) = 2^54 - 1 rounds to 2^54 and the naive result is 0
    local a, b = 2 ^ 27 + 1, 2 ^ 27
    local cw = { 0, 0, b, b - 1, a, b }
    local ccw = { 0, 0, a, b, b, b - 1 }

    it("returns 1/2 within 1 ulp in both orders", function()
      -- 1 ulp of 0.5 is 2^-53; the tolerance is the contract
      assert.near(0.5, area(cw), 2 ^ -53)
      assert.near(0.5, area(ccw), 2 ^ -53)
    end)

    it("returns 1/2 within 1 ulp when the triangle is moved by (2^20, 2^20)", function()
      local o = 2 ^ 20
      assert.near(0.5, area(shapes.translate(cw, o, o)), 2 ^ -53)
      assert.near(0.5, area(shapes.translate(ccw, o, o)), 2 ^ -53)
    end)
  end)

  describe("when the area is far below the size of the coordinates", function()
    it("returns 2^-52 for the sliver (0,0), (1,1), (2, 2 + 2^-51)", function()
      -- twice the area: 1*(2 + 2^-51) - 2*1 = 2^-51, so the area is 2^-52 (exact)
      local e = 2 ^ -51
      assert.are.equal(2 ^ -52, area({ 0, 0, 1, 1, 2, 2 + e }))
      assert.are.equal(2 ^ -52, area({ 0, 0, 2, 2 + e, 1, 1 }))
    end)
  end)
end)
