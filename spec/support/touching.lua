--- Outlines with holes that touch them and each other: each hole a small fan out from a point of
-- the outline or of a hole placed before it (a vertex, or a whole-number point inside an edge)
-- into the region, so that holes meet the outline and each other at vertices, inside edges and
-- at the outline's reflex corners, and sometimes at a second point too. Integer coordinates, so
-- that a touching point lies on its edge exactly; some cases are moved far from the origin. The
-- oracle keeps most holes that leave the case valid or undecided (and one in ten others), but
-- decides nothing about the case it returns: oracle.regionCrossing does that. Shares no code
-- with polygon.lua.

local oracle = require "oracle"

local touching = {}

local floor, cos, sin, pi, abs = math.floor, math.cos, math.sin, math.pi, math.abs

local OFFSETS = { 0, 0, 2 ^ 30 + 0.5, -3.7e9, 1e6 + 0.25, 2 ^ 40 }

local function gcd(a, b)
  a, b = abs(a), abs(b)
  while b ~= 0 do a, b = b, a % b end
  return a
end

-- A room with rectangular notches in its top and bottom sides (reflex corners), a star-shaped
-- polygon, or an octagon with edges at 45 degrees; clockwise on screen (y down) or not.
local function outline(rng)
  local kind, points = rng:int(1, 3), {}
  local function add(x, y) points[#points + 1], points[#points + 2] = x, y end
  if kind == 1 then
    local w, h = rng:int(10, 40) * 8, rng:int(10, 40) * 8
    for _, side in ipairs({ { 0, 1 }, { h, -1 } }) do   -- y of the side, the notches' way in
      local y, into = side[1], side[2]
      local from, to, step = 0, w, 1
      if into < 0 then from, to, step = w, 0, -1 end
      add(from, y)
      local x = from
      while true do
        local a = x + step * rng:int(2, 8) * 8
        local b = a + step * rng:int(1, 6) * 8
        if (b - to) * step > -16 then break end
        local depth = into * rng:int(1, math.min(6, floor(h / 16) - 1)) * 8   -- (under h / 2)
        add(a, y); add(a, y + depth); add(b, y + depth); add(b, y)
        x = b
      end
      add(to, y)
    end
  elseif kind == 2 then
    local m = rng:int(5, 16)
    for k = 1, m do
      local t = (k + 0.8 * (rng:float() - 0.5)) * 2 * pi / m
      local r = 400 * (0.3 + rng:float())
      add(floor(r * cos(t) + 0.5), floor(r * sin(t) + 0.5))
    end
  else
    local w, h = rng:int(8, 60) * 8, rng:int(8, 60) * 8
    local most = floor(math.min(w, h) / 16)
    local c1, c2, c3, c4 = rng:int(0, most) * 8, rng:int(0, most) * 8, rng:int(0, most) * 8,
      rng:int(0, most) * 8
    for _, v in ipairs({ c1, 0, w - c2, 0, w, c2, w, h - c3, w - c3, h, c4, h, 0, h - c4, 0, c1 }) do
      points[#points + 1] = v
    end
  end
  return points
end

-- The places a hole may start from on `ring`: its vertices, and two whole-number points inside
-- each edge that has some.
local function addAnchors(anchors, ring, rng)
  local n = #ring / 2
  for i = 1, n do
    local j = i % n + 1
    local x, y = ring[2 * i - 1], ring[2 * i]
    local dx, dy = ring[2 * j - 1] - x, ring[2 * j] - y
    anchors[#anchors + 1] = { x, y }
    local g = gcd(dx, dy)
    for _ = 1, g > 1 and 2 or 0 do
      local k = rng:int(1, g - 1)
      anchors[#anchors + 1] = { x + dx / g * k, y + dy / g * k }
    end
  end
end

-- Whether (x, y) lies strictly inside the outline and outside every hole of `list`.
local function inRegion(points, list, x, y)
  if not oracle.contains(points, x, y) or oracle.onBoundary(points, x, y) then return false end
  for _, hole in ipairs(list) do
    if oracle.contains(hole, x, y) or oracle.onBoundary(hole, x, y) then return false end
  end
  return true
end

-- A fan of 2 to 4 points out from anchor a around angle t, rounded to whole numbers, after a;
-- one of its points moved onto another anchor near a, now and then (a second touch).
local function fan(rng, a, t, anchors)
  local hole = { a[1], a[2] }
  local m, size, spread = rng:int(2, 4), rng:int(4, 40), rng:range(0.2, 1.2)
  for i = 1, m do
    local angle = t - spread / 2 + spread * (i - 0.5 + 0.3 * (rng:float() - 0.5)) / m
    local r = size * rng:range(0.5, 1.5)
    hole[#hole + 1] = floor(a[1] + r * cos(angle) + 0.5)
    hole[#hole + 1] = floor(a[2] + r * sin(angle) + 0.5)
  end
  if rng:int(1, 4) == 1 then
    local b = anchors[rng:int(1, #anchors)]
    if abs(b[1] - a[1]) + abs(b[2] - a[2]) < 120 and (b[1] ~= a[1] or b[2] ~= a[2]) then
      local i = rng:int(2, m + 1)
      hole[2 * i - 1], hole[2 * i] = b[1], b[2]
    end
  end
  return hole
end

-- The ring of flat array r, backwards when `backwards`, starting at its vertex `start`.
local function turned(r, backwards, start)
  local n, out = #r / 2, {}
  for i = 0, n - 1 do
    local k = (start - 1 + (backwards and -i or i)) % n + 1
    out[#out + 1], out[#out + 2] = r[2 * k - 1], r[2 * k]
  end
  return out
end

--- One case: an outline and a list of 1 to 8 holes.
function touching.case(rng)
  local points = outline(rng)
  local list, anchors = {}, {}
  addAnchors(anchors, points, rng)
  local wanted, tries = rng:int(1, 8), 0
  while #list < wanted and tries < 40 do
    tries = tries + 1
    local a = anchors[rng:int(1, #anchors)]
    local inward = {}   -- of 16 directions, those going into the region from a
    for k = 0, 15 do
      local t = k * pi / 8
      if inRegion(points, list, a[1] + 2 * cos(t), a[2] + 2 * sin(t)) then inward[#inward + 1] = t end
    end
    if #inward > 0 then
      local hole = fan(rng, a, inward[rng:int(1, #inward)], anchors)
      hole = turned(hole, rng:int(0, 1) == 1, rng:int(1, #hole / 2))
      list[#list + 1] = hole
      local verdict = oracle.regionCrossing(points, list)
      if verdict == "valid" or verdict == "unknown" or rng:int(1, 10) == 1 then
        addAnchors(anchors, hole, rng)
      else
        list[#list] = nil
      end
    end
  end
  local dx, dy = OFFSETS[rng:int(1, #OFFSETS)], OFFSETS[rng:int(1, #OFFSETS)]
  local rings = { points }
  for _, hole in ipairs(list) do rings[#rings + 1] = hole end
  for _, ring in ipairs(rings) do
    for i = 1, #ring, 2 do ring[i], ring[i + 1] = ring[i] + dx, ring[i + 1] + dy end
  end
  if rng:int(0, 1) == 1 then points = turned(points, true, 1) end
  return points, list
end

return touching
