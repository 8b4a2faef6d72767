-- projectPolygon(points, x, y, nx, ny): min, max of (px - x) * nx + (py - y) * ny over the
-- vertices (n is not normalised). projectCircle(cx, cy, r, x, y, nx, ny): s - r, s + r with
-- s = (cx - x) * nx + (cy - y) * ny.
local polygon = require "polygon"

local projectPolygon, projectCircle = polygon.projectPolygon, polygon.projectCircle

local SQUARE_CW = { 0, 0, 10, 0, 10, 10, 0, 10 }
local SQUARE_CCW = { 0, 0, 0, 10, 10, 10, 10, 0 }

local function range(fn, ...)
  local lo, hi = fn(...)
  return { lo, hi }
end

describe("projectPolygon", function()
  for _, case in ipairs({ { "cw", SQUARE_CW }, { "ccw", SQUARE_CCW } }) do
    local winding, square = case[1], case[2]

    describe("when the square is listed " .. winding, function()
      it("returns 0, 10 on the x and y axes from the origin", function()
        assert.are.same({ 0, 10 }, range(projectPolygon, square, 0, 0, 1, 0))
        assert.are.same({ 0, 10 }, range(projectPolygon, square, 0, 0, 0, 1))
      end)

      it("returns -10, 0 on the negative x axis", function()
        -- x * -1 over x in {0, 10}
        assert.are.same({ -10, 0 }, range(projectPolygon, square, 0, 0, -1, 0))
      end)

      it("returns 0, 20 on the unnormalised diagonal (1,1)", function()
        -- x + y: 0, 10, 20, 10
        assert.are.same({ 0, 20 }, range(projectPolygon, square, 0, 0, 1, 1))
      end)

      it("returns -10, 10 on (1,-1)", function()
        -- x - y: 0, 10, 0, -10
        assert.are.same({ -10, 10 }, range(projectPolygon, square, 0, 0, 1, -1))
      end)

      it("measures from the given origin: -5, 5 from (5,5) on the x axis", function()
        assert.are.same({ -5, 5 }, range(projectPolygon, square, 5, 5, 1, 0))
      end)

      it("scales with the normal's length: -10, 10 from (5,5) on (2,0)", function()
        assert.are.same({ -10, 10 }, range(projectPolygon, square, 5, 5, 2, 0))
      end)
    end)
  end

  describe("when the polygon is a triangle", function()
    it("returns 0, 18 for {0,0, 6,0, 0,3} on (3,6) from the origin", function()
      -- 3x + 6y: (0,0) -> 0, (6,0) -> 18, (0,3) -> 18
      assert.are.same({ 0, 18 }, range(projectPolygon, { 0, 0, 6, 0, 0, 3 }, 0, 0, 3, 6))
      assert.are.same({ 0, 18 }, range(projectPolygon, { 0, 0, 0, 3, 6, 0 }, 0, 0, 3, 6))
    end)

    it("returns -18, 0 from the origin (6,0)", function()
      -- (x - 6) * 3 + y * 6: (0,0) -> -18, (6,0) -> 0, (0,3) -> -18 + 18 = 0
      assert.are.same({ -18, 0 }, range(projectPolygon, { 0, 0, 6, 0, 0, 3 }, 6, 0, 3, 6))
      assert.are.same({ -18, 0 }, range(projectPolygon, { 0, 0, 0, 3, 6, 0 }, 6, 0, 3, 6))
    end)
  end)

  describe("when the smallest and largest vertices come last", function()
    it("returns -7, 9 for {0,0, 1,0, 9,0, -7,0} on the x axis", function()
      assert.are.same({ -7, 9 }, range(projectPolygon, { 0, 0, 1, 0, 9, 0, -7, 0 }, 0, 0, 1, 0))
    end)
  end)
end)

describe("projectCircle", function()
  it("returns 3, 7 for the circle (5,5) r 2 on the x axis from the origin", function()
    -- s = 5, s - 2 = 3, s + 2 = 7
    assert.are.same({ 3, 7 }, range(projectCircle, 5, 5, 2, 0, 0, 1, 0))
  end)

  it("returns 2, 6 from the origin (1,1) on the y axis", function()
    -- s = (5 - 1) * 0 + (5 - 1) * 1 = 4
    assert.are.same({ 2, 6 }, range(projectCircle, 5, 5, 2, 1, 1, 0, 1))
  end)

  it("returns 5, 5 for radius 0 from (0,10) on (0,-1)", function()
    -- s = (5 - 0) * 0 + (5 - 10) * -1 = 5
    assert.are.same({ 5, 5 }, range(projectCircle, 5, 5, 0, 0, 10, 0, -1))
  end)

  it("returns 20, 30 for the circle (4,3) r 5 on the unnormalised (4,3)", function()
    -- s = 4*4 + 3*3 = 25 (the radius is not scaled by |n|, as the contract says)
    assert.are.same({ 20, 30 }, range(projectCircle, 4, 3, 5, 0, 0, 4, 3))
  end)
end)
