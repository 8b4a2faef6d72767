-- Hard cases, family 1: near-collinear points, after Kettner, Mehlhorn, Pion, Schirra and Yap,
-- "Classroom examples of robustness problems in geometric computations" (2004/2008).
--
-- p = (0.5 + i u, 0.5 + j u) for i, j in 0..255 with u = 2^-53 (the gap between doubles just above
-- 0.5, so every p is a distinct double), against the far points q = (12, 12) and r = (24, 24).
-- Every such p is within 2^-45 of the line y = x through q and r. Exactly,
--   (q - p) x (r - p) = (11.5 - i u)(23.5 - j u) - (11.5 - j u)(23.5 - i u) = 12 u (j - i),
-- so p lies left of, on, or right of the line as j > i, j == i, j < i. The naive formulas round
-- 12 - p and 24 - p to multiples of 2^-49 and 2^-48 and lose that difference.
--
-- Every answer of the library is compared with the exact oracle (spec/support/oracle.lua). Each
-- spec also counts how often the naive floating-point formula, written out below, is wrong, and
-- asserts that it is wrong somewhere: the case is hard, and the library is still never wrong.

local polygon = require "polygon"
local oracle = require "oracle"
local tally = require "tally"

local U = 2 ^ -53
local SIZE = 256
local QX, QY, RX, RY = 12, 12, 24, 24

-- Calls visit(i, j, px, py) for every grid point p = (px, py).
local function eachPoint(visit)
  for i = 0, SIZE - 1 do
    for j = 0, SIZE - 1 do
      visit(i, j, 0.5 + i * U, 0.5 + j * U)
    end
  end
end

-- The same for the points on which the slower whole-polygon oracle functions run as well: a
-- coarse sub-grid and the band around the diagonal, where exact and naive answers part.
local function eachSampledPoint(visit)
  eachPoint(function(i, j, px, py)
    if (i % 8 == 0 and j % 8 == 0) or (i - j <= 2 and j - i <= 2) then
      visit(i, j, px, py)
    end
  end)
end

-- The exact side of every grid point, from the oracle: side[i][j] = orient(p, q, r).
local side = {}
for i = 0, SIZE - 1 do side[i] = {} end
eachPoint(function(i, j, px, py)
  side[i][j] = oracle.orient(px, py, QX, QY, RX, RY)
end)

local function signOf(v)
  return v > 0 and 1 or (v < 0 and -1 or 0)
end

local function windingOfSign(s)
  return s > 0 and "cw" or (s < 0 and "ccw" or nil)
end

describe("near-collinear points on an ulp grid (Kettner et al.)", function()
  it("has the exact sides the hand computation gives: sign(j - i)", function()
    local t = tally.new("oracle side vs sign(j - i)")
    eachPoint(function(i, j)
      t:check(side[i][j] == signOf(j - i), i, j, side[i][j])
    end)
    assert.are.equal(0, t.count, t:message())
    assert.are.equal(SIZE * SIZE, t.total)
  end)

  it("keeps every answer when scaled by powers of two to the ends of the exactness range", function()
    -- Scaling by 2^k is exact and changes no sign. With k = -446 the smallest coordinate is
    -- 0.5 * 2^-446 = 2^-447, with k = 495 the largest is 24 * 2^495 < 2^500: the contract's range.
    local t = tally.new("scaled grid")
    for _, k in ipairs({ -446, -300, 300, 495 }) do
      local s = 2 ^ k
      for i = 0, SIZE - 1, 9 do
        for j = 0, SIZE - 1, 3 do
          local px, py = (0.5 + i * U) * s, (0.5 + j * U) * s
          local tri = { px, py, QX * s, QY * s, RX * s, RY * s }
          local quad = { px, py, QX * s, QY * s, RX * s, RY * s, 24 * s, 0 }
          t:check(polygon.polygonWindingOrder(tri) == windingOfSign(side[i][j]), "winding", k, i, j)
          t:check(polygon.polygonType(quad) == (side[i][j] > 0 and "concave" or "convex"), "type", k, i, j)
          local above = { -12 * s, -12 * s, 24 * s, 24 * s, -12 * s, 24 * s }
          local expected = oracle.contains(above, px, py)
          t:check(polygon.polygonContains(above, px, py) == expected, "contains", k, i, j)
        end
      end
      t:check(oracle.orient(0.5 * s, (0.5 + U) * s, QX * s, QY * s, RX * s, RY * s) == 1, "oracle", k)
    end
    assert.are.equal(0, t.count, t:message())
  end)

  describe("polygonWindingOrder of the triangle p, q, r", function()
    it("matches the exact winding for all 65536 points, where the naive sum fails", function()
      local lib, naive = tally.new("library winding"), tally.new("naive winding")
      eachPoint(function(i, j, px, py)
        local expected = windingOfSign(side[i][j])
        -- the naive shoelace sum as the tutorial writes it: sum of (x_(k+1) + x_k)(y_(k+1) - y_k)
        local sum = (QX + px) * (QY - py) + (RX + QX) * (RY - QY) + (px + RX) * (py - RY)
        naive:check(windingOfSign(sum) == expected)
        local got = polygon.polygonWindingOrder({ px, py, QX, QY, RX, RY })
        lib:check(got == expected, "p =", px, py, "got", got, "expected", expected)
      end)
      naive:report()
      assert.are.equal(0, lib.count, lib:message())
      assert.is_true(naive.count > 0, "the naive winding should fail somewhere on this grid")
    end)

    it("agrees with the oracle's whole-polygon winding on the sampled points", function()
      local t = tally.new("library vs oracle.winding")
      eachSampledPoint(function(i, j, px, py)
        local pts = { px, py, QX, QY, RX, RY }
        t:check(polygon.polygonWindingOrder(pts) == oracle.winding(pts), i, j)
      end)
      assert.are.equal(0, t.count, t:message())
    end)
  end)

  describe("polygonType of the quadrilateral p, q, r, s with s = (24, 0)", function()
    -- With s below the line (screen coordinates), the turns at r, s and p are all negative:
    -- at r (12,12) x (0,-24) = -288, at s (0,-24) x (-23.5, 0.5) = -564, at p (-23.5, 0.5) x
    -- (11.5, 11.5) = -276 (to within the ulps of p). The turn at q has the sign of j - i, so the
    -- quadrilateral is convex for j <= i (j == i: p, q, r go on forward) and concave for j > i.
    local SX, SY = 24, 0

    it("matches the exact type for all 65536 points, where the naive cross products fail", function()
      local lib, naive = tally.new("library type"), tally.new("naive type")
      eachPoint(function(i, j, px, py)
        local expected = side[i][j] > 0 and "concave" or "convex"
        -- naive: the cross products of adjacent edges in floating point, every vertex checked,
        -- convex when no two nonzero ones differ in sign
        local pts = { px, py, QX, QY, RX, RY, SX, SY }
        local seen, naiveType = 0, "convex"
        for k = 1, 4 do
          local a, b, c = (k - 1) % 4, k % 4, (k + 1) % 4
          local ux, uy = pts[2 * b + 1] - pts[2 * a + 1], pts[2 * b + 2] - pts[2 * a + 2]
          local vx, vy = pts[2 * c + 1] - pts[2 * b + 1], pts[2 * c + 2] - pts[2 * b + 2]
          local s = signOf(ux * vy - uy * vx)
          if s ~= 0 then
            if seen ~= 0 and s ~= seen then
              naiveType = "concave"
            end
            seen = s
          end
        end
        naive:check(naiveType == expected)
        local got = polygon.polygonType(pts)
        lib:check(got == expected, "p =", px, py, "got", got, "expected", expected)
      end)
      naive:report()
      assert.are.equal(0, lib.count, lib:message())
      assert.is_true(naive.count > 0, "the naive type should fail somewhere on this grid")
    end)

    it("agrees with the oracle's polygonType on the sampled points, in both windings", function()
      local t = tally.new("library vs oracle.polygonType")
      eachSampledPoint(function(i, j, px, py)
        local forward = { px, py, QX, QY, RX, RY, SX, SY }
        local backward = { SX, SY, RX, RY, QX, QY, px, py }
        t:check(polygon.polygonType(forward) == oracle.polygonType(forward), "forward", i, j)
        t:check(polygon.polygonType(backward) == oracle.polygonType(backward), "backward", i, j)
      end)
      assert.are.equal(0, t.count, t:message())
    end)
  end)

  describe("polygonContains with triangles on either side of the line y = x", function()
    -- above = {(-12,-12), (24,24), (-12,24)} holds the points with y > x, below =
    -- {(-12,-12), (24,-12), (24,24)} those with y < x; both share the edge on y = x, so a grid point
    -- on the diagonal is in exactly one of them. The naive test computes the edge's x at height y
    -- as 36 (y + 12) / 36 - 12, and y + 12 keeps only multiples of 2^-49.
    local above = { -12, -12, 24, 24, -12, 24 }
    local below = { -12, -12, 24, -12, 24, 24 }

    -- the tutorial's crossing test (bench/baseline.lua, the one transcription of the tutorial)
    local naiveContains = require("bench.baseline").polygonContains

    it("matches the exact answer for all 65536 points, where the naive division fails", function()
      local lib, naive = tally.new("library contains"), tally.new("naive contains")
      local onlyOne = tally.new("diagonal point in exactly one triangle")
      eachPoint(function(i, j, px, py)
        local s = side[i][j]
        local inAbove = polygon.polygonContains(above, px, py)
        local inBelow = polygon.polygonContains(below, px, py)
        if s == 0 then
          onlyOne:check(inAbove ~= inBelow, i, j)
        else
          -- s > 0 means j > i: y > x, strictly inside `above` and outside `below`
          lib:check(inAbove == (s > 0) and inBelow == (s < 0), "p =", px, py)
          naive:check(naiveContains(above, px, py) == (s > 0))
          naive:check(naiveContains(below, px, py) == (s < 0))
        end
      end)
      naive:report()
      assert.are.equal(0, lib.count, lib:message())
      assert.are.equal(0, onlyOne.count, onlyOne:message())
      assert.are.equal(SIZE, onlyOne.total)
      assert.is_true(naive.count > 0, "the naive contains should fail somewhere on this grid")
    end)

    it("agrees with the oracle's crossing rule on the sampled points (Polygon:contains too)", function()
      local t = tally.new("library vs oracle.contains")
      local pa, pb = polygon.Polygon(above), polygon.Polygon.new(below)
      eachSampledPoint(function(i, j, px, py)
        local ea, eb = oracle.contains(above, px, py), oracle.contains(below, px, py)
        t:check(polygon.polygonContains(above, px, py) == ea, "above", i, j)
        t:check(polygon.polygonContains(below, px, py) == eb, "below", i, j)
        t:check(pa:contains(px, py) == ea and pb:contains(px, py) == eb, "Polygon:contains", i, j)
      end)
      assert.are.equal(0, t.count, t:message())
    end)
  end)
end)
