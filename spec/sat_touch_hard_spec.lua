-- Hard cases: touching convex pairs, where the separating-axis test's exact edge test meets one or
-- two vertices exactly on an edge's line (a shared edge's ends, a vertex on an edge). On LuaJIT
-- those vertices are decided together by a branch-free exact test when every difference of
-- coordinates is exact, and by the exact kernel otherwise (inexact differences, products near
-- underflow, coordinates beyond 2^500 in difference); both answers are checked here against the
-- exact oracle, in both argument orders, for polygonsCollide and polygonsCollideV.
--
-- Pairs: a convex polygon A (3 to 8 vertices, either winding) and
--   * B, A turned half a turn about the middle of one of its edges: the edge is shared;
--   * B, A scaled by -1/2, -1 or -3/2 about one of its vertices: only that vertex is shared;
--   * either of those with one of B's vertices moved one ulp in x or y, up or down: off the
--     line by one ulp, into A or away from it.
-- Families: coordinates on a 2^-30 grid near the origin and offset by up to 2^40 (differences
-- exact); polygons spanning -1e15 to 1e15 with fractional coordinates (differences inexact);
-- tiny (scale 1e-77, 2^-447 and 2^-490: products' rounding errors below 2^-1074) and huge (2^400,
-- and 2^520: products beyond 2^1024).

local polygon = require "polygon"
local oracle = require "oracle"
local prng = require "prng"
local shapes = require "shapes"
local exact = require "exact"

local floor = math.floor

-- A convex polygon of 3 to 8 vertices around the origin, scaled by `scale` after rounding to
-- `grid` (if given), then offset by (ox, oy); nil when rounding broke its convexity.
local function makeConvex(r, scale, grid, ox, oy)
  local points = shapes.convex(r, r:int(3, 8), 0, 0, r:range(5, 30), 0.3)
  if r:int(0, 1) == 1 then points = shapes.reverse(points) end
  for i = 1, #points do
    local v = points[i]
    if grid then v = floor(v * grid + 0.5) / grid end
    points[i] = v * scale + (i % 2 == 1 and ox or oy)
  end
  if oracle.polygonType(points) ~= "convex" then return nil end
  return points
end

-- B turned half a turn about the middle of A's edge k -> k + 1 (the edge shared).
local function halfTurn(A, k)
  local l = k + 2 <= #A and k + 2 or 1
  local sx, sy = A[k] + A[l], A[k + 1] + A[l + 1]
  local B = {}
  for i = 1, #A - 1, 2 do B[i], B[i + 1] = sx - A[i], sy - A[i + 1] end
  return B
end

-- B scaled by -lambda about A's vertex k (only that vertex shared).
local function mirrored(A, k, lambda)
  local px, py = A[k], A[k + 1]
  local B = {}
  for i = 1, #A - 1, 2 do B[i], B[i + 1] = px + lambda * (px - A[i]), py + lambda * (py - A[i + 1]) end
  return B
end

-- B with its coordinate j moved one ulp up (step 1) or down (-1).
local function nudged(B, j, step)
  local C = shapes.deepCopy(B)
  C[j] = step > 0 and exact.nextUp(C[j]) or exact.nextDown(C[j])
  return C
end

local function expectOracle(A, B, label)
  for order = 1, 2 do
    local P, Q = A, B
    if order == 2 then P, Q = B, A end
    local want = oracle.collides(P, Q, true)
    local got = polygon.polygonsCollideV(P, Q)
    local gotPlain = polygon.polygonsCollide(P, Q)
    if (got and true or false) ~= want or gotPlain ~= want then
      local function list(points)
        local out = {}
        for i = 1, #points do out[i] = ("%a"):format(points[i]) end
        return table.concat(out, ", ")
      end
      error(("%s, order %d: oracle %s, polygonsCollideV %s, polygonsCollide %s\nP = {%s}\nQ = {%s}")
        :format(label, order, tostring(want), tostring(got), tostring(gotPlain), list(P), list(Q)))
    end
  end
end

-- `count` polygons of a family, each with its touching partners and their one-ulp nudges.
local function checkFamily(seed, count, scale, grid, offset)
  local r = prng.new(seed)
  local made = 0
  while made < count do
    local ox, oy = 0.0, 0.0
    if offset then ox, oy = offset(r) end
    local A = makeConvex(r, scale, grid, ox, oy)
    if A then
      made = made + 1
      local k = 2 * r:int(0, #A / 2 - 1) + 1
      local partners = { halfTurn(A, k), mirrored(A, k, r:int(1, 3) / 2) }
      for p, B in ipairs(partners) do
        local label = ("polygon %d, partner %d"):format(made, p)
        expectOracle(A, B, label)
        -- B's vertex k lies on A's edge k: A's vertex k + 1 turned, or A's vertex k itself
        local j = k
        for _, step in ipairs({ 1, -1 }) do
          expectOracle(A, nudged(B, j, step), label .. (" x %+d ulp"):format(step))
          expectOracle(A, nudged(B, j + 1, step), label .. (" y %+d ulp"):format(step))
        end
      end
    end
  end
end

describe("polygonsCollideV and polygonsCollide on touching convex pairs", function()
  describe("when every difference of coordinates is exact", function()
    it("agree with the exact oracle on a 2^-30 grid near the origin", function()
      checkFamily(101, 60, 1.0, 2^30)
    end)

    it("agree with the exact oracle on a 2^-30 grid offset by up to 2^40", function()
      checkFamily(102, 40, 1.0, 2^30, function(r)
        local off = 2.0 ^ r:int(10, 40)
        return off * (r:int(0, 1) * 2 - 1), off * 0.75
      end)
    end)
  end)

  describe("when differences are inexact", function()
    it("agree with the exact oracle on polygons spanning -1e15 to 1e15 with fractions", function()
      checkFamily(103, 40, 3e13 + 0.1, nil)
    end)

    it("agree with the exact oracle at an offset of 1e15 plus a fraction", function()
      checkFamily(104, 40, 1.0, nil, function(r) return 1e15 + r:range(0, 1), -1e15 - r:range(0, 1) end)
    end)
  end)

  describe("when the polygons are tiny or huge", function()
    it("agree with the exact oracle at scale 1e-77 on a grid", function()
      checkFamily(105, 30, 1e-77, 2^30)
    end)

    it("agree with the exact oracle at scale 2^-447 (the exact range's smallest coordinates)", function()
      checkFamily(106, 30, 2^-447, 2^30)
    end)

    it("agree with the exact oracle at scale 2^400", function()
      checkFamily(107, 30, 2^400, 2^30)
    end)

    it("agree with the exact oracle at scale 2^520 (products of differences beyond 2^1024)", function()
      checkFamily(108, 30, 2^520, 2^30)
    end)

    it("agree with the exact oracle at scale 2^-490 (products' errors below 2^-1074)", function()
      checkFamily(109, 30, 2^-490, 2^30)
    end)
  end)

  describe("when a vertex is on the shared edge's line (hand-computed)", function()
    -- A = (0,0) (4,0) (4,4) (0,4); B = (4,0) (8,0) (8,4) (4,4) shares the edge x = 4: the cross
    -- products of B's vertices (4,0) and (4,4) with A's edge (4,0) -> (4,4) are 0, touching.
    local A = { 0, 0, 4, 0, 4, 4, 0, 4 }
    it("reports a shared edge as not colliding", function()
      expectOracle(A, { 4, 0, 8, 0, 8, 4, 4, 4 }, "shared edge")
      assert.is_false(polygon.polygonsCollideV(A, { 4, 0, 8, 0, 8, 4, 4, 4 }))
    end)

    it("reports a vertex one ulp inside as colliding", function()
      -- the double below 4 is 4 - 2^-51: B's vertex (4 - 2^-51, 2) is inside A
      local B = { 4 - 2^-51, 2, 8, 0, 8, 4 }
      expectOracle(A, B, "one ulp inside")
      assert.is_truthy(polygon.polygonsCollideV(A, B))
    end)
  end)
end)
