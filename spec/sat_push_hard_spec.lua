-- Hard cases for "one push separates": the check of a push tries every vertex of the polygon that
-- must leave from the chosen edge's first vertex only, and the cross product's error bound grows
-- with the vertex's distance from it. So here the vertex that ends on the edge's line sits at the
-- edge's far end (and near its start, and midway), along slanted edges at every angle, for
-- polygons from 1e-3 to 1e6 across at offsets 1 to 1e12, slivers among them, with overlaps from a
-- tenth of the size down to a few ulps. Every pair in both argument orders, through
-- polygonsCollideV and polygonCollidesWithV: after adding the push to the second polygon the way
-- a game does (p[i] = p[i] + dx, rounded), the module's exact test and the independent oracle
-- both say the pair no longer collides, and the push exceeds the oracle's exact least
-- penetration depth by at most 8 eps M (M the largest coordinate magnitude of the pair).
--
-- Measured with POLYGON_SPEC_COUNTS=1 (luajit /usr/bin/busted spec/sat_push_hard_spec.lua):
-- see the printed counts; the largest excess is reported there.

local polygon = require "polygon"
local prng = require "prng"
local shapes = require "shapes"
local tally = require "tally"
local checkPush = require "pushcheck"

local translate, largestMagnitude, ulp = shapes.translate, shapes.largestMagnitude, shapes.ulp
local OFFSETS = { 1, 1e3, 1e6, 1e9, 1e12 }
local SIZES = { 1e-3, 1, 1e3, 1e6 }
-- where along the edge (0 its first vertex, 1 its far end) the other polygon's deepest vertex is
local ALONG = { 1, 0.97, 0.5, 0.03 }

-- A quadrilateral with the edge from a to b (length `size`, direction angle `theta`, its outward
-- normal n to the left of a -> b when walking a, b, then inward), `thick` deep along -n, in
-- either winding; and a triangle whose apex lies `along` of the way from a to b, `depth` inside
-- the edge, its base far outside (so that the edge's normal is the axis of least penetration).
local function pokingPair(rng, cx, cy, size, theta, along, depth, thick)
  local ux, uy = math.cos(theta), math.sin(theta)      -- along the edge
  local nx, ny = -uy, ux                               -- outward
  local ax, ay = cx - 0.5 * size * ux, cy - 0.5 * size * uy
  local bx, by = cx + 0.5 * size * ux, cy + 0.5 * size * uy
  local quad = { ax, ay, bx, by, bx - thick * nx, by - thick * ny, ax - thick * nx, ay - thick * ny }
  local px = ax + along * (bx - ax) - depth * nx
  local py = ay + along * (by - ay) - depth * ny
  local reach, half = size * rng:range(0.6, 1.2), size * rng:range(0.05, 0.4)
  local tri = { px, py, px + reach * nx + half * ux, py + reach * ny + half * uy,
    px + reach * nx - half * ux, py + reach * ny - half * uy }
  if rng:int(0, 1) == 1 then quad = shapes.reverse(quad) end
  if rng:int(0, 1) == 1 then tri = shapes.reverse(tri) end
  return quad, tri
end

describe("one push separates where the deepest vertex is far from the edge's first vertex", function()
  for _, both in ipairs({ true, false }) do
    local name = both and "polygonsCollideV" or "polygonCollidesWithV"
    it(name .. ": slanted edges, sizes 1e-3 to 1e6, offsets 1 to 1e12, slivers, deep to a few ulps",
      function()
        local rng = prng.new(both and 6151 or 7013)
        local counts = {
          answers = tally.new(name .. " collides as the oracle says"),
          separations = tally.new(name .. " moved pair no longer collides"),
          excesses = tally.new(name .. " push longer than the depth by more than 8 eps M"),
        }
        local worst = 0
        for _, offset in ipairs(OFFSETS) do
          for _, size in ipairs(SIZES) do
            if size >= offset * 1e-9 then   -- (smaller ones are a few ulps across)
              for _, along in ipairs(ALONG) do
                local theta = rng:range(0, 2 * math.pi)
                local cx = rng:pick({ -1, 1 }) * offset * rng:range(0.5, 1)
                local cy = rng:pick({ -1, 1 }) * offset * rng:range(0.5, 1)
                -- a sliver (1e-6 of the size thick) one time in four
                local thick = size * (rng:int(1, 4) == 1 and 1e-6 or rng:range(0.2, 1))
                local depth = size * 10 ^ -rng:range(1, 9)
                local a, b = pokingPair(rng, cx, cy, size, theta, along, depth, thick)
                local list = { { a, b } }
                -- the same pair moved out by the push and back by 1 to 8 ulps: a few ulps deep
                local o, dx, dy = polygon.polygonsCollideV(a, b)
                if o and (dx ~= 0 or dy ~= 0) then
                  local step = rng:int(1, 8) * ulp(largestMagnitude(a, b))
                  list[2] = { a, translate(translate(b, dx, dy), dx > 0 and -step or dx < 0 and step
                    or 0, dy > 0 and -step or dy < 0 and step or 0) }
                end
                for _, pair in ipairs(list) do
                  for _, order in ipairs({ { pair[1], pair[2] }, { pair[2], pair[1] } }) do
                    worst = math.max(worst, checkPush(order[1], order[2], both, counts))
                  end
                end
              end
            end
          end
        end
        local colliding = counts.separations.total
        counts.answers:report()
        counts.separations:report((" (%d colliding)"):format(colliding))
        counts.excesses:report((", largest excess %.2f eps M"):format(worst))
        assert(colliding > 100, "too few colliding pairs to say anything")
        assert(counts.answers.count == 0, counts.answers:message())
        assert(counts.separations.count == 0, counts.separations:message())
        assert(counts.excesses.count == 0, counts.excesses:message())
      end)
  end
end)
