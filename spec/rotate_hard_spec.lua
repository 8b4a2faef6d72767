-- polygonRotate's rounding: against exact arithmetic on the rounded cos and sin, a full turn in
-- steps, and what rotation does to convexity (exact polygonType, checked by the oracle).
local polygon = require "polygon"
local oracle = require "oracle"
local exact = require "exact"
local prng = require "prng"

local rotate = polygon.polygonRotate
local EPS = 2 ^ -53

describe("polygonRotate rounding", function()
  -- x' = ox + (c (x - ox) - s (y - oy)) rounds five times: the differences x - ox and y - oy
  -- (errors eps |dx|, eps |dy|, carried on with factors |c|, |s|), the two products, their
  -- difference, and the final sum. Since |c dx| + |s dy| <= r (Cauchy-Schwarz, c^2 + s^2 = 1 up to
  -- rounding) the first four add at most 3 eps r and the sum eps |x'|: under 4 eps (r + |x'|) to
  -- first order.
  it("lands within 4 eps (r + |x'|) of the exact rotation by the doubles cos(angle), sin(angle)",
    function()
      local rng = prng.new(20261122)
      local ex = exact
      for _ = 1, 200 do
        local ox, oy = rng:range(-1e4, 1e4), rng:range(-1e4, 1e4)
        local points = {}
        for i = 1, 8 do points[i] = rng:range(-1e4, 1e4) end
        local angle = rng:range(-7, 7)
        local got = rotate(points, angle, ox, oy)
        local c, s = math.cos(angle), math.sin(angle)
        local eox, eoy, ec, es = ex.new(ox), ex.new(oy), ex.new(c), ex.new(s)
        for i = 1, 8, 2 do
          local dx, dy = ex.sub(ex.new(points[i]), eox), ex.sub(ex.new(points[i + 1]), eoy)
          local wantX = ex.tonumber(ex.add(eox, ex.sub(ex.mul(ec, dx), ex.mul(es, dy))))
          local wantY = ex.tonumber(ex.add(eoy, ex.add(ex.mul(es, dx), ex.mul(ec, dy))))
          local r = math.sqrt((points[i] - ox) ^ 2 + (points[i + 1] - oy) ^ 2)
          assert.is_true(math.abs(got[i] - wantX) <= 4 * EPS * (r + math.abs(wantX)))
          assert.is_true(math.abs(got[i + 1] - wantY) <= 4 * EPS * (r + math.abs(wantY)))
        end
      end
    end)

  -- k steps of 2 pi / k about a fixed pivot. Per step a coordinate is off by the 4 eps (r + M)
  -- above (M >= every |x'|) plus eps (|dx| + |dy|) <= sqrt 2 eps r from cos and sin (each within an
  -- ulp, <= eps below 1): in distance sqrt 2 (4 eps (r + M) + sqrt 2 eps r) < 9 eps (r + M). The
  -- k angles add up to 2 pi within k eps (2 pi / k) (each division rounds once) plus 2 |pi - fl(pi)|
  -- < 2.5e-16: under 9 eps radians, 9 eps r in distance. Total: 9 (k + 1) eps (r + M).
  it("returns within 9 (k + 1) eps (r + M) of the start after k steps of 2 pi / k", function()
    local square = { 100, 100, 110, 100, 110, 110, 100, 110 }
    local r = math.sqrt(50)                  -- vertex to pivot (105, 105)
    local M = 105 + r                        -- no coordinate passes it (up to the drift)
    for _, k in ipairs({ 4, 7, 360, 1000 }) do
      local q = {}
      for i = 1, 8 do q[i] = square[i] end
      for _ = 1, k do rotate(q, 2 * math.pi / k, 105, 105, q) end
      local worst = 0
      for i = 1, 8 do worst = math.max(worst, math.abs(q[i] - square[i])) end
      local limit = 9 * (k + 1) * EPS * (r + M)
      assert.is_true(worst <= limit, ("k = %d: off by %.3g, bound %.3g"):format(k, worst, limit))
      -- and the rounding is real: the square does not come back bit for bit
      if k >= 360 then assert.is_true(worst > 0) end
    end
  end)
end)

describe("polygonRotate and convexity", function()
  -- (3, 0) lies exactly on the edge from (0, 0) to (10, 0). Turned about the centroid, its rounded
  -- image lands a few ulps off the line through the rounded images of its neighbours, on either
  -- side: the exact polygonType then calls the result concave about half the time.
  describe("when a vertex is collinear with its neighbours", function()
    it("can come out concave, exactly so (the oracle agrees), and only at that vertex", function()
      local points = { 0, 0, 3, 0, 10, 0, 10, 10, 0, 10 }
      assert.are.equal("convex", polygon.polygonType(points))
      local concave, convex = 0, 0
      for k = 1, 200 do
        local turned = rotate(points, k * 0.01)
        local kind = polygon.polygonType(turned)
        assert.are.equal(oracle.polygonType(turned), kind)
        if kind == "concave" then
          concave = concave + 1
          -- the turn at every other vertex j keeps the polygon's way (clockwise: +1); the one at
          -- vertex 2, (3, 0), is the one that went the other way
          for _, j in ipairs({ 3, 4, 5, 1 }) do
            local a, b, c = (j + 3) % 5 * 2 + 1, j * 2 - 1, j % 5 * 2 + 1   -- vertices j-1, j, j+1
            assert.are.equal(1, oracle.orient(turned[a], turned[a + 1], turned[b], turned[b + 1],
              turned[c], turned[c + 1]))
          end
          assert.are.equal(-1, oracle.orient(turned[1], turned[2], turned[3], turned[4],
            turned[5], turned[6]))
        else
          convex = convex + 1
        end
      end
      assert.is_true(concave > 0)
      assert.is_true(convex > 0)
    end)
  end)

  -- A regular m-gon of radius r has every vertex r (1 - cos(2 pi / m)) from the line through its
  -- neighbours (>= 0.03 r for m <= 16): millions of times the rounding, so every turn keeps its sign.
  describe("when every vertex turns clearly", function()
    it("stays convex under any rotation (regular polygons of 3 to 16 vertices, both windings)",
      function()
        local rng = prng.new(7)
        for _ = 1, 300 do
          local m = rng:int(3, 16)
          local radius, cx, cy = rng:range(0.5, 1e3), rng:range(-1e5, 1e5), rng:range(-1e5, 1e5)
          local phase, dir = rng:range(0, 7), rng:pick({ 1, -1 })
          local points = {}
          for i = 0, m - 1 do
            local t = phase + dir * i * 2 * math.pi / m
            points[#points + 1] = cx + radius * math.cos(t)
            points[#points + 1] = cy + radius * math.sin(t)
          end
          local turned = rotate(points, rng:range(-7, 7))
          assert.are.equal("convex", polygon.polygonType(turned))
          assert.are.equal("convex", oracle.polygonType(turned))
          assert.are.equal(oracle.winding(points), oracle.winding(turned))
        end
      end)
  end)
end)
