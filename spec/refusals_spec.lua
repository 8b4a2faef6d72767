-- Issue 29, "no silent wrong answers": what the collision functions refuse, with every message,
-- each raised at the caller's line; the Polygon object taken for its points; false alone for no
-- collision; and the convexity check against the oracle on generated shapes.
local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local shapes = require "shapes"
local parts = require "parts"
local callsite = require "callsite"
local convex = require "polygon.convex"
local unpack = rawget(table, "unpack") or rawget(_G, "unpack")

local L = { 0, 0, 100, 0, 100, 20, 20, 20, 20, 100, 0, 100 }   -- the issue's L: reflex at vertex 4
local BOX = { 50, 10, 70, 10, 70, 30, 50, 30 }                   -- across the L's arm
local NEAR = { 60, 20, 80, 20, 80, 40, 60, 40 }                  -- overlaps BOX

-- The five collision functions, each called with a bad shape as its first or second shape.
local PAIR_FUNCTIONS = { "polygonCollidesWith", "polygonsCollide", "polygonCollidesWithV",
  "polygonsCollideV" }

-- Asserts that each function, given `bad` in each place, raises "<fname>: <argname> <what>" at
-- the caller's line.
local function refusedEverywhere(bad, what, functions)
  for _, fname in ipairs(functions or PAIR_FUNCTIONS) do
    local fn = polygon[fname]
    local gap = what:sub(1, 1) == "[" and "" or " "
    assert.has_error(function() fn(bad, BOX) end, ("%s: points1%s%s"):format(fname, gap, what))
    assert.has_error(function() fn(BOX, bad) end, ("%s: points2%s%s"):format(fname, gap, what))
    local ok, err = callsite.raisesAtCaller(fn, { bad, BOX })
    assert.is_true(ok, err)
    ok, err = callsite.raisesAtCaller(fn, { BOX, bad })
    assert.is_true(ok, err)
  end
  if not functions then
    assert.has_error(function() polygon.polygonCircleCollideV(bad, 60, 20, 5) end,
      ("polygonCircleCollideV: points%s%s"):format(what:sub(1, 1) == "[" and "" or " ", what))
    local ok, err = callsite.raisesAtCaller(polygon.polygonCircleCollideV, { bad, 60, 20, 5 })
    assert.is_true(ok, err)
  end
end

describe("the collision functions", function()
  describe("when a flat polygon is not convex", function()
    it("refuse the issue's L, naming the reflex vertex and the fix", function()
      -- the turn at vertex 4, (20, 20), from (100, 20) -> (20, 20) to (20, 20) -> (20, 100):
      -- (-80, 0) x (0, 80) = -6400, against the clockwise (positive) area: reflex
      refusedEverywhere(L, "is not convex (a reflex turn at vertex 4); split it once with "
        .. "polygonConvexParts and pass the parts")
    end)

    it("refuse a pentagram, whose turns all agree, as crossing itself", function()
      refusedEverywhere({ 10, 0, 16, 20, 0, 7, 20, 7, 4, 20 }, "is not convex (its turns all "
        .. "agree but it winds around more than once: it crosses itself); split it once with "
        .. "polygonConvexParts and pass the parts")
    end)

    it("refuse a spike (a zero turn that folds back), horizontal or vertical", function()
      -- vertex 3 is (10, 5) then (10, -5): the edges (0, 5) and (0, -10) fold back on x = 10
      refusedEverywhere({ 0, 0, 10, 0, 10, 5, 10, -5, 10, 10, 0, 10 }, "is not convex (a spike "
        .. "at vertex 3: its edges fold back on one line); split it once with polygonConvexParts "
        .. "and pass the parts")
      -- the same mirrored on y = x: vertex 3 is (5, 10) then (-5, 10): (5, 0) then (-10, 0)
      refusedEverywhere({ 0, 0, 0, 10, 5, 10, -5, 10, 10, 10, 10, 0 }, "is not convex (a "
        .. "spike at vertex 3: its edges fold back on one line); split it once with "
        .. "polygonConvexParts and pass the parts")
    end)

    it("refuse a bow tie (zero signed area, but it covers two triangles)", function()
      -- (0,0), (10,0), (0,10), (10,10). The reference is the turn at the lowest vertex, (0, 0):
      -- (v1 - v4) x (v2 - v1) = (-10, -10) x (10, 0) = 0 - (-10)(10) = 100; the walk starts at
      -- vertex 4: (v4 - v3) x (v1 - v4) = (10, 0) x (-10, -10) = -100, against it
      refusedEverywhere({ 0, 0, 10, 0, 0, 10, 10, 10 }, "is not convex (a reflex turn at vertex "
        .. "4); split it once with polygonConvexParts and pass the parts")
    end)
  end)

  describe("when the coordinates are tiny or huge (turns that underflow or overflow)", function()
    it("refuse a concave quadrilateral and take a convex one at 1e-200 and at 1e300", function()
      for _, k in ipairs({ 1e-200, 1e300 }) do
        -- a dart: (0,0), (10,0), (3,3), (0,10); the turn at vertex 3 is reflex:
        -- (3 - 10, 3 - 0) x (0 - 3, 10 - 3) = (-7)(7) - (3)(-3) = -40 against the others' +
        local dart = { 0, 0, 10 * k, 0, 3 * k, 3 * k, 0, 10 * k }
        local square = { 0, 0, 10 * k, 0, 10 * k, 10 * k, 0, 10 * k }
        local near = { 5 * k, 5 * k, 20 * k, 5 * k, 20 * k, 20 * k }
        assert.has_error(function() polygon.polygonsCollide(dart, near) end,
          "polygonsCollide: points1 is not convex (a reflex turn at vertex 3); split it once with "
          .. "polygonConvexParts and pass the parts")
        -- taken (the answer itself at 1e-200 is outside the exact range, docs/accuracy.md)
        assert.is_true(pcall(polygon.polygonsCollide, square, near))
        assert.is_nil(convex.vouchJit(dart, 8) or convex.vouchPuc(dart, 8))
      end
    end)
  end)

  describe("when a part of a list is not convex", function()
    it("refuse it by its index, in either place", function()
      local list = { parts.box(200, 200, 10, 10), L }
      for _, fname in ipairs({ "polygonsCollide", "polygonsCollideV" }) do
        local fn = polygon[fname]
        assert.has_error(function() fn(list, BOX) end, fname .. ": points1[2] is not convex (a "
          .. "reflex turn at vertex 4); split it once with polygonConvexParts and pass the parts")
        assert.has_error(function() fn(BOX, { L }) end, fname .. ": points2[1] is not convex (a "
          .. "reflex turn at vertex 4); split it once with polygonConvexParts and pass the parts")
        local ok, err = callsite.raisesAtCaller(fn, { { L }, BOX })
        assert.is_true(ok, err)
      end
      assert.has_error(function() polygon.polygonCircleCollideV({ L }, 50, 15, 8) end,
        "polygonCircleCollideV: points[1] is not convex (a reflex turn at vertex 4); split it once "
        .. "with polygonConvexParts and pass the parts")
    end)

    it("refuse a part made concave in place after the list was prepared", function()
      local part = { 0, 0, 100, 0, 100, 100, 0, 100 }
      local list = { part }
      assert.is_true(polygon.polygonsCollide(list, BOX))
      part[5], part[6] = 20, 20   -- vertex 3 pulled inside: a reflex turn there
      assert.has_error(function() polygon.polygonsCollide(list, BOX) end,
        "polygonsCollide: points1[1] is not convex (a reflex turn at vertex 3); split it once "
        .. "with polygonConvexParts and pass the parts")
    end)

    it("take the parts polygonConvexParts makes of the same L", function()
      local split = assert(polygon.polygonConvexParts(L))
      assert.is_true(polygon.polygonsCollide(split, BOX))
      assert.is_truthy(polygon.polygonsCollideV(BOX, split))
      assert.is_truthy(polygon.polygonCircleCollideV(split, 50, 15, 8))
    end)
  end)

  describe("when a shape has fewer than 3 points", function()
    it("refuse a segment, saying it is one", function()
      refusedEverywhere({ 0, 0, 100, 100 },
        "has 2 points: a segment; a polygon needs at least 3; "
        .. "for line of sight use polygonRayCast")
    end)

    it("refuse one point and an empty table", function()
      refusedEverywhere({ 5, 5 }, "has 1 point; a polygon needs at least 3")
      refusedEverywhere({}, "is empty; a polygon needs at least 3 points")
    end)

    it("refuse a part of a list with fewer than 3 points", function()
      assert.has_error(function() polygon.polygonsCollideV({ BOX, { 0, 0, 100, 100 } }, NEAR) end,
        "polygonsCollideV: points1[2] has 2 points: a segment; a polygon needs at least 3; "
        .. "for line of sight use polygonRayCast")
    end)
  end)

  describe("when entries are not numbers", function()
    it("refuse point tables, {x =, y =} or {x, y}", function()
      local what = "holds point tables; pass a flat array {x1, y1, x2, y2, ...}"
      refusedEverywhere({ { x = 50, y = 10 }, { x = 70, y = 10 }, { x = 70, y = 30 } }, what)
      refusedEverywhere({ { 50, 10 }, { 70, 10 }, { 70, 30 } }, what)
    end)

    it("refuse strings", function()
      refusedEverywhere({ "50", "10", "70", "10", "70", "30" }, "[1] must be a number, got string")
    end)

    -- Past the first entry the engines read each coordinate by arithmetic, before any check: a
    -- type test per entry would cost the PUC interpreters a call each, and catching the error a
    -- pcall on every call. So such an entry raises Lua's own error there (README: "an entry that
    -- is not a number (past the first: Lua's own error)"), never an answer.
    it("raise Lua's own error for an entry past the first that is not a number", function()
      for _, bad in ipairs({ { 50, 10, 70, "ten", 70, 30 }, { 50, 10, 70, 10, {}, 30 },
          { 50, 10, 70, 10, 70, true } }) do
        for _, fname in ipairs(PAIR_FUNCTIONS) do
          local ok, err = pcall(polygon[fname], BOX, bad)
          assert.is_false(ok)
          assert.truthy(tostring(err):find("attempt to ", 1, true), fname)
        end
        local ok, err = pcall(polygon.polygonCircleCollideV, bad, 60, 20, 5)
        assert.is_false(ok)
        assert.truthy(tostring(err):find("attempt to ", 1, true))
      end
    end)

    it("refuse a string in a part of a list", function()
      assert.has_error(function() polygon.polygonsCollide({ { "0", 0, 1, 0, 1, 1 } }, BOX) end,
        "polygonsCollide: points1[1][1] must be a number, got string; a list of parts holds flat arrays")
    end)

    it("refuse a list of parts in the one-sided functions", function()
      for _, fname in ipairs({ "polygonCollidesWith", "polygonCollidesWithV" }) do
        assert.has_error(function() polygon[fname]({ BOX }, NEAR) end, fname .. ": points1 is a "
          .. "list of parts; it takes convex polygons only (polygonsCollide takes lists)")
      end
    end)
  end)

  describe("when a zero-area polygon is given", function()
    it("never collide (no refusal): every point on one line", function()
      local line = { 40, 20, 60, 20, 80, 20 }   -- across BOX
      assert.is_false(polygon.polygonsCollide(line, BOX))
      assert.are.equal(false, polygon.polygonsCollideV(BOX, line))
      assert.are.equal(false, polygon.polygonCircleCollideV(line, 60, 20, 5))
    end)
  end)
end)

describe("the Polygon object", function()
  it("is taken wherever a collision function takes a polygon, its points used", function()
    local obj, near = polygon.Polygon.new(BOX), polygon.Polygon(NEAR)
    for _, fname in ipairs(PAIR_FUNCTIONS) do
      local fn = polygon[fname]
      local a, b, c = fn(BOX, NEAR)
      assert.is_truthy(a)
      local x, y, z = fn(obj, NEAR)
      assert.are.same({ a, b, c }, { x, y, z })
      x, y, z = fn(BOX, near)
      assert.are.same({ a, b, c }, { x, y, z })
    end
    assert.are.same({ polygon.polygonCircleCollideV(BOX, 60, 20, 5) },
      { polygon.polygonCircleCollideV(obj, 60, 20, 5) })
    assert.are.same({ polygon.polygonsCollideV({ BOX }, NEAR) }, { polygon.polygonsCollideV(obj, { NEAR }) })
  end)

  it("is taken by the measures, polygonContains and polygonBounds, its points used", function()
    local obj = polygon.Polygon.new(L)
    for _, fname in ipairs({ "polygonWindingOrder", "polygonArea", "polygonAreaAccurate", "polygonType",
                             "polygonCenter", "polygonCentroid", "polygonBounds" }) do
      assert.are.same({ polygon[fname](L) }, { polygon[fname](obj) }, fname)
    end
    -- (30, 30) lies in the L's notch, (10, 50) in its arm
    assert.is_false(polygon.polygonContains(obj, 30, 30))
    assert.is_true(polygon.polygonContains(obj, 10, 50))
    assert.are.equal(3600, polygon.polygonArea(obj))   -- 100 * 20 + 20 * 80
  end)

  it("is taken by projectPolygon, the transforms, the splits and validate, its points used", function()
    local obj = polygon.Polygon.new(L)
    assert.are.same({ polygon.projectPolygon(L, 1, 2, 0.6, 0.8) },
      { polygon.projectPolygon(obj, 1, 2, 0.6, 0.8) })
    assert.are.same(polygon.polygonTranslate(L, 3, 4), polygon.polygonTranslate(obj, 3, 4))
    assert.are.same(polygon.polygonRotate(L, 0.5), polygon.polygonRotate(obj, 0.5))
    assert.are.same(polygon.polygonTriangulate(L), polygon.polygonTriangulate(obj))
    assert.are.same(polygon.polygonConvexParts(L), polygon.polygonConvexParts(obj))
    assert.is_true(polygon.validate(obj))
    assert.are.equal(L, polygon.Polygon.new(obj).points)   -- an object of an object: its points
  end)

  it("is refused as a concave polygon when its points are", function()
    assert.has_error(function() polygon.polygonsCollide(polygon.Polygon.new(L), BOX) end,
      "polygonsCollide: points1 is not convex (a reflex turn at vertex 4); split it once with "
      .. "polygonConvexParts and pass the parts")
  end)
end)

describe("the functions of one shape", function()
  it("refuse point tables where they answered nil, false or empty tables", function()
    local two = { { x = 0, y = 0 }, { x = 10, y = 0 } }
    local three = { { 0, 0 }, { 10, 0 }, { 0, 10 } }
    for _, fname in ipairs({ "polygonWindingOrder", "polygonArea", "polygonAreaAccurate", "polygonType",
                             "polygonCenter", "polygonCentroid", "polygonBounds" }) do
      -- polygonBounds reads {x, y} pairs right, as parts of one point: only {x =, y =} refused
      for _, bad in ipairs(fname == "polygonBounds" and { two } or { two, three }) do
        assert.has_error(function() polygon[fname](bad) end,
          fname .. ": points holds point tables; pass a flat array {x1, y1, x2, y2, ...}")
        local ok, err = callsite.raisesAtCaller(polygon[fname], { bad })
        assert.is_true(ok, err)
      end
    end
    assert.has_error(function() polygon.polygonContains(two, 5, 0) end,
      "polygonContains: points holds point tables; pass a flat array {x1, y1, x2, y2, ...}")
    assert.are.same({ 0, 0, 10, 10 }, { polygon.polygonBounds(three) })
    for _, fname in ipairs({ "polygonTranslate", "polygonRotate", "polygonTriangulate",
                             "polygonConvexParts" }) do
      local fn = polygon[fname]
      local args = fname == "polygonTranslate" and { two, 1, 1 }
        or fname == "polygonRotate" and { two, 1 } or { two }
      assert.has_error(function() fn(unpack(args)) end,
        fname .. ": points holds point tables; pass a flat array {x1, y1, x2, y2, ...}")
      local ok, err = callsite.raisesAtCaller(fn, args)
      assert.is_true(ok, err)
    end
    assert.are.same({ nil, "points holds point tables; pass a flat array {x1, y1, x2, y2, ...}" },
      { polygon.validate(three) })
    local obj = setmetatable({ points = two }, polygon.Polygon)   -- past Polygon.new's check
    assert.has_error(function() obj:contains(5, 0) end,
      "Polygon:contains: points holds point tables; pass a flat array {x1, y1, x2, y2, ...}")
  end)
end)

describe("polygonRotate about its centroid", function()
  it("names itself for a non-finite coordinate (the centroid's error named polygonCentroid)", function()
    assert.has_error(function() polygon.polygonRotate({ 0, 0, 10, 0, 0 / 0, 10 }, 1) end)
    local ok, err = callsite.raisesAtCaller(polygon.polygonRotate, { { 0, 0, 10, 0, 1 / 0, 10 }, 1 })
    assert.is_true(ok, err)
    local want = "polygonRotate: points holds a non-finite coordinate, got inf at [5]"
    assert.is_truthy(err:find(want, 1, true), err)
    ok, err = callsite.raisesAtCaller(polygon.polygonRotate, { { { 0, 0, 10, 0, 1 / 0, 10 } }, 1 })
    assert.is_true(ok, err)
    assert.is_truthy(err:find("polygonRotate: points holds a non-finite coordinate", 1, true), err)
  end)
end)

describe("no collision", function()
  it("is false alone from every collision function, flat or parts", function()
    local apart = { 500, 500, 510, 500, 510, 510 }
    local function count(...) return select("#", ...), (...) end
    for _, fname in ipairs(PAIR_FUNCTIONS) do
      assert.are.same({ 1, false }, { count(polygon[fname](BOX, apart)) })
    end
    assert.are.same({ 1, false }, { count(polygon.polygonsCollideV({ BOX }, apart)) })
    assert.are.same({ 1, false }, { count(polygon.polygonsCollide(BOX, { apart })) })
    assert.are.same({ 1, false }, { count(polygon.polygonCircleCollideV(BOX, 500, 500, 1)) })
    assert.are.same({ 1, false }, { count(polygon.polygonCircleCollideV({ BOX }, 500, 500, 1)) })
    assert.are.same({ 1, false }, { count(polygon.polygonCircleCollideV(BOX, 60, 20, 0)) })
  end)
end)

describe("the convexity check on generated shapes", function()
  -- random convex polygons (rounded and not) and random stars (mostly concave), either winding
  local function generated(count, seed)
    local rng = prng.new(seed)
    local list = {}
    for k = 1, count do
      local m, size = rng:int(3, 12), rng:pick({ 1, 10, 100, 1e-3 })
      local ox, oy = rng:pick({ 0, 0, 1e6, -1e9 }), rng:pick({ 0, 0, 0.5, 1e6 })
      local p
      if k % 3 == 0 then
        p = shapes.star(rng, m, ox, oy, size)
      else
        p = shapes.convex(rng, m, ox, oy, size, 0.3)
        if k % 3 == 1 then for i = 1, #p do p[i] = math.floor(p[i] * 4 + 0.5) / 4 end end
      end
      if rng:int(0, 1) == 1 then p = shapes.reverse(p) end
      list[k] = p
    end
    return list
  end

  it("refuses exactly the polygons the oracle finds concave, naming a real reflex vertex", function()
    local refused, taken = 0, 0
    for _, p in ipairs(generated(600, 2911)) do
      local ok, err = pcall(polygon.polygonsCollide, p, BOX)
      local kind = oracle.polygonType(p)
      if kind == "concave" then
        assert.is_false(ok, "a concave polygon was taken")
        assert.is_truthy(tostring(err):find("is not convex", 1, true), tostring(err))
        local k = tonumber(tostring(err):match("reflex turn at vertex (%d+)"))
        if k then   -- the named vertex turns against the exact area's sign
          local m = #p / 2
          local function distinct(from, step)   -- the nearest vertex at another point
            local v = from
            repeat v = (v - 1 + step) % m + 1
            until p[2 * v - 1] ~= p[2 * k - 1] or p[2 * v] ~= p[2 * k]
            return v
          end
          local a, b, c = distinct(k, -1), k, distinct(k, 1)
          local turn = oracle.orient(p[2 * a - 1], p[2 * a], p[2 * b - 1], p[2 * b], p[2 * c - 1], p[2 * c])
          local area = oracle.winding(p)
          assert.is_true(turn ~= 0 and (area == nil or (turn > 0) ~= (area == "cw")),
            ("vertex %d of %s"):format(k, table.concat(p, ", ")))
        end
        refused = refused + 1
      else
        assert.is_true(ok, tostring(err))
        taken = taken + 1
      end
    end
    assert.is_true(refused > 100 and taken > 300, ("refused %d, taken %d"):format(refused, taken))
  end)

  it("has two vouching passes that agree, and neither vouches for a concave polygon", function()
    local sure = 0
    for _, p in ipairs(generated(900, 77)) do
      local j = { convex.vouchJit(p, #p) }
      local q = { convex.vouchPuc(p, #p) }
      local label = table.concat(p, ", ")
      for k = 1, 5 do assert.are.equal(j[k], q[k], label) end
      if j[1] then
        assert.are.equal("convex", oracle.polygonType(p), label)
        assert.are.equal(oracle.winding(p) == "cw" and 1 or -1, j[1], label)
        sure = sure + 1
      end
    end
    assert.is_true(sure > 300, ("the pass vouched for %d"):format(sure))
  end)
end)

-- polygonRayCast takes a flat polygon of any shape (issue 30: a concave level outline needs no
-- split): the shapes the collision functions refuse above are answered, their inside by the
-- crossing rule, even-odd, as polygonContains (without the boundary); a list of parts still
-- holds convex parts only, and fewer than 3 points is still a refusal.
describe("polygonRayCast", function()
  local EPS = 2 ^ -53

  -- Asserts a hit at the exact fraction t (within the contract's 8 eps M along the segment, M
  -- over its ends) through an edge of unit outward normal (mx, my) (within 16 eps a component).
  local function hits(t, mx, my, points, ax, ay, bx, by)
    local f, nx, ny = polygon.polygonRayCast(points, ax, ay, bx, by)
    assert.is_number(f)
    local M = math.max(math.abs(ax), math.abs(ay), math.abs(bx), math.abs(by))
    local length = math.sqrt((bx - ax) ^ 2 + (by - ay) ^ 2)
    assert.near(t, f, 8 * EPS * M / length)
    assert.near(mx, nx, 16 * EPS)
    assert.near(my, ny, 16 * EPS)
  end

  describe("when a flat polygon is not convex", function()
    it("takes the issue's L: a ray across the notch enters the far arm", function()
      -- leftward along y = 50 from x = 110: the notch (x > 20, y > 20) is outside, the left arm
      -- is entered at its edge (20, 20) -> (20, 100), outward +x: t = (110 - 20) / 120 = 0.75
      -- (a convex test would stop at the hull's edge x + y = 120, x = 70, t = 1/3)
      hits(0.75, 1, 0, L, 110, 50, -10, 50)
      -- along x + y = 120 from (30, 90) to (90, 30): x > 20 and y > 20 all the way: a miss
      assert.are.equal(false, polygon.polygonRayCast(L, 30, 90, 90, 30))
      -- from (10, 50), strictly inside the left arm
      assert.are.same({ 0, 0, 0 }, { polygon.polygonRayCast(L, 10, 50, 200, 50) })
      -- the Polygon object of the L, for its points
      hits(0.75, 1, 0, polygon.Polygon.new(L), 110, 50, -10, 50)
    end)

    it("takes a pentagram, whose middle (wound round twice) is outside by even-odd", function()
      -- (10,0), (16,20), (0,7), (20,7), (4,20). Along y = 10 the edges cross at
      -- (4,20)->(10,0): x = 10 - 6 (10 / 20) = 7; (10,0)->(16,20): x = 10 + 6 (10 / 20) = 13;
      -- (16,20)->(0,7): x = 16 - 16 (10 / 13) = 48 / 13; (20,7)->(4,20): x = 20 - 16 (3 / 13) =
      -- 212 / 13: inside on (48/13, 7) and (13, 212/13), the middle (7, 13) outside. From
      -- (10, 10) rightward to (30, 10): in at x = 13, t = 3 / 20, through (10,0)->(16,20),
      -- direction (6, 20), the arm to its right (+x): outward (-20, 6) / sqrt(436)
      local star = { 10, 0, 16, 20, 0, 7, 20, 7, 4, 20 }
      local s = math.sqrt(436)
      hits(0.15, -20 / s, 6 / s, star, 10, 10, 30, 10)
      hits(0.15, -20 / s, 6 / s, shapes.reverse(star), 10, 10, 30, 10)   -- either winding
    end)

    it("takes a bow tie (zero signed area, but it covers two triangles)", function()
      -- (0,0), (10,0), (0,10), (10,10) cross at (5, 5); the lower triangle lies between
      -- x = 10 - y and x = y: along y = 8, x from 2 to 8. From (-5, 8) to (15, 8): in at x = 2,
      -- t = 7 / 20, through (10,0)->(0,10), outward away from the triangle: -(1, 1) / sqrt(2)
      local r = math.sqrt(0.5)
      hits(0.35, -r, -r, { 0, 0, 10, 0, 0, 10, 10, 10 }, -5, 8, 15, 8)
      -- between the triangles, along y = 5 from (-5, 5) to (15, 5): only the crossing point
      -- (5, 5) is touched (the triangles' apexes): a miss
      assert.are.equal(false, polygon.polygonRayCast({ 0, 0, 10, 0, 0, 10, 10, 10 }, -5, 5, 15, 5))
    end)

    it("takes a spike and repeated vertices", function()
      -- the square (0,0)-(10,10) with a spike at vertex 3 folding back along x = 10: from
      -- (20, 3) leftward to (-5, 3), in at x = 10, t = 10 / 25; three edges run through (10, 3)
      -- both ways, and the boundary there is the square's side, outward +x
      hits(0.4, 1, 0, { 0, 0, 10, 0, 10, 5, 10, -5, 10, 10, 0, 10 }, 20, 3, -5, 3)
      -- the L with its first and fourth vertices repeated: the same answer as the L
      hits(0.75, 1, 0, { 0, 0, 0, 0, 100, 0, 100, 20, 20, 20, 20, 20, 20, 100, 0, 100 }, 110, 50, -10, 50)
    end)

    it("takes every generated polygon, concave ones too, without an error", function()
      local rng = prng.new(3030)
      local concave = 0
      for k = 1, 300 do
        local m, size = rng:int(3, 16), rng:pick({ 1, 10, 100 })
        local ox, oy = rng:pick({ 0, 1e6 }), rng:pick({ 0, 0.5 })
        local p = k % 2 == 0 and shapes.star(rng, m, ox, oy, size) or shapes.convex(rng, m, ox, oy, size, 0.3)
        if oracle.polygonType(p) == "concave" then concave = concave + 1 end
        local ok, err = pcall(polygon.polygonRayCast, p, ox - 2 * size, oy, ox + 2 * size, oy + size)
        assert.is_true(ok, tostring(err))
      end
      assert.is_true(concave > 100, ("%d concave"):format(concave))
    end)
  end)

  describe("when a part of a list is not convex", function()
    it("refuses it by its index, naming the reflex vertex and the fix", function()
      local list = { parts.box(200, 200, 10, 10), L }
      assert.has_error(function() polygon.polygonRayCast(list, 110, 50, -10, 50) end,
        "polygonRayCast: points[2] is not convex (a reflex turn at vertex 4); split it once with "
        .. "polygonConvexParts and pass the parts")
      local ok, err = callsite.raisesAtCaller(polygon.polygonRayCast, { { L }, 110, 50, -10, 50 })
      assert.is_true(ok, err)
      -- the L split by polygonConvexParts is taken, with the flat L's answer
      hits(0.75, 1, 0, assert(polygon.polygonConvexParts(L)), 110, 50, -10, 50)
    end)
  end)

  describe("when a shape has fewer than 3 points", function()
    it("refuses a segment, saying it is one (no pointer to itself)", function()
      assert.has_error(function() polygon.polygonRayCast({ 0, 0, 100, 100 }, 0, 50, 100, 50) end,
        "polygonRayCast: points has 2 points: a segment; a polygon needs at least 3")
      local ok, err = callsite.raisesAtCaller(polygon.polygonRayCast, { { 0, 0, 100, 100 }, 0, 50, 100, 50 })
      assert.is_true(ok, err)
    end)
  end)
end)
