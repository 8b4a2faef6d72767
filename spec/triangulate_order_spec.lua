-- The order of the validity check's sweep (polygon/order.lua): the edges along the vertical line
-- in blocks of at most 32 entries, each edge linked to its neighbours. First the structure alone,
-- against a plain sorted list, with numbers for edges and blocks small enough to split, merge
-- and share every few steps; then the sweep with blocks of 4 and 6 on random outlines with
-- random holes and on noisy circles, whose verdicts must stay the oracle's.

local polygon = require "polygon"
local order = require "polygon.order"
local nodes = require "polygon.nodes"
local sweep = require "polygon.sweep"
local oracle = require "oracle"
local prng = require "prng"
local holes = require "holes"
local shapes = require "shapes"

local JIT = rawget(_G, "jit") ~= nil
local INDEX = require "seeds"   -- this interpreter's range of seeds

-- Runs f with blocks of `size` entries, and puts the size back even when f fails.
local function withBlocks(size, f)
  local old = order.blockSize(size)
  local ok, err = pcall(f)
  order.blockSize(old)
  if not ok then error(err, 0) end
end

-- Random steps on the order and on a sorted list side by side, edge k standing for the number
-- value[k] ("above" compares the numbers, ties 0, as edges in line): an edge comes in where
-- find puts it, or beside an edge of its value (as the sweep puts an edge beside the last one),
-- or an edge leaves, or a new edge of the same value takes an edge's place. After each step,
-- every edge's neighbours and find's answer for every edge are the list's. The order starts
-- again (a new sweep on the same arrays, as the scratch pool keeps them) at a random step of the
-- second half, with the blocks of the first still in its arrays. Returns the most edges the
-- order held.
local function randomSteps(size, seed, steps)
  local rng = prng.new(seed)
  local value, list, made, most = {}, {}, 0, 0
  local function above(s, t) return value[s] > value[t] and 1 or value[s] < value[t] and -1 or 0 end
  local oldCompare = order.compare(above)
  nodes.usePool(2 * steps)
  local ok, err = pcall(withBlocks, size, function()
    local up, down = order.reset(steps, 2 * steps)
    local again = rng:int(steps / 2, steps * 3 / 4)
    for step = 1, steps do
      local where = ("blocks of %d, seed %d, step %d"):format(size, seed, step)
      if step == again then
        up, down = order.reset(steps, 2 * steps)
        list = {}
      end
      local choice = rng:float()
      -- more edges come in than leave, up to the second start, then fewer: the order grows and
      -- shrinks, so that blocks split, then merge and share
      local grow = step < again * 0.8 and 0.65 or step < again and 0.2 or 0.6
      if #list == 0 or choice < grow then
        made = made + 1
        local k = made
        value[k] = rng:int(1, 50)
        local i = 1
        while list[i] and value[list[i]] < value[k] do i = i + 1 end
        local near = list[i]
        if near and value[near] == value[k] and rng:float() < 0.5 then
          -- beside `near`: just below it (its place), or just above it
          local aboveIt = rng:float() < 0.5
          local b, at = order.beside(near, aboveIt)
          order.insert(b, at, k)
          if aboveIt then i = i + 1 end
        else
          local b, at = order.find(k)
          order.insert(b, at, k)
        end
        table.insert(list, i, k)
      elseif choice < grow + 0.1 then
        local i = rng:int(1, #list)
        made = made + 1
        value[made] = value[list[i]]
        order.replace(list[i], made)
        list[i] = made
      else
        local i = rng:int(1, #list)
        order.remove(list[i])
        table.remove(list, i)
      end
      most = math.max(most, #list)
      for i, f in ipairs(list) do
        assert.are.equal(list[i - 1] or false, down[f], where .. ": below " .. f)
        assert.are.equal(list[i + 1] or false, up[f], where .. ": above " .. f)
      end
      for _, f in ipairs(list) do
        local first   -- the first edge not below f
        for _, g in ipairs(list) do if value[g] >= value[f] then first = g; break end end
        assert.are.equal(first, order.edgeAt(order.find(f)), where .. ": find " .. f)
      end
    end
  end)
  order.compare(oldCompare)
  if not ok then error(err, 0) end
  return most
end

-- polygonTriangulate by the sweep (the grid turned off): the triangles or nil, the message.
local function bySweep(points, list)
  sweep.grid = false
  local ok, tris, message = pcall(polygon.polygonTriangulate, points, list)
  sweep.grid = true
  if not ok then error(tris, 0) end
  return tris, message
end

local function checkCase(points, list, where)
  local verdict = oracle.regionCrossing(points, list)
  local ok, why = oracle.agrees(points, list, verdict, bySweep(points, list))
  assert(ok, where .. ": " .. tostring(why))
  return verdict
end

describe("the sweep's order in blocks", function()
  describe("against a sorted list of numbers", function()
    it("keeps every neighbour and every search as the list, as blocks split, merge and share", function()
      for _, size in ipairs({ 4, 6, 32 }) do
        for seed = 1, 4 do
          local most = randomSteps(size, 9100 + 10 * INDEX + seed, 600)
          -- the order held several blocks' worth: splits happened
          assert.is_true(most > 2 * size, ("blocks of %d held %d at most"):format(size, most))
        end
      end
    end)
  end)

  describe("in the sweep, with blocks of 4 and 6", function()
    it("gives random outlines with random holes the oracle's verdicts", function()
      local verdicts = {}
      for _, size in ipairs({ 4, 6 }) do
        withBlocks(size, function()
          local first = 530000 + INDEX * 1000 + size * 100
          for seed = first, first + (JIT and 60 or 100) do
            local points, list = holes.case(prng.new(seed))
            local verdict = checkCase(points, list, ("blocks of %d, seed %d"):format(size, seed))
            verdicts[verdict] = (verdicts[verdict] or 0) + 1
          end
        end)
      end
      assert.is_true((verdicts.valid or 0) > 20 and (verdicts.cross or 0) > 0, "verdicts of each kind")
    end)

    it("triangulates noisy circles (hundreds of edges along the line) as the oracle covers them", function()
      withBlocks(4, function()
        for _, n in ipairs({ 300, 1000 }) do
          checkCase(shapes.noisyCircle(n, prng.new(n + INDEX)), {}, "noisy circle " .. n)
        end
      end)
    end)

    it("finds a crossing made in a noisy circle", function()
      withBlocks(4, function()
        -- two vertices of a noisy circle swapped: the edges around them cross
        local points = shapes.noisyCircle(400, prng.new(41 + INDEX))
        points[201], points[203] = points[203], points[201]
        points[202], points[204] = points[204], points[202]
        checkCase(points, {}, "noisy circle, two vertices swapped")
      end)
    end)
  end)
end)
