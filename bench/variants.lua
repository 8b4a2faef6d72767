-- bench/variants.lua: where polygon.lua's time goes, by timing it beside rewritten variants.
--
-- Run from the repository root:  luajit bench/variants.lua   (or lua5.4 bench/variants.lua)
-- Not part of `make bench`: a diagnostic for whoever optimises polygon.lua. Each variant is
-- checked against bench/exact.lua on the same inputs (wrong answers are printed beside its time),
-- so a variant that buys speed with exactness shows it.
package.path = "./?.lua;" .. package.path
local exact = require "bench.exact"
local W = require "bench.workloads"
local polygon = require "polygon"
local baseline = require "bench.baseline"

local abs, sqrt, huge = math.abs, math.sqrt, math.huge
local clock = os.clock
local loadstring = rawget(_G, "loadstring") or load
local jit = rawget(_G, "jit")

local EPS = 2 ^ -53
local CROSS_BOUND = (3 + 16 * EPS) * EPS

---------------------------------------------------------------------------------------------
-- polygonType variants (same answers as polygon.lua's, the exact fallback from bench/exact.lua)
---------------------------------------------------------------------------------------------
-- "carry": the edge vector of one step is the incoming edge of the next (two subtractions
-- per vertex fewer), a repeated vertex is a zero edge vector, the filter as polygon.lua's.
local function makeType(flips, filter)
  return function(points)
    local n = #points
    if n < 6 then return nil end
    local cx, cy = points[n - 1], points[n]
    local j = n - 3
    while j > 0 and points[j] == cx and points[j + 1] == cy do j = j - 2 end
    if j < 0 then return nil end
    local px, py = points[j], points[j + 1]
    local ux, uy = cx - px, cy - py
    local turn, spike, changes, dir = 0, false, 0, 0
    for i = 1, n - 1, 2 do
      local qx, qy = points[i], points[i + 1]
      local vx, vy = qx - cx, qy - cy
      if vx ~= 0 or vy ~= 0 then
        local l, r = ux * vy, uy * vx
        local s = l - r
        if filter then
          local e = l + r
          if e < 0 then e = -e end
          e = CROSS_BOUND * e
          if s < e and -s < e then s = exact.orient(px, py, cx, cy, qx, qy) end
        end
        if s > 0 then
          if turn < 0 then return "concave" end
          turn = 1
        elseif s < 0 then
          if turn > 0 then return "concave" end
          turn = -1
        elseif ux ~= 0 then
          if (ux > 0) ~= (vx > 0) then spike = true end
        elseif (uy > 0) ~= (vy > 0) then
          spike = true
        end
        if flips then
          if vx > 0 then
            if dir < 0 then changes = changes + 1 end
            dir = 1
          elseif vx < 0 then
            if dir > 0 then changes = changes + 1 end
            dir = -1
          end
        end
        px, py, cx, cy, ux, uy = cx, cy, qx, qy, vx, vy
      end
    end
    if turn == 0 then return nil end
    if spike or changes > 2 then return "concave" end
    return "convex"
  end
end

-- "two passes": a first pass without data-dependent branches (LuaJIT compiles math.min, max
-- and abs to single instructions) finds the least and greatest turn and whether every turn
-- passed the filter; mixed certain signs are concave at once. Otherwise, or to rule out
-- a polygon winding twice, the careful loop above runs.
local careful = makeType(true, true)
local mmin, mmax = math.min, math.max
local function typeTwoPass(points)
  local n = #points
  if n < 6 then return nil end
  local cx, cy = points[n - 1], points[n]
  local ux, uy = cx - points[n - 3], cy - points[n - 2]
  local lo, hi, margin = huge, -huge, huge
  for i = 1, n - 1, 2 do
    local qx, qy = points[i], points[i + 1]
    local vx, vy = qx - cx, qy - cy
    local l, r = ux * vy, uy * vx
    local s = l - r
    lo, hi = mmin(lo, s), mmax(hi, s)
    margin = mmin(margin, abs(s) - CROSS_BOUND * abs(l + r))
    cx, cy, ux, uy = qx, qy, vx, vy
  end
  if margin > 0 and lo < 0 and hi > 0 then return "concave" end
  return careful(points)
end

-- "one branch": like the tutorial, one comparison decides the common vertex: the turn agrees
-- with the first one and clears the filter (t * s > bound). Everything else (the first turn,
-- a concave turn, a zero or uncertain turn, a repeated vertex) leaves the fast loop: a certain
-- opposite turn returns "concave", the rest hands over to the careful loop. The x direction
-- changes are counted with one comparison per vertex (x going down after going up).
-- LuaJIT compiles math.abs to one instruction; the PUC interpreters would call a function
local fabs = jit and math.abs or function(v) if v < 0 then return -v end return v end
local function typeOneBranch(points)
  local n = #points
  if n < 6 then return nil end
  local cx, cy = points[n - 1], points[n]
  local ux, uy = cx - points[n - 3], cy - points[n - 2]
  local t, down, peaks = 0, ux < 0, 0
  for i = 1, n - 1, 2 do
    local qx, qy = points[i], points[i + 1]
    local vx, vy = qx - cx, qy - cy
    local l, r = ux * vy, uy * vx
    local s = l - r
    local e = CROSS_BOUND * fabs(l + r)
    if t * s <= e then
      if t == 0 and (s > e or -s > e) then
        t = s > 0 and 1 or -1
      elseif t ~= 0 and -t * s > e then
        return "concave"
      else
        return careful(points)
      end
    end
    if (vx < 0) ~= down then          -- x direction changed (vx == 0 keeps "up")
      down = not down
      peaks = peaks + 1
    end
    cx, cy, ux, uy = qx, qy, vx, vy
  end
  if peaks > 2 then return careful(points) end
  return "convex"
end

-- "peeled": as "one branch", with the first turn found before the loop so that the loop body
-- is the same for every vertex (on LuaJIT the first vertex otherwise leaves the trace on
-- every call).
local function typePeeled(points)
  local n = #points
  if n < 6 then return nil end
  local ax, ay = points[n - 3], points[n - 2]
  local cx, cy = points[n - 1], points[n]
  local qx, qy = points[1], points[2]
  local ux, uy = cx - ax, cy - ay
  local vx, vy = qx - cx, qy - cy
  local l, r = ux * vy, uy * vx
  local s = l - r
  local e = CROSS_BOUND * fabs(l + r)
  if not (s > e or -s > e) then return careful(points) end
  local t = s > 0 and 1 or -1
  local down, peaks = vx < 0, (ux < 0) ~= (vx < 0) and 1 or 0
  cx, cy, ux, uy = qx, qy, vx, vy
  for i = 3, n - 1, 2 do
    qx, qy = points[i], points[i + 1]
    vx, vy = qx - cx, qy - cy
    l, r = ux * vy, uy * vx
    s = l - r
    e = CROSS_BOUND * fabs(l + r)
    if t * s <= e then
      if -t * s > e then return "concave" end
      return careful(points)
    end
    if (vx < 0) ~= down then
      down = not down
      peaks = peaks + 1
    end
    cx, cy, ux, uy = qx, qy, vx, vy
  end
  if peaks > 2 then return careful(points) end
  return "convex"
end

---------------------------------------------------------------------------------------------
-- Parts of a call, to see what the set-up costs
---------------------------------------------------------------------------------------------
local winding = polygon.polygonWindingOrder
local function twoWindings(p1, p2) return winding(p1) and winding(p2) and 1 end

---------------------------------------------------------------------------------------------
-- Timing: fresh kernels, several epochs (LuaJIT traces flushed), equal pass counts, median.
---------------------------------------------------------------------------------------------
local TEMPLATE = [[
local f, A, B, C, D = ...
return function(n, reps)
  local acc = 0
  for _ = 1, reps do
    for i = 1, n do
      local a, b, c = f(A[i], B and B[i], C and C[i], D and D[i])
      if a then acc = acc + (a == true and 1 or type(a) == "string" and #a or a) end
      if b and type(b) == "number" then acc = acc + b end
      if c then acc = acc + c end
    end
  end
  return acc
end
]]

local function timeAll(fs, args, n)
  local kernels, times = {}, {}
  local reps = 1
  for name, f in pairs(fs) do
    local k = assert(loadstring(TEMPLATE, "=variant"))(f, args[1], args[2], args[3], args[4])
    local t0 = clock(); k(n, 1); local t = clock() - t0
    local r = math.ceil(0.004 / math.max(t, 1e-7))
    if r > reps then reps = r end
    kernels[name], times[name] = k, {}
  end
  for _ = 1, jit and 5 or 1 do
    if jit then jit.flush() end
    for name, f in pairs(fs) do
      kernels[name] = assert(loadstring(TEMPLATE, "=variant"))(f, args[1], args[2], args[3], args[4])
      kernels[name](n, reps)
    end
    for _ = 1, 3 do
      for name in pairs(fs) do
        local t0 = clock()
        local acc = kernels[name](n, reps)
        local t = clock() - t0
        assert(acc == acc, name .. ": NaN checksum")
        local list = times[name]
        list[#list + 1] = t / (n * reps) * 1e9
      end
    end
  end
  local out = {}
  for name, list in pairs(times) do
    table.sort(list)
    out[name] = list[math.floor((#list + 1) / 2)]
  end
  return out
end

local function report(title, fs, args, n, order, check)
  local t = timeAll(fs, args, n)
  print(("\n%s (N = %d)"):format(title, n))
  print("| variant | ns/call | / polygon.lua | check |")
  print("|---|---:|---:|---|")
  for _, name in ipairs(order) do
    print(("| %s | %.0f | %.2f | %s |"):format(name, t[name], t[name] / t["polygon.lua"],
      check and check(fs[name]) or ""))
  end
end

local interpreter = jit and jit.version or _VERSION
print("# Variants, " .. interpreter)

local ordinary = W.ordinary(200)
local typeRefs = {}
for i, p in ipairs(ordinary) do typeRefs[i] = exact.polygonType(p) end
local function typeCheck(f)
  local wrong = 0
  for i, p in ipairs(ordinary) do if f(p) ~= typeRefs[i] then wrong = wrong + 1 end end
  return ("wrong %d/%d"):format(wrong, #ordinary)
end
report("polygonType, 4-16 vertices near origin", {
  ["polygon.lua"] = polygon.polygonType,
  ["baseline"] = baseline.polygonType,
  ["carry (exact)"] = makeType(true, true),
  ["carry, no x-flip count (pentagrams pass)"] = makeType(false, true),
  ["carry, no filter (float signs)"] = makeType(true, false),
  ["two passes (branch-free first)"] = typeTwoPass,
  ["one branch per vertex (exact)"] = typeOneBranch,
  ["one branch, first turn peeled (exact)"] = typePeeled,
  ["polygonWindingOrder (one pass, for scale)"] = polygon.polygonWindingOrder,
}, { ordinary }, #ordinary, { "polygon.lua", "baseline", "carry (exact)",
  "carry, no x-flip count (pentagrams pass)", "carry, no filter (float signs)",
  "two passes (branch-free first)", "one branch per vertex (exact)",
  "one branch, first turn peeled (exact)", "polygonWindingOrder (one pass, for scale)" }, typeCheck)

local circles = W.circles(300, { 1, 2, 3, 4 })
local function circleCheck(f)
  if f == winding then return "" end
  local worst, differ = 0, 0
  for i = 1, #circles[1] do
    local a, ax, ay = f(circles[1][i], circles[2][i], circles[3][i], circles[4][i])
    local b, bx, by = polygon.polygonCircleCollideV(circles[1][i], circles[2][i], circles[3][i],
                                                     circles[4][i])
    if (a and true or false) ~= (b and true or false) then
      differ = differ + 1
    elseif a then
      local e = sqrt((ax - bx) ^ 2 + (ay - by) ^ 2) / b
      if e > worst then worst = e end
    end
  end
  return ("differs from polygon.lua: %d/%d, max rel. disp. difference %.1e"):format(differ,
    #circles[1], worst)
end
report("polygonCircleCollideV, circles: edge, corner, miss, inside", {
  ["polygon.lua"] = polygon.polygonCircleCollideV,
  ["baseline"] = baseline.polygonCircleCollideV,
  ["polygonWindingOrder (its area-sign pass)"] = winding,
}, circles, #circles[1], { "polygon.lua", "baseline",
  "polygonWindingOrder (its area-sign pass)" }, circleCheck)

local pairsMix = W.pairs(300, { W.pairOverlap, W.pairTouch, W.pairMiss })
local pairParts = {
  ["polygon.lua"] = polygon.polygonsCollideV,
  ["baseline"] = baseline.polygonsCollideV,
  ["polygonsCollide (no vector)"] = polygon.polygonsCollide,
  ["two polygonWindingOrder (the area-sign passes)"] = twoWindings,
}
local pairOrder = { "polygon.lua", "baseline", "polygonsCollide (no vector)",
  "two polygonWindingOrder (the area-sign passes)" }
report("polygonsCollideV, convex 6-8 pairs, 1/3 overlap, touch, miss", pairParts, pairsMix,
       #pairsMix[1], pairOrder)
local kinds = { { "overlap", W.pairOverlap }, { "touch", W.pairTouch }, { "miss", W.pairMiss } }
for _, kind in ipairs(kinds) do
  local p = W.pairs(300, { kind[2] })
  report("polygonsCollideV, convex 6-8 pairs, " .. kind[1], pairParts, p, #p[1], pairOrder)
end
