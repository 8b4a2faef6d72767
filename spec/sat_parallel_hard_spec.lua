-- Hard cases: convex pairs whose edges are parallel or nearly so, edge against edge, and pairs of
-- many vertices. On PUC Lua the SAT walks both polygons' edges at once in the order of their
-- normals' angles, deciding that order by the sign of a rounded cross product, so nearly
-- parallel edges of the two polygons are exactly where the order can come out wrong; ties
-- (exactly parallel edges) are where the least depth must still go to polygon 1, then to the
-- lower edge end; and many vertices against few make long runs of one polygon's edges.
-- A centrally symmetric polygon A (a regular 4-, 6- or 8-gon, or a rectangle) and a copy B of it
-- turned by a tiny angle about its own centre (0, 1e-16 to 1e-7 radians) and moved along the
-- normal of one of A's edges so that the two edges overlap, touch, or miss by a few ulps, at
-- offsets 1 to 1e9, both windings and both argument orders:
--   * polygonsCollide equals the independent oracle's exact SAT;
--   * polygonsCollideV returns false exactly then, and otherwise a push after which, added to
--     every vertex of the second polygon the way a game does it, both the module and the oracle
--     find the pair apart, no longer than the exact least depth by 8 eps M (M: the largest
--     coordinate magnitude).

local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local shapes = require "shapes"
local tally = require "tally"

local EPS = 2^-53
local translate = shapes.translate

-- m vertices around (cx, cy) at radius r, the first at angle a0; or a rectangle (m = 0).
local function symmetric(m, cx, cy, r, a0)
  local points = {}
  local corners = m == 0 and { a0 + 0.4, a0 + math.pi - 0.4, a0 + math.pi + 0.4, a0 - 0.4 }
  for i = 1, m == 0 and 4 or m do
    local angle = corners and corners[i] or a0 + (i - 1) * 2 * math.pi / m
    points[2 * i - 1] = cx + r * math.cos(angle)
    points[2 * i] = cy + r * math.sin(angle)
  end
  return points
end

-- The tallies of one test, and the check of one ordered pair (p, q) against the oracle.
local function newTallies()
  return {
    answers = tally.new("polygonsCollide and polygonsCollideV as the oracle says"),
    separations = tally.new("moved pair apart for the module and the oracle"),
    excesses = tally.new("push no longer than the exact depth by 8 eps M"),
    colliding = 0,
  }
end

local function checkPair(t, p, q)
  local hit = oracle.collides(p, q, true)
  local o, dx, dy = polygon.polygonsCollideV(p, q)
  t.answers:check(polygon.polygonsCollide(p, q) == hit and (o ~= false) == hit, p, q)
  if not o then return end
  t.colliding = t.colliding + 1
  local moved = translate(q, dx, dy)
  t.separations:check(not polygon.polygonsCollide(p, moved)
    and not oracle.collides(p, moved, true), p, q, dx, dy)
  local big = shapes.largestMagnitude(p, q)
  t.excesses:check(oracle.depthAtLeast(p, q, true, o, 8 * EPS * big), p, q, o)
end

local function assertTallies(t, least)
  t.answers:report(); t.separations:report(); t.excesses:report()
  assert(t.colliding > least, "too few colliding pairs to say anything: " .. t.colliding)
  assert(t.answers.count == 0, t.answers:message())
  assert(t.separations.count == 0, t.separations:message())
  assert(t.excesses.count == 0, t.excesses:message())
end

describe("convex pairs with parallel and nearly parallel edges", function()
  it("collide, and are pushed apart in one step, as the oracle says", function()
    local rng = prng.new(7051)
    local t = newTallies()
    for _, offset in ipairs({ 1, 1e3, 1e6, 1e9 }) do
      for _, turn in ipairs({ 0, 1e-16, 1e-13, 1e-10, 1e-7 }) do
        for _ = 1, 3 do
          local m = rng:pick({ 0, 4, 6, 8 })
          local cx, cy = offset * rng:range(0.5, 1), offset * rng:range(-1, -0.5)
          local r, a0 = rng:range(1, 20), rng:range(0, 2 * math.pi)
          local a = symmetric(m, cx, cy, r, a0)
          -- the copy's centre beyond the edge from vertex 1 to vertex 2, along its normal
          local ex, ey = a[3] - a[1], a[4] - a[2]
          local len = math.sqrt(ex * ex + ey * ey)
          local nx, ny = ey / len, -ex / len
          local mx, my = (a[1] + a[3]) / 2 - cx, (a[2] + a[4]) / 2 - cy
          if nx * mx + ny * my < 0 then nx, ny = -nx, -ny end
          local apothem = math.abs(nx * mx + ny * my)
          for _, gap in ipairs({ -0.3 * r, -1e-9 * r, 0, 2 * EPS * offset, 1e-9 * r }) do
            local reach = 2 * apothem + gap
            local b = symmetric(m, cx + reach * nx, cy + reach * ny, r, a0 + turn)
            if rng:int(0, 1) == 1 then b = shapes.reverse(b) end
            checkPair(t, a, b)
            checkPair(t, b, a)
          end
        end
      end
    end
    assertTallies(t, 150)
  end)

  it("of many vertices and unequal counts collide and separate as the oracle says", function()
    -- ellipses of 3 to 40 vertices each (the calipers walk many edges of one polygon between
    -- two of the other), overlapping deeply, slightly, or pushed out and back by a few ulps
    local rng = prng.new(90210)
    local t = newTallies()
    for _, offset in ipairs({ 1, 1e3, 1e6 }) do
      for _ = 1, 12 do
        local cx, cy = offset * rng:range(-1, 1), offset * rng:range(-1, 1)
        local size = rng:range(1, 30)
        local a = shapes.convex(rng, rng:int(3, 40), cx, cy, size, 0.4)
        local angle, reach = rng:range(0, 2 * math.pi), rng:range(0.2, 2.2) * size
        local b = shapes.convex(rng, rng:int(3, 40), cx + reach * math.cos(angle),
          cy + reach * math.sin(angle), rng:range(0.3, 1.5) * size, 0.4)
        if rng:int(0, 1) == 1 then b = shapes.reverse(b) end
        local cases = { { a, b }, { b, a } }
        local o, dx, dy = polygon.polygonsCollideV(a, b)
        if o then   -- the pushed copy moved back by a few ulps: overlapping by a hair
          local step = rng:int(1, 4) * 2 * EPS * shapes.largestMagnitude(a, b)
          cases[3] = { a, translate(b, dx - (dx > 0 and step or dx < 0 and -step or 0),
            dy - (dy > 0 and step or dy < 0 and -step or 0)) }
        end
        for _, pair in ipairs(cases) do checkPair(t, pair[1], pair[2]) end
      end
    end
    assertTallies(t, 40)
  end)

  it("give a tie of equal depths to the first polygon, then to its lower edge end", function()
    -- two unit squares overlapping by 1/2 along x and along y: depth 0.5 (squared 0.25 * 1 / 1)
    -- on four axes, A's edges (1, 0) -> (1, 1) (x = 1, ending at flat index 5) and
    -- (1, 1) -> (0, 1) (y = 1, index 7), and B's x = 0.5 and y = 0.5; the tie goes to A's edge
    -- x = 1, moving B by +0.5 along x
    local a = { 0, 0, 1, 0, 1, 1, 0, 1 }
    local b = { 0.5, 0.5, 1.5, 0.5, 1.5, 1.5, 0.5, 1.5 }
    assert.are.same({ 0.5, 0.5, 0 }, { polygon.polygonsCollideV(a, b) })
    -- the same with B wound the other way: still A's edge x = 1
    assert.are.same({ 0.5, 0.5, 0 }, { polygon.polygonsCollideV(a, shapes.reverse(b)) })
    -- A starting at another vertex: (1, 0) -> (1, 1) ends at index 1 and (1, 1) -> (0, 1) at
    -- index 3, so the tie goes to x = 1 again, the lower index
    local a2 = { 1, 1, 0, 1, 0, 0, 1, 0 }
    assert.are.same({ 0.5, 0.5, 0 }, { polygon.polygonsCollideV(a2, b) })
    -- a tie with an edge of B whose normal comes before A's x = 1 in the order of angles: B's
    -- edge (0.5, 0.25) -> (2.5, 1.75), normal (-1.5, 2) (|n|^2 = 6.25), reached by A's vertex
    -- (1, 0): (-1.5)(0.5) + 2(-0.25) = -1.25, squared depth 1.5625 / 6.25 = 0.25; A's x = 1 is
    -- reached by B's least x 0.5, squared depth 0.25 too; B's other edges and A's are deeper
    local c = { 0.5, 0.25, 2.5, 1.75, 2.5, -2 }
    assert.are.same({ 0.5, 0.5, 0 }, { polygon.polygonsCollideV(a, c) })
    assert.are.same({ 0.5, 0.5, 0 }, { polygon.polygonsCollideV(a, shapes.reverse(c)) })
  end)
end)
