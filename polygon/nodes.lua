-- polygon/nodes.lua: the node arrays of a triangulation and the exact tests on them, shared by
-- polygon/triangulate.lua (ear clipping, bridges) and polygon/sweep.lua (the validity check):
-- the scratch arrays kept between calls, the orientation of three nodes, two nodes at one
-- place, the order of two edges along a level, an edge's span in a row of cells, where a point
-- lies against a ring, and the nodes sorted by place. Every decision is one of kernel's exact
-- signs.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")

local abs, min, max, huge, floor = math.abs, math.min, math.max, math.huge, math.floor
local sort = table.sort
local CROSS_BOUND, crossExact, cross = kernel.CROSS_BOUND, kernel.crossExact, kernel.cross

local M = {}

-- The node arrays of the triangulation under way, bound by polygon/triangulate.lua at the start
-- of each call (see M.bind) and dropped at its end: upvalues, as in the files that use them.
local nodeX, nodeY      -- coordinates as doubles, for the predicates
local nextNode
local nodeRing          -- the ring a node was made for: 1 the outline, h + 1 hole h
local turn              -- the sign of the outer ring's area: > 0 clockwise on screen

-- Binds the node arrays of a triangulation (nil to drop them).
function M.bind(x, y, nextN, ring, sign)
  nodeX, nodeY, nextNode, nodeRing, turn = x, y, nextN, ring, sign
end

-- An empty table with room for `size` array entries: LuaJIT's table.new, {} elsewhere. The
-- node arrays are filled in order up to tens of thousands of entries; grown one entry at a
-- time, each is copied at every doubling and leaves its old parts as garbage.
local newArray = function() return {} end
do
  local found, tableNew = pcall(require, "table.new")
  if found then newArray = function(size) return tableNew(size, 0) end end
end
-- Scratch arrays, kept from one triangulation to the next when it makes at most SCRATCH_NODES
-- nodes: a call on a small outline spent about a tenth of its time making its thirty-odd
-- arrays and collecting them (bench/NOTES.md, session 20). Slot s holds one array at a time,
-- replaced by a larger one when a call needs more, so what stays is bounded (some 50 arrays of a
-- few thousand entries). A larger call's arrays are held weakly (bigPool): the next large call
-- takes them unless the collector has run since, which frees them, so a level's load keeps no
-- megabytes while a tool that triangulates a large map again and again does not make its
-- fifty-odd arrays each time (a tenth of tiles-120's time, bench/NOTES.md, session 25). A reused
-- array holds the last call's values: every user writes an entry before reading it, or clears it.
local SCRATCH_NODES = 2048
local pool, poolSize = {}, {}
local smallPool, smallSize = pool, poolSize
local bigPool, bigSize = setmetatable({}, { __mode = "v" }), {}
local function scratch(slot, size)
  local a = pool[slot]
  if a and poolSize[slot] >= size then return a end
  a = newArray(size)
  pool[slot], poolSize[slot] = a, size
  return a
end
-- Chooses the arrays for the call now starting, of at most `capacity` nodes.
function M.usePool(nodes)
  if nodes <= SCRATCH_NODES then pool, poolSize = smallPool, smallSize
  else pool, poolSize = bigPool, bigSize end
end

-- Nodes in order of x, then y (for table.sort).
local function leftmostFirst(a, b)
  return nodeX[a] < nodeX[b] or (nodeX[a] == nodeX[b] and nodeY[a] < nodeY[b])
end

-- A number with the sign of (b - a) x (c - a) for nodes, times turn: > 0 when c lies on the
-- interior side of the directed edge a -> b of a ring wound like the outer one. Only its sign
-- means anything.
local function orient(a, b, c)
  local ax, ay, bx, by, cx, cy = nodeX[a], nodeY[a], nodeX[b], nodeY[b], nodeX[c], nodeY[c]
  -- cross's filter written out, with crossExact only when it cannot vouch for the sign: the call
  -- with eight arguments made LuaJIT abort its side traces over and over ("register coalescing
  -- too complex"), as did branches taken half the time. The determinant is taken about c,
  -- (a - c) x (b - c), the same number as (b - a) x (c - a): with c at a or at b (edges meeting
  -- at a vertex, a pinch point's copies: thousands of calls on map data) both products are 0,
  -- so the filter vouches for the 0 and no branch leaves the common path
  local l, r = (ax - cx) * (by - cy), (ay - cy) * (bx - cx)
  local s = l - r
  local e = CROSS_BOUND * abs(l + r)
  -- one test of |s|, not one per sign: a branch taken for half the nodes (convex or reflex)
  -- made side traces that aborted until LuaJIT flushed all its traces
  if abs(s) < e or s ~= s then   -- also when l and r differ in sign and s is 0: exact, rare
    s = crossExact(ax, ay, bx, by, ax, ay, cx, cy)
  end
  return s * turn
end

-- Whether nodes a and b lie at one place. One comparison, not two: with `and`, the second
-- went either way on shared coordinates (tile maps, map data) and grew a side trace in every
-- caller. (A difference of doubles is 0 only for equal ones: subnormals, not flushed to zero.)
local function same(a, b)
  return abs(nodeX[a] - nodeX[b]) + abs(nodeY[a] - nodeY[b]) == 0
end

-- The span in x of the segment from (ax, ay) to (bx, by), not level, over the band of y of row
-- `row` of square cells of side `size` from y = top (the last of `rows` rows runs on past its
-- band: the row functions put every place beyond it there), band and span widened by `margin`
-- against rounding, clamped to the segment's box: its least and greatest x. (For sweep.lua's
-- grid of edges and triangulate.lua's index of the bridges.)
local function spanInRow(ax, ay, bx, by, top, size, rows, row, margin)
  local lo = max(min(ay, by), top + row * size - margin)
  local hi = max(ay, by)
  if row < rows - 1 then hi = min(hi, top + (row + 1) * size + margin) end
  local slope = (bx - ax) / (by - ay)
  -- too steep for a double (a rise below 2^-1022 or so against its run: outside the exact
  -- range): the segment's box
  if not (abs(slope) < huge) then return min(ax, bx), max(ax, bx) end   -- luacheck: ignore 581 (NaN too)
  local xa, xb = ax + (lo - ay) * slope, ax + (hi - ay) * slope
  return max(min(ax, bx), min(xa, xb) - margin), min(max(ax, bx), max(xa, xb) + margin)
end

-- Which of two edges crossing one level (each given by its lower end and its upper end, by y;
-- for sweep.lua's nearestLeft, the level just above y = vy, an end at vy counting as lower)
-- meets it further right: > 0 when e does, < 0 when f does, 0 when they run together there.
-- They do not cross properly, so the end of one at the higher of their lower ends, or else at
-- the lower of their upper ends, tested against the other tells. The plain sign of
-- (u - l) x (p - l) is < 0 for p right of an edge l -> u that goes up the y axis. (For the
-- placing of the holes and triangulate.lua's bridges.)
local function furtherRight(el, eu, fl, fu)
  local s
  if nodeY[el] >= nodeY[fl] then s = -orient(fl, fu, el) else s = orient(el, eu, fl) end
  if s == 0 then
    if nodeY[eu] <= nodeY[fu] then s = -orient(fl, fu, eu) else s = orient(el, eu, fu) end
  end
  return s * turn   -- orient's sign times turn: the plain sign
end

-- -1, 0 or 1: where (x, y) lies against the ring at node s (outside, on it, strictly inside),
-- by the crossing rule with the exact side test and an exact test for the boundary.
local function ringSide(s, x, y)
  local inside = false
  local k = s
  repeat
    local q = nextNode[k]
    local x1, y1, x2, y2 = nodeX[k], nodeY[k], nodeX[q], nodeY[q]
    local c = cross(x1, y1, x2, y2, x1, y1, x, y)
    if c == 0 and min(x1, x2) <= x and x <= max(x1, x2) and min(y1, y2) <= y and y <= max(y1, y2) then
      return 0
    end
    if (y1 > y) ~= (y2 > y) and (y2 > y1) == (c > 0) then inside = not inside end
    k = q
  until k == s
  return inside and 1 or -1
end

-- Where hole h lies, by the crossing rule from its vertices (the rings do not cross: the first
-- vertex off another ring decides), when the sweep or the grid's rays could not tell: a message
-- when it is outside the polygon or inside another hole, else nil.
local function holeMisplaced(starts, h)
  local k, side = starts[h]
  repeat
    side = ringSide(starts[1], nodeX[k], nodeY[k])
    k = nextNode[k]
  until side ~= 0 or k == starts[h]
  local name = nodeRing[starts[h]] - 1
  if side < 0 then return ("holes[%d] is outside the polygon"):format(name) end
  for g = 2, #starts do
    if g ~= h then
      k = starts[h]
      repeat
        side = ringSide(starts[g], nodeX[k], nodeY[k])
        k = nextNode[k]
      until side ~= 0 or k == starts[h]
      if side > 0 then
        return ("holes[%d] is inside holes[%d]"):format(name, nodeRing[starts[g]] - 1)
      end
    end
  end
  return nil
end

local BUCKET_RUN = 24   -- a bucket holding more nodes than this is sorted by table.sort
                        -- (many vertices on one vertical line), fewer by insertion

-- Whether the nodes order[lo..hi] all lie on one vertical line.
local function sameX(order, lo, hi)
  local x = nodeX[order[lo]]
  for i = lo + 1, hi do
    if nodeX[order[i]] ~= x then return false end
  end
  return true
end

-- Sorts order[lo..hi], nodes on one vertical line, by y: counted into as many buckets as nodes,
-- each then sorted by insertion; false, leaving them as they were, when a bucket is crowded. A
-- crowded bucket by x is most often such a line (a tile map's column of corners: tiles-120 has
-- 63 nodes a line), where table.sort with a Lua comparison took a fifth of the check.
local function sortByY(order, lo, hi)
  local y0, y1 = huge, -huge
  for i = lo, hi do y0, y1 = min(y0, nodeY[order[i]]), max(y1, nodeY[order[i]]) end
  if y1 == y0 then return true end   -- one place
  local count = hi - lo + 1
  local scale = count / (y1 - y0)
  local start, run = scratch(44, count + 1), scratch(45, count)
  for b = 1, count + 1 do start[b] = 0 end
  local most = 0
  for i = lo, hi do
    local b = min(floor((nodeY[order[i]] - y0) * scale), count - 1) + 1
    start[b] = start[b] + 1
    most = max(most, start[b])
  end
  if most > BUCKET_RUN then return false end   -- crowded again: table.sort (see below)
  local at = 1
  for b = 1, count + 1 do start[b], at = at, at + start[b] end
  for i = lo, hi do
    local k = order[i]
    local b = min(floor((nodeY[k] - y0) * scale), count - 1) + 1
    run[start[b]], start[b] = k, start[b] + 1
  end
  for i = 1, count do   -- each bucket's run by insertion: the buckets are in order
    local k, j = run[i], i - 1
    while j >= 1 and nodeY[run[j]] > nodeY[k] do run[j + 1] = run[j]; j = j - 1 end
    run[j + 1] = k
  end
  for i = 1, count do order[lo + i - 1] = run[i] end
  return true
end

-- The nodes of the rings at `starts` in (x, y) order, their count, and their ranks (rank[k]:
-- node k's place in that order, 1 for the first place; nodes at one place share it), for a
-- call of at most `capacity` nodes: counted into as many buckets as nodes by x (the bucket is
-- monotone in x), then each bucket sorted.
local function sortPlaces(starts, capacity)
  local x0, x1, count = huge, -huge, 0
  for _, s in ipairs(starts) do
    local k = s
    repeat
      x0, x1, count = min(x0, nodeX[k]), max(x1, nodeX[k]), count + 1
      k = nextNode[k]
    until k == s
  end
  local scale = count / (x1 - x0)   -- x1 > x0: the outer ring has area
  local bucketOf, first = scratch(1, capacity), scratch(2, count + 1)
  for b = 1, count + 1 do first[b] = 0 end
  for _, s in ipairs(starts) do
    local k = s
    repeat
      local b = min(floor((nodeX[k] - x0) * scale), count - 1) + 1
      bucketOf[k] = b
      first[b] = first[b] + 1
      k = nextNode[k]
    until k == s
  end
  local at = 1   -- first[b]: where bucket b starts in the order; then where its next node goes
  for b = 1, count + 1 do first[b], at = at, at + first[b] end
  local order, fill = scratch(3, count), scratch(4, count)
  for b = 1, count do fill[b] = first[b] end
  for _, s in ipairs(starts) do
    local k = s
    repeat
      local b = bucketOf[k]
      order[fill[b]] = k
      fill[b] = fill[b] + 1
      k = nextNode[k]
    until k == s
  end
  for b = 1, count do
    local lo, hi = first[b], first[b + 1] - 1
    if hi - lo >= BUCKET_RUN then
      if not (sameX(order, lo, hi) and sortByY(order, lo, hi)) then
        local run = {}
        for i = lo, hi do run[i - lo + 1] = order[i] end
        sort(run, leftmostFirst)
        for i = lo, hi do order[i] = run[i - lo + 1] end
      end
    else
      for i = lo + 1, hi do
        local k, j = order[i], i - 1
        while j >= lo and leftmostFirst(k, order[j]) do order[j + 1] = order[j]; j = j - 1 end
        order[j + 1] = k
      end
    end
  end
  local rank = scratch(5, capacity)
  local place = 0
  for i = 1, count do
    local k = order[i]
    if i == 1 or not same(k, order[i - 1]) then place = place + 1 end
    rank[k] = place
  end
  return order, count, rank
end

-- This file's main chunk: triangulate.lua turns LuaJIT's compiler off and on for every function
-- in it (see there).
M.chunk = debug.getinfo(1, "f").func

M.newArray, M.scratch, M.orient, M.same = newArray, scratch, orient, same
M.spanInRow, M.furtherRight, M.ringSide, M.holeMisplaced = spanInRow, furtherRight, ringSide, holeMisplaced
M.sortPlaces = sortPlaces

return M
