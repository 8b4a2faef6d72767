-- Issue 29 item 2: the collision functions' convexity check is fused into their engines' first
-- pass (convex.lua's vouching pass: one error bound shared by all turns, SHARED_BOUND spanX
-- spanY from the bounding box, plus TINY; the windings by the exact signs of the edges' x
-- differences). Hard cases around the bound's threshold, huge and tiny coordinates, slivers,
-- far offsets, windings and non-finite entries, each checked against the oracle's exact
-- convexity: a check that accepts exactly the convex polygons (and those of zero area), through
-- the pass or the careful walk, and a pass that never vouches for another and, when it vouches,
-- gives the area's sign and the box.
local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local shapes = require "shapes"
local convex = require "polygon.convex"

local FAR = { 1e30, 1e30, 1e30 + 1e15, 1e30, 1e30, 1e30 + 1e15 }   -- never near the cases

-- The pass's four bodies on one polygon: each dialect written out for its size (or its loop
-- beyond 8 vertices) and each dialect's loop. Asserts that they agree (the sign, the box;
-- PUC's indices between its two bodies) and returns the sign, or nil when none vouches.
local function passes(p)
  local n = #p
  local label = table.concat(p, ", ")
  local jit = { convex.vouchJit(p, n) }
  local jitLoop = { convex.vouchLoopJit(p, n) }
  local puc = { convex.vouchPuc(p, n) }
  local pucLoop = { convex.vouchLoopPuc(p, n) }
  for k = 1, 5 do
    assert.are.equal(jit[k], jitLoop[k], label)
    assert.are.equal(jit[k], puc[k], label)
  end
  for k = 1, 7 do assert.are.equal(puc[k], pucLoop[k], label) end
  return jit[1]
end

-- Asserts that the collision check accepts p exactly when the oracle finds it convex or of
-- zero area, and that no body of the pass vouches for a polygon the oracle does not find
-- convex, nor gives another sign than its area's. Returns whether the pass vouched.
local function agreesWithOracle(p)
  local kind = oracle.polygonType(p)
  local label = table.concat(p, ", ")
  local takes = kind ~= "concave"
  local ok, err = pcall(polygon.polygonsCollide, p, FAR)
  assert.are.equal(takes, ok, label .. ": " .. tostring(err))
  if not ok then assert.is_truthy(tostring(err):find("is not convex", 1, true), tostring(err)) end
  local turn = passes(p)
  if turn then
    assert.are.equal("convex", kind, label)
    assert.are.equal(oracle.winding(p) == "cw" and 1 or -1, turn, label)
  end
  return turn ~= nil
end

-- The box W x H with a vertex under the middle of its bottom edge, at (W/2, -k 2^-53 H): its
-- turn there is W k 2^-53 H exactly (W, H powers of two), against the shared bound 2 (3 + 16
-- eps) eps W (H + k 2^-53 H): just above it from k = 7, not from k = 6 down. k < 0 is a reflex
-- turn, k = 0 a collinear vertex (convex). Counter-clockwise, or reversed.
local function dented(W, H, k, reversed)
  local p = { 0, 0, W / 2, -k * 2^-53 * H, W, 0, W, H, 0, H }
  if reversed then p = shapes.reverse(p) end
  return p
end

describe("the shared bound's threshold", function()
  it("vouches from a turn of 7 eps of the box's area, leaves 6 and below to the walk", function()
    -- W = 2^p, H = 2^q: the dent's turn W (k 2^-53 H) = k 2^(p+q-53), the bound about 6 2^(p+q-53)
    for _, wh in ipairs({ { 1, 1 }, { 2^20, 2^-20 }, { 2^-30, 2^40 }, { 1024, 8 } }) do
      for _, reversed in ipairs({ false, true }) do
        for k = -9, 9 do
          local p = dented(wh[1], wh[2], k, reversed)
          local vouched = agreesWithOracle(p)
          assert.are.equal(k >= 7, vouched, ("k = %d, %s"):format(k, table.concat(p, ", ")))
        end
      end
    end
  end)

  it("holds at 2^500 (no overflow) and hands 2^-500 (turns below TINY) to the walk", function()
    for _, k in ipairs({ -7, -6, -1, 0, 1, 6, 7, 100 }) do
      local big = shapes.scale(dented(1, 1, k), 2^500)
      assert.are.equal(k >= 7, agreesWithOracle(big), "2^500, k = " .. k)
      local small = shapes.scale(dented(1, 1, k), 2^-500)
      assert.is_false(agreesWithOracle(small), "2^-500, k = " .. k)
    end
  end)

  it("decides by the walk where the box's area overflows (coordinates near 1e300)", function()
    for _, k in ipairs({ -2^40, -1, 0, 1, 2^40 }) do
      local p = shapes.scale(dented(1, 1, k), 2^1000)   -- area 2^2000: the bound is inf
      assert.is_false(agreesWithOracle(p), "k = " .. k)
      p = { -1e300, -1e300, 0, -1e300 - k * 1e284, 1e300, -1e300, 1e300, 1e300, -1e300, 1e300 }
      assert.is_false(agreesWithOracle(p), "1e300, k = " .. k)
    end
  end)

  it("keeps every decision at far offsets (1e6 + 0.5, 1e9, 1e12: the dent rounds)", function()
    for _, offset in ipairs({ 1e6 + 0.5, 1e9, 1e12, -1e12 }) do
      for _, size in ipairs({ 1, 1000, 2^-10 }) do
        for k = -8, 8 do
          for _, reversed in ipairs({ false, true }) do
            agreesWithOracle(shapes.translate(dented(size, size, k * 2^20, reversed), offset, offset))
            agreesWithOracle(shapes.translate(dented(size, size, k, reversed), offset, -offset))
          end
        end
      end
    end
  end)
end)

describe("slivers and near-collinear chains", function()
  it("vouches for thin triangles and needles (their turns are their boxes' areas)", function()
    for e = 1, 60, 3 do
      local h = 2^-e
      assert.is_true(agreesWithOracle({ 0, 0, 1, 0, 0.5, h }), "h = 2^-" .. e)
      -- a needle along the diagonal: its box is about its length squared, its turn h times it
      local needle = { 0, 0, 1, 1, 1 - h, 1 }
      local vouched = agreesWithOracle(needle)
      assert.are.equal(e <= 50, vouched, "needle h = 2^-" .. e)
      agreesWithOracle(shapes.translate(needle, 1e9, -1e9))
    end
  end)

  it("agrees with the oracle on arcs of many vertices whose turns are near the bound", function()
    -- vertices on y = -c x (m - x) for x = 0 .. m, closed by the chord; the turns 2 c, the box m
    -- by c m^2 / 4: turn over area about 8 / m^3, far above 2^-50, unless c is so small that the
    -- arc's y round (then collinear or reflex, the oracle decides)
    local rng = prng.new(2911)
    for _ = 1, 200 do
      local m = rng:int(3, 20)
      local c = 2^-rng:int(0, 60) * rng:range(0.5, 1)
      local ox, oy = rng:pick({ 0, 0.5, 1e6 + 0.5, -1e9 }), rng:pick({ 0, 1e6, 1e12 })
      local p = {}
      for x = 0, m do
        p[#p + 1], p[#p + 2] = x + ox, -c * x * (m - x) + oy
      end
      if rng:int(0, 1) == 1 then p = shapes.reverse(p) end
      agreesWithOracle(p)
    end
  end)
end)

describe("turns whose float sign is wrong", function()
  it("refuses the reflex ones and takes the convex ones (B rounded onto the segment AC)", function()
    -- A in [0, 1]^2, C in [50, 100]^2, B = A + u (C - A) rounded, D = (-50, 150) on the left:
    -- the turns at C, D and A are far from 0; the one at B is B's rounding, and the edges'
    -- rounded differences (B - A rounds at B's ulp) give its float value the wrong sign in
    -- about 1 case of 30 (a /tmp count: 101 of 3000) and 0 in about 1 of 4.
    local rng = prng.new(1234)
    local convexCount, concaveCount = 0, 0
    for _ = 1, 1500 do
      local ax, ay = rng:range(0, 1), rng:range(0, 1)
      local cx, cy = rng:range(50, 100), rng:range(50, 100)
      local u = rng:range(0.2, 0.8)
      local p = { ax, ay, ax + u * (cx - ax), ay + u * (cy - ay), cx, cy, -50, 150 }
      agreesWithOracle(p)
      agreesWithOracle(shapes.reverse(p))
      local kind = oracle.polygonType(p)
      if kind == "convex" then convexCount = convexCount + 1 end
      if kind == "concave" then concaveCount = concaveCount + 1 end
    end
    assert.is_true(convexCount > 300 and concaveCount > 300, convexCount .. " " .. concaveCount)
  end)
end)

describe("random convex polygons with a dented edge", function()
  it("agrees with the oracle when a vertex is put a few ulps off an edge's midpoint", function()
    local rng = prng.new(77)
    local vouched, refused = 0, 0
    for _ = 1, 400 do
      local m, size = rng:int(3, 10), rng:pick({ 1, 100, 1e-3, 1e5 })
      local ox, oy = rng:pick({ 0, 1e6 + 0.5, -1e9, 1e12 }), rng:pick({ 0, 0.5, 1e6 })
      local p = shapes.convex(rng, m, ox, oy, size, 0.3)
      local i = 2 * rng:int(1, m) - 1
      local j = i + 2 > #p and 1 or i + 2
      local mx, my = (p[i] + p[j]) / 2, (p[i + 1] + p[j + 1]) / 2
      local k = rng:int(-12, 12) * size * 2^-52
      local ex, ey = p[j] - p[i], p[j + 1] - p[i + 1]
      -- outward for counter-clockwise (shapes.convex): the right-hand normal (ey, -ex)
      local len = math.sqrt(ex * ex + ey * ey)
      table.insert(p, i + 2, my - k * ex / len)
      table.insert(p, i + 2, mx + k * ey / len)
      if rng:int(0, 1) == 1 then p = shapes.reverse(p) end
      if agreesWithOracle(p) then vouched = vouched + 1 end
      if oracle.polygonType(p) == "concave" then refused = refused + 1 end
    end
    assert.is_true(vouched > 20 and refused > 50, ("vouched %d, refused %d"):format(vouched, refused))
  end)
end)

describe("windings and non-finite entries", function()
  it("never vouches for a star that winds twice (its turns all agree)", function()
    for _, offset in ipairs({ 0, 1e6 + 0.5, 1e12 }) do
      local p = {}
      for v = 0, 4 do
        local a = v * 4 * math.pi / 5
        p[#p + 1], p[#p + 2] = math.cos(a) * 100 + offset, math.sin(a) * 100 + offset
      end
      assert.is_false(agreesWithOracle(p))
    end
  end)

  -- The star polygons {m/k} wind k times with every turn alike. Their x and y scaled apart,
  -- down to x differences below the least normal double (where a product of two differences
  -- underflows to 0: the winding count takes the differences' signs, exact at every size).
  it("never vouches for a star that winds more than once, its x and y scaled apart", function()
    local rng = prng.new(4242)
    local stars = { { 5, 2 }, { 7, 2 }, { 7, 3 }, { 8, 3 } }
    for _, xs in ipairs({ 1, 2^-1000, 2^-1040, 2^-1060, 2^-1070, 2^500 }) do
      for _, ys in ipairs({ 1, 2^-500, 2^500, 2^900 }) do
        for _, star in ipairs(stars) do
          local m, k = star[1], star[2]
          local p, phase = {}, rng:range(0, 2 * math.pi)
          for v = 0, m - 1 do
            local a = phase + v * k * 2 * math.pi / m
            p[#p + 1], p[#p + 2] = math.cos(a) * 100 * xs, math.sin(a) * 100 * ys
          end
          assert.is_false(agreesWithOracle(p), ("{%d/%d} at %g, %g"):format(m, k, xs, ys))
          agreesWithOracle(shapes.reverse(p))
        end
      end
    end
  end)

  it("agrees with the oracle on convex polygons whose x and y are scaled apart", function()
    local rng = prng.new(4243)
    local vouched = 0
    for _ = 1, 600 do
      local m = rng:int(3, 10)
      local p = shapes.convex(rng, m, 0, 0, 100, 0.3)
      local xs, ys = 2^-rng:int(0, 1070), 2^rng:int(-600, 900)
      if rng:int(0, 1) == 1 then xs, ys = ys, xs end
      for i = 1, #p - 1, 2 do p[i], p[i + 1] = p[i] * xs, p[i + 1] * ys end
      if rng:int(0, 1) == 1 then p = shapes.reverse(p) end
      if agreesWithOracle(p) then vouched = vouched + 1 end
    end
    assert.is_true(vouched > 100, ("vouched %d"):format(vouched))
  end)

  it("never vouches for a NaN or infinite coordinate (min and max may drop a NaN)", function()
    local nan, inf = 0 / 0, math.huge
    for _, bad in ipairs({ nan, inf, -inf }) do
      for slot = 1, 8 do
        local p = { 0, 0, 10, 0, 10, 10, 0, 10 }
        p[slot] = bad
        assert.is_nil(passes(p), ("slot %d, %s"):format(slot, tostring(bad)))
        local ok, err = pcall(polygon.polygonsCollide, p, FAR)
        assert.is_false(ok)
        assert.is_truthy(tostring(err):find("non-finite", 1, true), tostring(err))
      end
    end
  end)
end)

-- polygonCircleCollideV takes the check in its edge walk on LuaJIT, its error bound from the
-- squared distance to the farthest vertex: a circle far from a small polygon leaves the
-- decision to the careful walk. Either way the same polygons are taken and refused.
describe("the circle's check, near and far", function()
  it("takes and refuses as the oracle says, the circle at any distance", function()
    local rng = prng.new(5150)
    local taken, refused = 0, 0
    for _ = 1, 300 do
      local m = rng:int(3, 12)
      local p = shapes.convex(rng, m, rng:range(-50, 50), rng:range(-50, 50), rng:range(1, 40), 0.3)
      if rng:int(0, 2) == 0 then   -- a vertex pushed inward past its neighbours' chord: concave
        local i = 2 * rng:int(1, m) - 1
        p[i], p[i + 1] = p[i] * 0.2, p[i + 1] * 0.2
      end
      if rng:int(0, 1) == 1 then p = shapes.reverse(p) end
      local takes = oracle.polygonType(p) ~= "concave"
      for _, d in ipairs({ 0, 30, 1e6, 1e12, 1e200 }) do
        local ok, err = pcall(polygon.polygonCircleCollideV, p, d, -d, rng:range(0.5, 20) + d / 2)
        assert.are.equal(takes, ok, table.concat(p, ", ") .. " at " .. d .. ": " .. tostring(err))
        if not ok then assert.is_truthy(tostring(err):find("is not convex", 1, true)) end
      end
      if takes then taken = taken + 1 else refused = refused + 1 end
    end
    assert.is_true(taken > 100 and refused > 30, ("taken %d, refused %d"):format(taken, refused))
  end)
end)
