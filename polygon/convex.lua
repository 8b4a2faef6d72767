-- polygon/convex.lua: the shape the collision functions take, checked on every call: at least 3
-- points, numbers, and convex (exact: a filter, then the careful walk that names the vertex).
-- Every refusal's message is built here. Relies on kernel.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")

local abs, huge, min, max = math.abs, math.huge, math.min, math.max
local JIT, CROSS_BOUND, cross = kernel.JIT, kernel.CROSS_BOUND, kernel.cross
local powerScale = kernel.powerScale

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
-- least x; coordinates scaled as in carefulWalk), between its nearest distinct neighbours.
-- That vertex is a corner of the convex hull, so its turn has the sign of a convex polygon's
-- every turn (of a simple polygon's area); 0 only at a spike there.
local function lowestTurn(points, n, sx, sy)
  local low = 1
  for i = 3, n - 1, 2 do
    local y, ly = points[i + 1] * sy, points[low + 1] * sy
    if y < ly or (y == ly and points[i] * sx < points[low] * sx) then low = i end
  end
  local x, y = points[low] * sx, points[low + 1] * sy
  local a, b = low, low
  repeat a = (a - 3) % n + 1 until a == low or points[a] * sx ~= x or points[a + 1] * sy ~= y
  repeat b = (b + 1) % n + 1 until b == low or points[b] * sx ~= x or points[b + 1] * sy ~= y
  if a == low then return 0 end
  return cross(points[a] * sx, points[a + 1] * sy, x, y, x, y, points[b] * sx,
    points[b + 1] * sy)
end

-- THE CAREFUL WALK, one for the collision functions' check (whyNotConvex) and polygonType
-- (measures.lua): every turn through cross (exact), repeated vertices skipped, collinear vertices
-- told apart from spikes (a zero turn that doubles back), the windings counted by the changes of
-- sign of the edges' x direction (two around a convex polygon; counted along the walk they are
-- one fewer when the first and last edges differ, and the count around the cycle is even, so
-- more than two along the walk means more than two around). Coordinates are taken times powers
-- of two, x times sx and y times sy (no sign changes when the axes are scaled apart; 1 converts
-- Lua 5.3 integers). Returns nil when there is no turn at all (every
-- point on one line: zero area, which never collides), "convex", or why not: "reflex" or
-- "spike" and the vertex where the walk first turns back, or "winds" (its turns all agree but it
-- winds around more than once). The reference turn is the one at the lowest vertex when `named`
-- (lowestTurn; the first turn when that is zero), so the vertex named is where a walk around
-- the shape turns back against it; else the first turn (enough for a yes or no).
local function carefulWalk(points, n, sx, sy, named)
  local cx, cy = points[n - 1] * sx, points[n] * sy
  local j = n - 3
  while j > 0 and points[j] * sx == cx and points[j + 1] * sy == cy do j = j - 2 end
  if j < 0 then return nil end   -- all points are one point
  local px, py = points[j] * sx, points[j + 1] * sy
  local ref = named and lowestTurn(points, n, sx, sy) or 0
  local turned, flips, dir = false, 0, 0
  local spikeAt   -- the first spike; the answer once a turn shows the shape is not all on a line
  -- the turn at vertex k is taken at c (vertex m first, then 1, 2, ...)
  local k = n / 2
  for i = 1, n - 1, 2 do
    local qx, qy = points[i] * sx, points[i + 1] * sy
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
  -- coordinates far outside the exact range are scaled by a power of two first, x and y each
  -- by its own (exact, short of underflow; a turn keeps its sign), so that no product of
  -- differences underflows or overflows: a polygon of x near 1e-300 and y near 1e150 is
  -- decided as the same polygon near 1
  local mx, my = 0.0, 0.0
  for i = 1, n - 1, 2 do mx, my = max(mx, abs(points[i])), max(my, abs(points[i + 1])) end
  local sx, sy = 1.0, 1.0
  -- (tiny magnitudes go up to 2^-400 .. 2^-336 only: one factor to 1 would pass 2^1023 below
  -- about 2^-960, and there the products of differences keep their bits)
  if mx > 2^400 then sx = powerScale(mx, 2^-64, 1) elseif mx < 2^-400 then
    sx = powerScale(mx, 2^-400, 2^-336)
  end
  if my > 2^400 then sy = powerScale(my, 2^-64, 1) elseif my < 2^-400 then
    sy = powerScale(my, 2^-400, 2^-336)
  end
  local kind, vertex = carefulWalk(points, n, sx, sy, true)
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

-- THE VOUCHING PASS: the collision engines' first pass when they check (sat.lua's
-- convexPenetration; circle.lua's edge walk on PUC Lua, whose LuaJIT walk takes the same check in
-- its own loop), fused with the convexity filter: one read of
-- the vertices gives the polygon's bounding box and its turns, and when every turn is surely of
-- one sign and the polygon winds once, its orientation too (a convex polygon's area has its
-- turns' sign), so the engine needs no shoelace pass of its own. Returns turn (1.0 or -1.0),
-- xmin, xmax, ymin, ymax, and on PUC Lua low and high, the flat indices (of x) of the first
-- vertex of least y and of the first of largest y (kernel's turnAndBounds' values); nil when it
-- cannot vouch: then the caller checks the careful way (checkConvex) and runs the unchecked
-- engine. Never a wrong answer: nil for every polygon that is not convex, and for some that are
-- (collinear vertices, turns near the bound below, overflow, non-finite coordinates).
-- The turn at vertex k is s = e x f = l - r of the edges into it (e) and out of it (f). One
-- error bound serves all turns: each edge's computed difference is at most the box's computed
-- span (rounding is monotone), so |l| + |r| <= 2 spanX spanY, and Shewchuk's bound CROSS_BOUND
-- (|l| + |r|) of each turn is at most SHARED_BOUND spanX spanY, plus TINY for products that
-- underflow. A turn below that (about 6 eps of the box's area) goes to the walk. The windings:
-- with every turn surely of one sign, an edge along the y axis lies between a change of the x
-- direction (else the turns at its ends differ), so around m edges the signs sx of the edges'
-- x differences give sum sx_k sx_k+1 = m - 4 k for k windings. The signs are exact (a product
-- of two differences that underflows must not pass for a zero): LuaJIT's scales a nonzero
-- difference, at least 2^-1074, by 2^537 twice, to at least 1 (or inf); PUC Lua's looks again
-- at a product of 0 (zeroFlips).
-- Two bodies, the same answers (spec/convex_bound_hard_spec.lua runs both, and their loops, on
-- every interpreter); both read each coordinate by adding 0.0, so Lua 5.3 integers are
-- converted and an entry that is not a number raises Lua's own arithmetic error, as in the
-- engines without the check. Beyond their sizes, loops.
-- LuaJIT's (vouchJit) is one body for 3 to 8 vertices, the last vertex repeated (see there),
-- with no branch but the verdict: the box, the turns' extremes and the x differences' signs by
-- min and max (single instructions there); the turns' sum carries a NaN (min and max may drop
-- one) into the verdict.
-- PUC Lua's (vouchPuc) is written out for each size from 3 to 16 vertices (no loop's moves and
-- tests, no padding), as text built below and compiled once at load: comparisons (min and max
-- are calls there), each turn tested against the bound once the first turn has set the sign (a
-- NaN fails the test), the changes counted by the products of consecutive x differences (2 a
-- negative product, 1 a zero; the rare product of 0 by zeroFlips). Up to 4 vertices it counts
-- no windings: a polygon whose turns agree turns through less than 4 half turns there, so it
-- winds once.
local TINY = 2^-900   -- below every turn of the exact range worth trusting to the filter
local SHARED_BOUND = 2 * CROSS_BOUND   -- times spanX spanY
local loadChunk = rawget(_G, "loadstring") or load

-- What a product of two x differences of 0 adds to PUC Lua's count of changes (see above):
-- 1 when a difference is 0, else the product underflowed: 2 when their signs differ, 0 when
-- they agree.
local function zeroFlips(ex, fx)
  if ex == 0 or fx == 0 then return 1 end
  if (ex < 0) == (fx < 0) then return 0 end
  return 2
end

-- The source of the pass for m vertices (3 to 8) in one dialect ("jit" or "puc"). Vertex k is
-- xk, yk; edge k, from vertex k to vertex k + 1 (edge m back to vertex 1), is exk, eyk; the turn
-- at vertex k + 1 is edge k x edge k + 1.
local function vouchSource(m)
  local out = {}
  local function line(format, ...) out[#out + 1] = format:format(...) end
  local function after(k) return k % m + 1 end
  local function each(format, last, sep)
    local items = {}
    for k = 1, last or m do items[k] = format:gsub("#n", after(k)):gsub("#", k) end
    return table.concat(items, sep or ", ")
  end
  line("local SHARED_BOUND, TINY, zeroFlips = ...")
  line("return function(p)")
  line("local x1, y1 = p[1] + 0.0, p[2] + 0.0")
  line("local xmin, xmax, ymin, ymax, low, high = x1, x1, y1, y1, 1, 1")
  for k = 2, m do
    line("local x%d, y%d = p[%d] + 0.0, p[%d] + 0.0", k, k, 2 * k - 1, 2 * k)
    line("if x%d < xmin then xmin = x%d elseif x%d > xmax then xmax = x%d end", k, k, k, k)
    line("if y%d < ymin then ymin, low = y%d, %d elseif y%d > ymax then ymax, high = y%d, %d end",
      k, k, 2 * k - 1, k, k, 2 * k - 1)
  end
  line("local bound = SHARED_BOUND * ((xmax - xmin) * (ymax - ymin)) + TINY")
  line("local %s = %s", each("ex#, ey#"), each("x#n - x#, y#n - y#"))
  if m > 4 then
    line("local flips, xx = 0, 0.0")
    for k = 1, m do
      line("xx = ex%d * ex%d", k, after(k))
      line("if xx <= 0 then flips = flips + (xx < 0 and 2 or zeroFlips(ex%d, ex%d)) end", k, after(k))
    end
    line("if flips ~= 4 then return nil end")
  end
  -- the turn at vertex 1 sets the sign; every turn then surely of it
  line("local turn = 1.0")
  line("if ex%d * ey1 - ey%d * ex1 < 0 then turn, bound = -1.0, -bound end", m, m)
  line("if turn > 0 then")
  for k = 1, m do
    line("  if not (ex%d * ey%d - ey%d * ex%d > bound) then return nil end", k, after(k), k, after(k))
  end
  line("else")
  for k = 1, m do
    line("  if not (ex%d * ey%d - ey%d * ex%d < bound) then return nil end", k, after(k), k, after(k))
  end
  line("end")
  line("return turn, xmin, xmax, ymin, ymax, low, high")
  line("end")
  return table.concat(out, "\n")
end

-- Beyond the bodies, loops. LuaJIT's keeps every turn's extremes, as its bodies do.
local function vouchLoopJit(points, n)
  local bx, by = points[n - 1] + 0.0, points[n] + 0.0
  local ex, ey = bx - points[n - 3], by - points[n - 2]
  local sx = min(1, max(-1, ex * 2^537 * 2^537))
  local lo, hi, sum, agree = huge, -huge, 0, 0
  local xmin, xmax, ymin, ymax = bx, bx, by, by
  for i = 1, n - 1, 2 do
    local cx, cy = points[i] + 0.0, points[i + 1] + 0.0
    local fx, fy = cx - bx, cy - by
    local s, tx = ex * fy - ey * fx, min(1, max(-1, fx * 2^537 * 2^537))
    lo, hi, sum, agree = min(lo, s), max(hi, s), sum + s, agree + sx * tx
    xmin, xmax, ymin, ymax = min(xmin, cx), max(xmax, cx), min(ymin, cy), max(ymax, cy)
    bx, by, ex, ey, sx = cx, cy, fx, fy, tx
  end
  local bound = SHARED_BOUND * ((xmax - xmin) * (ymax - ymin)) + TINY
  if max(lo, -hi) > bound and agree == n / 2 - 4 and sum - sum == 0 then
    return min(1, max(-1, (lo + hi) * 2^1000)), xmin, xmax, ymin, ymax
  end
  return nil
end

-- LuaJIT's pass up to 8 vertices, one body for every size (no branch on the size: the traces of
-- a branch per size, each a copy of the rest of the caller, made whole collision calls fall back
-- to the interpreter in some processes, 4 to 36 times slower). As kernel's shoelaceBounds, slot
-- k holds vertex min(k, m), the last repeated for fewer; edge k runs from slot k to slot k + 1,
-- edge 8 back to slot 1 (the closing edge), and el is the edge into vertex m. The turns: at
-- vertex 1 (edge 8 x edge 1), at slots 2 to 7 (edge k - 1 x edge k), at vertex m (el x edge 8).
-- A slot from m on (2k >= n) turns between repeated vertices, 0: lifted out of lo and hi by a
-- pad (2^1000, beyond every bound below the 2^1023 where the turns' sum overflows); its edges
-- are 0, so are their signs and products in the windings' sum.
local PAD = 2^1000

local function vouchJit(points, n)
  if n > 16 or n < 6 then
    if n < 6 then return nil end
    return vouchLoopJit(points, n)
  end
  local x1, y1 = points[1] + 0.0, points[2] + 0.0
  local x2, y2 = points[3] + 0.0, points[4] + 0.0
  local x3, y3 = points[5] + 0.0, points[6] + 0.0
  local j = min(7, n - 1)
  local x4, y4 = points[j] + 0.0, points[j + 1] + 0.0
  j = min(9, n - 1)
  local x5, y5 = points[j] + 0.0, points[j + 1] + 0.0
  j = min(11, n - 1)
  local x6, y6 = points[j] + 0.0, points[j + 1] + 0.0
  j = min(13, n - 1)
  local x7, y7 = points[j] + 0.0, points[j + 1] + 0.0
  local x8, y8 = points[n - 1] + 0.0, points[n] + 0.0
  local xmin, xmax = min(x1, x2, x3, x4, x5, x6, x7, x8), max(x1, x2, x3, x4, x5, x6, x7, x8)
  local ymin, ymax = min(y1, y2, y3, y4, y5, y6, y7, y8), max(y1, y2, y3, y4, y5, y6, y7, y8)
  local e1x, e1y, e2x, e2y = x2 - x1, y2 - y1, x3 - x2, y3 - y2
  local e3x, e3y, e4x, e4y = x4 - x3, y4 - y3, x5 - x4, y5 - y4
  local e5x, e5y, e6x, e6y = x6 - x5, y6 - y5, x7 - x6, y7 - y6
  local e7x, e7y, e8x, e8y = x8 - x7, y8 - y7, x1 - x8, y1 - y8
  local elx, ely = x8 - points[n - 3], y8 - points[n - 2]
  local t1, t2 = e8x * e1y - e8y * e1x, e1x * e2y - e1y * e2x
  local t3, t4 = e2x * e3y - e2y * e3x, e3x * e4y - e3y * e4x
  local t5, t6 = e4x * e5y - e4y * e5x, e5x * e6y - e5y * e6x
  local t7, tm = e6x * e7y - e6y * e7x, elx * e8y - ely * e8x
  local np = n * PAD   -- slot k's pad: PAD when 2k >= n, else 0
  local p3, p4 = max(0, min(PAD, 7 * PAD - np)), max(0, min(PAD, 9 * PAD - np))
  local p5, p6 = max(0, min(PAD, 11 * PAD - np)), max(0, min(PAD, 13 * PAD - np))
  local p7 = max(0, min(PAD, 15 * PAD - np))
  local lo = min(t1, t2, t3 + p3, t4 + p4, t5 + p5, t6 + p6, t7 + p7, tm)
  local hi = max(t1, t2, t3 - p3, t4 - p4, t5 - p5, t6 - p6, t7 - p7, tm)
  local sum = ((t1 + t2) + (t3 + t4)) + ((t5 + t6) + (t7 + tm))
  local s1, s2 = min(1, max(-1, e1x * 2^537 * 2^537)), min(1, max(-1, e2x * 2^537 * 2^537))
  local s3, s4 = min(1, max(-1, e3x * 2^537 * 2^537)), min(1, max(-1, e4x * 2^537 * 2^537))
  local s5, s6 = min(1, max(-1, e5x * 2^537 * 2^537)), min(1, max(-1, e6x * 2^537 * 2^537))
  local s7, s8 = min(1, max(-1, e7x * 2^537 * 2^537)), min(1, max(-1, e8x * 2^537 * 2^537))
  local sl = min(1, max(-1, elx * 2^537 * 2^537))
  local agree = ((s8 * s1 + s1 * s2) + (s2 * s3 + s3 * s4)) + ((s4 * s5 + s5 * s6)
    + (s6 * s7 + sl * s8))
  local bound = SHARED_BOUND * ((xmax - xmin) * (ymax - ymin)) + TINY
  if max(lo, -hi) > bound and agree == n / 2 - 4 and sum - sum == 0 then
    return min(1, max(-1, (lo + hi) * 2^1000)), xmin, xmax, ymin, ymax
  end
  return nil
end

-- PUC Lua's: the box first (the bound), then the turns, each tested as it comes.
local function vouchLoopPuc(points, n)
  local x1, y1 = points[1] + 0.0, points[2] + 0.0
  local xmin, xmax, ymin, ymax, low, high = x1, x1, y1, y1, 1, 1
  for i = 3, n - 1, 2 do
    local x, y = points[i] + 0.0, points[i + 1] + 0.0
    if x < xmin then xmin = x elseif x > xmax then xmax = x end
    if y < ymin then ymin, low = y, i elseif y > ymax then ymax, high = y, i end
  end
  local bound = SHARED_BOUND * ((xmax - xmin) * (ymax - ymin)) + TINY
  local bx, by = points[n - 1] + 0.0, points[n] + 0.0
  local ex, ey = bx - points[n - 3], by - points[n - 2]
  local turn = 1.0   -- the turn at vertex 1 sets the sign
  if ex * (y1 - by) - ey * (x1 - bx) < 0 then turn, bound = -1.0, -bound end
  local flips = 0
  for i = 1, n - 1, 2 do
    local cx, cy = points[i] + 0.0, points[i + 1] + 0.0
    local fx, fy = cx - bx, cy - by
    local s = ex * fy - ey * fx
    -- luacheck: ignore 581 (NaN must fail)
    if turn > 0 then
      if not (s > bound) then return nil end
    elseif not (s < bound) then
      return nil
    end
    local xx = ex * fx
    if xx <= 0 then flips = flips + (xx < 0 and 2 or zeroFlips(ex, fx)) end
    bx, by, ex, ey = cx, cy, fx, fy
  end
  if flips ~= 4 then return nil end
  return turn, xmin, xmax, ymin, ymax, low, high
end

-- PUC Lua's written-out bodies, from 3 to `largest` vertices, by their count of numbers (6 to
-- 2 largest).
local function vouchBodies(largest)
  local byCount = {}
  for m = 3, largest do
    local chunk = assert(loadChunk(vouchSource(m), "=polygon/convex.lua vouch" .. m))
    byCount[2 * m] = chunk(SHARED_BOUND, TINY, zeroFlips)
  end
  return byCount
end

-- PUC Lua's pass for any size: its body from a table (one lookup against a chain of tests).
local vouchPuc
do
  local byCount = vouchBodies(16)
  vouchPuc = function(points, n)
    local body = byCount[n]
    if body then return body(points) end
    if n > 32 then return vouchLoopPuc(points, n) end
    return nil
  end
end

local vouch = JIT and vouchJit or vouchPuc

-- Checks that a flat shape a collision function was given (a table whose first entry the caller
-- has looked at) is a polygon it can take: at least 3 points, convex. Raises the argument error
-- at `level` (as error's, counted from the caller of this function).
local function checkConvex(points, n, fname, argname, level)
  if n < 6 then error(fewPointsMessage(fname, argname, n), level + 1) end
  if not vouch(points, n) then convexCareful(points, n, fname, argname, level + 1) end
end

M.SPLIT_FIX = SPLIT_FIX
M.fewPointsMessage = fewPointsMessage
M.refuseEntries = refuseEntries
M.whyNotConvex = whyNotConvex
M.carefulWalk = carefulWalk
M.vouch = vouch
M.vouchJit = vouchJit
M.vouchPuc = vouchPuc
M.vouchLoopJit = vouchLoopJit
M.vouchLoopPuc = vouchLoopPuc
M.convexCareful = convexCareful
M.checkConvex = checkConvex

return M
