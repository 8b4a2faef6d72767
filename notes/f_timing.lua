-- Throwaway timing of compound collisions against the convex pair calls they need.
-- Run from the worktree root: luajit notes/f_timing.lua 100000; lua5.4 notes/f_timing.lua 20000
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local polygon = require "polygon"
local parts = require "parts"
local clock = os.clock
local floor = parts.floor(20, 10, 100, 0)
local crates = {}
for k = 0, 99 do crates[#crates + 1] = parts.box(k * 1.91, 95, 8, 8) end   -- sunk 3, all along
local corner = { parts.box(0, 0, 10, 100), parts.box(10, 90, 100, 10) }
local cornerCrates = {}
for k = 0, 99 do cornerCrates[#cornerCrates + 1] = parts.box(5 + k * 0.03, 85, 8, 8) end
local N = tonumber(arg[1]) or 20000
local function time(name, body)
  body(1)
  local t0 = clock()
  local sum = 0
  for i = 1, N do sum = sum + (body(i) or 0) end
  local dt = clock() - t0
  print(("%-44s %8.2f us/call  (checksum %.6g)"):format(name, dt / N * 1e6, sum))
  return dt
end
local V, B = polygon.polygonsCollideV, polygon.polygonsCollide
-- the convex pair calls the compound call needs: the crate against the parts its box overlaps
local function pairsFor(c)
  local list = {}
  for _, p in ipairs(floor) do
    if p[1] < c[3] and c[1] < p[3] then list[#list + 1] = p end
  end
  return list
end
local needed = {}
for k, c in ipairs(crates) do needed[k] = pairsFor(c) end
for round = 1, 2 do
  print("round", round)
  time("compound V: crate vs 20-part floor", function(i) return (V(floor, crates[i % 100 + 1])) end)
  time("sum of convex V pair calls it needs", function(i)
    local c, s = crates[i % 100 + 1], 0
    for _, p in ipairs(needed[i % 100 + 1]) do s = s + (V(p, c) or 0) end
    return s
  end)
  time("naive loop: per part box, then V pair call", function(i)
    local c, s = crates[i % 100 + 1], 0
    local cx0, cy0, cx1, cy1 = c[1], c[2], c[5], c[6]
    for _, p in ipairs(floor) do
      local x0, y0, x1, y1 = math.huge, math.huge, -math.huge, -math.huge
      for j = 1, #p, 2 do
        local x, y = p[j], p[j + 1]
        if x < x0 then x0 = x end
        if x > x1 then x1 = x end
        if y < y0 then y0 = y end
        if y > y1 then y1 = y end
      end
      if x0 < cx1 and cx0 < x1 and y0 < cy1 and cy0 < y1 then s = s + (V(p, c) or 0) end
    end
    return s
  end)
  time("compound boolean: crate vs 20-part floor", function(i)
    return B(floor, crates[i % 100 + 1]) and 1 or 0
  end)
  time("sum of convex boolean pair calls", function(i)
    local c, s = crates[i % 100 + 1], 0
    for _, p in ipairs(needed[i % 100 + 1]) do s = s + (B(p, c) and 1 or 0) end
    return s
  end)
  time("compound V: crate in a concave corner", function(i) return (V(corner, cornerCrates[i % 100 + 1])) end)
  time("compound circle V: circle vs 20-part floor", function(i)
    return (polygon.polygonCircleCollideV(floor, 5 + (i % 100) * 1.9, 97, 5)) end)
  time("convex circle V: circle vs one part", function(i)
    local x = 5 + (i % 100) * 1.9
    return (polygon.polygonCircleCollideV(floor[math.floor(x / 10) + 1], x, 97, 5)) end)
end
