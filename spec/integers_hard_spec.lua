-- Hard cases, family 5: large integer coordinates.
--
-- On Lua 5.3 and 5.4 these coordinates are of the integer subtype (math.type(x) == "integer"),
-- whose products wrap silently past 2^63: with coordinates around 2^40 .. 2^52 every cross
-- product passes 2^63. The contract converts integers to doubles before any arithmetic, so the
-- answers must be those for the same values given as floats, and those of the exact oracle.
-- On Lua 5.1, 5.2 and LuaJIT there is no integer subtype: the same specs run on floats there
-- (and still compare with the oracle).

local polygon = require "polygon"
local oracle = require "oracle"
local exact = require "exact"
local prng = require "prng"
local tally = require "tally"
local helpers = require "shapes" -- (this file's `shapes` are its polygons)

-- int(x): x as a Lua integer where there is one; ints, floats: copies of an array as integers, floats
local int, ints, floats = helpers.integer, helpers.integers, helpers.floats

-- math.type exists from Lua 5.3 on (rawget: luacheck's std is the common one)
local mathType = rawget(math, "type")
local hasIntegers = mathType ~= nil and mathType(1) == "integer"
local SUBTYPE = hasIntegers and "integer subtype" or "floats (no integer subtype on this Lua)"

-- Near-collinear triangles: p0 = (a, b), p1 = p0 + (x1, y1), p2 = p0 + 2 (x1, y1) + (e1, e2), with
-- x1, y1 even numbers near 2^50 and e1, e2 in -1 .. 1. The cross product is then
-- x1 e2 - y1 e1: tiny next to the 2^100-sized products it comes from.
local function nearCollinear(r)
  local a, b = r:int(-2 ^ 30, 2 ^ 30) * 1024, r:int(-2 ^ 30, 2 ^ 30) * 1024
  local x1 = (r:int(2 ^ 28, 2 ^ 29) * 2 ^ 21 + r:int(0, 2 ^ 20)) * 2
  local y1 = (r:int(2 ^ 28, 2 ^ 29) * 2 ^ 21 + r:int(0, 2 ^ 20)) * 2
  if r:int(0, 1) == 1 then x1 = -x1 end
  local e1, e2 = r:int(-1, 1), r:int(-1, 1)
  return { a, b, a + x1, b + y1, a + 2 * x1 + e1, b + 2 * y1 + e2 }, a + x1 / 2, b + y1 / 2
end

describe("large integer coordinates, as " .. SUBTYPE, function()
  it("are of the integer subtype where Lua has one", function()
    local p = ints({ 2 ^ 52, 1 })
    if hasIntegers then
      assert.are.equal("integer", mathType(p[1]))
    else
      assert.are.equal(2 ^ 52, p[1])
    end
  end)

  it("give near-collinear triangles the exact winding and type, as floats do", function()
    local r = prng.new(9001)
    local t = tally.new("integer triangles")
    local zero = 0
    for _ = 1, 300 do
      local tri = nearCollinear(r)
      local ti, tf = ints(tri), floats(tri)
      local expected = oracle.winding(tf)
      if expected == nil then zero = zero + 1 end
      local got = polygon.polygonWindingOrder(ti)
      t:check(got == expected, "winding (integers)", ti, got, "expected", expected)
      t:check(polygon.polygonWindingOrder(tf) == expected, "winding (floats)", tf)
      -- a quadrilateral with a fourth corner far off the line p0 p2: convex or concave as p1 lies
      local quad = { tri[1], tri[2], tri[3], tri[4], tri[5], tri[6], tri[3] + 2 ^ 40, tri[4] - 2 ^ 41 }
      local qi, qf = ints(quad), floats(quad)
      local kind = oracle.polygonType(qf)
      t:check(polygon.polygonType(qi) == kind, "type (integers)", qi, polygon.polygonType(qi), kind)
      t:check(polygon.polygonType(qf) == kind, "type (floats)", qf)
    end
    assert.are.equal(0, t.count, t:message())
    assert.is_true(zero > 10 and zero < 290, "both collinear and non-collinear cases: " .. zero)
  end)

  it("place points on and beside the edges of such triangles exactly", function()
    local r = prng.new(9002)
    local t = tally.new("integer contains")
    for _ = 1, 150 do
      local tri, mx, my = nearCollinear(r)
      -- a fatter triangle sharing the edge p0 p1, whose midpoint (mx, my) is an integer on it
      local fat = { tri[1], tri[2], tri[3], tri[4], tri[1] - 2 ^ 45, tri[4] + 2 ^ 46 }
      for _, shape in ipairs({ tri, fat }) do
        local si, sf = ints(shape), floats(shape)
        for _, d in ipairs({ { 0, 0 }, { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 }, { 2, -2 } }) do
          local x, y = mx + d[1], my + d[2]
          local expected = oracle.contains(sf, x, y)
          t:check(polygon.polygonContains(si, int(x), int(y)) == expected, "contains (integers)", si, x, y)
          t:check(polygon.polygonContains(sf, x + 0.0, y + 0.0) == expected, "contains (floats)", sf, x, y)
        end
        -- the vertices themselves
        for i = 1, 5, 2 do
          local expected = oracle.contains(sf, shape[i], shape[i + 1])
          t:check(polygon.polygonContains(si, si[i], si[i + 1]) == expected, "vertex", si, i)
        end
      end
      assert.is_true(oracle.onSegment(tri[1], tri[2], tri[3], tri[4], mx, my))
    end
    assert.are.equal(0, t.count, t:message())
  end)

  it("keep touching integer tiles apart, with the exact area, as floats do", function()
    local t = tally.new("integer tiles")
    for _, base in ipairs({ 2 ^ 40, 2 ^ 46, 2 ^ 52 - 2 ^ 34 }) do
      local s = 2 ^ 32 + 12345 -- tile size: products of two sizes pass 2^64
      -- two squares sharing a vertical edge, split into four triangles along slanted diagonals
      local x0, x1, x2, y0, y1 = base, base + s, base + 2 * s, -base, -base + s
      local shapes = {
        { x0, y0, x1, y0, x1, y1, x0, y1 },
        { x1, y0, x2, y0, x2, y1, x1, y1 },
        { x0, y0, x1, y0, x1, y1 },
        { x0, y0, x1, y1, x0, y1 },
        { x1, y0, x2, y1, x1, y1 },
        { x1, y0, x2, y0, x2, y1 },
      }
      local function pair(i, j)
        local a, b = ints(shapes[i]), ints(shapes[j])
        local af, bf = floats(shapes[i]), floats(shapes[j])
        t:check(oracle.collides(af, bf, true) == false, "oracle", i, j)
        t:check(polygon.polygonsCollide(a, b) == false, "polygonsCollide", base, i, j)
        t:check(polygon.polygonsCollideV(a, b) == false, "polygonsCollideV", base, i, j)
        local oneSided = oracle.collides(af, bf, false)
        t:check(polygon.polygonCollidesWith(a, b) == oneSided, "polygonCollidesWith", base, i, j)
        t:check(polygon.polygonCollidesWith(af, bf) == oneSided, "floats", base, i, j)
      end
      pair(1, 2); pair(2, 1); pair(3, 4); pair(4, 3); pair(4, 5); pair(5, 4); pair(5, 6); pair(3, 6)
      -- points of the shared edges: each in exactly one of the two tiles
      local mid = y0 + (s - 1) / 2 -- an integer: s is odd
      for _, q in ipairs({ { x1, mid }, { x1, y0 }, { x1, y1 }, { x1 - 1, mid }, { x1 + 1, mid } }) do
        local n = 0
        for k = 1, 2 do
          if polygon.polygonContains(ints(shapes[k]), int(q[1]), int(q[2])) then n = n + 1 end
          t:check(polygon.polygonContains(ints(shapes[k]), int(q[1]), int(q[2]))
            == oracle.contains(floats(shapes[k]), q[1], q[2]), "contains", base, k, q)
        end
        t:check(n == (q[2] == y0 and 0 or 1), "in one tile", base, q, n)
      end
      -- the diagonal of the left square: x - x0 == y - y0 on it
      local dq = { x0 + 1000, y0 + 1000 }
      local n = 0
      for k = 3, 4 do
        if polygon.polygonContains(ints(shapes[k]), int(dq[1]), int(dq[2])) then n = n + 1 end
      end
      t:check(oracle.onSegment(x0, y0, x1, y1, dq[1], dq[2]) and n == 1, "diagonal point in one", base, n)
      -- areas: s^2 and s^2 / 2 (exact as doubles? s^2 = 2^64 + ... needs 66 bits: not exact,
      -- which is what the 1-ulp check of polygonAreaAccurate is for)
      for k = 1, 6 do
        local a = oracle.area(floats(shapes[k]))
        local ai = polygon.polygonAreaAccurate(ints(shapes[k]))
        local af = polygon.polygonAreaAccurate(floats(shapes[k]))
        t:check(ai == af and exact.withinUlps(ai, a, 1), "polygonAreaAccurate", base, k, ai, af)
        t:check(exact.withinUlps(polygon.polygonArea(ints(shapes[k])), a, 4), "polygonArea", base, k)
        t:check(polygon.polygonWindingOrder(ints(shapes[k])) == "cw", "winding", base, k)
        t:check(polygon.polygonType(ints(shapes[k])) == "convex", "type", base, k)
      end
    end
    assert.are.equal(0, t.count, t:message())
  end)

  it("beyond 2^53 and up to 2^62 answer as the doubles the integers convert to", function()
    -- The contract converts integers to doubles first; past 2^53 that rounds, and past 2^62 a
    -- difference of two integers would wrap. Compare integer input with its float conversion.
    local H = 2 ^ 62
    local shapes = {
      { -H, -H, H, -H, H, H, -H, H }, -- a square of side 2^63
      { -H, -H, H, H, -H, H }, -- its upper-left half
      { 2 ^ 60 + 2 ^ 8, 2 ^ 61 - 2 ^ 9, -2 ^ 61, 2 ^ 60 + 2 ^ 10, 2 ^ 59, -2 ^ 62 + 2 ^ 10 },
      { 2 ^ 54 + 2, 2 ^ 54 + 6, 2 ^ 55 + 8, 2 ^ 55 + 16, 2 ^ 56 + 20, 2 ^ 56 + 40, 0, 2 ^ 56 },
    }
    local t = tally.new("beyond 2^53")
    for k, shape in ipairs(shapes) do
      local si, sf = ints(shape), floats(shape)
      local winding = polygon.polygonWindingOrder(si)
      t:check(winding == oracle.winding(sf), "winding", k, winding)
      t:check(polygon.polygonType(si) == oracle.polygonType(sf), "type", k, polygon.polygonType(si))
      t:check(polygon.polygonAreaAccurate(si) == polygon.polygonAreaAccurate(sf), "area", k)
      t:check(exact.withinUlps(polygon.polygonAreaAccurate(si), oracle.area(sf), 1), "area exact", k)
      for _, q in ipairs({ { 0, 0 }, { 2 ^ 61, 2 ^ 61 }, { -2 ^ 61, 2 ^ 61 }, { H, 0 }, { 0, H } }) do
        local expected = oracle.contains(sf, q[1], q[2])
        t:check(polygon.polygonContains(si, int(q[1]), int(q[2])) == expected, "contains", k, q)
      end
      for j, other in ipairs(shapes) do
        local oi, of = ints(other), floats(other)
        t:check(polygon.polygonsCollide(si, oi) == oracle.collides(sf, of, true), "collide", k, j)
        t:check(polygon.polygonCollidesWith(si, oi) == oracle.collides(sf, of, false), "collideWith", k, j)
      end
    end
    assert.are.equal(0, t.count, t:message())
  end)
end)

-- Lua 5.3+ integers beyond 2^53: a coordinate counts as the double it converts to, in
-- comparisons as well as in arithmetic. Raw comparisons of integers with converted doubles are
-- exact for neither (2^53 + 1 > 2^53.0 as integers, equal as doubles). The integers are made with
-- load() so that this file still loads on Lua 5.1, 5.2 and LuaJIT, where it is skipped.

local loader = rawget(_G, "loadstring") or load
local chunk = loader("return 1 << 53")

local B = chunk and mathType and chunk()

-- the same points as doubles
local function converted(points)
  local out = {}
  for i = 1, #points do out[i] = points[i] + 0.0 end
  return out
end

local describeIntegers = B and describe or pending

describeIntegers("integer coordinates beyond 2^53", function()
  it("are integers here (the spec is not vacuous)", function()
    assert.are.equal("integer", mathType(B - 4))
  end)

  it("make polygonType concave both as integers and as the doubles they convert to", function()
    -- As doubles: (B-4, B), (B-1, B+4), (B+4, B-1), (B, B), (B, B) (B+3 rounds to B+4 and
    -- B+1 to B). Turns (e x f): at (B-1, B+4) (3, 4) x (5, -5) = -35, at (B+4, B-1)
    -- (5, -5) x (-4, 1) = -15, at (B, B) (-4, 1) x (-4, 0) = +4: concave.
    -- As integers: at (B-1, B+3) (3, 3) x (4, -4) = -24, at (B+3, B-1) (4, -4) x (-3, 2) = -4,
    -- at (B, B+1) (-3, 2) x (0, -1) = +3: concave.
    local p = { B - 4, B, B - 1, B + 3, B + 3, B - 1, B, B + 1, B, B }
    assert.are.equal("concave", polygon.polygonType(converted(p)))
    assert.are.equal("concave", polygon.polygonType(p))
  end)

  it("give polygonContains the answer of the converted polygon", function()
    -- B + 3 converts to B + 4: the converted square's top edge is at y = B + 4, and the point
    -- (8, B + 4) lies on its half-open boundary, inside (the right edge crosses its ray)
    local p = { 0, B - 8, 16, B - 8, 16, B + 3, 0, B + 3 }
    local y = (B + 4) + 0.0
    assert.is_true(polygon.polygonContains(converted(p), 8, y))
    assert.is_true(polygon.polygonContains(p, 8, y))
    assert.are.equal(polygon.polygonContains(converted(p), 8, B + 3), polygon.polygonContains(p, 8, B + 3))
  end)

  it("give polygonContains the answer of the converted polygon in x too", function()
    -- B + 3 converts to B + 4: the converted rectangle's right edge is at x = B + 4, and the
    -- point (B + 4, 8) lies on it, inside (the ray from it crosses that edge: x <= B + 4);
    -- as integers it would lie right of B + 3, outside. (B + 2, 8) and (B - 2, 8) are inside
    -- either way; B - 2 is below 2^53, where the PUC interpreters compare x unconverted.
    local p = { 0, 0, B + 3, 0, B + 3, 16, 0, 16 }
    local q = converted(p)
    for _, x in ipairs({ (B + 4) + 0.0, (B + 2) + 0.0, (B - 2) + 0.0, B - 2, B + 0.0 }) do
      assert.is_true(polygon.polygonContains(q, x, 8), "converted, x = " .. x)
      assert.is_true(polygon.polygonContains(p, x, 8), "integers, x = " .. x)
    end
    assert.is_false(polygon.polygonContains(p, (B + 8) + 0.0, 8))
    -- the mirror image: -B - 3 converts to -(B + 4), and a point on that left edge is outside
    -- (its ray crosses both sides), one at -(B + 2) inside
    local m = { 0, 0, -B - 3, 0, -B - 3, 16, 0, 16 }
    local mirrored = { { -(B + 8), false }, { -(B + 4), false }, { -(B + 2), true }, { -(B - 2), true } }
    for _, c in ipairs(mirrored) do
      assert.are.equal(c[2], polygon.polygonContains(converted(m), c[1] + 0.0, 8), "converted")
      assert.are.equal(c[2], polygon.polygonContains(m, c[1] + 0.0, 8), "integers")
    end
  end)

  it("give the measures the values of the converted polygon", function()
    local p = { B - 4, B, B - 1, B + 3, B + 3, B - 1, B, B + 1 }
    local q = converted(p)
    assert.are.equal(polygon.polygonWindingOrder(q), polygon.polygonWindingOrder(p))
    assert.are.equal(polygon.polygonArea(q), polygon.polygonArea(p))
    assert.are.equal(polygon.polygonAreaAccurate(q), polygon.polygonAreaAccurate(p))
    assert.are.same({ polygon.polygonCentroid(q) }, { polygon.polygonCentroid(p) })
    assert.are.same({ polygon.polygonCenter(q) }, { polygon.polygonCenter(p) })
  end)

  it("give the measures the values of the converted polygon for odd and even vertex counts", function()
    -- 3 to 8 vertices whose y are odd integers beyond 2^53, which round when converted: the
    -- loops read every other y unconverted and convert it through its differences
    for m = 3, 8 do
      local p = {}
      for k = 1, m do
        local t = 2 * math.pi * k / m
        p[2 * k - 1] = math.floor(1000 * math.cos(t))
        p[2 * k] = B + (k % 2 == 0 and 1 or 3) + math.floor(1000 * math.sin(t)) * 4
      end
      local q = converted(p)
      assert.are.equal(polygon.polygonWindingOrder(q), polygon.polygonWindingOrder(p), m)
      assert.are.equal(polygon.polygonArea(q), polygon.polygonArea(p), m)
      assert.are.equal(polygon.polygonAreaAccurate(q), polygon.polygonAreaAccurate(p), m)
      assert.is_true(exact.withinUlps(polygon.polygonAreaAccurate(p), oracle.area(q), 1), m)
    end
  end)
end)
