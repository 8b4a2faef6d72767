-- Hard cases, family 4: repeated vertices, collinear runs, spikes, all-collinear and zero-area
-- polygons. Each case carries its hand-derived answers, and the exact oracle must agree with them
-- before the library is compared with both.

local polygon = require "polygon"
local oracle = require "oracle"
local exact = require "exact"

local BIG = 2 ^ 52 -- 4503599627370496: x + 1 is still exact next to it

-- type, winding and whether the exact area is zero (then centroid nil, no collisions).
local CASES = {
  -- repeated vertices
  { "square, every vertex twice", { 0, 0, 0, 0, 10, 0, 10, 0, 10, 10, 10, 10, 0, 10, 0, 10 },
    "convex", "cw" },
  { "square, closed by repeating the first vertex", { 0, 0, 10, 0, 10, 10, 0, 10, 0, 0 }, "convex", "cw" },
  { "triangle, first vertex three times", { 1, 1, 1, 1, 1, 1, 5, 1, 1, 5 }, "convex", "cw" },
  { "triangle, ccw, repeated last vertex", { 1, 1, 1, 5, 5, 1, 5, 1 }, "convex", "ccw" },
  -- collinear runs going forward
  { "square with a midpoint on every edge", { 0, 0, 5, 0, 10, 0, 10, 5, 10, 10, 5, 10, 0, 10, 0, 5 },
    "convex", "cw" },
  { "triangle with a run on its hypotenuse", { 0, 0, 3, 0, 2, 1, 1, 2, 0, 3 }, "convex", "cw" },
  { "collinear first vertex", { 5, 0, 10, 0, 10, 10, 0, 10, 0, 0 }, "convex", "cw" },
  { "far square with a collinear run",
    { BIG, BIG, BIG + 1, BIG, BIG + 2, BIG, BIG + 2, BIG + 2, BIG, BIG + 2 },
    "convex", "cw" },
  -- spikes: a zero turn that doubles back
  { "square with a spike out of its right side", { 0, 0, 10, 0, 10, 5, 15, 5, 10, 5, 10, 10, 0, 10 },
    "concave", "cw" },
  { "square with a spike into it", { 0, 0, 10, 0, 10, 5, 5, 5, 10, 5, 10, 10, 0, 10 }, "concave", "cw" },
  { "triangle whose last edge doubles back", { 0, 0, 4, 0, 0, 4, 0, 8 }, "concave", "cw" },
  -- all points on one line: type nil, winding nil, area 0
  { "three points on y = x", { 0, 0, 1, 1, 2, 2 }, nil, nil, true },
  { "points on a line, doubling back", { 0, 0, 2, 0, 1, 0 }, nil, nil, true },
  { "vertical line with repeats", { 3, 0, 3, 0, 3, 7, 3, 2, 3, 2 }, nil, nil, true },
  { "all points equal", { 1.5, -2, 1.5, -2, 1.5, -2 }, nil, nil, true },
  { "non-dyadic points on y = x", { 0.1, 0.1, 0.7, 0.7, 0.3, 0.3, 1e-100, 1e-100 }, nil, nil, true },
  { "points on y = 2x (doubling is exact)", { 0.1, 0.2, 1 / 3, 2 / 3, -7.7, -15.4 }, nil, nil, true },
  { "points on y = -x far away", { 1e15, -1e15, 1e15 + 2, -1e15 - 2, 1e15 + 0.5, -1e15 - 0.5 },
    nil, nil, true },
  { "collinear with 2^52 coordinates", { BIG, 1, BIG + 1, 2, BIG + 2, 3, BIG + 4, 5 }, nil, nil, true },
  -- zero signed area without being one line
  { "symmetric bow-tie", { 0, 0, 2, 2, 2, 0, 0, 2 }, "concave", nil, true },
  { "there and back", { 0, 0, 1, 0, 1, 1, 1, 0 }, "concave", nil, true },
}

local function each(fn)
  for _, case in ipairs(CASES) do
    fn(case[1], case[2], case[3], case[4], case[5] or false)
  end
end

-- The largest |coordinate - first vertex| of a polygon.
local function extent(points)
  local e = 0
  for i = 1, #points - 1, 2 do
    e = math.max(e, math.abs(points[i] - points[1]), math.abs(points[i + 1] - points[2]))
  end
  return e
end

describe("degenerate polygons", function()
  it("have the hand-derived answers by the oracle (checks the cases themselves)", function()
    each(function(name, p, kind, winding, zero)
      assert.are.equal(kind, oracle.polygonType(p), name .. ": oracle type")
      assert.are.equal(winding, oracle.winding(p), name .. ": oracle winding")
      assert.are.equal(zero, exact.sign(oracle.area(p)) == 0, name .. ": oracle zero area")
    end)
  end)

  it("have the exact type and winding", function()
    each(function(name, p, kind, winding)
      assert.are.equal(kind, polygon.polygonType(p), name .. ": polygonType")
      assert.are.equal(winding, polygon.polygonWindingOrder(p), name .. ": polygonWindingOrder")
    end)
  end)

  it("have the exact area (accurate within 1 ulp, plain within a few ulps or rounding of 0)", function()
    each(function(name, p, _, _, zero)
      local a = oracle.area(p)
      local accurate, plain = polygon.polygonAreaAccurate(p), polygon.polygonArea(p)
      assert.is_true(exact.withinUlps(accurate, a, 1), name .. ": polygonAreaAccurate " .. accurate)
      if zero then
        assert.are.equal(0, accurate, name)
        -- the float sum can only leave rounding behind: at most about n eps extent^2
        local e = extent(p)
        assert.is_true(plain <= #p * 2 ^ -52 * e * e, name .. ": polygonArea " .. plain)
      else
        assert.is_true(exact.withinUlps(plain, a, 4), name .. ": polygonArea " .. plain)
      end
    end)
  end)

  it("have a centroid exactly when the area is not zero, and the right one", function()
    each(function(name, p, _, _, zero)
      local cx, cy = polygon.polygonCentroid(p)
      if zero then
        assert.is_nil(cx, name)
        assert.is_nil(cy, name)
      else
        local ex, ey = oracle.centroid(p)
        local tol = 2 ^ -44 * (extent(p) + math.abs(p[1]) + math.abs(p[2]))
        assert.is_true(math.abs(cx - ex) <= tol and math.abs(cy - ey) <= tol,
          ("%s: centroid %.17g, %.17g, expected %.17g, %.17g"):format(name, cx, cy, ex, ey))
      end
    end)
  end)

  it("never collide when their area is zero, with polygons or circles covering them", function()
    each(function(name, p, kind, _, zero)
      if zero and kind ~= "concave" then
        local cx, cy = oracle.center(p)
        local r = 4 * extent(p) + 1
        local cover = { cx - r, cy - r, cx + r, cy - r, cx + r, cy + r, cx - r, cy + r }
        for _, pair in ipairs({ { p, cover }, { cover, p }, { p, p } }) do
          local a, b = pair[1], pair[2]
          assert.is_false(oracle.collides(a, b, true), name .. ": oracle")
          assert.is_false(polygon.polygonsCollide(a, b), name .. ": polygonsCollide")
          assert.is_false(polygon.polygonCollidesWith(a, b), name .. ": polygonCollidesWith")
          assert.is_false(polygon.polygonsCollideV(a, b), name .. ": polygonsCollideV")
          assert.is_false(polygon.polygonCollidesWithV(a, b), name .. ": polygonCollidesWithV")
        end
        assert.is_false(polygon.polygonCircleCollideV(p, cx, cy, r), name .. ": polygonCircleCollideV")
      end
    end)
  end)

  it("collide as their distinct vertices do when they repeat vertices or run collinear", function()
    -- the square 0..10 overlapped by 2 from the right by b = [8, 18] x [1, 9]: depth 2 along x
    local b = { 8, 1, 18, 1, 18, 9, 8, 9 }
    local touching = { 10, 0, 20, 0, 20, 10, 10, 10 }
    each(function(name, p, kind, _, zero)
      if not zero and kind == "convex" and name:find("square") and not name:find("far") then
        assert.is_true(oracle.collides(p, b, true), name)
        assert.is_true(polygon.polygonsCollide(p, b), name .. ": polygonsCollide")
        assert.is_true(polygon.polygonCollidesWith(p, b), name .. ": polygonCollidesWith")
        local o, dx, dy = polygon.polygonsCollideV(p, b)
        -- b leaves along +x by max1 - min2 = 10 - 8 = 2
        assert.are.same({ 2, 2, 0 }, { o, dx, dy }, name .. ": polygonsCollideV")
        o, dx, dy = polygon.polygonsCollideV(b, p)
        assert.are.same({ 2, -2, 0 }, { o, dx, dy }, name .. ": polygonsCollideV swapped")
        assert.is_false(polygon.polygonsCollide(p, touching), name .. ": touching")
        assert.is_false(polygon.polygonsCollideV(touching, p), name .. ": touching V")
      end
    end)
  end)
end)
