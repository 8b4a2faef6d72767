-- bench/workloads.lua: the inputs the benchmark times, made from a fixed seed so that every
-- interpreter sees the same doubles. All coordinates are floats (never Lua 5.3+ integers).
local floor, pi, cos, sin, sqrt = math.floor, math.pi, math.cos, math.sin, math.sqrt
local ulp = require("bench.exact").ulp

local W = {}

-- Park-Miller generator on doubles: 16807 * seed < 2^46 stays exact on every interpreter.
local seed = 20261122.0
local function rand()
  seed = (seed * 16807.0) % 2147483647.0
  return seed / 2147483647.0
end
local function rnd() return rand() + rand() * 2 ^ -31 end   -- about 53 random bits
local function uniform(a, b) return a + (b - a) * rnd() end
local function randint(a, b) return a + floor(rand() * (b - a + 1)) end
W.rand, W.uniform, W.randint = rand, uniform, randint

local function reverse(points)
  local out, n = {}, #points
  for i = 1, n - 1, 2 do out[n - i] = points[i]; out[n - i + 1] = points[i + 1] end
  return out
end

local function translate(points, dx, dy)
  local out = {}
  for i = 1, #points - 1, 2 do out[i] = points[i] + dx; out[i + 1] = points[i + 1] + dy end
  return out
end
W.translate = translate

local function randomOrientation(points)
  if rand() < 0.5 then return reverse(points) end
  return points
end

-- Convex: vertices on an ellipse at jittered, increasing angles.
local function ellipse(n, cx, cy, a, b, jitter)
  local phi, start = uniform(0, 2 * pi), uniform(0, 2 * pi)
  local c, s = cos(phi), sin(phi)
  local pts = {}
  for k = 0, n - 1 do
    local t = start + (k + jitter * (rnd() - 0.5)) * 2 * pi / n
    local ex, ey = a * cos(t), b * sin(t)
    pts[#pts + 1] = cx + ex * c - ey * s
    pts[#pts + 1] = cy + ex * s + ey * c
  end
  return randomOrientation(pts)
end
W.ellipse = ellipse

-- Star-shaped, usually concave: random radii at jittered angles.
local function star(n, cx, cy, r)
  local start = uniform(0, 2 * pi)
  local pts = {}
  for k = 0, n - 1 do
    local t = start + (k + 0.6 * (rnd() - 0.5)) * 2 * pi / n
    local rk = r * uniform(0.35, 1)
    pts[#pts + 1] = cx + rk * cos(t)
    pts[#pts + 1] = cy + rk * sin(t)
  end
  return randomOrientation(pts)
end

local function mean(points)
  local sx, sy, n = 0, 0, #points / 2
  for i = 1, #points - 1, 2 do sx = sx + points[i]; sy = sy + points[i + 1] end
  return sx / n, sy / n
end

local function bbox(points)
  local x0, y0, x1, y1 = points[1], points[2], points[1], points[2]
  for i = 3, #points - 1, 2 do
    local x, y = points[i], points[i + 1]
    if x < x0 then x0 = x elseif x > x1 then x1 = x end
    if y < y0 then y0 = y elseif y > y1 then y1 = y end
  end
  return x0, y0, x1, y1
end

---------------------------------------------------------------------------------------------
-- Polygon sets (shape "p": one argument, the points)
---------------------------------------------------------------------------------------------
-- Ordinary scene polygons: 4 to 16 vertices, half convex, half star-shaped, near the origin.
function W.ordinary(count)
  local list = {}
  for i = 1, count do
    local n = 4 + (i - 1) % 13
    local cx, cy = uniform(-100, 100), uniform(-100, 100)
    if i % 2 == 1 then
      local a = uniform(5, 50)
      list[i] = ellipse(n, cx, cy, a, a * uniform(0.3, 1), 0.6)
    else
      list[i] = star(n, cx, cy, uniform(5, 50))
    end
  end
  return list
end

function W.translated(list, dx, dy)
  local out = {}
  for i = 1, #list do out[i] = translate(list[i], dx, dy) end
  return out
end

local function rotateStart(points)
  local n = #points / 2
  local k = randint(0, n - 1)
  local out = {}
  for i = 0, n - 1 do
    local j = (i + k) % n
    out[2 * i + 1], out[2 * i + 2] = points[2 * j + 1], points[2 * j + 2]
  end
  return out
end

-- Near-degenerate: a third Kettner et al.'s ulp grid triangles (a vertex moved by single ulps
-- near the line through (12, 12) and (24, 24)), a third near-collinear 3 to 5 gons whose y is
-- moved by up to 2 ulps, a third convex polygons with an extra vertex within 2 ulps of the
-- midpoint of an edge.
function W.nearDegenerate(count)
  local list = {}
  local u = 2 ^ -53
  for i = 1, count do
    local kind = i % 3
    local pts
    if kind == 0 then
      pts = { 0.5 + randint(0, 63) * u, 0.5 + randint(0, 63) * u, 12.0, 12.0, 24.0, 24.0 }
    elseif kind == 1 then
      local m = randint(3, 5)
      local x0, y0, t = uniform(-100, 100), uniform(-100, 100), uniform(0, 2 * pi)
      local dx, dy = cos(t), sin(t)
      pts = {}
      for _ = 1, m do
        local s = uniform(0, 30)
        local x, y = x0 + s * dx, y0 + s * dy
        pts[#pts + 1] = x
        pts[#pts + 1] = y + randint(-2, 2) * ulp(y)
      end
    else
      local base = ellipse(randint(5, 9), uniform(-100, 100), uniform(-100, 100),
                           uniform(5, 50), uniform(5, 50), 0.5)
      local k = 2 * randint(0, #base / 2 - 1) + 1
      local l = k + 2 <= #base and k + 2 or 1
      local mx, my = (base[k] + base[l]) * 0.5, (base[k + 1] + base[l + 1]) * 0.5
      mx = mx + randint(-2, 2) * ulp(mx)
      my = my + randint(-2, 2) * ulp(my)
      pts = {}
      for j = 1, #base do
        pts[#pts + 1] = base[j]
        if j == k + 1 then pts[#pts + 1] = mx; pts[#pts + 1] = my end
      end
    end
    list[i] = randomOrientation(rotateStart(pts))
  end
  return list
end

function W.large(n, count)
  local list = {}
  for i = 1, count do
    if i % 2 == 1 then
      list[i] = ellipse(n, 300 + uniform(-50, 50), 200 + uniform(-50, 50), 1000, 700, 0.3)
    else
      list[i] = star(n, 300 + uniform(-50, 50), 200 + uniform(-50, 50), 1000)
    end
  end
  return list
end

---------------------------------------------------------------------------------------------
-- Point queries (shape "pxy": points, x, y)
---------------------------------------------------------------------------------------------
function W.queriesInBox(polys, perPoly)
  local P, X, Y = {}, {}, {}
  for _, poly in ipairs(polys) do
    local x0, y0, x1, y1 = bbox(poly)
    local mx, my = (x1 - x0) * 0.1, (y1 - y0) * 0.1
    for _ = 1, perPoly do
      P[#P + 1] = poly
      X[#X + 1] = uniform(x0 - mx, x1 + mx)
      Y[#Y + 1] = uniform(y0 - my, y1 + my)
    end
  end
  return { P, X, Y }
end

-- Points on or within 3 ulps of edges, vertices, and rays through vertices.
function W.queriesNearEdges(polys, perPoly)
  local P, X, Y = {}, {}, {}
  for _, poly in ipairs(polys) do
    local nv = #poly / 2
    for _ = 1, perPoly do
      local k = 2 * randint(0, nv - 1) + 1
      local l = k + 2 <= #poly and k + 2 or 1
      local r = rand()
      local x, y
      if r < 0.2 then
        x, y = poly[k], poly[k + 1]
      elseif r < 0.3 then
        local x0, _, x1 = bbox(poly)
        x, y = uniform(x0, x1), poly[k + 1]
      else
        local t = rnd()
        x = poly[k] + t * (poly[l] - poly[k])
        y = poly[k + 1] + t * (poly[l + 1] - poly[k + 1])
        x = x + randint(-3, 3) * ulp(x)
      end
      P[#P + 1], X[#X + 1], Y[#Y + 1] = poly, x, y
    end
  end
  return { P, X, Y }
end

-- A jittered grid of quadrilateral tiles; queries on shared edges and shared corners, each
-- asked of every tile that touches it.
function W.tiles(g)
  local V = {}
  for i = 0, g do
    V[i] = {}
    for j = 0, g do V[i][j] = { 10 * i + uniform(-3, 3), 10 * j + uniform(-3, 3) } end
  end
  local T = {}
  for i = 0, g - 1 do
    T[i] = {}
    for j = 0, g - 1 do
      local a, b, c, d = V[i][j], V[i + 1][j], V[i + 1][j + 1], V[i][j + 1]
      T[i][j] = { a[1], a[2], b[1], b[2], c[1], c[2], d[1], d[2] }
    end
  end
  local P, X, Y = {}, {}, {}
  local function ask(tile, x, y) P[#P + 1], X[#X + 1], Y[#Y + 1] = tile, x, y end
  for i = 1, g - 1 do
    for j = 0, g - 1 do
      for _ = 1, 3 do       -- vertical edge V[i][j] - V[i][j+1] between T[i-1][j] and T[i][j]
        local a, b, t = V[i][j], V[i][j + 1], rnd()
        local x, y = a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])
        ask(T[i - 1][j], x, y); ask(T[i][j], x, y)
        a, b = V[j][i], V[j + 1][i]   -- horizontal edge between T[j][i-1] and T[j][i]
        x, y = a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])
        ask(T[j][i - 1], x, y); ask(T[j][i], x, y)
      end
    end
  end
  for i = 1, g - 1 do
    for j = 1, g - 1 do
      local v = V[i][j]
      ask(T[i - 1][j - 1], v[1], v[2]); ask(T[i][j - 1], v[1], v[2])
      ask(T[i - 1][j], v[1], v[2]); ask(T[i][j], v[1], v[2])
    end
  end
  return { P, X, Y }
end

function W.translatedQueries(q, dx, dy)
  local P, X, Y = {}, {}, {}
  local moved = {}
  for i = 1, #q[1] do
    local poly = q[1][i]
    moved[poly] = moved[poly] or translate(poly, dx, dy)
    P[i], X[i], Y[i] = moved[poly], q[2][i] + dx, q[3][i] + dy
  end
  return { P, X, Y }
end

---------------------------------------------------------------------------------------------
-- Polygon pairs (shape "pp"), convex, 6 to 8 vertices
---------------------------------------------------------------------------------------------
local function convex68(cx, cy, a)
  a = a or uniform(5, 30)
  local b = a * uniform(0.5, 1)
  return ellipse(randint(6, 8), cx, cy, a, b, 0.5), a, b
end

local function maybeSwap(A, B)
  if rand() < 0.5 then return B, A end
  return A, B
end

function W.pairOverlap()
  local cx, cy = uniform(-100, 100), uniform(-100, 100)
  local A, _, bA = convex68(cx, cy)
  local t, d = uniform(0, 2 * pi), uniform(0, 0.9) * bA
  return maybeSwap(A, translate(convex68(0, 0), cx + d * cos(t), cy + d * sin(t)))
end

function W.pairMiss()
  local cx, cy = uniform(-100, 100), uniform(-100, 100)
  local A, aA = convex68(cx, cy)
  local B, aB = convex68(0, 0)
  local t, d = uniform(0, 2 * pi), (aA + aB) * uniform(1.02, 1.4)
  return maybeSwap(A, translate(B, cx + d * cos(t), cy + d * sin(t)))
end

local GRID = 2 ^ 30
local function onGrid(v) return floor(v * GRID + 0.5) / GRID end
local function gridded(points)
  local out = {}
  for i = 1, #points do out[i] = onGrid(points[i]) end
  return out
end

-- Exactly touching, in turn: B shares an edge of A (B lies on the outer side); B is A mirrored
-- through one of A's vertices (they share that corner only); B has a vertex exactly on an edge
-- of A (a T contact; both on a 2^-30 grid so that the contact point is a double).
local touchKind = 0
function W.pairTouch()
  local A = convex68(uniform(-100, 100), uniform(-100, 100))
  local nv = #A / 2
  local k = 2 * randint(0, nv - 1) + 1
  local px, py = A[k], A[k + 1]
  local B = {}
  touchKind = touchKind % 3 + 1
  if touchKind == 3 then
    A = gridded(A)
    px, py = A[k], A[k + 1]
    local l = k + 2 <= #A and k + 2 or 1
    local qx, qy = A[l], A[l + 1]
    local mx, my = mean(A)
    -- contact at t = k/1024 along the edge: exact on the grid (38 + 10 bits), and unlike the
    -- midpoint its rounded projections differ from those of the edge's ends
    local t = randint(1, 1023) / 1024
    if t == 0.5 then t = 0.25 end
    local cx, cy = px + t * (qx - px), py + t * (qy - py)
    local nx, ny = qy - py, px - qx
    if nx * (mx - cx) + ny * (my - cy) > 0 then nx, ny = -nx, -ny end
    local len = sqrt(nx * nx + ny * ny)
    nx, ny = nx / len, ny / len
    local r = uniform(3, 20)
    local ox, oy = cx + r * nx, cy + r * ny       -- B is inscribed in the circle (o, r) through c
    local m = randint(5, 7)
    B[1], B[2] = cx, cy
    for j = 1, m do
      local phi = (20 + 320 * (j - 1) / (m - 1) + 8 * (rnd() - 0.5)) * pi / 180
      local c, s = cos(phi), sin(phi)
      B[#B + 1] = onGrid(ox - r * (nx * c - ny * s))
      B[#B + 1] = onGrid(oy - r * (nx * s + ny * c))
    end
  elseif touchKind == 1 then
    local l = k + 2 <= #A and k + 2 or 1
    local qx, qy = A[l], A[l + 1]
    local mx, my = mean(A)
    local nx, ny = qy - py, px - qx
    if nx * (mx - px) + ny * (my - py) > 0 then nx, ny = -nx, -ny end
    local len = sqrt(nx * nx + ny * ny)
    nx, ny = nx / len, ny / len
    -- contact at t = k/1024 along the edge: exact on the grid (38 + 10 bits), and unlike the
    -- midpoint its rounded projections differ from those of the edge's ends
    local t = randint(1, 1023) / 1024
    if t == 0.5 then t = 0.25 end
    local cx, cy = px + t * (qx - px), py + t * (qy - py)
    local h = len * 0.5 * uniform(0.5, 1.5)
    local m = randint(4, 6)
    B[1], B[2] = px, py
    for j = 1, m do
      local s = (0.12 + 0.76 * (j - 1) / (m - 1) + 0.04 * (rnd() - 0.5)) * pi
      B[#B + 1] = cx + cos(s) * (px - cx) + sin(s) * h * nx
      B[#B + 1] = cy + cos(s) * (py - cy) + sin(s) * h * ny
    end
    B[#B + 1], B[#B + 2] = qx, qy
  else
    local lambda = uniform(0.5, 1.5)
    for i = 1, #A - 1, 2 do
      if i == k then
        B[i], B[i + 1] = px, py
      else
        B[i], B[i + 1] = px + lambda * (px - A[i]), py + lambda * (py - A[i + 1])
      end
    end
  end
  return maybeSwap(A, B)
end

-- One polygon well inside the other (the tutorial's overlap is then not the depth).
function W.pairInside()
  local cx, cy = uniform(-100, 100), uniform(-100, 100)
  local A, _, bA = convex68(cx, cy, uniform(20, 30))
  local B = convex68(cx + uniform(-0.2, 0.2) * bA, cy + uniform(-0.2, 0.2) * bA, 0.15 * bA)
  return maybeSwap(A, B)
end

function W.pairs(count, makers)
  local A, B = {}, {}
  for i = 1, count do
    A[i], B[i] = makers[(i - 1) % #makers + 1]()
  end
  return { A, B }
end

function W.translatedPairs(p, dx, dy)
  return { W.translated(p[1], dx, dy), W.translated(p[2], dx, dy) }
end

---------------------------------------------------------------------------------------------
-- Circles around convex polygons (shape "pxyr": points, cx, cy, r)
---------------------------------------------------------------------------------------------
-- kinds: 1 touching an edge, 2 in a vertex region, 3 missing, 4 deep inside
function W.circles(count, kinds)
  local P, X, Y, R = {}, {}, {}, {}
  for i = 1, count do
    local kind = kinds[(i - 1) % #kinds + 1]
    local n = 4 + (i - 1) % 13
    local a = uniform(10, 50)
    local poly = ellipse(n, uniform(-100, 100), uniform(-100, 100), a, a * uniform(0.5, 1), 0.5)
    local mx, my = mean(poly)
    local r = uniform(2, 20)
    local k = 2 * randint(0, n - 1) + 1
    local l = k + 2 <= #poly and k + 2 or 1
    local cx, cy
    if kind == 1 then
      local t = uniform(0.2, 0.8)
      local ex, ey = poly[k] + t * (poly[l] - poly[k]), poly[k + 1] + t * (poly[l + 1] - poly[k + 1])
      local nx, ny = poly[l + 1] - poly[k + 1], poly[k] - poly[l]
      if nx * (mx - ex) + ny * (my - ey) > 0 then nx, ny = -nx, -ny end
      local len, d = sqrt(nx * nx + ny * ny), r * uniform(0.3, 0.95)
      cx, cy = ex + nx / len * d, ey + ny / len * d
    elseif kind == 2 then
      local dx, dy = poly[k] - mx, poly[k + 1] - my
      local len, d = sqrt(dx * dx + dy * dy), r * uniform(0.3, 0.95)
      cx, cy = poly[k] + dx / len * d, poly[k + 1] + dy / len * d
    elseif kind == 3 then
      local t, d = uniform(0, 2 * pi), a + r * uniform(1.1, 2)
      cx, cy = mx + d * cos(t), my + d * sin(t)
    else
      r = a * uniform(0.05, 0.2)
      cx, cy = mx + uniform(-0.2, 0.2) * a, my + uniform(-0.2, 0.2) * a
    end
    P[i], X[i], Y[i], R[i] = poly, cx, cy, r
  end
  return { P, X, Y, R }
end

function W.translatedCircles(c, dx, dy)
  local X, Y = {}, {}
  for i = 1, #c[2] do X[i], Y[i] = c[2][i] + dx, c[3][i] + dy end
  return { W.translated(c[1], dx, dy), X, Y, c[4] }
end

---------------------------------------------------------------------------------------------
-- Projections
---------------------------------------------------------------------------------------------
-- shape "proj": points, x, y, nx, ny with a vertex as reference and an edge normal as axis
function W.projections(polys)
  local P, X, Y, NX, NY = {}, {}, {}, {}, {}
  for i, poly in ipairs(polys) do
    local k = 2 * randint(0, #poly / 2 - 1) + 1
    local j = 2 * randint(0, #poly / 2 - 1) + 1
    local l = j + 2 <= #poly and j + 2 or 1
    P[i], X[i], Y[i] = poly, poly[k], poly[k + 1]
    NX[i], NY[i] = poly[l + 1] - poly[j + 1], poly[j] - poly[l]
  end
  return { P, X, Y, NX, NY }
end

-- shape "circ": cx, cy, r, x, y, nx, ny
function W.circleProjections(count)
  local A = { {}, {}, {}, {}, {}, {}, {} }
  for i = 1, count do
    local t = uniform(0, 2 * pi)
    local len = uniform(0.5, 50)
    A[1][i], A[2][i], A[3][i] = uniform(-100, 100), uniform(-100, 100), uniform(1, 20)
    A[4][i], A[5][i] = uniform(-100, 100), uniform(-100, 100)
    A[6][i], A[7][i] = len * cos(t), len * sin(t)
  end
  return A
end

return W
