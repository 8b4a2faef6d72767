-- Shape helpers shared by the specs, the benchmark and the examples. They build new tables of
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

--- The bounding box of a flat array: xmin, ymin, xmax, ymax (math.huge, math.huge, -math.huge,
-- -math.huge when it has no vertex).
function shapes.bounds(points)
  local xmin, ymin, xmax, ymax = math.huge, math.huge, -math.huge, -math.huge
  for i = 1, #points - 1, 2 do
    xmin, xmax = math.min(xmin, points[i]), math.max(xmax, points[i])
    ymin, ymax = math.min(ymin, points[i + 1]), math.max(ymax, points[i + 1])
  end
  return xmin, ymin, xmax, ymax
end

--- The mean of the vertices of a flat array (summed in order, then divided): x, y.
function shapes.vertexMean(points)
  local sx, sy = 0, 0
  for i = 1, #points - 1, 2 do sx, sy = sx + points[i], sy + points[i + 1] end
  return sx / (#points / 2), sy / (#points / 2)
end

--- A new array with every coordinate multiplied by k (exact for k a power of two, barring
-- overflow and underflow).
function shapes.scale(points, k)
  local out = {}
  for i = 1, #points do
    out[i] = points[i] * k
  end
  return out
end

--- The largest coordinate magnitude of any of the given flat arrays (0 for none).
function shapes.largestMagnitude(...)
  local largest = 0
  for k = 1, select("#", ...) do
    local points = select(k, ...)
    for i = 1, #points do
      largest = math.max(largest, math.abs(points[i]))
    end
  end
  return largest
end

-- math.tointeger exists from Lua 5.3 on (rawget: luacheck's std is the common one).
local toInteger = rawget(math, "tointeger")

-- The spacing of doubles at magnitude m (an ulp of m, for m a normal double).
function shapes.ulp(m)
  local e = 1.0
  while e * 2 <= m do e = e * 2 end
  while e > m and e > 1e-300 do e = e / 2 end
  return e * 2 * 2^-53
end

--- x as a Lua integer on a Lua with an integer subtype (5.3, 5.4), else x itself; an error when
-- x has no integer value.
function shapes.integer(x)
  if not toInteger then return x end
  local i = toInteger(x)
  assert(i, "not an integer: " .. tostring(x))
  return i
end

--- A new array of shapes.integer of every value.
function shapes.integers(list)
  local out = {}
  for i, v in ipairs(list) do out[i] = shapes.integer(v) end
  return out
end

--- A new array of every value as a float (v + 0.0).
function shapes.floats(list)
  local out = {}
  for i, v in ipairs(list) do out[i] = v + 0.0 end
  return out
end

--- A new list of polygons, each moved by (dx, dy): a compound shape, or a benchmark's inputs.
function shapes.translateEach(list, dx, dy)
  local out = {}
  for k, points in ipairs(list) do
    out[k] = shapes.translate(points, dx, dy)
  end
  return out
end

--- A new list of polygons, each in the other winding.
function shapes.reverseEach(list)
  local out = {}
  for k, points in ipairs(list) do
    out[k] = shapes.reverse(points)
  end
  return out
end

--- A random convex polygon of m vertices around (cx, cy), clockwise on screen, drawn from rng
-- (spec/support/prng.lua): vertex i at angle (i - 1 + u_i) * 2 pi / m, u_i in -jitter .. jitter
-- (below 0.5 the angles keep increasing, so it stays convex), on an ellipse whose radii are size
-- times 0.5 .. 1.5 (drawn after the angles).
function shapes.convex(rng, m, cx, cy, size, jitter)
  local angles = {}
  for i = 1, m do
    angles[i] = (i - 1 + rng:range(-jitter, jitter)) * 2 * math.pi / m
  end
  local rx, ry = size * rng:range(0.5, 1.5), size * rng:range(0.5, 1.5)
  local out = {}
  for i = 1, m do
    out[2 * i - 1], out[2 * i] = cx + rx * math.cos(angles[i]), cy + ry * math.sin(angles[i])
  end
  return out
end

--- A deep copy of any value (tables copied recursively, keys and values, metatable kept).
function shapes.deepCopy(value, seen)
  if type(value) ~= "table" then return value end
  seen = seen or {}
  if seen[value] then return seen[value] end
  local out = {}
  seen[value] = out
  for k, v in pairs(value) do
    out[shapes.deepCopy(k, seen)] = shapes.deepCopy(v, seen)
  end
  return setmetatable(out, getmetatable(value))
end

--- True when x is not NaN (NaN is the only value not equal to itself).
function shapes.isNumber(x)
  return type(x) == "number" and x == x
end

--- A thick spiral strip: out along the outer edge, back along the inner; n vertices.
function shapes.spiral(n, turns)
  local half = n / 2
  local outer, inner = {}, {}
  for i = 0, half - 1 do
    local t = i / (half - 1) * turns * 2 * math.pi
    -- turns 50 apart (8 * 2 pi), the strip 30 wide: a gap of 20 between turns
    local r = 40 + 8 * t
    outer[#outer + 1], outer[#outer + 2] = r * math.cos(t), r * math.sin(t)
    inner[#inner + 1], inner[#inner + 2] = (r - 30) * math.cos(t), (r - 30) * math.sin(t)
  end
  local points = outer
  for i = #inner - 1, 1, -2 do
    points[#points + 1], points[#points + 2] = inner[i], inner[i + 1]
  end
  return points
end

--- A star-shaped polygon of m vertices around (ox, oy) drawn from rng: vertex k at the angle
-- (k + u) 2 pi / m, u in -0.4 .. 0.4, and the radius size (0.3 + v), v in 0 .. 1 (u, then v).
function shapes.star(rng, m, ox, oy, size)
  local points = {}
  for k = 1, m do
    local t, r = (k + 0.8 * (rng:float() - 0.5)) * 2 * math.pi / m, size * (0.3 + rng:float())
    points[#points + 1], points[#points + 2] = ox + r * math.cos(t), oy + r * math.sin(t)
  end
  return points
end

--- A star-shaped outline of n vertices with random radii in [0.6 R, 1.4 R]: simple, concave.
function shapes.noisyCircle(n, rng)
  local points = {}
  for i = 0, n - 1 do
    local t = 2 * math.pi * i / n
    local r = 1000 * (0.6 + 0.8 * rng:float())
    points[#points + 1], points[#points + 2] = r * math.cos(t), r * math.sin(t)
  end
  return points
end

return shapes
