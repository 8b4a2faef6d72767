-- Hard cases for polygonType's first turns: the filter decides the turns at the last vertex and
-- at vertex 1 before its loop (the PUC interpreters end the call there when they disagree), takes
-- an x direction from the last edges, and starts its loop differently for odd and even vertex
-- counts. Every case is checked in every rotation of its vertex order (so that each vertex in
-- turn is the first) and in both windings, against the exact oracle (spec/support/oracle.lua).
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
end)
