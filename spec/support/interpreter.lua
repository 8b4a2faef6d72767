--- The command that started this very interpreter, for specs that run a script with it: busted's
-- arg[-1] ("lua5.4" under `lua5.4 /usr/bin/busted`, "luajit" under `luajit /usr/bin/busted`, "lua"
-- when busted runs through its own #!/usr/bin/env lua line). Returns nil and a message when arg[-1]
-- is missing or holds more than a plain command or path (it goes into a shell command line).
return function()
  local cmd = type(arg) == "table" and arg[-1]
  if type(cmd) ~= "string" or not cmd:match("^[%w%./_%-]+$") then
    return nil, "arg[-1] does not name the interpreter: " .. tostring(cmd)
  end
  return cmd
end
