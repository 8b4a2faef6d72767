-- What the measures and polygonContains do with a NaN or an infinite value. Finite input never
-- gives NaN (non_finite_hard_spec.lua); a non-finite coordinate in the points raises an error naming the
-- function and the argument, at the caller's line, instead of answering "ccw", "convex", NaN or
-- an infinite area. (The detection costs nothing on the ordinary path: a non-finite coordinate
-- always makes the float sums or the turn filter fail, and the rare path that follows checks.)
local polygon = require "polygon"
local callsite = require "callsite"

local nan, inf = 0 / 0, math.huge
local square = { 0, 0, 10, 0, 10, 10, 0, 10 }
local hexagon = { 5, 0, 15, 0, 20, 8, 15, 16, 5, 16, 0, 8 }

local measures = { "polygonWindingOrder", "polygonArea", "polygonAreaAccurate", "polygonType",
                   "polygonCenter", "polygonCentroid" }

-- every copy of points with one coordinate replaced by v
local function spoiled(points, v)
  local list = {}
  for k = 1, #points do
    local p = {}
    for i = 1, #points do p[i] = points[i] end
    p[k] = v
    list[#list + 1] = p
  end
  return list
end

describe("a non-finite coordinate", function()
  for _, name in ipairs(measures) do
    describe(name, function()
      it("raises an error naming the function and points, wherever the value sits", function()
        for _, base in ipairs({ square, hexagon }) do
          for _, v in ipairs({ nan, inf, -inf }) do
            for _, p in ipairs(spoiled(base, v)) do
              local ok, err = pcall(polygon[name], p)
              assert.is_false(ok, ("%s returned for %s"):format(name, tostring(v)))
              assert.is_truthy(err:find(name .. ": points holds a non-finite coordinate", 1, true), err)
            end
          end
        end
      end)

      it("points the error at the caller's line", function()
        assert.is_true(callsite.raisesAtCaller(polygon[name], { { 0, 0, 10, 0, nan, 10 } }))
      end)
    end)
  end

  it("never makes polygonType call a NaN polygon convex (it was 'convex' and 'ccw')", function()
    local p = { nan, nan, nan, nan, nan, nan }
    assert.has_error(function() polygon.polygonType(p) end)
    assert.has_error(function() polygon.polygonWindingOrder(p) end)
  end)
end)

describe("polygonContains", function()
  it("raises an error for a NaN or infinite x or y", function()
    for _, v in ipairs({ nan, inf, -inf }) do
      assert.has_error(function() polygon.polygonContains(square, v, 5) end,
        ("polygonContains: x and y must be finite, got %s, 5"):format(tostring(v)))
      assert.has_error(function() polygon.polygonContains(square, 5, v) end,
        ("polygonContains: x and y must be finite, got 5, %s"):format(tostring(v)))
      assert.has_error(function() polygon.Polygon.new(square):contains(v, 5) end)
    end
  end)

  it("answers true or false for a polygon holding a NaN (the points are not scanned)", function()
    for _, p in ipairs(spoiled(square, nan)) do
      local inside = polygon.polygonContains(p, 5, 5)
      assert.are.equal("boolean", type(inside))
    end
  end)
end)
