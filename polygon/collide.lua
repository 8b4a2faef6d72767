-- polygon/collide.lua: the public collision functions: their argument checks, then the convex
-- engines (sat, circle) or, for lists of parts, compound.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local check = require(_PACKAGE .. ".check")
local sat = require(_PACKAGE .. ".sat")
local compound = require(_PACKAGE .. ".compound")
local views = require(_PACKAGE .. ".views")
local circle = require(_PACKAGE .. ".circle")

local checkPoints, checkFiniteNumber = check.checkPoints, check.checkFiniteNumber
local checkRadius = check.checkRadius
local convexPenetration, separatingPush = sat.convexPenetration, sat.separatingPush
local collideParts, collideCircleParts = compound.collideParts, compound.collideCircleParts
local isParts = views.isParts
local circleCollision = circle.circleCollision

local M = {}


-- Raises the error for a non-finite coordinate at the caller of the public function, which
-- called the private function that calls this one.
local function raiseNonFinite(fname, argname)
  error(("%s: %s holds a non-finite coordinate"):format(fname, argname), 4)
end

-- kind1, kind2: the type of each argument's first entry where the caller has looked (it is a
-- table then), else nil.
local function collides(fname, points1, points2, both, kind1, kind2)
  local n1 = checkPoints(points1, fname, "points1", 4, kind1)
  local n2 = checkPoints(points2, fname, "points2", 4, kind2)
  local depth, argname = convexPenetration(points1, n1, points2, n2, both)
  if depth == nil then raiseNonFinite(fname, argname) end
  return depth ~= false
end


-- Whether the edge normals of points1 show no separating axis between two convex polygons.
-- Touching is not colliding; fewer than 3 points or zero area never collides. Exact.
-- Raises an error for a non-finite coordinate.
-- Returns true or false
function M.polygonCollidesWith(points1, points2)
  local collided = collides("polygonCollidesWith", points1, points2, false)
  return collided
end

-- Whether two convex polygons (either winding) overlap, by the separating axis theorem.
-- Either may be a list of convex parts instead (see polygon/compound.lua).
-- Touching is not colliding; fewer than 3 points or zero area never collides. Exact.
-- Raises an error for a non-finite coordinate.
-- Returns true or false
function M.polygonsCollide(points1, points2)
  -- isParts inlined, the kinds handed on to the checks (two calls and two type calls fewer)
  local kind1 = type(points1) == "table" and type(points1[1])
  local kind2 = type(points2) == "table" and type(points2[1])
  if kind1 == "table" or kind2 == "table" then
    local hit = collideParts("polygonsCollide", points1, points2, false, kind1 == "table",
      kind2 == "table")
    return hit
  end
  local collided = collides("polygonsCollide", points1, points2, true, kind1, kind2)
  return collided
end

-- convexPenetration, then separatingPush: false, or push length, dx, dy (adding (dx, dy) to
-- every vertex of points2 leaves the polygons touching or apart, exactly).
local function pushOut(fname, points1, points2, both, kind1, kind2)
  local n1, n2
  if kind1 and kind2 then   -- both tables: the rest of checkPoints' test, with no call
    n1 = #points1
    n2 = #points2
    if n1 % 2 ~= 0 or n2 % 2 ~= 0 then
      checkPoints(points1, fname, "points1", 4, kind1)
      checkPoints(points2, fname, "points2", 4, kind2)
    end
  else
    n1 = checkPoints(points1, fname, "points1", 4, kind1)
    n2 = checkPoints(points2, fname, "points2", 4, kind2)
  end
  local depth, ux, uy, owner, edgeEnd, base, inside =
    convexPenetration(points1, n1, points2, n2, both)
  if not depth then
    if depth == nil then raiseNonFinite(fname, ux) end
    return false
  end
  local push, dx, dy = separatingPush(points1, n1, points2, n2, depth, ux, uy, owner, edgeEnd,
    base, inside)
  return push, dx, dy
end

-- As polygonCollidesWith, with the minimum translation vector over the axes of points1.
-- Returns overlap, dx, dy or false: after adding (dx, dy) to every vertex of points2,
-- polygonCollidesWith(points1, moved) is false (see polygonsCollideV)
function M.polygonCollidesWithV(points1, points2)
  local push, dx, dy = pushOut("polygonCollidesWithV", points1, points2, false)
  return push, dx, dy
end

-- As polygonsCollide, with the minimum translation vector (lists of parts: see polygon/compound.lua).
-- overlap is the penetration depth along the axis of least penetration, right also when one
-- polygon contains the other; (dx, dy) moves points2 out of points1 (add it to every vertex of
-- points2), pointing the right way in either argument order and when the centres coincide.
-- One push separates: after p[i] = p[i] + dx (and + dy) on points2, rounded,
-- polygonsCollide(points1, moved) is false, and the push is at most a few ulps of the
-- coordinates longer than the exact depth. Raises an error for a non-finite coordinate.
-- Returns overlap, dx, dy or false
function M.polygonsCollideV(points1, points2)
  -- isParts inlined, the kinds handed on to the checks (as in polygonsCollide)
  local kind1 = type(points1) == "table" and type(points1[1])
  local kind2 = type(points2) == "table" and type(points2[1])
  if kind1 == "table" or kind2 == "table" then
    local overlap, dx, dy = collideParts("polygonsCollideV", points1, points2, true,
      kind1 == "table", kind2 == "table")
    return overlap, dx, dy
  end
  local push, dx, dy = pushOut("polygonsCollideV", points1, points2, true, kind1, kind2)
  return push, dx, dy
end
-- The minimum translation vector of a circle out of a convex polygon (either winding), or out of
-- a list of convex parts (see polygon/compound.lua).
-- Collides exactly when the open disc meets the polygon's interior: touching is not colliding,
-- a radius of 0 never collides, fewer than 3 points or zero area never collides. The overlap
-- is the full penetration (r minus the signed distance from the centre to the polygon), so a
-- circle deep inside is pushed out in one step, and the push separates for certain: after
-- cx + dx, cy + dy (rounded) the circle no longer collides. The push is longer than the exact
-- depth by at most 8 eps M, eps = 2^-53 and M the largest coordinate magnitude involved (the
-- polygon's, the centre's and the moved centre's; see circlePush for the bound, 7.1 eps M).
-- Returns overlap, dx, dy (move the circle by dx, dy) or false
function M.polygonCircleCollideV(points, cx, cy, radius)
  local fname = "polygonCircleCollideV"
  if isParts(points) then
    local overlap, dx, dy = collideCircleParts(fname, points, cx, cy, radius)
    return overlap, dx, dy
  end
  local n = checkPoints(points, fname)
  checkFiniteNumber(cx, fname, "cx")
  checkFiniteNumber(cy, fname, "cy")
  checkRadius(radius, fname, "radius")
  if n < 6 or radius == 0 then return false end
  -- converted in place: on LuaJIT the numbers of this frame and of circleCollision's are then
  -- the same (see circleCollision: fewer for a side trace to take over)
  cx = cx + 0.0
  cy = cy + 0.0
  radius = radius + 0.0
  local overlap, dx, dy = circleCollision(points, n, cx, cy, radius)
  if overlap == nil then error(fname .. ": points holds a non-finite coordinate", 2) end
  if not overlap then return false end
  return overlap, dx, dy
end


return M
