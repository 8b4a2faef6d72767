-- Time a call of polygonTriangulate on small outlines without holes, the shapes a game
-- triangulates most: regular stars of 8 to 128 vertices (radii 100 and 40 alternating, rounded
-- to integers), warm, microseconds a call. Run from the repository root with any Lua:
-- `luajit bench/small.lua`. To compare two trees, run it in each in turn, a few rounds
-- (bench/NOTES.md, session 25).
package.path = "./?.lua;" .. package.path
local polygon = require "polygon"

local clock = os.clock
local SIZES = { 8, 12, 24, 48, 64, 80, 96, 128 }
local WARM, TIME = 0.5, 0.5   -- seconds: the warm-up (LuaJIT compiles), then the timed rounds

local function star(n)
  local points = {}
  for i = 0, n - 1 do
    local a, r = 2 * math.pi * i / n, i % 2 == 0 and 100 or 40
    points[2 * i + 1] = math.floor(200 + r * math.cos(a))
    points[2 * i + 2] = math.floor(200 + r * math.sin(a))
  end
  return points
end

print(("%-8s %12s"):format("star", "us a call"))
for _, n in ipairs(SIZES) do
  local points = star(n)
  -- the triangles cover the star: their areas add up to its area (integers: exact sums).
  -- (Not n - 2 of them: the ear clipping drops a vertex left in line by a clip.)
  local area = 0
  for _, t in ipairs(polygon.polygonTriangulate(points)) do
    area = area + math.abs((t[3] - t[1]) * (t[6] - t[2]) - (t[4] - t[2]) * (t[5] - t[1]))
  end
  assert(area == 2 * math.abs(polygon.polygonArea(points)))
  local t = clock()
  while clock() - t < WARM do polygon.polygonTriangulate(points) end
  local calls = 0
  t = clock()
  while clock() - t < TIME do polygon.polygonTriangulate(points); calls = calls + 1 end
  print(("%-8d %12.2f"):format(n, (clock() - t) * 1e6 / calls))
end
