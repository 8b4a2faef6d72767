--- earcut's test fixtures (spec/support/earcut/*.json, copied from github.com/mapbox/earcut's
-- test/fixtures under its ISC licence, spec/support/earcut/LICENSE), as polygon.lua takes them.
-- Each file holds rings of [x, y] pairs, the outline first, then the holes. Shares no code with
-- polygon.lua.

local earcut = {}

local DIR = "spec/support/earcut/"

--- The fixture `name` (e.g. "water-huge3"): points (a flat array), holes (a list of flat
-- arrays) and the number of vertices in all.
function earcut.load(name)
  local file = assert(io.open(DIR .. name .. ".json"))
  local text = file:read("*a")
  file:close()
  -- nested arrays of numbers only: a stack of open arrays, numbers appended to the innermost
  local stack, top = {}, nil
  for token in text:gmatch("[%[%]]?[^%[%],%s]*") do
    local bracket, number = token:sub(1, 1), token
    if bracket == "[" then
      top = {}
      stack[#stack + 1] = top
      number = token:sub(2)
    elseif bracket == "]" then
      local done = table.remove(stack)
      top = stack[#stack]
      if top then top[#top + 1] = done else stack.result = done end
      number = token:sub(2)
    end
    if number ~= "" then top[#top + 1] = assert(tonumber(number), name .. ": " .. number) end
  end
  local rings = {}
  for r, pairsOf in ipairs(assert(stack.result, name)) do
    local ring = {}
    for i, pair in ipairs(pairsOf) do ring[2 * i - 1], ring[2 * i] = pair[1], pair[2] end
    rings[r] = ring
  end
  local holes, count = {}, #rings[1] / 2
  for r = 2, #rings do
    holes[r - 1] = rings[r]
    count = count + #rings[r] / 2
  end
  return rings[1], holes, count
end

--- The names of the fixtures, sorted.
function earcut.names()
  local names = {}
  local pipe = io.popen("ls " .. DIR)
  for line in pipe:lines() do
    local name = line:match("^(.+)%.json$")
    if name then names[#names + 1] = name end
  end
  pipe:close()
  table.sort(names)
  return names
end

return earcut
