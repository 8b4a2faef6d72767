--- Exact answers for the ray specs: where a segment first enters a shape's open interior, by real
-- arithmetic on the given doubles (spec/support/exact.lua). Shares no code and no method with
-- polygon.lua: a convex polygon by Cyrus and Beck's parametric clipping (one rational bound per
-- edge), a region bounded by rings (a concave outline, holes: what a list of parts covers) by
-- cutting the segment at every point where it meets a ring and testing a point of each piece
-- with the crossing rule, and a disc by the quadratic |A + t d - C|^2 = r^2.
-- Points are flat arrays {x1, y1, x2, y2, ...}; the segment is A + t (B - A), t in [0, 1].

local exact = require "exact"

local new, add, sub, mul, sign, compare = exact.new, exact.add, exact.sub, exact.mul, exact.sign,
  exact.compare

local rays = {}

local EPS = 2 ^ -53

-- (b - a) x (c - a) for exact values.
local function cross(ax, ay, bx, by, cx, cy)
  return sub(mul(sub(bx, ax), sub(cy, ay)), mul(sub(by, ay), sub(cx, ax)))
end

-- The exact shoelace sum's sign of a flat array: > 0 clockwise on screen (y down).
local function areaSign(points)
  local n = #points / 2
  local terms = {}
  for i = 1, n do
    local j = i % n + 1
    terms[#terms + 1] = mul(new(points[2 * i - 1]), new(points[2 * j]))
    terms[#terms + 1] = exact.neg(mul(new(points[2 * j - 1]), new(points[2 * i])))
  end
  return sign(exact.sum(terms))
end
rays.areaSign = areaSign

-- The unit outward normal of the edge p -> q of a ring whose region lies on the side where
-- side * (q - p) x (v - p) > 0, in floating point (each component within an ulp or two).
local function outwardNormal(px, py, qx, qy, side)
  local ex, ey = qx - px, qy - py
  local len = math.sqrt(ex * ex + ey * ey)
  return side * ey / len, -side * ex / len
end
rays.outwardNormal = outwardNormal

--- The entry of the segment A -> B into the open interior of the convex polygon `points`:
-- nil for a miss, "inside" when A lies strictly inside, else { num =, den =, normals = } with the
-- fraction num / den (den > 0, exact values) and the unit outward normals of the edges entered
-- there (two at a vertex). Cyrus-Beck: with w the area sign, edge i bounds the interior by
-- s_i(t) = a_i + t b_i > 0, a_i = w (q - p) x (A - p), b_i = w (q - p) x d.
function rays.convexEntry(points, ax, ay, bx, by)
  local w = areaSign(points)
  if w == 0 then return nil end
  local n = #points / 2
  local A = { new(ax), new(ay) }
  local d = { sub(new(bx), A[1]), sub(new(by), A[2]) }
  local loNum, loDen, loEdges = nil, nil, {}   -- the entry bound -a/b, largest
  local hiNum, hiDen = nil, nil                -- the exit bound, least
  local W = new(w)
  for i = 1, n do
    local j = i % n + 1
    local px, py, qx, qy = points[2 * i - 1], points[2 * i], points[2 * j - 1], points[2 * j]
    if px ~= qx or py ~= qy then
      local Px, Py, Qx, Qy = new(px), new(py), new(qx), new(qy)
      local a = mul(W, cross(Px, Py, Qx, Qy, A[1], A[2]))
      local b = mul(W, sub(mul(sub(Qx, Px), d[2]), mul(sub(Qy, Py), d[1])))
      local sb = sign(b)
      if sb == 0 then
        if sign(a) <= 0 then return nil end
      elseif sb > 0 then   -- t > -a / b: compare -a / b with the bound so far as fractions
        local num, den = exact.neg(a), b
        local c = loNum and compare(mul(num, loDen), mul(loNum, den)) or 1
        if c > 0 then loNum, loDen, loEdges = num, den, { i } elseif c == 0 then loEdges[#loEdges + 1] = i end
      else                 -- t < a / -b
        local num, den = a, exact.neg(b)
        if not hiNum or compare(mul(num, hiDen), mul(hiNum, den)) < 0 then hiNum, hiDen = num, den end
      end
    end
  end
  -- the open interval (lo, hi) of t inside, against [0, 1]
  if loNum and hiNum and compare(mul(loNum, hiDen), mul(hiNum, loDen)) >= 0 then return nil end
  if loNum and compare(loNum, loDen) >= 0 then return nil end   -- lo >= 1
  if hiNum and sign(hiNum) <= 0 then return nil end              -- hi <= 0
  if not loNum then return nil end   -- (a bounded polygon always has an entry bound for d ~= 0)
  if sign(loNum) < 0 then return "inside" end
  local normals = {}
  for _, i in ipairs(loEdges) do
    local j = i % n + 1
    normals[#normals + 1] = { outwardNormal(points[2 * i - 1], points[2 * i], points[2 * j - 1],
      points[2 * j], w) }
  end
  return { num = loNum, den = loDen, normals = normals }
end

--- Whether the point A lies strictly inside the convex polygon (for segments of no length).
function rays.convexInside(points, x, y)
  local w = areaSign(points)
  if w == 0 then return false end
  local n = #points / 2
  for i = 1, n do
    local j = i % n + 1
    local px, py, qx, qy = points[2 * i - 1], points[2 * i], points[2 * j - 1], points[2 * j]
    if (px ~= qx or py ~= qy) and
        sign(cross(new(px), new(py), new(qx), new(qy), new(x), new(y))) * w <= 0 then
      return false
    end
  end
  return true
end

-- Rings. A point given as (m A + k d) / m, m > 0 (k, m exact), is tested without division:
-- its coordinates X = m Ax + k dx, Y = m Ay + k dy over m.

-- The sign of (q - p) x (point - p) for the point (X, Y) / m.
local function sideOf(px, py, qx, qy, X, Y, m)
  local Px, Py = new(px), new(py)
  return sign(sub(mul(sub(new(qx), Px), sub(Y, mul(m, Py))), mul(sub(new(qy), Py), sub(X, mul(m, Px)))))
end

-- Whether the point (X, Y) / m lies on the closed edge p -> q.
local function onEdge(px, py, qx, qy, X, Y, m)
  if sideOf(px, py, qx, qy, X, Y, m) ~= 0 then return false end
  local lo, hi = math.min(px, qx), math.max(px, qx)
  local x0, x1 = compare(X, mul(m, new(lo))), compare(X, mul(m, new(hi)))
  lo, hi = math.min(py, qy), math.max(py, qy)
  local y0, y1 = compare(Y, mul(m, new(lo))), compare(Y, mul(m, new(hi)))
  return x0 >= 0 and x1 <= 0 and y0 >= 0 and y1 <= 0
end

-- The crossing rule for the point (X, Y) / m over every ring: odd is inside (even-odd).
local function crossingParity(rings, X, Y, m)
  local inside = false
  for _, ring in ipairs(rings) do
    local n = #ring / 2
    for i = 1, n do
      local j = i % n + 1
      local x1, y1, x2, y2 = ring[2 * i - 1], ring[2 * i], ring[2 * j - 1], ring[2 * j]
      local up1, up2 = compare(mul(m, new(y1)), Y) >= 0, compare(mul(m, new(y2)), Y) >= 0
      if up1 ~= up2 then
        -- the edge's x at the point's height is right of the point
        local s = sideOf(x1, y1, x2, y2, X, Y, m)
        if (y2 > y1 and s > 0) or (y2 < y1 and s < 0) then inside = not inside end
      end
    end
  end
  return inside
end

-- The parameters (num, den), den > 0, where the segment meets the edge p -> q: a crossing, or
-- the ends of a stretch along it (ends of the edge on the segment's line, and A and B are
-- added by the caller).
local function meetings(px, py, qx, qy, A, d, out)
  local Px, Py, Qx, Qy = new(px), new(py), new(qx), new(qy)
  local ex, ey = sub(Qx, Px), sub(Qy, Py)
  local den = sub(mul(d[1], ey), mul(d[2], ex))   -- d x e
  if sign(den) == 0 then
    -- parallel: on the same line, the edge's ends give the pieces' ends
    if sign(cross(A[1], A[2], add(A[1], d[1]), add(A[2], d[2]), Px, Py)) == 0 then
      local dd = add(mul(d[1], d[1]), mul(d[2], d[2]))
      for _, V in ipairs({ { Px, Py }, { Qx, Qy } }) do
        local num = add(mul(sub(V[1], A[1]), d[1]), mul(sub(V[2], A[2]), d[2]))
        out[#out + 1] = { num, dd }
      end
    end
    return
  end
  -- A + t d = P + s e: t = ((P - A) x e) / (d x e)
  local num = sub(mul(sub(Px, A[1]), ey), mul(sub(Py, A[2]), ex))
  if sign(den) < 0 then num, den = exact.neg(num), exact.neg(den) end
  out[#out + 1] = { num, den }
end

--- The entry of the segment A -> B into the open region bounded by `rings` (even-odd), as
-- rays.convexEntry answers (normals: of every ring edge through the entry point, outward from
-- the region). sides[r]: the region lies where sides[r] (q - p) x (v - p) > 0 along ring r; by
-- default rings[1] is the outline and the others holes.
function rays.ringsEntry(rings, ax, ay, bx, by, sides)
  local A = { new(ax), new(ay) }
  local d = { sub(new(bx), A[1]), sub(new(by), A[2]) }
  local ONE = new(1)
  local cuts = { { exact.ZERO, ONE }, { ONE, ONE } }
  for _, ring in ipairs(rings) do
    local n = #ring / 2
    for i = 1, n do
      local j = i % n + 1
      meetings(ring[2 * i - 1], ring[2 * i], ring[2 * j - 1], ring[2 * j], A, d, cuts)
    end
  end
  -- the cuts in [0, 1], sorted, without repeats
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
  -- whether the point at t = num / den is strictly inside the region
  local function interior(num, den)
    local X, Y = add(mul(den, A[1]), mul(num, d[1])), add(mul(den, A[2]), mul(num, d[2]))
    for _, ring in ipairs(rings) do
      local n = #ring / 2
      for i = 1, n do
        local j = i % n + 1
        if onEdge(ring[2 * i - 1], ring[2 * i], ring[2 * j - 1], ring[2 * j], X, Y, den) then
          return false
        end
      end
    end
    return crossingParity(rings, X, Y, den)
  end
  if interior(exact.ZERO, ONE) then return "inside" end
  for k = 1, #list - 1 do
    local u, v = list[k], list[k + 1]
    -- the middle of the piece: (u1 v2 + v1 u2) / (2 u2 v2)
    local num = add(mul(u[1], v[2]), mul(v[1], u[2]))
    local den = mul(new(2), mul(u[2], v[2]))
    if interior(num, den) then
      -- the entry point u and the ring edges through it
      local X, Y = add(mul(u[2], A[1]), mul(u[1], d[1])), add(mul(u[2], A[2]), mul(u[1], d[2]))
      local normals = {}
      for r, ring in ipairs(rings) do
        local w = areaSign(ring)
        local side = sides and sides[r] or (r == 1 and w or -w)
        local n = #ring / 2
        for i = 1, n do
          local j = i % n + 1
          local px, py, qx, qy = ring[2 * i - 1], ring[2 * i], ring[2 * j - 1], ring[2 * j]
          if (px ~= qx or py ~= qy) and onEdge(px, py, qx, qy, X, Y, u[2]) then
            normals[#normals + 1] = { outwardNormal(px, py, qx, qy, side) }
          end
        end
      end
      return { num = u[1], den = u[2], normals = normals }
    end
  end
  return nil
end

--- Whether the fraction f (a double) is within 8 eps M of the exact entry num / den along the
-- segment: |f - t| |d| <= 8 eps M, squared: (f den - num)^2 |d|^2 <= (8 eps M den)^2. M: the
-- largest coordinate magnitude of A and B.
function rays.fractionGood(f, entry, ax, ay, bx, by)
  local M = math.max(math.abs(ax), math.abs(ay), math.abs(bx), math.abs(by))
  local dx, dy = sub(new(bx), new(ax)), sub(new(by), new(ay))
  local gap = sub(mul(new(f), entry.den), entry.num)
  local lhs = mul(mul(gap, gap), add(mul(dx, dx), mul(dy, dy)))
  local bound = mul(mul(new(8 * EPS), new(M)), entry.den)
  return compare(lhs, mul(bound, bound)) <= 0
end

--- Whether (nx, ny) is one of the normals, each component within 16 eps.
function rays.normalGood(nx, ny, normals)
  for _, m in ipairs(normals) do
    if math.abs(nx - m[1]) <= 16 * EPS and math.abs(ny - m[2]) <= 16 * EPS then return true end
  end
  return false
end

-- Discs: with w = A - C, f(t) = Q t^2 + 2 P t + K, Q = |d|^2, P = d.w, K = |w|^2 - r^2.
local function quadratic(cx, cy, r, ax, ay, bx, by)
  local wx, wy = sub(new(ax), new(cx)), sub(new(ay), new(cy))
  local dx, dy = sub(new(bx), new(ax)), sub(new(by), new(ay))
  local R = new(r)
  return add(mul(dx, dx), mul(dy, dy)), add(mul(dx, wx), mul(dy, wy)),
    sub(add(mul(wx, wx), mul(wy, wy)), mul(R, R)), dx, dy, wx, wy
end

--- The segment against the open disc: nil (a miss), "inside" (A strictly inside) or "enters".
function rays.discMeets(cx, cy, r, ax, ay, bx, by)
  local Q, P, K = quadratic(cx, cy, r, ax, ay, bx, by)
  if sign(K) < 0 then return "inside" end
  if sign(Q) == 0 then return nil end
  -- f(1) = Q + 2 P + K < 0, or the least of f inside (0, 1) (at -P / Q) below 0: Q K < P^2
  if sign(add(add(Q, mul(new(2), P)), K)) < 0 then return "enters" end
  if sign(P) < 0 and compare(exact.neg(P), Q) < 0 and compare(mul(Q, K), mul(P, P)) < 0 then
    return "enters"
  end
  return nil
end

--- Whether the fraction f and normal (nx, ny) of an entry into the disc are good: f within
-- 8 eps M of the entry along the segment (M over A and B), by the quadratic's signs at
-- f -/+ delta (delta a double below 8 eps M / |d|); the normal within 8 eps of (Z - C) / r,
-- Z the exact entry, from a bracket of sqrt(G), G = P^2 - Q K, around which the normal's
-- components are linear.
function rays.discEntryGood(f, nx, ny, cx, cy, r, ax, ay, bx, by)
  local Q, P, K, dx, dy, wx, wy = quadratic(cx, cy, r, ax, ay, bx, by)
  local M = math.max(math.abs(ax), math.abs(ay), math.abs(bx), math.abs(by))
  local ddx, ddy = bx - ax, by - ay
  local length = math.sqrt(ddx * ddx + ddy * ddy) * (1 + 2 ^ -40)
  assert(compare(new(length * length), Q) >= 0)
  local delta = 8 * EPS * M / length * (1 - 2 ^ -40)
  local function at(t)   -- f(t) for a double t
    local T = new(t)
    return add(add(mul(Q, mul(T, T)), mul(new(2), mul(P, T))), K)
  end
  local tMin = exact.neg(P)   -- the least of f at tMin / Q
  local lo, hi = f - delta, f + delta
  local okLo = lo <= 0 or (compare(mul(new(lo), Q), tMin) < 0 and sign(at(lo)) >= 0)
  local okHi = compare(mul(new(hi), Q), tMin) >= 0 or sign(at(hi)) <= 0
  if not (okLo and okHi) then return false, "fraction" end
  -- the normal: (X (-dy, dx) - s d) / (r Q), X = d x w, s = sqrt(G), s in [s0, s1]
  local G = sub(mul(P, P), mul(Q, K))
  local s = math.sqrt(exact.tonumber(G))
  local s0, s1 = s * (1 - 2 ^ -51), s * (1 + 2 ^ -51)
  assert(compare(mul(new(s0), new(s0)), G) <= 0 and compare(mul(new(s1), new(s1)), G) >= 0)
  local X = sub(mul(dx, wy), mul(dy, wx))
  local rQ = mul(new(r), Q)
  local good = true
  for _, sv in ipairs({ s0, s1 }) do
    local S = new(sv)
    local ex = exact.tonumber(sub(exact.neg(mul(X, dy)), mul(S, dx))) / exact.tonumber(rQ)
    local ey = exact.tonumber(sub(mul(X, dx), mul(S, dy))) / exact.tonumber(rQ)
    if math.abs(nx - ex) > 8 * EPS + 4 * 2 ^ -51 or math.abs(ny - ey) > 8 * EPS + 4 * 2 ^ -51 then
      good = false
    end
  end
  return good, "normal"
end

return rays
