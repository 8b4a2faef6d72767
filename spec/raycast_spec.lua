-- Issue 30, rays: polygonRayCast against convex polygons and lists of parts, circleRayCast
-- against discs (spec/rayring_spec.lua: flat polygons of any shape). Hand-computed cases, the
-- refusals, the hard cases (grazing, along edges and one ulp either side, ending on the
-- boundary, starting on it, starting inside, along seams, tangents), each at offsets 0,
-- 1e6 + 0.5, 1e9 and 1e12, then random cases against the oracle (spec/support/rays.lua, exact
-- arithmetic sharing nothing with the library).
local polygon = require "polygon"
local rays = require "rays"
local exact = require "exact"
local prng = require "prng"
local shapes = require "shapes"
local tiles = require "tiles"
local parts = require "parts"
local callsite = require "callsite"
local rayring = require "polygon.rayring"
local oracle = require "oracle"

local cast, circleCast = polygon.polygonRayCast, polygon.circleRayCast
local nextUp, nextDown = exact.nextUp, exact.nextDown
local EPS = 2 ^ -53

local OFFSETS = { 0, 1e6 + 0.5, 1e9, 1e12 }

-- A flat array moved by (o, o) (exact for the shapes below at every offset).
local function moved(points, o)
  return shapes.translate(points, o, o)
end

-- A list of parts moved by (o, o).
local function movedList(list, o)
  return shapes.translateEach(list, o, o)
end

-- The library's answer against the oracle's for the segment A -> B: `entry` is nil (a miss),
-- "inside" or an entry; `result` what polygonRayCast or its like returned. Returns ok, message.
local function agrees(entry, f, nx, ny, ax, ay, bx, by)
  local where = ("(%.17g, %.17g) -> (%.17g, %.17g)"):format(ax, ay, bx, by)
  if entry == nil then
    return f == false and nx == nil, ("expected a miss for %s, got %s, %s, %s"):format(where,
      tostring(f), tostring(nx), tostring(ny))
  end
  if entry == "inside" then
    return f == 0 and nx == 0 and ny == 0, ("expected 0, 0, 0 for %s, got %s, %s, %s"):format(where,
      tostring(f), tostring(nx), tostring(ny))
  end
  if type(f) ~= "number" then
    return false, ("expected a hit at %s for %s, got %s"):format(
      exact.tostring(exact.mul(entry.num, exact.pow2(0))), where, tostring(f))
  end
  if not rays.fractionGood(f, entry, ax, ay, bx, by) then
    return false, ("fraction %.17g off the exact one (%s / %s) for %s"):format(f,
      exact.tostring(entry.num), exact.tostring(entry.den), where)
  end
  if not rays.normalGood(nx, ny, entry.normals) then
    local allowed = {}
    for _, m in ipairs(entry.normals) do allowed[#allowed + 1] = ("(%.17g, %.17g)"):format(m[1], m[2]) end
    return false, ("normal (%.17g, %.17g) is none of %s for %s"):format(nx, ny,
      table.concat(allowed, ", "), where)
  end
  return true
end

-- polygonRayCast on a convex polygon against rays.convexEntry.
local function checkConvex(points, ax, ay, bx, by)
  local f, nx, ny = cast(points, ax, ay, bx, by)
  local entry
  if ax == bx and ay == by then
    entry = rays.convexInside(points, ax, ay) and "inside" or nil
  else
    entry = rays.convexEntry(points, ax, ay, bx, by)
  end
  local ok, message = agrees(entry, f, nx, ny, ax, ay, bx, by)
  assert(ok, message)
  return f, nx, ny
end

-- polygonRayCast on a list of parts against rays.ringsEntry over the rings that bound it.
local function checkList(list, rings, ax, ay, bx, by, sides)
  local f, nx, ny = cast(list, ax, ay, bx, by)
  local ok, message = agrees(rays.ringsEntry(rings, ax, ay, bx, by, sides), f, nx, ny, ax, ay, bx, by)
  assert(ok, message)
  return f, nx, ny
end

-- circleRayCast against rays.discMeets and rays.discEntryGood.
local function checkDisc(cx, cy, r, ax, ay, bx, by)
  local f, nx, ny = circleCast(cx, cy, r, ax, ay, bx, by)
  local where = ("disc (%.17g, %.17g, %.17g), (%.17g, %.17g) -> (%.17g, %.17g)"):format(cx, cy, r,
    ax, ay, bx, by)
  local meets = rays.discMeets(cx, cy, r, ax, ay, bx, by)
  if meets == nil then
    assert(f == false, "expected a miss: " .. where .. ", got " .. tostring(f))
  elseif meets == "inside" then
    assert(f == 0 and nx == 0 and ny == 0, "expected 0, 0, 0: " .. where)
  else
    assert(type(f) == "number", "expected a hit: " .. where)
    local good, what = rays.discEntryGood(f, nx, ny, cx, cy, r, ax, ay, bx, by)
    assert(good, ("%s off (%.17g, %.17g, %.17g): %s"):format(what, f, nx, ny, where))
  end
  return f, nx, ny
end

local SQUARE = { 0, 0, 10, 0, 10, 10, 0, 10 }          -- clockwise on screen
local SQUARE_CCW = { 0, 0, 0, 10, 10, 10, 10, 0 }
local TRIANGLE = { 0, 0, 8, 0, 0, 6 }                   -- hypotenuse 3x + 4y = 24
-- two tiles side by side and their outline
local TILES = { { 0, 0, 10, 0, 10, 10, 0, 10 }, { 10, 0, 20, 0, 20, 10, 10, 10 } }
local TILES_OUTLINE = { 0, 0, 20, 0, 20, 10, 0, 10 }
-- an L of three tiles: its reflex corner at (10, 10)
local L3 = { { 0, 0, 10, 0, 10, 10, 0, 10 }, { 10, 0, 20, 0, 20, 10, 10, 10 },
  { 0, 10, 10, 10, 10, 20, 0, 20 } }
local L3_OUTLINE = { 0, 0, 20, 0, 20, 10, 10, 10, 10, 20, 0, 20 }

describe("polygonRayCast", function()
  describe("when computed by hand", function()
    it("enters a square through the edge it crosses, with that edge's outward normal", function()
      -- x from -5 to 15 at y = 5 meets x = 0 at t = (0 - -5) / 20 = 0.25; the left edge's normal
      -- points to -x
      local f, nx, ny = cast(SQUARE, -5, 5, 15, 5)
      assert.are.equal(0.25, f)
      assert.are.same({ -1, 0 }, { nx, ny })
      -- the other way: x = 10 at t = (15 - 10) / 20 = 0.25, normal +x
      f, nx, ny = cast(SQUARE, 15, 5, -5, 5)
      assert.are.equal(0.25, f)
      assert.are.same({ 1, 0 }, { nx, ny })
      -- either winding
      f, nx, ny = cast(SQUARE_CCW, -5, 5, 15, 5)
      assert.are.equal(0.25, f)
      assert.are.equal(-1, nx)
      assert.are.equal(0, ny)
    end)

    it("enters a triangle through its hypotenuse", function()
      -- from (8, 6) towards (0, 0): P(t) = (8 - 8t, 6 - 6t) meets 3x + 4y = 24 where
      -- 24 - 24t + 24 - 24t = 24, t = 0.5, at (4, 3); the outward normal (3, 4) / 5
      local f, nx, ny = cast(TRIANGLE, 8, 6, 0, 0)
      assert.are.equal(0.5, f)
      assert.is_true(math.abs(nx - 0.6) <= 2 * EPS and math.abs(ny - 0.8) <= 2 * EPS)
    end)

    it("answers false for a segment that stops short, passes by or points away", function()
      assert.are.equal(false, cast(SQUARE, -5, 5, -1, 5))
      assert.are.equal(false, cast(SQUARE, -5, 15, 15, 15))
      assert.are.equal(false, cast(SQUARE, -5, 5, -15, 5))
      local f, nx = cast(SQUARE, -5, 5, -15, 5)
      assert.are.equal(false, f)
      assert.is_nil(nx)   -- false alone
    end)

    it("gives 0, 0, 0 for a segment that starts strictly inside, a point inside too", function()
      assert.are.same({ 0, 0, 0 }, { cast(SQUARE, 5, 5, 50, 7) })
      assert.are.same({ 0, 0, 0 }, { cast(SQUARE, 5, 5, 5, 5) })
      assert.are.same({ false }, { cast(SQUARE, 10, 5, 10, 5) })   -- on the boundary: not inside
    end)

    it("enters a list of tiles where it crosses the outline, never at a seam", function()
      -- across both tiles: in at x = 0, t = 5 / 30; the seam at x = 10 does not count
      local f, nx, ny = cast(TILES, -5, 5, 25, 5)
      assert.are.equal(5 / 30, f)
      assert.are.same({ -1, 0 }, { nx, ny })
      -- from inside the second tile back across the seam and out: inside
      assert.are.same({ 0, 0, 0 }, { cast(TILES, 15, 5, -5, 5) })
      -- along the seam x = 10 from y = -10 to 20: in where the seam meets the outline, y = 0,
      -- t = 10 / 30, through the bottom (normal -y: y grows downwards, the outline's top edge)
      f, nx, ny = cast(TILES, 10, -10, 10, 20)
      assert.are.equal(10 / 30, f)
      assert.are.same({ 0, -1 }, { nx, ny })
    end)

    it("enters an L of tiles at its reflex corner with an edge of the outline there", function()
      -- from (20, 20) towards (0, 0): the corner (10, 10) at t = 0.5, entering the tile at the
      -- origin; its own edges there are seams, the outline's are x = 10 (normal +x) and y = 10
      -- (normal +y)
      local f, nx, ny = cast(L3, 20, 20, 0, 0)
      assert.are.equal(0.5, f)
      assert.is_true((nx == 1 and ny == 0) or (nx == 0 and ny == 1), nx .. ", " .. ny)
    end)

    it("gives a normal's zero component as 0, not -0, whichever the winding", function()
      -- the wall x in [100, 140] both ways round, and with a second part out to x = 150:
      -- from (0, 50) to (200, 50) in at x = 100, t = 100 / 200, normal (-1, 0); from (300, 50)
      -- to (0, 50) in at x = 140, t = (300 - 140) / 300 (150: t = 150 / 300), normal (1, 0)
      local wall = { 100, 0, 140, 0, 140, 200, 100, 200 }
      local walls = {
        { wall, 160 / 300 },
        { { 100, 0, 100, 200, 140, 200, 140, 0 }, 160 / 300 },
        { { wall, { 140, 0, 150, 0, 150, 200, 140, 200 } }, 150 / 300 },
      }
      for _, shape in ipairs(walls) do
        local f, nx, ny = cast(shape[1], 0, 50, 200, 50)
        assert.are.same({ 0.5, -1, "0" }, { f, nx, ("%g"):format(ny) })
        f, nx, ny = cast(shape[1], 300, 50, 0, 50)
        assert.are.same({ shape[2], 1, "0" }, { f, nx, ("%g"):format(ny) })
      end
      local f, nx, ny = polygon.circleRayCast(0, 0, 1, 0, -3, 0, 3)   -- in at (0, -1), t = 2 / 6
      assert.are.same({ 2 / 6, "0", -1 }, { f, ("%g"):format(nx), ny })
    end)
  end)

  describe("when given what the collision functions refuse", function()
    local BOX = { 50, 10, 70, 10, 70, 30, 50, 30 }
    it("refuses a list holding a concave part, naming the vertex and the fix", function()
      local L = { 0, 0, 100, 0, 100, 20, 20, 20, 20, 100, 0, 100 }
      assert.has_error(function() cast({ BOX, L }, 0, 0, 1, 1) end,
        "polygonRayCast: points[2] is not convex (a reflex turn at vertex 4); split it once with "
        .. "polygonConvexParts and pass the parts")
      -- flat, the same L is taken as it is: along y = 50 from x = 110 to -10 the ray passes the
      -- notch and enters the arm 0 < x < 20 at x = 20, t = (110 - 20) / 120 = 0.75, through the
      -- edge (20, 20) -> (20, 100), outward normal (1, 0)
      assert.are.same({ 0.75, 1, 0 }, { cast(L, 110, 50, -10, 50) })
    end)

    it("refuses fewer than 3 points, point tables and strings", function()
      assert.has_error(function() cast({ 0, 0, 100, 100 }, 0, 0, 1, 1) end,
        "polygonRayCast: points has 2 points: a segment; a polygon needs at least 3")
      assert.has_error(function() cast({}, 0, 0, 1, 1) end,
        "polygonRayCast: points is empty; a polygon needs at least 3 points")
      local pointTables = { { x = 0, y = 0 }, { x = 1, y = 0 }, { x = 1, y = 1 } }
      assert.has_error(function() cast(pointTables, 0, 0, 1, 1) end,
        "polygonRayCast: points holds point tables; pass a flat array {x1, y1, x2, y2, ...}")
      assert.has_error(function() cast({ "0", "0", "1", "0", "1", "1" }, 0, 0, 1, 1) end,
        "polygonRayCast: points[1] must be a number, got string")
      assert.has_error(function() cast({ BOX, { 0, 0, 1, 1 } }, 0, 0, 1, 1) end,
        "polygonRayCast: points[2] has 2 points: a segment; a polygon needs at least 3")
      assert.has_error(function() cast(nil, 0, 0, 1, 1) end,
        "polygonRayCast: points must be a table, got nil")
    end)

    it("refuses non-finite coordinates and ends", function()
      assert.has_error(function() cast({ 0, 0, 0 / 0, 0, 1, 1 }, 0, 0, 1, 1) end,
        "polygonRayCast: points holds a non-finite coordinate")
      assert.has_error(function() cast(BOX, 0, 0, 1 / 0, 1) end, "polygonRayCast: x2 must be finite, got inf")
      assert.has_error(function() cast({ BOX }, 0, "a", 1, 1) end,
        "polygonRayCast: y1 must be a number, got string")
    end)

    it("raises at the caller's line, and takes a Polygon object for its points", function()
      -- (a NaN vertex found by the sides' walk, and by the test of a segment of no length)
      for _, args in ipairs({ { { 0, 0, 1, 1 }, 0, 0, 1, 1 }, { BOX, 0, 0, 0 / 0, 1 },
          { { BOX, { 1 } }, 0, 0, 1, 1 }, { { 0, 0, 10, 0, 0 / 0, 5 }, -5, 2, 15, 2 },
          { { 0, 0, 10, 0, 0 / 0, 5 }, 3, 3, 3, 3 } }) do
        local ok, err = callsite.raisesAtCaller(cast, args)
        assert.is_true(ok, err)
      end
      assert.are.same({ cast(BOX, 0, 20, 100, 20) }, { cast(polygon.Polygon(BOX), 0, 20, 100, 20) })
    end)
  end)
end)

describe("circleRayCast", function()
  describe("when computed by hand", function()
    it("enters a disc where the segment meets its circle, the normal from the centre", function()
      -- x from -3 to 3 at y = 0 into the unit disc: x = -1 at t = 2 / 6
      local f, nx, ny = circleCast(0, 0, 1, -3, 0, 3, 0)
      assert.are.equal(1 / 3, f)
      assert.are.same({ -1, 0 }, { nx, ny })
      -- at y = 0.6: x = -0.8 (0.36 + 0.64 = 1), t = (3 - 0.8) / 6, normal (-0.8, 0.6)
      f, nx, ny = circleCast(0, 0, 1, -3, 0.6, 3, 0.6)
      assert.is_true(math.abs(f - 2.2 / 6) <= 4 * EPS)
      assert.is_true(math.abs(nx + 0.8) <= 4 * EPS and math.abs(ny - 0.6) <= 4 * EPS)
    end)

    it("misses a tangent, starts inside with 0, 0, 0, takes no radius 0", function()
      assert.are.equal(false, circleCast(0, 0, 1, -3, 1, 3, 1))
      assert.are.same({ 0, 0, 0 }, { circleCast(0, 0, 1, 0.5, 0, 3, 0) })
      assert.are.equal(false, circleCast(0, 0, 0, -3, 0, 3, 0))
    end)

    it("refuses bad arguments at the caller's line", function()
      assert.has_error(function() circleCast(0, 0, -1, 0, 0, 1, 1) end,
        "circleRayCast: radius must not be negative, got -1")
      assert.has_error(function() circleCast(0, 0, 1, 0, 0, 1, 0 / 0) end,
        "circleRayCast: y2 must be finite, got " .. tostring(0 / 0))
      local ok, err = callsite.raisesAtCaller(circleCast, { 0, 0, 1, 0, 0, nil, 1 })
      assert.is_true(ok, err)
    end)
  end)
end)

-- The hard cases, each at every offset o: the shapes and segments moved by (o, o), the ulp steps
-- taken at the moved coordinates.
describe("rays, hard cases: grazing a vertex", function()
  for _, o in ipairs(OFFSETS) do
    it("misses a square's corner exactly, hits one ulp inside, misses one ulp outside (offset "
        .. o .. ")", function()
      local sq = moved(SQUARE, o)
      -- y = x - 10 touches only the corner (10, 0)
      assert.are.equal(false, checkConvex(sq, o + 5, o - 5, o + 15, o + 5))
      -- the start one ulp to the left: the line cuts the corner
      assert.is_number(checkConvex(sq, nextDown(o + 5), o - 5, nextDown(o + 15), o + 5))
      assert.are.equal(false, checkConvex(sq, nextUp(o + 5), o - 5, nextUp(o + 15), o + 5))
      -- a triangle's apex (0, 6), grazed horizontally: miss; just below it: in
      local tri = moved(TRIANGLE, o)
      assert.are.equal(false, checkConvex(tri, o - 5, o + 6, o + 5, o + 6))
      assert.is_number(checkConvex(tri, o - 5, nextDown(o + 6), o + 5, nextDown(o + 6)))
    end)

    it("hits through a corner exactly, with either edge's normal (offset " .. o .. ")", function()
      local f, nx, ny = checkConvex(moved(SQUARE, o), o - 5, o - 5, o + 15, o + 15)
      assert.is_true((nx == -1 and ny == 0) or (nx == 0 and ny == -1))
      assert.is_true(f > 0.2 and f < 0.3)
    end)
  end
end)

describe("rays, hard cases: along an edge and one ulp either side", function()
  for _, o in ipairs(OFFSETS) do
    it("misses along the edge, hits one ulp inside, misses one ulp outside (offset " .. o .. ")", function()
      for _, sq in ipairs({ moved(SQUARE, o), moved(SQUARE_CCW, o) }) do
        assert.are.equal(false, checkConvex(sq, o - 5, o, o + 15, o))
        assert.is_number(checkConvex(sq, o - 5, nextUp(o), o + 15, nextUp(o)))
        assert.are.equal(false, checkConvex(sq, o - 5, nextDown(o), o + 15, nextDown(o)))
        -- vertical, along x = 10
        assert.are.equal(false, checkConvex(sq, o + 10, o + 20, o + 10, o - 20))
        assert.is_number(checkConvex(sq, nextDown(o + 10), o + 20, nextDown(o + 10), o - 20))
      end
      -- along the hypotenuse 3x + 4y = 24 from (-8, 12) to (16, -6)
      local tri = moved(TRIANGLE, o)
      assert.are.equal(false, checkConvex(tri, o - 8, o + 12, o + 16, o - 6))
      checkConvex(tri, o - 8, nextDown(o + 12), o + 16, nextDown(o - 6))
      checkConvex(tri, o - 8, nextUp(o + 12), o + 16, nextUp(o - 6))
    end)
  end
end)

-- A ray crossing an edge at a shallow angle: the float fraction's error grows as 1 / sin of the
-- angle, past 8 eps M at the origin's scale, so the fraction must come from the precise paths
-- (double doubles, then expansions). The three flat bodies, against the oracle.
describe("rays, hard cases: crossing an edge at a shallow angle", function()
  it("gives the fraction within 8 eps M at angles down to 1e-12", function()
    local rng = prng.new(3008)
    local hits = 0
    for _ = 1, 400 do
      local size = rng:pick({ 1, 100, 1e4 })
      -- a wedge whose long bottom edge runs from (0, 0) to (size, 0) and a few random vertices
      -- above it (convex: a fan of increasing angle)
      local points = { 0.0, 0.0, size, 0.0 }
      local m = rng:int(1, 6)
      for i = 1, m do
        local t = math.pi * (i - 0.5 + rng:range(-0.3, 0.3)) / m
        points[#points + 1] = size / 2 + size / 2 * math.cos(t)
        points[#points + 1] = -size / 3 * math.sin(t)   -- above on screen (y up is negative)
      end
      if rng:float() < 0.5 then points = shapes.reverse(points) end
      -- a ray from below, crossing the bottom edge at a shallow angle near its middle
      local angle = 10 ^ rng:range(-12, -1)
      local cx = size * rng:range(0.2, 0.8)
      local len = size * rng:range(0.5, 2)
      local ax, ay = cx - len * math.cos(angle), len * math.sin(angle)
      local bx, by = cx + len * math.cos(angle) * 0.5, -len * math.sin(angle) * 0.5
      -- all of it turned by a random angle about a random point (no edge along an axis)
      local turn, ox, oy = rng:range(0, 2 * math.pi), rng:range(-2, 2) * size, rng:range(-2, 2) * size
      local c, sn = math.cos(turn), math.sin(turn)
      local function turned(x, y) return ox + c * x - sn * y, oy + sn * x + c * y end
      for i = 1, #points, 2 do points[i], points[i + 1] = turned(points[i], points[i + 1]) end
      ax, ay = turned(ax, ay)
      bx, by = turned(bx, by)
      local n = #points
      if oracle.polygonType(points) ~= "convex" then points = nil end   -- turned out of convex
      local entry = points and rays.convexEntry(points, ax, ay, bx, by)
      local bodies = { rayring.castRingJit, rayring.castRingPuc, rayring.castRingExact }
      for _, body in ipairs(points and bodies or {}) do
        local f, nx, ny = body(points, n, ax, ay, bx, by)
        local ok, message = agrees(entry, f, nx, ny, ax, ay, bx, by)
        assert(ok, message)
      end
      if points then
        checkConvex(points, ax, ay, bx, by)   -- the public function too
        hits = hits + (type(entry) == "table" and 1 or 0)
      end
    end
    assert.is_true(hits > 300, hits .. " hits")   -- the generator's reach
  end)
end)

describe("rays, hard cases: ending exactly on the boundary", function()
  for _, o in ipairs(OFFSETS) do
    it("misses when the segment ends on the edge, hits when it ends one ulp past (offset "
        .. o .. ")", function()
      local sq = moved(SQUARE, o)
      assert.are.equal(false, checkConvex(sq, o - 5, o + 5, o, o + 5))
      local f = checkConvex(sq, o - 5, o + 5, nextUp(o), o + 5)
      assert.is_true(f > 0.99 and f <= 1)
      -- ending at a vertex from outside, along the diagonal
      assert.are.equal(false, checkConvex(sq, o - 5, o - 5, o, o))
      assert.are.equal(false, checkList(movedList(TILES, o), { moved(TILES_OUTLINE, o) }, o + 10, o - 5,
        o + 10, o))
    end)
  end
end)

describe("rays, hard cases: starting on the boundary", function()
  for _, o in ipairs(OFFSETS) do
    it("enters at fraction 0 heading in and misses heading out (offset " .. o .. ")", function()
      local sq = moved(SQUARE, o)
      assert.are.same({ 0, -1, 0 }, { checkConvex(sq, o, o + 5, o + 15, o + 5) })
      assert.are.equal(false, checkConvex(sq, o, o + 5, o - 15, o + 5))
      -- from a corner: in along the diagonal, out along it, along an edge
      local f, nx, ny = checkConvex(sq, o, o, o + 5, o + 5)
      assert.are.equal(0, f)
      assert.is_true((nx == -1 and ny == 0) or (nx == 0 and ny == -1))
      assert.are.equal(false, checkConvex(sq, o, o, o - 5, o - 5))
      assert.are.equal(false, checkConvex(sq, o, o, o + 20, o))
      -- a list: on the outline heading in, and on a seam (inside the union) either way
      local list, rings = movedList(L3, o), { moved(L3_OUTLINE, o) }
      assert.are.same({ 0, 0, 1 }, { checkList(list, rings, o + 5, o + 20, o + 5, o + 15) })
      assert.are.same({ 0, 0, 0 }, { checkList(list, rings, o + 10, o + 5, o + 15, o + 5) })
      assert.are.same({ 0, 0, 0 }, { checkList(list, rings, o + 10, o + 5, o + 5, o + 5) })
      -- at the reflex corner, into the union and out of it
      checkList(list, rings, o + 10, o + 10, o + 5, o + 5)
      assert.are.equal(false, checkList(list, rings, o + 10, o + 10, o + 15, o + 15))
    end)
  end
end)

describe("rays, hard cases: starting inside", function()
  for _, o in ipairs(OFFSETS) do
    it("gives 0, 0, 0, also on a seam and at a corner where tiles meet (offset " .. o .. ")", function()
      assert.are.same({ 0, 0, 0 }, { checkConvex(moved(SQUARE, o), o + 5, o + 5, o - 50, o + 5) })
      assert.are.same({ 0, 0, 0 }, { checkConvex(moved(TRIANGLE, o), o + 1, o + 1, o + 1, o + 1) })
      local grid = {}
      for r = 0, 1 do
        for c = 0, 1 do grid[#grid + 1] = parts.box(c * 10, r * 10, 10, 10) end
      end
      local list, rings = movedList(grid, o), { moved({ 0, 0, 20, 0, 20, 20, 0, 20 }, o) }
      assert.are.same({ 0, 0, 0 }, { checkList(list, rings, o + 10, o + 10, o + 30, o + 10) })
      assert.are.same({ 0, 0, 0 }, { checkList(list, rings, o + 10, o + 10, o + 10, o + 10) })
      assert.are.same({ 0, 0, 0 }, { checkList(list, rings, o + 10, o + 10, o - 30, o - 30) })
    end)
  end
end)

describe("rays, hard cases: along the seams of tiles", function()
  for _, o in ipairs(OFFSETS) do
    it("enters where a seam meets the outline, never stopping at seams (offset " .. o .. ")", function()
      -- a 3 x 3 block of tiles 10 wide: every seam, both ways, axis-parallel, and one ulp aside
      local grid = {}
      for r = 0, 2 do
        for c = 0, 2 do grid[#grid + 1] = parts.box(c * 10, r * 10, 10, 10) end
      end
      local list, rings = movedList(grid, o), { moved({ 0, 0, 30, 0, 30, 30, 0, 30 }, o) }
      for _, x in ipairs({ 0, 10, 20, 30 }) do
        for _, step in ipairs({ "down", "up", "left", "right" }) do
          local at = o + x
          if step == "left" then at = nextDown(at) elseif step == "right" then at = nextUp(at) end
          local f = checkList(list, rings, at, o - 10, at, o + 40)
          checkList(list, rings, at, o + 40, at, o - 10)
          checkList(list, rings, o - 10, at, o + 40, at)
          if (x == 10 or x == 20) and (step == "down" or step == "up") then assert.are.equal(0.2, f) end
          if x == 0 and step ~= "right" then assert.are.equal(false, f) end
        end
      end
    end)

    it("enters an L along its seams and at its notch (offset " .. o .. ")", function()
      local list, rings = movedList(L3, o), { moved(L3_OUTLINE, o) }
      -- along y = 10 from the right: the seam starts at the reflex corner (10, 10)
      local f, nx, ny = checkList(list, rings, o + 30, o + 10, o - 10, o + 10)
      assert.are.equal(0.5, f)
      assert.are.same({ 1, 0 }, { nx, ny })
      -- along x = 10 from below (y = 30 down to y = -10): in at the corner (10, 10)
      f, nx, ny = checkList(list, rings, o + 10, o + 30, o + 10, o - 10)
      assert.are.equal(0.5, f)
      assert.are.same({ 0, 1 }, { nx, ny })
      -- along the outline's edges: no entry
      assert.are.equal(false, checkList(list, rings, o + 30, o + 20, o - 10, o + 20))
      assert.are.equal(false, checkList(list, rings, o + 20, o + 30, o + 20, o - 10))
    end)
  end
end)

describe("circleRayCast, hard cases: tangents", function()
  for _, o in ipairs(OFFSETS) do
    it("misses a tangent, hits one ulp inside it, misses one ulp outside (offset " .. o .. ")", function()
      -- radius 5 about (o, o): the line y = o + 5 touches at (o, o + 5)
      assert.are.equal(false, checkDisc(o, o, 5, o - 20, o + 5, o + 20, o + 5))
      assert.is_number(checkDisc(o, o, 5, o - 20, nextDown(o + 5), o + 20, nextDown(o + 5)))
      assert.are.equal(false, checkDisc(o, o, 5, o - 20, nextUp(o + 5), o + 20, nextUp(o + 5)))
      -- the tangent at (3, 4): 3x + 4y = 25 through (7, 1) and (-1, 7)
      assert.are.equal(false, checkDisc(o, o, 5, o + 7, o + 1, o - 1, o + 7))
      checkDisc(o, o, 5, o + 7, nextDown(o + 1), o - 1, nextDown(o + 7))
      checkDisc(o, o, 5, o + 7, nextUp(o + 1), o - 1, nextUp(o + 7))
      -- from the circle: heading in at 0, heading out a miss; ending on it a miss
      assert.are.same({ 0, 0, 1 }, { checkDisc(o, o, 5, o, o + 5, o, o - 20) })
      assert.are.equal(false, checkDisc(o, o, 5, o, o + 5, o, o + 20))
      assert.are.equal(false, checkDisc(o, o, 5, o, o + 20, o, o + 5))
    end)
  end
end)

describe("circleRayCast, hard cases: small discs from far away", function()
  for _, o in ipairs(OFFSETS) do
    it("enters a disc 1e-3 wide from 1e3 away, the normal right to a few ulps (offset "
        .. o .. ")", function()
      local rng = prng.new(3007)
      for _ = 1, 40 do
        local cx, cy, r = o + rng:range(-1, 1), o + rng:range(-1, 1), 1e-3 * rng:range(0.5, 1.5)
        local t = rng:range(0, 2 * math.pi)
        local ax, ay = cx + 1e3 * math.cos(t), cy + 1e3 * math.sin(t)
        local aim = rng:range(-0.9, 0.9) * r   -- through the disc, off its centre
        local bx = cx - 1e3 * math.cos(t) - aim * math.sin(t)
        local by = cy - 1e3 * math.sin(t) + aim * math.cos(t)
        assert.is_number(checkDisc(cx, cy, r, ax, ay, bx, by))
      end
    end)
  end
end)

-- Random cases against the oracle: the shapes users make at the coordinates games use, and at
-- the offsets.
describe("rays, random cases against the oracle", function()
  it("agree on random convex polygons and segments", function()
    local rng = prng.new(3001)
    for round = 1, 300 do
      local o = OFFSETS[round % #OFFSETS + 1]
      local size = rng:pick({ 1, 10, 100 })
      local points = shapes.convex(rng, rng:int(3, 9), o, o, size, 0.4)
      if rng:float() < 0.5 then points = shapes.reverse(points) end
      for _ = 1, 4 do
        local ax, ay = o + rng:range(-3, 3) * size, o + rng:range(-3, 3) * size
        local bx, by = o + rng:range(-3, 3) * size, o + rng:range(-3, 3) * size
        if rng:float() < 0.3 then   -- through a vertex, or from one
          local k = 2 * rng:int(1, #points / 2) - 1
          if rng:float() < 0.5 then ax, ay = points[k], points[k + 1] else
            bx, by = points[k] + (points[k] - ax), points[k + 1] + (points[k + 1] - ay)
          end
        end
        checkConvex(points, ax, ay, bx, by)
      end
    end
  end)

  it("agree on lists of parts of random concave polygons, seams and corners included", function()
    local rng = prng.new(3002)
    for round = 1, 60 do
      local o = OFFSETS[round % #OFFSETS + 1]
      -- small integer stars: rays between vertices run along diagonals (seams) and through
      -- corners where parts meet
      local outline = {}
      local m = rng:int(5, 9)
      for k = 1, m do
        local t = (k + 0.6 * (rng:float() - 0.5)) * 2 * math.pi / m
        local r = rng:int(3, 10)
        outline[2 * k - 1] = o + math.floor(r * math.cos(t) + 0.5)
        outline[2 * k] = o + math.floor(r * math.sin(t) + 0.5)
      end
      local list = polygon.polygonConvexParts(outline)
      if list then
        for _ = 1, 8 do
          local i, j = 2 * rng:int(1, m) - 1, 2 * rng:int(1, m) - 1
          local ax, ay, bx, by = outline[i], outline[i + 1], outline[j], outline[j + 1]
          if rng:float() < 0.5 then   -- from outside through two vertices
            ax, ay = ax - (bx - ax), ay - (by - ay)
          elseif rng:float() < 0.5 then
            ax, ay = o + rng:int(-12, 12), o + rng:int(-12, 12)
          end
          checkList(list, { outline }, ax, ay, bx, by)
        end
      end
    end
  end)

  it("agree on random tile maps built as one square per tile, along seams and through corners", function()
    local rng = prng.new(3003)
    for round = 1, 40 do
      local o = OFFSETS[round % #OFFSETS + 1]
      local set = tiles.random(rng, 5, 5, 0.6)
      local list = {}
      for r = 1, 5 do
        for c = 1, 5 do
          if set[r][c] then
            local x, y = o + (c - 1) * 10, o + (r - 1) * 10
            list[#list + 1] = { x, y, x + 10, y, x + 10, y + 10, x, y + 10 }
          end
        end
      end
      if #list > 0 then
        local rings = tiles.loops(set, 10, o, o)
        local sides = {}
        for k = 1, #rings do sides[k] = 1 end   -- every loop keeps the tiles on its right
        for _ = 1, 10 do
          local ax, ay = o + 5 * rng:int(-2, 12), o + 5 * rng:int(-2, 12)
          local bx, by = o + 5 * rng:int(-2, 12), o + 5 * rng:int(-2, 12)
          if rng:float() < 0.5 then by = ay elseif rng:float() < 0.5 then bx = ax end
          local ok, err = pcall(checkList, list, rings, ax, ay, bx, by, sides)
          if not ok then
            local text = {}
            for _, p in ipairs(list) do text[#text + 1] = "{" .. table.concat(p, ",") .. "}" end
            error(tostring(err) .. " list " .. table.concat(text, ","))
          end
        end
      end
    end
  end)

  it("agree on random discs and segments, near tangents too", function()
    local rng = prng.new(3004)
    for round = 1, 300 do
      local o = OFFSETS[round % #OFFSETS + 1]
      local r = rng:pick({ 0.5, 3, 40, 1000 }) * rng:range(0.5, 1.5)
      local cx, cy = o + rng:range(-1, 1) * r, o + rng:range(-1, 1) * r
      local ax, ay = o + rng:range(-4, 4) * r, o + rng:range(-4, 4) * r
      local bx, by = o + rng:range(-4, 4) * r, o + rng:range(-4, 4) * r
      if round % 3 == 0 then   -- aim at the circle's rim: nearly tangent
        local t = rng:range(0, 2 * math.pi)
        local px, py = cx + r * math.cos(t), cy + r * math.sin(t)
        local ux, uy = -math.sin(t), math.cos(t)
        ax, ay, bx, by = px - 3 * r * ux, py - 3 * r * uy, px + 3 * r * ux, py + 3 * r * uy
      end
      checkDisc(cx, cy, r, ax, ay, bx, by)
    end
  end)
end)

-- The three bodies of the flat engine (LuaJIT's and PUC Lua's fast paths, and the exact path
-- that both fall back on), each on every interpreter, on convex polygons against the oracle.
describe("polygonRayCast's flat bodies on convex polygons", function()
  it("agree with the oracle and with each other, decision for decision", function()
    local rng = prng.new(3005)
    for round = 1, 300 do
      local o = OFFSETS[round % #OFFSETS + 1]
      local size = rng:pick({ 1, 10, 100 })
      local points = shapes.convex(rng, rng:int(3, 20), o, o, size, 0.4)
      if rng:float() < 0.5 then points = shapes.reverse(points) end
      for _ = 1, 4 do
        local ax, ay = o + rng:range(-3, 3) * size, o + rng:range(-3, 3) * size
        local bx, by = o + rng:range(-3, 3) * size, o + rng:range(-3, 3) * size
        if rng:float() < 0.3 then   -- from a vertex, along an edge, or to one
          local k = 2 * rng:int(1, #points / 2) - 1
          local j = (k + 1) % #points + 1
          if rng:float() < 0.3 then ax, ay = points[k], points[k + 1] end
          if rng:float() < 0.5 then bx, by = points[j], points[j + 1] end
        end
        if ax ~= bx or ay ~= by then
          local entry = rays.convexEntry(points, ax, ay, bx, by)
          local n = #points
          local answers = {}
          for _, body in ipairs({ rayring.castRingJit, rayring.castRingPuc, rayring.castRingExact }) do
            local f, nx, ny = body(points, n, ax, ay, bx, by)
            local ok, message = agrees(entry, f, nx, ny, ax, ay, bx, by)
            assert(ok, message)
            answers[#answers + 1] = f and (f == 0 and nx == 0 and "inside" or "hit") or "miss"
          end
          assert.are.same({ answers[1], answers[1] }, { answers[2], answers[3] })
        end
      end
    end
  end)
end)

-- Convex polygons with one vertex moved onto the line of its neighbours, then nudged by an ulp
-- or three (collinear, reflex or convex by a hair), rays from anywhere and through vertices:
-- every body against the oracle's rings (the polygon taken as it is: no convexity needed).
describe("rays, hard cases: polygons convex or reflex by an ulp", function()
  -- A convex polygon of 3 to 16 integer vertices with one vertex moved to the midpoint of its
  -- neighbours (exact: their coordinates' sums are even), then nudged by 0 to 3 ulps in x or y.
  -- Sometimes a vertex repeated, or all of it at an offset.
  local function nearDegenerate(rng)
    local m = rng:int(3, 16)
    local points = {}
    for i = 1, m do   -- even coordinates on a circle of radius ~1000, in order
      local t = (i - 1 + rng:range(-0.3, 0.3)) * 2 * math.pi / m
      points[2 * i - 1] = 2 * math.floor(500 * math.cos(t)) + 0.0
      points[2 * i] = 2 * math.floor(500 * math.sin(t)) + 0.0
    end
    if m >= 4 and rng:float() < 0.8 then
      local k = rng:int(1, m)
      local a, b = (k - 2) % m + 1, k % m + 1
      points[2 * k - 1] = (points[2 * a - 1] + points[2 * b - 1]) / 2
      points[2 * k] = (points[2 * a] + points[2 * b]) / 2
      local c = 2 * k - rng:int(0, 1)
      for _ = 1, rng:int(0, 3) do
        points[c] = rng:float() < 0.5 and nextUp(points[c]) or nextDown(points[c])
      end
    elseif rng:float() < 0.3 then
      local k = 2 * rng:int(1, m) - 1
      table.insert(points, k, points[k + 1])
      table.insert(points, k, points[k + 1])
    end
    local o = OFFSETS[rng:int(1, 3)]
    if rng:float() < 0.5 then points = shapes.reverse(points) end
    return moved(points, o), o
  end

  it("agree with the oracle, through vertices and along edges too", function()
    local rng = prng.new(3007)
    local hits = 0
    for _ = 1, 1500 do
      local points, o = nearDegenerate(rng)
      local n = #points
      local ax, ay = o + rng:range(-1500, 1500), o + rng:range(-1500, 1500)
      local bx, by = o + rng:range(-1500, 1500), o + rng:range(-1500, 1500)
      local pick = rng:float()
      if pick < 0.3 then   -- through a vertex: B beyond it on the line from A
        local k = 2 * rng:int(1, n / 2) - 1
        bx, by = 2 * points[k] - ax, 2 * points[k + 1] - ay
      elseif pick < 0.45 then   -- along an edge, from before it to past it
        local k = 2 * rng:int(1, n / 2) - 1
        local j = (k + 1) % n + 1
        local ex, ey = points[j] - points[k], points[j + 1] - points[k + 1]
        ax, ay, bx, by = points[k] - ex, points[k + 1] - ey, points[j] + ex, points[j + 1] + ey
      end
      if ax ~= bx or ay ~= by then
        local entry = rays.ringsEntry({ points }, ax, ay, bx, by)
        if type(entry) == "table" then hits = hits + 1 end
        for _, body in ipairs({ rayring.castRingJit, rayring.castRingPuc, rayring.castRingExact }) do
          local f, nx, ny = body(points, n, ax, ay, bx, by)
          local ok, message = agrees(entry, f, nx, ny, ax, ay, bx, by)
          assert(ok, message)
        end
      end
    end
    assert.is_true(hits > 300, "hits " .. hits)   -- (the generator's reach)
  end)
end)
