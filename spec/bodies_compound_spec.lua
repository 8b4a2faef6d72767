-- Two bodies: where LuaJIT and PUC Lua keep different code (circle.lua's edgeWalk, compound.lua's
-- partsOverlapping), both bodies run here on every interpreter, on the same generated inputs,
-- and must give the same numbers bit for bit: every return value (==, the sign of a zero, NaN
-- for NaN) and the scratch arrays they fill. Only one body runs in the library on a given
-- interpreter, so without this spec the other one is tested nowhere there.
-- (On Lua 5.3 and 5.4 a LuaJIT body's indices come out as floats, 3.0 for 3: equal as numbers
-- and as table keys, so the subtype is not compared.)
local circle = require "polygon.circle"
local compound = require "polygon.compound"
local views = require "polygon.views"
local faces = require "polygon.faces"
local polygon = require "polygon"
local prng = require "prng"
local shapes = require "shapes"
local parts = require "parts"
local tiles = require "tiles"

local huge = math.huge

-- Whether two values are the same bit for bit, as far as Lua can tell: equal, with zeros of one
-- sign, or both NaN. Not spec/support/bitwise.lua's same: on Lua 5.3+ edgeWalkJit returns its
-- vertex index as a float (1.0) where edgeWalkPuc returns an integer, which callers only index with.
local function same(a, b)
  if type(a) ~= type(b) then return false end
  if type(a) ~= "number" then return a == b end
  if a ~= a then return b ~= b end
  if a ~= b then return false end
  if a == 0 then return 1 / a == 1 / b end
  return true
end

-- A message naming the first return value that differs, or nil when all are the same.
local function compareResults(jit, puc, names)
  for i = 1, math.max(jit.n, puc.n) do
    if not same(jit[i], puc[i]) then
      local name = names[i] or ("value " .. i)
      return ("%s: Jit %s, Puc %s"):format(name, tostring(jit[i]), tostring(puc[i]))
    end
  end
  return nil
end

local function pack(...) return { n = select("#", ...), ... } end

-- Polygons for the edge walk, with circles around them: convex, both windings, at offsets up
-- to 1e9, sizes from 1e-3 to 1e6, integer coordinates, repeated vertices, collinear and nearly
-- collinear outlines, stars (a concave turn at vertex 1: the LuaJIT walk's second pass),
-- non-finite coordinates, and coordinates whose squares overflow or underflow. Each case is
-- { points, cx, cy, r }.
local function walkCases(rng, count)
  local cases = {}
  local offsets = { 0, 1e3, -1e3, 1e9, -1e9 }
  local sizes = { 1e-3, 1, 100, 1e6 }
  local function circlesAround(points, size)
    local x0, y0, x1, y1 = shapes.bounds(points)
    local cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    local out = {
      { cx, cy, size * rng:range(0.01, 2) },                                  -- inside
      { x1 + size * rng:range(-0.5, 0.5), cy, size * rng:range(0.01, 1) },    -- at an edge
      { x1 + 3 * size, y1 + 3 * size, size * rng:range(0.01, 1) },             -- apart
      { points[1], points[2], size * rng:range(0.01, 1) },                     -- on a vertex
      { (points[1] + points[3]) / 2, (points[2] + points[4]) / 2, size * 0.5 }, -- on an edge
      { cx + size * rng:range(-3, 3), cy + size * rng:range(-3, 3), size * rng:range(0.01, 2) },
    }
    return out
  end
  local function add(points, size)
    for _, c in ipairs(circlesAround(points, size)) do
      cases[#cases + 1] = { points, c[1], c[2], c[3] }
    end
  end
  while #cases < count do
    local kind = rng:int(1, 8)
    local ox, oy = rng:pick(offsets), rng:pick(offsets)
    local size = rng:pick(sizes)
    local m = rng:int(3, 12)
    if kind <= 3 then   -- convex, either winding
      local points = shapes.convex(rng, m, ox, oy, size, 0.4)
      if kind == 2 then points = shapes.reverse(points) end
      add(points, size)
    elseif kind == 4 then   -- integer coordinates, convex or a box
      local points = shapes.convex(rng, m, 0, 0, 100, 0.4)
      for i = 1, #points do points[i] = shapes.integer(math.floor(points[i] + 0.5)) end
      if rng:int(1, 3) == 1 then
        points = parts.box(rng:int(-50, 50), rng:int(-50, 50), rng:int(1, 40), rng:int(1, 40))
      end
      add(points, 100)
    elseif kind == 5 then   -- a repeated vertex, or a straight run
      local points = shapes.convex(rng, m, ox, oy, size, 0.4)
      local i = 2 * rng:int(1, m) - 1
      table.insert(points, i, points[i + 1])
      table.insert(points, i, points[i + 1])
      if rng:int(1, 2) == 1 then   -- a vertex in line with its neighbours, halfway
        local j = 2 * rng:int(1, m) - 1
        local nx, ny = points[j + 2] or points[1], points[j + 3] or points[2]
        table.insert(points, j + 2, (points[j + 1] + ny) / 2)
        table.insert(points, j + 2, (points[j] + nx) / 2)
      end
      add(points, size)
    elseif kind == 6 then   -- collinear (a zero area), or nearly: a triangle of tiny height
      local ax, ay, bx, by = ox, oy, ox + size * rng:range(0.5, 2), oy + size * rng:range(-2, 2)
      local t = rng:range(0.1, 0.9)
      local h = rng:pick({ 0, 0, 2^-40, -2^-40, 2^-20 }) * size
      add({ ax, ay, ax + t * (bx - ax), ay + t * (by - ay) + h, bx, by }, size)
    elseif kind == 7 then   -- a star: concave turns, often at vertex 1
      add(shapes.star(rng, m + 3, ox, oy, size), size)
    elseif rng:int(1, 2) == 1 then   -- a non-finite coordinate
      local points = shapes.convex(rng, m, ox, oy, size, 0.4)
      points[2 * rng:int(1, m) - 1] = rng:pick({ huge, -huge, 0 / 0 })
      add(points, size)
    else   -- huge or tiny coordinates: squares that overflow or underflow
      local scale = rng:pick({ 1e150, 1e200, 1e300, 1e-160, 1e-300 })
      add(shapes.convex(rng, m, scale * rng:pick({ 0, 1, -3 }), scale, scale, 0.4), scale)
    end
  end
  return cases
end

local WALK_NAMES = { "sign", "near", "nearSq", "farSq", "feature" }

describe("the two bodies of circle.lua's edgeWalk", function()
  local walkJit, walkPuc = circle.edgeWalkJit, circle.edgeWalkPuc
  local cases = walkCases(prng.new(20240611), 3000)

  it("are both exported, and one of them is the walk the library runs", function()
    assert.are.equal("function", type(walkJit))
    assert.are.equal("function", type(walkPuc))
    assert.are_not.equal(walkJit, walkPuc)
  end)

  it("give the same sign, nearest vertex, squared distances and farthest edge, bit for bit", function()
    -- with r = inf the PUC walk never stops early (its test key - inf > inf fails), so both walk
    -- every edge
    local failures = {}
    for c, case in ipairs(cases) do
      local points, cx, cy = case[1], case[2], case[3]
      local jit = pack(walkJit(points, #points, cx, cy))
      local puc = pack(walkPuc(points, #points, cx, cy, huge))
      local message = compareResults(jit, puc, WALK_NAMES)
      if message and #failures < 5 then failures[#failures + 1] = ("case %d: %s"):format(c, message) end
    end
    assert.are.same({}, failures)
  end)

  -- (With squares that underflow, farSq + r^2 < 2^-800, circleCollision scales the polygon
  -- after LuaJIT's walk, but PUC Lua's walk may already have stopped: there only the sign is
  -- compared.)
  it("stop early on PUC Lua only for a circle the full walk finds beyond an edge's line", function()
    local stopped = 0
    local failures = {}
    for c, case in ipairs(cases) do
      local points, cx, cy, r = case[1], case[2], case[3], case[4]
      local n = #points
      local jit = pack(walkJit(points, n, cx, cy))
      local puc = pack(walkPuc(points, n, cx, cy, r))
      local message = compareResults(jit, puc, WALK_NAMES)
      -- where circleCollision reads the walk: below, it scales the polygon first, on LuaJIT
      local used = jit[4] < 2^1000 and jit[4] + r * r >= 2^-800
      if message and not used and puc[5] == -1 and puc[1] == jit[1] then
        message = nil
      elseif message and puc[5] == -1 and puc[1] ~= 0 then
        stopped = stopped + 1
        -- the same sign, and the LuaJIT walk's farthest edge has the centre beyond its line by
        -- more than r
        local e = jit[5]
        local a = (e - 3) % n + 1
        local ax, ay = points[a] - cx, points[a + 1] - cy
        local ex, ey = points[e] - cx - ax, points[e + 1] - cy - ay
        local outside = (ex * ay - ey * ax) * jit[1]
        if not (puc[1] == jit[1] and outside > 0 and outside * outside / (ex * ex + ey * ey) > r * r) then
          message = "stopped early on a circle not beyond an edge"
        else
          message = nil
        end
      end
      if message and #failures < 5 then failures[#failures + 1] = ("case %d: %s"):format(c, message) end
    end
    assert.are.same({}, failures)
    assert.is_true(stopped > 100)   -- the early stop was reached
  end)
end)

-- Lists of parts for partsOverlapping: floors of boxes (rectangles from their (xmin, ymin)),
-- boxes starting at other corners, random convex parts, convex parts of random tile sets,
-- parts of zero area, at offsets up to 1e9, integer coordinates.
local function randomList(rng)
  local kind = rng:int(1, 5)
  local ox = rng:pick({ 0, 0, 1e3, -1e9, 1e9 })
  local oy = rng:pick({ 0, 0, -1e3, 1e9 })
  local list
  if kind == 1 then
    list = parts.floor(rng:int(1, 20), rng:pick({ 10, 32, 0.1 }), 200, 0)
  elseif kind == 2 then   -- boxes from any corner, either winding
    list = {}
    for k = 1, rng:int(1, 12) do
      local x, y, w, h = rng:int(-200, 200), rng:int(-200, 200), rng:int(1, 80), rng:int(1, 80)
      local b = parts.box(x, y, w, h)
      local start = 2 * rng:int(0, 3)
      local rotated = {}
      for i = 1, 8 do rotated[i] = b[(start + i - 1) % 8 + 1] end
      if rng:int(1, 2) == 1 then rotated = shapes.reverse(rotated) end
      list[k] = rotated
    end
  elseif kind == 3 then   -- random convex parts
    list = {}
    for k = 1, rng:int(1, 10) do
      local cx, cy = rng:range(-300, 300), rng:range(-300, 300)
      list[k] = shapes.convex(rng, rng:int(3, 8), cx, cy, rng:range(5, 80), 0.4)
    end
  elseif kind == 4 then   -- the convex parts of a tile set's outlines
    list = {}
    local set = tiles.random(rng, 5, 4, 0.5)
    for _, shape in ipairs(tiles.shapes(set, 32, -80, -64)) do
      for _, part in ipairs(polygon.polygonConvexParts(shape[1], shape[2]) or {}) do
        list[#list + 1] = part
      end
    end
    if #list == 0 then list[1] = parts.box(0, 0, 32, 32) end
  else   -- a few parts of zero area among boxes (fewer than three points are refused)
    list = {}
    for k = 1, rng:int(2, 8) do
      if rng:int(1, 3) == 1 then
        local x, y = rng:int(-100, 100), rng:int(-100, 100)
        list[k] = rng:int(1, 2) == 1 and { x, y, x, y, x, y }
          or { 0, 0, x, y, 2 * x, 2 * y }
      else
        list[k] = parts.box(rng:int(-100, 100), rng:int(-100, 100), rng:int(1, 50), rng:int(1, 50))
      end
    end
  end
  for _, part in ipairs(list) do
    for i = 1, #part - 1, 2 do part[i], part[i + 1] = part[i] + ox, part[i + 1] + oy end
  end
  return list
end

-- A box to test the list against: around a part, touching a part's box (a gap of 0), near the
-- list's box, or far from it, with a window of 0, the box's width plus height, or a random one.
local function randomBox(rng, view)
  local count = view.count
  local boxes = view.boxes
  local k = 4 * rng:int(1, count)
  local px0, py0, px1, py1 = boxes[k - 3], boxes[k - 2], boxes[k - 1], boxes[k]
  if px0 > px1 then px0, py0, px1, py1 = 0, 0, 1, 1 end   -- a part of fewer than three points
  local w, h = rng:range(1, 100), rng:range(1, 100)
  local x0, y0
  local place = rng:int(1, 5)
  if place == 1 then   -- around the part's corner
    x0, y0 = px0 + rng:range(-w, px1 - px0), py0 + rng:range(-h, py1 - py0)
  elseif place == 2 then   -- touching its right side
    x0, y0 = px1, py0 + rng:range(-h, py1 - py0)
  elseif place == 3 then   -- touching its top
    x0, y0 = px0 + rng:range(-w, px1 - px0), py0 - h
    h = py0 - y0
  elseif place == 4 then   -- somewhere in the list's box
    x0, y0 = rng:range(view.left - w, view.right), rng:range(view.top - h, view.bottom)
  else   -- far away
    x0, y0 = view.right + rng:range(0, 1e4), view.bottom + rng:range(-1e4, 1e4)
  end
  local x1, y1 = x0 + w, y0 + h
  local window = rng:pick({ 0, (x1 - x0) + (y1 - y0), rng:range(0, 300) })
  return x0, y0, x1, y1, window
end

-- A change a game might make to a list after it was prepared, which the scan must notice (or
-- not, for a coordinate off the part's box) the same way in both bodies.
local function change(rng, list)
  local k = rng:int(1, #list)
  local part = list[k]
  local how = rng:int(1, 5)
  if how == 1 and #part >= 2 then part[rng:int(1, #part)] = part[1] + 1
  elseif how == 2 then part[#part + 1], part[#part + 2] = 0, 0
  elseif how == 3 and #part >= 2 then part[#part], part[#part - 1] = nil, nil
  elseif how == 4 then list[k] = shapes.deepCopy(part)
  elseif how == 5 and #part >= 2 then part[1] = part[1] - 1   -- moves the box when x1 is xmin
  end
end

local OVERLAP_NAMES = { "found", "near", "leastGapX", "leastGapY" }
local SENTINEL = -12345   -- written into the scratch arrays before each call

-- Runs one body with the scratch arrays reset, and returns its values and copies of the arrays.
local function runScan(body, info, list, x0, y0, x1, y1, window)
  local overlapping, nearParts = faces.overlapping, faces.nearParts
  local room = #list + 2
  for i = 1, room do overlapping[i], nearParts[i] = SENTINEL, SENTINEL end
  local results = pack(body(info, list, x0, y0, x1, y1, window))
  local o, p = {}, {}
  for i = 1, room do o[i], p[i] = overlapping[i], nearParts[i] end
  return results, o, p
end

describe("the two bodies of compound.lua's partsOverlapping", function()
  local scanJit, scanPuc = compound.partsOverlappingJit, compound.partsOverlappingPuc

  -- Runs every case through both bodies: check(message) for the first few differences.
  local function compareScans(seed, lists, boxesEach, changed)
    local rng = prng.new(seed)
    local failures, nils, cases = {}, 0, 0
    for _ = 1, lists do
      local list = randomList(rng)
      local info = views.listView("partsOverlapping", "points", list)
      for b = 1, boxesEach do
        if changed and b == boxesEach then change(rng, list) end
        local x0, y0, x1, y1, window = randomBox(rng, info)
        local jit, oJit, pJit = runScan(scanJit, info, list, x0, y0, x1, y1, window)
        local puc, oPuc, pPuc = runScan(scanPuc, info, list, x0, y0, x1, y1, window)
        local message = compareResults(jit, puc, OVERLAP_NAMES)
        for i = 1, #oJit do
          if not message and not same(oJit[i], oPuc[i]) then
            message = ("overlapping[%d]: Jit %s, Puc %s"):format(i, tostring(oJit[i]), tostring(oPuc[i]))
          end
          if not message and not same(pJit[i], pPuc[i]) then
            message = ("nearParts[%d]: Jit %s, Puc %s"):format(i, tostring(pJit[i]), tostring(pPuc[i]))
          end
        end
        if message and #failures < 5 then
          failures[#failures + 1] = ("case %d: %s"):format(cases + 1, message)
        end
        cases = cases + 1
        if jit[1] == nil then nils = nils + 1 end
      end
    end
    return failures, cases, nils
  end

  it("are both exported", function()
    assert.are.equal("function", type(scanJit))
    assert.are.equal("function", type(scanPuc))
    assert.are_not.equal(scanJit, scanPuc)
  end)

  it("find the same parts, near parts and least gaps, bit for bit, on lists up to date", function()
    local failures, cases, nils = compareScans(7, 300, 8, false)
    assert.are.same({}, failures)
    assert.are.equal(2400, cases)
    assert.are.equal(0, nils)
  end)

  it("notice the same changes to a list (nil) and give the same numbers otherwise", function()
    local failures, _, nils = compareScans(11, 400, 3, true)
    assert.are.same({}, failures)
    assert.is_true(nils > 100)   -- the changes were seen
  end)

  -- A finding: the bodies differ for a part whose box lies within rounding of the window's
  -- edge. LuaJIT's tests fl(xmin - x1) < window, PUC Lua's xmin < fl(x1 + window) (and the same
  -- on the other three sides): for xmin = fl(x1 + window) the two roundings can disagree, and the
  -- part is near for one body and not for the other (nearParts, near, and the least gaps, which
  -- only near parts give). Which parts overlap the box itself (window 0) never differs.
  it("differ only on which parts lie at the window's edge, within rounding", function()
    local rng = prng.new(3)
    local failures, differing = {}, 0
    for c = 1, 600 do
      local x0, y0 = rng:range(-1e3, 1e3), rng:range(-1e3, 1e3)
      local x1, y1 = x0 + rng:range(1, 100), y0 + rng:range(1, 100)
      local window = rng:range(0, 300)
      local edge = x1 + window
      local u = shapes.ulp(math.abs(edge))
      local list = {}
      for k, x in ipairs({ edge - u, edge, edge + u }) do
        list[k] = { x, y0, x + 10, y0, x + 10, y1, x, y1 }
      end
      local info = views.listView("partsOverlapping", "points", list)
      local jit, oJit, pJit = runScan(scanJit, info, list, x0, y0, x1, y1, window)
      local puc, oPuc, pPuc = runScan(scanPuc, info, list, x0, y0, x1, y1, window)
      local message = compareResults(jit, puc, OVERLAP_NAMES)
      for i = 1, #oJit do
        if not message and not (same(oJit[i], oPuc[i]) and same(pJit[i], pPuc[i])) then
          message = ("scratch entry %d differs"):format(i)
        end
      end
      if message then
        differing = differing + 1
        -- none overlaps the box in either body, and the near parts of each are a run of the
        -- three parts, from the first: they differ only in where the window's edge falls
        local nearJit, nearPuc = jit[2], puc[2]
        if jit[1] ~= 0 or puc[1] ~= 0 or math.abs(nearJit - nearPuc) > 1 then
          failures[#failures + 1] = ("case %d: %s"):format(c, message)
        end
        for i = 1, math.max(nearJit, nearPuc) do
          if (i <= nearJit and pJit[i] ~= i) or (i <= nearPuc and pPuc[i] ~= i) then
            failures[#failures + 1] = ("case %d: near parts out of order"):format(c)
          end
        end
      end
    end
    assert.are.same({}, failures)
    assert.is_true(differing > 0)   -- the edge was reached: the finding still holds
  end)
end)
