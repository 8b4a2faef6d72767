-- polygonWindingOrder: "cw" or "ccw" as seen on a screen whose y axis grows downwards.
-- The shoelace sum S = sum_i (x_i * y_{i+1} - x_{i+1} * y_i) is positive for "cw".
local polygon = require "polygon"
local shapes = require "shapes"

local winding = polygon.polygonWindingOrder

describe("polygonWindingOrder", function()
  describe("when the polygon is a square", function()
    it('returns "cw" for {0,0, 10,0, 10,10, 0,10} (right, down, left on screen)', function()
      -- S = (0*0 - 10*0) + (10*10 - 10*0) + (10*10 - 0*10) + (0*0 - 0*10) = 200 > 0
      assert.are.equal("cw", winding({ 0, 0, 10, 0, 10, 10, 0, 10 }))
    end)

    it('returns "ccw" for the same square listed the other way round', function()
      -- S = -200
      assert.are.equal("ccw", winding({ 0, 0, 0, 10, 10, 10, 10, 0 }))
    end)

    it("does not depend on which vertex comes first", function()
      assert.are.equal("cw", winding({ 10, 10, 0, 10, 0, 0, 10, 0 }))
      assert.are.equal("ccw", winding({ 10, 10, 10, 0, 0, 0, 0, 10 }))
    end)

    it("does not depend on where the square lies", function()
      -- S of a translated polygon equals S of the original: still 200 and -200
      assert.are.equal("cw", winding({ -50, -70, -40, -70, -40, -60, -50, -60 }))
      assert.are.equal("ccw", winding({ -50, -70, -50, -60, -40, -60, -40, -70 }))
    end)
  end)

  describe("when the polygon is a triangle", function()
    it('returns "cw" for the 3-4-5 right triangle {0,0, 4,0, 0,3}', function()
      -- S = 0 + (4*3 - 0*0) + 0 = 12 > 0
      assert.are.equal("cw", winding({ 0, 0, 4, 0, 0, 3 }))
    end)

    it('returns "ccw" for {0,0, 0,3, 4,0}', function()
      -- S = -12
      assert.are.equal("ccw", winding({ 0, 0, 0, 3, 4, 0 }))
    end)
  end)

  describe("when the polygon is concave", function()
    local dart = { 0, 0, 10, 5, 0, 10, 3, 5 }

    it('returns "cw" for the dart {0,0, 10,5, 0,10, 3,5}', function()
      -- S = (0*5 - 10*0) + (10*10 - 0*5) + (0*5 - 3*10) + (3*0 - 0*5) = 0 + 100 - 30 + 0 = 70
      assert.are.equal("cw", winding(dart))
    end)

    it('returns "ccw" for the dart reversed', function()
      assert.are.equal("ccw", winding(shapes.reverse(dart)))
    end)

    it('returns "cw" for the L shape {0,0, 20,0, 20,10, 10,10, 10,20, 0,20}', function()
      -- S = 2 * area = 2 * (20*20 - 10*10) = 600 > 0
      assert.are.equal("cw", winding({ 0, 0, 20, 0, 20, 10, 10, 10, 10, 20, 0, 20 }))
      assert.are.equal("ccw", winding({ 0, 20, 10, 20, 10, 10, 20, 10, 20, 0, 0, 0 }))
    end)
  end)

  describe("when a vertex is collinear or repeated", function()
    it("keeps the winding of the square", function()
      assert.are.equal("cw", winding({ 0, 0, 5, 0, 10, 0, 10, 10, 0, 10 }))
      assert.are.equal("ccw", winding({ 0, 0, 0, 10, 10, 10, 10, 0, 5, 0 }))
      assert.are.equal("cw", winding({ 0, 0, 10, 0, 10, 0, 10, 10, 0, 10 }))
      assert.are.equal("ccw", winding({ 0, 0, 0, 10, 10, 10, 10, 0, 0, 0 }))
    end)
  end)

  describe("when there are fewer than 3 points", function()
    it("returns nil", function()
      assert.is_nil(winding({}))
      assert.is_nil(winding({ 3, 4 }))
      assert.is_nil(winding({ 0, 0, 10, 10 }))
    end)
  end)

  describe("when the signed area is zero", function()
    it("returns nil for collinear points", function()
      assert.is_nil(winding({ 0, 0, 1, 1, 2, 2 }))
      assert.is_nil(winding({ 0, 5, 20, 5, 10, 5 }))
    end)

    it("returns nil when every point is the same", function()
      assert.is_nil(winding({ 5, 5, 5, 5, 5, 5 }))
    end)

    it("returns nil for the bow-tie {0,0, 10,10, 10,0, 0,10} whose two lobes cancel", function()
      -- S = (0*10 - 10*0) + (10*0 - 10*10) + (10*10 - 0*0) + (0*0 - 0*10) = 0 - 100 + 100 + 0 = 0
      assert.is_nil(winding({ 0, 0, 10, 10, 10, 0, 0, 10 }))
    end)
  end)

  describe("when the coordinates are large integers", function()
    it("does not overflow 64-bit integers on Lua 5.3+ (coordinates are used as doubles)", function()
      -- side 2^40: S = 2 * 2^80, which wraps to 0 in 64-bit integer arithmetic
      local s = 1099511627776
      assert.are.equal("cw", winding({ 0, 0, s, 0, s, s, 0, s }))
      assert.are.equal("ccw", winding({ 0, 0, 0, s, s, s, s, 0 }))
    end)
  end)

  describe("when the polygon is nearly degenerate", function()
    it("decides the sign exactly where double rounding cancels it to 0", function()
      -- (0,0), (b, b-1), (a, b) with a = 2^27+1, b = 2^27: S = b*b - a*(b-1) = 2^54 - (2^54 - 1)
      -- = 1 > 0. In doubles the partial sums pass 2^54 + 2^27 + 1, which rounds to
      -- 2^54 + 2^27, and the naive sum comes out 0
      local a, b = 2 ^ 27 + 1, 2 ^ 27
      assert.are.equal("cw", winding({ 0, 0, b, b - 1, a, b }))
      assert.are.equal("ccw", winding({ 0, 0, a, b, b, b - 1 }))
      assert.are.equal("cw", winding(shapes.translate({ 0, 0, b, b - 1, a, b }, 2 ^ 20, -2 ^ 20)))
    end)

    it("decides the sign of a tiny signed area exactly", function()
      -- (0,0), (1,1), (2, 2 + 2^-51): S = 1*(2 + 2^-51) - 2*1 = 2^-51 > 0
      local e = 2 ^ -51
      assert.are.equal("cw", winding({ 0, 0, 1, 1, 2, 2 + e }))
      assert.are.equal("ccw", winding({ 0, 0, 2, 2 + e, 1, 1 }))
    end)
  end)
end)
