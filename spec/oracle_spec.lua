-- The oracle must be trustworthy before anything is checked against it: hand-computed cases for the
-- exact arithmetic (spec/support/exact.lua) and for the oracle's geometry (spec/support/oracle.lua).
-- Nothing here loads polygon.lua.

local exact = require "exact"
local oracle = require "oracle"
local prng = require "prng"

local new, add, sub, mul = exact.new, exact.add, exact.sub, exact.mul
local P2 = exact.POW2

local function isExactly(a, b)
  return exact.compare(a, b) == 0
end

describe("exact", function()
  describe("split", function()
    it("takes doubles apart into sign, integer mantissa and exponent", function()
      -- 0.75 = 3 / 4
      assert.are.same({ 1, 3, -2 }, { exact.split(0.75) })
      -- 0.1 = 0x1.999999999999ap-4 = 0xccccccccccccd * 2^-55 = 3602879701896397 * 2^-55
      assert.are.same({ 1, 3602879701896397, -55 }, { exact.split(0.1) })
      -- 12 = 3 * 2^2; -2^60 = -1 * 2^60
      assert.are.same({ 1, 3, 2 }, { exact.split(12) })
      assert.are.same({ -1, 1, 60 }, { exact.split(-2 ^ 60) })
      -- the smallest subnormal
      assert.are.same({ 1, 1, -1074 }, { exact.split(P2[-1074]) })
      -- 0.5 + 3 * 2^-53 = (2^52 + 3) * 2^-53
      assert.are.same({ 1, 2 ^ 52 + 3, -53 }, { exact.split(0.5 + 3 * 2 ^ -53) })
      -- the largest double (2^53 - 1) * 2^971
      assert.are.same({ 1, 2 ^ 53 - 1, 971 }, { exact.split(1.7976931348623157e308) })
    end)

    it("reconstructs every double it splits", function()
      local r = prng.new(20240601)
      for _ = 1, 300 do
        local x = r:range(-1, 1) * P2[r:int(-1070, 970)]
        if x ~= 0 then
          local s, m, e = exact.split(x)
          assert.is_true(m % 2 == 1 and m < P2[53])
          -- m * 2^e computed in two exact steps (m * 2^e is x itself, a double)
          local back = s * m * P2[math.floor(e / 2)] * P2[e - math.floor(e / 2)]
          assert.are.equal(x, back)
        end
      end
    end)
  end)

  describe("add, sub and mul", function()
    it("adds 0.1 and 0.2 exactly", function()
      -- 0.1 + 0.2 = 3 * 3602879701896397 * 2^-55 = 10808639105689191 * 2^-55, while the double 0.3
      -- is 5404319552844595 * 2^-54 = 10808639105689190 * 2^-55: the difference is 2^-55.
      local sum = add(new(0.1), new(0.2))
      assert.is_true(isExactly(sub(sum, new(0.3)), exact.pow2(-55)))
      assert.are.equal(1, exact.compare(sum, new(0.3)))
    end)

    it("multiplies without losing the low bits", function()
      -- (2^53 - 1)^2 = 2^106 - 2^54 + 1
      local a = new(2 ^ 53 - 1)
      local square = mul(a, a)
      local expected = add(sub(exact.pow2(106), exact.pow2(54)), new(1))
      assert.is_true(isExactly(square, expected))
      assert.is_true(isExactly(sub(square, add(exact.pow2(106), exact.neg(exact.pow2(54)))), new(1)))
      -- 3 * -0.5 = -1.5; 0 * x = 0
      assert.is_true(isExactly(mul(new(3), new(-0.5)), new(-1.5)))
      assert.are.equal(0, exact.sign(mul(new(0), new(7))))
    end)

    it("keeps a tiny term next to a huge one", function()
      -- (2^1000 + 2^-1000) - 2^1000 = 2^-1000
      local big, tiny = exact.pow2(1000), exact.pow2(-1000)
      assert.is_true(isExactly(sub(add(big, tiny), big), tiny))
      assert.are.equal(1, exact.sign(sub(add(big, tiny), big)))
    end)

    it("carries through whole limbs", function()
      -- (2^72 - 1) + 1 = 2^72: three full limbs of 0xffffff carry into a fourth
      local allOnes = sub(exact.pow2(72), new(1))
      assert.are.same({ 16777215, 16777215, 16777215 }, { allOnes[1], allOnes[2], allOnes[3] })
      assert.is_true(isExactly(add(allOnes, new(1)), exact.pow2(72)))
      -- (2^24 - 1)^2 = 2^48 - 2^25 + 1 = limbs {1, 0xfffffe}
      local m = exact.magnitude.mul({ 16777215 }, { 16777215 })
      assert.are.same({ 1, 16777214 }, m)
    end)

    it("subtracts to zero and changes sign", function()
      assert.are.equal(0, exact.sign(sub(new(0.1), new(0.1))))
      assert.are.equal(-1, exact.sign(sub(new(0.1), new(0.2))))
      assert.are.equal(1, exact.compare(new(-0.1), new(-0.2)))
      assert.are.equal(-1, exact.compare(new(-1e300), new(1e-300)))
    end)

    it("compares as doubles compare, and as the sign of the difference", function()
      local r = prng.new(31)
      local pool = { 0, 1, -1, 0.5, 2 ^ 60, -2 ^ -60, 1 + 2 ^ -52, 1 - 2 ^ -53 }
      for _ = 1, 40 do
        pool[#pool + 1] = r:range(-1, 1) * P2[r:int(-80, 80)]
      end
      for _, a in ipairs(pool) do
        for _, b in ipairs(pool) do
          local expected = a < b and -1 or (a > b and 1 or 0)
          assert.are.equal(expected, exact.compare(new(a), new(b)))
          assert.are.equal(expected, exact.sign(sub(new(a), new(b))))
        end
      end
      -- values that are not doubles: 2^70 + 1 against 2^70, and 1 + 2^-100 against 1
      assert.are.equal(1, exact.compare(add(exact.pow2(70), new(1)), exact.pow2(70)))
      assert.are.equal(-1, exact.compare(new(1), add(new(1), exact.pow2(-100))))
      assert.are.equal(-1, exact.compare(exact.neg(add(new(1), exact.pow2(-100))), new(-1)))
    end)

    it("agrees with the correctly rounded double operations on random doubles", function()
      -- IEEE 754 +, - and * are correctly rounded (ties to even), so rounding the exact result must
      -- give exactly the double result whenever that is finite.
      local r = prng.new(77)
      for _ = 1, 400 do
        local a = r:range(-1, 1) * P2[r:int(-60, 60)]
        local b = r:range(-1, 1) * P2[r:int(-60, 60)]
        local ea, eb = new(a), new(b)
        assert.are.equal(a + b, exact.tonumber(add(ea, eb)))
        assert.are.equal(a - b, exact.tonumber(sub(ea, eb)))
        assert.are.equal(a * b, exact.tonumber(mul(ea, eb)))
      end
    end)
  end)

  describe("sum", function()
    it("equals the additions one by one, whatever the exponents and signs", function()
      local r = prng.new(4711)
      for _ = 1, 30 do
        local list, total = {}, exact.ZERO
        for k = 1, r:int(0, 40) do
          local v = new(r:range(-1, 1) * P2[r:int(-200, 200)])
          if r:int(0, 3) == 0 then v = mul(v, new(r:range(-1, 1))) end -- two-double-wide values
          list[k] = v
          total = add(total, v)
        end
        assert.is_true(isExactly(exact.sum(list), total))
      end
      -- hand-computed: 2^100 + 1 - 2^100 + 2^-100 = 1 + 2^-100; 0.5 + 0.5 carries to 1
      local s = exact.sum({ exact.pow2(100), new(1), exact.neg(exact.pow2(100)), exact.pow2(-100) })
      assert.is_true(isExactly(s, add(new(1), exact.pow2(-100))))
      assert.is_true(isExactly(exact.sum({ new(0.5), new(0.5) }), new(1)))
      assert.are.equal(0, exact.sign(exact.sum({})))
      -- a thousand limbs of 0xffffff: carries over several limbs in one pass
      local many = {}
      for k = 1, 1000 do many[k] = new(16777215) end
      assert.is_true(isExactly(exact.sum(many), new(16777215000)))
    end)
  end)

  describe("sumOfProducts", function()
    it("equals exact.sum of exact.mul, whatever the exponents and signs", function()
      local r = prng.new(8080)
      for _ = 1, 30 do
        local as, bs, signs, products = {}, {}, {}, {}
        for k = 1, r:int(0, 30) do
          as[k] = r:pick({ 0, 1, -0.5, r:range(-1, 1) * P2[r:int(-300, 300)] })
          bs[k] = r:range(-1, 1) * P2[r:int(-300, 300)]
          signs[k] = r:pick({ 1, -1 })
          products[k] = mul(new(signs[k]), mul(new(as[k]), new(bs[k])))
        end
        assert.is_true(isExactly(exact.sumOfProducts(as, bs, signs), exact.sum(products)))
      end
    end)

    it("gives hand-computed sums", function()
      -- 3 * 4 - 0.5 * 0.25 = 11.875; (2^53 - 1)^2 - 2^106 = -2^54 + 1
      assert.is_true(isExactly(exact.sumOfProducts({ 3, 0.5 }, { 4, 0.25 }, { 1, -1 }), new(11.875)))
      local m = 2 ^ 53 - 1
      local s = exact.sumOfProducts({ m, 2 ^ 53 }, { m, 2 ^ 53 }, { 1, -1 })
      assert.is_true(isExactly(s, add(exact.neg(exact.pow2(54)), new(1))))
      assert.are.equal(0, exact.sign(exact.sumOfProducts({ 0.1, 0.2 }, { 0.2, 0.1 }, { 1, -1 })))
      assert.are.equal(0, exact.sign(exact.sumOfProducts({}, {}, {})))
    end)
  end)

  describe("tonumber", function()
    it("rounds ties to even", function()
      -- 2^53 + 1 lies halfway between 2^53 and 2^53 + 2: even mantissa wins, 2^53.
      assert.are.equal(2 ^ 53, exact.tonumber(add(exact.pow2(53), new(1))))
      -- 2^53 + 3 lies halfway between 2^53 + 2 and 2^53 + 4: 2^53 + 4.
      assert.are.equal(2 ^ 53 + 4, exact.tonumber(add(exact.pow2(53), new(3))))
      -- just above the halfway point rounds up: 2^53 + 1 + 2^-10 -> 2^53 + 2
      assert.are.equal(2 ^ 53 + 2, exact.tonumber(add(add(exact.pow2(53), new(1)), exact.pow2(-10))))
      -- 2^106 - 2^54 + 1 -> 2^106 - 2^54 (the gap below 2^106 is 2^53)
      local a = new(2 ^ 53 - 1)
      assert.are.equal(2 ^ 106 - 2 ^ 54, exact.tonumber(mul(a, a)))
    end)

    it("rounds in the subnormal range and overflows to infinity", function()
      -- 2^-1075 is halfway between 0 and 2^-1074: ties to even give 0.
      assert.are.equal(0, exact.tonumber(exact.pow2(-1075)))
      -- 3 * 2^-1075 is halfway between 1 and 2 times 2^-1074: 2 * 2^-1074.
      assert.are.equal(P2[-1073], exact.tonumber(mul(new(3), exact.pow2(-1075))))
      assert.are.equal(P2[-1074], exact.tonumber(exact.pow2(-1074)))
      -- just above half of 2^-1074 rounds up, in one rounding (two roundings, to 53 bits first
      -- and then to the subnormal grid, would give 0): 2^-1075 + 2^-1135
      assert.are.equal(P2[-1074], exact.tonumber(add(exact.pow2(-1075), exact.pow2(-1135))))
      -- and below the smallest normal: (2^52 - 1/2 - 2^-61) * 2^-1074 -> (2^52 - 1) * 2^-1074
      local below = sub(sub(exact.pow2(-1022), exact.pow2(-1075)), exact.pow2(-1135))
      assert.are.equal(P2[-1022] - P2[-1074], exact.tonumber(below))
      assert.are.equal(math.huge, exact.tonumber(exact.pow2(1024)))
      assert.are.equal(-1.7976931348623157e308, exact.tonumber(new(-1.7976931348623157e308)))
    end)

    it("returns every double unchanged", function()
      for _, x in ipairs({ 0.1, -0.3, 1e300, 5e-324, 2.2250738585072014e-308, 123456789.125, -2 ^ 60 }) do
        assert.are.equal(x, exact.tonumber(new(x)))
      end
    end)
  end)

  describe("nextUp and nextDown", function()
    it("step to the neighbouring doubles", function()
      assert.are.equal(1 + 2 ^ -52, exact.nextUp(1))
      assert.are.equal(1 - 2 ^ -53, exact.nextDown(1)) -- below a power of two the gap halves
      assert.are.equal(-1 + 2 ^ -53, exact.nextUp(-1))
      assert.are.equal(1.5 - 2 ^ -52, exact.nextDown(1.5))
      assert.are.equal(P2[-1074], exact.nextUp(0))
      assert.are.equal(-P2[-1074], exact.nextDown(0))
      assert.are.equal(0, exact.nextDown(P2[-1074]))
      -- the smallest normal: the subnormals below it are 2^-1074 apart too
      assert.are.equal(P2[-1022] - P2[-1074], exact.nextDown(P2[-1022]))
      assert.are.equal(1e15 + 0.125, exact.nextUp(1e15))
    end)
  end)

  describe("ulp and withinUlps", function()
    it("gives the place value of the last significand bit", function()
      assert.is_true(isExactly(exact.ulp(1), exact.pow2(-52)))
      assert.is_true(isExactly(exact.ulp(1.5), exact.pow2(-52)))
      assert.is_true(isExactly(exact.ulp(0.5), exact.pow2(-53)))
      assert.is_true(isExactly(exact.ulp(-3), exact.pow2(-51)))
      assert.is_true(isExactly(exact.ulp(0), exact.pow2(-1074)))
      assert.is_true(isExactly(exact.ulp(P2[-1074]), exact.pow2(-1074)))
      assert.is_true(isExactly(exact.ulp(1.7976931348623157e308), exact.pow2(971)))
    end)

    it("measures the distance exactly", function()
      local third = new(1 / 3)
      -- 1 + 2^-52 is one ulp above 1; 1 + 2^-51 two ulps
      assert.is_true(exact.withinUlps(1 + 2 ^ -52, new(1), 1))
      assert.is_false(exact.withinUlps(1 + 2 ^ -51, new(1), 1))
      assert.is_true(exact.withinUlps(1 + 2 ^ -51, new(1), 2))
      assert.is_true(exact.withinUlps(1 / 3, third, 0))
      -- 1/3 as a double vs 0.1 + 0.2 exact: far apart
      assert.is_false(exact.withinUlps(1 / 3, add(new(0.1), new(0.2)), 1))
    end)
  end)

  describe("new", function()
    it("takes Lua integers as the equal double", function()
      local toInteger = rawget(math, "tointeger") -- Lua 5.3+ only
      local i = toInteger and toInteger(4503599627370497) or 4503599627370497 -- 2^52 + 1
      assert.is_true(isExactly(new(i), add(exact.pow2(52), new(1))))
      assert.is_true(isExactly(new(-7), new(-7.0)))
    end)
  end)
end)

describe("oracle", function()
  describe("orient", function()
    it("signs the turn of three points (y down: positive is clockwise on screen)", function()
      -- (10,0)-(0,0) x (0,10)-(0,0) = 10 * 10 - 0 * 0 = 100
      assert.are.equal(1, oracle.orient(0, 0, 10, 0, 0, 10))
      assert.are.equal(-1, oracle.orient(0, 0, 0, 10, 10, 0))
      assert.are.equal(0, oracle.orient(0, 0, 1, 1, 3, 3))
      -- points with x == y always lie on the line y = x, whatever their rounding
      assert.are.equal(0, oracle.orient(0.1, 0.1, 0.2, 0.2, 0.3, 0.3))
      -- (0, 0), (1, 0.30000000000000004), (2, 0.6):
      -- cross = 1 * 0.6 - 0.30000000000000004 * 2 = 0.5999999999999999778 - 0.6000000000000000888 < 0
      assert.are.equal(-1, oracle.orient(0, 0, 1, 3 * 0.1, 2, 0.6))
    end)
  end)

  describe("shoelace and winding", function()
    it("follows the contract's square", function()
      -- {0,0, 10,0, 10,10, 0,10}: 0*0 - 10*0 + 10*10 - 10*0 + 10*10 - 0*10 + 0*0 - 0*10 = 200
      local square = { 0, 0, 10, 0, 10, 10, 0, 10 }
      assert.is_true(isExactly(oracle.shoelace(square), new(200)))
      assert.are.equal("cw", oracle.winding(square))
      assert.are.equal("ccw", oracle.winding({ 0, 10, 10, 10, 10, 0, 0, 0 }))
      assert.is_true(isExactly(oracle.area(square), new(100)))
      assert.is_nil(oracle.winding({ 0, 0, 1, 1, 2, 2 }))
      assert.is_nil(oracle.winding({ 0, 0, 1, 1 }))
      -- a bow-tie whose halves cancel: (0,0),(2,2),(2,0),(0,2) -> 0 + 4 - 4 + 0 ... = 0
      assert.is_nil(oracle.winding({ 0, 0, 2, 2, 2, 0, 0, 2 }))
    end)
  end)

  describe("contains", function()
    local square = { 0, 0, 10, 0, 10, 10, 0, 10 }
    it("uses the half-open boundary of the crossing rule", function()
      assert.is_true(oracle.contains(square, 5, 5))
      assert.is_false(oracle.contains(square, 15, 5))
      -- on the left edge: 0 <= 10 (right edge) and 0 <= 0 (left edge) both count: even, outside
      assert.is_false(oracle.contains(square, 0, 5))
      -- on the right edge: 10 <= 10 counts, 10 <= 0 does not: odd, inside
      assert.is_true(oracle.contains(square, 10, 5))
      -- top y = 0: edges (10,10)-(10,0) cross for y = 0 ((10 >= 0) ~= (0 >= 0) is false) -> outside
      assert.is_false(oracle.contains(square, 5, 0))
      -- bottom y = 10: (10 >= 10) ~= (0 >= 10) crosses at x = 10 and x = 0: 5 <= 10 only -> inside
      assert.is_true(oracle.contains(square, 5, 10))
      assert.is_false(oracle.contains({ 0, 0, 1, 1 }, 0, 0))
    end)

    it("decides slanted edges exactly", function()
      -- triangle (0,0),(3,0),(0,3): hypotenuse x + y = 3. 0.1 + 2.9 as doubles: 2.9 is
      -- 2.899999999999999911182158029987..., so (0.1, 2.9) has x + y = 2.99999999999999999444... < 3
      local tri = { 0, 0, 3, 0, 0, 3 }
      assert.is_true(oracle.contains(tri, 0.1, 2.9))
      -- (0.1, 2.9000000000000004) is above the line: x + y > 3
      assert.is_false(oracle.contains(tri, 0.1, 2.9000000000000004))
      -- exactly on the hypotenuse (1.5, 1.5): crossing edge (0,3)-(3,0)... x <= 1.5 holds -> inside
      assert.is_true(oracle.contains(tri, 1.5, 1.5))
      assert.is_true(oracle.onBoundary(tri, 1.5, 1.5))
      assert.is_false(oracle.onBoundary(tri, 0.1, 2.9))
    end)
  end)

  describe("polygonType", function()
    it("classifies by the contract's rules", function()
      assert.are.equal("convex", oracle.polygonType({ 0, 0, 10, 0, 10, 10, 0, 10 }))
      assert.are.equal("convex", oracle.polygonType({ 0, 10, 10, 10, 10, 0, 0, 0 }))
      -- a collinear vertex going forward and a repeated vertex
      assert.are.equal("convex", oracle.polygonType({ 0, 0, 5, 0, 10, 0, 10, 10, 10, 10, 0, 10 }))
      -- dart: reflex vertex (5,3) last
      assert.are.equal("concave", oracle.polygonType({ 0, 0, 10, 0, 5, 10, 5, 3 }))
      -- spike: (10,0) -> (15,0) -> (10,0)... doubles back with zero turn
      assert.are.equal("concave", oracle.polygonType({ 0, 0, 10, 0, 15, 0, 10, 0, 10, 10, 0, 10 }))
      -- bow-tie and pentagram
      assert.are.equal("concave", oracle.polygonType({ 0, 0, 2, 2, 2, 0, 0, 2 }))
      assert.are.equal("concave", oracle.polygonType({ 0, -10, 6, 8, -9, -3, 9, -3, -6, 8 }))
      -- a square walked twice winds twice
      assert.are.equal("concave", oracle.polygonType({ 0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1 }))
      assert.is_nil(oracle.polygonType({ 0, 0, 1, 1, 2, 2, 3, 3 }))
      assert.is_nil(oracle.polygonType({ 1, 1, 1, 1, 1, 1 }))
      assert.is_nil(oracle.polygonType({ 0, 0, 1, 1 }))
      -- collinear but doubling back (0,0),(2,0),(1,0): one line -> nil
      assert.is_nil(oracle.polygonType({ 0, 0, 2, 0, 1, 0 }))
      -- a triangle in both windings
      assert.are.equal("convex", oracle.polygonType({ 0, 0, 3, 0, 0, 3 }))
      assert.are.equal("convex", oracle.polygonType({ 0, 0, 0, 3, 3, 0 }))
    end)
  end)

  describe("collides", function()
    local a = { 0, 0, 10, 0, 10, 10, 0, 10 }
    it("separates, touches and overlaps exactly", function()
      assert.is_true(oracle.collides(a, { 5, 5, 15, 5, 15, 15, 5, 15 }, true))
      -- shared edge x = 10: touching is not colliding
      assert.is_false(oracle.collides(a, { 10, 0, 20, 0, 20, 10, 10, 10 }, true))
      -- shared corner
      assert.is_false(oracle.collides(a, { 10, 10, 20, 10, 20, 20, 10, 20 }, true))
      assert.is_false(oracle.collides(a, { 11, 0, 20, 0, 20, 10, 11, 10 }, true))
      -- a triangle whose slanted edge x + y = 20 meets the corner (10, 10): touching
      assert.is_false(oracle.collides(a, { 20, 0, 20, 20, 0, 20 }, true))
      -- p1's axes alone cannot separate this triangle's slanted side from the square's corner
      assert.is_true(oracle.collides(a, { 20, 0, 20, 20, 0, 20 }, false))
      -- zero-area polygons never collide
      assert.is_false(oracle.collides(a, { 1, 1, 5, 5, 9, 9 }, true))
      -- a repeated vertex gives no axis (a zero normal would make every pair "touch")
      local repeated = { 5, 5, 5, 5, 15, 5, 15, 15, 5, 15 }
      assert.is_true(oracle.collides(a, repeated, true))
      assert.is_true(oracle.collides(repeated, a, false))
    end)

    it("measures the depth as min(max1 - min2, max2 - min1) / |n|", function()
      -- b inside a: axes x and y, overlaps min(10 - 4, 6 - 0) = 6 and min(10 - 3, 5 - 0) = 5
      local depth = oracle.depth(a, { 4, 3, 6, 3, 6, 5, 4, 5 }, true)
      assert.are.equal(5, depth)
      -- overlap by 2 along x: b = [8, 18] x [0, 10]
      assert.are.equal(2, (oracle.depth(a, { 8, 0, 18, 0, 18, 10, 8, 10 }, true)))
      -- separated by 1: depth -1
      assert.are.equal(-1, (oracle.depth(a, { 11, 0, 21, 0, 21, 10, 11, 10 }, true)))
    end)
  end)

  describe("regionCrossing", function()
    local SQUARE = { 0, 0, 10, 0, 10, 10, 0, 10 }
    it("tells valid rings with holes from crossing, outside, nested and degenerate ones", function()
      assert.are.equal("valid", oracle.regionCrossing(SQUARE, { { 1, 1, 5, 1, 5, 5 } }))
      -- touching the outline at (0, 0), and two holes touching at (5, 5)
      assert.are.equal("valid", oracle.regionCrossing(SQUARE, { { 0, 0, 5, 1, 5, 5 } }))
      assert.are.equal("valid", oracle.regionCrossing(SQUARE, { { 1, 1, 5, 1, 5, 5 }, { 5, 5, 6, 5, 6, 6 } }))
      assert.are.same({ "cross", 1, 2 }, { oracle.regionCrossing(SQUARE, { { 5, 5, 15, 5, 15, 6 } }) })
      assert.are.same({ "outside", 1 }, { oracle.regionCrossing(SQUARE, { { 20, 0, 21, 0, 21, 1 } }) })
      assert.are.same({ "inside", 2, 1 },
        { oracle.regionCrossing(SQUARE, { { 1, 1, 5, 1, 5, 5 }, { 2, 1.5, 4, 1.5, 4, 3 } }) })
      -- a triangle inscribed in another, its corners inside the other's edges: they meet wrongly
      -- at (3, 1), (5, 3) and (3, 3) (the chains there do not nest)
      assert.are.same({ "cross", 2, 3 },
        { oracle.regionCrossing(SQUARE, { { 1, 1, 5, 1, 5, 5 }, { 3, 1, 5, 3, 3, 3 } }) })
      -- holes enclosing nothing are skipped; a hole folded into a bow-tie crosses itself
      assert.are.equal("valid", oracle.regionCrossing(SQUARE, { { 1, 1, 2, 2, 3, 3 }, { 4, 4 } }))
      assert.are.same({ "cross", 2, 2 }, { oracle.regionCrossing(SQUARE, { { 1, 1, 3, 3, 3, 1, 1, 3 } }) })
      assert.are.same({ "degenerate", 1 }, { oracle.regionCrossing({ 1, 1, 2, 2, 3, 3 }) })
      -- a bow-tie outline crosses itself
      assert.are.same({ "cross", 1, 1 },
        { oracle.regionCrossing({ 0, 0, 10, 10, 10, 0, 0, 20, -10, 20, -10, 10 }) })
    end)
  end)

  describe("checkCover", function()
    it("takes an exact cover and catches a gap, a piece in a hole and an overlap", function()
      local frame, window = { 0, 0, 30, 0, 30, 30, 0, 30 }, { 10, 10, 20, 10, 20, 20, 10, 20 }
      -- the frame as four trapezoids around the window (area 4 x 200 = 800 = 900 - 100)
      local parts = {
        { 0, 0, 30, 0, 20, 10, 10, 10 }, { 30, 0, 30, 30, 20, 20, 20, 10 },
        { 30, 30, 0, 30, 10, 20, 20, 20 }, { 0, 30, 0, 0, 10, 10, 10, 20 },
      }
      assert.is_true(oracle.checkCover(frame, { window }, parts, true))
      assert.is_false(oracle.checkCover(frame, { window }, { parts[1], parts[2], parts[3] }))
      -- the window's two triangles in place of the bottom trapezoid: a piece in the hole
      local swapped = { parts[2], parts[3], parts[4], { 10, 10, 20, 10, 20, 20 }, { 10, 10, 20, 20, 10, 20 } }
      assert.is_false(oracle.checkCover(frame, { window }, swapped))
      -- the same area as the window, placed over the frame's left trapezoid: an overlap
      local over = { parts[1], parts[2], parts[3], parts[4], { 0, 0, 10, 10, 0, 10 } }
      assert.is_false(oracle.checkCover(frame, { window }, over))
    end)
  end)
end)
