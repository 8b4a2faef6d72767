-- Small table helpers shared by the per-concept specs. They build new tables from
-- flat point arrays {x1, y1, x2, y2, ...} and share no code with polygon.lua.
local shapes = {}

--- A new array with every vertex moved by (dx, dy).
function shapes.translate(points, dx, dy)
  local out = {}
  for i = 1, #points, 2 do
    out[i], out[i + 1] = points[i] + dx, points[i + 1] + dy
  end
  return out
end

--- A new array with the vertices in reverse order (the other winding).
function shapes.reverse(points)
  local out, n = {}, #points
  for i = 1, n, 2 do
    out[n - i], out[n - i + 1] = points[i], points[i + 1]
  end
  return out
end

--- A deep copy of any value (tables copied recursively, keys and values, metatable kept).
function shapes.deepcopy(value, seen)
  if type(value) ~= "table" then return value end
  seen = seen or {}
  if seen[value] then return seen[value] end
  local out = {}
  seen[value] = out
  for k, v in pairs(value) do
    out[shapes.deepcopy(k, seen)] = shapes.deepcopy(v, seen)
  end
  return setmetatable(out, getmetatable(value))
end

--- True when x is not NaN (NaN is the only value not equal to itself).
function shapes.isnumber(x)
  return type(x) == "number" and x == x
end

return shapes
