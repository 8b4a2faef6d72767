-- polygon/sat.lua: projection and the separating axis theorem between two convex polygons: the
-- exact boolean and a push that separates. The convex engine behind collide and compound.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local check = require(_PACKAGE .. ".check")
local kernel = require(_PACKAGE .. ".kernel")
local convex = require(_PACKAGE .. ".convex")

local abs, sqrt, huge, min, max = math.abs, math.sqrt, math.huge, math.min, math.max
local checkPoints, checkNumber = check.checkPoints, check.checkNumber
local JIT, EPS, SPLITTER, CROSS_BOUND = kernel.JIT, kernel.EPS, kernel.SPLITTER, kernel.CROSS_BOUND
local crossExact, cross, shoelaceBounds = kernel.crossExact, kernel.cross, kernel.shoelaceBounds
local holdsNonFinite, areaSignOf = kernel.holdsNonFinite, kernel.areaSignOf
local turnAndBounds, EXACT_TOP = kernel.turnAndBounds, kernel.EXACT_TOP
local powerScale, largestMagnitude = kernel.powerScale, kernel.largestMagnitude
local vouch = convex.vouch

local M = {}


-- The range of the polygon projected on the axis (nx, ny), relative to the point (x, y).
-- Returns min, max of (px - x) * nx + (py - y) * ny over the vertices; nil for no points.
function M.projectPolygon(points, x, y, nx, ny)
  local n = checkPoints(points, "projectPolygon")
  checkNumber(x, "projectPolygon", "x")
  checkNumber(y, "projectPolygon", "y")
  checkNumber(nx, "projectPolygon", "nx")
  checkNumber(ny, "projectPolygon", "ny")
  if n < 2 then   -- a Polygon object: its points (point tables raise)
    local inner = type(points[1]) ~= "number" and check.shapeBehind(points, "projectPolygon",
      "points", 2)
    if inner then
      local lo, hi = M.projectPolygon(inner, x, y, nx, ny)
      return lo, hi
    end
    return nil
  end
  x, y = x + 0.0, y + 0.0
  local lo = (points[1] - x) * nx + (points[2] - y) * ny
  local hi = lo
  for i = 3, n - 1, 2 do
    local s = (points[i] - x) * nx + (points[i + 1] - y) * ny
    if s < lo then lo = s elseif s > hi then hi = s end
  end
  return lo, hi
end

-- The range of the projections nx (vx - ax) + ny (vy - ay) over the vertices of points.
-- LuaJIT compiles math.min and math.max to single branch-free instructions, where the unpredictable
-- comparisons would cost it most of the loop; the PUC interpreters call them as functions, so for
-- them plain comparisons are faster. The two bodies compute the same numbers. LuaJIT's
-- returns the whole range (projectRange): one loop for every projection is compiled sooner, from
-- any of its callers, than a short loop of its own.
-- LuaJIT's: the whole range by min and max, one loop (projectRange) for every projection.
local function minProjectionJit(points, n, ax, ay, nx, ny)
  local lo, hi = huge, -huge
  for i = 1, n - 1, 2 do
    local s = nx * (points[i] - ax) + ny * (points[i + 1] - ay)
    lo, hi = min(lo, s), max(hi, s)
  end
  return lo, hi
end

-- PUC Lua's: the least by comparisons, as math.min and math.max are calls there.
local function minProjectionPuc(points, n, ax, ay, nx, ny)
  local lo = huge
  for i = 1, n - 1, 2 do
    local s = nx * (points[i] - ax) + ny * (points[i + 1] - ay)
    if s < lo then lo = s end
  end
  return lo
end

local minProjection = JIT and minProjectionJit or minProjectionPuc

-- The projections above are taken relative to a vertex a of one polygon so that far from the
-- origin they stay as accurate as near it. Their rounding error is at most
-- 4 eps (spanX |nx| + spanY |ny|), where spanX and spanY bound every |vx - ax| and |vy - ay|;
-- a gap within four times that (16 eps: the bound of two projections subtracted, doubled for
-- the rounding of the bound itself) is decided again exactly, with the cross kernel.
local function projectionTolerance(spanX, spanY, nx, ny)
  return 16 * EPS * (spanX * abs(nx) + spanY * abs(ny))
end

-- 1 when d > 0, else 0, without a branch (for LuaJIT: d is a difference of doubles or inf, never
-- NaN; a positive one is at least 2^-1074, which the two factors take above 1, and 0 stays 0).
local function isAbove(d)
  return min(1, max(0, d * 2^1000 * 2^1000))
end

-- The SAT engine's one exact fallback: whether a vertex of points lies strictly on the side
-- `inside` (1 or -1, the sign of the cross product) of the line through c parallel to a -> b
-- (a and b converted to doubles): whether e x (p - c) has that sign for some vertex p, with e
-- = b - a turned by it. Cross's filter, inlined, decides almost every vertex: det = l - r is
-- surely > 0 when det - bound > 0 and surely not when det + bound <= 0 (bound being cross's
-- error bound; no finite subtraction rounds across 0, so those signs are exact); the vertices
-- between go to the exact kernel. The sign is multiplied by the sign +-1, never by an area, so
-- nothing underflows.
-- Two bodies giving the same answer. On LuaJIT a first pass keeps the largest det - bound and
-- det + bound with max and abs, no branch (the branches' side exits, taken from traces that
-- unroll this loop, fail to compile: "NYI: register coalescing too complex"), and counts
-- the vertices it cannot place, keeping the first and the last. When it cannot decide, at most
-- two of them (a touching pair's shared edge, a vertex on the edge) go to onLineSigns, an exact
-- test of both without a branch when their differences are exact, else to crossExact, whose
-- stage B decides all but exactly collinear ones with inexact differences (through cross, the
-- vertices near the line take its filter's side exit, and those side traces fail to compile
-- too), by two calls, cheaper than a pass over every vertex; more by a second pass with no
-- early exit (an exit in it makes LuaJIT abort the loop's trace, "leaving loop in root
-- trace"). On PUC Lua one pass returns at the first vertex surely inside, and calls crossExact
-- only for the vertices the filter cannot place, with no second pass: cross's own
-- filter, on the same products turned by `inside`, could not place them either, short of a det
-- exactly at its bound, whose sign crossExact gives too.
-- For vertexInside: whether its test of vertices p and q against the line can be trusted
-- (`unsafe` 0), and the larger of their exact signs turned by `inside` (see its use).
local function onLineSigns(ax, ay, bx, by, cx, cy, inside, px, py, qx, qy)
  local bxd, byd = bx + 0.0, by + 0.0
  local ux, uy = bxd - ax, byd - ay
  local t = bxd - ux
  local unsafe = abs((bxd - (ux + t)) + (t - ax))
  t = byd - uy
  unsafe = unsafe + abs((byd - (uy + t)) + (t - ay))
  ux, uy = ux * inside, uy * inside
  local pdx, pdy, qdx, qdy = px - cx, py - cy, qx - cx, qy - cy
  t = px - pdx
  unsafe = unsafe + abs((px - (pdx + t)) + (t - cx))
  t = py - pdy
  unsafe = unsafe + abs((py - (pdy + t)) + (t - cy))
  t = qx - qdx
  unsafe = unsafe + abs((qx - (qdx + t)) + (t - cx))
  t = qy - qdy
  unsafe = unsafe + abs((qy - (qdy + t)) + (t - cy))
  local aux, auy, apdx, apdy, aqdx, aqdy = abs(ux), abs(uy), abs(pdx), abs(pdy), abs(qdx),
    abs(qdy)
  local pl, pr, ql, qr = ux * pdy, uy * pdx, ux * qdy, uy * qdx   -- (p's l and r, q's)
  unsafe = unsafe + max(0, max(aux, auy, apdx, apdy, aqdx, aqdy) - 2^500,
    min(aux, apdy, 2^-900 - abs(pl)), min(auy, apdx, 2^-900 - abs(pr)),
    min(aux, aqdy, 2^-900 - abs(ql)), min(auy, aqdx, 2^-900 - abs(qr)))
  -- the splits into 26-bit halves, and the products' errors (Dekker's)
  t = SPLITTER * ux
  local uxh = t - (t - ux)
  local uxl = ux - uxh
  t = SPLITTER * uy
  local uyh = t - (t - uy)
  local uyl = uy - uyh
  t = SPLITTER * pdx
  local dxh = t - (t - pdx)
  local dxl = pdx - dxh
  t = SPLITTER * pdy
  local dyh = t - (t - pdy)
  local dyl = pdy - dyh
  local det = pl - pr
  local low = (uxl * dyl - (((pl - uxh * dyh) - uxl * dyh) - uxh * dyl))
    - (uyl * dxl - (((pr - uyh * dxh) - uyl * dxh) - uyh * dxl))
  local pSign = det + low * (1 - min(abs(det) * 2^1000 * 2^1000, 1))
  t = SPLITTER * qdx
  dxh = t - (t - qdx)
  dxl = qdx - dxh
  t = SPLITTER * qdy
  dyh = t - (t - qdy)
  dyl = qdy - dyh
  det = ql - qr
  low = (uxl * dyl - (((ql - uxh * dyh) - uxl * dyh) - uxh * dyl))
    - (uyl * dxl - (((qr - uyh * dxh) - uyl * dxh) - uyh * dxl))
  local qSign = det + low * (1 - min(abs(det) * 2^1000 * 2^1000, 1))
  return unsafe, max(pSign, qSign)
end

-- vertexInsideJit stays whole (about 120 lines, 8 vertices written out): with a step function
-- per vertex LuaJIT's traces abort.
-- LuaJIT's: branch-free passes, then onLineSigns for at most two vertices (see above).
local function vertexInsideJit(ax, ay, bx, by, cx, cy, inside, points, n)
  cx, cy = cx + 0.0, cy + 0.0
  local ex, ey = ((bx + 0.0) - ax) * inside, ((by + 0.0) - ay) * inside
  local sure, maybe = -huge, -huge
  -- how many vertices are not surely outside, and the first and the last of them
  local open, first, last = 0, 2^60, 0
  if n > 16 then
    for i = 1, n - 1, 2 do
      local l, r = ex * (points[i + 1] - cy), ey * (points[i] - cx)
      local det, bound = l - r, CROSS_BOUND * (abs(l) + abs(r))
      sure, maybe = max(sure, det - bound), max(maybe, det + bound)
      local unsure = isAbove(det + bound)
      open, first, last = open + unsure, min(first, i + (1 - unsure) * 2^60),
        max(last, i * unsure)
    end
  else
    -- Up to 8 vertices written out, the last one repeated for fewer and counted once: a loop
    -- of 6 to 8 steps here is copied unrolled by the side trace that reaches it from
    -- reachPast, one copy per polygon size, whose exits for the other sizes fail to compile
    -- ("NYI: register coalescing too complex"). A loop of a constant 8 steps, as faceAndFar's,
    -- has no such exits either, but is slower here; each vertex through a small step function
    -- returning the five numbers brings those aborts back.
    local i, l, r, det, bound, unsure
    i = 1
    l, r = ex * (points[i + 1] - cy), ey * (points[i] - cx)
    det, bound = l - r, CROSS_BOUND * (abs(l) + abs(r))
    sure, maybe = max(sure, det - bound), max(maybe, det + bound)
    unsure = isAbove(det + bound)
    open, first, last = open + unsure, min(first, i + (1 - unsure) * 2^60), max(last, i * unsure)
    i = min(3, n - 1)
    l, r = ex * (points[i + 1] - cy), ey * (points[i] - cx)
    det, bound = l - r, CROSS_BOUND * (abs(l) + abs(r))
    sure, maybe = max(sure, det - bound), max(maybe, det + bound)
    unsure = isAbove(det + bound)
    open, first, last = open + unsure * isAbove(n - 4), min(first, i + (1 - unsure) * 2^60),
      max(last, i * unsure)
    i = min(5, n - 1)
    l, r = ex * (points[i + 1] - cy), ey * (points[i] - cx)
    det, bound = l - r, CROSS_BOUND * (abs(l) + abs(r))
    sure, maybe = max(sure, det - bound), max(maybe, det + bound)
    unsure = isAbove(det + bound)
    open, first, last = open + unsure * isAbove(n - 6), min(first, i + (1 - unsure) * 2^60),
      max(last, i * unsure)
    i = min(7, n - 1)
    l, r = ex * (points[i + 1] - cy), ey * (points[i] - cx)
    det, bound = l - r, CROSS_BOUND * (abs(l) + abs(r))
    sure, maybe = max(sure, det - bound), max(maybe, det + bound)
    unsure = isAbove(det + bound)
    open, first, last = open + unsure * isAbove(n - 8), min(first, i + (1 - unsure) * 2^60),
      max(last, i * unsure)
    i = min(9, n - 1)
    l, r = ex * (points[i + 1] - cy), ey * (points[i] - cx)
    det, bound = l - r, CROSS_BOUND * (abs(l) + abs(r))
    sure, maybe = max(sure, det - bound), max(maybe, det + bound)
    unsure = isAbove(det + bound)
    open, first, last = open + unsure * isAbove(n - 10), min(first, i + (1 - unsure) * 2^60),
      max(last, i * unsure)
    i = min(11, n - 1)
    l, r = ex * (points[i + 1] - cy), ey * (points[i] - cx)
    det, bound = l - r, CROSS_BOUND * (abs(l) + abs(r))
    sure, maybe = max(sure, det - bound), max(maybe, det + bound)
    unsure = isAbove(det + bound)
    open, first, last = open + unsure * isAbove(n - 12), min(first, i + (1 - unsure) * 2^60),
      max(last, i * unsure)
    i = min(13, n - 1)
    l, r = ex * (points[i + 1] - cy), ey * (points[i] - cx)
    det, bound = l - r, CROSS_BOUND * (abs(l) + abs(r))
    sure, maybe = max(sure, det - bound), max(maybe, det + bound)
    unsure = isAbove(det + bound)
    open, first, last = open + unsure * isAbove(n - 14), min(first, i + (1 - unsure) * 2^60),
      max(last, i * unsure)
    i = n - 1
    l, r = ex * (points[i + 1] - cy), ey * (points[i] - cx)
    det, bound = l - r, CROSS_BOUND * (abs(l) + abs(r))
    sure, maybe = max(sure, det - bound), max(maybe, det + bound)
    unsure = isAbove(det + bound)
    open, first, last = open + unsure, min(first, i + (1 - unsure) * 2^60), max(last, i * unsure)
  end
  if sure > 0 then return true end
  if maybe <= 0 then return false end
  if open <= 2 then   -- (as on a touching pair's shared edge, or a vertex on an edge)
    -- Both vertices at once, exactly, without a branch, when every difference is exact (the
    -- usual case: a vertex on the line, nearby coordinates). Per vertex p, with u = (b - a)
    -- turned by `inside` and d = p - c: l = ux dy and r = uy dx rounded. Rounding being
    -- monotone (in the subnormal range too), l ~= r orders l and r as the exact products, and
    -- l - r, nonzero (gradual underflow), has the sign; when l = r the exact difference is
    -- pl - ql, the products' rounding errors by Dekker's split, whose subtraction's sign is
    -- exact. The value used is l - r + (pl - ql) z, z being 1 when l - r is 0 and 0 otherwise.
    -- It is only trusted when `unsafe` below is 0: every difference's TwoDiff error is 0; every
    -- |difference| is at most 2^500 (no product, split or step of Dekker's overflows); and no
    -- product of two nonzero differences is below 2^-900 in magnitude (then its factors'
    -- exponents sum to at least -902, every step of Dekker's is a multiple of 2^-1006 and
    -- exact, as without underflow; a zero factor makes l, pl and every step 0). NaN or inf
    -- anywhere makes `unsafe` NaN or positive. Otherwise both vertices go to crossExact.
    -- Cheaper than two crossExact calls always. Written inline here, the guard's snapshot would
    -- keep every temporary alive and spill them; in a function they die at its return.
    local px, py, qx, qy = points[first] + 0.0, points[first + 1] + 0.0, points[last] + 0.0,
      points[last + 1] + 0.0
    local unsafe, sign = onLineSigns(ax, ay, bx, by, cx, cy, inside, px, py, qx, qy)
    if unsafe == 0 then return sign > 0 end
    -- (each sign turned before the max: main's max(s1, s2) * inside missed a vertex inside
    -- next to one on the line when inside = -1, as the touching spec's one-ulp nudges found)
    return max(crossExact(ax, ay, bx, by, cx, cy, px, py) * inside,
      crossExact(ax, ay, bx, by, cx, cy, qx, qy) * inside) > 0
  end
  local found = 0.0
  for i = 1, n - 1, 2 do
    found = max(found, crossExact(ax, ay, bx, by, cx, cy, points[i] + 0.0, points[i + 1] + 0.0)
      * inside)
  end
  return found > 0
end

-- PUC Lua's: one pass that returns at the first vertex surely inside (see above).
local function vertexInsidePuc(ax, ay, bx, by, cx, cy, inside, points, n)
  cx, cy = cx + 0.0, cy + 0.0
  local ex, ey = ((bx + 0.0) - ax) * inside, ((by + 0.0) - ay) * inside
  -- (the filter without abs: the bound CROSS_BOUND (|l| + |r|) rounds to the larger of |t|,
  -- t = CROSS_BOUND (l + r), and that bound times |det|, which is below |det|: so det - bound
  -- > 0 exactly when det > t and det > -t, and det + bound <= 0 exactly when neither holds)
  local crossBound = CROSS_BOUND   -- (a local: an upvalue is read by an instruction of its own)
  for i = 1, n - 1, 2 do
    -- (as read: cx and cy are doubles, so the differences convert a Lua 5.3+ integer, and
    -- crossExact takes what cross takes)
    local px, py = points[i], points[i + 1]
    local l, r = ex * (py - cy), ey * (px - cx)
    local det, t = l - r, crossBound * (l + r)
    if det > t or det > -t then   -- not surely outside
      if det > t and det > -t then return true end   -- surely inside
      -- The exact sign, short of the zeros known without it: p = c, and p = b on the line
      -- through a (c = a), the far end of a touching pair's shared edge (a frequent call of
      -- crossExact from here)
      if (px ~= cx or py ~= cy) and (px ~= bx or py ~= by or cx ~= ax or cy ~= ay)
          and crossExact(ax, ay, bx, by, cx, cy, px, py) * inside > 0 then
        return true
      end
    end
  end
  return false
end

local vertexInside = JIT and vertexInsideJit or vertexInsidePuc

-- The index of a vertex of points deepest on the side `inside` of the edge a -> b, decided
-- exactly: v lies deeper than e when (b - a) x (v - e) has the sign `inside`.
local function deepestVertex(ax, ay, bx, by, inside, points, n)
  local best, ex, ey = 1, points[1], points[2]
  for i = 3, n - 1, 2 do
    local vx, vy = points[i], points[i + 1]
    if cross(ax, ay, bx, by, ex, ey, vx, vy) * inside > 0 then best, ex, ey = i, vx, vy end
  end
  return best
end

-- The separating axis test of two convex polygons, face by face: for each edge a -> b of
-- `edges` (turn: the sign of its area, 1 or -1), how deep `other` (turnOther likewise) reaches
-- past it along its outward normal n. Two convex polygons overlap exactly when every edge of
-- both is reached past, and the least such depth is the least penetration over all the
-- tutorial's axes and both ends of their ranges (the overlap of the far ends is never smaller:
-- it is the support of the Minkowski difference in a direction that is not a face of it). So
-- one polygon is projected per axis where the tutorial projects both; the edge itself is the
-- other's range end, at 0.
-- Returns false on a separating or touching axis; otherwise the least penetration's squared
-- depth o (o / |n|^2) (neither overflows nor underflows in the exact range), its overlap
-- o >= 0 along n (the depth is o / |n|), and the index of its edge's end b.
-- The least projection lo's rounding error is below 8 eps (spanX |nx| + spanY |ny|) (see
-- projectionTolerance), which is at most 8 eps |n| sqrt(spanX^2 + spanY^2) (Cauchy-Schwarz):
-- so an edge whose squared depth lo^2 / |n|^2 exceeds tolSq = (16 eps)^2 (spanX^2 + spanY^2)
-- has the sign of lo for sure, with room for the rounding of both squares, and one comparison
-- with a number computed once per call replaces a tolerance per edge. Within it, vertexInside
-- decides exactly.
-- Two bodies. On LuaJIT, for `other` of at most 8 vertices, one loop over the edges projects
-- all of other's vertices in one expression (the last one repeated for fewer, harmless to a
-- min), with no inner loop and no data-dependent exit: LuaJIT hoists the vertices' loads out
-- of the loop, the edges do not wait for each other (the least is kept by selection with
-- isAbove). Each edge's key is its squared depth, negated when the edge is apart, so that the
-- least key also names an edge within tolSq or apart (a touching pair's), if there is one,
-- which is decided after the loop from the loop's own numbers; if it is reached past after
-- all, reachPastFull decides from the start, as it does for larger polygons and where a
-- selection would not keep -0.0 or NaN as the comparisons do.
-- Any such edge will do: an edge decided apart makes the answer false whichever is examined,
-- and otherwise reachPastFull decides. The loop has no exit at such an edge: side traces that
-- reach the loop before it is compiled copy it, and the copy's exits fail to compile ("NYI:
-- register coalescing too complex").
-- reachPastFull is one flat loop over every (edge, vertex) pair, whose edge's verdict is a side
-- exit of its trace taken at every edge's last vertex (nested loops over a polygon's 6 to 8
-- vertices fail to become traces of their own, "leaving loop in root trace", and their
-- unrolled copies' side traces fail to compile). The one loop over the edges is faster, most of
-- all on overlapping pairs. PUC Lua runs reachBoth instead, below.

-- reachPast's and reachBoth's tolerance for polygons within a box of sides spanX and spanY:
-- (16 eps)^2 (spanX^2 + spanY^2), or every axis decided exactly where that square would
-- underflow (boxes below about 2^-450 only).
local function squaredTolerance(spanX, spanY)
  local tolSq = 2^-98 * (spanX * spanX + spanY * spanY)
  if tolSq < 2^-1000 then return huge end
  return tolSq
end

local function reachPastFull(edges, ne, turn, other, no, tolSq)
  local leastSquared, leastOverlap, leastEnd = huge, 0.0, 1
  local ia, ib = ne - 1, 1
  local ax, ay = edges[ia] + 0.0, edges[ia + 1] + 0.0
  local nx, ny = ((edges[2] + 0.0) - ay) * turn, (ax - edges[1]) * turn   -- outward
  local lo, i = huge, 1
  for _ = 1, ne * no / 4 do
    lo = min(lo, nx * (other[i] - ax) + ny * (other[i + 1] - ay))
    if i < no - 1 then
      i = i + 2
    else   -- the edge a -> b is done
      if nx ~= 0 or ny ~= 0 then   -- a repeated vertex gives no axis
        local squaredDepth = lo * (lo / (nx * nx + ny * ny))
        if squaredDepth <= tolSq then   -- decide exactly
          if not vertexInside(ax, ay, edges[ib], edges[ib + 1], ax, ay, turn, other, no) then
            return false
          end
          if lo > 0 then lo, squaredDepth = 0.0, 0.0 end
        elseif lo > 0 then   -- surely apart
          return false
        end
        if squaredDepth < leastSquared then   -- keep the least
          leastSquared, leastOverlap, leastEnd = squaredDepth, -lo, ib
        end
      end
      -- the next edge (after the last, the first again: its normal is never used)
      ia, ib = ib, ib + 2
      local jb = (ib - 1) % ne + 1
      ax, ay = edges[ia] + 0.0, edges[ia + 1] + 0.0
      nx, ny = ((edges[jb + 1] + 0.0) - ay) * turn, (ax - edges[jb]) * turn
      lo, i = huge, 1
    end
  end
  return leastSquared, leastOverlap, leastEnd
end

local function reachPast(edges, ne, turn, other, no, tolSq)
  if no > 16 then
    local least, overlap, edgeEnd = reachPastFull(edges, ne, turn, other, no, tolSq)
    return least, overlap, edgeEnd
  end
  -- the least key and its overlap and edge end; the largest key (see below)
  local leastKey, leastOverlap, leastEnd, largestKey = huge, 0.0, 1, -huge
  -- other's vertices, the last one repeated for fewer than 8 (harmless to a min), read before
  -- the loop: its trace then takes them from the stack, where reading them in the loop makes it
  -- convert and check every index on each entry (the reads, in the calling trace, share
  -- shoelaceBounds' there for the first call)
  -- (vertices 2 and 3 at constant indices: convexPenetration hands on 3 vertices or more)
  local x1, y1, x2, y2, x3, y3 = other[1], other[2], other[3], other[4], other[5], other[6]
  local j = min(7, no - 1)
  local x4, y4 = other[j], other[j + 1]
  j = min(9, no - 1)
  local x5, y5 = other[j], other[j + 1]
  j = min(11, no - 1)
  local x6, y6 = other[j], other[j + 1]
  j = min(13, no - 1)
  local x7, y7 = other[j], other[j + 1]
  local x8, y8 = other[no - 1], other[no]
  local ia = ne - 1
  for ib = 1, ne - 1, 2 do
    -- (no + 0.0 here: LuaJIT has no integers, and a -0.0 changes only the sign of a zero
    -- projection, which no key or decision below tells from +0.0; three additions an edge)
    local ax, ay = edges[ia], edges[ia + 1]
    local nx, ny = (edges[ib + 1] - ay) * turn, (ax - edges[ib]) * turn   -- outward
    -- as a tree of mins, not a chain: the edges' work overlaps more where each is shorter
    local lo = min(
      min(min(nx * (x1 - ax) + ny * (y1 - ay), nx * (x2 - ax) + ny * (y2 - ay)),
          min(nx * (x3 - ax) + ny * (y3 - ay), nx * (x4 - ax) + ny * (y4 - ay))),
      min(min(nx * (x5 - ax) + ny * (y5 - ay), nx * (x6 - ax) + ny * (y6 - ay)),
          min(nx * (x7 - ax) + ny * (y7 - ay), nx * (x8 - ax) + ny * (y8 - ay))))
    -- The edge's key: its squared depth, negated when it is apart (lo > 0). An edge is taken
    -- as it is when surely reached past (lo < 0) by a finite depth beyond tolSq: when its key
    -- is above tolSq and below 2^1023; so the least key is at most tolSq exactly when some
    -- edge is not (apart, within tolSq, no axis), and then it is such an edge. (A repeated
    -- vertex gives no axis: n = 0, lo = 0, and the key 0, not 0 / 0.)
    local overlap = -lo
    local key = overlap * (abs(overlap) / max(nx * nx + ny * ny, 2^-1074))
    local better = isAbove(leastKey - key)
    leastKey, largestKey = min(leastKey, key), max(largestKey, key)
    leastOverlap = better * overlap + (1 - better) * leastOverlap
    leastEnd = better * ib + (1 - better) * leastEnd
    ia = ib
  end
  -- (the vertices' locals dead from here: kept alive, the side traces leaving the loop take them
  -- over and fail to compile, "NYI: register coalescing too complex")
  x1, y1, x2, y2, x3, y3, x4, y4, x5, y5, x6, y6, x7, y7, x8, y8 = nil   -- luacheck: ignore 311 532
  if not (leastKey > tolSq and largestKey < 2^1023) then
    -- The edge of the least key: apart, surely or decided exactly; else (reached past exactly,
    -- no axis, keys beyond 2^1023 or -2^1023 only beyond the exact range, where no edge is
    -- chosen) reachPastFull decides from the start. (The loop's overlap is not used then.)
    if leastKey > -2^1023 and largestKey < 2^1023 then
      ia = leastEnd == 1 and ne - 1 or leastEnd - 2
      local ax, ay = edges[ia] + 0.0, edges[ia + 1] + 0.0
      local nx, ny = ((edges[leastEnd + 1] + 0.0) - ay) * turn, (ax - edges[leastEnd]) * turn
      if nx * nx + ny * ny > 0 then   -- (then the key is the squared depth, signed, unclamped)
        if leastKey < -tolSq then return false end   -- surely apart
        if leastKey <= tolSq and not vertexInside(ax, ay, edges[leastEnd], edges[leastEnd + 1],
                                                  ax, ay, turn, other, no) then
          return false
        end
      end
    end
    local least, overlap, edgeEnd = reachPastFull(edges, ne, turn, other, no, tolSq)
    return least, overlap, edgeEnd
  end
  return leastKey, leastOverlap, leastEnd
end

-- PUC Lua: the least over both polygons' edges at once (reachPast's results and the polygon
-- owning the edge, 1 or 2; ties go to polygon 1, then to the lower edge end, as on LuaJIT).
-- Rotating calipers over the edges of the Minkowski difference p1 - p2: both polygons' edges
-- in the order of their normals' angles, p2's taken backwards when it winds the other way.
-- Taking an edge of p1, p2's current vertex is the one deepest past it; taking one of p2,
-- p1's current vertex; the next edge is whichever of the two candidates turns least from the
-- last, the sign of their cross product (each turns less than a half turn from it). So an
-- edge costs one cross product and one projection, and only the first scans every vertex.
-- A cross product rounded to the wrong sign (within 3 eps |e| |f| of zero: nearly parallel
-- edges e and f) takes two edges in the wrong order, and the vertex used for the first lies
-- within that of the deepest along its normal; a run of such edges errs by less than 3 eps
-- |e| times their length, so the projections err by less than 8 eps |n| sqrt(spanX^2 +
-- spanY^2) in all (4 of them the projection's rounding), inside tolSq; where they pass it,
-- reachBoth and reachPast (both ways) give the same verdict. Their numbers are the same bit for
-- bit when both polygons wind the same way; otherwise p2's edges are projected from their other
-- end here, which changes the last bits (spec/bodies_sat_spec.lua). One walk over both
-- polygons, not one each: fewer instructions. (On LuaJIT the choice of edge, a data-dependent
-- branch per edge, would be a side trace, as the walks' exits were.)
-- reachBoth stays whole (about 110 lines): it is the hot loop of every PUC collision, and a call
-- per step costs more than the step.

-- Whether other reaches past the edge of `edges` ending at vertex index k, decided exactly.
local function edgeReached(edges, ne, turn, other, no, k)
  local j = k == 1 and ne - 1 or k - 2
  local ax, ay = edges[j], edges[j + 1]
  return vertexInside(ax, ay, edges[k], edges[k + 1], ax, ay, turn, other, no)
end

local function reachBoth(p1, n1, turn1, p2, n2, turn2, tolSq, top1, bottom2)
  -- each edge is known by a key: its end's index in p1, or n1 + its end's index in p2, so
  -- that the order of keys is the order of the ties' rule
  local least, leastOverlap, leastKey = huge, 0.0, 1
  -- The walk starts at a direction whose deepest vertices are known: with top1, the flat index
  -- of a vertex of p1 of largest y, and bottom2, one of p2 of least y (turnAndBounds'), at the
  -- outward direction (0, 1): p1's edges from top1 on and p2's from bottom2 on all come at or
  -- after it, within a half turn (with a tie, an edge whose normal is (0, 1) comes first or
  -- last, either way in order). Without them (pairOverlaps), at p1's first edge, p2's deepest
  -- vertex found over every vertex. Either way from p1's first edge with a normal there (the
  -- area is not zero, so there is one): c -> cn, cn at kn. The known start saves the scan, at
  -- the cost of the indices on every call.
  local lo
  local kn, d = top1 and top1 + 2 or 1, bottom2
  if kn > n1 then kn = 1 end
  local cx, cy = p1[kn == 1 and n1 - 1 or kn - 2] + 0.0, p1[kn == 1 and n1 or kn - 1] + 0.0
  local cnx, cny = p1[kn] + 0.0, p1[kn + 1] + 0.0
  while cnx == cx and cny == cy do
    kn = kn + 2
    if kn > n1 then kn = 1 end
    cx, cy, cnx, cny = cnx, cny, p1[kn] + 0.0, p1[kn + 1] + 0.0
  end
  local ex, ey = cnx - cx, cny - cy
  local nx, ny = ey * turn1, -ex * turn1   -- outward
  if not d then
    -- p2's vertex d deepest past c -> cn, over every vertex
    d, lo = 1, nx * (p2[1] - cx) + ny * (p2[2] - cy)
    for i = 3, n2 - 1, 2 do
      local s = nx * (p2[i] - cx) + ny * (p2[i + 1] - cy)
      if s < lo then
        d = i
        lo = s
      end
    end
  end
  -- the vertex after d, dn, and f = d - dn, the edge of -p2 from -d
  local step = turn2 == turn1 and 2 or -2
  local dn = d + step
  if dn > n2 then dn = 1 elseif dn < 1 then dn = n2 - 1 end
  local dx, dy, dnx, dny = p2[d] + 0.0, p2[d + 1] + 0.0, p2[dn] + 0.0, p2[dn + 1] + 0.0
  -- f is kept turned by turn1 (exact): the cross product below needs no turn then, and -f's
  -- outward normal is (-fy, fx)
  local fx, fy = (dx - dnx) * turn1, (dy - dny) * turn1
  -- the coordinates of each polygon's edges still to take, an integer on Lua 5.3+ as the
  -- loop's count (n1 / 2 would be a float)
  local left1, left2 = n1, n2
  local back = -turn1
  -- the key of p2's edge from d is keyAhead + d (its end is dn when p2 is taken forwards, d
  -- backwards), but n1 + 1 past keyWrap (dn wrapped round to 1)
  local keyAhead, keyWrap = n1 + (step > 0 and 2 or 0), n1 + n2
  local key, squaredNormal
  -- (one assignment per statement in this loop: Lua 5.4 gives a multiple assignment a move
  -- through a temporary per value)
  for _ = 2, n1 + n2, 2 do
    -- the next edge's squared outward normal and the least projection lo on that normal of the
    -- other polygon (from its current vertex), the edge's key; then its polygon moves on
    local turnOn = ex * fy - ey * fx   -- > 0: f turns on from e
    if left1 > 0 and (turnOn > 0 or turnOn == 0 and (fx ~= 0 or fy ~= 0)) or left2 == 0 then
      nx = ey * turn1
      ny = ex * back
      squaredNormal = nx * nx + ny * ny
      lo = nx * (dx - cx) + ny * (dy - cy)
      key = kn
      left1 = left1 - 2
      cx = cnx
      cy = cny
      kn = kn + 2
      if kn > n1 then kn = 1 end
      cnx = p1[kn] + 0.0
      cny = p1[kn + 1] + 0.0
      ex = cnx - cx
      ey = cny - cy
    else   -- the edge d -> dn of p2, which is -f
      squaredNormal = fy * fy + fx * fx
      lo = fx * (cy - dy) - fy * (cx - dx)
      key = keyAhead + d
      if key > keyWrap then key = n1 + 1 end
      left2 = left2 - 2
      d = dn
      dx = dnx
      dy = dny
      dn = d + step
      if dn > n2 then dn = 1 elseif dn < 1 then dn = n2 - 1 end
      dnx = p2[dn] + 0.0
      dny = p2[dn + 1] + 0.0
      fx = (dx - dnx) * turn1
      fy = (dy - dny) * turn1
    end
    -- (a repeated vertex gives no axis: n = 0, lo = 0, and the squared depth 0 / 0 is NaN,
    -- which every comparison below passes by)
    local squaredDepth = lo * (lo / squaredNormal)
    if squaredDepth <= tolSq then   -- decide exactly
      if key < n1 and not edgeReached(p1, n1, turn1, p2, n2, key)
          or key > n1 and not edgeReached(p2, n2, turn2, p1, n1, key - n1) then
        return false
      end
      if lo > 0 then lo, squaredDepth = 0.0, 0.0 end
    elseif lo > 0 then   -- surely apart
      return false
    end
    if squaredDepth <= least and (squaredDepth < least or key < leastKey) then
      least = squaredDepth
      leastOverlap = -lo
      leastKey = key
    end
  end
  if leastKey < n1 then return least, leastOverlap, leastKey, 1 end
  return least, leastOverlap, leastKey - n1, 2
end

-- For reachPastBothEnds: -lo and hi - own, where [lo, hi] is the range of the projections
-- n . (v - a) of other's vertices and own the least of edges' own. On LuaJIT one loop over both
-- polygons at once, the shorter one's last vertex read again (harmless to a min or max): half
-- the loops of the two calls, each a loop other traces could copy unrolled. Up to 8 vertices it
-- always runs 8 steps: a loop whose count is a constant has no side exit for the other polygon
-- sizes in the copies. Those exits fail to compile ("NYI: register coalescing too complex"); the
-- constant count costs a little time.
-- LuaJIT's: one loop over both polygons, 8 steps for up to 8 vertices.
local function faceAndFarJit(edges, ne, other, no, ax, ay, nx, ny)
  local lo, hi, own = huge, -huge, huge
  -- (a trace taking the first choice records the literal 15: a constant count)
  local last = ne <= 16 and no <= 16 and 15 or max(ne, no) - 1
  for i = 1, last, 2 do
    local j, k = min(i, no - 1), min(i, ne - 1)
    local s = nx * (other[j] - ax) + ny * (other[j + 1] - ay)
    lo, hi = min(lo, s), max(hi, s)
    own = min(own, nx * (edges[k] - ax) + ny * (edges[k + 1] - ay))
  end
  return -lo, hi - own
end

-- PUC Lua's: minProjection's and projectRange's loops written out, two calls an edge fewer.
local function faceAndFarPuc(edges, ne, other, no, ax, ay, nx, ny)
  local lo, hi = huge, -huge
  for i = 1, no - 1, 2 do
    local s = nx * (other[i] - ax) + ny * (other[i + 1] - ay)
    if s < lo then lo = s end
    if s > hi then hi = s end
  end
  local own = huge
  for i = 1, ne - 1, 2 do
    local s = nx * (edges[i] - ax) + ny * (edges[i + 1] - ay)
    if s < own then own = s end
  end
  return -lo, hi - own
end

local faceAndFar = JIT and faceAndFarJit or faceAndFarPuc

-- reachPast for the one-sided functions, which test the axes of `edges` only: both ends of each
-- range, so also how far `other` reaches beyond the vertex of `edges` deepest inside, along -n.
-- Returns false, or the squared depth, o, the edge's end and, when the least is at the far end,
-- the index of that deepest vertex (else 0).
-- The loop keeps only numbers, and across its two inner loops only the edge's start and normal
-- (its end is read again where needed, the tolerance computed after them); the deepest vertex
-- of the least is found once, after the loop. On LuaJIT a trace of the caller that runs on into
-- a loop not yet compiled unrolls it, and the side traces leaving that copy inherit every value
-- alive there: with a false-or-index, the edge's end and the tolerance alive too they need more
-- registers than there are ("NYI: register coalescing too complex", retried on every call).
local function reachPastBothEnds(edges, ne, turn, other, no, span)
  local leastSquared, leastOverlap, leastEnd, leastAtFar = huge, 0.0, 1, 0
  local ia = ne - 1
  for ib = 1, ne - 1, 2 do
    local ax, ay = edges[ia] + 0.0, edges[ia + 1] + 0.0
    local nx, ny = ((edges[ib + 1] + 0.0) - ay) * turn, (ax - edges[ib]) * turn   -- outward
    if nx ~= 0 or ny ~= 0 then   -- a repeated vertex gives no axis
      -- face: how far other must move along n to clear the edge; far: against n, past the
      -- deepest vertex of edges
      local face, far = faceAndFar(edges, ne, other, no, ax, ay, nx, ny)
      local tol = projectionTolerance(span, span, nx, ny)
      if face <= tol then
        if face < -tol or not vertexInside(ax, ay, edges[ib], edges[ib + 1], ax, ay, turn,
                                           other, no) then
          return false
        end
        if face < 0 then face = 0.0 end
      end
      if far <= tol then
        local bx, by = edges[ib], edges[ib + 1]
        local ic = deepestVertex(ax, ay, bx, by, turn, edges, ne)
        if far < -tol or not vertexInside(ax, ay, bx, by, edges[ic], edges[ic + 1], -turn,
                                          other, no) then
          return false
        end
        if far < 0 then far = 0.0 end
      end
      if JIT then   -- keep the least, selecting without a branch (see isAbove)
        local depth = min(face, far)
        local squaredDepth = depth * (depth / (nx * nx + ny * ny))
        -- NaN or inf only where the squared normal underflows, outside the exact range: such an
        -- axis is never chosen (as by the comparison below), and isAbove never sees a NaN
        if squaredDepth < huge then
          local better = isAbove(leastSquared - squaredDepth)
          leastSquared = min(leastSquared, squaredDepth)
          -- (b x + (1 - b) y with b 0 or 1 is x or y exactly; x + b (y - x) would round)
          leastOverlap = better * depth + (1 - better) * leastOverlap
          leastEnd = better * ib + (1 - better) * leastEnd
          leastAtFar = better * isAbove(face - far) + (1 - better) * leastAtFar
        end
      else
        local depth = face < far and face or far
        local squaredDepth = depth * (depth / (nx * nx + ny * ny))
        if squaredDepth < leastSquared then   -- keep the least
          leastSquared, leastOverlap, leastEnd = squaredDepth, depth, ib
          leastAtFar = far < face and 1 or 0
        end
      end
    end
    ia = ib
  end
  if leastAtFar == 0 then return leastSquared, leastOverlap, leastEnd, 0 end
  ia = leastEnd == 1 and ne - 1 or leastEnd - 2
  local deepest = deepestVertex(edges[ia], edges[ia + 1], edges[leastEnd], edges[leastEnd + 1], turn,
    edges, ne)
  return leastSquared, leastOverlap, leastEnd, deepest
end

-- The unit vector along (nx, ny) and the length of (nx, ny), scaled first by the larger
-- component so that neither squaring overflows nor underflows. (nx, ny) must not be (0, 0).
-- Two bodies computing the same numbers: max, not a branch, on LuaJIT (the branch's side exits,
-- taken for half of all directions, were side traces of the callers' big traces; max(|ny|, |nx|)
-- keeps |ny| on ties, as the branch did); comparisons on PUC Lua, where abs and max are three
-- C calls (|x| of -0 is -0 there, never the larger of the two: (nx, ny) is not (0, 0)).
-- LuaJIT's: max and abs, no branch.
local function unitJit(nx, ny)
  local m = max(abs(ny), abs(nx))
  nx, ny = nx / m, ny / m
  local len = sqrt(nx * nx + ny * ny)
  return nx / len, ny / len, len * m
end

-- PUC Lua's: comparisons, where abs and max are C calls.
local function unitPuc(nx, ny)
  local m = ny < 0 and -ny or ny
  local mx = nx < 0 and -nx or nx
  if m < mx then m = mx end
  nx = nx / m
  ny = ny / m
  local len = sqrt(nx * nx + ny * ny)
  return nx / len, ny / len, len * m
end

local unit = JIT and unitJit or unitPuc

-- Below 2^464 the products of two coordinate differences (each below 2^466 after scaling)
-- cannot overflow; from 2^400 up the scaled copies keep 64 binades of headroom below it.
local RESCALE_LOW, RESCALE_HIGH = 2^400, 2^464

-- THE SAT ENGINE. convexPenetration(p1, n1, p2, n2, both) decides exactly whether the
-- convex polygons p1[1..n1] and p2[1..n2] (flat arrays, either winding) overlap: touching is not
-- overlapping; fewer than 3 points or zero area never overlaps. both: the axes of both
-- polygons (polygonsCollide); false: the axes of p1 only, both ends of each range
-- (polygonCollidesWith). Allocates nothing (except on the rare path beyond 2^500); rescaled
-- is for that path only (callers leave it nil). vouched: the first pass is convex.lua's
-- vouching pass, the convexity check of the collision functions (see there). Call
-- separatingPush for a push.
-- Returns
--   false                                  no overlap (exact);
--   nil, "points1" or "points2"            that polygon holds a NaN or infinite coordinate;
--   nil, false                             (vouched) the pass could not vouch for a polygon:
--                                          check both the careful way, then call unvouched;
--   depth, ux, uy, owner, edgeEnd, base, inside
--     the least penetration: depth >= 0 (accurate to rounding) along the unit vector (ux, uy)
--     that p2 must move, and the line the move must clear, for separatingPush: in polygon
--     `owner` (1 or 2), the edge ending at vertex index edgeEnd moved to pass through vertex
--     index base, with `inside` the cross product's sign on the side the other must leave.
-- It stays whole (about 120 lines): the per-frame path of every collision, its LuaJIT and PUC
-- set-ups inline so that only the turns and spans stay alive at the box test's exit.
local function convexPenetration(p1, n1, p2, n2, both, rescaled, vouched)
  if n1 < 6 or n2 < 6 then
    if vouched then return nil, false end
    return false
  end
  -- Each polygon's turn, the sign of its area decided exactly, 1 or -1 (zero area never
  -- collides), and the sizes bounding every |vx - ax| and |vy - ay| in the projections: the box
  -- around both. A NaN or infinity makes the sums non-finite; so does overflow, which is not an
  -- error. The boxes are apart or touching (so are the polygons) when a difference is <= 0; no
  -- subtraction of finite doubles rounds across 0.
  local turn1, turn2, spanX, spanY
  local top1, bottom2   -- PUC Lua: where reachBoth's walk starts (see there)
  if JIT then
    local xmin1, xmax1, ymin1, ymax1, xmin2, xmax2, ymin2, ymax2
    if vouched then
      turn1, xmin1, xmax1, ymin1, ymax1 = vouch(p1, n1)
      if not turn1 then return nil, false end
      turn2, xmin2, xmax2, ymin2, ymax2 = vouch(p2, n2)
      if not turn2 then return nil, false end
    else
      -- Each polygon's sums, then at once its turn, so that only the sign and the box are kept
      -- while the other's sums are taken (fewer values for a side trace to inherit). Between
      -- the loops min, max and a division, which have no side exits (the branches' exits were
      -- side traces of shoelaceBounds' loop, past LuaJIT's 100 per loop).
      local area1, xSq1, dSq1, area2, xSq2, dSq2
      area1, xSq1, dSq1, xmin1, xmax1, ymin1, ymax1 = shoelaceBounds(p1, n1)
      -- luacheck: ignore 581 (NaN must count as non-finite)
      if not (xSq1 + dSq1 < huge) and holdsNonFinite(p1, n1) then return nil, "points1" end
      turn1 = areaSignOf(p1, n1, area1, xSq1, dSq1)
      area2, xSq2, dSq2, xmin2, xmax2, ymin2, ymax2 = shoelaceBounds(p2, n2)
      -- luacheck: ignore 581 (NaN must count as non-finite)
      if not (xSq2 + dSq2 < huge) and holdsNonFinite(p2, n2) then return nil, "points2" end
      turn2 = areaSignOf(p2, n2, area2, xSq2, dSq2)
    end
    -- Both turns and the spans before the box test, so that only those four numbers are alive
    -- at its exit: the side trace that a miss takes there inherits them, where with the sums
    -- and the boxes alive it can fail to compile ("NYI: register coalescing too complex")
    spanX, spanY = max(xmax1, xmax2) - min(xmin1, xmin2), max(ymax1, ymax2) - min(ymin1, ymin2)
    if both and min(xmax1 - xmin2, xmax2 - xmin1, ymax1 - ymin2, ymax2 - ymin1) <= 0 then
      return false   -- (the one-sided test may still see overlap)
    end
    if turn1 == 0 or turn2 == 0 then return false end
    -- (a sure sign is finite: areaSignOf sends an infinite sum to the exact path; so t / |t|
    -- is 1 or -1 exactly)
    turn1, turn2 = turn1 / abs(turn1), turn2 / abs(turn2)
  else
    -- PUC Lua: both in one call per polygon, comparisons instead of min and max (calls here);
    -- the vouching pass returns what turnAndBounds does, nil when it cannot vouch
    local pass = vouched and vouch or turnAndBounds
    local sign1, xmin1, xmax1, ymin1, ymax1, _, high1 = pass(p1, n1)
    if not sign1 then return nil, not vouched and "points1" end
    local sign2, xmin2, xmax2, ymin2, ymax2, low2 = pass(p2, n2)
    if not sign2 then return nil, not vouched and "points2" end
    if both and (xmax1 <= xmin2 or xmax2 <= xmin1 or ymax1 <= ymin2 or ymax2 <= ymin1) then
      return false   -- (the one-sided test may still see overlap)
    end
    if sign1 == 0 or sign2 == 0 then return false end
    turn1 = sign1
    turn2 = sign2
    top1 = high1
    bottom2 = low2
    spanX = (xmax1 > xmax2 and xmax1 or xmax2) - (xmin1 < xmin2 and xmin1 or xmin2)
    spanY = (ymax1 > ymax2 and ymax1 or ymax2) - (ymin1 < ymin2 and ymin1 or ymin2)
  end
  -- luacheck: ignore 581 (inf and NaN are too big)
  if not (spanX + spanY <= EXACT_TOP) and not rescaled then
    -- Far beyond the exact range the projections (products of two sizes) would overflow into
    -- infinities and NaN. Collide copies scaled by a power of two k instead (this rare path
    -- allocates them); the scaled engine does not rescale again, so this recurses once.
    local k = powerScale(largestMagnitude(p2, n2, largestMagnitude(p1, n1, 0.0)),
      RESCALE_LOW, RESCALE_HIGH)
    local s1, s2 = {}, {}
    for i = 1, n1 do s1[i] = p1[i] * k end
    for i = 1, n2 do s2[i] = p2[i] * k end
    local depth, ux, uy, owner, edgeEnd, base, inside =
      convexPenetration(s1, n1, s2, n2, both, true)
    if not depth then return false end
    return depth / k, ux, uy, owner, edgeEnd, base, inside
  end
  local squaredDepth, o, edgeEnd, far, owner, turn, lines, nl
  if both then
    local tolSq = 2^-98 * (spanX * spanX + spanY * spanY)   -- squaredTolerance, inlined
    if tolSq < 2^-1000 then tolSq = huge end
    if JIT then
      squaredDepth, o, edgeEnd = reachPast(p1, n1, turn1, p2, n2, tolSq)
      if not squaredDepth then return false end
      local squaredDepth2, o2, edgeEnd2 = reachPast(p2, n2, turn2, p1, n1, tolSq)
      if not squaredDepth2 then return false end
      owner = 1
      if squaredDepth2 < squaredDepth then   -- keep the least penetration
        squaredDepth, o, edgeEnd, owner = squaredDepth2, o2, edgeEnd2, 2
      end
    else
      squaredDepth, o, edgeEnd, owner = reachBoth(p1, n1, turn1, p2, n2, turn2, tolSq, top1,
        bottom2)
      if not squaredDepth then return false end
    end
    turn, lines, nl = turn1, p1, n1
    if owner == 2 then turn, lines, nl = turn2, p2, n2 end
  else
    squaredDepth, o, edgeEnd, far = reachPastBothEnds(p1, n1, turn1, p2, n2, max(spanX, spanY))
    if not squaredDepth then return false end
    owner, turn, lines, nl = 1, turn1, p1, n1
  end
  -- Only outside the exact range can every axis's squared normal underflow, leaving none chosen
  if squaredDepth == huge then return 0.0, 0.0, 0.0, owner, edgeEnd, edgeEnd, turn end
  -- the chosen edge's outward normal, turned the way p2 must move, and the line to clear
  local ia = edgeEnd == 1 and nl - 1 or edgeEnd - 2
  local nx = ((lines[edgeEnd + 1] + 0.0) - lines[ia + 1]) * turn
  local ny = ((lines[ia] + 0.0) - lines[edgeEnd]) * turn
  local base, inside = ia, turn
  if owner == 2 then
    nx, ny = -nx, -ny
  elseif far and far > 0 then
    nx, ny, base, inside = -nx, -ny, far, -turn
  end
  local ux, uy, len = unit(nx, ny)
  return o / len, ux, uy, owner, edgeEnd, base, inside
end

-- The line a push must clear and the move of the other polygon's vertices, for a push (dx, dy):
-- the direction e = b - a of the chosen edge and its point q (vertex `base`), both moved by
-- (dx, dy) when the line's polygon is the one that moves (lineMoves 1, else 0), and the move
-- (vx, vy) of the other polygon's vertices. Each coordinate rounds as a game's p[i] + dx.
local function pushLine(lines, ia, ib, base, lineMoves, dx, dy)
  local lx, ly = dx * lineMoves, dy * lineMoves
  return (lines[ib] + lx) - (lines[ia] + lx), (lines[ib + 1] + ly) - (lines[ia + 1] + ly),
    lines[base] + lx, lines[base + 1] + ly, dx - lx, dy - ly
end

-- separatingPush's check of one push along (ux, uy), on LuaJIT (PUC Lua's is written out in its
-- separatingPush, below): the largest det + bound over the vertices p of points moved by the push,
-- where det is e x (p - q) turned to be > 0 on the side `inside` (e premultiplied by that sign,
-- which is exact) and bound is cross's error bound, its filter inlined. No vertex is inside when it
-- is 0. One cross product a vertex, from q only: the bound grows with |p - q|, but the first
-- push's margin (see separatingPush) already covers the bound from q for all but a few vertices,
-- and a second cross product and bound from the edge's other end would cost every vertex. Up to
-- 8 vertices there is no loop: the vertices in one expression, as in reachPast (a loop of 6 to 8
-- steps often fails to become a trace of its own, "leaving loop in root trace", and the traces
-- that reach it then copy it unrolled). Beyond, the loop is branch-free and takes the line from
-- pushLine in every step: LuaJIT hoists those loads and products out of its compiled loop, and a
-- side trace that leaves the loop midway (a trace that runs on into it before it is compiled
-- unrolls it) inherits only the push from its parent. With the line's numbers held across the
-- loop such side traces need more registers than there are ("NYI: register coalescing too
-- complex", retried on every push).
-- one vertex's det + bound, from q
local function reachOf(ex, ey, qx, qy, px, py)
  local l, r = ex * (py - qy), ey * (px - qx)
  return l - r + CROSS_BOUND * (abs(l) + abs(r))
end
local function lineShortfall(lines, ia, ib, base, lineMoves, ux, uy, push, inside, points, n)
  local dx, dy = ux * push + 0.0, uy * push + 0.0
  if n <= 16 then
    -- Up to 8 vertices no loop: the vertices in one expression, the last one repeated for
    -- fewer (harmless to a max), taken in the loop's order
    local ex, ey, qx, qy, vx, vy = pushLine(lines, ia, ib, base, lineMoves, dx, dy)
    ex, ey = ex * inside, ey * inside
    -- (vertices 2 and 3 at constant indices: a polygon that collides has 3 vertices or more)
    local worst = max(0.0, reachOf(ex, ey, qx, qy, points[1] + vx, points[2] + vy))
    worst = max(worst, reachOf(ex, ey, qx, qy, points[3] + vx, points[4] + vy))
    worst = max(worst, reachOf(ex, ey, qx, qy, points[5] + vx, points[6] + vy))
    local j = min(7, n - 1)
    worst = max(worst, reachOf(ex, ey, qx, qy, points[j] + vx, points[j + 1] + vy))
    j = min(9, n - 1)
    worst = max(worst, reachOf(ex, ey, qx, qy, points[j] + vx, points[j + 1] + vy))
    j = min(11, n - 1)
    worst = max(worst, reachOf(ex, ey, qx, qy, points[j] + vx, points[j + 1] + vy))
    j = min(13, n - 1)
    worst = max(worst, reachOf(ex, ey, qx, qy, points[j] + vx, points[j + 1] + vy))
    return max(worst, reachOf(ex, ey, qx, qy, points[n - 1] + vx, points[n] + vy))
  end
  local worst = 0.0
  for i = 1, n - 1, 2 do
    local ex, ey, qx, qy, vx, vy = pushLine(lines, ia, ib, base, lineMoves, dx, dy)
    ex, ey = ex * inside, ey * inside
    local px, py = points[i] + vx, points[i + 1] + vy
    local l, r = ex * (py - qy), ey * (px - qx)
    worst = max(worst, l - r + CROSS_BOUND * (abs(l) + abs(r)))
  end
  return worst
end

-- How many times separatingPush may lengthen a push before it gives up: the rounding allowance
-- doubles each round, and 64 doublings of eps |x| outgrow any coordinate.
local PUSH_ROUNDS = 64

-- The push that separates, from convexPenetration's least penetration: a push of length >=
-- depth along (ux, uy) after which, with p2's coordinates moved by (dx, dy) and rounded the way
-- a game moves them (p[i] = p[i] + dx), the chosen line separates the polygons for sure. A
-- rounded move falls short of the exact depth by the rounding of the moved coordinates (eps
-- times their magnitude, along the push) and of the depth itself, so the push is checked on the
-- rounded coordinates: every vertex that must have left must lie on the far side of the line
-- or on it, which cross's filter proves (the same sign the exact kernel would find: touching
-- counts as apart). A vertex the filter cannot place lengthens the push by its shortfall plus
-- the bound and the rounding allowance at it, and the check runs again. Deciding such vertices
-- exactly instead would cost an expansion at nearly every push: its vertex ends on the line.
-- So along a slanted axis (ux uy not 0) the first push is already lengthened by a margin of
-- about what the check's rounding takes away, eps (|qx ux| + |qy uy| + |ex| + |ey|) (q the
-- line's point, e its edge: the moved coordinates' rounding, the depth's and the filter's bound
-- grow with them), and one check then proves most pushes, where from the depth itself many
-- need a second (which costs a square root and a division too). The margin lengthens a push no
-- more than the second round it replaces, well within the contract (8 eps M beyond the exact
-- depth). Along an axis the depth comes first: a move along x or y is often exact there.
-- Returns push length, dx, dy.
-- Two bodies computing the same push (to the depth's rounding, which differs by an ulp where the
-- two SAT bodies round differently). On PUC Lua the check (lineShortfall's, with pushLine's
-- line) is written out in the loop over the rounds, and its filter is tried first without abs,
-- which places most vertices: the calls (twelve arguments for the check, pushLine's eight
-- results, abs) are dear on PUC Lua. Each vertex from q only, as on LuaJIT (the same pushes).
-- LuaJIT's: the check by lineShortfall, the first push's margin without a branch.
local function separatingPushJit(p1, n1, p2, n2, depth, ux, uy, owner, edgeEnd, base, inside)
  if ux == 0 and uy == 0 then return 0.0, 0.0, 0.0 end   -- no axis: see convexPenetration
  local lines, nl, others, no, lineMoves = p1, n1, p2, n2, 0.0
  if owner == 2 then lines, nl, others, no, lineMoves = p2, n2, p1, n1, 1.0 end
  local ia = edgeEnd == 1 and nl - 1 or edgeEnd - 2
  -- a moved vertex rounds by up to eps |x| against the push, |x| about the line's: the
  -- allowance for it, none on the first check, then that, doubling every further round
  local allowance = 0.0
  -- the first push: with the margin along a slanted axis (see above), without a branch
  local push
  do
    local qx, qy = lines[base] + 0.0, lines[base + 1] + 0.0
    local ex, ey = (lines[edgeEnd] + 0.0) - lines[ia], (lines[edgeEnd + 1] + 0.0) - lines[ia + 1]
    push = depth + EPS * ((abs(qx * ux) + abs(qy * uy)) + (abs(ex) + abs(ey)))
      * isAbove(abs(ux * uy))
  end
  for _ = 1, PUSH_ROUNDS do
    local worst = lineShortfall(lines, ia, edgeEnd, base, lineMoves, ux, uy, push, inside,
      others, no)
    if worst == 0 then return push, ux * push + 0.0, uy * push + 0.0 end   -- + 0.0: -0 to 0
    -- lengthen by the shortfall and the rounding allowance at the line (where the vertex that
    -- fell short lies, to within the polygons' size), doubled every round
    local ex, ey, qx, qy = pushLine(lines, ia, edgeEnd, base, lineMoves,
      ux * push + 0.0, uy * push + 0.0)
    allowance = allowance == 0 and EPS * (abs(qx * ux) + abs(qy * uy)) or 2 * allowance
    push = push + worst / sqrt(ex * ex + ey * ey) + allowance
    -- only far outside the exact range can the check's products overflow: keep the depth
    if not (push < huge) then break end   -- luacheck: ignore 581 (NaN too)
  end
  return depth, ux * depth + 0.0, uy * depth + 0.0
end

-- PUC Lua's: the check written out in the loop, its filter first without abs.
local function separatingPushPuc(p1, n1, p2, n2, depth, ux, uy, owner, edgeEnd, base, inside)
  if ux == 0 and uy == 0 then return 0.0, 0.0, 0.0 end   -- no axis: see convexPenetration
  local lines, nl, points, n, lineMoves = p1, n1, p2, n2, 0.0
  if owner == 2 then lines, nl, points, n, lineMoves = p2, n2, p1, n1, 1.0 end
  local ia = edgeEnd == 1 and nl - 1 or edgeEnd - 2
  local crossBound = CROSS_BOUND   -- (a local: an upvalue is read by an instruction of its own)
  local allowance = 0.0   -- as on LuaJIT
  local push = depth
  if ux * uy ~= 0 then   -- the margin along a slanted axis, as on LuaJIT (isAbove's test)
    local qxu, qyu = (lines[base] + 0.0) * ux, (lines[base + 1] + 0.0) * uy
    local ex, ey = (lines[edgeEnd] + 0.0) - lines[ia], (lines[edgeEnd + 1] + 0.0) - lines[ia + 1]
    push = depth + EPS * (((qxu < 0 and -qxu or qxu) + (qyu < 0 and -qyu or qyu))
      + ((ex < 0 and -ex or ex) + (ey < 0 and -ey or ey)))
  end
  for _ = 1, PUSH_ROUNDS do
    -- the line and the move of points' vertices, as pushLine gives them, e turned by inside
    local dx, dy = ux * push + 0.0, uy * push + 0.0
    local lx, ly = dx * lineMoves, dy * lineMoves
    local ex = ((lines[edgeEnd] + lx) - (lines[ia] + lx)) * inside
    local ey = ((lines[edgeEnd + 1] + ly) - (lines[ia + 1] + ly)) * inside
    local qx, qy = lines[base] + lx, lines[base + 1] + ly
    local vx, vy = dx - lx, dy - ly
    local worst = 0.0
    for i = 1, n - 1, 2 do
      local px, py = points[i] + vx, points[i + 1] + vy
      local l, r = ex * (py - qy), ey * (px - qx)
      -- first without abs: the bound's |l| + |r| is |l + r| or |l - r|, the larger; det <= -t
      -- and det <= t, t = CROSS_BOUND (l + r), put the vertex surely on the line or outside
      -- (its reach <= 0 <= worst), as most vertices are
      local det, t = l - r, crossBound * (l + r)
      if det > t or det > -t then
        local reach = det + crossBound * ((l < 0 and -l or l) + (r < 0 and -r or r))
        if reach > worst then worst = reach end
      end
    end
    if worst == 0 then return push, dx, dy end
    local qxu, qyu = qx * ux, qy * uy
    if allowance == 0 then
      allowance = EPS * ((qxu < 0 and -qxu or qxu) + (qyu < 0 and -qyu or qyu))
    else
      allowance = 2 * allowance
    end
    push = push + worst / sqrt(ex * ex + ey * ey) + allowance
    if not (push < huge) then break end   -- luacheck: ignore 581 (NaN too)
  end
  return depth, ux * depth + 0.0, uy * depth + 0.0
end

local separatingPush = JIT and separatingPushJit or separatingPushPuc

M.unit = unit
M.unitJit = unitJit
M.unitPuc = unitPuc
M.convexPenetration = convexPenetration
M.minProjection = minProjection
M.minProjectionJit = minProjectionJit
M.minProjectionPuc = minProjectionPuc
M.projectionTolerance = projectionTolerance
M.vertexInside = vertexInside
M.vertexInsideJit = vertexInsideJit
M.vertexInsidePuc = vertexInsidePuc
M.isAbove = isAbove
M.reachBoth = reachBoth
M.reachPast = reachPast
M.squaredTolerance = squaredTolerance
M.separatingPush = separatingPush
M.separatingPushJit = separatingPushJit
M.separatingPushPuc = separatingPushPuc
M.faceAndFarJit = faceAndFarJit
M.faceAndFarPuc = faceAndFarPuc
M.lineShortfall = lineShortfall

return M
