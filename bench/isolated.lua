-- bench/isolated.lua: one function timed alone against the baseline, in a small loop over the
-- benchmark's own inputs, with nothing else in the process (no other workload's traces). Run
-- from the repository root: `luajit bench/isolated.lua polygonsCollideV` (or
-- polygonCircleCollideV; any Lua; `luajit bench/isolated.lua polygonsCollideV touch` times one
-- kind of the mixed pairs alone: overlap, touch or miss). Prints ns per call of each side for 7
-- alternating rounds and the median ratio. Compare with bench/run.lua's row to see what a
-- crowded process costs.
-- On LuaJIT it also counts the traces compiled for polygon.lua's side (polygon.lua's side runs
-- first, alone, until its traces settle) and the aborted ones by reason: a healthy function
-- compiles a few dozen traces and aborts few, none with "NYI". Which traces form depends on the
-- order in which exits grow hot, which differs from run to run: run it several times.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local W = require "bench.workloads"
local polygon = require "polygon"
local baseline = dofile("bench/baseline.lua")

local fname = arg[1] or "polygonsCollideV"
local args = fname == "polygonCircleCollideV" and W.circles(300, { 1, 2, 3, 4 })
  or W.pairs(300, { W.pairOverlap, W.pairTouch, W.pairMiss })
-- an optional second argument times one kind of the pairs alone: overlap, touch or miss
local kind = ({ overlap = 1, touch = 2, miss = 3 })[arg[2]]
if arg[2] and (not kind or fname == "polygonCircleCollideV") then
  error("kinds (overlap, touch, miss) are for the polygon pairs only", 0)
end
if kind then
  local A, B = {}, {}
  for i = kind, #args[1], 3 do A[#A + 1], B[#B + 1] = args[1][i], args[2][i] end
  args = { A, B }
end
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

-- LuaJIT's trace events while polygon.lua's side warms up alone
local jit = rawget(_G, "jit")
local traces, aborts, reasons, fallbacks = 0, 0, {}, 0
if jit then
  local util, vmdef = require "jit.util", require "jit.vmdef"
  jit.attach(function(what, tr, _, _, code, info)
    if what == "stop" then
      traces = traces + 1
      if util.traceinfo(tr).linktype == "interpreter" then fallbacks = fallbacks + 1 end
    elseif what == "abort" then
      aborts = aborts + 1
      local reason = (vmdef.traceerr[code] or "?"):format(info)
      reasons[reason] = (reasons[reason] or 0) + 1
    end
  end, "trace")
  for _ = 1, 5 do run(polygon[fname], 200) end
  jit.attach(function() end)
  print(("%s on LuaJIT, alone: %d traces (%d falling back to the interpreter), %d aborts"):format(
    fname, traces, fallbacks, aborts))
  for reason, count in pairs(reasons) do print(("  %4d aborted: %s"):format(count, reason)) end
end

local ratios = {}
for _ = 1, 7 do
  local lib, base = run(polygon[fname], 200), run(baseline[fname], 200)
  ratios[#ratios + 1] = lib / base
  io.write(("%.0f/%.0f ns  "):format(lib, base))
end
table.sort(ratios)
print(("\n%s%s: median ratio %.2f (polygon.lua / baseline)"):format(fname, arg[2] and " " .. arg[2] or "",
  ratios[4]))
