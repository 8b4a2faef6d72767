--- Test points for the specs: points on, at and a few ulps beside the edges and vertices of a polygon.
-- Whether a point is exactly on an edge is never assumed here; the oracle decides that.

local exact = require "exact"

local probe = {}

--- The edges of a polygon (flat array) as { x1, y1, x2, y2 }, the closing edge last.
function probe.edges(points)
  local list = {}
  local n = #points
  for i = 1, n - 1, 2 do
    local j = i + 2 > n and 1 or i + 2
    list[#list + 1] = { points[i], points[i + 1], points[j], points[j + 1] }
  end
  return list
end

--- The doubles k steps away from x: k = -2, -1, 1, 2 give two below, one below, ...
function probe.step(x, k)
  for _ = 1, math.abs(k) do
    x = k > 0 and exact.nextUp(x) or exact.nextDown(x)
  end
  return x
end

local STEPS = { -2, -1, 1, 2 }

--- Points along the edge e = { x1, y1, x2, y2 }: x1 + t (x2 - x1), y1 + t (y2 - y1) for each t in ts
-- (rounded, so on the edge or a rounding away from it), each also moved by one and two ulps left,
-- right, up and down. Appended to list (a new one when nil), which is returned.
function probe.around(e, ts, list)
  list = list or {}
  for _, t in ipairs(ts) do
    local x = e[1] + t * (e[3] - e[1])
    local y = e[2] + t * (e[4] - e[2])
    list[#list + 1] = { x, y }
    for _, k in ipairs(STEPS) do
      list[#list + 1] = { probe.step(x, k), y }
      list[#list + 1] = { x, probe.step(y, k) }
    end
  end
  return list
end

--- The list without repeated points.
function probe.distinct(list)
  local seen, out = {}, {}
  for _, p in ipairs(list) do
    local key = ("%.17g,%.17g"):format(p[1], p[2])
    if not seen[key] then
      seen[key] = true
      out[#out + 1] = p
    end
  end
  return out
end

--- Points on, at and beside every edge and vertex of the polygon (distinct).
function probe.pointsNear(points, ts)
  local list = {}
  for _, e in ipairs(probe.edges(points)) do
    probe.around(e, ts or { 0, 0.25, 0.5, 0.75 }, list)
  end
  return probe.distinct(list)
end

return probe
