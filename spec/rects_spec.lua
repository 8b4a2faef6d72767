-- polygonConvexParts on outlines whose edges, and their holes' edges, all run along the axes
-- (issue 28): axis-parallel rectangles, so that pushes against tile levels are exact. Checked
-- by hand on the README's shapes, and on random tile maps against the exact oracle (cover, no
-- overlap, every corner's coordinates input ones) and against the fewest rectangles possible
-- (spec/support/rectmin.lua).

local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local tiles = require "tiles"
local rectmin = require "rectmin"

local convexParts = polygon.polygonConvexParts

-- Whether a part is an axis-parallel rectangle: 4 corners, each edge along an axis.
local function isRectangle(part)
  if #part ~= 8 then return false end
  for i = 1, 7, 2 do
    local j = (i + 1) % 8 + 1
    if part[i] ~= part[j] and part[i + 1] ~= part[j + 1] then return false end
  end
  return true
end

-- The parts sorted and printed, so that a list compares whatever its order.
local function sorted(parts)
  local out = {}
  for i, p in ipairs(parts) do
    local x0, y0, x1, y1 = math.huge, math.huge, -math.huge, -math.huge
    for k = 1, #p - 1, 2 do
      x0, x1 = math.min(x0, p[k]), math.max(x1, p[k])
      y0, y1 = math.min(y0, p[k + 1]), math.max(y1, p[k + 1])
    end
    out[i] = ("%g %g %g %g"):format(x0, y0, x1, y1)
  end
  table.sort(out)
  return out
end

local U = { 0,0, 50,0, 50,200, 250,200, 250,0, 300,0, 300,250, 0,250 }   -- the README's floor
local FRAME = { -50,-50, 450,-50, 450,350, -50,350 }                     -- and its room
local ROOM = { 0,0, 400,0, 400,200, 200,200, 200,300, 0,300 }

describe("polygonConvexParts on outlines along the axes", function()
  describe("when given the README's shapes", function()
    it("splits the U floor into its two arms and the floor under them", function()
      -- the band y 0..200 holds x 0..50 and 250..300 (the arms); y 200..250 all of 0..300
      local parts = assert(convexParts(U))
      assert.are.same({ "0 0 50 200", "0 200 300 250", "250 0 300 200" }, sorted(parts))
    end)

    it("splits the frame around the L-shaped room into 5 rectangles", function()
      -- bands: -50..0 the top wall (x -50..450); 0..200 the left wall (-50..0) and the right one
      -- (400..450); 200..300 the left wall and the corner block (200..450), left wall running on
      -- from 0 to 300; 300..350 the bottom wall
      local parts = assert(convexParts(FRAME, { ROOM }))
      assert.are.same({ "-50 -50 450 0", "-50 0 0 300", "-50 300 450 350", "200 200 450 300",
        "400 0 450 200" }, sorted(parts))
      assert.are.equal(5, (rectmin.fewest(FRAME, { ROOM })))   -- the fewest possible
    end)

    it("winds every rectangle like the outline, either way", function()
      for _, outline in ipairs({ U, { 0,250, 300,250, 300,0, 250,0, 250,200, 50,200, 50,0, 0,0 } }) do
        local want = oracle.winding(outline)
        for _, part in ipairs(assert(convexParts(outline))) do
          assert.are.equal(want, oracle.winding(part))
        end
      end
    end)
  end)

  -- (These cases follow the rects helper's spec, branch `rects`, through polygonConvexParts.)
  describe("when given the hard cases of tile outlines", function()
    local function covers(points, holes, want)
      local parts = assert(convexParts(points, holes))
      assert.is_true(oracle.checkCover(points, holes, parts, true))
      for _, part in ipairs(parts) do assert.is_true(isRectangle(part)) end
      assert.are.same(want, sorted(parts))
    end

    it("splits a plus into its top arm, the bar across and its bottom arm", function()
      -- 100 + 300 + 100 = 500, 5 tiles of 10 x 10; the fewest is 3
      covers({ 10,0, 20,0, 20,10, 30,10, 30,20, 20,20, 20,30, 10,30, 10,20, 0,20, 0,10, 10,10 }, nil,
        { "0 10 30 20", "10 0 20 10", "10 20 20 30" })
    end)

    it("splits two tiles meeting at a corner into the two tiles", function()
      covers({ 0,0, 10,0, 10,10, 20,10, 20,20, 10,20, 10,10, 0,10 }, nil, { "0 0 10 10", "10 10 20 20" })
    end)

    it("reads repeated points and points in line as the plain outline", function()
      covers({ 0,0, 25,0, 50,0, 50,0, 50,100, 50,200, 250,200, 250,0, 250,0, 300,0, 300,250, 150,250,
        0,250, 0,125, 0,0 }, nil, { "0 0 50 200", "0 200 300 250", "250 0 300 200" })
    end)

    it("covers an outline that runs along itself: a slit up from the bottom, one in from the side", function()
      -- the slit x = 5, y 5..10 splits the lower band in two: 50 + 25 + 25 = 100; a slit along y
      -- has no vertical edge inside: the square
      covers({ 0,0, 10,0, 10,10, 5,10, 5,5, 5,10, 0,10 }, nil, { "0 0 10 5", "0 5 5 10", "5 5 10 10" })
      covers({ 0,0, 10,0, 10,10, 0,10, 0,5, 5,5, 0,5 }, nil, { "0 0 10 10" })
    end)

    it("splits a tile map whose two holes touch at a corner into 6", function()
      -- 4 x 4 tiles of 10 without (2, 2) and (3, 3), touching at (20, 20). Bands: y 0..10 [0, 40];
      -- 10..20 [0, 10], [20, 40]; 20..30 [0, 20], [30, 40]; 30..40 [0, 40]: none alike above
      -- another, 6 rectangles, 400 + 100 + 200 + 200 + 100 + 400 = 1400 = 1600 - 2 x 100
      covers({ 0,0, 40,0, 40,40, 0,40 }, { { 10,10, 20,10, 20,20, 10,20 }, { 20,20, 30,20, 30,30, 20,30 } },
        { "0 0 40 10", "0 10 10 20", "0 20 20 30", "0 30 40 40", "20 10 40 20", "30 20 40 30" })
    end)

    it("splits a tile map whose hole touches the outline's notch at a corner into 4", function()
      -- 3 x 3 tiles without the top left one (the notch) and the middle one (the hole), touching
      -- at (10, 10): 200 + 100 + 100 + 300 = 700 = 900 - 2 x 100
      covers({ 10,0, 30,0, 30,30, 0,30, 0,10, 10,10 }, { { 10,10, 20,10, 20,20, 10,20 } },
        { "0 10 10 20", "0 20 30 30", "10 0 30 10", "20 10 30 20" })
    end)

    it("splits a frame around a checkerboard of 18 holes, each touching others at its corners", function()
      -- 8 x 8 tiles, the border filled, inside it the tiles with r + c odd empty: the top and
      -- bottom rows whole, each row between in 4 runs, none alike above another: 1 + 6 x 4 + 1
      local set = { cols = 8, rows = 8 }
      for r = 1, 8 do
        set[r] = {}
        for c = 1, 8 do set[r][c] = r == 1 or r == 8 or c == 1 or c == 8 or (r + c) % 2 == 0 end
      end
      local shape = tiles.shapes(set, 16, 1e9, -1e9)[1]
      assert.are.equal(18, #shape[2])
      local parts = assert(convexParts(shape[1], shape[2]))
      assert.is_true(oracle.checkCover(shape[1], shape[2], parts, true))
      assert.are.equal(26, #parts)
    end)
  end)

  describe("when a box or a ball is pushed out of the parts", function()
    -- Along an axis by the depth itself: the coordinates are integers, so every difference is
    -- exact, and the move by the depth leaves the shapes touching, which is not colliding
    it("pushes a crate sunk 8 into the U floor up by exactly 8", function()
      -- the crate's bottom at y 208, the floor's top at 200: (0, -8)
      local floor = assert(convexParts(U))
      local crate = { 100,192, 120,192, 120,208, 100,208 }
      assert.are.same({ 8, 0, -8 }, { polygon.polygonsCollideV(floor, crate) })
      assert.are.same({ 8, 0, 8 }, { polygon.polygonsCollideV({ crate }, floor) })   -- the floor moves
      local moved = { 100,184, 120,184, 120,200, 100,200 }
      for _, part in ipairs(floor) do assert.is_false(oracle.collides(part, moved, true)) end
    end)

    it("pushes a box 8 into the room's wall out by exactly 8, and a ball 5 into it by 5", function()
      -- the left wall ends at x 0: the box from -8 to 12 goes right by 8; the ball at x 0,
      -- radius 5, right by 5, touching the wall at (0, 100)
      local walls = assert(convexParts(FRAME, { ROOM }))
      assert.are.same({ 8, 8, 0 }, { polygon.polygonsCollideV(walls, { -8,100, 12,100, 12,120, -8,120 }) })
      assert.are.same({ 5, 5, 0 }, { polygon.polygonCircleCollideV(walls, 0, 100, 5) })
      for _, part in ipairs(walls) do assert.is_false(oracle.discMeetsPolygon(part, 5, 100, 5)) end
    end)

    it("keeps the margin where the depth is no exact difference, and still separates", function()
      -- at 1e9 + 0.3 the box's coordinates round: its depth is not the difference of two of them
      local off = 1e9 + 0.3
      local walls = assert(convexParts(FRAME, { ROOM }))
      local moved = {}
      for k, part in ipairs(walls) do
        moved[k] = {}
        for i = 1, 8 do moved[k][i] = part[i] + off end
      end
      local box = { -8.1 + off, 100 + off, 12 + off, 100 + off, 12 + off, 120 + off, -8.1 + off, 120 + off }
      local overlap, dx, dy = polygon.polygonsCollideV(moved, box)
      assert.is_true(overlap > 8.09 and overlap < 8.11 and dy == 0)
      local after = {}
      for i = 1, 8, 2 do after[i], after[i + 1] = box[i] + dx, box[i + 1] + dy end
      for _, part in ipairs(moved) do assert.is_false(oracle.collides(part, after, true)) end
    end)

    it("separates a ball in the room's inner corner", function()
      local walls = assert(convexParts(FRAME, { ROOM }))
      local cx, cy, r = 197, 197, 5
      local _, dx, dy = polygon.polygonCircleCollideV(walls, cx, cy, r)
      for _, part in ipairs(walls) do assert.is_false(oracle.discMeetsPolygon(part, cx + dx, cy + dy, r)) end
    end)
  end)

  describe("when given random tile maps with their enclosed gaps", function()
    it("covers each exactly with rectangles, near the fewest possible", function()
      local maps, compared, total, fewest = 0, 0, 0, 0
      for seed = 1, 300 do
        local rng = prng.new(seed)
        local offset = ({ 0, 0, 1e6 + 0.5, 1e9 })[rng:int(1, 4)]
        local set = tiles.random(rng, rng:int(2, 9), rng:int(2, 9), 0.7)
        for _, shape in ipairs(tiles.shapes(set, 10, offset, offset)) do
          local points, holes = shape[1], shape[2]
          local parts = assert(convexParts(points, holes))
          for _, part in ipairs(parts) do assert.is_true(isRectangle(part), "seed " .. seed) end
          local ok, why = oracle.checkCover(points, holes, parts, true, true)
          assert(ok, ("seed %d: %s"):format(seed, tostring(why)))
          -- the issue's bound: r + 1 + the holes' vertices
          local bound = oracle.reflexCount(points) + 1
          for _, hole in ipairs(holes) do bound = bound + #hole / 2 end
          assert.is_true(#parts <= bound, ("seed %d: %d parts, bound %d"):format(seed, #parts, bound))
          local least = rectmin.fewest(points, holes)   -- (nil with pinch points)
          if least then
            assert.is_true(#parts >= least, ("seed %d: %d parts, fewer than %d"):format(seed, #parts, least))
            compared, total, fewest = compared + 1, total + #parts, fewest + least
          end
          maps = maps + 1
        end
      end
      assert.is_true(maps > 350 and compared > 150, ("%d maps, %d compared"):format(maps, compared))
      -- the bands' rectangles against the fewest
      -- 460 parts where the fewest is 421 (9% more) when written
      assert.is_true(total <= 1.2 * fewest, ("%d parts for a least of %d"):format(total, fewest))
    end)
  end)
end)
