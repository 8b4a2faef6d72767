-- polygon/order.lua: the order of polygon/sweep.lua's sweep, the edges its vertical line meets
-- from bottom to top, kept in blocks of at most BLOCK entries, each edge linked to its neighbours.
-- A vertical line meets a share of a spiky outline's edges, not a few: some 200 of a noisy
-- circle of 10,000 vertices, where one sorted array moved half the order for every edge coming
-- in or leaving (quadratic: 2 million moves a call there). In blocks an edge moves the entries of
-- its own block only, and the search halves over the blocks, then in one.
--
-- Every block but a lone one holds at least BLOCK / 4 entries, so the blocks take at most four
-- entries' room an edge in the order. blockList[1 .. blockCount] lists the blocks bottom to top
-- and listedAt[b] is block b's index there; block b's entries lie in status, bottom to top,
-- between two false entries (see base). slot[k] is edge k's place in status, kept as the
-- entries move; upEdge and downEdge link each edge to its neighbours, so that the sweep reads
-- them without asking which block they lie in.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local nodes = require(_PACKAGE .. ".nodes")

local scratch = nodes.scratch

local M = {}
-- This file's main chunk: triangulate.lua turns LuaJIT's compiler off and on for every function
-- in it (see there).
M.chunk = debug.getinfo(1, "f").func

local BLOCK = 32          -- entries a block holds at most (even)
local STRIDE = BLOCK + 2  -- a block's room: its entries between two false entries, so that the
                          -- place above or below is one read away inside a block
local status, slot        -- the entries; each edge's place
local upEdge, downEdge    -- each edge's neighbours in the order (false at the ends), for the sweep
local fill, blockList, listedAt, spare   -- as above; spare: blocks emptied, for reuse
local blockCount, spareCount, madeCount
local above               -- above(s, t): > 0 when edge s lies above edge t (sweep's edgeOrder)

-- Sets the entries a block holds (even, at least 4) and returns the last setting: for the specs,
-- which run the sweep on small outlines with blocks of 4 so that blocks split, merge and share.
function M.blockSize(n)
  local old = BLOCK
  assert(n % 2 == 0 and n >= 4, "a block holds an even number of entries, at least 4")
  BLOCK, STRIDE = n, n + 2
  return old
end

-- Sets the comparison of two edges along the line (sweep.lua, once; the specs, for a while) and
-- returns the last one.
function M.compare(f)
  local old = above
  above = f
  return old
end

-- Starts an empty order for `edges` edges among `capacity` nodes. Returns the arrays
-- of each edge's neighbours above and below, which the sweep reads (set while it is in the
-- order).
function M.reset(edges, capacity)
  local blocks = 4 * edges / BLOCK + 2
  status = scratch(9, blocks * STRIDE)
  slot, upEdge, downEdge = scratch(10, capacity), scratch(54, capacity), scratch(55, capacity)
  fill, blockList = scratch(50, blocks), scratch(51, blocks)
  listedAt, spare = scratch(52, blocks), scratch(53, blocks)
  fill[1], blockList[1], blockList[2], listedAt[1] = 0, 1, nil, 1
  status[1], status[2] = false, false
  blockCount, spareCount, madeCount = 1, 0, 1
  return upEdge, downEdge
end

-- Drops the arrays of the last sweep.
function M.release()
  status, slot, upEdge, downEdge, fill, blockList, listedAt, spare = nil, nil, nil, nil, nil, nil, nil, nil
end

-- Block b's entries lie at status[base(b) + 2 .. base(b) + 1 + fill[b]], with false at
-- base(b) + 1 and base(b) + 2 + fill[b].
local function base(b) return (b - 1) * STRIDE end

-- The block holding place p.
local function blockOf(p) return (p - 1 - (p - 1) % STRIDE) / STRIDE + 1 end

-- The edge above place p, or false at the top.
local function entryAbove(p)
  local f = status[p + 1]
  if f then return f end
  local c = blockList[listedAt[blockOf(p)] + 1]
  return c and status[base(c) + 2] or false
end

-- The edge below place p, or false at the bottom.
local function entryBelow(p)
  local f = status[p - 1]
  if f then return f end
  local c = blockList[listedAt[blockOf(p)] - 1]
  return c and status[base(c) + 1 + fill[c]] or false
end

-- The first place whose edge does not lie below edge s, as a block and an index in it (one past
-- the block's last entry when every edge lies below s: then the top block's). By halving, first
-- over the blocks' top entries, then in the block found.
function M.find(s)
  local lo, hi = 1, blockCount
  if fill[blockList[1]] == 0 then return blockList[1], 1 end   -- empty (a lone block)
  while lo < hi do
    local mid = (lo + hi - (lo + hi) % 2) / 2
    local b = blockList[mid]
    if above(s, status[base(b) + 1 + fill[b]]) > 0 then lo = mid + 1 else hi = mid end
  end
  local b = blockList[lo]
  local first, last = base(b) + 2, base(b) + 2 + fill[b]
  while first < last do
    local mid = (first + last - (first + last) % 2) / 2
    if above(s, status[mid]) > 0 then first = mid + 1 else last = mid end
  end
  return b, first - base(b) - 1
end

-- The edge at index i of block b, or false past its last entry.
function M.edgeAt(b, i)
  return i <= fill[b] and status[base(b) + 1 + i]
end

-- The block and index just above edge t (aboveIt true) or at it (false: just below it).
function M.beside(t, aboveIt)
  local p = slot[t]
  local b = blockOf(p)
  local i = p - base(b) - 1
  return b, aboveIt and i + 1 or i
end

local function move(from, to)
  local f = status[from]
  status[to], slot[f] = f, to
end

-- A block made (or taken from the spare ones) and listed just above block b, empty.
local function blockAbove(b)
  local c
  if spareCount > 0 then
    c, spareCount = spare[spareCount], spareCount - 1
  else
    madeCount = madeCount + 1
    c = madeCount
  end
  local i = listedAt[b] + 1
  for j = blockCount, i, -1 do
    local d = blockList[j]
    blockList[j + 1], listedAt[d] = d, j + 1
  end
  blockList[i], listedAt[c], fill[c] = c, i, 0
  status[base(c) + 1], status[base(c) + 2] = false, false
  blockCount = blockCount + 1
  blockList[blockCount + 1] = nil   -- a reused array: an earlier sweep's blocks may lie there
  return c
end

-- Drops block b (emptied) from the list.
local function dropBlock(b)
  for j = listedAt[b], blockCount - 1 do
    local d = blockList[j + 1]
    blockList[j], listedAt[d] = d, j
  end
  blockList[blockCount] = nil
  blockCount = blockCount - 1
  spareCount = spareCount + 1
  spare[spareCount] = b
end

-- Block b's entry count set to n, the false entry after them moved along.
local function setFill(b, n)
  fill[b] = n
  status[base(b) + 2 + n] = false
end

-- Puts edge s at index i of block b (1 to one past its last entry), the entries from there up
-- moved up by one; a full block first gives its upper half to a new block above it. Links s
-- to its neighbours.
function M.insert(b, i, s)
  local n = fill[b]
  if n == BLOCK then
    local c, half = blockAbove(b), BLOCK / 2
    local from, to = base(b) + 1 + half, base(c) + 1
    for j = 1, BLOCK - half do move(from + j, to + j) end
    setFill(b, half)
    setFill(c, BLOCK - half)
    if i > half + 1 then b, i = c, i - half end
    n = fill[b]
  end
  local first = base(b) + 1
  for p = first + n, first + i, -1 do move(p, p + 1) end
  local p = first + i
  status[p], slot[s] = s, p
  setFill(b, n + 1)
  local below, over = entryBelow(p), entryAbove(p)
  downEdge[s], upEdge[s] = below, over
  if below then upEdge[below] = s end
  if over then downEdge[over] = s end
end

-- Edge t takes edge s's place (and neighbours).
function M.replace(s, t)
  local p = slot[s]
  local below, over = downEdge[s], upEdge[s]
  status[p], slot[t] = t, p
  downEdge[t], upEdge[t] = below, over
  if below then upEdge[below] = t end
  if over then downEdge[over] = t end
end

-- Blocks b and c, next to each other (b below), as one block when their entries fit in three
-- quarters of one, else shared evenly: run when one falls below a quarter.
local function rebalance(b, c)
  local nb, nc = fill[b], fill[c]
  local firstB, firstC = base(b) + 1, base(c) + 1   -- the places before their first entries
  if nb + nc <= BLOCK - BLOCK / 4 then
    for j = 1, nc do move(firstC + j, firstB + nb + j) end
    setFill(b, nb + nc)
    dropBlock(c)
    return
  end
  local target = (nb + nc - (nb + nc) % 2) / 2
  if nb < target then   -- c's lowest entries to b's top, then c's others down
    local k = target - nb
    for j = 1, k do move(firstC + j, firstB + nb + j) end
    for j = k + 1, nc do move(firstC + j, firstC + j - k) end
    setFill(c, nc - k)
  else                  -- c's entries up, then b's highest entries to c's bottom
    local k = nb - target
    for j = nc, 1, -1 do move(firstC + j, firstC + j + k) end
    for j = 1, k do move(firstB + target + j, firstC + j) end
    setFill(c, nc + k)
  end
  setFill(b, target)
end

-- Takes edge s out, the entries above it in its block moved down by one, its neighbours linked.
function M.remove(s)
  local below, over = downEdge[s], upEdge[s]
  if below then upEdge[below] = over end
  if over then downEdge[over] = below end
  local p = slot[s]
  local b = blockOf(p)
  local n = fill[b]
  for q = p, base(b) + n do move(q + 1, q) end
  setFill(b, n - 1)
  if n - 1 < BLOCK / 4 and blockCount > 1 then
    local i = listedAt[b]
    if i < blockCount then rebalance(b, blockList[i + 1]) else rebalance(blockList[i - 1], b) end
  end
end

return M
