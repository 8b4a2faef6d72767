--- The fewest axis-parallel rectangles a region bounded by axis-parallel rings can be split
-- into: n / 2 + h - g - 1 (Lipski, Lodi, Luccio, Mugnai and Pagli; Ohtsuki), n the vertices of
-- all rings (collinear and repeated ones left out), h the holes, g the most chords between two
-- reflex vertices of the region that pairwise do not meet. Chords along one axis never cross,
-- so g = chords - (largest matching of crossing horizontal-vertical pairs), by Koenig's theorem.
-- Brute force over pairs of vertices: for the small regions of the specs. Shares no code with
-- polygon.lua; coordinates are compared, never computed with.

local rectmin = {}

-- The ring without repeated and collinear vertices, as {x, y} points.
local function corners(ring)
  local pts = {}
  local n = #ring / 2
  for i = 1, n do
    local x, y = ring[2 * i - 1], ring[2 * i]
    local last = pts[#pts]
    if not last or last[1] ~= x or last[2] ~= y then pts[#pts + 1] = { x, y } end
  end
  if #pts > 1 and pts[1][1] == pts[#pts][1] and pts[1][2] == pts[#pts][2] then pts[#pts] = nil end
  local changed = true
  while changed do   -- drop middle vertices of straight runs
    changed = false
    for i = 1, #pts do
      local a, b, c = pts[(i - 2) % #pts + 1], pts[i], pts[i % #pts + 1]
      if (a[1] == b[1] and b[1] == c[1]) or (a[2] == b[2] and b[2] == c[2]) then
        table.remove(pts, i)
        changed = true
        break
      end
    end
  end
  return pts
end

-- Twice the signed area's sign of a list of points.
local function turnOf(pts)
  local s = 0
  for i = 1, #pts do
    local a, b = pts[i], pts[i % #pts + 1]
    s = s + (a[1] * b[2] - b[1] * a[2])
  end
  return s > 0 and 1 or -1
end

-- Whether the open axis-parallel segment p-q meets the segment a-b (both axis-parallel).
local function meets(px, py, qx, qy, ax, ay, bx, by)
  local x0, x1 = math.min(px, qx), math.max(px, qx)
  local y0, y1 = math.min(py, qy), math.max(py, qy)
  local u0, u1 = math.min(ax, bx), math.max(ax, bx)
  local v0, v1 = math.min(ay, by), math.max(ay, by)
  if py == qy then   -- horizontal, open in x
    return v0 <= py and py <= v1 and u1 > x0 and u0 < x1
  end
  return u0 <= px and px <= u1 and v1 > y0 and v0 < y1
end

--- The fewest rectangles for the region inside `points` and outside `holes` (flat arrays, every
-- edge along an axis, valid), and the chords found; nil when the rings pass through one place
-- twice (a pinch point: the formula is for rings that are simple and apart).
function rectmin.fewest(points, holes)
  local rings = { corners(points) }
  for h, hole in ipairs(holes) do rings[h + 1] = corners(hole) end
  local seen = {}
  for _, pts in ipairs(rings) do
    for _, p in ipairs(pts) do
      local key = ("%.17g %.17g"):format(p[1], p[2])
      if seen[key] then return nil end
      seen[key] = true
    end
  end
  local outer = turnOf(rings[1])
  local n, reflex, edges = 0, {}, {}
  for r, pts in ipairs(rings) do
    n = n + #pts
    -- holes taken against the outline's turn, so the region is on one side of every edge
    local sense = r == 1 and 1 or (turnOf(pts) == outer and -1 or 1)
    for i = 1, #pts do
      local a = pts[(i - 2) % #pts + 1]
      local b, c = pts[i], pts[i % #pts + 1]
      edges[#edges + 1] = { b[1], b[2], c[1], c[2] }
      local turn = (b[1] - a[1]) * (c[2] - b[2]) - (b[2] - a[2]) * (c[1] - b[1])
      if turn * sense * outer < 0 then reflex[#reflex + 1] = b end
    end
  end
  -- chords: two reflex vertices in line, the open segment between them meeting no edge, its
  -- midpoint inside the region (crossing rule over all rings)
  local function inside(x, y)
    local odd = false
    for _, e in ipairs(edges) do
      if (e[2] > y) ~= (e[4] > y) and x < e[1] + (y - e[2]) * (e[3] - e[1]) / (e[4] - e[2]) then
        odd = not odd
      end
    end
    return odd
  end
  local horizontal, vertical = {}, {}
  for i = 1, #reflex do
    for j = i + 1, #reflex do
      local p, q = reflex[i], reflex[j]
      if (p[1] == q[1]) ~= (p[2] == q[2]) then
        local clear = true
        for _, e in ipairs(edges) do
          if meets(p[1], p[2], q[1], q[2], e[1], e[2], e[3], e[4]) then clear = false; break end
        end
        if clear and inside((p[1] + q[1]) / 2, (p[2] + q[2]) / 2) then
          local list = p[2] == q[2] and horizontal or vertical
          list[#list + 1] = { p[1], p[2], q[1], q[2] }
        end
      end
    end
  end
  -- largest matching of crossing pairs (Kuhn's augmenting paths)
  local function cross(hc, vc)
    local x0, x1 = math.min(hc[1], hc[3]), math.max(hc[1], hc[3])
    local y0, y1 = math.min(vc[2], vc[4]), math.max(vc[2], vc[4])
    return vc[1] >= x0 and vc[1] <= x1 and hc[2] >= y0 and hc[2] <= y1
  end
  local matchOf = {}
  local function augment(h, visited)
    for v = 1, #vertical do
      if not visited[v] and cross(horizontal[h], vertical[v]) then
        visited[v] = true
        if not matchOf[v] or augment(matchOf[v], visited) then
          matchOf[v] = h
          return true
        end
      end
    end
    return false
  end
  local matching = 0
  for h = 1, #horizontal do
    if augment(h, {}) then matching = matching + 1 end
  end
  local g = #horizontal + #vertical - matching
  return n / 2 + #holes - g - 1, #horizontal + #vertical
end

return rectmin
