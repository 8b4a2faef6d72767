-- bench/isolated.lua: one function timed alone against the baseline, in a small loop over the
-- benchmark's own inputs, with nothing else in the process (no other workload's traces). Run
-- from the repository root: `luajit bench/isolated.lua polygonsCollideV` (or
-- polygonCircleCollideV; any Lua). Prints ns per call of each side for 7 alternating rounds and
-- the median ratio. Compare with bench/run.lua's row to see what a crowded process costs.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local W = require "bench.workloads"
local polygon = require "polygon"
local baseline = dofile("bench/baseline.lua")

local fname = arg[1] or "polygonsCollideV"
local args = fname == "polygonCircleCollideV" and W.circles(300, { 1, 2, 3, 4 })
  or W.pairs(300, { W.pairOverlap, W.pairTouch, W.pairMiss })
local A1, A2, A3, A4 = args[1], args[2], args[3], args[4]
local n = #A1

local function run(f, reps)
  local hits, t = 0, os.clock()
  for _ = 1, reps do
    for i = 1, n do
      if f(A1[i], A2[i], A3 and A3[i], A4 and A4[i]) then hits = hits + 1 end
    end
  end
  return (os.clock() - t) / (reps * n) * 1e9, hits
end

local ratios = {}
for _ = 1, 7 do
  local lib, base = run(polygon[fname], 200), run(baseline[fname], 200)
  ratios[#ratios + 1] = lib / base
  io.write(("%.0f/%.0f ns  "):format(lib, base))
end
table.sort(ratios)
print(("\n%s: median ratio %.2f (polygon.lua / baseline)"):format(fname, ratios[4]))
