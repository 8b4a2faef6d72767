-- polygon/casts.lua: swept shapes: where a convex polygon moving along a vector first meets a
-- static convex polygon or list of convex parts (polygonsCast), and a moving circle a static one
-- (circlesCast). Every hit or miss and every order of two contact times is exact (kernel's cross,
-- then expansions); the fraction is stepped back until the moved shape, rounded as a game rounds
-- it, does not collide (sat's and circle.lua's exact tests). Relies on kernel, check, convex,
-- views, sat, collide and circle.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local check = require(_PACKAGE .. ".check")
local convex = require(_PACKAGE .. ".convex")
local views = require(_PACKAGE .. ".views")
local sat = require(_PACKAGE .. ".sat")
local collide = require(_PACKAGE .. ".collide")

local abs, huge, min, max, sqrt, floor = math.abs, math.huge, math.min, math.max, math.sqrt,
  math.floor
local cross, CROSS_BOUND, EPS, JIT = kernel.cross, kernel.CROSS_BOUND, kernel.EPS, kernel.JIT
local twoDiff, powerScale, areaSign = kernel.twoDiff, kernel.powerScale, kernel.areaSign
local expClear, expAddProduct, expCompress = kernel.expClear, kernel.expAddProduct, kernel.expCompress
local expCopy, expSign, expCrossScaled = kernel.expCopy, kernel.expSign, kernel.expCrossScaled
local twoProduct, twoSum, quotientDD, expTopTwo = kernel.twoProduct, kernel.twoSum, kernel.quotientDD,
  kernel.expTopTwo
local crossDD = kernel.crossDD
local checkPoints, checkFiniteNumber = check.checkPoints, check.checkFiniteNumber
local checkConvex = convex.checkConvex
local listView, call, checkCopy = views.listView, views.call, views.checkCopy
local unit, convexPenetration = sat.unit, sat.convexPenetration
local resolveShape, polygonsCollideV = collide.resolveShape, collide.polygonsCollideV
local circle = require(_PACKAGE .. ".circle")
local discEntryTerms = require(_PACKAGE .. ".circleray").discEntryTerms
local circlesCollideV = circle.circlesCollideV
-- circlesCast's step back tests moved circles within rounding of touching: on LuaJIT the exact
-- test alone (the filter's side exit, taken on nearly every hit, made a side trace that failed
-- to compile), on PUC Lua circle's reaches as before (the filter, then the exact test)
local stepReaches = JIT and circle.reachesExact or circle.reaches

local type = type

local M = {}


-- The moving polygon P2 is at P2 + t d, t in [0, 1], d = (dx, dy). Two convex polygons' open
-- interiors meet exactly when no edge line of either separates them, and each edge gives an
-- inequality linear in t. For the edge p -> q of P1 (turn w1, interior where w1 (q - p) x (v - p)
-- > 0): P2 lies outside it at t exactly when C + t S <= 0, C = max over P2's vertices v of
-- w1 (q - p) x (v - p), S = w1 (q - p) x d. For the edge r -> s of P2 (turn w2) the roles swap
-- and P2's edge moves: C = max over P1's vertices a of w2 (s - r) x (a - r), S = -w2 (s - r) x d.
-- The pair overlaps at t exactly when C + t S > 0 for every edge of both (the Minkowski
-- difference P1 - P2 is the intersection of these half-planes: its edges are both polygons'):
-- an open interval of t. An edge with S > 0 bounds it from below at t = -C / S (an entry), one
-- with S < 0 from above (an exit), one with S = 0 holds for every t or for none. So:
--   some edge with C <= 0 and S <= 0   a miss (P2 already outside it and not moving in: a slide
--                                      along a face has S = 0 and C = 0);
--   every C > 0                        colliding at t = 0;
--   else                               a hit exactly when the greatest entry (>= 0) is < 1 and
--                                      below every exit.
-- Every entry or exit is a ratio of two cross products of differences of the given doubles,
-- t = ((u1 - u0) x (v1 - v0)) / ((u1 - u0) x d): for P1's edge p -> q and P2's deepest vertex v,
-- u = (p, q), v = (v, p); for P2's edge r -> s and P1's deepest vertex a, u = (r, s), v = (r, a).
-- Two ratios are ordered by their float values when their error bounds part them, else by the
-- exact sign of n1 d2 - n2 d1 (products of expansions).

-- A ratio is held in a table of 9 numbers: u0x, u0y, u1x, u1y, v0x, v0y, v1x, v1y, and the sign
-- sigma that makes sigma ((u1 - u0) rotated a quarter turn clockwise, (ey, -ex)) the contact
-- normal from P1 toward P2 (w1 for P1's edges, -w2 for P2's).
local bestRatio, bestList, candidate = {}, {}, {}
local exits, exitCount = {}, 0   -- the exits of the last convexCast, 8 numbers each

-- Fills the ratio table R.
local function setRatio(R, u0x, u0y, u1x, u1y, v0x, v0y, v1x, v1y, sigma)
  R[1], R[2], R[3], R[4], R[5], R[6], R[7], R[8], R[9] = u0x, u0y, u1x, u1y, v0x, v0y, v1x, v1y, sigma
end

local function copyRatio(into, R)
  for i = 1, 9 do into[i] = R[i] end
end

-- The ratio R[base + 1 .. base + 8] in floating point and a bound on its absolute error (huge
-- where it cannot vouch): each cross product within CROSS_BOUND times its terms' size
-- (Shewchuk's bound, the differences' rounding included), the quotient's relative error their
-- relative bounds summed plus eps, to first order (the rest is negligible below 2^-20), where
-- no product overflowed or lost bits to underflow.
local function ratioEstimate(R, base, dx, dy)
  local ex, ey = R[base + 3] - R[base + 1], R[base + 4] - R[base + 2]
  local wx, wy = R[base + 7] - R[base + 5], R[base + 8] - R[base + 6]
  local nl, nr, dl, dr = ex * wy, ey * wx, ex * dy, ey * dx
  local num, den = nl - nr, dl - dr
  local numSize, denSize = abs(nl) + abs(nr), abs(dl) + abs(dr)
  local t = num / den
  if numSize == 0 and denSize > 2^-900 and denSize < 2^1000 and (ex == 0 or wy == 0)
      and (ey == 0 or wx == 0) then
    return 0.0, 0.0   -- the numerator is exactly 0 (no difference is 0 by rounding)
  end
  local rel = CROSS_BOUND * (numSize / abs(num) + denSize / abs(den))
  if rel < 2^-20 and numSize > 2^-900 and denSize > 2^-900 and numSize < 2^1000 and denSize < 2^1000 then
    return t, (rel + EPS) * abs(t) * (1 + 2^-18)
  end
  return t, huge
end

-- Scratch for the exact orders and fractions: compressed expansions copied out of kernel's one.
local partsA, partsB, partsC, partsD = {}, {}, {}, {}

-- The exact (u1 - u0) x (v1 - v0) of the coordinates times s (a power of two) into `into`,
-- compressed (its largest component last, within an ulp of the value); returns its length.
local function crossInto(into, u0x, u0y, u1x, u1y, v0x, v0y, v1x, v1y, s)
  expCrossScaled(u0x, u0y, u1x, u1y, v0x, v0y, v1x, v1y, s)
  return expCopy(into)
end

-- The largest magnitude among R[base + 1 .. base + 8].
local function ratioMagnitude(R, base)
  local m = 0.0
  for i = base + 1, base + 8 do m = max(m, abs(R[i])) end
  return m
end

-- The power of two for the exact products of four differences: coordinates beyond 2^250 or
-- below 2^-100 in magnitude are brought into [2^186, 2^250] (exact, short of underflow), so no
-- product of two cross products overflows.
local function productScale(m)
  if m > 2^250 or (m < 2^-100 and m > 0) then return powerScale(m, 2^186, 2^250) end
  return 1.0
end

-- The numerator and denominator of the ratio R[base + 1 ..] as exact expansions, into numParts
-- and denParts; returns their lengths.
local function ratioExact(R, base, dx, dy, s, numParts, denParts)
  local u0x, u0y, u1x, u1y = R[base + 1], R[base + 2], R[base + 3], R[base + 4]
  local numLen = crossInto(numParts, u0x, u0y, u1x, u1y, R[base + 5], R[base + 6], R[base + 7],
    R[base + 8], s)
  local denLen = crossInto(denParts, u0x, u0y, u1x, u1y, 0.0, 0.0, dx, dy, s)
  return numLen, denLen
end

-- The sign of the top component of an expansion copied into parts (length len), 0 when empty.
local function partsSign(parts, len)
  if len == 0 then return 0 end
  return parts[len] > 0 and 1 or -1
end

-- The sign of t(R) - t(Q), R at R[a + 1 ..], Q at Q[b + 1 ..] (both denominators nonzero). Exact.
local function compareRatios(R, a, Q, b, dx, dy)
  local tr, er = ratioEstimate(R, a, dx, dy)
  local tq, eq = ratioEstimate(Q, b, dx, dy)
  if tr + er < tq - eq then return -1 end
  if tq + eq < tr - er then return 1 end
  local m = max(ratioMagnitude(R, a), ratioMagnitude(Q, b), abs(dx), abs(dy))
  local s = productScale(m)
  local la, lb = ratioExact(R, a, dx, dy, s, partsA, partsB)
  local lc, ld = ratioExact(Q, b, dx, dy, s, partsC, partsD)
  -- nR / dR - nQ / dQ has the sign of (nR dQ - nQ dR) dR dQ
  expClear()
  for i = 1, la do
    for j = 1, ld do expAddProduct(partsA[i], partsD[j]) end
  end
  for i = 1, lc do
    for j = 1, lb do expAddProduct(-partsC[i], partsB[j]) end
  end
  return expSign() * partsSign(partsB, lb) * partsSign(partsD, ld)
end

-- Whether t(R) < 1 (R at R[1 ..], its denominator nonzero). Exact.
local function ratioBelowOne(R, dx, dy)
  local t, e = ratioEstimate(R, 0, dx, dy)
  if t + e < 1 then return true end
  if t - e > 1 then return false end
  local s = productScale(max(ratioMagnitude(R, 0), abs(dx), abs(dy)))
  local la, lb = ratioExact(R, 0, dx, dy, s, partsA, partsB)
  expClear()   -- (n - d) / d < 0
  for i = 1, la do expAddProduct(partsA[i], 1.0) end
  for i = 1, lb do expAddProduct(-partsB[i], 1.0) end
  return expSign() * partsSign(partsB, lb) < 0
end

-- t(R) from double doubles, with no loop (raycast.lua's edgeFractionDD with d exact): every
-- difference split exactly (TwoDiff), each cross product the exact difference of its two main
-- products (TwoProduct, then TwoDiff) plus its first-order terms, then the quotient corrected once
-- by its residual. What is dropped is below 2^-100 (|l| + |r|) (l and r a cross product's two
-- products), so t is within eps |t| (its own rounding) plus 2^-99 c |t|, c = (|l| + |r|) / |cross|
-- for either cross product: nil when c passes 2^30, or a product nears overflow or underflow.
local function ratioValueDD(R, dx, dy)
  local exh, exl = twoDiff(R[3], R[1])
  local eyh, eyl = twoDiff(R[4], R[2])
  local wxh, wxl = twoDiff(R[7], R[5])
  local wyh, wyl = twoDiff(R[8], R[6])
  local nh, numLow, numSize = crossDD(exh, exl, eyh, eyl, wxh, wxl, wyh, wyl)
  local lh, ll = twoProduct(exh, dy)
  local rh, rl = twoProduct(eyh, dx)
  local dh, d0 = twoDiff(lh, rh)
  local denLow = d0 + (ll - rl) + (exl * dy - eyl * dx)
  local denSize = abs(lh) + abs(rh)
  return quotientDD(nh, numLow, numSize, dh, denLow, denSize)
end

-- t(R) within u / 4 (u = eps M / |d|, the caller's unit of step) before its final rounding: the
-- float value when its bound allows, else ratioValueDD's, else the quotient of the exact
-- expansions' top components corrected once by the exact residual n - t0 d (within an ulp of t,
-- plus order eps^2).
local function ratioValue(R, dx, dy, u)
  local t, e = ratioEstimate(R, 0, dx, dy)
  if e <= 0.25 * u then return t end
  t = ratioValueDD(R, dx, dy)
  if t then return t end
  local s = productScale(max(ratioMagnitude(R, 0), abs(dx), abs(dy)))
  local la, lb = ratioExact(R, 0, dx, dy, s, partsA, partsB)
  if la == 0 then return 0.0 end
  local numTop, denTop = partsA[la], partsB[lb]
  local t0 = numTop / denTop
  expClear()
  for i = 1, la do expAddProduct(partsA[i], 1.0) end
  for i = 1, lb do expAddProduct(-t0, partsB[i]) end
  return t0 + expCompress() / denTop
end

-- The vertex index (odd) of `other` (m coordinates) deepest on the inner side of the edge
-- p -> q of a polygon of turn w: the greatest w (q - p) x (v - p). Exact.
local function deepest(px, py, qx, qy, w, other, m)
  local best = 1
  local bx, by = other[1] + 0.0, other[2] + 0.0
  for j = 3, m - 1, 2 do
    local vx, vy = other[j] + 0.0, other[j + 1] + 0.0
    if cross(px, py, qx, qy, bx, by, vx, vy) * w > 0 then best, bx, by = j, vx, vy end
  end
  return best
end

local MISS, HIT, INSIDE = 0, 1, 2

-- convexCast's walk over the edges of one polygon (`own`, turn w, its edges' u = (p, q)) against
-- the other's vertices. moving: own is P2 (its edges move). Leaves the greatest entry with C <= 0
-- in bestRatio (found: whether there is one yet) and appends the exits; returns MISS, or whether
-- every C was > 0 so far (allInside).
local function edgeWalk(own, n, w, other, m, moving, dx, dy, found, allInside)
  local px, py = own[n - 1] + 0.0, own[n] + 0.0
  local sigma = moving and -w or w
  for i = 1, n - 1, 2 do
    local qx, qy = own[i] + 0.0, own[i + 1] + 0.0
    if qx ~= px or qy ~= py then
      local j = deepest(px, py, qx, qy, w, other, m)
      local vx, vy = other[j] + 0.0, other[j + 1] + 0.0
      local c = cross(px, py, qx, qy, px, py, vx, vy) * w
      local sd = cross(px, py, qx, qy, 0.0, 0.0, dx, dy) * w
      if moving then sd = -sd end
      if c <= 0 then
        allInside = false
        if sd <= 0 then return MISS end
        -- an entry at t >= 0: u = (p, q); v = (v, p) for P1's edges, (p, v) for P2's
        if moving then
          setRatio(candidate, px, py, qx, qy, px, py, vx, vy, sigma)
        else
          setRatio(candidate, px, py, qx, qy, vx, vy, px, py, sigma)
        end
        if not found or compareRatios(candidate, 0, bestRatio, 0, dx, dy) > 0 then
          copyRatio(bestRatio, candidate)
          found = true
        end
      elseif sd < 0 then   -- an exit at t > 0
        local b = 8 * exitCount
        exits[b + 1], exits[b + 2], exits[b + 3], exits[b + 4] = px, py, qx, qy
        if moving then
          exits[b + 5], exits[b + 6], exits[b + 7], exits[b + 8] = px, py, vx, vy
        else
          exits[b + 5], exits[b + 6], exits[b + 7], exits[b + 8] = vx, vy, px, py
        end
        exitCount = exitCount + 1
      end
    end
    px, py = qx, qy
  end
  return found, allInside
end

-- Whether convex P1 (p1[1 .. n1], turn w1) and convex P2 (turn w2) moving by t d meet for some t
-- in [0, 1]: MISS, INSIDE (colliding at t = 0) or HIT, the entry left in bestRatio. Exact.
local function convexCast(p1, n1, w1, p2, n2, w2, dx, dy)
  if w1 == 0 or w2 == 0 then return MISS end   -- zero area never collides
  exitCount = 0
  local found, allInside = edgeWalk(p1, n1, w1, p2, n2, false, dx, dy, false, true)
  if found == MISS then return MISS end
  found, allInside = edgeWalk(p2, n2, w2, p1, n1, true, dx, dy, found, allInside)
  if found == MISS then return MISS end
  if allInside then return INSIDE end
  if not ratioBelowOne(bestRatio, dx, dy) then return MISS end
  for k = 0, exitCount - 1 do
    if compareRatios(bestRatio, 0, exits, 8 * k, dx, dy) >= 0 then return MISS end
  end
  return HIT
end

-- Scratch for the moved polygon of the step back.
local moved = {}

-- Whether P2 moved by t d, each coordinate rounded as a game computes it (x + t * dx), collides
-- with p1 (convex, n1 coordinates; exact), or with a near part of the list `shape` (view: its
-- view; near: how many of nearParts).
local nearParts = {}
local function movedCollides(p1, n1, view, near, p2, n2, t, dx, dy)
  for i = 1, n2 - 1, 2 do
    moved[i] = p2[i] + t * dx
    moved[i + 1] = p2[i + 1] + t * dy
  end
  if not view then return convexPenetration(p1, n1, moved, n2, true) ~= false end
  for j = 1, near do
    local k = nearParts[j]
    if view.turns[k] ~= 0 and convexPenetration(p1[k], view.lengths[k], moved, n2, true) then
      return true
    end
  end
  return false
end

-- The steps back from the computed entry t, in units of u = eps M / |d|. The computed t is within
-- e = u / 4 + 2 eps t of the exact one (ratioValue's bound, or the disc's double doubles, plus the
-- final roundings; 2 eps t <= 2 sqrt(2) u t as |d| <= 2 sqrt(2) M), so every t - k u / 4 down to
-- t - (8 u - e) is no earlier than 8 u before it: each is tried in turn. Where the motion grazes
-- the contact (nearly parallel to it) a step back of u hardly moves the shapes apart, and the
-- rounding of the moved coordinates, which changes every quarter u or so, decides. Past the
-- window (grazing contacts only) the steps double from 8 u, down to 0 (the start, which does not
-- collide): the move is never allowed to end colliding, even where no fraction within 8 u of
-- the contact leaves the rounded shapes apart.
local function windowSteps(t, u)
  return floor((8 * u - (0.25 * u + 2 * EPS * t)) / (0.25 * u) * (1 - 2^-20)) + 1
end

local COARSE = { 0, 1, 2, 3, 5 }   -- tried first: one or two tests find most answers
local function stepBack(k, window)
  if k <= #COARSE then return COARSE[k] end
  k = k - #COARSE
  if k <= window then return (k - 1) * 0.25 end
  return 8 * 2^(k - window - 1)
end

-- The fraction to return for the entry in bestRatio: the first of t, t - u, t - 2 u, t - 3 u,
-- t - 5 u, then t, t - u / 4, ... that leaves the moved polygon not colliding.
local function steppedFraction(p1, n1, view, near, p2, n2, dx, dy, m)
  local _, _, len = unit(dx, dy)
  local u = EPS * m / len
  local t = min(ratioValue(bestRatio, dx, dy, u), 1.0)
  local window = windowSteps(t, u)
  for k = 1, #COARSE + window + 1060 do
    local f = max(t - stepBack(k, window) * u, 0.0)
    if f == 0 or not movedCollides(p1, n1, view, near, p2, n2, f, dx, dy) then return f end
  end
  return 0.0
end

-- The largest coordinate magnitude of P2 at its start and moved by d (in floating point).
local function movingMagnitude(p2, n2, dx, dy)
  local m = 0.0
  for i = 1, n2 - 1, 2 do
    local x, y = p2[i], p2[i + 1]
    m = max(m, abs(x), abs(y), abs(x + dx), abs(y + dy))
  end
  return m
end

-- The contact normal of the entry in bestRatio: sigma (ey, -ex), unit.
local function entryNormal()
  local sigma = bestRatio[9]
  local nx, ny = unit(sigma * (bestRatio[4] - bestRatio[2]), -sigma * (bestRatio[3] - bestRatio[1]))
  return nx + 0.0, ny + 0.0   -- + 0.0: a component of -0 reads as 0
end

-- The answer when the pair collides at t = 0: 0 and the unit direction of polygonsCollideV's push.
local function startPush(points1, points2)
  local _, px, py = polygonsCollideV(points1, points2)
  local nx, ny = unit(px, py)
  return 0.0, nx + 0.0, ny + 0.0
end

-- Raises fname's non-finite error when points[1 .. n] holds a NaN or an infinity (at the caller
-- of the public function, which called this function's caller).
local function checkFinite(points, n, fname, argname, level)
  local sum = 0.0
  for i = 1, n do local v = points[i]; sum = sum + (v - v) end
  if sum ~= 0 then error(("%s: %s holds a non-finite coordinate"):format(fname, argname), level) end
end

-- The sign of a polygon's area (areaSign returns a number of that sign), 1, -1 or 0.
local function turnOf(points, n)
  local w = areaSign(points, n)
  return w > 0 and 1 or (w < 0 and -1 or 0)
end

-- The static shape's checks (polygonsCast's points1, polygonCircleCast's points): a Polygon
-- object's points taken, a flat one of at least 3 finite points and convex, a list of parts
-- left to its view. Returns the shape, its first entry's type ("table" for a list) and, flat,
-- its length. Raises at the caller of the public function, which called this one.
local function checkStatic(fname, argname, points)
  local kind = type(points) == "table" and type(points[1])
  if kind ~= "number" then
    points, kind = resolveShape(fname, argname, points, kind, 3)
  end
  local n
  if kind ~= "table" then
    n = checkPoints(points, fname, argname, 4)
    checkFinite(points, n, fname, argname, 4)
    checkConvex(points, n, fname, argname, 3)
  end
  return points, kind, n
end

-- P2's checks: a flat convex polygon of finite coordinates (a list of parts refused). Returns n2.
local function checkMoving(fname, points2)
  local kind = type(points2) == "table" and type(points2[1])
  if kind ~= "number" then
    local k
    points2, k = resolveShape(fname, "points2", points2, kind, 3)
    if k == "table" then
      error(("%s: points2 is a list of parts; the moving shape must be one convex polygon (cast "
        .. "each part, or their hull)"):format(fname), 3)
    end
  end
  local n2 = checkPoints(points2, fname, "points2", 4)
  checkFinite(points2, n2, fname, "points2", 4)
  checkConvex(points2, n2, fname, "points2", 3)
  return points2, n2
end

-- polygonsCast against a list of parts: false, or fraction, nx, ny.
local function castParts(fname, shape, p2, n2, w2, dx, dy)
  local view = listView(fname, "points1", shape)
  call.stamp = call.stamp + 1
  local stamp = call.stamp
  local boxes, turns = view.boxes, view.turns
  -- the box P2 sweeps, widened by far more than its rounding (a part beyond it cannot be met)
  local x0, y0, x1, y1 = huge, huge, -huge, -huge
  for i = 1, n2 - 1, 2 do
    local x, y = p2[i] + 0.0, p2[i + 1] + 0.0
    x0, y0, x1, y1 = min(x0, x, x + dx), min(y0, y, y + dy), max(x1, x, x + dx), max(y1, y, y + dy)
  end
  local pad = 2^-40 * max(abs(x0), abs(y0), abs(x1), abs(y1))
  x0, y0, x1, y1 = x0 - pad, y0 - pad, x1 + pad, y1 + pad
  local near, foundK = 0, 0
  local m = movingMagnitude(p2, n2, dx, dy)
  for k = 1, view.count do
    local b = 4 * k
    if boxes[b - 3] <= x1 and x0 <= boxes[b - 1] and boxes[b - 2] <= y1 and y0 <= boxes[b] then
      if view.checked[k] ~= stamp then checkCopy(view, k, shape[k], 4) end
      near = near + 1
      nearParts[near] = k
      m = max(m, abs(boxes[b - 3]), abs(boxes[b - 2]), abs(boxes[b - 1]), abs(boxes[b]))
      local w1 = turns[k]
      w1 = w1 > 0 and 1 or (w1 < 0 and -1 or 0)
      local status = convexCast(shape[k], view.lengths[k], w1, p2, n2, w2, dx, dy)
      if status == INSIDE then return startPush(shape, p2) end
      if status == HIT and (foundK == 0 or compareRatios(bestRatio, 0, bestList, 0, dx, dy) < 0) then
        copyRatio(bestList, bestRatio)
        foundK = k
      end
    end
  end
  if foundK == 0 then return false end
  copyRatio(bestRatio, bestList)
  local f = steppedFraction(shape, 0, view, near, p2, n2, dx, dy, m)
  local nx, ny = entryNormal()
  return f, nx, ny
end

-- DISCS. The moving disc (centre A, radius r2) meets the static one (centre C, radius r1) at t
-- when |w + t d| < R, w = A - C, R = r1 + r2 (exact as rh + rl, TwoSum): f(t) = Q t^2 + 2 P t + K
-- < 0, Q = |d|^2, P = d.w, K = |w|^2 - R^2. With K < 0 they collide at t = 0. Else (K >= 0) f
-- dips below 0 in [0, 1] exactly when f(1) < 0, or P < 0, P + Q > 0 (its least value inside) and
-- G = P^2 - Q K = R^2 Q - X^2 > 0, X = d x w (Lagrange's identity): each a sign of a sum of
-- products of the split differences wx = wxh + wxl, wy, of d and of rh + rl, summed exactly as an
-- expansion. The entry is t = K / (-P + sqrt G) (no cancellation: -P > 0) from the expansions'
-- top components as double doubles, the contact normal along X (-dy, dx) - sqrt(G) d (the
-- contact point's offset from C times Q).

-- The power of two for the disc tests (every term of degree 4 at most): into [2^186, 2^250]
-- (circle.lua's range for its exact tests), 2^200 for the sizes games use.
local function discScale(m)
  if m >= 2^-14 and m <= 2^50 then return 2^200 end
  return powerScale(m, 2^186, 2^250)
end

-- What discSetup leaves: the split differences and radius sum, scaled, and d scaled.
local wxh, wxl, wyh, wyl, rh, rl, ddx, ddy = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0

local function discSetup(cx, cy, R1, ax, ay, R2, dx, dy)
  local s = discScale(max(abs(cx), abs(cy), abs(ax), abs(ay), abs(dx), abs(dy), R1, R2))
  wxh, wxl = twoDiff(ax * s, cx * s)
  wyh, wyl = twoDiff(ay * s, cy * s)
  rh, rl = twoDiff(R1 * s, -R2 * s)
  ddx, ddy = dx * s, dy * s
end

-- Adds (a + b + c)^2 times sign to the scratch expansion.
local function expAddSquare3(a, b, c, sign)
  expAddProduct(sign * a, a); expAddProduct(sign * b, b); expAddProduct(sign * c, c)
  expAddProduct(2 * sign * a, b); expAddProduct(2 * sign * a, c); expAddProduct(2 * sign * b, c)
end

-- The exact sign of f(1) = |w + d|^2 - R^2.
local function discEndSign()
  expClear()
  expAddSquare3(wxh, wxl, ddx, 1)
  expAddSquare3(wyh, wyl, ddy, 1)
  expAddSquare3(rh, rl, 0.0, -1)
  return expSign()
end

-- The exact sign of P = d.w, and of P + Q = d.(w + d).
local function discTowardSigns()
  expClear()
  expAddProduct(ddx, wxh); expAddProduct(ddx, wxl); expAddProduct(ddy, wyh); expAddProduct(ddy, wyl)
  local p = expSign()
  expAddProduct(ddx, ddx); expAddProduct(ddy, ddy)
  return p, expSign()
end

local crossScratch, radiusScratch, lengthScratch = {}, {}, {}

-- G = R^2 Q - X^2 into the scratch expansion (compressed); returns its sign.
local function discGap()
  expClear()   -- X = d x w
  expAddProduct(ddx, wyh); expAddProduct(ddx, wyl); expAddProduct(-ddy, wxh); expAddProduct(-ddy, wxl)
  expCompress()
  local xLen = expCopy(crossScratch)
  expClear()
  expAddSquare3(rh, rl, 0.0, 1)
  expCompress()
  local rLen = expCopy(radiusScratch)
  expClear()
  expAddProduct(ddx, ddx); expAddProduct(ddy, ddy)
  expCompress()
  local qLen = expCopy(lengthScratch)
  expClear()
  for i = 1, rLen do
    for j = 1, qLen do expAddProduct(radiusScratch[i], lengthScratch[j]) end
  end
  for i = 1, xLen do
    for j = 1, xLen do expAddProduct(-crossScratch[i], crossScratch[j]) end
  end
  expCompress()
  return expSign(), xLen
end


-- The entry time and contact normal of a hit found by discCastStatus (discSetup's numbers):
-- t = K / (-P + sqrt G), each from its exact expansion's top two components.
local function discEntry()
  discGap()
  local gh, gl = expTopTwo()
  expClear()   -- X again, its top component, for the normal
  expAddProduct(ddx, wyh); expAddProduct(ddx, wyl); expAddProduct(-ddy, wxh); expAddProduct(-ddy, wxl)
  local xh = expCompress()
  expClear()   -- P
  expAddProduct(ddx, wxh); expAddProduct(ddx, wxl); expAddProduct(ddy, wyh); expAddProduct(ddy, wyl)
  local ph, pl = expTopTwo()
  expClear()   -- K = |w|^2 - R^2
  expAddSquare3(wxh, wxl, 0.0, 1)
  expAddSquare3(wyh, wyl, 0.0, 1)
  expAddSquare3(rh, rl, 0.0, -1)
  local kh, kl = expTopTwo()
  local root = sqrt(max(gh, 0.0))
  local rootLo = 0.0
  if root > 0 then
    local sh, sl = twoProduct(root, root)
    rootLo = (((gh - sh) - sl) + gl) / (2 * root)
  end
  local dh, dlo = twoSum(root, -ph)   -- D = sqrt G - P > 0
  dlo = dlo + (rootLo - pl)
  local t = kh / dh
  local th, tl = twoProduct(t, dh)
  t = t + ((((kh - th) - tl) + kl) - t * dlo) / dh
  local nx, ny = unit(-root * ddx - xh * ddy, xh * ddx - root * ddy)
  return max(t, 0.0), nx, ny
end

-- The signs discCastStatus needs, in floating point first: each value with a bound on its error
-- (w = A - C rounded once, w + d twice, r1 + r2 once; each square or product once more, each
-- sum once more: a few eps times the sizes of the terms, with the rounding of w + d counted
-- against |w| + |d| as it may cancel), 8 or 16 eps times the terms' size, which is more than
-- twice that. 0 where the bound cannot vouch (or a value nears overflow or underflow).
local function vouched(value, size)
  if (value > size or -value > size) and size > 2^-900 and size < 2^1000 then return value end
  return 0.0
end

-- discEntry's numbers as double doubles, with no loop (as circleray.lua's circleEntryDD, with d
-- exact and R = rh + rl): the differences split exactly, each product's main part exact
-- (TwoProduct), first-order terms added, each sum of high parts exact (TwoSum, TwoDiff). What is
-- dropped is below 2^-100 times a quantity's terms, so K, G and D = sqrt(G) - P are within
-- 2^-100 c of themselves, c their terms over them, and t = K / D, corrected once, is within eps
-- plus order eps^2 when c stays below 2^30 for K and G; else nil (the expansions).
local function discEntryDD(cx, cy, R1, ax, ay, R2, dx, dy)
  local wx, wxLo = twoDiff(ax, cx)
  local wy, wyLo = twoDiff(ay, cy)
  local rHi, rLo = twoSum(R1, R2)
  local m = max(abs(wx), abs(wy), abs(dx), abs(dy), rHi)
  if m > 2^200 or m < 2^-200 then return nil end   -- (products' range)
  local rrh, rrl = twoProduct(rHi, rHi)   -- R^2
  rrl = rrl + 2 * rHi * rLo
  local t, nx, ny = discEntryTerms(wx, wxLo, wy, wyLo, dx, 0.0, dy, 0.0, rrh, rrl)
  if not t then return nil end
  return max(t, 0.0), nx, ny
end

-- MISS, INSIDE or HIT from the float signs, or nil where one of them cannot be vouched for.
local function discCastFiltered(cx, cy, R1, ax, ay, R2, dx, dy)
  local wx, wy, R = ax - cx, ay - cy, R1 + R2
  local ww, rr = wx * wx + wy * wy, R * R
  local k = vouched(ww - rr, 8 * EPS * (ww + rr))
  if k == 0 then return nil end
  if k < 0 then return INSIDE end
  local ux, uy = wx + dx, wy + dy
  local sx, sy = abs(wx) + abs(dx), abs(wy) + abs(dy)
  local f1 = vouched(ux * ux + uy * uy - rr, 8 * EPS * (sx * sx + sy * sy + rr))
  if f1 == 0 then return nil end
  if f1 < 0 then return HIT end
  local p = vouched(dx * wx + dy * wy, 8 * EPS * (abs(dx * wx) + abs(dy * wy)))
  if p == 0 then return nil end
  if p > 0 then return MISS end
  local pq = vouched(dx * ux + dy * uy, 8 * EPS * (abs(dx) * sx + abs(dy) * sy))
  if pq == 0 then return nil end
  if pq < 0 then return MISS end
  local l, r = dx * wy, dy * wx
  local x, terms, q = l - r, abs(l) + abs(r), dx * dx + dy * dy
  local g = vouched(rr * q - x * x, 16 * EPS * (rr * q + terms * terms))
  if g == 0 then return nil end
  return g > 0 and HIT or MISS
end

-- 1 for x > 0, 0 for x <= 0 (a nonzero double times 2^2000 is at least 2^926), NaN for NaN.
local BIG = 2^1000
local function positive(x) return min(1, max(0, x * BIG * BIG)) end

-- The same signs, LuaJIT's, with no branch: each value kept where its bound vouches (times 1,
-- else times 0), then the outcome as a number (3 INSIDE, 2 HIT, 1 MISS, 0 or NaN: not vouched
-- for). The comparisons above go both ways from call to call, and their side traces, with this
-- many numbers alive, failed to compile ("NYI: register coalescing too complex", bench/NOTES.md).
local function discCodeJit(cx, cy, R1, ax, ay, R2, dx, dy)
  local wx, wy, R = ax - cx, ay - cy, R1 + R2
  local ww, rr = wx * wx + wy * wy, R * R
  local size = 8 * EPS * (ww + rr)
  local k = (ww - rr) * positive(min(abs(ww - rr) - size, size - 2^-900, 2^1000 - size))
  local ux, uy = wx + dx, wy + dy
  local sx, sy = abs(wx) + abs(dx), abs(wy) + abs(dy)
  size = 8 * EPS * (sx * sx + sy * sy + rr)
  local f1 = ux * ux + uy * uy - rr
  f1 = f1 * positive(min(abs(f1) - size, size - 2^-900, 2^1000 - size))
  size = 8 * EPS * (abs(dx * wx) + abs(dy * wy))
  local p = dx * wx + dy * wy
  p = p * positive(min(abs(p) - size, size - 2^-900, 2^1000 - size))
  size = 8 * EPS * (abs(dx) * sx + abs(dy) * sy)
  local pq = dx * ux + dy * uy
  pq = pq * positive(min(abs(pq) - size, size - 2^-900, 2^1000 - size))
  local l, r = dx * wy, dy * wx
  local x, terms, q = l - r, abs(l) + abs(r), dx * dx + dy * dy
  size = 16 * EPS * (rr * q + terms * terms)
  local g = rr * q - x * x
  g = g * positive(min(abs(g) - size, size - 2^-900, 2^1000 - size))
  -- as discCastFiltered's steps: k < 0 INSIDE; f1 < 0 HIT; p > 0 MISS; pq < 0 MISS; g's sign
  local kP, f1P, pN, pqP = positive(k), positive(f1), positive(-p), positive(pq)
  local before = kP * f1P * pN * pqP
  return 3 * positive(-k) + 2 * (kP * positive(-f1) + before * positive(g))
    + kP * f1P * (positive(p) + pN * (positive(-pq) + pqP * positive(-g)))
end

local function discCastFilteredJit(cx, cy, R1, ax, ay, R2, dx, dy)
  local code = discCodeJit(cx, cy, R1, ax, ay, R2, dx, dy)
  if code == 1 then return MISS end
  if code == 2 then return HIT end
  if code == 3 then return INSIDE end
  return nil
end

local discCastFilteredPuc = discCastFiltered
if JIT then discCastFiltered = discCastFilteredJit end

-- MISS, INSIDE or HIT for the disc (ax, ay, R2) moving by d against the disc (cx, cy, R1).
local function discCastStatus(cx, cy, R1, ax, ay, R2, dx, dy)
  local status = discCastFiltered(cx, cy, R1, ax, ay, R2, dx, dy)
  if status then return status end
  discSetup(cx, cy, R1, ax, ay, R2, dx, dy)
  expClear()   -- K = |w|^2 - R^2
  expAddSquare3(wxh, wxl, 0.0, 1)
  expAddSquare3(wyh, wyl, 0.0, 1)
  expAddSquare3(rh, rl, 0.0, -1)
  if expSign() < 0 then return INSIDE end
  if discEndSign() < 0 then return HIT end
  local p, pq = discTowardSigns()
  if p >= 0 or pq <= 0 then return MISS end
  if discGap() > 0 then return HIT end
  return MISS
end

-- polygonsCast(points1, points2, dx, dy): where the convex polygon points2, moving by t (dx, dy)
-- for t in [0, 1], first touches points1 (a convex polygon or a list of convex parts): fraction,
-- nx, ny or false. See polygon.lua for the contract.
function M.polygonsCast(points1, points2, dx, dy)
  local fname = "polygonsCast"
  local kind1, n1
  points1, kind1, n1 = checkStatic(fname, "points1", points1)
  local p2, n2 = checkMoving(fname, points2)
  checkFiniteNumber(dx, fname, "dx")
  checkFiniteNumber(dy, fname, "dy")
  dx, dy = dx + 0.0, dy + 0.0
  local w2 = turnOf(p2, n2)
  if kind1 == "table" then
    local f, nx, ny = castParts(fname, points1, p2, n2, w2, dx, dy)
    if not f then return false end
    return f, nx, ny
  end
  local status = convexCast(points1, n1, turnOf(points1, n1), p2, n2, w2, dx, dy)
  if status == MISS then return false end
  if status == INSIDE then
    local f, nx, ny = startPush(points1, p2)
    return f, nx, ny
  end
  local m = max(movingMagnitude(p2, n2, dx, dy), kernel.largestMagnitude(points1, n1, 0.0))
  local f = steppedFraction(points1, n1, nil, 0, p2, n2, dx, dy, m)
  local nx, ny = entryNormal()
  return f, nx, ny
end

-- Raises circlesCast's argument error for the first bad argument (at the caller of circlesCast).
local function checkCircles(x1, y1, r1, x2, y2, r2, dx, dy)
  local fname = "circlesCast"
  checkFiniteNumber(x1, fname, "x1", 4)
  checkFiniteNumber(y1, fname, "y1", 4)
  checkFiniteNumber(r1, fname, "r1", 4)
  if r1 < 0 then error(("%s: r1 must not be negative, got %s"):format(fname, tostring(r1)), 4) end
  checkFiniteNumber(x2, fname, "x2", 4)
  checkFiniteNumber(y2, fname, "y2", 4)
  checkFiniteNumber(r2, fname, "r2", 4)
  if r2 < 0 then error(("%s: r2 must not be negative, got %s"):format(fname, tostring(r2)), 4) end
  checkFiniteNumber(dx, fname, "dx", 4)
  checkFiniteNumber(dy, fname, "dy", 4)
end

-- circlesCast(x1, y1, r1, x2, y2, r2, dx, dy): where the circle (x2, y2, r2), moving by t (dx, dy)
-- for t in [0, 1], first touches the circle (x1, y1, r1): fraction, nx, ny or false. See
-- polygon.lua for the contract.
function M.circlesCast(x1, y1, r1, x2, y2, r2, dx, dy)
  -- the checks written out for the common case (eight calls to checkFiniteNumber took half of a
  -- miss's time on Lua 5.4): x - x is 0 for every finite number, NaN for an infinity or NaN
  if type(x1) ~= "number" or type(y1) ~= "number" or type(r1) ~= "number" or type(x2) ~= "number"
      or type(y2) ~= "number" or type(r2) ~= "number" or type(dx) ~= "number" or type(dy) ~= "number"
      or (x1 - x1) + (y1 - y1) + (r1 - r1) + (x2 - x2) + (y2 - y2) + (r2 - r2) + (dx - dx) + (dy - dy) ~= 0
      or r1 < 0 or r2 < 0 then
    checkCircles(x1, y1, r1, x2, y2, r2, dx, dy)
  end
  x1, y1, r1, x2, y2, r2 = x1 + 0.0, y1 + 0.0, r1 + 0.0, x2 + 0.0, y2 + 0.0, r2 + 0.0
  dx, dy = dx + 0.0, dy + 0.0
  local status = discCastStatus(x1, y1, r1, x2, y2, r2, dx, dy)
  if status == MISS then return false end
  if status == INSIDE then
    local _, px, py = circlesCollideV(x1, y1, r1, x2, y2, r2)
    local nx, ny = unit(px, py)
    return 0.0, nx + 0.0, ny + 0.0
  end
  local t, nx, ny = discEntryDD(x1, y1, r1, x2, y2, r2, dx, dy)
  if not t then
    discSetup(x1, y1, r1, x2, y2, r2, dx, dy)
    t, nx, ny = discEntry()
  end
  -- stepped back as steppedFraction does, the moved centre tested exactly (circlesCollide's test)
  local _, _, len = unit(dx, dy)
  local u = EPS * max(abs(x1), abs(y1), abs(x2), abs(y2), abs(x2 + dx), abs(y2 + dy)) / len
  local radiusHi, radiusLo = twoDiff(r1, -r2)
  t = min(t, 1.0)
  local window = windowSteps(t, u)
  for k = 1, #COARSE + window + 1060 do
    local f = max(t - stepBack(k, window) * u, 0.0)
    if f == 0 or stepReaches(x1, y1, x2 + f * dx, y2 + f * dy, radiusHi, radiusLo) <= 0 then
      return f, nx + 0.0, ny + 0.0
    end
  end
  return 0.0, nx + 0.0, ny + 0.0
end

-- For polygon/circlecast.lua (polygonCircleCast): the swept point against a convex polygon, the
-- moving disc against a point (a corner), and the step back.
local pointScratch = { 0.0, 0.0 }

-- Whether the point (cx, cy), moving by t d for t in [0, 1], meets the open interior of the convex
-- polygon p1[1 .. n1] (turn w1 = 1 or -1): convexCast's walk over p1's edges with P2 a point.
-- Exact.
function M.pathMeetsInterior(p1, n1, w1, cx, cy, dx, dy)
  pointScratch[1], pointScratch[2] = cx, cy
  exitCount = 0
  local found, allInside = edgeWalk(p1, n1, w1, pointScratch, 2, false, dx, dy, false, true)
  if found == MISS then return false end
  if allInside then return true end
  if not ratioBelowOne(bestRatio, dx, dy) then return false end
  for k = 0, exitCount - 1 do
    if compareRatios(bestRatio, 0, exits, 8 * k, dx, dy) >= 0 then return false end
  end
  return true
end

-- MISS, INSIDE or HIT for the disc (ax, ay, R2) moving by d against the point (px, py) (a disc
-- of radius 0). Exact.
function M.cornerCastStatus(px, py, ax, ay, R2, dx, dy)
  return discCastStatus(px, py, 0.0, ax, ay, R2, dx, dy)
end

-- The entry time (unclamped below 1) and unit normal of a hit found by cornerCastStatus.
function M.cornerEntry(px, py, ax, ay, R2, dx, dy)
  local t, nx, ny = discEntryDD(px, py, 0.0, ax, ay, R2, dx, dy)
  if not t then
    discSetup(px, py, 0.0, ax, ay, R2, dx, dy)
    t, nx, ny = discEntry()
  end
  return t, nx, ny
end

M.MISS, M.HIT, M.INSIDE = MISS, HIT, INSIDE
M.discCastFilteredJit, M.discCastFilteredPuc = discCastFilteredJit, discCastFilteredPuc   -- (the spec)
M.windowSteps, M.stepBack, M.COARSE_COUNT = windowSteps, stepBack, #COARSE
M.checkFinite, M.checkStatic = checkFinite, checkStatic

return M
