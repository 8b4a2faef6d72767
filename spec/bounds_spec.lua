-- polygonBounds(points): minx, miny, maxx, maxy of a flat array or of a list of convex parts.
local polygon = require "polygon"
local shapes = require "shapes"
local garbage = require "garbage"
local callsite = require "callsite"

local bounds = polygon.polygonBounds

local TRIANGLE = { 5, 13, 12, 6, 15, 15 }            -- clockwise on screen
local SQUARE = { 0, 0, 10, 0, 10, 10, 0, 10 }
local WEDGE = { 20, -5, 30, 0, 25, 8 }

local function box(points)
  return { bounds(points) }
end

describe("polygonBounds", function()
  describe("when given a flat array", function()
    -- x in {5, 12, 15}: 5 .. 15; y in {13, 6, 15}: 6 .. 15
    it("returns 5, 6, 15, 15 for the triangle in both windings", function()
      assert.are.same({ 5, 6, 15, 15 }, box(TRIANGLE))
      assert.are.same({ 5, 6, 15, 15 }, box(shapes.reverse(TRIANGLE)))
    end)

    it("returns the point twice for a single point and nil for no points", function()
      assert.are.same({ 3, -4, 3, -4 }, box({ 3, -4 }))
      assert.is_nil(bounds({}))
    end)

    -- Lua 5.3+ only (5.1, 5.2 and LuaJIT have no integers): the box comes back as floats, so
    -- arithmetic a caller does with it rounds the same way on every interpreter
    local mathType = rawget(math, "type")
    if mathType then
      it("returns floats for integer coordinates", function()
        local minx, miny, maxx, maxy = bounds(SQUARE)
        assert.are.same({ 0, 0, 10, 10 }, { minx, miny, maxx, maxy })
        for _, v in ipairs({ minx, miny, maxx, maxy }) do assert.are.equal("float", mathType(v)) end
      end)
    end

    it("keeps far coordinates exact: the box of a square moved to 1e15", function()
      local far = shapes.translate(SQUARE, 1e15, -1e15)
      -- 1e15 + 10 is exact (below 2^53)
      assert.are.same({ 1e15, -1e15, 1e15 + 10, -1e15 + 10 }, box(far))
    end)
  end)

  describe("when given a list of convex parts", function()
    -- square 0 .. 10 x 0 .. 10 and wedge 20 .. 30 x -5 .. 8: together 0 .. 30 x -5 .. 10
    it("returns the box of all parts, in both windings", function()
      assert.are.same({ 0, -5, 30, 10 }, box({ SQUARE, WEDGE }))
      assert.are.same({ 0, -5, 30, 10 }, box({ shapes.reverse(WEDGE), shapes.reverse(SQUARE) }))
    end)

    it("equals the box of the parts' coordinates joined into one array", function()
      local joined = {}
      for _, part in ipairs({ SQUARE, WEDGE, TRIANGLE }) do
        for i = 1, #part do joined[#joined + 1] = part[i] end
      end
      assert.are.same(box(joined), box({ SQUARE, WEDGE, TRIANGLE }))
    end)

    it("skips empty parts and returns nil when every part is empty", function()
      assert.are.same({ 20, -5, 30, 8 }, box({ {}, WEDGE, {} }))
      assert.is_nil(bounds({ {}, {} }))
    end)
  end)

  describe("when an argument is wrong", function()
    it("names the function, the argument and what it got", function()
      assert.has_error(function() bounds(nil) end, "polygonBounds: points must be a table, got nil")
      assert.has_error(function() bounds({ 1, 2, 3 }) end,
        "polygonBounds: points must hold an even number of coordinates, got 3")
      assert.has_error(function() bounds({ SQUARE, 7 }) end,
        "polygonBounds: points[2] must be a table, got number")
      assert.has_error(function() bounds({ SQUARE, { 1, 2, 3 } }) end,
        "polygonBounds: points[2] must hold an even number of coordinates, got 3")
    end)

    it("raises the error at the caller's level", function()
      assert.is_true(callsite.raisesAtCaller(bounds, { "square" }))
    end)
  end)

  describe("per call", function()
    it("allocates less than 1 KB over 10000 calls, flat and with parts", function()
      local inputs = { SQUARE, TRIANGLE, { SQUARE, WEDGE }, {}, { 3, 4 } }
      local kb = garbage.growth(function(i) bounds(inputs[i % #inputs + 1]) end, 10000)
      assert.is_true(kb < 1, ("%.3f KB"):format(kb))
    end)
  end)
end)
