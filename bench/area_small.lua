-- bench/area_small.lua: polygonAreaAccurate against polygonArea on the benchmark's small
-- polygons (bench/run.lua's `ord` and `far9` workloads: 200 polygons of 4-16 vertices, near
-- the origin and moved by (1e9, -0.6e9)), and on its 1,000-vertex ones, in nanoseconds a call.
--
-- From the repository root: luajit bench/area_small.lua [OTHER_POLYGON_LUA [ROUNDS]]
-- With OTHER_POLYGON_LUA (e.g. the main repository's polygon.lua) its polygonAreaAccurate is
-- timed too, as `other`, so that two versions compare in one process. Each round times every
-- function once per workload, in an order that turns round every round; the table shows the
-- median over the rounds (and the least and greatest). Every result is folded into a checksum
-- (printed), and each version's sum of areas must equal the other's.
-- luajit bench/area_small.lua --alone FILE [FUNCTION [WORKLOAD [PASSES]]] times one function
-- alone in its process (default polygonAreaAccurate on `ord`; `far9` too): PASSES (10,000)
-- passes over the 200 polygons, no other function's traces beside it. Run it for two files in
-- turn, several times; under cachegrind, the difference of two PASSES counts gives the machine
-- instructions a call without the setup.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path

local W = require "bench.workloads"
local shapes = require "shapes"

local clock = os.clock

local function loadModule(file)
  local chunk = assert(loadfile(file))
  return chunk("polygon")   -- the module name, from which the front requires polygon/
end

if arg and arg[1] == "--alone" then
  local f = loadModule(arg[2])[arg[3] or "polygonAreaAccurate"]
  local list = W.ordinary(200)
  if arg[4] == "far9" then list = shapes.translateEach(list, 1e9, -0.6e9) end
  local passes = tonumber(arg[5]) or 10000
  local sum, t0 = 0, clock()
  for _ = 1, passes do
    for i = 1, #list do sum = sum + f(list[i]) end
  end
  print(("%s %s: %.1f ns a call, checksum %.17g"):format(arg[2], arg[3] or "polygonAreaAccurate",
    (clock() - t0) / (passes * #list) * 1e9, sum))
  return
end

local otherFile, rounds = arg and arg[1], tonumber(arg and arg[2]) or 15

local mine = loadModule("polygon.lua")
local fns = {
  { "area", mine.polygonArea },
  { "accurate", mine.polygonAreaAccurate },
}
if otherFile then fns[#fns + 1] = { "other", loadModule(otherFile).polygonAreaAccurate } end

local ordinary = W.ordinary(200)
local workloads = {
  { "ord", ordinary },
  { "far9", shapes.translateEach(ordinary, 1e9, -0.6e9) },
  { "big", W.large(1000, 4) },
}

-- One timed pass: the whole list, repeated until it lasts 4 ms; returns ns a call and the sum.
local function pass(fn, list)
  local reps = 1
  while true do
    local t0, sum = clock(), 0
    for _ = 1, reps do
      sum = 0
      for i = 1, #list do sum = sum + fn(list[i]) end
    end
    local t = clock() - t0
    if t >= 0.004 then return t / (reps * #list) * 1e9, sum end
    reps = reps * 2
  end
end

local times, sums = {}, {}
for r = 1, rounds do
  for wi = 1, #workloads do
    local key, list = workloads[wi][1], workloads[wi][2]
    for j = 1, #fns do
      local f = (r + wi) % 2 == 0 and fns[j] or fns[#fns + 1 - j]
      local name = key .. " " .. f[1]
      local ns, sum = pass(f[2], list)
      times[name] = times[name] or {}
      table.insert(times[name], ns)
      sums[name] = sum
    end
  end
end

local function median(list)
  table.sort(list)
  return list[math.floor((#list + 1) / 2)], list[1], list[#list]
end

local jit = rawget(_G, "jit")
print(("%s, %d rounds: ns a call, median (least-greatest)"):format(jit and jit.version or _VERSION,
  rounds))
for wi = 1, #workloads do
  local key = workloads[wi][1]
  local line = { key }
  local base = median(times[key .. " area"])
  for j = 1, #fns do
    local name = key .. " " .. fns[j][1]
    local med, lo, hi = median(times[name])
    line[#line + 1] = ("%s %.1f (%.1f-%.1f) x%.2f"):format(fns[j][1], med, lo, hi, med / base)
  end
  print(table.concat(line, "  "))
  if sums[key .. " other"] and sums[key .. " other"] ~= sums[key .. " accurate"] then
    print(("  checksums differ: accurate %.17g, other %.17g"):format(sums[key .. " accurate"],
      sums[key .. " other"]))
  end
  print(("  checksum %.17g"):format(sums[key .. " accurate"]))
end
