-- polygon/rects.lua: an outline whose edges, and its holes' edges, all run along the axes (a
-- tile map, a room, a U floor) split into axis-parallel rectangles, for polygonConvexParts.
-- Rectangles where triangles merged into convex parts would leave slanted diagonals: between two
-- boxes the push is exact, so a crate sunk 8 into a floor gets (0, -8), not -8.000000000005.
-- The input has passed the triangulator's validity check; every coordinate of a rectangle is a
-- copy of an input coordinate, bit for bit (no arithmetic is done on them, only comparisons).

local sort, insert, remove = table.sort, table.insert, table.remove

local M = {}

-- Whether every edge of the flat array runs along an axis (a repeated vertex is no edge).
-- (Anything else answers false; the triangulator's checks then name the trouble.)
local function ringAlongAxes(ring)
  if type(ring) ~= "table" then return false end
  local n = #ring
  if n < 6 then return n == 0 or n % 2 == 0 end   -- a hole enclosing nothing is skipped
  local px, py = ring[n - 1], ring[n]
  for i = 1, n - 1, 2 do
    local x, y = ring[i], ring[i + 1]
    if x ~= px and y ~= py then return false end
    px, py = x, y
  end
  return true
end

--- Whether the outline and every hole in `holes` (flat arrays) run along the axes.
function M.alongAxes(points, holes)
  if not ringAlongAxes(points) then return false end
  if holes == nil then return true end
  if type(holes) ~= "table" then return false end
  for h = 1, #holes do
    if not ringAlongAxes(holes[h]) then return false end
  end
  return true
end

-- The vertical edges of a ring, appended to `edges` as x, low y, high y (in three arrays).
local function verticalEdges(ring, xs, lows, highs)
  local n = #ring
  local px, py = ring[n - 1], ring[n]
  for i = 1, n - 1, 2 do
    local x, y = ring[i], ring[i + 1]
    if x == px and y ~= py then
      local k = #xs + 1
      xs[k], lows[k], highs[k] = x, py < y and py or y, py < y and y or py
    end
    px, py = x, y
  end
end

--- The region inside `points` and outside every hole in `holes`, all edges along the axes and
-- the rings valid (no crossings, holes inside), as rectangles: flat arrays of 4 vertices wound
-- clockwise on screen when `clockwise`, else the other way. A sweep down the distinct y values:
-- between two of them the vertical edges spanning the band, sorted by x, bound the inside in
-- pairs (the crossing rule); an interval running on unchanged into the next band grows the
-- rectangle above it, any other closes it. So each rectangle ends only where a vertex of the
-- region meets its edge or corner.
function M.rectangles(points, holes, clockwise)
  local xs, lows, highs = {}, {}, {}
  verticalEdges(points, xs, lows, highs)
  for h = 1, #holes do verticalEdges(holes[h], xs, lows, highs) end
  -- the events: edges by their low end (coming in) and by their high end (leaving)
  local byLow, byHigh = {}, {}
  for k = 1, #xs do byLow[k], byHigh[k] = k, k end
  sort(byLow, function(a, b) return lows[a] < lows[b] end)
  sort(byHigh, function(a, b) return highs[a] < highs[b] end)
  local active = {}      -- the edges across the current band, sorted by x
  local open = {}        -- open[i]: the top y of the rectangle over interval i of `active`
  local out = {}
  local function close(left, right, top, bottom)
    if clockwise then
      out[#out + 1] = { left, top, right, top, right, bottom, left, bottom }
    else
      out[#out + 1] = { left, top, left, bottom, right, bottom, right, top }
    end
  end
  local i, j, count = 1, 1, #xs
  while i <= count or j <= count do
    -- the next y where something happens
    local y = highs[byHigh[j]]
    if i <= count and lows[byLow[i]] < y then y = lows[byLow[i]] end
    -- the intervals above y, pairs of `active`, before it changes
    local before, beforeTop = {}, {}
    for a = 1, #active - 1, 2 do
      before[#before + 1] = xs[active[a]]; before[#before + 1] = xs[active[a + 1]]
      beforeTop[#beforeTop + 1] = open[(a + 1) / 2]
    end
    while j <= count and highs[byHigh[j]] == y do   -- edges ending here leave
      local e = byHigh[j]
      for a = 1, #active do
        if active[a] == e then remove(active, a); break end
      end
      j = j + 1
    end
    while i <= count and lows[byLow[i]] == y do     -- edges starting here come in, by x
      local e = byLow[i]
      local at = #active + 1
      for a = 1, #active do
        if xs[active[a]] > xs[e] then at = a; break end
      end
      insert(active, at, e)
      i = i + 1
    end
    -- the intervals below y: one running on unchanged keeps its rectangle open
    -- (both lists run left to right: one pass over the intervals above finds each match)
    local carried, nextOpen, b = {}, {}, 1
    for a = 1, #active - 1, 2 do
      local left, right = xs[active[a]], xs[active[a + 1]]
      while b < #before and before[b] < left do b = b + 2 end
      local top = y
      if b < #before and before[b] == left and before[b + 1] == right then
        top = beforeTop[(b + 1) / 2]
        carried[b] = true
      end
      nextOpen[#nextOpen + 1] = top
    end
    for c = 1, #before - 1, 2 do   -- the others end at y (none of zero width: a slit)
      if not carried[c] and before[c] ~= before[c + 1] then
        close(before[c], before[c + 1], beforeTop[(c + 1) / 2], y)
      end
    end
    open = nextOpen
  end
  return out
end

return M
