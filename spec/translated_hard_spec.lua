-- Hard cases, family 2: polygons and tilings translated far from the origin (1e3 ... 1e15).
--
-- A tiling is a jittered lattice of vertices V[k][l] ~ (ox + k w, oy + l h), computed in floating
-- point once and shared by every tile that uses it: 3 x 3 quadrilaterals, and the same split
-- into 18 triangles along alternating diagonals, so shared edges are straight, slanted, and
-- (for the diagonals) steep. Since neighbouring tiles use the very same doubles, they touch
-- exactly: they must never collide, and by the crossing rule's half-open boundary every point
-- lies in as many tiles as the tiling's outline says (0 or 1), at any offset. The exact oracle
-- confirms each of those facts before the library is held to it.

local polygon = require "polygon"
local oracle = require "oracle"
local exact = require "exact"
local prng = require "prng"
local tally = require "tally"
local probe = require "probe"
local shapes = require "shapes"

local OFFSETS = {}
for _, e in ipairs({ 3, 6, 9, 12, 14, 15 }) do
  local o = 10 ^ e
  -- alternate signs and an odd fraction so that the offsets are not all round numbers
  OFFSETS[#OFFSETS + 1] = { (e % 2 == 0 and o or -o) + 0.375, o * 1.25 }
end

local COLS, ROWS = 3, 3

-- jitter(r) gives the offset of a vertex from its lattice place, as a fraction of the tile size.
local function tiling(ox, oy, w, h, seed, jitter)
  local r = prng.new(seed)
  local V = {}
  for k = 0, COLS do
    V[k] = {}
    for l = 0, ROWS do
      V[k][l] = { ox + k * w + jitter(r) * w, oy + l * h + jitter(r) * h }
    end
  end
  local quads, triangles = {}, {}
  for k = 0, COLS - 1 do
    for l = 0, ROWS - 1 do
      local a, b, c, d = V[k][l], V[k + 1][l], V[k + 1][l + 1], V[k][l + 1]
      quads[#quads + 1] = { a[1], a[2], b[1], b[2], c[1], c[2], d[1], d[2] }
      if (k + l) % 2 == 0 then
        triangles[#triangles + 1] = { a[1], a[2], b[1], b[2], c[1], c[2] }
        triangles[#triangles + 1] = { a[1], a[2], c[1], c[2], d[1], d[2] }
      else
        triangles[#triangles + 1] = { a[1], a[2], b[1], b[2], d[1], d[2] }
        triangles[#triangles + 1] = { b[1], b[2], c[1], c[2], d[1], d[2] }
      end
    end
  end
  -- the outline: the border vertices in order
  local outline = {}
  local function put(v)
    outline[#outline + 1] = v[1]
    outline[#outline + 1] = v[2]
  end
  for k = 0, COLS - 1 do put(V[k][0]) end
  for l = 0, ROWS - 1 do put(V[COLS][l]) end
  for k = COLS, 1, -1 do put(V[k][ROWS]) end
  for l = ROWS, 1, -1 do put(V[0][l]) end
  return quads, triangles, outline
end

-- Two kinds of tiling: "random", vertices moved by up to 0.2 of the tile size in random doubles
-- (every shared slanted edge is a rounding-hard line, but only vertices lie exactly on it), and
-- "snapped", tile size 16 g and vertices moved by multiples of g, a power of two at least 8 ulps
-- of the offset: then a + t (b - a) for t = 1/4, 1/2, 3/4 is a double exactly on the edge.
local KINDS = {
  { name = "random", minShared = 4, setup = function()
    return 7.3, function(r) return r:range(-0.2, 0.2) end
  end },
  { name = "snapped", minShared = 40, setup = function(o)
    local g = 2 ^ -4
    while g < 8 * exact.tonumber(exact.ulp(o)) do g = g * 2 end
    return 16 * g, function(r) return r:int(-3, 3) / 16 end
  end },
}

-- Whether (x, y) is inside the bounding box of the polygon (closed): a cheap exact prefilter for
-- the oracle's boundary test.
local function inBox(p, x, y)
  local x0, y0, x1, y1 = shapes.bounds(p)
  return x0 <= x and x <= x1 and y0 <= y and y <= y1
end

for _, kind in ipairs(KINDS) do
  describe(("%s tilings translated by 1e3 ... 1e15"):format(kind.name), function()
    for index, offset in ipairs(OFFSETS) do
      local ox, oy = offset[1], offset[2]
      local size, jitter = kind.setup(math.max(math.abs(ox), math.abs(oy)))
      local quads, triangles, outline = tiling(ox, oy, size, size, 1000 + index, jitter)
      local label = ("at (%.17g, %.17g)"):format(ox, oy)

      it("has convex tiles of the expected winding and area " .. label, function()
        local t = tally.new("tiles vs oracle")
        for _, tiles in ipairs({ quads, triangles }) do
          for _, p in ipairs(tiles) do
            assert.are.equal("convex", oracle.polygonType(p), "the generator should make convex tiles")
            t:check(polygon.polygonType(p) == "convex", "type", p)
            t:check(polygon.polygonWindingOrder(p) == oracle.winding(p), "winding", p)
            local a = oracle.area(p)
            t:check(exact.withinUlps(polygon.polygonAreaAccurate(p), a, 1), "areaAccurate", p)
            t:check(exact.withinUlps(polygon.polygonArea(p), a, 8), "area", p, polygon.polygonArea(p))
          end
        end
        assert.are.equal(0, t.count, t:message())
      end)

      it("never lets two tiles collide " .. label, function()
        local t = tally.new("tile pairs")
        local adjacentPairs = 0
        for _, tiles in ipairs({ quads, triangles }) do
          for i = 1, #tiles do
            for j = 1, #tiles do
              if i ~= j then
                local a, b = tiles[i], tiles[j]
                t:check(polygon.polygonsCollide(a, b) == false, "polygonsCollide", i, j, a, b)
                t:check(polygon.polygonsCollideV(a, b) == false, "polygonsCollideV", i, j)
                -- one-sided: p1's axes alone may fail to separate tiles that only meet at a corner
                local oneSided = polygon.polygonCollidesWith(a, b)
                local oneSidedV = polygon.polygonCollidesWithV(a, b)
                t:check((oneSidedV ~= false) == oneSided, "polygonCollidesWithV false iff not", i, j)
                -- the oracle for the pairs that share a vertex (the hard ones)
                local shares = false
                for u = 1, #a - 1, 2 do
                  for v = 1, #b - 1, 2 do
                    if a[u] == b[v] and a[u + 1] == b[v + 1] then shares = true end
                  end
                end
                if shares then
                  adjacentPairs = adjacentPairs + 1
                  if i < j then
                    assert.is_false(oracle.collides(a, b, true), "the oracle says the tiles overlap")
                  end
                  t:check(oneSided == oracle.collides(a, b, false), "polygonCollidesWith", i, j, a, b)
                end
              end
            end
          end
        end
        assert.are.equal(0, t.count, t:message())
        assert.is_true(adjacentPairs > 100)
      end)

      it("puts every point on and near the shared edges in as many tiles as the outline says " .. label,
        function()
          local t = tally.new("points near shared edges")
          local onShared = 0
          for _, tiles in ipairs({ quads, triangles }) do
            local candidates = {}
            for _, p in ipairs(tiles) do
              for _, e in ipairs(probe.edges(p)) do
                probe.around(e, { 0, 0.25, 0.5, 0.75 }, candidates)
              end
            end
            for _, q in ipairs(probe.distinct(candidates)) do
              local x, y = q[1], q[2]
              local expected = oracle.contains(outline, x, y) and 1 or 0
              local count, owners = 0, 0
              for _, p in ipairs(tiles) do
                local inside = polygon.polygonContains(p, x, y)
                if inside then count = count + 1 end
                if inBox(p, x, y) and oracle.onBoundary(p, x, y) then
                  owners = owners + 1
                  t:check(inside == oracle.contains(p, x, y), "contains vs oracle", p, x, y)
                end
              end
              if owners >= 2 and not oracle.onBoundary(outline, x, y) then
                onShared = onShared + 1 -- exactly on an edge or vertex shared by tiles, inside
                t:check(count == 1, "a point of a shared edge is in exactly one tile", x, y, count)
              end
              t:check(count == expected, "tiles containing", x, y, count, "outline says", expected)
            end
          end
          assert.are.equal(0, t.count, t:message())
          assert.is_true(onShared >= kind.minShared, "too few points exactly on shared edges: " .. onShared)
        end)
    end
  end)
end

describe("a concave polygon translated by 1e3 ... 1e15", function()
  -- an arrow pointing right, concave at (4, 3) and (4, 5) (hand drawn, both windings)
  local ARROW = { 0, 3, 4, 3, 4, 0, 9, 4, 4, 8, 4, 5, 0, 5 }

  local function moved(points, ox, oy, reverse)
    local out = {}
    local m = #points / 2
    for i = 1, m do
      local k = reverse and (m - i + 1) or i
      out[2 * i - 1] = points[2 * k - 1] * 0.37 + ox
      out[2 * i] = points[2 * k] * 0.37 + oy
    end
    return out
  end

  it("keeps type, winding, area, center, centroid and contains right at every offset", function()
    local t = tally.new("translated arrow")
    for _, offset in ipairs(OFFSETS) do
      for _, reverse in ipairs({ false, true }) do
        local p = moved(ARROW, offset[1], offset[2], reverse)
        local extent = 9 * 0.37
        t:check(polygon.polygonType(p) == oracle.polygonType(p), "type", p)
        t:check(oracle.polygonType(p) == "concave", "oracle type", p)
        t:check(polygon.polygonWindingOrder(p) == oracle.winding(p), "winding", p)
        local a = oracle.area(p)
        t:check(exact.withinUlps(polygon.polygonAreaAccurate(p), a, 1), "areaAccurate", p)
        t:check(exact.withinUlps(polygon.polygonArea(p), a, 8), "area", p, polygon.polygonArea(p))
        -- centre and centroid: a few ulps of the result plus a few eps of the polygon's extent,
        -- not of the offset (the tutorial's sums lose m * eps * offset)
        local cx, cy = polygon.polygonCenter(p)
        local ex, ey = oracle.center(p)
        local tol = 4 * exact.tonumber(exact.ulp(math.abs(ex) + math.abs(ey))) + 2 ^ -48 * extent
        t:check(math.abs(cx - ex) <= tol and math.abs(cy - ey) <= tol, "center", p, cx, cy, ex, ey)
        cx, cy = polygon.polygonCentroid(p)
        ex, ey = oracle.centroid(p)
        t:check(math.abs(cx - ex) <= tol and math.abs(cy - ey) <= tol, "centroid", p, cx, cy, ex, ey)
        for _, q in ipairs(probe.pointsNear(p)) do
          t:check(polygon.polygonContains(p, q[1], q[2]) == oracle.contains(p, q[1], q[2]), "contains", p, q)
        end
      end
    end
    assert.are.equal(0, t.count, t:message())
  end)
end)
