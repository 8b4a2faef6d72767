-- Hard cases for polygonType's filter: the PUC interpreters decide the turns at the last vertex
-- and at vertex 1 before their loop (and end the call there when they disagree), take two turns
-- per loop step and leave one after the loop for odd vertex counts; every body counts how often
-- the edges' x direction changes sign (once per winding each way), where an edge with dx = 0
-- may fall anywhere. Every case is checked in every rotation of its vertex order (so that each
-- vertex in turn is the first) and in both windings, against the exact oracle
-- (spec/support/oracle.lua).
local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local shapes = require "shapes"

-- points with vertex k first
local function rotated(points, k)
  local out, n = {}, #points
  for i = 0, n - 1 do out[i + 1] = points[(2 * (k - 1) + i) % n + 1] end
  return out
end

-- every rotation, both windings: the differences from the oracle, at most three described
local function mismatches(points, bad)
  for _, p in ipairs({ points, shapes.reverse(points) }) do
    for k = 1, #p / 2 do
      local q = rotated(p, k)
      local got, want = polygon.polygonType(q), oracle.polygonType(q)
      if got ~= want and #bad < 3 then
        bad[#bad + 1] = ("{%s}: got %s, exact %s"):format(table.concat(q, ", "), tostring(got),
          tostring(want))
      end
    end
  end
end

describe("polygonType in every rotation and winding", function()
  it("agrees with the oracle on small hand-made cases", function()
    local bad = {}
    for _, p in ipairs({
      { 0, 0, 4, 0, 0, 3 },                                   -- triangle (odd)
      { 0, 0, 10, 0, 10, 10, 0, 10 },                         -- square: vertical edges (dx = 0)
      { 0, 0, 10, 0, 10, 10, 5, 3, 0, 10 },                   -- one reflex vertex (odd)
      { 0, 0, 10, 0, 10, 10, 5, 3, 0, 10, -2, 5 },            -- one reflex vertex (even)
      { 0, 0, 10, 0, 10, 10, 5, 10, 0, 10 },                  -- a collinear vertex going on
      { 0, 0, 10, 0, 10, 10, 10, 5, 10, 20, 0, 10 },          -- a spike doubling back
      { 0, 0, 0, 5, 0, 10, 10, 10, 10, 0 },                   -- collinear on a vertical edge
      { 0, 0, 10, 0, 10, 0, 10, 10, 0, 10 },                  -- a repeated vertex
      { 0, 0, 2, 6, 4, 0, -1, 4, 5, 4 },                      -- pentagram: turns agree, winds twice
      { 0, 0, 1, 0, 2, 0 },                                   -- all on one line
    }) do
      mismatches(p, bad)
    end
    assert.are.same({}, bad)
  end)

  it("agrees with the oracle on random convex polygons and stars of 3 to 12 vertices", function()
    local r, bad = prng.new(4242), {}
    for trial = 1, 160 do
      local m = 3 + trial % 10
      local p = shapes.convex(r, m, r:range(-100, 100), r:range(-100, 100), r:range(1, 50), 0.3)
      if trial % 2 == 0 then   -- pull every other vertex in: a star, concave from vertex 1 on
        local cx, cy = shapes.vertexMean(p)
        for i = 1, #p, 4 do p[i], p[i + 1] = cx + 0.3 * (p[i] - cx), cy + 0.3 * (p[i + 1] - cy) end
      end
      mismatches(p, bad)
    end
    assert.are.same({}, bad)
  end)

  it("agrees with the oracle where a turn is within rounding of zero", function()
    -- a convex polygon with a vertex put at an edge's midpoint rounded, then moved by up to 2
    -- ulps: that turn is zero or nearly so, and lands first, second or later by rotation
    local r, bad = prng.new(977), {}
    for trial = 1, 120 do
      local m = 3 + trial % 6
      local p = shapes.convex(r, m, r:range(-100, 100), r:range(-100, 100), r:range(1, 50), 0.3)
      local k = 2 * r:int(0, m - 1) + 1
      local j = k + 2 > #p and 1 or k + 2
      local mx, my = (p[k] + p[j]) / 2, (p[k + 1] + p[j + 1]) / 2
      my = my + r:int(-2, 2) * 2 ^ (math.floor(math.log(math.abs(my) + 1) / math.log(2)) - 52)
      table.insert(p, k + 2, my)
      table.insert(p, k + 2, mx)
      mismatches(p, bad)
    end
    assert.are.same({}, bad)
  end)

  it("agrees with the oracle on stars that wind around two to six times", function()
    -- the regular star {m/k}: m points on a circle, visited every k-th, turns all one way and
    -- winding k times. The lower half of the circle mirrors the upper (x_(m-j) = x_j exactly),
    -- so an edge from vertex j to vertex m - j is vertical (dx = 0) wherever it falls.
    local bad = {}
    for m = 5, 14 do
      local xs, ys = {}, {}
      for j = 0, math.floor(m / 2) do
        local t = 2 * math.pi * j / m
        xs[j], ys[j] = 100 * math.cos(t), 100 * math.sin(t)
        xs[m - j], ys[m - j] = xs[j], -ys[j]
      end
      ys[0] = 0.0
      for k = 1, math.floor((m - 1) / 2) do
        local a, b = m, k   -- visits every vertex once when gcd(m, k) = 1
        while b > 0 do a, b = b, a % b end
        if a == 1 then
          local p = {}
          for i = 0, m - 1 do
            local v = i * k % m
            p[#p + 1], p[#p + 2] = xs[v] + 7, ys[v] - 3
          end
          mismatches(p, bad)
        end
      end
    end
    assert.are.same({}, bad)
  end)

  it("agrees with the oracle on axis-aligned outlines traversed once, twice and three times", function()
    local bad = {}
    local outlines = {
      { 0, 0, 10, 0, 10, 10, 0, 10 },                         -- square
      { 0, 1, 1, 0, 2, 0, 3, 1, 3, 2, 2, 3, 1, 3, 0, 2 },     -- octagon: 4 axis-aligned edges
      { 0, 0, 2, -1, 4, 0, 4, 2, 2, 3, 0, 2 },                -- hexagon: two vertical edges
      { 0, 0, 4, 0, 4, 4, 2, 6, 0, 4 },                       -- house (odd): two vertical edges
    }
    for _, outline in ipairs(outlines) do
      for times = 1, 3 do
        local p = {}
        for _ = 1, times do
          for i = 1, #outline do p[#p + 1] = outline[i] end
        end
        mismatches(p, bad)
      end
    end
    assert.are.same({}, bad)
  end)
end)
