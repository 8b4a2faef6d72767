-- polygonTranslate(points, dx, dy [, out]): the polygon moved by (dx, dy), into out or a new table.
local polygon = require "polygon"
local shapes = require "shapes"
local oracle = require "oracle"
local garbage = require "garbage"
local callsite = require "callsite"

local translate = polygon.polygonTranslate

local SQUARE = { 0, 0, 10, 0, 10, 10, 0, 10 }    -- clockwise on screen
local WEDGE = { 20, -5, 30, 0, 25, 8 }

describe("polygonTranslate", function()
  describe("when given a flat array and no out", function()
    -- every x + 3, every y - 2
    it("returns a new table with the square moved by (3, -2), in both windings", function()
      local moved = translate(SQUARE, 3, -2)
      assert.are_not.equal(SQUARE, moved)
      assert.are.same({ 3, -2, 13, -2, 13, 8, 3, 8 }, moved)
      assert.are.same({ 3, 8, 13, 8, 13, -2, 3, -2 }, translate(shapes.reverse(SQUARE), 3, -2))
    end)

    it("leaves the input unchanged and keeps the winding", function()
      for _, p in ipairs({ SQUARE, shapes.reverse(SQUARE) }) do
        local copy = shapes.deepCopy(p)
        local moved = translate(p, 0.5, 1e6)
        assert.are.same(copy, p)
        assert.are.equal(oracle.winding(p), oracle.winding(moved))
      end
    end)

    it("rounds each coordinate once: 0.1 moved by 0.2 is the double 0.1 + 0.2", function()
      local moved = translate({ 0.1, 0.7, 1, 1, 0, 1 }, 0.2, 0.1)
      assert.are.equal(0.1 + 0.2, moved[1])
      assert.are.equal(0.7 + 0.1, moved[2])
    end)

    it("returns an empty table for no points", function()
      assert.are.same({}, translate({}, 1, 2))
    end)
  end)

  describe("when given out", function()
    it("writes into out, returns it, and drops what out held beyond the result", function()
      local out = { 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9 }
      local got = translate(WEDGE, -20, 5, out)
      assert.are.equal(out, got)
      -- (20, -5) -> (0, 0); (30, 0) -> (10, 5); (25, 8) -> (5, 13)
      assert.are.same({ 0, 0, 10, 5, 5, 13 }, out)
    end)

    it("moves in place when out is points itself", function()
      local p = { 20, -5, 30, 0, 25, 8 }
      assert.are.equal(p, translate(p, 1, 1, p))
      assert.are.same({ 21, -4, 31, 1, 26, 9 }, p)
    end)
  end)

  describe("when given a list of convex parts", function()
    it("moves every part, into a new list of new parts without out", function()
      local parts = { SQUARE, WEDGE }
      local moved = translate(parts, 1, -1)
      assert.are_not.equal(parts, moved)
      assert.are_not.equal(SQUARE, moved[1])
      assert.are.same({ { 1, -1, 11, -1, 11, 9, 1, 9 }, { 21, -6, 31, -1, 26, 7 } }, moved)
      assert.are.same({ 0, 0, 10, 0, 10, 10, 0, 10 }, SQUARE)
    end)

    it("reuses out's part tables, creates missing ones, and drops extra parts", function()
      local first = { 7, 7 }
      local out = { first, nil }
      translate({ SQUARE, WEDGE }, 0, 10, out)
      assert.are.equal(first, out[1])
      assert.are.same({ { 0, 10, 10, 10, 10, 20, 0, 20 }, { 20, 5, 30, 10, 25, 18 } }, out)
      translate({ WEDGE }, 0, 0, out)
      assert.are.equal(first, out[1])
      assert.are.same({ { 20, -5, 30, 0, 25, 8 } }, out)
    end)

    it("moves in place when out is the list itself", function()
      local a, b = { 0, 0, 1, 0, 0, 1 }, { 5, 5, 6, 5, 5, 6 }
      local parts = { a, b }
      translate(parts, 2, 3, parts)
      assert.are.equal(a, parts[1])
      assert.are.same({ { 2, 3, 3, 3, 2, 4 }, { 7, 8, 8, 8, 7, 9 } }, parts)
    end)
  end)

  describe("when an argument is wrong", function()
    local cases = {
      { { nil, 1, 2 }, "polygonTranslate: points must be a table, got nil" },
      { { { 1, 2, 3 }, 1, 2 }, "polygonTranslate: points must hold an even number of coordinates, got 3" },
      { { { SQUARE, true }, 1, 2 }, "polygonTranslate: points[2] must be a table, got boolean" },
      { { SQUARE, "1", 2 }, "polygonTranslate: dx must be a number, got string" },
      { { SQUARE, 1, nil }, "polygonTranslate: dy must be a number, got nil" },
      { { SQUARE, math.huge, 2 },
        "polygonTranslate: dx must be finite, got " .. tostring(math.huge) },
      { { SQUARE, 1, 0 / 0 }, "polygonTranslate: dy must be finite, got " .. tostring(0 / 0) },
      { { SQUARE, 1, 2, 5 }, "polygonTranslate: out must be a table, got number" },
      { { { SQUARE }, 1, 2, { "x" } }, "polygonTranslate: out[1] must be a table, got string" },
    }
    for _, case in ipairs(cases) do
      it("raises '" .. case[2] .. "'", function()
        local args = case[1]
        assert.has_error(function() translate(args[1], args[2], args[3], args[4]) end, case[2])
      end)
    end

    it("raises the errors at the caller's level", function()
      for _, case in ipairs(cases) do
        assert.is_true(callsite.raisesAtCaller(translate, case[1]))
      end
    end)
  end)

  describe("per call with out", function()
    it("allocates less than 1 KB over 10000 calls, flat and with parts, once out is built", function()
      local flatOut, partsOut = {}, {}
      local parts = { SQUARE, WEDGE }
      local kb = garbage.growth(function(i)
        translate(SQUARE, i, -i, flatOut)
        translate(parts, 0.5, i, partsOut)
      end, 10000)
      assert.is_true(kb < 1, ("%.3f KB"):format(kb))
    end)

    it("the measurement sees the calls without out, which build tables", function()
      local kb = garbage.growth(function(i) translate(SQUARE, i, -i) end, 10000)
      assert.is_true(kb >= 1, ("%.3f KB"):format(kb))
    end)
  end)
end)
