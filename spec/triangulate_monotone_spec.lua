-- Triangulation by monotone pieces (polygon/monotone.lua): the way an outline without holes takes
-- when the check's sweep ran and found it plain (one vertex a place, none inside an edge, none in
-- line with its neighbours). The sweep runs on its own for long-edged outlines; here it is forced
-- (sweep.grid = false) on small ones, so that the pieces meet split and merge vertices, vertical
-- edges and columns of vertices at one x. Hand-computed cases first, then generated ones against
-- the oracle (spec/support: no code shared with the library), then the cases it leaves to ear
-- clipping.

local polygon = require "polygon"
local sweep = require "polygon.sweep"
local monotone = require "polygon.monotone"
local oracle = require "oracle"
local prng = require "prng"
local shapes = require "shapes"

local JIT = rawget(_G, "jit") ~= nil
local CASES = JIT and 1500 or 3000
local INDEX = require "seeds"   -- this interpreter's range of seeds

-- fn(points, holes) with the sweep forced: its answers, and how many calls monotone.lua took
-- and left to ear clipping.
local function bySweep(fn, points, holes)
  local taken, declined = monotone.taken, monotone.declined
  sweep.grid = false
  local result, message = fn(points, holes)
  sweep.grid = true
  return result, message, monotone.taken - taken, monotone.declined - declined
end

-- The triangles as sorted strings of their corners, sorted: comparable whatever the order.
local function triangleSet(tris)
  local set = {}
  for i, t in ipairs(tris) do
    local corners = {}
    for c = 1, 5, 2 do corners[#corners + 1] = ("%g,%g"):format(t[c], t[c + 1]) end
    table.sort(corners)
    set[i] = table.concat(corners, " ")
  end
  table.sort(set)
  return table.concat(set, " | ")
end

-- The triangles of an outline the pieces take (checked: no refusal, one call taken, every
-- triangle wound like the outline, whose shoelace is > 0 in these cases), as triangleSet.
local function piecesOf(points)
  local tris, message, taken = bySweep(polygon.polygonTriangulate, points)
  assert.is_nil(message)
  assert.are.equal(1, taken)
  for _, t in ipairs(tris) do
    assert.is_true((t[3] - t[1]) * (t[6] - t[2]) - (t[4] - t[2]) * (t[5] - t[1]) > 0)
  end
  return triangleSet(tris)
end

-- A star-shaped outline of random vertices on a small grid, in the order of their angles around
-- the origin (one vertex a direction): simple, with many vertices at one x, vertical edges, and
-- vertices in line with their neighbours on some.
local function gridStar(rng, size, count)
  local list, seen = {}, {}
  for _ = 1, count do
    local x, y = rng:int(-size, size), rng:int(-size, size)
    if x ~= 0 or y ~= 0 then
      local a, b = math.abs(x), math.abs(y)   -- the direction, as a key: reduced by the gcd
      while b > 0 do a, b = b, a % b end
      local key = ("%d,%d"):format(x / a, y / a)
      if not seen[key] then
        seen[key] = true
        -- the angle, exactly ordered: the half-plane, then the cross product with (1, 0)
        local half = (y > 0 or (y == 0 and x > 0)) and 0 or 1
        list[#list + 1] = { x, y, half }
      end
    end
  end
  table.sort(list, function(p, q)
    if p[3] ~= q[3] then return p[3] < q[3] end
    return p[1] * q[2] - p[2] * q[1] > 0
  end)
  local points = {}
  for _, p in ipairs(list) do points[#points + 1] = p[1]; points[#points + 1] = p[2] end
  return points
end

describe("polygonTriangulate by monotone pieces", function()
  after_each(function() sweep.grid = true end)

  describe("on hand-computed outlines", function()
    it("cuts an arrow pointing left at its split vertex", function()
      -- sweep order (x, then y): (0,5), (6,5), (10,0), (10,10). (6,5) has both neighbours
      -- later and turns away from the inside: a split vertex, whose helper is (0,5), the left
      -- end of the edge (0,5)-(10,0) right below it. The diagonal (0,5)-(6,5) leaves two
      -- triangles: (0,5),(10,0),(6,5): (10-0)*(5-5) - (0-5)*(6-0) = 30, area 15; and
      -- (0,5),(6,5),(10,10): 6*5 - 0*10 = 30, area 15. The outline: shoelace -50 + 50 + 10 + 50
      -- = 60, area 30 = 15 + 15.
      assert.are.equal("0,5 10,0 6,5 | 0,5 10,10 6,5", piecesOf({ 0,5, 10,0, 6,5, 10,10 }))
    end)

    it("joins an arrow pointing right at its merge vertex", function()
      -- sweep order: (0,0), (0,10), (4,5), (10,5). (4,5) has both neighbours earlier and is
      -- reflex: a merge vertex, helper of the edge below it, (0,0)-(10,5); the next vertex met,
      -- (10,5), joins it. Triangles (0,10),(4,5),(10,5): (4-0)*(5-10) - (5-10)*(10-0) = -20 +
      -- 50 = 30, area 15, and (0,0),(10,5),(4,5): 10*5 - 5*4 = 30, area 15; the outline: shoelace
      -- 100 - 40 + 0 + 0 = 60, area 30.
      assert.are.equal("0,0 10,5 4,5 | 0,10 10,5 4,5", piecesOf({ 10,5, 0,10, 4,5, 0,0 }))
    end)

    it("triangulates a square with a vertical edge either way round", function()
      -- (0,0), (0,4): one x, in y order; the square's two triangles, 8 each of 16
      for _, points in ipairs({ { 0,0, 4,0, 4,4, 0,4 }, { 0,0, 0,4, 4,4, 4,0 } }) do
        local tris, _, taken = bySweep(polygon.polygonTriangulate, points)
        assert.are.equal(1, taken)
        assert.are.equal(2, #tris)
        assert.is_true(oracle.checkCover(points, {}, tris))
      end
    end)
  end)

  describe("on generated outlines", function()
    it("covers noisy circles and grid stars exactly, as convex parts too", function()
      local taken, declined = 0, 0
      local first = 610000 + INDEX * 10000
      for seed = first, first + CASES - 1 do
        local rng = prng.new(seed)
        local points
        if seed % 3 == 0 then
          points = shapes.noisyCircle(8 + seed % 120, rng)
        else
          points = gridStar(rng, 2 + seed % 12, 4 + rng:int(0, 40))
        end
        if seed % 2 == 0 then   -- the other winding
          local reversed = {}
          for i = #points - 1, 1, -2 do
            reversed[#reversed + 1], reversed[#reversed + 2] = points[i], points[i + 1]
          end
          points = reversed
        end
        if seed % 5 == 0 then   -- far from the origin
          for i = 1, #points, 2 do points[i] = points[i] + 2 ^ 20 end
        end
        if #points >= 6 then
          local verdict = oracle.regionCrossing(points, {})
          local tris, message, took, left = bySweep(polygon.polygonTriangulate, points)
          taken, declined = taken + took, declined + left
          local ok, why = oracle.agrees(points, {}, verdict, tris, message)
          assert(ok, ("seed %d: %s"):format(seed, tostring(why)))
          if verdict == "valid" then
            local parts = bySweep(polygon.polygonConvexParts, points)
            ok, why = oracle.checkCover(points, {}, parts, true)
            assert(ok, ("seed %d, parts: %s"):format(seed, tostring(why)))
          end
        end
      end
      -- most valid outlines go by pieces; those with a vertex in line go to ear clipping
      assert.is_true(taken > CASES / 3, ("taken %d of %d"):format(taken, CASES))
      assert.is_true(declined > 0)
    end)
  end)

  describe("on outlines it leaves to ear clipping", function()
    it("leaves a vertex in line with its neighbours, an outline with a hole, and small outlines", function()
      -- (5,0) lies on the edge from (0,0) to (10,0): in line, so no kinds for the sweep
      local _, _, taken, declined = bySweep(polygon.polygonTriangulate, { 0,0, 5,0, 10,0, 10,10, 0,10 })
      assert.are.equal(0, taken)
      assert.are.equal(1, declined)
      -- a hole: the bridges and ear clipping, not asked at all
      _, _, taken, declined = bySweep(polygon.polygonTriangulate, { 0,0, 10,0, 10,10, 0,10 },
        { { 4,4, 6,4, 6,6, 4,6 } })
      assert.are.equal(0, taken + declined)
      -- the prune's check (the default for an outline alone of short edges) leaves no sweep
      -- to read
      local before = monotone.taken + monotone.declined
      assert.is_table(polygon.polygonTriangulate(shapes.noisyCircle(100, prng.new(100))))
      assert.are.equal("prune", sweep.lastWay)
      assert.are.equal(before, monotone.taken + monotone.declined)
    end)
  end)
end)
