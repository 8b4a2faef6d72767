-- One push separates: for random convex pairs at offsets from 1 to 1e12, in both argument orders,
-- with overlaps from deep to a few ulps, polygonsCollideV (and polygonCollidesWithV) return a push
-- (dx, dy) such that after adding it to every vertex of the second polygon, rounded the way a game
-- does it (p[i] = p[i] + dx), the module's exact predicate says the pair no longer collides, and
-- the independent oracle agrees. The push is at most 8 eps M longer than the oracle's exact least
-- penetration depth (M: the largest coordinate magnitude of the pair, eps = 2^-53).
--
-- Measured with POLYGON_SPEC_COUNTS=1 (lua5.4 /usr/bin/busted spec/sat_push_spec.lua): before the
-- separating push (polygon.lua at eda3a2c) most colliding pairs were still colliding after the
-- push (181 of 380 pairs), now none; the README's Accuracy section has the counts.

local polygon = require "polygon"
local prng = require "prng"
local shapes = require "shapes"
local tally = require "tally"
local checkPush = require "pushcheck"

local translate, reverse, ulp = shapes.translate, shapes.reverse, shapes.ulp
local EPS = 2^-53
local OFFSETS = { 1, 1e3, 1e6, 1e9, 1e12 }
local PAIRS_PER_OFFSET = 24

-- A convex polygon of 3 to 8 vertices on a circle of the given radius around (cx, cy), in either
-- winding. Consecutive angles are at least 0.3 of the even spacing apart, so every turn is clear
-- of rounding.
local function convexPolygon(rng, cx, cy, radius)
  local m = rng:int(3, 8)
  local points = {}
  for i = 1, m do
    local angle = (i - 1 + rng:range(-0.35, 0.35)) * 2 * math.pi / m
    points[2 * i - 1] = cx + radius * math.cos(angle)
    points[2 * i] = cy + radius * math.sin(angle)
  end
  if rng:int(0, 1) == 1 then points = reverse(points) end
  return points
end

local largestMagnitude = shapes.largestMagnitude

-- Pairs near (x, y): deep and shallow overlaps, misses, and from each colliding pair a copy
-- moved out by the module's push and back by 1 to 8 ulps (overlaps of a few ulps or touching).
local function pairsAt(rng, offset)
  local list = {}
  for _ = 1, PAIRS_PER_OFFSET do
    local sx, sy = rng:pick({ -1, 1 }), rng:pick({ -1, 1 })
    local cx, cy = sx * offset * rng:range(0.5, 1), sy * offset * rng:range(0.5, 1)
    local r1, r2 = rng:range(0.5, 20), rng:range(0.5, 20)
    local a = convexPolygon(rng, cx, cy, r1)
    local angle, reach = rng:range(0, 2 * math.pi), rng:range(0, 1.05) * (r1 + r2)
    local b = convexPolygon(rng, cx + reach * math.cos(angle), cy + reach * math.sin(angle), r2)
    list[#list + 1] = { a, b }
    local o, dx, dy = polygon.polygonsCollideV(a, b)
    if o and (dx ~= 0 or dy ~= 0) then
      local step = rng:int(1, 8) * ulp(largestMagnitude(a, b))
      local back = translate(translate(b, dx, dy), dx > 0 and -step or dx < 0 and step or 0,
        dy > 0 and -step or dy < 0 and step or 0)
      list[#list + 1] = { a, back }
    end
  end
  return list
end

describe("one push separates (polygonsCollideV, polygonCollidesWithV)", function()
  for _, both in ipairs({ true, false }) do
    local name = both and "polygonsCollideV" or "polygonCollidesWithV"
    it(name .. ": random convex pairs at offsets 1 to 1e12, both orders, deep to a few ulps",
      function()
        local rng = prng.new(both and 20261122 or 4242)
        local counts = {
          answers = tally.new(name .. " collides as the oracle says"),
          separations = tally.new(name .. " moved pair no longer collides"),
          excesses = tally.new(name .. " push longer than the depth by more than 8 eps M"),
        }
        local answers, separations, excesses = counts.answers, counts.separations, counts.excesses
        local worst = 0
        for _, offset in ipairs(OFFSETS) do
          for _, pair in ipairs(pairsAt(rng, offset)) do
            for _, order in ipairs({ { pair[1], pair[2] }, { pair[2], pair[1] } }) do
              local excess = checkPush(order[1], order[2], both, counts, true)
              worst = math.max(worst, excess)
            end
          end
        end
        local colliding = separations.total
        answers:report()
        separations:report((" (%d colliding)"):format(colliding))
        excesses:report((", largest excess %.2f eps M"):format(worst))
        assert(colliding > 100, "too few colliding pairs to say anything")
        assert(answers.count == 0, answers:message())
        assert(separations.count == 0, separations:message())
        assert(excesses.count == 0, excesses:message())
      end)
  end

  it("a depth within rounding of zero still gets a push that separates", function()
    -- B overlaps A = [0,1]^2 by one ulp of 1e6 + 1 (2^-33 ~ 1.2e-10) at offset 1e6:
    -- A's right edge is x = 1e6 + 1, B's left edge 1e6 + 1 - 2^-33
    local x0 = 1e6
    local a = { x0, x0, x0 + 1, x0, x0 + 1, x0 + 1, x0, x0 + 1 }
    local left = x0 + 1 - 2^-33
    local b = { left, x0, left + 1, x0, left + 1, x0 + 1, left, x0 + 1 }
    assert.is_true(polygon.polygonsCollide(a, b))
    local o, dx, dy = polygon.polygonsCollideV(a, b)
    assert.is_true(o > 0 and dx > 0 and dy == 0)
    assert.is_false(polygon.polygonsCollide(a, translate(b, dx, dy)))
    -- the exact depth is 2^-33 and M = 1e6 + 2: at most 8 eps M ~ 8.9e-10 longer
    assert.is_true(o <= 2^-33 + 8 * EPS * (x0 + 2))
  end)
end)
