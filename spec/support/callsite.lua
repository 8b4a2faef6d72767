--- Calls from a known line, for the specs that check where an argument error is raised: a public
-- function raises it at its caller's level, so the message starts with the file and line of the
-- call (here, a line of this file). A level too low names polygon.lua; one too high names pcall,
-- which has no line.
local unpack = table.unpack or unpack -- luacheck: ignore 113 143

local callsite = {}

-- How many arguments args holds: args.n, else its largest positive integer key (args may hold nils).
local function argumentCount(args)
  if args.n then return args.n end
  local count = 0
  for key in pairs(args) do
    if type(key) == "number" and key > count then count = key end
  end
  return count
end

--- Calls fn with the arguments in args, from one line of this file, under pcall.
-- @return ok, the error, and the "file:line: " that an error raised at the caller's level starts with
function callsite.call(fn, args)
  local line
  local ok, err = pcall(function()
    line = debug.getinfo(1, "l").currentline; fn(unpack(args, 1, argumentCount(args)))
  end)
  return ok, err, debug.getinfo(1, "S").short_src .. ":" .. line .. ": "
end

--- Whether fn(args) raises an error that starts with the position of the line calling fn; the
-- error (or "no error") as second result, for the assertion's message.
function callsite.raisesAtCaller(fn, args)
  local ok, err, where = callsite.call(fn, args)
  if ok then return false, "no error" end
  return tostring(err):sub(1, #where) == where, tostring(err)
end

return callsite
