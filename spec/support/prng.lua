--- A small deterministic random generator for the specs: the same numbers on every Lua version
-- (math.random differs between 5.1, 5.4 and LuaJIT).
--
-- Park and Miller's "minimal standard" generator: state <- state * 48271 mod (2^31 - 1).
-- state < 2^31 and 48271 < 2^16, so the product stays below 2^47: exact as a double and as an integer.

local MODULUS = 2147483647 -- 2^31 - 1
local MULTIPLIER = 48271

local prng = {}
prng.__index = prng

--- A generator from a seed in 1 .. 2^31 - 2.
function prng.new(seed)
  seed = seed % MODULUS
  if seed == 0 then
    seed = 1
  end
  return setmetatable({ state = seed }, prng)
end

--- The next raw state, an integer in 1 .. 2^31 - 2.
function prng:next()
  self.state = (self.state * MULTIPLIER) % MODULUS
  return self.state
end

--- An integer in lo .. hi (both inclusive; hi - lo < 2^31 - 2).
function prng:int(lo, hi)
  return lo + (self:next() % (hi - lo + 1))
end

--- A float in [0, 1) with 53 random bits (two draws of 31 bits, trimmed).
function prng:float()
  local a = self:next() % 67108864 -- 2^26
  local b = self:next() % 134217728 -- 2^27
  return (a * 134217728 + b) / 9007199254740992 -- (a * 2^27 + b) / 2^53, exact
end

--- A float in [lo, hi).
function prng:range(lo, hi)
  return lo + (hi - lo) * self:float()
end

--- One element of an array.
function prng:pick(list)
  return list[self:int(1, #list)]
end

return prng
