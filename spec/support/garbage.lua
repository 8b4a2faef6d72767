--- Heap growth of a loop, for the zero-garbage specs: the heap counted around a stopped
-- collector, made robust to LuaJIT's trace compiler. garbage.growth stops the collector itself
-- and restarts it before returning, so the specs need no before_each/after_each for it.
local garbage = {}

-- LuaJIT's compiled traces live on the heap, so they must be built before measuring. A loop over
-- inputs of several shapes (flat arrays and lists of parts) keeps recording new traces for a
-- while: measured by `luajit` on this machine, runs of 10000 calls of polygonBounds grew the
-- heap by 47, 37, 37 (100000 calls: 37 again, so not per call) and then 0 KB. So the growth is
-- the smallest over several runs: a body that allocates per call grows the heap in every run.
local WARMUPS = 2
local RUNS = 4

--- The smallest heap growth in KB over one run of `rounds` calls of body(i), over RUNS runs
-- after WARMUPS runs, with the collector stopped (a full collection first, a restart after).
function garbage.growth(body, rounds)
  collectgarbage("collect")
  collectgarbage("stop")
  for _ = 1, WARMUPS do
    for i = 1, rounds do body(i) end
  end
  local least = math.huge
  for _ = 1, RUNS do
    local before = collectgarbage("count")
    for i = 1, rounds do body(i) end
    least = math.min(least, collectgarbage("count") - before)
  end
  collectgarbage("restart")
  return least
end

return garbage
