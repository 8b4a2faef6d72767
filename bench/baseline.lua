-- bench/baseline.lua: the tutorial's formulas, transcribed as plainly as possible, so that the
-- benchmark can show what polygon.lua's accuracy and speed cost or save, function by function.
--
-- This is NOT a library to use. It keeps the tutorial's arithmetic and its defects on purpose:
--   * polygonWindingOrder answers "cw" for a zero sum and rounds freely (no exact sign);
--   * polygonType never checks the corner at the last vertex and trusts rounded cross products;
--   * the separating-axis functions call projectPolygon once per axis for both polygons, project
--     relative to the mixed point (x2, y1) and never skip a zero-length edge;
--   * overlap is min(max1, max2) - max(min1, min2), which is not the depth to push out when one
--     shape holds the other, and the displacement is never flipped towards the second shape;
--   * polygonsCollideV runs polygonCollidesWithV twice, the second pass with the roles swapped;
--   * the circle test picks the "nearest" vertex by the smallest dot product with the centre.
-- polygonCentroid is the textbook formula in absolute coordinates; polygonAreaAccurate is the
-- plain shoelace (the tutorial has neither).
local sqrt, abs, min, max = math.sqrt, math.abs, math.min, math.max

local baseline = {}

-- Twice the signed area, summed as (x[i+1] + x[i]) * (y[i+1] - y[i]) with the wrap-around term
-- (last vertex to first) first, as the tutorial writes it.
local function trapezoidSum(points)
  local n = #points
  local total = (points[1] + points[n - 1]) * (points[2] - points[n])
  for i = 1, n - 3, 2 do
    total = total + (points[i + 2] + points[i]) * (points[i + 3] - points[i + 1])
  end
  return total
end

function baseline.polygonWindingOrder(points)
  if #points < 6 then return nil end
  if trapezoidSum(points) < 0 then return "ccw" end
  return "cw"
end

function baseline.polygonArea(points)
  if #points < 6 then return nil end
  return abs(trapezoidSum(points)) * 0.5
end

-- The tutorial has no accurate area: the plain shoelace stands in for it.
baseline.polygonAreaAccurate = baseline.polygonArea

function baseline.polygonType(points)
  local n = #points
  if n < 6 then return nil end
  -- corner at the first vertex: edges to the last and to the second vertex
  local ax, ay = points[n - 1] - points[1], points[n] - points[2]
  local bx, by = points[3] - points[1], points[4] - points[2]
  local firstTurn = ax * by - ay * bx
  for i = 1, n - 5, 2 do
    ax, ay = -bx, -by
    bx, by = points[i + 4] - points[i + 2], points[i + 5] - points[i + 3]
    if firstTurn * (ax * by - ay * bx) < 0 then return "concave" end
  end
  return "convex"
end

function baseline.polygonCenter(points)
  local sx, sy = points[1], points[2]
  for i = 3, #points, 2 do
    sx = sx + points[i]
    sy = sy + points[i + 1]
  end
  local count = #points / 2
  return sx / count, sy / count
end

-- Textbook area centroid: sum of (p[i] + p[i+1]) * cross(p[i], p[i+1]) over 6 * area, all in
-- absolute coordinates. The one guard (zero area) only keeps the benchmark's checksum finite.
function baseline.polygonCentroid(points)
  local n = #points
  if n < 6 then return nil end
  local twiceArea, sx, sy = 0, 0, 0
  local px, py = points[n - 1], points[n]
  for i = 1, n - 1, 2 do
    local qx, qy = points[i], points[i + 1]
    local cross = px * qy - qx * py
    twiceArea = twiceArea + cross
    sx = sx + (px + qx) * cross
    sy = sy + (py + qy) * cross
    px, py = qx, qy
  end
  if twiceArea == 0 then return nil end
  return sx / (3 * twiceArea), sy / (3 * twiceArea)
end

-- Franklin's crossing test as in the tutorial's Polygon:contains, as a plain function.
function baseline.polygonContains(points, x, y)
  local n = #points
  if n < 6 then return false end
  local x1, y1, x2, y2 = points[n - 1], points[n], points[1], points[2]
  local inside = false
  for i = 1, n - 1, 2 do
    if ((y1 >= y) ~= (y2 >= y)) and (x <= (x2 - x1) * (y - y1) / (y2 - y1) + x1) then
      inside = not inside
    end
    x1, y1 = x2, y2
    x2, y2 = points[i + 2], points[i + 3]
  end
  return inside
end

function baseline.projectPolygon(points, x, y, nx, ny)
  local lo = (points[1] - x) * nx + (points[2] - y) * ny
  local hi = lo
  for i = 3, #points, 2 do
    local s = (points[i] - x) * nx + (points[i + 1] - y) * ny
    if s < lo then lo = s end
    if s > hi then hi = s end
  end
  return lo, hi
end
local projectPolygon = baseline.projectPolygon

function baseline.polygonCollidesWith(points1, points2)
  local x1, y1 = points1[#points1 - 1], points1[#points1]
  local x2, y2 = points1[1], points1[2]
  for i = 1, #points1, 2 do
    local nx, ny = y2 - y1, x1 - x2
    local min1, max1 = projectPolygon(points1, x2, y1, nx, ny)
    local min2, max2 = projectPolygon(points2, x2, y1, nx, ny)
    if max1 <= min2 or min1 >= max2 then return false end
    x1, y1 = x2, y2
    x2, y2 = points1[i + 2], points1[i + 3]
  end
  return true
end

function baseline.polygonsCollide(points1, points2)
  return baseline.polygonCollidesWith(points1, points2)
    and baseline.polygonCollidesWith(points2, points1)
end

function baseline.polygonCollidesWithV(points1, points2)
  local x1, y1 = points1[#points1 - 1], points1[#points1]
  local x2, y2 = points1[1], points1[2]
  local best, bestX, bestY
  for i = 1, #points1, 2 do
    local nx, ny = y2 - y1, x1 - x2
    local min1, max1 = projectPolygon(points1, x2, y1, nx, ny)
    local min2, max2 = projectPolygon(points2, x2, y1, nx, ny)
    if max1 <= min2 or min1 >= max2 then return false end
    local lengthSq = nx * nx + ny * ny
    local scaled = (min(max1, max2) - max(min1, min2)) / lengthSq
    local length = sqrt(lengthSq)
    if not best or scaled * length < best then
      best = scaled * length
      bestX, bestY = nx * scaled, ny * scaled
    end
    x1, y1 = x2, y2
    x2, y2 = points1[i + 2], points1[i + 3]
  end
  return best, bestX, bestY
end

function baseline.polygonsCollideV(points1, points2)
  local o1, ax, ay = baseline.polygonCollidesWithV(points1, points2)
  local o2, bx, by = baseline.polygonCollidesWithV(points2, points1)
  if o1 and o2 then
    if o1 < o2 then return o1, ax, ay end
    return o2, bx, by
  end
  return false
end

function baseline.projectCircle(cx, cy, radius, x, y, nx, ny)
  local s = (cx - x) * nx + (cy - y) * ny
  return s - radius, s + radius
end
local projectCircle = baseline.projectCircle

function baseline.polygonCircleCollideV(points, cx, cy, radius)
  local x1, y1 = points[#points - 1], points[#points]
  local x2, y2 = points[1], points[2]
  local best, bestX, bestY
  for i = 1, #points, 2 do
    local nx, ny = y2 - y1, x1 - x2
    local length = sqrt(nx * nx + ny * ny)
    nx, ny = nx / length, ny / length
    local min1, max1 = projectPolygon(points, x2, y1, nx, ny)
    local min2, max2 = projectCircle(cx, cy, radius, x2, y1, nx, ny)
    if max1 <= min2 or min1 >= max2 then return false end
    local overlap = min(max1, max2) - max(min1, min2)
    if not best or overlap < best then
      best, bestX, bestY = overlap, nx * overlap, ny * overlap
    end
    x1, y1 = x2, y2
    x2, y2 = points[i + 2], points[i + 3]
  end
  -- "nearest" vertex: the tutorial compares dot products with the centre, not distances
  local index, nearest = 1, cx * points[1] + cy * points[2]
  for i = 3, #points, 2 do
    local d = cx * points[i] + cy * points[i + 1]
    if d < nearest then index, nearest = i, d end
  end
  local px, py = points[index], points[index + 1]
  local nx, ny = cx - px, cy - py
  local length = sqrt(nx * nx + ny * ny)
  nx, ny = nx / length, ny / length
  local min1, max1 = projectPolygon(points, px, py, nx, ny)
  local min2, max2 = projectCircle(cx, cy, radius, px, py, nx, ny)
  if max1 <= min2 or min1 >= max2 then return false end
  local overlap = min(max1, max2) - max(min1, min2)
  if overlap < best then
    best, bestX, bestY = overlap, nx * overlap, ny * overlap
  end
  return best, bestX, bestY
end

-- Issue 30's queries are not in the tutorial: these are the float loops a user writes by hand,
-- the references of polygon.lua's exact ones. Each edge's crossing with the segment by the
-- usual parametric formula (t along the segment, u along the edge, both in [0, 1]), the least
-- t kept with its edge's normal (turned by the edge's direction, not the polygon's winding):
-- touching counts as a hit and a segment from inside reports where it leaves.
function baseline.polygonRayCast(points, x1, y1, x2, y2)
  local n = #points
  local best, bnx, bny
  local dx, dy = x2 - x1, y2 - y1
  local j = n - 1
  for i = 1, n - 1, 2 do
    local ax, ay, bx, by = points[j], points[j + 1], points[i], points[i + 1]
    local ex, ey = bx - ax, by - ay
    local den = dx * ey - dy * ex
    if den ~= 0 then
      local wx, wy = ax - x1, ay - y1
      local t = (wx * ey - wy * ex) / den
      local u = (wx * dy - wy * dx) / den
      if t >= 0 and t <= 1 and u >= 0 and u <= 1 and (not best or t < best) then
        best = t
        local len = sqrt(ex * ex + ey * ey)
        bnx, bny = ey / len, -ex / len
      end
    end
    j = i
  end
  if best then return best, bnx, bny end
  return false
end

-- The quadratic |A + t d - C|^2 = r^2 by the school formula.
function baseline.circleRayCast(cx, cy, radius, x1, y1, x2, y2)
  local dx, dy = x2 - x1, y2 - y1
  local fx, fy = x1 - cx, y1 - cy
  local a, b, c = dx * dx + dy * dy, 2 * (fx * dx + fy * dy), fx * fx + fy * fy - radius * radius
  if c < 0 then return 0, 0, 0 end
  local disc = b * b - 4 * a * c
  if a == 0 or disc < 0 then return false end
  local t = (-b - sqrt(disc)) / (2 * a)
  if t < 0 or t > 1 then return false end
  local px, py = x1 + t * dx - cx, y1 + t * dy - cy
  return t, px / radius, py / radius
end

-- The projection on every edge, clamped, the nearest kept; the sign by the tutorial's crossing
-- rule.
function baseline.polygonClosestPoint(points, x, y)
  local n = #points
  local best, bx, by = math.huge, 0, 0
  local j = n - 1
  for i = 1, n - 1, 2 do
    local ax, ay = points[j], points[j + 1]
    local ex, ey = points[i] - ax, points[i + 1] - ay
    local length = ex * ex + ey * ey
    local u = length > 0 and ((x - ax) * ex + (y - ay) * ey) / length or 0
    if u < 0 then u = 0 elseif u > 1 then u = 1 end
    local px, py = ax + u * ex, ay + u * ey
    local d = (x - px) * (x - px) + (y - py) * (y - py)
    if d < best then best, bx, by = d, px, py end
    j = i
  end
  local distance = sqrt(best)
  if baseline.polygonContains(points, x, y) then distance = -distance end
  return bx, by, distance
end

-- The swept separating-axis test a user writes by hand: on each edge normal of either polygon
-- (not normalized), the interval of t where the projections overlap, the latest entry and the
-- earliest exit in floating point, touching counted as a hit; the normal of the latest entry's
-- axis turned toward the moving polygon.
local function sweepAxes(points, n, p1, n1, p2, n2, dx, dy, state)
  local j = n - 1
  for i = 1, n - 1, 2 do
    local ax, ay = -(points[i + 1] - points[j + 1]), points[i] - points[j]
    local min1, max1, min2, max2 = math.huge, -math.huge, math.huge, -math.huge
    for k = 1, n1 - 1, 2 do
      local p = p1[k] * ax + p1[k + 1] * ay
      if p < min1 then min1 = p end
      if p > max1 then max1 = p end
    end
    for k = 1, n2 - 1, 2 do
      local p = p2[k] * ax + p2[k + 1] * ay
      if p < min2 then min2 = p end
      if p > max2 then max2 = p end
    end
    local speed = dx * ax + dy * ay
    if speed == 0 then
      if max2 < min1 or min2 > max1 then state.miss = true end
    else
      local t0, t1 = (min1 - max2) / speed, (max1 - min2) / speed
      local sign = -1
      if t0 > t1 then t0, t1, sign = t1, t0, 1 end
      if t0 > state.enter then
        state.enter, state.nx, state.ny = t0, sign * ax, sign * ay
      end
      if t1 < state.exit then state.exit = t1 end
    end
    j = i
  end
end

local sweepState = { enter = 0, exit = 0, nx = 0, ny = 0, miss = false }
function baseline.polygonsCast(points1, points2, dx, dy)
  local n1, n2 = #points1, #points2
  local state = sweepState
  state.enter, state.exit, state.nx, state.ny, state.miss = -math.huge, math.huge, 0, 0, false
  sweepAxes(points1, n1, points1, n1, points2, n2, dx, dy, state)
  sweepAxes(points2, n2, points1, n1, points2, n2, dx, dy, state)
  if state.miss or state.enter > state.exit or state.enter > 1 or state.exit < 0 then return false end
  local len = sqrt(state.nx * state.nx + state.ny * state.ny)
  return max(state.enter, 0), state.nx / len, state.ny / len
end

-- The moving centre against the disc of radius r1 + r2, by the school formula.
function baseline.circlesCast(x1, y1, r1, x2, y2, r2, dx, dy)
  local fx, fy, r = x2 - x1, y2 - y1, r1 + r2
  local a, b, c = dx * dx + dy * dy, 2 * (fx * dx + fy * dy), fx * fx + fy * fy - r * r
  if c < 0 then return 0, 1, 0 end
  local disc = b * b - 4 * a * c
  if a == 0 or disc < 0 then return false end
  local t = (-b - sqrt(disc)) / (2 * a)
  if t < 0 or t > 1 then return false end
  return t, (fx + t * dx) / r, (fy + t * dy) / r
end

-- The loop a user writes for a circle swept against a convex polygon: for each edge, where the
-- centre crosses the edge's line moved out by r (its foot on the edge), and where it comes within
-- r of the edge's end (the school formula); the least, or 0 when it starts within r.
function baseline.polygonCircleCast(points, cx, cy, r, dx, dy)
  local n = #points
  local w = 0
  for i = 1, n - 1, 2 do
    local j = i + 2 > n and 1 or i + 2
    w = w + points[i] * points[j + 1] - points[j] * points[i + 1]
  end
  w = w > 0 and 1 or -1
  local best, bnx, bny, inside = math.huge, 0, 0, true
  local ax, ay = points[n - 1], points[n]
  local qa = dx * dx + dy * dy
  for i = 1, n - 1, 2 do
    local bx, by = points[i], points[i + 1]
    local ex, ey = bx - ax, by - ay
    local len = sqrt(ex * ex + ey * ey)
    local nx, ny = w * ey / len, -w * ex / len
    local h0 = (cx - ax) * nx + (cy - ay) * ny
    local s0 = ((cx - ax) * ex + (cy - ay) * ey) / (len * len)
    if h0 > 0 then inside = false end
    if h0 >= 0 and h0 < r and s0 >= 0 and s0 <= 1 then return 0, nx, ny end
    local h1 = dx * nx + dy * ny
    if h1 < 0 and h0 >= r then
      local t = (h0 - r) / -h1
      local s = ((cx + t * dx - ax) * ex + (cy + t * dy - ay) * ey) / (len * len)
      if t <= 1 and s >= 0 and s <= 1 and t < best then best, bnx, bny = t, nx, ny end
    end
    local fx, fy = cx - bx, cy - by
    local p, c = fx * dx + fy * dy, fx * fx + fy * fy - r * r
    if c < 0 then return 0, fx / sqrt(fx * fx + fy * fy), fy / sqrt(fx * fx + fy * fy) end
    local disc = p * p - qa * c
    if qa > 0 and disc > 0 and p < 0 then
      local t = (-p - sqrt(disc)) / qa
      if t <= 1 and t < best then best, bnx, bny = t, (fx + t * dx) / r, (fy + t * dy) / r end
    end
    ax, ay = bx, by
  end
  if inside then return 0, 1, 0 end
  if best == math.huge then return false end
  return best, bnx, bny
end

-- The tutorial's class, reduced to what the benchmark times.
local Polygon = {}
Polygon.__index = Polygon
function Polygon.new(points) return setmetatable({ points = points }, Polygon) end
-- As in the tutorial, the method reads self.points afresh at every step.
function Polygon:contains(x, y)
  if #self.points < 6 then return false end
  local x1, y1 = self.points[#self.points - 1], self.points[#self.points]
  local x2, y2 = self.points[1], self.points[2]
  local inside = false
  for i = 1, #self.points - 1, 2 do
    if ((y1 >= y) ~= (y2 >= y)) and (x <= (x2 - x1) * (y - y1) / (y2 - y1) + x1) then
      inside = not inside
    end
    x1, y1 = x2, y2
    x2, y2 = self.points[i + 2], self.points[i + 3]
  end
  return inside
end
baseline.Polygon = Polygon

return baseline
