-- polygonTriangulate and polygonConvexParts on hard input: pinched tile-map outlines, spirals,
-- combs, stars with near-collinear runs, 1e-9 dents, a fine 256-gon far from the origin, all of
-- them again translated by 1e5, 1e9 and 1e12 plus a fraction, holes, 10,000-vertex outlines and
-- invalid input. Every result is held to the exact oracle (oracle.checkPieces).

local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local shapes = require "shapes"
local tiles = require "tiles"

local triangulate, convexParts = polygon.polygonTriangulate, polygon.polygonConvexParts

local spiral, noisyCircle = shapes.spiral, shapes.noisyCircle
local OFFSETS = { 1e5 + 0.375, 1e9 + 0.375, 1e12 + 0.375 }


-- A comb: a spine along the bottom and `teeth` teeth of width 2 with gaps of 1, pointing up.
local function comb(teeth)
  local points = { 0, 10, 0, 0 }
  for k = 0, teeth - 1 do
    local x = 3 * k + 1
    points[#points + 1], points[#points + 2] = x, 0
    points[#points + 1], points[#points + 2] = x, -40
    points[#points + 1], points[#points + 2] = x + 2, -40
    points[#points + 1], points[#points + 2] = x + 2, 0
  end
  points[#points + 1], points[#points + 2] = 3 * teeth + 1, 0
  points[#points + 1], points[#points + 2] = 3 * teeth + 1, 10
  return points
end

-- A star of `spikes` spikes whose edges are cut into `steps` pieces, each cut point moved off
-- the straight line by a few ulps: runs of vertices almost, but not exactly, in line.
local function nearCollinearStar(spikes, steps, rng)
  local points = {}
  for k = 0, 2 * spikes - 1 do
    local a0, a1 = k * math.pi / spikes, (k + 1) * math.pi / spikes
    local r0, r1 = k % 2 == 0 and 100 or 40, k % 2 == 0 and 40 or 100
    local x0, y0, x1, y1 = r0 * math.cos(a0), r0 * math.sin(a0), r1 * math.cos(a1), r1 * math.sin(a1)
    for s = 0, steps - 1 do
      local f = s / steps
      local wobble = 1 + (rng:int(-4, 4) * 2 ^ -52)
      points[#points + 1] = (x0 + (x1 - x0) * f) * wobble
      points[#points + 1] = (y0 + (y1 - y0) * f) * wobble
    end
  end
  return points
end

-- The unit square with a dent of depth 1e-9 in its bottom edge and a bump of 1e-9 on its top.
local DENTED = { 0, 0, 0.5, 1e-9, 1, 0, 1, 1, 0.5, 1 + 1e-9, 0, 1 }

-- A convex n-gon of radius r centred at (cx, cy).
local function regular(n, r, cx, cy)
  local points = {}
  for i = 0, n - 1 do
    local t = 2 * math.pi * i / n
    points[#points + 1], points[#points + 2] = cx + r * math.cos(t), cy + r * math.sin(t)
  end
  return points
end


-- Checks both functions on one polygon against the oracle; returns the parts.
-- A spike 1000 tall and 2 wide, tip (1, 1000) over base corners (0, 0) and (2, 0), standing on
-- a slab 1000 wide whose wavy bottom holds `baseVertices` vertices, so that the ear test's cells
-- are about 30 wide: the spike's ear crosses some 30 rows of them. A notch rises from the bottom
-- to r = (1.5 - hair, 500), inside the spike by `hair` from its right side (hair 0: on it), so r
-- blocks the spike's ear; missing it gives overlapping triangles. All of it turned by `angle`
-- around the origin (r stays inside: the turn rounds by about 1e-13).
-- Arithmetic: the right side runs from (1, 1000) to (2, 0), x = 2 - y / 1000, 1.5 at y = 500.
local function notchedSpike(baseVertices, hair, angle, rng)
  local points = { 0, 0, 1, 1000, 2, 0, 500, 0 }
  local function bottom(from, to, count)
    for k = 0, count - 1 do
      local x = from + (to - from) * k / count
      points[#points + 1], points[#points + 2] = x, -10 - 5 * rng:float()
    end
  end
  bottom(500, 1.55, baseVertices / 2)
  points[#points + 1], points[#points + 2] = 1.55, -10
  points[#points + 1], points[#points + 2] = 1.5 - hair, 500
  points[#points + 1], points[#points + 2] = 1.45, -10
  bottom(1.45, -500, baseVertices / 2)
  points[#points + 1], points[#points + 2] = -500, -10
  points[#points + 1], points[#points + 2] = -500, 0
  if angle ~= 0 then
    local c, s = math.cos(angle), math.sin(angle)
    for i = 1, #points, 2 do
      local x, y = points[i], points[i + 1]
      points[i], points[i + 1] = x * c - y * s, x * s + y * c
    end
  end
  return points
end

local function checkBoth(points, holes)
  local tris, message = triangulate(points, holes)
  assert.is_truthy(tris, message)
  local ok, why = oracle.checkPieces(points, holes, tris, false)
  assert.is_true(ok, why)
  local parts
  parts, message = convexParts(points, holes)
  assert.is_truthy(parts, message)
  ok, why = oracle.checkPieces(points, holes, parts, true)
  assert.is_true(ok, why)
  -- Hertel and Mehlhorn's bound: every diagonal left is needed at a reflex vertex, at most two
  -- per reflex vertex, so at most 2 r + 1 parts (every hole vertex counts as reflex)
  local r = oracle.reflexCount(points)
  for _, hole in ipairs(holes or {}) do r = r + #hole / 2 end
  assert.is_true(#parts <= 2 * r + 1, ("%d parts for %d reflex vertices"):format(#parts, r))
  assert.is_true(#parts <= #tris)
  return parts, tris
end

describe("the oracle for pieces", function()
  it("catches an overlap, a gap, a foreign vertex and a wrong winding", function()
    local square = { 0, 0, 10, 0, 10, 10, 0, 10 }
    local tris = triangulate(square)
    assert.is_true(oracle.checkPieces(square, nil, tris))
    -- the square's two halves along the other diagonal, plus one overlapping triangle
    local halves = { { 0, 0, 10, 0, 10, 10 }, { 0, 0, 10, 10, 0, 10 } }
    assert.is_true(oracle.checkPieces(square, nil, halves))
    assert.is_false(oracle.checkPieces(square, nil, { halves[1], { 0, 0, 10, 0, 0, 10 } }))
    assert.is_false(oracle.checkPieces(square, nil, { halves[1] }))
    assert.is_false(oracle.checkPieces(square, nil, { halves[1], { 0, 0, 10, 10, 0, 10.5 } }))
    assert.is_false(oracle.checkPieces(square, nil, { halves[1], shapes.reverse(halves[2]) }))
    -- equal area, but the pieces overlap and leave a gap
    assert.is_false(oracle.checkPieces(square, nil, { { 0, 0, 10, 0, 10, 10 }, { 0, 0, 10, 0, 10, 10 } }))
  end)
end)

describe("polygonTriangulate and polygonConvexParts on hard input", function()
  describe("when given pinched tile-map outlines", function()
    it("cover every outline of random tile sets exactly, holes included", function()
      local rng = prng.new(4242)
      local shapesSeen, holesSeen, pinches = 0, 0, 0
      for round = 1, 36 do
        local set = tiles.random(rng, 6, 6, ({ 0.55, 0.7, 0.8 })[round % 3 + 1])
        for _, shape in ipairs(tiles.shapes(set, 10, 0, 0)) do
          local outline, holes = shape[1], shape[2]
          checkBoth(outline, holes)
          shapesSeen, holesSeen = shapesSeen + 1, holesSeen + #holes
          local seen = {}
          for i = 1, #outline - 1, 2 do
            local key = outline[i] .. "," .. outline[i + 1]
            if seen[key] then pinches = pinches + 1 end
            seen[key] = true
          end
        end
      end
      -- the generator does make the cases this is about
      assert.is_true(shapesSeen > 40 and holesSeen > 5 and pinches > 20,
        ("%d outlines, %d holes, %d pinch points"):format(shapesSeen, holesSeen, pinches))
    end)

    it("do the same far from the origin", function()
      local rng = prng.new(777)
      for _ = 1, 6 do
        local set = tiles.random(rng, 5, 5, 0.7)
        for _, offset in ipairs(OFFSETS) do
          for _, shape in ipairs(tiles.shapes(set, 10, offset, -offset)) do
            checkBoth(shape[1], shape[2])
          end
        end
      end
    end)

    it("split two tiles meeting at a corner into the two tiles", function()
      local parts = checkBoth({ 0, 0, 10, 0, 10, 10, 20, 10, 20, 20, 10, 20, 10, 10, 0, 10 })
      assert.are.equal(2, #parts)
    end)
  end)

  describe("when given spirals, combs and near-collinear stars", function()
    it("cover a spiral of 400 vertices", function()
      checkBoth(spiral(400, 3))
    end)

    it("cover a comb of 40 teeth, in as many parts as teeth plus the spine", function()
      local parts = checkBoth(comb(40))
      assert.is_true(#parts <= 2 * 40 + 1)
    end)

    it("cover stars whose edges are runs of almost collinear vertices", function()
      local rng = prng.new(99)
      for _ = 1, 4 do
        checkBoth(nearCollinearStar(7, 6, rng))
      end
    end)

    it("cover a square with dents of 1e-9", function()
      local parts = checkBoth(DENTED)
      -- the dent is a reflex vertex, the bump a convex one: two parts
      assert.are.equal(2, #parts)
    end)

    it("cover all of them translated by 1e5, 1e9 and 1e12 plus a fraction", function()
      local rng = prng.new(5)
      local cases = { spiral(200, 2), comb(12), nearCollinearStar(5, 4, rng), DENTED }
      for _, offset in ipairs(OFFSETS) do
        for _, points in ipairs(cases) do
          checkBoth(shapes.translate(points, offset, offset * 0.75))
        end
      end
    end)
  end)

  describe("when a reflex vertex lies a hair inside a long thin ear", function()
    it("keeps the ear out, at every turn and offset", function()
      local rng = prng.new(77)
      for _, hair in ipairs({ 1e-6, 1e-9, 0 }) do
        for _, angle in ipairs({ 0, 0.3, 1.1, 2.5, -0.7 }) do
          if hair > 0 or angle == 0 then   -- hair 0 needs exact coordinates: no turn
            local points = notchedSpike(2000, hair, angle, rng)
            checkBoth(points)
            checkBoth(shapes.translate(points, OFFSETS[1], OFFSETS[1]))
          end
        end
      end
    end)
  end)

  describe("when given a convex 256-gon of radius 1 at (5e5, 5e5)", function()
    it("gives 254 triangles and one part", function()
      local points = regular(256, 1, 5e5, 5e5)
      assert.are.equal("convex", oracle.polygonType(points))
      local parts, tris = checkBoth(points)
      assert.are.equal(254, #tris)
      assert.are.equal(1, #parts)
      assert.are.equal(#points, #parts[1])
    end)
  end)

  describe("when given holes", function()
    it("cover a comb with holes, one touching the outline at a vertex", function()
      local outline = { 0, 0, 100, 0, 100, 100, 0, 100 }
      local holes = {
        { 0, 0, 20, 10, 10, 20 },                 -- touches the outline at (0, 0)
        { 40, 40, 60, 40, 60, 60, 40, 60 },
        { 60, 60, 80, 70, 70, 80 },               -- touches the square hole at (60, 60)
        { 20, 70, 30, 75, 25, 90 },
      }
      checkBoth(outline, holes)
      for _, offset in ipairs(OFFSETS) do
        local moved = {}
        for i, hole in ipairs(holes) do moved[i] = shapes.translate(hole, offset, offset) end
        checkBoth(shapes.translate(outline, offset, offset), moved)
      end
    end)

    it("cover a 64-gon with 20 square holes", function()
      local outline = regular(64, 1000, 0, 0)
      local holes = {}
      for i = 0, 19 do
        local x, y = -500 + (i % 5) * 220, -450 + math.floor(i / 5) * 250
        holes[#holes + 1] = { x, y, x + 100, y, x + 100, y + 100, x, y + 100 }
      end
      checkBoth(outline, holes)
    end)
  end)

  describe("when given 10,000-vertex outlines", function()
    it("cover a noisy circle of 10,000 vertices", function()
      local parts, tris = checkBoth(noisyCircle(10000, prng.new(31)))
      assert.are.equal(9998, #tris)
      assert.is_true(#parts < 9998)
    end)

    it("cover a spiral of 10,000 vertices with 9,998 triangles", function()
      -- the triangulation only: checking 5,000 convex parts exactly would double the spec's time
      local points = spiral(10000, 6)
      local tris = triangulate(points)
      assert.are.equal(9998, #tris)
      assert.is_true(oracle.checkPieces(points, nil, tris))
    end)
  end)

  describe("when noisy outlines of up to 160 vertices have two vertices swapped, or not", function()
    -- the sweep meets tens of edges at once, inserting and removing them all along its order,
    -- and the ear test's grid drops entries as it clips; each outline is held to the oracle's
    -- brute-force crossing test: nil exactly when it finds a crossing, else covered exactly
    it("return nil exactly for those that cross, and cover the others", function()
      local rng = prng.new(41)
      local seen = { cross = 0, simple = 0 }
      for trial = 1, 36 do
        local n = rng:int(40, 160)
        local points = noisyCircle(n, rng)
        if trial % 3 > 0 then   -- two of three swapped: most of those cross
          local i = rng:int(0, n - 1)
          local j = (i + rng:int(2, 4)) % n
          points[2 * i + 1], points[2 * j + 1] = points[2 * j + 1], points[2 * i + 1]
          points[2 * i + 2], points[2 * j + 2] = points[2 * j + 2], points[2 * i + 2]
        end
        local verdict = oracle.outlineCrossing(points)
        seen[verdict] = seen[verdict] + 1
        local tris, message = triangulate(points)
        if verdict == "cross" then
          assert.is_nil(tris)
          assert.are.equal("edges cross", message)
        else
          assert.is_true(oracle.checkPieces(points, nil, assert(tris, message)))
        end
      end
      -- both kinds came up
      assert.is_true(seen.cross >= 10 and seen.simple >= 10, seen.cross .. " " .. seen.simple)
    end)
  end)

  describe("when the outline crosses or overlaps itself where vertices meet", function()
    -- no two edges cross at a point inside both: each outline crosses itself at a vertex, or
    -- runs along itself the same way; the oracle's brute-force test says "cross" for each
    local crossing = {
      -- (1,5) -> (5,3) twice, the same way
      { 3, 5, 1, 5, 5, 3, 6, 6, 0, 6, 1, 5, 5, 3, 5, 5, 2, 6 },
      -- no repeated vertex: (4,3) lies inside the edge (5,1)-(3,5) ((4,3) - (5,1) = (-1,2), half
      -- of (-2,4)), and the path (6,0) -> (4,3) -> (2,3) crosses that edge there
      { 0, 1, 6, 0, 4, 3, 2, 3, 5, 1, 3, 5, 0, 4 },
      -- (5,6) visited twice, the two visits' edges interleaved around it
      { 5, 6, 1, 5, 2, 2, 5, 6, 3, 5, 2, 2, 2, 2, 4, 1 },
      { 6, 6, 5, 0, 5, 0, 4, 3, 0, 3, 6, 6, 3, 4, 4, 5 },
      -- (5,5) -> (5,1) and (5,2) -> (5,1) both run down x = 5 into (5,1)
      { 1, 4, 3, 6, 5, 5, 5, 1, 3, 3, 5, 2, 5, 1 },
      -- (5,2) -> (1,5) twice
      { 1, 5, 3, 4, 5, 2, 1, 5, 5, 4, 5, 2 },
      -- (2,1) and (4,1) inside the edge (5,1) -> (1,1), the path through (2,1) turning across it
      { 0, 1, 2, 3, 5, 1, 1, 1, 2, 1, 2, 2, 4, 1, 5, 0 },
    }

    it("returns nil and a message for each, as for crossing edges", function()
      for _, points in ipairs(crossing) do
        assert.are.equal("cross", oracle.outlineCrossing(points))
        local tris, message = triangulate(points)
        assert.is_nil(tris)
        assert.are.equal("edges cross", message)
        assert.is_nil(convexParts(points))
        assert.is_nil(triangulate(shapes.translate(points, 1e9 + 0.375, 1e9 + 0.375)))
      end
    end)

    it("still covers weakly simple outlines that touch or run along themselves", function()
      local cases = {
        -- a spike from (2,4) out along the edge (2,4) -> (4,2) and on to (5,1), and back
        { { 5, 1, 2, 4, 4, 2, 6, 2, 2, 4 } },
        -- a slit from (5,10) in to (5,5)
        { { 0, 0, 10, 0, 10, 10, 5, 10, 5, 5, 5, 10, 0, 10 } },
        -- a hole touching the outline at (5,0), inside the edge (0,0) -> (10,0)
        { { 0, 0, 10, 0, 10, 10, 0, 10 }, { { 5, 0, 7, 3, 3, 3 } } },
        -- two tiles meeting at a corner, and an hourglass pinched at (2,2)
        { { 0, 0, 10, 0, 10, 10, 20, 10, 20, 20, 10, 20, 10, 10, 0, 10 } },
        { { 0, 0, 4, 0, 2, 2, 4, 4, 0, 4, 2, 2 } },
      }
      for _, case in ipairs(cases) do
        local points, holes = case[1], case[2]
        assert.are_not.equal("cross", oracle.outlineCrossing(points))
        assert.is_true(oracle.checkPieces(points, holes, assert(triangulate(points, holes))))
        assert.is_true(oracle.checkPieces(points, holes, assert(convexParts(points, holes)), true))
      end
    end)

    it("agree with the oracle's brute-force test on random outlines on a 7 x 7 grid", function()
      -- "cross": nil; "simple": triangles that cover the outline; "unknown" (edges running
      -- along each other both ways, their order undecided locally): either
      local rng = prng.new(7)
      local seen = { cross = 0, simple = 0, unknown = 0 }
      for _ = 1, 2000 do
        local points = {}
        for i = 1, 2 * rng:int(3, 10) do points[i] = rng:int(0, 6) end
        if oracle.winding(points) then
          local verdict = oracle.outlineCrossing(points)
          seen[verdict] = seen[verdict] + 1
          local tris = triangulate(points)
          if verdict == "cross" then
            assert.is_nil(tris, table.concat(points, ","))
          elseif verdict == "simple" or tris then
            assert.is_true(oracle.checkPieces(points, nil, assert(tris, table.concat(points, ","))))
          end
        end
      end
      -- every kind came up often
      assert.is_true(seen.cross > 500 and seen.simple > 200 and seen.unknown > 50)
    end)
  end)

  describe("when given invalid input", function()
    it("returns nil and a message for a bow-tie", function()
      local tris, message = triangulate({ 0, 0, 10, 10, 10, 0, 0, 20, -10, 20, -10, 10 })
      assert.is_nil(tris)
      assert.are.equal("edges cross", message)
    end)

    it("returns nil and a message for a comb with one tooth bent across its neighbour", function()
      local points = comb(10)
      -- the third tooth's top right corner (9, -40) moved to x = 14, past the fourth tooth
      -- (x from 10 to 12): tooth k's corners start at index 5 + 8 k, this one is the third
      assert.are.equal(9, points[5 + 8 * 2 + 4])
      points[5 + 8 * 2 + 4] = 14
      local tris, message = triangulate(points)
      assert.is_nil(tris)
      assert.are.equal("edges cross", message)
      assert.is_nil(convexParts(points))
    end)

    it("returns nil and a message for a hole outside, far from the origin too", function()
      for _, offset in ipairs({ 0, 1e12 + 0.375 }) do
        local outline = shapes.translate({ 0, 0, 10, 0, 10, 10, 0, 10 }, offset, offset)
        local hole = shapes.translate({ 20, 0, 30, 0, 30, 10 }, offset, offset)
        local tris, message = triangulate(outline, { hole })
        assert.is_nil(tris)
        assert.truthy(message:find("outside"))
      end
    end)
  end)
end)
