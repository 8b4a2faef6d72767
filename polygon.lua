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
-- whether projected ranges overlap) comes from one of two predicates:
--   cross(u0, u1, v0, v1)  the sign of the 2x2 determinant (u1 - u0) x (v1 - v0)
--   shoelace(points)       the sign of twice the signed area
-- Each first computes in ordinary floating point with an error bound (Shewchuk's filter). Only
-- when the bound cannot vouch for the sign does it redo the sum exactly, as a floating-point
-- expansion: a sum of doubles whose bits do not overlap, built from TwoSum and TwoProduct
-- (Dekker's split). The exact path allocates nothing: it reuses one scratch array.
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

-- The scratch expansion: EXP[1..expLen], nonoverlapping, increasing in magnitude, no zeros.
local EXP, expLen = {}, 0

-- Adds the double b to the expansion exactly (Shewchuk's Grow-Expansion, zeros eliminated).
local function expAdd(b)
  if b == 0 then return end
  local q, k = b, 0
  for i = 1, expLen do
    local e = EXP[i]
    local s = q + e
    local bv = s - q
    local h = (q - (s - bv)) + (e - bv)
    q = s
    if h ~= 0 then k = k + 1; EXP[k] = h end
  end
  if q ~= 0 then k = k + 1; EXP[k] = q end
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
  local top = EXP[expLen]
  if expLen == 0 or top == 0 then return 0 end
  return top > 0 and 1 or -1
end

-- Compresses the expansion in place to an equal one with fewer components (Shewchuk's
-- Compress) and returns its largest component, which is within one ulp of the exact sum.
local function expCompress()
  if expLen == 0 then return 0.0 end
  local bottom, q = expLen, EXP[expLen]
  for i = expLen - 1, 1, -1 do
    local e = EXP[i]
    local s = q + e
    local small = e - (s - q)
    if small ~= 0 then
      EXP[bottom] = s; bottom = bottom - 1; q = small
    else
      q = s
    end
  end
  EXP[bottom] = q
  local top = 0
  for i = bottom + 1, expLen do
    local g = EXP[i]
    local s = g + q
    local small = q - (s - g)
    if small ~= 0 then top = top + 1; EXP[top] = small end
    q = s
  end
  top = top + 1; EXP[top] = q
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

-- Whether shoelace's sum is too close to zero for its sign to be trusted. Each term
-- (X_i + X_j) d is off by at most 4 eps (|X_i| + |X_j|) |d| and summing m terms adds (m - 1) eps
-- times their magnitudes, so the error is below (m + 3) eps T, where by Cauchy-Schwarz
-- T = sum (|X_i| + |X_j|) |d| <= 2 sqrt(sx sd). The test compares squares against a bound four
-- times that (no square root); an overflow (an infinite or NaN sum) only sends the decision to
-- the exact path.
local function areaUncertain(m, sum, sx, sd)
  local k = (m + 8) * 2^-50
  return not (sum * sum > k * k * sx * sd)   -- luacheck: ignore 581 (NaN must be uncertain)
end

-- Twice the signed area as an exact expansion in EXP: sum of x_i y_j - x_j y_i over all edges,
-- of the coordinates scaled by s (returned; 1 unless they pass 2^500).
local function shoelaceExact(points, n)
  local m = 0.0
  for i = 1, n do m = max(m, abs(points[i] + 0.0)) end
  local s = exactScale(m)
  expLen = 0
  local limit = 32
  local xi, yi = points[n - 1] * s, points[n] * s
  for i = 1, n - 1, 2 do
    local xj, yj = points[i] * s, points[i + 1] * s
    expAddProduct(xi, yj)
    expAddProduct(-xj, yi)
    xi, yi = xj, yj
    -- every addition walks the whole expansion: compress it whenever it has grown by 32
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

-- The projections above are taken relative to a vertex a of one polygon so that far from the
-- origin they stay as accurate as near it. Their rounding error is at most 4 eps (w |nx| + h |ny|)
-- where w and h bound every |vx - ax| and |vy - ay|; a gap within four times that is decided
-- again exactly, with the cross kernel.
local function projectionTolerance(w, h, nx, ny)
  return 16 * EPS * (w * abs(nx) + h * abs(ny))
end

-- The vertex of points extreme along the normal of edge a -> b: the largest projection when
-- want is -1, the smallest when it is 1. Compared exactly: n.(w - v) has the sign of
-- -(b - a) x (w - v).
local function extreme(ax, ay, bx, by, points, n, want)
  local ex, ey = points[1], points[2]
  for i = 3, n - 1, 2 do
    local vx, vy = points[i], points[i + 1]
    if cross(ax, ay, bx, by, ex, ey, vx, vy) * want > 0 then ex, ey = vx, vy end
  end
  return ex, ey
end

-- Whether the edge a -> b has a normal on which the ranges of p1 and p2 are separated or just
-- touch, decided exactly: max1 <= min2 <=> (b - a) x (min2 - max1) <= 0, and likewise below.
local function separatedExact(ax, ay, bx, by, p1, n1, p2, n2)
  local hx1, hy1 = extreme(ax, ay, bx, by, p1, n1, -1)
  local lx2, ly2 = extreme(ax, ay, bx, by, p2, n2, 1)
  if cross(ax, ay, bx, by, hx1, hy1, lx2, ly2) <= 0 then return true end
  local lx1, ly1 = extreme(ax, ay, bx, by, p1, n1, 1)
  local hx2, hy2 = extreme(ax, ay, bx, by, p2, n2, -1)
  return cross(ax, ay, bx, by, hx2, hy2, lx1, ly1) <= 0
end

-- The tutorial's test, on the edge normals of `axes` (p1 here): both polygons projected on each
-- normal, and both ends of the ranges compared. Used by the one-sided functions.
-- Returns false on a separating axis; otherwise the least penetration so far: bq, the squared
-- depth, the overlap o >= 0 along the normal (nx, ny) (depth o / |n|), and that normal turned
-- the way the second polygon must move. The squared depth is o (o / |n|^2), which neither
-- overflows nor underflows while the coordinates stay in the exact range.
-- w, h: see projectionTolerance.
local function leastPenetration(axes, na, p1, n1, p2, n2, w, h, bq, bo, bnx, bny)
  local ax, ay = axes[na - 1] + 0.0, axes[na] + 0.0
  for i = 1, na - 1, 2 do
    local bx, by = axes[i] + 0.0, axes[i + 1] + 0.0
    if bx ~= ax or by ~= ay then   -- a repeated vertex gives no axis
      local nx, ny = by - ay, ax - bx
      local min1, max1 = projectRange(p1, n1, ax, ay, nx, ny)
      local min2, max2 = projectRange(p2, n2, ax, ay, nx, ny)
      -- up: how far p2 must move along +n to clear p1; down: along -n
      local up, down = max1 - min2, max2 - min1
      local tol = projectionTolerance(w, h, nx, ny)
      if up <= tol or down <= tol then
        if up < -tol or down < -tol then return false end
        if separatedExact(ax, ay, bx, by, p1, n1, p2, n2) then return false end
        -- overlapping by less than the rounding: the float depth may have come out negative
        if up < 0 then up = 0 end
        if down < 0 then down = 0 end
      end
      local q = (up < down and up or down) / (nx * nx + ny * ny)
      if up < down then
        q = q * up
        if q < bq then bq, bo, bnx, bny = q, up, nx, ny end
      else
        q = q * down
        if q < bq then bq, bo, bnx, bny = q, down, -nx, -ny end
      end
    end
    ax, ay = bx, by
  end
  return bq, bo, bnx, bny
end

-- Whether no vertex of `other` lies strictly inside the edge a -> b of a polygon whose area has
-- the sign `turn` (> 0 clockwise on screen), decided exactly.
local function outsideExact(ax, ay, bx, by, turn, other, no)
  for i = 1, no - 1, 2 do
    if turn * cross(ax, ay, bx, by, ax, ay, other[i], other[i + 1]) > 0 then return false end
  end
  return true
end

-- The separating axis test of two convex polygons, face by face: for each edge of `edges`, how
-- deep `other` reaches past it, measured on the edge's outward normal. Two convex polygons
-- overlap exactly when every edge of both is reached past, and the least such depth is the
-- least penetration over all the tutorial's axes and both ends of their ranges (the overlap of
-- the far ends is never smaller: it is the support of the Minkowski difference in a direction
-- that is not a face of it). So one polygon is projected per axis where the tutorial projects
-- both, and the other polygon's own projection is known: its edge, at 0.
-- turn: the sign of the area of `edges`; push: 1 when `other` is the polygon the displacement
-- moves, -1 when `edges` is. Returns false or the best (bq, bo, bnx, bny) as leastPenetration.
local function deepestReach(edges, ne, turn, other, no, push, w, h, bq, bo, bnx, bny)
  local ax, ay = edges[ne - 1] + 0.0, edges[ne] + 0.0
  local sign = turn > 0 and 1.0 or -1.0   -- makes (by - ay, ax - bx) point outwards
  for i = 1, ne - 1, 2 do
    local bx, by = edges[i] + 0.0, edges[i + 1] + 0.0
    if bx ~= ax or by ~= ay then   -- a repeated vertex gives no axis
      local nx, ny = (by - ay) * sign, (ax - bx) * sign
      local depth = -minProjection(other, no, ax, ay, nx, ny)
      local tol = projectionTolerance(w, h, nx, ny)
      if depth <= tol then
        if depth < -tol or outsideExact(ax, ay, bx, by, turn, other, no) then return false end
        if depth < 0 then depth = 0 end
      end
      local q = depth * (depth / (nx * nx + ny * ny))
      if q < bq then bq, bo, bnx, bny = q, depth, nx * push, ny * push end
    end
    ax, ay = bx, by
  end
  return bq, bo, bnx, bny
end

-- The shared body of the four polygon collision functions: false, or the least penetration as
-- leastPenetration returns it and a size that bounds the coordinates' magnitudes.
-- both: the axes of both polygons, else those of p1 only.
local collide
function collide(fname, p1, p2, both)
  local n1 = checkPoints(p1, fname, "points1", 4)
  local n2 = checkPoints(p2, fname, "points2", 4)
  if n1 < 6 or n2 < 6 then return false end
  local a1, sx1, sd1 = shoelace(p1, n1)
  local turn1 = areaSignOf(p1, n1, a1, sx1, sd1)
  if turn1 == 0 then return false end
  local a2, sx2, sd2 = shoelace(p2, n2)
  local turn2 = areaSignOf(p2, n2, a2, sx2, sd2)
  if turn2 == 0 then return false end
  -- Sizes bounding every |vx - ax| and |vy - ay| in the projections: within a polygon of m
  -- vertices |x_i - x_1| <= sqrt(sx) and |y_i - y_1| <= sqrt(m sd); twice that and the distance
  -- between the two first vertices covers a vertex of one polygon seen from one of the other.
  local w = 2 * (sqrt(sx1) + sqrt(sx2) + abs((p2[1] + 0.0) - p1[1]))
  local h = 2 * (sqrt(n1 / 2 * sd1) + sqrt(n2 / 2 * sd2) + abs((p2[2] + 0.0) - p1[2]))
  if not (w + h <= EXACT_TOP) then   -- luacheck: ignore 581 (true for inf and NaN too)
    -- Far beyond the exact range the projections (products of two sizes) would overflow into
    -- infinities and NaN. Collide copies scaled by a power of two k instead, to coordinates
    -- below 2^464, so sizes below 2^500 (this rare path allocates the copies). A projection o
    -- scales by k^2 and a normal by k, so the normal times k again gives back the depth o / |n|.
    local m = 0.0
    for i = 1, n1 do m = max(m, abs(p1[i] + 0.0)) end
    for i = 1, n2 do m = max(m, abs(p2[i] + 0.0)) end
    local k = powerScale(m, 2^400, 2^464)
    local s1, s2 = {}, {}
    for i = 1, n1 do s1[i] = p1[i] * k end
    for i = 1, n2 do s2[i] = p2[i] * k end
    local q, o, nx, ny, size = collide(fname, s1, s2, both)
    if not q then return false end
    return q, o, nx * k, ny * k, size / k, p1, n1, p2, n2
  end
  local q, o, nx, ny
  if both then
    q, o, nx, ny = deepestReach(p1, n1, turn1, p2, n2, 1, w, h, huge, 0, 0, 0)
    if q then q, o, nx, ny = deepestReach(p2, n2, turn2, p1, n1, -1, w, h, q, o, nx, ny) end
  else
    q, o, nx, ny = leastPenetration(p1, n1, p1, n1, p2, n2, w, h, huge, 0, 0, 0)
  end
  if not q then return false end
  -- a bound on the largest coordinate magnitude: |x1| + |y1| + w + h
  return q, o, nx, ny, abs(p1[1] + 0.0) + abs(p1[2] + 0.0) + w + h, p1, n1, p2, n2
end

-- The unit vector along (nx, ny) and the length of (nx, ny), scaled first by the larger
-- component so that neither squaring overflows nor underflows. (nx, ny) must not be (0, 0).
local function unit(nx, ny)
  local m = abs(nx) > abs(ny) and abs(nx) or abs(ny)
  nx, ny = nx / m, ny / m
  local len = sqrt(nx * nx + ny * ny)
  return nx / len, ny / len, len * m
end

-- overlap, dx, dy from collide's least penetration. Adding (dx, dy) to the second polygon rounds
-- its coordinates, which can leave an overlap of an ulp that the exact test still sees; so a
-- depth below 2 eps M, M the largest coordinate magnitude (about an ulp of it), is raised to it.
-- Such a push moves every coordinate by at least an ulp along its larger component, so a loop
-- that resolves until nothing collides ends, instead of being told forever to move by zero.
local function displacement(q, o, nx, ny, size, p1, n1, p2, n2)
  if not q then return false end
  -- Only outside the exact range can every axis's squared normal underflow, leaving none chosen
  if nx == 0 and ny == 0 then return 0.0, 0.0, 0.0 end
  local ux, uy, len = unit(nx, ny)
  local depth = o / len
  if depth < 2 * EPS * size then   -- size >= M: only then is M worth finding
    local m = 0.0
    for i = 1, n1 do m = max(m, abs(p1[i] + 0.0)) end
    for i = 1, n2 do m = max(m, abs(p2[i] + 0.0)) end
    if depth < 2 * EPS * m then depth = 2 * EPS * m end
  end
  return depth, ux * depth + 0.0, uy * depth + 0.0   -- + 0.0 turns -0 into 0
end

--- Whether the edge normals of points1 show no separating axis between two convex polygons.
-- Touching is not colliding; fewer than 3 points or zero area never collides. Exact.
-- @return true or false
function polygon.polygonCollidesWith(points1, points2)
  return collide("polygonCollidesWith", points1, points2, false) ~= false
end

--- Whether two convex polygons (either winding) overlap, by the separating axis theorem.
-- Touching is not colliding; fewer than 3 points or zero area never collides. Exact.
-- @return true or false
function polygon.polygonsCollide(points1, points2)
  return collide("polygonsCollide", points1, points2, true) ~= false
end

--- As polygonCollidesWith, with the minimum translation vector over the axes of points1.
-- @return overlap, dx, dy (moving points2 by dx, dy makes the polygons just touch) or false
function polygon.polygonCollidesWithV(points1, points2)
  return displacement(collide("polygonCollidesWithV", points1, points2, false))
end

--- As polygonsCollide, with the minimum translation vector.
-- overlap is the penetration depth along the axis of least penetration, right also when one
-- polygon contains the other; (dx, dy) moves points2 out of points1 (add it to every vertex of
-- points2), pointing the right way in either argument order and when the centres coincide.
-- @return overlap, dx, dy or false
function polygon.polygonsCollideV(points1, points2)
  return displacement(collide("polygonsCollideV", points1, points2, true))
end

--------------------------------------------------------------------------------------------------
-- Circles
--------------------------------------------------------------------------------------------------
-- A disc collides with a shape when the OPEN disc meets the shape's interior: touching is not
-- colliding and a radius of 0 never collides. The answer compares squared distances exactly
-- (degree 2 against a vertex or another circle, degree 4 against an edge), first in floating
-- point with an error bound, then, only when that bound cannot vouch, as expansions.

-- shared helper: lead moves it to the kernels
-- Adds sign * (hi + lo)^2 = sign * (hi^2 + 2 hi lo + lo^2) to the expansion exactly.
local function expAddSquare(hi, lo, sign)
  expAddProduct(sign * hi, hi)
  expAddProduct(sign * 2 * hi, lo)
  expAddProduct(sign * lo, lo)
end

-- The exact tests scale their differences by a power of two into [2^186, 2^250]: a product of
-- four such numbers stays below 2^1000 (no overflow), and a term 2^400 times smaller than the
-- largest still has all its bits above the underflow threshold after four multiplications.
local SCALE_LO, SCALE_HI = 2^186, 2^250

-- Checks that v is a finite number (NaN and infinities say so in the message).
local function checkFinite(v, fname, argname, level)
  if type(v) ~= "number" then
    error(("%s: %s must be a number, got %s"):format(fname, argname, type(v)), level or 3)
  end
  if v ~= v or v == huge or v == -huge then
    error(("%s: %s must be finite, got %s"):format(fname, argname, tostring(v)), level or 3)
  end
end

local function checkRadius(r, fname, argname, level)
  checkFinite(r, fname, argname, (level or 3) + 1)
  if r < 0 then
    error(("%s: %s must not be negative, got %s"):format(fname, argname, tostring(r)), level or 3)
  end
end

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

-- The exact sign of (r1 + r2)^2 - ((x2 - x1)^2 + (y2 - y1)^2): > 0 when two circles collide.
-- Every difference and the sum of the radii are split exactly into hi + lo first.
local function circlesOverlapExact(x1, y1, r1, x2, y2, r2)
  local dxh, dxl = twoDiff(x2, x1)
  local dyh, dyl = twoDiff(y2, y1)
  local rh, rl = twoDiff(r1, -r2)
  local s = powerScale(max(abs(dxh), abs(dyh), rh), SCALE_LO, SCALE_HI)
  expLen = 0
  expAddSquare(rh * s, rl * s, 1)
  expAddSquare(dxh * s, dxl * s, -1)
  expAddSquare(dyh * s, dyl * s, -1)
  return expSign()
end

-- Whether two circles collide (the open discs meet), exactly. The float difference of the
-- squares is off by less than 8 eps times their sum (each square is within 3 eps, the
-- differences and the sum of the radii within one more rounding); beyond the range where the
-- squares neither overflow nor lose bits to underflow the exact path decides alone.
local function circlesCollide(x1, y1, r1, x2, y2, r2)
  local dx, dy, sum = x2 - x1, y2 - y1, r1 + r2
  local distSq, reachSq = dx * dx + dy * dy, sum * sum
  local gap = reachSq - distSq
  local bound = 8 * EPS * (reachSq + distSq)
  if gap > bound and reachSq < 2^1000 and bound > 2^-900 then return true end
  if -gap > bound and distSq < 2^1000 and bound > 2^-900 then return false end
  return circlesOverlapExact(x1, y1, r1, x2, y2, r2) > 0
end

--- Whether two circles overlap, with the push that separates them.
-- Touching is not colliding, and a circle of radius 0 never collides; decided exactly.
-- (dx, dy) moves the second circle: after x2 + dx, y2 + dy (rounded as a game adds them) the
-- circles no longer collide. Its length exceeds overlap by a few ulps of the coordinates at
-- most. Circles with the same centre are pushed along +x.
-- @return overlap, dx, dy (overlap = r1 + r2 - distance) or false
function polygon.circlesCollideV(x1, y1, r1, x2, y2, r2)
  local fname = "circlesCollideV"
  checkFinite(x1, fname, "x1")
  checkFinite(y1, fname, "y1")
  checkRadius(r1, fname, "r1")
  checkFinite(x2, fname, "x2")
  checkFinite(y2, fname, "y2")
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
  -- Moving by exactly overlap would leave the circles touching at best, and rounding x2 + dx
  -- can lose up to half an ulp of x2 on each axis. So the push is longer by half an ulp of the
  -- largest magnitude, doubled until the moved circle clears for certain (usually at once).
  local step = EPS * m
  for _ = 1, 64 do
    local length = overlap + step
    local px, py = ux * length + 0.0, uy * length + 0.0   -- + 0.0 turns -0 into 0
    if not circlesCollide(x1, y1, r1, x2 + px, y2 + py, r2) then
      return overlap / k, px / k, py / k
    end
    step = step * 2
  end
  error("circlesCollideV: no push separates the circles (an internal defect)", 2)
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
-- Moving and bounding shapes
--------------------------------------------------------------------------------------------------
-- A shape here is a flat array {x1, y1, ...} or a list of convex parts {part1, part2, ...}, each
-- part a flat array; one look at the first entry tells them apart (a number or a table).

local sin, cos = math.sin, math.cos

-- Whether points is a list of parts rather than a flat array of coordinates.
local function isParts(points)
  return type(points[1]) == "table"
end

-- Checks a list of parts: every entry a table with an even count. Returns their number. level as
-- in checkPoints, counted from here. The messages are built only on the error path (no garbage).
local function checkParts(parts, fname, level)
  local count = #parts
  for k = 1, count do
    local part = parts[k]
    if type(part) ~= "table" then
      error(("%s: points[%d] must be a table, got %s"):format(fname, k, type(part)), level)
    end
    if #part % 2 ~= 0 then
      error(("%s: points[%d] must hold an even number of coordinates, got %d")
        :format(fname, k, #part), level)
    end
  end
  return count
end

-- The caller's out table, or a new one when none was given.
local function checkOut(out, fname)
  if out == nil then return {} end
  if type(out) ~= "table" then
    error(("%s: out must be a table, got %s"):format(fname, type(out)), 3)
  end
  return out
end

-- The part of a list out to write part k into: the one there, or a new table the first time.
local function outPart(out, k, fname)
  local part = out[k]
  if part == nil then
    part = {}
    out[k] = part
  elseif type(part) ~= "table" then
    error(("%s: out[%d] must be a table, got %s"):format(fname, k, type(part)), 3)
  end
  return part
end

-- Removes what a reused out holds beyond its first `count` entries.
local function trim(out, count)
  for i = #out, count + 1, -1 do out[i] = nil end
end

-- The bounding box of points[1..n] merged with the box given (huge, huge, -huge, -huge: none).
local function boundsOf(points, n, minx, miny, maxx, maxy)
  for i = 1, n - 1, 2 do
    local x, y = points[i] + 0.0, points[i + 1] + 0.0
    if x < minx then minx = x end
    if x > maxx then maxx = x end
    if y < miny then miny = y end
    if y > maxy then maxy = y end
  end
  return minx, miny, maxx, maxy
end

--- The axis-aligned bounding box, the box a broadphase sorts shapes by. Allocates nothing.
-- @param points flat array {x1, y1, ...}, or a list of convex parts {part1, part2, ...}
-- @return minx, miny, maxx, maxy (the box of all parts for a list); nil for no points.
-- Coordinates are taken as finite (validate checks that): a NaN coordinate is skipped.
function polygon.polygonBounds(points)
  local fname = "polygonBounds"
  local minx, miny, maxx, maxy = huge, huge, -huge, -huge
  if type(points) == "table" and isParts(points) then
    local count = checkParts(points, fname, 3)
    for k = 1, count do
      local part = points[k]
      minx, miny, maxx, maxy = boundsOf(part, #part, minx, miny, maxx, maxy)
    end
  else
    local n = checkPoints(points, fname)
    minx, miny, maxx, maxy = boundsOf(points, n, minx, miny, maxx, maxy)
  end
  if minx > maxx then return nil end
  return minx, miny, maxx, maxy
end

-- points[1..n] moved by (dx, dy), written into out (which may be points itself).
local function translateInto(points, n, dx, dy, out)
  for i = 1, n - 1, 2 do
    -- + 0.0 first: Lua 5.3+ integers would otherwise add as integers, rounding differently
    out[i], out[i + 1] = (points[i] + 0.0) + dx, (points[i + 1] + 0.0) + dy
  end
  trim(out, n)
end

--- The polygon moved by (dx, dy).
-- @param points flat array, or a list of convex parts
-- @param out optional: the table to write the result into, reused from frame to frame so that a
--   call allocates nothing; it may be points itself (moves in place). For a list of parts, out is
--   a list of part tables (missing ones are created, the first time only). Without out the
--   result is a NEW table (a new list of new parts): fine once, garbage every frame.
-- @return out. Each coordinate is rounded once (x + dx).
function polygon.polygonTranslate(points, dx, dy, out)
  local fname = "polygonTranslate"
  if type(points) == "table" and isParts(points) then
    local count = checkParts(points, fname, 3)
    checkFinite(dx, fname, "dx")
    checkFinite(dy, fname, "dy")
    out = checkOut(out, fname)
    for k = 1, count do
      local part = points[k]
      translateInto(part, #part, dx, dy, outPart(out, k, fname))
    end
    trim(out, count)
  else
    local n = checkPoints(points, fname)
    checkFinite(dx, fname, "dx")
    checkFinite(dy, fname, "dy")
    out = checkOut(out, fname)
    translateInto(points, n, dx, dy, out)
  end
  return out
end

-- Adds the vertices of points[1..n] to the running sums (sx, sy) and count m.
local function addVertices(points, n, sx, sy, m)
  for i = 1, n - 1, 2 do sx, sy = sx + points[i], sy + points[i + 1] end
  return sx, sy, m + n / 2
end

-- The default pivot of polygonRotate: the area centroid; for a list of parts the centroids
-- weighted by the parts' areas; the vertex mean when there is no area at all; (0, 0) for no points.
local function pivotOf(points, parts, count)
  local sx, sy, m = 0.0, 0.0, 0
  if not parts then
    local cx, cy = polygon.polygonCentroid(points)
    if cx then return cx, cy end
    sx, sy, m = addVertices(points, count, sx, sy, m)
  else
    local wx, wy, total = 0.0, 0.0, 0.0
    for k = 1, count do
      local part = points[k]
      local cx, cy = polygon.polygonCentroid(part)
      if cx then
        local area = polygon.polygonArea(part)
        wx, wy, total = wx + area * cx, wy + area * cy, total + area
      end
    end
    if total > 0 then return wx / total, wy / total end
    for k = 1, count do
      local part = points[k]
      sx, sy, m = addVertices(part, #part, sx, sy, m)
    end
  end
  if m == 0 then return 0.0, 0.0 end
  return sx / m, sy / m
end

-- points[1..n] turned about (ox, oy) by the rotation (c -s; s c), written into out (which may be
-- points itself: each vertex is read before it is written).
local function rotateInto(points, n, c, s, ox, oy, out)
  for i = 1, n - 1, 2 do
    local x, y = points[i] - ox, points[i + 1] - oy
    out[i], out[i + 1] = ox + (c * x - s * y), oy + (s * x + c * y)
  end
  trim(out, n)
end

--- The polygon turned by angle (radians) about (ox, oy), by default its area centroid (for a list
-- of parts, the parts' centroids weighted by their areas; the vertex mean when the area is 0).
-- In screen coordinates (y down) a positive angle turns CLOCKWISE on screen: (1, 0) about (0, 0)
-- by pi / 2 goes to (0, 1), straight down.
-- Rounding: each new coordinate is x' = ox + (c (x - ox) - s (y - oy)) in five roundings, so a
-- vertex at distance r from the pivot lands within 4 eps (r + |x'|) (eps = 2^-53) of the exact
-- rotation by the doubles c = cos(angle), s = sin(angle); those are rounded too (and math.pi / 2
-- is not exactly pi / 2), a further 2 eps r or so: a few ulps. Angle 0 copies the points
-- unchanged. Rotating a convex
-- polygon keeps it convex only up to that rounding: a vertex (nearly) on the line through its
-- neighbours, within a few ulps of it, may land on either side, so polygonType (exact) can call
-- the result concave; a vertex that turns by more than the rounding keeps its turn.
-- @param points flat array, or a list of convex parts
-- @param ox, oy optional pivot (both or neither)
-- @param out optional table to write into, as in polygonTranslate (reused: no allocation; may
--   be points itself; without it the result is a NEW table). May come third: (points, angle, out).
-- @return out
function polygon.polygonRotate(points, angle, ox, oy, out)
  local fname = "polygonRotate"
  if type(ox) == "table" and oy == nil and out == nil then ox, out = nil, ox end
  local parts = type(points) == "table" and isParts(points)
  local count
  if parts then count = checkParts(points, fname, 3) else count = checkPoints(points, fname) end
  checkFinite(angle, fname, "angle")
  if ox ~= nil or oy ~= nil then
    checkFinite(ox, fname, "ox")
    checkFinite(oy, fname, "oy")
  end
  out = checkOut(out, fname)
  if ox == nil then ox, oy = pivotOf(points, parts, count) end
  ox, oy = ox + 0.0, oy + 0.0
  local c, s = cos(angle), sin(angle)
  -- angle 0 copies: the rotation's formula would round x to ox + (x - ox)
  local still = angle == 0
  if parts then
    for k = 1, count do
      local part = points[k]
      local into = outPart(out, k, fname)
      if still then translateInto(part, #part, 0.0, 0.0, into)
      else rotateInto(part, #part, c, s, ox, oy, into) end
    end
    trim(out, count)
  elseif still then
    translateInto(points, count, 0.0, 0.0, out)
  else
    rotateInto(points, count, c, s, ox, oy, out)
  end
  return out
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
