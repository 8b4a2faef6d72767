-- Differential test of polygon.lua against itself: every public function as it was at 5ffb0ce
-- (OLD, the last single-file release) against the one `require "polygon"` finds in the working
-- tree (NEW), on the same random arguments, every result compared bit for bit. It is the proof
-- that splitting the file into modules changed no behaviour, errors and their messages included.
--
-- From the repository root, on lua5.1, lua5.2, lua5.3, lua5.4 or luajit:
--   lua bench/differential.lua [CALLS] [SEED]
-- CALLS: random calls per public function (default 1000000); SEED: the seed of spec/support/prng.lua
-- (default 1). Each function draws from its own stream, made from the seed and its name, so
--   POLYGON_DIFF_ONLY=polygonsCollideV lua bench/differential.lua 4711 1
-- replays that function's first 4711 calls alone: a reported difference's call comes last.
-- Environment:
--   POLYGON_OLD=path              OLD from this file instead of `git show 5ffb0ce:polygon.lua`
--   POLYGON_NEW=path              NEW from this file instead of require (a patched copy, to see
--                                 that this script notices)
--   POLYGON_DIFF_ONLY=name        only this function, named as printed
--   POLYGON_DIFF_POSITIONS=exact  positions inside the library compared too (see sameError)
-- Prints per function the calls made and the differences found, each difference with its
-- function, seed, call and both results, and stops after 20. The last line reads
-- "differential: N calls, D differences"; the exit status is 1 when D > 0.
-- `make test` runs it with 20,000 calls a function on LuaJIT; the full run is `make differential`.

package.path = "./?.lua;./spec/support/?.lua;" .. package.path
local prng = require "prng"
local shapes = require "shapes"
local samples = require "samples"
local scenes = require "scenes"
local tiles = require "tiles"

local unpack = rawget(table, "unpack") or rawget(_G, "unpack")
local loadString = rawget(_G, "loadstring") or load   -- Lua 5.1's load takes no string
local mathType = rawget(math, "type")                  -- nil before Lua 5.3: no integer subtype
local toInteger = rawget(math, "tointeger")
local floor, huge = math.floor, math.huge

local OLD_COMMIT = "5ffb0ce"
local MAX_DIFFERENCES = 20
local NAN, INF = 0 / 0, math.huge
local NEG_ZERO = -1 / math.huge
-- An integer no double holds (2^53 + 1), where Lua 5.3+ has one: the module converts integers to
-- doubles before it compares them, and must keep doing so.
local BEYOND_DOUBLES = toInteger and toInteger(2 ^ 53) + 1 or 2 ^ 53

--------------------------------------------------------------------------------------------------
-- The two modules
--------------------------------------------------------------------------------------------------

-- Every module is loaded under the chunk name require gives ./polygon.lua on "./?.lua": an error
-- raised inside the library (a string coordinate reaches arithmetic) carries "./polygon.lua:749:",
-- and OLD's must read the same as NEW's while the code is the same. That is why OLD is loaded
-- from a string rather than from a temporary file: loadfile would name it after the file.
local CHUNK_NAME = "@./polygon.lua"

local function readAll(file, what)
  if not file then error("cannot read " .. what, 0) end
  local text = file:read("*a")
  file:close()
  if not text or text == "" then error("nothing read from " .. what, 0) end
  return text
end

-- The source of OLD: POLYGON_OLD's file, else polygon.lua at OLD_COMMIT from git.
local function oldSource()
  local path = os.getenv("POLYGON_OLD")
  if path and path ~= "" then return readAll(io.open(path, "rb"), path) end
  local command = "git show " .. OLD_COMMIT .. ":polygon.lua"
  return readAll(io.popen(command, "r"), command .. " (run from the repository root, or set POLYGON_OLD)")
end

-- Runs a module's source as require would (its name as `...`, so a front that takes its
-- modules' prefix from `...` finds them) and returns what it returns.
local function moduleFrom(source, what)
  local chunk, message = loadString(source, CHUNK_NAME)
  if not chunk then error(what .. ": " .. message, 0) end
  return chunk("polygon")
end

-- Three instances of the library (OLD, NEW and the helper below) need about three times the
-- traces one game does: the limits raised as the README tells a game to, and further. Without it
-- LuaJIT flushed all its traces over and over here, and the triangulation crawled (bench/NOTES.md).
local JIT = rawget(_G, "jit")
if JIT then JIT.opt.start("maxtrace=30000", "maxmcode=65536", "sizemcode=1024") end

local OLD_SOURCE = oldSource()
local OLD = moduleFrom(OLD_SOURCE, "OLD")
-- A third instance of the old code builds the arguments that need the library (convex parts to
-- collide, pushes to follow): calling OLD or NEW for them would fill one side's caches of lists
-- of parts and not the other's.
local HELPER = moduleFrom(OLD_SOURCE, "the helper")

local function newModule()
  local path = os.getenv("POLYGON_NEW")
  if path and path ~= "" then return moduleFrom(readAll(io.open(path, "rb"), path), path) end
  return require "polygon"
end
local NEW = newModule()

--------------------------------------------------------------------------------------------------
-- Comparing results bit for bit
--------------------------------------------------------------------------------------------------

-- Numbers are the same when they are the same double (or integer): NaN equals NaN, 0 and -0
-- differ, and so do 3 and 3.0 on Lua 5.3+.
local function sameNumber(a, b)
  if mathType and mathType(a) ~= mathType(b) then return false end
  if a ~= a then return b ~= b end
  return a == b and (a ~= 0 or 1 / a == 1 / b)
end

-- Objects of the class: OLD's on the old side stand for NEW's on the new side.
local CLASSES = { [OLD.Polygon] = NEW.Polygon, [HELPER.Polygon] = HELPER.Polygon }

-- Error messages are compared exactly, but for one thing a split must move: an error raised inside
-- the library itself (not an argument check: arithmetic on a string coordinate, say) starts with
-- the file and line that raised it, "./polygon.lua:749:" before the split and, say,
-- "./polygon/measures.lua:51:" after. Two such messages are the same when both positions are in
-- the library and the rest is equal; they are counted (movedPositions) and printed. An argument
-- error's position is its caller's (here pcall's: none), so a changed error level is still a
-- difference. POLYGON_DIFF_POSITIONS=exact compares those positions too.
local EXACT_POSITIONS = os.getenv("POLYGON_DIFF_POSITIONS") == "exact"
local movedPositions = 0

-- The message without a position inside the library (polygon.lua or polygon/*.lua), or nil.
local function withoutLibraryPosition(message)
  if type(message) ~= "string" then return nil end
  return message:match("^%./polygon%.lua:%d+: (.*)$") or message:match("^%./polygon/[%w_]+%.lua:%d+: (.*)$")
end

local function sameError(a, b)
  if a == b then return true end
  local restA = withoutLibraryPosition(a)
  if EXACT_POSITIONS or not restA or restA ~= withoutLibraryPosition(b) then return false end
  movedPositions = movedPositions + 1
  return true
end

local function keyName(k)
  if type(k) == "string" then return "." .. k end
  return "[" .. tostring(k) .. "]"
end

-- Pairs every table (and function, and metatable) reachable from the old side's arguments with
-- the new side's (the same when the arguments are shared): a result that is an argument must be
-- the same argument on both sides, and arguments built once per side correspond.
local function pairInputs(old, new, map)
  map[old] = new
  if type(old) ~= "table" then return end
  for k, v in pairs(old) do
    local kind = type(v)
    if (kind == "table" or kind == "function") and map[v] == nil then
      local w = rawget(new, k)
      if type(w) == kind then pairInputs(v, w, map) end
    end
  end
  local meta, newMeta = getmetatable(old), getmetatable(new)
  if type(meta) == "table" and type(newMeta) == "table" and map[meta] == nil then
    pairInputs(meta, newMeta, map)
  end
end

-- The comparison's memory for one call: the arguments of both sides, and (built on first use:
-- most calls return no table) which tables were paired already (the same sharing on both sides)
-- and which are arguments. lengths: compare # too.
local function newContext(args, argsNew, n, lengths)
  return { args = args, argsNew = argsNew, n = n, lengths = lengths }
end

local function inputsOf(ctx)
  if ctx.inputs then return ctx.inputs, ctx.newInputs end
  local inputs, newInputs = {}, {}
  for i = 1, ctx.n do
    local a, b = ctx.args[i], ctx.argsNew[i]
    local kind = type(a)
    if (kind == "table" or kind == "function") and type(b) == kind and inputs[a] == nil then
      pairInputs(a, b, inputs)
    end
  end
  for a, b in pairs(inputs) do newInputs[b] = a end
  ctx.inputs, ctx.newInputs, ctx.paired, ctx.pairedNew = inputs, newInputs, {}, {}
  return inputs, newInputs
end

local compare

-- The first difference between two tables, or nil; said from the table down ("[2][5]: ...").
local function compareTables(a, b, ctx)
  local inputs, newInputs = inputsOf(ctx)
  local input = inputs[a]
  if (input ~= nil or newInputs[b] ~= nil) and input ~= b then
    return ": one side returns an argument table, the other another table"
  end
  if rawequal(a, b) then return nil end
  local paired = ctx.paired[a]
  if paired ~= nil or ctx.pairedNew[b] ~= nil then
    if paired ~= b then return ": tables shared differently" end
    return nil
  end
  ctx.paired[a], ctx.pairedNew[b] = b, a
  local metaA, metaB = getmetatable(a), getmetatable(b)
  if metaA ~= metaB and (metaA == nil or (CLASSES[metaA] ~= metaB and inputs[metaA] ~= metaB)) then
    return ": different metatables"
  end
  if ctx.lengths and #a ~= #b then return (": lengths %d and %d"):format(#a, #b) end
  for k, v in pairs(a) do
    local w = rawget(b, k)
    if w == nil then return keyName(k) .. ": missing on the new side" end
    local difference = compare(v, w, ctx)
    if difference then return keyName(k) .. difference end
  end
  for k in pairs(b) do
    if rawget(a, k) == nil then return keyName(k) .. ": only on the new side" end
  end
  return nil
end

function compare(a, b, ctx)
  local kind = type(a)
  if kind ~= type(b) then return (": a %s and a %s"):format(kind, type(b)) end
  if kind == "number" then
    if sameNumber(a, b) then return nil end
    return ": different numbers"
  end
  if kind == "table" then return compareTables(a, b, ctx) end
  if a ~= b and inputsOf(ctx)[a] ~= b then return ": different values" end
  return nil
end

-- The first difference between two packed results (pcall's status first), or nil.
local function compareResults(old, new, ctx)
  if old[1] ~= new[1] then return "an error on one side only" end
  if old[1] == false then
    if sameError(old[2], new[2]) then return nil end
    local restOld = withoutLibraryPosition(old[2])
    if restOld and restOld == withoutLibraryPosition(new[2]) then
      return "error messages that differ in the library position only (POLYGON_DIFF_POSITIONS=exact)"
    end
    return "different error messages"
  end
  if old.n ~= new.n then return ("%d values returned and %d"):format(old.n - 1, new.n - 1) end
  for i = 2, old.n do
    local difference = compare(old[i], new[i], ctx)
    if difference then return ("value %d%s"):format(i - 1, difference) end
  end
  return nil
end

local function pack(...)
  return { n = select("#", ...), ... }
end

--------------------------------------------------------------------------------------------------
-- Showing values (a difference is printed with both results and the arguments)
--------------------------------------------------------------------------------------------------

local function showNumber(x)
  if mathType and mathType(x) == "integer" then return tostring(x) end
  if x ~= x then return "nan" end
  if x == 0 then return 1 / x < 0 and "-0.0" or "0.0" end
  local text = ("%.17g"):format(x)
  -- on Lua 5.3+ a float that prints as an integer would pass for one
  if mathType and not text:find("[%.eni]") then text = text .. ".0" end
  return text
end

local show

local function showTable(t, depth, seen)
  if seen[t] then return "<cycle>" end
  if depth > 3 then return "{...}" end
  seen[t] = true
  local items, n = {}, #t
  for i = 1, math.min(n, 64) do items[#items + 1] = show(t[i], depth + 1, seen) end
  if n > 64 then items[#items + 1] = ("...(%d entries)"):format(n) end
  local keys = {}
  for k in pairs(t) do
    if not (type(k) == "number" and k >= 1 and k <= n and k == floor(k)) then keys[#keys + 1] = k end
  end
  table.sort(keys, function(p, q) return tostring(p) < tostring(q) end)
  for _, k in ipairs(keys) do
    items[#items + 1] = "[" .. show(k, depth + 1, seen) .. "]=" .. show(t[k], depth + 1, seen)
  end
  seen[t] = nil
  local meta = getmetatable(t) and "<meta>" or ""
  return meta .. "{" .. table.concat(items, ", ") .. "}"
end

function show(v, depth, seen)
  local kind = type(v)
  if kind == "number" then return showNumber(v) end
  if kind == "string" then return ("%q"):format(v) end
  if kind == "table" then return showTable(v, depth or 1, seen or {}) end
  return tostring(v)
end

local function showList(list, first, last)
  local items = {}
  for i = first, last do items[#items + 1] = show(list[i]) end
  local text = table.concat(items, ", ")
  if #text > 2000 then text = text:sub(1, 2000) .. " ..." end
  return text
end

--------------------------------------------------------------------------------------------------
-- Random numbers and the placement of a drawing
--------------------------------------------------------------------------------------------------

-- A string hash (h * 31 + byte, modulo 2^31 - 1: below 2^36, exact everywhere): each function's
-- stream starts from its name and the seed, so one function's calls can be replayed alone.
local function streamFor(seed, name)
  local h = 0
  local text = ("%d/%s"):format(seed, name)
  for i = 1, #text do h = (h * 31 + text:byte(i)) % 2147483647 end
  return prng.new(h)
end

local function chance(rng, n) return rng:int(1, n) == 1 end
local function sign(rng) return rng:int(0, 1) * 2 - 1 end

-- Picks from a list of { weight, value } pairs.
local function weighted(rng, list)
  local total = 0
  for _, entry in ipairs(list) do total = total + entry[1] end
  local r = rng:int(1, total)
  for _, entry in ipairs(list) do
    r = r - entry[1]
    if r <= 0 then return entry[2] end
  end
end

-- Offsets far from the origin, where a double keeps few bits below the unit.
local FAR = { 1e6 + 0.5, 1e9, 1e12, 1e15 }

-- 10^k, an integer on Lua 5.3+ (so that integer coordinates moved by it stay integers).
local function powerOfTen(k)
  return toInteger and toInteger(10 ^ k) or 10 ^ k
end

-- Where one call's shapes are put, all alike so that shapes made to touch stay close: as made
-- half the time, else far from the origin, scaled by 1e-300 .. 1e300 (or a power of two, which
-- is exact), rounded to integers (Lua 5.3+ integers where math.floor gives them, some turned
-- back to floats), or moved past 2^53 as integers.
local function drawPlacement(rng)
  local place = { scale = 1, dx = 0, dy = 0, round = false, mixed = false }
  local kind = rng:int(1, 16)
  if kind <= 8 then return place end
  if kind <= 11 then
    place.dx = FAR[rng:int(1, #FAR)] * sign(rng)
    place.dy = chance(rng, 2) and place.dx or FAR[rng:int(1, #FAR)] * sign(rng)
  elseif kind <= 13 then
    place.scale = chance(rng, 2) and 2 ^ rng:int(-990, 990) or 10 ^ rng:int(-300, 300)
  elseif kind <= 15 then
    place.round, place.mixed = true, chance(rng, 3)
    if chance(rng, 3) then place.dx, place.dy = powerOfTen(rng:int(6, 15)), -powerOfTen(rng:int(6, 15)) end
  else
    place.round, place.dx, place.dy = true, BEYOND_DOUBLES, -BEYOND_DOUBLES
  end
  return place
end

local function placeNumber(place, rng, v, offset)
  v = v * place.scale
  if place.round then
    v = floor(v + 0.5)   -- an integer on Lua 5.3+ when it fits
    if place.mixed and chance(rng, 3) then v = v + 0.0 end
  end
  return v + offset   -- after the rounding: an integer offset keeps integers exact
end

-- A new copy of a flat array or a list of them, placed; entries that are not numbers stay.
local function placeShape(place, rng, shape)
  if type(shape) ~= "table" or (place.scale == 1 and place.dx == 0 and place.dy == 0
      and not place.round) then
    return shape
  end
  local out = {}
  for i = 1, #shape do
    local v = shape[i]
    if type(v) == "number" then
      out[i] = placeNumber(place, rng, v, i % 2 == 1 and place.dx or place.dy)
    else
      out[i] = placeShape(place, rng, v)
    end
  end
  return out
end

-- The spacing of doubles at |x| (shapes.ulp's, which never ends for an infinite x: 0 then).
local function ulp(x)
  if x - x ~= 0 then return 0 end
  return shapes.ulp(math.abs(x) + 0.0)
end

-- The spacing of doubles around the largest magnitude in a flat array (or list): one ulp there.
local function ulpOf(shape)
  local largest = 0
  for i = 1, type(shape) == "table" and #shape or 0 do
    local v = shape[i]
    if type(v) == "table" then
      largest = math.max(largest, ulpOf(v))
    elseif type(v) == "number" and v - v == 0 then
      largest = math.max(largest, ulp(v))
    end
  end
  return largest
end

-- The box of whatever numbers a (possibly broken) shape holds, for aiming points and circles at
-- it: xmin, ymin, xmax, ymax, or a box at the origin when it has none.
local function looseBounds(shape, box)
  box = box or { huge, huge, -huge, -huge }
  if type(shape) ~= "table" then return box end
  for i = 1, #shape do
    local v = shape[i]
    if type(v) == "table" then
      looseBounds(v, box)
    elseif type(v) == "number" and v - v == 0 then
      local axis = (i % 2 == 1) and 0 or 1
      box[1 + axis], box[3 + axis] = math.min(box[1 + axis], v), math.max(box[3 + axis], v)
    end
  end
  return box
end

local function boundsOf(shape)
  local box = looseBounds(shape)
  if box[1] > box[3] or box[2] > box[4] then return 0, 0, 1, 1 end
  return box[1], box[2], box[3], box[4]
end

--------------------------------------------------------------------------------------------------
-- Scalars: the ordinary ones and the ones argument checks exist for
--------------------------------------------------------------------------------------------------

local NOTHING = {}   -- stands for nil in lists of choices
local SPECIALS = { NAN, INF, -INF, 0, NEG_ZERO, 1e308, 5e-324, -1, 7, 2 ^ 53, BEYOND_DOUBLES,
  "1", "x", true, false, NOTHING, {} }

local function special(rng)
  local v = SPECIALS[rng:int(1, #SPECIALS)]
  if v == NOTHING then return nil end
  if type(v) == "table" then return {} end
  return v
end

-- A number for a coordinate-like argument around lo .. hi: a float, an integer, or one time in
-- `rare` a special value.
local function scalar(rng, lo, hi, rare)
  if chance(rng, rare or 24) then return special(rng) end
  if chance(rng, 4) then return rng:int(floor(lo), floor(hi)) end
  return rng:range(lo, hi)
end

--------------------------------------------------------------------------------------------------
-- Flat polygons: what users make, and the hard ones
--------------------------------------------------------------------------------------------------

local function convexShape(rng)
  return shapes.convex(rng, rng:int(3, 20), rng:range(-400, 400), rng:range(-400, 400),
    rng:range(1, 200), rng:range(0, 0.49))
end

-- An axis-parallel box of integers (a tile, a crate), sometimes flat (zero width or height).
local function boxShape(rng)
  local x, y = rng:int(-300, 300), rng:int(-300, 300)
  local w, h = rng:int(chance(rng, 20) and 0 or 1, 200), rng:int(1, 200)
  return { x, y, x + w, y, x + w, y + h, x, y + h }
end

local function starShape(rng)
  return shapes.star(rng, rng:int(3, 20), rng:range(-300, 300), rng:range(-300, 300), rng:range(5, 200))
end

local function noisyShape(rng) return shapes.noisyCircle(rng:int(3, 20), rng) end
local function spiralShape(rng) return shapes.spiral(2 * rng:int(4, 14), rng:range(0.5, 2)) end

-- pairs() order is not the same on every run: the samples by name, in a fixed order.
local SAMPLE_NAMES = { "SQUARE", "SQUARE_CCW", "L", "OVERLAP", "TOUCH", "APART", "INSIDE",
  "REPEATED", "CLOSED", "TRIANGLE", "SEGMENT", "TWO", "STAR", "SLIVER" }
local function sampleShape(rng)
  return shapes.translate(samples[SAMPLE_NAMES[rng:int(1, #SAMPLE_NAMES)]], 0, 0)
end

-- Self-intersecting: a bow-tie, or a few points in any order on a small grid (repeated and
-- collinear vertices, spikes and crossings galore).
local function bowTieShape(rng)
  local w, h = rng:int(1, 50), rng:int(1, 50)
  return { 0, 0, w, h, w, 0, 0, h }
end

local function scatteredShape(rng)
  local points = {}
  for i = 1, 2 * rng:int(3, 10) do points[i] = rng:int(0, 8) end
  return points
end

-- All on one line, as integer steps along (a, b): zero area, spikes, repeats.
local function collinearShape(rng)
  local a, b, points = rng:int(-5, 5), rng:int(-5, 5), {}
  local x0, y0 = rng:int(-100, 100), rng:int(-100, 100)
  for i = 1, rng:int(3, 8) do
    local t = rng:int(-10, 10)
    points[2 * i - 1], points[2 * i] = x0 + t * a, y0 + t * b
  end
  return points
end

-- Three or more points on a line, one of them moved off it by an ulp: the signs that need the
-- exact stages.
local function nearlyCollinearShape(rng)
  local a, b = rng:range(1, 1e6), rng:range(1, 1e6)
  local points = { 0, 0, a, b, 2 * a, 2 * b, 3 * a, 3 * b }
  if chance(rng, 2) then points[7], points[8] = nil, nil end
  local i = rng:int(1, #points)
  points[i] = points[i] + sign(rng) * ulp(math.abs(points[i]) + 1)
  return points
end

-- A convex polygon with a vertex repeated, or the first repeated at the end.
local function repeatedShape(rng)
  local points = convexShape(rng)
  local i = 2 * rng:int(1, #points / 2) - 1
  table.insert(points, i, points[i + 1])
  table.insert(points, i, points[i + 1])
  return points
end

-- A square with a spike that goes out and comes straight back.
local function spikeShape(rng)
  local s, t = rng:int(2, 50), rng:int(1, 50)
  return { 0, 0, s, 0, s + t, 0, s, 0, s, s, 0, s }
end

local function fewShape(rng)
  local points = {}
  for i = 1, 2 * rng:int(0, 2) do points[i] = rng:range(-100, 100) end
  return points
end

local FLAT_KINDS = {
  { 30, convexShape }, { 10, boxShape }, { 10, starShape }, { 5, noisyShape }, { 3, spiralShape },
  { 7, sampleShape }, { 3, bowTieShape }, { 7, scatteredShape }, { 5, collinearShape },
  { 5, nearlyCollinearShape }, { 5, repeatedShape }, { 2, spikeShape }, { 3, fewShape },
}

-- A new flat polygon of any kind, either winding.
local function flatShape(rng)
  local points = weighted(rng, FLAT_KINDS)(rng)
  if chance(rng, 2) then points = shapes.reverse(points) end
  return points
end

-- A convex polygon of the ordinary kinds (what the one-sided SAT functions are for).
local function convexOrBox(rng)
  local points = chance(rng, 4) and boxShape(rng) or convexShape(rng)
  if chance(rng, 2) then points = shapes.reverse(points) end
  return points
end

--------------------------------------------------------------------------------------------------
-- Broken arguments: every check the module makes, and what slips past them
--------------------------------------------------------------------------------------------------

-- A table that reads as the points through its metatable (# honours __len from Lua 5.2 on).
local function proxyOf(points)
  return setmetatable({}, { __index = points, __len = function() return #points end })
end

local function pairsOf(points, asFields)
  local out = {}
  for i = 1, #points - 1, 2 do
    out[#out + 1] = asFields and { x = points[i], y = points[i + 1] } or { points[i], points[i + 1] }
  end
  return out
end

-- The points (a fresh table, changed here) or something else in their place.
local function spoil(rng, points)
  local n = #points
  local kind = rng:int(1, 17)
  if n < 2 and kind >= 5 and kind <= 10 then kind = 1 end
  if kind == 1 then return nil end
  if kind == 2 then return "points" end
  if kind == 3 then return 42 end
  if kind == 4 then return true end
  if kind == 5 then points[n] = nil                                   -- an odd count
  elseif kind == 6 then points[rng:int(1, n)] = NAN
  elseif kind == 7 then points[rng:int(1, n)] = INF * sign(rng)
  elseif kind == 8 then points[rng:int(1, n)] = ({ "1", "x", "0x10" })[rng:int(1, 3)]
  elseif kind == 9 then points[rng:int(1, n)] = chance(rng, 2)
  elseif kind == 10 then points[rng:int(1, n - 1)] = nil              -- a hole in the array
  elseif kind == 11 then return pairsOf(points, false)                 -- {{x, y}, ...}
  elseif kind == 12 then return pairsOf(points, true)                  -- {{x =, y =}, ...}
  elseif kind == 13 then return setmetatable({ points = points }, HELPER.Polygon)
  elseif kind == 14 then return proxyOf(points)
  elseif kind == 15 then return {}
  elseif kind == 16 then points.n, points.name = n, "crate"           -- fields beside the array
  else return function() end end
  return points
end

--------------------------------------------------------------------------------------------------
-- Lists of convex parts
--------------------------------------------------------------------------------------------------

-- Lists the helper made once, at start, from their own stream: convex parts and triangles of
-- concave shapes (of tile maps with holes too), and compound scenes. A call takes a copy.
local bank, tileShapes = {}, {}

local function concaveOutline(rng)
  if chance(rng, 3) then return noisyShape(rng) end
  return shapes.star(rng, rng:int(4, 16), rng:range(-200, 200), rng:range(-200, 200), rng:range(20, 200))
end

-- Adds a list to the bank; a split that failed (nil) adds nothing.
local function deposit(list)
  if list then bank[#bank + 1] = list end
end

local function fillBank(seed)
  local rng = streamFor(seed, "bank")
  for _ = 1, 12 do
    local set = tiles.random(rng, rng:int(2, 5), rng:int(2, 5), 0.6)
    for _, shape in ipairs(tiles.shapes(set, rng:int(1, 40), rng:int(-100, 100), rng:int(-100, 100))) do
      tileShapes[#tileShapes + 1] = shape
      deposit(HELPER.polygonConvexParts(shape[1], shape[2]))
    end
  end
  for _ = 1, 32 do deposit(HELPER.polygonConvexParts(concaveOutline(rng))) end
  for _ = 1, 8 do deposit(HELPER.polygonTriangulate(concaveOutline(rng))) end
  for _ = 1, 8 do deposit(scenes.cluster(rng, rng:int(1, 6), 60, 30)) end
  for _ = 1, 8 do deposit((scenes.terrain(rng, rng:int(2, 12)))) end
end

-- The most parts a list gets, and the most pairs of parts two lists of one call make: a push
-- between lists costs time that grows as a high power of the parts that overlap, and a few large
-- overlapping lists would take most of a run (bench/NOTES.md).
local MAX_PARTS, PAIR_BUDGET = 12, 36

-- A grid of axis-parallel rectangles with tiles missing: tile seams, edges shared by neighbours.
-- At most `limit` tiles.
local function gridParts(rng, limit)
  local cols = rng:int(1, math.min(6, limit))
  local rows = rng:int(1, math.max(1, math.min(4, floor(limit / cols))))
  local w, h = rng:int(1, 40), rng:int(1, 40)
  local x0, y0, list = rng:int(-200, 200), rng:int(-200, 200), {}
  for r = 0, rows - 1 do
    for c = 0, cols - 1 do
      if not chance(rng, 5) or #list == 0 then
        local x, y = x0 + c * w, y0 + r * h
        list[#list + 1] = { x, y, x + w, y, x + w, y + h, x, y + h }
      end
    end
  end
  return list
end

-- A list of parts with something wrong in it.
local function spoiledParts(rng)
  local list = shapes.deepCopy(bank[rng:int(1, #bank)])
  local k = rng:int(1, #list + 1)
  local kind = rng:int(1, 7)
  if kind == 1 then list[k] = 5
  elseif kind == 2 then list[k] = { 1, 2, 3 }
  elseif kind == 3 then list[k] = {}
  elseif kind == 4 then list[k] = { 0, 0, NAN, 0, 0, 1 }
  elseif kind == 5 then list[k] = { 0, 0, 1, 0 }
  elseif kind == 6 then list[k] = "part"
  else list[k] = { 0, 0, INF, 0, 0, 1 } end
  return list
end

-- A new list of convex parts, of at most `limit` (MAX_PARTS) parts; or a broken one, one time
-- in `rare`.
local function partsShape(rng, rare, limit)
  limit = limit or MAX_PARTS
  if rare and chance(rng, rare) then return spoiledParts(rng) end
  local kind = rng:int(1, 20)
  if kind <= 12 then
    for _ = 1, 4 do
      local list = bank[rng:int(1, #bank)]
      if #list <= limit then
        list = shapes.deepCopy(list)
        if chance(rng, 3) then list = shapes.reverseEach(list) end
        return list
      end
    end
  end
  if kind <= 18 then return gridParts(rng, limit) end
  return { convexOrBox(rng) }
end

-- Lists kept from call to call and changed in place between calls, as a game moves its shapes:
-- the module prepares a list on first use and keeps what it learnt per table (see preparedParts),
-- so both sides must see the same tables change in the same order.
local function movePart(part, dx, dy)
  for i = 1, #part - 1, 2 do part[i], part[i + 1] = part[i] + dx, part[i + 1] + dy end
end

local function mutateList(rng, list, broken)
  local entry = broken[list]
  if entry and chance(rng, 2) then   -- a NaN put in before goes again (else it might stay long)
    entry[1][entry[2]], broken[list] = entry[3], nil
    return
  end
  local count = #list
  local k = rng:int(1, count)
  local part = list[k]
  local kind = rng:int(1, 10)
  if kind <= 4 then   -- the whole shape moves, each coordinate rounded as a game adds
    local dx = chance(rng, 2) and rng:int(-20, 20) or rng:range(-50, 50)
    local dy = chance(rng, 2) and rng:int(-20, 20) or rng:range(-50, 50)
    for j = 1, count do movePart(list[j], dx, dy) end
  elseif kind == 5 and #part >= 2 then   -- one vertex moves: an edit, not a move
    local i = 2 * rng:int(1, #part / 2) - 1
    part[i], part[i + 1] = part[i] + rng:range(-3, 3), part[i + 1] + rng:range(-3, 3)
  elseif kind == 6 then list[k] = shapes.translate(part, 0, 0)   -- the same part, a new table
  elseif kind == 7 then list[k] = convexOrBox(rng)
  elseif kind == 8 and count < MAX_PARTS then   -- a part more
    list[count + 1] = shapes.translate(part, rng:int(-30, 30), rng:int(-30, 30))
  elseif kind == 9 and count > 1 then list[count] = nil
  elseif kind == 10 and #part >= 1 and not entry then   -- a coordinate turns NaN for a while
    local i = rng:int(1, #part)
    broken[list] = { part, i, part[i] }
    part[i] = NAN
  end
end

-- A list of parts from the case's pool of three, changed since its last call, or a new one; and
-- whether it is kept (a list longer than `limit` is not used: a new one of the limit stands in).
local function pooledParts(rng, pool, limit)
  local slot = rng:int(1, 3)
  local list = pool[slot]
  if list == nil or chance(rng, 64) then
    list = partsShape(rng)
    pool[slot] = list
  else
    pool.broken = pool.broken or {}
    mutateList(rng, list, pool.broken)
  end
  if #list > limit then return partsShape(rng, nil, limit), false end
  return list, true
end

--------------------------------------------------------------------------------------------------
-- Pairs of shapes for the collisions, by how they meet
--------------------------------------------------------------------------------------------------

-- Two boxes of integers that share an edge, or only a corner.
local function touchingBoxes(rng)
  local x, y, w, h = rng:int(-100, 100), rng:int(-100, 100), rng:int(1, 60), rng:int(1, 60)
  local a = { x, y, x + w, y, x + w, y + h, x, y + h }
  local w2, h2 = rng:int(1, 60), rng:int(1, 60)
  local bx, by = x + w, chance(rng, 3) and y + h or y + rng:int(-h2 + 1, h - 1)
  if chance(rng, 2) then bx, by = x + rng:int(-w2 + 1, w - 1), y - h2 end
  return a, { bx, by, bx + w2, by, bx + w2, by + h2, bx, by + h2 }
end

-- Two triangles that share a slanted edge exactly.
local function touchingTriangles(rng)
  local x, y, w, h = rng:int(-100, 100), rng:int(-100, 100), rng:int(1, 60), rng:int(1, 60)
  return { x, y, x + w, y + h, x, y + h }, { x, y, x + w, y, x + w, y + h }
end

-- b moved by an ulp of its largest coordinate, towards a or away: overlapping by an ulp or not.
local function nudged(rng, b)
  local step = ulpOf(b) * sign(rng)
  local out = {}
  local axis = rng:int(0, 1)
  for i = 1, #b do out[i] = (i % 2 == axis) and b[i] + step or b[i] end
  return out
end

-- b moved by the push the helper finds out of a: the very edge of the library's separation.
local function pushedOut(a, b)
  local ok, overlap, dx, dy = pcall(HELPER.polygonsCollideV, a, b)
  if not (ok and overlap) then return b end
  if type(b[1]) == "table" then return shapes.translateEach(b, dx, dy) end
  return shapes.translate(b, dx, dy)
end

-- b shrunk halfway towards its vertex mean: one polygon inside the other.
local function shrunk(points)
  local cx, cy = shapes.vertexMean(points)
  local out = {}
  for i = 1, #points - 1, 2 do
    out[i], out[i + 1] = cx + (points[i] - cx) * 0.5, cy + (points[i + 1] - cy) * 0.5
  end
  return out
end

-- b (a new table) moved so that the middle of its box lands somewhere in a's box: shapes that
-- overlap, or nearly. Moved by whole numbers half the time (integer boxes stay integers).
local function movedNear(rng, b, a)
  local axmin, aymin, axmax, aymax = boundsOf(a)
  local bxmin, bymin, bxmax, bymax = boundsOf(b)
  local dx = rng:range(axmin, axmax) - (bxmin + bxmax) / 2
  local dy = rng:range(aymin, aymax) - (bymin + bymax) / 2
  if dx - dx ~= 0 or dy - dy ~= 0 then return b end   -- boxes beyond the largest double
  if chance(rng, 2) then dx, dy = floor(dx + 0.5), floor(dy + 0.5) end
  if type(b[1]) == "table" then return shapes.translateEach(b, dx, dy) end
  return shapes.translate(b, dx, dy)
end

-- A shape for one side of a collision: a flat polygon, or with allowParts a list of parts (new
-- or from the pool, at most `limit` parts); and whether it is a pool's (to be kept as it is).
local function collisionShape(rng, allowParts, pool, convexOnly, limit)
  limit = limit or MAX_PARTS
  if allowParts and chance(rng, 4) then
    if chance(rng, 2) then return pooledParts(rng, pool, limit) end
    return partsShape(rng, nil, limit), false
  end
  if convexOnly or chance(rng, 3) then return convexOrBox(rng), false end
  return flatShape(rng), false
end

-- A list of parts has a table first (the module's own test, isParts).
local function isList(shape)
  return type(shape) == "table" and type(shape[1]) == "table"
end

-- A new shape in the other winding, a list part by part.
local function reversed(shape)
  if isList(shape) then return shapes.reverseEach(shape) end
  return shapes.reverse(shape)
end

-- The most parts the second shape of a pair may have, given the first (PAIR_BUDGET).
local function partsLeft(a)
  if not isList(a) then return MAX_PARTS end
  return math.max(1, floor(PAIR_BUDGET / #a))
end

-- Two shapes and the way they meet. convexOnly: flat convex polygons mostly (the one-sided
-- functions take nothing else); allowParts: lists of parts on either side too.
local function shapePair(rng, allowParts, pool, convexOnly)
  local a, b, keepA, keepB
  local relation = rng:int(1, 12)
  if relation <= 2 then   -- anywhere: mostly apart
    a, keepA = collisionShape(rng, allowParts, pool, convexOnly)
    b, keepB = collisionShape(rng, allowParts, pool, convexOnly, partsLeft(a))
  elseif relation == 3 then   -- the same list (or polygon) on both sides
    a, keepA = collisionShape(rng, allowParts, pool, convexOnly, floor(math.sqrt(PAIR_BUDGET)))
    b, keepB = a, keepA
  elseif relation <= 5 then
    a, b = touchingBoxes(rng)
  elseif relation == 6 then
    a, b = touchingTriangles(rng)
  elseif relation == 7 then
    a = convexOrBox(rng)
    b = chance(rng, 2) and shrunk(a) or a
  elseif relation == 8 then
    a = convexOrBox(rng)
    b = shapes.translate(a, FAR[rng:int(1, #FAR)], rng:range(-10, 10))
  else   -- near each other: overlapping, or (below) pushed apart by the helper
    a, keepA = collisionShape(rng, allowParts, pool, convexOnly)
    b, keepB = collisionShape(rng, allowParts, pool, convexOnly, partsLeft(a))
    if not keepB then b = movedNear(rng, b, a) elseif not keepA then a = movedNear(rng, a, b) end
  end
  if chance(rng, 2) and not keepA then a = reversed(a) end
  if chance(rng, 2) and not keepB then b = reversed(b) end
  local place = drawPlacement(rng)
  if not keepA then a = placeShape(place, rng, a) end
  if not keepB then b = placeShape(place, rng, b) end
  -- finishing touches on placed shapes, so that the ulp and the push are the placed ones'
  if (relation == 4 or relation == 6) and not keepB and chance(rng, 2) then b = nudged(rng, b) end
  if relation >= 11 and not keepB then b = pushedOut(a, b) end
  if chance(rng, 2) then a, b = b, a end
  return a, b
end

--------------------------------------------------------------------------------------------------
-- Circles
--------------------------------------------------------------------------------------------------

-- A circle aimed at a shape: anywhere around it, touching a vertex exactly (a 3-4-5 triangle),
-- deep inside, of radius 0, tiny or huge, or moved out by the helper's push.
local function circleNear(rng, shape)
  local xmin, ymin, xmax, ymax = boundsOf(shape)
  local size = math.max(xmax - xmin, ymax - ymin, 1e-300)
  local cx = rng:range(xmin - size, xmax + size)
  local cy = rng:range(ymin - size, ymax + size)
  local r = rng:range(0, size)
  local kind = rng:int(1, 10)
  if kind == 1 then
    r = 0
  elseif kind == 2 then
    local i = 2 * rng:int(1, math.max(1, floor(#shape / 2))) - 1
    local vx, vy = shape[i], shape[i + 1]
    if type(vx) == "number" and type(vy) == "number" then
      local k = rng:int(1, 100)
      cx, cy, r = vx + 3 * k * sign(rng), vy + 4 * k * sign(rng), 5 * k
    end
  elseif kind == 3 then
    r = chance(rng, 2) and 1e300 or 1e-300
  elseif kind == 4 then
    cx, cy, r = (xmin + xmax) / 2, (ymin + ymax) / 2, size / 8
  elseif kind <= 6 then
    local ok, overlap, dx, dy = pcall(HELPER.polygonCircleCollideV, shape, cx, cy, r)
    if ok and overlap then cx, cy = cx + dx, cy + dy end
  end
  if chance(rng, 24) then cx = special(rng) end
  if chance(rng, 24) then cy = special(rng) end
  if chance(rng, 16) then r = chance(rng, 2) and -r or special(rng) end
  return cx, cy, r
end

--------------------------------------------------------------------------------------------------
-- The cases: one per public function, in the order of the README
--------------------------------------------------------------------------------------------------

-- A flat polygon for a function that takes one: any kind, placed, broken one time in `rare`.
local function anyFlat(rng, rare)
  -- a new table either way (placed or not): spoil may change it
  local points = placeShape(drawPlacement(rng), rng, flatShape(rng))
  if chance(rng, rare or 12) then return spoil(rng, points) end
  return points
end

-- A point to test against a shape: a vertex exactly, the middle of an edge, a vertex moved by an
-- ulp, or anywhere around it.
local function queryPoint(rng, points)
  local xmin, ymin, xmax, ymax = boundsOf(points)
  local x = rng:range(xmin - (xmax - xmin) / 8, xmax + (xmax - xmin) / 8)
  local y = rng:range(ymin - (ymax - ymin) / 8, ymax + (ymax - ymin) / 8)
  local n = type(points) == "table" and #points or 0
  if n >= 4 and type(points[1]) ~= "table" then
    local i = 2 * rng:int(1, floor(n / 2)) - 1
    local j = i + 2 <= n - 1 and i + 2 or 1
    local kind = rng:int(1, 4)
    local x1, y1, x2, y2 = points[i], points[i + 1], points[j], points[j + 1]
    local numbers = type(x1) == "number" and type(y1) == "number"
      and type(x2) == "number" and type(y2) == "number"
    if numbers and kind == 1 then
      x, y = x1, y1
    elseif numbers and kind == 2 then
      x, y = (x1 + x2) / 2, (y1 + y2) / 2
    elseif numbers and kind == 3 then
      x, y = x1 + sign(rng) * ulp(x1), y1
    end
  end
  if chance(rng, 24) then x = special(rng) end
  if chance(rng, 24) then y = special(rng) end
  return x, y
end

-- Outlines with holes for the triangulation: holes well inside a star, a triangle in a triangle,
-- boxes touching at a corner inside a box, tile maps with pinch points; then broken holes.
local function holedStar(rng)
  local size = rng:range(20, 200)
  local outline = shapes.star(rng, rng:int(3, 16), 0, 0, size)
  local holes, count = {}, rng:int(1, 3)
  -- the star reaches out to 0.3 size at least; holes of radius 0.06 size at most, 0.15 size out,
  -- at least 0.26 size apart: inside and apart
  for h = 1, count do
    local t = 2 * math.pi * h / count
    local hole = shapes.convex(rng, rng:int(3, 8), 0.15 * size * math.cos(t), 0.15 * size * math.sin(t),
      0.04 * size, 0.4)
    holes[h] = chance(rng, 2) and shapes.reverse(hole) or hole
  end
  return outline, holes
end

local function holedTriangle(rng)
  local outline = { rng:int(-100, 0), rng:int(-100, 0), rng:int(50, 150), rng:int(-80, 20),
    rng:int(-50, 50), rng:int(60, 160) }
  local cx, cy = shapes.vertexMean(outline)
  local hole = {}
  for i = 1, 5, 2 do
    hole[i], hole[i + 1] = cx + (outline[i] - cx) * 0.3, cy + (outline[i + 1] - cy) * 0.3
  end
  return outline, { chance(rng, 2) and shapes.reverse(hole) or hole }
end

local function holedBox()
  return { 0, 0, 10, 0, 10, 10, 0, 10 }, { { 2, 2, 2, 5, 5, 5, 5, 2 }, { 5, 5, 5, 8, 8, 8, 8, 5 } }
end

local function brokenHoles(rng, outline)
  local kind = rng:int(1, 8)
  if kind == 1 then return "holes" end
  if kind == 2 then return { 5 } end
  if kind == 3 then return { { 1, 2, 3 } } end
  if kind == 4 then return { { 0, 0, NAN, 0, 0, 1 } } end
  if kind == 5 then return { shapes.translate(outline, 1e6, 0) } end       -- outside
  if kind == 6 then return { shapes.scale(outline, 2) } end                -- crossing the outline
  if kind == 7 then return { outline } end                                 -- the outline itself
  return { { 0, 0, 1, 1, 2, 2 } }                                         -- zero area
end

local function triangulationArgs(rng)
  local kind = rng:int(1, 20)
  local outline, holes
  if kind <= 10 then
    outline = weighted(rng, { { 3, starShape }, { 2, noisyShape }, { 2, spiralShape },
      { 2, convexShape }, { 1, boxShape }, { 1, sampleShape }, { 1, scatteredShape },
      { 1, collinearShape }, { 1, repeatedShape }, { 1, spikeShape }, { 1, fewShape } })(rng)
    if chance(rng, 4) then holes = {} end
  elseif kind <= 12 then outline, holes = holedStar(rng)
  elseif kind <= 14 then outline, holes = holedTriangle(rng)
  elseif kind == 15 then outline, holes = holedBox()
  elseif kind <= 18 then
    local shape = shapes.deepCopy(tileShapes[rng:int(1, #tileShapes)])
    outline, holes = shape[1], shape[2]
  else
    outline = starShape(rng)
    holes = brokenHoles(rng, outline)
  end
  if chance(rng, 2) then outline = shapes.reverse(outline) end
  local place = drawPlacement(rng)
  outline = placeShape(place, rng, outline)
  if type(holes) == "table" then holes = placeShape(place, rng, holes) end
  if chance(rng, 16) then outline = spoil(rng, outline) end   -- a new table: made above
  if holes == nil and chance(rng, 8) then return { outline }, 1 end
  return { outline, holes }, 2
end

-- A shape for the moving functions: flat or a list of parts, placed.
local function movingShape(rng)
  if chance(rng, 3) then return placeShape(drawPlacement(rng), rng, partsShape(rng, 12)) end
  return anyFlat(rng, 16)
end

-- The out table of polygonTranslate and polygonRotate: none, a new one, a used one longer than
-- the result, the points themselves (in place), a broken one.
local function outFor(rng, points)
  local kind = rng:int(1, 10)
  if kind <= 3 then return nil end
  if kind <= 5 then return {} end
  if kind <= 7 then
    local out = {}
    for i = 1, rng:int(0, 50) do out[i] = chance(rng, 4) and i or { i } end
    return out
  end
  if kind <= 9 then return points end
  return chance(rng, 2) and "out" or { 5 }
end

local function angleOf(rng)
  local kind = rng:int(1, 10)
  if kind == 1 then return 0 end
  if kind == 2 then return rng:int(-4, 4) * math.pi / 2 end
  if kind == 3 then return chance(rng, 2) and 1e300 or 1e-300 end
  if kind == 4 then return special(rng) end
  return rng:range(-10, 10)
end

local function displacement(rng)
  local kind = rng:int(1, 8)
  if kind == 1 then return rng:int(-100, 100) end
  if kind == 2 then return FAR[rng:int(1, #FAR)] * sign(rng) end
  if kind == 3 then return special(rng) end
  return rng:range(-100, 100)
end

local function circleArgs(rng)
  local x1, y1, r1 = rng:range(-100, 100), rng:range(-100, 100), rng:range(0, 60)
  local x2, y2, r2 = rng:range(-100, 100), rng:range(-100, 100), rng:range(0, 60)
  local kind = rng:int(1, 10)
  if kind <= 2 then   -- touching exactly: distance 5k, radii summing to 5k
    local k = rng:int(1, 1000)
    x1, y1 = rng:int(-1000, 1000), rng:int(-1000, 1000)
    x2, y2 = x1 + 3 * k * sign(rng), y1 + 4 * k * sign(rng)
    r1 = rng:int(0, 5 * k)
    r2 = 5 * k - r1
    if kind == 2 then r2 = r2 + sign(rng) * ulp(r2 + 1.0) end
  elseif kind == 3 then
    x2, y2 = x1, y1
  elseif kind == 4 then
    r1, r2 = 0, chance(rng, 2) and 0 or r2
  elseif kind == 5 then
    local d = FAR[rng:int(1, #FAR)]
    x1, y1, x2, y2 = x1 + d, y1 - d, x2 + d, y2 - d
  elseif kind == 6 then
    r1, r2 = r1 * 1e300, r2 * 1e-300
  end
  local args = { x1, y1, r1, x2, y2, r2 }
  if chance(rng, 8) then args[rng:int(1, 6)] = special(rng) end
  if chance(rng, 16) then args[rng:int(1, 6)] = -rng:range(0, 10) end
  return args, 6
end

-- A case builds one call's arguments: args[1 .. n], and args for the new side when they differ
-- (tables the call may write to, copied; objects of each side's class). `pool` is the case's own.
local function flatCase(rare)
  return function(rng) return { anyFlat(rng, rare) }, 1 end
end

-- Arguments for functions that may write into them (out, in place): built twice from the same
-- draws, one set for each side, by the same steps, so that the sharing between them (out may be
-- the points) is the same and even an array with a hole in it has the same # on both sides (a
-- copy built another way may find another border). Reads the PRNG's state to draw again.
local function twice(build)
  return function(rng, pool)
    local state = rng.state
    local args, n = build(rng, pool)
    local after = rng.state
    rng.state = state
    local argsNew = build(rng, pool)
    assert(rng.state == after, "a case built twice drew differently")
    return args, n, argsNew
  end
end

local CASES = {
  { "polygonWindingOrder", flatCase() },
  { "polygonArea", flatCase() },
  { "polygonAreaAccurate", flatCase() },
  { "polygonType", flatCase() },
  { "polygonCenter", flatCase() },
  { "polygonCentroid", flatCase() },
  { "polygonContains", function(rng)
    local points = anyFlat(rng, 16)
    local x, y = queryPoint(rng, points)
    return { points, x, y }, 3
  end },
  { "projectPolygon", function(rng)
    local points = anyFlat(rng, 16)
    local x, y = queryPoint(rng, points)
    local t = rng:range(0, 2 * math.pi)
    local nx, ny = math.cos(t), math.sin(t)
    if chance(rng, 4) then nx, ny = rng:int(-1, 1), rng:int(-1, 1) end
    if chance(rng, 8) then nx, ny = nx * 1e200, ny * 1e200 end
    if chance(rng, 24) then nx = special(rng) end
    if chance(rng, 24) then ny = special(rng) end
    return { points, x, y, nx, ny }, 5
  end },
  { "polygonCollidesWith", function(rng, pool)
    local a, b = shapePair(rng, chance(rng, 16), pool, true)
    if chance(rng, 16) then a = spoil(rng, shapes.deepCopy(a)) end
    return { a, b }, 2
  end },
  { "polygonsCollide", function(rng, pool)
    local a, b = shapePair(rng, true, pool, false)
    if chance(rng, 24) then b = spoil(rng, shapes.deepCopy(b)) end
    return { a, b }, 2
  end },
  { "polygonCollidesWithV", function(rng, pool)
    local a, b = shapePair(rng, chance(rng, 16), pool, true)
    if chance(rng, 16) then b = spoil(rng, shapes.deepCopy(b)) end
    return { a, b }, 2
  end },
  { "polygonsCollideV", function(rng, pool)
    local a, b = shapePair(rng, true, pool, false)
    if chance(rng, 24) then a = spoil(rng, shapes.deepCopy(a)) end
    return { a, b }, 2
  end },
  { "projectCircle", function(rng)
    local args = {}
    for i = 1, 7 do args[i] = scalar(rng, -1000, 1000, 16) end
    if chance(rng, 8) then args[3] = scalar(rng, 0, 1000, 16) else args[3] = rng:range(0, 1000) end
    if chance(rng, 2) then
      local t = rng:range(0, 2 * math.pi)
      args[6], args[7] = math.cos(t), math.sin(t)
    end
    return args, 7
  end },
  { "circlesCollideV", circleArgs },
  { "polygonCircleCollideV", function(rng, pool)
    local shape = collisionShape(rng, true, pool, false)
    if type(shape[1]) ~= "table" then shape = placeShape(drawPlacement(rng), rng, shape) end
    local cx, cy, r = circleNear(rng, shape)
    if chance(rng, 24) then shape = spoil(rng, shapes.deepCopy(shape)) end
    return { shape, cx, cy, r }, 4
  end },
  { "polygonTriangulate", triangulationArgs },
  { "polygonConvexParts", triangulationArgs },
  { "polygonBounds", function(rng, pool)
    local shape = collisionShape(rng, true, pool, false)
    if chance(rng, 12) then shape = spoil(rng, shapes.deepCopy(shape)) end
    return { shape }, 1
  end },
  { "polygonTranslate", twice(function(rng)
    local points = movingShape(rng)
    return { points, displacement(rng), displacement(rng), outFor(rng, points) }, 4
  end) },
  { "polygonRotate", twice(function(rng)
    local points = movingShape(rng)
    local out = outFor(rng, points)
    local angle = angleOf(rng)
    local kind = rng:int(1, 12)
    local args, n
    if kind <= 4 then args, n = { points, angle, out }, out == nil and 2 or 3   -- (points, angle [, out])
    elseif kind <= 9 then
      args, n = { points, angle, scalar(rng, -500, 500), scalar(rng, -500, 500), out }, 5
    elseif kind <= 11 then args, n = { points, angle, nil, nil, out }, 5
    else args, n = { points, angle, scalar(rng, -500, 500) }, 3 end   -- ox without oy
    return args, n
  end) },
  { "validate", flatCase(6) },
  -- the class: Polygon.new, Polygon(points) (its __call) and Polygon:contains
  { "Polygon.new", flatCase(6) },
  { "Polygon()", flatCase(6) },
  { "Polygon:contains", function(rng)
    local points = anyFlat(rng, 16)
    local x, y = queryPoint(rng, points)
    local kind = rng:int(1, 40)
    if kind <= 37 then   -- each side's own object over the same points (unchecked: made here)
      return { setmetatable({ points = points }, OLD.Polygon), x, y }, 3,
        { setmetatable({ points = points }, NEW.Polygon), x, y }
    end
    if kind <= 39 then return { { points = points }, x, y }, 3 end   -- a plain table as self
    return { chance(rng, 2) and "self" or {}, x, y }, 3
  end },
}

-- How each side's function is found: a field of the module, the class's __call, or the method
-- through the object's metatable (as p:contains(x, y) finds it).
local function functionOf(module, name, args)
  if name == "Polygon.new" then return module.Polygon and module.Polygon.new end
  if name == "Polygon()" then return module.Polygon end
  if name == "Polygon:contains" then
    local self = args[1]
    if type(self) == "table" and getmetatable(self) then return self.contains end
    return module.Polygon and module.Polygon.contains
  end
  return module[name]
end

--------------------------------------------------------------------------------------------------
-- Running a case
--------------------------------------------------------------------------------------------------

-- A copy of the shared arguments' tables before a call, to see whether a call wrote into them:
-- seen maps each argument table to its copy (table values in a copy are copies).
local function copyInto(t, seen)
  local copy = {}
  seen[t] = copy
  for k, v in pairs(t) do
    if type(v) == "table" then v = seen[v] or copyInto(v, seen) end
    copy[k] = v
  end
  return copy
end

local function snapshot(args, n)
  local seen = {}
  for i = 1, n do
    local v = args[i]
    if type(v) == "table" and not seen[v] then copyInto(v, seen) end
  end
  return seen
end

-- Whether two values other than tables are the same, bit for bit (as sameNumber for numbers).
local function sameScalar(v, w)
  if v ~= w then return v ~= v and w ~= w end
  if v == 0 and 1 / v ~= 1 / w then return false end
  return not mathType or mathType(v) == mathType(w)
end

-- Whether every table of a snapshot still holds what its copy holds: the same keys, the same
-- values, the same tables in them.
local function unchanged(seen)
  for live, copy in pairs(seen) do
    local count = 0
    for k, v in pairs(copy) do
      local w = rawget(live, k)
      if type(v) == "table" then
        if seen[w] ~= v then return false end
      elseif not sameScalar(v, w) then
        return false
      end
      count = count + 1
    end
    for _ in pairs(live) do count = count - 1 end
    if count ~= 0 then return false end
  end
  return true
end

-- Writes the snapshot back into the argument tables: the old side wrote into shared arguments,
-- and the new side must get them as they were.
local function restore(seen)
  local liveOf = {}
  for live, copy in pairs(seen) do liveOf[copy] = live end
  for live, copy in pairs(seen) do
    for k in pairs(live) do
      if rawget(copy, k) == nil then rawset(live, k, nil) end
    end
    for k, v in pairs(copy) do rawset(live, liveOf[k] or k, liveOf[v] or v) end
  end
end

local totalCalls, totalDifferences = 0, 0

-- The interpreter this runs on, for the command that replays a difference.
local commandLine = rawget(_G, "arg")
local INTERPRETER = commandLine and commandLine[-1] or "lua"

-- The settings a rerun needs besides the function, the seed and the call.
local function environment()
  local settings = {}
  for _, name in ipairs({ "POLYGON_OLD", "POLYGON_NEW", "POLYGON_DIFF_POSITIONS" }) do
    local value = os.getenv(name)
    if value and value ~= "" then settings[#settings + 1] = ("%s='%s' "):format(name, value) end
  end
  return table.concat(settings)
end

-- What a call did: "returned" and its values, or "raised" and the error.
local function outcome(result)
  if result[1] then return "returned " .. showList(result, 2, result.n) end
  return "raised " .. show(result[2])
end

local function report(name, seed, call, args, argsNew, n, old, new, where)
  print(("DIFFERENCE in %s, seed %d, call %d: %s"):format(name, seed, call, where))
  print(("  rerun: %sPOLYGON_DIFF_ONLY='%s' %s bench/differential.lua %d %d")
    :format(environment(), name, INTERPRETER, call, seed))
  print("  arguments: " .. showList(args, 1, n))
  if argsNew ~= args then print("  arguments (new side): " .. showList(argsNew, 1, n)) end
  print("  old: " .. outcome(old))
  print("  new: " .. outcome(new))
  io.stdout:flush()
end

--------------------------------------------------------------------------------------------------
-- Intended changes, each accepted by a narrow rule named after its issue and checked
-- independently of the library (spec/support/oracle.lua)
--------------------------------------------------------------------------------------------------

local oracle = require "oracle"

-- Issue 29 ("no silent wrong answers"): the collision functions refuse what they cannot handle,
-- a Polygon object is taken for its points, and no collision is `false` alone; the measures,
-- polygonContains and polygonBounds take a Polygon object too and refuse point tables.
local ISSUE_29_FUNCTIONS = { polygonCollidesWith = true, polygonsCollide = true,
  polygonCollidesWithV = true, polygonsCollideV = true, polygonCircleCollideV = true,
  polygonWindingOrder = true, polygonArea = true, polygonAreaAccurate = true, polygonType = true,
  polygonCenter = true, polygonCentroid = true, polygonContains = true, polygonBounds = true,
  ["Polygon:contains"] = true, projectPolygon = true, polygonTranslate = true, polygonRotate = true,
  polygonTriangulate = true, polygonConvexParts = true, validate = true, ["Polygon.new"] = true,
  ["Polygon()"] = true }

-- The shape a refusal names ("points1", "points2[3]", "points"), from the call's arguments.
local function namedShape(args, argname)
  local base, index = argname:match("^points(%d?)(.*)$")
  local shape = args[base == "2" and 2 or 1]
  local k = index:match("^%[(%d+)%]$")
  if k then
    shape = type(shape) == "table" and shape[tonumber(k)]
  end
  return shape
end

-- The entries a collision function reads of a shape: a NEW Polygon object's points.
local function pointsOf(shape)
  if type(shape) == "table" and NEW.Polygon and getmetatable(shape) == NEW.Polygon then
    return rawget(shape, "points")
  end
  return shape
end

-- Whether NEW's refusal message names a shape that is of the refused kind, judged here.
local function refusalHolds(name, args, message)
  name = name == "Polygon()" and "Polygon.new" or name   -- (its messages name Polygon.new)
  local argname, what = message:match("^" .. name .. ": (points%d?)(%[%d+%] must be a number, got %a+)$")
  if not argname then
    argname, what = message:match("^" .. name .. ": (points%d?%[%d+%])(%[%d+%] must be a "
      .. "number, got %a+; a list of parts holds flat arrays)$")
  end
  if not argname then
    argname, what = message:match("^" .. name .. ": (points%d?[%[%]%d]*) (.*)$")
    if not argname then return false end
  end
  local shape = pointsOf(namedShape(args, argname))
  if name == "Polygon:contains" then shape = type(args[1]) == "table" and rawget(args[1], "points") end
  if type(shape) ~= "table" then return false end
  local n = #shape
  if what:find("^is not convex %(") then
    -- judged on the doubles the library reads (a Lua 5.3+ integer beyond 2^53 converted)
    local doubles = {}
    for i = 1, n do
      if type(shape[i]) ~= "number" then return false end
      doubles[i] = shape[i] + 0.0
    end
    return n >= 6 and n % 2 == 0 and oracle.polygonType(doubles) == "concave"
  end
  if what == "holds a non-finite coordinate" then   -- now seen in every part when it is prepared
    local list = type(shape[1]) == "table" and shape or { shape }
    for _, part in ipairs(list) do
      for i = 1, #part do
        local v = part[i]
        if type(v) == "number" and (v ~= v or v == huge or v == -huge) then return true end
      end
    end
    return false
  end
  if what == "has 2 points: a segment; a polygon needs at least 3" then return n == 4 end
  -- issue 30: a segment's refusal points to the ray cast
  if what == "has 2 points: a segment; a polygon needs at least 3; for line of sight use "
      .. "polygonRayCast" then
    return n == 4
  end
  if what == "has 1 point; a polygon needs at least 3" then return n == 2 end
  if what == "is empty; a polygon needs at least 3 points" then return n == 0 end
  if what == "holds point tables; pass a flat array {x1, y1, x2, y2, ...}" then
    local first = shape[1]
    return type(first) == "table" and (first.x ~= nil or #first == 2)
  end
  local k, got = what:match("^%[(%d+)%] must be a number, got (%a+)$")
  if got then return type(shape[tonumber(k)]) == got and got ~= "number" end
  k, got = what:match("^%[(%d+)%] must be a number, got (%a+); a list of parts holds flat arrays$")
  if got then return type(shape[tonumber(k)]) == got and got ~= "number" end
  if what == "is a list of parts; it takes convex polygons only (polygonsCollide takes lists)" then
    return type(shape[1]) == "table" and shape[1].x == nil and #shape[1] ~= 2
  end
  return false
end

-- Issue 29, item 4 (circles at every radius): polygonCircleCollideV finds the nearest feature
-- from the given coordinates, not from their offsets to the centre, and scales a small polygon
-- against a huge circle differently, so some answers change (by an ulp, or from a wrong push).
-- NEW's answer for a flat polygon is accepted where the oracle agrees with all of it: the
-- boolean, and a push that clears and is at most 8 eps M past the exact depth.
local function circleAnswerHolds(args, new)
  local points, cx, cy, r = pointsOf(args[1]), args[2], args[3], args[4]
  if not new[1] or type(points) ~= "table" or type(cx) ~= "number" or type(cy) ~= "number"
      or type(r) ~= "number" then
    return false
  end
  local m = math.max(math.abs(cx), math.abs(cy))
  for i = 1, #points do
    if type(points[i]) ~= "number" then return false end
    m = math.max(m, math.abs(points[i]))
  end
  local overlap, dx, dy = new[2], new[3], new[4]
  if oracle.discMeetsPolygon(points, cx, cy, r) ~= (overlap ~= false) then return false end
  if not overlap then return true end
  if oracle.discMeetsPolygon(points, cx + dx, cy + dy, r) then return false end
  m = math.max(m, math.abs(cx + dx), math.abs(cy + dy))
  return oracle.circleDepthAtLeast(points, cx, cy, r, oracle.lengthAbove(dx, dy), 8 * 2^-53 * m)
end

local function issue29Accepts(name, args, n, old, new)
  -- any function: the odd-count error of a table of point tables now says what it is
  if not old[1] and not new[1] and type(new[2]) == "string"
      and new[2]:find(" holds point tables; pass a flat array", 1, true)
      and refusalHolds(name, args, new[2]) then
    return true
  end
  if not ISSUE_29_FUNCTIONS[name] then return false end
  -- polygonRotate's pivot: the non-finite error names polygonRotate, not polygonCentroid
  if name == "polygonRotate" and not old[1] and not new[1] and type(old[2]) == "string" then
    local was = old[2]:match("polygonCentroid: (points holds a non%-finite coordinate.*)$")
    if was and new[2]:match("polygonRotate: (.*)$") == was then return true end
  end
  -- validate's answer for point tables
  if name == "validate" and new[1] and new[2] == nil
      and new[3] == "points holds point tables; pass a flat array {x1, y1, x2, y2, ...}" then
    local first = type(args[1]) == "table" and args[1][1]
    return type(first) == "table" and (first.x ~= nil or #first == 2)
  end
  -- no collision: false alone where OLD gave false, nil, nil
  if old[1] and new[1] and old[2] == false and new[2] == false and new.n == 2 then return true end
  -- a refusal of a shape that is of the refused kind
  if not new[1] and type(new[2]) == "string" and refusalHolds(name, args, new[2]) then return true end
  -- Lua's own error where OLD answered, for a flat shape holding an entry that is not a number
  -- past its first (the check reads every entry; such entries are refused, past the first by
  -- Lua's own error: spec/refusals_spec.lua)
  if not new[1] and type(new[2]) == "string" and new[2]:find("attempt to perform arithmetic", 1, true) then
    for i = 1, n do
      local shape = pointsOf(args[i])
      if type(shape) == "table" and type(shape[1]) == "number" then
        for j = 2, #shape do
          if type(shape[j]) ~= "number" then return true end
        end
      end
    end
  end
  if name == "polygonCircleCollideV" and old[1] and circleAnswerHolds(args, new) then return true end
  -- a NEW Polygon object taken for its points: the same as NEW on the points themselves
  local plain, changed = {}, false
  for i = 1, n do
    plain[i] = pointsOf(args[i])
    if plain[i] ~= args[i] then changed = true end
  end
  if changed and new[1] then
    local again = pack(pcall(NEW[name], unpack(plain, 1, n)))
    if again.n ~= new.n then return false end
    for i = 1, new.n do
      if not (again[i] == new[i] or again[i] ~= again[i] and new[i] ~= new[i]) then return false end
    end
    return true
  end
  return false
end

-- Issue 28 (polygons with holes): polygonTriangulate and polygonConvexParts bridge holes
-- differently (the hit edge's left end), triangulate valid input v0.7.0 refused, name the rings
-- in their messages, and skip holes enclosing nothing (fewer than 3 points, zero area) where
-- v0.7.0 raised or refused. Where the two sides differ, NEW is checked on its own: pieces must
-- cover the outline minus the holes exactly (oracle.checkCover: input vertices, winding, no
-- overlap, the region's boundary; convex for polygonConvexParts), and OLD must have returned
-- pieces or nil, or raised only for a hole of fewer than 3 points; a refusal must be OLD's with
-- the same message, or of input the oracle finds invalid (oracle.regionCrossing). Outside the
-- exact range (README: nonzero coordinates between 2^-447 and 2^500) the library's area sign
-- may round to 0: there a hole OLD refused as "holes[h] has zero area", NEW skips, unchecked.
-- Returns nil when the difference is of that kind, else `where` (the difference) with the reason.
local HOLES_RULE = { polygonTriangulate = true, polygonConvexParts = true }
local holesRuleAccepted = 0
local function outsideExactRange(points, holes)
  for _, ring in ipairs({ points, unpack(holes or {}) }) do
    for _, v in ipairs(ring) do
      local m = math.abs(v)
      if m ~= 0 and (m < 2 ^ -447 or m > 2 ^ 500) then return true end
    end
  end
  return false
end
local function holesRule(name, args, old, new, where)
  local points, holes = args[1], args[2]
  if not new[1] then return where end   -- NEW raising where OLD did not, or differently
  if type(holes) ~= "table" then holes = nil end
  local pieces, message = new[2], new[3]
  if type(pieces) == "table" and old[1] and old[2] == nil
    and tostring(old[3]):find("^holes%[%d+%] has zero area$") and outsideExactRange(points, holes) then
    holesRuleAccepted = holesRuleAccepted + 1
    return nil
  end
  if type(pieces) == "table" then
    if not old[1] and not tostring(old[2]):find("holes%[%d+%]: points must hold at least 3 points") then
      return where .. " (issue 28 rule: OLD raised, and not for a hole of fewer than 3 points)"
    end
    local convex = name == "polygonConvexParts"
    -- rectangles where every edge runs along an axis: their corners' coordinates are input ones
    local grid = convex and oracle.alongAxes(points, holes)
    local ok, why = oracle.checkCover(points, holes, pieces, convex, grid)
    if not ok then return where .. " (issue 28 rule: NEW's pieces: " .. why .. ")" end
  else
    if not old[1] then return where .. " (issue 28 rule: NEW refused where OLD raised)" end
    if old[2] ~= nil or old[3] ~= message then
      local verdict = oracle.regionCrossing(points, holes)
      if verdict == "valid" or verdict == "unknown" then
        return where .. " (issue 28 rule: NEW refused input the oracle finds " .. verdict .. ")"
      end
    end
  end
  holesRuleAccepted = holesRuleAccepted + 1
  return nil
end

-- Issue 28, exact pushes over lists of rectangles: where OLD's push along an axis was the depth
-- plus its margin, NEW may give the depth itself, when that already separates. Accepted when
-- both pushed along the same axis the same way, NEW no longer than OLD and shorter by at most
-- 2^-40 of the shapes' largest coordinate or extent (the margin is about 80 eps E + 2.5 eps S),
-- overlap its length, and NEW's move, each coordinate rounded as a game moves it, leaves no
-- part colliding by the oracle's exact test.
local exactPushAccepted = 0
local function largest(shape, m)
  if type(shape) ~= "table" then return m end
  for _, v in ipairs(shape) do
    if type(v) == "table" then
      m = largest(v, m)
    elseif type(v) == "number" then
      m = math.max(m, math.abs(v))
    end
  end
  return m
end
local function exactPushAccepts(name, args, old, new)
  if name ~= "polygonsCollideV" and name ~= "polygonCircleCollideV" then return false end
  if not (old[1] and new[1]) or type(old[2]) ~= "number" or type(new[2]) ~= "number" then return false end
  local ox, oy, nx, ny = old[3], old[4], new[3], new[4]
  if (ox == 0) ~= (nx == 0) or (oy == 0) ~= (ny == 0) or (ox ~= 0 and oy ~= 0) then return false end
  if (ox < 0) ~= (nx < 0) or (oy < 0) ~= (ny < 0) then return false end
  local oldLength, newLength = math.abs(ox + oy), math.abs(nx + ny)
  local scale
  if name == "polygonCircleCollideV" then
    scale = largest(args[1], math.abs(args[2]) + math.abs(args[3]) + args[4])
  else
    scale = largest(args[2], largest(args[1], 0))
  end
  if not (newLength <= oldLength and oldLength - newLength <= 2 ^ -40 * scale and new[2] == newLength) then
    return false
  end
  local function parts(shape)
    shape = pointsOf(shape)
    if type(shape) == "table" and type(shape[1]) == "table" then return shape end
    return { shape }
  end
  if name == "polygonCircleCollideV" then
    local mx, my = args[2] + nx, args[3] + ny
    for _, part in ipairs(parts(args[1])) do
      if oracle.discMeetsPolygon(part, mx, my, args[4]) then return false end
    end
  else
    for _, moving in ipairs(parts(args[2])) do
      local moved = {}
      for i = 1, #moving, 2 do moved[i], moved[i + 1] = moving[i] + nx, moving[i + 1] + ny end
      for _, part in ipairs(parts(args[1])) do
        if oracle.collides(part, moved, true) then return false end
      end
    end
  end
  exactPushAccepted = exactPushAccepted + 1
  return true
end

-- polygonContains on a polygon holding NaN: the README says it is not scanned and gets an
-- answer, which one unspecified; on LuaJIT it depends on which of its paths are compiled when
-- the call comes (v0.7.0's too: runs differ in the traces LuaJIT's randomized penalties let
-- it keep), so both sides answering a boolean is the contract.
local nanContainsAccepted = 0
local function nanContainsAccepts(name, args, old, new)
  if name ~= "polygonContains" or not (old[1] and new[1]) then return false end
  if type(old[2]) ~= "boolean" or type(new[2]) ~= "boolean" then return false end
  local points = pointsOf(args[1])
  if type(points) ~= "table" then return false end
  for _, v in ipairs(points) do
    if v ~= v then
      nanContainsAccepted = nanContainsAccepted + 1
      return true
    end
  end
  return false
end

-- One call of a case on both sides; the first difference, described, or nil; both results.
local function oneCall(name, args, n, argsNew)
  local oldF, newF = functionOf(OLD, name, args), functionOf(NEW, name, argsNew)
  local shared = argsNew == args
  local before = shared and snapshot(args, n)
  local old = pack(pcall(oldF, unpack(args, 1, n)))
  local leftByOld = before
  if shared and not unchanged(before) then
    leftByOld = snapshot(args, n)   -- what the new side must leave too
    restore(before)
  end
  local new = pack(pcall(newF, unpack(argsNew, 1, n)))
  local ctx = newContext(args, argsNew, n, true)
  local where = compareResults(old, new, ctx)
  if where and HOLES_RULE[name] and shared then where = holesRule(name, args, old, new, where) end
  -- an intended change: its rule checked the whole outcome (a refusal leaves `out` unwritten)
  if where and issue29Accepts(name, args, n, old, new) then return nil, old, new end
  if where and shared and exactPushAccepts(name, args, old, new) then return nil, old, new end
  if where and nanContainsAccepts(name, args, old, new) then return nil, old, new end
  if where then return where, old, new end
  if shared then
    if not unchanged(leftByOld) then return "the two sides left the arguments different", old, new end
    return nil, old, new
  end
  for i = 1, n do   -- what each side left in its own arguments (out)
    local difference = compare(args[i], argsNew[i], ctx)
    if difference then return ("argument %d after the call%s"):format(i, difference), old, new end
  end
  return nil, old, new
end

local function runCase(name, make, calls, seed)
  local rng, pool = streamFor(seed, name), {}
  local differences, started = 0, os.clock()
  local made = 0
  for call = 1, calls do
    if totalDifferences >= MAX_DIFFERENCES then break end
    local args, n, argsNew = make(rng, pool)
    argsNew = argsNew or args
    local where, old, new = oneCall(name, args, n, argsNew)
    made = made + 1
    if where then
      differences, totalDifferences = differences + 1, totalDifferences + 1
      report(name, seed, call, args, argsNew, n, old, new, where)
    end
  end
  totalCalls = totalCalls + made
  print(("%-22s %9d calls %6d differences %9.1f s"):format(name, made, differences, os.clock() - started))
  io.stdout:flush()   -- a line per function as it ends, also into a file or a CI log
end

--------------------------------------------------------------------------------------------------
-- The API itself: the same names, of the same types
--------------------------------------------------------------------------------------------------

local function sortedKeys(t)
  local keys = {}
  for k in pairs(t) do keys[#keys + 1] = k end
  table.sort(keys, function(p, q) return tostring(p) < tostring(q) end)
  return keys
end

-- Every field of OLD (and of its class) must be in NEW with the same type; the metadata strings
-- (_VERSION ...) may change, and fields only in NEW are reported but are no difference.
-- Returns the names of OLD's functions, the class's as the cases name them.
local function compareExports()
  local functions = {}
  local function check(oldTable, newTable, prefix)
    for _, key in ipairs(sortedKeys(oldTable)) do
      local name = prefix .. tostring(key)
      local kind, newKind = type(oldTable[key]), type(newTable and newTable[key])
      if kind ~= newKind then
        print(("DIFFERENCE in the exports: %s is a %s, on the new side a %s"):format(name, kind, newKind))
        totalDifferences = totalDifferences + 1
      elseif kind == "string" and oldTable[key] ~= newTable[key] then
        print(("note: %s changed: %q -> %q"):format(name, oldTable[key], newTable[key]))
      end
      if kind == "function" then functions[name] = true end
    end
    for _, key in ipairs(sortedKeys(newTable or {})) do
      if oldTable[key] == nil then print(("note: %s%s is new"):format(prefix, tostring(key))) end
    end
  end
  check(OLD, NEW, "")
  check(OLD.Polygon, NEW.Polygon, "Polygon.")
  local call = getmetatable(OLD.Polygon).__call
  if type(call) == "function" then functions["Polygon()"] = true end
  local newMeta = type(NEW.Polygon) == "table" and getmetatable(NEW.Polygon)
  if type(call) ~= type(newMeta and newMeta.__call) then
    print("DIFFERENCE in the exports: Polygon(points) is not callable on the new side")
    totalDifferences = totalDifferences + 1
  end
  functions["Polygon.contains"], functions["Polygon:contains"] = nil, functions["Polygon.contains"]
  return functions
end

--------------------------------------------------------------------------------------------------
-- Main
--------------------------------------------------------------------------------------------------

local function wholeNumber(text, default, what)
  if text == nil then return default end
  local value = tonumber(text)
  if not value or value < 0 or value ~= floor(value) then
    error(("%s must be a whole number, got %s"):format(what, text), 0)
  end
  return value
end

local function main(arg1, arg2)
  local calls = wholeNumber(arg1, 1000000, "CALLS")
  local seed = wholeNumber(arg2, 1, "SEED")
  local only = os.getenv("POLYGON_DIFF_ONLY")
  fillBank(seed)
  local functions = compareExports()
  local covered = {}
  for _, case in ipairs(CASES) do covered[case[1]] = true end
  for name in pairs(functions) do
    -- a public function without a case would pass unseen: refuse to run
    if not covered[name] then error("no case for the public function " .. name .. ": add one", 0) end
  end
  for _, case in ipairs(CASES) do
    local name = case[1]
    if (not only or only == name) and totalDifferences < MAX_DIFFERENCES then
      if not functions[name] then error("a case for " .. name .. ", which OLD does not export", 0) end
      if functionOf(NEW, name, {}) == nil then
        print(("%-22s missing on the new side"):format(name))
      else
        runCase(name, case[2], calls, seed)
      end
    end
  end
  if totalDifferences >= MAX_DIFFERENCES then
    print(("stopped after %d differences"):format(MAX_DIFFERENCES))
  end
  print(("errors raised inside the library, the same but for the file and line: %d"):format(movedPositions))
  print(("issue 28 rule (holes): %d differences of polygonTriangulate and polygonConvexParts"
    .. " checked and accepted"):format(holesRuleAccepted))
  print(("issue 28 rule (exact pushes): %d pushes of the depth itself over lists of parts checked and"
    .. " accepted"):format(exactPushAccepted))
  print(("polygonContains on a polygon holding NaN (any boolean is the contract): %d answers differed"
    .. " and were accepted"):format(nanContainsAccepted))
  print(("differential: %d calls, %d differences"):format(totalCalls, totalDifferences))
  os.exit(totalDifferences > 0 and 1 or 0)
end

main(...)
