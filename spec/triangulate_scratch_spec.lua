-- polygonTriangulate and polygonConvexParts keep their work arrays from one call to the next
-- (polygon/sweep.lua's scratch, for calls of up to 2,048 nodes): a call must answer the same
-- whatever came before it. Each input's answer from a fresh copy of the library (loaded anew,
-- its arrays never used) is compared with the shared copy's after other inputs, larger or
-- smaller, with or without holes, valid or refused, left the arrays full of other values.

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
