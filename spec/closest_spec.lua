-- Issue 30, closest points: polygonClosestPoint on convex and concave polygons. Hand-computed
-- cases, the refusals, hard cases (on the boundary and one ulp either side, at vertices, on the
-- medial axis where two edges tie and one ulp off it, far away) at offsets 0, 1e6 + 0.5, 1e9 and
-- 1e12, then random cases against the exact oracle (spec/support/nearest.lua).
local polygon = require "polygon"
local nearest = require "nearest"
local exact = require "exact"
local prng = require "prng"
local shapes = require "shapes"
local tiles = require "tiles"
local callsite = require "callsite"
local closestModule = require "polygon.closest"

local closest = polygon.polygonClosestPoint
local nextUp, nextDown = exact.nextUp, exact.nextDown

local OFFSETS = { 0, 1e6 + 0.5, 1e9, 1e12 }

-- polygonClosestPoint against the oracle; returns its answer.
local function checked(points, x, y)
  local px, py, d = closest(points, x, y)
  local ok, why = nearest.check(points, x, y, px, py, d)
  assert(ok, ("%s for (%.17g, %.17g): got (%.17g, %.17g), %.17g"):format(tostring(why), x, y, px, py, d))
  return px, py, d
end

local function moved(points, o) return shapes.translate(points, o, o) end

local SQUARE = { 0, 0, 10, 0, 10, 10, 0, 10 }
local L = { 0, 0, 20, 0, 20, 10, 10, 10, 10, 20, 0, 20 }   -- reflex corner at (10, 10)
local TRIANGLE = { 0, 0, 8, 0, 0, 6 }                       -- hypotenuse 3x + 4y = 24

describe("polygonClosestPoint", function()
  describe("when computed by hand", function()
    it("finds the foot on an edge, outside positive and inside negative", function()
      assert.are.same({ 5, 0, 3 }, { closest(SQUARE, 5, -3) })
      assert.are.same({ 5, 0, -3 }, { closest(SQUARE, 5, 3) })
      -- (8, 6) from the hypotenuse: 3 * 8 + 4 * 6 - 24 = 24, over |(3, 4)| = 5: 4.8, at
      -- (8, 6) - 4.8 (0.6, 0.8) = (5.12, 2.16)
      local px, py, d = closest(TRIANGLE, 8, 6)
      assert.is_true(math.abs(px - 5.12) < 1e-14 and math.abs(py - 2.16) < 1e-14)
      assert.is_true(math.abs(d - 4.8) < 1e-14)
    end)

    it("finds a vertex from beyond it, and answers 0 on the boundary", function()
      -- (13, 14) - (10, 10) = (3, 4): 5
      assert.are.same({ 10, 10, 5 }, { closest(SQUARE, 13, 14) })
      assert.are.same({ 10, 5, 0 }, { closest(SQUARE, 10, 5) })
      assert.are.same({ 0, 0, 0 }, { closest(SQUARE, 0, 0) })
    end)

    it("works for concave polygons, a segment and a point", function()
      -- in the L's notch, 5 from both edges at the reflex corner
      local px, py, d = closest(L, 15, 15)
      assert.are.equal(5, d)
      assert.is_true((px == 15 and py == 10) or (px == 10 and py == 15))
      -- inside the L's arm: 2 from x = 0
      assert.are.same({ 0, 5, -2 }, { closest(L, 2, 5) })
      assert.are.same({ 4, 3, 5 }, { closest({ 0, 0, 4, 3 }, 8, 6) })
      assert.are.same({ 3, 4, 5 }, { closest({ 3, 4 }, 0, 0) })
      assert.are.same({ 5, 0, 3 }, { closest(polygon.Polygon(SQUARE), 5, -3) })
    end)

    it("refuses what is not a polygon, at the caller's line", function()
      assert.has_error(function() closest({}, 0, 0) end,
        "polygonClosestPoint: points is empty; a polygon needs at least 1 point")
      assert.has_error(function() closest({ SQUARE }, 0, 0) end,
        "polygonClosestPoint: points is a list of parts; it takes one polygon (pass the outline the "
        .. "parts were made from)")
      assert.has_error(function() closest({ { x = 0, y = 0 } }, 0, 0) end,
        "polygonClosestPoint: points holds point tables; pass a flat array {x1, y1, x2, y2, ...}")
      assert.has_error(function() closest({ 0, 0, 1 }, 0, 0) end,
        "polygonClosestPoint: points must hold an even number of coordinates, got 3")
      assert.has_error(function() closest({ 0, 0, 0 / 0, 1 }, 0, 0) end,
        "polygonClosestPoint: points holds a non-finite coordinate")
      assert.has_error(function() closest(SQUARE, 0, 1 / 0) end,
        "polygonClosestPoint: y must be finite, got inf")
      assert.has_error(function() closest(nil, 0, 0) end,
        "polygonClosestPoint: points must be a table, got nil")
      for _, args in ipairs({ { {}, 0, 0 }, { { SQUARE }, 0, 0 }, { SQUARE, "x", 0 }, { nil, 0, 0 },
          { { 0, 0, 0 / 0, 1 }, 0, 0 } }) do
        local ok, err = callsite.raisesAtCaller(closest, args)
        assert.is_true(ok, err)
      end
    end)
  end)
end)

describe("polygonClosestPoint, hard cases: on the boundary and one ulp either side", function()
  for _, o in ipairs(OFFSETS) do
    it("answers 0 exactly on edges and vertices, a tiny signed distance beside them (offset "
        .. o .. ")", function()
      local sq, tri = moved(SQUARE, o), moved(TRIANGLE, o)
      assert.are.same({ o + 10, o + 5, 0 }, { checked(sq, o + 10, o + 5) })
      assert.are.same({ o, o, 0 }, { checked(sq, o, o) })
      local _, _, d = checked(sq, nextDown(o + 10), o + 5)
      assert.is_true(d < 0)
      _, _, d = checked(sq, nextUp(o + 10), o + 5)
      assert.is_true(d > 0)
      -- the hypotenuse through (4, 3): on it, and one ulp either side
      assert.are.same({ o + 4, o + 3, 0 }, { checked(tri, o + 4, o + 3) })
      checked(tri, nextUp(o + 4), o + 3)
      checked(tri, nextDown(o + 4), o + 3)
      checked(tri, o + 4, nextUp(o + 3))
    end)
  end
end)

describe("polygonClosestPoint, hard cases: ties between edges", function()
  for _, o in ipairs(OFFSETS) do
    it("takes either edge at a tie and the nearer one an ulp off it (offset " .. o .. ")", function()
      local sq, l = moved(SQUARE, o), moved(L, o)
      checked(sq, o + 5, o + 5)                   -- the centre: four edges tie
      checked(sq, nextUp(o + 5), o + 5)
      checked(sq, o + 5, nextDown(o + 5))
      checked(sq, o + 2, o + 2)                   -- on a diagonal: two edges tie
      checked(sq, nextUp(o + 2), o + 2)
      checked(l, o + 15, o + 15)                  -- the notch's bisector
      checked(l, nextUp(o + 15), o + 15)
      checked(l, o + 15, nextUp(o + 15))
      checked(l, o + 12, o + 12)
      checked(l, nextDown(o + 12), o + 12)
    end)

    it("is right far away and at every vertex (offset " .. o .. ")", function()
      local l = moved(L, o)
      checked(l, o - 1e5, o + 3)
      checked(l, o + 7, o + 1e7)
      for i = 1, #l, 2 do checked(l, l[i], l[i + 1]) end
    end)
  end
end)

describe("polygonClosestPoint, random cases against the oracle", function()
  it("agrees on random convex and star-shaped polygons, points near their edges too", function()
    local rng = prng.new(3101)
    for round = 1, 200 do
      local o = OFFSETS[round % #OFFSETS + 1]
      local size = rng:pick({ 1, 10, 1000 })
      local points = round % 2 == 0 and shapes.convex(rng, rng:int(3, 9), o, o, size, 0.4)
        or shapes.star(rng, rng:int(3, 12), o, o, size)
      for _ = 1, 4 do
        local x, y = o + rng:range(-2, 2) * size, o + rng:range(-2, 2) * size
        if rng:float() < 0.4 then   -- on an edge's line near the edge, or an ulp off a vertex
          local k = 2 * rng:int(1, #points / 2) - 1
          local j = (k + 1) % #points + 1
          local u = rng:range(-0.2, 1.2)
          x = points[k] + u * (points[j] - points[k])
          y = points[k + 1] + u * (points[j + 1] - points[k + 1])
          if rng:float() < 0.3 then x, y = nextUp(points[k]), points[k + 1] end
        end
        checked(points, x, y)
      end
    end
  end)

  it("agrees on tile outlines at integer and half-integer points", function()
    local rng = prng.new(3102)
    for round = 1, 40 do
      local o = OFFSETS[round % #OFFSETS + 1]
      local set = tiles.random(rng, 4, 4, 0.6)
      for _, ring in ipairs(tiles.loops(set, 10, o, o)) do
        for _ = 1, 5 do
          checked(ring, o + 2.5 * rng:int(-4, 20), o + 2.5 * rng:int(-4, 20))
        end
      end
    end
  end)
end)

describe("polygonClosestPoint, random near ties against the oracle", function()
  -- the distance to the closed segment a -> b in floating point (for placing points only)
  local function segmentDistance(ax, ay, bx, by, x, y)
    local ex, ey = bx - ax, by - ay
    local u = ((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey)
    u = math.max(0, math.min(1, u))
    local dx, dy = x - (ax + u * ex), y - (ay + u * ey)
    return math.sqrt(dx * dx + dy * dy)
  end

  it("agrees where two edges are within rounding of equally near, and an ulp either side", function()
    local rng = prng.new(3103)
    local tried = 0
    for round = 1, 400 do
      local o = OFFSETS[round % #OFFSETS + 1]
      local size = rng:pick({ 0.3, 7, 300 })
      local points = round % 2 == 0 and shapes.convex(rng, rng:int(3, 8), o, o, size, 0.4)
        or shapes.star(rng, rng:int(4, 9), o, o, size)
      local m = #points / 2
      local i, j = rng:int(1, m), rng:int(1, m)
      if i ~= j then
        local function edgeGap(x, y)
          local a, b = 2 * i - 1, 2 * (i % m) + 1
          local c, d = 2 * j - 1, 2 * (j % m) + 1
          return segmentDistance(points[a], points[a + 1], points[b], points[b + 1], x, y)
            - segmentDistance(points[c], points[c + 1], points[d], points[d + 1], x, y)
        end
        -- along a random line through the middle, where the two distances cross (bisection)
        local t = rng:range(0, 2 * math.pi)
        local vx, vy = math.cos(t) * size, math.sin(t) * size
        local lo, hi = -2.0, 2.0
        local glo = edgeGap(o + lo * vx, o + lo * vy)
        if glo * edgeGap(o + hi * vx, o + hi * vy) < 0 then
          for _ = 1, 80 do
            local mid = (lo + hi) / 2
            local g = edgeGap(o + mid * vx, o + mid * vy)
            if (g < 0) == (glo < 0) then lo, glo = mid, g else hi = mid end
          end
          local x, y = o + lo * vx, o + lo * vy
          tried = tried + 1
          for _, q in ipairs({ { x, y }, { nextUp(x), y }, { nextDown(x), y }, { x, nextUp(y) },
              { x, nextDown(y) } }) do
            checked(points, q[1], q[2])
          end
        end
      end
    end
    assert.is_true(tried > 100)
  end)
end)

-- The two bodies of the nearest edge's search (LuaJIT's without branches, PUC Lua's), each on
-- every interpreter: the same edge, squared distance, bound and least lower bound of the others.
describe("polygonClosestPoint's two bodies", function()
  it("find the same nearest edge with the same numbers", function()
    local rng = prng.new(3104)
    for round = 1, 300 do
      local o = OFFSETS[round % #OFFSETS + 1]
      local size = rng:pick({ 1, 10, 1000 })
      local points = round % 2 == 0 and shapes.convex(rng, rng:int(3, 9), o, o, size, 0.4)
        or shapes.star(rng, rng:int(3, 12), o, o, size)
      if round % 5 == 0 then   -- a repeated vertex: an edge of no length
        table.insert(points, 3, points[2])
        table.insert(points, 3, points[1])
      end
      for _ = 1, 4 do
        local x, y = o + rng:range(-2, 2) * size, o + rng:range(-2, 2) * size
        if rng:float() < 0.3 then x, y = points[1], points[2] end
        local jit = { closestModule.nearestEdgeJit(points, #points, x, y) }
        local puc = { closestModule.nearestEdgePuc(points, #points, x, y) }
        assert.are.same(puc, jit)
      end
    end
  end)
end)
