-- Hard cases for polygonAreaAccurate from 65 to 4,096 vertices, where it first tries a split in
-- two passes (the odd vertices' terms x_k (y_{k-1} - y_{k+1}), then the even ones', each pass
-- ending with up to two terms outside its loop of two, the very last one wrapping round to
-- y_1), then tests after the loops: every |x| and |y| small enough for the split, the exact
-- part's partial sums below 2^53 quanta squared (one vertex far out breaks either, or both),
-- and the float part's error below a quarter ulp (a sliver, or a strip winding 40 times round,
-- whose area is tiny for its coordinates, breaks that). Where a test fails the answer comes
-- from the compensated sum or the exact expansion. Within one ulp of the oracle's exact area
-- every time, on every interpreter. (Which test decided was checked, while writing these, with
-- a copy of polygon.lua printing it: of this file's 222 calls that reach the split, before the
-- garbage check was added, 55 passed all four tests.)

local polygon = require "polygon"
local oracle = require "oracle"
local exact = require "exact"
local prng = require "prng"
local shapes = require "shapes"
local garbage = require "garbage"

local function offByMore(points)
  local a = polygon.polygonAreaAccurate(points)
  local want = oracle.area(points)
  if exact.withinUlps(a, want, 1) then return nil end
  return ("%d vertices: got %.17g, exact %s"):format(#points / 2, a, exact.tostring(want))
end

-- Collects the first three polygons off by more than one ulp (none expected).
local function checkAll(list)
  local bad = {}
  for _, points in ipairs(list) do
    local message = offByMore(points)
    if message and #bad < 3 then bad[#bad + 1] = message end
  end
  assert.are.same({}, bad)
end

-- A star of m vertices: random radii at jittered angles around (ox, oy).
local star = shapes.star

-- A star at a random size (2^-30 to 2^30) and offset (up to 2^40 times that), either winding.
local function randomStar(r, m)
  local size = 2 ^ r:int(-30, 30) * (0.5 + r:float())
  local p = star(r, m, size * (r:float() - 0.5) * 2 ^ r:int(0, 40),
    size * (r:float() - 0.5) * 2 ^ r:int(0, 40), size)
  return r:int(0, 1) == 1 and shapes.reverse(p) or p
end

describe("polygonAreaAccurate from 65 to 4,096 vertices", function()
  it("is within one ulp at every number of vertices from 65 to 96 (each pass's last terms)", function()
    local r, list = prng.new(6502), {}
    for m = 65, 96 do
      list[#list + 1] = randomStar(r, m)
      list[#list + 1] = shapes.convex(r, m, r:range(-1e3, 1e3), r:range(-1e3, 1e3), r:range(1, 1e3), 0.3)
    end
    checkAll(list)
  end)

  it("is within one ulp at 4,095, 4,096 and 4,097 vertices", function()
    local r = prng.new(4096)
    checkAll({ star(r, 4095, 3, -2, 50), star(r, 4096, 3, -2, 50), randomStar(r, 4096),
      randomStar(r, 4097), shapes.noisyCircle(4096, r) })
  end)

  it("is within one ulp when one vertex lies far out in x or in y", function()
    -- each pass's first y (vertices m and 1), a vertex of each pass, the middle one (the
    -- size guess) and the last: moved 2^20 to 2^70 times the size away
    local r, list = prng.new(1109), {}
    for _, m in ipairs({ 100, 101, 1000 }) do
      for _, k in ipairs({ 1, 2, 37, 38, (m - m % 2 + 2) / 2, m }) do
        for _, axis in ipairs({ 0, 1 }) do
          for _, shift in ipairs({ 20, 45, 70 }) do
            local p = star(r, m, 5, -3, 100)
            p[2 * k - 1 + axis] = p[2 * k - 1 + axis] + 100 * 2 ^ shift * (r:int(0, 1) * 2 - 1)
            list[#list + 1] = p
          end
        end
      end
    end
    checkAll(list)
  end)

  it("is within one ulp on a strip winding 40 times round (partial sums far beyond the area)", function()
    -- out along a spiral of 40 turns and back along the same spiral 1e-6 further in: the area
    -- is a thin strip's, the partial sums of the terms up to the spiral's whole disc (the
    -- float part's bound fails for these two; shapes.spiral's thick strip passes every test)
    local list = {}
    for _, m in ipairs({ 400, 1201 }) do
      local half, p = math.floor(m / 2), {}
      for i = 0, half - 1 do
        local t = i / half * 40 * 2 * math.pi
        p[#p + 1], p[#p + 2] = (1000 + t) * math.cos(t), (1000 + t) * math.sin(t)
      end
      for i = m - half - 1, 0, -1 do
        local t = i / (m - half) * 40 * 2 * math.pi
        p[#p + 1], p[#p + 2] = (1000 + t - 1e-6) * math.cos(t), (1000 + t - 1e-6) * math.sin(t)
      end
      list[#list + 1] = p
    end
    list[#list + 1] = shapes.spiral(1000, 12)
    checkAll(list)
  end)

  it("is within one ulp on slivers whose float parts cancel", function()
    -- out along y = 0.3 x + up to 2^-k of the length (k from 10 to 60), back along y = 0.3 x
    local r, list = prng.new(3301), {}
    for _, m in ipairs({ 66, 67, 500, 1999 }) do
      for _, k in ipairs({ 10, 30, 45, 60 }) do
        local p, half, ox = {}, math.floor(m / 2), r:range(-1e6, 1e6)
        for i = 1, half do
          local x = ox + i * 0.25
          p[#p + 1], p[#p + 2] = x, 0.3 * x + m * 2 ^ -k * r:float()
        end
        for i = m - half, 1, -1 do
          local x = ox + i * 0.25 * half / (m - half)
          p[#p + 1], p[#p + 2] = x, 0.3 * x
        end
        list[#list + 1] = p
      end
    end
    checkAll(list)
  end)

  it("gives integer and float coordinates the same area, within one ulp", function()
    -- integers on Lua 5.3 and 5.4 (elsewhere the same floats): products of integer parts
    -- would wrap round if they were not converted
    local r = prng.new(5303)
    for _, m in ipairs({ 65, 200, 1001 }) do
      local p = {}
      for k = 1, m do
        local t, rk = 2 * math.pi * k / m, 2 ^ 40 * (0.5 + r:float())
        p[#p + 1], p[#p + 2] = math.floor(rk * math.cos(t)), math.floor(rk * math.sin(t))
      end
      local ints, floats = shapes.integers(p), shapes.floats(p)
      assert.are.equal(polygon.polygonAreaAccurate(floats), polygon.polygonAreaAccurate(ints))
      assert.is_nil(offByMore(floats))
    end
  end)

  it("allocates nothing, on the split and on its fallbacks", function()
    -- a star near the origin and a spiral strip (the split), a star far along both axes (Dot2)
    local r = prng.new(99)
    local near, far = star(r, 1000, 3, -2, 50), star(r, 1000, 1e7, 1e7, 50)
    local list = { near, far, shapes.spiral(1000, 12) }
    local sum = 0
    local kb = garbage.growth(function(i) sum = sum + polygon.polygonAreaAccurate(list[i % 3 + 1]) end, 300)
    assert.are.equal(0, kb)
    assert.is_true(sum > 0)
  end)

  it("raises an error for a non-finite coordinate at any vertex", function()
    local r = prng.new(7)
    for _, bad in ipairs({ 0 / 0, math.huge, -math.huge }) do
      for _, at in ipairs({ 1, 2, 139, 140, 200 }) do
        local p = star(r, 100, 0, 0, 10)
        p[at] = bad
        assert.has_error(function() polygon.polygonAreaAccurate(p) end)
        local ok, message = pcall(polygon.polygonAreaAccurate, p)
        assert.is_false(ok)
        assert.is_truthy(tostring(message):find("polygonAreaAccurate: points holds a non-finite", 1, true))
      end
    end
  end)
end)
