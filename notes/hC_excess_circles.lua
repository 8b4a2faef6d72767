-- circlesCollideV's push excess over the exact depth in eps M (M: the centres before and after the
-- move, not the radii), by bisection on an exact check. From the repository root:
--   lua5.4 notes/hC_excess_circles.lua
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local polygon = require "polygon"
local oracle = require "oracle"
local exact = require "exact"
local prng = require "prng"
local EPS = 2^-53
local new, add, sub, mul = exact.new, exact.add, exact.sub, exact.mul
local function ok(x1, y1, r1, x2, y2, r2, q, k)
  local s = sub(add(add(new(r1), new(r2)), new(k)), new(q))
  if exact.sign(s) < 0 then return false end
  local dx, dy = sub(new(x2), new(x1)), sub(new(y2), new(y1))
  return exact.compare(add(mul(dx, dx), mul(dy, dy)), mul(s, s)) <= 0
end
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
    if not ok(x1, y1, r1, x2, y2, r2, q, hi * EPS * m) then hi = math.huge else
      for _ = 1, 12 do
        local mid = (lo + hi) / 2
        if ok(x1, y1, r1, x2, y2, r2, q, mid * EPS * m) then hi = mid else lo = mid end
      end
    end
    if hi > 8 then over = over + 1 end
    worst = math.max(worst, hi)
  end
end
print(("circlesCollideV: %d pushes, %d above 8 eps M (M without radii), largest %.3f eps M")
  :format(cnt, over, worst))
