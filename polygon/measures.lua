-- polygon/measures.lua: winding order, area (fast and accurate), convex or concave, centre and
-- centroid, from kernel's exact signs and sums (polygonType's careful walk is convex.lua's).

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local check = require(_PACKAGE .. ".check")
local carefulWalk = require(_PACKAGE .. ".convex").carefulWalk

local abs, sqrt, min, max = math.abs, math.sqrt, math.min, math.max
local CROSS_BOUND, shoelaceExact, expSign = kernel.CROSS_BOUND, kernel.shoelaceExact, kernel.expSign
local expCompress, JIT, SPLITTER = kernel.expCompress, kernel.JIT, kernel.SPLITTER
local expClear, expAddTriple = kernel.expClear, kernel.expAddTriple
local expLength, powerScale = kernel.expLength, kernel.powerScale
local largestMagnitude = kernel.largestMagnitude
local checkPoints, checkFinitePoints = check.checkPoints, check.checkFinitePoints
local shapeBehind = check.shapeBehind

local M = {}


-- The PUC polygonType filter's bound on a turn's rounding error, squared: CROSS_BOUND^2 times
-- 2, room for the rounding of the sum of squares and of the squares.
local TURN_BOUND_SQ = 2 * CROSS_BOUND * CROSS_BOUND

-- The winding order as seen on screen (y down).
-- points: flat array {x1, y1, ...}
-- Returns "cw" or "ccw"; nil for fewer than 3 points or zero signed area. Exact. A non-finite
-- coordinate raises an error (it makes the sum NaN or infinite, which takes the exact path).
function M.polygonWindingOrder(points)
  -- The checks written out where they pass, and shoelace's loop copied here, unrolled by two
  -- (no multiple assignment): a Lua call is dear on PUC Lua. polygonArea's loop is this one
  -- without the squares. A change to shoelace or to areaSignOf's bound must be made here too.
  local n = type(points) == "table" and #points or -1
  if n % 2 ~= 0 then checkPoints(points, "polygonWindingOrder") end
  if n < 6 then   -- a Polygon object: its points (point tables raise)
    local inner = type(points[1]) ~= "number" and shapeBehind(points, "polygonWindingOrder", "points", 2)
    if inner then
      local a, b = M.polygonWindingOrder(inner)
      return a, b
    end
    return nil
  end
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

-- The area (non-negative) by the shoelace formula, relative to the first vertex.
-- Returns area; nil for fewer than 3 points. Off by a few ulps for ordinary polygons at any
-- offset; a self-intersecting polygon's lobes count with their winding's sign. An area that
-- overflows is infinite; a non-finite coordinate raises an error.
function M.polygonArea(points)
  if type(points) ~= "table" or #points % 2 ~= 0 then checkPoints(points, "polygonArea") end
  local n = #points
  if n < 6 then   -- a Polygon object: its points (point tables raise)
    local inner = type(points[1]) ~= "number" and shapeBehind(points, "polygonArea", "points", 2)
    if inner then
      local a, b = M.polygonArea(inner)
      return a, b
    end
    return nil
  end
  -- shoelace's sum alone, unrolled as in polygonWindingOrder: no sums of squares, which only
  -- the sign's bound needs
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

-- The exact area of the given doubles, rounded to within one ulp.
-- From 65 to 4,096 vertices first a split in two passes (below); up to 64 vertices a split in one
-- pass, over the vertices on LuaJIT, over the edges on PUC Lua (below that); where their tests
-- after the loop fail: a compensated sum (Ogita, Rump and Oishi's Dot2) of 2A = sum over vertices
-- of x_i (y_{i+1} - y_{i-1}), with every difference split into hi + lo exactly (TwoSum) and every
-- x * hi product too (TwoProduct): its error is below eps |2A| plus 16 eps^2 m^2 T, T the sum of
-- |products| (bounded through their squares, which need no branch or abs). When that second part
-- could reach a quarter ulp of the result the area is summed exactly as an expansion instead
-- (several times slower). The x are not taken relative to vertex 1 (as shoelace does): far from
-- the origin that makes T larger, but the test below still passes while T / |2A| is below about
-- 2^37 at 16 vertices (2^27 for the benchmark's polygons at 1e9), and the x differences' TwoSums
-- are saved.
-- It stays one function (about 340 lines, half of them the proofs of its tests): each split is
-- the per-call hot path of its size, and a call per path costs PUC Lua more than the test.
-- Returns area; nil for fewer than 3 points. A non-finite coordinate raises an error.
function M.polygonAreaAccurate(points)
  if type(points) ~= "table" or #points % 2 ~= 0 then checkPoints(points, "polygonAreaAccurate") end
  local n = #points
  if n < 6 then   -- a Polygon object: its points (point tables raise)
    local inner = type(points[1]) ~= "number" and shapeBehind(points, "polygonAreaAccurate", "points", 2)
    if inner then
      local a, b = M.polygonAreaAccurate(inner)
      return a, b
    end
    return nil
  end
  local m = n / 2
  -- Both splits round every coordinate to a multiple of a quantum q, a power of two from the
  -- polygon's size guessed from vertex 1 and the middle vertex: g = |x_k - x_1| + |y_k - y_1|
  -- (abs is a call on PUC), q 2^-20 times the power of two above g. With sigma = 2^53 q and
  -- |v| <= 2^52 q, vh = (v + sigma) - sigma (Rump, Ogita and Oishi's ExtractScalar) is v
  -- rounded to a multiple of q, exactly, and vl = v - vh is exact and at most q; beyond,
  -- |vh| > 2^51 q, so a bound on every |vh| below that bounds every |v|.
  -- One quantum serves both axes, guessed from one pair of vertices (a second pair costs
  -- instructions on every call, and ordinary polygons pass the tests with one); a
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
    -- Dot2's 33.
    -- Each step splits its neighbours' y again, carrying no part from step to step: with the
    -- four y parts carried (two fewer splits a vertex) the traces that leave the loop fail to
    -- compile ("NYI: register coalescing too complex"). The middle vertex comes from integer
    -- operations: m - m % 2 + 1 is a floating-point floor on LuaJIT, slower, and on the path
    -- to every split.
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
        -- leave the loop moving values between registers), the last term wrapping round to
        -- y_1. Alongside: sx = sum xh^2, sd = sum dh^2 and l2, the sum of lo^2 after every
        -- second term, which bound everything the tests after the loops need with no branch,
        -- no call and no abs per vertex (math.max and math.abs tracking the largest |x|, |dh|
        -- and partial sum cost LuaJIT more than sums of squares, and PUC Lua a call each).
        -- On LuaJIT this loop is bound by its floating-point additions, 13.5 a vertex: so x is
        -- taken as it is, not relative to vertex 1 (one more subtraction a vertex). Instead x
        -- and y swap roles when |x_1| > |y_1| (the term becomes y_k (x_{k-1} - x_{k+1}), of
        -- opposite sign; the index arithmetic costs LuaJIT no time): a polygon far from the
        -- origin along one axis passes the tests below; one far along both fails them and takes
        -- Dot2 (bench/workloads.lua's polygons of 1,000 vertices moved by (d, d): all pass at
        -- d = 8 times their radius, none at 32).
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
        -- Fewer VM instructions per vertex than Dot2's below.
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
    -- x dh = p + e exactly: twoProduct written out, as on PUC Lua a call costs more than the
    -- product
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

-- The careful walk for polygonType (convex.lua's, shared with the collision functions' check):
-- taken only when the one-pass filter below cannot decide (a turn within rounding of zero, a
-- repeated vertex, an overflow or a non-finite coordinate, which it checks for first).
local function typeCareful(points, n)
  checkFinitePoints(points, n, "polygonType", "points", 4)
  local kind = carefulWalk(points, n, 1.0, 1.0, false)
  if kind == nil or kind == "convex" then return kind end
  return "concave"
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
-- LuaJIT (no integers, so no conversions): no branch in the loop. math.min, math.max and
-- math.abs compile to single instructions; data-dependent branches become side traces, dearer
-- than the loop's steps.
-- The sign of the product of consecutive edges' dx is taken without a branch: in the exact
-- range a nonzero product of coordinate differences is at least 2^-998, so 2^1000 times it
-- clamps to +-1. Around m edges whose turns are all certain, no two consecutive dx are 0 and
-- each winding changes the sign twice (directly, or through one 0 which zeroes two products),
-- so the sum of those signs is m - 4k for k windings.
-- The filter sums |l + r|, not |l| + |r|: when l and r differ in sign no cancellation can
-- happen, and |l + r| <= |s| passes anyway (as in cross). Any NaN or overflow makes errSum
-- NaN or infinite, so nothing is certain.
-- The turns at the last vertex, at vertex 1 and at vertex 2 are taken before the loop, and
-- when they disagree the call ends there (most concave polygons turn both ways within their
-- first few vertices). Only four sums cross that branch: its side trace inherits little (with
-- the first turns' differences and products alive there too it can fail to compile, "NYI:
-- register coalescing too complex").
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
-- LuaJIT's: typeFiltered's branch-free pass (min, max and abs are single instructions there).
local function polygonTypeJit(points)
  local n = checkPoints(points, "polygonType")
  if n < 6 then   -- a Polygon object: its points (point tables raise)
    local inner = type(points[1]) ~= "number" and shapeBehind(points, "polygonType", "points", 2)
    if inner then
      local a, b = polygonTypeJit(inner)
      return a, b
    end
    return nil
  end
  local kind = typeFiltered(points, n)
  if kind == false then kind = typeCareful(points, n) end
  return kind
end

-- PUC Lua: math.min/max/abs are C calls, dearer than comparisons, so one
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
-- Flipping y costs less than walking such a polygon backwards, whose longer start the loop
-- does not win back on 4 to 16 vertices.
-- polygonTypePuc stays whole (about 100 lines): its loop is the hot path, and a call per step or
-- per part would cost more than the turns it takes.
-- PUC Lua's: one branchy pass, one comparison per turn, as calls cost more than branches.
local function polygonTypePuc(points)
  if type(points) ~= "table" then checkPoints(points, "polygonType") end
  local n = #points
  if n % 2 ~= 0 then checkPoints(points, "polygonType") end
  if n < 6 then   -- a Polygon object: its points (point tables raise)
    local inner = type(points[1]) ~= "number" and shapeBehind(points, "polygonType", "points", 2)
    if inner then
      local a, b = polygonTypePuc(inner)
      return a, b
    end
    return nil
  end
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

local polygonType = JIT and polygonTypeJit or polygonTypePuc

-- Whether the polygon is convex.
-- Checks every vertex (the tutorial skips the last one). Repeated consecutive vertices and
-- collinear vertices that go on forward are allowed; a zero turn that doubles back (a spike) is
-- concave, and so is a polygon whose turns all agree but which winds around more than once
-- (a pentagram): its edges' x directions change sign more than twice.
-- A non-finite coordinate raises an error once read (every NaN or infinity sends the filter
-- to the careful walk, which checks); a polygon found concave before one is read is concave.
-- Returns "convex", "concave", or nil for fewer than 3 points or all points on one line. Exact.
M.polygonType = polygonType
M.polygonTypeJit = polygonTypeJit
M.polygonTypePuc = polygonTypePuc

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

-- The centre as the tutorial defines it: the mean of the vertices.
-- Within an ulp or two of exact wherever the polygon is and whatever its size (compensated
-- sums; sums that overflow are redone on coordinates scaled down by a power of two).
-- Returns cx, cy; nil for fewer than 3 points. A non-finite coordinate raises an error.
function M.polygonCenter(points)
  local n = checkPoints(points, "polygonCenter")
  if n < 6 then   -- a Polygon object: its points (point tables raise)
    local inner = type(points[1]) ~= "number" and shapeBehind(points, "polygonCenter", "points", 2)
    if inner then
      local a, b = M.polygonCenter(inner)
      return a, b
    end
    return nil
  end
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
  expClear()
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
    if expLength() > limit then
      expCompress()
      limit = expLength() + 32
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

-- The area centroid, the point a physics step rotates a uniform polygon about.
-- Float sums relative to vertex 1 for ordinary polygons; where they cancel (slivers, nearly
-- degenerate or self-cancelling polygons) exact sums instead: within a few ulps of the
-- coordinates' magnitude of the exact centroid either way.
-- Returns cx, cy; nil for fewer than 3 points or zero (exact) signed area. A non-finite
-- coordinate raises an error.
-- polygonCentroid's computation for n >= 6 coordinates; a non-finite coordinate raises fname's
-- error at `level` (counted from checkFinitePoints: polygonRotate's pivot names itself).
local function centroidOf(points, n, fname, level)
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
    checkFinitePoints(points, n, fname, "points", level)
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

function M.polygonCentroid(points)
  local n = checkPoints(points, "polygonCentroid")
  if n < 6 then   -- a Polygon object: its points (point tables raise)
    local inner = type(points[1]) ~= "number" and shapeBehind(points, "polygonCentroid", "points", 2)
    if inner then
      local a, b = M.polygonCentroid(inner)
      return a, b
    end
    return nil
  end
  local cx, cy = centroidOf(points, n, "polygonCentroid", 4)
  if cx == nil then return nil end   -- (one value, as ever)
  return cx, cy
end
M.centroidOf = centroidOf


return M
