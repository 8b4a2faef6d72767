-- polygon/views.lua: what the collisions read of a shape: the preparation of a list of
-- convex parts (boxes, signs, normals, kept while the list lives and refreshed when a part
-- changes) and the scratch views of flat arrays. Relies on kernel and sat's unit.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local sat = require(_PACKAGE .. ".sat")
local convex = require(_PACKAGE .. ".convex")

local sqrt, huge, min, max = math.sqrt, math.huge, math.min, math.max
local areaSign, JIT, cross = kernel.areaSign, kernel.JIT, kernel.cross
local unit = sat.unit
local checkConvex, fewPointsMessage = convex.checkConvex, convex.fewPointsMessage

local M = {}

-- polygonsCollide, polygonsCollideV and polygonCircleCollideV also take, for either shape, a list
-- of convex parts {part1, part2, ...}: what polygonConvexParts returns, or parts built by hand.
-- A flat array holds a number at [1], a list of parts a table.

-- Whether shape is a list of parts rather than a flat array of coordinates (the collision
-- functions dispatch on it).
local function isParts(shape)
  return type(shape) == "table" and type(shape[1]) == "table"
end

-- The preparation each list of parts gets on first use, kept while the list lives (weak keys):
-- per part a copy of its coordinates, its bounding box, its area sign and its outward unit edge
-- normals, and which of its edges are internal: internal[k][i] is 1 when the edge of part k
-- ending at vertex index i (odd; from the vertex before, the last for the first) is covered by
-- edges of other parts running the opposite way along the same line (shared with the
-- neighbours, whole or in pieces), else 0 (numbers, not true and nil: on LuaJIT a load whose
-- type varies is a side exit).
-- Keeping it right. Reading every coordinate on every call costs as much as the pair tests a
-- call needs, so each call checks, per part, only its table, its length and the four
-- coordinates on its box (the vertices that gave xmin, ymin, xmax, ymax). That is exact for a
-- move (polygonTranslate in place, or p[i] = p[i] + dx on every coordinate, rounded): rounding
-- is monotonic, so if the coordinates on the box did not change, no moved coordinate left the
-- box, and the box is right. A part whose box is used (it overlaps the other shape's) is
-- compared with its whole copy too, so its sign and normals are always those of its present
-- coordinates. What is not seen: an edit other than a move that leaves the coordinates on a
-- part's box as they were and takes another vertex beyond it (give the part a new table then).
-- A changed part gets its copy, box, sign and normals again, in place, without allocating; a
-- change in the number of parts or of a part's coordinates prepares the list again
-- (allocates). The internal edges are kept when coordinates change: moving a shape keeps them
-- right, and after other edits a stale table costs at most a longer push (a foot skipped) or
-- some time (a foot tried), never a wrong one, as every candidate is checked against every part.
local preparedParts = setmetatable({}, { __mode = "k" })

-- The interval an edge covers along its line: on x unless the line is vertical (exact).
local function edgeSpan(ax, ay, bx, by, onX)
  if onX then return min(ax, bx), max(ax, bx) end
  return min(ay, by), max(ay, by)
end

-- Whether the spans in `covers` (pairs lo, hi, any order) cover [lo, hi].
local function covered(covers, lo, hi)
  table.sort(covers, function(p, q) return p[1] < q[1] end)
  local reach = lo
  for _, span in ipairs(covers) do
    if span[1] > reach then return false end
    if span[2] > reach then reach = span[2] end
    if reach >= hi then return true end
  end
  return reach >= hi
end

-- A view of a shape is what the collisions read of it: count, lengths[k], boxes (xmin, ymin,
-- xmax, ymax of part k at 4k - 3 .. 4k), turns[k] (area sign 1, -1 or 0: signs, never
-- magnitudes, are multiplied), normals[k] (the outward unit normal of the edge ending at vertex
-- index i at [i], [i + 1]), internal[k], rects[k] (rectKind's 0, 1 or 2) and sides[k] (a
-- rectangle's sides, rectSides), and over all parts size (the largest coordinate magnitude)
-- and the box left, top, right, bottom. A list's preparation is its view, with
-- records[k] for the per-call checks: xmin, ymin, xmax, ymax of part k at [1] .. [4] again, the
-- indices of the coordinates that gave them at [5] .. [8], the part's table at [9] (false after
-- a non-finite coordinate) and its length at [10] (constant indices: one instruction each on
-- PUC Lua, in the loop over every part). A flat array is seen through one of two scratch views,
-- filled on every call.

-- 1 when points[1 .. n] is a rectangle with axis-parallel sides whose edge into vertex 1 is
-- vertical, 2 when that edge is horizontal, else 0, as the coordinates' floats give it (its
-- box xmin < xmax, ymin < ymax: no side has length 0). Such a part's faces take no projection
-- (pairFaces).
local function rectKind(points, n, xmin, ymin, xmax, ymax)
  if n ~= 8 or not (xmin < xmax and ymin < ymax) then return 0 end
  local x1, y1, x2, y2 = points[1] + 0.0, points[2] + 0.0, points[3] + 0.0, points[4] + 0.0
  local x3, y3, x4, y4 = points[5] + 0.0, points[6] + 0.0, points[7] + 0.0, points[8] + 0.0
  if x4 == x1 and y1 == y2 and x2 == x3 and y3 == y4 then return 1 end
  if y4 == y1 and x1 == x2 and y2 == y3 and x3 == x4 then return 2 end
  return 0
end

-- The sides of a rectangle of kind rect (rectKind; xmin, ymin its box's), numbered left 1, top
-- 2, right 3, bottom 4 (outward normals (-1, 0), (0, -1), (1, 0), (0, 1)): at odd index i the
-- side of the edge into vertex index i, at i + 1 the opposite side. Its edges alternate between
-- vertical and horizontal sides (a vertical one first for rect 1), the first vertical one at
-- v1's x, the first horizontal one at v1's y, then their opposites. Eight orders in all, made
-- once here and shared (read only): RECT_SIDES[4 (rect - 1) + 2 (v1 on the right) + (v1 at
-- the bottom) + 1]. A view's sides[k] is one of them (a flat rectangle's is picked per call, by
-- flatBoxPuc without a call).
local RECT_SIDES = {}
for pattern = 1, 8 do
  local rect, right, bottom = pattern <= 4 and 1 or 2, (pattern - 1) % 4 >= 2, (pattern - 1) % 2 == 1
  local vertical, horizontal = right and 3 or 1, bottom and 4 or 2
  local first, second = horizontal, vertical
  if rect == 1 then first, second = vertical, horizontal end
  local third, fourth = (first + 1) % 4 + 1, (second + 1) % 4 + 1
  RECT_SIDES[pattern] = { first, third, second, fourth, third, first, fourth, second }
end

local function rectSides(points, rect, xmin, ymin)
  local pattern = 4 * (rect - 1) + 1
  if points[1] + 0.0 ~= xmin then pattern = pattern + 2 end
  if points[2] + 0.0 ~= ymin then pattern = pattern + 1 end
  return RECT_SIDES[pattern]
end

-- The box of part k (n coordinates) of a list into view.boxes and its record; false when a
-- coordinate is inf or NaN.
local function partBox(view, k, part, n)
  local finite = 0.0
  local xmin, ymin, xmax, ymax = huge, huge, -huge, -huge
  local ixmin, iymin, ixmax, iymax = 1, 2, 1, 2
  for i = 1, n - 1, 2 do
    local x, y = part[i] + 0.0, part[i + 1] + 0.0
    finite = finite + (x * 0 + y * 0)   -- stays 0 unless a coordinate is inf or NaN
    if x < xmin then xmin, ixmin = x, i end
    if x > xmax then xmax, ixmax = x, i end
    if y < ymin then ymin, iymin = y, i + 1 end
    if y > ymax then ymax, iymax = y, i + 1 end
  end
  if n < 6 then xmin, xmax = huge, -huge end   -- fewer than 3 points: never collides
  local boxes, record, b = view.boxes, view.records[k], 4 * k
  boxes[b - 3], boxes[b - 2], boxes[b - 1], boxes[b] = xmin, ymin, xmax, ymax
  record[1], record[2], record[3], record[4] = xmin, ymin, xmax, ymax
  record[5], record[6], record[7], record[8] = ixmin, iymin, ixmax, iymax
  local rect = finite == 0 and rectKind(part, n, xmin, ymin, xmax, ymax) or 0
  view.rects[k] = rect
  record[11] = rect
  if rect ~= 0 then
    view.sides[k] = rectSides(part, rect, xmin, ymin)
    -- A rectangle's first and third vertices are opposite corners: their coordinates are the
    -- four on its box, the ones watched (at constant indices on LuaJIT: see compound.lua's
    -- partsOverlapping)
    local x1, y1 = part[1] + 0.0, part[2] + 0.0
    ixmin, iymin = x1 == xmin and 1 or 5, y1 == ymin and 2 or 6
    record[5], record[6], record[7], record[8] = ixmin, iymin, 6 - ixmin, 8 - iymin
    record[12], record[13], record[14], record[15] = x1, y1, part[5] + 0.0, part[6] + 0.0
  end
  -- PUC Lua's scan: 0 for a rectangle whose first vertex is its (xmin, ymin), and so its third
  -- its (xmax, ymax) (a box as games write it), compared with the box's values it loads anyway
  -- (see compound.lua's partsOverlapping); else the length
  record[16] = rect ~= 0 and ixmin == 1 and iymin == 2 and 0 or n
  return finite == 0
end

-- The area sign of part k (finite coordinates) into view, and returned.
local function partTurn(view, k, part, n)
  local turn = 0.0
  if n >= 6 then
    local sign = areaSign(part, n)
    turn = sign > 0 and 1.0 or sign < 0 and -1.0 or 0.0
  end
  view.turns[k] = turn
  return turn
end

-- The area sign and the edge normals of part k (finite coordinates) into view: unit's numbers.
-- Two bodies, the same numbers (spec/bodies_faces_spec.lua compares them).
-- LuaJIT's: unit's call, which a trace inlines.
local function partNormalsJit(view, k, part, n)
  local turn = partTurn(view, k, part, n)
  if turn == 0 then return end   -- never collides: no normal is read
  local normals = view.normals[k]
  local ax, ay = part[n - 1] + 0.0, part[n] + 0.0
  for i = 1, n - 1, 2 do
    local bx, by = part[i] + 0.0, part[i + 1] + 0.0
    local ux, uy = 0.0, 0.0   -- a repeated vertex gives no edge
    if bx ~= ax or by ~= ay then ux, uy = unit((by - ay) * turn, (ax - bx) * turn) end
    normals[i], normals[i + 1] = ux, uy
    ax, ay = bx, by
  end
end

-- PUC Lua's: unit written out (PUC Lua pays for every call, math.max and abs too), one
-- assignment per statement (Lua 5.4 moves a multiple assignment through a temporary per value).
local function partNormalsPuc(view, k, part, n)
  local turn = partTurn(view, k, part, n)
  if turn == 0 then return end   -- never collides: no normal is read
  local normals = view.normals[k]
  local ax, ay = part[n - 1] + 0.0, part[n] + 0.0
  for i = 1, n - 1, 2 do
    local bx, by = part[i] + 0.0, part[i + 1] + 0.0
    local ux = (by - ay) * turn
    local uy = (ax - bx) * turn
    if uy == 0 and ux ~= 0 then
      -- a vertical edge (a tile's, a box's): what the lines below give, (+-1, uy), uy a
      -- zero of turn's sign, without their division and square root
      normals[i] = ux > 0 and 1.0 or -1.0
      normals[i + 1] = uy
    elseif ux == 0 and uy ~= 0 then   -- a horizontal one
      normals[i] = ux
      normals[i + 1] = uy > 0 and 1.0 or -1.0
    elseif bx ~= ax or by ~= ay then
      local m = uy   -- max(|uy|, |ux|)
      if m < 0 then m = -m end
      local mx = ux
      if mx < 0 then mx = -mx end
      if mx > m then m = mx end
      ux = ux / m
      uy = uy / m
      local len = sqrt(ux * ux + uy * uy)
      normals[i] = ux / len
      normals[i + 1] = uy / len
    else   -- a repeated vertex gives no edge
      normals[i] = 0.0
      normals[i + 1] = 0.0
    end
    ax = bx
    ay = by
  end
end

local partNormals = JIT and partNormalsJit or partNormalsPuc

-- The box around all parts of view and their largest coordinate magnitude, into view.
local function shapeBox(view)
  local magnitude, left, top, right, bottom = 0.0, huge, huge, -huge, -huge
  local boxes = view.boxes
  for b = 4, 4 * view.count, 4 do
    local xmin, ymin, xmax, ymax = boxes[b - 3], boxes[b - 2], boxes[b - 1], boxes[b]
    if xmin <= xmax then   -- parts of fewer than 3 points have none
      magnitude = max(magnitude, -xmin, xmax, -ymin, ymax)
      left, top, right, bottom = min(left, xmin), min(top, ymin), max(right, xmax), max(bottom, ymax)
    end
  end
  view.magnitude, view.left, view.top, view.right, view.bottom = magnitude, left, top, right, bottom
end

-- Builds the preparation of a list of parts, whose parts were checked to be tables of even
-- length (allocates: on first use, or after the number of parts or coordinates changed). A
-- non-finite coordinate raises the argument error at the caller of the public function.
local function prepareParts(fname, argname, parts)
  local count = #parts
  local info = { count = count, lengths = {}, internal = {}, copies = {}, boxes = {}, turns = {},
                 normals = {}, records = {}, checked = {}, rects = {}, sides = {} }
  for k = 1, count do
    local part = parts[k]
    local n = #part
    local copy = {}
    for i = 1, n do copy[i] = part[i] end
    local flags = {}
    for i = 1, n - 1, 2 do flags[i] = 0 end
    info.lengths[k], info.internal[k], info.copies[k], info.normals[k] = n, flags, copy, {}
    info.records[k], info.checked[k] = { 0, 0, 0, 0, 1, 2, 1, 2, part, n, 0, 0, 0, 0, 0, n }, 0
    if not partBox(info, k, part, n) then
      error(("%s: %s holds a non-finite coordinate"):format(fname, argname), 5)
    end
    checkConvex(part, n, fname, ("%s[%d]"):format(argname, k), 5)
    partNormals(info, k, part, n)
  end
  shapeBox(info)
  local edges = {}
  for k = 1, count do
    local part = parts[k]
    local n = #part
    for e = 1, n / 2 do
      local j = e % (n / 2) + 1
      local ax, ay = part[2 * e - 1] + 0.0, part[2 * e] + 0.0
      local bx, by = part[2 * j - 1] + 0.0, part[2 * j] + 0.0
      if ax ~= bx or ay ~= by then
        edges[#edges + 1] = { k = k, e = e, ax = ax, ay = ay, bx = bx, by = by,
                              xmin = min(ax, bx), xmax = max(ax, bx), covers = {} }
      end
    end
  end
  -- sweep over the edges in order of their smallest x: only edges whose x ranges meet can share
  table.sort(edges, function(p, q) return p.xmin < q.xmin end)
  for s = 1, #edges do
    local E = edges[s]
    local t = s + 1
    while edges[t] and edges[t].xmin <= E.xmax do
      local T = edges[t]
      if T.k ~= E.k and cross(E.ax, E.ay, E.bx, E.by, E.ax, E.ay, T.ax, T.ay) == 0
        and cross(E.ax, E.ay, E.bx, E.by, E.ax, E.ay, T.bx, T.by) == 0 then
        local onX = E.ax ~= E.bx   -- then T, on the same line, is not vertical either
        local forwardE = onX and E.bx > E.ax or not onX and E.by > E.ay
        local forwardT = onX and T.bx > T.ax or not onX and T.by > T.ay
        if forwardE ~= forwardT then
          local elo, ehi = edgeSpan(E.ax, E.ay, E.bx, E.by, onX)
          local tlo, thi = edgeSpan(T.ax, T.ay, T.bx, T.by, onX)
          if tlo < ehi and elo < thi then
            E.covers[#E.covers + 1] = { tlo, thi }
            T.covers[#T.covers + 1] = { elo, ehi }
          end
        end
      end
      t = t + 1
    end
  end
  for _, E in ipairs(edges) do
    if #E.covers > 0 then
      local onX = E.ax ~= E.bx
      local lo, hi = edgeSpan(E.ax, E.ay, E.bx, E.by, onX)
      if covered(E.covers, lo, hi) then   -- the edge ends at vertex e % (n / 2) + 1
        local n = info.lengths[E.k]
        info.internal[E.k][2 * (E.e % (n / 2)) + 1] = 1
      end
    end
  end
  preparedParts[parts] = info
  return info
end

-- Checks that every part of a list is a table of even length: the argument errors, raised at
-- the caller of the public function (level 5: it is called by listView).
local function checkList(fname, argname, shape)
  for k = 1, #shape do
    local part = shape[k]
    if type(part) ~= "table" then
      error(("%s: %s[%d] must be a table, got %s"):format(fname, argname, k, type(part)), 5)
    end
    if #part % 2 ~= 0 then
      error(("%s: %s[%d] must hold an even number of coordinates, got %d")
        :format(fname, argname, k, #part), 5)
    end
    for i = 1, #part do
      local v = part[i]
      if type(v) ~= "number" then
        error(("%s: %s[%d][%d] must be a number, got %s; a list of parts holds flat arrays")
          :format(fname, argname, k, i, type(v)), 5)
      end
    end
    if #part < 6 then
      local name = ("%s[%d]"):format(argname, k)
      if #part == 0 and getmetatable(part) ~= nil then
        error(("%s: %s is an object; a list of parts holds flat arrays (pass its .points)")
          :format(fname, name), 5)
      end
      error(fewPointsMessage(fname, name, #part), 5)
    end
  end
end

local call = { stamp = 0 }   -- counts the calls that push: checked[k] == callStamp when compared

-- Brings part k of a prepared list up to date from its present coordinates, in place. Raises the
-- non-finite error at `level` (counted from here, 1).
local function refreshPart(view, k, part, n, level)
  if not partBox(view, k, part, n) then
    view.records[k][9] = false   -- the next call refreshes the part again, and raises again
    error(("%s: %s holds a non-finite coordinate"):format(view.fname, view.argname), level)
  end
  if n >= 6 then checkConvex(part, n, view.fname, ("%s[%d]"):format(view.argname, k), level) end
  partNormals(view, k, part, n)
  local copy = view.copies[k]
  for i = 1, n do copy[i] = part[i] end
end

-- Compares part k of a prepared list with its whole copy, once per call, before its sign and
-- normals are read (see preparedParts); level as in refreshPart, counted from here.
local function checkCopy(view, k, part, level)
  view.checked[k] = call.stamp
  local copy, n = view.copies[k], view.lengths[k]
  if view.rects[k] ~= 0 then
    -- An axis-parallel rectangle: its first and third vertices are the coordinates watched on
    -- its box (partBox), which every call compares before it reads a part (compound.lua's
    -- partsOverlapping, listView): equal to their copies. The other two vertices are compared
    -- here.
    if part[3] == copy[3] and part[4] == copy[4] and part[7] == copy[7] and part[8] == copy[8] then
      return
    end
    refreshPart(view, k, part, n, level + 1)
    return
  end
  if n == 8 then   -- a quadrilateral (a tile, a box) unrolled: constant indices, no loop steps
    if part[1] == copy[1] and part[2] == copy[2] and part[3] == copy[3] and part[4] == copy[4]
        and part[5] == copy[5] and part[6] == copy[6] and part[7] == copy[7] and part[8] == copy[8] then
      return
    end
    refreshPart(view, k, part, n, level + 1)
    return
  end
  for i = 1, n do
    if part[i] ~= copy[i] then
      refreshPart(view, k, part, n, level + 1)
      return
    end
  end
end

-- The view of a list of parts: its preparation, brought up to date (see preparedParts). Raises
-- the argument errors at the caller of the public function (level 4).
local function listView(fname, argname, shape)
  local info = preparedParts[shape]
  if info and info.count == #shape then
    info.fname, info.argname = fname, argname
    local records = info.records
    local changed = false
    for k = 1, info.count do
      local part, record = shape[k], records[k]
      local n = record[10]
      if part ~= record[9] then   -- another table, or a non-finite coordinate before (false)
        if type(part) ~= "table" or #part ~= n then
          changed = nil   -- prepare again (or raise the error)
          break
        end
        record[9], changed = part, true
        refreshPart(info, k, part, n, 5)
      elseif #part ~= n then   -- another length
        changed = nil
        break
      elseif n >= 6 and (part[record[5]] ~= record[1] or part[record[6]] ~= record[2]
          or part[record[7]] ~= record[3] or part[record[8]] ~= record[4]) then
        changed = true
        refreshPart(info, k, part, n, 5)
      end
    end
    if changed ~= nil then
      if changed then shapeBox(info) end
      return info
    end
  end
  checkList(fname, argname, shape)
  info = prepareParts(fname, argname, shape)
  info.fname, info.argname = fname, argname
  return info
end

-- The two views of flat arrays (one per argument), refilled on every call. `pending`: the area
-- sign and normals are still to compute (only a push on overlapping boxes needs them);
-- `turnPending`: the area sign is (a boolean on overlapping boxes needs only that). No edge
-- of a flat array is internal: internal[1] holds 0 at vertex indices 1 .. edgeRoom, grown when a
-- larger array comes (once, never shrunk).
local function newFlatView()
  return { count = 1, lengths = {}, internal = { {} }, edgeRoom = 0, boxes = {},
           turns = {}, normals = { {} }, rects = { 0 }, sides = { {} }, pending = false,
           turnPending = false }
end
local flatView1, flatView2 = newFlatView(), newFlatView()

-- The box of a flat array (n coordinates) into view as part k = 1, as partBox gives it but
-- without the record (the extremes' indices, which only a list's parts keep), and whether every
-- coordinate is finite; for an axis-parallel rectangle its kind, sides and area sign too.
-- Two bodies, the same numbers (spec/bodies_faces_spec.lua compares them).
-- LuaJIT's: min and max four vertices a round, the last round padded with the last vertex (as
-- leastProjectionJit, for the same reason: a branch on every vertex is a side exit); flatView
-- then calls shapeBox.
local function flatBoxJit(view, _, shape, n)
  local finite = 0.0
  local xmin, ymin, xmax, ymax = huge, huge, -huge, -huge
  local last = n - 1
  for i = 1, last, 8 do
    local i2, i3, i4 = min(i + 2, last), min(i + 4, last), min(i + 6, last)
    local x1, y1, x2, y2 = shape[i] + 0.0, shape[i + 1] + 0.0, shape[i2] + 0.0, shape[i2 + 1] + 0.0
    local x3, y3, x4, y4 = shape[i3] + 0.0, shape[i3 + 1] + 0.0, shape[i4] + 0.0, shape[i4 + 1] + 0.0
    -- stays 0 unless a coordinate is inf or NaN
    finite = finite + ((x1 * 0 + y1 * 0) + (x2 * 0 + y2 * 0) + (x3 * 0 + y3 * 0) + (x4 * 0 + y4 * 0))
    xmin, xmax = min(xmin, x1, x2, x3, x4), max(xmax, x1, x2, x3, x4)
    ymin, ymax = min(ymin, y1, y2, y3, y4), max(ymax, y1, y2, y3, y4)
  end
  if n < 6 then xmin, xmax = huge, -huge end   -- fewer than 3 points: never collides
  local boxes = view.boxes
  boxes[1], boxes[2], boxes[3], boxes[4] = xmin, ymin, xmax, ymax
  -- an axis-parallel rectangle: its sides and its area sign (see flatBoxPuc)
  local rect = finite == 0 and rectKind(shape, n, xmin, ymin, xmax, ymax) or 0
  view.rects[1] = rect
  if rect ~= 0 then
    view.sides[1] = rectSides(shape, rect, xmin, ymin)
    local x1, y1 = shape[1] + 0.0, shape[2] + 0.0
    if rect == 1 then
      view.turns[1] = (shape[3] + 0.0 > x1) == (shape[6] + 0.0 > y1) and 1.0 or -1.0
    else
      view.turns[1] = (shape[5] + 0.0 > x1) == (shape[4] + 0.0 > y1) and -1.0 or 1.0
    end
  end
  return finite == 0
end

-- PUC Lua's: partBox's loop, and shapeBox's numbers for the one part, without their calls. One
-- function, not split into steps: it runs on every call with a flat array, where PUC Lua pays
-- for every call.
local function flatBoxPuc(view, _, shape, n)
  local finite, rect = 0.0, 0
  local xmin, ymin, xmax, ymax
  if n == 8 then
    -- A quadrilateral (a crate, a tile) unrolled: the loop's numbers (the least of equals is
    -- the first, as there), and whether it is an axis-parallel rectangle, what rectKind and
    -- rectSides give, from the same locals. An axis-parallel rectangle first: its x are v1's
    -- and the opposite corner's (each equal to one of them, NaN never is), its y too, so two
    -- comparisons give its box, and it is finite when its box is; the other shapes (and a
    -- rectangle of no width or height, or with an infinite side) by eight coordinates' sums
    -- and twelve comparisons (a crate, the common case, takes far fewer instructions so than
    -- with those first: bench/NOTES.md). Its area sign from comparisons: twice its
    -- area is 2 (x2 - x1) (y3 - y1) for kind 1, -2 (x3 - x1) (y2 - y1) for kind 2, each
    -- factor's sign flipped when the opposite corner lies left of or above v1 (flatView then
    -- computes no area sign).
    local x1, y1, x2, y2 = shape[1] + 0.0, shape[2] + 0.0, shape[3] + 0.0, shape[4] + 0.0
    local x3, y3, x4, y4 = shape[5] + 0.0, shape[6] + 0.0, shape[7] + 0.0, shape[8] + 0.0
    if x4 == x1 and y1 == y2 and x2 == x3 and y3 == y4 then
      rect = 1
    elseif y4 == y1 and x1 == x2 and y2 == y3 and x3 == x4 then
      rect = 2
    end
    if rect ~= 0 then
      local xa, ya, turn = x2, y3, 1.0   -- the corner opposite v1
      if rect == 2 then
        xa = x3
        ya = y2
        turn = -1.0
      end
      local pattern = 4 * rect - 3   -- as rectSides
      xmin = x1
      xmax = xa
      if xa < x1 then
        xmin = xa
        xmax = x1
        pattern = pattern + 2
        turn = -turn
      end
      ymin = y1
      ymax = ya
      if ya < y1 then
        ymin = ya
        ymax = y1
        pattern = pattern + 1
        turn = -turn
      end
      local big = huge
      if xmin < xmax and ymin < ymax and -big < xmin and xmax < big and -big < ymin and ymax < big then
        view.turns[1] = turn
        view.sides[1] = RECT_SIDES[pattern]
      else
        rect = 0
      end
    end
    if rect == 0 then
      -- 0 unless a coordinate is inf or NaN (x - x is NaN then)
      finite = (x1 - x1) + (y1 - y1) + (x2 - x2) + (y2 - y2) + (x3 - x3) + (y3 - y3)
        + (x4 - x4) + (y4 - y4)
      xmin = x1
      xmax = x1
      if x2 < xmin then xmin = x2 end
      if x2 > xmax then xmax = x2 end
      if x3 < xmin then xmin = x3 end
      if x3 > xmax then xmax = x3 end
      if x4 < xmin then xmin = x4 end
      if x4 > xmax then xmax = x4 end
      ymin = y1
      ymax = y1
      if y2 < ymin then ymin = y2 end
      if y2 > ymax then ymax = y2 end
      if y3 < ymin then ymin = y3 end
      if y3 > ymax then ymax = y3 end
      if y4 < ymin then ymin = y4 end
      if y4 > ymax then ymax = y4 end
    end
  else
    xmin, ymin, xmax, ymax = huge, huge, -huge, -huge
    for i = 1, n - 1, 2 do
      local x, y = shape[i] + 0.0, shape[i + 1] + 0.0
      finite = finite + (x * 0 + y * 0)   -- stays 0 unless a coordinate is inf or NaN
      if x < xmin then xmin = x end
      if x > xmax then xmax = x end
      if y < ymin then ymin = y end
      if y > ymax then ymax = y end
    end
    if n < 6 then xmin, xmax = huge, -huge end   -- fewer than 3 points: never collides
  end
  view.rects[1] = rect
  local boxes = view.boxes   -- one assignment per statement: see partNormalsPuc
  boxes[1] = xmin
  boxes[2] = ymin
  boxes[3] = xmax
  boxes[4] = ymax
  local magnitude = 0.0
  if xmin <= xmax then   -- as shapeBox: max(0, -xmin, xmax, -ymin, ymax), the first of equals
    if -xmin > magnitude then magnitude = -xmin end
    if xmax > magnitude then magnitude = xmax end
    if -ymin > magnitude then magnitude = -ymin end
    if ymax > magnitude then magnitude = ymax end
  else
    xmin, ymin, xmax, ymax = huge, huge, -huge, -huge
  end
  view.magnitude = magnitude
  view.left = xmin
  view.top = ymin
  view.right = xmax
  view.bottom = ymax
  return finite == 0
end

local flatBox = JIT and flatBoxJit or flatBoxPuc

-- Fills `view` for the flat array shape and returns it; or nil and the argument error's message
-- (the caller raises it: after a list's errors, when the list is the first argument).
local function flatView(fname, argname, shape, view)
  if type(shape) ~= "table" then
    return nil, ("%s: %s must be a table, got %s"):format(fname, argname, type(shape))
  end
  local n = #shape
  if n % 2 ~= 0 then
    return nil, ("%s: %s must hold an even number of coordinates, got %d"):format(fname, argname, n)
  end
  if not flatBox(view, 1, shape, n) then
    return nil, ("%s: %s holds a non-finite coordinate"):format(fname, argname)
  end
  if n > view.edgeRoom then
    local flags = view.internal[1]
    for i = view.edgeRoom + 1, n do flags[i] = 0 end
    view.edgeRoom = n
  end
  view.lengths[1], view.pending, view.turnPending = n, true, view.rects[1] == 0
  if JIT then shapeBox(view) end   -- PUC Lua: flatBoxPuc did
  return view
end

M.call = call
M.checkCopy = checkCopy
M.partTurn = partTurn
M.partNormals = partNormals
M.flatView = flatView
-- both bodies of each pair, for spec/bodies_faces_spec.lua only (and shapeBox, which follows
-- flatBoxJit in flatView)
M.flatBoxJit = flatBoxJit
M.flatBoxPuc = flatBoxPuc
M.partNormalsJit = partNormalsJit
M.partNormalsPuc = partNormalsPuc
M.shapeBox = shapeBox
M.flatView2 = flatView2
M.flatView1 = flatView1
M.preparedParts = preparedParts
M.listView = listView
M.isParts = isParts

return M
