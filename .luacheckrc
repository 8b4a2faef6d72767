-- polygon.lua is plain Lua: only the globals every version shares.
std = "min"
max_line_length = 110

files["spec"] = { std = "+busted" }
files["examples/love"] = { std = "luajit+love" }   -- LÖVE runs on LuaJIT
files["bench"] = { std = "min" }

exclude_files = { ".luarocks", "lua_modules", ".install" }
