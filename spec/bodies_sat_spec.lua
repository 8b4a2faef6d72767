-- The two bodies of kernel, measures, contains and sat, LuaJIT's and PUC Lua's, run side by side
-- on every interpreter: for generated inputs both must return the same numbers, bit for bit (the
-- sign of a zero included; any NaN equals any NaN). The library runs one body of each pair per
-- interpreter; this spec is where the other one is tested there.
-- Inputs come the way the callers build them: random convex polygons of 3 to 20 vertices in both
-- windings, at offsets up to 1e9 and 2^40, slivers, collinear and repeated vertices, integer
-- coordinates (Lua integers on 5.3 and 5.4), and pairs that touch, overlap and miss.
local prng = require "prng"
local bitwise = require "bitwise"
local shapes = require "shapes"
local kernel = require "polygon.kernel"
local measures = require "polygon.measures"
local contains = require "polygon.contains"
local sat = require "polygon.sat"

local floor = math.floor
local unpack = rawget(table, "unpack") or rawget(_G, "unpack")   -- (5.1 and LuaJIT: a global)

local same = bitwise.same

local pack = bitwise.pack

-- A description of a list of values with every digit (%.17g), for a failure's message.
local function show(list, count)
  local out = {}
  for i = 1, count or list.n or #list do
    local v = list[i]
    out[i] = type(v) == "number" and ("%.17g"):format(v) or tostring(v)
  end
  return "{" .. table.concat(out, ", ") .. "}"
end

-- Counts the cases and keeps the first difference, so that a failure names its inputs.
local function newTally()
  return { cases = 0, first = nil }
end

local function compare(tally, what, inputs, r1, r2)
  tally.cases = tally.cases + 1
  if tally.first then return end
  local count = r1.n > r2.n and r1.n or r2.n
  for i = 1, count do
    if not same(r1[i], r2[i]) then
      tally.first = ("%s: result %d differs on %s: LuaJIT's body %s, PUC Lua's %s")
        :format(what, i, show(inputs), show(r1, count), show(r2, count))
      return
    end
  end
end

local function assertNoDifference(tally, least)
  assert.is_nil(tally.first)
  assert.is_true(tally.cases >= least, "only " .. tally.cases .. " cases")
end

---------------------------------------------------------------------------------------------
-- Inputs

local OFFSETS = { 0, 0, 0, 37.25, -1000, 1e9, -1e9, 2^40 }
local SIZES = { 1e-3, 1, 100, 1e6 }

-- points with every coordinate rounded to an integer (a Lua integer on 5.3 and 5.4 when asked)
local function rounded(points, asIntegers)
  local out = {}
  for i = 1, #points do out[i] = floor(points[i] + 0.5) + 0.0 end
  if asIntegers then return shapes.integers(out) end
  return out
end

-- points with a vertex added at the middle of some edges (exactly on the edge for even integer
-- differences, within rounding of it otherwise) and some vertices repeated
local function withExtraVertices(rng, points)
  local out, n = {}, #points
  for i = 1, n - 1, 2 do
    out[#out + 1], out[#out + 2] = points[i], points[i + 1]
    local pick = rng:int(1, 6)
    if pick == 1 then
      local j = i + 2 > n and 1 or i + 2
      out[#out + 1] = (points[i] + points[j]) / 2
      out[#out + 1] = (points[i + 1] + points[j + 1]) / 2
    elseif pick == 2 then
      out[#out + 1], out[#out + 2] = points[i], points[i + 1]
    end
  end
  return out
end

-- A convex polygon (or nearly: rounding may dent a sliver) of 3 to 20 vertices in either
-- winding: plain, with integer coordinates, a sliver, or with collinear and repeated vertices.
local function convexPolygon(rng, ox, oy, size)
  local kind = rng:int(1, 5)
  local points
  if kind == 1 then
    -- integer coordinates: a radius of 1000 keeps every rounded polygon convex
    local asIntegers = rng:int(1, 2) == 1
    points = rounded(shapes.convex(rng, rng:int(3, 20), floor(ox), floor(oy), 1000, 0.3), asIntegers)
  else
    points = shapes.convex(rng, rng:int(3, 20), ox, oy, size, 0.3)
    if kind == 2 then   -- a sliver: y squeezed around oy
      for i = 2, #points, 2 do points[i] = oy + (points[i] - oy) * 1e-12 end
    elseif kind == 3 then
      points = withExtraVertices(rng, points)
    end
  end
  if rng:int(1, 2) == 1 then points = shapes.reverse(points) end
  return points
end

-- A second polygon against p1 (a convex polygon of size `size`): overlapping, missing, sharing
-- one of its edges (touching from outside, or one part in 2^50 of size inside or out), or
-- sharing one of its vertices.
local function partner(rng, p1, size)
  local n1 = #p1
  local kind = rng:int(1, 5)
  local cx, cy = p1[1], p1[2]
  if kind == 1 then
    return convexPolygon(rng, cx + size * rng:range(-1, 1), cy + size * rng:range(-1, 1), size)
  elseif kind == 2 then
    return convexPolygon(rng, cx + 4 * size, cy - 3 * size, size)
  elseif kind <= 4 then
    -- the edge a -> b of p1 taken backwards, and a third and fourth vertex beyond it
    local i = 2 * rng:int(0, n1 / 2 - 1) + 1
    local j = i + 2 > n1 and 1 or i + 2
    local ax, ay, bx, by = p1[i], p1[i + 1], p1[j], p1[j + 1]
    local area = kernel.areaSign(p1, n1)
    local turn = area > 0 and 1 or -1
    -- outward normal of a -> b (the side away from p1)
    local nx, ny = -(by - ay) * turn, (bx - ax) * turn
    local nudge = kind == 4 and (rng:int(0, 2) - 1) * size * 2^-50 or 0
    local points = {
      bx, by, ax, ay,
      ax + nx * 0.5, ay + ny * 0.5, bx + nx * 0.7, by + ny * 0.7,
    }
    local len = (nx * nx + ny * ny) ^ 0.5
    if len > 0 then
      for k = 1, #points - 1, 2 do
        points[k] = points[k] + nudge * nx / len
        points[k + 1] = points[k + 1] + nudge * ny / len
      end
    end
    if rng:int(1, 2) == 1 then points = shapes.reverse(points) end
    return points
  end
  -- sharing a vertex: a polygon moved so that one of its vertices lands on one of p1's
  local q = convexPolygon(rng, 0, 0, size)
  local i, k = 2 * rng:int(0, n1 / 2 - 1) + 1, 2 * rng:int(0, #q / 2 - 1) + 1
  return shapes.translate(q, p1[i] - q[k], p1[i + 1] - q[k + 1])
end

-- A pair of polygons, each convex, as the SAT engine receives them.
local function polygonPair(rng)
  local size = rng:pick(SIZES)
  local p1 = convexPolygon(rng, rng:pick(OFFSETS), rng:pick(OFFSETS), size)
  return p1, partner(rng, p1, size)
end

-- The turn of a polygon (1 or -1) as convexPenetration takes it, or nil for zero area.
local function turnOf(points)
  local sign = kernel.areaSign(points, #points)
  if sign > 0 then return 1 elseif sign < 0 then return -1 end
  return nil
end

---------------------------------------------------------------------------------------------

describe("the two bodies of each pair", function()
  describe("kernel", function()
    it("crossJit and crossPuc return the same number and leave the same expansion", function()
      local rng, tally = prng.new(101), newTally()
      local expansion = kernel.expansion
      local function run(f, args)
        kernel.expClear()
        local r = pack(f(unpack(args, 1, 8)))
        for i = 1, kernel.expLength() do r[r.n + i] = expansion[i] end
        r.n = r.n + kernel.expLength()
        return r
      end
      for _ = 1, 3000 do
        local args
        local kind = rng:int(1, 4)
        local ox, oy, size = rng:pick(OFFSETS), rng:pick(OFFSETS), rng:pick(SIZES)
        if kind == 1 then   -- anywhere
          args = {}
          for i = 1, 8, 2 do
            args[i], args[i + 1] = ox + size * rng:range(-1, 1), oy + size * rng:range(-1, 1)
          end
        else   -- v1 on or within rounding of the line u0 -> u1 (v0 = u0), as orient's callers ask
          local ux0, uy0 = ox + size * rng:range(-1, 1), oy + size * rng:range(-1, 1)
          local dx, dy = size * rng:range(-1, 1), size * rng:range(-1, 1)
          local t = rng:range(-2, 2)
          if kind == 3 then   -- integers, exactly on the line
            ux0, uy0, dx, dy = floor(ux0), floor(uy0), floor(dx / size * 1000), floor(dy / size * 1000)
            t = rng:int(-3, 3)
          end
          args = { ux0, uy0, ux0 + dx, uy0 + dy, ux0, uy0, ux0 + t * dx, uy0 + t * dy }
          if kind == 4 then   -- one ulp or two off the line
            args[8] = args[8] + (rng:int(0, 4) - 2) * shapes.ulp(math.abs(args[8]) + 1e-300)
          end
          if kind == 3 and rng:int(1, 2) == 1 then args = shapes.integers(args) end
        end
        compare(tally, "cross", args, run(kernel.crossJit, args), run(kernel.crossPuc, args))
      end
      assertNoDifference(tally, 3000)
    end)

    it("shoelaceBounds (LuaJIT's) and turnAndBounds (PUC Lua's) give the same turn and box", function()
      local rng, tally = prng.new(102), newTally()
      for _ = 1, 2000 do
        local points = convexPolygon(rng, rng:pick(OFFSETS), rng:pick(OFFSETS), rng:pick(SIZES))
        local n = #points
        local sum, xSq, dSq, xmin, xmax, ymin, ymax = kernel.shoelaceBounds(points, n)
        local sign = kernel.areaSignOf(points, n, sum, xSq, dSq)
        sign = sign > 0 and 1.0 or sign < 0 and -1.0 or 0.0
        local r2 = pack(kernel.turnAndBounds(points, n))
        compare(tally, "shoelaceBounds", points, pack(sign, xmin, xmax, ymin, ymax),
          pack(r2[1], r2[2], r2[3], r2[4], r2[5]))
      end
      assertNoDifference(tally, 2000)
    end)
  end)

  describe("measures", function()
    it("polygonTypeJit and polygonTypePuc classify alike", function()
      local rng, tally = prng.new(201), newTally()
      for k = 1, 3000 do
        local points
        local kind = k % 4
        if kind == 0 then
          points = convexPolygon(rng, rng:pick(OFFSETS), rng:pick(OFFSETS), rng:pick(SIZES))
        elseif kind == 1 then   -- concave: a star, or a convex polygon with one vertex pulled in
          points = shapes.star(rng, rng:int(3, 20), rng:pick(OFFSETS), 0, rng:pick(SIZES))
        elseif kind == 2 then   -- winding twice (a pentagram's way) or doubling back on a line
          local m = rng:int(5, 9)
          points = shapes.convex(rng, m, rng:pick(OFFSETS), 0, 10, 0)
          local twice = {}
          for i = 0, m - 1 do
            local j = (2 * i) % m
            twice[2 * i + 1], twice[2 * i + 2] = points[2 * j + 1], points[2 * j + 2]
          end
          points = m % 2 == 1 and twice or { 0, 0, 4, 0, 2, 0, 6, 0, 3, 3 }
        else   -- every vertex on one line, or a triangle within rounding of one
          local ox, size = rng:pick(OFFSETS), rng:pick(SIZES)
          local dx, dy = size * rng:range(-1, 1), size * rng:range(-1, 1)
          points = { ox, ox, ox + dx, ox + dy, ox + 2 * dx, ox + 2 * dy }
          if rng:int(1, 2) == 1 then points[5] = points[5] + shapes.ulp(math.abs(points[5]) + 1) end
          if rng:int(1, 2) == 1 then points = shapes.reverse(points) end
        end
        compare(tally, "polygonType", points, pack(pcall(measures.polygonTypeJit, points)),
          pack(pcall(measures.polygonTypePuc, points)))
      end
      assertNoDifference(tally, 3000)
    end)
  end)

  describe("contains", function()
    it("containsShort4 to containsShort16, containsByRuns and polygonContains agree", function()
      local rng, tally = prng.new(301), newTally()
      local shorts = { contains.containsShort4, contains.containsShort8, contains.containsShort12,
        contains.containsShort16 }
      for _ = 1, 1500 do
        local size = rng:pick(SIZES)
        local points
        if rng:int(1, 2) == 1 then
          points = convexPolygon(rng, rng:pick(OFFSETS), rng:pick(OFFSETS), size)
        else
          points = shapes.star(rng, rng:int(3, 16), rng:pick(OFFSETS), rng:pick(OFFSETS), size)
        end
        local n = #points
        if n <= 32 then
          local short = shorts[floor((n - 1) / 8) + 1]
          for _ = 1, 4 do
            -- a point anywhere near, a vertex, or on (within rounding of) an edge
            local i = 2 * rng:int(0, n / 2 - 1) + 1
            local j = i + 2 > n and 1 or i + 2
            local x, y
            local pick = rng:int(1, 3)
            if pick == 1 then
              x, y = points[i] + size * rng:range(-1.5, 1.5), points[i + 1] + size * rng:range(-1.5, 1.5)
            elseif pick == 2 then
              x, y = points[i], points[i + 1]
            else
              local t = rng:float()
              x = points[i] + t * (points[j] - points[i])
              y = points[i + 1] + t * (points[j + 1] - points[i + 1])
            end
            x, y = x + 0.0, y + 0.0   -- as polygonContains converts them
            local byRuns = pack(contains.containsByRuns(points, n, x, y))
            local inputs = { x, y, unpack(points) }
            compare(tally, "containsShort", inputs, pack(short(points, n, x, y)), byRuns)
            compare(tally, "polygonContains", inputs, pack(contains.polygonContains(points, x, y)),
              byRuns)
          end
        end
      end
      assertNoDifference(tally, 10000)
    end)
  end)

  describe("sat", function()
    -- Each test below takes its edges and normals from pairs of polygons, as reachPast,
    -- reachPastBothEnds and convexPenetration do: for edge a -> b of p1 (turn: its area's sign)
    -- the outward normal n = ((b - a) turned) and the other polygon p2.
    local function eachEdge(seed, pairs, fn)
      local rng = prng.new(seed)
      for _ = 1, pairs do
        local p1, p2 = polygonPair(rng)
        local turn = turnOf(p1)
        if turn and turnOf(p2) then
          local n1, n2 = #p1, #p2
          local ia = n1 - 1
          for ib = 1, n1 - 1, 2 do
            local ax, ay = p1[ia] + 0.0, p1[ia + 1] + 0.0
            local nx, ny = ((p1[ib + 1] + 0.0) - ay) * turn, (ax - p1[ib]) * turn
            -- (a repeated vertex gives no axis, and the callers skip it)
            if nx ~= 0 or ny ~= 0 then fn(p1, n1, p2, n2, turn, ia, ib, ax, ay, nx, ny) end
            ia = ib
          end
        end
      end
    end

    it("minProjectionJit's first result is minProjectionPuc's", function()
      local tally = newTally()
      eachEdge(401, 300, function(_, _, p2, n2, _, _, _, ax, ay, nx, ny)
        local lo = sat.minProjectionJit(p2, n2, ax, ay, nx, ny)
        compare(tally, "minProjection", { ax, ay, nx, ny, unpack(p2) }, pack(lo),
          pack(sat.minProjectionPuc(p2, n2, ax, ay, nx, ny)))
      end)
      assertNoDifference(tally, 2000)
    end)

    it("faceAndFarJit and faceAndFarPuc give the same two reaches", function()
      local tally = newTally()
      eachEdge(402, 300, function(p1, n1, p2, n2, _, _, _, ax, ay, nx, ny)
        compare(tally, "faceAndFar", { ax, ay, nx, ny, unpack(p2) },
          pack(sat.faceAndFarJit(p1, n1, p2, n2, ax, ay, nx, ny)),
          pack(sat.faceAndFarPuc(p1, n1, p2, n2, ax, ay, nx, ny)))
      end)
      assertNoDifference(tally, 2000)
    end)

    it("unitJit and unitPuc give the same unit vector and length", function()
      local rng, tally = prng.new(403), newTally()
      local specials = { 0.0, -0.0, 1.0, -1.0, 2^-1074, -2^-1074, 1e300, -1e300, 3.0, -3.0 }
      for k = 1, 3000 do
        local nx, ny
        if k % 3 == 0 then
          nx, ny = rng:pick(specials), rng:pick(specials)
          if nx == 0 and ny == 0 then ny = 1.0 end
        else
          local scale = 2^rng:int(-1000, 1000)
          nx, ny = rng:range(-1, 1) * scale, rng:range(-1, 1) * scale
          if k % 3 == 1 then ny = nx * (rng:int(0, 2) - 1) end   -- the diagonals and axes: ties
          if nx == 0 and ny == 0 then nx = 1.0 end
        end
        compare(tally, "unit", { nx, ny }, pack(sat.unitJit(nx, ny)), pack(sat.unitPuc(nx, ny)))
      end
      assertNoDifference(tally, 3000)
    end)

    it("vertexInsideJit and vertexInsidePuc decide alike on edges and deepest vertices", function()
      local tally = newTally()
      eachEdge(404, 400, function(p1, n1, p2, n2, turn, ia, ib)
        local ax, ay, bx, by = p1[ia], p1[ia + 1], p1[ib], p1[ib + 1]
        -- the edge's own line (reachPast) and the line through a vertex of p1, turned the other
        -- way (reachPastBothEnds' far end)
        local k = 2 * ((ib - 1) / 2 % (n1 / 2)) + 1
        for _, line in ipairs({ { ax, ay, turn }, { p1[k], p1[k + 1], -turn } }) do
          local cx, cy, inside = line[1], line[2], line[3]
          compare(tally, "vertexInside", { ax, ay, bx, by, cx, cy, inside, unpack(p2) },
            pack(sat.vertexInsideJit(ax, ay, bx, by, cx, cy, inside, p2, n2)),
            pack(sat.vertexInsidePuc(ax, ay, bx, by, cx, cy, inside, p2, n2)))
        end
      end)
      assertNoDifference(tally, 4000)
    end)

    it("separatingPushJit and separatingPushPuc give the same push", function()
      local rng, tally = prng.new(405), newTally()
      local overlapping = 0
      for _ = 1, 2500 do
        local p1, p2 = polygonPair(rng)
        local n1, n2 = #p1, #p2
        for _, both in ipairs({ true, false }) do
          local r = pack(sat.convexPenetration(p1, n1, p2, n2, both))
          if r[1] then
            overlapping = overlapping + 1
            local args = { p1, n1, p2, n2, unpack(r, 1, 7) }
            compare(tally, "separatingPush", { unpack(r, 1, 7) },
              pack(sat.separatingPushJit(unpack(args, 1, 11))),
              pack(sat.separatingPushPuc(unpack(args, 1, 11))))
          end
        end
      end
      assertNoDifference(tally, 1000)
      assert.is_true(overlapping >= 1000)
    end)

    -- reachPast (LuaJIT's, once each way) and reachBoth (PUC Lua's calipers) are not one pair
    -- of bodies: reachBoth projects on an edge of p2 from the edge's end in p2's own order, which
    -- is the start of the edge reachPast projects from only when both polygons wind the same way,
    -- and its calipers assume strict convexity, which rounding takes from a polygon a few ulps
    -- wide. Their verdicts agree on every pair; their numbers agree bit for bit on pairs of one
    -- winding whose polygons are many ulps wide, and otherwise differ in the last bits (about one
    -- opposite-wound overlapping pair in ten), or, for polygons dented by rounding, in the edge.
    it("reachPast, both ways, and reachBoth give the same verdict, and the same numbers on pairs"
      .. " of one winding", function()
      local rng, verdicts, numbers = prng.new(406), newTally(), newTally()
      for _ = 1, 2500 do
        local p1, p2 = polygonPair(rng)
        local n1, n2 = #p1, #p2
        local sign1, xmin1, xmax1, ymin1, ymax1, _, high1 = kernel.turnAndBounds(p1, n1)
        local sign2, xmin2, xmax2, ymin2, ymax2, low2 = kernel.turnAndBounds(p2, n2)
        -- as convexPenetration: boxes that overlap, areas not zero
        if sign1 ~= 0 and sign2 ~= 0 and xmax1 > xmin2 and xmax2 > xmin1 and ymax1 > ymin2
            and ymax2 > ymin1 then
          local spanX = math.max(xmax1, xmax2) - math.min(xmin1, xmin2)
          local spanY = math.max(ymax1, ymax2) - math.min(ymin1, ymin2)
          local tolSq = sat.squaredTolerance(spanX, spanY)
          local jit
          local squared, o, edgeEnd = sat.reachPast(p1, n1, sign1, p2, n2, tolSq)
          if not squared then
            jit = pack(false)
          else
            local squared2, o2, edgeEnd2 = sat.reachPast(p2, n2, sign2, p1, n1, tolSq)
            if not squared2 then
              jit = pack(false)
            elseif squared2 < squared then
              jit = pack(squared2, o2, edgeEnd2, 2)
            else
              jit = pack(squared, o, edgeEnd, 1)
            end
          end
          local inputs = { sign1, sign2, tolSq, unpack(p1) }
          -- many ulps wide: each polygon's box at least 2^-30 of its largest coordinate
          local wide = true
          for _, box in ipairs({ { xmin1, xmax1, ymin1, ymax1 }, { xmin2, xmax2, ymin2, ymax2 } }) do
            local m = shapes.largestMagnitude(box)
            if box[2] - box[1] < 2^-30 * m or box[4] - box[3] < 2^-30 * m then wide = false end
          end
          for _, puc in ipairs({ pack(sat.reachBoth(p1, n1, sign1, p2, n2, sign2, tolSq, high1, low2)),
                                 pack(sat.reachBoth(p1, n1, sign1, p2, n2, sign2, tolSq)) }) do
            compare(verdicts, "reachBoth's verdict", inputs, pack(jit[1] ~= false),
              pack(puc[1] ~= false))
            if sign1 == sign2 and wide then compare(numbers, "reachBoth", inputs, jit, puc) end
          end
        end
      end
      assertNoDifference(verdicts, 2000)
      assertNoDifference(numbers, 800)
    end)
  end)
end)
