-- Hard cases for polygonAreaAccurate from 3 to 64 vertices, where it first tries a split in one
-- pass: over the vertices on LuaJIT (the terms x_k (y_{k-1} - y_{k+1}), relative to x_1's
-- rounded part, the last one after the loop), over the edges on PUC Lua. Both round every
-- coordinate to a multiple of a quantum guessed from vertex 1 and the middle vertex, and test
-- after the loop that every coordinate was small enough for the split (near vertex 1, in
-- quanta), that the rounded parts' sum was exact, and that the float part's error is below a
-- quarter ulp. Where a test fails the answer comes from the compensated sum (Dot2) or the exact
-- expansion. Within one ulp of the oracle's exact area every time, on every interpreter.
-- The polygons come in families: ordinary ones at every size and many scales, far from the
-- origin (1e9, and 2^40 plus fractions, where vertex 1 is too far out for the split), slivers
-- (too little area for the float part's error), integers (Lua 5.3+ integer subtype), and
-- polygons made to fail the guess (vertex 1 and the middle vertex equal or a few ulps apart, one
-- vertex far out, y far out on the second vertex or on every even one). Which way the split's
-- tests went was counted, while writing these, with a copy of polygon.lua that tallied it
-- (LuaJIT): of this file's 8,462 calls before the garbage check, 5,396 passed them and 3,066
-- fell back. Copies with a mistake each failed here: lo without its xl dl part, no test of the
-- sum of squares, no test of the float part's error.

local polygon = require "polygon"
local oracle = require "oracle"
local exact = require "exact"
local prng = require "prng"
local shapes = require "shapes"
local garbage = require "garbage"

local area = polygon.polygonAreaAccurate

-- The first three polygons off by more than one ulp (none expected), as messages, and the count.
local function offByMore(list)
  local bad, count = {}, 0
  for _, points in ipairs(list) do
    local got = area(points)
    local want = oracle.area(points)
    if not exact.withinUlps(got, want, 1) then
      count = count + 1
      if #bad < 3 then
        bad[#bad + 1] = ("%d vertices: got %.17g, exact %s"):format(#points / 2, got, exact.tostring(want))
      end
    end
  end
  return count, bad
end

local function checkAll(list)
  local count, bad = offByMore(list)
  assert.are.same({}, bad)
  assert.are.equal(0, count)
end

-- Either winding, at random.
local function eitherWinding(r, points)
  return r:int(0, 1) == 1 and shapes.reverse(points) or points
end

-- A star or a convex polygon of m vertices of the given size around (ox, oy).
local function polygonOf(r, m, ox, oy, size)
  local p = r:int(0, 1) == 1 and shapes.star(r, m, ox, oy, size)
    or shapes.convex(r, m, ox, oy, size, 0.3)
  return eitherWinding(r, p)
end

describe("polygonAreaAccurate from 3 to 64 vertices", function()
  it("is within one ulp near the origin at every size and scales from 2^-30 to 2^30", function()
    local r, list = prng.new(364), {}
    for m = 3, 64 do
      for _ = 1, 30 do
        local size = 2 ^ r:int(-30, 30) * (0.5 + r:float())
        list[#list + 1] = polygonOf(r, m, size * (r:float() - 0.5) * 8, size * (r:float() - 0.5) * 8, size)
      end
    end
    checkAll(list)
  end)

  it("is within one ulp at 1e9 and at offsets up to 2^40 times the size", function()
    local r, list = prng.new(1009), {}
    for m = 3, 64 do
      for _ = 1, 20 do
        local size = r:range(1, 100)
        list[#list + 1] = polygonOf(r, m, 1e9 + r:range(-1e3, 1e3), -0.6e9, size)
        local far = 2 ^ r:int(20, 40)
        list[#list + 1] = polygonOf(r, m, far * (r:float() - 0.5), far * (r:float() - 0.5), size)
      end
    end
    checkAll(list)
  end)

  it("is within one ulp at 2^40 plus fractions (vertex 1 too far out for the split)", function()
    -- coordinates 2^40 + k / 8: exact doubles (2^40 has ulp 2^-12), with products near 2^81
    local r, list = prng.new(240), {}
    for m = 3, 64 do
      for _ = 1, 10 do
        local p = {}
        for i = 1, 2 * m do p[i] = 2 ^ 40 + r:int(-4000, 4000) / 8 end
        list[#list + 1] = p
        list[#list + 1] = shapes.translate(polygonOf(r, m, 0, 0, 100), 2 ^ 40, -2 ^ 40)
      end
    end
    checkAll(list)
  end)

  it("is within one ulp on slivers, whose area is tiny for their size", function()
    -- vertices along y = s x with y moved by up to 2 ulps: the area is a few ulps of x y
    local r, list = prng.new(5), {}
    for m = 3, 64 do
      for _ = 1, 10 do
        local p, slope, x0 = {}, r:range(-3, 3), r:range(-1e3, 1e3)
        for k = 1, m do
          local x = x0 + r:range(0, 100)
          local y = slope * x
          p[2 * k - 1], p[2 * k] = x, y + r:int(-2, 2) * exact.tonumber(exact.ulp(y ~= 0 and y or 1))
        end
        list[#list + 1] = p
        -- a thin rectangle, 1e-9 thick, rotated: its area is 1e-6 against products of 1e6
        local c, s = math.cos(r:range(0, 6)), math.sin(r:range(0, 6))
        local q = {}
        for k = 1, m do
          local u = k <= m / 2 and (k - 1) * 1e3 / m or (m - k) * 1e3 / m
          local v = k <= m / 2 and 0 or 1e-9
          q[2 * k - 1], q[2 * k] = 500 + u * c - v * s, -500 + u * s + v * c
        end
        list[#list + 1] = q
      end
    end
    checkAll(list)
  end)

  it("is within one ulp on integer coordinates (Lua integers on 5.3 and 5.4)", function()
    local r, list = prng.new(53), {}
    for m = 3, 64 do
      for _ = 1, 10 do
        local p, q = {}, {}
        for i = 1, 2 * m do
          p[i] = shapes.integer(r:int(-1000, 1000))
          -- up to about 2^52 (exact doubles; their products reach 2^105)
          q[i] = shapes.integer(r:int(-2 ^ 29, 2 ^ 29) * 2 ^ 23 + r:int(0, 2 ^ 23 - 1))
        end
        list[#list + 1] = p
        list[#list + 1] = q
      end
    end
    checkAll(list)
  end)

  describe("when the quantum's guess is bad", function()
    it("is within one ulp with the middle vertex at vertex 1 (a guessed size of 0)", function()
      local r, list = prng.new(77), {}
      for m = 3, 64 do
        local p = polygonOf(r, m, r:range(-10, 10), r:range(-10, 10), r:range(1, 10))
        local k = m - m % 2 + 1   -- the middle vertex's x
        p[k], p[k + 1] = p[1], p[2]
        list[#list + 1] = p
      end
      checkAll(list)
    end)

    it("is within one ulp with the middle vertex a few ulps from vertex 1", function()
      local r, list = prng.new(78), {}
      for m = 3, 64 do
        local p = polygonOf(r, m, r:range(-10, 10), r:range(-10, 10), r:range(1, 10))
        local k = m - m % 2 + 1
        p[k] = exact.tonumber(exact.add(exact.new(p[1]), exact.mul(exact.new(r:int(1, 3)), exact.ulp(p[1]))))
        p[k + 1] = p[2]
        list[#list + 1] = p
      end
      checkAll(list)
    end)

    it("is within one ulp with one vertex far out (2^30 and 2^60 times the size)", function()
      local r, list = prng.new(79), {}
      for m = 3, 64 do
        for _, factor in ipairs({ 2 ^ 30, 2 ^ 60 }) do
          local p = polygonOf(r, m, 0, 0, 1)
          local j = 2 * r:int(1, m) - 1
          p[j], p[j + 1] = p[j] * factor, p[j + 1] * factor
          list[#list + 1] = p
        end
      end
      checkAll(list)
    end)

    it("is within one ulp with vertex 2's y far out (the split's second chain of y)", function()
      local r, list = prng.new(80), {}
      for m = 4, 64 do
        local p = polygonOf(r, m, 0, 0, 1)
        p[4] = p[4] * 2 ^ 40
        list[#list + 1] = p
      end
      checkAll(list)
    end)

    it("is within one ulp with every even vertex's y far out (only y_2 shows it)", function()
      -- m even: y_{k-1} - y_{k+1} joins vertices of one parity, so moving every even vertex
      -- by 2^30 to 2^70 times the size changes no difference the split sums; only the test of
      -- y_2's size sees that those y were too large for it
      local r, list = prng.new(82), {}
      for m = 4, 64, 2 do
        for _, shift in ipairs({ 2 ^ 30, 2 ^ 50, 2 ^ 70 }) do
          local p = polygonOf(r, m, 0, 0, 1)
          for j = 4, 2 * m, 4 do p[j] = p[j] + shift end
          list[#list + 1] = p
        end
      end
      checkAll(list)
    end)
  end)

  it("allocates nothing on ordinary polygons", function()
    local r, list = prng.new(81), {}
    for m = 3, 64 do list[#list + 1] = polygonOf(r, m, r:range(-100, 100), 1e9, r:range(1, 50)) end
    local sum = 0
    local kb = garbage.growth(function(i) sum = sum + area(list[i % #list + 1]) end, 2000)
    assert.are.equal(0, kb)
    assert.is_true(sum > 0)
  end)
end)
