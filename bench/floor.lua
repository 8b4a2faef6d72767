-- bench/floor.lua: polygonTriangulate against the plainest ear clipping Lua can run, on small
-- inputs: a rough floor for any triangulator written in Lua at these sizes. The bare clipper
-- below takes floating-point orientation tests (not exact), checks nothing, knows no ties or
-- pinch points, and writes one flat array of vertex numbers (no tables a triangle): not a
-- triangulator to use, a floor to measure against. Its ear test reads every vertex of the ring,
-- as earcut's does up to 80 vertices (past that earcut hashes its vertices, and this clipper's
-- cost, growing with the square of the size, is no floor any more). It joins holes as simply:
-- each, from the leftmost, at its leftmost vertex to the vertex of the ring that the ray to the
-- left reaches first (or the vertex inside the triangle of the ray's hit that lies nearest the
-- ray's direction; of vertices at one place, the one whose inside holds the hole), and drops
-- the vertices in line with their neighbours, at the start and wherever a clip leaves them.
-- Enough for the inputs here, which it is checked on: every triangle turns the outline's way,
-- and they add up to the outline's area less the holes'.
-- Both take the inputs of bench/cycled.lua's noisy-30, noisy-100 and tiles-8, different ones in
-- turn and the first repeated, after 0.5 s of laps, in alternating rounds, ns a vertex, the best
-- of each; earcut in node on the same inputs (bench/earcut-cycled.js), when node and earcut are
-- there (as bench/cycled.lua).
-- From the repository root: `luajit bench/floor.lua` (any Lua; about 30 s): each case in a
-- process of its own (LuaJIT's traces for one size served the next one worse: noisy-100 took
-- 600 ns a vertex after noisy-30 in one process, 450 alone); `luajit bench/floor.lua tiles-8`:
-- one case, here, its numbers bare and polygonTriangulate repeated, then in turn.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local polygon = require "polygon"
local prng = require "prng"
local shapes = require "shapes"
local tiles = require "tiles"
local shell = require "bench.shell"

local CASES = { "noisy-30", "noisy-100", "tiles-8" }
local LAP = 50000     -- vertices of a lap of the inputs, at least
local ROUNDS = 5      -- rounds of each, alternating
local ROUND = 0.2     -- seconds a round runs, at least
local WARM = 0.5      -- seconds of laps of each before the rounds (LuaJIT compiles), as cycled.lua

local min, max, abs, huge = math.min, math.max, math.abs, math.huge
local X, Y, nextV, prevV = {}, {}, {}, {}
local out = {}     -- the triangles' vertex numbers, three a triangle
local lefts = {}   -- the holes' leftmost vertices, in the order they are joined
local way          -- the outline's turn: 1 or -1, the sign of an ear's turn

-- twice the signed area of (a, b, c), > 0 turning left in y-up axes, rounded
local function turn(a, b, c)
  return (X[b] - X[a]) * (Y[c] - Y[a]) - (Y[b] - Y[a]) * (X[c] - X[a])
end

-- Vertices first + 1 .. first + m from the flat ring pts, linked in a circle as listed, or
-- backwards when `sign` is given and the ring's turn is not of that sign; the ring's turn.
local function linkRing(pts, first, sign)
  local m = #pts / 2
  local sum = 0
  for i = 1, m do X[first + i], Y[first + i] = pts[2 * i - 1], pts[2 * i] end
  for i = 1, m do
    local j = i % m + 1
    sum = sum + X[first + i] * Y[first + j] - X[first + j] * Y[first + i]
  end
  local forward = not sign or (sum > 0) == (sign > 0)
  for i = 1, m do
    local after, before = first + i % m + 1, first + (i - 2) % m + 1
    if forward then nextV[first + i], prevV[first + i] = after, before
    else nextV[first + i], prevV[first + i] = before, after end
  end
  return sum > 0 and 1 or -1
end

-- Whether the ring's inside at vertex p holds the direction from p to vertex m.
local function opensTo(p, m)
  local a, c = prevV[p], nextV[p]
  local afterA, beforeC = way * turn(a, p, m) >= 0, way * turn(p, c, m) >= 0
  if way * turn(a, p, c) >= 0 then return afterA and beforeC end
  return afterA or beforeC
end

-- The vertex of the ring at `ring` that hole vertex m joins: where the ray from m to the left
-- meets the ring first, or the end further left of the edge it meets, or the vertex inside the
-- triangle of m, that hit and that end lying nearest the ray's direction; of several vertices
-- at that place, the one whose inside holds m.
local function joinTarget(m, ring)
  local mx, my = X[m], Y[m]
  local hitX, hit = -huge, nil
  local p = ring
  repeat
    local q = nextV[p]
    local py, qy = Y[p], Y[q]
    if py ~= qy and min(py, qy) <= my and max(py, qy) >= my then
      local x = X[p] + (my - py) * (X[q] - X[p]) / (qy - py)
      if x <= mx and x > hitX then hitX, hit = x, p end
    end
    p = q
  until p == ring
  assert(hit, "bench/floor.lua: a hole's ray met no edge")
  local q = nextV[hit]
  local target
  if X[hit] == hitX and Y[hit] == my then target = hit
  elseif X[q] == hitX and Y[q] == my then target = q
  else
    target = X[q] < X[hit] and q or hit
    local tx, ty = X[target], Y[target]
    local best = abs(ty - my) / (mx - tx)
    p = ring
    repeat
      local x, y = X[p], Y[p]
      if x < mx and x >= tx and p ~= target then
        -- inside the triangle (m, the hit, the end): on one side of its three sides, or on them
        local s1 = (hitX - mx) * (y - my)
        local s2 = (tx - hitX) * (y - my) - (ty - my) * (x - hitX)
        local s3 = (mx - tx) * (y - ty) - (my - ty) * (x - tx)
        if (s1 >= 0 and s2 >= 0 and s3 >= 0) or (s1 <= 0 and s2 <= 0 and s3 <= 0) then
          local t = abs(y - my) / (mx - x)
          if t < best or (t == best and x > X[target]) then target, best = p, t end
        end
      end
      p = nextV[p]
    until p == ring
  end
  p = ring
  repeat
    if X[p] == X[target] and Y[p] == Y[target] and opensTo(p, m) then return p end
    p = nextV[p]
  until p == ring
  return target
end

-- Drops the vertices in line with their neighbours (repeated ones among them) from the ring at
-- p of `left` vertices; returns the vertices left (start: one of them).
local start
local function dropInLine(p, left)
  local steady = 0
  while steady <= left and left > 2 do
    local a, c = prevV[p], nextV[p]
    if turn(a, p, c) == 0 then
      nextV[a], prevV[c] = c, a
      left, p, steady = left - 1, a, 0
    else
      p, steady = c, steady + 1
    end
  end
  start = p
  return left
end

-- Triangulates the flat outline pts with the flat holes of list `holes` (or none); returns the
-- number of triangles written to out, and the number of vertices left when the clipping ended.
local function bareClip(pts, holes)
  way = linkRing(pts, 0)
  local n = #pts / 2
  local count = holes and #holes or 0
  for h = 1, count do
    local hole, first = holes[h], n
    linkRing(hole, first, -way)
    local m = first + 1
    for i = first + 2, first + #hole / 2 do
      if X[i] < X[m] or (X[i] == X[m] and Y[i] < Y[m]) then m = i end
    end
    local at = h   -- the holes by their leftmost vertex, from the left (insertion)
    while at > 1 and X[lefts[at - 1]] > X[m] do lefts[at] = lefts[at - 1]; at = at - 1 end
    lefts[at] = m
    n = n + #hole / 2
  end
  for h = 1, count do   -- join hole h to the ring: its vertex m to target t, both doubled
    local m = lefts[h]
    local t = joinTarget(m, 1)
    local t2, m2 = n + 1, n + 2
    X[t2], Y[t2], X[m2], Y[m2] = X[t], Y[t], X[m], Y[m]
    local tNext, mPrev = nextV[t], prevV[m]
    nextV[t], prevV[m] = m, t
    nextV[mPrev], prevV[m2] = m2, mPrev
    nextV[m2], prevV[t2] = t2, m2
    nextV[t2], prevV[tNext] = tNext, t2
    n = n + 2
  end
  local left, written = dropInLine(1, n), 0
  local ear, stop = start, start
  while left > 2 do
    local a, c = prevV[ear], nextV[ear]
    local isEar = way * turn(a, ear, c) > 0
    if isEar then
      local ax, ay, bx, by, cx, cy = X[a], Y[a], X[ear], Y[ear], X[c], Y[c]
      local x0, y0 = min(ax, bx, cx), min(ay, by, cy)
      local x1, y1 = max(ax, bx, cx), max(ay, by, cy)
      local p = nextV[c]
      while p ~= a do
        local x, y = X[p], Y[p]
        -- inside or on the triangle, not at a's place, and not convex
        if x >= x0 and x <= x1 and y >= y0 and y <= y1 and way * turn(a, ear, p) >= 0
          and way * turn(ear, c, p) >= 0 and way * turn(c, a, p) >= 0
          and (x ~= ax or y ~= ay) and way * turn(prevV[p], p, nextV[p]) <= 0 then
          isEar = false
          break
        end
        p = nextV[p]
      end
    end
    if isEar then
      out[written + 1], out[written + 2], out[written + 3] = a, ear, c
      written = written + 3
      nextV[a], prevV[c] = c, a
      left = left - 1
      -- a and c left in line with their neighbours: dropped, and theirs after them
      local dropped = true
      while dropped and left > 2 do
        dropped = false
        if turn(prevV[a], a, c) == 0 then
          local p = prevV[a]
          nextV[p], prevV[c], a, left, dropped = c, p, p, left - 1, true
        end
        local q = nextV[c]
        if left > 2 and turn(a, c, q) == 0 then
          nextV[a], prevV[q], c, left, dropped = q, a, q, left - 1, true
        end
      end
      ear = nextV[c]
      stop = ear
    else
      ear = c
      if ear == stop then   -- a lap without an ear: the vertices in line dropped, as earcut
        local was = left     -- does, and another lap; else given up (counted below)
        left = dropInLine(ear, left)
        if left == was then break end
        ear, stop = start, start
      end
    end
  end
  return written / 3, left
end

-- One call of f on each input; the triangles made, counted (the checksum that keeps the calls).
local function lap(points, holes, f)
  local made = 0
  for i = 1, #points do
    local r = f(points[i], holes[i])
    made = made + (type(r) == "table" and #r or r)
  end
  return made
end

-- Twice the area of the flat ring pts, unsigned.
local function ringArea(pts)
  local m, sum = #pts / 2, 0
  for i = 1, m do
    local j = i % m + 1
    sum = sum + pts[2 * i - 1] * pts[2 * j] - pts[2 * j - 1] * pts[2 * i]
  end
  return abs(sum)
end

local case = arg[1]
if not case then
  -- each case in its own process; earcut on the same inputs (bench/cycled.lua's export) in node
  local self = arg[-1] or "lua"
  local earcutFile = shell.earcut()
  local dir = earcutFile and shell.tempDir()
  if dir then
    assert(shell.ok(("%s bench/cycled.lua export %s"):format(self, dir)), "bench/cycled.lua export failed")
  end
  print(("polygonTriangulate on %s against the bare clipper, and earcut in node: ns a vertex"):format(self))
  print(("%-10s %6s | %-36s | %-36s"):format("", "", "one input repeated", "inputs in turn"))
  print(("%-10s %6s | %6s %6s %6s %7s %7s | %6s %6s %6s %7s %7s"):format("input", "inputs",
    "bare", "polygon", "earcut", "p/bare", "bare/e", "bare", "polygon", "earcut", "p/bare", "bare/e"))
  for _, each in ipairs(CASES) do
    local ours = shell.words(("%s bench/floor.lua %s"):format(self, each))
    assert(ours[1] == each, "bench/floor.lua " .. each .. " failed: " .. table.concat(ours, " "))
    local theirs = dir and shell.words(("EARCUT=%s node bench/earcut-cycled.js %s/%s.json"):format(
      earcutFile, dir, each)) or {}
    local function ns(v) return v and ("%.0f"):format(v) or "-" end
    local function ratio(x, y) return x and y and ("%.2f"):format(x / y) or "-" end
    local count, bareA, libA, bareB, libB = tonumber(ours[2]), tonumber(ours[3]), tonumber(ours[4]),
      tonumber(ours[5]), tonumber(ours[6])
    local earA, earB = tonumber(theirs[2]), tonumber(theirs[3])
    print(("%-10s %6d | %6s %6s %6s %7s %7s | %6s %6s %6s %7s %7s"):format(each, count,
      ns(bareA), ns(libA), ns(earA), ratio(libA, bareA), ratio(bareA, earA),
      ns(bareB), ns(libB), ns(earB), ratio(libB, bareB), ratio(bareB, earB)))
    io.stdout:flush()
  end
  if dir then shell.ok("rm -rf " .. dir) end
  return
end
do
  local kind, size = case:match("^(%a+)%-(%d+)$")
  size = assert(tonumber(size), "bench/floor.lua: a case is noisy-N or tiles-N")
  local points, holes, vertices = {}, {}, 0
  repeat
    local k = #points + 1   -- (bench/cycled.lua's inputs: their earcut times are there)
    local seed = k == 1 and size or size * 100000 + k
    if kind == "noisy" then
      points[k], holes[k] = shapes.noisyCircle(size, prng.new(seed)), {}
    else
      points[k], holes[k] = tiles.level(prng.new(seed), size)
    end
    -- the benchmark times whole clippings only, of triangles each turning the outline's way,
    -- covering the outline less the holes (twice the areas, to a relative 1e-9)
    local count, left = bareClip(points[k], holes[k])
    assert(left == 2, "the bare clipper gave up")
    local area, sum = ringArea(points[k]), 0
    for _, hole in ipairs(holes[k]) do area = area - ringArea(hole) end
    for t = 1, 3 * count, 3 do
      local s = way * turn(out[t], out[t + 1], out[t + 2])
      assert(s > 0, "the bare clipper's triangles turn both ways")
      sum = sum + s
    end
    assert(abs(sum - area) <= 1e-9 * area, "the bare clipper's triangles miss the area")
    vertices = vertices + #points[k] / 2
    for _, hole in ipairs(holes[k]) do vertices = vertices + #hole / 2 end
  until #points >= 16 and vertices >= LAP
  local first = { {}, {} }   -- the first input as many times
  for i = 1, #points do first[1][i], first[2][i] = points[1], holes[1] end
  local firstVertices = #points[1] / 2
  for _, hole in ipairs(holes[1]) do firstVertices = firstVertices + #hole / 2 end
  local best = { math.huge, math.huge, math.huge, math.huge }
  local ways = { bareClip, polygon.polygonTriangulate }
  local made = 0
  for _, f in ipairs(ways) do
    local began = os.clock()
    repeat made = made + lap(points, holes, f) until os.clock() - began > WARM
  end
  for _ = 1, ROUNDS do
    for w, f in ipairs(ways) do
      for repeated = 0, 1 do
        local P, H = points, holes
        local total = vertices
        if repeated == 1 then P, H, total = first[1], first[2], firstVertices * #points end
        local laps, began = 0, os.clock()
        repeat made = made + lap(P, H, f); laps = laps + 1 until os.clock() - began > ROUND
        local slot = 2 * w - 1 + repeated
        best[slot] = min(best[slot], (os.clock() - began) / (laps * total) * 1e9)
      end
    end
  end
  assert(made > 0)
  -- for the table above: the case, its inputs, then repeated and in turn, each bare and ours
  print(case, #points, best[2], best[4], best[1], best[3])
end
