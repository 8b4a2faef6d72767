-- polygon/transform.lua: bounds, translation and rotation of flat arrays and lists of parts, into
-- new tables or the caller's `out`.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local views = require(_PACKAGE .. ".views")
local check = require(_PACKAGE .. ".check")
local measures = require(_PACKAGE .. ".measures")

local huge, sin, cos = math.huge, math.sin, math.cos
local isParts = views.isParts
local checkPoints, checkFiniteNumber = check.checkPoints, check.checkFiniteNumber
local shapeBehind = check.shapeBehind
local centroidOf, polygonArea = measures.centroidOf, measures.polygonArea

local M = {}

-- A shape here is a flat array {x1, y1, ...} or a list of convex parts {part1, part2, ...}, each
-- part a flat array; isParts (polygon/views.lua) tells them apart by the first entry.


-- Checks a list of parts: every entry a table with an even count. Returns their number. level as
-- in checkPoints, counted from here. The messages are built only on the error path (no garbage).
-- Whether shape is a list of {x, y} pairs: bounded, moved and turned as parts of one point
-- each, as ever (every coordinate is read right), so not refused here.
local function pointPairs(shape)
  local first = shape[1]
  return type(first) == "table" and #first == 2 and first.x == nil
end

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

-- The axis-aligned bounding box, the box a broadphase sorts shapes by. Allocates nothing.
-- points: flat array {x1, y1, ...}, or a list of convex parts {part1, part2, ...}
-- Returns minx, miny, maxx, maxy (the box of all parts for a list); nil for no points.
-- Coordinates are taken as finite (validate checks that): a NaN coordinate is skipped.
function M.polygonBounds(points)
  local fname = "polygonBounds"
  local minx, miny, maxx, maxy = huge, huge, -huge, -huge
  if type(points) == "table" and type(points[1]) ~= "number" and not pointPairs(points) then
    -- a Polygon object: its points; {x =, y =} tables raise
    points = shapeBehind(points, fname, "points", 2) or points
  end
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

-- The polygon moved by (dx, dy).
-- points: flat array, or a list of convex parts
-- out: optional: the table to write the result into, reused from frame to frame so that a
--   call allocates nothing; it may be points itself (moves in place). For a list of parts, out is
--   a list of part tables (missing ones are created, the first time only). Without out the
--   result is a NEW table (a new list of new parts): fine once, garbage every frame.
-- Returns out. Each coordinate is rounded once (x + dx).
function M.polygonTranslate(points, dx, dy, out)
  local fname = "polygonTranslate"
  if type(points) == "table" and type(points[1]) ~= "number" and not pointPairs(points) then
    -- a Polygon object: its points; {x =, y =} tables raise
    points = shapeBehind(points, fname, "points", 2) or points
  end
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
  -- centroidOf, so that a non-finite coordinate's error names polygonRotate (level 5: from
  -- checkFinitePoints through centroidOf, here and polygonRotate to its caller)
  if not parts then
    local cx, cy
    if count >= 6 then cx, cy = centroidOf(points, count, "polygonRotate", 5) end
    if cx then return cx, cy end
    sumX, sumY, m = addVertices(points, count, sumX, sumY, m)
  else
    local wx, wy, total = 0.0, 0.0, 0.0
    for k = 1, count do
      local part = points[k]
      local cx, cy
      if #part >= 6 then cx, cy = centroidOf(part, #part, "polygonRotate", 5) end
      if cx then
        local area = polygonArea(part)
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

-- The polygon turned by angle (radians) about (ox, oy), by default its area centroid (for a list
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
-- points: flat array, or a list of convex parts
-- ox, oy: optional pivot (both or neither)
-- out: optional table to write into, as in polygonTranslate (reused: no allocation; may
--   be points itself; without it the result is a NEW table). May come third: (points, angle, out).
-- Returns out
function M.polygonRotate(points, angle, ox, oy, out)
  local fname = "polygonRotate"
  if type(ox) == "table" and oy == nil and out == nil then ox, out = nil, ox end
  if type(points) == "table" and type(points[1]) ~= "number" and not pointPairs(points) then
    -- a Polygon object: its points; {x =, y =} tables raise
    points = shapeBehind(points, fname, "points", 2) or points
  end
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


return M
