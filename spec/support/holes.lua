--- Random outlines with random holes, of the shapes game levels are made of: a triangle with a
-- small hole, a star-shaped outline with a few small convex holes (some snapped onto a vertex of
-- the outline or of another hole, so that they touch there), and a tile map's outline with its
-- enclosed gaps. Nothing here decides whether a case is valid: oracle.regionCrossing does.
-- Shares no code with polygon.lua.

local shapes = require "shapes"
local tiles = require "tiles"

local holes = {}

local OFFSETS = { 0, 0, 0, 1e5 + 0.375, 1e9 + 0.375 }

local function rounded(points)
  for i = 1, #points do points[i] = math.floor(points[i] + 0.5) end
  return points
end

-- A small convex hole of 3 or 4 vertices around a random point of the box x0..x1, y0..y1.
local function smallHole(rng, x0, y0, x1, y1, size)
  local cx, cy = rng:int(x0, x1), rng:int(y0, y1)
  local hole = rounded(shapes.convex(rng, rng:int(3, 4), cx, cy, size, 0.3))
  return hole
end

-- Moves one vertex of `hole` onto a vertex of one of `rings`, so that the two touch there (or
-- cross: the oracle says which).
local function snap(rng, hole, rings)
  local ring = rings[rng:int(1, #rings)]
  local v, w = rng:int(1, #ring / 2), rng:int(1, #hole / 2)
  hole[2 * w - 1], hole[2 * w] = ring[2 * v - 1], ring[2 * v]
end

--- One case: points, holes (a list of flat arrays) and its kind's name.
function holes.case(rng)
  local kind = rng:int(1, 10)
  local points, list, name
  if kind <= 3 then   -- a triangle with one small triangular hole, as in issue 28
    name = "triangle"
    points = {}
    for i = 1, 6 do points[i] = rng:int(0, 200) end
    -- its centre at a random point of the triangle (barycentric weights), or anywhere
    local u, v = rng:float(), rng:float()
    if u + v > 1 then u, v = 1 - u, 1 - v end
    local cx = points[1] + u * (points[3] - points[1]) + v * (points[5] - points[1])
    local cy = points[2] + u * (points[4] - points[2]) + v * (points[6] - points[2])
    if rng:int(1, 8) == 1 then cx, cy = rng:int(0, 200), rng:int(0, 200) end
    list = { rounded(shapes.convex(rng, 3, cx, cy, rng:int(2, 6), 0.3)) }
  elseif kind <= 8 then   -- a star-shaped outline with a few small holes
    name = "star"
    points = rounded(shapes.star(rng, rng:int(5, 30), 500, 500, 400))
    list = {}
    for h = 1, rng:int(1, 8) do
      -- most well inside (the star's radius is at least 120), some anywhere in its box
      local reach = rng:int(1, 6) == 1 and 350 or 100
      local hole = smallHole(rng, 500 - reach, 500 - reach, 500 + reach, 500 + reach, rng:int(3, 12))
      if rng:int(1, 4) == 1 then
        local rings = { points }
        for g = 1, h - 1 do rings[#rings + 1] = list[g] end
        snap(rng, hole, rings)
      end
      list[h] = hole
    end
  else   -- a tile map: the largest outline and every enclosed gap as a hole
    name = "tiles"
    local set = tiles.random(rng, rng:int(3, 9), rng:int(3, 9), 0.75)
    local best
    for _, shape in ipairs(tiles.shapes(set, 10, 0, 0)) do
      if not best or #shape[1] > #best[1] then best = shape end
    end
    if not best then return holes.case(rng) end
    points, list = best[1], best[2]
    -- tile maps give their holes only to the outline around them: the gaps inside, always
    if #list == 0 then return holes.case(rng) end
  end
  local offset = OFFSETS[rng:int(1, #OFFSETS)]
  if offset ~= 0 then
    points = shapes.translate(points, offset, offset)
    list = shapes.translateEach(list, offset, offset)
  end
  if rng:int(1, 2) == 1 then list[1] = shapes.reverse(list[1]) end   -- holes wound either way
  return points, list, name
end

--- A rectangle with small holes inside and one or two holes with a vertex on one of its edges
-- (the hole touches the outline there, inside an edge). Such a hole's leftmost vertex on the
-- top or bottom edge casts its ray along that edge, to the corner, where the holes further left
-- have often joined already: the case whose answer once depended on the order the corner's
-- nodes were met in. Every coordinate is an integer, so the touching vertex lies on the edge
-- exactly.
function holes.onEdge(rng)
  local w, h = 4 * rng:int(50, 300), 4 * rng:int(50, 300)
  local x0, y0 = 0, 0
  if rng:int(1, 3) == 1 then x0, y0 = 2 ^ 20, -2 ^ 20 end
  local points = { x0, y0, x0 + w, y0, x0 + w, y0 + h, x0, y0 + h }
  local list = {}
  for i = 1, rng:int(0, 5) do
    list[i] = smallHole(rng, x0 + w / 8, y0 + h / 8, x0 + w - w / 8, y0 + h - h / 8, rng:int(3, 12))
  end
  for _ = 1, rng:int(1, 2) do
    -- a vertex at a quarter, half or three quarters of an edge, and two more inside
    local side, t, s = rng:int(1, 4), rng:int(1, 3), 2 * rng:int(2, 15)
    local hole
    if side == 1 then       -- top: the vertex leftmost
      local x = x0 + t * w / 4
      hole = { x, y0, x + s, y0 + s / 2, x + s / 2, y0 + s }
    elseif side == 2 then   -- bottom
      local x = x0 + t * w / 4
      hole = { x, y0 + h, x + s / 2, y0 + h - s, x + s, y0 + h - s / 2 }
    elseif side == 3 then   -- left
      local y = y0 + t * h / 4
      hole = { x0, y, x0 + s, y - s / 2, x0 + s, y + s / 2 }
    else                    -- right
      local y = y0 + t * h / 4
      hole = { x0 + w, y, x0 + w - s, y + s / 2, x0 + w - s, y - s / 2 }
    end
    if rng:int(1, 2) == 1 then hole = shapes.reverse(hole) end
    list[#list + 1] = hole
  end
  return points, list
end

return holes
