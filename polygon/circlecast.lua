-- polygon/circlecast.lua: a moving circle swept against a static convex polygon or list of convex
-- parts (polygonCircleCast). The hit or miss is exact (circle.lua's tests, casts.lua's swept
-- point and corner discs, and one exact test of the move's end against each edge); the entry
-- time comes from double doubles, then is stepped back as casts.lua does until the moved
-- circle, rounded as a game moves it, does not collide. Relies on kernel, check, views,
-- sat, collide, circle and casts.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local check = require(_PACKAGE .. ".check")
local views = require(_PACKAGE .. ".views")
local sat = require(_PACKAGE .. ".sat")
local collide = require(_PACKAGE .. ".collide")
local circle = require(_PACKAGE .. ".circle")
local casts = require(_PACKAGE .. ".casts")

local abs, huge, min, max, sqrt = math.abs, math.huge, math.min, math.max, math.sqrt
local cross, EPS = kernel.cross, kernel.EPS
local twoDiff, twoProduct, twoSum, sqrtDD = kernel.twoDiff, kernel.twoProduct, kernel.twoSum,
  kernel.sqrtDD
local powerScale, areaSign, largestMagnitude = kernel.powerScale, kernel.areaSign,
  kernel.largestMagnitude
local expClear, expAddProduct, expCompress = kernel.expClear, kernel.expAddProduct, kernel.expCompress
local expCopy, expSign, expAddSquare = kernel.expCopy, kernel.expSign, kernel.expAddSquare
local checkFiniteNumber, checkRadius = check.checkFiniteNumber, check.checkRadius
local listView, call, checkCopy = views.listView, views.call, views.checkCopy
local unit = sat.unit
local polygonCircleCollideV = collide.polygonCircleCollideV
local circleCollision = circle.circleCollision
local pathMeetsInterior, cornerCastStatus, cornerEntry = casts.pathMeetsInterior,
  casts.cornerCastStatus, casts.cornerEntry
local HIT = casts.HIT
local windowSteps, stepBack, COARSE_COUNT = casts.windowSteps, casts.stepBack, casts.COARSE_COUNT
local checkStatic = casts.checkStatic


local M = {}

-- The centre moves along the segment S from C to C + d. The open disc of radius r meets the open
-- interior of a convex polygon P (of nonzero area) at t exactly when the centre lies within r of
-- the closed polygon, so the move hits exactly when dist(S, P) < r. With the start clear of P
-- (circle.lua's exact test) that holds exactly when one of these does:
--   a vertex of P lies within r of S (the corner disc met by the moving centre: casts.lua's exact
--   disc test with a radius 0);
--   the end C + d lies within r of an edge with the foot of its perpendicular strictly between
--   the edge's ends (endWithinEdge, below);
--   S meets P's open interior (casts.lua's swept point, exact).
-- (Where S misses P, the distance between S and P is that between S and an edge, taken at an end
-- of one of the two segments: a vertex against S, or C or C + d against an edge; C is clear. A
-- segment touching P's boundary only touches it at a vertex or ends on an edge.)
-- The set of t where the disc meets P is an open interval, and with the start clear its least
-- end is where the centre first comes within r of a vertex (the corner disc's entry) or crosses
-- an edge's line moved out by r with its foot between the edge's ends (a face's entry): the
-- least of those, each in double doubles. A list of parts: the least over the parts that are
-- hit (the distance to a union is the least distance to its parts, so a seam is never met).

-- The move's end C + d against the edge a -> b: whether it lies strictly within r of the edge's
-- line with the foot of its perpendicular strictly between a and b. Every quantity a polynomial
-- in the given doubles (C + d is never rounded): (E - a).e > 0, (E - b).e < 0 and
-- r^2 |e|^2 - (e x (E - a))^2 > 0, e = b - a, E = C + d, on exact expansions of the split
-- differences, scaled into [2^186, 2^250] (products of four stay below 2^1015).
local crossScratch, lengthScratch = {}, {}

local function endWithinEdgeExact(ax, ay, bx, by, cx, cy, dx, dy, r)
  local s = powerScale(max(abs(ax), abs(ay), abs(bx), abs(by), abs(cx), abs(cy), abs(dx), abs(dy), r),
    2^186, 2^250)
  ax, ay, bx, by, cx, cy = ax * s, ay * s, bx * s, by * s, cx * s, cy * s
  dx, dy, r = dx * s, dy * s, r * s
  local exh, exl = twoDiff(bx, ax)
  local eyh, eyl = twoDiff(by, ay)
  local uxh, uxl = twoDiff(cx, ax)
  local uyh, uyl = twoDiff(cy, ay)
  expClear()   -- (E - a).e = (C - a).e + d.e
  expAddProduct(exh, uxh); expAddProduct(exh, uxl); expAddProduct(exl, uxh); expAddProduct(exl, uxl)
  expAddProduct(eyh, uyh); expAddProduct(eyh, uyl); expAddProduct(eyl, uyh); expAddProduct(eyl, uyl)
  expAddProduct(exh, dx); expAddProduct(exl, dx); expAddProduct(eyh, dy); expAddProduct(eyl, dy)
  if expSign() <= 0 then return false end
  local vxh, vxl = twoDiff(cx, bx)
  local vyh, vyl = twoDiff(cy, by)
  expClear()   -- (E - b).e
  expAddProduct(exh, vxh); expAddProduct(exh, vxl); expAddProduct(exl, vxh); expAddProduct(exl, vxl)
  expAddProduct(eyh, vyh); expAddProduct(eyh, vyl); expAddProduct(eyl, vyh); expAddProduct(eyl, vyl)
  expAddProduct(exh, dx); expAddProduct(exl, dx); expAddProduct(eyh, dy); expAddProduct(eyl, dy)
  if expSign() >= 0 then return false end
  expClear()   -- e x (E - a) = ex (uy + dy) - ey (ux + dx)
  expAddProduct(exh, uyh); expAddProduct(exh, uyl); expAddProduct(exl, uyh); expAddProduct(exl, uyl)
  expAddProduct(exh, dy); expAddProduct(exl, dy)
  expAddProduct(-eyh, uxh); expAddProduct(-eyh, uxl); expAddProduct(-eyl, uxh); expAddProduct(-eyl, uxl)
  expAddProduct(-eyh, dx); expAddProduct(-eyl, dx)
  expCompress()
  local crossLen = expCopy(crossScratch)
  expClear()   -- |e|^2
  expAddSquare(exh, exl, 1)
  expAddSquare(eyh, eyl, 1)
  expCompress()
  local lengthLen = expCopy(lengthScratch)
  local rrh, rrl = twoProduct(r, r)
  expClear()
  for i = 1, lengthLen do
    expAddProduct(lengthScratch[i], rrh)
    expAddProduct(lengthScratch[i], rrl)
  end
  for i = 1, crossLen do
    for j = 1, crossLen do expAddProduct(-crossScratch[i], crossScratch[j]) end
  end
  return expSign() > 0
end

-- endWithinEdge in floating point first. With m the largest of |a|, |b|, |C| + |d| per
-- coordinate, every computed difference (E rounded once, then each difference) is within 3.01 eps m
-- of exact and below 2.01 m, so each dot product within 37 eps m^2, the cross product's square
-- within 680 eps m^4 and r^2 |e|^2 within 32 eps r^2 m^2: the bounds below are more than that.
local FILTER_LO, FILTER_HI = 2^-900, 2^1000

local function endWithinEdge(ax, ay, bx, by, cx, cy, dx, dy, r)
  local ex, ey = bx - ax, by - ay
  local px, py = cx + dx, cy + dy
  local m = max(abs(ax), abs(ay), abs(bx), abs(by), abs(cx) + abs(dx), abs(cy) + abs(dy))
  local mm = m * m
  local dotBound = 64 * EPS * mm
  local ux, uy = px - ax, py - ay
  local da = ux * ex + uy * ey
  local db = (px - bx) * ex + (py - by) * ey
  local crossed = ex * uy - ey * ux
  local reachSq = r * r * (ex * ex + ey * ey)
  local gap = reachSq - crossed * crossed
  local gapBound = 64 * EPS * mm * (16 * mm + r * r)
  if not (dotBound > FILTER_LO and gapBound < FILTER_HI) then
    return endWithinEdgeExact(ax, ay, bx, by, cx, cy, dx, dy, r)
  end
  -- one comparison each (on LuaJIT every comparison that goes both ways grows a side trace)
  if max(-da - dotBound, db - dotBound, -gap - gapBound) > 0 then return false end   -- certainly not
  if min(da - dotBound, -db - dotBound, gap - gapBound) > 0 then return true end     -- certainly
  return endWithinEdgeExact(ax, ay, bx, by, cx, cy, dx, dy, r)
end

-- The face entries. For the edge a -> b of a polygon of turn w the centre's distance beyond the
-- edge's line, times |e|, is h(t) = h0 + t h1, h0 = -w e x (C - a), h1 = -w e x d; the centre
-- crosses the line moved out by r when h(t) = r |e|: t = (h0 - r |e|) / -h1 (h1 < 0: moving
-- toward the polygon), an entry when the foot q(t) = (C(t) - a).e lies in [0, |e|^2] there.
-- Every quantity as a double double (the differences split exactly, the main products exact,
-- first-order terms added, each renormalised by TwoSum: near a slide e x d is all low parts):
-- t within eps plus order eps^2 c, c the terms of h0 - r |e| over it. Where the foot lies
-- within that rounding of an end of the edge, the corner disc there is entered within as
-- little of the same time (the moved line is tangent to it), so either answer serves; an entry
-- whose foot falls outside is kept aside (by how far) in case no other candidate of a part
-- that is hit remains.
local faceT, faceNx, faceNy, faceOff = 0.0, 0.0, 0.0, 0.0

-- Sets faceT, faceNx, faceNy and faceOff (0 when the foot lies on the edge, else how far
-- outside, relative to |e|^2) for the edge a -> b, h1 < 0; returns false when t < -2^-30 (the
-- line was crossed before the start: the centre entered the strip beyond an end, at a corner),
-- or when floating point alone shows t > 1, t < 0 or the foot off the edge.
local function faceEntry(ax, ay, bx, by, w, cx, cy, dx, dy, r)
  -- First in floating point: each cross or dot product and r |e| within 8 eps of its terms; when
  -- numerator and denominator are each within 2^-30 of themselves, t is within 2^-28 of itself
  -- and the foot within 2^-27 of its terms, so a crossing after 1 or before the start, or one
  -- whose foot lies clearly off the edge, needs no double doubles.
  do
    local ex, ey, wx, wy = bx - ax, by - ay, cx - ax, cy - ay
    local c1, c2, s1, s2 = ex * wy, ey * wx, ex * dy, ey * dx
    local lengthSq = ex * ex + ey * ey
    local reach = r * sqrt(lengthSq)
    local num, den = -w * (c1 - c2) - reach, w * (s1 - s2)
    local numTerms, denTerms = abs(c1) + abs(c2) + reach, abs(s1) + abs(s2)
    -- one comparison each (as in endWithinEdge)
    if min(abs(num) * 2^-30 - 8 * EPS * numTerms, abs(den) * 2^-30 - 8 * EPS * denTerms,
        numTerms - 2^-900, 2^900 - numTerms, denTerms - 2^-900, 2^900 - denTerms) > 0 then
      local t = num / den
      local a1, a2, b1, b2 = ex * wx, ey * wy, ex * dx, ey * dy
      local foot = (a1 + a2) + t * (b1 + b2)
      local footRoom = 2^-20 * (abs(a1) + abs(a2) + abs(t) * (abs(b1) + abs(b2)) + lengthSq)
      if max(t - (1 + 2^-20), -2^-20 - t, -footRoom - foot, foot - lengthSq - footRoom) > 0 then
        return false
      end
    end
  end
  local m = max(abs(ax), abs(ay), abs(bx), abs(by), abs(cx), abs(cy), abs(dx), abs(dy), r)
  if m > 2^200 or m < 2^-200 then   -- t is unchanged by a common scale; keep products in range
    local s = powerScale(m, 1.0, 2^64)
    ax, ay, bx, by, cx, cy, dx, dy, r = ax * s, ay * s, bx * s, by * s, cx * s, cy * s, dx * s,
      dy * s, r * s
  end
  local exh, exl = twoDiff(bx, ax)
  local eyh, eyl = twoDiff(by, ay)
  local wxh, wxl = twoDiff(cx, ax)
  local wyh, wyl = twoDiff(cy, ay)
  local h, l, h2, l2, e
  h, l = twoProduct(exh, wyh)   -- e x (C - a)
  h2, l2 = twoProduct(eyh, wxh)
  local ch, cl = twoDiff(h, h2)
  cl = cl + (l - l2) + ((exh * wyl + exl * wyh) - (eyh * wxl + eyl * wxh))
  ch, cl = twoSum(ch, cl)
  h, l = twoProduct(exh, dy)   -- e x d
  h2, l2 = twoProduct(eyh, dx)
  local sh, sl = twoDiff(h, h2)
  sl = sl + (l - l2) + (exl * dy - eyl * dx)
  sh, sl = twoSum(sh, sl)
  h, l = twoProduct(exh, exh)   -- |e|^2
  h2, l2 = twoProduct(eyh, eyh)
  local qh, ql = twoSum(h, h2)
  ql = ql + (l + l2) + 2 * (exh * exl + eyh * eyl)
  qh, ql = twoSum(qh, ql)
  local lh, ll = sqrtDD(qh, ql)
  h, l = twoProduct(r, lh)   -- r |e|
  l = l + r * ll
  h, l = twoSum(h, l)
  -- numerator h0 - r |e| = -w (e x (C - a)) - r |e|; denominator -h1 = w (e x d) > 0
  local nh, nl = twoDiff(-w * ch, h)
  nl = nl + (-w * cl - l)
  nh, nl = twoSum(nh, nl)
  local dh, dl = w * sh, w * sl
  local t = nh / dh
  h, l = twoProduct(t, dh)
  local tl = ((((nh - h) - l) + nl) - t * dl) / dh
  if t + tl < -2^-30 then return false end
  -- the foot at t: (C - a).e + t d.e, against 0 and |e|^2
  h, l = twoProduct(exh, wxh)
  h2, l2 = twoProduct(eyh, wyh)
  local ah, al = twoSum(h, h2)
  al = al + (l + l2) + ((exh * wxl + exl * wxh) + (eyh * wyl + eyl * wyh))
  ah, al = twoSum(ah, al)
  h, l = twoProduct(exh, dx)
  h2, l2 = twoProduct(eyh, dy)
  local bh, bl = twoSum(h, h2)
  bl = bl + (l + l2) + (exl * dx + eyl * dy)
  bh, bl = twoSum(bh, bl)
  h, l = twoProduct(t, bh)
  local fh, fl = twoSum(ah, h)
  fl = fl + al + l + t * bl + tl * bh
  local below = fh + fl                  -- the foot, >= 0 on the edge
  h, e = twoDiff(qh, fh)
  local above = h + (e + ql - fl)        -- |e|^2 less the foot, >= 0 on the edge
  faceOff = max(-below, -above, 0.0) / qh
  faceT = t + tl
  local nx, ny = unit(w * eyh, -w * exh)
  faceNx, faceNy = nx, ny
  return true
end

-- False when the vertex (px, py) certainly lies farther than r from the segment C -> C + d, by
-- floating point: the squared distance (to the nearest point of the segment) is within a few eps
-- of S = |v - C|^2 + |d|^2 + r^2, far less than the 2^-40 S of room. Most vertices of a part
-- are far; they skip the exact test (and on LuaJIT its float filter's branches, whose side
-- traces failed to compile with partCast's values live: "register coalescing too complex").
local function cornerNear(px, py, cx, cy, r, dx, dy)
  local wx, wy = px - cx, py - cy
  local ww, dd, rr = wx * wx + wy * wy, dx * dx + dy * dy, r * r
  local along = min(max(wx * dx + wy * dy, 0.0), dd)
  local ux, uy = wx - dx * (along / dd), wy - dy * (along / dd)
  if dd == 0 then ux, uy = wx, wy end
  local S = ww + dd + rr
  return not (ux * ux + uy * uy - rr > 2^-40 * S and S < 2^1000 and S > 2^-900)
end

-- The best candidate of the part being cast (partT = huge: none), and of the aside entries.
local partT, partNx, partNy = huge, 0.0, 0.0
local asideT, asideNx, asideNy, asideOff = huge, 0.0, 0.0, huge

-- Whether the circle (cx, cy, r), clear of the convex polygon points[1 .. n] (turn w, 1 or -1)
-- at the start, meets it moving by t d, t in [0, 1] (exact); leaves its entry in partT, partNx,
-- partNy when it does.
local function partCast(points, n, w, cx, cy, r, dx, dy)
  partT, asideT, asideOff = huge, huge, huge
  local hit = false
  local ax, ay = points[n - 1] + 0.0, points[n] + 0.0
  for i = 1, n - 1, 2 do
    local bx, by = points[i] + 0.0, points[i + 1] + 0.0
    if cornerNear(bx, by, cx, cy, r, dx, dy) and cornerCastStatus(bx, by, cx, cy, r, dx, dy) == HIT then
      hit = true
      local t, nx, ny = cornerEntry(bx, by, cx, cy, r, dx, dy)
      if t < partT then partT, partNx, partNy = t, nx, ny end
    end
    if bx ~= ax or by ~= ay then
      if cross(ax, ay, bx, by, 0.0, 0.0, dx, dy) * w > 0
          and faceEntry(ax, ay, bx, by, w, cx, cy, dx, dy, r) then
        if faceOff == 0 then
          if faceT < partT then partT, partNx, partNy = faceT, faceNx, faceNy end
        elseif faceOff < asideOff then
          asideT, asideNx, asideNy, asideOff = faceT, faceNx, faceNy, faceOff
        end
      end
      if not hit and endWithinEdge(ax, ay, bx, by, cx, cy, dx, dy, r) then hit = true end
    end
    ax, ay = bx, by
  end
  if not hit and not pathMeetsInterior(points, n, w, cx, cy, dx, dy) then return false end
  if partT == huge then partT, partNx, partNy = min(asideT, 1.0), asideNx, asideNy end
  return true
end

-- The sign of a polygon's area, 1, -1 or 0.
local function turnOf(points, n)
  local w = areaSign(points, n)
  return w > 0 and 1 or (w < 0 and -1 or 0)
end

-- Whether the circle centred at (x, y) collides with the convex polygon (n coordinates), or with
-- one of the near parts of the list `shape` (view: its view; near: how many of nearParts).
local nearParts = {}
local function movedCollides(points, n, view, near, x, y, r)
  if not view then return circleCollision(points, n, x, y, r) ~= false end
  for j = 1, near do
    local k = nearParts[j]
    if view.turns[k] ~= 0 and circleCollision(points[k], view.lengths[k], x, y, r) then return true end
  end
  return false
end

-- The fraction to return for the entry t: the first of casts.lua's steps back from t (in units
-- of u = eps M / |d|) that leaves the circle, its centre moved as a game moves it, not colliding.
local function steppedFraction(points, n, view, near, t, cx, cy, r, dx, dy, m)
  local _, _, len = unit(dx, dy)
  local u = EPS * m / len
  t = min(max(t, 0.0), 1.0)
  local window = windowSteps(t, u)
  for k = 1, COARSE_COUNT + window + 1060 do
    local f = max(t - stepBack(k, window) * u, 0.0)
    if f == 0 or not movedCollides(points, n, view, near, cx + f * dx, cy + f * dy, r) then return f end
  end
  return 0.0
end

-- The answer when the circle collides at t = 0: 0 and the unit direction of
-- polygonCircleCollideV's push.
local function startPush(points, cx, cy, r)
  local _, px, py = polygonCircleCollideV(points, cx, cy, r)
  local nx, ny = unit(px, py)
  return 0.0, nx + 0.0, ny + 0.0
end

-- polygonCircleCast against a list of parts: false, or fraction, nx, ny.
local function castParts(fname, shape, cx, cy, r, dx, dy)
  local view = listView(fname, "points", shape)
  call.stamp = call.stamp + 1
  local stamp = call.stamp
  local boxes, turns = view.boxes, view.turns
  -- the box the disc sweeps, widened by far more than its rounding (a part beyond it is never met)
  local x0, y0 = min(cx, cx + dx) - r, min(cy, cy + dy) - r
  local x1, y1 = max(cx, cx + dx) + r, max(cy, cy + dy) + r
  local pad = 2^-40 * max(abs(x0), abs(y0), abs(x1), abs(y1))
  x0, y0, x1, y1 = x0 - pad, y0 - pad, x1 + pad, y1 + pad
  local near = 0
  local m = max(abs(cx), abs(cy), abs(cx + dx), abs(cy + dy))
  for k = 1, view.count do
    local b = 4 * k
    if boxes[b - 3] <= x1 and x0 <= boxes[b - 1] and boxes[b - 2] <= y1 and y0 <= boxes[b] then
      if view.checked[k] ~= stamp then checkCopy(view, k, shape[k], 4) end
      if turns[k] ~= 0 then
        near = near + 1
        nearParts[near] = k
        m = max(m, abs(boxes[b - 3]), abs(boxes[b - 2]), abs(boxes[b - 1]), abs(boxes[b]))
        if circleCollision(shape[k], view.lengths[k], cx, cy, r) then return startPush(shape, cx, cy, r) end
      end
    end
  end
  if dx == 0 and dy == 0 then return false end
  local bestT, nx, ny = huge, 0.0, 0.0
  for j = 1, near do
    local k = nearParts[j]
    local w = turns[k] > 0 and 1 or -1
    if partCast(shape[k], view.lengths[k], w, cx, cy, r, dx, dy) and partT < bestT then
      bestT, nx, ny = partT, partNx, partNy
    end
  end
  if bestT == huge then return false end
  local f = steppedFraction(shape, 0, view, near, bestT, cx, cy, r, dx, dy, m)
  return f, nx + 0.0, ny + 0.0
end

-- polygonCircleCast(points, cx, cy, radius, dx, dy): where the circle, its centre moving by
-- t (dx, dy) for t in [0, 1], first touches points (a convex polygon or a list of convex parts):
-- fraction, nx, ny or false. See polygon.lua for the contract.
function M.polygonCircleCast(points, cx, cy, radius, dx, dy)
  local fname = "polygonCircleCast"
  local kind, n
  points, kind, n = checkStatic(fname, "points", points)
  checkFiniteNumber(cx, fname, "cx")
  checkFiniteNumber(cy, fname, "cy")
  checkRadius(radius, fname, "radius")
  checkFiniteNumber(dx, fname, "dx")
  checkFiniteNumber(dy, fname, "dy")
  cx, cy, radius, dx, dy = cx + 0.0, cy + 0.0, radius + 0.0, dx + 0.0, dy + 0.0
  if radius == 0 then return false end   -- the open disc is empty
  if kind == "table" then
    local f, nx, ny = castParts(fname, points, cx, cy, radius, dx, dy)
    if not f then return false end
    return f, nx, ny
  end
  local w = turnOf(points, n)
  if w == 0 then return false end   -- zero area never collides
  if circleCollision(points, n, cx, cy, radius) then
    local f, nx, ny = startPush(points, cx, cy, radius)
    return f, nx, ny
  end
  if (dx == 0 and dy == 0) or not partCast(points, n, w, cx, cy, radius, dx, dy) then return false end
  local m = max(largestMagnitude(points, n, 0.0), abs(cx), abs(cy), abs(cx + dx), abs(cy + dy))
  local f = steppedFraction(points, n, nil, 0, partT, cx, cy, radius, dx, dy, m)
  return f, partNx + 0.0, partNy + 0.0
end

return M
