-- polygon/places.lua: whether the rings of a triangulation cross or overlap at one place where
-- several of their vertices meet, or where a vertex lies inside an edge: there two rings (or
-- one ring with itself) may cross without two edges crossing properly, which is all that
-- polygon/sweep.lua's ways test. sweep.lua finds the places and the edges through them and asks
-- chainsCross about each. Every decision is an exact sign (kernel.cross) or a comparison of
-- coordinates.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")

local cross, sort = kernel.cross, table.sort

local M = {}
-- This file's main chunk: triangulate.lua turns LuaJIT's compiler off and on for every function
-- in it (see there).
M.chunk = debug.getinfo(1, "f").func

-- The node arrays of the triangulation under way (bound by sweep.lua's bind), and the kind of
-- edge (0 leaving the place, 1 reaching it; see below) with the polygon's inside just after it
-- by angle: every ring has the inside on its orient > 0 side, on the left of its edges when the
-- outline turns positively.
local nodeX, nodeY, nextNode, prevNode, nodeRing, capacity, insideKind

local undecided   -- a place was left untested since the last bind (see M.undecided)

function M.bind(x, y, nextN, prevN, cap, ring, sign)
  nodeX, nodeY, nextNode, prevNode, capacity, nodeRing = x, y, nextN, prevN, cap, ring
  insideKind = sign and (sign > 0 and 0 or 1)
  undecided = false
end

-- Whether chainsCross left a place untested (three or more edges along one direction) since
-- the triangulation's arrays were bound: the rings may still cross there.
function M.undecided() return undecided end

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
-- edge): one edge each way may go in either order, which alternation decides (below); three
-- or more leave the place untested. An entry is 2k for the edge from node k to its
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

-- Whether entries[1..count], sorted by angle, alternate in and out and nest like brackets.
local open = {}   -- alternateAndNest's open brackets: read only up to its depth
local function alternateAndNest(entries, count)
  local depth = 0   -- the chains' pairs, as brackets
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

-- The ring of entry u's chain: its node's, or that of the edge holding the place inside.
local function entryRing(u)
  local k = (u - u % 2) / 2
  return nodeRing[k > capacity and k - capacity or k]
end

-- Whether every sector the alternation gives the polygon (the one after an edge of insideKind)
-- lies on the polygon's side of each ring through the place by that ring's own edges there:
-- inside the outline, outside each hole. (A hole running along the outline's edge and on past
-- the outline's vertex, out of the polygon, alternates and nests there, but covers the
-- outline's corner: there a sector after an edge of the outline lies after an edge of the hole
-- of the other kind.)
local ringsAt, ringOf = {}, {}   -- the rings through the place, each entry's: read only up
                                 -- to their counts
local function ringsAgree(entries, count)
  local rings = 0
  for j = 1, count do
    local r, known = entryRing(entries[j]), false
    ringOf[j] = r
    for g = 1, rings do known = known or ringsAt[g] == r end
    if not known then rings = rings + 1; ringsAt[rings] = r end
  end
  for g = 1, rings > 1 and rings or 0 do   -- (one ring alone agrees with itself)
    local r, last = ringsAt[g], nil
    for j = count, 1, -1 do   -- the kind of r's last edge before the first, going round
      if ringOf[j] == r then last = entries[j] % 2; break end
    end
    for j = 1, count do
      local kind = entries[j] % 2
      if ringOf[j] == r then last = kind
      elseif kind == insideKind and last ~= insideKind then return false end
    end
  end
  return true
end

-- chainsCross's arrays, kept from one place to the next (read only up to their counts): tile
-- maps meet at a thousand places, each of which made three tables.
local entries, tied = {}, {}
local SORT_RUN = 16   -- entries sorted by insertion at most (in Lua, which LuaJIT compiles;
                      -- table.sort's comparison calls are not compiled into the caller)

-- Whether the chains of the nodes placeOrder[first..last], all at one place, and of the edges
-- `touched` holding it inside (or nil), cross or overlap there (see above).
function M.chainsCross(placeOrder, first, last, touched)
  local count = 0
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
  if count <= SORT_RUN then
    for i = 2, count do
      local u, j = entries[i], i - 1
      while j >= 1 and byAngle(u, entries[j]) do entries[j + 1] = entries[j]; j = j - 1 end
      entries[j + 1] = u
    end
  else
    for i = #entries, count + 1, -1 do entries[i] = nil end   -- table.sort sorts them all
    sort(entries, byAngle)
  end
  local at, tiedCount = 1, 0
  while at <= count do   -- the runs of edges in one direction: count those leaving, reaching
    local u, runEnd, balance = entries[at], at, 0
    while runEnd < count and not byAngle(u, entries[runEnd + 1]) do runEnd = runEnd + 1 end
    for j = at, runEnd do balance = balance + (entries[j] % 2 == 0 and 1 or -1) end
    if balance > 1 or balance < -1 then return true end
    if runEnd > at + 1 then undecided = true; return false end   -- three or more: not decided here
    if runEnd == at + 1 then tiedCount = tiedCount + 1; tied[tiedCount] = at end   -- either order
    at = runEnd + 1
  end
  if tiedCount == 0 then return not (alternateAndNest(entries, count) and ringsAgree(entries, count)) end
  -- Alternation fixes every entry's kind by its position, up to one flip of them all: (j +
  -- entries[j]) % 2 is one number for every j. The entries not in a tied pair say which, or no
  -- order alternates; each tied pair (one edge each way) then has the one order that gives its
  -- first position the kind it needs. So of the 2^pairs orders at most two alternate: those are
  -- tested, and only when no entry outside the pairs fixes the flip, both.
  local parity, t = -1, 1
  local j = 1
  while j <= count do
    if t <= tiedCount and tied[t] == j then
      t, j = t + 1, j + 2
    else
      local p = (j + entries[j]) % 2
      if parity < 0 then parity = p elseif p ~= parity then return true end
      j = j + 1
    end
  end
  for flip = 0, parity < 0 and 1 or 0 do
    local want = parity < 0 and flip or parity
    for g = 1, tiedCount do
      j = tied[g]
      if (j + entries[j]) % 2 ~= want then entries[j], entries[j + 1] = entries[j + 1], entries[j] end
    end
    if alternateAndNest(entries, count) and ringsAgree(entries, count) then return false end
  end
  return true
end

return M
