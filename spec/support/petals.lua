--- Pinch points of every kind, as level outlines make them: petals, each a polygon star-shaped
-- from one shared point, its apex, and lying in its own wedge around it. Several petals in one
-- outline pinch it at the apex (the outline passes through it once a petal); petals as holes meet
-- each other there, or the outline at one of its vertices; holes inside an outline's petals meet
-- its pinch point. Petals on whole directions (`rays`) share the rays between their wedges: edges
-- run along one another from the apex, outwards and back. Coordinates are integers, moved by an
-- offset in some cases. Nothing here decides whether a case is valid: oracle.regionCrossing does.
-- Shares no code with polygon.lua.

local petals = {}

local floor, pi, cos, sin = math.floor, math.pi, math.cos, math.sin

local OFFSETS = { 0, 0, 0, 1e5 + 0.5, 1e9 + 0.375 }

-- k wedges (from, to) in angle order, inside the span of angles from `first` over `span`.
local function wedges(rng, k, first, span)
  local ends = {}
  for i = 1, 2 * k do ends[i] = first + span * rng:float() end
  table.sort(ends)
  local list = {}
  for i = 1, k do list[i] = { ends[2 * i - 1], ends[2 * i] } end
  return list
end

-- A petal with its apex at (ax, ay) in the wedge from angle a to angle b (counterclockwise, y
-- up): the apex, then 2 to 4 points by angle inside the wedge, at distances r0 to r1, rounded.
local function petal(rng, ax, ay, a, b, r0, r1)
  local m = rng:int(2, 4)
  local points = { ax, ay }
  for i = 1, m do
    local angle = a + (b - a) * (i - 0.5 + 0.4 * (rng:float() - 0.5)) / m
    local r = r0 + (r1 - r0) * rng:float()
    points[#points + 1] = floor(ax + r * cos(angle) + 0.5)
    points[#points + 1] = floor(ay + r * sin(angle) + 0.5)
  end
  return points
end

-- The 16 directions (x, y) with |x|, |y| <= 2 and no common factor, by angle (y up).
local RAYS = { { 1, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 1 }, { -1, 2 }, { -1, 1 }, { -2, 1 },
  { -1, 0 }, { -2, -1 }, { -1, -1 }, { -1, -2 }, { 0, -1 }, { 1, -2 }, { 1, -1 }, { 2, -1 } }

-- A petal over the directions `from` to `to` (counted on past 16), apex (ax, ay): the apex, then
-- a point at a whole multiple r0 to r1 of each direction. Its first and last points lie on the
-- wedge's rays exactly.
local function rayPetal(rng, ax, ay, from, to, r0, r1)
  local points = { ax, ay }
  for d = from, to do
    local ray, r = RAYS[(d - 1) % 16 + 1], rng:int(r0, r1)
    points[#points + 1] = ax + r * ray[1]
    points[#points + 1] = ay + r * ray[2]
  end
  return points
end

-- k wedges over the 16 directions, each 1 to 7 directions wide (under half a turn), each
-- beginning on the ray where the last one ends or one further; nil when they would go round
-- more than once.
local function rayWedges(rng, k)
  local list, at = {}, rng:int(1, 16)
  local first = at
  for i = 1, k do
    local width = rng:int(1, 7)
    list[i] = { at, at + width }
    at = at + width + rng:int(0, 1)
  end
  if list[k][2] - first > 16 or (list[k][2] - first == 16 and k == 1) then return nil end
  return list
end

local function moved(points, dx, dy)
  for i = 1, #points, 2 do points[i], points[i + 1] = points[i] + dx, points[i + 1] + dy end
  return points
end

-- A hole of zero area around (cx, cy), one of four shapes: slits out from the centre and back
-- (2 to 4 of them, in any order: out of their turn around it, the ring crosses itself), a loop
-- and its mirror image through the centre (a figure eight whose loops cancel: it crosses
-- itself), a bow-tie with its crossing point made a vertex of one of the crossing edges (the
-- same, the point inside the other edge), or a sliver folded flat along one line.
local function zeroHole(rng, cx, cy)
  local shape, hole = rng:int(1, 4), {}
  if shape == 1 then
    for _ = 1, rng:int(2, 4) do
      hole[#hole + 1], hole[#hole + 2] = cx, cy
      hole[#hole + 1], hole[#hole + 2] = cx + rng:int(-20, 20), cy + rng:int(-20, 20)
    end
  elseif shape == 2 then
    local loop = {}
    for i = 1, rng:int(2, 3) do loop[i] = { rng:int(1, 20), rng:int(-20, 20) } end
    table.sort(loop, function(p, q) return p[2] * q[1] < q[2] * p[1] end)   -- by angle (x > 0)
    hole = { cx, cy }
    for _, p in ipairs(loop) do hole[#hole + 1], hole[#hole + 2] = cx + p[1], cy + p[2] end
    hole[#hole + 1], hole[#hole + 2] = cx, cy
    for _, p in ipairs(loop) do hole[#hole + 1], hole[#hole + 2] = cx - p[1], cy + p[2] end
  elseif shape == 3 then
    local a, b = rng:int(5, 20), rng:int(5, 20)
    hole = { cx - a, cy - b, cx + a, cy + b, cx + a, cy - b, cx - a, cy + b }
    local at = rng:int(0, 1) == 1 and 3 or 7   -- inside the first crossing edge or the second
    table.insert(hole, at, cy)
    table.insert(hole, at, cx)
  else
    local dx, dy = rng:int(-3, 3), rng:int(-3, 3)
    for _ = 1, rng:int(3, 5) do
      local t = rng:int(-6, 6)
      hole[#hole + 1], hole[#hole + 2] = cx + t * dx, cy + t * dy
    end
  end
  return hole
end

-- The slits of kind 9: out from (ax, ay) to each arm's end and back, in the arms' order,
-- appended to `points`.
local function slitsFrom(ax, ay, arms, points)
  for _, arm in ipairs(arms) do
    points[#points + 1], points[#points + 2] = ax, ay
    points[#points + 1], points[#points + 2] = ax + arm[1], ay + arm[2]
  end
  return points
end

local atan2 = rawget(math, "atan2") or math.atan   -- (Lua 5.3 and 5.4: atan takes y, x)

local function gcd(a, b)
  while b ~= 0 do a, b = b, a % b end
  return a
end

-- `count` whole vectors of up to 30 * s a side in different directions, none due west, by angle
-- clockwise (y up) from due west, or shuffled.
local function arms(rng, count, shuffled, s)
  local list, seen = {}, {}
  while #list < count do
    local x, y = rng:int(-30, 30), rng:int(-30, 30)
    local g = gcd(math.abs(x), math.abs(y))
    local key = g > 0 and (x / g) .. "," .. (y / g)
    if key and not seen[key] and not (y == 0 and x < 0) then
      seen[key] = true
      list[#list + 1] = { x * s, y * s, atan2(y, x) }
    end
  end
  table.sort(list, function(p, q) return p[3] > q[3] end)
  for i = shuffled and #list or 0, 2, -1 do
    local j = rng:int(1, i)
    list[i], list[j] = list[j], list[i]
  end
  return list
end

petals.KINDS = { "pinched", "holes meeting", "holes at the outline", "holes at its pinch",
  "pinched on rays", "holes meeting on rays", "holes at its pinch on rays", "a hole of zero area",
  "slits from one point" }

--- A random case of kind `kind` (an index into petals.KINDS): an outline, a list of holes.
function petals.case(rng, kind)
  local s = rng:int(1, 3) == 1 and 1 or 10   -- small coordinates, where rounding puts points in line
  local ax, ay = 50 * s, 50 * s
  local square = { 0, 0, 100 * s, 0, 100 * s, 100 * s, 0, 100 * s }
  local points, list = {}, {}
  if kind == 1 then
    for _, w in ipairs(wedges(rng, rng:int(2, 5), 2 * pi * rng:float(), 2 * pi)) do
      for _, v in ipairs(petal(rng, ax, ay, w[1], w[2], 5 * s, 45 * s)) do points[#points + 1] = v end
    end
  elseif kind == 2 then
    points = square
    for _, w in ipairs(wedges(rng, rng:int(2, 5), 2 * pi * rng:float(), 2 * pi)) do
      list[#list + 1] = petal(rng, ax, ay, w[1], w[2], 5 * s, 40 * s)
    end
  elseif kind == 3 then
    -- the apex a vertex of the square's left side; the petals point into the square
    points = { 0, 0, 100 * s, 0, 100 * s, 100 * s, 0, 100 * s, 0, ay }
    for _, w in ipairs(wedges(rng, rng:int(1, 4), -pi / 2, pi)) do
      list[#list + 1] = petal(rng, 0, ay, w[1], w[2], 5 * s, 40 * s)
    end
  elseif kind == 9 then
    -- 2 to 7 slits out from the apex and back, in their turn around it or shuffled (then the
    -- ring may cross itself there): in an outline, which comes in along a slit of its own from
    -- the square's left side and goes back along it, or as a hole of zero area in the square
    local shuffled = rng:int(0, 1) == 1
    if rng:int(0, 1) == 1 then
      points = { 0, 0, 100 * s, 0, 100 * s, 100 * s, 0, 100 * s, 0, ay }
      slitsFrom(ax, ay, arms(rng, rng:int(2, 7), shuffled, s), points)
      points[#points + 1], points[#points + 2] = ax, ay
      points[#points + 1], points[#points + 2] = 0, ay
    else
      points = square
      list[1] = slitsFrom(ax, ay, arms(rng, rng:int(3, 7), shuffled, s), {})
    end
  elseif kind == 8 then
    points = square
    list[1] = zeroHole(rng, ax, ay)
    if rng:int(0, 1) == 1 then   -- beside a hole with area
      list[2] = { 10 * s, 10 * s, 20 * s, 10 * s, 15 * s, 20 * s }
    end
  elseif kind == 4 then
    for _, w in ipairs(wedges(rng, rng:int(2, 4), 2 * pi * rng:float(), 2 * pi)) do
      for _, v in ipairs(petal(rng, ax, ay, w[1], w[2], 30 * s, 48 * s)) do points[#points + 1] = v end
      if rng:int(0, 1) == 1 then   -- a hole in the petal's wedge, touching its apex
        local a = w[1] + (w[2] - w[1]) * (0.2 + 0.3 * rng:float())
        list[#list + 1] = petal(rng, ax, ay, a, a + 0.01 + 0.3 * (w[2] - w[1]) * rng:float(), 5 * s, 20 * s)
      end
    end
  else
    local ws
    repeat ws = rayWedges(rng, rng:int(2, 4)) until ws
    if kind == 6 then points = square end
    for _, w in ipairs(ws) do
      if kind == 6 then
        list[#list + 1] = rayPetal(rng, ax, ay, w[1], w[2], 2 * s, 20 * s)
      else
        for _, v in ipairs(rayPetal(rng, ax, ay, w[1], w[2], kind == 5 and 2 * s or 12 * s, 20 * s)) do
          points[#points + 1] = v
        end
        if kind == 7 and w[2] - w[1] >= 2 and rng:int(0, 1) == 1 then
          local from = rng:int(w[1], w[2] - 1)
          list[#list + 1] = rayPetal(rng, ax, ay, from, rng:int(from + 1, w[2]), 2 * s, 10 * s)
        end
      end
    end
  end
  local offset = OFFSETS[rng:int(1, #OFFSETS)]
  moved(points, offset, -offset)
  for _, hole in ipairs(list) do moved(hole, offset, -offset) end
  return points, list
end

return petals
