-- No function modifies its input tables: each call runs on tables deep-copied beforehand and
-- the inputs must equal their copies afterwards (same keys, same values, same metatable).
local polygon = require "polygon"
local shapes = require "shapes"

local samples = require "samples"

local deepcopy = shapes.deepCopy

local SQUARE, SQUARE_CCW, L, OVERLAP = samples.SQUARE, samples.SQUARE_CCW, samples.L, samples.OVERLAP
local TOUCH, INSIDE, REPEATED, CLOSED = samples.TOUCH, samples.INSIDE, samples.REPEATED, samples.CLOSED
local TRIANGLE, SEGMENT, TWO = samples.TRIANGLE, samples.SEGMENT, samples.TWO
local STAR, SLIVER = samples.STAR, samples.SLIVER

local POLYS = {
  SQUARE, SQUARE_CCW, L, OVERLAP, TOUCH, INSIDE, REPEATED, CLOSED, TRIANGLE, SEGMENT, TWO, STAR, SLIVER, {},
}

-- calls fn(...) on the given tables and asserts that they are unchanged afterwards
local function assertUnchanged(fn, ...)
  local args = { ... }
  local n = select("#", ...)
  local before = deepcopy(args)
  local ok, err = pcall(fn, ...)
  -- a collision function's refusal of a concave polygon or of fewer than 3 points is an
  -- answer too (spec/refusals_spec.lua); the tables must be unchanged after it as well
  assert.is_true(ok or tostring(err):find("is not convex", 1, true) ~= nil
    or tostring(err):find("a polygon needs at least 3", 1, true) ~= nil, tostring(err))
  for i = 1, n do
    assert.are.same(before[i], args[i])
    if type(args[i]) == "table" then
      assert.are.equal(#before[i], #args[i])
      assert.are.equal(getmetatable(before[i]), getmetatable(args[i]))
    end
  end
end

local ONE = {
  "polygonWindingOrder", "polygonArea", "polygonAreaAccurate", "polygonType", "polygonCenter",
  "polygonCentroid", "validate",
}
local TWO_ARG = { "polygonCollidesWith", "polygonsCollide", "polygonCollidesWithV", "polygonsCollideV" }

describe("input tables", function()
  for _, name in ipairs(ONE) do
    it("are unchanged by " .. name, function()
      for _, p in ipairs(POLYS) do
        assertUnchanged(polygon[name], p)
      end
    end)
  end

  it("are unchanged by polygonContains", function()
    for _, p in ipairs(POLYS) do
      for _, q in ipairs({ { 5, 5 }, { 10, 5 }, { 0, 0 }, { 15, 15 } }) do
        assertUnchanged(polygon.polygonContains, p, q[1], q[2])
      end
    end
  end)

  it("are unchanged by projectPolygon", function()
    for _, p in ipairs(POLYS) do
      if #p >= 2 then assertUnchanged(polygon.projectPolygon, p, 1, 2, 3, -4) end
    end
  end)

  for _, name in ipairs(TWO_ARG) do
    it("are unchanged by " .. name .. " in both argument orders", function()
      for _, p in ipairs(POLYS) do
        for _, q in ipairs(POLYS) do
          assertUnchanged(polygon[name], p, q)
        end
      end
    end)
  end

  it("are unchanged by polygonsCollideV when both arguments are the same table", function()
    assertUnchanged(polygon.polygonsCollideV, SQUARE, SQUARE)
  end)

  it("are unchanged by polygonCircleCollideV", function()
    for _, p in ipairs(POLYS) do
      for _, c in ipairs({ { 12, 5, 3 }, { 7, 4, 1 }, { 10, 10, 2 }, { 0, 0, 3 }, { 6, 5, 100 } }) do
        assertUnchanged(polygon.polygonCircleCollideV, p, c[1], c[2], c[3])
      end
    end
  end)

  it("are unchanged by Polygon.new, Polygon() and p:contains", function()
    for _, p in ipairs({ SQUARE, SQUARE_CCW, L, STAR, REPEATED }) do
      assertUnchanged(polygon.Polygon.new, p)
      assertUnchanged(polygon.Polygon, p)
      assertUnchanged(function(points) return polygon.Polygon.new(points):contains(5, 5) end, p)
    end
  end)

  it("are unchanged by validate on rejected input", function()
    for _, bad in ipairs({ { 0, 0, 10 }, { 0, 0, 10, 0 }, { 0, 0, 10, 0 / 1, "x", 5 } }) do
      assertUnchanged(polygon.validate, bad)
    end
  end)

  it("keep extra fields and metatables the caller put on them", function()
    local mt = { __index = function() return nil end }
    local p = setmetatable({ 0, 0, 10, 0, 10, 10, 0, 10, name = "box" }, mt)
    assertUnchanged(polygon.polygonArea, p)
    assertUnchanged(polygon.polygonsCollideV, p, OVERLAP)
    assertUnchanged(polygon.polygonCircleCollideV, p, 12, 5, 3)
    assertUnchanged(polygon.Polygon.new, p)
  end)
end)
