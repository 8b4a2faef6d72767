-- polygon/monotone.lua: triangulation by monotone pieces, for an outline without holes that
-- polygon/sweep.lua's sweep has checked and found plain (each place holds one vertex, no vertex
-- lies inside an edge). The sweep notes the edge right below each vertex as it goes; from those,
-- diagonals cut the outline into pieces monotone in the sweep's order (the helper rule), and each
-- piece is triangulated with a stack. Linear after the sweep, where ear clipping's tests grow with
-- the outline's spikes: a noisy circle of 10,000 vertices spent 5.4 ms in the ear test's grid and
-- its ears, about 2.4 ms here (bench/NOTES.md, session 24). Every decision is an exact sign
-- (orient), a comparison of the sweep's ranks or of two coordinates.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local nodes = require(_PACKAGE .. ".nodes")

local scratch, orient = nodes.scratch, nodes.orient

local M = {}
-- This file's main chunk: triangulate.lua turns LuaJIT's compiler off and on for every function
-- in it (see there).
M.chunk = debug.getinfo(1, "f").func
-- Calls that gave triangles, and calls that left them to ear clipping (for the specs).
M.taken, M.declined = 0, 0

-- The node arrays (bound by triangulate.lua) and the sweep's results (see M.triangulate).
local nodeX, nodeY, nextNode, prevNode, turn, capacity
local rank, placeOrder, placeCount, belowOf

function M.bind(x, y, nextN, prevN, sign, cap)
  nodeX, nodeY, nextNode, prevNode, turn, capacity = x, y, nextN, prevN, sign, cap
end

-- A vertex's kind along the sweep: both neighbours later (a start, or a split when reflex), both
-- earlier (an end, or a merge when reflex), else regular, with the inside on the side of higher
-- y (a place above it in the sweep's order) or of lower y.
local START, SPLIT, END, MERGE, INSIDE_UP, INSIDE_DOWN = 1, 2, 3, 4, 5, 6
local kind, helper, diagA, diagB, diagCount

-- Whether edge k (node k to its successor) has the inside above it in the sweep's order: it runs
-- forward (to a later place) and the ring turns positively, or backward and negatively.
local function insideUp(k)
  return (rank[k] < rank[nextNode[k]]) == (turn > 0)
end

local function addDiagonal(a, b)
  diagCount = diagCount + 1
  diagA[diagCount], diagB[diagCount] = a, b
end

-- The diagonals, by the helper rule (sweep order): helper[e], for an edge e with the inside above
-- it, is the last vertex met with e right below it (at first e's own left end). A split vertex
-- joins its helper; a merge vertex is joined by the next vertex met in its gap. false when a
-- vertex lies in line with its neighbours or an edge below is missing (then ear clipping).
-- Each vertex's kind is found as the sweep meets it: a helper is always a vertex met before.
-- (One pass rather than a pass for the kinds first: noisy outlines of 1,000 vertices taken in
-- turn 3 % faster, bench/NOTES.md, session 28.)
local function decompose()
  diagCount = 0
  for i = 1, placeCount do
    local v = placeOrder[i]
    local p, q = prevNode[v], nextNode[v]
    local s = orient(p, v, q)
    if s == 0 then return false end
    local r = rank[v]
    local kv
    if r < rank[p] and r < rank[q] then kv = s > 0 and START or SPLIT
    elseif r > rank[p] and r > rank[q] then kv = s > 0 and END or MERGE
    elseif insideUp(rank[p] < r and p or v) then kv = INSIDE_UP
    else kv = INSIDE_DOWN end
    kind[v] = kv
    if kv == START then
      helper[insideUp(v) and v or p] = v
    elseif kv == END then
      local e = insideUp(p) and p or v
      if kind[helper[e]] == MERGE then addDiagonal(v, helper[e]) end
    elseif kv == INSIDE_UP then   -- the edge ending here hands its gap to the one starting here
      local ending, starting = v, p
      if rank[p] < rank[v] then ending, starting = p, v end
      if kind[helper[ending]] == MERGE then addDiagonal(v, helper[ending]) end
      helper[starting] = v
    else
      if kv == MERGE then
        local e = insideUp(p) and p or v
        if kind[helper[e]] == MERGE then addDiagonal(v, helper[e]) end
      end
      local e = belowOf[v]
      if e == 0 or not insideUp(e) then return false end
      if kv == SPLIT then
        addDiagonal(v, helper[e])
        helper[insideUp(v) and v or p] = v
      elseif kind[helper[e]] == MERGE then
        addDiagonal(v, helper[e])
      end
      helper[e] = v
    end
  end
  return true
end

-- The diagonals' ends' neighbours: each such vertex's ring neighbours and its diagonals' far
-- ends, sorted by angle, in adj from adjStart[v] (adjCount[v] of them); lists[1 .. listCount]
-- the vertices with a list. A vertex without one (not listed[v]) has its ring's two
-- neighbours alone, and a piece walking through it goes on along the ring. ringUsed[k]:
-- the ring's edge from k walked; used[h]: the half-edge from a listed vertex to adj[h] walked.
local adjStart, adjCount, adj, used, ringUsed, listed, lists, listCount
local diagsAt          -- diagonals at a vertex

-- Whether the direction from v to a comes before the one to b counterclockwise from +x (in the
-- coordinates' own frame: y up): by half-plane, then by the exact sign of their cross product.
local function before(v, a, b)
  local ay, by = nodeY[a] - nodeY[v], nodeY[b] - nodeY[v]
  local ha = (ay > 0 or (ay == 0 and nodeX[a] > nodeX[v])) and 0 or 1
  local hb = (by > 0 or (by == 0 and nodeX[b] > nodeX[v])) and 0 or 1
  if ha ~= hb then return ha < hb end
  return orient(v, a, b) * turn > 0
end

-- Gives diagonal end v its list on first sight (its ring's two neighbours), then adds w.
local at
local function listEnd(v, w)
  if not listed[v] then
    listed[v], adjStart[v], adjCount[v] = true, at, 2
    adj[at], adj[at + 1] = nextNode[v], prevNode[v]
    at = at + 2 + diagsAt[v]
    listCount = listCount + 1
    lists[listCount] = v
  end
  local c = adjCount[v]
  adj[adjStart[v] + c], adjCount[v] = w, c + 1
end

local function link()
  for i = 1, placeCount do
    local k = placeOrder[i]
    listed[k], ringUsed[k] = false, false
  end
  for i = 1, diagCount do diagsAt[diagA[i]], diagsAt[diagB[i]] = 0, 0 end
  for i = 1, diagCount do   -- the diagonals at each end
    local a, b = diagA[i], diagB[i]
    diagsAt[a], diagsAt[b] = diagsAt[a] + 1, diagsAt[b] + 1
  end
  at, listCount = 1, 0
  for i = 1, diagCount do
    listEnd(diagA[i], diagB[i])
    listEnd(diagB[i], diagA[i])
  end
  for j = 1, at - 1 do used[j] = false end
  for i = 1, listCount do   -- each list in order (insertion: a few entries)
    local v = lists[i]
    local s, c = adjStart[v], adjCount[v]
    for j = s + 1, s + c - 1 do
      local a, g = adj[j], j - 1
      while g >= s and before(v, a, adj[g]) do adj[g + 1] = adj[g]; g = g - 1 end
      adj[g + 1] = a
    end
  end
end

-- Where listed vertex w's neighbour u is.
local function slotOf(w, u)
  local j = adjStart[w]
  while adj[j] ~= u do j = j + 1 end
  return j
end

-- Marks the half-edge from u to w walked.
local function mark(u, w)
  if w == nextNode[u] then ringUsed[u] = true else used[slotOf(u, w)] = true end
end

-- The next vertex of a piece at w, coming from u, with the half-edge to it marked: along the
-- ring when w has no list, else the neighbour next to u on the inside's side (clockwise of u
-- when the ring turns counterclockwise, y up).
local function turnAt(w, u)
  if not listed[w] then
    ringUsed[w] = true
    return nextNode[w]
  end
  local s = adjStart[w]
  local h = s + (slotOf(w, u) - s - turn) % adjCount[w]
  local z = adj[h]
  if z == nextNode[w] then ringUsed[w] = true else used[h] = true end
  return z
end

local tris, triCount
local piece, merged, chain, stack

local function emit(a, b, c)
  local s = orient(a, b, c)
  if s < 0 then b, c = c, b end
  local t = tris
  t[triCount + 1], t[triCount + 2], t[triCount + 3] = a, b, c
  triCount = triCount + 3
  return s ~= 0
end

-- Walks the piece from half-edge u -> w and triangulates it: its two chains merged in the sweep's
-- order, then a stack (a vertex on the other chain sees every stacked one; on its own chain, as
-- far as the chain turns towards the inside). false when a triangle comes out flat.
local pieceLimit        -- more vertices than the ring and the diagonals hold: a walk gone wrong
local function triangulatePiece(u, w)
  mark(u, w)
  piece[1] = u
  local m, a, b = 1, u, w
  while b ~= u do
    m = m + 1
    if m > pieceLimit then return false end
    piece[m] = b
    a, b = b, turnAt(b, a)
  end
  if m == 3 then return emit(piece[1], piece[2], piece[3]) end
  local left, right = 1, 1
  for i = 2, m do
    if rank[piece[i]] < rank[piece[left]] then left = i end
    if rank[piece[i]] > rank[piece[right]] then right = i end
  end
  local lower, upper, k = left % m + 1, (left - 2) % m + 1, 1
  merged[1] = piece[left]
  chain[piece[left]] = 0
  while lower ~= right or upper ~= right do
    local lo, up = piece[lower], piece[upper]
    k = k + 1
    if lower ~= right and (upper == right or rank[lo] < rank[up]) then
      merged[k], chain[lo], lower = lo, 1, lower % m + 1
    else
      merged[k], chain[up], upper = up, 2, (upper - 2) % m + 1
    end
  end
  k = k + 1
  merged[k] = piece[right]
  chain[piece[right]] = 0
  stack[1], stack[2] = merged[1], merged[2]
  local top, flat = 2, false
  for q = 3, k - 1 do
    local v = merged[q]
    if chain[v] ~= chain[stack[top]] then
      for s = top, 2, -1 do flat = not emit(v, stack[s], stack[s - 1]) or flat end
      stack[1], stack[2], top = merged[q - 1], v, 2
    else
      local last = stack[top]
      top = top - 1
      while top >= 1 do
        local s = orient(stack[top], last, v)
        if (chain[v] == 1 and s <= 0) or (chain[v] == 2 and s >= 0) then break end
        flat = not emit(stack[top], last, v) or flat
        last = stack[top]
        top = top - 1
      end
      stack[top + 1], stack[top + 2], top = last, v, top + 2
    end
  end
  for s = top, 2, -1 do flat = not emit(merged[k], stack[s], stack[s - 1]) or flat end
  return not flat
end

-- Triangulates the ring whose nodes, count of them, sweep.plainSweep returned (order, count,
-- ranks, below) into out (three nodes a triangle, each wound like the ring): the entries
-- written, or nil when this way does not apply (a vertex in line with its neighbours; then ear
-- clipping).
function M.triangulate(out, order, count, ranks, below)
  rank, placeOrder, placeCount, belowOf = ranks, order, count, below
  -- the arrays of ear clipping's grid and bridges, which a call taking this way never builds
  -- (only the sweep's results are read here): kept between calls, they are not kept twice
  kind, helper = scratch(14, capacity), scratch(15, capacity)
  diagA, diagB = scratch(16, count), scratch(17, count)
  local ok = decompose()
  if ok then
    local halfEdges = count + 2 * diagCount
    pieceLimit = halfEdges
    adjStart, adjCount, listed = scratch(18, capacity), scratch(19, capacity), scratch(49, capacity)
    diagsAt, lists = scratch(11, capacity), scratch(12, 2 * diagCount)
    adj, used, ringUsed = scratch(20, 6 * diagCount), scratch(21, 6 * diagCount), scratch(22, capacity)
    piece, merged, chain = scratch(33, halfEdges), scratch(46, halfEdges), scratch(47, capacity)
    stack = scratch(48, halfEdges)
    link()
    tris, triCount = out, 0
    for i = 1, placeCount do
      local k = placeOrder[i]
      if not ringUsed[k] then ok = triangulatePiece(k, nextNode[k]) and ok end
    end
    for i = 1, triCount < 3 * (count - 2) and diagCount or 0 do   -- a piece of diagonals alone
      local a, b = diagA[i], diagB[i]
      if not used[slotOf(a, b)] then ok = triangulatePiece(a, b) and ok end
      if not used[slotOf(b, a)] then ok = triangulatePiece(b, a) and ok end
    end
    ok = ok and triCount == 3 * (count - 2)
  end
  rank, placeOrder, belowOf, kind, helper, diagA, diagB = nil, nil, nil, nil, nil, nil, nil
  adjStart, adjCount, adj, used, ringUsed, tris = nil, nil, nil, nil, nil, nil
  listed, diagsAt, lists = nil, nil, nil
  piece, merged, chain, stack = nil, nil, nil, nil
  if not ok then M.declined = M.declined + 1; return nil end
  M.taken = M.taken + 1
  return triCount
end

return M
