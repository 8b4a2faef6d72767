--- Outlines of tile sets, as a tile map's collision shapes: shares no code with polygon.lua.
--
-- Each filled tile contributes its four edges, wound clockwise on screen (y down); an edge
-- between two filled tiles comes in both directions and cancels. The edges left form loops.
-- Where two filled tiles meet only at a corner (a pinch point) two loops could part or join:
-- the walk turns left there, going on around the other tile, so one loop passes the point
-- twice, as in {0,0, 10,0, 10,10, 20,10, 20,20, 10,20, 10,10, 0,10}. Clockwise loops are
-- outlines, counter-clockwise ones holes (enclosed empty tiles), which may touch their
-- outline or each other at pinch points.

local oracle = require "oracle"

local tiles = {}

--- A random tile set: rows[r][c] is true for a filled tile, each with probability `fill`.
function tiles.random(rng, cols, rows, fill)
  local set = { cols = cols, rows = rows }
  for r = 1, rows do
    set[r] = {}
    for c = 1, cols do
      set[r][c] = rng:float() < fill
    end
  end
  return set
end

--- The loops of a tile set (flat arrays, tiles `size` wide, the grid's corner at ox, oy), every
-- unit step a vertex, so straight runs are full of vertices in line.
function tiles.loops(set, size, ox, oy)
  local outgoing, order, edges = {}, {}, 0
  local function add(x1, y1, x2, y2)
    local key = x1 .. "," .. y1
    if not outgoing[key] then
      outgoing[key], order[#order + 1] = {}, key
    end
    table.insert(outgoing[key], { x1, y1, x2, y2 })
    edges = edges + 1
  end
  local function filled(r, c)
    return r >= 1 and r <= set.rows and c >= 1 and c <= set.cols and set[r][c]
  end
  for r = 1, set.rows do
    for c = 1, set.cols do
      if set[r][c] then
        local x0, y0, x1, y1 = c - 1, r - 1, c, r
        if not filled(r - 1, c) then add(x0, y0, x1, y0) end
        if not filled(r, c + 1) then add(x1, y0, x1, y1) end
        if not filled(r + 1, c) then add(x1, y1, x0, y1) end
        if not filled(r, c - 1) then add(x0, y1, x0, y0) end
      end
    end
  end
  local plain = {}   -- vertices that are no pinch point: most loops have one to start from
  for _, key in ipairs(order) do
    plain[key] = #outgoing[key] == 1
  end
  local loops = {}
  while true do
    local edge
    for _, key in ipairs(order) do
      if plain[key] and #outgoing[key] > 0 then
        edge = table.remove(outgoing[key])
        break
      end
    end
    -- a loop all of whose vertices are pinch points (an empty tile whose four neighbours are
    -- filled and whose four diagonal ones are empty) has no plain vertex: start it at a pinch
    for _, key in ipairs(edge and {} or order) do
      if #outgoing[key] > 0 then
        edge = table.remove(outgoing[key])
        break
      end
    end
    if not edge then
      break
    end
    local loop = {}
    repeat
      loop[#loop + 1], loop[#loop + 2] = edge[1] * size + ox, edge[2] * size + oy
      local choices = outgoing[edge[3] .. "," .. edge[4]]
      local pick = #choices
      if #choices == 2 then
        -- a pinch point: take the left turn (negative cross product on screen)
        local dx, dy = edge[3] - edge[1], edge[4] - edge[2]
        for i, f in ipairs(choices) do
          if dx * (f[4] - f[2]) - dy * (f[3] - f[1]) < 0 then
            pick = i
          end
        end
      end
      edge = pick > 0 and table.remove(choices, pick)
    until not edge
    loops[#loops + 1] = loop
  end
  return loops
end

--- The tile set as shapes: a list of { outline, holes }, each hole given to the smallest
-- outline around the centre of a filled tile next to the hole's first edge.
function tiles.shapes(set, size, ox, oy)
  local outlines, holes = {}, {}
  for _, loop in ipairs(tiles.loops(set, size, ox, oy)) do
    if oracle.winding(loop) == "cw" then
      outlines[#outlines + 1] = { loop, {} }
    else
      holes[#holes + 1] = loop
    end
  end
  for _, hole in ipairs(holes) do
    -- the filled tile lies on the right of the edge (on screen): from the edge's middle, half a
    -- tile along the direction turned a quarter clockwise
    local dx, dy = (hole[3] - hole[1]) / 2, (hole[4] - hole[2]) / 2
    local px, py = hole[1] + dx - dy, hole[2] + dy + dx
    local best, bestArea
    for _, shape in ipairs(outlines) do
      if oracle.contains(shape[1], px, py) then
        local area = oracle.area(shape[1])
        if not best or require("exact").compare(area, bestArea) < 0 then
          best, bestArea = shape, area
        end
      end
    end
    assert(best, "a hole outside every outline")
    table.insert(best[2], hole)
  end
  return outlines
end

--- A level: a random map of size x size tiles, each filled with probability 0.85, its border
-- filled, tiles 10 wide from (0, 0); its largest outline and the enclosed gaps as holes (for the
-- benchmarks: bench/holes.lua's tile maps, bench/cycled.lua's).
function tiles.level(rng, size)
  local set = tiles.random(rng, size, size, 0.85)
  for c = 1, size do set[1][c], set[size][c], set[c][1], set[c][size] = true, true, true, true end
  local best
  for _, shape in ipairs(tiles.shapes(set, 10, 0, 0)) do
    if not best or #shape[1] > #best[1] then best = shape end
  end
  return best[1], best[2]
end

return tiles
