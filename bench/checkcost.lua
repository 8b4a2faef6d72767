-- bench/checkcost.lua: where a checked polygonsCollide's time goes, per pair of the benchmark's
-- pMix polygons (bench/run.lua's workload), in interleaved rounds in one process: the checked
-- engine's first pass alone (convex.lua's vouching pass, both polygons), the unchecked engine's
-- first pass alone (LuaJIT: shoelaceBounds and areaSignOf; PUC Lua: turnAndBounds), the
-- unchecked and the checked call. Prints the median and interquartile range of 15 rounds.
-- Optional: another convex.lua to time its vouching pass beside.
--   luajit bench/checkcost.lua [passes] [other/polygon/convex.lua]
--   lua5.4 bench/checkcost.lua 100
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local W = require "bench.workloads"
local polygon = require "polygon"
local kernel = require "polygon.kernel"
local convex = require "polygon.convex"
local collide = require "polygon.collide"

local passes = tonumber(arg[1]) or (kernel.JIT and 1000 or 100)
local cols = W.pairs(300, { W.pairOverlap, W.pairTouch, W.pairMiss })
local A, B = cols[1], cols[2]
local N = #A
local sb, aso, tab = kernel.shoelaceBounds, kernel.areaSignOf, kernel.turnAndBounds
local checked, unchecked = polygon.polygonsCollide, collide.unchecked.polygonsCollide

local function passTimer(pass)
  return function()
    local c = 0
    for i = 1, N do
      local p, q = A[i], B[i]
      if pass(p, #p) then c = c + 1 end
      if pass(q, #q) then c = c + 1 end
    end
    return c
  end
end
local tests = {
  vouching = passTimer(convex.vouch),
  firstPass = kernel.JIT and function()
    local c = 0
    for i = 1, N do
      local p, q = A[i], B[i]
      local a, x, d = sb(p, #p)
      c = c + aso(p, #p, a, x, d)
      a, x, d = sb(q, #q)
      c = c + aso(q, #q, a, x, d)
    end
    return c
  end or function()
    local c = 0
    for i = 1, N do c = c + tab(A[i], #A[i]) + tab(B[i], #B[i]) end
    return c
  end,
  unchecked = function()
    local c = 0
    for i = 1, N do if unchecked(A[i], B[i]) then c = c + 1 end end
    return c
  end,
  checked = function()
    local c = 0
    for i = 1, N do if checked(A[i], B[i]) then c = c + 1 end end
    return c
  end,
}
local names = { "vouching", "firstPass", "unchecked", "checked" }
if arg[2] then
  tests.otherVouching = passTimer(assert(loadfile(arg[2]))("polygon.convex").vouch)
  table.insert(names, 2, "otherVouching")
end
local times, sink = {}, 0
for _, k in ipairs(names) do times[k] = {} end
for _ = 1, 15 do
  for _, k in ipairs(names) do
    local f = tests[k]
    local t0 = os.clock()
    for _ = 1, passes do sink = sink + f() end
    table.insert(times[k], (os.clock() - t0) / (passes * N) * 1e9)
  end
end
local out = {}
for _, k in ipairs(names) do
  table.sort(times[k])
  out[#out + 1] = ("%s %.0f (%.0f-%.0f)"):format(k, times[k][8], times[k][4], times[k][12])
end
print(table.concat(out, "; ") .. " ns a pair, median (IQR) of 15 rounds; checksum " .. sink)
