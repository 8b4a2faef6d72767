-- Hard cases for the separating axis functions: pairs about 1e-77 in size (where a product of
-- an area and a cross product underflows), non-finite coordinates, and Lua 5.3/5.4 integers
-- beyond 2^53 (compared only after conversion to doubles).

local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local shapes = require "shapes"
local tally = require "tally"

local translate, reverse = shapes.translate, shapes.reverse

local function scaled(points, k)
  local out = {}
  for i = 1, #points do out[i] = points[i] * k end
  return out
end

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
    local moved = translate(big, 0.5e300, 0.5e300)
    assert.is_true(polygon.polygonsCollide(big, moved))
    assert.is_false(polygon.polygonsCollide(big, translate(big, 2e300, 0)))
  end)
end)

describe("Lua 5.3/5.4 integers beyond 2^53", function()
  local toInteger = rawget(math, "tointeger")
  local function ints(list)
    local out = {}
    for i, v in ipairs(list) do out[i] = toInteger and toInteger(v) or v end
    return out
  end
  -- Odd integers past 2^53 are not doubles: B + 1 converts to B (ties to even), B + 3 to B + 4.
  -- Each pair is decided on the doubles the integers convert to.
  local B = 2^53

  it("answer as the converted doubles, and one push separates them", function()
    local rng = prng.new(53)
    local t = tally.new("integers beyond 2^53")
    for _ = 1, 40 do
      local x, y = B + rng:int(0, 64), B + rng:int(0, 64)
      local s = rng:int(8, 40)
      local a = { x, y, x + s, y, x + s, y + s, x, y + s }
      local bx, by = x + s - rng:int(-3, 6), y + rng:int(-s, s)
      local b = { bx, by, bx + s + 1, by + 1, bx + s, by + s + 3, bx - 1, by + s }
      local ai, bi = ints(a), ints(b)
      local expected = oracle.collides(scaled(a, 1.0), scaled(b, 1.0), true)
      t:check(polygon.polygonsCollide(ai, bi) == expected, "collide", a, b)
      t:check(polygon.polygonsCollide(bi, ai) == expected, "collide reversed", a, b)
      local o, dx, dy = polygon.polygonsCollideV(ai, bi)
      t:check((o ~= false) == expected, "collideV", a, b)
      if o then
        t:check(not polygon.polygonsCollide(ai, translate(bi, dx, dy)), "push", a, b, dx, dy)
      end
    end
    assert(t.count == 0, t:message())
  end)
end)
