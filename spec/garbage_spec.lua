-- Per-call functions allocate nothing: with the collector stopped, 10000 calls of each (over
-- inputs that take every branch: collide, touch, apart, contained, degenerate) must grow the
-- heap by less than 1 KB. The loop itself allocates nothing: it only reads prepared tables.
local polygon = require "polygon"
local garbage = require "garbage"
local samples = require "samples"

local N = 10000
local LIMIT_KB = 1

local SQUARE, SQUARE_CCW, L, OVERLAP = samples.SQUARE, samples.SQUARE_CCW, samples.L, samples.OVERLAP
local TOUCH, APART, INSIDE, REPEATED = samples.TOUCH, samples.APART, samples.INSIDE, samples.REPEATED
local TRIANGLE, SEGMENT, TWO = samples.TRIANGLE, samples.SEGMENT, samples.TWO

local POLYS = { SQUARE, SQUARE_CCW, L, OVERLAP, TOUCH, APART, INSIDE, REPEATED, TRIANGLE, SEGMENT, TWO }
local PAIRS = {
  { SQUARE, OVERLAP }, { OVERLAP, SQUARE }, { SQUARE_CCW, OVERLAP }, { SQUARE, TOUCH },
  { SQUARE, APART }, { SQUARE, INSIDE }, { INSIDE, SQUARE }, { REPEATED, OVERLAP },
  { SQUARE, TRIANGLE }, { TRIANGLE, SQUARE }, { SQUARE, SQUARE },
}
-- the collision functions refuse concave polygons and fewer than 3 points (spec/refusals_spec.lua)
local CONVEX = { SQUARE, SQUARE_CCW, OVERLAP, TOUCH, APART, INSIDE, REPEATED, TRIANGLE }
local POINTS = { { 5, 5 }, { 10, 5 }, { 0, 5 }, { 15, 15 }, { 5, 10 }, { -1, -1 } }
local CIRCLES = {
  { 12, 5, 3 }, { 13, 5, 3 }, { 13, 14, 6 }, { 13, 14, 4.9 }, { 7, 4, 1 }, { 10, 10, 2 },
  { 0, 0, 3 }, { 6, 5, 100 },
}

-- segments: across, along edges and seams, through corners, from inside, from the boundary,
-- of no length
local RAYS = {
  { -5, 5, 25, 5 }, { 25, 7, -5, 3 }, { -5, 0, 25, 0 }, { -5, -5, 25, 25 }, { 5, 5, 30, 40 },
  { 0, 5, 20, 5 }, { 10, -5, 10, 25 }, { 5, 5, 5, 5 }, { 12, 14, 12, 14 }, { 40, 40, 50, 50 },
  { 10, 10, 0, 0 }, { 7, -3, 13, 17 },
}
-- moves for the casts: across, along axes (slides), diagonal, long (through), none
local MOVES = { { -30, 0 }, { 30, 0 }, { 0, 25 }, { -17, -13 }, { 400, 3 }, { 0, 0 }, { 11, -40 } }
-- lists of parts: two tiles side by side, an L of three tiles, a convex polygon as one part
local LISTS = {
  { { 0, 0, 10, 0, 10, 10, 0, 10 }, { 10, 0, 20, 0, 20, 10, 10, 10 } },
  { { 0, 0, 10, 0, 10, 10, 0, 10 }, { 10, 0, 20, 0, 20, 10, 10, 10 }, { 0, 10, 10, 10, 10, 20, 0, 20 } },
  { TRIANGLE },
}

-- the heap growth in KB over N calls of body(i): the least over several runs after warm-up runs
-- (spec/support/garbage.lua). LuaJIT's compiled traces live on the heap and may still be
-- recorded, or flushed and recorded again, during any one run; a body that allocates per call
-- grows the heap in every run.
local function growth(body)
  return garbage.growth(body, N)
end

local CASES = {
  polygonContains = function(i)
    local q = POINTS[i % #POINTS + 1]
    polygon.polygonContains(POLYS[i % #POLYS + 1], q[1], q[2])
  end,
  ["Polygon:contains"] = (function()
    local objects = {}
    for _, p in ipairs(POLYS) do
      if #p >= 6 then objects[#objects + 1] = polygon.Polygon.new(p) end
    end
    return function(i)
      local q = POINTS[i % #POINTS + 1]
      objects[i % #objects + 1]:contains(q[1], q[2])
    end
  end)(),
  projectPolygon = function(i) polygon.projectPolygon(POLYS[i % #POLYS + 1], 1, 2, 3, -4) end,
  projectCircle = function(i) polygon.projectCircle(i, 2, 3, 4, 5, 0.6, 0.8) end,
  polygonCircleCollideV = function(i)
    local c = CIRCLES[i % #CIRCLES + 1]
    polygon.polygonCircleCollideV(CONVEX[i % #CONVEX + 1], c[1], c[2], c[3])
  end,
  validate = function(i) polygon.validate(POLYS[i % 4 + 1]) end, -- valid inputs only
  -- rays that hit, miss, graze, start inside and on the boundary, over every convex polygon
  polygonRayCast = function(i)
    local r = RAYS[i % #RAYS + 1]
    polygon.polygonRayCast(CONVEX[i % #CONVEX + 1], r[1], r[2], r[3], r[4])
  end,
  -- and over lists of parts: seams crossed and followed, corners where parts meet
  -- flat polygons of any shape: the L, a bow tie, a comb whose teeth the rows y = 0, 5, 10 run
  -- along (the exact path: vertices on the ray's line, more than two crossings)
  ["polygonRayCast (any flat polygon)"] = (function()
    local shapes = { L, { 0, 0, 10, 10, 10, 0, 0, 10 },
      { 0, 0, 20, 0, 20, 10, 15, 10, 15, 5, 10, 5, 10, 10, 5, 10, 5, 5, 0, 5 } }
    return function(i)
      local r = RAYS[i % #RAYS + 1]
      polygon.polygonRayCast(shapes[i % #shapes + 1], r[1], r[2], r[3], r[4])
    end
  end)(),
  ["polygonRayCast (parts)"] = function(i)
    local r = RAYS[i % #RAYS + 1]
    polygon.polygonRayCast(LISTS[i % #LISTS + 1], r[1], r[2], r[3], r[4])
  end,
  -- nearest points of convex and concave polygons, from outside, inside, on the boundary, at
  -- ties between edges
  polygonClosestPoint = function(i)
    local q = POINTS[i % #POINTS + 1]
    polygon.polygonClosestPoint(POLYS[i % #POLYS + 1], q[1], q[2])
  end,
  circleRayCast = function(i)
    local c, r = CIRCLES[i % #CIRCLES + 1], RAYS[i % #RAYS + 1]
    polygon.circleRayCast(c[1], c[2], c[3], r[1], r[2], r[3], r[4])
  end,
  -- casts that hit (the fraction stepped back), miss, slide along a face, start overlapped (the
  -- push), of no length, over every convex pair
  polygonsCast = function(i)
    local pair, m = PAIRS[i % #PAIRS + 1], MOVES[i % #MOVES + 1]
    polygon.polygonsCast(pair[1], pair[2], m[1], m[2])
  end,
  ["polygonsCast (parts)"] = function(i)
    local m = MOVES[i % #MOVES + 1]
    polygon.polygonsCast(LISTS[i % #LISTS + 1], CONVEX[i % #CONVEX + 1], m[1], m[2])
  end,
  polygonCircleCast = function(i)
    local c, m = CIRCLES[i % #CIRCLES + 1], MOVES[i % #MOVES + 1]
    polygon.polygonCircleCast(CONVEX[i % #CONVEX + 1], c[1], c[2], c[3], m[1], m[2])
  end,
  ["polygonCircleCast (parts)"] = function(i)
    local c, m = CIRCLES[i % #CIRCLES + 1], MOVES[i % #MOVES + 1]
    polygon.polygonCircleCast(LISTS[i % #LISTS + 1], c[1], c[2], c[3], m[1], m[2])
  end,
}
-- the functions of one polygon, over every polygon in turn
local ONE_POLYGON = {
  "polygonWindingOrder", "polygonArea", "polygonAreaAccurate", "polygonType", "polygonCenter",
  "polygonCentroid",
}
for _, name in ipairs(ONE_POLYGON) do
  local fn = polygon[name]
  CASES[name] = function(i) fn(POLYS[i % #POLYS + 1]) end
end
-- the functions of two polygons, over every pair in turn
local TWO_POLYGONS = { "polygonCollidesWith", "polygonsCollide", "polygonCollidesWithV", "polygonsCollideV" }
for _, name in ipairs(TWO_POLYGONS) do
  local fn = polygon[name]
  CASES[name] = function(i)
    local pair = PAIRS[i % #PAIRS + 1]
    fn(pair[1], pair[2])
  end
end

local NAMES = {}
for name in pairs(CASES) do NAMES[#NAMES + 1] = name end
table.sort(NAMES)

describe("per-call functions", function()
  for _, name in ipairs(NAMES) do
    it(name .. " allocates less than 1 KB over 10000 calls", function()
      local kb = growth(CASES[name])
      assert.is_true(kb < LIMIT_KB, ("%s allocated %.3f KB over %d calls"):format(name, kb, N))
    end)
  end

  it("the measurement sees a loop that does allocate (a table per call)", function()
    local sink
    local kb = growth(function(i) sink = { i } end)
    assert.is_true(sink[1] == N)
    assert.is_true(kb >= LIMIT_KB)
  end)
end)
