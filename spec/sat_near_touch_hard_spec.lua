-- Pairs within a few ulps of touching, from 1 to 2^40 from the origin: polygonsCollide and
-- polygonsCollideV answer as the independent oracle (exact, big integers) does. These are the
-- pairs whose edges the SAT's rounded projections cannot place, so they test its error bound and
-- tolerance (an edge decided by the rounded projection alone must have the exact sign) and its
-- exact fallback. Each case is tried in both argument orders.

local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local shapes = require "shapes"
local tally = require "tally"

local translate = shapes.translate
local OFFSETS = { 1, 2^10, 1e6, 1e9, 2^32, 2^40 }
local CASES_PER_OFFSET = 40

local ulp = shapes.ulp   -- (m >= 1 here)

-- Vertex k (1-based, odd index into the flat array) and the next one, cyclically.
local function nextIndex(points, k)
  return k + 2 > #points and 1 or k + 2
end

-- Near-touching partners of p: q moved so that a point of one of its edges lands on a vertex of
-- p, q moved so that one of its vertices lands on one of p's, and p reflected through the middle
-- of one of its edges (the edge shared, reversed); each then nudged by a few ulps either way.
local function nearTouching(rng, p, q, offset)
  local step = ulp(shapes.largestMagnitude(p, q) + offset)
  local v = 2 * rng:int(1, #p / 2) - 1
  local k = 2 * rng:int(1, #q / 2) - 1
  local k2 = nextIndex(q, k)
  local t = rng:float()
  local ex, ey = q[k] + t * (q[k2] - q[k]), q[k + 1] + t * (q[k2 + 1] - q[k + 1])
  local w = nextIndex(p, v)
  local reflected = {}
  for i = 1, #p, 2 do
    reflected[i], reflected[i + 1] = p[v] + p[w] - p[i], p[v + 1] + p[w + 1] - p[i + 1]
  end
  local list = {}
  for _, base in ipairs({ translate(q, p[v] - ex, p[v + 1] - ey),
                          translate(q, p[v] - q[k], p[v + 1] - q[k + 1]), reflected }) do
    local nudgeX, nudgeY = rng:int(-3, 3) * step, rng:int(-3, 3) * step
    list[#list + 1] = base
    list[#list + 1] = translate(base, nudgeX, nudgeY)
  end
  return list
end

describe("polygonsCollide near touching, offsets 1 to 2^40 (hard cases)", function()
  it("two unit squares sharing an edge at 2^40 touch; one ulp (2^-12) closer they overlap", function()
    -- at 2^40 doubles are 2^(40 - 52) = 2^-12 apart, so 2^40 + 1 and 2^40 + 1 - 2^-12 are exact
    local x = 2^40
    local left = { x, x, x + 1, x, x + 1, x + 1, x, x + 1 }
    local right = { x + 1, x, x + 2, x, x + 2, x + 1, x + 1, x + 1 }
    assert.is_false(polygon.polygonsCollide(left, right))
    assert.is_false(polygon.polygonsCollideV(left, right))
    local closer = translate(right, -2^-12, 0)
    assert.is_true(polygon.polygonsCollide(left, closer))
    -- the overlap is 2^-12 along x: the second, closer, must move +2^-12 (up to the push's own rounding)
    local depth, dx, dy = polygon.polygonsCollideV(left, closer)
    assert.is_true(depth >= 2^-12 and depth <= 2^-12 * (1 + 2^-40))
    assert.is_true(dx > 0 and dy == 0)
  end)

  it("random convex pairs within 3 ulps of touching agree with the oracle, both orders", function()
    local rng = prng.new(20261123)
    local wrong = tally.new("polygonsCollide(V) near touching as the oracle says")
    local colliding = 0
    for _, offset in ipairs(OFFSETS) do
      for _ = 1, CASES_PER_OFFSET do
        local p = shapes.convex(rng, rng:int(3, 8), offset + rng:range(-5, 5),
          offset + rng:range(-5, 5), rng:range(0.5, 20), 0.3)
        local q = shapes.convex(rng, rng:int(3, 8), offset + rng:range(-5, 5),
          offset + rng:range(-5, 5), rng:range(0.5, 20), 0.3)
        for _, partner in ipairs(nearTouching(rng, p, q, offset)) do
          for _, order in ipairs({ { p, partner }, { partner, p } }) do
            local a, b = order[1], order[2]
            local expected = oracle.collides(a, b, true)
            local depth = polygon.polygonsCollideV(a, b)
            wrong:check(polygon.polygonsCollide(a, b) == expected
              and (depth ~= false) == expected, a, b, expected)
            if expected then colliding = colliding + 1 end
          end
        end
      end
    end
    wrong:report((" (%d colliding)"):format(colliding))
    -- both answers must occur often, or the cases would not test the boundary
    assert(colliding > wrong.total / 5 and colliding < wrong.total * 4 / 5,
      ("colliding %d of %d"):format(colliding, wrong.total))
    assert(wrong.count == 0, wrong:message())
  end)
end)
