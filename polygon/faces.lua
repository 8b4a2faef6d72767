-- polygon/faces.lua: the push search over lists of convex parts: the half-planes (faces) of
-- each pair of parts, the nearest free foot or crossing among them, and the faster search for
-- axis-parallel rectangles. Relies on kernel, sat and views.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local sat = require(_PACKAGE .. ".sat")
local kernel = require(_PACKAGE .. ".kernel")
local views = require(_PACKAGE .. ".views")

local abs, sqrt, huge, min, max = math.abs, math.sqrt, math.huge, math.min, math.max
local convexPenetration, minProjection = sat.convexPenetration, sat.minProjection
local projectionTolerance, vertexInside = sat.projectionTolerance, sat.vertexInside
local isAbove, reachBoth, squaredTolerance = sat.isAbove, sat.reachBoth, sat.squaredTolerance
local JIT, EPS = kernel.JIT, kernel.EPS
local twoDiff = kernel.twoDiff
local call, checkCopy, partTurn = views.call, views.checkCopy, views.partTurn
local partNormals = views.partNormals

local M = {}


-- Scratch space reused by every call (grown once, never shrunk): no garbage per frame.
local faceX, faceY, faceC = {}, {}, {}   -- the half-planes faceX tx + faceY ty < faceC
local faceSeam = {}                -- 1 for a face from an internal edge (no foot on it), else 0
local faceReach = {}               -- |faceC + lift|: how near the origin the face's lifted line passes
local faceFirst = {}               -- pair p owns faces faceFirst[p] .. faceFirst[p + 1] - 1
local pairAdded = {}               -- per pair of parts i, j (at (i - 1) count2 + j): call.stamp once in
local pairPart1, pairPart2 = {}, {}   -- pair p's parts i and j (LuaJIT: compound.lua's pairsOverlap)
-- pairBox[p] is 1 when pair p is two axis-parallel rectangles (rectPairFaces, boxPush), else 0;
-- then pairRects holds their boxes at 8p - 7 .. 8p: xmin, ymin, xmax, ymax of the first shape's
-- part, then of the second's, the one a push moves (pushFree)
local pairBox, pairRects = {}, {}

-- Whether two convex parts overlap (exact), by the SAT engine. A non-finite coordinate the
-- checks of the views did not see (one off the box of a list's part) raises the argument error
-- at the caller of the public function (level 4).
local function overlapsConvex(fname, p1, p2)
  local depth, argname = convexPenetration(p1, #p1, p2, #p2, true)
  if depth == nil then error(("%s: %s holds a non-finite coordinate"):format(fname, argname), 4) end
  return depth ~= false
end

-- The least projection nx (vx - ax) + ny (vy - ay) over the vertices of points. Two bodies,
-- the same number (spec/bodies_faces_spec.lua compares them).
-- LuaJIT's: eight vertices a round, the last round padded with the last vertex (a repeat cannot
-- change the least), so that a part of up to eight vertices takes no loop: a loop that never
-- runs twice is compiled into its caller's trace, where minProjection's loop is a trace of its
-- own, entered and left once per edge.
local function leastProjectionJit(points, n, ax, ay, nx, ny)
  local lo, last = huge, n - 1
  for i = 1, last, 16 do
    local i2, i3, i4 = min(i + 2, last), min(i + 4, last), min(i + 6, last)
    local i5, i6, i7, i8 = min(i + 8, last), min(i + 10, last), min(i + 12, last), min(i + 14, last)
    lo = min(lo, nx * (points[i] - ax) + ny * (points[i + 1] - ay),
      nx * (points[i2] - ax) + ny * (points[i2 + 1] - ay),
      nx * (points[i3] - ax) + ny * (points[i3 + 1] - ay),
      nx * (points[i4] - ax) + ny * (points[i4 + 1] - ay),
      nx * (points[i5] - ax) + ny * (points[i5 + 1] - ay),
      nx * (points[i6] - ax) + ny * (points[i6 + 1] - ay),
      nx * (points[i7] - ax) + ny * (points[i7 + 1] - ay),
      nx * (points[i8] - ax) + ny * (points[i8 + 1] - ay))
  end
  return lo
end

-- PUC Lua's: sat's minProjection.
local leastProjectionPuc = minProjection

local leastProjection = JIT and leastProjectionJit or leastProjectionPuc

-- Whether the edge a -> b of a part (turn its area sign, (ux, uy) its outward normal, unit or
-- not) separates the part from `other`, whose least projection on (ux, uy) from a is lo:
-- decided exactly, by cross's sign where projectionTolerance cannot vouch.
local function edgeSeparates(lo, ax, ay, bx, by, turn, ux, uy, other, no, spanX, spanY)
  local tol = projectionTolerance(spanX, spanY, ux, uy)
  return -lo <= tol and (-lo < -tol or not vertexInside(ax, ay, bx, by, ax, ay, turn, other, no))
end

local faceLift = 0.0   -- lift (see nearestFree) of the call under way, for faceReach
-- The faces with the nearest and the second nearest foot so far (first in face order among
-- equals), their reaches, and the nearest reach of an internal edge's face: kept by addFaces.
-- FAR stands for none: finite (keepFeet multiplies it by 0) and beyond every reach (every
-- coordinate is below 2^501, or scaled below 2^165).
local FAR = 2^1000
-- Over the pairs so far, the largest of each pair's least fc + lift (as faceReach has it, before
-- its abs): a point nearer the origin than this less 0.75 margin lies inside that pair's D
-- widened by margin, so pushFree would find it not free (see nearestFree). -FAR for none.
local leastFree = -FAR
local nearestFoot, nearestReach, secondFoot, secondReach, seamReach = 0, FAR, 0, FAR, FAR
-- rectPairFacesPuc keeps its internal faces' nearest reach apart, by line direction:
-- seamX for the vertical lines (normal (+-1, 0)), seamY for the horizontal ones (see
-- nearestFree); LuaJIT's keepFeet every internal face's whose normal is one of those
local seamX, seamY = FAR, FAR
local feetKept = 0   -- LuaJIT: the faces 1 .. feetKept are in the five above (see keepFeet)

-- Starts a push's search: no feet kept and no pair added yet; lift is nearestFree's.
local function startSearch(lift)
  faceLift = lift
  nearestFoot, nearestReach, secondFoot, secondReach, seamReach = 0, FAR, 0, FAR, FAR
  seamX, seamY, feetKept, leastFree = FAR, FAR, 0, -FAR
end

-- Keeps the nearest feet and the nearest internal faces among faces first .. last, in order, as
-- nearestFoot and the rest describe, and as pairFacesPuc does with branches: here without one
-- (for LuaJIT's bodies: addFaces' faces, rectPairFacesJit's). Each choice is a factor 0 or 1
-- (isAbove), and a sum of products by them is exactly the value chosen (every value finite:
-- FAR, not huge). An internal face whose unit normal is (+-1, 0) or (0, +-1) (one component a
-- zero) goes into seamX or seamY, as rectPairFacesPuc keeps a rectangle pair's, whatever pair
-- it is from: the early end of nearestFree needs only that the lines it counts there be
-- parallel, so that no two of them cross (their det is a zero; a crate at a seam of a floor
-- of boxes: its neighbours' vertical internal faces, kept with the others, would send it into
-- the crossing search).
local function keepFeet(first, last)
  local foot, footReach, foot2, foot2Reach = nearestFoot, nearestReach, secondFoot, secondReach
  local seamLeast, seamLeastX, seamLeastY = seamReach, seamX, seamY
  for f = first, last do
    local d, seam = faceReach[f], faceSeam[f]
    -- an outer face's reach, FAR for an internal one (d + FAR rounds to FAR), which is never
    -- nearer: the reaches kept are the least and the second least of these, by min and max
    -- (the same numbers as choosing them)
    local outerReach = d + seam * FAR
    -- an outer face nearer than the nearest foot, else nearer than the second
    local nearer = isAbove(footReach - outerReach)
    local second = (1 - nearer) * isAbove(foot2Reach - outerReach)
    foot2 = nearer * foot + second * f + (1 - nearer - second) * foot2
    foot2Reach = min(foot2Reach, max(footReach, outerReach))
    foot, footReach = nearer * f + (1 - nearer) * foot, min(footReach, outerReach)
    -- an internal face's reach, FAR for an outer one; apart by direction: 1 for a vertical
    -- line (its normal's y a zero), for a horizontal one
    local seamD = d + (1 - seam) * FAR
    local vertical, horizontal = 1 - isAbove(abs(faceY[f])), 1 - isAbove(abs(faceX[f]))
    seamLeastX = min(seamLeastX, seamD + (1 - vertical) * FAR)
    seamLeastY = min(seamLeastY, seamD + (1 - horizontal) * FAR)
    seamLeast = min(seamLeast, seamD + (vertical + horizontal) * FAR)
  end
  nearestFoot, nearestReach, secondFoot, secondReach = foot, footReach, foot2, foot2Reach
  seamReach, seamX, seamY = seamLeast, seamLeastX, seamLeastY
end

-- Appends to the face arrays, from index top + 1, the half-planes of D that the edges of one
-- part give (normals its outward unit normals; sense 1 for a part of the first shape, -1 for
-- one of the second, whose outward normal points the other way in t), with `other` the part it
-- is paired with, and each face's reach (see nearestFree). Coordinates are scaled by k (spanX,
-- spanY bound the scaled coordinate differences, for projectionTolerance). Returns the last
-- index used, `sure` (below) and the largest lo.
-- LuaJIT's (pairFacesJit's, once a part; pairFacesPuc gives the same faces), in two loops
-- without a branch that goes both ways (on LuaJIT such a branch is a side exit whose side trace
-- may fail to compile, "NYI: register coalescing too complex"): the faces, with the projections
-- by leastProjection, here, and the nearest feet, by keepFeet over all new faces at once when
-- nearestFree needs them. The face loop runs a constant 8 steps for parts of up to 8 vertices
-- (a repeated vertex, as the last one read again is, adds no face, without a branch): a loop
-- counting a part's vertices has a side exit for every other part size. Instead of whether
-- some edge separates the parts it returns `sure`, 1 when none can (then they overlap for
-- sure), else 0: compound.lua's collideParts decides those pairs exactly when it needs to
-- (pairsOverlap).
local function addFaces(edges, ne, normals, other, no, internal, sense, k, spanX, spanY, top)
  local fx, fy, fc, seam, reach = faceX, faceY, faceC, faceSeam, faceReach
  local lift, highest = faceLift, -huge   -- highest: the largest lo
  local ax, ay = edges[ne - 1] + 0.0, edges[ne] + 0.0
  -- up to 8 vertices a constant count, the last vertex again past the last (see sat.lua's
  -- faceAndFar)
  local last = ne <= 16 and 15 or ne - 1
  for i = 1, last, 2 do
    local l = min(i, ne - 1)
    local bx, by = edges[l] + 0.0, edges[l + 1] + 0.0
    -- 1 for an edge, 0 for a repeated vertex, which gives none (its normal is (0, 0)): its
    -- face is written past top, and left there
    local edge = isAbove(abs(bx - ax) + abs(by - ay))
    local ux, uy = normals[l], normals[l + 1]
    local lo
    if k ~= 1 then   -- scaled: the same numbers as unscaled where k is 1
      lo = huge
      local kax, kay = ax * k, ay * k
      for j = 1, no - 1, 2 do
        lo = min(lo, ux * (other[j] * k - kax) + uy * (other[j + 1] * k - kay))
      end
    else
      lo = leastProjection(other, no, ax, ay, ux, uy)
    end
    highest = max(highest, lo - (1 - edge) * FAR)
    local slot = top + 1
    fx[slot], fy[slot], fc[slot] = ux * sense, uy * sense, -lo
    seam[slot], reach[slot] = internal[l], abs(lift - lo)
    top = top + edge
    ax, ay = bx, by
  end
  -- projectionTolerance's bound for any unit normal (|ux|, |uy| <= 1; rounding is monotonic):
  -- an edge whose -lo exceeds it cannot separate; 1 when every edge's does (no NaN: a
  -- difference is > 0 exactly when its first term is the larger)
  return top, isAbove(-(16 * EPS * (spanX + spanY)) - highest), highest
end

-- LuaJIT's faces of a pair of which one part is an axis-parallel rectangle (rectKind, unscaled)
-- and the other not: addFaces' faces, the same numbers, each edge's least projection taken from
-- the other part's box x0, y0, x1, y1 instead of its vertices, min(ux (x0 - ax), ux (x1 - ax))
-- + min(uy (y0 - ay), uy (y1 - ay)): four products where leastProjection takes eight. The same
-- number because rounding is monotonic: fl(fl(ux (x - ax)) + fl(uy (y - ay))) is least at the
-- corner whose terms are least, and every corner is a vertex of the other part when it is the
-- rectangle (its vertices are its box's corners), while against a part that is not, the
-- rectangle's own edges have normals (+-1, +-0), whose projection of a vertex is +-(x - ax) (or
-- +-(y - ay)) up to a zero's sign, least at the box's side. The loop as addFaces' (constant 8
-- steps up to 8 vertices).
local function addBoxFaces(edges, ne, normals, x0, y0, x1, y1, internal, sense, spanX, spanY, top)
  local fx, fy, fc, seam, reach = faceX, faceY, faceC, faceSeam, faceReach
  local lift, highest = faceLift, -huge   -- highest: the largest lo
  local ax, ay = edges[ne - 1] + 0.0, edges[ne] + 0.0
  local last = ne <= 8 and 7 or ne <= 16 and 15 or ne - 1
  for i = 1, last, 2 do
    local l = min(i, ne - 1)
    local bx, by = edges[l] + 0.0, edges[l + 1] + 0.0
    local edge = isAbove(abs(bx - ax) + abs(by - ay))   -- as in addFaces
    local ux, uy = normals[l], normals[l + 1]
    local lo = min(ux * (x0 - ax), ux * (x1 - ax)) + min(uy * (y0 - ay), uy * (y1 - ay))
    highest = max(highest, lo - (1 - edge) * FAR)
    local slot = top + 1
    fx[slot], fy[slot], fc[slot] = ux * sense, uy * sense, -lo
    seam[slot], reach[slot] = internal[l], abs(lift - lo)
    top = top + edge
    ax, ay = bx, by
  end
  return top, isAbove(-(16 * EPS * (spanX + spanY)) - highest), highest
end

-- LuaJIT's faces of part i of view, an axis-parallel rectangle (rectKind), against a part that
-- is not, whose box is at boxes[b - 3 .. b]: addFaces' faces, without a loop, the rectangle's
-- sides in the order of its edges (sides[i]), each side's constant the other box's far side
-- less the rectangle's own, the same numbers as rectPairFaces' (a side's normal (+-1, 0) or
-- (0, +-1): its projections are the coordinates' differences, least at the box's side, exactly
-- as addBoxFaces computes them, up to zeros' signs, which change no comparison and no push).
-- (SIDE_X, SIDE_Y: the outward normals of the sides left, top, right, bottom, as rectSides
-- numbers them)
local SIDE_X, SIDE_Y = { -1.0, 0.0, 1.0, 0.0 }, { 0.0, -1.0, 0.0, 1.0 }
local rectC = { 0.0, 0.0, 0.0, 0.0 }
local function rectFaces(view, i, boxes, b, sense, spanX, spanY, top)
  local sides, internal, own, a = view.sides[i], view.internal[i], view.boxes, 4 * i
  local cLeft, cTop = boxes[b - 1] - own[a - 3], boxes[b] - own[a - 2]
  local cRight, cBottom = own[a - 1] - boxes[b - 3], own[a] - boxes[b - 2]
  local c = rectC
  c[1], c[2], c[3], c[4] = cLeft, cTop, cRight, cBottom
  local fx, fy, fc, seam, reach = faceX, faceY, faceC, faceSeam, faceReach
  local lift = faceLift
  local line = sides[1]
  fx[top + 1], fy[top + 1], fc[top + 1], seam[top + 1], reach[top + 1] = SIDE_X[line] * sense,
    SIDE_Y[line] * sense, c[line], internal[1], abs(lift + c[line])
  line = sides[3]
  fx[top + 2], fy[top + 2], fc[top + 2], seam[top + 2], reach[top + 2] = SIDE_X[line] * sense,
    SIDE_Y[line] * sense, c[line], internal[3], abs(lift + c[line])
  line = sides[5]
  fx[top + 3], fy[top + 3], fc[top + 3], seam[top + 3], reach[top + 3] = SIDE_X[line] * sense,
    SIDE_Y[line] * sense, c[line], internal[5], abs(lift + c[line])
  line = sides[7]
  fx[top + 4], fy[top + 4], fc[top + 4], seam[top + 4], reach[top + 4] = SIDE_X[line] * sense,
    SIDE_Y[line] * sense, c[line], internal[7], abs(lift + c[line])
  -- addFaces' 1 when no side can separate: every lo = -c below -16 eps (spanX + spanY); and
  -- the largest lo
  local least = min(cLeft, cTop, cRight, cBottom)
  return top + 4, isAbove(least - 16 * EPS * (spanX + spanY)), -least
end

-- The faces of both parts of a pair: addFaces' for p1 (sense 1) and then for p2 (sense -1), 1
-- when the parts overlap, else 0, and the largest lo. Two bodies, the same faces (up to zeros'
-- signs, which change no comparison and no push; spec/bodies_faces_spec.lua compares them).
-- LuaJIT's: addFaces twice; its 1 means overlap for sure, 0 also when the parts may not (see
-- addFaces); the nearest feet kept later, by keepFeet.
local function pairFacesJit(p1, n1, _, normals1, internal1, p2, n2, _, normals2, internal2,
                            k, spanX, spanY, top)
  local sure1, sure2, highest1, highest2
  top, sure1, highest1 = addFaces(p1, n1, normals1, p2, n2, internal1, 1.0, k, spanX, spanY, top)
  top, sure2, highest2 = addFaces(p2, n2, normals2, p1, n1, internal2, -1.0, k, spanX, spanY, top)
  return top, sure1 * sure2, max(highest1, highest2)
end

-- PUC Lua's: overlap decided exactly, the nearest feet kept as the faces are written; one call
-- for both parts (a call's arguments and set-up cost on PUC Lua), minProjection's loop inline,
-- unrolled for a quadrilateral, an axis-parallel rectangle's faces from the boxes. One function,
-- not split into steps: it runs for every pair of parts a push tests, where PUC Lua pays for
-- every call.
local function pairFacesPuc(p1, n1, turn1, normals1, internal1, p2, n2, turn2, normals2,
                            internal2, k, spanX, spanY, top, boxes1, a, boxes2, b, rect1, rect2)
  local separated, highest = false, -huge   -- highest: the largest lo
  local fx, fy, fc, seam, reach = faceX, faceY, faceC, faceSeam, faceReach
  local lift, foot, footReach = faceLift, nearestFoot, nearestReach
  local foot2, foot2Reach = secondFoot, secondReach
  local scaled = k ~= 1
  -- lo < loBound, -lo > 16 eps (spanX + spanY), projectionTolerance's bound for any unit
  -- normal (|ux|, |uy| <= 1; rounding is monotonic): the edge cannot separate
  local loBound = -(16 * EPS * (spanX + spanY))
  -- p1's edges against p2's vertices, then p2's against p1's (one assignment per statement:
  -- Lua 5.4 moves a multiple assignment through a temporary per value)
  local edges, ne, turn, normals, internal, other, no, sense =
    p1, n1, turn1, normals1, internal1, p2, n2, 1.0
  local ownBoxes, e, otherBoxes, o, rect = boxes1, a, boxes2, b, rect1
  local otherRect = rect2
  for side = 1, 2 do
    if side == 2 then
      edges = p2
      ne = n2
      turn = turn2
      normals = normals2
      internal = internal2
      other = p1
      no = n1
      sense = -1.0
      ownBoxes = boxes2
      e = b
      otherBoxes = boxes1
      o = a
      rect = rect2
      otherRect = rect1
    end
    local quad = no == 8
    -- the other part's box (exact: its least and greatest coordinates, as floats)
    local oxmin, oymin = otherBoxes[o - 3], otherBoxes[o - 2]
    local oxmax, oymax = otherBoxes[o - 1], otherBoxes[o]
    -- An axis-parallel rectangle (see rectKind): its faces without reading its vertices or
    -- normals. Each side's least projection is the axis-parallel edge's below (the same
    -- number); its edges alternate between vertical and horizontal sides (a vertical one
    -- first for rect 1), the first vertical one at v1's x, the first horizontal one at v1's y.
    local vertical, loX, loX2, nx, loY, loY2, ny = rect == 1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    if scaled then
      rect = 0
    elseif rect ~= 0 then
      local exmin, eymin = ownBoxes[e - 3], ownBoxes[e - 2]
      loX = exmin - oxmax   -- the left side's (outward normal (-1, 0)), then the right's
      loX2 = oxmin - ownBoxes[e - 1]
      nx = -1.0
      if edges[1] + 0.0 ~= exmin then
        loX2 = loX
        loX = oxmin - ownBoxes[e - 1]
        nx = 1.0
      end
      loY = eymin - oymax   -- the top side's (outward normal (0, -1)), then the bottom's
      loY2 = oymin - ownBoxes[e]
      ny = -1.0
      if edges[2] + 0.0 ~= eymin then
        loY2 = loY
        loY = oymin - ownBoxes[e]
        ny = 1.0
      end
    end
    local ax, ay = edges[ne - 1] + 0.0, edges[ne] + 0.0
    for i = 1, ne - 1, 2 do
      local ux, uy, lo
      if rect ~= 0 then
        if vertical then
          ux = nx
          uy = 0.0
          lo = loX
          nx = -nx   -- the next vertical side is the opposite one
          loX = loX2
        else
          ux = 0.0
          uy = ny
          lo = loY
          ny = -ny
          loY = loY2
        end
        vertical = not vertical
        -- the side separates exactly when the other part lies beyond it or on its line
        if lo >= 0 then separated = true end
      else
        local bx, by = edges[i] + 0.0, edges[i + 1] + 0.0
        if bx ~= ax or by ~= ay then   -- a repeated vertex gives no edge
          ux = normals[i]
          uy = normals[i + 1]
          if scaled then   -- the same numbers as unscaled where k is 1
            lo = huge
            local kax, kay = ax * k, ay * k
            for j = 1, no - 1, 2 do
              local s = ux * (other[j] * k - kax) + uy * (other[j + 1] * k - kay)
              if s < lo then lo = s end
            end
          elseif uy == 0 then
            -- An axis-parallel edge (a tile's, a box's): its unit normal is exactly (1, 0) or
            -- (-1, 0) up to the zero's sign (unit's scaling), so each projection is
            -- +-(vx - ax) up to the sign of a zero, and rounding is monotonic: the least is
            -- the other part's box side less ax, the same number minProjection gives (a
            -- zero's sign aside, which nothing after reads: lo only meets sums with lift and
            -- margin, both > 0, and comparisons), by one subtraction instead of a projection
            -- a vertex.
            if ux > 0 then lo = oxmin - ax else lo = ax - oxmax end
          elseif ux == 0 then   -- the same along y
            if uy > 0 then lo = oymin - ay else lo = ay - oymax end
          elseif otherRect ~= 0 then
            -- The other part is an axis-parallel rectangle: its vertices are its box's
            -- corners, and rounding is monotonic, so the least of the projections
            -- fl(fl(ux (x - ax)) + fl(uy (y - ay))) is the corner's whose terms are least, x
            -- its least for ux >= 0, its greatest else (for ux a zero either term is a zero),
            -- and y the same: the number minProjection gives, by two products where the
            -- quadrilateral's below take eight
            local sx = oxmin - ax
            if ux < 0 then sx = oxmax - ax end
            local sy = oymin - ay
            if uy < 0 then sy = oymax - ay end
            lo = ux * sx + uy * sy
          elseif quad then
            -- a quadrilateral: minProjection's loop unrolled, the same numbers (the first s
            -- is finite, so lo = s is what s < huge gives): constant indices and no loop
            -- steps
            lo = ux * (other[1] - ax) + uy * (other[2] - ay)
            local s = ux * (other[3] - ax) + uy * (other[4] - ay)
            if s < lo then lo = s end
            s = ux * (other[5] - ax) + uy * (other[6] - ay)
            if s < lo then lo = s end
            s = ux * (other[7] - ax) + uy * (other[8] - ay)
            if s < lo then lo = s end
          else   -- minProjection's loop, without the call's instructions
            lo = huge
            for j = 1, no - 1, 2 do
              local s = ux * (other[j] - ax) + uy * (other[j + 1] - ay)
              if s < lo then lo = s end
            end
          end
          if not separated and lo >= loBound then
            separated = edgeSeparates(lo, ax, ay, bx, by, turn, ux, uy, other, no, spanX, spanY)
          end
        end
        ax = bx
        ay = by
      end
      if lo then
        if lo > highest then highest = lo end
        top = top + 1
        fx[top], fy[top], fc[top] = ux * sense, uy * sense, -lo
        local flag, d = internal[i], lift - lo
        if d < 0 then d = -d end   -- a comparison, not abs's call
        seam[top], reach[top] = flag, d
        if flag ~= 0 then
          if d < seamReach then seamReach = d end
        elseif d < footReach then
          foot, footReach, foot2, foot2Reach = top, d, foot, footReach
        elseif d < foot2Reach then
          foot2, foot2Reach = top, d
        end
      end
    end
  end
  nearestFoot, nearestReach, secondFoot, secondReach = foot, footReach, foot2, foot2Reach
  if separated then return top, 0, highest end
  return top, 1, highest
end

local pairFaces = JIT and pairFacesJit or pairFacesPuc

-- Two axis-parallel rectangles (rectKind, unscaled), part i of view1 (p1) and part j of view2
-- (p2), as pair p: the faces pairFacesPuc gives, less those that change nothing. D is then a box:
-- each side of p2 gives the line of the opposite side of p1, the same numbers (lo of p1's right
-- side, oxmin - exmax, is lo of p2's left side, ax - oxmax, with the same roles). A later face
-- equal to an earlier one, line and flag (seam or outer), decides nothing: pushFree's test is
-- the same, it is never nearer than its twin, which comes first (feet and crossings keep the
-- first of equals), and the crossings it gives are its twin's (the same point: (c1 y2 - c2 y1)
-- / det with the lines swapped is the same number). So a side of p2 gives a face only when its
-- flag differs from that of p1's side on its line (a seam of the list against the flat shape's
-- outer edge, whose foot is tried). The views' sides give the sides in edge order (see
-- rectSides). Returns the last face's index and 1 when the rectangles overlap (exactly: no side
-- has the other rectangle beyond it or on its line), else 0. Two bodies, the same faces and
-- answers (spec/bodies_faces_spec.lua compares them).
local sideConstant, sideFlag = { 0.0, 0.0, 0.0, 0.0 }, { 0, 0, 0, 0 }

-- The face of the side `line` (rectSides' numbers, constant sideConstant[line]), flag its seam
-- flag, written at index top (rectPairFacesJit's).
local function putSide(line, flag, top)
  local c = sideConstant[line]
  faceX[top], faceY[top], faceC[top], faceSeam[top], faceReach[top] = SIDE_X[line],
    SIDE_Y[line], c, flag, abs(faceLift + c)
end

-- LuaJIT's: rectPairFacesPuc's faces, without a branch: each of p2's sides is written after
-- p1's and kept (top moves on) when its flag differs from that of p1's side on its line, by the
-- difference's abs, 1 or 0; the nearest feet kept later by keepFeet, as for addFaces' faces;
-- without a loop (a loop of four steps is a trace of its own, entered and left twice a pair).
local function rectPairFacesJit(view1, i, view2, j, top, p)
  local sides1, internal1, boxes1, a = view1.sides[i], view1.internal[i], view1.boxes, 4 * i
  local sides2, internal2, boxes2, b = view2.sides[j], view2.internal[j], view2.boxes, 4 * j
  local sideC, flags = sideConstant, sideFlag
  local cLeft, cTop = boxes2[b - 1] - boxes1[a - 3], boxes2[b] - boxes1[a - 2]
  local cRight, cBottom = boxes1[a - 1] - boxes2[b - 3], boxes1[a] - boxes2[b - 2]
  sideC[1], sideC[2], sideC[3], sideC[4] = cLeft, cTop, cRight, cBottom
  local rects, r = pairRects, 8 * p   -- for pushFree
  pairBox[p] = 1
  rects[r - 7], rects[r - 6], rects[r - 5], rects[r - 4] = boxes1[a - 3], boxes1[a - 2],
    boxes1[a - 1], boxes1[a]
  rects[r - 3], rects[r - 2], rects[r - 1], rects[r] = boxes2[b - 3], boxes2[b - 2],
    boxes2[b - 1], boxes2[b]
  local line1, line2, line3, line4 = sides1[1], sides1[3], sides1[5], sides1[7]
  local flag1, flag2, flag3, flag4 = internal1[1], internal1[3], internal1[5], internal1[7]
  flags[line1], flags[line2], flags[line3], flags[line4] = flag1, flag2, flag3, flag4
  putSide(line1, flag1, top + 1)
  putSide(line2, flag2, top + 2)
  putSide(line3, flag3, top + 3)
  putSide(line4, flag4, top + 4)
  top = top + 4
  local line, flag = sides2[2], internal2[1]
  putSide(line, flag, top + 1)
  top = top + abs(flag - flags[line])
  line, flag = sides2[4], internal2[3]
  putSide(line, flag, top + 1)
  top = top + abs(flag - flags[line])
  line, flag = sides2[6], internal2[5]
  putSide(line, flag, top + 1)
  top = top + abs(flag - flags[line])
  line, flag = sides2[8], internal2[7]
  putSide(line, flag, top + 1)
  top = top + abs(flag - flags[line])
  local least = min(cLeft, cTop, cRight, cBottom)
  leastFree = max(leastFree, faceLift + least)
  return top, isAbove(least)
end

-- PUC Lua's: the nearest feet and seams kept as the faces are written. One function, not split
-- into steps: it runs for every pair of rectangles a push tests, where PUC Lua pays for every
-- call.
local function rectPairFacesPuc(view1, i, view2, j, top, p)
  local sides1, internal1, boxes1, a = view1.sides[i], view1.internal[i], view1.boxes, 4 * i
  local sides2, internal2, boxes2, b = view2.sides[j], view2.internal[j], view2.boxes, 4 * j
  local fx, fy, fc, seam, reach = faceX, faceY, faceC, faceSeam, faceReach
  local sideX, sideY, sideC, flags = SIDE_X, SIDE_Y, sideConstant, sideFlag
  local lift, foot, footReach = faceLift, nearestFoot, nearestReach
  local foot2, foot2Reach, nearX, nearY = secondFoot, secondReach, seamX, seamY
  -- p1's sides' faceC, -lo of the axis-parallel edges in pairFacesPuc (fl(b - a) = -fl(a - b))
  local cLeft = boxes2[b - 1] - boxes1[a - 3]
  local cTop = boxes2[b] - boxes1[a - 2]
  local cRight = boxes1[a - 1] - boxes2[b - 3]
  local cBottom = boxes1[a] - boxes2[b - 2]
  sideC[1] = cLeft
  sideC[2] = cTop
  sideC[3] = cRight
  sideC[4] = cBottom
  local rects, r = pairRects, 8 * p   -- for pushFree
  pairBox[p] = 1
  rects[r - 7] = boxes1[a - 3]
  rects[r - 6] = boxes1[a - 2]
  rects[r - 5] = boxes1[a - 1]
  rects[r - 4] = boxes1[a]
  rects[r - 3] = boxes2[b - 3]
  rects[r - 2] = boxes2[b - 2]
  rects[r - 1] = boxes2[b - 1]
  rects[r] = boxes2[b]
  -- p1's sides in the order of its edges, then those of p2 whose flags differ: two loops, the
  -- face's code in both (one loop over the eight edges would tell the two apart at every edge;
  -- one assignment per statement, as in pairFacesPuc). The reach lift + c is
  -- pairFacesPuc's lift - lo.
  for e = 1, 7, 2 do
    local line, flag = sides1[e], internal1[e]
    flags[line] = flag
    local c = sideC[line]
    local d = lift + c
    if d < 0 then d = -d end   -- a comparison, not abs's call
    top = top + 1
    local ux = sideX[line]
    fx[top] = ux
    fy[top] = sideY[line]
    fc[top] = c
    seam[top] = flag
    reach[top] = d
    if flag ~= 0 then
      if ux ~= 0 then
        if d < nearX then nearX = d end
      elseif d < nearY then
        nearY = d
      end
    elseif d < footReach then
      foot2 = foot
      foot2Reach = footReach
      foot = top
      footReach = d
    elseif d < foot2Reach then
      foot2 = top
      foot2Reach = d
    end
  end
  for e = 1, 7, 2 do
    local line, flag = sides2[e + 1], internal2[e]
    if flag ~= flags[line] then   -- else as the face of p1's on the same line: nothing to add
      local c = sideC[line]
      local d = lift + c
      if d < 0 then d = -d end
      top = top + 1
      local ux = sideX[line]
      fx[top] = ux
      fy[top] = sideY[line]
      fc[top] = c
      seam[top] = flag
      reach[top] = d
      if flag ~= 0 then
        if ux ~= 0 then
          if d < nearX then nearX = d end
        elseif d < nearY then
          nearY = d
        end
      elseif d < footReach then
        foot2 = foot
        foot2Reach = footReach
        foot = top
        footReach = d
      elseif d < foot2Reach then
        foot2 = top
        foot2Reach = d
      end
    end
  end
  nearestFoot, nearestReach, secondFoot, secondReach = foot, footReach, foot2, foot2Reach
  seamX, seamY = nearX, nearY
  local least = cLeft   -- leastFree, as rectPairFacesJit's
  if cTop < least then least = cTop end
  if cRight < least then least = cRight end
  if cBottom < least then least = cBottom end
  least = lift + least
  if least > leastFree then leastFree = least end
  if cLeft > 0 and cTop > 0 and cRight > 0 and cBottom > 0 then return top, 1 end
  return top, 0
end

local rectPairFaces = JIT and rectPairFacesJit or rectPairFacesPuc

-- Whether t lies outside every D of pairs 1 .. np widened by margin. A pair of rectangles
-- (pairBox) exactly instead: whether the second's box moved by t, each side as the move rounds
-- it (x + dx, as a game moves each vertex), overlaps the first's, which is whether the moved
-- rectangles overlap. So a push that leaves a crate touching a wall is free, and one push
-- still separates: a crate that fits a slot of a floor of boxes exactly, sunk into its bottom,
-- goes straight up, flush with both walls, not out over one of them (as it did when D widened
-- by margin was tested here too). Written as the negation of a disjunction, so that a NaN
-- is inside, as in the faces' tests.
local function pushFree(tx, ty, np, margin)
  local first, fx, fy, fc = faceFirst, faceX, faceY, faceC   -- locals: PUC Lua reads upvalues slower
  local isBox, rects = pairBox, pairRects
  for p = 1, np do
    if isBox[p] ~= 0 then
      local b = 8 * p
      if not (rects[b - 7] >= rects[b - 1] + tx or rects[b - 3] + tx >= rects[b - 5]
          or rects[b - 6] >= rects[b] + ty or rects[b - 2] + ty >= rects[b - 4]) then
        return false
      end
    else
      local inside = true
      for f = first[p], first[p + 1] - 1 do
        if fx[f] * tx + fy[f] * ty >= fc[f] + margin then
          inside = false
          break
        end
      end
      if inside then return false end
    end
  end
  return true
end

local nearLines = {}   -- scratch for nearestFree: the faces whose lines pass nearer than the best

-- The nearest free candidate among the faces of pairs 1 .. np: its length and vector, or huge.
-- One function, not split into steps: it runs on every push over lists of parts, where PUC Lua
-- pays for every call and LuaJIT would leave its trace at each.
local function nearestFree(np, margin)
  local fx, fy, fc, reach = faceX, faceY, faceC, faceReach   -- locals: PUC Lua reads upvalues slower
  local best, bestX, bestY = huge, 0.0, 0.0
  local last = faceFirst[np + 1] - 1
  local lift = 1.25 * margin
  -- A candidate t whose computed length e is below low = leastFree - 0.75 margin is not free,
  -- and is not tried (pushFree would say false: the answer is the same; on LuaJIT the
  -- crossings are, see below). Let L = leastFree, the least fc + lift of some pair: each
  -- face h of that pair has fc + lift >= L (1 - eps), so fc + margin (lift = 1.25 margin)
  -- rounds to at least L (1 - 2 eps) - 0.25 margin; and t gives fx tx + fy ty <= e (1 + 10 eps)
  -- (a unit normal within 4 eps of length 1, |t| within 5 eps of e for a foot or a crossing,
  -- the products and the sum rounded), below that when 0.5 margin > 14 eps L, true as
  -- L <= 1.01 E and margin >= 64 eps E: t lies inside the pair's D widened by margin, for
  -- every face. (A crate turned on a floor: its nearest foot is mostly a face of the crate
  -- against the part it barely reaches into, inside the other part's D.)
  local low = leastFree - 0.75 * margin
  if JIT and feetKept < last then   -- (PUC Lua: the bodies kept them)
    keepFeet(feetKept + 1, last)
    feetKept = last
  end
  -- The nearest foot first, then the second nearest (addFaces keeps them): usually one of them
  -- is free, and then no other foot is nearer (the feet loop below would pick the first free one
  -- in the order of reach, then of faces; it runs when neither is free).
  local found = 0
  if nearestFoot > 0 and nearestReach >= low then
    local d = fc[nearestFoot] + lift
    local tx, ty = fx[nearestFoot] * d, fy[nearestFoot] * d
    if pushFree(tx, ty, np, margin) then best, bestX, bestY, found = nearestReach, tx, ty, 1 end
  end
  if found == 0 and secondFoot > 0 and secondReach >= low then
    local d = fc[secondFoot] + lift
    local tx, ty = fx[secondFoot] * d, fy[secondFoot] * d
    if pushFree(tx, ty, np, margin) then best, bestX, bestY, found = secondReach, tx, ty, 2 end
  end
  if found == 0 then
    -- feet of the perpendiculars on the outer edges' lines, but the nearest two: not free (tried
    -- above, they would be tried again)
    local foot, foot2 = nearestFoot, secondFoot
    for f = 1, last do
      if faceSeam[f] == 0 and reach[f] < best and reach[f] >= low and f ~= foot and f ~= foot2 then
        local d = fc[f] + lift
        local tx, ty = fx[f] * d, fy[f] * d
        if pushFree(tx, ty, np, margin) then best, bestX, bestY = reach[f], tx, ty end
      end
    end
  elseif seamReach >= best then
    -- Every outer edge's line passes at least as far as the nearest foot (found 1) or the
    -- second (found 2: all but the nearest): at most one outer line nearer than the best, the
    -- nearest foot's. No crossing when the lines nearer than the best are all parallel to an
    -- axis, the same one: a crate on a floor at a seam, whose neighbours' vertical internal
    -- faces pass nearer than the top (their det is exactly 0: no crossing either way).
    if seamY >= best and (seamX >= best or found == 1 or fy[nearestFoot] == 0)
        or seamX >= best and (found == 1 or fx[nearestFoot] == 0) then
      return best, bestX, bestY
    end
  end
  -- Crossings of two lines, each nearer than the best so far (a crossing is no nearer than
  -- either line): only the lines nearer than the best now can take part, usually a few of them.
  local count = 0
  for f = 1, last do
    if reach[f] < best then count = count + 1; nearLines[count] = f end
  end
  for a = 1, count - 1 do
    local f = nearLines[a]
    if reach[f] < best then
      local c1, x1, y1 = fc[f] + lift, fx[f], fy[f]
      for b = a + 1, count do
        local g = nearLines[b]
        if reach[g] < best then
          local c2 = fc[g] + lift
          local x2, y2 = fx[g], fy[g]
          local det = x1 * y2 - y1 * x2
          if det ~= 0 then
            local tx, ty = (c1 * y2 - c2 * y1) / det, (x1 * c2 - x2 * c1) / det
            local d = sqrt(tx * tx + ty * ty)
            -- Below low not tried on PUC Lua, as the feet; tried on LuaJIT, where that test's
            -- side exits lead into pushFree in side traces that may fail to compile ("NYI:
            -- register coalescing too complex")
            if d < best and (JIT or d >= low) and pushFree(tx, ty, np, margin) then
              best, bestX, bestY = d, tx, ty
            end
          end
        end
      end
    end
  end
  return best, bestX, bestY
end

-- Brings part p1 (number i of view1) and p2 (number j of view2) up to date for the boolean's
-- pair test (addPair does the same for a push, with the flat view's normals): a list's part
-- compared with its whole copy (the non-finite error raised at the public function's caller,
-- level 7 from checkCopy), a flat view's area sign computed. Returns their area signs and
-- spanX, spanY bounding their coordinate differences.
local function prepareSide(view, p, i)
  if view.copies then
    if view.checked[i] ~= call.stamp then checkCopy(view, i, p, 7) end
  elseif view.turnPending then
    partTurn(view, 1, p, #p); view.turnPending = false
  end
end

local function preparePair(view1, p1, i, view2, p2, j)
  prepareSide(view1, p1, i)
  prepareSide(view2, p2, j)
  local boxes1, boxes2, a, b = view1.boxes, view2.boxes, 4 * i, 4 * j
  local right, bottom, left, top = boxes1[a - 1], boxes1[a], boxes1[a - 3], boxes1[a - 2]
  if JIT then
    right, bottom = max(right, boxes2[b - 1]), max(bottom, boxes2[b])
    left, top = min(left, boxes2[b - 3]), min(top, boxes2[b - 2])
  else   -- the same numbers without calls
    if boxes2[b - 1] > right then right = boxes2[b - 1] end
    if boxes2[b] > bottom then bottom = boxes2[b] end
    if boxes2[b - 3] < left then left = boxes2[b - 3] end
    if boxes2[b - 2] < top then top = boxes2[b - 2] end
  end
  return view1.turns[i], view2.turns[j], right - left, bottom - top
end

-- Whether some edge of the part `edges` (turn its area sign) separates it from the part
-- `other`, decided exactly: the SAT engine's test (reachPast's), on each edge's outward normal
-- as the coordinates' differences give it (unscaled coordinates: the boolean's pairs).
local function edgesSeparate(edges, ne, turn, other, no, spanX, spanY)
  -- at least projectionTolerance of every edge's normal, whose |nx| <= spanY, |ny| <= spanX
  -- (rounding is monotonic): an edge whose -lo exceeds it cannot separate
  local tolBound = 16 * EPS * (2 * (spanX * spanY))
  local ax, ay = edges[ne - 1] + 0.0, edges[ne] + 0.0
  for i = 1, ne - 1, 2 do
    local bx, by = edges[i] + 0.0, edges[i + 1] + 0.0
    if bx ~= ax or by ~= ay then   -- a repeated vertex gives no edge
      local nx, ny = (by - ay) * turn, (ax - bx) * turn
      local lo = leastProjection(other, no, ax, ay, nx, ny)
      if -lo <= tolBound and edgeSeparates(lo, ax, ay, bx, by, turn, nx, ny, other, no, spanX, spanY) then
        return true
      end
    end
    ax, ay = bx, by
  end
  return false
end

-- Whether part p1 (number i of view1) and p2 (number j of view2) overlap, exactly: the boolean
-- addPair returns, without building faces.
-- On PUC Lua the SAT engine's calipers over both parts (reachBoth) decide it, one projection an
-- edge; on LuaJIT, which runs the engine's flat loop, edgesSeparate, which stops at the first
-- separating edge.
local function pairOverlaps(view1, p1, i, view2, p2, j)
  local turn1, turn2, spanX, spanY = preparePair(view1, p1, i, view2, p2, j)
  if turn1 == 0 or turn2 == 0 then return false end   -- zero area: never collides
  local n1, n2 = view1.lengths[i], view2.lengths[j]
  if not JIT then
    return reachBoth(p1, n1, turn1, p2, n2, turn2, squaredTolerance(spanX, spanY)) ~= false
  end
  return not (edgesSeparate(p1, n1, turn1, p2, n2, spanX, spanY)
    or edgesSeparate(p2, n2, turn2, p1, n1, spanX, spanY))
end

-- Appends the faces of D for part p1 (number i of view1) and p2 (number j of view2) as pair
-- np + 1, noting i and j (pairsOverlap). Returns np, top and pairFaces' 1 or 0 (whether the
-- parts overlap; on LuaJIT, overlap for sure).
local function addPair(view1, p1, i, view2, p2, j, k, np, top)
  -- preparePair's work inline (PUC Lua pays for every call): checkCopy's level counts from there
  -- A flat rectangle needs no normals unscaled (flatBox gave its sign): rectPairFaces and
  -- pairFacesPuc read none; LuaJIT's addFaces reads them against a part not a rectangle, so
  -- there they wait for such a pair.
  if view1.copies then
    if view1.checked[i] ~= call.stamp then checkCopy(view1, i, p1, 5) end
  elseif view1.pending then
    local needed = k ~= 1 or view1.rects[1] == 0 or JIT and view2.rects[j] == 0
    if needed then partNormals(view1, 1, p1, #p1) end
    view1.pending = JIT and not needed
  end
  if view2.copies then
    if view2.checked[j] ~= call.stamp then checkCopy(view2, j, p2, 5) end
  elseif view2.pending then
    local needed = k ~= 1 or view2.rects[1] == 0 or JIT and view1.rects[i] == 0
    if needed then partNormals(view2, 1, p2, #p2) end
    view2.pending = JIT and not needed
  end
  local turn1, turn2 = view1.turns[i], view2.turns[j]
  if turn1 == 0 or turn2 == 0 then return np, top, 0 end   -- zero area: never collides
  faceFirst[np + 1] = top + 1
  if k == 1 and view1.rects[i] ~= 0 and view2.rects[j] ~= 0 then
    local overlaps
    top, overlaps = rectPairFaces(view1, i, view2, j, top, np + 1)
    faceFirst[np + 2] = top + 1
    if JIT then pairPart1[np + 1], pairPart2[np + 1] = i, j end
    return np + 1, top, overlaps
  end
  local boxes1, boxes2, a, b = view1.boxes, view2.boxes, 4 * i, 4 * j
  local right1, bottom1, left1, low1 = boxes1[a - 1], boxes1[a], boxes1[a - 3], boxes1[a - 2]
  local right, bottom, left, low = right1, bottom1, left1, low1
  if JIT then
    right, bottom = max(right, boxes2[b - 1]), max(bottom, boxes2[b])
    left, low = min(left, boxes2[b - 3]), min(low, boxes2[b - 2])
  else   -- the same numbers without calls
    if boxes2[b - 1] > right then right = boxes2[b - 1] end
    if boxes2[b] > bottom then bottom = boxes2[b] end
    if boxes2[b - 3] < left then left = boxes2[b - 3] end
    if boxes2[b - 2] < low then low = boxes2[b - 2] end
  end
  local spanX, spanY = (right - left) * k, (bottom - low) * k
  local n1, n2 = view1.lengths[i], view2.lengths[j]
  pairBox[np + 1] = 0
  local overlaps
  if JIT and k == 1 and view1.rects[i] + view2.rects[j] ~= 0 then   -- one is a rectangle
    local sure1, sure2, highest1, highest2
    if view1.rects[i] ~= 0 then
      top, sure1, highest1 = rectFaces(view1, i, boxes2, b, 1.0, spanX, spanY, top)
    else
      top, sure1, highest1 = addBoxFaces(p1, n1, view1.normals[i], boxes2[b - 3], boxes2[b - 2],
        boxes2[b - 1], boxes2[b], view1.internal[i], 1.0, spanX, spanY, top)
    end
    if view2.rects[j] ~= 0 then
      top, sure2, highest2 = rectFaces(view2, j, boxes1, a, -1.0, spanX, spanY, top)
    else
      top, sure2, highest2 = addBoxFaces(p2, n2, view2.normals[j], left1, low1, right1, bottom1,
        view2.internal[j], -1.0, spanX, spanY, top)
    end
    faceFirst[np + 2] = top + 1
    pairPart1[np + 1], pairPart2[np + 1] = i, j
    leastFree = max(leastFree, faceLift - max(highest1, highest2))
    return np + 1, top, sure1 * sure2
  end
  local highest
  top, overlaps, highest = pairFaces(p1, n1, turn1, view1.normals[i], view1.internal[i],
    p2, n2, turn2, view2.normals[j], view2.internal[j], k, spanX, spanY, top, boxes1, a, boxes2, b,
    view1.rects[i], view2.rects[j])
  highest = faceLift - highest   -- this pair's least fc + lift (see leastFree)
  if highest > leastFree then leastFree = highest end
  faceFirst[np + 2] = top + 1
  if JIT then pairPart1[np + 1], pairPart2[np + 1] = i, j end
  return np + 1, top, overlaps
end

local overlapping = {}   -- scratch: the parts of a list whose boxes overlap a flat shape's box
local nearParts = {}     -- scratch: those whose boxes come within the window of it (see below)

-- Scratch for boxPush: per pair p, at 4p - 3 .. 4p, the lines of its first shape's sides in the
-- order of that part's edges (its faces' order in rectPairFaces): the side (1 left, 2 top, 3
-- right, 4 bottom, as rectSides numbers them) and its c + lift, which is also the line's
-- distance from the origin (its reach): the pairs' rectangles overlap, so every c > 0.
local boxSide, boxLine = {}, {}

-- Pairs 1 .. found of boxPush: their parts brought up to date (see preparedParts), each pair's
-- boxes (pairRects, for pushFree) and lines, from the boxes of the part and of the flat
-- rectangle; lines 4 found + 1 .. 8 FAR (see boxPush). Returns leastFree (see
-- nearestFree), or nil when a part is not a rectangle. A function of its own, its loop holding
-- few values: where the loop's end is a side exit, LuaJIT takes over in registers every value
-- live there, and failed to compile it ("NYI: register coalescing too complex") when
-- boxPush's were live too.
local function boxLines(info, list, flat, listFirst, found, margin)
  local lift, fb, flatSides, least = 1.25 * margin, flat.boxes, flat.sides[1], -huge
  local fx0, fy0, fx1, fy1 = fb[1], fb[2], fb[3], fb[4]
  for q = 1, found do
    local k = overlapping[q]
    if info.checked[k] ~= call.stamp then checkCopy(info, k, list[k], 6) end
    if info.rects[k] == 0 then return nil end
    local boxes, a = info.boxes, 4 * k
    local x0, y0, x1, y1 = boxes[a - 3], boxes[a - 2], boxes[a - 1], boxes[a]
    local cLeft, cTop, cRight, cBottom = fx1 - x0, fy1 - y0, x1 - fx0, y1 - fy0
    local order, rects, r = flatSides, pairRects, 8 * q   -- pairRects for pushFree
    pairBox[q] = 1
    if listFirst then
      order = info.sides[k]
      rects[r - 7], rects[r - 6], rects[r - 5], rects[r - 4] = x0, y0, x1, y1
      rects[r - 3], rects[r - 2], rects[r - 1], rects[r] = fx0, fy0, fx1, fy1
    else
      cLeft, cTop, cRight, cBottom = x1 - fx0, y1 - fy0, fx1 - x0, fy1 - y0
      rects[r - 7], rects[r - 6], rects[r - 5], rects[r - 4] = fx0, fy0, fx1, fy1
      rects[r - 3], rects[r - 2], rects[r - 1], rects[r] = x0, y0, x1, y1
    end
    local c, sides, lines = sideConstant, boxSide, boxLine
    c[1], c[2], c[3], c[4] = cLeft, cTop, cRight, cBottom
    local b, side = 4 * q, order[1]
    sides[b - 3], lines[b - 3] = side, c[side] + lift
    side = order[3]
    sides[b - 2], lines[b - 2] = side, c[side] + lift
    side = order[5]
    sides[b - 1], lines[b - 1] = side, c[side] + lift
    side = order[7]
    sides[b], lines[b] = side, c[side] + lift
    least = max(least, lift + min(cLeft, cTop, cRight, cBottom))
  end
  if found == 1 then
    local sides, lines = boxSide, boxLine
    sides[5], sides[6], sides[7], sides[8] = 1, 2, 1, 2
    lines[5], lines[6], lines[7], lines[8] = FAR, FAR, FAR, FAR
  end
  return least
end

-- The rank of line l's foot in the order nearestFree meets the feet (ties go to the first):
-- 8 p + 1 .. 8 p + 8 for pair p. A side of the pair's first part that is not a seam in that
-- part's order, 1 to 4; a seam's foot is the face of the flat rectangle's side on that line
-- (rectPairFaces), after those, 5 to 8 in the order of the flat rectangle's sides. (Only ties
-- ask for it: equal reaches.)
local function boxRank(l, info, flat, listFirst)
  local q = (l - 1 - (l - 1) % 4) / 4 + 1   -- the pair
  local e = l - 4 * q + 4   -- the side's place in the order of the pair's first part
  if not listFirst or info.internal[overlapping[q]][2 * e - 1] == 0 then return 8 * q + e end
  local flatSides, side = flat.sides[1], boxSide[l]
  for e2 = 1, 4 do
    if flatSides[2 * e2] == side then return 8 * q + 4 + e2 end
  end
end

-- The foot of line l of boxPush, and whether it is free among pairs 1 .. found.
local function boxFoot(l, found, margin)
  local d, side = boxLine[l], boxSide[l]
  local tx, ty = 0.0, 0.0
  if side == 1 then tx = -d elseif side == 3 then tx = d elseif side == 2 then ty = -d else ty = d end
  return pushFree(tx, ty, found, margin), tx, ty
end

-- The nearest free foot of boxPush's lines 1 .. last whose reach is low or more, after the
-- nearest two feet, which were not free (foot2 the second, at foot2Reach): the feet in order of
-- reach, then of rank (boxRank). Its reach and vector, or huge, 0, 0 when none is free. A
-- function of its own: the nearest two are usually free, so it rarely runs.
local function laterFreeFoot(info, flat, listFirst, found, margin, low, last, foot2, foot2Reach)
  local lines = boxLine
  -- the feet up to here were tried: those before (triedReach, triedRank)
  local triedReach, triedRank = foot2Reach, boxRank(foot2, info, flat, listFirst)
  while true do
    local f, reach, rank = 0, huge, 0
    for l = 1, last do
      local r = lines[l]
      if r >= low and r <= reach and r >= triedReach then
        local lRank = boxRank(l, info, flat, listFirst)
        if (r < reach or lRank < rank) and (r > triedReach or lRank > triedRank) then
          f, reach, rank = l, r, lRank
        end
      end
    end
    if f == 0 then return huge, 0.0, 0.0 end
    local free, tx, ty = boxFoot(f, found, margin)
    if free then return reach, tx, ty end
    triedReach, triedRank = reach, rank
  end
end

-- The push of a flat axis-parallel rectangle out of a list of them, or into it (a crate on a
-- floor of tiles or boxes), unscaled: every D is a box, and nearestFree's search comes down to
-- feet and crossings on the four lines of each box. Pair p's D is the open box -cLeft < tx <
-- cRight, -cTop < ty < cBottom (rectPairFaces' constants, the same numbers); its lines lifted
-- are left at tx = -(cLeft + lift), top at ty = -(cTop + lift), right at tx = cRight + lift and
-- bottom at ty = cBottom + lift, a foot where a line meets its axis, a crossing (+-x, +-y)
-- where a vertical line meets a horizontal one: the numbers nearestFree computes from the
-- faces. The pairs are the parts whose boxes overlap the rectangle's (overlapping, 1 ..
-- found); the feet are tried nearest first (then in line order) until one is free, then the
-- crossings of the lines nearer than it. As collideParts' loop does, the free point stands when
-- no other near part's box of D comes within near of it (the largest gaps of the scan tell
-- most calls at once) and it lies within half the window. Returns the push as collideParts
-- does, or nil when a part is not a rectangle, no candidate is free, or the point does not
-- stand: then collideParts' search decides. One function but for laterFreeFoot's rare search:
-- it runs on every push of a rectangle over rectangles, where PUC Lua pays for every call and
-- LuaJIT would leave its trace at each.
local function boxPush(info, list, flat, listFirst, found, nearCount, leastGapX, leastGapY,
                       margin, window)
  local least = boxLines(info, list, flat, listFirst, found, margin)
  if not least then return nil end
  local low, lines, sides = least - 0.75 * margin, boxLine, boxSide
  -- The nearest foot and the second nearest (among equals the first by boxRank), in one pass
  -- of at least 8 steps (FAR past the lines: a constant count for one pair or two); usually one
  -- of them is free. Else the feet in order of reach, then of rank.
  local last = 4 * found
  local steps = last < 8 and 8 or last
  local foot, footReach, foot2, foot2Reach = 0, huge, 0, huge
  for l = 1, steps do
    local r = lines[l]
    if r >= low then
      if r < footReach or r == footReach and r < FAR
          and boxRank(l, info, flat, listFirst) < boxRank(foot, info, flat, listFirst) then
        foot, footReach, foot2, foot2Reach = l, r, foot, footReach
      elseif r < foot2Reach or r == foot2Reach and r < FAR
          and boxRank(l, info, flat, listFirst) < boxRank(foot2, info, flat, listFirst) then
        foot2, foot2Reach = l, r
      end
    end
  end
  local best, bestX, bestY = huge, 0.0, 0.0
  local free, tx, ty = false, 0.0, 0.0
  if footReach < FAR then free, tx, ty = boxFoot(foot, found, margin) end
  if free then
    best, bestX, bestY = footReach, tx, ty
  else
    if foot2Reach < FAR then free, tx, ty = boxFoot(foot2, found, margin) end
    if free then
      best, bestX, bestY = foot2Reach, tx, ty
    elseif foot2Reach < FAR then
      best, bestX, bestY = laterFreeFoot(info, flat, listFirst, found, margin, low, last, foot2,
        foot2Reach)
    end
  end
  -- crossings of a vertical line and a horizontal one, both nearer than the best, in the order
  -- of nearestFree's (each line with those after it)
  local count = 0
  for l = 1, steps do
    if lines[l] < best then count = count + 1; nearLines[count] = l end
  end
  for a = 1, count - 1 do
    local f = nearLines[a]
    local x, side = lines[f], sides[f]
    if lines[f] < best then
      local vertical = side % 2
      if side <= 2 then x = -x end
      for b = a + 1, count do
        local g = nearLines[b]
        local y = lines[g]
        if lines[g] < best and sides[g] % 2 ~= vertical then
          if sides[g] <= 2 then y = -y end
          local cx, cy = x, y
          if vertical == 0 then cx, cy = y, x end
          local d = sqrt(cx * cx + cy * cy)
          -- below low not tried on PUC Lua, as nearestFree's crossings
          if d < best and (JIT or d >= low) and pushFree(cx, cy, found, margin) then
            best, bestX, bestY = d, cx, cy
          end
        end
      end
    end
  end
  if best == huge then return nil end
  local near, sx, sy = 4 * margin, bestX, bestY
  if not listFirst then sx, sy = -sx, -sy end   -- the box of D of flat - part: the tests on -t
  local reachX, reachY = sx < 0 and -sx or sx, sy < 0 and -sy or sy
  if 2 * ((reachX < reachY and reachY or reachX) + near) > window then return nil end
  if leastGapX - reachX < near or leastGapY - reachY < near then
    local boxes, fb = info.boxes, flat.boxes
    local fx0, fy0, fx1, fy1 = fb[1], fb[2], fb[3], fb[4]
    for q = 1, nearCount do
      local a = 4 * nearParts[q]
      local x0, y0, x1, y1 = boxes[a - 3], boxes[a - 2], boxes[a - 1], boxes[a]
      -- not a pair (its box and the rectangle's apart), and its box of D near t
      if not (x0 < fx1 and fx0 < x1 and y0 < fy1 and fy0 < y1) and (x0 - fx1) - sx < near
          and sx - (x1 - fx0) < near and (y0 - fy1) - sy < near and sy - (y1 - fy0) < near then
        return nil
      end
    end
  end
  return best, bestX + 0.0, bestY + 0.0
end

-- A push along an axis out of pairs of rectangles, the depth itself: the search's push is the
-- foot on a side's line lifted by `lift` (c + lift, c the side's constant from the two boxes);
-- when c is the exact difference of the two box coordinates it comes from, and the move by c,
-- rounded as a game moves the shape, leaves every pair 1 .. count apart (pushFree: exact for
-- pairs of rectangles, margin-safe for others), the push is c: a crate sunk 8 into a floor of
-- rectangles goes up by 8, not 8.000000000005. Among sides whose lifted constant is the push,
-- the largest exact c (the same whichever order the pairs came in, so a box against a list and
-- as a one-part list answer alike). Returns the push, as given when no side qualifies.
local function exactSidePush(count, best, tx, ty, lift, margin)
  if (tx ~= 0) == (ty ~= 0) then return best, tx, ty end   -- not along an axis
  local rects, isBox, found = pairRects, pairBox, -huge
  for p = 1, count do
    if isBox[p] ~= 0 then
      local r = 8 * p   -- the first shape's box at r - 7 .. r - 4, the second's at r - 3 .. r
      local a, b   -- c = a - b, the side's constant in the push's direction (rectPairFaces')
      if tx > 0 then a, b = rects[r - 5], rects[r - 3]
      elseif tx < 0 then a, b = rects[r - 1], rects[r - 7]
      elseif ty > 0 then a, b = rects[r - 4], rects[r - 2]
      else a, b = rects[r], rects[r - 6] end
      local c, err = twoDiff(a, b)
      if err == 0 and c > found and c + lift == best then found = c end
    end
  end
  if found <= 0 then return best, tx, ty end
  local dx = tx > 0 and found or (tx < 0 and -found or 0.0)
  local dy = ty > 0 and found or (ty < 0 and -found or 0.0)
  if not pushFree(dx, dy, count, margin) then return best, tx, ty end
  return found, dx, dy
end

M.exactSidePush = exactSidePush
M.nearParts = nearParts
M.overlapping = overlapping
M.pairPart1 = pairPart1
M.pairPart2 = pairPart2
M.overlapsConvex = overlapsConvex
M.pairOverlaps = pairOverlaps
M.boxPush = boxPush
M.pairAdded = pairAdded
M.startSearch = startSearch
M.addPair = addPair
M.nearestFree = nearestFree
M.pushFree = pushFree
M.faceX = faceX
M.faceY = faceY
M.faceC = faceC
M.faceSeam = faceSeam
M.faceFirst = faceFirst

-- For spec/bodies_faces_spec.lua only: both bodies of each pair, the LuaJIT-only helpers, the
-- scratch they write, and the search's state as they leave it.
M.leastProjectionJit = leastProjectionJit
M.leastProjectionPuc = leastProjectionPuc
M.pairFacesJit = pairFacesJit
M.pairFacesPuc = pairFacesPuc
M.rectPairFacesJit = rectPairFacesJit
M.rectPairFacesPuc = rectPairFacesPuc
M.addBoxFaces = addBoxFaces
M.rectFaces = rectFaces
M.keepFeet = keepFeet
M.faceReach = faceReach
M.pairBox = pairBox
M.pairRects = pairRects
function M.searchState()
  return nearestFoot, nearestReach, secondFoot, secondReach, seamReach, seamX, seamY, leastFree
end

return M
