-- Compound shapes: polygonsCollide and polygonsCollideV take lists of convex parts {part1, ...}
-- wherever they take a convex polygon. Some part of one overlapping some part of the other is a
-- collision; the push (dx, dy) moves the whole second shape, and edges shared by two parts of one
-- shape are inside it: never a direction to push along. Pushes carry a rounding margin of a few
-- hundred eps times the scene's size (parts.slack), so lengths are compared within it.
local polygon = require "polygon"
local parts = require "parts"
local shapes = require "shapes"
local oracle = require "oracle"
local callsite = require "callsite"

local collide, collideV = polygon.polygonsCollide, polygon.polygonsCollideV

-- The U-shaped floor U = {0,0, 50,0, 50,200, 250,200, 250,0, 300,0, 300,250, 0,250} cut by hand into
-- two pillars and the floor between them (y down: the floor's top edge is y = 200).
local U = {
  { 0, 0, 50, 0, 50, 250, 0, 250 },
  { 50, 200, 250, 200, 250, 250, 50, 250 },
  { 250, 0, 300, 0, 300, 250, 250, 250 },
}
local CRATE = { 130, 165, 170, 165, 170, 205, 130, 205 }   -- its bottom y = 205: sunk 5

-- fn(a, b) for both windings of every part of each shape (flat shapes stay flat)
local function windings(s1, s2, fn)
  local function both(s)
    if type(s[1]) == "table" then return { s, parts.reverse(s) } end
    return { s, shapes.reverse(s) }
  end
  for _, a in ipairs(both(s1)) do
    for _, b in ipairs(both(s2)) do fn(a, b) end
  end
end

local function asList(s)
  if type(s[1]) == "table" then return s end
  return { s }
end

-- the push separates the shapes (module and oracle agree) and has the expected length and
-- direction within the margin
local function assertPush(s1, s2, ex, ey)
  local overlap, dx, dy = collideV(s1, s2)
  assert.is_number(overlap)
  local slack = parts.slack(asList(s1), asList(s2))
  local len = math.sqrt(ex * ex + ey * ey)
  assert.is_true(overlap >= len and overlap <= len + slack,
    ("overlap %.17g, expected %.17g"):format(overlap, len))
  assert.is_true(math.abs(dx - ex) <= slack and math.abs(dy - ey) <= slack,
    ("push %.17g %.17g, expected %g %g"):format(dx, dy, ex, ey))
  local moved = parts.translate(asList(s2), dx, dy)
  assert.is_false(parts.collide(asList(s1), moved))
  assert.is_false(collide(s1, moved))
  return dx, dy
end

describe("compound shapes", function()
  describe("when a crate is sunk 5 into the floor of a U cut into three parts", function()
    it("collides in both argument orders and windings", function()
      windings(U, CRATE, function(u, crate)
        assert.is_true(collide(u, crate))
        assert.is_true(collide(crate, u))
      end)
    end)

    it("pushes the crate straight up by 5 (205 - 200), or the U down by 5", function()
      windings(U, CRATE, function(u, crate)
        local dx = assertPush(u, crate, 0, -5)
        assert.are.equal(0, dx)
        dx = assertPush(crate, u, 0, 5)
        assert.are.equal(0, dx)
      end)
    end)

    it("does not collide once resting on the floor (touching is not colliding)", function()
      local resting = shapes.translate(CRATE, 0, -5)
      windings(U, resting, function(u, crate)
        assert.is_false(collide(u, crate))
        assert.is_false(collideV(u, crate))
        assert.is_false(collideV(crate, u))
      end)
    end)
  end)

  describe("when a crate sits in a concave corner of the U", function()
    -- crate x 45..65, y 190..210: 5 into the left pillar (x < 50), 10 into the floor (y > 200).
    -- Straight up it must clear the pillar (210 up), sideways the whole floor; out of the
    -- corner it moves by (5, -10), length sqrt(125).
    local crate = parts.box(45, 190, 20, 20)
    -- the mirror image in the right corner: x 235..255 is 5 into the right pillar (x > 250)
    local mirrored = parts.box(235, 190, 20, 20)

    it("goes out of the corner, not through a wall", function()
      windings(U, crate, function(u, c)
        assertPush(u, c, 5, -10)
        assertPush(c, u, -5, 10)
      end)
      windings(U, mirrored, function(u, c)
        assertPush(u, c, -5, -10)
      end)
    end)
  end)

  describe("when a crate is sunk into a floor of 20 parts", function()
    -- 20 parts of width 10 from x = 0 to 200, top edge y = 100; crate 8 by 8.
    local floor = parts.floor(20, 10, 100, 0)

    it("is pushed straight up by its depth at every position, on the seams too", function()
      for _, depth in ipairs({ 0.25, 3, 7.5 }) do
        for step = 0, 384 do   -- x from 0 to 192 by 0.5: every seam x = 10 k is met
          local crate = parts.box(step / 2, 100 - 8 + depth, 8, 8)
          local overlap, dx, dy = collideV(floor, crate)
          assert.are.equal(0, dx)
          assert.is_true(overlap >= depth and overlap <= depth + parts.slack(floor, { crate }))
          assert.are.equal(-overlap, dy)
          assert.is_false(collide(floor, shapes.translate(crate, dx, dy)))
        end
      end
    end)

    it("pushes the floor down instead in the other argument order", function()
      for step = 0, 40 do
        local crate = parts.box(step * 4.75, 95, 8, 8)   -- sunk 3
        windings(floor, crate, function(f, c)
          assertPush(c, f, 0, 3)
        end)
      end
    end)

    it("is pushed up when the crate is itself made of two parts split over a seam", function()
      for step = 0, 40 do
        local x = step * 4.75
        local crate = { parts.box(x, 96, 4, 8), parts.box(x + 4, 96, 4, 8) }   -- sunk 4
        windings(floor, crate, function(f, c)
          assertPush(f, c, 0, -4)
          assertPush(c, f, 0, 4)
        end)
      end
    end)
  end)

  describe("when parts share edges only in pieces", function()
    -- two layers of blocks with staggered seams: the top layer (y 100..110) from x = 5, the
    -- bottom one (y 110..120) from x = 0, both of width 10: each top block's bottom edge is
    -- covered by halves of two bottom blocks' top edges
    local layered = {}
    for k = 0, 9 do
      layered[#layered + 1] = parts.box(5 + 10 * k, 100, 10, 10)
      layered[#layered + 1] = parts.box(10 * k, 110, 10, 10)
    end

    it("pushes a crate out through the top or the bottom, never along a seam", function()
      for step = 0, 30 do
        local x = 10 + step * 2.5
        windings(layered, parts.box(x, 94, 8, 8), function(l, c)
          assertPush(l, c, 0, -2)   -- bottom at 102: sunk 2 into the top layer
        end)
        windings(layered, parts.box(x, 119, 8, 8), function(l, c)
          assertPush(l, c, 0, 1)    -- top at 119: 1 into the bottom layer from below
        end)
      end
    end)
  end)

  describe("when a convex polygon meets a compound shape", function()
    it("takes a flat polygon for either argument", function()
      local slab = { 0, 100, 200, 100, 200, 130, 0, 130 }
      local crate = { parts.box(50, 96, 4, 8), parts.box(54, 96, 4, 8) }   -- sunk 4
      assertPush(slab, crate, 0, -4)
      assertPush(crate, slab, 0, 4)
    end)
  end)

  describe("when parts are degenerate", function()
    it("ignores parts of zero area", function()
      local list = { { 0, 0, 5, 5, 10, 10 }, { 3, 3, 3, 3, 3, 3 }, parts.box(0, 0, 10, 10) }
      assert.is_true(collide(list, parts.box(8, 2, 10, 5)))
      assertPush(list, parts.box(8, 2, 10, 5), 2, 0)
      assert.is_false(collide({ { 0, 0, 5, 5, 10, 10 } }, parts.box(0, 0, 10, 10)))
      assert.are.equal(false, collideV({ { 0, 0, 5, 5, 10, 10 } }, parts.box(0, 0, 10, 10)))
    end)

    it("refuses parts with fewer than 3 points (spec/refusals_spec.lua has every message)", function()
      local box = parts.box(8, 2, 10, 5)
      assert.has_error(function() collide({ { 0, 0, 10, 0 }, parts.box(0, 0, 10, 10) }, box) end,
        "polygonsCollide: points1[1] has 2 points: a segment; a polygon needs at least 3; "
        .. "for line of sight use polygonRayCast")
      assert.has_error(function() collideV({ parts.box(0, 0, 10, 10), {} }, parts.box(8, 2, 10, 5)) end,
        "polygonsCollideV: points1[2] is empty; a polygon needs at least 3 points")
    end)
  end)

  describe("when a list's parts change between calls", function()
    -- Each list keeps its parts' boxes, signs and normals from call to call: the changes a game
    -- makes must be seen, and each answer be the one for the coordinates of the moment.
    it("follows a floor moved in place by polygonTranslate", function()
      local floor = parts.floor(20, 10, 100, 0)
      local crate = parts.box(50, 95, 8, 8)   -- bottom y = 103: sunk 3
      assertPush(floor, crate, 0, -3)
      polygon.polygonTranslate(floor, 0, 10, floor)   -- top edge now y = 110: 7 below the crate
      assert.is_false(collide(floor, crate))
      assert.is_false(collideV(floor, crate))
      polygon.polygonTranslate(floor, 0, -11, floor)   -- top edge y = 99: sunk 4
      assertPush(floor, crate, 0, -4)
    end)

    it("follows one part moved by hand, coordinate by coordinate", function()
      local list = { parts.box(0, 0, 10, 10), parts.box(100, 0, 10, 10) }
      local crate = parts.box(40, 2, 8, 6)
      assert.is_false(collideV(list, crate))
      local far = list[2]
      for i = 1, #far, 2 do far[i] = far[i] - 58 end   -- x from 42 to 52: 48 - 42 = 6 into the crate
      assert.is_true(collide(list, crate))
      assertPush(list, crate, -6, 0)
    end)

    it("follows a part reshaped with its first vertex kept", function()
      local list = { { 0, 0, 10, 0, 10, 10, 0, 10 } }
      local crate = parts.box(40, 2, 8, 6)
      assert.is_false(collideV(list, crate))
      list[1][3], list[1][5] = 42, 42   -- the right side from x = 10 to 42: 42 - 40 = 2 into it
      assert.is_true(collide(list, crate))
      assertPush(list, crate, 2, 0)
    end)

    it("sees a rectangle's second or fourth vertex moved inside its box", function()
      -- A rectangle's first and third vertices hold the four coordinates on its box: the other
      -- two can move with the box unchanged. The square 0..10 with its second vertex (10, 0)
      -- moved to (5, 0): the edge (5, 0) -> (10, 10) is the line x = 5 + y / 2, at x = 5.75 for
      -- y = 1.5, left of the crate x 8..9.5, y 0.5..1.5, which was inside the square (out
      -- through the top by 1.5: 1.5 < 2 right, 9.5 down or left).
      local list = { parts.box(0, 0, 10, 10), parts.box(30, 0, 10, 10) }
      local crate = parts.box(8, 0.5, 1.5, 1)
      for _ = 1, 2 do
        assertPush(list, crate, 0, -1.5)
        list[1][3] = 5
        assert.is_false(parts.collide(list, { crate }))
        assert.is_false(collide(list, crate))
        assert.is_false(collideV(list, crate))
        assert.is_false(collideV(crate, list))
        list[1][3] = 10
      end
      -- Its fourth vertex (0, 10) moved to (0, 5): the edge (10, 10) -> (0, 5) is the line
      -- y = 5 + x / 2, at y = 5.75 for x = 1.5, above the crate x 0.5..1.5, y 8..9.5, which was
      -- inside the square (out through the left by 1.5: 1.5 < 2 down, 9.5 up or right).
      crate = parts.box(0.5, 8, 1, 1.5)
      for _ = 1, 2 do
        assertPush(list, crate, -1.5, 0)
        list[1][8] = 5
        assert.is_false(parts.collide(list, { crate }))
        assert.is_false(collide(list, crate))
        assert.is_false(collideV(list, crate))
        list[1][8] = 10
      end
    end)

    it("follows a rectangle written from another corner, moved by hand", function()
      -- {10,10, 0,10, 0,0, 10,0}: its first vertex is its (xmax, ymax). Moved right by 32, its x
      -- 32..42 reach 42 - 40 = 2 into the crate x 40..48: out to the right by 2 (to the left by
      -- 48 - 32 = 16; the crate's y 2..8 against 0..10: down by 10 - 2 = 8, up by 8 - 0 = 8).
      local list = { { 10, 10, 0, 10, 0, 0, 10, 0 }, parts.box(100, 0, 10, 10) }
      local crate = parts.box(40, 2, 8, 6)
      assert.is_false(collideV(list, crate))
      for i = 1, 7, 2 do list[1][i] = list[1][i] + 32 end
      assert.is_true(collide(list, crate))
      assertPush(list, crate, 2, 0)
      for i = 1, 7, 2 do list[1][i] = list[1][i] - 32 end
      assert.is_false(collide(list, crate))
      assert.is_false(collideV(list, crate))
    end)

    it("follows a part whose table is replaced or whose vertex count changes", function()
      local list = { parts.box(0, 0, 10, 10) }
      local crate = parts.box(40, 2, 8, 6)
      assert.is_false(collideV(list, crate))
      -- x from 35 to 45: right by 45 - 40 = 5, left by 48 - 35 = 13, up or down by 8
      list[1] = parts.box(35, 0, 10, 10)
      assertPush(list, crate, 5, 0)
      -- a fifth vertex: the tip (44, 5) reaches into the crate
      list[1] = parts.box(0, 0, 10, 10)
      assert.is_false(collideV(list, crate))
      table.insert(list[1], 5, 44)
      table.insert(list[1], 6, 5)
      assert.is_true(parts.collide(list, { crate }))
      assert.is_true(collide(list, crate))
      local overlap, dx, dy = collideV(list, crate)
      assert.is_number(overlap)
      assert.is_false(parts.collide(list, parts.translate({ crate }, dx, dy)))
    end)

    it("follows a vertex inserted or removed with the coordinates on the part's box kept", function()
      -- The triangle (0,0) (10,0) (0,10): x + y < 10 inside. Its box's xmin, ymin, xmax, ymax
      -- are first met at indices 1, 2, 3 and 6; a vertex (10,10) inserted after (10,0) keeps
      -- those four coordinates (0, 0, 10 and now 10,10's y = 10) and makes the square 0..10.
      local list = { { 0, 0, 10, 0, 0, 10 } }
      local crate = parts.box(8, 6, 1.5, 1)   -- 8 + 6 = 14 > 10: clear of the triangle
      for _ = 1, 2 do
        assert.is_false(collide(list, crate))
        assert.is_false(collideV(list, crate))
        table.insert(list[1], 5, 10)
        table.insert(list[1], 6, 10)
        -- in the square: right by 10 - 8 = 2, down by 10 - 6 = 4, up by 7, left by 9.5
        assert.is_true(collide(list, crate))
        assertPush(list, crate, 2, 0)
        assertPush(crate, list, -2, 0)
        table.remove(list[1], 5)
        table.remove(list[1], 5)   -- the triangle again, a length 8 -> 6 with the same four
      end
      assert.is_false(collideV(crate, list))
      -- A square whose fifth vertex (-4, 5) is appended: its corners and box unchanged, the
      -- crate x -3..-1, y 4..6 then inside it (at y = 4 and 6 the slanted edges are at x = -3.2).
      list = { parts.box(0, 0, 10, 10) }
      crate = parts.box(-3, 4, 2, 2)
      for _ = 1, 2 do
        assert.is_false(collideV(list, crate))
        list[1][9], list[1][10] = -4, 5
        assert.is_true(collide(list, crate))
        local overlap, dx, dy = collideV(list, crate)
        assert.is_number(overlap)
        assert.is_false(parts.collide(list, parts.translate({ crate }, dx, dy)))
        list[1][10], list[1][9] = nil, nil
      end
    end)

    it("sees the interior coordinates of a part moved by a tie (extremes kept)", function()
      -- x = 2 and 3 have even last bits, 2 + 2^-51 an odd one: adding half their ulp (2^-52)
      -- leaves 2 and 3 (ties round to even) and moves 2 + 2^-51 to 2 + 2^-50. The box is unchanged
      -- (rounding is monotonic), and the answers are the oracle's for the moved coordinates.
      local odd = 2 + 2 ^ -51
      local list = { { 2, 0, 3, 0, 3, 1, odd, 2 } }
      local crate = { 2.5, 1.5, 4, 1.5, 4, 3, 2.5, 3 }
      local before = collideV(list, crate)
      for i = 1, 7, 2 do list[1][i] = list[1][i] + 2 ^ -52 end
      assert.are.equal(2, list[1][1])
      assert.are.equal(2 + 2 ^ -50, list[1][7])
      assert.are.equal(parts.collide(list, { crate }), collide(list, crate))
      local overlap, dx, dy = collideV(list, crate)
      assert.are.equal(before ~= false, overlap ~= false)
      if overlap then assert.is_false(parts.collide(list, parts.translate({ crate }, dx, dy))) end
    end)

    it("raises the error for a non-finite coordinate written into a prepared part", function()
      local list = { parts.box(0, 0, 10, 10), parts.box(100, 0, 10, 10) }
      local crate = parts.box(5, 5, 8, 8)
      assert.is_number(collideV(list, crate))
      -- far from the crate, but watched: a rectangle's first and third vertices (opposite
      -- corners) hold the four coordinates on its box; the third one's x is its xmax
      list[2][5] = 0 / 0
      for _ = 1, 2 do
        assert.has_error(function() collideV(list, crate) end,
          "polygonsCollideV: points1 holds a non-finite coordinate")
      end
      list[2][5] = 110
      assert.is_number(collideV(list, crate))
      list[1][3] = math.huge   -- near the crate, off the watched coordinates of the box
      assert.has_error(function() collideV(list, crate) end,
        "polygonsCollideV: points1 holds a non-finite coordinate")
      assert.has_error(function() collide(list, crate) end,
        "polygonsCollide: points1 holds a non-finite coordinate")
    end)
  end)

  describe("when arguments are bad", function()
    it("names the function, the argument and the part", function()
      local box = parts.box(0, 0, 10, 10)
      assert.has_error(function() collideV({ box, 5 }, box) end,
        "polygonsCollideV: points1[2] must be a table, got number")
      assert.has_error(function() collide(box, { box, { 1, 2, 3 } }) end,
        "polygonsCollide: points2[2] must hold an even number of coordinates, got 3")
      assert.has_error(function() collideV({ box }, nil) end,
        "polygonsCollideV: points2 must be a table, got nil")
    end)

    it("points the error at the caller's line, for a bad coordinate near the other shape or far", function()
      local crate = parts.box(5, 5, 8, 8)
      local function spoilt(k, i)   -- a prepared list whose part k gets a NaN at index i
        local list = { parts.box(0, 0, 10, 10), parts.box(100, 0, 10, 10) }
        assert.is_number(collideV(list, crate))
        list[k][i] = 0 / 0
        return list
      end
      -- part 1 (near the crate) off its box's watched coordinates (its second vertex), part 2
      -- (far) on its xmax (its third vertex: see above)
      for _, where in ipairs({ { 1, 3 }, { 2, 5 } }) do
        local k, i = where[1], where[2]
        assert.is_true(callsite.raisesAtCaller(collideV, { spoilt(k, i), crate }))
        assert.is_true(callsite.raisesAtCaller(collideV, { crate, spoilt(k, i) }))
        assert.is_true(callsite.raisesAtCaller(collideV, { spoilt(k, i), { crate } }))
        assert.is_true(callsite.raisesAtCaller(collide, { spoilt(k, i), crate }))
        assert.is_true(callsite.raisesAtCaller(polygon.polygonCircleCollideV, { spoilt(k, i), 6, 6, 2 }))
      end
    end)

    it("raises the first argument's error first when both are bad", function()
      local box = parts.box(0, 0, 10, 10)
      for _, fn in ipairs({ collide, collideV }) do
        local name = fn == collide and "polygonsCollide" or "polygonsCollideV"
        assert.has_error(function() fn({ box, 5 }, { 1, 2, 3 }) end,
          name .. ": points1[2] must be a table, got number")
        assert.has_error(function() fn({ 1, 2, 3, 4 }, { box, 5 }) end,
          name .. ": points1 has 2 points: a segment; a polygon needs at least 3; "
          .. "for line of sight use polygonRayCast")
        assert.has_error(function() fn({ box, { 0 / 0, 0, 1, 0, 1, 1 } }, { 0, 0, 1 / 0, 0, 1, 1 }) end,
          name .. ": points1 holds a non-finite coordinate")
      end
    end)

    it("raises the same error as for flat polygons on a non-finite coordinate", function()
      local box = parts.box(0, 0, 10, 10)
      for _, bad in ipairs({ 0 / 0, math.huge, -math.huge }) do
        assert.has_error(function() collideV({ box, { 1, 1, bad, 1, 2, 2 } }, box) end,
          "polygonsCollideV: points1 holds a non-finite coordinate")
        assert.has_error(function() collide(box, { { 1, 1, 5, 1, 2, bad } }) end,
          "polygonsCollide: points2 holds a non-finite coordinate")
      end
    end)
  end)
end)

describe("compound shapes against circles", function()
  local circleV = polygon.polygonCircleCollideV

  -- the circle moved by the push meets no part, by the exact oracle and by the module
  local function assertCirclePush(list, cx, cy, r, ex, ey)
    local overlap, dx, dy = circleV(list, cx, cy, r)
    assert.is_number(overlap)
    local slack = parts.slack(list, { parts.box(cx - r, cy - r, 2 * r, 2 * r) })
    local len = math.sqrt(ex * ex + ey * ey)
    assert.is_true(overlap >= len and overlap <= len + slack,
      ("overlap %.17g, expected %.17g"):format(overlap, len))
    assert.is_true(math.abs(dx - ex) <= slack and math.abs(dy - ey) <= slack,
      ("push %.17g %.17g, expected %g %g"):format(dx, dy, ex, ey))
    assert.is_false(circleV(list, cx + dx, cy + dy, r))
    for _, p in ipairs(list) do assert.is_false(oracle.discMeetsPolygon(p, cx + dx, cy + dy, r)) end
    return dx, dy
  end

  it("pushes a circle sunk 5 into the U's floor straight up by 5", function()
    -- centre y 190, radius 15: the disc reaches y = 205, the floor's top is y = 200
    for _, u in ipairs({ U, parts.reverse(U) }) do
      local dx = assertCirclePush(u, 150, 190, 15, 0, -5)
      assert.are.equal(0, dx)
    end
  end)

  it("pushes a circle out of a concave corner along the diagonal", function()
    -- centre (60, 190), radius 15: 5 into the left pillar (x < 50) and 5 into the floor; out of
    -- the corner the centre goes to (65, 185), 15 from both lines: a move of (5, -5)
    for _, u in ipairs({ U, parts.reverse(U) }) do
      assertCirclePush(u, 60, 190, 15, 5, -5)
      assertCirclePush(u, 240, 190, 15, -5, -5)
    end
  end)

  it("pushes a circle up by its depth at every position along a 20-part floor", function()
    local floor = parts.floor(20, 10, 100, 0)
    for step = 0, 80 do   -- centres from x = 5 to 195 by 2.375, seams x = 10 k among them
      local x = 5 + step * 2.375
      local overlap, dx, dy = circleV(floor, x, 97, 5)   -- reaches y = 102: depth 2
      assert.are.equal(0, dx)
      assert.are.equal(-overlap, dy)
      assert.is_true(overlap >= 2 and overlap <= 2 + parts.slack(floor, { parts.box(x - 5, 92, 10, 10) }))
      assert.is_false(circleV(floor, x + dx, 97 + dy, 5))
    end
  end)

  it("does not collide when touching a part, or with radius 0", function()
    assert.is_false(circleV(U, 150, 185, 15))   -- reaches y = 200 exactly
    assert.is_false(circleV(U, 65, 185, 15))    -- touches the pillar and the floor
    assert.is_false(circleV(U, 150, 220, 0))
  end)

  it("names the function and argument for bad circles and parts", function()
    assert.has_error(function() circleV(U, 0 / 0, 1, 1) end, "polygonCircleCollideV: cx must be finite, got "
      .. tostring(0 / 0))
    assert.has_error(function() circleV(U, 1, 1, -1) end,
      "polygonCircleCollideV: radius must not be negative, got -1")
    assert.has_error(function() circleV({ U[1], { 0, 0, 1, 0, 0, math.huge } }, 1, 1, 1) end,
      "polygonCircleCollideV: points holds a non-finite coordinate")
    assert.has_error(function() circleV({ U[1], 7 }, 1, 1, 1) end,
      "polygonCircleCollideV: points[2] must be a table, got number")
  end)
end)

describe("compound shapes from polygonConvexParts", function()
  it("push a crate out of the U-shaped floor by 5, out of its corner by (5, -10)", function()
    local u = { 0, 0, 50, 0, 50, 200, 250, 200, 250, 0, 300, 0, 300, 250, 0, 250 }
    local parts1 = assert(polygon.polygonConvexParts(u))
    assertPush(parts1, CRATE, 0, -5)
    assertPush(parts1, parts.box(45, 190, 20, 20), 5, -10)
    assertPush(CRATE, parts1, 0, 5)
  end)

  it("push a crate straight up along a floor whose parts meet the top at many seams", function()
    -- top edge y = 100 from x = 0 to 200 through a vertex every 10; a zigzag underside makes
    -- the outline concave, so its parts are cut along diagonals that end on the top edge
    local outline = {}
    for x = 0, 200, 10 do outline[#outline + 1] = x; outline[#outline + 1] = 100 end
    for k = 0, 20 do
      outline[#outline + 1] = 200 - 10 * k
      outline[#outline + 1] = 130 + (k % 2) * 10
    end
    local list = assert(polygon.polygonConvexParts(outline))
    assert.is_true(#list > 5)
    for step = 0, 96 do
      local crate = parts.box(step * 2, 94, 8, 8)   -- sunk 2
      local overlap, dx, dy = collideV(list, crate)
      assert.are.equal(0, dx)
      assert.are.equal(-overlap, dy)
      assert.is_true(overlap >= 2 and overlap <= 2 + parts.slack(list, { crate }))
      local ox, cdx, cdy = polygon.polygonCircleCollideV(list, step * 2 + 1, 97, 5)   -- sunk 2
      assert.are.equal(0, cdx)
      assert.is_true(ox >= 2 and -cdy == ox)
    end
  end)
end)
