-- polygonTriangulate and polygonConvexParts keep their work arrays from one call to the next
-- (polygon/nodes.lua's scratch: kept for calls of up to 2,048 nodes, held weakly past that): a
-- call must answer the same whatever came before it. Each input's answer from a fresh copy of
-- the library (loaded anew, its arrays never used) is compared with the shared copy's after
-- other inputs, larger or smaller, with or without holes, valid or refused, left the arrays
-- full of other values.

local polygon = require "polygon"
local prng = require "prng"
local shapes = require "shapes"
local holes = require "holes"
local earcut = require "earcut"

local triangulate, convexParts = polygon.polygonTriangulate, polygon.polygonConvexParts

-- The inputs: outlines with holes of a few to a thousand vertices, hole-free noisy circles, and
-- refused ones (a bow-tie, a hole crossing the outline), in an order that alternates sizes.
local function inputs()
  local list = {}
  local rng = prng.new(2020)
  for _ = 1, 12 do
    local points, rings = holes.case(rng)
    list[#list + 1] = { points, rings }
  end
  list[#list + 1] = { shapes.noisyCircle(300, prng.new(300)), {} }
  list[#list + 1] = { earcut.load("water2") }
  list[#list + 1] = { shapes.noisyCircle(40, prng.new(40)), {} }
  list[#list + 1] = { { 0, 0, 10, 10, 10, 0, 0, 10 }, {} }                          -- a bow-tie
  list[#list + 1] = { { 0, 0, 10, 0, 10, 10, 0, 10 }, { { 5, 5, 15, 5, 15, 6, 5, 6 } } }  -- a hole across
  list[#list + 1] = { earcut.load("eberly-6") }
  -- a noisy circle with two vertices swapped at its right end: refused once the sweep has
  -- nearly passed it, its order of edges full
  local crossed = shapes.noisyCircle(300, prng.new(301))
  local right = 1
  for i = 1, #crossed - 3, 2 do if crossed[i] > crossed[right] then right = i end end
  right = math.min(right, #crossed - 3)
  crossed[right], crossed[right + 2] = crossed[right + 2], crossed[right]
  crossed[right + 1], crossed[right + 3] = crossed[right + 3], crossed[right + 1]
  list[#list + 1] = { crossed, {} }
  list[#list + 1] = { shapes.noisyCircle(300, prng.new(301)), {} }   -- the same, valid
  list[#list + 1] = { { 0, 0, 10, 0, 10, 10, 0, 10 }, { { 4, 4, 4, 6, 6, 6, 6, 4 } } }
  return list
end

-- A copy of the library loaded anew (its own module state), the shared one left in place.
local function freshLibrary()
  local saved = {}
  for name, module in pairs(package.loaded) do
    if name == "polygon" or name:sub(1, 8) == "polygon." then saved[name] = module end
  end
  for name in pairs(saved) do package.loaded[name] = nil end
  local fresh = require "polygon"
  for name in pairs(package.loaded) do
    if name == "polygon" or name:sub(1, 8) == "polygon." then package.loaded[name] = nil end
  end
  for name, module in pairs(saved) do package.loaded[name] = module end
  return fresh
end

-- An answer as a string: every number of every piece, or the message.
local function answer(fn, points, rings)
  local pieces, message = fn(points, rings)
  if not pieces then return "nil: " .. tostring(message) end
  local out = {}
  for i, piece in ipairs(pieces) do
    local cells = {}
    for j, v in ipairs(piece) do cells[j] = ("%.17g"):format(v) end
    out[i] = table.concat(cells, ",")
  end
  return table.concat(out, ";")
end

for _, fn in ipairs({ { "polygonTriangulate", triangulate }, { "polygonConvexParts", convexParts } }) do
  describe(fn[1] .. " after other calls", function()
    it("answers each input as a fresh copy of the library does, in order, reversed, interleaved", function()
      local list = inputs()
      local first = {}
      for i, case in ipairs(list) do first[i] = answer(freshLibrary()[fn[1]], case[1], case[2]) end
      assert.are_not.equal(freshLibrary()[fn[1]], fn[2])   -- the copies are other functions
      for i = 1, #list do
        assert.are.equal(first[i], answer(fn[2], list[i][1], list[i][2]))
      end
      -- some answers are refusals and some are pieces: the list holds both kinds
      local refused = 0
      for i = 1, #first do if first[i]:sub(1, 4) == "nil:" then refused = refused + 1 end end
      assert.is_true(refused >= 2 and refused < #first)
      for i = #list, 1, -1 do
        assert.are.equal(first[i], answer(fn[2], list[i][1], list[i][2]))
      end
      for i = 1, #list do   -- each after the largest and after the smallest
        answer(fn[2], list[14][1], list[14][2])
        assert.are.equal(first[i], answer(fn[2], list[i][1], list[i][2]))
        answer(fn[2], list[#list][1], list[#list][2])
        assert.are.equal(first[i], answer(fn[2], list[i][1], list[i][2]))
      end
    end)
  end)
end

-- Past 2,048 nodes a call's arrays are held weakly (polygon/nodes.lua, bigPool): the next large
-- call takes them unless the collector has freed them. The same answers, in any order, and
-- nothing of them kept once the collector has run.
local tiles = require "tiles"

local function largeInputs()
  local list = {}
  list[#list + 1] = { shapes.noisyCircle(2600, prng.new(2600)), {} }
  local rng = prng.new(80)
  local set = tiles.random(rng, 80, 80, 0.85)   -- a tile map of 80 by 80 with its border filled
  for c = 1, 80 do set[1][c], set[80][c], set[c][1], set[c][80] = true, true, true, true end
  local best
  for _, shape in ipairs(tiles.shapes(set, 10, 0, 0)) do
    if not best or #shape[1] > #best[1] then best = shape end
  end
  list[#list + 1] = { best[1], best[2] }
  list[#list + 1] = { shapes.noisyCircle(4000, prng.new(4000)), {} }
  local crossed = shapes.noisyCircle(3000, prng.new(3000))   -- two vertices swapped: refused
  crossed[101], crossed[103] = crossed[103], crossed[101]
  crossed[102], crossed[104] = crossed[104], crossed[102]
  list[#list + 1] = { crossed, {} }
  list[#list + 1] = { earcut.load("rain") }
  return list
end

describe("polygonTriangulate past 2,048 nodes", function()
  it("answers each input as a fresh copy of the library does, in order and reversed", function()
    local list = largeInputs()
    local first, nodesOf = {}, {}
    for i, case in ipairs(list) do
      first[i] = answer(freshLibrary().polygonTriangulate, case[1], case[2])
      local count = #case[1] / 2
      for _, ring in ipairs(case[2]) do count = count + #ring / 2 end
      nodesOf[i] = count
    end
    for i = 1, #list do assert.is_true(nodesOf[i] > 2048, "input " .. i .. " is small") end
    assert.are.equal("nil: ", first[4]:sub(1, 5))   -- the crossed one is refused, the rest not
    for i = 1, #list do
      if i ~= 4 then assert.are_not.equal("nil: ", first[i]:sub(1, 5)) end
    end
    for i = 1, #list do assert.are.equal(first[i], answer(triangulate, list[i][1], list[i][2])) end
    for i = #list, 1, -1 do assert.are.equal(first[i], answer(triangulate, list[i][1], list[i][2])) end
    for i = 1, #list do   -- each after a small call, which takes the other pool
      answer(triangulate, list[1][1], { { 1, 1, 2, 1, 2, 2 } })
      answer(triangulate, { 0, 0, 10, 0, 10, 10, 0, 10 }, {})
      assert.are.equal(first[i], answer(triangulate, list[i][1], list[i][2]))
    end
  end)

  it("keeps nothing of a large call's arrays once the collector has run", function()
    local points = shapes.noisyCircle(10000, prng.new(10000))
    triangulate(shapes.noisyCircle(3000, prng.new(1)), {})   -- the pools as a game's would be
    triangulate({ 0, 0, 10, 0, 10, 10, 0, 10 }, {})
    collectgarbage("collect"); collectgarbage("collect")
    local before = collectgarbage("count")
    local tris = triangulate(points, {})
    assert.are.equal(9998, #tris)   -- n - 2 triangles
    tris = nil -- luacheck: ignore
    local during = collectgarbage("count")
    collectgarbage("collect"); collectgarbage("collect")
    local kept = collectgarbage("count") - before
    -- the call's arrays are 40-odd of 10,000 entries, megabytes (LuaJIT 2.5 MB counted after the
    -- call, Lua 5.4 7.7 MB): a few KB stay (the hole lists' tables), far below one array's 80 KB
    assert.is_true(during - before > 1000, "the call made its arrays")
    assert.is_true(kept < 60, ("%.0f KB kept"):format(kept))
  end)
end)
