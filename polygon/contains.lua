-- polygon/contains.lua: point in polygon by the crossing rule, each edge's side decided exactly
-- (kernel's cross).

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local check = require(_PACKAGE .. ".check")

local abs, min, max = math.abs, math.min, math.max
local CROSS_BOUND, cross, JIT = kernel.CROSS_BOUND, kernel.cross, kernel.JIT
local checkPoints, checkNumber = check.checkPoints, check.checkNumber
local shapeBehind = check.shapeBehind

local M = {}


-- W. R. Franklin's crossing rule, as in the tutorial: count the edges crossed by the ray from
-- (x, y) to the right. An edge counts when (y1 >= y) ~= (y2 >= y) and x <= the edge's x at height
-- y. That half-open rule puts a point on an edge shared by two polygons in exactly one of them.
-- The tutorial divides to find the edge's x; here the comparison is the exact side test
-- x <= x'  <=>  (p2 - p1) x (q - p1) >= 0 when the edge goes down (y2 > y1), <= 0 when it goes up.
-- The walk carries whether the last vertex was at or below the ray's height (y >= the ray's y,
-- screen down) and reads an edge's x coordinates only where it crosses. x and y are converted
-- (+ 0.0), and so is every coordinate the walks subtract (cross converts its own), so that Lua
-- 5.3+ integers count as the doubles they convert to. Two walks, computing the same answer
-- (spec/bodies_sat_spec.lua compares them, and containsShort4 to containsShort16, below):
-- - containsByRuns, LuaJIT's (and PUC Lua's for |x| or |y| >= 2^53): the vertices come in runs
--   on one side of the ray's height, each walked by one numeric for loop with one comparison
--   per vertex, the same loop for both sides (a sign picks the side), so that LuaJIT's trace
--   of it is the walk that crosses nothing, whatever vertex it was recorded on; a crossing is
--   its side exit, counted without a branch by crossingCounts, and the walk goes on in the same
--   loop. One loop for both sides, not one each: when one of two short loops failed to become
--   a trace, the other's side traces copied it unrolled, one per run length, until LuaJIT gave
--   up.
-- - PUC Lua's, written out in polygonContains (no call: a call costs more than a vertex's
--   work): per vertex one read and two comparisons, and at a crossing the x coordinates
--   compared with x first, the side test (a call of cross) only when x lies between them. The
--   coordinates are compared as they are, not converted (an instruction less each): comparing
--   a Lua 5.3+ integer with a double below 2^53 in magnitude gives the converted integer's
--   answer (the integer is then compared as its exact double, or it is beyond 2^53 and so is
--   its conversion, on the same side).
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
      -- (NaN and overflow too) through cross, not crossExact directly: the side traces of
      -- crossExact's first branch failed to compile when called from here
      side = cross(x1, y1, x2, y2, x1, y1, x, y)
    end
    return min(1, max(0, dir * side * 2^600 + 1))
  end

  containsByRuns = function(points, n, x, y)
    -- A run of vertices at or below the ray's height (sign = 2^600, tie = 0) ends at a vertex
    -- with (y' - y) 2^600 < 0; a run above it (sign = -2^600, tie = 2^-500) at one with
    -- -(y' - y) 2^600 < 2^-500, that is y' - y >= 0 (a nonzero difference of doubles is at least
    -- 2^-1074). The edge into that vertex crosses, going up after a run at or below (dir =
    -- -sign), down after one above. The numbers stay clear of subnormals, slow on x86 (a tie
    -- of 2^-1074 is a subnormal). y' - y converts a Lua 5.3+ integer y'.
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
-- g det 2^1000 clamps to 1 or 0 exactly. Straight-line code, not a loop: a loop of a few steps
-- often fails to become a trace of its own, and the traces reaching it then copy it unrolled,
-- with a side exit for every other size. worst is a sum, not a max: 0 times an infinite bound
-- is NaN, which a max can drop (a wrong answer); the sum keeps it, and containsByRuns decides.
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
-- constant k into constant indices (fewer machine instructions than min(k, n) everywhere).
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

local function containsShort4(points, n, x, y)
  local dx1, dy1, a1, m1 = vertexFrom(points, 2, x, y)
  local count, worst, total, dx, dy, a, m = firstSteps(points, n, x, y, dx1, dy1, a1, m1)
  return lastEdge(points, n, x, y, count, worst, total, dx, dy, a, m, dx1, dy1, a1, m1)
end

local function containsShort8(points, n, x, y)
  local dx1, dy1, a1, m1 = vertexFrom(points, 2, x, y)
  local count, worst, total, dx, dy, a, m = firstSteps(points, UNCLAMPED, x, y, dx1, dy1, a1, m1)
  count, worst, total, dx, dy, a, m = fourSteps(points, 10, n, x, y, count, worst, total, dx, dy, a, m)
  return lastEdge(points, n, x, y, count, worst, total, dx, dy, a, m, dx1, dy1, a1, m1)
end

local function containsShort12(points, n, x, y)
  local dx1, dy1, a1, m1 = vertexFrom(points, 2, x, y)
  local count, worst, total, dx, dy, a, m = firstSteps(points, UNCLAMPED, x, y, dx1, dy1, a1, m1)
  count, worst, total, dx, dy, a, m =
    fourSteps(points, 10, UNCLAMPED, x, y, count, worst, total, dx, dy, a, m)
  count, worst, total, dx, dy, a, m = fourSteps(points, 18, n, x, y, count, worst, total, dx, dy, a, m)
  return lastEdge(points, n, x, y, count, worst, total, dx, dy, a, m, dx1, dy1, a1, m1)
end

local function containsShort16(points, n, x, y)
  local dx1, dy1, a1, m1 = vertexFrom(points, 2, x, y)
  local count, worst, total, dx, dy, a, m = firstSteps(points, UNCLAMPED, x, y, dx1, dy1, a1, m1)
  count, worst, total, dx, dy, a, m =
    fourSteps(points, 10, UNCLAMPED, x, y, count, worst, total, dx, dy, a, m)
  count, worst, total, dx, dy, a, m =
    fourSteps(points, 18, UNCLAMPED, x, y, count, worst, total, dx, dy, a, m)
  count, worst, total, dx, dy, a, m = fourSteps(points, 26, n, x, y, count, worst, total, dx, dy, a, m)
  return lastEdge(points, n, x, y, count, worst, total, dx, dy, a, m, dx1, dy1, a1, m1)
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

-- Whether (x, y) lies inside the polygon, by the crossing rule with the tutorial's half-open
-- boundary. Works for concave and self-intersecting polygons (even-odd). Exact. x and y must be
-- finite (an error otherwise); the polygon's coordinates are not checked (validate does that).
-- Returns true or false; false for fewer than 3 points.
local function polygonContains(points, x, y)
  -- the checks written out where they pass (a Lua call costs more than them)
  local n = type(points) == "table" and #points or -1
  if n % 2 ~= 0 or type(x) ~= "number" or type(y) ~= "number" or x - x ~= 0 or y - y ~= 0 then
    checkQuery("polygonContains", points, x, y, 3)
  end
  if n < 6 then   -- a Polygon object: its points (point tables raise)
    local inner = type(points[1]) ~= "number" and shapeBehind(points, "polygonContains", "points", 2)
    if inner then
      local inside = polygonContains(inner, x, y)
      return inside
    end
    return false
  end
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
M.polygonContains = polygonContains

M.checkQuery = checkQuery
M.containsByRuns = containsByRuns
M.containsShort4 = containsShort4
M.containsShort8 = containsShort8
M.containsShort12 = containsShort12
M.containsShort16 = containsShort16
M.polygonContains = polygonContains

return M
