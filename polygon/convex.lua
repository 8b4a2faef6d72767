-- polygon/convex.lua: the shape the collision functions take, checked on every call: at least 3
-- points, numbers, and convex (exact: a filter, then the careful walk that names the vertex).
-- Every refusal's message is built here. Relies on kernel.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")

local abs, huge, min, max = math.abs, math.huge, math.min, math.max
local JIT, CROSS_BOUND, cross = kernel.JIT, kernel.CROSS_BOUND, kernel.cross
local powerScale, largestMagnitude = kernel.powerScale, kernel.largestMagnitude

local M = {}


-- The fix named by every refusal of a concave shape, in one place.
local SPLIT_FIX = "split it once with polygonConvexParts and pass the parts"

-- What a shape of fewer than 3 points is, for the refusal's message (one place). A segment
-- handed to a collision function is most often a line of sight: the message points to the ray
-- cast (which refuses it too, without the pointer to itself).
local function fewPointsMessage(fname, argname, n)
  if n == 4 then
    local message = ("%s: %s has 2 points: a segment; a polygon needs at least 3"):format(fname, argname)
    if fname == "polygonRayCast" then return message end
    return message .. "; for line of sight use polygonRayCast"
  end
  if n == 0 then
    return ("%s: %s is empty; a polygon needs at least 3 points"):format(fname, argname)
  end
  return ("%s: %s has 1 point; a polygon needs at least 3"):format(fname, argname)
end

-- The argument error for a shape whose first entry is not a number (kind: its type): a table of
-- point tables, strings. level as error's, counted from the caller of this function.
local function refuseEntries(fname, argname, shape, kind, level)
  local first = shape[1]
  if kind == "table" and (first.x ~= nil or #first == 2) then
    error(("%s: %s holds point tables; pass a flat array {x1, y1, x2, y2, ...}")
      :format(fname, argname), level + 1)
  end
  error(("%s: %s[1] must be a number, got %s"):format(fname, argname, kind), level + 1)
end

-- The non-finite refusal (the engines' own message, the same words).
local function refuseNonFinite(fname, argname, level)
  error(("%s: %s holds a non-finite coordinate"):format(fname, argname), level + 1)
end

-- The reference turn of the careful walk: the exact turn at the lowest vertex (least y, then
-- least x; coordinates times scale), between its nearest distinct neighbours. That vertex is a
-- corner of the convex hull, so its turn has the sign of a convex polygon's every turn (of a
-- simple polygon's area); 0 only at a spike there.
local function lowestTurn(points, n, scale)
  local low = 1
  for i = 3, n - 1, 2 do
    local y, ly = points[i + 1] * scale, points[low + 1] * scale
    if y < ly or (y == ly and points[i] * scale < points[low] * scale) then low = i end
  end
  local x, y = points[low] * scale, points[low + 1] * scale
  local a, b = low, low
  repeat a = (a - 3) % n + 1 until a == low or points[a] * scale ~= x or points[a + 1] * scale ~= y
  repeat b = (b + 1) % n + 1 until b == low or points[b] * scale ~= x or points[b + 1] * scale ~= y
  if a == low then return 0 end
  return cross(points[a] * scale, points[a + 1] * scale, x, y, x, y, points[b] * scale,
    points[b + 1] * scale)
end

-- THE CAREFUL WALK, one for the collision functions' check (whyNotConvex) and polygonType
-- (measures.lua): every turn through cross (exact), repeated vertices skipped, collinear vertices
-- told apart from spikes (a zero turn that doubles back), the windings counted by the changes of
-- sign of the edges' x direction (two around a convex polygon; counted along the walk they are
-- one fewer when the first and last edges differ, and the count around the cycle is even, so
-- more than two along the walk means more than two around). Coordinates are taken times `scale`
-- (a power of two; 1 converts Lua 5.3 integers). Returns nil when there is no turn at all (every
-- point on one line: zero area, which never collides), "convex", or why not: "reflex" or
-- "spike" and the vertex where the walk first turns back, or "winds" (its turns all agree but it
-- winds around more than once). The reference turn is the one at the lowest vertex when `named`
-- (lowestTurn; the first turn when that is zero), so the vertex named is where a walk around
-- the shape turns back against it; else the first turn (enough for a yes or no).
local function carefulWalk(points, n, scale, named)
  local cx, cy = points[n - 1] * scale, points[n] * scale
  local j = n - 3
  while j > 0 and points[j] * scale == cx and points[j + 1] * scale == cy do j = j - 2 end
  if j < 0 then return nil end   -- all points are one point
  local px, py = points[j] * scale, points[j + 1] * scale
  local ref = named and lowestTurn(points, n, scale) or 0
  local turned, flips, dir = false, 0, 0
  local spikeAt   -- the first spike; the answer once a turn shows the shape is not all on a line
  -- the turn at vertex k is taken at c (vertex m first, then 1, 2, ...)
  local k = n / 2
  for i = 1, n - 1, 2 do
    local qx, qy = points[i] * scale, points[i + 1] * scale
    if qx ~= cx or qy ~= cy then
      local s = cross(px, py, cx, cy, cx, cy, qx, qy)
      if s ~= 0 then
        turned = true
        if ref == 0 then ref = s end
        if spikeAt then return "spike", spikeAt end
        if (s > 0) ~= (ref > 0) then return "reflex", k end
      elseif not spikeAt and
          ((cx ~= px and (cx > px) ~= (qx > cx)) or (cx == px and (cy > py) ~= (qy > cy))) then
        spikeAt = k
        if turned then return "spike", k end
      end
      if qx > cx then
        if dir < 0 then flips = flips + 1 end
        dir = 1
      elseif qx < cx then
        if dir > 0 then flips = flips + 1 end
        dir = -1
      end
      px, py, cx, cy = cx, cy, qx, qy
    end
    k = (i + 1) / 2
  end
  if not turned then return nil end
  if spikeAt then return "spike", spikeAt end
  if flips > 2 then return "winds" end
  return "convex"
end

-- Why a polygon is not convex, for the refusal's message, or nil when it is convex or has no
-- turn at all (the careful walk, the vertex named).
local function whyNotConvex(points, n)
  -- coordinates far outside the exact range are scaled by a power of two first (exact, short
  -- of underflow), so that no product of differences underflows or overflows
  local magnitude = largestMagnitude(points, n, 0.0)
  local scale = 1.0
  if magnitude < 2^-400 or magnitude > 2^400 then scale = powerScale(magnitude, 2^-64, 1) end
  local kind, vertex = carefulWalk(points, n, scale, true)
  if kind == "reflex" then return ("a reflex turn at vertex %d"):format(vertex) end
  if kind == "spike" then
    return ("a spike at vertex %d: its edges fold back on one line"):format(vertex)
  end
  if kind == "winds" then
    return "its turns all agree but it winds around more than once: it crosses itself"
  end
  return nil
end

-- Raises the refusal of a shape the filter could not vouch for, when it is not convex: the
-- careful walk decides. level as error's, counted from the caller of this function.
local function convexCareful(points, n, fname, argname, level)
  for i = 1, n do
    local v = points[i]
    if type(v) ~= "number" then
      error(("%s: %s[%d] must be a number, got %s"):format(fname, argname, i, type(v)), level + 1)
    end
    if v - v ~= 0 then refuseNonFinite(fname, argname, level + 1) end
  end
  local why = whyNotConvex(points, n)
  if why then
    error(("%s: %s is not convex (%s); %s"):format(fname, argname, why, SPLIT_FIX), level + 1)
  end
end

-- THE FILTER: true when the polygon points[1..n] (n >= 6) is surely convex, false when the
-- careful walk must decide (never a wrong true). Per vertex, the turn e x f = l - r of the edges
-- into it (e) and out of it (f), with cross's error bound CROSS_BOUND |l + r| (when l and r
-- differ in sign no cancellation happens and |l + r| <= |s|) plus TINY: every turn surely
-- positive, or every one surely negative. So a turn of 0 (collinear vertices, a spike, a
-- repeated vertex) or one that underflows goes to the walk. The windings are counted as in
-- polygonType (typeFiltered): around m edges whose turns are certain, the signs of consecutive
-- edges' x products sum to m - 4 k for k windings. The bounds' sum is kept finite: an overflow
-- (NaN or inf) goes to the walk too.
-- Two bodies, the same answers (spec/refusals_spec.lua compares them).
local TINY = 2^-900   -- below every turn of the exact range worth trusting to the filter

-- LuaJIT's: min, max and abs are single instructions there (no branch), and LuaJIT has no
-- integers, so no coordinate is converted. Beyond 8 vertices a loop.
local function convexFilterJitLoop(points, n)
  local lo, hi, agree, bsum = huge, -huge, 0, 0
  local ax, ay = points[n - 3], points[n - 2]
  local bx, by = points[n - 1], points[n]
  local ex, ey = bx - ax, by - ay
  for i = 1, n - 1, 2 do
    local cx, cy = points[i], points[i + 1]
    local fx, fy = cx - bx, cy - by
    local l, r, xx = ex * fy, ey * fx, ex * fx
    local s, b = l - r, CROSS_BOUND * abs(l + r) + TINY
    lo, hi, bsum = min(lo, s - b), max(hi, s + b), bsum + b
    agree = agree + min(1, max(-1, xx * 2^1000))
    bx, by, ex, ey = cx, cy, fx, fy
  end
  return max(lo, -hi) > 0 and agree == n / 2 - 4 and bsum < huge
end

-- Up to 8 vertices written out, as sat's shoelaceBounds: a loop of 3 to 8 steps is copied
-- unrolled into its callers' traces, whose exits for the other sizes fail to compile ("NYI:
-- register coalescing too complex") until the loop is left to the interpreter. Slot k holds
-- vertex min(k, m) (the last repeated for fewer); edge k runs from slot k to slot k + 1 (edge 8
-- back to slot 1). A slot from m on (2k >= n) turns between repeated vertices: its turn is
-- taken out of lo and hi by `pad` (2^1000) and its x product is 0; the real turn at vertex m
-- is taken once more at the end (for 8 vertices a repeat of slot 8's, its x product not
-- counted).
local PAD = 2^1000

local function convexFilterJit(points, n)
  if n > 16 then
    local sure = convexFilterJitLoop(points, n)
    return sure
  end
  local x1, y1 = points[1], points[2]
  local x2, y2 = points[3], points[4]
  local x3, y3 = points[5], points[6]
  local j = min(7, n - 1)
  local x4, y4 = points[j], points[j + 1]
  j = min(9, n - 1)
  local x5, y5 = points[j], points[j + 1]
  j = min(11, n - 1)
  local x6, y6 = points[j], points[j + 1]
  j = min(13, n - 1)
  local x7, y7 = points[j], points[j + 1]
  local x8, y8 = points[n - 1], points[n]
  local xp, yp = points[n - 3], points[n - 2]   -- the real vertex before the last
  local e1x, e1y, e2x, e2y = x2 - x1, y2 - y1, x3 - x2, y3 - y2
  local e3x, e3y, e4x, e4y = x4 - x3, y4 - y3, x5 - x4, y5 - y4
  local e5x, e5y, e6x, e6y = x6 - x5, y6 - y5, x7 - x6, y7 - y6
  local e7x, e7y, e8x, e8y = x8 - x7, y8 - y7, x1 - x8, y1 - y8
  local l, r, xx, s, b, pad
  local lo, hi, agree, bsum
  l, r, xx = e8x * e1y, e8y * e1x, e8x * e1x   -- slot 1
  s, b = l - r, CROSS_BOUND * abs(l + r) + TINY
  lo, hi, agree, bsum = s - b, s + b, min(1, max(-1, xx * 2^1000)), b
  l, r, xx = e1x * e2y, e1y * e2x, e1x * e2x   -- slot 2 (always a real vertex)
  s, b = l - r, CROSS_BOUND * abs(l + r) + TINY
  lo, hi = min(lo, s - b), max(hi, s + b)
  agree, bsum = agree + min(1, max(-1, xx * 2^1000)), bsum + b
  l, r, xx = e2x * e3y, e2y * e3x, e2x * e3x   -- slot 3
  s, b, pad = l - r, CROSS_BOUND * abs(l + r) + TINY, PAD * min(1, max(0, 7 - n))
  lo, hi = min(lo, s - b + pad), max(hi, s + b - pad)
  agree, bsum = agree + min(1, max(-1, xx * 2^1000)), bsum + b
  l, r, xx = e3x * e4y, e3y * e4x, e3x * e4x   -- slot 4
  s, b, pad = l - r, CROSS_BOUND * abs(l + r) + TINY, PAD * min(1, max(0, 9 - n))
  lo, hi = min(lo, s - b + pad), max(hi, s + b - pad)
  agree, bsum = agree + min(1, max(-1, xx * 2^1000)), bsum + b
  l, r, xx = e4x * e5y, e4y * e5x, e4x * e5x   -- slot 5
  s, b, pad = l - r, CROSS_BOUND * abs(l + r) + TINY, PAD * min(1, max(0, 11 - n))
  lo, hi = min(lo, s - b + pad), max(hi, s + b - pad)
  agree, bsum = agree + min(1, max(-1, xx * 2^1000)), bsum + b
  l, r, xx = e5x * e6y, e5y * e6x, e5x * e6x   -- slot 6
  s, b, pad = l - r, CROSS_BOUND * abs(l + r) + TINY, PAD * min(1, max(0, 13 - n))
  lo, hi = min(lo, s - b + pad), max(hi, s + b - pad)
  agree, bsum = agree + min(1, max(-1, xx * 2^1000)), bsum + b
  l, r, xx = e6x * e7y, e6y * e7x, e6x * e7x   -- slot 7
  s, b, pad = l - r, CROSS_BOUND * abs(l + r) + TINY, PAD * min(1, max(0, 15 - n))
  lo, hi = min(lo, s - b + pad), max(hi, s + b - pad)
  agree, bsum = agree + min(1, max(-1, xx * 2^1000)), bsum + b
  l, r, xx = e7x * e8y, e7y * e8x, e7x * e8x   -- slot 8 (for 8 vertices the repeat below)
  s, b = l - r, CROSS_BOUND * abs(l + r) + TINY
  lo, hi = min(lo, s - b + PAD), max(hi, s + b - PAD)
  agree, bsum = agree + min(1, max(-1, xx * 2^1000)), bsum + b
  local elx, ely = x8 - xp, y8 - yp   -- the real turn at the last vertex
  l, r, xx = elx * e8y, ely * e8x, elx * e8x
  s, b = l - r, CROSS_BOUND * abs(l + r) + TINY
  lo, hi, bsum = min(lo, s - b), max(hi, s + b), bsum + b
  agree = agree + min(1, max(-1, xx * 2^1000)) * min(1, max(0, 16 - n))
  return max(lo, -hi) > 0 and agree == n / 2 - 4 and bsum < huge
end

-- PUC Lua's: one loop with comparisons (math.min, max and abs are calls there).
local function convexFilterPuc(points, n)
  local lo, hi, agree, bsum = huge, -huge, 0, 0
  local bx, by = points[n - 1] + 0.0, points[n] + 0.0
  local ex = bx - points[n - 3]
  local ey = by - points[n - 2]
  for i = 1, n - 1, 2 do
    local cx = points[i] + 0.0
    local cy = points[i + 1] + 0.0
    local fx = cx - bx
    local fy = cy - by
    local l = ex * fy
    local r = ey * fx
    local s = l - r
    local b = l + r
    if b < 0 then b = -b end
    b = CROSS_BOUND * b + TINY
    bsum = bsum + b
    if s - b < lo then lo = s - b end
    if s + b > hi then hi = s + b end
    local xx = ex * fx
    if xx > 0 then agree = agree + 1 elseif xx < 0 then agree = agree - 1 end
    bx = cx
    by = cy
    ex = fx
    ey = fy
  end
  return (lo > 0 or hi < 0) and agree == n / 2 - 4 and bsum < huge
end

local convexFilter = JIT and convexFilterJit or convexFilterPuc

-- Checks that a flat shape a collision function was given (a table whose first entry the caller
-- has looked at) is a polygon it can take: at least 3 points, convex. Raises the argument error
-- at `level` (as error's, counted from the caller of this function).
local function checkConvex(points, n, fname, argname, level)
  if n < 6 then error(fewPointsMessage(fname, argname, n), level + 1) end
  if not convexFilter(points, n) then convexCareful(points, n, fname, argname, level + 1) end
end

M.SPLIT_FIX = SPLIT_FIX
M.fewPointsMessage = fewPointsMessage
M.refuseEntries = refuseEntries
M.whyNotConvex = whyNotConvex
M.carefulWalk = carefulWalk
M.convexFilter = convexFilter
M.convexFilterJit = convexFilterJit
M.convexFilterJitLoop = convexFilterJitLoop
M.convexFilterPuc = convexFilterPuc
M.convexCareful = convexCareful
M.checkConvex = checkConvex

return M
