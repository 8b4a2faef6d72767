--- Helpers for specs on compound shapes (lists of convex parts). Shares no code with polygon.lua.
local oracle = require "oracle"
local shapes = require "shapes"

local parts = {}

--- A new list with every part moved by (dx, dy) (each coordinate rounded as a game would), and
-- a new list with every part in the other winding: the shape helpers under the names the compound
-- specs use.
parts.translate = shapes.translateEach
parts.reverse = shapes.reverseEach

local box = shapes.bounds

--- Whether some part of one list overlaps some part of the other, by the exact oracle (parts
-- whose boxes do not overlap cannot: the comparisons of coordinates are exact).
function parts.collide(list1, list2)
  for _, a in ipairs(list1) do
    local ax0, ay0, ax1, ay1 = box(a)
    for _, b in ipairs(list2) do
      local bx0, by0, bx1, by1 = box(b)
      if ax0 < bx1 and bx0 < ax1 and ay0 < by1 and by0 < ay1 and oracle.collides(a, b, true) then
        return true
      end
    end
  end
  return false
end

--- The allowed excess of a push over the least translation: the rounding margin the module
-- documents is about 80 eps E + 5 eps S (E the width plus height of the box around both shapes,
-- S the largest coordinate magnitude); this is three times that.
function parts.slack(list1, list2)
  local xmin, ymin, xmax, ymax = math.huge, math.huge, -math.huge, -math.huge
  for _, list in ipairs({ list1, list2 }) do
    for _, p in ipairs(list) do
      local x0, y0, x1, y1 = box(p)
      xmin, ymin, xmax, ymax = math.min(xmin, x0), math.min(ymin, y0), math.max(xmax, x1), math.max(ymax, y1)
    end
  end
  -- the largest coordinate magnitude is at a side of the box
  local size = math.max(-xmin, xmax, -ymin, ymax)
  local eps = 2 ^ -53
  return 3 * (80 * eps * ((xmax - xmin) + (ymax - ymin)) + 5 * eps * size)
end

--- A floor of `count` rectangles of width `width`, top edge at y = top, depth 30, from x = x0.
function parts.floor(count, width, top, x0)
  local list = {}
  for k = 0, count - 1 do
    local l, r = x0 + k * width, x0 + (k + 1) * width
    list[k + 1] = { l, top, r, top, r, top + 30, l, top + 30 }
  end
  return list
end

--- An axis-aligned box {x, y, x + w, y, x + w, y + h, x, y + h} (clockwise on screen).
function parts.box(x, y, w, h)
  return { x, y, x + w, y, x + w, y + h, x, y + h }
end

return parts
