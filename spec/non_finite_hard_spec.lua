-- "Finite input never gives NaN": random polygons whose coordinates span the whole double range
-- (magnitudes 1e-300 to 1e300, mixed within one polygon, so far outside the exact range that
-- the answers themselves are not checked here, only that every number returned is a number).
local polygon = require "polygon"
local unpack = rawget(_G, "unpack") or rawget(table, "unpack")
local prng = require "prng"

local function coordinate(r, style)
  if style == 1 then   -- any magnitude, any sign
    return (r:float() * 2 - 1) * 10 ^ r:int(-300, 300)
  elseif style == 2 then   -- large ones mixed with ordinary ones
    return (r:float() - 0.5) * 10 ^ r:int(-20, 300)
  end
  return r:int(-3, 3) * 10 ^ r:int(-300, 300)   -- zeros and exact repeats
end

describe("wild finite coordinates", function()
  it("never make any function return NaN", function()
    local r = prng.new(4242)
    local bad = {}
    local function check(name, ...)
      for i = 1, select("#", ...) do
        local v = select(i, ...)
        if v ~= v and #bad < 5 then bad[#bad + 1] = name end
      end
    end
    for _ = 1, 1500 do
      local style = r:int(1, 3)
      local a, b = {}, {}
      for i = 1, 2 * r:int(3, 6) do a[i] = coordinate(r, style) end
      for i = 1, 2 * r:int(3, 6) do b[i] = coordinate(r, style) end
      check("polygonArea", polygon.polygonArea(a))
      check("polygonAreaAccurate", polygon.polygonAreaAccurate(a))
      check("polygonCenter", polygon.polygonCenter(a))
      check("polygonCentroid", polygon.polygonCentroid(a))
      -- the collision functions answer, or refuse a polygon as not convex (most of these are
      -- concave; beyond the exact range the refusal itself is not checked here, only that no
      -- other error and no NaN comes out)
      local function answer(name, fn, ...)
        local results = { pcall(fn, ...) }
        if results[1] then
          check(name, unpack(results, 2, 4))
        elseif not tostring(results[2]):find("is not convex", 1, true) and #bad < 5 then
          bad[#bad + 1] = name .. ": " .. tostring(results[2])
        end
      end
      answer("polygonsCollideV", polygon.polygonsCollideV, a, b)
      answer("polygonCollidesWithV", polygon.polygonCollidesWithV, a, b)
      answer("polygonCircleCollideV", polygon.polygonCircleCollideV, a, coordinate(r, style),
        coordinate(r, style), math.abs(coordinate(r, style)))
      -- the sign functions must simply answer
      polygon.polygonType(a)
      polygon.polygonWindingOrder(a)
      polygon.polygonContains(a, coordinate(r, style), coordinate(r, style))
    end
    assert.are.same({}, bad)
  end)
end)
