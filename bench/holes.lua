-- Triangulation with holes against earcut (issue 28): earcut's fixtures with holes, tile maps
-- with 100+ holes and hole-free outlines of 100 to 10,000 vertices, polygonTriangulate's exact
-- validity check included. One table, side by side: LuaJIT and Lua 5.4, each warm (the best
-- round of 0.2 s once three in a row bring it down by less than 2%, after a warm-up of 0.5 s, in
-- milliseconds per call) and on its first call
-- in a fresh process (what a level load pays), against earcut in node likewise.
-- From the repository root: `luajit bench/holes.lua` (node and `npm install --prefix /tmp/earcut
-- earcut` for the earcut columns; EARCUT=file names another copy). Each measurement runs in its
-- own process: `lua5.4 bench/holes.lua warm tiles-40` or `... first tiles-40`.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local polygon = require "polygon"
local prng = require "prng"
local shapes = require "shapes"
local tiles = require "tiles"
local earcut = require "earcut"
local shell = require "bench.shell"

-- A tile map of size x size tiles (see tiles.level): the largest outline, its gaps as holes.
local function tileMap(size) return tiles.level(prng.new(size), size) end

-- name, and a function making points, holes
local CASES = {
  { "eberly-6", function() return earcut.load("eberly-6") end },
  { "rain", function() return earcut.load("rain") end },
  { "self-tangent-4", function() return earcut.load("self-tangent-4") end },
  { "touching-holes6", function() return earcut.load("touching-holes6") end },
  { "water2", function() return earcut.load("water2") end },
  { "water-huge3", function() return earcut.load("water-huge3") end },
  { "tiles-8", function() return tileMap(8) end },
  { "tiles-40", function() return tileMap(40) end },
  { "tiles-120", function() return tileMap(120) end },
  { "noisy-circle-100", function() return shapes.noisyCircle(100, prng.new(100)), {} end },
  { "noisy-circle-1000", function() return shapes.noisyCircle(1000, prng.new(1000)), {} end },
  { "noisy-circle-10000", function() return shapes.noisyCircle(10000, prng.new(10000)), {} end },
}

local function find(name)
  for _, case in ipairs(CASES) do
    if case[1] == name then return case[2]() end
  end
  error("no case " .. tostring(name))
end

local function vertexCount(points, holes)
  local n = #points / 2
  for _, hole in ipairs(holes) do n = n + #hole / 2 end
  return n
end

local mode, name = arg[1], arg[2]
if mode == "first" then
  local points, holes = find(name)
  local start = os.clock()
  local tris, message = polygon.polygonTriangulate(points, holes)
  local ms = (os.clock() - start) * 1e3
  print(name, ms, tris and #tris or -1, message or "")
  return
elseif mode == "warm" then
  -- rounds of 0.2 s after a warm-up of 0.5 s, until three in a row do not bring the best down
  -- by 2% (at most 10 s): LuaJIT compiles the triangulation's 400 to 1,400 traces at 0.4 to 1 ms
  -- each on these machines, for a second or more on the larger inputs, and three rounds after
  -- half a second timed the compiler as often as the code (bench/NOTES.md, session 21)
  local points, holes = find(name)
  local best, tris, message = math.huge
  local round, calm, began = 0, 0, os.clock()
  repeat
    local runs, start = 0, os.clock()
    repeat
      tris, message = polygon.polygonTriangulate(points, holes)
      runs = runs + 1
    until runs >= 2 and os.clock() - start > (round == 0 and 0.5 or 0.2)
    if round > 0 then
      local ms = (os.clock() - start) / runs * 1e3
      calm = ms < 0.98 * best and 0 or calm + 1
      best = math.min(best, ms)
    end
    round = round + 1
  until calm >= 3 or os.clock() - began > 10
  print(name, best, tris and #tris or -1, message or "")   -- the count: the checksum
  return
elseif mode == "export" then
  -- earcut's input: the vertices flat, the holes as the indices where they start
  for _, case in ipairs(CASES) do
    local points, holes = case[2]()
    local flat, starts = {}, {}
    for i, v in ipairs(points) do flat[i] = ("%.17g"):format(v) end
    for _, hole in ipairs(holes) do
      starts[#starts + 1] = #flat / 2
      for _, v in ipairs(hole) do flat[#flat + 1] = ("%.17g"):format(v) end
    end
    local f = assert(io.open(("%s/%s.json"):format(name, case[1]), "w"))
    f:write('{"vertices":[', table.concat(flat, ","), '],"holes":[', table.concat(starts, ","), "]}\n")
    f:close()
  end
  return
end

local run, have = shell.words, shell.have
local dir = shell.tempDir()
local self = arg[-1] or "lua"
assert(shell.ok(("%s bench/holes.lua export %s"):format(self, dir)))
local earcutFile = shell.earcut()
local warmEarcut = {}
local withEarcut = earcutFile ~= nil
if withEarcut then
  local pipe = assert(io.popen(("EARCUT=%s node bench/earcut-holes.js %s"):format(earcutFile, dir)))
  for line in pipe:lines() do
    local n, ms = line:match("^(%S+) %S+ (%S+)")
    if n then warmEarcut[n] = tonumber(ms) end
  end
  pipe:close()
end

local luas = {}
for _, lua in ipairs({ "luajit", "lua5.4" }) do if have(lua) then luas[#luas + 1] = lua end end
print(("polygonTriangulate (its exact validity check included) against earcut %s; milliseconds per call")
  :format(withEarcut and "in node" or "(skipped)"))
print("warm: the best round once it settles, after a warm-up; first: the first call in a fresh process")
print(("%-19s %6s %5s | %9s %9s %6s | %9s %9s %6s | %9s %9s"):format("input", "n", "holes",
  "LuaJIT", "earcut", "ratio", "LuaJIT 1st", "earcut 1st", "ratio", "Lua 5.4", "5.4 1st"))
local perVertex, failed = {}, false
for _, case in ipairs(CASES) do
  local label = case[1]
  local points, holes = case[2]()
  local n = vertexCount(points, holes)
  local cells = {}
  for _, lua in ipairs(luas) do
    local warm = run(("%s bench/holes.lua warm %s"):format(lua, label))
    local first = run(("%s bench/holes.lua first %s"):format(lua, label))
    if not tonumber(warm[3]) or tonumber(warm[3]) < 0 then   -- a refusal or an error: no time
      io.stderr:write(("bench/holes.lua: %s on %s: %s\n"):format(label, lua, table.concat(warm, " ")))
      failed, warm[2] = true, nil
    end
    cells[lua] = { tonumber(warm[2]), tonumber(first[2]) }
  end
  local ew, ef = warmEarcut[label], nil
  if withEarcut then
    ef = tonumber(run(("EARCUT=%s node bench/earcut-holes.js %s %s"):format(earcutFile, dir, label))[3])
  end
  local jit, puc = cells.luajit or {}, cells["lua5.4"] or {}
  local function ms(v) return v and ("%.4g"):format(v) or "-" end   -- 4 digits: tiles-8 takes 0.004
  local function ratio(a, b) return a and b and b > 0 and ("%.1fx"):format(a / b) or "-" end
  print(("%-19s %6d %5d | %9s %9s %6s | %9s %9s %6s | %9s %9s"):format(label, n, #holes,
    ms(jit[1]), ms(ew), ratio(jit[1], ew), ms(jit[2]), ms(ef), ratio(jit[2], ef), ms(puc[1]), ms(puc[2])))
  perVertex[label] = { jit[1] and jit[1] / n, puc[1] and puc[1] / n }
end
local function growth(small, large, which)
  local a, b = perVertex[small] and perVertex[small][which], perVertex[large] and perVertex[large][which]
  return a and b and ("%.2f"):format(b / a) or "-"
end
print()
print("cost per vertex, the largest input's over the smallest's (target: at most 2), one input repeated")
print("(the processor learns a small call repeated: inputs in turn, `luajit bench/cycled.lua`)")
print(("%-40s %8s %8s"):format("", "LuaJIT", "Lua 5.4"))
print(("%-40s %8s %8s"):format("noisy-circle-10000 / noisy-circle-100",
  growth("noisy-circle-100", "noisy-circle-10000", 1), growth("noisy-circle-100", "noisy-circle-10000", 2)))
print(("%-40s %8s %8s"):format("tiles-120 / tiles-8 (holes included)", growth("tiles-8", "tiles-120", 1),
  growth("tiles-8", "tiles-120", 2)))
shell.ok("rm -rf " .. dir)
if failed then os.exit(1) end
