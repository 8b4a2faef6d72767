--- Exact arithmetic on dyadic rationals, for the specs' oracle only.
--
-- Every finite double is m * 2^e with m an integer, so sums, differences and products of doubles
-- are again integers times a power of two. A value here is such a number held exactly:
--
--   { s = sign (-1, 0 or 1), e = exponent, [1..n] = limbs of |m|, base 2^24, least significant first }
--
-- The top limb is never zero and zero has no limbs (s = 0, e = 0). Values are never modified once
-- made. A limb is below 2^24, so a limb product is below 2^48 and every step of the schoolbook loops
-- below stays under 2^53: an exact double on every Lua version, no integer subtype needed.
--
-- This file deliberately shares nothing with polygon.lua (which uses floating-point expansions):
-- doubles are taken apart by scaling with powers of two (no math.frexp, missing on 5.3/5.4), and
-- all arithmetic is on integer limbs.

local floor = math.floor

local exact = {}

local BITS = 24
local BASE = 16777216 -- 2^24

-- POW2[k] == 2^k for -1074 <= k <= 1023, built by doubling and halving (exact) rather than by pow().
local POW2 = { [0] = 1.0 }
for k = 1, 1023 do POW2[k] = POW2[k - 1] * 2 end
for k = 1, 1074 do POW2[-k] = POW2[-k + 1] / 2 end
exact.POW2 = POW2

local ZERO = { s = 0, e = 0 }
exact.ZERO = ZERO

---------------------------------------------------------------------------------------------------
-- Magnitudes: plain arrays of limbs, least significant first.

-- Drop zero limbs at the top so that #m is the true length.
local function trim(m)
  local n = #m
  while n > 0 and m[n] == 0 do
    m[n] = nil
    n = n - 1
  end
  return m
end

-- Limbs of a non-negative integer-valued double (below 2^53 here, or any exact integer double).
local function limbsOfInteger(v)
  local m = {}
  local n = 0
  while v > 0 do
    local q = floor(v / BASE)
    n = n + 1
    m[n] = v - q * BASE
    v = q
  end
  return m
end

-- -1, 0, 1 as a < b, a == b, a > b.
local function magCompare(a, b)
  if #a ~= #b then
    return #a < #b and -1 or 1
  end
  for i = #a, 1, -1 do
    if a[i] ~= b[i] then
      return a[i] < b[i] and -1 or 1
    end
  end
  return 0
end

local function magAdd(a, b)
  local r = {}
  local carry = 0
  for i = 1, math.max(#a, #b) do
    local t = (a[i] or 0) + (b[i] or 0) + carry
    if t >= BASE then
      r[i], carry = t - BASE, 1
    else
      r[i], carry = t, 0
    end
  end
  if carry > 0 then
    r[#r + 1] = carry
  end
  return r
end

-- a - b for a >= b.
local function magSub(a, b)
  local r = {}
  local borrow = 0
  for i = 1, #a do
    local t = a[i] - (b[i] or 0) - borrow
    if t < 0 then
      r[i], borrow = t + BASE, 1
    else
      r[i], borrow = t, 0
    end
  end
  assert(borrow == 0, "magSub: a < b")
  return trim(r)
end

local function magMul(a, b)
  local r = {}
  local na, nb = #a, #b
  for i = 1, na + nb do
    r[i] = 0
  end
  for i = 1, na do
    local ai = a[i]
    local carry = 0
    for j = 1, nb do
      -- r < 2^24, ai * b[j] < 2^48, carry < 2^25: t < 2^49, exact; so are t % BASE and the
      -- division of t - low by BASE (a power of two).
      local t = r[i + j - 1] + ai * b[j] + carry
      local low = t % BASE
      r[i + j - 1] = low
      carry = (t - low) / BASE
    end
    local k = i + nb
    while carry > 0 do
      local t = r[k] + carry
      local low = t % BASE
      r[k] = low
      carry = (t - low) / BASE
      k = k + 1
    end
  end
  return trim(r)
end

-- a * 2^k for k >= 0.
local function magShiftLeft(a, k)
  if #a == 0 then
    return {}
  end
  local whole, part = floor(k / BITS), k % BITS
  local factor = POW2[part]
  local r = {}
  for i = 1, whole do
    r[i] = 0
  end
  local carry = 0
  for i = 1, #a do
    local t = a[i] * factor + carry -- < 2^48
    local low = t % BASE
    r[whole + i] = low
    carry = (t - low) / BASE
  end
  r[whole + #a + 1] = carry
  return trim(r)
end

-- floor(a / 2^k) for k >= 0.
local function magShiftRight(a, k)
  local whole, part = floor(k / BITS), k % BITS
  local divisor = POW2[part]
  local r = {}
  local rest = 0 -- what the limb above leaves over, in units of that limb
  for i = #a, whole + 1, -1 do
    local t = rest * BASE + a[i] -- < 2^(24 + part) <= 2^47
    local q = floor(t / divisor)
    r[i - whole] = q
    rest = t - q * divisor
  end
  return trim(r)
end

local function bitLength(a)
  local n = #a
  if n == 0 then
    return 0
  end
  local top, bits = a[n], 0
  while top >= 1 do
    top = top / 2
    bits = bits + 1
  end
  return (n - 1) * BITS + bits
end

---------------------------------------------------------------------------------------------------
-- Values.

-- Build a value from sign, exponent and magnitude (which it takes over). Whole zero limbs at the
-- bottom move into the exponent so that values stay short.
local function make(s, e, m)
  trim(m)
  if #m == 0 or s == 0 then
    return ZERO
  end
  local low = 0
  while m[low + 1] == 0 do
    low = low + 1
  end
  if low > 0 then
    local n = #m
    for i = 1, n - low do
      m[i] = m[i + low]
    end
    for i = n - low + 1, n do
      m[i] = nil
    end
  end
  m.s, m.e = s, e + low * BITS
  return m
end

--- Split a finite double x != 0 into sign, odd integer mantissa (0 < m < 2^53) and exponent:
-- x == sign * m * 2^e. Scaling by a power of two is exact as long as the result stays a normal
-- double, which the steps below make sure of: first |x| is brought into [2^52, 2^53), where every
-- double is an integer, then the mantissa's trailing zero bits move into the exponent.
local STEPS = { 32, 16, 8, 4, 2, 1 }
function exact.split(x)
  assert(x == x and x ~= math.huge and x ~= -math.huge and x ~= 0, "exact.split: x must be finite, not 0")
  local s = 1
  if x < 0 then
    s, x = -1, -x
  end
  local e = 0
  if x >= POW2[53] then
    -- x >= 2^116 has an ulp >= 2^64, so x / 2^64 >= 2^52 is exact; then before the step of k,
    -- x < 2^(52 + 2k), and x >= 2^(52 + k) has an ulp >= 2^k: each division is exact.
    while x >= POW2[116] do
      x, e = x / POW2[64], e + 64
    end
    for i = 1, #STEPS do
      local k = STEPS[i]
      if x >= POW2[52 + k] then
        x, e = x / POW2[k], e + k
      end
    end
  elseif x < POW2[52] then
    -- Multiplying by a power of two is exact here (the result stays below 2^53); before the step
    -- of k, x >= 2^(53 - 2k).
    while x < POW2[-11] do
      x, e = x * POW2[64], e - 64
    end
    for i = 1, #STEPS do
      local k = STEPS[i]
      if x < POW2[53 - k] then
        x, e = x * POW2[k], e - k
      end
    end
  end
  for i = 1, #STEPS do
    local k = STEPS[i]
    if x % POW2[k] == 0 then
      x, e = x / POW2[k], e + k
    end
  end
  return s, x, e
end

--- The exact value of the number x (a Lua 5.3/5.4 integer is first converted to a double, as the
-- library does; that is exact for |x| <= 2^53).
function exact.new(x)
  assert(type(x) == "number", "exact.new: x must be a number")
  x = x + 0.0
  if x == 0 then
    return ZERO
  end
  local s, m, e = exact.split(x)
  return make(s, e, limbsOfInteger(m))
end

--- 2^k exactly, for any integer k.
function exact.pow2(k)
  return make(1, k, { 1 })
end

function exact.sign(a)
  return a.s
end

function exact.neg(a)
  if a.s == 0 then
    return a
  end
  local m = {}
  for i = 1, #a do
    m[i] = a[i]
  end
  return make(-a.s, a.e, m)
end

function exact.abs(a)
  return a.s < 0 and exact.neg(a) or a
end

-- The magnitudes of a and b over their common exponent min(a.e, b.e).
local function aligned(a, b)
  if a.e == b.e then
    return a, b, a.e
  elseif a.e > b.e then
    return magShiftLeft(a, a.e - b.e), b, b.e
  else
    return a, magShiftLeft(b, b.e - a.e), a.e
  end
end

-- a + sb * |b|, where sb is b's sign or its opposite.
local function addSigned(a, b, sb)
  if sb == 0 then
    return a
  elseif a.s == 0 then
    return sb == b.s and b or exact.neg(b)
  end
  local ma, mb, e = aligned(a, b)
  if a.s == sb then
    return make(sb, e, magAdd(ma, mb))
  end
  local c = magCompare(ma, mb)
  if c == 0 then
    return ZERO
  elseif c > 0 then
    return make(a.s, e, magSub(ma, mb))
  else
    return make(sb, e, magSub(mb, ma))
  end
end

function exact.add(a, b)
  return addSigned(a, b, b.s)
end

function exact.sub(a, b)
  return addSigned(a, b, -b.s)
end

function exact.mul(a, b)
  if a.s == 0 or b.s == 0 then
    return ZERO
  end
  return make(a.s * b.s, a.e + b.e, magMul(a, b))
end

--- -1, 0 or 1 as a < b, a == b, a > b.
function exact.compare(a, b)
  if a.s ~= b.s then
    return a.s < b.s and -1 or 1
  elseif a.s == 0 then
    return 0
  end
  -- Same sign: the magnitudes decide, first by the place of their top bits (no shifting needed).
  local topA, topB = a.e + bitLength(a), b.e + bitLength(b)
  local c
  if topA ~= topB then
    c = topA < topB and -1 or 1
  else
    local ma, mb = aligned(a, b)
    c = magCompare(ma, mb)
  end
  return a.s * c
end

-- The value digits * 2^low of an accumulator whose limbs may exceed the base (below 2^53): one
-- carry pass, in place.
local function carried(digits, low)
  local carry, k = 0, 1
  while k <= #digits or carry > 0 do
    local t = (digits[k] or 0) + carry
    local limb = t % BASE
    digits[k] = limb
    carry = (t - limb) / BASE
    k = k + 1
  end
  return make(1, low, digits)
end

--- Sum of an array of values (fewer than 2^28 of them). Positive and negative terms are added
-- limb by limb into two arrays over the smallest exponent, without carrying: each addition is
-- below 2^24, so a limb stays below 2^52 and exact. One carry pass at the end, one subtraction.
function exact.sum(list)
  assert(#list < 2 ^ 28, "exact.sum: too many terms")
  local low
  for i = 1, #list do
    local v = list[i]
    if v.s ~= 0 and (not low or v.e < low) then
      low = v.e
    end
  end
  if not low then
    return ZERO
  end
  local acc = { [1] = {}, [-1] = {} }
  for i = 1, #list do
    local v = list[i]
    if v.s ~= 0 then
      local a = acc[v.s]
      local shift = v.e - low
      local whole = floor(shift / BITS)
      local factor = POW2[shift % BITS]
      for k = #a + 1, whole + #v + 1 do
        a[k] = 0
      end
      for k = 1, #v do
        local t = v[k] * factor -- < 2^48
        local limb = t % BASE
        a[whole + k] = a[whole + k] + limb
        a[whole + k + 1] = a[whole + k + 1] + (t - limb) / BASE
      end
    end
  end
  return exact.sub(carried(acc[1], low), carried(acc[-1], low))
end

--- The exact sum of signs[i] * as[i] * bs[i] over i (doubles; signs are 1 or -1), for long sums
-- such as the shoelace formula of 10^5 vertices: the same result as exact.sum of exact.mul, without
-- making a value per product. Each product's mantissas are multiplied limb by limb straight into
-- two accumulators (positive and negative terms) over the smallest exponent of all products:
--   a = ma * 2^ea, b = mb * 2^eb, shift = ea + eb - low = 24 whole + part;
--   ma * 2^part < 2^77 is an exact double and splits into four limbs, mb < 2^53 into three;
--   the limb products (< 2^48, at most three per place: < 2^50) are split in two below 2^24 and
--   2^26 before being added, so an accumulator limb grows by < 2^27 per product (n < 2^24).
-- (a4 < 2^5 and b3 < 2^5, which is why three limbs of b and four of a suffice.)
function exact.sumOfProducts(as, bs, signs)
  local n = #as
  assert(n < 2 ^ 24, "exact.sumOfProducts: too many terms")
  local split = exact.split
  -- the products' signs, mantissas and exponents, and the smallest exponent
  local ts, tma, tmb, te, m = {}, {}, {}, {}, 0
  local low
  for i = 1, n do
    local a, b = as[i] + 0.0, bs[i] + 0.0
    if a ~= 0 and b ~= 0 then
      local sa, ma, ea = split(a)
      local sb, mb, eb = split(b)
      m = m + 1
      ts[m], tma[m], tmb[m], te[m] = sa * sb * signs[i], ma, mb, ea + eb
      if not low or ea + eb < low then
        low = ea + eb
      end
    end
  end
  if not low then
    return ZERO
  end
  local acc = { [1] = {}, [-1] = {} }
  -- adds p < 2^51 at place k of the accumulator, as two parts below 2^24 and 2^27
  local function deposit(target, k, p)
    local limb = p % BASE
    target[k] = target[k] + limb
    target[k + 1] = target[k + 1] + (p - limb) / BASE
  end
  for t = 1, m do
    local target = acc[ts[t]]
    local shift = te[t] - low
    local whole = floor(shift / BITS)
    local ma, mb = tma[t] * POW2[shift % BITS], tmb[t]
    local a1 = ma % BASE
    ma = (ma - a1) / BASE
    local a2 = ma % BASE
    ma = (ma - a2) / BASE
    local a3 = ma % BASE
    local a4 = (ma - a3) / BASE
    local b1 = mb % BASE
    mb = (mb - b1) / BASE
    local b2 = mb % BASE
    local b3 = (mb - b2) / BASE
    for k = #target + 1, whole + 7 do
      target[k] = 0
    end
    deposit(target, whole + 1, a1 * b1)
    deposit(target, whole + 2, a1 * b2 + a2 * b1)
    deposit(target, whole + 3, a1 * b3 + a2 * b2 + a3 * b1)
    deposit(target, whole + 4, a2 * b3 + a3 * b2 + a4 * b1)
    deposit(target, whole + 5, a3 * b3 + a4 * b2)
    deposit(target, whole + 6, a4 * b3)
  end
  return exact.sub(carried(acc[1], low), carried(acc[-1], low))
end

-- x * 2^k for a double x and an integer k, by steps that never round: the caller guarantees that
-- x * 2^k is a double (or overflows to infinity), and every intermediate lies between x and it.
local function scale(x, k)
  while k > 1000 do
    x, k = x * POW2[1000], k - 1000
  end
  while k < -1000 do
    x, k = x * POW2[-1000], k + 1000
  end
  return x * POW2[k]
end

--- The double nearest to a (ties to even), infinity past the largest double.
function exact.tonumber(a)
  if a.s == 0 then
    return 0.0
  end
  local length = bitLength(a)
  -- Exponent of the last bit a double can keep: 53 significant bits, none below 2^-1074.
  local last = math.max(a.e + length - 53, -1074)
  local m, e = a, a.e
  if last > e then
    local drop = last - e
    local q = magShiftRight(a, drop)
    local rest = magSub(a, magShiftLeft(q, drop))
    local half = magShiftLeft({ 1 }, drop - 1)
    local c = magCompare(rest, half)
    if c > 0 or (c == 0 and (q[1] or 0) % 2 == 1) then
      q = magAdd(q, { 1 })
    end
    m, e = q, last
  end
  -- m now has at most 53 bits (54 when rounding carried into 2^53, which is exact too).
  local v = 0.0
  for i = #m, 1, -1 do
    v = v * BASE + m[i]
  end
  return a.s * scale(v, e)
end

--- ulp(x) as an exact value: the gap between |x| and the next double away from zero, i.e. the
-- place value of the last bit of x's 53-bit significand (2^-1074 for subnormals and zero).
function exact.ulp(x)
  x = x + 0.0
  if x == 0 then
    return exact.pow2(-1074)
  end
  local _, m, e = exact.split(x)
  local bits = bitLength(limbsOfInteger(m))
  return exact.pow2(math.max(e + bits - 53, -1074))
end

--- The next double above x (x finite, below the largest double).
function exact.nextUp(x)
  x = x + 0.0
  if x < 0 then
    return -exact.nextDown(-x)
  end
  return x + exact.tonumber(exact.ulp(x))
end

--- The next double below x (x finite, above minus the largest double).
function exact.nextDown(x)
  x = x + 0.0
  if x <= 0 then
    return -exact.nextUp(-x)
  end
  local u = exact.tonumber(exact.ulp(x))
  local _, m = exact.split(x)
  if m == 1 and u > POW2[-1074] then
    -- a power of two above the subnormals' spacing: the gap below it is half the gap above
    u = u / 2
  end
  return x - u
end

--- Is |x - a| <= k * ulp(x), exactly? (x a double, a an exact value, k a small integer.)
function exact.withinUlps(x, a, k)
  local err = exact.abs(exact.sub(exact.new(x), a))
  return exact.compare(err, exact.mul(exact.new(k), exact.ulp(x))) <= 0
end

--- |x - a| in ulps of a (a exact, x a number): 0 when equal, infinity for x not finite or a = 0 != x.
function exact.ulpsOff(a, x)
  if type(x) ~= "number" or x ~= x or x == math.huge or x == -math.huge then
    return math.huge
  end
  local err = exact.tonumber(exact.abs(exact.sub(exact.new(x), a)))
  local v = exact.tonumber(a)
  if err == 0 or v == 0 then
    return err == 0 and 0 or math.huge
  end
  return err / exact.tonumber(exact.ulp(v))
end

--- A readable form: the nearest double, then the exact value as hexadecimal limbs times 2^e.
function exact.tostring(a)
  if a.s == 0 then
    return "0"
  end
  local parts = { ("%x"):format(a[#a]) }
  for i = #a - 1, 1, -1 do
    parts[#parts + 1] = ("%06x"):format(a[i])
  end
  local sign = a.s < 0 and "-" or ""
  return ("%.17g (= %s0x%s * 2^%d)"):format(exact.tonumber(a), sign, table.concat(parts), a.e)
end

-- Magnitude helpers, exposed for the oracle's own spec.
exact.magnitude = {
  add = magAdd,
  sub = magSub,
  mul = magMul,
  compare = magCompare,
  shiftLeft = magShiftLeft,
  shiftRight = magShiftRight,
  bitLength = bitLength,
  ofInteger = limbsOfInteger,
}

return exact
