-- polygon/object.lua: validate (the full O(n) check) and the Polygon object, whose contains is
-- polygonContains.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local contains = require(_PACKAGE .. ".contains")
local check = require(_PACKAGE .. ".check")

local huge = math.huge
local checkQuery, polygonContains = contains.checkQuery, contains.polygonContains

local M = {}


-- Checks everything about a polygon: a table, an even count, at least 3 points, every
-- coordinate a finite number. O(n), so the per-frame functions keep to O(1) checks.
-- Returns true, or nil and a message
function M.validate(points)
  if type(points) ~= "table" then
    return nil, "points must be a table, got " .. type(points)
  end
  if getmetatable(points) == check.Polygon then points = rawget(points, "points") end   -- its points
  if type(points) ~= "table" then
    return nil, "points must be a table, got " .. type(points)
  end
  local first = points[1]
  if type(first) == "table" and (first.x ~= nil or #first == 2) then
    return nil, "points holds point tables; pass a flat array {x1, y1, x2, y2, ...}"
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

local validate = M.validate

-- A polygon object holding the caller's points table (not a copy). Its class table is check's,
-- so that every function taking a polygon knows it (check.shapeBehind).
local Polygon = check.Polygon
Polygon.__index = Polygon

local function newPolygon(points, level)
  if getmetatable(points) == Polygon then points = rawget(points, "points") end   -- a copy of one
  local ok, message = validate(points)
  if not ok then error("Polygon.new: " .. message, level + 1) end
  -- not a tail call: after a tail call to setmetatable (a built-in with side effects) LuaJIT
  -- had no snapshot for the return past the frame where validate's loop trace began, and every
  -- trace leaving that loop aborted ("NYI: return to lower frame")
  local p = setmetatable({ points = points }, Polygon)
  return p
end

-- Polygon.new(points), also Polygon(points): validates, then wraps points.
function Polygon.new(points)
  local p = newPolygon(points, 2)   -- not a tail call, so the error level is the same everywhere
  return p
end

-- Whether (x, y) lies inside, as polygonContains.
function Polygon:contains(x, y)
  local points = self.points
  -- polygonContains' checks, naming this method (there they pass again)
  local n = type(points) == "table" and #points or -1
  if n % 2 ~= 0 or type(x) ~= "number" or type(y) ~= "number" or x - x ~= 0 or y - y ~= 0 then
    checkQuery("Polygon:contains", points, x, y, 3)
  end
  if n < 6 and type(points[1]) == "table" then   -- point tables: refused naming this method
    check.shapeBehind(points, "Polygon:contains", "points", 2)
  end
  local inside = polygonContains(points, x, y)
  return inside
end

-- The points of a Polygon object, or nil for anything else: the functions that take a polygon
-- take the object too and use its points (called only where a shape's first entry is not a
-- number, so flat arrays pay nothing).
local function objectPoints(shape)
  if getmetatable(shape) == Polygon then return rawget(shape, "points") end
  return nil
end
M.objectPoints = objectPoints

setmetatable(Polygon, { __call = function(_, points)
  local p = newPolygon(points, 2)
  return p
end })
M.Polygon = Polygon

M.validate = validate

return M
