-- polygon/closest.lua: the nearest point of a polygon's boundary to a point, and the signed
-- distance to it (negative strictly inside by polygonContains' crossing rule, 0 on the
-- boundary). Relies on kernel, check, convex's refusals, object, contains and circle's dot.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local check = require(_PACKAGE .. ".check")
local convex = require(_PACKAGE .. ".convex")
local object = require(_PACKAGE .. ".object")
local contains = require(_PACKAGE .. ".contains")
local circle = require(_PACKAGE .. ".circle")

local abs, min, max = math.abs, math.min, math.max
local type = type
local EPS, CROSS_BOUND, cross, JIT = kernel.EPS, kernel.CROSS_BOUND, kernel.cross, kernel.JIT
local twoDiff, twoProduct, powerScale = kernel.twoDiff, kernel.twoProduct, kernel.powerScale
local twoSum, sqrtDD, divideDD = kernel.twoSum, kernel.sqrtDD, kernel.divideDD
local expClear, expAddProduct, expAddSquare = kernel.expClear, kernel.expAddProduct, kernel.expAddSquare
local expCompress, expLength, expansion, expSign = kernel.expCompress, kernel.expLength,
  kernel.expansion, kernel.expSign
local checkPoints, checkFiniteNumber = check.checkPoints, check.checkFiniteNumber
local refuseEntries = convex.refuseEntries
local objectPoints = object.objectPoints
local polygonContains = contains.polygonContains
local dot = circle.dot

local M = {}


-- The nearest point of the boundary lies on the nearest edge: its foot of the perpendicular
-- when that falls strictly inside the edge, else the nearer end. Each edge's squared distance
-- is computed in floating point with an error bound; where the bounds cannot tell the nearest
-- edge from another, exact expansions compare their squared distances (degree up to 6:
-- c1^2 L2 against c2^2 L1, c the cross product of the edge with the point, L its squared
-- length). The nearest edge's kind (foot or end), its on-the-boundary test and the point's
-- side are exact signs; the point and the distance are computed in double doubles, so each is
-- within an ulp or so of the exact one, well within 8 eps M.


-- The squared distance from (x, y) to the edge a -> b (flat indices ia and ib) in floating
-- point, a bound on its error from the exact squared distance to the closed segment, and the
-- index of the end that is surely the nearest point (0 when none is sure). The differences round
-- by eps each, products and sums by eps, the cross product by CROSS_BOUND of its terms
-- (Shewchuk); where the float dot product's sign may be wrong, the kinds (end or foot) differ by
-- at most dotErr^2 / L, which is added. UNSURE (finite, so that the LuaJIT body's arithmetic
-- stays finite) where a square may have overflowed or underflowed.
local UNSURE = 2^1000

-- PUC Lua's, with branches.
local function edgeDistancePuc(ax, ay, bx, by, x, y, ia, ib)
  local ex, ey = bx - ax, by - ay
  local wx, wy = x - ax, y - ay
  local along = ex * wx + ey * wy
  local length = ex * ex + ey * ey
  local slip = 3 * EPS * (abs(ex * wx) + abs(ey * wy))   -- the dot products' error bound
  local d2, err, sure
  if along <= 0 or length == 0 then
    d2 = wx * wx + wy * wy
    err = 6 * EPS * d2
    sure = along < -slip and ia or 0
  elseif along >= length then
    local vx, vy = x - bx, y - by
    d2 = vx * vx + vy * vy
    err = 6 * EPS * d2
    sure = along - length > slip + 4 * EPS * length and ib or 0
  else
    local l, r = ex * wy, ey * wx
    local c = l - r
    local cErr = CROSS_BOUND * (abs(l) + abs(r))
    d2 = c * c / length
    err = (2 * abs(c) * cErr + cErr * cErr) / length * (1 + 8 * EPS) + 4 * EPS * d2
    sure = 0
  end
  if length > 0 then err = err + slip * slip / length * (1 + 8 * EPS) end
  -- luacheck: ignore 581 (NaN too)
  if not (d2 < 2^900 and (d2 > 2^-900 or d2 == 0) and (length > 2^-900 or length == 0)) then
    err = UNSURE
  end
  return d2, err, sure
end

-- 1 for x > 0, else 0, without a branch (LuaJIT's min and max are single instructions).
local function positive(x)
  return min(1, max(0, x * 2^1000 * 2^1000))
end

-- LuaJIT's: the same numbers with no branch (each comparison that goes both ways is a side exit,
-- whose side traces here failed to compile: bench/NOTES.md). The end's squared distance is the
-- lesser of the two ends' when the float foot falls outside the edge (then it is no less than
-- the line's); coordinates are below 2^400 (the caller's test), so everything stays finite.
local function edgeDistanceJit(ax, ay, bx, by, x, y, ia, ib)
  local ex, ey = bx - ax, by - ay
  local wx, wy = x - ax, y - ay
  local vx, vy = x - bx, y - by
  local along = ex * wx + ey * wy
  local length = ex * ex + ey * ey
  local slip = 3 * EPS * (abs(ex * wx) + abs(ey * wy))
  local l, r = ex * wy, ey * wx
  local c = l - r
  local cErr = CROSS_BOUND * (abs(l) + abs(r))
  local safeLength = max(length, 2^-1000)
  local inside = positive(along) * positive(length - along)
  local endD2 = min(wx * wx + wy * wy, vx * vx + vy * vy)
  local footD2 = c * c / safeLength
  local d2 = max(footD2, (1 - inside) * endD2)
  local footErr = (2 * abs(c) * cErr + cErr * cErr) / safeLength * (1 + 8 * EPS) + 4 * EPS * footD2
  local err = inside * footErr + (1 - inside) * 6 * EPS * d2
    + positive(length) * slip * slip / safeLength * (1 + 8 * EPS)
  local valid = positive(2^900 - d2) * (1 - positive(length) * positive(2^-900 - length))
    * (1 - positive(d2) * positive(2^-900 - d2))
  err = valid * err + (1 - valid) * UNSURE
  local sure = positive(-along - slip) * ia + positive(along - length - slip - 4 * EPS * length) * ib
  return d2, err, sure
end

-- Exact squared distances. Scratch for compressed expansions copied out of kernel's one.
local exParts = {}
local num1, den1, num2, den2, left, right = {}, {}, {}, {}, {}, {}
local ONE = { 1.0 }

-- Copies kernel's scratch expansion into `into`; returns its length.
local function copyExpansion(into)
  expCompress()
  local len = expLength()
  for i = 1, len do into[i] = expansion[i] end
  return len
end

-- Adds the products of every component of a[1 .. na] with every one of b[1 .. nb], times sign,
-- to kernel's scratch expansion.
local function addProducts(a, na, b, nb, sign)
  for i = 1, na do
    local ai = sign * a[i]
    for j = 1, nb do expAddProduct(ai, b[j]) end
  end
end

-- The exact squared distance from p to the segment a -> b, coordinates times s (a power of
-- two), as num / den: expansions into numOut and denOut (den > 0); returns their lengths.
-- With w = p - a and e = b - a split exactly: the end a when w.e <= 0, the end b when
-- (p - b).(a - b) <= 0, else the foot: (e x w)^2 / |e|^2.
local function exactDistance(ax, ay, bx, by, px, py, s, numOut, denOut)
  local wxh, wxl = twoDiff(px * s, ax * s)
  local wyh, wyl = twoDiff(py * s, ay * s)
  local exh, exl = twoDiff(bx * s, ax * s)
  local eyh, eyl = twoDiff(by * s, ay * s)
  expClear()   -- w.e
  expAddProduct(wxh, exh); expAddProduct(wxh, exl); expAddProduct(wxl, exh); expAddProduct(wxl, exl)
  expAddProduct(wyh, eyh); expAddProduct(wyh, eyl); expAddProduct(wyl, eyh); expAddProduct(wyl, eyl)
  local alongA = expSign()
  local vxh, vxl = twoDiff(px * s, bx * s)
  local vyh, vyl = twoDiff(py * s, by * s)
  expClear()   -- (p - b).(a - b) = -(p - b).e
  expAddProduct(-vxh, exh); expAddProduct(-vxh, exl); expAddProduct(-vxl, exh); expAddProduct(-vxl, exl)
  expAddProduct(-vyh, eyh); expAddProduct(-vyh, eyl); expAddProduct(-vyl, eyh); expAddProduct(-vyl, eyl)
  local alongB = expSign()
  denOut[1] = 1.0
  if alongA <= 0 or (exh == 0 and eyh == 0) then
    expClear()
    expAddSquare(wxh, wxl, 1)
    expAddSquare(wyh, wyl, 1)
    return copyExpansion(numOut), 1
  end
  if alongB <= 0 then
    expClear()
    expAddSquare(vxh, vxl, 1)
    expAddSquare(vyh, vyl, 1)
    return copyExpansion(numOut), 1
  end
  expClear()   -- e x w
  expAddProduct(exh, wyh); expAddProduct(exh, wyl); expAddProduct(exl, wyh); expAddProduct(exl, wyl)
  expAddProduct(-eyh, wxh); expAddProduct(-eyh, wxl); expAddProduct(-eyl, wxh)
  expAddProduct(-eyl, wxl)
  local crossLen = copyExpansion(exParts)
  expClear()
  addProducts(exParts, crossLen, exParts, crossLen, 1)
  local numLen = copyExpansion(numOut)
  expClear()
  expAddSquare(exh, exl, 1)
  expAddSquare(eyh, eyl, 1)
  return numLen, copyExpansion(denOut)
end

-- The sign of dist^2(p, segment 1) - dist^2(p, segment 2), exact: num1 den2 - num2 den1.
-- The differences are scaled into [2^60, 2^124] so that no product of six overflows.
local function compareEdges(ax, ay, bx, by, cx, cy, dx, dy, px, py)
  local m = max(abs(ax - px), abs(ay - py), abs(bx - px), abs(by - py), abs(cx - px), abs(cy - py),
    abs(dx - px), abs(dy - py))
  local s = m > 0 and powerScale(m, 2^60, 2^124) or 1.0
  local n1, d1 = exactDistance(ax, ay, bx, by, px, py, s, num1, den1)
  local n2, d2 = exactDistance(cx, cy, dx, dy, px, py, s, num2, den2)
  expClear()
  addProducts(num1, n1, den2, d2, 1)
  local leftLen = copyExpansion(left)
  expClear()
  addProducts(num2, n2, den1, d1, 1)
  local rightLen = copyExpansion(right)
  expClear()
  addProducts(left, leftLen, ONE, 1, 1)
  addProducts(right, rightLen, ONE, 1, -1)
  return expSign()
end

-- The distance from p to the point v, within eps (plus order eps^2): the differences exact,
-- their squares' sum as a double double, its root.
local function pointDistance(vx, vy, px, py)
  local xh, xl = twoDiff(px, vx)
  local yh, yl = twoDiff(py, vy)
  if abs(xh) + abs(yh) > 2^500 or abs(xh) + abs(yh) < 2^-500 then   -- (out of double doubles' range)
    local k = abs(xh) + abs(yh)
    if k == 0 then return 0.0 end
    local s = powerScale(k, 1, 2^64)
    return pointDistance(vx * s, vy * s, px * s, py * s) / s
  end
  local ah, al = twoProduct(xh, xh)
  local bh, bl = twoProduct(yh, yh)
  local h, l = twoSum(ah, bh)
  l = l + (al + bl) + 2 * (xh * xl + yh * yl)
  h, l = twoSum(h, l)
  local rh, rl = sqrtDD(h, l)
  return rh + rl
end

-- The foot of the perpendicular from p to the edge a -> b (strictly inside it: exact signs
-- said so) and its distance, each within an ulp or so: u = (w.e) / |e|^2 and c = e x w as
-- double doubles from the exact differences, the foot a + u e from the nearer end, the distance
-- |c| / |e|. Coordinates beyond 2^400 or below 2^-400 are scaled by a power of two first.
local function footOf(ax, ay, bx, by, px, py)
  local m = max(abs(ax), abs(ay), abs(bx), abs(by), abs(px), abs(py))
  if m > 2^400 or (m < 2^-400 and m > 0) then
    local s = powerScale(m, 2^-64, 1)
    local fx, fy, d = footOf(ax * s, ay * s, bx * s, by * s, px * s, py * s)
    return fx / s, fy / s, d / s
  end
  local exh, exl = twoDiff(bx, ax)
  local eyh, eyl = twoDiff(by, ay)
  local wxh, wxl = twoDiff(px, ax)
  local wyh, wyl = twoDiff(py, ay)
  -- w.e, |e|^2 and e x w: the main products exact, the first-order terms added
  local ph, pl = twoProduct(wxh, exh)
  local qh, ql = twoProduct(wyh, eyh)
  local alongH, alongL = twoSum(ph, qh)
  alongL = alongL + (pl + ql) + (wxh * exl + wxl * exh + wyh * eyl + wyl * eyh)
  ph, pl = twoProduct(exh, exh)
  qh, ql = twoProduct(eyh, eyh)
  local lengthH, lengthL = twoSum(ph, qh)
  lengthL = lengthL + (pl + ql) + 2 * (exh * exl + eyh * eyl)
  ph, pl = twoProduct(exh, wyh)
  qh, ql = twoProduct(eyh, wxh)
  local crossH, crossL = twoDiff(ph, qh)
  crossL = crossL + (pl - ql) + ((exh * wyl + exl * wyh) - (eyh * wxl + eyl * wxh))
  local u = divideDD(alongH, alongL, lengthH, lengthL)
  -- from the nearer end: a + u e, or b + (u - 1) e (u - 1 exact by Sterbenz's lemma), chosen
  -- without a branch (selections with one term 0 are exact)
  local far = min(1, max(0, (u - 0.5) * 2^1000 * 2^1000))
  local k = u - far
  local hx, lx = twoProduct(k, exh)
  local hy, ly = twoProduct(k, eyh)
  local fx = (far * bx + (1 - far) * ax) + (hx + (lx + k * exl))
  local fy = (far * by + (1 - far) * ay) + (hy + (ly + k * eyl))
  local rootH, rootL = sqrtDD(lengthH, lengthL)
  return fx, fy, abs(divideDD(crossH, crossL, rootH, rootL))
end

-- The nearest edge by the float distances: its end's flat index, its squared distance and
-- error bound, the least lower bound (d2 - err) of the other edges, and a number that is 0
-- unless a coordinate is NaN or infinite. Edges whose nearest points are surely the same end
-- tie: the later one's bound does not count (a vertex nearest is common; each such tie would
-- take the exact comparison).
-- PUC Lua's: branches.
local function nearestEdgePuc(points, n, x, y)
  local best, bestD2, bestErr, bestSure, otherLower = n - 1, UNSURE * 2^20, 0.0, 0, UNSURE * 2^20
  local ax, ay = points[n - 1] + 0.0, points[n] + 0.0
  local ia = n - 1
  local finite = (ax - ax) + (ay - ay)
  for i = 1, n - 1, 2 do
    local bx, by = points[i] + 0.0, points[i + 1] + 0.0
    finite = finite + ((bx - bx) + (by - by))
    local d2, err, sure = edgeDistancePuc(ax, ay, bx, by, x, y, ia, i)
    if d2 < bestD2 then
      otherLower = min(otherLower, bestD2 - bestErr)
      best, bestD2, bestErr, bestSure = i, d2, err, sure
    elseif sure == 0 or sure ~= bestSure then
      otherLower = min(otherLower, d2 - err)
    end
    ax, ay, ia = bx, by, i
  end
  return best, bestD2, bestErr, otherLower, finite
end

-- LuaJIT's: the same without a branch; its `finite` is also nonzero for a coordinate beyond
-- 2^400 (edgeDistanceJit's range: the PUC body takes those).
local function nearestEdgeJit(points, n, x, y)
  local best, bestD2, bestErr, bestSure, otherLower = n - 1, UNSURE * 2^20, 0.0, 0, UNSURE * 2^20
  local ax, ay = points[n - 1] + 0.0, points[n] + 0.0
  local ia = n - 1
  local finite = (ax - ax) + (ay - ay)
  local big = max(abs(ax), abs(ay), abs(x), abs(y))
  for i = 1, n - 1, 2 do
    local bx, by = points[i] + 0.0, points[i + 1] + 0.0
    finite = finite + ((bx - bx) + (by - by))
    big = max(big, abs(bx), abs(by))
    local d2, err, sure = edgeDistanceJit(ax, ay, bx, by, x, y, ia, i)
    local better = positive(bestD2 - d2)
    local tie = (1 - min(1, abs(sure - bestSure))) * min(1, sure)
    otherLower = min(otherLower,
      better * (bestD2 - bestErr) + (1 - better) * (d2 - err) + tie * UNSURE * 2^20)
    -- selections with one term 0 (exact: a difference of the two would lose the smaller)
    best, bestD2 = better * i + (1 - better) * best, better * d2 + (1 - better) * bestD2
    bestErr, bestSure = better * err + (1 - better) * bestErr, better * sure + (1 - better) * bestSure
    ax, ay, ia = bx, by, i
  end
  return best, bestD2, bestErr, otherLower, finite + positive(big - 2^400)
end

-- 1 when the nearest point of the edge a -> b to (x, y) is a, 2 when it is b, 0 for the foot
-- inside it: exact signs of dot products (circle.lua's dot).
local function nearestEnd(ax, ay, bx, by, x, y)
  if (ax == bx and ay == by) or dot(ax, ay, x, y, bx, by) <= 0 then return 1 end
  if dot(bx, by, x, y, ax, ay) <= 0 then return 2 end
  return 0
end

-- Raises the refusal of a shape whose first entry is not a number (kind: its type, false for a
-- non-table), or returns a Polygon object's points.
local function resolvePoints(fname, points, kind)
  if kind == false then checkPoints(points, fname, "points", 4) end
  local inner = objectPoints(points)
  if inner then
    if type(inner[1]) == "number" or #inner == 0 then return inner end
    points = inner
  end
  if #points == 0 then error(("%s: points is empty; a polygon needs at least 1 point"):format(fname), 3) end
  local first = points[1]
  if type(first) == "table" and first.x == nil and #first ~= 2 then
    error(("%s: points is a list of parts; it takes one polygon (pass the outline the parts "
      .. "were made from)"):format(fname), 3)
  end
  refuseEntries(fname, "points", points, type(first), 3)
end

-- polygonClosestPoint(points, x, y): the nearest point of the polygon's boundary to (x, y) and
-- the signed distance to it: px, py, distance.
function M.polygonClosestPoint(points, x, y)
  local fname = "polygonClosestPoint"
  if type(points) ~= "table" or type(points[1]) ~= "number" then
    points = resolvePoints(fname, points, type(points) == "table" and type(points[1]))
  end
  local n = #points
  if n % 2 ~= 0 then checkPoints(points, fname, "points", 3, true) end
  if n == 0 then error(("%s: points is empty; a polygon needs at least 1 point"):format(fname), 2) end
  checkFiniteNumber(x, fname, "x")
  checkFiniteNumber(y, fname, "y")
  x, y = x + 0.0, y + 0.0
  local best, bestD2, bestErr, otherLower, finite
  if JIT then
    best, bestD2, bestErr, otherLower, finite = nearestEdgeJit(points, n, x, y)
    if finite ~= 0 then best, bestD2, bestErr, otherLower, finite = nearestEdgePuc(points, n, x, y) end
  else
    best, bestD2, bestErr, otherLower, finite = nearestEdgePuc(points, n, x, y)
  end
  if finite ~= 0 then error(("%s: points holds a non-finite coordinate"):format(fname), 2) end
  if otherLower <= bestD2 + bestErr then
    -- the bounds cannot tell: each edge that may be nearer, against the best so far, exactly
    -- (two edges whose nearest points are surely their shared end tie, and are skipped)
    local limit = bestD2 + bestErr
    local ax, ay = points[n - 1] + 0.0, points[n] + 0.0
    local ia = n - 1
    for i = 1, n - 1, 2 do
      local bx, by = points[i] + 0.0, points[i + 1] + 0.0
      local d2, err = edgeDistancePuc(ax, ay, bx, by, x, y, ia, i)
      if i ~= best and d2 - err <= limit then
        local b = best
        local a = b == 1 and n - 1 or b - 2
        local cx, cy, dx, dy = points[a] + 0.0, points[a + 1] + 0.0, points[b] + 0.0, points[b + 1] + 0.0
        local endI = nearestEnd(ax, ay, bx, by, x, y)
        local endB = nearestEnd(cx, cy, dx, dy, x, y)
        local vx, vy = endI == 1 and ax or bx, endI == 1 and ay or by
        local wx, wy = endB == 1 and cx or dx, endB == 1 and cy or dy
        if not (endI ~= 0 and endB ~= 0 and vx == wx and vy == wy)
            and compareEdges(ax, ay, bx, by, cx, cy, dx, dy, x, y) < 0 then
          best = i
        end
      end
      ax, ay, ia = bx, by, i
    end
  end
  -- the nearest edge a -> b: its end or the foot, by exact signs
  local a = best == 1 and n - 1 or best - 2
  local ax, ay = points[a] + 0.0, points[a + 1] + 0.0
  local bx, by = points[best] + 0.0, points[best + 1] + 0.0
  local px, py, distance
  if (ax == bx and ay == by) or dot(ax, ay, x, y, bx, by) <= 0 then
    px, py = ax, ay
    distance = pointDistance(ax, ay, x, y)
  elseif dot(bx, by, x, y, ax, ay) <= 0 then
    px, py = bx, by
    distance = pointDistance(bx, by, x, y)
  elseif cross(ax, ay, bx, by, ax, ay, x, y) == 0 then
    return x, y, 0.0   -- on the edge
  else
    px, py, distance = footOf(ax, ay, bx, by, x, y)
  end
  if distance == 0 then return x, y, 0.0 end
  if polygonContains(points, x, y) then distance = -distance end
  return px, py, distance
end

M.nearestEdgeJit, M.nearestEdgePuc = nearestEdgeJit, nearestEdgePuc   -- both bodies, for the spec
return M
