-- polygon/circle.lua: circles: projection, circle against circle, and the engine of a convex
-- polygon against a circle (exact tests, a push that separates).

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local check = require(_PACKAGE .. ".check")
local sat = require(_PACKAGE .. ".sat")
local convex = require(_PACKAGE .. ".convex")

local abs, sqrt, huge, min, max = math.abs, math.sqrt, math.huge, math.min, math.max
local powerScale, EPS, twoDiff = kernel.powerScale, kernel.EPS, kernel.twoDiff
local twoProduct, expClear, expAddSquare = kernel.twoProduct, kernel.expClear, kernel.expAddSquare
local expSign, expAddProduct, expCompress = kernel.expSign, kernel.expAddProduct, kernel.expCompress
local expLength, expansion, cross = kernel.expLength, kernel.expansion, kernel.cross
local SPLITTER, JIT, shoelace = kernel.SPLITTER, kernel.JIT, kernel.shoelace
local areaSignOf, areaSign = kernel.areaSignOf, kernel.areaSign
local checkNumber, checkFiniteNumber = check.checkNumber, check.checkFiniteNumber
local checkRadius = check.checkRadius
local unit = sat.unit
local vouch, CROSS_BOUND = convex.vouch, kernel.CROSS_BOUND

local M = {}


-- A circle collides with a shape when the OPEN disc meets the shape's interior: touching is not
-- colliding. Every such answer compares squared distances exactly: against a point (a vertex, or
-- another circle's centre) r^2 with |c - v|^2, degree 2; against an edge's line r^2 |b - a|^2
-- with ((b - a) x (c - a))^2, degree 4. Each is first decided in floating point with an error
-- bound and redone as an expansion only when the bound cannot vouch for the sign.

-- The exact tests scale their differences by a power of two into [2^186, 2^250]: a product of
-- four such numbers stays below 2^1010 (no overflow), and a term up to 2^400 times smaller than
-- the largest keeps every bit above the underflow threshold through four multiplications.
local SCALE_LO, SCALE_HI = 2^186, 2^250

-- The power of two for the exact tests: 2^200 for every m in [2^-14, 2^50], the sizes games
-- use, without powerScale's loops (on LuaJIT a loop inside a function that a trace starts in
-- aborts it: "inner loop in root trace").
local function exactTestScale(m)
  if m >= 2^-14 and m <= 2^50 then return 2^200 end
  return powerScale(m, SCALE_LO, SCALE_HI)
end

-- The float filters below trust a result only inside [2^-900, 2^1000]: there no square or
-- product of theirs has overflowed or lost bits to underflow.
local FILTER_LO, FILTER_HI = 2^-900, 2^1000

-- reachesExact's second stage trusts its double-double gap G when |G| > REACH_BOUND M (below).
local REACH_BOUND = 64 * EPS * EPS   -- 2^-100, exact

-- A number with the sign of (rh + rl)^2 - |(x2, y2) - (x1, y1)|^2, exact: > 0 when the point
-- (x2, y2) lies strictly within rh + rl of (x1, y1). rh + rl is a radius (rl = 0) or an exact
-- sum of two (|rl| <= eps |rh|, from twoDiff). The differences are split exactly, d = dh + dl,
-- and scaled (see exactTestScale). It is called just after a push, where the circles are within
-- rounding of touching and the float filter cannot vouch, so on every resolved contact: a game's
-- "resolve until nothing collides" loop meets it for every pair it has just pushed apart. So a
-- second stage without loops comes first. With R = rh, X = dxh, Y = dyh (and r, x, y their
-- lows) the gap is R^2 - X^2 - Y^2 + 2 (R r - X x - Y y) + r^2 - x^2 - y^2; the three squares
-- are split exactly (TwoProduct), their highs subtracted exactly (two TwoDiffs: b + be + ae),
-- and the eleven small terms added in floating point. With M = R^2 + X^2 + Y^2 (their highs)
-- and eps = 2^-53, each small term is at most about 2 eps M, together below 5.01 eps M, so their
-- float sum (eleven terms, six of them rounded products) is off by less than 12.01 eps times
-- that: 61 eps^2 M. G = b + the sum rounded once has the sign of b + the float sum, and
-- |G| > 64 eps^2 M (computed M rounded twice) clears that error: the sign is the exact gap's.
-- (Every value stays below 2^502 after the scaling, and below M's bound, at least 2^266, an
-- underflow's absolute error is negligible.) Only near-exact ties reach the expansion: its
-- loops, met as side exits of LuaJIT's traces, failed to compile ("register coalescing too
-- complex").
local function reachesExact(x1, y1, x2, y2, rh, rl)
  local dxh, dxl = twoDiff(x2, x1)
  local dyh, dyl = twoDiff(y2, y1)
  local s = exactTestScale(max(abs(dxh), abs(dyh), abs(rh)))
  rh, rl, dxh, dxl, dyh, dyl = rh * s, rl * s, dxh * s, dxl * s, dyh * s, dyl * s
  local ph, pl = twoProduct(rh, rh)
  local xh, xl = twoProduct(dxh, dxh)
  local yh, yl = twoProduct(dyh, dyh)
  local a, ae = twoDiff(ph, xh)
  local b, be = twoDiff(a, yh)
  local small = (be + ae) + ((pl - xl) - yl) + 2 * ((rh * rl - dxh * dxl) - dyh * dyl)
    + ((rl * rl - dxl * dxl) - dyl * dyl)
  local gap = b + small
  if abs(gap) > REACH_BOUND * ((ph + xh) + yh) then return gap end
  expClear()
  expAddSquare(rh, rl, 1)
  expAddSquare(dxh, dxl, -1)
  expAddSquare(dyh, dyl, -1)
  return expSign()
end

-- A number with the sign of (rh + rl)^2 - |(x2, y2) - (x1, y1)|^2, exact. The float difference
-- is off by less than 8 eps times the sum of the squares: each square is within 3 eps, the
-- differences and the radius within one more rounding.
local function reachesFiltered(x1, y1, x2, y2, rh)
  local dx, dy = x2 - x1, y2 - y1
  local distSq, reachSq = dx * dx + dy * dy, rh * rh
  local gap = reachSq - distSq
  local bound = 8 * EPS * (reachSq + distSq)
  -- abs, not two comparisons: on LuaJIT the sign of gap then takes no side exit
  if abs(gap) > bound and bound > FILTER_LO and bound < FILTER_HI then return gap end
  return 0.0   -- the bound cannot vouch
end

local function reaches(x1, y1, x2, y2, rh, rl)
  local gap = reachesFiltered(x1, y1, x2, y2, rh)
  if gap ~= 0 then return gap end
  return reachesExact(x1, y1, x2, y2, rh, rl)
end

-- Scratch expansions for the degree-4 test: the cross product and the squared edge length.
local crossParts, lengthParts = {}, {}

-- The exact sign of r^2 |b - a|^2 - ((b - a) x (c - a))^2: > 0 when the centre c lies strictly
-- within r of the line through a and b. The differences are split exactly, the cross product
-- and the squared length summed as compressed expansions, then their products expanded.
local function lineWithinExact(ax, ay, bx, by, cx, cy, r)
  local exh, exl = twoDiff(bx, ax)
  local eyh, eyl = twoDiff(by, ay)
  local wxh, wxl = twoDiff(cx, ax)
  local wyh, wyl = twoDiff(cy, ay)
  local s = exactTestScale(max(abs(exh), abs(eyh), abs(wxh), abs(wyh), r))
  exh, exl, eyh, eyl = exh * s, exl * s, eyh * s, eyl * s
  wxh, wxl, wyh, wyl = wxh * s, wxl * s, wyh * s, wyl * s
  expClear()
  expAddProduct(exh, wyh); expAddProduct(exh, wyl); expAddProduct(exl, wyh); expAddProduct(exl, wyl)
  expAddProduct(-eyh, wxh); expAddProduct(-eyh, wxl); expAddProduct(-eyl, wxh); expAddProduct(-eyl, wxl)
  expCompress()
  local crossLen = expLength()
  for i = 1, crossLen do crossParts[i] = expansion[i] end
  expClear()
  expAddSquare(exh, exl, 1)
  expAddSquare(eyh, eyl, 1)
  expCompress()
  local lengthLen = expLength()
  for i = 1, lengthLen do lengthParts[i] = expansion[i] end
  local radiusSqHi, radiusSqLo = twoProduct(r * s, r * s)
  expClear()
  for i = 1, lengthLen do
    expAddProduct(lengthParts[i], radiusSqLo)
    expAddProduct(lengthParts[i], radiusSqHi)
  end
  for i = 1, crossLen do
    for j = 1, crossLen do expAddProduct(-crossParts[i], crossParts[j]) end
  end
  return expSign()
end

-- A number with the sign of r^2 |b - a|^2 - ((b - a) x (c - a))^2, exact. The cross product is
-- off by at most 4 eps t, t = |ex wy| + |ey wx|, so its square by 9 eps t^2; the other side by
-- 6 eps of itself: 16 eps times the sum bounds the error of the difference.
local function lineWithin(ax, ay, bx, by, cx, cy, r)
  local ex, ey, wx, wy = bx - ax, by - ay, cx - ax, cy - ay
  local left, right = ex * wy, ey * wx
  local crossed = left - right
  local t = abs(left) + abs(right)
  local reachSq = r * r * (ex * ex + ey * ey)
  local gap = reachSq - crossed * crossed
  local bound = 16 * EPS * (reachSq + t * t)
  if (gap > bound or -gap > bound) and bound > FILTER_LO and bound < FILTER_HI then return gap end
  return lineWithinExact(ax, ay, bx, by, cx, cy, r)
end

-- A number with the sign of (c - a).(b - a), exact: it is the cross product of c - a with
-- b - a turned a quarter, (c - a) x (ay - by, bx - ax).
local function dot(ax, ay, cx, cy, bx, by)
  return cross(ax, ay, cx, cy, by, ax, ay, bx)
end

-- Whether the circle (cx, cy, r) stays on the outer side of the line through a -> b, touching at
-- most, for a polygon whose area has the sign `sign`: then it cannot meet the interior. Exact.
local function clearOfEdge(ax, ay, bx, by, sign, cx, cy, r)
  if cross(ax, ay, bx, by, ax, ay, cx, cy) * sign > 0 then return false end
  return lineWithin(ax, ay, bx, by, cx, cy, r) <= 0
end

-- Whether the open disc (cx, cy, r), r > 0, meets the interior of the convex polygon, exactly:
-- the centre is in the closed polygon, or within r of a vertex, or within r of an edge's line
-- with the foot of its perpendicular strictly between the edge's ends. The slow path of
-- circleCollision, for circles within rounding of touching.
local function discMeetsExact(points, n, sign, cx, cy, r)
  local inside = true
  local ax, ay = points[n - 1] + 0.0, points[n] + 0.0
  for i = 1, n - 1, 2 do
    local bx, by = points[i] + 0.0, points[i + 1] + 0.0
    if reaches(bx, by, cx, cy, r, 0.0) > 0 then return true end
    if bx ~= ax or by ~= ay then
      if cross(ax, ay, bx, by, ax, ay, cx, cy) * sign < 0 then inside = false end
      if dot(ax, ay, cx, cy, bx, by) > 0 and dot(bx, by, cx, cy, ax, ay) > 0
          and lineWithin(ax, ay, bx, by, cx, cy, r) > 0 then
        return true
      end
    end
    ax, ay = bx, by
  end
  return inside
end

-- The range of a circle projected on the axis (nx, ny) (unit length), relative to (x, y).
-- Returns min, max
function M.projectCircle(cx, cy, radius, x, y, nx, ny)
  local fname = "projectCircle"
  checkNumber(cx, fname, "cx")
  checkNumber(cy, fname, "cy")
  checkNumber(radius, fname, "radius")
  checkNumber(x, fname, "x")
  checkNumber(y, fname, "y")
  checkNumber(nx, fname, "nx")
  checkNumber(ny, fname, "ny")
  if radius < 0 then error(("%s: radius must not be negative, got %s"):format(fname, radius), 2) end
  local s = ((cx + 0.0) - x) * nx + ((cy + 0.0) - y) * ny
  return s - radius, s + radius
end

-- Whether two circles collide: |c2 - c1|^2 < (r1 + r2)^2, the sum of the radii exact.
local function circlesCollide(x1, y1, r1, x2, y2, r2)
  return reaches(x1, y1, x2, y2, twoDiff(r1, -r2)) > 0
end

-- Whether two circles overlap, with the push that separates them.
-- Touching is not colliding; decided exactly ((x2 - x1)^2 + (y2 - y1)^2 < (r1 + r2)^2), so a
-- circle of radius 0 is a point, colliding only strictly inside the other circle.
-- (dx, dy) moves the second circle: after x2 + dx, y2 + dy (rounded as a game adds them) the
-- circles no longer collide. Its length exceeds overlap by a few ulps of the coordinates at
-- most. Circles with the same centre are pushed along +x.
-- Returns overlap, dx, dy (overlap = r1 + r2 - distance) or false
function M.circlesCollideV(x1, y1, r1, x2, y2, r2)
  local fname = "circlesCollideV"
  checkFiniteNumber(x1, fname, "x1")
  checkFiniteNumber(y1, fname, "y1")
  checkRadius(r1, fname, "r1")
  checkFiniteNumber(x2, fname, "x2")
  checkFiniteNumber(y2, fname, "y2")
  checkRadius(r2, fname, "r2")
  x1, y1, r1, x2, y2, r2 = x1 + 0.0, y1 + 0.0, r1 + 0.0, x2 + 0.0, y2 + 0.0, r2 + 0.0
  -- Far from 1 in magnitude the squares would overflow or underflow: work on copies scaled by a
  -- power of two (exact, and rounding commutes with it), then scale the answer back.
  local m = max(abs(x1), abs(y1), abs(x2), abs(y2), r1 + r2)
  local k = 1.0
  if m > 2^500 or m < 2^-400 then
    -- small ones go to 2^-200: every scale factor 2^(64 j) below it stays a finite double
    k = m > 1 and powerScale(m, 2^-32, 2^32) or powerScale(m, 2^-200, 2^-136)
    x1, y1, r1, x2, y2, r2 = x1 * k, y1 * k, r1 * k, x2 * k, y2 * k, r2 * k
    m = m * k
  end
  if not circlesCollide(x1, y1, r1, x2, y2, r2) then return false end
  local dx, dy = x2 - x1, y2 - y1
  local ux, uy, dist = 1.0, 0.0, 0.0
  if dx ~= 0 or dy ~= 0 then ux, uy, dist = unit(dx, dy) end
  local overlap = (r1 + r2) - dist
  -- Moving by overlap leaves the circles touching at best, and rounding x2 + dx can lose half
  -- an ulp of x2 on each axis. So unless that push already clears them, it grows by half an
  -- ulp of the largest magnitude, doubled until the moved circle clears for certain.
  local extra, step = 0.0, EPS * m
  for _ = 1, 64 do
    local length = overlap + extra
    local px, py = ux * length + 0.0, uy * length + 0.0   -- + 0.0 turns -0 into 0
    -- circlesCollide's exact test directly: after the push the circles are within rounding of
    -- touching, where its filter cannot vouch (on LuaJIT its side exit made a side trace of
    -- the caller's trace on every push, which failed, "register coalescing too complex")
    if reachesExact(x1, y1, x2 + px, y2 + py, twoDiff(r1, -r2)) <= 0 then
      return overlap / k, px / k, py / k
    end
    extra, step = step, step * 2
  end
  -- not reached: 64 doublings lengthen the push by 2^11 times the largest magnitude
  return overlap / k, ux * (overlap + extra) / k, uy * (overlap + extra) / k
end

-- The neighbour of vertex i (an odd index) distinct from it, walking by `dir` (2 or -2) around
-- the n coordinates; i itself when every vertex is the same point.
local function distinctNeighbour(points, n, i, dir)
  local x, y = points[i] + 0.0, points[i + 1] + 0.0
  local j = (i + dir - 1) % n + 1   -- wraps around without a branch: 1 after n - 1, n - 1 before 1
  -- the usual case without a loop, which LuaJIT would fail to compile inside the caller's trace
  if points[j] + 0.0 ~= x or points[j + 1] + 0.0 ~= y then return j end
  for _ = 2, n / 2 - 1 do
    j = (j + dir - 1) % n + 1
    if points[j] + 0.0 ~= x or points[j + 1] + 0.0 ~= y then return j end
  end
  return j
end

-- A number < 0 when the centre (cx, cy) lies strictly inside the corner region of the vertex v
-- between its distinct neighbours w and u (indices): the larger of (c - v).(w - v) and
-- (c - v).(u - v) (0 when c is v, or on the region's edge, where the edge's line is as near).
-- w - v and u - v come from the given coordinates, not as differences of c - w and c - v: far
-- from a large circle's centre those round to multiples of its ulp, which may exceed the
-- whole polygon. No branch: one comparison of the caller decides (on LuaJIT each comparison
-- that goes both ways grows a side trace).
local function cornerMargin(points, v, w, u, cx, cy)
  local x, y = points[v] + 0.0, points[v + 1] + 0.0
  local vx, vy = x - cx, y - cy
  return max(vx * (x - points[w]) + vy * (y - points[w + 1]),
    vx * (x - points[u]) + vy * (y - points[u + 1]))
end

local penetration, circlePush
do   -- the push's helpers are local to this block
-- The push's direction, left here by penetration for circlePush: its unit vector (ux, uy), to
-- rounding, and |(ux, uy)|^2 - 1, to order eps^2. Not returned: on LuaJIT every number held in
-- a local of circleCollision at its branches would go to their side traces (see there), and
-- only the push needs these.
local pushUx, pushUy, pushNormError = 0.0, 0.0, 0.0

-- a * a as hi + lo exactly: twoProduct with one split instead of two (the push squares often)
local function twoSquare(a)
  local x = a * a
  local c = SPLITTER * a
  local ahi = c - (c - a)
  local alo = a - ahi
  return x, alo * alo - ((x - ahi * ahi) - 2 * ahi * alo)
end

-- (b - a) x (c - a) and |b - a|^2, each as an unevaluated sum hi + low of two doubles, within
-- 8 eps^2 t and 8 eps^2 |b - a|^2 (t = |ex wy| + |ey wx|, the magnitudes of the cross product's
-- terms, returned last): the differences split exactly into hi + lo, the main products by
-- TwoProduct, the first-order terms of the low parts added once; what is dropped (products of
-- two low parts, the roundings of terms already of order eps) is of order eps^2.
local function crossAndLengthAccurate(ax, ay, bx, by, cx, cy)
  local exh, exl = twoDiff(bx, ax)
  local eyh, eyl = twoDiff(by, ay)
  local wxh, wxl = twoDiff(cx, ax)
  local wyh, wyl = twoDiff(cy, ay)
  local p, pLow = twoProduct(exh, wyh)
  local q, qLow = twoProduct(eyh, wxh)
  local crossed, crossedLow = twoDiff(p, q)
  crossedLow = crossedLow + (pLow - qLow) + (exh * wyl + exl * wyh) - (eyh * wxl + eyl * wxh)
  local lengthSq, lengthSqLow
  do   -- (scoped: a small frame, see circleCollision)
    local xx, xxLow = twoSquare(exh)
    local yy, yyLow = twoSquare(eyh)
    lengthSq, lengthSqLow = twoDiff(xx, -yy)
    lengthSqLow = lengthSqLow + (xxLow + yyLow) + 2 * (exh * exl + eyh * eyl)
  end
  return crossed, crossedLow, lengthSq, lengthSqLow, abs(p) + abs(q)
end

-- A margin > 0 when the circle (cx, cy, r) certainly stays beyond the line of the edge a -> b
-- (as clearOfEdge), by float arithmetic alone: <= 0 also when rounding cannot tell. It compares
-- outside^2 with r^2 |b - a|^2, outside = (b - a) x (a - c) turned outwards, every product kept
-- as hi + low: the difference is off by less than 32 eps^2 (outside^2 + r^2 |b - a|^2 + t^2)
-- (the high parts' difference is exact by Sterbenz's lemma when they are within a factor 2,
-- and dwarfs the rest otherwise). So the test needs room of order eps^2, not eps: a push that
-- clears by a rounding of the coordinates passes it. One comparison of a min, not a chain of
-- them: on LuaJIT each comparison is a guard, and a failing guard grows a side trace.
local function beyondEdgeFiltered(ax, ay, bx, by, sign, cx, cy, r)
  local crossed, crossedLow, lengthSq, lengthSqLow, t = crossAndLengthAccurate(ax, ay, bx, by, cx, cy)
  -- (few locals: this is the deepest frame of the push, and on Lua 5.4 a deeper stack means
  -- one more stack reallocation after each full collection)
  local outside = -crossed * sign
  local outsideSq, outsideSqLow = twoSquare(outside)
  outsideSqLow = outsideSqLow - 2 * outside * crossedLow * sign
  local radiusSq, radiusSqLow = twoSquare(r)
  local reachSq, reachSqLow = twoProduct(radiusSq, lengthSq)
  reachSqLow = reachSqLow + (radiusSq * lengthSqLow + radiusSqLow * lengthSq)
  -- the gap outside^2 - r^2 |b - a|^2 less its error bound
  local clearance = (outsideSq - reachSq) + (outsideSqLow - reachSqLow)
    - 32 * EPS * EPS * (outsideSq + reachSq + t * t)
  local bound = 32 * EPS * EPS * (outsideSq + reachSq)
  return min(outside, clearance, bound - FILTER_LO, FILTER_HI - bound)
end

-- A margin > 0 when the circle (cx, cy, r) certainly lies in the corner region of the vertex b
-- between its neighbours a and q, at distance r or more from b, by float arithmetic alone. Each dot
-- product (m - b).(a - b) is within 3 eps of the sum of its terms' magnitudes; |m - b|^2 - r^2
-- is summed from exact squares of the split differences, off by less than 16 eps^2 of
-- |m - b|^2 + r^2 (as in beyondEdgeFiltered, room of order eps^2).
local function cornerClearFiltered(ax, ay, bx, by, qx, qy, cx, cy, r)
  local wx, wxLow = twoDiff(cx, bx)
  local wy, wyLow = twoDiff(cy, by)
  local s1, s2 = wx * (ax - bx), wy * (ay - by)
  local t1, t2 = wx * (qx - bx), wy * (qy - by)
  local xx, xxLow = twoSquare(wx)
  local yy, yyLow = twoSquare(wy)
  local distSq, distSqLow = twoDiff(xx, -yy)
  local radiusSq, radiusSqLow = twoSquare(r)
  local gap = (distSq - radiusSq)
    + ((distSqLow + (xxLow + yyLow) + 2 * (wx * wxLow + wy * wyLow)) - radiusSqLow)
  local bound = 16 * EPS * EPS * (distSq + radiusSq)
  return min(-(s1 + s2) - 4 * EPS * (abs(s1) + abs(s2)), -(t1 + t2) - 4 * EPS * (abs(t1) + abs(t2)),
    gap - bound, bound - FILTER_LO, FILTER_HI - bound)
end

-- The exact test behind tryPush's filters, for the moved centre (mx, my).
local function pushClears(points, a, b, q, sign, mx, my, r)
  local ax, ay, bx, by = points[a] + 0.0, points[a + 1] + 0.0, points[b] + 0.0, points[b + 1] + 0.0
  if q == 0 then return clearOfEdge(ax, ay, bx, by, sign, mx, my, r) end
  local qx, qy = points[q] + 0.0, points[q + 1] + 0.0
  -- in the corner region of b, where the distance to the polygon is |m - b|, or beyond an edge
  return dot(bx, by, mx, my, ax, ay) <= 0 and dot(bx, by, mx, my, qx, qy) <= 0
      and reachesExact(bx, by, mx, my, r, 0.0) <= 0
    or clearOfEdge(ax, ay, bx, by, sign, mx, my, r) or clearOfEdge(bx, by, qx, qy, sign, mx, my, r)
end

-- One try of circlePush: the push of length depth + lengthLow along (ux, uy), and whether the
-- certificate holds for it; `late`: consult the exact tests where the float ones cannot tell.
-- For the edge a -> b (q == 0), or the vertex b between its distinct neighbours a and q (all
-- indices into points, read here rather than held, which keeps few numbers live for LuaJIT).
local function tryPush(points, a, b, q, sign, cx, cy, r, ux, uy, depth, lengthLow, late)
  -- (ux, uy) (depth + lengthLow), each coordinate rounded once: + 0.0 turns -0 into 0
  local px, py
  do   -- (scoped: a small frame, see circleCollision)
    local hi, low = twoProduct(ux, depth)
    px = hi + (low + ux * lengthLow) + 0.0
    hi, low = twoProduct(uy, depth)
    py = hi + (low + uy * lengthLow) + 0.0
  end
  -- the filters' margin: > 0 when one of them vouches. Only the indices are kept across the
  -- branch on it (on LuaJIT a side trace there took over every number alive: with the
  -- coordinates it failed to compile, "NYI: register coalescing too complex", for lists of parts)
  local margin
  do
    local mx, my = cx + px, cy + py
    local ax, ay, bx, by = points[a] + 0.0, points[a + 1] + 0.0, points[b] + 0.0, points[b + 1] + 0.0
    if q == 0 then
      margin = beyondEdgeFiltered(ax, ay, bx, by, sign, mx, my, r)
    else
      local qx, qy = points[q] + 0.0, points[q + 1] + 0.0
      margin = cornerClearFiltered(ax, ay, bx, by, qx, qy, mx, my, r)
      if JIT then   -- all three, no branch
        margin = max(margin, beyondEdgeFiltered(ax, ay, bx, by, sign, mx, my, r),
          beyondEdgeFiltered(bx, by, qx, qy, sign, mx, my, r))
      elseif margin <= 0 then   -- the next only when needed (each is a call on PUC Lua)
        margin = beyondEdgeFiltered(ax, ay, bx, by, sign, mx, my, r)
        if margin <= 0 then margin = beyondEdgeFiltered(bx, by, qx, qy, sign, mx, my, r) end
      end
    end
  end
  if margin > 0 then return px, py, true end
  if not late then return px, py, false end
  local cleared = pushClears(points, a, b, q, sign, cx + px, cy + py, r)
  return px, py, cleared
end

-- The push out of the polygon along (ux, uy), a unit vector to rounding, depth + lengthLow (to
-- order eps^2) the length that moves the centre by the penetration depth + depthLow (the
-- direction and the penetration from penetration, lengthLow correcting for |(ux, uy)| - 1,
-- depthLow for a depth set to 0): the first length tried that the certificate accepts. That
-- length is lengthened by what rounding can take from the push (EPS = 2^-53 bounds the
-- relative error of one rounding): cx + px rounds by at most EPS |cx + px|, which moves the
-- centre along the push by at most EPS (|mx ux| + |my uy|), m the moved centre; px and py,
-- each rounded once (tryPush), by at most EPS depth along it. The certificates need room of
-- order eps^2 only, so that first push clears unless a second edge is within rounding of
-- touching (then the exact tests accept the same push), and its length exceeds the depth by
-- at most EPS (|mx ux| + |my uy| + 2 depth) and terms of order eps^2: with M the largest
-- coordinate magnitude, the moved centre's included, |m| <= sqrt(2) M and
-- depth <= |m| + |c| <= 2 sqrt(2) M, so at most 7.1 eps M.
-- feature: the edge or vertex, as in penetration. far: whether the magnitudes reach about
-- 2^240, where the float certificate's squares (degree 4) overflow and only the exact one
-- tells; it only spares a try (the next try takes the same push to the exact tests).
function circlePush(points, n, sign, cx, cy, r, depth, depthLow, feature, far)
  local ux, uy = pushUx, pushUy
  -- EPS (|mx ux| + |my uy| + depth), m = c + depth u; the EPS^2 term keeps the extra positive
  -- (it grows below) when the rest is zero; 1 + 2^-20 covers the roundings of the bound itself
  local extra = (1 + 2^-20) * EPS
    * (abs((cx + ux * depth) * ux) + abs((cy + uy * depth) * uy) + depth)
    + EPS * EPS * (abs(cx) + abs(cy) + r)
  local lengthLow = (depthLow - depth * pushNormError * 0.5) + extra
  -- the edge a -> b (feature > 0), or the vertex b = -feature and its neighbours a, q
  local a, b, q = feature == 1 and n - 1 or feature - 2, feature, 0
  if feature < 0 then
    b = -feature
    a, q = distinctNeighbour(points, n, b, -2), distinctNeighbour(points, n, b, 2)
  end
  -- the first try outside the loop: LuaJIT cannot compile a loop entered from the caller's
  -- trace with this many live values ("register coalescing too complex"), and one try is usual
  local px, py, cleared = tryPush(points, a, b, q, sign, cx, cy, r, ux, uy, depth, lengthLow, far)
  if cleared then return px, py end
  -- within rounding of touching a second edge or vertex: the exact tests decide from here on,
  -- first for the same push, then with the extra growing by a quarter of itself each try, then
  -- by 4 (a concave polygon, which the certificate may never accept)
  for i = 1, 40 do
    px, py, cleared = tryPush(points, a, b, q, sign, cx, cy, r, ux, uy, depth, lengthLow, true)
    if cleared then return px, py end
    local more = extra * (i <= 8 and 0.25 or 3)
    extra, lengthLow = extra + more, lengthLow + more
  end
  -- only a concave polygon or sizes outside the exact range get here: the longest push tried
  return px, py
end

-- The penetration of the circle (cx, cy, r) along the push out of the polygon: depth + depthLow,
-- r less the distance from the centre to the polygon to order eps^2; the push's direction is
-- left in pushUx, pushUy and pushNormError. From the vertex -feature (index) when feature < 0
-- (the centre lies in its corner region), else from the edge ending at index feature. The
-- distance is computed again from the given coordinates, each square root and quotient refined
-- by one Newton step on the exact residual.
-- (Apart from circleCollision, so that its frame stays small: on Lua 5.4 a larger frame makes
-- the stack grow again, allocating, after every full collection.)
function penetration(points, n, sign, cx, cy, r, feature)
  local ux, uy, distance, distanceLow
  if feature < 0 then
    local v = -feature
    local wx, wxLow = twoDiff(cx, points[v] + 0.0)
    local wy, wyLow = twoDiff(cy, points[v + 1] + 0.0)
    local xx, xxLow = twoSquare(wx)
    local yy, yyLow = twoSquare(wy)
    local distSq, distSqLow = twoDiff(xx, -yy)
    distSqLow = distSqLow + (xxLow + yyLow) + 2 * (wx * wxLow + wy * wyLow)
    distance = sqrt(distSq)
    local sq, sqLow = twoSquare(distance)
    distanceLow = ((distSq - sq) - sqLow + distSqLow) / (2 * distance)
    ux, uy = wx / distance, wy / distance
  else
    -- the edge a -> b: its outward unit normal, and the centre's signed distance from its
    -- line, -((b - a) x (c - a)) / |b - a| turned outwards
    local a = feature == 1 and n - 1 or feature - 2
    local ax, ay = points[a] + 0.0, points[a + 1] + 0.0
    local bx, by = points[feature] + 0.0, points[feature + 1] + 0.0
    local crossed, crossedLow, lengthSq, lengthSqLow = crossAndLengthAccurate(ax, ay, bx, by, cx, cy)
    local length = sqrt(lengthSq)
    local sq, sqLow = twoSquare(length)
    local lengthLow = ((lengthSq - sq) - sqLow + lengthSqLow) / (2 * length)
    local outside, outsideLow = -crossed * sign, -crossedLow * sign
    distance = outside / length
    local product, productLow = twoProduct(distance, length)
    distanceLow = ((outside - product) - productLow + outsideLow - distance * lengthLow) / length
    ux, uy = (by - ay) * sign / length, (ax - bx) * sign / length
  end
  -- |(ux, uy)|^2 - 1, to order eps^2 (the squares' high parts sum to within an ulp of 1, so
  -- less 1 is exact: Sterbenz)
  local xx, xxLow = twoSquare(ux)
  local yy, yyLow = twoSquare(uy)
  local normSq, normSqLow = twoDiff(xx, -yy)
  pushUx, pushUy, pushNormError = ux, uy, (normSq - 1) + (normSqLow + (xxLow + yyLow))
  local depth, depthLow = twoDiff(r, distance)
  return depth, depthLow - distanceLow
end
end

-- The edge walk, in coordinates relative to the centre (c): the sign of the polygon's area,
-- 1.0 or -1.0, which makes distances positive outside, the nearest vertex, its squared
-- distance, the largest squared distance to a vertex, and the edge (the index of its end)
-- whose line lies farthest behind the centre; that index is -1 for a zero area and -2 when
-- the area is not finite (the other numbers then placeholders).
-- An edge's signed distance is its cross product (b - a) x (a - c) over |b - a|; edges are
-- compared by its signed square, outside |outside| / |b - a|^2, so no square root is taken.
-- Two bodies. As in projectRange, LuaJIT gets a loop without data-dependent branches: each
-- such branch becomes a side trace, and the rest of the function is compiled again behind
-- every one of them. It is one pass, the sign included: the extremes by min and max, the index
-- of each extreme's first match by a select without a branch (it moves to i by (i - index)
-- times 1 when the new number beats the extreme, times 0 when not). The farthest edge depends
-- on the sign, known only after the loop: the loop takes the sign of the turn at vertex 1 as a
-- guess (the area's sign for a convex polygon) and runs again with the sign when the guess was
-- wrong. The sign comes from the same cross products (below), the exact kernel deciding where
-- they cannot. Few values stay alive across the loop and after it: more made side traces fail
-- to compile ("NYI: register coalescing too complex"). The PUC interpreters call min and max
-- as functions, so for them a branchy pass is faster.

-- The sign of the polygon's area as 1.0 or -1.0, exact; 0 for a zero area, nil when the area
-- is not finite (a non-finite coordinate, or an overflow).
local function exactTurn(points, n)
  local area, sumX2, sumD2 = shoelace(points, n)
  if area - area ~= 0 then return nil end
  local turn = areaSignOf(points, n, area, sumX2, sumD2)
  if turn == 0 then return 0 end
  return turn > 0 and 1.0 or -1.0
end

-- min(x * LIFT * LIFT, 1) is 1 when x > 0 and 0 when x == 0, for x >= 0, without a branch:
-- the least positive double, 2^-1074, times 2^1074 is 1. (Written out where used: as a
-- function called per vertex it started traces of its own, which LuaJIT aborted.)
local LIFT = 2^537
-- One pass with the sign guessed (1.0 or -1.0): near, nearSq, farSq, and the farthest edge
-- as if the area's sign were `guess`, its key, and the sum of the cross products (below).
-- checks: the convexity check of polygonCircleCollideV in the same pass, convex.lua's vouching
-- pass for this walk: the turns (e x f of the edges into and out of each vertex) and the
-- windings (the exact signs of the x differences; see convex.lua), and in place of the sum,
-- 1 when every turn is surely of guess's sign and the polygon winds once (it is convex, and
-- guess is its area's sign), else 0. The turns' error bound comes from farSq, not from a box:
-- every vertex lies within sqrt(farSq) (rounded) of the centre, so every edge's difference is
-- below 2 sqrt(farSq) and |l| + |r| below 8 farSq, times 1 + a few eps (9 covers it); with
-- the circle far from a small polygon it cannot vouch, and the caller checks the careful way.
local function walkGuessed(points, n, cx, cy, guess, checks)
  local nearSq, farSq, near = huge, 0.0, 1
  -- the farthest edge's key and index: an edge's key is outside |outside| / |b - a|^2,
  -- outside = crossed * sign, less 2^1000 for a repeated vertex (|b - a|^2 == 0): below
  -- every real edge's key in the range where the walk's answer is used (farSq < 2^1000)
  local bestKey, best = -huge, 1
  local turnSum = 0.0
  local px, py = points[n - 1], points[n]
  local ax, ay = px - cx, py - cy
  local lo, hi, agree, pex, pey, psx = huge, -huge, 0, 0.0, 0.0, 0
  if checks then   -- the edge into vertex m
    pex, pey = px - points[n - 3], py - points[n - 2]
    psx = min(1, max(-1, pex * 2^537 * 2^537))
  end
  for i = 1, n - 1, 2 do
    local qx, qy = points[i], points[i + 1]
    local bx, by = qx - cx, qy - cy
    local distSq = bx * bx + by * by
    near = near + (i - near) * min(max(nearSq - distSq, 0) * LIFT * LIFT, 1)
    nearSq, farSq = min(nearSq, distSq), max(farSq, distSq)
    local ex, ey = qx - px, qy - py   -- from the given coordinates (see edgeWalk)
    local lengthSq = ex * ex + ey * ey
    local crossed = ex * ay - ey * ax
    turnSum = turnSum + crossed
    local outside = crossed * guess
    local key = outside * (abs(outside) / max(lengthSq, 2^-1074))
      - (1 - min(lengthSq * LIFT * LIFT, 1)) * 2^1000
    best = best + (i - best) * min(max(key - bestKey, 0) * LIFT * LIFT, 1)
    bestKey = max(bestKey, key)
    if checks then
      local turn, sx = pex * ey - pey * ex, min(1, max(-1, ex * 2^537 * 2^537))
      lo, hi, agree = min(lo, turn), max(hi, turn), agree + psx * sx
      pex, pey, psx = ex, ey, sx
    end
    px, py, ax, ay = qx, qy, bx, by
  end
  if checks then
    -- (the sum carries a NaN or an overflow, which min and max may drop)
    if max(lo, -hi) > 9 * CROSS_BOUND * farSq + 2^-900 and agree == n / 2 - 4
        and turnSum - turnSum == 0 and (lo + hi) * guess > 0 then
      return near, nearSq, farSq, best, bestKey, 1
    end
    return near, nearSq, farSq, best, bestKey, 0
  end
  return near, nearSq, farSq, best, bestKey, turnSum
end

-- The edge walk for LuaJIT: two branch-free passes at most (walkGuessed), the sign filtered
-- from the cross products' sum. checks: the convexity check in the same pass (walkGuessed's);
-- when it cannot vouch, feature -3 (the caller checks the careful way and walks again).
local function edgeWalkJit(points, n, cx, cy, _, checks)
  -- the guess: the sign of the turn at vertex 1, without a branch (1 when it is 0); it is
  -- the area's for a convex polygon
  local guess
  do
    local x0, y0, x1, y1 = points[n - 1], points[n], points[1], points[2]
    local turn = (x1 - x0) * (points[4] - y1) - (y1 - y0) * (points[3] - x1)
    guess = 1 - 2 * min(max(-turn * LIFT * LIFT, 0), 1)
  end
  if checks then
    local near, nearSq, farSq, best, bestKey, vouched = walkGuessed(points, n, cx, cy, guess, true)
    if vouched == 0 then return 0.0, 1, 0.0, 0.0, -3 end
    if bestKey - bestKey ~= 0 then best = 0 end   -- as below
    return guess, near, nearSq, farSq, best
  end
  local near, nearSq, farSq, best, bestKey, turnSum = walkGuessed(points, n, cx, cy, guess)
  -- The sum of the cross products (b - a) x a = b x a is minus twice the area of the polygon
  -- moved by -c and rounded, which is off from the exact area by 2 eps S at most, S the sum
  -- of the squared distances; the cross products and their sum add (m + 5) eps S (m = n / 2;
  -- a cross product's terms are at most (|a|^2 + |b|^2) / 2 in magnitude). S <= m farSq, and
  -- the factor 4 and the 16 cover the second-order terms and this bound's own roundings;
  -- 2^-900 is far above what underflow can take (a multiple of n 2^-1074).
  local sign
  local m = n * 0.5
  if abs(turnSum) > max((m + 16) * 2^-51 * m * farSq, 2^-900) then
    sign = -turnSum / abs(turnSum)
  else
    sign = exactTurn(points, n)
    if sign == nil then return 0.0, 1, 0.0, 0.0, -2 end
    if sign == 0 then return 0.0, 1, 0.0, 0.0, -1 end
  end
  if sign ~= guess then   -- a wrong guess (rare: a concave or degenerate turn at vertex 1)
    near, nearSq, farSq, best, bestKey = walkGuessed(points, n, cx, cy, sign)
  end
  -- an infinite key (an overflow) gives 0, which sends the caller to its scaled path
  if bestKey - bestKey ~= 0 then best = 0 end
  return sign, near, nearSq, farSq, best
end

-- The edge walk for PUC Lua: one pass with branches, the sign from the exact kernel first;
-- checks: from convex.lua's vouching pass instead (feature -3 when it cannot vouch, as in
-- edgeWalkJit).
-- It also stops at the first edge whose line the circle (radius r) is certainly
-- beyond, returning best = -1: an edge's squared signed distance is off by less than
-- 32 eps (r^2 + the squared distances of its ends), so a key past r^2 by that much means
-- the circle is apart, as the full pass would decide too (LuaJIT's loop stays branch-free).
local function edgeWalkPuc(points, n, cx, cy, r, checks)
  local sign
  if checks then
    sign = vouch(points, n)
    if not sign then return 0.0, 1, 0.0, 0.0, -3 end
  else   -- exactTurn written out (a call costs PUC Lua more than these lines)
    local area, sumX2, sumD2 = shoelace(points, n)
    if area - area ~= 0 then return 0.0, 1, 0.0, 0.0, -2 end
    local turn = areaSignOf(points, n, area, sumX2, sumD2)
    if turn == 0 then return 0.0, 1, 0.0, 0.0, -1 end
    sign = turn > 0 and 1.0 or -1.0
  end
  local nearSq, farSq, near = huge, 0.0, 1
  local bestKey, best = -huge, 0
  local px, py = points[n - 1] + 0.0, points[n] + 0.0
  local ax, ay = px - cx, py - cy
  local radiusSq = r * r
  local prevSq = ax * ax + ay * ay
  for i = 1, n - 1, 2 do
    local qx, qy = points[i], points[i + 1]
    local bx, by = qx - cx, qy - cy
    local distSq = bx * bx + by * by
    if distSq < nearSq then nearSq, near = distSq, i end
    if distSq > farSq then farSq = distSq end
    local ex, ey = qx - px, qy - py   -- px, py floats: no integer overflow
    local lengthSq = ex * ex + ey * ey
    if lengthSq > 0 then   -- a repeated vertex gives no edge
      local outside = (ex * ay - ey * ax) * sign
      local key = outside * (abs(outside) / lengthSq)
      if key > bestKey then
        bestKey, best = key, i
        if key - radiusSq > 32 * EPS * (radiusSq + prevSq + distSq) then
          return sign, near, nearSq, farSq, -1
        end
      end
    end
    px, py, ax, ay, prevSq = qx + 0.0, qy + 0.0, bx, by, distSq
  end
  return sign, near, nearSq, farSq, best
end

local edgeWalk = JIT and edgeWalkJit or edgeWalkPuc

local circleCollision

-- circleCollision on a copy of the polygon, the centre and the radius scaled by a power of two
-- into the range where its squares neither overflow nor underflow, the answer scaled back; nil
-- for a non-finite coordinate. Rare (coordinates beyond 2^500 or all below 2^-400), so this
-- path allocates the copy.
local function circleCollisionScaled(points, n, cx, cy, r)
  local m, size = max(abs(cx), abs(cy), r), 0.0
  for i = 1, n do
    local v = points[i] + 0.0
    if v ~= v or v == huge or v == -huge then return nil end
    size = max(size, abs(v))
  end
  m = max(m, size)
  local k = m > 1 and powerScale(m, 2^-32, 2^32) or powerScale(m, 2^-200, 2^-136)
  if m > 2^500 and size * k < 2^-400 then
    -- a polygon far smaller than a huge circle: the largest magnitude goes to 2^472 .. 2^480
    -- instead, the most room for the polygon's squares below it (its own range is 2^-447 up)
    k = powerScale(m, 2^416, 2^480)
    while m * k < 2^472 do k = k * 2 end
  end
  if k == 1 then
    -- Scaling cannot help: sizes more than 2^400 apart (a polygon of size 1e-200 against a
    -- radius of 1), outside the exact range. Decide as exactly as the kernels can, and push
    -- along +x by the radius, so that nothing loops or returns NaN.
    local turn = areaSign(points, n)
    if turn == 0 or not discMeetsExact(points, n, turn > 0 and 1.0 or -1.0, cx, cy, r) then
      return false
    end
    return r, r, 0.0
  end
  local scaled = {}
  for i = 1, n do scaled[i] = points[i] * k end
  local overlap, px, py = circleCollision(scaled, n, cx * k, cy * k, r * k)
  if not overlap then return overlap end
  return overlap / k, px / k, py / k
end

-- The collision of the circle (cx, cy, r), r > 0 and every number finite, with the convex
-- polygon points[1..n], n >= 6: overlap, px, py (move the circle by px, py), false, or nil
-- when the polygon holds a non-finite coordinate. One convex polygon; polygonCircleCollideV
-- is a thin wrapper around it, so that a compound shape can call it once per part. checks:
-- the convexity check of polygonCircleCollideV in the engine's first pass (see edgeWalk);
-- nil, "unsure" when it cannot vouch for the polygon (the caller checks it the careful way and
-- calls again without checks).
--
-- A disc against a convex polygon needs no projections. The least penetration is r minus the
-- signed distance from the centre to the polygon, and that distance is the centre's largest
-- signed distance beyond an edge's line, unless the centre lies in the corner region of its
-- nearest vertex, where it is the distance to that vertex (the tutorial's axes, edge normals
-- and the nearest vertex's axis, give the same least overlap: the far ends of their ranges
-- are never the least). Three ideas, in order:
--   the edge walk: one pass for the nearest vertex and the edge line farthest behind the centre,
--   the nearest-vertex axis: whether the centre is in that vertex's corner region,
--   the exact filter: within rounding of touching, discMeetsExact decides.
function circleCollision(points, n, cx, cy, r, checks)
  -- (the do-blocks here keep the frame small: on Lua 5.4 a larger one can make the stack grow
  -- again, allocating, after every full collection)
  -- sign: 1 or -1, makes the signed distances positive outside. feature: the edge whose line
  -- lies farthest behind the centre (the index of its end), below minus the nearest vertex's
  -- index when the centre lies in that vertex's corner region
  local sign, near, nearSq, farSq, feature = edgeWalk(points, n, cx, cy, r, checks)
  if feature < 0 then   -- certainly apart (PUC only), a zero area or a non-finite one (see edgeWalk)
    if feature == -3 then return nil, "unsure" end
    if feature == -2 then   -- an infinite or NaN area: a non-finite coordinate or overflow
      local overlap, px, py = circleCollisionScaled(points, n, cx, cy, r)
      return overlap, px, py
    end
    return false
  end
  -- luacheck: ignore 581 (NaN too)
  if not (farSq < 2^1000) or farSq + r * r < 2^-800 or feature == 0 then
    local overlap, px, py = circleCollisionScaled(points, n, cx, cy, r)
    return overlap, px, py
  end
  if JIT then
    -- Certainly apart, decided as the penetration below would: the nearest vertex and the line
    -- of the farthest edge both farther than r + 2 tol (tol as below), whichever feature the
    -- corner test picks. (r + 2 tol)^2 < r^2 + 128 eps (r^2 + farSq) =: reach^2, as tol <=
    -- 16 eps (sqrt(farSq) + r) and 2 r sqrt(farSq) <= r^2 + farSq; the line by lineWithin's
    -- filter, its margins and nearSq's taken by one min (one branch). A quarter of the
    -- benchmark's circles miss; they skip the corner test and the penetration. (PUC Lua's walk
    -- ends early instead.)
    local reachSq = r * r + 128 * EPS * (r * r + farSq)
    local a = (feature - 3) % n + 1   -- the edge's start, without a branch
    local ax, ay = points[a] + 0.0, points[a + 1] + 0.0
    local ex, ey = points[feature] - ax, points[feature + 1] - ay
    local left, right = ex * (cy - ay), ey * (cx - ax)
    local crossed, t = left - right, abs(left) + abs(right)
    local lineReachSq = reachSq * (ex * ex + ey * ey)
    local bound = 16 * EPS * (lineReachSq + t * t)
    if min(-crossed * sign, (crossed * crossed - lineReachSq) - bound, nearSq - reachSq,
        bound - FILTER_LO, FILTER_HI - bound) > 0 then
      return false
    end
  end
  -- The nearest-vertex axis: when the nearest point of the polygon is a vertex w, the centre
  -- lies in its corner region, behind neither edge meeting there, and the distance to the
  -- polygon is |c - w|, the push along c - w. The vertex of the least computed distance is
  -- tested. It can be another vertex than w only when rounding hides their difference: every
  -- squared distance is within 4 eps farSq, and in w's corner region |c - v|^2 >= |c - w|^2 +
  -- |v - w|^2 for every vertex v, so then |near - w|^2 <= 8 eps farSq (far from a large
  -- circle's centre every squared distance rounds to the same number). And w is an end of an
  -- edge whose line lies farthest behind the centre (the other edges' normals turn farther from
  -- c - w): so the ends of the walk's edge that close to `near` are tested next. (Not when the
  -- least squared distance is 0: the centre on a vertex, or an underflow; the edge decides.)
  if nearSq > 0 then
    local x, y = points[near] + 0.0, points[near + 1] + 0.0
    if cornerMargin(points, near, distinctNeighbour(points, n, near, -2),
        distinctNeighbour(points, n, near, 2), cx, cy) < 0 then
      feature = -near
    else
      local b, a = feature, (feature - 3) % n + 1   -- the edge's start, without a branch
      local close = 2^-48 * farSq   -- 32 eps farSq
      local dx, dy = points[b] - x, points[b + 1] - y
      if b ~= near and dx * dx + dy * dy <= close
          and cornerMargin(points, b, a, distinctNeighbour(points, n, b, 2), cx, cy) < 0 then
        feature = -b
      else
        dx, dy = points[a] - x, points[a + 1] - y
        if a ~= near and dx * dx + dy * dy <= close
            and cornerMargin(points, a, distinctNeighbour(points, n, a, -2), b, cx, cy) < 0 then
          feature = -a
        end
      end
    end
  end
  -- On LuaJIT a branch below that goes both ways (as the first two do in a game: circles in
  -- contact, and circles a push has just left touching) becomes a side trace, which takes over
  -- in registers every number held in a local still in scope there, the callers' included:
  -- with more than the registers it fails to compile ("NYI: register coalescing too complex").
  -- So near and nearSq are dropped here, and the push's direction is not held in locals (see
  -- penetration).
  near, nearSq = nil, nil   -- luacheck: ignore 311 (dropped, see above)
  local depth, depthLow = penetration(points, n, sign, cx, cy, r, feature)
  -- The exact filter: the float depth is off by far less than tol, a few eps times the farthest
  -- vertex's distance and the radius. Apart needs less room from an edge: a circle beyond an
  -- edge's line by more than r misses the convex polygon whichever feature is nearest, and
  -- depth + depthLow measures that to order eps^2 (within 32 eps^2 (|c - a| + r)). So a circle
  -- that a push left touching by a few ulps is decided apart here, not by discMeetsExact.
  local tol = 16 * EPS * (sqrt(farSq) + r)
  if depth <= tol then
    if depth < -tol then return false end
    if feature > 0 and depth + depthLow < -32 * EPS * EPS * (sqrt(farSq) + r) then return false end
    if not discMeetsExact(points, n, sign, cx, cy, r) then return false end
    if depth + depthLow < 0 then depth, depthLow = 0.0, 0.0 end
  end
  local px, py = circlePush(points, n, sign, cx, cy, r, depth, depthLow, feature,
    cx * cx + cy * cy + r * r + farSq > 2^480)
  return depth + depthLow, px, py
end

M.circleCollision = circleCollision
M.reaches, M.lineWithin, M.dot = reaches, lineWithin, dot   -- for polygon/raycast.lua's discs
M.reachesExact = reachesExact   -- for polygon/casts.lua's step back (within rounding of touching)
M.edgeWalkJit = edgeWalkJit   -- both bodies, for spec/bodies_compound_spec.lua
M.edgeWalkPuc = edgeWalkPuc

return M
