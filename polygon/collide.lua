-- polygon/collide.lua: the public collision functions: their argument checks, then the convex
-- engines (sat, circle) or, for lists of parts, compound.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local check = require(_PACKAGE .. ".check")
local sat = require(_PACKAGE .. ".sat")
local compound = require(_PACKAGE .. ".compound")
local circle = require(_PACKAGE .. ".circle")
local convex = require(_PACKAGE .. ".convex")
local object = require(_PACKAGE .. ".object")

local checkPoints, checkFiniteNumber = check.checkPoints, check.checkFiniteNumber
local checkRadius = check.checkRadius
local convexPenetration, separatingPush = sat.convexPenetration, sat.separatingPush
local collideParts, collideCircleParts = compound.collideParts, compound.collideCircleParts
local circleCollision = circle.circleCollision
local checkConvex, refuseEntries = convex.checkConvex, convex.refuseEntries
local objectPoints = object.objectPoints

local M = {}


-- Raises the error for a non-finite coordinate at the caller of the public function, which
-- called the private function that calls this one (level 4 as error's; one more for each call
-- between).
local function raiseNonFinite(fname, argname, level)
  error(("%s: %s holds a non-finite coordinate"):format(fname, argname), level or 4)
end

-- The engine's answer where its vouching pass (the convexity check fused into its first pass,
-- convex.lua) could not vouch for a polygon: the engine without it, then both polygons checked
-- the careful way (checkConvex: raises for a concave one), in the order of the unchecked
-- functions plus the check. Called from collides and pushOut (their callers' callers are the
-- public functions' callers).
local function penetrationCarefully(fname, points1, n1, points2, n2, both)
  local depth, ux, uy, owner, edgeEnd, base, inside =
    convexPenetration(points1, n1, points2, n2, both)
  if depth == nil then raiseNonFinite(fname, ux, 5) end
  checkConvex(points1, n1, fname, "points1", 4)
  checkConvex(points2, n2, fname, "points2", 4)
  return depth, ux, uy, owner, edgeEnd, base, inside
end

-- The shape a collision function was handed when its first entry is not a number (kind: its
-- type, false for a non-table): a Polygon object's points, a list of parts (kind "table"), or
-- the argument error, raised at `level` (as error's, counted from this function's caller).
-- Returns the shape and its kind: "number" for a flat array, "table" for a list of parts.
local function resolveShape(fname, argname, shape, kind, level)
  -- not a table: raised by the engines' own checks, after a list's errors (as before)
  if kind == false then return shape, false end
  local points = objectPoints(shape)
  if points then shape, kind = points, type(points[1]) end
  if kind == "table" then
    local first = shape[1]
    -- a point {x =, y =} or {x, y}: refused; else a list of parts (checked when prepared)
    if first.x == nil and #first ~= 2 then return shape, "table" end
    refuseEntries(fname, argname, shape, kind, level + 1)
  end
  if kind == "nil" and #shape < 6 then
    local n = checkPoints(shape, fname, argname, level + 2, true)
    checkConvex(shape, n, fname, argname, level + 1)   -- raises: fewer than 3 points
  elseif kind ~= "number" then
    refuseEntries(fname, argname, shape, kind, level + 1)
  end
  return shape, kind
end

-- Checks a flat shape handed with a list of parts (the list's parts are checked when it is
-- prepared): an even count, at least 3 points, convex; before collideParts when it is the first
-- argument, after it (and the list's errors) when it is the second. level as in resolveShape.
local function checkFlat(fname, argname, shape, level)
  local n = checkPoints(shape, fname, argname, level + 2)
  checkConvex(shape, n, fname, argname, level + 1)
end

-- Both arguments of a function that takes lists of parts, resolved (called from the public
-- function when a first entry is not a number). Returns the shapes and their kinds.
local function resolveTwo(fname, points1, points2, kind1, kind2)
  points1, kind1 = resolveShape(fname, "points1", points1, kind1, 3)
  points2, kind2 = resolveShape(fname, "points2", points2, kind2, 3)
  return points1, points2, kind1, kind2
end

-- Both arguments of a one-sided function (convex polygons only, no lists of parts), resolved.
local function resolveOne(fname, points1, points2, kind1, kind2)
  points1, kind1 = resolveShape(fname, "points1", points1, kind1, 3)
  if kind1 == "table" then
    error(("%s: points1 is a list of parts; it takes convex polygons only (polygonsCollide "
      .. "takes lists)"):format(fname), 3)
  end
  points2, kind2 = resolveShape(fname, "points2", points2, kind2, 3)
  if kind2 == "table" then
    error(("%s: points2 is a list of parts; it takes convex polygons only (polygonsCollide "
      .. "takes lists)"):format(fname), 3)
  end
  return points1, points2, kind1, kind2
end

-- The public functions, built twice: with the convexity check (checked, the module's) and
-- without it (M.unchecked, for the benchmark's rows that show what the check costs: the same
-- code but for the one branch).
local function build(T, checked)
  -- kind1, kind2: the type of each argument's first entry where the caller has looked (it is a
  -- table then), else nil.
  local function collides(fname, points1, points2, both, kind1, kind2)
    local n1 = checkPoints(points1, fname, "points1", 4, kind1)
    local n2 = checkPoints(points2, fname, "points2", 4, kind2)
    -- checked: the engine's first pass vouches that both are convex, or the careful way
    local depth, argname = convexPenetration(points1, n1, points2, n2, both, nil, checked)
    if depth == nil then
      if argname ~= false then raiseNonFinite(fname, argname) end
      depth = penetrationCarefully(fname, points1, n1, points2, n2, both)
    end
    return depth ~= false
  end


  -- Whether the edge normals of points1 show no separating axis between two convex polygons.
  -- Touching is not colliding; zero area never collides (fewer than 3 points and concave
  -- polygons are refused). Exact.
  -- Raises an error for a non-finite coordinate.
  -- Returns true or false
  function T.polygonCollidesWith(points1, points2)
    local fname = "polygonCollidesWith"
    local kind1 = type(points1) == "table" and type(points1[1])
    local kind2 = type(points2) == "table" and type(points2[1])
    if kind1 ~= "number" or kind2 ~= "number" then
      points1, points2, kind1, kind2 = resolveOne(fname, points1, points2, kind1, kind2)
    end
    local collided = collides(fname, points1, points2, false, kind1, kind2)
    return collided
  end

  -- Whether two convex polygons (either winding) overlap, by the separating axis theorem.
  -- Either may be a list of convex parts instead (see polygon/compound.lua).
  -- Touching is not colliding; zero area never collides (fewer than 3 points and concave
  -- polygons are refused). Exact.
  -- Raises an error for a non-finite coordinate.
  -- Returns true or false
  function T.polygonsCollide(points1, points2)
    -- isParts inlined, the kinds handed on to the checks (two calls and two type calls fewer)
    local kind1 = type(points1) == "table" and type(points1[1])
    local kind2 = type(points2) == "table" and type(points2[1])
    if kind1 ~= "number" or kind2 ~= "number" then
      points1, points2, kind1, kind2 = resolveTwo("polygonsCollide", points1, points2, kind1, kind2)
      if kind1 == "table" or kind2 == "table" then
        -- a flat shape's refusals in argument order: before the list's errors when it comes first
        if kind1 ~= "table" then checkFlat("polygonsCollide", "points1", points1, 2) end
        local hit = collideParts("polygonsCollide", points1, points2, false, kind1 == "table",
          kind2 == "table")
        if kind2 ~= "table" then checkFlat("polygonsCollide", "points2", points2, 2) end
        return hit
      end
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
      convexPenetration(points1, n1, points2, n2, both, nil, checked)   -- as in collides
    if depth == nil then
      if ux ~= false then raiseNonFinite(fname, ux) end
      depth, ux, uy, owner, edgeEnd, base, inside =
        penetrationCarefully(fname, points1, n1, points2, n2, both)
    end
    if not depth then return false end
    local push, dx, dy = separatingPush(points1, n1, points2, n2, depth, ux, uy, owner, edgeEnd,
      base, inside)
    return push, dx, dy
  end

  -- As polygonCollidesWith, with the minimum translation vector over the axes of points1.
  -- Returns overlap, dx, dy or false: after adding (dx, dy) to every vertex of points2,
  -- polygonCollidesWith(points1, moved) is false (see polygonsCollideV)
  function T.polygonCollidesWithV(points1, points2)
    local fname = "polygonCollidesWithV"
    local kind1 = type(points1) == "table" and type(points1[1])
    local kind2 = type(points2) == "table" and type(points2[1])
    if kind1 ~= "number" or kind2 ~= "number" then
      points1, points2, kind1, kind2 = resolveOne(fname, points1, points2, kind1, kind2)
    end
    local push, dx, dy = pushOut(fname, points1, points2, false, kind1, kind2)
    if not push then return false end
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
  function T.polygonsCollideV(points1, points2)
    -- isParts inlined, the kinds handed on to the checks (as in polygonsCollide)
    local kind1 = type(points1) == "table" and type(points1[1])
    local kind2 = type(points2) == "table" and type(points2[1])
    if kind1 ~= "number" or kind2 ~= "number" then
      points1, points2, kind1, kind2 = resolveTwo("polygonsCollideV", points1, points2, kind1, kind2)
      if kind1 == "table" or kind2 == "table" then
        if kind1 ~= "table" then checkFlat("polygonsCollideV", "points1", points1, 2) end
        local overlap, dx, dy = collideParts("polygonsCollideV", points1, points2, true,
          kind1 == "table", kind2 == "table")
        if kind2 ~= "table" then checkFlat("polygonsCollideV", "points2", points2, 2) end
        if not overlap then return false end
        return overlap, dx, dy
      end
    end
    local push, dx, dy = pushOut("polygonsCollideV", points1, points2, true, kind1, kind2)
    if not push then return false end
    return push, dx, dy
  end
  -- The minimum translation vector of a circle out of a convex polygon (either winding), or out of
  -- a list of convex parts (see polygon/compound.lua).
  -- Collides exactly when the open disc meets the polygon's interior: touching is not colliding,
  -- a radius of 0 or zero area never collides (fewer than 3 points are refused). The overlap
  -- is the full penetration (r minus the signed distance from the centre to the polygon), so a
  -- circle deep inside is pushed out in one step, and the push separates for certain: after
  -- cx + dx, cy + dy (rounded) the circle no longer collides. The push is longer than the exact
  -- depth by at most 8 eps M, eps = 2^-53 and M the largest coordinate magnitude involved (the
  -- polygon's, the centre's and the moved centre's; see circlePush for the bound, 7.1 eps M).
  -- Returns overlap, dx, dy (move the circle by dx, dy) or false
  function T.polygonCircleCollideV(points, cx, cy, radius)
    local fname = "polygonCircleCollideV"
    local kind = type(points) == "table" and type(points[1])
    if kind ~= "number" then
      points, kind = resolveShape(fname, "points", points, kind, 2)
      if kind == "table" then
        local overlap, dx, dy = collideCircleParts(fname, points, cx, cy, radius)
        if not overlap then return false end
        return overlap, dx, dy
      end
    end
    local n = checkPoints(points, fname, "points", 3, kind)
    checkFiniteNumber(cx, fname, "cx")
    checkFiniteNumber(cy, fname, "cy")
    checkRadius(radius, fname, "radius")
    if n < 6 or radius == 0 then
      if checked then checkConvex(points, n, fname, "points", 2) end
      return false
    end
    -- converted in place: on LuaJIT the numbers of this frame and of circleCollision's are then
    -- the same (see circleCollision: fewer for a side trace to take over)
    cx = cx + 0.0
    cy = cy + 0.0
    radius = radius + 0.0
    -- checked: the engine's first pass vouches that the polygon is convex, or the careful way
    -- (raises for a concave polygon or a non-finite coordinate) and the engine again
    local overlap, dx, dy = circleCollision(points, n, cx, cy, radius, checked)
    if overlap == nil and dx == "unsure" then
      checkConvex(points, n, fname, "points", 2)
      overlap, dx, dy = circleCollision(points, n, cx, cy, radius)
    end
    if overlap == nil then error(fname .. ": points holds a non-finite coordinate", 2) end
    if not overlap then return false end
    return overlap, dx, dy
  end
  return T
end

build(M, true)
M.unchecked = build({}, false)
M.resolveShape = resolveShape   -- for polygon/raycast.lua: the same shapes taken, the same refusals

return M
