-- Properties on random inputs, against the exact oracle (spec/support/oracle.lua).
--
-- The inputs come from a fixed-seed generator of our own (spec/support/prng.lua), so every Lua
-- version draws the same cases. Half of them are snapped to coarse grids (integers in -3 .. 3,
-- halves far from the origin) so that collinear vertices, repeated vertices, points on edges and
-- vertices, horizontal edges and exactly touching polygons are frequent, not rare.

local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local tally = require "tally"

local toInteger = rawget(math, "tointeger") -- Lua 5.3+ only

-- How a coordinate is drawn: each style returns a function of the generator.
-- unit: a typical distance between drawn coordinates.
local STYLES = {
  { name = "floats near the origin", unit = 1, draw = function(r) return r:range(-10, 10) end },
  { name = "integers -3 .. 3", unit = 1, draw = function(r) return r:int(-3, 3) + 0.0 end },
  { name = "halves near 1e6", unit = 1, draw = function(r) return 1e6 + r:int(-8, 8) * 0.5 end },
  { name = "floats near 1e9", unit = 1, draw = function(r) return 1e9 + r:range(-4, 4) end },
  { name = "tiny floats", unit = 2 ^ -402, draw = function(r) return r:range(-1, 1) * 2 ^ -400 end },
  -- Lua integers on 5.3/5.4 (floats elsewhere): k 2^43 + j, whose products pass 2^63
  { name = "large integers", unit = 2 ^ 43, draw = function(r)
    local v = r:int(-4, 4) * 2 ^ 43 + r:int(-2, 2)
    return toInteger and toInteger(v) or v
  end },
}

local function randomPolygon(r, style)
  local points = {}
  for i = 1, 2 * r:int(3, 7) do
    points[i] = style.draw(r)
  end
  return points
end

-- A convex polygon: corners on an ellipse in order, snapped like the style (which may leave it
-- degenerate or not convex: callers ask the oracle).
local function convexPolygon(r, style)
  local m = r:int(3, 7)
  local cx, cy = style.draw(r), style.draw(r)
  local size = (math.abs(style.draw(r) - style.draw(r)) + style.unit) / 2
  local points = {}
  for i = 1, m do
    local angle = (i - 1 + r:range(-0.3, 0.3)) * 2 * math.pi / m
    local x, y = cx + size * math.cos(angle), cy + size * math.sin(angle)
    if style.name == "integers -3 .. 3" then
      x, y = math.floor(x + 0.5), math.floor(y + 0.5)
    elseif style.name == "large integers" then
      -- back onto the integers (of the integer subtype where there is one)
      x, y = math.floor(x / 2 ^ 40 + 0.5) * 2 ^ 40 + 1, math.floor(y / 2 ^ 40 + 0.5) * 2 ^ 40 - 1
      if toInteger then x, y = toInteger(x), toInteger(y) end
    elseif style.name == "halves near 1e6" then
      x, y = math.floor(x * 2 + 0.5) / 2, math.floor(y * 2 + 0.5) / 2
    end
    points[2 * i - 1], points[2 * i] = x, y
  end
  return points
end

describe("on random polygons", function()
  for k, style in ipairs(STYLES) do
    it(("winding, type and contains agree with the oracle (%s)"):format(style.name), function()
      local r = prng.new(1000 + k)
      local t = tally.new(style.name)
      local kinds = {}
      for _ = 1, 250 do
        local p = randomPolygon(r, style)
        local kind = oracle.polygonType(p)
        kinds[tostring(kind)] = true
        t:check(polygon.polygonWindingOrder(p) == oracle.winding(p), "winding", p)
        t:check(polygon.polygonType(p) == kind, "type", p, "got", polygon.polygonType(p), "expected", kind)
        local object = polygon.Polygon(p)
        for _ = 1, 4 do
          -- a drawn point, or a vertex of the polygon
          local x, y
          if r:int(0, 2) == 0 then
            local v = r:int(1, #p / 2)
            x, y = p[2 * v - 1], p[2 * v]
          else
            x, y = style.draw(r), style.draw(r)
          end
          local expected = oracle.contains(p, x, y)
          t:check(polygon.polygonContains(p, x, y) == expected, "contains", p, x, y, "expected", expected)
          t:check(object:contains(x, y) == expected, "Polygon:contains", p, x, y)
        end
      end
      assert.are.equal(0, t.count, t:message())
      -- random polygons are mostly concave; the grids also give collinear (nil) ones
      assert.is_true(kinds.concave ~= nil)
    end)

    it(("convex polygons collide as the exact SAT says (%s)"):format(style.name), function()
      local r = prng.new(2000 + k)
      local t = tally.new(style.name)
      local seen = { collide = 0, apart = 0 }
      for _ = 1, 120 do
        local a, b = convexPolygon(r, style), convexPolygon(r, style)
        -- only convex or degenerate (zero-area) polygons are the collision functions' input
        local usable = true
        for _, p in ipairs({ a, b }) do
          local kind = oracle.polygonType(p)
          if kind == "concave" and oracle.winding(p) ~= nil then usable = false end
        end
        if usable then
          for _, order in ipairs({ { a, b }, { b, a } }) do
            local p, q = order[1], order[2]
            local both, oneSided = oracle.collides(p, q, true), oracle.collides(p, q, false)
            seen[both and "collide" or "apart"] = seen[both and "collide" or "apart"] + 1
            t:check(polygon.polygonsCollide(p, q) == both, "polygonsCollide", p, q, "expected", both)
            t:check(polygon.polygonCollidesWith(p, q) == oneSided, "polygonCollidesWith", p, q,
              "expected", oneSided)
            t:check((polygon.polygonsCollideV(p, q) ~= false) == both, "polygonsCollideV", p, q)
            t:check((polygon.polygonCollidesWithV(p, q) ~= false) == oneSided, "polygonCollidesWithV", p, q)
          end
        end
      end
      t:report((" (colliding %d, apart %d)"):format(seen.collide, seen.apart))
      assert.are.equal(0, t.count, t:message())
      assert.is_true(seen.collide > 20 and seen.apart > 20,
        ("collide %d, apart %d"):format(seen.collide, seen.apart))
    end)
  end
end)
