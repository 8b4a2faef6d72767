--- The true least translation between two shapes made of convex parts, for the specs only.
--
-- Moving the second shape by t makes part A of the first and part B of the second overlap when t
-- is inside the Minkowski difference D = A - B = {a - b}, the convex hull of all vertex
-- differences. The least translation is the nearest point to the origin that is in no open D:
-- a point on the boundary of their union. Here that boundary is found the plain way: every edge
-- of every D is cut where edges of the other D cross it, and a piece whose midpoint lies inside
-- no other D is boundary. No candidate directions, no half-planes, nothing from polygon.lua.
--
-- Floating point (the brief allows it for this measurement): the differences a - b are exact when
-- the two shapes are near each other (Sterbenz), the hulls and cuts are rounded, and "inside"
-- means deeper than 1e-12 times the size of the numbers, so the answer is good to about that.
-- Points are flat arrays {x1, y1, ...}; a shape is a list of such parts.

local union = {}

-- The convex hull of a list of points {x, y} (Andrew's monotone chain), counter-clockwise in
-- y-up terms (every interior point is to the left of every edge); nil for zero area.
local function hull(points)
  table.sort(points, function(p, q)
    if p[1] ~= q[1] then return p[1] < q[1] end
    return p[2] < q[2]
  end)
  local function turn(o, a, b)
    return (a[1] - o[1]) * (b[2] - o[2]) - (a[2] - o[2]) * (b[1] - o[1])
  end
  local out = {}
  for _, p in ipairs(points) do
    while #out >= 2 and turn(out[#out - 1], out[#out], p) <= 0 do out[#out] = nil end
    out[#out + 1] = p
  end
  local lower = #out + 1
  for i = #points - 1, 1, -1 do
    local p = points[i]
    while #out >= lower and turn(out[#out - 1], out[#out], p) <= 0 do out[#out] = nil end
    out[#out + 1] = p
  end
  out[#out] = nil
  if #out < 3 then return nil end
  return out
end

--- The Minkowski difference A - B of two flat arrays as a hull (list of {x, y}), or nil.
function union.difference(a, b)
  local points = {}
  for i = 1, #a, 2 do
    for j = 1, #b, 2 do
      points[#points + 1] = { a[i] - b[j], a[i + 1] - b[j + 1] }
    end
  end
  return hull(points)
end

-- The largest coordinate magnitude of a hull.
local function magnitude(h)
  local m = 0
  for _, p in ipairs(h) do m = math.max(m, math.abs(p[1]), math.abs(p[2])) end
  return m
end

-- Whether (x, y) is inside hull h deeper than tol.
local function inside(h, x, y, tol)
  local n = #h
  for i = 1, n do
    local p, q = h[i], h[i % n + 1]
    local ex, ey = q[1] - p[1], q[2] - p[2]
    local depth = (ex * (y - p[2]) - ey * (x - p[1])) / math.sqrt(ex * ex + ey * ey)
    if depth <= tol then return false end
  end
  return true
end

-- Parameters s in (0, 1) where segment p -> q meets segment r -> t (both ends when collinear).
local function cuts(p, q, r, t, out)
  local dx, dy = q[1] - p[1], q[2] - p[2]
  local ex, ey = t[1] - r[1], t[2] - r[2]
  local den = dx * ey - dy * ex
  local len2 = dx * dx + dy * dy
  if math.abs(den) <= 1e-15 * math.sqrt(len2 * (ex * ex + ey * ey)) then
    -- parallel: when on one line, r and t cut p -> q where they fall on it
    for _, v in ipairs({ r, t }) do
      local s = ((v[1] - p[1]) * dx + (v[2] - p[2]) * dy) / len2
      if s > 0 and s < 1 then out[#out + 1] = s end
    end
    return
  end
  local s = ((r[1] - p[1]) * ey - (r[2] - p[2]) * ex) / den
  local u = ((r[1] - p[1]) * dy - (r[2] - p[2]) * dx) / den
  if s > 0 and s < 1 and u >= 0 and u <= 1 then out[#out + 1] = s end
end

--- The hulls of every pair of parts (parts of zero area give none).
function union.differences(parts1, parts2)
  local list = {}
  for _, a in ipairs(parts1) do
    for _, b in ipairs(parts2) do
      local h = union.difference(a, b)
      if h then list[#list + 1] = h end
    end
  end
  return list
end

-- The distance from the origin to the nearest point outside every open hull of the list, and
-- that point; 0, 0, 0 when the origin is in none.
local function nearestOutside(list)
  local scale = 0
  for _, h in ipairs(list) do scale = math.max(scale, magnitude(h)) end
  local tol = 1e-12 * scale
  local covered = false
  for _, h in ipairs(list) do
    if inside(h, 0, 0, tol) then covered = true end
  end
  if not covered then return 0, 0, 0 end
  local best, bx, by = math.huge, 0, 0
  for a, h in ipairs(list) do
    for i = 1, #h do
      local p, q = h[i], h[i % #h + 1]
      local ss = { 0, 1 }
      for b, g in ipairs(list) do
        if b ~= a then
          for j = 1, #g do cuts(p, q, g[j], g[j % #g + 1], ss) end
        end
      end
      table.sort(ss)
      local dx, dy = q[1] - p[1], q[2] - p[2]
      for k = 1, #ss - 1 do
        local s0, s1 = ss[k], ss[k + 1]
        if s1 > s0 then
          local mx, my = p[1] + dx * (s0 + s1) / 2, p[2] + dy * (s0 + s1) / 2
          local free = true
          for b, g in ipairs(list) do
            if b ~= a and inside(g, mx, my, tol) then
              free = false
              break
            end
          end
          if free then
            -- the point of the piece nearest the origin
            local s = -(p[1] * dx + p[2] * dy) / (dx * dx + dy * dy)
            s = math.max(s0, math.min(s1, s))
            local x, y = p[1] + dx * s, p[2] + dy * s
            local d = math.sqrt(x * x + y * y)
            if d < best then best, bx, by = d, x, y end
          end
        end
      end
    end
  end
  return best, bx, by
end

--- The least translation of the second shape out of the first: the distance from the origin to
-- the nearest point outside every open D, and that point (dx, dy); 0, 0, 0 when the origin is
-- in no D. parts1, parts2: lists of convex parts (flat arrays).
function union.leastTranslation(parts1, parts2)
  return nearestOutside(union.differences(parts1, parts2))
end

--- Bounds on the least move of a circle (cx, cy, r) out of a list of convex parts: the disc is
-- replaced by a regular polygon of `sides` sides inscribed in it (giving a lower bound) and one
-- circumscribed about it (an upper bound), and each part grown by it, A - (disc - c), becomes a
-- hull as above. Returns lower, upper, and the upper bound's move (dx, dy).
function union.circleLeastMove(list, cx, cy, r, sides)
  local function grown(radius)
    local disc = {}
    for i = 0, sides - 1 do
      local angle = 2 * math.pi * i / sides
      disc[#disc + 1] = cx + radius * math.cos(angle)
      disc[#disc + 1] = cy + radius * math.sin(angle)
    end
    return union.differences(list, { disc })
  end
  local lower = nearestOutside(grown(r))
  local upper, dx, dy = nearestOutside(grown(r / math.cos(math.pi / sides)))
  return lower, upper, dx, dy
end

return union
