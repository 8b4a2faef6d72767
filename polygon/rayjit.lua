-- polygon/rayjit.lua: LuaJIT's pieces of the ray cast against a convex polygon (raycast.lua's
-- castConvexJit): the convexity filter and the sides' walk written out without a branch, the
-- finish's outcome as a code, the entry fraction in double doubles. Every branch in LuaJIT's
-- traces is a side exit, and the side traces of a long body failed to compile (bench/NOTES.md),
-- hence min and max (single instructions there) where PUC Lua's body compares. Relies on kernel,
-- convex's TINY and sat's unit.

local _PACKAGE = (...):match("^(.+)%.[^%.]+")
local kernel = require(_PACKAGE .. ".kernel")
local convex = require(_PACKAGE .. ".convex")
local sat = require(_PACKAGE .. ".sat")

local abs, huge, min, max = math.abs, math.huge, math.min, math.max
local CROSS_BOUND, EPS = kernel.CROSS_BOUND, kernel.EPS
local twoDiff, crossDD = kernel.twoDiff, kernel.crossDD
local unit = sat.unit
local TINY = convex.TINY

local M = {}

-- A nonzero double times BIG twice is at least 2^926 in magnitude: min(1, max(0, x BIG BIG)) is
-- 1 for x > 0 and 0 otherwise, with no branch.
local BIG = 2^1000
local FINISH_TINY = 2^-900   -- the least size trusted to the float bounds (as convex.TINY)

-- LuaJIT's sides' walk, with no branch (each comparison that goes both ways is a side exit, and
-- a loop of a polygon's few vertices is copied unrolled into the calling trace with an exit for
-- every other size, whose side traces failed to compile: bench/NOTES.md). Each side is
-- lineSide's float number with how far it clears its error bound (< 0: not sure); a fall from
-- > 0 to <= 0 and a rise from < 0 to >= 0 are 0 or 1 by min and max, so the crossing edges'
-- indices are sums (a convex polygon has one of each, or none).
local function sideJit(x, y, ax, ay, dx, dy)
  local l, r = dx * (y - ay), dy * (x - ax)
  local o = l - r
  return o, abs(o) - CROSS_BOUND * (abs(l) + abs(r))
end

-- 1 when the side goes from oPrev > 0 to o <= 0, else 0; rise: from < 0 to >= 0.
local function fall(oPrev, o)
  return min(1, max(0, oPrev * BIG * BIG)) * (1 - min(1, max(0, o * BIG * BIG)))
end
local function rise(oPrev, o)
  return min(1, max(0, -oPrev * BIG * BIG)) * (1 - min(1, max(0, -o * BIG * BIG)))
end

-- Up to 16 vertices the filter and the walk are written out, one vertex slot at a time (a loop
-- of a polygon's few vertices is copied unrolled into the calling trace with an exit for every
-- other size, whose side traces failed to compile: bench/NOTES.md). Slot k holds vertex
-- min(k, m) (m = n / 2), so that one body serves every size up to its slots; a slot past m
-- repeats vertex m. Only the running sums are alive from one slot to the next: the filter's
-- and the walk's slots written side by side, or all the vertices read first, kept too many
-- numbers alive for the registers, and the calling loop's trace failed to compile ("too many
-- spill slots"). Two passes, the filter's and the walk's, each with few numbers alive.
local PAD = 2^1000

-- The filter's slot: the vertex at flat index i after (px, py), reached along (ex, ey): the
-- turn at (px, py) with its bound, as convex.lua's convexFilterJit (the same numbers). A slot
-- past m has a zero edge: its turn is taken out of lo and hi by `pad` (2^1000), and its x
-- product is 0; the turn at vertex m is slot 1's, taken from the edge into vertex m.
local function turnSlot(points, i, pad, px, py, ex, ey, lo, hi, agree, bsum)
  local cx, cy = points[i], points[i + 1]
  local fx, fy = cx - px, cy - py
  local l, r = ex * fy, ey * fx
  local s, b = l - r, CROSS_BOUND * abs(l + r) + TINY
  return cx, cy, fx, fy, min(lo, s - b + pad), max(hi, s + b - pad),
    agree + min(1, max(-1, ex * fx * 2^1000)), bsum + b
end

-- Slots 1 to 7 of either body (the same there): the filter's sums after them, and the last
-- vertex and edge.
local function firstTurns(points, n)
  local last = n - 1
  local px, py = points[last], points[n]
  local ex, ey = px - points[n - 3], py - points[n - 2]
  local lo, hi, agree, bsum = huge, -huge, 0, 0
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, 1, 0, px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, 3, 0, px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, 5, 0, px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, min(7, last), PAD * min(1, max(0, 8 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, min(9, last), PAD * min(1, max(0, 10 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, min(11, last), PAD * min(1, max(0, 12 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, min(13, last), PAD * min(1, max(0, 14 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  return px, py, ex, ey, lo, hi, agree, bsum
end

-- The area sign when the filter vouches for convexity (every turn surely positive, or every
-- one surely negative, one winding, no overflow), else 0 (convex.lua's careful check decides).
local function turnSign(n, lo, hi, agree, bsum)
  if agree ~= n / 2 - 4 or bsum == huge then return 0 end
  return min(1, max(0, lo * BIG * BIG)) - min(1, max(0, -hi * BIG * BIG))
end

local function filterJit8(points, n)
  local px, py, ex, ey, lo, hi, agree, bsum = firstTurns(points, n)
  local _
  _, _, _, _, lo, hi, agree, bsum =
    turnSlot(points, n - 1, PAD * min(1, max(0, 16 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  return turnSign(n, lo, hi, agree, bsum)
end

local function filterJit16(points, n)
  local last = n - 1
  local px, py, ex, ey, lo, hi, agree, bsum = firstTurns(points, n)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, min(15, last), PAD * min(1, max(0, 16 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, min(17, last), PAD * min(1, max(0, 18 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, min(19, last), PAD * min(1, max(0, 20 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, min(21, last), PAD * min(1, max(0, 22 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, min(23, last), PAD * min(1, max(0, 24 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, min(25, last), PAD * min(1, max(0, 26 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, min(27, last), PAD * min(1, max(0, 28 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  px, py, ex, ey, lo, hi, agree, bsum =
    turnSlot(points, min(29, last), PAD * min(1, max(0, 30 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  local _
  _, _, _, _, lo, hi, agree, bsum =
    turnSlot(points, last, PAD * min(1, max(0, 32 - n)), px, py, ex, ey, lo, hi, agree, bsum)
  return turnSign(n, lo, hi, agree, bsum)
end

-- The walk's slot: the side of the vertex at flat index i (its sign, -1, 0 or 1, by min and
-- max), after a vertex whose side's sign is signPrev. A fall (from > 0 to <= 0) or a rise (from
-- < 0 to >= 0) adds i to fq or rq; a slot past m repeats a side, no crossing.
local function sideSlot(points, i, signPrev, ax, ay, dx, dy, sure, fq, rq)
  local o, c = sideJit(points[i], points[i + 1], ax, ay, dx, dy)
  local sign = min(1, max(-1, o * BIG * BIG))
  fq = fq + i * max(0, signPrev) * (1 - max(0, sign))
  rq = rq + i * max(0, -signPrev) * (1 - max(0, -sign))
  return sign, min(sure, c), fq, rq
end

-- Slots 1 to 7 of either walk (the same there): the last slot's sign and the sums after them.
local function firstSides(points, n, ax, ay, dx, dy)
  local last = n - 1
  local o, sure = sideJit(points[last], points[n], ax, ay, dx, dy)
  local sign, fq, rq = min(1, max(-1, o * BIG * BIG)), 0, 0
  sign, sure, fq, rq = sideSlot(points, 1, sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, 3, sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, 5, sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, min(7, last), sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, min(9, last), sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, min(11, last), sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, min(13, last), sign, ax, ay, dx, dy, sure, fq, rq)
  return sign, sure, fq, rq
end

-- The falling edge's ends (flat indices: the vertex before q is q - 2, or the last for the
-- first; 0 ends when there is none: fq 0), the rising edge's, and the least clearance of the
-- sides (< 0: redo exactly).
local function crossings(n, fq, rq, sure)
  return (fq - 2 + n * (1 - min(1, fq - 1))) * min(1, fq), fq,
    (rq - 2 + n * (1 - min(1, rq - 1))) * min(1, rq), rq, sure
end

local function sidesJit8(points, n, ax, ay, dx, dy)
  local sign, sure, fq, rq = firstSides(points, n, ax, ay, dx, dy)
  local _
  _, sure, fq, rq = sideSlot(points, n - 1, sign, ax, ay, dx, dy, sure, fq, rq)
  return crossings(n, fq, rq, sure)
end

local function sidesJit16(points, n, ax, ay, dx, dy)
  local last = n - 1
  local sign, sure, fq, rq = firstSides(points, n, ax, ay, dx, dy)
  sign, sure, fq, rq = sideSlot(points, min(15, last), sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, min(17, last), sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, min(19, last), sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, min(21, last), sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, min(23, last), sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, min(25, last), sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, min(27, last), sign, ax, ay, dx, dy, sure, fq, rq)
  sign, sure, fq, rq = sideSlot(points, min(29, last), sign, ax, ay, dx, dy, sure, fq, rq)
  local _
  _, sure, fq, rq = sideSlot(points, last, sign, ax, ay, dx, dy, sure, fq, rq)
  return crossings(n, fq, rq, sure)
end

-- Beyond 16 vertices the same in a loop (long enough to be a trace of its own).
local function sidesJitLoop(points, n, ax, ay, dx, dy)
  local prev, sure = sideJit(points[n - 1] + 0.0, points[n] + 0.0, ax, ay, dx, dy)
  local fp, fq, rp, rq = 0, 0, 0, 0
  local prevIndex = n - 1
  for i = 1, n - 1, 2 do
    local o, c = sideJit(points[i] + 0.0, points[i + 1] + 0.0, ax, ay, dx, dy)
    local f, r = fall(prev, o), rise(prev, o)
    fp, fq, rp, rq = fp + f * prevIndex, fq + f * i, rp + r * prevIndex, rq + r * i
    sure = min(sure, c)
    prev, prevIndex = o, i
  end
  return fp, fq, rp, rq, sure
end

-- castFinish for LuaJIT, without a branch: each outcome a margin (> 0 when the bounds vouch
-- for it), the answer a code: 1 a hit whose float fraction is within 7 eps M, 4 a hit that
-- needs entryFractionDD's, 2 A inside, 3 a miss, 0 when the bounds vouch for none (the exact
-- path then). Every branch on LuaJIT is a side exit, and a side trace starting where many
-- numbers are alive failed to compile ("NYI: register coalescing too complex": the registers
-- ran out while taking over the parent trace's): the caller branches on the code with only the
-- code and the normal alive (raycast.lua keeps the rest in its scratch). Returns the code, the
-- float fraction, the unit outward normal and the entry edge's ends (flat indices). With
-- e = q - p the entry edge, cA = e x (A - p) and cB = e x (B - p) are of opposite signs at a
-- hit, so the entry fraction t = cA / (cA - cB) divides by |cA| + |cB| with no cancellation:
-- within (2 errA + errB) / (|cA| + |cB|) + 2 eps t of the exact one, errA and errB cross's
-- bounds.
-- Coordinates beyond 2^400 never come here; sizes below 2^-900 are taken for error (TINY).
local function finishJit(points, w, fp, fq, rp, rq, ax, ay, bx, by)
  local entering = 0.5 + 0.5 * w   -- 1: the falling edge is the entry
  local p, xp = rp + (fp - rp) * entering, fp + (rp - fp) * entering
  local q, xq = rq + (fq - rq) * entering, fq + (rq - fq) * entering
  -- A strictly inside the exit edge's line
  local rx, ry = points[xp], points[xp + 1]
  local l, r = (points[xq] - rx) * (ay - ry), (points[xq + 1] - ry) * (ax - rx)
  local exitSize = abs(l) + abs(r)
  local exitMargin = (l - r) * w - CROSS_BOUND * exitSize - FINISH_TINY
  -- A and B against the entry edge's line
  local px, py = points[p], points[p + 1]
  local ex, ey = points[q] - px, points[q + 1] - py
  l, r = ex * (ay - py), ey * (ax - px)
  local cA, errA = l - r, CROSS_BOUND * (abs(l) + abs(r)) + FINISH_TINY
  l, r = ex * (by - py), ey * (bx - px)
  local cB, errB = l - r, CROSS_BOUND * (abs(l) + abs(r)) + FINISH_TINY
  local wA, wB = cA * w, cB * w
  local hit = min(exitMargin, wB - errB, -wA - errA)
  local missed = max(-exitMargin - 2 * CROSS_BOUND * exitSize - 2 * FINISH_TINY, -wB - errB)
  local inside = min(exitMargin, wA - errA)
  local den = abs(cA) + abs(cB)
  local t = abs(cA) / max(den, FINISH_TINY)
  local errT = (2 * errA + errB) / max(den, FINISH_TINY) * (1 + 2^-10) + 2 * EPS * t
  local precise = 7 * EPS * max(abs(ax), abs(ay), abs(bx), abs(by))
    - errT * (abs(bx - ax) + abs(by - ay))
  local isHit = min(1, max(0, hit * BIG * BIG))
  local isPrecise = min(1, max(0, precise * BIG * BIG))
  local code = isHit * (1 + 3 * (1 - isPrecise)) + 3 * min(1, max(0, missed * BIG * BIG))
    + 2 * min(1, max(0, inside * BIG * BIG))
  local nx, ny = unit(ey * w, -ex * w)
  return code, t, nx, ny, p, q
end

-- The same t = cA / (cA - cB) from double doubles, as edgeFractionDD: every difference split
-- exactly (TwoDiff), each determinant the exact difference of its two main products plus its
-- first-order terms (what is dropped is below 2^-100 of its products' size), then one division
-- (no cancellation: cA and cB are of opposite signs): t within eps, plus 2^-99 times the sizes
-- over |cA| + |cB|. nil where that ratio passes 2^40 (nearly parallel) or the products near
-- underflow: the expansions then.
local function entryFractionDD(px, py, qx, qy, ax, ay, bx, by)
  local exh, exl = twoDiff(qx, px)
  local eyh, eyl = twoDiff(qy, py)
  local uxh, uxl = twoDiff(ax, px)
  local uyh, uyl = twoDiff(ay, py)
  local ah, al, sizeA = crossDD(exh, exl, eyh, eyl, uxh, uxl, uyh, uyl)
  uxh, uxl = twoDiff(bx, px)
  uyh, uyl = twoDiff(by, py)
  local bh, bl, sizeB = crossDD(exh, exl, eyh, eyl, uxh, uxl, uyh, uyl)
  local a, b, size = ah + al, bh + bl, sizeA + sizeB
  local den = abs(a) + abs(b)
  if den < size * 2^-40 or size < 2^-800 then return nil end
  return abs(a) / den
end

M.sideJit, M.fall, M.rise = sideJit, fall, rise
M.filterJit8, M.filterJit16 = filterJit8, filterJit16
M.sidesJit8, M.sidesJit16, M.sidesJitLoop = sidesJit8, sidesJit16, sidesJitLoop
M.finishJit, M.entryFractionDD = finishJit, entryFractionDD

return M
