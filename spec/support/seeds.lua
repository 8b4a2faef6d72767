--- The interpreter running the specs as a number, for the specs that give each interpreter its
-- own range of seeds (so that CI's five runs check five times as many generated cases): LuaJIT
-- 0, Lua 5.1 to 5.4 1 to 4, any other 5.
local JIT = rawget(_G, "jit") ~= nil
return JIT and 0 or ({ ["Lua 5.1"] = 1, ["Lua 5.2"] = 2, ["Lua 5.3"] = 3, ["Lua 5.4"] = 4 })[_VERSION] or 5
