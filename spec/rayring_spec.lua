-- Issue 30, rays against one flat ring of any shape: polygonRayCast on a concave, self-crossing
-- or degenerate polygon, whose region is the open interior by the crossing rule (even-odd, as
-- polygonContains). Hand-computed cases, then generated ones, then the hard cases, every answer
-- checked against spec/support/rays.lua's ringsEntry (exact arithmetic, sharing nothing with the
-- library): hit, miss and inside exactly, the fraction within 8 eps M, the normal an edge's.
local polygon = require "polygon"
local rays = require "rays"
local exact = require "exact"
local prng = require "prng"
local shapes = require "shapes"
local tiles = require "tiles"

local cast = polygon.polygonRayCast
local nextUp, nextDown = exact.nextUp, exact.nextDown
local EPS = 2 ^ -53

local OFFSETS = { 0, 1e6 + 0.5, 1e9, 1e12 }

local function moved(points, o)
  return shapes.translate(points, o, o)
end

local function text(points)
  local out = {}
  for i, v in ipairs(points) do out[i] = ("%.17g"):format(v) end
  return "{" .. table.concat(out, ", ") .. "}"
end

-- The oracle's entry of A -> B into the ring: nil, "inside" or { num, den, normals }. A point
-- (A = B) is inside when A is; ringsEntry cuts a segment of no length at fractions 0 / 0, but
-- it decides "inside" before it looks at the pieces, so it is asked with another B. `crossing`:
-- the ring crosses itself, its normals taken with one fixed side (its winding means nothing).
local function entryOf(points, ax, ay, bx, by, crossing)
  if ax == bx and ay == by then
    local far = ax + (math.abs(ax) + 1)
    return rays.ringsEntry({ points }, ax, ay, far, ay) == "inside" and "inside" or nil
  end
  return rays.ringsEntry({ points }, ax, ay, bx, by, crossing and { 1 } or nil)
end

-- polygonRayCast against the oracle: the same miss, inside or hit; a hit's fraction within
-- 8 eps M of the exact entry. The normal: of a simple ring, one of the oracle's (outward by the
-- winding); of a self-crossing ring (whose winding says nothing of outward), only where the
-- entry lies on one edge alone and the segment crosses it clearly: that edge's normal, against
-- the motion (the region lies ahead). Returns the library's answer.
local function check(points, ax, ay, bx, by, crossing)
  local f, nx, ny = cast(points, ax, ay, bx, by)
  local entry = entryOf(points, ax, ay, bx, by, crossing)
  local where = ("(%.17g, %.17g) -> (%.17g, %.17g) against %s: got %s, %s, %s"):format(ax, ay, bx,
    by, text(points), tostring(f), tostring(nx), tostring(ny))
  if entry == nil then
    assert(f == false and nx == nil, "expected a miss: " .. where)
  elseif entry == "inside" then
    assert(f == 0 and nx == 0 and ny == 0, "expected 0, 0, 0: " .. where)
  else
    assert(type(f) == "number" and type(nx) == "number" and type(ny) == "number",
      "expected a hit: " .. where)
    assert(rays.fractionGood(f, entry, ax, ay, bx, by), ("fraction off the exact %s / %s: %s"):format(
      exact.tostring(entry.num), exact.tostring(entry.den), where))
    if not crossing then
      local allowed = {}
      for _, m in ipairs(entry.normals) do allowed[#allowed + 1] = ("(%.17g, %.17g)"):format(m[1], m[2]) end
      assert(rays.normalGood(nx, ny, entry.normals), "normal none of " .. table.concat(allowed, ", ")
        .. ": " .. where)
    elseif #entry.normals == 1 then
      local m, dx, dy = entry.normals[1], bx - ax, by - ay
      local dot = m[1] * dx + m[2] * dy
      if math.abs(dot) > 1e-6 * math.sqrt(dx * dx + dy * dy) then
        local k = dot < 0 and 1 or -1
        assert(rays.normalGood(nx, ny, { { k * m[1], k * m[2] } }),
          "normal not against the motion: " .. where)
      end
    end
  end
  return f, nx, ny
end

-- check on the ring and on it reversed (the other winding: the same region).
local function checkBoth(points, ax, ay, bx, by)
  check(shapes.reverse(points), ax, ay, bx, by)
  return check(points, ax, ay, bx, by)
end

-- A hand-computed hit: the fraction t within 8 eps and the normal one of `normals`, each
-- component within 4 eps (the oracle holds the contract; this holds the arithmetic).
local function expectHit(t, normals, f, nx, ny)
  assert(type(f) == "number" and math.abs(f - t) <= 8 * EPS, ("fraction %s, expected %.17g"):format(
    tostring(f), t))
  for _, m in ipairs(normals) do
    if math.abs(nx - m[1]) <= 4 * EPS and math.abs(ny - m[2]) <= 4 * EPS then return end
  end
  error(("normal (%.17g, %.17g) is none expected"):format(nx, ny))
end
local PX, NX, PY, NY = { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 }

-- The L: a horizontal arm x in [0, 100], y in [0, 20] and a vertical one x in [0, 20], y in
-- [0, 100]; its notch x > 20, y > 20 is outside; (20, 20) is the reflex vertex. Clockwise on
-- screen (y down): (0,0) -> (100,0) -> (100,20) turns by 100 * 20 > 0.
local L = { 0, 0, 100, 0, 100, 20, 20, 20, 20, 100, 0, 100 }
-- The U: a base y in [0, 10], x in [0, 30], prongs x in [0, 10] and [20, 30] down to y = 50.
local U = { 0, 0, 30, 0, 30, 50, 20, 50, 20, 10, 10, 10, 10, 50, 0, 50 }
-- The bow-tie: diagonals crossing at (5, 5); lobes the triangles (0,0) (5,5) (0,10) on the left
-- and (10,0) (5,5) (10,10) on the right, wound opposite ways (its shoelace sum is 0).
local BOWTIE = { 0, 0, 10, 10, 10, 0, 0, 10 }
-- A staircase: rows y in (0, 10) for x in (0, 10), (10, 20) for x in (0, 20), (20, 30) for
-- x in (0, 30).
local STAIRS = { 0, 0, 10, 0, 10, 10, 20, 10, 20, 20, 30, 20, 30, 30, 0, 30 }
-- A comb: a base y in [0, 10], x in [0, 50], teeth x in [0, 10], [20, 30], [40, 50] down to 40.
local COMB = { 0, 0, 50, 0, 50, 40, 40, 40, 40, 10, 30, 10, 30, 40, 20, 40, 20, 10, 10, 10, 10, 40, 0, 40 }

describe("polygonRayCast on one ring of any shape", function()
  describe("when computed by hand", function()
    it("enters an L's arm across its edge, either winding", function()
      -- y = 50 from x = -20 to 60: in at x = 0, t = 20 / 80, the left edge's normal -x
      expectHit(0.25, { NX }, checkBoth(L, -20, 50, 60, 50))
      -- from (120, 60) to (-20, 60): past the notch x in (20, 100), in at the vertical arm's
      -- edge x = 20, t = (120 - 20) / 140 = 5 / 7, normal +x (not the hull's x = 100)
      expectHit(5 / 7, { PX }, checkBoth(L, 120, 60, -20, 60))
      -- up from the notch, (50, 60) to (50, -20): in at y = 20, t = 40 / 80, normal +y
      expectHit(0.5, { PY }, checkBoth(L, 50, 60, 50, -20))
    end)

    it("gives the first entry of a segment that enters, leaves and enters again", function()
      -- x + y = 80 from (-10, 90) to (90, -10): in at x = 0 (y = 80), t = 10 / 100, out at
      -- x = 20 into the notch, in again at y = 20 (x = 60); the first: normal -x
      expectHit(0.1, { NX }, checkBoth(L, -10, 90, 90, -10))
      -- back: in at y = 0 (x = 80), t = 10 / 100, normal -y
      expectHit(0.1, { NY }, checkBoth(L, 90, -10, -10, 90))
    end)

    it("gives 0, 0, 0 from inside the corner square, and a miss inside the notch", function()
      assert.are.same({ 0, 0, 0 }, { checkBoth(L, 10, 10, 50, 50) })
      assert.are.same({ 0, 0, 0 }, { checkBoth(L, 90, 10, 90, 90) })   -- out of the arm: inside at A
      assert.are.same({ false }, { checkBoth(L, 30, 30, 90, 90) })
    end)

    it("enters through the reflex vertex (20, 20) exactly, with either edge's normal", function()
      -- y = x from (30, 30) to (10, 10): the vertex at t = 10 / 20; its edges y = 20 (normal +y)
      -- and x = 20 (normal +x). Slopes 1/2: y = 10 + x / 2, y = 20 + (x - 20) / 2, the vertex
      -- halfway again, inside the arm past it (0 < y < 20, x < 20)
      for _, seg in ipairs({ { 30, 30, 10, 10 }, { 40, 30, 0, 10 }, { 60, 40, -20, 0 } }) do
        expectHit(0.5, { PY, PX }, checkBoth(L, seg[1], seg[2], seg[3], seg[4]))
      end
    end)

    it("misses along the edge y = 20 from the notch side, enters where the edge ends", function()
      assert.are.equal(false, checkBoth(L, 90, 20, 30, 20))
      assert.are.equal(false, checkBoth(L, 120, 20, 20, 20))   -- ends at the reflex vertex
      -- from (90, 20) to (-10, 20): along the edge to (20, 20), then inside: t = 70 / 100
      expectHit(0.7, { PY, PX }, checkBoth(L, 90, 20, -10, 20))
      -- along x = 20 from (20, 60) up: in at (20, 20), t = 40 / 80
      expectHit(0.5, { PY, PX }, checkBoth(L, 20, 60, 20, -20))
    end)

    it("enters a U's nearer prong, from outside and from the gap between prongs", function()
      -- y = 30 from x = -10 to 40: in at x = 0, t = 10 / 50; back: in at x = 30, t = 10 / 50
      expectHit(0.2, { NX }, checkBoth(U, -10, 30, 40, 30))
      expectHit(0.2, { PX }, checkBoth(U, 40, 30, -10, 30))
      -- from the gap (15, 30) to (40, 30): in at x = 20, t = 5 / 25, normal -x (toward the gap)
      expectHit(0.2, { NX }, checkBoth(U, 15, 30, 40, 30))
      -- down the gap x = 15 from y = 60 to -10: in at the base's edge y = 10, t = 50 / 70, +y
      expectHit(5 / 7, { PY }, checkBoth(U, 15, 60, 15, -10))
    end)

    it("enters a bow-tie's lobes, touches its crossing point without entering", function()
      local function bow(ax, ay, bx, by)
        check(shapes.reverse(BOWTIE), ax, ay, bx, by, true)
        return check(BOWTIE, ax, ay, bx, by, true)
      end
      -- y = 5 through the crossing: in the left lobe at x = 0, t = 5 / 20, normal -x (outward
      -- from the lobe, whatever its winding)
      expectHit(0.25, { NX }, bow(-5, 5, 15, 5))
      -- y = 2 from x = 15: in the right lobe at x = 10, t = 5 / 20, normal +x; it leaves at
      -- x = 8 (y = 10 - x) and enters the left lobe again at x = 2 (y = x)
      expectHit(0.25, { PX }, bow(15, 2, -5, 2))
      -- x = 5 meets the bow-tie at its crossing point alone; y = x runs along an edge
      assert.are.equal(false, bow(5, -5, 5, 15))
      assert.are.equal(false, bow(-5, -5, 15, 15))
      -- from the crossing point: into the left lobe at 0 (the normal of an edge through it), into
      -- the gap between the lobes a miss; from inside a lobe 0, 0, 0
      local s = math.sqrt(0.5)
      expectHit(0, { { -s, s }, { -s, -s }, { s, -s }, { s, s } }, bow(5, 5, 0, 5))
      assert.are.equal(false, bow(5, 5, 5, 0))
      assert.are.same({ 0, 0, 0 }, { bow(2, 5, 2, 50) })
    end)
  end)

  describe("on generated rings", function()
    -- Segments for a shape around (cx, cy) of radius about s, by kind: through it, at random
    -- near it, short, from a point halfway to a vertex, from far away, to or from a vertex.
    local function segment(rng, points, cx, cy, s)
      local kind = rng:int(1, 6)
      local t = rng:range(0, 2 * math.pi)
      local k = 2 * rng:int(1, #points / 2) - 1
      local vx, vy = points[k], points[k + 1]
      if kind == 1 then
        local u = t + math.pi + rng:range(-0.5, 0.5)
        return cx + 2 * s * math.cos(t), cy + 2 * s * math.sin(t), cx + 2 * s * math.cos(u),
          cy + 2 * s * math.sin(u)
      elseif kind == 2 then
        return cx + rng:range(-2, 2) * s, cy + rng:range(-2, 2) * s, cx + rng:range(-2, 2) * s,
          cy + rng:range(-2, 2) * s
      elseif kind == 3 then
        local ax, ay = cx + rng:range(-1.5, 1.5) * s, cy + rng:range(-1.5, 1.5) * s
        return ax, ay, ax + 0.05 * s * math.cos(t), ay + 0.05 * s * math.sin(t)
      elseif kind == 4 then
        local ax, ay = cx + (vx - cx) / 2, cy + (vy - cy) / 2
        return ax, ay, ax + 3 * s * math.cos(t), ay + 3 * s * math.sin(t)
      elseif kind == 5 then
        return cx + 1e3 * s * math.cos(t), cy + 1e3 * s * math.sin(t), cx + rng:range(-1, 1) * s,
          cy + rng:range(-1, 1) * s
      end
      local ax, ay = cx + 2 * s * math.cos(t), cy + 2 * s * math.sin(t)
      if rng:float() < 0.5 then return ax, ay, vx, vy end
      return vx, vy, ax, ay
    end

    it("agree with the oracle on star-shaped rings of 5 to 40 vertices (a sixth convex), both windings",
        function()
      local rng = prng.new(3101)
      local hits, misses, inside = 0, 0, 0
      for round = 1, 100 do
        local o = OFFSETS[round % #OFFSETS + 1]
        local size = rng:pick({ 10, 100, 1000 })
        local points = shapes.star(rng, rng:int(5, 40), o, o, size)
        if round % 6 == 0 then points = shapes.convex(rng, rng:int(3, 12), o, o, size, 0.4) end
        if round % 2 == 0 then points = shapes.reverse(points) end
        for _ = 1, 6 do
          local f = check(points, segment(rng, points, o, o, size))
          if f == false then misses = misses + 1
          elseif f == 0 then inside = inside + 1
          else hits = hits + 1 end
        end
      end
      -- the generator's reach: every answer often
      assert.is_true(hits > 200 and misses > 130 and inside > 100, ("%d hits, %d misses, %d inside"):format(
        hits, misses, inside))
    end)

    it("agree with the oracle on a spiral strip and on tile maps' outlines", function()
      local rng = prng.new(3102)
      for round = 1, 4 do
        local o = OFFSETS[round % #OFFSETS + 1]
        local points = moved(shapes.spiral(60, 1.5), o)
        for _ = 1, 6 do check(points, segment(rng, points, o, o, 200)) end
      end
      local rings = 0
      while rings < 24 do
        local set = tiles.random(rng, 5, 5, 0.7)
        local loops = tiles.loops(set, 10, 0, 0)
        if #loops == 1 then   -- one outline, no hole
          rings = rings + 1
          local o = OFFSETS[rings % #OFFSETS + 1]
          local points = moved(loops[1], o)
          if rings % 2 == 0 then points = shapes.reverse(points) end
          for _ = 1, 5 do check(points, segment(rng, points, o + 25, o + 25, 25)) end
        end
      end
    end)

    it("agree with the oracle on self-crossing rings of random vertex order", function()
      local rng = prng.new(3103)
      local hits = 0
      for round = 1, 150 do
        local o = OFFSETS[round % #OFFSETS + 1]
        local size = rng:pick({ 10, 100 })
        local points = {}
        for i = 1, rng:int(4, 12) do
          points[2 * i - 1], points[2 * i] = o + rng:range(-1, 1) * size, o + rng:range(-1, 1) * size
        end
        for _ = 1, 5 do
          local ax, ay, bx, by = segment(rng, points, o, o, size)
          local f = check(points, ax, ay, bx, by, true)
          hits = hits + ((f and f > 0) and 1 or 0)
        end
      end
      assert.is_true(hits > 250, hits .. " hits")
    end)
  end)
end)

-- The hard cases, each at every offset o: the shapes and segments moved by (o, o) (exact: the
-- shapes are integers), the ulp steps taken at the moved coordinates.
describe("rays on one ring, hard cases: through vertices exactly", function()
  for _, o in ipairs(OFFSETS) do
    it("enters through reflex and convex vertices, grazes convex ones (offset " .. o .. ")", function()
      local l = moved(L, o)
      -- x + y = 120 and y = x - 100 touch the convex vertices (100, 20) and (100, 0) alone
      assert.are.equal(false, checkBoth(l, o + 110, o + 10, o + 90, o + 30))
      assert.are.equal(false, checkBoth(l, o + 90, o - 10, o + 110, o + 10))
      -- y = x - 80 through (100, 20): inside for 80 < x < 100, in at t = 10 / 20
      expectHit(0.5, { PX, PY }, checkBoth(l, o + 110, o + 30, o + 90, o + 10))
      -- through the reflex vertex from every side, and each line moved by an ulp of x either way
      for _, seg in ipairs({ { 40, 40, 0, 0 }, { 0, 0, 40, 40 }, { 20, 40, 20, 0 }, { 40, 20, 0, 20 },
          { 30, 10, 10, 30 }, { 10, 30, 30, 10 }, { 60, 40, -20, 0 } }) do
        local ax, ay, bx, by = o + seg[1], o + seg[2], o + seg[3], o + seg[4]
        checkBoth(l, ax, ay, bx, by)
        checkBoth(l, nextUp(ax), ay, nextUp(bx), by)
        checkBoth(l, nextDown(ax), ay, nextDown(bx), by)
      end
      -- the staircase's vertices in a row: y = x through (10, 10) and (20, 20), reflex both
      for _, seg in ipairs({ { -5, -5, 35, 35 }, { 35, 35, -5, -5 }, { 40, 30, -10, -20 } }) do
        checkBoth(moved(STAIRS, o), o + seg[1], o + seg[2], o + seg[3], o + seg[4])
      end
    end)
  end
end)

describe("rays on one ring, hard cases: along edges and one ulp either side", function()
  -- A concave ring with slanted edges: a chevron, its notch at (10, 6).
  local CHEVRON = { 0, 0, 10, 6, 20, 0, 20, 10, 10, 16, 0, 10 }
  for _, o in ipairs(OFFSETS) do
    it("misses along an edge's line outside, enters beyond, one ulp aside (offset " .. o .. ")", function()
      for _, ring in ipairs({ moved(L, o), moved(U, o), moved(CHEVRON, o), moved(COMB, o) }) do
        local n = #ring
        for i = 1, n, 2 do
          local j = (i + 1) % n + 1
          local px, py, qx, qy = ring[i], ring[i + 1], ring[j], ring[j + 1]
          -- from one edge length before p to one after q (integers: exact), either way
          local ax, ay, bx, by = 2 * px - qx, 2 * py - qy, 2 * qx - px, 2 * qy - py
          for _, seg in ipairs({ { ax, ay, bx, by }, { bx, by, ax, ay }, { px, py, qx, qy } }) do
            checkBoth(ring, seg[1], seg[2], seg[3], seg[4])
            checkBoth(ring, seg[1], nextUp(seg[2]), seg[3], nextUp(seg[4]))
            checkBoth(ring, seg[1], nextDown(seg[2]), seg[3], nextDown(seg[4]))
            checkBoth(ring, nextUp(seg[1]), seg[2], nextUp(seg[3]), seg[4])
            checkBoth(ring, nextDown(seg[1]), seg[2], nextDown(seg[3]), seg[4])
          end
        end
      end
      -- by hand: along the chevron's edge (0, 0) -> (10, 6) from (-10, -6) to (20, 12): on it to
      -- the notch (10, 6), then inside (above (10, 6) -> (20, 0)): t = 20 / 30
      -- the notch's edges' normals (6, -10) / sqrt(136) and (-6, -10) / sqrt(136) (outward: -y)
      local r = math.sqrt(136)
      expectHit(2 / 3, { { 6 / r, -10 / r }, { -6 / r, -10 / r } },
        checkBoth(moved(CHEVRON, o), o - 10, o - 6, o + 20, o + 12))
    end)
  end
end)

describe("rays on one ring, hard cases: starting on the boundary", function()
  for _, o in ipairs(OFFSETS) do
    it("enters at 0 heading in and misses heading out, from edges and vertices (offset " .. o .. ")",
        function()
      local l = moved(L, o)
      -- from the edge x = 0 (at y = 50) in and out; from the edge y = 20 into the notch and back
      expectHit(0, { NX }, checkBoth(l, o, o + 50, o + 10, o + 50))
      assert.are.equal(false, checkBoth(l, o, o + 50, o - 10, o + 50))
      assert.are.equal(false, checkBoth(l, o + 50, o + 20, o + 50, o + 40))
      expectHit(0, { PY }, checkBoth(l, o + 50, o + 20, o + 50, o + 10))
      -- from the reflex vertex: into the corner square, into the notch, along its edges outward
      expectHit(0, { PX, PY }, checkBoth(l, o + 20, o + 20, o + 10, o + 10))
      assert.are.equal(false, checkBoth(l, o + 20, o + 20, o + 40, o + 40))
      assert.are.equal(false, checkBoth(l, o + 20, o + 20, o + 60, o + 20))
      expectHit(0, { PX, PY }, checkBoth(l, o + 20, o + 20, o, o + 20))
      -- from a convex vertex: in along the diagonal, out, along an edge
      expectHit(0, { PY, PX }, checkBoth(l, o + 100, o + 20, o + 90, o + 10))
      assert.are.equal(false, checkBoth(l, o + 100, o + 20, o + 110, o + 30))
      assert.are.equal(false, checkBoth(l, o + 100, o + 20, o + 100, o))
      -- every vertex of the comb toward each of the 8 neighbours one unit away
      local comb = moved(COMB, o)
      for i = 1, #comb, 2 do
        for _, d in ipairs({ { 1, 0 }, { 1, 1 }, { 0, 1 }, { -1, 1 }, { -1, 0 }, { -1, -1 }, { 0, -1 },
            { 1, -1 } }) do
          checkBoth(comb, comb[i], comb[i + 1], comb[i] + d[1], comb[i + 1] + d[2])
        end
      end
    end)
  end
end)

describe("rays on one ring, hard cases: ending exactly on the boundary", function()
  for _, o in ipairs(OFFSETS) do
    it("misses when the segment ends on an edge or vertex, hits one ulp past (offset " .. o .. ")",
        function()
      local l = moved(L, o)
      assert.are.equal(false, checkBoth(l, o + 60, o + 60, o + 60, o + 20))
      -- in at y = 20: t = 40 / (40 + the ulp below o + 20)
      expectHit(40 / ((o + 60) - nextDown(o + 20)), { PY }, checkBoth(l, o + 60, o + 60, o + 60,
        nextDown(o + 20)))
      assert.are.equal(false, checkBoth(l, o + 60, o + 60, o + 20, o + 20))   -- the reflex vertex
      checkBoth(l, o + 60, o + 60, nextDown(o + 20), nextDown(o + 20))
      assert.are.equal(false, checkBoth(l, o + 120, o + 60, o + 20, o + 60))  -- across the notch
      checkBoth(l, o + 120, o + 60, nextDown(o + 20), o + 60)
      -- ending on the comb's tooth tops, from outside: a miss; a point on the boundary: a miss
      assert.are.equal(false, checkBoth(moved(COMB, o), o + 25, o + 60, o + 25, o + 40))
      assert.are.equal(false, checkBoth(l, o + 20, o + 20, o + 20, o + 20))
      assert.are.same({ 0, 0, 0 }, { checkBoth(l, o + 10, o + 10, o + 10, o + 10) })
    end)
  end
end)

describe("rays on one ring, hard cases: along rows of a tile map's outline", function()
  for _, o in ipairs(OFFSETS) do
    it("enters staircases and combs along rows and columns through many vertices (offset " .. o .. ")",
        function()
      local stairs, comb = moved(STAIRS, o), moved(COMB, o)
      -- y = 10 from the right: past (20, 10), along (20, 10) -> (10, 10), in at (10, 10),
      -- t = (35 - 10) / 40; from the left in at x = 0, t = 5 / 40
      expectHit(25 / 40, { PY, PX }, checkBoth(stairs, o + 35, o + 10, o - 5, o + 10))
      expectHit(5 / 40, { NX }, checkBoth(stairs, o - 5, o + 10, o + 35, o + 10))
      -- the comb along y = 10 (the gaps' ends, four vertices on it): from x = 60 in at x = 50,
      -- t = 10 / 70; from (35, 10) on the gap's end, along it to (30, 10), then inside: t = 5 / 45
      expectHit(10 / 70, { PX }, checkBoth(comb, o + 60, o + 10, o - 10, o + 10))
      expectHit(5 / 45, { PY, PX }, checkBoth(comb, o + 35, o + 10, o - 10, o + 10))
      -- along the tooth tops y = 40: boundary and gaps only; up the tooth side x = 20 from y = 50:
      -- along (20, 40) -> (20, 10), in at (20, 10), t = 40 / 60
      assert.are.equal(false, checkBoth(comb, o - 10, o + 40, o + 60, o + 40))
      expectHit(40 / 60, { PY, NX }, checkBoth(comb, o + 20, o + 50, o + 20, o - 10))
      -- every grid line both ways, on it and one ulp either side
      for _, ring in ipairs({ stairs, comb }) do
        for k = -1, 5 do
          local at = o + 10 * k
          for _, c in ipairs({ at, nextUp(at), nextDown(at) }) do
            checkBoth(ring, o - 10, c, o + 60, c)
            checkBoth(ring, o + 60, c, o - 10, c)
            checkBoth(ring, c, o - 10, c, o + 60)
            checkBoth(ring, c, o + 60, c, o - 10)
          end
        end
      end
    end)

    it("agrees with the oracle on random tile outlines along grid lines (offset " .. o .. ")", function()
      local rng = prng.new(3104)
      local done = 0
      while done < 12 do
        local loops = tiles.loops(tiles.random(rng, 6, 6, 0.65), 10, o, o)
        if #loops == 1 then
          done = done + 1
          for _ = 1, 8 do
            local line, from, to = o + 5 * rng:int(-1, 13), o + 5 * rng:int(-2, 14), o + 5 * rng:int(-2, 14)
            if rng:float() < 0.5 then checkBoth(loops[1], from, line, to, line) else
              checkBoth(loops[1], line, from, line, to) end
          end
        end
      end
    end)
  end
end)

describe("rays on one ring, hard cases: repeated vertices and zero-length edges", function()
  -- Every vertex given twice, or one given three times: the same region as without.
  local function doubled(points)
    local out = {}
    for i = 1, #points, 2 do
      for _ = 1, 2 do out[#out + 1], out[#out + 2] = points[i], points[i + 1] end
    end
    return out
  end
  for _, o in ipairs(OFFSETS) do
    it("answers as without the repeats (offset " .. o .. ")", function()
      local l = moved(L, o)
      local tripled = moved({ 0, 0, 100, 0, 100, 20, 20, 20, 20, 20, 20, 20, 20, 100, 0, 100 }, o)
      for _, ring in ipairs({ doubled(l), tripled }) do   -- the L's hand-computed cases again
        expectHit(0.25, { NX }, checkBoth(ring, o - 20, o + 50, o + 60, o + 50))
        expectHit(0.5, { PY, PX }, checkBoth(ring, o + 30, o + 30, o + 10, o + 10))
        expectHit(0.7, { PY, PX }, checkBoth(ring, o + 90, o + 20, o - 10, o + 20))
        assert.are.equal(false, checkBoth(ring, o + 90, o + 20, o + 30, o + 20))
        assert.are.same({ 0, 0, 0 }, { checkBoth(ring, o + 10, o + 10, o + 50, o + 50) })
      end
      for _, ring in ipairs({ doubled(l), tripled, doubled(moved(COMB, o)), doubled(moved(STAIRS, o)) }) do
        for i = 1, #ring, 2 do   -- from each vertex to the far corners
          checkBoth(ring, ring[i], ring[i + 1], o - 7, o - 3)
          checkBoth(ring, ring[i], ring[i + 1], o + 107, o + 103)
        end
      end
    end)
  end
end)

describe("rays on one ring, hard cases: zero area", function()
  for _, o in ipairs(OFFSETS) do
    it("never hits a ring whose points lie on one line (offset " .. o .. ")", function()
      local flats = { { 0, 0, 10, 0, 20, 0 }, { 0, 0, 10, 10, 5, 5, 20, 20 }, { 3, 3, 3, 3, 3, 3 },
        { 0, 0, 0, 10, 0, 10, 0, 5 } }
      for _, flat in ipairs(flats) do
        local ring = moved(flat, o)
        for _, seg in ipairs({ { -5, 5, 25, 5 }, { 5, -5, 5, 25 }, { -5, -5, 25, 25 }, { 0, 0, 20, 0 },
            { -5, 0, 25, 0 }, { 3, 3, 3, 3 }, { 5, 5, 5, 5 }, { 0, 5, 10, 5 } }) do
          assert.are.equal(false, checkBoth(ring, o + seg[1], o + seg[2], o + seg[3], o + seg[4]))
        end
      end
    end)
  end
end)

describe("rays on one ring, hard cases: self-crossing rings along edges and through crossings", function()
  -- A pentagram: the pentagon (0,-10) (10,-3) (6,8) (-6,8) (-10,-3) taken every second vertex;
  -- by the crossing rule its five spikes are inside, its middle pentagon (crossed twice) is not.
  local PENTAGRAM = { 0, -10, 6, 8, -10, -3, 10, -3, -6, 8 }
  for _, o in ipairs(OFFSETS) do
    it("misses along edges through crossing points, agrees one ulp aside (offset " .. o .. ")", function()
      local function both(ring, ax, ay, bx, by)
        check(shapes.reverse(ring), ax, ay, bx, by, true)
        return check(ring, ax, ay, bx, by, true)
      end
      local star, bowtie = moved(PENTAGRAM, o), moved(shapes.scale(BOWTIE, 2), o)
      -- up from the middle (0, 0): out of the pentagon into the top spike across y = -3 at
      -- t = 3 / 20, the spike's outward normal +y; from the middle sideways: out at a spike's tip
      expectHit(0.15, { PY }, both(star, o, o, o, o - 20))
      assert.are.same({ false }, { both(star, o, o, o + 1, o) })
      -- the bow-tie's diagonal y = x through its crossing (10, 10): boundary all along
      assert.are.equal(false, both(bowtie, o - 5, o - 5, o + 25, o + 25))
      assert.are.equal(false, both(bowtie, o + 10, o + 10, o + 25, o + 25))
      for _, ring in ipairs({ star, bowtie }) do
        local n = #ring
        for i = 1, n, 2 do
          local j = (i + 1) % n + 1
          local px, py, qx, qy = ring[i], ring[i + 1], ring[j], ring[j + 1]
          local ax, ay, bx, by = 2 * px - qx, 2 * py - qy, 2 * qx - px, 2 * qy - py
          for _, seg in ipairs({ { ax, ay, bx, by }, { bx, by, ax, ay }, { px, py, qx, qy } }) do
            assert.are.equal(false, both(ring, seg[1], seg[2], seg[3], seg[4]))
            both(ring, seg[1], nextUp(seg[2]), seg[3], nextUp(seg[4]))
            both(ring, seg[1], nextDown(seg[2]), seg[3], nextDown(seg[4]))
            both(ring, nextUp(seg[1]), seg[2], nextUp(seg[3]), seg[4])
            both(ring, nextDown(seg[1]), seg[2], nextDown(seg[3]), seg[4])
          end
          for k = 1, n, 2 do   -- from this vertex through every other one, and on past it
            both(ring, px, py, ring[k], ring[k + 1])
            both(ring, px, py, 2 * ring[k] - px, 2 * ring[k + 1] - py)
          end
        end
      end
    end)
  end
end)

-- A segment crossing a long edge at a shallow angle: a float fraction's error grows as 1 / sin
-- of the angle, so the fraction must come from a precise path.
describe("rays on one ring, hard cases: shallow crossings", function()
  it("gives the fraction within 8 eps M at angles down to 1e-12, concave rings turned", function()
    local rng = prng.new(3105)
    local hits = 0
    for round = 1, 160 do
      local o = OFFSETS[round % #OFFSETS + 1]
      local size = rng:pick({ 1, 100, 1e4 })
      local ring = shapes.scale(rng:float() < 0.5 and L or U, size / 100)
      -- across the long top edge y = 0 near its middle, from above (y < 0) down into the ring
      local angle = 10 ^ rng:range(-12, -1)
      local cx, len = size * rng:range(0.02, 0.28), size * rng:range(0.5, 2)
      local ax, ay = cx - len * math.cos(angle), -len * math.sin(angle)
      local bx, by = cx + len * math.cos(angle) * 0.5, len * math.sin(angle) * 0.5
      local turn = rng:float() < 0.25 and 0 or rng:range(0, 2 * math.pi)
      local c, sn = math.cos(turn), math.sin(turn)
      local function turned(x, y) return o + c * x - sn * y, o + sn * x + c * y end
      for i = 1, #ring, 2 do ring[i], ring[i + 1] = turned(ring[i], ring[i + 1]) end
      ax, ay = turned(ax, ay)
      bx, by = turned(bx, by)
      if round % 2 == 0 then ring = shapes.reverse(ring) end
      local f = check(ring, ax, ay, bx, by)
      hits = hits + ((f and f > 0) and 1 or 0)
    end
    assert.is_true(hits > 110, hits .. " hits")
  end)
end)

-- The entry at the tip of a slit or spike lying along the segment's line: every edge at the
-- entry point runs along the line, and the normal is theirs (a reviewer found NaN there).
describe("rays on one ring, hard cases: entering at the tip of a slit along the ray", function()
  -- a 4 by 4 square with a slit down from its top edge at x = 2 to (2, 2)
  local SLIT = { 0, 0, 4, 0, 4, 4, 2, 4, 2, 2, 2, 4, 0, 4 }
  -- a triangle with a spike up from its apex (2, 2) to (2, 8) and back
  local SPIKE = { 2, 4, 2, 2, 2, 8, 0, 2, 4, 0 }
  for _, o in ipairs(OFFSETS) do
    it("gives the slit's or spike's normal, a unit vector (offset " .. o .. ")", function()
      -- down x = 2 from y = 6: along the slit from y = 4, inside past its tip (2, 2):
      -- t = (6 - 2) / 6 = 2/3; the slit's edges' normals are (1, 0) and (-1, 0)
      expectHit(2 / 3, { PX, NX }, checkBoth(moved(SLIT, o), o + 2, o + 6, o + 2, o))
      -- from the tip itself: in at 0
      expectHit(0, { PX, NX }, checkBoth(moved(SLIT, o), o + 2, o + 2, o + 2, o))
      -- down x = 2 from y = 10 along the spike (8 to 2), inside past (2, 2): t = 8 / 10
      expectHit(0.8, { PX, NX }, checkBoth(moved(SPIKE, o), o + 2, o + 10, o + 2, o))
    end)
  end
end)
