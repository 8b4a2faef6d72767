-- circlesCollideV(x1, y1, r1, x2, y2, r2): overlap, dx, dy or false. The circles collide when
-- (x2 - x1)^2 + (y2 - y1)^2 < (r1 + r2)^2 exactly; (dx, dy) moves the second circle, and after
-- x2 + dx, y2 + dy (rounded) they no longer collide.
local polygon = require "polygon"
local garbage = require "garbage"
local oracle = require "oracle"
local exact = require "exact"
local prng = require "prng"

local circlesV = polygon.circlesCollideV
local EPS = 2 ^ -53

-- the push separates for certain: the oracle sees no overlap at the moved centre
local function assertSeparates(x1, y1, r1, x2, y2, r2, dx, dy)
  assert.is_true(oracle.circlesOverlapSign(x1, y1, r1, x2 + dx, y2 + dy, r2) <= 0)
  assert.are.equal(false, circlesV(x1, y1, r1, x2 + dx, y2 + dy, r2))
end

-- the push is no longer than the exact depth plus 8 eps M, M the largest coordinate magnitude
-- involved (the centres before and after the move; the radii are lengths), decided exactly:
-- depth >= q - 8 eps M, with q >= |(dx, dy)| checked exactly too
local function assertTight(x1, y1, r1, x2, y2, r2, dx, dy)
  local m = math.max(math.abs(x1), math.abs(y1), math.abs(x2), math.abs(y2),
    math.abs(x2 + dx), math.abs(y2 + dy))
  local q = oracle.lengthAbove(dx, dy)
  assert.is_true(oracle.circlesDepthAtLeast(x1, y1, r1, x2, y2, r2, q, 8 * EPS * m),
    ("push %.17g longer than the depth by more than 8 eps M = %g"):format(q, 8 * EPS * m))
end

describe("circlesCollideV", function()
  describe("when two circles overlap along x", function()
    -- centres 1.5 apart, radii 1 and 1: overlap 2 - 1.5 = 0.5, the second circle goes +x
    it("returns overlap 0.5 and pushes the second circle by about (0.5, 0), in both orders", function()
      local overlap, dx, dy = circlesV(0, 0, 1, 1.5, 0, 1)
      assert.are.equal(0.5, overlap)
      assert.near(0.5, dx, 4 * EPS)
      assert.are.equal(0, dy)
      assertSeparates(0, 0, 1, 1.5, 0, 1, dx, dy)
      overlap, dx, dy = circlesV(1.5, 0, 1, 0, 0, 1)
      assert.are.equal(0.5, overlap)
      assert.near(-0.5, dx, 4 * EPS)
      assert.are.equal(0, dy)
      assertSeparates(1.5, 0, 1, 0, 0, 1, dx, dy)
    end)
  end)

  describe("when the centres are 5 apart on a 3-4-5 triangle", function()
    -- (0,0) r 2 and (3,4) r 4: distance 5, overlap 6 - 5 = 1 along (0.6, 0.8)
    it("returns overlap 1 along (0.6, 0.8), and the opposite way in the other order", function()
      local overlap, dx, dy = circlesV(0, 0, 2, 3, 4, 4)
      assert.are.equal(1, overlap)
      assert.near(0.6, dx, 1e-15)
      assert.near(0.8, dy, 1e-15)
      assertSeparates(0, 0, 2, 3, 4, 4, dx, dy)
      overlap, dx, dy = circlesV(3, 4, 4, 0, 0, 2)
      assert.are.equal(1, overlap)
      assert.near(-0.6, dx, 1e-15)
      assert.near(-0.8, dy, 1e-15)
      assertSeparates(3, 4, 4, 0, 0, 2, dx, dy)
    end)
  end)

  describe("when one circle lies inside the other", function()
    -- (0,0) r 10 and (1,0) r 1: overlap 11 - 1 = 10, the small one leaves along +x
    it("returns the full overlap 10", function()
      local overlap, dx, dy = circlesV(0, 0, 10, 1, 0, 1)
      assert.are.equal(10, overlap)
      assert.near(10, dx, 1e-14)
      assert.are.equal(0, dy)
      assertSeparates(0, 0, 10, 1, 0, 1, dx, dy)
    end)
  end)

  describe("when the centres coincide", function()
    -- distance 0: overlap r1 + r2 = 5, pushed along +x by convention
    it("pushes the second circle along +x by the sum of the radii, with no NaN", function()
      local overlap, dx, dy = circlesV(7, -3, 2, 7, -3, 3)
      assert.are.equal(5, overlap)
      assert.near(5, dx, 1e-14)
      assert.are.equal(0, dy)
      assertSeparates(7, -3, 2, 7, -3, 3, dx, dy)
    end)
  end)

  describe("when the circles touch or are apart", function()
    it("returns false for circles touching exactly (distance 5 = 2 + 3)", function()
      assert.are.equal(false, circlesV(0, 0, 2, 3, 4, 3))
      assert.are.equal(false, circlesV(3, 4, 3, 0, 0, 2))
    end)

    it("collides one ulp past touching and not one ulp before", function()
      local up, down = exact.nextUp(3), exact.nextDown(3)
      assert.is_truthy(circlesV(0, 0, 2, 3, 4, up))
      assert.are.equal(false, circlesV(0, 0, 2, 3, 4, down))
      assert.is_truthy(circlesV(3, 4, up, 0, 0, 2))
      assert.are.equal(false, circlesV(3, 4, down, 0, 0, 2))
    end)

    it("returns false for circles far apart", function()
      assert.are.equal(false, circlesV(0, 0, 1, 100, 0, 1))
    end)
  end)

  describe("when the sum of the radii is not a double", function()
    -- r1 + r2 = 1 + 2^-60 rounds to 1, so the float test sees a tie in each case below
    it("decides gaps of 2^-59 relative to the squares", function()
      -- centre 2 at (1, 0): (1 + 2^-60)^2 - 1 = 2^-59 + 2^-120 > 0, collides
      assert.is_truthy(circlesV(0, 0, 1, 1, 0, 2 ^ -60))
      assert.is_truthy(circlesV(1, 0, 2 ^ -60, 0, 0, 1))
      -- centre 2 at (1, 2^-29): 1 + 2^-58 > 1 + 2^-59 + 2^-120, apart
      assert.are.equal(false, circlesV(0, 0, 1, 1, 2 ^ -29, 2 ^ -60))
      assert.are.equal(false, circlesV(1, 2 ^ -29, 2 ^ -60, 0, 0, 1))
    end)

    it("decides gaps of 2^-122 relative to the squares", function()
      -- centre 2 at (1, 2^-30): |c2 - c1|^2 = 1 + 2^-60;
      -- r2 = 2^-61: (1 + 2^-61)^2 = 1 + 2^-60 + 2^-122, 2^-122 more: collides
      assert.is_truthy(circlesV(0, 0, 1, 1, 2 ^ -30, 2 ^ -61))
      assert.is_truthy(circlesV(1, 2 ^ -30, 2 ^ -61, 0, 0, 1))
      -- r2 = 2^-62: (1 + 2^-62)^2 = 1 + 2^-61 + 2^-124 < 1 + 2^-60: apart
      assert.are.equal(false, circlesV(0, 0, 1, 1, 2 ^ -30, 2 ^ -62))
      -- r2 = 2^-61 with centre 2 at (1, 2^-30 + 2^-82): the squared distance gains
      -- 2 * 2^-30 * 2^-82 + 2^-164 = 2^-111 + 2^-164 > 2^-122: apart
      assert.are.equal(false, circlesV(0, 0, 1, 1, 2 ^ -30 + 2 ^ -82, 2 ^ -61))
    end)
  end)

  describe("when the tangent pair is far from the origin", function()
    -- the 3-4-5 touching pair moved by 1e9 and 1e12 (exact: integers below 2^53)
    for _, offset in ipairs({ 1e9, 1e12 }) do
      it("decides touching exactly at offset " .. offset, function()
        local x1, y1 = offset, -offset
        assert.are.equal(false, circlesV(x1, y1, 2, x1 + 3, y1 + 4, 3))
        local overlap, dx, dy = circlesV(x1, y1, 2, x1 + 3, y1 + 4, exact.nextUp(3))
        assert.is_truthy(overlap)
        assertSeparates(x1, y1, 2, x1 + 3, y1 + 4, exact.nextUp(3), dx, dy)
        assert.are.equal(false, circlesV(x1, y1, 2, x1 + 3, y1 + 4, exact.nextDown(3)))
      end)
    end
  end)

  describe("when a radius is huge or zero", function()
    it("returns the huge overlap for a radius of 1e300", function()
      local overlap, dx, dy = circlesV(0, 0, 1e300, 3, 4, 1)
      assert.near(1e300, overlap, 1e285)
      assert.near(0.6e300, dx, 1e285)
      assert.near(0.8e300, dy, 1e285)
      assertSeparates(0, 0, 1e300, 3, 4, 1, dx, dy)
    end)

    it("treats a circle of radius 0 as a point: inside the other circle it collides", function()
      -- (0,0) r 0 and (3,4) r 6: distance 5 < 0 + 6, overlap 1
      local overlap = circlesV(0, 0, 0, 3, 4, 6)
      assert.are.equal(1, overlap)
      assert.are.equal(false, circlesV(0, 0, 0, 3, 4, 5))   -- on the circle: touching
    end)

    it("never collides two points, even at the same place", function()
      assert.are.equal(false, circlesV(1, 2, 0, 1, 2, 0))
    end)

    it("decides circles of size 2^-500 and 2^500 exactly", function()
      for _, k in ipairs({ 2 ^ -500, 2 ^ 500, 2 ^ -1000 }) do
        assert.are.equal(false, circlesV(0, 0, 2 * k, 3 * k, 4 * k, 3 * k))
        local overlap, dx, dy = circlesV(0, 0, 2 * k, 3 * k, 4 * k, 4 * k)
        assert.near(1, overlap / k, 1e-15)
        assertSeparates(0, 0, 2 * k, 3 * k, 4 * k, 4 * k, dx, dy)
      end
    end)
  end)

  describe("when an argument is wrong", function()
    it("names the function, the argument and what it got", function()
      assert.has_error(function() circlesV("0", 0, 1, 0, 0, 1) end,
        "circlesCollideV: x1 must be a number, got string")
      assert.has_error(function() circlesV(0, 0, -1, 0, 0, 1) end,
        "circlesCollideV: r1 must not be negative, got -1")
      assert.has_error(function() circlesV(0, 0, 1, 0, 0, -2) end,
        "circlesCollideV: r2 must not be negative, got -2")
      assert.has_error(function() circlesV(0, 0, 1, math.huge, 0, 1) end,
        "circlesCollideV: x2 must be finite, got " .. tostring(math.huge))
      local ok, message = pcall(circlesV, 0, 0, 1, 0, 0 / 0, 1)
      assert.is_false(ok)
      assert.truthy(message:find("circlesCollideV: y2 must be finite", 1, true))
      ok, message = pcall(circlesV, 0, 0, 1, 0, 0, 0 / 0)
      assert.is_false(ok)
      assert.truthy(message:find("circlesCollideV: r2 must be finite", 1, true))
    end)

    it("points the error at the caller's line", function()
      local ok, message = pcall(function() circlesV(0, 0, 1, 0, 0, -1) end)
      assert.is_false(ok)
      assert.truthy(message:find("circles_spec.lua", 1, true))
    end)
  end)

  describe("on generated pairs near touching, at offsets 1 to 1e12", function()
    it("agrees with the exact oracle, and every push separates and is tight", function()
      local r = prng.new(20261122)
      local collided = 0
      for trial = 1, 1500 do
        local offset = 10 ^ r:int(0, 12)
        local x1, y1 = offset * (r:float() * 2 - 1), offset * (r:float() * 2 - 1)
        local r1 = r:range(0.1, 50)
        local angle = r:range(0, 2 * math.pi)
        local dist = r:range(0, 100)
        local x2, y2 = x1 + dist * math.cos(angle), y1 + dist * math.sin(angle)
        -- r2 near touching: the rounded distance less r1, nudged by up to a few ulps or deep
        local touch = math.sqrt((x2 - x1) ^ 2 + (y2 - y1) ^ 2) - r1
        local r2 = math.abs(touch)
        local kind = trial % 3
        if kind == 0 then
          for _ = 1, r:int(0, 3) do r2 = exact.nextUp(r2) end
        elseif kind == 1 then
          for _ = 1, r:int(0, 3) do r2 = exact.nextDown(r2) end
        else
          r2 = r2 + r:range(0, 30)
        end
        if r2 < 0 then r2 = 0 end
        if trial % 2 == 0 then x1, y1, r1, x2, y2, r2 = x2, y2, r2, x1, y1, r1 end
        local expected = oracle.circlesOverlapSign(x1, y1, r1, x2, y2, r2) > 0
        local overlap, dx, dy = circlesV(x1, y1, r1, x2, y2, r2)
        assert.are.equal(expected, overlap ~= false)
        if overlap then
          collided = collided + 1
          assertSeparates(x1, y1, r1, x2, y2, r2, dx, dy)
          assertTight(x1, y1, r1, x2, y2, r2, dx, dy)
        end
      end
      assert.is_true(collided > 300)
    end)
  end)

  describe("when called many times", function()
    it("allocates nothing", function()
      local cases = { { 0, 0, 1, 1.5, 0, 1 }, { 0, 0, 2, 3, 4, 3 }, { 0, 0, 2, 3, 4, 3.0000000000000004 },
        { 7, -3, 2, 7, -3, 3 }, { 1e12, 1e12, 2, 1e12 + 3, 1e12 + 4, 3 } }
      local function body(i)
        local c = cases[i % #cases + 1]
        circlesV(c[1], c[2], c[3], c[4], c[5], c[6])
      end
      -- the least growth over several runs after warm-up (LuaJIT's traces live on the heap)
      collectgarbage("stop")
      local grown = garbage.growth(body, 5000)
      collectgarbage("restart")
      assert.is_true(grown < 1, grown .. " KB")
    end)
  end)
end)
