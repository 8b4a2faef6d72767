-- polygonCenter: the mean of the vertices (as in the tutorial).
-- polygonCentroid: the area centroid, cx = sum (x_i + x_{i+1}) c_i / (3 S),
-- cy = sum (y_i + y_{i+1}) c_i / (3 S), with c_i = x_i y_{i+1} - x_{i+1} y_i and S = sum c_i.
-- Every case below has a centroid that doubles represent exactly.
local polygon = require "polygon"
local shapes = require "shapes"

local center, centroid = polygon.polygonCenter, polygon.polygonCentroid

local function check(fn, points, ex, ey)
  local cx, cy = fn(points)
  assert.are.equal(ex, cx)
  assert.are.equal(ey, cy)
  cx, cy = fn(shapes.reverse(points))
  assert.are.equal(ex, cx)
  assert.are.equal(ey, cy)
end

describe("polygonCenter", function()
  describe("when the polygon is a square", function()
    it("returns 5, 5 for the 10 by 10 square in both windings", function()
      check(center, { 0, 0, 10, 0, 10, 10, 0, 10 }, 5, 5)
    end)
  end)

  describe("when the polygon is a triangle", function()
    it("returns 2, 1 for {0,0, 6,0, 0,3}", function()
      -- (0 + 6 + 0) / 3 = 2, (0 + 0 + 3) / 3 = 1
      check(center, { 0, 0, 6, 0, 0, 3 }, 2, 1)
    end)
  end)

  describe("when the vertices crowd one side", function()
    it("returns the vertex mean 4, 5, not the centroid, for the square with a point at (0,5)", function()
      -- x: (0 + 10 + 10 + 0 + 0) / 5 = 4, y: (0 + 0 + 10 + 10 + 5) / 5 = 5
      check(center, { 0, 0, 10, 0, 10, 10, 0, 10, 0, 5 }, 4, 5)
    end)
  end)

  describe("when the polygon is far from the origin", function()
    it("returns 1005, 2005 for the square moved by (1000, 2000)", function()
      check(center, { 1000, 2000, 1010, 2000, 1010, 2010, 1000, 2010 }, 1005, 2005)
    end)
  end)

  describe("when all points lie on one line", function()
    it("still returns the mean of the vertices", function()
      -- (0 + 5 + 10) / 3 = 5, y = 0
      check(center, { 0, 0, 5, 0, 10, 0 }, 5, 0)
    end)
  end)

  describe("when there are fewer than 3 points", function()
    it("returns nil", function()
      assert.is_nil(center({}))
      assert.is_nil(center({ 1, 2 }))
      assert.is_nil(center({ 1, 2, 3, 4 }))
    end)
  end)
end)

describe("polygonCentroid", function()
  describe("when the polygon is a square", function()
    it("returns 5, 5 for the 10 by 10 square in both windings", function()
      check(centroid, { 0, 0, 10, 0, 10, 10, 0, 10 }, 5, 5)
    end)
  end)

  describe("when the polygon is a triangle", function()
    it("returns 2, 1 for {0,0, 6,0, 0,3}", function()
      -- c = (0, 6*3 - 0*0 = 18, 0), S = 18: cx = (6 + 0) * 18 / 54 = 2, cy = (0 + 3) * 18 / 54 = 1
      check(centroid, { 0, 0, 6, 0, 0, 3 }, 2, 1)
    end)
  end)

  describe("when the vertices crowd one side", function()
    it("returns 5, 5 for the square with an extra point at (0,5), unlike polygonCenter", function()
      check(centroid, { 0, 0, 10, 0, 10, 10, 0, 10, 0, 5 }, 5, 5)
    end)
  end)

  describe("when the polygon is concave", function()
    local L = { 0, 0, 30, 0, 30, 10, 10, 10, 10, 20, 0, 20 }

    it("returns 12.5, 7.5 for the L {0,0, 30,0, 30,10, 10,10, 10,20, 0,20}", function()
      -- bar 30x10: area 300 at (15, 5); foot 10x10 below it: area 100 at (5, 15)
      -- cx = (300*15 + 100*5) / 400 = 5000 / 400 = 12.5
      -- cy = (300*5 + 100*15) / 400 = 3000 / 400 = 7.5
      check(centroid, L, 12.5, 7.5)
    end)

    it("moves with the polygon: 1012.5, 2007.5 after moving it by (1000, 2000)", function()
      check(centroid, shapes.translate(L, 1000, 2000), 1012.5, 2007.5)
    end)
  end)

  describe("when the coordinates are very large or very small", function()
    -- the 10 by 10 square scaled by 2^e (exact): its centroid is (5 * 2^e, 5 * 2^e)
    for _, e in ipairs({ -440, -400, -370, 350, 400, 490, 520 }) do
      it("returns (5 * 2^" .. e .. ", 5 * 2^" .. e .. ") for the square of side 10 * 2^" .. e, function()
        local k = 2 ^ e
        check(centroid, { 0, 0, 10 * k, 0, 10 * k, 10 * k, 0, 10 * k }, 5 * k, 5 * k)
      end)
    end
  end)

  describe("when the area is zero", function()
    it("returns nil for collinear points", function()
      assert.is_nil(centroid({ 0, 0, 5, 0, 10, 0 }))
      assert.is_nil(centroid({ 0, 0, 5, 5, 10, 10 }))
    end)

    it("returns nil when every point is the same", function()
      assert.is_nil(centroid({ 4, 4, 4, 4, 4, 4 }))
    end)
  end)

  describe("when there are fewer than 3 points", function()
    it("returns nil", function()
      assert.is_nil(centroid({}))
      assert.is_nil(centroid({ 1, 2 }))
      assert.is_nil(centroid({ 1, 2, 3, 4 }))
    end)
  end)
end)
