-- polygon/rayring.lua: rays against one flat polygon of any shape (convex, concave, crossing
-- itself): where a segment first enters its open interior by the crossing rule (even-odd, as
-- polygonContains), and the public polygonRayCast, which hands lists of parts to raycast.lua.
-- Every hit or miss and every choice of edge is an exact sign (kernel's cross); each fraction
-- comes from floating point with an error bound, or from double doubles or exact expansions
-- where the bound cannot vouch for it. Relies on kernel, check, sat's unit, collide's shape
-- resolution, convex's refusal words and raycast's orders along the ray and exact fractions.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local check = require(_PACKAGE .. ".check")
local sat = require(_PACKAGE .. ".sat")
local collide = require(_PACKAGE .. ".collide")
local raycast = require(_PACKAGE .. ".raycast")
local convex = require(_PACKAGE .. ".convex")

local abs, min, max, sqrt = math.abs, math.min, math.max, math.sqrt
local cross, crossExact, CROSS_BOUND, JIT = kernel.cross, kernel.crossExact, kernel.CROSS_BOUND, kernel.JIT
local EPS = kernel.EPS
local checkPoints, checkFiniteNumber = check.checkPoints, check.checkFiniteNumber
local unit = sat.unit
local fewPointsMessage = convex.fewPointsMessage
local resolveShape = collide.resolveShape
local lineSide, alongOrder, entryOrder = raycast.lineSide, raycast.alongOrder, raycast.entryOrder
local entryEstimate, pointFraction = raycast.entryEstimate, raycast.pointFraction
local edgeFractionExact, castParts = raycast.edgeFractionExact, raycast.castParts
local checkEnds, ENTERS_EDGE, ENTERS_VERTEX = raycast.checkEnds, raycast.ENTERS_EDGE, raycast.ENTERS_VERTEX
local twoDiff, crossDD = kernel.twoDiff, kernel.crossDD

local type = type

local M = {}

-- The segment is P(t) = A + t d, d = B - A, t in [0, 1]; its line L. o(v) = d x (v - A) (exact
-- sign) tells the side of L each vertex lies on. The polygon's open interior along L, by the
-- crossing rule: going along L, a point off the boundary is inside when an odd number of edges
-- cross L before it. Where no vertex lies on L, the edges crossing L are those whose ends lie on
-- opposite sides, and the interior along L is the stretches between the first and second
-- crossing, the third and fourth, and so on. With exactly two crossings (a convex polygon, and
-- most rays through a concave one) the segment enters at the nearer one unless that lies past B
-- or A lies beyond both; that is the fast path. Every other case (a vertex on L, more than two
-- crossings, a bound that cannot vouch) takes the exact path: the crossings of L with o = 0
-- counted on the positive side (L moved by an infinitesimal to the negative side: the parity of
-- every stretch between vertices is the same), sorted along L exactly, and edges lying along L
-- taken out of the interior (they are boundary).

-- For a crossing edge p -> q, with o(p) and o(q) of opposite signs: s = sign(o(q)) is the sign
-- of d x (q - p) = o(q) - o(p); with g(X) = (q - p) x (X - p) (0 on the edge's line) the
-- crossing is at t = g(A) / (g(A) - g(B)), g(A) - g(B) = d x (q - p); so a = s g(A) and
-- b = s g(B) have a > b, t > 0 exactly when a > 0 and t < 1 exactly when b < 0; and when both
-- hold t = a / (a - b) has no cancellation. Entering across the edge along d, its outward
-- normal is the one against d: -s (qy - py, px - qx) / |q - p|.

local TINY = 2^-900   -- sizes below it are taken for error by the float bounds

-- A fraction f is good when A + f d lies within 8 eps M of the exact entry point (M the largest
-- coordinate magnitude of A and B): |f - t| |d| <= 8 eps M. The float fraction is kept when its
-- error bound times |d| (|d| within 2 eps, and the product's rounding, inside the factor
-- 1 + 2^-40) stays below PRECISE M; else double doubles or exact expansions give it within eps.
local PRECISE = 7.75 * EPS

-- The entry fraction t = a / (a - b) across the edge p -> q (a = g(A), b = g(B), of opposite
-- signs) from double doubles: every difference split exactly (TwoDiff), each determinant the
-- exact difference of its two main products plus its first-order terms (what is dropped is
-- below 2^-100 of its products' size), then one division (no cancellation): t within eps, plus
-- 2^-99 times the sizes over |a| + |b|. nil where that ratio passes 2^40 (nearly parallel) or
-- the products near underflow: the expansions then.
local function entryFractionDD(px, py, qx, qy, ax, ay, bx, by)
  local exh, exl = twoDiff(qx, px)
  local eyh, eyl = twoDiff(qy, py)
  local uxh, uxl = twoDiff(ax, px)
  local uyh, uyl = twoDiff(ay, py)
  local ah, al, sizeA = crossDD(exh, exl, eyh, eyl, uxh, uxl, uyh, uyl)
  uxh, uxl = twoDiff(bx, px)
  uyh, uyl = twoDiff(by, py)
  local bh, bl, sizeB = crossDD(exh, exl, eyh, eyl, uxh, uxl, uyh, uyl)
  local a, b, size = ah + al, bh + bl, sizeA + sizeB
  local den = abs(a) + abs(b)
  if den < size * 2^-40 or size < 2^-800 then return nil end
  return abs(a) / den
end

-- The entry fraction across the edge p -> q (A and B on its two sides) within 8 eps M: double
-- doubles, or exact expansions where those cannot vouch or coordinates pass 2^400 (where the
-- double doubles' splits could overflow).
local function entryFractionPrecise(points, p, q, ax, ay, bx, by)
  local px, py, qx, qy = points[p] + 0.0, points[p + 1] + 0.0, points[q] + 0.0, points[q + 1] + 0.0
  local t
  if max(abs(px), abs(py), abs(qx), abs(qy), abs(ax), abs(ay), abs(bx), abs(by)) <= 2^400 then
    t = entryFractionDD(px, py, qx, qy, ax, ay, bx, by)
  end
  t = t or edgeFractionExact(px, py, qx, qy, ax, ay, bx, by)
  return min(max(t, 0.0), 1.0)
end

-- The two-crossing finish, PUC Lua's (comparisons: abs and max are calls there): edges
-- p1 -> q1 and p2 -> q2 with signs s1, s2. Returns a fraction, nx, ny; false; or nil where a
-- bound cannot vouch (the exact path then).
local function twoCrossingsPuc(points, p1, q1, s1, p2, q2, s2, ax, ay, bx, by)
  local px, py = points[p1] + 0.0, points[p1 + 1] + 0.0   -- (+ 0.0: no integer subtraction)
  local ex, ey = points[q1] - px, points[q1 + 1] - py
  local l, r = ex * (ay - py), ey * (ax - px)
  local a1 = (l - r) * s1
  local errA1 = CROSS_BOUND * ((l > 0 and l or -l) + (r > 0 and r or -r)) + TINY
  l, r = ex * (by - py), ey * (bx - px)
  local b1 = (l - r) * s1
  local errB1 = CROSS_BOUND * ((l > 0 and l or -l) + (r > 0 and r or -r)) + TINY
  local sx, sy = points[p2] + 0.0, points[p2 + 1] + 0.0
  local fx, fy = points[q2] - sx, points[q2 + 1] - sy
  l, r = fx * (ay - sy), fy * (ax - sx)
  local a2 = (l - r) * s2
  local errA2 = CROSS_BOUND * ((l > 0 and l or -l) + (r > 0 and r or -r)) + TINY
  l, r = fx * (by - sy), fy * (bx - sx)
  local b2 = (l - r) * s2
  local errB2 = CROSS_BOUND * ((l > 0 and l or -l) + (r > 0 and r or -r)) + TINY
  -- every sign sure, or the exact path (NaN and infinities from an overflow too)
  if not ((a1 > errA1 or -a1 > errA1) and (b1 > errB1 or -b1 > errB1)
      and (a2 > errA2 or -a2 > errA2) and (b2 > errB2 or -b2 > errB2)) then
    return nil
  end
  if (a1 < 0 and a2 < 0) or (b1 > 0 and b2 > 0) then return false end   -- both before A or past B
  if (a1 < 0) ~= (a2 < 0) then return 0.0, 0.0, 0.0 end                  -- A between them
  -- both past A, not both past B: the entry is the nearer (each bound: the signs' errors to
  -- first order, then two roundings of t and two of the order's test)
  local t1 = a1 / (a1 - b1)
  local err1 = (errA1 + errB1) / (a1 - b1) * (1 + 2^-10) + 4 * EPS * t1
  local t, err, p, q, s = t1, err1, p1, q1, s1
  if b2 < 0 then
    local t2 = a2 / (a2 - b2)
    local err2 = (errA2 + errB2) / (a2 - b2) * (1 + 2^-10) + 4 * EPS * t2
    if b1 > 0 or t2 + err2 < t1 - err1 then
      t, err, p, q, s, ex, ey = t2, err2, p2, q2, s2, fx, fy
    elseif t1 + err1 >= t2 - err2 then
      return nil   -- too close to order by the bounds
    end
  end
  local m = ax > 0 and ax or -ax
  if ay > m then m = ay elseif -ay > m then m = -ay end
  if bx > m then m = bx elseif -bx > m then m = -bx end
  if by > m then m = by elseif -by > m then m = -by end
  local dx, dy = bx - ax, by - ay
  if err * sqrt(dx * dx + dy * dy) * (1 + 2^-40) > PRECISE * m then
    t = entryFractionPrecise(points, p, q, ax, ay, bx, by)
  end
  local nx, ny = unit(-s * ey, s * ex)
  return t, nx, ny
end

-- 1 for x > 0, else 0, with no branch (a nonzero double times 2^2000 is at least 2^926).
local BIG = 2^1000
local function positive(x) return min(1, max(0, x * BIG * BIG)) end   -- luacheck: ignore 581

-- The same finish, LuaJIT's: no branch (a branch's side exit with this many numbers alive is
-- "NYI: register coalescing too complex", the side trace is never compiled). Returns a code
-- and the entry's fraction, normal and edge: 1 a hit, 4 a hit whose fraction needs double
-- doubles, 3 a miss, 2 A inside, anything else the exact path.
local function twoCrossingsJit(points, p1, q1, s1, p2, q2, s2, ax, ay, bx, by)
  local px, py = points[p1] + 0.0, points[p1 + 1] + 0.0   -- (+ 0.0: no integer subtraction)
  local ex, ey = points[q1] - px, points[q1 + 1] - py
  local l, r = ex * (ay - py), ey * (ax - px)
  local a1, errA1 = (l - r) * s1, CROSS_BOUND * (abs(l) + abs(r)) + TINY
  l, r = ex * (by - py), ey * (bx - px)
  local b1, errB1 = (l - r) * s1, CROSS_BOUND * (abs(l) + abs(r)) + TINY
  local sx, sy = points[p2] + 0.0, points[p2 + 1] + 0.0
  local fx, fy = points[q2] - sx, points[q2 + 1] - sy
  l, r = fx * (ay - sy), fy * (ax - sx)
  local a2, errA2 = (l - r) * s2, CROSS_BOUND * (abs(l) + abs(r)) + TINY
  l, r = fx * (by - sy), fy * (bx - sx)
  local b2, errB2 = (l - r) * s2, CROSS_BOUND * (abs(l) + abs(r)) + TINY
  -- the signs, each 1 when sure: t > 0, t < 0, t < 1, t > 1
  local aP1, aN1 = positive(a1 - errA1), positive(-a1 - errA1)
  local bN1, bP1 = positive(-b1 - errB1), positive(b1 - errB1)
  local aP2, aN2 = positive(a2 - errA2), positive(-a2 - errA2)
  local bN2, bP2 = positive(-b2 - errB2), positive(b2 - errB2)
  local sure = (aP1 + aN1) * (bN1 + bP1) * (aP2 + aN2) * (bN2 + bP2)
  local inv1, inv2 = 1 / max(a1 - b1, TINY), 1 / max(a2 - b2, TINY)
  -- three roundings each (a - b, the inverse, the product), and two more of the order's test
  local t1, t2 = a1 * inv1, a2 * inv2
  local err1 = (errA1 + errB1) * inv1 * (1 + 2^-10) + 5 * EPS * abs(t1)
  local err2 = (errA2 + errB2) * inv2 * (1 + 2^-10) + 5 * EPS * abs(t2)
  local mid1, mid2 = aP1 * bN1, aP2 * bN2
  local enter1 = mid1 * (bP2 + mid2 * positive(t2 - err2 - t1 - err1))
  local enter2 = mid2 * (bP1 + mid1 * positive(t1 - err1 - t2 - err2))
  local t = enter1 * t1 + enter2 * t2
  local err = enter1 * err1 + enter2 * err2
  local dx, dy = bx - ax, by - ay
  local precise = positive(PRECISE * max(abs(ax), abs(ay), abs(bx), abs(by))
    - err * sqrt(dx * dx + dy * dy) * (1 + 2^-40))
  local code = sure * (3 * max(aN1 * aN2, bP1 * bP2) + 2 * (aN1 * aP2 + aN2 * aP1)
    + (enter1 + enter2) * (4 - 3 * precise))
  return code, t, enter1 * s1 + enter2 * s2, enter1 * p1 + enter2 * p2, enter1 * q1 + enter2 * q2
end

-- The unit normal -s (qy - py, px - qx) / |q - p| of the entry edge p -> q: one division and a
-- square root where |q - p|^2 neither overflows nor loses bits (each component within 3 ulps),
-- else sat's unit.
local function entryNormal(points, p, q, s)
  local ex, ey = points[q] + 0.0 - points[p], points[q + 1] + 0.0 - points[p + 1]
  local sq = ex * ex + ey * ey
  if sq > 2^-900 and sq < 2^900 then
    local k = s / sqrt(sq)
    return -ey * k, ex * k
  end
  local nx, ny = unit(-s * ey, s * ex)
  return nx, ny
end

-- The exact path's scratch (numbers in arrays reused from call to call: nothing allocated once
-- they have grown to the largest polygon's size). Per vertex (by its flat index) its side; per
-- event along L (a crossing: at a vertex with o = 0, or inside an edge; or the far end of an
-- edge along L, where the boundary along L may give way to the interior) its points for
-- entryOrder (p = q = the vertex for a vertex), its kind, w = -s (entryOrder's inner side) and
-- whether it changes the parity (1, a crossing) or not (0, an end); per edge along L (a cover)
-- its ends in order along d.
local sideOf = {}
local evP, evQ, evW, evKind, evT, evErr, evOrder, evToggle = {}, {}, {}, {}, {}, {}, {}, {}
local covLo, covHi = {}, {}

-- The order along L of events i and j (-1: i first), by their estimates where the bounds
-- keep them apart, else exactly.
local function eventCompare(points, i, j, ax, ay, bx, by)
  if evT[i] + evErr[i] < evT[j] - evErr[j] then return -1 end
  if evT[j] + evErr[j] < evT[i] - evErr[i] then return 1 end
  return entryOrder(points, evP[i], evQ[i], evW[i], evKind[i],
    points, evP[j], evQ[j], evW[j], evKind[j], ax, ay, bx, by)
end

-- The order along L of event i and the point z on L (-1: the event first).
local function eventAgainst(points, i, zx, zy, dx, dy)
  if evKind[i] == ENTERS_VERTEX then
    local v = evQ[i]
    return alongOrder(points[v] + 0.0, points[v + 1] + 0.0, zx, zy, dx, dy)
  end
  local p, q = evP[i], evQ[i]
  local px, py = points[p] + 0.0, points[p + 1] + 0.0
  local s = cross(px, py, points[q] + 0.0, points[q + 1] + 0.0, px, py, zx, zy) * evW[i]
  if s > 0 then return -1 elseif s < 0 then return 1 end
  return 0
end

-- Whether an edge along L covers the stretch just past A: some cover with lo <= A < hi. With
-- touch, whether A lies on a cover at all (lo <= A <= hi).
local function coveredAt(points, covers, zx, zy, dx, dy, touch)
  for c = 1, covers do
    local lo, hi = covLo[c], covHi[c]
    if alongOrder(points[lo] + 0.0, points[lo + 1] + 0.0, zx, zy, dx, dy) <= 0 then
      local o = alongOrder(zx, zy, points[hi] + 0.0, points[hi + 1] + 0.0, dx, dy)
      if o < 0 or (touch and o == 0) then return true end
    end
  end
  return false
end

-- Whether an edge along L covers the stretch just past event i's point z: some cover with
-- lo <= z < hi (z may be a crossing inside an edge that meets an edge along L: a polygon that
-- crosses itself there).
local function coveredPast(points, covers, i, dx, dy)
  for c = 1, covers do
    local lo, hi = covLo[c], covHi[c]
    if eventAgainst(points, i, points[lo] + 0.0, points[lo + 1] + 0.0, dx, dy) >= 0
        and eventAgainst(points, i, points[hi] + 0.0, points[hi + 1] + 0.0, dx, dy) < 0 then
      return true
    end
  end
  return false
end

-- The unit outward normal where the segment enters at the point z of the boundary: of the
-- edges with an end at z (a vertex) that do not lie along L, the one nearest in direction to d
-- (the outside behind z lies on its far side: at a vertex of the outline the ray passes, and
-- at a reflex vertex that the ray leaves from), turned against d; event i's edge (a crossing
-- inside it) when z is nil (no vertex). d x e has the sign of o(q) - o(p) (one of them 0, or
-- both of opposite signs: no cancellation).
local function normalAt(points, n, i, zx, zy, dx, dy)
  local best, bp, bq = -math.huge, 0, 0
  local j = n - 1
  for k = zx and 1 or n + 1, n - 1, 2 do
    if sideOf[j] ~= 0 or sideOf[k] ~= 0 then   -- not along L
      local jx, jy, kx, ky = points[j] + 0.0, points[j + 1] + 0.0, points[k] + 0.0, points[k + 1] + 0.0
      local wx, wy
      if jx == zx and jy == zy then wx, wy = kx - zx, ky - zy
      elseif kx == zx and ky == zy then wx, wy = jx - zx, jy - zy end
      if wx then
        local ux, uy = unit(wx, wy)
        local c = ux * dx + uy * dy
        if c > best then best, bp, bq = c, j, k end
      end
    end
    j = k
  end
  if bp == 0 and zx then   -- every edge at z lies along L (the end of a slit or a spike)
    j = n - 1
    for k = 1, n - 1, 2 do
      if (points[j] ~= points[k] or points[j + 1] ~= points[k + 1])
          and ((points[j] == zx and points[j + 1] == zy) or (points[k] == zx and points[k + 1] == zy)) then
        -- its normal to the positive side of L, (-dy, dx): the side the infinitesimal shift of
        -- L (to the negative side) leaves outside past z
        local ex, ey = points[k] + 0.0 - points[j], points[k + 1] + 0.0 - points[j + 1]
        if ex * dx + ey * dy > 0 then return unit(-ey, ex) end
        return unit(ey, -ex)
      end
      j = k
    end
  end
  if bp == 0 then bp, bq = evP[i], evQ[i] end
  local ex, ey = points[bq] + 0.0 - points[bp], points[bq + 1] + 0.0 - points[bp + 1]
  if sideOf[bq] - sideOf[bp] < 0 then return unit(ey, -ex) end
  return unit(-ey, ex)
end

-- Any flat polygon by the exact predicates alone: false, or fraction, nx, ny (see the notes at
-- the top). The events and the edges along L, the events sorted along L (insertion sort: their
-- estimates, exact where those cannot tell), then a sweep along L in groups of events at the
-- same point, the parity counted from far before A: A is strictly inside when the parity just
-- past it is odd and it is on no boundary; else the entry is the first point from A on, short
-- of B, with the parity just past it odd and no edge along L just past it.
local function castRingExact(points, n, ax, ay, bx, by)
  local dx, dy = bx - ax, by - ay
  local finite = dx - dx == 0 and dy - dy == 0   -- (else d overflowed: cross alone)
  local aOnVertex = false
  for i = 1, n - 1, 2 do
    local vx, vy = points[i] + 0.0, points[i + 1] + 0.0
    local o
    if finite then
      o = lineSide(vx, vy, ax, ay, bx, by, dx, dy)
    else
      o = crossExact(ax, ay, bx, by, ax, ay, vx, vy)
    end
    sideOf[i] = o
    if o == 0 and vx == ax and vy == ay then aOnVertex = true end
  end
  local events, covers = 0, 0
  local j = n - 1
  for i = 1, n - 1, 2 do
    local oj, oi = sideOf[j], sideOf[i]
    if (oj >= 0) ~= (oi >= 0) then
      events = events + 1
      if oj == 0 then
        evP[events], evQ[events], evKind[events] = j, j, ENTERS_VERTEX
      elseif oi == 0 then
        evP[events], evQ[events], evKind[events] = i, i, ENTERS_VERTEX
      else
        evP[events], evQ[events], evKind[events] = j, i, ENTERS_EDGE
      end
      evW[events], evToggle[events] = oi >= 0 and -1.0 or 1.0, 1
      local t, err = entryEstimate(points, j, evQ[events], evKind[events], ax, ay, bx, by)
      evT[events], evErr[events] = t, err + 4 * EPS * abs(t)   -- (and eventCompare's roundings)
    elseif oj == 0 and oi == 0 and (points[j] ~= points[i] or points[j + 1] ~= points[i + 1]) then
      covers = covers + 1
      local lo, hi = j, i
      local jx, jy, ix, iy = points[j] + 0.0, points[j + 1] + 0.0, points[i] + 0.0, points[i + 1] + 0.0
      if alongOrder(jx, jy, ix, iy, dx, dy) > 0 then
        lo, hi = i, j
      end
      covLo[covers], covHi[covers] = lo, hi
    end
    j = i
  end
  if events == 0 then return false end   -- every stretch of L outside (or along an edge)
  for c = 1, covers do
    events = events + 1
    local v = covHi[c]
    evP[events], evQ[events], evKind[events], evW[events], evToggle[events] = v, v, ENTERS_VERTEX, 1.0, 0
    local t, err = entryEstimate(points, v, v, ENTERS_VERTEX, ax, ay, bx, by)
    evT[events], evErr[events] = t, err + 4 * EPS * abs(t)
  end
  for e = 1, events do   -- the events sorted along L
    local k = e - 1
    while k >= 1 and eventCompare(points, evOrder[k], e, ax, ay, bx, by) > 0 do
      evOrder[k + 1] = evOrder[k]
      k = k - 1
    end
    evOrder[k + 1] = e
  end
  local parity, seenA, g = 0, false, 1
  while g <= events do
    local first = evOrder[g]
    local h = g   -- the group: events g .. h at the same point
    while h < events and eventCompare(points, evOrder[h + 1], first, ax, ay, bx, by) == 0 do h = h + 1 end
    local atA = eventAgainst(points, first, ax, ay, dx, dy)
    if atA > 0 and not seenA then   -- past A: A's state first
      seenA = true
      if parity % 2 == 1 then
        local onBoundary = aOnVertex or coveredAt(points, covers, ax, ay, dx, dy, true)
        if not onBoundary then return 0.0, 0.0, 0.0 end
        if not coveredAt(points, covers, ax, ay, dx, dy, false) then
          return 0.0, normalAt(points, n, first, ax, ay, dx, dy)
        end
      end
    end
    for k = g, h do parity = parity + evToggle[evOrder[k]] end
    if atA >= 0 then
      if eventAgainst(points, first, bx, by, dx, dy) >= 0 then return false end   -- at or past B
      -- the group's point
      local zx, zy
      if evKind[first] == ENTERS_VERTEX then
        zx, zy = points[evQ[first]] + 0.0, points[evQ[first] + 1] + 0.0
      end
      if parity % 2 == 1 and not coveredPast(points, covers, first, dx, dy) then
        local f
        if atA == 0 then
          f = 0.0
        elseif zx then
          f = pointFraction(zx, zy, ax, ay, bx, by)
        else
          f = entryFractionPrecise(points, evP[first], evQ[first], ax, ay, bx, by)
        end
        return f, normalAt(points, n, first, zx, zy, dx, dy)
      end
      if atA == 0 then seenA = true end
    end
    g = h + 1
  end
  return false   -- (every event before A: the parity past them all is even, A outside)
end

-- Whether (x, y) lies strictly inside the polygon: on no edge, and an odd number of edges
-- crossing the row y to its right, each end counted above when y < its y (the rule of
-- contains.lua, exact by cross's sign).
local function insideRing(points, n, x, y)
  local inside = false
  local px, py = points[n - 1] + 0.0, points[n] + 0.0
  for i = 1, n - 1, 2 do
    local qx, qy = points[i] + 0.0, points[i + 1] + 0.0
    if min(px, qx) <= x and x <= max(px, qx) and min(py, qy) <= y and y <= max(py, qy)
        and cross(px, py, qx, qy, px, py, x, y) == 0 then
      return false   -- on the boundary
    end
    if (py > y) ~= (qy > y) then
      -- the edge crosses the row: right of (x, y) when (x, y) lies on the side of the edge's
      -- line that faces -x, that is the sign of (q - p) x ((x, y) - p) against qy - py
      local c = cross(px, py, qx, qy, px, py, x, y)
      if (c > 0) == (qy > py) then inside = not inside end
    end
    px, py = qx, qy
  end
  return inside
end

-- The collision functions' refusal of a coordinate that is not finite (their words), raised at
-- the caller of polygonRayCast (level: that many calls below it).
local function refuseNonFinite(points, n, level)
  for i = 1, n do
    local v = points[i]
    if v - v ~= 0 then
      error("polygonRayCast: points holds a non-finite coordinate", level + 1)
    end
  end
end

-- o(c) exact for the walks' rare path; NaN where a coordinate or d is not finite (the walks'
-- sum then sends the call to checkFinitePoints, or to the exact path after an overflow).
local function sideExact(ax, ay, bx, by, cx, cy)
  if (cx - cx) + (cy - cy) + (bx - ax) - (bx - ax) + (by - ay) - (by - ay) ~= 0 then return 0 / 0 end
  return crossExact(ax, ay, bx, by, ax, ay, cx, cy)
end

-- After a walk whose sides summed to a NaN or an infinity: the refusal of a coordinate that is
-- not finite (at the caller of polygonRayCast), else (an overflow) the exact path.
local function castRingUnsure(points, n, ax, ay, bx, by)
  refuseNonFinite(points, n, 4)
  local f, nx, ny = castRingExact(points, n, ax, ay, bx, by)
  return f, nx, ny
end

-- The sides' walk, PUC Lua's: o of every vertex (kernel's cross with its filter written out,
-- NaN from an overflow going to the exact cross), the edges where o changes strict sign (the
-- first two: p, q and s = sign(o(q))), their count, and whether some o is 0.
local function castRingPuc(points, n, ax, ay, bx, by)
  local dx = bx - ax
  local dy = by - ay
  local prev = lineSide(points[n - 1] + 0.0, points[n] + 0.0, ax, ay, bx, by, dx, dy)
  local prevIndex = n - 1
  local count, zero, p1, q1, s1, p2, q2, s2 = 0, prev == 0, 0, 0, 0, 0, 0, 0
  local sum = prev
  for i = 1, n - 1, 2 do
    local cx = points[i]
    local cy = points[i + 1]
    local l = dx * (cy - ay)
    local r = dy * (cx - ax)
    local o = l - r
    if l > 0 then
      if r > 0 then
        local b = CROSS_BOUND * (l + r)
        if not (o >= b or -o >= b) then o = sideExact(ax, ay, bx, by, cx + 0.0, cy + 0.0) end
      end
    elseif l < 0 then
      if r < 0 then
        local b = -CROSS_BOUND * (l + r)
        if not (o >= b or -o >= b) then o = sideExact(ax, ay, bx, by, cx + 0.0, cy + 0.0) end
      end
    end   -- (l = 0: o = -r exactly; NaN: the sum below)
    if o > 0 then
      if prev < 0 then
        count = count + 1
        if count == 1 then p1, q1, s1 = prevIndex, i, 1.0 else p2, q2, s2 = prevIndex, i, 1.0 end
      end
    elseif o < 0 then
      if prev > 0 then
        count = count + 1
        if count == 1 then p1, q1, s1 = prevIndex, i, -1.0 else p2, q2, s2 = prevIndex, i, -1.0 end
      end
    else
      zero = true
    end
    sum = sum + o
    prev = o
    prevIndex = i
  end
  if not (sum - sum == 0) then   -- luacheck: ignore 581 (NaN too)
    local f, nx, ny = castRingUnsure(points, n, ax, ay, bx, by)
    return f, nx, ny
  end
  if zero or count ~= 2 then
    if count == 0 and not zero then return false end   -- L misses the polygon
    local f, nx, ny = castRingExact(points, n, ax, ay, bx, by)
    return f, nx, ny
  end
  local f, nx, ny = twoCrossingsPuc(points, p1, q1, s1, p2, q2, s2, ax, ay, bx, by)
  if f == nil then f, nx, ny = castRingExact(points, n, ax, ay, bx, by) end
  return f, nx, ny
end

-- The same, LuaJIT's. Only the filter differs, on purpose, and so the two loops are written
-- twice: abs here (its comparisons on PUC Lua are calls), comparisons there (here each one that
-- goes both ways is a side exit; raycast's lineSide for the first vertex made side traces that
-- never compiled and hits took 300 times longer: bench/NOTES.md). Sharing the bookkeeping would
-- take a Lua call per vertex, on PUC Lua where the walk is most of a miss's time.
local function castRingJit(points, n, ax, ay, bx, by)
  local dx, dy = bx - ax, by - ay
  local cx, cy = points[n - 1], points[n]
  local l, r = dx * (cy - ay), dy * (cx - ax)
  local prev = l - r
  if not (abs(prev) >= CROSS_BOUND * (abs(l) + abs(r))) then   -- luacheck: ignore 581 (NaN)
    prev = sideExact(ax, ay, bx, by, cx + 0.0, cy + 0.0)
  end
  local prevIndex = n - 1
  local count, zero, p1, q1, s1, p2, q2, s2 = 0, prev == 0, 0, 0, 0, 0, 0, 0
  local sum = prev
  for i = 1, n - 1, 2 do
    cx, cy = points[i], points[i + 1]
    l, r = dx * (cy - ay), dy * (cx - ax)
    local o = l - r
    if not (abs(o) >= CROSS_BOUND * (abs(l) + abs(r))) then   -- luacheck: ignore 581 (NaN)
      o = sideExact(ax, ay, bx, by, cx + 0.0, cy + 0.0)
    end
    if o > 0 then
      if prev < 0 then
        count = count + 1
        if count == 1 then p1, q1, s1 = prevIndex, i, 1.0 else p2, q2, s2 = prevIndex, i, 1.0 end
      end
    elseif o < 0 then
      if prev > 0 then
        count = count + 1
        if count == 1 then p1, q1, s1 = prevIndex, i, -1.0 else p2, q2, s2 = prevIndex, i, -1.0 end
      end
    else
      zero = true
    end
    sum = sum + o
    prev, prevIndex = o, i
  end
  if not (sum - sum == 0) then   -- luacheck: ignore 581 (NaN too)
    local f, nx, ny = castRingUnsure(points, n, ax, ay, bx, by)
    return f, nx, ny
  end
  if zero or count ~= 2 then
    if count == 0 and not zero then return false end
    local f, nx, ny = castRingExact(points, n, ax, ay, bx, by)
    return f, nx, ny
  end
  local code, t, s, p, q = twoCrossingsJit(points, p1, q1, s1, p2, q2, s2, ax, ay, bx, by)
  if code == 1 then
    local nx, ny = entryNormal(points, p, q, s)
    return t, nx, ny
  end
  if code == 3 then return false end
  if code == 2 then return 0.0, 0.0, 0.0 end
  if code == 4 then
    local nx, ny = entryNormal(points, p, q, s)
    return entryFractionPrecise(points, p, q, ax, ay, bx, by), nx, ny
  end
  local f, nx, ny = castRingExact(points, n, ax, ay, bx, by)
  return f, nx, ny
end

local castRing = JIT and castRingJit or castRingPuc

-- polygonRayCast(points, x1, y1, x2, y2): where the segment from (x1, y1) to (x2, y2) first
-- enters the open interior of a flat polygon of any shape (by the crossing rule) or of the
-- union of a list of convex parts: fraction, nx, ny, or false. Touching is not colliding; a
-- segment that starts strictly inside gives 0, 0, 0.
function M.polygonRayCast(points, x1, y1, x2, y2)
  local fname = "polygonRayCast"
  local kind = type(points) == "table" and type(points[1])
  if kind ~= "number" then
    points, kind = resolveShape(fname, "points", points, kind, 2)
    if kind == "table" then
      checkFiniteNumber(x1, fname, "x1")
      checkFiniteNumber(y1, fname, "y1")
      checkFiniteNumber(x2, fname, "x2")
      checkFiniteNumber(y2, fname, "y2")
      local f, nx, ny = castParts(fname, points, x1 + 0.0, y1 + 0.0, x2 + 0.0, y2 + 0.0)
      if not f then return false end
      return f, nx + 0.0, ny + 0.0   -- + 0.0: a normal of -0 reads as 0
    end
  end
  if not kind then checkPoints(points, fname, "points", 3) end
  local n = #points
  if n % 2 ~= 0 then checkPoints(points, fname, "points", 3, kind) end
  if n < 6 then error(fewPointsMessage(fname, "points", n), 2) end
  -- the ends' checks written out (four calls to checkFiniteNumber took a tenth of a call on
  -- Lua 5.4): x - x is 0 for every finite number, NaN for an infinity or NaN
  if type(x1) ~= "number" or type(y1) ~= "number" or type(x2) ~= "number" or type(y2) ~= "number"
      or (x1 - x1) + (y1 - y1) + (x2 - x2) + (y2 - y2) ~= 0 then
    checkEnds(fname, x1, y1, x2, y2)
  end
  local ax, ay, bx, by = x1 + 0.0, y1 + 0.0, x2 + 0.0, y2 + 0.0
  if ax == bx and ay == by then   -- a point: inside or not
    refuseNonFinite(points, n, 2)
    if insideRing(points, n, ax, ay) then return 0.0, 0.0, 0.0 end
    return false
  end
  local f, nx, ny = castRing(points, n, ax, ay, bx, by)
  if not f then return false end
  return f, nx + 0.0, ny + 0.0
end

-- both bodies and the exact path, for the spec
M.castRingJit, M.castRingPuc, M.castRingExact = castRingJit, castRingPuc, castRingExact
return M
