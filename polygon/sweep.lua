-- polygon/sweep.lua: whether the rings of a polygon with holes are a valid input for the
-- triangulation (no two edges cross, no ring overlaps another, every hole inside the outline and
-- outside the other holes), pair by pair (a small outline alone), by a sweep and prune (a larger
-- outline alone of short edges), by a grid of edges or by a sweep over the node rings that
-- polygon/triangulate.lua builds; the places where vertices meet by polygon/places.lua. Every
-- decision is one of kernel's exact signs (through polygon/nodes.lua's tests on the nodes).

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local nodes = require(_PACKAGE .. ".nodes")
local lineOrder = require(_PACKAGE .. ".order")
local places = require(_PACKAGE .. ".places")

local abs, huge, min, max, sqrt = math.abs, math.huge, math.min, math.max, math.sqrt
local floor, sort = math.floor, table.sort
local JIT = kernel.JIT
local scratch, orient, same, sortPlaces = nodes.scratch, nodes.orient, nodes.same, nodes.sortPlaces
local spanInRow, furtherRight, holeMisplaced = nodes.spanInRow, nodes.furtherRight, nodes.holeMisplaced
local chainsCross = places.chainsCross

local M = {}

-- The node arrays of the triangulation under way, bound by polygon/triangulate.lua at the start
-- of each call (see M.bind) and dropped at its end. They are upvalues here, as there, so the hot
-- loops of both files read them as cheaply: a table of state would cost a lookup per read.
local nodeX, nodeY      -- coordinates as doubles, for the predicates
local nextNode, prevNode
local nodeRing          -- the ring a node was made for: 1 the outline, h + 1 hole h
local capacity          -- the number of nodes the call can make, at most
local turn              -- the sign of the outer ring's area: > 0 clockwise on screen
local twin              -- filled by the sweep: twin[k], the next node at node k's place
local plain, plainOrder, plainCount, plainRank, plainBelow   -- see M.plainSweep
local keptFirst, keptEdge   -- the last check's cells, when it went by the grid: see M.edgeCells

-- Sort orders, made once: a function made per call would keep LuaJIT from compiling its caller.
local sortKey
local function bySortKey(a, b) return sortKey[a] < sortKey[b] end
-- This file's main chunk: triangulate.lua turns LuaJIT's compiler off and on for every function
-- in it (see there).
M.chunk = debug.getinfo(1, "f").func

-- Binds the node arrays of a triangulation (nil to drop them), here and in polygon/nodes.lua.
function M.bind(x, y, nextN, prevN, ring, cap, sign, twins)
  nodeX, nodeY, nextNode, prevNode, nodeRing, capacity, turn = x, y, nextN, prevN, ring, cap, sign
  twin = twins
  plain, plainOrder, plainCount, plainRank, plainBelow = false, nil, nil, nil, nil
  keptFirst, keptEdge = nil, nil
  nodes.bind(x, y, nextN, ring, sign)
  places.bind(x, y, nextN, prevN, cap, ring, sign)
end

-- The ring node k was made for: 1 the outline, h + 1 hole h.
local crossedA, crossedB   -- nodes of the two edges found crossing (or meeting wrongly), for
                           -- the message naming their rings
local function ringOf(k) return nodeRing[k] end

-- The message for two rings found crossing or meeting wrongly (crossedA, crossedB).
local function crossingMessage()
  local r, g = ringOf(crossedA), ringOf(crossedB)
  if r > g then r, g = g, r end
  if g == 1 then return "edges cross" end
  if r == g then return ("holes[%d] crosses itself"):format(g - 1) end
  if r == 1 then return ("holes[%d] crosses the outline"):format(g - 1) end
  return ("holes[%d] and holes[%d] cross"):format(r - 1, g - 1)
end

-- Whether segments a-b and c-d cross at one point inside both (a proper crossing): c and d
-- strictly on opposite sides of a-b, and a and b of c-d. Each side test is one comparison,
-- min(max(s1, s2), -min(s1, s2)) > 0, rarely true: sign tests that went both ways made LuaJIT
-- grow side traces in the sweep until its machine-code area ran out.
local function properlyCross(a, b, c, d)
  local s1, s2 = orient(a, b, c), orient(a, b, d)
  if min(max(s1, s2), -min(s1, s2)) <= 0 then return false end
  local s3, s4 = orient(c, d, a), orient(c, d, b)
  if min(max(s3, s4), -min(s3, s4)) <= 0 then return false end
  crossedA, crossedB = a, c
  return true
end

-- Shamos and Hoey's sweep: the edges in order along a vertical line moving right; a proper
-- crossing shows up between two edges next to each other in that order before the line reaches
-- it, so each edge is tested only against its neighbours when it comes in and when it leaves.
-- Edge k runs from node k to nextNode[k]; sweepLeft[k] and sweepRight[k] are its ends in (x, y)
-- order. An event is k (edge k comes in at its left end) or -k (it leaves at its right end).
-- The vertices are sorted by place in expected linear time (buckets by x, nodes.sortPlaces);
-- the order along the line is polygon/order.lua's: blocks of a sorted array, searched by
-- halving, each edge linked to its neighbours. (A skip list made LuaJIT grow traces until its
-- machine-code area ran out; one sorted array moved half the order for every edge.)
local sweepLeft, sweepRight
local rank                  -- rank[k]: node k's place in (x, y) order (1 for the first place)
local placeOrder, placeCount   -- the nodes in (x, y) order (nodes.sortPlaces), and their count

-- > 0 when edge s lies above edge t where the line meets both (in y-up terms), < 0 below, 0 for
-- edges in line: the later left end tested against the other edge, then its right end.
local function edgeOrder(s, t)
  local flip = 1
  if rank[sweepLeft[s]] < rank[sweepLeft[t]] then s, t, flip = t, s, -1 end
  local a, b = sweepLeft[t], sweepRight[t]
  local side = orient(a, b, sweepLeft[s])
  if side == 0 then side = orient(a, b, sweepRight[s]) end
  return side * turn * flip
end
lineOrder.compare(edgeOrder)

-- The events in order: by place, and at one place every edge leaving before any coming in.
local function sweepEvents(starts)
  local order, count = placeOrder, placeCount
  sweepLeft, sweepRight = scratch(6, capacity), scratch(7, capacity)
  for _, s in ipairs(starts) do
    local k = s
    repeat
      local q = nextNode[k]
      if rank[k] < rank[q] then sweepLeft[k], sweepRight[k] = k, q else sweepLeft[k], sweepRight[k] = q, k end
      k = q
    until k == s
  end
  local events, e = scratch(8, 2 * count), 0
  local i = 1
  while i <= count do
    local last = i   -- the nodes at one place are order[i..last]
    while last < count and rank[order[last + 1]] == rank[order[i]] do last = last + 1 end
    for g = i, last do
      local v = order[g]
      local p = prevNode[v]
      if sweepRight[p] == v then e = e + 1; events[e] = -p end
      if sweepRight[v] == v then e = e + 1; events[e] = -v end
    end
    for g = i, last do
      local v = order[g]
      local p = prevNode[v]
      if sweepLeft[p] == v then e = e + 1; events[e] = p end
      if sweepLeft[v] == v then e = e + 1; events[e] = v end
    end
    i = last + 1
  end
  return events, e
end

local belowOf           -- belowOf[v]: the edge right below node v as the sweep passed it (not
                        -- one of v's own), or 0: for polygon/monotone.lua
local upEdge, downEdge   -- the edges along the line (polygon/order.lua): each one's neighbours
local lastUp, lastDown   -- the edges above and below the last event: the edge that came in and
                         -- the one below it, or the two that an edge leaving left next to each other
local touchedAt         -- touchedAt[r]: the edges whose inside holds the place of rank r, or nil

-- Notes the edges next to edge `from` in the order, going along `links` (upEdge or downEdge),
-- that hold node p: a run of edges through p's place, each ending there or holding it inside
-- (noted in touchedAt, for placesCross). An edge holding p inside lies next to an edge ending at p, or
-- next to another edge through p, when an edge ending at p comes in or leaves.
local function noteTouches(p, from, links)
  local px, py = nodeX[p], nodeY[p]
  local f = links[from]
  while f do
    local q = nextNode[f]
    if orient(f, q, p) ~= 0 or px < min(nodeX[f], nodeX[q]) or px > max(nodeX[f], nodeX[q])
      or py < min(nodeY[f], nodeY[q]) or py > max(nodeY[f], nodeY[q]) then
      return
    end
    if not same(p, f) and not same(p, q) then
      local r = rank[p]
      local list = touchedAt[r] or {}
      touchedAt[r] = list
      local known = false
      for g = 1, #list do known = known or list[g] == f end
      if not known then list[#list + 1] = f end
    end
    f = links[f]
  end
end

-- For an edge s coming in next to the last event's edge, its block and index in the order (else
-- nil); for an edge s leaving, whether it lies next to the last event: most vertices of an
-- outline that are not passed by an edge coming in where another leaves (see sweep) start two
-- edges or end two, one event after the other, next to each other along the line. An edge
-- coming in goes beside the edge that came in last from the same vertex when two tests vouch
-- for it (as for an edge taking another's place); an edge leaving is found by identity. Spares
-- most searches of a noisy circle, whose order holds hundreds of edges.
local function besideLast(s, coming)
  local t = lastUp
  if not coming then return s == t or s == lastDown end
  if not t or rank[sweepLeft[t]] ~= rank[sweepLeft[s]] then return nil end
  if edgeOrder(s, t) > 0 then
    local above = upEdge[t]
    if not above or edgeOrder(s, above) <= 0 then return lineOrder.beside(t, true) end
    return nil
  end
  local below = downEdge[t]
  if not below or edgeOrder(s, below) > 0 then return lineOrder.beside(t, false) end
  return nil
end

-- Where each ring lies, read off the order at its leftmost place: the edge just below the
-- ring's lowest edge there bounds the region the ring starts in. Every edge has the inside on
-- one side (the holes run against the outline), so a hole starts in the polygon's inside
-- exactly when that edge has the inside above it, and rings that do not cross keep all their
-- other points on that side too. An edge has the inside above it (in y-up terms, as edgeOrder)
-- when it runs rightwards and the rings turn positively, or leftwards and they turn negatively.
-- ringStart[r]: 1 when ring r starts inside the polygon, -1 outside, 0 undecided (its lowest
-- edge runs along the edge below: their order there is not known); ringBelow[r]: the edge below,
-- or false for none.
local ringStart, ringBelow, leftRank

-- Notes edge `below` (or nil) as the edge just below edge s, when s starts at its ring's
-- leftmost place and `below` is not the ring's own (another of its edges from that place).
-- Whether edge t runs along edge s where s starts (both ends of s on t's line).
local function alongside(t, s)
  return t and orient(sweepLeft[t], sweepRight[t], sweepLeft[s]) == 0
    and orient(sweepLeft[t], sweepRight[t], sweepRight[s]) == 0
end

local function noteBelow(s, below, above)
  local v = sweepLeft[s]
  local r = nodeRing[v]
  if rank[v] ~= leftRank[r] then return end
  if below and nodeRing[below] == r and rank[sweepLeft[below]] == rank[v] then return end
  ringBelow[r] = below or false
  -- an edge along s, on either side of it in the order, leaves the order there undecided; so
  -- does an edge along the edge below, right under it: two edges running along each other (a
  -- spike out of the outline, two parts of it meeting along a line), in an order not known
  -- here, one of them with the inside above it and one with the outside
  if alongside(below, s) or (above and nodeRing[above] ~= r and alongside(above, s))
    or (below and alongside(downEdge[below], below)) then
    ringStart[r] = 0
  elseif not below then
    ringStart[r] = -1
  else
    ringStart[r] = ((sweepLeft[below] == below) == (turn > 0)) and 1 or -1
  end
end

-- Notes where edge s, now at place `at` of the order, lies: above the edge below it, and below
-- the edge above it (which may start at its ring's leftmost place, where s comes in too).
local function noteRings(s)
  local above = upEdge[s]
  noteBelow(s, downEdge[s], above)
  if above and rank[sweepLeft[above]] == rank[sweepLeft[s]] then noteBelow(above, s, upEdge[above]) end
end

-- true when two edges of the rings at `starts` properly cross, false when none do, nil when the
-- order came out inconsistent (then the caller asks anyCrossing).
local function sweep(starts)
  local events, eventCount = sweepEvents(starts)
  ringStart, ringBelow, leftRank = {}, {}, {}
  for i = placeCount, 1, -1 do
    local k = placeOrder[i]
    leftRank[nodeRing[k]] = rank[k]
  end
  upEdge, downEdge = lineOrder.reset(eventCount / 2, capacity)   -- an edge comes in and leaves
  lastUp, lastDown = nil, nil
  belowOf = scratch(71, capacity)
  for i = 1, placeCount do belowOf[placeOrder[i]] = 0 end
  -- the place of the last event, its edge, and whether that edge left: an edge at the same
  -- place next to it has the same edges through the place beside it, noted already (most
  -- vertices of a spiky outline start two edges or end two)
  local walkRank, walkEdge, walkGone = 0, nil, false
  local i = 1
  while i <= eventCount do
    local e = events[i]
    local s = e > 0 and e or -e
    if e > 0 then
      local b, at = besideLast(s, true)
      if not b then b, at = lineOrder.find(s) end
      lineOrder.insert(b, at, s)
      local below, above = downEdge[s], upEdge[s]
      lastUp, lastDown = s, below
      local p = sweepLeft[s]
      if below and sweepLeft[below] ~= p then belowOf[p] = below end
      if rank[p] ~= walkRank or walkGone or (below ~= walkEdge and above ~= walkEdge) then
        noteTouches(p, s, downEdge)
        noteTouches(p, s, upEdge)
      end
      walkRank, walkEdge, walkGone = rank[p], s, false
      noteRings(s)
      if below and properlyCross(s, nextNode[s], below, nextNode[below]) then return true end
      if above and properlyCross(s, nextNode[s], above, nextNode[above]) then return true end
    else
      local below, above = downEdge[s], upEdge[s]
      -- an edge leaving, found by identity: right beside the last event, or when the edges
      -- beside it lie below and above it (else the search, which may find the order
      -- inconsistent)
      local beside = besideLast(s, false)
      if not beside and ((below and edgeOrder(s, below) < 0) or (above and edgeOrder(s, above) > 0)) then
        local f = lineOrder.edgeAt(lineOrder.find(s))   -- the first edge not below s
        while f and f ~= s and edgeOrder(s, f) == 0 do f = upEdge[f] end
        if f ~= s then return nil end
      end
      local p = sweepRight[s]
      if below and sweepRight[below] ~= p then belowOf[p] = below end
      if rank[p] ~= walkRank or not walkGone or not beside then
        noteTouches(p, s, downEdge)
        noteTouches(p, s, upEdge)
      end
      walkRank, walkEdge, walkGone = rank[p], s, true
      -- an edge coming in where s leaves (a vertex along the outline) most often takes its
      -- place: two tests vouch for it, and the order is not moved twice
      local t = events[i + 1]
      if t and t > 0 and rank[sweepLeft[t]] == rank[sweepRight[s]]
        and (not below or edgeOrder(t, below) > 0) and (not above or edgeOrder(t, above) <= 0) then
        lineOrder.replace(s, t)
        lastUp, lastDown = t, below
        walkEdge, walkGone = t, false
        noteRings(t)
        i = i + 1
        if below and properlyCross(t, nextNode[t], below, nextNode[below]) then return true end
        if above and properlyCross(t, nextNode[t], above, nextNode[above]) then return true end
      else
        lineOrder.remove(s)
        lastUp, lastDown = above, below
        if below and above and properlyCross(below, nextNode[below], above, nextNode[above]) then
          return true
        end
      end
    end
    i = i + 1
  end
  return false
end

-- Whether the chains cross or overlap at some place where several vertices meet, or where a
-- vertex lies inside an edge.
local function placesCross()
  local i = 1
  while i <= placeCount do
    local r, last = rank[placeOrder[i]], i
    while last < placeCount and rank[placeOrder[last + 1]] == r do last = last + 1 end
    if (last > i or touchedAt[r]) and chainsCross(placeOrder, i, last, touchedAt[r]) then
      -- the rings meeting there: two of the nodes, or a node and an edge through the place
      local touched = touchedAt[r]
      crossedA, crossedB = placeOrder[i], touched and touched[1] or placeOrder[last]
      for g = i + 1, last do
        if ringOf(placeOrder[g]) ~= ringOf(crossedA) then crossedB = placeOrder[g] end
      end
      return true
    end
    i = last + 1
  end
  return false
end

-- The check's usual way, before the sweep (its fallback): a grid of cells over the rings' box,
-- each edge filed in the cells it passes through, and every two edges filed in one cell whose
-- boxes overlap given the tests the sweep gives neighbours (a proper crossing, or an end of one
-- inside the other: touchedAt, for placesCross). Two edges that meet share the cell of a point
-- where they meet, so no meeting is missed. With edges short against the box (tile maps, map
-- data, drawn levels: an edge in a cell or two, meeting a few others) these are straight loops,
-- without the sweep's ordered search and shifts (150 to 250 ns an event on LuaJIT). Edges long
-- against the cells (a noisy circle's spikes) overlap by the dozen in every cell they cross,
-- where the sweep's order stays cheap: past GRID_REACH, GRID_BUDGET or GRID_PAIRS the grid is
-- given up for the sweep, and so it is when the cells are too small for the coordinates.
local GRID_LOAD = 1        -- edges a cell, about (2 was slower on map data: bench/NOTES.md)
local GRID_BUDGET = 6      -- cell entries an edge, on average, at most
local GRID_PAIRS = 48      -- pairs of edges sharing a cell, an edge, on average, at most
local GRID_REACH = 2       -- an edge's |dx| + |dy| in cells, on average, at most (a noisy
                           -- circle's reach 4 to 12: boxes overlapping by the dozen)
local GRID_FINE = 2^-24    -- a cell's side against the largest coordinate's magnitude, at least:
                           -- the rows' spans in x below then err by far less than GRID_MARGIN
local GRID_MARGIN = 0.25   -- cells: the spans' widening against rounding
local gridLeft, gridTop, gridScale, gridSize, gridCols, gridRows
local cellFirst, cellEdge  -- cellEdge[cellFirst[c] .. cellFirst[c + 1] - 1]: the edges in cell c
local boxX0, boxX1, boxY0, boxY1   -- boxX0[k] .. boxY1[k]: edge k's box (pairsCrossing's: by
                                   -- position along the ring)
local stamp                -- stamp[k]: the node whose ray last looked at edge k (see gridPlace)

-- (On LuaJIT min, not a branch: see fileShort. On PUC Lua the branch, cheaper than a call.)
local function gridCol(x)
  if JIT then return min(floor((x - gridLeft) * gridScale), gridCols - 1) end
  local col = floor((x - gridLeft) * gridScale)
  return col < gridCols and col or gridCols - 1
end
local function gridRow(y)
  if JIT then return min(floor((y - gridTop) * gridScale), gridRows - 1) end
  local row = floor((y - gridTop) * gridScale)
  return row < gridRows and row or gridRows - 1
end

-- The first and last cells (numbers, from 1) that the edge from node k to node q, not level,
-- may pass through in a row.
local function gridSpan(k, q, row)
  local x0, x1 = spanInRow(nodeX[k], nodeY[k], nodeX[q], nodeY[q], gridTop, gridSize, gridRows,
    row, GRID_MARGIN * gridSize)
  local base = row * gridCols + 1
  return base + gridCol(x0), base + gridCol(x1)
end

-- Notes that node p lies inside edge f (f's list at p's place, once).
local function touch(p, f)
  local r = rank[p]
  local list = touchedAt[r]
  if not list then list = {}; touchedAt[r] = list end
  for g = 1, #list do if list[g] == f then return end end
  list[#list + 1] = f
end

-- Whether node p, in line with nodes a and b, lies inside the segment a-b (not at an end).
-- (Two tests of two numbers: a branch per comparison grew side traces that aborted on tile
-- maps, whose edges lie in line by the hundred.)
local function within(p, a, b)
  local px, py, ax, ay, bx, by = nodeX[p], nodeY[p], nodeX[a], nodeY[a], nodeX[b], nodeY[b]
  return max(min(ax, bx) - px, px - max(ax, bx), min(ay, by) - py, py - max(ay, by)) <= 0
    and min(abs(px - ax) + abs(py - ay), abs(px - bx) + abs(py - by)) > 0
end

-- Whether edges e and f cross properly (then crossedA, crossedB are set); notes an end of
-- one inside the other.
local function pairCross(e, f)
  local a, b, c, d = e, nextNode[e], f, nextNode[f]
  if d == a then a, b, c, d, e, f = c, d, a, b, f, e end
  if b == c then   -- one after the other: they meet at b, and overlap only folded in line
    if orient(a, b, d) == 0 then
      if within(d, a, b) then touch(d, e) end
      if within(a, c, d) then touch(a, f) end
    end
    return false
  end
  local s1, s2 = orient(a, b, c), orient(a, b, d)
  if JIT then   -- c and d on one side (on PUC Lua the comparisons, cheaper than the calls)
    if min(s1, s2) > 0 or max(s1, s2) < 0 then return false end
  elseif (s1 > 0 and s2 > 0) or (s1 < 0 and s2 < 0) then
    return false
  end
  local s3, s4 = orient(c, d, a), orient(c, d, b)
  if min(max(s1, s2), -min(s1, s2)) > 0 and min(max(s3, s4), -min(s3, s4)) > 0 then
    crossedA, crossedB = a, c
    return true
  end
  if s1 == 0 and within(c, a, b) then touch(c, e) end
  if s2 == 0 and within(d, a, b) then touch(d, e) end
  if s3 == 0 and within(a, c, d) then touch(a, f) end
  if s4 == 0 and within(b, c, d) then touch(b, f) end
  return false
end

-- Files the edges listed in longEdges[1 .. long], those that pass more than two cells or more
-- than one row (see fileShort), in the cells they pass through, their entries after entry n:
-- the entries' count then, or nil past the budget. One loop over the cells of all their rows,
-- edge after edge, with few live values: nested loops' side traces aborted on LuaJIT
-- (bench/NOTES.md), and a loop per edge, a few cells long, was compiled late, while the row
-- and column helpers it called from the interpreter had their own traces abort until LuaJIT
-- blacklisted them, and with them every loop that calls them (one process in ten filed a noisy
-- 100-gon in 13 us instead of 5; bench/NOTES.md, session 26).
local entryCell, entryEdge, entryBudget
local function fileLong(longEdges, long, n)
  local j, k, q, row, lastRow, c, last = 0, 0, 0, 0, 0, 1, 0
  while true do
    if c <= last then
      if n >= entryBudget then return nil end
      n = n + 1
      entryCell[n], entryEdge[n] = c, k
      c = c + 1
    elseif row < lastRow then   -- the edge's next row
      row = row + 1
      c, last = gridSpan(k, q, row)
    else                        -- the next edge
      j = j + 1
      if j > long then return n end
      k = longEdges[j]
      q = nextNode[k]
      row, lastRow = gridRow(boxY0[k]), gridRow(boxY1[k])
      c, last = row * gridCols + gridCol(boxX0[k]) + 1, row * gridCols + gridCol(boxX1[k]) + 1
      if row < lastRow then c, last = gridSpan(k, q, row) end   -- rows apart: see gridSpan
    end
  end
end

-- Notes the box of edge k (to node q) and files it when it lies in one cell or in two side
-- by side: the entries' count then, or -1 - n for an edge left to fileLong. An edge in one cell
-- takes two entries too, the second in the spare cell past the grid (junkCell), which no loop
-- reads: a branch between one and two made a side trace that LuaJIT could not compile.
local junkCell
local function fileShort(k, q, n)
  local ax, ay, bx, by = nodeX[k], nodeY[k], nodeX[q], nodeY[q]
  local ex0, ex1, ey0, ey1 = min(ax, bx), max(ax, bx), min(ay, by), max(ay, by)
  boxX0[k], boxX1[k], boxY0[k], boxY1[k], stamp[k] = ex0, ex1, ey0, ey1, 0
  local row, c0, c1 = gridRow(ey0), gridCol(ex0), gridCol(ex1)
  if max(gridRow(ey1) - row, c1 - c0 - 1, n + 2 - entryBudget) > 0 then return -1 - n end
  local cell = row * gridCols + c0 + 1
  entryCell[n + 1], entryEdge[n + 1] = cell, k
  entryCell[n + 2], entryEdge[n + 2] = max(cell + c1 - c0, junkCell * (c0 + 1 - c1)), k
  return n + 2
end

-- Files every edge in the cells it passes through: true when done, false when the cells are
-- too small for the coordinates, or the entries or the pairs they make pass their budgets
-- (then the sweep). The edges are read ring after ring, in the nodes' order: read in the
-- places' x order, the node arrays were met at random, and a 120 by 120 tile map's filing
-- took a fifth longer (bench/NOTES.md, session 26).
local function fileEdges(starts)
  local x0, x1 = nodeX[placeOrder[1]], nodeX[placeOrder[placeCount]]
  local y0, y1, reach = huge, -huge, 0
  for r = 1, #starts do
    local s = starts[r]
    local k = s
    repeat
      local y, q = nodeY[k], nextNode[k]
      y0, y1 = min(y0, y), max(y1, y)
      reach = reach + abs(nodeX[q] - nodeX[k]) + abs(nodeY[q] - y)
      k = q
    until k == s
  end
  -- the outer ring has area: its box has width and height
  gridSize = sqrt((x1 - x0) * (y1 - y0) * GRID_LOAD / placeCount)
  if gridSize <= GRID_FINE * max(abs(x0), abs(x1), abs(y0), abs(y1)) or gridSize == huge
    or reach > GRID_REACH * gridSize * placeCount then
    return false   -- also when the box's area underflows or overflows
  end
  gridLeft, gridTop, gridScale = x0, y0, 1 / gridSize
  gridCols = min(floor((x1 - x0) * gridScale) + 1, placeCount)
  gridRows = min(floor((y1 - y0) * gridScale) + 1, placeCount)
  junkCell = gridCols * gridRows + 1
  entryBudget = GRID_BUDGET * placeCount
  -- made for 3 entries an edge (2 for most: a short edge's second may be the spare cell's);
  -- past that they grow
  entryCell, entryEdge = scratch(34, 3 * placeCount), scratch(35, 3 * placeCount)
  boxX0, boxX1 = scratch(36, capacity), scratch(37, capacity)
  boxY0, boxY1 = scratch(38, capacity), scratch(39, capacity)
  stamp = scratch(40, capacity)
  local n, long, longEdges = 0, 0, scratch(43, capacity)
  for r = 1, #starts do   -- the short edges; the others listed
    local s = starts[r]
    local k = s
    repeat
      local q = nextNode[k]
      n = fileShort(k, q, n)
      if n < 0 then n, long = -1 - n, long + 1; longEdges[long] = k end
      k = q
    until k == s
  end
  n = fileLong(longEdges, long, n)
  if not n then return false end
  -- the entries sorted by cell (counted, then placed)
  local cells = gridCols * gridRows
  cellFirst = scratch(41, cells + 2)
  for c = 1, cells + 2 do cellFirst[c] = 0 end
  for j = 1, n do
    local c = entryCell[j]
    cellFirst[c] = cellFirst[c] + 1
  end
  local at, pairCount = 1, 0   -- each cell's first entry, then (filling) its next one
  for c = 1, cells + 2 do
    local count = cellFirst[c]
    cellFirst[c], at, pairCount = at, at + count, pairCount + count * (count - 1)
  end
  local junk = cellFirst[junkCell + 1] - cellFirst[junkCell]
  pairCount = pairCount - junk * (junk - 1)   -- the spare cell's pairs are never tested
  if pairCount > 2 * GRID_PAIRS * placeCount then return false end
  cellEdge = scratch(42, n)
  for j = 1, n do
    local c = entryCell[j]
    cellEdge[cellFirst[c]], cellFirst[c] = entryEdge[j], cellFirst[c] + 1
  end
  for c = cells + 1, 1, -1 do cellFirst[c + 1] = cellFirst[c] end   -- back to first entries
  cellFirst[1] = 1
  return true
end

local foundA, foundB, foundLow, foundHigh   -- the crossing to name, so far, and its rings

-- Notes the crossing just found by pairCross (of edges e and f) when it comes first so far.
local function noteCrossing(e, f)
  local low, high = nodeRing[e], nodeRing[f]
  if low > high then low, high = high, low end
  if low < foundLow or (low == foundLow and high < foundHigh) then
    foundA, foundB, foundLow, foundHigh = crossedA, crossedB, low, high
  end
end

-- true when two edges cross properly, false when none do, nil when the grid was given up.
-- Of several crossings, the one named is the first by its rings (the outline's own first,
-- then by the lower ring, then the higher): the cells' order says nothing a user could use.
-- The pairs of each cell by nested loops. (One flat loop over all the pairs, with a branch for
-- the next entry and the next cell, left LuaJIT's root trace on whichever path the loop was
-- on when it got hot: in one process in four or five a cell's or an entry's change, and then
-- every pair's test ran through a side trace: eberly-6's call 0.97 ms, not 0.80. The nested
-- loops measured no slower on tile maps, of a pair or two a cell: bench/NOTES.md, session 26.)
local function gridCrossing(starts)
  if not fileEdges(starts) then return nil end
  keptFirst, keptEdge = cellFirst, cellEdge
  foundA, foundB, foundLow, foundHigh = nil, nil, huge, huge
  local cells = gridCols * gridRows
  for c = 1, cells do
    local last = cellFirst[c + 1] - 1
    for i = cellFirst[c], last - 1 do
      local e = cellEdge[i]
      for j = i + 1, last do
        local f = cellEdge[j]
        -- the boxes overlap: on LuaJIT one test of one number (its differences are exact in
        -- sign), on PUC Lua the comparisons, most often only the first (no call of max)
        if JIT then
          if max(boxX0[f] - boxX1[e], boxX0[e] - boxX1[f], boxY0[f] - boxY1[e], boxY0[e] - boxY1[f]) <= 0
            and pairCross(e, f) then
            noteCrossing(e, f)
          end
        elseif boxX0[f] <= boxX1[e] and boxX0[e] <= boxX1[f] and boxY0[f] <= boxY1[e]
          and boxY0[e] <= boxY1[f] and pairCross(e, f) then
          noteCrossing(e, f)
        end
      end
    end
  end
  crossedA, crossedB = foundA, foundB
  return foundA ~= nil
end

-- The same answer for an outline alone of few edges (PAIRS_ALL): every pair of edges whose
-- boxes meet gets the exact tests, with no cells to file them in; the boxes by position along
-- the ring (edges[i]'s at i), read in order. One loop over the pairs: nested loops here ran
-- every size at twice the time in one process in ten. (Past these sizes the pairs can cost
-- more than the cells: bench/NOTES.md, session 25.)
local PAIRS_ALL = JIT and 48 or 24
local function pairsCrossing(start)
  boxX0, boxX1 = scratch(36, capacity), scratch(37, capacity)
  boxY0, boxY1 = scratch(38, capacity), scratch(39, capacity)
  local edges, n, k = scratch(43, capacity), 0, start
  repeat   -- by position along the ring: the boxes of edges[i] at i
    local q = nextNode[k]
    local ax, ay, bx, by = nodeX[k], nodeY[k], nodeX[q], nodeY[q]
    n = n + 1
    edges[n], boxX0[n], boxX1[n], boxY0[n], boxY1[n] = k, min(ax, bx), max(ax, bx), min(ay, by), max(ay, by)
    k = q
  until k == start
  foundA, foundB, foundLow, foundHigh = nil, nil, huge, huge
  local i, j = 1, 2
  while true do
    if j <= n then
      if max(boxX0[j] - boxX1[i], boxX0[i] - boxX1[j], boxY0[j] - boxY1[i], boxY0[i] - boxY1[j]) <= 0
        and pairCross(edges[i], edges[j]) then
        noteCrossing(edges[i], edges[j])
      end
      j = j + 1
    elseif i + 2 <= n then
      i, j = i + 1, i + 2
    else
      break
    end
  end
  crossedA, crossedB = foundA, foundB
  return foundA ~= nil
end

-- The same answer for an outline alone whose edges are short across its width (most outlines
-- past PAIRS_ALL: a drawn shape, a noisy circle of a few hundred vertices): a sweep and prune.
-- The edges in the order of their left ends (read off the places' order: an edge comes with the
-- end of lower rank), each tested against those after it that start before it ends. The tests
-- an edge takes are about the times a vertical line meets the outline, the sum of |dx| over the
-- box's width: past PRUNE_LOAD the sweep's order is cheaper (noisy circles: the prune took 0.15
-- ms to the sweep's 0.18 at 400 vertices, 0.38 to 0.23 at 500; bench/NOTES.md, session 27), and
-- so the prune is not begun. Places stacked in a column (edges starting at one x by the dozen)
-- make more pairs than that estimate says: past twice PRUNE_LOAD tests an edge it is given up
-- midway, for the grid. nil when given up.
local PRUNE_LOAD = 20
local function pruneCrossing(start)
  local width, k = 0, start
  repeat
    local q = nextNode[k]
    width = width + abs(nodeX[q] - nodeX[k])
    k = q
  until k == start
  if width > PRUNE_LOAD * (nodeX[placeOrder[placeCount]] - nodeX[placeOrder[1]]) then return nil end
  boxX0, boxX1 = scratch(36, capacity), scratch(37, capacity)
  boxY0, boxY1 = scratch(38, capacity), scratch(39, capacity)
  local edges, n = scratch(43, capacity), 0
  for g = 1, placeCount do   -- boxes by position in the order: edges[i]'s at i
    local p = placeOrder[g]
    local r, q, o = rank[p], nextNode[p], prevNode[p]
    if r <= rank[q] then   -- the edge from p (of p and q, the one of lower rank holds it)
      local y, qy = nodeY[p], nodeY[q]
      n = n + 1
      edges[n], boxX0[n], boxX1[n], boxY0[n], boxY1[n] = p, nodeX[p], nodeX[q], min(y, qy), max(y, qy)
    end
    if r < rank[o] then    -- the edge to p
      local y, oy = nodeY[p], nodeY[o]
      n = n + 1
      edges[n], boxX0[n], boxX1[n], boxY0[n], boxY1[n] = o, nodeX[p], nodeX[o], min(y, oy), max(y, oy)
    end
  end
  foundA, foundB, foundLow, foundHigh = nil, nil, huge, huge
  local budget = 2 * PRUNE_LOAD * n
  for i = 1, n - 1 do
    local right, low, high = boxX1[i], boxY0[i], boxY1[i]
    local j = i + 1
    while j <= n and boxX0[j] <= right do
      -- the boxes overlap in y (in x they do): as in gridCrossing
      if JIT then
        if max(boxY0[j] - high, low - boxY1[j]) <= 0 and pairCross(edges[i], edges[j]) then
          noteCrossing(edges[i], edges[j])
        end
      elseif boxY0[j] <= high and low <= boxY1[j] and pairCross(edges[i], edges[j]) then
        noteCrossing(edges[i], edges[j])
      end
      j = j + 1
    end
    budget = budget - (j - i)
    if budget < 0 then return nil end
  end
  crossedA, crossedB = foundA, foundB
  return foundA ~= nil
end

-- Where the hole at node `start` lies, by the crossing rule along a row or a column of cells
-- (the rings do not cross): a message when outside the polygon or inside another hole, nil when well
-- placed, false when every vertex of the hole lies on another ring (holeMisplaced decides).
-- A ray from a vertex v of the hole, along its row or its column of cells to one side of the
-- grid (see rayOf): the other rings' edges it crosses lie in those cells (the edges reaching
-- v's level there pass through them). Crossing the edges of ring r an odd number of times
-- puts v inside ring r. An edge of another ring holding v (an end, or inside) leaves the count
-- undecided: the next vertex is tried.
local oddRing, oddRings = {}, {}

-- The ray a hole's vertex v is placed by: the cells it walks (from v's own, by `step`, to
-- `lastCell`), whether it runs along a column, whether it goes left (along a row) or down (along
-- a column), and the entries it reads. The side of v's row with fewer entries (a difference of
-- cellFirst's), or a side of its column when that row reads more entries than the grid has rows
-- (a wide flat outline: one or two rows of thousands of cells, where every hole's row ray read
-- half of all the entries: 1,000 holes in a strip took 68 ms to the sweep's 42).
local function rayOf(v, columns)
  local row, col = gridRow(nodeY[v]), gridCol(nodeX[v])
  local base = row * gridCols + 1
  local cell = base + col
  local left = cellFirst[cell + 1] - cellFirst[base]
  local right = cellFirst[base + gridCols] - cellFirst[cell]
  local lastCell, step, vertical, sense, count = base, -1, false, true, left
  if right < left then lastCell, step, sense, count = base + gridCols - 1, 1, false, right end
  if columns and count > gridRows then
    local up, down = 0, 0
    for c = col + 1, cell, gridCols do up = up + cellFirst[c + 1] - cellFirst[c] end
    for c = cell, junkCell - 1, gridCols do down = down + cellFirst[c + 1] - cellFirst[c] end
    if up < count and up <= down then
      lastCell, step, vertical, sense, count = col + 1, -gridCols, true, false, up
    elseif down < count then
      lastCell, step, vertical, sense, count = junkCell - gridCols + col, gridCols, true, true, down
    end
  end
  return cell, step, lastCell, vertical, sense, count
end

local function gridPlace(start)
  local ring = nodeRing[start]
  -- from the vertex whose row ray reads the fewest entries (holes are small: a few rows apart)
  local v, k, fewest = start, start, huge
  repeat
    local count = select(6, rayOf(k, false))
    if count < fewest then v, fewest = k, count end
    k = nextNode[k]
  until k == start
  start = v
  repeat
    local vx, vy = nodeX[v], nodeY[v]
    local cell, step, lastCell, vertical, sense = rayOf(v, true)
    -- the ray's level coordinate (y along a row, x along a column) and the edges' extent in it
    local vu, coord, low, high = vy, nodeY, boxY0, boxY1
    if vertical then vu, coord, low, high = vx, nodeX, boxX0, boxX1 end
    local decided, count = true, 0
    -- one loop over the cells' entries, cell after cell (see gridCrossing)
    local i, last = cellFirst[cell], cellFirst[cell + 1] - 1
    while true do
      if i > last then
        if cell == lastCell then break end
        cell = cell + step
        i, last = cellFirst[cell], cellFirst[cell + 1] - 1
      else
        local e = cellEdge[i]
        i = i + 1
        -- most entries do not reach v's level: that test first (on LuaJIT as one number, one
        -- branch; on PUC Lua two comparisons, cheaper than a call of max)
        local reaches
        if JIT then reaches = max(low[e] - vu, vu - high[e]) <= 0
        else reaches = low[e] <= vu and high[e] >= vu end
        if reaches and stamp[e] ~= v and nodeRing[e] ~= ring then
          stamp[e] = v
          local q = nextNode[e]
          local side = orient(e, q, v) * turn   -- the sign of (q - e) x (v - e)
          if side == 0 and boxX0[e] <= vx and boxX1[e] >= vx and boxY0[e] <= vy and boxY1[e] >= vy then
            decided = false
            break
          end
          local ua, ub = coord[e], coord[q]
          -- crossing v's level, ends at that level counted as below it (each crossing once);
          -- along a row v lies right of the crossing when side < 0 for an edge going down the
          -- screen, along a column below it when side > 0 for an edge going right
          if (ua > vu) ~= (ub > vu) and ((side < 0) == (ub > ua)) == sense then
            local r = nodeRing[e]
            local odd = oddRing[r]
            if odd == nil then count, odd = count + 1, false; oddRings[count] = r end
            oddRing[r] = not odd
          end
        end
      end
    end
    local message
    if decided then
      message = nil
      if not oddRing[1] then message = ("holes[%d] is outside the polygon"):format(ring - 1) end
      for j = 1, count do
        local r = oddRings[j]
        if r > 1 and oddRing[r] and not message then
          message = ("holes[%d] is inside holes[%d]"):format(ring - 1, r - 1)
        end
      end
    end
    for j = 1, count do oddRing[oddRings[j]] = nil; oddRings[j] = nil end
    if decided then return message end
    v = nextNode[v]
  until v == start
  return false
end

-- Placing the holes by the nearest crossing. The ray from a hole's vertex v to the left, at a
-- level just above v's (the crossing rule's half-open levels: an end at v's level counts as
-- below it), first meets some edge e of another ring; v lies in the region on e's side facing
-- it, as nothing lies between. When that side is the polygon's (every ring runs with the
-- polygon's inside on its orient > 0 side: the holes are linked reversed) and e is the
-- outline's, the hole is inside the outline, and outside every other hole unless one holds
-- the whole outline (one holding v would hold the outline's edge at e, and with no crossing all
-- of the outline; see gridPlaceAll). When e is another hole's, v lies where that hole's outside
-- lies, and the hole is placed as that one is. So a hole reads only the cells from v to the
-- nearest crossing, where the crossing rule reads half a row or column. Anything else (no
-- crossing, the other side, v on another ring's edge, two edges meeting the ray at one point, a
-- chain of holes coming back to one already on it) leaves the hole to gridPlace, which also
-- names the trouble.

-- The edge (its node) the ray from node v to the left meets first, with v on its polygon side
-- (orient > 0); or nil when that is not so or cannot be told here (see above).
local function nearestLeft(v)
  local ring, vx, vy = nodeRing[v], nodeX[v], nodeY[v]
  local rowFirst = gridRow(vy) * gridCols + 1
  local cell, stop = rowFirst + gridCol(vx), rowFirst
  local near, nearLow, nearUp = nil, 0, 0
  -- one loop over the cells' entries, cell after cell (see gridCrossing)
  local i, last = cellFirst[cell], cellFirst[cell + 1] - 1
  while true do
    if i > last then
      -- every crossing not yet seen lies in a column left of those walked, so further left
      -- than one a column left of the nearest's (its place estimated: the cells are coarse
      -- against the rounding, see GRID_FINE)
      if near then
        local lx, ly = nodeX[nearLow], nodeY[nearLow]
        local x = lx + (vy - ly) * (nodeX[nearUp] - lx) / (nodeY[nearUp] - ly)
        stop = max(stop, rowFirst + gridCol(x) - 1)
      end
      cell = cell - 1
      if cell < stop then break end
      i, last = cellFirst[cell], cellFirst[cell + 1] - 1
    else
      local e = cellEdge[i]
      i = i + 1
      if nodeRing[e] ~= ring and boxY0[e] <= vy and boxY1[e] >= vy then
        local q = nextNode[e]
        local side = orient(e, q, v)
        if side == 0 and boxX0[e] <= vx and boxX1[e] >= vx then return nil end   -- v on it
        local ey = nodeY[e]
        if (ey > vy) ~= (nodeY[q] > vy) then   -- crosses the level just above v's
          local low, up = e, q
          if ey > vy then low, up = q, e end
          -- left of v: v right of the edge low -> up
          if orient(low, up, v) * turn < 0 then
            if not near then
              near, nearLow, nearUp = e, low, up
            elseif e ~= near then   -- (an edge through several cells comes once a cell)
              local s = furtherRight(low, up, nearLow, nearUp)
              if s == 0 then return nil end
              if s > 0 then near, nearLow, nearUp = e, low, up end
            end
          end
        end
      end
    end
  end
  if near and orient(near, nextNode[near], v) > 0 then return near end
  return nil
end

local gridUsed   -- whether the last check went by the grid (then gridPlaceAll places the holes)
M.grid = true    -- false: the sweep always (for the specs that compare the two ways)
M.lastWay = nil  -- "pairs", "prune", "grid" or "sweep": the way the last check went (for those specs)
M.PAIRS_ALL = PAIRS_ALL
M.pairsLimit = PAIRS_ALL   -- an outline alone of this many places at most goes by the pairs (the
                           -- specs set 0 to send small outlines to the prune)
M.lastSlow = nil -- the holes the last check by the grid placed by gridPlace (for the specs)

local holeLefts, leftCount   -- each hole's first node in (x, y) order, and their count

-- The holes' first nodes in (x, y) order (the leftmost, the topmost of those), as the last check
-- found them: an array and a count.
function M.holeLefts() return holeLefts, leftCount end

-- The last check's cells, when it went by the grid (else nil): the edges (their first nodes) in
-- cell c at cellEdge[cellFirst[c] .. cellFirst[c + 1] - 1], cell c = row * columns + column + 1;
-- then the grid's left, top, scale (cells a unit), cell side, columns and rows. Every edge lies
-- in the cells of the points it passes through, within a quarter cell (GRID_MARGIN), and a
-- point's cell is the floor of its offset times the scale, clamped to the last column and row.
-- For triangulate.lua's bridges, which search these cells rather than build their own.
function M.edgeCells()
  if not keptFirst then return nil end
  return keptFirst, keptEdge, gridLeft, gridTop, gridScale, gridSize, gridCols, gridRows
end

-- After a check whose sweep went through and found each node at a place of its own, inside no
-- edge: the nodes in the sweep's order, their count, their ranks and belowOf; else nil.
function M.plainSweep()
  if not plain then return nil end
  return plainOrder, plainCount, plainRank, plainBelow
end

local function sweepCrossing(starts)
  keptFirst, keptEdge = nil, nil   -- (a hole of zero area may have been checked alone before)
  placeOrder, placeCount, rank = sortPlaces(starts, capacity)
  touchedAt = {}
  local crossing
  local way = "sweep"
  if M.grid and #starts == 1 and placeCount <= M.pairsLimit then
    crossing, way = pairsCrossing(starts[1]), "pairs"
  elseif M.grid then
    if #starts == 1 then crossing, way = pruneCrossing(starts[1]), "prune" end
    if crossing == nil then crossing, way = gridCrossing(starts), "grid" end
  end
  gridUsed = crossing ~= nil   -- (the pairs and the prune too: no sweep, and no holes to place)
  M.lastWay = gridUsed and way or "sweep"
  if crossing == nil then
    touchedAt = {}   -- the sweep notes them again
    crossing = sweep(starts)
  end
  if crossing == false and placesCross() then crossing = true end
  -- for polygon/monotone.lua (see M.plainSweep)
  plain = not gridUsed and crossing == false and next(touchedAt) == nil
    and rank[placeOrder[placeCount]] == placeCount
  plainOrder, plainCount, plainRank, plainBelow = placeOrder, placeCount, rank, belowOf
  -- the nodes at one place, linked in a circle (twin[k]: the next; k alone: itself), for the
  -- bridges to find a pinch point's nodes without walking the ring; and each hole's first node
  -- in (x, y) order, the one the bridges join (a sort of the holes by it took 5% of a tile
  -- map's call)
  local rings = 0
  for r = 1, #starts do rings = max(rings, nodeRing[starts[r]]) end
  local seen = scratch(56, rings)
  for r = 1, #starts do seen[nodeRing[starts[r]]] = false end
  leftCount = 0
  holeLefts = scratch(57, #starts)
  local i = 1
  while i <= placeCount do
    local first, last = i, i
    while last < placeCount and rank[placeOrder[last + 1]] == rank[placeOrder[first]] do last = last + 1 end
    for g = first, last do
      local k = placeOrder[g]
      twin[k] = placeOrder[g < last and g + 1 or first]
      local r = nodeRing[k]
      if r > 1 and not seen[r] then
        seen[r] = true
        leftCount = leftCount + 1
        holeLefts[leftCount] = k
      end
    end
    i = last + 1
  end
  sweepLeft, sweepRight, rank, upEdge, placeOrder, touchedAt, downEdge = nil, nil, nil, nil, nil, nil, nil
  lastUp, lastDown, belowOf = nil, nil, nil
  lineOrder.release()
  return crossing
end

-- The same answer by a plainer sweep, should sweepCrossing find its order inconsistent: the
-- edges sorted by their left end, each compared with the earlier ones still reaching it.
local function anyCrossing(starts)
  local edges, left = {}, {}
  for _, s in ipairs(starts) do
    local k = s
    repeat
      local q = nextNode[k]
      edges[#edges + 1] = k
      left[k] = min(nodeX[k], nodeX[q])
      k = q
    until k == s
  end
  sortKey = left
  sort(edges, bySortKey)
  local active, count = {}, 0
  for e = 1, #edges do
    local a = edges[e]
    local b = nextNode[a]
    local x0 = left[a]
    local y0, y1 = min(nodeY[a], nodeY[b]), max(nodeY[a], nodeY[b])
    local j = 1
    while j <= count do
      local c = active[j]
      local d = nextNode[c]
      if max(nodeX[c], nodeX[d]) < x0 then   -- ends before this edge begins: drop it
        active[j] = active[count]; active[count] = nil; count = count - 1
      else
        if max(nodeY[c], nodeY[d]) >= y0 and min(nodeY[c], nodeY[d]) <= y1
          and properlyCross(a, b, c, d) then
          return true
        end
        j = j + 1
      end
    end
    count = count + 1; active[count] = a
  end
  return false
end

-- Where the holes at starts[2], ... lie, when the grid found no crossing: the message for the
-- first one (in the holes' order) outside the polygon or inside another hole, else nil. Each
-- hole is placed by nearestLeft when it can be, through the chain of holes whose polygon side
-- its ray meets first, up to the outline; a hole that no vertex's ray places, or a chain that
-- comes back to a hole on it, by gridPlace (then by holeMisplaced). placed[r]: ring r's
-- verdict, kept for the chains that reach it (false while on the chain being followed). A hole
-- not placed is placed by gridPlace, which names the trouble. So a hole placed inside the
-- outline is passed even when another hole holds the whole outline: that one is outside, and
-- is named when its turn comes (as the sweep names it). gridPlace runs once a hole (its
-- stamps would hide edges from a second run from the same vertex): told[r] keeps its message,
-- or true for none.
local told, placed, chain, indexOf = {}, {}, {}, {}   -- by ring; emptied after each call
local function slowPlace(starts, i)
  local r = nodeRing[starts[i]]
  if told[r] == nil then
    M.lastSlow = M.lastSlow + 1
    local message = gridPlace(starts[i])
    if message == false then message = holeMisplaced(starts, i) end
    told[r] = message or true
  end
  return told[r] ~= true and told[r] or nil
end

local function placeAll(starts)
  M.lastSlow = 0
  for i = 2, #starts do indexOf[nodeRing[starts[i]]] = i end
  for i = 2, #starts do
    local r, count, ok = nodeRing[starts[i]], 0, nil
    while ok == nil do
      ok = placed[r]
      if ok == nil then
        count = count + 1
        chain[count], placed[r] = r, false
        -- from the hole's first vertex, or the next ones while a ray cannot tell
        local s = starts[indexOf[r]]
        local v, e = s
        repeat
          e = nearestLeft(v)
          v = nextNode[v]
        until e or v == s
        if not e then
          ok = slowPlace(starts, indexOf[r]) == nil
        elseif nodeRing[e] == 1 then
          ok = true
        else
          r = nodeRing[e]
        end
      end
    end
    for j = 1, count do placed[chain[j]] = ok end
    if not ok then
      local message = slowPlace(starts, i)
      if message then return message end
    end
  end
  return nil
end

local function gridPlaceAll(starts)
  local message = placeAll(starts)
  for i = 2, #starts do
    local r = nodeRing[starts[i]]
    told[r], placed[r], chain[i - 1], indexOf[r] = nil, nil, nil, nil
  end
  return message
end

-- nil when the rings at starts (starts[1] the outline, then the holes with area) are a valid
-- input, else the message naming the trouble: which rings cross, or a hole outside the polygon
-- or inside another hole.
local function trouble(starts)
  local crossing = sweepCrossing(starts)
  local ordered = crossing ~= nil   -- the sweep's order held: ringStart is known
  if crossing == nil then crossing = anyCrossing(starts) end
  if crossing then return crossingMessage() end
  if gridUsed then return gridPlaceAll(starts) end
  for i = 2, #starts do
    local h = nodeRing[starts[i]]   -- hole h - 1
    local start = ordered and ringStart[h] or 0
    if start < 0 then
      local g = ringBelow[h] and nodeRing[ringBelow[h]] or 1
      if g == 1 then return ("holes[%d] is outside the polygon"):format(h - 1) end
      return ("holes[%d] is inside holes[%d]"):format(h - 1, g - 1)
    end
    if start == 0 then
      local misplaced = holeMisplaced(starts, i)
      if misplaced then return misplaced end
    end
  end
  return nil
end

function M.ringsTrouble(starts)
  local message = trouble(starts)
  ringStart, ringBelow, leftRank = nil, nil, nil
  cellFirst, cellEdge, boxX0, boxX1, boxY0, boxY1, stamp = nil, nil, nil, nil, nil, nil, nil
  entryCell, entryEdge = nil, nil
  return message
end

M.anyCrossing = anyCrossing

return M
