-- polygon/triangulate.lua: polygonTriangulate and polygonConvexParts: ear clipping with holes
-- bridged in, a sweep that refuses crossing rings, and the merge of triangles into convex
-- parts. Every decision is one of kernel's exact signs.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local check = require(_PACKAGE .. ".check")
local object = require(_PACKAGE .. ".object")

local abs, sqrt, huge, min, max = math.abs, math.sqrt, math.huge, math.min, math.max
local floor, sort = math.floor, table.sort
local CROSS_BOUND, crossExact, JIT = kernel.CROSS_BOUND, kernel.crossExact, kernel.JIT
local cross, areaSign = kernel.cross, kernel.areaSign
local checkPoints = check.checkPoints
local shapeBehind = check.shapeBehind
local validate = object.validate

local M = {}


-- Ear clipping over one ring of vertex nodes: holes are first joined to the outer ring by a
-- bridge to a vertex they see (Eberly's method), an ear is a strictly convex vertex whose
-- triangle no other vertex blocks, and the vertices that could block it are found in a grid of
-- cells, visited along the triangle row by row, holding only vertices that are not strictly
-- convex (or sit at a pinch point), so an ear test looks at the few vertices near its triangle,
-- not at all of them. Every decision is an exact sign (orient: cross's filter, then crossExact);
-- coordinates are only ever copied.
-- The nodes live in arrays indexed by node number, set up by one call and dropped at its end.


-- An empty table with room for `size` array entries: LuaJIT's table.new, {} elsewhere. The
-- node arrays are filled in order up to tens of thousands of entries; grown one entry at a
-- time, each is copied at every doubling and leaves its old parts as garbage.
local newArray = function() return {} end
do
  local found, tableNew = pcall(require, "table.new")
  if found then newArray = function(size) return tableNew(size, 0) end end
end
local capacity          -- the number of nodes a call can make, at most: the arrays' size

local nodeX, nodeY      -- coordinates as doubles (+ 0.0), for the predicates
local inX, inY          -- the caller's values, copied into the output bit for bit
local origin            -- the input vertex a node stands for (a bridge copies two of them)
local nodeRing          -- the ring a node was made for: 1 the outline, h + 1 hole h
local nextNode, prevNode, nodeCount
local gone              -- gone[k]: node k has been unlinked
local cellStart         -- the ear test's grid (see buildGrid): where cell c's entries begin
local entryX, entryY, entryNode   -- its entries, cell by cell: a node's place and number
local entryOf           -- entryOf[k]: node k's entry
local listed            -- listed[k]: node k is still in the ear test's grid
local shared            -- shared[k]: another node lies at node k's place
local reflexSeen        -- reflexSeen[k]: node k was found not strictly convex and has kept
                        -- its neighbours since
local listStale         -- a node dropped from the grid may have turned reflex
local turn              -- the sign of the outer ring's area: > 0 clockwise on screen

-- Sort orders, made once: a function made per call would keep LuaJIT from compiling its caller.
local sortKey
local function bySortKey(a, b) return sortKey[a] < sortKey[b] end
local function leftmostFirst(a, b)
  return nodeX[a] < nodeX[b] or (nodeX[a] == nodeX[b] and nodeY[a] < nodeY[b])
end

-- A number with the sign of (b - a) x (c - a) for nodes, times turn: > 0 when c lies on the
-- interior side of the directed edge a -> b of a ring wound like the outer one. Only its sign
-- means anything.
local function orient(a, b, c)
  local ax, ay, bx, by, cx, cy = nodeX[a], nodeY[a], nodeX[b], nodeY[b], nodeX[c], nodeY[c]
  -- c at b is common (edges meeting at a vertex): 0 at once, as the filter would go exact
  if (cx == bx and cy == by) or (cx == ax and cy == ay) then return 0 end
  -- cross's filter written out, with crossExact only when it cannot vouch for the sign: the call
  -- with eight arguments made LuaJIT abort its side traces over and over ("register coalescing
  -- too complex"), as did branches taken half the time
  local l, r = (bx - ax) * (cy - ay), (by - ay) * (cx - ax)
  local s = l - r
  local e = CROSS_BOUND * abs(l + r)
  -- one test of |s|, not one per sign: a branch taken for half the nodes (convex or reflex)
  -- made side traces that aborted until LuaJIT flushed all its traces
  if abs(s) < e or s ~= s then   -- also when l and r differ in sign and s is 0: exact, rare
    s = crossExact(ax, ay, bx, by, ax, ay, cx, cy)
  end
  return s * turn
end

local function same(a, b)
  return nodeX[a] == nodeX[b] and nodeY[a] == nodeY[b]
end

-- The ring node k was made for: 1 the outline, h + 1 hole h.
local crossedA, crossedB   -- nodes of the two edges found crossing (or meeting wrongly), for
                           -- the message naming their rings
local function ringOf(k)
  return nodeRing[k]
end

-- The message for two rings found crossing or meeting wrongly (crossedA, crossedB).
local function crossingMessage()
  local r, g = ringOf(crossedA), ringOf(crossedB)
  if r > g then r, g = g, r end
  if g == 1 then return "edges cross" end
  if r == g then return ("holes[%d] crosses itself"):format(g - 1) end
  if r == 1 then return ("holes[%d] crosses the outline"):format(g - 1) end
  return ("holes[%d] and holes[%d] cross"):format(r - 1, g - 1)
end

local function newNode(x, y, id)
  nodeCount = nodeCount + 1
  local k = nodeCount
  inX[k], inY[k], nodeX[k], nodeY[k], origin[k] = x, y, x + 0.0, y + 0.0, id
  return k
end

-- Drops node k from its cell of the ear test's grid.
local function unlist(k)
  listed[k] = false
  entryX[entryOf[k]] = huge   -- no span holds it: the scans pass over it
end

-- Unlinks node k from the ring and, once built, from the ear test's grid.
local function unlink(k)
  gone[k] = true
  local p, q = prevNode[k], nextNode[k]
  nextNode[p], prevNode[q] = q, p
  if listed and listed[k] then unlist(k) end
end

-- Links the vertices of a flat array into a ring, in reverse when `reversed`, skipping
-- repeated consecutive vertices. firstId: the id of the array's first vertex. Returns a node.
local function linkRing(points, n, firstId, reversed, ring)
  local first, last
  for j = 1, n - 1, 2 do
    local i = reversed and n - j or j
    local x, y = points[i], points[i + 1]
    if not last or x + 0.0 ~= nodeX[last] or y + 0.0 ~= nodeY[last] then
      local k = newNode(x, y, firstId + (i - 1) / 2)
      nodeRing[k] = ring
      if last then nextNode[last], prevNode[k] = k, last else first = k end
      last = k
    end
  end
  nextNode[last], prevNode[first] = first, last
  if last ~= first and same(first, last) then unlink(last) end
  return first
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
-- The vertices are sorted by place in expected linear time (buckets by x, see sortPlaces);
-- the order along the line is a sorted array, searched by halving. (A skip list, which spares
-- the array's shifts, made LuaJIT grow traces until its machine-code area ran out.)
-- The sweep stays in this file, with the ear clipping: both read the node arrays, which one
-- call makes and drops, through orient, which reads the call's turn; a file of its own would
-- share that state across files or pass it through its hot loops as arguments.
local sweepLeft, sweepRight
local rank                  -- rank[k]: node k's place in (x, y) order (1 for the first place)
local placeOrder, placeCount   -- the nodes in (x, y) order (see sortPlaces), and their count

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

local BUCKET_RUN = 24   -- a bucket holding more nodes than this is sorted by table.sort
                        -- (many vertices on one vertical line), fewer by insertion

-- The nodes of the rings at `starts` in (x, y) order, and their count: counted into as many
-- buckets as nodes by x (the bucket is monotone in x), then each bucket sorted. Sets rank.
local function sortPlaces(starts)
  local x0, x1, count = huge, -huge, 0
  for _, s in ipairs(starts) do
    local k = s
    repeat
      x0, x1, count = min(x0, nodeX[k]), max(x1, nodeX[k]), count + 1
      k = nextNode[k]
    until k == s
  end
  local scale = count / (x1 - x0)   -- x1 > x0: the outer ring has area
  local bucketOf, first = newArray(capacity), newArray(count + 1)
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
  local order, fill = newArray(count), newArray(count)
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
      local run = {}
      for i = lo, hi do run[i - lo + 1] = order[i] end
      sort(run, leftmostFirst)
      for i = lo, hi do order[i] = run[i - lo + 1] end
    else
      for i = lo + 1, hi do
        local k, j = order[i], i - 1
        while j >= lo and leftmostFirst(k, order[j]) do order[j + 1] = order[j]; j = j - 1 end
        order[j + 1] = k
      end
    end
  end
  rank = newArray(capacity)
  local place = 0
  for i = 1, count do
    local k = order[i]
    if i == 1 or not same(k, order[i - 1]) then place = place + 1 end
    rank[k] = place
  end
  placeOrder, placeCount = order, count
  return order, count
end

-- The events in order: by place, and at one place every edge leaving before any coming in.
local function sweepEvents(starts)
  local order, count = sortPlaces(starts)
  sweepLeft, sweepRight = newArray(capacity), newArray(capacity)
  for _, s in ipairs(starts) do
    local k = s
    repeat
      local q = nextNode[k]
      if rank[k] < rank[q] then sweepLeft[k], sweepRight[k] = k, q else sweepLeft[k], sweepRight[k] = q, k end
      k = q
    until k == s
  end
  local events, e = newArray(2 * count), 0
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

local status, lastPlace   -- the edges in order along the line; where the last event's edge was
local touchedAt         -- touchedAt[r]: the edges whose inside holds the place of rank r, or nil

-- Notes the edges next to place `from` of the order, going `step` (-1 or 1), that hold node p:
-- a run of edges through p's place, each ending there or holding it inside (noted in
-- touchedAt, for placesCross). An edge holding p inside lies next to an edge ending at p, or
-- next to another edge through p, when an edge ending at p comes in or leaves.
local function noteTouches(p, from, step)
  local px, py = nodeX[p], nodeY[p]
  local j = from + step
  local f = status[j]
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
    j = j + step
    f = status[j]
  end
end

-- Where edge s goes or is, when next to the last event's edge, or 0: most vertices of an
-- outline that are not passed by an edge coming in where another leaves (see sweep) start two
-- edges or end two, one event after the other, next to each other along the line. An edge
-- coming in goes beside the edge that came in last from the same vertex when two tests vouch
-- for it (as for an edge taking another's place); an edge leaving is found by identity. Spares
-- most searches of a noisy circle, whose order holds hundreds of edges.
local function besideLast(s, coming)
  local t = status[lastPlace]
  if coming then
    if not t or rank[sweepLeft[t]] ~= rank[sweepLeft[s]] then return 0 end
    if edgeOrder(s, t) > 0 then
      local above = status[lastPlace + 1]
      return (not above or edgeOrder(s, above) <= 0) and lastPlace + 1 or 0
    end
    local below = status[lastPlace - 1]
    return (not below or edgeOrder(s, below) > 0) and lastPlace or 0
  end
  if t == s then return lastPlace end
  return status[lastPlace - 1] == s and lastPlace - 1 or 0
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
  -- an edge along s, on either side of it in the order, leaves the order there undecided
  if alongside(below, s) or (above and nodeRing[above] ~= r and alongside(above, s)) then
    ringStart[r] = 0
  elseif not below then
    ringStart[r] = -1
  else
    ringStart[r] = ((sweepLeft[below] == below) == (turn > 0)) and 1 or -1
  end
end

-- Notes where edge s, now at place `at` of the order, lies: above the edge below it, and below
-- the edge above it (which may start at its ring's leftmost place, where s comes in too).
local function noteRings(s, at)
  local above = status[at + 1]
  noteBelow(s, status[at - 1], above)
  if above and rank[sweepLeft[above]] == rank[sweepLeft[s]] then noteBelow(above, s, status[at + 2]) end
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
  -- the order is status[bottom + 1 .. bottom + m]. On LuaJIT an edge coming in or leaving
  -- shifts the shorter side, so bottom moves, by one per event at most: starting it half the
  -- events up keeps it in the array. (A vertical line meets some 650 edges of a noisy circle
  -- of 10,000 vertices: the shorter side moves 200 entries a vertex where one side moved 440.)
  local m, bottom = 0, JIT and eventCount or 0
  status, touchedAt = newArray(2 * eventCount + 2), {}
  lastPlace = bottom + 1
  local i = 1
  while i <= eventCount do
    local e = events[i]
    local s = e > 0 and e or -e
    local lo = besideLast(s, e > 0)
    if lo == 0 then   -- the first place whose edge does not lie below s
      local hi
      lo, hi = bottom + 1, bottom + m + 1
      while lo < hi do
        local mid = (lo + hi - (lo + hi) % 2) / 2
        if edgeOrder(s, status[mid]) > 0 then lo = mid + 1 else hi = mid end
      end
    end
    if e > 0 then
      if not JIT then   -- on PUC Lua table.insert's C loop is faster than a loop in Lua
        table.insert(status, lo, s)
      elseif lo - bottom - 1 < bottom + m + 1 - lo then   -- fewer entries below: shift those down
        for j = bottom + 1, lo - 1 do status[j - 1] = status[j] end
        bottom, lo = bottom - 1, lo - 1
        status[lo] = s
      else
        for j = bottom + m, lo, -1 do status[j + 1] = status[j] end
        status[lo] = s
      end
      m = m + 1
      lastPlace = lo
      noteTouches(sweepLeft[s], lo, -1)
      noteTouches(sweepLeft[s], lo, 1)
      noteRings(s, lo)
      local below, above = status[lo - 1], status[lo + 1]
      if below and properlyCross(s, nextNode[s], below, nextNode[below]) then return true end
      if above and properlyCross(s, nextNode[s], above, nextNode[above]) then return true end
    else
      while lo <= bottom + m and status[lo] ~= s and edgeOrder(s, status[lo]) == 0 do lo = lo + 1 end
      if status[lo] ~= s then return nil end
      lastPlace = lo
      noteTouches(sweepRight[s], lo, -1)
      noteTouches(sweepRight[s], lo, 1)
      local below, above = status[lo - 1], status[lo + 1]
      -- an edge coming in where s leaves (a vertex along the outline) most often takes its
      -- place: two tests vouch for it, and the list is not shifted twice
      local t = events[i + 1]
      if t and t > 0 and rank[sweepLeft[t]] == rank[sweepRight[s]]
        and (not below or edgeOrder(t, below) > 0) and (not above or edgeOrder(t, above) <= 0) then
        status[lo] = t
        noteRings(t, lo)
        i = i + 1
        if below and properlyCross(t, nextNode[t], below, nextNode[below]) then return true end
        if above and properlyCross(t, nextNode[t], above, nextNode[above]) then return true end
      else
        if not JIT then   -- as for table.insert above (on LuaJIT the loop is faster)
          table.remove(status, lo)
        elseif lo - bottom - 1 < bottom + m - lo then   -- the entries below s move up
          for j = lo, bottom + 2, -1 do status[j] = status[j - 1] end
          status[bottom + 1] = nil
          bottom = bottom + 1
          lastPlace = lo + 1   -- as when the entries above move down: the two ends are at
        else                   -- lastPlace - 1 and lastPlace
          for j = lo, bottom + m - 1 do status[j] = status[j + 1] end
          status[bottom + m] = nil
        end
        m = m - 1
        if below and above and properlyCross(below, nextNode[below], above, nextNode[above]) then
          return true
        end
      end
    end
    i = i + 1
  end
  return false
end

-- Where several vertices meet, or a vertex lies inside an edge, the outline may cross or
-- overlap itself without two edges crossing properly (the sweep's test). Around such a place
-- each vertex is a chain: an edge coming in (from its node's predecessor) and one going out
-- (to its successor); an edge holding the place inside is a chain too. Sorted by angle, the
-- edges must alternate, in, out, in, out: crossing an edge changes the winding number by one,
-- up for one kind and down for the other, so two of a kind in a row make a sector covered
-- twice (or wound the wrong way). And no two chains may interleave (the in-out pairs must nest
-- like brackets): chains that interleave cross there, whatever is done near the place. Edges
-- in one direction overlap along it: crossing them all changes the winding number by those
-- leaving less those reaching, which must be -1, 0 or 1 (two edges leaving in one direction,
-- none reaching: the region between them is inside one and outside the other); past that
-- their order across the direction is not known there (a slit, a bridge, a spike along an
-- edge): one edge each way may go in either order (each is tried), more leave the place
-- untested. An entry is 2k for the edge from node k to its
-- successor, 2k + 1 for the edge from its predecessor; an edge f holding the place inside is
-- chain k = capacity + f, its ends f (before) and f's successor (after).
local placeX, placeY        -- the place being tested, for byAngle
local function entryTarget(entry)
  local k = (entry - entry % 2) / 2
  if k > capacity then
    local f = k - capacity
    return entry % 2 == 0 and nextNode[f] or f
  end
  return entry % 2 == 0 and nextNode[k] or prevNode[k]
end
-- Whether the entry u's edge comes before v's by angle about the place, from the +x axis
-- (exact: the side of the x axis, then the sign of a cross product).
local function byAngle(u, v)
  local a, b = entryTarget(u), entryTarget(v)
  local ax, ay, bx, by = nodeX[a], nodeY[a], nodeX[b], nodeY[b]
  local lowerA = ay < placeY or (ay == placeY and ax < placeX)
  local lowerB = by < placeY or (by == placeY and bx < placeX)
  if lowerA ~= lowerB then return lowerB end
  return cross(placeX, placeY, ax, ay, placeX, placeY, bx, by) > 0
end

-- Whether the chains of the nodes placeOrder[first..last], all at one place, and of the edges
-- `touched` holding it inside (or nil), cross or overlap there (see above).
local TIED_PAIRS = 4      -- pairs of edges along one another (both ways) at a place, at most,
                        -- whose 2^pairs orders are tried; past that the place is not tested

-- Whether entries[1..count], sorted by angle, alternate in and out and nest like brackets.
local function alternateAndNest(entries, count)
  local open, depth = {}, 0   -- the chains' pairs, as brackets
  for j = 1, count do
    local u = entries[j]
    if u % 2 == entries[j % count + 1] % 2 then return false end   -- two of a kind in a row
    local chain = (u - u % 2) / 2
    if depth > 0 and open[depth] == chain then
      open[depth] = nil
      depth = depth - 1
    else
      depth = depth + 1
      open[depth] = chain
    end
  end
  return depth == 0
end

local function chainsCross(first, last, touched)
  local entries, count = {}, 0
  for g = first, last do
    local k = placeOrder[g]
    entries[count + 1], entries[count + 2] = 2 * k, 2 * k + 1
    count = count + 2
  end
  for g = 1, touched and #touched or 0 do
    local k = capacity + touched[g]
    entries[count + 1], entries[count + 2] = 2 * k, 2 * k + 1
    count = count + 2
  end
  placeX, placeY = nodeX[placeOrder[first]], nodeY[placeOrder[first]]
  sort(entries, byAngle)
  local at, tied = 1, {}
  while at <= count do   -- the runs of edges in one direction: count those leaving, reaching
    local u, runEnd, balance = entries[at], at, 0
    while runEnd < count and not byAngle(u, entries[runEnd + 1]) do runEnd = runEnd + 1 end
    for j = at, runEnd do balance = balance + (entries[j] % 2 == 0 and 1 or -1) end
    if balance > 1 or balance < -1 then return true end
    if runEnd > at + 1 then return false end   -- three or more: not decided here
    if runEnd == at + 1 then tied[#tied + 1] = at end   -- one each way: either order
    at = runEnd + 1
  end
  if #tied > TIED_PAIRS then return false end
  for orders = 0, 2 ^ #tied - 1 do   -- bit t of orders: swap the t-th tied pair
    local swapped = orders
    for t = 1, #tied do
      local j = tied[t]
      if swapped % 2 == 1 then entries[j], entries[j + 1] = entries[j + 1], entries[j] end
      swapped = (swapped - swapped % 2) / 2
    end
    if alternateAndNest(entries, count) then return false end
    swapped = orders
    for t = 1, #tied do
      local j = tied[t]
      if swapped % 2 == 1 then entries[j], entries[j + 1] = entries[j + 1], entries[j] end
      swapped = (swapped - swapped % 2) / 2
    end
  end
  return true
end

-- Whether the chains cross or overlap at some place where several vertices meet, or where a
-- vertex lies inside an edge.
local function placesCross()
  local i = 1
  while i <= placeCount do
    local r, last = rank[placeOrder[i]], i
    while last < placeCount and rank[placeOrder[last + 1]] == r do last = last + 1 end
    if (last > i or touchedAt[r]) and chainsCross(i, last, touchedAt[r]) then
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

local function sweepCrossing(starts)
  local crossing = sweep(starts)
  if crossing == false and placesCross() then crossing = true end
  sweepLeft, sweepRight, rank, status, placeOrder, touchedAt = nil, nil, nil, nil, nil, nil
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
-- vertex off another ring decides), when the sweep could not tell: a message when it is outside
-- the polygon or inside another hole, else nil.
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

-- Whether the direction from node k to node t points strictly into the interior at k.
local function sectorHolds(k, t)
  local a, c = prevNode[k], nextNode[k]
  local s1, s2 = orient(a, k, t), orient(k, c, t)
  if orient(a, k, c) > 0 then return s1 > 0 and s2 > 0 end
  return s1 > 0 or s2 > 0
end

-- Among the nodes of the ring at s at the place of node m, one whose interior holds the
-- direction towards node t (a pinch point has several; each sees a different side).
local function copyFacing(s, m, t)
  local k, found = s, m
  repeat
    if same(k, m) and sectorHolds(k, t) then found = k end
    k = nextNode[k]
  until k == s
  return found
end

-- Which of two edges, each crossing the line y = hy strictly between its ends, meets it further
-- right: 1 when f does, -1 when e does, 0 when they meet it at one point. The edges do not
-- properly cross, so one end of either, tested against the other, tells. e and f are the
-- lower ends' nodes (by y), eh and fh the upper.
local function rightOf(e, eh, f, fh)
  local s
  if nodeY[f] >= nodeY[e] then s = -orient(e, eh, f) else s = orient(f, fh, e) end
  if s == 0 then
    if nodeY[fh] <= nodeY[eh] then s = -orient(e, eh, fh) else s = orient(f, fh, eh) end
  end
  return s * turn   -- orient's sign times turn is the plain sign of the cross product
end

-- Whether (x, y), in line with (hx, hy) and (bx, by) on the same side, lies strictly between.
local function between(hx, hy, x, y, bx, by)
  if x ~= bx then return (hx < x) == (x < bx) and x ~= hx end
  return (hy < y) == (y < by) and y ~= hy
end

-- The node of the ring at s that the hole's leftmost node h joins: the nearest point hit by the
-- ray from h to the left is a vertex, or lies on an edge whose left end P is seen from h unless
-- another vertex in the triangle (h, hit, P) is: the one there at the least angle from the ray
-- (nearest on ties) is seen. nil when the ray hits nothing (the hole is outside).
local function bridgeTarget(s, h)
  local hx, hy = nodeX[h], nodeY[h]
  local vertex, lo, hi   -- the nearest hit so far: a vertex, or an edge lo -> hi (upwards in y)
  local k = s
  repeat
    local q = nextNode[k]
    local x, y = nodeX[k], nodeY[k]
    if y == hy and x <= hx then
      if x == hx then return copyFacing(s, k, nextNode[h]) end   -- the hole touches the ring here
      if lo then
        if cross(nodeX[lo], nodeY[lo], nodeX[hi], nodeY[hi], nodeX[lo], nodeY[lo], x, y) <= 0 then
          vertex, lo, hi = k, nil, nil
        end
      elseif not vertex or x > nodeX[vertex] then
        vertex = k
      end
    end
    local qy = nodeY[q]
    if (y < hy and qy > hy) or (y > hy and qy < hy) then
      local a, b = k, q
      if y > qy then a, b = q, k end
      local ax, ay = nodeX[a], nodeY[a]
      if cross(ax, ay, nodeX[b], nodeY[b], ax, ay, hx, hy) <= 0 then   -- meets the ray
        if vertex then
          if cross(ax, ay, nodeX[b], nodeY[b], ax, ay, nodeX[vertex], nodeY[vertex]) > 0 then
            vertex, lo, hi = nil, a, b
          end
        elseif not lo or rightOf(lo, hi, a, b) > 0 then
          lo, hi = a, b
        end
      end
    end
    k = q
  until k == s
  if vertex then return copyFacing(s, vertex, h) end
  if not lo then return nil end
  -- the edge's left end: mirrored Eberly (the ray goes left), P.x <= hit.x < hx, so the
  -- triangle (h, hit, P) lies left of h and holds no part of the hole
  local p = nodeX[hi] < nodeX[lo] and hi or lo
  local side = nodeY[p] > hy and 1 or -1   -- the side of the ray the triangle lies on
  local lx, ly, ux, uy = nodeX[lo], nodeY[lo], nodeX[hi], nodeY[hi]
  local best = p
  k = s
  repeat
    local x, y = nodeX[k], nodeY[k]
    if (y - hy) * side > 0 and cross(lx, ly, ux, uy, lx, ly, x, y) <= 0 then
      local c = cross(hx, hy, nodeX[p], nodeY[p], hx, hy, x, y) * side
      if c >= 0 then   -- inside the triangle (h, hit, P) or on its sides
        local t = cross(hx, hy, x, y, hx, hy, nodeX[best], nodeY[best]) * side
        if t < 0 or (t == 0 and between(hx, hy, x, y, nodeX[best], nodeY[best])) then best = k end
      end
    end
    k = nextNode[k]
  until k == s
  return copyFacing(s, best, h)
end

-- Joins the hole ring at node h to the ring at node m: m -> h ... around the hole ... h' -> m'
-- with h' and m' new nodes at the places of h and m. A hole touching the ring (m at h) makes
-- repeated vertices, removed at once.
local function bridge(m, h)
  local m2, h2 = newNode(inX[m], inY[m], origin[m]), newNode(inX[h], inY[h], origin[h])
  local mn, hp = nextNode[m], prevNode[h]
  nextNode[m], prevNode[h] = h, m
  nextNode[hp], prevNode[h2] = h2, hp
  nextNode[h2], prevNode[m2] = m2, h2
  nextNode[m2], prevNode[mn] = mn, m2
  if same(m, h) then unlink(h); unlink(m2) end
end

-- The ear test's index: a grid of square cells over the ring's box, each holding entries for the
-- nodes in it that may still block an ear (see keepListed). An ear's triangle is visited row of
-- cells by row, only the cells its span in that row touches: a long thin triangle (a spike of
-- a noisy outline) meets a few cells per row where its box would hold a large share of all
-- the nodes.
local CELL_LOAD = 2     -- nodes per cell on average, when the grid is built
local SHARED_RUN = 8    -- nodes of one cell compared pair by pair, at most (then all shared)
local FINE = 2 ^ -30    -- cells wider than this times the largest coordinate are visited by
                        -- the triangle's span (rounding stays far below a cell); narrower
                        -- ones, by its box (an outline tiny against its offset)
local SPAN_MARGIN = 2 ^ -10   -- a span's widening, in cells: with FINE, at least 2^-40 of the
                        -- largest coordinate, thousands of times its few ulps of rounding
local gridLeft, gridTop, gridScale, gridCols, gridRows, cellSize, gridFine
local spanMargin        -- twice SPAN_MARGIN cells (nearTriangle compares doubled widths), or
                        -- huge when the grid is not fine

-- The column or row of a coordinate: monotone in it (the scaling rounds monotonically), so a
-- box's corners bound the cells of every point inside it.
local function colOf(x)
  local col = floor((x - gridLeft) * gridScale)
  return col < gridCols and col or gridCols - 1
end
local function rowOf(y)
  local row = floor((y - gridTop) * gridScale)
  return row < gridRows and row or gridRows - 1
end

-- Files the nodes of the ring at s that may block an ear in their cells (the strictly convex
-- ones are left out from the start, see keepListed), and marks the nodes sharing a place. The
-- entries lie cell after cell, each with its node's place copied in, so the cells of a row's
-- span are one stretch of consecutive entries, read by one loop (see isEar); a node dropped
-- later keeps its entry, marked by x = huge, which no span holds.
local function buildGrid(s)
  local x0, y0, x1, y1, count = huge, huge, -huge, -huge, 0
  local k = s
  repeat
    x0, y0 = min(x0, nodeX[k]), min(y0, nodeY[k])
    x1, y1 = max(x1, nodeX[k]), max(y1, nodeY[k])
    count = count + 1
    k = nextNode[k]
  until k == s
  -- the ring has area, so its box has width and height
  cellSize = sqrt((x1 - x0) * (y1 - y0) * CELL_LOAD / count)
  gridLeft, gridTop, gridScale = x0, y0, 1 / cellSize
  gridCols = min(floor((x1 - x0) * gridScale) + 1, count)
  gridRows = min(floor((y1 - y0) * gridScale) + 1, count)
  gridFine = cellSize > FINE * max(abs(x0), abs(x1), abs(y0), abs(y1))
  spanMargin = gridFine and 2 * SPAN_MARGIN * cellSize or huge
  local cells = gridRows * gridCols
  local cellOf = newArray(capacity)
  cellStart = newArray(cells + 1)
  for c = 1, cells + 1 do cellStart[c] = 0 end
  k = s
  repeat
    local cell = rowOf(nodeY[k]) * gridCols + colOf(nodeX[k]) + 1
    cellOf[k], cellStart[cell] = cell, cellStart[cell] + 1
    k = nextNode[k]
  until k == s
  local at = 1   -- the counts become each cell's first entry, then (filling) its next one
  for c = 1, cells + 1 do cellStart[c], at = at, at + cellStart[c] end
  entryX, entryY, entryNode = newArray(count), newArray(count), newArray(count)
  entryOf = newArray(capacity)
  listed, shared, reflexSeen, listStale = newArray(capacity), newArray(capacity), newArray(capacity), false
  k = s
  repeat
    local cell = cellOf[k]
    entryNode[cellStart[cell]], cellStart[cell] = k, cellStart[cell] + 1
    k = nextNode[k]
  until k == s
  for c = cells, 1, -1 do cellStart[c + 1] = cellStart[c] end   -- back to first entries
  cellStart[1] = 1
  local kept = 0
  for c = 1, cells do
    local first, last = cellStart[c], cellStart[c + 1] - 1
    -- nodes at one place share a cell; a crowded cell is all marked shared
    for i = first, last do
      local j = entryNode[i]
      if last - first >= SHARED_RUN then shared[j] = true end
      for m = i + 1, last - first < SHARED_RUN and last or i do
        if same(j, entryNode[m]) then shared[j], shared[entryNode[m]] = true, true end
      end
    end
    -- keep the nodes not strictly convex and those sharing a place, packed cell after cell
    cellStart[c] = kept + 1
    for i = first, last do
      k = entryNode[i]
      local convex = not shared[k] and orient(prevNode[k], k, nextNode[k]) > 0
      if not convex then
        kept = kept + 1
        entryNode[kept], entryX[kept], entryY[kept], entryOf[k] = k, nodeX[k], nodeY[k], kept
        listed[k], reflexSeen[k] = true, not shared[k]
      end
    end
  end
  cellStart[cells + 1] = kept + 1
end

-- Whether node k may still block an ear: an ear's triangle that holds some node holds a node
-- not strictly convex (the highest point inside over the new edge c -> a turns away from the
-- inside, which sees past it), or one at a pinch point; a strictly convex node elsewhere is
-- left out of the grid, or dropped from it at its first test, as clipping never makes it reflex again (its
-- neighbours only move inwards) unless a spike collapses over it (then settle sets listStale
-- and the grid is built again).
local function keepListed(k)
  if reflexSeen[k] or shared[k] then return true end
  if orient(prevNode[k], k, nextNode[k]) > 0 then unlist(k); return false end
  reflexSeen[k] = true
  return true
end

-- Whether node k keeps the triangle (a, b, c) (turning the ring's way) from being an ear: it
-- lies strictly inside, or on the triangle's boundary with an edge going into it, or (while
-- `strict`) on the new edge c -> a, which would leave a vertex inside an edge and so a
-- triangle that cannot merge with its neighbours.
local strict = true
local function blocks(k, a, b, c)
  local s1 = orient(a, b, k)
  if s1 < 0 then return false end
  local s2 = orient(b, c, k)
  if s2 < 0 then return false end
  local s3 = orient(c, a, k)
  if s3 < 0 then return false end
  if s1 > 0 and s2 > 0 and s3 > 0 then return true end
  if strict and s3 == 0 and not same(k, a) and not same(k, c) then return true end
  for side = 1, 2 do
    local t = side == 1 and prevNode[k] or nextNode[k]
    if same(k, a) then
      if orient(a, b, t) > 0 and orient(c, a, t) > 0 then return true end
    elseif same(k, b) then
      if orient(a, b, t) > 0 and orient(b, c, t) > 0 then return true end
    elseif same(k, c) then
      if orient(b, c, t) > 0 and orient(c, a, t) > 0 then return true end
    elseif (s1 == 0 and orient(a, b, t) > 0) or (s2 == 0 and orient(b, c, t) > 0)
      or (s3 == 0 and orient(c, a, t) > 0) then
      return true
    end
  end
  return false
end

-- The triangle under test, for the helpers below (upvalues rather than arguments: loops with
-- many live values, or branches inside them, made LuaJIT 2.1 abort their side traces,
-- "register coalescing too complex", until it flushed all its traces). Corners a, b, c as the
-- ring runs; the box x0..x1, y0..y1; for the spans, the top corner t, the middle one m, and
-- the slopes dx/dy of the long side t -> bottom and of the short sides t -> m and m -> bottom.
local earA, earB, earC, boxX0, boxY0, boxX1, boxY1, boxCol0, boxCol1
local spanX0, spanX1    -- the triangle's widened span in x over the row being visited
local nearby = {}       -- on LuaJIT, the entries near the triangle, tested after the scan
local topX, topY, midX, midY, longSlope, upperSlope, lowerSlope

-- The columns of the cells the triangle may meet in a row: its span in x over the row's band
-- of y, band and span widened by SPAN_MARGIN cells against rounding (the last row's band runs
-- to the box's bottom: rowOf puts every node beyond the grid there). Each side is straight, so
-- its x over [lo, hi] is extreme at the ends; a short side's ends are clamped to its own rows
-- (m may come in when outside [lo, hi]: a wider span, never a narrower one). A cell's width
-- of widening on each side cost a thin spike's ear three cells a row instead of one or two.
local function rowSpan(row)
  if not gridFine then spanX0, spanX1 = boxX0, boxX1; return boxCol0, boxCol1 end
  local margin = SPAN_MARGIN * cellSize
  local lo = max(boxY0, gridTop + row * cellSize - margin)
  local hi = row < gridRows - 1 and min(boxY1, gridTop + (row + 1) * cellSize + margin) or boxY1
  local x1, x2 = topX + (lo - topY) * longSlope, topX + (hi - topY) * longSlope
  local x3, x4 = topX + (min(lo, midY) - topY) * upperSlope, topX + (min(hi, midY) - topY) * upperSlope
  local x5, x6 = midX + (max(lo, midY) - midY) * lowerSlope, midX + (max(hi, midY) - midY) * lowerSlope
  spanX0 = max(boxX0, min(x1, x2, x3, x4, x5, x6) - margin)
  spanX1 = min(boxX1, max(x1, x2, x3, x4, x5, x6) + margin)
  return colOf(spanX0), colOf(spanX1)
end

-- Whether (x, y), in the triangle's box, lies near the triangle: within its span in x at
-- height y, widened by spanMargin (as rowSpan, far beyond rounding). A long thin ear meets
-- about one candidate a row that only the exact test would turn down otherwise. The short
-- sides are both measured from m, each clamped to its own rows, so their sum is the short
-- side's x at y (a level side too) without a branch: branches here multiplied LuaJIT's side
-- traces until its machine-code area ran out.
local function nearTriangle(x, y)
  local xLong = topX + (y - topY) * longSlope
  local xShort = midX + (min(y, midY) - midY) * upperSlope + (max(y, midY) - midY) * lowerSlope
  return abs(x + x - xLong - xShort) <= abs(xLong - xShort) + spanMargin
end

-- Whether node b, strictly convex, is an ear: no listed node in the cells its triangle meets
-- blocks it.
local function isEar(b)
  local a, c = prevNode[b], nextNode[b]
  earA, earB, earC = a, b, c
  boxX0, boxY0 = min(nodeX[a], nodeX[b], nodeX[c]), min(nodeY[a], nodeY[b], nodeY[c])
  boxX1, boxY1 = max(nodeX[a], nodeX[b], nodeX[c]), max(nodeY[a], nodeY[b], nodeY[c])
  boxCol0, boxCol1 = colOf(boxX0), colOf(boxX1)
  local t, m, u = a, b, c
  if nodeY[m] < nodeY[t] then t, m = m, t end
  if nodeY[u] < nodeY[m] then m, u = u, m end
  if nodeY[m] < nodeY[t] then t, m = m, t end
  topX, topY, midX, midY = nodeX[t], nodeY[t], nodeX[m], nodeY[m]
  -- a level side has slope 0: its ends come in as the other sides' ends
  longSlope = (nodeX[u] - topX) / (nodeY[u] - topY)   -- not level: the triangle has area
  upperSlope = midY > topY and (midX - topX) / (midY - topY) or 0
  lowerSlope = nodeY[u] > midY and (nodeX[u] - midX) / (nodeY[u] - midY) or 0
  -- one loop over the entries of the rows' spans, one row after the other: a loop per row (a
  -- few entries) ran as a trace of its own, and every row left it for the interpreter
  local row, lastRow, j, last = rowOf(boxY0) - 1, rowOf(boxY1), 1, 0
  local found = 0
  while true do
    if j > last then   -- the next row's span
      row = row + 1
      if row > lastRow then break end
      local left, right = rowSpan(row)
      local base = row * gridCols + 1
      j, last = cellStart[base + left], cellStart[base + right + 1] - 1
    elseif JIT then
      -- the tests of the span, the box and nearTriangle as one number, <= 0 when all pass, and
      -- one branch, taken about once per ear: a branch per test went both ways, and every
      -- side trace taken went back to the loop's start (x clamped: dropped entries hold huge)
      local x, y = entryX[j], entryY[j]
      local xLong = topX + (y - topY) * longSlope
      local xShort = midX + (min(y, midY) - midY) * upperSlope + (max(y, midY) - midY) * lowerSlope
      local xNear = min(x, spanX1)
      -- an entry passing is only noted, and tested after the scan: tested here, the exact
      -- tests' side traces, started with the loop's many live values, aborted ("register
      -- coalescing too complex") thousands of times on outlines with holes
      if max(spanX0 - x, x - spanX1, boxY0 - y, y - boxY1,
          abs(xNear + xNear - xLong - xShort) - abs(xLong - xShort) - spanMargin) <= 0 then
        found = found + 1
        nearby[found] = j
      end
      j = j + 1
    else
      local x = entryX[j]
      if x >= spanX0 and x <= spanX1 then
        local y, k = entryY[j], entryNode[j]
        if y >= boxY0 and y <= boxY1 and k ~= earA and k ~= earC and nearTriangle(x, y)
          and keepListed(k) and blocks(k, earA, earB, earC) then
          return false
        end
      end
      j = j + 1
    end
  end
  for i = 1, found do
    local k = entryNode[nearby[i]]
    if k ~= earA and k ~= earC and keepListed(k) and blocks(k, earA, earB, earC) then
      return false
    end
  end
  return true
end

-- Clips ears from the ring at s until it is gone, appending each triangle's three nodes to
-- tris. No node in line with its neighbours is kept (a straight run, a repeated vertex, the tip
-- of a spike): each is dropped without a triangle, at the start and whenever a clip or a drop
-- brings one about, so the ring never holds a zero-width spike for an ear to reach across.
-- A lap that finds no ear is retried with strict off; returns false when that one finds none
-- either (the ring is not weakly simple).
local ringCount, pending, pendingTop   -- clipEars' state, for settle

-- Drops the pending nodes that lie in line with their neighbours, and those this brings in line.
local function settle()
  while pendingTop > 0 and ringCount > 2 do
    local j = pending[pendingTop]
    pending[pendingTop] = nil; pendingTop = pendingTop - 1
    if not gone[j] and orient(prevNode[j], j, nextNode[j]) == 0 then
      unlink(j); ringCount = ringCount - 1
      local p, q = prevNode[j], nextNode[j]
      pending[pendingTop + 1], pending[pendingTop + 2] = p, q
      pendingTop = pendingTop + 2
      if listed then
        reflexSeen[p], reflexSeen[q] = false, false
        -- a spike dropped may leave p or q facing back: reflex again, and maybe off the list
        if (not listed[p] and orient(prevNode[p], p, q) <= 0)
          or (not listed[q] and orient(p, q, nextNode[q]) <= 0) then
          listStale = true
        end
      end
    end
  end
  for j = pendingTop, 1, -1 do pending[j] = nil end
  pendingTop = 0
end

local function clipEars(s, tris)
  strict = true
  ringCount, pending = 0, {}
  local k = s
  repeat ringCount = ringCount + 1; pending[ringCount] = k; k = nextNode[k] until k == s
  pendingTop = ringCount
  settle()
  local ear = s
  while gone[ear] do ear = nextNode[ear] end
  local stop = ear
  while ringCount > 2 do
    local a, c = prevNode[ear], nextNode[ear]
    if listStale then buildGrid(ear) end
    if orient(a, ear, c) > 0 and isEar(ear) then
      local t = #tris
      tris[t + 1], tris[t + 2], tris[t + 3] = a, ear, c
      unlink(ear); ringCount = ringCount - 1
      reflexSeen[a], reflexSeen[c] = false, false
      pending[1], pending[2], pendingTop = a, c, 2
      settle()
      ear = c
      while gone[ear] do ear = nextNode[ear] end
      stop = ear
      strict = true
    else
      ear = c
      if ear == stop then
        if not strict then return false end
        strict = false
      end
    end
  end
  return true
end

-- Checks the arguments and triangulates: the triangles' nodes (a flat array, three per
-- triangle), or nil and a message. Leaves the node arrays set for the caller to read.
local function triangulate(fname, points, holes)
  local n = checkPoints(points, fname, "points", 4)
  if holes ~= nil and type(holes) ~= "table" then
    error(("%s: holes must be a table, got %s"):format(fname, type(holes)), 3)
  end
  local ok, message = validate(points)
  if not ok then
    if n < 6 then return nil, message end
    error(fname .. ": " .. message, 3)
  end
  for h = 1, holes and #holes or 0 do
    local hole = holes[h]
    ok, message = validate(hole)
    -- a hole of fewer than 3 points encloses nothing and is skipped (see below), but its
    -- coordinates must still be finite numbers
    if not ok and type(hole) == "table" and #hole % 2 == 0 and #hole < 6 then
      ok = true
      for i = 1, #hole do
        local v = hole[i]
        if type(v) ~= "number" or v ~= v or v == huge or v == -huge then
          ok, message = false, ("points[%d] must be a finite number, got %s"):format(i, tostring(v))
        end
      end
    end
    if not ok then error(("%s: holes[%d]: %s"):format(fname, h, message), 3) end
  end
  turn = areaSign(points, n)
  local flat = turn == 0   -- zero area: a bow-tie's halves cancel; say so when edges cross
  turn = turn < 0 and -1 or 1
  capacity = n / 2
  for h = 1, holes and #holes or 0 do capacity = capacity + #holes[h] / 2 + 2 end   -- 2: a bridge
  nodeX, nodeY, inX, inY = newArray(capacity), newArray(capacity), newArray(capacity), newArray(capacity)
  origin, nextNode = newArray(capacity), newArray(capacity)
  prevNode, gone = newArray(capacity), newArray(capacity)
  nodeCount = 0
  listed = nil
  nodeRing = newArray(capacity)
  local outer = linkRing(points, n, 1, false, 1)
  if flat then
    if anyCrossing({ outer }) then return nil, "edges cross" end
    return nil, "points have zero area"
  end
  local starts, firstId = { outer }, n / 2 + 1
  for h = 1, holes and #holes or 0 do
    local hole = holes[h]
    local m = #hole
    -- a hole enclosing nothing (fewer than 3 points, or zero area without crossing itself: a
    -- point, a segment, a sliver folded flat) takes nothing away and is skipped, as earcut's
    -- Steiner points and the slivers of map data come
    local s = m >= 6 and areaSign(hole, m) or 0
    if m >= 6 then
      -- a hole runs against the outer ring, so that the joined ring keeps the inside on one side
      local first = linkRing(hole, m, firstId, (s > 0) == (turn > 0), h + 1)
      if s ~= 0 then
        starts[#starts + 1] = first
      elseif anyCrossing({ first }) then
        return nil, ("holes[%d] crosses itself"):format(h)
      end
    end
    firstId = firstId + m / 2
  end
  local crossing = sweepCrossing(starts)
  local ordered = crossing ~= nil   -- the sweep's order held: ringStart is known
  if crossing == nil then crossing = anyCrossing(starts) end
  if crossing then return nil, crossingMessage() end
  for i = 2, #starts do
    local h = nodeRing[starts[i]]   -- hole h - 1
    local start = ordered and ringStart[h] or 0
    if start < 0 then
      local g = ringBelow[h] and nodeRing[ringBelow[h]] or 1
      if g == 1 then return nil, ("holes[%d] is outside the polygon"):format(h - 1) end
      return nil, ("holes[%d] is inside holes[%d]"):format(h - 1, g - 1)
    end
    if start == 0 then
      local misplaced = holeMisplaced(starts, i)
      if misplaced then return nil, misplaced end
    end
  end
  ringStart, ringBelow = nil, nil
  -- join the holes from left to right, each at its leftmost vertex (ties: the topmost)
  -- join the holes from left to right, each at its leftmost vertex (ties: the topmost)
  local lefts = {}
  for h = 2, #starts do
    local best, k = starts[h], starts[h]
    repeat
      if nodeX[k] < nodeX[best] or (nodeX[k] == nodeX[best] and nodeY[k] < nodeY[best]) then best = k end
      k = nextNode[k]
    until k == starts[h]
    lefts[#lefts + 1] = best
  end
  sort(lefts, leftmostFirst)
  for i = 1, #lefts do
    local m = bridgeTarget(outer, lefts[i])
    if not m then return nil, "a hole is outside the polygon" end
    bridge(m, lefts[i])
  end
  buildGrid(outer)
  local tris = newArray(3 * nodeCount)
  if not clipEars(outer, tris) then return nil, "edges overlap or cross" end
  return tris
end

-- Drops the node arrays of the last call.
local function releaseNodes()
  nodeX, nodeY, inX, inY, origin, nextNode, prevNode, gone = nil, nil, nil, nil, nil, nil, nil, nil
  sortKey, listed, shared, reflexSeen, nodeRing = nil, nil, nil, nil, nil
  ringStart, ringBelow = nil, nil
  cellStart, entryX, entryY, entryNode, entryOf = nil, nil, nil, nil, nil
end

-- polygonTriangulate, documented in polygon.lua: the triangles as new tables of the input's own
-- numbers, each wound like points.
function M.polygonTriangulate(points, holes)
  if type(points) == "table" and type(points[1]) ~= "number" then   -- a Polygon: its points
    points = shapeBehind(points, "polygonTriangulate", "points", 2) or points end      -- (point tables raise)
  local tris, message = triangulate("polygonTriangulate", points, holes)
  if not tris then releaseNodes(); return nil, message end
  local out = newArray(#tris / 3)
  for t = 1, #tris, 3 do
    local a, b, c = tris[t], tris[t + 1], tris[t + 2]
    out[#out + 1] = { inX[a], inY[a], inX[b], inY[b], inX[c], inY[c] }
  end
  releaseNodes()
  return out
end

-- The corners' edges that the triangulation holds both ways (u -> v in one triangle, v -> u in
-- the next), as pairs of corners in a flat array: the edges two parts may merge across. Edges
-- meet by the input vertices they join, so a bridge is an edge like any other: each corner's
-- edge u -> v waits in a list kept at the lower of u and v (a few corners) until the edge
-- v -> u comes; a later u -> v takes the place of one waiting. (A list at a vertex, not a hash
-- table keyed by the pair, which grew by rehashing.)
local function sharedEdges(tris, node, nextCorner, cornerCount)
  local joins = newArray(cornerCount)
  local idLimit = 0
  for k = 1, nodeCount do idLimit = max(idLimit, origin[k]) end
  idLimit = idLimit + 1
  local waitingAt, nextWaiting = newArray(idLimit), newArray(cornerCount)
  for c = 1, #tris do
    local u, v = origin[node[c]], origin[node[nextCorner[c]]]
    local low = min(u, v)
    local before, other = nil, waitingAt[low]
    while other and (origin[node[other]] ~= v or origin[node[nextCorner[other]]] ~= u) do
      before, other = other, nextWaiting[other]
    end
    if other then   -- v -> u was waiting: join, and take it off the list
      joins[#joins + 1] = other; joins[#joins + 1] = c
      if before then nextWaiting[before] = nextWaiting[other] else waitingAt[low] = nextWaiting[other] end
    else
      before, other = nil, waitingAt[low]
      while other and (origin[node[other]] ~= u or origin[node[nextCorner[other]]] ~= v) do
        before, other = other, nextWaiting[other]
      end
      if other then   -- u -> v already waiting: c waits in its place
        nextWaiting[c] = nextWaiting[other]
        if before then nextWaiting[before] = c else waitingAt[low] = c end
      else
        nextWaiting[c], waitingAt[low] = waitingAt[low], c
      end
    end
  end
  return joins
end

-- Merges the parts across each shared edge (joins, from sharedEdges) in turn, when the two
-- parts differ and both ends of the edge stay convex: the corners' rings are spliced, and the
-- part of one joined to the other's (union-find). Returns heir: a dropped corner's outgoing
-- edge now starts at heir[corner].
local function mergeParts(joins, node, nextCorner, prevCorner, part, cornerCount)
  local heir = newArray(cornerCount)
  for j = 1, #joins, 2 do
    local pu, qv = joins[j], joins[j + 1]
    while heir[pu] do pu = heir[pu] end
    while heir[qv] do qv = heir[qv] end
    local pv, qu = nextCorner[pu], nextCorner[qv]
    -- the parts' roots (union-find with path halving)
    local rp, rq = pu, qv
    while part[rp] ~= rp do part[rp] = part[part[rp]]; rp = part[rp] end
    while part[rq] ~= rq do part[rq] = part[part[rq]]; rq = part[rq] end
    if rp ~= rq and origin[node[pv]] == origin[node[qv]] and origin[node[qu]] == origin[node[pu]]
      and orient(node[prevCorner[pu]], node[pu], node[nextCorner[qu]]) >= 0
      and orient(node[prevCorner[qv]], node[pv], node[nextCorner[pv]]) >= 0 then
      local un, vp = nextCorner[qu], prevCorner[qv]
      nextCorner[pu], prevCorner[un] = un, pu
      prevCorner[pv], nextCorner[vp] = vp, pv
      heir[qu], heir[qv] = pu, pu
      part[rq] = rp
    end
  end
  return heir
end

-- The parts as flat arrays of input vertices: each ring of corners still alive (no heir), once.
local function partPolygons(tris, node, nextCorner, heir, cornerCount)
  local out, seen = {}, newArray(cornerCount)   -- seen: filled out of order, so made at size
  for c = 1, #tris do
    if not heir[c] and not seen[c] then
      local poly, k = {}, c
      repeat
        seen[k] = true
        poly[#poly + 1] = inX[node[k]]; poly[#poly + 1] = inY[node[k]]
        k = nextCorner[k]
      until k == c
      out[#out + 1] = poly
    end
  end
  return out
end

-- polygonConvexParts, documented in polygon.lua: the triangles merged greedily across their
-- shared edges while both ends stay convex (Hertel and Mehlhorn: at most four times the fewest
-- parts possible). Builds new tables.
function M.polygonConvexParts(points, holes)
  if type(points) == "table" and type(points[1]) ~= "number" then   -- a Polygon: its points
    points = shapeBehind(points, "polygonConvexParts", "points", 2) or points end      -- (point tables raise)
  local tris, message = triangulate("polygonConvexParts", points, holes)
  if not tris then releaseNodes(); return nil, message end
  -- corners: three per triangle, linked around their part; a part is the triangles joined so far
  local cornerCount = #tris
  local node, nextCorner = newArray(cornerCount), newArray(cornerCount)
  local prevCorner, part = newArray(cornerCount), newArray(cornerCount)
  for c = 1, #tris do
    local first = c - (c - 1) % 3
    node[c], part[c] = tris[c], first   -- part: a corner's union-find link, the first of a triangle
    nextCorner[c] = c % 3 == 0 and first or c + 1
    prevCorner[c] = c == first and first + 2 or c - 1
  end
  local joins = sharedEdges(tris, node, nextCorner, cornerCount)
  local heir = mergeParts(joins, node, nextCorner, prevCorner, part, cornerCount)
  local out = partPolygons(tris, node, nextCorner, heir, cornerCount)
  releaseNodes()
  return out
end

return M
