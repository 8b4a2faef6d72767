-- polygon/raycast.lua: rays against a list of convex parts: where a segment first enters their
-- union (seams inside it), and the orders along a ray and exact fractions that rayring.lua (one
-- flat polygon of any shape, and the public polygonRayCast) shares; discs are circleray.lua's.
-- Every hit or miss and every choice of edge is an exact sign (kernel's cross); each fraction
-- comes from floating point with an error bound, or from exact expansions where the bound
-- cannot vouch for it. Relies on kernel, check, views.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local check = require(_PACKAGE .. ".check")
local views = require(_PACKAGE .. ".views")

local abs, huge, min, max = math.abs, math.huge, math.min, math.max
local cross, crossExact, CROSS_BOUND, JIT = kernel.cross, kernel.crossExact, kernel.CROSS_BOUND, kernel.JIT
local EPS, twoDiff, twoProduct, powerScale = kernel.EPS, kernel.twoDiff, kernel.twoProduct, kernel.powerScale
local quotientDD, crossDD = kernel.quotientDD, kernel.crossDD
local expClear, expAddProduct, expCompress = kernel.expClear, kernel.expAddProduct, kernel.expCompress
local expCopy, expSign = kernel.expCopy, kernel.expSign
local checkFiniteNumber = check.checkFiniteNumber
local listView, call, checkCopy = views.listView, views.call, views.checkCopy

local M = {}


-- The segment is P(t) = A + t (B - A), t in [0, 1], d = B - A. It hits a shape when some P(t)
-- lies in the shape's open interior; the fraction is the least such t (an infimum). Against a
-- convex polygon the sides of the ray's line decide everything: o(v) = d x (v - A) (kernel's
-- cross, exact) is positive on one side, negative on the other. The line meets the open
-- interior exactly when some vertex lies on each side; then it crosses the boundary twice, on
-- the edge where o falls from > 0 to <= 0 and on the one where it rises from < 0 to >= 0. With
-- w the polygon's area sign (interior points v have w (q - p) x (v - p) > 0 for every edge
-- p -> q), the edge p -> q is entered along d when w (o(p) - o(q)) > 0: the falling edge when
-- w > 0, the rising one otherwise. The segment reaches the interior when B lies strictly
-- inside the entry edge's line and A strictly inside the exit edge's line; A lies strictly
-- inside the polygon when it is also strictly inside the entry edge's line. All of these are
-- signs of 2x2 determinants of differences of the given doubles: exact, with no division.

-- The side of the ray's line A -> B that the point v lies on: a number with the sign of
-- (B - A) x (v - A), exact. Kernel's cross with its filter written out, d = B - A taken once per
-- ray instead of once per vertex (sideWalk calls this for every vertex; the same differences, so
-- the same filter). PUC Lua's comparisons of signs (abs is a call there), as crossPuc.
local function lineSidePuc(vx, vy, ax, ay, bx, by, dx, dy)
  local l = dx * (vy - ay)
  local r = dy * (vx - ax)
  local det = l - r
  local sum
  if l > 0 then
    if r <= 0 then return det end
    sum = l + r
  elseif l < 0 then
    if r >= 0 then return det end
    sum = -l - r
  else
    return det
  end
  local bound = CROSS_BOUND * sum
  if det >= bound or -det >= bound then return det end
  return crossExact(ax, ay, bx, by, ax, ay, vx, vy)
end

-- LuaJIT's: the filter by abs, with no branch but the rare exact one (the comparisons above go
-- both ways, and their side traces from a caller's trace with many numbers alive failed to
-- compile: "NYI: register coalescing too complex", bench/NOTES.md). The same signs.
local function lineSideJit(vx, vy, ax, ay, bx, by, dx, dy)
  local l, r = dx * (vy - ay), dy * (vx - ax)
  local det = l - r
  if abs(det) >= CROSS_BOUND * (abs(l) + abs(r)) then return det end
  return crossExact(ax, ay, bx, by, ax, ay, vx, vy)
end

local lineSide = JIT and lineSideJit or lineSidePuc

-- What sideWalk leaves (numbers, so that nothing is allocated): the flat indices (of x) of the
-- ends of the edge where o falls from > 0 to <= 0 (0 when there is none) and whether o is 0 at
-- its end; the same for the edge where o rises from < 0 to >= 0; the ends of the run of vertices
-- on the line (0 when there is none) and the sign of the last vertex off it.
local fallP, fallQ, fallZero, riseP, riseQ, riseZero = 0, 0, false, 0, 0, false
local runFirst, runLast, offSide = 0, 0, 0

-- The sides of the ray's line of every vertex of points[1 .. n], walked once around.
local function sideWalk(points, n, ax, ay, bx, by, dx, dy)
  local prev = lineSide(points[n - 1] + 0.0, points[n] + 0.0, ax, ay, bx, by, dx, dy)
  local prevIndex = n - 1
  fallP, riseP, runFirst, runLast, offSide = 0, 0, 0, 0, 0
  for i = 1, n - 1, 2 do
    local s = lineSide(points[i] + 0.0, points[i + 1] + 0.0, ax, ay, bx, by, dx, dy)
    if prev > 0 then
      if s <= 0 then fallP, fallQ, fallZero = prevIndex, i, s == 0 end
    elseif prev < 0 then
      if s >= 0 then riseP, riseQ, riseZero = prevIndex, i, s == 0 end
    end
    if s == 0 then
      if prev ~= 0 then runFirst = i end
    else
      if prev == 0 then runLast = prevIndex end
      offSide = s
    end
    prev, prevIndex = s, i
  end
end

-- Whether (x, y) lies strictly inside the convex polygon points[1 .. n] (every edge of nonzero
-- length turns the same strict way to it; a polygon of zero area has edges both ways). Exact.
local function insideConvex(points, n, x, y)
  local sign = 0
  local px, py = points[n - 1] + 0.0, points[n] + 0.0
  for i = 1, n - 1, 2 do
    local qx, qy = points[i] + 0.0, points[i + 1] + 0.0
    if qx ~= px or qy ~= py then
      local s = cross(px, py, qx, qy, px, py, x, y)
      if s == 0 or (sign ~= 0 and (s > 0) ~= (sign > 0)) then return false end
      sign = s
    end
    px, py = qx, qy
  end
  return sign ~= 0
end

-- convexEntry's answers, and what it leaves for an entry: the entry edge's ends (flat indices)
-- and where the segment enters: ENTERS_EDGE inside the edge, ENTERS_VERTEX at its end q,
-- ENTERS_AT_A at A itself (fraction 0).
local MISS, ENTERS, INSIDE = 0, 1, 2
local ENTERS_EDGE, ENTERS_VERTEX, ENTERS_AT_A = 0, 1, 2
local entryP, entryQ, entryKind = 0, 0, ENTERS_EDGE

-- After sideWalk found both a falling and a rising edge: whether the segment enters the convex
-- polygon of area sign w, or starts strictly inside it. Exact.
local function convexEntry(points, w, ax, ay, bx, by)
  local p, q, zero, xp, xq = riseP, riseQ, riseZero, fallP, fallQ
  if w > 0 then p, q, zero, xp, xq = fallP, fallQ, fallZero, riseP, riseQ end
  local px, py, qx, qy = points[p] + 0.0, points[p + 1] + 0.0, points[q] + 0.0, points[q + 1] + 0.0
  if cross(px, py, qx, qy, px, py, bx, by) * w <= 0 then return MISS end   -- B not past the entry
  local rx, ry, sx, sy = points[xp] + 0.0, points[xp + 1] + 0.0, points[xq] + 0.0, points[xq + 1] + 0.0
  if cross(rx, ry, sx, sy, rx, ry, ax, ay) * w <= 0 then return MISS end   -- A not before the exit
  local atA = cross(px, py, qx, qy, px, py, ax, ay) * w
  if atA > 0 then return INSIDE end
  entryP, entryQ = p, q
  entryKind = atA == 0 and ENTERS_AT_A or (zero and ENTERS_VERTEX or ENTERS_EDGE)
  return ENTERS
end

-- Fractions. A fraction f is good when A + f d lies within 8 eps M of the exact entry point
-- (eps = 2^-53, M the largest coordinate magnitude of A and B; the entry point lies between
-- them, so |Z - A| <= 2 sqrt(2) M): |f - t| |d| <= 8 eps M. Rounding t alone costs eps |Z - A|,
-- up to 2.83 eps M, so the float formula is trusted only when its own error bound stays below
-- 4 eps M; else the exact path gives t to within eps, plus order eps^2.

-- (z - a) / (b - a), a != b, to within eps (plus order eps^2): both differences exact as hi + lo,
-- then one correction of the quotient by its exact residual.
local function ratioAlong(z, a, b)
  local nh, nl = twoDiff(z, a)
  local dh, dl = twoDiff(b, a)
  if abs(dh) > 2^900 or abs(nh) > 2^900 then   -- twoProduct's split must not overflow
    nh, nl, dh, dl = nh * 2^-100, nl * 2^-100, dh * 2^-100, dl * 2^-100
  end
  local t = nh / dh
  local ph, pl = twoProduct(t, dh)
  return t + (((nh - ph) - pl) + (nl - t * dl)) / dh   -- nh - ph exact (Sterbenz)
end

-- The fraction of the point z, which lies exactly on the ray's line, along the axis on which
-- the ray moves most.
local function pointFraction(zx, zy, ax, ay, bx, by)
  local t
  if abs(bx - ax) >= abs(by - ay) then t = ratioAlong(zx, ax, bx) else t = ratioAlong(zy, ay, by) end
  return min(max(t, 0.0), 1.0)
end

-- Scratch for the exact fractions and orders: compressed expansions copied out of kernel's one.
local numParts, denParts, partsA, partsB = {}, {}, {}, {}

-- The exact (u1 - u0) x (v1 - v0) of the coordinates times s (a power of two) into kernel's
-- scratch expansion, compressed; returns its largest component (within an ulp of the value).
local crossValue = kernel.expCrossScaled

-- The power of two for the exact fractions: coordinates beyond 2^400 or below 2^-400 in
-- magnitude are brought into [2^-64, 1] (exact, short of underflow), so that no product of two
-- differences overflows or underflows.
local function fractionScale(m)
  if m > 2^400 or (m < 2^-400 and m > 0) then return powerScale(m, 2^-64, 1) end
  return 1.0
end

-- t = ((p - A) x (q - p)) / ((B - A) x (q - p)) from exact expansions of both: the quotient of
-- their largest components, then one correction by the exact residual num - t0 den.
local function edgeFractionExact(px, py, qx, qy, ax, ay, bx, by)
  local m = max(abs(px), abs(py), abs(qx), abs(qy), abs(ax), abs(ay), abs(bx), abs(by))
  local s = fractionScale(m)
  local numTop = crossValue(ax, ay, px, py, px, py, qx, qy, s)
  local numLen = expCopy(numParts)
  local denTop = crossValue(ax, ay, bx, by, px, py, qx, qy, s)
  local denLen = expCopy(denParts)
  local t0 = numTop / denTop
  expClear()
  for i = 1, numLen do expAddProduct(numParts[i], 1.0) end
  for i = 1, denLen do expAddProduct(-t0, denParts[i]) end
  local residual = expCompress()
  return t0 + residual / denTop
end

-- t = ((p - A) x e) / (d x e), e = q - p, as edgeFractionExact but from double doubles, with no
-- loop: every difference split exactly (TwoDiff), each determinant the exact difference of its
-- two main products (TwoProduct, then TwoDiff) plus its first-order terms, then the quotient
-- corrected once by its residual. What is dropped or rounded below the high parts is below
-- 2^-100 (|l| + |r|) (l and r the determinant's two products), so t is within eps |t| (its
-- own rounding) plus 2^-99 c |t|, c = (|l| + |r|) / |det| for either determinant: nil when c
-- passes 2^30 (the expansions then), or a product nears overflow or underflow.
local function edgeFractionDD(px, py, qx, qy, ax, ay, bx, by)
  local wxh, wxl = twoDiff(px, ax)
  local wyh, wyl = twoDiff(py, ay)
  local exh, exl = twoDiff(qx, px)
  local eyh, eyl = twoDiff(qy, py)
  local dxh, dxl = twoDiff(bx, ax)
  local dyh, dyl = twoDiff(by, ay)
  local nh, numLow, numSize = crossDD(wxh, wxl, wyh, wyl, exh, exl, eyh, eyl)
  local dh, denLow, denSize = crossDD(dxh, dxl, dyh, dyl, exh, exl, eyh, eyl)
  return quotientDD(nh, numLow, numSize, dh, denLow, denSize)
end

-- The fraction where the ray crosses the line of the edge p -> q (not parallel to it) in
-- floating point, and a bound on its absolute error (huge where it cannot vouch). num = (p - A)
-- x e and den = d x e (e = q - p) are each within Shewchuk's bound CROSS_BOUND (|l| + |r|) of
-- exact, so t = num / den is within rel = those relative bounds summed, plus eps for the
-- division, to first order (the second order is negligible once rel < 2^-20), where no product
-- has overflowed or lost bits to underflow.
local function edgeEstimate(px, py, qx, qy, ax, ay, bx, by)
  local dx, dy = bx - ax, by - ay
  local ex, ey = qx - px, qy - py
  local wx, wy = px - ax, py - ay
  local nl, nr, dl, dr = wx * ey, wy * ex, dx * ey, dy * ex
  local num, den = nl - nr, dl - dr
  local numSize, denSize = abs(nl) + abs(nr), abs(dl) + abs(dr)
  local t = num / den
  local rel = CROSS_BOUND * (numSize / abs(num) + denSize / abs(den))
  if JIT then   -- (no branch: as signOf's)
    local ok = min(2^-20 - rel, numSize - 2^-900, denSize - 2^-900, 2^1000 - numSize, 2^1000 - denSize)
    return t, (rel + EPS) * abs(t) * (1 + 2^-18) + 2^1000 * (1 - min(1, max(0, ok * 2^1000 * 2^1000)))
  end
  if rel < 2^-20 and numSize > 2^-900 and denSize > 2^-900 and numSize < 2^1000 and denSize < 2^1000 then
    return t, (rel + EPS) * abs(t) * (1 + 2^-18)
  end
  return t, huge
end

-- The same fraction within 8 eps M: the float one when its bound keeps the point within 7 eps
-- M (|d| <= |dx| + |dy|, M over A and B), else edgeFractionDD's, else edgeFractionExact's.
local function edgeFraction(px, py, qx, qy, ax, ay, bx, by)
  local t, err = edgeEstimate(px, py, qx, qy, ax, ay, bx, by)
  if err * (abs(bx - ax) + abs(by - ay)) > 7 * EPS * max(abs(ax), abs(ay), abs(bx), abs(by)) then
    t = edgeFractionDD(px, py, qx, qy, ax, ay, bx, by) or edgeFractionExact(px, py, qx, qy, ax, ay, bx, by)
  end
  return min(max(t, 0.0), 1.0)
end

-- The fraction of an entry convexEntry found into points (kind: where), within 8 eps M.
local function entryFraction(points, p, q, kind, ax, ay, bx, by)
  if kind == ENTERS_AT_A then return 0.0 end
  local qx, qy = points[q] + 0.0, points[q + 1] + 0.0
  if kind == ENTERS_VERTEX then return pointFraction(qx, qy, ax, ay, bx, by) end
  local t = edgeFraction(points[p] + 0.0, points[p + 1] + 0.0, qx, qy, ax, ay, bx, by)
  return t
end

-- The same fraction in floating point and a bound on its error, for the order of entries: at q,
-- two differences and a quotient along the axis the ray moves most on (three roundings).
local function entryEstimate(points, p, q, kind, ax, ay, bx, by)
  if kind == ENTERS_AT_A then return 0.0, 0.0 end
  local qx, qy = points[q] + 0.0, points[q + 1] + 0.0
  if kind == ENTERS_VERTEX then
    local t
    if abs(bx - ax) >= abs(by - ay) then t = (qx - ax) / (bx - ax) else t = (qy - ay) / (by - ay) end
    return t, 4 * EPS * abs(t)
  end
  local t, err = edgeEstimate(points[p] + 0.0, points[p + 1] + 0.0, qx, qy, ax, ay, bx, by)
  return t, err
end


-- Lists of parts. The shape is the union of the parts, so its interior holds the seams between
-- them. Along the ray the points of the union's interior are (1) the points inside some part
-- and (2) points on the ray's line L, where L runs along edges, that have parts on both sides:
-- the cover of L by the edges on it of parts lying left of it, and the one of parts lying right.
-- So the fraction is the least of the parts' entries and of the start of the stretch of L
-- covered on both sides (where a seam meets the outline). Which part is entered first is an
-- exact order (entryOrder), and where the entry point is a vertex (of any part) or A itself the
-- outline's edge there is found by turning around the point (sweepAround): a part's entry edge
-- may be a seam there.

-- The order along the ray of two points on its line: -1 when z1 comes first, 1 when z2 does, 0
-- for the same point. Exact: the coordinate along which the ray moves most.
local function alongOrder(z1x, z1y, z2x, z2y, dx, dy)
  local u1, u2, du = z1x, z2x, dx
  if abs(dy) > abs(dx) then u1, u2, du = z1y, z2y, dy end
  if u1 == u2 then return 0 end
  if (u1 < u2) == (du > 0) then return -1 end
  return 1
end

-- -1, 0 or 1 for the sign of s (s not NaN). LuaJIT's by min and max, with no branch: its
-- callers' traces (the sorts and sweeps of the exact paths) have many numbers alive, and the
-- side traces of a branch that goes both ways failed to compile there.
local function signOfPuc(s)
  if s > 0 then return 1 elseif s < 0 then return -1 end
  return 0
end

local function signOfJit(s)
  return min(1, max(0, s * 2^1000 * 2^1000)) - min(1, max(0, -s * 2^1000 * 2^1000))
end

local signOf = JIT and signOfJit or signOfPuc

-- The order of two crossings of the ray's line with the lines of edges whose ends each
-- straddle the other's line (only parts that overlap have such edges): the sign of
-- s2(Z1) = w2 (q2 - p2) x (Z1 - p2), Z1 the crossing on edge 1, is that of
-- alpha s2(q1) - beta s2(p1) times that of alpha, alpha = o(p1) and beta = o(q1) (of opposite
-- signs): degree 4, from exact expansions of the four determinants, scaled so that no product
-- of four differences overflows. Returns -1 when crossing 1 comes first.
local function crossingOrder(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y, w2, ax, ay, bx, by)
  local m = max(abs(p1x), abs(p1y), abs(q1x), abs(q1y), abs(p2x), abs(p2y), abs(q2x), abs(q2y),
    abs(ax), abs(ay), abs(bx), abs(by))
  local s = m > 0 and powerScale(m, 2^60, 2^124) or 1.0
  local alphaTop = crossValue(ax, ay, bx, by, ax, ay, p1x, p1y, s)
  local alphaLen = expCopy(partsA)
  crossValue(p2x, p2y, q2x, q2y, p2x, p2y, q1x, q1y, s)
  local sqLen = expCopy(partsB)
  expClear()
  for i = 1, alphaLen do
    for j = 1, sqLen do expAddProduct(partsA[i], partsB[j]) end
  end
  local firstLen = expCopy(numParts)   -- alpha s2(q1), kept while beta s2(p1) is made
  crossValue(ax, ay, bx, by, ax, ay, q1x, q1y, s)
  local betaLen = expCopy(partsA)
  crossValue(p2x, p2y, q2x, q2y, p2x, p2y, p1x, p1y, s)
  local spLen = expCopy(partsB)
  expClear()
  for i = 1, firstLen do expAddProduct(numParts[i], 1.0) end
  for i = 1, betaLen do
    for j = 1, spLen do expAddProduct(-partsA[i], partsB[j]) end
  end
  local sign = expSign() * w2 * signOf(alphaTop)
  return signOf(sign)
end

-- The order along the ray of the entries into two parts (each: the part, its entry edge's ends
-- p and q, its area sign and convexEntry's kind): -1 when the first is met first, 1 when the
-- second is, 0 when both enter at the same point. Exact. An entry at a vertex or at A is a point
-- on the ray's line: against the other edge's line it is before the crossing there when it lies
-- outside that line. Two crossings inside edges: the second edge's line against the first
-- edge's ends, whose side is the crossing's unless they straddle the line; then the other way
-- round; both straddling only for parts that overlap (crossingOrder).
local function entryOrder(part1, p1, q1, w1, kind1, part2, p2, q2, w2, kind2, ax, ay, bx, by)
  local z1x, z1y, z2x, z2y = ax, ay, ax, ay
  if kind1 == ENTERS_VERTEX then z1x, z1y = part1[q1] + 0.0, part1[q1 + 1] + 0.0 end
  if kind2 == ENTERS_VERTEX then z2x, z2y = part2[q2] + 0.0, part2[q2 + 1] + 0.0 end
  if kind1 ~= ENTERS_EDGE and kind2 ~= ENTERS_EDGE then
    return alongOrder(z1x, z1y, z2x, z2y, bx - ax, by - ay)
  end
  local a1x, a1y, b1x, b1y = part1[p1] + 0.0, part1[p1 + 1] + 0.0, part1[q1] + 0.0, part1[q1 + 1] + 0.0
  local a2x, a2y, b2x, b2y = part2[p2] + 0.0, part2[p2 + 1] + 0.0, part2[q2] + 0.0, part2[q2 + 1] + 0.0
  if kind1 ~= ENTERS_EDGE then
    return signOf(cross(a2x, a2y, b2x, b2y, a2x, a2y, z1x, z1y) * w2)
  end
  if kind2 ~= ENTERS_EDGE then
    return -signOf(cross(a1x, a1y, b1x, b1y, a1x, a1y, z2x, z2y) * w1)
  end
  local sp = signOf(cross(a2x, a2y, b2x, b2y, a2x, a2y, a1x, a1y) * w2)
  local sq = signOf(cross(a2x, a2y, b2x, b2y, a2x, a2y, b1x, b1y) * w2)
  if sp * sq >= 0 then return sp ~= 0 and sp or sq end
  local rp = signOf(cross(a1x, a1y, b1x, b1y, a1x, a1y, a2x, a2y) * w1)
  local rq = signOf(cross(a1x, a1y, b1x, b1y, a1x, a1y, b2x, b2y) * w1)
  if rp * rq >= 0 then return -(rp ~= 0 and rp or rq) end
  return crossingOrder(a1x, a1y, b1x, b1y, a2x, a2y, b2x, b2y, w2, ax, ay, bx, by)
end

-- Turning around a point Z of the boundary of some parts. Each part with Z on its boundary
-- covers a wedge of directions from Z, between two spokes along its edges (one spoke each way
-- along an edge with Z inside it): the part lies on the turning side of its entering spoke and
-- before its leaving one. Directions are taken by their angle from a reference direction r,
-- turning the way of a positive cross product; every comparison is an exact sign. The outline's
-- edge where the ray enters is the first spoke at which the cover starts, turning from
-- r = A - B (the way the ray comes from) to the side that is not covered next to r; if both
-- sides are covered, Z is inside the union.
local spokeX, spokeY, spokePart, spokeEdge, spokeEnters, spokeClass, spokeOrder = {}, {}, {}, {}, {}, {}, {}

-- The class of the direction from Z to v by its angle from r = r1 - r0: 0 for r itself, 1 for
-- (0, pi), 2 for pi, 3 for (pi, 2 pi).
local function angleClass(zx, zy, vx, vy, r0x, r0y, r1x, r1y)
  local c = cross(r0x, r0y, r1x, r1y, zx, zy, vx, vy)
  if c > 0 then return 1 elseif c < 0 then return 3 end
  -- on r's line: the same way as r when the differences' signs agree (exact comparisons)
  if (vx > zx) == (r1x > r0x) and (vx < zx) == (r1x < r0x) and (vy > zy) == (r1y > r0y)
      and (vy < zy) == (r1y < r0y) then
    return 0
  end
  return 2
end

-- The order of spokes i and j by angle: -1, 0 or 1.
local function spokeCompare(i, j, zx, zy)
  local ci, cj = spokeClass[i], spokeClass[j]
  if ci ~= cj then return ci < cj and -1 or 1 end
  if ci == 1 or ci == 3 then
    return -signOf(cross(zx, zy, spokeX[i], spokeY[i], zx, zy, spokeX[j], spokeY[j]))
  end
  return 0
end

local spokeCount = 0

local function addSpoke(vx, vy, k, edge, enters)
  spokeCount = spokeCount + 1
  local s = spokeCount
  spokeX[s], spokeY[s], spokePart[s], spokeEdge[s], spokeEnters[s] = vx, vy, k, edge, enters
end

-- The spokes at Z of part k (area sign w, n coordinates), added after those before. Returns
-- whether Z lies strictly inside the part (no spokes then).
local function partSpokes(part, n, k, w, zx, zy)
  local ax, ay = part[n - 1] + 0.0, part[n] + 0.0
  local before = spokeCount
  for i = 1, n - 1, 2 do
    local bx, by = part[i] + 0.0, part[i + 1] + 0.0
    if (ax ~= bx or ay ~= by) and min(ax, bx) <= zx and zx <= max(ax, bx)
        and min(ay, by) <= zy and zy <= max(ay, by) then
      if ax == zx and ay == zy then
        addSpoke(bx, by, k, i, w > 0)
      elseif bx == zx and by == zy then
        addSpoke(ax, ay, k, i, w < 0)
      elseif cross(ax, ay, bx, by, ax, ay, zx, zy) == 0 then
        addSpoke(bx, by, k, i, w > 0)
        addSpoke(ax, ay, k, i, w < 0)
      end
    end
    ax, ay = bx, by
  end
  return spokeCount == before and insideConvex(part, n, zx, zy)
end

-- The unit outward normal of the outline's edge at Z where a ray coming from r0 towards r1
-- (r = r1 - r0 pointing back along the ray) enters the union, from the parts whose boxes hold
-- Z; or nil when the union covers every direction around Z (Z inside it).
local function sweepAround(view, shape, zx, zy, r0x, r0y, r1x, r1y)
  local boxes, turns, normals = view.boxes, view.turns, view.normals
  spokeCount = 0
  local covered = 0   -- the wedges that hold the directions just past r
  for k = 1, view.count do
    local b = 4 * k
    local w = turns[k]
    if w ~= 0 and boxes[b - 3] <= zx and zx <= boxes[b - 1] and boxes[b - 2] <= zy and zy <= boxes[b] then
      local part = shape[k]
      local first = spokeCount + 1
      if partSpokes(part, view.lengths[k], k, w, zx, zy) then return nil end
      if spokeCount == first + 1 then   -- a wedge: its entering spoke and its leaving one
        for s = first, first + 1 do
          spokeClass[s] = angleClass(zx, zy, spokeX[s], spokeY[s], r0x, r0y, r1x, r1y)
          -- a leaving spoke along r ends the wedge at a full turn
          if spokeClass[s] == 0 and not spokeEnters[s] then spokeClass[s] = 4 end
        end
        local e, x = first, first + 1
        if not spokeEnters[e] then e, x = x, e end
        if spokeClass[e] == 0 or spokeCompare(x, e, zx, zy) < 0 then covered = covered + 1 end
      else
        spokeCount = first - 1   -- (a convex part meets a point once: not expected)
      end
    end
  end
  -- the spokes by angle (insertion sort: a handful)
  for s = 1, spokeCount do
    local j = s - 1
    while j >= 1 and spokeCompare(spokeOrder[j], s, zx, zy) > 0 do
      spokeOrder[j + 1] = spokeOrder[j]
      j = j - 1
    end
    spokeOrder[j + 1] = s
  end
  -- turning from r: the first spoke where the cover starts after a gap, and the last where it
  -- ends with no cover after it up to the full turn
  local c, firstStart, lastEnd, gap = covered, 0, 0, covered == 0
  local g = 1
  while g <= spokeCount do
    local h = g
    while h < spokeCount and spokeCompare(spokeOrder[h + 1], spokeOrder[g], zx, zy) == 0 do h = h + 1 end
    local class = spokeClass[spokeOrder[g]]
    if class ~= 0 then   -- (entering spokes along r are in `covered` already)
      local before = c
      local entering, leaving = 0, 0
      for j = g, h do
        local s = spokeOrder[j]
        if spokeEnters[s] then c, entering = c + 1, s else c, leaving = c - 1, s end
      end
      if before == 0 and c > 0 and firstStart == 0 then firstStart = entering end
      if class ~= 4 then
        if c == 0 then
          gap = true
          if before > 0 then lastEnd = leaving end
        else
          lastEnd = 0
        end
      end
    end
    g = h + 1
  end
  if not gap then return nil end   -- covered all around
  -- the side of r that is not covered next to it; when r itself is covered (a segment that
  -- starts on the outline, heading in with the outline behind it too), the first gap's end
  local s = firstStart
  if covered > 0 and lastEnd ~= 0 then s = lastEnd end
  if s == 0 then return nil end
  local normal = normals[spokePart[s]]
  return normal[spokeEdge[s]], normal[spokeEdge[s] + 1]
end

-- A vertex of some part (of nonzero area) at the point where the ray crosses the edge p -> q
-- of part k inside it: its coordinates, or nil. Such a vertex lies in the edge's box, on the
-- ray's line and on the edge's line.
local function vertexAtCrossing(view, shape, px, py, qx, qy, ax, ay, bx, by)
  local x0, x1, y0, y1 = min(px, qx), max(px, qx), min(py, qy), max(py, qy)
  local boxes, turns = view.boxes, view.turns
  local dx, dy = bx - ax, by - ay
  for k = 1, view.count do
    local b = 4 * k
    if turns[k] ~= 0 and boxes[b - 3] <= x1 and x0 <= boxes[b - 1] and boxes[b - 2] <= y1
        and y0 <= boxes[b] then
      local part = shape[k]
      for i = 1, view.lengths[k] - 1, 2 do
        local vx, vy = part[i] + 0.0, part[i + 1] + 0.0
        if x0 <= vx and vx <= x1 and y0 <= vy and vy <= y1
            and lineSide(vx, vy, ax, ay, bx, by, dx, dy) == 0
            and cross(px, py, qx, qy, px, py, vx, vy) == 0 then
          return vx, vy
        end
      end
    end
  end
  return nil
end

-- The stretches of the ray's line covered by parts' edges on it: per cover the side its part
-- lies on (the sign of o off the line) and its ends, ordered along the ray.
local coverSide, coverLoX, coverLoY, coverHiX, coverHiY = {}, {}, {}, {}, {}

-- Whether the point c on the ray's line has covers on both sides from it on: some cover of
-- each side with lo <= c < hi. strict: lo < c < hi instead (then c is inside the union).
local function coveredBothWays(covers, cx, cy, dx, dy, strict)
  local left, right = false, false
  for i = 1, covers do
    local lo = alongOrder(coverLoX[i], coverLoY[i], cx, cy, dx, dy)
    if (lo < 0 or (lo == 0 and not strict)) and alongOrder(cx, cy, coverHiX[i], coverHiY[i], dx, dy) < 0 then
      if coverSide[i] > 0 then left = true else right = true end
    end
  end
  return left and right
end

-- The union's interior against a point (the segment of no length): 0, 0, 0 or false.
local function pointInParts(view, shape, x, y)
  local boxes, turns = view.boxes, view.turns
  for k = 1, view.count do
    local b = 4 * k
    if turns[k] ~= 0 and boxes[b - 3] <= x and x <= boxes[b - 1] and boxes[b - 2] <= y and y <= boxes[b]
        and insideConvex(shape[k], view.lengths[k], x, y) then
      return 0.0, 0.0, 0.0
    end
  end
  -- on seams: covered all around? (any reference direction: a point off (x, y) on its row)
  local rx = x + 1.0
  if rx == x then rx = 2 * x end
  if sweepAround(view, shape, x, y, x, y, rx, y) == nil and spokeCount > 0 then return 0.0, 0.0, 0.0 end
  return false
end

local nearParts = {}   -- castParts' scratch: the parts whose boxes meet the segment's and its line

-- Whether the box at boxes[b - 3 .. b] (xmin, ymin, xmax, ymax) lies strictly on one side of the
-- ray's line, surely: the corners' sides o(v) = d x (v - A) at their least and largest (the
-- corners chosen by the signs of dx and dy) clear their error bounds (lineSide's, Shewchuk's).
-- false also where rounding cannot tell (d = 0 too).
local function lineMissesBox(boxes, b, ax, ay, dx, dy)
  local xmin, ymin, xmax, ymax = boxes[b - 3], boxes[b - 2], boxes[b - 1], boxes[b]
  local hiY, loY = dx > 0 and ymax or ymin, dx > 0 and ymin or ymax
  local hiX, loX = dy > 0 and xmin or xmax, dy > 0 and xmax or xmin
  local l, r = dx * (hiY - ay), dy * (hiX - ax)   -- the largest o
  if l - r < -CROSS_BOUND * (abs(l) + abs(r)) then return true end
  l, r = dx * (loY - ay), dy * (loX - ax)         -- the least o
  return l - r > CROSS_BOUND * (abs(l) + abs(r))
end

-- polygonRayCast for a list of parts: false, or fraction, nx, ny. Its steps: the list's view,
-- each part whose box meets the segment's (its entry, in order with the best so far; or the
-- cover of the line by its edge on it), the start of the seams covered both ways, then the
-- normal at the entry (sweepAround where the entry point is a vertex or A).
local function castParts(fname, shape, ax, ay, bx, by)
  local view = listView(fname, "points", shape)
  call.stamp = call.stamp + 1
  local stamp = call.stamp
  local boxes, turns = view.boxes, view.turns
  local dx, dy = bx - ax, by - ay
  -- every part whose box meets the segment's and its line is brought up to date (its sign and
  -- normals are read: see views.lua's preparedParts); the others can hold no entry, no cover
  -- and no vertex on the line
  local x0, y0, x1, y1 = min(ax, bx), min(ay, by), max(ax, bx), max(ay, by)
  local near = 0   -- the parts so found, their indices in nearParts
  for k = 1, view.count do
    local b = 4 * k
    if boxes[b - 3] <= x1 and x0 <= boxes[b - 1] and boxes[b - 2] <= y1 and y0 <= boxes[b]
        and not lineMissesBox(boxes, b, ax, ay, dx, dy) then
      if view.checked[k] ~= stamp then checkCopy(view, k, shape[k], 4) end
      near = near + 1
      nearParts[near] = k
    end
  end
  if dx == 0 and dy == 0 then
    local f, nx, ny = pointInParts(view, shape, ax, ay)
    return f, nx, ny
  end
  local bestK, bestP, bestQ, bestW, bestKind, bestT, bestErr = 0, 0, 0, 0.0, 0, 0.0, 0.0
  local covers = 0
  for j = 1, near do
    local k = nearParts[j]
    local w = turns[k]
    if w ~= 0 then
      local part, n = shape[k], view.lengths[k]
      sideWalk(part, n, ax, ay, bx, by, dx, dy)
      if fallP ~= 0 and riseP ~= 0 then
        local status = convexEntry(part, w, ax, ay, bx, by)
        if status == INSIDE then return 0.0, 0.0, 0.0 end
        if status == ENTERS then
          local p, q, kind = entryP, entryQ, entryKind
          local t, err = entryEstimate(part, p, q, kind, ax, ay, bx, by)
          local order = -1
          if bestK ~= 0 then
            if t + err < bestT - bestErr then order = -1
            elseif bestT + bestErr < t - err then order = 1
            else order = entryOrder(part, p, q, w, kind, shape[bestK], bestP, bestQ, bestW, bestKind,
              ax, ay, bx, by) end
            -- at the same point: an entry at a vertex or at A (sweepAround decides there)
            if order == 0 and kind ~= ENTERS_EDGE and bestKind == ENTERS_EDGE then order = -1 end
          end
          if order < 0 then
            bestK, bestP, bestQ, bestW, bestKind, bestT, bestErr = k, p, q, w, kind, t, err
          end
        end
      elseif runFirst ~= 0 and runLast ~= 0 and (part[runFirst] ~= part[runLast]
          or part[runFirst + 1] ~= part[runLast + 1]) then
        -- an edge on the line: a cover, on the side of the part's other vertices
        covers = covers + 1
        local fx, fy = part[runFirst] + 0.0, part[runFirst + 1] + 0.0
        local lx, ly = part[runLast] + 0.0, part[runLast + 1] + 0.0
        if alongOrder(fx, fy, lx, ly, dx, dy) > 0 then fx, fy, lx, ly = lx, ly, fx, fy end
        coverSide[covers], coverLoX[covers], coverLoY[covers] = offSide, fx, fy
        coverHiX[covers], coverHiY[covers] = lx, ly
      end
    end
  end
  -- the seams: the least point from A on (before B) with covers on both sides from it on
  local seamX, seamY
  if covers > 0 then
    if coveredBothWays(covers, ax, ay, dx, dy, false) then
      if coveredBothWays(covers, ax, ay, dx, dy, true) then return 0.0, 0.0, 0.0 end
      seamX, seamY = ax, ay
    else
      for i = 1, covers do
        local cx, cy = coverLoX[i], coverLoY[i]
        if alongOrder(ax, ay, cx, cy, dx, dy) < 0 and alongOrder(cx, cy, bx, by, dx, dy) < 0
            and (not seamX or alongOrder(cx, cy, seamX, seamY, dx, dy) < 0)
            and coveredBothWays(covers, cx, cy, dx, dy, false) then
          seamX, seamY = cx, cy
        end
      end
    end
  end
  if seamX and bestK ~= 0 then   -- the seam's start against the best part's entry
    local order
    local best = shape[bestK]
    if bestKind ~= ENTERS_EDGE then
      local zx, zy = ax, ay
      if bestKind == ENTERS_VERTEX then zx, zy = best[bestQ] + 0.0, best[bestQ + 1] + 0.0 end
      order = alongOrder(seamX, seamY, zx, zy, dx, dy)
    else
      local px, py = best[bestP] + 0.0, best[bestP + 1] + 0.0
      local qx, qy = best[bestQ] + 0.0, best[bestQ + 1] + 0.0
      order = signOf(cross(px, py, qx, qy, px, py, seamX, seamY) * bestW)
    end
    if order > 0 then seamX = nil end
  end
  if seamX then
    local nx, ny = sweepAround(view, shape, seamX, seamY, bx, by, ax, ay)
    if seamX == ax and seamY == ay then
      if nx == nil then return 0.0, 0.0, 0.0 end
      return 0.0, nx, ny
    end
    if nx == nil then return false end   -- (not expected: the seam's start is on the outline)
    return pointFraction(seamX, seamY, ax, ay, bx, by), nx, ny
  end
  if bestK == 0 then return false end
  local best = shape[bestK]
  local px, py, qx, qy = best[bestP] + 0.0, best[bestP + 1] + 0.0, best[bestQ] + 0.0, best[bestQ + 1] + 0.0
  bestT = entryFraction(best, bestP, bestQ, bestKind, ax, ay, bx, by)   -- (the estimate ordered them)
  local zx, zy
  if bestKind == ENTERS_AT_A then
    zx, zy = ax, ay
  elseif bestKind == ENTERS_VERTEX then
    zx, zy = qx, qy
  else
    zx, zy = vertexAtCrossing(view, shape, px, py, qx, qy, ax, ay, bx, by)
  end
  if zx then
    local nx, ny = sweepAround(view, shape, zx, zy, bx, by, ax, ay)
    if nx == nil then
      if bestKind == ENTERS_AT_A then return 0.0, 0.0, 0.0 end
    else
      return bestT, nx, ny
    end
  end
  local normal = view.normals[bestK]
  return bestT, normal[bestQ], normal[bestQ + 1]
end

-- Raises the argument error for the first of the ends that is not a finite number.
local function checkEnds(fname, x1, y1, x2, y2)
  checkFiniteNumber(x1, fname, "x1", 4)
  checkFiniteNumber(y1, fname, "y1", 4)
  checkFiniteNumber(x2, fname, "x2", 4)
  checkFiniteNumber(y2, fname, "y2", 4)
end

-- What rayring.lua (flat polygons of any shape, and the public polygonRayCast) shares.
M.lineSide, M.alongOrder, M.entryOrder, M.entryEstimate = lineSide, alongOrder, entryOrder, entryEstimate
M.pointFraction, M.edgeFractionExact = pointFraction, edgeFractionExact
M.castParts, M.checkEnds = castParts, checkEnds
M.ENTERS_EDGE, M.ENTERS_VERTEX, M.ENTERS_AT_A = ENTERS_EDGE, ENTERS_VERTEX, ENTERS_AT_A
return M
