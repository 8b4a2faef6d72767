-- bench/run.lua: speed against error, polygon.lua beside the tutorial's formulas (bench/baseline.lua).
--
-- Run from the repository root:  luajit bench/run.lua [--quick] [--out FILE] [--data FILE]
--                                                     [--only PATTERN] [--label NAME]
-- Prints a markdown section to stdout (and to --out), writes gnuplot points to --data, and exits
-- non-zero if any row raised an error, a function is missing or a checksum is NaN.
-- BENCH_QUICK=1 in the environment is the same as --quick (small inputs, short timings).
package.path = "./?.lua;./spec/support/?.lua;" .. package.path

local exact = require "bench.exact"
local W = require "bench.workloads"
local baseline = require "bench.baseline"
package.loaded["bench.baseline"] = nil

local ceil, huge, sqrt, abs = math.ceil, math.huge, math.sqrt, math.abs
local clock = os.clock
local loadstring = rawget(_G, "loadstring") or load
local jit = rawget(_G, "jit")

---------------------------------------------------------------------------------------------
-- Options
---------------------------------------------------------------------------------------------
local opts = { quick = os.getenv("BENCH_QUICK") == "1" }
do
  local i = 1
  while arg and arg[i] do
    local a = arg[i]
    if a == "--quick" then opts.quick = true
    elseif a == "--aa" then opts.aa = true
    elseif a == "--out" or a == "--data" or a == "--only" or a == "--label" then
      opts[a:sub(3)] = arg[i + 1]; i = i + 1
    else
      io.stderr:write("bench/run.lua: unknown argument ", a, "\n"); os.exit(2)
    end
    i = i + 1
  end
end

-- --aa (an A/A test) times a second copy of the baseline in place of polygon.lua: the ratios
-- it prints are the noise floor of this machine and interpreter.
local MODULE = opts.aa and "bench.baseline" or "polygon"
local function loadFresh(name)
  package.loaded[name] = nil
  local lib = require(name)
  package.loaded[name] = nil
  return lib
end
local okModule, polygon = pcall(loadFresh, MODULE)
if not okModule then
  io.stderr:write("bench/run.lua: cannot load polygon.lua (run from the repository root): ",
                  tostring(polygon), "\n")
  os.exit(2)
end

local QUICK = opts.quick
local TARGET_SECONDS = QUICK and 0.0005 or 0.004   -- one timed repetition lasts at least this
-- Epochs start from fresh kernels and, on LuaJIT, flushed traces (see measureRow). PUC Lua
-- runs the same bytecode every time, so one epoch of more repetitions serves it.
local EPOCHS = (QUICK or not jit) and 1 or 7
local REPEATS = QUICK and 2 or jit and 2 or 5
local started = clock()

local interpreter = jit and jit.version or _VERSION
local function cpuName()
  local f = io.open("/proc/cpuinfo", "r")
  if not f then return "unknown CPU" end
  local name, cores = nil, 0
  for line in f:lines() do
    local m = line:match("^model name%s*:%s*(.-)%s*$")
    if m then name = name or m; cores = cores + 1 end
  end
  f:close()
  if not name then return "unknown CPU" end
  return ("%s, %d logical CPUs"):format(name, cores)
end

---------------------------------------------------------------------------------------------
-- Kernels: one freshly loaded chunk per (row, variant), so that LuaJIT records separate traces
-- and no variant runs on traces specialised for the other. Every result is folded into acc.
---------------------------------------------------------------------------------------------
local CALLS = {
  p = "f(A1[i])",
  pxy = "f(A1[i], A2[i], A3[i])",
  oxy = "A1[i]:contains(A2[i], A3[i])",
  pp = "f(A1[i], A2[i])",
  pxyr = "f(A1[i], A2[i], A3[i], A4[i])",
  proj = "f(A1[i], A2[i], A3[i], A4[i], A5[i])",
  circ = "f(A1[i], A2[i], A3[i], A4[i], A5[i], A6[i], A7[i])",
}
local FOLDS = {
  num = "if a then acc = acc + a end",
  num2 = "if a then acc = acc + a + 0.5 * b end",
  str = "if a then acc = acc + #a end",
  bool = "if a then acc = acc + 1 end",
  v3 = "if a then acc = acc + a + 0.5 * b + 0.25 * c end",
}
local TEMPLATE = [[
local f, A1, A2, A3, A4, A5, A6, A7 = ...
return function(n, reps)
  local acc = 0
  for _ = 1, reps do
    for i = 1, n do
      local a, b, c = CALL
      FOLD
    end
  end
  return acc
end
]]

local function makeKernel(shape, fold, f, args)
  local src = TEMPLATE:gsub("CALL", CALLS[shape])
  src = src:gsub("FOLD", FOLDS[fold])
  local chunk = assert(loadstring(src, "=kernel"))
  return chunk(f, args[1], args[2], args[3], args[4], args[5], args[6], args[7])
end

local function timeKernel(kernel, n, reps)
  local t0 = clock()
  local acc = kernel(n, reps)
  return clock() - t0, acc
end

local function calibrate(kernel, n)
  local reps = 1
  while true do
    local t = timeKernel(kernel, n, reps)
    if t >= TARGET_SECONDS or reps >= 2 ^ 26 then return reps end
    local factor = t > 0 and TARGET_SECONDS / t * 1.2 or 16
    if factor > 16 then factor = 16 elseif factor < 2 then factor = 2 end
    reps = ceil(reps * factor)
  end
end

local function garbagePerCall(kernel, n, reps)
  collectgarbage("collect")
  collectgarbage("stop")
  local before = collectgarbage("count")
  kernel(n, reps)
  local after = collectgarbage("count")
  collectgarbage("restart")
  return (after - before) * 1024 / (n * reps)
end

local function median(list)
  local s = {}
  for i = 1, #list do s[i] = list[i] end
  table.sort(s)
  local m = #s
  if m == 0 then return nil end
  if m % 2 == 1 then return s[(m + 1) / 2] end
  return (s[m / 2] + s[m / 2 + 1]) / 2
end

local function maximum(list)
  local m = nil
  for i = 1, #list do if not m or list[i] > m then m = list[i] end end
  return m
end

---------------------------------------------------------------------------------------------
-- Workloads
---------------------------------------------------------------------------------------------
local SIZES = QUICK and { polys = 26, degen = 60, queries = 4, pairs = 24, circles = 24, big = 2,
                          bigN = 1000, hugeN = nil, tiles = 4 }
                     or { polys = 200, degen = 600, queries = 10, pairs = 300, circles = 300, big = 4,
                          bigN = 1000, hugeN = 100000, tiles = 12 }

local WL, WL_ORDER = {}, {}
local function workload(key, name, shape, args)
  local wl = { key = key, name = name, shape = shape, args = args, n = #args[1], refs = {} }
  WL[key] = wl
  WL_ORDER[#WL_ORDER + 1] = wl
  return wl
end

local ordinary = W.ordinary(SIZES.polys)
workload("ord", "4-16 vertices, near origin (half convex)", "p", { ordinary })
workload("far6", "4-16 vertices, translated by 1e6", "p", { W.translated(ordinary, 1e6, -0.6e6) })
workload("far9", "4-16 vertices, translated by 1e9", "p", { W.translated(ordinary, 1e9, -0.6e9) })
workload("far12", "4-16 vertices, translated by 1e12", "p", { W.translated(ordinary, 1e12, -0.6e12) })
workload("degen", "near-degenerate (ulp grids, near-collinear)", "p", { W.nearDegenerate(SIZES.degen) })
local big = W.large(SIZES.bigN, SIZES.big)
workload("big", ("%d vertices"):format(SIZES.bigN), "p", { big })
local huge100k = SIZES.hugeN and W.large(SIZES.hugeN, 2)
if huge100k then workload("huge", "100,000 vertices", "p", { huge100k }) end

local qOrd = W.queriesInBox(ordinary, SIZES.queries)
workload("cOrd", "4-16 vertices, points in bounding box", "pxy", qOrd)
workload("cFar", "4-16 vertices at 1e9, points in bounding box", "pxy",
         W.translatedQueries(qOrd, 1e9, -0.6e9))
workload("cEdge", "points on / within 3 ulps of edges and vertices", "pxy",
         W.queriesNearEdges(ordinary, SIZES.queries))
workload("cTiles", "touching tiles, points on shared edges and corners", "pxy", W.tiles(SIZES.tiles))
workload("cBig", ("%d vertices, points in bounding box"):format(SIZES.bigN), "pxy",
         W.queriesInBox(big, QUICK and 20 or 100))
if huge100k then workload("cHuge", "100,000 vertices, points in bounding box", "pxy",
                          W.queriesInBox(huge100k, 10)) end
-- the class: same queries as cOrd, the objects made per variant
workload("oOrd", "4-16 vertices, points in bounding box", "oxy", qOrd)

local mixedPairs = W.pairs(SIZES.pairs, { W.pairOverlap, W.pairTouch, W.pairMiss })
workload("pMix", "convex 6-8 pairs: 1/3 overlap, 1/3 touch, 1/3 miss", "pp", mixedPairs)
workload("pOver", "convex 6-8 pairs: overlapping", "pp", W.pairs(SIZES.pairs, { W.pairOverlap }))
workload("pTouch", "convex 6-8 pairs: touching (shared edge, corner or T)", "pp",
         W.pairs(SIZES.pairs, { W.pairTouch }))
workload("pMiss", "convex 6-8 pairs: missing", "pp", W.pairs(SIZES.pairs, { W.pairMiss }))
workload("pIn", "convex 6-8 pairs: one inside the other", "pp", W.pairs(SIZES.pairs, { W.pairInside }))
workload("pFar", "convex 6-8 pairs, mixed, translated by 1e6", "pp",
         W.translatedPairs(mixedPairs, 1e6, -0.6e6))

local circles = W.circles(SIZES.circles, { 1, 2, 3, 4 })
workload("ciMix", "4-16 vertices, circles: edge, corner, miss, inside", "pxyr", circles)
workload("ciFar", "the same translated by 1e6", "pxyr", W.translatedCircles(circles, 1e6, -0.6e6))
workload("ciIn", "4-16 vertices, circle deep inside", "pxyr", W.circles(SIZES.circles, { 4 }))

local convexPairs = mixedPairs[1]
workload("prOrd", "convex 6-8, vertex and edge normal", "proj", W.projections(convexPairs))
workload("prFar", "the same translated by 1e6", "proj",
         W.projections(W.translated(convexPairs, 1e6, -0.6e6)))
workload("pcOrd", "random circle, point and axis near origin", "circ",
         W.circleProjections(SIZES.circles))

---------------------------------------------------------------------------------------------
-- Exact references (computed once per workload and input, outside every timing)
---------------------------------------------------------------------------------------------
local function refs(wl, key, compute)
  local list = wl.refs[key]
  if not list then
    list = {}
    for i = 1, wl.n do list[i] = compute(i, wl.args) end
    wl.refs[key] = list
  end
  return list
end

local function twiceRefs(wl) return refs(wl, "twice", function(i, a) return exact.twiceArea(a[1][i]) end) end

-- Error evaluators: (wl, call) -> summary, with call(i) returning the variant's results.
local evaluators = {}

local function signSummary(wrong, total)
  return { wrong = wrong, total = total, text = ("wrong %d/%d"):format(wrong, total) }
end

local function fmt(x)
  if x == nil then return "-" end
  if x == 0 then return "0" end
  if x == huge then return "inf" end
  if x >= 1000 or x < 0.01 then return ("%.1e"):format(x) end
  return ("%.2f"):format(x)
end
local function fmtRel(x)
  if x == nil then return "-" end
  if x == 0 then return "0" end
  if x == huge then return "inf" end
  return ("%.1e"):format(x)
end

local function ulpSummary(errs, extra)
  local mx, md = maximum(errs), median(errs)
  local s = { max = mx, med = md, text = ("max %s, med %s ulp"):format(fmt(mx), fmt(md)) }
  if extra and extra > 0 then s.text = s.text .. (", %d wrong nil"):format(extra); s.wrong = extra end
  return s
end

function evaluators.winding(wl, call)
  local twice, wrong = twiceRefs(wl), 0
  for i = 1, wl.n do
    local sg = exact.sign(twice[i])
    local want = sg > 0 and "cw" or sg < 0 and "ccw" or nil
    if call(i) ~= want then wrong = wrong + 1 end
  end
  return signSummary(wrong, wl.n)
end

function evaluators.area(wl, call)
  local twice, errs = twiceRefs(wl), {}
  for i = 1, wl.n do
    local got = call(i)
    local e = twice[i]
    local half = exact.scale(e, exact.sign(e) < 0 and -0.5 or 0.5)
    errs[i] = got and exact.ulpError(half, got) or huge
  end
  return ulpSummary(errs)
end

function evaluators.type(wl, call)
  local want, wrong = refs(wl, "type", function(i, a) return exact.polygonType(a[1][i]) end), 0
  for i = 1, wl.n do if call(i) ~= want[i] then wrong = wrong + 1 end end
  return signSummary(wrong, wl.n)
end

function evaluators.center(wl, call)
  local sums = refs(wl, "sums", function(i, a) return { exact.coordinateSums(a[1][i]) } end)
  local errs = {}
  for i = 1, wl.n do
    local gx, gy = call(i)
    local count = #wl.args[1][i] / 2
    if gx then
      local ex = exact.meanError(sums[i][1], count, gx)
      local ey = exact.meanError(sums[i][2], count, gy)
      errs[i] = ex > ey and ex or ey
    else
      errs[i] = huge
    end
  end
  return ulpSummary(errs)
end

function evaluators.centroid(wl, call)
  local sums = refs(wl, "centroid", function(i, a) return { exact.centroidSums(a[1][i]) } end)
  local errs, wrongNil = {}, 0
  for i = 1, wl.n do
    local gx, gy = call(i)
    local twice, nx, ny = sums[i][1], sums[i][2], sums[i][3]
    if exact.sign(twice) == 0 then
      if gx ~= nil then wrongNil = wrongNil + 1 end
    elseif not gx then
      wrongNil = wrongNil + 1
    else
      local ex = exact.centroidError(twice, nx, gx)
      local ey = exact.centroidError(twice, ny, gy)
      errs[#errs + 1] = ex > ey and ex or ey
    end
  end
  return ulpSummary(errs, wrongNil)
end

function evaluators.contains(wl, call)
  local want = refs(wl, "contains", function(i, a) return exact.contains(a[1][i], a[2][i], a[3][i]) end)
  local wrong = 0
  for i = 1, wl.n do if (call(i) and true or false) ~= want[i] then wrong = wrong + 1 end end
  return signSummary(wrong, wl.n)
end

local function satRefs(wl, both)
  return refs(wl, both and "sat2" or "sat1", function(i, a)
    return { exact.sat(a[1][i], a[2][i], both) }
  end)
end

local function collideBool(both)
  return function(wl, call)
    local want, wrong = satRefs(wl, both), 0
    for i = 1, wl.n do
      if (call(i) and true or false) ~= want[i][1] then wrong = wrong + 1 end
    end
    return signSummary(wrong, wl.n)
  end
end
evaluators.collide1, evaluators.collide2 = collideBool(false), collideBool(true)

local function extent(points)
  local x0, y0, x1, y1 = huge, huge, -huge, -huge
  for i = 1, #points - 1, 2 do
    local x, y = points[i], points[i + 1]
    if x < x0 then x0 = x end
    if x > x1 then x1 = x end
    if y < y0 then y0 = y end
    if y > y1 then y1 = y end
  end
  return math.max(x1 - x0, y1 - y0)
end

-- Size of the shapes of input i: the larger bounding box side (circle: its diameter).
local function shapeSize(wl, i)
  local a = wl.args
  if wl.shape == "pp" then return math.max(extent(a[1][i]), extent(a[2][i])) end
  return math.max(extent(a[1][i]), 2 * a[4][i])
end

-- Depth and displacement errors are relative to the exact depth, or to DEPTH_FLOOR times the
-- shapes' size when the depth is smaller (shapes touching to within rounding, where a relative
-- error says nothing).
local DEPTH_FLOOR = 1e-12

local function displacementSummary(wl, call, want)
  local wrong, depths, disps, total = 0, {}, {}, 0
  for i = 1, wl.n do
    local got, dx, dy = call(i)
    local r = want[i]
    total = total + 1
    if (got and true or false) ~= r[1] then
      wrong = wrong + 1
    elseif got then
      local scale = math.max(r[2], DEPTH_FLOOR * shapeSize(wl, i))
      depths[#depths + 1] = abs((got - r[2]) - r[3]) / scale
      local best = huge
      for _, d in ipairs(r[4]) do
        local ex, ey = (dx - d[1]) - d[2], (dy - d[3]) - d[4]
        local e = sqrt(ex * ex + ey * ey) / scale
        if e < best then best = e end
      end
      disps[#disps + 1] = best
    end
  end
  local s = { wrong = wrong, total = total, depthMax = maximum(depths), depthMed = median(depths),
              dispMax = maximum(disps), dispMed = median(disps) }
  s.text = ("wrong %d/%d; depth %s/%s; disp %s/%s"):format(wrong, total,
    fmtRel(s.depthMax), fmtRel(s.depthMed), fmtRel(s.dispMax), fmtRel(s.dispMed))
  return s
end

evaluators.collideV1 = function(wl, call) return displacementSummary(wl, call, satRefs(wl, false)) end
evaluators.collideV2 = function(wl, call) return displacementSummary(wl, call, satRefs(wl, true)) end
evaluators.circleV = function(wl, call)
  return displacementSummary(wl, call, refs(wl, "circle", function(i, a)
    return { exact.circle(a[1][i], a[2][i], a[3][i], a[4][i]) }
  end))
end

function evaluators.project(wl, call)
  local a, errs = wl.args, {}
  local want = refs(wl, "proj", function(i)
    return { exact.projectRange(a[1][i], a[2][i], a[3][i], a[4][i], a[5][i]) }
  end)
  for i = 1, wl.n do
    local lo, hi = call(i)
    local e1, e2 = exact.ulpError(want[i][1], lo), exact.ulpError(want[i][2], hi)
    errs[i] = e1 > e2 and e1 or e2
  end
  return ulpSummary(errs)
end

function evaluators.projectCircle(wl, call)
  local a, errs = wl.args, {}
  for i = 1, wl.n do
    local lo, hi = call(i)
    local s = exact.add(exact.scale(exact.diff(a[1][i], a[4][i]), a[6][i]),
                        exact.scale(exact.diff(a[2][i], a[5][i]), a[7][i]))
    local e1 = exact.ulpError(exact.grow(s, -a[3][i]), lo)
    local e2 = exact.ulpError(exact.grow(s, a[3][i]), hi)
    errs[i] = e1 > e2 and e1 or e2
  end
  return ulpSummary(errs)
end

function evaluators.valid(wl, call)
  local wrong = 0
  for i = 1, wl.n do if call(i) ~= true then wrong = wrong + 1 end end
  return signSummary(wrong, wl.n)
end

---------------------------------------------------------------------------------------------
-- Rows
---------------------------------------------------------------------------------------------
local ROWS = {}
local function row(fname, wlKey, fold, kind, label)
  local wl = WL[wlKey]
  if wl then
    ROWS[#ROWS + 1] = { fname = fname, label = label or fname, wl = wl, fold = fold, kind = kind }
  end
end

local measureKeys = { "ord", "far6", "far9", "far12", "degen", "big", "huge" }
for _, k in ipairs(measureKeys) do row("polygonWindingOrder", k, "str", "winding") end
for _, k in ipairs(measureKeys) do row("polygonArea", k, "num", "area") end
for _, k in ipairs(measureKeys) do row("polygonAreaAccurate", k, "num", "area") end
for _, k in ipairs(measureKeys) do row("polygonType", k, "str", "type") end
for _, k in ipairs(measureKeys) do row("polygonCenter", k, "num2", "center") end
for _, k in ipairs(measureKeys) do row("polygonCentroid", k, "num2", "centroid") end
for _, k in ipairs({ "cOrd", "cFar", "cEdge", "cTiles", "cBig", "cHuge" }) do
  row("polygonContains", k, "bool", "contains")
end
row("Polygon:contains", "oOrd", "bool", "contains")
for _, f in ipairs({ { "polygonCollidesWith", "bool", "collide1" },
                     { "polygonsCollide", "bool", "collide2" },
                     { "polygonCollidesWithV", "v3", "collideV1" },
                     { "polygonsCollideV", "v3", "collideV2" } }) do
  for _, k in ipairs({ "pMix", "pOver", "pTouch", "pMiss", "pIn", "pFar" }) do row(f[1], k, f[2], f[3]) end
end
row("projectPolygon", "prOrd", "num2", "project")
row("projectPolygon", "prFar", "num2", "project")
for _, k in ipairs({ "ciMix", "ciFar", "ciIn" }) do row("polygonCircleCollideV", k, "v3", "circleV") end
row("projectCircle", "pcOrd", "num2", "projectCircle")
row("validate", "ord", "bool", "valid")
row("validate", "big", "bool", "valid")

local TARGETS = {
  { "polygonsCollideV", "pMix", 0.35 },
  { "polygonCircleCollideV", "ciMix", 0.7 },
  { "polygonContains", "cOrd", 1.0 },
  { "polygonArea", "ord", 1.1 },
  { "polygonWindingOrder", "ord", 1.2 },
  { "polygonType", "ord", 1.3 },
}

---------------------------------------------------------------------------------------------
-- Measuring
---------------------------------------------------------------------------------------------
local function objectsFor(lib, list)
  local out = {}
  for i = 1, #list do out[i] = lib.Polygon.new(list[i]) end
  return out
end

local function variantOf(lib, r)
  if r.fname == "Polygon:contains" then
    if type(lib.Polygon) ~= "table" or type(lib.Polygon.new) ~= "function" then return nil end
    local a = r.wl.args
    local args = { objectsFor(lib, a[1]), a[2], a[3] }
    return { args = args, f = false,
             call = function(i) return args[1][i]:contains(args[2][i], args[3][i]) end }
  end
  local f = lib[r.fname]
  if type(f) ~= "function" then return nil end
  local a = r.wl.args
  return { args = a, f = f, call = function(i)
    return f(a[1][i], a[2] and a[2][i], a[3] and a[3][i], a[4] and a[4][i], a[5] and a[5][i],
             a[6] and a[6][i], a[7] and a[7][i])
  end }
end

-- call(i) must pass exactly the arguments the kernel passes
local function exactCall(shape, v)
  if shape == "p" then local A = v.args; return function(i) return v.f(A[1][i]) end end
  if shape == "pp" then local A = v.args; return function(i) return v.f(A[1][i], A[2][i]) end end
  if shape == "pxy" then local A = v.args; return function(i) return v.f(A[1][i], A[2][i], A[3][i]) end end
  return v.call
end

local failures = {}
local checksum = { module = 0, baseline = 0 }

-- Fresh copies of both libraries: new function prototypes at new addresses.
local function freshLibraries()
  return loadFresh(MODULE), loadFresh("bench.baseline")
end

local function measureRow(r)
  local wl = r.wl
  collectgarbage("collect")
  local names = { "module", "baseline" }
  local variants = {}
  variants.module = variantOf(polygon, r)
  if r.fname ~= "validate" then variants.baseline = variantOf(baseline, r) end
  if not variants.module then
    if not opts.aa then failures[#failures + 1] = r.fname .. " is missing from polygon.lua" end
    r.missing = true
    return
  end
  local times, reps = { module = {}, baseline = {} }, {}
  -- On LuaJIT the speed of a function moves by +-10% from process to process with where its
  -- bytecode lands (hot counters are hashed by address) and which traces form first. Each
  -- epoch therefore reloads both libraries, flushes all traces and loads fresh kernels; the
  -- result is the median over every repetition of every epoch.
  for epoch = 1, EPOCHS do
    if epoch > 1 then
      local lib, base = freshLibraries()
      variants.module = variantOf(lib, r)
      if variants.baseline then variants.baseline = variantOf(base, r) end
    end
    if jit then jit.flush() end
    -- alternate which variant runs first
    local order = epoch % 2 == 1 and names or { names[2], names[1] }
    for _, name in ipairs(order) do
      local v = variants[name]
      if v then
        v.kernel = makeKernel(wl.shape, r.fold, v.f, v.args)
        if epoch == 1 then reps[name] = calibrate(v.kernel, wl.n) else v.kernel(wl.n, reps[name]) end
        v.times = times[name]
      end
    end
    -- Variants of similar speed run the same number of passes: with different counts an A/A
    -- test (the baseline against a copy of itself) drifted by up to 20% on LuaJIT, with equal
    -- ones by about 4%. Where one is over 4 times slower each keeps its own count.
    if epoch == 1 then
      local a, b = reps.module, reps.baseline or reps.module
      if a <= 4 * b and b <= 4 * a then
        reps.module = math.max(a, b)
        reps.baseline = reps.module
      end
    end
    for _, name in ipairs(names) do
      if variants[name] then variants[name].reps = reps[name] end
    end
    for _ = 1, REPEATS do
      for _, name in ipairs(order) do
        local v = variants[name]
        if v then
          local t, acc = timeKernel(v.kernel, wl.n, v.reps)
          v.times[#v.times + 1] = t / (wl.n * v.reps) * 1e9
          if acc ~= acc then v.nan = true end
          checksum[name] = checksum[name] + acc
        end
      end
    end
  end
  for _, name in ipairs(names) do
    local v = variants[name]
    if v then
      v.ns = median(v.times)
      local greps = ceil(2000 / wl.n)
      if greps > v.reps then greps = v.reps end
      -- a trace compiled during the count allocates once: keep the least of three counts
      v.bytes = garbagePerCall(v.kernel, wl.n, greps)
      for _ = 1, 2 do
        if v.bytes > 0 then v.bytes = math.min(v.bytes, garbagePerCall(v.kernel, wl.n, greps)) end
      end
      v.err = evaluators[r.kind](wl, exactCall(wl.shape, v))
      if v.nan then
        failures[#failures + 1] = ("%s on %s (%s): checksum is NaN"):format(r.label, wl.name, name)
      end
    end
  end
  r.module, r.baseline = variants.module, variants.baseline
end

local rowsRun = {}
for _, r in ipairs(ROWS) do
  if not opts.only or (r.fname .. " " .. r.wl.key):find(opts.only) then
    local ok, err = pcall(measureRow, r)
    if not ok then
      r.error = tostring(err)
      failures[#failures + 1] = ("%s on %s raised: %s"):format(r.label, r.wl.name, r.error)
    end
    rowsRun[#rowsRun + 1] = r
  end
end
if checksum.module ~= checksum.module or checksum.baseline ~= checksum.baseline then
  failures[#failures + 1] = "total checksum is NaN"
end

---------------------------------------------------------------------------------------------
-- Reporting
---------------------------------------------------------------------------------------------
local out = {}
local function emit(s) out[#out + 1] = s end

local function ns(x)
  if not x then return "-" end
  if x >= 1e6 then return ("%.2f ms"):format(x / 1e6) end
  if x >= 1e4 then return ("%.1f us"):format(x / 1e3) end
  return ("%.0f ns"):format(x)
end
local function bytes(x)
  if not x then return "-" end
  if x < 0.05 then return "0" end
  return ("%.1f"):format(x)
end
local function ratio(r)
  if r.module and r.baseline and r.baseline.ns > 0 then return r.module.ns / r.baseline.ns end
  return nil
end

local label = opts.label or interpreter
local title = ("%s, %s"):format(interpreter, cpuName())
emit(("## %s"):format(title))
emit("")
emit(("Command: `%s bench/run.lua%s%s` (part of `make bench`), %s. Time per call is the median " ..
      "of %d repetitions of at least %g ms each%s; garbage is counted with the collector " ..
      "stopped; errors are against exact answers (bench/exact.lua).%s%s")
     :format(label, QUICK and " --quick" or "", opts.aa and " --aa" or "", os.date("!%Y-%m-%d"),
             REPEATS * EPOCHS, TARGET_SECONDS * 1000,
             EPOCHS > 1 and (" (%d epochs, each reloading both libraries, flushing LuaJIT's traces " ..
                             "and loading fresh kernels)"):format(EPOCHS) or "",
             QUICK and " QUICK MODE: small inputs, the numbers mean nothing." or "",
             opts.aa and " A/A TEST: the \"polygon.lua\" columns are a copy of the baseline." or ""))
emit("")

local PUC = not jit
local byKey = {}
for _, r in ipairs(rowsRun) do byKey[r.fname .. "@" .. r.wl.key] = r end

emit("### Targets (ratio = polygon.lua time / baseline time, same run)")
emit("")
emit("| function | workload | ratio | target | met | polygon.lua B/call | 0 B target |")
emit("|---|---|---:|---:|---|---:|---|")
for _, t in ipairs(TARGETS) do
  local r = byKey[t[1] .. "@" .. t[2]]
  local goal = PUC and 1.6 or t[3]
  if r then
    local q = ratio(r)
    local b = r.module and r.module.bytes
    emit(("| `%s` | %s | %s | %s%s | %s | %s | %s |"):format(t[1], r.wl.name,
      q and ("%.2f"):format(q) or "-", ("%.2f"):format(goal),
      (PUC and _VERSION ~= "Lua 5.4") and " (5.4's)" or "",
      q and (q <= goal and "met" or "**not met**") or "-",
      bytes(b), b and (b < 0.05 and "met" or "**not met**") or "-"))
  end
end
emit("")

emit("### All rows")
emit("")
emit("Error columns: `wrong k/N` counts answers that differ from exact real arithmetic on the " ..
     "input doubles; `ulp` is |result - exact| in units in the last place of the exact value; " ..
     "`depth a/b; disp c/d` are the max/median relative errors of the overlap and of the " ..
     "displacement (dx, dy) where both say the shapes collide (relative to the exact depth, or " ..
     "to 1e-12 of the shapes' size when the depth is smaller: touching to within rounding).")
emit("")
emit("| function | workload | N | polygon.lua | baseline | ratio | B/call (lib/base) " ..
     "| polygon.lua error | baseline error |")
emit("|---|---|---:|---:|---:|---:|---:|---|---|")
for _, r in ipairs(rowsRun) do
  if r.error then
    emit(("| `%s` | %s | %d | ERROR | | | | %s | |"):format(r.label, r.wl.name, r.wl.n,
      r.error:gsub("|", "/"):gsub("\n", " ")))
  elseif r.missing then
    emit(("| `%s` | %s | %d | missing | | | | | |"):format(r.label, r.wl.name, r.wl.n))
  else
    local m, b = r.module, r.baseline
    local q = ratio(r)
    emit(("| `%s` | %s | %d | %s | %s | %s | %s / %s | %s | %s |"):format(r.label, r.wl.name, r.wl.n,
      ns(m.ns), b and ns(b.ns) or "-", q and ("%.2f"):format(q) or "-",
      bytes(m.bytes), b and bytes(b.bytes) or "-", m.err.text, b and b.err.text or "-"))
  end
end
emit("")

emit("### What exactness costs: `polygonArea` against `polygonAreaAccurate` (both polygon.lua)")
emit("")
emit("| workload | polygonArea | polygonAreaAccurate | time ratio | polygonArea error | " ..
     "polygonAreaAccurate error |")
emit("|---|---:|---:|---:|---|---|")
for _, k in ipairs(measureKeys) do
  local a, b = byKey["polygonArea@" .. k], byKey["polygonAreaAccurate@" .. k]
  if a and b and a.module and b.module then
    emit(("| %s | %s | %s | %.2f | %s | %s |"):format(a.wl.name, ns(a.module.ns), ns(b.module.ns),
      b.module.ns / a.module.ns, a.module.err.text, b.module.err.text))
  end
end
emit("")
emit(("Checksum of every timed result: polygon.lua %.17g, baseline %.17g. Run time %.0f s (CPU)."):format(
  checksum.module, checksum.baseline, clock() - started))
if #failures > 0 then
  emit("")
  emit("FAILURES:")
  for _, f in ipairs(failures) do emit("- " .. f) end
end
emit("")

local text = table.concat(out, "\n")
print(text)
if opts.out then
  local f = assert(io.open(opts.out, "w"))
  f:write(text, "\n")
  f:close()
end

-- Points for bench/plot.gp: three panels, each "module" then "baseline" block.
-- Errors of 0 are drawn at the panel's floor (noted in the plot).
if opts.data then
  local panels = {
    { floor = 0.01, rows = { { "polygonArea", "far6", "area" },
                             { "polygonAreaAccurate", "far6", "areaAccurate" },
                             { "polygonCenter", "far6", "center" },
                             { "polygonCentroid", "far6", "centroid" } },
      value = function(e) return e.max end },
    { floor = 0.01, rows = { { "polygonWindingOrder", "degen", "winding" },
                             { "polygonType", "degen", "type" },
                             { "polygonContains", "cEdge", "contains" },
                             { "polygonsCollide", "pTouch", "collide" } },
      value = function(e) return e.wrong and 100 * e.wrong / e.total end },
    { floor = 1e-17, rows = { { "polygonsCollideV", "pMix", "collideV" },
                              { "polygonCollidesWithV", "pMix", "collidesWithV" },
                              { "polygonCircleCollideV", "ciMix", "circleV" },
                              { "polygonsCollideV", "pIn", "collideV-inside" } },
      value = function(e) return e.dispMax end },
  }
  local f = assert(io.open(opts.data, "w"))
  f:write(("# %s: time per call (ns) against error; panels: max ulp (polygons at 1e6), " ..
           "wrong %% (near-degenerate), max relative displacement error\n"):format(title))
  for p, panel in ipairs(panels) do
    for _, variant in ipairs({ "module", "baseline" }) do
      f:write(("# panel %d %s\n"):format(p, variant))
      for k, spec in ipairs(panel.rows) do
        local r = byKey[spec[1] .. "@" .. spec[2]]
        local v = r and r[variant]
        if v and v.err then
          local e = panel.value(v.err) or 0
          if e < panel.floor then e = panel.floor end
          if e == huge then e = 1e300 end
          f:write(("%.6g %.6g \"%s\" %d\n"):format(v.ns, e, spec[3], k - 1))
        end
      end
      f:write("\n\n")
    end
  end
  f:close()
end

if #failures > 0 then
  io.stderr:write(("bench/run.lua: %d failure(s)\n"):format(#failures))
  os.exit(1)
end
