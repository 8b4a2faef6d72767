-- polygonTriangulate and polygonConvexParts: hand-computed cases. Every result is also held to
-- the exact oracle (oracle.checkPieces: input vertices bit for bit, the winding of points,
-- areas adding up exactly, no overlaps), which shares no code with polygon.lua.

local polygon = require "polygon"
local oracle = require "oracle"
local shapes = require "shapes"

local triangulate, convexParts = polygon.polygonTriangulate, polygon.polygonConvexParts

local SQUARE = { 0, 0, 10, 0, 10, 10, 0, 10 }
local L = { 0, 0, 20, 0, 20, 10, 10, 10, 10, 20, 0, 20 }
local U = { 0, 0, 50, 0, 50, 200, 250, 200, 250, 0, 300, 0, 300, 250, 0, 250 }
local PINCHED = { 0, 0, 10, 0, 10, 10, 20, 10, 20, 20, 10, 20, 10, 10, 0, 10 }
local FRAME, WINDOW = { 0, 0, 30, 0, 30, 30, 0, 30 }, { 10, 10, 20, 10, 20, 20, 10, 20 }

-- The sum of the pieces' areas, as doubles (exact for these small integers).
local function totalArea(pieces)
  local sum = 0
  for _, piece in ipairs(pieces) do
    sum = sum + polygon.polygonArea(piece)
  end
  return sum
end

local function assertPieces(points, holes, pieces, convex)
  local ok, why = oracle.checkPieces(points, holes, pieces, convex)
  assert.is_true(ok, why)
end

describe("polygonTriangulate", function()
  describe("when given simple polygons", function()
    it("splits a square into two triangles of area 50", function()
      local tris = triangulate(SQUARE)
      assert.are.equal(2, #tris)
      for _, t in ipairs(tris) do
        assert.are.equal(6, #t)
        assert.are.equal(50, polygon.polygonArea(t))   -- 10 * 10 / 2
      end
      assertPieces(SQUARE, nil, tris)
    end)

    it("splits an L of area 300 into four triangles", function()
      -- 20 * 10 + 10 * 10 = 300; 6 vertices give 6 - 2 = 4 triangles
      local tris = triangulate(L)
      assert.are.equal(4, #tris)
      assert.are.equal(300, totalArea(tris))
      assertPieces(L, nil, tris)
    end)

    it("splits the U floor of area 35000 into six triangles", function()
      -- 300 * 250 - 200 * 200 = 35000
      local tris = triangulate(U)
      assert.are.equal(6, #tris)
      assert.are.equal(35000, totalArea(tris))
      assertPieces(U, nil, tris)
    end)

    it("keeps the winding of points, either way round", function()
      for _, points in ipairs({ L, shapes.reverse(L), U, shapes.reverse(U) }) do
        local winding = polygon.polygonWindingOrder(points)
        for _, t in ipairs(triangulate(points)) do
          assert.are.equal(winding, oracle.winding(t))
        end
      end
    end)

    it("copies the vertices bit for bit", function()
      local points = { 0.1, 0.2, 5.5, 1e-300, 6 + 1 / 3, 5.5, -0.0, 3 }
      for _, t in ipairs(triangulate(points)) do
        for i = 1, 5, 2 do
          local found = false
          for j = 1, #points - 1, 2 do
            if t[i] == points[j] and t[i + 1] == points[j + 1] then found = true end
          end
          assert.is_true(found)
        end
      end
      assertPieces(points, nil, triangulate(points))
    end)

    it("leaves out vertices in line, making no zero-area triangle", function()
      -- a 3 x 1 rectangle with a vertex at every unit: area 3, two triangles suffice
      local points = { 0, 0, 1, 0, 2, 0, 3, 0, 3, 1, 2, 1, 1, 1, 0, 1 }
      local tris = triangulate(points)
      for _, t in ipairs(tris) do
        assert.are_not.equal(0, polygon.polygonArea(t))
      end
      assert.are.equal(3, totalArea(tris))
      assertPieces(points, nil, tris)
    end)

    it("ignores repeated vertices", function()
      local points = { 0, 0, 0, 0, 10, 0, 10, 10, 10, 10, 10, 10, 0, 10, 0, 0 }
      local tris = triangulate(points)
      assert.are.equal(2, #tris)
      assertPieces(points, nil, tris)
    end)
  end)

  describe("when the outline touches itself at a vertex", function()
    it("splits two tiles meeting at a corner into two squares' triangles", function()
      local tris = triangulate(PINCHED)
      assert.are.equal(4, #tris)
      assert.are.equal(200, totalArea(tris))
      assertPieces(PINCHED, nil, tris)
    end)
  end)

  describe("when given holes", function()
    it("covers a frame of area 800 (900 - 100) with eight triangles", function()
      -- 4 + 4 vertices and one hole: 4 + 4 + 2 * 1 - 2 = 8 triangles
      local tris = triangulate(FRAME, { WINDOW })
      assert.are.equal(8, #tris)
      assert.are.equal(800, totalArea(tris))
      assertPieces(FRAME, { WINDOW }, tris)
    end)

    it("takes a hole of either winding", function()
      local tris = triangulate(FRAME, { shapes.reverse(WINDOW) })
      assert.are.equal(800, totalArea(tris))
      assertPieces(FRAME, { shapes.reverse(WINDOW) }, tris)
    end)

    it("takes a hole touching the outline at a vertex", function()
      -- the triangle (0,0) (10,10) (20,10) has area |10 * 10 - 10 * 20| / 2 = 50
      local hole = { 0, 0, 10, 10, 20, 10 }
      local tris = triangulate(FRAME, { hole })
      assert.are.equal(850, totalArea(tris))
      assertPieces(FRAME, { hole }, tris)
    end)

    it("takes two holes touching each other at a vertex", function()
      local holes = { { 5, 5, 15, 5, 15, 15, 5, 15 }, { 15, 15, 25, 15, 25, 25, 15, 25 } }
      local tris = triangulate(FRAME, holes)
      assert.are.equal(700, totalArea(tris))
      assertPieces(FRAME, holes, tris)
    end)
  end)

  describe("when the input is no polygon it can triangulate", function()
    it("returns nil and a message for fewer than 3 points", function()
      local tris, message = triangulate({ 0, 0, 1, 1 })
      assert.is_nil(tris)
      assert.are.equal("string", type(message))
    end)

    it("returns nil and a message for zero area", function()
      assert.is_nil(triangulate({ 0, 0, 1, 1, 2, 2, 3, 3 }))
      assert.is_nil(triangulate({ 5, 5, 5, 5, 5, 5 }))
    end)

    it("returns nil and a message for a bow-tie", function()
      -- lobes of areas 50 and 200 wound against each other
      local tris, message = triangulate({ 0, 0, 10, 10, 10, 0, 0, 20, -10, 20, -10, 10 })
      assert.is_nil(tris)
      assert.are.equal("edges cross", message)
    end)

    it("returns nil and a message for slits from one point visited out of their turn", function()
      -- a square with a slit in from the west to (50, 50), then slits north, east, north-east
      -- and south, each out and back: five pairs of edges along one another at (50, 50), each
      -- pair in either order. Clockwise (y up) around the point the arms lie W, N, NE, E, S;
      -- the visit from N to E holds NE between its ends and the one from NE to S does not, so
      -- the two cross there in every order (four pairs were the most tested before)
      local points = { 0,0, 100,0, 100,100, 0,100, 0,50, 50,50, 50,80, 50,50, 80,50, 50,50,
        70,70, 50,50, 50,20, 50,50, 0,50 }
      local tris, message = triangulate(points)
      assert.is_nil(tris)
      assert.are.equal("edges cross", message)
      assert.are.same({ nil, "edges cross" }, { convexParts(points) })
      -- visited in their turn, N, NE, E, S, they nest: the square's 2 triangles
      local inTurn = { 0,0, 100,0, 100,100, 0,100, 0,50, 50,50, 50,80, 50,50, 70,70, 50,50,
        80,50, 50,50, 50,20, 50,50, 0,50 }
      assertPieces(inTurn, {}, assert(triangulate(inTurn)))
    end)

    it("returns nil and a message for a hole outside", function()
      local tris, message = triangulate(FRAME, { { 40, 10, 50, 10, 50, 20 } })
      assert.is_nil(tris)
      assert.truthy(message:find("outside"))
    end)

    it("returns nil and a message for a hole crossing the outline", function()
      local tris, message = triangulate(FRAME, { { 20, 10, 40, 10, 40, 20 } })
      assert.is_nil(tris)
      assert.are.equal("holes[1] crosses the outline", message)
    end)

    it("returns nil and a message for a hole inside another hole", function()
      local tris, message = triangulate(FRAME, { WINDOW, { 12, 12, 18, 12, 18, 18 } })
      assert.is_nil(tris)
      assert.truthy(message:find("inside"))
    end)
  end)

  -- A hole of zero area takes nothing away and is skipped, unless it crosses itself: where two
  -- edges cross, or where it touches itself and passes through in a crossing order. Only the
  -- first was looked for, and the others were skipped as enclosing nothing.
  describe("when a hole has zero area", function()
    local BIG = { 0, 0, 100, 0, 100, 100, 0, 100 }

    local function refused(hole)
      local tris, message = triangulate(BIG, { hole })
      local parts, partsMessage = convexParts(BIG, { hole })
      assert.is_nil(tris)
      assert.is_nil(parts)
      assert.are.equal("holes[1] crosses itself", message)
      assert.are.equal(message, partsMessage)
    end

    it("skips one that does not cross itself: slits in turn around a point, a sliver", function()
      -- slits east, north, west, south of (50, 50), in that turn: the square's 2 triangles
      local tris = triangulate(BIG, { { 50,50, 60,50, 50,50, 50,60, 50,50, 40,50, 50,50, 50,40 } })
      assert.are.equal(2, #tris)
      assertPieces(BIG, {}, tris)
      assert.are.equal(2, #triangulate(BIG, { { 20,20, 40,40, 30,30 } }))   -- folded flat
    end)

    it("refuses slits visited out of their turn around the point", function()
      -- east, west, north, south: the visit from east to west and the one from north to south
      -- cross at (50, 50)
      refused({ 50,50, 60,50, 50,50, 40,50, 50,50, 50,60, 50,50, 50,40 })
    end)

    it("refuses five slits visited out of their turn", function()
      -- as the outline's slits above, with a fifth, west: N, E, NE, S, W; the visits from N to
      -- E and from NE to S cross at (50, 50)
      refused({ 50,50, 50,80, 50,50, 80,50, 50,50, 70,70, 50,50, 50,20, 50,50, 20,50 })
    end)

    it("refuses a figure eight whose loops cancel", function()
      -- loops (50,50) (60,40) (60,60) and (50,50) (40,40) (40,60): twice their areas +200 and
      -- -200 (shoelace: -1000 + 1200 + 0 and 0 + 800 - 1000); at (50, 50) the edges in from
      -- (60,60) at 45 degrees and from (40,60) at 135 come one after the other
      refused({ 50,50, 60,40, 60,60, 50,50, 40,40, 40,60 })
    end)

    it("refuses one whose vertex lies inside its own edge, its loops wound against each other", function()
      -- twice the area: -900 - 106 + 404 - 248 + 850 = 0; (64,52) lies on the edge from
      -- (50,50) to (71,53) (both steps of slope 1/7), and the loops on either side of it have
      -- twice the areas +2 and -2
      refused({ 50,50, 71,53, 73,53, 64,52, 70,53 })
    end)
  end)

  describe("when given bad arguments", function()
    it("raises errors naming the function and argument", function()
      assert.has_error(function() triangulate("x") end,
        "polygonTriangulate: points must be a table, got string")
      assert.has_error(function() triangulate({ 0, 0, 1 }) end,
        "polygonTriangulate: points must hold an even number of coordinates, got 3")
      assert.has_error(function() triangulate(SQUARE, 5) end,
        "polygonTriangulate: holes must be a table, got number")
      assert.has_error(function() triangulate({ 0, 0, 1, 0, 0, "a" }) end,
        "polygonTriangulate: points[6] must be a finite number, got a")
      assert.has_error(function() triangulate(SQUARE, { { 1, 1, 2, 1, 0 / 0, 2 } }) end)
    end)

    it("does not change its arguments", function()
      local points, holes = shapes.deepCopy(FRAME), { shapes.deepCopy(WINDOW) }
      triangulate(points, holes)
      convexParts(points, holes)
      assert.are.same(FRAME, points)
      assert.are.same({ WINDOW }, holes)
    end)
  end)
end)

describe("polygonConvexParts", function()
  it("gives a convex polygon back as one part", function()
    local parts = convexParts(SQUARE)
    assert.are.equal(1, #parts)
    assert.are.equal(8, #parts[1])
    assertPieces(SQUARE, nil, parts, true)
  end)

  it("splits an L into two parts (one reflex vertex: at least ceil(1 / 2) + 1 = 2)", function()
    local parts = convexParts(L)
    assert.are.equal(2, #parts)
    assertPieces(L, nil, parts, true)
  end)

  it("splits the U floor into three parts: its two walls and the floor between", function()
    local parts = convexParts(U)
    assert.are.equal(3, #parts)
    for _, part in ipairs(parts) do
      assert.are.equal("convex", polygon.polygonType(part))
    end
    assertPieces(U, nil, parts, true)
  end)

  it("splits two tiles meeting at a corner into the two tiles", function()
    local parts = convexParts(PINCHED)
    assert.are.equal(2, #parts)
    assert.are.equal(100, polygon.polygonArea(parts[1]))
    assert.are.equal(100, polygon.polygonArea(parts[2]))
    assertPieces(PINCHED, nil, parts, true)
  end)

  it("splits a frame into four parts", function()
    local parts = convexParts(FRAME, { WINDOW })
    assert.are.equal(4, #parts)
    assertPieces(FRAME, { WINDOW }, parts, true)
  end)

  it("keeps the winding of points", function()
    local parts = convexParts(shapes.reverse(U))
    for _, part in ipairs(parts) do
      assert.are.equal("ccw", oracle.winding(part))
    end
  end)

  it("returns nil and a message where polygonTriangulate does", function()
    local parts, message = convexParts({ 0, 0, 10, 10, 10, 0, 0, 20, -10, 20, -10, 10 })
    assert.is_nil(parts)
    assert.are.equal("edges cross", message)
    assert.has_error(function() convexParts(true) end,
      "polygonConvexParts: points must be a table, got boolean")
  end)
end)
