-- bench/instructions.lua: Lua VM instructions per call of polygon.lua and of bench/baseline.lua on
-- the benchmark's pair workloads, counted with a debug.sethook count hook (every instruction;
-- C functions such as math.sqrt count as one call). Load on a shared machine cannot change
-- these counts, which is why they are quoted where timings are too noisy to show a change.
-- From the repository root, on PUC Lua: `lua5.4 bench/instructions.lua [FUNCTION]` (default
-- polygonsCollideV; also polygonsCollide, polygonCollidesWith, polygonCollidesWithV).
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local W = require "bench.workloads"
local polygon = require "polygon"
local baseline = dofile("bench/baseline.lua")

local fname = arg[1] or "polygonsCollideV"
local kinds = {
  { "mixed (1/3 overlap, touch, miss)", { W.pairOverlap, W.pairTouch, W.pairMiss } },
  { "overlapping", { W.pairOverlap } },
  { "touching", { W.pairTouch } },
  { "missing", { W.pairMiss } },
}

local function count(f, A1, A2)
  local n = 0
  debug.sethook(function() n = n + 1 end, "", 1)
  for i = 1, #A1 do f(A1[i], A2[i]) end
  debug.sethook()
  return n / #A1
end

print(("%s, %s: VM instructions per call"):format(fname, _VERSION))
print(("%-34s %10s %10s %7s"):format("pairs (300 each)", "polygon", "baseline", "ratio"))
for _, kind in ipairs(kinds) do
  local args = W.pairs(300, kind[2])
  local a = count(polygon[fname], args[1], args[2])
  local b = count(baseline[fname], args[1], args[2])
  print(("%-34s %10.0f %10.0f %7.3f"):format(kind[1], a, b, a / b))
end
