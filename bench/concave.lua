-- Time per vertex of polygonTriangulate and polygonConvexParts at 100, 1,000 and 10,000
-- vertices, on outlines of two kinds: a noisy circle (random radii, half its vertices reflex)
-- and a thick spiral. Run from the repository root: `luajit bench/concave.lua` (any Lua).
-- `lua bench/concave.lua export DIR` writes the same outlines as JSON for bench/earcut.js.
package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local polygon = require "polygon"
local prng = require "prng"
local oracle = require "oracle"

local shapes = require "shapes"
local shell = require "bench.shell"

local SIZES = { 100, 1000, 10000 }

local function noisyCircle(n) return shapes.noisyCircle(n, prng.new(n)) end

-- more turns for more vertices keeps the edges short
local function spiral(n) return shapes.spiral(n, math.max(2, math.floor(math.sqrt(n) / 16))) end

local KINDS = { { "noisy circle", noisyCircle }, { "spiral", spiral } }

-- Hard cases (where love.math.triangulate or naive ear clipping fail): each is a flat array and
-- whether it is a valid polygon.
local function translated(points, d) return shapes.translate(points, d, d) end
local U = { 0, 0, 50, 0, 50, 200, 250, 200, 250, 0, 300, 0, 300, 250, 0, 250 }
local L = { 0, 0, 20, 0, 20, 10, 10, 10, 10, 20, 0, 20 }
local GON = {}
for i = 0, 255 do
  GON[#GON + 1], GON[#GON + 2] = 5e5 + math.cos(i * math.pi / 128), 5e5 + math.sin(i * math.pi / 128)
end
local TILES = {   -- a 4 x 4 tile map with three pinch points (spec/support/tiles.lua's walk)
  0, 0, 10, 0, 10, 10, 20, 10, 20, 0, 30, 0, 30, 10, 40, 10, 40, 20, 30, 20, 30, 30, 40, 30,
  40, 40, 30, 40, 30, 30, 20, 30, 20, 20, 10, 20, 10, 30, 0, 30, 0, 20, 10, 20, 10, 10, 0, 10 }
local HARD = {
  { "pinched-tiles", { 0, 0, 10, 0, 10, 10, 20, 10, 20, 20, 10, 20, 10, 10, 0, 10 }, true },
  { "tile-map-4x4", TILES, true },
  { "256-gon-at-5e5", GON, true },
  { "U-at-1e8", translated(U, 1e8), true },
  { "L-at-1e7", translated(L, 1e7), true },
  { "bow-tie", { 0, 0, 10, 10, 10, 0, 0, 20, -10, 20, -10, 10 }, false },
}

local function numbers(points)
  local out = {}
  for i, v in ipairs(points) do out[i] = ("%.17g"):format(v) end
  return table.concat(out, ",")
end

-- Writes every outline as DIR/name.json (for earcut) and DIR/cases.lua (for LÖVE).
local function export(dir)
  local cases = {}
  local function put(name, points)
    local f = assert(io.open(("%s/%s.json"):format(dir, name), "w"))
    f:write("[", numbers(points), "]\n")
    f:close()
    cases[#cases + 1] = ("{ %q, { %s } }"):format(name, numbers(points))
  end
  for _, kind in ipairs(KINDS) do
    for _, n in ipairs(SIZES) do put(("%s-%d"):format(kind[1]:gsub(" ", "-"), n), kind[2](n)) end
  end
  for _, case in ipairs(HARD) do put(case[1], case[2]) end
  local f = assert(io.open(dir .. "/cases.lua", "w"))
  f:write("return {\n", table.concat(cases, ",\n"), "\n}\n")
  f:close()
end

if arg[1] == "export" then export(arg[2]); return end

-- Runs f(points) for 0.5 s to warm up (LuaJIT takes hundreds of runs to settle), then three
-- rounds of 0.2 s (at least two runs each);
-- returns the best round's time per vertex in microseconds (the machine is shared: the best is
-- the least disturbed) and the pieces of the last run (their count is the checksum that keeps
-- the work from being skipped), or nil and the message.
local function timePerVertex(f, points)
  local best, pieces = math.huge, nil
  for round = 0, 3 do
    local runs, start = 0, os.clock()
    repeat
      local message
      pieces, message = f(points)
      if not pieces then return nil, message end
      runs = runs + 1
    until runs >= 2 and os.clock() - start > (round == 0 and 0.5 or 0.2)
    if round > 0 then best = math.min(best, (os.clock() - start) / runs / (#points / 2) * 1e6) end
  end
  return best, pieces
end

-- The relative error of the pieces' total area (each piece's area to an ulp).
local function areaError(points, pieces)
  local sum = 0
  for _, piece in ipairs(pieces) do sum = sum + polygon.polygonAreaAccurate(piece) end
  local area = polygon.polygonAreaAccurate(points)
  return math.abs(sum - area) / area
end

-- Runs a command, returning its output lines split into fields keyed by the first.
local function fieldsOf(command)
  local pipe = io.popen(command)
  local out = {}
  for line in pipe:lines() do
    local fields = {}
    for word in line:gmatch("%S+") do fields[#fields + 1] = word end
    if #fields > 0 then out[fields[1]] = fields end
  end
  pipe:close()
  return out
end

local dir = shell.tempDir()
export(dir)
local earcutFile = shell.earcut()
local earcut, love = {}, {}
if earcutFile then earcut = fieldsOf(("EARCUT=%s node bench/earcut.js %s"):format(earcutFile, dir)) end
local haveLove = "command -v love >/dev/null 2>&1 && command -v xvfb-run >/dev/null 2>&1"
if os.getenv("LOVE") ~= "0" and shell.ok(haveLove) then
  assert(shell.ok(("cp bench/love-triangulate.lua %s/main.lua"):format(dir)))
  love = fieldsOf(("xvfb-run -a love %s 2>/dev/null"):format(dir))
else
  print("(love.math.triangulate skipped: needs love and xvfb-run)")
end
local jit = rawget(_G, "jit")
print(("%s; microseconds per vertex; earcut on node, love.math.triangulate in LÖVE (LuaJIT)")
  :format(jit and jit.version or _VERSION))
print(("%-19s %6s %9s %9s %6s %6s %9s %7s %9s"):format("outline", "n", "triangul.", "convexP.", "parts",
  "bound", "earcut", "ratio", "love"))
local function row(name, points)
  local n = #points / 2
  local tt, tris = timePerVertex(polygon.polygonTriangulate, points)
  local tp, parts = timePerVertex(polygon.polygonConvexParts, points)
  local e, l = earcut[name], love[name]
  local et = e and tonumber(e[3])
  -- the fewest convex parts possible are at least ceil(r / 2) + 1, r the reflex vertices
  local bound = math.ceil(oracle.reflexCount(points) / 2) + 1
  print(("%-19s %6d %9s %9s %6s %6d %9s %7s %9s"):format(name, n,
    tt and ("%.2f"):format(tt) or "nil", tp and ("%.2f"):format(tp) or "nil", tp and #parts or "-", bound,
    et and et >= 0 and ("%.2f"):format(et) or "-",
    tt and et and et > 0 and ("%.1fx"):format(tt / et) or "-",
    l and (l[2] == "fail" and "fails" or ("%.2f"):format(tonumber(l[3]))) or "-"))
  return tris
end
for _, kind in ipairs(KINDS) do
  for _, n in ipairs(SIZES) do row(("%s-%d"):format(kind[1]:gsub(" ", "-"), n), kind[2](n)) end
end
print()
print("hard cases: relative area error of the pieces (0: exact), or what went wrong")
print(("%-19s %-22s %-22s %-22s"):format("outline", "polygon.lua", "earcut", "love.math.triangulate"))
for _, case in ipairs(HARD) do
  local name, points, valid = case[1], case[2], case[3]
  local tris, message = polygon.polygonTriangulate(points)
  local mine = tris and ("%d tris, %.1e"):format(#tris, areaError(points, tris)) or ("nil: " .. message)
  local e, l = earcut[name], love[name]
  local theirs = e and (tonumber(e[3]) < 0 and "throws"
    or ("%s tris, %.1e"):format(e[4], tonumber(e[5]))) or "-"
  local lov = l and (l[2] == "fail" and "fails" or ("%s tris, %.1e"):format(l[4], tonumber(l[5]))) or "-"
  print(("%-19s %-22s %-22s %-22s%s"):format(name, mine, theirs, lov, valid and "" or "  (invalid input)"))
end
shell.ok("rm -rf " .. dir)
