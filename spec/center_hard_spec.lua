-- polygonCentroid on slivers and nearly degenerate polygons, against the oracle's exact
-- centroid (spec/support/oracle.lua: exact sums, rounded at the end). Where the rounded area of
-- a thin polygon cancels, its rounded moments have cancelled too, so the float formula alone
-- can be off by anything; the centroid must stay within a few ulps of the coordinates'
-- magnitude all the same.
local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local shapes = require "shapes"

local centroid = polygon.polygonCentroid

local magnitude = shapes.largestMagnitude

-- |got - want| in units of eps * M (M the largest coordinate magnitude)
local function epsError(points, gx, gy, wx, wy)
  local unit = 2 ^ -52 * magnitude(points)
  return math.max(math.abs(gx - wx), math.abs(gy - wy)) / unit
end

describe("polygonCentroid on slivers", function()
  it("returns a triangle's vertex mean for a sliver whose rounded area cancels", function()
    -- (-26.2 + 37.0 + 21.2) / 3 = 10.667, (188.7 + 290.7 + 265.2) / 3 = 248.2: the three
    -- points lie within rounding of one line (slopes 102 / 63.2 and 76.5 / 47.4, both 1.6139)
    local p = { -26.2, 188.7, 37.0, 290.7, 21.2, 265.2 }
    local cx, cy = centroid(p)
    assert.is_true(math.abs(cx - 32 / 3) < 1e-12, tostring(cx))
    assert.is_true(math.abs(cy - 248.2) < 1e-12, tostring(cy))
    local wx, wy = oracle.centroid(p)
    assert.is_true(epsError(p, cx, cy, wx, wy) <= 4)
  end)

  it("agrees with the exact centroid on random near-collinear triangles and quadrilaterals", function()
    local r = prng.new(9090)
    local worst, count = 0, 0
    for _ = 1, 300 do
      -- points near the line through (x0, y0) in direction (dx, dy), off it by a few ulps
      local x0, y0 = r:float() * 200 - 100, r:float() * 200 - 100
      local t = r:float() * 6.283
      local dx, dy = math.cos(t), math.sin(t)
      local p = {}
      for _ = 1, r:int(3, 4) do
        local s = r:float() * 300
        p[#p + 1] = x0 + s * dx
        p[#p + 1] = y0 + s * dy + r:int(-3, 3) * 2 ^ -44
      end
      local wx, wy = oracle.centroid(p)
      local cx, cy = centroid(p)
      if wx == nil then
        assert.is_nil(cx)
      else
        count = count + 1
        worst = math.max(worst, epsError(p, cx, cy, wx, wy))
      end
    end
    assert.is_true(count > 250)
    assert.is_true(worst <= 4, ("worst error %.3g eps M"):format(worst))
  end)

  it("agrees with the exact centroid on thin rectangles at any rotation and offset", function()
    local r = prng.new(4711)
    local worst = 0
    for _ = 1, 200 do
      local len, thick = 10 ^ r:int(0, 4), 10 ^ -r:int(3, 12)
      local t = r:float() * 6.283
      local ux, uy = math.cos(t), math.sin(t)
      local ox, oy = (r:float() - 0.5) * 10 ^ r:int(0, 9), (r:float() - 0.5) * 10 ^ r:int(0, 9)
      local p = { ox, oy, ox + len * ux, oy + len * uy,
                  ox + len * ux - thick * uy, oy + len * uy + thick * ux,
                  ox - thick * uy, oy + thick * ux }
      local wx, wy = oracle.centroid(p)
      if wx then
        local cx, cy = centroid(p)
        worst = math.max(worst, epsError(p, cx, cy, wx, wy))
      end
    end
    assert.is_true(worst <= 4, ("worst error %.3g eps M"):format(worst))
  end)
end)
