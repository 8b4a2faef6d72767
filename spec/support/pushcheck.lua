--- The one-push contract checked on one ordered pair, for spec/sat_push_spec.lua and
-- spec/sat_push_hard_spec.lua: polygonsCollideV (both = true) or polygonCollidesWithV answers as
-- the oracle does, and when it collides, the second polygon moved by the push (rounded, as a
-- game moves it) no longer collides by the module's exact test nor by the oracle, and the push
-- is at most 8 eps M longer than the exact least penetration depth (M the largest coordinate
-- magnitude of the pair). With lengthToo, (dx, dy) must also be the push's length to rounding.

local polygon = require "polygon"
local oracle = require "oracle"
local shapes = require "shapes"

local EPS = 2^-53

local function length(dx, dy)
  local m = math.max(math.abs(dx), math.abs(dy))
  if m == 0 then return 0 end
  return m * math.sqrt((dx / m) ^ 2 + (dy / m) ^ 2)
end

-- counts: tallies answers, separations and excesses. Returns the push's excess over the exact
-- depth in units of eps M (0 when the pair does not collide), for the report.
return function(a, b, both, counts, lengthToo)
  local collideV = both and polygon.polygonsCollideV or polygon.polygonCollidesWithV
  local collide = both and polygon.polygonsCollide or polygon.polygonCollidesWith
  local o, dx, dy = collideV(a, b)
  counts.answers:check((o ~= false) == oracle.collides(a, b, both), a, b)
  if not o then return 0 end
  local moved = shapes.translate(b, dx, dy)
  counts.separations:check(not collide(a, moved) and not oracle.collides(a, moved, both), a, b,
    dx, dy)
  local m = shapes.largestMagnitude(a, b)
  -- exactly: the least penetration is at least o - 8 eps M; and (dx, dy) is o long, to rounding
  local short = oracle.depthAtLeast(a, b, both, o, 8 * EPS * m)
  local consistent = not lengthToo or math.abs(length(dx, dy) - o) <= 4 * EPS * o
  local excess = (o - oracle.depth(a, b, both)) / (EPS * m)
  counts.excesses:check(short and consistent, a, b, o, dx, dy, excess)
  return excess
end
