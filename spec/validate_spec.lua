-- validate(points): true, or nil and a message; argument errors of every public function
-- (message names the function, the argument and the type got, raised at the caller's level);
-- Polygon.new raises validate's message.
local polygon = require "polygon"
local callsite = require "callsite"

local unpack = table.unpack or unpack -- luacheck: ignore 113 143
local validate, Polygon = polygon.validate, polygon.Polygon

local SQUARE = { 0, 0, 10, 0, 10, 10, 0, 10 }
local ODD = { 0, 0, 10, 0, 5 } -- 5 coordinates

-- every public function that takes point arrays, with good arguments; `slots` names the
-- argument at each position
local FUNCTIONS = {
  { "polygonWindingOrder", { SQUARE }, { "points" } },
  { "polygonArea", { SQUARE }, { "points" } },
  { "polygonAreaAccurate", { SQUARE }, { "points" } },
  { "polygonType", { SQUARE }, { "points" } },
  { "polygonCenter", { SQUARE }, { "points" } },
  { "polygonCentroid", { SQUARE }, { "points" } },
  { "polygonContains", { SQUARE, 5, 5 }, { "points", "x", "y" } },
  { "projectPolygon", { SQUARE, 0, 0, 1, 0 }, { "points", "x", "y" } },
  { "polygonCollidesWith", { SQUARE, SQUARE }, { "points1", "points2" } },
  { "polygonsCollide", { SQUARE, SQUARE }, { "points1", "points2" } },
  { "polygonCollidesWithV", { SQUARE, SQUARE }, { "points1", "points2" } },
  { "polygonsCollideV", { SQUARE, SQUARE }, { "points1", "points2" } },
  { "polygonCircleCollideV", { SQUARE, 5, 5, 1 }, { "points", "cx", "cy", "radius" } },
  { "projectCircle", { 5, 5, 1, 0, 0, 1, 0 }, { "cx", "cy", "radius", "x", "y" } },
}

-- a copy of args with position i replaced by value (value may be nil)
local function with(args, i, value)
  local out = { n = #args }
  for k = 1, #args do out[k] = args[k] end
  out[i] = value
  return out
end

-- whether s ends with suffix (Polygon.new may put its own name before validate's message)
local function endsWith(s, suffix)
  return s:sub(-#suffix) == suffix
end

-- the message without the "file:line: " position
local function strip(err)
  return (tostring(err):gsub("^.-:%d+: ", "", 1))
end

describe("validate", function()
  describe("when the points are good", function()
    it("returns true for a square in both windings", function()
      assert.are.equal(true, validate(SQUARE))
      assert.are.equal(true, validate({ 0, 0, 0, 10, 10, 10, 10, 0 }))
    end)

    it("returns true for a triangle, a concave polygon and collinear points", function()
      assert.are.equal(true, validate({ 0, 0, 4, 0, 0, 3 }))
      assert.are.equal(true, validate({ 0, 0, 20, 0, 20, 10, 10, 10, 10, 20, 0, 20 }))
      assert.are.equal(true, validate({ 0, 0, 5, 0, 10, 0 }))
    end)

    it("returns true for negative, fractional and large finite coordinates", function()
      assert.are.equal(true, validate({ -1.5, -2.25, 1e300, 0, 0, -1e300 }))
      assert.are.equal(true, validate({ 0, 0, 1099511627776, 0, 0, 1099511627776 }))
    end)
  end)

  describe("when points is not a table", function()
    it("returns nil and a message naming the type got", function()
      for _, bad in ipairs({ { nil, "nil" }, { 42, "number" }, { "0,0", "string" }, { true, "boolean" } }) do
        local ok, msg = validate(bad[1])
        assert.is_nil(ok)
        assert.are.equal("string", type(msg))
        assert.is_truthy(msg:find("table", 1, true))
        assert.is_truthy(msg:find(bad[2], 1, true))
      end
    end)
  end)

  describe("when the number of coordinates is odd", function()
    it("returns nil and a message saying so with the count", function()
      local ok, msg = validate(ODD)
      assert.is_nil(ok)
      assert.is_truthy(msg:find("even", 1, true))
      assert.is_truthy(msg:find("5", 1, true))
    end)
  end)

  describe("when there are fewer than 3 points", function()
    it("returns nil and a message", function()
      for _, bad in ipairs({ {}, { 0, 0 }, { 0, 0, 10, 0 } }) do
        local ok, msg = validate(bad)
        assert.is_nil(ok)
        assert.are.equal("string", type(msg))
        assert.is_truthy(msg:find("3", 1, true))
      end
    end)
  end)

  describe("when a coordinate is not a finite number", function()
    it("returns nil and a message for NaN, +inf and -inf", function()
      for _, v in ipairs({ 0 / 0, math.huge, -math.huge }) do
        for i = 1, 6 do
          local bad = { 0, 0, 10, 0, 0, 10 }
          bad[i] = v
          local ok, msg = validate(bad)
          assert.is_nil(ok)
          assert.is_truthy(msg:find("finite", 1, true))
        end
      end
    end)

    it("returns nil and a message for a string or boolean coordinate", function()
      for _, v in ipairs({ "5", true, {} }) do
        local ok, msg = validate({ 0, 0, 10, v, 0, 10 })
        assert.is_nil(ok)
        assert.is_truthy(msg:find("number", 1, true))
      end
    end)
  end)
end)

describe("argument errors", function()
  for _, entry in ipairs(FUNCTIONS) do
    local name, args, slots = entry[1], entry[2], entry[3]
    local fn = polygon[name]

    describe(name, function()
      it("accepts the good arguments", function()
        assert.is_true((callsite.call(fn, args)))
      end)

      for i, slot in ipairs(slots) do
        if slot:find("^points") then
          it("raises '" .. name .. ": " .. slot .. " must be a table, got nil'", function()
            assert.has_error(function() fn(unpack(with(args, i, nil), 1, #args)) end,
              name .. ": " .. slot .. " must be a table, got nil")
          end)

          it("names the type got for " .. slot .. " = 7", function()
            assert.has_error(function() fn(unpack(with(args, i, 7), 1, #args)) end,
              name .. ": " .. slot .. " must be a table, got number")
          end)

          it("raises '" .. name .. ": " .. slot .. " must hold an even number of coordinates, got 5'",
            function()
              assert.has_error(function() fn(unpack(with(args, i, ODD), 1, #args)) end,
                name .. ": " .. slot .. " must hold an even number of coordinates, got 5")
            end)

          it("raises the error for " .. slot .. " at the caller's level", function()
            assert.is_true(callsite.raisesAtCaller(fn, with(args, i, nil)))
          end)
        else
          it("raises '" .. name .. ": " .. slot .. " must be a number, got string'", function()
            assert.has_error(function() fn(unpack(with(args, i, "5"), 1, #args)) end,
              name .. ": " .. slot .. " must be a number, got string")
          end)

          it("raises the error for " .. slot .. " at the caller's level", function()
            assert.is_true(callsite.raisesAtCaller(fn, with(args, i, "5")))
          end)
        end
      end
    end)
  end

  describe("when the radius is negative", function()
    it("polygonCircleCollideV raises an error naming the function and radius", function()
      local ok, err = callsite.call(polygon.polygonCircleCollideV, { SQUARE, 5, 5, -1 })
      assert.is_false(ok)
      assert.is_truthy(strip(err):find("^polygonCircleCollideV: radius"))
    end)

    it("projectCircle raises an error naming the function and radius", function()
      local ok, err = callsite.call(polygon.projectCircle, { 5, 5, -1, 0, 0, 1, 0 })
      assert.is_false(ok)
      assert.is_truthy(strip(err):find("^projectCircle: radius"))
    end)
  end)
end)

describe("Polygon.new", function()
  local BAD = {
    { nil },
    { "square" },
    { ODD },
    { {} },
    { { 0, 0, 10, 0 } },
    { { 0, 0, 10, 0 / 0, 0, 10 } },
    { { 0, 0, 10, math.huge, 0, 10 } },
    { { 0, 0, 10, "0", 0, 10 } },
  }

  it("raises validate's message (after its own name) for every input validate rejects", function()
    for _, case in ipairs(BAD) do
      local bad = case[1]
      local ok, msg = validate(bad)
      assert.is_nil(ok)
      local raised, err = pcall(Polygon.new, bad)
      assert.is_false(raised)
      assert.is_true(endsWith(strip(err), msg), tostring(err))
    end
  end)

  it("raises validate's message when the class is called as Polygon(points)", function()
    for _, case in ipairs(BAD) do
      local bad = case[1]
      local _, msg = validate(bad)
      local raised, err = pcall(Polygon, bad)
      assert.is_false(raised)
      assert.is_true(endsWith(strip(err), msg), tostring(err))
    end
  end)

  it("raises at the caller's level", function()
    assert.is_true(callsite.raisesAtCaller(Polygon.new, { n = 1 }))
    assert.is_true(callsite.raisesAtCaller(Polygon, { { 0, 0 } }))
  end)

  it("accepts what validate accepts", function()
    assert.are.equal(true, validate(SQUARE))
    assert.are.equal(SQUARE, Polygon.new(SQUARE).points)
  end)
end)
