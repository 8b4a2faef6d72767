--- The circle contract checked on one case, for spec/circle_hard_spec.lua and
-- spec/circle_huge_hard_spec.lua: polygonCircleCollideV(points, cx, cy, r) answers as the oracle
-- does (the open disc meets the interior); a push clears for certain (the oracle sees no overlap
-- at the moved centre), and its length q (a double at least |(dx, dy)|, checked exactly) is at
-- most the exact depth plus 8 eps M, decided exactly: depth >= q - 8 eps M, M the largest
-- coordinate magnitude involved (the polygon's, the centre's, the moved centre's; the radius is
-- a length, not a coordinate). Returns the answer: overlap, dx, dy or false.

local assert = require "luassert"
local polygon = require "polygon"
local oracle = require "oracle"

local EPS = 2^-53

-- M: the largest coordinate magnitude involved, the moved centre's included
local function magnitude(points, cx, cy, dx, dy)
  local m = math.max(math.abs(cx), math.abs(cy), math.abs(cx + dx), math.abs(cy + dy))
  for i = 1, #points do m = math.max(m, math.abs(points[i])) end
  return m
end

return function(points, cx, cy, r)
  local expected = oracle.discMeetsPolygon(points, cx, cy, r)
  local overlap, dx, dy = polygon.polygonCircleCollideV(points, cx, cy, r)
  assert.are.equal(expected, overlap ~= false,
    ("centre (%.17g, %.17g) r %.17g"):format(cx, cy, r))
  if overlap then
    assert.is_false(oracle.discMeetsPolygon(points, cx + dx, cy + dy, r))
    local m = magnitude(points, cx, cy, dx, dy)
    local q = oracle.lengthAbove(dx, dy)
    assert.is_true(oracle.circleDepthAtLeast(points, cx, cy, r, q, 8 * EPS * m),
      ("centre (%.17g, %.17g) r %.17g: push %.17g longer than the depth by more than 8 eps M")
        :format(cx, cy, r, q))
    -- the overlap is the depth to within 8 eps max(M, r), both sides decided exactly (the
    -- oracle's rounded depth, circleDepth, overflows its squares for radii beyond 2^500)
    local tol = 8 * EPS * math.max(m, r)
    assert.is_true(oracle.circleDepthAtLeast(points, cx, cy, r, overlap, tol))
    assert.is_false(oracle.circleDepthAtLeast(points, cx, cy, r, overlap, -tol))
  end
  return overlap, dx, dy
end
