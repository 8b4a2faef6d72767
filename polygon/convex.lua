-- polygon/convex.lua: the shape the collision functions take, checked on every call: at least 3
-- points, numbers, and convex (exact: a filter, then the careful walk that names the vertex).
-- Every refusal's message is built here. Relies on kernel.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")

local abs, huge, min, max = math.abs, math.huge, math.min, math.max
local JIT, CROSS_BOUND, cross, areaSign = kernel.JIT, kernel.CROSS_BOUND, kernel.cross,
  kernel.areaSign

local M = {}


-- The fix named by every refusal of a concave shape, in one place.
local SPLIT_FIX = "split it once with polygonConvexParts and pass the parts"

-- What a shape of fewer than 3 points is, for the refusal's message (one place: a pointer to
-- another function for segments is one line here).
local function fewPointsMessage(fname, argname, n)
  if n == 4 then
    return ("%s: %s has 2 points: a segment; a polygon needs at least 3"):format(fname, argname)
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
  if kind == "table" and (first.x ~= nil or first[1] ~= nil and first[3] == nil) then
    error(("%s: %s holds point tables; pass a flat array {x1, y1, x2, y2, ...}")
      :format(fname, argname), level + 1)
  end
  error(("%s: %s[1] must be a number, got %s"):format(fname, argname, kind), level + 1)
end

-- The non-finite refusal (the engines' own message, the same words).
local function refuseNonFinite(fname, argname, level)
  error(("%s: %s holds a non-finite coordinate"):format(fname, argname), level + 1)
end

-- The careful walk: every turn through cross (exact), repeated vertices skipped. Returns nil when
-- the polygon is convex or has no turn at all (every point on one line: zero area, which never
-- collides), else the reason it is not convex, for the message. The reference turn is the sign
-- of the exact area (the first turn when that is zero, as for a bow tie), so the vertex named
-- is where a walk around the shape turns back against it.
local function whyNotConvex(points, n)
  local m = n / 2
  local ref = areaSign(points, n)
  local cx, cy = points[n - 1] + 0.0, points[n] + 0.0
  local j = n - 3
  while j > 0 and points[j] + 0.0 == cx and points[j + 1] + 0.0 == cy do j = j - 2 end
  if j < 0 then return nil end   -- all points are one point
  local px, py = points[j] + 0.0, points[j + 1] + 0.0
  local turned, flips, dir = false, 0, 0
  local firstBad, badKind
  -- the turn at vertex k is taken at c (vertex m first, then 1, 2, ...)
  local k = m
  for i = 1, n - 1, 2 do
    local qx, qy = points[i] + 0.0, points[i + 1] + 0.0
    if qx ~= cx or qy ~= cy then
      local s = cross(px, py, cx, cy, cx, cy, qx, qy)
      if s ~= 0 then
        turned = true
        if ref == 0 then ref = s end
        if (s > 0) ~= (ref > 0) and not firstBad then firstBad, badKind = k, "reflex" end
      elseif (cx ~= px and (cx > px) ~= (qx > cx)) or (cx == px and (cy > py) ~= (qy > cy)) then
        if not firstBad then firstBad, badKind = k, "spike" end
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
  if badKind == "reflex" then return ("a reflex turn at vertex %d"):format(firstBad) end
  if badKind == "spike" then
    return ("a spike at vertex %d: its edges fold back on one line"):format(firstBad)
  end
  if flips > 2 then return "its turns all agree but it winds around more than once: it crosses itself" end
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

-- THE FILTER: true when the polygon points[1..n] (n >= 6) is surely convex or surely has every
-- turn exactly zero, false when the careful walk must decide (never a wrong true). Per vertex,
-- the turn e x f = l - r of the edges into it (e) and out of it (f), with cross's error bound
-- CROSS_BOUND |l + r| (when l and r differ in sign no cancellation happens and |l + r| <= |s|);
-- every turn surely >= 0, or every one surely <= 0 (a turn computed as 0 from l = r = 0 is
-- exactly 0: a product of differences is 0 only when a difference is, and then exactly). A zero
-- turn that doubles back (a spike: e . f < 0) is sent to the walk by a tiny extra bound; the
-- windings are counted as in polygonType (typeFiltered): the signs of consecutive edges' x
-- products sum to m - 4 k around m edges of certain turns winding k times; any zero edge or
-- collinear pair breaks the count and goes to the walk, never to a wrong true.
-- Two bodies, the same answers (spec/refusals_spec.lua compares them).
-- One vertex's contribution, for LuaJIT's unrolled body (kept as an expression per vertex:
-- a step function returning several numbers makes its traces abort, see sat's vertexInside).
-- LuaJIT's: up to 8 vertices unrolled, the last one repeated for fewer (its zero edges give
-- zero turns, zero bounds and zero x products), and the real turn at the last vertex added
-- once more; a loop beyond. min, max and abs are single instructions there, and LuaJIT has no
-- integers, so no coordinate is converted.
local SPIKE = 2^-600   -- any spike's tiny bound: a real turn's margin is far above it

local function convexFilterJitLoop(points, n)
  local lo, hi, agree = huge, -huge, 0
  local ax, ay = points[n - 3], points[n - 2]
  local bx, by = points[n - 1], points[n]
  local ex, ey = bx - ax, by - ay
  for i = 1, n - 1, 2 do
    local cx, cy = points[i], points[i + 1]
    local fx, fy = cx - bx, cy - by
    local l, r, xx = ex * fy, ey * fx, ex * fx
    local s, b = l - r, CROSS_BOUND * abs(l + r) + SPIKE * max(0, -(xx + ey * fy))
    lo, hi = min(lo, s - b), max(hi, s + b)
    agree = agree + min(1, max(-1, xx * 2^1000))
    bx, by, ex, ey = cx, cy, fx, fy
  end
  return max(lo, -hi) >= 0 and agree == n / 2 - 4
end

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
  -- edges: e_k from vertex k to k + 1 (e8 back to 1), and the real last edge into vertex 8
  local e1x, e1y, e2x, e2y = x2 - x1, y2 - y1, x3 - x2, y3 - y2
  local e3x, e3y, e4x, e4y = x4 - x3, y4 - y3, x5 - x4, y5 - y4
  local e5x, e5y, e6x, e6y = x6 - x5, y6 - y5, x7 - x6, y7 - y6
  local e7x, e7y, e8x, e8y = x8 - x7, y8 - y7, x1 - x8, y1 - y8
  local elx, ely = x8 - xp, y8 - yp
  local l, r, xx, s, b
  local lo, hi, agree
  l, r, xx = e8x * e1y, e8y * e1x, e8x * e1x   -- at vertex 1
  s, b = l - r, CROSS_BOUND * abs(l + r) + SPIKE * max(0, -(xx + e8y * e1y))
  lo, hi, agree = s - b, s + b, min(1, max(-1, xx * 2^1000))
  l, r, xx = e1x * e2y, e1y * e2x, e1x * e2x   -- at vertex 2
  s, b = l - r, CROSS_BOUND * abs(l + r) + SPIKE * max(0, -(xx + e1y * e2y))
  lo, hi, agree = min(lo, s - b), max(hi, s + b), agree + min(1, max(-1, xx * 2^1000))
  l, r, xx = e2x * e3y, e2y * e3x, e2x * e3x   -- at vertex 3
  s, b = l - r, CROSS_BOUND * abs(l + r) + SPIKE * max(0, -(xx + e2y * e3y))
  lo, hi, agree = min(lo, s - b), max(hi, s + b), agree + min(1, max(-1, xx * 2^1000))
  l, r, xx = e3x * e4y, e3y * e4x, e3x * e4x   -- at vertex 4
  s, b = l - r, CROSS_BOUND * abs(l + r) + SPIKE * max(0, -(xx + e3y * e4y))
  lo, hi, agree = min(lo, s - b), max(hi, s + b), agree + min(1, max(-1, xx * 2^1000))
  l, r, xx = e4x * e5y, e4y * e5x, e4x * e5x   -- at vertex 5
  s, b = l - r, CROSS_BOUND * abs(l + r) + SPIKE * max(0, -(xx + e4y * e5y))
  lo, hi, agree = min(lo, s - b), max(hi, s + b), agree + min(1, max(-1, xx * 2^1000))
  l, r, xx = e5x * e6y, e5y * e6x, e5x * e6x   -- at vertex 6
  s, b = l - r, CROSS_BOUND * abs(l + r) + SPIKE * max(0, -(xx + e5y * e6y))
  lo, hi, agree = min(lo, s - b), max(hi, s + b), agree + min(1, max(-1, xx * 2^1000))
  l, r, xx = e6x * e7y, e6y * e7x, e6x * e7x   -- at vertex 7
  s, b = l - r, CROSS_BOUND * abs(l + r) + SPIKE * max(0, -(xx + e6y * e7y))
  lo, hi, agree = min(lo, s - b), max(hi, s + b), agree + min(1, max(-1, xx * 2^1000))
  l, r, xx = e7x * e8y, e7y * e8x, e7x * e8x   -- at vertex 8
  s, b = l - r, CROSS_BOUND * abs(l + r) + SPIKE * max(0, -(xx + e7y * e8y))
  lo, hi, agree = min(lo, s - b), max(hi, s + b), agree + min(1, max(-1, xx * 2^1000))
  -- the real turn at the last vertex (the padding's zero edges hid it; for 8 vertices a repeat,
  -- harmless to lo and hi, and its x product is not counted twice)
  l, r, xx = elx * e8y, ely * e8x, elx * e8x
  s, b = l - r, CROSS_BOUND * abs(l + r) + SPIKE * max(0, -(xx + ely * e8y))
  lo, hi = min(lo, s - b), max(hi, s + b)
  agree = agree + min(1, max(-1, xx * 2^1000)) * min(1, max(0, 16 - n))
  return max(lo, -hi) >= 0 and agree == n / 2 - 4
end

-- PUC Lua's: one loop with comparisons (math.min, max and abs are calls there).
local function convexFilterPuc(points, n)
  local lo, hi, agree = huge, -huge, 0
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
    local xx = ex * fx
    local s = l - r
    local b = l + r
    if b < 0 then b = -b end
    b = CROSS_BOUND * b
    local d = xx + ey * fy
    if d < 0 then b = b - SPIKE * d end
    if s - b < lo then lo = s - b end
    if s + b > hi then hi = s + b end
    if xx > 0 then agree = agree + 1 elseif xx < 0 then agree = agree - 1 end
    bx = cx
    by = cy
    ex = fx
    ey = fy
  end
  return max(lo, -hi) >= 0 and agree == n / 2 - 4
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
M.convexFilter = convexFilter
M.convexFilterJit = convexFilterJit
M.convexFilterPuc = convexFilterPuc
M.convexCareful = convexCareful
M.checkConvex = checkConvex

return M
