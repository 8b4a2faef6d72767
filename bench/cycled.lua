-- The cost per vertex of one input triangulated again and again (as bench/holes.lua's warm
-- column times it) against that of different inputs of its kind and size taken in turn (as a
-- level load meets its outlines): polygonTriangulate on LuaJIT, and earcut in node likewise.
-- Noisy circles of 30 to 10,000 vertices and tile maps of 8 to 120 tiles a side; at the sizes
-- bench/holes.lua has, the first input is its own. The processor learns the branches of a
-- call repeated, up to some thousands of vertices' worth, so a small input repeated runs faster
-- per vertex than inputs taken in turn, and so does a lap of a few small inputs: each case
-- takes as many inputs as hold LAP vertices (16 at least). Past that size the two ways agree
-- (bench/NOTES.md, session 28).
-- From the repository root: `luajit bench/cycled.lua` (node and `npm install --prefix
-- /tmp/earcut earcut` for the earcut columns, as bench/holes.lua). One case in this process:
-- `lua5.4 bench/cycled.lua run noisy-1000`.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local polygon = require "polygon"
local prng = require "prng"
local shapes = require "shapes"
local tiles = require "tiles"
local shell = require "bench.shell"

local LAP = 50000      -- vertices in a lap of a case's inputs, at least (16 noisy circles of 100
                       -- vertices in turn ran 0.31 us a vertex, 64 of them 0.48, 256 0.53)
local FEWEST = 16      -- inputs of a case, at least
local ROUNDS = 4       -- timed rounds of each way, the two ways alternating
local ROUND = 0.2      -- seconds a round runs, at least (whole laps of the inputs)
local WARM = 0.5       -- seconds of laps before the rounds (LuaJIT compiles)
-- noisy-30, noisy-300 and tiles-20 besides bench/holes.lua's sizes: the small sizes, where the
-- ratio to earcut passes 3 (bench/NOTES.md, session 29)
local CASES = { "noisy-30", "noisy-100", "noisy-300", "noisy-1000", "noisy-10000",
  "tiles-8", "tiles-20", "tiles-40", "tiles-120" }

local function vertexCount(points, holes)
  local n = #points / 2
  for _, hole in ipairs(holes) do n = n + #hole / 2 end
  return n
end

-- The inputs of a case: lists of points and of holes, and their count; input 1 bench/holes.lua's.
local function inputs(case)
  local kind, size = case:match("^(%a+)%-(%d+)$")
  size = tonumber(size)
  local points, holes, count, vertices = {}, {}, 0, 0
  while count < FEWEST or vertices < LAP do
    count = count + 1
    local seed = count == 1 and size or size * 100000 + count
    if kind == "noisy" then
      points[count], holes[count] = shapes.noisyCircle(size, prng.new(seed)), {}
    else
      points[count], holes[count] = tiles.level(prng.new(seed), size)
    end
    vertices = vertices + vertexCount(points[count], holes[count])
  end
  return points, holes, count
end

local mode, name = arg[1], arg[2]
if mode == "run" then
  -- this process: ns a vertex, the best round of each way, and the mean vertex count
  local points, holes, count = inputs(name)
  local counts, total = {}, 0
  for i = 1, count do counts[i] = vertexCount(points[i], holes[i]); total = total + counts[i] end
  local triangulate = polygon.polygonTriangulate
  local function lap(repeated)   -- count calls; the vertices they took
    local vertices = 0
    for i = 1, count do
      local k = repeated and 1 or i
      assert(triangulate(points[k], holes[k]), "refused")
      vertices = vertices + counts[k]
    end
    return vertices
  end
  local start = os.clock()
  repeat lap(false) until os.clock() - start > WARM
  local best = { [true] = math.huge, [false] = math.huge }
  for _ = 1, ROUNDS do
    for _, repeated in ipairs({ true, false }) do
      local vertices, began = 0, os.clock()
      repeat vertices = vertices + lap(repeated) until os.clock() - began > ROUND
      best[repeated] = math.min(best[repeated], (os.clock() - began) / vertices * 1e9)
    end
  end
  print(name, best[true], best[false], total / count, count)
  return
elseif mode == "export" then
  -- earcut's input for each case: a JSON array of its inputs, each {vertices, holes} (the
  -- holes as the indices where they start)
  for _, case in ipairs(CASES) do
    local points, holes, count = inputs(case)
    local items = {}
    for i = 1, count do
      local flat, starts = {}, {}
      for j, v in ipairs(points[i]) do flat[j] = ("%.17g"):format(v) end
      for _, hole in ipairs(holes[i]) do
        starts[#starts + 1] = #flat / 2
        for _, v in ipairs(hole) do flat[#flat + 1] = ("%.17g"):format(v) end
      end
      items[i] = ('{"vertices":[%s],"holes":[%s]}'):format(table.concat(flat, ","), table.concat(starts, ","))
    end
    local f = assert(io.open(("%s/%s.json"):format(name, case), "w"))
    f:write("[", table.concat(items, ",\n"), "]\n")
    f:close()
  end
  return
end

local fields = shell.words
local self = arg[-1] or "lua"
local earcutFile = shell.earcut()
local withEarcut = earcutFile ~= nil
local dir
if withEarcut then
  dir = shell.tempDir()
  assert(shell.ok(("%s bench/cycled.lua export %s"):format(self, dir)))
end
print(("polygonTriangulate on %s and earcut: ns a vertex, one input repeated against inputs in turn")
  :format(self))
print(("%-12s %7s %6s | %9s %9s %6s | %9s %9s %6s | %s"):format("input", "n", "inputs", "repeated",
  "in turn", "slower", "earcut", "in turn", "slower", "ratio in turn"))
local perVertex, failed = {}, false
for _, case in ipairs(CASES) do
  local ours = fields(("%s bench/cycled.lua run %s"):format(self, case))
  if ours[1] ~= case then   -- a refusal or an error: no time
    io.stderr:write(("bench/cycled.lua: %s on %s: %s\n"):format(case, self, table.concat(ours, " ")))
    failed = true
  end
  local theirs = withEarcut and fields(("EARCUT=%s node bench/earcut-cycled.js %s/%s.json"):format(
    earcutFile, dir, case)) or {}
  local a, b, n, count = tonumber(ours[2]), tonumber(ours[3]), tonumber(ours[4]), tonumber(ours[5])
  local c, d = tonumber(theirs[2]), tonumber(theirs[3])
  local function ns(v) return v and ("%.0f"):format(v) or "-" end
  local function ratio(x, y) return x and y and ("%.2f"):format(x / y) or "-" end
  print(("%-12s %7.0f %6d | %9s %9s %6s | %9s %9s %6s | %s"):format(case, n or 0, count or 0,
    ns(a), ns(b), ratio(b, a), ns(c), ns(d), ratio(d, c), ratio(b, d)))
  perVertex[case] = { a, b }
end
print()
print(("cost per vertex, the largest input's over the smallest's (%s: repeated, in turn)"):format(self))
for _, pair in ipairs({ { "noisy-100", "noisy-10000" }, { "tiles-8", "tiles-120" } }) do
  local small, large = perVertex[pair[1]], perVertex[pair[2]]
  local function growth(w) return small[w] and large[w] and ("%.2f"):format(large[w] / small[w]) or "-" end
  print(("%-26s %6s %6s"):format(pair[2] .. " / " .. pair[1], growth(1), growth(2)))
end
if dir then shell.ok("rm -rf " .. dir) end
if failed then os.exit(1) end
