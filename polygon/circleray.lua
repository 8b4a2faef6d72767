-- polygon/circleray.lua: rays against discs: where a segment first enters an open disc
-- (circleRayCast). Hit or miss from circle.lua's exact distance tests; the entry from double
-- doubles, or from exact expansions near a tangent. Relies on kernel, check, circle's tests and
-- sat's unit.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local check = require(_PACKAGE .. ".check")
local sat = require(_PACKAGE .. ".sat")
local circle = require(_PACKAGE .. ".circle")

local abs, sqrt, min, max = math.abs, math.sqrt, math.min, math.max
local twoDiff, twoProduct, powerScale = kernel.twoDiff, kernel.twoProduct, kernel.powerScale
local expClear, expAddProduct, expCompress = kernel.expClear, kernel.expAddProduct, kernel.expCompress
local expCopy, expAddSquare = kernel.expCopy, kernel.expAddSquare
local expTopTwo, twoSum, sqrtDD, divideDD = kernel.expTopTwo, kernel.twoSum, kernel.sqrtDD, kernel.divideDD
local checkFiniteNumber, checkRadius = check.checkFiniteNumber, check.checkRadius
local unit = sat.unit
local reaches, lineWithin, dot = circle.reaches, circle.lineWithin, circle.dot

local M = {}

-- Scratch for the exact entry: compressed expansions copied out of kernel's one.
local numParts, denParts = {}, {}

-- Discs. The segment meets the open disc exactly when A or B lies strictly inside it, or the
-- foot of the perpendicular from the centre C lies strictly between A and B and the line passes
-- strictly within r of C (circle.lua's exact tests). Then with w = A - C the entry is the least
-- root of Q t^2 + 2 P t + K, Q = |d|^2, P = d.w, K = |w|^2 - r^2 >= 0 (A is not inside), whose
-- discriminant is G = P^2 - Q K = r^2 Q - X^2, X = d x w (Lagrange's identity), so
-- t = K / (-P + sqrt(G)) (-P > 0 for a segment that enters from outside): no cancellation once
-- G is known. The entry point is Z = C + (X (-dy, dx) - sqrt(G) d) / Q, which gives the normal
-- without the difference Z - C (far from a small circle that difference is mostly rounding).
-- Near a tangent G is a small difference of large degree-4 terms, so every quantity is taken
-- from exact expansions of the split differences and carried as hi + lo to the end: t within
-- eps (plus order eps^2), the normal within a few ulps.

-- fraction, nx, ny of the entry of the segment A -> B into the disc (C, r), which it meets and
-- A does not lie strictly inside.
local function circleEntry(cx, cy, r, ax, ay, bx, by)
  local wxh, wxl = twoDiff(ax, cx)
  local wyh, wyl = twoDiff(ay, cy)
  local dxh, dxl = twoDiff(bx, ax)
  local dyh, dyl = twoDiff(by, ay)
  -- as circle.lua's exact tests: into [2^186, 2^250], so no product of four overflows
  local s = powerScale(max(abs(wxh), abs(wyh), abs(dxh), abs(dyh), r), 2^186, 2^250)
  wxh, wxl, wyh, wyl = wxh * s, wxl * s, wyh * s, wyl * s
  dxh, dxl, dyh, dyl = dxh * s, dxl * s, dyh * s, dyl * s
  r = r * s
  expClear()   -- X = d x w
  expAddProduct(dxh, wyh); expAddProduct(dxh, wyl); expAddProduct(dxl, wyh); expAddProduct(dxl, wyl)
  expAddProduct(-dyh, wxh); expAddProduct(-dyh, wxl); expAddProduct(-dyl, wxh)
  expAddProduct(-dyl, wxl)
  local xh = expCompress()
  local xLen = expCopy(numParts)
  expClear()   -- Q = |d|^2
  expAddSquare(dxh, dxl, 1)
  expAddSquare(dyh, dyl, 1)
  expCompress()
  local qLen = expCopy(denParts)
  local rrh, rrl = twoProduct(r, r)
  expClear()   -- G = r^2 Q - X^2
  for i = 1, qLen do
    expAddProduct(denParts[i], rrl)
    expAddProduct(denParts[i], rrh)
  end
  for i = 1, xLen do
    for j = 1, xLen do expAddProduct(-numParts[i], numParts[j]) end
  end
  local gh, gl = expTopTwo()
  expClear()   -- P = d.w
  expAddProduct(dxh, wxh); expAddProduct(dxh, wxl); expAddProduct(dxl, wxh); expAddProduct(dxl, wxl)
  expAddProduct(dyh, wyh); expAddProduct(dyh, wyl); expAddProduct(dyl, wyh); expAddProduct(dyl, wyl)
  local ph, pl = expTopTwo()
  expClear()   -- K = |w|^2 - r^2
  expAddSquare(wxh, wxl, 1)
  expAddSquare(wyh, wyl, 1)
  expAddProduct(-r, r)
  local kh, kl = expTopTwo()
  -- sqrt(G) as hi + lo: one Newton step from the root of its high part
  local root = sqrt(gh)
  local sh, sl = twoProduct(root, root)
  local rootLo = (((gh - sh) - sl) + gl) / (2 * root)
  -- D = -P + sqrt(G) as hi + lo (both terms > 0), then t = K / D by one correction
  local dh, dlo = twoDiff(root, ph)
  dlo = dlo + (rootLo - pl)
  local t = kh / dh
  local th, tl = twoProduct(t, dh)
  t = t + ((((kh - th) - tl) + kl) - t * dlo) / dh
  local nx, ny = unit(-root * dxh - xh * dyh, xh * dxh - root * dyh)
  return min(max(t, 0.0), 1.0), nx, ny
end

-- circleEntry's numbers as double doubles instead of expansions, with no loop: the differences
-- split exactly, every product's main part exact (TwoProduct), first-order terms added, each sum
-- of high parts exact (TwoSum, TwoDiff). What is dropped is below 2^-100 times the terms of a
-- quantity, so K, G and D = sqrt(G) - P are within 2^-100 c of themselves, c their terms over
-- them (D has no cancellation: -P > 0), and t = K / D, corrected once, is within eps plus
-- order eps^2 when c stays below 2^30 for K (A near the circle) and for G (a near tangent);
-- else nil (circleEntry's expansions). The normal from the high parts: within a few eps.
--
-- The work from w = A - C and d = B - A as hi + lo (low parts exact) and r^2 as hi + lo: t
-- (unclamped), nx, ny, or nil. casts.lua's circlesCast takes it too, with d exact and R^2 of
-- R = r1 + r2 held as a TwoSum.
local function discEntryTerms(wx, wxl, wy, wyl, dx, dxl, dy, dyl, rrh, rrl)
  local h, l, h2, l2, e
  h, l = twoProduct(dx, wy)   -- X = d x w
  h2, l2 = twoProduct(dy, wx)
  local xh, xl = twoDiff(h, h2)
  xl = xl + (l - l2) + ((dx * wyl + dxl * wy) - (dy * wxl + dyl * wx))
  xh, xl = twoSum(xh, xl)
  h, l = twoProduct(dx, dx)   -- Q = |d|^2
  h2, l2 = twoProduct(dy, dy)
  local qh, ql = twoSum(h, h2)
  ql = ql + (l + l2) + 2 * (dx * dxl + dy * dyl)
  h, l = twoProduct(dx, wx)   -- P = d.w
  h2, l2 = twoProduct(dy, wy)
  local ph, pl = twoSum(h, h2)
  pl = pl + (l + l2) + ((dx * wxl + dxl * wx) + (dy * wyl + dyl * wy))
  h, l = twoProduct(wx, wx)   -- K = |w|^2 - r^2
  h2, l2 = twoProduct(wy, wy)
  local kh, kl = twoSum(h, h2)
  local kTerms = kh + rrh
  kl = kl + (l + l2) + 2 * (wx * wxl + wy * wyl)
  kh, e = twoDiff(kh, rrh)
  kl = kl + e - rrl
  kh, kl = twoSum(kh, kl)
  h, l = twoProduct(rrh, qh)   -- G = r^2 Q - X^2
  h2, l2 = twoProduct(xh, xh)
  local gTerms = h + h2
  local gh, gl = twoDiff(h, h2)
  gl = gl + (l - l2) + (rrh * ql + rrl * qh) - 2 * xh * xl
  gh, gl = twoSum(gh, gl)
  if not (kh > 0 and gh > 0 and kTerms < 2^30 * kh and gTerms < 2^30 * gh) then return nil end
  local rootH, rootL = sqrtDD(gh, gl)
  local dh, dl = twoDiff(rootH, ph)   -- D = sqrt(G) - P
  dl = dl + (rootL - pl)
  local t = divideDD(kh, kl, dh, dl)
  local nx, ny = unit(-rootH * dx - xh * dy, xh * dx - rootH * dy)
  return t, nx, ny
end
M.discEntryTerms = discEntryTerms

local function circleEntryDD(cx, cy, r, ax, ay, bx, by)
  local wx, wxl = twoDiff(ax, cx)
  local wy, wyl = twoDiff(ay, cy)
  local dx, dxl = twoDiff(bx, ax)
  local dy, dyl = twoDiff(by, ay)
  local m = max(abs(wx), abs(wy), abs(dx), abs(dy), r)
  if m > 2^200 or m < 2^-200 then return nil end   -- (products' range)
  local rrh, rrl = twoProduct(r, r)
  local t, nx, ny = discEntryTerms(wx, wxl, wy, wyl, dx, dxl, dy, dyl, rrh, rrl)
  if not t then return nil end
  return min(max(t, 0.0), 1.0), nx, ny
end

-- circleRayCast: false, or fraction, nx, ny, as polygonRayCast against the open disc.
function M.circleRayCast(cx, cy, radius, x1, y1, x2, y2)
  local fname = "circleRayCast"
  checkFiniteNumber(cx, fname, "cx")
  checkFiniteNumber(cy, fname, "cy")
  checkRadius(radius, fname, "radius")
  checkFiniteNumber(x1, fname, "x1")
  checkFiniteNumber(y1, fname, "y1")
  checkFiniteNumber(x2, fname, "x2")
  checkFiniteNumber(y2, fname, "y2")
  cx, cy, radius = cx + 0.0, cy + 0.0, radius + 0.0
  local ax, ay, bx, by = x1 + 0.0, y1 + 0.0, x2 + 0.0, y2 + 0.0
  if radius == 0 then return false end   -- the open disc is empty
  if reaches(cx, cy, ax, ay, radius, 0.0) > 0 then return 0.0, 0.0, 0.0 end
  if not (reaches(cx, cy, bx, by, radius, 0.0) > 0 or (dot(ax, ay, cx, cy, bx, by) > 0
      and dot(bx, by, cx, cy, ax, ay) > 0 and lineWithin(ax, ay, bx, by, cx, cy, radius) > 0)) then
    return false
  end
  local f, nx, ny = circleEntryDD(cx, cy, radius, ax, ay, bx, by)
  if not f then f, nx, ny = circleEntry(cx, cy, radius, ax, ay, bx, by) end
  return f, nx + 0.0, ny + 0.0   -- + 0.0: a normal of -0 reads as 0
end

return M
