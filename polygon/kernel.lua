-- polygon/kernel.lua: the exact arithmetic every sign of the library comes from: error-free
-- transformations, the scratch expansion, the filtered cross product and area sign, the shoelace
-- sums. It relies on nothing but math.


local abs, huge, min, max, sqrt = math.abs, math.huge, math.min, math.max, math.sqrt

local M = {}


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
-- computing the same numbers side by side, XJit and XPuc, one line choosing by JIT below
-- (spec/bodies_sat_spec.lua runs both on every interpreter); the LuaJIT bodies keep few values
-- alive across their loops, since a side trace leaving a loop must take them all over in
-- registers, and avoid short inner loops: a loop of a few steps (a polygon's vertices) often
-- fails to become a trace of its own, and other traces then copy it unrolled, with a side exit
-- for every other polygon size (so the SAT's hot paths read up to 8 vertices in one expression,
-- the last one repeated for fewer, and run flat over (edge, vertex) pairs beyond). The PUC
-- bodies save instructions instead: the two-sided SAT walks both polygons' edges at once
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

-- Empties the scratch expansion, for the exact tests of other files built on it.
local function expClear() expLen = 0 end

-- The number of components of the scratch expansion.
local function expLength() return expLen end

-- Copies the scratch expansion into `into` (a caller's scratch table); returns its length.
local function expCopy(into)
  for i = 1, expLen do into[i] = expansion[i] end
  return expLen
end

-- Adds the double b to the expansion exactly (Shewchuk's Grow-Expansion, zeros eliminated).
-- On LuaJIT without a branch inside: each part is written at k + 1 and k counts it when it is
-- not 0, so that a trace copying this loop has no side exit for a zero part (such exits fail
-- to compile: "NYI: register coalescing too complex"). min(|h| 2^1000 2^1000, 1) is 0 for a
-- zero and 1 for any other double. A NaN part (only input outside the exact range makes one)
-- counts too, as on PUC Lua, and never reaches k: LuaJIT's min returns its second argument
-- when either is NaN (on x64 in the interpreter and in traces; spec/non_finite_hard_spec.lua's
-- wild coordinates make NaN parts, and with min(1, ...) k became NaN).
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

-- The largest two components of the scratch expansion after compressing it: a double double
-- within order eps^2 of its value.
local function expTopTwo()
  local hi = expCompress()
  if expLen >= 2 then return hi, expansion[expLen - 1] end
  return hi, 0.0
end

-- The exact (u1 - u0) x (v1 - v0) of the coordinates times s (a power of two, so that no
-- product overflows or underflows) into the scratch expansion, compressed; returns its largest
-- component (within an ulp of the value). For the exact fractions of rays and casts.
local function expCrossScaled(u0x, u0y, u1x, u1y, v0x, v0y, v1x, v1y, s)
  local axh, axl = twoDiff(u1x * s, u0x * s)
  local ayh, ayl = twoDiff(u1y * s, u0y * s)
  local bxh, bxl = twoDiff(v1x * s, v0x * s)
  local byh, byl = twoDiff(v1y * s, v0y * s)
  expLen = 0
  expAddProduct(axh, byh); expAddProduct(axh, byl); expAddProduct(axl, byh); expAddProduct(axl, byl)
  expAddProduct(-ayh, bxh); expAddProduct(-ayh, bxl); expAddProduct(-ayl, bxh)
  expAddProduct(-ayl, bxl)
  return expCompress()
end

-- Double doubles, for the fractions of rays and casts and the nearest points' distances.
-- a + b as hi + lo exactly (Knuth's TwoSum).
local function twoSum(a, b)
  local x = a + b
  local bv = x - a
  local av = x - bv
  return x, (a - av) + (b - bv)
end

-- The square root of hi + lo > 0 as a double double (one Newton step).
local function sqrtDD(hi, lo)
  local root = sqrt(hi)
  local sh, sl = twoProduct(root, root)
  return twoSum(root, (((hi - sh) - sl) + lo) / (2 * root))
end

-- (xh + xl) / (yh + yl) to within eps, plus order eps^2: the quotient corrected once.
local function divideDD(xh, xl, yh, yl)
  local q = xh / yh
  local ph, pl = twoProduct(q, yh)
  return q + ((((xh - ph) - pl) + xl) - q * yl) / yh
end

-- u x v = ux vy - uy vx from double-double differences (each coordinate hi + lo, as twoDiff
-- gives it), for quotientDD: hi, the rounded difference of the two main products (TwoProduct,
-- then TwoDiff, exact); lo, the rest to first order (the products' low parts and the cross
-- terms; what is dropped is below 2^-100 size); size = |ux vy| + |uy vx| of the main products.
-- The callers split the differences themselves, so one shared by two cross products (the ray's
-- edge in raycast.lua) is split once.
local function crossDD(uxh, uxl, uyh, uyl, vxh, vxl, vyh, vyl)
  local lh, ll = twoProduct(uxh, vyh)
  local rh, rl = twoProduct(uyh, vxh)
  local h, h0 = twoDiff(lh, rh)
  local lo = h0 + (ll - rl) + ((uxh * vyl + uxl * vyh) - (uyh * vxl + uyl * vxh))
  return h, lo, abs(lh) + abs(rh)
end

-- (nh + nl) / (dh + dl) for a numerator and a denominator each made as a difference of two
-- products (nh the rounded difference, nl the rest, numSize the sum of the products' sizes;
-- likewise the denominator): nil where cancellation or the range leaves the double doubles
-- untrustworthy (the caller takes exact expansions then).
local function quotientDD(nh, nl, numSize, dh, dl, denSize)
  if not (numSize < 2^30 * abs(nh) and denSize < 2^30 * abs(dh) and numSize > 2^-800
      and denSize > 2^-800 and numSize < 2^900 and denSize < 2^900) then
    return nil
  end
  local t = nh / dh
  local th, tl = twoProduct(t, dh)
  return t + ((((nh - th) - tl) + nl) - t * dl) / dh   -- nh - th exact (Sterbenz)
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
-- every value alive there, and with the eight parts too (and the caller's values) it needs more
-- registers than there are ("NYI: register coalescing too complex", retried on every call).
local crossExact
do
  local BOUND_B = (2 + 12 * EPS) * EPS             -- Shewchuk's ccwerrboundB
  local BOUND_C = (9 + 64 * EPS) * EPS * EPS       -- ccwerrboundC
  local BOUND_RESULT = (3 + 8 * EPS) * EPS         -- resulterrbound

  -- The last stage: the sign of the sum of the eight products of the differences' parts, as an
  -- expansion. The factors wait in a table, so that a trace running this inline keeps only the
  -- loop's index in registers at the exits of expAdd's loops, not the eight parts: with them
  -- (and a calling loop's values) the side traces there fail to compile, "NYI: register
  -- coalescing too complex" at expAdd's end.
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
    -- operations (TwoDiff's written out: a call costs more than its body on PUC Lua) where stage
    -- B below takes four TwoDiffs, two TwoProducts and a Two-Two-Diff. (Not on LuaJIT, which
    -- compiles stage B inline: there the branches' side traces, inheriting the eight parts, fail
    -- to compile, "NYI: register coalescing too complex".)
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
-- Two bodies computing the same test, side by side.
-- LuaJIT's: abs is one instruction, and one branch leaves a calling loop one side exit.
local function crossJit(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1)
  local l = ((ux1 + 0.0) - ux0) * ((vy1 + 0.0) - vy0)
  local r = ((uy1 + 0.0) - uy0) * ((vx1 + 0.0) - vx0)
  local det = l - r
  if abs(det) >= CROSS_BOUND * (abs(l) + abs(r)) then return det end
  return crossExact(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1)
end

-- PUC Lua's: the signs of l and r compared first, as abs is a call there.
local function crossPuc(ux0, uy0, ux1, uy1, vx0, vy0, vx1, vy1)
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

local cross = JIT and crossJit or crossPuc

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
-- exits would be side traces of this loop, and with those of the code after it they pass
-- LuaJIT's 100 side traces per loop, after which whole calls run in the interpreter. The PUC
-- interpreters call min and max as functions, so there comparisons are faster, and the area's
-- sign is decided in the same call: turnAndBounds, below. LuaJIT's xSq and dSq up to 8
-- vertices bound the sums by the box, as turnAndBounds does, which changes only how often
-- areaSignOf needs its exact path, never its sign.
-- Beyond 8 vertices a loop. The first vertex and the previous one are read from points in
-- every step (LuaJIT hoists the first and forwards the previous): only the seven sums cross
-- from one step to the next, so a side trace that leaves the loop midway inherits few values
-- (see lineShortfall).
local function shoelaceBoundsLoop(points, n)
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
local function shoelaceBounds(points, n)
  if n > 16 then
    local sum, xSq, dSq, xmin, xmax, ymin, ymax = shoelaceBoundsLoop(points, n)
    return sum, xSq, dSq, xmin, xmax, ymin, ymax
  end
  -- Up to 8 vertices no loop: a loop of 3 to 8 steps is a trace of its own whose entry and
  -- exit cost more than its steps. Vertices 2 to 8, the last one repeated for fewer (its edges
  -- add 0 to the sum); the sum in pairs, as a tree, where the loop's is a chain.
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
local function turnAndBounds(points, n)
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

M.CROSS_BOUND = CROSS_BOUND
M.shoelaceExact = shoelaceExact
M.expSign = expSign
M.expCompress = expCompress
M.JIT = JIT
M.SPLITTER = SPLITTER
M.cross = cross
M.crossJit = crossJit
M.crossPuc = crossPuc
M.expClear = expClear
M.expAddTriple = expAddTriple
M.expLength = expLength
M.expTopTwo = expTopTwo
M.expCrossScaled = expCrossScaled
M.twoSum = twoSum
M.sqrtDD = sqrtDD
M.divideDD = divideDD
M.quotientDD = quotientDD
M.crossDD = crossDD
M.expCopy = expCopy
M.powerScale = powerScale
M.largestMagnitude = largestMagnitude
M.EPS = EPS
M.crossExact = crossExact
M.shoelaceBounds = shoelaceBounds
M.holdsNonFinite = holdsNonFinite
M.areaSignOf = areaSignOf
M.turnAndBounds = turnAndBounds
M.EXACT_TOP = EXACT_TOP
M.twoDiff = twoDiff
M.twoProduct = twoProduct
M.expAddSquare = expAddSquare
M.expAddProduct = expAddProduct
M.expansion = expansion
M.shoelace = shoelace
M.areaSign = areaSign

return M
