-- polygon/check.lua: the O(1) argument checks of the public functions, raised at the caller's
-- level.


local huge = math.huge

local M = {}


-- level: where the error points, counted from checkPoints (3: the caller of a public function).
-- isTable: the caller has seen that points is a table (a type call fewer: on PUC Lua each costs
-- about two Lua calls' time).
local function checkPoints(points, fname, argname, level, isTable)
  if not isTable and type(points) ~= "table" then
    error(("%s: %s must be a table, got %s"):format(fname, argname or "points", type(points)),
      level or 3)
  end
  local n = #points
  if n % 2 ~= 0 then
    if type(points[1]) == "table" and (points[1].x ~= nil or #points[1] == 2) then
      error(("%s: %s holds point tables; pass a flat array {x1, y1, x2, y2, ...}")
        :format(fname, argname or "points"), level or 3)
    end
    error(("%s: %s must hold an even number of coordinates, got %d")
      :format(fname, argname or "points", n), level or 3)
  end
  return n
end

local function checkNumber(v, fname, argname, level)
  if type(v) ~= "number" then
    error(("%s: %s must be a number, got %s"):format(fname, argname, type(v)), level or 3)
  end
end

-- Raises fname's error when points holds a NaN or an infinite coordinate (x - x is 0 exactly
-- for every finite x, NaN otherwise). O(n): only for the rare paths that a non-finite value
-- always reaches (a NaN or infinite sum, a failed filter). level as in checkPoints.
local function checkFinitePoints(points, n, fname, argname, level)
  for i = 1, n do
    local v = points[i]
    if v - v ~= 0 then
      error(("%s: %s holds a non-finite coordinate, got %s at [%d]")
        :format(fname, argname, tostring(v), i), level)
    end
  end
end

-- Checks that v is a number and finite (NaN and infinities named as such).
local function checkFiniteNumber(v, fname, argname, level)
  checkNumber(v, fname, argname, (level or 3) + 1)
  if v ~= v or v == huge or v == -huge then
    error(("%s: %s must be finite, got %s"):format(fname, argname, tostring(v)), level or 3)
  end
end

-- Checks that a radius is a finite number, not negative.
local function checkRadius(r, fname, argname)
  checkFiniteNumber(r, fname, argname, 4)
  if r < 0 then
    error(("%s: %s must not be negative, got %s"):format(fname, argname, tostring(r)), 3)
  end
end

-- The class of Polygon objects (object.lua gives it its methods), here so that every function
-- that takes a polygon can know one.
local Polygon = {}

-- What a function that read fewer than 3 points in `shape` (a table) takes instead: a Polygon
-- object's points (the caller computes again on them), else nil; raises fname's argument error
-- for a table of point tables. Called only on that rare path, so flat arrays pay nothing.
local function shapeBehind(shape, fname, argname, level)
  if getmetatable(shape) == Polygon then return rawget(shape, "points") end
  local first = shape[1]
  if type(first) == "table" and (first.x ~= nil or #first == 2) then
    error(("%s: %s holds point tables; pass a flat array {x1, y1, x2, y2, ...}")
      :format(fname, argname), level + 1)
  end
  return nil
end

M.Polygon = Polygon
M.shapeBehind = shapeBehind
M.checkPoints = checkPoints
M.checkFinitePoints = checkFinitePoints
M.checkNumber = checkNumber
M.checkFiniteNumber = checkFiniteNumber
M.checkRadius = checkRadius

return M
