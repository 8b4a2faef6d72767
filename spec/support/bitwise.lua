-- Bit-for-bit comparison of Lua values, for the specs that run two bodies of one function (or
-- two versions of the library) on the same input: same(a, b) when a and b are of one type and,
-- for numbers, of one subtype (Lua 5.3+), both NaN or equal with zeros of one sign.
local mathType = rawget(math, "type") or function() return nil end

local bitwise = {}

function bitwise.same(a, b)
  if type(a) ~= "number" or type(b) ~= "number" then return a == b end
  if a ~= a then return b ~= b end
  if a ~= b or mathType(a) ~= mathType(b) then return false end
  return a ~= 0 or 1 / a == 1 / b
end

-- The values of a call with their count, nils included.
function bitwise.pack(...) return { n = select("#", ...), ... } end

return bitwise
