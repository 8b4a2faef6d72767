-- Hard cases, family 3: points on edges, on vertices, on horizontal edges, and one and two ulps
-- to either side of them (polygonContains against the exact crossing rule of the oracle).
--
-- The polygons have slanted edges whose lines pass between doubles almost everywhere, edges with
-- exactly representable points (coordinates on a coarse dyadic grid), horizontal and vertical
-- edges, in both windings and near and far from the origin. Test points are x1 + t (x2 - x1),
-- y1 + t (y2 - y1) as rounded, and the same moved by one and two ulps in x and in y; the oracle
-- says which are exactly on an edge, which on a vertex, and the inside/outside of every one.

local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local probe = require "probe"
local tally = require "tally"
local shapes = require "shapes"

local reversed, shifted = shapes.reverse, shapes.translate

-- The naive crossing test, dividing for the edge's x at height y: the tutorial's own
-- (bench/baseline.lua, the one transcription of the tutorial).
local naiveContains = require("bench.baseline").polygonContains

-- Hand-made shapes: a triangle with slanted sides whose slopes are not dyadic, a trapezoid with
-- two horizontal edges, a concave arrow with horizontal and vertical edges, a thin sliver.
local SHAPES = {
  triangle = { 0.1, 0.2, 3.7, 1.3, 1.9, 4.3 },
  trapezoid = { 1, 1, 6, 1, 5, 3, 2, 3 },
  arrow = { 0, 3, 4, 3, 4, 0, 9, 4, 4, 8, 4, 5, 0, 5 },
  sliver = { 0, 0, 10, 1e-9, 10.000000001, 3e-9 },
  grid = { 0.25, 0.5, 4.75, 1.25, 3.5, 5.125, 0.75, 4.5 },
}

-- Random shapes: triangles and convex quadrilaterals with random doubles, and the same snapped to
-- a grid of 1/8 so that quarter points of edges are exactly on them.
local function randomShapes(seed, count)
  local r = prng.new(seed)
  local list = {}
  for k = 1, count do
    local snap = k % 2 == 0
    local pts = {}
    local m = 3 + k % 2
    for i = 1, m do
      -- corners roughly around a circle, so quadrilaterals come out convex
      local angle = (i - 1 + r:range(-0.3, 0.3)) * 2 * math.pi / m
      local radius = r:range(2, 6)
      local x, y = radius * math.cos(angle), radius * math.sin(angle)
      if snap then
        x, y = math.floor(x * 8) / 8, math.floor(y * 8) / 8
      end
      pts[2 * i - 1], pts[2 * i] = x, y
    end
    list[#list + 1] = pts
  end
  return list
end

local function allCases()
  local cases = {}
  local function add(name, points)
    cases[#cases + 1] = { name = name, points = points }
    cases[#cases + 1] = { name = name .. " reversed", points = reversed(points) }
  end
  for name, points in pairs(SHAPES) do
    add(name, points)
    add(name .. " at 1e6", shifted(points, 1e6, -2.5e6))
  end
  for k, points in ipairs(randomShapes(4242, 24)) do
    add("random " .. k, points)
  end
  table.sort(cases, function(a, b) return a.name < b.name end)
  return cases
end

describe("points on and one or two ulps beside edges and vertices", function()
  local cases = allCases()

  it("are inside exactly when the exact crossing rule says so", function()
    local t = tally.new("polygonContains vs oracle")
    local naive = tally.new("naive contains vs oracle")
    local onEdge, onVertex, onHorizontal, checked = 0, 0, 0, 0
    for _, case in ipairs(cases) do
      local p = case.points
      local object = polygon.Polygon(p)
      local vertices = {}
      for i = 1, #p - 1, 2 do vertices[("%.17g,%.17g"):format(p[i], p[i + 1])] = true end
      for _, q in ipairs(probe.pointsNear(p, { 0, 1 / 3, 0.25, 0.5, 0.75 })) do
        local x, y = q[1], q[2]
        local expected = oracle.contains(p, x, y)
        checked = checked + 1
        if oracle.onBoundary(p, x, y) then
          if vertices[("%.17g,%.17g"):format(x, y)] then
            onVertex = onVertex + 1
          else
            onEdge = onEdge + 1
          end
          for _, e in ipairs(probe.edges(p)) do
            if e[2] == e[4] and e[2] == y and oracle.onSegment(e[1], e[2], e[3], e[4], x, y) then
              onHorizontal = onHorizontal + 1
            end
          end
        end
        t:check(polygon.polygonContains(p, x, y) == expected, case.name, x, y, "expected", expected)
        t:check(object:contains(x, y) == expected, case.name, "Polygon:contains", x, y)
        naive:check(naiveContains(p, x, y) == expected)
      end
    end
    naive:report((" (on edges %d, on vertices %d, on horizontal edges %d)")
      :format(onEdge, onVertex, onHorizontal))
    assert.are.equal(0, t.count, t:message())
    -- the cases really include what they claim to
    assert.is_true(onEdge > 100, "points exactly on edges: " .. onEdge)
    assert.is_true(onVertex > 50, "points on vertices: " .. onVertex)
    assert.is_true(onHorizontal > 20, "points on horizontal edges: " .. onHorizontal)
    assert.is_true(checked > 3000)
    assert.is_true(naive.count > 0, "the naive division should misplace some of these points")
  end)

  it("are placed the same way when every coordinate is 2^60 times as large", function()
    -- Scaling by a power of two is exact and keeps every answer. There |y| >= 2^53 for almost
    -- every point, which on the PUC interpreters takes the walk that LuaJIT always takes (the
    -- one whose comparisons are computed as numbers).
    local t = tally.new("polygonContains vs oracle, scaled by 2^60")
    local checked, far = 0, 0
    for _, case in ipairs(cases) do
      local p = {}
      for i = 1, #case.points do p[i] = case.points[i] * 2 ^ 60 end
      for _, q in ipairs(probe.pointsNear(p, { 0, 0.25, 0.5 })) do
        local x, y = q[1], q[2]
        checked = checked + 1
        if y >= 2 ^ 53 or y <= -2 ^ 53 then far = far + 1 end
        t:check(polygon.polygonContains(p, x, y) == oracle.contains(p, x, y), case.name, x, y)
      end
    end
    assert.are.equal(0, t.count, t:message())
    assert.is_true(far > 1000, "points beyond 2^53: " .. far .. " of " .. checked)
  end)

  it("are placed the same way on either side of the PUC interpreters' switch at 2^53", function()
    -- Scaled by 2^49 and 2^50 the coordinates reach about 2^52 to 2^54: on the PUC interpreters
    -- a point with x^2 + y^2 < 2^106 (so |x|, |y| < 2^53) takes the walk that compares x and y
    -- with unconverted coordinates, any other point the walk that LuaJIT always takes.
    local t = tally.new("polygonContains vs oracle, scaled by 2^49 and 2^50")
    local near, far = 0, 0
    for _, scale in ipairs({ 2 ^ 49, 2 ^ 50 }) do
      for _, case in ipairs(cases) do
        local p = {}
        for i = 1, #case.points do p[i] = case.points[i] * scale end
        for _, q in ipairs(probe.pointsNear(p, { 0, 0.25, 0.5 })) do
          local x, y = q[1], q[2]
          if x * x + y * y < 2 ^ 106 then near = near + 1 else far = far + 1 end
          t:check(polygon.polygonContains(p, x, y) == oracle.contains(p, x, y), case.name, scale, x, y)
        end
      end
    end
    assert.are.equal(0, t.count, t:message())
    assert.is_true(near > 1000 and far > 1000, ("points on either side: %d, %d"):format(near, far))
  end)

  it("are placed the same way when every coordinate is 2^-440 times as large", function()
    -- near the small end of the exact range: differences of heights down to about 2^-490, which
    -- the LuaJIT walk scales by 2^600 and compares with 0 or 2^-500 to tell the sides apart.
    -- Points moved off 0 by an ulp (subnormal, below the exact range's 2^-447) are left out.
    local function inRange(v) return v == 0 or math.abs(v) >= 2 ^ -447 end
    local t = tally.new("polygonContains vs oracle, scaled by 2^-440")
    local checked = 0
    for _, case in ipairs(cases) do
      local p = {}
      for i = 1, #case.points do p[i] = case.points[i] * 2 ^ -440 end
      for _, q in ipairs(probe.pointsNear(p, { 0, 0.25, 0.5 })) do
        local x, y = q[1], q[2]
        if inRange(x) and inRange(y) then
          checked = checked + 1
          t:check(polygon.polygonContains(p, x, y) == oracle.contains(p, x, y), case.name, x, y)
        end
      end
    end
    assert.are.equal(0, t.count, t:message())
    assert.is_true(checked > 5000, "points checked: " .. checked)
  end)

  it("follow the half-open rule on horizontal edges and at vertices (hand-computed)", function()
    -- trapezoid (1,1) (6,1) (5,3) (2,3): the top edge y = 1 is outside, the bottom edge y = 3
    -- inside between its ends; the left side is x = 1 + (y - 1) / 2, the right one
    -- x = 6 - (y - 1) / 2, so at y = 2 they are at x = 1.5 and x = 5.5.
    local trapezoid = SHAPES.trapezoid
    local cases2 = {
      { 3, 1, false }, -- on the top edge
      { 3, 3, true }, -- on the bottom edge
      { 2, 3, false }, -- bottom-left vertex: crossing of x = 2 and x = 5 both count, even
      { 5, 3, true }, -- bottom-right vertex: only the right side counts (5 <= 5), odd
      { 1, 1, false }, { 6, 1, false }, -- top vertices: no edge crosses y = 1 half-openly
      { 1.5, 2, false }, -- on the left side: both sides count
      { 5.5, 2, true }, -- on the right side: only the right one
      { 1.4999999999999998, 2, false }, { 5.5000000000000009, 2, false },
      { 1.5000000000000002, 2, true }, { 5.4999999999999991, 2, true },
    }
    for _, c in ipairs(cases2) do
      assert.are.equal(c[3], oracle.contains(trapezoid, c[1], c[2]), "oracle at " .. c[1] .. ", " .. c[2])
      local at = c[1] .. ", " .. c[2]
      assert.are.equal(c[3], polygon.polygonContains(trapezoid, c[1], c[2]), "library at " .. at)
      assert.are.equal(c[3], polygon.polygonContains(reversed(trapezoid), c[1], c[2]), "reversed")
    end
  end)
end)
