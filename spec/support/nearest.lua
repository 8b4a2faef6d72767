--- Exact nearest points of a polygon's boundary, for the specs of polygonClosestPoint: real
-- arithmetic on the given doubles (spec/support/exact.lua), sharing no code with polygon.lua.
-- The squared distance to each edge is a fraction num / den of exact values: to an end |p - v|^2,
-- to the foot of the perpendicular (when (p - a).e > 0 and (p - b).(a - b) > 0) c^2 / |e|^2,
-- c = e x (p - a); the least of them, and its points, by cross-multiplication.

local exact = require "exact"
local oracle = require "oracle"

local new, add, sub, mul, sign, compare = exact.new, exact.add, exact.sub, exact.mul, exact.sign,
  exact.compare

local nearest = {}

local EPS = 2 ^ -53

-- The squared distance from (x, y) to the segment a -> b: num, den (den > 0) and the nearest
-- point as (X / den, Y / den).
local function toSegment(ax, ay, bx, by, x, y)
  local Ax, Ay, Bx, By, Px, Py = new(ax), new(ay), new(bx), new(by), new(x), new(y)
  local ex, ey = sub(Bx, Ax), sub(By, Ay)
  local wx, wy = sub(Px, Ax), sub(Py, Ay)
  local along = add(mul(ex, wx), mul(ey, wy))
  local length = add(mul(ex, ex), mul(ey, ey))
  local ONE = new(1)
  if sign(along) <= 0 or sign(length) == 0 then
    return add(mul(wx, wx), mul(wy, wy)), ONE, Ax, Ay
  end
  if compare(along, length) >= 0 then
    local vx, vy = sub(Px, Bx), sub(Py, By)
    return add(mul(vx, vx), mul(vy, vy)), ONE, Bx, By
  end
  local c = sub(mul(ex, wy), mul(ey, wx))
  -- the foot a + (along / length) e = (a length + along e) / length
  return mul(c, c), length, add(mul(Ax, length), mul(along, ex)), add(mul(Ay, length), mul(along, ey))
end

--- Whether polygonClosestPoint's answer px, py, distance is right for the polygon and (x, y):
-- the sign exact (0 exactly on the boundary, negative exactly inside by the crossing rule), the
-- distance within 8 eps M of the least exact distance, and (px, py) within 8 eps M of the
-- nearest point of an edge at that least distance (M over the polygon and the point). Returns
-- true, or false and why.
function nearest.check(points, x, y, px, py, distance)
  local n = #points / 2
  local M = math.max(math.abs(x), math.abs(y))
  for i = 1, #points do M = math.max(M, math.abs(points[i])) end
  local tol = new(8 * EPS * M)
  -- the least squared distance, and every edge's
  local edges, bestNum, bestDen = {}, nil, nil
  for i = 1, n do
    local j = i % n + 1
    local num, den, X, Y = toSegment(points[2 * i - 1], points[2 * i], points[2 * j - 1], points[2 * j], x, y)
    edges[i] = { num, den, X, Y }
    if not bestNum or compare(mul(num, bestDen), mul(bestNum, den)) < 0 then bestNum, bestDen = num, den end
  end
  local onBoundary = sign(bestNum) == 0
  if onBoundary then
    if not (distance == 0 and px == x and py == y) then return false, "on the boundary: expected x, y, 0" end
    return true
  end
  if distance == 0 then return false, "distance 0 off the boundary" end
  local inside = oracle.contains(points, x, y)
  if (distance < 0) ~= inside then return false, "the sign" end
  -- (|d| - tol)^2 <= D^2 <= (|d| + tol)^2, D^2 = bestNum / bestDen
  local d = new(math.abs(distance))
  local hi = add(d, tol)
  if compare(bestNum, mul(mul(hi, hi), bestDen)) > 0 then return false, "the distance (too short)" end
  local lo = sub(d, tol)
  if sign(lo) > 0 and compare(mul(mul(lo, lo), bestDen), bestNum) > 0 then
    return false, "the distance (too long)"
  end
  -- the point near the nearest point of an edge at the least distance
  local P = { new(px), new(py) }
  for _, e in ipairs(edges) do
    if compare(mul(e[1], bestDen), mul(bestNum, e[2])) == 0 then
      local gx, gy = sub(mul(P[1], e[2]), e[3]), sub(mul(P[2], e[2]), e[4])
      local bound = mul(tol, e[2])
      if compare(add(mul(gx, gx), mul(gy, gy)), mul(bound, bound)) <= 0 then return true end
    end
  end
  return false, "the point is near no nearest point"
end

return nearest
