-- bench/floor.lua: polygonTriangulate against the plainest ear clipping Lua can run, on small
-- outlines: a rough floor for any triangulator written in Lua at these sizes. The bare clipper
-- below takes floating-point orientation tests (not exact), checks nothing, knows no holes, ties
-- or repeated points, and writes one flat array of vertex numbers (no tables a triangle): not a
-- triangulator to use, a floor to measure against. Its ear test reads every vertex of the ring,
-- as earcut's does up to 80 vertices (past that earcut hashes its vertices, and this clipper's
-- cost, growing with the square of the size, is no floor any more). Both take the same noisy
-- circles, bench/cycled.lua's noisy-30 and noisy-100 (earcut's times on them are there),
-- different ones in turn, after 0.5 s of laps, in alternating rounds; ns a vertex, the best of
-- each.
-- From the repository root: `luajit bench/floor.lua` (any Lua): each size in a process of its
-- own (LuaJIT's traces for one size served the next one worse: noisy-100 took 600 ns a vertex
-- after noisy-30 in one process, 450 alone); `luajit bench/floor.lua 100`: one size, here.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local polygon = require "polygon"
local prng = require "prng"
local shapes = require "shapes"
local shell = require "bench.shell"

local SIZES = { 30, 100 }
local LAP = 50000     -- vertices of a lap of the inputs, at least
local ROUNDS = 5      -- rounds of each, alternating
local ROUND = 0.2     -- seconds a round runs, at least
local WARM = 0.5      -- seconds of laps of each before the rounds (LuaJIT compiles), as cycled.lua

local min, max = math.min, math.max
local X, Y, nextV, prevV = {}, {}, {}, {}
local out = {}   -- the triangles' vertex numbers, three a triangle

-- twice the signed area of (a, b, c), > 0 turning left in y-up axes, rounded
local function turn(a, b, c)
  return (X[b] - X[a]) * (Y[c] - Y[a]) - (Y[b] - Y[a]) * (X[c] - X[a])
end

-- Clips the flat outline pts; returns the number of triangles written to out.
local function bareClip(pts)
  local n = #pts / 2
  local sum = 0
  for i = 1, n do
    X[i], Y[i], nextV[i], prevV[i] = pts[2 * i - 1], pts[2 * i], i % n + 1, (i - 2) % n + 1
  end
  for i = 1, n do
    local j = nextV[i]
    sum = sum + X[i] * Y[j] - X[j] * Y[i]
  end
  local s = sum > 0 and 1 or -1   -- the ring's turn: an ear turns the same way
  local ear, stop, left, written = 1, 1, n, 0
  while left > 2 do
    local a, c = prevV[ear], nextV[ear]
    local isEar = s * turn(a, ear, c) > 0
    if isEar then
      local x0, y0 = min(X[a], X[ear], X[c]), min(Y[a], Y[ear], Y[c])
      local x1, y1 = max(X[a], X[ear], X[c]), max(Y[a], Y[ear], Y[c])
      local p = nextV[c]
      while p ~= a do
        local x, y = X[p], Y[p]
        if x >= x0 and x <= x1 and y >= y0 and y <= y1 and s * turn(a, ear, p) >= 0
          and s * turn(ear, c, p) >= 0 and s * turn(c, a, p) >= 0 then
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
      ear = nextV[c]
      stop = ear
    else
      ear = c
      if ear == stop then break end   -- a lap without an ear: given up (counted below)
    end
  end
  return written / 3
end

-- One call of f on each input; the triangles made, counted (the checksum that keeps the calls).
local function lap(inputs, f)
  local made = 0
  for i = 1, #inputs do
    local r = f(inputs[i])
    made = made + (type(r) == "table" and #r or r)
  end
  return made
end

local size = tonumber(arg[1])
if not size then
  print("ns a vertex, inputs in turn: the bare clipper, polygonTriangulate, and their ratio")
  io.stdout:flush()
  for _, each in ipairs(SIZES) do
    assert(shell.ok(("%s bench/floor.lua %d"):format(arg[-1] or "lua", each)), "bench/floor.lua failed")
  end
  return
end
do
  local inputs = {}
  repeat
    local k = #inputs + 1   -- (bench/cycled.lua's inputs: their earcut times are there)
    local points = shapes.noisyCircle(size, prng.new(k == 1 and size or size * 100000 + k))
    -- the benchmark times whole clippings only, of triangles each turning the outline's way
    local count, sign = bareClip(points), 0
    for t = 1, 3 * count, 3 do
      local s = turn(out[t], out[t + 1], out[t + 2])
      assert(s * sign >= 0 and s ~= 0, "the bare clipper's triangles turn both ways")
      sign = s
    end
    assert(count == size - 2, "the bare clipper gave up")
    inputs[#inputs + 1] = points
  until #inputs * size >= LAP
  local best = { math.huge, math.huge }
  local ways = { bareClip, polygon.polygonTriangulate }
  local made = 0
  for _, f in ipairs(ways) do
    local began = os.clock()
    repeat made = made + lap(inputs, f) until os.clock() - began > WARM
  end
  for _ = 1, ROUNDS do
    for w, f in ipairs(ways) do
      local laps, began = 0, os.clock()
      repeat made = made + lap(inputs, f); laps = laps + 1 until os.clock() - began > ROUND
      best[w] = min(best[w], (os.clock() - began) / (laps * #inputs * size) * 1e9)
    end
  end
  assert(made > 0)
  print(("noisy-%-5d %5d inputs  bare %5.0f  polygonTriangulate %5.0f  ratio %.1f")
    :format(size, #inputs, best[1], best[2], best[2] / best[1]))
end
