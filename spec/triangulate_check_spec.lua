-- The validity check of polygonTriangulate and polygonConvexParts has two ways (polygon/sweep.lua):
-- a grid of cells, whose pairs of edges in one cell are tested and which places each hole by the
-- nearest crossing to its left (or, when that cannot tell, by the crossing rule along a row or
-- column), and the sweep, taken when the grid would be slow (long edges) or too coarse for the
-- coordinates. Both must give every input the same verdict, the oracle's (spec/support: no code
-- shared with the library). Generated cases through both ways, then the hard cases of the grid's
-- hole placement: a hole touching another ring exactly where the crossing rule's ray starts,
-- which once would have taken the touching vertex's side for the hole's; the nearest crossing
-- behind a long edge listed first, at one point for two edges, or on a chain of holes that comes
-- back to itself.

local polygon = require "polygon"
local sweep = require "polygon.sweep"
local oracle = require "oracle"
local prng = require "prng"
local holes = require "holes"
local shapes = require "shapes"
local earcut = require "earcut"

local triangulate = polygon.polygonTriangulate

local JIT = rawget(_G, "jit") ~= nil
local CASES = JIT and 300 or 600
local INDEX = require "seeds"   -- this interpreter's range of seeds

-- polygonTriangulate by one way: the triangles or nil, the message, and the way taken.
local function byWay(grid, points, list)
  sweep.grid = grid
  sweep.lastWay = nil   -- a call refused before the check (zero area) leaves it nil
  local tris, message = triangulate(points, list)
  local way = sweep.lastWay
  sweep.grid = true
  return tris, message, way
end

-- The outline through points {x, y, angle} in order of angle, with points i and i + apart
-- swapped when i is given (most then cross); scaled to thousandths when the seed is a multiple of
-- 5, moved out by 2^40 when of 7.
local function byAngle(pts, seed, i, apart)
  table.sort(pts, function(a, b) return a[3] < b[3] end)
  if i then pts[i], pts[i + apart] = pts[i + apart], pts[i] end
  local scale, offset = seed % 5 == 0 and 1e-3 or 1, seed % 7 == 0 and 2 ^ 40 or 0
  local points = {}
  for _, p in ipairs(pts) do
    points[#points + 1], points[#points + 2] = p[1] * scale + offset, p[2] * scale - offset
  end
  return points
end

-- polygonTriangulate with an outline alone of few edges sent to the prune (not the pairs), against
-- the oracle's verdict; returns the way taken.
local function checkPruned(points, where)
  sweep.pairsLimit = 0
  sweep.lastWay = nil
  local tris, message = triangulate(points)
  local way = sweep.lastWay
  sweep.pairsLimit = sweep.PAIRS_ALL
  local ok, why = oracle.agrees(points, {}, oracle.regionCrossing(points, {}), tris, message)
  assert(ok, where .. ", the prune: " .. tostring(why))
  return way
end

-- Checks one case against the oracle's verdict by both ways; returns the way the default took.
local function checkBoth(points, list, where)
  local verdict = oracle.regionCrossing(points, list)
  local gridTris, gridMessage, way = byWay(true, points, list)
  local sweepTris, sweepMessage, sweepWay = byWay(false, points, list)
  assert(sweepWay == nil or sweepWay == "sweep", where)
  assert((gridTris == nil) == (sweepTris == nil), ("%s: grid %s, sweep %s"):format(where,
    tostring(gridMessage or "accepts"), tostring(sweepMessage or "accepts")))
  local ok, why = oracle.agrees(points, list, verdict, gridTris, gridMessage)
  assert(ok, where .. ": " .. tostring(why))
  -- the sweep's refusal names the trouble too, and its triangles (by monotone pieces, when
  -- the sweep found the outline plain) cover the region as well
  ok, why = oracle.agrees(points, list, verdict, sweepTris, sweepMessage)
  assert(ok, where .. ", the sweep: " .. tostring(why))
  return way, verdict
end

describe("polygonTriangulate's validity check", function()
  after_each(function() sweep.grid, sweep.pairsLimit = true, sweep.PAIRS_ALL end)

  describe("when the grid and the sweep check the same random outlines with random holes", function()
    it("give each the oracle's verdict, and the grid takes most of them", function()
      local ways, verdicts = {}, {}
      local first = 520000 + INDEX * 1000
      for seed = first, first + CASES - 1 do
        local points, list = holes.case(prng.new(seed))
        local way, verdict = checkBoth(points, list, "seed " .. seed)
        ways[way or "none"] = (ways[way or "none"] or 0) + 1
        verdicts[verdict] = (verdicts[verdict] or 0) + 1
      end
      assert.is_true((ways.grid or 0) > CASES / 2, tostring(ways.grid))
      assert.is_true(verdicts.valid > CASES / 3 and verdicts.cross > 0 and verdicts.outside > 0)
    end)
  end)

  describe("when an outline alone has few edges (every pair tested, no cells)", function()
    -- star-shaped outlines of 3 to 22 points of a small integer grid sorted by angle about the
    -- origin (vertical edges, vertices in line with their neighbours, edges through a vertex),
    -- half of them with two vertices swapped (then most cross), some far from the origin or
    -- scaled to thousandths
    local angle = rawget(math, "atan2") or math.atan   -- math.atan takes (y, x) from Lua 5.3
    local function smallOutline(seed)
      local rng = prng.new(seed)
      local size, wanted = 2 + seed % 9, rng:int(3, 22)
      local pts, seen = {}, {}
      for _ = 1, wanted do
        local x, y = rng:int(-size, size), rng:int(-size, size)
        if not seen[x * 1000 + y] and (x ~= 0 or y ~= 0) then
          seen[x * 1000 + y] = true
          pts[#pts + 1] = { x, y, angle(y, x) }
        end
      end
      return byAngle(pts, seed, seed % 2 == 1 and #pts >= 4 and rng:int(1, #pts - 1), 1)
    end

    it("gives random small outlines the oracle's verdict, the sweep's too", function()
      local ways, verdicts, first = {}, {}, 530000 + INDEX * 1000
      for seed = first, first + 2 * CASES - 1 do
        local points = smallOutline(seed)
        if #points >= 6 then
          local way, verdict = checkBoth(points, {}, "seed " .. seed)
          ways[way or "none"] = (ways[way or "none"] or 0) + 1
          verdicts[verdict] = (verdicts[verdict] or 0) + 1
        end
      end
      -- every outline of 3 to 22 vertices that reaches the check goes by the pairs
      assert.are.equal(nil, ways.grid)
      assert.are.equal(nil, ways.sweep)
      assert.is_true(ways.pairs > CASES, tostring(ways.pairs))
      assert.is_true(verdicts.valid > CASES / 4 and verdicts.cross > CASES / 4,
        ("valid %s, cross %s"):format(tostring(verdicts.valid), tostring(verdicts.cross)))
    end)

    it("gives scribbles (random vertices on a 5 by 5 grid) the oracle's verdict", function()
      -- 4 to 9 vertices of 0..4 by 0..4 in random order: crossings, edges along one another,
      -- vertices on edges and repeated, zero areas; the boxes of level and upright edges meet
      -- at their sides only
      local ways, first = {}, 540000 + INDEX * 10000
      for seed = first, first + 4 * CASES - 1 do
        local rng = prng.new(seed)
        local points = {}
        for i = 1, 2 * rng:int(4, 9) do points[i] = rng:int(0, 4) end
        local way = checkBoth(points, {}, "seed " .. seed)
        ways[way or "none"] = (ways[way or "none"] or 0) + 1
        local pruned = checkPruned(points, "seed " .. seed) == "prune" and "pruned" or "not pruned"
        ways[pruned] = (ways[pruned] or 0) + 1
      end
      assert.is_true(ways.pairs > CASES, tostring(ways.pairs))
      assert.is_true(ways.pruned > CASES, tostring(ways.pruned))
      -- cases that mutants of the pairs' loop got wrong (its first form, in the place order,
      -- without its last pair; boxes meeting at a side taken as apart)
      for _, points in ipairs({ { 1,1, 2,2, 1,0, 0,4, 4,3 }, { 2,1, 1,2, 3,1, 0,0, 0,2, 2,3, 4,0 },
          { 3,3, 0,3, 4,4, 3,1, 1,0, 3,1, 3,0 }, { 0,2, 4,2, 1,3, 2,2, 1,1, 3,2 } }) do
        local way, verdict = checkBoth(points, {}, table.concat(points, ","))
        assert.are.equal("pairs", way)
        assert.are.equal("cross", verdict)
      end
      -- and cases that mutants of the prune's loop got wrong (found among scribbles of 0..6
      -- sent to it: its x test with < rather than <=, its y test likewise, without its last
      -- edge, without the last edge it tests an edge against)
      for _, points in ipairs({ { 2,3, 3,1, 2,1, 1,2, 0,2, 1,3, 1,1, 1,3 },
          { 5,3, 4,2, 5,4, 6,0, 1,0, 0,1, 5,5, 5,2 }, { 2,3, 4,1, 4,0, 3,1, 5,1, 1,1 },
          { 2,0, 2,2, 3,3, 1,2, 1,2, 4,2, 3,4, 0,4, 1,1, 2,1, 2,1 }, { 6,6, 2,5, 3,5, 2,6, 1,4 },
          { 2,2, 1,4, 0,0, 4,3, 1,3 }, { 6,0, 1,4, 3,0, 5,6, 1,4 }, { 4,2, 2,3, 4,1, 3,3, 2,3 } }) do
        assert.are.equal("cross", oracle.regionCrossing(points, {}))
        assert.are.equal("prune", checkPruned(points, table.concat(points, ",")))
      end
    end)

    it("takes the pairs where the cells would be too small (2^60), and answers as the oracle", function()
      -- the doubles near 2^60 lie u = 2^8 apart. A U (its notch from x = 16u to 48u, 48u deep),
      -- then a pentagon whose vertex (32u, 80u) lies past its top edge at y = 64u: crossing
      local big, u = 2 ^ 60, 2 ^ 8
      local function at(list)
        local out = {}
        for i, v in ipairs(list) do out[i] = big + v * u end
        return out
      end
      local shape = at({ 0,0, 16,0, 16,48, 48,48, 48,0, 64,0, 64,64, 0,64 })
      assert.are.equal("pairs", (checkBoth(shape, {}, "U at 2^60")))
      local crossed = at({ 0,0, 64,0, 32,80, 64,64, 0,64 })
      local way, verdict = checkBoth(crossed, {}, "crossed at 2^60")
      assert.are.equal("pairs", way)
      assert.are.equal("cross", verdict)
    end)

    it("tells touching at a vertex, a vertex inside an edge and an edge folded back", function()
      -- two squares meeting at (10, 10), one ring: valid (a pinch point)
      local pinch = { 0,0, 10,0, 10,10, 20,10, 20,20, 10,20, 10,10, 0,10 }
      local way, verdict = checkBoth(pinch, {}, "pinch")
      assert.are.equal("pairs", way)
      assert.are.equal("valid", verdict)
      -- the notch's tip (10, 0) on the bottom edge from (0, 0) to (20, 0): touching inside an
      -- edge, which the oracle's verdict decides
      checkBoth({ 0,0, 20,0, 20,20, 15,20, 10,0, 5,20, 0,20 }, {}, "tip on an edge")
      -- a spike out and back along one line: (30, 10) -> (40, 10) -> (30, 10)... as a fold
      checkBoth({ 0,0, 20,0, 20,10, 40,10, 20,10, 20,20, 0,20 }, {}, "fold")
    end)
  end)

  describe("when an outline alone has more edges, short across its width (the prune)", function()
    -- A saw: teeth along the top from (0, 10) to (50, 10), each notch down to (2i + 1, 5), then
    -- (50, 0) and (0, 0): 53 vertices, past the pairs' 48. A vertical line meets it twice to
    -- four times, so the edges by their left ends each meet a few others.
    local function saw(tipX, tipY)
      local points = {}
      for i = 0, 24 do
        local x, y = 2 * i + 1, 5
        if x == tipX then y = tipY end
        for _, v in ipairs({ 2 * i, 10, x, y }) do points[#points + 1] = v end
      end
      for _, v in ipairs({ 50, 10, 50, 0, 0, 0 }) do points[#points + 1] = v end
      return points
    end
    -- twice the triangles' areas, summed (integers: exact)
    local function doubleArea(tris)
      local sum = 0
      for _, t in ipairs(tris) do
        sum = sum + math.abs((t[3] - t[1]) * (t[6] - t[2]) - (t[4] - t[2]) * (t[5] - t[1]))
      end
      return sum
    end

    it("triangulates a saw of 53 vertices and finds a tooth through its base", function()
      -- area: the 50 by 10 box less 25 notches of base 2 and depth 5: 500 - 25 * 5 = 375
      local points = saw()
      local way, verdict = checkBoth(points, {}, "saw")
      assert.are.equal("prune", way)
      assert.are.equal("valid", verdict)
      assert.are.equal(2 * 375, doubleArea(triangulate(points)))
      -- the notch at x = 25 down to y = -1: its edges from (24, 10) and to (26, 10) cross the
      -- base y = 0 at x = 24 + 10/11 and 25 + 1/11, inside it (0 .. 50)
      way, verdict = checkBoth(saw(25, -1), {}, "saw, a tooth through the base")
      assert.are.equal("prune", way)
      assert.are.equal("cross", verdict)
      assert.same({ nil, "edges cross" }, { triangulate(saw(25, -1)) })
      -- down to y = 0: the tip on the base, inside that edge (the oracle decides)
      assert.are.equal("prune", (checkBoth(saw(25, 0), {}, "saw, a tip on the base")))
      -- the last notch, at x = 49, to (49, 0): ending where no later edge begins
      assert.are.equal("prune", (checkBoth(saw(49, 0), {}, "saw, the last tip on the base")))
      assert.are.equal("prune", (checkBoth(saw(49, -1), {}, "saw, the last tooth through")))
    end)

    -- 49 to 260 points about the origin by angle, at radii R (1 - amp u), u uniform, rounded
    -- to integers (repeated points, points in line, edges through vertices); half of them with
    -- two points 2 to 6 apart swapped (most then cross), some scaled to thousandths or far out
    local angle = rawget(math, "atan2") or math.atan
    local function roundOutline(seed)
      local rng = prng.new(seed)
      local n, radius, amp = rng:int(49, 260), rng:int(20, 200), ({ 0.05, 0.2, 0.5 })[seed % 3 + 1]
      local pts = {}
      for i = 1, n do
        local a, r = 2 * math.pi * (i - 1 + 0.8 * rng:float()) / n, radius * (1 - amp * rng:float())
        local x, y = math.floor(r * math.cos(a) + 0.5), math.floor(r * math.sin(a) + 0.5)
        pts[i] = { x, y, angle(y, x) }
      end
      local i = seed % 2 == 1 and rng:int(1, n - 6)
      return byAngle(pts, seed, i, i and rng:int(2, 6))
    end

    it("gives random round outlines the oracle's verdict, the sweep's too", function()
      local ways, verdicts, first = {}, {}, 550000 + INDEX * 1000
      for seed = first, first + CASES - 1 do
        local way, verdict = checkBoth(roundOutline(seed), {}, "seed " .. seed)
        ways[way or "none"] = (ways[way or "none"] or 0) + 1
        verdicts[verdict] = (verdicts[verdict] or 0) + 1
      end
      assert.is_true((ways.prune or 0) > CASES / 2, tostring(ways.prune))
      assert.is_true(verdicts.valid > CASES / 4 and verdicts.cross > CASES / 4,
        ("valid %s, cross %s"):format(tostring(verdicts.valid), tostring(verdicts.cross)))
    end)

    it("is given up for the cells when its edges all start at one line", function()
      -- a zigzag of 120 edges between x = 0 and x = 0.1 down the left of the box 0..10 x
      -- 0..120: the edges' widths add up to about 32, 3 times the box's, but every zigzag edge
      -- starts at x = 0 and meets the 120 others there: 7,000 tests, past twice 20 an edge
      local points = {}
      for i = 0, 120 do points[#points + 1], points[#points + 2] = (i % 2) * 0.1, i end
      for _, v in ipairs({ 10, 120, 10, 0 }) do points[#points + 1] = v end
      local way, verdict = checkBoth(points, {}, "zigzag")
      assert.are_not.equal("prune", way)
      assert.are.equal("valid", verdict)
      -- the last vertex, (10, 0), moved to (-1, 60): the edge to it from (10, 120) passes x =
      -- 0.1 at y = 120 - 60 * 9.9 / 11 = 66, through the zigzag
      points[#points - 1], points[#points] = -1, 60
      way, verdict = checkBoth(points, {}, "zigzag, crossed")
      assert.are_not.equal("prune", way)
      assert.are.equal("cross", verdict)
    end)
  end)

  describe("when the edges are long against the rings' box", function()
    it("takes the sweep for a noisy circle (spikes by the hundred) and answers as the oracle", function()
      -- 1,000 vertices at radii 600 to 1,400: an edge reaches 2.8 cells on average
      local points = shapes.noisyCircle(1000, prng.new(7))
      local way = checkBoth(points, {}, "noisy circle")
      assert.are.equal("sweep", way)
    end)
  end)

  describe("when the coordinates are too large for cells of the rings' size", function()
    it("takes the sweep at 2^60 and answers as the oracle", function()
      -- the doubles near 2^60 lie 2^8 apart: a square of side 64 * 2^8 with a hole in it,
      -- cells of about that side, far below 2^-24 of the coordinates
      local big, u = 2 ^ 60, 2 ^ 8
      local points = { big, big, big + 64 * u, big, big + 64 * u, big + 64 * u, big, big + 64 * u }
      local list = { { big + 16 * u, big + 16 * u, big + 16 * u, big + 32 * u, big + 32 * u, big + 32 * u } }
      assert.is_true(big + 16 * u > big)
      assert.are.equal("sweep", (checkBoth(points, list, "2^60")))
      list[1][1] = big - 16 * u   -- now the hole crosses the outline
      assert.are.equal("sweep", (checkBoth(points, list, "2^60 crossing")))
    end)
  end)

  describe("when many vertices share one vertical line", function()
    it("sorts them by y, spread or crowded, and answers as the oracle", function()
      -- the left side: 40 vertices at x = 0, y spread over 0..390 (a tile map's column) or
      -- crowded into 0..39e-6 below one at y = 400 (the sort's buckets by y crowd again)
      for _, step in ipairs({ 10, 1e-6 }) do
        local points = { 0, 400 }
        for i = 39, 0, -1 do points[#points + 1], points[#points + 2] = 0, i * step end
        for _, v in ipairs({ 100, 0, 100, 400 }) do points[#points + 1] = v end
        checkBoth(points, { { 50, 200, 60, 210, 50, 220 } }, "column " .. step)
        points[2] = 0.5 * step   -- now the first edge runs back along the column: overlapping
        checkBoth(points, {}, "column overlapping " .. step)
      end
    end)
    it("finds the holes that meet the column at one of its vertices", function()
      -- (0, 200) is the outline's and each hole's: touching there, or overlapping, or outside;
      -- the places along the column must come out in order for the nodes there to be one place
      local column = { 0, 400 }
      for i = 39, 0, -1 do column[#column + 1], column[#column + 2] = 0, 10 * i end
      for _, v in ipairs({ 100, 0, 100, 400 }) do column[#column + 1] = v end
      local reversed = {}
      for i = #column - 1, 1, -2 do
        reversed[#reversed + 1], reversed[#reversed + 2] = column[i], column[i + 1]
      end
      local lists = {
        { { 0, 200, 20, 190, 20, 210 } },
        { { 0, 200, 20, 190, 20, 210 }, { 0, 200, 20, 215, 20, 230 } },
        { { 0, 200, 20, 190, 20, 230 }, { 0, 200, 20, 200, 20, 220 } },
        { { 0, 200, -20, 190, -20, 210 } },
      }
      for _, points in ipairs({ column, reversed }) do
        for c, list in ipairs(lists) do checkBoth(points, list, "column, holes " .. c) end
      end
    end)
  end)

  describe("when the outline is a wide flat strip", function()
    it("places its holes along the columns and answers as the oracle", function()
      -- 0..1600 x 0..10, its long sides in edges of 5, so the grid takes it (two rows of
      -- cells); 40 square holes 4 wide at x = 20h - 10; then one hole moved out of the strip,
      -- one into another hole, one touching the bottom side at a vertex
      local points = {}
      for i = 0, 320 do points[#points + 1], points[#points + 2] = 5 * i, 0 end
      for i = 320, 0, -1 do points[#points + 1], points[#points + 2] = 5 * i, 10 end
      local function square(x, y, size) return { x, y, x + size, y, x + size, y + size, x, y + size } end
      local list = {}
      for h = 1, 40 do list[h] = square(20 * h - 10, 3, 4) end
      assert.are.equal("valid", select(2, checkBoth(points, list, "strip")))
      for _, change in ipairs({ { 17, square(330, 12, 4), "outside" },
                                { 18, square(331, 4, 2), "inside" },
                                { 19, { 380, 0, 384, 4, 376, 4 }, "valid" } }) do
        local moved = {}
        for h = 1, 40 do moved[h] = list[h] end
        moved[change[1]] = change[2]
        local way, verdict = checkBoth(points, moved, "strip, hole " .. change[1])
        assert.are.equal(change[3], verdict)
        assert.are.equal("grid", way)
      end
    end)
  end)

  -- A hole in the notch of another: hole 1 is the rectangle 20..80 x 30..70 with a V cut down
  -- from its top side to w = (50, 50), so w is reflex and both its edges rise to y = 30.
  -- Hole 2 touches hole 1 at w only. Seen from w, a ray's side of hole 1 is not hole 2's side:
  -- the grid tries the next vertex of hole 2 (or the placement by the whole rings).
  local OUTLINE = { 0, 0, 100, 0, 100, 100, 0, 100 }
  local NOTCHED = { 20, 30, 50, 50, 80, 30, 80, 70, 20, 70 }
  -- all the orders of a triangle's vertices: each of them first, both ways round
  local function orders(tri)
    local out = {}
    for start = 0, 2 do
      local fwd, back = {}, {}
      for j = 0, 2 do
        local f, b = (start + j) % 3, (start - j) % 3
        fwd[#fwd + 1], fwd[#fwd + 2] = tri[2 * f + 1], tri[2 * f + 2]
        back[#back + 1], back[#back + 2] = tri[2 * b + 1], tri[2 * b + 2]
      end
      out[#out + 1], out[#out + 1] = fwd, back
    end
    return out
  end
  -- the picture mirrored top to bottom (y -> 100 - y), and the outline's turn reversed
  local function flipped(points)
    local out = {}
    for i = 1, #points, 2 do out[i], out[i + 1] = points[i], 100 - points[i + 1] end
    return out
  end

  -- checkBoth on the outline, the notched hole and the triangle `tri` as hole 2, mirrored or not
  local function inNotch(tri, flip, label)
    local outline, notched = OUTLINE, NOTCHED
    if flip then outline, notched, tri = flipped(OUTLINE), flipped(NOTCHED), flipped(tri) end
    return checkBoth(outline, { notched, tri }, label .. " " .. table.concat(tri, ","))
  end

  describe("when a hole touches another at its reflex vertex", function()
    for _, flip in ipairs({ false, true }) do
      local label = flip and " (mirrored)" or ""
      it("accepts the hole in the notch, whichever vertex comes first" .. label, function()
        -- (45, 35) and (55, 35) lie above both edges of the notch: the edge (20, 30)-(50, 50)
        -- is at y = 30 + 25 * 20 / 30 = 46.7 for x = 45, below 35 on screen
        for _, tri in ipairs(orders({ 50, 50, 55, 35, 45, 35 })) do
          local way, verdict = inNotch(tri, flip, "notch")
          assert.are.equal("valid", verdict)
          assert.are.equal("grid", way)
        end
      end)
      it("refuses the hole inside the other, touching at the reflex vertex" .. label, function()
        -- (45, 60) and (55, 60) lie inside hole 1's rectangle, below w: the two holes'
        -- regions overlap, which the oracle and the library call a crossing
        for _, tri in ipairs(orders({ 50, 50, 45, 60, 55, 60 })) do
          local _, verdict = inNotch(tri, flip, "nested")
          assert.are.equal("cross", verdict)
        end
      end)
    end
  end)

  -- The oracle's verdicts on OUTLINE with the holes `before` and then `tri`, in each order of
  -- tri's vertices, each checked by checkBoth.
  local unpack = rawget(table, "unpack") or rawget(_G, "unpack")   -- (5.1, LuaJIT: a global)
  local function verdicts(before, tri, label)
    local out = {}
    for _, t in ipairs(orders(tri)) do
      local list = { unpack(before) }
      list[#list + 1] = t
      local _, verdict = checkBoth(OUTLINE, list, label .. " " .. table.concat(t, ","))
      out[#out + 1] = verdict
    end
    return out
  end
  local function allOf(list, wanted)
    for _, v in ipairs(list) do assert.are.equal(wanted, v) end
  end

  describe("when a hole's vertex lies inside a level edge of another ring", function()
    it("accepts the hole touching from outside and refuses it from inside", function()
      -- hole 1: the rectangle 20..80 x 40..60; (50, 40) lies inside its top edge
      local rect = { 20, 40, 80, 40, 80, 60, 20, 60 }
      allOf(verdicts({ rect }, { 50, 40, 55, 30, 45, 30 }, "above"), "valid")
      allOf(verdicts({ rect }, { 50, 40, 45, 50, 55, 50 }, "below"), "cross")   -- overlapping
      -- the outline's top edge holds (50, 0): a hole touching it from inside the polygon
      allOf(verdicts({}, { 50, 0, 55, 10, 45, 10 }, "outline"), "valid")
    end)
  end)

  describe("when every vertex of a hole lies on another ring", function()
    it("places the hole by the whole rings", function()
      -- hole 2's three vertices lie on hole 1's boundary (two of its corners and a point of
      -- its bottom side): inside hole 1, so refused
      local rect = { 20, 20, 80, 20, 80, 80, 20, 80 }
      for _, verdict in ipairs(verdicts({ rect }, { 20, 20, 80, 20, 50, 80 }, "on rect")) do
        assert.is_true(verdict == "inside" or verdict == "cross" or verdict == "unknown", verdict)
      end
      for _, tri in ipairs(orders({ 20, 20, 80, 20, 50, 80 })) do
        assert.is_nil((triangulate(OUTLINE, { rect, tri })))
      end
    end)
  end)

  -- The square 0..100 with its top side (y = 100) in `teeth` teeth 1 deep, so that the grid
  -- takes it with holes of long edges (400 edges in a box of 100: cells of about 5); flipped, the
  -- same picture upside down, where each ring's nodes run the other way round.
  local function toothed(teeth, flip)
    local out = { 0, 0, 100, 0, 100, 100 }
    for i = 1, teeth do
      local x = 100 - 100 * i / teeth
      out[#out + 1], out[#out + 2] = x + 50 / teeth, 99
      out[#out + 1], out[#out + 2] = x, 100
    end
    return flip and flipped(out) or out
  end

  describe("when a hole is placed by the nearest crossing to its left", function()
    it("looks past a long shallow edge that its cells list first", function()
      -- the outline's edge e from (1000, 544.5) to (450, 517) rises 0.05 a unit: at hole 2's
      -- levels (519.6 to 520.8) it lies in the row of cells 499.4..549.3 (cells of 1,000 /
      -- sqrt(401) = 49.94) from x = 450 to 1,000, so the cell of hole 2's vertex lists it; it
      -- meets y = 520 at x = 450 + 3 / 0.05 = 510, in the column 499.4..549.3 where hole 1's
      -- left side x = 540 also is. Hole 1 lies under e (e is at 517 + 0.05 * 90 = 521.5 at x =
      -- 540, above hole 1's top 521) and holds hole 2: the ray must read that whole column.
      local points = { 0, 0, 1000, 0, 1000, 544.5, 450, 517, 450, 1000 }
      for i = 1, 194 do   -- the top: teeth, so that the cells are small
        local x = 450 - 450 * i / 195
        points[#points + 1], points[#points + 2] = x + 450 / 195 / 2, 995
        points[#points + 1], points[#points + 2] = x, 1000
      end
      points[#points + 1], points[#points + 2] = 0, 1000
      local box = { 540, 515, 950, 515, 950, 521, 540, 521 }
      for _, tri in ipairs(orders({ 900, 520, 880, 519.6, 885, 520.8 })) do
        local way, verdict = checkBoth(points, { box, tri }, "roof " .. table.concat(tri, ","))
        assert.are.equal("inside", verdict)
        assert.are.equal("grid", way)
        assert.are.equal("grid", (checkBoth(points, { tri }, "roof alone")))
      end
    end)

    it("refuses a hole inside one of two holes back to back, whichever comes first", function()
      -- holes 1 and 2 share a stretch of x = 50; hole 3 lies inside the right one, so its ray
      -- meets both edges there at one point: that tells nothing, and the whole rings decide
      local lefts = { { 10, 10, 50, 10, 50, 90, 10, 90 }, { 10, 30, 50, 30, 50, 90, 10, 90 } }
      local rights = { { 50, 10, 90, 10, 90, 90, 50, 90 }, { 50, 10, 90, 10, 90, 70, 50, 70 } }
      for _, flip in ipairs({ false, true }) do
        local outline = toothed(200, flip)
        for v = 1, 2 do
          for _, tri in ipairs(orders({ 60, 40, 70, 50, 60, 60 })) do
            for _, list in ipairs({ { lefts[v], rights[v], tri }, { rights[v], lefts[v], tri } }) do
              local way, verdict = checkBoth(outline, list, "back to back " .. v)
              assert.are.equal("inside", verdict)
              assert.are.equal("grid", way)
            end
          end
        end
      end
    end)

    it("refuses a hole inside another whose side has a vertex at the hole's level", function()
      -- hole 1's left side x = 10 has a vertex at (10, 40) or (10, 60), at the level of hole
      -- 2's vertices: the edge below it crosses the level just above, the one above it does not
      -- (an end at the level counts as below); both ways round (flipped)
      local inner = { 40, 40, 60, 40, 60, 60, 40, 60 }
      for _, y in ipairs({ 40, 60 }) do
        local around = { 10, 10, 90, 10, 90, 90, 10, 90, 10, y }
        for _, flip in ipairs({ false, true }) do
          local list = flip and { flipped(around), flipped(inner) } or { around, inner }
          local way, verdict = checkBoth(toothed(200, flip), list, "vertex at the level " .. y)
          assert.are.equal("inside", verdict)
          assert.are.equal("grid", way)
        end
      end
    end)

    it("places holes whose rays meet each other, inside the outline or out of it", function()
      -- hole G is a C open to the right (its mouth 20..95 x 40..60) with a tooth hanging into
      -- the mouth's end at (93, 50); hole H, a tongue 30..88 x 45..55, lies in the mouth. H's
      -- rays meet G's mouth; the ray from the tooth's tip meets H's right side: a chain that
      -- comes back to H, placed by the whole rings. Inside the outline both are valid; moved
      -- 200 to the right, both are outside, and the first is named.
      local g = { 96, 60, 96, 80, 10, 80, 10, 20, 95, 20, 95, 40, 20, 40, 20, 60, 90, 60, 93, 50 }
      local h = { 30, 45, 88, 45, 88, 55, 30, 55 }
      local function moved(ring, dx)
        local out = {}
        for i = 1, #ring, 2 do out[i], out[i + 1] = ring[i] + dx, ring[i + 1] end
        return out
      end
      for _, flip in ipairs({ false, true }) do
        local outline = toothed(200, flip)
        local gf, hf = flip and flipped(g) or g, flip and flipped(h) or h
        for _, list in ipairs({ { hf, gf }, { gf, hf } }) do
          local way, verdict = checkBoth(outline, list, "C and tongue")
          assert.are.equal("valid", verdict)
          assert.are.equal("grid", way)
          local out = { moved(list[1], 200), moved(list[2], 200) }
          way, verdict = checkBoth(outline, out, "C and tongue outside")
          assert.are.equal("outside", verdict)
          assert.are.equal("grid", way)
          assert.are.equal("holes[1] is outside the polygon", select(2, triangulate(outline, out)))
        end
      end
    end)

    it("places a strip's holes each through its neighbour, none by whole rows", function()
      -- the strip of "when the outline is a wide flat strip": 0..1600 x 0..10 with 40 squares
      -- 4 wide at x = 20h - 10, in cells of about sqrt(16000 / 802) = 4.5, so a square's sides
      -- pass two cells: a ray sees one edge twice, which is no tie. Each hole's first ray meets
      -- its left neighbour's right side (the first hole's, the outline's left side).
      local points = {}
      for i = 0, 320 do points[#points + 1], points[#points + 2] = 5 * i, 0 end
      for i = 320, 0, -1 do points[#points + 1], points[#points + 2] = 5 * i, 10 end
      local list = {}
      for h = 1, 40 do
        local x = 20 * h - 10
        list[h] = { x, 3, x + 4, 3, x + 4, 7, x, 7 }
      end
      local tris, message, way = byWay(true, points, list)
      assert.truthy(tris, message)
      assert.are.equal("grid", way)
      assert.are.equal(0, sweep.lastSlow)
    end)

    it("places nearly every hole of earcut's fixtures by the nearest crossing", function()
      -- holes touching each other at vertices by the hundred: a ray that starts on another ring
      -- tells nothing, the hole's next vertex does (counted once: 0 of self-tangent-4's 272 and
      -- touching-holes6's 168 holes were left to whole rows, and 10 of water-huge3's 1,443)
      for _, name in ipairs({ "self-tangent-4", "touching-holes6" }) do
        local points, list = earcut.load(name)
        local tris, message, way = byWay(true, points, list)
        assert.truthy(tris, message)
        assert.are.equal("grid", way)
        assert.is_true(sweep.lastSlow <= #list / 20, name .. ": " .. sweep.lastSlow)
      end
    end)

    it("names a hole holding the whole outline as the sweep does", function()
      -- hole 1 lies inside the outline; hole 2 holds all of it, and so is outside the polygon
      local inner, around = { 40, 40, 60, 40, 60, 60, 40, 60 }, { -50, -50, 150, -50, 150, 150, -50, 150 }
      local outline = toothed(200, false)
      for _, grid in ipairs({ true, false }) do
        local tris, message, way = byWay(grid, outline, { inner, around })
        assert.is_nil(tris)
        assert.are.equal(grid and "grid" or "sweep", way)
        assert.are.equal("holes[2] is outside the polygon", message)
      end
    end)
  end)

  -- The sweep places a hole by the edge just below its leftmost place: inside when that edge has
  -- the inside above it. Two edges running along each other, one each way, have the inside on
  -- opposite sides; which of them the order puts nearer the hole is not known there, so such a
  -- pair leaves the hole to the crossing rule. Taking the nearer one as it came placed a hole
  -- above a spike out of a square inside (the ear clipping then refused it: "edges overlap or
  -- cross"), and one inside an outline whose two parts meet along a line outside.
  -- At a place where a vertex lies inside another ring's edge, the edges there alternated and
  -- nested, but nothing asked whether the polygon's side of each edge lies on the polygon's side
  -- of every other ring through the place.
  describe("when a hole runs along the outline's edge and on past its vertex", function()
    it("names the hole crossing the outline, both ways", function()
      -- the outline's edges lie on x = 24 (y from 0 to 48) and x + y = 72 (x from 0 to 24),
      -- the triangle on x + y <= 72; the hole's (24, 37) and (20, 52) lie on them and (0, 72)
      -- is the outline's vertex, but (24, 58) lies outside (24 + 58 = 82): its edge up x = 24
      -- passes the outline's vertex (24, 48), out of the polygon. Before, the ear clipping
      -- refused it without naming a ring ("edges overlap or cross").
      local points, list = { 0,72, 24,48, 24,0 }, { { 24,37, 0,72, 20,52, 24,58 } }
      for _, grid in ipairs({ true, false }) do
        local tris, message = byWay(grid, points, list)
        assert.is_nil(tris)
        assert.are.equal("holes[1] crosses the outline", message)
      end
    end)
  end)

  -- Three or more edges along one direction from a place leave it untested (polygon/places.lua):
  -- the ear clipping decides such a case for polygonTriangulate, and polygonConvexParts' path
  -- for outlines along the axes (rectangles, no ear clipping) took the check's word for it.
  describe("when the check leaves a place untested", function()
    it("gives polygonTriangulate's answer from polygonConvexParts too, both ways", function()
      -- hole 1 a square (1..2, 8..9) with a spike down x = 1 to (1, 6) and back; hole 2 the
      -- square (1..2, 6..7), its edge from (1, 6) to (1, 7) along the spike: three edges go up
      -- x = 1 from (1, 6). The oracle leaves it undecided.
      local points, list = { 0,0, 3,0, 3,12, 0,12 }, { { 1,9, 2,9, 2,8, 1,8, 1,6 }, { 2,7, 2,6, 1,6, 1,7 } }
      assert.are.equal("unknown", oracle.regionCrossing(points, list))
      for _, grid in ipairs({ true, false }) do
        sweep.grid = grid
        local tris, message = triangulate(points, list)
        local parts, partsMessage = polygon.polygonConvexParts(points, list)
        sweep.grid = true
        assert.are.equal(tris == nil, parts == nil, "grid " .. tostring(grid))
        assert.are.equal(message, partsMessage)
        if tris then
          assert.is_true((oracle.checkCover(points, list, tris)))
          assert.is_true((oracle.checkCover(points, list, parts, true)))
        end
      end
    end)
  end)

  describe("when the edge below a hole runs along another edge", function()
    it("places the hole by the crossing rule, both ways", function()
      -- a square with a spike out along y = 50 to (150, 50) and back; triangles above and below
      -- the spike, outside the square
      local spiked = { 0,0, 100,0, 100,50, 150,50, 100,50, 100,100, 0,100 }
      for _, hole in ipairs({ { 120,55, 130,55, 125,60 }, { 120,45, 125,40, 130,45 },
          { 110,55, 140,55, 140,60, 110,60 } }) do
        local _, verdict = checkBoth(spiked, { hole }, "above or below a spike")
        assert.are.equal("outside", verdict)
        for _, grid in ipairs({ true, false }) do
          local tris, message = byWay(grid, spiked, { hole })
          assert.is_nil(tris)
          assert.are.equal("holes[1] is outside the polygon", message)
        end
      end
      -- an outline of petals about (50, 50), two of them meeting along the ray from there
      -- through (31, 88) and (30, 90) (its edges from (31, 88) back to the centre and from the
      -- centre out to (30, 90) run along each other), a hole in the petal above the ray touching
      -- the centre: inside (its point (50.5, 55.2) has winding number 1), the oracle undecided
      local petals = { 50,50, 80,35, 69,50, 50,50, 74,62, 68,68, 50,50, 65,65, 68,86, 50,63, 31,88,
        50,50, 30,90, 33,67 }
      local hole = { 50,50, 53,56, 50,55, 47,56 }
      checkBoth(petals, { hole }, "petals meeting along a ray")
      for _, grid in ipairs({ true, false }) do
        local tris = byWay(grid, petals, { hole })
        assert.is_truthy(tris)
        assert.is_true((oracle.checkCover(petals, { hole }, tris)))
      end
    end)
  end)
end)
