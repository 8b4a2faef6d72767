-- bench/run.lua: speed beside error, polygon.lua against the tutorial's formulas (bench/baseline.lua).
--
-- From the repository root: luajit bench/run.lua [--quick] [--only PATTERN] [--out FILE] [--data FILE]
-- [--label NAME] [--draws K] [--targets]. --only times the rows whose "function workload" (e.g.
-- "polygonType ord"; "unchecked polygonsCollideV pMix" for a collision row against itself
-- without the convexity check) matches the Lua pattern, --targets the rows with a target. Prints a
-- markdown section (also to --out), writes gnuplot points to --data, and exits non-zero if a row
-- raised an error, a function is missing or a checksum is NaN.
-- BENCH_QUICK=1 in the environment is --quick: small inputs and few rounds, a smoke test.
-- Draws: LuaJIT picks its traces with penalties it seeds at random at start-up, so one process
-- times one draw of traces, and a row's ratio moved from run to run by more than its targets'
-- margins (bench/NOTES.md): polygon.lua's side of polygonContains took 55-59 ns a call in eight
-- runs, the tutorial's 62-78. PUC Lua's ratios move from process to process too, less and for
-- reasons not pinned down (memory layout, the shared machine): Lua 5.4's polygonWindingOrder
-- read 1.16 to 1.32 in eight runs, 1.20 to 1.27 in six with address randomization off
-- (setarch -R). So every row with a target (LuaJIT, Lua 5.4) is timed in K processes (--draws
-- K; 16 by default, 1 with --quick): this one, then K - 1 fresh ones running only that row
-- (--ratios: they print the per-round ratios and times and skip the error counts). The ratio is
-- the median over all K x rounds ratios, the ratio of a typical draw (the times shown are
-- medians over them too); the table also shows the least and the largest of the K processes'
-- own medians, what one unlucky or lucky run would see. With TRACE_SEED fixed (bench/fixseed.c)
-- LuaJIT's traces are the same in every draw.
-- Each row loads both sides afresh (new function prototypes; on LuaJIT all traces flushed first),
-- then runs in rounds, each timing polygon.lua and its reference back to back, alternating which
-- goes first (ABBAAB...). The row reports the median of the per-round ratios and their
-- interquartile range: drift of the shared machine hits both sides of a ratio alike. (Reloading
-- and flushing in every round left LuaJIT interpreting after a few rows: 20 times slower.)
-- Errors are counted against spec/support/oracle.lua (exact big-integer arithmetic sharing no code
-- with polygon.lua), computed once per input outside every timing.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path

local W = require "bench.workloads"
local oracle = require "oracle"
local shapes = require "shapes"
local exact = require "exact"
local rays = require "rays"
local nearest = require "nearest"
local sweeps = require "sweeps"

local huge, sqrt, abs, max = math.huge, math.sqrt, math.abs, math.max
local clock, jit = os.clock, rawget(_G, "jit")
local loadstring, unpack = rawget(_G, "loadstring") or load, rawget(_G, "unpack") or rawget(table, "unpack")

local opts, argi = { quick = os.getenv("BENCH_QUICK") == "1" }, 1
while arg and arg[argi] do
  local a = arg[argi]
  if a == "--quick" then opts.quick = true
  elseif a == "--ratios" then opts.ratios = true
  elseif a == "--targets" then opts.targets = true
  elseif a == "--out" or a == "--data" or a == "--only" or a == "--label" or a == "--draws" then
    opts[a:sub(3)] = arg[argi + 1]; argi = argi + 1
  else io.stderr:write("bench/run.lua: unknown argument ", a, "\n"); os.exit(2) end
  argi = argi + 1
end

local function loadFresh(name)
  package.loaded[name] = nil
  local ok, lib = pcall(require, name)
  package.loaded[name] = nil
  if not ok then
    io.stderr:write("bench/run.lua: cannot load ", name, " (run from the repository root): ",
                    tostring(lib), "\n")
    os.exit(2)
  end
  return lib
end
loadFresh("polygon")

local QUICK = opts.quick
local TARGET_SECONDS = QUICK and 0.0005 or 0.004   -- one timed pass lasts at least this
local ROUNDS = QUICK and 2 or 15
local DRAWS = tonumber(opts.draws) or (QUICK and 1 or 16)
local INTERPRETER_PATH = arg and arg[-1] or "lua"
local started = clock()
local interpreter = jit and jit.version or _VERSION
-- the targets hold for LuaJIT and Lua 5.4; other versions are reported without them
local TARGET_COLUMN = jit and 3 or (_VERSION == "Lua 5.4" and 4 or nil)

local function cpuName()
  local f = io.open("/proc/cpuinfo", "r")
  local text = f and f:read("*a") or ""
  if f then f:close() end
  local _, cores = text:gsub("model name", "")
  return ("%s, %d logical CPUs"):format(text:match("model name%s*:%s*([^\n]-)%s*\n") or "unknown CPU", cores)
end

---------------------------------------------------------------------------------------------
-- Kernels: one freshly loaded chunk per side and row; every result is folded into acc, which
-- the caller adds to a printed checksum, so no call can be optimised away.
---------------------------------------------------------------------------------------------
local FOLDS = {
  num = "if a then acc = acc + a end",
  num2 = "if a then acc = acc + a + 0.5 * b end",
  str = "if a then acc = acc + #a end",
  bool = "if a then acc = acc + 1 end",
  v3 = "if a then acc = acc + a + 0.5 * b + 0.25 * c end",
}
local TEMPLATE = [[
local f, A1, A2, A3, A4, A5, A6, A7, A8 = ...
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

-- CALL is f(A1[i], ..., Ak[i]) for k argument columns, or the class's method call.
local function makeKernel(wl, fold, f, args)
  local call = {}
  for k = 1, #args do call[k] = ("A%d[i]"):format(k) end
  call = wl.method and "A1[i]:contains(A2[i], A3[i])" or "f(" .. table.concat(call, ", ") .. ")"
  local src = TEMPLATE:gsub("CALL", call):gsub("FOLD", FOLDS[fold])
  return assert(loadstring(src, "=kernel"))(f, args[1], args[2], args[3], args[4], args[5], args[6], args[7],
    args[8])
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
    reps = math.ceil(reps * (t > 0 and math.min(16, math.max(2, TARGET_SECONDS / t * 1.2)) or 16))
  end
end

local function garbagePerCall(kernel, n, reps)
  collectgarbage("collect"); collectgarbage("stop")
  local before = collectgarbage("count")
  kernel(n, reps)
  local bytes = (collectgarbage("count") - before) * 1024 / (n * reps)
  collectgarbage("restart")
  return bytes
end

-- The q-quantile of a list (linear between order statistics); q = 0.5 is the median.
local function quantile(list, q)
  local s = {}
  for i = 1, #list do s[i] = list[i] end
  table.sort(s)
  if #s == 0 then return nil end
  local h = 1 + (#s - 1) * q
  local lo = math.floor(h)
  return h == lo and s[lo] or s[lo] + (h - lo) * (s[lo + 1] - s[lo])
end

---------------------------------------------------------------------------------------------
-- Workloads: key, name, argument columns (call i passes row i of each)
---------------------------------------------------------------------------------------------
local SIZES = QUICK and { polys = 26, degen = 60, queries = 4, pairs = 24, circles = 24, big = 2, tiles = 4 }
  or { polys = 200, degen = 600, queries = 10, pairs = 300, circles = 300, big = 4, tiles = 12 }
local WL = {}
local function workload(key, name, args, method)
  WL[key] = { key = key, name = name, args = args, n = #args[1], refs = {}, method = method }
end

local ordinary = W.ordinary(SIZES.polys)
local big = W.large(1000, SIZES.big)
workload("ord", "4-16 vertices near the origin, half convex", { ordinary })
workload("far9", "4-16 vertices translated by 1e9", { shapes.translateEach(ordinary, 1e9, -0.6e9) })
workload("degen", "near-degenerate (ulp grids, near-collinear)", { W.nearDegenerate(SIZES.degen) })
workload("big", "1,000 vertices", { big })
if not QUICK then workload("huge", "100,000 vertices", { W.large(100000, 2) }) end
local queries = W.queriesInBox(ordinary, SIZES.queries)
workload("cOrd", "4-16 vertices, points in the bounding box", queries)
workload("cEdge", "points on, or within 3 ulps of, edges", W.queriesNearEdges(ordinary, SIZES.queries))
workload("cTiles", "touching tiles, points on shared edges and corners", W.tiles(SIZES.tiles))
workload("cBig", "1,000 vertices, points in the bounding box", W.queriesInBox(big, QUICK and 20 or 100))
workload("oOrd", "4-16 vertices, points in the bounding box", queries, true)
local function pairs68(...) return W.pairs(SIZES.pairs, { ... }) end
local mixed = pairs68(W.pairOverlap, W.pairTouch, W.pairMiss)
workload("pMix", "convex 6-8 pairs: 1/3 overlap, 1/3 touch, 1/3 miss", mixed)
workload("pOver", "convex 6-8 pairs: overlapping", pairs68(W.pairOverlap))
workload("pTouch", "convex 6-8 pairs: touching (shared edge, corner or T)", pairs68(W.pairTouch))
workload("pMiss", "convex 6-8 pairs: missing", pairs68(W.pairMiss))
workload("pIn", "convex 6-8 pairs: one inside the other", pairs68(W.pairInside))
workload("pFar", "convex 6-8 pairs, mixed, translated by 1e6",
         { shapes.translateEach(mixed[1], 1e6, -0.6e6), shapes.translateEach(mixed[2], 1e6, -0.6e6) })
workload("ciMix", "4-16 vertices, circles at an edge, a corner, missing, inside",
         W.circles(SIZES.circles, { 1, 2, 3, 4 }))
workload("ciIn", "4-16 vertices, small circle near the middle", W.circles(SIZES.circles, { 4 }))
local segments = W.rays(SIZES.circles, { 1, 2, 3, 4 })
workload("rMix", "convex 4-12, segments: 1/4 through, 1/4 passing by, 1/4 short, 1/4 from inside", segments)
workload("rHit", "convex 4-12, segments through the polygon", W.rays(SIZES.circles, { 1 }))
workload("rMiss", "convex 4-12, segments passing by", W.rays(SIZES.circles, { 2 }))
workload("rFar", "convex 4-12, segments, mixed, translated by 1e6", { shapes.translateEach(segments[1], 1e6,
  -0.6e6), W.shift(segments[2], 1e6), W.shift(segments[3], -0.6e6), W.shift(segments[4], 1e6),
  W.shift(segments[5], -0.6e6) })
workload("rConcave", "stars 8-16 (concave, flat), segments: 1/4 through, 1/4 passing by, 1/4 short, "
  .. "1/4 from near the middle", W.concaveRays(SIZES.circles))
workload("crMix", "discs, segments: 1/4 through, passing, short, from inside", W.circleRays(SIZES.circles))
workload("scMix", "convex 4-8 static, 4-6 moving: 1/4 hit, 1/4 pass by, 1/4 short, 1/4 overlapped",
         W.casts(SIZES.circles))
workload("ccMix", "circles: 1/4 hit, 1/4 pass by, 1/4 short, 1/4 overlapped", W.circleCasts(SIZES.circles))
workload("pccMix", "convex 4-8 static, a circle: 1/4 hit, 1/4 pass by, 1/4 short, 1/4 overlapped",
         W.polygonCircleCasts(SIZES.circles))
workload("npOrd", "4-16 vertices, half convex, points in and around the box", W.nearestQueries(ordinary))
workload("prOrd", "convex 6-8, a vertex and an edge normal", W.projections(mixed[1]))
workload("pcOrd", "random circle, point and axis", W.circleProjections(SIZES.circles))

---------------------------------------------------------------------------------------------
-- Errors against the oracle. An evaluator takes the workload and call(i), which returns what
-- the measured function returns for input i, and gives { text = ..., plus numbers for the plot }.
---------------------------------------------------------------------------------------------
local function refs(wl, key, compute)
  if not wl.refs[key] then
    local list, a = {}, wl.args
    for i = 1, wl.n do list[i] = compute(a[1][i], a[2] and a[2][i], a[3] and a[3][i], a[4] and a[4][i]) end
    wl.refs[key] = list
  end
  return wl.refs[key]
end

local ulpError = exact.ulpsOff

local function countWrong(wl, call, want, field)   -- field: compare want[i][field]
  local wrong = 0
  for i = 1, wl.n do
    local w = want[i]
    if field then w = w[field] end
    if call(i) ~= w then wrong = wrong + 1 end
  end
  return { wrong = wrong, total = wl.n, text = ("wrong %d/%d"):format(wrong, wl.n) }
end

local function ulpSummary(errs, note)
  local mx, md = quantile(errs, 1) or 0, quantile(errs, 0.5) or 0
  return { max = mx, text = ("max %.3g, med %.3g ulp%s"):format(mx, md, note or "") }
end

local function boolOf(f) return function(i) return f(i) and true or false end end

local function circleRef(points, cx, cy, r)
  local depth, ux, uy = oracle.circleDepth(points, cx, cy, r)
  return { depth > 0, depth, { ux * depth, uy * depth } }
end

local function extent(points)   -- the larger side of the bounding box
  local x0, y0, x1, y1 = shapes.bounds(points)
  return max(x1 - x0, y1 - y0)
end

-- Depth and displacement errors are relative to the exact depth, or to 1e-12 of the shapes' size
-- when the depth is smaller (touching to within rounding, where a relative error says nothing).
local function displacementSummary(wl, call, want)
  local wrong, depths, moves = 0, {}, {}
  for i = 1, wl.n do
    local got, dx, dy = call(i)
    local r = want[i]
    if (got and true or false) ~= r[1] then
      wrong = wrong + 1
    elseif got then
      local a = wl.args
      local size = max(extent(a[1][i]), #a == 2 and extent(a[2][i]) or 2 * a[4][i])
      local scale = max(r[2], 1e-12 * size)
      depths[#depths + 1] = abs(got - r[2]) / scale
      local best = huge   -- r[3] lists the displacements of the tied least-depth axes, x then y
      for k = 1, #r[3], 2 do best = math.min(best, sqrt((dx - r[3][k]) ^ 2 + (dy - r[3][k + 1]) ^ 2)) end
      moves[#moves + 1] = best / scale
    end
  end
  local s = { wrong = wrong, total = wl.n, dispMax = quantile(moves, 1) or 0 }
  s.text = ("wrong %d/%d; depth %.1e, disp %.1e (max rel.)"):format(wrong, wl.n, quantile(depths, 1) or 0,
                                                                      s.dispMax)
  return s
end

local evaluate = {
  winding = function(wl, call) return countWrong(wl, call, refs(wl, "winding", oracle.winding)) end,
  type = function(wl, call) return countWrong(wl, call, refs(wl, "type", oracle.polygonType)) end,
  contains = function(wl, call)
    return countWrong(wl, boolOf(call), refs(wl, "contains", oracle.contains))
  end,
  circleV = function(wl, call) return displacementSummary(wl, call, refs(wl, "circle", circleRef)) end,
  valid = function(wl, call) return countWrong(wl, call, refs(wl, "valid", function() return true end)) end,
  none = function() return { text = "-" } end,   -- the projections: the tutorial's own arithmetic
}

-- collide1, collideV1: the axes of the first polygon only; collide2, collideV2: of both
for key, both in pairs({ ["1"] = false, ["2"] = true }) do
  local function push(p, q) return { oracle.push(p, q, both) } end
  evaluate["collide" .. key] = function(wl, f) return countWrong(wl, boolOf(f), refs(wl, key, push), 1) end
  evaluate["collideV" .. key] = function(wl, f) return displacementSummary(wl, f, refs(wl, key, push)) end
end

-- Rays (issue 30): `wrong` counts hit, miss and start-inside answers other than the exact ones
-- (spec/support/rays.lua); `frac` is the largest |f - t| |d| / (eps M) over the hits both agree
-- on (M over the segment's ends), `normal` the largest error of the normal's components in eps,
-- against the nearest of the edges entered.
local function rayError(wl, call, want)
  local wrong, fracs, normals = 0, {}, {}
  local a = wl.args
  for i = 1, wl.n do
    local f, nx, ny = call(i)
    local w = want[i]
    local ax, ay, bx, by = a[#a - 3][i], a[#a - 2][i], a[#a - 1][i], a[#a][i]
    if w == nil or w == "inside" then
      if (w == nil and f ~= false) or (w == "inside" and not (f == 0 and nx == 0 and ny == 0)) then
        wrong = wrong + 1
      end
    elseif type(f) ~= "number" then
      wrong = wrong + 1
    else
      local M = max(abs(ax), abs(ay), abs(bx), abs(by))
      local dx, dy = exact.sub(exact.new(bx), exact.new(ax)), exact.sub(exact.new(by), exact.new(ay))
      local gap = exact.sub(exact.mul(exact.new(f), w.den), w.num)
      local length = sqrt(exact.tonumber(exact.add(exact.mul(dx, dx), exact.mul(dy, dy))))
      fracs[#fracs + 1] = abs(exact.tonumber(gap) / exact.tonumber(w.den)) * length / (2 ^ -53 * M)
      local best = huge
      for _, m in ipairs(w.normals) do best = math.min(best, max(abs(nx - m[1]), abs(ny - m[2]))) end
      normals[#normals + 1] = best / 2 ^ -53
    end
  end
  return { wrong = wrong, total = wl.n, text = ("wrong %d/%d; frac %.2g eps M, normal %.2g eps (max)")
    :format(wrong, wl.n, quantile(fracs, 1) or 0, quantile(normals, 1) or 0) }
end

-- ray: convex polygons, by rays.convexEntry; rayRings: any simple flat polygon (rConcave's
-- stars), by rays.ringsEntry over its one ring (even-odd, as polygonContains)
local function rayEvaluator(key, entry)
  return function(wl, call)
    if not wl.refs[key] then   -- (refs passes four columns; a segment takes five)
      local a, list = wl.args, {}
      for i = 1, wl.n do list[i] = entry(a[1][i], a[2][i], a[3][i], a[4][i], a[5][i]) or false end
      wl.refs[key] = list
    end
    local want = {}
    for i = 1, wl.n do want[i] = wl.refs[key][i] or nil end
    return rayError(wl, call, want)
  end
end
evaluate.ray = rayEvaluator("ray", rays.convexEntry)
evaluate.rayRings = rayEvaluator("rayRings", function(p, ...) return rays.ringsEntry({ p }, ...) end)

-- discs: `wrong` counts hit, miss and start-inside answers other than the exact ones, and
-- entries whose fraction is beyond 8 eps M or whose normal is beyond 16 eps of exact
-- (spec/support/rays.lua's discEntryGood)
function evaluate.circleRay(wl, call)
  local a, wrong = wl.args, 0
  for i = 1, wl.n do
    local cx, cy, r, ax, ay, bx, by = a[1][i], a[2][i], a[3][i], a[4][i], a[5][i], a[6][i], a[7][i]
    local meets = rays.discMeets(cx, cy, r, ax, ay, bx, by)
    local f, nx, ny = call(i)
    if meets == nil then
      if f ~= false then wrong = wrong + 1 end
    elseif meets == "inside" then
      if not (f == 0 and nx == 0 and ny == 0) then wrong = wrong + 1 end
    elseif type(f) ~= "number" or not rays.discEntryGood(f, nx, ny, cx, cy, r, ax, ay, bx, by) then
      wrong = wrong + 1
    end
  end
  return { wrong = wrong, total = wl.n,
    text = ("wrong %d/%d (beyond 8 eps M or 16 eps)"):format(wrong, wl.n) }
end

-- The casts' tally: `wrong` of n answers (a miss or hit other than the oracle's, or a hit whose
-- moved shape collides or whose fraction is beyond 8 eps M of the exact contact).
local function castTally(wrong, n)
  return { wrong = wrong, total = n,
    text = ("wrong %d/%d (colliding after the move, or beyond 8 eps M)"):format(wrong, n) }
end

-- casts: `wrong` counts hit, miss and overlapped answers other than the exact ones
-- (spec/support/sweeps.lua), and hits whose fraction leaves the moved polygon colliding or is
-- beyond 8 eps M / |d| of the exact contact time
function evaluate.cast(wl, call)
  local a, wrong = wl.args, 0
  local collide = require("polygon").polygonsCollide
  for i = 1, wl.n do
    local p1, p2, dx, dy = a[1][i], a[2][i], a[3][i], a[4][i]
    local contact = sweeps.convexContact(p1, p2, dx, dy)
    local f = call(i)
    if contact == nil then
      if f ~= false then wrong = wrong + 1 end
    elseif contact == "inside" then
      if f ~= 0 then wrong = wrong + 1 end
    else
      local M = 0
      for _, v in ipairs(p1) do M = max(M, abs(v)) end
      for k = 1, #p2, 2 do M = max(M, abs(p2[k]), abs(p2[k + 1]), abs(p2[k] + dx), abs(p2[k + 1] + dy)) end
      if type(f) ~= "number" or collide(p1, sweeps.moveBy(p2, f, dx, dy))
          or not sweeps.fractionNear(f, contact, dx, dy, M) then
        wrong = wrong + 1
      end
    end
  end
  return castTally(wrong, wl.n)
end

function evaluate.circleCast(wl, call)
  local a, wrong = wl.args, 0
  local collide = require("polygon").circlesCollideV
  for i = 1, wl.n do
    local x1, y1, r1, x2, y2, r2 = a[1][i], a[2][i], a[3][i], a[4][i], a[5][i], a[6][i]
    local dx, dy = a[7][i], a[8][i]
    local contact = sweeps.discContact(x1, y1, r1, x2, y2, r2, dx, dy)
    local f = call(i)
    if contact == nil then
      if f ~= false then wrong = wrong + 1 end
    elseif contact == "inside" then
      if f ~= 0 then wrong = wrong + 1 end
    else
      local M = max(abs(x1), abs(y1), abs(x2), abs(y2), abs(x2 + dx), abs(y2 + dy))
      local b = 8 * 2 ^ -53 * M / sqrt(dx * dx + dy * dy) * (1 - 2 ^ -30)
      if type(f) ~= "number" or collide(x1, y1, r1, x2 + f * dx, y2 + f * dy, r2)
          or not sweeps.discFractionNear(f, b, x1, y1, r1, x2, y2, r2, dx, dy) then
        wrong = wrong + 1
      end
    end
  end
  return castTally(wrong, wl.n)
end

-- a circle against a polygon: `wrong` counts hit, miss and overlapped answers other than
-- sweeps.discReach's, and hits whose moved circle collides or whose fraction is more than
-- 8 eps M / |d| before the exact contact
function evaluate.polygonCircleCast(wl, call)
  local a, wrong = wl.args, 0
  local collide = require("polygon").polygonCircleCollideV
  for i = 1, wl.n do
    local p, cx, cy, r, dx, dy = a[1][i], a[2][i], a[3][i], a[4][i], a[5][i], a[6][i]
    local f = call(i)
    if sweeps.discReach(p, cx, cy, r, dx, dy, 0) then
      if f ~= 0 then wrong = wrong + 1 end
    elseif not sweeps.discReach(p, cx, cy, r, dx, dy, 1) then
      if f ~= false then wrong = wrong + 1 end
    else
      local M = max(abs(cx), abs(cy), abs(cx + dx), abs(cy + dy))
      for _, v in ipairs(p) do M = max(M, abs(v)) end
      local b = 8 * 2 ^ -53 * M / sqrt(dx * dx + dy * dy) * (1 - 2 ^ -30)
      if type(f) ~= "number" or collide(p, cx + f * dx, cy + f * dy, r)
          or not sweeps.discReach(p, cx, cy, r, dx, dy, f, b) then
        wrong = wrong + 1
      end
    end
  end
  return castTally(wrong, wl.n)
end

-- nearest points: `wrong` counts answers nearest.check refuses (sign, distance or point beyond
-- 8 eps M of exact)
function evaluate.nearest(wl, call)
  local wrong, a = 0, wl.args
  for i = 1, wl.n do
    local px, py, d = call(i)
    if not nearest.check(a[1][i], a[2][i], a[3][i], px, py, d) then wrong = wrong + 1 end
  end
  return { wrong = wrong, total = wl.n, text = ("wrong %d/%d"):format(wrong, wl.n) }
end

function evaluate.area(wl, call)
  local want, errs = refs(wl, "area", oracle.area), {}
  for i = 1, wl.n do errs[i] = ulpError(want[i], call(i)) end
  return ulpSummary(errs)
end

-- The centre and the centroid against the oracle's, which are rounded once or twice from exact
-- sums: errors below an ulp or two are the reference's own.
local function pointError(ref)
  return function(wl, call)
    local want, errs, nils = refs(wl, ref, function(p) return { oracle[ref](p) } end), {}, 0
    for i = 1, wl.n do
      local x, y = call(i)
      if (x == nil) ~= (want[i][1] == nil) then
        nils = nils + 1
      elseif x then
        errs[#errs + 1] = max(ulpError(exact.new(want[i][1]), x), ulpError(exact.new(want[i][2]), y))
      end
    end
    return ulpSummary(errs, nils > 0 and (", %d nil wrong"):format(nils) or "")
  end
end
evaluate.center, evaluate.centroid = pointError("center"), pointError("centroid")

---------------------------------------------------------------------------------------------
-- Rows: function, workload, fold, evaluator; `base` names a polygon.lua function to time
-- against instead of the tutorial's (polygonAreaAccurate against polygonArea).
---------------------------------------------------------------------------------------------
local ROWS = {}
local function row(fname, key, fold, kind, base)
  if WL[key] then ROWS[#ROWS + 1] = { fname = fname, wl = WL[key], fold = fold, kind = kind, base = base } end
end
local MEASURED = { "ord", "far9", "degen", "big", "huge" }
for _, k in ipairs(MEASURED) do row("polygonWindingOrder", k, "str", "winding") end
for _, k in ipairs(MEASURED) do row("polygonArea", k, "num", "area") end
for _, k in ipairs(MEASURED) do row("polygonAreaAccurate", k, "num", "area", "polygonArea") end
for _, k in ipairs(MEASURED) do row("polygonType", k, "str", "type") end
for _, k in ipairs(MEASURED) do row("polygonCenter", k, "num2", "center") end
for _, k in ipairs(MEASURED) do row("polygonCentroid", k, "num2", "centroid") end
for _, k in ipairs({ "cOrd", "cEdge", "cTiles", "cBig" }) do row("polygonContains", k, "bool", "contains") end
row("Polygon:contains", "oOrd", "bool", "contains")
for _, f in ipairs({ { "polygonCollidesWith", "bool", "collide1" }, { "polygonsCollide", "bool", "collide2" },
                     { "polygonCollidesWithV", "v3", "collideV1" },
                     { "polygonsCollideV", "v3", "collideV2" } }) do
  for _, k in ipairs({ "pMix", "pOver", "pTouch", "pMiss", "pIn", "pFar" }) do row(f[1], k, f[2], f[3]) end
end
row("projectPolygon", "prOrd", "num2", "none")
row("polygonCircleCollideV", "ciMix", "v3", "circleV")
row("polygonCircleCollideV", "ciIn", "v3", "circleV")
row("projectCircle", "pcOrd", "num2", "none")
row("validate", "ord", "bool", "valid", "validate")
for _, k in ipairs({ "rMix", "rHit", "rMiss", "rFar" }) do row("polygonRayCast", k, "v3", "ray") end
row("polygonRayCast", "rConcave", "v3", "rayRings")   -- any flat polygon (no target)
row("circleRayCast", "crMix", "v3", "circleRay")
row("polygonClosestPoint", "npOrd", "v3", "nearest")
row("polygonsCast", "scMix", "v3", "cast")
row("circlesCast", "ccMix", "v3", "circleCast")
row("polygonCircleCast", "pccMix", "v3", "polygonCircleCast")
-- the convexity check's cost (issue 29): each collision row against the same function without it
for _, f in ipairs({ { "polygonCollidesWith", "bool", "collide1" }, { "polygonsCollide", "bool", "collide2" },
                     { "polygonCollidesWithV", "v3", "collideV1" },
                     { "polygonsCollideV", "v3", "collideV2" } }) do
  row(f[1], "pMix", f[2], f[3], "unchecked " .. f[1])
end
row("polygonCircleCollideV", "ciMix", "v3", "circleV", "unchecked polygonCircleCollideV")

-- function, workload, LuaJIT target, Lua 5.4 target (ratio of the medians at most); a workload
-- "KEY@unchecked" is the row against the same function without the convexity check (issue 29:
-- the check costs at most 15%)
local TARGETS = {
  { "polygonsCollideV", "pMix", 0.25, 0.45 },
  { "polygonCircleCollideV", "ciMix", 0.35, 0.9 },
  { "polygonContains", "cOrd", 0.8, 0.9 },
  { "polygonArea", "ord", 1.0, 1.1 },
  { "polygonWindingOrder", "ord", 1.1, 1.3 },
  { "polygonType", "ord", 1.25, 1.5 },
  { "polygonAreaAccurate", "ord", 3, 3 },
  { "polygonAreaAccurate", "far9", 3, 3 },
  { "polygonAreaAccurate", "big", 3, 3 },
  { "polygonRayCast", "rMix", 1.5, 2 },
  { "polygonCollidesWith", "pMix@unchecked", 1.15, 1.15 },
  { "polygonsCollide", "pMix@unchecked", 1.15, 1.15 },
  { "polygonCollidesWithV", "pMix@unchecked", 1.15, 1.15 },
  { "polygonsCollideV", "pMix@unchecked", 1.15, 1.15 },
  { "polygonCircleCollideV", "ciMix@unchecked", 1.15, 1.15 },
}

---------------------------------------------------------------------------------------------
-- Measuring
---------------------------------------------------------------------------------------------
-- The function (or, for the class, the method's objects) of one side, and call(i) passing exactly
-- the arguments the kernel passes.
local function sideOf(lib, fname, wl)
  local a = wl.args
  if fname == "Polygon:contains" then
    if type(lib.Polygon) ~= "table" then return nil end
    local objects = {}
    for i = 1, wl.n do objects[i] = lib.Polygon.new(a[1][i]) end
    local args = { objects, a[2], a[3] }
    return { args = args, call = function(i) return objects[i]:contains(a[2][i], a[3][i]) end }
  end
  local f = lib[fname]
  -- "unchecked NAME": NAME without the convexity check (polygon/collide.lua's M.unchecked)
  local uncheckedName = fname:match("^unchecked (.+)$")
  if uncheckedName then f = require("polygon.collide").unchecked[uncheckedName] end
  if type(f) ~= "function" then return nil end
  return { f = f, args = a, call = function(i)
    local values = {}
    for c = 1, #a do values[c] = a[c][i] end
    return f(unpack(values, 1, #a))
  end }
end

local failures, checksum = {}, { 0, 0 }

-- Both sides of a row, freshly loaded: polygon.lua's function and its reference.
local function sides(r)
  local lib = loadFresh("polygon")
  local ref = r.base and lib or loadFresh("bench.baseline")
  local s = { sideOf(lib, r.fname, r.wl), sideOf(ref, r.base or r.fname, r.wl) }
  for _, v in ipairs(s) do v.kernel = makeKernel(r.wl, r.fold, v.f, v.args) end
  return s
end

local isTarget = {}
for _, t in ipairs(TARGETS) do isTarget[t[1] .. "@" .. t[2]] = true end
-- a row's key; the rows against an unchecked variant (the convexity check's cost) have their own
local function isUnchecked(r) return r.base and r.base:match("^unchecked ") ~= nil end
local function rowKey(r)
  return r.fname .. "@" .. r.wl.key .. (isUnchecked(r) and "@unchecked" or "")
end
-- what --only matches: "FUNCTION WORKLOAD", "unchecked FUNCTION WORKLOAD" for those rows
local function rowName(r)
  return (isUnchecked(r) and "unchecked " or "") .. r.fname .. " " .. r.wl.key
end

-- The per-round ratios of one row timed in a fresh process (a new draw of LuaJIT's traces), and
-- each side's per-round times (ns a call).
local function drawRatios(r)
  local command = ("%s bench/run.lua --ratios --only '^%s$'"):format(INTERPRETER_PATH, rowName(r))
  local pipe = assert(io.popen(command, "r"))
  local text = pipe:read("*a")
  pipe:close()
  local lists = {}
  for k, name in ipairs({ "RATIOS", "MODULE", "REFERENCE" }) do
    local list = text:match(name .. " %S+ %S+ ([^\n]*)")
    if not list then error(("no %s from `%s`: %s"):format(name, command, text)) end
    lists[k] = {}
    for v in list:gmatch("%S+") do lists[k][#lists[k] + 1] = tonumber(v) end
  end
  return lists[1], lists[2], lists[3]
end

local function measureRow(r)
  local wl = r.wl
  r.missing = not sideOf(loadFresh("polygon"), r.fname, wl)
  if r.missing then failures[#failures + 1] = r.fname .. " is missing from polygon.lua"; return end
  collectgarbage("collect")
  if jit then jit.flush() end
  local s = sides(r)
  -- calibrated twice: the first pass pays for compiling traces (LuaJIT) and would leave too few
  local reps = {}
  for k = 1, 2 do calibrate(s[k].kernel, wl.n); reps[k] = calibrate(s[k].kernel, wl.n) end
  -- sides of similar speed run the same number of passes (unequal counts drifted by up to 20%
  -- on LuaJIT in an A/A test, equal ones by about 4%)
  if reps[1] <= 4 * reps[2] and reps[2] <= 4 * reps[1] then
    reps[1] = max(reps[1], reps[2]); reps[2] = reps[1]
  end
  local ns, ratios = { {}, {} }, {}
  for round = 1, ROUNDS do
    local t = {}
    for j = 1, 2 do
      local k = (round + j) % 2 + 1                           -- module first in odd rounds
      local seconds, acc = timeKernel(s[k].kernel, wl.n, reps[k])
      t[k] = seconds / (wl.n * reps[k]) * 1e9
      if acc ~= acc then failures[#failures + 1] = ("%s on %s: checksum is NaN"):format(r.fname, wl.key) end
      checksum[k] = checksum[k] + acc
      ns[k][round] = t[k]
    end
    ratios[round] = t[1] / t[2]
  end
  if opts.ratios then
    print(("RATIOS %s %s %s"):format(r.fname, wl.key, table.concat(ratios, " ")))
    print(("MODULE %s %s %s"):format(r.fname, wl.key, table.concat(ns[1], " ")))
    print(("REFERENCE %s %s %s"):format(r.fname, wl.key, table.concat(ns[2], " ")))
    return
  end
  r.drawLow, r.drawHigh = quantile(ratios, 0.5), quantile(ratios, 0.5)
  if TARGET_COLUMN and DRAWS > 1 and isTarget[rowKey(r)] then
    r.draws = DRAWS
    for _ = 2, DRAWS do
      local own, moduleNs, referenceNs = drawRatios(r)
      for _, v in ipairs(moduleNs) do ns[1][#ns[1] + 1] = v end
      for _, v in ipairs(referenceNs) do ns[2][#ns[2] + 1] = v end
      local m = quantile(own, 0.5)
      r.drawLow, r.drawHigh = math.min(r.drawLow, m), max(r.drawHigh, m)
      for _, v in ipairs(own) do ratios[#ratios + 1] = v end
    end
  end
  r.ratio, r.low, r.high = quantile(ratios, 0.5), quantile(ratios, 0.25), quantile(ratios, 0.75)
  r.min, r.max = quantile(ratios, 0), quantile(ratios, 1)
  for k = 1, 2 do
    local v = s[k]
    v.ns = quantile(ns[k], 0.5)
    -- a trace compiled during a count allocates once: keep the least of three counts
    local greps = math.min(reps[k], math.ceil(2000 / wl.n))
    v.bytes = huge
    for _ = 1, 3 do v.bytes = math.min(v.bytes, garbagePerCall(v.kernel, wl.n, greps)) end
    v.err = evaluate[r.kind](wl, v.call)
  end
  r.module, r.reference = s[1], s[2]
end

local rowsRun, byKey = {}, {}
for _, r in ipairs(ROWS) do
  if (not opts.only or rowName(r):find(opts.only))
      and (not opts.targets or isTarget[rowKey(r)]) then
    local ok, err = pcall(measureRow, r)
    if not ok then
      r.error = tostring(err)
      failures[#failures + 1] = ("%s on %s raised: %s"):format(r.fname, r.wl.key, r.error)
    end
    rowsRun[#rowsRun + 1] = r
    byKey[rowKey(r)] = r
  end
end
if opts.ratios then
  if #failures > 0 then io.stderr:write(table.concat(failures, "\n"), "\n"); os.exit(1) end
  os.exit(0)
end
if checksum[1] ~= checksum[1] or checksum[2] ~= checksum[2] then
  failures[#failures + 1] = "total checksum is NaN"
end

---------------------------------------------------------------------------------------------
-- Reporting
---------------------------------------------------------------------------------------------
local out = {}
local function emit(s) out[#out + 1] = s end
local function ns(x)
  if x >= 1e6 then return ("%.2f ms"):format(x / 1e6) end
  if x >= 1e4 then return ("%.1f us"):format(x / 1e3) end
  return ("%.0f ns"):format(x)
end
local function bytes(x) return x < 0.05 and "0" or ("%.1f"):format(x) end
local function spread(r) return ("%.2f-%.2f"):format(r.low, r.high) end
local function against(r) return r.base and (" (against polygon.lua's %s)"):format(r.base) or "" end

local title = ("%s, %s"):format(interpreter, cpuName())
emit(("## %s\n"):format(title))
emit(("Command: `%s bench/run.lua%s` (part of `make bench`), %s. %d rounds per row, each pass at " ..
      "least %g ms; ratio = polygon.lua's time / the reference's time in the same round (the " ..
      "tutorial's formulas unless the row says otherwise), median and interquartile range over " ..
      "the rounds.%s")
     :format(opts.label or interpreter, QUICK and " --quick" or "", os.date("!%Y-%m-%d"), ROUNDS,
             TARGET_SECONDS * 1000, QUICK and " QUICK MODE: small inputs, the numbers mean nothing." or ""))
emit("\n### Targets\n")
emit(("Each row with a target is timed in %d process%s (%d rounds each; see the header of " ..
      "bench/run.lua): the median, IQR and min-max (and the times in \"All rows\") are over all " ..
      "their rounds, and \"process " ..
      "medians\" gives the least and the largest of the processes' own medians.\n")
     :format(DRAWS, DRAWS == 1 and "" or "es", ROUNDS))
emit("| function | workload | median ratio | IQR | min-max | process medians | target | met " ..
     "| polygon.lua B/call |")
emit("|---|---|---:|---:|---:|---:|---:|---|---:|")
for _, t in ipairs(TARGETS) do
  local r = byKey[t[1] .. "@" .. t[2]]
  if r and r.ratio then
    local goal = TARGET_COLUMN and t[TARGET_COLUMN]
    emit(("| `%s` | %s%s | %.2f | %s | %.2f-%.2f | %.2f-%.2f (%d) | %s | %s | %s |"):format(t[1], r.wl.name,
      against(r), r.ratio, spread(r), r.min, r.max, r.drawLow, r.drawHigh, r.draws or 1,
      goal and ("%.2f"):format(goal) or "-",
      goal and (r.ratio <= goal and "met" or "**not met**") or "-", bytes(r.module.bytes)))
  end
end
emit("\n### All rows\n")
emit("Errors are against exact answers (spec/support/oracle.lua): `wrong k/N` counts answers that " ..
     "differ from exact real arithmetic on the input doubles; `ulp` is |result - exact| in units in " ..
     "the last place of the exact value; `depth`, `disp` are the largest relative errors of the " ..
     "overlap and of (dx, dy) where both say the shapes collide (relative to the exact depth, or " ..
     "to 1e-12 of the shapes' size when the depth is smaller).\n")
emit("| function | workload | N | polygon.lua | reference | ratio | IQR | B/call | polygon.lua error " ..
     "| reference error |")
emit("|---|---|---:|---:|---:|---:|---:|---:|---|---|")
for _, r in ipairs(rowsRun) do
  if r.error or r.missing then
    emit(("| `%s` | %s | %d | %s | | | | | | |"):format(r.fname, r.wl.name, r.wl.n,
      r.missing and "missing" or "ERROR: " .. r.error:gsub("[|\n]", " ")))
  else
    local m, b = r.module, r.reference
    emit(("| `%s` | %s%s | %d | %s | %s | %.2f | %s | %s / %s | %s | %s |"):format(r.fname, r.wl.name,
      against(r), r.wl.n, ns(m.ns), ns(b.ns), r.ratio, spread(r), bytes(m.bytes), bytes(b.bytes), m.err.text,
      b.err.text))
  end
end
emit(("\nChecksum of every timed result: polygon.lua %.17g, reference %.17g. Run time %.0f s (CPU).\n")
  :format(checksum[1], checksum[2], clock() - started))
if #failures > 0 then emit("FAILURES:\n- " .. table.concat(failures, "\n- ") .. "\n") end

local text = table.concat(out, "\n")
print(text)
if opts.out then
  local f = assert(io.open(opts.out, "w"))
  f:write(text, "\n"); f:close()
end

-- bench/plot.gp's points: 3 panels, each a polygon.lua then a reference block of "ns error label
-- place"; errors of 0 are drawn at the panel's floor.
if opts.data then
  local panels = {   -- floor, error field, then "function workload label" per point
    { 0.01, "max", "polygonArea far9 area", "polygonAreaAccurate far9 areaAccurate",
      "polygonCenter far9 center", "polygonCentroid far9 centroid" },
    { 0.01, "wrong", "polygonWindingOrder degen winding", "polygonType degen type",
      "polygonContains cEdge contains", "polygonsCollide pTouch collide" },
    { 1e-17, "dispMax", "polygonsCollideV pMix collideV", "polygonCollidesWithV pMix collidesWithV",
      "polygonCircleCollideV ciMix circleV", "polygonsCollideV pIn collideV-inside" },
  }
  local f = assert(io.open(opts.data, "w"))
  f:write(("# %s: time per call (ns) against error; panels: max ulp (polygons at 1e9), " ..
           "wrong %% (near-degenerate), max relative displacement error\n"):format(title))
  for p, panel in ipairs(panels) do
    for side, name in ipairs({ "module", "reference" }) do
      f:write(("# panel %d %s\n"):format(p, name))
      for k = 3, #panel do
        local fname, key, label = panel[k]:match("(%S+) (%S+) (%S+)")
        local r = byKey[fname .. "@" .. key]
        if r and r.module and not (side == 2 and r.base) then
          local e = side == 1 and r.module.err or r.reference.err
          local value = e[panel[2]] or 0
          if panel[2] == "wrong" then value = 100 * value / e.total end
          f:write(("%.6g %.6g \"%s\" %d\n"):format(side == 1 and r.module.ns or r.reference.ns,
            math.min(max(value, panel[1]), 1e300), label, k - 3))
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
