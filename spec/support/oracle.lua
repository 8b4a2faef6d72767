--- Exact answers for the specs: what real arithmetic on the given doubles says.
--
-- Built on spec/support/exact.lua (big integers times powers of two). Slow on purpose: it shares
-- no code and no method with polygon.lua, so agreement between the two means something.
-- Points are flat arrays {x1, y1, x2, y2, ...} in screen coordinates (y down), as in the library.

local exact = require "exact"

local new, add, sub, mul, sign = exact.new, exact.add, exact.sub, exact.mul, exact.sign

local oracle = {}

-- Exact vertices of a flat array: xs[i], ys[i].
local function vertices(points)
  local xs, ys = {}, {}
  for i = 1, #points / 2 do
    xs[i], ys[i] = new(points[2 * i - 1]), new(points[2 * i])
  end
  return xs, ys
end
oracle.vertices = vertices

-- (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) for exact values.
local function cross(ax, ay, bx, by, cx, cy)
  return sub(mul(sub(bx, ax), sub(cy, ay)), mul(sub(by, ay), sub(cx, ax)))
end

-- (bx - ax) * (cx - bx) + (by - ay) * (cy - by): > 0 when a -> b -> c goes on forward.
local function forward(ax, ay, bx, by, cx, cy)
  return add(mul(sub(bx, ax), sub(cx, bx)), mul(sub(by, ay), sub(cy, by)))
end

--- Sign of the cross product (b - a) x (c - a) of three points given as numbers.
-- On screen (y down) a positive sign means a -> b -> c turns clockwise.
function oracle.orient(ax, ay, bx, by, cx, cy)
  return sign(cross(new(ax), new(ay), new(bx), new(by), new(cx), new(cy)))
end

--- The exact shoelace sum  sum_i x_i * y_(i+1) - x_(i+1) * y_i  (twice the signed area).
function oracle.shoelace(points)
  local n = #points / 2
  local as, bs, signs = {}, {}, {}
  for i = 1, n do
    local j = i % n + 1
    as[2 * i - 1], bs[2 * i - 1], signs[2 * i - 1] = points[2 * i - 1], points[2 * j], 1
    as[2 * i], bs[2 * i], signs[2 * i] = points[2 * j - 1], points[2 * i], -1
  end
  return exact.sumOfProducts(as, bs, signs)
end

--- "cw" for a positive shoelace sum, "ccw" for a negative one, nil for zero or < 3 points.
function oracle.winding(points)
  if #points < 6 then
    return nil
  end
  local s = sign(oracle.shoelace(points))
  if s > 0 then
    return "cw"
  elseif s < 0 then
    return "ccw"
  end
  return nil
end

--- The exact area (an exact value: half the absolute shoelace sum), nil for < 3 points.
function oracle.area(points)
  if #points < 6 then
    return nil
  end
  return mul(exact.abs(oracle.shoelace(points)), exact.pow2(-1))
end

--- The crossing rule with the tutorial's half-open boundary, decided exactly: edge (x1, y1)-(x2, y2)
-- counts when (y1 >= y) ~= (y2 >= y) and x <= the edge's x at height y. That last test is
-- x - x1 <= (y - y1) * (x2 - x1) / (y2 - y1); multiplied out with d = (x - x1) * (y2 - y1) -
-- (y - y1) * (x2 - x1) it reads d <= 0 when y2 > y1 and d >= 0 when y2 < y1 (no division).
function oracle.contains(points, x, y)
  local n = #points / 2
  if n < 3 then
    return false
  end
  local ex, ey = new(x), new(y)
  local inside = false
  for i = 1, n do
    local j = i % n + 1
    local x1, y1 = points[2 * i - 1], points[2 * i]
    local x2, y2 = points[2 * j - 1], points[2 * j]
    if (y1 >= y) ~= (y2 >= y) then
      local ex1, ey1 = new(x1), new(y1)
      local d = sign(sub(mul(sub(ex, ex1), sub(new(y2), ey1)), mul(sub(ey, ey1), sub(new(x2), ex1))))
      if (y2 > y1 and d <= 0) or (y2 < y1 and d >= 0) then
        inside = not inside
      end
    end
  end
  return inside
end

--- Is (x, y) exactly on the closed segment (x1, y1)-(x2, y2)?
function oracle.onSegment(x1, y1, x2, y2, x, y)
  local inBox = math.min(x1, x2) <= x and x <= math.max(x1, x2)
    and math.min(y1, y2) <= y and y <= math.max(y1, y2)
  return inBox and oracle.orient(x1, y1, x2, y2, x, y) == 0
end

--- Is (x, y) exactly on the boundary of the polygon?
function oracle.onBoundary(points, x, y)
  local n = #points / 2
  for i = 1, n do
    local j = i % n + 1
    if oracle.onSegment(points[2 * i - 1], points[2 * i], points[2 * j - 1], points[2 * j], x, y) then
      return true
    end
  end
  return false
end

-- Vertices with consecutive repeats removed (cyclically): xs, ys as the doubles given.
local function distinctDoubles(points)
  local n = #points / 2
  local xs, ys = {}, {}
  for i = 1, n do
    local j = i % n + 1
    if points[2 * i - 1] ~= points[2 * j - 1] or points[2 * i] ~= points[2 * j] then
      xs[#xs + 1], ys[#ys + 1] = points[2 * i - 1], points[2 * i]
    end
  end
  return xs, ys
end

-- The same as exact numbers.
local function distinctVertices(points)
  local xs, ys = distinctDoubles(points)
  for i = 1, #xs do xs[i], ys[i] = new(xs[i]), new(ys[i]) end
  return xs, ys
end

--- Are all points on one line (also: all equal, or fewer than 3 points)?
function oracle.allCollinear(points)
  local xs, ys = distinctVertices(points)
  if #xs < 2 then
    return true
  end
  for k = 3, #xs do
    if sign(cross(xs[1], ys[1], xs[2], ys[2], xs[k], ys[k])) ~= 0 then
      return false
    end
  end
  -- Non-consecutive points may still differ from the first two, but every point lies on the
  -- line through xs[1] and xs[2] (which differ), so all lie on one line.
  return true
end

-- 0 for directions in [0, pi) (dy > 0, or dy == 0 and dx > 0), 1 for [pi, 2 pi). Angles are
-- measured from +x towards +y; only their order matters here.
local function half(dx, dy)
  local sy = sign(dy)
  if sy > 0 or (sy == 0 and sign(dx) > 0) then
    return 0
  end
  return 1
end

-- Is the angle of direction a strictly smaller than that of direction b (both in [0, 2 pi))?
local function angleLess(ax, ay, bx, by)
  local ha, hb = half(ax, ay), half(bx, by)
  if ha ~= hb then
    return ha < hb
  end
  return sign(sub(mul(ax, by), mul(ay, bx))) > 0
end

--- "convex", "concave" or nil, by the contract's rules: nil for < 3 points or all points on one
-- line; repeated consecutive vertices are ignored; a zero turn that goes on forward is fine, one
-- that doubles back (a spike) is concave; all turns must have one sign and the edge direction
-- must go round exactly once (a pentagram, whose turns all agree, goes round twice).
function oracle.polygonType(points)
  if #points < 6 or oracle.allCollinear(points) then
    return nil
  end
  local xs, ys = distinctVertices(points)
  local n = #xs
  local turn = 0
  local dxs, dys = {}, {}
  for i = 1, n do
    local j = i % n + 1
    dxs[i], dys[i] = sub(xs[j], xs[i]), sub(ys[j], ys[i])
  end
  for i = 1, n do
    -- the turn at vertex i + 1, between edge i and edge i + 1
    local j = i % n + 1
    local k = j % n + 1
    local s = sign(cross(xs[i], ys[i], xs[j], ys[j], xs[k], ys[k]))
    if s == 0 then
      if sign(forward(xs[i], ys[i], xs[j], ys[j], xs[k], ys[k])) <= 0 then
        return "concave" -- doubles back
      end
    elseif turn == 0 then
      turn = s
    elseif s ~= turn then
      return "concave"
    end
  end
  -- All turns agree with `turn` (angles grow for turn > 0). Count how often the direction wraps
  -- past angle 0: once for a convex polygon.
  local wraps = 0
  for i = 1, n do
    local j = i % n + 1
    local wrapped
    if turn > 0 then
      wrapped = angleLess(dxs[j], dys[j], dxs[i], dys[i])
    else
      wrapped = angleLess(dxs[i], dys[i], dxs[j], dys[j])
    end
    if wrapped then
      wraps = wraps + 1
    end
  end
  return wraps == 1 and "convex" or "concave"
end

---------------------------------------------------------------------------------------------------
-- Separating axes, exactly. For convex polygons only, as the library's collision functions.

-- Exact min and max of x * nx + y * ny over the vertices.
local function projectRange(xs, ys, nx, ny)
  local lo, hi
  for i = 1, #xs do
    local s = add(mul(xs[i], nx), mul(ys[i], ny))
    if not lo or exact.compare(s, lo) < 0 then
      lo = s
    end
    if not hi or exact.compare(s, hi) > 0 then
      hi = s
    end
  end
  return lo, hi
end

-- The axes (edge normals, zero-length edges skipped) of a polygon's exact vertices.
local function axes(xs, ys)
  local list = {}
  local n = #xs
  for i = 1, n do
    local j = i % n + 1
    local nx, ny = sub(ys[i], ys[j]), sub(xs[j], xs[i])
    if sign(nx) ~= 0 or sign(ny) ~= 0 then
      list[#list + 1] = { nx, ny }
    end
  end
  return list
end

-- Does a polygon collide at all in the contract's sense (>= 3 points, nonzero area)?
local function solid(points)
  return #points >= 6 and sign(oracle.shoelace(points)) ~= 0
end

--- For each axis of p1 (and of p2 when both is true), the exact projected overlap
-- min(max1 - min2, max2 - min1) (not yet divided by |n|) together with the axis.
-- Returns a list of { overlap = exact, nx = exact, ny = exact, side = "+"/"-" } where side "+" means
-- max1 - min2 < max2 - min1 (the second shape leaves along +n).
function oracle.axisOverlaps(p1, p2, both)
  local x1, y1 = vertices(p1)
  local x2, y2 = vertices(p2)
  local list = {}
  local function scan(xs, ys)
    for _, axis in ipairs(axes(xs, ys)) do
      local nx, ny = axis[1], axis[2]
      local min1, max1 = projectRange(x1, y1, nx, ny)
      local min2, max2 = projectRange(x2, y2, nx, ny)
      local a, b = sub(max1, min2), sub(max2, min1)
      local plus = exact.compare(a, b) < 0
      list[#list + 1] = { overlap = plus and a or b, nx = nx, ny = ny, side = plus and "+" or "-" }
    end
  end
  scan(x1, y1)
  if both then
    scan(x2, y2)
  end
  return list
end

--- Exact SAT: true when no tested axis separates or makes the polygons touch.
-- both = false tests the axes of p1 only (polygonCollidesWith), true those of both (polygonsCollide).
function oracle.collides(p1, p2, both)
  if not solid(p1) or not solid(p2) then
    return false
  end
  for _, o in ipairs(oracle.axisOverlaps(p1, p2, both)) do
    if sign(o.overlap) <= 0 then
      return false
    end
  end
  return true
end

--- The penetration depth min over axes of overlap / |n|, as a double (each term is the exact
-- overlap and |n|^2 rounded once, then divided: a few ulps). Negative when an axis separates.
-- Returns depth and the axis record that attains it.
function oracle.depth(p1, p2, both)
  local best, bestAxis
  for _, o in ipairs(oracle.axisOverlaps(p1, p2, both)) do
    local n2 = exact.tonumber(add(mul(o.nx, o.nx), mul(o.ny, o.ny)))
    local d = exact.tonumber(o.overlap) / math.sqrt(n2)
    if not best or d < best then
      best, bestAxis = d, o
    end
  end
  return best, bestAxis
end

---------------------------------------------------------------------------------------------------
-- Floating results, from exact sums rounded once or twice (for tolerance checks).

--- The mean of the vertices: x1 + round(sum (x_i - x1)) / m, the sum exact. Within an ulp or so.
function oracle.center(points)
  local m = #points / 2
  if m < 3 then
    return nil
  end
  local x0, y0 = points[1] + 0.0, points[2] + 0.0
  local ex0, ey0 = new(x0), new(y0)
  local sx, sy = {}, {}
  for i = 1, m do
    sx[i] = sub(new(points[2 * i - 1]), ex0)
    sy[i] = sub(new(points[2 * i]), ey0)
  end
  return x0 + exact.tonumber(exact.sum(sx)) / m, y0 + exact.tonumber(exact.sum(sy)) / m
end

--- The area centroid, nil for zero area. Exact sums relative to vertex 1 (X = x - x1):
-- c_i = X_i Y_j - X_j Y_i, cx = x1 + sum (X_i + X_j) c_i / (3 sum c_i), rounded at the end only.
function oracle.centroid(points)
  local m = #points / 2
  if m < 3 then
    return nil
  end
  local xs, ys = vertices(points)
  local ex0, ey0 = xs[1], ys[1]
  for i = 1, m do
    xs[i], ys[i] = sub(xs[i], ex0), sub(ys[i], ey0)
  end
  local a2, sx, sy = {}, {}, {}
  for i = 1, m do
    local j = i % m + 1
    local c = sub(mul(xs[i], ys[j]), mul(xs[j], ys[i]))
    a2[i] = c
    sx[i] = mul(add(xs[i], xs[j]), c)
    sy[i] = mul(add(ys[i], ys[j]), c)
  end
  local area2 = exact.sum(a2)
  if sign(area2) == 0 then
    return nil
  end
  local d = 3 * exact.tonumber(area2)
  return points[1] + exact.tonumber(exact.sum(sx)) / d, points[2] + exact.tonumber(exact.sum(sy)) / d
end

--- The contract's circle depth: over the edge normals n of the polygon and the axis from the vertex
-- nearest to the centre (by exact squared distance; skipped when the centre is on it),
-- min(max1 - min2, max2 - min1) with the circle's range s - r .. s + r, s = c.n / |n|.
-- The differences of projections are exact, then rounded once and divided by |n|: a few ulps.
-- Returns the depth and the unit direction (ux, uy) in which the circle leaves along that axis.
function oracle.circleDepth(points, cx, cy, r)
  local xs, ys = vertices(points)
  local ecx, ecy = new(cx), new(cy)
  local axisList = axes(xs, ys)
  local nearest, nearestD
  for i = 1, #xs do
    local dx, dy = sub(ecx, xs[i]), sub(ecy, ys[i])
    local d = add(mul(dx, dx), mul(dy, dy))
    if not nearestD or exact.compare(d, nearestD) < 0 then
      nearest, nearestD = i, d
    end
  end
  if sign(nearestD) ~= 0 then
    axisList[#axisList + 1] = { sub(ecx, xs[nearest]), sub(ecy, ys[nearest]) }
  end
  local best, bux, buy
  for _, axis in ipairs(axisList) do
    local nx, ny = axis[1], axis[2]
    local min1, max1 = projectRange(xs, ys, nx, ny)
    local s = add(mul(ecx, nx), mul(ecy, ny))
    local len = math.sqrt(exact.tonumber(add(mul(nx, nx), mul(ny, ny))))
    local up = exact.tonumber(sub(max1, s)) / len + r -- the circle leaves along +n
    local down = exact.tonumber(sub(s, min1)) / len + r -- along -n
    local fx, fy = exact.tonumber(nx) / len, exact.tonumber(ny) / len
    if not best or up < best then
      best, bux, buy = up, fx, fy
    end
    if down < best then
      best, bux, buy = down, -fx, -fy
    end
  end
  return best, bux, buy
end

--- The exact SAT's answer with its push: collides (as oracle.collides), then the depth (as
-- oracle.depth) and a flat list dx1, dy1, dx2, dy2, ... of the displacements of p2 out of p1 along
-- each axis whose depth ties with the least to within 1e-12 (all rounded a few times).
function oracle.push(p1, p2, both)
  if not oracle.collides(p1, p2, both) then
    return false
  end
  local depth = oracle.depth(p1, p2, both)
  local moves = {}
  for _, o in ipairs(oracle.axisOverlaps(p1, p2, both)) do
    local length = math.sqrt(exact.tonumber(add(mul(o.nx, o.nx), mul(o.ny, o.ny))))
    local d = exact.tonumber(o.overlap) / length
    if d <= depth * (1 + 1e-12) then
      local s = (o.side == "+" and d or -d) / length
      moves[#moves + 1], moves[#moves + 2] = exact.tonumber(o.nx) * s, exact.tonumber(o.ny) * s
    end
  end
  return true, depth, moves
end

---------------------------------------------------------------------------------------------------
-- Depth bounds without rounding.

--- Whether the exact least penetration depth (min over the tested axes of overlap / |n|) is at
-- least a - b, for doubles a and b, decided exactly: x <= overlap / |n| <=> x <= 0 or
-- x^2 |n|^2 <= overlap^2 (every overlap is >= 0 when the polygons collide; call it only then).
function oracle.depthAtLeast(p1, p2, both, a, b)
  local x = sub(new(a), new(b))
  if sign(x) <= 0 then
    return true
  end
  local xx = mul(x, x)
  for _, o in ipairs(oracle.axisOverlaps(p1, p2, both)) do
    local nn = add(mul(o.nx, o.nx), mul(o.ny, o.ny))
    if sign(o.overlap) < 0 or exact.compare(mul(xx, nn), mul(o.overlap, o.overlap)) > 0 then
      return false
    end
  end
  return true
end

---------------------------------------------------------------------------------------------------
-- Circles, exactly: the open disc against another disc or against a convex polygon's interior.

-- (x - a)^2 + (y - b)^2 for exact values.
local function distanceSquared(x, y, a, b)
  local dx, dy = sub(x, a), sub(y, b)
  return add(mul(dx, dx), mul(dy, dy))
end

--- The sign of (r1 + r2)^2 - ((x2 - x1)^2 + (y2 - y1)^2): 1 when two circles collide.
function oracle.circlesOverlapSign(x1, y1, r1, x2, y2, r2)
  local reach = add(new(r1), new(r2))
  return sign(sub(mul(reach, reach), distanceSquared(new(x2), new(y2), new(x1), new(y1))))
end

--- The penetration depth r1 + r2 - |c2 - c1| of two circles: the exact sum of the radii less the
-- square root of the exact squared distance rounded once (a few ulps of the larger term).
function oracle.circlesDepth(x1, y1, r1, x2, y2, r2)
  local d2 = exact.tonumber(distanceSquared(new(x2), new(y2), new(x1), new(y1)))
  return exact.tonumber(add(new(r1), new(r2))) - math.sqrt(d2)
end

--- Whether the open disc (cx, cy, r) meets the interior of a convex polygon of nonzero area:
-- r > 0 and the squared distance from the centre to the closed polygon is below r^2. The
-- distance to a segment a -> b is found by the parameter t = (c - a).(b - a) / |b - a|^2 of the
-- foot: with L = |b - a|^2 and k = (c - a).(b - a), the foot is a + (k / L)(b - a), and
-- |c - foot|^2 < r^2 <=> |L (c - a) - k (b - a)|^2 < r^2 L^2, all integers times powers of two.
-- Whether some point of the polygon's boundary (xs, ys: exact vertices) lies within distance
-- sqrt(d2) of the exact point (ecx, ecy): strictly closer when strict, else at most that far.
-- A vertex, or the foot of the perpendicular on an edge when it falls strictly between the ends.
local function boundaryWithin(xs, ys, ecx, ecy, d2, strict)
  local limit = strict and 0 or 1   -- compare(...) < limit: < 0 strict, <= 0 otherwise
  local n = #xs
  for i = 1, n do
    if exact.compare(distanceSquared(ecx, ecy, xs[i], ys[i]), d2) < limit then
      return true
    end
    local j = i % n + 1
    local ex, ey = sub(xs[j], xs[i]), sub(ys[j], ys[i])
    local len2 = add(mul(ex, ex), mul(ey, ey))
    local k = add(mul(sub(ecx, xs[i]), ex), mul(sub(ecy, ys[i]), ey))
    -- the foot lies strictly between a and b: 0 < k < L
    if sign(k) > 0 and exact.compare(k, len2) < 0 then
      local fx = sub(mul(len2, sub(ecx, xs[i])), mul(k, ex))
      local fy = sub(mul(len2, sub(ecy, ys[i])), mul(k, ey))
      if exact.compare(add(mul(fx, fx), mul(fy, fy)), mul(d2, mul(len2, len2))) < limit then
        return true
      end
    end
  end
  return false
end

function oracle.discMeetsPolygon(points, cx, cy, r)
  if not solid(points) or r <= 0 then
    return false
  end
  local xs, ys = vertices(points)
  local ecx, ecy, er = new(cx), new(cy), new(r)
  local r2 = mul(er, er)
  local n = #xs
  -- inside or on the boundary: the centre is on the inner side of (or on) every edge's line
  local turn = sign(oracle.shoelace(points))
  local inside = true
  for i = 1, n do
    local j = i % n + 1
    if sign(cross(xs[i], ys[i], xs[j], ys[j], ecx, ecy)) * turn < 0 then
      inside = false
    end
  end
  if inside then
    return true
  end
  return boundaryWithin(xs, ys, ecx, ecy, r2, true)
end


---------------------------------------------------------------------------------------------------
-- Pieces of a polygon (triangulations, convex decompositions), checked exactly.

-- The sign of (b - a) x (c - a): the product in doubles when it clears Shewchuk's error bound
-- for it ((3 + 16 eps) eps (|l| + |r|) < 1e-15 (|l| + |r|)), else the exact oracle.orient. The
-- filter is the oracle's own; a point equal to a or b gives 0 at once.
local function orientFiltered(ax, ay, bx, by, cx, cy)
  if (cx == ax and cy == ay) or (cx == bx and cy == by) then
    return 0
  end
  local l = ((bx + 0.0) - ax) * ((cy + 0.0) - ay)
  local r = ((by + 0.0) - ay) * ((cx + 0.0) - ax)
  local det, bound = l - r, 1e-15 * (math.abs(l) + math.abs(r))
  if det > bound then
    return 1
  elseif det < -bound then
    return -1
  end
  return oracle.orient(ax, ay, bx, by, cx, cy)
end
oracle.orientFiltered = orientFiltered

-- Whether an edge of convex p (wound by w: 1 for "cw", -1 for "ccw") has every vertex of q on its
-- outer side or on its line: then the interiors of p and q are disjoint.
local function edgeSeparates(p, q, w)
  local n = #p
  for i = 1, n - 1, 2 do
    local j = i + 2 > n and 1 or i + 2
    local ax, ay, bx, by = p[i], p[i + 1], p[j], p[j + 1]
    if ax ~= bx or ay ~= by then
      local all = true
      for k = 1, #q - 1, 2 do
        if w * orientFiltered(ax, ay, bx, by, q[k], q[k + 1]) > 0 then
          all = false
          break
        end
      end
      if all then
        return true
      end
    end
  end
  return false
end

--- Checks pieces (flat arrays) against a polygon with optional holes, exactly: every piece
-- vertex is an input vertex bit for bit, every piece is wound like points (nonzero area) and,
-- with `convex`, oracle.polygonType says "convex" (triangles always are), the pieces' signed
-- areas add up to the polygon's (holes subtracted) exactly, and no two pieces' interiors
-- overlap (two convex polygons are disjoint when an edge of one has the other on its outer
-- side: tested for every pair whose boxes overlap, found by a sweep in x).
-- With `grid`, a piece vertex may be any point whose x is an input x and whose y an input y,
-- each bit for bit: the contract of convex parts of an outline whose edges all run along the
-- axes (rectangles, whose corners may lie where a cut meets an edge), so it is on for those.
-- @return true, or false and what failed
function oracle.checkPieces(points, holes, pieces, convex, grid)
  holes = holes or {}
  grid = grid or (convex and oracle.alongAxes(points, holes))
  local key = function(x, y)
    return ("%.17g %.17g"):format(x, y)
  end
  local known, knownX, knownY = {}, {}, {}
  local rings = { points }
  for _, hole in ipairs(holes) do
    rings[#rings + 1] = hole
  end
  for _, ring in ipairs(rings) do
    for i = 1, #ring - 1, 2 do
      known[key(ring[i], ring[i + 1])] = true
      knownX[("%.17g"):format(ring[i])], knownY[("%.17g"):format(ring[i + 1])] = true, true
    end
  end
  local winding = oracle.winding(points)
  local w = winding == "cw" and 1 or -1
  for p, piece in ipairs(pieces) do
    for i = 1, #piece - 1, 2 do
      local onGrid = grid and knownX[("%.17g"):format(piece[i])] and knownY[("%.17g"):format(piece[i + 1])]
      if not known[key(piece[i], piece[i + 1])] and not onGrid then
        return false, ("piece %d: vertex %s is not an input vertex"):format(p, key(piece[i], piece[i + 1]))
      end
    end
    if #piece == 6 then
      if orientFiltered(piece[1], piece[2], piece[3], piece[4], piece[5], piece[6]) ~= w then
        return false, ("piece %d is not wound %s"):format(p, winding)
      end
    elseif oracle.winding(piece) ~= winding then
      return false, ("piece %d is not wound %s"):format(p, winding)
    end
    if convex and #piece > 6 and oracle.polygonType(piece) ~= "convex" then
      return false, ("piece %d is not convex"):format(p)
    end
  end
  -- area: sum over pieces of their shoelace terms minus the polygon's, holes subtracted
  local as, bs, signs = {}, {}, {}
  local function terms(ring, s)
    local n = #ring / 2
    for i = 1, n do
      local j = i % n + 1
      local m = #as
      as[m + 1], bs[m + 1], signs[m + 1] = ring[2 * i - 1], ring[2 * j], s
      as[m + 2], bs[m + 2], signs[m + 2] = ring[2 * j - 1], ring[2 * i], -s
    end
  end
  for _, piece in ipairs(pieces) do
    terms(piece, 1)
  end
  terms(points, -1)
  for _, hole in ipairs(holes) do
    -- a hole takes away its area whatever its winding: add its terms with the sign against points
    terms(hole, oracle.winding(hole) == winding and 1 or -1)
  end
  if sign(exact.sumOfProducts(as, bs, signs)) ~= 0 then
    return false, "the pieces' areas do not add up to the polygon's"
  end
  -- overlaps
  local order, box = {}, {}
  for p, piece in ipairs(pieces) do
    local x0, y0, x1, y1 = math.huge, math.huge, -math.huge, -math.huge
    for i = 1, #piece - 1, 2 do
      x0, x1 = math.min(x0, piece[i]), math.max(x1, piece[i])
      y0, y1 = math.min(y0, piece[i + 1]), math.max(y1, piece[i + 1])
    end
    box[p], order[p] = { x0, y0, x1, y1 }, p
  end
  table.sort(order, function(a, b)
    return box[a][1] < box[b][1]
  end)
  local active = {}
  for _, p in ipairs(order) do
    local bp = box[p]
    local kept = {}
    for _, q in ipairs(active) do
      local bq = box[q]
      if bq[3] > bp[1] then
        kept[#kept + 1] = q
        if bq[2] < bp[4] and bp[2] < bq[4]
          and not edgeSeparates(pieces[p], pieces[q], w) and not edgeSeparates(pieces[q], pieces[p], w) then
          return false, ("pieces %d and %d overlap"):format(q, p)
        end
      end
    end
    kept[#kept + 1] = p
    active = kept
  end
  return true
end

--- Whether every edge of the outline and of the holes runs along an axis (a repeated vertex is
-- no edge): the inputs whose convex parts are rectangles.
function oracle.alongAxes(points, holes)
  local rings = { points }
  for h, hole in ipairs(holes or {}) do rings[h + 1] = hole end
  for _, ring in ipairs(rings) do
    local n = #ring
    for i = 1, n - 1, 2 do
      local j = i + 2 <= n and i + 2 or 1
      if ring[i] ~= ring[j] and ring[i + 1] ~= ring[j + 1] then return false end
    end
  end
  return true
end

--- Checks that pieces cover a polygon with optional holes exactly: oracle.checkPieces, then
-- the boundary of the pieces taken together is the boundary of the region, edge for edge. Each
-- edge, of a piece or of a ring, is cut at every input vertex lying inside it; every cut piece
-- of a piece's edge counts +1 in its direction, of the outline's edges -1, of a hole's edges
-- +1 (a hole runs against the outline), and the counts of u -> v and v -> u must cancel for
-- every u, v. Pieces wound like the outline with this boundary add up, point by point, to the
-- region's winding number: 1 inside, 0 outside and in the holes, so they cover it exactly.
-- @return true, or false and what failed
function oracle.checkCover(points, holes, pieces, convex, grid)
  grid = grid or (convex and oracle.alongAxes(points, holes))
  local ok, why = oracle.checkPieces(points, holes, pieces, convex, grid)
  if not ok then
    return false, why
  end
  holes = holes or {}
  local winding = oracle.winding(points)
  local vx, vy, seen = {}, {}, {}
  local function keyOf(x, y)
    return ("%.17g %.17g"):format(x, y)
  end
  local rings = { points }
  for h = 1, #holes do
    rings[h + 1] = holes[h]
  end
  if grid then   -- the edges are cut at the pieces' vertices too, which need not be input vertices
    for _, piece in ipairs(pieces) do rings[#rings + 1] = piece end
  end
  for _, ring in ipairs(rings) do
    for i = 1, #ring - 1, 2 do
      local key = keyOf(ring[i], ring[i + 1])
      if not seen[key] then
        seen[key] = true
        vx[#vx + 1], vy[#vy + 1] = ring[i], ring[i + 1]
      end
    end
  end
  local order = {}
  for i = 1, #vx do
    order[i] = i
  end
  table.sort(order, function(a, b)
    return vx[a] < vx[b] or (vx[a] == vx[b] and vy[a] < vy[b])
  end)
  local count = {}
  local function addEdge(ax, ay, bx, by, weight)
    local x0, x1 = math.min(ax, bx), math.max(ax, bx)
    local y0, y1 = math.min(ay, by), math.max(ay, by)
    local lo, hi = 1, #order + 1
    while lo < hi do
      local mid = math.floor((lo + hi) / 2)
      if vx[order[mid]] < x0 then
        lo = mid + 1
      else
        hi = mid
      end
    end
    local cuts = { { ax, ay, 0 }, { bx, by, math.huge } }
    for k = lo, #order do
      local v = order[k]
      local x, y = vx[v], vy[v]
      if x > x1 then
        break
      end
      if y >= y0 and y <= y1 and not (x == ax and y == ay) and not (x == bx and y == by)
        and orientFiltered(ax, ay, bx, by, x, y) == 0 then
        cuts[#cuts + 1] = { x, y, ax ~= bx and math.abs(x - ax) or math.abs(y - ay) }
      end
    end
    table.sort(cuts, function(a, b)
      return a[3] < b[3]
    end)
    for c = 1, #cuts - 1 do
      local u, w = keyOf(cuts[c][1], cuts[c][2]), keyOf(cuts[c + 1][1], cuts[c + 1][2])
      if u ~= w then
        local key, signed = u .. ">" .. w, weight
        if u > w then
          key, signed = w .. ">" .. u, -weight
        end
        count[key] = (count[key] or 0) + signed
      end
    end
  end
  local function addRing(ring, weight)
    local n = #ring / 2
    for i = 1, n do
      local j = i % n + 1
      addEdge(ring[2 * i - 1], ring[2 * i], ring[2 * j - 1], ring[2 * j], weight)
    end
  end
  for _, piece in ipairs(pieces) do
    addRing(piece, 1)
  end
  addRing(points, -1)
  for _, hole in ipairs(holes) do
    local w = oracle.winding(hole)   -- nil: the hole encloses nothing and is skipped
    if w then addRing(hole, w == winding and 1 or -1) end
  end
  for key, c in pairs(count) do
    if c ~= 0 then
      return false, ("the pieces' boundary differs from the region's along %s (%d)"):format(key, c)
    end
  end
  return true
end

--- The number of reflex vertices of a polygon (turning against its winding), exactly; repeated
-- consecutive vertices are skipped.
function oracle.reflexCount(points)
  local w = oracle.winding(points) == "cw" and 1 or -1
  local xs, ys = distinctDoubles(points)
  local count = 0
  for i = 1, #xs do
    local a, c = (i - 2) % #xs + 1, i % #xs + 1
    if w * orientFiltered(xs[a], ys[a], xs[i], ys[i], xs[c], ys[c]) < 0 then
      count = count + 1
    end
  end
  return count
end

---------------------------------------------------------------------------------------------------
-- A circle's depth bound without rounding.

--- Whether the exact least penetration depth of the circle (cx, cy, r) into a convex polygon of
-- nonzero area, D = r - (signed distance from the centre to the polygon, negative inside), is at
-- least a - b, for doubles a and b, decided exactly. With s = r - (a - b) it asks whether the
-- signed distance is at most s. For s >= 0: the centre is in the closed polygon, or its squared
-- distance to a vertex or to an edge (foot strictly inside, as in discMeetsPolygon) is at most
-- s^2. For s < 0: the centre is inside at distance at least -s from every edge's line (for a
-- convex polygon the distance to the boundary from inside is the least of those), that is,
-- cross >= 0 and cross^2 >= s^2 |e|^2 with cross = (b - a) x (c - a) signed positive inside.
function oracle.circleDepthAtLeast(points, cx, cy, r, a, b)
  local xs, ys = vertices(points)
  local ecx, ecy = new(cx), new(cy)
  local s = sub(new(r), sub(new(a), new(b)))
  local s2 = mul(s, s)
  local n = #xs
  local turn = sign(oracle.shoelace(points))
  local inside = true
  for i = 1, n do
    local j = i % n + 1
    local c = mul(cross(xs[i], ys[i], xs[j], ys[j], ecx, ecy), new(turn))
    if sign(c) < 0 then
      inside = false
    elseif sign(s) < 0 then
      local ex, ey = sub(xs[j], xs[i]), sub(ys[j], ys[i])
      if exact.compare(mul(c, c), mul(s2, add(mul(ex, ex), mul(ey, ey)))) < 0 then
        return false
      end
    end
  end
  if sign(s) < 0 then
    return inside
  end
  if inside then
    return true
  end
  return boundaryWithin(xs, ys, ecx, ecy, s2, false)
end

--- A double q >= |(dx, dy)| exactly, within an ulp or two of it: the rounded length, raised
-- until q^2 >= dx^2 + dy^2 holds in exact arithmetic.
function oracle.lengthAbove(dx, dy)
  local big = math.max(math.abs(dx), math.abs(dy))
  if big == 0 then
    return 0
  end
  local q = big * math.sqrt((dx / big) ^ 2 + (dy / big) ^ 2)
  local ex, ey = new(dx), new(dy)
  local lengthSq = add(mul(ex, ex), mul(ey, ey))
  while exact.compare(mul(new(q), new(q)), lengthSq) < 0 do
    q = exact.nextUp(q)
  end
  return q
end

--- Whether the exact depth of two circles, r1 + r2 - |c2 - c1|, is at least a - b, for doubles
-- a and b, decided exactly: with s = r1 + r2 - (a - b), it asks s >= 0 and |c2 - c1|^2 <= s^2.
function oracle.circlesDepthAtLeast(x1, y1, r1, x2, y2, r2, a, b)
  local s = sub(add(new(r1), new(r2)), sub(new(a), new(b)))
  if sign(s) < 0 then
    return false
  end
  return exact.compare(distanceSquared(new(x2), new(y2), new(x1), new(y1)), mul(s, s)) <= 0
end

-- The verdict at place (px, py) of the edges `near` (edge i runs from vertex i to nextOf[i];
-- every edge holding the place, maybe others): "cross", "undecided" or nil (see outlineCrossing).
local function placeVerdict(xs, ys, nextOf, near, px, py)
  local n = #xs
  -- entries: { target vertex, 1 leaving or -1 reaching, chain }
  local entries = {}
  for _, i in ipairs(near) do
    local j = nextOf[i]
    if xs[i] == px and ys[i] == py then
      entries[#entries + 1] = { j, 1, i }
    elseif xs[j] == px and ys[j] == py then
      entries[#entries + 1] = { i, -1, j }
    elseif oracle.onSegment(xs[i], ys[i], xs[j], ys[j], px, py) then
      entries[#entries + 1] = { j, 1, n + i }
      entries[#entries + 1] = { i, -1, n + i }
    end
  end
  if #entries <= 2 then
    return nil
  end
  -- by angle from +x about p: the upper half (y > py, or y == py and x > px) first
  local function upper(v)
    return ys[v] > py or (ys[v] == py and xs[v] > px)
  end
  local function before(u, v)
    if upper(u[1]) ~= upper(v[1]) then
      return upper(u[1])
    end
    return oracle.orient(px, py, xs[u[1]], ys[u[1]], xs[v[1]], ys[v[1]]) > 0
  end
  -- insertion sort: no sort with a comparator that may call equal entries unequal
  for i = 2, #entries do
    local e, j = entries[i], i - 1
    while j >= 1 and before(e, entries[j]) do
      entries[j + 1] = entries[j]
      j = j - 1
    end
    entries[j + 1] = e
  end
  -- edges in one direction: more than one more leaving than reaching (or the other way)
  -- crosses; one each way may lie in either order (both are tried); more are not decided
  local pairsAt, many = {}, false
  for i = 1, #entries do
    local balance, alike = 0, 0
    for j = 1, #entries do
      if not before(entries[i], entries[j]) and not before(entries[j], entries[i]) then
        balance, alike = balance + entries[j][2], alike + 1
      end
    end
    if math.abs(balance) >= 2 then
      return "cross"
    end
    many = many or alike > 2
    if alike == 2 and i < #entries and not before(entries[i], entries[i + 1]) then
      pairsAt[#pairsAt + 1] = i
    end
  end
  local function nested(list)
    local stack = {}
    for i = 1, #list do
      local e, f = list[i], list[i % #list + 1]
      if e[2] == f[2] then
        return false
      end
      if stack[#stack] == e[3] then
        stack[#stack] = nil
      else
        stack[#stack + 1] = e[3]
      end
    end
    return #stack == 0
  end
  if many then
    return "undecided"
  end
  local found = false
  for orders = 0, 2 ^ #pairsAt - 1 do
    local list = {}
    for i = 1, #entries do
      list[i] = entries[i]
    end
    for t, i in ipairs(pairsAt) do
      if math.floor(orders / 2 ^ (t - 1)) % 2 == 1 then
        list[i], list[i + 1] = list[i + 1], list[i]
      end
    end
    found = found or nested(list)
  end
  if not found then
    return "cross"
  end
  return #pairsAt > 0 and "undecided" or nil
end

--- Whether a closed outline (a flat array; consecutive repeats are ignored) crosses or overlaps
-- itself, by brute force over every pair of edges and every vertex, with exact signs:
-- "cross" when two edges cross at a point inside both, or when, at a vertex (or a vertex lying
-- inside an edge), the edges through it, sorted by angle, do not alternate between an edge
-- reaching the point and one leaving it, or the in-out pairs of the chains through it (one per
-- visit of the outline) do not nest like brackets, or edges in one direction there count two
-- more leaving than reaching (or the other way), or no order of the pairs of edges running
-- along each other there (one each way) alternates and nests; "unknown" when none of that
-- happens but some edges run along each other both ways at a point (their order there is not
-- decided); "simple" otherwise.
function oracle.outlineCrossing(points)
  local xs, ys = distinctDoubles(points)
  local n = #xs
  local nextOf, all = {}, {}
  for i = 1, n do
    nextOf[i], all[i] = i % n + 1, i
  end
  local function orient(a, b, c)   -- vertex indices
    return oracle.orient(xs[a], ys[a], xs[b], ys[b], xs[c], ys[c])
  end
  for i = 1, n do
    for j = i + 1, n do
      local a, b, c, d = i, nextOf[i], j, nextOf[j]
      if orient(a, b, c) * orient(a, b, d) < 0 and orient(c, d, a) * orient(c, d, b) < 0 then
        return "cross"
      end
    end
  end
  local undecided = false
  for p = 1, n do
    local verdict = placeVerdict(xs, ys, nextOf, all, xs[p], ys[p])
    if verdict == "cross" then
      return "cross"
    end
    undecided = undecided or verdict == "undecided"
  end
  return undecided and "unknown" or "simple"
end

--- Whether an outline with holes (flat arrays; consecutive repeats ignored) is a valid region:
-- the outline and the holes, each hole turned to run against the outline, taken together as
-- one set of edges, pass outlineCrossing's tests (no two edges cross at a point inside both,
-- and at every place where vertices meet or a vertex lies inside an edge the edges alternate
-- and the chains nest), and each hole lies inside the outline and outside every other hole (a
-- vertex of it off the other ring's boundary decides: rings that do not cross keep all their
-- other points on one side). Edges are paired only when their boxes overlap (a sweep in x).
-- A hole enclosing nothing (fewer than 3 points, or zero area without crossing itself) is
-- skipped: it takes nothing away.
-- @return "valid"; "cross", i, j (rings i and j cross or overlap: 1 the outline, h + 1 hole h);
--   "outside", h (hole h not inside the outline); "inside", h, g (hole h inside hole g);
--   "degenerate", 1 (the outline has fewer than 3 distinct vertices or zero area); "unknown"
--   when a place's order is not decided or a hole has every vertex on another ring
function oracle.regionCrossing(points, holes)
  holes = holes or {}
  local rings = { points }
  for h = 1, #holes do
    rings[h + 1] = holes[h]
  end
  local outerWinding = oracle.winding(points)
  local xs, ys, nextOf, ringOf, first, last, skipped = {}, {}, {}, {}, {}, {}, {}
  for r, ring in ipairs(rings) do
    local w = oracle.winding(ring)
    local rx, ry = distinctDoubles(ring)
    if r > 1 and not w and #rx >= 3 and oracle.outlineCrossing(ring) == "cross" then
      return "cross", r, r
    end
    if r == 1 and (#rx < 3 or not w) then
      return "degenerate", 1
    end
    if not w then   -- a hole enclosing nothing: skipped
      rx, ry, skipped[r] = {}, {}, true
    end
    local reversed = r > 1 and w == outerWinding
    local base = #xs
    first[r], last[r] = base + 1, base + #rx
    for i = 1, #rx do
      local s = reversed and #rx + 1 - i or i
      xs[base + i], ys[base + i], ringOf[base + i] = rx[s], ry[s], r
      nextOf[base + i] = base + i % #rx + 1
    end
  end
  local n = #xs
  local function orient(a, b, c)   -- vertex indices
    return orientFiltered(xs[a], ys[a], xs[b], ys[b], xs[c], ys[c])
  end
  -- edges by the left end of their box; each paired with the earlier ones still reaching it
  local x0, x1, y0, y1, byLeft = {}, {}, {}, {}, {}
  for i = 1, n do
    local j = nextOf[i]
    x0[i], x1[i] = math.min(xs[i], xs[j]), math.max(xs[i], xs[j])
    y0[i], y1[i] = math.min(ys[i], ys[j]), math.max(ys[i], ys[j])
    byLeft[i] = i
  end
  table.sort(byLeft, function(a, b)
    return x0[a] < x0[b] or (x0[a] == x0[b] and a < b)
  end)
  local near = {}   -- near[v]: the edges whose box holds vertex v
  for i = 1, n do
    near[i] = {}
  end
  local active = {}
  for _, e in ipairs(byLeft) do
    local kept = {}
    for _, f in ipairs(active) do
      if x1[f] >= x0[e] then
        kept[#kept + 1] = f
        if y1[f] >= y0[e] and y1[e] >= y0[f] then
          local a, b, c, d = e, nextOf[e], f, nextOf[f]
          if orient(a, b, c) * orient(a, b, d) < 0 and orient(c, d, a) * orient(c, d, b) < 0 then
            return "cross", math.min(ringOf[e], ringOf[f]), math.max(ringOf[e], ringOf[f])
          end
        end
      end
    end
    kept[#kept + 1] = e
    active = kept
  end
  -- the vertices in x order, to find the edges whose box holds each
  local vs = {}
  for i = 1, n do
    vs[i] = i
  end
  table.sort(vs, function(a, b)
    return xs[a] < xs[b] or (xs[a] == xs[b] and a < b)
  end)
  for e = 1, n do
    local lo, hi = 1, n + 1   -- the first vertex with x >= x0[e]
    while lo < hi do
      local mid = math.floor((lo + hi) / 2)
      if xs[vs[mid]] < x0[e] then
        lo = mid + 1
      else
        hi = mid
      end
    end
    for k = lo, n do
      local v = vs[k]
      if xs[v] > x1[e] then
        break
      end
      if ys[v] >= y0[e] and ys[v] <= y1[e] then
        local list = near[v]
        list[#list + 1] = e
      end
    end
  end
  local undecided, done = false, {}
  for v = 1, n do
    local key = ("%.17g %.17g"):format(xs[v], ys[v])
    if not done[key] then
      done[key] = true
      local verdict = placeVerdict(xs, ys, nextOf, near[v], xs[v], ys[v])
      if verdict == "cross" then
        local lowest, highest = math.huge, -math.huge
        for _, e in ipairs(near[v]) do
          if oracle.onSegment(xs[e], ys[e], xs[nextOf[e]], ys[nextOf[e]], xs[v], ys[v]) then
            lowest, highest = math.min(lowest, ringOf[e]), math.max(highest, ringOf[e])
          end
        end
        return "cross", lowest, highest
      end
      undecided = undecided or verdict == "undecided"
    end
  end
  -- where the rings lie against each other: a vertex of ring r off ring g's boundary
  local function sideOf(r, g)   -- true inside g, false outside, nil: every vertex on g
    for v = first[r], last[r] do
      if not oracle.onBoundary(rings[g], xs[v], ys[v]) then
        return oracle.contains(rings[g], xs[v], ys[v])
      end
    end
    return nil
  end
  local function boxesMeet(r, g)
    local ax0, ay0, ax1, ay1 = math.huge, math.huge, -math.huge, -math.huge
    local bx0, by0, bx1, by1 = math.huge, math.huge, -math.huge, -math.huge
    for v = first[r], last[r] do
      ax0, ax1 = math.min(ax0, xs[v]), math.max(ax1, xs[v])
      ay0, ay1 = math.min(ay0, ys[v]), math.max(ay1, ys[v])
    end
    for v = first[g], last[g] do
      bx0, bx1 = math.min(bx0, xs[v]), math.max(bx1, xs[v])
      by0, by1 = math.min(by0, ys[v]), math.max(by1, ys[v])
    end
    return ax0 <= bx1 and bx0 <= ax1 and ay0 <= by1 and by0 <= ay1
  end
  for r = 2, #rings do
    local inside = skipped[r] or sideOf(r, 1)
    if inside == nil then
      undecided = true
    elseif not inside then
      return "outside", r - 1
    end
  end
  for r = 2, #rings do
    for g = 2, #rings do
      if g ~= r and not skipped[r] and not skipped[g] and boxesMeet(r, g) then
        local inside = sideOf(r, g)
        if inside == nil then
          undecided = true
        elseif inside then
          return "inside", r - 1, g - 1
        end
      end
    end
  end
  return undecided and "unknown" or "valid"
end

-- The words a refusal of each of regionCrossing's verdicts must hold.
oracle.NAMED = { cross = "cross", outside = "outside", inside = "inside" }

--- Whether a triangulation's answer agrees with regionCrossing's verdict on points and holes:
-- pieces covering the region exactly when valid (checkCover), a refusal whose message holds the
-- verdict's word when not, anything when undecided.
-- @param verdict regionCrossing's verdict
-- @param pieces the pieces, or nil for a refusal
-- @param message the refusal's message
-- @return true, or false and what failed
function oracle.agrees(points, holes, verdict, pieces, message)
  local word = oracle.NAMED[verdict]
  if verdict == "valid" then
    if not pieces then return false, "refused: " .. tostring(message) end
    return oracle.checkCover(points, holes, pieces)
  elseif word then
    if pieces then return false, "accepted" end
    if not tostring(message):find(word) then return false, "refused with " .. tostring(message) end
  end
  return true
end

return oracle
