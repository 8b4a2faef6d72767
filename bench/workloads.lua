-- bench/workloads.lua: the inputs the benchmark times, from a fixed seed of spec/support/prng.lua,
-- so that every interpreter sees the same doubles. Coordinates are floats (never 5.3+ integers).
-- Each workload is a list of argument columns: { points[], x[], y[] ... }, call i takes row i.
local prng = require "prng"
local shapes = require "shapes"
local exact = require "exact"

local pi, cos, sin, sqrt, floor = math.pi, math.cos, math.sin, math.sqrt, math.floor
local reverse = shapes.reverse

local W = {}
local rng = prng.new(20261122)
local function uniform(a, b) return rng:range(a, b) end
local function randint(a, b) return rng:int(a, b) end
local function ulp(x) return exact.tonumber(exact.ulp(x)) end

local function eitherWinding(points) return randint(0, 1) == 1 and reverse(points) or points end
local function convex(m, cx, cy, size) return eitherWinding(shapes.convex(rng, m, cx, cy, size, 0.3)) end

-- Star-shaped, usually concave: random radii at jittered angles.
local function star(m, cx, cy, r)
  local out = {}
  for k = 0, m - 1 do
    local t, rk = (k + uniform(-0.3, 0.3)) * 2 * pi / m, r * uniform(0.35, 1)
    out[2 * k + 1], out[2 * k + 2] = cx + rk * cos(t), cy + rk * sin(t)
  end
  return eitherWinding(out)
end

local function mean(points)
  local sx, sy, m = 0, 0, #points / 2
  for i = 1, #points - 1, 2 do sx, sy = sx + points[i], sy + points[i + 1] end
  return sx / m, sy / m
end

local bbox = shapes.bounds -- x0, y0, x1, y1

-- The k-th edge's far end (flat index of its x), wrapping round.
local function nextVertex(points, k) return k + 2 <= #points and k + 2 or 1 end

-- Outward unit normal of the edge from vertex k of a polygon whose mean is (mx, my).
local function outward(points, k, mx, my)
  local l = nextVertex(points, k)
  local nx, ny = points[l + 1] - points[k + 1], points[k] - points[l]
  if nx * (mx - points[k]) + ny * (my - points[k + 1]) > 0 then nx, ny = -nx, -ny end
  local length = sqrt(nx * nx + ny * ny)
  return nx / length, ny / length, length
end

---------------------------------------------------------------------------------------------
-- Polygons (one argument)
---------------------------------------------------------------------------------------------
-- Scene polygons: 4 to 16 vertices, half convex, half star-shaped, near the origin.
function W.ordinary(count)
  local list = {}
  for i = 1, count do
    local m, cx, cy, size = 4 + (i - 1) % 13, uniform(-100, 100), uniform(-100, 100), uniform(5, 50)
    list[i] = i % 2 == 1 and convex(m, cx, cy, size) or star(m, cx, cy, size)
  end
  return list
end

-- Near-degenerate: in turn Kettner et al.'s ulp-grid triangles (a vertex moved by single ulps
-- near the line through (12, 12) and (24, 24)), near-collinear 3 to 5-gons with y moved by up
-- to 2 ulps, and convex polygons with an extra vertex within 2 ulps of an edge's midpoint.
function W.nearDegenerate(count)
  local list, u = {}, 2 ^ -53
  for i = 1, count do
    local pts = {}
    if i % 3 == 0 then
      pts = { 0.5 + randint(0, 63) * u, 0.5 + randint(0, 63) * u, 12.0, 12.0, 24.0, 24.0 }
    elseif i % 3 == 1 then
      local x0, y0, t = uniform(-100, 100), uniform(-100, 100), uniform(0, 2 * pi)
      for j = 1, randint(3, 5) do
        local s = uniform(0, 30)
        local y = y0 + s * sin(t)
        pts[2 * j - 1], pts[2 * j] = x0 + s * cos(t), y + randint(-2, 2) * ulp(y)
      end
    else
      local base = convex(randint(5, 9), uniform(-100, 100), uniform(-100, 100), uniform(5, 50))
      local k = 2 * randint(0, #base / 2 - 1) + 1
      local l = nextVertex(base, k)
      local mx, my = (base[k] + base[l]) * 0.5, (base[k + 1] + base[l + 1]) * 0.5
      for j = 1, #base do
        pts[#pts + 1] = base[j]
        if j == k + 1 then
          pts[#pts + 1] = mx + randint(-2, 2) * ulp(mx)
          pts[#pts + 1] = my + randint(-2, 2) * ulp(my)
        end
      end
    end
    list[i] = pts
  end
  return list
end

-- Large polygons of m vertices, alternately convex and star-shaped.
function W.large(m, count)
  local list = {}
  for i = 1, count do
    local cx, cy = 300 + uniform(-50, 50), 200 + uniform(-50, 50)
    list[i] = i % 2 == 1 and convex(m, cx, cy, 800) or star(m, cx, cy, 1000)
  end
  return list
end

---------------------------------------------------------------------------------------------
-- Point queries (points, x, y)
---------------------------------------------------------------------------------------------
function W.queriesInBox(polys, perPoly)
  local P, X, Y = {}, {}, {}
  for _, poly in ipairs(polys) do
    local x0, y0, x1, y1 = bbox(poly)
    local mx, my = (x1 - x0) * 0.1, (y1 - y0) * 0.1
    for _ = 1, perPoly do
      P[#P + 1], X[#X + 1], Y[#Y + 1] = poly, uniform(x0 - mx, x1 + mx), uniform(y0 - my, y1 + my)
    end
  end
  return { P, X, Y }
end

-- Points on vertices (1 in 5), at a vertex's height (1 in 10), or on an edge moved by up to 3 ulps.
function W.queriesNearEdges(polys, perPoly)
  local P, X, Y = {}, {}, {}
  for _, poly in ipairs(polys) do
    for _ = 1, perPoly do
      local k = 2 * randint(0, #poly / 2 - 1) + 1
      local l, r = nextVertex(poly, k), rng:float()
      local x, y = poly[k], poly[k + 1]
      if r >= 0.3 then
        local t = rng:float()
        x, y = x + t * (poly[l] - x), y + t * (poly[l + 1] - y)
        x = x + randint(-3, 3) * ulp(x)
      elseif r >= 0.2 then
        local x0, _, x1 = bbox(poly)
        x = uniform(x0, x1)
      end
      P[#P + 1], X[#X + 1], Y[#Y + 1] = poly, x, y
    end
  end
  return { P, X, Y }
end

-- A jittered g x g grid of quadrilateral tiles; points on the shared edges and corners, each asked
-- of every tile that touches it.
function W.tiles(g)
  local V, T = {}, {}
  for i = 0, g do
    V[i] = {}
    for j = 0, g do V[i][j] = { 10 * i + uniform(-3, 3), 10 * j + uniform(-3, 3) } end
  end
  for i = 0, g - 1 do
    T[i] = {}
    for j = 0, g - 1 do
      local a, b, c, d = V[i][j], V[i + 1][j], V[i + 1][j + 1], V[i][j + 1]
      T[i][j] = { a[1], a[2], b[1], b[2], c[1], c[2], d[1], d[2] }
    end
  end
  local P, X, Y = {}, {}, {}
  local function ask(x, y, ...)
    for _, tile in ipairs({ ... }) do P[#P + 1], X[#X + 1], Y[#Y + 1] = tile, x, y end
  end
  local function onEdge(a, b, t) return a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]) end
  for i = 1, g - 1 do
    for j = 0, g - 1 do
      for _ = 1, 3 do
        local t = rng:float()
        local x, y = onEdge(V[i][j], V[i][j + 1], t)      -- between T[i-1][j] and T[i][j]
        ask(x, y, T[i - 1][j], T[i][j])
        x, y = onEdge(V[j][i], V[j + 1][i], t)            -- between T[j][i-1] and T[j][i]
        ask(x, y, T[j][i - 1], T[j][i])
      end
      if j > 0 then
        local v = V[i][j]
        ask(v[1], v[2], T[i - 1][j - 1], T[i][j - 1], T[i - 1][j], T[i][j])
      end
    end
  end
  return { P, X, Y }
end

---------------------------------------------------------------------------------------------
-- Convex pairs of 6 to 8 vertices (points1, points2), in random order
---------------------------------------------------------------------------------------------
local function pair(a, b) if randint(0, 1) == 1 then return b, a end return a, b end

function W.pairOverlap()
  local cx, cy, size = uniform(-100, 100), uniform(-100, 100), uniform(5, 30)
  local t, d = uniform(0, 2 * pi), uniform(0, 0.3) * size
  return pair(convex(randint(6, 8), cx, cy, size),
              convex(randint(6, 8), cx + d * cos(t), cy + d * sin(t), uniform(5, 30)))
end

function W.pairMiss()
  local cx, cy, sa, sb = uniform(-100, 100), uniform(-100, 100), uniform(5, 30), uniform(5, 30)
  local t, d = uniform(0, 2 * pi), 1.5 * (sa + sb) * uniform(1.02, 1.4)
  return pair(convex(randint(6, 8), cx, cy, sa), convex(randint(6, 8), cx + d * cos(t), cy + d * sin(t), sb))
end

-- One well inside the other (where the tutorial's overlap is not the depth).
function W.pairInside()
  local cx, cy, size = uniform(-100, 100), uniform(-100, 100), uniform(20, 30)
  return pair(convex(randint(6, 8), cx, cy, size),
              convex(randint(6, 8), cx + uniform(-1, 1), cy + uniform(-1, 1), 0.1 * size))
end

-- Exactly touching, all on a 2^-30 grid so that the sums below are exact, in turn: B is A
-- reflected through the midpoint of A's edge k (sharing that edge); B is A mirrored through its
-- vertex k and scaled (sharing that corner only); B has a vertex exactly on A's edge k (a T
-- contact, k/1024 along the edge, and B inscribed in a circle tangent to the edge there).
local touchKind, GRID = 0, 2 ^ 30
local function onGrid(v) return floor(v * GRID + 0.5) / GRID end
function W.pairTouch()
  local A = convex(randint(6, 8), uniform(-100, 100), uniform(-100, 100), uniform(5, 30))
  for i = 1, #A do A[i] = onGrid(A[i]) end
  touchKind = touchKind % 3 + 1
  local k = 2 * randint(0, #A / 2 - 1) + 1
  local l = nextVertex(A, k)
  local px, py, qx, qy = A[k], A[k + 1], A[l], A[l + 1]
  local B = {}
  if touchKind == 1 then
    for i = 1, #A - 1, 2 do B[i], B[i + 1] = (px + qx) - A[i], (py + qy) - A[i + 1] end
  elseif touchKind == 2 then
    local lambda = randint(1, 3) / 2
    for i = 1, #A - 1, 2 do B[i], B[i + 1] = px + lambda * (px - A[i]), py + lambda * (py - A[i + 1]) end
  else
    local t, r, m = randint(1, 1023) / 1024, uniform(3, 20), randint(5, 7)
    local cx, cy = px + t * (qx - px), py + t * (qy - py)
    local nx, ny = outward(A, k, mean(A))
    local ox, oy = cx + r * nx, cy + r * ny
    B[1], B[2] = cx, cy
    for j = 1, m do
      local phi = (20 + 320 * (j - 1) / (m - 1)) * pi / 180
      B[2 * j + 1] = onGrid(ox - r * (nx * cos(phi) - ny * sin(phi)))
      B[2 * j + 2] = onGrid(oy - r * (nx * sin(phi) + ny * cos(phi)))
    end
  end
  return pair(A, B)
end

function W.pairs(count, makers)
  local A, B = {}, {}
  for i = 1, count do A[i], B[i] = makers[(i - 1) % #makers + 1]() end
  return { A, B }
end

---------------------------------------------------------------------------------------------
-- Circles against convex polygons (points, cx, cy, radius)
---------------------------------------------------------------------------------------------
-- kinds: 1 overlapping an edge, 2 in a vertex region, 3 missing, 4 small, near the middle
function W.circles(count, kinds)
  local P, X, Y, R = {}, {}, {}, {}
  for i = 1, count do
    local kind, size = kinds[(i - 1) % #kinds + 1], uniform(10, 50)
    local poly = convex(4 + (i - 1) % 13, uniform(-100, 100), uniform(-100, 100), size)
    local mx, my = mean(poly)
    local k, r = 2 * randint(0, #poly / 2 - 1) + 1, uniform(2, 20)
    local d, cx, cy = r * uniform(0.3, 0.95)
    if kind == 1 then
      local l, t = nextVertex(poly, k), uniform(0.2, 0.8)
      local nx, ny = outward(poly, k, mx, my)
      cx = poly[k] + t * (poly[l] - poly[k]) + nx * d
      cy = poly[k + 1] + t * (poly[l + 1] - poly[k + 1]) + ny * d
    elseif kind == 2 then
      local dx, dy = poly[k] - mx, poly[k + 1] - my
      local length = sqrt(dx * dx + dy * dy)
      cx, cy = poly[k] + dx / length * d, poly[k + 1] + dy / length * d
    elseif kind == 3 then
      local t = uniform(0, 2 * pi)
      d = 1.5 * size + r * uniform(1.1, 2)
      cx, cy = mx + d * cos(t), my + d * sin(t)
    else
      r, cx, cy = size * uniform(0.05, 0.2), mx + uniform(-0.1, 0.1) * size, my + uniform(-0.1, 0.1) * size
    end
    P[i], X[i], Y[i], R[i] = poly, cx, cy, r
  end
  return { P, X, Y, R }
end

---------------------------------------------------------------------------------------------
-- Rays and nearest points (issue 30)
---------------------------------------------------------------------------------------------
-- points, x1, y1, x2, y2: a convex polygon of 4 to 12 vertices (concave: a star of 8 to 16,
-- mostly concave, its middle its centre) and a segment from 3 sizes away. kinds: 1 through the
-- polygon (to beyond a point near its middle), 2 passing it by (its line misses), 3 stopping
-- short of it, 4 from near its middle (inside it but for a few stars), out
function W.rays(count, kinds, concave)
  local P, X1, Y1, X2, Y2 = {}, {}, {}, {}, {}
  for i = 1, count do
    local kind, size = kinds[(i - 1) % #kinds + 1], uniform(10, 50)
    local poly, mx, my
    if concave then
      mx, my = uniform(-100, 100), uniform(-100, 100)
      poly = star(8 + (i - 1) % 9, mx, my, size)
    else
      poly = convex(4 + (i - 1) % 9, uniform(-100, 100), uniform(-100, 100), size)
      mx, my = mean(poly)
    end
    local t = uniform(0, 2 * pi)
    local ax, ay = mx + 3 * size * cos(t), my + 3 * size * sin(t)
    local bx, by
    if kind == 1 then
      local tx, ty = mx + uniform(-0.3, 0.3) * size, my + uniform(-0.3, 0.3) * size
      bx, by = ax + 2 * (tx - ax), ay + 2 * (ty - ay)
    elseif kind == 2 then
      local s = t + pi + uniform(0.6, 1.2) * (randint(0, 1) * 2 - 1)
      bx, by = ax + 6 * size * cos(s), ay + 6 * size * sin(s)
    elseif kind == 3 then
      local k = uniform(0.1, 0.4)
      bx, by = ax + (mx - ax) * k, ay + (my - ay) * k
    else
      ax, ay = mx + uniform(-0.2, 0.2) * size, my + uniform(-0.2, 0.2) * size
      bx, by = mx + 3 * size * cos(t), my + 3 * size * sin(t)
    end
    P[i], X1[i], Y1[i], X2[i], Y2[i] = poly, ax, ay, bx, by
  end
  return { P, X1, Y1, X2, Y2 }
end

-- W.rays' four kinds against stars (concave flat polygons), drawn from a seed of their own so
-- that the workloads made after them keep their inputs.
function W.concaveRays(count)
  local shared = rng
  rng = prng.new(20261129)
  local list = W.rays(count, { 1, 2, 3, 4 }, true)
  rng = shared
  return list
end

-- A new array of every value plus d (rounded as a game moves things).
function W.shift(list, d)
  local out = {}
  for i, v in ipairs(list) do out[i] = v + d end
  return out
end

-- cx, cy, radius, x1, y1, x2, y2: the same four kinds against a disc of radius 10 to 50
function W.circleRays(count)
  local A = { {}, {}, {}, {}, {}, {}, {} }
  for i = 1, count do
    local kind, r = (i - 1) % 4 + 1, uniform(10, 50)
    local cx, cy, t = uniform(-100, 100), uniform(-100, 100), uniform(0, 2 * pi)
    local ax, ay = cx + 3 * r * cos(t), cy + 3 * r * sin(t)
    local bx, by
    if kind == 1 then
      bx, by = ax + 2 * (cx + uniform(-0.3, 0.3) * r - ax), ay + 2 * (cy + uniform(-0.3, 0.3) * r - ay)
    elseif kind == 2 then
      local s = t + pi + uniform(0.6, 1.2) * (randint(0, 1) * 2 - 1)
      bx, by = ax + 6 * r * cos(s), ay + 6 * r * sin(s)
    elseif kind == 3 then
      bx, by = ax + (cx - ax) * 0.3, ay + (cy - ay) * 0.3
    else
      ax, ay = cx + uniform(-0.5, 0.5) * r, cy + uniform(-0.5, 0.5) * r
      bx, by = cx + 3 * r * cos(t), cy + 3 * r * sin(t)
    end
    A[1][i], A[2][i], A[3][i], A[4][i], A[5][i], A[6][i], A[7][i] = cx, cy, r, ax, ay, bx, by
  end
  return A
end

-- points, x, y: scene polygons (half convex, half star-shaped) and a point in their box grown
-- by half its size on every side
function W.nearestQueries(polys)
  local P, X, Y = {}, {}, {}
  for i, poly in ipairs(polys) do
    local x0, y0, x1, y1 = bbox(poly)
    local w, h = x1 - x0, y1 - y0
    P[i], X[i], Y[i] = poly, uniform(x0 - w / 2, x1 + w / 2), uniform(y0 - h / 2, y1 + h / 2)
  end
  return { P, X, Y }
end

---------------------------------------------------------------------------------------------
-- Projections
---------------------------------------------------------------------------------------------
-- points, x, y, nx, ny: a vertex as the reference, an edge normal as the axis
function W.projections(polys)
  local P, X, Y, NX, NY = {}, {}, {}, {}, {}
  for i, poly in ipairs(polys) do
    local k, j = 2 * randint(0, #poly / 2 - 1) + 1, 2 * randint(0, #poly / 2 - 1) + 1
    local l = nextVertex(poly, j)
    P[i], X[i], Y[i], NX[i], NY[i] = poly, poly[k], poly[k + 1], poly[l + 1] - poly[j + 1], poly[j] - poly[l]
  end
  return { P, X, Y, NX, NY }
end

-- cx, cy, radius, x, y, nx, ny
function W.circleProjections(count)
  local A = { {}, {}, {}, {}, {}, {}, {} }
  for i = 1, count do
    local t, length = uniform(0, 2 * pi), uniform(0.5, 50)
    A[1][i], A[2][i], A[3][i] = uniform(-100, 100), uniform(-100, 100), uniform(1, 20)
    A[4][i], A[5][i] = uniform(-100, 100), uniform(-100, 100)
    A[6][i], A[7][i] = length * cos(t), length * sin(t)
  end
  return A
end

---------------------------------------------------------------------------------------------
-- Casts (issue 30)
---------------------------------------------------------------------------------------------
-- points1, points2, dx, dy: a static convex polygon of 4 to 8 vertices and a moving one of 4 to 6
-- from 3 sizes away. kinds: 1 a move through the static one's middle (a hit), 2 passing it by,
-- 3 stopping short of it, 4 starting overlapped
function W.casts(count)
  local P1, P2, DX, DY = {}, {}, {}, {}
  for i = 1, count do
    local kind, size = (i - 1) % 4 + 1, uniform(10, 50)
    local cx, cy = uniform(-100, 100), uniform(-100, 100)
    local t = uniform(0, 2 * pi)
    local distance = kind == 4 and 0.5 * size or 3 * size
    local mx, my = cx + distance * cos(t), cy + distance * sin(t)
    local moving = convex(4 + (i - 1) % 3, mx, my, 0.4 * size)
    local dx, dy
    if kind == 1 or kind == 4 then
      dx, dy = 2 * (cx + uniform(-0.3, 0.3) * size - mx), 2 * (cy + uniform(-0.3, 0.3) * size - my)
    elseif kind == 2 then
      local s = t + pi + uniform(0.8, 1.2) * (randint(0, 1) * 2 - 1)
      dx, dy = 6 * size * cos(s), 6 * size * sin(s)
    else
      dx, dy = 0.2 * (cx - mx), 0.2 * (cy - my)
    end
    P1[i], P2[i], DX[i], DY[i] = convex(4 + (i - 1) % 5, cx, cy, size), moving, dx, dy
  end
  return { P1, P2, DX, DY }
end

-- The move of a circle starting at (mx, my), at angle t from the target (cx, cy), for the four
-- kinds of the circles' casts (size: the target's): 1 through the target, 2 passing it by, 3
-- stopping short, 4 from overlapping, through.
local function castMotion(kind, cx, cy, mx, my, t, size)
  if kind == 1 or kind == 4 then
    return 2 * (cx + uniform(-0.3, 0.3) * size - mx), 2 * (cy + uniform(-0.3, 0.3) * size - my)
  elseif kind == 2 then
    local s = t + pi + uniform(0.8, 1.2) * (randint(0, 1) * 2 - 1)
    return 6 * size * cos(s), 6 * size * sin(s)
  end
  return 0.2 * (cx - mx), 0.2 * (cy - my)
end

-- x1, y1, r1, x2, y2, r2, dx, dy: the same four kinds for circles of radius 5 to 50
function W.circleCasts(count)
  local A = { {}, {}, {}, {}, {}, {}, {}, {} }
  for i = 1, count do
    local kind, r1, r2 = (i - 1) % 4 + 1, uniform(10, 50), uniform(5, 20)
    local cx, cy, t = uniform(-100, 100), uniform(-100, 100), uniform(0, 2 * pi)
    local distance = kind == 4 and 0.5 * r1 or 3 * (r1 + r2)
    local mx, my = cx + distance * cos(t), cy + distance * sin(t)
    local dx, dy = castMotion(kind, cx, cy, mx, my, t, r1)
    A[1][i], A[2][i], A[3][i], A[4][i], A[5][i], A[6][i], A[7][i], A[8][i] = cx, cy, r1, mx, my, r2, dx, dy
  end
  return A
end

-- points, cx, cy, radius, dx, dy: a static convex polygon of 4 to 8 vertices and a circle of
-- radius 0.2 to 0.6 of its size, the same four kinds as W.casts
function W.polygonCircleCasts(count)
  local A = { {}, {}, {}, {}, {}, {} }
  for i = 1, count do
    local kind, size = (i - 1) % 4 + 1, uniform(10, 50)
    local cx, cy, t = uniform(-100, 100), uniform(-100, 100), uniform(0, 2 * pi)
    local r = uniform(0.2, 0.6) * size
    local distance = kind == 4 and 0.5 * size or 3 * size
    local mx, my = cx + distance * cos(t), cy + distance * sin(t)
    local dx, dy = castMotion(kind, cx, cy, mx, my, t, size)
    A[1][i], A[2][i], A[3][i], A[4][i], A[5][i], A[6][i] = convex(4 + (i - 1) % 5, cx, cy, size), mx, my, r,
      dx, dy
  end
  return A
end

return W
