-- polygonCircleCollideV against circles far larger than the polygon: radius-to-size ratios 1e10,
-- 1e15, 1e20, 1e100 and 1e300, the circle's leftmost point at the origin among the polygon's
-- vertices. Far from such a centre every vertex's offset from it rounds to a multiple of the
-- centre's ulp, larger than the whole polygon: the nearest vertex and the edge farthest behind
-- the centre cannot be read from those offsets. The contract is the same as for any circle
-- (spec/support/circlecheck.lua): the exact answer, a push that clears, at most 8 eps M long
-- past the exact depth.
local exact = require "exact"
local prng = require "prng"
local shapes = require "shapes"
local check = require "circlecheck"

local up, down = exact.nextUp, exact.nextDown

local RATIOS = { 1e10, 1e15, 1e20, 1e100, 1e300 }

for _, ratio in ipairs(RATIOS) do
  -- polygons of size about 1 near the origin; the circle (R, 0) of radius R passes through it
  local R = ratio
  describe("a circle of radius " .. ratio .. " times the polygon's size", function()
    local both = function(points, body) body(points); body(shapes.reverse(points)) end

    it("touches, and does not collide with, a square whose edge lies on its tangent x = 0", function()
      -- the edge (0,-0.5) -> (0,0.5) passes through (0,0), the disc's leftmost point; every
      -- other point of it is sqrt(R^2 + y^2) > R from the centre
      both({ -1,-0.5, 0,-0.5, 0,0.5, -1,0.5 }, function(p)
        assert.are.equal(false, check(p, R, 0, R))
        -- one ulp more radius reaches past x = 0; one ulp less misses by an ulp
        assert.is_truthy(check(p, R, 0, up(R)))
        assert.are.equal(false, check(p, R, 0, down(R)))
        -- the centre one ulp left: the disc reaches past x = 0 by an ulp of R
        assert.is_truthy(check(p, down(R), 0, R))
        assert.are.equal(false, check(p, up(R), 0, R))
      end)
    end)

    it("touches a triangle at its vertex (0,0), and collides one ulp of radius further", function()
      both({ -1,-0.5, 0,0, -1,0.5 }, function(p)
        assert.are.equal(false, check(p, R, 0, R))
        assert.is_truthy(check(p, R, 0, up(R)))
        -- the same vertex approached from below and above the axis
        assert.are.equal(false, check(p, R, 1e-3, R))
        assert.are.equal(false, check(p, R, -1e-3, R))
      end)
    end)

    it("collides with a square straddling x = 0, pushing it along +x by about its depth", function()
      -- the disc reaches x = 0 at y = 0 and 0.5^2 / (2 R) short of it at y = +-0.5: the
      -- depth is 0.5 less that sag (within 8 eps M, M = R)
      both({ -0.5,-0.5, 0.5,-0.5, 0.5,0.5, -0.5,0.5 }, function(p)
        local overlap, dx, dy = check(p, R, 0, R)
        assert.is_truthy(overlap)
        assert.is_true(dx > 0 and math.abs(dy) <= math.abs(dx))
      end)
    end)

    it("misses a vertical edge off the axis by its sag, and meets it a few ulps to the right", function()
      -- the edge x = t from (t,0.1) to (t,0.5): the disc meets it when 2 R t > t^2 + 0.01,
      -- t about 0.005 / R; the doubles around that are decided by the oracle, both answers
      -- occurring (a case list that cannot fail on one side is a defect)
      local t0 = 0.005 / R
      if t0 < 2^-447 then return end   -- below the exact range (ratio 1e300)
      local seen = {}
      for k = -3, 3 do
        local t = t0
        for _ = 1, math.abs(k) do t = k > 0 and up(t) or down(t) end
        local p = { -1,0.1, t,0.1, t,0.5, -1,0.5 }
        seen[check(p, R, 0, R) ~= false] = true
      end
      assert.is_true(seen[true] and seen[false])
    end)
  end)
end

describe("generated polygons of size 0.2 near the origin against the circle (R,0) of radius R", function()
  for _, ratio in ipairs(RATIOS) do
    it("answers as the oracle and pushes within the contract at R = " .. ratio, function()
      local g = prng.new(29)
      local hits = 0
      for _ = 1, 60 do
        local k = g:int(3, 8)
        local ux, uy = g:range(-0.2, 0.1), g:range(-0.1, 0.1)
        local start = g:range(0, 2 * math.pi)
        local p = {}
        for i = 1, k do
          local a = start + (i - 1) * 2 * math.pi / k
          p[#p + 1], p[#p + 2] = ux + 0.1 * math.cos(a), uy + 0.1 * math.sin(a)
        end
        if check(p, ratio, 0, ratio) then hits = hits + 1 end
      end
      -- both answers occur (about half the polygons reach past x = 0)
      assert.is_true(hits > 10 and hits < 50)
    end)
  end
end)
