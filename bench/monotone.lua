-- A measurement, not the library: what triangulating by monotone pieces would cost on the noisy
-- outlines of bench/holes.lua, next to the ear clipping's grid and ear phases (bench/NOTES.md,
-- session 24). `luajit bench/monotone.lua N` (N vertices, default 1000) prints the pieces'
-- count, a check of the triangles and the warm time a call.
--
-- An outline in general position (no vertical edge, no three vertices in line: the noisy
-- circles' random radii) is cut into x-monotone pieces by diagonals, sweeping in x, each
-- vertex's edge below it known, then each piece is triangulated with a stack. The edge below a
-- vertex is what the check's sweep (polygon/sweep.lua) finds as it goes; here it is found by
-- brute force, untimed, so the time is the work a triangulation in the check's own sweep would
-- add to it. Float orientation only (a degenerate triple raises): fit for the measurement, not
-- for the library.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local prng = require "prng"
local shapes = require "shapes"

local abs, min, huge = math.abs, math.min, math.huge
local n = tonumber(arg and arg[1]) or 1000
local points = shapes.noisyCircle(n, prng.new(n))
local X, Y = {}, {}
for i = 1, n do X[i], Y[i] = points[2 * i - 1], points[2 * i] end

-- > 0 when a, b, c turn left (y up, as the noisy circles run)
local function orient(a, b, c)
  local l, r = (X[a] - X[c]) * (Y[b] - Y[c]), (Y[a] - Y[c]) * (X[b] - X[c])
  local s = l - r
  if abs(s) <= 1e-14 * abs(l + r) then error("bench/monotone.lua: a near-degenerate triple") end
  return s
end

local nextV, prevV = {}, {}
for i = 1, n do nextV[i], prevV[i] = i % n + 1, (i - 2) % n + 1 end
local order, rank = {}, {}
for i = 1, n do order[i] = i end
table.sort(order, function(a, b) return X[a] < X[b] or (X[a] == X[b] and Y[a] < Y[b]) end)
for i = 1, n do rank[order[i]] = i end

-- Untimed: below[v], the edge k -> nextV[k] running rightwards (the inside above it) that the
-- line x = X[v] meets right below v.
local below = {}
for v = 1, n do
  local best, bestY = nil, -huge
  for k = 1, n do
    local q = nextV[k]
    if rank[k] < rank[v] and rank[v] < rank[q] then
      local y = Y[k] + (Y[q] - Y[k]) * (X[v] - X[k]) / (X[q] - X[k])
      if y < Y[v] and y > bestY then best, bestY = k, y end
    end
  end
  below[v] = best
end

-- Each vertex's kind in the sweep: both neighbours later (a start, or a split when reflex), both
-- earlier (an end, or a merge), else regular with the inside above it or below it.
local START, SPLIT, END, MERGE, INSIDE_ABOVE, INSIDE_BELOW = 1, 2, 3, 4, 5, 6
local kind = {}
for v = 1, n do
  local p, q = prevV[v], nextV[v]
  local convex = orient(p, v, q) > 0
  if rank[v] < rank[p] and rank[v] < rank[q] then kind[v] = convex and START or SPLIT
  elseif rank[p] < rank[v] and rank[q] < rank[v] then kind[v] = convex and END or MERGE
  elseif rank[p] < rank[v] then kind[v] = INSIDE_ABOVE
  else kind[v] = INSIDE_BELOW end
end

-- The diagonals, by the helper rule: helper[e] is the last vertex met with edge e right below
-- it (or e's own start); a diagonal joins a split vertex to its helper, and a merge vertex to the
-- next vertex met in the same gap.
local helper, diagA, diagB = {}, {}, {}
local function decompose()
  local d = 0
  for i = 1, n do
    local v = order[i]
    local kv = kind[v]
    if kv == START or kv == INSIDE_ABOVE then
      if kv == INSIDE_ABOVE and kind[helper[prevV[v]]] == MERGE then
        d = d + 1; diagA[d], diagB[d] = v, helper[prevV[v]]
      end
      helper[v] = v
    elseif kv == END then
      if kind[helper[prevV[v]]] == MERGE then d = d + 1; diagA[d], diagB[d] = v, helper[prevV[v]] end
    elseif kv == SPLIT then
      local e = below[v]
      d = d + 1; diagA[d], diagB[d] = v, helper[e]
      helper[e], helper[v] = v, v
    else   -- MERGE or INSIDE_BELOW: the gap above the edge below v
      if kv == MERGE and kind[helper[prevV[v]]] == MERGE then
        d = d + 1; diagA[d], diagB[d] = v, helper[prevV[v]]
      end
      local e = below[v]
      if kind[helper[e]] == MERGE then d = d + 1; diagA[d], diagB[d] = v, helper[e] end
      helper[e] = v
    end
  end
  return d
end

-- Each vertex's neighbours (its ring's two, then its diagonals' ends), sorted by angle where it
-- has diagonals; used[h] marks a half-edge walked.
local adjStart, adjCount, adj, used, usedRing, fill, angle = {}, {}, {}, {}, {}, {}, {}

-- A number in [0, 4) growing with the direction's angle (a square's perimeter, not trigonometry).
local function pseudoAngle(dx, dy)
  if dy >= 0 then return dx >= 0 and dy / (dx + dy) or 1 - dx / (dy - dx) end
  return dx < 0 and 2 - dy / (-dx - dy) or 3 + dx / (dx - dy)
end
local function link(d)
  for v = 1, n do adjCount[v] = 2 end
  for i = 1, d do
    adjCount[diagA[i]], adjCount[diagB[i]] = adjCount[diagA[i]] + 1, adjCount[diagB[i]] + 1
  end
  local at = 1
  for v = 1, n do
    adjStart[v], adj[at], adj[at + 1], fill[v] = at, nextV[v], prevV[v], at + 2
    at = at + adjCount[v]
  end
  for i = 1, d do
    local a, b = diagA[i], diagB[i]
    adj[fill[a]], fill[a] = b, fill[a] + 1
    adj[fill[b]], fill[b] = a, fill[b] + 1
  end
  for v = 1, n do
    local s, c = adjStart[v], adjCount[v]
    if c > 2 then
      for j = s, s + c - 1 do local a = adj[j]; angle[a] = pseudoAngle(X[a] - X[v], Y[a] - Y[v]) end
      for j = s + 1, s + c - 1 do   -- insertion sort: a few entries
        local a, g = adj[j], j - 1
        while g >= s and angle[adj[g]] > angle[a] do adj[g + 1] = adj[g]; g = g - 1 end
        adj[g + 1] = a
      end
    end
  end
  for h = 1, at - 1 do used[h] = false end
  for v = 1, n do usedRing[v] = false end
end

local function slot(w, u)
  for j = adjStart[w], adjStart[w] + adjCount[w] - 1 do if adj[j] == u then return j end end
end

-- The piece's next half-edge: at w, coming from u, the neighbour just clockwise of u.
local function turnAt(w, u)
  local s, c = adjStart[w], adjCount[w]
  if c == 2 then return adj[s] == u and adj[s + 1] or adj[s] end
  return adj[s + (slot(w, u) - s - 1) % c]
end

local tris, triCount = {}, 0
local chain, merged, stack, piece = {}, {}, {}, {}
local function emit(a, b, c)
  tris[triCount + 1], tris[triCount + 2], tris[triCount + 3] = a, b, c
  triCount = triCount + 3
end

-- Walks the piece with half-edge u -> w and triangulates it: its two chains merged in sweep
-- order, then the stack (a vertex on the other chain sees every stacked one; on the same chain,
-- those its turn allows).
local function triangulatePiece(u, w)
  local m, a, b = 0, u, w
  repeat
    m = m + 1; piece[m] = a
    if b == nextV[a] then usedRing[a] = true else used[slot(a, b)] = true end
    a, b = b, turnAt(b, a)
  until a == u and b == w
  if m == 3 then emit(piece[1], piece[2], piece[3]); return end
  local left, right = 1, 1
  for i = 2, m do
    if rank[piece[i]] < rank[piece[left]] then left = i end
    if rank[piece[i]] > rank[piece[right]] then right = i end
  end
  local lower, upper, k = left % m + 1, (left - 2) % m + 1, 1
  merged[1] = piece[left]; chain[piece[left]] = 0
  while lower ~= right or upper ~= right do
    local lo, up = piece[lower], piece[upper]
    if lower ~= right and (upper == right or rank[lo] < rank[up]) then
      k = k + 1; merged[k] = lo; chain[lo] = 1; lower = lower % m + 1
    else
      k = k + 1; merged[k] = up; chain[up] = 2; upper = (upper - 2) % m + 1
    end
  end
  k = k + 1; merged[k] = piece[right]; chain[piece[right]] = 0
  stack[1], stack[2] = merged[1], merged[2]
  local top = 2
  for q = 3, k - 1 do
    local v = merged[q]
    if chain[v] ~= chain[stack[top]] then
      for s = top, 2, -1 do emit(v, stack[s], stack[s - 1]) end
      stack[1], stack[2], top = merged[q - 1], v, 2
    else
      local last = stack[top]
      top = top - 1
      while top >= 1 do
        local s = orient(stack[top], last, v)
        if (chain[v] == 1) ~= (s > 0) then break end
        emit(stack[top], last, v)
        last = stack[top]
        top = top - 1
      end
      stack[top + 1], stack[top + 2], top = last, v, top + 2
    end
  end
  for s = top, 2, -1 do emit(merged[k], stack[s], stack[s - 1]) end
end

local function triangulate()
  triCount = 0
  local d = decompose()
  link(d)
  for v = 1, n do
    if not usedRing[v] then triangulatePiece(v, nextV[v]) end
  end
  for i = 1, d do   -- a piece bounded by diagonals alone
    local a, b = diagA[i], diagB[i]
    if not used[slot(a, b)] then triangulatePiece(a, b) end
    if not used[slot(b, a)] then triangulatePiece(b, a) end
  end
  return d
end

-- A check of the output (not a proof): n - 2 triangles whose areas, taken positive, add up to
-- the outline's (in floats: to about 1e-14 of it).
local diagonals = triangulate()
local area, sum = 0, 0
for i = 1, n do local q = nextV[i]; area = area + X[i] * Y[q] - X[q] * Y[i] end
for t = 1, triCount, 3 do sum = sum + abs(orient(tris[t], tris[t + 1], tris[t + 2])) end
print(("%d vertices: %d diagonals, %d triangles (%d wanted), areas' sum / area - 1 = %.1e")
  :format(n, diagonals, triCount / 3, n - 2, sum / area - 1))

local began = os.clock()
while os.clock() - began < 1 do triangulate() end
local best = huge
for _ = 1, 5 do
  local calls, start = 0, os.clock()
  repeat triangulate(); calls = calls + 1 until os.clock() - start > 0.2
  best = min(best, (os.clock() - start) / calls * 1e6)
end
print(("pieces and their triangles: %.1f us a call (best of 5 rounds of 0.2 s)"):format(best))
