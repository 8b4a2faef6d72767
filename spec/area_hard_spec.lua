-- polygonAreaAccurate on its fast path (a compensated sum whose bound must vouch for one ulp)
-- and on its fallback (the expansion), against the oracle's exact area: random polygons of 3 to
-- 40 vertices at offsets from 0 to 1e12, nearly collinear ones whose sums cancel, and polygons
-- mixing huge and tiny coordinates. Within one ulp of the exact area every time.
local polygon = require "polygon"
local oracle = require "oracle"
local exact = require "exact"
local prng = require "prng"

local function check(points, bad)
  local a = polygon.polygonAreaAccurate(points)
  local want = oracle.area(points)
  if not exact.withinUlps(a, want, 1) and #bad < 3 then
    bad[#bad + 1] = ("got %.17g, exact %s"):format(a, exact.tostring(want))
  end
end

describe("polygonAreaAccurate against the exact area", function()
  it("is within one ulp on random star-shaped polygons at offsets up to 1e12", function()
    local r, bad = prng.new(31337), {}
    for _ = 1, 400 do
      local m, radius = r:int(3, 40), 10 ^ r:int(-3, 4)
      local ox, oy = (r:float() - 0.5) * 10 ^ r:int(0, 12), (r:float() - 0.5) * 10 ^ r:int(0, 12)
      local p = {}
      for k = 1, m do
        local t, rk = (k + 0.8 * (r:float() - 0.5)) * 2 * math.pi / m, radius * (0.3 + r:float())
        p[#p + 1], p[#p + 2] = ox + rk * math.cos(t), oy + rk * math.sin(t)
      end
      check(p, bad)
    end
    assert.are.same({}, bad)
  end)

  it("is within one ulp where the sum cancels (nearly collinear points)", function()
    local r, bad = prng.new(2718), {}
    for _ = 1, 300 do
      local p = {}
      local x0, y0, dx, dy = r:float() * 100, r:float() * 100, r:float(), r:float()
      for _ = 1, r:int(3, 8) do
        local s = r:float() * 50
        p[#p + 1], p[#p + 2] = x0 + s * dx, y0 + s * dy + r:int(-2, 2) * 2 ^ -46
      end
      check(p, bad)
    end
    assert.are.same({}, bad)
  end)
end)
