-- polygon/compound.lua: collisions where either shape is a list of convex parts: which pairs to
-- test, the exact boolean, the push (through faces), and a circle against a list.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local faces = require(_PACKAGE .. ".faces")
local views = require(_PACKAGE .. ".views")
local check = require(_PACKAGE .. ".check")
local circle = require(_PACKAGE .. ".circle")

local abs, sqrt, huge, min, max = math.abs, math.sqrt, math.huge, math.min, math.max
local JIT, EXACT_TOP, powerScale = kernel.JIT, kernel.EXACT_TOP, kernel.powerScale
local twoDiff = kernel.twoDiff
local nearParts, overlapping, pairPart1 = faces.nearParts, faces.overlapping, faces.pairPart1
local pairPart2, overlapsConvex = faces.pairPart2, faces.overlapsConvex
local pairOverlaps, boxPush, pairAdded = faces.pairOverlaps, faces.boxPush, faces.pairAdded
local exactSidePush = faces.exactSidePush
local startSearch, addPair, nearestFree = faces.startSearch, faces.addPair, faces.nearestFree
local pushFree, faceX, faceY, faceC = faces.pushFree, faces.faceX, faces.faceY, faces.faceC
local faceSeam, faceFirst = faces.faceSeam, faces.faceFirst
local flatView, flatView2, flatView1 = views.flatView, views.flatView2, views.flatView1
local preparedParts, listView, call = views.preparedParts, views.listView, views.call
local checkCopy = views.checkCopy
local checkFiniteNumber = check.checkFiniteNumber
local circleCollision = circle.circleCollision

local M = {}

-- Overlap. Two shapes overlap when some part of one overlaps some part of the other, each pair
-- decided exactly (touching is not colliding) after a bounding-box test per pair.
--
-- The push. Moving the second shape by t makes part A of the first and part B of the second
-- overlap exactly when t lies inside D = A - B = {a - b}, a convex polygon with one edge per edge
-- of A and of B. An edge of A from vertex a, with outward unit normal u, bounds D by the open
-- half-plane u.t < c, c = -min over the vertices v of B of u.(v - a) (how far B reaches past the
-- edge); an edge of B from b, outward normal u, by -u.t < c, c = -min over the vertices w of A
-- of u.(w - b). The least push is the point nearest the origin that lies in no open D (over all
-- pairs of parts). That point is on the boundary of the union of the D, so on an edge of one D:
-- inside that edge it is the foot of the perpendicular from the origin to the edge's line, else
-- it is the end of a piece of the edge, where the edge's line crosses another (of the same D, a
-- corner, or of another D, where two D cross). So the candidates are the feet and the crossings,
-- and the push is the nearest candidate outside every D: the true least translation, up to the
-- margin below. Feet need not be tried on an edge shared with another part of the same shape
-- (internal, see preparedParts): such a foot, if on the edge, has the neighbouring part
-- overlapping (the other part reaches on past the shared edge, as a half-disc around every point
-- inside it) and so is never free; off the edge it is on another line, found there. Crossings use
-- every line, as an end of an internal edge can be a corner of the union.
--
-- Which pairs. D lies in the box [A's box - B's box]. The pairs whose boxes overlap (D holds the
-- origin) come first. The nearest point t free among them is the least push of all when it lies
-- outside every other D too, as more pairs can only take free points away; so a pair is added
-- only when its box of D comes within 4 delta of t on every side, and the nearest free point
-- is sought again, round after round. Against a flat shape only the parts in a window around
-- it are visited for that while |t| is at most half the window: the others' boxes of D lie
-- farther than a window from the origin.
--
-- Which feet and crossings. The feet are tried nearest first (the nearest and the second
-- nearest are kept as the faces are made), as the nearest free foot is the first free one in
-- the order of reach, then of faces; a crossing is no nearer than either of its lines, so
-- crossings are sought only among the lines nearer than the best so far, and not at all when
-- only one can be (every outer edge's line at least as far as the best, and every internal
-- one). So on a floor the push usually costs the faces of the pairs and one or two freeness
-- checks.
--
-- Rectangles. Every D of two axis-parallel rectangles is a box: a flat one against a list of
-- them (a crate on tiles) takes boxPush, this search on the boxes' lines without faces; and such
-- a pair is free at t when the moved rectangle, rounded as a game moves it, does not overlap the
-- other, tested exactly (pushFree), so a push may leave them touching (an exact fit in a slot).
--
-- Margin: one push separates. The faces are computed in floating point and the moved vertices
-- are rounded, so a candidate must lie outside every D widened by delta, and feet and crossings
-- are taken on the lines moved out by lift = 1.25 delta (a quarter of delta covers their own
-- rounding, a few eps E). With E the width plus the height of the box around both shapes and S
-- their largest coordinate magnitude, every D lies in the box of D's, within 1.5 E of the origin,
-- so every |v - a| <= E, every push |t| < 1.5 E (a point farther out is free), and the moved
-- coordinates stay below S + 1.5 E. Errors of the quantities the test u.t >= c + delta compares,
-- in eps: the unit normal from rounded differences (eps each, then unit's 3) turns by at most
-- 5 eps, moving u.(v - a) by 5 E and u.t by 7.5 E; the projection rounds by 3 E; the test's own
-- sums and products by 3 (1.5 E + E) = 7.5 E: 23 E in all, below 64 E, so a candidate found
-- outside the widened D is in truth at distance 41 eps E or more from D: part B moved by it
-- exactly keeps that distance from A. Rounding moves each of its coordinates by at most
-- eps (S + 1.5 E), each vertex by 1.42 eps (S + 1.5 E), so the rounded part (the hull of the
-- rounded vertices) lies within that of the exact one: still apart when 41 eps E + 2 eps S, the
-- rest of delta = 64 eps E + 2 eps S, exceeds 1.42 eps (S + 1.5 E). So no pair of parts collides
-- after the rounded move: one push separates. The push exceeds the least translation by about
-- lift (80 eps E + 2.5 eps S) on a face, lift / sin(angle / 2) at a crossing of lines meeting at
-- an angle. Coordinates beyond 2^500 or below 2^-400 are scaled by a power of two k first
-- (exact), so no product overflows or underflows.

-- The parts of a prepared list whose boxes overlap the box x0, y0, x1, y1 (strictly), in order,
-- into overlapping, and those whose boxes overlap it grown by `window` on every side into
-- nearParts; returns both numbers and, over the parts in nearParts but not in overlapping, the
-- least of the largest box gaps along x of those whose largest gap is along x, and the same
-- along y (or huge; see collideParts). First sees whether some part changed,
-- as listView does (its table, its length, the coordinates on its box: see preparedParts), and
-- then returns nil at once: the same checks in the same loop as the box tests, which read the
-- same boxes (after listView they pass: the list is up to date).
-- Two bodies: on LuaJIT the box tests by the largest gap, one branch a part; on PUC Lua by
-- comparisons, most parts failing the first or second.

-- partsOverlapping for LuaJIT: the changes sought by array borders (#part is a call there), the
-- box tests by the largest gap.
local function partsOverlappingJit(info, shape, x0, y0, x1, y1, window)
  local found, near, leastGapX, leastGapY = 0, 0, huge, huge
  local records = info.records
  for k = 1, info.count do
    local part, record = shape[k], records[k]
    local xmin, ymin, xmax, ymax = record[1], record[2], record[3], record[4]
    if part ~= record[9] then return nil end
    if record[16] == 0 then
      -- a rectangle from its (xmin, ymin): as below, against the box's values loaded (fewer
      -- machine instructions than reading record[12] .. [15])
      if part[1] ~= xmin or part[2] ~= ymin or part[5] ~= xmax or part[6] ~= ymax
          or part[9] ~= nil or part[8] == nil then
        return nil
      end
    elseif record[11] ~= 0 then
      -- an axis-parallel rectangle (rectKind): the coordinates of its first and third
      -- vertices, the four watched (see partBox), read at constant indices, not through the
      -- indices kept (a conversion and a bounds check each), and its length 8
      if part[1] ~= record[12] or part[2] ~= record[13] or part[5] ~= record[14]
          or part[6] ~= record[15] or part[9] ~= nil or part[8] == nil then
        return nil
      end
    else
      local n = record[10]
      if n >= 6 then
        -- the length as a border, part[n] set and part[n + 1] not, the same for an array
        -- without holes: #part is a call on LuaJIT, across which every live number goes to
        -- memory
        if part[n + 1] ~= nil or part[n] == nil or part[record[5]] ~= xmin
            or part[record[6]] ~= ymin or part[record[7]] ~= xmax or part[record[8]] ~= ymax then
          return nil
        end
      elseif #part ~= n then
        return nil
      end
    end
    -- the largest gap between the boxes (< 0 when they overlap: a - b < 0 exactly when a < b,
    -- no NaN), by max: one branch for most parts (PUC Lua's tests: four, each a side exit)
    local gapX, gapY = max(xmin - x1, x0 - xmax), max(ymin - y1, y0 - ymax)
    local gap = max(gapX, gapY)
    if gap < window then
      near = near + 1
      nearParts[near] = k
      if gap < 0 then
        found = found + 1
        overlapping[found] = k
      elseif gapX >= gapY then
        leastGapX = min(leastGapX, gapX)
      else
        leastGapY = min(leastGapY, gapY)
      end
    end
  end
  return found, near, leastGapX, leastGapY
end

-- partsOverlapping for PUC Lua: the changes sought by #part, the box tests by comparisons.
local function partsOverlappingPuc(info, shape, x0, y0, x1, y1, window)
  local found, near, leastGapX, leastGapY = 0, 0, huge, huge
  local wx0, wy0, wx1, wy1 = x0 - window, y0 - window, x1 + window, y1 + window
  local records = info.records
  for k = 1, info.count do
    local part, record = shape[k], records[k]
    local xmin, ymin, xmax, ymax = record[1], record[2], record[3], record[4]
    local n = record[16]   -- 0 for a rectangle from its (xmin, ymin), else the length
    if part ~= record[9] then return nil end
    if n == 0 then
      -- its watched coordinates at constant indices, against the box's values loaded: two VM
      -- instructions each, where the indices kept take three
      if #part ~= 8 or part[1] ~= xmin or part[2] ~= ymin or part[5] ~= xmax or part[6] ~= ymax then
        return nil
      end
    elseif #part ~= n or n >= 6 and (part[record[5]] ~= xmin or part[record[6]] ~= ymin
        or part[record[7]] ~= xmax or part[record[8]] ~= ymax) then
      return nil
    end
    if xmin < wx1 and wx0 < xmax and ymin < wy1 and wy0 < ymax then
      near = near + 1
      nearParts[near] = k
      if xmin < x1 and x0 < xmax and ymin < y1 and y0 < ymax then
        found = found + 1
        overlapping[found] = k
      else   -- the largest gaps, as on LuaJIT (the same differences)
        local gapX, gapY = xmin - x1, ymin - y1
        if x0 - xmax > gapX then gapX = x0 - xmax end
        if y0 - ymax > gapY then gapY = y0 - ymax end
        if gapX >= gapY then
          if gapX < leastGapX then leastGapX = gapX end
        elseif gapY < leastGapY then
          leastGapY = gapY
        end
      end
    end
  end
  return found, near, leastGapX, leastGapY
end

local partsOverlapping = JIT and partsOverlappingJit or partsOverlappingPuc

-- Whether some pair 1 .. np overlaps, decided exactly (on LuaJIT, after addPair found none that
-- overlaps for sure): as the boolean decides each pair.
local function pairsOverlap(fname, view1, shape1, view2, shape2, np, scaled)
  for p = 1, np do
    local i, j = pairPart1[p], pairPart2[p]
    local p1 = view1.copies and shape1[i] or shape1
    local p2 = view2.copies and shape2[j] or shape2
    if scaled then
      if overlapsConvex(fname, p1, p2) then return true end
    elseif pairOverlaps(view1, p1, i, view2, p2, j) then
      return true
    end
  end
  return false
end

-- The compound cases of the public functions: whether shape1 and shape2 (flat arrays or lists
-- of parts: parts1, parts2, as isParts tells, which the public functions did inline) overlap,
-- or with wantPush the least translation of shape2 out of shape1 as overlap, dx, dy, or false.
-- Its steps: the views (a list against a flat shape scanned by partsOverlapping), the boolean,
-- the scaling, the pairs whose boxes overlap, then rounds of pairs near the best free point.
-- It stays whole: the functions it calls raise argument errors at levels counted from its
-- frame (listView's and overlapsConvex's 4, addPair's checkCopy 5, its own checkCopy 4), so a
-- step moved into a function of its own would put those errors on the wrong line; and the
-- rounds share a dozen numbers with the steps before them (np, top, k, margin, the window).
local function collideParts(fname, shape1, shape2, wantPush, parts1, parts2)
  local view1, view2, found, nearCount, window, leastGapX, leastGapY
  if parts1 ~= parts2 then
    -- A list against a flat shape: the list's checks and its parts' box tests in one loop
    -- (partsOverlapping), so the flat shape's box first, its argument errors raised after the
    -- list's when the list comes first, as below.
    local list, flat, listName, flatName = shape1, shape2, "points1", "points2"
    if parts2 then list, flat, listName, flatName = shape2, shape1, "points2", "points1" end
    local flatSide, message = flatView(fname, flatName, flat, parts1 and flatView2 or flatView1)
    if not flatSide and parts2 then error(message, 3) end
    local info = preparedParts[list]
    local boxes = flatSide and flatSide.boxes
    -- the window for the pairs the search may add later: the flat shape's width plus height
    -- (pushes are mostly shorter than half that: see the loop after the search)
    window = flatSide and wantPush and (boxes[3] - boxes[1]) + (boxes[4] - boxes[2]) or 0
    if flatSide and info and info.count == #list then
      found, nearCount, leastGapX, leastGapY =
        partsOverlapping(info, list, boxes[1], boxes[2], boxes[3], boxes[4], window)
    end
    if found then
      info.fname, info.argname = fname, listName
    else
      info = listView(fname, listName, list)
      if not flatSide then error(message, 3) end
      found, nearCount, leastGapX, leastGapY =
        partsOverlapping(info, list, boxes[1], boxes[2], boxes[3], boxes[4], window)
    end
    if parts1 then view1, view2 = info, flatSide else view1, view2 = flatSide, info end
  else
    local message
    if parts1 then view1 = listView(fname, "points1", shape1)
    else
      view1, message = flatView(fname, "points1", shape1, flatView1)
      if not view1 then error(message, 3) end
    end
    if parts2 then view2 = listView(fname, "points2", shape2)
    else
      view2, message = flatView(fname, "points2", shape2, flatView2)
      if not view2 then error(message, 3) end
    end
  end
  local count1, count2 = view1.count, view2.count
  local boxes1, boxes2 = view1.boxes, view2.boxes
  local magnitude = max(view1.magnitude, view2.magnitude)
  call.stamp = call.stamp + 1
  local callStamp = call.stamp
  if not wantPush then
    -- Each pair as addPair decides it, from the prepared normals (no faces); beyond the exact
    -- range, where the push scales (below), by the SAT engine, which rescales itself.
    local scaled = magnitude > EXACT_TOP or magnitude < 2^-400
    if found then   -- a list against a flat shape: the parts whose boxes overlap its box
      local list, flat = view2, view1
      if parts1 then list, flat = view1, view2 end
      local flatRect = flat.rects[1] ~= 0
      for f = 1, found do
        local k = overlapping[f]
        local i, j, p1, p2 = 1, k, shape1, shape2[k]
        if parts1 then i, j, p1, p2 = k, 1, shape1[k], shape2 end
        -- two axis-parallel rectangles are their boxes: boxes that overlap (strictly, as
        -- partsOverlapping tests them) are rectangles that overlap (the part's whole copy
        -- compared first, as for any pair: see preparedParts)
        if flatRect then
          if list.checked[k] ~= callStamp then checkCopy(list, k, parts1 and p1 or p2, 4) end
          if list.rects[k] ~= 0 then return true end
        end
        if scaled then
          if overlapsConvex(fname, p1, p2) then return true end
        elseif pairOverlaps(view1, p1, i, view2, p2, j) then
          return true
        end
      end
      return false
    end
    local i, j = 1, 0
    for _ = 1, count1 * count2 do   -- one loop over the pairs: see below
      if j == count2 then i, j = i + 1, 1 else j = j + 1 end
      local a, b = 4 * i, 4 * j
      if boxes1[a - 3] < boxes2[b - 1] and boxes2[b - 3] < boxes1[a - 1]
          and boxes1[a - 2] < boxes2[b] and boxes2[b - 2] < boxes1[a] then
        local p1, p2 = parts1 and shape1[i] or shape1, parts2 and shape2[j] or shape2
        if scaled then
          if overlapsConvex(fname, p1, p2) then return true end
        elseif pairOverlaps(view1, p1, i, view2, p2, j) then
          return true
        end
      end
    end
    return false
  end
  -- beyond the exact range, or so small that products would underflow, the faces are built on
  -- coordinates scaled by a power of two k into [2^100, 2^164]: there every product of two
  -- stays far from overflow (2^328) and underflow, and scaling back is exact
  local k = 1.0
  if magnitude > EXACT_TOP or magnitude < 2^-400 then k = powerScale(magnitude, 2^100, 2^164) end
  local extent = ((max(view1.right, view2.right) - min(view1.left, view2.left))
    + (max(view1.bottom, view2.bottom) - min(view1.top, view2.top))) * k
  local margin = 2^-47 * extent + 2^-52 * magnitude * k   -- delta above: 64 eps E + 2 eps S
  if found and found > 0 and k == 1 then
    local flat = parts1 and view2 or view1
    if flat.rects[1] ~= 0 then
      local best, tx, ty = boxPush(parts1 and view1 or view2, parts1 and shape1 or shape2, flat,
        parts1, found, nearCount, leastGapX, leastGapY, margin, window)
      if best then return exactSidePush(found, best, tx, ty, 1.25 * margin, margin) end
    end
  end
  -- The pairs whose boxes overlap go in now, marked in pairAdded; the others when their box of D
  -- comes near the best free point (below). A pair is numbered (i - 1) count2 + j; against a
  -- flat shape, by the list's part. One loop over the pairs, not two nested (on LuaJIT an inner
  -- loop of one part, as for a flat second shape, costs a trace exit for every part of the
  -- first).
  local np, top, hits = 0, 0, 0
  local added = pairAdded   -- a local: PUC Lua reads an upvalue by an extra instruction
  startSearch(1.25 * margin)   -- as nearestFree's lift
  if found then
    for f = 1, found do
      local part = overlapping[f]
      added[part] = callStamp
      local overlaps
      if parts1 then
        np, top, overlaps = addPair(view1, shape1[part], part, view2, shape2, 1, k, np, top)
      else
        np, top, overlaps = addPair(view1, shape1, 1, view2, shape2[part], part, k, np, top)
      end
      hits = hits + overlaps
    end
  else
    local i, j = 1, 0
    for pair = 1, count1 * count2 do
      if j == count2 then i, j = i + 1, 1 else j = j + 1 end
      local a, b = 4 * i, 4 * j
      if boxes1[a - 3] < boxes2[b - 1] and boxes2[b - 3] < boxes1[a - 1]
          and boxes1[a - 2] < boxes2[b] and boxes2[b - 2] < boxes1[a] then
        added[pair] = callStamp
        local overlaps
        np, top, overlaps = addPair(view1, parts1 and shape1[i] or shape1, i, view2,
          parts2 and shape2[j] or shape2, j, k, np, top)
        hits = hits + overlaps
      end
    end
  end
  local scaled = k ~= 1   -- as the boolean's (powerScale's k is never 1 there)
  if hits == 0 and not (JIT and pairsOverlap(fname, view1, shape1, view2, shape2, np, scaled)) then
    return false
  end
  local best, tx, ty = nearestFree(np, margin)
  local near = 4 * margin   -- a box of D this far from t cannot hold it, widened by delta
  while true do
    -- every pair not in yet whose box of D comes within near of t (on every side; when no point
    -- is free yet, every pair whose parts have boxes) goes in
    local before = np
    local anyBox = best == huge
    if found then
      -- the list's part against the flat shape's box; the box of D is that of part - flat for a
      -- list first, of flat - part for a list second: the same tests on -t (exact negations)
      -- Only the parts near the flat shape (in nearParts) when t and near are at most half the
      -- window: a part outside it lies a window or more away along x or y, so its box of D
      -- lies farther than 2 (|t| + near) from the origin, more than near from t (the rounding
      -- errors of these sums are a few eps of the coordinates, below near).
      local listBoxes, fb = boxes1, boxes2
      local sx, sy = tx, ty
      if parts2 then listBoxes, fb, sx, sy = boxes2, boxes1, -tx, -ty end
      local fx0, fy0, fx1, fy1 = fb[1], fb[2], fb[3], fb[4]
      local reachX, reachY = sx < 0 and -sx or sx, sy < 0 and -sy or sy
      local reach = reachX
      if reachY > reach then reach = reachY end
      local useNear = not anyBox and 2 * (reach + near) <= window * k
      local last = useNear and nearCount or (parts1 and count1 or count2)
      -- None of the near parts when each one not in has its largest box gap g (the list's
      -- part's side less the flat shape's far side, as the tests below compute it), along x say,
      -- at least leastGapX, and leastGapX k - |sx| >= near: then g k - |sx| >= near fails the
      -- test on that side (the roundings are monotonic, and fl(a - b) = -fl(b - a)).
      if useNear and leastGapX * k - reachX >= near and leastGapY * k - reachY >= near then
        last = 0
      end
      for q = 1, last do
        local part = useNear and nearParts[q] or q
        local a = 4 * part
        if (anyBox and listBoxes[a - 3] <= listBoxes[a - 1]
            or (listBoxes[a - 3] - fx1) * k - sx < near and sx - (listBoxes[a - 1] - fx0) * k < near
            and (listBoxes[a - 2] - fy1) * k - sy < near and sy - (listBoxes[a] - fy0) * k < near)
            and added[part] ~= callStamp then
          added[part] = callStamp
          if parts1 then
            np, top = addPair(view1, shape1[part], part, view2, shape2, 1, k, np, top)
          else
            np, top = addPair(view1, shape1, 1, view2, shape2[part], part, k, np, top)
          end
        end
      end
    else
      local i, j = 1, 0
      for pair = 1, count1 * count2 do
        if j == count2 then i, j = i + 1, 1 else j = j + 1 end
        local a, b = 4 * i, 4 * j
        -- how far t lies beyond the box of D on each side, all four below near (an empty box,
        -- of huge minus any coordinate, never is)
        if (anyBox and boxes1[a - 3] <= boxes1[a - 1] and boxes2[b - 3] <= boxes2[b - 1]
            or (boxes1[a - 3] - boxes2[b - 1]) * k - tx < near
            and tx - (boxes1[a - 1] - boxes2[b - 3]) * k < near
            and (boxes1[a - 2] - boxes2[b]) * k - ty < near
            and ty - (boxes1[a] - boxes2[b - 2]) * k < near)
            and added[pair] ~= callStamp then
          added[pair] = callStamp
          np, top = addPair(view1, parts1 and shape1[i] or shape1, i, view2,
            parts2 and shape2[j] or shape2, j, k, np, top)
        end
      end
    end
    if np == before then break end
    -- If the best point is still free among the pairs added, it stays (see "Which pairs").
    if best == huge or not pushFree(tx, ty, np, margin) then best, tx, ty = nearestFree(np, margin) end
  end
  if best == huge then
    -- No candidate checked free (not expected): 2 E along any direction clears every D.
    best, tx, ty = 2 * extent, faceX[1] * 2 * extent, faceY[1] * 2 * extent
  elseif k == 1 then
    best, tx, ty = exactSidePush(np, best, tx, ty, 1.25 * margin, margin)
  end
  return best / k, tx / k + 0.0, ty / k + 0.0
end

-- Circles. A circle (c, r) whose centre moves by t meets part A exactly when c + t lies within
-- r of A: t inside D = (A - c) grown by r, a convex shape bounded by the edges' lines moved out
-- by r and arcs of radius r around the vertices. The least push is again the point nearest the
-- origin outside every D. On the boundary of the union it is the foot of the perpendicular on
-- a moved edge line, or the point of an arc nearest the origin (straight away from a vertex),
-- or a crossing of two of those pieces: line and line, line and arc, arc and arc. Each candidate
-- is kept when it is farther than r + delta from every part (the same margins as above, with
-- the circle's box in E and S), and the nearest kept one is the push.

local faceAX, faceAY, faceBX, faceBY = {}, {}, {}, {}   -- edge ends relative to the centre
local faceQ = {}                                        -- |faceAX, faceAY|: the vertex's distance

-- Appends the edges of part (normals: its outward unit normals, from its view) as faces relative
-- to the centre (cx, cy), all scaled by k: the outward unit normal, the signed distance faceC of
-- the edge's line from the centre (u.t - faceC is how far t lies beyond it) and the edge's ends.
-- Returns the last index.
local function addCircleFaces(part, n, normals, internal, cx, cy, k, top)
  local ax, ay = part[n - 1] + 0.0, part[n] + 0.0
  local kcx, kcy = cx * k, cy * k
  for i = 1, n - 1, 2 do
    local bx, by = part[i] + 0.0, part[i + 1] + 0.0
    if bx ~= ax or by ~= ay then   -- a repeated vertex gives no edge
      local ux, uy = normals[i], normals[i + 1]
      local qax, qay = ax * k - kcx, ay * k - kcy
      top = top + 1
      faceX[top], faceY[top], faceC[top] = ux, uy, ux * qax + uy * qay
      faceAX[top], faceAY[top], faceBX[top], faceBY[top] = qax, qay, bx * k - kcx, by * k - kcy
      faceQ[top] = sqrt(qax * qax + qay * qay)
      faceSeam[top] = internal[i]
    end
    ax, ay = bx, by
  end
  return top
end

-- Whether t lies at least `need` from the part whose faces are first .. last.
local function farFromPart(tx, ty, first, last, need)
  local beyond = -huge
  for f = first, last do beyond = max(beyond, faceX[f] * tx + faceY[f] * ty - faceC[f]) end
  if beyond >= need then return true end
  if beyond <= 0 then return false end   -- inside the part
  -- outside: the nearest point lies on an edge whose line t is beyond
  local needSq = need * need
  for f = first, last do
    if faceX[f] * tx + faceY[f] * ty - faceC[f] > 0 then
      local ax, ay = faceAX[f], faceAY[f]
      local ex, ey = faceBX[f] - ax, faceBY[f] - ay
      local along = ((tx - ax) * ex + (ty - ay) * ey) / (ex * ex + ey * ey)
      if along < 0 then along = 0 elseif along > 1 then along = 1 end
      local dx, dy = tx - (ax + along * ex), ty - (ay + along * ey)
      if dx * dx + dy * dy < needSq then return false end
    end
  end
  return true
end

-- Whether t lies at least need from every part 1 .. np.
local function circleFree(tx, ty, np, need)
  for p = 1, np do
    if not farFromPart(tx, ty, faceFirst[p], faceFirst[p + 1] - 1, need) then return false end
  end
  return true
end

-- Keeps candidate t when it is nearer than best and free.
local function tryCircle(tx, ty, np, need, best, bestX, bestY)
  local d = sqrt(tx * tx + ty * ty)
  if d < best and circleFree(tx, ty, np, need) then return d, tx, ty end
  return best, bestX, bestY
end

-- A push of a circle along an axis, the depth itself (as exactSidePush for rectangles): the
-- search's push is the foot on a part's side lifted by `lift`, c + r + lift with c the side's
-- coordinate less the centre's (a convex part's side along an axis lies on its box). When c and
-- c + r are exact and the circle moved by c + r (the centre rounded as a game moves it) meets
-- no part by the exact test, the push is c + r: a ball 5 into a wall of rectangles goes out by
-- 5. The largest such push among the parts whose lifted side is the push (any order gives it).
local function exactCirclePush(shape, view, cx, cy, r, best, tx, ty, lift)
  if (tx ~= 0) == (ty ~= 0) then return best, tx, ty end
  local boxes, turns, found = view.boxes, view.turns, -huge
  local reach = r + lift
  for i = 1, view.count do
    local a = 4 * i
    if turns[i] ~= 0 and boxes[a - 3] <= boxes[a - 1] then
      local c, err
      if tx > 0 then c, err = twoDiff(boxes[a - 1], cx)
      elseif tx < 0 then c, err = twoDiff(cx, boxes[a - 3])
      elseif ty > 0 then c, err = twoDiff(boxes[a], cy)
      else c, err = twoDiff(cy, boxes[a - 2]) end
      local d, err2 = twoDiff(c, -r)   -- c + r
      if err == 0 and err2 == 0 and d > found and c + reach == best then found = d end
    end
  end
  if found <= 0 then return best, tx, ty end
  local dx = tx > 0 and found or (tx < 0 and -found or 0.0)
  local dy = ty > 0 and found or (ty < 0 and -found or 0.0)
  local mx, my = cx + dx, cy + dy   -- the centre moved as a game moves it
  for i = 1, view.count do
    local a = 4 * i
    -- the box tests widened past their own rounding by lift
    if turns[i] ~= 0 and boxes[a - 3] < mx + reach and mx - reach < boxes[a - 1]
        and boxes[a - 2] < my + reach and my - reach < boxes[a]
        and circleCollision(shape[i], #shape[i], mx, my, r) then
      return best, tx, ty
    end
  end
  return found, dx, dy
end

-- The nearest free candidate for a circle of (scaled) radius r among parts 1 .. np.
local function nearestFreeCircle(np, r, margin)
  local best, bestX, bestY = huge, 0.0, 0.0
  local last = faceFirst[np + 1] - 1
  local reach, need = r + 1.25 * margin, r + margin   -- lines and arcs moved out by lift
  for f = 1, last do   -- feet on the outer edges' moved lines
    local d = faceC[f] + reach
    if faceSeam[f] == 0 and abs(d) < best then
      best, bestX, bestY = tryCircle(faceX[f] * d, faceY[f] * d, np, need, best, bestX, bestY)
    end
  end
  for f = 1, last do   -- straight away from each vertex (the start of each edge)
    local q = faceQ[f]
    if q > 0 and abs(q - reach) < best then
      local s = 1 - reach / q
      best, bestX, bestY = tryCircle(faceAX[f] * s, faceAY[f] * s, np, need, best, bestX, bestY)
    end
  end
  -- Crossings. A point on a line lies at least |its constant| from the origin, one on an arc at
  -- least |q - reach|: pieces no nearer than the best so far are skipped.
  for f = 1, last do
    local c1, x1, y1 = faceC[f] + reach, faceX[f], faceY[f]
    local qx, qy = faceAX[f], faceAY[f]
    local lineNear, arcNear = abs(c1) < best, abs(faceQ[f] - reach) < best
    if lineNear or arcNear then
      for g = 1, last do
        local c2 = faceC[g] + reach
        if lineNear and g > f and abs(c2) < best then   -- line and line
          local x2, y2 = faceX[g], faceY[g]
          local det = x1 * y2 - y1 * x2
          if det ~= 0 then
            best, bestX, bestY = tryCircle((c1 * y2 - c2 * y1) / det, (x1 * c2 - x2 * c1) / det,
              np, need, best, bestX, bestY)
          end
        end
        local px, py = faceAX[g], faceAY[g]
        if abs(faceQ[g] - reach) < best then
          if lineNear then   -- line f and the arc around vertex g
            local h = c1 - (x1 * px + y1 * py)   -- from the vertex to the line, along the normal
            if abs(h) < reach then
              local w = sqrt(reach * reach - h * h)
              local mx, my = px + x1 * h, py + y1 * h
              best, bestX, bestY = tryCircle(mx - y1 * w, my + x1 * w, np, need, best, bestX, bestY)
              best, bestX, bestY = tryCircle(mx + y1 * w, my - x1 * w, np, need, best, bestX, bestY)
            end
          end
          if arcNear and g > f then   -- the arcs around vertices f and g
            local ex, ey = px - qx, py - qy
            local gap = sqrt(ex * ex + ey * ey)
            if gap > 0 and gap < 2 * reach then
              local w = sqrt(reach * reach - gap * gap / 4) / gap
              local mx, my = (qx + px) / 2, (qy + py) / 2
              best, bestX, bestY = tryCircle(mx - ey * w, my + ex * w, np, need, best, bestX, bestY)
              best, bestX, bestY = tryCircle(mx + ey * w, my - ex * w, np, need, best, bestX, bestY)
            end
          end
        end
      end
    end
  end
  return best, bestX, bestY
end

local circleAdded = {}   -- circleAdded[i] == callStamp: part i's faces are in

-- polygonCircleCollideV for a list of parts: overlap, dx, dy (move the circle) or false.
local function collideCircleParts(fname, shape, cx, cy, r)
  checkFiniteNumber(cx, fname, "cx", 4)
  checkFiniteNumber(cy, fname, "cy", 4)
  checkFiniteNumber(r, fname, "radius", 4)
  if r < 0 then error(("%s: radius must not be negative, got %s"):format(fname, tostring(r)), 3) end
  local view = listView(fname, "points", shape)
  local count, turns, normals, internal = view.count, view.turns, view.normals, view.internal
  local left, top, right, bottom = view.left, view.top, view.right, view.bottom
  local boxes = view.boxes
  cx, cy, r = cx + 0.0, cy + 0.0, r + 0.0
  if r == 0 then return false end
  local magnitude = max(view.magnitude, abs(cx) + r, abs(cy) + r)
  call.stamp = call.stamp + 1
  local callStamp = call.stamp
  local k = 1.0   -- scaled as for polygons (collideParts), for the same reason
  if magnitude > EXACT_TOP or magnitude < 2^-400 then k = powerScale(magnitude, 2^100, 2^164) end
  local extent = ((max(right, cx + r) - min(left, cx - r)) + (max(bottom, cy + r) - min(top, cy - r))) * k
  local margin = 2^-47 * extent + 2^-52 * magnitude * k   -- as for polygons: 64 eps E + 2 eps S
  local np, last, hit = 0, 0, false
  for i = 1, count do
    if boxes[4 * i - 3] < cx + r and cx - r < boxes[4 * i - 1]
        and boxes[4 * i - 2] < cy + r and cy - r < boxes[4 * i] then
      local part = shape[i]
      local n = #part
      if view.checked[i] ~= callStamp then checkCopy(view, i, part, 4) end
      if turns[i] ~= 0 then
        if circleCollision(part, n, cx, cy, r) then hit = true end
        np = np + 1
        faceFirst[np] = last + 1
        last = addCircleFaces(part, n, normals[i], internal[i], cx, cy, k, last)
        faceFirst[np + 1] = last + 1
      end
    end
  end
  if not hit then return false end
  -- The other parts go in when their box of D (the part's box less the centre, grown by r) comes
  -- within 4 delta of the best free point, round after round, as for polygons ("Which pairs"):
  -- farther, its part is more than r + delta from the moved centre.
  local best, tx, ty = nearestFreeCircle(np, r * k, margin)
  local near = 4 * margin
  while true do
    local before = np
    for i = 1, count do
      local a = 4 * i
      if boxes[a - 3] <= boxes[a - 1] and circleAdded[i] ~= callStamp
          and not (boxes[a - 3] < cx + r and cx - r < boxes[a - 1]
                   and boxes[a - 2] < cy + r and cy - r < boxes[a]) then
        -- how far t lies beyond the box of D, along x and along y (< 0 inside)
        local outX = max((boxes[a - 3] - cx - r) * k - tx, tx - (boxes[a - 1] - cx + r) * k)
        local outY = max((boxes[a - 2] - cy - r) * k - ty, ty - (boxes[a] - cy + r) * k)
        if best == huge or max(outX, outY) < near then
          circleAdded[i] = callStamp
          if view.checked[i] ~= callStamp then checkCopy(view, i, shape[i], 4) end
          if turns[i] ~= 0 then
            np = np + 1
            faceFirst[np] = last + 1
            last = addCircleFaces(shape[i], #shape[i], normals[i], internal[i], cx, cy, k, last)
            faceFirst[np + 1] = last + 1
          end
        end
      end
    end
    if np == before then break end
    -- More parts can only lengthen the least move: if the best point is still free, it stays.
    if best == huge or not circleFree(tx, ty, np, r * k + margin) then
      best, tx, ty = nearestFreeCircle(np, r * k, margin)
    end
  end
  if best == huge then
    -- No candidate checked free (not expected): 2 E along any direction clears every D.
    best, tx, ty = 2 * extent, 0.0, -2 * extent
  elseif k == 1 then
    best, tx, ty = exactCirclePush(shape, view, cx, cy, r, best, tx, ty, 1.25 * margin)
  end
  return best / k, tx / k + 0.0, ty / k + 0.0
end

M.collideParts = collideParts
M.collideCircleParts = collideCircleParts
M.partsOverlappingJit = partsOverlappingJit   -- both bodies, for spec/bodies_compound_spec.lua
M.partsOverlappingPuc = partsOverlappingPuc

return M
