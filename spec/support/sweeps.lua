--- Exact answers for the cast specs: when a convex polygon moving by t d, t in [0, 1], first
-- meets a static convex polygon's open interior, by real arithmetic on the given doubles
-- (spec/support/exact.lua). Shares no code and no method with polygon.lua: every time at which a
-- vertex of one polygon crosses the line of an edge of the other is a candidate; between two
-- consecutive candidates the pair either overlaps throughout or not at all, so the overlap is
-- tested once, at the midpoint, by the separating axis test on exact coordinates scaled by the
-- midpoint's denominator; the contact time is the candidate before the first overlapping piece.
-- Points are flat arrays {x1, y1, x2, y2, ...}.

local exact = require "exact"

local new, add, sub, mul, sign, compare, neg = exact.new, exact.add, exact.sub, exact.mul,
  exact.sign, exact.compare, exact.neg

local sweeps = {}

local EPS = 2 ^ -53

-- (b - a) x (c - a) for exact points {x, y}.
local function cross(a, b, c)
  return sub(mul(sub(b[1], a[1]), sub(c[2], a[2])), mul(sub(b[2], a[2]), sub(c[1], a[1])))
end

-- The sign of twice the signed area of a list of exact points.
local function areaSign(P)
  local terms = {}
  for i = 1, #P do
    local j = i % #P + 1
    terms[#terms + 1] = sub(mul(P[i][1], P[j][2]), mul(P[j][1], P[i][2]))
  end
  return sign(exact.sum(terms))
end

-- Whether the open interiors of the convex polygons P and Q (lists of exact points) meet: no
-- edge line of either has the other wholly on or beyond its outer side.
local function interiorsMeet(P, Q)
  local wp, wq = areaSign(P), areaSign(Q)
  if wp == 0 or wq == 0 then return false end
  for _, pair in ipairs({ { P, Q, wp }, { Q, P, wq } }) do
    local A, B, w = pair[1], pair[2], pair[3]
    for i = 1, #A do
      local a, b = A[i], A[i % #A + 1]
      if compare(a[1], b[1]) ~= 0 or compare(a[2], b[2]) ~= 0 then
        local separates = true
        for _, v in ipairs(B) do
          if sign(cross(a, b, v)) * w > 0 then separates = false; break end
        end
        if separates then return false end
      end
    end
  end
  return true
end

-- The exact points of a flat array.
local function points(flat)
  local P = {}
  for i = 1, #flat, 2 do P[#P + 1] = { new(flat[i]), new(flat[i + 1]) } end
  return P
end

-- P1 times den and P2 times den moved by num d: the pair at t = num / den (den > 0), scaled.
local function at(P1, P2, D, num, den)
  local A, B = {}, {}
  for i, p in ipairs(P1) do A[i] = { mul(p[1], den), mul(p[2], den) } end
  for i, p in ipairs(P2) do
    B[i] = { add(mul(p[1], den), mul(num, D[1])), add(mul(p[2], den), mul(num, D[2])) }
  end
  return A, B
end

-- Appends the times (num, den), den > 0, at which a vertex of `movers` (moving by s d) crosses
-- the line of an edge of `fixed`, s = +1 for P2's vertices against P1's edges, -1 for P1's
-- vertices against P2's edges (P2's edges move by t d: the same as P1 moving by -t d).
local function crossings(fixed, movers, D, s, out)
  for i = 1, #fixed do
    local p, q = fixed[i], fixed[i % #fixed + 1]
    local ex, ey = sub(q[1], p[1]), sub(q[2], p[2])
    local den = sub(mul(ex, D[2]), mul(ey, D[1]))   -- e x d
    if sign(den) ~= 0 then
      for _, v in ipairs(movers) do
        -- (v + t s d - p) lies on the line: e x (v - p) + t s (e x d) = 0
        local num = sub(mul(ex, sub(p[2], v[2])), mul(ey, sub(p[1], v[1])))   -- e x (p - v)
        local dd = s > 0 and den or neg(den)
        if sign(dd) < 0 then num, dd = neg(num), neg(dd) end
        out[#out + 1] = { num, dd }
      end
    end
  end
end

--- The contact of the convex polygon `moving` moved by t (dx, dy) with the convex polygon
-- `static`: nil (they never overlap for t in [0, 1]), "inside" (they overlap at t = 0), or
-- { num =, den = } with the contact time num / den (den > 0, exact values).
function sweeps.convexContact(static, moving, dx, dy)
  local P1, P2 = points(static), points(moving)
  local D = { new(dx), new(dy) }
  local ONE = new(1)
  if interiorsMeet(P1, P2) then return "inside" end
  local cuts = { { exact.ZERO, ONE }, { ONE, ONE } }
  crossings(P1, P2, D, 1, cuts)
  crossings(P2, P1, D, -1, cuts)
  local kept = {}
  for _, c in ipairs(cuts) do
    if sign(c[1]) >= 0 and compare(c[1], c[2]) <= 0 then kept[#kept + 1] = c end
  end
  table.sort(kept, function(u, v) return compare(mul(u[1], v[2]), mul(v[1], u[2])) < 0 end)
  local list = {}
  for _, c in ipairs(kept) do
    local last = list[#list]
    if not last or compare(mul(last[1], c[2]), mul(c[1], last[2])) ~= 0 then list[#list + 1] = c end
  end
  for k = 1, #list - 1 do
    local a, b = list[k], list[k + 1]
    -- the midpoint (na db + nb da) / (2 da db)
    local num = add(mul(a[1], b[2]), mul(b[1], a[2]))
    local den = mul(new(2), mul(a[2], b[2]))
    if interiorsMeet(at(P1, P2, D, num, den)) then return { num = a[1], den = a[2] } end
  end
  return nil
end

--- The same against a list of convex parts: the least contact over the parts ("inside" when any
-- part overlaps at t = 0).
function sweeps.partsContact(list, moving, dx, dy)
  local best
  for _, part in ipairs(list) do
    local c = sweeps.convexContact(part, moving, dx, dy)
    if c == "inside" then return "inside" end
    if c and (not best or compare(mul(c.num, best.den), mul(best.num, c.den)) < 0) then best = c end
  end
  return best
end

--- The unit normals, from `static` toward `moving`, of the edges along which the pair touches at
-- the contact c (edges of static with moving on their line, and moving's edges with static on
-- theirs, either entering: the motion takes the polygons toward each other across them), in
-- floating point.
function sweeps.contactNormals(static, moving, dx, dy, c)
  local P1, P2 = points(static), points(moving)
  local D = { new(dx), new(dy) }
  local A, B = at(P1, P2, D, c.num, c.den)
  local normals = {}
  for _, pair in ipairs({ { A, B, static, 1 }, { B, A, moving, -1 } }) do
    local X, Y, flat, s = pair[1], pair[2], pair[3], pair[4]
    local w = areaSign(X)
    for i = 1, #X do
      local j = i % #X + 1
      local p, q = X[i], X[j]
      -- the other wholly on or beyond the edge's line, touching it
      local deepest
      for _, v in ipairs(Y) do
        local side = sign(cross(p, q, v)) * w
        if not deepest or side > deepest then deepest = side end
      end
      local ex, ey = sub(q[1], p[1]), sub(q[2], p[2])
      local approach = sign(sub(mul(ex, D[2]), mul(ey, D[1]))) * w * s   -- > 0: moving in
      if deepest == 0 and approach > 0 then
        local px, py = flat[2 * i - 1], flat[2 * i]
        local qx, qy = flat[2 * j - 1], flat[2 * j]
        local fx, fy = qx - px, qy - py
        local len = math.sqrt(fx * fx + fy * fy)
        -- the outward normal w (ey, -ex), from static toward moving: s times it
        normals[#normals + 1] = { s * w * fy / len, -s * w * fx / len }
      end
    end
  end
  return normals
end

--- Whether the fraction f lies within 8 eps M / |d| of the exact contact c (M: the largest
-- magnitude among `magnitudes`): (f den - num)^2 |d|^2 <= (8 eps M den)^2, exactly.
function sweeps.fractionNear(f, c, dx, dy, M)
  local D = { new(dx), new(dy) }
  local gap = sub(mul(new(f), c.den), c.num)
  local lhs = mul(mul(gap, gap), add(mul(D[1], D[1]), mul(D[2], D[2])))
  local bound = mul(mul(new(8 * EPS), new(M)), c.den)
  return compare(lhs, mul(bound, bound)) <= 0
end

--- Whether f is no later than the contact c: f den <= num.
function sweeps.notAfter(f, c)
  return compare(mul(new(f), c.den), c.num) <= 0
end

--- The moving polygon moved by f (dx, dy) the way a game computes it: x + f * dx, rounded.
function sweeps.moveBy(moving, f, dx, dy)
  local out = {}
  for i = 1, #moving, 2 do
    out[i] = moving[i] + f * dx
    out[i + 1] = moving[i + 1] + f * dy
  end
  return out
end

--- Whether the open interiors of two convex polygons (flat arrays) meet, exactly.
function sweeps.overlap(a, b)
  return interiorsMeet(points(a), points(b))
end

-- Discs: the moving centre A + t d against C with R = r1 + r2: g(t) = Q t^2 + 2 P t + K, w = A - C,
-- Q = |d|^2, P = d.w, K = |w|^2 - R^2, all exact.
local function discTerms(x1, y1, r1, x2, y2, r2, dx, dy)
  local wx, wy = sub(new(x2), new(x1)), sub(new(y2), new(y1))
  local Dx, Dy = new(dx), new(dy)
  local R = add(new(r1), new(r2))
  return add(mul(Dx, Dx), mul(Dy, Dy)), add(mul(Dx, wx), mul(Dy, wy)),
    sub(add(mul(wx, wx), mul(wy, wy)), mul(R, R))
end

-- g(t) for the exact value of the double t.
local function discValue(Q, P, K, t)
  local T = new(t)
  return add(add(mul(Q, mul(T, T)), mul(mul(new(2), P), T)), K)
end

--- The moving disc (x2, y2, r2) + t (dx, dy) against the disc (x1, y1, r1): nil (no overlap for t
-- in [0, 1]), "inside" (overlapping at t = 0), or "enters".
function sweeps.discContact(x1, y1, r1, x2, y2, r2, dx, dy)
  local Q, P, K = discTerms(x1, y1, r1, x2, y2, r2, dx, dy)
  if sign(K) < 0 then return "inside" end
  if sign(discValue(Q, P, K, 1)) < 0 then return "enters" end
  -- the least of g at -P / Q inside (0, 1) below 0: P < 0, -P < Q, P^2 > Q K
  if sign(P) < 0 and compare(neg(P), Q) < 0 and compare(mul(P, P), mul(Q, K)) > 0 then return "enters" end
  return nil
end

--- Whether the fraction f is within b of the first root t_c of g (the disc's entry), b a double
-- at most 8 eps M / |d|: f - b < 0, or g(f - b) >= 0 with f - b before the vertex -P / Q (then
-- f - b <= t_c), and g(f + b) <= 0 or f + b past the vertex -P / Q.
function sweeps.discFractionNear(f, b, x1, y1, r1, x2, y2, r2, dx, dy)
  local Q, P, K = discTerms(x1, y1, r1, x2, y2, r2, dx, dy)
  local lo, hi = f - b, f + b
  if lo > 0 and (sign(discValue(Q, P, K, lo)) < 0 or compare(mul(new(lo), Q), neg(P)) > 0) then
    return false
  end
  if sign(discValue(Q, P, K, hi)) <= 0 then return true end
  return compare(mul(new(hi), Q), neg(P)) > 0   -- past the vertex: t_c <= vertex < hi
end

--- Whether the double t lies no later than the disc's entry: t <= 0, or g(t) > 0 with t before
-- the vertex -P / Q.
function sweeps.discBefore(t, x1, y1, r1, x2, y2, r2, dx, dy)
  if t <= 0 then return true end
  local Q, P, K = discTerms(x1, y1, r1, x2, y2, r2, dx, dy)
  return sign(discValue(Q, P, K, t)) > 0 and compare(mul(new(t), Q), neg(P)) <= 0
end

-- A moving disc against a convex polygon: the centre X(t) = C + t d and the squared distance
-- D(t) from X(t) to the closed polygon, which is convex in t (the distance to a convex set is
-- convex). D is a quadratic between the times where X crosses an edge's line or the line through
-- an edge's end perpendicular to it (where its nearest feature changes); within such a piece it
-- is least at an end, or (nearest a vertex v) where X is nearest v. So the least of D over
-- [0, T] is its least at those candidate times, each a rational num / den, and D at a rational
-- time is a rational (the polygon's points and X scaled by den): the disc meets the polygon's
-- interior (D < r^2) somewhere in [0, T] exactly when it does at a candidate. Nothing here is
-- the library's method (it works from the move's end and swept point, with no candidate times).

-- Whether D(num / den) < r^2 (den > 0): X den = C den + num d against the polygon scaled by den.
local function discMeetsAt(P, w, C, D, R, num, den)
  local X = { add(mul(C[1], den), mul(num, D[1])), add(mul(C[2], den), mul(num, D[2])) }
  local rr = mul(mul(R, R), mul(den, den))
  local inside = true
  for i = 1, #P do
    local a, b = P[i], P[i % #P + 1]
    local ad, bd = { mul(a[1], den), mul(a[2], den) }, { mul(b[1], den), mul(b[2], den) }
    local ex, ey = sub(b[1], a[1]), sub(b[2], a[2])
    local ux, uy = sub(X[1], ad[1]), sub(X[2], ad[2])
    local side = sign(sub(mul(ex, uy), mul(ey, ux))) * w
    if side < 0 then inside = false end
    if sign(ex) ~= 0 or sign(ey) ~= 0 then
      local along = add(mul(ux, ex), mul(uy, ey))   -- (X - a den).e
      local lengthSq = add(mul(ex, ex), mul(ey, ey))
      if sign(along) <= 0 then
        if compare(add(mul(ux, ux), mul(uy, uy)), rr) < 0 then return true end
      elseif compare(along, mul(lengthSq, den)) >= 0 then
        local vx, vy = sub(X[1], bd[1]), sub(X[2], bd[2])
        if compare(add(mul(vx, vx), mul(vy, vy)), rr) < 0 then return true end
      else
        local c = sub(mul(ex, uy), mul(ey, ux))
        if compare(mul(c, c), mul(rr, lengthSq)) < 0 then return true end
      end
    end
  end
  return inside
end

-- Appends num / den (den > 0) when den ~= 0.
local function candidate(out, num, den)
  if sign(den) == 0 then return end
  if sign(den) < 0 then num, den = neg(num), neg(den) end
  out[#out + 1] = { num, den }
end

-- Whether the disc (cx, cy, r) moved by t (dx, dy) meets the convex polygon `flat`'s open
-- interior for some t in [0, T], T = t1 + t2 (exact sum of two doubles >= 0 in all).
local function discReachConvex(flat, cx, cy, r, dx, dy, t1, t2)
  local P = points(flat)
  local w = areaSign(P)
  if w == 0 then return false end
  local C, D, R = { new(cx), new(cy) }, { new(dx), new(dy) }, new(r)
  local ONE = new(1)
  local T = add(new(t1), new(t2))
  local times = { { exact.ZERO, ONE }, { T, ONE } }
  local dd = add(mul(D[1], D[1]), mul(D[2], D[2]))
  for i = 1, #P do
    local a, b = P[i], P[i % #P + 1]
    local ex, ey = sub(b[1], a[1]), sub(b[2], a[2])
    -- the edge's line: e x (C + t d - a) = 0
    candidate(times, sub(mul(ex, sub(a[2], C[2])), mul(ey, sub(a[1], C[1]))),
      sub(mul(ex, D[2]), mul(ey, D[1])))
    -- the perpendiculars at a and b: (C + t d - p).e = 0
    local de = add(mul(D[1], ex), mul(D[2], ey))
    for _, p in ipairs({ a, b }) do
      candidate(times, add(mul(sub(p[1], C[1]), ex), mul(sub(p[2], C[2]), ey)), de)
    end
    -- nearest the vertex a: (C + t d - a).d = 0
    candidate(times, add(mul(sub(a[1], C[1]), D[1]), mul(sub(a[2], C[2]), D[2])), dd)
  end
  for _, c in ipairs(times) do
    -- within [0, T]: num >= 0 and num <= T den
    if sign(c[1]) >= 0 and compare(c[1], mul(T, c[2])) <= 0 and discMeetsAt(P, w, C, D, R, c[1], c[2]) then
      return true
    end
  end
  return false
end

--- Whether the disc (cx, cy, r) moved by t (dx, dy) meets the open interior of `static` (a convex
-- polygon or a list of convex parts, flat arrays) for some t in [0, t1 + t2] (t1, t2 doubles,
-- summed exactly; t2 defaults to 0): t1 = 1 asks whether the move hits, t1 = 0 whether it
-- starts colliding.
function sweeps.discReach(static, cx, cy, r, dx, dy, t1, t2)
  t2 = t2 or 0
  for _, part in ipairs(type(static[1]) == "table" and static or { static }) do
    if discReachConvex(part, cx, cy, r, dx, dy, t1, t2) then return true end
  end
  return false
end

return sweeps
