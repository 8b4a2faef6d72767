-- A small scene of polygons and a circle, run with plain Lua (no LÖVE):
--   lua5.4 examples/scene.lua        (from the repository root; or with polygon installed)
-- It prints each shape's measures, a few point queries, every colliding pair with the
-- displacement that separates it, and the scene after applying those displacements.
package.path = "./?.lua;" .. package.path
local polygon = require "polygon"

-- Screen coordinates: y grows downwards.
local shapes = {
  { name = "crate",  points = { 100, 100, 160, 100, 160, 160, 100, 160 } },
  { name = "wedge",  points = { 150, 150, 220, 150, 150, 200 } },
  { name = "hexagon", points = { 300, 100, 330, 117, 330, 152, 300, 170, 270, 152, 270, 117 } },
  { name = "floor",  points = { 0, 240, 400, 240, 400, 260, 0, 260 }, static = true },
  { name = "boulder", points = { 40, 210, 80, 200, 100, 230, 70, 250, 35, 240 } },
  { name = "arrow",  points = { 250, 10, 290, 30, 250, 50, 262, 30 } },   -- concave
}
local ball = { name = "ball", x = 310, y = 172, r = 12 }

local function fmt(x) return ("%.2f"):format(x) end

print("shapes")
for _, s in ipairs(shapes) do
  local cx, cy = polygon.polygonCenter(s.points)
  print(("  %-8s winding %-3s  area %8s  %-7s  centre (%s, %s)"):format(s.name,
    polygon.polygonWindingOrder(s.points), fmt(polygon.polygonArea(s.points)),
    polygon.polygonType(s.points), fmt(cx), fmt(cy)))
end

print("point queries")
local queries = { { 130, 130 }, { 160, 130 }, { 100, 130 }, { 262, 30 }, { 270, 30 }, { 300, 135 } }
for _, q in ipairs(queries) do
  local inside = {}
  for _, s in ipairs(shapes) do
    if polygon.polygonContains(s.points, q[1], q[2]) then inside[#inside + 1] = s.name end
  end
  print(("  (%d, %d) is in: %s"):format(q[1], q[2], #inside > 0 and table.concat(inside, ", ") or "nothing"))
end

-- Collisions are for convex shapes: the concave arrow takes part in none.
local function collisions()
  local found = {}
  for i = 1, #shapes do
    local a = shapes[i]
    if polygon.polygonType(a.points) == "convex" then
      for j = i + 1, #shapes do
        local b = shapes[j]
        if polygon.polygonType(b.points) == "convex" then
          local overlap, dx, dy = polygon.polygonsCollideV(a.points, b.points)
          if overlap then found[#found + 1] = { a, b, overlap, dx, dy } end
        end
      end
      local overlap, dx, dy = polygon.polygonCircleCollideV(a.points, ball.x, ball.y, ball.r)
      if overlap then found[#found + 1] = { a, ball, overlap, dx, dy } end
    end
  end
  return found
end

local function move(shape, dx, dy)
  if shape.points then
    polygon.polygonTranslate(shape.points, dx, dy, shape.points) -- in place: out is points
  else
    shape.x, shape.y = shape.x + dx, shape.y + dy
  end
end

print("colliding pairs")
local pairsFound = collisions()
for _, c in ipairs(pairsFound) do
  print(("  %s and %s overlap by %s: move %s by (%s, %s)"):format(c[1].name, c[2].name,
    fmt(c[3]), c[2].name, fmt(c[4]), fmt(c[5])))
end
if #pairsFound == 0 then print("  none") end

-- Resolve: move the second shape of each pair out of the first, or the first back by the opposite
-- vector when the second is static (the floor). Pushing one shape out can push it into another,
-- so repeat a few rounds.
local rounds = 0
repeat
  local found = collisions()
  for _, c in ipairs(found) do
    if c[2].static then move(c[1], -c[4], -c[5]) else move(c[2], c[4], c[5]) end
  end
  rounds = rounds + 1
until #found == 0 or rounds == 10

print(("after resolving (%d rounds)"):format(rounds))
for _, s in ipairs(shapes) do
  local cx, cy = polygon.polygonCenter(s.points)
  print(("  %-8s centre (%s, %s)"):format(s.name, fmt(cx), fmt(cy)))
end
print(("  %-8s centre (%s, %s)"):format(ball.name, fmt(ball.x), fmt(ball.y)))
local left = collisions()
print(#left == 0 and "no colliding pairs left" or (#left .. " colliding pairs left"))
