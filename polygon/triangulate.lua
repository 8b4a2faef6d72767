-- polygon/triangulate.lua: polygonTriangulate and polygonConvexParts: ear clipping with holes
-- bridged in (after polygon/sweep.lua's check of the rings), and the merge of triangles into
-- convex parts. Every decision is one of kernel's exact signs.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local check = require(_PACKAGE .. ".check")
local object = require(_PACKAGE .. ".object")
local nodes = require(_PACKAGE .. ".nodes")
local sweep = require(_PACKAGE .. ".sweep")
local order = require(_PACKAGE .. ".order")
local monotone = require(_PACKAGE .. ".monotone")
local places = require(_PACKAGE .. ".places")
local rects = require(_PACKAGE .. ".rects")

local abs, sqrt, huge, min, max = math.abs, math.sqrt, math.huge, math.min, math.max
local floor = math.floor
local JIT = kernel.JIT
local cross, areaSign = kernel.cross, kernel.areaSign
local checkPoints = check.checkPoints
local shapeBehind = check.shapeBehind
local validate = object.validate
local orient, same, newArray = nodes.orient, nodes.same, nodes.newArray
local scratch = nodes.scratch   -- arrays kept between calls (slots 1 to 10, 34 to 45, 50 to 57
                                -- and 71 are sweep.lua's and order.lua's; monotone.lua borrows
                                -- 11 to 22, 33 and 46 to 49 before the bridges and the ears)
local anyCrossing, ringsTrouble = sweep.anyCrossing, sweep.ringsTrouble
local furtherRight, spanInRow = nodes.furtherRight, nodes.spanInRow

local M = {}


-- Ear clipping over one ring of vertex nodes: holes are first joined to the outer ring by a
-- bridge to a vertex they see (Eberly's method), an ear is a strictly convex vertex whose
-- triangle no other vertex blocks, and the vertices that could block it are found in a grid of
-- cells, visited along the triangle row by row, holding only vertices that are not strictly
-- convex (or sit at a pinch point), so an ear test looks at the few vertices near its triangle,
-- not at all of them. Every decision is an exact sign (orient: cross's filter, then crossExact);
-- coordinates are only ever copied.
-- The nodes live in arrays indexed by node number, set up by one call and dropped at its end;
-- polygon/sweep.lua and polygon/nodes.lua read the same arrays (bound at the start of the call,
-- see sweep.bind).

local capacity          -- the number of nodes a call can make, at most: the arrays' size

local nodeX, nodeY      -- coordinates as doubles (+ 0.0), for the predicates
local inX, inY          -- the caller's values, copied into the output bit for bit
local origin            -- the input vertex a node stands for (a bridge copies two of them)
local nodeRing          -- the ring a node was made for: 1 the outline, h + 1 hole h
local nextNode, prevNode, nodeCount
local gone              -- gone[k]: node k has been unlinked
local twin              -- twin[k]: the next node at node k's place, in a circle (see sweep.lua)
local joined            -- joined[r]: ring r is part of the ring being clipped (1, the outline)
local cellStart         -- the ear test's grid (see buildGrid): where cell c's entries begin
local entryX, entryY, entryNode   -- its entries, cell by cell: a node's place and number
local entryOf           -- entryOf[k]: node k's entry
local entryRow          -- entryRow[e]: the row of entry e's cell
local gridStride        -- cells per row: the grid's columns and one empty cell closing the row
local rowDropped        -- rowDropped[r + 1]: entries of row r dropped since it was last packed
local dueRows, dueCount = {}, 0   -- rows with more entries dropped than kept, to pack
local listed            -- listed[k]: node k is still in the ear test's grid
local shared            -- shared[k]: another node lies at node k's place
local reflexSeen        -- reflexSeen[k]: node k was found not strictly convex and has kept
                        -- its neighbours since
local blocker           -- blocker[k]: the node found blocking node k's last ear test, or 0
local heldBy            -- heldBy[k]: a node strictly inside node k's triangle, found since k's
                        -- neighbours last changed, or 0: k is no ear while that node is linked
local insideFound       -- the node blocks last found strictly inside its triangle (see isEar)
local turn              -- the sign of the outer ring's area: > 0 clockwise on screen

local function newNode(x, y, id)
  nodeCount = nodeCount + 1
  local k = nodeCount
  inX[k], inY[k], nodeX[k], nodeY[k], origin[k], gone[k] = x, y, x + 0.0, y + 0.0, id, false
  return k
end

-- Drops node k from its cell of the ear test's grid. Its entry stays, marked by x = huge,
-- which no span holds, until its row is packed (see packRow): the clipping eats the ring's
-- nodes where it walks, so the entries there die first (eberly-6: 40,000 of the 74,000 entries
-- the ear tests read were dropped ones).
local function unlist(k)
  listed[k] = false
  local e = entryOf[k]
  entryX[e] = huge
  local r = entryRow[e]
  local dropped = rowDropped[r + 1] + 1
  rowDropped[r + 1] = dropped
  local first = r * gridStride + 1
  if dropped + dropped > cellStart[first + gridStride - 1] - cellStart[first] then
    dueCount = dueCount + 1
    dueRows[dueCount] = r
  end
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

-- Whether the direction from node k to node t points strictly into the interior at k.
local function sectorHolds(k, t)
  local a, c = prevNode[k], nextNode[k]
  local s1, s2 = orient(a, k, t), orient(k, c, t)
  if orient(a, k, c) > 0 then return s1 > 0 and s2 > 0 end
  return s1 > 0 or s2 > 0
end

-- Whether the direction from node k to node w lies strictly inside the wedge from the
-- direction k -> u to the direction k -> t, turning towards the interior side of k -> u.
local function wedgeHolds(k, u, t, w)
  if orient(k, u, t) > 0 then return orient(k, u, w) > 0 and orient(k, w, t) > 0 end
  return orient(k, u, w) > 0 or orient(k, w, t) > 0
end

-- Whether node t lies in line with nodes k and e, on e's side of k (neither at k's place).
local function along(k, e, t)
  if orient(k, e, t) ~= 0 or same(k, t) or same(k, e) then return false end
  local kx = nodeX[k]
  if nodeX[e] ~= kx then return (nodeX[e] > kx) == (nodeX[t] > kx) end
  return (nodeY[e] > nodeY[k]) == (nodeY[t] > nodeY[k])
end

-- Among the nodes of the joined ring at the place of node m, the one to bridge from towards
-- node t: its sector holds the direction, and where several do (a pinch point where joined
-- rings pass through one place, their sectors nested), the one whose outgoing edge comes last
-- before the direction, turning towards the inside: the bridge then goes into the gap between
-- that edge and the next ring's. The place's nodes come from the sweep (twin), those of holes
-- yet to join left out. The answer must not depend on which node of the place the search met
-- first (the cells' order decides that), so two kinds of node wait for the others:
-- - a spike, whose neighbours lie one way from it (a bridge's end at a place with other nodes):
--   its sector is all or nothing, and sectorHolds takes it for all; it is the answer only when
--   no other node's sector holds the direction (the tip of a slit, all of whose sector is
--   inside);
-- - where no sector holds the direction strictly, it runs along an edge from the place (a
--   hole's vertex inside the outline's edge, its ray along that edge): the node whose edge it
--   runs along holds it in its sector's closure, and the bridge goes there.
local function copyFacing(m, t)
  local k, found, spike = m, nil, nil
  repeat
    if not gone[k] and joined[nodeRing[k]] and sectorHolds(k, t) then
      if along(k, prevNode[k], nextNode[k]) then
        spike = spike or k
      elseif not found or wedgeHolds(k, nextNode[found], t, nextNode[k]) then
        found = k
      end
    end
    k = twin[k]
  until k == m
  if found then return found end
  repeat
    if not gone[k] and joined[nodeRing[k]] and not along(k, prevNode[k], nextNode[k])
      and (along(k, nextNode[k], t) or along(k, prevNode[k], t)) then
      return k
    end
    k = twin[k]
  until k == m
  return spike or m
end

-- Whether (x, y), in line with (hx, hy) and (bx, by) on the same side, lies strictly between.
local function between(hx, hy, x, y, bx, by)
  if x ~= bx then return (hx < x) == (x < bx) and x ~= hx end
  return (hy < y) == (y < by) and y ~= hy
end

-- The bridges' index: a grid of square cells over the rings' box, each listing the nodes whose
-- edge (k -> nextNode[k]) passes through it. A hole's ray walks its row of cells leftwards from
-- the hole and stops one column past the nearest hit found, and the triangle searched next
-- reads only the cells under its box: bands of whole rows made every ray read its band from end
-- to end, which on a long flat strip with a thousand holes, or water-huge3's 1,443, was most of
-- the call (bench/NOTES.md, session 22). A node is listed again when its edge changes (at a
-- bridge); an entry whose node is gone, not yet joined, or whose edge no longer passes the
-- cell, is passed over. A cell's entries are those the validity check filed there when it went
-- by its grid (sweep.edgeCells: the index takes that grid's cells, and building its own was a
-- tenth of a small tile map's call), then those listed here, singly linked from the cell's head.
local INDEX_LOAD = 2        -- nodes per cell, about, when the cells are made
local INDEX_ENTRIES = 4     -- entries per node at most; larger cells when the edges pass more
local INDEX_MARGIN = 0.25   -- cells: an edge's span in a row, widened against rounding
local INDEX_FINE = 2 ^ -30  -- cells narrower than this times the largest coordinate list edges
                            -- by their boxes, and rays walk their whole row (rounding could
                            -- pass a margin of a quarter cell)
local indexHead, indexNext, indexNode, indexEntries
local filedFirst, filedNode   -- the check's entries: cell c's at filedNode[filedFirst[c] ..
                              -- filedFirst[c + 1] - 1] (none when the index lists them all)
local indexLeft, indexTop, indexScale, indexSize, indexCols, indexRows, indexFine

-- The cell, from 0, of coordinate v along an axis of `count` cells from `from`, `scale` cells a
-- unit: monotone in v (the scaling rounds monotonically), so a box's corners bound the cells of
-- every point inside it. The last cell holds every place past it. (For this index and the ear
-- test's grid.)
local function cellAlong(v, from, scale, count)
  local c = floor((v - from) * scale)
  return c < count and c or count - 1
end

local function indexCol(x) return cellAlong(x, indexLeft, indexScale, indexCols) end
local function indexRow(y) return cellAlong(y, indexTop, indexScale, indexRows) end

-- The cells (numbers, from 1) edge k passes in row r, first and last: the columns of its span
-- in x over the row's band of y, band and span widened by INDEX_MARGIN cells (nodes.spanInRow);
-- the columns of its box when it lies in one row (oneRow), or when the cells are too fine for
-- the margin.
local function indexSpan(k, r, oneRow)
  local q = nextNode[k]
  local ax, ay, bx, by = nodeX[k], nodeY[k], nodeX[q], nodeY[q]
  local base = r * indexCols + 1
  if oneRow or not indexFine then return base + indexCol(min(ax, bx)), base + indexCol(max(ax, bx)) end
  local x0, x1 = spanInRow(ax, ay, bx, by, indexTop, indexSize, indexRows, r, INDEX_MARGIN * indexSize)
  return base + indexCol(x0), base + indexCol(x1)
end

-- Lists node k in the cells its edge passes through. One flat loop over the cells of all its
-- rows (nested loops here aborted LuaJIT's traces by the thousand: "register coalescing too
-- complex", as in polygon/sweep.lua's filing).
local function listEdge(k)
  local y0, y1 = nodeY[k], nodeY[nextNode[k]]
  local r, lastRow = indexRow(min(y0, y1)), indexRow(max(y0, y1))
  local c, last = indexSpan(k, r, r == lastRow)
  local n = indexEntries
  while true do
    if c > last then
      r = r + 1
      if r > lastRow then break end
      c, last = indexSpan(k, r, false)
    else
      n = n + 1
      indexNode[n], indexNext[n], indexHead[c] = k, indexHead[c], n
      c = c + 1
    end
  end
  indexEntries = n
end

-- Builds the index over the rings at starts: the check's cells when it went by its grid, with
-- nothing listed yet (the bridges list theirs); else cells of about INDEX_LOAD nodes, or larger
-- ones when the edges are long: an edge passes at most (|dx| + |dy|) / size + 2 cells in the
-- cells' own size, so with L the edges' sum of |dx| + |dy|, cells of at least L / (2 n) keep
-- the entries near INDEX_ENTRIES = 4 per node.
local function buildIndex(starts)
  local first, filed, left, top, scale, size, cols, rows = sweep.edgeCells()
  if first then
    filedFirst, filedNode = first, filed
    indexLeft, indexTop, indexScale, indexSize, indexCols, indexRows = left, top, scale, size, cols, rows
    indexFine = true   -- (the check gives its grid up when the cells are too fine)
    local cells = cols * rows
    indexHead, indexEntries = scratch(11, cells), 0
    indexNext, indexNode = scratch(12, 3 * #starts), scratch(13, 3 * #starts)
    for c = 1, cells do indexHead[c] = 0 end
    return
  end
  local x0, y0, x1, y1, n, length = huge, huge, -huge, -huge, 0, 0
  for _, s in ipairs(starts) do
    local k = s
    repeat
      local x, y, q = nodeX[k], nodeY[k], nextNode[k]
      x0, y0, x1, y1 = min(x0, x), min(y0, y), max(x1, x), max(y1, y)
      n, length, k = n + 1, length + abs(nodeX[q] - x) + abs(nodeY[q] - y), q
    until k == s
  end
  -- the outline has area, so the box has width and height
  indexLeft, indexTop = x0, y0
  indexSize = max(sqrt((x1 - x0) * (y1 - y0) * INDEX_LOAD / n), length / ((INDEX_ENTRIES - 2) * n))
  indexScale = 1 / indexSize
  indexCols = min(floor((x1 - x0) * indexScale) + 1, n)
  indexRows = min(floor((y1 - y0) * indexScale) + 1, n)
  indexFine = indexSize > INDEX_FINE * max(abs(x0), abs(x1), abs(y0), abs(y1))
  local cells = indexCols * indexRows
  indexHead, indexEntries = scratch(11, cells), 0
  indexNext, indexNode = scratch(12, INDEX_ENTRIES * capacity), scratch(13, INDEX_ENTRIES * capacity)
  filedFirst, filedNode = scratch(58, cells + 1), nil
  for c = 1, cells do indexHead[c], filedFirst[c] = 0, 1 end
  filedFirst[cells + 1] = 1
  for _, s in ipairs(starts) do
    local k = s
    repeat listEdge(k); k = nextNode[k] until k == s
  end
end

-- The node of the joined ring that the hole's leftmost node h joins: the nearest point hit by
-- the ray from h to the left is a vertex, or lies on an edge whose left end P is seen from h
-- unless another vertex in the triangle (h, hit, P) is: the one there at the least angle from
-- the ray (nearest on ties) is seen. nil when the ray hits nothing (the hole is outside). The
-- holes join from left to right, so no hole yet to join reaches left of h: the joined ring's
-- edges in h's row of cells are all the ray can meet. Where the hole meets an edge of the joined
-- ring at h alone (h inside it, h's neighbours on its inside), that edge's node and true: the
-- hole joins there (splitEdge); a bridge to P would run along the edge, over its other side.
local function meetsAlone(k, q, h)   -- h's neighbours on the inside of the edge k -> q
  return orient(k, q, nextNode[h]) > 0 and orient(k, q, prevNode[h]) > 0
end
local function bridgeTarget(h)
  local hx, hy = nodeX[h], nodeY[h]
  local vertex, lo, hi   -- the nearest hit so far: a vertex, or an edge lo -> hi (upwards in y)
  local through          -- an edge of the joined ring holding h's place inside
  local rowFirst = indexRow(hy) * indexCols + 1
  local cell, stop = rowFirst + indexCol(hx), rowFirst
  while cell >= stop do
    -- the cell's filed entries, then its listed ones
    local i, last, e = filedFirst[cell], filedFirst[cell + 1] - 1, indexHead[cell]
    while i <= last or e > 0 do
      local k
      if i <= last then k, i = filedNode[i], i + 1 else k, e = indexNode[e], indexNext[e] end
      if not gone[k] and joined[nodeRing[k]] then
        local q = nextNode[k]
        local x, y = nodeX[k], nodeY[k]
        if y == hy and x <= hx then
          if x == hx then return copyFacing(k, nextNode[h]) end   -- the hole touches the ring here
          if lo then
            if cross(nodeX[lo], nodeY[lo], nodeX[hi], nodeY[hi], nodeX[lo], nodeY[lo], x, y) <= 0 then
              vertex, lo, hi = k, nil, nil
            end
          elseif not vertex or x > nodeX[vertex] then
            vertex = k
          end
        end
        local qy = nodeY[q]
        if y == hy and qy == hy and min(x, nodeX[q]) < hx and hx < max(x, nodeX[q])
          and meetsAlone(k, q, h) then
          through = k   -- a level edge holding h inside, the hole meeting it there alone
        end
        if (y < hy and qy > hy) or (y > hy and qy < hy) then
          local a, b = k, q
          if y > qy then a, b = q, k end
          local ax, ay = nodeX[a], nodeY[a]
          local side = cross(ax, ay, nodeX[b], nodeY[b], ax, ay, hx, hy)
          if side == 0 and meetsAlone(k, q, h) then
            through = k   -- (of two edges along each other, the one facing the hole; a hole
                          -- running along the edge from h goes the ray's way)
          elseif side <= 0 then   -- meets the ray
            if vertex then
              if cross(ax, ay, nodeX[b], nodeY[b], ax, ay, nodeX[vertex], nodeY[vertex]) > 0 then
                vertex, lo, hi = nil, a, b
              end
            elseif not lo or furtherRight(a, b, lo, hi) > 0 then   -- (both cross y = hy)
              lo, hi = a, b
            end
          end
        end
      end
    end
    -- (h's own cell holds a vertex at h's place, if any: that one first, above)
    if through then return through, true end
    -- every hit not yet seen lies in a column left of those walked; one left of the nearest
    -- hit's (its place estimated when on an edge) holds none nearer
    if indexFine and (vertex or lo) then
      local x = vertex and nodeX[vertex]
        or nodeX[lo] + (hy - nodeY[lo]) * (nodeX[hi] - nodeX[lo]) / (nodeY[hi] - nodeY[lo])
      stop = max(stop, rowFirst + indexCol(x) - 1)
    end
    cell = cell - 1
  end
  if vertex then return copyFacing(vertex, h) end
  if not lo then return nil end
  -- the edge's left end: mirrored Eberly (the ray goes left), P.x <= hit.x < hx, so the
  -- triangle (h, hit, P) lies left of h and holds no part of the hole
  local p = nodeX[hi] < nodeX[lo] and hi or lo
  local side = nodeY[p] > hy and 1 or -1   -- the side of the ray the triangle lies on
  local lx, ly, ux, uy = nodeX[lo], nodeY[lo], nodeX[hi], nodeY[hi]
  local best = p
  -- the triangle's nodes lie in the cells of its box; each node is listed in its own cell
  local r0, r1 = indexRow(hy), indexRow(nodeY[p])
  if r0 > r1 then r0, r1 = r1, r0 end
  local c0, c1 = indexCol(nodeX[p]), indexCol(hx)
  for r = r0, r1 do
    for c = r * indexCols + c0 + 1, r * indexCols + c1 + 1 do
      local i, last, e = filedFirst[c], filedFirst[c + 1] - 1, indexHead[c]
      while i <= last or e > 0 do
        local k
        if i <= last then k, i = filedNode[i], i + 1 else k, e = indexNode[e], indexNext[e] end
        local x, y = nodeX[k], nodeY[k]
        if not gone[k] and joined[nodeRing[k]] and (y - hy) * side > 0
          and cross(lx, ly, ux, uy, lx, ly, x, y) <= 0 then
          local s = cross(hx, hy, nodeX[p], nodeY[p], hx, hy, x, y) * side
          if s >= 0 then   -- inside the triangle (h, hit, P) or on its sides
            local t = cross(hx, hy, x, y, hx, hy, nodeX[best], nodeY[best]) * side
            if t < 0 or (t == 0 and between(hx, hy, x, y, nodeX[best], nodeY[best])) then best = k end
          end
        end
      end
    end
  end
  return copyFacing(best, h)
end

-- A new node at hole node h's place in the edge k -> nextNode[k] of the joined ring, which holds
-- that place inside, for the hole to join (see bridgeTarget); bridge lists its edges.
local function splitEdge(k, h)
  local w, q = newNode(inX[h], inY[h], origin[h]), nextNode[k]
  nodeRing[w] = nodeRing[k]
  twin[w], twin[h] = twin[h], w
  nextNode[k], prevNode[w], nextNode[w], prevNode[q] = w, k, q, w
  return w
end

-- Joins the hole ring at node h to the ring at node m: m -> h ... around the hole ... h' -> m'
-- with h' and m' new nodes at the places of h and m. A hole touching the ring (m at h) makes
-- repeated vertices, removed at once.
local function bridge(m, h)
  local m2, h2 = newNode(inX[m], inY[m], origin[m]), newNode(inX[h], inY[h], origin[h])
  nodeRing[m2], nodeRing[h2] = nodeRing[m], nodeRing[h]
  twin[m2], twin[m] = twin[m], m2   -- the copies join their places' circles
  twin[h2], twin[h] = twin[h], h2
  joined[nodeRing[h]] = true
  local mn, hp = nextNode[m], prevNode[h]
  nextNode[m], prevNode[h] = h, m
  nextNode[hp], prevNode[h2] = h2, hp
  nextNode[h2], prevNode[m2] = m2, h2
  nextNode[m2], prevNode[mn] = mn, m2
  if same(m, h) then unlink(h); unlink(m2) end
  -- the edges that changed: m -> h, h' -> m' and m' -> (m's old successor), as they are now
  if not gone[m] then listEdge(m) end
  if not gone[m2] then listEdge(m2) end
  if not gone[h2] then listEdge(h2) end
end

-- The ear test's index: a grid of square cells over the ring's box, each holding entries for the
-- nodes in it that may still block an ear (see keepListed). An ear's triangle is visited row of
-- cells by row, only the cells its span in that row touches: a long thin triangle (a spike of
-- a noisy outline) meets a few cells per row where its box would hold a large share of all
-- the nodes.
local CELL_LOAD = 2     -- nodes per cell on average, when the grid is built
local ONE_CELL = 40     -- a ring of at most this many nodes gets one cell: each ear test reads
                        -- every entry in one loop, with no rows or spans to compute (small
                        -- outlines taken in turn ran 5 to 15 % faster on LuaJIT, 4 to 5 % on
                        -- Lua 5.4; past 40 nodes slower: bench/NOTES.md, session 28)
local SHARED_RUN = 8    -- nodes of one cell compared pair by pair, at most (then all shared)
local FINE = 2 ^ -30    -- cells wider than this times the largest coordinate are visited by
                        -- the triangle's span (rounding stays far below a cell); narrower
                        -- ones, by its box (an outline tiny against its offset)
local SPAN_MARGIN = 2 ^ -10   -- a span's widening, in cells: with FINE, at least 2^-40 of the
                        -- largest coordinate, thousands of times its few ulps of rounding
local gridLeft, gridTop, gridScale, gridCols, gridRows, cellSize, gridFine
local listStale         -- a node dropped from the grid may have turned reflex
local spanMargin        -- twice SPAN_MARGIN cells (nearTriangle compares doubled widths), or
                        -- huge when the grid is not fine

-- The column or row of a coordinate (see cellAlong).
local function colOf(x) return cellAlong(x, gridLeft, gridScale, gridCols) end
local function rowOf(y) return cellAlong(y, gridTop, gridScale, gridRows) end

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
  if count <= ONE_CELL then cellSize = 2 * max(x1 - x0, y1 - y0) end   -- one column, one row
  gridLeft, gridTop, gridScale = x0, y0, 1 / cellSize
  gridCols = min(floor((x1 - x0) * gridScale) + 1, count)
  gridRows = min(floor((y1 - y0) * gridScale) + 1, count)
  gridFine = cellSize > FINE * max(abs(x0), abs(x1), abs(y0), abs(y1))
  spanMargin = gridFine and 2 * SPAN_MARGIN * cellSize or huge
  gridStride = gridCols + 1
  local cells = gridRows * gridStride
  local cellOf = scratch(14, capacity)
  cellStart = scratch(15, cells + 1)
  for c = 1, cells + 1 do cellStart[c] = 0 end
  k = s
  repeat
    local cell = rowOf(nodeY[k]) * gridStride + colOf(nodeX[k]) + 1
    cellOf[k], cellStart[cell] = cell, cellStart[cell] + 1
    k = nextNode[k]
  until k == s
  local at = 1   -- the counts become each cell's first entry, then (filling) its next one
  for c = 1, cells + 1 do cellStart[c], at = at, at + cellStart[c] end
  entryX, entryY, entryNode = scratch(16, count), scratch(17, count), scratch(18, count)
  entryOf, entryRow, rowDropped = scratch(19, capacity), scratch(47, count), scratch(48, gridRows)
  for r = 1, gridRows do rowDropped[r] = 0 end
  dueCount = 0
  listed, shared, reflexSeen = scratch(20, capacity), scratch(21, capacity), scratch(22, capacity)
  listStale = false
  blocker, heldBy = scratch(33, capacity), scratch(46, capacity)
  k = s
  repeat
    listed[k], shared[k], reflexSeen[k], blocker[k], heldBy[k] = false, false, false, 0, 0
    k = nextNode[k]
  until k == s
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
    if count <= ONE_CELL then
      -- the one cell of a small ring: the nodes at another's place, from the check's circles
      -- of twins (all of them would be marked below, and listed at every ear test)
      for i = first, last do
        local j = entryNode[i]
        local t = twin[j]
        while t ~= j and gone[t] do t = twin[t] end
        shared[j] = t ~= j
      end
    else
      -- nodes at one place share a cell; a crowded cell is all marked shared, its nodes listed
      -- for good (marked only at their places, the nodes a drop leaves reflex and unlisted
      -- make settle rebuild the grid: water2's five times rather than three, 14 % slower)
      for i = first, last do
        local j = entryNode[i]
        if last - first >= SHARED_RUN then shared[j] = true end
        for m = i + 1, last - first < SHARED_RUN and last or i do
          if same(j, entryNode[m]) then shared[j], shared[entryNode[m]] = true, true end
        end
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
        entryRow[kept] = (c - 1 - (c - 1) % gridStride) / gridStride
        listed[k], reflexSeen[k] = true, not shared[k]
      end
    end
  end
  cellStart[cells + 1] = kept + 1
end

-- Packs the entries of row r that are still listed to the row's start, cell after cell; the
-- row's closing cell takes the room freed. Run between ear tests (the scans keep entry
-- numbers), when more of the row's entries are dropped than kept: each entry is moved at most
-- as often as entries are dropped.
local function packRow(r)
  local first = r * gridStride + 1
  local last = first + gridCols   -- the closing cell
  local at = cellStart[first]
  if rowDropped[r + 1] + rowDropped[r + 1] <= cellStart[last] - at then return end   -- done
  for c = first, last - 1 do
    local from, to = cellStart[c], cellStart[c + 1] - 1
    cellStart[c] = at
    for e = from, to do
      local x = entryX[e]
      if x ~= huge then
        local k = entryNode[e]
        entryX[at], entryY[at], entryNode[at], entryRow[at], entryOf[k] = x, entryY[e], k, r, at
        at = at + 1
      end
    end
  end
  cellStart[last] = at
  rowDropped[r + 1] = 0
end

local function packRows()
  for i = 1, dueCount do packRow(dueRows[i]) end
  dueCount = 0
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
  if s1 > 0 and s2 > 0 and s3 > 0 then insideFound = k; return true end
  local atA, atB, atC = same(k, a), same(k, b), same(k, c)   -- each asked once (pinch points)
  if strict and s3 == 0 and not atA and not atC then return true end
  -- an edge of another node along a side the same way, from its first corner or to its last
  -- (any length: a vertex inside an edge makes shorter sides): the side's far side is outside
  -- there, which cutting the ear off would leave inside the ring (two cuts meeting along one
  -- diagonal both ways, at pinch points, leave such an edge)
  local q, p = nextNode[k], prevNode[k]
  if (atC and (along(c, a, q) or along(c, b, p)))
    or (atA and (along(a, b, q) or (p ~= c and along(a, c, p))))
    or (atB and k ~= b and (along(b, c, q) or along(b, a, p))) then
    return true
  end
  for side = 1, 2 do
    local t = side == 1 and prevNode[k] or nextNode[k]
    if atA then
      if orient(a, b, t) > 0 and orient(c, a, t) > 0 then return true end
    elseif atB then
      if orient(a, b, t) > 0 and orient(b, c, t) > 0 then return true end
    elseif atC then
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
local earWide, earMargin   -- the box stands for the spans (see isEar); spanMargin, or huge

-- The columns of the cells the triangle may meet in a row: its span in x over the row's band
-- of y, band and span widened by SPAN_MARGIN cells against rounding (the last row's band runs
-- to the box's bottom: rowOf puts every node beyond the grid there). Each side is straight, so
-- its x over [lo, hi] is extreme at the ends; a short side's ends are clamped to its own rows
-- (m may come in when outside [lo, hi]: a wider span, never a narrower one). A cell's width
-- of widening on each side cost a thin spike's ear three cells a row instead of one or two.
local function rowSpan(row)
  if earWide then spanX0, spanX1 = boxX0, boxX1; return boxCol0, boxCol1 end
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
-- height y, widened by earMargin (as rowSpan, far beyond rounding). A long thin ear meets
-- about one candidate a row that only the exact test would turn down otherwise. The short
-- sides are both measured from m, each clamped to its own rows, so their sum is the short
-- side's x at y (a level side too) without a branch: branches here multiplied LuaJIT's side
-- traces until its machine-code area ran out.
local function nearTriangle(x, y)
  local xLong = topX + (y - topY) * longSlope
  local xShort = midX + (min(y, midY) - midY) * upperSlope + (max(y, midY) - midY) * lowerSlope
  return abs(x + x - xLong - xShort) <= abs(xLong - xShort) + earMargin
end

-- Whether node b, strictly convex, is an ear: no listed node in the cells its triangle meets
-- blocks it. When one blocks from strictly inside, heldBy[b] keeps it (see clipEars).
local function isEar(b)
  local a, c = prevNode[b], nextNode[b]
  insideFound = 0
  -- the node that blocked b's last test, first: most tests that fail repeat one that failed
  -- before, as the clipping laps the ring (water2: 2,650 of 2,710), and one exact test spares
  -- the scan. A listed node that blocks is one the scan finds, so the answer is the scan's.
  local k = blocker[b]
  if k > 0 and not gone[k] and listed[k] and k ~= a and k ~= c and keepListed(k) and blocks(k, a, b, c) then
    heldBy[b] = insideFound
    return false
  end
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
  -- cells too fine for the margin, or a slope past the doubles (outside the exact range): the
  -- box stands for the spans, and every entry in it goes to the exact test
  local steep = abs(longSlope) + abs(upperSlope) + abs(lowerSlope)
  earWide = not gridFine or not (steep < huge)   -- luacheck: ignore 581 (NaN too)
  if earWide then longSlope, upperSlope, lowerSlope = 0, 0, 0 end
  earMargin = earWide and huge or spanMargin
  -- one loop over the entries of the rows' spans, one row after the other: a loop per row (a
  -- few entries) ran as a trace of its own, and every row left it for the interpreter
  local row, lastRow, j, last = rowOf(boxY0) - 1, rowOf(boxY1), 1, 0
  local found = 0
  -- the corners, when listed, are hidden from the scan (their entries' x set to huge, as a
  -- dropped one's): they lie on the triangle, so every scan found them, and the loop over what
  -- it found ran for them alone on most ears
  local listedA, listedB, listedC = listed[a], listed[b], listed[c]
  if listedA then entryX[entryOf[a]] = huge end
  if listedB then entryX[entryOf[b]] = huge end
  if listedC then entryX[entryOf[c]] = huge end
  while true do
    if j > last then   -- the next row's span
      row = row + 1
      if row > lastRow then break end
      local left, right = rowSpan(row)
      local base = row * gridStride + 1
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
          abs(xNear + xNear - xLong - xShort) - abs(xLong - xShort) - earMargin) <= 0 then
        found = found + 1
        nearby[found] = j
      end
      j = j + 1
    else
      local x = entryX[j]
      if x >= spanX0 and x <= spanX1 then
        local y = entryY[j]
        k = entryNode[j]
        if y >= boxY0 and y <= boxY1 and nearTriangle(x, y) and keepListed(k)
          and blocks(k, earA, earB, earC) then
          found = -1
          break
        end
      end
      j = j + 1
    end
  end
  if listedA then entryX[entryOf[a]] = nodeX[a] end
  if listedB then entryX[entryOf[b]] = nodeX[b] end
  if listedC then entryX[entryOf[c]] = nodeX[c] end
  if found < 0 then   -- PUC Lua's scan found k blocking
    blocker[b], heldBy[b] = k, insideFound
    return false
  end
  for i = 1, found do
    k = entryNode[nearby[i]]
    if keepListed(k) and blocks(k, earA, earB, earC) then
      blocker[b], heldBy[b] = k, insideFound
      return false
    end
  end
  return true
end

-- Clips ears from the ring at s until it is gone, appending each triangle's three nodes to
-- tris. No node in line with its neighbours is kept (a straight run, a repeated vertex, the tip
-- of a spike): each is dropped without a triangle, at the start (dropInLine) and whenever a clip
-- or a drop brings one about, so the ring never holds a zero-width spike for an ear to reach
-- across.
-- A lap that finds no ear is retried with strict off; returns false when that one finds none
-- either (the ring is not weakly simple).
local ringCount, pending, pendingTop   -- clipEars' state, for settle
local triCount          -- the entries clipEars has written to its tris (# searched for the
                        -- end of the array made at its full size, at every ear)

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
        reflexSeen[p], reflexSeen[q], heldBy[p], heldBy[q] = false, false, 0, 0
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

-- Drops the nodes of the ring at s that lie in line with their neighbours, before the grid is
-- built (a tile map's outline has a third of its nodes along straight runs, which the grid
-- would list only for settle to drop them again), and returns a node left.
local function dropInLine(s)
  ringCount, pending = 0, scratch(49, capacity + capacity)   -- settle may push two a drop
  local k = s
  repeat ringCount = ringCount + 1; pending[ringCount] = k; k = nextNode[k] until k == s
  pendingTop = ringCount
  settle()
  while gone[s] do s = nextNode[s] end
  return s
end

local function clipEars(s, tris)
  strict = true
  local ear = s
  local stop = ear
  while ringCount > 2 do
    local a, c = prevNode[ear], nextNode[ear]
    if listStale then buildGrid(ear) elseif dueCount > 0 then packRows() end
    -- passed over without a test: a node known not strictly convex (reflexSeen: most nodes a
    -- lap passes over), or one whose triangle holds a linked node strictly inside (heldBy: the
    -- same neighbours, the same places, so the test would fail again; water2: 2,500 of 3,900
    -- tests, each repeating the last one as the walk lapped the bridged ring)
    local held = heldBy[ear]
    local known = reflexSeen[ear] or (held > 0 and not gone[held])
    local turning = not known and orient(a, ear, c) > 0
    if turning and isEar(ear) then
      local t = triCount
      tris[t + 1], tris[t + 2], tris[t + 3] = a, ear, c
      triCount = t + 3
      unlink(ear); ringCount = ringCount - 1
      reflexSeen[a], reflexSeen[c], heldBy[a], heldBy[c] = false, false, 0, 0
      -- most clips leave a and c turning: tested here, settle's loop (a trace of its own on
      -- LuaJIT, entered and left at every ear) runs only when one lies in line
      if ringCount <= 2 or orient(prevNode[a], a, c) == 0 or orient(a, c, nextNode[c]) == 0 then
        pending[1], pending[2], pendingTop = a, c, 2
        settle()
      end
      ear = c
      while gone[ear] do ear = nextNode[ear] end
      stop = ear
      strict = true
    else
      if not known and not turning then reflexSeen[ear] = true end
      ear = c
      if ear == stop then
        if not strict then return false end
        strict = false
      end
    end
  end
  return true
end

-- LuaJIT: compiled only once it pays. Compiling the ear clipping and the sweep costs some 10 to
-- 200 ms of traces (they compile to 700 to 1,500 of them), several times what the interpreter
-- takes for one triangulation of a few thousand vertices (rain: 28 ms interpreted, 115 ms on a
-- first compiled call, 3 ms once compiled), and a level loads its outlines once. So the
-- functions of this file, sweep.lua and nodes.lua start interpreted (jit.off), and are compiled
-- (jit.on) once the triangulations have spent INTERPRETED_BUDGET seconds of CPU time in the
-- interpreter: the ski-rental rule, never more than about twice the better of the two choices
-- made in hindsight.
-- The room for compiled code is raised at the first triangulation: on outlines with a thousand
-- holes the traces need 1.2 MB, past LuaJIT 2.1's defaults (1,000 traces, 512 KB), and a full
-- area makes LuaJIT throw away every trace, the game's too, and compile again, each call: 5 to
-- 40 times slower (see bench/NOTES.md). Raised to 6,000 and 8 MB, which LuaJIT fills only as it
-- needs; a game that wants other limits sets them with jit.opt.start after its first
-- triangulation (at the first, so that the game knows when: not at the switch, which comes
-- whenever the budget runs out).
local INTERPRETED_BUDGET = 0.05
local compiled = not JIT
local interpreted = 0
local clock = os.clock
local jit = JIT and rawget(_G, "jit")
local chunk = JIT and debug.getinfo(1, "f").func
if JIT then
  jit.off(chunk, true)
  jit.off(sweep.chunk, true)
  jit.off(nodes.chunk, true)
  jit.off(order.chunk, true)
  jit.off(monotone.chunk, true)
  jit.off(places.chunk, true)
end

local roomMade = not JIT
local function makeRoom()
  roomMade = true
  if jit.opt and jit.opt.start then pcall(jit.opt.start, "maxtrace=8000", "maxmcode=16384") end
end

-- Charges the interpreter's time since t0 and compiles once the budget is spent.
local function charge(t0)
  interpreted = interpreted + (clock() - t0)
  if interpreted < INTERPRETED_BUDGET then return end
  compiled = true
  jit.on(chunk, true)
  jit.on(sweep.chunk, true)
  jit.on(nodes.chunk, true)
  jit.on(order.chunk, true)
  jit.on(monotone.chunk, true)
  jit.on(places.chunk, true)
end

local build

-- Checks the arguments and triangulates: the triangles' nodes (a flat array, three per
-- triangle), or nil and a message. Leaves the node arrays set for the caller to read.
local function triangulate(fname, points, holes, checkOnly)
  if not roomMade then makeRoom() end
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
  if compiled then return build(points, n, holes, checkOnly) end
  local t0 = clock()
  local tris, why = build(points, n, holes, checkOnly)
  charge(t0)
  return tris, why
end

-- Whether the ring at node `first`, a hole of zero area, crosses itself: where two edges cross,
-- or where its vertices meet or one lies inside an edge and the ring passes through in a crossing
-- order (a figure eight whose loops are wound against each other and cancel, slits from one
-- point visited out of their turn around it), as the check tests an outline. A ring along one
-- vertical line (no width for the check's sort) cannot; nor can any ring along one line, which
-- the check passes (a sliver folded flat).
local function flatHoleCrosses(first)
  if anyCrossing({ first }) then return true end
  local x0, x1, k = huge, -huge, first
  repeat
    x0, x1 = min(x0, nodeX[k]), max(x1, nodeX[k])
    k = nextNode[k]
  until k == first
  return x1 > x0 and ringsTrouble({ first }) ~= nil
end

-- triangulate's work, on arguments it has checked.
function build(points, n, holes, checkOnly)
  turn = areaSign(points, n)
  local flat = turn == 0   -- zero area: a bow-tie's halves cancel; say so when edges cross
  turn = turn < 0 and -1 or 1
  capacity = n / 2
  -- 3: a bridge's two, and one where the hole touches an edge (splitEdge)
  for h = 1, holes and #holes or 0 do capacity = capacity + #holes[h] / 2 + 3 end
  nodes.usePool(capacity)
  nodeX, nodeY = scratch(23, capacity), scratch(24, capacity)
  inX, inY = scratch(25, capacity), scratch(26, capacity)
  origin, nextNode = scratch(27, capacity), scratch(28, capacity)
  prevNode, gone = scratch(29, capacity), scratch(30, capacity)
  nodeCount = 0
  listed = nil
  nodeRing, twin, joined = scratch(31, capacity), scratch(32, capacity), { true }
  sweep.bind(nodeX, nodeY, nextNode, prevNode, nodeRing, capacity, turn, twin)
  monotone.bind(nodeX, nodeY, nextNode, prevNode, turn, capacity)
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
      elseif flatHoleCrosses(first) then
        return nil, ("holes[%d] crosses itself"):format(h)
      end
    end
    firstId = firstId + m / 2
  end
  local trouble = ringsTrouble(starts)
  if trouble then return nil, trouble end
  -- (where the check left a place untested, the ear clipping decides, as it does for
  -- polygonTriangulate: polygonConvexParts' rectangles then come back only when the triangles
  -- would)
  if checkOnly and not places.undecided() then return true end
  -- an outline alone that the sweep found plain: by monotone pieces (see polygon/monotone.lua)
  local placeOrder, placeCount, placeRank, below = sweep.plainSweep()
  if placeOrder and #starts == 1 then
    local tris = newArray(3 * nodeCount)
    local written = monotone.triangulate(tris, placeOrder, placeCount, placeRank, below)
    if written then triCount = written; return tris end
  end
  -- join the holes from left to right, each at its leftmost vertex (ties: the topmost)
  local lefts, leftCount = sweep.holeLefts()
  if leftCount > 0 then buildIndex(starts) end
  for i = 1, leftCount do
    local m, inside = bridgeTarget(lefts[i])
    if not m then return nil, "a hole is outside the polygon" end
    if inside then m = splitEdge(m, lefts[i]) end
    bridge(m, lefts[i])
  end
  local first = dropInLine(outer)
  if ringCount > 2 then buildGrid(first) end   -- (a ring with area keeps three nodes at least)
  local tris = newArray(3 * nodeCount)
  triCount = 0
  if not clipEars(first, tris) then return nil, "edges overlap or cross" end
  return tris
end

-- Drops the node arrays of the last call.
local function releaseNodes()
  nodeX, nodeY, inX, inY, origin, nextNode, prevNode, gone = nil, nil, nil, nil, nil, nil, nil, nil
  listed, shared, reflexSeen, nodeRing, blocker, heldBy = nil, nil, nil, nil, nil, nil
  twin, joined, indexHead, indexNext, indexNode = nil, nil, nil, nil, nil
  filedFirst, filedNode = nil, nil
  sweep.bind(nil, nil, nil, nil, nil, nil, nil, nil)
  monotone.bind(nil, nil, nil, nil, nil, nil)
  cellStart, entryX, entryY, entryNode, entryOf = nil, nil, nil, nil, nil
  entryRow, rowDropped, pending = nil, nil, nil
end

-- polygonTriangulate, documented in polygon.lua: the triangles as new tables of the input's own
-- numbers, each wound like points.
function M.polygonTriangulate(points, holes)
  if type(points) == "table" and type(points[1]) ~= "number" then   -- a Polygon: its points
    points = shapeBehind(points, "polygonTriangulate", "points", 2) or points end      -- (point tables raise)
  local tris, message = triangulate("polygonTriangulate", points, holes)
  if not tris then releaseNodes(); return nil, message end
  local count, m = triCount, 0
  local out = newArray(count / 3)
  for t = 1, count, 3 do
    local a, b, c = tris[t], tris[t + 1], tris[t + 2]
    m = m + 1
    out[m] = { inX[a], inY[a], inX[b], inY[b], inX[c], inY[c] }
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
local function sharedEdges(node, nextCorner, cornerCount)
  local joins = newArray(cornerCount)
  local idLimit = 0
  for k = 1, nodeCount do idLimit = max(idLimit, origin[k]) end
  idLimit = idLimit + 1
  local waitingAt, nextWaiting = newArray(idLimit), newArray(cornerCount)
  for c = 1, cornerCount do
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
local function partPolygons(node, nextCorner, heir, cornerCount)
  local out, seen = {}, newArray(cornerCount)   -- seen: filled out of order, so made at size
  for c = 1, cornerCount do
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
  if type(points) == "table" and rects.alongAxes(points, holes) then
    -- every edge along an axis (checked on the raw arrays: a bad one fails the check below):
    -- rectangles, once the rings pass the triangulator's check
    local ok, message = triangulate("polygonConvexParts", points, holes, true)
    releaseNodes()
    if not ok then return nil, message end
    local kept = {}   -- the holes that enclose something (the others are skipped, as there)
    for h = 1, holes and #holes or 0 do
      if #holes[h] >= 6 and areaSign(holes[h], #holes[h]) ~= 0 then kept[#kept + 1] = holes[h] end
    end
    return rects.rectangles(points, kept, areaSign(points, #points) > 0)
  end
  local tris, message = triangulate("polygonConvexParts", points, holes)
  if not tris then releaseNodes(); return nil, message end
  -- corners: three per triangle, linked around their part; a part is the triangles joined so far
  local cornerCount = triCount
  local node, nextCorner = newArray(cornerCount), newArray(cornerCount)
  local prevCorner, part = newArray(cornerCount), newArray(cornerCount)
  for c = 1, cornerCount do
    local first = c - (c - 1) % 3
    node[c], part[c] = tris[c], first   -- part: a corner's union-find link, the first of a triangle
    nextCorner[c] = c % 3 == 0 and first or c + 1
    prevCorner[c] = c == first and first + 2 or c - 1
  end
  local joins = sharedEdges(node, nextCorner, cornerCount)
  local heir = mergeParts(joins, node, nextCorner, prevCorner, part, cornerCount)
  local out = partPolygons(node, nextCorner, heir, cornerCount)
  releaseNodes()
  return out
end

return M
