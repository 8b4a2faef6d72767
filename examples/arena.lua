-- A box arena of about 250 shapes falling under gravity and resolved with polygon.lua's V
-- functions, in plain Lua (no LÖVE). It needs only polygon.lua (and its polygon/ folder, if any),
-- found beside this file or in the current directory. From the repository root:
--   luajit examples/arena.lua [frames]        (or lua5.1 .. lua5.4; 300 frames by default)
--   luajit examples/arena.lua 300 default     (LuaJIT with its default trace limits, see below)
-- It prints the time per frame, the garbage per frame of the module's calls, the largest overlap
-- left after resolution, and a checksum of the final positions: the same on every run and every
-- interpreter, because nothing in the loop depends on `pairs` order, math.random or the clock.
-- As a module (require "examples.arena"), arena.run(frames) returns those numbers as a table.
--
-- The pieces meant to be copied into a game: the grid broadphase (Grid), the mass split (push)
-- and the dispatch on shape kinds (resolvePair).
local requiredAs = ...
if not (type(requiredAs) == "string" and requiredAs:match("arena$")) then
  -- run as a script: polygon.lua beside this file (copied into a game's folder), else in the
  -- current directory (the repository root)
  local here = type(arg) == "table" and type(arg[0]) == "string" and arg[0]:match("^(.*[/\\])")
  package.path = (here and here .. "?.lua;" or "") .. "./?.lua;" .. package.path
end
local polygon = require "polygon"

local floor = math.floor

local WIDTH, HEIGHT = 640, 480       -- the arena: x in [0, WIDTH], y in [0, HEIGHT], y down
local CELL = 32                      -- grid cell: a bit more than the largest shape (28 across)
local DT = 1 / 60                    -- one frame of a 60 Hz game
local GRAVITY = 600                  -- px / s^2, down: GRAVITY * DT^2 = 1/6 px per frame per frame
local DAMPING = 0.99                 -- keeps 99% of last frame's velocity (air drag, calms piles)
local ITERATIONS = 6                 -- resolution passes per frame over the candidate pairs
local WALL = 200                     -- wall thickness: far more than a frame's motion, no tunnelling

--------------------------------------------------------------------------------------------------
-- A random generator of the file's own, so that the arena needs nothing but polygon.lua.
-- math.random draws different numbers on 5.1, 5.4 and LuaJIT; this one draws the same on all
-- five: Park and Miller's minimal standard, state <- state * 48271 mod (2^31 - 1), whose products
-- stay below 2^47, exact as doubles and as integers. It is the specs' generator
-- (spec/support/prng.lua), and spec/arena_spec.lua checks that both draw the same numbers.
--------------------------------------------------------------------------------------------------
local MODULUS, MULTIPLIER = 2147483647, 48271   -- 2^31 - 1; a multiplier below 2^16
local TWO26, TWO27, TWO53 = 67108864, 134217728, 9007199254740992

local Random = {}
Random.__index = Random

-- A generator from an integer seed (taken mod 2^31 - 1; 0, which would stay 0, becomes 1).
function Random.new(seed)
  seed = seed % MODULUS
  return setmetatable({ state = seed == 0 and 1 or seed }, Random)
end

-- The next state, an integer in 1 .. 2^31 - 2.
function Random:next()
  self.state = self.state * MULTIPLIER % MODULUS
  return self.state
end

-- An integer in lo .. hi, both inclusive.
function Random:int(lo, hi)
  return lo + self:next() % (hi - lo + 1)
end

-- A number in [lo, hi): 53 random bits (26 from one draw, 27 from the next) over 2^53, exactly.
function Random:range(lo, hi)
  local high, low = self:next() % TWO26, self:next() % TWO27
  return lo + (hi - lo) * ((high * TWO27 + low) / TWO53)
end

--------------------------------------------------------------------------------------------------
-- Uniform grid broadphase, fed by polygonBounds. Allocates only while its tables first grow.
--------------------------------------------------------------------------------------------------
local Grid = {}
Grid.__index = Grid

-- A grid of cols x rows cells of `size` over [x0, x0 + cols size] x [y0, y0 + rows size]; boxes
-- outside are clamped to the border cells.
function Grid.new(size, x0, y0, cols, rows)
  return setmetatable({ size = size, x0 = x0, y0 = y0, cols = cols, rows = rows,
    cells = {}, counts = {}, used = {}, nused = 0, cx0 = {}, cy0 = {}, cx1 = {}, cy1 = {} }, Grid)
end

-- The cell column (or row) holding coordinate v, clamped to [0, last].
local function cellOf(v, origin, size, last)
  local c = floor((v - origin) / size)
  if c < 0 then return 0 elseif c > last then return last end
  return c
end

-- Empties the cells used since the last clear (their tables are kept for the next frame).
function Grid:clear()
  for k = 1, self.nused do self.counts[self.used[k]] = 0 end
  self.nused = 0
end

-- Puts shape `id` into every cell its box touches (pairs come out in the order of insertion).
function Grid:insert(id, minx, miny, maxx, maxy)
  local size, cols = self.size, self.cols
  local cx0, cx1 = cellOf(minx, self.x0, size, cols - 1), cellOf(maxx, self.x0, size, cols - 1)
  local cy0, cy1 = cellOf(miny, self.y0, size, self.rows - 1), cellOf(maxy, self.y0, size, self.rows - 1)
  self.cx0[id], self.cy0[id], self.cx1[id], self.cy1[id] = cx0, cy0, cx1, cy1
  local cells, counts = self.cells, self.counts
  for cy = cy0, cy1 do
    for cx = cx0, cx1 do
      local c = cy * cols + cx + 1
      local count = counts[c] or 0
      if count == 0 then self.nused = self.nused + 1; self.used[self.nused] = c end
      if not cells[c] then cells[c] = {} end
      count = count + 1
      cells[c][count], counts[c] = id, count
    end
  end
end

-- Writes every pair of ids whose boxes share a cell into pairA, pairB (a < b) and returns how many.
-- A pair sharing several cells is written once: in the first cell both cover (the largest of
-- their first columns and of their first rows). Order: by a, then cell, then b: deterministic.
function Grid:pairs(nshapes, pairA, pairB)
  local cols, cells, counts = self.cols, self.cells, self.counts
  local cx0, cy0, cx1, cy1 = self.cx0, self.cy0, self.cx1, self.cy1
  local npairs = 0
  for a = 1, nshapes do
    for cy = cy0[a], cy1[a] do
      for cx = cx0[a], cx1[a] do
        local c = cy * cols + cx + 1
        local cell = cells[c]
        for k = 1, counts[c] do
          local b = cell[k]
          if b > a and cx == (cx0[b] > cx0[a] and cx0[b] or cx0[a])
             and cy == (cy0[b] > cy0[a] and cy0[b] or cy0[a]) then
            npairs = npairs + 1
            pairA[npairs], pairB[npairs] = a, b
          end
        end
      end
    end
  end
  return npairs
end

--------------------------------------------------------------------------------------------------
-- Shapes: a body is a polygon (points in world coordinates, rebuilt each frame from `base`, the
-- shape about its centroid at angle 0) or a circle; invMass is 0 for the static walls.
--------------------------------------------------------------------------------------------------

-- Sets a circle body's box from its centre and radius.
local function circleBox(body)
  body.minx, body.miny, body.maxx, body.maxy = body.x - body.r, body.y - body.r, body.x + body.r,
    body.y + body.r
end

-- Moves a body by (dx, dy): its position, its box and, for a polygon, its world points in place.
-- The polygon's box moves with it exactly: rounding keeps order, so min(x_i) + dx rounds to
-- min(x_i + dx) rounded.
local function move(body, dx, dy)
  body.x, body.y = body.x + dx, body.y + dy
  if body.kind == "polygon" then
    polygon.polygonTranslate(body.points, dx, dy, body.points)
    body.minx, body.miny, body.maxx, body.maxy = body.minx + dx, body.miny + dy, body.maxx + dx,
      body.maxy + dy
  else
    circleBox(body)
  end
end

-- Applies the push (dx, dy) that separates `b` from `a`, split by mass: b moves by the share
-- invB / (invA + invB) of it and a by the rest, the other way. A static body (invMass 0) does not
-- move and the other takes the whole push.
local function push(a, b, dx, dy)
  local total = a.invMass + b.invMass
  local shareA, shareB = a.invMass / total, b.invMass / total
  if shareA > 0 then move(a, -dx * shareA, -dy * shareA) end
  if shareB > 0 then move(b, dx * shareB, dy * shareB) end
end

-- The overlap of a candidate pair and the push moving b out of a (false when apart), by kinds.
-- polygonsCollideV moves its second polygon, polygonCircleCollideV the circle, circlesCollideV
-- the second circle: to move the first shape instead, subtract the push from it.
local function collidePair(a, b)
  if a.kind == "polygon" then
    if b.kind == "polygon" then
      local overlap, dx, dy = polygon.polygonsCollideV(a.points, b.points)
      return overlap, dx, dy
    end
    local overlap, dx, dy = polygon.polygonCircleCollideV(a.points, b.x, b.y, b.r)
    return overlap, dx, dy
  elseif b.kind == "polygon" then
    -- the push moves the circle a out of the polygon b: b leaves a the opposite way
    local overlap, dx, dy = polygon.polygonCircleCollideV(b.points, a.x, a.y, a.r)
    if not overlap then return false end
    return overlap, -dx, -dy
  end
  local overlap, dx, dy = polygon.circlesCollideV(a.x, a.y, a.r, b.x, b.y, b.r)
  return overlap, dx, dy
end

-- Resolves one candidate pair; returns the overlap found (0 when apart). Boxes that do not
-- overlap (or just touch: touching is not colliding) rule the pair out before the exact test:
-- most grid neighbours are apart.
local function resolvePair(a, b)
  if a.invMass == 0 and b.invMass == 0 then return 0 end
  if a.maxx <= b.minx or b.maxx <= a.minx or a.maxy <= b.miny or b.maxy <= a.miny then return 0 end
  local overlap, dx, dy = collidePair(a, b)
  if not overlap then return 0 end
  push(a, b, dx, dy)
  return overlap
end

-- Rebuilds a moving polygon's world points from its base shape, angle and position, into the
-- same reused table every frame (nothing allocated), and sets every body's box. Turning the base
-- by the whole angle, rather than last frame's points by the step, keeps rounding from piling up.
local function place(body)
  if body.kind == "polygon" then
    if body.spin ~= 0 then
      polygon.polygonRotate(body.base, body.angle, 0, 0, body.points)
      polygon.polygonTranslate(body.points, body.x, body.y, body.points)
    elseif body.invMass > 0 then   -- a shape that does not spin was turned once, in newWorld
      polygon.polygonTranslate(body.base, body.x, body.y, body.points)
    end
    body.minx, body.miny, body.maxx, body.maxy = polygon.polygonBounds(body.points)
  else
    circleBox(body)
  end
end

--------------------------------------------------------------------------------------------------
-- The world
--------------------------------------------------------------------------------------------------

-- A convex polygon of m vertices about (0, 0): a regular polygon stretched by (sx, sy) (a
-- stretched convex polygon stays convex), centred on its centroid.
local function newShape(rng, m, radius)
  local sx, sy = rng:range(0.6, 1), rng:range(0.6, 1)
  local phase = rng:range(0, 2 * math.pi)
  local base = {}
  for i = 0, m - 1 do
    local t = phase + i * 2 * math.pi / m
    base[2 * i + 1], base[2 * i + 2] = radius * sx * math.cos(t), radius * sy * math.sin(t)
  end
  local cx, cy = polygon.polygonCentroid(base)
  return polygon.polygonTranslate(base, -cx, -cy, base)
end

local function newStatic(points)
  return { kind = "polygon", points = points, invMass = 0, x = 0, y = 0, spin = 0 }
end

--- A new world: the four walls, a concave floor of three convex parts, 200 polygons (50 of them
-- spinning) and 50 circles, laid out on a lattice of 13 rows from just above the floor up, with
-- small random offsets and velocities: the pile is in contact from the first frames.
local function newWorld(seed)
  local rng = Random.new(seed or 12345)
  local bodies = {
    newStatic({ -WALL, -WALL, 0, -WALL, 0, HEIGHT + WALL, -WALL, HEIGHT + WALL }),                -- left
    newStatic({ WIDTH, -WALL, WIDTH + WALL, -WALL, WIDTH + WALL, HEIGHT + WALL, WIDTH, HEIGHT + WALL }),
    newStatic({ 0, -WALL, WIDTH, -WALL, WIDTH, 0, 0, 0 }),                                       -- top
    newStatic({ 0, HEIGHT, WIDTH, HEIGHT, WIDTH, HEIGHT + WALL, 0, HEIGHT + WALL }),             -- bottom
    -- a concave floor as one shape, a list of convex parts: a ramp down from each side wall and a
    -- bump in the middle. polygonBounds, polygonsCollideV and polygonCircleCollideV take the list.
    newStatic({
      { 0, HEIGHT - 40, 120, HEIGHT, 0, HEIGHT },
      { WIDTH, HEIGHT - 40, WIDTH, HEIGHT, WIDTH - 120, HEIGHT },
      { 280, HEIGHT, 300, HEIGHT - 24, 340, HEIGHT - 24, 360, HEIGHT },
    }),
  }
  for k = 0, 249 do
    local x = 20 + (k % 20) * 31 + rng:range(-3, 3)
    local y = HEIGHT - 54 - floor(k / 20) * 24 + rng:range(-2, 2)   -- rows from above the floor up
    local body = { x = x, y = y, px = x - rng:range(-1, 1), py = y - rng:range(-1, 1), angle = 0 }
    if k % 5 == 4 then   -- every fifth a circle
      body.kind, body.r = "circle", rng:range(5, 10)
      body.invMass = 1 / (math.pi * body.r * body.r)
    else
      body.kind = "polygon"
      body.base = newShape(rng, rng:int(3, 8), rng:range(7, 11))
      body.points = {}
      body.angle = rng:range(0, 2 * math.pi)
      body.spin = (k % 4 == 1) and rng:range(-0.05, 0.05) or 0   -- 50 spin (radians per frame)
      if body.spin == 0 then body.base = polygon.polygonRotate(body.base, body.angle, 0, 0) end
      body.invMass = 1 / polygon.polygonArea(body.base)
    end
    bodies[#bodies + 1] = body
  end
  for i = 1, #bodies do place(bodies[i]) end
  local cols, rows = floor((WIDTH + 2 * WALL) / CELL) + 1, floor((HEIGHT + 2 * WALL) / CELL) + 1
  return { bodies = bodies, grid = Grid.new(CELL, -WALL, -WALL, cols, rows), pairA = {}, pairB = {},
    npairs = 0, moving = {}, fixed = {} }
end

-- One frame: Verlet integration (velocity = this frame's position - last frame's), new points and
-- boxes, the broadphase, then ITERATIONS passes of pairwise resolution and one against the walls.
local function step(world)
  local bodies, grid = world.bodies, world.grid
  local fall = GRAVITY * DT * DT
  for i = 1, #bodies do
    local b = bodies[i]
    if b.invMass > 0 then
      local vx, vy = (b.x - b.px) * DAMPING, (b.y - b.py) * DAMPING + fall
      b.px, b.py = b.x, b.y
      b.x, b.y = b.x + vx, b.y + vy
      if b.spin then b.angle = b.angle + b.spin end
      place(b)
    end
  end
  grid:clear()
  for i = 1, #bodies do
    local b = bodies[i]
    grid:insert(i, b.minx, b.miny, b.maxx, b.maxy)
  end
  local npairs = grid:pairs(#bodies, world.pairA, world.pairB)
  world.npairs = npairs
  -- pairs of two moving shapes, and pairs with a wall or the floor, in two lists
  local pairA, pairB, moving, fixed = world.pairA, world.pairB, world.moving, world.fixed
  local nmoving, nfixed = 0, 0
  for k = 1, npairs do
    local a, b = bodies[pairA[k]], bodies[pairB[k]]
    if a.invMass > 0 and b.invMass > 0 then
      nmoving = nmoving + 1
      moving[nmoving] = k
    elseif a.invMass > 0 or b.invMass > 0 then
      nfixed = nfixed + 1
      fixed[nfixed] = k
    end
  end
  for _ = 1, ITERATIONS do
    for i = 1, nmoving do
      local k = moving[i]
      resolvePair(bodies[pairA[k]], bodies[pairB[k]])
    end
    for i = 1, nfixed do
      local k = fixed[i]
      resolvePair(bodies[pairA[k]], bodies[pairB[k]])
    end
  end
  -- the walls and the floor once more, so that no shape ends the frame in them: what the
  -- iterations leave over stays between moving shapes, and the next frame resolves it
  for i = 1, nfixed do
    local k = fixed[i]
    resolvePair(bodies[pairA[k]], bodies[pairB[k]])
  end
end

-- The largest overlap among this frame's candidate pairs, without resolving anything.
local function largestOverlap(world)
  local bodies, largest = world.bodies, 0
  for k = 1, world.npairs do
    local a, b = bodies[world.pairA[k]], bodies[world.pairB[k]]
    if a.invMass > 0 or b.invMass > 0 then
      local overlap = collidePair(a, b)
      if overlap and overlap > largest then largest = overlap end
    end
  end
  return largest
end

-- A number that changes with any bit of any position: positions weighted by the body's index.
local function checksum(world)
  local sum = 0
  for i = 1, #world.bodies do
    local b = world.bodies[i]
    sum = sum + b.x * i + b.y * (i + 0.5)
  end
  return sum
end

-- How far any body reaches outside the arena now (0 when every body is inside).
local function escape(world)
  local worst = 0
  for i = 1, #world.bodies do
    local b = world.bodies[i]
    if b.invMass > 0 then
      local minx, miny, maxx, maxy
      if b.kind == "polygon" then
        minx, miny, maxx, maxy = polygon.polygonBounds(b.points)
      else
        minx, miny, maxx, maxy = b.x - b.r, b.y - b.r, b.x + b.r, b.y + b.r
      end
      worst = math.max(worst, -minx, -miny, maxx - WIDTH, maxy - HEIGHT)
    end
  end
  return worst
end

local arena = { WIDTH = WIDTH, HEIGHT = HEIGHT, Random = Random, Grid = Grid, newWorld = newWorld,
  step = step }

-- The module's calls counted: a table with the same functions, each adding the heap growth
-- during its calls to moduleGarbage (the collector stopped). Built once, outside the frames.
local moduleGarbage = { kb = 0, calls = 0, growingCalls = 0, lastFrame = 0, frame = 0 }
local function countingModule(module)
  local counted, tally = {}, moduleGarbage
  for _, fname in ipairs({ "polygonsCollideV", "polygonCircleCollideV", "circlesCollideV",
      "polygonBounds", "polygonTranslate", "polygonRotate" }) do
    local fn = module[fname]
    counted[fname] = function(a, b, c, d, e, f)
      local before = collectgarbage("count")
      local r1, r2, r3, r4 = fn(a, b, c, d, e, f)
      local grown = collectgarbage("count") - before
      tally.calls = tally.calls + 1
      if grown > 0 then
        tally.kb, tally.growingCalls, tally.lastFrame = tally.kb + grown, tally.growingCalls + 1,
          tally.frame
      end
      return r1, r2, r3, r4
    end
  end
  return counted
end

--- Runs `frames` frames (300 by default) of the world from `seed` twice: once timed, once with
-- the module's calls counted. Returns a table:
-- msPerFrame: os.clock time of `step` per frame, in the timed run (collector running);
-- garbageKB: the heap growth during the module's calls over all frames of the counted run, the
--   collector stopped; garbageCalls: how many calls grew the heap, out of calls; lastGarbageFrame:
--   the last frame in which one did (0: none). On LuaJIT the counted run has the JIT compiler
--   off, so that compiling traces does not count: compiled code allocates no more than the
--   interpreter (allocation sinking only removes allocations). Growth in the first frames is the
--   interpreter's stack and the module's scratch arrays reaching their size, once.
-- maxOverlap: the largest overlap left after a frame's resolution, over all frames;
-- escape: how far any shape reached outside the arena after a frame, over all frames (0: none);
-- checksum: of the final positions (the same in both runs, checked); pairs: the last frame's
--   candidate pairs; bodies.
function arena.run(frames, seed)
  frames = frames or 300
  local world = newWorld(seed)
  local time = 0
  for _ = 1, frames do
    local t0 = os.clock()
    step(world)
    time = time + (os.clock() - t0)
  end
  local timedChecksum = checksum(world)

  world = newWorld(seed)
  local plain = polygon
  polygon = countingModule(plain)   -- every function above now calls through the counters
  local jit = rawget(_G, "jit")
  -- off and flushed: traces compiled in the timed run would otherwise go on running, and their
  -- exits to the interpreter allocate (measured: 80 KB in 10 frames with jit.off() alone, 0.7
  -- with the flush, all of it in frame 1)
  if jit then jit.off(); jit.flush() end
  local tally = moduleGarbage
  tally.kb, tally.calls, tally.growingCalls, tally.lastFrame = 0, 0, 0, 0
  local maxOverlap, worstEscape = 0, 0
  collectgarbage("collect")
  collectgarbage("stop")
  for f = 1, frames do
    tally.frame = f
    step(world)
    local overlap = largestOverlap(world)
    if overlap > maxOverlap then maxOverlap = overlap end
    local e = escape(world)
    if e > worstEscape then worstEscape = e end
  end
  collectgarbage("restart")
  if jit then jit.on() end
  polygon = plain
  local sum = checksum(world)
  assert(sum == timedChecksum, "the timed and the counted runs differ: not deterministic")
  return { frames = frames, msPerFrame = time * 1000 / frames, garbageKB = tally.kb,
    calls = tally.calls, garbageCalls = tally.growingCalls, lastGarbageFrame = tally.lastFrame,
    maxOverlap = maxOverlap, escape = worstEscape, checksum = sum, pairs = world.npairs,
    bodies = #world.bodies }
end

if type(requiredAs) == "string" and requiredAs:match("arena$") then return arena end

-- LuaJIT keeps at most 1000 traces in 512 KB of machine code by default. The exact fallbacks and
-- compound shapes of polygon.lua give it many side traces; once either limit is reached it
-- flushes every trace and starts over (`luajit -jv` shows "failed to allocate mcode memory"), and
-- this scene runs several times slower. A game with much branchy Lua code raises the limits the
-- same way, once at start-up: `luajit examples/arena.lua 300 default` keeps LuaJIT's defaults.
local jit = rawget(_G, "jit")
if jit and arg[2] ~= "default" then jit.opt.start("maxtrace=8000", "maxmcode=16384") end
local frames = tonumber(arg and arg[1]) or 300
local stats = arena.run(frames)
print(("arena: %d bodies, %d frames on %s"):format(stats.bodies, stats.frames,
  rawget(_G, "jit") and rawget(_G, "jit").version or _VERSION))
print(("  ms per frame            %.3f"):format(stats.msPerFrame))
print(("  module garbage          %.3f KB in all, %.4f KB per frame: %d of %d calls grew the heap,"
  .. " the last in frame %d"):format(stats.garbageKB, stats.garbageKB / stats.frames,
  stats.garbageCalls, stats.calls, stats.lastGarbageFrame))
print(("  largest overlap left    %.6f px"):format(stats.maxOverlap))
print(("  furthest escape         %.6f px"):format(stats.escape))
print(("  candidate pairs (last)  %d"):format(stats.pairs))
print(("  checksum                %.17g"):format(stats.checksum))
return arena
