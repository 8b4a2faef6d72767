-- Two bodies side by side: where LuaJIT and PUC Lua keep different code for the collisions of
-- lists of parts (polygon/views.lua, polygon/faces.lua), both bodies run here on every
-- interpreter, on the same generated inputs, and their results are compared bit for bit: the
-- same value, the same sign of a zero, NaN for NaN, and on Lua 5.3 and later the same subtype
-- (integer or float). The interpreter runs one body in the field; this spec keeps the other
-- honest.
--
-- What is compared, pair by pair, and why:
-- * leastProjection (faces.lua; PUC Lua's body is sat's minProjection, which is sat's
--   projectRange on LuaJIT): the number returned, bit for bit, ties of +0 and -0 included
--   (PUC Lua's math.min keeps the first of equals, as the loop does; LuaJIT's keeps the last,
--   as projectRange does there).
-- * partNormals (views.lua): the area sign and every normal written, bit for bit.
-- * flatBox (views.lua): whether the coordinates are finite; then the box, the rectangle kind,
--   for a rectangle its sides (the same shared table) and area sign, and the box around all
--   parts and the largest magnitude, which flatView takes from shapeBox after flatBoxJit and
--   which flatBoxPuc writes itself. (After a non-finite coordinate flatView returns nil and no
--   one reads the box.)
-- * pairFaces (faces.lua), on sequences of one to three pairs as a push adds them: the index of
--   the last face, and each face's faceX, faceY, faceC, faceSeam and faceReach over the range
--   the body returns (pairFacesJit writes a face for a repeated vertex past that range: no
--   caller reads it); the largest lo; and the nearest feet after keepFeet has run over the new
--   faces, as nearestFree runs it before it reads them on LuaJIT. By design they differ in
--   two things, compared as the callers read them: pairFacesJit's 1 means "overlap for sure",
--   so it must imply pairFacesPuc's exact 1 (compound.lua's pairsOverlap decides the rest);
--   and keepFeet keeps the internal faces whose normals are (+-1, 0) or (0, +-1) in seamX and
--   seamY, pairFacesPuc every internal face in seamReach, so the least of the three is
--   compared (nearestFree's early end reads them only against the best reach). faceX, faceY,
--   faceC and the largest lo are compared up to zeros' signs: pairFacesPuc takes an
--   axis-parallel rectangle's normals as +-1.0, 0.0 and its projections from the boxes, where
--   pairFacesJit takes partNormals' numbers (a zero of the area sign's sign) and products
--   (-1 (x - ax) + 0 (y - ay)): the same numbers, but zeros may carry other signs. Those zeros
--   only meet sums with lift or margin (both > 0), products summed with nonzero terms, and
--   comparisons, as the notes in faces.lua say; faceSeam, faceReach and the feet are compared
--   bit for bit.
-- * The LuaJIT-only rectFaces and addBoxFaces, composed as addPair composes them for a pair of
--   which one part is an axis-parallel rectangle: against pairFacesPuc, as pairFaces above.
-- * rectPairFaces (faces.lua), on sequences of one to three pairs of rectangles: the index of
--   the last face, the faces over that range, the overlap (both exact: equal), pairBox and
--   pairRects, and after keepFeet the nearest feet, seamReach, seamX, seamY and leastFree, all
--   bit for bit.
local prng = require "prng"
local oracle = require "oracle"
local bitwise = require "bitwise"
local shapes = require "shapes"
local parts = require "parts"
local tiles = require "tiles"
require "polygon"
local views = require "polygon.views"
local faces = require "polygon.faces"

local mathType = rawget(math, "type") or function() return nil end

local same = bitwise.same

-- Whether a and b are equal numbers, a zero's sign aside (see the head of the file).
local function zerosAside(a, b)
  if a ~= a then return b ~= b end
  return a == b
end

local function describeValue(x)
  if type(x) == "number" then return ("%.17g (%s)"):format(x, mathType(x) or "number") end
  return tostring(x)
end

-- Asserts that `check` holds for a and b, naming what and the case when it does not.
local function expectSame(check, a, b, what, case)
  if not check(a, b) then
    error(("%s differs in %s: LuaJIT's body %s, PUC Lua's %s"):format(what, case,
      describeValue(a), describeValue(b)), 2)
  end
end

-- Inputs ------------------------------------------------------------------------------------

-- Every coordinate rounded to an integer (a tile map's).
local function rounded(points)
  local out = {}
  for i = 1, #points do out[i] = math.floor(points[i] + 0.5) end
  return out
end

-- A random convex part of 3 .. 20 vertices, either winding, around (cx, cy): rounded to
-- integers, or shrunk to a sliver (nearly collinear), or as drawn.
local function randomPart(rng, cx, cy, size)
  local m = rng:int(3, 20)
  local part = shapes.convex(rng, m, cx, cy, size, 0.3)
  local kind = rng:int(1, 6)
  if kind == 1 then
    part = rounded(part)
  elseif kind == 2 then   -- a sliver: y squeezed to within 1e-9 of cy
    for i = 2, #part, 2 do part[i] = cy + (part[i] - cy) * 1e-9 end
  end
  if rng:int(0, 1) == 1 then part = shapes.reverse(part) end
  return part
end

-- An axis-parallel rectangle of either kind and winding, its first vertex at any corner.
local function randomRect(rng, x, y, w, h)
  local box = parts.box(x, y, w, h)   -- clockwise from (x, y)
  local shift = rng:int(0, 3)
  local out = {}
  for v = 0, 3 do
    local s = (v + shift) % 4
    out[2 * v + 1], out[2 * v + 2] = box[2 * s + 1], box[2 * s + 2]
  end
  if rng:int(0, 1) == 1 then out = shapes.reverse(out) end
  return out
end

-- A convex part cut along a chord into two, which share that edge (an internal edge).
local function cutPart(rng, cx, cy, size)
  local whole = shapes.convex(rng, rng:int(4, 12), cx, cy, size, 0.3)
  if rng:int(0, 1) == 1 then whole = rounded(whole) end
  local m = #whole / 2
  local k = rng:int(3, m - 1)
  local a, b = {}, {}
  for v = 1, k do a[#a + 1], a[#a + 2] = whole[2 * v - 1], whole[2 * v] end
  for v = k, m do b[#b + 1], b[#b + 2] = whole[2 * v - 1], whole[2 * v] end
  b[#b + 1], b[#b + 2] = whole[1], whole[2]
  return { a, b }
end

-- A list of boxes, one a filled tile of a random tile set (neighbours share sides: internal).
local function tileBoxes(rng, ox, oy, size)
  local set = tiles.random(rng, rng:int(1, 4), rng:int(1, 3), 0.7)
  local list = {}
  for r = 1, set.rows do
    for c = 1, set.cols do
      if set[r][c] then
        list[#list + 1] = randomRect(rng, ox + (c - 1) * size, oy + (r - 1) * size, size, size)
      end
    end
  end
  if #list == 0 then list[1] = parts.box(ox, oy, size, size) end
  return list
end

local OFFSETS = { 0, 0, 0, 1e9, -1e9, 0.5, 4096 }

-- A list of parts near (cx, cy) of one of several kinds.
local function randomList(rng, cx, cy, size, rectsOnly)
  local kind = rectsOnly and rng:int(4, 6) or rng:int(1, 6)
  if kind == 1 then return { randomPart(rng, cx, cy, size) } end
  if kind == 2 then return cutPart(rng, cx, cy, size) end
  if kind == 3 then return { randomPart(rng, cx, cy, size), randomRect(rng, cx, cy, size, size) } end
  if kind == 4 then
    return { randomRect(rng, cx - size * rng:float(), cy - size * rng:float(), size * rng:range(0.2, 2),
      size * rng:range(0.2, 2)) }
  end
  if kind == 5 then return tileBoxes(rng, cx - size, cy - size, rng:pick({ 1, 8, 10, 32 })) end
  return parts.floor(rng:int(1, 4), size, cy, cx - size)
end

-- Whether every part of a list is one the collision functions take (convex or of zero area, by
-- the oracle): a rounded or cut part can turn back by an ulp, and listView refuses it.
local function acceptable(list)
  for _, part in ipairs(list) do
    if oracle.polygonType(part) == "concave" then return false end
  end
  return true
end

-- Two lists that touch, overlap or miss, as views (listView), far from the origin or not.
local function randomScene(rng, rectsOnly)
  local offset = rng:pick(OFFSETS)
  local size = rng:pick({ 1, 10, 16, 100 })
  local list1 = randomList(rng, offset, offset, size, rectsOnly)
  local gap = rng:pick({ 0, 0, 0.5, 1, 1.5, 3 }) * size   -- 0: touching or overlapping
  local list2 = randomList(rng, offset + rng:range(-gap, gap), offset + rng:range(-gap, gap),
    size, rectsOnly)
  if not (acceptable(list1) and acceptable(list2)) then return randomScene(rng, rectsOnly) end
  return views.listView("spec", "shape1", list1), list1, views.listView("spec", "shape2", list2),
    list2
end

-- Harness ------------------------------------------------------------------------------------

local SENTINEL = 7777.5
local faceArrays = { faceX = faces.faceX, faceY = faces.faceY, faceC = faces.faceC,
                     faceSeam = faces.faceSeam, faceReach = faces.faceReach }

local function clearScratch()
  for _, array in pairs(faceArrays) do
    for f = 1, 200 do array[f] = SENTINEL end
  end
  for p = 1, 8 do faces.pairBox[p] = SENTINEL end
  for r = 1, 64 do faces.pairRects[r] = SENTINEL end
end

-- The faces 1 .. top and the search's state, copied.
local function snapshot(top)
  local copy = { top = top, state = { faces.searchState() } }
  for name, array in pairs(faceArrays) do
    local values = {}
    for f = 1, top do values[f] = array[f] end
    copy[name] = values
  end
  copy.pairBox, copy.pairRects = {}, {}
  for p = 1, 8 do copy.pairBox[p] = faces.pairBox[p] end
  for r = 1, 64 do copy.pairRects[r] = faces.pairRects[r] end
  return copy
end

-- What addPair passes for the pair (part i of view1, part j of view2), scaled by k.
local function pairArguments(view1, list1, i, view2, list2, j, k)
  local b1, b2, a, b = view1.boxes, view2.boxes, 4 * i, 4 * j
  local right, bottom = math.max(b1[a - 1], b2[b - 1]), math.max(b1[a], b2[b])
  local left, top = math.min(b1[a - 3], b2[b - 3]), math.min(b1[a - 2], b2[b - 2])
  return list1[i], view1.lengths[i], view1.turns[i], view1.normals[i], view1.internal[i],
    list2[j], view2.lengths[j], view2.turns[j], view2.normals[j], view2.internal[j],
    k, (right - left) * k, (bottom - top) * k
end

-- Up to three pairs of parts of the scene that a push would add (area not zero; both
-- rectangles when `rects`), as {i, j}.
local function pickPairs(rng, view1, view2, rects)
  local chosen = {}
  for _ = 1, 12 do
    local i, j = rng:int(1, view1.count), rng:int(1, view2.count)
    local ok = view1.turns[i] ~= 0 and view2.turns[j] ~= 0
    if rects ~= nil then ok = ok and ((view1.rects[i] ~= 0 and view2.rects[j] ~= 0) == rects) end
    if ok then chosen[#chosen + 1] = { i, j } end
    if #chosen == 3 or #chosen > 0 and rng:int(0, 2) == 0 then break end
  end
  return chosen
end

local FAR = 2^1000

-- Compares the faces of two runs over their ranges, face by face.
local function compareFaces(jit, puc, case, loose)
  expectSame(same, jit.top, puc.top, "the last face's index", case)
  local numeric = loose and zerosAside or same
  for f = 1, jit.top do
    local at = (" (face %d)"):format(f)
    expectSame(numeric, jit.faceX[f], puc.faceX[f], "faceX" .. at, case)
    expectSame(numeric, jit.faceY[f], puc.faceY[f], "faceY" .. at, case)
    expectSame(numeric, jit.faceC[f], puc.faceC[f], "faceC" .. at, case)
    expectSame(same, jit.faceSeam[f], puc.faceSeam[f], "faceSeam" .. at, case)
    expectSame(same, jit.faceReach[f], puc.faceReach[f], "faceReach" .. at, case)
  end
end

-- Compares the feet kept (nearestFoot, nearestReach, secondFoot, secondReach) and the internal
-- faces' least reach: pairFacesPuc's seamReach against the least of keepFeet's three.
local function compareFeet(jit, puc, case)
  local names = { "nearestFoot", "nearestReach", "secondFoot", "secondReach" }
  for v = 1, 4 do expectSame(same, jit.state[v], puc.state[v], names[v], case) end
  local j, p = jit.state, puc.state
  expectSame(same, math.min(j[5], j[6], j[7]), math.min(p[5], p[6], p[7]),
    "the internal faces' least reach", case)
  expectSame(same, p[6], FAR, "pairFacesPuc's seamX (untouched)", case)
  expectSame(same, p[7], FAR, "pairFacesPuc's seamY (untouched)", case)
end

describe("two bodies side by side (polygon/views.lua, polygon/faces.lua)", function()
  describe("when leastProjectionJit and leastProjectionPuc (sat's minProjection) run", function()
    it("return the same least projection, bit for bit", function()
      local jit, puc = faces.leastProjectionJit, faces.leastProjectionPuc
      local rng = prng.new(2101)
      local cases = 0
      for c = 1, 3000 do
        local offset = rng:pick(OFFSETS)
        local points = randomPart(rng, offset, offset, rng:pick({ 1, 10, 100 }))
        local other = randomPart(rng, offset + rng:range(-50, 50), offset, 30)
        local v = 2 * rng:int(1, #other / 2) - 1
        local ax, ay = other[v], other[v + 1]
        local nx, ny
        local kind = rng:int(1, 4)
        if kind == 1 then   -- an axis-parallel unit normal, its zero of either sign
          nx, ny = rng:pick({ 1.0, -1.0 }), rng:pick({ 0.0, -0.0 })
          if rng:int(0, 1) == 1 then nx, ny = ny, nx end
        elseif kind == 2 then   -- an edge's normal as the differences give it
          local w = v + 2 <= #other and v + 2 or 1
          nx, ny = other[w + 1] - ay, ax - other[w]
        else   -- a unit normal
          local angle = rng:range(0, 2 * math.pi)
          nx, ny = math.cos(angle), math.sin(angle)
        end
        local case = ("case %d (%d coordinates)"):format(c, #points)
        local a, b = jit(points, #points, ax, ay, nx, ny), puc(points, #points, ax, ay, nx, ny)
        expectSame(same, a, b, "the least projection", case)
        cases = cases + 1
      end
      assert.are.equal(3000, cases)
    end)

    it("agree on the zero's sign when +0 and -0 tie for the least", function()
      -- along (-1, 0) from (0, 0): (0, 5) projects to -0 + 0 = 0, (0, -5) to -0 + -0 = -0
      -- (0 times -5), (-3, 0) to 3
      for _, points in ipairs({ { 0, 5, 0, -5, -3, 0 }, { 0, -5, 0, 5, -3, 0 } }) do
        local a = faces.leastProjectionJit(points, 6, 0.0, 0.0, -1.0, 0.0)
        local b = faces.leastProjectionPuc(points, 6, 0.0, 0.0, -1.0, 0.0)
        assert.are.equal(0, a)
        expectSame(same, a, b, "the least projection", "the tie of +0 and -0")
      end
    end)
  end)

  describe("when partNormalsJit and partNormalsPuc run", function()
    it("write the same area sign and normals, bit for bit", function()
      local rng = prng.new(2203)
      for c = 1, 3000 do
        local offset = rng:pick(OFFSETS)
        local part
        local kind = rng:int(1, 5)
        if kind <= 2 then
          part = randomPart(rng, offset, offset, rng:pick({ 1, 10, 100 }))
        elseif kind == 3 then
          part = randomRect(rng, offset, offset, rng:pick({ 1, 3, 0.25 }), rng:pick({ 2, 5, 0.5 }))
        elseif kind == 4 then   -- collinear: zero area, no normal read
          part = { offset, offset, offset + 1, offset + 2, offset + 2, offset + 4 }
        else   -- a repeated vertex, and a part with -0 coordinates
          part = randomRect(rng, -0.0, -0.0, 4, 4)
          table.insert(part, 3, part[2]); table.insert(part, 3, part[1])
        end
        local n = #part
        local viewJ = { turns = {}, normals = { {} } }
        local viewP = { turns = {}, normals = { {} } }
        views.partNormalsJit(viewJ, 1, part, n)
        views.partNormalsPuc(viewP, 1, part, n)
        local case = ("case %d (kind %d, %d coordinates)"):format(c, kind, n)
        expectSame(same, viewJ.turns[1], viewP.turns[1], "the area sign", case)
        for i = 1, n do
          expectSame(same, viewJ.normals[1][i], viewP.normals[1][i], ("normal [%d]"):format(i), case)
        end
      end
    end)
  end)

  describe("when flatBoxJit (then shapeBox, as flatView) and flatBoxPuc run", function()
    it("return the same finiteness and write the same box, kind, sides, sign and bounds", function()
      local rng = prng.new(2309)
      local specials = { 1 / 0, -1 / 0, 0 / 0, -0.0 }
      for c = 1, 4000 do
        local offset = rng:pick(OFFSETS)
        local shape
        local kind = rng:int(1, 6)
        if kind <= 2 then
          shape = randomRect(rng, offset + rng:int(-5, 5), offset, rng:pick({ 1, 7, 0.5 }),
            rng:pick({ 2, 0.25 }))
        elseif kind == 3 then
          shape = randomPart(rng, offset, offset, rng:pick({ 1, 10, 100 }))
        elseif kind == 4 then   -- fewer than 3 points, or none
          shape = {}
          for i = 1, 2 * rng:int(0, 2) do shape[i] = offset + rng:int(-9, 9) end
        elseif kind == 5 then   -- a rectangle of no width, or a near-rectangle
          shape = randomRect(rng, offset, offset, rng:pick({ 0, 3 }), rng:pick({ 0, 2 }))
          if rng:int(0, 1) == 1 then
            local i = rng:int(1, 8)
            shape[i] = shape[i] + rng:pick({ 1e-9, -1, 2^-40 })
          end
        else   -- a special value somewhere: inf, NaN or -0
          shape = rng:int(0, 1) == 1 and randomRect(rng, 0, 0, 3, 2) or randomPart(rng, 0, 0, 10)
          shape[rng:int(1, #shape)] = rng:pick(specials)
        end
        local n = #shape
        local viewJ = { count = 1, boxes = {}, rects = {}, sides = {}, turns = {} }
        local viewP = { count = 1, boxes = {}, rects = {}, sides = {}, turns = {} }
        local finiteJ = views.flatBoxJit(viewJ, 1, shape, n)
        local finiteP = views.flatBoxPuc(viewP, 1, shape, n)
        local case = ("case %d (kind %d, %d coordinates)"):format(c, kind, n)
        expectSame(same, finiteJ, finiteP, "finiteness", case)
        if finiteJ then
          views.shapeBox(viewJ)
          for i = 1, 4 do expectSame(same, viewJ.boxes[i], viewP.boxes[i], ("box [%d]"):format(i), case) end
          expectSame(same, viewJ.rects[1], viewP.rects[1], "rectangle kind", case)
          if viewP.rects[1] ~= 0 then
            expectSame(same, viewJ.sides[1], viewP.sides[1], "sides", case)
            expectSame(same, viewJ.turns[1], viewP.turns[1], "area sign", case)
          end
          for _, name in ipairs({ "magnitude", "left", "top", "right", "bottom" }) do
            expectSame(same, viewJ[name], viewP[name], name, case)
          end
        end
      end
    end)
  end)

  describe("when pairFacesJit (then keepFeet) and pairFacesPuc run on the pairs of a push", function()
    it("write the same faces and keep the same feet; LuaJIT's 'sure' implies PUC Lua's overlap", function()
      local rng = prng.new(2411)
      local sequences, pairCount = 0, 0
      while sequences < 1500 do
        local view1, list1, view2, list2 = randomScene(rng, false)
        local chosen = pickPairs(rng, view1, view2, nil)
        if #chosen > 0 then
          sequences = sequences + 1
          local k = rng:pick({ 1, 1, 1, 0.5, 2^-20 })
          local lift = 1.25 * rng:pick({ 1e-9, 1e-6, 0.01 })
          local runs, answers = {}, {}
          for body = 1, 2 do
            clearScratch()
            faces.startSearch(lift)
            local top, out = 0, {}
            for q, pair in ipairs(chosen) do
              local i, j = pair[1], pair[2]
              local first = top + 1
              local overlaps, highest
              local args = { pairArguments(view1, list1, i, view2, list2, j, k) }
              if body == 1 then
                top, overlaps, highest = faces.pairFacesJit(args[1], args[2], args[3], args[4], args[5],
                  args[6], args[7], args[8], args[9], args[10], args[11], args[12], args[13], top)
                faces.keepFeet(first, top)
              else
                local b1, b2 = view1.boxes, view2.boxes
                top, overlaps, highest = faces.pairFacesPuc(args[1], args[2], args[3], args[4], args[5],
                  args[6], args[7], args[8], args[9], args[10], args[11], args[12], args[13], top,
                  b1, 4 * i, b2, 4 * j, view1.rects[i], view2.rects[j])
              end
              out[q] = { overlaps, highest }
            end
            runs[body], answers[body] = snapshot(top), out
          end
          local case = ("sequence %d (%d pairs, k %g)"):format(sequences, #chosen, k)
          compareFaces(runs[1], runs[2], case, true)
          compareFeet(runs[1], runs[2], case)
          for q = 1, #chosen do
            local at = (" (pair %d)"):format(q)
            expectSame(zerosAside, answers[1][q][2], answers[2][q][2], "the largest lo" .. at, case)
            if answers[1][q][1] == 1 then
              expectSame(same, 1, answers[2][q][1], "the overlap, LuaJIT's sure" .. at, case)
            end
          end
          pairCount = pairCount + #chosen
        end
      end
      assert.is_true(pairCount >= 1500)
    end)

    it("as rectFaces and addBoxFaces (addPair's LuaJIT path for one rectangle) write them", function()
      local rng = prng.new(2503)
      local sequences = 0
      while sequences < 1500 do
        local view1, list1, view2, list2 = randomScene(rng, false)
        local chosen = pickPairs(rng, view1, view2, false)
        local mixed = {}
        for _, pair in ipairs(chosen) do   -- exactly one rectangle
          if view1.rects[pair[1]] + view2.rects[pair[2]] ~= 0 then mixed[#mixed + 1] = pair end
        end
        if #mixed > 0 then
          sequences = sequences + 1
          local lift = 1.25 * rng:pick({ 1e-9, 1e-6, 0.01 })
          local runs, answers = {}, {}
          for body = 1, 2 do
            clearScratch()
            faces.startSearch(lift)
            local top, out = 0, {}
            for q, pair in ipairs(mixed) do
              local i, j = pair[1], pair[2]
              local p1, n1, turn1, normals1, internal1, p2, n2, turn2, normals2, internal2, k, spanX, spanY =
                pairArguments(view1, list1, i, view2, list2, j, 1)
              local b1, b2, a, b = view1.boxes, view2.boxes, 4 * i, 4 * j
              local first = top + 1
              local overlaps, highest
              if body == 1 then   -- as addPair composes them on LuaJIT
                local sure1, sure2, highest1, highest2
                if view1.rects[i] ~= 0 then
                  top, sure1, highest1 = faces.rectFaces(view1, i, b2, b, 1.0, spanX, spanY, top)
                else
                  top, sure1, highest1 = faces.addBoxFaces(p1, n1, normals1, b2[b - 3], b2[b - 2],
                    b2[b - 1], b2[b], internal1, 1.0, spanX, spanY, top)
                end
                if view2.rects[j] ~= 0 then
                  top, sure2, highest2 = faces.rectFaces(view2, j, b1, a, -1.0, spanX, spanY, top)
                else
                  top, sure2, highest2 = faces.addBoxFaces(p2, n2, normals2, b1[a - 3], b1[a - 2],
                    b1[a - 1], b1[a], internal2, -1.0, spanX, spanY, top)
                end
                overlaps, highest = sure1 * sure2, math.max(highest1, highest2)
                faces.keepFeet(first, top)
              else
                top, overlaps, highest = faces.pairFacesPuc(p1, n1, turn1, normals1, internal1, p2, n2,
                  turn2, normals2, internal2, k, spanX, spanY, top, b1, a, b2, b, view1.rects[i],
                  view2.rects[j])
              end
              out[q] = { overlaps, highest }
            end
            runs[body], answers[body] = snapshot(top), out
          end
          local case = ("sequence %d (%d pairs)"):format(sequences, #mixed)
          compareFaces(runs[1], runs[2], case, true)
          compareFeet(runs[1], runs[2], case)
          for q = 1, #mixed do
            local at = (" (pair %d)"):format(q)
            expectSame(zerosAside, answers[1][q][2], answers[2][q][2], "the largest lo" .. at, case)
            if answers[1][q][1] == 1 then
              expectSame(same, 1, answers[2][q][1], "the overlap, LuaJIT's sure" .. at, case)
            end
          end
        end
      end
    end)
  end)

  describe("when rectPairFacesJit (then keepFeet) and rectPairFacesPuc run on pairs of rectangles", function()
    it("write the same faces, boxes, feet, seams and leastFree, and the same overlap, bit for bit", function()
      local rng = prng.new(2609)
      local sequences = 0
      while sequences < 2000 do
        local view1, _, view2 = randomScene(rng, true)
        local chosen = pickPairs(rng, view1, view2, true)
        if #chosen > 0 then
          sequences = sequences + 1
          local lift = 1.25 * rng:pick({ 1e-9, 1e-6, 0.01, 0.5 })
          local runs, answers = {}, {}
          for body = 1, 2 do
            clearScratch()
            faces.startSearch(lift)
            local top, out = 0, {}
            for q, pair in ipairs(chosen) do
              local first = top + 1
              local overlaps
              if body == 1 then
                top, overlaps = faces.rectPairFacesJit(view1, pair[1], view2, pair[2], top, q)
                faces.keepFeet(first, top)
              else
                top, overlaps = faces.rectPairFacesPuc(view1, pair[1], view2, pair[2], top, q)
              end
              out[q] = overlaps
            end
            runs[body], answers[body] = snapshot(top), out
          end
          local jit, puc = runs[1], runs[2]
          local case = ("sequence %d (%d pairs)"):format(sequences, #chosen)
          compareFaces(jit, puc, case, false)
          local names = { "nearestFoot", "nearestReach", "secondFoot", "secondReach", "seamReach",
                          "seamX", "seamY", "leastFree" }
          for v = 1, #names do expectSame(same, jit.state[v], puc.state[v], names[v], case) end
          for q = 1, #chosen do
            expectSame(same, answers[1][q], answers[2][q], ("the overlap (pair %d)"):format(q), case)
            expectSame(same, jit.pairBox[q], puc.pairBox[q], ("pairBox [%d]"):format(q), case)
          end
          for r = 1, 8 * #chosen do
            expectSame(same, jit.pairRects[r], puc.pairRects[r], ("pairRects [%d]"):format(r), case)
          end
        end
      end
    end)
  end)
end)
