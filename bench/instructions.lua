-- bench/instructions.lua: Lua VM instructions per call of polygon.lua and of bench/baseline.lua on
-- the benchmark's workloads, counted with a debug.sethook count hook (every instruction; C
-- functions such as math.sqrt count as one call). Load on a shared machine cannot change these
-- counts, which is why they are quoted where timings are too noisy to show a change.
-- From the repository root, on PUC Lua: `lua5.4 bench/instructions.lua [FUNCTION]` (default
-- polygonsCollideV). Pair functions (polygonsCollide(V), polygonCollidesWith(V)) run on the
-- pair workloads; one-polygon functions (polygonType, polygonArea, polygonWindingOrder,
-- polygonAreaAccurate) on the ordinary polygons, the same at 1e9 and 1,000 vertices, where
-- polygonAreaAccurate is compared with polygonArea as in the benchmark; polygonCircleCollideV
-- on the benchmark's circles (at an edge, a corner, missing, inside); circlesCollideV, which the
-- tutorial has not (no reference), on overlapping pairs, on the same pairs after their push (a
-- resolve loop's second test: touching within rounding) and on missing pairs.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local W = require "bench.workloads"
local shapes = require "shapes"
local polygon = require "polygon"
local baseline = dofile("bench/baseline.lua")

local fname = arg[1] or "polygonsCollideV"
local PAIRS = { polygonsCollide = true, polygonsCollideV = true, polygonCollidesWith = true,
  polygonCollidesWithV = true }

-- args: arrays of the calls' arguments, one, two, four or six (args[k][i]: argument k of call
-- i); the loop's own instructions are counted too, the same for both sides of a row
local function pass(f, A1, A2, A3, A4, A5, A6)
  if A5 then
    for i = 1, #A1 do f(A1[i], A2[i], A3[i], A4[i], A5[i], A6[i]) end
  elseif A3 then
    for i = 1, #A1 do f(A1[i], A2[i], A3[i], A4[i]) end
  else
    for i = 1, #A1 do f(A1[i], A2 and A2[i]) end
  end
end

local function count(f, args)
  pass(f, args[1], args[2], args[3], args[4], args[5], args[6])   -- a warm-up (first-call work)
  local n = 0
  debug.sethook(function() n = n + 1 end, "", 1)
  pass(f, args[1], args[2], args[3], args[4], args[5], args[6])
  debug.sethook()
  return n / #args[1]
end

-- circlesCollideV's pairs: the benchmark's circles' centres and radii, the second circle along
-- a direction at a distance from 0.3 to 0.95 times the sum of the radii (overlapping) or 1.2 to
-- 2 times it (missing); "pushed" moves each overlapping pair's second circle by its push.
local function circlePairs(which)
  local C = W.circles(300, { 1, 2, 3, 4 })
  local X1, Y1, R1, X2, Y2, R2 = {}, {}, {}, {}, {}, {}
  for i = 1, #C[1] do
    local r1, r2 = C[4][i], C[4][i % #C[1] + 1]
    local t, f = i * 2.4, which == "missing" and 1.2 + 0.8 * (i % 7) / 7 or 0.3 + 0.65 * (i % 7) / 7
    local x1, y1 = C[2][i], C[3][i]
    local x2, y2 = x1 + (r1 + r2) * f * math.cos(t), y1 + (r1 + r2) * f * math.sin(t)
    if which == "pushed" then
      local _, dx, dy = polygon.circlesCollideV(x1, y1, r1, x2, y2, r2)
      x2, y2 = x2 + dx, y2 + dy
    end
    X1[i], Y1[i], R1[i], X2[i], Y2[i], R2[i] = x1, y1, r1, x2, y2, r2
  end
  return { X1, Y1, R1, X2, Y2, R2 }
end

-- the reference: the tutorial's function, or for polygonAreaAccurate polygon.lua's polygonArea
local reference = fname == "polygonAreaAccurate" and polygon.polygonArea or baseline[fname]
local kinds
if fname == "polygonCircleCollideV" then
  kinds = {
    { "edge, corner, missing, inside (mixed)", W.circles(300, { 1, 2, 3, 4 }) },
    { "at an edge", W.circles(300, { 1 }) },
    { "at a corner", W.circles(300, { 2 }) },
    { "missing", W.circles(300, { 3 }) },
  }
elseif fname == "circlesCollideV" then
  kinds = {
    { "overlapping pairs", circlePairs("overlapping") },
    { "the same pairs after their push", circlePairs("pushed") },
    { "missing pairs", circlePairs("missing") },
  }
elseif PAIRS[fname] then
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
  fname == "polygonAreaAccurate" and "polygonArea" or reference and "the tutorial's" or "none"))
print(("%-40s %10s %10s %7s"):format("workload", "polygon", "reference", "ratio"))
for _, kind in ipairs(kinds) do
  local args = kind[2]
  local a = count(polygon[fname], args)
  if reference then
    local b = count(reference, args)
    print(("%-40s %10.0f %10.0f %7.3f"):format(kind[1], a, b, a / b))
  else
    print(("%-40s %10.0f %10s %7s"):format(kind[1], a, "-", "-"))
  end
end
