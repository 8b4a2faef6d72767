local polygon = {
  _VERSION     = "polygon 0.7.0",
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

-- What the module offers, in the order of the file and of the README (every other name is
-- private; the sections below say how each works):
--   measures          polygonWindingOrder, polygonArea, polygonAreaAccurate, polygonType,
--                     polygonCenter, polygonCentroid
--   point in polygon  polygonContains
--   separating axes   projectPolygon, polygonCollidesWith, polygonsCollide,
--                     polygonCollidesWithV, polygonsCollideV
--   circles           projectCircle, circlesCollideV, polygonCircleCollideV
--   concave shapes    polygonTriangulate, polygonConvexParts (and lists of convex parts wherever
--                     polygonsCollide, polygonsCollideV and polygonCircleCollideV take a polygon)
--   moving shapes     polygonBounds, polygonTranslate, polygonRotate
--   checking          validate, Polygon.new / Polygon(points), Polygon:contains

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
-- cross's is CROSS_BOUND, the area's is areaSignOf's. Only when the bound cannot vouch for the
-- sign does it redo the sum exactly, as a floating-point expansion: a sum of doubles whose bits
-- do not overlap, built from TwoSum and TwoProduct (Dekker's split). The exact path allocates
-- nothing: it reuses one scratch array (and when the differences are exact, the common case,
-- cross needs no loop at all). Hot loops that inline cross's filter say so where they do it,
-- with the measured reason (vertexInside, lineShortfall, PUC Lua's separatingPush,
-- polygonType); they call cross, or its exact stages (crossExact), where the filter cannot
-- decide, or, in separatingPush, lengthen the push until it can.
--
-- LuaJIT and the PUC interpreters want different code: PUC Lua pays for every call (math.min
-- and math.abs included) and little for a branch; LuaJIT compiles min, max and abs to single
-- instructions, and turns every branch that goes both ways into a side trace, whose number is
-- limited (100 per loop, 1000 in all by default). Where that matters a function has two bodies
-- computing the same numbers, chosen once by JIT below; the LuaJIT bodies keep few values alive
-- across their loops, since a side trace leaving a loop must take them all over in registers,
-- and avoid short inner loops: a loop of a few steps (a polygon's vertices) often fails to
-- become a trace of its own, and other traces then copy it unrolled, with a side exit for every
-- other polygon size (so the SAT's hot paths read up to 8 vertices in one expression, the last
-- one repeated for fewer, and run flat over (edge, vertex) pairs beyond; a short loop has no
-- data-dependent exit but its last; `bash bench/aborts.sh` counts what LuaJIT still aborts).
-- The PUC bodies count instructions instead
-- (`lua5.4 bench/instructions.lua`): the two-sided SAT walks both polygons' edges at once
-- (rotating calipers), one projection an edge, where LuaJIT projects every pair.
--
-- Exactness holds while no product overflows or underflows: every nonzero coordinate between
-- 2^-447 and 2^500 in magnitude (then all coordinates are multiples of 2^-499, all products of
-- differences multiples of 2^-998, which doubles still hold exactly). Lua 5.3+ integers are
-- converted to doubles (`+ 0.0`) before any difference or product, so they cannot wrap past
-- 2^63 and an integer beyond 2^53 counts as the double it converts to.

local EPS = 2^-53                         -- unit roundoff of a double
-- LuaJIT (LÖVE's runtime) or a PUC interpreter (see above); LuaJIT compiles a test of it away
local JIT = rawget(_G, "jit") ~= nil
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
-- On LuaJIT without a branch inside: each part is written at k + 1 and k counts it when it is
-- not 0, so that a trace copying this loop has no side exit for a zero part (such exits failed
-- to compile in some runs of the benchmark: "NYI: register coalescing too complex", 31 and 42
-- in two batches of `bash bench/aborts.sh 16`). min(|h| 2^1000 2^1000, 1) is 0 for a zero and
-- 1 for any other double. A NaN part (only input outside the exact range makes one) counts too,
-- as on PUC Lua, and never reaches k: LuaJIT's min returns its second argument when either is
-- NaN (on x64 in the interpreter and in traces; spec/non_finite_hard_spec.lua's wild
-- coordinates make NaN parts, and with min(1, ...) k became NaN).
local function expAdd(b)
  if b == 0 then return end
  local q, k = b, 0
  for i = 1, expLen do
    local e = expansion[i]
    local s = q + e
    local bv = s - q
    local h = (q - (s - bv)) + (e - bv)
    q = s
    if JIT then
      expansion[k + 1] = h   -- (k < i: the part read at i is not overwritten before it is read)
      k = k + min(abs(h) * 2^1000 * 2^1000, 1)
    elseif h ~= 0 then
      k = k + 1; expansion[k] = h
    end
  end
  if JIT then
    expansion[k + 1] = q
    expLen = k + min(abs(q) * 2^1000 * 2^1000, 1)
  else
    if q ~= 0 then k = k + 1; expansion[k] = q end
    expLen = k
  end
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

-- The exact sign of (u1 - u0) x (v1 - v0), for cross when its filter cannot decide: Shewchuk's
-- adaptive stages after the filter's. Each difference, scaled by s (see exactScale), is split
-- into hi + lo exactly; the determinant of the his, B = ph + pl - qh - ql (two exact products),
-- is written by his Two-Two-Diff as four nonoverlapping parts x3 > x2 > x1 > x0 in magnitude
-- (zeros allowed). When every lo is 0 (nearby coordinates, the usual case) B is the determinant.
-- Otherwise B's estimate, then the estimate with the los' products added, decide it when they
-- clear his bounds for those stages; only what remains is summed as an expansion of the sixteen
-- partial products, from the differences split again. The first stages have no loop and keep
-- three numbers across their branches: on LuaJIT a side trace taken at one of them inherits
-- every value alive there, and with the eight parts too (and the caller's values) it needed more
-- registers than there are ("NYI: register coalescing too complex", retried on every call).
local crossExact
do
  local BOUND_B = (2 + 12 * EPS) * EPS             -- Shewchuk's ccwerrboundB
  local BOUND_C = (9 + 64 * EPS) * EPS * EPS       -- ccwerrboundC
  local BOUND_RESULT = (3 + 8 * EPS) * EPS         -- resulterrbound

  -- The last stage: the sign of the sum of the eight products of the differences' parts, as an
  -- expansion. The factors wait in a table, so that a trace running this inline keeps only the
  -- loop's index in registers at the exits of expAdd's loops, not the eight parts: with them
  -- (and a calling loop's values) the side traces there failed to compile, "NYI: register
  -- coalescing too complex" at expAdd's end, 527 aborts in 4 of 16 runs of `bash bench/aborts.sh
  -- 16`, all from the one-sided functions' deepestVertex loop.
  local factors = {}
  local function expansionSign(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1, s)
    local axh, axl = twoDiff(ux1 * s, ux0 * s)
    local ayh, ayl = twoDiff(uy1 * s, uy0 * s)
    local bxh, bxl = twoDiff(vx1 * s, vx0 * s)
    local byh, byl = twoDiff(vy1 * s, vy0 * s)
    local f = factors
    f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8] = axh, byh, axh, byl, axl, byh, axl, byl
    f[9], f[10], f[11], f[12], f[13], f[14], f[15], f[16] =
      -ayh, bxh, -ayh, bxl, -ayl, bxh, -ayl, bxl
    expLen = 0
    for i = 1, 15, 2 do expAddProduct(f[i], f[i + 1]) end
    return expSign()
  end

  crossExact = function(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1)
    local s = 1.0
    if JIT then
      local m = abs(ux0 + 0.0)
      m = max(m, abs(uy0 + 0.0), abs(ux1 + 0.0), abs(uy1 + 0.0))
      m = max(m, abs(vx0 + 0.0), abs(vy0 + 0.0), abs(vx1 + 0.0), abs(vy1 + 0.0))
      s = exactScale(m)
    else   -- every |coordinate| is at most 2^500 (s = 1) when their squares sum to at most
      -- 2^1000: products instead of ten C calls to abs and max
      local a, b, c, d = ux0 + 0.0, uy0 + 0.0, ux1 + 0.0, uy1 + 0.0
      local e, f, g, h = vx0 + 0.0, vy0 + 0.0, vx1 + 0.0, vy1 + 0.0
      local squares = a * a + b * b + c * c + d * d + e * e + f * f + g * g + h * h
      if not (squares <= 2^1000) then   -- luacheck: ignore 581 (NaN too)
        local m = abs(a)
        m = max(m, abs(b), abs(c), abs(d), abs(e), abs(f), abs(g), abs(h))
        s = exactScale(m)
      end
    end
    -- PUC Lua: when every difference is exact (nearby coordinates, the usual case, such as a
    -- vertex on an edge's line), rounding being monotone, two products that round apart are
    -- ordered as their exact values, and the difference of the rounded ones has the sign;
    -- products that round alike differ by their rounding errors, whose difference has it. A few
    -- operations (TwoDiff's written out: its calls were about a third of the instructions here)
    -- where stage B below takes four TwoDiffs, two TwoProducts and a Two-Two-Diff. (On LuaJIT,
    -- which compiles stage B inline, the branches' side traces, inheriting the eight parts,
    -- failed to compile: "NYI: register coalescing too complex".)
    if not JIT then
      local a, b = ux1 * s, ux0 * s
      local axh = a - b
      local bv = a - axh
      local exact = (a - (axh + bv)) + (bv - b) == 0
      a, b = uy1 * s, uy0 * s
      local ayh = a - b
      bv = a - ayh
      exact = exact and (a - (ayh + bv)) + (bv - b) == 0
      a, b = vx1 * s, vx0 * s
      local bxh = a - b
      bv = a - bxh
      exact = exact and (a - (bxh + bv)) + (bv - b) == 0
      a, b = vy1 * s, vy0 * s
      local byh = a - b
      bv = a - byh
      if exact and (a - (byh + bv)) + (bv - b) == 0 then
        local l, r = axh * byh, ayh * bxh
        if l ~= r then return l - r end
        local _, pl = twoProduct(axh, byh)
        local _, ql = twoProduct(ayh, bxh)
        return pl - ql
      end
    end
    local det, detsum, tails
    do
      local axh, axl = twoDiff(ux1 * s, ux0 * s)
      local ayh, ayl = twoDiff(uy1 * s, uy0 * s)
      local bxh, bxl = twoDiff(vx1 * s, vx0 * s)
      local byh, byl = twoDiff(vy1 * s, vy0 * s)
      local ph, pl = twoProduct(axh, byh)
      local qh, ql = twoProduct(ayh, bxh)
      local i, x0 = twoDiff(pl, ql)
      local j, k = twoDiff(ph, -i)
      local g, x1 = twoDiff(k, qh)
      local x3, x2 = twoDiff(j, -g)
      -- B's estimate (its parts summed from the smallest) has B's sign (Shewchuk), so it
      -- decides when the los are all 0 (then tails is 0 and detsum, below, is 0 too)
      det, detsum = x0 + x1 + x2 + x3, abs(ph) + abs(qh)
      tails = (axh * byl + byh * axl) - (ayh * bxl + bxh * ayl)
      if abs(axl) + abs(ayl) + abs(bxl) + abs(byl) == 0 then detsum = 0.0 end
    end
    if abs(det) >= BOUND_B * detsum then return det end
    local bound = BOUND_C * detsum + BOUND_RESULT * abs(det)
    det = det + tails
    if abs(det) >= bound then return det end
    local sign = expansionSign(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1, s)
    return sign
  end
end

-- A number with the sign of (u1 - u0) x (v1 - v0), exact for the given doubles: positive when
-- v turns clockwise from u on screen. orient(a, b, c) is cross(a, b, a, c).
-- The filter: det = l - r is certain when |det| >= CROSS_BOUND (|l| + |r|) (Shewchuk's bound;
-- when l and r differ in sign or one is zero no cancellation happens and that always holds).
-- Two bodies computing the same test: on PUC Lua the signs of l and r are compared first (abs
-- is a call there); on LuaJIT abs is one instruction and the single branch leaves loops that
-- call cross with one side exit instead of five.
local cross
if JIT then
  cross = function(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1)
    local l = ((ux1 + 0.0) - ux0) * ((vy1 + 0.0) - vy0)
    local r = ((uy1 + 0.0) - uy0) * ((vx1 + 0.0) - vx0)
    local det = l - r
    if abs(det) >= CROSS_BOUND * (abs(l) + abs(r)) then return det end
    return crossExact(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1)
  end
else
  cross = function(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1)
    local l = ((ux1 + 0.0) - ux0) * ((vy1 + 0.0) - vy0)
    local r = ((uy1 + 0.0) - uy0) * ((vx1 + 0.0) - vx0)
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
    return crossExact(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1)
  end
end

-- Twice the signed area of points[1..n] (n = #points >= 6), with what its error bound needs.
-- The x coordinates are taken relative to the first vertex so the offset of a polygon does not
-- matter: sum over edges of (X_i + X_j)(y_j - y_i) with X = x - x_1, the tutorial's trapezoid
-- form, equal to the cross-product form because the y differences around a polygon sum to zero.
-- Also returns xSq = sum of X_i^2 and dSq = sum of (y_j - y_i)^2, branch-free, for
-- areaSignOf's bound.
local function shoelace(points, n)
  local x0, y1 = points[1] + 0.0, points[2] + 0.0
  local px, py = 0.0, y1
  local sum, xSq, dSq = 0.0, 0.0, 0.0
  for i = 3, n - 1, 2 do
    local x, y = points[i] - x0, points[i + 1] + 0.0
    local d = y - py
    sum = sum + (px + x) * d
    xSq, dSq = xSq + x * x, dSq + d * d
    px, py = x, y
  end
  local d = y1 - py
  return sum + px * d, xSq, dSq + d * d
end

-- shoelace and the bounding box in one pass, for the collision functions on LuaJIT: returns
-- shoelace's three sums and xmin, xmax, ymin, ymax. A NaN or infinite coordinate makes xSq + dSq
-- non-finite. The box is kept with min and max, single instructions there: the comparisons' side
-- exits were side traces of this loop, and with those of the code after it they passed LuaJIT's
-- 100 side traces per loop, after which whole calls ran in the interpreter (`luajit -jv
-- bench/run.lua --only 'polygonsCollideV pMix'`). The PUC interpreters call min and max as
-- functions, so there comparisons are faster, and the area's sign is decided in the same call:
-- turnAndBounds, below. LuaJIT's xSq and dSq up to 8 vertices bound the sums by the box, as
-- turnAndBounds does, which changes only how often areaSignOf needs its exact path, never its sign.
local shoelaceBounds
if JIT then
  -- Beyond 8 vertices a loop. The first vertex and the previous one are read from points in
  -- every step (LuaJIT hoists the first and forwards the previous): only the seven sums cross
  -- from one step to the next, so a side trace that leaves the loop midway inherits few values
  -- (see lineShortfall).
  local shoelaceBoundsLoop = function(points, n)
    local sum, xSq, dSq = 0.0, 0.0, 0.0
    local xmin, xmax, ymin, ymax = points[1] + 0.0, points[1] + 0.0, points[2] + 0.0, points[2] + 0.0
    for i = 3, n - 1, 2 do
      local x0 = points[1] + 0.0
      local vx, y = points[i] + 0.0, points[i + 1] + 0.0
      local px, py = points[i - 2] - x0, points[i - 1] + 0.0
      local x, d = vx - x0, y - py
      sum = sum + (px + x) * d
      xSq, dSq = xSq + x * x, dSq + d * d
      xmin, xmax, ymin, ymax = min(xmin, vx), max(xmax, vx), min(ymin, y), max(ymax, y)
    end
    local d = (points[2] + 0.0) - points[n]
    return sum + (points[n - 1] - points[1]) * d, xSq, dSq + d * d, xmin, xmax, ymin, ymax
  end
  shoelaceBounds = function(points, n)
    if n > 16 then
      local sum, xSq, dSq, xmin, xmax, ymin, ymax = shoelaceBoundsLoop(points, n)
      return sum, xSq, dSq, xmin, xmax, ymin, ymax
    end
    -- Up to 8 vertices no loop: a loop of 3 to 8 steps is a trace of its own whose entry and
    -- exit cost more than its steps (a miss, decided by the boxes, took 0.27 to 0.32 of the
    -- tutorial's time with the loop, 0.12 to 0.16 without: `luajit bench/isolated.lua
    -- polygonsCollideV miss`). Vertices 2 to 8, the last one repeated for fewer (its edges add
    -- 0 to the sum); the sum in pairs, as a tree, where the loop's is a chain.
    -- (vertices 2 and 3 at constant indices: convexPenetration, the one caller, hands on 3
    -- vertices or more)
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
    x2, x3, x4, x5, x6, x7, x8 = x2 - x1, x3 - x1, x4 - x1, x5 - x1, x6 - x1, x7 - x1, x8 - x1
    local sum = ((x2 * (y2 - y1) + (x2 + x3) * (y3 - y2)) + ((x3 + x4) * (y4 - y3)
      + (x4 + x5) * (y5 - y4))) + (((x5 + x6) * (y6 - y5) + (x6 + x7) * (y7 - y6))
      + ((x7 + x8) * (y8 - y7) + x8 * (y1 - y8)))
    local m, spanX, spanY = n / 2, xmax - xmin, ymax - ymin
    return sum, m * spanX * spanX + (sum - sum), m * spanY * spanY, xmin, xmax, ymin, ymax
  end
end

-- The largest coordinate magnitude of points[1..n], or m if that is larger.
local function largestMagnitude(points, n, m)
  for i = 1, n do
    local v = points[i] + 0.0
    if v < 0 then v = -v end
    if v > m then m = v end
  end
  return m
end

-- Twice the signed area as an exact expansion in `expansion`: sum of x_i y_j - x_j y_i over all
-- edges, of the coordinates scaled by s (returned; 1 unless they pass 2^500).
local function shoelaceExact(points, n)
  local s = exactScale(largestMagnitude(points, n, 0.0))
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
-- The sum is trusted when it is far enough from zero. Each term (X_i + X_j) d is off by at most
-- 4 eps (|X_i| + |X_j|) |d| and summing m terms adds (m - 1) eps times their magnitudes, so the
-- error is below (m + 3) eps T, where by Cauchy-Schwarz T = sum (|X_i| + |X_j|) |d| <=
-- 2 sqrt(xSq dSq). The test compares squares against a bound four times that (no square root);
-- an overflow (an infinite or NaN sum) only sends the decision to the exact path.
local function areaSignOf(points, n, sum, xSq, dSq)
  -- 2^-50 = 8 eps: (m + 8) 8 eps, m = n / 2, is four times the derived 2 (m + 3) eps, and the
  -- + 5 more than covers the rounding of this bound's own products
  local k = (n / 2 + 8) * 2^-50
  if sum * sum > k * k * xSq * dSq then return sum end   -- (NaN: not trusted)
  shoelaceExact(points, n)
  return expSign()
end

local function areaSign(points, n)
  return areaSignOf(points, n, shoelace(points, n))
end

-- Small kernels of the exact paths: a triple product and a square added to the expansion,
-- and the scan for non-finite coordinates that the rare paths make.

-- Adds a * b * c to the scratch expansion exactly (products below 2^996, none underflowing).
local function expAddTriple(a, b, c)
  local hi, lo = twoProduct(a, b)
  expAddProduct(hi, c)
  expAddProduct(lo, c)
end

-- Adds sign * (hi + lo)^2 = sign * (hi^2 + 2 hi lo + lo^2) to the expansion exactly.
local function expAddSquare(hi, lo, sign)
  expAddProduct(sign * hi, hi)
  expAddProduct(sign * 2 * hi, lo)
  expAddProduct(sign * lo, lo)
end

-- Whether points[1..n] holds a NaN or an infinity. Called only where a sum came out non-finite.
local function holdsNonFinite(points, n)
  for i = 1, n do
    local v = points[i] + 0.0
    if v ~= v or v == huge or v == -huge then return true end
  end
  return false
end

-- PUC Lua's first step of the SAT engine, for one polygon: its turn, the exact sign of its area
-- (1.0, -1.0 or 0.0), its box xmin, xmax, ymin, ymax, and the flat indices (of x) of a vertex of
-- least y and of one of largest y, where reachBoth's walk starts; nil when a coordinate is NaN or
-- infinite. shoelaceBounds' loop with areaSignOf's test written out after it, in one call where
-- LuaJIT makes two (on Lua 5.4 a call takes the time of several VM instructions).
-- The test's xSq and dSq come from the box, not from sums: every |X| is at most spanX and every
-- |d| at most spanY, so m spanX^2 and m spanY^2 (m vertices) bound them, and areaSignOf's bound
-- holds with them (looser, but only slivers notice); two fewer sums per vertex. The shoelace
-- sum, not the box (comparisons pass a NaN by), carries a NaN or infinity into the check for
-- them. Only the sign is returned, so a sound filter gives the same turn as areaSignOf's.
local turnAndBounds
if not JIT then
  turnAndBounds = function(points, n)
    local x0, y1 = points[1] + 0.0, points[2] + 0.0
    local px, py = 0.0, y1
    local sum = 0.0
    local xmin, xmax, ymin, ymax = x0, x0, y1, y1
    local low, high = 1, 1   -- the flat index of x at a vertex of least y, and of largest y
    -- Two vertices a step, the previous vertex's X and y in px and py at the start of each: the
    -- second vertex is read straight into them, so no value is moved (on Lua 5.4 the moves and
    -- the loop's own instruction were a sixth of the loop). vx is compared as read, a Lua 5.3+
    -- integer too: the conversion to a double is monotone, so the extremes converted once are the
    -- extremes of the converted coordinates (x = vx - x0 converts it, x0 being a double).
    for i = 3, n - 3, 4 do
      local vx, y = points[i], points[i + 1] + 0.0
      local x = vx - x0
      sum = sum + (px + x) * (y - py)
      if vx < xmin then xmin = vx elseif vx > xmax then xmax = vx end
      if y < ymin then
        ymin = y
        low = i
      elseif y > ymax then
        ymax = y
        high = i
      end
      vx = points[i + 2]
      py = points[i + 3] + 0.0
      px = vx - x0
      sum = sum + (x + px) * (py - y)
      if vx < xmin then xmin = vx elseif vx > xmax then xmax = vx end
      if py < ymin then
        ymin = py
        low = i + 2
      elseif py > ymax then
        ymax = py
        high = i + 2
      end
    end
    if n % 4 == 0 then   -- an odd number of vertices after the first: the last one alone
      local vx, y = points[n - 1], points[n] + 0.0
      local x = vx - x0
      sum = sum + (px + x) * (y - py)
      if vx < xmin then xmin = vx elseif vx > xmax then xmax = vx end
      if y < ymin then
        ymin = y
        low = n - 1
      elseif y > ymax then
        ymax = y
        high = n - 1
      end
      px = x
      py = y
    end
    sum = sum + px * (y1 - py)
    xmin = xmin + 0.0
    xmax = xmax + 0.0
    local m, spanX, spanY = n / 2, xmax - xmin, ymax - ymin
    -- luacheck: ignore 581 (NaN must count as non-finite)
    if not ((sum - sum) + spanX + spanY < huge) and holdsNonFinite(points, n) then return nil end
    -- areaSignOf's test (see there) with xSq = m spanX^2 and dSq = m spanY^2: its bound k^2 xSq
    -- dSq is the square of k m spanX spanY, which takes fewer operations (and underflows alike)
    local bound = (m + 8) * 2^-50 * m * spanX * spanY
    if not (sum * sum > bound * bound) then   -- luacheck: ignore 581 (NaN: not trusted)
      shoelaceExact(points, n)
      sum = expSign()
    end
    if sum > 0 then return 1.0, xmin, xmax, ymin, ymax, low, high end
    if sum < 0 then return -1.0, xmin, xmax, ymin, ymax, low, high end
    return 0.0, xmin, xmax, ymin, ymax, low, high
  end
end

--------------------------------------------------------------------------------------------------
-- Argument checks: O(1), raised at the caller's level
--------------------------------------------------------------------------------------------------

-- level: where the error points, counted from checkPoints (3: the caller of a public function).
-- isTable: the caller has seen that points is a table (a type call fewer: on PUC Lua each costs
-- about two Lua calls' time).
local function checkPoints(points, fname, argname, level, isTable)
  if not isTable and type(points) ~= "table" then
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

-- Raises fname's error when points holds a NaN or an infinite coordinate (x - x is 0 exactly
-- for every finite x, NaN otherwise). O(n): only for the rare paths that a non-finite value
-- always reaches (a NaN or infinite sum, a failed filter). level as in checkPoints.
local function checkFinitePoints(points, n, fname, argname, level)
  for i = 1, n do
    local v = points[i]
    if v - v ~= 0 then
      error(("%s: %s holds a non-finite coordinate, got %s at [%d]")
        :format(fname, argname, tostring(v), i), level)
    end
  end
end

-- Checks that v is a number and finite (NaN and infinities named as such).
local function checkFiniteNumber(v, fname, argname, level)
  checkNumber(v, fname, argname, (level or 3) + 1)
  if v ~= v or v == huge or v == -huge then
    error(("%s: %s must be finite, got %s"):format(fname, argname, tostring(v)), level or 3)
  end
end

-- Checks that a radius is a finite number, not negative.
local function checkRadius(r, fname, argname)
  checkFiniteNumber(r, fname, argname, 4)
  if r < 0 then
    error(("%s: %s must not be negative, got %s"):format(fname, argname, tostring(r)), 3)
  end
end

--------------------------------------------------------------------------------------------------
-- Measures: winding, area, type, centre
--------------------------------------------------------------------------------------------------

-- The PUC polygonType filter's bound on a turn's rounding error, squared: CROSS_BOUND^2 times
-- 2, room for the rounding of the sum of squares and of the squares.
local TURN_BOUND_SQ = 2 * CROSS_BOUND * CROSS_BOUND

--- The winding order as seen on screen (y down).
-- @param points flat array {x1, y1, ...}
-- @return "cw" or "ccw"; nil for fewer than 3 points or zero signed area. Exact. A non-finite
-- coordinate raises an error (it makes the sum NaN or infinite, which takes the exact path).
function polygon.polygonWindingOrder(points)
  -- The checks written out where they pass, and shoelace's loop copied here, unrolled by two
  -- (no multiple assignment): each Lua call costs about 13 ns on Lua 5.4. Calling shoelace
  -- instead took this from 1.2 to 1.4 times the tutorial's time on Lua 5.4, and an unrolled
  -- shoelace to 1.3 (21 interleaved rounds on bench/workloads.lua's ordinary polygons; the
  -- target is 1.3 in lua5.4 bench/run.lua --only 'polygonWindingOrder ord'). polygonArea's
  -- loop is this one without the squares. A change to shoelace or to areaSignOf's bound
  -- must be made here too.
  local n = type(points) == "table" and #points or -1
  if n % 2 ~= 0 then checkPoints(points, "polygonWindingOrder") end
  if n < 6 then return nil end
  -- shoelace's sum with its bound's sums of X^2 (xSq) and d^2 (dSq), as in shoelace. Of the
  -- two y read per step only the second is converted: each difference has one converted side,
  -- which converts the other (a Lua 5.3+ integer counts as its double), one instruction less.
  local x0, y1 = points[1] + 0.0, points[2] + 0.0
  local px, py = 0.0, y1
  local sum, xSq, dSq = 0.0, 0.0, 0.0
  local start = 3
  if n % 4 == 0 then   -- an even number of vertices: one step before the pairs
    px, py = points[3] - x0, points[4] + 0.0
    local d = py - y1
    sum, xSq, dSq, start = px * d, px * px, d * d, 5
  end
  for i = start, n - 3, 4 do
    local x = points[i] - x0
    local y = points[i + 1]
    local d = y - py
    sum = sum + (px + x) * d
    xSq = xSq + x * x
    dSq = dSq + d * d
    px = points[i + 2] - x0
    py = points[i + 3] + 0.0
    d = py - y
    sum = sum + (x + px) * d
    xSq = xSq + px * px
    dSq = dSq + d * d
  end
  local d = y1 - py
  sum = sum + px * d
  dSq = dSq + d * d
  -- areaSignOf's test written out (a call costs more than the test)
  local k = (n / 2 + 8) * 2^-50
  if not (sum * sum > k * k * xSq * dSq) then   -- luacheck: ignore 581 (NaN is uncertain)
    checkFinitePoints(points, n, "polygonWindingOrder", "points", 3)
    shoelaceExact(points, n)
    sum = expSign()
  end
  if sum > 0 then return "cw" elseif sum < 0 then return "ccw" end
  return nil
end

-- Twice the signed area, summed exactly and rounded once: the rare path of polygonArea (terms
-- that overflowed) and of polygonAreaAccurate (a sum its bound cannot vouch for). Raises fname's
-- error, at its caller's caller, for a NaN or infinite coordinate.
local function twiceAreaExact(points, n, fname)
  checkFinitePoints(points, n, fname, "points", 4)
  local s = shoelaceExact(points, n)
  return expCompress() / s / s
end

--- The area (non-negative) by the shoelace formula, relative to the first vertex.
-- @return area; nil for fewer than 3 points. Off by a few ulps for ordinary polygons at any
-- offset; a self-intersecting polygon's lobes count with their winding's sign. An area that
-- overflows is infinite; a non-finite coordinate raises an error.
function polygon.polygonArea(points)
  if type(points) ~= "table" or #points % 2 ~= 0 then checkPoints(points, "polygonArea") end
  local n = #points
  if n < 6 then return nil end
  -- shoelace's sum alone, unrolled as in polygonWindingOrder: the loop that sums the squares
  -- too took this from 0.92 to 1.19 times the tutorial's time on Lua 5.4 and from 0.81 to
  -- 0.97 on LuaJIT (targets 1.1 and 1.0), measured as in polygonWindingOrder
  local x0, y1 = points[1] + 0.0, points[2] + 0.0
  local px, py, sum = 0.0, y1, 0.0
  local start = 3
  if n % 4 == 0 then
    px, py = points[3] - x0, points[4] + 0.0
    sum, start = px * (py - y1), 5
  end
  for i = start, n - 3, 4 do
    local x = points[i] - x0
    local y = points[i + 1]   -- converted by its differences, as in polygonWindingOrder
    sum = sum + (px + x) * (y - py)
    px = points[i + 2] - x0
    py = points[i + 3] + 0.0
    sum = sum + (x + px) * (py - y)
  end
  sum = sum + px * (y1 - py)
  if sum - sum ~= 0 then
    -- NaN or infinite: a non-finite coordinate (an error), or terms that overflowed, whose
    -- exact sum (scaled) may still be finite
    sum = twiceAreaExact(points, n, "polygonArea")
  end
  return (sum < 0 and -sum or sum) * 0.5
end

--- The exact area of the given doubles, rounded to within one ulp.
-- From 65 to 4,096 vertices first a split in two passes (below); up to 64 vertices a split in one
-- pass, over the vertices on LuaJIT, over the edges on PUC Lua (below that); where their tests
-- after the loop fail: a compensated sum (Ogita, Rump and Oishi's Dot2) of 2A = sum over vertices
-- of x_i (y_{i+1} - y_{i-1}), with every difference split into hi + lo exactly (TwoSum) and every
-- x * hi product too (TwoProduct): its error is below eps |2A| plus 16 eps^2 m^2 T, T the sum of
-- |products| (bounded through their squares, which need no branch or abs). When that second part
-- could reach a quarter ulp of the result the area is summed exactly as an expansion instead
-- (several times slower). The x are not taken relative to vertex 1 (as shoelace does): far from
-- the origin that makes T larger, but the test below still passes while T / |2A| is below about
-- 2^37 at 16 vertices (2^27 for the benchmark's polygons at 1e9), and dropping the x differences'
-- TwoSums took this from 3.8 to 3.3 times polygonArea's time on Lua 5.4 (interleaved rounds on
-- bench/workloads.lua's ordinary polygons).
-- @return area; nil for fewer than 3 points. A non-finite coordinate raises an error.
function polygon.polygonAreaAccurate(points)
  if type(points) ~= "table" or #points % 2 ~= 0 then checkPoints(points, "polygonAreaAccurate") end
  local n = #points
  if n < 6 then return nil end
  local m = n / 2
  -- Both splits round every coordinate to a multiple of a quantum q, a power of two from the
  -- polygon's size guessed from vertex 1 and the middle vertex: g = |x_k - x_1| + |y_k - y_1|
  -- (abs is a call on PUC), q 2^-20 times the power of two above g. With sigma = 2^53 q and
  -- |v| <= 2^52 q, vh = (v + sigma) - sigma (Rump, Ogita and Oishi's ExtractScalar) is v
  -- rounded to a multiple of q, exactly, and vl = v - vh is exact and at most q; beyond,
  -- |vh| > 2^51 q, so a bound on every |vh| below that bounds every |v|.
  -- One quantum serves both axes, guessed from one pair of vertices: from two pairs (1 and m
  -- too) the guess cost 10 more Lua 5.4 instructions a call (368 against 358 on
  -- bench/workloads.lua's ordinary polygons, each of which passes the tests either way); a
  -- polygon far narrower than long, or whose middle vertex lies near vertex 1, only fails the
  -- tests sooner. (Beyond 4,096 vertices the large split's bound on its float part fails for
  -- spiky polygons: on bench/workloads.lua's large star it is 0.09, 0.17, 1.1 and 31 times what
  -- the test allows at 2,048, 4,096, 16,384 and 100,000 vertices, on its convex polygon 0.04,
  -- 0.09, 0.5 and 2.7.)
  if JIT and m <= 64 then
    -- LuaJIT up to 64 vertices: a split of the same kind (see above) in one pass, one vertex a
    -- step and no branch. Up to sign, twice the area is the sum over vertices of X_k D_k with
    -- X_k = x_k - x0h (x0h: x_1's rounded part; the D_k sum to 0, so the shift changes
    -- nothing) and D_k = y_{k-1} - y_{k+1}. In the split's parts X_k = X + xl (X = xh - x0h)
    -- and D_k = dh + dlExact (dh = yh_{k-1} - yh_{k+1}, dlExact = yl_{k-1} - yl_{k+1}): the
    -- term is X dh, summed exactly in hi, plus X dlExact + xl (dh + dlExact), small, summed in
    -- floating point in lo (dl, dlExact rounded). 26 floating-point operations a vertex against
    -- Dot2's 33: about 750 machine instructions a call against 944 (cachegrind, the difference
    -- of 500 and 1,500 passes of luajit bench/area_small.lua --alone FILE polygonAreaAccurate
    -- ord PASSES; polygonArea 391).
    -- Each step splits its neighbours' y again, carrying no part from step to step: with the
    -- four y parts carried (two fewer splits a vertex) the traces that left the loop failed to
    -- compile ("NYI: register coalescing too complex", 291 and 385 aborts in 3 and 6 of 16
    -- runs of `bash bench/aborts.sh 16 polygonAreaAccurate`; 0 in 32 runs so, as with Dot2
    -- alone), for about 3 % more time (`luajit bench/area_small.lua --alone FILE
    -- polygonAreaAccurate ord 20000`, three alternating runs: 70.0-71.6 -> 72.7-76.4 ns). The
    -- middle vertex comes from integer operations: m - m % 2 + 1 is a floating-point floor on
    -- LuaJIT, on the path to every split; the same instructions, but it cost 3 to 8 ns a call
    -- (luajit bench/area_small.lua --alone, alternating runs).
    local x1, y1 = points[1], points[2]
    local k = (n - n % 4) / 2 + 1
    local g = abs(points[k] - x1) + abs(points[k + 1] - y1)
    -- sigma = 2^53 q, the power of two at or above 2^33 g: (t + u) - t rounds to it, or to 0
    -- when u is one (a tie, rounded to even t), which max turns into u
    local t, u = g * 2^86, g * 2^33
    local sigma = max((t + u) - t, u)
    local x0h = (x1 + sigma) - sigma
    -- vertex k's term from its x and the y of its neighbours (yp before, yn after), each split
    -- again where it is read: no part carried from step to step
    local hi, lo, sqSum = 0.0, 0.0, 0.0   -- sqSum: the sum of X^2 + dh^2
    for i = 3, n - 3, 2 do
      local x, yp, yn = points[i], points[i - 1], points[i + 3]
      local xh = (x + sigma) - sigma
      local xl = x - xh
      local X = xh - x0h
      local yph = (yp + sigma) - sigma
      local ynh = (yn + sigma) - sigma
      local dh = yph - ynh
      local dl = (yp - yph) - (yn - ynh)
      hi = hi + X * dh
      lo = lo + (X * dl + xl * (dh + dl))
      sqSum = sqSum + (X * X + dh * dh)
    end
    -- vertex 1 (X = 0: its term is all in lo) and vertex m, across the wrap
    local yp, yn = points[n], points[4]
    local yph, ynh = (yp + sigma) - sigma, (yn + sigma) - sigma
    local dh, dl = yph - ynh, (yp - yph) - (yn - ynh)
    lo = lo + (x1 - x0h) * (dh + dl)
    sqSum = sqSum + dh * dh
    local x = points[n - 1]
    local xh = (x + sigma) - sigma
    local xl = x - xh
    local X = xh - x0h
    yp, yn = points[n - 2], y1
    yph, ynh = (yp + sigma) - sigma, (yn + sigma) - sigma
    dh, dl = yph - ynh, (yp - yph) - (yn - ynh)
    local twice = (hi + X * dh) + (lo + (X * dl + xl * (dh + dl)))
    sqSum = sqSum + (X * X + dh * dh)
    local q = sigma * 2^-53
    local qSq = q * q
    -- The tests (with g in [2^-120, 2^120], 2^33 g and 2^86 g are exact, q >= 2^-140):
    -- (1) sqSum <= 2^53 q^2, rounded by less than 1% (m <= 64): every |X| and |dh| is below
    --     2^26.6 q. (2) |x_1|, |y_1|, |y_2| <= 2^49 q: x0h and y_1's, y_2's parts are exact.
    --     Then every |xh| < 2^52 q (else |X| > 2^51 q), so every x split is exact and X too;
    --     each y_j is joined to y_1 or y_2 by a chain of dh (y_{k-1} to y_{k+1}), and the first
    --     |yh| >= 2^52 q along one would follow one below 2^49.1 q (the sum of |dh| is below
    --     sqrt(m sqSum) < 2^30 q) with a |dh| > 2^51 q: so every y split and dh is exact.
    --     Every |X dh| and partial sum of hi is below sqSum / 2 < 2^53 q^2: hi is exact.
    -- (3) lo's error: each term's rounding (dl, dh + dl, two products, one sum) errs by at
    --     most 4.01 eps U_k, U_k = 2 q |X| + q (|dh| + 2 q) (|dlExact| <= 2 q, |xl| <= q), and
    --     the m - 1 additions to lo by (m - 1) eps sum U_k at most: 1.01 (m + 4) eps sum U_k
    --     in all, where sum U_k <= q sqrt(5.06 m sqSum) + 2 m q^2 (Cauchy-Schwarz, and 1% for
    --     sqSum's rounding). That is at most 2^-56 |twice| (an eighth of an ulp, so twice, hi +
    --     lo rounded once, is within 0.75 ulp of twice the area) when
    --     1.03 (m + 4)^2 2 (5.06 m q^2 sqSum + 4 m^2 q^4) <= 2^-6 twice^2, which
    --     668 (m + 4)^2 m q^2 (sqSum + m q^2) <= twice^2 implies: tested with 2^10 for 668, room
    --     for the test's own rounding. It passes only for |twice| >= 2^-280, so products that
    --     underflow (an absolute error of 2^-1075 each) stay far inside that room. NaN fails
    --     every test. (LuaJIT has no integers: no + 0.0 here.)
    if g >= 2^-120 and g <= 2^120 and sqSum <= 2^53 * qSq
      and max(abs(x1), abs(y1), abs(points[4])) <= 2^49 * q
      and 2^10 * (m + 4) * (m + 4) * m * qSq * (sqSum + m * qSq) <= twice * twice then
      return abs(twice) * 0.5
    end
  elseif m <= 4096 then
    local x1, y1 = points[1] + 0.0, points[2] + 0.0
    local k = m - m % 2 + 1   -- the middle vertex, as the flat index of its x
    local g = points[k] - x1
    if g < 0 then g = -g end
    local d = points[k + 1] - y1
    if d < 0 then g = g - d else g = g + d end
    if g >= 2^-120 and g <= 2^120 then
      -- the power of two above g: (g 2^53 + g) - g 2^53 rounds to it, or to 0 when g is one
      local t = g * 2^53
      local q = (t + g) - t
      if q == 0 then q = g end
      q = q * 2^-20
      local sigma = q * 2^53
      local qSq = q * q
      if m > 64 then
        -- Twice the area as sum over vertices of x_k (y_{k-1} - y_{k+1}) (the sign does not
        -- matter): with dh = yh_{k-1} - yh_{k+1} and dl = yl_{k-1} - yl_{k+1} (dl rounded),
        -- each term is xh dh + (x dl + xl dh), the first a multiple of q^2 summed exactly in
        -- hi, the second small and summed in floating point in lo. The odd vertices' terms
        -- take the even vertices' y, and the even ones the odd: one pass over each half, each
        -- carrying only the split of the y before it (two values, not four: on LuaJIT four
        -- left the loop moving values between registers), the last term wrapping round to
        -- y_1. Alongside: sx = sum xh^2, sd = sum dh^2 and l2, the sum of lo^2 after every
        -- second term, which bound everything the tests after the loops need with no branch,
        -- no call and no abs per vertex (tracking the largest |x|, |dh| and partial sum with
        -- math.max and math.abs instead took 2.8 times polygonArea's time at 1,000 vertices on
        -- LuaJIT against 2.3 with a sum of squares, in one run of interleaved rounds; PUC Lua
        -- would pay a call for each).
        -- On LuaJIT this loop is bound by its floating-point additions, 13.5 a vertex (one
        -- fewer a vertex took 9% off its time, one fewer multiplication nothing): so x is
        -- taken as it is, not relative to vertex 1 (one more subtraction a vertex, 7% more
        -- time). Instead x and y swap roles when |x_1| > |y_1| (the term becomes
        -- y_k (x_{k-1} - x_{k+1}), of opposite sign; the index arithmetic costs LuaJIT no
        -- time): a polygon far from the origin along one axis passes the tests below; one far
        -- along both fails them and takes Dot2 (bench/workloads.lua's polygons of 1,000
        -- vertices moved by (d, d): all pass at d = 8 times their radius, none at 32).
        -- Below, x and y name the coordinates in their roles.
        -- a: 1 when the roles swap; the flat index of a term's x plus yNext is that of the
        -- next vertex's y (3, or 1 for the next vertex's x when swapped)
        local a = (x1 < 0 and -x1 or x1) > (y1 < 0 and -y1 or y1) and 1 or 0
        local yNext = 3 - 2 * a
        local yNext2 = yNext + 4
        local yFirst = points[2 - a] + 0.0
        local hi, lo, sx, sd, l2 = 0.0, 0.0, 0.0, 0.0, 0.0
        local yStart = points[n - a] + 0.0   -- the first pass begins at x_1 with y_m before it
        for start = 1, 3, 2 do
          local yhP = (yStart + sigma) - sigma
          local ylP = yStart - yhP
          for j = start + a, n - 7 + a, 8 do
            -- two terms, at x_k and x_{k+2}; each difference is taken where the older y's
            -- part was (luajit: no move between registers but the carried pair's)
            local x = points[j]
            local y = points[j + yNext]
            local x2 = points[j + 4]
            local y2 = points[j + yNext2]
            local xh = (x + sigma) - sigma
            local xl = x - xh
            local yh = (y + sigma) - sigma
            local yl = y - yh
            local dh = yhP - yh
            local dl = ylP - yl
            lo = lo - (x * dl + xl * dh)
            hi = hi - xh * dh
            sx = sx + xh * xh
            sd = sd + dh * dh
            xh = (x2 + sigma) - sigma
            xl = x2 - xh
            yhP = (y2 + sigma) - sigma
            ylP = y2 - yhP
            dh = yh - yhP
            dl = yl - ylP
            lo = lo - (x2 * dl + xl * dh)
            hi = hi - xh * dh
            sx = sx + xh * xh
            sd = sd + dh * dh
            l2 = l2 + lo * lo
          end
          -- the pass's last terms (at most two), one a step; the last of all takes y_1
          local i = n - 7 >= start and n + 1 - (n - 7 - start) % 8 or start
          while i < n do
            local x = points[i + a]
            local y = i + 3 <= n and points[i + 3 - a] or yFirst
            local xh = (x + sigma) - sigma
            local xl = x - xh
            local yh = (y + sigma) - sigma
            local yl = y - yh
            local dh = yhP - yh
            local dl = ylP - yl
            lo = lo - (x * dl + xl * dh)
            hi = hi - xh * dh
            sx = sx + xh * xh
            sd = sd + dh * dh
            l2 = l2 + lo * lo
            yhP, ylP = yh, yl
            i = i + 4
          end
          yStart = yFirst   -- the second pass begins at x_2 with y_1 before it
        end
        local twice = hi + lo
        -- The tests, each squared sum rounded by less than m eps relative (room below):
        -- (1) sx <= 2^100 q^2: every |xh| <= 2^50 q, so |x| <= 2^50 q + q and |xl| <= q.
        -- (2) y_m and y_1 (the passes' first y) rounded within 2^48 q of 0, and
        --     m sd <= 2^96 q^2: every further yh is its pass's first one minus a sum of dh,
        --     of magnitude at most sqrt(m sd) <= 2^48 q (Cauchy-Schwarz), so every |yh| <=
        --     2^49 q, |y| <= 2^49 q + q and |yl| <= q.
        -- (3) sx sd <= 2^104 q^4: sum |xh dh| <= sqrt(sx sd) <= 2^52 q^2, so every product
        --     and partial sum of hi is a multiple of q^2 below 2^53 q^2: hi is exact.
        -- (4) lo's error: each term errs by at most 3.01 eps U_k, U_k = 2 q |x| + q |dh| >=
        --     |x dl| + |xl dh| (dl rounded, two products, one sum), and each subtraction from
        --     lo by eps |lo| after it. The |lo| after the first term of a loop step is at most
        --     the |lo| after the second plus 1.001 U_k, and l2 sums the squares of the others,
        --     at most m / 2 + 4 of them. So the error is below
        --     1.02 eps (2 sqrt((m / 2 + 4) l2) + 4.02 sum U_k), where sum U_k is below
        --     2 q sqrt(m sx) + 2 m q^2 + q sqrt(m sd), 1.02 covering the rounding of this
        --     bound. Kept below 2^-56 |twice| (NaN fails), a quarter ulp of the result with
        --     room: twice, hi + lo rounded once, is then within 0.75 ulp of twice the area.
        if sx <= 2^100 * qSq and m * sd <= 2^96 * qSq and sx * sd <= 2^104 * qSq * qSq then
          local yhLast, yhFirst = (points[n - a] + sigma) - sigma, (yFirst + sigma) - sigma
          local errBound = 1.02 * 2^-53 * (2 * sqrt((m / 2 + 4) * l2)
            + 4.02 * (2 * q * sqrt(m * sx) + 2 * m * qSq + q * sqrt(m * sd)))
          local size = twice < 0 and -twice or twice
          if errBound <= 2^-56 * size and yhLast * yhLast <= 2^96 * qSq
            and yhFirst * yhFirst <= 2^96 * qSq then
            return size * 0.5
          end
        end
      else
        -- PUC Lua up to 64 vertices: twice the area is sum over edges i -> j of
        -- (X_i + X_j)(y_j - y_i), X = x - (x_1 rounded): of the rounded parts, sh = Xh_i + Xh_j
        -- and dh = yh_j - yh_i are exact multiples of q, and so is every sum of their
        -- products, while below 2^53 q^2: that sum is exact. The rest,
        -- sh (yl_j - yl_i) + (Xl_i + Xl_j)(y_j - y_i), is small and summed in floating point.
        -- About 26 Lua 5.4 instructions per vertex against Dot2's 42 below.
        local x0h = (x1 + sigma) - sigma
        -- the parts of the edge's first vertex (xHi = xh - x0h): the last vertex first
        local x, y = points[n - 1], points[n]
        local xh, yh = (x + sigma) - sigma, (y + sigma) - sigma
        local xHi, xLo, yLo = xh - x0h, x - xh, y - yh
        -- hi, lo and sqSum (the sum of sh^2 + dh^2) of the edges
        local hi, lo, sqSum = 0.0, 0.0, 0.0
        local start = 1
        if m % 2 == 1 then   -- an odd number of edges: one before the pairs
          x, y = points[1], points[2]
          local x2h, y2h = (x + sigma) - sigma, (y + sigma) - sigma
          local x2Hi, x2Lo, y2Lo = x2h - x0h, x - x2h, y - y2h
          local sh, dh = xHi + x2Hi, y2h - yh
          local dl = y2Lo - yLo
          hi, lo = sh * dh, sh * dl + (xLo + x2Lo) * (dh + dl)
          sqSum = sh * sh + dh * dh
          xHi, xLo, yh, yLo, start = x2Hi, x2Lo, y2h, y2Lo, 3
        end
        -- two edges per step, the second writing the parts the first reads (no moves), one
        -- addition to each sum per step
        for i = start, n - 3, 4 do
          x = points[i]
          y = points[i + 1]
          local x2h, y2h = (x + sigma) - sigma, (y + sigma) - sigma
          local x2Hi, x2Lo, y2Lo = x2h - x0h, x - x2h, y - y2h
          local sh, dh = xHi + x2Hi, y2h - yh
          local dl = y2Lo - yLo
          local lo1 = sh * dl + (xLo + x2Lo) * (dh + dl)
          x = points[i + 2]
          y = points[i + 3]
          xh = (x + sigma) - sigma
          yh = (y + sigma) - sigma
          xHi = xh - x0h
          xLo = x - xh
          yLo = y - yh
          local sh2, dh2 = x2Hi + xHi, yh - y2h
          local dl2 = yLo - y2Lo
          hi = hi + (sh * dh + sh2 * dh2)
          lo = lo + (lo1 + (sh2 * dl2 + (x2Lo + xLo) * (dh2 + dl2)))
          sqSum = sqSum + ((sh * sh + dh * dh) + (sh2 * sh2 + dh2 * dh2))
        end
        local twice = hi + lo
        -- With sSq = sum sh^2 and dSq = sum dh^2 (sqSum = sSq + dSq): every |Xh| and
        -- |yh - yh_1| is at most the sum of |sh| (|dh|) along the walk from vertex 1, below
        -- sqrt(m sSq) (sqrt(m dSq)) <= 2^50 q; with |x_1|, |y_1| <= 2^50 q every |v| is then
        -- below sigma / 2, and every sh, dh exact (the first test).
        -- sum |sh dh| <= sqrt(sSq dSq) <= sqSum / 2 <= 2^50 q^2 keeps every partial sum of hi
        -- exact (the second). The float part's error is below (m + 6) eps B (m additions and
        -- 6 roundings per term), B = 2 q sum |sh| + 2 q sum |dh| + 4 m q^2 over all edges
        -- (|yl|, |Xl| <= q); B^2 <= 12 m q^2 (sqSum + 4 m q^2), and 4 (m + 6) B <= |twice| is
        -- tested squared, 16 * 12 rounded up to 256 (the third). The factors of 4 between 2^50
        -- and 2^53 cover the rounding of the sums of squares.
        if x1 * x1 + y1 * y1 + m * sqSum <= 2^100 * qSq and sqSum <= 2^51 * qSq
          and 256 * (m + 6) * (m + 6) * m * qSq * (sqSum + 4 * m * qSq) < twice * twice then
          return (twice < 0 and -twice or twice) * 0.5
        end
      end
    end
  end
  local splitter = SPLITTER   -- a register, not an upvalue, in the loop
  -- x and y of the vertex whose term is summed next, and the y before it: the last vertex first
  -- (so that every next y is points[i + 1], with no test for the end). x is not converted: a
  -- Lua 5.3+ integer x meets a float in every operation, which converts it as + 0.0 would
  local x, y, yPrev = points[n - 1], points[n] + 0.0, points[n - 2] + 0.0
  local sum, err, magSq = 0.0, 0.0, 0.0
  for i = 1, n - 1, 2 do
    local yNext = points[i + 1] + 0.0
    local dh = yNext - yPrev              -- D = dh + dl exactly (TwoSum)
    local bv = yNext - dh
    local dl = (yNext - (dh + bv)) + (bv - yPrev)
    -- x dh = p + e exactly: twoProduct written out, as calling it took this from 3.2 to 4.1
    -- times polygonArea's time on Lua 5.4 (no change on LuaJIT), in 61 interleaved rounds on
    -- bench/workloads.lua's ordinary polygons
    local p = x * dh
    local c = splitter * x
    local ah = c - (c - x)
    local al = x - ah
    c = splitter * dh
    local bh = c - (c - dh)
    local bl = dh - bh
    local e = al * bl - (((p - ah * bh) - al * bh) - ah * bl)
    local t = sum + p                     -- sum + p = t + (TwoSum error)
    bv = t - sum
    err = err + ((sum - (t - bv)) + (p - bv)) + (e + x * dl)
    sum = t
    magSq = magSq + p * p
    x = points[i]
    yPrev = y
    y = yNext
  end
  local twice = sum + err
  -- Dot2's bound on its rounding beyond the final one is dot2Bound m^2 T, dot2Bound = 16 eps^2
  -- = 2^-102: the m TwoSum errors are each below eps |partial sum| <= eps T, and summing them
  -- with the product errors adds at most 3m eps times that; 16 leaves room for the terms' own
  -- parts. T <= sqrt(m magSq) (Cauchy-Schwarz), so the test is dot2Bound m^2 T < eps |twice| / 4
  -- (eps / 4 = 2^-55), squared. NaN and infinity fail it, and so do squares that underflow to 0
  -- (strict <). The powers of two are literals, which the compiler folds.
  local quarterUlp, m2 = 2^-55 * twice, m * m
  local boundSq = 2^-204 * m2 * m2 * m * magSq
  if not (boundSq < quarterUlp * quarterUlp) then   -- luacheck: ignore 581
    twice = twiceAreaExact(points, n, "polygonAreaAccurate")
  end
  return (twice < 0 and -twice or twice) * 0.5
end

-- The careful walk for polygonType: every turn through cross's exact fallback, repeated vertices
-- skipped, collinear vertices told apart from spikes. Taken only when the one-pass filter below
-- cannot decide (a turn within rounding of zero, a repeated vertex, an overflow or a non-finite
-- coordinate, which it checks for first). Every coordinate is converted before it is compared.
local function typeCareful(points, n)
  checkFinitePoints(points, n, "polygonType", "points", 4)
  local cx, cy = points[n - 1] + 0.0, points[n] + 0.0
  local j = n - 3
  while j > 0 and points[j] + 0.0 == cx and points[j + 1] + 0.0 == cy do j = j - 2 end
  if j < 0 then return nil end   -- all points are one point
  local px, py = points[j] + 0.0, points[j + 1] + 0.0
  local turn, spike = 0, false
  local flips, dir = 0, 0
  for i = 1, n - 1, 2 do
    local qx, qy = points[i] + 0.0, points[i + 1] + 0.0
    if qx ~= cx or qy ~= cy then
      local s = cross(px, py, cx, cy, cx, cy, qx, qy)
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

-- The one-pass filter of polygonType: "convex" or "concave" when every turn's sign is certain
-- from floating point, false when typeCareful must decide. The turn at vertex c (edge e into it,
-- f out of it) is e x f = l - r, l = ex fy, r = ey fx: cross's arithmetic written out, as a call
-- per vertex costs the PUC interpreters half the loop and LuaJIT a side trace per branch.
-- Its error is below CROSS_BOUND (|l| + |r|) (Shewchuk's bound); a semi-static filter bounds
-- it for all turns at once. Convex means all turns certainly one sign and the edges' x
-- direction changing sign exactly twice around the polygon (twice per winding, so four times
-- or more for a pentagram): with every turn below a half turn, the signs of dx run
-- + (0) - (0) + once per winding.
local polygonType
if JIT then
  -- LuaJIT (no integers, so no conversions): no branch in the loop. math.min, math.max and
  -- math.abs compile to single instructions; data-dependent branches became side traces and
  -- made this loop over twice the baseline's time (bench/run.lua --only 'polygonType ord').
  -- The sign of the product of consecutive edges' dx is taken without a branch: in the exact
  -- range a nonzero product of coordinate differences is at least 2^-998, so 2^1000 times it
  -- clamps to +-1. Around m edges whose turns are all certain, no two consecutive dx are 0 and
  -- each winding changes the sign twice (directly, or through one 0 which zeroes two products),
  -- so the sum of those signs is m - 4k for k windings.
  -- The filter sums |l + r|, not |l| + |r|: when l and r differ in sign no cancellation can
  -- happen, and |l + r| <= |s| passes anyway (as in cross). Any NaN or overflow makes errSum
  -- NaN or infinite, so nothing is certain.
  -- The turns at the last vertex, at vertex 1 and at vertex 2 are taken before the loop, and
  -- when they disagree the call ends there (58 of the 100 stars among bench/run.lua's ordinary
  -- polygons end there; 44 with the first two turns only, when `luajit bench/run.lua --only
  -- '^polygonType ord'`, ten runs each alternating, gave medians of 1.195 and 1.23 with two,
  -- 1.165 and 1.18 with three). Only four sums cross that branch: its side trace inherits
  -- little (with the first turns' differences and products alive there too it failed to
  -- compile in 1 of 4 runs, "NYI: register coalescing too complex").
  local function typeFiltered(points, n)
    local cx, cy = points[n - 1], points[n]
    local ex, ey = cx - points[n - 3], cy - points[n - 2]
    local lo, hi, errSum, dirAgree
    do
      local qx, qy = points[1], points[2]
      local fx, fy = qx - cx, qy - cy
      local px, py = points[3], points[4]
      local gx, gy = px - qx, py - qy
      local hx, hy = points[5] - px, points[6] - py
      local l, r = ex * fy, ey * fx
      local l2, r2 = fx * gy, fy * gx
      local l3, r3 = gx * hy, gy * hx
      local s, s2, s3 = l - r, l2 - r2, l3 - r3   -- the turns at the last vertex, at 1 and at 2
      lo, hi = min(s, s2, s3), max(s, s2, s3)
      errSum = abs(l + r) + abs(l2 + r2) + abs(l3 + r3)
      dirAgree = min(1, max(-1, ex * fx * 2^1000)) + min(1, max(-1, fx * gx * 2^1000))
        + min(1, max(-1, gx * hx * 2^1000))
    end
    if lo * hi < 0 then
      local bound = CROSS_BOUND * errSum
      if lo < -bound and hi > bound then return "concave" end
      return false
    end
    cx, cy = points[5], points[6]
    ex, ey = cx - points[3], cy - points[4]
    for i = 7, n - 1, 2 do
      local qx, qy = points[i], points[i + 1]
      local fx, fy = qx - cx, qy - cy
      local l, r = ex * fy, ey * fx
      local s = l - r
      lo, hi = min(lo, s), max(hi, s)
      errSum = errSum + abs(l + r)
      dirAgree = dirAgree + min(1, max(-1, ex * fx * 2^1000))
      cx, cy, ex, ey = qx, qy, fx, fy
      if lo * hi < 0 then break end   -- turns of both signs seen: concave if certain
    end
    local bound = CROSS_BOUND * errSum
    if lo > bound or hi < -bound then
      if dirAgree == n / 2 - 4 then return "convex" end
      return "concave"
    end
    if lo < -bound and hi > bound then return "concave" end
    return false
  end
  polygonType = function(points)
    local n = checkPoints(points, "polygonType")
    if n < 6 then return nil end
    local kind = typeFiltered(points, n)
    if kind == false then kind = typeCareful(points, n) end
    return kind
  end
else
  -- PUC Lua: math.min/max/abs are C calls (about 16 ns each, a Lua call about 13), so one
  -- function with a branchy loop, one comparison per turn in the common case. The turns at
  -- the last vertex and at vertex 1 come first: the first one's sign picks ySign, which flips y
  -- so that every turn of a convex polygon is positive, and a second turn against it ends the
  -- call early (most concave polygons turn both ways within their first few vertices). The loop
  -- takes two turns per step, the second writing the vertex and edge the first reads, so no
  -- value is moved; with an odd number of vertices one turn is left after it. The vertex the
  -- first turn reads is not converted (its differences with the converted one convert it).
  -- The filter bounds every |l + r| by the square root of the sum of their squares and
  -- compares squares (NaN or overflow only make it fail; squares that underflow come with an
  -- lo that does too). Windings are counted without a direction variable: with every turn
  -- positive and below a half turn, the edges' direction turns one way and leaves the half
  -- plane dx > 0 exactly once per winding (a turn cannot cross the half plane dx <= 0, a half
  -- turn wide), so the turns from an edge with dx > 0 to one with dx <= 0 count the windings.
  -- Lua 5.4 instructions per call on bench/workloads.lua's ordinary polygons (a debug.sethook
  -- count hook): 180 with one turn per step, its moves and a direction variable, 153 so (the
  -- tutorial's 132), lua5.4 bench/run.lua --only '^polygonType ord$' 1.5-1.6 -> 1.35-1.4;
  -- walking a polygon with a negative first turn backwards instead of flipping y took 167
  -- (a longer start than the loop saves on 4 to 16 vertices).
  polygonType = function(points)
    if type(points) ~= "table" then checkPoints(points, "polygonType") end
    local n = #points
    if n % 2 ~= 0 then checkPoints(points, "polygonType") end
    if n < 6 then return nil end
    local cx, cy = points[n - 1] + 0.0, points[n] + 0.0
    local ex, ey = cx - points[n - 3], cy - points[n - 2]
    local qx, qy = points[1] + 0.0, points[2] + 0.0
    local fx, fy = qx - cx, qy - cy
    local l, r = ex * fy, ey * fx
    local s = l - r   -- the turn at the last vertex, from edge e to edge f
    local ySign = 1.0
    if s < 0 then   -- (one statement each: a multiple assignment costs a move per value)
      ySign = -1.0
      s = -s
      qy = -qy
      fy = -fy
    end
    local firstTurn = s
    local e = l + r   -- the first turn's error bound is CROSS_BOUND |e|
    local firstBound = e * e
    -- A turn s <= 0 (or NaN) ends the walk: concave when it and the first turn are certain,
    -- as is a first turn of 0 or NaN.
    if s > 0 then
      local windings = 0
      if fx <= 0 and ex > 0 then windings = 1 end
      cx = points[3] + 0.0   -- the turn at vertex 1, from edge f to edge e
      cy = points[4] * ySign
      ex = cx - qx
      ey = cy - qy
      l = fx * ey
      r = fy * ex
      s = l - r
      if s > 0 then
        local lo = firstTurn
        if s < lo then lo = s end
        e = l + r
        local errSq = firstBound + e * e
        if ex <= 0 and fx > 0 then windings = windings + 1 end
        for i = 5, n - 3, 4 do
          qx = points[i]               -- the turn at c, from edge e to edge f
          qy = points[i + 1] * ySign
          fx = qx - cx
          fy = qy - cy
          l = ex * fy
          r = ey * fx
          s = l - r
          if s < lo then
            if not (s > 0) then break end   -- luacheck: ignore 581 (NaN too)
            lo = s
          end
          e = l + r
          errSq = errSq + e * e
          if fx <= 0 and ex > 0 then windings = windings + 1 end
          cx = points[i + 2] + 0.0     -- the turn at q, from edge f to edge e
          cy = points[i + 3] * ySign
          ex = cx - qx
          ey = cy - qy
          l = fx * ey
          r = fy * ex
          s = l - r
          if s < lo then
            if not (s > 0) then break end   -- luacheck: ignore 581
            lo = s
          end
          e = l + r
          errSq = errSq + e * e
          if ex <= 0 and fx > 0 then windings = windings + 1 end
        end
        if n % 4 == 2 and s > 0 then   -- an odd number of vertices: the turn at m - 1 is left
          qx = points[n - 1]
          qy = points[n] * ySign
          fx = qx - cx
          fy = qy - cy
          l = ex * fy
          r = ey * fx
          s = l - r
          if s < lo then lo = s end
          e = l + r
          errSq = errSq + e * e
          if fx <= 0 and ex > 0 then windings = windings + 1 end
        end
        if s > 0 and lo * lo > TURN_BOUND_SQ * errSq then
          if windings == 1 then return "convex" end
          return "concave"
        end
      end
    end
    if not (s > 0) then   -- luacheck: ignore 581
      -- both turns certain (compared squared: underflow or overflow only fails the test)
      e = l + r
      if s * s > TURN_BOUND_SQ * (e * e) and firstTurn * firstTurn > TURN_BOUND_SQ * firstBound then
        return "concave"
      end
    end
    local kind = typeCareful(points, n)
    return kind
  end
end

--- Whether the polygon is convex.
-- Checks every vertex (the tutorial skips the last one). Repeated consecutive vertices and
-- collinear vertices that go on forward are allowed; a zero turn that doubles back (a spike) is
-- concave, and so is a polygon whose turns all agree but which winds around more than once
-- (a pentagram): its edges' x directions change sign more than twice.
-- A non-finite coordinate raises an error once read (every NaN or infinity sends the filter
-- to the careful walk, which checks); a polygon found concave before one is read is concave.
-- @return "convex", "concave", or nil for fewer than 3 points or all points on one line. Exact.
polygon.polygonType = polygonType

-- The vertex sums of polygonCenter, each coordinate times scale (a power of two), compensated:
-- TwoSum carries each addition's rounding error into errX, errY.
local function vertexSums(points, n, scale)
  local sumX, sumY, errX, errY = 0.0, 0.0, 0.0, 0.0
  for i = 1, n - 1, 2 do
    local x, y = points[i] * scale, points[i + 1] * scale
    local t = sumX + x
    local v = t - sumX
    errX = errX + ((sumX - (t - v)) + (x - v))
    sumX = t
    t = sumY + y
    v = t - sumY
    errY = errY + ((sumY - (t - v)) + (y - v))
    sumY = t
  end
  return sumX + errX, sumY + errY
end

--- The centre as the tutorial defines it: the mean of the vertices.
-- Within an ulp or two of exact wherever the polygon is and whatever its size (compensated
-- sums; sums that overflow are redone on coordinates scaled down by a power of two).
-- @return cx, cy; nil for fewer than 3 points. A non-finite coordinate raises an error.
function polygon.polygonCenter(points)
  local n = checkPoints(points, "polygonCenter")
  if n < 6 then return nil end
  local m = n / 2
  local sumX, sumY = vertexSums(points, n, 1.0)
  if sumX - sumX ~= 0 or sumY - sumY ~= 0 then   -- NaN or infinite: rare, so check here
    checkFinitePoints(points, n, "polygonCenter", "points", 3)
    local scale = 1.0   -- finite coordinates whose sum overflowed: scale by 2^-k, 2^k >= m
    while scale * m > 1 do scale = scale * 0.5 end
    sumX, sumY = vertexSums(points, n, scale)
    return sumX / m / scale, sumY / m / scale
  end
  return sumX / m, sumY / m
end

-- The moment sum (u_i + u_j)(u_i v_j - u_j v_i) over the edges i -> j, as an exact expansion in
-- expansion of the coordinates times s; u at offset du, v at dv of each vertex (x moment: 0, 1).
local function momentExact(points, n, s, du, dv)
  expLen = 0
  local limit = 32   -- as in shoelaceExact: compress whenever the expansion has grown by 32
  local ui, vi = points[n - 1 + du] * s, points[n - 1 + dv] * s
  for k = 1, n - 1, 2 do
    local uj, vj = points[k + du] * s, points[k + dv] * s
    -- (u_i + u_j)(u_i v_j - u_j v_i) = u_i^2 v_j + u_i u_j v_j - u_i u_j v_i - u_j^2 v_i
    expAddTriple(ui, ui, vj)
    expAddTriple(ui, uj, vj)
    expAddTriple(-ui, uj, vi)
    expAddTriple(-uj, uj, vi)
    ui, vi = uj, vj
    if expLen > limit then
      expCompress()
      limit = expLen + 32
    end
  end
  return expCompress()
end

-- The centroid from exact sums (the rare path of polygonCentroid): twice the area and the two
-- moments as expansions, each rounded once, then divided: a few ulps of the centroid. The
-- coordinates are scaled by a power of two so that every product of three stays below 2^900;
-- exact unless some product of three coordinates underflows. nil for an exact area of zero.
local function centroidExact(points, n)
  -- 2^300 cubed is 2^900; the range must span 2^64
  local s = powerScale(largestMagnitude(points, n, 0.0), 2^236, 2^300)
  local sScaled = shoelaceExact(points, n)   -- twice the area, of the coordinates times sScaled
  local area2 = expCompress() * (s / sScaled) * (s / sScaled)
  if area2 == 0 then return nil end
  local momentX = momentExact(points, n, s, 0, 1)
  local momentY = -momentExact(points, n, s, 1, 0)   -- (y_i + y_j)(x_i y_j - x_j y_i), swapped
  return momentX / (3 * area2) / s, momentY / (3 * area2) / s
end

-- The fast path of polygonCentroid trusts its float sums while the fan's products have not
-- cancelled by more than this factor times m: a fat polygon's products add up to about m / pi
-- times twice its area, a sliver's (or a cancelling, self-intersecting one's) to far more.
local CANCELLATION_LIMIT = 64

--- The area centroid, the point a physics step rotates a uniform polygon about.
-- Float sums relative to vertex 1 for ordinary polygons; where they cancel (slivers, nearly
-- degenerate or self-cancelling polygons) exact sums instead: within a few ulps of the
-- coordinates' magnitude of the exact centroid either way.
-- @return cx, cy; nil for fewer than 3 points or zero (exact) signed area. A non-finite
-- coordinate raises an error.
function polygon.polygonCentroid(points)
  local n = checkPoints(points, "polygonCentroid")
  if n < 6 then return nil end
  local x0, y0 = points[1] + 0.0, points[2] + 0.0
  -- The sums below are cubic in the coordinates (relative to vertex 1): scale x and y each by a
  -- power of two to near 1 so that they neither overflow nor underflow, and scale back at the
  -- end (x by kx: the area scales by kx ky, the x moment by kx^2 ky). 2^-32 and 2^32 leave
  -- cubes between 2^-96 and 2^96 whatever the polygon's extent.
  local extentX, extentY = 0.0, 0.0
  for i = 3, n - 1, 2 do
    extentX, extentY = max(extentX, abs(points[i] - x0)), max(extentY, abs(points[i + 1] - y0))
  end
  local kx, ky = powerScale(extentX, 2^-32, 2^32), powerScale(extentY, 2^-32, 2^32)
  local area2, momentX, momentY, magnitude = 0.0, 0.0, 0.0, 0.0
  -- The three sums are compensated (TwoSum carries their rounding into errA, errX, errY):
  -- the plain running sums, mostly the area's, were the error at 1,000 vertices (up to 35 eps
  -- relative against the oracle, 3.3 with the compensation).
  local errA, errX, errY = 0.0, 0.0, 0.0
  -- relative to vertex 1, the edges from and to it add nothing: start at edge 2 -> 3
  local xi, yi = 0.0, 0.0
  for i = 3, n - 1, 2 do
    local xj, yj = (points[i] - x0) * kx, (points[i + 1] - y0) * ky
    local l, r = xi * yj, xj * yi
    local c = l - r
    local sum = area2 + c
    local v = sum - area2
    errA = errA + ((area2 - (sum - v)) + (c - v))
    area2 = sum
    local term = (xi + xj) * c
    sum = momentX + term
    v = sum - momentX
    errX = errX + ((momentX - (sum - v)) + (term - v))
    momentX = sum
    term = (yi + yj) * c
    sum = momentY + term
    v = sum - momentY
    errY = errY + ((momentY - (sum - v)) + (term - v))
    momentY = sum
    if JIT then   -- abs is one instruction there; the comparisons' exits were side traces
      magnitude = magnitude + abs(l) + abs(r)
    else          -- abs is a call on PUC Lua
      magnitude = magnitude + (l < 0 and -l or l) + (r < 0 and -r or r)
    end
    xi, yi = xj, yj
  end
  area2, momentX, momentY = area2 + errA, momentX + errX, momentY + errY
  local cx, cy
  -- NaN and infinite sums fail the test too
  if (area2 < 0 and -area2 or area2) * (CANCELLATION_LIMIT * n / 2) > magnitude then
    cx, cy = x0 + momentX / (3 * area2) / kx, y0 + momentY / (3 * area2) / ky
  else
    checkFinitePoints(points, n, "polygonCentroid", "points", 3)
    cx, cy = centroidExact(points, n)
    if cx == nil then return nil end
  end
  if cx - cx ~= 0 or cy - cy ~= 0 then
    -- Only outside the exact range: coordinates so small that products of three underflow, or
    -- of magnitudes too far apart for one scale each. Its vertex mean is finite and nearby.
    cx, cy = vertexSums(points, n, 1.0)
    cx, cy = cx / (n / 2), cy / (n / 2)
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
-- The walk carries whether the last vertex was at or below the ray's height (y >= the ray's y,
-- screen down) and reads an edge's x coordinates only where it crosses. x and y are converted
-- (+ 0.0), and so is every coordinate the walks subtract (cross converts its own), so that Lua
-- 5.3+ integers count as the doubles they convert to. Two walks, computing the same answer:
-- - containsByRuns, LuaJIT's (and PUC Lua's for |x| or |y| >= 2^53): the vertices come in runs
--   on one side of the ray's height, each walked by one numeric for loop with one comparison
--   per vertex, the same loop for both sides (a sign picks the side), so that LuaJIT's trace
--   of it is the walk that crosses nothing, whatever vertex it was recorded on; a crossing is
--   its side exit, counted without a branch by crossingCounts, and the walk goes on in the same
--   loop. Measured on LuaJIT (luajit bench/run.lua --only '^polygonContains cOrd', ten runs
--   each, medians): the previous walk, an inner while loop computing at-or-below as the number
--   min(1, max(0, (y' - y) 2^1200 + 1)) per vertex, 0.87; this loop as a repeat-until with a
--   floating-point index, 0.82; as a for loop (an integer index, bounds checks hoisted), 0.80.
--   A loop of its own for each side ran 0.63 to 0.8 in most runs but 4 to 6 times the
--   tutorial's time in 4 of 14: when one of the two short loops failed to become a trace
--   ("leaving loop in root trace"), the side traces of the other copied it unrolled, one per
--   run length, until LuaJIT gave up and interpreted. The loop with a branch per comparison
--   grew a tree of side traces that passed LuaJIT's limit of 100 per loop in some runs; one
--   loop over all vertices without a branch (the side test of every edge) took 1.07.
-- - PUC Lua's, written out in polygonContains (a call to it cost 0.03 of the tutorial's time on
--   Lua 5.4): per vertex one read and two comparisons, and at a crossing the x coordinates
--   compared with x first, the side test (a call of cross) only when x lies between them. The
--   coordinates are compared as they are, not converted (an instruction less each: 0.96 to 0.87
--   times the tutorial's time on Lua 5.4 for y): comparing a Lua 5.3+ integer with a double
--   below 2^53 in magnitude gives the converted integer's answer (the integer is then compared
--   as its exact double, or it is beyond 2^53 and so is its conversion, on the same side).
local containsByRuns
do
  -- 1 when the edge from vertex j to vertex i, which crosses the ray's height going down
  -- (dir = 2^600) or up (dir = -2^600), passes at or right of (x, y), else 0: its side test's
  -- sign times dir's, clamped without a branch (cross's filter written out, cross where it
  -- cannot vouch; a nonzero side is at least 2^-1074, so dir * side * 2^600 reaches 2^126).
  local function crossingCounts(points, j, i, x, y, dir)
    local x1, y1, x2, y2 = points[j - 1] + 0.0, points[j] + 0.0, points[i - 1] + 0.0, points[i] + 0.0
    local l, r = (x2 - x1) * (y - y1), (y2 - y1) * (x - x1)
    local side = l - r   -- its sign: cross(x1, y1, x2, y2, x1, y1, x, y)
    if not (abs(side) >= CROSS_BOUND * (abs(l) + abs(r))) then   -- luacheck: ignore 581
      -- (NaN and overflow too) through cross, not crossExact directly: called here, the side
      -- traces of crossExact's first branch failed to compile ("NYI: register coalescing too
      -- complex") and points near edges took 7 to 80 times the tutorial's time, 4 to 5 this way
      -- (luajit bench/run.lua --only 'polygonContains cEdge')
      side = cross(x1, y1, x2, y2, x1, y1, x, y)
    end
    return min(1, max(0, dir * side * 2^600 + 1))
  end

  containsByRuns = function(points, n, x, y)
    -- A run of vertices at or below the ray's height (sign = 2^600, tie = 0) ends at a vertex
    -- with (y' - y) 2^600 < 0; a run above it (sign = -2^600, tie = 2^-500) at one with
    -- -(y' - y) 2^600 < 2^-500, that is y' - y >= 0 (a nonzero difference of doubles is at least
    -- 2^-1074). The edge into that vertex crosses, going up after a run at or below (dir =
    -- -sign), down after one above. The numbers stay clear of subnormals, slow on x86 (with a
    -- tie of 2^-1074 the row took 1.2 to 1.3 times the tutorial's time, with 2^-500 about
    -- 0.84). y' - y converts a Lua 5.3+ integer y'.
    local above = min(1, max(0, (y - points[n]) * 2^600 * 2^600))   -- vertex n above: 1, else 0
    local sign, tie = (1 - 2 * above) * 2^600, above * 2^-500
    local crossings, i = 0, 0   -- vertex i = 0 stands for vertex n
    while true do
      local start = i + 2
      i = n + 2
      for k = start, n, 2 do
        if (points[k] - y) * sign < tie then i = k; break end
      end
      if i > n then break end
      -- j = n when i = 2, else i - 2
      crossings = crossings + crossingCounts(points, i - 2 + n * max(0, 3 - i), i, x, y, -sign)
      sign = -sign
      tie = 2^-500 - tie
    end
    return crossings % 2 == 1
  end
end

-- LuaJIT, 3 to 16 vertices: containsShort4, containsShort8, containsShort12 and containsShort16,
-- the same walk as straight-line code without a branch, over 4, 8, 12 or 16 vertices (the fewest
-- that hold the polygon's; one branch on n picks), built from firstSteps, fourSteps and lastEdge:
-- vertex k is read at flat index min(2k, n), so a shorter polygon repeats its last vertex, and
-- the edges between the copies have length 0 and cross nothing. Each edge adds to three sums:
-- count, 1 when it crosses the ray's height and its side test is certainly >= 0 (going down) or
-- <= 0 (going up); worst, more than 0 when it crosses and its side is not certain; total, its
-- determinant, so that an infinite or NaN one (overflow) shows in the sum. Unless worst is 0
-- and total finite, containsByRuns decides the call from the start (a point on or within a few
-- ulps of a crossing edge; differences from (x, y) beyond about 2^537, or crossing edges'
-- determinants below 2^-950). The side test is
-- the determinant of (p_j - q, p_i - q), whose sign is that of (p_i - p_j) x (q - p_j):
-- dx dy' - dy dx', certain when its magnitude is at least
-- (|dx| + |dy|) (|dx'| + |dy'|) 2^-50 (above Shewchuk's bound 3 eps (|l| + |r|), with room for
-- the roundings of the bound's own terms) and at least 2^-950 (so that products that underflow,
-- off by at most 2^-1075 each, stay within that room); the factors m = (|dx| + |dy|) 2^-25 +
-- 2^-475 are taken once per vertex. A certain determinant is then at least 2^-950, so that
-- g det 2^1000 clamps to 1 or 0 exactly. Measured with `TRACE_SEED=N LD_PRELOAD=/tmp/fixseed.so
-- setarch -R luajit bench/run.lua --only '^polygonContains cOrd$' --draws 1` (bench/fixseed.c),
-- N = 1..20: polygon.lua's side 48 to 54 ns in each (single runs up to 70 when the machine was
-- busy, the tutorial's side as slow then), where containsByRuns took 55 to 66 (the tutorial's
-- between 58 and 88); `--draws 8`: 0.72 and 0.74 of the tutorial's time (48 and 49 ns; process
-- medians 0.58 to 0.85), not 0.84 and 0.87 (56 and 60 ns).
-- Timed alone over the same queries (a loop of calls, the least of 30 passes), 8 vertices take
-- about 32 ns, 16 about 57, containsByRuns 42 to 60 at every size.
-- Tried and dropped:
-- - containsShort8 alone (4 to 8 vertices), containsByRuns for 9 to 16: as fast in most runs,
--   but in 1 of 10 (seed 6 of `--only '^polygonContains'`) 100 to 115 ns: the side exit for n > 16
--   reached containsByRuns' loops before they were traces, failed ("loop unroll limit reached",
--   "trace too long") and was left to the interpreter; the straight-line code has no loop to
--   wait for. A 10-vertex version alone: 1.4 times the tutorial's time in 1 of 20 seeds.
-- - the same step in a for loop over the vertices: 67 ns on 9 to 16 vertices, not 57.
-- - the vertices read before the edges (32 values live): spilled to the stack, 33.0 ns on 3 to 8
--   vertices where edge after vertex takes 32.1.
-- - worst as a max: 0 times an infinite bound is NaN, which math.max(worst, NaN) returned and
--   the next max dropped, with the worst before it (a wrong answer for a vertex at y = 1e308 among
--   ones near 1e-319); the sum keeps it, and then containsByRuns decides.
-- - without containsShort4 (quadrilaterals through containsShort8): the tiles (cTiles, every call
--   falling back) 61 to 102 ns, 45 to 79 with it.
-- Points on or near edges pay for both walks: `--only '^polygonContains'` took the tiles 45 to 79
-- ns where containsByRuns alone took 44 to 72, and the points near edges (cEdge) 73 to 107 where
-- it took 66 to 104 (both rows noisy from run to run, on either side).
local containsShort4, containsShort8, containsShort12, containsShort16
if JIT then
  -- Vertex k (its y at points[k]) relative to (x, y): dx, dy, 1 when it is above the ray's height
  -- (dy < 0: at most -2^-1074, times -2^1200 beyond 1), else 0, and its factor m of the bound.
  local function vertexFrom(points, k, x, y)
    local dx, dy = points[k - 1] - x, points[k] - y
    return dx, dy, min(1, max(0, dy * -2^600 * 2^600)), (abs(dx) + abs(dy)) * 2^-25 + 2^-475
  end

  -- The edge from vertex j to vertex i added to the sums. g = 1: it crosses going down (from
  -- above), -1: going up, 0: it does not cross; it counts when g det > 0 and det is certain.
  local function addEdge(count, worst, total, dxj, dyj, aj, mj, dxi, dyi, ai, mi)
    local g = aj - ai
    local det = dxj * dyi - dyj * dxi
    local c = g * g
    return count + min(1, max(0, g * det * 2^1000)), worst + c * max(0, mj * mi - abs(det)),
      total + det
  end

  -- The next vertex, at points[k], and the edge into it from the last one (dxj, dyj, aj, mj).
  local function step(points, k, x, y, count, worst, total, dxj, dyj, aj, mj)
    local dxi, dyi, ai, mi = vertexFrom(points, k, x, y)
    count, worst, total = addEdge(count, worst, total, dxj, dyj, aj, mj, dxi, dyi, ai, mi)
    return count, worst, total, dxi, dyi, ai, mi
  end

  -- The first three steps, to the vertices at flat indices 4, 6 and min(8, last), from vertex 1;
  -- then four more, to those at min(k, last) to min(k + 6, last). last is n where the polygon
  -- may end within the steps, else the constant UNCLAMPED, which LuaJIT folds with the
  -- constant k into constant indices (min(k, n) for every index took 27 machine instructions
  -- a call more, 744 against 717, cachegrind at trace seeds 1 to 3 on the cOrd queries).
  local UNCLAMPED = 64
  local function firstSteps(points, last, x, y, dx1, dy1, a1, m1)
    local count, worst, total, dx, dy, a, m = step(points, 4, x, y, 0, 0, 0, dx1, dy1, a1, m1)
    count, worst, total, dx, dy, a, m = step(points, 6, x, y, count, worst, total, dx, dy, a, m)
    return step(points, min(8, last), x, y, count, worst, total, dx, dy, a, m)
  end

  local function fourSteps(points, k, last, x, y, count, worst, total, dx, dy, a, m)
    count, worst, total, dx, dy, a, m =
      step(points, min(k, last), x, y, count, worst, total, dx, dy, a, m)
    count, worst, total, dx, dy, a, m =
      step(points, min(k + 2, last), x, y, count, worst, total, dx, dy, a, m)
    count, worst, total, dx, dy, a, m =
      step(points, min(k + 4, last), x, y, count, worst, total, dx, dy, a, m)
    return step(points, min(k + 6, last), x, y, count, worst, total, dx, dy, a, m)
  end

  -- The edge back to vertex 1, then the answer, or containsByRuns' where a side is not certain.
  local function lastEdge(points, n, x, y, count, worst, total, dx, dy, a, m, dx1, dy1, a1, m1)
    count, worst, total = addEdge(count, worst, total, dx, dy, a, m, dx1, dy1, a1, m1)
    if worst + total * 0 == 0 then return count % 2 == 1 end
    local inside = containsByRuns(points, n, x, y)
    return inside
  end

  containsShort4 = function(points, n, x, y)
    local dx1, dy1, a1, m1 = vertexFrom(points, 2, x, y)
    local count, worst, total, dx, dy, a, m = firstSteps(points, n, x, y, dx1, dy1, a1, m1)
    return lastEdge(points, n, x, y, count, worst, total, dx, dy, a, m, dx1, dy1, a1, m1)
  end

  containsShort8 = function(points, n, x, y)
    local dx1, dy1, a1, m1 = vertexFrom(points, 2, x, y)
    local count, worst, total, dx, dy, a, m = firstSteps(points, UNCLAMPED, x, y, dx1, dy1, a1, m1)
    count, worst, total, dx, dy, a, m = fourSteps(points, 10, n, x, y, count, worst, total, dx, dy, a, m)
    return lastEdge(points, n, x, y, count, worst, total, dx, dy, a, m, dx1, dy1, a1, m1)
  end

  containsShort12 = function(points, n, x, y)
    local dx1, dy1, a1, m1 = vertexFrom(points, 2, x, y)
    local count, worst, total, dx, dy, a, m = firstSteps(points, UNCLAMPED, x, y, dx1, dy1, a1, m1)
    count, worst, total, dx, dy, a, m =
      fourSteps(points, 10, UNCLAMPED, x, y, count, worst, total, dx, dy, a, m)
    count, worst, total, dx, dy, a, m = fourSteps(points, 18, n, x, y, count, worst, total, dx, dy, a, m)
    return lastEdge(points, n, x, y, count, worst, total, dx, dy, a, m, dx1, dy1, a1, m1)
  end

  containsShort16 = function(points, n, x, y)
    local dx1, dy1, a1, m1 = vertexFrom(points, 2, x, y)
    local count, worst, total, dx, dy, a, m = firstSteps(points, UNCLAMPED, x, y, dx1, dy1, a1, m1)
    count, worst, total, dx, dy, a, m =
      fourSteps(points, 10, UNCLAMPED, x, y, count, worst, total, dx, dy, a, m)
    count, worst, total, dx, dy, a, m =
      fourSteps(points, 18, UNCLAMPED, x, y, count, worst, total, dx, dy, a, m)
    count, worst, total, dx, dy, a, m = fourSteps(points, 26, n, x, y, count, worst, total, dx, dy, a, m)
    return lastEdge(points, n, x, y, count, worst, total, dx, dy, a, m, dx1, dy1, a1, m1)
  end
end

-- The O(1) checks of polygonContains and Polygon:contains, raised at their callers' lines
-- (level counted from checkQuery). A NaN or infinite x or y would make the crossing rule
-- meaningless.
local function checkQuery(fname, points, x, y, level)
  local n = checkPoints(points, fname, "points", level + 1)
  checkNumber(x, fname, "x", level + 1)
  checkNumber(y, fname, "y", level + 1)
  if x - x ~= 0 or y - y ~= 0 then
    error(("%s: x and y must be finite, got %s, %s"):format(fname, tostring(x), tostring(y)),
      level)
  end
  return n
end

--- Whether (x, y) lies inside the polygon, by the crossing rule with the tutorial's half-open
-- boundary. Works for concave and self-intersecting polygons (even-odd). Exact. x and y must be
-- finite (an error otherwise); the polygon's coordinates are not checked (validate does that).
-- @return true or false; false for fewer than 3 points.
local function polygonContains(points, x, y)
  -- the checks written out where they pass (a Lua call costs about 13 ns on Lua 5.4)
  local n = type(points) == "table" and #points or -1
  if n % 2 ~= 0 or type(x) ~= "number" or type(y) ~= "number" or x - x ~= 0 or y - y ~= 0 then
    checkQuery("polygonContains", points, x, y, 3)
  end
  if n < 6 then return false end
  x = x + 0.0
  y = y + 0.0
  if JIT and n <= 32 then   -- (see containsShort4)
    local inside
    if n <= 8 then inside = containsShort4(points, n, x, y)
    elseif n <= 16 then inside = containsShort8(points, n, x, y)
    elseif n <= 24 then inside = containsShort12(points, n, x, y)
    else inside = containsShort16(points, n, x, y) end
    return inside
  end
  if JIT or x * x + y * y >= 2^106 then   -- (then |x| or |y| may reach 2^53)
    local inside = containsByRuns(points, n, x, y)
    return inside   -- not a tail call: the argument errors point at the caller's line
  end
  -- PUC Lua, |x| and |y| below 2^53: the walk written out (see the section's comment)
  local inside = false
  local below = points[n] >= y
  for i = 2, n, 2 do
    if below then
      if points[i] < y then   -- the edge into vertex i goes up across the ray's height
        below = false
        local j = i - 2
        if j == 0 then j = n end
        local x1, x2 = points[j - 1], points[i - 1]
        if x <= x1 then
          if x <= x2 or cross(x1, points[j], x2, points[i], x1, points[j], x, y) <= 0 then
            inside = not inside
          end
        elseif x <= x2 and cross(x1, points[j], x2, points[i], x1, points[j], x, y) <= 0 then
          inside = not inside
        end
      end
    elseif points[i] >= y then   -- it goes down across
      below = true
      local j = i - 2
      if j == 0 then j = n end
      local x1, x2 = points[j - 1], points[i - 1]
      if x <= x1 then
        if x <= x2 or cross(x1, points[j], x2, points[i], x1, points[j], x, y) >= 0 then
          inside = not inside
        end
      elseif x <= x2 and cross(x1, points[j], x2, points[i], x1, points[j], x, y) >= 0 then
        inside = not inside
      end
    end
  end
  return inside
end
polygon.polygonContains = polygonContains

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
-- them plain comparisons are faster. The two bodies compute the same numbers. On LuaJIT
-- minProjection is projectRange itself (the max costs one instruction): a loop of 6 to 8 steps
-- often fails to become a trace of its own ("leaving loop in root trace"), and other traces then
-- copy it unrolled, with side exits for every polygon size; one loop for every projection is
-- compiled sooner, from any of its callers.
local projectRange, minProjection
if JIT then
  projectRange = function(points, n, ax, ay, nx, ny)
    local lo, hi = huge, -huge
    for i = 1, n - 1, 2 do
      local s = nx * (points[i] - ax) + ny * (points[i + 1] - ay)
      lo, hi = min(lo, s), max(hi, s)
    end
    return lo, hi
  end
  minProjection = projectRange   -- (its second result unused)
else   -- (PUC Lua's projectRange is written out in faceAndFar, its one caller there)
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
-- det + bound with max and abs, no branch (the branches' side exits, taken from traces that had
-- unrolled this loop, failed to compile: "NYI: register coalescing too complex"), and counts
-- the vertices it cannot place, keeping the first and the last. When it cannot decide, at most
-- two of them (a touching pair's shared edge, a vertex on the edge) go to onLineSigns, an exact
-- test of both without a branch when their differences are exact, else to crossExact, whose
-- stage B decides all but exactly collinear ones with inexact differences (through cross, the
-- vertices near the line took its filter's side exit, and those side traces failed to compile
-- too), by two calls, where a pass over every vertex took touching pairs
-- 0.31 to 0.32 of the tutorial's time, not 0.26 to 0.27 (`luajit bench/isolated.lua
-- polygonsCollideV touch`); more by a second pass with no early exit (an exit in it made
-- LuaJIT abort the loop's trace, "leaving loop in root trace"). On PUC Lua one pass returns at
-- the first vertex surely inside, and calls crossExact only for the vertices the filter cannot
-- place (on a touching pair's shared edge the second pass took a third of this): cross's own
-- filter, on the same products turned by `inside`, could not place them either, short of a det
-- exactly at its bound, whose sign crossExact gives too.
local vertexInside
if JIT then
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

  vertexInside = function(ax, ay, bx, by, cx, cy, inside, points, n)
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
      -- of 6 to 8 steps here was copied unrolled by the side trace that reaches it from
      -- reachPast, one copy per polygon size, whose exits for the other sizes failed to compile
      -- ("NYI: register coalescing too complex", in 1 to 3 of 12 runs of the mixed pairs). A
      -- loop of a constant 8 steps, as faceAndFar's, has no such exits either, but took the
      -- mixed pairs 0.30-0.38 of the tutorial's time where this takes 0.26-0.29 (`luajit
      -- bench/isolated.lua polygonsCollideV`, four interleaved runs; touching pairs 0.35-0.36
      -- against 0.31-0.34). Each vertex through a small step function returning the five
      -- numbers was as fast, but brought NYI aborts back (9 in 3 of 16 runs of `bash
      -- bench/aborts.sh 16 polygonsCollide`, against none in 32).
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
      -- Against two crossExact calls always: touching pairs 204 -> 193, 208 -> 197, 206 -> 189 ns
      -- a call, mixed 235 -> 232, 228 -> 227, 237 -> 231 (`luajit /work/brief/s10/tools/t2.lua
      -- touch|mix`, interleaved, machine shared); machine instructions a touching call 2,646 ->
      -- 2,504, mixed 2,361 -> 2,295 (cachegrind, fixed trace seed). Written inline here, the
      -- guard's snapshot kept every temporary alive and spilled them (2,520 instructions); in a
      -- function they die at its return.
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
else
  vertexInside = function(ax, ay, bx, by, cx, cy, inside, points, n)
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
        -- through a (c = a), the far end of a touching pair's shared edge (half of crossExact's
        -- calls from here on the benchmark's mixed pairs, 51 of 101)
        if (px ~= cx or py ~= cy) and (px ~= bx or py ~= by or cx ~= ax or cy ~= ay)
            and crossExact(ax, ay, bx, by, cx, cy, px, py) * inside > 0 then
          return true
        end
      end
    end
    return false
  end
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
-- selection would not keep -0.0 or NaN as the comparisons do. (Before, a second selection per
-- edge noted the first such edge and the projections were taken again for it: 4,040 -> 3,840
-- machine instructions per overlapping call, 2,891 -> 2,844 per touching one, cachegrind.)
-- Any such edge will do: an edge decided apart makes the answer false whichever is examined,
-- and otherwise reachPastFull decides. With an exit from the loop at such an edge, side traces
-- that reached the loop before it was compiled copied it, and the copy's exits failed to
-- compile ("NYI: register coalescing too complex", 2,216 aborts in 1 of 12 runs of the
-- touching pairs).
-- reachPastFull is one flat loop over every (edge, vertex) pair, whose edge's verdict is a side
-- exit of its trace taken at every edge's last vertex (nested loops over a polygon's 6 to 8
-- vertices failed to become traces of their own, "leaving loop in root trace", and their
-- unrolled copies' side traces failed to compile). With the one loop over the edges
-- polygonsCollideV took 0.24 to 0.27 of the tutorial's time where the flat loop took 0.28 to
-- 0.33, and its overlapping pairs 0.27 to 0.29, not 0.36 to 0.42 (`luajit bench/isolated.lua
-- polygonsCollideV` and `... polygonsCollideV overlap`). PUC Lua runs reachBoth instead, below.

-- reachPast's and reachBoth's tolerance for polygons within a box of sides spanX and spanY:
-- (16 eps)^2 (spanX^2 + spanY^2), or every axis decided exactly where that square would
-- underflow (boxes below about 2^-450 only).
local function squaredTolerance(spanX, spanY)
  local tolSq = 2^-98 * (spanX * spanX + spanY * spanY)
  if tolSq < 2^-1000 then return huge end
  return tolSq
end

local reachPast, reachBoth
if JIT then
  local reachPastFull = function(edges, ne, turn, other, no, tolSq)
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

  reachPast = function(edges, ne, turn, other, no, tolSq)
    if no > 16 then
      local least, overlap, edgeEnd = reachPastFull(edges, ne, turn, other, no, tolSq)
      return least, overlap, edgeEnd
    end
    -- the least key and its overlap and edge end; the largest key (see below)
    local leastKey, leastOverlap, leastEnd, largestKey = huge, 0.0, 1, -huge
    -- other's vertices, the last one repeated for fewer than 8 (harmless to a min), read before
    -- the loop: its trace then takes them from the stack, where reading them in the loop made it
    -- convert and check every index on each entry (its first pass took 387 machine instructions
    -- on the overlapping pairs so, 228 now, callgrind; the reads, in the calling trace, share
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
    -- (the vertices' locals dead from here: kept alive, the side traces leaving the loop took them
    -- over and failed to compile, "NYI: register coalescing too complex", 382 and 669 aborts a
    -- run when the traces were first recorded on missing pairs)
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
else
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
  -- the two bodies agree. On Lua 5.4 polygonsCollideV takes 1,229 VM instructions per call of
  -- the benchmark's mixed pairs with it, 1,297 with a calipers walk per polygon (the tutorial:
  -- 1,865). (On LuaJIT the choice of edge, a data-dependent branch per edge, would be a side
  -- trace, as the walks' exits were.)

  -- Whether other reaches past the edge of `edges` ending at vertex index k, decided exactly.
  local function edgeReached(edges, ne, turn, other, no, k)
    local j = k == 1 and ne - 1 or k - 2
    local ax, ay = edges[j], edges[j + 1]
    return vertexInside(ax, ay, edges[k], edges[k + 1], ax, ay, turn, other, no)
  end

  reachBoth = function(p1, n1, turn1, p2, n2, turn2, tolSq, top1, bottom2)
    -- each edge is known by a key: its end's index in p1, or n1 + its end's index in p2, so
    -- that the order of keys is the order of the ties' rule
    local least, leastOverlap, leastKey = huge, 0.0, 1
    -- The walk starts at a direction whose deepest vertices are known: with top1, the flat index
    -- of a vertex of p1 of largest y, and bottom2, one of p2 of least y (turnAndBounds'), at the
    -- outward direction (0, 1): p1's edges from top1 on and p2's from bottom2 on all come at or
    -- after it, within a half turn (with a tie, an edge whose normal is (0, 1) comes first or
    -- last, either way in order). Without them (pairOverlaps), at p1's first edge, p2's deepest
    -- vertex found over every vertex. Either way from p1's first edge with a normal there (the
    -- area is not zero, so there is one): c -> cn, cn at kn. The known start saves the scan:
    -- Lua 5.4 VM instructions a call of the benchmark's mixed pairs 875 -> 855 (overlapping
    -- 1,368 -> 1,320, touching 844 -> 872, missing 355 -> 371: the indices cost every call,
    -- `lua5.4 bench/instructions.lua`); `lua5.4 bench/run.lua --only '^polygonsCollideV pMix$'`
    -- over 16 processes, two runs each, alternating: 0.44 and 0.44 -> 0.43 and 0.43. The same
    -- answers as the scan's start on 240,000 calls of random convex pairs (boxes, grid polygons
    -- with ties, repeated vertices, both windings, offsets to 1e9).
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
    -- through a temporary per value, which here was a tenth of the loop)
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
end

-- For reachPastBothEnds: -lo and hi - own, where [lo, hi] is the range of the projections
-- n . (v - a) of other's vertices and own the least of edges' own. On LuaJIT one loop over both
-- polygons at once, the shorter one's last vertex read again (harmless to a min or max): half
-- the loops of the two calls, each a loop other traces could copy unrolled. Up to 8 vertices it
-- always runs 8 steps: a loop whose count is a constant has no side exit for the other polygon
-- sizes in the copies. Those exits failed to compile ("NYI: register coalescing too complex":
-- 160 of the 236 NYI aborts in 16 runs of `bash bench/aborts.sh 16`; none at this loop in 48
-- runs after, while other sites still gave some, 283 in 3 of the last 16), for a few percent
-- more time (`luajit bench/isolated.lua polygonCollidesWithV`, six runs each: 0.89-0.98 of the
-- tutorial's time before, 0.84-1.05 after). Two other shapes were measured and dropped: the
-- edge loop flat over (edge, vertex) pairs, as reachPast's, with the verdicts after it, took
-- 0.99-1.68 (mostly above 1.4); each polygon's eight projections as one expression, with no
-- inner loop, 0.71-1.68, with 735 to 2,460 of those aborts a run.
local faceAndFar
if JIT then
  faceAndFar = function(edges, ne, other, no, ax, ay, nx, ny)
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
else
  -- projectRange's and minProjection's loops written out, not called: two calls an edge
  -- (polygonCollidesWith on Lua 5.4, the benchmark's mixed pairs: 1,614 VM instructions per
  -- call with the calls, 1,531 without, `lua5.4 bench/instructions.lua polygonCollidesWith`)
  faceAndFar = function(edges, ne, other, no, ax, ay, nx, ny)
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
end

-- reachPast for the one-sided functions, which test the axes of `edges` only: both ends of each
-- range, so also how far `other` reaches beyond the vertex of `edges` deepest inside, along -n.
-- Returns false, or the squared depth, o, the edge's end and, when the least is at the far end,
-- the index of that deepest vertex (else 0).
-- The loop keeps only numbers, and across its two inner loops only the edge's start and normal
-- (its end is read again where needed, the tolerance computed after them); the deepest vertex
-- of the least is found once, after the loop. On LuaJIT a trace of the caller that runs on into
-- a loop not yet compiled unrolls it, and the side traces leaving that copy inherit every value
-- alive there: with a false-or-index, the edge's end and the tolerance alive too they needed more
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
local unit
if JIT then
  unit = function(nx, ny)
    local m = max(abs(ny), abs(nx))
    nx, ny = nx / m, ny / m
    local len = sqrt(nx * nx + ny * ny)
    return nx / len, ny / len, len * m
  end
else
  unit = function(nx, ny)
    local m = ny < 0 and -ny or ny
    local mx = nx < 0 and -nx or nx
    if m < mx then m = mx end
    nx = nx / m
    ny = ny / m
    local len = sqrt(nx * nx + ny * ny)
    return nx / len, ny / len, len * m
  end
end

-- Below 2^464 the products of two coordinate differences (each below 2^466 after scaling)
-- cannot overflow; from 2^400 up the scaled copies keep 64 binades of headroom below it.
local RESCALE_LOW, RESCALE_HIGH = 2^400, 2^464

--- THE SAT ENGINE. convexPenetration(p1, n1, p2, n2, both) decides exactly whether the
-- convex polygons p1[1..n1] and p2[1..n2] (flat arrays, either winding) overlap: touching is not
-- overlapping; fewer than 3 points or zero area never overlaps. both: the axes of both
-- polygons (polygonsCollide); false: the axes of p1 only, both ends of each range
-- (polygonCollidesWith). Allocates nothing (except on the rare path beyond 2^500); rescaled
-- is for that path only (callers leave it nil). Call separatingPush for a push.
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
  -- Each polygon's turn, the sign of its area decided exactly, 1 or -1 (zero area never
  -- collides), and the sizes bounding every |vx - ax| and |vy - ay| in the projections: the box
  -- around both. A NaN or infinity makes the sums non-finite; so does overflow, which is not an
  -- error. The boxes are apart or touching (so are the polygons) when a difference is <= 0; no
  -- subtraction of finite doubles rounds across 0.
  local turn1, turn2, spanX, spanY
  local top1, bottom2   -- PUC Lua: where reachBoth's walk starts (see there)
  if JIT then
    -- Each polygon's sums, then at once its turn, so that only the sign and the box are kept
    -- while the other's sums are taken (fewer values for a side trace to inherit). Between the
    -- loops min, max and a division, which have no side exits (the branches' exits were side
    -- traces of shoelaceBounds' loop, past LuaJIT's 100 per loop).
    local area1, xSq1, dSq1, xmin1, xmax1, ymin1, ymax1 = shoelaceBounds(p1, n1)
    -- luacheck: ignore 581 (NaN must count as non-finite)
    if not (xSq1 + dSq1 < huge) and holdsNonFinite(p1, n1) then return nil, "points1" end
    turn1 = areaSignOf(p1, n1, area1, xSq1, dSq1)
    local area2, xSq2, dSq2, xmin2, xmax2, ymin2, ymax2 = shoelaceBounds(p2, n2)
    -- luacheck: ignore 581 (NaN must count as non-finite)
    if not (xSq2 + dSq2 < huge) and holdsNonFinite(p2, n2) then return nil, "points2" end
    -- Both turns and the spans before the box test, so that only those four numbers are alive
    -- at its exit: the side trace that a miss takes there inherits them, where with the sums
    -- and the boxes alive it failed to compile in some runs ("NYI: register coalescing too
    -- complex", 10 in 3 of 16 runs of `bash bench/aborts.sh 16`)
    turn2 = areaSignOf(p2, n2, area2, xSq2, dSq2)
    spanX, spanY = max(xmax1, xmax2) - min(xmin1, xmin2), max(ymax1, ymax2) - min(ymin1, ymin2)
    if both and min(xmax1 - xmin2, xmax2 - xmin1, ymax1 - ymin2, ymax2 - ymin1) <= 0 then
      return false   -- (the one-sided test may still see overlap)
    end
    if turn1 == 0 or turn2 == 0 then return false end
    -- (a sure sign is finite: areaSignOf sends an infinite sum to the exact path; so t / |t|
    -- is 1 or -1 exactly)
    turn1, turn2 = turn1 / abs(turn1), turn2 / abs(turn2)
  else
    -- PUC Lua: both in one call per polygon, comparisons instead of min and max (calls here)
    local sign1, xmin1, xmax1, ymin1, ymax1, _, high1 = turnAndBounds(p1, n1)
    if not sign1 then return nil, "points1" end
    local sign2, xmin2, xmax2, ymin2, ymax2, low2 = turnAndBounds(p2, n2)
    if not sign2 then return nil, "points2" end
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
-- is 0. One cross product a vertex, from q only: the bound grows with |p - q|, and trying each
-- vertex from the edge's other end too (the better of the two kept, as before) placed the vertex
-- that ends near that end, but cost a second cross product and bound for every vertex, where the
-- first push's margin (see separatingPush) already covers the bound from q for all but a few: on
-- the benchmark's 300 overlapping pairs 321 checks instead of 318. The largest excess:
-- `spec/sat_push_spec.lua` 4.76 eps M on LuaJIT as before, 4.76 -> 5.99 on Lua 5.4 (whose sin and
-- cos make other pairs); 5.16 -> 6.31 over 4,000 calls on random pairs at offsets to 2^40;
-- `spec/sat_push_hard_spec.lua` (the deepest vertex at the edge's far end) 2.56 -> 3.88 and 4.15 ->
-- 4.79. LuaJIT machine instructions per overlapping call 3,619 -> 3,514, mixed 2,361 -> 2,308
-- (valgrind's cachegrind, 900 minus 300 passes over `W.pairs(300, ...)`, trace seed fixed by
-- bench/fixseed.c); time per call overlapping about 7 % less, mixed 4 to 7 % (both versions in one
-- process, interleaved rounds). Up to 8 vertices there is no loop: the vertices in one expression,
-- as in reachPast (a loop of 6 to 8 steps often failed to become a trace of its own, "leaving loop
-- in root trace" in 2 of 6 runs of the mixed pairs under `luajit -jv`, and the traces that reached
-- it then copied it unrolled). Beyond, the loop is branch-free and takes the line from pushLine in
-- every step: LuaJIT hoists those loads and products out of its compiled loop, and a side trace
-- that leaves the loop midway (a trace that ran on into it before it was compiled had unrolled it)
-- inherits only the push from its parent. With the line's numbers held across the loop such
-- side traces needed more registers than there are ("NYI: register coalescing too complex", retried
-- on every push, `luajit bench/isolated.lua polygonsCollideV`).
local lineShortfall
if JIT then
  -- one vertex's det + bound, from q
  local reachOf = function(ex, ey, qx, qy, px, py)
    local l, r = ex * (py - qy), ey * (px - qx)
    return l - r + CROSS_BOUND * (abs(l) + abs(r))
  end
  lineShortfall = function(lines, ia, ib, base, lineMoves, ux, uy, push, inside, points, n)
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
-- So along a slanted axis (ux uy not 0) the first push is already lengthened by a margin of
-- about what the check's rounding takes away, eps (|qx ux| + |qy uy| + |ex| + |ey|) (q the
-- line's point, e its edge: the moved coordinates' rounding, the depth's and the filter's bound
-- grow with them), and one check proves it for 282 of the benchmark's 300 overlapping pairs,
-- where from the depth itself 201 needed a second (which costs a square root and a division
-- too; 318 checks in all, not 501: `bench/workloads.lua`'s pairOverlap, a count hook; counted
-- again per call, 285 in one check, and 282 and 321 since it tries each vertex from q only).
-- The largest excess in `spec/sat_push_spec.lua` went from 4.46 to 4.76 eps M (the contract:
-- 8), as long as the second round's pushes it replaces. Along an axis the depth comes first, as
-- before: a move along x or y is often exact there.
-- Returns push length, dx, dy.
-- Two bodies computing the same push (to the depth's rounding, which differs by an ulp where the
-- two SAT bodies round differently). On PUC Lua the check (lineShortfall's, with pushLine's
-- line) is written out in the loop over the rounds, and its filter is tried first without abs,
-- which places most vertices: with the calls (twelve arguments for the check, pushLine's eight
-- results, abs) the push took 395 VM instructions per overlapping pair of the benchmark on Lua
-- 5.4, 313 so (`lua5.4 bench/instructions.lua`, the push's share counted by a count hook). Each
-- vertex from q only, as on LuaJIT (the same pushes): overlapping pairs 1,374 -> 1,368 VM
-- instructions a call, mixed 876 -> 875.
local separatingPush
if JIT then
  separatingPush = function(p1, n1, p2, n2, depth, ux, uy, owner, edgeEnd, base, inside)
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
else
  separatingPush = function(p1, n1, p2, n2, depth, ux, uy, owner, edgeEnd, base, inside)
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
end

-- Raises the error for a non-finite coordinate at the caller of the public function, which
-- called the private function that calls this one.
local function raiseNonFinite(fname, argname)
  error(("%s: %s holds a non-finite coordinate"):format(fname, argname), 4)
end

-- kind1, kind2: the type of each argument's first entry where the caller has looked (it is a
-- table then), else nil.
local function collides(fname, points1, points2, both, kind1, kind2)
  local n1 = checkPoints(points1, fname, "points1", 4, kind1)
  local n2 = checkPoints(points2, fname, "points2", 4, kind2)
  local depth, argname = convexPenetration(points1, n1, points2, n2, both)
  if depth == nil then raiseNonFinite(fname, argname) end
  return depth ~= false
end

-- Lists of convex parts in place of a polygon: the public functions below (and the circle's)
-- hand them to the "Compound shapes" section, defined after the SAT engine, the circles and the
-- convex parts it builds on; declared here so the public functions stay beside their engine.
local isParts, collideParts, collideCircleParts

--- Whether the edge normals of points1 show no separating axis between two convex polygons.
-- Touching is not colliding; fewer than 3 points or zero area never collides. Exact.
-- Raises an error for a non-finite coordinate.
-- @return true or false
function polygon.polygonCollidesWith(points1, points2)
  local collided = collides("polygonCollidesWith", points1, points2, false)
  return collided
end

--- Whether two convex polygons (either winding) overlap, by the separating axis theorem.
-- Either may be a list of convex parts instead (see "Compound shapes").
-- Touching is not colliding; fewer than 3 points or zero area never collides. Exact.
-- Raises an error for a non-finite coordinate.
-- @return true or false
function polygon.polygonsCollide(points1, points2)
  -- isParts inlined, the kinds handed on to the checks (two calls and two type calls fewer)
  local kind1 = type(points1) == "table" and type(points1[1])
  local kind2 = type(points2) == "table" and type(points2[1])
  if kind1 == "table" or kind2 == "table" then
    local hit = collideParts("polygonsCollide", points1, points2, false, kind1 == "table",
      kind2 == "table")
    return hit
  end
  local collided = collides("polygonsCollide", points1, points2, true, kind1, kind2)
  return collided
end

-- convexPenetration, then separatingPush: false, or push length, dx, dy (adding (dx, dy) to
-- every vertex of points2 leaves the polygons touching or apart, exactly).
local function pushOut(fname, points1, points2, both, kind1, kind2)
  local n1, n2
  if kind1 and kind2 then   -- both tables: the rest of checkPoints' test, with no call
    n1 = #points1
    n2 = #points2
    if n1 % 2 ~= 0 or n2 % 2 ~= 0 then
      checkPoints(points1, fname, "points1", 4, kind1)
      checkPoints(points2, fname, "points2", 4, kind2)
    end
  else
    n1 = checkPoints(points1, fname, "points1", 4, kind1)
    n2 = checkPoints(points2, fname, "points2", 4, kind2)
  end
  local depth, ux, uy, owner, edgeEnd, base, inside =
    convexPenetration(points1, n1, points2, n2, both)
  if not depth then
    if depth == nil then raiseNonFinite(fname, ux) end
    return false
  end
  local push, dx, dy = separatingPush(points1, n1, points2, n2, depth, ux, uy, owner, edgeEnd,
    base, inside)
  return push, dx, dy
end

--- As polygonCollidesWith, with the minimum translation vector over the axes of points1.
-- @return overlap, dx, dy or false: after adding (dx, dy) to every vertex of points2,
-- polygonCollidesWith(points1, moved) is false (see polygonsCollideV)
function polygon.polygonCollidesWithV(points1, points2)
  local push, dx, dy = pushOut("polygonCollidesWithV", points1, points2, false)
  return push, dx, dy
end

--- As polygonsCollide, with the minimum translation vector (lists of parts: see "Compound shapes").
-- overlap is the penetration depth along the axis of least penetration, right also when one
-- polygon contains the other; (dx, dy) moves points2 out of points1 (add it to every vertex of
-- points2), pointing the right way in either argument order and when the centres coincide.
-- One push separates: after p[i] = p[i] + dx (and + dy) on points2, rounded,
-- polygonsCollide(points1, moved) is false, and the push is at most a few ulps of the
-- coordinates longer than the exact depth. Raises an error for a non-finite coordinate.
-- @return overlap, dx, dy or false
function polygon.polygonsCollideV(points1, points2)
  -- isParts inlined, the kinds handed on to the checks (as in polygonsCollide)
  local kind1 = type(points1) == "table" and type(points1[1])
  local kind2 = type(points2) == "table" and type(points2[1])
  if kind1 == "table" or kind2 == "table" then
    local overlap, dx, dy = collideParts("polygonsCollideV", points1, points2, true,
      kind1 == "table", kind2 == "table")
    return overlap, dx, dy
  end
  local push, dx, dy = pushOut("polygonsCollideV", points1, points2, true, kind1, kind2)
  return push, dx, dy
end

--------------------------------------------------------------------------------------------------
-- Circles
--------------------------------------------------------------------------------------------------
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
-- underflow's absolute error is negligible.) Only near-exact ties reach the expansion: in the
-- arena of examples/arena.lua (300 frames) 189,427 calls, whose expansions' loops were LuaJIT
-- traces' side exits that failed to compile ("register coalescing too complex").
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
  expLen = 0
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
  expLen = 0
  expAddProduct(exh, wyh); expAddProduct(exh, wyl); expAddProduct(exl, wyh); expAddProduct(exl, wyl)
  expAddProduct(-eyh, wxh); expAddProduct(-eyh, wxl); expAddProduct(-eyl, wxh); expAddProduct(-eyl, wxl)
  expCompress()
  local crossLen = expLen
  for i = 1, crossLen do crossParts[i] = expansion[i] end
  expLen = 0
  expAddSquare(exh, exl, 1)
  expAddSquare(eyh, eyl, 1)
  expCompress()
  local lengthLen = expLen
  for i = 1, lengthLen do lengthParts[i] = expansion[i] end
  local radiusSqHi, radiusSqLo = twoProduct(r * s, r * s)
  expLen = 0
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

-- Whether two circles collide: |c2 - c1|^2 < (r1 + r2)^2, the sum of the radii exact.
local function circlesCollide(x1, y1, r1, x2, y2, r2)
  return reaches(x1, y1, x2, y2, twoDiff(r1, -r2)) > 0
end

--- Whether two circles overlap, with the push that separates them.
-- Touching is not colliding; decided exactly ((x2 - x1)^2 + (y2 - y1)^2 < (r1 + r2)^2), so a
-- circle of radius 0 is a point, colliding only strictly inside the other circle.
-- (dx, dy) moves the second circle: after x2 + dx, y2 + dy (rounded as a game adds them) the
-- circles no longer collide. Its length exceeds overlap by a few ulps of the coordinates at
-- most. Circles with the same centre are pushed along +x.
-- @return overlap, dx, dy (overlap = r1 + r2 - distance) or false
function polygon.circlesCollideV(x1, y1, r1, x2, y2, r2)
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
-- As in projectRange, LuaJIT gets a loop without data-dependent branches: each such branch
-- becomes a side trace, and the rest of the function is compiled again behind every one of
-- them (measured: about 10 times slower). It is one pass, the sign included: the extremes by
-- min and max, the index of each extreme's first match by a select without a branch (it moves
-- to i by (i - index) times 1 when the new number beats the extreme, times 0 when not). The
-- farthest edge depends on the sign, known only after the loop: the loop takes the sign of the
-- turn at vertex 1 as a guess (the area's sign for a convex polygon) and runs again with the
-- sign when the guess was wrong. The sign comes from the same cross products (below), the
-- exact kernel deciding where they cannot.
-- (The walk was three passes: the shoelace sum for the sign, then the extremes, then a second
-- pass finding their indices by recomputing the same numbers: 2,867 machine instructions per
-- call of the benchmark's circles, about 2,040 now with the early exit below;
-- `valgrind --tool=cachegrind`.) Few values stay alive across the loop and after it: with both
-- signs' farthest edges kept at once, four more, side traces in the arena of
-- examples/arena.lua failed to compile ("NYI: register coalescing too complex", 95 to 6,060 a
-- run in four runs; the three-pass walk 0 to 1,442 in eleven, this one 67 to 898 in seven).
-- The PUC interpreters call min and max as functions, so for them a branchy pass is faster.
local edgeWalk

-- The sign of the polygon's area as 1.0 or -1.0, exact; 0 for a zero area, nil when the area
-- is not finite (a non-finite coordinate, or an overflow).
local function exactTurn(points, n)
  local area, sumX2, sumD2 = shoelace(points, n)
  if area - area ~= 0 then return nil end
  local turn = areaSignOf(points, n, area, sumX2, sumD2)
  if turn == 0 then return 0 end
  return turn > 0 and 1.0 or -1.0
end

if JIT then
  -- min(x * LIFT * LIFT, 1) is 1 when x > 0 and 0 when x == 0, for x >= 0, without a branch:
  -- the least positive double, 2^-1074, times 2^1074 is 1. (Written out where used: as a
  -- function called per vertex it started traces of its own, which LuaJIT aborted.)
  local LIFT = 2^537
  -- One pass with the sign guessed (1.0 or -1.0): near, nearSq, farSq, and the farthest edge
  -- as if the area's sign were `guess`, its key, and the sum of the cross products (below).
  local function walkGuessed(points, n, cx, cy, guess)
    local nearSq, farSq, near = huge, 0.0, 1
    -- the farthest edge's key and index: an edge's key is outside |outside| / |b - a|^2,
    -- outside = crossed * sign, less 2^1000 for a repeated vertex (|b - a|^2 == 0): below
    -- every real edge's key in the range where the walk's answer is used (farSq < 2^1000)
    local bestKey, best = -huge, 1
    local turnSum = 0.0
    local ax, ay = points[n - 1] - cx, points[n] - cy
    for i = 1, n - 1, 2 do
      local bx, by = points[i] - cx, points[i + 1] - cy
      local distSq = bx * bx + by * by
      near = near + (i - near) * min(max(nearSq - distSq, 0) * LIFT * LIFT, 1)
      nearSq, farSq = min(nearSq, distSq), max(farSq, distSq)
      local ex, ey = bx - ax, by - ay
      local lengthSq = ex * ex + ey * ey
      local crossed = ex * ay - ey * ax
      turnSum = turnSum + crossed
      local outside = crossed * guess
      local key = outside * (abs(outside) / max(lengthSq, 2^-1074))
        - (1 - min(lengthSq * LIFT * LIFT, 1)) * 2^1000
      best = best + (i - best) * min(max(key - bestKey, 0) * LIFT * LIFT, 1)
      bestKey = max(bestKey, key)
      ax, ay = bx, by
    end
    return near, nearSq, farSq, best, bestKey, turnSum
  end
  edgeWalk = function(points, n, cx, cy)
    -- the guess: the sign of the turn at vertex 1, without a branch (1 when it is 0); it is
    -- the area's for a convex polygon
    local guess
    do
      local x0, y0, x1, y1 = points[n - 1], points[n], points[1], points[2]
      local turn = (x1 - x0) * (points[4] - y1) - (y1 - y0) * (points[3] - x1)
      guess = 1 - 2 * min(max(-turn * LIFT * LIFT, 0), 1)
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
else
  -- The PUC loop also stops at the first edge whose line the circle (radius r) is certainly
  -- beyond, returning best = -1: an edge's squared signed distance is off by less than
  -- 32 eps (r^2 + the squared distances of its ends), so a key past r^2 by that much means
  -- the circle is apart, as the full pass would decide too (LuaJIT's loop stays branch-free).
  edgeWalk = function(points, n, cx, cy, r)
    local sign   -- exactTurn written out (a call costs PUC Lua more than these lines)
    do
      local area, sumX2, sumD2 = shoelace(points, n)
      if area - area ~= 0 then return 0.0, 1, 0.0, 0.0, -2 end
      local turn = areaSignOf(points, n, area, sumX2, sumD2)
      if turn == 0 then return 0.0, 1, 0.0, 0.0, -1 end
      sign = turn > 0 and 1.0 or -1.0
    end
    local nearSq, farSq, near = huge, 0.0, 1
    local bestKey, best = -huge, 0
    local ax, ay = points[n - 1] - cx, points[n] - cy
    local radiusSq = r * r
    local prevSq = ax * ax + ay * ay
    for i = 1, n - 1, 2 do
      local bx, by = points[i] - cx, points[i + 1] - cy
      local distSq = bx * bx + by * by
      if distSq < nearSq then nearSq, near = distSq, i end
      if distSq > farSq then farSq = distSq end
      local ex, ey = bx - ax, by - ay
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
      ax, ay, prevSq = bx, by, distSq
    end
    return sign, near, nearSq, farSq, best
  end
end

local circleCollision

-- circleCollision on a copy of the polygon, the centre and the radius scaled by a power of two
-- into the range where its squares neither overflow nor underflow, the answer scaled back; nil
-- for a non-finite coordinate. Rare (coordinates beyond 2^500 or all below 2^-400), so this
-- path allocates the copy.
local function circleCollisionScaled(points, n, cx, cy, r)
  local m = max(abs(cx), abs(cy), r)
  for i = 1, n do
    local v = points[i] + 0.0
    if v ~= v or v == huge or v == -huge then return nil end
    m = max(m, abs(v))
  end
  local k = m > 1 and powerScale(m, 2^-32, 2^32) or powerScale(m, 2^-200, 2^-136)
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
-- is a thin wrapper around it, so that a compound shape can call it once per part.
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
function circleCollision(points, n, cx, cy, r)
  -- (the do-blocks here keep the frame small: on Lua 5.4 a larger one can make the stack grow
  -- again, allocating, after every full collection)
  -- sign: 1 or -1, makes the signed distances positive outside. feature: the edge whose line
  -- lies farthest behind the centre (the index of its end), below minus the nearest vertex's
  -- index when the centre lies in that vertex's corner region
  local sign, near, nearSq, farSq, feature = edgeWalk(points, n, cx, cy, r)
  if feature < 0 then   -- certainly apart (PUC only), a zero area or a non-finite one (see edgeWalk)
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
  -- The nearest-vertex axis: the centre is in the corner region of the nearest vertex v when
  -- it lies behind neither edge meeting there, (c - v).(p - v) <= 0 for both distinct
  -- neighbours p; then the distance to the polygon is |c - v|, and the push goes along c - v.
  if nearSq > 0 then
    local vx, vy = points[near] - cx, points[near + 1] - cy   -- v - c
    local p = distinctNeighbour(points, n, near, -2)
    local q = distinctNeighbour(points, n, near, 2)
    if vx * (vx - (points[p] - cx)) + vy * (vy - (points[p + 1] - cy)) <= 0
        and vx * (vx - (points[q] - cx)) + vy * (vy - (points[q + 1] - cy)) <= 0 then
      feature = -near
    end
  end
  -- On LuaJIT a branch below that goes both ways (as the first two do in a game: circles in
  -- contact, and circles a push has just left touching) becomes a side trace, which takes over
  -- in registers every number held in a local still in scope there, the callers' included:
  -- with more than the registers it fails to compile ("NYI: register coalescing too complex").
  -- So near and nearSq are dropped here, and the push's direction is not held in locals (see
  -- penetration). Measured in the arena of examples/arena.lua (300 frames, `luajit -jv`): such
  -- aborts in this section went from 2,260 in sixteen runs (0 to 887 a run) to 1 in twenty-four,
  -- not counting traces through the compound code, whose frames hold most of the numbers there.
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

--- The minimum translation vector of a circle out of a convex polygon (either winding), or out of
-- a list of convex parts (see "Compound shapes").
-- Collides exactly when the open disc meets the polygon's interior: touching is not colliding,
-- a radius of 0 never collides, fewer than 3 points or zero area never collides. The overlap
-- is the full penetration (r minus the signed distance from the centre to the polygon), so a
-- circle deep inside is pushed out in one step, and the push separates for certain: after
-- cx + dx, cy + dy (rounded) the circle no longer collides. The push is longer than the exact
-- depth by at most 8 eps M, eps = 2^-53 and M the largest coordinate magnitude involved (the
-- polygon's, the centre's and the moved centre's; see circlePush for the bound, 7.1 eps M).
-- @return overlap, dx, dy (move the circle by dx, dy) or false
function polygon.polygonCircleCollideV(points, cx, cy, radius)
  local fname = "polygonCircleCollideV"
  if isParts(points) then
    local overlap, dx, dy = collideCircleParts(fname, points, cx, cy, radius)
    return overlap, dx, dy
  end
  local n = checkPoints(points, fname)
  checkFiniteNumber(cx, fname, "cx")
  checkFiniteNumber(cy, fname, "cy")
  checkRadius(radius, fname, "radius")
  if n < 6 or radius == 0 then return false end
  -- converted in place: on LuaJIT the numbers of this frame and of circleCollision's are then
  -- the same (see circleCollision: fewer for a side trace to take over)
  cx = cx + 0.0
  cy = cy + 0.0
  radius = radius + 0.0
  local overlap, dx, dy = circleCollision(points, n, cx, cy, radius)
  if overlap == nil then error(fname .. ": points holds a non-finite coordinate", 2) end
  if not overlap then return false end
  return overlap, dx, dy
end

--------------------------------------------------------------------------------------------------
-- Triangulation and convex parts
--------------------------------------------------------------------------------------------------
do   -- this section's helpers are local to it
-- Ear clipping over one ring of vertex nodes: holes are first joined to the outer ring by a
-- bridge to a vertex they see (Eberly's method), an ear is a strictly convex vertex whose
-- triangle no other vertex blocks, and the vertices that could block it are found in a grid of
-- cells, visited along the triangle row by row, holding only vertices that are not strictly
-- convex (or sit at a pinch point), so an ear test looks at the few vertices near its triangle,
-- not at all of them. Every decision is an exact sign (orient: cross's filter, then crossExact);
-- coordinates are only ever copied.
-- The nodes live in arrays indexed by node number, set up by one call and dropped at its end.

local floor, sort = math.floor, table.sort

-- An empty table with room for `size` array entries: LuaJIT's table.new, {} elsewhere. The
-- node arrays are filled in order up to tens of thousands of entries; grown one entry at a
-- time, each is copied at every doubling and leaves its old parts as garbage.
local newArray = function() return {} end
do
  local found, tableNew = pcall(require, "table.new")
  if found then newArray = function(size) return tableNew(size, 0) end end
end
local capacity          -- the number of nodes a call can make, at most: the arrays' size

local nodeX, nodeY      -- coordinates as doubles (+ 0.0), for the predicates
local inX, inY          -- the caller's values, copied into the output bit for bit
local origin            -- the input vertex a node stands for (a bridge copies two of them)
local nextNode, prevNode, nodeCount
local gone              -- gone[k]: node k has been unlinked
local cellStart         -- the ear test's grid (see buildGrid): where cell c's entries begin
local entryX, entryY, entryNode   -- its entries, cell by cell: a node's place and number
local entryOf           -- entryOf[k]: node k's entry
local listed            -- listed[k]: node k is still in the ear test's grid
local shared            -- shared[k]: another node lies at node k's place
local reflexSeen        -- reflexSeen[k]: node k was found not strictly convex and has kept
                        -- its neighbours since
local listStale         -- a node dropped from the grid may have turned reflex
local turn              -- the sign of the outer ring's area: > 0 clockwise on screen

-- Sort orders, made once: a function made per call would keep LuaJIT from compiling its caller.
local sortKey
local function bySortKey(a, b) return sortKey[a] < sortKey[b] end
local function leftmostFirst(a, b)
  return nodeX[a] < nodeX[b] or (nodeX[a] == nodeX[b] and nodeY[a] < nodeY[b])
end

-- A number with the sign of (b - a) x (c - a) for nodes, times turn: > 0 when c lies on the
-- interior side of the directed edge a -> b of a ring wound like the outer one. Only its sign
-- means anything.
local function orient(a, b, c)
  local ax, ay, bx, by, cx, cy = nodeX[a], nodeY[a], nodeX[b], nodeY[b], nodeX[c], nodeY[c]
  -- c at b is common (edges meeting at a vertex): 0 at once, as the filter would go exact
  if (cx == bx and cy == by) or (cx == ax and cy == ay) then return 0 end
  -- cross's filter written out, with crossExact only when it cannot vouch for the sign: the call
  -- with eight arguments made LuaJIT abort its side traces over and over ("register coalescing
  -- too complex"), which cost polygonConvexParts 50 times its time on a 100-vertex outline
  -- (Branches taken half the time, as an if for |l + r| or for the sign returned, made more.)
  local l, r = (bx - ax) * (cy - ay), (by - ay) * (cx - ax)
  local s = l - r
  local e = CROSS_BOUND * abs(l + r)
  -- one test of |s|, not one per sign: a branch taken for half the nodes (convex or reflex)
  -- made side traces that aborted until LuaJIT flushed all its traces
  if abs(s) < e or s ~= s then   -- also when l and r differ in sign and s is 0: exact, rare
    s = crossExact(ax, ay, bx, by, ax, ay, cx, cy)
  end
  return s * turn
end

local function same(a, b)
  return nodeX[a] == nodeX[b] and nodeY[a] == nodeY[b]
end

local function newNode(x, y, id)
  nodeCount = nodeCount + 1
  local k = nodeCount
  inX[k], inY[k], nodeX[k], nodeY[k], origin[k] = x, y, x + 0.0, y + 0.0, id
  return k
end

-- Drops node k from its cell of the ear test's grid.
local function unlist(k)
  listed[k] = false
  entryX[entryOf[k]] = huge   -- no span holds it: the scans pass over it
end

-- Unlinks node k from the ring and, once built, from the ear test's grid.
local function unlink(k)
  gone[k] = true
  local p, q = prevNode[k], nextNode[k]
  nextNode[p], prevNode[q] = q, p
  if listed and listed[k] then unlist(k) end
end

-- Links the vertices of a flat array into a ring, in reverse when `reversed`, skipping
-- repeated consecutive vertices. firstId: the id of the array's first vertex. Returns a node.
local function linkRing(points, n, firstId, reversed)
  local first, last
  for j = 1, n - 1, 2 do
    local i = reversed and n - j or j
    local x, y = points[i], points[i + 1]
    if not last or x + 0.0 ~= nodeX[last] or y + 0.0 ~= nodeY[last] then
      local k = newNode(x, y, firstId + (i - 1) / 2)
      if last then nextNode[last], prevNode[k] = k, last else first = k end
      last = k
    end
  end
  nextNode[last], prevNode[first] = first, last
  if last ~= first and same(first, last) then unlink(last) end
  return first
end

-- Whether segments a-b and c-d cross at one point inside both (a proper crossing): c and d
-- strictly on opposite sides of a-b, and a and b of c-d. Each side test is one comparison,
-- min(max(s1, s2), -min(s1, s2)) > 0, rarely true: sign tests that went both ways made LuaJIT
-- grow side traces in the sweep until its machine-code area ran out.
local function properlyCross(a, b, c, d)
  local s1, s2 = orient(a, b, c), orient(a, b, d)
  if min(max(s1, s2), -min(s1, s2)) <= 0 then return false end
  local s3, s4 = orient(c, d, a), orient(c, d, b)
  return min(max(s3, s4), -min(s3, s4)) > 0
end

-- Shamos and Hoey's sweep: the edges in order along a vertical line moving right; a proper
-- crossing shows up between two edges next to each other in that order before the line reaches
-- it, so each edge is tested only against its neighbours when it comes in and when it leaves.
-- Edge k runs from node k to nextNode[k]; sweepLeft[k] and sweepRight[k] are its ends in (x, y)
-- order. An event is k (edge k comes in at its left end) or -k (it leaves at its right end).
-- The vertices are sorted by place in expected linear time (buckets by x, see sortPlaces);
-- the order along the line is a sorted array, searched by halving. (A skip list, which spares
-- the array's shifts, made LuaJIT grow traces until its machine-code area ran out.)
local sweepCrossing
do   -- the sweep's helpers are local to it (the file is near Lua's 200 locals per function)
local sweepLeft, sweepRight
local rank                  -- rank[k]: node k's place in (x, y) order (1 for the first place)
local placeOrder, placeCount   -- the nodes in (x, y) order (see sortPlaces), and their count

-- > 0 when edge s lies above edge t where the line meets both (in y-up terms), < 0 below, 0 for
-- edges in line: the later left end tested against the other edge, then its right end.
local function edgeOrder(s, t)
  local flip = 1
  if rank[sweepLeft[s]] < rank[sweepLeft[t]] then s, t, flip = t, s, -1 end
  local a, b = sweepLeft[t], sweepRight[t]
  local side = orient(a, b, sweepLeft[s])
  if side == 0 then side = orient(a, b, sweepRight[s]) end
  return side * turn * flip
end

local BUCKET_RUN = 24   -- a bucket holding more nodes than this is sorted by table.sort
                        -- (many vertices on one vertical line), fewer by insertion

-- The nodes of the rings at `starts` in (x, y) order, and their count: counted into as many
-- buckets as nodes by x (the bucket is monotone in x), then each bucket sorted. Sets rank.
local function sortPlaces(starts)
  local x0, x1, count = huge, -huge, 0
  for _, s in ipairs(starts) do
    local k = s
    repeat
      x0, x1, count = min(x0, nodeX[k]), max(x1, nodeX[k]), count + 1
      k = nextNode[k]
    until k == s
  end
  local scale = count / (x1 - x0)   -- x1 > x0: the outer ring has area
  local bucketOf, first = newArray(capacity), newArray(count + 1)
  for b = 1, count + 1 do first[b] = 0 end
  for _, s in ipairs(starts) do
    local k = s
    repeat
      local b = min(floor((nodeX[k] - x0) * scale), count - 1) + 1
      bucketOf[k] = b
      first[b] = first[b] + 1
      k = nextNode[k]
    until k == s
  end
  local at = 1   -- first[b]: where bucket b starts in the order; then where its next node goes
  for b = 1, count + 1 do first[b], at = at, at + first[b] end
  local order, fill = newArray(count), newArray(count)
  for b = 1, count do fill[b] = first[b] end
  for _, s in ipairs(starts) do
    local k = s
    repeat
      local b = bucketOf[k]
      order[fill[b]] = k
      fill[b] = fill[b] + 1
      k = nextNode[k]
    until k == s
  end
  for b = 1, count do
    local lo, hi = first[b], first[b + 1] - 1
    if hi - lo >= BUCKET_RUN then
      local run = {}
      for i = lo, hi do run[i - lo + 1] = order[i] end
      sort(run, leftmostFirst)
      for i = lo, hi do order[i] = run[i - lo + 1] end
    else
      for i = lo + 1, hi do
        local k, j = order[i], i - 1
        while j >= lo and leftmostFirst(k, order[j]) do order[j + 1] = order[j]; j = j - 1 end
        order[j + 1] = k
      end
    end
  end
  rank = newArray(capacity)
  local place = 0
  for i = 1, count do
    local k = order[i]
    if i == 1 or not same(k, order[i - 1]) then place = place + 1 end
    rank[k] = place
  end
  placeOrder, placeCount = order, count
  return order, count
end

-- The events in order: by place, and at one place every edge leaving before any coming in.
local function sweepEvents(starts)
  local order, count = sortPlaces(starts)
  sweepLeft, sweepRight = newArray(capacity), newArray(capacity)
  for _, s in ipairs(starts) do
    local k = s
    repeat
      local q = nextNode[k]
      if rank[k] < rank[q] then sweepLeft[k], sweepRight[k] = k, q else sweepLeft[k], sweepRight[k] = q, k end
      k = q
    until k == s
  end
  local events, e = newArray(2 * count), 0
  local i = 1
  while i <= count do
    local last = i   -- the nodes at one place are order[i..last]
    while last < count and rank[order[last + 1]] == rank[order[i]] do last = last + 1 end
    for g = i, last do
      local v = order[g]
      local p = prevNode[v]
      if sweepRight[p] == v then e = e + 1; events[e] = -p end
      if sweepRight[v] == v then e = e + 1; events[e] = -v end
    end
    for g = i, last do
      local v = order[g]
      local p = prevNode[v]
      if sweepLeft[p] == v then e = e + 1; events[e] = p end
      if sweepLeft[v] == v then e = e + 1; events[e] = v end
    end
    i = last + 1
  end
  return events, e
end

local status, lastPlace   -- the edges in order along the line; where the last event's edge was
local touchedAt         -- touchedAt[r]: the edges whose inside holds the place of rank r, or nil

-- Notes the edges next to place `from` of the order, going `step` (-1 or 1), that hold node p:
-- a run of edges through p's place, each ending there or holding it inside (noted in
-- touchedAt, for placesCross). An edge holding p inside lies next to an edge ending at p, or
-- next to another edge through p, when an edge ending at p comes in or leaves.
local function noteTouches(p, from, step)
  local px, py = nodeX[p], nodeY[p]
  local j = from + step
  local f = status[j]
  while f do
    local q = nextNode[f]
    if orient(f, q, p) ~= 0 or px < min(nodeX[f], nodeX[q]) or px > max(nodeX[f], nodeX[q])
      or py < min(nodeY[f], nodeY[q]) or py > max(nodeY[f], nodeY[q]) then
      return
    end
    if not same(p, f) and not same(p, q) then
      local r = rank[p]
      local list = touchedAt[r] or {}
      touchedAt[r] = list
      local known = false
      for g = 1, #list do known = known or list[g] == f end
      if not known then list[#list + 1] = f end
    end
    j = j + step
    f = status[j]
  end
end

-- Where edge s goes or is, when next to the last event's edge, or 0: most vertices of an
-- outline that are not passed by an edge coming in where another leaves (see sweep) start two
-- edges or end two, one event after the other, next to each other along the line. An edge
-- coming in goes beside the edge that came in last from the same vertex when two tests vouch
-- for it (as for an edge taking another's place); an edge leaving is found by identity. Spares
-- most searches of a noisy circle, whose order holds hundreds of edges.
local function besideLast(s, coming)
  local t = status[lastPlace]
  if coming then
    if not t or rank[sweepLeft[t]] ~= rank[sweepLeft[s]] then return 0 end
    if edgeOrder(s, t) > 0 then
      local above = status[lastPlace + 1]
      return (not above or edgeOrder(s, above) <= 0) and lastPlace + 1 or 0
    end
    local below = status[lastPlace - 1]
    return (not below or edgeOrder(s, below) > 0) and lastPlace or 0
  end
  if t == s then return lastPlace end
  return status[lastPlace - 1] == s and lastPlace - 1 or 0
end

-- true when two edges of the rings at `starts` properly cross, false when none do, nil when the
-- order came out inconsistent (then the caller asks anyCrossing).
local function sweep(starts)
  local events, eventCount = sweepEvents(starts)
  -- the order is status[bottom + 1 .. bottom + m]. On LuaJIT an edge coming in or leaving
  -- shifts the shorter side, so bottom moves, by one per event at most: starting it half the
  -- events up keeps it in the array. (A vertical line meets some 650 edges of a noisy circle
  -- of 10,000 vertices: the shorter side moves 200 entries a vertex where one side moved 440.)
  local m, bottom = 0, JIT and eventCount or 0
  status, touchedAt = newArray(2 * eventCount + 2), {}
  lastPlace = bottom + 1
  local i = 1
  while i <= eventCount do
    local e = events[i]
    local s = e > 0 and e or -e
    local lo = besideLast(s, e > 0)
    if lo == 0 then   -- the first place whose edge does not lie below s
      local hi
      lo, hi = bottom + 1, bottom + m + 1
      while lo < hi do
        local mid = (lo + hi - (lo + hi) % 2) / 2
        if edgeOrder(s, status[mid]) > 0 then lo = mid + 1 else hi = mid end
      end
    end
    if e > 0 then
      if not JIT then   -- on PUC Lua table.insert's C loop is faster than a loop in Lua
        table.insert(status, lo, s)
      elseif lo - bottom - 1 < bottom + m + 1 - lo then   -- fewer entries below: shift those down
        for j = bottom + 1, lo - 1 do status[j - 1] = status[j] end
        bottom, lo = bottom - 1, lo - 1
        status[lo] = s
      else
        for j = bottom + m, lo, -1 do status[j + 1] = status[j] end
        status[lo] = s
      end
      m = m + 1
      lastPlace = lo
      noteTouches(sweepLeft[s], lo, -1)
      noteTouches(sweepLeft[s], lo, 1)
      local below, above = status[lo - 1], status[lo + 1]
      if below and properlyCross(s, nextNode[s], below, nextNode[below]) then return true end
      if above and properlyCross(s, nextNode[s], above, nextNode[above]) then return true end
    else
      while lo <= bottom + m and status[lo] ~= s and edgeOrder(s, status[lo]) == 0 do lo = lo + 1 end
      if status[lo] ~= s then return nil end
      lastPlace = lo
      noteTouches(sweepRight[s], lo, -1)
      noteTouches(sweepRight[s], lo, 1)
      local below, above = status[lo - 1], status[lo + 1]
      -- an edge coming in where s leaves (a vertex along the outline) most often takes its
      -- place: two tests vouch for it, and the list is not shifted twice
      local t = events[i + 1]
      if t and t > 0 and rank[sweepLeft[t]] == rank[sweepRight[s]]
        and (not below or edgeOrder(t, below) > 0) and (not above or edgeOrder(t, above) <= 0) then
        status[lo] = t
        i = i + 1
        if below and properlyCross(t, nextNode[t], below, nextNode[below]) then return true end
        if above and properlyCross(t, nextNode[t], above, nextNode[above]) then return true end
      else
        if not JIT then   -- as for table.insert above (a loop is 40 % faster on LuaJIT)
          table.remove(status, lo)
        elseif lo - bottom - 1 < bottom + m - lo then   -- the entries below s move up
          for j = lo, bottom + 2, -1 do status[j] = status[j - 1] end
          status[bottom + 1] = nil
          bottom = bottom + 1
          lastPlace = lo + 1   -- as when the entries above move down: the two ends are at
        else                   -- lastPlace - 1 and lastPlace
          for j = lo, bottom + m - 1 do status[j] = status[j + 1] end
          status[bottom + m] = nil
        end
        m = m - 1
        if below and above and properlyCross(below, nextNode[below], above, nextNode[above]) then
          return true
        end
      end
    end
    i = i + 1
  end
  return false
end

-- Where several vertices meet, or a vertex lies inside an edge, the outline may cross or
-- overlap itself without two edges crossing properly (the sweep's test). Around such a place
-- each vertex is a chain: an edge coming in (from its node's predecessor) and one going out
-- (to its successor); an edge holding the place inside is a chain too. Sorted by angle, the
-- edges must alternate, in, out, in, out: crossing an edge changes the winding number by one,
-- up for one kind and down for the other, so two of a kind in a row make a sector covered
-- twice (or wound the wrong way). And no two chains may interleave (the in-out pairs must nest
-- like brackets): chains that interleave cross there, whatever is done near the place. Edges
-- in one direction overlap along it: crossing them all changes the winding number by those
-- leaving less those reaching, which must be -1, 0 or 1 (two edges leaving in one direction,
-- none reaching: the region between them is inside one and outside the other); past that
-- their order across the direction is not known there (a slit, a bridge, a spike along an
-- edge): one edge each way may go in either order (each is tried), more leave the place
-- untested. An entry is 2k for the edge from node k to its
-- successor, 2k + 1 for the edge from its predecessor; an edge f holding the place inside is
-- chain k = capacity + f, its ends f (before) and f's successor (after).
local placeX, placeY        -- the place being tested, for byAngle
local function entryTarget(entry)
  local k = (entry - entry % 2) / 2
  if k > capacity then
    local f = k - capacity
    return entry % 2 == 0 and nextNode[f] or f
  end
  return entry % 2 == 0 and nextNode[k] or prevNode[k]
end
-- Whether the entry u's edge comes before v's by angle about the place, from the +x axis
-- (exact: the side of the x axis, then the sign of a cross product).
local function byAngle(u, v)
  local a, b = entryTarget(u), entryTarget(v)
  local ax, ay, bx, by = nodeX[a], nodeY[a], nodeX[b], nodeY[b]
  local lowerA = ay < placeY or (ay == placeY and ax < placeX)
  local lowerB = by < placeY or (by == placeY and bx < placeX)
  if lowerA ~= lowerB then return lowerB end
  return cross(placeX, placeY, ax, ay, placeX, placeY, bx, by) > 0
end

-- Whether the chains of the nodes placeOrder[first..last], all at one place, and of the edges
-- `touched` holding it inside (or nil), cross or overlap there (see above).
local TIED_PAIRS = 4      -- pairs of edges along one another (both ways) at a place, at most,
                        -- whose 2^pairs orders are tried; past that the place is not tested

-- Whether entries[1..count], sorted by angle, alternate in and out and nest like brackets.
local function alternateAndNest(entries, count)
  local open, depth = {}, 0   -- the chains' pairs, as brackets
  for j = 1, count do
    local u = entries[j]
    if u % 2 == entries[j % count + 1] % 2 then return false end   -- two of a kind in a row
    local chain = (u - u % 2) / 2
    if depth > 0 and open[depth] == chain then
      open[depth] = nil
      depth = depth - 1
    else
      depth = depth + 1
      open[depth] = chain
    end
  end
  return depth == 0
end

local function chainsCross(first, last, touched)
  local entries, count = {}, 0
  for g = first, last do
    local k = placeOrder[g]
    entries[count + 1], entries[count + 2] = 2 * k, 2 * k + 1
    count = count + 2
  end
  for g = 1, touched and #touched or 0 do
    local k = capacity + touched[g]
    entries[count + 1], entries[count + 2] = 2 * k, 2 * k + 1
    count = count + 2
  end
  placeX, placeY = nodeX[placeOrder[first]], nodeY[placeOrder[first]]
  sort(entries, byAngle)
  local at, tied = 1, {}
  while at <= count do   -- the runs of edges in one direction: count those leaving, reaching
    local u, runEnd, balance = entries[at], at, 0
    while runEnd < count and not byAngle(u, entries[runEnd + 1]) do runEnd = runEnd + 1 end
    for j = at, runEnd do balance = balance + (entries[j] % 2 == 0 and 1 or -1) end
    if balance > 1 or balance < -1 then return true end
    if runEnd > at + 1 then return false end   -- three or more: not decided here
    if runEnd == at + 1 then tied[#tied + 1] = at end   -- one each way: either order
    at = runEnd + 1
  end
  if #tied > TIED_PAIRS then return false end
  for orders = 0, 2 ^ #tied - 1 do   -- bit t of orders: swap the t-th tied pair
    local swapped = orders
    for t = 1, #tied do
      local j = tied[t]
      if swapped % 2 == 1 then entries[j], entries[j + 1] = entries[j + 1], entries[j] end
      swapped = (swapped - swapped % 2) / 2
    end
    if alternateAndNest(entries, count) then return false end
    swapped = orders
    for t = 1, #tied do
      local j = tied[t]
      if swapped % 2 == 1 then entries[j], entries[j + 1] = entries[j + 1], entries[j] end
      swapped = (swapped - swapped % 2) / 2
    end
  end
  return true
end

-- Whether the chains cross or overlap at some place where several vertices meet, or where a
-- vertex lies inside an edge.
local function placesCross()
  local i = 1
  while i <= placeCount do
    local r, last = rank[placeOrder[i]], i
    while last < placeCount and rank[placeOrder[last + 1]] == r do last = last + 1 end
    if (last > i or touchedAt[r]) and chainsCross(i, last, touchedAt[r]) then return true end
    i = last + 1
  end
  return false
end

function sweepCrossing(starts)
  local crossing = sweep(starts)
  if crossing == false and placesCross() then crossing = true end
  sweepLeft, sweepRight, rank, status, placeOrder, touchedAt = nil, nil, nil, nil, nil, nil
  return crossing
end
end

-- The same answer by a plainer sweep, should sweepCrossing find its order inconsistent: the
-- edges sorted by their left end, each compared with the earlier ones still reaching it.
local function anyCrossing(starts)
  local edges, left = {}, {}
  for _, s in ipairs(starts) do
    local k = s
    repeat
      local q = nextNode[k]
      edges[#edges + 1] = k
      left[k] = min(nodeX[k], nodeX[q])
      k = q
    until k == s
  end
  sortKey = left
  sort(edges, bySortKey)
  local active, count = {}, 0
  for e = 1, #edges do
    local a = edges[e]
    local b = nextNode[a]
    local x0 = left[a]
    local y0, y1 = min(nodeY[a], nodeY[b]), max(nodeY[a], nodeY[b])
    local j = 1
    while j <= count do
      local c = active[j]
      local d = nextNode[c]
      if max(nodeX[c], nodeX[d]) < x0 then   -- ends before this edge begins: drop it
        active[j] = active[count]; active[count] = nil; count = count - 1
      else
        if max(nodeY[c], nodeY[d]) >= y0 and min(nodeY[c], nodeY[d]) <= y1
          and properlyCross(a, b, c, d) then
          return true
        end
        j = j + 1
      end
    end
    count = count + 1; active[count] = a
  end
  return false
end

-- -1, 0 or 1: where (x, y) lies against the ring at node s (outside, on it, strictly inside),
-- by the crossing rule with the exact side test and an exact test for the boundary.
local function ringSide(s, x, y)
  local inside = false
  local k = s
  repeat
    local q = nextNode[k]
    local x1, y1, x2, y2 = nodeX[k], nodeY[k], nodeX[q], nodeY[q]
    local c = cross(x1, y1, x2, y2, x1, y1, x, y)
    if c == 0 and min(x1, x2) <= x and x <= max(x1, x2) and min(y1, y2) <= y and y <= max(y1, y2) then
      return 0
    end
    if (y1 > y) ~= (y2 > y) and (y2 > y1) == (c > 0) then inside = not inside end
    k = q
  until k == s
  return inside and 1 or -1
end

-- Whether the direction from node k to node t points strictly into the interior at k.
local function sectorHolds(k, t)
  local a, c = prevNode[k], nextNode[k]
  local s1, s2 = orient(a, k, t), orient(k, c, t)
  if orient(a, k, c) > 0 then return s1 > 0 and s2 > 0 end
  return s1 > 0 or s2 > 0
end

-- Among the nodes of the ring at s at the place of node m, one whose interior holds the
-- direction towards node t (a pinch point has several; each sees a different side).
local function copyFacing(s, m, t)
  local k, found = s, m
  repeat
    if same(k, m) and sectorHolds(k, t) then found = k end
    k = nextNode[k]
  until k == s
  return found
end

-- Which of two edges, each crossing the line y = hy strictly between its ends, meets it further
-- right: 1 when f does, -1 when e does, 0 when they meet it at one point. The edges do not
-- properly cross, so one end of either, tested against the other, tells. e and f are the
-- lower ends' nodes (by y), eh and fh the upper.
local function rightOf(e, eh, f, fh)
  local s
  if nodeY[f] >= nodeY[e] then s = -orient(e, eh, f) else s = orient(f, fh, e) end
  if s == 0 then
    if nodeY[fh] <= nodeY[eh] then s = -orient(e, eh, fh) else s = orient(f, fh, eh) end
  end
  return s * turn   -- orient's sign times turn is the plain sign of the cross product
end

-- Whether (x, y), in line with (hx, hy) and (bx, by) on the same side, lies strictly between.
local function between(hx, hy, x, y, bx, by)
  if x ~= bx then return (hx < x) == (x < bx) and x ~= hx end
  return (hy < y) == (y < by) and y ~= hy
end

-- The node of the ring at s that the hole's leftmost node h joins: the nearest point hit by the
-- ray from h to the left is a vertex, or lies on an edge whose right end P is seen from h unless
-- another vertex in the triangle (h, hit, P) is: the one there at the least angle from the ray
-- (nearest on ties) is seen. nil when the ray hits nothing (the hole is outside).
local function bridgeTarget(s, h)
  local hx, hy = nodeX[h], nodeY[h]
  local vertex, lo, hi   -- the nearest hit so far: a vertex, or an edge lo -> hi (upwards in y)
  local k = s
  repeat
    local q = nextNode[k]
    local x, y = nodeX[k], nodeY[k]
    if y == hy and x <= hx then
      if x == hx then return copyFacing(s, k, nextNode[h]) end   -- the hole touches the ring here
      if lo then
        if cross(nodeX[lo], nodeY[lo], nodeX[hi], nodeY[hi], nodeX[lo], nodeY[lo], x, y) <= 0 then
          vertex, lo, hi = k, nil, nil
        end
      elseif not vertex or x > nodeX[vertex] then
        vertex = k
      end
    end
    local qy = nodeY[q]
    if (y < hy and qy > hy) or (y > hy and qy < hy) then
      local a, b = k, q
      if y > qy then a, b = q, k end
      local ax, ay = nodeX[a], nodeY[a]
      if cross(ax, ay, nodeX[b], nodeY[b], ax, ay, hx, hy) <= 0 then   -- meets the ray
        if vertex then
          if cross(ax, ay, nodeX[b], nodeY[b], ax, ay, nodeX[vertex], nodeY[vertex]) > 0 then
            vertex, lo, hi = nil, a, b
          end
        elseif not lo or rightOf(lo, hi, a, b) > 0 then
          lo, hi = a, b
        end
      end
    end
    k = q
  until k == s
  if vertex then return copyFacing(s, vertex, h) end
  if not lo then return nil end
  local p = nodeX[hi] > nodeX[lo] and hi or lo
  local side = nodeY[p] > hy and 1 or -1   -- the side of the ray the triangle lies on
  local lx, ly, ux, uy = nodeX[lo], nodeY[lo], nodeX[hi], nodeY[hi]
  local best = p
  k = s
  repeat
    local x, y = nodeX[k], nodeY[k]
    if (y - hy) * side > 0 and cross(lx, ly, ux, uy, lx, ly, x, y) <= 0 then
      local c = cross(hx, hy, nodeX[p], nodeY[p], hx, hy, x, y) * side
      if c >= 0 then   -- inside the triangle (h, hit, P) or on its sides
        local t = cross(hx, hy, x, y, hx, hy, nodeX[best], nodeY[best]) * side
        if t < 0 or (t == 0 and between(hx, hy, x, y, nodeX[best], nodeY[best])) then best = k end
      end
    end
    k = nextNode[k]
  until k == s
  return copyFacing(s, best, h)
end

-- Joins the hole ring at node h to the ring at node m: m -> h ... around the hole ... h' -> m'
-- with h' and m' new nodes at the places of h and m. A hole touching the ring (m at h) makes
-- repeated vertices, removed at once.
local function bridge(m, h)
  local m2, h2 = newNode(inX[m], inY[m], origin[m]), newNode(inX[h], inY[h], origin[h])
  local mn, hp = nextNode[m], prevNode[h]
  nextNode[m], prevNode[h] = h, m
  nextNode[hp], prevNode[h2] = h2, hp
  nextNode[h2], prevNode[m2] = m2, h2
  nextNode[m2], prevNode[mn] = mn, m2
  if same(m, h) then unlink(h); unlink(m2) end
end

-- The ear test's index: a grid of square cells over the ring's box, each holding entries for the
-- nodes in it that may still block an ear (see keepListed). An ear's triangle is visited row of
-- cells by row, only the cells its span in that row touches: a long thin triangle (a spike of
-- a noisy outline) meets a few cells per row where its box would hold a large share of all
-- the nodes.
local CELL_LOAD = 2     -- nodes per cell on average, when the grid is built
local SHARED_RUN = 8    -- nodes of one cell compared pair by pair, at most (then all shared)
local FINE = 2 ^ -30    -- cells wider than this times the largest coordinate are visited by
                        -- the triangle's span (rounding stays far below a cell); narrower
                        -- ones, by its box (an outline tiny against its offset)
local SPAN_MARGIN = 2 ^ -10   -- a span's widening, in cells: with FINE, at least 2^-40 of the
                        -- largest coordinate, thousands of times its few ulps of rounding
local gridLeft, gridTop, gridScale, gridCols, gridRows, cellSize, gridFine
local spanMargin        -- twice SPAN_MARGIN cells (nearTriangle compares doubled widths), or
                        -- huge when the grid is not fine

-- The column or row of a coordinate: monotone in it (the scaling rounds monotonically), so a
-- box's corners bound the cells of every point inside it.
local function colOf(x)
  local col = floor((x - gridLeft) * gridScale)
  return col < gridCols and col or gridCols - 1
end
local function rowOf(y)
  local row = floor((y - gridTop) * gridScale)
  return row < gridRows and row or gridRows - 1
end

-- Files the nodes of the ring at s that may block an ear in their cells (the strictly convex
-- ones are left out from the start, see keepListed), and marks the nodes sharing a place. The
-- entries lie cell after cell, each with its node's place copied in, so the cells of a row's
-- span are one stretch of consecutive entries, read by one loop (see isEar); a node dropped
-- later keeps its entry, marked by x = huge, which no span holds.
local function buildGrid(s)
  local x0, y0, x1, y1, count = huge, huge, -huge, -huge, 0
  local k = s
  repeat
    x0, y0 = min(x0, nodeX[k]), min(y0, nodeY[k])
    x1, y1 = max(x1, nodeX[k]), max(y1, nodeY[k])
    count = count + 1
    k = nextNode[k]
  until k == s
  -- the ring has area, so its box has width and height
  cellSize = sqrt((x1 - x0) * (y1 - y0) * CELL_LOAD / count)
  gridLeft, gridTop, gridScale = x0, y0, 1 / cellSize
  gridCols = min(floor((x1 - x0) * gridScale) + 1, count)
  gridRows = min(floor((y1 - y0) * gridScale) + 1, count)
  gridFine = cellSize > FINE * max(abs(x0), abs(x1), abs(y0), abs(y1))
  spanMargin = gridFine and 2 * SPAN_MARGIN * cellSize or huge
  local cells = gridRows * gridCols
  local cellOf = newArray(capacity)
  cellStart = newArray(cells + 1)
  for c = 1, cells + 1 do cellStart[c] = 0 end
  k = s
  repeat
    local cell = rowOf(nodeY[k]) * gridCols + colOf(nodeX[k]) + 1
    cellOf[k], cellStart[cell] = cell, cellStart[cell] + 1
    k = nextNode[k]
  until k == s
  local at = 1   -- the counts become each cell's first entry, then (filling) its next one
  for c = 1, cells + 1 do cellStart[c], at = at, at + cellStart[c] end
  entryX, entryY, entryNode = newArray(count), newArray(count), newArray(count)
  entryOf = newArray(capacity)
  listed, shared, reflexSeen, listStale = newArray(capacity), newArray(capacity), newArray(capacity), false
  k = s
  repeat
    local cell = cellOf[k]
    entryNode[cellStart[cell]], cellStart[cell] = k, cellStart[cell] + 1
    k = nextNode[k]
  until k == s
  for c = cells, 1, -1 do cellStart[c + 1] = cellStart[c] end   -- back to first entries
  cellStart[1] = 1
  local kept = 0
  for c = 1, cells do
    local first, last = cellStart[c], cellStart[c + 1] - 1
    -- nodes at one place share a cell; a crowded cell is all marked shared
    for i = first, last do
      local j = entryNode[i]
      if last - first >= SHARED_RUN then shared[j] = true end
      for m = i + 1, last - first < SHARED_RUN and last or i do
        if same(j, entryNode[m]) then shared[j], shared[entryNode[m]] = true, true end
      end
    end
    -- keep the nodes not strictly convex and those sharing a place, packed cell after cell
    cellStart[c] = kept + 1
    for i = first, last do
      k = entryNode[i]
      local convex = not shared[k] and orient(prevNode[k], k, nextNode[k]) > 0
      if not convex then
        kept = kept + 1
        entryNode[kept], entryX[kept], entryY[kept], entryOf[k] = k, nodeX[k], nodeY[k], kept
        listed[k], reflexSeen[k] = true, not shared[k]
      end
    end
  end
  cellStart[cells + 1] = kept + 1
end

-- Whether node k may still block an ear: an ear's triangle that holds some node holds a node
-- not strictly convex (the highest point inside over the new edge c -> a turns away from the
-- inside, which sees past it), or one at a pinch point; a strictly convex node elsewhere is
-- left out of the grid, or dropped from it at its first test, as clipping never makes it reflex again (its
-- neighbours only move inwards) unless a spike collapses over it (then settle sets listStale
-- and the grid is built again).
local function keepListed(k)
  if reflexSeen[k] or shared[k] then return true end
  if orient(prevNode[k], k, nextNode[k]) > 0 then unlist(k); return false end
  reflexSeen[k] = true
  return true
end

-- Whether node k keeps the triangle (a, b, c) (turning the ring's way) from being an ear: it
-- lies strictly inside, or on the triangle's boundary with an edge going into it, or (while
-- `strict`) on the new edge c -> a, which would leave a vertex inside an edge and so a
-- triangle that cannot merge with its neighbours.
local strict = true
local function blocks(k, a, b, c)
  local s1 = orient(a, b, k)
  if s1 < 0 then return false end
  local s2 = orient(b, c, k)
  if s2 < 0 then return false end
  local s3 = orient(c, a, k)
  if s3 < 0 then return false end
  if s1 > 0 and s2 > 0 and s3 > 0 then return true end
  if strict and s3 == 0 and not same(k, a) and not same(k, c) then return true end
  for side = 1, 2 do
    local t = side == 1 and prevNode[k] or nextNode[k]
    if same(k, a) then
      if orient(a, b, t) > 0 and orient(c, a, t) > 0 then return true end
    elseif same(k, b) then
      if orient(a, b, t) > 0 and orient(b, c, t) > 0 then return true end
    elseif same(k, c) then
      if orient(b, c, t) > 0 and orient(c, a, t) > 0 then return true end
    elseif (s1 == 0 and orient(a, b, t) > 0) or (s2 == 0 and orient(b, c, t) > 0)
      or (s3 == 0 and orient(c, a, t) > 0) then
      return true
    end
  end
  return false
end

-- The triangle under test, for the helpers below (upvalues rather than arguments: loops with
-- many live values, or branches inside them, made LuaJIT 2.1 abort their side traces,
-- "register coalescing too complex", until it flushed all its traces). Corners a, b, c as the
-- ring runs; the box x0..x1, y0..y1; for the spans, the top corner t, the middle one m, and
-- the slopes dx/dy of the long side t -> bottom and of the short sides t -> m and m -> bottom.
local earA, earB, earC, boxX0, boxY0, boxX1, boxY1, boxCol0, boxCol1
local spanX0, spanX1    -- the triangle's widened span in x over the row being visited
local topX, topY, midX, midY, longSlope, upperSlope, lowerSlope

-- The columns of the cells the triangle may meet in a row: its span in x over the row's band
-- of y, band and span widened by SPAN_MARGIN cells against rounding (the last row's band runs
-- to the box's bottom: rowOf puts every node beyond the grid there). Each side is straight, so
-- its x over [lo, hi] is extreme at the ends; a short side's ends are clamped to its own rows
-- (m may come in when outside [lo, hi]: a wider span, never a narrower one). A cell's width
-- of widening on each side cost a thin spike's ear three cells a row instead of one or two.
local function rowSpan(row)
  if not gridFine then spanX0, spanX1 = boxX0, boxX1; return boxCol0, boxCol1 end
  local margin = SPAN_MARGIN * cellSize
  local lo = max(boxY0, gridTop + row * cellSize - margin)
  local hi = row < gridRows - 1 and min(boxY1, gridTop + (row + 1) * cellSize + margin) or boxY1
  local x1, x2 = topX + (lo - topY) * longSlope, topX + (hi - topY) * longSlope
  local x3, x4 = topX + (min(lo, midY) - topY) * upperSlope, topX + (min(hi, midY) - topY) * upperSlope
  local x5, x6 = midX + (max(lo, midY) - midY) * lowerSlope, midX + (max(hi, midY) - midY) * lowerSlope
  spanX0 = max(boxX0, min(x1, x2, x3, x4, x5, x6) - margin)
  spanX1 = min(boxX1, max(x1, x2, x3, x4, x5, x6) + margin)
  return colOf(spanX0), colOf(spanX1)
end

-- Whether (x, y), in the triangle's box, lies near the triangle: within its span in x at
-- height y, widened by spanMargin (as rowSpan, far beyond rounding). A long thin ear meets
-- about one candidate a row that only the exact test would turn down otherwise. The short
-- sides are both measured from m, each clamped to its own rows, so their sum is the short
-- side's x at y (a level side too) without a branch: branches here multiplied LuaJIT's side
-- traces until its machine-code area ran out.
local function nearTriangle(x, y)
  local xLong = topX + (y - topY) * longSlope
  local xShort = midX + (min(y, midY) - midY) * upperSlope + (max(y, midY) - midY) * lowerSlope
  return abs(x + x - xLong - xShort) <= abs(xLong - xShort) + spanMargin
end

-- Whether node b, strictly convex, is an ear: no listed node in the cells its triangle meets
-- blocks it.
local function isEar(b)
  local a, c = prevNode[b], nextNode[b]
  earA, earB, earC = a, b, c
  boxX0, boxY0 = min(nodeX[a], nodeX[b], nodeX[c]), min(nodeY[a], nodeY[b], nodeY[c])
  boxX1, boxY1 = max(nodeX[a], nodeX[b], nodeX[c]), max(nodeY[a], nodeY[b], nodeY[c])
  boxCol0, boxCol1 = colOf(boxX0), colOf(boxX1)
  local t, m, u = a, b, c
  if nodeY[m] < nodeY[t] then t, m = m, t end
  if nodeY[u] < nodeY[m] then m, u = u, m end
  if nodeY[m] < nodeY[t] then t, m = m, t end
  topX, topY, midX, midY = nodeX[t], nodeY[t], nodeX[m], nodeY[m]
  -- a level side has slope 0: its ends come in as the other sides' ends
  longSlope = (nodeX[u] - topX) / (nodeY[u] - topY)   -- not level: the triangle has area
  upperSlope = midY > topY and (midX - topX) / (midY - topY) or 0
  lowerSlope = nodeY[u] > midY and (nodeX[u] - midX) / (nodeY[u] - midY) or 0
  -- one loop over the entries of the rows' spans, one row after the other: a loop per row (a
  -- few entries) ran as a trace of its own, and every row left it for the interpreter
  local row, lastRow, j, last = rowOf(boxY0) - 1, rowOf(boxY1), 1, 0
  while true do
    if j > last then   -- the next row's span
      row = row + 1
      if row > lastRow then return true end
      local left, right = rowSpan(row)
      local base = row * gridCols + 1
      j, last = cellStart[base + left], cellStart[base + right + 1] - 1
    elseif JIT then
      -- the tests of the span, the box and nearTriangle as one number, <= 0 when all pass, and
      -- one branch, taken about once per ear: a branch per test went both ways, and every
      -- side trace taken went back to the loop's start (x clamped: dropped entries hold huge)
      local x, y = entryX[j], entryY[j]
      local xLong = topX + (y - topY) * longSlope
      local xShort = midX + (min(y, midY) - midY) * upperSlope + (max(y, midY) - midY) * lowerSlope
      local xNear = min(x, spanX1)
      if max(spanX0 - x, x - spanX1, boxY0 - y, y - boxY1,
          abs(xNear + xNear - xLong - xShort) - abs(xLong - xShort) - spanMargin) <= 0 then
        local k = entryNode[j]
        if k ~= earA and k ~= earC and keepListed(k) and blocks(k, earA, earB, earC) then
          return false
        end
      end
      j = j + 1
    else
      local x = entryX[j]
      if x >= spanX0 and x <= spanX1 then
        local y, k = entryY[j], entryNode[j]
        if y >= boxY0 and y <= boxY1 and k ~= earA and k ~= earC and nearTriangle(x, y)
          and keepListed(k) and blocks(k, earA, earB, earC) then
          return false
        end
      end
      j = j + 1
    end
  end
end

-- Clips ears from the ring at s until it is gone, appending each triangle's three nodes to
-- tris. No node in line with its neighbours is kept (a straight run, a repeated vertex, the tip
-- of a spike): each is dropped without a triangle, at the start and whenever a clip or a drop
-- brings one about, so the ring never holds a zero-width spike for an ear to reach across.
-- A lap that finds no ear is retried with strict off; returns false when that one finds none
-- either (the ring is not weakly simple).
local ringCount, pending, pendingTop   -- clipEars' state, for settle

-- Drops the pending nodes that lie in line with their neighbours, and those this brings in line.
local function settle()
  while pendingTop > 0 and ringCount > 2 do
    local j = pending[pendingTop]
    pending[pendingTop] = nil; pendingTop = pendingTop - 1
    if not gone[j] and orient(prevNode[j], j, nextNode[j]) == 0 then
      unlink(j); ringCount = ringCount - 1
      local p, q = prevNode[j], nextNode[j]
      pending[pendingTop + 1], pending[pendingTop + 2] = p, q
      pendingTop = pendingTop + 2
      if listed then
        reflexSeen[p], reflexSeen[q] = false, false
        -- a spike dropped may leave p or q facing back: reflex again, and maybe off the list
        if (not listed[p] and orient(prevNode[p], p, q) <= 0)
          or (not listed[q] and orient(p, q, nextNode[q]) <= 0) then
          listStale = true
        end
      end
    end
  end
  for j = pendingTop, 1, -1 do pending[j] = nil end
  pendingTop = 0
end

local function clipEars(s, tris)
  strict = true
  ringCount, pending = 0, {}
  local k = s
  repeat ringCount = ringCount + 1; pending[ringCount] = k; k = nextNode[k] until k == s
  pendingTop = ringCount
  settle()
  local ear = s
  while gone[ear] do ear = nextNode[ear] end
  local stop = ear
  while ringCount > 2 do
    local a, c = prevNode[ear], nextNode[ear]
    if listStale then buildGrid(ear) end
    if orient(a, ear, c) > 0 and isEar(ear) then
      local t = #tris
      tris[t + 1], tris[t + 2], tris[t + 3] = a, ear, c
      unlink(ear); ringCount = ringCount - 1
      reflexSeen[a], reflexSeen[c] = false, false
      pending[1], pending[2], pendingTop = a, c, 2
      settle()
      ear = c
      while gone[ear] do ear = nextNode[ear] end
      stop = ear
      strict = true
    else
      ear = c
      if ear == stop then
        if not strict then return false end
        strict = false
      end
    end
  end
  return true
end

-- Checks the arguments and triangulates: the triangles' nodes (a flat array, three per
-- triangle), or nil and a message. Leaves the node arrays set for the caller to read.
local function triangulate(fname, points, holes)
  local n = checkPoints(points, fname, "points", 4)
  if holes ~= nil and type(holes) ~= "table" then
    error(("%s: holes must be a table, got %s"):format(fname, type(holes)), 3)
  end
  local ok, message = polygon.validate(points)
  if not ok then
    if n < 6 then return nil, message end
    error(fname .. ": " .. message, 3)
  end
  for h = 1, holes and #holes or 0 do
    ok, message = polygon.validate(holes[h])
    if not ok then error(("%s: holes[%d]: %s"):format(fname, h, message), 3) end
  end
  turn = areaSign(points, n)
  if turn == 0 then return nil, "points have zero area" end
  turn = turn > 0 and 1 or -1
  capacity = n / 2
  for h = 1, holes and #holes or 0 do capacity = capacity + #holes[h] / 2 + 2 end   -- 2: a bridge
  nodeX, nodeY, inX, inY = newArray(capacity), newArray(capacity), newArray(capacity), newArray(capacity)
  origin, nextNode = newArray(capacity), newArray(capacity)
  prevNode, gone = newArray(capacity), newArray(capacity)
  nodeCount = 0
  listed = nil
  local outer = linkRing(points, n, 1, false)
  local starts, firstId = { outer }, n / 2 + 1
  for h = 1, holes and #holes or 0 do
    local hole = holes[h]
    local m = #hole
    local s = areaSign(hole, m)
    if s == 0 then return nil, ("holes[%d] has zero area"):format(h) end
    -- a hole runs against the outer ring, so that the joined ring keeps the inside on one side
    starts[h + 1] = linkRing(hole, m, firstId, (s > 0) == (turn > 0))
    firstId = firstId + m / 2
  end
  local crossing = sweepCrossing(starts)
  if crossing == nil then crossing = anyCrossing(starts) end
  if crossing then return nil, "edges cross" end
  for h = 2, #starts do
    local k, side = starts[h]
    repeat
      side = ringSide(outer, nodeX[k], nodeY[k])
      k = nextNode[k]
    until side ~= 0 or k == starts[h]
    if side < 0 then return nil, ("holes[%d] is outside the polygon"):format(h - 1) end
    for g = 2, #starts do
      if g ~= h then
        k = starts[h]
        repeat
          side = ringSide(starts[g], nodeX[k], nodeY[k])
          k = nextNode[k]
        until side ~= 0 or k == starts[h]
        if side > 0 then return nil, ("holes[%d] is inside holes[%d]"):format(h - 1, g - 1) end
      end
    end
  end
  -- join the holes from left to right, each at its leftmost vertex (ties: the topmost)
  local lefts = {}
  for h = 2, #starts do
    local best, k = starts[h], starts[h]
    repeat
      if nodeX[k] < nodeX[best] or (nodeX[k] == nodeX[best] and nodeY[k] < nodeY[best]) then best = k end
      k = nextNode[k]
    until k == starts[h]
    lefts[#lefts + 1] = best
  end
  sort(lefts, leftmostFirst)
  for i = 1, #lefts do
    local m = bridgeTarget(outer, lefts[i])
    if not m then return nil, "a hole is outside the polygon" end
    bridge(m, lefts[i])
  end
  buildGrid(outer)
  local tris = newArray(3 * nodeCount)
  if not clipEars(outer, tris) then return nil, "edges overlap or cross" end
  return tris
end

-- Drops the node arrays of the last call.
local function releaseNodes()
  nodeX, nodeY, inX, inY, origin, nextNode, prevNode, gone = nil, nil, nil, nil, nil, nil, nil, nil
  sortKey, listed, shared, reflexSeen = nil, nil, nil, nil
  cellStart, entryX, entryY, entryNode, entryOf = nil, nil, nil, nil, nil
end

--- Splits a polygon, optionally with holes, into triangles. Builds new tables: for load time,
-- not for every frame.
-- points: a flat array; holes: nil or an array of flat arrays inside the polygon (a hole may
-- touch the outline or another hole at a vertex). Weakly simple outlines work: repeated
-- vertices, straight runs, outlines touching themselves at a vertex (tile-map outlines).
-- Every decision is an exact sign; no triangle has zero area. Edges that properly cross are
-- found by a sweep (Shamos and Hoey), an outline crossing or running along itself where
-- vertices meet by the order of the edges around each such place; the ears cost a few
-- microseconds per vertex on LuaJIT, growing about as the square root of n on outlines of long
-- thin spikes (bench/concave.lua).
-- @return an array of triangles {x1, y1, x2, y2, x3, y3}, copies of input vertices, each wound
-- like points; or nil and a message (fewer than 3 points, zero area, crossing edges, a hole
-- outside the polygon)
function polygon.polygonTriangulate(points, holes)
  local tris, message = triangulate("polygonTriangulate", points, holes)
  if not tris then releaseNodes(); return nil, message end
  local out = newArray(#tris / 3)
  for t = 1, #tris, 3 do
    local a, b, c = tris[t], tris[t + 1], tris[t + 2]
    out[#out + 1] = { inX[a], inY[a], inX[b], inY[b], inX[c], inY[c] }
  end
  releaseNodes()
  return out
end

--- Splits a polygon, optionally with holes, into convex parts: the triangulation's triangles
-- merged greedily across their shared edges while both ends stay convex (Hertel and Mehlhorn:
-- at most four times the fewest parts possible). Builds new tables: for load time.
-- Arguments and errors as polygonTriangulate; a convex polygon gives one part.
-- @return an array of convex polygons (flat arrays of input vertices, wound like points), or
-- nil and a message
function polygon.polygonConvexParts(points, holes)
  local tris, message = triangulate("polygonConvexParts", points, holes)
  if not tris then releaseNodes(); return nil, message end
  -- corners: three per triangle, linked around their part; a part is the triangles joined so far
  local cornerCount = #tris
  local node, nextCorner = newArray(cornerCount), newArray(cornerCount)
  local prevCorner, part = newArray(cornerCount), newArray(cornerCount)
  local joins = newArray(cornerCount)
  local idLimit = 0
  for k = 1, nodeCount do idLimit = max(idLimit, origin[k]) end
  idLimit = idLimit + 1
  for c = 1, #tris do
    local first = c - (c - 1) % 3
    node[c], part[c] = tris[c], first   -- part: a corner's union-find link, the first of a triangle
    nextCorner[c] = c % 3 == 0 and first or c + 1
    prevCorner[c] = c == first and first + 2 or c - 1
  end
  -- edges meet by the input vertices they join, so a bridge is an edge like any other: each
  -- corner's edge u -> v waits in a list kept at the lower of u and v (a few corners) until the
  -- edge v -> u comes; a later u -> v takes the place of one waiting. (A hash table keyed by
  -- the pair took a quarter of the time at 10,000 vertices, and grew by rehashing.)
  local waitingAt, nextWaiting = newArray(idLimit), newArray(cornerCount)
  for c = 1, #tris do
    local u, v = origin[node[c]], origin[node[nextCorner[c]]]
    local low = min(u, v)
    local before, other = nil, waitingAt[low]
    while other and (origin[node[other]] ~= v or origin[node[nextCorner[other]]] ~= u) do
      before, other = other, nextWaiting[other]
    end
    if other then   -- v -> u was waiting: join, and take it off the list
      joins[#joins + 1] = other; joins[#joins + 1] = c
      if before then nextWaiting[before] = nextWaiting[other] else waitingAt[low] = nextWaiting[other] end
    else
      before, other = nil, waitingAt[low]
      while other and (origin[node[other]] ~= u or origin[node[nextCorner[other]]] ~= v) do
        before, other = other, nextWaiting[other]
      end
      if other then   -- u -> v already waiting: c waits in its place
        nextWaiting[c] = nextWaiting[other]
        if before then nextWaiting[before] = c else waitingAt[low] = c end
      else
        nextWaiting[c], waitingAt[low] = waitingAt[low], c
      end
    end
  end
  -- a dropped corner's outgoing edge now starts at heir[corner]
  local heir = newArray(cornerCount)
  for j = 1, #joins, 2 do
    local pu, qv = joins[j], joins[j + 1]
    while heir[pu] do pu = heir[pu] end
    while heir[qv] do qv = heir[qv] end
    local pv, qu = nextCorner[pu], nextCorner[qv]
    -- the parts' roots (union-find with path halving)
    local rp, rq = pu, qv
    while part[rp] ~= rp do part[rp] = part[part[rp]]; rp = part[rp] end
    while part[rq] ~= rq do part[rq] = part[part[rq]]; rq = part[rq] end
    if rp ~= rq and origin[node[pv]] == origin[node[qv]] and origin[node[qu]] == origin[node[pu]]
      and orient(node[prevCorner[pu]], node[pu], node[nextCorner[qu]]) >= 0
      and orient(node[prevCorner[qv]], node[pv], node[nextCorner[pv]]) >= 0 then
      local un, vp = nextCorner[qu], prevCorner[qv]
      nextCorner[pu], prevCorner[un] = un, pu
      prevCorner[pv], nextCorner[vp] = vp, pv
      heir[qu], heir[qv] = pu, pu
      part[rq] = rp
    end
  end
  local out, seen = {}, newArray(cornerCount)   -- seen: filled out of order, so made at size
  for c = 1, #tris do
    if not heir[c] and not seen[c] then
      local poly, k = {}, c
      repeat
        seen[k] = true
        poly[#poly + 1] = inX[node[k]]; poly[#poly + 1] = inY[node[k]]
        k = nextCorner[k]
      until k == c
      out[#out + 1] = poly
    end
  end
  releaseNodes()
  return out
end

end
--------------------------------------------------------------------------------------------------
-- Compound shapes: lists of convex parts
--------------------------------------------------------------------------------------------------
do   -- this section's helpers are local to it
-- polygonsCollide, polygonsCollideV and polygonCircleCollideV also take, for either shape, a list
-- of convex parts {part1, part2, ...}: what polygonConvexParts returns, or parts built by hand.
-- A flat array holds a number at [1], a list of parts a table.
--
-- Overlap. Two shapes overlap when some part of one overlaps some part of the other, each pair
-- decided exactly (touching is not colliding) after a bounding-box test per pair.
--
-- The push. Moving the second shape by t makes part A of the first and part B of the second
-- overlap exactly when t lies inside D = A - B = {a - b}, a convex polygon with one edge per edge
-- of A and of B. An edge of A from vertex a, with outward unit normal u, bounds D by the open
-- half-plane u.t < c, c = -min over the vertices v of B of u.(v - a) (how far B reaches past the
-- edge); an edge of B from b, outward normal u, by -u.t < c, c = -min over the vertices w of A
-- of u.(w - b). The least push is the point nearest the origin that lies in no open D (over all
-- pairs of parts). That point is on the boundary of the union of the D, so on an edge of one D:
-- inside that edge it is the foot of the perpendicular from the origin to the edge's line, else
-- it is the end of a piece of the edge, where the edge's line crosses another (of the same D, a
-- corner, or of another D, where two D cross). So the candidates are the feet and the crossings,
-- and the push is the nearest candidate outside every D: the true least translation, up to the
-- margin below. Feet need not be tried on an edge shared with another part of the same shape
-- (internal, see preparedParts): such a foot, if on the edge, has the neighbouring part
-- overlapping (the other part reaches on past the shared edge, as a half-disc around every point
-- inside it) and so is never free; off the edge it is on another line, found there. Crossings use
-- every line, as an end of an internal edge can be a corner of the union.
--
-- Which pairs. D lies in the box [A's box - B's box]. The pairs whose boxes overlap (D holds the
-- origin) come first. The nearest point t free among them is the least push of all when it lies
-- outside every other D too, as more pairs can only take free points away; so a pair is added
-- only when its box of D comes within 4 delta of t on every side, and the nearest free point
-- is sought again, round after round. Against a flat shape only the parts in a window around
-- it are visited for that while |t| is at most half the window: the others' boxes of D lie
-- farther than a window from the origin.
--
-- Which feet and crossings. The feet are tried nearest first (the nearest and the second
-- nearest are kept as the faces are made), as the nearest free foot is the first free one in
-- the order of reach, then of faces; a crossing is no nearer than either of its lines, so
-- crossings are sought only among the lines nearer than the best so far, and not at all when
-- only one can be (every outer edge's line at least as far as the best, and every internal
-- one). So on a floor the push usually costs the faces of the pairs and one or two freeness
-- checks.
--
-- Rectangles. Every D of two axis-parallel rectangles is a box: a flat one against a list of
-- them (a crate on tiles) takes boxPush, this search on the boxes' lines without faces; and such
-- a pair is free at t when the moved rectangle, rounded as a game moves it, does not overlap the
-- other, tested exactly (pushFree), so a push may leave them touching (an exact fit in a slot).
--
-- Margin: one push separates. The faces are computed in floating point and the moved vertices
-- are rounded, so a candidate must lie outside every D widened by delta, and feet and crossings
-- are taken on the lines moved out by lift = 1.25 delta (a quarter of delta covers their own
-- rounding, a few eps E). With E the width plus the height of the box around both shapes and S
-- their largest coordinate magnitude, every D lies in the box of D's, within 1.5 E of the origin,
-- so every |v - a| <= E, every push |t| < 1.5 E (a point farther out is free), and the moved
-- coordinates stay below S + 1.5 E. Errors of the quantities the test u.t >= c + delta compares,
-- in eps: the unit normal from rounded differences (eps each, then unit's 3) turns by at most
-- 5 eps, moving u.(v - a) by 5 E and u.t by 7.5 E; the projection rounds by 3 E; the test's own
-- sums and products by 3 (1.5 E + E) = 7.5 E: 23 E in all, below 64 E, so a candidate found
-- outside the widened D is in truth at distance 41 eps E or more from D: part B moved by it
-- exactly keeps that distance from A. Rounding moves each of its coordinates by at most
-- eps (S + 1.5 E), each vertex by 1.42 eps (S + 1.5 E), so the rounded part (the hull of the
-- rounded vertices) lies within that of the exact one: still apart when 41 eps E + 2 eps S, the
-- rest of delta = 64 eps E + 2 eps S, exceeds 1.42 eps (S + 1.5 E). So no pair of parts collides
-- after the rounded move: one push separates. The push exceeds the least translation by about
-- lift (80 eps E + 2.5 eps S) on a face, lift / sin(angle / 2) at a crossing of lines meeting at
-- an angle. Coordinates beyond 2^500 or below 2^-400 are scaled by a power of two k first
-- (exact), so no product overflows or underflows.

-- Whether shape is a list of parts rather than a flat array of coordinates (declared before the
-- public collision functions, which dispatch on it).
function isParts(shape)
  return type(shape) == "table" and type(shape[1]) == "table"
end

-- The preparation each list of parts gets on first use, kept while the list lives (weak keys):
-- per part a copy of its coordinates, its bounding box, its area sign and its outward unit edge
-- normals, and which of its edges are internal: internal[k][i] is 1 when the edge of part k
-- ending at vertex index i (odd; from the vertex before, the last for the first) is covered by
-- edges of other parts running the opposite way along the same line (shared with the
-- neighbours, whole or in pieces), else 0 (numbers, not true and nil: on LuaJIT a load whose
-- type varies is a side exit).
-- Keeping it right. Reading every coordinate on every call costs as much as the pair tests a
-- call needs, so each call checks, per part, only its table, its length and the four
-- coordinates on its box (the vertices that gave xmin, ymin, xmax, ymax). That is exact for a
-- move (polygonTranslate in place, or p[i] = p[i] + dx on every coordinate, rounded): rounding
-- is monotonic, so if the coordinates on the box did not change, no moved coordinate left the
-- box, and the box is right. A part whose box is used (it overlaps the other shape's) is
-- compared with its whole copy too, so its sign and normals are always those of its present
-- coordinates. What is not seen: an edit other than a move that leaves the coordinates on a
-- part's box as they were and takes another vertex beyond it (give the part a new table then).
-- A changed part gets its copy, box, sign and normals again, in place, without allocating; a
-- change in the number of parts or of a part's coordinates prepares the list again
-- (allocates). The internal edges are kept when coordinates change: moving a shape keeps them
-- right, and after other edits a stale table costs at most a longer push (a foot skipped) or
-- some time (a foot tried), never a wrong one, as every candidate is checked against every part.
local preparedParts = setmetatable({}, { __mode = "k" })

-- The interval an edge covers along its line: on x unless the line is vertical (exact).
local function edgeSpan(ax, ay, bx, by, onX)
  if onX then return min(ax, bx), max(ax, bx) end
  return min(ay, by), max(ay, by)
end

-- Whether the spans in `covers` (pairs lo, hi, any order) cover [lo, hi].
local function covered(covers, lo, hi)
  table.sort(covers, function(p, q) return p[1] < q[1] end)
  local reach = lo
  for _, span in ipairs(covers) do
    if span[1] > reach then return false end
    if span[2] > reach then reach = span[2] end
    if reach >= hi then return true end
  end
  return reach >= hi
end

-- A view of a shape is what the collisions read of it: count, lengths[k], boxes (xmin, ymin,
-- xmax, ymax of part k at 4k - 3 .. 4k), turns[k] (area sign 1, -1 or 0: signs, never
-- magnitudes, are multiplied), normals[k] (the outward unit normal of the edge ending at vertex
-- index i at [i], [i + 1]), internal[k], rects[k] (rectKind's 0, 1 or 2) and sides[k] (a
-- rectangle's sides, rectSides), and over all parts size (the largest coordinate magnitude)
-- and the box left, top, right, bottom. A list's preparation is its view, with
-- records[k] for the per-call checks: xmin, ymin, xmax, ymax of part k at [1] .. [4] again, the
-- indices of the coordinates that gave them at [5] .. [8], the part's table at [9] (false after
-- a non-finite coordinate) and its length at [10] (constant indices: one instruction each on
-- PUC Lua, in the loop over every part). A flat array is seen through one of two scratch views,
-- filled on every call.

-- 1 when points[1 .. n] is a rectangle with axis-parallel sides whose edge into vertex 1 is
-- vertical, 2 when that edge is horizontal, else 0, as the coordinates' floats give it (its
-- box xmin < xmax, ymin < ymax: no side has length 0). Such a part's faces take no projection
-- (pairFaces).
local function rectKind(points, n, xmin, ymin, xmax, ymax)
  if n ~= 8 or not (xmin < xmax and ymin < ymax) then return 0 end
  local x1, y1, x2, y2 = points[1] + 0.0, points[2] + 0.0, points[3] + 0.0, points[4] + 0.0
  local x3, y3, x4, y4 = points[5] + 0.0, points[6] + 0.0, points[7] + 0.0, points[8] + 0.0
  if x4 == x1 and y1 == y2 and x2 == x3 and y3 == y4 then return 1 end
  if y4 == y1 and x1 == x2 and y2 == y3 and x3 == x4 then return 2 end
  return 0
end

-- The sides of a rectangle of kind rect (rectKind; xmin, ymin its box's), numbered left 1, top
-- 2, right 3, bottom 4 (outward normals (-1, 0), (0, -1), (1, 0), (0, 1)): at odd index i the
-- side of the edge into vertex index i, at i + 1 the opposite side. Its edges alternate between
-- vertical and horizontal sides (a vertical one first for rect 1), the first vertical one at
-- v1's x, the first horizontal one at v1's y, then their opposites. Eight orders in all, made
-- once here and shared (read only): RECT_SIDES[4 (rect - 1) + 2 (v1 on the right) + (v1 at
-- the bottom) + 1]. A view's sides[k] is one of them (a flat rectangle's is picked per call, by
-- PUC Lua's flatBox without a call).
local RECT_SIDES = {}
for pattern = 1, 8 do
  local rect, right, bottom = pattern <= 4 and 1 or 2, (pattern - 1) % 4 >= 2, (pattern - 1) % 2 == 1
  local vertical, horizontal = right and 3 or 1, bottom and 4 or 2
  local first, second = horizontal, vertical
  if rect == 1 then first, second = vertical, horizontal end
  local third, fourth = (first + 1) % 4 + 1, (second + 1) % 4 + 1
  RECT_SIDES[pattern] = { first, third, second, fourth, third, first, fourth, second }
end

local function rectSides(points, rect, xmin, ymin)
  local pattern = 4 * (rect - 1) + 1
  if points[1] + 0.0 ~= xmin then pattern = pattern + 2 end
  if points[2] + 0.0 ~= ymin then pattern = pattern + 1 end
  return RECT_SIDES[pattern]
end

-- The box of part k (n coordinates) of a list into view.boxes and its record; false when a
-- coordinate is inf or NaN.
local function partBox(view, k, part, n)
  local finite = 0.0
  local xmin, ymin, xmax, ymax = huge, huge, -huge, -huge
  local ixmin, iymin, ixmax, iymax = 1, 2, 1, 2
  for i = 1, n - 1, 2 do
    local x, y = part[i] + 0.0, part[i + 1] + 0.0
    finite = finite + (x * 0 + y * 0)   -- stays 0 unless a coordinate is inf or NaN
    if x < xmin then xmin, ixmin = x, i end
    if x > xmax then xmax, ixmax = x, i end
    if y < ymin then ymin, iymin = y, i + 1 end
    if y > ymax then ymax, iymax = y, i + 1 end
  end
  if n < 6 then xmin, xmax = huge, -huge end   -- fewer than 3 points: never collides
  local boxes, record, b = view.boxes, view.records[k], 4 * k
  boxes[b - 3], boxes[b - 2], boxes[b - 1], boxes[b] = xmin, ymin, xmax, ymax
  record[1], record[2], record[3], record[4] = xmin, ymin, xmax, ymax
  record[5], record[6], record[7], record[8] = ixmin, iymin, ixmax, iymax
  local rect = finite == 0 and rectKind(part, n, xmin, ymin, xmax, ymax) or 0
  view.rects[k] = rect
  record[11] = rect
  if rect ~= 0 then
    view.sides[k] = rectSides(part, rect, xmin, ymin)
    -- A rectangle's first and third vertices are opposite corners: their coordinates are the
    -- four on its box, the ones watched (at constant indices on LuaJIT: see partsOverlapping)
    local x1, y1 = part[1] + 0.0, part[2] + 0.0
    ixmin, iymin = x1 == xmin and 1 or 5, y1 == ymin and 2 or 6
    record[5], record[6], record[7], record[8] = ixmin, iymin, 6 - ixmin, 8 - iymin
    record[12], record[13], record[14], record[15] = x1, y1, part[5] + 0.0, part[6] + 0.0
  end
  -- PUC Lua's scan: 0 for a rectangle whose first vertex is its (xmin, ymin), and so its third
  -- its (xmax, ymax) (a box as games write it), compared with the box's values it loads anyway
  -- (see partsOverlapping); else the length
  record[16] = rect ~= 0 and ixmin == 1 and iymin == 2 and 0 or n
  return finite == 0
end

-- The area sign of part k (finite coordinates) into view, and returned.
local function partTurn(view, k, part, n)
  local turn = 0.0
  if n >= 6 then
    local sign = areaSign(part, n)
    turn = sign > 0 and 1.0 or sign < 0 and -1.0 or 0.0
  end
  view.turns[k] = turn
  return turn
end

-- The area sign and the edge normals of part k (finite coordinates) into view: unit's numbers.
-- On PUC Lua without its calls (PUC Lua pays for each, math.max and abs too), one assignment
-- per statement (Lua 5.4 moves a multiple assignment through a temporary per value).
local partNormals
if JIT then
  partNormals = function(view, k, part, n)
    local turn = partTurn(view, k, part, n)
    if turn == 0 then return end   -- never collides: no normal is read
    local normals = view.normals[k]
    local ax, ay = part[n - 1] + 0.0, part[n] + 0.0
    for i = 1, n - 1, 2 do
      local bx, by = part[i] + 0.0, part[i + 1] + 0.0
      local ux, uy = 0.0, 0.0   -- a repeated vertex gives no edge
      if bx ~= ax or by ~= ay then ux, uy = unit((by - ay) * turn, (ax - bx) * turn) end
      normals[i], normals[i + 1] = ux, uy
      ax, ay = bx, by
    end
  end
else
  partNormals = function(view, k, part, n)
    local turn = partTurn(view, k, part, n)
    if turn == 0 then return end   -- never collides: no normal is read
    local normals = view.normals[k]
    local ax, ay = part[n - 1] + 0.0, part[n] + 0.0
    for i = 1, n - 1, 2 do
      local bx, by = part[i] + 0.0, part[i + 1] + 0.0
      local ux = (by - ay) * turn
      local uy = (ax - bx) * turn
      if uy == 0 and ux ~= 0 then
        -- a vertical edge (a tile's, a box's): what the lines below give, (+-1, uy), uy a
        -- zero of turn's sign, without their division and square root
        normals[i] = ux > 0 and 1.0 or -1.0
        normals[i + 1] = uy
      elseif ux == 0 and uy ~= 0 then   -- a horizontal one
        normals[i] = ux
        normals[i + 1] = uy > 0 and 1.0 or -1.0
      elseif bx ~= ax or by ~= ay then
        local m = uy   -- max(|uy|, |ux|)
        if m < 0 then m = -m end
        local mx = ux
        if mx < 0 then mx = -mx end
        if mx > m then m = mx end
        ux = ux / m
        uy = uy / m
        local len = sqrt(ux * ux + uy * uy)
        normals[i] = ux / len
        normals[i + 1] = uy / len
      else   -- a repeated vertex gives no edge
        normals[i] = 0.0
        normals[i + 1] = 0.0
      end
      ax = bx
      ay = by
    end
  end
end

-- The box around all parts of view and their largest coordinate magnitude, into view.
local function shapeBox(view)
  local magnitude, left, top, right, bottom = 0.0, huge, huge, -huge, -huge
  local boxes = view.boxes
  for b = 4, 4 * view.count, 4 do
    local xmin, ymin, xmax, ymax = boxes[b - 3], boxes[b - 2], boxes[b - 1], boxes[b]
    if xmin <= xmax then   -- parts of fewer than 3 points have none
      magnitude = max(magnitude, -xmin, xmax, -ymin, ymax)
      left, top, right, bottom = min(left, xmin), min(top, ymin), max(right, xmax), max(bottom, ymax)
    end
  end
  view.magnitude, view.left, view.top, view.right, view.bottom = magnitude, left, top, right, bottom
end

-- Builds the preparation of a list of parts, whose parts were checked to be tables of even
-- length (allocates: on first use, or after the number of parts or coordinates changed). A
-- non-finite coordinate raises the argument error at the caller of the public function.
local function prepareParts(fname, argname, parts)
  local count = #parts
  local info = { count = count, lengths = {}, internal = {}, copies = {}, boxes = {}, turns = {},
                 normals = {}, records = {}, checked = {}, rects = {}, sides = {} }
  for k = 1, count do
    local part = parts[k]
    local n = #part
    local copy = {}
    for i = 1, n do copy[i] = part[i] end
    local flags = {}
    for i = 1, n - 1, 2 do flags[i] = 0 end
    info.lengths[k], info.internal[k], info.copies[k], info.normals[k] = n, flags, copy, {}
    info.records[k], info.checked[k] = { 0, 0, 0, 0, 1, 2, 1, 2, part, n, 0, 0, 0, 0, 0, n }, 0
    if not partBox(info, k, part, n) then
      error(("%s: %s holds a non-finite coordinate"):format(fname, argname), 5)
    end
    partNormals(info, k, part, n)
  end
  shapeBox(info)
  local edges = {}
  for k = 1, count do
    local part = parts[k]
    local n = #part
    for e = 1, n / 2 do
      local j = e % (n / 2) + 1
      local ax, ay = part[2 * e - 1] + 0.0, part[2 * e] + 0.0
      local bx, by = part[2 * j - 1] + 0.0, part[2 * j] + 0.0
      if ax ~= bx or ay ~= by then
        edges[#edges + 1] = { k = k, e = e, ax = ax, ay = ay, bx = bx, by = by,
                              xmin = min(ax, bx), xmax = max(ax, bx), covers = {} }
      end
    end
  end
  -- sweep over the edges in order of their smallest x: only edges whose x ranges meet can share
  table.sort(edges, function(p, q) return p.xmin < q.xmin end)
  for s = 1, #edges do
    local E = edges[s]
    local t = s + 1
    while edges[t] and edges[t].xmin <= E.xmax do
      local T = edges[t]
      if T.k ~= E.k and cross(E.ax, E.ay, E.bx, E.by, E.ax, E.ay, T.ax, T.ay) == 0
        and cross(E.ax, E.ay, E.bx, E.by, E.ax, E.ay, T.bx, T.by) == 0 then
        local onX = E.ax ~= E.bx   -- then T, on the same line, is not vertical either
        local forwardE = onX and E.bx > E.ax or not onX and E.by > E.ay
        local forwardT = onX and T.bx > T.ax or not onX and T.by > T.ay
        if forwardE ~= forwardT then
          local elo, ehi = edgeSpan(E.ax, E.ay, E.bx, E.by, onX)
          local tlo, thi = edgeSpan(T.ax, T.ay, T.bx, T.by, onX)
          if tlo < ehi and elo < thi then
            E.covers[#E.covers + 1] = { tlo, thi }
            T.covers[#T.covers + 1] = { elo, ehi }
          end
        end
      end
      t = t + 1
    end
  end
  for _, E in ipairs(edges) do
    if #E.covers > 0 then
      local onX = E.ax ~= E.bx
      local lo, hi = edgeSpan(E.ax, E.ay, E.bx, E.by, onX)
      if covered(E.covers, lo, hi) then   -- the edge ends at vertex e % (n / 2) + 1
        local n = info.lengths[E.k]
        info.internal[E.k][2 * (E.e % (n / 2)) + 1] = 1
      end
    end
  end
  preparedParts[parts] = info
  return info
end

-- Checks that every part of a list is a table of even length: the argument errors, raised at
-- the caller of the public function (level 5: it is called by listView).
local function checkList(fname, argname, shape)
  for k = 1, #shape do
    local part = shape[k]
    if type(part) ~= "table" then
      error(("%s: %s[%d] must be a table, got %s"):format(fname, argname, k, type(part)), 5)
    end
    if #part % 2 ~= 0 then
      error(("%s: %s[%d] must hold an even number of coordinates, got %d")
        :format(fname, argname, k, #part), 5)
    end
  end
end

local callStamp = 0   -- counts the calls that push: checked[k] == callStamp when compared

-- Brings part k of a prepared list up to date from its present coordinates, in place. Raises the
-- non-finite error at `level` (counted from here, 1).
local function refreshPart(view, k, part, n, level)
  if not partBox(view, k, part, n) then
    view.records[k][9] = false   -- the next call refreshes the part again, and raises again
    error(("%s: %s holds a non-finite coordinate"):format(view.fname, view.argname), level)
  end
  partNormals(view, k, part, n)
  local copy = view.copies[k]
  for i = 1, n do copy[i] = part[i] end
end

-- Compares part k of a prepared list with its whole copy, once per call, before its sign and
-- normals are read (see preparedParts); level as in refreshPart, counted from here.
local function checkCopy(view, k, part, level)
  view.checked[k] = callStamp
  local copy, n = view.copies[k], view.lengths[k]
  if view.rects[k] ~= 0 then
    -- An axis-parallel rectangle: its first and third vertices are the coordinates watched on
    -- its box (partBox), which every call compares before it reads a part (partsOverlapping,
    -- listView): equal to their copies. The other two vertices are compared here.
    if part[3] == copy[3] and part[4] == copy[4] and part[7] == copy[7] and part[8] == copy[8] then
      return
    end
    refreshPart(view, k, part, n, level + 1)
    return
  end
  if n == 8 then   -- a quadrilateral (a tile, a box) unrolled: constant indices, no loop steps
    if part[1] == copy[1] and part[2] == copy[2] and part[3] == copy[3] and part[4] == copy[4]
        and part[5] == copy[5] and part[6] == copy[6] and part[7] == copy[7] and part[8] == copy[8] then
      return
    end
    refreshPart(view, k, part, n, level + 1)
    return
  end
  for i = 1, n do
    if part[i] ~= copy[i] then
      refreshPart(view, k, part, n, level + 1)
      return
    end
  end
end

-- The view of a list of parts: its preparation, brought up to date (see preparedParts). Raises
-- the argument errors at the caller of the public function (level 4).
local function listView(fname, argname, shape)
  local info = preparedParts[shape]
  if info and info.count == #shape then
    info.fname, info.argname = fname, argname
    local records = info.records
    local changed = false
    for k = 1, info.count do
      local part, record = shape[k], records[k]
      local n = record[10]
      if part ~= record[9] then   -- another table, or a non-finite coordinate before (false)
        if type(part) ~= "table" or #part ~= n then
          changed = nil   -- prepare again (or raise the error)
          break
        end
        record[9], changed = part, true
        refreshPart(info, k, part, n, 5)
      elseif #part ~= n then   -- another length
        changed = nil
        break
      elseif n >= 6 and (part[record[5]] ~= record[1] or part[record[6]] ~= record[2]
          or part[record[7]] ~= record[3] or part[record[8]] ~= record[4]) then
        changed = true
        refreshPart(info, k, part, n, 5)
      end
    end
    if changed ~= nil then
      if changed then shapeBox(info) end
      return info
    end
  end
  checkList(fname, argname, shape)
  info = prepareParts(fname, argname, shape)
  info.fname, info.argname = fname, argname
  return info
end

-- The two views of flat arrays (one per argument), refilled on every call. `pending`: the area
-- sign and normals are still to compute (only a push on overlapping boxes needs them);
-- `turnPending`: the area sign is (a boolean on overlapping boxes needs only that). No edge
-- of a flat array is internal: internal[1] holds 0 at vertex indices 1 .. edgeRoom, grown when a
-- larger array comes (once, never shrunk).
local function newFlatView()
  return { count = 1, lengths = {}, internal = { {} }, edgeRoom = 0, boxes = {},
           turns = {}, normals = { {} }, rects = { 0 }, sides = { {} }, pending = false,
           turnPending = false }
end
local flatView1, flatView2 = newFlatView(), newFlatView()

-- The box of a flat array (n coordinates) into view as part k = 1, as partBox gives it but
-- without the record (the extremes' indices, which only a list's parts keep), and whether every
-- coordinate is finite. On LuaJIT min and max four vertices a round, the last round padded with
-- the last vertex (as leastProjection, for the same reason: partBox's branches on every vertex
-- were 9 % of a push's time on the crate and floor of bench/compound.lua by `luajit -jp=f`).
-- On PUC Lua partBox's loop, and shapeBox's numbers for the one part without its calls.
local flatBox
if JIT then
  flatBox = function(view, _, shape, n)
    local finite = 0.0
    local xmin, ymin, xmax, ymax = huge, huge, -huge, -huge
    local last = n - 1
    for i = 1, last, 8 do
      local i2, i3, i4 = min(i + 2, last), min(i + 4, last), min(i + 6, last)
      local x1, y1, x2, y2 = shape[i] + 0.0, shape[i + 1] + 0.0, shape[i2] + 0.0, shape[i2 + 1] + 0.0
      local x3, y3, x4, y4 = shape[i3] + 0.0, shape[i3 + 1] + 0.0, shape[i4] + 0.0, shape[i4 + 1] + 0.0
      -- stays 0 unless a coordinate is inf or NaN
      finite = finite + ((x1 * 0 + y1 * 0) + (x2 * 0 + y2 * 0) + (x3 * 0 + y3 * 0) + (x4 * 0 + y4 * 0))
      xmin, xmax = min(xmin, x1, x2, x3, x4), max(xmax, x1, x2, x3, x4)
      ymin, ymax = min(ymin, y1, y2, y3, y4), max(ymax, y1, y2, y3, y4)
    end
    if n < 6 then xmin, xmax = huge, -huge end   -- fewer than 3 points: never collides
    local boxes = view.boxes
    boxes[1], boxes[2], boxes[3], boxes[4] = xmin, ymin, xmax, ymax
    -- an axis-parallel rectangle: its sides and its area sign (see PUC Lua's flatBox)
    local rect = finite == 0 and rectKind(shape, n, xmin, ymin, xmax, ymax) or 0
    view.rects[1] = rect
    if rect ~= 0 then
      view.sides[1] = rectSides(shape, rect, xmin, ymin)
      local x1, y1 = shape[1] + 0.0, shape[2] + 0.0
      if rect == 1 then
        view.turns[1] = (shape[3] + 0.0 > x1) == (shape[6] + 0.0 > y1) and 1.0 or -1.0
      else
        view.turns[1] = (shape[5] + 0.0 > x1) == (shape[4] + 0.0 > y1) and -1.0 or 1.0
      end
    end
    return finite == 0
  end
else
  flatBox = function(view, _, shape, n)
    local finite, rect = 0.0, 0
    local xmin, ymin, xmax, ymax
    if n == 8 then
      -- A quadrilateral (a crate, a tile) unrolled: the loop's numbers (the least of equals is
      -- the first, as there), and whether it is an axis-parallel rectangle, what rectKind and
      -- rectSides give, from the same locals. An axis-parallel rectangle first: its x are v1's
      -- and the opposite corner's (each equal to one of them, NaN never is), its y too, so two
      -- comparisons give its box, and it is finite when its box is; the other shapes (and a
      -- rectangle of no width or height, or with an infinite side) by eight coordinates' sums
      -- and twelve comparisons (flatBox took 81 VM instructions for the crate of
      -- bench/compound.lua, 118 with those first). Its area sign from comparisons: twice its
      -- area is 2 (x2 - x1) (y3 - y1) for kind 1, -2 (x3 - x1) (y2 - y1) for kind 2, each
      -- factor's sign flipped when the opposite corner lies left of or above v1 (flatView then
      -- computes no area sign).
      local x1, y1, x2, y2 = shape[1] + 0.0, shape[2] + 0.0, shape[3] + 0.0, shape[4] + 0.0
      local x3, y3, x4, y4 = shape[5] + 0.0, shape[6] + 0.0, shape[7] + 0.0, shape[8] + 0.0
      if x4 == x1 and y1 == y2 and x2 == x3 and y3 == y4 then
        rect = 1
      elseif y4 == y1 and x1 == x2 and y2 == y3 and x3 == x4 then
        rect = 2
      end
      if rect ~= 0 then
        local xa, ya, turn = x2, y3, 1.0   -- the corner opposite v1
        if rect == 2 then
          xa = x3
          ya = y2
          turn = -1.0
        end
        local pattern = 4 * rect - 3   -- as rectSides
        xmin = x1
        xmax = xa
        if xa < x1 then
          xmin = xa
          xmax = x1
          pattern = pattern + 2
          turn = -turn
        end
        ymin = y1
        ymax = ya
        if ya < y1 then
          ymin = ya
          ymax = y1
          pattern = pattern + 1
          turn = -turn
        end
        local big = huge
        if xmin < xmax and ymin < ymax and -big < xmin and xmax < big and -big < ymin and ymax < big then
          view.turns[1] = turn
          view.sides[1] = RECT_SIDES[pattern]
        else
          rect = 0
        end
      end
      if rect == 0 then
        -- 0 unless a coordinate is inf or NaN (x - x is NaN then)
        finite = (x1 - x1) + (y1 - y1) + (x2 - x2) + (y2 - y2) + (x3 - x3) + (y3 - y3)
          + (x4 - x4) + (y4 - y4)
        xmin = x1
        xmax = x1
        if x2 < xmin then xmin = x2 end
        if x2 > xmax then xmax = x2 end
        if x3 < xmin then xmin = x3 end
        if x3 > xmax then xmax = x3 end
        if x4 < xmin then xmin = x4 end
        if x4 > xmax then xmax = x4 end
        ymin = y1
        ymax = y1
        if y2 < ymin then ymin = y2 end
        if y2 > ymax then ymax = y2 end
        if y3 < ymin then ymin = y3 end
        if y3 > ymax then ymax = y3 end
        if y4 < ymin then ymin = y4 end
        if y4 > ymax then ymax = y4 end
      end
    else
      xmin, ymin, xmax, ymax = huge, huge, -huge, -huge
      for i = 1, n - 1, 2 do
        local x, y = shape[i] + 0.0, shape[i + 1] + 0.0
        finite = finite + (x * 0 + y * 0)   -- stays 0 unless a coordinate is inf or NaN
        if x < xmin then xmin = x end
        if x > xmax then xmax = x end
        if y < ymin then ymin = y end
        if y > ymax then ymax = y end
      end
      if n < 6 then xmin, xmax = huge, -huge end   -- fewer than 3 points: never collides
    end
    view.rects[1] = rect
    local boxes = view.boxes   -- one assignment per statement: see partNormals
    boxes[1] = xmin
    boxes[2] = ymin
    boxes[3] = xmax
    boxes[4] = ymax
    local magnitude = 0.0
    if xmin <= xmax then   -- as shapeBox: max(0, -xmin, xmax, -ymin, ymax), the first of equals
      if -xmin > magnitude then magnitude = -xmin end
      if xmax > magnitude then magnitude = xmax end
      if -ymin > magnitude then magnitude = -ymin end
      if ymax > magnitude then magnitude = ymax end
    else
      xmin, ymin, xmax, ymax = huge, huge, -huge, -huge
    end
    view.magnitude = magnitude
    view.left = xmin
    view.top = ymin
    view.right = xmax
    view.bottom = ymax
    return finite == 0
  end
end

-- Fills `view` for the flat array shape and returns it; or nil and the argument error's message
-- (the caller raises it: after a list's errors, when the list is the first argument).
local function flatView(fname, argname, shape, view)
  if type(shape) ~= "table" then
    return nil, ("%s: %s must be a table, got %s"):format(fname, argname, type(shape))
  end
  local n = #shape
  if n % 2 ~= 0 then
    return nil, ("%s: %s must hold an even number of coordinates, got %d"):format(fname, argname, n)
  end
  if not flatBox(view, 1, shape, n) then
    return nil, ("%s: %s holds a non-finite coordinate"):format(fname, argname)
  end
  if n > view.edgeRoom then
    local flags = view.internal[1]
    for i = view.edgeRoom + 1, n do flags[i] = 0 end
    view.edgeRoom = n
  end
  view.lengths[1], view.pending, view.turnPending = n, true, view.rects[1] == 0
  if JIT then shapeBox(view) end   -- PUC Lua: flatBox did
  return view
end

-- Scratch space reused by every call (grown once, never shrunk): no garbage per frame.
local faceX, faceY, faceC = {}, {}, {}   -- the half-planes faceX tx + faceY ty < faceC
local faceSeam = {}                -- 1 for a face from an internal edge (no foot on it), else 0
local faceReach = {}               -- |faceC + lift|: how near the origin the face's lifted line passes
local faceFirst = {}               -- pair p owns faces faceFirst[p] .. faceFirst[p + 1] - 1
local pairAdded = {}               -- per pair of parts i, j (at (i - 1) count2 + j): callStamp once in
local pairPart1, pairPart2 = {}, {}   -- pair p's parts i and j (LuaJIT: see pairsOverlap)
-- pairBox[p] is 1 when pair p is two axis-parallel rectangles (rectPairFaces, boxPush), else 0;
-- then pairRects holds their boxes at 8p - 7 .. 8p: xmin, ymin, xmax, ymax of the first shape's
-- part, then of the second's, the one a push moves (pushFree)
local pairBox, pairRects = {}, {}

-- Whether two convex parts overlap (exact), by the SAT engine. A non-finite coordinate the
-- checks of the views did not see (one off the box of a list's part) raises the argument error
-- at the caller of the public function (level 4).
local function overlapsConvex(fname, p1, p2)
  local depth, argname = convexPenetration(p1, #p1, p2, #p2, true)
  if depth == nil then error(("%s: %s holds a non-finite coordinate"):format(fname, argname), 4) end
  return depth ~= false
end

-- The same number as minProjection: the least projection nx (vx - ax) + ny (vy - ay) over the
-- vertices of points. On LuaJIT four vertices a round, the last round padded with the last
-- vertex (a repeat cannot change the least), so that a part of up to four vertices takes no
-- loop: a loop that never runs twice is compiled into its caller's trace, where minProjection's
-- loop was a trace of its own, entered and left once per edge (22 % of the push's time on the
-- crate and floor of bench/compound.lua by `luajit -jp=f`, 7 % as here). PUC Lua: minProjection.
local leastProjection = minProjection
if JIT then
  leastProjection = function(points, n, ax, ay, nx, ny)
    local lo, last = huge, n - 1
    for i = 1, last, 16 do
      local i2, i3, i4 = min(i + 2, last), min(i + 4, last), min(i + 6, last)
      local i5, i6, i7, i8 = min(i + 8, last), min(i + 10, last), min(i + 12, last), min(i + 14, last)
      lo = min(lo, nx * (points[i] - ax) + ny * (points[i + 1] - ay),
        nx * (points[i2] - ax) + ny * (points[i2 + 1] - ay),
        nx * (points[i3] - ax) + ny * (points[i3 + 1] - ay),
        nx * (points[i4] - ax) + ny * (points[i4 + 1] - ay),
        nx * (points[i5] - ax) + ny * (points[i5 + 1] - ay),
        nx * (points[i6] - ax) + ny * (points[i6 + 1] - ay),
        nx * (points[i7] - ax) + ny * (points[i7 + 1] - ay),
        nx * (points[i8] - ax) + ny * (points[i8 + 1] - ay))
    end
    return lo
  end
end

-- Whether the edge a -> b of a part (turn its area sign, (ux, uy) its outward normal, unit or
-- not) separates the part from `other`, whose least projection on (ux, uy) from a is lo:
-- decided exactly, by cross's sign where projectionTolerance cannot vouch.
local function edgeSeparates(lo, ax, ay, bx, by, turn, ux, uy, other, no, spanX, spanY)
  local tol = projectionTolerance(spanX, spanY, ux, uy)
  return -lo <= tol and (-lo < -tol or not vertexInside(ax, ay, bx, by, ax, ay, turn, other, no))
end

local faceLift = 0.0   -- lift (see nearestFree) of the call under way, for faceReach
-- The faces with the nearest and the second nearest foot so far (first in face order among
-- equals), their reaches, and the nearest reach of an internal edge's face: kept by addFaces.
-- FAR stands for none: finite (keepFeet multiplies it by 0) and beyond every reach (every
-- coordinate is below 2^501, or scaled below 2^165).
local FAR = 2^1000
-- Over the pairs so far, the largest of each pair's least fc + lift (as faceReach has it, before
-- its abs): a point nearer the origin than this less 0.75 margin lies inside that pair's D
-- widened by margin, so pushFree would find it not free (see nearestFree). -FAR for none.
local leastFree = -FAR
local nearestFoot, nearestReach, secondFoot, secondReach, seamReach = 0, FAR, 0, FAR, FAR
-- PUC Lua's rectPairFaces keeps its internal faces' nearest reach apart, by line direction:
-- seamX for the vertical lines (normal (+-1, 0)), seamY for the horizontal ones (see
-- nearestFree); LuaJIT's keepFeet every internal face's whose normal is one of those
local seamX, seamY = FAR, FAR
local feetKept = 0   -- LuaJIT: the faces 1 .. feetKept are in the five above (see keepFeet)

-- Appends to the face arrays, from index top + 1, the half-planes of D that the edges of one
-- part give (normals its outward unit normals; sense 1 for a part of the first shape, -1 for
-- one of the second, whose outward normal points the other way in t), with `other` the part it
-- is paired with, and each face's reach (see nearestFree); keeps the nearest feet's faces.
-- Coordinates are scaled by k (spanX, spanY bound the scaled coordinate differences, for
-- projectionTolerance). Returns the last index used.
-- LuaJIT's (PUC Lua's is pairFaces, below: the same faces), in two loops without a branch that
-- goes both ways (each was a side exit whose side trace LuaJIT could not compile, "NYI: register
-- coalescing too complex", thousands of times in `luajit -jv examples/arena.lua 300 default`):
-- the faces, with the projections by leastProjection, here, and the nearest feet, by keepFeet
-- over all new faces at once when nearestFree needs them (one loop of 4 steps per part was a
-- quarter of the push's time on the crate and floor of bench/compound.lua, `luajit -jp=l`). The
-- face loop runs a constant 8 steps for parts of up to 8 vertices (a repeated vertex, as the last
-- one read again is, adds no face, without a branch): the copies of a loop counting a part's
-- vertices had a side exit for every other part size, and those failed to compile in the arena
-- (`luajit -jv examples/arena.lua 300 default`, NYI aborts in this section, 8 runs each:
-- 0, 0, 272, 803, 4, 102, 520 and 0 before, at most 4 a run after; its frames 6.9-9.3 ms before,
-- 5.3-6.8 after, 3 runs each). Instead
-- of whether some edge separates the parts it returns 1 when none can (then they overlap for
-- sure), else 0: collideParts decides those pairs exactly when it needs to (pairsOverlap).
local addFaces

-- Keeps the nearest feet and the nearest internal faces among faces first .. last, in order, as
-- nearestFoot and the rest describe, and as pairFaces does with branches: here without one
-- (for LuaJIT). Each choice is a factor 0 or 1 (isAbove), and a sum of products by them is
-- exactly the value chosen (every value finite: FAR, not huge). An internal face whose unit
-- normal is (+-1, 0) or (0, +-1) (one component a zero) goes into seamX or seamY, as PUC Lua's
-- rectPairFaces keeps a rectangle pair's, whatever pair it is from: the early end of
-- nearestFree needs only that the lines it counts there be parallel, so that no two of them
-- cross (their det is a zero; a crate at a seam of a floor of boxes: its neighbours'
-- vertical internal faces, which sent four calls in five of bench/compound.lua's pushFloor
-- into the crossing search on LuaJIT: with them apart, 24.4 -> 22.4 simulated branch
-- mispredictions a call, `valgrind --tool=cachegrind --branch-sim=yes`, and the ratio to
-- the pair calls 1.20 -> 1.10, medians over five fixed trace seeds: see bench/NOTES.md).
local function keepFeet(first, last)
  local foot, footReach, foot2, foot2Reach = nearestFoot, nearestReach, secondFoot, secondReach
  local seamLeast, seamLeastX, seamLeastY = seamReach, seamX, seamY
  for f = first, last do
    local d, seam = faceReach[f], faceSeam[f]
    -- an outer face's reach, FAR for an internal one (d + FAR rounds to FAR), which is never
    -- nearer: the reaches kept are the least and the second least of these, by min and max
    -- (the same numbers as choosing them)
    local outerReach = d + seam * FAR
    -- an outer face nearer than the nearest foot, else nearer than the second
    local nearer = isAbove(footReach - outerReach)
    local second = (1 - nearer) * isAbove(foot2Reach - outerReach)
    foot2 = nearer * foot + second * f + (1 - nearer - second) * foot2
    foot2Reach = min(foot2Reach, max(footReach, outerReach))
    foot, footReach = nearer * f + (1 - nearer) * foot, min(footReach, outerReach)
    -- an internal face's reach, FAR for an outer one; apart by direction: 1 for a vertical
    -- line (its normal's y a zero), for a horizontal one
    local seamD = d + (1 - seam) * FAR
    local vertical, horizontal = 1 - isAbove(abs(faceY[f])), 1 - isAbove(abs(faceX[f]))
    seamLeastX = min(seamLeastX, seamD + (1 - vertical) * FAR)
    seamLeastY = min(seamLeastY, seamD + (1 - horizontal) * FAR)
    seamLeast = min(seamLeast, seamD + (vertical + horizontal) * FAR)
  end
  nearestFoot, nearestReach, secondFoot, secondReach = foot, footReach, foot2, foot2Reach
  seamReach, seamX, seamY = seamLeast, seamLeastX, seamLeastY
end

if JIT then
  addFaces = function(edges, ne, normals, other, no, internal, sense, k, spanX, spanY, top)
    local fx, fy, fc, seam, reach = faceX, faceY, faceC, faceSeam, faceReach
    local lift, highest = faceLift, -huge   -- highest: the largest lo
    local ax, ay = edges[ne - 1] + 0.0, edges[ne] + 0.0
    -- up to 8 vertices a constant count, the last vertex again past the last (see faceAndFar)
    local last = ne <= 16 and 15 or ne - 1
    for i = 1, last, 2 do
      local l = min(i, ne - 1)
      local bx, by = edges[l] + 0.0, edges[l + 1] + 0.0
      -- 1 for an edge, 0 for a repeated vertex, which gives none (its normal is (0, 0)): its
      -- face is written past top, and left there
      local edge = isAbove(abs(bx - ax) + abs(by - ay))
      local ux, uy = normals[l], normals[l + 1]
      local lo
      if k ~= 1 then   -- scaled: the same numbers as unscaled where k is 1
        lo = huge
        local kax, kay = ax * k, ay * k
        for j = 1, no - 1, 2 do
          lo = min(lo, ux * (other[j] * k - kax) + uy * (other[j + 1] * k - kay))
        end
      else
        lo = leastProjection(other, no, ax, ay, ux, uy)
      end
      highest = max(highest, lo - (1 - edge) * FAR)
      local slot = top + 1
      fx[slot], fy[slot], fc[slot] = ux * sense, uy * sense, -lo
      seam[slot], reach[slot] = internal[l], abs(lift - lo)
      top = top + edge
      ax, ay = bx, by
    end
    -- projectionTolerance's bound for any unit normal (|ux|, |uy| <= 1; rounding is monotonic):
    -- an edge whose -lo exceeds it cannot separate; 1 when every edge's does (no NaN: a
    -- difference is > 0 exactly when its first term is the larger)
    return top, isAbove(-(16 * EPS * (spanX + spanY)) - highest), highest
  end
end

-- LuaJIT's faces of a pair of which one part is an axis-parallel rectangle (rectKind, unscaled)
-- and the other not: addFaces' faces, the same numbers, each edge's least projection taken from
-- the other part's box x0, y0, x1, y1 instead of its vertices, min(ux (x0 - ax), ux (x1 - ax))
-- + min(uy (y0 - ay), uy (y1 - ay)): four products where leastProjection takes eight. The same
-- number because rounding is monotonic: fl(fl(ux (x - ax)) + fl(uy (y - ay))) is least at the
-- corner whose terms are least, and every corner is a vertex of the other part when it is the
-- rectangle (its vertices are its box's corners), while against a part that is not, the
-- rectangle's own edges have normals (+-1, +-0), whose projection of a vertex is +-(x - ax) (or
-- +-(y - ay)) up to a zero's sign, least at the box's side. (The crate turned 0.5 radian on the
-- floor of bench/compound.lua: addFaces and leastProjection were 39 % of its push by `luajit
-- -jp=f`.) The loop as addFaces' (constant 8 steps up to 8 vertices).
local addBoxFaces
if JIT then
  addBoxFaces = function(edges, ne, normals, x0, y0, x1, y1, internal, sense, spanX, spanY, top)
    local fx, fy, fc, seam, reach = faceX, faceY, faceC, faceSeam, faceReach
    local lift, highest = faceLift, -huge   -- highest: the largest lo
    local ax, ay = edges[ne - 1] + 0.0, edges[ne] + 0.0
    local last = ne <= 8 and 7 or ne <= 16 and 15 or ne - 1
    for i = 1, last, 2 do
      local l = min(i, ne - 1)
      local bx, by = edges[l] + 0.0, edges[l + 1] + 0.0
      local edge = isAbove(abs(bx - ax) + abs(by - ay))   -- as in addFaces
      local ux, uy = normals[l], normals[l + 1]
      local lo = min(ux * (x0 - ax), ux * (x1 - ax)) + min(uy * (y0 - ay), uy * (y1 - ay))
      highest = max(highest, lo - (1 - edge) * FAR)
      local slot = top + 1
      fx[slot], fy[slot], fc[slot] = ux * sense, uy * sense, -lo
      seam[slot], reach[slot] = internal[l], abs(lift - lo)
      top = top + edge
      ax, ay = bx, by
    end
    return top, isAbove(-(16 * EPS * (spanX + spanY)) - highest), highest
  end
end

-- LuaJIT's faces of part i of view, an axis-parallel rectangle (rectKind), against a part that
-- is not, whose box is at boxes[b - 3 .. b]: addFaces' faces, without a loop, the rectangle's
-- sides in the order of its edges (sides[i]), each side's constant the other box's far side
-- less the rectangle's own, the same numbers as rectPairFaces' (a side's normal (+-1, 0) or
-- (0, +-1): its projections are the coordinates' differences, least at the box's side, exactly
-- as addBoxFaces computes them, up to zeros' signs, which change no comparison and no push).
-- (SIDE_X, SIDE_Y: the outward normals of the sides left, top, right, bottom; see rectPairFaces)
local SIDE_X, SIDE_Y = { -1.0, 0.0, 1.0, 0.0 }, { 0.0, -1.0, 0.0, 1.0 }
local rectFaces
if JIT then
  local rectC = { 0.0, 0.0, 0.0, 0.0 }
  rectFaces = function(view, i, boxes, b, sense, spanX, spanY, top)
    local sides, internal, own, a = view.sides[i], view.internal[i], view.boxes, 4 * i
    local cLeft, cTop = boxes[b - 1] - own[a - 3], boxes[b] - own[a - 2]
    local cRight, cBottom = own[a - 1] - boxes[b - 3], own[a] - boxes[b - 2]
    local c = rectC
    c[1], c[2], c[3], c[4] = cLeft, cTop, cRight, cBottom
    local fx, fy, fc, seam, reach = faceX, faceY, faceC, faceSeam, faceReach
    local lift = faceLift
    local line = sides[1]
    fx[top + 1], fy[top + 1], fc[top + 1], seam[top + 1], reach[top + 1] = SIDE_X[line] * sense,
      SIDE_Y[line] * sense, c[line], internal[1], abs(lift + c[line])
    line = sides[3]
    fx[top + 2], fy[top + 2], fc[top + 2], seam[top + 2], reach[top + 2] = SIDE_X[line] * sense,
      SIDE_Y[line] * sense, c[line], internal[3], abs(lift + c[line])
    line = sides[5]
    fx[top + 3], fy[top + 3], fc[top + 3], seam[top + 3], reach[top + 3] = SIDE_X[line] * sense,
      SIDE_Y[line] * sense, c[line], internal[5], abs(lift + c[line])
    line = sides[7]
    fx[top + 4], fy[top + 4], fc[top + 4], seam[top + 4], reach[top + 4] = SIDE_X[line] * sense,
      SIDE_Y[line] * sense, c[line], internal[7], abs(lift + c[line])
    -- addFaces' 1 when no side can separate: every lo = -c below -16 eps (spanX + spanY); and
    -- the largest lo
    local least = min(cLeft, cTop, cRight, cBottom)
    return top + 4, isAbove(least - 16 * EPS * (spanX + spanY)), -least
  end
end

-- The faces of both parts of a pair: addFaces for p1 (sense 1) and then for p2 (sense -1), and
-- 1 when the parts overlap, else 0: decided exactly on PUC Lua; on LuaJIT 0 also when they
-- may not (see addFaces). On PUC Lua one call for both (the arguments and
-- the set-up of a call were a tenth of the faces' instructions), minProjection's loop inline,
-- unrolled for a quadrilateral.
local pairFaces
if JIT then
  pairFaces = function(p1, n1, _, normals1, internal1, p2, n2, _, normals2, internal2,
                       k, spanX, spanY, top)
    local sure1, sure2, highest1, highest2
    top, sure1, highest1 = addFaces(p1, n1, normals1, p2, n2, internal1, 1.0, k, spanX, spanY, top)
    top, sure2, highest2 = addFaces(p2, n2, normals2, p1, n1, internal2, -1.0, k, spanX, spanY, top)
    return top, sure1 * sure2, max(highest1, highest2)
  end
else
  pairFaces = function(p1, n1, turn1, normals1, internal1, p2, n2, turn2, normals2, internal2,
                       k, spanX, spanY, top, boxes1, a, boxes2, b, rect1, rect2)
    local separated, highest = false, -huge   -- highest: the largest lo
    local fx, fy, fc, seam, reach = faceX, faceY, faceC, faceSeam, faceReach
    local lift, foot, footReach = faceLift, nearestFoot, nearestReach
    local foot2, foot2Reach = secondFoot, secondReach
    local scaled = k ~= 1
    -- lo < loBound, -lo > 16 eps (spanX + spanY), projectionTolerance's bound for any unit
    -- normal (|ux|, |uy| <= 1; rounding is monotonic): the edge cannot separate
    local loBound = -(16 * EPS * (spanX + spanY))
    -- p1's edges against p2's vertices, then p2's against p1's (one assignment per statement:
    -- Lua 5.4 moves a multiple assignment through a temporary per value)
    local edges, ne, turn, normals, internal, other, no, sense =
      p1, n1, turn1, normals1, internal1, p2, n2, 1.0
    local ownBoxes, e, otherBoxes, o, rect = boxes1, a, boxes2, b, rect1
    local otherRect = rect2
    for side = 1, 2 do
      if side == 2 then
        edges = p2
        ne = n2
        turn = turn2
        normals = normals2
        internal = internal2
        other = p1
        no = n1
        sense = -1.0
        ownBoxes = boxes2
        e = b
        otherBoxes = boxes1
        o = a
        rect = rect2
        otherRect = rect1
      end
      local quad = no == 8
      -- the other part's box (exact: its least and greatest coordinates, as floats)
      local oxmin, oymin = otherBoxes[o - 3], otherBoxes[o - 2]
      local oxmax, oymax = otherBoxes[o - 1], otherBoxes[o]
      -- An axis-parallel rectangle (see rectKind): its faces without reading its vertices or
      -- normals. Each side's least projection is the axis-parallel edge's below (the same
      -- number); its edges alternate between vertical and horizontal sides (a vertical one
      -- first for rect 1), the first vertical one at v1's x, the first horizontal one at v1's y.
      local vertical, loX, loX2, nx, loY, loY2, ny = rect == 1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
      if scaled then
        rect = 0
      elseif rect ~= 0 then
        local exmin, eymin = ownBoxes[e - 3], ownBoxes[e - 2]
        loX = exmin - oxmax   -- the left side's (outward normal (-1, 0)), then the right's
        loX2 = oxmin - ownBoxes[e - 1]
        nx = -1.0
        if edges[1] + 0.0 ~= exmin then
          loX2 = loX
          loX = oxmin - ownBoxes[e - 1]
          nx = 1.0
        end
        loY = eymin - oymax   -- the top side's (outward normal (0, -1)), then the bottom's
        loY2 = oymin - ownBoxes[e]
        ny = -1.0
        if edges[2] + 0.0 ~= eymin then
          loY2 = loY
          loY = oymin - ownBoxes[e]
          ny = 1.0
        end
      end
      local ax, ay = edges[ne - 1] + 0.0, edges[ne] + 0.0
      for i = 1, ne - 1, 2 do
        local ux, uy, lo
        if rect ~= 0 then
          if vertical then
            ux = nx
            uy = 0.0
            lo = loX
            nx = -nx   -- the next vertical side is the opposite one
            loX = loX2
          else
            ux = 0.0
            uy = ny
            lo = loY
            ny = -ny
            loY = loY2
          end
          vertical = not vertical
          -- the side separates exactly when the other part lies beyond it or on its line
          if lo >= 0 then separated = true end
        else
          local bx, by = edges[i] + 0.0, edges[i + 1] + 0.0
          if bx ~= ax or by ~= ay then   -- a repeated vertex gives no edge
            ux = normals[i]
            uy = normals[i + 1]
            if scaled then   -- the same numbers as unscaled where k is 1
              lo = huge
              local kax, kay = ax * k, ay * k
              for j = 1, no - 1, 2 do
                local s = ux * (other[j] * k - kax) + uy * (other[j + 1] * k - kay)
                if s < lo then lo = s end
              end
            elseif uy == 0 then
              -- An axis-parallel edge (a tile's, a box's): its unit normal is exactly (1, 0) or
              -- (-1, 0) up to the zero's sign (unit's scaling), so each projection is
              -- +-(vx - ax) up to the sign of a zero, and rounding is monotonic: the least is
              -- the other part's box side less ax, the same number minProjection gives (a
              -- zero's sign aside, which nothing after reads: lo only meets sums with lift and
              -- margin, both > 0, and comparisons), by one subtraction instead of a projection
              -- a vertex.
              if ux > 0 then lo = oxmin - ax else lo = ax - oxmax end
            elseif ux == 0 then   -- the same along y
              if uy > 0 then lo = oymin - ay else lo = ay - oymax end
            elseif otherRect ~= 0 then
              -- The other part is an axis-parallel rectangle: its vertices are its box's
              -- corners, and rounding is monotonic, so the least of the projections
              -- fl(fl(ux (x - ax)) + fl(uy (y - ay))) is the corner's whose terms are least, x
              -- its least for ux >= 0, its greatest else (for ux a zero either term is a zero),
              -- and y the same: the number minProjection gives, by two products (the crate
              -- turned 0.5 radian on the floor of bench/compound.lua: 12 VM instructions an
              -- edge where the quadrilateral's below take 32)
              local sx = oxmin - ax
              if ux < 0 then sx = oxmax - ax end
              local sy = oymin - ay
              if uy < 0 then sy = oymax - ay end
              lo = ux * sx + uy * sy
            elseif quad then
              -- a quadrilateral: minProjection's loop unrolled, the same numbers (the first s
              -- is finite, so lo = s is what s < huge gives): constant indices and no loop
              -- steps, 32 VM instructions where the loop takes 46 (Lua 5.4)
              lo = ux * (other[1] - ax) + uy * (other[2] - ay)
              local s = ux * (other[3] - ax) + uy * (other[4] - ay)
              if s < lo then lo = s end
              s = ux * (other[5] - ax) + uy * (other[6] - ay)
              if s < lo then lo = s end
              s = ux * (other[7] - ax) + uy * (other[8] - ay)
              if s < lo then lo = s end
            else   -- minProjection's loop, without the call's instructions
              lo = huge
              for j = 1, no - 1, 2 do
                local s = ux * (other[j] - ax) + uy * (other[j + 1] - ay)
                if s < lo then lo = s end
              end
            end
            if not separated and lo >= loBound then
              separated = edgeSeparates(lo, ax, ay, bx, by, turn, ux, uy, other, no, spanX, spanY)
            end
          end
          ax = bx
          ay = by
        end
        if lo then
          if lo > highest then highest = lo end
          top = top + 1
          fx[top], fy[top], fc[top] = ux * sense, uy * sense, -lo
          local flag, d = internal[i], lift - lo
          if d < 0 then d = -d end   -- a comparison, not abs's call
          seam[top], reach[top] = flag, d
          if flag ~= 0 then
            if d < seamReach then seamReach = d end
          elseif d < footReach then
            foot, footReach, foot2, foot2Reach = top, d, foot, footReach
          elseif d < foot2Reach then
            foot2, foot2Reach = top, d
          end
        end
      end
    end
    nearestFoot, nearestReach, secondFoot, secondReach = foot, footReach, foot2, foot2Reach
    if separated then return top, 0, highest end
    return top, 1, highest
  end
end

-- Two axis-parallel rectangles (rectKind, unscaled), part i of view1 (p1) and part j of view2
-- (p2), as pair p: the faces pairFaces gives, less those that change nothing. D is then a box:
-- each side of p2 gives the line of the opposite side of p1, the same numbers (lo of p1's right
-- side, oxmin - exmax, is lo of p2's left side, ax - oxmax, with the same roles). A later face
-- equal to an earlier one, line and flag (seam or outer), decides nothing: pushFree's test is
-- the same, it is never nearer than its twin, which comes first (feet and crossings keep the
-- first of equals), and the crossings it gives are its twin's (the same point: (c1 y2 - c2 y1)
-- / det with the lines swapped is the same number). So a side of p2 gives a face only when its
-- flag differs from that of p1's side on its line (a seam of the list against the flat shape's
-- outer edge, whose foot is tried). The views' sides give the sides in edge order (see
-- rectSides). Returns the last face's index and 1 when the rectangles overlap (exactly: no side
-- has the other rectangle beyond it or on its line), else 0.
local sideConstant, sideFlag = { 0.0, 0.0, 0.0, 0.0 }, { 0, 0, 0, 0 }
local rectPairFaces
if JIT then
  -- LuaJIT's: PUC Lua's faces, without a branch: each of p2's sides is written after p1's
  -- and kept (top moves on) when its flag differs from that of p1's side on its line, by the
  -- difference's abs, 1 or 0 (all eight kept, the feet sought over them all: 6,614 against
  -- 6,489 machine instructions a push of bench/compound.lua's crate by callgrind, medians
  -- over five seeds of LuaJIT's random trace penalties); the
  -- nearest feet kept later by keepFeet, as for addFaces' faces; without a loop (a loop of
  -- four steps was a trace of its own, entered and left twice a pair).
  local function putSide(line, flag, top)
    local c = sideConstant[line]
    faceX[top], faceY[top], faceC[top], faceSeam[top], faceReach[top] = SIDE_X[line],
      SIDE_Y[line], c, flag, abs(faceLift + c)
  end
  rectPairFaces = function(view1, i, view2, j, top, p)
    local sides1, internal1, boxes1, a = view1.sides[i], view1.internal[i], view1.boxes, 4 * i
    local sides2, internal2, boxes2, b = view2.sides[j], view2.internal[j], view2.boxes, 4 * j
    local sideC, flags = sideConstant, sideFlag
    local cLeft, cTop = boxes2[b - 1] - boxes1[a - 3], boxes2[b] - boxes1[a - 2]
    local cRight, cBottom = boxes1[a - 1] - boxes2[b - 3], boxes1[a] - boxes2[b - 2]
    sideC[1], sideC[2], sideC[3], sideC[4] = cLeft, cTop, cRight, cBottom
    local rects, r = pairRects, 8 * p   -- for pushFree
    pairBox[p] = 1
    rects[r - 7], rects[r - 6], rects[r - 5], rects[r - 4] = boxes1[a - 3], boxes1[a - 2],
      boxes1[a - 1], boxes1[a]
    rects[r - 3], rects[r - 2], rects[r - 1], rects[r] = boxes2[b - 3], boxes2[b - 2],
      boxes2[b - 1], boxes2[b]
    local line1, line2, line3, line4 = sides1[1], sides1[3], sides1[5], sides1[7]
    local flag1, flag2, flag3, flag4 = internal1[1], internal1[3], internal1[5], internal1[7]
    flags[line1], flags[line2], flags[line3], flags[line4] = flag1, flag2, flag3, flag4
    putSide(line1, flag1, top + 1)
    putSide(line2, flag2, top + 2)
    putSide(line3, flag3, top + 3)
    putSide(line4, flag4, top + 4)
    top = top + 4
    local line, flag = sides2[2], internal2[1]
    putSide(line, flag, top + 1)
    top = top + abs(flag - flags[line])
    line, flag = sides2[4], internal2[3]
    putSide(line, flag, top + 1)
    top = top + abs(flag - flags[line])
    line, flag = sides2[6], internal2[5]
    putSide(line, flag, top + 1)
    top = top + abs(flag - flags[line])
    line, flag = sides2[8], internal2[7]
    putSide(line, flag, top + 1)
    top = top + abs(flag - flags[line])
    local least = min(cLeft, cTop, cRight, cBottom)
    leastFree = max(leastFree, faceLift + least)
    return top, isAbove(least)
  end
else
  rectPairFaces = function(view1, i, view2, j, top, p)
    local sides1, internal1, boxes1, a = view1.sides[i], view1.internal[i], view1.boxes, 4 * i
    local sides2, internal2, boxes2, b = view2.sides[j], view2.internal[j], view2.boxes, 4 * j
    local fx, fy, fc, seam, reach = faceX, faceY, faceC, faceSeam, faceReach
    local sideX, sideY, sideC, flags = SIDE_X, SIDE_Y, sideConstant, sideFlag
    local lift, foot, footReach = faceLift, nearestFoot, nearestReach
    local foot2, foot2Reach, nearX, nearY = secondFoot, secondReach, seamX, seamY
    -- p1's sides' faceC, -lo of the axis-parallel edges in pairFaces (fl(b - a) = -fl(a - b))
    local cLeft = boxes2[b - 1] - boxes1[a - 3]
    local cTop = boxes2[b] - boxes1[a - 2]
    local cRight = boxes1[a - 1] - boxes2[b - 3]
    local cBottom = boxes1[a] - boxes2[b - 2]
    sideC[1] = cLeft
    sideC[2] = cTop
    sideC[3] = cRight
    sideC[4] = cBottom
    local rects, r = pairRects, 8 * p   -- for pushFree
    pairBox[p] = 1
    rects[r - 7] = boxes1[a - 3]
    rects[r - 6] = boxes1[a - 2]
    rects[r - 5] = boxes1[a - 1]
    rects[r - 4] = boxes1[a]
    rects[r - 3] = boxes2[b - 3]
    rects[r - 2] = boxes2[b - 2]
    rects[r - 1] = boxes2[b - 1]
    rects[r] = boxes2[b]
    -- p1's sides in the order of its edges, then those of p2 whose flags differ: two loops, the
    -- face's code in both (one loop over the eight edges took 5 more VM instructions an edge to
    -- tell the two apart; one assignment per statement, as in pairFaces). The reach lift + c is
    -- pairFaces' lift - lo.
    for e = 1, 7, 2 do
      local line, flag = sides1[e], internal1[e]
      flags[line] = flag
      local c = sideC[line]
      local d = lift + c
      if d < 0 then d = -d end   -- a comparison, not abs's call
      top = top + 1
      local ux = sideX[line]
      fx[top] = ux
      fy[top] = sideY[line]
      fc[top] = c
      seam[top] = flag
      reach[top] = d
      if flag ~= 0 then
        if ux ~= 0 then
          if d < nearX then nearX = d end
        elseif d < nearY then
          nearY = d
        end
      elseif d < footReach then
        foot2 = foot
        foot2Reach = footReach
        foot = top
        footReach = d
      elseif d < foot2Reach then
        foot2 = top
        foot2Reach = d
      end
    end
    for e = 1, 7, 2 do
      local line, flag = sides2[e + 1], internal2[e]
      if flag ~= flags[line] then   -- else as the face of p1's on the same line: nothing to add
        local c = sideC[line]
        local d = lift + c
        if d < 0 then d = -d end
        top = top + 1
        local ux = sideX[line]
        fx[top] = ux
        fy[top] = sideY[line]
        fc[top] = c
        seam[top] = flag
        reach[top] = d
        if flag ~= 0 then
          if ux ~= 0 then
            if d < nearX then nearX = d end
          elseif d < nearY then
            nearY = d
          end
        elseif d < footReach then
          foot2 = foot
          foot2Reach = footReach
          foot = top
          footReach = d
        elseif d < foot2Reach then
          foot2 = top
          foot2Reach = d
        end
      end
    end
    nearestFoot, nearestReach, secondFoot, secondReach = foot, footReach, foot2, foot2Reach
    seamX, seamY = nearX, nearY
    local least = cLeft   -- leastFree, as LuaJIT's
    if cTop < least then least = cTop end
    if cRight < least then least = cRight end
    if cBottom < least then least = cBottom end
    least = lift + least
    if least > leastFree then leastFree = least end
    if cLeft > 0 and cTop > 0 and cRight > 0 and cBottom > 0 then return top, 1 end
    return top, 0
  end
end

-- Whether t lies outside every D of pairs 1 .. np widened by margin. A pair of rectangles
-- (pairBox) exactly instead: whether the second's box moved by t, each side as the move rounds
-- it (x + dx, as a game moves each vertex), overlaps the first's, which is whether the moved
-- rectangles overlap. So a push that leaves a crate touching a wall is free, and one push
-- still separates: a crate that fits a slot of a floor of boxes exactly, sunk into its bottom,
-- goes straight up, flush with both walls, not out over one of them (as it did when D widened
-- by margin was tested here too). Written as the negation of a disjunction, so that a NaN
-- is inside, as in the faces' tests.
local function pushFree(tx, ty, np, margin)
  local first, fx, fy, fc = faceFirst, faceX, faceY, faceC   -- locals: PUC Lua reads upvalues slower
  local isBox, rects = pairBox, pairRects
  for p = 1, np do
    if isBox[p] ~= 0 then
      local b = 8 * p
      if not (rects[b - 7] >= rects[b - 1] + tx or rects[b - 3] + tx >= rects[b - 5]
          or rects[b - 6] >= rects[b] + ty or rects[b - 2] + ty >= rects[b - 4]) then
        return false
      end
    else
      local inside = true
      for f = first[p], first[p + 1] - 1 do
        if fx[f] * tx + fy[f] * ty >= fc[f] + margin then
          inside = false
          break
        end
      end
      if inside then return false end
    end
  end
  return true
end

local nearLines = {}   -- scratch for nearestFree: the faces whose lines pass nearer than the best

-- The nearest free candidate among the faces of pairs 1 .. np: its length and vector, or huge.
local function nearestFree(np, margin)
  local fx, fy, fc, reach = faceX, faceY, faceC, faceReach   -- locals: PUC Lua reads upvalues slower
  local best, bestX, bestY = huge, 0.0, 0.0
  local last = faceFirst[np + 1] - 1
  local lift = 1.25 * margin
  -- A candidate t whose computed length e is below low = leastFree - 0.75 margin is not free,
  -- and is not tried (pushFree would say false: the answer is the same; on LuaJIT the
  -- crossings are, see below). Let L = leastFree, the least fc + lift of some pair: each
  -- face h of that pair has fc + lift >= L (1 - eps), so fc + margin (lift = 1.25 margin)
  -- rounds to at least L (1 - 2 eps) - 0.25 margin; and t gives fx tx + fy ty <= e (1 + 10 eps)
  -- (a unit normal within 4 eps of length 1, |t| within 5 eps of e for a foot or a crossing,
  -- the products and the sum rounded), below that when 0.5 margin > 14 eps L, true as
  -- L <= 1.01 E and margin >= 64 eps E: t lies inside the pair's D widened by margin, for
  -- every face. (The crate turned 0.5 radian on bench/compound.lua's floor: its
  -- nearest foot is mostly a face of the crate against the part it barely reaches into, inside
  -- the other part's D: pushFree 3.62 -> 1.31 calls a push on PUC Lua, 1.84 on LuaJIT, by a
  -- count in a copy.)
  local low = leastFree - 0.75 * margin
  if JIT and feetKept < last then   -- (PUC Lua: pairFaces kept them)
    keepFeet(feetKept + 1, last)
    feetKept = last
  end
  -- The nearest foot first, then the second nearest (addFaces keeps them): usually one of them
  -- is free, and then no other foot is nearer (the feet loop below would pick the first free one
  -- in the order of reach, then of faces; it runs when neither is free).
  local found = 0
  if nearestFoot > 0 and nearestReach >= low then
    local d = fc[nearestFoot] + lift
    local tx, ty = fx[nearestFoot] * d, fy[nearestFoot] * d
    if pushFree(tx, ty, np, margin) then best, bestX, bestY, found = nearestReach, tx, ty, 1 end
  end
  if found == 0 and secondFoot > 0 and secondReach >= low then
    local d = fc[secondFoot] + lift
    local tx, ty = fx[secondFoot] * d, fy[secondFoot] * d
    if pushFree(tx, ty, np, margin) then best, bestX, bestY, found = secondReach, tx, ty, 2 end
  end
  if found == 0 then
    -- feet of the perpendiculars on the outer edges' lines, but the nearest two: not free (the
    -- crate turned 0.5 radian: 0.29 of 0.67 pushFree calls a push here were those again)
    local foot, foot2 = nearestFoot, secondFoot
    for f = 1, last do
      if faceSeam[f] == 0 and reach[f] < best and reach[f] >= low and f ~= foot and f ~= foot2 then
        local d = fc[f] + lift
        local tx, ty = fx[f] * d, fy[f] * d
        if pushFree(tx, ty, np, margin) then best, bestX, bestY = reach[f], tx, ty end
      end
    end
  elseif seamReach >= best then
    -- Every outer edge's line passes at least as far as the nearest foot (found 1) or the
    -- second (found 2: all but the nearest): at most one outer line nearer than the best, the
    -- nearest foot's. No crossing when the lines nearer than the best are all parallel to an
    -- axis, the same one: a crate on a floor at a seam, whose neighbours' vertical internal
    -- faces pass nearer than the top (their det is exactly 0: no crossing either way).
    if seamY >= best and (seamX >= best or found == 1 or fy[nearestFoot] == 0)
        or seamX >= best and (found == 1 or fx[nearestFoot] == 0) then
      return best, bestX, bestY
    end
  end
  -- Crossings of two lines, each nearer than the best so far (a crossing is no nearer than
  -- either line): only the lines nearer than the best now can take part, usually a few of them.
  local count = 0
  for f = 1, last do
    if reach[f] < best then count = count + 1; nearLines[count] = f end
  end
  for a = 1, count - 1 do
    local f = nearLines[a]
    if reach[f] < best then
      local c1, x1, y1 = fc[f] + lift, fx[f], fy[f]
      for b = a + 1, count do
        local g = nearLines[b]
        if reach[g] < best then
          local c2 = fc[g] + lift
          local x2, y2 = fx[g], fy[g]
          local det = x1 * y2 - y1 * x2
          if det ~= 0 then
            local tx, ty = (c1 * y2 - c2 * y1) / det, (x1 * c2 - x2 * c1) / det
            local d = sqrt(tx * tx + ty * ty)
            -- Below low not tried on PUC Lua, as the feet (2,924 -> 2,848 VM instructions a
            -- push of the turned crate); tried on LuaJIT, where that test's side exits led
            -- into pushFree in side traces that failed to compile, "NYI: register coalescing
            -- too complex", about 250 aborts in each of 2 of 11 runs of `luajit -jv
            -- bench/compound.lua timing 5000` at fixed trace seeds (without it 4 aborts in 7
            -- of 14 runs, as before this test in 7 of 10)
            if d < best and (JIT or d >= low) and pushFree(tx, ty, np, margin) then
              best, bestX, bestY = d, tx, ty
            end
          end
        end
      end
    end
  end
  return best, bestX, bestY
end

-- Brings part p1 (number i of view1) and p2 (number j of view2) up to date for the boolean's
-- pair test (addPair does the same for a push, with the flat view's normals): a list's part
-- compared with its whole copy (the non-finite error raised at the public function's caller,
-- level 7 from checkCopy), a flat view's area sign computed. Returns their area signs and
-- spanX, spanY bounding their coordinate differences.
local function prepareSide(view, p, i)
  if view.copies then
    if view.checked[i] ~= callStamp then checkCopy(view, i, p, 7) end
  elseif view.turnPending then
    partTurn(view, 1, p, #p); view.turnPending = false
  end
end

local function preparePair(view1, p1, i, view2, p2, j)
  prepareSide(view1, p1, i)
  prepareSide(view2, p2, j)
  local boxes1, boxes2, a, b = view1.boxes, view2.boxes, 4 * i, 4 * j
  local right, bottom, left, top = boxes1[a - 1], boxes1[a], boxes1[a - 3], boxes1[a - 2]
  if JIT then
    right, bottom = max(right, boxes2[b - 1]), max(bottom, boxes2[b])
    left, top = min(left, boxes2[b - 3]), min(top, boxes2[b - 2])
  else   -- the same numbers without calls
    if boxes2[b - 1] > right then right = boxes2[b - 1] end
    if boxes2[b] > bottom then bottom = boxes2[b] end
    if boxes2[b - 3] < left then left = boxes2[b - 3] end
    if boxes2[b - 2] < top then top = boxes2[b - 2] end
  end
  return view1.turns[i], view2.turns[j], right - left, bottom - top
end

-- Whether some edge of the part `edges` (turn its area sign) separates it from the part
-- `other`, decided exactly: the SAT engine's test (reachPast's), on each edge's outward normal
-- as the coordinates' differences give it (unscaled coordinates: the boolean's pairs).
local function edgesSeparate(edges, ne, turn, other, no, spanX, spanY)
  -- at least projectionTolerance of every edge's normal, whose |nx| <= spanY, |ny| <= spanX
  -- (rounding is monotonic): an edge whose -lo exceeds it cannot separate
  local tolBound = 16 * EPS * (2 * (spanX * spanY))
  local ax, ay = edges[ne - 1] + 0.0, edges[ne] + 0.0
  for i = 1, ne - 1, 2 do
    local bx, by = edges[i] + 0.0, edges[i + 1] + 0.0
    if bx ~= ax or by ~= ay then   -- a repeated vertex gives no edge
      local nx, ny = (by - ay) * turn, (ax - bx) * turn
      local lo = leastProjection(other, no, ax, ay, nx, ny)
      if -lo <= tolBound and edgeSeparates(lo, ax, ay, bx, by, turn, nx, ny, other, no, spanX, spanY) then
        return true
      end
    end
    ax, ay = bx, by
  end
  return false
end

-- Whether part p1 (number i of view1) and p2 (number j of view2) overlap, exactly: the boolean
-- addPair returns, without building faces.
-- On PUC Lua the SAT engine's calipers over both parts (reachBoth) decide it, one projection an
-- edge; on LuaJIT, which runs the engine's flat loop, edgesSeparate, which stops at the first
-- separating edge.
local function pairOverlaps(view1, p1, i, view2, p2, j)
  local turn1, turn2, spanX, spanY = preparePair(view1, p1, i, view2, p2, j)
  if turn1 == 0 or turn2 == 0 then return false end   -- zero area: never collides
  local n1, n2 = view1.lengths[i], view2.lengths[j]
  if not JIT then
    return reachBoth(p1, n1, turn1, p2, n2, turn2, squaredTolerance(spanX, spanY)) ~= false
  end
  return not (edgesSeparate(p1, n1, turn1, p2, n2, spanX, spanY)
    or edgesSeparate(p2, n2, turn2, p1, n1, spanX, spanY))
end

-- Appends the faces of D for part p1 (number i of view1) and p2 (number j of view2) as pair
-- np + 1, noting i and j (pairsOverlap). Returns np, top and pairFaces' 1 or 0 (whether the
-- parts overlap; on LuaJIT, overlap for sure).
local function addPair(view1, p1, i, view2, p2, j, k, np, top)
  -- preparePair's work inline (PUC Lua pays for every call): checkCopy's level counts from there
  -- A flat rectangle needs no normals unscaled (flatBox gave its sign): rectPairFaces and PUC
  -- Lua's pairFaces read none; LuaJIT's addFaces reads them against a part not a rectangle, so
  -- there they wait for such a pair.
  if view1.copies then
    if view1.checked[i] ~= callStamp then checkCopy(view1, i, p1, 5) end
  elseif view1.pending then
    local needed = k ~= 1 or view1.rects[1] == 0 or JIT and view2.rects[j] == 0
    if needed then partNormals(view1, 1, p1, #p1) end
    view1.pending = JIT and not needed
  end
  if view2.copies then
    if view2.checked[j] ~= callStamp then checkCopy(view2, j, p2, 5) end
  elseif view2.pending then
    local needed = k ~= 1 or view2.rects[1] == 0 or JIT and view1.rects[i] == 0
    if needed then partNormals(view2, 1, p2, #p2) end
    view2.pending = JIT and not needed
  end
  local turn1, turn2 = view1.turns[i], view2.turns[j]
  if turn1 == 0 or turn2 == 0 then return np, top, 0 end   -- zero area: never collides
  faceFirst[np + 1] = top + 1
  if k == 1 and view1.rects[i] ~= 0 and view2.rects[j] ~= 0 then
    local overlaps
    top, overlaps = rectPairFaces(view1, i, view2, j, top, np + 1)
    faceFirst[np + 2] = top + 1
    if JIT then pairPart1[np + 1], pairPart2[np + 1] = i, j end
    return np + 1, top, overlaps
  end
  local boxes1, boxes2, a, b = view1.boxes, view2.boxes, 4 * i, 4 * j
  local right1, bottom1, left1, low1 = boxes1[a - 1], boxes1[a], boxes1[a - 3], boxes1[a - 2]
  local right, bottom, left, low = right1, bottom1, left1, low1
  if JIT then
    right, bottom = max(right, boxes2[b - 1]), max(bottom, boxes2[b])
    left, low = min(left, boxes2[b - 3]), min(low, boxes2[b - 2])
  else   -- the same numbers without calls
    if boxes2[b - 1] > right then right = boxes2[b - 1] end
    if boxes2[b] > bottom then bottom = boxes2[b] end
    if boxes2[b - 3] < left then left = boxes2[b - 3] end
    if boxes2[b - 2] < low then low = boxes2[b - 2] end
  end
  local spanX, spanY = (right - left) * k, (bottom - low) * k
  local n1, n2 = view1.lengths[i], view2.lengths[j]
  pairBox[np + 1] = 0
  local overlaps
  if JIT and k == 1 and view1.rects[i] + view2.rects[j] ~= 0 then   -- one is a rectangle
    local sure1, sure2, highest1, highest2
    if view1.rects[i] ~= 0 then
      top, sure1, highest1 = rectFaces(view1, i, boxes2, b, 1.0, spanX, spanY, top)
    else
      top, sure1, highest1 = addBoxFaces(p1, n1, view1.normals[i], boxes2[b - 3], boxes2[b - 2],
        boxes2[b - 1], boxes2[b], view1.internal[i], 1.0, spanX, spanY, top)
    end
    if view2.rects[j] ~= 0 then
      top, sure2, highest2 = rectFaces(view2, j, boxes1, a, -1.0, spanX, spanY, top)
    else
      top, sure2, highest2 = addBoxFaces(p2, n2, view2.normals[j], left1, low1, right1, bottom1,
        view2.internal[j], -1.0, spanX, spanY, top)
    end
    faceFirst[np + 2] = top + 1
    pairPart1[np + 1], pairPart2[np + 1] = i, j
    leastFree = max(leastFree, faceLift - max(highest1, highest2))
    return np + 1, top, sure1 * sure2
  end
  local highest
  top, overlaps, highest = pairFaces(p1, n1, turn1, view1.normals[i], view1.internal[i],
    p2, n2, turn2, view2.normals[j], view2.internal[j], k, spanX, spanY, top, boxes1, a, boxes2, b,
    view1.rects[i], view2.rects[j])
  highest = faceLift - highest   -- this pair's least fc + lift (see leastFree)
  if highest > leastFree then leastFree = highest end
  faceFirst[np + 2] = top + 1
  if JIT then pairPart1[np + 1], pairPart2[np + 1] = i, j end
  return np + 1, top, overlaps
end

local overlapping = {}   -- scratch: the parts of a list whose boxes overlap a flat shape's box
local nearParts = {}     -- scratch: those whose boxes come within the window of it (see below)

-- The parts of a prepared list whose boxes overlap the box x0, y0, x1, y1 (strictly), in order,
-- into overlapping, and those whose boxes overlap it grown by `window` on every side into
-- nearParts; returns both numbers and, over the parts in nearParts but not in overlapping, the
-- least of the largest box gaps along x of those whose largest gap is along x, and the same
-- along y (or huge; see collideParts). First sees whether some part changed,
-- as listView does (its table, its length, the coordinates on its box: see preparedParts), and
-- then returns nil at once: the same checks in the same loop as the box tests, which read the
-- same boxes (after listView they pass: the list is up to date).
-- Two bodies: on LuaJIT the box tests by the largest gap, one branch a part; on PUC Lua by
-- comparisons, most parts failing the first or second.
local partsOverlapping
if JIT then
  partsOverlapping = function(info, shape, x0, y0, x1, y1, window)
    local found, near, leastGapX, leastGapY = 0, 0, huge, huge
    local records = info.records
    for k = 1, info.count do
      local part, record = shape[k], records[k]
      local xmin, ymin, xmax, ymax = record[1], record[2], record[3], record[4]
      if part ~= record[9] then return nil end
      if record[16] == 0 then
        -- a rectangle from its (xmin, ymin): as below, against the box's values loaded (the
        -- scan of bench/compound.lua's floor: 2,815 machine instructions a call by callgrind,
        -- where record[12] .. [15] took 2,978)
        if part[1] ~= xmin or part[2] ~= ymin or part[5] ~= xmax or part[6] ~= ymax
            or part[9] ~= nil or part[8] == nil then
          return nil
        end
      elseif record[11] ~= 0 then
        -- an axis-parallel rectangle (rectKind): the coordinates of its first and third
        -- vertices, the four watched (see partBox), read at constant indices, not through the
        -- indices kept (a conversion and a bounds check each: the scan of the 20 parts of
        -- bench/compound.lua took a fifth fewer machine instructions), and its length 8
        if part[1] ~= record[12] or part[2] ~= record[13] or part[5] ~= record[14]
            or part[6] ~= record[15] or part[9] ~= nil or part[8] == nil then
          return nil
        end
      else
        local n = record[10]
        if n >= 6 then
          -- the length as a border, part[n] set and part[n + 1] not, the same for an array
          -- without holes: #part is a call on LuaJIT, across which every live number goes to
          -- memory (the scan of 20 parts of bench/compound.lua took 13 % longer with it)
          if part[n + 1] ~= nil or part[n] == nil or part[record[5]] ~= xmin
              or part[record[6]] ~= ymin or part[record[7]] ~= xmax or part[record[8]] ~= ymax then
            return nil
          end
        elseif #part ~= n then
          return nil
        end
      end
      -- the largest gap between the boxes (< 0 when they overlap: a - b < 0 exactly when a < b,
      -- no NaN), by max: one branch for most parts (PUC Lua's tests: four, each a side exit)
      local gapX, gapY = max(xmin - x1, x0 - xmax), max(ymin - y1, y0 - ymax)
      local gap = max(gapX, gapY)
      if gap < window then
        near = near + 1
        nearParts[near] = k
        if gap < 0 then
          found = found + 1
          overlapping[found] = k
        elseif gapX >= gapY then
          leastGapX = min(leastGapX, gapX)
        else
          leastGapY = min(leastGapY, gapY)
        end
      end
    end
    return found, near, leastGapX, leastGapY
  end
else
  partsOverlapping = function(info, shape, x0, y0, x1, y1, window)
    local found, near, leastGapX, leastGapY = 0, 0, huge, huge
    local wx0, wy0, wx1, wy1 = x0 - window, y0 - window, x1 + window, y1 + window
    local records = info.records
    for k = 1, info.count do
      local part, record = shape[k], records[k]
      local xmin, ymin, xmax, ymax = record[1], record[2], record[3], record[4]
      local n = record[16]   -- 0 for a rectangle from its (xmin, ymin), else the length
      if part ~= record[9] then return nil end
      if n == 0 then
        -- its watched coordinates at constant indices, against the box's values loaded: two VM
        -- instructions each, where the indices kept take three (14 a part for the checks here,
        -- 18 below; the 20 parts of bench/compound.lua's floor are such rectangles)
        if #part ~= 8 or part[1] ~= xmin or part[2] ~= ymin or part[5] ~= xmax or part[6] ~= ymax then
          return nil
        end
      elseif #part ~= n or n >= 6 and (part[record[5]] ~= xmin or part[record[6]] ~= ymin
          or part[record[7]] ~= xmax or part[record[8]] ~= ymax) then
        return nil
      end
      if xmin < wx1 and wx0 < xmax and ymin < wy1 and wy0 < ymax then
        near = near + 1
        nearParts[near] = k
        if xmin < x1 and x0 < xmax and ymin < y1 and y0 < ymax then
          found = found + 1
          overlapping[found] = k
        else   -- the largest gaps, as on LuaJIT (the same differences)
          local gapX, gapY = xmin - x1, ymin - y1
          if x0 - xmax > gapX then gapX = x0 - xmax end
          if y0 - ymax > gapY then gapY = y0 - ymax end
          if gapX >= gapY then
            if gapX < leastGapX then leastGapX = gapX end
          elseif gapY < leastGapY then
            leastGapY = gapY
          end
        end
      end
    end
    return found, near, leastGapX, leastGapY
  end
end

-- Scratch for boxPush: per pair p, at 4p - 3 .. 4p, the lines of its first shape's sides in the
-- order of that part's edges (its faces' order in rectPairFaces): the side (1 left, 2 top, 3
-- right, 4 bottom, as rectSides numbers them) and its c + lift, which is also the line's
-- distance from the origin (its reach): the pairs' rectangles overlap, so every c > 0.
local boxSide, boxLine = {}, {}

-- Pairs 1 .. found of boxPush: their parts brought up to date (see preparedParts), each pair's
-- boxes (pairRects, for pushFree) and lines, from the boxes of the part and of the flat
-- rectangle; lines 4 found + 1 .. 8 FAR (see boxPush). Returns leastFree (see
-- nearestFree), or nil when a part is not a rectangle. A function of its own, its loop holding
-- few values: where the loop's end is a side exit, LuaJIT takes over in registers every value
-- live there, and failed to compile it ("NYI: register coalescing too complex") when
-- boxPush's were live too.
local function boxLines(info, list, flat, listFirst, found, margin)
  local lift, fb, flatSides, least = 1.25 * margin, flat.boxes, flat.sides[1], -huge
  local fx0, fy0, fx1, fy1 = fb[1], fb[2], fb[3], fb[4]
  for q = 1, found do
    local k = overlapping[q]
    if info.checked[k] ~= callStamp then checkCopy(info, k, list[k], 6) end
    if info.rects[k] == 0 then return nil end
    local boxes, a = info.boxes, 4 * k
    local x0, y0, x1, y1 = boxes[a - 3], boxes[a - 2], boxes[a - 1], boxes[a]
    local cLeft, cTop, cRight, cBottom = fx1 - x0, fy1 - y0, x1 - fx0, y1 - fy0
    local order, rects, r = flatSides, pairRects, 8 * q   -- pairRects for pushFree
    pairBox[q] = 1
    if listFirst then
      order = info.sides[k]
      rects[r - 7], rects[r - 6], rects[r - 5], rects[r - 4] = x0, y0, x1, y1
      rects[r - 3], rects[r - 2], rects[r - 1], rects[r] = fx0, fy0, fx1, fy1
    else
      cLeft, cTop, cRight, cBottom = x1 - fx0, y1 - fy0, fx1 - x0, fy1 - y0
      rects[r - 7], rects[r - 6], rects[r - 5], rects[r - 4] = fx0, fy0, fx1, fy1
      rects[r - 3], rects[r - 2], rects[r - 1], rects[r] = x0, y0, x1, y1
    end
    local c, sides, lines = sideConstant, boxSide, boxLine
    c[1], c[2], c[3], c[4] = cLeft, cTop, cRight, cBottom
    local b, side = 4 * q, order[1]
    sides[b - 3], lines[b - 3] = side, c[side] + lift
    side = order[3]
    sides[b - 2], lines[b - 2] = side, c[side] + lift
    side = order[5]
    sides[b - 1], lines[b - 1] = side, c[side] + lift
    side = order[7]
    sides[b], lines[b] = side, c[side] + lift
    least = max(least, lift + min(cLeft, cTop, cRight, cBottom))
  end
  if found == 1 then
    local sides, lines = boxSide, boxLine
    sides[5], sides[6], sides[7], sides[8] = 1, 2, 1, 2
    lines[5], lines[6], lines[7], lines[8] = FAR, FAR, FAR, FAR
  end
  return least
end

-- The rank of line l's foot in the order nearestFree meets the feet (ties go to the first):
-- 8 p + 1 .. 8 p + 8 for pair p. A side of the pair's first part that is not a seam in that
-- part's order, 1 to 4; a seam's foot is the face of the flat rectangle's side on that line
-- (rectPairFaces), after those, 5 to 8 in the order of the flat rectangle's sides. (Only ties
-- ask for it: equal reaches.)
local function boxRank(l, info, flat, listFirst)
  local q = (l - 1 - (l - 1) % 4) / 4 + 1   -- the pair
  local e = l - 4 * q + 4   -- the side's place in the order of the pair's first part
  if not listFirst or info.internal[overlapping[q]][2 * e - 1] == 0 then return 8 * q + e end
  local flatSides, side = flat.sides[1], boxSide[l]
  for e2 = 1, 4 do
    if flatSides[2 * e2] == side then return 8 * q + 4 + e2 end
  end
end

-- The foot of line l of boxPush, and whether it is free among pairs 1 .. found.
local function boxFoot(l, found, margin)
  local d, side = boxLine[l], boxSide[l]
  local tx, ty = 0.0, 0.0
  if side == 1 then tx = -d elseif side == 3 then tx = d elseif side == 2 then ty = -d else ty = d end
  return pushFree(tx, ty, found, margin), tx, ty
end

-- The push of a flat axis-parallel rectangle out of a list of them, or into it (a crate on a
-- floor of tiles or boxes), unscaled: every D is a box, and nearestFree's search comes down to
-- feet and crossings on the four lines of each box. Pair p's D is the open box -cLeft < tx <
-- cRight, -cTop < ty < cBottom (rectPairFaces' constants, the same numbers); its lines lifted
-- are left at tx = -(cLeft + lift), top at ty = -(cTop + lift), right at tx = cRight + lift and
-- bottom at ty = cBottom + lift, a foot where a line meets its axis, a crossing (+-x, +-y)
-- where a vertical line meets a horizontal one: the numbers nearestFree computes from the
-- faces. The pairs are the parts whose boxes overlap the rectangle's (overlapping, 1 ..
-- found); the feet are tried nearest first (then in line order) until one is free, then the
-- crossings of the lines nearer than it. As collideParts' loop does, the free point stands when
-- no other near part's box of D comes within near of it (the largest gaps of the scan tell
-- most calls at once) and it lies within half the window. Returns the push as collideParts
-- does, or nil when a part is not a rectangle, no candidate is free, or the point does not
-- stand: then collideParts' search decides. (bench/compound.lua's crate on the 20-part floor:
-- 1.21 -> 0.86 of its pair calls' time on LuaJIT, medians over 10 and 16 processes; Lua 5.4
-- 1,613 -> 1,373 VM instructions; bench/NOTES.md, session 13.)
local function boxPush(info, list, flat, listFirst, found, nearCount, leastGapX, leastGapY,
                       margin, window)
  local least = boxLines(info, list, flat, listFirst, found, margin)
  if not least then return nil end
  local low, lines, sides = least - 0.75 * margin, boxLine, boxSide
  -- The nearest foot and the second nearest (among equals the first by boxRank), in one pass
  -- of at least 8 steps (FAR past the lines: a constant count for one pair or two); usually one
  -- of them is free. Else the feet in order of reach, then of rank.
  local last = 4 * found
  local steps = last < 8 and 8 or last
  local foot, footReach, foot2, foot2Reach = 0, huge, 0, huge
  for l = 1, steps do
    local r = lines[l]
    if r >= low then
      if r < footReach or r == footReach and r < FAR
          and boxRank(l, info, flat, listFirst) < boxRank(foot, info, flat, listFirst) then
        foot, footReach, foot2, foot2Reach = l, r, foot, footReach
      elseif r < foot2Reach or r == foot2Reach and r < FAR
          and boxRank(l, info, flat, listFirst) < boxRank(foot2, info, flat, listFirst) then
        foot2, foot2Reach = l, r
      end
    end
  end
  local best, bestX, bestY = huge, 0.0, 0.0
  local free, tx, ty = false, 0.0, 0.0
  if footReach < FAR then free, tx, ty = boxFoot(foot, found, margin) end
  if free then
    best, bestX, bestY = footReach, tx, ty
  else
    if foot2Reach < FAR then free, tx, ty = boxFoot(foot2, found, margin) end
    if free then
      best, bestX, bestY = foot2Reach, tx, ty
    elseif foot2Reach < FAR then
      -- the feet up to here were tried: those before (triedReach, triedRank)
      local triedReach, triedRank = foot2Reach, boxRank(foot2, info, flat, listFirst)
      while true do
        local f, reach, rank = 0, huge, 0
        for l = 1, last do
          local r = lines[l]
          if r >= low and r <= reach and r >= triedReach then
            local lRank = boxRank(l, info, flat, listFirst)
            if (r < reach or lRank < rank) and (r > triedReach or lRank > triedRank) then
              f, reach, rank = l, r, lRank
            end
          end
        end
        if f == 0 then break end
        free, tx, ty = boxFoot(f, found, margin)
        if free then
          best, bestX, bestY = reach, tx, ty
          break
        end
        triedReach, triedRank = reach, rank
      end
    end
  end
  -- crossings of a vertical line and a horizontal one, both nearer than the best, in the order
  -- of nearestFree's (each line with those after it)
  local count = 0
  for l = 1, steps do
    if lines[l] < best then count = count + 1; nearLines[count] = l end
  end
  for a = 1, count - 1 do
    local f = nearLines[a]
    local x, side = lines[f], sides[f]
    if lines[f] < best then
      local vertical = side % 2
      if side <= 2 then x = -x end
      for b = a + 1, count do
        local g = nearLines[b]
        local y = lines[g]
        if lines[g] < best and sides[g] % 2 ~= vertical then
          if sides[g] <= 2 then y = -y end
          local cx, cy = x, y
          if vertical == 0 then cx, cy = y, x end
          local d = sqrt(cx * cx + cy * cy)
          -- below low not tried on PUC Lua, as nearestFree's crossings
          if d < best and (JIT or d >= low) and pushFree(cx, cy, found, margin) then
            best, bestX, bestY = d, cx, cy
          end
        end
      end
    end
  end
  if best == huge then return nil end
  local near, sx, sy = 4 * margin, bestX, bestY
  if not listFirst then sx, sy = -sx, -sy end   -- the box of D of flat - part: the tests on -t
  local reachX, reachY = sx < 0 and -sx or sx, sy < 0 and -sy or sy
  if 2 * ((reachX < reachY and reachY or reachX) + near) > window then return nil end
  if leastGapX - reachX < near or leastGapY - reachY < near then
    local boxes, fb = info.boxes, flat.boxes
    local fx0, fy0, fx1, fy1 = fb[1], fb[2], fb[3], fb[4]
    for q = 1, nearCount do
      local a = 4 * nearParts[q]
      local x0, y0, x1, y1 = boxes[a - 3], boxes[a - 2], boxes[a - 1], boxes[a]
      -- not a pair (its box and the rectangle's apart), and its box of D near t
      if not (x0 < fx1 and fx0 < x1 and y0 < fy1 and fy0 < y1) and (x0 - fx1) - sx < near
          and sx - (x1 - fx0) < near and (y0 - fy1) - sy < near and sy - (y1 - fy0) < near then
        return nil
      end
    end
  end
  return best, bestX + 0.0, bestY + 0.0
end

-- Whether some pair 1 .. np overlaps, decided exactly (on LuaJIT, after addPair found none that
-- overlaps for sure): as the boolean decides each pair.
local function pairsOverlap(fname, view1, shape1, view2, shape2, np, scaled)
  for p = 1, np do
    local i, j = pairPart1[p], pairPart2[p]
    local p1 = view1.copies and shape1[i] or shape1
    local p2 = view2.copies and shape2[j] or shape2
    if scaled then
      if overlapsConvex(fname, p1, p2) then return true end
    elseif pairOverlaps(view1, p1, i, view2, p2, j) then
      return true
    end
  end
  return false
end

-- The compound cases of the public functions: whether shape1 and shape2 (flat arrays or lists
-- of parts: parts1, parts2, as isParts tells, which the public functions did inline) overlap,
-- or with wantPush the least translation of shape2 out of shape1 as overlap, dx, dy, or false.
function collideParts(fname, shape1, shape2, wantPush, parts1, parts2)
  local view1, view2, found, nearCount, window, leastGapX, leastGapY
  if parts1 ~= parts2 then
    -- A list against a flat shape: the list's checks and its parts' box tests in one loop
    -- (partsOverlapping), so the flat shape's box first, its argument errors raised after the
    -- list's when the list comes first, as below.
    local list, flat, listName, flatName = shape1, shape2, "points1", "points2"
    if parts2 then list, flat, listName, flatName = shape2, shape1, "points2", "points1" end
    local flatSide, message = flatView(fname, flatName, flat, parts1 and flatView2 or flatView1)
    if not flatSide and parts2 then error(message, 3) end
    local info = preparedParts[list]
    local boxes = flatSide and flatSide.boxes
    -- the window for the pairs the search may add later: the flat shape's width plus height
    -- (pushes are mostly shorter than half that: see the loop after the search)
    window = flatSide and wantPush and (boxes[3] - boxes[1]) + (boxes[4] - boxes[2]) or 0
    if flatSide and info and info.count == #list then
      found, nearCount, leastGapX, leastGapY =
        partsOverlapping(info, list, boxes[1], boxes[2], boxes[3], boxes[4], window)
    end
    if found then
      info.fname, info.argname = fname, listName
    else
      info = listView(fname, listName, list)
      if not flatSide then error(message, 3) end
      found, nearCount, leastGapX, leastGapY =
        partsOverlapping(info, list, boxes[1], boxes[2], boxes[3], boxes[4], window)
    end
    if parts1 then view1, view2 = info, flatSide else view1, view2 = flatSide, info end
  else
    local message
    if parts1 then view1 = listView(fname, "points1", shape1)
    else
      view1, message = flatView(fname, "points1", shape1, flatView1)
      if not view1 then error(message, 3) end
    end
    if parts2 then view2 = listView(fname, "points2", shape2)
    else
      view2, message = flatView(fname, "points2", shape2, flatView2)
      if not view2 then error(message, 3) end
    end
  end
  local count1, count2 = view1.count, view2.count
  local boxes1, boxes2 = view1.boxes, view2.boxes
  local magnitude = max(view1.magnitude, view2.magnitude)
  callStamp = callStamp + 1
  if not wantPush then
    -- Each pair as addPair decides it, from the prepared normals (no faces); beyond the exact
    -- range, where the push scales (below), by the SAT engine, which rescales itself.
    local scaled = magnitude > EXACT_TOP or magnitude < 2^-400
    if found then   -- a list against a flat shape: the parts whose boxes overlap its box
      local list, flat = view2, view1
      if parts1 then list, flat = view1, view2 end
      local flatRect = flat.rects[1] ~= 0
      for f = 1, found do
        local k = overlapping[f]
        local i, j, p1, p2 = 1, k, shape1, shape2[k]
        if parts1 then i, j, p1, p2 = k, 1, shape1[k], shape2 end
        -- two axis-parallel rectangles are their boxes: boxes that overlap (strictly, as
        -- partsOverlapping tests them) are rectangles that overlap (the part's whole copy
        -- compared first, as for any pair: see preparedParts)
        if flatRect then
          if list.checked[k] ~= callStamp then checkCopy(list, k, parts1 and p1 or p2, 4) end
          if list.rects[k] ~= 0 then return true end
        end
        if scaled then
          if overlapsConvex(fname, p1, p2) then return true end
        elseif pairOverlaps(view1, p1, i, view2, p2, j) then
          return true
        end
      end
      return false
    end
    local i, j = 1, 0
    for _ = 1, count1 * count2 do   -- one loop over the pairs: see below
      if j == count2 then i, j = i + 1, 1 else j = j + 1 end
      local a, b = 4 * i, 4 * j
      if boxes1[a - 3] < boxes2[b - 1] and boxes2[b - 3] < boxes1[a - 1]
          and boxes1[a - 2] < boxes2[b] and boxes2[b - 2] < boxes1[a] then
        local p1, p2 = parts1 and shape1[i] or shape1, parts2 and shape2[j] or shape2
        if scaled then
          if overlapsConvex(fname, p1, p2) then return true end
        elseif pairOverlaps(view1, p1, i, view2, p2, j) then
          return true
        end
      end
    end
    return false
  end
  -- beyond the exact range, or so small that products would underflow, the faces are built on
  -- coordinates scaled by a power of two k into [2^100, 2^164]: there every product of two
  -- stays far from overflow (2^328) and underflow, and scaling back is exact
  local k = 1.0
  if magnitude > EXACT_TOP or magnitude < 2^-400 then k = powerScale(magnitude, 2^100, 2^164) end
  local extent = ((max(view1.right, view2.right) - min(view1.left, view2.left))
    + (max(view1.bottom, view2.bottom) - min(view1.top, view2.top))) * k
  local margin = 2^-47 * extent + 2^-52 * magnitude * k   -- delta above: 64 eps E + 2 eps S
  if found and found > 0 and k == 1 then
    local flat = parts1 and view2 or view1
    if flat.rects[1] ~= 0 then
      local best, tx, ty = boxPush(parts1 and view1 or view2, parts1 and shape1 or shape2, flat,
        parts1, found, nearCount, leastGapX, leastGapY, margin, window)
      if best then return best, tx, ty end
    end
  end
  -- The pairs whose boxes overlap go in now, marked in pairAdded; the others when their box of D
  -- comes near the best free point (below). A pair is numbered (i - 1) count2 + j; against a
  -- flat shape, by the list's part. One loop over the pairs, not two nested (on LuaJIT an inner
  -- loop of one part, as for a flat second shape, costs a trace exit for every part of the
  -- first).
  local np, top, hits = 0, 0, 0
  local added = pairAdded   -- a local: PUC Lua reads an upvalue by an extra instruction
  faceLift = 1.25 * margin   -- as nearestFree's lift
  nearestFoot, nearestReach, secondFoot, secondReach, seamReach = 0, FAR, 0, FAR, FAR
  seamX, seamY, feetKept, leastFree = FAR, FAR, 0, -FAR
  if found then
    for f = 1, found do
      local part = overlapping[f]
      added[part] = callStamp
      local overlaps
      if parts1 then
        np, top, overlaps = addPair(view1, shape1[part], part, view2, shape2, 1, k, np, top)
      else
        np, top, overlaps = addPair(view1, shape1, 1, view2, shape2[part], part, k, np, top)
      end
      hits = hits + overlaps
    end
  else
    local i, j = 1, 0
    for pair = 1, count1 * count2 do
      if j == count2 then i, j = i + 1, 1 else j = j + 1 end
      local a, b = 4 * i, 4 * j
      if boxes1[a - 3] < boxes2[b - 1] and boxes2[b - 3] < boxes1[a - 1]
          and boxes1[a - 2] < boxes2[b] and boxes2[b - 2] < boxes1[a] then
        added[pair] = callStamp
        local overlaps
        np, top, overlaps = addPair(view1, parts1 and shape1[i] or shape1, i, view2,
          parts2 and shape2[j] or shape2, j, k, np, top)
        hits = hits + overlaps
      end
    end
  end
  local scaled = k ~= 1   -- as the boolean's (powerScale's k is never 1 there)
  if hits == 0 and not (JIT and pairsOverlap(fname, view1, shape1, view2, shape2, np, scaled)) then
    return false
  end
  local best, tx, ty = nearestFree(np, margin)
  local near = 4 * margin   -- a box of D this far from t cannot hold it, widened by delta
  while true do
    -- every pair not in yet whose box of D comes within near of t (on every side; when no point
    -- is free yet, every pair whose parts have boxes) goes in
    local before = np
    local anyBox = best == huge
    if found then
      -- the list's part against the flat shape's box; the box of D is that of part - flat for a
      -- list first, of flat - part for a list second: the same tests on -t (exact negations)
      -- Only the parts near the flat shape (in nearParts) when t and near are at most half the
      -- window: a part outside it lies a window or more away along x or y, so its box of D
      -- lies farther than 2 (|t| + near) from the origin, more than near from t (the rounding
      -- errors of these sums are a few eps of the coordinates, below near).
      local listBoxes, fb = boxes1, boxes2
      local sx, sy = tx, ty
      if parts2 then listBoxes, fb, sx, sy = boxes2, boxes1, -tx, -ty end
      local fx0, fy0, fx1, fy1 = fb[1], fb[2], fb[3], fb[4]
      local reachX, reachY = sx < 0 and -sx or sx, sy < 0 and -sy or sy
      local reach = reachX
      if reachY > reach then reach = reachY end
      local useNear = not anyBox and 2 * (reach + near) <= window * k
      local last = useNear and nearCount or (parts1 and count1 or count2)
      -- None of the near parts when each one not in has its largest box gap g (the list's
      -- part's side less the flat shape's far side, as the tests below compute it), along x say,
      -- at least leastGapX, and leastGapX k - |sx| >= near: then g k - |sx| >= near fails the
      -- test on that side (the roundings are monotonic, and fl(a - b) = -fl(b - a)).
      if useNear and leastGapX * k - reachX >= near and leastGapY * k - reachY >= near then
        last = 0
      end
      for q = 1, last do
        local part = useNear and nearParts[q] or q
        local a = 4 * part
        if (anyBox and listBoxes[a - 3] <= listBoxes[a - 1]
            or (listBoxes[a - 3] - fx1) * k - sx < near and sx - (listBoxes[a - 1] - fx0) * k < near
            and (listBoxes[a - 2] - fy1) * k - sy < near and sy - (listBoxes[a] - fy0) * k < near)
            and added[part] ~= callStamp then
          added[part] = callStamp
          if parts1 then
            np, top = addPair(view1, shape1[part], part, view2, shape2, 1, k, np, top)
          else
            np, top = addPair(view1, shape1, 1, view2, shape2[part], part, k, np, top)
          end
        end
      end
    else
      local i, j = 1, 0
      for pair = 1, count1 * count2 do
        if j == count2 then i, j = i + 1, 1 else j = j + 1 end
        local a, b = 4 * i, 4 * j
        -- how far t lies beyond the box of D on each side, all four below near (an empty box,
        -- of huge minus any coordinate, never is)
        if (anyBox and boxes1[a - 3] <= boxes1[a - 1] and boxes2[b - 3] <= boxes2[b - 1]
            or (boxes1[a - 3] - boxes2[b - 1]) * k - tx < near
            and tx - (boxes1[a - 1] - boxes2[b - 3]) * k < near
            and (boxes1[a - 2] - boxes2[b]) * k - ty < near
            and ty - (boxes1[a] - boxes2[b - 2]) * k < near)
            and added[pair] ~= callStamp then
          added[pair] = callStamp
          np, top = addPair(view1, parts1 and shape1[i] or shape1, i, view2,
            parts2 and shape2[j] or shape2, j, k, np, top)
        end
      end
    end
    if np == before then break end
    -- If the best point is still free among the pairs added, it stays (see "Which pairs").
    if best == huge or not pushFree(tx, ty, np, margin) then best, tx, ty = nearestFree(np, margin) end
  end
  if best == huge then
    -- No candidate checked free (not expected): 2 E along any direction clears every D.
    best, tx, ty = 2 * extent, faceX[1] * 2 * extent, faceY[1] * 2 * extent
  end
  return best / k, tx / k + 0.0, ty / k + 0.0
end

-- Circles. A circle (c, r) whose centre moves by t meets part A exactly when c + t lies within
-- r of A: t inside D = (A - c) grown by r, a convex shape bounded by the edges' lines moved out
-- by r and arcs of radius r around the vertices. The least push is again the point nearest the
-- origin outside every D. On the boundary of the union it is the foot of the perpendicular on
-- a moved edge line, or the point of an arc nearest the origin (straight away from a vertex),
-- or a crossing of two of those pieces: line and line, line and arc, arc and arc. Each candidate
-- is kept when it is farther than r + delta from every part (the same margins as above, with
-- the circle's box in E and S), and the nearest kept one is the push.

local faceAX, faceAY, faceBX, faceBY = {}, {}, {}, {}   -- edge ends relative to the centre
local faceQ = {}                                        -- |faceAX, faceAY|: the vertex's distance

-- Appends the edges of part (normals: its outward unit normals, from its view) as faces relative
-- to the centre (cx, cy), all scaled by k: the outward unit normal, the signed distance faceC of
-- the edge's line from the centre (u.t - faceC is how far t lies beyond it) and the edge's ends.
-- Returns the last index.
local function addCircleFaces(part, n, normals, internal, cx, cy, k, top)
  local ax, ay = part[n - 1] + 0.0, part[n] + 0.0
  local kcx, kcy = cx * k, cy * k
  for i = 1, n - 1, 2 do
    local bx, by = part[i] + 0.0, part[i + 1] + 0.0
    if bx ~= ax or by ~= ay then   -- a repeated vertex gives no edge
      local ux, uy = normals[i], normals[i + 1]
      local qax, qay = ax * k - kcx, ay * k - kcy
      top = top + 1
      faceX[top], faceY[top], faceC[top] = ux, uy, ux * qax + uy * qay
      faceAX[top], faceAY[top], faceBX[top], faceBY[top] = qax, qay, bx * k - kcx, by * k - kcy
      faceQ[top] = sqrt(qax * qax + qay * qay)
      faceSeam[top] = internal[i]
    end
    ax, ay = bx, by
  end
  return top
end

-- Whether t lies at least `need` from the part whose faces are first .. last.
local function farFromPart(tx, ty, first, last, need)
  local beyond = -huge
  for f = first, last do beyond = max(beyond, faceX[f] * tx + faceY[f] * ty - faceC[f]) end
  if beyond >= need then return true end
  if beyond <= 0 then return false end   -- inside the part
  -- outside: the nearest point lies on an edge whose line t is beyond
  local needSq = need * need
  for f = first, last do
    if faceX[f] * tx + faceY[f] * ty - faceC[f] > 0 then
      local ax, ay = faceAX[f], faceAY[f]
      local ex, ey = faceBX[f] - ax, faceBY[f] - ay
      local along = ((tx - ax) * ex + (ty - ay) * ey) / (ex * ex + ey * ey)
      if along < 0 then along = 0 elseif along > 1 then along = 1 end
      local dx, dy = tx - (ax + along * ex), ty - (ay + along * ey)
      if dx * dx + dy * dy < needSq then return false end
    end
  end
  return true
end

-- Whether t lies at least need from every part 1 .. np.
local function circleFree(tx, ty, np, need)
  for p = 1, np do
    if not farFromPart(tx, ty, faceFirst[p], faceFirst[p + 1] - 1, need) then return false end
  end
  return true
end

-- Keeps candidate t when it is nearer than best and free.
local function tryCircle(tx, ty, np, need, best, bestX, bestY)
  local d = sqrt(tx * tx + ty * ty)
  if d < best and circleFree(tx, ty, np, need) then return d, tx, ty end
  return best, bestX, bestY
end

-- The nearest free candidate for a circle of (scaled) radius r among parts 1 .. np.
local function nearestFreeCircle(np, r, margin)
  local best, bestX, bestY = huge, 0.0, 0.0
  local last = faceFirst[np + 1] - 1
  local reach, need = r + 1.25 * margin, r + margin   -- lines and arcs moved out by lift
  for f = 1, last do   -- feet on the outer edges' moved lines
    local d = faceC[f] + reach
    if faceSeam[f] == 0 and abs(d) < best then
      best, bestX, bestY = tryCircle(faceX[f] * d, faceY[f] * d, np, need, best, bestX, bestY)
    end
  end
  for f = 1, last do   -- straight away from each vertex (the start of each edge)
    local q = faceQ[f]
    if q > 0 and abs(q - reach) < best then
      local s = 1 - reach / q
      best, bestX, bestY = tryCircle(faceAX[f] * s, faceAY[f] * s, np, need, best, bestX, bestY)
    end
  end
  -- Crossings. A point on a line lies at least |its constant| from the origin, one on an arc at
  -- least |q - reach|: pieces no nearer than the best so far are skipped.
  for f = 1, last do
    local c1, x1, y1 = faceC[f] + reach, faceX[f], faceY[f]
    local qx, qy = faceAX[f], faceAY[f]
    local lineNear, arcNear = abs(c1) < best, abs(faceQ[f] - reach) < best
    if lineNear or arcNear then
      for g = 1, last do
        local c2 = faceC[g] + reach
        if lineNear and g > f and abs(c2) < best then   -- line and line
          local x2, y2 = faceX[g], faceY[g]
          local det = x1 * y2 - y1 * x2
          if det ~= 0 then
            best, bestX, bestY = tryCircle((c1 * y2 - c2 * y1) / det, (x1 * c2 - x2 * c1) / det,
              np, need, best, bestX, bestY)
          end
        end
        local px, py = faceAX[g], faceAY[g]
        if abs(faceQ[g] - reach) < best then
          if lineNear then   -- line f and the arc around vertex g
            local h = c1 - (x1 * px + y1 * py)   -- from the vertex to the line, along the normal
            if abs(h) < reach then
              local w = sqrt(reach * reach - h * h)
              local mx, my = px + x1 * h, py + y1 * h
              best, bestX, bestY = tryCircle(mx - y1 * w, my + x1 * w, np, need, best, bestX, bestY)
              best, bestX, bestY = tryCircle(mx + y1 * w, my - x1 * w, np, need, best, bestX, bestY)
            end
          end
          if arcNear and g > f then   -- the arcs around vertices f and g
            local ex, ey = px - qx, py - qy
            local gap = sqrt(ex * ex + ey * ey)
            if gap > 0 and gap < 2 * reach then
              local w = sqrt(reach * reach - gap * gap / 4) / gap
              local mx, my = (qx + px) / 2, (qy + py) / 2
              best, bestX, bestY = tryCircle(mx - ey * w, my + ex * w, np, need, best, bestX, bestY)
              best, bestX, bestY = tryCircle(mx + ey * w, my - ex * w, np, need, best, bestX, bestY)
            end
          end
        end
      end
    end
  end
  return best, bestX, bestY
end

local circleAdded = {}   -- circleAdded[i] == callStamp: part i's faces are in

-- polygonCircleCollideV for a list of parts: overlap, dx, dy (move the circle) or false.
function collideCircleParts(fname, shape, cx, cy, r)
  checkFiniteNumber(cx, fname, "cx", 4)
  checkFiniteNumber(cy, fname, "cy", 4)
  checkFiniteNumber(r, fname, "radius", 4)
  if r < 0 then error(("%s: radius must not be negative, got %s"):format(fname, tostring(r)), 3) end
  local view = listView(fname, "points", shape)
  local count, turns, normals, internal = view.count, view.turns, view.normals, view.internal
  local left, top, right, bottom = view.left, view.top, view.right, view.bottom
  local boxes = view.boxes
  cx, cy, r = cx + 0.0, cy + 0.0, r + 0.0
  if r == 0 then return false end
  local magnitude = max(view.magnitude, abs(cx) + r, abs(cy) + r)
  callStamp = callStamp + 1
  local k = 1.0   -- scaled as for polygons (collideParts), for the same reason
  if magnitude > EXACT_TOP or magnitude < 2^-400 then k = powerScale(magnitude, 2^100, 2^164) end
  local extent = ((max(right, cx + r) - min(left, cx - r)) + (max(bottom, cy + r) - min(top, cy - r))) * k
  local margin = 2^-47 * extent + 2^-52 * magnitude * k   -- as for polygons: 64 eps E + 2 eps S
  local np, last, hit = 0, 0, false
  for i = 1, count do
    if boxes[4 * i - 3] < cx + r and cx - r < boxes[4 * i - 1]
        and boxes[4 * i - 2] < cy + r and cy - r < boxes[4 * i] then
      local part = shape[i]
      local n = #part
      if view.checked[i] ~= callStamp then checkCopy(view, i, part, 4) end
      if turns[i] ~= 0 then
        if circleCollision(part, n, cx, cy, r) then hit = true end
        np = np + 1
        faceFirst[np] = last + 1
        last = addCircleFaces(part, n, normals[i], internal[i], cx, cy, k, last)
        faceFirst[np + 1] = last + 1
      end
    end
  end
  if not hit then return false end
  -- The other parts go in when their box of D (the part's box less the centre, grown by r) comes
  -- within 4 delta of the best free point, round after round, as for polygons ("Which pairs"):
  -- farther, its part is more than r + delta from the moved centre.
  local best, tx, ty = nearestFreeCircle(np, r * k, margin)
  local near = 4 * margin
  while true do
    local before = np
    for i = 1, count do
      local a = 4 * i
      if boxes[a - 3] <= boxes[a - 1] and circleAdded[i] ~= callStamp
          and not (boxes[a - 3] < cx + r and cx - r < boxes[a - 1]
                   and boxes[a - 2] < cy + r and cy - r < boxes[a]) then
        -- how far t lies beyond the box of D, along x and along y (< 0 inside)
        local outX = max((boxes[a - 3] - cx - r) * k - tx, tx - (boxes[a - 1] - cx + r) * k)
        local outY = max((boxes[a - 2] - cy - r) * k - ty, ty - (boxes[a] - cy + r) * k)
        if best == huge or max(outX, outY) < near then
          circleAdded[i] = callStamp
          if view.checked[i] ~= callStamp then checkCopy(view, i, shape[i], 4) end
          if turns[i] ~= 0 then
            np = np + 1
            faceFirst[np] = last + 1
            last = addCircleFaces(shape[i], #shape[i], normals[i], internal[i], cx, cy, k, last)
            faceFirst[np + 1] = last + 1
          end
        end
      end
    end
    if np == before then break end
    -- More parts can only lengthen the least move: if the best point is still free, it stays.
    if best == huge or not circleFree(tx, ty, np, r * k + margin) then
      best, tx, ty = nearestFreeCircle(np, r * k, margin)
    end
  end
  if best == huge then
    -- No candidate checked free (not expected): 2 E along any direction clears every D.
    best, tx, ty = 2 * extent, 0.0, -2 * extent
  end
  return best / k, tx / k + 0.0, ty / k + 0.0
end

end
--------------------------------------------------------------------------------------------------
-- Moving and bounding shapes
--------------------------------------------------------------------------------------------------
do   -- this section's helpers are local to it (a chunk may hold at most 200 locals)
-- A shape here is a flat array {x1, y1, ...} or a list of convex parts {part1, part2, ...}, each
-- part a flat array; isParts (Compound shapes) tells them apart by the first entry.

local sin, cos = math.sin, math.cos

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
  if isParts(points) then
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
  if isParts(points) then
    local count = checkParts(points, fname, 3)
    checkFiniteNumber(dx, fname, "dx")
    checkFiniteNumber(dy, fname, "dy")
    out = checkOut(out, fname)
    for k = 1, count do
      local part = points[k]
      translateInto(part, #part, dx, dy, outPart(out, k, fname))
    end
    trim(out, count)
  else
    local n = checkPoints(points, fname)
    checkFiniteNumber(dx, fname, "dx")
    checkFiniteNumber(dy, fname, "dy")
    out = checkOut(out, fname)
    translateInto(points, n, dx, dy, out)
  end
  return out
end

-- Adds the vertices of points[1..n] to the running sums (sumX, sumY) and count m.
local function addVertices(points, n, sumX, sumY, m)
  for i = 1, n - 1, 2 do sumX, sumY = sumX + points[i], sumY + points[i + 1] end
  return sumX, sumY, m + n / 2
end

-- The default pivot of polygonRotate: the area centroid; for a list of parts the centroids
-- weighted by the parts' areas; the vertex mean when there is no area at all; (0, 0) for no points.
local function pivotOf(points, parts, count)
  local sumX, sumY, m = 0.0, 0.0, 0
  if not parts then
    local cx, cy = polygon.polygonCentroid(points)
    if cx then return cx, cy end
    sumX, sumY, m = addVertices(points, count, sumX, sumY, m)
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
      sumX, sumY, m = addVertices(part, #part, sumX, sumY, m)
    end
  end
  if m == 0 then return 0.0, 0.0 end
  return sumX / m, sumY / m
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
  local parts = isParts(points)
  local count
  if parts then count = checkParts(points, fname, 3) else count = checkPoints(points, fname) end
  checkFiniteNumber(angle, fname, "angle")
  if ox ~= nil or oy ~= nil then
    checkFiniteNumber(ox, fname, "ox")
    checkFiniteNumber(oy, fname, "oy")
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
  -- not a tail call: after a tail call to setmetatable (a built-in with side effects) LuaJIT
  -- had no snapshot for the return past the frame where validate's loop trace began, and every
  -- trace leaving that loop aborted ("NYI: return to lower frame")
  local p = setmetatable({ points = points }, Polygon)
  return p
end

--- Polygon.new(points), also Polygon(points): validates, then wraps points.
function Polygon.new(points)
  local p = newPolygon(points, 2)   -- not a tail call, so the error level is the same everywhere
  return p
end

--- Whether (x, y) lies inside, as polygonContains.
function Polygon:contains(x, y)
  local points = self.points
  -- polygonContains' checks, naming this method (there they pass again)
  local n = type(points) == "table" and #points or -1
  if n % 2 ~= 0 or type(x) ~= "number" or type(y) ~= "number" or x - x ~= 0 or y - y ~= 0 then
    checkQuery("Polygon:contains", points, x, y, 3)
  end
  local inside = polygonContains(points, x, y)
  return inside
end

setmetatable(Polygon, { __call = function(_, points)
  local p = newPolygon(points, 2)
  return p
end })
polygon.Polygon = Polygon

return polygon
