-- bench/exact.lua: exact answers for the benchmark's error columns.
--
-- Every sign is decided on floating-point expansions (a value held as a sum of doubles whose
-- bits do not overlap, after Shewchuk's "Adaptive Precision Floating-Point Arithmetic"), so it is
-- the sign exact real arithmetic gives on the input doubles. Values that involve a square root
-- (depths and displacements) are formed from exact numerators in double-double, about 1e-30
-- relative, far below the errors being measured. A cheap floating-point filter with a proven
-- error bound answers the easy cases and leaves only the close ones to the expansions.
--
-- Shares no code with polygon.lua. Valid while products neither overflow nor underflow, which
-- holds for every benchmark input (|coordinates| <= 2e12, nonzero differences >= 1e-100).
local abs, sqrt, floor, log, huge = math.abs, math.sqrt, math.floor, math.log, math.huge

local exact = {}

local EPS = 2 ^ -53                    -- unit roundoff of a double
local SPLITTER = 134217729.0           -- 2^27 + 1, splits a double into two 26-bit halves
local ORIENT_BOUND = (3 + 16 * EPS) * EPS  -- Shewchuk's ccwerrboundA
local PROJ_BOUND = 8 * EPS             -- bound of (a - b) * n + (c - d) * m against its magnitude
local TINY = 2 ^ -1074

---------------------------------------------------------------------------------------------
-- Error-free transformations
---------------------------------------------------------------------------------------------
local function twoSum(a, b)
  local s = a + b
  local bv = s - a
  local av = s - bv
  return s, (a - av) + (b - bv)
end

local function twoDiff(a, b)
  local s = a - b
  local bv = a - s
  local av = s + bv
  return s, (a - av) + (bv - b)
end

local function twoProd(a, b)
  local p = a * b
  local c = SPLITTER * a
  local ah = c - (c - a)
  local al = a - ah
  c = SPLITTER * b
  local bh = c - (c - b)
  local bl = b - bh
  return p, al * bl - (((p - ah * bh) - al * bh) - ah * bl)
end
exact.twoSum, exact.twoDiff, exact.twoProd = twoSum, twoDiff, twoProd

---------------------------------------------------------------------------------------------
-- Expansions: arrays of nonoverlapping doubles, smallest magnitude first, no zeros; {} is 0.
---------------------------------------------------------------------------------------------
local function grow(e, b)
  local h, k, q = {}, 0, b
  for i = 1, #e do
    local s, err = twoSum(q, e[i])
    if err ~= 0 then k = k + 1; h[k] = err end
    q = s
  end
  if q ~= 0 then h[k + 1] = q end
  return h
end

local function add(e, f)
  local h = e
  for j = 1, #f do h = grow(h, f[j]) end
  return h
end

local function neg(e)
  local h = {}
  for i = 1, #e do h[i] = -e[i] end
  return h
end

local function sub(e, f) return add(e, neg(f)) end

local function scale(e, b)
  local h, k = {}, 0
  if #e == 0 or b == 0 then return h end
  local q, t = twoProd(e[1], b)
  if t ~= 0 then k = k + 1; h[k] = t end
  for i = 2, #e do
    local p1, p0 = twoProd(e[i], b)
    local s
    s, t = twoSum(q, p0)
    if t ~= 0 then k = k + 1; h[k] = t end
    q, t = twoSum(p1, s)
    if t ~= 0 then k = k + 1; h[k] = t end
  end
  if q ~= 0 then h[k + 1] = q end
  return h
end

local function mul(e, f)
  local h = {}
  for j = 1, #f do h = add(h, scale(e, f[j])) end
  return h
end

local function diffE(a, b)
  local s, t = twoDiff(a, b)
  if t ~= 0 then return { t, s } elseif s ~= 0 then return { s } end
  return {}
end

local function sign(e)
  local top = e[#e]
  if not top then return 0 elseif top > 0 then return 1 end
  return -1
end

local function approx(e)
  local s = 0
  for i = 1, #e do s = s + e[i] end
  return s
end

-- Shewchuk's compress: same value, fewer and larger components.
local function compress(e)
  local m = #e
  if m < 2 then return e end
  local g, bottom, q = {}, m, e[m]
  for i = m - 1, 1, -1 do
    local s, t = twoSum(q, e[i])
    if t ~= 0 then g[bottom] = s; bottom = bottom - 1; q = t else q = s end
  end
  g[bottom] = q
  local h, top = {}, 0
  for i = bottom + 1, m do
    local s, t = twoSum(g[i], q)
    if t ~= 0 then top = top + 1; h[top] = t end
    q = s
  end
  if q ~= 0 then h[top + 1] = q end
  return h
end

-- Double-double (hi, lo) nearest the expansion's value, about 2^-105 relative.
local function toDD(e)
  e = compress(e)
  local m = #e
  if m == 0 then return 0, 0 end
  local lo = 0
  for i = 1, m - 1 do lo = lo + e[i] end
  return twoSum(e[m], lo)
end

exact.grow, exact.add, exact.sub, exact.neg, exact.scale, exact.mul = grow, add, sub, neg, scale, mul
exact.diff, exact.sign, exact.approx, exact.compress, exact.toDD = diffE, sign, approx, compress, toDD

-- A growing sum kept in place (acc.n components), compressed now and then.
local function accNew() return { n = 0 } end

local function accAdd(acc, b)
  if b == 0 then return end
  local n, k, q = acc.n, 0, b
  for i = 1, n do
    local e = acc[i]
    local s = q + e
    local bv = s - q
    local err = (q - (s - bv)) + (e - bv)
    q = s
    if err ~= 0 then k = k + 1; acc[k] = err end
  end
  if q ~= 0 then k = k + 1; acc[k] = q end
  acc.n = k
  if k > 12 then
    local c = {}
    for i = 1, k do c[i] = acc[i] end
    c = compress(c)
    for i = 1, #c do acc[i] = c[i] end
    acc.n = #c
  end
end

local function accProd(acc, a, b)
  local p, e = twoProd(a, b)
  accAdd(acc, e)
  accAdd(acc, p)
end

local function accValue(acc)
  local e = {}
  for i = 1, acc.n do e[i] = acc[i] end
  return compress(e)
end

---------------------------------------------------------------------------------------------
-- Double-double helpers and error measures
---------------------------------------------------------------------------------------------
local function ddDiv(ah, al, bh, bl)
  local q1 = ah / bh
  local p, pe = twoProd(q1, bh)
  local r = ((ah - p) - pe + al) - q1 * bl
  return twoSum(q1, r / bh)
end

local function ddMul(ah, al, bh, bl)
  local p, pe = twoProd(ah, bh)
  return twoSum(p, pe + (ah * bl + al * bh))
end

local function ddSqrt(ah, al)
  if ah <= 0 then return 0, 0 end
  local s = sqrt(ah)
  local p, pe = twoProd(s, s)
  return twoSum(s, ((ah - p) - pe + al) / (2 * s))
end

local function ddAdd(ah, al, bh, bl)
  local s, e = twoSum(ah, bh)
  return twoSum(s, e + al + bl)
end
exact.ddDiv, exact.ddMul, exact.ddSqrt, exact.ddAdd = ddDiv, ddMul, ddSqrt, ddAdd

local LOG2 = log(2)
-- Unit in the last place of |x| (the gap above the largest power of two <= |x|).
local function ulp(x)
  x = abs(x)
  if x == 0 or x ~= x then return TINY end
  if x == huge then return huge end
  local p = 2 ^ floor(log(x) / LOG2)
  if p > x then p = p / 2 elseif p * 2 <= x then p = p * 2 end
  if p < 2 ^ -1022 then return TINY end
  return p * EPS * 2
end
exact.ulp = ulp

-- |got - value of e| in ulps of the value (0 if both are 0, huge if only e is 0).
local function ulpError(e, got)
  local ref = approx(compress(e))
  local d = approx(compress(grow(neg(e), got)))
  if d == 0 then return 0 end
  if ref == 0 then return huge end
  return abs(d) / ulp(ref)
end
exact.ulpError = ulpError

-- |got - (hi + lo)| / |hi + lo|
local function relError(got, hi, lo)
  if hi == 0 then return got == 0 and 0 or huge end
  return abs((got - hi) - lo) / abs(hi)
end
exact.relError = relError

---------------------------------------------------------------------------------------------
-- Signs of small determinants
---------------------------------------------------------------------------------------------
-- sign of (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
local function orient(ax, ay, bx, by, cx, cy)
  local l = (bx - ax) * (cy - ay)
  local r = (by - ay) * (cx - ax)
  local det = l - r
  local bound = ORIENT_BOUND * (abs(l) + abs(r))
  if det > bound then return 1 elseif -det > bound then return -1 end
  return sign(sub(mul(diffE(bx, ax), diffE(cy, ay)), mul(diffE(by, ay), diffE(cx, ax))))
end
exact.orient = orient

---------------------------------------------------------------------------------------------
-- Measures
---------------------------------------------------------------------------------------------
-- Twice the signed area, sum of x[i] * y[i+1] - x[i+1] * y[i] (positive: "cw" on screen).
function exact.twiceArea(points)
  local n = #points
  local acc = accNew()
  local px, py = points[n - 1], points[n]
  for i = 1, n - 1, 2 do
    local qx, qy = points[i], points[i + 1]
    accProd(acc, px, qy)
    accProd(acc, -qx, py)
    px, py = qx, qy
  end
  return accValue(acc)
end

-- Exact sums for the area centroid: twice the area and the centroid numerators, where
-- centroid = (nx, ny) / (3 * twiceArea).
function exact.centroidSums(points)
  local n = #points
  local area, sx, sy = accNew(), accNew(), accNew()
  local px, py = points[n - 1], points[n]
  for i = 1, n - 1, 2 do
    local qx, qy = points[i], points[i + 1]
    local p1, e1 = twoProd(px, qy)
    local p2, e2 = twoProd(qx, py)
    accAdd(area, e1); accAdd(area, -e2); accAdd(area, p1); accAdd(area, -p2)
    local c = { e1, -e2, p1, -p2 }
    for k = 1, 4 do
      local ck = c[k]
      accProd(sx, px, ck); accProd(sx, qx, ck)
      accProd(sy, py, ck); accProd(sy, qy, ck)
    end
    px, py = qx, qy
  end
  return accValue(area), accValue(sx), accValue(sy)
end

function exact.coordinateSums(points)
  local sx, sy = accNew(), accNew()
  for i = 1, #points - 1, 2 do
    accAdd(sx, points[i])
    accAdd(sy, points[i + 1])
  end
  return accValue(sx), accValue(sy)
end

-- ulps between got and s / n (exact sum s, n a small integer)
function exact.meanError(s, n, got)
  local p, pe = twoProd(got, n)
  local d = approx(compress(sub(grow({ pe }, p), s))) / n
  local ref = approx(s) / n
  if d == 0 then return 0 end
  if ref == 0 then return huge end
  return abs(d) / ulp(ref)
end

-- ulps between got and num / (3 * twice)
function exact.centroidError(twice, num, got)
  local den = scale(twice, 3)
  local d = approx(compress(sub(scale(den, got), num))) / approx(den)
  local ref = approx(num) / approx(den)
  if d == 0 then return 0 end
  if ref == 0 then return huge end
  return abs(d) / ulp(ref)
end

function exact.winding(points)
  if #points < 6 then return nil end
  local s = sign(exact.twiceArea(points))
  if s > 0 then return "cw" elseif s < 0 then return "ccw" end
  return nil
end

-- Which half-turn a nonzero direction lies in: 0 for angles [0, pi), 1 for [pi, 2 pi).
local function half(dx, dy)
  if dy > 0 or (dy == 0 and dx > 0) then return 0 end
  return 1
end

local function sgn(v) if v > 0 then return 1 elseif v < 0 then return -1 end return 0 end

function exact.polygonType(points)
  local xs, ys, m = {}, {}, 0
  for i = 1, #points - 1, 2 do
    local x, y = points[i], points[i + 1]
    if m == 0 or x ~= xs[m] or y ~= ys[m] then m = m + 1; xs[m], ys[m] = x, y end
  end
  while m > 1 and xs[m] == xs[1] and ys[m] == ys[1] do m = m - 1 end
  if m < 3 then return nil end
  local flat = true
  for k = 3, m do
    if orient(xs[1], ys[1], xs[2], ys[2], xs[k], ys[k]) ~= 0 then flat = false; break end
  end
  if flat then return nil end
  local turn = 0
  for i = 1, m do
    local a = i == 1 and m or i - 1
    local c = i == m and 1 or i + 1
    local o = orient(xs[a], ys[a], xs[i], ys[i], xs[c], ys[c])
    if o == 0 then
      -- parallel edges: doubling back (a spike) is not convex. Component signs are exact.
      local ux, uy = sgn(xs[i] - xs[a]), sgn(ys[i] - ys[a])
      local vx, vy = sgn(xs[c] - xs[i]), sgn(ys[c] - ys[i])
      if ux * vx < 0 or uy * vy < 0 then return "concave" end
    elseif turn == 0 then
      turn = o
    elseif o ~= turn then
      return "concave"
    end
  end
  -- All turns agree; convex only if the edge direction goes round exactly once.
  local wraps = 0
  for i = 1, m do
    local j = i == m and 1 or i + 1
    local k = j == m and 1 or j + 1
    local h1 = half(xs[j] - xs[i], ys[j] - ys[i])
    local h2 = half(xs[k] - xs[j], ys[k] - ys[j])
    if (turn > 0 and h1 == 1 and h2 == 0) or (turn < 0 and h1 == 0 and h2 == 1) then
      wraps = wraps + 1
    end
  end
  return wraps == 1 and "convex" or "concave"
end

-- Franklin's rule with the tutorial's half-open boundary, decided exactly.
function exact.contains(points, x, y)
  local n = #points
  if n < 6 then return false end
  local x1, y1 = points[n - 1], points[n]
  local inside = false
  for i = 1, n - 1, 2 do
    local x2, y2 = points[i], points[i + 1]
    if (y1 >= y) ~= (y2 >= y) then
      local o = orient(x1, y1, x2, y2, x, y)
      if (y2 > y1 and o >= 0) or (y2 < y1 and o <= 0) then inside = not inside end
    end
    x1, y1 = x2, y2
  end
  return inside
end

---------------------------------------------------------------------------------------------
-- Projections and separating axes
---------------------------------------------------------------------------------------------
-- exact (px - rx) * nx + (py - ry) * ny for expansion normals
local function projE(px, py, rx, ry, nxE, nyE)
  return add(mul(diffE(px, rx), nxE), mul(diffE(py, ry), nyE))
end

local function exactRange(points, rx, ry, nxE, nyE)
  local lo, hi
  for i = 1, #points - 1, 2 do
    local s = projE(points[i], points[i + 1], rx, ry, nxE, nyE)
    if not lo or sign(sub(s, lo)) < 0 then lo = s end
    if not hi or sign(sub(s, hi)) > 0 then hi = s end
  end
  return lo, hi
end

-- Float range with bounds: the exact min lies in [minLo, minHi], the exact max in [maxLo, maxHi].
local function floatRange(points, rx, ry, nx, ny)
  local minLo, minHi, maxLo, maxHi = huge, huge, -huge, -huge
  for i = 1, #points - 1, 2 do
    local a = (points[i] - rx) * nx
    local b = (points[i + 1] - ry) * ny
    local s = a + b
    local e = PROJ_BOUND * (abs(a) + abs(b))
    local lo, hi = s - e, s + e
    if lo < minLo then minLo = lo end
    if hi < minHi then minHi = hi end
    if lo > maxLo then maxLo = lo end
    if hi > maxHi then maxHi = hi end
  end
  return minLo, minHi, maxLo, maxHi
end

-- min and max of (px - x) * nx + (py - y) * ny for given doubles, as expansions
function exact.projectRange(points, x, y, nx, ny)
  return exactRange(points, x, y, { nx }, { ny })
end

-- Axes of a polygon's edges: reference vertex, float normal, exact normal (zero edges skipped).
local function edgeAxes(points, list)
  local n = #points
  local x1, y1 = points[n - 1], points[n]
  for i = 1, n - 1, 2 do
    local x2, y2 = points[i], points[i + 1]
    if x1 ~= x2 or y1 ~= y2 then
      list[#list + 1] = { rx = x2, ry = y2, nx = y2 - y1, ny = x1 - x2,
                          nxE = diffE(y2, y1), nyE = diffE(x1, x2) }
    end
    x1, y1 = x2, y2
  end
  return list
end

local function axisLength(ax)
  if not ax.lenHi then
    local h, l = toDD(add(mul(ax.nxE, ax.nxE), mul(ax.nyE, ax.nyE)))
    ax.lenHi, ax.lenLo = ddSqrt(h, l)
  end
  return ax.lenHi, ax.lenLo
end

-- Unit displacement (dd) along dir * n / |n| times depth (dd).
local function displacement(ax, dir, dh, dl)
  local lh, ll = axisLength(ax)
  local nxh, nxl = toDD(ax.nxE)
  local nyh, nyl = toDD(ax.nyE)
  local ux, uxl = ddDiv(nxh, nxl, lh, ll)
  local uy, uyl = ddDiv(nyh, nyl, lh, ll)
  local xh, xl = ddMul(ux, uxl, dh, dl)
  local yh, yl = ddMul(uy, uyl, dh, dl)
  return dir * xh, dir * xl, dir * yh, dir * yl
end

local function finishCandidates(cands)
  -- cands: { depthHi, depthLo, ax, dirs }; keep those tied (1e-12 relative) with the least.
  local best = huge
  for i = 1, #cands do if cands[i][1] < best then best = cands[i][1] end end
  local out = {}
  for i = 1, #cands do
    local c = cands[i]
    if c[1] <= best * (1 + 1e-12) + 1e-300 then
      for _, dir in ipairs(c[4]) do
        local xh, xl, yh, yl = displacement(c[3], dir, c[1], c[2])
        out[#out + 1] = { xh, xl, yh, yl }
      end
    end
  end
  local depthHi, depthLo = huge, 0
  for i = 1, #cands do
    if cands[i][1] < depthHi then depthHi, depthLo = cands[i][1], cands[i][2] end
  end
  return depthHi, depthLo, out
end

-- Reference for polygonCollidesWith(V) (p2's axes ignored) and polygonsCollide(V) (both).
-- Returns collides (exact boolean) and, when true, depth (dd) and the list of acceptable
-- displacements of p2 out of p1 (dd components; several only when axes tie).
function exact.sat(p1, p2, both)
  local axes = edgeAxes(p1, {})
  if both then edgeAxes(p2, axes) end
  if #axes == 0 or #p1 < 6 or #p2 < 6 then return false end
  local float = {}
  for k = 1, #axes do
    local ax = axes[k]
    local a1, b1, c1, d1 = floatRange(p1, ax.rx, ax.ry, ax.nx, ax.ny)
    local a2, b2, c2, d2 = floatRange(p2, ax.rx, ax.ry, ax.nx, ax.ny)
    local separated
    if d1 <= a2 or a1 >= d2 then
      separated = true
    elseif c1 > b2 and b1 < c2 then
      separated = false
    else
      local mn1, mx1 = exactRange(p1, ax.rx, ax.ry, ax.nxE, ax.nyE)
      local mn2, mx2 = exactRange(p2, ax.rx, ax.ry, ax.nxE, ax.nyE)
      separated = sign(sub(mx1, mn2)) <= 0 or sign(sub(mn1, mx2)) >= 0
    end
    if separated then return false end
    -- bounds of the overlap along this axis, in units of |n|
    local len = sqrt(ax.nx * ax.nx + ax.ny * ax.ny)
    local lo = math.min(c1 - b2, c2 - b1) / len * (1 - 1e-12)
    local hi = math.min(d1 - a2, d2 - a1) / len * (1 + 1e-12)
    float[k] = { lo, hi }
  end
  local upper = huge
  for k = 1, #axes do if float[k][2] < upper then upper = float[k][2] end end
  local cands = {}
  for k = 1, #axes do
    if float[k][1] <= upper then
      local ax = axes[k]
      local mn1, mx1 = exactRange(p1, ax.rx, ax.ry, ax.nxE, ax.nyE)
      local mn2, mx2 = exactRange(p2, ax.rx, ax.ry, ax.nxE, ax.nyE)
      local a, b = sub(mx1, mn2), sub(mx2, mn1)
      local cmp = sign(sub(a, b))
      local oh, ol = toDD(cmp < 0 and a or b)
      local lh, ll = axisLength(ax)
      local dh, dl = ddDiv(oh, ol, lh, ll)
      local dirs = cmp < 0 and { 1 } or cmp > 0 and { -1 } or { 1, -1 }
      cands[#cands + 1] = { dh, dl, ax, dirs }
    end
  end
  return true, finishCandidates(cands)
end

-- Reference for polygonCircleCollideV: axes are the edge normals and the axis from the vertex
-- nearest (by distance) to the centre. Decided in double-double from exact numerators.
function exact.circle(points, cx, cy, r)
  local axes = edgeAxes(points, {})
  -- nearest vertex: float filter, then exact squared distances for the close ones
  local n = #points
  local dLo, dHi = {}, {}
  local bestHi = huge
  for i = 1, n - 1, 2 do
    local dx, dy = points[i] - cx, points[i + 1] - cy
    local d = dx * dx + dy * dy
    dLo[i], dHi[i] = d * (1 - 8 * EPS), d * (1 + 8 * EPS)
    if dHi[i] < bestHi then bestHi = dHi[i] end
  end
  local best, bestE
  for i = 1, n - 1, 2 do
    if dLo[i] <= bestHi then
      local ex, ey = diffE(points[i], cx), diffE(points[i + 1], cy)
      local d = add(mul(ex, ex), mul(ey, ey))
      if not best or sign(sub(d, bestE)) < 0 then best, bestE = i, d end
    end
  end
  local px, py = points[best], points[best + 1]
  if px ~= cx or py ~= cy then
    axes[#axes + 1] = { rx = px, ry = py, nx = cx - px, ny = cy - py,
                        nxE = diffE(cx, px), nyE = diffE(cy, py) }
  end
  if #axes == 0 then return false end
  local cands = {}
  for k = 1, #axes do
    local ax = axes[k]
    local mn1, mx1 = exactRange(points, ax.rx, ax.ry, ax.nxE, ax.nyE)
    local sc = projE(cx, cy, ax.rx, ax.ry, ax.nxE, ax.nyE)
    local lh, ll = axisLength(ax)
    -- a = max1 - (s - r) and b = (s + r) - min1, in units of the unit normal
    local ah, al = toDD(sub(mx1, sc))
    ah, al = ddDiv(ah, al, lh, ll)
    ah, al = ddAdd(ah, al, r, 0)
    local bh, bl = toDD(sub(sc, mn1))
    bh, bl = ddDiv(bh, bl, lh, ll)
    bh, bl = ddAdd(bh, bl, r, 0)
    if ah <= 0 or bh <= 0 then return false end
    local cmp = sign(sub(add(mx1, mn1), scale(sc, 2)))  -- sign of a - b
    local dirs = cmp < 0 and { 1 } or cmp > 0 and { -1 } or { 1, -1 }
    if cmp < 0 then
      cands[#cands + 1] = { ah, al, ax, dirs }
    else
      cands[#cands + 1] = { bh, bl, ax, dirs }
    end
  end
  return true, finishCandidates(cands)
end

return exact
