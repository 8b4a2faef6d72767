--- Random compound scenes for the specs and measurements on compound shapes (deterministic, from
-- spec/support/prng.lua). Shares no code with polygon.lua.
local oracle = require "oracle"

local scenes = {}

--- A random convex polygon with up to m vertices on a circle of radius r around (cx, cy),
-- coordinates rounded to multiples of `grain`, clockwise on screen; nil if rounding spoiled it.
function scenes.convex(g, cx, cy, r, m, grain)
  local angles = {}
  for i = 1, m do angles[i] = g:float() * 2 * math.pi end
  table.sort(angles)
  local p = {}
  for i = 1, m do
    p[#p + 1] = cx + math.floor(r * math.cos(angles[i]) / grain + 0.5) * grain
    p[#p + 1] = cy + math.floor(r * math.sin(angles[i]) / grain + 0.5) * grain
  end
  if oracle.polygonType(p) ~= "convex" then return nil end
  return p
end

--- A list of `count` random convex parts in the square [0, span]^2 (some may overlap).
function scenes.cluster(g, count, span, r)
  local list = {}
  while #list < count do
    local p = scenes.convex(g, g:range(0, span), g:range(0, span), g:range(r / 3, r), g:int(3, 7), 1)
    if p then list[#list + 1] = p end
  end
  return list
end

--- A terrain: `count` columns of random widths side by side, each a convex quadrilateral with a
-- sloped top (shared corners: the columns' sides are seams), bottom at y = 100.
function scenes.terrain(g, count)
  local list, x, y = {}, 0, g:int(40, 60)
  for _ = 1, count do
    local w, y2 = g:int(5, 20), math.max(20, math.min(80, y + g:int(-8, 8)))
    list[#list + 1] = { x, y, x + w, y2, x + w, 100, x, 100 }
    x, y = x + w, y2
  end
  return list, x
end

--- One of the three kinds of scenes the compound measurements mix: kind 1, two clusters (1-5
-- parts and 1-2); 2, a terrain of 12 columns and a 10 by 10 crate placed in its span; 3, a
-- terrain of 8 columns and a cluster of 2. Returns the two lists of parts.
function scenes.pair(g, kind)
  if kind == 1 then
    return scenes.cluster(g, g:int(1, 5), 60, 30), scenes.cluster(g, g:int(1, 2), 60, 20)
  elseif kind == 2 then
    local terrain, width = scenes.terrain(g, 12)
    local x, y = g:range(0, width - 10), g:range(10, 80)
    return terrain, { { x, y, x + 10, y, x + 10, y + 10, x, y + 10 } }
  end
  return scenes.terrain(g, 8), scenes.cluster(g, 2, 60, 10)
end

return scenes
