-- Hard cases, family 7: generated convex pairs and circles around touching, with the collision
-- answer, the depth and the displacement checked against the exact separating-axis oracle.
--
-- For a pair (A, B) of convex polygons:
--   * polygonsCollide / polygonCollidesWith equal the exact SAT on both / A's axes (touching is not
--     colliding), in both argument orders; the V functions return false exactly when those do;
--   * overlap is the exact least penetration min over axes of min(max1 - min2, max2 - min1) / |n|
--     within TOL = M 2^-50 (M: the largest coordinate magnitude, so TOL is 2 to 4 ulps of it), and
--     |(dx, dy)| == overlap within TOL;
--   * after moving B by (dx, dy) the exact SAT finds them just touching: least penetration in
--     [-TOL, TOL] (for the one-sided function: no more overlap on A's axes than TOL).
--   Measured with POLYGON_SPEC_COUNTS=1: |overlap - exact| <= 0.2 M 2^-50 (polygon.lua 0119724).
-- For a polygon and a circle the same with the contract's circle axes and TOL = 2^-46 (M + r)
-- (unit normals cannot be exact); the library may call an overlap within its rounding "touching",
-- so only depths beyond TOL must agree in kind.

local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local tally = require "tally"
local shapes = require "shapes"

-- A convex polygon of 3 to 8 vertices (or to `most`) on an ellipse around (cx, cy), in either
-- winding.
local function convex(r, cx, cy, size, most)
  local points = shapes.convex(r, r:int(3, most or 8), cx, cy, size, 0.35)
  if r:int(0, 1) == 1 then points = shapes.reverse(points) end
  return points
end

local function support(points, ux, uy, want)
  local best
  for i = 1, #points - 1, 2 do
    local s = points[i] * ux + points[i + 1] * uy
    if not best or (s - best) * want > 0 then best = s end
  end
  return best
end

local moved, magnitude = shapes.translate, shapes.largestMagnitude

-- Gaps (as fractions of the size) by which B is placed beyond touching A along a direction:
-- negative ones overlap.
local GAPS = { -0.3, -1e-3, -1e-9, -1e-13, 0, 1e-13, 1e-9, 1e-3 }

-- Pairs around touching: B translated along a random direction u so that its extent along u starts
-- where A's ends, plus the gap; and pairs that share an edge or a vertex exactly.
local function pairsAround(seed, count, offset, most)
  local r = prng.new(seed)
  local list = {}
  for _ = 1, count do
    local size = r:range(1, 10)
    local cx, cy = offset + r:range(-5, 5), -offset + r:range(-5, 5)
    local a = convex(r, cx, cy, size, most)
    local b0 = convex(r, 0, 0, size * r:range(0.3, 2), most)
    -- B in front of A's edge f (so that the gap is measured on an axis of the SAT), or in a random
    -- direction u
    local m = #a / 2
    local f = r:int(1, m)
    local g = f % m + 1
    local ccx, ccy = oracle.center(a)
    local ux, uy = a[2 * g] - a[2 * f], a[2 * f - 1] - a[2 * g - 1]
    local length = math.sqrt(ux * ux + uy * uy)
    ux, uy = ux / length, uy / length
    local mx, my = (a[2 * f - 1] + a[2 * g - 1]) / 2, (a[2 * f] + a[2 * g]) / 2
    if (mx - ccx) * ux + (my - ccy) * uy < 0 then ux, uy = -ux, -uy end -- outwards
    if r:int(0, 2) == 0 then
      local angle = r:range(0, 2 * math.pi)
      ux, uy = math.cos(angle), math.sin(angle)
      mx, my = ccx, ccy
    end
    local shift = support(a, ux, uy, 1) - (mx * ux + my * uy) - support(b0, ux, uy, -1) + r:pick(GAPS) * size
    list[#list + 1] = { a, moved(b0, mx + shift * ux, my + shift * uy) }
    -- B sharing A's edge k exactly: the edge's two vertices and a point beyond it
    local k = r:int(1, m)
    local j = k % m + 1
    local x1, y1, x2, y2 = a[2 * k - 1], a[2 * k], a[2 * j - 1], a[2 * j]
    mx, my = (x1 + x2) / 2, (y1 + y2) / 2
    list[#list + 1] = { a, { x2, y2, x1, y1, 2 * mx - ccx, 2 * my - ccy } }
    -- B sharing only the vertex k, pointing away from A's centre
    local vx, vy = x1 - ccx, y1 - ccy
    list[#list + 1] = { a, { x1, y1, x1 + vx - 0.3 * vy, y1 + vy + 0.3 * vx,
      x1 + vx + 0.3 * vy, y1 + vy - 0.3 * vx } }
  end
  return list
end

local function checkPair(t, a, b, counts)
  local tol = magnitude(a, b) * 2 ^ -50
  for _, order in ipairs({ { a, b }, { b, a } }) do
    local p, q = order[1], order[2]
    local both, oneSided = oracle.collides(p, q, true), oracle.collides(p, q, false)
    t:check(polygon.polygonsCollide(p, q) == both, "polygonsCollide", p, q, "expected", both)
    t:check(polygon.polygonCollidesWith(p, q) == oneSided, "polygonCollidesWith", p, q, "expected", oneSided)
    local o, dx, dy = polygon.polygonsCollideV(p, q)
    t:check((o ~= false) == both, "polygonsCollideV false iff polygonsCollide is", p, q)
    if both and o then
      counts.colliding = counts.colliding + 1
      local depth = oracle.depth(p, q, true)
      t:check(math.abs(o - depth) <= tol, "depth", p, q, o, "exact", depth)
      counts.excess = math.max(counts.excess, math.abs(o - depth) / tol)
      t:check(math.abs(math.sqrt(dx * dx + dy * dy) - o) <= tol, "|(dx, dy)| == overlap", p, q, o, dx, dy)
      local after = oracle.depth(p, moved(q, dx, dy), true)
      t:check(after <= tol, "no overlap after the move", p, q, dx, dy, "depth after", after)
      t:check(after >= -tol, "touching after the move", p, q, dx, dy, "depth after", after)
    elseif not both then
      local depth = oracle.depth(p, q, true)
      if depth == 0 then counts.touching = counts.touching + 1 end
    end
    local o1, dx1, dy1 = polygon.polygonCollidesWithV(p, q)
    t:check((o1 ~= false) == oneSided, "polygonCollidesWithV false iff polygonCollidesWith is", p, q)
    if oneSided and o1 then
      local depth = oracle.depth(p, q, false)
      t:check(math.abs(o1 - depth) <= tol, "one-sided depth", p, q, o1, "exact", depth)
      local after = oracle.depth(p, moved(q, dx1, dy1), false)
      t:check(after <= tol, "no overlap on p's axes after the move", p, q, dx1, dy1, "depth after", after)
    end
  end
end

describe("convex pairs around touching", function()
  for _, offset in ipairs({ 0, 1e3, 1e6 }) do
    it(("agree with the exact SAT, with depth and displacement, at offset %g"):format(offset), function()
      local t = tally.new("pairs at " .. offset)
      local counts = { colliding = 0, touching = 0, excess = 0 }
      for _, pair in ipairs(pairsAround(500 + offset % 997, 40, offset)) do
        assert.are.equal("convex", oracle.polygonType(pair[1]), "the generator should make convex polygons")
        assert.are.equal("convex", oracle.polygonType(pair[2]), "the generator should make convex polygons")
        checkPair(t, pair[1], pair[2], counts)
      end
      t:report((" (colliding %d, exactly touching %d, largest |overlap - exact| %.1f M 2^-50)")
        :format(counts.colliding, counts.touching, counts.excess))
      assert.are.equal(0, t.count, t:message())
      assert.is_true(counts.colliding > 10, "colliding cases: " .. counts.colliding)
      assert.is_true(counts.touching > 20, "exactly touching cases: " .. counts.touching)
    end)
  end

  -- up to 8 vertices LuaJIT's one-sided test projects in a loop of a constant count, beyond
  -- that in one as long as the larger polygon: pairs of sizes on both sides of 8
  it("agree with the exact SAT for polygons of 3 to 14 vertices, at offset 1e3", function()
    local t = tally.new("pairs of 3 to 14 vertices")
    local counts = { colliding = 0, touching = 0, excess = 0 }
    local large = 0
    for _, pair in ipairs(pairsAround(909, 60, 1e3, 14)) do
      if #pair[1] > 16 or #pair[2] > 16 then large = large + 1 end
      checkPair(t, pair[1], pair[2], counts)
    end
    t:report((" (colliding %d, exactly touching %d)"):format(counts.colliding, counts.touching))
    assert.are.equal(0, t.count, t:message())
    assert.is_true(large > 20, "pairs with a polygon of more than 8 vertices: " .. large)
    assert.is_true(counts.colliding > 10, "colliding cases: " .. counts.colliding)
    assert.is_true(counts.touching > 20, "exactly touching cases: " .. counts.touching)
  end)
end)

describe("circles around touching a convex polygon", function()
  for _, offset in ipairs({ 0, 1e3, 1e6 }) do
    it(("have the contract's depth and a displacement leaving them touching, at offset %g"):format(offset),
      function()
        local r = prng.new(700 + offset % 991)
        local t = tally.new("circles at " .. offset)
        local colliding, apart = 0, 0
        for _ = 1, 40 do
          local size = r:range(1, 10)
          local a = convex(r, offset + r:range(-5, 5), offset + r:range(-5, 5), size)
          local radius = size * r:range(0.05, 3)
          local ccx, ccy = oracle.center(a)
          local centres = {}
          -- around touching in a random direction, at the vertices, at the centre
          for _ = 1, 4 do
            local angle = r:range(0, 2 * math.pi)
            local ux, uy = math.cos(angle), math.sin(angle)
            local s = support(a, ux, uy, 1) - (ccx * ux + ccy * uy) + radius + r:pick(GAPS) * size
            centres[#centres + 1] = { ccx + s * ux, ccy + s * uy }
          end
          local k = r:int(1, #a / 2)
          centres[#centres + 1] = { a[2 * k - 1], a[2 * k] }
          centres[#centres + 1] = { ccx, ccy }
          for _, c in ipairs(centres) do
            local cx, cy = c[1], c[2]
            local tol = 2 ^ -46 * (magnitude(a, { cx, cy }) + radius)
            local depth = oracle.circleDepth(a, cx, cy, radius)
            local o, dx, dy = polygon.polygonCircleCollideV(a, cx, cy, radius)
            if depth > tol then
              colliding = colliding + 1
              t:check(o ~= false, "should collide", a, cx, cy, radius, "depth", depth)
              if o then
                t:check(math.abs(o - depth) <= tol, "depth", a, cx, cy, radius, o, "exact", depth)
                t:check(math.abs(math.sqrt(dx * dx + dy * dy) - o) <= tol, "|(dx, dy)| == overlap", o, dx, dy)
                local after = oracle.circleDepth(a, cx + dx, cy + dy, radius)
                t:check(math.abs(after) <= tol, "touching after the move", a, cx, cy, radius, dx, dy, after)
              end
            elseif depth < -tol then
              apart = apart + 1
              t:check(o == false, "should not collide", a, cx, cy, radius, "depth", depth)
            else
              t:check(o == false or o <= 2 * tol, "within rounding of touching", a, cx, cy, radius, o)
            end
          end
        end
        t:report((" (colliding %d, apart %d)"):format(colliding, apart))
        assert.are.equal(0, t.count, t:message())
        assert.is_true(colliding > 50 and apart > 20, ("colliding %d, apart %d"):format(colliding, apart))
      end)
  end
end)

-- Hard cases for the separating axis functions: pairs about 1e-77 in size (where a product of
-- an area and a cross product underflows), non-finite coordinates, and Lua 5.3/5.4 integers
-- beyond 2^53 (compared only after conversion to doubles).


local translate, reverse = shapes.translate, shapes.reverse

local scaled = shapes.scale

local UNIT = { 0, 0, 1, 0, 1, 1, 0, 1 }

describe("polygons about 1e-77 in size", function()
  local K = 2^-256   -- ~8.6e-78: a power of two, so scaling is exact and keeps every answer
  -- UNIT and UNIT moved right by 1 - 2^-52 overlap by 2^-52 (one ulp of 1), by 1: touch,
  -- by 1 + 2^-52: apart. The same after scaling by K: the twice-area of a scaled square is
  -- 2^-512 and a cross product of its edges about 2^-564, whose product (2^-1076) underflows.
  local cases = {
    { dx = 1 - 2^-52, collides = true },
    { dx = 1, collides = false },
    { dx = 1 + 2^-52, collides = false },
    { dx = 0.5, dy = 1 - 2^-53, collides = true },
    { dx = 0.5, dy = 1, collides = false },
  }

  it("decide touching and one-ulp overlaps as at size 1, in both orders and windings", function()
    for _, case in ipairs(cases) do
      local b = translate(UNIT, case.dx, case.dy or 0)
      local orders = { { UNIT, b }, { b, UNIT }, { reverse(UNIT), b }, { UNIT, reverse(b) } }
      for _, pair in ipairs(orders) do
        local p, q = scaled(pair[1], K), scaled(pair[2], K)
        assert.are.equal(case.collides, polygon.polygonsCollide(p, q))
        assert.are.equal(case.collides, polygon.polygonCollidesWith(p, q))
        assert.are.equal(case.collides, polygon.polygonsCollideV(p, q) ~= false)
        assert.are.equal(case.collides, oracle.collides(p, q, true))
      end
    end
  end)

  it("push scaled pairs apart in one step", function()
    for _, case in ipairs(cases) do
      if case.collides then
        local p, q = scaled(UNIT, K), scaled(translate(UNIT, case.dx, case.dy or 0), K)
        local o, dx, dy = polygon.polygonsCollideV(p, q)
        assert.is_true(o > 0)
        assert.is_false(polygon.polygonsCollide(p, translate(q, dx, dy)))
        assert.is_false(oracle.collides(p, translate(q, dx, dy), true))
      end
    end
  end)

  it("agree with the oracle on random near-touching pairs scaled by 2^-256", function()
    local rng = prng.new(1077)
    local t = tally.new("scaled near-touching pairs")
    for _ = 1, 60 do
      -- a triangle and a square sharing the line x = 1 to within a few ulps
      local e = rng:int(-3, 3) * 2^-52
      local a = { 0, 0, 1, rng:range(0, 1), 0, 1 }
      local b = { 1 + e, -1, 3, -1, 3, 2, 1 + e, 2 }
      local p, q = scaled(a, K), scaled(b, K)
      local expected = oracle.collides(a, b, true)
      t:check(polygon.polygonsCollide(p, q) == expected, a, b)
      t:check(polygon.polygonsCollide(q, p) == expected, b, a)
      t:check(oracle.collides(p, q, true) == expected, "oracle scaled", a, b)
    end
    assert(t.count == 0, t:message())
  end)
end)

describe("non-finite coordinates", function()
  local functions = { "polygonsCollide", "polygonsCollideV", "polygonCollidesWith",
    "polygonCollidesWithV" }
  local values = { 0 / 0, math.huge, -math.huge }

  it("raise an error naming the function and the argument, at the caller's line", function()
    for _, fname in ipairs(functions) do
      for _, bad in ipairs(values) do
        for position = 1, #UNIT do
          local b = translate(UNIT, 0.5, 0.5)
          b[position] = bad
          for argument = 1, 2 do
            local ok, message = pcall(function()
              local result   -- not a tail call, so the error has this line to point at
              if argument == 1 then
                result = polygon[fname](b, UNIT)
              else
                result = polygon[fname](UNIT, b)
              end
              return result
            end)
            assert.is_false(ok)
            local expected = ("sat_hard_spec%%.lua:%%d+: %s: points%d holds a non%%-finite "
              .. "coordinate"):format(fname, argument)
            assert.is_truthy(tostring(message):find(expected), tostring(message))
          end
        end
      end
    end
  end)

  it("are not confused with finite coordinates whose sums overflow", function()
    -- 1e300 squared overflows the size sums, but every coordinate is finite: no error
    local big = scaled(UNIT, 1e300)
    local shifted = translate(big, 0.5e300, 0.5e300)
    assert.is_true(polygon.polygonsCollide(big, shifted))
    assert.is_false(polygon.polygonsCollide(big, translate(big, 2e300, 0)))
  end)
end)

describe("Lua 5.3/5.4 integers beyond 2^53", function()
  local ints = shapes.integers
  -- Odd integers past 2^53 are not doubles: B + 1 converts to B (ties to even), B + 3 to B + 4.
  -- Each pair is decided on the doubles the integers convert to.
  local B = shapes.integer(2 ^ 53) -- an integer where Lua has them, so B + 1 is exact

  it("answer as the converted doubles, and one push separates them", function()
    local rng = prng.new(53)
    local t = tally.new("integers beyond 2^53")
    local notDoubles = 0 -- coordinates that no double equals (only where Lua has integers)
    for _ = 1, 40 do
      local x, y = B + rng:int(0, 64), B + rng:int(0, 64)
      local s = rng:int(8, 40)
      local a = { x, y, x + s, y, x + s, y + s, x, y + s }
      local bx, by = x + s - rng:int(-3, 6), y + rng:int(-s, s)
      local b = { bx, by, bx + s + 1, by + 1, bx + s, by + s + 3, bx - 1, by + s }
      local ai, bi = ints(a), ints(b)
      for _, v in ipairs(ai) do
        if shapes.integer(v + 0.0) ~= v then notDoubles = notDoubles + 1 end
      end
      local expected = oracle.collides(shapes.floats(a), shapes.floats(b), true)
      t:check(polygon.polygonsCollide(ai, bi) == expected, "collide", a, b)
      t:check(polygon.polygonsCollide(bi, ai) == expected, "collide reversed", a, b)
      local o, dx, dy = polygon.polygonsCollideV(ai, bi)
      t:check((o ~= false) == expected, "collideV", a, b)
      if o then
        t:check(not polygon.polygonsCollide(ai, translate(bi, dx, dy)), "push", a, b, dx, dy)
      end
    end
    assert(t.count == 0, t:message())
    if rawget(math, "type") then
      assert.is_true(notDoubles > 0, "no coordinate was an integer beyond the doubles")
    end
  end)
end)

-- The exact kernel's loop-free path: when every coordinate difference is exact (nearby
-- coordinates, the usual case for touching shapes) the sign of the determinant comes from four
-- parts (the difference of two exact products) instead of the general expansion. Triangles
-- whose vertex lies on the line of the other's edge, or a few ulps off it, at scales from 2^-30
-- to 2^30 and offsets up to 2^40, decide touching exactly as the oracle does.
describe("a vertex on another polygon's edge line, coordinates on a grid", function()
  it("is decided as the oracle decides, in both orders", function()
    local r = prng.new(8071)
    local cases, touching = 0, 0
    for _ = 1, 3000 do
      local scale = 2 ^ r:int(-30, 30)
      local offset = r:int(0, 1) == 1 and 2 ^ r:int(0, 40) or 0
      local function grid() return offset + r:int(0, 63) * scale end
      local ax, ay, bx, by, cx, cy = grid(), grid(), grid(), grid(), grid(), grid()
      -- B's first vertex on the line a-b, at a + k (b - a), maybe nudged by a few ulps
      local k = r:int(-2, 3)
      local px, py = ax + k * (bx - ax), ay + k * (by - ay)
      if r:int(0, 1) == 1 then px = px + r:int(-3, 3) * scale * 2 ^ -r:int(20, 52) end
      local a = { ax, ay, bx, by, cx, cy }
      local b = { px, py, px + r:int(-9, 9) * scale, py - 9 * scale,
                  px - 9 * scale, py + r:int(-9, 9) * scale }
      if oracle.winding(a) and oracle.winding(b) then
        cases = cases + 1
        local want = oracle.collides(a, b, true)
        if not want then touching = touching + 1 end
        assert.are.equal(want, polygon.polygonsCollide(a, b))
        assert.are.equal(want, polygon.polygonsCollide(b, a))
      end
    end
    assert.is_true(cases > 2000 and touching > 100)
  end)
end)
