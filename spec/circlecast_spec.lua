-- Issue 30, casts: polygonCircleCast, a circle swept against a convex polygon or a list of convex
-- parts. Hand-computed cases, the refusals, the hard cases (face to face, diagonal onto a corner,
-- slides along a face exactly at the radius and one ulp either way, a fast move through a thin
-- wall, starts overlapping or touching, zero motion, rows of tiles with seams along the path),
-- each at offsets 0, 1e6 + 0.5, 1e9 and 1e12, then random cases against the oracle
-- (spec/support/sweeps.lua's discReach: exact candidate times, sharing nothing with the library).
-- Every hit's fraction is checked twice: the circle, its centre moved as a game moves it, does not
-- collide (polygonCircleCollideV), and the exact contact lies no later than the fraction plus
-- 8 eps M / |d|.
local polygon = require "polygon"
local sweeps = require "sweeps"
local exact = require "exact"
local prng = require "prng"
local shapes = require "shapes"
local callsite = require "callsite"

local cast = polygon.polygonCircleCast
local nextUp, nextDown = exact.nextUp, exact.nextDown
local EPS = 2 ^ -53

local OFFSETS = { 0, 1e6 + 0.5, 1e9, 1e12 }

-- An axis-parallel box, clockwise on screen.
local function box(x, y, w, h)
  return { x, y, x + w, y, x + w, y + h, x, y + h }
end

-- The parts of a static shape (a flat array or a list).
local function partsOf(static)
  return type(static[1]) == "table" and static or { static }
end

-- The largest coordinate magnitude of the static shape and the centre, moved or not.
local function magnitude(static, cx, cy, dx, dy)
  local m = math.max(math.abs(cx), math.abs(cy), math.abs(cx + dx), math.abs(cy + dy))
  for _, part in ipairs(partsOf(static)) do
    for _, v in ipairs(part) do m = math.max(m, math.abs(v)) end
  end
  return m
end

-- The nearest point of the parts' boundaries to (x, y), in floating point (a plain loop over
-- the edges: for the normal's check only).
local function nearestPoint(static, x, y)
  local best, bx, by = math.huge, 0, 0
  for _, part in ipairs(partsOf(static)) do
    local n = #part
    for i = 1, n, 2 do
      local ax, ay = part[i], part[i + 1]
      local j = i + 2 > n and 1 or i + 2
      local ex, ey = part[j] - ax, part[j + 1] - ay
      local s = ((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey)
      s = math.max(0, math.min(1, s))
      local px, py = ax + s * ex, ay + s * ey
      local d = (x - px) ^ 2 + (y - py) ^ 2
      if d < best then best, bx, by = d, px, py end
    end
  end
  return bx, by
end

local function unitOf(x, y)
  local len = math.sqrt(x * x + y * y)
  return x / len, y / len
end

-- Whether the circle with its centre moved by s (dx, dy), rounded as a game moves it, collides.
local function movedCollides(static, cx, cy, r, dx, dy, s)
  return polygon.polygonCircleCollideV(static, cx + s * dx, cy + s * dy, r) ~= false
end

-- polygonCircleCast's answer against the oracle's. Returns ok, message.
local function agrees(static, cx, cy, r, dx, dy, f, nx, ny)
  local where = ("circle (%.17g, %.17g, %.17g), d = (%.17g, %.17g)"):format(cx, cy, r, dx, dy)
  if sweeps.discReach(static, cx, cy, r, dx, dy, 0) then
    if f ~= 0 then return false, ("expected 0 (overlapping) for %s, got %s"):format(where, tostring(f)) end
    local _, px, py = polygon.polygonCircleCollideV(static, cx, cy, r)
    local ux, uy = unitOf(px, py)
    if math.abs(nx - ux) > 16 * EPS or math.abs(ny - uy) > 16 * EPS then
      return false, ("normal (%.17g, %.17g) is not the push's direction (%.17g, %.17g) for %s"):format(
        nx, ny, ux, uy, where)
    end
    return true
  end
  if not sweeps.discReach(static, cx, cy, r, dx, dy, 1) then
    return f == false and nx == nil, ("expected a miss for %s, got %s, %s, %s"):format(where,
      tostring(f), tostring(nx), tostring(ny))
  end
  if type(f) ~= "number" or f < 0 or f > 1 then
    return false, ("expected a hit for %s, got %s"):format(where, tostring(f))
  end
  if movedCollides(static, cx, cy, r, dx, dy, f) then
    return false, ("moved by fraction %.17g the circle collides, %s"):format(f, where)
  end
  local M = magnitude(static, cx, cy, dx, dy)
  -- 8 eps M / |d|, rounded down a little: the exact contact must lie no later than f plus it
  local b = 8 * EPS * M / math.sqrt(dx * dx + dy * dy) * (1 - 2 ^ -40)
  if not sweeps.discReach(static, cx, cy, r, dx, dy, f, b) then
    -- too early: allowed only where every double fraction within the bound before the contact
    -- leaves the rounded circle colliding (a grazing contact: rounding decides). The contact
    -- lies in (lo, hi], found by bisection, then the doubles from hi down to the bound's end are
    -- tried.
    local lo, hi = f, 1
    for _ = 1, 80 do
      local mid = lo + (hi - lo) / 2
      if mid <= lo or mid >= hi then break end
      if sweeps.discReach(static, cx, cy, r, dx, dy, mid) then hi = mid else lo = mid end
    end
    -- every double of the window when it holds up to 4096 of them, else 1024 evenly spaced
    local step = 0
    if b / (hi - nextDown(hi)) > 4096 then step = b / 1024 end
    local s, count = hi, 0
    while s > f and sweeps.discReach(static, cx, cy, r, dx, dy, s, b) and count < 4200 do
      if not sweeps.discReach(static, cx, cy, r, dx, dy, s)
          and not movedCollides(static, cx, cy, r, dx, dy, s) then
        return false, ("fraction %.17g is more than 8 eps M / |d| before the contact, and %.17g would do, %s")
          :format(f, s, where)
      end
      s, count = step > 0 and s - step or nextDown(s), count + 1
    end
    if count == 4200 then
      return false, ("fraction %.17g: the window is too wide to try, %s"):format(f, where)
    end
  end
  -- the normal: from the nearest point of the shape toward the centre at contact
  local px, py = nearestPoint(static, cx + f * dx, cy + f * dy)
  local ux, uy = unitOf(cx + f * dx - px, cy + f * dy - py)
  local tol = 1e-9 + 64 * EPS * M / r
  if math.abs(nx - ux) > tol or math.abs(ny - uy) > tol or math.abs(nx * nx + ny * ny - 1) > 8 * EPS then
    return false, ("normal (%.17g, %.17g), expected (%.17g, %.17g), %s"):format(nx, ny, ux, uy, where)
  end
  return true
end

-- Asserts the library agrees with the oracle, and returns the library's answer.
local function checked(static, cx, cy, r, dx, dy)
  local f, nx, ny = cast(static, cx, cy, r, dx, dy)
  local ok, message = agrees(static, cx, cy, r, dx, dy, f, nx, ny)
  assert(ok, message)
  return f, nx, ny
end

describe("polygonCircleCast", function()
  describe("when computed by hand", function()
    it("meets a box face to face, the normal out of the face", function()
      -- box [0, 10]^2; the centre (-5, 5) moving by (10, 0) comes within 1 of the side x = 0 at
      -- x = -1: t = 4 / 10; normal (-1, 0)
      local f, nx, ny = checked(box(0, 0, 10, 10), -5, 5, 1, 10, 0)
      assert.are.same({ 0.4, -1, 0 }, { f, nx, ny })
      -- falling onto a floor (y down): the bottom of the circle, y + 5, reaches 40 at y = 35:
      -- t = 35 / 50 = 0.7; normal (0, -1)
      f, nx, ny = checked(box(-100, 40, 200, 10), 0, 0, 5, 0, 50)
      assert.are.same({ 0.7, 0, -1 }, { f, nx, ny })
    end)

    it("meets a corner diagonally, the normal from the corner to the centre", function()
      -- the centre (-5, -5) moving by (20, 20) comes within 1 of the corner (0, 0) at (-s, -s),
      -- s = sqrt(1 / 2): 20 t = 5 - s, t = 0.2146446609406726; normal (-s, -s)
      local f, nx, ny = checked(box(0, 0, 10, 10), -5, -5, 1, 20, 20)
      assert.is_true(math.abs(f - (5 - math.sqrt(0.5)) / 20) < 8 * EPS)
      assert.is_true(math.abs(nx + math.sqrt(0.5)) < 4 * EPS and math.abs(ny + math.sqrt(0.5)) < 4 * EPS)
      -- passing the corner at 0.5 from it (off the face's line): (x)^2 + 0.5^2 = 1, x = -sqrt(0.75)
      f, nx, ny = checked(box(0, 0, 10, 10), -5, 10.5, 1, 10, 0)
      assert.is_true(math.abs(f - (5 - math.sqrt(0.75)) / 10) < 8 * EPS)
      assert.is_true(math.abs(nx + math.sqrt(0.75)) < 4 * EPS and math.abs(ny - 0.5) < 4 * EPS)
    end)

    it("answers false for a move that stops short, passes by or goes away", function()
      assert.is_false(cast(box(0, 0, 10, 10), -5, 5, 1, 3, 0))     -- stops at x = -2
      assert.is_false(cast(box(0, 0, 10, 10), -5, 5, 1, 4, 0))     -- ends touching (x = -1)
      assert.is_false(cast(box(0, 0, 10, 10), -5, 5, 1, -10, 0))   -- away
      assert.is_false(cast(box(0, 0, 10, 10), -5, -2, 1, 30, 0))   -- passes above, 2 away
      assert.is_false(cast(box(0, 0, 10, 10), -5, 5, 0, 10, 0))    -- radius 0: never collides
    end)

    it("gives 0 and the push's direction when it starts overlapping, moving or not", function()
      -- the centre (-0.5, 5) lies 0.5 from x = 0: polygonCircleCollideV pushes by (-0.5, 0)
      assert.are.same({ 0, -1, 0 }, { checked(box(0, 0, 10, 10), -0.5, 5, 1, 10, 3) })
      assert.are.same({ 0, -1, 0 }, { checked(box(0, 0, 10, 10), -0.5, 5, 1, 0, 0) })
      assert.is_false(cast(box(0, 0, 10, 10), -5, 5, 1, 0, 0))   -- no move apart: false
    end)

    it("enters at 0 when it starts touching and moves in, misses when it moves away", function()
      assert.are.same({ 0, -1, 0 }, { checked(box(0, 0, 10, 10), -1, 5, 1, 1, 0) })
      assert.is_false(checked(box(0, 0, 10, 10), -1, 5, 1, -1, 0))
    end)

    it("takes either winding, a Polygon object and a list of parts", function()
      local a = box(0, 0, 10, 10)
      local expected = { cast(a, -5, -5, 1, 20, 20) }
      assert.are.same(expected, { cast(shapes.reverse(a), -5, -5, 1, 20, 20) })
      assert.are.same(expected, { cast(polygon.Polygon(a), -5, -5, 1, 20, 20) })
      assert.are.same(expected, { cast({ a }, -5, -5, 1, 20, 20) })
    end)
  end)

  describe("when given what the collision functions refuse", function()
    local BOX = box(0, 0, 10, 10)
    it("refuses a concave polygon, fewer than 3 points, point tables, non-finite coordinates", function()
      local L = { 0, 0, 100, 0, 100, 20, 20, 20, 20, 100, 0, 100 }
      assert.has_error(function() cast(L, 0, 0, 1, 1, 1) end,
        "polygonCircleCast: points is not convex (a reflex turn at vertex 4); split it once with "
        .. "polygonConvexParts and pass the parts")
      assert.has_error(function() cast({ BOX, L }, 0, 0, 1, 1, 1) end,
        "polygonCircleCast: points[2] is not convex (a reflex turn at vertex 4); split it once with "
        .. "polygonConvexParts and pass the parts")
      assert.has_error(function() cast({ 0, 0, 100, 100 }, 0, 0, 1, 1, 1) end,
        "polygonCircleCast: points has 2 points: a segment; a polygon needs at least 3; for line of "
        .. "sight use polygonRayCast")
      assert.has_error(function() cast({}, 0, 0, 1, 1, 1) end,
        "polygonCircleCast: points is empty; a polygon needs at least 3 points")
      local pointTables = { { x = 0, y = 0 }, { x = 1, y = 0 }, { x = 1, y = 1 } }
      assert.has_error(function() cast(pointTables, 0, 0, 1, 1, 1) end,
        "polygonCircleCast: points holds point tables; pass a flat array {x1, y1, x2, y2, ...}")
      assert.has_error(function() cast({ 0, 0, 1 / 0, 0, 1, 1 }, 0, 0, 1, 1, 1) end,
        "polygonCircleCast: points holds a non-finite coordinate")
    end)

    it("refuses bad numbers and a negative radius at the caller's line", function()
      assert.has_error(function() cast(BOX, 0, 0, -1, 1, 1) end,
        "polygonCircleCast: radius must not be negative, got -1")
      assert.has_error(function() cast(BOX, 0, 0 / 0, 1, 1, 1) end,
        "polygonCircleCast: cy must be finite, got " .. tostring(0 / 0))
      assert.has_error(function() cast(BOX, 0, 0, 1, 1, "x") end,
        "polygonCircleCast: dy must be a number, got string")
      assert.has_error(function() cast(BOX, 0, 0, 1, -1 / 0, 0) end,
        "polygonCircleCast: dx must be finite, got " .. tostring(-1 / 0))
      local ok, err = callsite.raisesAtCaller(cast, { BOX, 0, 0, 1, 1 / 0, 0 })
      assert.is_true(ok, err)
      ok, err = callsite.raisesAtCaller(cast, { { 0, 0, 1, 1 }, 0, 0, 1, 1, 0 })
      assert.is_true(ok, err)
    end)
  end)
end)

describe("polygonCircleCast, hard cases: face to face and onto corners", function()
  for _, o in ipairs(OFFSETS) do
    it("meets each side at the exact time, and a corner diagonally (offset " .. o .. ")", function()
      local B = box(o, o, 10, 10)
      -- from each side, radius 2, 10 from the box's side: the circle's edge reaches it after 8 of
      -- the 20 units, t = 0.4; normals out of the sides
      checked(B, o - 10, o + 5, 2, 20, 0)
      checked(B, o + 20, o + 5, 2, -20, 0)
      checked(B, o + 5, o - 10, 2, 0, 20)
      checked(B, o + 5, o + 20, 2, 0, -20)
      -- diagonally onto each corner (t = (10 - sqrt 2) / 20 for radius 2 from 10 away per axis)
      checked(B, o - 10, o - 10, 2, 20, 20)
      checked(B, o + 20, o - 10, 2, -20, 20)
      checked(B, o + 20, o + 20, 2, -20, -20)
      checked(B, o - 10, o + 20, 2, 20, -20)
    end)
  end
end)

describe("polygonCircleCast, hard cases: slides along a face", function()
  for _, o in ipairs(OFFSETS) do
    it("misses at exactly the radius, hits one ulp in, misses one ulp out (offset " .. o .. ")", function()
      local B = box(o, o, 10, 10)
      -- the top y = o (y down): a centre at y = o - 1 with radius 1 slides along it touching
      assert.is_false(checked(B, o - 5, o - 1, 1, 20, 0))
      assert.is_false(checked(B, o + 2, o - 1, 1, 5, 0))             -- starting over the face
      assert.is_number(checked(B, o - 5, nextUp(o - 1), 1, 20, 0))    -- one ulp in: the corner
      assert.is_false(checked(B, o - 5, nextDown(o - 1), 1, 20, 0))  -- one ulp out
      -- the side x = o + 10, going down along it
      assert.is_false(checked(B, o + 11, o - 5, 1, 0, 20))
      assert.is_number(checked(B, nextDown(o + 11), o - 5, 1, 0, 20))
      assert.is_false(checked(B, nextUp(o + 11), o - 5, 1, 0, 20))
      -- grazing the corner (o, o) at exactly the radius on a diagonal path: the path x - y =
      -- 2 sqrt(1/2) is not exact, so take the corner's tangent along x: centre y = o - 1
      assert.is_false(checked(B, o - 5, o - 1, 1, 4, 0))   -- ends before the corner, 1 from it
    end)
  end
end)

describe("polygonCircleCast, hard cases: a fast move through a thin wall", function()
  for _, o in ipairs(OFFSETS) do
    it("hits a wall 0.25 thick crossed in one move of 1000 (offset " .. o .. ")", function()
      local wall = { o, o, o + 0.25, o, o + 0.25, o + 100, o, o + 100 }
      -- from x = o - 10 to o + 990: the circle's edge reaches x = o after 9 of 1000, t = 0.009
      local f, nx, ny = checked(wall, o - 10, o + 50, 1, 1000, 0)
      assert.is_true(f <= 0.009 and f > 0.0089)
      assert.are.same({ -1, 0 }, { nx, ny })
      -- and back the other way, both ends far from the wall
      checked(wall, o + 500, o + 50, 1, -1000, 0)
      -- a slanted pass through its middle
      checked(wall, o - 300, o - 250, 3, 600, 600)
    end)
  end
end)

describe("polygonCircleCast, hard cases: starting overlapped or touching, zero motion", function()
  for _, o in ipairs(OFFSETS) do
    it("gives 0 and the push, 0 entering from a touch, false apart (offset " .. o .. ")", function()
      local B = box(o, o, 10, 10)
      checked(B, o - 0.5, o + 5, 1, 3, 7)
      checked(B, o - 0.5, o + 5, 1, 0, 0)
      checked(B, o + 5, o + 5, 1, 0, 0)         -- the centre inside
      checked(B, o - 1, o + 5, 1, 1, 0)         -- touching, moving in: 0
      checked(B, o - 1, o + 5, 1, 0, 1)         -- touching, sliding: false
      assert.is_false(checked(B, o - 1, o + 5, 1, 0, 0))
      assert.is_false(checked(B, o - 3, o + 5, 1, 0, 0))
    end)
  end
end)

describe("polygonCircleCast, hard cases: rows of tiles", function()
  for _, o in ipairs(OFFSETS) do
    it("slides along a row, falls onto a seam, runs along a seam's line (offset " .. o .. ")", function()
      local row = { box(o, o, 10, 10), box(o + 10, o, 10, 10), box(o + 20, o, 10, 10) }
      assert.is_false(checked(row, o - 5, o - 1, 1, 40, 0))      -- along the top at the radius
      assert.is_number(checked(row, o - 5, nextUp(o - 1), 1, 40, 0))
      -- onto the seam x = o + 10 from above: the bottom of the circle reaches y = o at t = 0.4
      local f, nx, ny = checked(row, o + 10, o - 5, 1, 0, 10)
      assert.are.same({ 0, -1 }, { nx, ny })
      assert.is_true(f <= 0.4 and f > 0.39)
      -- a column of tiles, the centre along the seam's line y = o + 10 into their left side
      local column = { box(o, o, 10, 10), box(o, o + 10, 10, 10) }
      f, nx, ny = checked(column, o - 5, o + 10, 1, 10, 0)
      assert.are.same({ -1, 0 }, { nx, ny })
      assert.is_true(f <= 0.4 and f > 0.39)
      -- already inside the union across the seam
      checked(row, o + 10, o + 5, 1, 30, 0)
    end)
  end
end)

describe("polygonCircleCast, random cases against the oracle", function()
  it("agree on random convex polygons, circles and moves, aimed at vertices too", function()
    local rng = prng.new(36)
    for _ = 1, 100 do
      local o = OFFSETS[rng:int(1, #OFFSETS)]
      local a = shapes.convex(rng, rng:int(3, 6), o, o, rng:range(5, 40), 0.3)
      local cx, cy, r = o + rng:range(-80, 80), o + rng:range(-80, 80), rng:range(0.5, 20)
      local dx, dy = rng:range(-200, 200), rng:range(-200, 200)
      if rng:float() < 0.2 then dy = 0 end
      checked(a, cx, cy, r, dx, dy)
      local i = 2 * rng:int(1, #a / 2) - 1
      checked(a, cx, cy, r, a[i] - cx, a[i + 1] - cy)   -- the centre aimed at a vertex
    end
  end)

  it("agree on moves along an edge at the radius's distance, exactly and one ulp off", function()
    local rng = prng.new(37)
    for _ = 1, 60 do
      local o = OFFSETS[rng:int(1, #OFFSETS)]
      local a = shapes.convex(rng, rng:int(3, 6), o, o, rng:range(5, 40), 0.3)
      local i = 2 * rng:int(1, #a / 2) - 1
      local k = i + 2 > #a and 1 or i + 2
      local ex, ey = a[k] - a[i], a[k + 1] - a[i + 1]
      -- the circle through the vertex a[i], moving along the edge: its distance to the edge's
      -- line is 0, so with the radius that distance plus a little it starts colliding; instead
      -- start beyond the vertex, back along the edge, touching the vertex
      local len = math.sqrt(ex * ex + ey * ey)
      local r = rng:range(0.5, 5)
      local cx, cy = a[i] - ex / len * r, a[i + 1] - ey / len * r
      checked(a, cx, cy, r, ex * 1.5, ey * 1.5)
      checked(a, cx, cy, r, nextUp(ex * 1.5), ey * 1.5)
      checked(a, cx, cy, r, ex * 1.5, nextDown(ey * 1.5))
      -- parallel to the edge, offset by the radius along its normal (rounded: near the radius)
      local px, py = a[i] + ey / len * r, a[i + 1] - ex / len * r
      checked(a, px - ex, py - ey, r, 3 * ex, 3 * ey)
      px, py = a[i] - ey / len * r, a[i + 1] + ex / len * r
      checked(a, px - ex, py - ey, r, 3 * ex, 3 * ey)
    end
  end)

  it("agree on lists of random convex parts", function()
    local rng = prng.new(38)
    for _ = 1, 40 do
      local o = OFFSETS[rng:int(1, #OFFSETS)]
      local list = {}
      for _ = 1, rng:int(1, 4) do
        list[#list + 1] = shapes.convex(rng, rng:int(3, 5), o + rng:range(-60, 60), o + rng:range(-60, 60),
          rng:range(5, 25), 0.3)
      end
      checked(list, o + rng:range(-100, 100), o + rng:range(-100, 100), rng:range(0.5, 15),
        rng:range(-200, 200), rng:range(-200, 200))
    end
  end)

  it("agree on rows of tiles crossed along and across their seams", function()
    local rng = prng.new(39)
    for _ = 1, 40 do
      local o = OFFSETS[rng:int(1, #OFFSETS)]
      local row = {}
      for k = 0, 3 do row[#row + 1] = box(o + 8 * k, o, 8, 8) end
      local r = rng:int(1, 4)
      -- the centre on a seam's line or at the radius above the row, moving along or across
      local y = rng:pick({ o - r, o + 8 + r, o + 4, o - r - 1 })
      checked(row, o - 10, y, r, rng:pick({ 50, 20, 60 }), rng:pick({ 0, 0, 1, -1 }))
      local x = o + 8 * rng:int(1, 3)
      checked(row, x, o - 20, r, rng:pick({ 0, 1, -1 }), 40)
    end
  end)
end)
