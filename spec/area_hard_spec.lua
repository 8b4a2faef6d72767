-- Hard cases, family 6: polygons of 10^5 vertices, for the area.
--
-- polygonAreaAccurate must be within 1 ulp of the exact area of the given doubles for any number
-- of vertices; polygonArea sums 10^5 rounded terms, so its error grows with n: measured here at
-- 83 ulps (around the origin) and 61 ulps (around (1e6, -1e6)), the same on every interpreter,
-- and asserted below 2^-42 relative (about 1000 to 2000 ulps). The tutorial's sum, not taken
-- relative to a vertex, is off by 215552 ulps (2.5e-11 relative, about 2^-35) at (1e6, -1e6).

local polygon = require "polygon"
local oracle = require "oracle"
local exact = require "exact"
local prng = require "prng"
local shapes = require "shapes"

local N = 100000

-- A wobbly circle of radius about 100 around (ox, oy), counter-clockwise in math terms.
local function wobbly(ox, oy, seed)
  local r = prng.new(seed)
  local points = {}
  for k = 1, N do
    local angle = 2 * math.pi * (k - 1) / N
    local radius = 100 * (1 + 0.01 * r:range(-1, 1))
    points[2 * k - 1] = ox + radius * math.cos(angle)
    points[2 * k] = oy + radius * math.sin(angle)
  end
  return points
end

-- A sliver: out along y = 0.3 x + a wobble of 1e-9, back along y = 0.3 x (both rounded), so the
-- area is about 1e-7 while the products x y reach 3e11: the float sum cancels almost everything.
local function sliver(ox, seed)
  local r = prng.new(seed)
  local points = {}
  local half = N / 2
  for k = 1, half do
    local x = ox + k * 0.001
    points[2 * k - 1], points[2 * k] = x, 0.3 * x + 1e-9 * r:range(0, 1)
  end
  for k = 1, half do
    local x = ox + (half - k + 1) * 0.001
    points[N + 2 * k - 1], points[N + 2 * k] = x, 0.3 * x
  end
  return points
end

local function relativeError(value, exactValue)
  return math.abs(exact.tonumber(exact.sub(exact.new(value), exactValue))) / exact.tonumber(exactValue)
end

describe("a polygon of 10^5 vertices", function()
  for _, case in ipairs({ { 0, 0, 11 }, { 1e6, -1e6, 14 } }) do
    local ox, oy = case[1], case[2]
    describe(("(a wobbly circle around (%g, %g))"):format(ox, oy), function()
      local points = wobbly(ox, oy, case[3])
      local twice = oracle.shoelace(points)
      local area = exact.mul(exact.abs(twice), exact.pow2(-1))

      it("has polygonAreaAccurate within 1 ulp of the exact area", function()
        local a = polygon.polygonAreaAccurate(points)
        assert.is_true(exact.withinUlps(a, area, 1),
          ("got %.17g, exact %s"):format(a, exact.tostring(area)))
      end)

      it("has polygonArea within 2^-42 relative of the exact area", function()
        local a = polygon.polygonArea(points)
        local err = relativeError(a, area)
        assert.is_true(err <= 2 ^ -42,
          ("got %.17g, exact %s, relative error %g"):format(a, exact.tostring(area), err))
      end)

      if ox ~= 0 then
        it("has its area wrong by far more when the sum is not taken relative to a vertex", function()
          -- the tutorial's sum of (x_(k+1) + x_k)(y_(k+1) - y_k): far from the origin its terms
          -- are much larger than the area's share of each, and so is their rounding
          local n = #points
          local sum = (points[1] + points[n - 1]) * (points[2] - points[n])
          for i = 1, n - 3, 2 do
            sum = sum + (points[i + 2] + points[i]) * (points[i + 3] - points[i + 1])
          end
          local naive = relativeError(math.abs(sum) * 0.5, area)
          assert.is_true(naive > 2 ^ -42, "the naive sum should fail the bound here: " .. naive)
        end)
      end

      it("has the exact winding", function()
        -- math-ccw with y up is clockwise on screen: a positive shoelace sum
        assert.are.equal(1, exact.sign(twice))
        assert.are.equal("cw", polygon.polygonWindingOrder(points))
      end)
    end)
  end

  describe("(a sliver whose float shoelace sum cancels, at x = 1e6)", function()
    local points = sliver(1e6, 21)
    local twice = oracle.shoelace(points)
    local area = exact.mul(exact.abs(twice), exact.pow2(-1))

    it("has polygonAreaAccurate within 1 ulp of the exact area", function()
      local a = polygon.polygonAreaAccurate(points)
      assert.is_true(exact.withinUlps(a, area, 1), ("got %.17g, exact %s"):format(a, exact.tostring(area)))
    end)

    it("still has the exact winding", function()
      -- out along y = 0.3 x + wobble (the larger y), back along y = 0.3 x: like (0, e), (1, e),
      -- (1, 0), (0, 0), whose shoelace sum is -e - e + 0 + 0 < 0: counter-clockwise on screen
      assert.are.equal(-1, exact.sign(twice))
      assert.are.equal("ccw", polygon.polygonWindingOrder(points))
    end)
  end)
end)

-- polygonAreaAccurate on its fast path (a compensated sum whose bound must vouch for one ulp)
-- and on its fallback (the expansion), against the oracle's exact area: random polygons of 3 to
-- 40 vertices at offsets from 0 to 1e12, nearly collinear ones whose sums cancel, and polygons
-- mixing huge and tiny coordinates. Within one ulp of the exact area every time.

local function check(points, bad)
  local a = polygon.polygonAreaAccurate(points)
  local want = oracle.area(points)
  if not exact.withinUlps(a, want, 1) and #bad < 3 then
    bad[#bad + 1] = ("got %.17g, exact %s"):format(a, exact.tostring(want))
  end
end

-- Checks count polygons made by make(r, i) from a generator seeded with seed: none may be off.
local function checkGenerated(seed, count, make)
  local r, bad = prng.new(seed), {}
  for i = 1, count do check(make(r, i), bad) end
  assert.are.same({}, bad)
end

describe("polygonAreaAccurate against the exact area", function()
  it("is within one ulp on random star-shaped polygons at offsets up to 1e12", function()
    checkGenerated(31337, 400, function(r)
      local m, radius = r:int(3, 40), 10 ^ r:int(-3, 4)
      local ox, oy = (r:float() - 0.5) * 10 ^ r:int(0, 12), (r:float() - 0.5) * 10 ^ r:int(0, 12)
      return shapes.star(r, m, ox, oy, radius)
    end)
  end)

  it("is within one ulp where the sum cancels (nearly collinear points)", function()
    checkGenerated(2718, 300, function(r)
      local p = {}
      local x0, y0, dx, dy = r:float() * 100, r:float() * 100, r:float(), r:float()
      for _ = 1, r:int(3, 8) do
        local s = r:float() * 50
        p[#p + 1], p[#p + 2] = x0 + s * dx, y0 + s * dy + r:int(-2, 2) * 2 ^ -46
      end
      return p
    end)
  end)
end)

-- The split path: coordinates rounded to multiples of a quantum guessed from vertex 1 and the
-- middle one, beyond 64 vertices in two passes (spec/area_large_hard_spec.lua has more of
-- those). Its tests after the loop must
-- catch every case where the guess was wrong (the other vertices far beyond the guessed size,
-- so that the rounded sums are not exact), where the polygon lies far from the origin for its
-- size (the rounding is then no longer exact), and where the small parts' float sum is too
-- rough for one ulp (slivers, very flat boxes); the answer is within one ulp of the exact area
-- either way.
describe("polygonAreaAccurate's split path against the exact area", function()
  local function polygonOf(r, kind, mLo, mHi)
    local m, p = r:int(mLo or 3, mHi or 64), {}
    local size = 2 ^ r:int(-40, 40) * (0.5 + r:float())
    local ox = (r:float() - 0.5) * 2 ^ r:int(-10, 60)
    local oy = (r:float() - 0.5) * 2 ^ r:int(-10, 60)
    if kind == 0 then   -- vertices 1, m and the middle close together, the others up to 2^40 farther
      local far = size * 2 ^ r:int(0, 40)
      for _ = 1, m do
        p[#p + 1], p[#p + 2] = ox + far * (r:float() - 0.5), oy + far * (r:float() - 0.5)
      end
      local middle = m - m % 2 + 1
      p[1], p[2] = ox, oy
      p[middle], p[middle + 1] = ox + size, oy + size * 0.5
      p[2 * m - 1], p[2 * m] = ox + size * 0.3, oy - size
    elseif kind == 1 then   -- a sliver: points near a line, y off it by 2^-10 to 2^-60 of the size
      local ux, uy = r:float() - 0.5, r:float() - 0.5
      for _ = 1, m do
        local t = size * r:float()
        p[#p + 1] = ox + ux * t + size * 1e-12 * r:float()
        p[#p + 1] = oy + uy * t + size * 2 ^ -r:int(10, 60) * r:float()
      end
    elseif kind == 2 then   -- random points in a box up to 2^20 times as wide as high (or high)
      local aspect = 2 ^ r:int(-20, 20)
      for _ = 1, m do
        p[#p + 1], p[#p + 2] = ox + size * (r:float() - 0.5), oy + size * aspect * (r:float() - 0.5)
      end
    elseif kind == 3 then   -- a regular polygon: ox, oy near 2^50 times the quanta at some sizes
      for k = 1, m do
        local t = 2 * math.pi * k / m
        p[#p + 1], p[#p + 2] = ox + size * math.cos(t), oy + size * math.sin(t)
      end
    else   -- a star
      p = shapes.star(r, m, ox, oy, size)
    end
    return p
  end

  it("is within one ulp on guess-breaking, far, flat, sliver, regular and star polygons", function()
    checkGenerated(20261122, 1000, function(r, i) return polygonOf(r, i % 5) end)
  end)

  it("is within one ulp on the same kinds of 65 to 1,200 vertices (in two passes)", function()
    checkGenerated(8675309, 150, function(r, i) return polygonOf(r, i % 5, 65, 1200) end)
  end)

  it("is within one ulp on small integer grids far out (exact products everywhere)", function()
    -- multiples of 2^k around an integer offset: every rounded part is the coordinate itself
    checkGenerated(4099, 200, function(r)
      local g, ox, oy = 2 ^ r:int(0, 30), r:int(-2 ^ 40, 2 ^ 40), r:int(-2 ^ 40, 2 ^ 40)
      local p = {}
      for _ = 1, r:int(3, 64) do
        p[#p + 1], p[#p + 2] = ox + r:int(-1000, 1000) * g, oy + r:int(-1000, 1000) * g
      end
      return p
    end)
  end)
end)
