-- bench/instructions.lua: Lua VM instructions per call of polygon.lua and of bench/baseline.lua on
-- the benchmark's workloads, counted with a debug.sethook count hook (every instruction; C
-- functions such as math.sqrt count as one call). Load on a shared machine cannot change these
-- counts, which is why they are quoted where timings are too noisy to show a change.
-- From the repository root, on PUC Lua: `lua5.4 bench/instructions.lua [FUNCTION]` (default
-- polygonsCollideV). Pair functions (polygonsCollide(V), polygonCollidesWith(V)) run on the
-- pair workloads; one-polygon functions (polygonType, polygonArea, polygonWindingOrder,
-- polygonAreaAccurate) on the ordinary polygons, the same at 1e9 and 1,000 vertices, where
-- polygonAreaAccurate is compared with polygonArea as in the benchmark.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local W = require "bench.workloads"
local shapes = require "shapes"
local polygon = require "polygon"
local baseline = dofile("bench/baseline.lua")

local fname = arg[1] or "polygonsCollideV"
local PAIRS = { polygonsCollide = true, polygonsCollideV = true, polygonCollidesWith = true,
  polygonCollidesWithV = true }

local function count(f, A1, A2)
  for i = 1, #A1 do f(A1[i], A2 and A2[i]) end   -- a warm-up pass (caches, first-call work)
  local n = 0
  debug.sethook(function() n = n + 1 end, "", 1)
  for i = 1, #A1 do f(A1[i], A2 and A2[i]) end
  debug.sethook()
  return n / #A1
end

-- the reference: the tutorial's function, or for polygonAreaAccurate polygon.lua's polygonArea
local reference = fname == "polygonAreaAccurate" and polygon.polygonArea or baseline[fname]
local kinds
if PAIRS[fname] then
  kinds = {
    { "mixed pairs (1/3 overlap, touch, miss)", W.pairs(300, { W.pairOverlap, W.pairTouch, W.pairMiss }) },
    { "overlapping pairs", W.pairs(300, { W.pairOverlap }) },
    { "touching pairs", W.pairs(300, { W.pairTouch }) },
    { "missing pairs", W.pairs(300, { W.pairMiss }) },
  }
else
  local ordinary = W.ordinary(200)
  kinds = {
    { "ordinary polygons (4-16 vertices)", { ordinary } },
    { "the same at 1e9", { shapes.translateEach(ordinary, 1e9, -0.6e9) } },
    { "1,000 vertices", { W.large(1000, 4) } },
  }
end

print(("%s, %s: VM instructions per call (reference: %s)"):format(fname, _VERSION,
  fname == "polygonAreaAccurate" and "polygonArea" or "the tutorial's"))
print(("%-40s %10s %10s %7s"):format("workload", "polygon", "reference", "ratio"))
for _, kind in ipairs(kinds) do
  local args = kind[2]
  local a = count(polygon[fname], args[1], args[2])
  local b = count(reference, args[1], args[2])
  print(("%-40s %10.0f %10.0f %7.3f"):format(kind[1], a, b, a / b))
end
