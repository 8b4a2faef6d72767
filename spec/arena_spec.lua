-- examples/arena.lua as a module: 60 frames of its 255 shapes (the walls, the concave floor of
-- three convex parts, 200 polygons, 50 circles), run through arena.run. By frame 60 the pile has
-- slumped onto the floor: the largest overlap of the 300-frame run (2.84 px) happens by then.
local arena = require "examples.arena"
local polygon = require "polygon"
local prng = require "prng"
local interpreter = require "interpreter"

local FRAMES = 60
-- Recorded from a real run: the line "checksum 24115748.062509604" that
-- `lua5.4 examples/arena.lua 60` prints, printed alike by `lua5.1`, `lua5.2`, `lua5.3` and
-- `luajit examples/arena.lua 60` (recorded again, unchanged, when the arena got its own copy of
-- the specs' generator: the same draws give the same world; recorded again when pushes out of
-- rectangles became the exact depth, v0.8.0). This spec runs on all five, so its
-- passing everywhere is the cross-interpreter determinism of the whole simulation.
local CHECKSUM = "24115748.062509604"

-- Copies polygon.lua (and its polygon/ folder, when there is one) and examples/arena.lua into a
-- new empty directory and runs the script there for `frames` frames, with no LUA_PATH or LUA_INIT
-- of the caller's: what a game that copies the two files gets. Returns its output and exit status.
local function runCopied(frames)
  local lua = assert(interpreter())
  local mk = assert(io.popen("mktemp -d"))
  local dir = mk:read("*l")
  mk:close()
  assert(dir and dir:match("^[%w%./_%-]+$"), "mktemp -d gave " .. tostring(dir))
  local script = table.concat({
    "cp polygon.lua examples/arena.lua " .. dir,
    "if [ -d polygon ]; then cp -R polygon " .. dir .. "/; fi",
    "cd " .. dir,
    "unset LUA_PATH LUA_PATH_5_2 LUA_PATH_5_3 LUA_PATH_5_4 LUA_INIT LUA_INIT_5_2 LUA_INIT_5_3 LUA_INIT_5_4",
    lua .. " arena.lua " .. frames .. " 2>&1",
    "echo \"@@exit status: $?\"",
  }, "\n")
  local pipe = assert(io.popen("(" .. script .. ")"))
  local out = pipe:read("*a")
  pipe:close()
  os.execute("rm -rf " .. dir)
  return out, tonumber(out:match("@@exit status: (%d+)"))
end

-- The thinnest shape's width: for a polygon the least extent over its edge normals (the width
-- of a convex polygon is attained on an edge normal), for a circle its diameter.
local function thinnestWidth(bodies)
  local thinnest = math.huge
  for _, b in ipairs(bodies) do
    if b.invMass > 0 then
      if b.kind == "circle" then
        thinnest = math.min(thinnest, 2 * b.r)
      else
        local p, n = b.base, #b.base
        local ax, ay = p[n - 1], p[n]
        for i = 1, n - 1, 2 do
          local bx, by = p[i], p[i + 1]
          local len = math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay))
          local lo, hi = polygon.projectPolygon(p, ax, ay, (by - ay) / len, (ax - bx) / len)
          thinnest = math.min(thinnest, hi - lo)
          ax, ay = bx, by
        end
      end
    end
  end
  return thinnest
end

describe("examples/arena.lua", function()
  local stats
  setup(function() stats = arena.run(FRAMES) end)

  it("ends with the checksum its script prints for " .. FRAMES .. " frames, on every interpreter", function()
    assert.are.equal(CHECKSUM, ("%.17g"):format(stats.checksum))
    assert.are.equal(255, stats.bodies)
  end)

  it("resolves real contacts: hundreds of candidate pairs, over 100000 module calls", function()
    assert.is_true(stats.pairs > 200, tostring(stats.pairs))
    assert.is_true(stats.calls > 100000, tostring(stats.calls))
  end)

  -- A call that built one table would grow the heap by 16+ bytes per call, 2+ MB in all; what
  -- does grow is a few one-time allocations in the first frames (the interpreter's stack, the
  -- exact path's scratch array, the floor's list of parts prepared on first use), measured at
  -- 7.8 to 13 KB in 2 to 5 calls, none after frame 17, on the five interpreters (60 frames).
  it("grows the heap by less than 16 KB over all the module's calls, in at most 8 calls", function()
    assert.is_true(stats.garbageKB < 16, ("%.3f KB"):format(stats.garbageKB))
    assert.is_true(stats.garbageCalls <= 8, tostring(stats.garbageCalls))
  end)

  -- The walls are resolved last in every frame, so a shape ends a frame touching a wall at most:
  -- out by the rounding of a push, a few ulps of 640 (1.1e-13 each).
  it("keeps every shape inside the arena, up to rounding", function()
    assert.is_true(stats.escape <= 1e-9, tostring(stats.escape))
  end)

  -- What the iterations leave over must stay below half the thinnest shape's width: then the
  -- minimum translation vector of an overlapping pair still points out the near side (a shape
  -- pushed in by more than half its width is nearer to leaving by the far side) and no shape
  -- can pass through another.
  it("leaves every overlap below half the thinnest shape's width", function()
    local half = thinnestWidth(arena.newWorld().bodies) / 2
    assert.is_true(half > 1, tostring(half))
    assert.is_true(stats.maxOverlap < half, ("%.4f >= %.4f"):format(stats.maxOverlap, half))
  end)
end)

describe("examples/arena.lua copied beside polygon.lua into an empty directory", function()
  it("runs there and prints the same checksum for " .. FRAMES .. " frames", function()
    local out, status = runCopied(FRAMES)
    assert.are.equal(0, status, out)
    assert.is_truthy(out:find("\n  checksum%s+" .. CHECKSUM:gsub("%.", "%%.") .. "\n"), out)
  end)
end)

describe("the arena's random generator", function()
  -- the arena keeps its own copy so that it needs only polygon.lua; it must stay the specs' one
  it("draws the same integers and numbers as spec/support/prng.lua, from the same seeds", function()
    for _, seed in ipairs({ 12345, 99, 1, 2147483646 }) do
      local ours, specs = arena.Random.new(seed), prng.new(seed)
      for _ = 1, 200 do
        assert.are.equal(specs:int(3, 8), ours:int(3, 8))
        assert.are.equal(specs:range(-3, 3), ours:range(-3, 3))
      end
    end
  end)

  it("starts from 1 when the seed is a multiple of 2^31 - 1, not from 0 (where it would stay)", function()
    assert.are.equal(48271, arena.Random.new(0):next())
    assert.are.equal(48271, arena.Random.new(2147483647):next())
  end)
end)

describe("the arena's grid broadphase", function()
  -- every pair of boxes that overlap (or touch) shares a cell, so the grid must list it, once
  it("lists every overlapping pair of 300 random boxes once, in the same order twice", function()
    local rng = prng.new(99)
    local boxes = {}
    for i = 1, 300 do
      -- some beyond the grid (x past 860, y past 700): clamped into its border cells
      local x, y, w, h = rng:range(-150, 950), rng:range(-150, 750), rng:range(1, 40), rng:range(1, 40)
      boxes[i] = { x, y, x + w, y + h }
    end
    local grid = arena.Grid.new(32, -100, -100, 30, 25)
    local function listed()
      grid:clear()
      for i, b in ipairs(boxes) do grid:insert(i, b[1], b[2], b[3], b[4]) end
      local pairA, pairB = {}, {}
      local n = grid:pairs(#boxes, pairA, pairB)
      local seen, order = {}, {}
      for k = 1, n do
        local key = pairA[k] .. ":" .. pairB[k]
        assert.is_nil(seen[key], "listed twice: " .. key)
        assert.is_true(pairA[k] < pairB[k])
        seen[key], order[k] = true, key
      end
      return seen, order, n
    end
    local seen, order, n = listed()
    local overlapping = 0
    for i = 1, #boxes do
      for j = i + 1, #boxes do
        local a, b = boxes[i], boxes[j]
        if a[1] <= b[3] and b[1] <= a[3] and a[2] <= b[4] and b[2] <= a[4] then
          overlapping = overlapping + 1
          assert.is_true(seen[i .. ":" .. j], "missing " .. i .. ":" .. j)
        end
      end
    end
    assert.is_true(overlapping > 50, tostring(overlapping))
    assert.is_true(n >= overlapping)
    local _, again = listed()
    assert.are.same(order, again)
  end)
end)
