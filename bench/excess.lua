-- bench/excess.lua: how much longer than the exact depth the circle pushes are, in units of
-- eps M (eps = 2^-53, M the largest coordinate magnitude involved: polygon, centre, moved centre;
-- the radius is a length, not in M), found by bisection on the oracle's exact checks. The
-- contract is at most 8 eps M; spec/circle_hard_spec.lua and spec/circles_spec.lua check it.
-- From the repository root: lua5.4 bench/excess.lua [trials] [seed]
-- Prints, for polygonCircleCollideV, the pushes that did not separate, those above 8 eps M, the
-- largest excess and a histogram; then the same for circlesCollideV.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local polygon = require "polygon"
local oracle = require "oracle"
local exact = require "exact"
local prng = require "prng"
local shapes = require "shapes"
local EPS = 2^-53

do   -- polygonCircleCollideV
local trials, seed = tonumber(arg[1] or 400), tonumber(arg[2] or 8086)
local r = prng.new(seed)
local function convex(offset, size)
  local n = r:int(3, 10)
  local angles, t = {}, r:range(0, 2 * math.pi)
  local step = 2 * math.pi / n
  for i = 1, n do angles[i] = t + (i - 1) * step + r:range(0, step - 0.3) end
  local a, b = r:range(5, 50) * (size or 1), r:range(5, 50) * (size or 1)
  local ox, oy = offset * (r:float() * 2 - 1), offset * (r:float() * 2 - 1)
  local points = {}
  for i = 1, n do points[2*i-1] = ox + a * math.cos(angles[i]); points[2*i] = oy + b * math.sin(angles[i]) end
  return points
end
local function excessUnits(points, cx, cy, rad, dx, dy, m)
  local q = oracle.lengthAbove(dx, dy)
  local lo, hi = -64, 64
  if not oracle.circleDepthAtLeast(points, cx, cy, rad, q, hi * EPS * m) then return math.huge end
  for _ = 1, 12 do
    local mid = (lo + hi) / 2
    if oracle.circleDepthAtLeast(points, cx, cy, rad, q, mid * EPS * m) then hi = mid else lo = mid end
  end
  return hi
end
local worst, worstR, count, over, notsep = -1e9, -1e9, 0, 0, 0
local hist = {}
local worstCase
for trial = 1, trials do
  local points, cx, cy, radius
  local kind = trial % 5
  if kind <= 2 then
    points = convex(10 ^ r:int(0, 12))
    local n = #points
    local i = 2 * r:int(0, n / 2 - 1) + 1
    local j = i + 2 <= n and i + 2 or 1
    local t = trial % 3 == 0 and 0 or r:float()
    local bx, by = points[i] + t * (points[j] - points[i]), points[i+1] + t * (points[j+1] - points[i+1])
    local angle, dist = r:range(0, 2 * math.pi), r:range(0, 30) * (kind == 2 and 10 ^ r:int(0, 8) or 1)
    cx, cy = bx + dist * math.cos(angle), by + dist * math.sin(angle)
    radius = math.sqrt((cx - bx) ^ 2 + (cy - by) ^ 2)
    local k = r:int(0, 3)
    if k == 0 then for _ = 1, r:int(0, 2) do radius = exact.nextUp(radius) end
    elseif k == 1 then for _ = 1, r:int(0, 2) do radius = exact.nextDown(radius) end
    elseif k == 2 then radius = radius + r:range(0, 40) end
  elseif kind == 3 then
    -- deep: centre inside or near, radius up to a few times the size
    points = convex(10 ^ r:int(0, 3))
    cx, cy = points[1] + r:range(-20, 20), points[2] + r:range(-20, 20)
    radius = r:range(0.1, 200)
  elseif kind == 4 and trial % 10 == 9 then
    -- deepest: a polygon across the origin, the centre near a vertex, pushed across it
    local size = 10 ^ r:range(0, 9)
    points = convex(0, size / 30)
    local k = 2 * r:int(0, #points / 2 - 1) + 1
    cx, cy = points[k] * r:range(0.9, 1.1), points[k + 1] * r:range(0.9, 1.1)
    radius = size * r:range(0.5, 3)
  else
    -- r comparable to the coordinates: polygon near the origin, centre far, radius reaching it
    points = convex(r:range(0, 50))
    local angle, dist = r:range(0, 2 * math.pi), 10 ^ r:range(1, 7)
    cx, cy = points[1] + dist * math.cos(angle), points[2] + dist * math.sin(angle)
    radius = math.sqrt((cx - points[1]) ^ 2 + (cy - points[2]) ^ 2) * (1 + r:range(-1e-3, 1e-3))
  end
  if trial % 2 == 0 then points = shapes.reverse(points) end
  if radius > 0 then
    local o, dx, dy = polygon.polygonCircleCollideV(points, cx, cy, radius)
    if o then
      count = count + 1
      if oracle.discMeetsPolygon(points, cx + dx, cy + dy, radius) then notsep = notsep + 1 end
      local m = math.max(math.abs(cx), math.abs(cy), math.abs(cx + dx), math.abs(cy + dy))
      for k = 1, #points do m = math.max(m, math.abs(points[k])) end
      local e = excessUnits(points, cx, cy, radius, dx, dy, m)
      local mr = math.max(m, radius)
      local er = e * m / mr
      if e > 8 then over = over + 1 end
      if e > worst then worst = e; worstCase = { kind, cx, cy, radius, m, #points } end
      if er > worstR then worstR = er end
      local b = math.floor(e); hist[b] = (hist[b] or 0) + 1
    end
  end
end
print(("collided %d, not separated %d, excess > 8 eps M: %d, largest excess %.3f eps M (M without r), "
  .. "%.3f eps max(M, r)")
  :format(count, notsep, over, worst, worstR))
local keys = {}
for k in pairs(hist) do keys[#keys + 1] = k end
table.sort(keys)
local line = {}
for _, k in ipairs(keys) do line[#line + 1] = ("[%d,%d): %d"):format(k, k + 1, hist[k]) end
print("histogram (eps M): " .. table.concat(line, "  "))
print(("worst: kind %d centre (%.17g, %.17g) r %.17g M %.6g n %d")
  :format(worstCase[1], worstCase[2], worstCase[3], worstCase[4], worstCase[5], worstCase[6]))
end

do   -- circlesCollideV
local r = prng.new(7)
local worst, over, cnt = 0, 0, 0
for _ = 1, 3000 do
  local off = 10 ^ r:int(0, 12)
  local x1, y1 = off * (r:float() * 2 - 1), off * (r:float() * 2 - 1)
  local r1, r2 = r:range(1, 100), r:range(1, 100)
  local a, d = r:range(0, 2 * math.pi), (r1 + r2) * r:range(0, 1.0001)
  local x2, y2 = x1 + d * math.cos(a), y1 + d * math.sin(a)
  local o, dx, dy = polygon.circlesCollideV(x1, y1, r1, x2, y2, r2)
  if o then
    cnt = cnt + 1
    local m = math.max(math.abs(x1), math.abs(y1), math.abs(x2), math.abs(y2),
      math.abs(x2 + dx), math.abs(y2 + dy))
    local q = oracle.lengthAbove(dx, dy)
    local lo, hi = -64, 64
    local function within(k) return oracle.circlesDepthAtLeast(x1, y1, r1, x2, y2, r2, q, k * EPS * m) end
    if not within(hi) then hi = math.huge else
      for _ = 1, 12 do
        local mid = (lo + hi) / 2
        if within(mid) then hi = mid else lo = mid end
      end
    end
    if hi > 8 then over = over + 1 end
    worst = math.max(worst, hi)
  end
end
print(("circlesCollideV: %d pushes, %d above 8 eps M (M without radii), largest %.3f eps M")
  :format(cnt, over, worst))
end
