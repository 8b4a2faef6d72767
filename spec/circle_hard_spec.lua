-- polygonCircleCollideV on the hard cases: circles within an ulp of touching an edge or a
-- vertex, centres on vertices and edges, far offsets, zero and huge radii, non-finite input;
-- then generated circles against the exact oracle, from a few ulps of overlap to deep inside,
-- at offsets 1 to 1e12. The contract: it collides exactly when the open disc meets the
-- polygon's interior, and the returned push separates for certain (the oracle sees no overlap
-- at the moved centre) while its length exceeds the exact least penetration depth by at most
-- 8 eps M, eps = 2^-53 and M the largest coordinate magnitude involved: the polygon's, the
-- centre's and the moved centre's coordinates (the radius is a length, not a coordinate).
local polygon = require "polygon"
local oracle = require "oracle"
local exact = require "exact"
local prng = require "prng"
local shapes = require "shapes"

local circleV = polygon.polygonCircleCollideV
local EPS = 2 ^ -53
local up, down = exact.nextUp, exact.nextDown

local SQUARE = { 0, 0, 10, 0, 10, 10, 0, 10 }
-- the hypotenuse from (8,0) to (0,6) lies on 3x + 4y = 24, |(3,4)| = 5: the centre (5,6) is
-- (15 + 24 - 24) / 5 = 3 from it, with the foot (5,6) - 3 (0.6,0.8) = (3.2,3.6) inside the edge
local TRIANGLE = { 0, 0, 8, 0, 0, 6 }

-- the answer, the push's separation and its excess, checked against the oracle
local check = require "circlecheck"

local function bothWindings(points, body)
  body(points)
  body(shapes.reverse(points))
end

describe("polygonCircleCollideV hard cases", function()
  for _, offset in ipairs({ 0, 1e9, 1e12 }) do
    describe("at offset " .. offset, function()
      local square = shapes.translate(SQUARE, offset, offset)
      local triangle = shapes.translate(TRIANGLE, offset, -offset)

      it("decides a circle tangent to an edge exactly, and one ulp either way", function()
        -- centre (13,5) r 3 touches the right edge x = 10
        bothWindings(square, function(p)
          assert.are.equal(false, check(p, offset + 13, offset + 5, 3))
          assert.is_truthy(check(p, offset + 13, offset + 5, up(3)))
          assert.are.equal(false, check(p, offset + 13, offset + 5, down(3)))
        end)
      end)

      it("decides a circle tangent to a slanted edge exactly, and one ulp either way", function()
        bothWindings(triangle, function(p)
          assert.are.equal(false, check(p, offset + 5, -offset + 6, 3))
          assert.is_truthy(check(p, offset + 5, -offset + 6, up(3)))
          assert.are.equal(false, check(p, offset + 5, -offset + 6, down(3)))
        end)
      end)

      it("decides a circle tangent to a vertex exactly, and one ulp either way", function()
        -- centre (13,14) is 5 from the corner (10,10) (3-4-5) and in its corner region
        bothWindings(square, function(p)
          assert.are.equal(false, check(p, offset + 13, offset + 14, 5))
          assert.is_truthy(check(p, offset + 13, offset + 14, up(5)))
          assert.are.equal(false, check(p, offset + 13, offset + 14, down(5)))
        end)
      end)

      it("collides with a centre on a vertex or on an edge, with a push that clears", function()
        bothWindings(square, function(p)
          -- on the vertex (10,10) r 2: depth 2 along x or y; on the edge point (10,5) r 1: depth 1
          assert.are.equal(2, check(p, offset + 10, offset + 10, 2))
          assert.are.equal(1, check(p, offset + 10, offset + 5, 1))
          assert.is_truthy(check(p, offset + 10, offset + 5, 2 ^ -20))
        end)
      end)

      it("never collides with a radius of 0, even inside", function()
        bothWindings(square, function(p)
          assert.are.equal(false, circleV(p, offset + 5, offset + 5, 0))
          assert.are.equal(false, circleV(p, offset + 10, offset + 10, 0))
        end)
      end)

      it("pushes a circle of radius 1e300 out in one step", function()
        bothWindings(square, function(p)
          local overlap = check(p, offset + 5, offset + 4, 1e300)
          assert.near(1e300, overlap, 1e285)
        end)
      end)
    end)
  end

  describe("the hanging example: 1e-12 past touching a corner at 10000", function()
    it("returns a push that moves the centre and clears in one step", function()
      local box = { 10000, 10000, 10001, 10000, 10001, 10001, 10000, 10001 }
      local cx, cy, r = 9997, 9996, 5 + 1e-12
      local overlap, dx, dy = circleV(box, cx, cy, r)
      assert.is_truthy(overlap)
      assert.is_true(cx + dx ~= cx or cy + dy ~= cy)
      assert.are.equal(false, circleV(box, cx + dx, cy + dy, r))
      assert.is_false(oracle.discMeetsPolygon(box, cx + dx, cy + dy, r))
    end)
  end)

  -- The square 0..10 written so that the turn at vertex 1 is zero: vertex 1 repeated, or on the
  -- middle of an edge, in both windings (each list keeps that vertex first). Its winding then
  -- cannot be read from that turn.
  describe("when the turn at vertex 1 is zero", function()
    local starts = {
      { 0, 0, 0, 0, 10, 0, 10, 10, 0, 10 }, { 0, 0, 0, 0, 0, 10, 10, 10, 10, 0 },   -- (0,0) twice
      { 5, 0, 10, 0, 10, 10, 0, 10, 0, 0 }, { 5, 0, 0, 0, 0, 10, 10, 10, 10, 0 },   -- (5,0) on y = 0
    }
    for k, p in ipairs(starts) do
      it("decides and pushes as for the plain square (list " .. k .. ")", function()
        -- inside: the nearest line x = 10 is 4 away from (6,5), so the depth is 1 + 4 = 5
        assert.near(5, check(p, 6, 5, 1), 1e-12)
        -- the centre 0.5 below the edge y = 0: depth 1 - 0.5 = 0.5
        assert.near(0.5, check(p, 5, -0.5, 1), 1e-12)
        -- tangent to y = 0 (distance exactly 1): apart; one ulp more radius reaches in
        assert.are.equal(false, check(p, 5, -1, 1))
        assert.is_truthy(check(p, 5, -1, up(1)))
        -- near the corner (0,0): (-0.6)^2 + (-0.8)^2 is 1 to rounding, the oracle decides
        check(p, -0.6, -0.8, 1)
        -- 2 beyond x = 10 with radius 1: apart
        assert.are.equal(false, check(p, 12, 5, 1))
      end)
    end
  end)

  describe("when an input is not finite", function()
    it("names the function and the argument", function()
      local inf, nan = math.huge, 0 / 0
      local function message(...)
        local ok, err = pcall(circleV, ...)
        assert.is_false(ok)
        return err
      end
      assert.truthy(message(SQUARE, nan, 5, 1):find("polygonCircleCollideV: cx must be finite", 1, true))
      assert.truthy(message(SQUARE, 5, inf, 1):find("polygonCircleCollideV: cy must be finite", 1, true))
      assert.truthy(message(SQUARE, 5, 5, inf):find("polygonCircleCollideV: radius must be finite", 1, true))
      assert.truthy(message(SQUARE, 5, 5, nan):find("polygonCircleCollideV: radius must be finite", 1, true))
      assert.truthy(message({ 0, 0, 10, nan, 10, 10 }, 5, 5, 1)
        :find("polygonCircleCollideV: points holds a non-finite coordinate", 1, true))
      assert.truthy(message({ 0, 0, inf, 0, 10, 10 }, 5, 5, 1)
        :find("polygonCircleCollideV: points holds a non-finite coordinate", 1, true))
    end)

    it("points the error at the caller's line", function()
      local ok, err = pcall(function() circleV({ 0, 0, 10, 0 / 0, 10, 10 }, 5, 5, 1) end)
      assert.is_false(ok)
      assert.truthy(err:find("circle_hard_spec.lua", 1, true))
    end)
  end)
end)

describe("polygonCircleCollideV on generated circles near contact, at offsets 1 to 1e12", function()
  -- convex polygons: 3 to 10 vertices on an ellipse at sorted angles at least 0.3 apart, so
  -- rounding the vertices cannot make them concave
  local function convex(r, offset)
    local n = r:int(3, 10)
    local angles, t = {}, r:range(0, 2 * math.pi)
    local step = 2 * math.pi / n
    for i = 1, n do angles[i] = t + (i - 1) * step + r:range(0, step - 0.3) end
    local a, b = r:range(5, 50), r:range(5, 50)
    local ox, oy = offset * (r:float() * 2 - 1), offset * (r:float() * 2 - 1)
    local points = {}
    for i = 1, n do
      points[2 * i - 1] = ox + a * math.cos(angles[i])
      points[2 * i] = oy + b * math.sin(angles[i])
    end
    return points
  end

  it("agrees with the oracle; every push clears and is tight", function()
    local r = prng.new(8086)
    local collided = 0
    for trial = 1, 400 do
      local points = convex(r, 10 ^ r:int(0, 12))
      if trial % 2 == 0 then points = shapes.reverse(points) end
      local n = #points
      -- a boundary point: a vertex, or a point along an edge
      local i = 2 * r:int(0, n / 2 - 1) + 1
      local j = i + 2 <= n and i + 2 or 1
      local t = trial % 3 == 0 and 0 or r:float()
      local bx = points[i] + t * (points[j] - points[i])
      local by = points[i + 1] + t * (points[j + 1] - points[i + 1])
      -- the centre: from there along a random direction, the radius near that distance
      local angle, dist = r:range(0, 2 * math.pi), r:range(0, 30)
      local cx, cy = bx + dist * math.cos(angle), by + dist * math.sin(angle)
      local radius = math.sqrt((cx - bx) ^ 2 + (cy - by) ^ 2)
      local kind = trial % 4
      if kind == 0 then
        for _ = 1, r:int(0, 2) do radius = up(radius) end
      elseif kind == 1 then
        for _ = 1, r:int(0, 2) do radius = down(radius) end
      elseif kind == 2 then
        radius = radius + r:range(0, 40)
      end
      if radius > 0 and check(points, cx, cy, radius) then collided = collided + 1 end
    end
    assert.is_true(collided > 150, collided .. " collided")
  end)

  it("pushes deep circles out in one step, tight: centres inside, radii up to 200", function()
    local r = prng.new(4004)
    local collided = 0
    for trial = 1, 150 do
      local points = convex(r, 10 ^ r:int(0, 12))
      if trial % 2 == 0 then points = shapes.reverse(points) end
      -- a centre between the first vertex and the vertex mean: inside
      local mx, my = shapes.vertexMean(points)
      local t = r:float()
      local cx, cy = mx + t * (points[1] - mx), my + t * (points[2] - my)
      if check(points, cx, cy, r:range(0.01, 200)) then collided = collided + 1 end
    end
    assert.are.equal(150, collided)
  end)

  it("keeps the bound where the radius is as large as the coordinates: far centres, near polygons", function()
    -- a polygon within 50 of the origin and a centre 10 to 1e7 away, the radius within 0.1% of
    -- the distance to its first vertex: the radius is about M, the depth small
    local r = prng.new(5005)
    local collided = 0
    for trial = 1, 150 do
      local points = convex(r, 50)
      if trial % 2 == 0 then points = shapes.reverse(points) end
      local angle, dist = r:range(0, 2 * math.pi), 10 ^ r:range(1, 7)
      local cx, cy = points[1] + dist * math.cos(angle), points[2] + dist * math.sin(angle)
      local radius = math.sqrt((cx - points[1]) ^ 2 + (cy - points[2]) ^ 2) * (1 + r:range(-1e-3, 1e-3))
      if check(points, cx, cy, radius) then collided = collided + 1 end
    end
    assert.is_true(collided > 50, collided .. " collided")
  end)

  it("keeps the bound for pushes across a polygon around the origin (depth up to 2 sqrt(2) M)", function()
    -- the centre near a vertex, the radius 0.5 to 3 times the polygon's size: the push carries
    -- the centre past the far side, its length up to the distance between opposite corners
    local r = prng.new(6006)
    for trial = 1, 150 do
      local size = 10 ^ r:range(0, 9)
      local points = convex(r, 0)
      for i = 1, #points do points[i] = points[i] * size / 30 end
      if trial % 2 == 0 then points = shapes.reverse(points) end
      local k = 2 * r:int(0, #points / 2 - 1) + 1
      local cx, cy = points[k] * r:range(0.9, 1.1), points[k + 1] * r:range(0.9, 1.1)
      assert.is_truthy(check(points, cx, cy, size * r:range(0.5, 3)))
    end
  end)
end)

describe("the push's excess check", function()
  it("rejects a push 9 eps M longer than the depth and accepts one 6 eps M longer", function()
    -- centre (13,5) r 4 against the square: 3 from the edge x = 10, depth 1 along +x; with the
    -- push of length about 1 the moved centre is (14,5), so M = 14 and 8 eps M = 112 eps
    assert.is_false(oracle.circleDepthAtLeast(SQUARE, 13, 5, 4, 1 + 126 * EPS, 8 * EPS * 14))
    assert.is_true(oracle.circleDepthAtLeast(SQUARE, 13, 5, 4, 1 + 84 * EPS, 8 * EPS * 14))
    -- inside: centre (5,5) r 1 is 5 from every edge, depth 6 (s = r - (q - 8 eps M) < 0)
    assert.is_true(oracle.circleDepthAtLeast(SQUARE, 5, 5, 1, 6, 0))
    assert.is_false(oracle.circleDepthAtLeast(SQUARE, 5, 5, 1, 6 + 2 ^ -40, 0))
  end)
end)
