-- Compound shapes, hard cases: generated scenes checked against the exact per-pair oracle
-- (spec/support/oracle.lua) and the true least translation (spec/support/union.lua, the nearest
-- boundary point of the union of the parts' Minkowski differences); far offsets; no garbage.
local polygon = require "polygon"
local parts = require "parts"
local scenes = require "scenes"
local union = require "union"
local prng = require "prng"
local tally = require "tally"
local garbage = require "garbage"

local collide, collideV = polygon.polygonsCollide, polygon.polygonsCollideV

local OFFSETS = { 0, 1e5, 1e9, 1e12 + 0.375 }

-- Checks one call: boolean as the oracle's, push separating, and the push's excess over the true
-- least translation. Returns the excess (nil when the shapes do not collide).
local function check(s1, s2, wrong)
  local overlap, dx, dy = collideV(s1, s2)
  local truth = parts.collide(s1, s2)
  wrong.boolean:check(collide(s1, s2) == truth and (overlap ~= false) == truth, s1, s2)
  -- a list of one part passed as the flat array itself, the other shape still a list: the same
  -- answers, number for number (two flat arrays go to the convex engine, another push)
  for _, pair in ipairs({ { #s1 == 1 and s1[1], s2 }, { s1, #s2 == 1 and s2[1] } }) do
    if pair[1] and pair[2] then
      local o, x, y = collideV(pair[1], pair[2])
      wrong.flat:check(collide(pair[1], pair[2]) == truth and o == overlap and x == dx and y == dy,
        s1, s2)
    end
  end
  if not overlap then return nil end
  local moved = parts.translate(s2, dx, dy)
  wrong.separation:check(not parts.collide(s1, moved) and not collide(s1, moved), s1, s2, dx, dy)
  local least = union.leastTranslation(s1, s2)
  -- the oracle is good to about 1e-12 of the numbers' size; the push may not be shorter
  wrong.shorter:check(overlap >= least * (1 - 1e-9), s1, s2, overlap, least)
  return overlap - least, parts.slack(s1, s2), least
end

local function newWrong()
  return { boolean = tally.new("boolean unlike the oracle"),
           flat = tally.new("a one-part list passed flat answers otherwise"),
           separation = tally.new("push leaves a collision"),
           shorter = tally.new("push shorter than the least translation") }
end

local function assertNone(wrong)
  for _, t in pairs(wrong) do
    assert.are.equal(0, t.count, t.what .. ": " .. table.concat(t.examples, "\n"))
  end
end

-- check in both argument orders, counted into stats: the collisions, those whose excess is
-- beyond the face margin, and the worst excess relative to the least push plus that margin
local function checkBothOrders(s1, s2, wrong, stats)
  for _, order in ipairs({ { s1, s2 }, { s2, s1 } }) do
    local excess, slack, least = check(order[1], order[2], wrong)
    if excess then
      stats.collisions = stats.collisions + 1
      if excess > slack then stats.beyondSlack = stats.beyondSlack + 1 end
      stats.worst = math.max(stats.worst, excess / (least + slack))
    end
  end
end

describe("compound shapes against the union oracle", function()
  it("agrees on random clusters, terrains and crates, both argument orders, at every offset", function()
    local g = prng.new(2026)
    local wrong = newWrong()
    local stats = { collisions = 0, beyondSlack = 0, worst = 0 }
    for trial = 1, 240 do
      local off = OFFSETS[trial % #OFFSETS + 1]
      local s1, s2 = scenes.pair(g, trial % 3 + 1)
      if trial % 2 == 0 then s1 = parts.reverse(s1) end
      checkBothOrders(parts.translate(s1, off, off), parts.translate(s2, off, off), wrong, stats)
    end
    assertNone(wrong)
    assert.is_true(stats.collisions > 150)
    -- beyond the face margin only at crossings of lines meeting at an angle
    assert.is_true(stats.beyondSlack <= stats.collisions / 50,
      stats.beyondSlack .. " of " .. stats.collisions)
    assert.is_true(stats.worst < 1e-2, "worst relative excess " .. stats.worst)
  end)

  it("agrees on lists of axis-parallel rectangles (tiles) against boxes and tiles, both orders", function()
    -- every part a rectangle: seams on both sides, vertices in every order and winding
    local g = prng.new(4242)
    local function tileList(cols, rows, size, ox, oy)
      local list = {}
      for r = 0, rows - 1 do
        for c = 0, cols - 1 do
          if #list == 0 or g:float() < 0.7 then
            local b = parts.box(ox + c * size, oy + r * size, size, size)
            if g:float() < 0.5 then b = { b[1], b[2], b[7], b[8], b[5], b[6], b[3], b[4] } end
            local start = 2 * g:int(0, 3)   -- the first vertex any corner
            local turned = {}
            for i = 1, 8 do turned[i] = b[(i - 1 + start) % 8 + 1] end
            list[#list + 1] = turned
          end
        end
      end
      return list
    end
    local wrong = newWrong()
    local stats = { collisions = 0, beyondSlack = 0, worst = 0 }
    for trial = 1, 120 do
      local off = OFFSETS[trial % #OFFSETS + 1]
      local s1 = tileList(g:int(1, 4), g:int(1, 3), g:pick({ 1, 2.5, 10 }), off, off)
      local s2 = tileList(g:int(1, 2), g:int(1, 2), g:pick({ 0.5, 3, 7 }),
        off + g:range(-2, 10), off + g:range(-2, 10))
      checkBothOrders(s1, s2, wrong, stats)
    end
    assertNone(wrong)
    assert.is_true(stats.collisions > 60, stats.collisions .. " collisions")
    assert.is_true(stats.beyondSlack <= stats.collisions / 50,
      stats.beyondSlack .. " of " .. stats.collisions)
    assert.is_true(stats.worst < 1e-2, "worst relative excess " .. stats.worst)
  end)

  it("pushes a flat box out of a list of boxes as out of the one-part list, at every way out", function()
    -- A box against a list of boxes takes the rectangles' own search (every D a box); passed as a
    -- one-part list it takes the general one: check compares them number for number, and both
    -- with the oracle. The scenes reach each way that search hands back to the general one: a
    -- push beyond half the box's width plus height (deep and thin crates), a part near the push
    -- that is not a pair (crates flush with a part's side or a gap's edge), a near part that is
    -- not a rectangle (a wedge in the row), and pushes at a crossing (crates in a corner).
    -- Scenes with a wedge count apart: a crate that fits a slot exactly, flush with the wedge's
    -- vertical side, is not free there (a pair that is not two rectangles is tested widened by
    -- the margin), and its push may be longer than the least (README, "Accuracy").
    local g = prng.new(515)
    local wrong = newWrong()
    local stats = { collisions = 0, beyondSlack = 0, worst = 0 }
    local wedgeStats = { collisions = 0, beyondSlack = 0, worst = 0 }
    for trial = 1, 200 do
      local off = OFFSETS[trial % #OFFSETS + 1]
      local size = g:pick({ 1, 4, 10 })
      local list = {}
      local wedge = false
      for k = 0, 5 do
        if g:float() < 0.8 then   -- a row of parts with gaps, some taller (corners)
          local top = 10 * size - (g:float() < 0.3 and g:int(1, 3) * size or 0)
          if g:float() < 0.1 then   -- a wedge, not a rectangle
            wedge = true
            list[#list + 1] = { off + k * size, off + 13 * size, off + (k + 1) * size, off + top,
                                off + (k + 1) * size, off + 13 * size }
          else
            list[#list + 1] = parts.box(off + k * size, off + top, size, 13 * size - top)
          end
        end
      end
      if #list == 0 then list[1] = parts.box(off, off + 10 * size, size, size) end
      local w = g:pick({ 0.3, 0.8, 2, 5 }) * size
      local h = g:pick({ 0.3, 0.8, 2, 5 }) * size
      -- on the grid (flush with sides and seams) or off it
      local x = g:float() < 0.5 and g:int(-1, 6) * size or g:range(-1, 6) * size
      local y = 10 * size - h + g:pick({ 0.25, 0.5, 1, 2, 4 }) * size * (g:float() < 0.3 and 0.01 or 1)
      local crate = parts.box(off + x, off + y, w, h)
      checkBothOrders(list, { crate }, wrong, wedge and wedgeStats or stats)
    end
    assertNone(wrong)
    assert.is_true(wedgeStats.collisions > 20, wedgeStats.collisions .. " collisions with a wedge")
    assert.is_true(stats.collisions > 150, stats.collisions .. " collisions")
    -- rectangles only: every push within the face margin (tripled) of the least, crossings too
    -- (their lines meet at right angles); the depths of 0.01 size at 1e12 are near that margin
    assert.are.equal(0, stats.beyondSlack, stats.beyondSlack .. " of " .. stats.collisions)
  end)

  it("pushes a 4 x 4 crate sunk 1 into the seam of two boxes straight up, either order", function()
    -- floor boxes x 0..10 and 10..20, top y = 10; the crate x 8..12, y 7..11: it reaches 1 below
    -- the top, and 2 past the seam on each side: the least push is up 1 (the margin is about
    -- 2^-47 (20 + 4) + 2^-52 20, below 1e-12). The crate first: the floor moves down by 1.
    local floor = { parts.box(0, 10, 10, 20), parts.box(10, 10, 10, 20) }
    local crate = parts.box(8, 7, 4, 4)
    local overlap, dx, dy = collideV(floor, crate)
    assert.are.equal(0, dx)
    assert.is_true(math.abs(dy + 1) < 1e-12 and math.abs(overlap - 1) < 1e-12, overlap .. " " .. dy)
    overlap, dx, dy = collideV(crate, floor)
    assert.are.equal(0, dx)
    assert.is_true(math.abs(dy - 1) < 1e-12 and math.abs(overlap - 1) < 1e-12, overlap .. " " .. dy)
  end)

  it("pushes a crate that fits a slot exactly straight up out of it, flush with both walls", function()
    -- walls x 0..10 and 20..30 from y 0, the slot's bottom x 10..20 from y 20; the crate x 10..20,
    -- y 12..22 reaches 2 into the bottom and touches both walls: up 2 leaves it touching them,
    -- which is not colliding (it went 20 sideways, over a wall, while touching counted as not free);
    -- 2 itself where the depth is exact (at offset 0 and 1e5), else 2 and the margin
    local slot = { parts.box(0, 0, 10, 40), parts.box(10, 20, 10, 20), parts.box(20, 0, 10, 40) }
    for _, off in ipairs(OFFSETS) do
      local shifted, crate = parts.translate(slot, off, off), parts.box(10 + off, 12 + off, 10, 10)
      local overlap, dx, dy = collideV(shifted, crate)
      assert.are.equal(0, dx)
      assert.is_true(math.abs(dy + 2) < 1e-3 and dy <= -2 and overlap >= 2, off .. ": " .. dy)
      assert.is_false(collide(shifted, parts.translate({ crate }, dx, dy)))
      overlap, dx, dy = collideV({ crate }, shifted)   -- the slot moves down instead
      assert.are.equal(0, dx)
      assert.is_true(math.abs(dy - 2) < 1e-3 and dy >= 2 and overlap >= 2, off .. ": " .. dy)
    end
  end)

  it("finds the least translation exactly (within the margin) for crates on terrain", function()
    -- every push along a face: the margin bounds the excess everywhere
    local g = prng.new(77)
    local wrong = newWrong()
    for trial = 1, 120 do
      local terrain, width = scenes.terrain(g, 15)
      local x = g:range(0, width - 6)
      local crate = { parts.box(x, 15, 6, g:range(30, 60)) }   -- a pillar from above into it
      local excess, slack = check(terrain, crate, wrong)
      if excess then wrong.shorter:check(excess <= 100 * slack, trial, excess, slack) end
    end
    assertNone(wrong)
  end)
end)

describe("circles against compound shapes, against the oracle", function()
  it("decide overlap exactly, separate in one push, and move no farther than needed", function()
    -- The least move of a circle is bounded by union.circleLeastMove: the disc replaced by a
    -- 24-gon inscribed in it (a lower bound) and one circumscribed (an upper bound, 0.9% longer).
    local oracle = require "oracle"
    local g = prng.new(9)
    local wrong = newWrong()
    local collisions = 0
    for trial = 1, 60 do
      local off = OFFSETS[trial % #OFFSETS + 1]
      local list = trial % 2 == 0 and scenes.cluster(g, g:int(1, 5), 60, 30) or scenes.terrain(g, 10)
      local cx, cy, r = g:range(0, 80), g:range(0, 90), g:range(1, 20)
      if trial % 3 == 0 then list = parts.reverse(list) end
      local moved = parts.translate(list, off, off)
      local overlap, dx, dy = polygon.polygonCircleCollideV(moved, cx + off, cy + off, r)
      local truth = false
      for _, p in ipairs(moved) do
        if oracle.discMeetsPolygon(p, cx + off, cy + off, r) then truth = true end
      end
      wrong.boolean:check((overlap ~= false) == truth, trial)
      if overlap then
        collisions = collisions + 1
        local meets = polygon.polygonCircleCollideV(moved, cx + off + dx, cy + off + dy, r)
        for _, p in ipairs(moved) do
          if oracle.discMeetsPolygon(p, cx + off + dx, cy + off + dy, r) then meets = true end
        end
        wrong.separation:check(not meets, trial, dx, dy)
        local lower, upper = union.circleLeastMove(list, cx, cy, r, 24)
        local slack = parts.slack(moved, { parts.box(cx + off - r, cy + off - r, 2 * r, 2 * r) })
        -- the bounds are of the problem before the offset; cx + off and cy + off round by half
        -- an ulp of the offset each, which moves the least move by up to an ulp (a push of the
        -- depth itself, along a side, may come that much below the bound at 1e12)
        local shift = 2 ^ -52 * off
        wrong.shorter:check(overlap >= lower * (1 - 1e-9) - shift and overlap <= upper + slack,
          trial, overlap, lower, upper)
      end
    end
    assertNone(wrong)
    assert.is_true(collisions > 20, collisions)
  end)
end)

describe("compound shapes far from the origin", function()
  local U = {
    { 0, 0, 50, 0, 50, 250, 0, 250 },
    { 50, 200, 250, 200, 250, 250, 50, 250 },
    { 250, 0, 300, 0, 300, 250, 250, 250 },
  }
  local floor = parts.floor(20, 10, 100, 0)

  it("pushes the crate out of the U floor and corner by the same amounts at 1e5, 1e9, 1e12", function()
    for _, off in ipairs(OFFSETS) do
      local u = parts.translate(U, off, off + 0.25)
      local cases = { { parts.box(130, 165, 40, 40), 0, -5 }, { parts.box(45, 190, 20, 20), 5, -10 } }
      for _, case in ipairs(cases) do
        local crate = parts.translate({ case[1] }, off, off + 0.25)
        local overlap, dx, dy = collideV(u, crate)
        local slack = parts.slack(u, crate)
        assert.is_true(math.abs(dx - case[2]) <= slack and math.abs(dy - case[3]) <= slack,
          ("offset %.17g: push %.17g %.17g"):format(off, dx, dy))
        assert.is_true(overlap >= math.sqrt(case[2] ^ 2 + case[3] ^ 2))
        assert.is_false(parts.collide(u, parts.translate(crate, dx, dy)))
        assert.is_false(collide(u, parts.translate(crate, dx, dy)))
      end
    end
  end)

  it("pushes a crate straight up along a 20-part floor at 1e12 plus a fraction, seams too", function()
    local off = 1e12 + 0.375
    local f = parts.translate(floor, off, off)
    for step = 0, 96 do
      local crate = parts.translate({ parts.box(step * 2, 95, 8, 8) }, off, off)   -- sunk 3
      local overlap, dx, dy = collideV(f, crate)
      assert.are.equal(0, dx)
      assert.are.equal(-overlap, dy)
      assert.is_true(overlap >= 3 and overlap <= 3 + parts.slack(f, crate))
      assert.is_false(collide(f, parts.translate(crate, dx, dy)))
    end
  end)

  it("decides touching exactly at every offset", function()
    for _, off in ipairs(OFFSETS) do
      local f = parts.translate(floor, off, off)
      local resting = parts.translate({ parts.box(35, 92, 8, 8) }, off, off)   -- bottom on y = 100
      assert.is_false(collide(f, resting))
      assert.is_false(collideV(resting, f))
      -- down by about an ulp of the coordinates
      local nudge = math.max(2 ^ -20, off * 2 ^ -50)
      local nudged = parts.translate({ parts.box(35, 92, 8, 8) }, off, off + nudge)
      assert.is_true(collide(f, nudged))
    end
  end)
end)

describe("the boolean at contact", function()
  -- A flat crate (and its mirror, a flat floor part against a list crate) resting exactly on a
  -- random terrain's sloped tops, then moved by about an ulp down, up and sideways: the answers
  -- are the exact oracle's at every offset, in both argument orders. The terrain's tops are
  -- lines through integer points, so a corner placed on one is exactly on it.
  it("agrees with the oracle on resting and nudged crates, flat or listed, at every offset", function()
    local g = prng.new(23)
    local wrong = tally.new("boolean unlike the oracle")
    for _ = 1, 150 do
      local terrain = scenes.terrain(g, 8)
      local column = terrain[g:int(1, #terrain)]
      -- a vertex of the column's top edge, and the crate resting on it or hanging off its end
      local onRight = g:int(0, 1) == 1
      local x, y = column[onRight and 3 or 1], column[onRight and 4 or 2]
      local w, h = g:int(1, 12), g:int(1, 12)
      local left = x - w * g:int(0, 1)   -- its bottom left or bottom right corner there
      for _, off in ipairs(OFFSETS) do
        local nudge = math.max(2 ^ -40, off * 2 ^ -50)
        for _, move in ipairs({ { 0, 0 }, { 0, nudge }, { 0, -nudge }, { nudge, 0 }, { -nudge, nudge } }) do
          local crate = parts.box(left + off + move[1], y - h + off + move[2], w, h)
          local t = parts.translate(terrain, off, off)
          local truth = parts.collide(t, { crate })
          wrong:check(collide(t, crate) == truth and collide(crate, t) == truth
            and collide(t, { crate }) == truth, tally.show(t), tally.show(crate))
          local flatColumn = parts.translate({ column }, off, off)[1]
          local truthColumn = parts.collide({ flatColumn }, { crate })
          wrong:check(collide(flatColumn, { crate }) == truthColumn
            and collide({ crate }, flatColumn) == truthColumn, tally.show(flatColumn), tally.show(crate))
        end
      end
    end
    assert.are.equal(0, wrong.count, table.concat(wrong.examples, "\n"))
    assert.is_true(wrong.total >= 6000)
  end)
end)

describe("compound shapes per frame", function()
  it("allocate nothing once prepared", function()
    local floor = parts.floor(20, 10, 100, 0)
    local crates, twoPart = {}, {}
    for k = 0, 9 do
      crates[#crates + 1] = parts.box(k * 19, 95, 8, 8)
      twoPart[#twoPart + 1] = { parts.box(k * 19, 96, 4, 8), parts.box(k * 19 + 4, 96, 4, 8) }
    end
    local corner = { parts.box(0, 0, 10, 100), parts.box(10, 90, 100, 10) }
    local far = parts.box(300, 0, 5, 5)
    local function body(i)
      local c = crates[i % 10 + 1]
      collideV(floor, c)
      collideV(c, floor)
      collide(floor, c)
      collideV(twoPart[i % 10 + 1], floor)
      collideV(corner, c)
      collideV(floor, far)
      polygon.polygonCircleCollideV(floor, i % 200, 97, 5)
      polygon.polygonCircleCollideV(corner, 12, 88, 4)
    end
    -- garbage.growth runs warm-up rounds first (they prepare the lists and let LuaJIT build
    -- its traces, which live on the heap) and takes the least growth over several runs: a body
    -- that allocated per call would grow the heap in every run.
    collectgarbage("stop")
    local grown = garbage.growth(body, 10000)
    collectgarbage("restart")
    assert.is_true(grown < 1, grown .. " KB")
  end)
end)
