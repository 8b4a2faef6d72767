local polygon = {
  _VERSION     = "polygon 0.1.0",
  _DESCRIPTION = "Polygon geometry for games: winding, area, convexity, centre, point in polygon, "
              .. "separating-axis collision with a minimum translation vector, polygon against circle",
  _URL         = "https://github.com/polygon-lua/polygon.lua",
  _LICENSE     = [[
    MIT License

    Copyright (c) 2026 the polygon.lua developers

    Permission is hereby granted, free of charge, to any person obtaining a copy of this software
    and associated documentation files (the "Software"), to deal in the Software without
    restriction, including without limitation the rights to use, copy, modify, merge, publish,
    distribute, sublicense, and/or sell copies of the Software, and to permit persons to whom the
    Software is furnished to do so, subject to the following conditions:

    The above copyright notice and this permission notice shall be included in all copies or
    substantial portions of the Software.

    THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR IMPLIED, INCLUDING
    BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY, FITNESS FOR A PARTICULAR PURPOSE AND
    NONINFRINGEMENT. IN NO EVENT SHALL THE AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM,
    DAMAGES OR OTHER LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
    OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE SOFTWARE.
  ]],
}

-- Points are flat arrays {x1, y1, x2, y2, ...} in screen coordinates: y grows downwards, so a
-- polygon whose shoelace sum is positive turns clockwise on screen.

local abs, sqrt, huge, min, max = math.abs, math.sqrt, math.huge, math.min, math.max
local type, error, tostring, setmetatable = type, error, tostring, setmetatable

--------------------------------------------------------------------------------------------------
-- Arithmetic kernels: the only place that decides a sign
--------------------------------------------------------------------------------------------------
-- Every sign the library decides (winding, convexity, which side of an edge a point lies on,
-- whether projected ranges overlap) comes from one of these predicates:
--   cross(u0, u1, v0, v1)        the sign of the 2x2 determinant (u1 - u0) x (v1 - v0)
--   areaSign(points, n)          the sign of twice the signed area; areaSignOf(points, n, ...)
--                                is the same from shoelace's (or shoelaceBounds') sums, for
--                                callers that use those sums too
-- Each first computes in ordinary floating point with an error bound (Shewchuk's filter):
-- cross's is CROSS_BOUND, the area's is areaUncertain. Only when the bound cannot vouch for the
-- sign does it redo the sum exactly, as a floating-point expansion: a sum of doubles whose bits
-- do not overlap, built from TwoSum and TwoProduct (Dekker's split). The exact path allocates
-- nothing: it reuses one scratch array. Hot loops that inline cross's filter say so where they
-- do it, with the measured reason (vertexInside, separatingPush); they call cross where the
-- filter cannot decide, or, in separatingPush, lengthen the push until it can.
--
-- Exactness holds while no product overflows or underflows: every nonzero coordinate between
-- 2^-447 and 2^500 in magnitude (then all coordinates are multiples of 2^-499, all products of
-- differences multiples of 2^-998, which doubles still hold exactly). Lua 5.3+ integers are
-- converted to doubles (`+ 0.0`) before any difference or product, so they cannot wrap past
-- 2^63 and an integer beyond 2^53 counts as the double it converts to.

local EPS = 2^-53                         -- unit roundoff of a double
local SPLITTER = 134217729.0              -- 2^27 + 1, splits a double into two 26-bit halves
local CROSS_BOUND = (3 + 16 * EPS) * EPS  -- Shewchuk's ccwerrboundA for a 2x2 determinant

-- a * b as hi + lo exactly (Dekker). Needs |a|, |b| < 2^996 so the split cannot overflow.
local function twoProduct(a, b)
  local x = a * b
  local c = SPLITTER * a
  local ahi = c - (c - a)
  local alo = a - ahi
  c = SPLITTER * b
  local bhi = c - (c - b)
  local blo = b - bhi
  return x, alo * blo - (((x - ahi * bhi) - alo * bhi) - ahi * blo)
end

-- a - b as hi + lo exactly (Knuth's TwoSum on a and -b).
local function twoDiff(a, b)
  local x = a - b
  local bv = a - x
  local av = x + bv
  return x, (a - av) + (bv - b)
end

-- The scratch expansion: expansion[1..expLen], nonoverlapping, increasing in magnitude, no
-- zeros (expAdd drops them).
local expansion, expLen = {}, 0

-- Adds the double b to the expansion exactly (Shewchuk's Grow-Expansion, zeros eliminated).
local function expAdd(b)
  if b == 0 then return end
  local q, k = b, 0
  for i = 1, expLen do
    local e = expansion[i]
    local s = q + e
    local bv = s - q
    local h = (q - (s - bv)) + (e - bv)
    q = s
    if h ~= 0 then k = k + 1; expansion[k] = h end
  end
  if q ~= 0 then k = k + 1; expansion[k] = q end
  expLen = k
end

-- Adds a * b to the expansion exactly.
local function expAddProduct(a, b)
  if a == 0 or b == 0 then return end
  local hi, lo = twoProduct(a, b)
  expAdd(lo)
  expAdd(hi)
end

-- The sign of the expansion is the sign of its largest component.
local function expSign()
  if expLen == 0 then return 0 end
  return expansion[expLen] > 0 and 1 or -1
end

-- Compresses the expansion in place to an equal one with fewer components (Shewchuk's
-- Compress) and returns its largest component, which is within one ulp of the exact sum.
local function expCompress()
  if expLen == 0 then return 0.0 end
  local bottom, q = expLen, expansion[expLen]
  for i = expLen - 1, 1, -1 do
    local e = expansion[i]
    local s = q + e
    local small = e - (s - q)
    if small ~= 0 then
      expansion[bottom] = s; bottom = bottom - 1; q = small
    else
      q = s
    end
  end
  expansion[bottom] = q
  local top = 0
  for i = bottom + 1, expLen do
    local g = expansion[i]
    local s = g + q
    local small = q - (s - g)
    if small ~= 0 then top = top + 1; expansion[top] = small end
    q = s
  end
  top = top + 1; expansion[top] = q
  expLen = top
  return q
end

-- A power of two s that brings m > 0 into [lo, hi] (hi / lo >= 2^64): multiplying coordinates
-- by it is exact (short of underflow) and keeps every sign and ratio. 1 for 0, inf or NaN.
local function powerScale(m, lo, hi)
  local s = 1.0
  if m == 0 or m ~= m or m == huge then return s end
  while m * s > hi do s = s * 2^-64 end
  while m * s < lo do s = s * 2^64 end
  return s
end

-- Beyond 2^500 the exact kernels' products would overflow; coordinates that large are first
-- scaled down by a power of two (small ones among them may then lose bits to underflow, which is
-- why the guaranteed range stops at 2^500).
local EXACT_TOP = 2^500

local function exactScale(m)
  if m <= EXACT_TOP then return 1.0 end
  return powerScale(m, 2^-64 * EXACT_TOP, EXACT_TOP)
end

-- The exact sign of (u1 - u0) x (v1 - v0): each difference is split into hi + lo exactly, and the
-- sixteen partial products are summed as an expansion.
local function crossExact(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1)
  local m = abs(ux0 + 0.0)
  m = max(m, abs(uy0 + 0.0), abs(ux1 + 0.0), abs(uy1 + 0.0))
  m = max(m, abs(vx0 + 0.0), abs(vy0 + 0.0), abs(vx1 + 0.0), abs(vy1 + 0.0))
  local s = exactScale(m)
  local axh, axl = twoDiff(ux1 * s, ux0 * s)
  local ayh, ayl = twoDiff(uy1 * s, uy0 * s)
  local bxh, bxl = twoDiff(vx1 * s, vx0 * s)
  local byh, byl = twoDiff(vy1 * s, vy0 * s)
  expLen = 0
  expAddProduct(axh, byh); expAddProduct(axh, byl); expAddProduct(axl, byh); expAddProduct(axl, byl)
  expAddProduct(-ayh, bxh); expAddProduct(-ayh, bxl); expAddProduct(-ayl, bxh); expAddProduct(-ayl, bxl)
  return expSign()
end

-- A number with the sign of (u1 - u0) x (v1 - v0), exact for the given doubles: positive when
-- v turns clockwise from u on screen. orient(a, b, c) is cross(a, b, a, c).
local function cross(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1)
  local l = ((ux1 + 0.0) - ux0) * ((vy1 + 0.0) - vy0)
  local r = ((uy1 + 0.0) - uy0) * ((vx1 + 0.0) - vx0)
  local det = l - r
  local sum
  -- When l and r differ in sign (or one is zero) no cancellation can happen and det's sign is
  -- right; otherwise the filter compares det with the rounding error Shewchuk bounds.
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
  return crossExact(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1)
end

-- Twice the signed area of points[1..n] (n = #points >= 6), with what its error bound needs.
-- The x coordinates are taken relative to the first vertex so the offset of a polygon does not
-- matter: sum over edges of (X_i + X_j)(y_j - y_i) with X = x - x_1, the tutorial's trapezoid
-- form, equal to the cross-product form because the y differences around a polygon sum to zero.
-- Also returns sx = sum of X_i^2 and sd = sum of (y_j - y_i)^2, branch-free, for areaBound.
local function shoelace(points, n)
  local x0, y1 = points[1] + 0.0, points[2] + 0.0
  local px, py = 0.0, y1
  local sum, sx, sd = 0.0, 0.0, 0.0
  for i = 3, n - 1, 2 do
    local x, y = points[i] - x0, points[i + 1] + 0.0
    local d = y - py
    sum = sum + (px + x) * d
    sx, sd = sx + x * x, sd + d * d
    px, py = x, y
  end
  local d = y1 - py
  return sum + px * d, sx, sd + d * d
end

-- shoelace and the bounding box in one pass, for the collision functions: returns shoelace's
-- three sums and xmin, xmax, ymin, ymax. A NaN or infinite coordinate makes sx + sd non-finite.
local function shoelaceBounds(points, n)
  local x0, y1 = points[1] + 0.0, points[2] + 0.0
  local px, py = 0.0, y1
  local sum, sx, sd = 0.0, 0.0, 0.0
  local xmin, xmax, ymin, ymax = x0, x0, y1, y1
  for i = 3, n - 1, 2 do
    local vx, y = points[i] + 0.0, points[i + 1] + 0.0
    local x, d = vx - x0, y - py
    sum = sum + (px + x) * d
    sx, sd = sx + x * x, sd + d * d
    if vx < xmin then xmin = vx elseif vx > xmax then xmax = vx end
    if y < ymin then ymin = y elseif y > ymax then ymax = y end
    px, py = x, y
  end
  local d = y1 - py
  return sum + px * d, sx, sd + d * d, xmin, xmax, ymin, ymax
end

-- Whether shoelace's sum is too close to zero for its sign to be trusted. Each term
-- (X_i + X_j) d is off by at most 4 eps (|X_i| + |X_j|) |d| and summing m terms adds (m - 1) eps
-- times their magnitudes, so the error is below (m + 3) eps T, where by Cauchy-Schwarz
-- T = sum (|X_i| + |X_j|) |d| <= 2 sqrt(sx sd). The test compares squares against a bound four
-- times that (no square root); an overflow (an infinite or NaN sum) only sends the decision to
-- the exact path.
local function areaUncertain(m, sum, sx, sd)
  -- 2^-50 = 8 eps: (m + 8) 8 eps is four times the derived 2 (m + 3) eps, and the + 5 more
  -- than covers the rounding of this bound's own products
  local k = (m + 8) * 2^-50
  return not (sum * sum > k * k * sx * sd)   -- luacheck: ignore 581 (NaN must be uncertain)
end

-- Twice the signed area as an exact expansion in `expansion`: sum of x_i y_j - x_j y_i over all
-- edges, of the coordinates scaled by s (returned; 1 unless they pass 2^500).
local function shoelaceExact(points, n)
  local m = 0.0
  for i = 1, n do m = max(m, abs(points[i] + 0.0)) end
  local s = exactScale(m)
  expLen = 0
  -- compress when 32 components have been added: often enough that each addition walks a short
  -- expansion, rarely enough that compressing costs little next to the additions
  local limit = 32
  local xi, yi = points[n - 1] * s, points[n] * s
  for i = 1, n - 1, 2 do
    local xj, yj = points[i] * s, points[i + 1] * s
    expAddProduct(xi, yj)
    expAddProduct(-xj, yi)
    xi, yi = xj, yj
    if expLen > limit then
      expCompress()
      limit = expLen + 32
    end
  end
  return s
end

-- The exact sign of twice the signed area (> 0: clockwise on screen), given shoelace's results.
local function areaSignOf(points, n, sum, sx, sd)
  if not areaUncertain(n / 2, sum, sx, sd) then return sum end
  shoelaceExact(points, n)
  return expSign()
end

local function areaSign(points, n)
  return areaSignOf(points, n, shoelace(points, n))
end

--------------------------------------------------------------------------------------------------
-- Argument checks: O(1), raised at the caller's level
--------------------------------------------------------------------------------------------------

-- level: where the error points, counted from checkPoints (3: the caller of a public function).
local function checkPoints(points, fname, argname, level)
  if type(points) ~= "table" then
    error(("%s: %s must be a table, got %s"):format(fname, argname or "points", type(points)),
      level or 3)
  end
  local n = #points
  if n % 2 ~= 0 then
    error(("%s: %s must hold an even number of coordinates, got %d")
      :format(fname, argname or "points", n), level or 3)
  end
  return n
end

local function checkNumber(v, fname, argname, level)
  if type(v) ~= "number" then
    error(("%s: %s must be a number, got %s"):format(fname, argname, type(v)), level or 3)
  end
end

--------------------------------------------------------------------------------------------------
-- Measures: winding, area, type, centre
--------------------------------------------------------------------------------------------------

--- The winding order as seen on screen (y down).
-- @param points flat array {x1, y1, ...}
-- @return "cw" or "ccw"; nil for fewer than 3 points or zero signed area. Exact.
function polygon.polygonWindingOrder(points)
  local n = checkPoints(points, "polygonWindingOrder")
  if n < 6 then return nil end
  local s, sx, sd = shoelace(points, n)
  if areaUncertain(n / 2, s, sx, sd) then
    shoelaceExact(points, n)
    s = expSign()
  end
  if s > 0 then return "cw" elseif s < 0 then return "ccw" end
  return nil
end

--- The area (non-negative) by the shoelace formula, relative to the first vertex.
-- @return area; nil for fewer than 3 points. Off by a few ulps for ordinary polygons at any
-- offset; a self-intersecting polygon's lobes count with their winding's sign.
function polygon.polygonArea(points)
  local n = checkPoints(points, "polygonArea")
  if n < 6 then return nil end
  -- shoelace's sum alone: the loop without the error bound's sums is the cost of the naive one
  local x0, y1 = points[1] + 0.0, points[2] + 0.0
  local px, py, sum = 0.0, y1, 0.0
  for i = 3, n - 1, 2 do
    local x, y = points[i] - x0, points[i + 1] + 0.0
    sum = sum + (px + x) * (y - py)
    px, py = x, y
  end
  sum = sum + px * (y1 - py)
  if sum ~= sum then   -- terms overflowed to infinities of both signs: take the exact area
    local s = shoelaceExact(points, n)
    sum = expCompress() / s / s
  end
  return (sum < 0 and -sum or sum) * 0.5
end

--- The exact area of the given doubles, rounded to within one ulp.
-- @return area; nil for fewer than 3 points. Costs an expansion sum: several times polygonArea.
function polygon.polygonAreaAccurate(points)
  local n = checkPoints(points, "polygonAreaAccurate")
  if n < 6 then return nil end
  local s = shoelaceExact(points, n)
  return abs(expCompress()) * 0.5 / s / s
end

--- Whether the polygon is convex.
-- Checks every vertex (the tutorial skips the last one). Repeated consecutive vertices and
-- collinear vertices that go on forward are allowed; a zero turn that doubles back (a spike) is
-- concave, and so is a polygon whose turns all agree but which winds around more than once
-- (a pentagram): its edges' x directions change sign more than twice.
-- @return "convex", "concave", or nil for fewer than 3 points or all points on one line. Exact.
function polygon.polygonType(points)
  local n = checkPoints(points, "polygonType")
  if n < 6 then return nil end
  -- Walk the turns at every vertex, starting at the last one: the previous vertex is the last
  -- one before it that differs from it, and a next vertex equal to the current one is skipped.
  local cx, cy = points[n - 1] + 0.0, points[n] + 0.0
  local j = n - 3
  while j > 0 and points[j] == cx and points[j + 1] == cy do j = j - 2 end
  if j < 0 then return nil end   -- all points are one point
  local px, py = points[j] + 0.0, points[j + 1] + 0.0
  local turn, spike = 0, false
  local flips, dir = 0, 0
  for i = 1, n - 1, 2 do
    local qx, qy = points[i] + 0.0, points[i + 1] + 0.0
    if qx ~= cx or qy ~= cy then
      -- cross(p, c, c, q) with its filter written out, as the per-vertex call would cost the
      -- PUC interpreters half the loop: when l and r differ in sign |l + r| <= |l - r| always
      -- passes; when they agree |l + r| = |l| + |r|, Shewchuk's bound.
      local l = (cx - px) * (qy - cy)
      local r = (cy - py) * (qx - cx)
      local s, e = l - r, l + r
      if e < 0 then e = -e end
      e = CROSS_BOUND * e
      if not (s >= e or -s >= e) then s = crossExact(px, py, cx, cy, cx, cy, qx, qy) end
      if s > 0 then
        if turn < 0 then return "concave" end
        turn = 1
      elseif s < 0 then
        if turn > 0 then return "concave" end
        turn = -1
      elseif cx ~= px then   -- collinear: a spike if the walk reverses (x decides on a line...
        if (cx > px) ~= (qx > cx) then spike = true end
      elseif (cy > py) ~= (qy > cy) then   -- ...unless the line is vertical)
        spike = true
      end
      -- Count the changes of sign of the edges' x direction: around a convex polygon there are
      -- two. Counted along the walk they are one fewer when the first and last edges differ,
      -- and the count around the cycle is even, so more than two along the walk means more
      -- than two around.
      if qx > cx then
        if dir < 0 then flips = flips + 1 end
        dir = 1
      elseif qx < cx then
        if dir > 0 then flips = flips + 1 end
        dir = -1
      end
      px, py, cx, cy = cx, cy, qx, qy
    end
  end
  if turn == 0 then return nil end   -- no turn at all: every point on one line
  if spike or flips > 2 then return "concave" end
  return "convex"
end

--- The centre as the tutorial defines it: the mean of the vertices.
-- @return cx, cy; nil for fewer than 3 points.
function polygon.polygonCenter(points)
  local n = checkPoints(points, "polygonCenter")
  if n < 6 then return nil end
  -- Compensated sums (TwoSum carries each addition's rounding error into ex, ey), so the mean is
  -- within an ulp or two of exact wherever the polygon is and whatever its size.
  local sx, sy, ex, ey = 0.0, 0.0, 0.0, 0.0
  for i = 1, n - 1, 2 do
    local x, y = points[i] + 0.0, points[i + 1] + 0.0
    local t = sx + x
    local v = t - sx
    ex = ex + ((sx - (t - v)) + (x - v))
    sx = t
    t = sy + y
    v = t - sy
    ey = ey + ((sy - (t - v)) + (y - v))
    sy = t
  end
  local m = n / 2
  return (sx + ex) / m, (sy + ey) / m
end

--- The area centroid, the point a physics step rotates a uniform polygon about.
-- @return cx, cy; nil for fewer than 3 points or zero (exact) signed area.
function polygon.polygonCentroid(points)
  local n = checkPoints(points, "polygonCentroid")
  if n < 6 then return nil end
  if areaSign(points, n) == 0 then return nil end
  local x0, y0 = points[1] + 0.0, points[2] + 0.0
  -- The sums below are cubic in the coordinates (relative to vertex 1): scale x and y each by a
  -- power of two to near 1 so that they neither overflow nor underflow, and scale back at the
  -- end (x by kx: the area scales by kx ky, the x moment by kx^2 ky).
  local mx, my = 0.0, 0.0
  for i = 3, n - 1, 2 do
    mx, my = max(mx, abs(points[i] - x0)), max(my, abs(points[i + 1] - y0))
  end
  local kx, ky = powerScale(mx, 2^-32, 2^32), powerScale(my, 2^-32, 2^32)
  local a2, sx, sy = 0.0, 0.0, 0.0
  -- relative to vertex 1, the edges from and to it add nothing: start at edge 2 -> 3
  local xi, yi = 0.0, 0.0
  for i = 3, n - 1, 2 do
    local xj, yj = (points[i] - x0) * kx, (points[i + 1] - y0) * ky
    local c = xi * yj - xj * yi
    a2 = a2 + c
    sx = sx + (xi + xj) * c
    sy = sy + (yi + yj) * c
    xi, yi = xj, yj
  end
  if a2 == 0 then   -- the rounded sum lost everything: take the exact area, scaled by kx ky
    local s = shoelaceExact(points, n)   -- the expansion holds it scaled by s^2
    a2 = expCompress() * (kx / s) * (ky / s)
  end
  local cx, cy = x0 + sx / (3 * a2) / kx, y0 + sy / (3 * a2) / ky
  if cx ~= cx or cy ~= cy then
    -- Only outside the exact range: a sliver far thinner than it is long, or coordinates of
    -- magnitudes too far apart for one scale each. Its vertex mean is finite and nearby.
    cx, cy = polygon.polygonCenter(points)
  end
  return cx, cy
end

--------------------------------------------------------------------------------------------------
-- Point in polygon
--------------------------------------------------------------------------------------------------

-- W. R. Franklin's crossing rule, as in the tutorial: count the edges crossed by the ray from
-- (x, y) to the right. An edge counts when (y1 >= y) ~= (y2 >= y) and x <= the edge's x at height
-- y. That half-open rule puts a point on an edge shared by two polygons in exactly one of them.
-- The tutorial divides to find the edge's x; here the comparison is the exact side test
-- x <= x'  <=>  (p2 - p1) x (q - p1) >= 0 when the edge goes down (y2 > y1), <= 0 when it goes up.
local function contains(points, n, x, y)
  local inside = false
  local x1, y1 = points[n - 1], points[n]
  for i = 1, n - 1, 2 do
    local x2, y2 = points[i], points[i + 1]
    if (y1 >= y) ~= (y2 >= y) then
      if x <= x1 and x <= x2 then
        inside = not inside
      elseif x <= x1 or x <= x2 then
        local s = cross(x1, y1, x2, y2, x1, y1, x, y)
        if y2 > y1 then
          if s >= 0 then inside = not inside end
        elseif s <= 0 then
          inside = not inside
        end
      end
    end
    x1, y1 = x2, y2
  end
  return inside
end

-- contains with the argument checks of polygonContains and Polygon:contains, whose callers'
-- lines the errors point at (level 4).
local function checkedContains(fname, points, x, y)
  local n = checkPoints(points, fname, "points", 4)
  checkNumber(x, fname, "x", 4)
  checkNumber(y, fname, "y", 4)
  if n < 6 then return false end
  return contains(points, n, x, y)
end

--- Whether (x, y) lies inside the polygon, by the crossing rule with the tutorial's half-open
-- boundary. Works for concave and self-intersecting polygons (even-odd). Exact.
-- @return true or false; false for fewer than 3 points.
function polygon.polygonContains(points, x, y)
  local inside = checkedContains("polygonContains", points, x, y)
  return inside   -- not a tail call: the argument errors point at the caller's line
end

--------------------------------------------------------------------------------------------------
-- Projection and the separating axis theorem
--------------------------------------------------------------------------------------------------

--- The range of the polygon projected on the axis (nx, ny), relative to the point (x, y).
-- @return min, max of (px - x) * nx + (py - y) * ny over the vertices; nil for no points.
function polygon.projectPolygon(points, x, y, nx, ny)
  local n = checkPoints(points, "projectPolygon")
  checkNumber(x, "projectPolygon", "x")
  checkNumber(y, "projectPolygon", "y")
  checkNumber(nx, "projectPolygon", "nx")
  checkNumber(ny, "projectPolygon", "ny")
  if n < 2 then return nil end
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
-- them plain comparisons are faster. The two bodies compute the same numbers.
local projectRange, minProjection
if rawget(_G, "jit") then
  projectRange = function(points, n, ax, ay, nx, ny)
    local lo, hi = huge, -huge
    for i = 1, n - 1, 2 do
      local s = nx * (points[i] - ax) + ny * (points[i + 1] - ay)
      lo, hi = min(lo, s), max(hi, s)
    end
    return lo, hi
  end
  minProjection = function(points, n, ax, ay, nx, ny)
    local lo = huge
    for i = 1, n - 1, 2 do lo = min(lo, nx * (points[i] - ax) + ny * (points[i + 1] - ay)) end
    return lo
  end
else
  projectRange = function(points, n, ax, ay, nx, ny)
    local lo, hi = huge, -huge
    for i = 1, n - 1, 2 do
      local s = nx * (points[i] - ax) + ny * (points[i + 1] - ay)
      if s < lo then lo = s end
      if s > hi then hi = s end
    end
    return lo, hi
  end
  minProjection = function(points, n, ax, ay, nx, ny)
    local lo = huge
    for i = 1, n - 1, 2 do
      local s = nx * (points[i] - ax) + ny * (points[i + 1] - ay)
      if s < lo then lo = s end
    end
    return lo
  end
end

-- The least projection nx (vx - ax) + ny (vy - ay) over the vertices of a convex polygon, with
-- the index of a vertex where it is found, for the edges of another convex polygon in turn.
-- Rotating calipers: as the edges' outward normals turn, the deepest vertex moves on around
-- `points`, `step` (2 or -2) at a time; so the first edge (deepest == 0) scans every vertex and
-- each next one walks on from the last deepest vertex while the projection does not rise. A walk
-- stopped early by rounding misses the least by less than the projections' tolerance, and
-- the SAT engine decides every depth within that of zero again over all vertices, exactly.
-- On LuaJIT the walk's data-dependent exits become side traces that cost more than they save
-- (measured: compiling them took most of the time of a mixed collision workload), so there the
-- scan is whole, branch-free, every time.
local deepestPast
if rawget(_G, "jit") then
  deepestPast = function(points, n, ax, ay, nx, ny, deepest)
    return deepest, minProjection(points, n, ax, ay, nx, ny)
  end
else
  deepestPast = function(points, n, ax, ay, nx, ny, deepest, step)
    local lo
    if deepest == 0 then
      deepest, lo = 1, nx * (points[1] - ax) + ny * (points[2] - ay)
      for i = 3, n - 1, 2 do
        local s = nx * (points[i] - ax) + ny * (points[i + 1] - ay)
        if s < lo then deepest, lo = i, s end
      end
      return deepest, lo
    end
    lo = nx * (points[deepest] - ax) + ny * (points[deepest + 1] - ay)
    for _ = 3, n, 2 do   -- at most m - 1 steps around a polygon of m vertices
      local k = deepest + step
      if k > n then k = 1 elseif k < 1 then k = n - 1 end
      local s = nx * (points[k] - ax) + ny * (points[k + 1] - ay)
      if s > lo then break end
      deepest, lo = k, s
    end
    return deepest, lo
  end
end

-- The projections above are taken relative to a vertex a of one polygon so that far from the
-- origin they stay as accurate as near it. Their rounding error is at most
-- 4 eps (spanX |nx| + spanY |ny|), where spanX and spanY bound every |vx - ax| and |vy - ay|;
-- a gap within four times that (16 eps: the bound of two projections subtracted, doubled for
-- the rounding of the bound itself) is decided again exactly, with the cross kernel.
local function projectionTolerance(spanX, spanY, nx, ny)
  return 16 * EPS * (spanX * abs(nx) + spanY * abs(ny))
end

-- shared helper: lead moves it to the kernels
-- Whether points[1..n] holds a NaN or an infinity. Called only where a sum came out non-finite.
local function holdsNonFinite(points, n)
  for i = 1, n do
    local v = points[i] + 0.0
    if v ~= v or v == huge or v == -huge then return true end
  end
  return false
end

-- shared helper: lead moves it to the kernels
-- The largest coordinate magnitude of points[1..n], or m if that is larger.
local function largestMagnitude(points, n, m)
  for i = 1, n do
    local v = points[i] + 0.0
    if v < 0 then v = -v end
    if v > m then m = v end
  end
  return m
end

-- The SAT engine's one exact fallback: the index of a vertex of points that, moved by (dx, dy)
-- and rounded as a caller's `p[i] + dx` rounds, lies strictly on the side `inside` (1 or -1, the
-- sign of the cross product) of the line through c parallel to a -> b; false when none does.
-- The sign is multiplied by the sign +-1, never by an area, so nothing underflows.
local function vertexInside(ax, ay, bx, by, cx, cy, inside, points, n, dx, dy)
  local ex, ey = (bx + 0.0) - ax, (by + 0.0) - ay
  for i = 1, n - 1, 2 do
    local px, py = points[i] + dx, points[i + 1] + dy
    -- cross's filter inlined (a call per vertex is most of this loop's time on PUC Lua): the
    -- vertex is certainly not inside when -inside det >= bound, certainly inside when
    -- inside det >= bound; only between does cross decide, exactly
    local l, r = ex * (py - cy), ey * (px - cx)
    local det = (l - r) * inside
    local bound = CROSS_BOUND * ((l < 0 and -l or l) + (r < 0 and -r or r))
    if -det < bound and (det >= bound and det > 0 or
                         cross(ax, ay, bx, by, cx, cy, px, py) * inside > 0) then
      return i
    end
  end
  return false
end

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
-- spanX, spanY: see projectionTolerance.
local function reachPast(edges, ne, turn, other, no, turnOther, spanX, spanY)
  local leastSquared, leastOverlap, leastEnd = huge, 0.0, 1
  -- the calipers' state for deepestPast: the last deepest vertex of other (0: none yet) and the
  -- way it moves as the normals turn: forward if other winds like edges
  local deepest, step = 0, turnOther == turn and 2 or -2
  local ax, ay = edges[ne - 1] + 0.0, edges[ne] + 0.0
  for ib = 1, ne - 1, 2 do
    local bx, by = edges[ib] + 0.0, edges[ib + 1] + 0.0
    if bx ~= ax or by ~= ay then   -- a repeated vertex gives no axis
      local nx, ny = (by - ay) * turn, (ax - bx) * turn   -- outward
      local lo
      deepest, lo = deepestPast(other, no, ax, ay, nx, ny, deepest, step)
      local depth = -lo
      -- projectionTolerance, inlined (math.abs and the call cost PUC Lua a third of this loop)
      local tol = 16 * EPS * (spanX * (nx < 0 and -nx or nx) + spanY * (ny < 0 and -ny or ny))
      if depth <= tol then
        if depth < -tol or not vertexInside(ax, ay, bx, by, ax, ay, turn, other, no, 0.0, 0.0) then
          return false
        end
        if depth < 0 then depth = 0.0 end
      end
      local squaredDepth = depth * (depth / (nx * nx + ny * ny))
      if squaredDepth < leastSquared then   -- keep the least
        leastSquared, leastOverlap, leastEnd = squaredDepth, depth, ib
      end
    end
    ax, ay = bx, by
  end
  return leastSquared, leastOverlap, leastEnd
end

-- reachPast for the one-sided functions, which test the axes of `edges` only: both ends of each
-- range, so also how far `other` reaches beyond the vertex of `edges` deepest inside, along -n.
-- Returns false, or the squared depth, o, the edge's end and, for the far end, the index of
-- that deepest vertex
-- (else false).
local function reachPastBothEnds(edges, ne, turn, other, no, spanX, spanY)
  local leastSquared, leastOverlap, leastEnd, leastFar = huge, 0.0, 1, false
  local ax, ay = edges[ne - 1] + 0.0, edges[ne] + 0.0
  for ib = 1, ne - 1, 2 do
    local bx, by = edges[ib] + 0.0, edges[ib + 1] + 0.0
    if bx ~= ax or by ~= ay then   -- a repeated vertex gives no axis
      local nx, ny = (by - ay) * turn, (ax - bx) * turn   -- outward
      local tol = projectionTolerance(spanX, spanY, nx, ny)
      local lo, hi = projectRange(other, no, ax, ay, nx, ny)
      -- face: how far other must move along n to clear the edge; far: against n, past the
      -- deepest vertex of edges
      local face, far = -lo, hi - minProjection(edges, ne, ax, ay, nx, ny)
      if face <= tol then
        if face < -tol or not vertexInside(ax, ay, bx, by, ax, ay, turn, other, no, 0.0, 0.0) then
          return false
        end
        if face < 0 then face = 0.0 end
      end
      local ic = false
      if far <= tol then
        ic = deepestVertex(ax, ay, bx, by, turn, edges, ne)
        if far < -tol or not vertexInside(ax, ay, bx, by, edges[ic], edges[ic + 1], -turn,
                                          other, no, 0.0, 0.0) then
          return false
        end
        if far < 0 then far = 0.0 end
      end
      local depth = face < far and face or far
      local squaredDepth = depth * (depth / (nx * nx + ny * ny))
      if squaredDepth < leastSquared then   -- keep the least
        if far < face then
          leastFar = ic or deepestVertex(ax, ay, bx, by, turn, edges, ne)
        else
          leastFar = false
        end
        leastSquared, leastOverlap, leastEnd = squaredDepth, depth, ib
      end
    end
    ax, ay = bx, by
  end
  return leastSquared, leastOverlap, leastEnd, leastFar
end

-- The unit vector along (nx, ny) and the length of (nx, ny), scaled first by the larger
-- component so that neither squaring overflows nor underflows. (nx, ny) must not be (0, 0).
local function unit(nx, ny)
  local m = abs(nx) > abs(ny) and abs(nx) or abs(ny)
  nx, ny = nx / m, ny / m
  local len = sqrt(nx * nx + ny * ny)
  return nx / len, ny / len, len * m
end

-- Below 2^464 the products of two coordinate differences (each below 2^466 after scaling)
-- cannot overflow; from 2^400 up the scaled copies keep 64 binades of headroom below it.
local RESCALE_LOW, RESCALE_HIGH = 2^400, 2^464

--- THE SAT ENGINE. convexPenetration(p1, n1, p2, n2, both) decides exactly whether the
-- convex polygons p1[1..n1] and p2[1..n2] (flat arrays, either winding) overlap: touching is not
-- overlapping; fewer than 3 points or zero area never overlaps. both: the axes of both
-- polygons (polygonsCollide); false: the axes of p1 only, both ends of each range
-- (polygonCollidesWith). Allocates nothing (except on the rare path beyond 2^500); rescaled
-- is for that path only (callers leave it nil). Call separatingPush (or convexPush) for a push.
-- Returns
--   false                                  no overlap (exact);
--   nil, "points1" or "points2"            that polygon holds a NaN or infinite coordinate;
--   depth, ux, uy, owner, edgeEnd, base, inside
--     the least penetration: depth >= 0 (accurate to rounding) along the unit vector (ux, uy)
--     that p2 must move, and the line the move must clear, for separatingPush: in polygon
--     `owner` (1 or 2), the edge ending at vertex index edgeEnd moved to pass through vertex
--     index base, with `inside` the cross product's sign on the side the other must leave.
local function convexPenetration(p1, n1, p2, n2, both, rescaled)
  if n1 < 6 or n2 < 6 then return false end
  local area1, sx1, sd1, xmin1, xmax1, ymin1, ymax1 = shoelaceBounds(p1, n1)
  local area2, sx2, sd2, xmin2, xmax2, ymin2, ymax2 = shoelaceBounds(p2, n2)
  -- a NaN or infinity makes these sums non-finite; so does overflow, which is not an error
  -- luacheck: ignore 581 (NaN must count as non-finite)
  if not (sx1 + sd1 < huge) and holdsNonFinite(p1, n1) then return nil, "points1" end
  -- luacheck: ignore 581 (NaN must count as non-finite)
  if not (sx2 + sd2 < huge) and holdsNonFinite(p2, n2) then return nil, "points2" end
  -- boxes apart or touching: so are the polygons (the one-sided test may still see overlap)
  if both and (xmax1 <= xmin2 or xmax2 <= xmin1 or ymax1 <= ymin2 or ymax2 <= ymin1) then
    return false
  end
  -- zero area never collides: the turn is the sign of the area, decided exactly
  local turn1 = areaSignOf(p1, n1, area1, sx1, sd1)
  if turn1 == 0 then return false end
  local turn2 = areaSignOf(p2, n2, area2, sx2, sd2)
  if turn2 == 0 then return false end
  turn1, turn2 = turn1 > 0 and 1.0 or -1.0, turn2 > 0 and 1.0 or -1.0   -- signs, not magnitudes
  -- Sizes bounding every |vx - ax| and |vy - ay| in the projections: the box around both
  local spanX = (xmax1 > xmax2 and xmax1 or xmax2) - (xmin1 < xmin2 and xmin1 or xmin2)
  local spanY = (ymax1 > ymax2 and ymax1 or ymax2) - (ymin1 < ymin2 and ymin1 or ymin2)
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
    squaredDepth, o, edgeEnd = reachPast(p1, n1, turn1, p2, n2, turn2, spanX, spanY)
    if not squaredDepth then return false end
    local squaredDepth2, o2, edgeEnd2 = reachPast(p2, n2, turn2, p1, n1, turn1, spanX, spanY)
    if not squaredDepth2 then return false end
    owner, turn, lines, nl = 1, turn1, p1, n1
    if squaredDepth2 < squaredDepth then   -- keep the least penetration
      squaredDepth, o, edgeEnd, owner, turn, lines, nl =
        squaredDepth2, o2, edgeEnd2, 2, turn2, p2, n2
    end
  else
    squaredDepth, o, edgeEnd, far = reachPastBothEnds(p1, n1, turn1, p2, n2, spanX, spanY)
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
  elseif far then
    nx, ny, base, inside = -nx, -ny, far, -turn
  end
  local ux, uy, len = unit(nx, ny)
  return o / len, ux, uy, owner, edgeEnd, base, inside
end

-- separatingPush's check of one push, cross's filter inlined (a call per vertex is most of
-- the loop's time on PUC Lua): the largest det + bound over the vertices p of points moved by
-- (dx, dy), where det is (b - a) x (p - q) turned to be > 0 on the side `inside` and bound is
-- cross's error bound. No vertex is inside when it is 0. The bound grows with |p - q|, so each
-- vertex is tried from a second point qb of the line too (the edge's other end; q itself when
-- the line has no second vertex), and the better of the two kept. On LuaJIT, branch-free (with
-- branches its side traces aborted, "register coalescing too complex", on every push).
local lineShortfall
if rawget(_G, "jit") then
  lineShortfall = function(ex, ey, qx, qy, qbx, qby, inside, points, n, dx, dy)
    local worst = 0.0
    for i = 1, n - 1, 2 do
      local px, py = points[i] + dx, points[i + 1] + dy
      local l, r = ex * (py - qy), ey * (px - qx)
      local lb, rb = ex * (py - qby), ey * (px - qbx)
      worst = max(worst, min((l - r) * inside + CROSS_BOUND * (abs(l) + abs(r)),
        (lb - rb) * inside + CROSS_BOUND * (abs(lb) + abs(rb))))
    end
    return worst
  end
else
  lineShortfall = function(ex, ey, qx, qy, qbx, qby, inside, points, n, dx, dy)
    local worst = 0.0
    for i = 1, n - 1, 2 do
      local px, py = points[i] + dx, points[i + 1] + dy
      local l, r = ex * (py - qy), ey * (px - qx)
      local reach = (l - r) * inside + CROSS_BOUND * ((l < 0 and -l or l) + (r < 0 and -r or r))
      if reach > worst then
        l, r = ex * (py - qby), ey * (px - qbx)
        local fromB = (l - r) * inside + CROSS_BOUND * ((l < 0 and -l or l) + (r < 0 and -r or r))
        if fromB < reach then reach = fromB end
        if reach > worst then worst = reach end
      end
    end
    return worst
  end
end

-- How many times separatingPush may lengthen a push before it gives up: the rounding allowance
-- doubles each round, and 64 doublings of eps |x| outgrow any coordinate.
local PUSH_ROUNDS = 64

--- The push that separates, from convexPenetration's least penetration: a push of length >=
-- depth along (ux, uy) after which, with p2's coordinates moved by (dx, dy) and rounded the way
-- a game moves them (p[i] = p[i] + dx), the chosen line separates the polygons for sure. A
-- rounded move falls short of the exact depth by the rounding of the moved coordinates (eps
-- times their magnitude, along the push) and of the depth itself, so the push is checked on the
-- rounded coordinates: every vertex that must have left must lie on the far side of the line
-- or on it, which cross's filter proves (the same sign the exact kernel would find: touching
-- counts as apart). A vertex the filter cannot place lengthens the push by its shortfall plus
-- the bound and the rounding allowance at it, and the check runs again. Deciding such vertices
-- exactly instead would cost an expansion at nearly every push: its vertex ends on the line.
-- Returns push length, dx, dy.
local function separatingPush(p1, n1, p2, n2, depth, ux, uy, owner, edgeEnd, base, inside)
  if ux == 0 and uy == 0 then return 0.0, 0.0, 0.0 end   -- no axis: see convexPenetration
  local lines, nl, others, no, lineMoves = p1, n1, p2, n2, 0.0
  if owner == 2 then lines, nl, others, no, lineMoves = p2, n2, p1, n1, 1.0 end
  local ia = edgeEnd == 1 and nl - 1 or edgeEnd - 2
  local ax, ay, bx, by = lines[ia] + 0.0, lines[ia + 1] + 0.0, lines[edgeEnd] + 0.0,
    lines[edgeEnd + 1] + 0.0
  local cx, cy = lines[base] + 0.0, lines[base + 1] + 0.0
  local face = base == ia   -- the line is the edge, through a and b
  local ulx, uly = abs(ux), abs(uy)
  -- a moved vertex rounds by up to eps |x| against the push, |x| about the line's: the
  -- allowance for it, none on the first check, then that, doubling every further round
  local allowance = 0.0
  local push = depth   -- first as it is: an exact move along an axis keeps it exact
  for _ = 1, PUSH_ROUNDS do
    local dx, dy = ux * push + 0.0, uy * push + 0.0   -- + 0.0 turns -0 into 0
    -- the polygon that moves is p2: its line when owner is 2, else its vertices
    local lx, ly = dx * lineMoves, dy * lineMoves
    local vx, vy = dx - lx, dy - ly
    local qx, qy = cx + lx, cy + ly
    local qbx, qby = bx + lx, by + ly   -- the line's other point, when it is the edge
    local ex, ey = qbx - (ax + lx), qby - (ay + ly)
    local worst
    if face then
      worst = lineShortfall(ex, ey, qx, qy, qbx, qby, inside, others, no, vx, vy)
    else
      worst = lineShortfall(ex, ey, qx, qy, qx, qy, inside, others, no, vx, vy)
    end
    if worst == 0 then return push, dx, dy end
    -- lengthen by the shortfall and the rounding allowance at the line (where the vertex that
    -- fell short lies, to within the polygons' size), doubled every round
    allowance = allowance == 0 and EPS * (abs(qx) * ulx + abs(qy) * uly) or 2 * allowance
    push = push + worst / sqrt(ex * ex + ey * ey) + allowance
    -- only far outside the exact range can the check's products overflow: keep the depth
    if not (push < huge) then break end   -- luacheck: ignore 581 (NaN too)
  end
  return depth, ux * depth + 0.0, uy * depth + 0.0
end

--- convexPush(p1, n1, p2, n2, both): convexPenetration, then separatingPush. Returns false, or
-- nil and the argument name for a non-finite coordinate, or push length, dx, dy: adding (dx, dy)
-- to every vertex of p2 leaves the polygons touching or apart, exactly.
local function convexPush(p1, n1, p2, n2, both)
  local depth, ux, uy, owner, edgeEnd, base, inside = convexPenetration(p1, n1, p2, n2, both)
  if not depth then return depth, ux end
  return separatingPush(p1, n1, p2, n2, depth, ux, uy, owner, edgeEnd, base, inside)
end

-- Raises the error for a non-finite coordinate at the caller of the public function, which
-- called the private function that calls this one.
local function raiseNonFinite(fname, argname)
  error(("%s: %s holds a non-finite coordinate"):format(fname, argname), 4)
end

local function collides(fname, points1, points2, both)
  local n1 = checkPoints(points1, fname, "points1", 4)
  local n2 = checkPoints(points2, fname, "points2", 4)
  local depth, argname = convexPenetration(points1, n1, points2, n2, both)
  if depth == nil then raiseNonFinite(fname, argname) end
  return depth ~= false
end

--- Whether the edge normals of points1 show no separating axis between two convex polygons.
-- Touching is not colliding; fewer than 3 points or zero area never collides. Exact.
-- Raises an error for a non-finite coordinate.
-- @return true or false
function polygon.polygonCollidesWith(points1, points2)
  local collided = collides("polygonCollidesWith", points1, points2, false)
  return collided
end

--- Whether two convex polygons (either winding) overlap, by the separating axis theorem.
-- Touching is not colliding; fewer than 3 points or zero area never collides. Exact.
-- Raises an error for a non-finite coordinate.
-- @return true or false
function polygon.polygonsCollide(points1, points2)
  local collided = collides("polygonsCollide", points1, points2, true)
  return collided
end

local function pushOut(fname, points1, points2, both)
  local n1 = checkPoints(points1, fname, "points1", 4)
  local n2 = checkPoints(points2, fname, "points2", 4)
  local push, dx, dy = convexPush(points1, n1, points2, n2, both)
  if push == nil then raiseNonFinite(fname, dx) end
  return push, dx, dy
end

--- As polygonCollidesWith, with the minimum translation vector over the axes of points1.
-- @return overlap, dx, dy or false: after adding (dx, dy) to every vertex of points2,
-- polygonCollidesWith(points1, moved) is false (see polygonsCollideV)
function polygon.polygonCollidesWithV(points1, points2)
  local push, dx, dy = pushOut("polygonCollidesWithV", points1, points2, false)
  return push, dx, dy
end

--- As polygonsCollide, with the minimum translation vector.
-- overlap is the penetration depth along the axis of least penetration, right also when one
-- polygon contains the other; (dx, dy) moves points2 out of points1 (add it to every vertex of
-- points2), pointing the right way in either argument order and when the centres coincide.
-- One push separates: after p[i] = p[i] + dx (and + dy) on points2, rounded,
-- polygonsCollide(points1, moved) is false, and the push is at most a few ulps of the
-- coordinates longer than the exact depth. Raises an error for a non-finite coordinate.
-- @return overlap, dx, dy or false
function polygon.polygonsCollideV(points1, points2)
  local push, dx, dy = pushOut("polygonsCollideV", points1, points2, true)
  return push, dx, dy
end

--------------------------------------------------------------------------------------------------
-- Circles
--------------------------------------------------------------------------------------------------

--- The range of a circle projected on the axis (nx, ny) (unit length), relative to (x, y).
-- @return min, max
function polygon.projectCircle(cx, cy, radius, x, y, nx, ny)
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

--- The minimum translation vector of a circle out of a convex polygon.
-- The axes are the edge normals and the axis from the vertex nearest the centre (by distance;
-- the tutorial compares dot products) to the centre. The depth is the full penetration, so a
-- circle deep inside is pushed out in one step. Touching is not colliding, and since a unit
-- normal cannot be exact, neither is an overlap below the rounding error of the projections
-- (8 eps times the sizes involved): a circle moved by the returned vector no longer collides.
-- @return overlap, dx, dy (move the circle by dx, dy) or false
function polygon.polygonCircleCollideV(points, cx, cy, radius)
  local fname = "polygonCircleCollideV"
  local n = checkPoints(points, fname)
  checkNumber(cx, fname, "cx")
  checkNumber(cy, fname, "cy")
  checkNumber(radius, fname, "radius")
  if radius < 0 then error(("%s: radius must not be negative, got %s"):format(fname, radius), 2) end
  if n < 6 then return false end
  local turn = areaSign(points, n)
  if turn == 0 then return false end
  local sign = turn > 0 and 1.0 or -1.0   -- makes (by - ay, ax - bx) point outwards
  cx, cy = cx + 0.0, cy + 0.0
  -- The projections' rounding error is a few eps times the polygon's extent plus the centre's
  -- distance from it plus the radius; an overlap below 8 eps times that counts as touching.
  local xmin, xmax, ymin, ymax = huge, -huge, huge, -huge
  for i = 1, n - 1, 2 do
    local x, y = points[i] + 0.0, points[i + 1] + 0.0
    if x < xmin then xmin = x end
    if x > xmax then xmax = x end
    if y < ymin then ymin = y end
    if y > ymax then ymax = y end
  end
  local reach = max(abs(cx - xmin), abs(cx - xmax)) + max(abs(cy - ymin), abs(cy - ymax))
  local tol = 8 * EPS * ((xmax - xmin) + (ymax - ymin) + reach + radius)
  local best, bux, buy = huge, 0.0, 0.0
  local nearX, nearY, nearD = 0.0, 0.0, huge
  -- On an edge's outward normal a convex polygon spans [-width, 0]: its edge is the near end.
  -- The vertex at the far end moves forward around the polygon as the edges do (rotating
  -- calipers), so each edge walks on from the previous one's far vertex instead of projecting
  -- every vertex. The walk goes on through steps within the rounding and stops at the first
  -- certain rise, past which a convex polygon's projections only rise.
  local far = 0   -- index of the far vertex, 0 until the first edge has scanned them all
  local ax, ay = points[n - 1] + 0.0, points[n] + 0.0
  for i = 1, n - 1, 2 do
    local bx, by = points[i] + 0.0, points[i + 1] + 0.0
    local d = (bx - cx) * (bx - cx) + (by - cy) * (by - cy)
    if d < nearD then nearX, nearY, nearD = bx, by, d end
    if bx ~= ax or by ~= ay then
      local nx, ny = unit((by - ay) * sign, (ax - bx) * sign)
      local lo
      if far == 0 then
        lo = huge
        for j = 1, n - 1, 2 do
          local s = nx * (points[j] - ax) + ny * (points[j + 1] - ay)
          if s < lo then lo, far = s, j end
        end
      else
        lo = nx * (points[far] - ax) + ny * (points[far + 1] - ay)
        local j = far
        for _ = 1, n / 2 do
          j = j + 2
          if j > n then j = 1 end
          local s = nx * (points[j] - ax) + ny * (points[j + 1] - ay)
          if s > lo + tol then break end
          if s < lo then lo, far = s, j end
        end
      end
      local s = nx * (cx - ax) + ny * (cy - ay)
      local up, down = radius - s, (s + radius) - lo
      if up <= tol or down <= tol then return false end
      if up < best then best, bux, buy = up, nx, ny end
      if down < best then best, bux, buy = down, -nx, -ny end
    end
    ax, ay = bx, by
  end
  if nearD > 0 then
    -- the axis from the nearest vertex to the centre, where the centre projects at |c - v|
    local nx, ny, len = unit(cx - nearX, cy - nearY)
    local min1, max1 = projectRange(points, n, nearX, nearY, nx, ny)
    local up, down = max1 - (len - radius), (len + radius) - min1
    if up <= tol or down <= tol then return false end
    if up < best then best, bux, buy = up, nx, ny end
    if down < best then best, bux, buy = down, -nx, -ny end
  end
  return best, bux * best + 0.0, buy * best + 0.0
end

--------------------------------------------------------------------------------------------------
-- Validation and the Polygon class
--------------------------------------------------------------------------------------------------

--- Checks everything about a polygon: a table, an even count, at least 3 points, every
-- coordinate a finite number. O(n), so the per-frame functions keep to O(1) checks.
-- @return true, or nil and a message
function polygon.validate(points)
  if type(points) ~= "table" then
    return nil, "points must be a table, got " .. type(points)
  end
  local n = #points
  if n % 2 ~= 0 then
    return nil, ("points must hold an even number of coordinates, got %d"):format(n)
  end
  if n < 6 then
    return nil, ("points must hold at least 3 points, got %d"):format(n / 2)
  end
  for i = 1, n do
    local v = points[i]
    if type(v) ~= "number" or v ~= v or v == huge or v == -huge then
      return nil, ("points[%d] must be a finite number, got %s"):format(i, tostring(v))
    end
  end
  return true
end

local validate = polygon.validate

--- A polygon object holding the caller's points table (not a copy).
local Polygon = {}
Polygon.__index = Polygon

local function newPolygon(points, level)
  local ok, message = validate(points)
  if not ok then error("Polygon.new: " .. message, level + 1) end
  return setmetatable({ points = points }, Polygon)
end

--- Polygon.new(points), also Polygon(points): validates, then wraps points.
function Polygon.new(points)
  local p = newPolygon(points, 2)   -- not a tail call, so the error level is the same everywhere
  return p
end

--- Whether (x, y) lies inside, as polygonContains.
function Polygon:contains(x, y)
  local inside = checkedContains("Polygon:contains", self.points, x, y)
  return inside
end

setmetatable(Polygon, { __call = function(_, points)
  local p = newPolygon(points, 2)
  return p
end })
polygon.Polygon = Polygon

return polygon
